"""Free-free Euler-Bernoulli beam functions (memo section 4.1, appendices B and C).

phi_n = cosh X + cos X - alpha_n (sinh X + sin X), X = lambda_n zeta / 2 (C-1, erratum E5),
zeta = xi_bar - d4/L + 1 from 0 (aft edge) to 2 (nose) (C-6); cos(lambda) cosh(lambda) = 1;
a prime is d/dX (C-2..C-5). Evaluated in scaled form so nothing forms e^lambda. The
coefficient integrals of appendix B (r, s, t, x, y, z) by the memo's closed form, a corrected
closed form or quadrature, in the printed (E10) or zero phase of theta_j. Theory:
docs/theory/beam-pitch.md.

References: Tech Memo 104, eqs. (4.1-2), (4.2-8b), (5.3-2), (5.3-3), appendices B, C;
R. D. Blevins, *Formulas for Natural Frequency and Mode Shape*, 1979, table 8-1;
L. Meirovitch, *Elements of Vibration Analysis*, 1986, sec. 7.4.
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
    """The first ``n`` roots lambda_1..lambda_n > 0 of cos(lambda) cosh(lambda) = 1, to full
    precision (Blevins 1979, table 8-1).

    Newton on cos(lambda) = sech(lambda) from (n + 1/2) pi; the memo's lambda_n ~ (2n - 1) pi / 2
    (C-IV) is off by one index (erratum C-IV-a).

    Parameters
    ----------
    n : int
        Number of roots (n >= 1).
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
    """alpha_n = (cosh lambda_n - cos lambda_n) / (sinh lambda_n - sin lambda_n), n = 1..n (C-IV),
    without overflow.

    Parameters
    ----------
    n : int
        Number of values (n >= 1).
    """
    return alpha_from_eigenvalues(free_free_eigenvalues(n))


def alpha_from_eigenvalues(lam: np.ndarray) -> np.ndarray:
    """alpha_n = (cosh - cos) / (sinh - sin) of lambda_n, without overflow (memo C-IV).

    Parameters
    ----------
    lam : numpy.ndarray
        Free-free eigenvalues lambda_n, > 0.
    """
    e = np.exp(-lam)
    sech = 2.0 * e / (1.0 + e * e)
    tanh = (1.0 - e * e) / (1.0 + e * e)
    # C-IV: alpha = (cosh - cos)/(sinh - sin), numerator and denominator divided by cosh
    return (1.0 - np.cos(lam) * sech) / (tanh - np.sin(lam) * sech)


def one_minus_alpha_scaled(lam: np.ndarray) -> np.ndarray:
    """(1 - alpha_n) e^lambda_n / 2, computed without forming e^lambda (memo C-IV).

    Parameters
    ----------
    lam : numpy.ndarray
        Free-free eigenvalues lambda_n, > 0.
    """
    e = np.exp(-lam)
    # 1 - alpha = (cos - sin - e^-lam) / (sinh - sin),
    # sinh - sin = e^lam (1 - e^-2lam - 2 e^-lam sin) / 2
    return (np.cos(lam) - np.sin(lam) - e) / (1.0 - e * e - 2.0 * e * np.sin(lam))


def mode_shape(n: int | np.ndarray, zeta: np.ndarray, derivative: int = 0) -> np.ndarray:
    """The free-free mode phi_n^(k)(X) at zeta in [0, 2], int_0^2 phi_n^2 dzeta = 2 (4.1-2,
    C-1..C-5, E5).

    phi^(k) = A e^X + (-1)^k B e^-X + cos(X + k pi/2) - alpha sin(X + k pi/2), A = (1 - alpha)/2,
    B = (1 + alpha)/2, with A e^X = [(1 - alpha) e^lambda / 2] e^(X - lambda): no overflow.

    Parameters
    ----------
    n : int or array of int
        Mode numbers (>= 1), broadcast against ``zeta``.
    zeta : array_like
        Beam coordinate (C-6), 0 at the aft edge, 2 at the nose.
    derivative : int
        Order k of the derivative in X = lambda_n zeta / 2, 0..4 (the orders of the beam
        equation, 4.1-4..7); d/dzeta adds (lambda_n / 2)^k.
    """
    n = np.asarray(n)
    if n.size == 0 or not np.issubdtype(n.dtype, np.integer) or np.min(n) < 1:
        raise ValueError(f"n = {n!r}: mode numbers must be integers >= 1")
    derivative = count("derivative", derivative, 0, 4)  # the orders of the beam equation
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
    """omega_1 = (lambda_1 / 2L)^2 R1 sqrt(E / (2 rho)) (rad/s), memo eq. (4.2-8b): the thin tube
    of cylinder 1 (EI/m = E R1^2 / (2 rho)) for the whole beam.

    Parameters
    ----------
    L : float
        Half-length of the composite (m); the beam length is 2L.
    R1 : float
        Radius of cylinder 1 (m).
    E, rho : float
        Young's modulus (Pa) and density (kg/m^3).
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
    lambda_n, alpha_n : numpy.ndarray
        Shape (N,), roots of cos(lambda) cosh(lambda) = 1 and the mode constants.
    omega_n : numpy.ndarray or None
        Shape (N,), omega_n = (lambda_n / 2L)^2 R1 sqrt(E / 2 rho) (rad/s) when the beam data
        were given; omega_n[0] is omega_1.
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
    """lambda_n, alpha_n (n = 1..N) and, when L, R1, E and rho are all given, omega_n (rad/s;
    eq. 4.2-8b for n = 1).

    Parameters
    ----------
    N : int
        Number of modes (>= 1).
    L, R1 : float, optional
        Half-length of the composite and radius of cylinder 1 (m).
    E, rho : float, optional
        Young's modulus (Pa) and density (kg/m^3).
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
