"""The optional ``[flight]`` table of a case file: the vehicle through its flight.

``[[flight.points]]`` rows give, at their ``time``, the mean thrust ``F0``, the ``fill`` of
each tank of ``[[vehicle.tanks]]`` (in that order), the band of the thrust oscillation's
frequency ``oscillation`` (``[lo, hi]`` or one value for a known frequency; "Hz" values are
cyclic) and its relative amplitude ``gamma``; every quantity is linear in time between the
points (:class:`flexbooster.flight.Timeline`). ``stations`` equally spaced frozen times, or
the frozen ``times`` themselves, are where the vehicle is analysed
(docs/theory/flight.md). An invalid field raises :class:`~flexbooster.errors.CaseError`
naming it, e.g. ``flight.points[2].fill``.
"""

from __future__ import annotations

import math
from typing import Any

from pydantic import BaseModel, ConfigDict, StrictInt, field_validator

from .errors import CaseError
from .units import to_si

__all__ = ["FLIGHT_STATIONS", "FLIGHT_STATIONS_LIMIT", "FlightPointTable", "FlightTable",
           "check_flight"]

#: Default number of equally spaced frozen times (``flight.stations``).
FLIGHT_STATIONS = 11
#: Largest ``flight.stations`` (and number of ``flight.times``) a case may ask for.
FLIGHT_STATIONS_LIMIT = 1000

_FROZEN = ConfigDict(extra="forbid", frozen=True)


def _scalar(kind: str, rule: str):
    """Validator: ``to_si`` of ``kind``, then ``rule`` (">=0", "any", "[0,1)")."""
    def convert(cls, value: Any, info) -> float:  # noqa: ANN001
        result = to_si(info.field_name, value, kind)
        if rule == ">=0" and not result >= 0.0:
            raise ValueError("must be >= 0")
        if rule == "[0,1)" and not 0.0 <= result < 1.0:
            raise ValueError("must lie in [0, 1)")
        return result

    return convert


class FlightPointTable(BaseModel):
    """One ``[[flight.points]]`` row.

    Attributes
    ----------
    time : float
        Flight time (s), finite.
    F0 : float
        Mean thrust (N), > 0.
    fill : tuple of float
        Fill level of each tank of ``[[vehicle.tanks]]``, in that order, each in [0, 1].
    oscillation : tuple of float
        (lo, hi): the band of the oscillation's pulsation Omega (rad/s), 0 < lo <= hi; one
        value in the file gives lo = hi (a known frequency).
    gamma : float
        Oscillation amplitude over the mean thrust, [0, 1).
    """

    model_config = _FROZEN
    time: float
    F0: float
    fill: tuple[float, ...] = ()
    oscillation: tuple[float, float]
    gamma: float

    _time = field_validator("time", mode="before")(_scalar("time", "any"))
    _gamma = field_validator("gamma", mode="before")(_scalar("dimensionless", "[0,1)"))

    @field_validator("F0", mode="before")
    @classmethod
    def _F0(cls, value: Any) -> float:
        result = to_si("F0", value, "force")
        if not result > 0.0:
            raise ValueError("must be positive (N)")
        return result

    @field_validator("fill", mode="before")
    @classmethod
    def _fill(cls, value: Any) -> tuple[float, ...]:
        values = value if isinstance(value, list | tuple) else [value]
        out = tuple(to_si("fill", v, "dimensionless") for v in values)
        if any(not 0.0 <= v <= 1.0 for v in out):
            raise ValueError(f"each value must lie in [0, 1] (got {list(out)})")
        return out

    @field_validator("oscillation", mode="before")
    @classmethod
    def _oscillation(cls, value: Any) -> tuple[float, float]:
        values = list(value) if isinstance(value, list | tuple) else [value, value]
        if len(values) != 2:
            raise ValueError(f"must be one frequency or a band [lo, hi] ({len(values)} given)")
        lo, hi = (to_si("oscillation", v, "angular_frequency") for v in values)
        if not 0.0 < lo <= hi:
            raise ValueError(f"need 0 < lo <= hi (got {lo!r}, {hi!r} rad/s)")
        return lo, hi


