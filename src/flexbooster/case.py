"""Case files: TOML input validated by pydantic, physical values converted to SI by pint.

One vehicle per case: ``[booster]`` (``cylinder1``, ``cylinder2``: the memo's two bare
cylinders) or ``[vehicle]`` with ``[[vehicle.segments]]``, never both; then ``[thrust]``
(needed by ``run``, not by ``modes``), ``[truncation]`` and the optional tables. The embedded
default case (``flexbooster init``: a launch vehicle through its flight) and memo case
(``flexbooster init --memo``: the memo's two cylinders) document every field. A
value is an SI number or a string with units. Invalid input raises
:class:`~flexbooster.errors.CaseError` naming the field, the value and the rule.
"""

from __future__ import annotations

import math
import os
import stat
import tomllib
from collections.abc import Mapping
from importlib import resources
from pathlib import Path
from typing import Any, Literal

import numpy as np
from pydantic import BaseModel, ConfigDict, StrictInt, ValidationError, field_validator

from .errors import AnalysisWarning, CaseError
from .flight_case import FlightTable, check_flight
from .units import to_si
from .vehicle_case import REGION_DAMPING_RATIO, VehicleTable, check_vehicle

__all__ = [
    "Cylinder",
    "Booster",
    "Thrust",
    "Truncation",
    "Damping",
    "SpectrumLine",
    "OutputStation",
    "Output",
    "SeverityTable",
    "Case",
    "MAX_MODES",
    "vehicle_length",
    "MODAL_DAMPING_RATIO",
    "DEPRECATED_KEYS",
    "deprecation_warnings",
    "load_case",
    "default_case",
    "default_case_text",
    "memo_case",
    "memo_case_text",
]

#: Largest mode count, harmonic count or grid size a case may ask for (each index).
MAX_MODES = 500
#: Largest number of points of the Omega grid.
MAX_GRID = 100_000

#: Default damping ratio of every elastic mode (``damping.modal_ratio``).
MODAL_DAMPING_RATIO = REGION_DAMPING_RATIO
#: Keys kept for old case files: (deprecated key, key that replaces it). Each one given is
#: used for its modes (over ``damping.modal_ratio``), with a ``deprecated-key`` warning
#: (:func:`deprecation_warnings`).
DEPRECATED_KEYS = (("damping.beam_modal_ratio", "damping.modal_ratio"),
                   ("vehicle.damping_ratio", "damping.modal_ratio"))

_FROZEN = ConfigDict(extra="forbid", frozen=True)


def _quantity(kind: str, positive: bool = True):
    """A 'before' validator: number or string with units -> float in SI, optionally > 0."""

    def convert(cls, value: Any, info) -> float:  # noqa: ANN001
        result = to_si(info.field_name, value, kind)
        if positive and not result > 0.0:
            raise ValueError("must be positive")
        return result

    return convert


def _fraction(rule: str):
    """A 'before' validator: a dimensionless number in [0, 1), else ``rule``."""

    def convert(cls, value: Any, info) -> float:  # noqa: ANN001
        result = to_si(info.field_name, value, "dimensionless")
        if not 0.0 <= result < 1.0:
            raise ValueError(rule)
        return result

    return convert


class Cylinder(BaseModel):
    """One thin cylindrical shell of the composite.

    Attributes
    ----------
    radius : float
        Mid-surface radius R_d (m), > 0.
    half_length : float
        Half-length L_d (m), > 0; the cylinder is 2 L_d long.
    """

    model_config = _FROZEN
    radius: float
    half_length: float

    _length = field_validator("radius", "half_length", mode="before")(_quantity("length"))


class Booster(BaseModel):
    """The two-cylinder composite: cylinder 1 aft (thrust end), cylinder 2 forward.

    Attributes
    ----------
    cylinder1, cylinder2 : Cylinder
        Geometry of each shell.
    thickness : float
        Shell thickness h (m), the same for both (memo 2.2), 0 < h < R_d.
    E, nu, rho : float
        Young's modulus (Pa) > 0, Poisson's ratio in (0, 0.5), density (kg/m^3) > 0.
    """

    model_config = _FROZEN
    cylinder1: Cylinder
    cylinder2: Cylinder
    thickness: float
    E: float
    nu: float
    rho: float

    _h = field_validator("thickness", mode="before")(_quantity("length"))
    _E = field_validator("E", mode="before")(_quantity("pressure"))
    _rho = field_validator("rho", mode="before")(_quantity("density"))

    @field_validator("nu", mode="before")
    @classmethod
    def _nu(cls, value: Any) -> float:
        result = to_si("nu", value, "dimensionless")
        if not 0.0 < result < 0.5:
            raise ValueError("Poisson's ratio must lie in (0, 0.5)")
        return result


