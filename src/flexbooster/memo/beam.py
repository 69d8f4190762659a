"""Free-free Euler-Bernoulli beam functions (memo section 4.1, appendices B and C).

The composite is treated, for its bending, as a uniform free-free beam of the same mass and
length 2L (memo 4.1 A).  Its modes are written in the beam coordinate zeta = xi_bar - d4/L + 1
(C-6), which runs from 0 at the aft edge to 2 at the nose; with X = lambda_n zeta / 2,

    phi_n = cosh X + cos X - alpha_n (sinh X + sin X)                       (C-1, erratum E5)

where lambda_n are the roots of cos(lambda) cosh(lambda) = 1 and
alpha_n = (cosh lambda_n - cos lambda_n) / (sinh lambda_n - sin lambda_n) (C-IV).  As in the
memo (C-2..C-5), a prime on phi_n is a derivative with respect to the argument X; the
derivative with respect to xi_bar (or zeta) carries a factor (lambda_n / 2) per order.

cosh and sinh grow like e^lambda, so the functions are evaluated in scaled form: with
A = (1 - alpha)/2, B = (1 + alpha)/2, cosh X - alpha sinh X = A e^X + B e^-X, and A is computed
as a ratio that never forms e^lambda (see :func:`mode_shape`).

The coefficient integrals of appendix B,

    r_jn = int sin(theta_j),           s_jn = int phi_n sin(theta_j),
    t_jn = int phi_n' sin(theta_j),    x_jn = int phi_n'' sin(theta_j),
    y_jn = int phi_n''' sin(theta_j),  z_jn = int phi_n' cos(theta_j),

over one cylinder (xi_bar from a to c for cylinder 1, from c to b for cylinder 2) are given
three ways (:func:`coefficient_integrals`): the closed form printed in the memo (B-1, B-7,
B-13..B-17, B-19..B-23; ``method="memo"``), a corrected closed form (the antiderivative
evaluated at the limits; ``method="closed"``) and Gauss-Legendre quadrature
(``method="quadrature"``), each for two phases of the shell functions theta_j (``phase``):

* ``"memo"``: as printed in 5.3-2/5.3-3, theta_j = (j pi / 2)((L/L1) xi_bar - r1 + 1),
  r1 = (L1 - d1)/L1, for cylinder 1 and theta_j = (j pi / 2)((L/L2) xi_bar + r2 + 1),
  r2 = (d1 - L1 - L2)/L2, for cylinder 2 (reading guide erratum E10: not zero at the aft edge
  of the cylinder);
* ``"zero"``: theta_j = 0 at the aft edge of the cylinder and j pi at its forward edge.

References
----------
.. [1] Tech Memo 104, eqs. (4.1-2), (4.2-8b), (5.3-2), (5.3-3), appendices B and C.
.. [2] R. D. Blevins, *Formulas for Natural Frequency and Mode Shape*, Van Nostrand, 1979,
   table 8-1 (free-free beam: lambda = 4.73004074, 7.85320462, 10.9956078, ...).
.. [3] L. Meirovitch, *Elements of Vibration Analysis*, 2nd ed., McGraw-Hill, 1986, sec. 7.4
   (orthogonality of the free-free modes).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..checks import count

__all__ = [
    "one_minus_alpha_scaled",
    "alpha_from_eigenvalues",
    "free_free_eigenvalues",
    "free_free_alpha",
    "first_bending_frequency",
    "mode_shape",
    "BeamModes",
    "beam_modes",
]



def _check_count(name: str, value: Any, minimum: int = 1) -> int:
    return count(name, value, low=minimum, high=None)


def free_free_eigenvalues(n: int) -> np.ndarray:
    """The first ``n`` roots lambda_1..lambda_n of cos(lambda) cosh(lambda) = 1, lambda > 0.

    Parameters
    ----------
    n : int
        Number of roots (n >= 1).

    Returns
    -------
    numpy.ndarray
        Shape (n,), the eigenvalues of the free-free beam (dimensionless; frequency
        omega_n = (lambda_n / l)^2 sqrt(EI / m) for a beam of length l), to full double
        precision.

    Notes
    -----
    The equation is solved as cos(lambda) = sech(lambda), Newton's method from
    (n + 1/2) pi; sech is evaluated as 2 e^-lambda / (1 + e^-2 lambda), which never overflows.
    The memo's asymptotic value lambda_n ~ (2n - 1) pi / 2 (C-IV) is off by one index: the
    root near (2n - 1) pi / 2 is lambda_(n-1) (erratum C-IV-a).

    References
    ----------
    Tech Memo 104, appendix C-IV; Blevins (1979), table 8-1.
    """
    n = _check_count("n", n)
    lam = (np.arange(1, n + 1) + 0.5) * np.pi
    for _ in range(50):
        e = np.exp(-lam)
        sech = 2.0 * e / (1.0 + e * e)
        tanh = (1.0 - e * e) / (1.0 + e * e)
        f = np.cos(lam) - sech  # C-IV: cos(lambda) cosh(lambda) = 1
        fp = -np.sin(lam) + sech * tanh
        step = f / fp
        lam = lam - step
        if np.all(np.abs(step) <= 4.0 * np.finfo(float).eps * lam):
            break
    return lam


def free_free_alpha(n: int) -> np.ndarray:
    """alpha_n = (cosh lambda_n - cos lambda_n) / (sinh lambda_n - sin lambda_n), n = 1..n.

    Parameters
    ----------
    n : int
        Number of values (n >= 1).

    Returns
    -------
    numpy.ndarray
        Shape (n,), dimensionless.  Evaluated divided through by cosh lambda, so it does not
        overflow for large n (alpha_n -> 1).

    References
    ----------
    Tech Memo 104, appendix C-IV.
    """
    return alpha_from_eigenvalues(free_free_eigenvalues(n))


def alpha_from_eigenvalues(lam: np.ndarray) -> np.ndarray:
    """alpha_n = (cosh - cos) / (sinh - sin) of lambda_n, without overflow (memo C-IV).

    Parameters
    ----------
    lam : numpy.ndarray
        Free-free eigenvalues lambda_n (dimensionless), > 0.

    Returns
    -------
    numpy.ndarray
        alpha_n (dimensionless).
    """
    e = np.exp(-lam)
    sech = 2.0 * e / (1.0 + e * e)
    tanh = (1.0 - e * e) / (1.0 + e * e)
    # C-IV: alpha = (cosh - cos)/(sinh - sin), numerator and denominator divided by cosh
    return (1.0 - np.cos(lam) * sech) / (tanh - np.sin(lam) * sech)


def one_minus_alpha_scaled(lam: np.ndarray) -> np.ndarray:
    """(1 - alpha) e^lambda / 2, computed without forming e^lambda (memo C-IV).

    Parameters
    ----------
    lam : numpy.ndarray
        Free-free eigenvalues lambda_n (dimensionless), > 0.

    Returns
    -------
    numpy.ndarray
        (1 - alpha_n) e^lambda_n / 2 (dimensionless).
    """
    e = np.exp(-lam)
    # 1 - alpha = (cos - sin - e^-lam) / (sinh - sin),
    # sinh - sin = e^lam (1 - e^-2lam - 2 e^-lam sin) / 2
    return (np.cos(lam) - np.sin(lam) - e) / (1.0 - e * e - 2.0 * e * np.sin(lam))


def mode_shape(n: int | np.ndarray, zeta: np.ndarray, derivative: int = 0) -> np.ndarray:
    """The free-free mode phi_n and its derivatives at beam coordinates zeta in [0, 2].

    Parameters
    ----------
    n : int or array of int
        Mode numbers (1-based, >= 1); broadcast against ``zeta``.
    zeta : array_like
        Beam coordinate zeta = xi_bar - d4/L + 1 (C-6), 0 at the aft edge, 2 at the nose
        (dimensionless).
    derivative : int
        Order k >= 0 of the derivative with respect to the argument X = lambda_n zeta / 2, as
        the memo writes phi_n^(k) (C-2..C-5); the derivative with respect to zeta is
        (lambda_n / 2)^k times this.

    Returns
    -------
    numpy.ndarray
        phi_n^(k)(X), normalised so that the integral of phi_n^2 over zeta in [0, 2] is 2.

    Notes
    -----
    With A = (1 - alpha)/2 and B = (1 + alpha)/2,
    phi^(k) = A e^X + (-1)^k B e^-X + cos(X + k pi/2) - alpha sin(X + k pi/2), and
    A e^X = [(1 - alpha) e^lambda / 2] e^(X - lambda) with X <= lambda, so nothing overflows
    on [0, 2].

    References
    ----------
    Tech Memo 104, eqs. (4.1-2), (C-1)..(C-5) (erratum E5: no sum over n).
    """
    n = np.asarray(n)
    if n.size == 0 or not np.issubdtype(n.dtype, np.integer) or np.min(n) < 1:
        raise ValueError(f"n = {n!r}: mode numbers must be integers >= 1")
    derivative = _check_count("derivative", derivative, minimum=0)
    zeta = np.asarray(zeta, dtype=float)
    if not np.all(np.isfinite(zeta)):
        raise ValueError("zeta: must be finite")
    nmax = int(np.max(n))
    lam_all = free_free_eigenvalues(nmax)
    lam = lam_all[n - 1]
    alpha = alpha_from_eigenvalues(lam)
    x = lam * zeta / 2.0  # C-6: X = (lambda_n / 2)(xi_bar - d4/L + 1)
    grow = one_minus_alpha_scaled(lam) * np.exp(x - lam)  # A e^X
    decay = 0.5 * (1.0 + alpha) * np.exp(-x)  # B e^-X
    shift = derivative * np.pi / 2.0
    # C-1..C-5: phi^(k) = A e^X + (-1)^k B e^-X + cos(X + k pi/2) - alpha sin(X + k pi/2)
    return grow + (-1.0) ** derivative * decay + np.cos(x + shift) - alpha * np.sin(x + shift)


def first_bending_frequency(L: float, R1: float, E: float, rho: float) -> float:
    """omega_1 of memo eq. (4.2-8b): the first free-free bending frequency (rad/s).

    Parameters
    ----------
    L : float
        Half-length of the composite (m); the beam length is 2L.
    R1 : float
        Radius of cylinder 1 (m), whose thin-tube section gives EI/m = E R1^2 / (2 rho).
    E : float
        Young's modulus (Pa).
    rho : float
        Density (kg/m^3).

    Returns
    -------
    float
        omega_1 = (lambda_1 / 2L)^2 R1 sqrt(E / (2 rho)) in rad/s.

    Notes
    -----
    For a thin tube I = pi R^3 h and the mass per length is 2 pi R h rho, so
    sqrt(EI/m) = R sqrt(E / (2 rho)); the memo uses the radius of cylinder 1 for the whole
    beam (its equivalent-beam assumption, 4.1 A).

    References
    ----------
    Tech Memo 104, eq. (4.2-8b).
    """
    for name, value in (("L", L), ("R1", R1), ("E", E), ("rho", rho)):
        if not (np.isfinite(value) and value > 0):
            raise ValueError(f"{name} = {value!r}: must be finite and > 0")
    lam1 = free_free_eigenvalues(1)[0]
    return float((lam1 / (2.0 * L)) ** 2 * R1 * np.sqrt(E / (2.0 * rho)))  # eq. (4.2-8b)


# --------------------------------------------------------------------------------------------
# Result object for the pipeline
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class BeamModes:
    """The first N free-free beam modes (memo appendix C-IV, eq. 4.2-8b).

    Attributes
    ----------
    lambda_n : numpy.ndarray
        Shape (N,), roots of cos(lambda) cosh(lambda) = 1 (dimensionless).
    alpha_n : numpy.ndarray
        Shape (N,), mode constants alpha_n (dimensionless).
    omega_n : numpy.ndarray or None
        Shape (N,), bending frequencies omega_n = (lambda_n / 2L)^2 R1 sqrt(E / 2 rho) (rad/s),
        when the beam data were given; omega_n[0] is omega_1 of eq. (4.2-8b).
    """

    lambda_n: np.ndarray
    alpha_n: np.ndarray
    omega_n: np.ndarray | None = None

    @property
    def omega_1(self) -> float | None:
        """First bending frequency omega_1 (rad/s), eq. (4.2-8b), or None."""
        return None if self.omega_n is None else float(self.omega_n[0])

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready mapping: lists of floats; omega entries are None without beam data."""
        return {
            "N": int(self.lambda_n.size),
            "lambda_n": [float(v) for v in self.lambda_n],
            "alpha_n": [float(v) for v in self.alpha_n],
            "omega_n": None if self.omega_n is None else [float(v) for v in self.omega_n],
            "omega_1": self.omega_1,
        }


