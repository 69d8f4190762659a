"""Cost and feasibility of a case before its analysis: bounded run time, physical validity.

:func:`estimate_cost` predicts the run time of :func:`flexbooster.analysis.analyze` from the
derived model alone, one term per expensive kernel with the case fields that drive it;
:func:`check_case_cost` refuses a case over its budget (``max_seconds``); :func:`check_physical`
refuses a load at or above what the structure carries and :func:`physical_warnings` names
the others. Constants calibrated on the memo case (docs/theory/robustness.md), good to a
factor of about 2.

References: Tech Memo 104, eqs. (4.1-10)..(4.1-12), (4.2-3), (4.2-4), sec. 7.3;
S. P. Timoshenko, J. M. Gere, *Theory of Elastic Stability*, 1961, eq. (11-17);
V. L. Beal, AIAA J. 3 (1965) 486-494.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .bands import CRITICAL_DAMPING_COUNT
from .checks import count, nonnegative, positive
from .errors import AnalysisWarning, CaseError
from .floquet import MATHIEU_SCALE_MAX, hill_order, search_work
from .memo.beam_action import (
    BAND_MAX_CANDIDATES,
    BAND_MAX_ORDER,
    BAND_OMEGA_BAR_MIN,
    BAND_RTOL,
    MONODROMY_MAX_STEPS,
    TONGUE_FLOOR_OMEGA_BAR,
    TONGUE_GAMMA_RTOL,
    TONGUE_MAX_HARMONICS,
    TONGUE_MAX_ORDER,
    beam_system,
    loaded_frequencies,
    modal_damping,
    monodromy_steps,
    pitch_guide,
    pitch_mode,
    tongue_hill_harmonics,
)
from .memo.charts import PITCH_BAND_CHART_LEVELS
from .memo.model import BoosterModel
from .memo.pitch import PITCH_MAX_TONGUE
from .memo.stability import SCAN_POINTS

__all__ = [
    "check_pitch_range",
    "CostEstimate",
    "flight_time_seconds",
    "pass_over_seconds",
    "PASS_OVER_PART",
    "forced_seconds",
    "forced_run_seconds",
    "FORCED_COUNT_MAX_DOFS",
    "with_flight",
    "estimate_cost",
    "check_case_cost",
    "check_physical",
    "physical_warnings",
    "capped_steps_warning",
    "estimate_vehicle_cost",
    "estimate_pitch_cost",
    "combined",
    "region_modes",
    "search_seconds",
    "bending_search_steps",
    "damped_band_steps",
    "damped_search_cost",
    "search_step_seconds",
    "BENDING_SEARCH_PART",
    "SHELL_SEARCH_PART",
    "CRITICAL_DAMPING_PART",
    "FLIGHT_SAMPLES",
    "shell_search_seconds",
    "undamped_search_seconds",
    "UNDAMPED_SEARCH_PART",
    "UNDAMPED_SAMPLES",
    "TONGUE_PART",
    "tongue_search_seconds",
]

#: Name of the part of :func:`estimate_cost` for the rigid-pitch tongue search below
#: omega_1 / 4 (:func:`tongue_search_seconds`).
TONGUE_PART = "beam-action pitch tongues"


# Calibration (s), measured on the memo case on one core (docs/theory/robustness.md).
_C_MONODROMY = 9e-5  # per grid point and Lawson step, n <= 24 modes (numpy overhead bound)
_C_HILL = 2e-9  # per (2 m)^3 of one Hill eigenproblem, m = n (2 S + 1)
_C_BANDS = 5.4e-3  # band search, per resonance candidate and order j (default: 204, 1.1 s)
_C_CHART = 2.5  # beam-action chart of the default, scales like (n / 11)^2.5
# per Magnus step: fixed, per grid point (2e-5 s fixed on a free core; 3.2e-5 s at load 4 on
# the 2-core machine: the estimate takes the shared machine's figure)
_C_PITCH_STEP = (3e-5, 3e-7)
# pitch bands, per tongue examined (memo.pitch: from Omega_max / 2 down to the first tongue
# below the range): c0 + c1 r min(g, 1), g = gamma / (1 - zeta^2) (0.07 s at r ~ 5; 2.3 s for
# r = 43..60 at g = 1, q ~ 3000, on a loaded core: 0.13 s at r ~ 50; narrow tongues, small g,
# cost about c0)
_C_TONGUE = (0.05, 0.0016)
# pitch bands at a large pulsation: tongue r (a ~ r^2) costs ~ r^1.5 Hill rows x evaluations
# while it is wider than round-off, r <= 110 gamma (fuzz cases: 5.2 s at gamma
# = 0.78 for r = 6..60, 0.83 s at 0.4, x 2.5 with pitch damping, 12 s)
_C_TONGUE_R = (4.6e-4, 0.78, 110.0, 2.5)  # per r^1.5 at gamma_ref; r cut / gamma; damped x
_C_TONGUE_LEVEL = 0.04  # pitch chart, per tongue and gamma level
# critical damping of one pitch tongue r (floquet.tongue_critical_damping), c0 + c1 r s: 0.61 s
# at r = 5 to 2.46 s at r = 33, gamma = 0.92 (one core, measured on a fuzz case)
_C_TONGUE_CRITICAL = (0.28, 0.066)
# per (excitation curve x shell mode): the memo case at M = N = 10 and 14 (660 and 1,260 shell
# modes, 42,000 and 73,000 roots) 0.57 s and 1.09 s on a loaded core, 1.43x and 1.47x of
# 1.5e-6; 2e-6 taken
_C_STABILITY = 2e-6
# the stability table's pitch exponent beta (Hill's continuant, N rows: floquet.hill_order) on
# its scan grid and again, about as much, at the roots' brackets: per row and point, measured
# 1.1e-7 s (2,001 points: 0.7 s at a = 3e5, N = 3306, loaded core; the table 1.65 s)
_C_HILL_ROW = 1.1e-7
_C_SHELL = 1e-4  # per shell mode
_HILL_POINTS = 3  # beam_action_analysis n_hill


@dataclass(frozen=True)
class CostEstimate:
    """Predicted run time of :func:`flexbooster.analysis.analyze` by kernel.

    Attributes
    ----------
    seconds : float
        Total (s).
    parts : dict of str to float
        Seconds by kernel.
    drivers : dict of str to tuple of str
        The case fields that drive each kernel.
    capped_points, capped_omega_max : int, float
        Omega grid points whose beam-action step count is capped
        (:data:`flexbooster.memo.beam_action.MONODROMY_MAX_STEPS`), and the largest (rad/s; 0).
    """

    seconds: float
    parts: dict = field(default_factory=dict)
    drivers: dict = field(default_factory=dict)
    capped_points: int = 0
    capped_omega_max: float = 0.0

    def describe(self, n: int = 3) -> str:
        """The largest ``n`` parts with their fields in one line, e.g. ``"Hill determinant 2.2e+03 s
        (truncation.N, truncation.S); ..."``.

        Parameters
        ----------
        n : int
            Number of parts named.
        """
        top = sorted(self.parts.items(), key=lambda kv: -kv[1])[:n]
        return "; ".join(f"{k} {v:.3g} s ({', '.join(self.drivers[k])})" for k, v in top)

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready mapping."""
        return {"seconds": float(self.seconds),
                "parts": {k: float(v) for k, v in self.parts.items()},
                "drivers": {k: list(v) for k, v in self.drivers.items()},
                "capped_points": int(self.capped_points),
                "capped_omega_max": float(self.capped_omega_max)}


def _resonance_weight(A0: np.ndarray, B: np.ndarray, lo: float, hi: float) -> float:
    """Sum of the orders j of the resonance centres in [lo, hi] (units of omega_1) whose width
    estimate is above the band tolerance (an over-count of the toolkit's candidates).
    """
    mu, V = np.linalg.eig(A0)
    w = np.sqrt(np.abs(mu.real))
    Bt = np.abs(np.linalg.solve(V, B @ V))  # modal coupling, eq. (4.1-11)
    wt = np.maximum(w, 0.5 * lo)
    Z = Bt / np.outer(wt, wt)
    zeta = min(float(np.max(Z)), 1e6)
    zrow = np.max(np.maximum(Z, Z.T), axis=1)
    ii, kk = np.triu_indices(w.size, 1)
    base = np.concatenate([2.0 * w, w[ii] + w[kk], np.abs(w[kk] - w[ii])])
    scale = np.concatenate([zrow**2, zrow[ii] * zrow[kk], zrow[ii] * zrow[kk]])
    ok = base > 1e-12 * max(float(np.max(w)), 1e-300)
    base, scale = base[ok], scale[ok]
    j_lo = np.maximum(1.0, np.ceil(base / hi))
    j_hi = np.minimum(np.floor(base / lo), 1e7)
    if zeta < 1.0:  # est ~ scale zeta^(j - 2) >= 1e-2 rtol: the highest order kept
        top = 2.0 + np.log(np.maximum(1e-2 * BAND_RTOL / np.maximum(scale, 1e-300),
                                      1e-300)) / np.log(max(zeta, 1e-300))
        j_hi = np.minimum(j_hi, np.maximum(top, 1.0))
    n_j = np.maximum(0.0, j_hi - j_lo + 1.0)
    return float(np.sum(n_j * 0.5 * (j_lo + j_hi)))  # sum of j over the kept orders


def _tongues(omega_psi: float, lo: float, hi: float, widen: float) -> int:
    """Pitch tongues r (Omega ~ 2 omega_psi / r) that reach [lo, hi] (widened), capped."""
    if omega_psi <= 0.0:
        return 0
    r_hi = min(PITCH_MAX_TONGUE, math.floor(widen * 2.0 * omega_psi / lo))
    r_lo = max(1, math.ceil(2.0 * omega_psi / (widen * hi)))
    return max(0, r_hi - r_lo + 1)


def _tongues_examined(omega_psi: float, gamma: float, pitch_ratio: float, lo: float,
                      hi: float) -> np.ndarray:
    """The tongue orders r the pitch-band search (:mod:`flexbooster.memo.pitch`) examines:
    from r = floor(omega_psi / hi) up to the first tongue wholly below ``lo``, estimated as the
    smaller of Weyl's bound 2 omega_psi sqrt(s (1 + g)) / lo (s = 1 - zeta^2, g = gamma / s)
    and 1.2 x the large-q one, where the lowest edge a = -2q + 2 (2r + 1) sqrt(q) (DLMF
    28.8.1) on the path q = g a / 2 gives a = 2 g (2r + 1)^2 / (1 + g)^2 (measured: tongues
    43..60 examined where it gives 55.5), at most PITCH_MAX_TONGUE."""
    if omega_psi <= 0.0 or gamma <= 0.0:
        return np.zeros(0)
    s = 1.0 - pitch_ratio * pitch_ratio
    g = gamma / s
    x_max = 4.0 * omega_psi**2 * s / lo**2
    weyl = 2.0 * omega_psi * math.sqrt(s * (1.0 + g)) / lo
    large_q = 1.2 * 0.5 * (math.sqrt(x_max * (1.0 + g) ** 2 / (2.0 * g)) - 1.0)
    r_lo = max(1, math.floor(omega_psi / hi))
    r_hi = min(PITCH_MAX_TONGUE, math.floor(min(weyl, large_q)))
    return np.arange(r_lo, r_hi + 1, dtype=float)


