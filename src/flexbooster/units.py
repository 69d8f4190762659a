"""Physical quantities in case files: plain SI numbers or strings with units (pint).

A plain number is in the field's SI unit; a string ("120 in", "10.5e6 psi") is converted by
pint, except that a value in (prefixed) hertz is a cyclic frequency, multiplied by 2 pi on
conversion to rad/s (pint would take 2 Hz as 2 rad/s). Input layer; only
:mod:`flexbooster.case` imports it.
"""

from __future__ import annotations

import math
import sys
from functools import lru_cache
from typing import TYPE_CHECKING

from .checks import choice, finite
from .errors import CaseError

if TYPE_CHECKING:
    import pint

__all__ = ["SI_UNITS", "US_UNITS", "to_si", "to_us"]

#: The inch-pound unit shown beside each SI unit when ``[output] units = "US"``.
US_UNITS: dict[str, str] = {
    "m": "in",
    "Pa": "psi",
    "kg/m^3": "lb/in^3",
    "N": "lbf",
    "N/m": "lbf/in",
    "kg": "lb",
    "kg m^2": "lb*in^2",
}

#: SI unit of each kind of quantity that a case file may hold.
SI_UNITS: dict[str, str] = {
    "length": "m",
    "area": "m^2",
    "second_moment": "m^4",
    "mass": "kg",
    "areal_density": "kg/m^2",
    "moment_of_inertia": "kg*m^2",
    "pressure": "Pa",
    "density": "kg/m^3",
    "force": "N",
    "force_per_length": "N/m",
    "angular_frequency": "rad/s",
    "time": "s",
    "dimensionless": "",
}


@lru_cache(maxsize=1)
def _pint():
    """pint, imported on first use without its optional dask support (``sys.modules["dask"] =
    None`` while it imports, where dask is not imported yet: half of pint's import time).
    """
    hide = "dask" not in sys.modules
    if hide:
        sys.modules["dask"] = None  # type: ignore[assignment]
    try:
        import pint
    finally:
        if hide:
            sys.modules.pop("dask", None)
    return pint


@lru_cache(maxsize=1)
def _registry() -> pint.UnitRegistry:
    # pint's on-disk cache of its parsed definitions (the user cache folder): about 8x faster
    # than parsing them at every start (0.08 s against 0.66 s measured); parsed when the
    # cache cannot be used
    pint = _pint()
    try:
        return pint.UnitRegistry(cache_folder=":auto:")
    except Exception:  # noqa: BLE001 - any cache problem: the uncached registry is equivalent
        return pint.UnitRegistry()


def _is_hertz(quantity: pint.Quantity) -> bool:
    return any("hertz" in name for name in quantity._units)  # noqa: SLF001


def to_si(field: str, value: object, kind: str) -> float:
    """Convert a case value to a float in the SI unit of ``kind`` (rad/s for angular frequencies).
    CaseError for a boolean, an unparsable string, an unknown or wrong-dimension unit, or a
    non-finite value; ValueError for an unknown ``kind``.

    Parameters
    ----------
    field : str
        Dotted name of the field (for the message).
    value : float or int or str
        A plain number (already SI) or a string with units.
    kind : str
        One of the keys of :data:`SI_UNITS`.
    """
    target = SI_UNITS[choice("kind", kind, tuple(SI_UNITS))]
    if isinstance(value, bool):
        raise CaseError(
            field, value, f"must be a number or a string with units of {target or 'nothing'}"
        )
    if isinstance(value, int | float):
        try:
            result = float(value)
        except OverflowError:  # an integer literal of hundreds of digits (TOML allows it)
            raise CaseError(field, value, "must be finite (beyond the float range)") from None
    elif isinstance(value, str):
        ureg = _registry()
        pint = _pint()
        try:
            quantity = ureg.Quantity(value.strip())
        except pint.errors.UndefinedUnitError as exc:
            raise CaseError(
                field, value, f"unknown unit ({exc.unit_names[0] if exc.unit_names else exc})"
            ) from None
        except Exception:  # pint raises several kinds of parse errors
            raise CaseError(field, value, "cannot read this as a number with units") from None
        if not isinstance(quantity, pint.Quantity):  # a bare number in a string
            quantity = ureg.Quantity(float(quantity), "")
        scale = 2.0 * math.pi if (kind == "angular_frequency" and _is_hertz(quantity)) else 1.0
        try:
            result = float(quantity.to(target).magnitude) * scale
        except OverflowError:
            raise CaseError(field, value, "must be finite (beyond the float range)") from None
        except pint.errors.DimensionalityError:
            expected = f"units of {target}" if target else "no units"
            raise CaseError(field, value, f"wrong dimension: expected {expected}") from None
    else:
        raise CaseError(
            field, value, f"must be a number or a string with units of {target or 'nothing'}"
        )
    if not math.isfinite(result):
        raise CaseError(field, value, "must be finite")
    return result


def to_us(value: float, si_unit: str) -> tuple[float, str] | None:
    """(value, unit name) in the inch-pound unit of an SI unit of :data:`US_UNITS`, None without a
    counterpart; ValueError for a non-finite value or result.

    Parameters
    ----------
    value : float
        The value in ``si_unit``.
    si_unit : str
        One of the keys of :data:`US_UNITS` ("m", "Pa", "kg/m^3", "N", "N/m", "kg", "kg m^2").
    """
    value = finite("value", value)
    if not isinstance(si_unit, str):
        raise ValueError(f"si_unit = {si_unit!r}: must be a string (a unit such as 'm')")
    us = US_UNITS.get(si_unit)
    if us is None:
        return None
    ureg = _registry()
    quantity = ureg.Quantity(value, si_unit.replace(" ", "*"))
    result = float(quantity.to(us).magnitude)
    if not math.isfinite(result):
        raise ValueError(f"value = {value!r}: {si_unit} -> {us} is beyond the float range")
    return result, us
