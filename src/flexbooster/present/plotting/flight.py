"""The flight's Campbell diagram: the lowest modes per harmonic k against flight time, the thrust
oscillation band shaded over them and the flight's events marked (docs/theory/flight.md).
Draws the stored :class:`~flexbooster.flight_results.FlightResults` only.
"""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure

from ...flight_results import FlightResults
from .layout import new_axes

__all__ = ["flight_campbell", "CAMPBELL_TOP_FACTOR"]

#: The frequency axis ends at this times the top of the oscillation band.
CAMPBELL_TOP_FACTOR = 2.0


def flight_campbell(flight: FlightResults, ax: Axes | None = None) -> Figure:
    """Frequencies (Hz) of the tracked modes of every harmonic against flight time (s), one
    colour per k; the oscillation band shaded; each event's interval marked along the top.

    Parameters
    ----------
    flight : FlightResults
        The stored flight results.
    ax : matplotlib.axes.Axes, optional
        Axes to draw on; a new figure by default.
    """
    fig, ax = new_axes(ax, (7.5, 4.5))
    t = flight.times
    lo, hi = flight.oscillation[:, 0] / (2 * np.pi), flight.oscillation[:, 1] / (2 * np.pi)
    top = CAMPBELL_TOP_FACTOR * float(hi.max())
    colours = {h.k: f"C{n % 10}" for n, h in enumerate(flight.harmonics)}
    for h in flight.harmonics:
        hz = h.frequencies / (2 * np.pi)
        for j in range(hz.shape[1]):
            if np.nanmin(hz[:, j]) <= top:
                ax.plot(t, hz[:, j], color=colours[h.k], lw=1.0,
                        label=f"k = {h.k}" if j == 0 else None)
    ax.fill_between(t, lo, hi, color="0.5", alpha=0.3, lw=0, label="oscillation band")
    if np.all(lo == hi):
        ax.plot(t, lo, color="0.3", lw=1.5)
    for n, e in enumerate(flight.events):
        y = top * (0.97 - 0.04 * (n % 5))
        ax.plot([e.t_start_s, e.t_end_s], [y, y], color="k" if e.mechanism != "forced"
                else "C3", lw=3, solid_capstyle="butt")
        ax.annotate(f"{n + 1}", (e.t_start_s, y), fontsize=7, xytext=(2, -3), va="top",
                    textcoords="offset points")
    ax.set_ylim(0.0, top)
    ax.set_xlim(float(t[0]), float(t[-1]))
    ax.set_xlabel("flight time (s)")
    ax.set_ylabel("frequency (Hz)")
    ax.set_title("Flight Campbell diagram: modes per k, oscillation band (grey), events\n"
                 "(bars: black regions, red resonances, numbered as listed: the worst first)",
                 fontsize=9)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    return fig