class SpectrumLine(BaseModel):
    """One ``[[thrust.spectrum]]`` row: a line of the oscillation, Delta F = a F0 cos(Omega t).

    Attributes
    ----------
    frequency : float
        Omega of the line (rad/s; "Hz" values are cyclic, times 2 pi), > 0.
    amplitude : float
        a, the line's amplitude as a fraction of F0, 0 <= a < 1.
    """

    model_config = _FROZEN
    frequency: float
    amplitude: float

    _frequency = field_validator("frequency", mode="before")(_quantity("angular_frequency"))
    _amplitude = field_validator("amplitude", mode="before")(
        _fraction("must lie in [0, 1) (a fraction of F0)"))


class Thrust(BaseModel):
    """The gimbaled pulsating end thrust T(t) = T0 (1 - gamma cos Omega t) (memo 2.2-2); exactly
    one of ``F0`` and ``T0`` (F0 = 2 pi R1 T0).

    Attributes
    ----------
    F0, T0 : float or None
        Total steady thrust (N) or per unit circumference of the aft edge (N/m), > 0.
    gamma : float
        Relative pulsation amplitude, 0 <= gamma < 1.
    K : float
        Gimbal gain, >= 0: the thrust turns by K psi.
    omega_min, omega_max : float
        Range of Omega (rad/s; "Hz" values are cyclic, times 2 pi), 0 < omega_min < omega_max.
    n_omega : int
        Points of the uniform Omega grid, 2..100000.
    misalignment : float
        Angle delta between the thrust line and the axis (rad; "deg" accepted), |delta| < pi/2,
        default 0: the forced response's lateral (k = 1) load is sin(delta) Delta F.
    spectrum : tuple of SpectrumLine or None
        Lines of the thrust oscillation for the forced response, instead of gamma over the
        Omega range; frequencies strictly increasing.
    duration : float or None
        How long the pulsation lasts (s), > 0, finite: the amplification exp(sigma T) of each
        band over it; None (default): the verdict speaks of e-folding times only.
    """

    model_config = _FROZEN
    F0: float | None = None
    T0: float | None = None
    gamma: float
    K: float
    omega_min: float
    omega_max: float
    n_omega: StrictInt = 401
    misalignment: float = 0.0
    spectrum: tuple[SpectrumLine, ...] | None = None

    @field_validator("misalignment", mode="before")
    @classmethod
    def _misalignment(cls, value: Any) -> float:
        result = to_si("misalignment", value, "dimensionless")  # radians
        if not abs(result) < math.pi / 2.0:
            raise ValueError("must be an angle in (-pi/2, pi/2) rad")
        return result
    duration: float | None = None

    _F0 = field_validator("F0", mode="before")(_quantity("force"))
    _duration = field_validator("duration", mode="before")(_quantity("time"))
    _T0 = field_validator("T0", mode="before")(_quantity("force_per_length"))
    _omega = field_validator("omega_min", "omega_max", mode="before")(
        _quantity("angular_frequency")
    )

    _gamma = field_validator("gamma", mode="before")(
        _fraction("must lie in [0, 1) so that the thrust stays positive"))

    @field_validator("K", mode="before")
    @classmethod
    def _K(cls, value: Any) -> float:
        result = to_si("K", value, "dimensionless")
        if result < 0.0:
            raise ValueError("gimbal gain must be >= 0 (directional control, memo 2.2-2c)")
        return result

    @field_validator("n_omega")
    @classmethod
    def _n_omega(cls, value: int) -> int:
        if not 2 <= value <= MAX_GRID:
            raise ValueError(f"must be an integer in [2, {MAX_GRID}]")
        return value


