"""The flight in the outputs: the summary's "Flight" lines (the worst moment first), the
report's section, flight-modes.csv and flight-events.csv (:mod:`flexbooster.flight_results`).
"""

from __future__ import annotations

import html
from pathlib import Path

from ..danger import NEGLIGIBLE_AMPLIFICATION, NEGLIGIBLE_GROWTH, g_text
from ..flight_results import EVENT_COLUMNS, MODE_COLUMNS, FlightResults
from .io import write_csv_atomic

__all__ = ["FLIGHT_CSVS", "FLIGHT_FIGURES", "flight_lines", "flight_report_html",
           "write_flight_csvs", "flight_figure_names", "event_text"]

#: The flight's figure (file stem) and its caption in the report.
#: The flight's tables in the output set.
FLIGHT_CSVS = ("flight-modes.csv", "flight-events.csv")
FLIGHT_FIGURES = {
    "flight-campbell": (
        "The flight's Campbell diagram: the frequencies of the tracked modes of every harmonic "
        "k against flight time, the thrust oscillation band shaded grey, and the events (bars "
        "along the top, numbered as in the list: those that count, the worst first, then those "
        "of negligible growth; black a parametric region met by the band, red a k = 0 "
        "resonance crossed)."),
}


def event_text(e) -> str:
    """One event in words: mechanism, k, modes, interval, growth or peak.

    Parameters
    ----------
    e : FlightEvent
        The event.
    """
    k = "" if e.k is None else f" k = {e.k}"
    what = (f"peak {g_text(e.peak_acceleration_g)} at {e.station}"
            if e.peak_acceleration_g is not None
            else f"max growth {e.max_growth_1_s:.3g} 1/s, {e.efolds:.3g} e-folds "
                 f"(amplification {e.amplification:.4g})")
    return (f"{e.mechanism}{k} {e.modes}: t = {e.t_start_s:.4g}..{e.t_end_s:.4g} s "
            f"(dwell {e.dwell_s:.3g} s), {what}")


def flight_lines(flight: FlightResults) -> list[str]:
    """The summary's "Flight" lines: the worst moment first, then every event that counts,
    how many of negligible growth were dropped, the notes.

    Parameters
    ----------
    flight : FlightResults
        The flight.
    """
    t = flight.times
    out = [f"{t.size} frozen times over t = {t[0]:.4g}..{t[-1]:.4g} s; mass "
           f"{flight.mass[0].mass_kg:.4g} -> {flight.mass[-1].mass_kg:.4g} kg"]
    worst = flight.worst
    if worst is None:
        out.insert(0, "Worst moment: the oscillation band meets no region that counts and no "
                      "k = 0 resonance during the flight")
    else:
        out.insert(0, "Worst moment: " + event_text(worst))
        out += [f"{n + 1}. {event_text(e)}" for n, e in enumerate(flight.counted)]
    if flight.dropped:
        n = flight.dropped
        out.append(f"{n} event{'s' if n > 1 else ''} of negligible growth dropped (growth "
                   f"rate under {NEGLIGIBLE_GROWTH:g} 1/s or amplification under "
                   f"{NEGLIGIBLE_AMPLIFICATION:g}; all in {FLIGHT_CSVS[1]})")
    mins = [f"k = {h.k}: {h.min_mac:.2f}" for h in flight.harmonics]
    out.append("smallest MAC of a tracked mode between neighbouring times: " + ", ".join(mins))
    if flight.gaps:
        out.append(f"not fully searched: {len(flight.gaps)} harmonics past a search limit "
                   "(results.json flight.gaps)")
    out += [f"note: {n}" for n in flight.notes]
    return out


def flight_report_html(flight: FlightResults) -> str:
    """The report's flight section: the lines of :func:`flight_lines` (the figure is the
    report's ``flight-campbell``).

    Parameters
    ----------
    flight : FlightResults
        The flight.
    """
    items = "".join(f"<li>{html.escape(line)}</li>" for line in flight_lines(flight))
    return f"<ul>{items}</ul>"


def write_flight_csvs(flight: FlightResults | None, folder: Path) -> list[Path]:
    """flight-modes.csv and flight-events.csv in ``folder`` (none without a flight).

    Parameters
    ----------
    flight : FlightResults or None
        The flight.
    folder : pathlib.Path
        The output set's staging folder.
    """
    if flight is None:
        return []
    modes = flight.mode_rows() or {c: [] for c in MODE_COLUMNS}
    events = flight.event_rows() or {c: [] for c in EVENT_COLUMNS}
    return [write_csv_atomic(Path(folder) / FLIGHT_CSVS[0], modes),
            write_csv_atomic(Path(folder) / FLIGHT_CSVS[1], events)]


def flight_figure_names(flight: FlightResults | None) -> tuple[str, ...]:
    """The flight's figure names (none without a flight).

    Parameters
    ----------
    flight : FlightResults or None
        The flight.
    """
    return () if flight is None else tuple(FLIGHT_FIGURES)