def _tongue_orders(omega_psi: float, gamma: float, pitch_ratio: float, lo: float,
                   hi: float) -> float:
    """Order-dependent part of the pitch-band search (s): sum of r^1.5 over the tongues in the
    range wider than round-off (r <= 110 gamma), scaled by gamma^1.5.
    """
    c, g_ref, r_per_gamma, damped = _C_TONGUE_R
    if omega_psi <= 0.0 or gamma <= 0.0:
        return 0.0
    r_lo = max(1, math.ceil(2.0 * omega_psi / hi))
    r_hi = min(PITCH_MAX_TONGUE, math.floor(2.0 * omega_psi / lo),
               math.floor(r_per_gamma * gamma))
    if r_hi < r_lo:
        return 0.0
    orders = np.arange(r_lo, r_hi + 1, dtype=float)
    factor = damped if pitch_ratio > 0.0 else 1.0
    return float(c * (gamma / g_ref) ** 1.5 * factor * np.sum(orders**1.5))


def estimate_pitch_cost(*, omega_psi: float, Omega, gamma: float,
                        pitch_ratio: float = 0.0) -> CostEstimate:
    """The predicted run time of the rigid-body pitch (the Magnus pass over the Omega grid, the
    tongues' bands and the critical damping of the fastest of them), for the memo's model and
    the one-vehicle case alike.

    Parameters
    ----------
    omega_psi : float
        Rigid-body pitch frequency (rad/s), >= 0.
    Omega : array_like
        The Omega grid (rad/s), > 0.
    gamma : float
        Pulsation amplitude.
    pitch_ratio : float
        Damping ratio of the pitch.
    """
    Omega = np.asarray(Omega, dtype=float)
    G = Omega.size
    lo, hi = float(Omega.min()), float(Omega.max())
    parts: dict[str, float] = {}
    drivers: dict[str, tuple[str, ...]] = {}
    a_max = 4.0 * omega_psi**2 / lo**2  # eq. (4.2-4)
    scale = math.sqrt(a_max * (1.0 + gamma))
    steps = 24.0 + 16.0 * min(scale, MATHIEU_SCALE_MAX)
    c0, c1 = _C_PITCH_STEP
    parts["pitch (Magnus)"] = 3.0 * steps * (c0 + c1 * G)
    drivers["pitch (Magnus)"] = ("thrust.omega_min", "thrust.F0", "thrust.K", "thrust.n_omega")
    t_bands = _tongues(omega_psi, lo, hi, 1.0)
    examined = _tongues_examined(omega_psi, gamma, pitch_ratio, lo, hi)
    g = min(1.0, gamma / (1.0 - pitch_ratio**2))
    parts["pitch bands"] = float(np.sum(_C_TONGUE[0] + _C_TONGUE[1] * g * examined)) + (
        _tongue_orders(omega_psi, gamma, pitch_ratio, lo, hi))
    drivers["pitch bands"] = ("thrust.omega_min", "thrust.F0", "thrust.K")
    if 0.0 < gamma < 1.0 and t_bands > 0:  # the fastest (lowest) tongues' critical
        # damping, CRITICAL_DAMPING_COUNT at most, each costing more with its order r
        r_lo = max(1, math.ceil(2.0 * omega_psi / hi))
        orders = np.arange(r_lo, r_lo + min(CRITICAL_DAMPING_COUNT, t_bands))
        c0, c1 = _C_TONGUE_CRITICAL
        parts["pitch critical damping"] = float(np.sum(c0 + c1 * orders))
        drivers["pitch critical damping"] = ("thrust.gamma", "thrust.omega_min")
    return CostEstimate(seconds=float(sum(parts.values())), parts=parts, drivers=drivers)


def estimate_cost(model: BoosterModel, *, beam_action: bool = True, stability: bool = True,
                  figures: bool = True) -> CostEstimate:
    """The predicted run time of the analysis of a derived model, by kernel: pitch Magnus pass,
    pitch bands and chart, shell frequencies, beam-action monodromy, Hill determinant, band
    search and chart, the pitch tongues below omega_1 / 4 (:data:`TONGUE_PART`), stability table.

    Parameters
    ----------
    model : BoosterModel
        The derived model (:func:`flexbooster.model.model_from_case`).
    beam_action, stability, figures : bool
        The stages that will run (as the arguments of :func:`flexbooster.analysis.analyze`).
    """
    n = model.truncation
    Omega = np.asarray(model.Omega, dtype=float)
    G = Omega.size
    lo, hi = float(Omega.min()), float(Omega.max())
    parts: dict[str, float] = {}
    drivers: dict[str, tuple[str, ...]] = {}
    pitch = estimate_pitch_cost(omega_psi=model.omega_psi, Omega=Omega, gamma=model.gamma,
                                pitch_ratio=model.pitch_damping_ratio)
    parts.update(pitch.parts)
    drivers.update(pitch.drivers)
    modes = (n.M1 + 1) * (n.N1 + 1) + (n.M2 + 1) * (n.N2 + 1)
    parts["shell frequencies"] = _C_SHELL * modes
    drivers["shell frequencies"] = ("truncation.M1", "truncation.N1", "truncation.M2",
                                    "truncation.N2")
    capped, capped_omega = 0, 0.0
    if beam_action:
        nn = n.N + 1
        system = beam_system(model)
        raw = monodromy_steps(system, Omega, np.full(G, model.gamma))
        over = raw > MONODROMY_MAX_STEPS
        capped = int(np.sum(over))
        capped_omega = float(np.max(Omega[over])) if capped else 0.0
        work = float(np.sum(np.minimum(raw, MONODROMY_MAX_STEPS)))
        parts["beam-action monodromy"] = _C_MONODROMY * work * max(1.0, (nn / 24.0) ** 3)
        drivers["beam-action monodromy"] = ("thrust.omega_min", "thrust.n_omega",
                                            "truncation.N")
        m2 = 2.0 * nn * (2 * n.S + 1)
        parts["Hill determinant"] = _C_HILL * m2**3 * min(_HILL_POINTS, G)
        drivers["Hill determinant"] = ("truncation.N", "truncation.S")
        if hi > BAND_OMEGA_BAR_MIN * model.omega_1:
            lo_b = max(lo, BAND_OMEGA_BAR_MIN * model.omega_1) / model.omega_1
            weight = _resonance_weight(system.A0, model.gamma * system.B, lo_b,
                                       hi / model.omega_1)
            damped = model.beam_damping_ratio > 0.0 or model.pitch_damping_ratio > 0.0
            # damped: the undamped seeds, the damped regions and their critical gamma, all
            # counted in monodromy steps (the undamped search alone: per candidate and order)
            parts["beam-action bands"] = (damped_band_steps(model)[1] if damped
                                          else _C_BANDS * weight)
            drivers["beam-action bands"] = ("truncation.N", "thrust.omega_min",
                                            "damping.modal_ratio", "thrust.F0")
            if model.gamma > 0.0:  # the critical damping ratios of the bands that count:
                # all CRITICAL_DAMPING_COUNT undamped, one where the damping closes most
                counted = 1 if model.beam_damping_ratio > 0.0 else CRITICAL_DAMPING_COUNT
                parts["beam-action critical damping"] = counted * _C_CRITICAL_BAND * max(
                    1.0, (nn / _CRITICAL_BAND_N) ** 3)
                drivers["beam-action critical damping"] = ("damping.modal_ratio",
                                                           "truncation.N")
        low_hi = min(hi, BAND_OMEGA_BAR_MIN * model.omega_1)
        if low_hi > lo:  # below omega_1 / 4: the rigid-pitch tongues (harmonic balance)
            parts[TONGUE_PART] = tongue_search_seconds(
                system, model.gamma, omega_min=lo, omega_max=low_hi,
                beam_ratio=model.beam_damping_ratio, pitch_ratio=model.pitch_damping_ratio)
            drivers[TONGUE_PART] = ("thrust.omega_min", "thrust.gamma", "truncation.N",
                                    "damping.pitch_ratio", "damping.modal_ratio")
    if beam_action and stability:
        curves = 13.0 * n.R * (2 * n.S + 1)
        a_max = 4.0 * model.omega_psi**2 / lo**2  # eq. (4.2-4)
        rows = hill_order(a_max, 0.5 * model.gamma * a_max)
        parts["stability table"] = (_C_STABILITY * curves * modes
                                    + 2.0 * _C_HILL_ROW * rows * SCAN_POINTS)
        drivers["stability table"] = ("truncation.R", "truncation.S", "truncation.M1",
                                      "truncation.N1", "truncation.M2", "truncation.N2")
    if figures:
        parts["pitch chart"] = (_C_TONGUE_LEVEL * PITCH_BAND_CHART_LEVELS
                                * _tongues(model.omega_psi, lo, hi, 1.5))
        drivers["pitch chart"] = ("thrust.omega_min", "thrust.F0", "thrust.K")
        if beam_action and hi > BAND_OMEGA_BAR_MIN * model.omega_1:
            parts["beam-action chart"] = _C_CHART * ((n.N + 1) / 11.0) ** 2.5
            drivers["beam-action chart"] = ("truncation.N",)
    return CostEstimate(seconds=float(sum(parts.values())), parts=parts, drivers=drivers,
                        capped_points=capped, capped_omega_max=capped_omega)


# The rigid-pitch tongue search (flexbooster.memo.beam_action.pitch_tongue_bands; one core),
# measured on 310 fuzz-like boosters (N = 1..4, 2..5 modes) and the memo booster at N = 6
# and 10 (benchmarks/bench_cost.py): each harmonic-balance eigenproblem (QZ, order m = n h,
# 2 n h with damping, h = 2 K or 2 K + 1 harmonic blocks) costs _TONGUE_QZ m^3 + _TONGUE_CALL;
# the growth maximum of tongue r (~31 Hill eigenproblems of order 2 n (2 S_r + 1) and one of
# 2 n (2 S_r + 9)) _TONGUE_GROWTH[0] + _TONGUE_GROWTH[1] x their m^3; the pitch-only guide
# (1 x 1 harmonic balance) _TONGUE_GUIDE per use; with damping the critical gamma is a
# bisection of _TONGUE_BISECTIONS steps, one eigenproblem each at the tongue's converged K.
_TONGUE_QZ = 1.2e-8
_TONGUE_CALL = 4e-4
_TONGUE_GROWTH = (0.1, 3e-9)
_TONGUE_GUIDE = 3.5e-3
_TONGUE_BISECTIONS = int(math.ceil(math.log2(1.0 / TONGUE_GAMMA_RTOL)))
# Without pitch damping the search is modelled to stop after tongue r = 11 at the latest (the
# highest found over the calibration cases: 10), or once the tongue's relative width
# (Mathieu, small q, A&S 20.2.25) is below 1e-6.
_TONGUE_R_MODEL = 11
_TONGUE_WIDTH_MODEL = 1e-6


def _qz_seconds(n: int, K: int, period: str, damped: bool) -> float:
    """Modelled time of one harmonic-balance eigenproblem (n modes, K harmonics)."""
    m = n * (2 * K if period == "2T" else 2 * K + 1) * (2 if damped else 1)
    return _TONGUE_QZ * float(m) ** 3 + _TONGUE_CALL