class Truncation(BaseModel):
    """Series truncation (memo 4.1, 5.2, 7).

    Attributes
    ----------
    M1, N1, M2, N2 : int
        Shell modes of cylinder 1 and 2: j = 0..M_d axial, k = 0..N_d circumferential;
        each in [1, 500].
    N : int
        Elastic free-free beam modes, [1, 500].
    S : int
        Harmonics s = -S..S of the Floquet (Hill) expansion (4.1-10/11), [0, 500].
    R : int
        Beam-action exponents alpha_r reported, r = 1..R, [1, N + 1].
    """

    model_config = _FROZEN
    M1: StrictInt = 10
    N1: StrictInt = 10
    M2: StrictInt = 10
    N2: StrictInt = 10
    N: StrictInt = 10
    S: StrictInt = 10
    R: StrictInt = 4

    @field_validator("M1", "N1", "M2", "N2", "N", "R")
    @classmethod
    def _count(cls, value: int) -> int:
        if not 1 <= value <= MAX_MODES:
            raise ValueError(f"must be an integer in [1, {MAX_MODES}]")
        return value

    @field_validator("S")
    @classmethod
    def _harmonics(cls, value: int) -> int:
        if not 0 <= value <= MAX_MODES:
            raise ValueError(f"must be an integer in [0, {MAX_MODES}]")
        return value


class Damping(BaseModel):
    """Viscous modal damping of every mechanism (table ``[damping]``).

    Attributes
    ----------
    modal_ratio : float
        Damping ratio zeta of every elastic mode of every mechanism: the memo's beam modes
        (beam action), the vehicle's loaded modes (parametric regions), 0 <= zeta < 1, default
        :data:`MODAL_DAMPING_RATIO`; 0 gives the memo's undamped idealisation.
    pitch_ratio : float
        Damping ratio of the rigid-body pitch, 0 <= zeta < 1, default 0.
    beam_modal_ratio : float or None
        Deprecated name of the beam modes' ratio (:data:`DEPRECATED_KEYS`): used for the beam
        modes when given, with a warning naming ``damping.modal_ratio``.
    """

    model_config = _FROZEN
    modal_ratio: float = MODAL_DAMPING_RATIO
    pitch_ratio: float = 0.0
    beam_modal_ratio: float | None = None

    @field_validator("modal_ratio", "beam_modal_ratio", "pitch_ratio", mode="before")
    @classmethod
    def _ratio(cls, value: Any, info) -> float:  # noqa: ANN001
        result = to_si(info.field_name, value, "dimensionless")
        if not 0.0 <= result < 1.0:
            raise ValueError("damping ratio must lie in [0, 1)")
        return result

    @property
    def beam_ratio(self) -> float:
        """Damping ratio of the memo's elastic beam modes: ``modal_ratio``, or the deprecated
        ``beam_modal_ratio`` where given."""
        return self.modal_ratio if self.beam_modal_ratio is None else self.beam_modal_ratio


class OutputStation(BaseModel):
    """One ``[[output.stations]]`` row: a station of the forced response.

    Attributes
    ----------
    name : str
        Label in the outputs, unique, not one of the automatic names ("aft-edge",
        "forward-edge", "junction-i").
    station : float
        Axial distance from the aft edge (m), in [0, the vehicle's length].
    """

    model_config = _FROZEN
    name: str
    station: float

    _station = field_validator("station", mode="before")(_quantity("length", positive=False))

    @field_validator("name")
    @classmethod
    def _name(cls, value: str) -> str:
        if not value.strip():
            raise ValueError("must be a non-empty name")
        return value


class Output(BaseModel):
    """How the summary and the report show values (``[output]``).

    Attributes
    ----------
    units : str
        ``"SI"`` (default): SI only; ``"US"``: the inputs and mass properties also in
        inch-pound units (in, psi, lbf, lb, ...) beside SI.  The analysis is SI either way.
    stations : tuple of OutputStation
        Stations of the forced response besides the edges, junctions and lumped masses.
    """

    model_config = _FROZEN
    units: Literal["SI", "US"] = "SI"
    stations: tuple[OutputStation, ...] = ()
