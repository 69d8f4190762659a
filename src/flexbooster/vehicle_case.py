"""The optional ``[vehicle]`` table of a case file: the vehicle as one shell of revolution.

``[[vehicle.segments]]`` lists cylinders and cones from the aft edge forward
(:class:`flexbooster.shell_of_revolution.Vehicle`); without segments the vehicle is the
memo's two cylinders of ``[booster]`` joined by a "memo-bulkhead" with "shear-diaphragm"
ends (Tech Memo 104, sec. 5.3, Fig. 1), of which the table may change the junction, the ends,
the theory, ``k_max`` and the regions' ``damping_ratio`` and ``n_modes``. An invalid field
raises :class:`~flexbooster.errors.CaseError` naming it, e.g.
``vehicle.segments[1].radius_aft``.
"""

from __future__ import annotations

import math
from typing import Any

from pydantic import BaseModel, ConfigDict, StrictInt, field_validator

from .errors import CaseError
from .units import to_si

__all__ = [
    "SEGMENT_KINDS",
    "VEHICLE_ENDS",
    "VEHICLE_JUNCTIONS",
    "VEHICLE_THEORIES",
    "MEMO_JUNCTION",
    "MEMO_END",
    "K_MAX_LIMIT",
    "RADIUS_RTOL",
    "REGION_DAMPING_RATIO",
    "REGION_N_MODES",
    "REGION_N_MODES_LIMIT",
    "VehicleStiffeners",
    "VehicleSegment",
    "VehicleMass",
    "VehicleTankTable",
    "VehicleTable",
    "check_vehicle",
]

#: Segment kinds of ``[[vehicle.segments]]``.
SEGMENT_KINDS = ("cylinder", "cone")
#: End conditions of ``vehicle.aft_end`` / ``vehicle.fwd_end``.
VEHICLE_ENDS = ("free", "shear-diaphragm", "clamped", "hinged")
#: Junctions: per segment (its aft edge) or, for the memo vehicle, ``vehicle.junction``.
VEHICLE_JUNCTIONS = ("continuous", "rigid-bulkhead", "memo-bulkhead")
#: Shell theories.
VEHICLE_THEORIES = ("sanders", "donnell")
#: Junction of the memo vehicle built from ``[booster]`` (the memo's disc, Fig. 1).
MEMO_JUNCTION = "memo-bulkhead"
#: Ends of the memo vehicle: the memo's end bulkheads, v = w = 0 (memo eqs. 5.3-2, 5.3-3).
MEMO_END = "shear-diaphragm"
#: Largest circumferential wave number a case may ask for.
K_MAX_LIMIT = 200
#: Relative tolerance on the radii where two segments meet at a continuous junction.
RADIUS_RTOL = 1e-6

#: Default modal damping ratio of every elastic mode (``damping.modal_ratio``).
REGION_DAMPING_RATIO = 0.01
#: Default modes per harmonic k in the regions' modal basis (``vehicle.n_modes``).
REGION_N_MODES = 20
#: Largest ``vehicle.n_modes`` a case may ask for.
REGION_N_MODES_LIMIT = 500

_FROZEN = ConfigDict(extra="forbid", frozen=True)


def _length(positive: bool):
    def convert(cls, value: Any, info) -> float | None:  # noqa: ANN001
        if value is None:
            return None
        result = to_si(info.field_name, value, "length")
        if positive and not result > 0.0:
            raise ValueError("must be positive")
        if not positive and result < 0.0:
            raise ValueError("must be >= 0")
        return result

    return convert


def _material(cls, value: Any, info) -> float | None:  # noqa: ANN001
    if value is None:
        return None
    name = info.field_name
    if name == "nu":
        result = to_si(name, value, "dimensionless")
        if not 0.0 < result < 0.5:
            raise ValueError("Poisson's ratio must lie in (0, 0.5)")
        return result
    result = to_si(name, value, "pressure" if name == "E" else "density")
    if not result > 0.0:
        raise ValueError("must be positive")
    return result


def _quantity(kind: str, rule: str):
    """Validator: ``to_si`` of ``kind``, then ``rule`` (">0", ">=0", "any", "0..1")."""
    def convert(cls, value: Any, info) -> float | None:  # noqa: ANN001
        if value is None:
            return None
        result = to_si(info.field_name, value, kind)
        if rule == ">0" and not result > 0.0:
            raise ValueError("must be positive")
        if rule == ">=0" and not result >= 0.0:
            raise ValueError("must be >= 0")
        if rule == "0..1" and not 0.0 <= result <= 1.0:
            raise ValueError("must lie in [0, 1]")
        return result

    return convert


