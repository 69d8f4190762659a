"""Sweep files: a base case and axes over its fields, parsed and validated before anything runs.

A sweep file (docs/sweeps.md) names a base case (``case``, a path or an inline table), the
``mode`` ("product" or "zip"), the analysis stages and ``[axes]``: dotted case fields with a
list of values or ``{start, stop, num[, scale]}``, units as in case files. Every point is the
base case's raw TOML mapping with each axis value set at its path (``thrust.F0`` and
``thrust.T0`` replace each other), validated by :func:`flexbooster.load_case`. Imports
neither dask nor xarray.
"""

from __future__ import annotations

import copy
import hashlib
import json
import math
import re
import tomllib
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..errors import CaseError

__all__ = [
    "Axis",
    "SweepSpec",
    "MAX_POINTS",
    "MODES",
    "axis_units",
    "parse_axes",
    "load_sweep",
    "make_spec",
    "point_cases",
    "si_value",
]

#: Largest number of points a sweep may have (a guard against a typo such as num = 1e9).
MAX_POINTS = 1_000_000
#: How the axes combine: every combination (outer product) or element by element.
MODES = ("product", "zip")
#: Keys a sweep file may hold at its top level.
_TOP_KEYS = {"case", "axes", "mode", "beam_action", "stability"}
#: Thrust fields of which a case holds exactly one.
_EXCLUSIVE = {"thrust.F0": "thrust.T0", "thrust.T0": "thrust.F0"}
#: SI unit of each case field (the units of results.json's "case" table).
_FIELD_UNITS = {
    "booster.cylinder1.radius": "m",
    "booster.cylinder1.half_length": "m",
    "booster.cylinder2.radius": "m",
    "booster.cylinder2.half_length": "m",
    "booster.thickness": "m",
    "booster.E": "Pa",
    "booster.nu": "1",
    "booster.rho": "kg/m^3",
    "thrust.F0": "N",
    "thrust.T0": "N/m",
    "thrust.gamma": "1",
    "thrust.K": "1",
    "thrust.omega_min": "rad/s",
    "thrust.omega_max": "rad/s",
    "thrust.n_omega": "1",
}
_NUMBER_WITH_UNIT = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")


def axis_units(name: str) -> str:
    """SI unit of a case field: ``"m"``, ``"Pa"``, ``"rad/s"`` ..., ``"1"`` for dimensionless
    numbers and counts, ``""`` for text.

    Parameters
    ----------
    name : str
        Dotted case field, e.g. ``"booster.thickness"``.
    """
    if name.startswith("truncation."):
        return "1"
    return _FIELD_UNITS.get(name, "")


@dataclass(frozen=True)
class Axis:
    """One sweep axis: a case field and its values as written (numbers or strings with units).

    Attributes
    ----------
    name : str
        Dotted case field, e.g. ``"thrust.gamma"``.
    values : tuple
        The values, in order, as the case file would hold them.
    """

    name: str
    values: tuple

    @property
    def units(self) -> str:
        """SI unit of the field (see :func:`axis_units`)."""
        return axis_units(self.name)

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready form: name, values as written, SI units."""
        return {"name": self.name, "values": list(self.values), "units": self.units}


@dataclass(frozen=True)
class SweepSpec:
    """A parsed sweep: base case (raw mapping), axes, combination mode and analysis options.

    Attributes
    ----------
    base : dict
        The base case as its raw TOML mapping.
    axes : tuple of Axis
        The axes, in file order.
    mode : str
        ``"product"`` (one dimension per axis) or ``"zip"`` (equal-length axes element by
        element; one dimension ``point``).
    beam_action, stability : bool
        Flags passed to :func:`flexbooster.analyze` for every point.
    """

    base: dict
    axes: tuple
    mode: str = "product"
    beam_action: bool = True
    stability: bool = True

    @property
    def shape(self) -> tuple[int, ...]:
        """Shape of the result arrays: one length per axis (product) or (n_points,) (zip)."""
        if self.mode == "zip":
            return (len(self.axes[0].values),)
        return tuple(len(axis.values) for axis in self.axes)

    @property
    def dims(self) -> tuple[str, ...]:
        """Dimension names of the result arrays: the axis names (product) or ``("point",)``."""
        return ("point",) if self.mode == "zip" else tuple(a.name for a in self.axes)

    @property
    def n_points(self) -> int:
        """Number of analyses the sweep runs."""
        return math.prod(self.shape)

    def point_values(self, flat: int) -> tuple:
        """Axis values (as written) of the point with flat (C-order) index ``flat``."""
        if self.mode == "zip":
            return tuple(axis.values[flat] for axis in self.axes)
        index = _unravel(flat, self.shape)
        return tuple(axis.values[i] for axis, i in zip(self.axes, index, strict=True))

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready form (what the output's ``sweep_json`` attribute records)."""
        return {
            "base": copy.deepcopy(self.base),
            "axes": [axis.to_dict() for axis in self.axes],
            "mode": self.mode,
            "beam_action": self.beam_action,
            "stability": self.stability,
        }

    def fingerprint(self) -> str:
        """SHA-256 of the canonical JSON of :meth:`to_dict`: a store resumes only its own sweep."""
        text = json.dumps(self.to_dict(), sort_keys=True, separators=(",", ":"), default=str)
        return hashlib.sha256(text.encode("utf-8")).hexdigest()


