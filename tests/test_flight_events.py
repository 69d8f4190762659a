"""flexbooster.flight.events: where and for how long the bands meet the oscillation band
along the flight, and the growth accumulated meanwhile (docs/theory/flight.md).

Evidence: (1) synthetic bands whose edges move linearly in time, frozen times off the
crossings: crossing times and e-folds in closed form (1e-12); (2) a constant system under a
constant oscillation: e-folds = growth rate x duration exactly, with the rate from
flexbooster.floquet; (3) a mode drifting through a fixed oscillation frequency: the
non-stationary peak acceleration against solve_ivp of the drifting equation; (4) the CSV
row and bad input.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from flexbooster.bands import Band, BandMode
from flexbooster.flight import (
    EVENT_COLUMNS,
    FlightEvent,
    band_events,
    band_rate,
    meeting_intervals,
    passes_over,
    resonance_events,
)
from flexbooster.floquet import growth_rate


def _band(lo: float, hi: float, rate: float, label: str = "bending 1", k: int = 1) -> Band:
    return Band(mechanism="vehicle", Omega_lo=lo, Omega_hi=hi, kind="simple", order=1,
                modes=(BandMode(label=label, k=k),), growth_rate_max=rate,
                Omega_at_max=0.5 * (lo + hi), Omega_center=0.5 * (lo + hi), k=k)


TIMES = np.array([0.0, 3.0, 7.0, 10.0])  # no frozen time on a crossing


def test_moving_band_meets_a_known_frequency_at_the_edge_crossings():
    """Closed form: edges 10 + 2t and 12 + 2t rad/s meet Omega = 20 for 4 <= t <= 5 s (the
    frozen times 0, 3, 7, 10 bracket both crossings); a constant rate 0.5 1/s gives 0.5
    e-folds. Tolerance 1e-12."""
    bands = [[_band(10 + 2 * t, 12 + 2 * t, 0.5)] for t in TIMES]
    osc = np.full((TIMES.size, 2), 20.0)
    (event,) = band_events(TIMES, bands, osc)
    assert event.t_start_s == pytest.approx(4.0, rel=1e-12)
    assert event.t_end_s == pytest.approx(5.0, rel=1e-12)
    assert event.efolds == pytest.approx(0.5, rel=1e-12)
    assert event.amplification == pytest.approx(math.exp(0.5), rel=1e-12)
    assert (event.mechanism, event.k, event.modes) == ("vehicle", 1, "bending 1")


def test_rate_linear_in_time_is_integrated_exactly():
    """Closed form: the same band with growth rate 0.1 t 1/s at the frozen times (linear in
    between): e-folds = integral of 0.1 t over [4, 5] = 0.45, the largest rate 0.5 at t = 5;
    rates_per_time overrides growth_rate_max (here 2 x 0.1 t: 0.9 e-folds), None entries
    fall back to it. Tolerance 1e-12."""
    bands = [[_band(10 + 2 * t, 12 + 2 * t, 0.1 * t)] for t in TIMES]
    osc = np.full((TIMES.size, 2), 20.0)
    (event,) = band_events(TIMES, bands, osc)
    assert event.efolds == pytest.approx(0.45, rel=1e-12)
    assert event.max_growth_1_s == pytest.approx(0.5, rel=1e-12)
    (twice,) = band_events(TIMES, bands, osc, rates_per_time=[[0.2 * t] for t in TIMES])
    assert twice.efolds == pytest.approx(0.9, rel=1e-12)
    # None (the bands do not meet at that frozen time): the band's growth_rate_max
    (same,) = band_events(TIMES, bands, osc, rates_per_time=[[None] for _ in TIMES])
    assert same.efolds == pytest.approx(0.45, rel=1e-12)


def test_moving_oscillation_band_meets_a_fixed_band():
    """Closed form: oscillation band [15 + t, 16 + t] and region [20, 22]: they meet while
    16 + t >= 20 and 15 + t <= 22, t in [4, 7] (7 is a frozen time); rate 0.2: 0.6 e-folds."""
    bands = [[_band(20.0, 22.0, 0.2)] for _ in TIMES]
    osc = np.stack([15.0 + TIMES, 16.0 + TIMES], axis=1)
    (event,) = band_events(TIMES, bands, osc)
    assert (event.t_start_s, event.t_end_s) == (pytest.approx(4.0, rel=1e-12), 7.0)
    assert event.efolds == pytest.approx(0.6, rel=1e-12)
    assert meeting_intervals(TIMES, np.full(4, 20.0), np.full(4, 22.0), osc[:, 0],
                             osc[:, 1]) == [(pytest.approx(4.0), 7.0, 1), (7.0, 7.0, 2)]


def test_two_passages_and_two_bands_worst_first():
    """Closed form: a known Omega = 12 + 1.6 t up to t = 5 s, then back down, meets a band
    [17, 19] twice, on [3.125, 4.375] and [5.625, 6.875] (rate 0.4: 0.5 e-folds each), and
    a band [19.5, 21] once across the turn, on [4.6875, 5.3125] (rate 0.1: 0.0625); the
    worst (largest e-folds, then earliest) first. Tolerance 1e-12."""
    times = np.array([0.0, 5.0, 10.0])
    om = np.array([12.0, 20.0, 12.0])
    bands = [[_band(17.0, 19.0, 0.4), _band(19.5, 21.0, 0.1, label="bending 2")]
             for _ in times]
    events = band_events(times, bands, np.stack([om, om], axis=1))
    assert [(e.modes, pytest.approx(e.t_start_s), pytest.approx(e.t_end_s)) for e in events] \
        == [("bending 1", 3.125, 4.375), ("bending 1", 5.625, 6.875),
            ("bending 2", 4.6875, 5.3125)]
    np.testing.assert_allclose([e.efolds for e in events], [0.5, 0.5, 0.0625], rtol=1e-12)


def test_constant_system_and_oscillation_efolds_are_rate_times_duration():
    """Acceptance, exact: a damped Mathieu mode (M = 1, C = 2 zeta w, A = w^2,
    B = -2 mu w^2, w = 30 rad/s, mu = 0.1, zeta = 0.01) under Omega = 2 w at every frozen
    time: its Floquet growth rate (flexbooster.floquet.growth_rate) times the 80 s duration;
    tolerance 1e-12 relative."""
    w, mu, zeta = 30.0, 0.1, 0.01
    sigma = float(growth_rate(np.eye(1), 2 * zeta * w * np.eye(1), w * w * np.eye(1),
                              -2 * mu * w * w * np.eye(1), [2 * w])[0])
    assert sigma > 0.0
    times = np.linspace(0.0, 80.0, 9)
    bands = [[_band(2 * w * (1 - mu / 2), 2 * w * (1 + mu / 2), sigma)] for _ in times]
    (event,) = band_events(times, bands, np.full((9, 2), 2 * w))
    assert event.efolds == pytest.approx(sigma * 80.0, rel=1e-12)
    assert (event.t_start_s, event.t_end_s) == (0.0, 80.0)


def test_band_rate_is_the_largest_rate_inside_the_overlap():
    """Independent method: the largest Floquet growth rate of the damped Mathieu mode
    (w = 30 rad/s, mu = 0.1, zeta = 0.01) over the overlap of its principal region with an
    oscillation band, by :func:`band_rate` (one evaluation) against a 2001-point scan of
    floquet.growth_rate over the overlap: 1e-9 relative where the largest is at an end of the
    overlap (the scan includes the ends), 1e-6 where the overlap holds the band's maximum (the
    test's band takes it from a 4001-point grid, error quadratic in the spacing); None for a
    band outside the region."""
    w, mu, zeta = 30.0, 0.1, 0.01

    def growth(Om):
        Om = np.atleast_1d(np.asarray(Om, dtype=float))
        return growth_rate(np.eye(1), 2 * zeta * w * np.eye(1), w * w * np.eye(1),
                           -2 * mu * w * w * np.eye(1), Om)

    grid = np.linspace(2 * w * 0.9, 2 * w * 1.1, 4001)
    rates = growth(grid)
    inside = grid[rates > 0.0]
    i_max = int(np.argmax(rates))
    band = _band(float(inside[0]), float(inside[-1]), float(rates[i_max]))
    band = Band(**{**band.__dict__, "Omega_at_max": float(grid[i_max])})
    for lo, hi in [(55.0, 61.0), (59.0, 60.5), (61.2, 70.0), (50.0, 57.5)]:
        got = band_rate(band, lo, hi, lambda Om: float(growth(Om)[0]))
        a, b = max(lo, band.Omega_lo), min(hi, band.Omega_hi)
        scan = float(np.max(growth(np.linspace(a, b, 2001))))
        holds_max = a <= band.Omega_at_max <= b
        assert got == pytest.approx(scan, rel=1e-6 if holds_max else 1e-9), (lo, hi)
    assert band_rate(band, 10.0, 20.0, lambda Om: 1.0) is None


def test_band_present_at_one_end_is_held_over_the_segment():
    """Rule (docs/theory/flight.md): a band that closes between frozen times is held from
    the last time it exists to the next frozen time (an upper bound): band [19, 21] rate 1
    at t = 0 and 3 only; Omega = 20 fixed: met on [0, 7], 1 x 7 = 7 e-folds."""
    bands = [[_band(19.0, 21.0, 1.0)], [_band(19.0, 21.0, 1.0)], [], []]
    (event,) = band_events(TIMES, bands, np.full((4, 2), 20.0))
    assert (event.t_start_s, event.t_end_s) == (0.0, 7.0)
    assert event.efolds == pytest.approx(7.0, rel=1e-12)


def _drift_peak(rate: float, zeta: float = 0.02, Om: float = 15.0):
    """Peak acceleration of q'' + 2 zeta w(t) q' + w(t)^2 q = cos(Omega t), w linear through
    Omega = 15 (from 10 upward or from 20 downward over 10 rad/s), by solve_ivp DOP853
    (rtol 1e-10) from the steady start, and the event's prediction (steady resonant
    acceleration 1 / (2 zeta sqrt(1 - zeta^2)) at every frozen time)."""
    T = 10.0 / abs(rate)
    w0 = 10.0 if rate > 0 else 20.0
    times = np.linspace(0.0, T, 101)
    om = w0 + rate * times
    steady = np.full(times.size, 1.0 / (2 * zeta * math.sqrt(1 - zeta * zeta)))
    (event,) = resonance_events(times, om, np.full((times.size, 2), Om), zeta=zeta,
                                steady_peak_g=steady, modes="axial 1", k=0, station="aft")
    H = 1.0 / (w0 * w0 - Om * Om + 2j * zeta * w0 * Om)

    def rhs(t, y):
        w = w0 + rate * t
        return [y[1], math.cos(Om * t) - 2 * zeta * w * y[1] - w * w * y[0]]

    sol = solve_ivp(rhs, (0.0, T), [H.real, (1j * Om * H).real], method="DOP853", rtol=1e-10,
                    atol=1e-14, dense_output=True)
    tt = np.linspace(0.0, T, int(T * Om / (2 * math.pi) * 50))
    q, v = sol.sol(tt)
    w = w0 + rate * tt
    acc = np.cos(Om * tt) - 2 * zeta * w * v - w * w * q
    return event, float(np.max(np.abs(acc)))


@pytest.mark.slow
def test_mode_drifting_through_a_known_frequency_non_stationary_peak():
    """Independent model: a mode drifting at 0.1 rad/s^2 through a fixed Omega (the rate
    eta = w' / w^2 = 4.4e-4, 1.1 zeta^2): the event's peak acceleration (the drifting
    equation stepped exactly, :func:`crossing_peak_ratio`) against solve_ivp DOP853 (rtol
    1e-10) of the drifting equation, tolerance 2 %; the half-power band w (1 -+ zeta) meets Omega
    from t = (Omega / 1.02 - 10) / 0.1 to (Omega / 0.98 - 10) / 0.1 (closed form, 1e-9)."""
    event, direct = _drift_peak(0.1)
    assert event.peak_acceleration_g == pytest.approx(direct, rel=0.02)
    assert event.t_start_s == pytest.approx((15.0 / 1.02 - 10.0) / 0.1, rel=1e-9)
    assert event.t_end_s == pytest.approx((15.0 / 0.98 - 10.0) / 0.1, rel=1e-9)
    assert (event.mechanism, event.k, event.station, event.efolds) == ("forced", 0, "aft", 0.0)
    assert event.peak_acceleration_g < 1.0 / (2 * 0.02 * math.sqrt(1 - 0.02 ** 2))


@pytest.mark.parametrize("rate", [1.0, -1.0])
def test_fast_drift_up_and_down(rate):
    """Independent model: a fast drift, w' = +-1 rad/s^2 (eta = 4.4e-3, 11 zeta^2), where a
    constant-mode sweep at the same relative rate would miss the peak by 8 %: the event's
    peak acceleration against solve_ivp DOP853 (rtol 1e-10) of the drifting equation, 2 %."""
    event, direct = _drift_peak(rate)
    assert event.peak_acceleration_g == pytest.approx(direct, rel=0.02)


def test_band_peak_is_the_steady_peak_inside_the_event():
    """Closed form: a mode omega = 10 + 0.4 t rad/s (zeta = 0.01) under a band [9.5, 12]: its
    half-power band meets the band from t = 0 until omega (1 - zeta) = 12, t_end = (12 / 0.99 -
    10) / 0.4 = 5.303 s; the steady peak 1, 2, 30 g at t = 0, 10, 20 s, linear in between
    like the frequency, is largest inside the event at t_end: 1 + t_end / 10 g (1e-12), not the
    2 g or 30 g of frozen times after it; the station that of the frozen time nearest (10 s)."""
    times = np.array([0.0, 10.0, 20.0])
    (event,) = resonance_events(times, 10.0 + 0.4 * times, np.tile([9.5, 12.0], (3, 1)),
                                zeta=0.01, steady_peak_g=[1.0, 2.0, 30.0], modes="mode 1",
                                k=0, station=["aft", "mid", "fwd"])
    t_end = (12.0 / 0.99 - 10.0) / 0.4
    assert (event.t_start_s, event.t_end_s) == (0.0, pytest.approx(t_end, rel=1e-12))
    assert event.peak_acceleration_g == pytest.approx(1.0 + t_end / 10.0, rel=1e-12)
    assert event.station == "mid"
    with pytest.raises(ValueError, match="^station"):
        resonance_events(times, 10.0 + 0.4 * times, np.tile([9.5, 12.0], (3, 1)), zeta=0.01,
                         steady_peak_g=[1.0, 2.0, 30.0], modes="m", station=["aft"])


def test_event_row_has_the_csv_columns():
    """The flight-events.csv row: exactly the README's columns, in order, JSON types."""
    e = FlightEvent(mechanism="vehicle", k=2, modes="bending 1", t_start_s=1.0, t_end_s=2.5,
                    max_growth_1_s=0.3, efolds=0.2, amplification=math.exp(0.2))
    row = e.to_dict()
    assert tuple(row) == EVENT_COLUMNS
    assert row["peak_acceleration_g"] is None and row["station"] is None
    assert e.dwell_s == 1.5


def test_bad_input_names_the_parameter():
    """Bad input: ValueError naming the parameter."""
    bands = [[_band(10.0, 12.0, 0.5)] for _ in TIMES]
    osc = np.full((TIMES.size, 2), 20.0)
    with pytest.raises(ValueError, match="^oscillation"):
        band_events(TIMES, bands, osc[:2])
    with pytest.raises(ValueError, match="^bands_per_time"):
        band_events(TIMES, bands[:2], osc)
    with pytest.raises(ValueError, match=r"^bands_per_time\[0\]"):
        band_events(TIMES, [bands[0] * 2] + bands[1:], osc)
    with pytest.raises(ValueError, match=r"^rates_per_time\[1\]"):
        band_events(TIMES, bands, osc, rates_per_time=[[0.1], [], [0.1], [0.1]])
    with pytest.raises(ValueError, match="^times"):
        band_events(TIMES[::-1], bands, osc)
    with pytest.raises(ValueError, match="^zeta"):
        resonance_events(TIMES, np.full(4, 20.0), osc, zeta=0.8, steady_peak_g=np.ones(4),
                         modes="m")
    with pytest.raises(ValueError, match="^osc_lo, osc_hi"):
        meeting_intervals(TIMES, np.ones(4), np.ones(4), np.full(4, 2.0), np.ones(4))


def test_passes_over_finds_the_centres_that_jump_the_range():
    """Closed form: identities 0 and 1 at 2 and 3 rad/s, then 2 and 9 rad/s, range [4, 5]:
    2 w_1 / 2 goes 3 -> 9, (w_0 + w_1) / 2 goes 2.5 -> 5.5 and |w_1 - w_0| goes 1 -> 7, each
    from below 4 to above 5; 2 w_1 = 6 -> 18 and w_0 + w_1 = 5 -> 11 (5 is inside) do not,
    nor a centre inside the range at one end, nor an identity absent (NaN) at either end.
    Reversed in time, the same combinations pass down."""
    f = np.array([[2.0, 3.0, np.nan], [2.0, 9.0, 1.0]])
    got = {(p.kind, p.identities, p.order) for p in passes_over([0.0, 1.0], f, 4.0, 5.0)}
    want = {("simple", (1, 1), 2), ("sum", (0, 1), 2), ("difference", (0, 1), 1)}
    assert got == want
    back = passes_over([0.0, 1.0], f[::-1], 4.0, 5.0)
    assert {(p.kind, p.identities, p.order) for p in back} == want
    assert all((p.t_start, p.t_end) == (0.0, 1.0) for p in back)
    assert passes_over([0.0, 1.0], f, 4.0, 5.0, orders=1) == tuple(
        p for p in passes_over([0.0, 1.0], f, 4.0, 5.0) if p.order == 1)
    # kinds: only those asked for (a canonical harmonic has no difference regions)
    assert passes_over([0.0, 1.0], f, 4.0, 5.0, kinds=("simple", "sum")) == tuple(
        p for p in passes_over([0.0, 1.0], f, 4.0, 5.0) if p.kind != "difference")
    # three times: the jump is reported for its own step only
    three = passes_over([0.0, 1.0, 2.0], np.array([[2.0, 3.0], [2.0, 3.1], [2.0, 9.0]]), 4.0,
                        5.0)
    assert {(p.t_start, p.t_end) for p in three} == {(1.0, 2.0)}


@pytest.mark.parametrize(("kwargs", "name"), [
    ({"times": [0.0, np.inf]}, "times"), ({"frequencies": [[1.0]]}, "frequencies"),
    ({"lo": 0.0}, "lo"), ({"hi": 3.0}, "hi"), ({"orders": 0}, "orders"),
    ({"kinds": ("sum", "diff")}, "kinds"), ({"kinds": "sum"}, "kinds")])
def test_passes_over_bad_input_names_the_parameter(kwargs, name):
    args = dict(times=[0.0, 1.0], frequencies=[[1.0], [2.0]], lo=4.0, hi=5.0) | kwargs
    with pytest.raises(ValueError, match=name):
        passes_over(args.pop("times"), args.pop("frequencies"), args.pop("lo"), args.pop("hi"),
                    **args)