def _one_of(options: tuple[str, ...]):
    def check(cls, value: Any) -> Any:  # noqa: ANN001
        if value is not None and value not in options:
            raise ValueError("must be one of " + ", ".join(f'"{o}"' for o in options))
        return value

    return check


class VehicleStiffeners(BaseModel):
    """``rings`` or ``stringers`` of a segment: one family of equally spaced stiffeners of the
    segment's material, smeared over the wall (Baruch-Singer).

    Attributes
    ----------
    spacing : float
        Distance between neighbours (m), > 0: along the axis for rings, around the
        circumference for stringers.
    area : float
        Cross-section area (m^2), > 0.
    inertia : float
        Second moment of the cross-section about its own centroid (m^4), >= 0, default 0.
    eccentricity : float
        Centroid's distance from the wall's mid-surface (m), positive outward, default 0.
    """

    model_config = _FROZEN
    spacing: float
    area: float
    inertia: float = 0.0
    eccentricity: float = 0.0

    _spacing = field_validator("spacing", mode="before")(_quantity("length", ">0"))
    _area = field_validator("area", mode="before")(_quantity("area", ">0"))
    _inertia = field_validator("inertia", mode="before")(_quantity("second_moment", ">=0"))
    _ecc = field_validator("eccentricity", mode="before")(_quantity("length", "any"))


class VehicleSegment(BaseModel):
    """One ``[[vehicle.segments]]`` entry: a cylinder or a conical frustum.

    Attributes
    ----------
    kind : str
        ``"cylinder"`` or ``"cone"`` (a cone of length 0 is a flat annular plate).
    radius : float or None
        Mid-surface radius of a cylinder (m), > 0.
    radius_aft, radius_fwd : float or None
        Mid-surface radii of a cone at its aft and forward edges (m), > 0.
    length : float
        Axial length (m); > 0 for a cylinder, >= 0 for a cone.
    thickness : float
        Wall thickness h (m), 0 < h < the segment's smallest radius.
    E, nu, rho : float or None
        Young's modulus (Pa), Poisson's ratio, density (kg/m^3); default the ``[vehicle]``
        table's, then the ``[booster]``'s.
    junction : str or None
        Junction with the previous segment: ``"continuous"`` (default), ``"rigid-bulkhead"`` or
        ``"memo-bulkhead"``; not on the first segment.
    nonstructural_mass : float
        Smeared mass on the wall (kg/m^2), >= 0, default 0: insulation, equipment.
    pressure : float
        Internal gauge pressure (Pa), default 0: membrane pre-stress N_theta = p R,
        N_x = p R / 2.
    rings, stringers : VehicleStiffeners or None
        Smeared stiffeners.
    """

    model_config = _FROZEN
    kind: str
    radius: float | None = None
    radius_aft: float | None = None
    radius_fwd: float | None = None
    length: float
    thickness: float
    E: float | None = None
    nu: float | None = None
    rho: float | None = None
    junction: str | None = None
    nonstructural_mass: float = 0.0
    pressure: float = 0.0
    rings: VehicleStiffeners | None = None
    stringers: VehicleStiffeners | None = None

    _nsm = field_validator("nonstructural_mass", mode="before")(
        _quantity("areal_density", ">=0"))
    _pressure = field_validator("pressure", mode="before")(_quantity("pressure", "any"))
    _kind = field_validator("kind", mode="before")(_one_of(SEGMENT_KINDS))
    _radii = field_validator("radius", "radius_aft", "radius_fwd", "thickness",
                             mode="before")(_length(True))
    _len = field_validator("length", mode="before")(_length(False))
    _mat = field_validator("E", "nu", "rho", mode="before")(_material)
    _junction = field_validator("junction", mode="before")(_one_of(VEHICLE_JUNCTIONS))

    @property
    def r_aft(self) -> float:
        """Radius at the aft edge (m)."""
        return self.radius if self.kind == "cylinder" else self.radius_aft

    @property
    def r_fwd(self) -> float:
        """Radius at the forward edge (m)."""
        return self.radius if self.kind == "cylinder" else self.radius_fwd