def _unravel(flat: int, shape: tuple[int, ...]) -> tuple[int, ...]:
    index = []
    for n in reversed(shape):
        flat, i = divmod(flat, n)
        index.append(i)
    return tuple(reversed(index))


def _scalar(value: Any, where: str) -> Any:
    if isinstance(value, bool) or not isinstance(value, int | float | str):
        raise CaseError(where, value, "must be a number or a string with units")
    if isinstance(value, float) and not math.isfinite(value):
        raise CaseError(where, value, "must be finite")
    return value


def _split_unit(value: Any, where: str) -> tuple[float, str]:
    if isinstance(value, bool) or not isinstance(value, int | float | str):
        raise CaseError(where, value, "must be a number or a string with units")
    if isinstance(value, int | float):
        return float(value), ""
    match = _NUMBER_WITH_UNIT.match(value)
    if match is None:
        raise CaseError(where, value, 'must be a number or "number unit", e.g. "10 mm"')
    return float(match.group(1)), match.group(2)


def _range(name: str, table: Mapping[str, Any]) -> tuple:
    where = f"axes.{name}"
    unknown = sorted(set(table) - {"start", "stop", "num", "scale"})
    if unknown:
        raise CaseError(f"{where}.{unknown[0]}", table[unknown[0]], "unknown key")
    for key in ("start", "stop", "num"):
        if key not in table:
            raise CaseError(f"{where}.{key}", None, "required field is missing")
    start, unit = _split_unit(table["start"], f"{where}.start")
    stop, unit_stop = _split_unit(table["stop"], f"{where}.stop")
    if unit != unit_stop:
        raise CaseError(f"{where}.stop", table["stop"], f"must have the unit of start ({unit!r})")
    num = table["num"]
    if isinstance(num, bool) or not isinstance(num, int) or not 1 <= num <= MAX_POINTS:
        raise CaseError(f"{where}.num", num, f"must be an integer in [1, {MAX_POINTS}]")
    scale = table.get("scale", "linear")
    if scale not in ("linear", "log"):
        raise CaseError(f"{where}.scale", scale, 'must be "linear" or "log"')
    for key, value in (("start", start), ("stop", stop)):
        if not math.isfinite(value):
            raise CaseError(f"{where}.{key}", table[key], "must be finite")
        if scale == "log" and not value > 0.0:
            raise CaseError(f"{where}.{key}", table[key], 'must be > 0 with scale = "log"')
    if num == 1:
        values = [start]
    elif scale == "linear":
        # numpy.linspace's formula, start + k (stop - start)/(num - 1), with exact end points
        values = [start + k * (stop - start) / (num - 1) for k in range(num - 1)] + [stop]
    else:
        lo, hi = math.log10(start), math.log10(stop)
        # numpy.logspace's formula, 10^(log10 start + k (log10 stop - log10 start)/(num - 1)),
        # with exact end points
        inner = [10.0 ** (lo + k * (hi - lo) / (num - 1)) for k in range(1, num - 1)]
        values = [start, *inner, stop]
    return tuple(v if not unit else f"{v!r} {unit}" for v in values)


