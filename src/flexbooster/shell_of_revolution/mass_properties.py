"""Mass, centre of mass and pitch inertia of a vehicle, contribution by contribution.

Every contribution is an axisymmetric body; its pitch inertia (about a transverse axis) about
its own centre of mass is I_cm = int (x - x_c)^2 dm + int j dm, with j = r^2 / 2 for a thin
wall (a ring about a diameter) and j = r^2 / 4 for the liquid (a disc about a diameter); the
liquid counts as a rigid body. The integrands are polynomials in the meridian coordinate on
every conical segment and frustum of liquid, integrated exactly by Gauss-Legendre quadrature.
The whole vehicle combines the contributions by the parallel-axis theorem.

References: J. L. Meriam, L. G. Kraige, *Engineering Mechanics: Dynamics*, appendix B (mass
moments of inertia); H. N. Abramson (ed.), NASA SP-106, 1966, ch. 6 (the liquid as a body).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.polynomial import legendre as leg

from .geometry import Vehicle, wall_masses
from .wetted_wall import vehicle_tank

__all__ = ["CONTRIBUTION_KINDS", "MassContribution", "MassProperties", "mass_properties"]

#: Kinds of contribution, in the order they are listed.
CONTRIBUTION_KINDS = ("shell", "nonstructural", "stiffeners", "lumped", "tank")
#: Gauss points per interval: exact for the integrands (degree <= 5 in the coordinate).
_POINTS = 4


@dataclass(frozen=True)
class MassContribution:
    """One part of the vehicle's mass.

    Attributes
    ----------
    name : str
        Label (the mass's or tank's name, or the kind).
    kind : str
        One of :data:`CONTRIBUTION_KINDS`.
    mass_kg : float
        Mass (kg).
    cm_m : float
        Axial station of its centre of mass from the aft edge (m).
    I_cm_kg_m2 : float
        Pitch moment of inertia about its own centre of mass (kg m^2), axis perpendicular to
        the vehicle's axis.
    """

    name: str
    kind: str
    mass_kg: float
    cm_m: float
    I_cm_kg_m2: float

    def to_dict(self) -> dict:
        """JSON-ready mapping."""
        return {"name": self.name, "kind": self.kind, "mass_kg": self.mass_kg,
                "cm_m": self.cm_m, "I_cm_kg_m2": self.I_cm_kg_m2}


@dataclass(frozen=True)
class MassProperties:
    """Mass properties of the whole vehicle.

    Attributes
    ----------
    mass_kg, cm_m, I_cm_kg_m2 : float
        Total mass (kg), centre of mass from the aft edge (m), pitch inertia about it (kg m^2).
    contributions : tuple of MassContribution
        The parts, in the order of :data:`CONTRIBUTION_KINDS`.
    """

    mass_kg: float
    cm_m: float
    I_cm_kg_m2: float
    contributions: tuple

    def to_dict(self) -> dict:
        """JSON-ready mapping."""
        return {"mass_kg": self.mass_kg, "cm_m": self.cm_m, "I_cm_kg_m2": self.I_cm_kg_m2,
                "contributions": [c.to_dict() for c in self.contributions]}


def _moments(weights: np.ndarray, x: np.ndarray, j: np.ndarray) -> np.ndarray:
    """(m, int x dm, int (x^2 + j) dm) of point masses ``weights`` at ``x``."""
    return np.array([weights.sum(), weights @ x, weights @ (x**2 + j)])


def _contribution(name: str, kind: str, mom: np.ndarray) -> MassContribution:
    """A contribution from its moments (m, S_x, S_xx): x_c = S_x / m, I = S_xx - m x_c^2."""
    m, sx, sxx = (float(v) for v in mom)
    cm = sx / m
    return MassContribution(name=name, kind=kind, mass_kg=m, cm_m=cm,
                            I_cm_kg_m2=float(sxx - 2.0 * cm * sx + m * cm**2))


def _wall_moments(vehicle: Vehicle) -> np.ndarray:
    """Moments of the unit areal mass of every segment's wall, shape (segments, 3):
    dm = 2 pi r ds, j = r^2 / 2 (Gauss-Legendre, exact)."""
    g, w = leg.leggauss(_POINTS)
    out = []
    x0 = 0.0
    for seg, lm in zip(vehicle.segments, vehicle.meridian_lengths(), strict=True):
        t = 0.5 * (1.0 + g)  # fraction of the meridian
        r = seg.radius_aft + t * (seg.radius_fwd - seg.radius_aft)
        x = x0 + t * seg.length
        out.append(_moments(2.0 * np.pi * r * 0.5 * lm * w, x, 0.5 * r**2))
        x0 += seg.length
    return np.array(out)


def _liquid_moments(vehicle: Vehicle, tank) -> np.ndarray:
    """Moments of a tank's liquid: dm = rho pi r^2 dx, j = r^2 / 4 (Gauss-Legendre, exact)."""
    liquid = vehicle_tank(vehicle, aft=tank.aft, fwd=tank.fwd, fill=tank.fill,
                          density=tank.density)
    xs, rs = liquid.wetted()
    g, w = leg.leggauss(_POINTS)
    t = 0.5 * (1.0 + g)
    x = (xs[:-1, None] + t[None, :] * np.diff(xs)[:, None]).ravel()
    r = (rs[:-1, None] + t[None, :] * np.diff(rs)[:, None]).ravel()
    dx = (0.5 * np.diff(xs)[:, None] * w[None, :]).ravel()
    return _moments(tank.density * np.pi * r**2 * dx, x, 0.25 * r**2)


def mass_properties(vehicle: Vehicle) -> MassProperties:
    """Mass, centre of mass and pitch inertia of the vehicle and of each contribution: the
    shell walls, the non-structural mass, the smeared stiffeners (each summed over the
    segments, listed when non-zero), every lumped mass and every tank's liquid.

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    """
    unit = _wall_moments(vehicle)
    areal = np.array([wall_masses(seg) for seg in vehicle.segments])  # (segments, 3)
    parts = []
    for col, kind in enumerate(CONTRIBUTION_KINDS[:3]):
        mom = areal[:, col] @ unit
        if mom[0] > 0.0:
            parts.append(_contribution(kind, kind, mom))
    for i, lm in enumerate(vehicle.masses):
        x = lm.station + lm.offset
        mom = np.array([lm.mass, lm.mass * x, lm.mass * x**2 + lm.transverse_inertia])
        parts.append(_contribution(lm.name or f"mass {i}", "lumped", mom))
    for i, tank in enumerate(vehicle.tanks):
        if tank.fill > 0.0:
            parts.append(_contribution(tank.name or f"tank {i}", "tank",
                                       _liquid_moments(vehicle, tank)))
    total = sum(np.array([c.mass_kg, c.mass_kg * c.cm_m, c.I_cm_kg_m2 + c.mass_kg * c.cm_m**2])
                for c in parts)
    whole = _contribution("vehicle", "vehicle", total)
    return MassProperties(mass_kg=whole.mass_kg, cm_m=whole.cm_m, I_cm_kg_m2=whole.I_cm_kg_m2,
                          contributions=tuple(parts))