def _growth_seconds(n: int, S: int) -> float:
    """Modelled time of the growth maximum of a tongue (n modes, S Hill harmonics)."""
    c0, c1 = _TONGUE_GROWTH
    m = 2 * n * (2 * S + 1)
    return c0 + c1 * (31.0 * m**3 + (2 * n * (2 * S + 9)) ** 3)


def _model_harmonics(r: int, centre: float, damped: bool) -> int:
    """Harmonics K at which the edges of tongue r are modelled to converge: 4 for r <= 2, 8 for
    r <= 6, ..., one step more below TONGUE_FLOOR_OMEGA_BAR with damping, up to
    TONGUE_MAX_HARMONICS - 4.
    """
    K = 4 * math.ceil((r + 2) / 4)
    if damped and centre < TONGUE_FLOOR_OMEGA_BAR:
        K += 4
    return min(K, TONGUE_MAX_HARMONICS - 4)


def _mathieu_log_width(theta: float, r: int) -> float:
    """log of the relative width (in a) of Mathieu tongue r at q = theta r^2, small-q leading
    term 2 q^r / (4^(r-1) ((r-1)!)^2) / r^2 (A&S 20.2.25).
    """
    q = theta * r * r
    if not q > 0.0:
        return -math.inf
    return (math.log(2.0) + r * math.log(q) - (r - 1) * math.log(4.0)
            - 2.0 * math.lgamma(r) - 2.0 * math.log(r))


def tongue_search_seconds(system: Any, gamma: float, *, omega_min: float, omega_max: float,
                          beam_ratio: float = 0.0, pitch_ratio: float = 0.0) -> float:
    """Estimated time (s, one core) of :func:`flexbooster.memo.beam_action.pitch_tongue_bands`,
    without solving an eigenproblem of the search.

    The tongues r with their tip in the range are counted while they exist: damped, while the
    undamped width of the pitch-only Mathieu tongue exceeds 4 zeta_p; undamped, while it
    exceeds 1e-6 and r <= 11; for r >= 3 while r theta^2 <= 2 (the tongue's drift stays in the
    window). Each costs its edges, its growth maximum and, damped, the bisection of its critical
    gamma (A&S 20.2.25; Bolotin 1964, sec. 6; measured in benchmarks/bench_cost.py).

    Parameters
    ----------
    system : BeamActionSystem
        The normalised beam-action system.
    gamma : float
        Pulsation amplitude, 0 <= gamma < 1.
    omega_min, omega_max : float
        The low Omega range (rad/s), 0 < omega_min < omega_max.
    beam_ratio, pitch_ratio : float
        Modal damping ratios.
    """
    gamma, lo, hi = (nonnegative("gamma", gamma), positive("omega_min", omega_min),
                     positive("omega_max", omega_max))
    if gamma >= 1.0 or not lo < hi:
        raise ValueError(f"gamma = {gamma!r}, omega_min = {lo!r}, omega_max = {hi!r}: must "
                         "satisfy gamma < 1 and omega_min < omega_max")
    C = modal_damping(system, beam_ratio=beam_ratio, pitch_ratio=pitch_ratio)
    w1 = float(system.omega_1)
    wp = complex(loaded_frequencies(system)[pitch_mode(system)])
    if gamma == 0.0 or wp.imag != 0.0 or not wp.real > 0.0:
        return 0.0
    wp = wp.real
    n = system.A0.shape[0]
    mu_p, b_p, c_p = pitch_guide(system, C)
    theta = gamma * abs(b_p) / (2.0 * mu_p)
    zeta = abs(c_p) / (2.0 * math.sqrt(mu_p)) if pitch_ratio > 0.0 else 0.0
    damped = C is not None
    seconds = 0.0
    r_min = max(1, int(np.ceil(2.0 * wp * w1 / hi - 1e-12)))
    for r in range(r_min, TONGUE_MAX_ORDER + 1):
        centre = 2.0 * wp / r
        if centre * w1 < lo:
            break
        period = "2T" if r % 2 else "T"
        K = _model_harmonics(r, centre, damped)
        log_w = _mathieu_log_width(theta, r)
        exists = (log_w > math.log(4.0 * zeta) if zeta > 0.0 else
                  log_w > math.log(_TONGUE_WIDTH_MODEL) and r <= _TONGUE_R_MODEL)
        # a tongue r >= 3 drifts below its tip by ~theta^2 / 4 (Mathieu: a_r ~ r^2 + q^2 /
        # (2 (r^2 - 1))): out of the search window (0.5 / (r + 1) below the tip) past 2/theta^2
        exists = exists and (r <= 2 or r * theta**2 <= 2.0)
        if not exists:  # its edges (K = 4, 8) end the search, or (r <= 2) go on
            seconds += _TONGUE_GUIDE + sum(_qz_seconds(n, k, period, damped) for k in (4, 8))
            if r > 2:
                break
            continue
        Ks = (range(4, TONGUE_MAX_HARMONICS + 1, 4)
              if not damped and centre < TONGUE_FLOOR_OMEGA_BAR else range(4, K + 5, 4))
        seconds += _TONGUE_GUIDE + sum(_qz_seconds(n, k, period, damped) for k in Ks)
        seconds += _growth_seconds(n, tongue_hill_harmonics(r))
        if damped:
            seconds += _TONGUE_BISECTIONS * (_TONGUE_GUIDE + _qz_seconds(n, K, period, True))
    return float(seconds)


# Vehicle stages: calibration on the memo case's vehicle (the memo's two
# cylinders, 263 FE DOFs), one core.  The modes survey (``[vehicle]`` only): k_max = 20 in
# 0.38 s, 40 in 0.47 s (-> 0.3 s + 5e-3 s per harmonic); building a harmonic of the regions:
# 0.02 s; its search where the certificate does not cover it: search_seconds.
_C_SURVEY = (0.3, 5e-3)
_C_HARMONIC_BUILD = 0.02
_REF_DOFS = 263.0
# The FE work per harmonic against x = DOFs / 263 (the matrices are assembled dense: n^2 work
# and memory, and dense eigensolves n^3 where the sparse Lanczos does not apply), floored at a
# third (fixed overheads): the survey 1.5 x^2 + 0.25 x^3, a build 0.5 x + 0.2 x^3, in units
# of the constants above.  Fitted on tubes of 89-3,846 DOFs (6 modes, no tanks; idle core, CPU
# time): a survey harmonic 0.74, 1.0, 1.5, 4.8, 14, 102, 346, 757 units at x = 0.34, 0.86,
# 1.37, 2.08, 3.25, 7.0, 11.1, 14.6, a build 0.12, 0.38, 0.55, 1.24, 2.3, 41, 189, 481 units.
# The stages of those tubes (scripts/fe_work_law.py --large) take 1/1.7 (3,846 DOFs) to 1/19
# (89 DOFs, the fixed 0.3 s) of the "vehicle modes" part and 1/1.7 to 1/5.3 of the "vehicle
# regions" part; the cube alone priced the 780-DOF default vehicle's builds 14x their time.
_SURVEY_DOF_LAW = (1.5, 0.25)  # x^2, x^3
_BUILD_DOF_LAW = (0.5, 0.2)  # x, x^3
# Those tubes are hinged: no harmonic has rigid-body motions. A free end's k = 0 and 1 have two
# each (shell_of_revolution.rigid_motion_count), and their modes are solved on the complement
# of those motions (a dense projection, a solve for the lowest modes and often a second one
# for the band of the survey): a survey harmonic of free-free tubes of radius 0.2 m (348-3,051
# DOFs, k_max = 1, idle core) took 9, 30, 127, 349 and 727 units at x = 2.10, 3.52, 6.17, 8.89
# and 11.6, priced 1.5 x^2 + 0.55 x^3 (1.43-1.46x).
_SURVEY_DENSE_LAW = (1.5, 0.55)  # x^2, x^3
# The build of such a harmonic for the regions (k = 1, 20 modes on the complement): 3.1, 11.5,
# 56, 149 and 350 units at x = 1.76, 3.18, 5.83, 8.55 and 11.3 (free-free tubes of radius
# 0.2 m, 463-2,962 DOFs; k = 2 of the same tubes 1.7-28 units), priced x + 0.35 x^3
# (1.2-1.5x); the law above priced it 0.83x at 2,962 DOFs.
_BUILD_DENSE_LAW = (1.0, 0.35)  # x, x^3
# Attached masses (benchmarks/bench_vehicle_modes.py's two-stage vehicle, 691 FE DOFs, one
# core): the liquid mesh of a tank once (4 tanks: 0.11 s), its added mass per harmonic
# (0.0133 s per tank and k); a lumped mass's matrix per harmonic k <= 1 (1.7e-3 s).
_C_TANK = (0.03, 0.015)
_C_MASS = 2e-3
# One harmonic's region search, up front (no FE solved): k = 3, gamma = 0.05, undamped, Omega
# 5..2000 rad/s: 4 modes 0.11 s, 8: 0.53 s, 12: 1.43 s, 20: 9.6 s (-> 0.1 + 6e-5 n^4); 20
# modes over 5..500 rad/s: 8.0 s (-> the log-range factor).  Blind to the frequencies: the
# README's [vehicle] example (modes up to 4000 rad/s), k = 2, 8 modes: 6.3 s against 0.35 s.
_SEARCH_FIXED, _SEARCH_PER_N4, _SEARCH_LOG_RANGE = 0.1, 6e-5, float(np.log(400.0))
# Damped: the undamped seeds, the damped search of those holding a region and the critical
# gamma of each (measured 2.4x the README example's k = 2 and 3.8x the free-free default
# vehicle's k = 1 estimate); with the chart's curves: the search and 3 more levels.
_DAMPED_UPFRONT_FACTOR, _BOUNDARY_SEARCH_FACTOR = 3.0, 4.0
# the stability certificate of a damped harmonic (floquet.bounds: a bounded count of dense
# 2n x 2n LAPACK operations): s per (2n)^3, one core (3.4e-9 at n = 200, 3.6e-9 at n = 120,
# CPU time); computed for the map, again by the search, and once more for the chart's curves
_C_CERTIFICATE = 3.5e-9
# The forced response of one harmonic forced (k = 0, and k = 1 with a misalignment), with its
# half-basis convergence run: c0 + c1 (n / 780)^2 for the full model's n DOFs (its dense
# eigenproblem and static correction) plus, per Omega point, c2 + c3 min(n, 200) (the modal
# solves; the basis, unknown up front, is at most the DOFs). Measured on one loaded core:
# 0.49-0.63 s at n = 780 (13 basis modes) and 20-4,000 points, 1.0 s at 20,000; 0.34-0.54 s
# at n = 263 (95 modes), 1.65 s at 20,000 points; 0.20 s at n = 369; 0.22 s at n = 543 with
# two harmonics.
_C_FORCED = (0.4, 0.8, 2e-5, 5e-7)
_FORCED_DOFS, _FORCED_BASIS = 780.0, 200.0
# A basis of many modes (all below 4 Omega_max: unknown up front) costs like the DOFs cubed:
# 3.2 s for both harmonics at n = 416 with 225 and 344 basis modes (a fuzz case; 0.63 s by
# the law above), 0.9 s x (n / 263)^3 per harmonic bounds it; the larger of the two is taken
_C_FORCED_BASIS = 0.9