class SeverityTable(BaseModel):
    """Optional reference amplitudes and thresholds of the severity (table ``[severity]``;
    docs/theory/severity.md).

    Attributes
    ----------
    psi0 : float
        Reference initial pitch angle psi(0) (rad), default 0.01.
    beam_amplitude : float
        Reference norm of the beam Floquet vector (units of L), >= 0, default 1e-4.
    threshold : float
        severity_rel at and above which a root is "active", in [0, 1], default 1e-6.
    resolution : float
        Relative resolution in Omega within which active roots merge, in (0, 1), default 0.005.
    """

    model_config = _FROZEN
    psi0: float = 0.01
    beam_amplitude: float = 1e-4
    threshold: float = 1e-6
    resolution: float = 0.005

    @field_validator("psi0", "beam_amplitude", "threshold", "resolution", mode="before")
    @classmethod
    def _severity_value(cls, value: Any, info) -> float:  # noqa: ANN001
        result = to_si(info.field_name, value, "dimensionless")
        name = info.field_name
        if name == "beam_amplitude" and result < 0.0:
            raise ValueError("must be >= 0")
        if name == "threshold" and not 0.0 <= result <= 1.0:
            raise ValueError("must lie in [0, 1]")
        if name == "resolution" and not 0.0 < result < 1.0:
            raise ValueError("must lie in (0, 1)")
        return result


class Case(BaseModel):
    """A validated analysis case, all values in SI.

    Attributes
    ----------
    name : str
        A label for reports.
    booster : Booster or None
        The memo's two bare cylinders; None for a case whose vehicle is
        ``[[vehicle.segments]]`` (exactly one of the two is given).
    thrust : Thrust or None
        The pulsating thrust; None only for the unloaded modes (``flexbooster modes``).
    truncation : Truncation
        Series truncation of the memo's method.
    damping, severity : Damping, SeverityTable
        Optional tables (1 % modal damping, undamped rigid pitch by default).
    vehicle : VehicleTable or None
        The optional ``[vehicle]`` table (:mod:`flexbooster.vehicle_case`).
    flight : FlightTable or None
        The optional ``[flight]`` table (:mod:`flexbooster.flight_case`).
    output : Output
        Optional ``[output]``: ``units = "SI" | "US"`` of the summary and report.
    max_seconds : float
        Budget of the analysis (s), > 0, default 300: a case whose estimated run time exceeds
        it is refused before it starts.
    """

    model_config = _FROZEN
    name: str = "case"
    max_seconds: float = 300.0
    booster: Booster | None = None
    thrust: Thrust | None = None
    truncation: Truncation = Truncation()
    damping: Damping = Damping()
    vehicle: VehicleTable | None = None
    flight: FlightTable | None = None  # flexbooster.flight_case
    output: Output = Output()

    @field_validator("max_seconds", mode="before")
    @classmethod
    def _max_seconds(cls, value: Any) -> float:
        result = to_si("max_seconds", value, "dimensionless")  # seconds
        if not (math.isfinite(result) and result > 0.0):
            raise ValueError("must be a finite time > 0 (s)")
        return result
    severity: SeverityTable = SeverityTable()

    @property
    def has_segments(self) -> bool:
        """True when the vehicle is ``[[vehicle.segments]]`` (not the memo's ``[booster]``)."""
        return self.vehicle is not None and self.vehicle.segments is not None

    @property
    def aft_radius(self) -> float:
        """Mid-surface radius of the aft edge, where the thrust acts (m): R1 of ``[booster]`` or
        the first segment's aft radius."""
        if self.booster is not None:
            return self.booster.cylinder1.radius
        return self.vehicle.segments[0].r_aft

    @property
    def F0(self) -> float:
        """Total steady thrust F0 = 2 pi R_aft T0 (N); CaseError on ``thrust`` without it."""
        t = self.required_thrust()
        if t.F0 is not None:
            return t.F0
        return 2.0 * math.pi * self.aft_radius * t.T0

    @property
    def T0(self) -> float:
        """Steady thrust per unit circumference of the aft edge (N/m); CaseError on ``thrust``
        without it."""
        t = self.required_thrust()
        if t.T0 is not None:
            return t.T0
        return t.F0 / (2.0 * math.pi * self.aft_radius)

    def required_thrust(self) -> Thrust:
        """The ``[thrust]`` table; CaseError on ``thrust`` when the case has none."""
        if self.thrust is None:
            raise CaseError("thrust", None, "required field is missing (the analysis needs "
                            "the thrust; 'flexbooster modes' gives the unloaded modes without)")
        return self.thrust

    @property
    def vehicle_damping_ratio(self) -> float:
        """Damping ratio of the vehicle's loaded modes: ``damping.modal_ratio``, or the
        deprecated ``vehicle.damping_ratio`` where given."""
        v = self.vehicle
        return self.damping.modal_ratio if v is None or v.damping_ratio is None \
            else v.damping_ratio

    def omega_grid(self) -> np.ndarray:
        """The uniform grid of thrust pulsation frequencies Omega (rad/s)."""
        t = self.required_thrust()
        return np.linspace(t.omega_min, t.omega_max, t.n_omega)

    def to_si_dict(self) -> dict[str, Any]:
        """The case as plain SI numbers (what results.json records as its input)."""
        data = self.model_dump()
        for key in ("booster", "thrust"):  # the one vehicle: [booster] or [vehicle] segments
            if data.get(key) is None:
                data.pop(key, None)
        if self.thrust is not None:
            data["thrust"]["F0"] = self.F0
            data["thrust"]["T0"] = self.T0
        if data.get("vehicle") is None:  # no [vehicle]: results.json as before
            data.pop("vehicle", None)
        if not data.get("output", {}).get("stations", True):
            data["output"].pop("stations")
        if data.get("flight") is None:  # no [flight]: results.json as before
            data.pop("flight", None)
        if data.get("output") == {"units": "SI"}:  # the default [output]: as before
            data.pop("output", None)
        return data


