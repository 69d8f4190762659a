"""The events of a flight: the time intervals in which a band (a parametric region or a forced
resonance) meets the thrust oscillation's band, with the growth accumulated while they meet.

Between two frozen times every edge is linear in time: the band's Omega edges, the
oscillation band's edges and the growth rate. The crossing times are the roots of the linear
edge differences, never points of an Omega or time grid. Theory: docs/theory/flight.md.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Hashable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..bands import Band
from ..checks import finite_array, positive
from ..floquet import RESONANCE_KINDS, StepLimitError
from .passage import Passage, accumulated_growth, crossing_peak_ratio

__all__ = ["FlightEvent", "EVENT_COLUMNS", "band_key", "band_events", "band_rate",
           "resonance_events", "meeting_intervals", "worst_first", "PASS_OVER_ORDERS",
           "PASS_OVER_WINDOW", "PASS_OVER_REACH", "MAX_PASS_OVER_SEARCHES", "PassOver",
           "pass_over_windows",
           "passes_over"]

#: Columns of flight-events.csv, in order (the keys of :meth:`FlightEvent.to_dict`).
EVENT_COLUMNS = ("mechanism", "k", "modes", "t_start_s", "t_end_s", "max_growth_1_s",
                 "efolds", "amplification", "peak_acceleration_g", "station")


@dataclass(frozen=True)
class FlightEvent:
    """One band met by the oscillation during one interval of the flight.

    Attributes
    ----------
    mechanism : str
        A key of :data:`flexbooster.bands.MECHANISMS`, or ``"forced"`` for a forced resonance
        of a structural mode.
    k : int or None
        Circumferential harmonic, where one.
    modes : str
        The modes in words (" + " between the modes of a combination region), without k
        (the texts put ``k`` before them).
    t_start_s, t_end_s : float
        The interval (s) in which the band meets the oscillation band.
    max_growth_1_s : float
        Largest growth rate in the interval (1/s; 0 for a forced resonance).
    efolds : float
        integral of the growth rate over the interval (dimensionless).
    amplification : float
        exp(efolds), the amplitude's growth (saturating at the largest float).
    peak_acceleration_g : float or None
        A forced resonance's peak acceleration (g) at ``station``; None for a region.
    station : str or None
        Where that peak is, in words.
    """

    mechanism: str
    k: int | None
    modes: str
    t_start_s: float
    t_end_s: float
    max_growth_1_s: float
    efolds: float
    amplification: float
    peak_acceleration_g: float | None = None
    station: str | None = None

    @property
    def dwell_s(self) -> float:
        """t_end_s - t_start_s (s)."""
        return self.t_end_s - self.t_start_s

    def to_dict(self) -> dict[str, Any]:
        """The row of flight-events.csv (:data:`EVENT_COLUMNS`), JSON-ready (None kept)."""
        return {"mechanism": self.mechanism, "k": None if self.k is None else int(self.k),
                "modes": self.modes, "t_start_s": float(self.t_start_s),
                "t_end_s": float(self.t_end_s), "max_growth_1_s": float(self.max_growth_1_s),
                "efolds": float(self.efolds), "amplification": float(self.amplification),
                "peak_acceleration_g": None if self.peak_acceleration_g is None
                else float(self.peak_acceleration_g),
                "station": self.station}


def band_key(band: Band) -> Hashable:
    """The identity of a band across frozen times: mechanism, harmonic, kind, order and the
    labels of its modes (the labels should name tracked modes, :func:`.track_modes`).

    Parameters
    ----------
    band : Band
        The band.
    """
    return (band.mechanism, band.k, band.kind, band.order,
            tuple(m.label for m in band.modes))


def band_rate(band: Band, osc_lo: float, osc_hi: float,
              growth_at: Callable[[float], float]) -> float | None:
    """The largest growth rate of a region inside the oscillation band [osc_lo, osc_hi] at one
    frozen time (1/s), for ``rates_per_time`` of :func:`band_events`; None where they do not
    meet. The growth rate is taken unimodal across the region (it rises from 0 at one edge to
    ``growth_rate_max`` at ``Omega_at_max`` and falls to 0 at the other, as in a Mathieu
    tongue): inside the overlap the largest is ``growth_rate_max`` where the overlap holds
    ``Omega_at_max``, else the rate at the overlap's end nearer to it (one evaluation).

    Parameters
    ----------
    band : Band
        The region at this frozen time.
    osc_lo, osc_hi : float
        The oscillation band (rad/s), osc_lo <= osc_hi.
    growth_at : callable
        Omega (rad/s) -> the region's growth rate there (1/s), the caller's Floquet analysis.
    """
    lo, hi = max(band.Omega_lo, float(osc_lo)), min(band.Omega_hi, float(osc_hi))
    if lo > hi:
        return None
    if lo <= band.Omega_at_max <= hi:
        return float(band.growth_rate_max)
    end = hi if hi < band.Omega_at_max else lo  # the overlap's end nearer the maximum
    rate = float(growth_at(end))
    if not math.isfinite(rate):
        raise ValueError(f"growth_at({end!r}) = {rate!r}: must be finite")
    return rate


def _linear_nonnegative(g0: float, g1: float) -> tuple[float, float] | None:
    """The part of s in [0, 1] with g0 + s (g1 - g0) >= 0, an interval or None."""
    if g0 >= 0.0 and g1 >= 0.0:
        return 0.0, 1.0
    if g0 < 0.0 and g1 < 0.0:
        return None
    root = g0 / (g0 - g1)  # the crossing of the linear edge difference
    return (root, 1.0) if g1 >= 0.0 else (0.0, root)


def meeting_intervals(times: Any, lo: Any, hi: Any, osc_lo: Any, osc_hi: Any,
                      present: Any = None) -> list[tuple[float, float, int]]:
    """Where [lo(t), hi(t)] meets [osc_lo(t), osc_hi(t)], every edge linear between the
    frozen times: per segment the roots of osc_hi - lo and hi - osc_lo.

    Parameters
    ----------
    times : array_like
        Frozen times (s), strictly increasing, T >= 2.
    lo, hi : array_like
        The band's edges at those times (rad/s), lo <= hi; ignored where not ``present``.
    osc_lo, osc_hi : array_like
        The oscillation band's edges (rad/s), osc_lo <= osc_hi.
    present : array_like of bool, optional
        Where the band exists. On a segment with the band at one end only, that end's band is
        held over the segment (the frozen times do not resolve where it closes: a bound).

    Returns
    -------
    list of (t_a, t_b, i)
        Pieces t_a <= t_b within segment [times[i], times[i + 1]], in time order.
    """
    t = finite_array("times", times).ravel()
    if t.size < 2 or np.any(np.diff(t) <= 0.0):
        raise ValueError("times: need at least 2, strictly increasing")
    arrays = []
    for name, value in (("lo", lo), ("hi", hi), ("osc_lo", osc_lo), ("osc_hi", osc_hi)):
        a = np.asarray(value, dtype=float).ravel()
        if a.size != t.size:
            raise ValueError(f"{name}: {a.size} values, must be {t.size} like times")
        arrays.append(a)
    lo_, hi_, olo, ohi = arrays
    have = np.ones(t.size, bool) if present is None else np.asarray(present, bool).ravel()
    if have.size != t.size:
        raise ValueError(f"present: {have.size} values, must be {t.size} like times")
    finite_array("osc_lo, osc_hi", np.concatenate([olo, ohi]))
    if np.any(olo > ohi):
        raise ValueError("osc_lo, osc_hi: need osc_lo <= osc_hi at every time")
    if np.any(~np.isfinite(lo_[have])) or np.any(~np.isfinite(hi_[have])) or \
            np.any(lo_[have] > hi_[have]):
        raise ValueError("lo, hi: need finite lo <= hi where the band is present")
    pieces: list[tuple[float, float, int]] = []
    for i in range(t.size - 1):
        j0, j1 = i, i + 1
        if not (have[j0] or have[j1]):
            continue
        if not have[j0]:
            j0 = j1  # hold the band of the end where it exists
        if not have[j1]:
            j1 = j0
        a = _linear_nonnegative(ohi[i] - lo_[j0], ohi[i + 1] - lo_[j1])  # lo <= osc_hi
        b = _linear_nonnegative(hi_[j0] - olo[i], hi_[j1] - olo[i + 1])  # osc_lo <= hi
        if a is None or b is None:
            continue
        s0, s1 = max(a[0], b[0]), min(a[1], b[1])
        if s0 > s1:
            continue
        h = t[i + 1] - t[i]
        ta = t[i + 1] if s0 == 1.0 else t[i] + s0 * h
        tb = t[i + 1] if s1 == 1.0 else t[i] + s1 * h
        pieces.append((float(ta), float(tb), i))
    return pieces


def _merge(pieces: list[tuple[float, float, int]]) -> list[list[tuple[float, float, int]]]:
    """Pieces that touch (one ends where the next starts) as one run."""
    runs: list[list[tuple[float, float, int]]] = []
    for p in pieces:
        if runs and p[0] <= runs[-1][-1][1]:
            runs[-1].append(p)
        else:
            runs.append([p])
    return runs


def _run_growth(run: list[tuple[float, float, int]], times: np.ndarray,
                rate: np.ndarray) -> Passage:
    """The e-folds of a run: the rate linear in each segment, integrated exactly."""
    knots_t: list[float] = []
    knots_s: list[float] = []
    for ta, tb, i in run:
        h = times[i + 1] - times[i]
        for tk in (ta, tb):
            s = rate[i] + (rate[i + 1] - rate[i]) * (tk - times[i]) / h  # linear in time
            if knots_t and tk <= knots_t[-1]:
                continue
            knots_t.append(tk)
            knots_s.append(max(s, 0.0))
    if len(knots_t) == 1:  # the band only touches the oscillation band
        return Passage(efolds=0.0, max_growth=knots_s[0], t_start=knots_t[0],
                       t_end=knots_t[0], dwell=0.0, net_efolds=0.0)
    return accumulated_growth(knots_t, knots_s)


def band_events(times: Any, bands_per_time: Sequence[Sequence[Band]], oscillation: Any, *,
                rates_per_time: Sequence[Sequence[float]] | None = None,
                key: Callable[[Band], Hashable] = band_key) -> tuple[FlightEvent, ...]:
    """Every interval of the flight in which a band meets the oscillation band, with the
    growth accumulated over it.

    Bands at different frozen times are the same band when ``key`` says so. Between two
    frozen times the band's edges and its growth rate are linear in time; the interval's ends
    are the crossings of the edges (:func:`meeting_intervals`); the e-folds integrate the rate
    exactly on that schedule. A band present at one end of a segment only is held over it.

    Parameters
    ----------
    times : array_like
        Frozen times (s), strictly increasing, T >= 2.
    bands_per_time : sequence of sequence of Band
        Per frozen time, the bands of every mechanism (keys unique within a time).
    oscillation : array_like
        (T, 2): the oscillation band (lo, hi) at each frozen time (rad/s).
    rates_per_time : sequence of sequence of float or None, optional
        Per frozen time and band, the growth rate to integrate (1/s): the largest inside the
        band and the oscillation band (:func:`band_rate`). Default, and where an entry is
        None (the bands do not meet at that time), the band's ``growth_rate_max``, an upper
        bound where the oscillation band holds only part of the band.
    key : callable
        Band -> hashable identity across times (default :func:`band_key`).
    """
    t = finite_array("times", times).ravel()
    osc = finite_array("oscillation", oscillation)
    if osc.shape != (t.size, 2):
        raise ValueError(f"oscillation = shape {osc.shape}: must be ({t.size}, 2)")
    if len(bands_per_time) != t.size:
        raise ValueError(f"bands_per_time: {len(bands_per_time)} times, must be {t.size}")
    if rates_per_time is not None and len(rates_per_time) != t.size:
        raise ValueError(f"rates_per_time: {len(rates_per_time)} times, must be {t.size}")
    table: dict[Hashable, list[tuple[Band, float] | None]] = {}
    for j, bands in enumerate(bands_per_time):
        rates = None if rates_per_time is None else list(rates_per_time[j])
        if rates is not None and len(rates) != len(bands):
            raise ValueError(f"rates_per_time[{j}]: {len(rates)} rates for {len(bands)} bands")
        for n, band in enumerate(bands):
            if not isinstance(band, Band):
                raise ValueError(f"bands_per_time[{j}][{n}] = {band!r:.60}: must be a Band")
            kb = key(band)
            row = table.setdefault(kb, [None] * t.size)
            if row[j] is not None:
                raise ValueError(f"bands_per_time[{j}]: two bands with the key {kb!r:.80}")
            rate = band.growth_rate_max if rates is None or rates[n] is None else rates[n]
            if not math.isfinite(float(rate)):
                raise ValueError(f"rates_per_time[{j}][{n}] = {rate!r}: must be finite")
            row[j] = (band, float(rate))
    events: list[FlightEvent] = []
    for row in table.values():
        have = np.array([r is not None for r in row])
        first = next(r for r in row if r is not None)[0]
        lo = np.array([r[0].Omega_lo if r else np.nan for r in row])
        hi = np.array([r[0].Omega_hi if r else np.nan for r in row])
        rate = np.array([r[1] if r else np.nan for r in row])
        # where absent, the held band's rate (the same hold as the edges)
        for j in np.nonzero(~have)[0]:
            near = [i for i in (j - 1, j + 1) if 0 <= i < t.size and have[i]]
            if near:
                rate[j] = max(rate[i] for i in near)
        pieces = meeting_intervals(t, lo, hi, osc[:, 0], osc[:, 1], present=have)
        for run in _merge(pieces):
            p = _run_growth(run, t, np.nan_to_num(rate))
            events.append(FlightEvent(
                mechanism=first.mechanism, k=first.k, modes=first.mode_text,
                t_start_s=run[0][0], t_end_s=run[-1][1], max_growth_1_s=p.max_growth,
                efolds=p.efolds, amplification=p.amplification))
    return tuple(worst_first(events))


def resonance_events(times: Any, omega: Any, oscillation: Any, *, zeta: float,
                     steady_peak_g: Any, modes: str, k: int | None = None,
                     station: str | Sequence[str] | None = None) -> tuple[FlightEvent, ...]:
    """The intervals in which a tracked mode's half-power band omega (1 -+ zeta) meets the
    oscillation band, with the peak acceleration: a known oscillation frequency (lo == hi)
    crossing the mode's frequency gives the non-stationary peak, the steady peak at the
    crossing times :func:`.crossing_peak_ratio` of the mode and the forcing drifting at
    their rates in that segment (the largest over the run's crossings); a frequency band
    gives the largest steady peak inside the run (the oscillation may dwell at the
    resonance), the steady peak linear in time between the frozen times as the frequencies.
    Where the crossing is too slow for :data:`.MAX_SWEEP_STEPS`, the steady peak (a bound).

    Parameters
    ----------
    times : array_like
        Frozen times (s), strictly increasing, T >= 2.
    omega : array_like
        The tracked mode's natural frequency at each time (rad/s), > 0.
    oscillation : array_like
        (T, 2): the oscillation band (lo, hi) at each time (rad/s).
    zeta : float
        The mode's damping ratio, 0 < zeta < 1/sqrt(2).
    steady_peak_g : array_like
        The steady resonant peak acceleration (g) at each time, >= 0.
    modes : str
        The mode in words.
    k : int, optional
        Its circumferential harmonic.
    station : str or sequence of str, optional
        Where the peak acceleration is: one name, or one per time (the event's is that of
        the frozen time nearest to where its peak is).
    """
    t = finite_array("times", times).ravel()
    om = finite_array("omega", omega, positive=True).ravel()
    osc = finite_array("oscillation", oscillation)
    zeta = positive("zeta", zeta)
    if zeta >= math.sqrt(0.5):
        raise ValueError(f"zeta = {zeta!r}: must be < 1/sqrt(2) for a resonant peak")
    peak = finite_array("steady_peak_g", steady_peak_g).ravel()
    if om.size != t.size or peak.size != t.size or osc.shape != (t.size, 2):
        raise ValueError(f"omega, steady_peak_g, oscillation: need {t.size} times like times")
    places = [station] * t.size if station is None or isinstance(station, str) else list(station)
    if len(places) != t.size:
        raise ValueError(f"station: {len(places)} names, need {t.size} like times (or one)")
    pieces = meeting_intervals(t, om * (1.0 - zeta), om * (1.0 + zeta), osc[:, 0], osc[:, 1])

    def nearest(i: int, when: float) -> int:  # of segment i's frozen times, the nearer
        return i + int(when - t[i] > t[i + 1] - when)

    events = []
    for run in _merge(pieces):
        idx = sorted({i for _, _, i in run} | {i + 1 for _, _, i in run})
        # a band: the largest steady peak inside the run, the peak linear in time between the
        # frozen times as the frequencies are (a linear function's largest value on a piece
        # is at one of its ends)
        g, at = max((float(np.interp(end, t[i:i + 2], peak[i:i + 2])), nearest(i, end))
                    for ta, tb, i in run for end in (ta, tb))
        if np.all(osc[idx, 0] == osc[idx, 1]):
            # a known frequency: where Omega = omega, the steady peak there and the drift
            crossings = []
            for _, _, i in run:
                h = t[i + 1] - t[i]
                d0, d1 = osc[i, 0] - om[i], osc[i + 1, 0] - om[i + 1]
                if d0 * d1 <= 0.0 and d0 != d1:
                    s = d0 / (d0 - d1)  # Omega - omega linear in the segment
                    crossings.append((om[i] + s * (om[i + 1] - om[i]),
                                      (om[i + 1] - om[i]) / h, (osc[i + 1, 0] - osc[i, 0]) / h,
                                      peak[i] + s * (peak[i + 1] - peak[i]),
                                      nearest(i, t[i] + s * h)))
            ratios = []
            for w_c, w_rate, W_rate, g_c, where in crossings:
                try:
                    ratio = crossing_peak_ratio(zeta=zeta, omega=w_c, omega_rate=w_rate,
                                                Omega_rate=W_rate)
                except StepLimitError:  # too slow to integrate: the steady peak bounds it
                    ratio = 1.0
                ratios.append((ratio * g_c, where))
            if ratios:
                g, at = max(ratios)
        events.append(FlightEvent(
            mechanism="forced", k=k, modes=modes, t_start_s=run[0][0], t_end_s=run[-1][1],
            max_growth_1_s=0.0, efolds=0.0, amplification=1.0,
            peak_acceleration_g=float(g), station=places[at]))
    return tuple(events)


def worst_first(events: Sequence[FlightEvent]) -> list[FlightEvent]:
    """The events, the worst first: the largest e-folds, then the largest peak acceleration,
    then the earliest.

    Parameters
    ----------
    events : sequence of FlightEvent
        The events.
    """
    return sorted(events, key=lambda e: (-e.efolds, -(e.peak_acceleration_g or 0.0),
                                         e.t_start_s))


#: Orders n of the combination centres (2 w_i, w_i + w_j, |w_i - w_j|) / n checked by
#: :func:`passes_over` (the first two: the widest regions).
PASS_OVER_ORDERS = 2
#: A combination passing over the searched range between two frozen times is searched at
#: each of them in the window centre (1 -+ PASS_OVER_WINDOW) outside that range (the first-
#: order width of a region is a small fraction of its centre: Bolotin 1964, sec. 3).
PASS_OVER_WINDOW = 0.1
#: Such windows are searched within [lo / PASS_OVER_REACH, hi PASS_OVER_REACH] of the searched
#: range [lo, hi] (a window further out is a search gap: its cost grows as 1 / Omega).
PASS_OVER_REACH = 2.0
#: Most such windows searched in one flight (merged per frozen time and harmonic); the pass-
#: overs beyond are search gaps.
MAX_PASS_OVER_SEARCHES = 24


@dataclass(frozen=True)
class PassOver:
    """A combination of tracked modes whose centre passes over the searched Omega range
    between two neighbouring frozen times, where neither searched it.

    Attributes
    ----------
    kind : str
        "simple" (2 w_i / n), "sum" ((w_i + w_j) / n) or "difference" (|w_i - w_j| / n).
    identities : (int, int)
        The tracked identities i <= j (i = j for "simple").
    order : int
        n.
    t_start, t_end : float
        The two frozen times (s).
    centre_start, centre_end : float
        The centre (rad/s) at each.
    """

    kind: str
    identities: tuple
    order: int
    t_start: float
    t_end: float
    centre_start: float
    centre_end: float


def passes_over(times: Any, frequencies: Any, lo: float, hi: float, *,
                orders: int = PASS_OVER_ORDERS,
                kinds: Sequence[str] = RESONANCE_KINDS) -> tuple[PassOver, ...]:
    """The combinations of tracked modes whose centre lies below ``lo`` at one frozen time and
    above ``hi`` at the next, or the reverse. The frequencies, and so the centres, are linear
    between frozen times (as everywhere in the flight), so such a centre crosses all of
    [lo, hi] between the two times, where a search at each frozen time over [lo, hi] sees
    none of its regions (docs/theory/flight.md, "What the frozen times do not see").

    Parameters
    ----------
    times : array_like, shape (T,)
        Frozen times (s), increasing.
    frequencies : array_like, shape (T, N)
        Frequency (rad/s) of each tracked identity at each time; NaN where absent.
    lo, hi : float
        The searched Omega range (rad/s), 0 < lo <= hi.
    orders : int
        The orders n = 1..orders of the centres, >= 1.
    kinds : sequence of str
        The kinds of combination looked at, of "simple", "sum", "difference" (a harmonic's
        :func:`flexbooster.floquet.resonance_kinds`).
    """
    t = finite_array("times", times)
    f = np.asarray(frequencies, dtype=float)
    if t.ndim != 1 or f.ndim != 2 or f.shape[0] != t.size:
        raise ValueError(f"frequencies: shape {f.shape}, need ({t.size}, N)")
    lo, hi = positive("lo", lo), positive("hi", hi)
    if hi < lo:
        raise ValueError(f"hi = {hi!r}: must be >= lo = {lo!r}")
    if not isinstance(orders, int | np.integer) or orders < 1:
        raise ValueError(f"orders = {orders!r}: must be an integer >= 1")
    bad = [k for k in kinds if k not in RESONANCE_KINDS]
    if isinstance(kinds, str) or bad:
        raise ValueError(f"kinds = {kinds!r}: each must be 'simple', 'sum' or 'difference'")
    i, j = np.triu_indices(f.shape[1])
    out = []
    for s in range(t.size - 1):
        a, b = f[s], f[s + 1]
        for kind, c0, c1, pairs in (
                ("simple", 2.0 * a[i], 2.0 * b[i], i == j),
                ("sum", a[i] + a[j], b[i] + b[j], i < j),
                ("difference", np.abs(a[i] - a[j]), np.abs(b[i] - b[j]), i < j)):
            if kind not in kinds:
                continue
            for n in range(1, int(orders) + 1):
                lo0, hi0, lo1, hi1 = c0 / n < lo, c0 / n > hi, c1 / n < lo, c1 / n > hi
                for m in np.flatnonzero(pairs & ((lo0 & hi1) | (hi0 & lo1))):  # NaN: False
                    out.append(PassOver(kind=kind, identities=(int(i[m]), int(j[m])), order=n,
                                        t_start=float(t[s]), t_end=float(t[s + 1]),
                                        centre_start=float(c0[m] / n),
                                        centre_end=float(c1[m] / n)))
    return tuple(out)


def pass_over_windows(times: Any, frequencies: Any, lo: float, hi: float, *,
                      kinds_at: Callable[[int], Sequence[str]]
                      ) -> tuple[int, dict[int, list[tuple[float, float]]], list[tuple]]:
    """Where one harmonic is searched outside the range for its combinations that pass over it
    between frozen times (:func:`passes_over`): at both times of each step, the window centre
    (1 -+ :data:`PASS_OVER_WINDOW`) on the centre's side of [lo, hi], merged per time where
    they overlap; windows beyond :data:`PASS_OVER_REACH` of the range are listed apart (the
    flight's search gaps). Returns (the number of pass-overs, {time index: [(a, b), ...]
    within the reach, ascending}, [(time index, a, b), ...] beyond it).

    Parameters
    ----------
    times, frequencies, lo, hi
        As :func:`passes_over`.
    kinds_at : callable
        ``kinds_at(s)``: the kinds that can open a region between times s and s + 1 (the
        union of both times' :func:`flexbooster.floquet.resonance_kinds`); empty: the step is
        skipped (a harmonic certified stable at both times).
    """
    t = finite_array("times", times)
    f = np.asarray(frequencies, dtype=float)
    count, spans, far = 0, {}, []
    for s in range(t.size - 1):
        kinds = tuple(kinds_at(s))
        if not kinds:
            continue
        for p in passes_over(t[s:s + 2], f[s:s + 2], lo, hi, kinds=kinds):
            count += 1
            for i, c in ((s, p.centre_start), (s + 1, p.centre_end)):
                a, b = c * (1.0 - PASS_OVER_WINDOW), c * (1.0 + PASS_OVER_WINDOW)
                a, b = (a, min(b, lo)) if c < lo else (max(a, hi), b)
                if a >= b:
                    continue
                if a < lo / PASS_OVER_REACH or b > hi * PASS_OVER_REACH:
                    far.append((i, a, b))
                else:
                    spans.setdefault(i, []).append((a, b))
    merged = {}
    for i, windows in spans.items():
        windows.sort()
        out = [list(windows[0])]
        for a, b in windows[1:]:  # overlapping windows searched once
            if a <= out[-1][1]:
                out[-1][1] = max(out[-1][1], b)
            else:
                out.append([a, b])
        merged[i] = [(a, b) for a, b in out]
    return count, merged, far