def search_seconds(n_modes: int, omega_min: float, omega_max: float, *, damped: bool,
                   boundaries: bool = False) -> float:
    """Estimated time (s, one core) of the region search of one harmonic not certified stable:
    (0.1 + 6e-5 n^4) ln(omega_max / omega_min) / ln(400), x 3 damped, x 4 with the chart.

    Parameters
    ----------
    n_modes : int
        Modes n of the harmonic's system, >= 1.
    omega_min, omega_max : float
        Omega range (rad/s), 0 < omega_min < omega_max.
    damped, boundaries : bool
        Damping > 0; the chart's curves traced as well.
    """
    n = count("n_modes", n_modes, 1, 100_000)
    lo, hi = positive("omega_min", omega_min), positive("omega_max", omega_max)
    if lo >= hi:
        raise ValueError(f"omega_min = {omega_min!r}: must be < omega_max = {omega_max!r}")
    t = (_SEARCH_FIXED + _SEARCH_PER_N4 * float(n) ** 4) * max(
        np.log(hi / lo) / _SEARCH_LOG_RANGE, 0.05)
    return float(t * (_DAMPED_UPFRONT_FACTOR if damped else 1.0)
                 * (_BOUNDARY_SEARCH_FACTOR if boundaries else 1.0))


# The critical damping ratio of one beam-action band: 7.6 s for the 8 bands of the memo case
# undamped (one core, measured; 11 modes), n^3 assumed above
_C_CRITICAL_BAND, _CRITICAL_BAND_N = 0.95, 11.0
# The critical damping ratio of one region (an Illinois root in zeta of Brent maxima over
# Omega, some 200 monodromies): 6.5 s for 8 regions of the default case undamped, k <= 4,
# 20 modes per harmonic (one core, measured); n^3 assumed above 20 modes (dense products)
_C_CRITICAL_REGION, _CRITICAL_REGION_N = 0.8, 20.0

#: Name of the part of :func:`estimate_vehicle_cost` for the search of the damped k = 1
#: harmonic (:func:`bending_search_steps`).
BENDING_SEARCH_PART = "vehicle k = 1 search"
#: Name of the part of :func:`estimate_vehicle_cost` for the searches of the harmonics k >= 2
#: that damping does not certify (:func:`shell_search_seconds`).
SHELL_SEARCH_PART = "vehicle k >= 2 searches"
#: Name of the part of :func:`estimate_vehicle_cost` for the regions' critical damping ratios.
CRITICAL_DAMPING_PART = "vehicle critical damping"
# The damped k = 1 search keeps the undamped rigid pitch (gimbal gain K > 0), so the damping
# certifies nothing and the harmonic is searched.  The work of a damped search, counted by a
# step counter (scripts/free_free_damped_cases.py, tests/test_cost.py), in units of the step
# counts at the candidate centres (floquet.search_work): light damping (zeta = 0.01) 7.8 x the
# undamped and 33.5 x the damped steps (the memo's default: seeds, damped regions, critical
# gamma; the README's two-stage liquid vehicle's k = 1, 232 candidates: 33 x in all), so 10 x
# and 40 x; heavy damping (zeta = 0.3, free-free, 2 modes, Omega 0.2-6 rad/s: the marches run
# to the ends of the widened range) 250-500 x in all, so 30 x and 500 x; log-log between, the
# end values outside.  Evaluated points: 68 per candidate (memo), 24 (liquid): 70.
_EVALS_ZETA = (0.01, 0.3)
_EVALS_UNDAMPED, _EVALS_DAMPED, _EVALS_POINTS = (10.0, 30.0), (40.0, 500.0), 70.0
# A candidate between modes without modal damping (the gimbaled rigid pitch of k = 1) is a
# region at any damping of the others: its edges and critical amplitude (Illinois on Brent
# maxima) take some 230-330 more evaluations at about its centre's damped step count
# (counted on a flight's free-free vehicle, zeta = 0.02, pitch orders 1-3 at 0.9-3.6 Hz:
# 786, 666 and 1,115 points for 2, 2 and 3 such regions); 350 each.
_EVALS_OPEN = 350.0
# CPU, one core: per evaluated point 4e-4 s (the step rule, two expm, the eigenvalues) and per
# integration step of one point 1e-6 s + 3e-10 s (2n)^3, fitted on whole damped searches (their
# CPU over their steps, on a loaded core): the memo's default (n = 11: 1,775 points, 81,931
# steps, 1.2 s), the liquid vehicle's k = 1 (n = 19: 5,571 points, 1.38 million steps, 24.6 s)
# and free-free index 7 (n = 2: 2.08 million steps, 1.8 s). The dense kernel alone takes less
# per step on an idle core (0.49, 6.80, 42.0 microseconds at n = 2, 19, 40; 64 points a batch);
# this law also covers the step counts' shortfall where the gimbaled pitch's candidates open
# at any damping but are counted as damped ones (a mutated liquid vehicle's k = 1: 1.43
# million steps run, 0.56 million counted)
_C_SEARCH_POINT = 4e-4
_C_SEARCH_STEP = (1e-6, 3e-10)
# above this many modes the k = 1 search is estimated by search_seconds (n^4 law: 96 s at 40
# modes, so such a search is the budget's concern anyway) after the certificate, without
# enumerating its candidates (247 modes over a wide range: more than 20 GB of candidates)
_K1_COUNTED_MODES = 40


def bending_search_steps(work: Any, *, damping_ratio: float) -> tuple[float, float]:
    """Monodromy integration steps (summed over the evaluated points) and CPU time (s, one core)
    of the k = 1 region search whose work the toolkit counts up front (steps per period chosen
    exactly as the monodromy kernel does, at each candidate's centre): :func:`damped_search_cost`.

    Parameters
    ----------
    work : flexbooster.floquet.SearchWork
        :func:`flexbooster.floquet.search_work` of the harmonic (0 steps when steady or
        certified stable: no search).
    damping_ratio : float
        The modal damping ratio of the harmonic, 0 < zeta < 1.
    """
    return damped_search_cost(work, damping_ratio=damping_ratio)


def _check_work(work: Any) -> None:
    """TypeError naming ``work`` unless it is a :class:`flexbooster.floquet.SearchWork`."""
    from .floquet import SearchWork

    if not isinstance(work, SearchWork):
        raise TypeError(f"work = {type(work).__name__}: must be a SearchWork")


def damped_search_cost(work: Any, *, damping_ratio: float) -> tuple[float, float]:
    """Steps (summed over the evaluated points) and CPU time (s, one core) of a damped region
    search (the undamped seeds, the damped regions, the critical gamma of each) from its count
    up front: E_u x the undamped + E_d x the damped steps at the candidate centres, E_u = 10,
    E_d = 40 at zeta <= 0.01 to 30 and 500 at zeta >= 0.3 (log-log between), and 70 evaluated
    points per candidate; a candidate between undamped modes (a region at any damping) at
    least 350 evaluations at its damped steps (max(E_d, 350)); the candidates of the seeds'
    second pass (``work.n_retry``) as many more, at E_u; 4e-4 s per point and
    :func:`search_step_seconds` per step (measured).

    Parameters
    ----------
    work : flexbooster.floquet.SearchWork
        :func:`flexbooster.floquet.search_work` of the damped system (0 when steady or
        certified stable: no search).
    damping_ratio : float
        The damping ratio that drives the search, 0 < zeta < 1.
    """
    _check_work(work)
    zeta = positive("damping_ratio", damping_ratio)
    if zeta >= 1.0:
        raise ValueError(f"damping_ratio = {zeta!r}: must satisfy 0 < zeta < 1")
    if work.steady or work.certified:
        return 0.0, 0.0
    z0, z1 = _EVALS_ZETA
    x = min(max(math.log(zeta / z0) / math.log(z1 / z0), 0.0), 1.0)  # log-log interpolation
    e_u, e_d = (a * (b / a) ** x for a, b in (_EVALS_UNDAMPED, _EVALS_DAMPED))
    e_o = max(e_d, _EVALS_OPEN)
    steps = (e_u * (work.undamped_steps + work.retry_steps)
             + e_d * (work.damped_steps - work.open_steps) + e_o * work.open_steps)
    seconds = (_C_SEARCH_POINT * (_EVALS_POINTS * (work.n_candidates + work.n_retry)
                                  + _EVALS_OPEN * work.n_open)
               + steps * search_step_seconds(work.n))
    return float(steps), float(seconds)


def search_step_seconds(n: int) -> float:
    """CPU time (s, one core) of one monodromy integration step of one point of a system of n
    degrees of freedom, its share of the search's other work included: 1e-6 s + 3e-10 s
    (2n)^3 (measured, see above).

    Parameters
    ----------
    n : int
        Degrees of freedom, >= 1.
    """
    c0, c1 = _C_SEARCH_STEP
    return c0 + c1 * float(2 * count("n", n, 1, None)) ** 3


def damped_band_steps(model: BoosterModel) -> tuple[float, float]:
    """Monodromy steps (summed over the evaluated points) and CPU time (s, one core) of the damped
    part of the memo's beam-action band search above omega_1 / 4 (the damped regions from their
    undamped seeds and the critical gamma of each): :func:`damped_search_cost` at the largest
    of the beam and pitch damping ratios; 0 without damping or pulsation, or where the damping
    certifies the system stable.

    Parameters
    ----------
    model : BoosterModel
        The derived model.
    """
    if model.gamma <= 0.0:
        return 0.0, 0.0
    system = beam_system(model)
    w1 = float(system.omega_1)
    lo = max(float(np.min(model.Omega)), BAND_OMEGA_BAR_MIN * w1) / w1
    hi = float(np.max(model.Omega)) / w1
    C = modal_damping(system, beam_ratio=model.beam_damping_ratio,
                      pitch_ratio=model.pitch_damping_ratio)
    if C is None or not hi > lo:
        return 0.0, 0.0
    n = system.N + 1
    try:
        work = search_work(np.eye(n), C, system.A0, -model.gamma * system.B, lo, hi,
                           rtol=BAND_RTOL, max_order=BAND_MAX_ORDER,
                           max_candidates=BAND_MAX_CANDIDATES, step_phase=0.12)
    except ValueError:  # past a size limit of the toolkit: the stage says so
        return 0.0, 0.0
    return damped_search_cost(work, damping_ratio=max(model.beam_damping_ratio,
                                                      model.pitch_damping_ratio))


#: The step limit of a count that must not stop at floquet.MAX_STEPS (no integration).
_COUNT_MAX_STEPS = 2**62


def _system_search_seconds(build, thrust, price, elastic: list | None = None) -> float:
    """CPU time (s) of the damped region search of the harmonic ``build()`` returns over the
    thrust's Omega range (:func:`_work_seconds` at its gamma); 0 where the harmonic cannot be
    built (the stage says why). With ``elastic``, appends the number of its candidates between
    elastic modes (:func:`_elastic_candidates`), or None where its work is not counted."""
    from .dynamics.harmonic import LIMIT_ERRORS
    from .shell_of_revolution import BucklingError

    try:
        h = build()
        system = h.periodic(thrust.gamma)
    except (*LIMIT_ERRORS, BucklingError, ValueError):
        return 0.0
    if elastic is None:
        return _work_seconds(system, thrust.omega_min, thrust.omega_max, price)
    seen: list = []

    def counted(work) -> float:
        seen.append(_elastic_candidates(h, work))
        return price(work)

    seconds = _work_seconds(system, thrust.omega_min, thrust.omega_max, counted)
    if seen or seconds > 0.0:  # a search priced without its work: its candidates unknown
        elastic.append(seen[0] if seen else None)
    return seconds


