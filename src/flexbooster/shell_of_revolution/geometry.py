"""Segments, junctions and end conditions of a vehicle modelled as one thin shell of revolution.

The meridian runs from the aft edge (x = 0) forward through :class:`Cylinder` and
:class:`Cone` segments (a cone of axial length 0 is a flat annular plate), joined by
:data:`JUNCTIONS`, with :data:`END_CONDITIONS` at the ends
(docs/theory/shell-of-revolution.md).

References: H. Kraus, *Thin Elastic Shells*, 1967, ch. 2-3; A. W. Leissa, *Vibration of
Shells*, NASA SP-288, 1973, sec. 1.6, 2.3, ch. 4.
"""

from __future__ import annotations

import math
from dataclasses import KW_ONLY, dataclass, field

import numpy as np

from ..checks import FieldValueError, choice, finite, nonnegative, positive
from .liquid_mesh import Tank

__all__ = [
    "END_CONDITIONS",
    "JUNCTIONS",
    "THEORIES",
    "RADIUS_RTOL",
    "STATION_RTOL",
    "THICK_SHELL_RATIO",
    "Cylinder",
    "Cone",
    "LumpedMass",
    "ShellWarning",
    "Stiffeners",
    "stiffener_matrix",
    "tank_liquid",
    "tank_wall",
    "wall_masses",
    "Vehicle",
    "VehicleTank",
]

#: End conditions accepted for the aft and the forward edge.
END_CONDITIONS = ("free", "shear-diaphragm", "hinged", "clamped")
#: Junction types between consecutive segments.
JUNCTIONS = ("continuous", "rigid-bulkhead", "memo-bulkhead")
#: Shell theories: Sanders-Koiter (default) and Donnell-Mushtari.
THEORIES = ("sanders", "donnell")
#: Relative tolerance on the radii of neighbouring segments where they meet.
RADIUS_RTOL = 1e-6
#: Relative tolerance (of the vehicle's length) of a tank end on a segment boundary.
STATION_RTOL = 1e-9
#: h / R above which a thin-shell warning is returned.
THICK_SHELL_RATIO = 1.0 / 20.0


@dataclass(frozen=True)
class Stiffeners:
    """One family of equally spaced stiffeners (rings or stringers) of the segment's material,
    smeared over the wall (Baruch and Singer, J. Mech. Eng. Sci. 5 (1963) 23-27).

    Parameters
    ----------
    spacing : float
        Distance between neighbouring stiffeners (m), > 0: along the meridian for rings,
        along the circumference for stringers.
    area : float
        Cross-section area (m^2), > 0.
    inertia : float
        Second moment of the cross-section about its own centroid, for bending out of the
        wall (m^4), >= 0.
    eccentricity : float
        Distance of the centroid from the wall's mid-surface (m), positive outward.
    """

    spacing: float
    area: float
    inertia: float = 0.0
    eccentricity: float = 0.0

    def __post_init__(self) -> None:
        object.__setattr__(self, "spacing", positive("spacing", self.spacing))
        object.__setattr__(self, "area", positive("area", self.area))
        object.__setattr__(self, "inertia", nonnegative("inertia", self.inertia))
        object.__setattr__(self, "eccentricity", finite("eccentricity", self.eccentricity))

    def to_dict(self) -> dict:
        """JSON-ready mapping."""
        return {"spacing": self.spacing, "area": self.area, "inertia": self.inertia,
                "eccentricity": self.eccentricity}


def _wall_extras(seg) -> None:
    """Check and normalise the optional wall fields shared by Cylinder and Cone."""
    object.__setattr__(seg, "nonstructural_mass",
                       nonnegative("nonstructural_mass", seg.nonstructural_mass))
    object.__setattr__(seg, "pressure", finite("pressure", seg.pressure))
    for name in ("rings", "stringers"):
        val = getattr(seg, name)
        if val is not None and not isinstance(val, Stiffeners):
            raise ValueError(f"{name} = {val!r}: must be None or a Stiffeners")


