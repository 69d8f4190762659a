"""What the flight stage (:mod:`flexbooster.flight_stage`) found: the frozen times, the vehicle's
mass properties, modes (tracked across times), parametric regions and k = 0 axial resonances at
each, and the flight's events, the worst first (results.json ``"flight"``; flight-modes.csv,
flight-events.csv). Theory: docs/theory/flight.md.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .danger import event_status
from .flight import EVENT_COLUMNS, MODE_COLUMNS, FlightEvent, TrackedModes, mode_rows

__all__ = ["FlightHarmonic", "FlightResults", "EVENT_COLUMNS", "MODE_COLUMNS", "verdict_order"]


@dataclass(frozen=True)
class FlightHarmonic:
    """The tracked modes of one harmonic k through the frozen times.

    Attributes
    ----------
    k : int
        Circumferential wave number.
    frequencies : numpy.ndarray
        (T, N): the frequency (rad/s) of identity j at frozen time t; NaN where absent
        (:class:`flexbooster.flight.TrackedModes`).
    types : numpy.ndarray
        (T, N) str: each identity's mode type at each time ("" where absent).
    mac : numpy.ndarray
        (T - 1, N): MAC of identity j between times t and t + 1; NaN where absent.
    order : numpy.ndarray
        (T, N) int: identity j's column among the harmonic's modes (ascending frequency) at
        time t; -1 where absent.
    """

    k: int
    frequencies: np.ndarray
    types: np.ndarray
    mac: np.ndarray
    order: np.ndarray

    @property
    def min_mac(self) -> float:
        """The smallest MAC of a continued identity (1.0 where none)."""
        values = self.mac[np.isfinite(self.mac)]
        return float(values.min()) if values.size else 1.0

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready mapping (None for NaN)."""
        def plain(a: np.ndarray) -> list:
            return [[None if not np.isfinite(v) else float(v) for v in row] for row in a]

        return {"k": int(self.k), "hz": plain(self.frequencies / (2.0 * np.pi)),
                "types": self.types.tolist(), "mac": plain(self.mac),
                "min_mac": self.min_mac}


def verdict_order(events) -> tuple[FlightEvent, ...]:
    """The events in the verdict's order: those that count (:func:`flexbooster.danger.event_status`
    not negligible), then those of negligible growth, each in the given (worst-first) order; the
    order of flight-events.csv, the report's list and the Campbell diagram's numbers.

    Parameters
    ----------
    events : sequence of FlightEvent
        The events, the worst first (:func:`flexbooster.flight.worst_first`).
    """
    return tuple(sorted(events, key=lambda e: event_status(e) == "negligible"))  # stable


@dataclass(frozen=True)
class FlightResults:
    """The vehicle through its flight.

    Attributes
    ----------
    times : numpy.ndarray
        (T,) frozen times (s), strictly increasing.
    F0, gamma : numpy.ndarray
        (T,) mean thrust (N) and relative oscillation amplitude at each time.
    fill : numpy.ndarray
        (T, n_tanks) fill level of each tank.
    oscillation : numpy.ndarray
        (T, 2) the oscillation band (lo, hi) at each time (rad/s).
    tank_names : tuple of str
        The tanks, in the order of ``fill``'s columns.
    mass : tuple of MassProperties
        Per time, the vehicle's mass properties.
    harmonics : tuple of FlightHarmonic
        The tracked modes of k = 0..k_max.
    regions : tuple of tuple of Band
        Per time, the parametric regions of k = 1..k_max over ``omega_range``.
    omega_range : tuple of float
        The Omega range (rad/s) of the regions: the union of the oscillation bands.
    events : tuple of FlightEvent
        The regions and resonances the oscillation band meets, in :func:`verdict_order`.
    gaps : tuple of SearchGap
        What the searches' limits left out, at any frozen time.
    notes : tuple of str
        What the flight does not cover (e.g. a forced response not computed), for the summary.
    """

    times: np.ndarray
    F0: np.ndarray
    gamma: np.ndarray
    fill: np.ndarray
    oscillation: np.ndarray
    tank_names: tuple
    mass: tuple
    harmonics: tuple
    regions: tuple
    omega_range: tuple
    events: tuple
    gaps: tuple = ()
    notes: tuple = field(default=())

    @property
    def counted(self) -> tuple[FlightEvent, ...]:
        """The events that count (:func:`flexbooster.danger.event_status` not negligible: a
        region whose growth is below the verdict's floors is dropped), worst first."""
        return tuple(e for e in self.events if event_status(e) != "negligible")

    @property
    def dropped(self) -> int:
        """How many events of negligible growth :attr:`counted` leaves out."""
        return len(self.events) - len(self.counted)

    @property
    def worst(self) -> FlightEvent | None:
        """The worst event that counts (the first of :attr:`counted`), None where the
        oscillation meets nothing that counts."""
        counted = self.counted
        return counted[0] if counted else None

    def mode_rows(self) -> list[dict[str, Any]]:
        """The rows of flight-modes.csv (:data:`MODE_COLUMNS`): per harmonic
        :func:`flexbooster.flight.mode_rows` of its tracked modes."""
        return [row for h in self.harmonics for row in mode_rows(
            self.times, TrackedModes(order=h.order, mac=h.mac, frequencies=h.frequencies),
            k=h.k, types=h.types)]

    def event_rows(self) -> list[dict[str, Any]]:
        """The rows of flight-events.csv (:data:`EVENT_COLUMNS`), in :func:`verdict_order`."""
        return [e.to_dict() for e in self.events]

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready mapping (results.json ``"flight"``)."""
        worst = self.worst
        return {
            "times_s": self.times.tolist(), "F0_N": self.F0.tolist(),
            "gamma": self.gamma.tolist(), "fill": self.fill.tolist(),
            "tank_names": list(self.tank_names),
            "oscillation_rad_s": self.oscillation.tolist(),
            "omega_range_rad_s": [float(v) for v in self.omega_range],
            "mass_properties": [m.to_dict() for m in self.mass],
            "modes": [h.to_dict() for h in self.harmonics],
            "regions": [[b.to_dict() for b in bands] for bands in self.regions],
            "events": self.event_rows(),
            "worst": None if worst is None else worst.to_dict(),
            "events_dropped": self.dropped,
            "gaps": [g.to_dict() for g in self.gaps],
            "notes": list(self.notes),
        }

