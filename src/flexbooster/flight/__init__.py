"""The flight: piecewise-linear schedules (:mod:`.timeline`), mode tracking across frozen
times (:mod:`.tracking`), passage through regions and resonances (:mod:`.passage`) and the
events of the flight (:mod:`.events`). Numerical core: numpy and scipy only. Theory:
``docs/theory/flight.md``.
"""

from .events import (
    EVENT_COLUMNS,
    MAX_PASS_OVER_SEARCHES,
    PASS_OVER_ORDERS,
    PASS_OVER_REACH,
    PASS_OVER_WINDOW,
    FlightEvent,
    PassOver,
    band_events,
    band_key,
    band_rate,
    meeting_intervals,
    pass_over_windows,
    passes_over,
    resonance_events,
    worst_first,
)
from .passage import (
    MAX_SWEEP_STEPS,
    SWEEP_WINDOW,
    Passage,
    ResonancePassage,
    accumulated_growth,
    crossing_peak_ratio,
    peak_ratio,
    steady_peak,
    step_maps,
    sweep_passage,
    sweep_response,
)
from .timeline import (
    KNOWN_FREQUENCY_MARGIN,
    FlightPoint,
    Timeline,
    flight_omega_range,
    frozen_times,
)
from .tracking import MODE_COLUMNS, TrackedModes, mac_matrix, mode_rows, track_modes

__all__ = ["FlightPoint", "Timeline", "frozen_times", "flight_omega_range",
           "KNOWN_FREQUENCY_MARGIN", "TrackedModes", "MODE_COLUMNS",
           "mac_matrix", "mode_rows", "track_modes", "MAX_SWEEP_STEPS", "SWEEP_WINDOW",
           "Passage", "ResonancePassage", "accumulated_growth", "crossing_peak_ratio",
           "peak_ratio", "steady_peak", "step_maps", "sweep_passage", "sweep_response",
           "EVENT_COLUMNS", "FlightEvent", "band_events", "band_key", "band_rate",
           "meeting_intervals", "resonance_events", "worst_first", "PASS_OVER_ORDERS",
           "PASS_OVER_WINDOW", "PASS_OVER_REACH", "MAX_PASS_OVER_SEARCHES", "PassOver",
           "passes_over", "pass_over_windows"]