def _extras_dict(seg) -> dict:
    """The optional wall fields that differ from their defaults (JSON-ready)."""
    out = {}
    if seg.nonstructural_mass:
        out["nonstructural_mass"] = seg.nonstructural_mass
    if seg.pressure:
        out["pressure"] = seg.pressure
    for name in ("rings", "stringers"):
        if getattr(seg, name) is not None:
            out[name] = getattr(seg, name).to_dict()
    return out


def _material(E: float, nu: float, rho: float) -> tuple[float, float, float]:
    E = positive("E", E)
    rho = positive("rho", rho)
    nu = nonnegative("nu", nu)
    if nu >= 0.5:
        raise ValueError(f"nu = {nu!r}: must be in [0, 0.5)")
    return E, nu, rho


@dataclass(frozen=True)
class Cylinder:
    """Circular cylindrical segment.

    Parameters
    ----------
    radius, length, thickness : float
        Mid-surface radius, axial length and wall thickness (m), > 0.
    E, nu, rho : float
        Young's modulus (Pa) > 0, Poisson's ratio in [0, 0.5), density (kg/m^3) > 0
        (keyword-only).
    nonstructural_mass : float
        Smeared mass on the wall (kg/m^2), >= 0: inertia only, no stiffness (keyword-only).
    pressure : float
        Internal gauge pressure (Pa): membrane pre-stress N_theta = p r / cos(phi),
        N_s = p r / (2 cos(phi)) of a closed tank (keyword-only).
    rings, stringers : Stiffeners or None
        Smeared stiffeners (Baruch-Singer 1963) of the segment's E and rho (keyword-only).
    """

    radius: float
    length: float
    thickness: float
    _: KW_ONLY
    E: float
    nu: float
    rho: float
    nonstructural_mass: float = 0.0
    pressure: float = 0.0
    rings: Stiffeners | None = None
    stringers: Stiffeners | None = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "radius", positive("radius", self.radius))
        object.__setattr__(self, "length", positive("length", self.length))
        object.__setattr__(self, "thickness", positive("thickness", self.thickness))
        E, nu, rho = _material(self.E, self.nu, self.rho)
        object.__setattr__(self, "E", E)
        object.__setattr__(self, "nu", nu)
        object.__setattr__(self, "rho", rho)
        _wall_extras(self)

    @property
    def radius_aft(self) -> float:
        """Radius at the aft edge (m)."""
        return self.radius

    @property
    def radius_fwd(self) -> float:
        """Radius at the forward edge (m)."""
        return self.radius

    def to_dict(self) -> dict:
        """JSON-ready mapping (``kind`` plus the fields)."""
        return {"kind": "cylinder", "radius": self.radius, "length": self.length,
                "thickness": self.thickness, "E": self.E, "nu": self.nu, "rho": self.rho,
                **_extras_dict(self)}