def _describe(loc: tuple) -> str:
    if not loc:
        return "case"
    out = ""
    for part in loc:  # list indices as [i]: vehicle.segments[1].radius_aft
        out += f"[{part}]" if isinstance(part, int) else (f".{part}" if out else str(part))
    return out


def _model_at(loc: tuple) -> type[BaseModel] | None:
    """The pydantic model that holds the key at ``loc`` (None if it cannot be found)."""
    model: type[BaseModel] | None = Case
    for part in loc[:-1]:
        if isinstance(part, int) or model is None:
            continue
        info = model.model_fields.get(str(part))
        if info is None:
            return None
        model = _find_model(info.annotation)
    return model


def _find_model(annotation: object) -> type[BaseModel] | None:
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return annotation
    for arg in getattr(annotation, "__args__", ()):
        found = _find_model(arg)
        if found is not None:
            return found
    return None


def _unknown_key(loc: tuple, value: object) -> CaseError:
    """'unknown key 'gama' (did you mean 'gamma'?)' (difflib), a table named, not dumped."""
    import difflib

    field, key = _describe(loc), str(loc[-1])
    model = _model_at(loc)
    known = sorted(model.model_fields) if model is not None else []
    what = "table" if isinstance(value, Mapping) else "key"
    close = difflib.get_close_matches(key, known, n=1, cutoff=0.6)
    hint = f" (did you mean '{close[0]}'?)" if close else (
        f" (known: {', '.join(known)})" if known else "")
    rule = f"unknown {what} '{key}'{hint}"
    return CaseError(field, "table" if what == "table" else value, rule,
                     message=f"{field}: {rule}")


def _from_validation_error(exc: ValidationError) -> CaseError:
    """The first pydantic error as a one-line CaseError (an unknown key before a missing one; a
    CaseError raised in a validator kept as it is).
    """
    errors = exc.errors(include_url=False)
    err = next((e for e in errors if e["type"] == "extra_forbidden"), errors[0])
    field = _describe(err["loc"])
    kind = err["type"]
    value = err.get("input")
    if kind == "missing":
        return CaseError(field, None, "required field is missing")
    if kind == "extra_forbidden":
        return _unknown_key(tuple(err["loc"]), value)
    inner = (err.get("ctx") or {}).get("error")
    if isinstance(inner, CaseError):  # from to_si: the value once, its rule
        return CaseError(field, inner.value, inner.rule)
    message = err["msg"].removeprefix("Value error, ")
    if kind == "literal_error":
        message = f"must be {(err.get('ctx') or {}).get('expected', 'one of the choices')}"
    elif kind in ("int_type", "int_from_float", "int_parsing"):
        message = "must be a whole number (integer)"
    elif kind == "model_type":
        message = "must be a table"
    return CaseError(field, value, message)


