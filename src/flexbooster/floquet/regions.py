"""Instability regions in Omega of M q'' + C q' + (A + B cos Omega t) q = 0, and their
amplitude dependence.

Regions grow out of the analytic candidates 2 omega_i / j and (omega_i +- omega_k) / j, never
from a grid: a smooth indicator per candidate, positive exactly where its multipliers leave
the unit circle, is maximised near the centre and both edges are refined on its zero; regions
below the indicators' round-off floor go to :mod:`.narrow`; with damping the undamped regions
seed the search of max log|rho| > 0. Theory: docs/theory/floquet.md.

References: V. V. Bolotin, *The Dynamic Stability of Elastic Systems*, 1964, ch. 1-2, sec. 6;
C. S. Hsu, J. Appl. Mech. 30 (1963) 367-372; W. Magnus, S. Winkler, *Hill's Equation*, 1966;
K. Takahashi, J. Sound Vib. 78 (1981) 519-529.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field

import numpy as np

from .bounds import stability_certificate
from .multipliers import (
    MAX_STEPS,
    LinearPeriodicSystem,
    PeriodMapOverflowError,
    half_period_maps,
    largest_multiplier,
    period_maps,
    periodic_system,
    s_matrices,
    s_value_sets,
    step_counts,
)
from .narrow import narrow_search
from .optimize import brent_max, expand_bracket, golden_section_max, illinois_root

__all__ = ["DAMPING_MARGIN", "TooManyCandidatesError", "InstabilityRegion", "instability_regions",
           "resonance_kinds", "RESONANCE_KINDS",
           "RegionBoundary", "region_boundaries", "CriticalAmplitude", "critical_amplitude",
           "SearchWork", "search_work", "OPEN_DAMPING_FRACTION"]

#: The kinds of resonance centre: 2 omega_i / j, (omega_i + omega_k) / j, |omega_k - omega_i| / j.
RESONANCE_KINDS = ("simple", "sum", "difference")


class TooManyCandidatesError(ValueError):
    """The resonance candidates to examine exceed ``max_candidates`` (omega_min too small for the
    frequencies): a search past a size limit, not a wrong argument.
    """
#: Round-off floor of the indicators (s-values are O(1), eigenvalue errors ~ eps ||S||): a
#: maximum below it is not a region.  Detection limit: relative width ~ 2 sqrt(floor) / (pi j).
_F_FLOOR = 1e-14
#: Candidates whose estimated width is below 1e-2 x this (relative) are not examined by the
#: harmonic-balance pair of :mod:`.narrow`: 1e-14, its reporting floor ``narrow.MIN_WIDTH``.
_NARROW_FLOOR = 1e-12
#: A monodromy candidate whose indicator maximum is below -_F_SCREEN has no region (its pair
#: of s-values stays 1e-6 apart, far beyond the integration error): not re-examined.
_F_SCREEN = 1e-6
#: Centres closer than this (relative) coincide (2 w_2 = w_1 + w_3 in exact arithmetic): the
#: window of each reaches to the nearest other, distinct centre.
_COINCIDENT = 1e-12
#: Smallest half-window (relative to the centre) of the narrow-region search.
_NARROW_WINDOW = 1e-3
#: Safety factor of the damping filter (see :func:`_damping_caps`): a candidate is examined
#: when margin x its first-order growth-rate bound exceeds the decay rate of its modes.
DAMPING_MARGIN = 4.0


@dataclass(frozen=True)
class InstabilityRegion:
    """One instability region Omega in (omega_lo, omega_hi) (Bolotin 1964; Hsu 1963).

    Attributes
    ----------
    omega_lo, omega_hi, omega_at_max, omega_center : float
        Edges (|rho|_max = 1), where the growth is largest, the analytic centre (rad per time
        unit of the matrices).
    growth_rate_max : float
        Largest log|rho|_max / T inside (1 / time unit).
    kind, modes, order : str, tuple of int, int
        "simple", "sum", "difference" or "steady" (unstable steady system: the whole range);
        the modes (ascending frequency) and j.
    clipped : bool
        An edge is an end of the range asked for.
    """

    omega_lo: float
    omega_hi: float
    growth_rate_max: float
    omega_at_max: float
    kind: str
    modes: tuple[int, ...]
    order: int
    omega_center: float
    clipped: bool = False

    @property
    def width(self) -> float:
        """omega_hi - omega_lo."""
        return self.omega_hi - self.omega_lo

    def to_dict(self) -> dict:
        """JSON-ready mapping."""
        return {"omega_lo": float(self.omega_lo), "omega_hi": float(self.omega_hi),
                "growth_rate_max": float(self.growth_rate_max),
                "omega_at_max": float(self.omega_at_max), "kind": self.kind,
                "modes": [int(m) for m in self.modes], "order": int(self.order),
                "omega_center": float(self.omega_center), "clipped": bool(self.clipped)}


@dataclass(frozen=True)
class _Options:
    rtol: float
    step_phase: float
    max_steps: int
    max_order: int | None
    max_candidates: int
    chunk: int
    damping_margin: float | None = DAMPING_MARGIN


def _options(rtol=1e-9, step_phase=0.12, max_steps=MAX_STEPS, max_order=None,
             max_candidates=200_000, chunk=256,
             damping_margin=DAMPING_MARGIN) -> _Options:
    if not (np.isfinite(rtol) and 1e-14 <= rtol <= 1e-2):
        raise ValueError(f"rtol = {rtol!r}: must be in 1e-14..1e-2")
    if max_order is not None and (not isinstance(max_order, int | np.integer)
                                  or not 1 <= max_order <= 10_000):
        raise ValueError(f"max_order = {max_order!r}: must be None or an integer in 1..10000")
    if not isinstance(max_candidates, int | np.integer) or max_candidates < 1:
        raise ValueError(f"max_candidates = {max_candidates!r}: must be an integer >= 1")
    if not isinstance(max_steps, int | np.integer) or max_steps < 8:
        raise ValueError(f"max_steps = {max_steps!r}: must be an integer >= 8")
    if not isinstance(chunk, int | np.integer) or chunk < 1:
        raise ValueError(f"chunk = {chunk!r}: must be an integer >= 1")
    if not (np.isfinite(step_phase) and step_phase > 0.0):
        raise ValueError(f"step_phase = {step_phase!r}: must be finite and > 0")
    if damping_margin is not None and (
            isinstance(damping_margin, bool)
            or not isinstance(damping_margin, int | float | np.floating | np.integer)
            or not np.isfinite(damping_margin) or damping_margin < 1.0):
        raise ValueError(f"damping_margin = {damping_margin!r}: must be None or a finite "
                         "number >= 1")
    return _Options(float(rtol), float(step_phase), int(max_steps), max_order,
                    int(max_candidates), int(chunk),
                    None if damping_margin is None else float(damping_margin))


def _range(omega_min, omega_max) -> tuple[float, float]:
    for name, v in (("omega_min", omega_min), ("omega_max", omega_max)):
        if not isinstance(v, int | float | np.floating | np.integer) or not np.isfinite(v) \
                or v <= 0.0:
            raise ValueError(f"{name} = {v!r}: must be finite and > 0")
    if omega_min >= omega_max:
        raise ValueError(f"omega_min = {omega_min!r}: must be < omega_max = {omega_max!r}")
    return float(omega_min), float(omega_max)


# --------------------------------------------------------------------------------------------
# Candidates
# --------------------------------------------------------------------------------------------
def _damping_caps(w, Bt, base, kind, i0, k0, zrow, zeta, rate, margin, jmax) -> np.ndarray:
    """Largest order j per resonance base that damping could leave unstable (0: none).

    The averaged equations couple with H_ab = |Bt_ab| / (4 sqrt(w_a w_b)); the undamped growth is
    at most the largest row sum R_a (Gershgorin), order j >= 2 at most base zeta_i zeta_k
    zeta^(j-2) / 4 times the small-denominator factors of :func:`_internal_resonance` (up to
    :data:`_CAP_SCAN` order beyond the cap without them, at most ``jmax``); kept while margin
    x growth exceeds min(delta_i, delta_k) (Hsu 1963).
    """
    with np.errstate(divide="ignore", invalid="ignore"):
        H = np.abs(Bt) / (4.0 * np.sqrt(np.outer(w, w)))
    H = np.where(np.isfinite(H), H, np.inf)
    R = np.sum(H, axis=1)
    d = np.minimum(rate[i0], rate[k0])
    lam2 = base * zrow[i0] * zrow[k0] / 4.0  # j = 2 (and the path part of j = 1)
    lam1 = np.maximum(np.maximum(R[i0], R[k0]), lam2)
    cap = np.where(margin * lam1 > d, 1, 0).astype(np.int64)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):  # t = inf: no j >= 2
        t = d / (margin * lam2)  # j >= 2 kept while zeta^(j-2) > t
        if zeta < 1.0:
            L = np.where(t < 1.0, np.log(np.maximum(t, 1e-300)) / np.log(zeta), -1.0)
            cap = np.where(t < 1.0, 1 + np.ceil(np.minimum(L, 1e9)), cap).astype(np.int64)
        else:
            cap = np.where(t < 1.0, np.iinfo(np.int64).max // 4, cap)
    if 0.0 < zeta < 1.0:
        cap = _internal_resonance(w, base, kind, i0, k0, zeta, d / margin, lam2, cap, jmax)
    return np.where(d > 0.0, cap, np.iinfo(np.int64).max // 4)


#: Orders beyond the damping cap that :func:`_internal_resonance` examines (one: the damped
#: survey of scripts/region_search_survey.py has no miss with 1, 2 or 4; each order more adds
#: candidates between the gimbaled pitch and bending at low Omega, 234 -> 269, 299 and 304 on
#: the two-stage liquid example's k = 1), and the largest cap it raises (above it the coupling
#: is strong enough that orders decay slowly anyway).
_CAP_SCAN, _CAP_SCAN_MAX = 1, 64


def _internal_resonance(w, base, kind, i0, k0, zeta, floor, lam2, cap, jmax) -> np.ndarray:
    """The damping caps raised where an order's chain passes near a mode (small denominators).

    The order-j term of a resonance couples j times through the intermediate frequencies
    nu_p = w_i - p Omega_c (sum and simple; w_lo + p Omega_c for a difference), p = 1..j-1; a
    mode m with w_m near |nu_p| multiplies it by a_p = w_m^2 / |w_m^2 - nu_p^2| (the response
    of mode m off resonance, against the w_m^2 that zeta assumes: the near-resonant terms of
    the perturbation series, Nayfeh & Mook 1979, ch. 5), each factor at most 1 / zeta (there
    the chain is as strong as a lower order). Order j (2 <= j <= min(cap + :data:`_CAP_SCAN`,
    jmax), cap <= :data:`_CAP_SCAN_MAX`) is kept while lam2 zeta^(j-2) prod a_p exceeds
    ``floor``.
    """
    rows = np.flatnonzero((cap < jmax) & (cap <= _CAP_SCAN_MAX))
    if rows.size == 0 or w.size == 0:
        return cap
    out = cap.copy()
    w2 = (w * w)[None, None, :]
    log_floor = np.log(np.maximum(floor[rows], 1e-300)) - np.log(np.maximum(lam2[rows], 1e-300))
    start = np.maximum(out[rows], 1)
    lo_mode = np.where(w[i0[rows]] <= w[k0[rows]], i0[rows], k0[rows])
    sign = np.where(kind[rows] == 2, 1.0, -1.0)
    first = np.where(kind[rows] == 2, w[lo_mode], w[i0[rows]])
    for extra in range(1, _CAP_SCAN + 1):
        j = np.maximum(start + extra, 2)
        step = max(1, 4_000_000 // max(w.size * int(j.max()), 1))
        for s in range(0, rows.size, step):  # batches of bounded memory
            c = slice(s, s + step)
            p = np.arange(1, int(j[c].max()))[None, :]
            nu = first[c, None] + sign[c, None] * p * (base[rows[c]] / j[c])[:, None]
            with np.errstate(divide="ignore", invalid="ignore"):
                a = w2 / np.abs(w2 - (nu * nu)[:, :, None])
            a = np.max(np.where(np.isnan(a), 1.0, a), axis=2)  # 0 / 0: a rigid mode at nu = 0
            log_a = np.where(p < j[c, None], np.log(np.clip(a, 1.0, 1.0 / zeta)), 0.0)
            kept = ((j[c] - 2) * np.log(zeta) + log_a.sum(axis=1) > log_floor[c]) & (
                j[c] <= jmax[rows[c]])
            out[rows[c]] = np.where(kept, np.maximum(out[rows[c]], j[c]), out[rows[c]])
    return out


def _candidates(w: np.ndarray, Bt: np.ndarray, lo: float, hi: float, opt: _Options,
                rate: np.ndarray | None = None, canonical: bool = False) -> dict:
    """Analytic centres in [lo, hi] with their first-order width estimates.

    Arrays kind (0 simple, 1 sum, 2 difference), i, k, j, centre, est, gap (distance to the
    nearest other centre of any order in [lo / 2, 2 hi]), mono, c_i and c_k (the s-values
    a combination indicator pairs), e_i and e_k (those of its second search when the first
    found nothing; both :func:`_pair_sizes`), retry (a combination candidate
    with more of them: searched again if the first pass finds nothing), and the window searched by
    the monodromy, middle +- half; the rows ``shifted`` are further windows of candidates
    moved by the second-order frequency shifts or split by a near resonance
    (:func:`_shifted_copies`). Orders suppressed
    by damping (:func:`_damping_caps`) or below the floor are not enumerated; more than
    ``opt.max_candidates`` kept raises :class:`TooManyCandidatesError`. A ``canonical`` system
    (:class:`.multipliers.LinearPeriodicSystem`) has no difference candidates: at
    (omega_k - omega_i) / j the colliding multipliers are of the same Krein kind and stay on
    the unit circle (Krein 1955; Yakubovich and Starzhinskii 1975, ch. VI); their centres still
    bound the other candidates' windows (``gap``).
    """
    n = w.size
    ii, kk = np.triu_indices(n, 1)
    base = np.concatenate([2.0 * w, w[ii] + w[kk], np.abs(w[kk] - w[ii])])
    kind0 = np.concatenate([np.zeros(n, int), np.ones(ii.size, int), np.full(ii.size, 2)])
    i0 = np.concatenate([np.arange(n), ii, ii])
    k0 = np.concatenate([np.arange(n), kk, kk])
    ok = base > 1e-12 * max(float(np.max(w)), 1e-300)
    base, kind0, i0, k0 = base[ok], kind0[ok], i0[ok], k0[ok]
    wt = np.maximum(w, 0.5 * lo)
    Z = np.abs(Bt) / np.outer(wt, wt)
    zeta = float(np.max(Z))
    zrow = np.max(np.maximum(Z, Z.T), axis=1)
    # all orders whose centre lies in [lo / 2, 2 hi] (for the gaps), capped
    jmax_all = np.floor(base / (0.5 * lo)).astype(np.int64)
    if rate is not None and opt.damping_margin is not None:
        jmax_all = np.minimum(jmax_all, _damping_caps(w, Bt, base, kind0, i0, k0, zrow, zeta,
                                                      rate, opt.damping_margin, jmax_all))
    jmin_all = np.maximum(1, np.ceil(base / (2.0 * hi)).astype(np.int64))
    # enumerated: the orders up to the last whose width estimate can pass the floor below
    # (est / centre = zeta_i zeta_k zeta^(j-2) >= 1e-2 _NARROW_FLOOR; 3 orders of slack)
    jhi = np.minimum(jmax_all, _order_cap(zrow[i0] * zrow[k0], zeta, opt.max_order))
    counts = np.maximum(0, jhi - jmin_all + 1)
    parts, kept = [], 0
    for sel in _batches(counts, _ENUMERATION_BATCH) if counts.size else (np.arange(0),):
        c = _enumerate(sel, counts[sel], jmin_all[sel], base, kind0, i0, k0, w, Bt, zrow,
                       zeta, lo, hi, opt, canonical)
        kept += c["j"].size
        if kept > opt.max_candidates:
            raise TooManyCandidatesError(
                f"omega_min = {lo!r}: more than max_candidates = {opt.max_candidates} "
                "resonance candidates to examine (omega_min too small for the frequencies)")
        parts.append(c)
    out = {key: np.concatenate([p[key] for p in parts]) for key in parts[0]}
    out["gap"] = _gaps(out.pop("base"), out["j"], out["centre"], base, jmin_all, jmax_all)
    Oc = out["centre"]
    # the window: no other centre inside (the pair indicator stays unimodal), at least the
    # estimated width; a lone candidate (gap = inf: no other centre in [lo / 2, 2 hi]) within
    # (0.5, 1.9) Oc
    out["middle"] = Oc.copy()
    with np.errstate(over="ignore"):  # est near the largest float: the cap
        out["half"] = np.maximum(0.45 * np.minimum(out["gap"], 2.0 * Oc),
                                 np.minimum(2.0 * out["est"], 0.2 * Oc / out["j"]))
    out["shifted"] = np.zeros(Oc.size, bool)
    out = _shifted_copies(out, w, Bt, lo, hi, opt)
    for m, other in (("i", "k"), ("k", "i")):
        out["c_" + m], out["e_" + m] = _pair_sizes(w, out[m], out[other], out)
    # the combination candidates a second pass searches again if the first finds nothing
    out["retry"] = (out["kind"] != 0) & ((out["e_i"] > out["c_i"]) | (out["e_k"] > out["c_k"]))
    return out


def _pair_sizes(w: np.ndarray, mode: np.ndarray, partner: np.ndarray,
                cand: dict) -> tuple[np.ndarray, np.ndarray]:
    """Per candidate, the s-values its combination indicator pairs about the prediction
    p = 2 cos(2 pi w / Omega) of its ``mode`` (:func:`_indicator`), each at most
    :data:`_CLUSTER_MAX`: (c, e).

    c: its cluster, the modes within j est of the frequency of ``mode`` (itself included; est
    near the largest float: every mode). e: those of the search of a candidate that found
    nothing (:func:`_undamped_search`): its cluster and every mode m other than its
    ``partner`` whose prediction equals its own where a region of the candidate can lie
    (w_m -+ w = q Omega, q >= 1, within twice the estimated width of the centre, or in a
    second window), and in a second window (the s-values moved far from their predictions)
    at least the two nearest: a complex s and its conjugate are equally near a real
    prediction."""
    cluster = np.empty(mode.size, dtype=np.int64)
    out = np.empty(mode.size, dtype=np.int64)
    est, j, middle, shifted = cand["est"], cand["j"], cand["middle"], cand["shifted"]
    with np.errstate(over="ignore"):
        reach = np.where(shifted, cand["half"], np.minimum(cand["half"], 2.0 * est))
    step = max(1, _ENUMERATION_BATCH // max(w.size, 1))
    for s in range(0, mode.size, step):  # batches of bounded memory
        c = slice(s, s + step)
        rows = np.arange(mode[c].size)
        wi = w[mode[c]][:, None]
        a = np.maximum(middle[c] - reach[c], 1e-300)[:, None]
        b = (middle[c] + reach[c])[:, None]
        with np.errstate(invalid="ignore", over="ignore"):
            near = np.abs(w[None, :] - wi) <= (est[c] * j[c])[:, None]
            near[rows, mode[c]] = True
            cluster[c] = near.sum(axis=1)
            for x in (np.abs(w[None, :] - wi), w[None, :] + wi):
                meet = np.floor(x / a) >= np.maximum(np.ceil(x / b), 1.0)
                meet[rows, partner[c]] = False
                near |= meet
        out[c] = np.maximum(near.sum(axis=1), np.where(shifted[c], min(2, w.size), 1))
    return np.minimum(cluster, _CLUSTER_MAX), np.minimum(out, _CLUSTER_MAX)


def _shifted_frequencies(w: np.ndarray, Bt: np.ndarray, i: np.ndarray, Omega: np.ndarray,
                         centre: np.ndarray) -> np.ndarray:
    """Second-order frequencies w~_i of the modes ``i`` at Omega, w~_i^2 = w_i^2 -
    (1/4) sum_k Bt_ik Bt_ki sum_+- 1 / (w_k^2 - (w_i +- Omega)^2) (averaging of the
    non-resonant terms; for one mode Mathieu's nu^2 = a - q^2 / (2 (a - 1)), DLMF 28.15.1),
    without the terms resonant at the analytic ``centre`` (w_k = |w_i +- centre| to 1e-9: the
    candidate's own first-order resonance); NaN where w~_i^2 <= 0."""
    out = np.empty(i.size)
    step = max(1, _ENUMERATION_BATCH // max(w.size, 1))
    for s in range(0, i.size, step):  # batches of bounded memory
        m, Om, Oc = i[s:s + step], Omega[s:s + step, None], centre[s:s + step, None]
        bb = Bt[m, :] * Bt[:, m].T  # Bt_ik Bt_ki
        wi, wk2 = w[m][:, None], w[None, :] ** 2
        total = np.zeros(m.size)
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            for sign in (1.0, -1.0):
                resonant = np.abs(wk2 - (wi + sign * Oc) ** 2) <= 1e-9 * wk2
                total += np.sum(np.where(resonant, 0.0, bb / (wk2 - (wi + sign * Om) ** 2)),
                                axis=1)
            w2 = w[m] ** 2 - 0.25 * total
            out[s:s + step] = np.where(np.isfinite(w2) & (w2 > 0.0), np.sqrt(np.abs(w2)),
                                       np.nan)
    return out


def _shifted_copies(cand: dict, w: np.ndarray, Bt: np.ndarray, lo: float, hi: float,
                    opt: _Options) -> dict:
    """``cand`` with a second window (``shifted`` rows, the analytic centre kept) for each
    monodromy candidate whose estimated width is above :func:`_indicator_floor` and whose
    centre, moved by the second-order frequency shifts (:func:`_shifted_frequencies` at the
    moved centre, two fixed-point steps), lies outside the inner half of its window, by at
    most :data:`_MAX_SHIFT` of the centre. The window reaches from the analytic centre to the
    moved one (the estimate overshoots near a small denominator), widened by twice the
    estimated width (at most 0.2 Oc / j) on both sides, clipped to [lo, hi]. Also ``shifted``
    rows: the windows of a region split by a near resonance (:func:`_branch_windows`)."""
    floor = _indicator_floor(cand["j"].astype(float), opt.rtol)
    mono = np.nonzero(cand["mono"] & (cand["est"] >= floor * cand["centre"]))[0]
    if mono.size == 0:
        return cand
    kind, i, k, j = (cand[key][mono] for key in ("kind", "i", "k", "j"))
    Oc = cand["centre"][mono]
    Om = Oc
    for _ in range(2):
        Om = _moved_centre(w, Bt, kind, i, k, j, Om, Oc)
    shift = np.abs(Om - Oc)
    # NaN (no second-order frequency): no copy; est near the largest float: the cap
    with np.errstate(invalid="ignore", over="ignore"):
        far = (shift > 0.5 * cand["half"][mono]) & (shift <= _MAX_SHIFT * Oc)
        est = np.minimum(2.0 * cand["est"][mono], 0.2 * Oc / j)
        a = np.maximum(np.minimum(Om, Oc) - est, lo)
        b = np.minimum(np.maximum(Om, Oc) + est, hi)
        far &= b > a
    row, ba, bb = _branch_windows(w, Bt, kind, i, k, j, Oc, cand["est"][mono],
                                  cand["half"][mono], lo, hi)
    sel = np.concatenate([mono[far], mono[row]])
    if sel.size == 0:
        return cand
    a, b = np.concatenate([a[far], ba]), np.concatenate([b[far], bb])
    copy = {key: v[sel] for key, v in cand.items()}
    copy["middle"] = 0.5 * (a + b)
    copy["half"] = 0.5 * (b - a)
    copy["shifted"] = np.ones(sel.size, bool)
    return {key: np.concatenate([cand[key], copy[key]]) for key in cand}


def _moved_centre(w, Bt, kind, i, k, j, Omega, centre) -> np.ndarray:
    """The candidates' centres from the second-order frequencies at Omega
    (:func:`_shifted_frequencies`): 2 w~_i / j, (w~_i + w~_k) / j or |w~_k - w~_i| / j."""
    wi, wk = (_shifted_frequencies(w, Bt, m, Omega, centre) for m in (i, k))
    return np.where(kind == 0, 2.0 * wi, np.where(kind == 1, wi + wk, np.abs(wk - wi))) / j


#: Chebyshev points per interval between poles at which the moved-centre equation is sampled
#: for a sign change (:func:`_branch_windows`), and bisection steps on each change found (a
#: bracket of at most 1e-2 Oc to 1e-8 Oc).
_BRANCH_SAMPLES, _BRANCH_BISECTIONS = 16, 20


def _branch_windows(w, Bt, kind, i, k, j, Oc, est, half, lo, hi) -> tuple:
    """Windows of a candidate split by the poles of its second-order frequencies.

    A pole is an Omega where a mode m resonates with mode i of the candidate (w_m =
    |w_i +- Omega|, :func:`_shifted_frequencies`): near it the centre moves by more than the
    second-order terms can say, and a region of the candidate may be split in two, one part on
    either side (e.g. a principal region of mode i on both sides of w_m - w_i). For the poles
    inside Oc (1 +- :data:`_MAX_SHIFT`) whose term, at the distance d of the pole from Oc,
    moves the centre by more than a quarter of the estimated width (|Bt_im Bt_mi| /
    (8 j w_i w_m d) > est / 4; for each mode i of the candidate):

    * the window Oc +- ``half``, cut at the poles inside it: one window per piece (the pair
      indicator may have a maximum on either side);
    * on each interval between poles that does not hold Oc, every root of Omega = the moved
      centre (:func:`_moved_centre`; a sign change among :data:`_BRANCH_SAMPLES` Chebyshev
      points, then bisection): a window from the pole to the root, widened beyond it by
      min(2 est, 0.2 Oc / j).

    Windows clipped to [lo, hi]. Returns (rows of the candidates given, lower and upper window
    edges).
    """
    n = w.size
    out = [(np.zeros(0, int), np.zeros(0), np.zeros(0))]
    t = 0.5 * (1.0 - np.cos(np.pi * (np.arange(_BRANCH_SAMPLES) + 0.5) / _BRANCH_SAMPLES))
    step = max(1, _ENUMERATION_BATCH // (4 * max(n, 1) * _BRANCH_SAMPLES))
    for s in range(0, Oc.size, step):  # batches of bounded memory
        c = np.arange(s, min(s + step, Oc.size))
        poles = np.concatenate([np.abs(w[None, :] - w[i[c], None]), w[None, :] + w[i[c], None],
                                np.abs(w[None, :] - w[k[c], None]), w[None, :] + w[k[c], None]],
                               axis=1)
        # the pole's reach: its term moves the centre by |Bt_am Bt_ma| / (8 j w_a w_m d) at a
        # distance d from it, more than a quarter of the estimated width within the reach
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            ci, ck = (np.abs(Bt[a, :] * Bt[:, a].T) / np.outer(w[a], w) for a in (i[c], k[c]))
            reach = np.concatenate([ci, ci, ck, ck], axis=1) / (2.0 * j[c, None]
                                                                * est[c, None])
        d = np.abs(poles - Oc[c, None])
        inside = (d < np.minimum(reach, _MAX_SHIFT * Oc[c, None])) & (d > 1e-9 * Oc[c, None])
        inside[:, 2 * n:] &= kind[c, None] != 0  # a simple candidate: mode i's poles once
        poles = np.sort(np.where(inside, poles, np.inf), axis=1)
        m = np.arange(poles.shape[1])[None, :] < inside.sum(axis=1)[:, None]
        if not m.any():
            continue
        cc = np.broadcast_to(c[:, None], poles.shape)[m]  # one entry per pole
        p = poles[m]
        nxt = np.concatenate([poles[:, 1:], np.full((c.size, 1), np.inf)], axis=1)[m]
        prv = np.concatenate([np.full((c.size, 1), -np.inf), poles[:, :-1]], axis=1)[m]
        # the window cut at its poles: the piece below each pole inside it, and the piece
        # above the highest one
        w_lo, w_hi = Oc[cc] - half[cc], Oc[cc] + half[cc]
        cut = (p > w_lo) & (p < w_hi)
        top = cut & ~(nxt < w_hi)
        out.append((np.concatenate([cc[cut], cc[top]]),
                    np.concatenate([np.maximum(prv, w_lo)[cut], p[top]]),
                    np.concatenate([p[cut], w_hi[top]])))
        # the interval on each pole's side away from Oc: the roots of the moved centre
        up = p > Oc[cc]
        a = np.where(up, p, np.maximum(prv, Oc[cc] * (1.0 - _MAX_SHIFT)))
        b = np.where(up, np.minimum(nxt, Oc[cc] * (1.0 + _MAX_SHIFT)), p)
        pts = a[:, None] + (b - a)[:, None] * t[None, :]
        rep = np.repeat(cc, _BRANCH_SAMPLES)
        g = pts - _moved_centre(w, Bt, kind[rep], i[rep], k[rep], j[rep], pts.ravel(),
                                Oc[rep]).reshape(pts.shape)
        with np.errstate(invalid="ignore"):
            r_, s_ = np.nonzero(g[:, :-1] * g[:, 1:] < 0.0)
        if r_.size == 0:
            continue
        xa, xb, ga, gb = pts[r_, s_], pts[r_, s_ + 1], g[r_, s_], g[r_, s_ + 1]
        cb = cc[r_]
        for _ in range(_BRANCH_BISECTIONS):
            xm = 0.5 * (xa + xb)
            gm = xm - _moved_centre(w, Bt, kind[cb], i[cb], k[cb], j[cb], xm, Oc[cb])
            left = np.sign(gm) == np.sign(ga)
            xa, ga = np.where(left, xm, xa), np.where(left, gm, ga)
            xb, gb = np.where(left, xb, xm), np.where(left, gb, gm)
        root = 0.5 * (xa + xb)
        e = np.minimum(2.0 * est[cb], 0.2 * Oc[cb] / j[cb])
        with np.errstate(invalid="ignore", over="ignore"):
            ok = np.isfinite(gb)  # a bracket closed on a NaN (no frequency) is no root
        out.append((cb[ok], np.where(up[r_], a[r_], root - e)[ok],
                    np.where(up[r_], root + e, b[r_])[ok]))
    rows, wa, wb = (np.concatenate(v) for v in zip(*out, strict=True))
    wa, wb = np.maximum(wa, lo), np.minimum(wb, hi)
    keep = wb > wa
    return rows[keep], wa[keep], wb[keep]


#: The largest relative shift of a centre given a second window (:func:`_shifted_copies`).
_MAX_SHIFT = 0.05


def _indicator_floor(j: np.ndarray, rtol: float) -> np.ndarray:
    """Relative width below which the monodromy indicators of order ``j`` cannot tell a region
    from round-off: at a tangency F ~ -kappa (dOmega)^2, so 2 sqrt(_F_FLOOR) / (pi j), and at
    least the edge tolerance ``rtol`` (docs/theory/floquet.md sec. 6)."""
    return np.maximum(rtol, 2.0 * np.sqrt(_F_FLOOR) / (np.pi * j))


#: Resonance candidates enumerated at once (:func:`_candidates`).
_ENUMERATION_BATCH = 1 << 20


def _order_cap(p: np.ndarray, zeta: float, max_order: int | None) -> np.ndarray:
    """Largest order j whose width estimate p zeta^(j-2) Omega_c can reach the narrow floor
    1e-2 _NARROW_FLOOR Omega_c (3 orders of slack for round-off; at least 2)."""
    big = np.iinfo(np.int64).max // 4
    cap = np.full(p.size, big if max_order is None else int(max_order), dtype=np.int64)
    if 0.0 < zeta < 1.0:
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            L = np.log(1e-2 * _NARROW_FLOOR / p) / np.log(zeta)
        L = np.where(p > 0.0, np.minimum(np.nan_to_num(L, nan=0.0), 1e15), 0.0)
        cap = np.minimum(cap, np.maximum(2, 5 + np.floor(L)).astype(np.int64))
    elif zeta == 0.0:
        cap = np.minimum(cap, 2)
    return cap


def _batches(counts: np.ndarray, size: int):
    """Consecutive index ranges of ``counts`` whose sums are at most ``size`` (or one entry)."""
    start, csum = 0, np.cumsum(counts)
    while start < counts.size:
        before = csum[start - 1] if start else 0
        stop = max(start + 1, int(np.searchsorted(csum, before + size, side="right")))
        yield np.arange(start, min(stop, counts.size))
        start = stop


def _enumerate(sel, counts, jmin, base, kind0, i0, k0, w, Bt, zrow, zeta, lo, hi,
               opt, canonical=False) -> dict:
    """The candidates of the bases ``sel``, orders jmin.. (``counts`` each), that are kept (no
    difference candidate of a ``canonical`` system: :func:`_candidates`)."""
    total = int(np.sum(counts))
    rep = np.repeat(sel, counts)
    offs = np.arange(total) - np.repeat(np.cumsum(counts) - counts, counts)
    j = np.repeat(jmin, counts) + offs
    centre = base[rep] / j
    kind, i, k = kind0[rep], i0[rep], k0[rep]
    # width estimates: first order (Bolotin sec. 3 for simple, Hsu 1963 for combinations);
    # order j: a product of j couplings along a path i -> ... -> k, bounded by
    # Omega_c zeta_i zeta_k zeta^(j-2) with zeta_ab = |Bt_ab| / (w~_a w~_b), w~ = max(w, lo/2)
    # (small denominators through slow modes are kept), zeta_i = max_b zeta_ib
    jf = j.astype(float)
    with np.errstate(over="ignore"):  # couplings above the frequencies: est = inf, kept
        est = centre * zrow[i] * zrow[k] * zeta ** np.maximum(jf - 2.0, 0.0)
    first = np.where(kind == 0, np.abs(Bt[i, i]) / w[i],
                     np.sqrt(np.abs(Bt[i, k] * Bt[k, i]) / (w[i] * w[k])))
    est = np.where(j == 1, np.maximum(first, est), est)
    # regions narrower than the round-off floor of the indicators cannot be told from zero by
    # the monodromy ("mono" candidates: est above it); the narrower ones down to the floor of
    # the harmonic-balance pair (:mod:`.narrow`, resolution linear in the width) are kept too
    floor = _indicator_floor(jf, opt.rtol)
    keep = (centre >= lo * (1.0 - 1e-9)) & (centre <= hi * (1.0 + 1e-9))
    with np.errstate(over="ignore", invalid="ignore"):
        keep |= (centre + 2.0 * est >= lo) & (centre - 2.0 * est <= hi)
    keep &= est >= 1e-2 * _NARROW_FLOOR * centre
    if opt.max_order is not None:
        keep &= j <= opt.max_order
    if canonical:
        keep &= kind != 2
    mono = est >= 1e-2 * floor * centre
    return {"kind": kind[keep], "i": i[keep], "k": k[keep], "j": j[keep],
            "centre": centre[keep], "est": est[keep], "mono": mono[keep], "base": rep[keep]}


def _gaps(own: np.ndarray, j: np.ndarray, centre: np.ndarray, base: np.ndarray,
          jmin: np.ndarray, jmax: np.ndarray) -> np.ndarray:
    """Distance from each centre (base ``own``, order j) to the nearest other centre
    base[m] / j' of every base m and order jmin[m] <= j' <= jmax[m]: the orders nearest to
    base[m] / centre (b / j' is monotone in j'), in batches of bounded memory."""
    gap = np.full(centre.size, np.inf)
    empty = jmax < jmin
    step = max(1, _ENUMERATION_BATCH // max(4 * base.size, 1))
    for s in range(0, centre.size, step):
        c, o, jo = centre[s:s + step, None], own[s:s + step, None], j[s:s + step, None]
        jf = np.floor(np.minimum(base[None, :] / c, 2.0**62)).astype(np.int64)
        for d in (-1, 0, 1, 2):
            jj = np.clip(jf + d, jmin[None, :], np.maximum(jmax, jmin)[None, :])
            dist = np.abs(c - base[None, :] / jj)
            dist[empty[None, :] | ((np.arange(base.size)[None, :] == o) & (jj == jo))] = np.inf
            dist[dist <= _COINCIDENT * c] = np.inf  # a coincident centre shares the window
            gap[s:s + step] = np.minimum(gap[s:s + step], np.min(dist, axis=1))
    return gap


# --------------------------------------------------------------------------------------------
# Indicators (vectorised over candidates)
# --------------------------------------------------------------------------------------------
def _s_values(system: LinearPeriodicSystem, om: np.ndarray, opt: _Options) -> tuple:
    """(s, s - 2, s + 2) at om (see :func:`.multipliers.s_value_sets`)."""
    return s_value_sets(_half_maps_at(system, om, opt))


def _half_maps_at(system: LinearPeriodicSystem, om: np.ndarray, opt: _Options) -> np.ndarray:
    """Phi(T/2) at om with the search's step counts."""
    steps = step_counts(system, om, step_phase=opt.step_phase, max_steps=opt.max_steps)
    return half_period_maps(system, om, steps, chunk=opt.chunk)


def _s_matrices_at(system, om, opt) -> tuple:
    """:func:`.multipliers.s_matrices` of the half-period maps at om;
    :class:`.multipliers.PeriodMapOverflowError` where a map is singular to working precision
    (finite entries, but a growth over half a period beyond floating point)."""
    try:
        return s_matrices(_half_maps_at(system, om, opt))
    except np.linalg.LinAlgError:
        raise PeriodMapOverflowError(
            f"Omega = {float(np.min(om))!r}..{float(np.max(om))!r}: the half-period map is "
            "singular to working precision (growth over half a period beyond floating point)",
            float(np.min(om))) from None


def _indicator(system, w, cand, om, opt) -> np.ndarray:
    """F per candidate at om; each point decomposes only the one matrix of
    :func:`.multipliers.s_matrices` it needs (s, s - 2 or s + 2).
    """
    mats = _s_matrices_at(system, om, opt)
    P = om.size
    rows = np.arange(P)
    simple = cand["kind"] == 0
    sig = np.where(cand["j"] % 2 == 0, 1.0, -1.0)
    which = np.where(simple, np.where(sig > 0.0, 1, 2), 0)  # S, Xp (s - 2) or Xm (s + 2)
    ev = np.empty((P, mats[0].shape[-1]), dtype=complex)
    for m, mat in enumerate(mats):
        sel = np.nonzero(which == m)[0]
        if sel.size:
            ev[sel] = np.linalg.eigvals(mat[sel])
    # the s of each mode is tracked from its gamma -> 0 value 2 cos(2 pi omega / Omega)
    p_i = 2.0 * np.cos(2.0 * np.pi * w[cand["i"]] / om)
    p_k = 2.0 * np.cos(2.0 * np.pi * w[cand["k"]] / om)
    # simple: F = (-1)^j Re s_i - 2 > 0 where s_i is real beyond +-2 (rho = +-1 at F = 0),
    # taken from the shifted set s -+ 2 (no cancellation); a complex s_i belongs to a
    # combination pair: F <= -|Im s_i| there
    near = np.argmin(np.abs(ev + 2.0 * sig[:, None] - p_i[:, None]), axis=1)
    x_i = ev[rows, near]  # s - 2 sigma
    f_simple = sig * x_i.real  # sigma (s - 2 sigma) = sigma s - 2
    f_simple = np.where(x_i.imag == 0.0, f_simple, np.minimum(f_simple, -np.abs(x_i.imag)))
    if ev.shape[1] >= 2:
        # combination: the s nearest to each prediction; F = -Re (s_a - s_b)^2 > 0 where the
        # pair is complex (left |rho| = 1), 0 where it collides on |rho| = 1. A mode m nearly
        # degenerate with i (|w_m - w_i| <= j est: its combination centre with k within the
        # estimated width) has an s near the same prediction, and so for k: a among the c_i s
        # nearest to p_i, b among the c_k nearest to p_k (other than a; c <= _CLUSTER_MAX),
        # the largest F
        first = np.argmin(np.abs(ev - p_i[:, None]), axis=1)
        d_k = np.abs(ev - p_k[:, None])
        d_k[rows, first] = np.inf
        second = np.argmin(d_k, axis=1)
        f_comb = -((ev[rows, first] - ev[rows, second]) ** 2).real
        c_i, c_k = cand["c_i"], cand["c_k"]  # :func:`_pair_sizes`
        many = np.nonzero((~simple) & ((c_i > 1) | (c_k > 1)))[0]
        if many.size:
            f_comb[many] = _cluster_pairs(ev[many], p_i[many], p_k[many], c_i[many], c_k[many])
    else:
        f_comb = np.full(P, -1.0)
    return np.where(simple, f_simple, f_comb)


#: The most s-values near one prediction that a combination indicator pairs (a strongly
#: coupled candidate's estimated width can span every mode; :func:`_indicator`).
_CLUSTER_MAX = 4


def _cluster_pairs(ev, p_i, p_k, c_i, c_k) -> np.ndarray:
    """max -Re (s_a - s_b)^2 over a among the c_i s-values ``ev`` nearest to p_i and b among
    the c_k nearest to p_k other than a (per row)."""
    rows = np.arange(ev.shape[0])
    order_i = np.argsort(np.abs(ev - p_i[:, None]), axis=1, kind="stable")
    order_k = np.argsort(np.abs(ev - p_k[:, None]), axis=1, kind="stable")
    out = np.full(ev.shape[0], -np.inf)
    for ai in range(min(int(c_i.max()), ev.shape[1])):
        a = order_i[:, ai]
        pos = np.argmax(order_k == a[:, None], axis=1)  # a's place in order_k
        for bk in range(min(int(c_k.max()) + 1, ev.shape[1])):
            b = order_k[:, bk]
            ok = (ai < c_i) & (bk != pos) & (bk - (pos < bk) < c_k)
            out = np.where(ok, np.maximum(out, -((ev[rows, a] - ev[rows, b]) ** 2).real), out)
    return out


def _unstable_indicator(system, om, opt) -> np.ndarray:
    """U > 0 exactly where the undamped system is unstable, U = 0 on |rho|_max = 1:
    U = max(max_a |Re s_a| - 2, max_{a<b} -Re (s_a - s_b)^2) - floor (floor: round-off).
    """
    s, xp, xm = _s_values(system, om, opt)
    # |s| - 2 from the shifted sets: s - 2 where Re s >= 0, -(s + 2) where Re s < 0
    up = np.where((xp.real + 2.0) >= 0.0, xp.real, -np.inf)
    um = np.where((xm.real - 2.0) < 0.0, -xm.real, -np.inf)
    u = np.maximum(np.max(up, axis=1), np.max(um, axis=1))
    n = s.shape[1]
    if n >= 2:
        a, b = np.triu_indices(n, 1)
        u = np.maximum(u, np.max(-((s[:, a] - s[:, b]) ** 2).real, axis=1))
    return u - _F_FLOOR


def _growth_undamped(system, om, opt) -> np.ndarray:
    _, Xp, Xm = _s_matrices_at(system, om, opt)
    rho = largest_multiplier(np.linalg.eigvals(Xp), np.linalg.eigvals(Xm))
    return np.log(rho) * om / (2.0 * np.pi)  # log|rho|_max / T


def _growth_damped(system, om, opt, amplitude=None) -> np.ndarray:
    steps = step_counts(system, om, step_phase=opt.step_phase, max_steps=opt.max_steps)
    rho = np.linalg.eigvals(period_maps(system, om, steps, chunk=opt.chunk,
                                        amplitude=amplitude))
    return np.log(np.max(np.abs(rho), axis=1)) * om / (2.0 * np.pi)  # log|rho|_max / T


def _edges(f, x0: np.ndarray, f0: np.ndarray, d0: np.ndarray, direction,
           limit: np.ndarray, xtol: np.ndarray, scale: np.ndarray,
           max_rounds: int = 6) -> tuple[np.ndarray, np.ndarray]:
    """First boundary from x0 (f(x0) > 0) in ``direction``: bracket, refine, then check 8 points
    between (64 beyond 4 ``scale``) for a stable gap jumped over, up to ``max_rounds``.
    Returns (root, clipped).
    """
    xi, fi, xo, fo, clip = expand_bracket(f, x0, f0, d0, direction, limit)
    root = np.where(clip, limit, xo)

    def refine(idx, a, fa, b, fb):
        return illinois_root(lambda x, act: f(x, idx[act]), a, fa, b, fb, xtol[idx])

    idx = np.nonzero(~clip)[0]
    if idx.size:
        root[idx] = refine(idx, xi[idx], fi[idx], xo[idx], fo[idx])
    check = np.ones(root.size, dtype=bool)  # entries whose root is new: the others passed
    for _ in range(max_rounds):
        redo_all = []
        for n_check, sel in ((8, np.abs(root - x0) <= 4.0 * scale),
                             (64, np.abs(root - x0) > 4.0 * scale)):
            ids = np.nonzero(sel & check)[0]
            if ids.size == 0:
                continue
            frac = np.arange(1, n_check + 1) / (n_check + 1.0)
            pts = x0[ids, None] + (root - x0)[ids, None] * frac[None, :]
            fp = f(pts.ravel(), np.repeat(ids, n_check)).reshape(pts.shape)
            gap = fp <= 0.0
            bad = np.nonzero(np.any(gap, axis=1))[0]
            if bad.size == 0:
                continue
            first = np.argmax(gap[bad], axis=1)
            prev = np.maximum(first - 1, 0)
            b = pts[bad, first]
            fb = fp[bad, first]
            a = np.where(first > 0, pts[bad, prev], x0[ids[bad]])
            fa = np.where(first > 0, fp[bad, prev], f0[ids[bad]])
            redo_all.append((ids[bad], a, fa, b, fb))
        if not redo_all:
            return root, clip
        check[:] = False
        for redo, a, fa, b, fb in redo_all:
            root[redo] = refine(redo, a, fa, b, fb)
            clip[redo] = False
            check[redo] = True
    return root, clip


#: Seeds of the damped search (:func:`_seed_edges`): each undamped edge to this fraction of
#: the region's width (the damped search samples the seed interval and marches out from its
#: damped maximum, so the seed's edges need not be |rho| = 1 points to rtol).
_SEED_WIDTH_FRACTION = 1e-3


def _seed_edges(f, x0: np.ndarray, f0: np.ndarray, d0: np.ndarray, limit: np.ndarray,
                xtol: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Both edges of each region about x0 to a fraction of its width (entries 0..P-1 down,
    P..2P-1 up). Returns (edges, clipped).
    """
    P = x0.size
    direction = np.concatenate([-np.ones(P), np.ones(P)])
    X0, F0, D0 = (np.concatenate([v, v]) for v in (x0, f0, d0))

    def width(xi):
        w_in = np.abs(xi[P:] - xi[:P])
        return np.concatenate([w_in, w_in])

    return _coarse_edges(f, X0, F0, D0, direction, limit, np.concatenate([xtol, xtol]), width)


def _coarse_edges(f, X0, F0, D0, direction, limit, XT, width) -> tuple[np.ndarray, np.ndarray]:
    """The first sign change of f from X0 along ``direction`` (a march, then Illinois) to
    _SEED_WIDTH_FRACTION of ``width(x_in)`` (or XT). Returns (edges, clipped)."""
    xi, fi, xo, fo, clip = expand_bracket(f, X0, F0, D0, direction, limit)
    for _ in range(40):  # each round cuts the brackets by 100 at least
        goal = np.maximum(XT, _SEED_WIDTH_FRACTION * width(xi))
        act = np.nonzero(~clip & (np.abs(xo - xi) > goal))[0]
        if act.size == 0:
            break
        tol = np.maximum(goal[act], 1e-2 * np.abs(xo - xi)[act])
        xi[act], fi[act], xo[act], fo[act] = illinois_root(
            lambda x, a, act=act: f(x, act[a]), xi[act], fi[act], xo[act], fo[act], tol,
            bracket=True)
    return np.where(clip, limit, 0.5 * (xi + xo)), clip


# --------------------------------------------------------------------------------------------
# The search
# --------------------------------------------------------------------------------------------
def _steady_check(system: LinearPeriodicSystem):
    """(stable, growth, unstable modes) of the steady system (B = 0)."""
    n = system.n
    L0 = np.block([[np.zeros((n, n)), np.eye(n)], [-system.K0, -system.Kc]])
    lam = np.linalg.eigvals(L0)
    scale = max(float(np.max(np.abs(lam))), 1e-300)
    mu = system.mu
    bad = (np.abs(mu.imag) > 1e-10 * max(float(np.max(np.abs(mu))), 1e-300)) | (mu.real <= 0.0)
    growth = float(np.max(lam.real))
    unstable = bool(np.any(bad)) or growth > 1e-12 * scale
    return not unstable, max(growth, 0.0) + 0.0, tuple(int(m) for m in np.nonzero(bad)[0])


def _modal_decay_rates(system: LinearPeriodicSystem) -> np.ndarray | None:
    """First-order modal decay rates delta_a = Re (V^-1 M^-1 C V)_aa / 2 (1/time unit); exact for
    modal damping.
    """
    if system.V is None:
        return None
    Ct = np.linalg.solve(system.V, system.Kc @ system.V)
    return 0.5 * np.real(np.diag(Ct))


#: Work arrays of the monodromy candidates evaluated at once (bytes; :func:`_undamped_search`).
_SEARCH_BATCH_BYTES = 1 << 28


def _undamped_search(system, w, cand, lo, hi, opt, narrow: bool = True,
                     seeds: bool = False) -> list[dict]:
    """Regions of the undamped system for the candidate table, as dicts; ``seeds``: the seeds of
    the damped search (edges by :func:`_seed_edges`, no narrow pass).
    """
    if cand["centre"].size == 0:
        return []
    mono = cand["mono"]
    sub = {key: v[mono] for key, v in cand.items()}
    regs, fmax = _batched_search(system, w, sub, lo, hi, opt, seeds)
    # the combination candidates that found nothing, again with more s-values paired
    # (:func:`_pair_sizes`): the regions outside every one found
    again = (fmax <= _F_FLOOR) & sub["retry"]
    if again.any():
        retry = {key: v[again] for key, v in sub.items()}
        retry["c_i"], retry["c_k"] = retry["e_i"], retry["e_k"]
        regs += [r for r in _batched_search(system, w, retry, lo, hi, opt, seeds)[0]
                 if not _overlaps(r, regs)]
    if not narrow or seeds:
        return regs
    # the candidates below the monodromy floor, and those whose indicator maximum stayed
    # between -_F_SCREEN and the round-off floor (a pair that approaches within 1e-6 in s)
    extra = (fmax <= _F_FLOOR) & (fmax > -_F_SCREEN) & ~sub["shifted"]
    missed = {key: np.concatenate([v[~mono], v[mono][extra]]) for key, v in cand.items()}
    return regs + _narrow_pass(system, missed, regs, lo, hi)


def _overlaps(r: dict, regs: list[dict]) -> bool:
    """Region ``r`` meets one of ``regs`` (closed intervals lo..hi)."""
    return any(r["lo"] <= q["hi"] and q["lo"] <= r["hi"] for q in regs)


def _batched_search(system, w, cand, lo, hi, opt, seeds: bool) -> tuple[list[dict], np.ndarray]:
    """:func:`_monodromy_search` of the candidate table in batches of bounded memory, then of
    the rest of the windows where it found a region (:func:`_rest_of_windows`)."""
    regs, fmax = _plain_batches(system, w, cand, lo, hi, opt, seeds)
    regs += _rest_of_windows(system, w, cand, regs, lo, hi, opt, seeds)
    for r in regs:
        r.pop("row")
    return regs, fmax


def _plain_batches(system, w, cand, lo, hi, opt, seeds) -> tuple[list[dict], np.ndarray]:
    """:func:`_monodromy_search` in batches; each region's "row" is its candidate's."""
    regs, fmax = [], [np.zeros(0)]
    step = max(1, _SEARCH_BATCH_BYTES // (256 * system.n ** 2))  # 4 complex 2n x 2n each
    for s in range(0, cand["centre"].size, step):  # batches: each candidate on its own
        r, f = _monodromy_search(system, w, {key: v[s:s + step] for key, v in cand.items()},
                                 lo, hi, opt, seeds=seeds)
        for x in r:
            x["row"] += s
        regs += r
        fmax.append(f)
    return regs, np.concatenate(fmax)


#: Rounds of :func:`_rest_of_windows` (each searches the pieces the last one split).
_WINDOW_ROUNDS = 2


def _rest_of_windows(system, w, cand, regs, lo, hi, opt, seeds) -> list[dict]:
    """Regions in the rest of a window where the search found one: a window may hold several
    (a strongly coupled cluster: the s-value nearest a prediction changes with Omega), and the
    maximisation stops at the first point above the floor. The window less the region found
    (4 x the edge tolerance beyond its edges) is searched again, piece by piece, in at most
    :data:`_WINDOW_ROUNDS` rounds; pieces shorter than a tenth of the estimated width or 8 x
    the edge tolerance are left. The regions kept lie outside every region found before."""
    Oc, half, est = cand["middle"], cand["half"], cand["est"]
    a_win = np.maximum(Oc - half, 0.5 * Oc)
    b_win = Oc + half
    out, found = [], list(regs)
    cluster = (cand["c_i"] > 1) | (cand["c_k"] > 1)
    pieces = [(r["row"], a_win[r["row"]], b_win[r["row"]], r) for r in regs if cluster[r["row"]]]
    for _ in range(_WINDOW_ROUNDS):
        rows, lefts, rights = [], [], []
        for m, a, b, r in pieces:
            gap = 4.0 * opt.rtol * Oc[m]
            for left, right in ((a, min(b, r["lo"] - gap)), (max(a, r["hi"] + gap), b)):
                if right - left > max(8.0 * opt.rtol * Oc[m], 0.1 * est[m]):
                    rows.append(m)
                    lefts.append(left)
                    rights.append(right)
        if not rows:
            break
        idx = np.array(rows)
        sub = {key: v[idx] for key, v in cand.items()}
        left, right = np.array(lefts), np.array(rights)
        sub["middle"], sub["half"] = 0.5 * (left + right), 0.5 * (right - left)
        new, _ = _plain_batches(system, w, sub, lo, hi, opt, seeds)
        pieces = []
        for r in new:
            if _overlaps(r, found):
                continue
            piece = int(r["row"])
            r["row"] = int(idx[piece])
            pieces.append((r["row"], left[piece], right[piece], r))
            found.append(r)
            out.append(r)
    return out


def _narrow_pass(system, cand, regs, lo, hi) -> list[dict]:
    """Regions narrower than the monodromy's round-off floor (:mod:`.narrow`), as dicts, less
    those inside a region the monodromy found.
    """
    if cand["centre"].size == 0:
        return []
    Oc = cand["centre"]
    sub = dict(cand)
    # the window: to the next centre, at least the size of the second-order frequency shifts
    # (a pair's discriminant is its own: another centre inside does not disturb it)
    sub["window"] = np.minimum(np.maximum(0.45 * cand["gap"], _NARROW_WINDOW * Oc),
                               0.2 * Oc / cand["j"])
    res = narrow_search(system.mu.real, system.Bt, sub)
    out = []
    for m in np.nonzero(res["found"] & res["converged"])[0]:
        a, b = float(res["lo"][m]), float(res["hi"][m])
        if b < lo or a > hi or any(r["lo"] <= a and b <= r["hi"] for r in regs):
            continue
        out.append({"lo": a, "hi": b, "kind": int(cand["kind"][m]), "i": int(cand["i"][m]),
                    "k": int(cand["k"][m]), "j": int(cand["j"][m]), "centre": float(Oc[m]),
                    "clipped": False, "growth": float(res["growth"][m]),
                    "at": float(res["omega_at_max"][m])})
    return out


def _monodromy_search(system, w, cand, lo, hi, opt,
                      seeds: bool = False) -> tuple[list[dict], np.ndarray]:
    """Regions found from the monodromy indicators (module docstring), and the maximum of
    each candidate's indicator (``seeds``: the edges by :func:`_seed_edges`)."""
    if cand["centre"].size == 0:
        return [], np.zeros(0)
    Oc = cand["middle"]
    xtol = opt.rtol * Oc

    def F(x, idx=None):
        sub = cand if idx is None else {key: v[idx] for key, v in cand.items()}
        return _indicator(system, w, sub, x, opt)

    delta = cand["half"]  # the window (:func:`_candidates`)
    a = np.maximum(Oc - delta, 0.5 * Oc)
    b = Oc + delta
    xs, fs = brent_max(F, a, b, Oc, np.maximum(10.0 * xtol, 1e-15 * Oc), stop_above=_F_FLOOR)
    hit = np.nonzero(fs > _F_FLOOR)[0]
    if hit.size == 0:
        return [], fs
    sub = {key: v[hit] for key, v in cand.items()}
    x0 = xs[hit]
    f0 = fs[hit]
    d0 = np.maximum(np.minimum(sub["est"], delta[hit]) / 4.0, 4.0 * xtol[hit])

    def Fo(x, idx):  # this candidate's own pair indicator
        return _indicator(system, w, {key: v[idx] for key, v in sub.items()}, x, opt)

    def U(x, idx):  # the whole system: unstable where > 0
        return _unstable_indicator(system, x, opt)

    scale = np.maximum(sub["est"], 4.0 * xtol[hit])
    out = []
    # both edges in one batch: entries 0..P-1 go down, P..2P-1 go up
    P = hit.size
    direction = np.concatenate([-np.ones(P), np.ones(P)])
    limit = np.concatenate([np.full(P, lo), np.full(P, hi)])
    X0, F0, D0 = (np.concatenate([v, v]) for v in (x0, f0, d0))
    XT, SC = np.concatenate([xtol[hit], xtol[hit]]), np.concatenate([scale, scale])
    if seeds:  # the damped search's seeds: each edge to a fraction of the width
        edge, clip = _seed_edges(lambda x, idx: Fo(x, idx % P), x0, f0, d0, limit, xtol[hit])
    else:  # stage 1: where this candidate's pair returns to |rho| = 1
        edge, clip = _edges(lambda x, idx: Fo(x, idx % P), X0, F0, D0, direction, limit, XT,
                            SC)
    # stage 2: if the system is still unstable just beyond (an overlapping region), go on to
    # the first Omega where it is stable: the boundary is |rho|_max = 1 (a seed then spans
    # the overlapping regions, inside which a damped region may lie beside its own)
    beyond = edge + direction * 4.0 * XT
    go = np.nonzero(~clip & (direction * (limit - beyond) > 0.0))[0]
    if go.size:
        u = U(beyond[go], None)
        go, u = go[u > 0.0], u[u > 0.0]
    if go.size and seeds:  # to a fraction of the seed's width, as its own edges
        span = np.abs(edge[P:] - edge[:P])[go % P]
        e2, c2 = _coarse_edges(lambda x, idx: U(x, None), beyond[go], u,
                               np.maximum(D0[go], 4.0 * XT[go]), direction[go], limit[go],
                               XT[go], lambda xi: np.abs(xi - beyond[go]) + span)
        edge[go], clip[go] = e2, c2
    elif go.size:
        e2, c2 = _edges(lambda x, idx: U(x, None), beyond[go], u,
                        np.maximum(D0[go], 4.0 * XT[go]), direction[go], limit[go], XT[go],
                        SC[go])
        edge[go], clip[go] = e2, c2
    olo, ohi, clo, chi = edge[:P], edge[P:], clip[:P], clip[P:]
    olo, ohi = np.maximum(olo, lo), np.minimum(ohi, hi)
    for m in range(hit.size):
        if ohi[m] - olo[m] <= xtol[hit][m] or ohi[m] <= lo or olo[m] >= hi:
            continue
        out.append({"lo": float(olo[m]), "hi": float(ohi[m]), "kind": int(sub["kind"][m]),
                    "i": int(sub["i"][m]), "k": int(sub["k"][m]), "j": int(sub["j"][m]),
                    "centre": float(sub["centre"][m]), "clipped": bool(clo[m] or chi[m]),
                    "row": int(hit[m])})
    return out, fs


def _damped_search(system, undamped, opt, lo, hi) -> list[dict]:
    """Regions with damping, seeded by the undamped regions; the marches go on to the ends of
    [lo, hi] (a damped region may be much wider than its seed, Hsu 1963); an edge is a point of
    log|rho|_max = 0 or an end of that range (``clipped``).
    """
    if not undamped:
        return []
    lo_u = np.array([r["lo"] for r in undamped])
    hi_u = np.array([r["hi"] for r in undamped])
    width = hi_u - lo_u
    nsamp = 9
    grid = lo_u[:, None] + width[:, None] * np.linspace(0.0, 1.0, nsamp)[None, :]
    g = _growth_damped(system, grid.ravel(), opt).reshape(grid.shape)
    best = np.argmax(g, axis=1)
    rows = np.arange(lo_u.size)
    a = grid[rows, np.maximum(best - 1, 0)]
    b = grid[rows, np.minimum(best + 1, nsamp - 1)]
    xtol = opt.rtol * 0.5 * (lo_u + hi_u)

    def G(x, idx=None):
        return _growth_damped(system, x, opt)

    xs, gs = golden_section_max(G, a, b, xtol=np.maximum(10.0 * xtol, 1e-15 * hi_u),
                                stop_above=0.0)

    def march(hit, x0, g0) -> list[dict]:
        # the marches go on to the ends of the (widened) range: a damped region may be much
        # wider than its undamped seed (a combination region with a nearly undamped mode: the
        # threshold detuning grows like sqrt(lambda^2 / (delta_i delta_k)), Hsu 1963), and an
        # edge is either a point of log|rho|_max = 0 or an end of the range (clipped)
        P = hit.size
        d0 = np.maximum(width[hit] / 16.0, 4.0 * xtol[hit])
        edge, clip = _edges(lambda x, idx: G(x), np.concatenate([x0, x0]),
                            np.concatenate([g0, g0]), np.concatenate([d0, d0]),
                            np.concatenate([-np.ones(P), np.ones(P)]),
                            np.concatenate([np.full(P, lo), np.full(P, hi)]),
                            np.concatenate([xtol[hit], xtol[hit]]),
                            np.concatenate([0.5 * width[hit], 0.5 * width[hit]]))
        found = []
        for m_, m in enumerate(hit):
            r = dict(undamped[m])
            r["lo"], r["hi"] = float(edge[m_]), float(edge[P + m_])
            r["clipped"] = bool(r["clipped"] or clip[m_] or clip[P + m_])
            found.append(r)
        return found

    hit = np.nonzero(gs > 0.0)[0]
    out = march(hit, xs[hit], gs[hit]) if hit.size else []
    # a seed's samples where the damped system is unstable outside every region found (the
    # damped parts of overlapping undamped regions may separate: two damped regions in one
    # seed): marched from the largest such sample of each seed, which the new region holds,
    # until every unstable sample lies in a region (at most nsamp rounds)
    for _ in range(nsamp):
        covered = np.zeros(grid.shape, dtype=bool)
        for r in out:
            covered |= (grid >= r["lo"]) & (grid <= r["hi"])
        left = np.where((g > 0.0) & ~covered, g, -np.inf)
        hit = np.nonzero(np.isfinite(left).any(axis=1))[0]
        if hit.size == 0:
            break
        pick = np.argmax(left[hit], axis=1)
        out += march(hit, grid[hit, pick], g[hit, pick])
    return out


def _finish(system, regions, lo, hi, opt, damped) -> tuple[InstabilityRegion, ...]:
    """Clip to the range, drop duplicates, maximise the growth rate inside each region."""
    regs = []
    quantum = 100.0 * opt.rtol * hi

    def order(r):  # by the lower edge (to the tolerance), then the lowest order first
        return (round(r["lo"] / quantum), r["j"], r["kind"])

    for r in sorted(regions, key=order):
        r = dict(r)
        if r["lo"] < lo:
            r["lo"], r["clipped"] = lo, True
        if r["hi"] > hi:
            r["hi"], r["clipped"] = hi, True
        if r["hi"] <= r["lo"]:
            continue
        tol = 10.0 * opt.rtol * r["hi"]
        if any(abs(q["lo"] - r["lo"]) <= tol and abs(q["hi"] - r["hi"]) <= tol for q in regs):
            continue  # the same region reached from two candidates
        regs.append(r)
    if not regs:
        return ()
    narrow = [r for r in regs if "growth" in r]  # from the harmonic-balance pair
    regs = [r for r in regs if "growth" not in r]
    out = [] if not regs else list(_finish_monodromy(system, regs, opt, damped))
    for r in narrow:
        modes = (r["i"],) if r["kind"] == 0 else (r["i"], r["k"])
        out.append(InstabilityRegion(
            omega_lo=r["lo"], omega_hi=r["hi"], growth_rate_max=r["growth"],
            omega_at_max=r["at"], kind=RESONANCE_KINDS[r["kind"]], modes=modes, order=r["j"],
            omega_center=r["centre"], clipped=r["clipped"]))
    return tuple(sorted(out, key=lambda q: (round(q.omega_lo / quantum), q.order,
                                            RESONANCE_KINDS.index(q.kind))))


def _finish_monodromy(system, regs, opt, damped) -> tuple[InstabilityRegion, ...]:
    """Growth-rate maxima of the monodromy regions (9 samples, then Brent)."""
    a = np.array([r["lo"] for r in regs])
    b = np.array([r["hi"] for r in regs])
    grow = _growth_damped if damped else _growth_undamped

    def G(x, idx=None):
        return grow(system, x, opt)

    nsamp = 9  # a region may be a union of overlapping ones: sample, then golden section
    grid = a[:, None] + (b - a)[:, None] * np.linspace(0.0, 1.0, nsamp)[None, :]
    gg = G(grid.ravel()).reshape(grid.shape)
    best = np.argmax(gg, axis=1)
    rows = np.arange(a.size)
    a2 = grid[rows, np.maximum(best - 1, 0)]
    b2 = grid[rows, np.minimum(best + 1, nsamp - 1)]
    xm, gm = brent_max(G, a2, b2, grid[rows, best], np.maximum(1e-4 * (b2 - a2), 1e-15 * b2))
    out = []
    for m, r in enumerate(regs):
        modes = (r["i"],) if r["kind"] == 0 else (r["i"], r["k"])
        out.append(InstabilityRegion(
            omega_lo=r["lo"], omega_hi=r["hi"], growth_rate_max=float(max(gm[m], 0.0)),
            omega_at_max=float(xm[m]), kind=RESONANCE_KINDS[r["kind"]], modes=modes, order=r["j"],
            omega_center=r["centre"], clipped=r["clipped"]))
    return tuple(out)


def _search(system: LinearPeriodicSystem, lo: float, hi: float, opt: _Options,
            select=None) -> tuple[InstabilityRegion, ...]:
    stable, growth, bad = _steady_check(system)
    if not stable:
        return (InstabilityRegion(omega_lo=lo, omega_hi=hi, growth_rate_max=growth,
                                  omega_at_max=lo, kind="steady", modes=bad, order=0,
                                  omega_center=lo, clipped=True),)
    undamped = system if not system.damped else dataclasses.replace(
        system, Kc=np.zeros_like(system.Kc), damped=False)
    if undamped.Bt is None:
        raise ValueError("A = the steady matrix M^-1 A is defective (no modal frame): "
                         "instability_regions needs distinct or semisimple eigenvalues")
    w = np.sqrt(system.mu.real)
    rate = None
    if system.damped and opt.damping_margin is not None:
        if stability_certificate(system, None, None, None).certified:  # stable at every Omega
            return ()
        rate = _modal_decay_rates(system)
    cand = _candidates(w, undamped.Bt, lo, hi, opt, rate=rate, canonical=system.canonical)
    if select is not None:
        keep = select(cand)
        cand = {key: v[keep] for key, v in cand.items()}
    if system.damped:  # seeds from the undamped system, searched a little wider
        # regions narrower than the monodromy floor (growth ~ width) are not looked for: damping
        # suppresses them unless the decay rate is below that growth
        regs = _undamped_search(undamped, w, cand, 0.5 * lo, 2.0 * hi, opt, narrow=False,
                                seeds=True)
        regs = _damped_search(system, regs, opt, 0.5 * lo, 2.0 * hi)
    else:
        regs = _undamped_search(undamped, w, cand, lo, hi, opt)
    return _finish(system, regs, lo, hi, opt, system.damped)


def resonance_kinds(M, C, A, B) -> tuple[str, ...]:
    """The kinds of resonance from whose centres :func:`instability_regions` looks for regions:
    ("simple", "sum") for a canonical system (M, A, B symmetric, M and A positive definite,
    :class:`.multipliers.LinearPeriodicSystem`), whose multipliers at a difference centre
    (omega_k - omega_i) / j collide with their own Krein kind and stay on the unit circle
    (Krein 1955; Yakubovich and Starzhinskii 1975, ch. VI); all three otherwise.

    Parameters
    ----------
    M, C, A, B : array_like
        As :func:`instability_regions`.
    """
    return RESONANCE_KINDS[:2] if periodic_system(M, C, A, B).canonical else RESONANCE_KINDS


def instability_regions(M, C, A, B, omega_min: float, omega_max: float, *,
                        rtol: float = 1e-9, step_phase: float = 0.12,
                        max_steps: int = MAX_STEPS, max_order: int | None = None,
                        max_candidates: int = 200_000, chunk: int = 256,
                        damping_margin: float | None = DAMPING_MARGIN,
                        ) -> tuple[InstabilityRegion, ...]:
    """Instability regions in Omega in [omega_min, omega_max], from the analytic candidates.

    Sorted by omega_lo; every edge a point of |rho|_max = 1 or an end of the range; overlaps as
    their union; regions below the indicators' floor (~6e-8 / j) from :mod:`.narrow` down to
    1e-14 of the centre; an unstable steady system one "steady" region.

    Parameters
    ----------
    M, C, A, B : array_like
        The system, each (n, n) (C may be None).
    omega_min, omega_max : float
        Range of Omega (rad per time unit of the matrices), 0 < omega_min < omega_max.
    rtol : float
        Edge tolerance relative to the candidate centre, 1e-14..1e-2.
    step_phase, max_steps, chunk
        Monodromy accuracy, cap and batch (:func:`.multipliers.monodromy`).
    max_order : int, optional
        Largest order j (default: every order whose estimated width exceeds 1e-3 rtol Omega_c).
    max_candidates : int
        Cap on the candidates examined (TooManyCandidatesError beyond it).
    damping_margin : float or None
        With damping, >= 1: no search where :func:`.bounds.stability_certificate` holds, and a
        candidate only where margin x its growth bound exceeds its modes' decay; None: all.
    """
    lo, hi = _range(omega_min, omega_max)
    opt = _options(rtol, step_phase, max_steps, max_order, max_candidates, chunk,
                   damping_margin)
    return _search(periodic_system(M, C, A, B), lo, hi, opt)


@dataclass(frozen=True)
class SearchWork:
    """What :func:`instability_regions` will integrate, known before it runs (a cost model).

    Attributes
    ----------
    n : int
        Degrees of freedom.
    steady, certified : bool
        The steady system is unstable, or damped and certified stable: no search.
    n_candidates, n_narrow : int
        Candidates examined by the monodromy and left to :mod:`.narrow`.
    undamped_steps, damped_steps : int
        Sums of the step counts at the candidate centres (each step ~n^3).
    n_open, open_steps : int
        Of a damped system, the candidates whose modes have no modal damping (their regions
        open at any amplitude, so their edges and critical amplitude are searched) and the
        sum of the damped system's step counts at their centres.
    undamped_max_steps : int
        The largest of the undamped step counts at the candidate centres: the candidates'
        indicators are integrated in one batch, which runs as long as its longest member.
    n_retry, retry_steps : int
        The combination candidates that a second pass searches again, with more s-values
        paired, if the first finds nothing (all of them counted: an upper bound), and the
        sum of the undamped step counts at their centres.
    canonical : bool
        The system is canonical (:class:`.multipliers.LinearPeriodicSystem`): its candidates
        are simple and sum ones only.
    pairs : tuple of (int, int)
        The modes (i, k) of each candidate examined by the monodromy (i = k: simple), in the
        system's modal order (:attr:`InstabilityRegion.modes` of the regions found).
    """

    n: int
    steady: bool
    certified: bool
    n_candidates: int
    n_narrow: int
    undamped_steps: int
    damped_steps: int
    n_open: int = 0
    open_steps: int = 0
    undamped_max_steps: int = 0
    n_retry: int = 0
    retry_steps: int = 0
    canonical: bool = False
    pairs: tuple = field(default=(), repr=False)

    def to_dict(self) -> dict:
        """JSON-ready mapping."""
        return {"n": int(self.n), "steady": bool(self.steady),
                "certified": bool(self.certified), "n_candidates": int(self.n_candidates),
                "n_narrow": int(self.n_narrow), "undamped_steps": int(self.undamped_steps),
                "damped_steps": int(self.damped_steps), "n_open": int(self.n_open),
                "open_steps": int(self.open_steps),
                "undamped_max_steps": int(self.undamped_max_steps),
                "n_retry": int(self.n_retry), "retry_steps": int(self.retry_steps),
                "canonical": bool(self.canonical),
                "pairs": [[int(i), int(k)] for i, k in self.pairs]}


#: A mode whose modal damping ratio is below this fraction of the largest counts as undamped
#: in :class:`SearchWork` (its candidates' regions open at almost any amplitude): a mode without
#: damping of its own (the gimbaled rigid pitch) gets some only through the coupling of the
#: modal frame, orders of magnitude below the damped modes' (1.4e-4 of it for the k = 1 pitch
#: of tests/data/gimbal_pitch_coupled_damping_case.toml).
OPEN_DAMPING_FRACTION = 1e-2


def search_work(M, C, A, B, omega_min: float, omega_max: float, **options) -> SearchWork:
    """The candidates and step counts of :func:`instability_regions`, without integrating (it
    raises as the search does).

    Parameters
    ----------
    M, C, A, B, omega_min, omega_max, **options
        As :func:`instability_regions`.
    """
    lo, hi = _range(omega_min, omega_max)
    opt = _options(**options)
    system = periodic_system(M, C, A, B)
    none = dict(n=system.n, steady=False, certified=False, n_candidates=0, n_narrow=0,
                undamped_steps=0, damped_steps=0, canonical=system.canonical)
    if not _steady_check(system)[0]:
        return SearchWork(**{**none, "steady": True})
    if system.Bt is None:
        raise ValueError("A = the steady matrix M^-1 A is defective (no modal frame): "
                         "instability_regions needs distinct or semisimple eigenvalues")
    undamped = system if not system.damped else dataclasses.replace(
        system, Kc=np.zeros_like(system.Kc), damped=False)
    rate = None
    if system.damped and opt.damping_margin is not None:
        if stability_certificate(system, None, None, None).certified:  # as _search: none
            return SearchWork(**{**none, "certified": True})
        rate = _modal_decay_rates(system)
    cand = _candidates(np.sqrt(system.mu.real), undamped.Bt, lo, hi, opt, rate=rate,
                       canonical=system.canonical)
    mono = cand["mono"]
    centres = cand["middle"][mono]
    steps_u = steps_d = steps_o = longest = 0
    retry = cand["retry"][mono]  # the candidates of the second pass (:func:`_candidates`)
    steps_r = 0
    # candidates between modes without damping of their own: damping ratio delta_a / w_a
    # below OPEN_DAMPING_FRACTION of the largest
    free = None
    if rate is not None:
        w = np.sqrt(np.abs(system.mu))
        ratio = np.divide(np.abs(rate), w, out=np.where(rate == 0.0, 0.0, np.inf), where=w > 0.0)
        free = ratio <= OPEN_DAMPING_FRACTION * np.max(ratio[np.isfinite(ratio)], initial=0.0)
    is_open = (np.zeros(centres.size, bool) if free is None
               else free[cand["i"][mono]] & free[cand["k"][mono]])
    if centres.size:
        counts_u = step_counts(undamped, centres, step_phase=opt.step_phase,
                               max_steps=opt.max_steps)
        steps_u, longest = int(np.sum(counts_u)), int(np.max(counts_u))
        steps_r = int(np.sum(counts_u[retry]))
        if system.damped:
            counts = step_counts(system, centres, step_phase=opt.step_phase,
                                 max_steps=opt.max_steps)
            steps_d, steps_o = int(np.sum(counts)), int(np.sum(counts[is_open]))
    return SearchWork(**{**none, "n_candidates": int(centres.size),
                         "n_narrow": 0 if system.damped else int(np.count_nonzero(~mono)),
                         "undamped_steps": steps_u, "damped_steps": steps_d,
                         "n_open": int(np.count_nonzero(is_open)), "open_steps": steps_o,
                         "undamped_max_steps": longest,
                         "n_retry": int(np.count_nonzero(retry)), "retry_steps": steps_r,
                         "pairs": tuple(zip(cand["i"][mono].tolist(), cand["k"][mono].tolist(),
                                            strict=True))})


# --------------------------------------------------------------------------------------------
# Amplitude dependence
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class CriticalAmplitude:
    """Smallest amplitude at which a region exists (B = gamma B1; Bolotin 1964, sec. 6).

    Attributes
    ----------
    kind, modes, order
        The region (:class:`InstabilityRegion`).
    gamma_cr, omega_cr : float
        The critical amplitude (0 without damping) and the Omega where the region appears.
    """

    kind: str
    modes: tuple[int, ...]
    order: int
    gamma_cr: float
    omega_cr: float

    def to_dict(self) -> dict:
        """JSON-ready mapping."""
        return {"kind": self.kind, "modes": [int(m) for m in self.modes],
                "order": int(self.order), "gamma_cr": float(self.gamma_cr),
                "omega_cr": float(self.omega_cr)}


@dataclass(frozen=True)
class RegionBoundary:
    """Boundary curves of one region in the (Omega, gamma) plane (B = gamma B1).

    Attributes
    ----------
    kind, modes, order
        The region (:class:`InstabilityRegion`).
    gamma, omega_lo, omega_hi : numpy.ndarray
        Amplitudes ascending from the critical one, and the edges there (rad per time unit).
    """

    kind: str
    modes: tuple[int, ...]
    order: int
    gamma: np.ndarray
    omega_lo: np.ndarray
    omega_hi: np.ndarray

    def to_dict(self) -> dict:
        """JSON-ready mapping."""
        return {"kind": self.kind, "modes": [int(m) for m in self.modes],
                "order": int(self.order), "gamma": self.gamma.tolist(),
                "omega_lo": self.omega_lo.tolist(), "omega_hi": self.omega_hi.tolist()}


def _gamma_max(gamma_max) -> float:
    if not isinstance(gamma_max, int | float | np.floating | np.integer) or not np.isfinite(
            gamma_max) or gamma_max <= 0.0:
        raise ValueError(f"gamma_max = {gamma_max!r}: must be finite and > 0")
    return float(gamma_max)


def _key(r) -> tuple:
    return (r.kind, r.modes, r.order)


def critical_amplitude(M, C, A, B1, *, gamma_max: float, omega_min: float, omega_max: float,
                       gamma_rtol: float = 1e-6, regions: tuple | None = None,
                       **options) -> tuple[CriticalAmplitude, ...]:
    """Critical amplitude of every non-steady region at gamma_max (B = gamma B1).

    With damping, g(gamma) = max_Omega log|rho|_max / T near the region is < 0 at 0 and > 0 at
    gamma_max; its root (Illinois, each g a Brent maximum) is where the two boundaries meet
    (Bolotin 1964, sec. 6). Without damping every region grows out of gamma = 0.

    Parameters
    ----------
    M, C, A, B1 : array_like
        The system with B = gamma B1 (see :func:`instability_regions`).
    gamma_max : float
        Largest amplitude, > 0.
    omega_min, omega_max : float
        Omega range (rad per time unit).
    gamma_rtol : float
        Tolerance relative to gamma_max, 1e-12..1e-2.
    regions : tuple of InstabilityRegion, optional
        The search at gamma_max with the same range and options, if known.
    **options
        As :func:`instability_regions`.
    """
    gmax = _gamma_max(gamma_max)
    lo, hi = _range(omega_min, omega_max)
    opt = _options(**options)
    if not (np.isfinite(gamma_rtol) and 1e-12 <= gamma_rtol <= 1e-2):
        raise ValueError(f"gamma_rtol = {gamma_rtol!r}: must be in 1e-12..1e-2")
    B1 = np.asarray(B1, dtype=float)
    base = periodic_system(M, C, A, gmax * B1)
    top = _search(base, lo, hi, opt) if regions is None else tuple(regions)
    top = tuple(r for r in top if r.kind != "steady")
    if not base.damped:
        return tuple(CriticalAmplitude(r.kind, r.modes, r.order, 0.0, r.omega_center)
                     for r in top)
    if not top:
        return ()
    c_cr, om_cr = _tips(base, top, opt, gamma_rtol)
    return tuple(CriticalAmplitude(r.kind, r.modes, r.order, float(c * gmax), float(o))
                 for r, c, o in zip(top, c_cr, om_cr, strict=True))


#: Monodromy step parameter of the tip search (:func:`_tips`), whatever the search's own.
_TIP_STEP_PHASE = 0.12
#: Omega tolerance of the growth maximum at each amplitude, relative to the region's width at
#: gamma_max (the growth is quadratic about its maximum: its error is ~1e-8 of the peak).
_TIP_OMEGA_XTOL = 1e-4
#: Samples across each region's Omega interval (ends included) besides the previous maximiser
#: and the candidate centre, before each Brent maximum of the tip search.
_TIP_SAMPLES = 5


def _tips(base: LinearPeriodicSystem, top, opt: _Options, gamma_rtol: float):
    """Critical amplitude factors c (B = c B_top) and Omega of the tips, all regions at once: the
    root of g(c) (g(0) < 0, g(1) > 0) by Illinois, each g a Brent maximum at _TIP_STEP_PHASE.
    """
    tip = _Options(rtol=opt.rtol, step_phase=min(opt.step_phase, _TIP_STEP_PHASE),
                   max_steps=opt.max_steps, max_order=opt.max_order,
                   max_candidates=opt.max_candidates, chunk=opt.chunk,
                   damping_margin=opt.damping_margin)
    a = np.array([r.omega_lo for r in top])
    b = np.array([r.omega_hi for r in top])
    xs = np.array([r.omega_at_max for r in top])
    centre = np.clip(np.array([r.omega_center for r in top]), a, b)
    xtol = np.maximum(_TIP_OMEGA_XTOL * (b - a), 1e-15 * b)
    grid = np.linspace(0.0, 1.0, _TIP_SAMPLES)

    def g(c, idx):
        def f(x, sub):
            return _growth_damped(base, x, tip, amplitude=c[idx][sub])

        # the start: the best of the previous maximiser, the candidate centre and a few
        # samples.  Outside the undamped region of amplitude c the growth is flat (the
        # modes' own decay); Brent started there converges on the plateau and misses a
        # narrow peak near the tip (the region at a small c is a narrow interval about the
        # centre: the first-order width is linear in c, its shift quadratic)
        starts = np.column_stack([xs[idx], centre[idx],
                                  a[idx, None] + (b - a)[idx, None] * grid[None, :]])
        m = starts.shape[1]
        fs = f(starts.ravel(), np.repeat(np.arange(idx.size), m)).reshape(starts.shape)
        x0 = starts[np.arange(idx.size), np.argmax(fs, axis=1)]
        x, gx = brent_max(f, a[idx], b[idx], x0, xtol[idx])
        xs[idx] = x
        return gx

    n = base.n
    L0 = np.block([[np.zeros((n, n)), np.eye(n)], [-base.K0, -base.Kc]])
    g0 = float(np.max(np.linalg.eigvals(L0).real))  # growth at c = 0 (steady), < 0
    P = len(top)
    every = np.arange(P)
    g1 = g(np.ones(P), every)
    c_in, f_in = np.ones(P), g1
    c_out, f_out = np.zeros(P), np.full(P, g0)
    pos = g1 > 0.0  # a region at gamma_max (always, unless given a stale table)
    c_cr = np.ones(P)
    if pos.any():
        ids = np.nonzero(pos)[0]
        c_vec = np.ones(P)
        # first a probe at the tolerance: a region that holds down to gamma_rtol (one of its
        # modes undamped: the threshold c^2 |H_ik H_ki| > delta_i delta_k is 0, Hsu 1963) has
        # its root in the final bracket [0, gamma_rtol] at once, not after ~log2(1 / gamma_rtol)
        # halvings from c = 1; the others get a nearer outer end than c = 0
        c_vec[ids] = gamma_rtol
        g_probe = g(c_vec, ids)
        low = g_probe > 0.0
        c_cr[ids[low]] = 0.5 * gamma_rtol  # the midpoint of that bracket, as illinois_root
        c_out[ids[~low]], f_out[ids[~low]] = gamma_rtol, g_probe[~low]
        rest = ids[~low]
        if rest.size:
            c_vec[rest] = 1.0

            def root_f(c, act):
                c_vec[rest[act]] = c
                return g(c_vec, rest[act])

            c_cr[rest] = illinois_root(root_f, c_in[rest], f_in[rest], c_out[rest],
                                       f_out[rest], np.full(rest.size, gamma_rtol))
        c_vec[ids] = c_cr[ids]
        g(c_vec, ids)  # the maximiser at the tip
    return c_cr, xs


def region_boundaries(M, C, A, B1, *, gamma_max: float, omega_min: float, omega_max: float,
                      n_gamma: int = 21, regions: tuple | None = None,
                      **options) -> tuple[RegionBoundary, ...]:
    """Boundary curves omega_lo(gamma), omega_hi(gamma) of every region at gamma_max: the regions
    at ``n_gamma`` amplitudes in (0, gamma_max] matched by (kind, modes, order), and the tip at
    the critical amplitude (Bolotin 1964, ch. 1).

    Parameters
    ----------
    M, C, A, B1, gamma_max, omega_min, omega_max, regions, **options
        As :func:`critical_amplitude`.
    n_gamma : int
        Amplitude levels, 2..1000.
    """
    gmax = _gamma_max(gamma_max)
    lo, hi = _range(omega_min, omega_max)
    if isinstance(n_gamma, bool) or not isinstance(n_gamma, int | np.integer) or not (
            2 <= n_gamma <= 1000):
        raise ValueError(f"n_gamma = {n_gamma!r}: must be an integer in 2..1000")
    opt = _options(**options)
    B1 = np.asarray(B1, dtype=float)
    levels = np.linspace(0.0, gmax, n_gamma)[1:]
    found = [_search(periodic_system(M, C, A, g * B1), lo, hi, opt) for g in levels[:-1]]
    found.append(_search(periodic_system(M, C, A, levels[-1] * B1), lo, hi, opt)
                 if regions is None else tuple(regions))  # levels[-1] = gamma_max
    crit = critical_amplitude(M, C, A, B1, gamma_max=gmax, omega_min=lo, omega_max=hi,
                              regions=found[-1], **options)  # levels[-1] = gamma_max
    out = []
    for c in crit:
        key = (c.kind, c.modes, c.order)
        g, a, b = [c.gamma_cr], [c.omega_cr], [c.omega_cr]
        for lev, regs in zip(levels, found, strict=True):
            match = [r for r in regs if _key(r) == key]
            if match and lev > c.gamma_cr:
                g.append(float(lev))
                a.append(match[0].omega_lo)
                b.append(match[0].omega_hi)
        out.append(RegionBoundary(c.kind, c.modes, c.order, np.array(g), np.array(a),
                                  np.array(b)))
    return tuple(out)
