"""Excitation of the shells: psi(tau), T(tau) and the beam coordinates (memo 4.1-10, 4.2-6)."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np
import scipy.linalg

from ...checks import count, finite, positive
from ...floquet import characteristic_exponent
from ..beam_action import (
    BeamActionResult,
    beam_system,
    hill_exponents,
    loaded_frequencies,
    natural_branch,
    reduced_exponents,
)
from ..model import BoosterModel
from ..pitch import mathieu_parameters

__all__ = [
    "excitation_at",
    "beam_exponents_on",
    "N_BASIS",
    "checked_times",
    "BASIS",
    "Excitation",
    "ExcitationParameters",
    "excitation_parameters",
    "make_excitation",
]

BASIS = ("F_T", "u_T", "u_T_dd", "psi_dd", "psi_d_sq", "F_T_psi")
N_BASIS = len(BASIS)


def checked_times(tau: Any) -> np.ndarray:
    """Times tau as a checked 1-D float array.

    Parameters
    ----------
    tau : array_like
        Dimensionless times tau = omega_1 t, finite, >= 0, non-decreasing, non-empty.
    """
    tau = np.atleast_1d(np.asarray(tau, dtype=float))
    if tau.ndim != 1 or tau.size == 0 or not np.all(np.isfinite(tau)) or np.any(tau < 0):
        raise ValueError("tau: must be a non-empty 1-D array of finite values >= 0")
    if np.any(np.diff(tau) < 0):
        raise ValueError("tau: must be non-decreasing")
    return tau


@dataclass(frozen=True)
class Excitation:
    """Time functions that force the shell modes at one thrust frequency Omega.

    Attributes
    ----------
    Omega_bar, gamma, K : float
        Omega / omega_1, thrust pulsation amplitude, gimbal gain.
    T0_bar, strain : float
        T0 / (rho h L^2 omega_1^2) (3.0-4b) and (1 - nu^2) T0 / (E h) (5.3-4a).
    beta : float
        Pitch exponent beta (real, 4.2-9).
    A, Omega_i : numpy.ndarray
        Shape (3,): A_1..A_3 of psi (4.2-7) (rad) and Omega_i = [(i-2)^2 + eps_i beta] Omega_bar
        (7.2-6), units of omega_1.
    beam_freq, beam_amp : numpy.ndarray
        (alpha_r + s) Omega_bar, shape (C,), and C_n^(s), shape (C, N + 1) complex (4.1-10..12).
    N : int
        Beam modes.
    alpha : complex
        The beam exponent alpha_r used (its real part sets beam_freq).
    warnings : tuple of str
        Conditions under which the excitation was built (e.g. an unstable beam exponent).
    """

    Omega_bar: float
    gamma: float
    K: float
    T0_bar: float
    strain: float
    beta: float
    A: np.ndarray
    Omega_i: np.ndarray
    beam_freq: np.ndarray
    beam_amp: np.ndarray
    N: int
    alpha: complex = 0j
    warnings: tuple[str, ...] = field(default_factory=tuple)

    def thrust(self, tau: np.ndarray, derivative: int = 0) -> np.ndarray:
        """T(tau) / T0 = 1 - gamma cos(Omega_bar tau) (4.2-1a) or its second derivative."""
        tau = np.asarray(tau, dtype=float)
        c = np.cos(self.Omega_bar * tau)
        if derivative == 2:
            return self.gamma * self.Omega_bar**2 * c  # d^2/dtau^2 of (4.2-1a)
        return 1.0 - self.gamma * c  # eq. (4.2-1a)

    def psi(self, tau: np.ndarray, derivative: int = 0) -> np.ndarray:
        """psi = sum A_i cos(Omega_i tau) (4.2-6) and its derivatives (rad)."""
        ph = np.multiply.outer(np.asarray(tau, dtype=float), self.Omega_i)
        w = self.Omega_i**derivative
        trig = (np.cos, lambda x: -np.sin(x), lambda x: -np.cos(x))[derivative]
        return trig(ph) @ (self.A * w)  # eq. (4.2-6)

    def beam(self, tau: np.ndarray, derivative: int = 0) -> np.ndarray:
        """q_1..q_N, q_B (4.1-10/11): Re sum_s C^(s) e^{i nu_s tau}, shape (N + 1, nt)."""
        tau = np.atleast_1d(np.asarray(tau, dtype=float))
        if self.beam_freq.size == 0:
            return np.zeros((self.N + 1, tau.size))
        e = np.exp(1j * np.multiply.outer(self.beam_freq, tau))  # (C, nt)
        amp = self.beam_amp * ((1j * self.beam_freq[:, None]) ** derivative)
        return np.real(amp.T @ e)  # eqs. (4.1-10), (4.1-11)

    def time_functions(self, tau: np.ndarray) -> np.ndarray:
        """All basis functions in the time domain, shape (6 + 2(N + 1), nt): :data:`BASIS`, then
        q_1..q_N, q_B, then their second derivatives.
        """
        tau = np.atleast_1d(np.asarray(tau, dtype=float))
        T = self.thrust(tau)
        psi = self.psi(tau)
        rows = [0.5 * self.T0_bar * T, self.strain * T, self.strain * self.thrust(tau, 2),
                self.psi(tau, 2), self.psi(tau, 1) ** 2, 0.5 * self.K * self.T0_bar * T * psi]
        return np.concatenate([np.stack(rows), self.beam(tau), self.beam(tau, 2)])

    def harmonics(self) -> tuple[np.ndarray, np.ndarray]:
        """The basis functions as f_b(tau) = Re sum_h c[b, h] e^{i nu_h tau}: nu (H,) (units of
        omega_1) and c (6 + 2(N + 1), H); the products psi'^2 and T psi expand into the sum and
        difference frequencies of memo 7.3.
        """
        Ob, g, A, W = self.Omega_bar, self.gamma, self.A, self.Omega_i
        tf, eps, kt = 0.5 * self.T0_bar, self.strain, 0.5 * self.K * self.T0_bar
        nb = N_BASIS + 2 * (self.N + 1)
        nu: list[float] = []
        cols: list[tuple[int, complex]] = []

        def add(freq: float, row: int, amp: complex) -> None:
            nu.append(float(freq))
            cols.append((row, complex(amp)))

        add(0.0, 0, tf)  # T0_bar T / 2, T = 1 - gamma cos(Omega_bar tau) (4.2-1a)
        add(Ob, 0, -g * tf)
        add(0.0, 1, eps)  # eps T
        add(Ob, 1, -g * eps)
        add(Ob, 2, eps * g * Ob**2)  # eps T''
        for i in range(3):
            add(W[i], 3, -A[i] * W[i] ** 2)  # psi'' (4.2-6)
            add(W[i], 5, kt * A[i])  # K T0_bar T psi / 2
            add(Ob + W[i], 5, -0.5 * g * kt * A[i])
            add(Ob - W[i], 5, -0.5 * g * kt * A[i])
            for p in range(3):
                half = 0.5 * A[i] * A[p] * W[i] * W[p]
                add(W[i] - W[p], 4, half)  # psi'^2
                add(W[i] + W[p], 4, -half)
        for c, f in enumerate(self.beam_freq):
            for b in range(self.N + 1):
                add(f, N_BASIS + b, self.beam_amp[c, b])  # q_b
                add(f, N_BASIS + self.N + 1 + b, -(f**2) * self.beam_amp[c, b])  # q_b''
        out = np.zeros((nb, len(nu)), dtype=complex)
        for h, (row, amp) in enumerate(cols):
            out[row, h] = amp
        return np.asarray(nu), out


@dataclass(frozen=True)
class ExcitationParameters:
    """beta(Omega_bar) and alpha_r(Omega_bar): the one parameter function of the forcing, shared by
    the stability roots and :func:`make_excitation` (a simulation at a root is exactly resonant).

    Attributes
    ----------
    omega_psi, omega_1 : float
        Rigid-body pitch and reference frequencies (rad/s).
    gamma : float
        Pulsation amplitude.
    Omega_bar : numpy.ndarray
        Shape (G,), increasing, the grid of the beam exponents (units of omega_1).
    alpha_Omega : numpy.ndarray
        Shape (G, R), Re alpha_r Omega_bar on that grid (units of omega_1), interpolated.
    """

    omega_psi: float
    gamma: float
    omega_1: float
    Omega_bar: np.ndarray
    alpha_Omega: np.ndarray
    _spline: Any = field(repr=False, compare=False)

    def beta(self, Omega_bar: Any) -> np.ndarray:
        """Exact characteristic exponent beta (complex; Hill's determinant) at Omega_bar (4.2-9).

        Parameters
        ----------
        Omega_bar : array_like
            Omega / omega_1, > 0.
        """
        x = np.atleast_1d(np.asarray(Omega_bar, dtype=float))
        a, q = mathieu_parameters(x * self.omega_1, self.omega_psi, self.gamma)  # (4.2-4)
        return characteristic_exponent(a, q, method="hill")

    def alpha(self, Omega_bar: Any) -> np.ndarray:
        """Re alpha_r (r = 1..R) at Omega_bar, shape (n, R): the cubic spline of alpha_r Omega_bar.

        Parameters
        ----------
        Omega_bar : array_like
            Omega / omega_1, > 0; held constant outside the grid.
        """
        x = np.atleast_1d(np.asarray(Omega_bar, dtype=float))
        lo, hi = self.Omega_bar[0], self.Omega_bar[-1]
        return self._spline(np.clip(x, lo, hi)) / x[:, None]

    def __call__(self, Omega_bar: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(Re beta (n,), Re alpha_r (n, R)) at Omega_bar, the ``params`` of the stability solver.

        Parameters
        ----------
        Omega_bar : numpy.ndarray
            Shape (n,), Omega / omega_1, > 0.
        """
        return self.beta(Omega_bar).real, self.alpha(Omega_bar)


def excitation_parameters(model: BoosterModel,
                          beam_action: BeamActionResult) -> ExcitationParameters:
    """The parameter function of a booster (4.1-10, 4.1-11, 4.2-4, 4.2-9): beta exact (Hill) at any
    Omega, alpha_r Omega_bar a cubic spline of the grid's exponents, constant outside.

    Parameters
    ----------
    model : BoosterModel
        The derived model (omega_psi, gamma, omega_1).
    beam_action : BeamActionResult
        Beam-action exponents on the Omega grid: ``Omega_bar`` and ``alpha`` alone are used.
    """
    x = beam_action.Omega_bar
    order = np.argsort(x)
    y = (beam_action.alpha.real * x[:, None])[order]
    return ExcitationParameters(
        omega_psi=float(model.omega_psi), gamma=float(model.gamma),
        omega_1=float(model.omega_1), Omega_bar=x[order], alpha_Omega=y,
        _spline=cubic_spline(x[order], y))


@dataclass(frozen=True)
class CubicSplineData:
    """A piecewise cubic y(x) = sum_k c[k, i] (x - x_i)^(3 - k) on [x_i, x_(i+1)].

    Attributes
    ----------
    x : numpy.ndarray
        Shape (n,), the breakpoints, increasing.
    c : numpy.ndarray
        Shape (4, n - 1, m), the coefficients, highest power first.
    """

    x: np.ndarray
    c: np.ndarray

    def __call__(self, xi: np.ndarray) -> np.ndarray:
        """The spline at ``xi``, shape (k,) -> (k, m); the end pieces extend beyond the breakpoints;
        the arithmetic of scipy's ``PPoly``, bit for bit.
        """
        i = np.clip(np.searchsorted(self.x, xi, side="right") - 1, 0, self.x.size - 2)
        s = (xi - self.x[i])[:, None]
        c = self.c[:, i]
        value = 0.0 + c[3]
        power = s
        value = value + c[2] * power
        power = power * s
        value = value + c[1] * power
        power = power * s
        return value + c[0] * power


def cubic_spline(x: np.ndarray, y: np.ndarray) -> CubicSplineData:
    """The not-a-knot cubic spline of y(x) (de Boor, *A Practical Guide to Splines*, 2001, ch. IV).

    The knot slopes solve the tridiagonal C2 system by ``solve_banded``; three knots give the
    parabola, two the line: the arithmetic of ``scipy.interpolate.CubicSpline`` without
    importing scipy.interpolate (and scipy.optimize) at start.

    Parameters
    ----------
    x : numpy.ndarray
        Shape (n,), n >= 2, strictly increasing, finite.
    y : numpy.ndarray
        Shape (n, m), finite.
    """
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    n = x.size
    dx = np.diff(x)
    if (x.ndim != 1 or n < 2 or y.ndim != 2 or y.shape[0] != n
            or not (np.all(np.isfinite(x)) and np.all(np.isfinite(y)) and np.all(dx > 0))):
        raise ValueError("x, y: x must be 1-D, finite, strictly increasing, n >= 2; y finite, "
                         "shape (n, m)")
    dxr = dx[:, None]
    slope = np.diff(y, axis=0) / dxr
    if n == 2:  # the line
        s = np.concatenate((slope, slope))
    elif n == 3:  # the parabola: s_0 + s_1 = 2 slope_0, s_1 + s_2 = 2 slope_1, C2 at x_1
        dense = np.array([[1.0, 1.0, 0.0],
                          [dx[1], 2 * (dx[0] + dx[1]), dx[0]],
                          [0.0, 1.0, 1.0]])
        rhs = np.stack((2 * slope[0], 3 * (dxr[0] * slope[1] + dxr[1] * slope[0]),
                        2 * slope[1]))
        s = scipy.linalg.solve(dense, rhs, overwrite_a=True, overwrite_b=True,
                               check_finite=False)
    else:
        band = np.zeros((3, n))  # the tridiagonal matrix by diagonals (solve_banded's layout)
        rhs = np.empty(y.shape)
        band[1, 1:-1] = 2 * (dx[:-1] + dx[1:])  # C2 continuity at the interior knots
        band[0, 2:] = dx[:-1]
        band[-1, :-2] = dx[1:]
        rhs[1:-1] = 3 * (dxr[1:] * slope[:-1] + dxr[:-1] * slope[1:])
        d = x[2] - x[0]  # not-a-knot at x_1
        band[1, 0] = dx[1]
        band[0, 1] = d
        rhs[0] = ((dxr[0] + 2 * d) * dxr[1] * slope[0] + dxr[0] ** 2 * slope[1]) / d
        d = x[-1] - x[-3]  # and at x_(n-2)
        band[1, -1] = dx[-2]
        band[-1, -2] = d
        rhs[-1] = (dxr[-1] ** 2 * slope[-2] + (2 * d + dxr[-1]) * dxr[-2] * slope[-1]) / d
        s = scipy.linalg.solve_banded((1, 1), band, rhs, overwrite_ab=True, overwrite_b=True,
                                      check_finite=False)
    t = (s[:-1] + s[1:] - 2 * slope) / dxr  # the Hermite cubic of each piece
    return CubicSplineData(x=x, c=np.stack((t / dxr, (slope - s[:-1]) / dxr - t, s[:-1],
                                            y[:-1])))


def beam_exponents_on(model: BoosterModel, x: np.ndarray, N: int, S: int) -> tuple:
    """(HillResult, natural-branch exponents (G, N + 1)) of the beam-action system on a grid (memo
    4.1-10, 4.1-11).

    Parameters
    ----------
    model : BoosterModel
        The derived model (omega_1, gamma).
    x : numpy.ndarray
        Omega / omega_1, shape (G,).
    N, S : int
        Elastic beam modes and Hill harmonics s = -S..S.
    """
    system = beam_system(model, N)
    hill = hill_exponents(system, x * model.omega_1, np.full(x.shape, model.gamma), S)
    nat = natural_branch(reduced_exponents(hill.alpha), x, loaded_frequencies(system))
    return hill, nat


def make_excitation(model: BoosterModel, Omega: float, *, psi0: float = 0.01,
                    beam_amplitude: float = 1e-4, beam_mode: int = 1, N: int | None = None,
                    S: int | None = None, params: ExcitationParameters | None = None
                    ) -> Excitation:
    """The time functions that force the shells at the thrust frequency Omega (memo 4.1-10..12,
    4.2-6..9).

    A_i from (4.2-7b..d) with the exact beta; the beam vector from Hill's determinant at the
    exponent nearest alpha_r. ValueError for bad input, an unbounded pitch (complex beta) or
    an unbounded beam (complex alpha_r: Omega inside a beam-action instability band).

    Parameters
    ----------
    model : BoosterModel
        The derived model; ``truncation.N``, ``.S`` give the defaults of N, S.
    Omega : float
        Thrust pulsation frequency (rad/s), > 0.
    psi0 : float
        Initial pitch angle psi(0) (rad) (4.2-8a); 0 switches the rigid-body terms off.
    beam_amplitude : float
        Norm of the beam's Floquet vector (units of L); 0 switches the beam terms off.
    beam_mode : int
        Which beam exponent alpha_r (r = 1..N + 1, natural branch) moves the beam.
    N, S : int, optional
        Beam modes and Hill harmonics (default: the case's truncation).
    params : ExcitationParameters, optional
        The pipeline's parameter function (beta, alpha_r as the stability roots use them);
        without it, both from Hill's determinant at Omega.
    """
    N = count("N", model.truncation.N if N is None else N, 0)
    S = count("S", model.truncation.S if S is None else S, 0)
    return excitation_at(model, Omega, psi0, beam_amplitude, beam_mode, N, S, params)


def excitation_at(model: BoosterModel, Omega: float, psi0: float, beam_amplitude: float,
                     beam_mode: int, N: int, S: int, params: ExcitationParameters | None,
                     beam_pre: tuple | None = None) -> Excitation:
    """:func:`make_excitation` with every argument given (checked here).

    Parameters
    ----------
    model : BoosterModel
        The derived model.
    Omega : float
        Thrust frequency (rad/s), > 0.
    psi0 : float
        Initial pitch angle (rad).
    beam_amplitude : float
        Norm of the beam's Floquet vector (units of L).
    beam_mode : int
        Beam exponent followed, 1..N + 1.
    N, S : int
        Elastic beam modes; Hill harmonics.
    params : ExcitationParameters or None
        Precomputed exponents along Omega (None: computed here).
    beam_pre : tuple, optional
        :func:`beam_exponents_on` at this Omega, computed before.
    """
    Omega = positive("Omega", Omega)
    psi0 = finite("psi0", psi0)
    beam_amplitude = finite("beam_amplitude", beam_amplitude)
    beam_mode = count("beam_mode", beam_mode, 1, N + 1)
    Ob = Omega / model.omega_1
    a, q = mathieu_parameters(np.array([Omega]), model.omega_psi, model.gamma)  # (4.2-4)
    a, q = float(a[0]), float(q[0])
    if params is not None:
        beta_c = complex(params.beta(Ob)[0])
    else:
        beta_c = complex(characteristic_exponent(a, q, "hill"))
    if abs(beta_c.imag) > 0.0:
        raise ValueError(f"Omega = {Omega!r}: the pitch motion is unbounded (beta = {beta_c}); "
                         "psi of eq. (4.2-6) does not exist")
    beta = beta_c.real
    if psi0 != 0.0:
        den1, den3 = a - (beta - 2.0) ** 2, a - (2.0 + beta) ** 2
        A2 = psi0 / (1.0 + q * (1.0 / den3 + 1.0 / den1))  # eq. (4.2-7c)
        A = np.array([A2 * q / den1, A2, A2 * q / den3])  # eqs. (4.2-7b, d)
    else:
        A = np.zeros(3)
    Omega_i = np.array([1.0 - beta / 2.0, beta / 2.0, 1.0 + beta / 2.0]) * Ob  # (7.2-1..3)
    warnings: list[str] = []
    alpha = 0j
    if beam_amplitude != 0.0 and N >= 0:
        if beam_pre is None:
            hill, nat = beam_exponents_on(model, np.array([Ob]), N, S)
            beam_pre = (hill.alpha[0], hill.C[0], nat[0])
        cand, Cs, nat_row = beam_pre
        target = complex(nat_row[beam_mode - 1])
        if params is not None and beam_mode <= params.alpha_Omega.shape[1]:
            target = complex(params.alpha(Ob)[0, beam_mode - 1], target.imag)
        shift = cand.real - target.real - np.round(cand.real - target.real)
        dist = np.abs(shift) + np.abs(cand.imag - target.imag)
        e = int(np.argmin(dist))
        alpha = complex(cand[e])
        if abs(alpha.imag) > 1e-9:  # q ~ exp(i alpha Omega t): grows, no bounded form
            raise ValueError(
                f"Omega = {Omega!r}: inside an instability band of the beam action (alpha_"
                f"{beam_mode} = {alpha:.6g} is complex): the beam motion grows like exp("
                f"{abs(alpha.imag) * Omega:.4g} t / s), which the bounded Floquet form "
                "(4.1-10) cannot show; choose an Omega outside the band "
                "(flexbooster stability lists them) or beam_amplitude = 0")
        if params is not None:  # the parameter function's value, in Hill's representative
            alpha = complex(alpha.real - shift[e], alpha.imag)
        s = np.arange(-S, S + 1)
        beam_freq = (alpha.real + s) * Ob  # eqs. (4.1-10), (4.1-11)
        C = Cs[e]  # (2S + 1, N + 1), unit norm
        beam_amp = beam_amplitude * C
    else:
        beam_freq = np.zeros(0)
        beam_amp = np.zeros((0, N + 1), dtype=complex)
    return Excitation(Omega_bar=Ob, gamma=model.gamma, K=model.K, T0_bar=model.T0_bar,
                      strain=model.strain, beta=beta, A=A, Omega_i=Omega_i,
                      beam_freq=beam_freq, beam_amp=beam_amp, N=N, alpha=alpha,
                      warnings=tuple(warnings))
