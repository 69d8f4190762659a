"""Rigid-body pitch of the booster under the gimbaled pulsating thrust (memo section 4.2).

psi'' + (2 pi R1 d2 K T(t) / I_cm) psi = 0 (4.2-1, lever arm d2, erratum E2) is, with
tau_1 = Omega t / 2, Mathieu's equation (4.2-3) with a = 4 omega_psi^2 / Omega^2,
q = gamma a / 2 (4.2-4). beta and the tongues from :mod:`flexbooster.floquet.mathieu`;
:func:`memo_exponent` is the memo's small-q formula (4.2-9). Theory: docs/theory/beam-pitch.md.

References: Tech Memo 104, eqs. (2.2-2c), (4.2-1)..(4.2-9); Abramowitz & Stegun, ch. 20;
V. V. Bolotin, *The Dynamic Stability of Elastic Systems*, 1964, sec. 6.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..bands import Band, BandMode, SearchGap, gaps_text
from ..checks import count, nonnegative, positive
from ..floquet import mathieu

__all__ = ["pitch_frequency", "mathieu_parameters", "memo_exponent", "psi_three_term",
           "psi_numerical", "three_term_error", "PITCH_MAX_TONGUE", "PITCH_MODE",
           "pitch_band_edges", "pitch_tongue_omega_bound", "pitch_bands", "PitchResult",
           "pitch_analysis"]


def pitch_frequency(F0: float, d2: float, K: float, I_cm: float) -> float:
    """Rigid-body pitch frequency omega_psi = sqrt(F0 d2 K / I_cm) (rad/s) under the steady thrust
    (4.2-1 linearised, E2).

    Parameters
    ----------
    F0 : float
        Total steady thrust 2 pi R1 T0 (N), >= 0.
    d2 : float
        Lever arm, CM to the aft edge (m), > 0.
    K : float
        Gimbal gain, >= 0.
    I_cm : float
        Pitch moment of inertia about the CM (kg m^2), > 0.
    """
    F0, K = nonnegative("F0", F0), nonnegative("K", K)
    d2, I_cm = positive("d2", d2), positive("I_cm", I_cm)
    with np.errstate(over="ignore"):
        result = float(np.sqrt(np.float64(F0) * d2 * K / I_cm))  # eq. (4.2-1), sin(K psi) ~ K psi
    if not np.isfinite(result):
        raise ValueError(f"F0 = {F0!r}, K = {K!r}: F0 d2 K / I_cm overflows double precision")
    return result


def mathieu_parameters(
    Omega: np.ndarray, omega_psi: float, gamma: float
) -> tuple[np.ndarray, np.ndarray]:
    """Mathieu parameters a = 4 omega_psi^2 / Omega^2 and q = gamma a / 2 (eq. 4.2-4, E2).

    Parameters
    ----------
    Omega : array_like
        Thrust frequencies (rad/s), > 0; a, q are shaped like it.
    omega_psi, gamma : float
        Pitch frequency (rad/s) and pulsation amplitude, >= 0.
    """
    Omega = np.asarray(Omega, dtype=float)
    if Omega.size == 0 or not np.all(np.isfinite(Omega)) or np.any(Omega <= 0):
        raise ValueError(f"Omega = {Omega!r}: every value must be finite and > 0")
    if not (np.isfinite(omega_psi) and omega_psi >= 0):
        raise ValueError(f"omega_psi = {omega_psi!r}: must be finite and >= 0")
    if not (np.isfinite(gamma) and gamma >= 0):
        raise ValueError(f"gamma = {gamma!r}: must be finite and >= 0")
    with np.errstate(over="ignore", divide="ignore", invalid="ignore"):
        a = 4.0 * omega_psi**2 / Omega**2  # eq. (4.2-4): 8 pi R1 d2 K T0 / (I_cm Omega^2)
        q = gamma * a / 2.0  # eq. (4.2-4)
    if not (np.all(np.isfinite(a)) and np.all(np.isfinite(q))):
        low = float(np.min(Omega))
        raise ValueError(f"Omega = {low!r} (the smallest): a = 4 omega_psi^2 / Omega^2 or q = "
                         f"gamma a / 2 overflows double precision (omega_psi = {omega_psi!r})")
    return a, q


def memo_exponent(a: Any, q: Any, *, printed: bool = False) -> np.ndarray:
    """beta on the band r = floor(sqrt a) from the memo's small-q formula (4.2-9) with erratum E4:
    cos(pi beta) = cos(pi sqrt a) + pi q^2 / (4 sqrt(a) (a - 1)) sin(pi sqrt a) (A&S 20.3.15).

    Parameters
    ----------
    a, q : array_like
        Mathieu parameters, broadcast together; every a > 0, a != 1.
    printed : bool
        The formula as printed, with sin(pi sqrt(a) / 2) (an O(q^2) error).
    """
    a, q = np.broadcast_arrays(np.asarray(a, dtype=float), np.asarray(q, dtype=float))
    if not (np.all(np.isfinite(a)) and np.all(np.isfinite(q))):
        raise ValueError("a, q: every value must be finite")
    if np.any(a <= 0.0):
        raise ValueError(f"a = {a!r}: eq. (4.2-9) needs every a > 0")
    if np.any(a == 1.0):
        raise ValueError("a = 1: eq. (4.2-9) is singular at a = 1 (factor 1/(a - 1))")
    sa = np.sqrt(a)
    s_term = np.sin(np.pi * sa / 2.0) if printed else np.sin(np.pi * sa)  # erratum E4
    # eq. (4.2-9): cos(beta pi) = cos(pi a^1/2) + pi q^2 / (4 a^1/2 (a - 1)) sin(...)
    corr = np.pi * q**2 / (4.0 * sa * (a - 1.0)) * s_term
    # 1 -+ cos(pi beta) with 1 -+ cos(pi sqrt a) written as 2 sin^2, 2 cos^2 (no cancellation)
    one_minus = 2.0 * np.sin(0.5 * np.pi * sa) ** 2 - corr
    one_plus = 2.0 * np.cos(0.5 * np.pi * sa) ** 2 + corr
    return mathieu.beta_from_discriminants(one_minus, one_plus, 2.0 * np.floor(sa) + 1.0)


# --------------------------------------------------------------------------------------------
# psi(tau): the memo's three-term solution and direct integration
# --------------------------------------------------------------------------------------------


def _scalar_aq(a: Any, q: Any) -> tuple[float, float]:
    a, q = float(a), float(q)
    if not np.isfinite(a):
        raise ValueError(f"a = {a!r}: must be finite")
    if not np.isfinite(q):
        raise ValueError(f"q = {q!r}: must be finite")
    return a, q


def psi_three_term(
    tau1: Any, a: float, q: float, psi0: float = 1.0, beta: float | None = None
) -> np.ndarray:
    """The memo's three-term solution psi = sum_(i=1..3) A_i cos(Omega_i tau) (rad) (4.2-6..8).

    Parameters
    ----------
    tau1 : array_like
        Mathieu time tau_1 = Omega t / 2; Omega_i tau = (2 - beta), beta, (2 + beta) times
        tau_1 (4.2-7e..g).
    a, q : float
        Mathieu parameters in a stable band.
    psi0 : float
        psi(0) (rad); psi'(0) = 0 (4.2-8a).
    beta : float, optional
        The real exponent to use (default the exact one).
    """
    a, q = _scalar_aq(a, q)
    if beta is None:
        b = complex(mathieu.characteristic_exponent(a, q, "floquet"))
        if b.imag != 0.0:
            raise ValueError(
                f"a = {a}, q = {q}: unstable (beta = {b}); the three-term form "
                "(4.2-6) needs a real beta"
            )
        beta = b.real
    if not np.isfinite(beta):
        raise ValueError(f"beta = {beta!r}: must be finite and real")
    tau1 = np.asarray(tau1, dtype=float)
    den1 = a - (beta - 2.0) ** 2
    den3 = a - (2.0 + beta) ** 2
    if den1 == 0.0 or den3 == 0.0:
        raise ValueError(f"a = {a}, beta = {beta}: a - (2 -+ beta)^2 = 0 in eq. (4.2-7)")
    A2 = psi0 / (1.0 + q * (1.0 / den3 + 1.0 / den1))  # eq. (4.2-7c)
    A1 = A2 * q / den1  # eq. (4.2-7b)
    A3 = A2 * q / den3  # eq. (4.2-7d)
    return (
        A1 * np.cos((2.0 - beta) * tau1)  # eq. (4.2-6), (4.2-7e)
        + A2 * np.cos(beta * tau1)  # eq. (4.2-7f)
        + A3 * np.cos((2.0 + beta) * tau1)  # eq. (4.2-7g)
    )


def psi_numerical(tau1: Any, a: Any, q: Any, psi0: float = 1.0) -> np.ndarray:
    """psi(tau_1) (rad) of eq. (4.2-3) by solve_ivp DOP853, rtol 1e-12, shape (len(a), len(tau1))
    or (len(tau1),) for scalars.

    Parameters
    ----------
    tau1 : array_like
        Increasing times tau_1 >= 0, 1-D.
    a, q : array_like
        Scalars or equal-length 1-D arrays: one solution per pair.
    psi0 : float
        psi(0) (rad), non-zero; psi'(0) = 0.
    """
    scalar = np.ndim(a) == 0 and np.ndim(q) == 0
    if not (np.all(np.isfinite(np.asarray(a, dtype=float)))
            and np.all(np.isfinite(np.asarray(q, dtype=float)))):
        raise ValueError("a, q: every value must be finite")
    a, q = np.broadcast_arrays(
        np.atleast_1d(np.asarray(a, dtype=float)), np.atleast_1d(np.asarray(q, dtype=float))
    )
    a, q = a.ravel(), q.ravel()
    tau1 = np.atleast_1d(np.asarray(tau1, dtype=float))
    if not np.all(np.isfinite(tau1)):
        raise ValueError("tau1: every time must be finite")
    if tau1.ndim == 1 and tau1.size and tau1[-1] * np.sqrt(np.max(np.abs(a) + 2 * np.abs(q),
                                                                  initial=0.0)) > 1e5:
        raise ValueError(f"tau1 = {tau1[-1]!r}: tau1_max sqrt(|a| + 2|q|) must be <= 1e5 "
                         "(about 16000 oscillations; a longer integration would not end)")
    if tau1.ndim != 1 or np.any(tau1 < 0) or np.any(np.diff(tau1) < 0):
        raise ValueError("tau1: must be a 1-D non-decreasing array of values >= 0")
    if not (np.isfinite(psi0) and psi0 != 0):
        raise ValueError(f"psi0 = {psi0!r}: must be finite and non-zero")
    m = a.size

    def rhs(t: float, y: np.ndarray) -> np.ndarray:
        return np.concatenate([y[m:], -(a - 2.0 * q * np.cos(2.0 * t)) * y[:m]])  # eq. (4.2-3)

    y0 = np.concatenate([np.full(m, float(psi0)), np.zeros(m)])
    t_end = float(tau1[-1])
    if t_end == 0.0:
        out = np.full((m, tau1.size), float(psi0))
    else:
        from scipy import integrate  # only here: its import is a tenth of a run's imports

        sol = integrate.solve_ivp(
            rhs, (0.0, t_end), y0, method="DOP853", t_eval=tau1, rtol=1e-12, atol=1e-14 * abs(psi0)
        )
        out = sol.y[:m]
    return out[0] if scalar else out


def three_term_error(
    a: float, q: Any, tau1_max: float = 20.0 * np.pi, n_times: int = 2001
) -> np.ndarray:
    """max |psi_3 - psi| / |psi0| over [0, tau1_max] per q, with the exact beta: the O(q^2)
    truncation error of (4.2-6).

    Parameters
    ----------
    a : float
        0 < a < 1 (memo range).
    q : array_like
        1-D, each (a, q) stable.
    tau1_max : float
        Length of the comparison in tau_1, > 0.
    n_times : int
        Comparison times.
    """
    q = np.atleast_1d(np.asarray(q, dtype=float))
    if not (np.isfinite(tau1_max) and tau1_max > 0):
        raise ValueError(f"tau1_max = {tau1_max!r}: must be finite and > 0")
    tau = np.linspace(0.0, tau1_max, count("n_times", n_times, 2, 10**6))
    exact = psi_numerical(tau, np.full(q.shape, float(a)), q)
    betas = mathieu.characteristic_exponent(float(a), q, "floquet")
    if np.any(betas.imag != 0.0):
        raise ValueError(f"q = {q!r}: every (a, q) must be stable for the three-term form")
    approx = np.stack(
        [psi_three_term(tau, a, qi, 1.0, float(b.real)) for qi, b in zip(q, betas, strict=True)]
    )
    return np.max(np.abs(approx - exact), axis=1)


# --------------------------------------------------------------------------------------------
# Exact instability bands in Omega (the operating path crossing the transition curves)
# --------------------------------------------------------------------------------------------
#: Largest tongue order r searched; tongues narrower than the round-off of a_r - b_r end the
#: search earlier (their width falls like (gamma / 8)^r).
PITCH_MAX_TONGUE = 60
#: The one mode of the rigid-body pitch bands.
PITCH_MODE = BandMode(label="rigid pitch")


def _check(omega_psi: float, gamma: float, damping_ratio: float) -> float:
    """Validate omega_psi >= 0, 0 <= gamma < 1, 0 <= damping_ratio < 1; returns the ratio."""
    nonnegative("omega_psi", omega_psi)
    for name, value in (("gamma", gamma), ("damping_ratio", damping_ratio)):
        if not nonnegative(name, value) < 1.0:
            raise ValueError(f"{name} = {value!r}: must be < 1")
    return float(damping_ratio)


def pitch_tongue_omega_bound(omega_psi: float, gamma: float, *, tongue: int,
                             damping_ratio: float = 0.0) -> float:
    """Upper bound (rad/s) on the thrust frequencies of Mathieu tongue r, without a solve:
    2 omega_psi sqrt((1 - zeta^2)(1 + g)) / r, g = gamma / (1 - zeta^2), since |a_r - r^2|,
    |b_r - r^2| <= 2|q| (Weyl; Kato 1966, V.4.3).

    Parameters
    ----------
    omega_psi : float
        Pitch frequency (rad/s), >= 0.
    gamma, damping_ratio : float
        Pulsation amplitude and pitch damping ratio zeta, in [0, 1).
    tongue : int
        Order r >= 1.
    """
    _check(omega_psi, gamma, damping_ratio)
    tongue = count("tongue", tongue, 1, None)
    s = 1.0 - damping_ratio * damping_ratio
    return float(2.0 * omega_psi * np.sqrt(s * (1.0 + gamma / s)) / tongue)


def pitch_band_edges(omega_psi: float, gamma: float, *, tongue: int,
                     damping_ratio: float = 0.0) -> tuple[float, float] | None:
    """Edges (omega_lo, omega_hi) (rad/s) of Mathieu tongue r on the operating path, as
    :func:`pitch_bands`, not clipped; None where the band does not exist or is below round-off.

    Parameters
    ----------
    omega_psi : float
        Pitch frequency (rad/s), > 0.
    gamma, damping_ratio : float
        Pulsation amplitude and pitch damping ratio zeta, in [0, 1).
    tongue : int
        Order r, 1..PITCH_MAX_TONGUE.
    """
    _check(positive("omega_psi", omega_psi), gamma, damping_ratio)
    r, zeta = count("tongue", tongue, 1, PITCH_MAX_TONGUE), float(damping_ratio)
    s = 1.0 - zeta * zeta
    w = float(omega_psi)
    if gamma == 0.0:
        return None if zeta > 0.0 else (2.0 * w * np.sqrt(s) / r,) * 2
    g = gamma / s
    edges = mathieu.tongue_edges(r, g)
    if edges is None:
        return None
    if zeta > 0.0:
        band = mathieu.damped_tongue(edges[0], edges[1], g, zeta)
        if band is None:
            return None
        edges = band[:2]
    return (float(2.0 * w * np.sqrt(s / edges[1])), float(2.0 * w * np.sqrt(s / edges[0])))


def pitch_bands(omega_psi: float, gamma: float, *, omega_min: float, omega_max: float,
                damping_ratio: float = 0.0) -> tuple[Band, ...]:
    """Every instability band of the rigid-body pitch in [omega_min, omega_max], sorted by Omega.

    Undamped: where the path a = 4 omega_psi^2 / Omega^2, q = gamma a / 2 crosses a_r(q), b_r(q);
    damped: Im beta = zeta sqrt(a) on the path a' = a (1 - zeta^2). Growth rate (Im beta -
    zeta sqrt(a)) Omega / 2, maximised per band. Not reported: tongues below round-off and
    r > :data:`PITCH_MAX_TONGUE` (:attr:`PitchResult.gaps`). Memo 4.2-3, 4.2-4; Bolotin, sec. 6.

    Parameters
    ----------
    omega_psi : float
        Pitch frequency (rad/s), >= 0.
    gamma : float
        Pulsation amplitude, 0 <= gamma < 1.
    omega_min, omega_max : float
        Omega range (rad/s), 0 < omega_min < omega_max.
    damping_ratio : float
        zeta of psi'' + 2 zeta omega_psi psi' + omega_psi^2 (1 - gamma cos Omega t) psi = 0,
        0 <= zeta < 1.
    """
    return _pitch_search(omega_psi, gamma, omega_min, omega_max, damping_ratio)[0]


def _pitch_search(omega_psi: float, gamma: float, omega_min: float, omega_max: float,
                  damping_ratio: float) -> tuple[tuple[Band, ...], tuple[SearchGap, ...]]:
    """:func:`pitch_bands` and what PITCH_MAX_TONGUE leaves out."""
    _check(omega_psi, gamma, damping_ratio)
    if not positive("omega_min", omega_min) < positive("omega_max", omega_max):
        raise ValueError(f"omega_min = {omega_min!r}: must be < omega_max = {omega_max!r}")
    if omega_psi == 0.0 or gamma == 0.0:
        return (), ()  # q = 0: a = r^2 are isolated points, no band
    zeta = float(damping_ratio)
    s = 1.0 - zeta * zeta
    g = gamma / s  # the path in (q, a') = (q, a (1 - zeta^2)): q = g a' / 2
    w = float(omega_psi)

    def omega(x: float) -> float:
        return 2.0 * w * np.sqrt(s / x)  # a' = x = 4 omega_psi^2 (1 - zeta^2) / Omega^2

    r_first = max(1, int(np.floor(2.0 * w / omega_max * 0.5)))
    bands = []
    for r in range(r_first, PITCH_MAX_TONGUE + 1):
        # a tongue wholly below omega_min by this bound (and every higher one) ends the search
        # before an edge is solved
        if pitch_tongue_omega_bound(w, gamma, tongue=r, damping_ratio=zeta) < omega_min:
            break
        edges = mathieu.tongue_edges(r, g)
        if edges is None:
            break  # this and every higher tongue is below round-off
        x_b, x_a = edges
        if omega(x_b) < omega_min:  # the whole tongue lies below the range, and higher ones
            break
        if omega(x_a) > omega_max:
            continue
        band = mathieu.damped_tongue(x_b, x_a, g, zeta)
        if band is None:
            continue
        x_lo, x_hi, x_m, f_m = band
        lo, hi = omega(x_hi), omega(x_lo)  # larger x is smaller Omega
        if hi < omega_min or lo > omega_max:
            continue  # the damped band (inside the undamped tongue) lies outside the range
        clipped = lo < omega_min or hi > omega_max
        lo, hi = max(lo, omega_min), min(hi, omega_max)
        om_m = omega(x_m)
        if not omega_min <= om_m <= omega_max:  # the peak is outside the clipped band
            om_m = lo if om_m < lo else hi
            x_m = 4.0 * w * w * s / om_m**2
            mu = float(np.imag(mathieu.characteristic_exponent(x_m, 0.5 * g * x_m, "hill")))
            f_m = mu - zeta * np.sqrt(x_m / s)
        # growth of psi: e^((mu - c) tau_1), tau_1 = Omega t / 2, c = zeta sqrt(a)
        growth = max(f_m, 0.0) * om_m / 2.0
        crit = mathieu.tongue_critical_gamma(r, gamma, zeta) if zeta > 0.0 else 0.0
        bands.append(Band(mechanism="pitch", Omega_lo=float(lo), Omega_hi=float(hi),
                          kind="simple", order=r, modes=(PITCH_MODE,),
                          growth_rate_max=float(growth), Omega_at_max=float(om_m),
                          Omega_center=2.0 * w / r,  # tongue r: a = 4 omega_psi^2/Omega^2 = r^2
                          critical_gamma=crit, clipped=bool(clipped)))
    else:  # the order limit, not a stopping rule, ended the scan
        r = PITCH_MAX_TONGUE + 1
        top = pitch_tongue_omega_bound(w, gamma, tongue=r, damping_ratio=zeta)
        if top >= omega_min:
            gap = SearchGap(stage="pitch", limit="PITCH_MAX_TONGUE", order=r,
                            Omega_lo=float(omega_min), Omega_hi=float(min(top, omega_max)),
                            reason=f"the Mathieu tongues r >= {r} (Omega <= {top:.6g} rad/s) "
                                   f"not searched: PITCH_MAX_TONGUE = {PITCH_MAX_TONGUE}")
            return tuple(sorted(bands, key=lambda b: b.Omega_lo)), (gap,)
    return tuple(sorted(bands, key=lambda b: b.Omega_lo)), ()


# --------------------------------------------------------------------------------------------
# Result object for the pipeline
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class PitchResult:
    """Rigid-body pitch stability along the Omega grid (memo section 4.2).

    Attributes
    ----------
    Omega, a, q : numpy.ndarray
        Thrust frequencies (rad/s) and the Mathieu parameters (4.2-4).
    omega_psi, gamma, damping_ratio : float
        Pitch frequency (rad/s), pulsation amplitude, pitch damping ratio.
    beta_real, beta_imag, beta_memo_real, beta_memo_imag : numpy.ndarray
        The exact exponent and eq. (4.2-9) with E4 (0 where a <= 0 or a = 1).
    growth_rate, stable, in_memo_range : numpy.ndarray
        Growth of psi (1/s; 0 where stable), beta real, 0 < a < 1 and 0 < q <= 0.05 (4.2-5).
    verdict : str
        One line, from the bands ("not fully searched: ..." with a gap and no band).
    bands, gaps : tuple
        The exact bands over the grid's range; what PITCH_MAX_TONGUE left out.
    """

    Omega: np.ndarray
    omega_psi: float
    gamma: float
    a: np.ndarray
    q: np.ndarray
    beta_real: np.ndarray
    beta_imag: np.ndarray
    beta_memo_real: np.ndarray
    beta_memo_imag: np.ndarray
    growth_rate: np.ndarray
    stable: np.ndarray
    in_memo_range: np.ndarray
    verdict: str
    bands: tuple = ()
    damping_ratio: float = 0.0
    gaps: tuple = ()

    @property
    def all_stable(self) -> bool:
        """True when psi stays bounded over the whole grid."""
        return bool(np.all(self.stable))

    @property
    def max_growth_rate(self) -> float:
        """Largest growth rate (1/s) of the bands' maxima and the grid points; 0 when stable."""
        grid = float(np.max(self.growth_rate)) if self.growth_rate.size else 0.0
        return max([grid, *(float(b.growth_rate_max) for b in self.bands)])

    def unstable_intervals(self) -> list[tuple[float, float]]:
        """The exact instability bands as (omega_lo, omega_hi) (rad/s), from :attr:`bands`."""
        return [(float(b.Omega_lo), float(b.Omega_hi)) for b in self.bands]

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready mapping: plain lists of floats/bools, no NaN or inf."""

        def fl(x: np.ndarray) -> list[float]:
            return [float(v) for v in np.nan_to_num(np.asarray(x, dtype=float))]

        return {
            "omega_psi": float(self.omega_psi),
            "gamma": float(self.gamma),
            "Omega": fl(self.Omega),
            "a": fl(self.a),
            "q": fl(self.q),
            "beta_real": fl(self.beta_real),
            "beta_imag": fl(self.beta_imag),
            "beta_memo_real": fl(self.beta_memo_real),
            "beta_memo_imag": fl(self.beta_memo_imag),
            "growth_rate": fl(self.growth_rate),
            "stable": [bool(v) for v in self.stable],
            "in_memo_range": [bool(v) for v in self.in_memo_range],
            "all_stable": self.all_stable,
            "max_growth_rate": self.max_growth_rate,
            "unstable_intervals": [list(iv) for iv in self.unstable_intervals()],
            "verdict": self.verdict,
            "bands": [b.to_dict() for b in self.bands],
            "damping_ratio": float(self.damping_ratio),
            "gaps": [g.to_dict() for g in self.gaps],
        }


def pitch_analysis(Omega: Any, omega_psi: float, gamma: float, *,
                   damping_ratio: float = 0.0) -> PitchResult:
    """Rigid-body pitch stability over a grid of thrust frequencies, with its exact bands (memo
    4.2-3..4.2-5, 4.2-9). With damping beta is that of a' = a (1 - zeta^2) and the growth
    (Im beta - zeta sqrt a) Omega / 2.

    Parameters
    ----------
    Omega : array_like
        Thrust frequencies (rad/s), > 0, 1-D, increasing.
    omega_psi : float
        Pitch frequency (rad/s), from :func:`pitch_frequency`.
    gamma : float
        Pulsation amplitude, 0 <= gamma < 1.
    damping_ratio : float
        Pitch damping ratio zeta, 0 <= zeta < 1.
    """
    Omega = np.atleast_1d(np.asarray(Omega, dtype=float))
    if Omega.ndim != 1:
        raise ValueError(f"Omega: must be 1-D, got shape {Omega.shape}")
    zeta = _check(omega_psi, 0.0, damping_ratio)
    a, q = mathieu_parameters(Omega, omega_psi, gamma)
    if zeta == 0.0:
        beta = mathieu.characteristic_exponent(a, q, "floquet")
        stable = beta.imag == 0.0
        growth = np.where(stable, 0.0, beta.imag * Omega / 2.0)  # e^(mu tau_1), tau_1 = Omega t/2
    else:
        beta = mathieu.characteristic_exponent(a * (1.0 - zeta**2), q, "floquet")  # u, psi e^(c t1)
        excess = beta.imag - zeta * np.sqrt(a)  # mu - c, c = 2 zeta omega_psi / Omega
        stable = excess <= 0.0
        growth = np.where(stable, 0.0, excess * Omega / 2.0)
    memo = np.zeros(a.shape, dtype=complex)
    ok = (a > 0) & (a != 1.0)
    if np.any(ok):
        memo[ok] = memo_exponent(a[ok], q[ok])
    in_range = (a > 0) & (a < 1) & (q > 0) & (q <= 0.05)  # eq. (4.2-5)
    lo_om, hi_om = float(Omega.min()), float(Omega.max())
    bands, gaps = ((), ()) if not hi_om > lo_om else _pitch_search(omega_psi, gamma, lo_om,
                                                                   hi_om, zeta)
    if gaps and not bands:
        verdict = f"rigid-body pitch {gaps_text(gaps)}"
    elif not bands:
        verdict = (
            f"rigid-body pitch stable for all Omega in [{lo_om:.6g}, {hi_om:.6g}] rad/s "
            "(no Mathieu instability band in the range)"
        )
    else:
        top = max(bands, key=lambda b: b.growth_rate_max)
        spans = ", ".join(f"[{b.Omega_lo:.6g}, {b.Omega_hi:.6g}]" for b in bands[:4])
        more = f" and {len(bands) - 4} more" if len(bands) > 4 else ""
        verdict = (
            f"rigid-body pitch UNSTABLE in {len(bands)} band(s) {spans}{more} rad/s; max "
            f"growth rate {top.growth_rate_max:.6g} 1/s at Omega = {top.Omega_at_max:.6g} "
            f"rad/s (tongue {top.order})"
        )
    if not np.all(in_range):
        verdict += f"; {int(np.sum(~in_range))} points outside the memo range (4.2-5)"
    return PitchResult(
        Omega=Omega,
        omega_psi=float(omega_psi),
        gamma=float(gamma),
        a=a,
        q=q,
        beta_real=beta.real.copy(),
        beta_imag=beta.imag.copy(),
        beta_memo_real=memo.real.copy(),
        beta_memo_imag=memo.imag.copy(),
        growth_rate=growth,
        stable=stable,
        in_memo_range=in_range,
        verdict=verdict,
        bands=bands,
        damping_ratio=zeta,
        gaps=gaps,
    )