class VehicleMass(BaseModel):
    """One ``[[vehicle.masses]]`` entry: a rigid mass attached to the wall's ring at a station
    (engines, payload, avionics, interstage hardware); it acts on k = 0 and k = 1.

    Attributes
    ----------
    station : float
        Axial distance of the attachment from the aft edge (m), >= 0, within the vehicle.
    mass : float
        Mass (kg), > 0.
    transverse_inertia : float
        Moment of inertia about a transverse axis through its centre of mass (kg m^2), >= 0,
        default 0.
    offset : float
        Axial distance of its centre of mass forward of ``station`` (m), default 0.
    name : str
        Label in the outputs (default "mass i").
    """

    model_config = _FROZEN
    station: float
    mass: float
    transverse_inertia: float = 0.0
    offset: float = 0.0
    name: str = ""

    _station = field_validator("station", mode="before")(_quantity("length", ">=0"))
    _mass = field_validator("mass", mode="before")(_quantity("mass", ">0"))
    _inertia = field_validator("transverse_inertia", mode="before")(
        _quantity("moment_of_inertia", ">=0"))
    _offset = field_validator("offset", mode="before")(_quantity("length", "any"))


class VehicleTankTable(BaseModel):
    """One ``[[vehicle.tanks]]`` entry: liquid propellant between two stations, settled aft.

    Attributes
    ----------
    aft, fwd : float
        Stations of the tank's ends from the aft edge (m): each a segment boundary or a vehicle
        end, aft < fwd, the wall between them one continuous meridian.
    fill : float
        Liquid height as a fraction of the tank's length, 0..1 (1: full).
    density : float
        Liquid density (kg/m^3), > 0.
    name : str
        Label in the outputs (default "tank i").
    """

    model_config = _FROZEN
    aft: float
    fwd: float
    fill: float
    density: float
    name: str = ""

    _aft = field_validator("aft", mode="before")(_quantity("length", ">=0"))
    _fwd = field_validator("fwd", mode="before")(_quantity("length", ">0"))
    _fill = field_validator("fill", mode="before")(_quantity("dimensionless", "0..1"))
    _density = field_validator("density", mode="before")(_quantity("density", ">0"))


class VehicleTable(BaseModel):
    """The ``[vehicle]`` table.

    Attributes
    ----------
    E, nu, rho : float or None
        Default material of the segments (Pa, -, kg/m^3); default the ``[booster]``'s.
    aft_end, fwd_end : str or None
        ``"free"``, ``"shear-diaphragm"``, ``"clamped"`` or ``"hinged"``; default ``"free"``
        with segments, :data:`MEMO_END` for the memo vehicle.
    theory : str
        ``"sanders"`` (default) or ``"donnell"``.
    k_max : int
        Circumferential harmonics k = 0..k_max, 0..200, default 20.
    junction : str or None
        Only without segments: the memo vehicle's junction (default :data:`MEMO_JUNCTION`;
        ``"continuous"`` needs R1 = R2).
    segments : tuple of VehicleSegment or None
        The segments from the aft edge forward; None: the memo vehicle.
    damping_ratio : float or None
        Deprecated: the modal damping ratio of the loaded modes in the regions, [0, 1); by
        default ``damping.modal_ratio`` (``Case.vehicle_damping_ratio``).
    n_modes : int
        Modes per harmonic in the regions' basis, 1..:data:`REGION_N_MODES_LIMIT`, default
        :data:`REGION_N_MODES`.
    masses : tuple of VehicleMass
        ``[[vehicle.masses]]`` (only with segments).
    tanks : tuple of VehicleTankTable
        ``[[vehicle.tanks]]`` (only with segments).
    """

    model_config = _FROZEN
    E: float | None = None
    nu: float | None = None
    rho: float | None = None
    aft_end: str | None = None
    fwd_end: str | None = None
    theory: str = "sanders"
    k_max: StrictInt = 20
    junction: str | None = None
    segments: tuple[VehicleSegment, ...] | None = None
    damping_ratio: float | None = None
    n_modes: StrictInt = REGION_N_MODES
    masses: tuple[VehicleMass, ...] = ()
    tanks: tuple[VehicleTankTable, ...] = ()

    _mat = field_validator("E", "nu", "rho", mode="before")(_material)
    _ends = field_validator("aft_end", "fwd_end", mode="before")(_one_of(VEHICLE_ENDS))
    _theory = field_validator("theory", mode="before")(_one_of(VEHICLE_THEORIES))
    _junction = field_validator("junction", mode="before")(_one_of(VEHICLE_JUNCTIONS))

    @field_validator("k_max")
    @classmethod
    def _k_max(cls, value: int) -> int:
        if not 0 <= value <= K_MAX_LIMIT:
            raise ValueError(f"must be an integer in [0, {K_MAX_LIMIT}]")
        return value

    @field_validator("damping_ratio", mode="before")
    @classmethod
    def _damping_ratio(cls, value: Any) -> float:
        result = to_si("damping_ratio", value, "dimensionless")
        if not 0.0 <= result < 1.0:  # math.isfinite: nan fails both comparisons
            raise ValueError("damping ratio must lie in [0, 1)")
        return result

    @field_validator("n_modes")
    @classmethod
    def _n_modes(cls, value: int) -> int:
        if not 1 <= value <= REGION_N_MODES_LIMIT:
            raise ValueError(f"must be an integer in [1, {REGION_N_MODES_LIMIT}]")
        return value


