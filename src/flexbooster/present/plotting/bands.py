"""Instability regions in the (Omega, gamma) plane, drawn from their traced boundaries, with the
regions open at the case's gamma and damping (the stored bands) on its line."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure

from ...bands import Band
from ...memo.charts import BandChart, RegionCurves
from .labels import plain_log_ticks
from .layout import new_axes

__all__ = ["plot_band_chart", "band_key", "region_outline"]

_TO_HZ = 1.0 / (2.0 * np.pi)


def band_key(band: Band) -> tuple:
    """(kind, mode indices, order) of a band: the :attr:`RegionCurves.key` of its region.

    Parameters
    ----------
    band : Band
        A band of the pitch or the beam action.
    """
    return str(band.kind), tuple(m.index for m in band.modes), int(band.order)


def region_outline(region: RegionCurves, band: Band | None,
                   gamma: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(gamma, omega_lo, omega_hi) of a traced region (rad/s), with the stored band's edges at
    the case's ``gamma`` put in as one more level (replacing a traced level there) when the
    band is that region's and gamma lies above the tip.

    Parameters
    ----------
    region : RegionCurves
        The traced boundaries.
    band : Band or None
        The same region at the case's gamma (its edges), or None.
    gamma : float
        The case's gamma.
    """
    g = np.asarray(region.gamma, dtype=float)
    lo = np.asarray(region.omega_lo, dtype=float)
    hi = np.asarray(region.omega_hi, dtype=float)
    if band is None or not (g.size and gamma > g[0]):
        return g, lo, hi
    keep = ~np.isclose(g, gamma, rtol=1e-12, atol=0.0)
    g, lo, hi = g[keep], lo[keep], hi[keep]
    at = int(np.searchsorted(g, gamma))
    return (np.insert(g, at, gamma), np.insert(lo, at, band.Omega_lo),
            np.insert(hi, at, band.Omega_hi))


def plot_band_chart(chart: BandChart, ax: Axes | None = None, *,
                    omega_1: float | None = None, bands: Sequence[Band] = (),
                    damping_text: str = "",
                    searched: tuple[float, float] | None = None) -> Figure:
    """Shade each region between its traced edges, Omega in Hz (log) against gamma, the case's
    gamma dashed and on it, as thick bars, the regions open at the case's gamma and damping
    (``bands``; each also put into its region's outline, :func:`region_outline`) (Bolotin 1964,
    ch. 1; memo 4.1-4.2).

    Parameters
    ----------
    chart : BandChart
        From :func:`flexbooster.memo.charts.pitch_band_chart` or ``beam_action_chart``.
    ax : matplotlib.axes.Axes, optional
        Axes to draw on; a new figure is made when None.
    omega_1 : float, optional
        First bending frequency (rad/s), > 0: adds a secondary axis Omega / omega_1 on top.
    bands : sequence of Band
        The mechanism's stored bands at the case's gamma and damping (Omega in rad/s).
    damping_text : str
        The damping the regions were computed with, in words (added to the title).
    searched : (float, float), optional
        The Omega range searched (rad/s): outside it shaded "not searched".
    """
    fig, ax = new_axes(ax, (6.4, 4.8))
    gamma = float(chart.gamma_operating)
    by_key = {band_key(b): b for b in bands}
    for i, reg in enumerate(chart.regions):
        g, lo, hi = region_outline(reg, by_key.get(tuple(reg.key)) if reg.key else None, gamma)
        x = np.concatenate([lo, hi[::-1]]) * _TO_HZ
        y = np.concatenate([g, g[::-1]])
        ax.fill(x, y, color="C3", alpha=0.3, lw=0.6, ec="C3",
                label="unstable region" if i == 0 else None)
    x_lo, x_hi = chart.omega_min * _TO_HZ, chart.omega_max * _TO_HZ
    if searched is not None:
        for a, b in ((x_lo, searched[0] * _TO_HZ), (searched[1] * _TO_HZ, x_hi)):
            if b > a:
                ax.axvspan(a, b, color="0.88", lw=0,
                           label="not searched" if a == x_lo else None)
    ax.axhline(gamma, color="C0", ls="--", lw=1.2, label=f"case's gamma = {gamma:g}")
    for i, b in enumerate(bands):
        ax.plot([b.Omega_lo * _TO_HZ, b.Omega_hi * _TO_HZ], [gamma, gamma], color="darkred",
                lw=5, solid_capstyle="butt",
                label="open at the case's gamma and damping" if i == 0 else None)
    if not chart.regions and not bands:
        ax.text(0.5, 0.5, "no instability region in the range", transform=ax.transAxes,
                ha="center", va="center")
    ax.set_xscale("log")
    ax.set_xlim(x_lo, x_hi)
    ax.set_ylim(0.0, chart.gamma_max)
    ax.set_xlabel("thrust frequency Omega (Hz)")
    ax.set_ylabel("gamma (pulsation amplitude)")
    title = chart.title + (f"\n{damping_text}" if damping_text else "")
    ax.set_title(title, fontsize=10)
    plain_log_ticks(ax.xaxis)
    if omega_1 is not None and omega_1 > 0:
        w1_hz = omega_1 * _TO_HZ
        sec = ax.secondary_xaxis("top", functions=(lambda f: f / w1_hz, lambda r: r * w1_hz))
        sec.set_xlabel("Omega / omega_1")
        plain_log_ticks(sec.xaxis)
    ax.legend(loc="upper left", fontsize=8, framealpha=0.9)
    return fig
