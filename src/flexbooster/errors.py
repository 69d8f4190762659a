"""Exceptions and warnings shared by every layer of flexbooster.

A :class:`CaseError` is raised for input that makes the analysis impossible; it always names
the field, the offending value and the rule that was broken, so that the command line can
print it on one line and exit with status 2.  A :class:`AnalysisWarning` records a condition
under which the analysis goes on but the user must be told (it reaches the summary and
``results.json``).
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["CaseError", "AnalysisWarning"]


class CaseError(ValueError):
    """Invalid input: names the field, the value and the rule.

    Parameters
    ----------
    field : str
        Dotted path of the offending field, e.g. ``"booster.cylinder1.radius"``.
    value : object
        The value that was given (as the user wrote it where possible).
    rule : str
        The rule that the value breaks, in words.
    message : str, optional
        The whole line, where ``field = value: rule`` does not read well (an unknown key:
        ``thrust.gama: unknown key 'gama' (did you mean 'gamma'?)``).
    """

    def __init__(self, field: str, value: object, rule: str, *,
                 message: str | None = None) -> None:
        self.field = field
        self.value = value
        self.rule = rule
        super().__init__(message if message is not None else f"{field} = {value!r}: {rule}")


@dataclass(frozen=True)
class AnalysisWarning:
    """A condition under which the analysis continues but the user must be told.

    Attributes
    ----------
    code : str
        Short stable identifier, e.g. ``"thin-shell"`` or ``"mathieu-range"``.
    field : str
        The input field or result the warning is about.
    message : str
        One-line human-readable explanation, including the rule.
    """

    code: str
    field: str
    message: str

    def to_dict(self) -> dict[str, str]:
        """Return the warning as a JSON-ready mapping."""
        return {"code": self.code, "field": self.field, "message": self.message}
