"""Exceptions and warnings shared by every layer: :class:`CaseError` names the field, the value
and the rule of input that makes the analysis impossible (one line, exit 2);
:class:`AnalysisWarning` records a condition under which the analysis goes on (it reaches the
summary and ``results.json``).
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
        The whole line, where ``field = value: rule`` does not read well.
    """

    def __init__(self, field: str, value: object, rule: str, *,
                 message: str | None = None) -> None:
        self.field = field
        self.value = value
        self.rule = rule
        super().__init__(message if message is not None else f"{field} = {value!r}: {rule}")

    def __reduce__(self):
        """Pickled with its field, value, rule and line (a Dask task's error comes back whole)."""
        return _case_error, (type(self), self.field, self.value, self.rule, str(self))


def _case_error(cls: type, field: str, value: object, rule: str, message: str) -> CaseError:
    """A pickled :class:`CaseError` (or subclass) rebuilt."""
    return cls(field, value, rule, message=message)


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
