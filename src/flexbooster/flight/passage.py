"""Passage through a parametric region and through a forced resonance during the flight.

* Slow passage through a region: with sigma(t) the frozen-time Floquet growth rate, the
  amplitude grows by exp(integral of max(sigma, 0) dt) (the e-folds); sigma is linear between
  the frozen times and the integral of its positive part is exact on that schedule.
* Passage through a damped resonance under a linear sweep: q'' + 2 zeta w q' + w^2 q =
  f cos(phi(t)), phi' = Omega(t) linear in t and w constant or linear in t, stepped exactly
  for the forcing linear between samples (first-order hold; the step maps in closed form, w
  at each step's midpoint), the affine recursion run as a vectorised scan, from the steady
  state at the start. The peak is lower than the steady one,
  f / (2 zeta sqrt(1 - zeta^2) w^2), and tends to it as the sweep slows.

Theory: docs/theory/flight.md. References: V. V. Bolotin, *The Dynamic Stability of Elastic
Systems*, 1964 (frozen-coefficient growth); F. M. Lewis, Trans. ASME 54 (1932) 253-261;
R. Markert, M. Seidler, Int. J. Solids Struct. 38 (2001) 1975-1992 (passage through
resonance); G. F. Franklin, J. D. Powell, M. Workman, *Digital Control of Dynamic Systems*,
1998, sec. 6.3 (first-order hold); W. D. Hillis, G. L. Steele, Commun. ACM 29 (1986)
1170-1183 (scan).
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..checks import count, finite, finite_array, nonnegative, positive
from ..floquet import StepLimitError

__all__ = ["Passage", "accumulated_growth", "ResonancePassage", "step_maps", "sweep_response",
           "sweep_passage", "steady_peak", "peak_ratio", "crossing_peak_ratio", "MAX_SWEEP_STEPS",
           "SWEEP_WINDOW"]

#: Default cap on the samples of one sweep (about 100 MB of work arrays).
MAX_SWEEP_STEPS = 2_000_000
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
        f / (2 zeta sqrt(1 - zeta^2) omega^2), the stationary peak, omega the mode's frequency
        at ``t_peak``.
    peak_acceleration : float
        Largest |q''| over the sweep (units of f).
    steady_peak_acceleration : float
        f / (2 zeta sqrt(1 - zeta^2)), the largest stationary |q''| (at any omega).
    steps : int
        Samples of the forcing (first-order hold).
    """

    peak: float
    t_peak: float
    Omega_at_peak: float
    steady_peak: float
    peak_acceleration: float
    steady_peak_acceleration: float
    steps: int

    @property
    def ratio(self) -> float:
        """peak / steady_peak (< 1 for a sweep that does not dwell)."""
        return self.peak / self.steady_peak

    @property
    def acceleration_ratio(self) -> float:
        """peak_acceleration / steady_peak_acceleration."""
        return self.peak_acceleration / self.steady_peak_acceleration


def _sweep_args(omega, omega_end, zeta, force, Omega_start, Omega_end, duration,
                steps_per_cycle, max_steps):
    omega = positive("omega", omega)
    omega_end = omega if omega_end is None else positive("omega_end", omega_end)
    zeta = nonnegative("zeta", zeta)
    if zeta >= 1.0:
        raise ValueError(f"zeta = {zeta!r}: must be in [0, 1) (an oscillating mode)")
    force = finite("force", force)
    Om0 = positive("Omega_start", Omega_start)
    Om1 = positive("Omega_end", Omega_end)
    duration = positive("duration", duration)
    spc = count("steps_per_cycle", steps_per_cycle, low=8, high=10_000)
    max_steps = count("max_steps", max_steps, low=16, high=None)
    cycles = max(omega, omega_end, Om0, Om1) * duration / (2.0 * math.pi)
    steps = int(math.ceil(spc * cycles))
    if steps > max_steps:
        raise StepLimitError(f"steps = {steps}: a sweep of {cycles:.4g} cycles at "
                             f"{spc} steps per cycle exceeds max_steps = {max_steps}")
    return omega, omega_end, zeta, force, Om0, Om1, duration, max(steps, 16)