@dataclass(frozen=True)
class Cone:
    """Conical frustum segment (``length = 0``: flat annular plate).

    Parameters
    ----------
    radius_aft, radius_fwd : float
        Mid-surface radii at the aft and forward edges (m), > 0; they differ when ``length = 0``.
    length : float
        Axial length (m), >= 0.
    thickness : float
        Wall thickness h (m), > 0.
    E, nu, rho : float
        Young's modulus (Pa) > 0, Poisson's ratio in [0, 0.5), density (kg/m^3) > 0
        (keyword-only).
    nonstructural_mass, pressure, rings, stringers
        As :class:`Cylinder` (keyword-only).
    """

    radius_aft: float
    radius_fwd: float
    length: float
    thickness: float
    _: KW_ONLY
    E: float
    nu: float
    rho: float
    nonstructural_mass: float = 0.0
    pressure: float = 0.0
    rings: Stiffeners | None = None
    stringers: Stiffeners | None = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "radius_aft", positive("radius_aft", self.radius_aft))
        object.__setattr__(self, "radius_fwd", positive("radius_fwd", self.radius_fwd))
        object.__setattr__(self, "length", nonnegative("length", self.length))
        object.__setattr__(self, "thickness", positive("thickness", self.thickness))
        E, nu, rho = _material(self.E, self.nu, self.rho)
        object.__setattr__(self, "E", E)
        object.__setattr__(self, "nu", nu)
        object.__setattr__(self, "rho", rho)
        _wall_extras(self)
        if self.length == 0.0 and self.radius_aft == self.radius_fwd:
            raise ValueError(f"length = {self.length!r}: a flat plate (length 0) needs "
                             "radius_aft != radius_fwd")

    def to_dict(self) -> dict:
        """JSON-ready mapping (``kind`` plus the fields)."""
        return {"kind": "cone", "radius_aft": self.radius_aft, "radius_fwd": self.radius_fwd,
                "length": self.length, "thickness": self.thickness, "E": self.E,
                "nu": self.nu, "rho": self.rho, **_extras_dict(self)}


def wall_masses(seg: Cylinder | Cone) -> tuple[float, float, float]:
    """Mass per unit wall area (kg/m^2) of the shell (rho h), of the non-structural mass and of
    the smeared stiffeners (rho A / spacing of each family, Baruch-Singer 1963).

    Parameters
    ----------
    seg : Cylinder or Cone
        The segment.
    """
    stiff = sum(seg.rho * st.area / st.spacing for st in (seg.rings, seg.stringers)
                if st is not None)
    return seg.rho * seg.thickness, seg.nonstructural_mass, float(stiff)


def stiffener_matrix(seg: Cylinder | Cone) -> np.ndarray | None:
    """Smeared-stiffener terms of the constitutive matrix diag(A, D), shape (6, 6), in the order
    (eps_s, eps_theta, gamma, kappa_s, kappa_theta, tau); None without stiffeners.

    A family of spacing d, area A_st, inertia I_st and eccentricity e (centroid strain
    eps + e kappa) adds E A_st / d to the extensional, E A_st e / d to the coupling and
    E (I_st + A_st e^2) / d to the bending stiffness of its direction: stringers along the
    meridian (s), rings around it (theta); their torsional stiffness is neglected
    (Baruch and Singer 1963, eq. 1-3; Brush and Almroth 1975, sec. 5.6).

    Parameters
    ----------
    seg : Cylinder or Cone
        The segment (its E and stiffeners).
    """
    if seg.rings is None and seg.stringers is None:
        return None
    out = np.zeros((6, 6))
    for st, i in ((seg.stringers, 0), (seg.rings, 1)):
        if st is None:
            continue
        ea = seg.E * st.area / st.spacing
        out[i, i] += ea
        out[i, i + 3] += ea * st.eccentricity
        out[i + 3, i] += ea * st.eccentricity
        out[i + 3, i + 3] += seg.E * (st.inertia + st.area * st.eccentricity**2) / st.spacing
    return out


@dataclass(frozen=True)
class LumpedMass:
    """A rigid mass attached to the wall's ring at one station (engines, payload, avionics).

    Parameters
    ----------
    station : float
        Axial distance of the attachment ring from the aft edge (m), in [0, total length].
    mass : float
        Mass (kg), > 0.
    transverse_inertia : float
        Moment of inertia about a transverse axis through its own centre of mass (kg m^2), >= 0.
    offset : float
        Axial distance of its centre of mass forward of ``station`` (m).
    name : str
        Label in the outputs.
    """

    station: float
    mass: float
    transverse_inertia: float = 0.0
    offset: float = 0.0
    name: str = ""

    def __post_init__(self) -> None:
        object.__setattr__(self, "station", nonnegative("station", self.station))
        object.__setattr__(self, "mass", positive("mass", self.mass))
        object.__setattr__(self, "transverse_inertia",
                           nonnegative("transverse_inertia", self.transverse_inertia))
        object.__setattr__(self, "offset", finite("offset", self.offset))
        if not isinstance(self.name, str):
            raise ValueError(f"name = {self.name!r}: must be a string")

    def to_dict(self) -> dict:
        """JSON-ready mapping."""
        return {"station": self.station, "mass": self.mass,
                "transverse_inertia": self.transverse_inertia, "offset": self.offset,
                "name": self.name}


