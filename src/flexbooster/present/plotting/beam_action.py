"""Instability chart of the beam-action system in the (Omega, gamma) plane (memo 4.1, ref. 11)."""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.colors import LogNorm
from matplotlib.figure import Figure

from ...memo.beam_action import StabilityChart
from .labels import plain_log_ticks
from .layout import axes_with_colorbar

__all__ = ["plot_stability_chart"]


def plot_stability_chart(chart: StabilityChart, ax: Axes | None = None) -> Figure:
    """Unstable points of the beam-action system coloured by the growth rate (1/s, log), gamma
    against Omega in Hz (log) (Bolotin 1964, ch. 3; memo 4.1).

    Parameters
    ----------
    chart : StabilityChart
        Result of :func:`flexbooster.memo.beam_action.stability_chart`.
    ax : matplotlib.axes.Axes, optional
        Axes to draw on; a new figure is made when None.
    """
    x = chart.Omega / (2.0 * np.pi)  # rad/s -> Hz
    growth = np.where(chart.stable, np.nan, chart.growth_rate)
    finite = growth[np.isfinite(growth)]
    fig, ax, cax = axes_with_colorbar(ax, (6.4, 4.8), colorbar=bool(finite.size))
    if finite.size:
        lo = max(float(finite.min()), 1e-12)
        hi = max(float(finite.max()), lo * 10.0)
        mesh = ax.pcolormesh(x, chart.gamma, np.ma.masked_invalid(growth), shading="nearest",
                             norm=LogNorm(vmin=lo, vmax=hi), cmap="magma_r")
        fig.colorbar(mesh, ax=ax, cax=cax, label="growth rate max |Im alpha| Omega (1/s)")
    else:
        ax.text(0.5, 0.5, f"stable at all {chart.stable.size} grid points", transform=ax.transAxes,
                ha="center", va="center")
    ax.set_xscale("log")
    plain_log_ticks(ax.xaxis)
    ax.set_xlabel("thrust frequency Omega (Hz)")
    ax.set_ylabel("gamma (pulsation amplitude)")
    ax.set_xlim(x.min(), x.max())
    ax.set_ylim(chart.gamma.min(), chart.gamma.max())
    ax.set_title("Beam action: instability regions (shaded)")
    return fig
