"""Steady meridional prestress of a vehicle accelerated by its thrust (inertia relief).

A free-free vehicle driven by the thrust F0 at its aft edge accelerates at F0 / m_total; the
axial force carried at a station is what accelerates the mass ahead of it,

    F(s) = F0 m_ahead(s) / m_total          (F0 at the aft edge, 0 at the nose),

and per unit circumference of a cone of meridian angle phi (membrane state)

    N_s^0(s) = -F(s) / (2 pi r(s) cos(phi)).

With ``supported_forward_end`` the force is uniform, F(s) = F0 (thrust reacted at the nose).
Neglected: the hoop resultant N_theta^0 that the axial inertia load induces on cones (its normal
component), and the bending boundary layers of the prestate at junctions (membrane prestate).

References
----------
.. [1] D. O. Brush, B. O. Almroth, *Buckling of Bars, Plates and Shells*, 1975, sec. 5.3
   (membrane prebuckling state of an axially loaded shell).
.. [2] W. Flügge, *Stresses in Shells*, 2nd ed., 1973, sec. 2.2.2 (membrane forces of a cone
   under axial load: N_s = -P / (2 pi r cos(phi)), N_theta = 0).
"""

from __future__ import annotations

import numpy as np

from ..checks import finite, finite_array

__all__ = ["axial_force", "meridional_resultant"]


def _mass_behind(r1, sin_phi, length, rho_h, t):
    """Shell mass (kg) between each element's aft end and the local coordinate t (m)."""
    return 2.0 * np.pi * rho_h * (r1 * t + 0.5 * sin_phi * t**2)  # int 2 pi rho h r ds


def axial_force(
    t: np.ndarray, F0: float, *, r1: np.ndarray, sin_phi: np.ndarray, length: np.ndarray,
    rho_h: np.ndarray, supported_forward_end: bool = False,
) -> np.ndarray:
    """Axial compressive force F(s) (N) at points t (m) inside every element.

    Parameters
    ----------
    t : ndarray, shape (e, g)
        Meridian distance of the points from each element's aft end (m).
    F0 : float
        Thrust at the aft edge (N).
    r1 : ndarray, shape (e,)
        Radius at each element's aft end (m).
    sin_phi : ndarray, shape (e,)
        dr/ds of each element (dimensionless).
    length : ndarray, shape (e,)
        Meridian length of each element (m); the elements are ordered aft to forward.
    rho_h : ndarray, shape (e,)
        Mass per unit area rho h (kg/m^2).
    supported_forward_end : bool
        Uniform F = F0 (reacted at the nose) instead of inertia relief.

    Returns
    -------
    ndarray, shape (e, g)
        F(s) (N), positive in compression.

    References
    ----------
    .. [1] Brush & Almroth 1975, ch. 5; Newton's second law for the mass ahead of s.
    """
    F0 = finite("F0", F0)
    t = finite_array("t", t)
    r1, sin_phi = finite_array("r1", r1), finite_array("sin_phi", sin_phi)
    length = finite_array("length", length, positive=True)
    rho_h = finite_array("rho_h", rho_h, positive=True)
    if supported_forward_end:
        return np.full(t.shape, F0)
    elem_mass = _mass_behind(r1, sin_phi, length, rho_h, length)
    before = np.concatenate(([0.0], np.cumsum(elem_mass)[:-1]))
    total = elem_mass.sum()
    behind = before[:, None] + _mass_behind(r1[:, None], sin_phi[:, None], length[:, None],
                                            rho_h[:, None], t)
    return F0 * (total - behind) / total  # F = F0 m_ahead / m_total (inertia relief)


def meridional_resultant(force: np.ndarray, r: np.ndarray, *, cos_phi: np.ndarray
                         ) -> np.ndarray:
    """Membrane prestress N_s^0 = -F / (2 pi r cos(phi)) (N/m, compression negative).

    Parameters
    ----------
    force : ndarray, shape (e, g)
        Axial compressive force (N).
    r : ndarray, shape (e, g)
        Radius at the points (m), > 0.
    cos_phi : ndarray, shape (e,)
        dx/ds of each element (dimensionless), nonzero.

    Returns
    -------
    ndarray, shape (e, g)
        N_s^0 (N/m).

    References
    ----------
    .. [1] Flügge 1973, sec. 2.2.2 (axial equilibrium of a cone: 2 pi r N_s cos(phi) = -F).
    """
    force, r = finite_array("force", force), finite_array("r", r, positive=True)
    cos_phi = finite_array("cos_phi", cos_phi)
    flat = (cos_phi == 0.0)[:, None]
    if np.any(flat & (force != 0.0)):
        raise ValueError("cos_phi = 0 (a flat annular plate): cannot carry a non-zero axial "
                         "force as a membrane")
    cos_safe = np.where(flat, 1.0, cos_phi[:, None])  # a flat plate without force: N_s = 0
    return np.where(flat, 0.0, -force / (2.0 * np.pi * r * cos_safe))  # Flügge 2.2.2
