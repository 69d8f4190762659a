"""The meridian mesh of a shell-of-revolution vehicle: arrays over its conical elements."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["Mesh"]


@dataclass(frozen=True)
class Mesh:
    """Elements of the meridian (arrays over the elements, aft to forward).

    Attributes
    ----------
    order : int
        Polynomial degree p.
    segment : ndarray of int
        Segment index of each element.
    s1, x1, r1 : ndarray
        Meridian coordinate, axial station and radius of each element's aft end (m).
    length : ndarray
        Meridian length of each element (m).
    sin_phi, cos_phi, phi : ndarray
        Meridian angle of each element (phi in rad).
    thickness, E, nu, rho : ndarray
        Element properties (m, Pa, -, kg/m^3).
    elements_per_segment : tuple of int
        Element count of every segment.
    dofs : ndarray of int, shape (e, 3 (p + 1))
        Full DOF index of every element DOF.
    frame : ndarray, shape (e, 2)
        Angle (rad) of the node frame at each element's ends (phi: local, 0: global).
    n_full : int
        Number of full DOFs.
    end_nodes : tuple
        Full DOF index of the first node DOF at the aft end, forward end and each junction
        (aft side, forward side).
    areal_mass : ndarray or None
        Mass per unit wall area of each element (kg/m^2): rho h plus the non-structural and
        smeared stiffener masses; None: rho h.
    pressure : ndarray or None
        Internal gauge pressure of each element (Pa); None: 0.
    stiffening : ndarray, shape (e, 6, 6), or None
        Smeared-stiffener terms added to the constitutive matrix diag(A, D) (N/m, N, N m);
        None: none.
    """

    order: int
    segment: np.ndarray
    s1: np.ndarray
    x1: np.ndarray
    r1: np.ndarray
    length: np.ndarray
    sin_phi: np.ndarray
    cos_phi: np.ndarray
    phi: np.ndarray
    thickness: np.ndarray
    E: np.ndarray
    nu: np.ndarray
    rho: np.ndarray
    elements_per_segment: tuple
    dofs: np.ndarray
    frame: np.ndarray
    n_full: int
    end_nodes: tuple
    areal_mass: np.ndarray | None = None
    pressure: np.ndarray | None = None
    stiffening: np.ndarray | None = None

    @property
    def wall_mass(self) -> np.ndarray:
        """Mass per unit wall area of each element (kg/m^2)."""
        return self.rho * self.thickness if self.areal_mass is None else self.areal_mass

    @property
    def n_elements(self) -> int:
        """Number of elements."""
        return int(self.length.size)
