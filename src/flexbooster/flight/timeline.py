"""The flight as piecewise-linear schedules: mean thrust, tank fill levels, the thrust
oscillation's frequency band and its relative amplitude, linear in time between given points,
and the frozen times at which the vehicle is analysed. Theory: docs/theory/flight.md.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..checks import count, finite, finite_array, nonnegative

__all__ = ["FlightPoint", "Timeline", "frozen_times", "flight_omega_range",
           "KNOWN_FREQUENCY_MARGIN"]

#: A flight whose oscillation is one constant frequency: the regions are searched over that
#: frequency times (1 -+ this), so that a region holding it is found with its edges.
KNOWN_FREQUENCY_MARGIN = 0.05


def _pair(name: str, value: Any) -> tuple[float, float]:
    """An oscillation band (lo, hi) in rad/s from a pair or one value (lo == hi)."""
    if np.ndim(value) == 0:
        lo = hi = finite(name, value)
    else:
        values = finite_array(name, value).ravel()
        if values.size != 2:
            raise ValueError(f"{name} = {value!r:.60}: must be one value or a pair [lo, hi]")
        lo, hi = float(values[0]), float(values[1])
    if not 0.0 < lo <= hi:
        raise ValueError(f"{name} = ({lo!r}, {hi!r}): need 0 < lo <= hi (rad/s)")
    return lo, hi


@dataclass(frozen=True)
class FlightPoint:
    """The state of the flight at one time.

    Attributes
    ----------
    time : float
        Flight time (s), finite.
    F0 : float
        Mean thrust (N), finite and >= 0.
    fill : tuple of float
        Fill level of each tank, each in [0, 1] (0 empty, 1 full); may be empty.
    oscillation : tuple of float
        The band (lo, hi) of thrust-oscillation pulsations Omega (rad/s), 0 < lo <= hi; lo == hi
        for a known frequency. One value is taken as (value, value).
    gamma : float
        Oscillation amplitude over the mean thrust, Delta F = gamma F0 cos(Omega t), >= 0.
    """

    time: float
    F0: float
    fill: tuple[float, ...]
    oscillation: tuple[float, float]
    gamma: float

    def __post_init__(self) -> None:
        object.__setattr__(self, "time", finite("time", self.time))
        object.__setattr__(self, "F0", nonnegative("F0", self.F0))
        fill = finite_array("fill", self.fill, nonempty=False).ravel()
        if np.any((fill < 0.0) | (fill > 1.0)):
            raise ValueError(f"fill = {tuple(fill.tolist())!r:.60}: each must be in [0, 1]")
        object.__setattr__(self, "fill", tuple(float(v) for v in fill))
        object.__setattr__(self, "oscillation", _pair("oscillation", self.oscillation))
        object.__setattr__(self, "gamma", nonnegative("gamma", self.gamma))

    @property
    def known_frequency(self) -> bool:
        """The oscillation is one known pulsation (lo == hi)."""
        return self.oscillation[0] == self.oscillation[1]


@dataclass(frozen=True)
class Timeline:
    """A flight schedule, linear in time between its points.

    Attributes
    ----------
    points : tuple of FlightPoint
        At least two, times strictly increasing, the same number of tanks in each.
    """

    points: tuple[FlightPoint, ...]

    def __post_init__(self) -> None:
        points = tuple(self.points)
        if len(points) < 2:
            raise ValueError(f"points: {len(points)} given, a timeline needs at least 2")
        for i, p in enumerate(points):
            if not isinstance(p, FlightPoint):
                raise ValueError(f"points[{i}] = {p!r:.60}: must be a FlightPoint")
        times = np.array([p.time for p in points])
        if np.any(np.diff(times) <= 0.0):
            i = int(np.argmax(np.diff(times) <= 0.0)) + 1
            raise ValueError(f"points[{i}].time = {times[i]!r}: times must be strictly "
                             f"increasing (previous {times[i - 1]!r})")
        tanks = len(points[0].fill)
        for i, p in enumerate(points):
            if len(p.fill) != tanks:
                raise ValueError(f"points[{i}].fill = {p.fill!r:.60}: must hold {tanks} "
                                 "values like points[0].fill (one per tank)")
        object.__setattr__(self, "points", points)

    @property
    def times(self) -> np.ndarray:
        """The points' times (s), shape (P,)."""
        return np.array([p.time for p in self.points])

    @property
    def start(self) -> float:
        """First time (s)."""
        return self.points[0].time

    @property
    def end(self) -> float:
        """Last time (s)."""
        return self.points[-1].time

    @property
    def duration(self) -> float:
        """end - start (s)."""
        return self.end - self.start

    def at(self, t: float) -> FlightPoint:
        """The schedule at time ``t``: every quantity linear between the neighbouring points.

        Parameters
        ----------
        t : float
            Time (s) in [start, end].
        """
        t = finite("t", t)
        if not self.start <= t <= self.end:
            raise ValueError(f"t = {t!r}: must be in [{self.start!r}, {self.end!r}] (s), the "
                             "timeline's range")
        times = self.times
        i = min(int(np.searchsorted(times, t, side="right")) - 1, len(times) - 2)
        a, b = self.points[i], self.points[i + 1]
        w = (t - a.time) / (b.time - a.time)  # linear interpolation weight

        def mix(x: float, y: float) -> float:
            return (1.0 - w) * x + w * y  # exact at both ends

        return FlightPoint(
            time=t, F0=mix(a.F0, b.F0),
            fill=tuple(min(max(mix(x, y), 0.0), 1.0) for x, y in zip(a.fill, b.fill, strict=True)),
            oscillation=(mix(a.oscillation[0], b.oscillation[0]),
                         mix(a.oscillation[1], b.oscillation[1])),
            gamma=mix(a.gamma, b.gamma))

    def oscillation_at(self, t: Any) -> tuple[np.ndarray, np.ndarray]:
        """The oscillation band's edges (rad/s) at times ``t`` (vectorised :meth:`at`).

        Parameters
        ----------
        t : array_like
            Times (s) in [start, end].
        """
        t = finite_array("t", t, nonempty=False)
        if np.any((t < self.start) | (t > self.end)):
            raise ValueError(f"t: must be in [{self.start!r}, {self.end!r}] (s)")
        times = self.times
        lo = np.interp(t, times, [p.oscillation[0] for p in self.points])
        hi = np.interp(t, times, [p.oscillation[1] for p in self.points])
        return lo, hi