def parse_axes(axes: Mapping[str, Any]) -> tuple[Axis, ...]:
    """Axes from the ``[axes]`` table, in its order (numpy linspace / logspace for ranges);
    CaseError naming ``axes.<field>`` for an empty list, a bad value, a malformed range, or both
    ``thrust.F0`` and ``thrust.T0``.

    Parameters
    ----------
    axes : Mapping
        Dotted case field -> list of values (SI numbers or strings with units), or
        ``{start, stop, num}`` with ``scale = "linear"`` (default) or ``"log"``.
    """
    if not isinstance(axes, Mapping) or not axes:
        raise CaseError("axes", axes, "must be a non-empty table of case field = values")
    out = []
    for name, spec in axes.items():
        where = f"axes.{name}"
        if not isinstance(name, str) or not name or name.startswith(".") or ".." in name:
            raise CaseError("axes", name, "an axis must be a dotted case field name")
        if isinstance(spec, Mapping):
            values = _range(name, spec)
        elif isinstance(spec, Sequence) and not isinstance(spec, str):
            if not spec:
                raise CaseError(where, list(spec), "must hold at least one value")
            values = tuple(_scalar(v, f"{where}[{i}]") for i, v in enumerate(spec))
        else:
            raise CaseError(where, spec, "must be a list of values or {start, stop, num}")
        out.append(Axis(name, values))
    names = {axis.name for axis in out}
    if {"thrust.F0", "thrust.T0"} <= names:
        raise CaseError("axes.thrust.T0", "both", "sweep one of thrust.F0 and thrust.T0, not both")
    return tuple(out)


def make_spec(
    base: Mapping[str, Any] | str | Path,
    axes: Mapping[str, Any],
    *,
    mode: str = "product",
    beam_action: bool = True,
    stability: bool = True,
    base_dir: str | Path | None = None,
) -> SweepSpec:
    """Build and check a :class:`SweepSpec` (point values are checked by :func:`point_cases`);
    CaseError for a missing or unreadable case file, an unknown mode, bad axes, zip axes of
    unequal length, or more than :data:`MAX_POINTS` points.

    Parameters
    ----------
    base : Mapping or str or pathlib.Path
        Raw case mapping, a validated ``Case`` (its SI mapping), or a case file path.
    axes : Mapping
        See :func:`parse_axes`.
    mode : str
        ``"product"`` or ``"zip"``.
    beam_action, stability : bool
        Analysis stages (see :func:`flexbooster.analyze`).
    base_dir : str or pathlib.Path, optional
        Folder against which a relative case path is resolved (default: the working folder).
    """
    raw = _base_mapping(base, base_dir)
    if mode not in MODES:
        raise CaseError("mode", mode, 'must be "product" or "zip"')
    for key, flag in (("beam_action", beam_action), ("stability", stability)):
        if not isinstance(flag, bool):
            raise CaseError(key, flag, "must be true or false")
    parsed = parse_axes(axes)
    if mode == "zip":
        lengths = {axis.name: len(axis.values) for axis in parsed}
        if len(set(lengths.values())) > 1:
            raise CaseError("axes", lengths, 'with mode = "zip" every axis needs as many values')
    spec = SweepSpec(raw, parsed, mode, beam_action, stability)
    if spec.n_points > MAX_POINTS:
        raise CaseError("axes", f"{spec.n_points} points", f"a sweep holds at most {MAX_POINTS}")
    return spec


def _base_mapping(base: Any, base_dir: str | Path | None) -> dict:
    if hasattr(base, "model_dump"):  # a validated Case: its SI values
        return base.model_dump(exclude_none=True)
    if isinstance(base, Mapping):
        return copy.deepcopy(dict(base))
    if isinstance(base, str | Path):
        path = Path(base)
        if base_dir is not None and not path.is_absolute():
            path = Path(base_dir) / path
        try:
            return tomllib.loads(path.read_text(encoding="utf-8"))
        except FileNotFoundError:
            raise CaseError("case", str(path), "file not found") from None
        except (OSError, UnicodeDecodeError) as exc:
            raise CaseError("case", str(path), f"cannot be read ({type(exc).__name__})") from None
        except tomllib.TOMLDecodeError as exc:
            raise CaseError("case", str(path), f"not a valid TOML file ({exc})") from None
    raise CaseError("case", type(base).__name__, "must be a case file path or a [case] table")


