"""The first lateral slosh mode of a tank's liquid and its spring-mass analogy.

Under the axial acceleration a the free surface carries dPhi/dx = kappa Phi, kappa =
omega^2 / a; for k = 1 the Steklov problem H Phi = kappa S Phi is condensed on the surface and
its smallest kappa taken; m_1 = rho_L kappa Gamma^2 / N, Gamma = int_S y Phi dS,
N = int_S Phi^2 dS; m_L - m_1 is the fixed mass. Theory: docs/theory/liquid.md.

References: H. N. Abramson (ed.), NASA SP-106, 1966, ch. 2, 6; F. T. Dodge, SwRI, 2000,
ch. 1-3; R. A. Ibrahim, *Liquid Sloshing Dynamics*, 2005, ch. 2, 9.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.linalg as sla
from scipy.sparse.linalg import splu

from ..checks import positive
from .elements import theta_weight
from .liquid_mesh import LiquidMesh, condensed_operator, dof_index, radial_mass, radial_moments

__all__ = ["SloshMode", "slosh_mode"]


@dataclass(frozen=True)
class SloshMode:
    """First lateral (k = 1) slosh mode of a tank and its spring-mass analogy.

    Attributes
    ----------
    omega : float
        Circular frequency (rad/s); ``hz`` the same in Hz.
    mass, fixed_mass, liquid_mass : float
        Slosh mass m_1, the rest m_L - m_1 (rigidly attached) and m_L (kg).
    acceleration : float
        The axial acceleration that settles the liquid (m/s^2).
    tank : str
        The tank's label ("" when not from a vehicle).
    """

    omega: float
    mass: float
    fixed_mass: float
    liquid_mass: float
    acceleration: float
    tank: str = ""

    @property
    def mass_kg(self) -> float:
        """Slosh mass m_1 (kg)."""
        return self.mass

    @property
    def hz(self) -> float:
        """Frequency (Hz)."""
        return self.omega / (2.0 * np.pi)

    def to_dict(self) -> dict:
        """JSON-ready mapping (SI units in the keys)."""
        return {"tank": self.tank, "hz": self.hz, "mass_kg": self.mass,
                "fixed_mass_kg": self.fixed_mass,
                "liquid_mass_kg": self.liquid_mass, "acceleration_m_s2": self.acceleration}


def slosh_mode(mesh: LiquidMesh, acceleration: float) -> SloshMode | None:
    """First k = 1 slosh mode under the axial acceleration, or None without a free surface
    (``fill`` 0 or 1) (Abramson 1966 ch. 2, 6; Dodge 2000 ch. 3).

    Parameters
    ----------
    mesh : LiquidMesh
        The tank's liquid.
    acceleration : float
        Axial acceleration a (m/s^2), > 0 (liquid settled aft).
    """
    a = positive("acceleration", acceleration)
    tank = mesh.tank
    if mesh.nodes.size == 0 or tank.fill == 1.0:
        return None
    nx, ny = mesh.shape
    index, n_dof = dof_index(mesh, 1, open_surface=False)
    H = condensed_operator(mesh, 1, index, n_dof)
    top = index[(nx - 1) * ny + np.arange(ny)]
    on = top >= 0
    s = top[on]
    inner = np.setdiff1d(np.arange(n_dof), s)
    R = float(tank.radius(tank.surface))
    S = R**2 * radial_mass(mesh)[np.ix_(on, on)]  # int psi psi r dr on the surface
    his = H[inner][:, s].toarray()
    lu = splu(H[inner][:, inner].tocsc(), permc_spec="MMD_AT_PLUS_A")
    D = H[s][:, s].toarray() - his.T @ lu.solve(his)  # Schur complement on the surface
    kappa, vec = sla.eigh(0.5 * (D + D.T), S, subset_by_index=[0, 0])
    v = vec[:, 0]
    gamma = R**3 * radial_moments(mesh, 2)[on] @ v  # int y Phi dS / c_1 (y = r cos theta)
    m1 = tank.density * theta_weight(1) * kappa[0] * gamma**2 / (v @ S @ v)
    m_l = tank.liquid_mass()
    return SloshMode(omega=float(np.sqrt(a * kappa[0])), mass=float(m1),
                     fixed_mass=float(m_l - m1), liquid_mass=m_l, acceleration=a)