def _elastic_candidates(h: Any, work: Any) -> int:
    """The candidates of ``work`` (a harmonic ``h``'s search) between elastic modes: the only
    ones whose regions get a critical damping ratio (dynamics.region_critical_damping leaves
    out the regions that hold a rigid mode, which no modal damping closes)."""
    rigid = {i for i in range(work.n) if h.mode(i).type.startswith("rigid")}
    return sum(1 for i, k in work.pairs if i not in rigid and k not in rigid)


def _work_seconds(system: tuple, omega_min: float, omega_max: float, price) -> float:
    """CPU time (s) of the region search of the periodic system (M, C, A, B) over [omega_min,
    omega_max]: its work counted up front and priced by ``price(work)``, or, past
    :data:`_K1_COUNTED_MODES` modes, the n^4 law of :func:`search_seconds` unless its
    certificate holds (enumerating the candidates alone can pass the memory); 0 where it
    passes a toolkit limit (the stage says why)."""
    from . import floquet
    from .dynamics.harmonic import LIMIT_ERRORS, floquet_options

    try:
        n = system[0].shape[0]
        if n > _K1_COUNTED_MODES:
            if floquet.stability_certificate(*system).certified:
                return 0.0
            return search_seconds(n, omega_min, omega_max, damped=True)
        try:
            work = floquet.search_work(*system, omega_min, omega_max, **floquet_options())
        except floquet.StepLimitError:
            # a candidate past the step limit: the search integrates only where its seeds
            # lead, so it may never meet that one and run in full; every candidate's steps
            # counted with no limit (an upper bound)
            work = floquet.search_work(*system, omega_min, omega_max,
                                       **{**floquet_options(), "max_steps": _COUNT_MAX_STEPS})
    except (*LIMIT_ERRORS, ValueError):
        return 0.0
    return price(work)


def _bending_search_seconds(case: Any, vehicle: Any, n_modes: int, zeta: float,
                            elastic: list | None = None) -> float:
    """The k = 1 search of a damped case (:func:`bending_search_steps`); ``elastic`` as
    :func:`_system_search_seconds`."""
    from .dynamics import bending_harmonic

    return _system_search_seconds(
        lambda: bending_harmonic(vehicle, F0=case.F0, n_modes=max(n_modes, 3),
                                 damping_ratio=zeta, gimbal_gain=case.thrust.K),
        case.thrust, lambda work: bending_search_steps(work, damping_ratio=zeta)[1], elastic)


# The candidates' indicators are integrated in one batch (the Lawson modal kernel), which
# runs as long as its longest candidate: each step of the batch costs a fixed 15e-6 s (its
# numpy calls: 13-16e-6 s measured at n = 3..10) on top of the points' own steps, and the
# longest candidate is integrated in some 60 batch evaluations (Brent maxima, then the
# edges): a short wide cylinder, k = 2, 30 candidates, the longest 23,171 half-period steps
# at n = 5: 62 evaluations, 1.05 million batch steps, 17.8 s (13.1e-6 s per batch step and
# 1.39e-6 s per point-step fitted on its 62 calls); one candidate of 23,171 steps at n = 20:
# 40 s on a loaded core (this law: 22.7 s and 49 s)
_BATCH_ROUNDS, _C_BATCH_STEP = 60.0, 15e-6


def shell_search_seconds(work: Any) -> float:
    """CPU time (s, one core) of the region search of a damped harmonic k >= 2 from its work
    counted up front: the undamped seed search, E_u = 10 evaluations of the steps at the
    candidate centres or, where longer, the batch's rounds (60 evaluations of the longest
    candidate, see above), and 70 evaluated points per candidate
    (:func:`damped_search_cost`'s constants), the candidates of the second pass
    (``work.n_retry``) counted as many more; the damped search runs only from the seeds it
    finds, unknown up front, and is not priced (measured on three vehicles' harmonics k =
    3..20, seeds or none, the search took 0.3-1.0 times this). 0 when steady or certified
    stable.

    Parameters
    ----------
    work : flexbooster.floquet.SearchWork
        :func:`flexbooster.floquet.search_work` of the damped harmonic.
    """
    _check_work(work)
    if work.steady or work.certified:
        return 0.0
    step = search_step_seconds(work.n)
    # the seeds' indicators in one batch, as long as its longest candidate (see above)
    rounds = _BATCH_ROUNDS * work.undamped_max_steps * (_C_BATCH_STEP + step)
    return float(_C_SEARCH_POINT * _EVALS_POINTS * (work.n_candidates + work.n_retry)
                 + max(_EVALS_UNDAMPED[0] * (work.undamped_steps + work.retry_steps) * step,
                       rounds))


#: Name of the part of :func:`estimate_vehicle_cost` for the searches of an undamped vehicle's
#: harmonics k = 1..k_max (:func:`undamped_search_seconds`).
UNDAMPED_SEARCH_PART = "vehicle undamped searches"
#: Name of the part of :func:`with_flight` for the searches outside the flight's range
#: (:func:`pass_over_seconds`).
PASS_OVER_PART = "flight pass-over searches"
# The undamped search of a harmonic (every combination of its modes whose region the step rule
# resolves at the case's gamma: more, and of higher orders, as gamma grows) integrates about
# E_u = 10 times the step counts at its candidates' centres (counted: 7.7-13.4 x on a fuzz
# flight's harmonics k = 2..20, tests/test_cost.py), at the dense step cost, plus 3e-3 s per
# candidate examined by the monodromy (the step rule, expm and eigenvalues of its points);
# fitted on that flight's free-free tanked vehicle (k <= 20, 6 modes, and k <= 8, 14 modes;
# gamma 0.02 and 0.2 at lift-off and burnout: 351-1,410 regions, 2.1-34.5 s CPU on a loaded
# core): every one of those eight runs within 1.07-1.62x of it, none above. Each evaluation
# integrates the candidates in one batch, as long as the longest (15e-6 s per batch step, see
# :func:`shell_search_seconds`): E_u x that as well. A lone candidate of 92,682 half-period
# steps (the short wide cylinder of tests/data, undamped, k = 2, n = 5, Omega within 0.5 % of
# one centre): 7-10 evaluations, 9.8-13.8 s CPU measured, 1.2 s priced without this term.
_C_UNDAMPED_CANDIDATE = 3e-3
# A canonical harmonic (every k >= 2: floquet.SearchWork.canonical) has no difference
# candidates, and nearly all of its simple and sum ones open a region when undamped, each
# then refined at both edges: 17.7 and 14.5 x its centre steps (tests/data/
# flight_undamped_case.toml at lift-off and burnout, k = 3..6: 162 regions of 170 candidates
# and 113 of 214), so E_u = 18; that flight's whole vehicle-regions stage (k <= 20, 433 and
# 938 regions, 3.8 and 9.0 s CPU) is then 1.0 and 1.42 x its estimate.
_EVALS_UNDAMPED_CANONICAL = 18.0


def undamped_search_seconds(work: Any) -> float:
    """CPU time (s, one core) of the region search of an undamped harmonic from its work
    counted up front: 3e-3 s per candidate examined by the monodromy and E_u = 10 evaluations
    (18 for a canonical harmonic) of the steps at its centre (:func:`search_step_seconds`),
    the candidates of the second pass (``work.n_retry``) counted as many more, each with the
    batch's overhead for its longest candidate (15e-6 s per step of
    ``work.undamped_max_steps``); 0 when steady (no search).

    Parameters
    ----------
    work : flexbooster.floquet.SearchWork
        :func:`flexbooster.floquet.search_work` of the undamped harmonic.
    """
    _check_work(work)
    if work.steady:
        return 0.0
    evals = _EVALS_UNDAMPED_CANONICAL if work.canonical else _EVALS_UNDAMPED[0]
    return float(_C_UNDAMPED_CANDIDATE * (work.n_candidates + work.n_retry) + evals * (
        (work.undamped_steps + work.retry_steps) * search_step_seconds(work.n)
        + work.undamped_max_steps * _C_BATCH_STEP))


#: Harmonics whose undamped search :func:`estimate_vehicle_cost` counts (the others
#: interpolated linearly in k between them): the build of a harmonic's modal system, which the
#: count needs, is what a large k_max would otherwise cost the estimate (40 harmonics of 40
#: modes: 8.7 s). The counted price varies smoothly with k (a fuzz flight's k = 1..20:
#: 0.09-0.25 s, 0.13-0.51 s), so k = 1, 2 and geometric steps to k_max.
UNDAMPED_SAMPLES = 8


def _undamped_searches(case: Any, vehicle: Any, n_k: int, n_modes: int) -> float:
    """The searches of the harmonics k = 1..n_k of an undamped case, each the larger of
    :func:`undamped_search_seconds` of its counted work (the modal system built as the stage
    builds it: k = 1 with the gimbaled rigid pitch) and the blind law :func:`search_seconds`;
    counted at :data:`UNDAMPED_SAMPLES` harmonics at most, linear in k between them; the
    blind law alone past :data:`_K1_COUNTED_MODES` modes."""
    from .dynamics import bending_harmonic, harmonic_system
    from .shell_of_revolution import shared_harmonics

    t = case.thrust

    def build(k: int):
        if k == 1:
            return bending_harmonic(vehicle, F0=case.F0, n_modes=max(n_modes, 3),
                                    damping_ratio=0.0, gimbal_gain=t.K)
        return harmonic_system(vehicle, k, F0=case.F0, n_modes=n_modes, damping_ratio=0.0,
                               unloaded_frequencies=False)

    blind = search_seconds(max(n_modes, 3), t.omega_min, t.omega_max, damped=False)
    if n_modes > _K1_COUNTED_MODES:  # the blind law (the candidates are not enumerated)
        return float(n_k * blind)
    ks = _sampled_harmonics(n_k)
    with shared_harmonics():
        each = [max(blind, _system_search_seconds(lambda k=int(k): build(k), t,
                                                  undamped_search_seconds)) for k in ks]
    return float(np.sum(np.interp(np.arange(1, n_k + 1), ks, each)))


def _sampled_harmonics(n_k: int) -> np.ndarray:
    """The harmonics k of 1..n_k whose search work the estimate counts, the others linear in k
    between them: all up to :data:`UNDAMPED_SAMPLES`, else k = 1, 2 and geometric steps to
    n_k.

    Parameters
    ----------
    n_k : int
        Highest harmonic, >= 1.
    """
    n_k = count("n_k", n_k, 1, None)
    if n_k <= UNDAMPED_SAMPLES:
        return np.arange(1, n_k + 1)
    return np.unique(np.concatenate([[1, 2], np.geomspace(
        1, n_k, UNDAMPED_SAMPLES - 1).round().astype(int), [n_k]]))


def _shell_searches(case: Any, vehicle: Any, n_k: int, n_modes: int,
                    elastic: list | None = None) -> float:
    """:func:`shell_search_seconds` summed over the harmonics k = 2..n_k of a damped case, each
    harmonic's modal system built as the stage builds it; ``elastic`` as
    :func:`_system_search_seconds`."""
    from .dynamics import harmonic_system
    from .shell_of_revolution import shared_harmonics

    with shared_harmonics():
        return float(sum(_system_search_seconds(
            lambda k=k: harmonic_system(vehicle, k, F0=case.F0, n_modes=n_modes,
                                        damping_ratio=case.vehicle_damping_ratio,
                                        unloaded_frequencies=False),
            case.thrust, shell_search_seconds, elastic) for k in range(2, n_k + 1)))


