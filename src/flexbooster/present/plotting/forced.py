"""Figures of the vehicle's forced response: acceleration per station against Omega, and the
load envelopes along the vehicle.

Draws a stored :class:`~flexbooster.results.ForcedLoads` (its curves on the case's Omega grid or
spectrum lines, its peaks and its envelopes); it computes nothing but unit conversions.
"""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.ticker import MaxNLocator

from ...dynamics.forced import STANDARD_GRAVITY
from ...results import ForcedLoads
from .layout import new_axes, panel_axes

__all__ = ["forced_acceleration_chart", "forced_envelope_chart"]

_TO_HZ = 1.0 / (2.0 * np.pi)
_STYLE = {0: "-", 1: "--"}
_WORDS = {0: "axial", 1: "lateral"}


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
    fig, ax = new_axes(ax, (7.0, 4.6))
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
    where each is largest, and the envelope of the peaks over the Omega range (dotted): one
    panel per forced quantity, the stations marked.

    Parameters
    ----------
    loads : ForcedLoads
        The stored forced response.
    ax : matplotlib.axes.Axes, optional
        Its place is split into the panels; a new figure is made when None.
    """
    r = loads.response
    forced = {k: loads.convergence[ik] is not None for ik, k in enumerate(r.harmonics)}
    wanted = [(q, k, c, lab) for q, k, c, lab in (
        ("axial_force", 0, "C0", "axial force amplitude (N)"),
        ("bending_moment", 1, "C3", "bending moment amplitude (N m)"))
        if forced.get(k, False) and any(e.quantity == q for e in r.envelopes)]
    fig, axes = panel_axes(ax, max(1, len(wanted)), (7.0, 1.4 + 2.8 * max(1, len(wanted))))
    for axis, (quantity, _k, colour, label) in zip(axes, wanted, strict=False):
        env = next(e for e in r.envelopes if e.quantity == quantity)
        axis.plot(env.x, np.abs(env.at_worst), "-", color=colour,
                  label=f"{quantity.replace('_', ' ')} at {env.worst_omega * _TO_HZ:.4g} Hz")
        axis.plot(env.x, env.peak, ":", color=colour, label="peak over the range")
        axis.set_ylabel(label)
        # ticks independent of the panel's height: the labels the layout measures are drawn
        axis.yaxis.set_major_locator(MaxNLocator(nbins=6))
        axis.legend(loc="upper right", fontsize="x-small")
    if not wanted:
        axes[0].text(0.5, 0.5, "no thrust oscillation: zero loads", transform=axes[0].transAxes,
                     ha="center", va="center")
    for axis in axes:
        for s in r.stations:
            axis.axvline(s.x, color="0.8", lw=0.6)
    for axis in axes[:-1]:
        axis.tick_params(axis="x", labelbottom=False)
    axes[-1].set_xlabel("station: distance from the aft edge (m)")
    axes[0].set_title("Internal loads along the vehicle at the worst Omega")
    return fig