def step_maps(omega: Any, zeta: float, h: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Exact one-step maps of x' = A x + (0, u)^T, A = [[0, 1], [-w^2, -2 zeta w]], for u
    linear over the step (first-order hold): x_1 = Phi x_0 + Ga u_0 + Gb u_1, with
    F1 = A^-1 (Phi - I) B, F2 = F1 - A^-1 Phi B + A^-2 (Phi - I) B / h, Ga = F1 - F2, Gb = F2
    (Franklin, Powell, Workman 1998, sec. 6.3; Phi in closed form, Meirovitch 1986, sec. 3.1).

    Parameters
    ----------
    omega : array_like
        Natural frequencies w (rad/s), > 0, one per step, shape (N,).
    zeta : float
        Damping ratio, 0 <= zeta < 1.
    h : float
        Step (s), > 0.

    Returns
    -------
    Phi, Ga, Gb : numpy.ndarray
        (N, 2, 2), (N, 2), (N, 2).
    """
    w = finite_array("omega", omega, positive=True).ravel()
    h = positive("h", h)
    wd = w * math.sqrt(1.0 - zeta * zeta)
    e = np.exp(-zeta * w * h)
    c, s = np.cos(wd * h), np.sin(wd * h)
    Phi = np.empty((w.size, 2, 2))
    Phi[:, 0, 0] = e * (c + zeta * w / wd * s)  # free damped oscillator over h
    Phi[:, 0, 1] = e * s / wd
    Phi[:, 1, 0] = -e * w * w / wd * s
    Phi[:, 1, 1] = e * (c - zeta * w / wd * s)
    Ainv = np.empty((w.size, 2, 2))  # A^-1 = [[-2 zeta / w, -1 / w^2], [1, 0]]
    Ainv[:, 0, 0] = -2.0 * zeta / w
    Ainv[:, 0, 1] = -1.0 / (w * w)
    Ainv[:, 1, 0] = 1.0
    Ainv[:, 1, 1] = 0.0
    dB = Phi[:, :, 1] - np.array([0.0, 1.0])  # (Phi - I) B, B = (0, 1)
    F1 = np.einsum("nij,nj->ni", Ainv, dB)
    F2 = F1 - np.einsum("nij,nj->ni", Ainv, Phi[:, :, 1]) + np.einsum(
        "nij,nj->ni", Ainv, F1) / h
    return Phi, F1 - F2, F2


#: Steps per block of the affine scan (bounds the work arrays).
_SCAN_BLOCK = 1 << 15


def _affine_scan(Phi: np.ndarray, g: np.ndarray, x0: np.ndarray) -> np.ndarray:
    """States x_1..x_N of x_{n+1} = Phi_n x_n + g_n: an inclusive scan of the affine maps
    (Hillis & Steele 1986; log2(N) vectorised passes on the six components of the 2 x 2
    maps), applied to x_0."""
    a, b = Phi[:, 0, 0].copy(), Phi[:, 0, 1].copy()
    c, d = Phi[:, 1, 0].copy(), Phi[:, 1, 1].copy()
    e, f = g[:, 0].copy(), g[:, 1].copy()
    k = 1
    while k < e.size:  # map[i] <- map[i] o map[i - k]: (A_i A_j, A_i g_j + g_i)
        a2, b2, c2, d2 = a[:-k], b[:-k], c[:-k], d[:-k]
        e2, f2 = e[:-k], f[:-k]
        a1, b1, c1, d1 = a[k:], b[k:], c[k:], d[k:]
        e[k:], f[k:] = a1 * e2 + b1 * f2 + e[k:], c1 * e2 + d1 * f2 + f[k:]
        a[k:], b[k:], c[k:], d[k:] = (a1 * a2 + b1 * c2, a1 * b2 + b1 * d2,
                                      c1 * a2 + d1 * c2, c1 * b2 + d1 * d2)
        k *= 2
    return np.stack([a * x0[0] + b * x0[1] + e, c * x0[0] + d * x0[1] + f], axis=1)


def sweep_response(*, omega: float, zeta: float, force: float, Omega_start: float,
                   Omega_end: float, duration: float, omega_end: float | None = None,
                   phase: float = 0.0, steps_per_cycle: int = 64,
                   max_steps: int = MAX_SWEEP_STEPS
                   ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Response of q'' + 2 zeta w(t) q' + w(t)^2 q = f cos(phi(t)),
    phi = phase + Omega_start t + (Omega_end - Omega_start) t^2 / (2 duration), w linear from
    ``omega`` to ``omega_end``, from the steady state at the start. Each step is exact for the
    forcing linear over it and w at its midpoint (:func:`step_maps`; exact for a constant w).

    Parameters
    ----------
    omega : float
        Natural frequency at the start (rad/s), > 0.
    zeta : float
        Damping ratio, 0 <= zeta < 1.
    force : float
        Forcing per unit modal mass f (units of q times s^-2); :func:`sweep_passage`: != 0.
    Omega_start, Omega_end : float
        Forcing pulsation at the start and at the end (rad/s), > 0.
    duration : float
        Sweep time (s), > 0.
    omega_end : float, optional
        Natural frequency at the end (rad/s), > 0; default ``omega`` (a constant mode).
    phase : float
        phi(0) (rad).
    steps_per_cycle : int
        Samples per period of the fastest of w and Omega (8..10000): the deterministic
        accuracy limit; the forcing's interpolation error is about (2 pi / steps)^2 / 12.
    max_steps : int
        Cap on the samples (:class:`flexbooster.floquet.StepLimitError` beyond).

    Returns
    -------
    t, q, a : numpy.ndarray
        Sample times (s), displacements q and accelerations q''.
    """
    omega, omega_end, zeta, force, Om0, Om1, duration, steps = _sweep_args(
        omega, omega_end, zeta, force, Omega_start, Omega_end, duration, steps_per_cycle,
        max_steps)
    phase = finite("phase", phase)
    h = duration / steps
    t = np.linspace(0.0, duration, steps + 1)
    alpha = (Om1 - Om0) / duration
    u = force * np.cos(phase + Om0 * t + 0.5 * alpha * t * t)  # f cos(phi(t))
    w_of = (omega_end - omega) / duration
    H = force / (omega * omega - Om0 * Om0 + 2j * zeta * omega * Om0)  # steady at the start
    x = np.empty((steps + 1, 2))
    x[0] = np.real(H * np.exp(1j * phase)), np.real(1j * Om0 * H * np.exp(1j * phase))
    constant = step_maps([omega], zeta, h) if omega_end == omega else None
    for lo in range(0, steps, _SCAN_BLOCK):  # blocks bound the work arrays
        hi = min(lo + _SCAN_BLOCK, steps)
        if constant is not None:
            Phi, Ga, Gb = (np.broadcast_to(m, (hi - lo,) + m.shape[1:]) for m in constant)
        else:
            Phi, Ga, Gb = step_maps(omega + w_of * (t[lo:hi] + 0.5 * h), zeta, h)  # midpoint
        g = Ga * u[lo:hi, None] + Gb * u[lo + 1:hi + 1, None]
        x[lo + 1:hi + 1] = _affine_scan(Phi, g, x[lo])
    w = omega + w_of * t
    acc = u - 2.0 * zeta * w * x[:, 1] - w * w * x[:, 0]  # q'' from the equation of motion
    return t, x[:, 0], acc


def _peak(t: np.ndarray, y: np.ndarray) -> tuple[float, float]:
    """max |y| and where, refined by the parabola through the largest sample and its two
    neighbours (vertex offset within half a step)."""
    a = np.abs(y)
    i = int(np.clip(np.argmax(a), 1, a.size - 2))
    y0, y1, y2 = a[i - 1], a[i], a[i + 1]
    den = y0 - 2.0 * y1 + y2
    s = float(np.clip(0.5 * (y0 - y2) / den, -0.5, 0.5)) if den < 0.0 else 0.0
    return float(y1 - 0.25 * (y0 - y2) * s), float(t[i] + s * (t[1] - t[0]))


def sweep_passage(*, omega: float, zeta: float, force: float, Omega_start: float,
                  Omega_end: float, duration: float, omega_end: float | None = None,
                  phase: float = 0.0, steps_per_cycle: int = 64,
                  max_steps: int = MAX_SWEEP_STEPS) -> ResonancePassage:
    """The largest |q| and |q''| of :func:`sweep_response`, each refined by a parabola through
    the largest sample and its neighbours, against the steady peaks.

    Parameters
    ----------
    omega, zeta, force, Omega_start, Omega_end, duration, omega_end
        As :func:`sweep_response`; here 0 < zeta < 1/sqrt(2).
    phase, steps_per_cycle, max_steps
        As :func:`sweep_response`.
    """
    t, q, acc = sweep_response(omega=omega, zeta=zeta, force=force, Omega_start=Omega_start,
                               Omega_end=Omega_end, duration=duration, omega_end=omega_end,
                               phase=phase, steps_per_cycle=steps_per_cycle,
                               max_steps=max_steps)
    f = abs(finite("force", force))
    peak, t_peak = _peak(t, q)
    peak_acc, _ = _peak(t, acc)
    w_end = omega if omega_end is None else omega_end
    w_peak = omega + (w_end - omega) * t_peak / duration
    stat = steady_peak(w_peak, zeta, f)
    Om_peak = float(Omega_start + (Omega_end - Omega_start) * t_peak / duration)
    return ResonancePassage(peak=peak, t_peak=t_peak, Omega_at_peak=Om_peak,
                            steady_peak=float(stat), peak_acceleration=peak_acc,
                            steady_peak_acceleration=float(stat * w_peak * w_peak),
                            steps=int(t.size - 1))


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


def crossing_peak_ratio(*, zeta: float, omega: float, omega_rate: float, Omega_rate: float,
                        steps_per_cycle: int = 64, max_steps: int = MAX_SWEEP_STEPS) -> float:
    """Peak |q''| over its steady peak f / (2 zeta sqrt(1 - zeta^2)) where a mode drifting at
    ``omega_rate`` meets a forcing drifting at ``Omega_rate`` (both linear in time, equal
    to ``omega`` at the crossing): the drifting equation of :func:`sweep_response` through
    a window where Omega / omega runs over 1 -+ SWEEP_WINDOW (zeta + sqrt|eta|),
    eta = (Omega_rate - omega_rate) / omega^2, both frequencies kept >= omega / 2.

    Parameters
    ----------
    zeta : float
        Damping ratio, 0 < zeta < 1/sqrt(2).
    omega : float
        The mode's frequency at the crossing (rad/s), > 0.
    omega_rate, Omega_rate : float
        d omega / dt and d Omega / dt (rad/s^2), different (a crossing, not a dwell).
    steps_per_cycle, max_steps : int
        As :func:`sweep_response`.
    """
    zeta = positive("zeta", zeta)
    w = positive("omega", omega)
    wr = finite("omega_rate", omega_rate)
    Wr = finite("Omega_rate", Omega_rate)
    eta = (Wr - wr) / (w * w)  # d(Omega / omega)/dt / omega at Omega = omega
    if eta == 0.0:
        raise ValueError("omega_rate, Omega_rate: equal, the forcing dwells at the resonance")
    span = SWEEP_WINDOW * (zeta + math.sqrt(abs(eta))) / (abs(eta) * w)  # time to +-window
    before = after = span
    for rate in (wr, Wr):  # keep both frequencies >= omega / 2 over the window
        if rate > 0.0:
            before = min(before, 0.5 * w / rate)
        elif rate < 0.0:
            after = min(after, 0.5 * w / -rate)
    duration = before + after
    result = sweep_passage(omega=w - wr * before, omega_end=w + wr * after, zeta=zeta,
                           force=1.0, Omega_start=w - Wr * before, Omega_end=w + Wr * after,
                           duration=duration, steps_per_cycle=steps_per_cycle,
                           max_steps=max_steps)
    return result.acceleration_ratio