def _dof_factors(mesh) -> tuple[float, float, float, float]:
    """The FE work of a harmonic of the modes survey and of a harmonic's build, then of the
    same for a harmonic with rigid-body motions, on ``mesh``, in units of the reference
    vehicle's (:data:`_SURVEY_DOF_LAW`, :data:`_BUILD_DOF_LAW`, :data:`_SURVEY_DENSE_LAW`,
    :data:`_BUILD_DENSE_LAW`)."""
    x = mesh.n_full / _REF_DOFS
    (s2, s3), (b1, b3) = _SURVEY_DOF_LAW, _BUILD_DOF_LAW
    (d2, d3), (e1, e3) = _SURVEY_DENSE_LAW, _BUILD_DENSE_LAW
    return tuple(max(1.0 / 3.0, v) for v in (s2 * x**2 + s3 * x**3, b1 * x + b3 * x**3,
                                              d2 * x**2 + d3 * x**3, e1 * x + e3 * x**3))


def _dense_harmonics(vehicle, mesh, k_max: int) -> tuple[int, ...]:
    """The harmonics k <= min(1, k_max) whose modes are solved dense: rigid-body motions
    (:func:`.shell_of_revolution.rigid_motion_count`), or at k = 0 a full tank (its liquid's
    volume constraint; a vehicle's tanks have rigid ends)."""
    from .shell_of_revolution import rigid_motion_count

    full = any(t.fill == 1.0 for t in vehicle.tanks)
    return tuple(k for k in range(min(1, k_max) + 1)
                 if (k == 0 and full) or rigid_motion_count(vehicle, mesh, k))


def region_modes(case: Any, vehicle: Any = None, *, k_max: int = 10) -> tuple[int, int]:
    """The modes per harmonic of the vehicle's regions (``vehicle.n_modes``, at most the DOFs of
    the mesh in a harmonic k = 0..k_max) and the smallest mode count of the harmonics.

    Parameters
    ----------
    case : Case
        The validated case.
    vehicle : Vehicle, optional
        Its vehicle (:func:`flexbooster.model.vehicle_from_case`), when already built.
    k_max : int
        Highest harmonic of the regions, >= 1.
    """
    from .model import vehicle_from_case
    from .shell_of_revolution import mesh_vehicle
    from .shell_of_revolution.assembly import dof_map
    from .vehicle_case import REGION_N_MODES

    wanted = case.vehicle.n_modes if case.vehicle is not None else REGION_N_MODES
    vehicle = vehicle_from_case(case) if vehicle is None else vehicle
    mesh = mesh_vehicle(vehicle)
    # k = 0 (the forced axial modes) loses its rigid motions (axial translation, torsion: at
    # most 2) to the modal basis; k = 1 keeps them (the bending basis); k >= 2 has none
    dofs = min(dof_map(vehicle, mesh, k).n - (2 if k == 0 else 0)
               for k in range(0, min(max(1, int(k_max)), 2) + 1))  # k >= 2: one class
    return min(wanted, dofs), dofs


def estimate_vehicle_cost(case: Any, *, regions_k_max: int | None = None,
                          regions: bool = True, figures: bool = True,
                          certified: bool = True, forced: bool = False,
                          vehicle: Any = None) -> CostEstimate:
    """The predicted time of the vehicle stages of :func:`flexbooster.analysis.analyze`: "vehicle
    modes" (``[vehicle]`` only) and "vehicle regions" (:func:`search_seconds` per harmonic not
    certified), each with the tanks' liquid (a mesh per tank, an added mass per tank and
    harmonic) and the lumped masses (k <= 1), with their fields; no solver is run.

    Parameters
    ----------
    case : Case
        The validated case (SI).
    regions_k_max : int, optional
        Highest harmonic of the regions, >= 1; default ``vehicle.k_max``.
    regions : bool
        The vehicle's parametric regions are computed.
    figures : bool
        With the chart's boundary curves.
    certified : bool
        Assume that damping certifies every harmonic stable (the lower bound); False: every
        harmonic searched (the upper bound).
    forced : bool
        The vehicle's forced response is computed ("vehicle forced response":
        :func:`forced_run_seconds`).
    vehicle : Vehicle, optional
        The case's vehicle (:func:`flexbooster.model.vehicle_from_case`), when the caller has
        it: the harmonics the estimate builds are then shared with the caller's.
    """
    from .model import vehicle_from_case
    from .shell_of_revolution import mesh_vehicle
    from .vehicle_case import VehicleTable

    table = case.vehicle if case.vehicle is not None else VehicleTable()
    t = case.thrust
    parts: dict[str, float] = {}
    drivers: dict[str, tuple[str, ...]] = {}
    n_k = table.k_max if regions_k_max is None else min(table.k_max, int(regions_k_max))
    try:
        vehicle = vehicle_from_case(case) if vehicle is None else vehicle
        mesh = mesh_vehicle(vehicle)
        survey_dofs, build_dofs, dense_dofs, dense_build = _dof_factors(mesh)
        dense = _dense_harmonics(vehicle, mesh, max(table.k_max, min(n_k, 1)))
        n_dense = sum(1 for k in dense if k <= table.k_max)
        n_dense_build = sum(1 for k in dense if 1 <= k <= n_k)  # the regions' k = 1
        n_modes = region_modes(case, vehicle, k_max=max(n_k, 1))[0]
    except ValueError:  # a vehicle the mesh refuses: the stage says why, not the estimate
        return CostEstimate(seconds=0.0)
    n_tanks = sum(1 for tank in vehicle.tanks if tank.fill > 0.0)
    n_masses = len(vehicle.masses)
    attached = tuple(name for name, n in (("vehicle.tanks", n_tanks),
                                          ("vehicle.masses", n_masses)) if n)

    def per_harmonic(n_harmonics: int, n_low: int) -> float:  # n harmonics, n_low of k <= 1
        return n_harmonics * n_tanks * _C_TANK[1] + n_low * n_masses * _C_MASS

    if case.vehicle is not None:  # the modes survey, k = 0..k_max
        c0, c1 = _C_SURVEY
        parts["vehicle modes"] = (c0 + c1 * ((table.k_max + 1 - n_dense) * survey_dofs
                                             + n_dense * dense_dofs)
                                  + n_tanks * _C_TANK[0]
                                  + per_harmonic(table.k_max + 1, min(table.k_max + 1, 2)))
        drivers["vehicle modes"] = ("vehicle.k_max", "vehicle.segments") + attached
    if regions and n_k >= 1:
        damped = case.vehicle_damping_ratio > 0.0
        # the blind law for the damped upper bound; undamped, each harmonic's candidates are
        # counted (UNDAMPED_SEARCH_PART, below)
        searched = n_k if damped and not certified and t.gamma > 0.0 else 0
        # k = 1 has the rigid modes too (at least 3 basis modes)
        search = searched * search_seconds(max(n_modes, 3), t.omega_min, t.omega_max,
                                           damped=damped, boundaries=figures)
        parts["vehicle regions"] = _C_HARMONIC_BUILD * (
            (n_k - n_dense_build) * build_dofs + n_dense_build * dense_build) * max(
            1.0, n_modes / 20.0) + per_harmonic(n_k, 1) + search
        drivers["vehicle regions"] = ("vehicle.n_modes", "damping.modal_ratio",
                                      "vehicle.k_max", "thrust.omega_min", "thrust.omega_max",
                                      "vehicle.segments") + attached
        elastic: list = []  # per searched harmonic: its candidates between elastic modes
        if damped and certified and t.gamma > 0.0:
            # the harmonics k >= 2 that damping does not certify after all: searched
            shell = _shell_searches(case, vehicle, n_k, n_modes, elastic)
            if shell > 0.0:
                parts[SHELL_SEARCH_PART] = shell
                drivers[SHELL_SEARCH_PART] = ("damping.modal_ratio", "thrust.gamma",
                                              "thrust.omega_min", "thrust.omega_max",
                                              "vehicle.n_modes", "vehicle.k_max")
            # k = 1 keeps its undamped rigid pitch
            k1 = _bending_search_seconds(case, vehicle, n_modes, case.vehicle_damping_ratio,
                                         elastic) * (_BOUNDARY_SEARCH_FACTOR if figures else 1.0)
            if k1 > 0.0:
                parts[BENDING_SEARCH_PART] = k1
                drivers[BENDING_SEARCH_PART] = ("damping.modal_ratio", "thrust.omega_min",
                                                "thrust.K", "vehicle.n_modes")
        if not damped and t.gamma > 0.0:
            parts[UNDAMPED_SEARCH_PART] = _undamped_searches(case, vehicle, n_k, n_modes) * (
                _BOUNDARY_SEARCH_FACTOR if figures else 1.0)
            drivers[UNDAMPED_SEARCH_PART] = ("damping.modal_ratio", "thrust.gamma",
                                             "thrust.omega_min", "thrust.omega_max",
                                             "vehicle.n_modes", "vehicle.k_max")
        if searched or any(p in parts for p in (BENDING_SEARCH_PART, SHELL_SEARCH_PART,
                                                UNDAMPED_SEARCH_PART)):
            # regions may open: their critical damping ratios
            # (dynamics.region_critical_damping), at most a fixed number, and of a damped
            # case's counted searches at most one per candidate between elastic modes (a
            # region holding a rigid mode gets none)
            regions = CRITICAL_DAMPING_COUNT
            if not searched and elastic and None not in elastic:
                regions = min(regions, sum(elastic))
            if regions:
                parts[CRITICAL_DAMPING_PART] = regions * _C_CRITICAL_REGION * max(
                    1.0, (max(n_modes, 3) / _CRITICAL_REGION_N) ** 3)
                drivers[CRITICAL_DAMPING_PART] = ("vehicle.n_modes", "damping.modal_ratio")
        if damped:  # the certificates: map, search, chart (none undamped: no certificate)
            calls = 2 + bool(figures)
            parts["vehicle certificates"] = n_k * calls * _C_CERTIFICATE * (
                2.0 * max(n_modes, 3)) ** 3
            drivers["vehicle certificates"] = ("vehicle.n_modes", "vehicle.k_max")
    if forced:
        parts["vehicle forced response"] = forced_run_seconds(case, vehicle)
        drivers["vehicle forced response"] = ("vehicle.segments", "thrust.misalignment",
                                              "thrust.n_omega")
    return CostEstimate(seconds=float(sum(parts.values())), parts=parts, drivers=drivers)


