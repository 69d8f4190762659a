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

from ..checks import choice, nonnegative, positive

__all__ = [
    "END_CONDITIONS",
    "JUNCTIONS",
    "THEORIES",
    "RADIUS_RTOL",
    "THICK_SHELL_RATIO",
    "Cylinder",
    "Cone",
    "ShellWarning",
    "Vehicle",
]

#: End conditions accepted for the aft and the forward edge.
END_CONDITIONS = ("free", "shear-diaphragm", "hinged", "clamped")
#: Junction types between consecutive segments.
JUNCTIONS = ("continuous", "rigid-bulkhead", "memo-bulkhead")
#: Shell theories: Sanders-Koiter (default) and Donnell-Mushtari.
THEORIES = ("sanders", "donnell")
#: Relative tolerance on the radii of neighbouring segments where they meet.
RADIUS_RTOL = 1e-6
#: h / R above which a thin-shell warning is returned.
THICK_SHELL_RATIO = 1.0 / 20.0


def _thin(name: str, thickness: float, radius: float) -> float:
    """``thickness`` > 0 and below ``radius`` (a thin shell: the wall inside the radius)."""
    h = positive(name, thickness)
    if not h < radius:
        raise ValueError(f"{name} = {thickness!r}: must be < the radius {radius!r} (a thin "
                         "shell)")
    return h


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
        Mid-surface radius, axial length and wall thickness (m), > 0; thickness < radius.
    E, nu, rho : float
        Young's modulus (Pa) > 0, Poisson's ratio in [0, 0.5), density (kg/m^3) > 0
        (keyword-only).
    """

    radius: float
    length: float
    thickness: float
    _: KW_ONLY
    E: float
    nu: float
    rho: float

    def __post_init__(self) -> None:
        object.__setattr__(self, "radius", positive("radius", self.radius))
        object.__setattr__(self, "length", positive("length", self.length))
        object.__setattr__(self, "thickness", _thin("thickness", self.thickness,
                                                     min(self.radius_aft, self.radius_fwd)))
        E, nu, rho = _material(self.E, self.nu, self.rho)
        object.__setattr__(self, "E", E)
        object.__setattr__(self, "nu", nu)
        object.__setattr__(self, "rho", rho)

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
                "thickness": self.thickness, "E": self.E, "nu": self.nu, "rho": self.rho}


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
        Wall thickness h (m), > 0 and < the smaller radius.
    E, nu, rho : float
        Young's modulus (Pa) > 0, Poisson's ratio in [0, 0.5), density (kg/m^3) > 0
        (keyword-only).
    """

    radius_aft: float
    radius_fwd: float
    length: float
    thickness: float
    _: KW_ONLY
    E: float
    nu: float
    rho: float

    def __post_init__(self) -> None:
        object.__setattr__(self, "radius_aft", positive("radius_aft", self.radius_aft))
        object.__setattr__(self, "radius_fwd", positive("radius_fwd", self.radius_fwd))
        object.__setattr__(self, "length", nonnegative("length", self.length))
        object.__setattr__(self, "thickness", _thin("thickness", self.thickness,
                                                     min(self.radius_aft, self.radius_fwd)))
        E, nu, rho = _material(self.E, self.nu, self.rho)
        object.__setattr__(self, "E", E)
        object.__setattr__(self, "nu", nu)
        object.__setattr__(self, "rho", rho)
        if self.length == 0.0 and self.radius_aft == self.radius_fwd:
            raise ValueError(f"length = {self.length!r}: a flat plate (length 0) needs "
                             "radius_aft != radius_fwd")

    def to_dict(self) -> dict:
        """JSON-ready mapping (``kind`` plus the fields)."""
        return {"kind": "cone", "radius_aft": self.radius_aft, "radius_fwd": self.radius_fwd,
                "length": self.length, "thickness": self.thickness, "E": self.E,
                "nu": self.nu, "rho": self.rho}


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
    """

    segments: tuple
    junctions: tuple = None  # type: ignore[assignment]
    aft_end: str = "free"
    fwd_end: str = "free"
    theory: str = "sanders"
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
        warns = []
        for i, seg in enumerate(segs):
            rmin = min(seg.radius_aft, seg.radius_fwd)
            if seg.thickness / rmin > THICK_SHELL_RATIO:
                warns.append(ShellWarning(
                    "thick-shell", i,
                    f"segment {i}: h/R = {seg.thickness / rmin:.3g} > 1/20, thin-shell "
                    "theory (no transverse shear, no rotary inertia) is doubtful"))
        object.__setattr__(self, "warnings", tuple(warns))

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
                "warnings": [w.to_dict() for w in self.warnings]}
