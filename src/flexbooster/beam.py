"""Free-free Euler-Bernoulli beam functions (memo section 4.1, appendix C).

The composite is treated, for its bending, as a uniform free-free beam of the same mass and
length 2L (memo 4.1 A).  Its modes are written in the beam coordinate zeta = xi_bar - d4/L + 1
(C-6), which runs from 0 at the aft edge to 2 at the nose; with x = lambda_n zeta / 2,

    phi_n = cosh x + cos x - alpha_n (sinh x + sin x)                       (C-1, erratum E5)

where lambda_n are the roots of cos(lambda) cosh(lambda) = 1 and
alpha_n = (cosh lambda_n - cos lambda_n) / (sinh lambda_n - sin lambda_n) (C-IV).

cosh and sinh grow like e^lambda, so the functions are evaluated in scaled form: with
A = (1 - alpha)/2, B = (1 + alpha)/2, cosh x - alpha sinh x = A e^x + B e^-x, and A is computed
as a ratio that never forms e^lambda (see :func:`mode_shape`).

References
----------
.. [1] Tech Memo 104, eq. (4.1-2), (4.2-8b), appendix C.
.. [2] R. D. Blevins, *Formulas for Natural Frequency and Mode Shape*, Van Nostrand, 1979,
   table 8-1 (free-free beam: lambda = 4.73004074, 7.85320462, 10.9956078, ...).
"""

from __future__ import annotations

import numpy as np

__all__ = [
    "free_free_eigenvalues",
    "free_free_alpha",
    "first_bending_frequency",
    "mode_shape",
]


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

    References
    ----------
    Tech Memo 104, appendix C-IV; Blevins (1979), table 8-1.
    """
    n = int(n)
    if n < 1:
        raise ValueError(f"n = {n}: need at least one root")
    lam = (np.arange(1, n + 1) + 0.5) * np.pi
    for _ in range(50):
        e = np.exp(-lam)
        sech = 2.0 * e / (1.0 + e * e)
        tanh = (1.0 - e * e) / (1.0 + e * e)
        f = np.cos(lam) - sech
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
        Number of values.

    Returns
    -------
    numpy.ndarray
        Shape (n,), dimensionless.  Evaluated divided through by cosh lambda, so it does not
        overflow for large n (alpha_n -> 1).

    References
    ----------
    Tech Memo 104, appendix C-IV.
    """
    return _alpha(free_free_eigenvalues(n))


def _alpha(lam: np.ndarray) -> np.ndarray:
    e = np.exp(-lam)
    sech = 2.0 * e / (1.0 + e * e)
    tanh = (1.0 - e * e) / (1.0 + e * e)
    return (1.0 - np.cos(lam) * sech) / (tanh - np.sin(lam) * sech)


def _one_minus_alpha_scaled(lam: np.ndarray) -> np.ndarray:
    """(1 - alpha) e^lambda / 2, computed without forming e^lambda."""
    e = np.exp(-lam)
    # 1 - alpha = (cos - sin - e^-lam) / (sinh - sin); sinh - sin = e^lam (1 - e^-2lam - 2 e^-lam sin)/2
    return (np.cos(lam) - np.sin(lam) - e) / (1.0 - e * e - 2.0 * e * np.sin(lam))


def mode_shape(n: int | np.ndarray, zeta: np.ndarray, derivative: int = 0) -> np.ndarray:
    """The free-free mode phi_n and its derivatives at beam coordinates zeta in [0, 2].

    Parameters
    ----------
    n : int or array of int
        Mode numbers (1-based); broadcast against ``zeta``.
    zeta : array_like
        Beam coordinate zeta = xi_bar - d4/L + 1 (C-6), 0 at the aft edge, 2 at the nose
        (dimensionless).
    derivative : int
        Order k of the derivative with respect to the argument x = lambda_n zeta / 2, as the
        memo writes phi_n^(k) (C-2..C-5); the derivative with respect to zeta is
        (lambda_n / 2)^k times this.

    Returns
    -------
    numpy.ndarray
        phi_n^(k)(x), normalised so that the integral of phi_n^2 over zeta in [0, 2] is 2.

    Notes
    -----
    With A = (1 - alpha)/2 and B = (1 + alpha)/2,
    phi^(k) = A e^x + (-1)^k B e^-x + cos(x + k pi/2) - alpha sin(x + k pi/2), and
    A e^x = [(1 - alpha) e^lambda / 2] e^(x - lambda) with x <= lambda, so nothing overflows.

    References
    ----------
    Tech Memo 104, eqs. (4.1-2), (C-1)..(C-5) (erratum E5: no sum over n).
    """
    n = np.asarray(n)
    zeta = np.asarray(zeta, dtype=float)
    nmax = int(np.max(n))
    lam_all = free_free_eigenvalues(nmax)
    lam = lam_all[n - 1]
    alpha = _alpha(lam)
    x = lam * zeta / 2.0
    grow = _one_minus_alpha_scaled(lam) * np.exp(x - lam)  # A e^x
    decay = 0.5 * (1.0 + alpha) * np.exp(-x)  # B e^-x
    shift = derivative * np.pi / 2.0
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
    lam1 = free_free_eigenvalues(1)[0]
    return float((lam1 / (2.0 * L)) ** 2 * R1 * np.sqrt(E / (2.0 * rho)))  # eq. (4.2-8b)