def check_case_cost(model: BoosterModel | None, max_seconds: float, *,
                    vehicle: CostEstimate | None = None, **stages: bool) -> CostEstimate:
    """The cost estimate (the vehicle parts included), or a ``CaseError`` on ``max_seconds`` with
    the estimate and its fields when it exceeds the budget.

    Parameters
    ----------
    model : BoosterModel or None
        The derived model; None for a ``[[vehicle.segments]]`` case (no memo stage).
    max_seconds : float
        Budget (s), > 0.
    vehicle : CostEstimate, optional
        The vehicle stages (:func:`estimate_vehicle_cost`), added to the memo's.
    **stages : bool
        ``beam_action``, ``stability``, ``figures`` as for :func:`estimate_cost`.
    """
    max_seconds = positive("max_seconds", max_seconds)
    est = CostEstimate(seconds=0.0) if model is None else estimate_cost(model, **stages)
    if vehicle is not None and vehicle.parts:
        est = CostEstimate(seconds=est.seconds + vehicle.seconds,
                           parts={**est.parts, **vehicle.parts},
                           drivers={**est.drivers, **vehicle.drivers},
                           capped_points=est.capped_points,
                           capped_omega_max=est.capped_omega_max)
    if est.seconds > max_seconds:
        raise CaseError("max_seconds", max_seconds,
                        f"the estimated run time {est.seconds:.3g} s exceeds the budget: "
                        f"{est.describe()}; reduce those fields or raise the budget "
                        "(--max-seconds)")
    return est


def check_pitch_range(*, F0: float, omega_psi: float, omega_min: float, gamma: float) -> None:
    """CaseError on ``thrust.F0`` when the rigid pitch's Mathieu a = 4 omega_psi^2 / Omega^2
    (memo eq. 4.2-4) at the lowest Omega is beyond what the Mathieu numerics bound
    (MATHIEU_SCALE_MAX^2), before any solver runs.

    Parameters
    ----------
    F0 : float
        Steady thrust (N).
    omega_psi : float
        Rigid-body pitch frequency (rad/s).
    omega_min : float
        Lowest thrust pulsation frequency (rad/s), > 0.
    gamma : float
        Pulsation amplitude.
    """
    a_max = 4.0 * omega_psi**2 / omega_min**2  # eq. (4.2-4)
    if not math.sqrt(a_max * (1.0 + gamma)) <= MATHIEU_SCALE_MAX:
        raise CaseError("thrust.F0", F0,
                        f"gives Mathieu a = 4 omega_psi^2/Omega^2 = {a_max:.3g} at the lowest "
                        f"Omega {omega_min:.6g} rad/s (omega_psi = {omega_psi:.6g} rad/s), "
                        f"beyond {MATHIEU_SCALE_MAX**2:.3g} (eq. 4.2-4): reduce it or the "
                        "gimbal gain K, or raise omega_min")


def check_physical(model: BoosterModel) -> None:
    """Refuse a load at or above what the structure carries, before any solver runs: CaseError on
    ``thrust.F0`` when the steady beam-action system diverges or flutters (Beal 1965; memo
    4.1-11) or a = 4 omega_psi^2 / omega_min^2 (4.2-4) exceeds MATHIEU_SCALE_MAX^2.

    Parameters
    ----------
    model : BoosterModel
        The derived model.
    """
    check_pitch_range(F0=model.F0, omega_psi=model.omega_psi,
                      omega_min=float(np.min(model.Omega)), gamma=model.gamma)
    system = beam_system(model)
    mu = np.linalg.eigvals(system.A0)  # squared steady frequencies / omega_1^2, eq. (4.1-11)
    big = float(np.max(np.abs(mu)))
    tol = 1e-9 * big
    if np.any(np.abs(mu.imag) > tol):
        raise CaseError("thrust.F0", model.F0,
                        "at or above the flutter load of the steady beam-action system "
                        f"(complex eigenvalue {complex(mu[np.argmax(np.abs(mu.imag))]):.4g} "
                        "of Lambda + B, eq. 4.1-11 with gamma = 0): the booster is unstable "
                        "without pulsation")
    if np.any(mu.real < -tol):
        raise CaseError("thrust.F0", model.F0,
                        "at or above the divergence load of the steady beam-action system "
                        f"(eigenvalue {float(np.min(mu.real)):.4g} < 0 of Lambda + B, "
                        "eq. 4.1-11 with gamma = 0): the booster is unstable without pulsation")


def physical_warnings(model: BoosterModel) -> list[AnalysisWarning]:
    """``shell-buckling`` (field ``thrust.F0``) when F0 reaches the classical axial buckling load
    2 pi E h^2 / sqrt(3 (1 - nu^2)) of a cylinder (Timoshenko & Gere 1961, eq. 11-17).

    Parameters
    ----------
    model : BoosterModel
        The derived model.
    """
    f_cr = 2.0 * math.pi * model.E * model.h**2 / math.sqrt(3.0 * (1.0 - model.nu**2))
    if model.F0 >= f_cr:
        return [AnalysisWarning(
            "shell-buckling", "thrust.F0",
            f"F0 = {model.F0:.4g} N reaches the classical axial buckling load "
            f"2 pi E h^2 / sqrt(3 (1 - nu^2)) = {f_cr:.4g} N of the cylinders (Timoshenko & "
            "Gere 11-17; real shells buckle lower): the memo's shell frequencies are those "
            "of the unloaded shells")]
    return []


def capped_steps_warning(estimate: CostEstimate, model: BoosterModel) -> list[AnalysisWarning]:
    """``beam-action-step-cap`` (field ``thrust.omega_min``) when the beam-action step count was
    capped at some grid points (docs/theory/robustness.md), or nothing.

    Parameters
    ----------
    estimate : CostEstimate
        From :func:`estimate_cost`.
    model : BoosterModel
        The derived model.
    """
    if not estimate.capped_points:
        return []
    return [AnalysisWarning(
        "beam-action-step-cap", "thrust.omega_min",
        f"{estimate.capped_points} of {np.size(model.Omega)} grid points, Omega up to "
        f"{estimate.capped_omega_max:.6g} rad/s: the beam-action step count per half "
        f"period is capped at {MONODROMY_MAX_STEPS} (bounded cost); alpha there is accurate "
        "to about 1e-5 instead of 1e-9")]


# The forced resonances of one frozen time (flexbooster.flight_stage: the modal model of each
# harmonic forced and the peak of each resonance met, one run on a two-point grid): 0.09 s per
# frozen time of the flight example (n = 369), about 0.14 s for the default case (n = 780),
# one harmonic each; a quarter of :func:`forced_seconds` (0.15 s and 0.3 s)
_FLIGHT_FORCED = 0.25


def forced_seconds(vehicle: Any, n_omega: int, *, large_basis: bool = True) -> float:
    """CPU time (s, one core) of the forced response of one harmonic forced, with its
    convergence run: the larger of c0 + c1 (n / 780)^2 (a few basis modes) and 0.9 (n / 263)^3
    (a basis of many: the modes below 4 Omega_max are not known up front), plus n_omega (c2 +
    c3 min(n, 200)), for the mesh's n DOFs (measured, see above).

    Parameters
    ----------
    vehicle : flexbooster.shell_of_revolution.Vehicle
        The vehicle.
    n_omega : int
        Omega points of the response, >= 0.
    large_basis : bool
        Bound a basis of many modes too (False: the few-modes law alone, as measured for the
        flight's frozen times).
    """
    from .shell_of_revolution import mesh_vehicle

    n = float(mesh_vehicle(vehicle).n_full)
    c0, c1, c2, c3 = _C_FORCED
    points = count("n_omega", n_omega, 0, None)
    many = _C_FORCED_BASIS * (n / _REF_DOFS) ** 3 if large_basis else 0.0
    return float(max(c0 + c1 * (n / _FORCED_DOFS) ** 2, many)
                 + points * (c2 + c3 * min(n, _FORCED_BASIS)))


# The single run's forced response (k = 0 and 1 on the case's grid and the half-basis
# convergence run) from the counted bases m_k: c_n x^2 max(1, x), x = n / 780 (the dense
# eigenproblems and static corrections of the n DOFs; n^3 past the measured n <= 917) +
# c_s sum m^3 (the complex Schur form of each 2m companion matrix) + c_f sum_forced m^3 (the
# peak search on ~65 points per pole) + c_p sum_forced m^2 n_omega + c_m sum m + c_h per
# harmonic forced. Non-negative least squares on 251 independent-fuzz cases (seed 40, cases
# 0-399 with a forced response; n 55-917, m 6-344; CPU of one core, two fits running on the
# 2-core machine): actual / fit median 0.97, largest 2.5 (runs under 0.2 s). Taken 0.1 s +
# twice the fit: actual / estimate at most 0.76 on those cases (median estimate 2.7x).
_C_FORCED_RUN = (0.27, 1.15e-8, 9.13e-8, 3.6e-9, 5e-4, 0.009)
_FORCED_RUN_FLOOR, _FORCED_RUN_MARGIN = 0.1, 2.0
# The peak near each forced mode in the range (dynamics.mode_peaks: one window_peaks each, 65
# points and the golden steps of the model's response): per mode 3.8, 13.0 and 17.7 ms at
# bases of 15, 70 and 133 modes (the default case, the two-stage liquid example, the memo
# case; one core) -> 2 ms + 0.15 ms per basis mode, priced for every basis mode of a forced
# harmonic (those in the range are not counted up front: an upper bound; 1.57 s against 1.15 s
# measured for the memo case's 65 peaks)
_C_MODE_PEAK = (2e-3, 1.5e-4)
#: Past this many DOFs the forced response's basis is not counted: the count assembles each
#: harmonic's dense matrices (8 n^2 bytes each: 50 MB at 2,500) and factorises them, which a
#: case refused for its size should not pay; :func:`forced_seconds` (its DOFs-cubed bound)
#: prices it instead (the count took 0.23 s at 882 DOFs, 1.5 s at 2,340 on a loaded machine,
#: where the bound gives 634 s for a forced response of 2.7 s).
FORCED_COUNT_MAX_DOFS = 2500


def forced_run_seconds(case: Any, vehicle: Any) -> float:
    """CPU time (s, one core) of the forced response of a single run
    (:func:`flexbooster.analysis.analyze_forced_response`) from its counted basis per harmonic
    (:func:`flexbooster.dynamics.basis_sizes`, Sylvester's law of inertia; no eigenvector):
    the law above, and with a sweep the peak near each forced mode (``_C_MODE_PEAK`` per basis
    mode of a forced harmonic); :func:`forced_seconds` for each harmonic forced where the count
    cannot be made (the stage then says why) or past :data:`FORCED_COUNT_MAX_DOFS` DOFs.

    Parameters
    ----------
    case : Case
        The validated case (SI).
    vehicle : flexbooster.shell_of_revolution.Vehicle
        Its vehicle (:func:`flexbooster.model.vehicle_from_case`).
    """
    from .dynamics import basis_sizes
    from .model import forced_stations
    from .shell_of_revolution import mesh_vehicle

    t = case.thrust
    forced = 1 + (t.misalignment != 0.0)
    n_omega = 0 if t.spectrum is not None else t.n_omega
    top = (max(line.frequency for line in t.spectrum) if t.spectrum is not None
           else float(case.omega_grid().max()))
    n = mesh_vehicle(vehicle).n_full
    if n > FORCED_COUNT_MAX_DOFS:  # counting would cost what it prices: the bound
        return forced_seconds(vehicle, n_omega) * forced
    try:
        m = np.array(basis_sizes(vehicle, F0=case.F0, omega_max=top,
                                 stations=forced_stations(case, vehicle)[0]), dtype=float)
    except (ValueError, np.linalg.LinAlgError):
        return forced_seconds(vehicle, n_omega) * forced
    x = n / _FORCED_DOFS
    c_n, c_s, c_f, c_p, c_m, c_h = _C_FORCED_RUN
    mf = m[:forced]  # k = 0, and k = 1 with a misalignment
    fit = (c_n * x * x * max(1.0, x) + c_s * np.sum(m**3) + c_f * np.sum(mf**3)
           + c_p * np.sum(mf**2) * n_omega + c_m * np.sum(m) + c_h * forced)
    peaks = float(np.sum(mf * (_C_MODE_PEAK[0] + _C_MODE_PEAK[1] * mf))) if n_omega else 0.0
    return float(_FORCED_RUN_FLOOR + _FORCED_RUN_MARGIN * fit + peaks)


