"""Figures of the vehicle's forced response: acceleration per station against Omega, and the
load envelopes along the vehicle.

Draws a stored :class:`~flexbooster.results.ForcedLoads` (its curves on the case's Omega grid or
spectrum lines, its peaks and its envelopes); it computes nothing but unit conversions.
"""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure

from ...dynamics.forced import STANDARD_GRAVITY
from ...results import ForcedLoads

__all__ = ["forced_acceleration_chart", "forced_envelope_chart"]

_TO_HZ = 1.0 / (2.0 * np.pi)
_STYLE = {0: "-", 1: "--"}
_WORDS = {0: "axial", 1: "lateral"}


def _new(ax: Axes | None, size: tuple[float, float]) -> tuple[Figure, Axes]:
    if ax is not None:
        return ax.figure, ax
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=size)
    return fig, ax


def forced_acceleration_chart(loads: ForcedLoads, ax: Axes | None = None) -> Figure:
    """Acceleration amplitude in g at every station against Omega in Hz (log y): the stored curves
    (k = 0 solid, k = 1 dashed; a spectrum: its lines as stems) and each station's peak (the
    resonance's, not the grid's) as a marker.

    Parameters
    ----------
    loads : ForcedLoads
        The stored forced response.
    ax : matplotlib.axes.Axes, optional
        Axes to draw on; a new figure is made when None.
    """
    fig, ax = _new(ax, (7.0, 4.6))
    r = loads.response
    hz = r.omega * _TO_HZ
    acc = np.abs(r.acceleration) / STANDARD_GRAVITY
    colours = {s.name: f"C{i % 10}" for i, s in enumerate(r.stations)}
    drawn = False
    for ik, k in enumerate(r.harmonics):
        if loads.convergence[ik] is None:  # not forced: zero everywhere
            continue
        for js, s in enumerate(r.stations):
            y = np.where(acc[ik, js] > 0.0, acc[ik, js], np.nan)
            label = f"{s.name} ({s.x:.3g} m), {_WORDS[k]}"
            if r.combination == "spectrum":
                ax.plot(hz, y, "o", color=colours[s.name], label=label, ms=4)
            else:
                ax.plot(hz, y, _STYLE[k], color=colours[s.name], label=label, lw=1.0)
            p = r.peak(k, s.name, "acceleration")
            if p.value > 0.0 and r.combination == "sweep":
                ax.plot([p.omega * _TO_HZ], [p.value / STANDARD_GRAVITY], "v",
                        color=colours[s.name], ms=5)
            drawn = drawn or bool(np.any(acc[ik, js] > 0.0))
    if drawn:
        ax.set_yscale("log")
        ax.legend(fontsize="x-small", ncol=2)
    else:
        ax.text(0.5, 0.5, "no thrust oscillation: zero response", transform=ax.transAxes,
                ha="center", va="center")
    what = ("the spectrum's lines" if r.combination == "spectrum"
            else f"gamma = {r.amplitude[0]:.3g}")
    ax.set_title(f"Acceleration amplitude at the stations ({what}; peaks marked)")
    ax.set_xlabel("thrust oscillation frequency Omega (Hz)")
    ax.set_ylabel("acceleration amplitude (g)")
    ax.grid(True, which="both", alpha=0.3)
    return fig


def forced_envelope_chart(loads: ForcedLoads, ax: Axes | None = None) -> Figure:
    """The axial force (k = 0) and bending moment (k = 1) amplitudes along the vehicle at the Omega
    where each is largest, and the envelope of the peaks over the Omega range (dotted).

    Parameters
    ----------
    loads : ForcedLoads
        The stored forced response.
    ax : matplotlib.axes.Axes, optional
        Axes of the axial force; the bending moment on a twin axis. A new figure when None.
    """
    fig, ax = _new(ax, (7.0, 4.6))
    r = loads.response
    forced = {k: loads.convergence[ik] is not None for ik, k in enumerate(r.harmonics)}
    panels = [(ax, "axial_force", 0, "C0", "axial force amplitude (N)")]
    if forced.get(1, False):
        panels.append((ax.twinx(), "bending_moment", 1, "C3", "bending moment amplitude (N m)"))
    for axis, quantity, k, colour, label in panels:
        env = next((e for e in r.envelopes if e.quantity == quantity), None)
        if env is None or not forced.get(k, False):
            continue
        axis.plot(env.x, np.abs(env.at_worst), "-", color=colour,
                  label=f"{quantity.replace('_', ' ')} at {env.worst_omega * _TO_HZ:.4g} Hz")
        axis.plot(env.x, env.peak, ":", color=colour, label="peak over the range")
        axis.set_ylabel(label, color=colour)
        axis.legend(loc="upper left" if k == 0 else "lower center", fontsize="x-small")
    for s in r.stations:
        ax.axvline(s.x, color="0.8", lw=0.6)
    ax.set_xlabel("station: distance from the aft edge (m)")
    ax.set_title("Internal loads along the vehicle at the worst Omega")
    return fig