def load_sweep(source: str | Path | Mapping[str, Any]) -> SweepSpec:
    """Parse a sweep file (or its parsed mapping) into a :class:`SweepSpec`; CaseError for a
    missing or malformed file, an unknown key, or any rule of :func:`make_spec`.

    Parameters
    ----------
    source : str or pathlib.Path or Mapping
        Path of the sweep TOML file, or the parsed mapping (a relative ``case`` path then
        against the working folder).
    """
    base_dir: Path | None = None
    if isinstance(source, Mapping):
        data = dict(source)
    else:
        path = Path(source)
        base_dir = path.parent
        try:
            data = tomllib.loads(path.read_text(encoding="utf-8"))
        except FileNotFoundError:
            raise CaseError("sweep file", str(path), "file not found") from None
        except (OSError, UnicodeDecodeError) as exc:
            raise CaseError(
                "sweep file", str(path), f"cannot be read ({type(exc).__name__})"
            ) from None
        except tomllib.TOMLDecodeError as exc:
            raise CaseError("sweep file", str(path), f"not a valid TOML file ({exc})") from None
    unknown = sorted(set(data) - _TOP_KEYS)
    if unknown:
        raise CaseError(unknown[0], data[unknown[0]], "unknown key in a sweep file")
    if "case" not in data:
        raise CaseError("case", None, "required: a case file path or an inline [case] table")
    axes = data.get("axes")
    if isinstance(axes, Mapping):
        axes = dict(axes)
    mode = data.get("mode", "product")
    if isinstance(axes, dict) and isinstance(axes.get("mode"), str):
        # `mode` written inside [axes] (accepted as well): no case field is named so
        if "mode" in data:
            raise CaseError("axes.mode", axes["mode"], "give mode once (top level or in [axes])")
        mode = axes.pop("mode")
    return make_spec(
        data["case"],
        axes,
        mode=mode,
        beam_action=data.get("beam_action", True),
        stability=data.get("stability", True),
        base_dir=base_dir,
    )


def _set_path(data: dict, name: str, value: Any) -> None:
    parts = name.split(".")
    node = data
    for i, part in enumerate(parts[:-1]):
        child = node.setdefault(part, {})
        if not isinstance(child, dict):
            raise CaseError(
                f"axes.{name}", value, f"{'.'.join(parts[: i + 1])} is a value, not a table"
            )
        node = child
    node[parts[-1]] = value
    other = _EXCLUSIVE.get(name)
    if other is not None:
        data.get("thrust", {}).pop(other.split(".")[1], None)


def _describe(spec: SweepSpec, flat: int) -> str:
    pairs = ", ".join(
        f"{axis.name} = {value!r}"
        for axis, value in zip(spec.axes, spec.point_values(flat), strict=True)
    )
    return f"sweep point {flat} ({pairs})"


def point_cases(spec: SweepSpec) -> list:
    """Validate every point before anything runs: one case per point in flat C order; CaseError
    at the first invalid point (field, value, rule, the point's index and axis values).

    Parameters
    ----------
    spec : SweepSpec
        The sweep.
    """
    from ..case import load_case

    names = {axis.name for axis in spec.axes}
    try:
        # the base validated once, as SI numbers: a point then parses only its axis values
        # (0.1 ms instead of 6 ms a point: pint parses every unit string); the case is the same
        base = load_case(spec.base).model_dump(exclude_none=True)
    except CaseError:  # the base alone is invalid (an axis may supply the field): point by point
        base = spec.base
    cases = []
    for flat in range(spec.n_points):
        data = copy.deepcopy(base)
        values = spec.point_values(flat)
        for axis, value in zip(spec.axes, values, strict=True):
            _set_path(data, axis.name, value)
        try:
            cases.append(load_case(data))
        except CaseError as exc:
            field = f"axes.{exc.field}" if exc.field in names else exc.field
            raise CaseError(field, exc.value, f"{exc.rule}; at {_describe(spec, flat)}") from None
    return cases


def si_value(case: Any, name: str) -> Any:
    """The SI value of a dotted field of a validated case (``Case.to_si_dict``: F0 and T0 both).

    Parameters
    ----------
    case : flexbooster.Case
        A validated case.
    name : str
        Dotted field, e.g. ``"booster.thickness"``.
    """
    node: Any = case.to_si_dict()
    for part in name.split("."):
        node = node[part]
    return node
