"""The derived model of a booster: every quantity the memo's stages share, computed once.

:func:`booster_model` turns the case's SI numbers into a frozen :class:`BoosterModel`: mass
properties (2.2), omega_1 (4.2-8b), omega_psi (4.2-1, E2), the dimensionless groups and shell
parameters (3.0, E3), the strain scale (5.3-4a), the thrust, truncation and Omega grid.
Inside the solvers frequencies are in units of omega_1; rad/s only at the edges.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..checks import count, finite, nonnegative, positive
from .beam import first_bending_frequency
from .geometry import DimensionlessGroups, MassProperties, dimensionless_groups, mass_properties
from .pitch import pitch_frequency
from .shell_coefficients import ShellParameters, shell_parameters

__all__ = ["Truncation", "BoosterModel", "booster_model"]


@dataclass(frozen=True)
class Truncation:
    """Mode counts of the memo's series (dimensionless integers).

    Attributes
    ----------
    M1, N1, M2, N2 : int
        Shell modes j = 0..M_d, k = 0..N_d of cylinder d (5.2-1).
    N : int
        Elastic free-free beam modes n = 1..N (4.1-1).
    S : int
        Floquet harmonics s = -S..S (4.1-10/11).
    R : int
        Beam exponents alpha_r reported, r = 1..R.
    """

    M1: int
    N1: int
    M2: int
    N2: int
    N: int
    S: int
    R: int


@dataclass(frozen=True)
class BoosterModel:
    """The derived model of a booster (all SI; built by :func:`booster_model`).

    Attributes
    ----------
    R1, L1, R2, L2 : float
        Radii and half-lengths of cylinder 1 (aft) and 2 (forward) (m).
    h, E, nu, rho : float
        Shell thickness (m), Young's modulus (Pa), Poisson's ratio, density (kg/m^3).
    F0, T0 : float
        Total steady thrust (N) and per unit circumference of the aft edge, F0 / (2 pi R1) (N/m).
    gamma, K : float
        Pulsation amplitude of T0 (1 - gamma cos Omega t) and gimbal gain.
    Omega : numpy.ndarray
        The case's uniform grid of thrust frequencies (rad/s).
    truncation : Truncation
        Mode counts.
    mass : MassProperties
        Geometry and mass properties (memo 2.2).
    omega_1, omega_psi : float
        First bending frequency (4.2-8b) and rigid pitch frequency sqrt(F0 d2 K / I_cm)
        (4.2-1) (rad/s).
    groups : DimensionlessGroups
        mu, lambda_d, sigma, T0_bar (memo 3.0).
    shell : ShellParameters
        Dimensionless shell parameters (3.0-1, 3.0-4).
    strain : float
        (1 - nu^2) T0 / (E h), the scale of the membrane strain u* (5.3-4a).
    beam_damping_ratio, pitch_damping_ratio : float
        Modal damping ratios of the elastic beam modes and of the rigid pitch, in [0, 1).
    """

    R1: float
    L1: float
    R2: float
    L2: float
    h: float
    E: float
    nu: float
    rho: float
    F0: float
    T0: float
    gamma: float
    K: float
    Omega: np.ndarray
    truncation: Truncation
    mass: MassProperties
    omega_1: float
    omega_psi: float
    groups: DimensionlessGroups
    shell: ShellParameters
    strain: float
    beam_damping_ratio: float = 0.0
    pitch_damping_ratio: float = 0.0

    @property
    def T0_bar(self) -> float:
        """T0_bar = T0 / (rho h L^2 omega_1^2), eq. (3.0-4b) (dimensionless)."""
        return self.groups.T0_bar

    @property
    def Omega_bar(self) -> np.ndarray:
        """The Omega grid in units of omega_1 (dimensionless)."""
        return self.Omega / self.omega_1

    @property
    def omega_range(self) -> tuple[float, float]:
        """(omega_min, omega_max) of the grid (rad/s)."""
        return float(self.Omega[0]), float(self.Omega[-1])

    @property
    def radii(self) -> tuple[float, float]:
        """(R1, R2) (m)."""
        return self.R1, self.R2


def booster_model(
    *,
    R1: float,
    L1: float,
    R2: float,
    L2: float,
    h: float,
    E: float,
    nu: float,
    rho: float,
    F0: float,
    gamma: float,
    K: float,
    Omega: np.ndarray,
    truncation: Truncation,
    beam_damping_ratio: float = 0.0,
    pitch_damping_ratio: float = 0.0,
) -> BoosterModel:
    """Build the derived model of a booster (memo 2.2-3, 3.0-1, 3.0-4b, 4.2-1, 4.2-8b, 5.3-4a).

    Parameters
    ----------
    R1, L1, R2, L2 : float
        Radius and half-length of the aft and forward cylinders (m), > 0.
    h : float
        Shell thickness (m), 0 < h < min(R1, R2).
    E, nu, rho : float
        Young's modulus (Pa) > 0, Poisson's ratio in [0, 0.5), density (kg/m^3) > 0.
    F0 : float
        Total steady thrust (N), > 0.
    gamma, K : float
        Pulsation amplitude in [0, 1) and gimbal gain >= 0.
    Omega : array_like
        Thrust frequencies of the grid (rad/s), 1-D, > 0, increasing.
    truncation : Truncation
        Mode counts.
    beam_damping_ratio, pitch_damping_ratio : float
        Damping ratios of the elastic beam modes and of the rigid pitch, in [0, 1).
    """
    F0 = positive("F0", F0)
    gamma = nonnegative("gamma", gamma)
    if gamma >= 1.0:
        raise ValueError(f"gamma = {gamma!r}: must satisfy 0 <= gamma < 1")
    K = nonnegative("K", K)
    Omega = np.atleast_1d(np.asarray(Omega, dtype=float))
    if Omega.ndim != 1 or Omega.size == 0 or not np.all(np.isfinite(Omega)) or Omega[0] <= 0:
        raise ValueError("Omega: must be a non-empty 1-D array of finite values > 0 (rad/s)")
    if np.any(np.diff(Omega) <= 0):
        raise ValueError("Omega: must be increasing")
    for name in ("M1", "N1", "M2", "N2", "N", "R"):
        count(f"truncation.{name}", getattr(truncation, name), 1)
    count("truncation.S", truncation.S, 0)
    nu = finite("nu", nu)
    for name, zeta in (("beam_damping_ratio", beam_damping_ratio),
                       ("pitch_damping_ratio", pitch_damping_ratio)):
        if nonnegative(name, zeta) >= 1.0:
            raise ValueError(f"{name} = {zeta!r}: must satisfy 0 <= zeta < 1")
    mass = mass_properties(R1, L1, R2, L2, h, rho)
    omega_1 = first_bending_frequency(mass.L, R1, E, rho)  # eq. (4.2-8b)
    T0 = F0 / (2.0 * math.pi * R1)  # F0 = 2 pi R1 T0
    return BoosterModel(
        R1=float(R1), L1=float(L1), R2=float(R2), L2=float(L2), h=float(h), E=float(E),
        nu=nu, rho=float(rho), F0=F0, T0=T0, gamma=gamma, K=K, Omega=Omega,
        truncation=truncation, mass=mass, omega_1=omega_1,
        omega_psi=pitch_frequency(F0, mass.d2, K, mass.I_cm),  # eq. (4.2-1), erratum E2
        groups=dimensionless_groups(mass.L, R1, R2, h, E, rho, omega_1, T0),
        shell=shell_parameters(R1, L1, R2, L2, h, E, nu, rho, omega_1),
        strain=(1.0 - nu**2) * T0 / (E * h),  # eq. (5.3-4a) scale
        beam_damping_ratio=float(beam_damping_ratio),
        pitch_damping_ratio=float(pitch_damping_ratio),
    )