def beam_modes(
    N: int,
    L: float | None = None,
    R1: float | None = None,
    E: float | None = None,
    rho: float | None = None,
) -> BeamModes:
    """lambda_n, alpha_n (n = 1..N) and, given the beam data, omega_n and omega_1.

    Parameters
    ----------
    N : int
        Number of modes (>= 1).
    L : float, optional
        Half-length of the composite (m).
    R1 : float, optional
        Radius of cylinder 1 (m).
    E : float, optional
        Young's modulus (Pa).
    rho : float, optional
        Density (kg/m^3).  The frequencies are computed only when L, R1, E and rho are all
        given.

    Returns
    -------
    BeamModes
        The mode constants and, optionally, omega_n = (lambda_n / 2L)^2 R1 sqrt(E / 2 rho)
        (rad/s; eq. 4.2-8b for n = 1).

    References
    ----------
    Tech Memo 104, appendix C-IV and eq. (4.2-8b).
    """
    N = _check_count("N", N)
    lam = free_free_eigenvalues(N)
    alpha = alpha_from_eigenvalues(lam)
    data = (L, R1, E, rho)
    omega = None
    if all(v is not None for v in data):
        omega1 = first_bending_frequency(L, R1, E, rho)
        omega = omega1 * (lam / lam[0]) ** 2  # eq. (4.2-8b) with lambda_n for lambda_1
    elif any(v is not None for v in data):
        raise ValueError("L, R1, E, rho: give all four beam data or none")
    return BeamModes(lambda_n=lam, alpha_n=alpha, omega_n=omega)
