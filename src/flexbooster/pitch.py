"""Rigid-body pitch of the booster under the gimbaled pulsating thrust (memo section 4.2).

For small psi, eq. (4.2-1) with the lever arm d2 (erratum E2) is

    psi'' + (2 pi R1 d2 K T(t) / I_cm) psi = 0,  T(t) = T0 (1 - gamma cos Omega t),

and with tau_1 = Omega t / 2 it becomes the Mathieu equation (4.2-3)
psi'' + (a - 2 q cos 2 tau_1) psi = 0 with (4.2-4)

    a = 8 pi R1 d2 K T0 / (I_cm Omega^2) = 4 omega_psi^2 / Omega^2,   q = gamma a / 2,

where omega_psi = sqrt(2 pi R1 d2 K T0 / I_cm) is the rigid-body pitch frequency under the
steady thrust.

References
----------
.. [1] Tech Memo 104, eqs. (2.2-2c), (4.2-1)..(4.2-5).
.. [2] N. W. McLachlan, *Theory and Application of Mathieu Functions*, Oxford, 1947.
"""

from __future__ import annotations

import numpy as np

__all__ = ["pitch_frequency", "mathieu_parameters"]


def pitch_frequency(F0: float, d2: float, K: float, I_cm: float) -> float:
    """Rigid-body pitch frequency omega_psi under the steady thrust (rad/s).

    Parameters
    ----------
    F0 : float
        Total steady thrust, F0 = 2 pi R1 T0 (N).
    d2 : float
        Lever arm, CM to the aft edge (m) (erratum E2).
    K : float
        Gimbal gain (dimensionless, >= 0): the thrust turns by K psi.
    I_cm : float
        Pitch moment of inertia about the CM (kg m^2).

    Returns
    -------
    float
        omega_psi = sqrt(F0 d2 K / I_cm) (rad/s); zero when K = 0.

    References
    ----------
    Tech Memo 104, eq. (4.2-1) linearised, with erratum E2.
    """
    return float(np.sqrt(F0 * d2 * K / I_cm))  # eq. (4.2-1), sin(K psi) ~ K psi


def mathieu_parameters(
    Omega: np.ndarray, omega_psi: float, gamma: float
) -> tuple[np.ndarray, np.ndarray]:
    """Mathieu parameters a(Omega), q(Omega) of the rigid-body pitch equation.

    Parameters
    ----------
    Omega : array_like
        Thrust pulsation frequency (rad/s), > 0.
    omega_psi : float
        Rigid-body pitch frequency (rad/s), see :func:`pitch_frequency`.
    gamma : float
        Relative amplitude of the thrust pulsation (dimensionless).

    Returns
    -------
    a, q : numpy.ndarray
        a = 4 omega_psi^2 / Omega^2 = 8 pi R1 d2 K T0 / (I_cm Omega^2) and q = gamma a / 2
        (eq. 4.2-4), dimensionless, shaped like ``Omega``.

    References
    ----------
    Tech Memo 104, eq. (4.2-4) with erratum E2.
    """
    Omega = np.asarray(Omega, dtype=float)
    a = 4.0 * omega_psi**2 / Omega**2  # eq. (4.2-4): 8 pi R1 d2 K T0 / (I_cm Omega^2)
    q = gamma * a / 2.0  # eq. (4.2-4)
    return a, q
