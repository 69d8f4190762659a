"""Passage through a parametric region and through a forced resonance during the flight.

* Slow passage through a region: with sigma(t) the frozen-time Floquet growth rate, the
  amplitude grows by exp(integral of max(sigma, 0) dt) (the e-folds); sigma is linear between
  the frozen times and the integral of its positive part is exact on that schedule.
* Passage through a damped resonance under a linear sweep: q'' + 2 zeta omega q' + omega^2 q =
  f cos(phi(t)), phi' = Omega(t) linear in t, integrated exactly for the forcing linear between
  samples (first-order hold: the state transition and the two input matrices from one matrix
  exponential, then a first-order complex recursion run by scipy.signal.lfilter), starting in
  the steady state of the first frequency. The peak is lower than the steady one,
  f / (2 zeta sqrt(1 - zeta^2) omega^2), and tends to it as the sweep slows.

Theory: docs/theory/flight.md. References: V. V. Bolotin, *The Dynamic Stability of Elastic
Systems*, 1964 (frozen-coefficient growth); F. M. Lewis, Trans. ASME 54 (1932) 253-261;
R. Markert, M. Seidler, Mech. Syst. Signal Process. 15 (2001) 1281-1291 (passage through
resonance); G. F. Franklin, J. D. Powell, M. Workman, *Digital Control of Dynamic Systems*,
1998, sec. 6.3 (first-order hold).
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass
from typing import Any

import numpy as np
import scipy.linalg
import scipy.signal

from ..checks import count, finite, finite_array, nonnegative, positive
from ..floquet import StepLimitError

__all__ = ["Passage", "accumulated_growth", "ResonancePassage", "sweep_response",
           "sweep_passage", "steady_peak", "peak_ratio", "MAX_SWEEP_STEPS",
           "SWEEP_WINDOW"]

#: Default cap on the samples of one sweep (about 160 MB of work arrays).
MAX_SWEEP_STEPS = 10_000_000
#: Half-width of the dimensionless sweep window of :func:`peak_ratio`, in units of
#: zeta + sqrt(eta) around Omega / omega = 1.
SWEEP_WINDOW = 12.0


@dataclass(frozen=True)
class Passage:
    """Accumulated growth of a piecewise-linear growth rate sigma(t).

    Attributes
    ----------
    efolds : float
        integral of max(sigma, 0) dt (dimensionless, >= 0).
    max_growth : float
        Largest sigma (1/s), of the knots.
    t_start, t_end : float or None
        First and last time at which sigma > 0 (s); None where sigma <= 0 throughout.
    dwell : float
        Total time with sigma > 0 (s).
    net_efolds : float
        integral of sigma dt, signed (the decay outside the regions included).
    """

    efolds: float
    max_growth: float
    t_start: float | None
    t_end: float | None
    dwell: float
    net_efolds: float

    @property
    def amplification(self) -> float:
        """exp(efolds), the growth of the amplitude; the largest float where it overflows."""
        if self.efolds >= math.log(sys.float_info.max):
            return sys.float_info.max
        return math.exp(self.efolds)


def accumulated_growth(times: Any, sigma: Any, *, tol: float = 0.0) -> Passage:
    """The e-folds integral of max(sigma, 0) dt, sigma linear between the knots: on each
    segment the positive part is a trapezoid or a triangle cut at the zero
    t_c = t_0 + h s_0 / (s_0 - s_1), integrated exactly.

    Parameters
    ----------
    times : array_like
        Knots (s), strictly increasing, at least one.
    sigma : array_like
        Growth rate at the knots (1/s), finite, same length.
    tol : float
        Rates |sigma| <= tol are taken as 0 (>= 0; the round-off of a neutrally stable
        frozen system's log|rho| / T): the e-folds change by at most tol times the duration.
    """
    t = finite_array("times", times).ravel()
    s = finite_array("sigma", sigma).ravel()
    tol = nonnegative("tol", tol)
    if s.size != t.size:
        raise ValueError(f"sigma: {s.size} values, must be {t.size} like times")
    if np.any(np.diff(t) <= 0.0):
        raise ValueError("times: must be strictly increasing")
    s = np.where(np.abs(s) <= tol, 0.0, s)
    s0, s1, h = s[:-1], s[1:], np.diff(t)
    both = (s0 >= 0.0) & (s1 >= 0.0)
    mixed = (s0 > 0.0) != (s1 > 0.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        frac_pos = np.where(mixed, np.maximum(s0, s1) / np.abs(s1 - s0), 0.0)
    area = np.where(both, 0.5 * (s0 + s1) * h,  # trapezoid
                    np.where(mixed & ~both, 0.5 * np.maximum(s0, s1) * frac_pos * h, 0.0))
    # the open set {sigma > 0} as a length and its first and last points
    pos_len = np.where(both, h, np.where(mixed & ~both, frac_pos * h, 0.0))
    pos_len = np.where((s0 == 0.0) & (s1 == 0.0), 0.0, pos_len)
    opened = np.nonzero(pos_len > 0.0)[0]
    if opened.size:
        i, j = int(opened[0]), int(opened[-1])
        t_start = float(t[i] if s[i] > 0.0 else t[i + 1] - frac_pos[i] * h[i])
        t_end = float(t[j + 1] if s[j + 1] > 0.0 else t[j] + frac_pos[j] * h[j])
    else:  # sigma <= 0 throughout, or > 0 on a set of zero measure (one knot)
        t_start = t_end = None
    net = float(np.sum(0.5 * (s0 + s1) * h))  # trapezoid, exact for linear sigma
    return Passage(efolds=float(np.sum(area)), max_growth=float(np.max(s)),
                   t_start=t_start, t_end=t_end, dwell=float(np.sum(pos_len)), net_efolds=net)


def steady_peak(omega: float, zeta: float, force: float) -> float:
    """Largest steady amplitude of q'' + 2 zeta omega q' + omega^2 q = f cos(Omega t) over
    Omega: f / (2 zeta sqrt(1 - zeta^2) omega^2), at Omega = omega sqrt(1 - 2 zeta^2)
    (Meirovitch 1986, sec. 3.2); zeta < 1/sqrt(2).

    Parameters
    ----------
    omega, zeta, force : float
        Natural frequency (rad/s, > 0), damping ratio (0 < zeta < 1/sqrt 2), forcing per unit
        modal mass f (> 0).
    """
    omega = positive("omega", omega)
    zeta = positive("zeta", zeta)
    force = positive("force", force)
    if zeta >= math.sqrt(0.5):
        raise ValueError(f"zeta = {zeta!r}: must be < 1/sqrt(2) for a resonant peak")
    return force / (2.0 * zeta * math.sqrt(1.0 - zeta * zeta) * omega * omega)


@dataclass(frozen=True)
class ResonancePassage:
    """The response to a linear sweep through a resonance.

    Attributes
    ----------
    peak : float
        Largest |q| over the sweep (units of f / omega^2).
    t_peak : float
        When (s from the sweep's start).
    Omega_at_peak : float
        The forcing pulsation then (rad/s).
    steady_peak : float
        f / (2 zeta sqrt(1 - zeta^2) omega^2), the stationary peak.
    steps : int
        Samples of the forcing (first-order hold).
    """

    peak: float
    t_peak: float
    Omega_at_peak: float
    steady_peak: float
    steps: int

    @property
    def ratio(self) -> float:
        """peak / steady_peak (< 1 for a sweep that does not dwell)."""
        return self.peak / self.steady_peak


def _sweep_args(omega, zeta, force, Omega_start, Omega_end, duration, steps_per_cycle,
                max_steps) -> tuple[float, float, float, float, float, float, int]:
    omega = positive("omega", omega)
    zeta = nonnegative("zeta", zeta)
    if zeta >= 1.0:
        raise ValueError(f"zeta = {zeta!r}: must be in [0, 1) (an oscillating mode)")
    force = finite("force", force)
    Om0 = positive("Omega_start", Omega_start)
    Om1 = positive("Omega_end", Omega_end)
    duration = positive("duration", duration)
    spc = count("steps_per_cycle", steps_per_cycle, low=8, high=10_000)
    max_steps = count("max_steps", max_steps, low=16, high=None)
    cycles = max(omega, Om0, Om1) * duration / (2.0 * math.pi)
    steps = int(math.ceil(spc * cycles))
    if steps > max_steps:
        raise StepLimitError(f"steps = {steps}: a sweep of {cycles:.4g} cycles at "
                             f"{spc} steps per cycle exceeds max_steps = {max_steps}")
    return omega, zeta, force, Om0, Om1, duration, max(steps, 16)


def sweep_response(*, omega: float, zeta: float, force: float, Omega_start: float,
                   Omega_end: float, duration: float, phase: float = 0.0,
                   steps_per_cycle: int = 64,
                   max_steps: int = MAX_SWEEP_STEPS) -> tuple[np.ndarray, np.ndarray]:
    """Response q(t) of q'' + 2 zeta omega q' + omega^2 q = f cos(phi(t)),
    phi = phase + Omega_start t + (Omega_end - Omega_start) t^2 / (2 duration), from the
    steady state of Omega_start: exact for the forcing linear between the samples.

    Parameters
    ----------
    omega : float
        Natural frequency (rad/s), > 0.
    zeta : float
        Damping ratio, 0 <= zeta < 1.
    force : float
        Forcing per unit modal mass f (units of q times s^-2); :func:`sweep_passage`: != 0.
    Omega_start, Omega_end : float
        Forcing pulsation at the start and at the end (rad/s), > 0.
    duration : float
        Sweep time (s), > 0.
    phase : float
        phi(0) (rad).
    steps_per_cycle : int
        Samples per period of the fastest of omega and Omega (8..10000): the deterministic
        accuracy limit; the forcing's interpolation error is about (2 pi / steps)^2 / 12.
    max_steps : int
        Cap on the samples (:class:`flexbooster.floquet.StepLimitError` beyond).

    Returns
    -------
    t, q : numpy.ndarray
        Sample times (s) and displacements.
    """
    omega, zeta, force, Om0, Om1, duration, steps = _sweep_args(
        omega, zeta, force, Omega_start, Omega_end, duration, steps_per_cycle, max_steps)
    phase = finite("phase", phase)
    h = duration / steps
    t = np.linspace(0.0, duration, steps + 1)
    alpha = (Om1 - Om0) / duration
    u = force * np.cos(phase + Om0 * t + 0.5 * alpha * t * t)  # f cos(phi(t))
    A = np.array([[0.0, 1.0], [-omega * omega, -2.0 * zeta * omega]])
    aug = np.zeros((4, 4))
    aug[:2, :2] = A * h
    aug[1, 2] = h
    aug[2, 3] = 1.0
    E = scipy.linalg.expm(aug)  # first-order hold (Franklin, Powell, Workman sec. 6.3)
    Phi, F1, F2 = E[:2, :2], E[:2, 2], E[:2, 3]
    # x_{n+1} = Phi x_n + (F1 - F2) u_n + F2 u_{n+1}; diagonalise Phi (complex pair)
    mu, V = np.linalg.eig(Phi)
    W = np.linalg.inv(V)
    k = int(np.argmax(mu.imag)) if np.any(mu.imag != 0.0) else 0
    w, v = W[k], V[:, k]
    H = force / (omega * omega - Om0 * Om0 + 2j * zeta * omega * Om0)  # steady at Omega_start
    x0 = np.array([np.real(H * np.exp(1j * phase)), np.real(1j * Om0 * H * np.exp(1j * phase))])
    if np.any(mu.imag != 0.0):
        b = [w @ F2, w @ (F1 - F2)]
        y0 = w @ x0
        y, _ = scipy.signal.lfilter(b, [1.0, -mu[k]], u.astype(complex),
                                    zi=[y0 - b[0] * u[0]])
        q = 2.0 * np.real(v[0] * y)  # x = v y + conj(v y)
    else:  # zeta = 0 with omega h a multiple of pi cannot occur: steps_per_cycle >= 8
        raise ValueError(f"zeta = {zeta!r}: the state transition has no complex pair")
    return t, q


def sweep_passage(*, omega: float, zeta: float, force: float, Omega_start: float,
                  Omega_end: float, duration: float, phase: float = 0.0,
                  steps_per_cycle: int = 64,
                  max_steps: int = MAX_SWEEP_STEPS) -> ResonancePassage:
    """The largest |q| of :func:`sweep_response`, refined by the parabola through the largest
    sample and its neighbours, against the steady peak.

    Parameters
    ----------
    omega, zeta, force, Omega_start, Omega_end, duration, phase, steps_per_cycle, max_steps
        As :func:`sweep_response`; here 0 < zeta < 1/sqrt(2).
    """
    t, q = sweep_response(omega=omega, zeta=zeta, force=force, Omega_start=Omega_start,
                          Omega_end=Omega_end, duration=duration, phase=phase,
                          steps_per_cycle=steps_per_cycle, max_steps=max_steps)
    stat = steady_peak(omega, zeta, abs(finite("force", force)))
    a = np.abs(q)
    i = int(np.clip(np.argmax(a), 1, a.size - 2))
    y0, y1, y2 = a[i - 1], a[i], a[i + 1]
    den = y0 - 2.0 * y1 + y2
    s = 0.5 * (y0 - y2) / den if den < 0.0 else 0.0  # vertex of the parabola, |s| <= 1/2
    s = float(np.clip(s, -0.5, 0.5))
    peak = float(y1 - 0.25 * (y0 - y2) * s)
    h = t[1] - t[0]
    t_peak = float(t[i] + s * h)
    Om_peak = float(Omega_start + (Omega_end - Omega_start) * t_peak / duration)
    return ResonancePassage(peak=peak, t_peak=t_peak, Omega_at_peak=Om_peak,
                            steady_peak=float(stat), steps=int(t.size - 1))


def peak_ratio(zeta: float, eta: float, *, steps_per_cycle: int = 64,
               max_steps: int = MAX_SWEEP_STEPS) -> float:
    """Non-stationary over steady peak of a mode swept through resonance at the dimensionless
    rate eta = d(Omega / omega)/dt / omega (= alpha / omega^2 for a constant omega and
    Omega' = alpha; > 0 upward, < 0 downward), through Omega / omega in
    1 -+ SWEEP_WINDOW (zeta + sqrt|eta|); the peak of a slow sweep is the steady one
    (ratio -> 1 as eta -> 0, Lewis 1932).

    Parameters
    ----------
    zeta : float
        Damping ratio, 0 < zeta < 1/sqrt(2).
    eta : float
        Dimensionless sweep rate, != 0.
    steps_per_cycle, max_steps : int
        As :func:`sweep_response`.
    """
    zeta = positive("zeta", zeta)
    eta = finite("eta", eta)
    if eta == 0.0:
        raise ValueError("eta = 0.0: must be != 0 (a sweep; a dwell has the steady peak)")
    rate = abs(eta)
    half = SWEEP_WINDOW * (zeta + math.sqrt(rate))
    lo = max(1.0 - half, 0.05)
    hi = 1.0 + half
    start, end = (lo, hi) if eta > 0.0 else (hi, lo)
    result = sweep_passage(omega=1.0, zeta=zeta, force=1.0, Omega_start=start, Omega_end=end,
                           duration=(hi - lo) / rate, steps_per_cycle=steps_per_cycle,
                           max_steps=max_steps)
    return result.ratio