def _radius_field(i: int, seg: VehicleSegment, end: str) -> str:
    return f"vehicle.segments[{i}]." + ("radius" if seg.kind == "cylinder" else f"radius_{end}")


def check_vehicle(table: VehicleTable | None, *, booster_radii: tuple[float, float]) -> None:
    """Rules of the ``[vehicle]`` table that involve more than one field (CaseError naming it).

    Parameters
    ----------
    table : VehicleTable or None
        The validated table (None: nothing to check).
    booster_radii : tuple of float
        (R1, R2) of ``[booster]`` (m), for ``junction = "continuous"`` on the memo vehicle.
    """
    if table is None:
        return
    if table.segments is None:
        if table.junction == "continuous":
            r1, r2 = booster_radii
            if abs(r1 - r2) > RADIUS_RTOL * max(r1, r2):
                raise CaseError("vehicle.junction", table.junction,
                                f"a continuous junction needs booster.cylinder1.radius = "
                                f"cylinder2.radius (they are {r1!r} and {r2!r} m)")
        for name in ("E", "nu", "rho"):
            if getattr(table, name) is not None:
                raise CaseError(f"vehicle.{name}", getattr(table, name),
                                "only with [[vehicle.segments]] (the memo vehicle takes the "
                                "material of [booster])")
        for name in ("masses", "tanks"):
            if getattr(table, name):
                raise CaseError(f"vehicle.{name}", "[...]", "only with [[vehicle.segments]] "
                                "(stations refer to the segments)")
        return
    if table.junction is not None:
        raise CaseError("vehicle.junction", table.junction,
                        "only without [[vehicle.segments]]; give each segment's junction "
                        "(at its aft edge) instead")
    if len(table.segments) == 0:
        raise CaseError("vehicle.segments", [], "at least one segment is needed")
    for i, tank in enumerate(table.tanks):
        if not tank.fwd > tank.aft:
            raise CaseError(f"vehicle.tanks[{i}].fwd", tank.fwd,
                            f"must be forward of aft = {tank.aft!r} m")
    for i, seg in enumerate(table.segments):
        _check_segment(i, seg)
        if i == 0:
            if seg.junction is not None:
                raise CaseError("vehicle.segments[0].junction", seg.junction,
                                "the first (aft) segment has no junction")
            continue
        prev = table.segments[i - 1]
        ra, rb = prev.r_fwd, seg.r_aft
        if (seg.junction or "continuous") == "continuous" and \
                abs(ra - rb) > RADIUS_RTOL * max(ra, rb):
            raise CaseError(_radius_field(i, seg, "aft"), rb,
                            f"must equal {_radius_field(i - 1, prev, 'fwd')} = {ra!r} m at a "
                            'continuous junction (junction = "rigid-bulkhead" joins radii that '
                            "differ)")


def _check_segment(i: int, seg: VehicleSegment) -> None:
    where = f"vehicle.segments[{i}]"
    if seg.kind == "cylinder":
        for name in ("radius_aft", "radius_fwd"):
            if getattr(seg, name) is not None:
                raise CaseError(f"{where}.{name}", getattr(seg, name),
                                'a cylinder has one radius: give "radius"')
        if seg.radius is None:
            raise CaseError(f"{where}.radius", None, "required field is missing (cylinder)")
        if not seg.length > 0.0:
            raise CaseError(f"{where}.length", seg.length, "a cylinder's length must be > 0")
    else:
        if seg.radius is not None:
            raise CaseError(f"{where}.radius", seg.radius,
                            'a cone has two radii: give "radius_aft" and "radius_fwd"')
        for name in ("radius_aft", "radius_fwd"):
            if getattr(seg, name) is None:
                raise CaseError(f"{where}.{name}", None, "required field is missing (cone)")
        if seg.length == 0.0 and math.isclose(seg.radius_aft, seg.radius_fwd,
                                              rel_tol=RADIUS_RTOL):
            raise CaseError(f"{where}.radius_fwd", seg.radius_fwd,
                            "a flat plate (cone of length 0) needs radius_fwd != radius_aft")
    r_min = min(seg.r_aft, seg.r_fwd)
    if not seg.thickness < r_min:
        raise CaseError(f"{where}.thickness", seg.thickness,
                        f"must be smaller than the segment's radius ({r_min!r} m)")