class FlightTable(BaseModel):
    """The ``[flight]`` table.

    Attributes
    ----------
    duration : float or None
        Length of the flight (s), > 0; when given it must equal the last point's time minus
        the first's (a check on the schedule).
    stations : int or None
        Number of equally spaced frozen times, 2..:data:`FLIGHT_STATIONS_LIMIT`; default
        :data:`FLIGHT_STATIONS` (without ``times``). The points' own times are added.
    times : tuple of float or None
        The frozen times (s) themselves, strictly increasing, within the points' times.
    points : tuple of FlightPointTable
        At least two, times strictly increasing.
    """

    model_config = _FROZEN
    duration: float | None = None
    stations: StrictInt | None = None
    times: tuple[float, ...] | None = None
    points: tuple[FlightPointTable, ...]

    @field_validator("duration", mode="before")
    @classmethod
    def _duration(cls, value: Any) -> float | None:
        if value is None:
            return None
        result = to_si("duration", value, "time")
        if not result > 0.0:
            raise ValueError("must be a time > 0 (s)")
        return result

    @field_validator("stations")
    @classmethod
    def _stations(cls, value: int | None) -> int | None:
        if value is not None and not 2 <= value <= FLIGHT_STATIONS_LIMIT:
            raise ValueError(f"must be in 2..{FLIGHT_STATIONS_LIMIT}")
        return value

    @field_validator("times", mode="before")
    @classmethod
    def _times(cls, value: Any) -> tuple[float, ...] | None:
        if value is None:
            return None
        if not isinstance(value, list | tuple) or len(value) < 1:
            raise ValueError("must be a list of at least one time")
        out = tuple(to_si("times", v, "time") for v in value)
        if len(out) > FLIGHT_STATIONS_LIMIT:
            raise ValueError(f"at most {FLIGHT_STATIONS_LIMIT} times")
        if any(b <= a for a, b in zip(out, out[1:], strict=False)):
            raise ValueError("must be strictly increasing")
        return out


def check_flight(flight: FlightTable | None, *, n_tanks: int) -> None:
    """Rules of the ``[flight]`` table that involve more than one field (CaseError naming it).

    Parameters
    ----------
    flight : FlightTable or None
        The validated table (None: nothing to check).
    n_tanks : int
        Number of ``[[vehicle.tanks]]``.
    """
    if flight is None:
        return
    points = flight.points
    if len(points) < 2:
        raise CaseError("flight.points", len(points),
                        "needs at least 2 points (a schedule linear between them)")
    for i in range(1, len(points)):
        if not points[i].time > points[i - 1].time:
            raise CaseError(f"flight.points[{i}].time", points[i].time,
                            f"must be later than points[{i - 1}].time = {points[i - 1].time!r} s")
    for i, p in enumerate(points):
        if len(p.fill) != n_tanks:
            where = ("one per tank of [[vehicle.tanks]], in their order" if n_tanks
                     else "none: the case has no [[vehicle.tanks]]")
            raise CaseError(f"flight.points[{i}].fill", list(p.fill),
                            f"needs {n_tanks} values, {where}")
    start, end = points[0].time, points[-1].time
    if flight.duration is not None and not math.isclose(flight.duration, end - start,
                                                         rel_tol=1e-9, abs_tol=1e-12):
        raise CaseError("flight.duration", flight.duration,
                        f"must equal the points' span {end - start!r} s (points[0].time = "
                        f"{start!r} to points[{len(points) - 1}].time = {end!r})")
    if flight.times is not None:
        if flight.stations is not None:
            raise CaseError("flight.stations", flight.stations,
                            "give stations or times, not both")
        if flight.times[0] < start or flight.times[-1] > end:
            raise CaseError("flight.times", list(flight.times),
                            f"must lie within the points' times [{start!r}, {end!r}] s")