@dataclass(frozen=True)
class VehicleTank:
    """Liquid propellant between two stations of the vehicle (inviscid, incompressible; its ends
    are rigid walls for the liquid).

    Parameters
    ----------
    aft, fwd : float
        Stations of the tank's ends (m from the aft edge), each a segment boundary or a vehicle
        end, aft < fwd.
    fill : float
        Liquid height as a fraction of the tank's length, 0..1, settled aft.
    density : float
        Liquid density (kg/m^3), > 0.
    name : str
        Label in the outputs.
    """

    aft: float
    fwd: float
    fill: float
    density: float
    name: str = ""

    def __post_init__(self) -> None:
        object.__setattr__(self, "aft", nonnegative("aft", self.aft))
        object.__setattr__(self, "fwd", positive("fwd", self.fwd))
        if self.fwd <= self.aft:
            raise ValueError(f"fwd = {self.fwd!r}: must be forward of aft = {self.aft!r}")
        fill = nonnegative("fill", self.fill)
        if fill > 1.0:
            raise ValueError(f"fill = {self.fill!r}: must be in [0, 1]")
        object.__setattr__(self, "fill", fill)
        object.__setattr__(self, "density", positive("density", self.density))
        if not isinstance(self.name, str):
            raise ValueError(f"name = {self.name!r}: must be a string")

    @property
    def surface(self) -> float:
        """Station of the free surface, aft + fill (fwd - aft) (m)."""
        return self.aft + self.fill * (self.fwd - self.aft)

    def to_dict(self) -> dict:
        """JSON-ready mapping."""
        return {"aft": self.aft, "fwd": self.fwd, "fill": self.fill, "density": self.density,
                "name": self.name}


@dataclass(frozen=True)
class ShellWarning:
    """A non-fatal remark on a vehicle (returned, never printed).

    Attributes
    ----------
    code : str
        Short identifier, e.g. ``"thick-shell"``.
    segment : int
        Index of the segment concerned (0 = aft).
    message : str
        Human-readable text.
    """

    code: str
    segment: int
    message: str

    def to_dict(self) -> dict:
        """JSON-ready mapping."""
        return {"code": self.code, "segment": self.segment, "message": self.message}


def _meridian(seg: Cylinder | Cone) -> tuple[float, float, float, float]:
    """(r_aft, r_fwd, axial length, meridian length) of a segment (m)."""
    r1, r2 = seg.radius_aft, seg.radius_fwd
    return r1, r2, seg.length, math.hypot(seg.length, r2 - r1)


