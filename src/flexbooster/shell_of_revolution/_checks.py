"""Argument checks of the shell-of-revolution package (numpy only).

Each check returns the converted value or raises ``ValueError("name = value: rule")``.
"""

from __future__ import annotations

from typing import Any

import numpy as np

__all__ = ["finite", "positive", "nonnegative", "integer", "choice"]


def finite(name: str, value: Any) -> float:
    """``value`` as a finite float (``ValueError`` otherwise)."""
    try:
        result = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name} = {value!r}: must be a finite number") from None
    if not np.isfinite(result):
        raise ValueError(f"{name} = {value!r}: must be finite")
    return result


def positive(name: str, value: Any) -> float:
    """``value`` as a finite float > 0."""
    result = finite(name, value)
    if result <= 0.0:
        raise ValueError(f"{name} = {value!r}: must be finite and > 0")
    return result


def nonnegative(name: str, value: Any) -> float:
    """``value`` as a finite float >= 0."""
    result = finite(name, value)
    if result < 0.0:
        raise ValueError(f"{name} = {value!r}: must be finite and >= 0")
    return result


def integer(name: str, value: Any, low: int, high: int) -> int:
    """``value`` as an int in ``low..high`` (no bools, no floats)."""
    if isinstance(value, bool) or not isinstance(value, int | np.integer):
        raise ValueError(f"{name} = {value!r}: must be an integer in {low}..{high}")
    if not low <= int(value) <= high:
        raise ValueError(f"{name} = {value!r}: must be an integer in {low}..{high}")
    return int(value)


def choice(name: str, value: Any, options: tuple[str, ...]) -> str:
    """``value`` if it is one of ``options``."""
    if not isinstance(value, str) or value not in options:
        raise ValueError(f"{name} = {value!r}: must be one of {options}")
    return value