def _cross_checks(case: Case) -> None:
    """Rules that involve more than one field."""
    _one_vehicle(case)
    b, t, n = case.booster, case.thrust, case.truncation
    if t is not None and (t.F0 is None) == (t.T0 is None):
        given = "both" if t.F0 is not None else "neither"
        raise CaseError(
            "thrust.F0/thrust.T0",
            given,
            "give exactly one of F0 (total) and T0 (per unit circumference)",
        )
    for d, cyl in () if b is None else ((1, b.cylinder1), (2, b.cylinder2)):
        if not b.thickness < cyl.radius:
            raise CaseError(
                "booster.thickness",
                b.thickness,
                f"must be smaller than cylinder{d}.radius = {cyl.radius!r} m",
            )
    if t is not None and not t.omega_min < t.omega_max:
        raise CaseError(
            "thrust.omega_min",
            t.omega_min,
            f"must be smaller than thrust.omega_max = {t.omega_max!r} rad/s",
        )
    if n.R > n.N + 1:
        raise CaseError(
            "truncation.R",
            n.R,
            f"must not exceed N + 1 = {n.N + 1} (rigid rotation plus N elastic modes)",
        )
    # without [booster] the table has segments, which do not read the radii
    radii = (math.nan, math.nan) if b is None else (b.cylinder1.radius, b.cylinder2.radius)
    check_vehicle(case.vehicle, booster_radii=radii)
    if b is None:
        _segment_materials(case.vehicle)
    _check_forced_inputs(case)
    check_flight(case.flight, n_tanks=len(case.vehicle.tanks) if case.vehicle else 0)


def _one_vehicle(case: Case) -> None:
    """One vehicle per case: ``[booster]`` or ``[vehicle]`` with segments, never both, never
    neither (a ``[vehicle]`` without segments only tunes the memo vehicle of ``[booster]``)."""
    if case.booster is not None and case.has_segments:
        raise CaseError("booster/vehicle.segments", "both",
                        "a case describes one vehicle: give [booster] (the memo's two bare "
                        "cylinders) or [vehicle] with [[vehicle.segments]], not both")
    if case.booster is None and not case.has_segments:
        raise CaseError("booster", None, "required field is missing (or give [vehicle] with "
                        "[[vehicle.segments]])")


def _segment_materials(table: VehicleTable) -> None:
    """Without ``[booster]`` every segment needs E, nu and rho, its own or ``[vehicle]``'s."""
    for name in ("E", "nu", "rho"):
        if getattr(table, name) is not None:
            continue
        for i, seg in enumerate(table.segments):
            if getattr(seg, name) is None:
                raise CaseError(f"vehicle.segments[{i}].{name}", None,
                                f"required field is missing (or give vehicle.{name} for every "
                                "segment; a case without [booster] has no default material)")


def vehicle_length(case: Case) -> float:
    """Axial length of the case's vehicle (m): the sum of its segments' lengths, or 2 (L1 + L2)
    of the memo vehicle.

    Parameters
    ----------
    case : Case
        A validated case.
    """
    table, b = case.vehicle, case.booster
    if table is None or table.segments is None:
        return 2.0 * (b.cylinder1.half_length + b.cylinder2.half_length)
    return float(sum(seg.length for seg in table.segments))


def _check_forced_inputs(case: Case) -> None:
    """``[[thrust.spectrum]]`` frequencies strictly increasing; ``[[output.stations]]`` on the
    vehicle with names of their own."""
    lines = None if case.thrust is None else case.thrust.spectrum
    if lines is not None:
        if not lines:
            raise CaseError("thrust.spectrum", [], "at least one line is needed")
        for i in range(1, len(lines)):
            if not lines[i].frequency > lines[i - 1].frequency:
                raise CaseError(f"thrust.spectrum[{i}].frequency", lines[i].frequency,
                                "must be larger than the previous line's "
                                f"({lines[i - 1].frequency!r} rad/s): lines in increasing "
                                "frequency, each once")
    length = vehicle_length(case)
    n_seg = 2 if case.vehicle is None or case.vehicle.segments is None else len(
        case.vehicle.segments)
    taken = {"aft-edge", "forward-edge"} | {f"junction-{i}" for i in range(1, n_seg)}
    for i, st in enumerate(case.output.stations):
        if not 0.0 <= st.station <= length:
            raise CaseError(f"output.stations[{i}].station", st.station,
                            f"must lie on the vehicle: 0 <= station <= {length!r} m (its "
                            "length)")
        if st.name in taken:
            raise CaseError(f"output.stations[{i}].name", st.name,
                            "must differ from the other stations' names (and from aft-edge, "
                            "forward-edge, junction-i)")
        taken.add(st.name)