@dataclass(frozen=True)
class Vehicle:
    """A vehicle: axisymmetric segments from the aft edge forward, junctions, ends, theory
    (Bushnell 1974, BOSOR). s (m) runs along the generators from the aft edge, x (m) is the
    axial station; :attr:`warnings` lists segments with h/R > 1/20.

    Parameters
    ----------
    segments : sequence of Cylinder or Cone
        At least one, aft to forward; across a ``"continuous"`` junction the radii match within
        :data:`RADIUS_RTOL` (relative); a bulkhead may join different radii.
    junctions : sequence of str, optional
        One per pair of neighbours, from :data:`JUNCTIONS`; default all ``"continuous"``.
    aft_end, fwd_end : str
        End conditions from :data:`END_CONDITIONS` (default ``"free"``).
    theory : str
        ``"sanders"`` (Sanders-Koiter, default) or ``"donnell"``.
    masses : sequence of LumpedMass
        Rigid masses on the wall (keyword-only; station within the vehicle).
    tanks : sequence of VehicleTank
        Liquid tanks (keyword-only; ends on segment boundaries or vehicle ends, the wall between
        them one continuous meridian: no flat plate, no radius step).
    """

    segments: tuple
    junctions: tuple = None  # type: ignore[assignment]
    aft_end: str = "free"
    fwd_end: str = "free"
    theory: str = "sanders"
    _: KW_ONLY
    masses: tuple = ()
    tanks: tuple = ()
    warnings: tuple = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        segs = tuple(self.segments) if not isinstance(self.segments, Cylinder | Cone) else (
            self.segments,)
        if len(segs) == 0:
            raise ValueError("segments = (): at least one segment is needed")
        for i, seg in enumerate(segs):
            if not isinstance(seg, Cylinder | Cone):
                raise ValueError(f"segments[{i}] = {seg!r}: must be a Cylinder or a Cone")
        object.__setattr__(self, "segments", segs)
        junctions = self.junctions
        if junctions is None:
            junctions = ("continuous",) * (len(segs) - 1)
        elif isinstance(junctions, str):
            junctions = (junctions,) * (len(segs) - 1)
        junctions = tuple(junctions)
        if len(junctions) != len(segs) - 1:
            raise ValueError(f"junctions = {junctions!r}: need {len(segs) - 1} entries "
                             "(one per pair of neighbouring segments)")
        for i, jn in enumerate(junctions):
            choice(f"junctions[{i}]", jn, JUNCTIONS)
        object.__setattr__(self, "junctions", junctions)
        choice("aft_end", self.aft_end, END_CONDITIONS)
        choice("fwd_end", self.fwd_end, END_CONDITIONS)
        choice("theory", self.theory, THEORIES)
        for i in range(len(segs) - 1):
            ra, rb = segs[i].radius_fwd, segs[i + 1].radius_aft
            if junctions[i] == "continuous" and abs(ra - rb) > RADIUS_RTOL * max(ra, rb):
                raise ValueError(f"segments[{i + 1}].radius_aft = {rb!r}: must equal "
                                 f"segments[{i}].radius_fwd = {ra!r} (relative tolerance "
                                 f"{RADIUS_RTOL:g})")
        self._check_masses_and_tanks()
        warns = []
        for i, seg in enumerate(segs):
            rmin = min(seg.radius_aft, seg.radius_fwd)
            if seg.thickness / rmin > THICK_SHELL_RATIO:
                warns.append(ShellWarning(
                    "thick-shell", i,
                    f"segment {i}: h/R = {seg.thickness / rmin:.3g} > 1/20, thin-shell "
                    "theory (no transverse shear, no rotary inertia) is doubtful"))
        object.__setattr__(self, "warnings", tuple(warns))

    def boundaries(self) -> np.ndarray:
        """Axial stations of the segment boundaries, 0 .. total length (m)."""
        return np.concatenate(([0.0], np.cumsum([s.length for s in self.segments])))

    def _check_masses_and_tanks(self) -> None:
        masses, tanks = tuple(self.masses), tuple(self.tanks)
        length = self.total_length
        for i, m in enumerate(masses):
            if not isinstance(m, LumpedMass):
                raise FieldValueError(f"masses[{i}]", m, "must be a LumpedMass")
            if m.station > length * (1.0 + STATION_RTOL):
                raise FieldValueError(f"masses[{i}].station", m.station,
                                      f"must be within the vehicle, 0 .. {length:g} m")
        for i, t in enumerate(tanks):
            if not isinstance(t, VehicleTank):
                raise FieldValueError(f"tanks[{i}]", t, "must be a VehicleTank")
            tank_liquid(self, t, prefix=f"tanks[{i}].")
        object.__setattr__(self, "masses", masses)
        object.__setattr__(self, "tanks", tanks)

    @property
    def total_length(self) -> float:
        """Axial length of the vehicle (m)."""
        return float(sum(seg.length for seg in self.segments))

    def meridian_lengths(self) -> np.ndarray:
        """Meridian (generator) length of every segment (m), aft to forward."""
        return np.array([_meridian(seg)[3] for seg in self.segments])

    def mass(self) -> float:
        """Shell mass (kg); bulkheads are weightless."""
        total = 0.0
        for seg in self.segments:
            r1, r2, _, lm = _meridian(seg)
            total += seg.rho * seg.thickness * math.pi * (r1 + r2) * lm
        return total

    def to_dict(self) -> dict:
        """JSON-ready mapping of the vehicle definition (and its warnings)."""
        return {"segments": [seg.to_dict() for seg in self.segments],
                "junctions": list(self.junctions), "aft_end": self.aft_end,
                "fwd_end": self.fwd_end, "theory": self.theory,
                "warnings": [w.to_dict() for w in self.warnings],
                **({"masses": [m.to_dict() for m in self.masses]} if self.masses else {}),
                **({"tanks": [t.to_dict() for t in self.tanks]} if self.tanks else {})}


