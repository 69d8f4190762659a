"""Argument checks shared by the numerical modules.

Each check returns the value converted (float or int) or raises ``ValueError`` with a message
that names the parameter, the value and the rule, e.g. ``"N = 2.5: must be an integer in
1..500"``.  Numerical core: imports numpy only.
"""

from __future__ import annotations

from typing import Any

import numpy as np

__all__ = ["FieldValueError", "choice", "count", "finite", "finite_array", "nonnegative",
           "positive"]


class FieldValueError(ValueError):
    """A ValueError that names the field (a path such as ``"tanks[0].aft"``), the value and the
    rule, so that the input layer can report it under the case's own field name.

    Parameters
    ----------
    field : str
        Path of the field in the object checked.
    value : object
        The value given.
    rule : str
        The rule it breaks, in words.
    """

    def __init__(self, field: str, value: Any, rule: str) -> None:
        self.field = field
        self.value = value
        self.rule = rule
        super().__init__(f"{field} = {value!r}: {rule}")


def finite(name: str, value: Any) -> float:
    """``value`` as a finite float.

    Parameters
    ----------
    name : str
        Parameter name for the message.
    value : float-like
        The value to check.
    """
    try:
        result = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name} = {value!r}: must be a finite number") from None
    if not np.isfinite(result):
        raise ValueError(f"{name} = {value!r}: must be finite")
    return result


def positive(name: str, value: Any) -> float:
    """``value`` as a finite float > 0.

    Parameters
    ----------
    name : str
        Parameter name for the message.
    value : float-like
        The value to check.
    """
    result = finite(name, value)
    if result <= 0.0:
        raise ValueError(f"{name} = {value!r}: must be finite and > 0")
    return result


def nonnegative(name: str, value: Any) -> float:
    """``value`` as a finite float >= 0.

    Parameters
    ----------
    name : str
        Parameter name for the message.
    value : float-like
        The value to check.
    """
    result = finite(name, value)
    if result < 0.0:
        raise ValueError(f"{name} = {value!r}: must be finite and >= 0")
    return result


def count(name: str, value: Any, low: int = 1, high: int | None = 500) -> int:
    """``value`` as an int in ``low..high`` (Python or numpy integers only, not bools or floats).

    Parameters
    ----------
    name : str
        Parameter name for the message.
    value : int
        The value to check.
    low, high : int, int or None
        Smallest and largest allowed values (high None: no upper bound).
    """
    rule = (
        f"must be an integer in {low}..{high}"
        if high is not None
        else f"must be an integer >= {low}"
    )
    if isinstance(value, bool | np.bool_) or not isinstance(value, int | np.integer):
        raise ValueError(f"{name} = {value!r}: {rule}")
    result = int(value)
    if result < low or (high is not None and result > high):
        raise ValueError(f"{name} = {value!r}: {rule}")
    return result


def choice(name: str, value: Any, options: tuple[str, ...]) -> str:
    """``value`` if it is one of ``options``.

    Parameters
    ----------
    name : str
        Parameter name for the message.
    value : str
        The value to check.
    options : tuple of str
        The allowed values.
    """
    if not isinstance(value, str) or value not in options:
        raise ValueError(f"{name} = {value!r}: must be one of {options}")
    return value


def finite_array(name: str, value: Any, *, positive: bool = False,
                 nonempty: bool = True) -> np.ndarray:
    """``np.asarray(value, dtype=float)`` of finite values (> 0 with ``positive``); the ValueError
    quotes the first few values on one line.

    Parameters
    ----------
    name : str
        Parameter name for the message.
    value : array_like
        The values to check (any shape).
    positive : bool
        Also require every value > 0.
    nonempty : bool
        Also require at least one value.
    """
    rule = (f"must be a{' non-empty' if nonempty else 'n'} array of finite values"
            f"{' > 0' if positive else ''}")
    try:
        result = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"{name} = {value!r:.60}: {rule}") from None
    bad = (nonempty and result.size == 0) or not np.all(np.isfinite(result)) or (
        positive and not np.all(result > 0.0))
    if bad:
        flat = result.ravel()
        shown = ", ".join(repr(float(v)) for v in flat[:4]) + (", ..." if flat.size > 4 else "")
        raise ValueError(f"{name}: {rule} (got [{shown}])")
    return result