def _deprecated_given(case: Case) -> list[tuple[str, float]]:
    """(key, value) of each deprecated key of :data:`DEPRECATED_KEYS` the case gives."""
    given = {"damping.beam_modal_ratio": case.damping.beam_modal_ratio,
             "vehicle.damping_ratio": None if case.vehicle is None
             else case.vehicle.damping_ratio}
    return [(key, given[key]) for key, _ in DEPRECATED_KEYS if given[key] is not None]


def deprecation_warnings(case: Case) -> list[AnalysisWarning]:
    """A ``deprecated-key`` warning for each deprecated key the case gives, naming the key
    that replaces it (:data:`DEPRECATED_KEYS`).

    Parameters
    ----------
    case : Case
        A validated case.
    """
    new = dict(DEPRECATED_KEYS)
    return [AnalysisWarning("deprecated-key", key,
                            f"{key} = {value:g} is deprecated: write {new[key]} (the damping "
                            "ratio of every elastic mode); the value given is used for "
                            + ("the beam modes" if key.startswith("damping") else
                               "the vehicle's modes"))
            for key, value in _deprecated_given(case)]


def _validate(data: Mapping[str, Any]) -> Case:
    if not isinstance(data, Mapping):
        raise CaseError("case", type(data).__name__, "must be a table (mapping)")
    try:
        case = Case.model_validate(dict(data))
    except ValidationError as exc:
        raise _from_validation_error(exc) from None
    _cross_checks(case)
    return case


def load_case(source: str | Path | Mapping[str, Any]) -> Case:
    """Load and validate a case from a TOML file or a mapping (CaseError for a missing file, a
    path that is not a regular file (a folder, a FIFO, a device, a symlink loop), a file that is
    not UTF-8 TOML, or any invalid field; a leading UTF-8 byte-order mark is skipped; TypeError
    for a ``source`` of another type).

    Parameters
    ----------
    source : str or pathlib.Path or Mapping
        Path of a TOML case file, or the already-parsed mapping.
    """
    if isinstance(source, Mapping):
        return _validate(source)
    if not isinstance(source, str | os.PathLike):
        raise TypeError(f"source = {source!r:.60}: must be a path (str or os.PathLike) or a "
                        f"mapping, not {type(source).__name__}")
    path = Path(source)
    try:
        # stat first: opening a FIFO or a device would block or read without end (but a pipe
        # that is this process's standard input, e.g. /dev/stdin, has its writer)
        info = path.stat()
        if not stat.S_ISREG(info.st_mode) and not _is_standard_input(info):
            raise CaseError("case file", str(path), "must be a regular file (not a folder, a "
                            "FIFO or a device)")
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise CaseError("case file", str(path), "file not found") from None
    except (OSError, UnicodeDecodeError) as exc:  # a symlink loop, a name too long, no access
        reason = exc.strerror if isinstance(exc, OSError) and exc.strerror else type(exc).__name__
        raise CaseError("case file", str(path), f"cannot be read as text ({reason})") from None
    try:
        data = tomllib.loads(text.removeprefix("\ufeff"))  # a byte-order mark (some editors)
    except tomllib.TOMLDecodeError as exc:
        raise CaseError("case file", str(path), f"not a valid TOML file ({exc})") from None
    return _validate(data)


def _is_standard_input(info: os.stat_result) -> bool:
    """``info`` (a ``stat``) is a pipe that is this process's standard input."""
    try:
        return stat.S_ISFIFO(info.st_mode) and os.path.samestat(info, os.fstat(0))
    except OSError:  # no standard input
        return False


def _packaged(name: str) -> str:
    return resources.files("flexbooster").joinpath(f"data/{name}").read_text("utf-8")


def default_case_text() -> str:
    """The embedded default case file, with a comment on every field: a Titan-II-like
    two-stage liquid launch vehicle (``[vehicle]`` with tanks) through its first-stage burn
    (``[flight]``), the source of each number tagged in the file."""
    return _packaged("default_case.toml")


def default_case() -> Case:
    """The embedded default case (:func:`default_case_text`), validated."""
    return _validate(tomllib.loads(default_case_text()))


def memo_case_text() -> str:
    """The embedded memo case file, with a comment on every field: a Saturn-class booster as
    the memo's two bare cylinders (``[booster]``, Tech Memo 104 Fig. 1)."""
    return _packaged("memo_case.toml")


def memo_case() -> Case:
    """The embedded memo case (:func:`memo_case_text`), validated."""
    return _validate(tomllib.loads(memo_case_text()))