def tank_wall(vehicle: Vehicle, aft: float, fwd: float, *,
              prefix: str = "") -> tuple[tuple, tuple]:
    """Stations and radii (m) of the wall of a tank between two stations of the vehicle;
    ValueError naming ``prefix + "aft"`` or ``"fwd"`` unless each is a segment boundary or a
    vehicle end (within :data:`STATION_RTOL` of the length), aft < fwd, and the wall between
    them one continuous meridian (no flat plate, no radius step).

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    aft, fwd : float
        Tank end stations (m from the aft edge).
    prefix : str
        Put before the field names in the messages (e.g. ``"tanks[0]."``).
    """
    bounds = vehicle.boundaries()
    tol = STATION_RTOL * bounds[-1]
    i_a, i_f = (int(np.argmin(np.abs(bounds - v))) for v in (aft, fwd))
    for name, v, i in (("aft", aft, i_a), ("fwd", fwd, i_f)):
        if not (np.isfinite(v) and abs(bounds[i] - v) <= tol):
            raise FieldValueError(f"{prefix}{name}", v, "must be a segment boundary or a "
                                  f"vehicle end ({', '.join(f'{b:g}' for b in bounds)} m)")
    if i_f <= i_a:
        raise FieldValueError(f"{prefix}fwd", fwd, f"must be forward of aft = {aft!r}")
    segs = vehicle.segments[i_a:i_f]
    for a, b in zip(segs[:-1], segs[1:], strict=True):
        if a.length == 0.0 or b.length == 0.0 or a.radius_fwd != b.radius_aft:
            raise FieldValueError(f"{prefix}fwd", fwd, f"the tank's wall from aft = {aft!r} "
                                  "must be one continuous meridian (no flat plate, no radius "
                                  "step)")
    radii = [s.radius_aft for s in segs] + [segs[-1].radius_fwd]
    return tuple(float(b) for b in bounds[i_a:i_f + 1]), tuple(radii)


def tank_liquid(vehicle: Vehicle, tank: VehicleTank, *, prefix: str = "") -> Tank:
    """The :class:`.liquid_mesh.Tank` (wall stations and radii, fill, density; rigid ends) of a
    vehicle's tank; ValueError naming ``prefix`` + the field (:func:`tank_wall`, and a liquid
    depth below :data:`.liquid_mesh.MIN_DEPTH_RADII` of the radius).

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    tank : VehicleTank
        One of its tanks.
    prefix : str
        Put before the field names in the messages.
    """
    stations, radii = tank_wall(vehicle, tank.aft, tank.fwd, prefix=prefix)
    try:
        return Tank(stations=stations, radii=radii, fill=tank.fill, density=tank.density)
    except ValueError as exc:  # the depth rule of the liquid mesh, under the field's full name
        raise FieldValueError(f"{prefix}fill", tank.fill, str(exc)) from exc