def frozen_times(timeline: Timeline, *, n: int | None = None, times: Any = None,
                 include_points: bool = False) -> np.ndarray:
    """The frozen times (s) at which the vehicle is analysed, strictly increasing.

    Parameters
    ----------
    timeline : Timeline
        The flight.
    n : int, optional
        That many times equally spaced over [start, end], both ends included (2..10000).
    times : array_like, optional
        The times themselves, strictly increasing, within [start, end]. Exactly one of ``n``
        and ``times``.
    include_points : bool
        Also include the timeline's own points, so that the schedules are sampled at every
        corner (the result may then hold more than ``n`` times).
    """
    if not isinstance(timeline, Timeline):
        raise ValueError(f"timeline = {timeline!r:.60}: must be a Timeline")
    if (n is None) == (times is None):
        raise ValueError("n, times: give exactly one of them")
    if n is not None:
        n = count("n", n, low=2, high=10_000)
        out = np.linspace(timeline.start, timeline.end, n)
    else:
        out = finite_array("times", times).ravel()
        if np.any(np.diff(out) <= 0.0):
            raise ValueError(f"times = {out.tolist()!r:.60}: must be strictly increasing")
        if out[0] < timeline.start or out[-1] > timeline.end:
            raise ValueError(f"times = {out.tolist()!r:.60}: must lie in "
                             f"[{timeline.start!r}, {timeline.end!r}] (s)")
    if include_points:
        out = np.union1d(out, timeline.times)
        # merge times closer than rounding (an equally spaced time on a corner)
        keep = np.concatenate([[True], np.diff(out) > 1e-12 * max(1.0, math.fabs(out[-1]))])
        out = out[keep]
    return out


def flight_omega_range(timeline) -> tuple[float, float]:
    """The Omega range (rad/s) searched at every frozen time: the union of the oscillation
    bands, widened by :data:`KNOWN_FREQUENCY_MARGIN` around one constant frequency.

    Parameters
    ----------
    timeline : flexbooster.flight.Timeline
        The flight's schedule (:func:`flexbooster.model.timeline_from_case`).
    """
    lo = min(p.oscillation[0] for p in timeline.points)
    hi = max(p.oscillation[1] for p in timeline.points)
    if hi <= lo:
        return lo * (1.0 - KNOWN_FREQUENCY_MARGIN), hi * (1.0 + KNOWN_FREQUENCY_MARGIN)
    return lo, hi
