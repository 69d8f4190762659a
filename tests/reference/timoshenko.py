"""A free-free Timoshenko beam with rigid end bodies: an independent model of the k = 1 bending
of a slender thin tube (verification only).

Linear w and theta elements, one-point (reduced) shear integration, consistent mass with the
rotary inertia, Cowper's thin-tube shear coefficient 2 (1 + nu) / (4 + 3 nu); a rigid body
(m, offset e, I) at a node adds m (w + e theta)^2 + I theta^2 to the kinetic form.

References: S. P. Timoshenko, Phil. Mag. 41 (1921) 744; G. R. Cowper, J. Appl. Mech. 33 (1966)
335-340; T. J. R. Hughes, *The Finite Element Method*, 1987, sec. 5.3 (reduced integration).
"""

from __future__ import annotations

import math

import numpy as np
import scipy.linalg as sla

__all__ = ["tube_bending_frequencies"]


def tube_bending_frequencies(*, radius: float, length: float, thickness: float, E: float,
                             nu: float, rho: float, bodies=(), extra_mass_per_length: float = 0.0,
                             n_el: int = 800, count: int = 3) -> np.ndarray:
    """Lowest ``count`` elastic omega (rad/s) of the free-free thin tube as a Timoshenko beam.

    Parameters
    ----------
    radius, length, thickness, E, nu, rho : float
        The tube (m, Pa, -, kg/m^3).
    bodies : sequence of (node, (m, e, I))
        Rigid end bodies at nodes 0..n_el.
    extra_mass_per_length : float
        Translational mass per unit length added to rho A (kg/m), no rotary inertia (a liquid
        that moves with the tube).
    n_el, count : int
        Elements and frequencies.
    """
    ei = E * math.pi * radius**3 * thickness
    area = 2.0 * math.pi * radius * thickness
    kga = 2.0 * (1.0 + nu) / (4.0 + 3.0 * nu) * E / (2.0 * (1.0 + nu)) * area
    rho_a, rho_i = rho * area + extra_mass_per_length, rho * math.pi * radius**3 * thickness
    le = length / n_el
    n = 2 * (n_el + 1)
    K, M = np.zeros((n, n)), np.zeros((n, n))
    lin = np.array([[1.0, 0.5], [0.5, 1.0]]) * le / 3.0  # consistent linear mass
    shear = np.array([-1.0 / le, -0.5, 1.0 / le, -0.5])  # gamma = w' - theta at the midpoint
    for e in range(n_el):
        w, t = [2 * e, 2 * e + 2], [2 * e + 1, 2 * e + 3]
        d = [2 * e, 2 * e + 1, 2 * e + 2, 2 * e + 3]
        K[np.ix_(t, t)] += ei / le * np.array([[1.0, -1.0], [-1.0, 1.0]])
        K[np.ix_(d, d)] += kga * le * np.outer(shear, shear)
        M[np.ix_(w, w)] += rho_a * lin
        M[np.ix_(t, t)] += rho_i * lin
    for node, (m, off, inertia) in bodies:
        row, rot = np.zeros(n), np.zeros(n)
        row[2 * node], row[2 * node + 1] = 1.0, off
        rot[2 * node + 1] = 1.0
        M += m * np.outer(row, row) + inertia * np.outer(rot, rot)
    vals = sla.eigh(K, M, subset_by_index=(0, count + 1), eigvals_only=True)
    return np.sqrt(vals[2:2 + count])  # two rigid-body modes first
