"""Instability regions in the (Omega, gamma) plane, drawn from their traced boundaries."""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure

from ...memo.charts import BandChart
from .layout import new_axes

__all__ = ["plot_band_chart"]


def plot_band_chart(chart: BandChart, ax: Axes | None = None, *,
                    omega_1: float | None = None) -> Figure:
    """Shade each region between its traced edges, Omega in Hz (log) against gamma, the operating
    gamma dashed (Bolotin 1964, ch. 1; memo 4.1-4.2).

    Parameters
    ----------
    chart : BandChart
        From :func:`flexbooster.memo.charts.pitch_band_chart` or ``beam_action_chart``.
    ax : matplotlib.axes.Axes, optional
        Axes to draw on; a new figure is made when None.
    omega_1 : float, optional
        First bending frequency (rad/s), > 0: adds a secondary axis Omega / omega_1 on top.
    """
    fig, ax = new_axes(ax, (6.4, 4.8))
    to_hz = 1.0 / (2.0 * np.pi)
    for i, reg in enumerate(chart.regions):
        x = np.concatenate([reg.omega_lo, reg.omega_hi[::-1]]) * to_hz
        y = np.concatenate([reg.gamma, reg.gamma[::-1]])
        ax.fill(x, y, color="C3", alpha=0.35, lw=0.6, ec="C3",
                label="unstable" if i == 0 else None)
    ax.axhline(chart.gamma_operating, color="C0", ls="--", lw=1.6,
               label=f"operating gamma = {chart.gamma_operating:g}")
    ax.annotate(f"operating gamma {chart.gamma_operating:g}", (1.0, chart.gamma_operating),
                xycoords=("axes fraction", "data"), xytext=(-4, 3), textcoords="offset points",
                ha="right", va="bottom", fontsize=8, color="C0")
    if not chart.regions:
        ax.text(0.5, 0.5, "no instability region in the range", transform=ax.transAxes,
                ha="center", va="center")
    ax.set_xscale("log")
    ax.set_xlim(chart.omega_min * to_hz, chart.omega_max * to_hz)
    ax.set_ylim(0.0, chart.gamma_max)
    ax.set_xlabel("thrust frequency Omega (Hz)")
    ax.set_ylabel("gamma (pulsation amplitude)")
    ax.set_title(chart.title)
    from .labels import plain_log_ticks

    plain_log_ticks(ax.xaxis)
    if omega_1 is not None and omega_1 > 0:
        w1_hz = omega_1 * to_hz
        sec = ax.secondary_xaxis("top", functions=(lambda f: f / w1_hz, lambda r: r * w1_hz))
        sec.set_xlabel("Omega / omega_1")
        plain_log_ticks(sec.xaxis)
    ax.legend(loc="upper left", fontsize=8)
    return fig