#: The flight's frozen times whose vehicle stages are estimated (:func:`flight_time_seconds`):
#: this many, equally spaced in index from the first to the last (each sample builds the
#: harmonics' modal systems: about 0.5-1 s for the default vehicle).
FLIGHT_SAMPLES = 3
# A frozen time builds its modes and harmonics with the thrust prestate, the labels and the
# liquid's operators shared across its harmonics: measured 0.19 (the flight example) and 0.26
# (the default case) of the "vehicle modes" and "vehicle regions" parts of a separate run;
# 0.4 taken (the searches and certificates are priced in full)
_FLIGHT_SHARED = 0.4
_FLIGHT_SHARED_PARTS = ("vehicle modes", "vehicle regions")


def flight_time_seconds(case: Any) -> float:
    """The predicted mean time (s, one core) of a frozen time of the flight
    (:mod:`flexbooster.flight_stage`): :func:`estimate_vehicle_cost` of the frozen case
    (:func:`flexbooster.model.frozen_case`: its fills, F0 and gamma over the flight's Omega
    range; no figures and no critical damping, which the flight does not compute; its modes and
    harmonic builds at 0.4 of a separate run's, shared across harmonics) at
    :data:`FLIGHT_SAMPLES` frozen times equally spaced in index, averaged over the frozen times
    by the trapezoidal rule (linear between the samples), plus the forced resonances of each
    time (k = 0, and k = 1 with a misalignment); 0 without ``[flight]``.

    Parameters
    ----------
    case : Case
        The validated case (SI).
    """
    return _flight_samples(case)[0]


def pass_over_seconds(case: Any) -> float:
    """The predicted time (s, one core) of the flight's searches outside its range, where a
    combination passes over it between frozen times (:mod:`flexbooster.flight_stage`): the
    windows :func:`flexbooster.flight.pass_over_windows` puts on the frequencies of the
    harmonics at the :data:`FLIGHT_SAMPLES` frozen times of :func:`flight_time_seconds`
    (linear in time between them), at most ``MAX_PASS_OVER_SEARCHES``, each priced as the
    search of that window (:func:`_pass_over_price`); 0 without ``[flight]``.

    Parameters
    ----------
    case : Case
        The validated case (SI).
    """
    return _flight_samples(case)[1]


def _flight_samples(case: Any) -> tuple[float, float]:
    """(:func:`flight_time_seconds`, :func:`pass_over_seconds`) from the same samples."""
    from .flight import flight_omega_range
    from .model import flight_times, frozen_case, timeline_from_case, vehicle_from_case
    from .shell_of_revolution import shared_harmonics

    times = flight_times(case)
    if times.size == 0:
        return 0.0, 0.0
    try:
        forced = _FLIGHT_FORCED * forced_seconds(vehicle_from_case(case), 0,
                                                 large_basis=False) * (
            1.0 + (case.thrust.misalignment != 0.0))
    except ValueError:  # a vehicle the mesh refuses: the stage says why
        return 0.0, 0.0
    samples = np.unique(np.linspace(0, times.size - 1, FLIGHT_SAMPLES).round().astype(int))

    def sample(i: int) -> tuple[float, dict]:  # another vehicle: its builds released after it
        with shared_harmonics(isolated=True):
            frozen = frozen_case(case, float(times[i]))
            try:  # one vehicle: the estimate's harmonics are the pass-over's
                vehicle = vehicle_from_case(frozen)
            except ValueError:  # a vehicle the mesh refuses: the stage says why
                return 0.0, {}
            parts = estimate_vehicle_cost(frozen, figures=False, vehicle=vehicle).parts
            harmonics = _pass_over_harmonics(frozen, vehicle) if times.size > 1 else {}
        return (sum(v * (_FLIGHT_SHARED if k in _FLIGHT_SHARED_PARTS else 1.0)
                    for k, v in parts.items() if k != CRITICAL_DAMPING_PART), harmonics)

    each, harmonics = zip(*(sample(int(i)) for i in samples), strict=True)
    mean = float(np.mean(np.interp(np.arange(times.size), samples, each)))
    lo, hi = flight_omega_range(timeline_from_case(case))
    outside = 0.0 if times.size < 2 else _pass_over_price(times, samples, harmonics, lo, hi)
    return mean + forced, outside


def _pass_over_harmonics(case: Any, vehicle: Any) -> dict[int, tuple]:
    """Per harmonic k of :func:`_sampled_harmonics` of a frozen case, as the flight stage builds
    it: (its steady frequencies in rad/s, ascending; the kinds of resonance that can open a
    region; the periodic system at the case's gamma; the price of its search's work;
    searched, i.e. not certified stable by damping), built on ``vehicle`` (the case's). The
    harmonics that cannot be built are left out."""
    from . import floquet
    from .dynamics import bending_harmonic, harmonic_system
    from .dynamics.harmonic import LIMIT_ERRORS
    from .shell_of_revolution import BucklingError

    t, zeta = case.thrust, case.vehicle_damping_ratio
    k_max = case.vehicle.k_max if case.vehicle is not None else 0
    out: dict[int, tuple] = {}
    try:
        n_modes = region_modes(case, vehicle, k_max=max(k_max, 1))[0]
    except ValueError:  # a vehicle the mesh refuses: the stage says why
        return out
    for k in (int(k) for k in _sampled_harmonics(k_max)) if k_max >= 1 else ():
        try:
            if k == 1:
                h = bending_harmonic(vehicle, F0=case.F0, n_modes=max(n_modes, 3),
                                     damping_ratio=zeta, gimbal_gain=t.K)
            else:
                h = harmonic_system(vehicle, k, F0=case.F0, n_modes=n_modes,
                                    damping_ratio=zeta, unloaded_frequencies=False)
            system = h.periodic(t.gamma)
            w = np.sort(floquet.steady_frequencies(system[0], system[2]).real)
            kinds = floquet.resonance_kinds(*system)
            searched = zeta == 0.0 or not floquet.stability_certificate(*system).certified
        except (*LIMIT_ERRORS, BucklingError, ValueError):
            continue
        price = (undamped_search_seconds if zeta == 0.0 else shell_search_seconds if k > 1
                 else lambda work: bending_search_steps(work, damping_ratio=zeta)[1])
        out[k] = (w, kinds, system, price, searched)
    return out


def _pass_over_price(times: np.ndarray, samples: np.ndarray, harmonics: Sequence[dict],
                     lo: float, hi: float) -> float:
    """The flight's searches outside [lo, hi] (:func:`pass_over_seconds`) predicted from the
    harmonics of frozen times ``samples`` (:func:`_pass_over_harmonics`): each harmonic's
    frequencies linear in time between the samples (by rank), its pass-over windows where the
    stage puts them (:func:`flexbooster.flight.pass_over_windows`; a step searched where the
    nearest sample of either end is), each priced as the search of that window in the nearest
    sample's system (:func:`_work_seconds`); the harmonics between the sampled ones linear in
    k (their windows and prices); scaled down to ``MAX_PASS_OVER_SEARCHES`` windows when
    more (the stage searches no more)."""
    from .flight import MAX_PASS_OVER_SEARCHES, pass_over_windows

    sample_times = times[samples]
    nearest = np.argmin(np.abs(times[:, None] - sample_times[None, :]), axis=1)
    ks = sorted(k for k in set().union(*harmonics) if all(k in h for h in harmonics))
    if not ks:  # no harmonic the stage can build at every sample: it says why
        return 0.0
    windows: dict[tuple[int, int], list] = {}
    for k in ks:
        n = max(h[k][0].size for h in harmonics)
        f = np.full((len(harmonics), n), np.nan)
        for row, h in zip(f, harmonics, strict=True):
            row[:h[k][0].size] = h[k][0]
        at = np.column_stack([np.interp(times, sample_times, c) for c in f.T])

        def kinds_at(s: int, k: int = k) -> tuple[str, ...]:
            ends = [harmonics[nearest[i]][k] for i in (s, s + 1)]
            return tuple(set().union(*(e[1] for e in ends))) if any(e[4] for e in ends) else ()

        spans = pass_over_windows(times, at, lo, hi, kinds_at=kinds_at)[1]
        windows.update({(t, k): v for t, v in spans.items()})
    per_k = {k: [0, 0.0] for k in ks}  # windows and their price, per sampled harmonic
    for (t, k), v in windows.items():
        per_k[k][0] += len(v)
        per_k[k][1] += sum(_work_seconds(harmonics[nearest[t]][k][2], a, b,
                                         harmonics[nearest[t]][k][3]) for a, b in v)
    every = np.arange(ks[0], ks[-1] + 1)
    n, seconds = (float(np.sum(np.interp(every, ks, [per_k[k][i] for k in ks])))
                  for i in (0, 1))
    return seconds * min(1.0, MAX_PASS_OVER_SEARCHES / n) if n > 0.0 else 0.0


def combined(*estimates: CostEstimate) -> CostEstimate:
    """The estimates of stages that run one after the other, as one (parts by name).

    Parameters
    ----------
    *estimates : CostEstimate
        Estimates with distinct part names.
    """
    parts, drivers = {}, {}
    for e in estimates:
        parts.update(e.parts)
        drivers.update(e.drivers)
    return CostEstimate(seconds=float(sum(e.seconds for e in estimates)), parts=parts,
                        drivers=drivers,
                        capped_points=sum(e.capped_points for e in estimates),
                        capped_omega_max=max((e.capped_omega_max for e in estimates),
                                             default=0.0))


def with_flight(case: Any, vehicle: CostEstimate) -> CostEstimate:
    """``vehicle`` (:func:`estimate_vehicle_cost`) with the part "flight": the frozen times
    (:func:`flexbooster.model.flight_times`) times :func:`flight_time_seconds`, and the part
    :data:`PASS_OVER_PART` (:func:`pass_over_seconds`).

    Parameters
    ----------
    case : Case
        The validated case (SI).
    vehicle : CostEstimate
        The vehicle stages' estimate.
    """
    from .model import flight_times

    n = int(flight_times(case).size)
    if n == 0:
        return vehicle
    each, outside = _flight_samples(case)
    seconds = n * each
    return CostEstimate(seconds=vehicle.seconds + seconds + outside,
                        parts={**vehicle.parts, "flight": seconds,
                               PASS_OVER_PART: outside},
                        drivers={**vehicle.drivers,
                                 "flight": ("flight.stations", "flight.times", "vehicle.k_max",
                                            "vehicle.n_modes", "vehicle.segments"),
                                 PASS_OVER_PART: ("flight.stations", "vehicle.n_modes",
                                                  "damping.modal_ratio")},
                        capped_points=vehicle.capped_points,
                        capped_omega_max=vehicle.capped_omega_max)
