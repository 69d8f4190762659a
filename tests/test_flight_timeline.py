"""flexbooster.flight.timeline: the flight's piecewise-linear schedules and frozen times
(docs/theory/flight.md).

Evidence: exact values of linear interpolation (closed form, to 1e-12 relative), the
frozen-time rules, and bad input (ValueError naming the parameter).
"""

from __future__ import annotations

import numpy as np
import pytest

from flexbooster.flight import FlightPoint, Timeline, frozen_times


def _timeline() -> Timeline:
    return Timeline(points=(
        FlightPoint(time=0.0, F0=2.0e6, fill=(1.0, 1.0), oscillation=(60.0, 80.0), gamma=0.02),
        FlightPoint(time=40.0, F0=2.4e6, fill=(0.5, 0.8), oscillation=75.0, gamma=0.01),
        FlightPoint(time=100.0, F0=1.0e6, fill=(0.0, 0.1), oscillation=(70.0, 90.0), gamma=0.0),
    ))


def test_at_interpolates_every_quantity_linearly():
    """Closed form: at t = 10 s, a quarter of the first segment, each quantity is
    a + (b - a) / 4; at t = 70 s, the middle of the second, (a + b) / 2; tolerance 1e-12."""
    tl = _timeline()
    p = tl.at(10.0)
    assert p.F0 == pytest.approx(2.1e6, rel=1e-12)
    assert p.fill == pytest.approx((0.875, 0.95), rel=1e-12)
    assert p.oscillation == pytest.approx((63.75, 78.75), rel=1e-12)
    assert p.gamma == pytest.approx(0.0175, rel=1e-12)
    q = tl.at(70.0)
    assert q.F0 == pytest.approx(1.7e6, rel=1e-12)
    assert q.fill == pytest.approx((0.25, 0.45), rel=1e-12)
    assert q.oscillation == pytest.approx((72.5, 82.5), rel=1e-12)
    lo, hi = tl.oscillation_at([10.0, 70.0])
    np.testing.assert_allclose(lo, [63.75, 72.5], rtol=1e-12)
    np.testing.assert_allclose(hi, [78.75, 82.5], rtol=1e-12)


def test_at_returns_the_points_themselves_at_their_times():
    """Exact: the interpolation passes through every point (end points included)."""
    tl = _timeline()
    for p in tl.points:
        assert tl.at(p.time) == p
    assert tl.duration == 100.0 and tl.start == 0.0 and tl.end == 100.0


def test_single_value_oscillation_is_a_known_frequency():
    """One value v is the band (v, v)."""
    p = _timeline().points[1]
    assert p.oscillation == (75.0, 75.0) and p.known_frequency
    assert not _timeline().points[0].known_frequency


def test_frozen_times_equally_spaced_and_with_corners():
    """Exact: n equally spaced times include both ends; with the corners the union."""
    tl = _timeline()
    np.testing.assert_allclose(frozen_times(tl, n=5), [0.0, 25.0, 50.0, 75.0, 100.0])
    np.testing.assert_allclose(frozen_times(tl, n=5, include_points=True),
                               [0.0, 25.0, 40.0, 50.0, 75.0, 100.0])
    np.testing.assert_allclose(frozen_times(tl, times=[0.0, 40.0, 99.0]), [0.0, 40.0, 99.0])


@pytest.mark.parametrize("kwargs, name", [
    (dict(time=float("nan")), "time"),
    (dict(F0=-1.0), "F0"),
    (dict(fill=(1.2,)), "fill"),
    (dict(fill=(float("inf"),)), "fill"),
    (dict(oscillation=(80.0, 60.0)), "oscillation"),
    (dict(oscillation=(0.0, 60.0)), "oscillation"),
    (dict(oscillation=(1.0, 2.0, 3.0)), "oscillation"),
    (dict(gamma=-0.1), "gamma"),
])
def test_bad_point_names_the_parameter(kwargs, name):
    """Bad input: a ValueError whose message starts with the parameter's name."""
    base = dict(time=0.0, F0=1.0, fill=(0.5,), oscillation=(1.0, 2.0), gamma=0.1)
    with pytest.raises(ValueError, match=f"^{name}"):
        FlightPoint(**{**base, **kwargs})


def test_bad_timeline_names_the_parameter():
    """Bad input: too few points, times not increasing, tanks differing, t out of range."""
    a = FlightPoint(time=0.0, F0=1.0, fill=(0.5,), oscillation=1.0, gamma=0.1)
    b = FlightPoint(time=0.0, F0=1.0, fill=(0.5,), oscillation=1.0, gamma=0.1)
    c = FlightPoint(time=2.0, F0=1.0, fill=(0.5, 0.2), oscillation=1.0, gamma=0.1)
    with pytest.raises(ValueError, match="^points"):
        Timeline(points=(a,))
    with pytest.raises(ValueError, match=r"^points\[1\].time"):
        Timeline(points=(a, b))
    with pytest.raises(ValueError, match=r"^points\[1\].fill"):
        Timeline(points=(a, c))
    tl = _timeline()
    with pytest.raises(ValueError, match="^t "):
        tl.at(100.5)
    with pytest.raises(ValueError, match="^n, times"):
        frozen_times(tl)
    with pytest.raises(ValueError, match="^n "):
        frozen_times(tl, n=1)
    with pytest.raises(ValueError, match="^times"):
        frozen_times(tl, times=[0.0, 120.0])
    with pytest.raises(ValueError, match="^times"):
        frozen_times(tl, times=[5.0, 5.0])


def test_frozen_case_at_a_point_holds_that_row():
    """flexbooster.model.frozen_case at a [[flight.points]] row's time: that row's fills, F0
    and gamma as written in tests/data/flight_open_pitch_case.toml (t = 100 s: F0 = 1.0 MN,
    fill 0.35, gamma 0.005), Omega over the union of the rows' bands (0.6573 Hz to 14 Hz,
    2 pi x Hz, 1e-12 relative), no [flight]; a case without [flight] is refused."""
    import math
    from pathlib import Path

    import flexbooster
    from flexbooster.model import frozen_case

    case = flexbooster.load_case(Path(__file__).parent / "data" / "flight_open_pitch_case.toml")
    frozen = frozen_case(case, 100.0)
    assert frozen.flight is None and frozen.F0 == pytest.approx(1.0e6, rel=1e-12)
    assert frozen.thrust.gamma == pytest.approx(0.005, rel=1e-12)
    assert [tank.fill for tank in frozen.vehicle.tanks] == pytest.approx([0.35], rel=1e-12)
    assert (frozen.thrust.omega_min, frozen.thrust.omega_max) == pytest.approx(
        (2 * math.pi * 0.6573, 2 * math.pi * 14.0), rel=1e-12)
    with pytest.raises(ValueError, match="flight"):
        frozen_case(frozen, 0.0)
