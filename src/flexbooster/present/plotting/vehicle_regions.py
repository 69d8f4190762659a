"""The vehicle's Ince-Strutt chart: parametric instability regions in the (Omega, gamma) plane.

Draws a stored :class:`~flexbooster.dynamics.VehicleRegions` (its boundary curves
:class:`~flexbooster.dynamics.RegionCurve` and its regions at the case's gamma); it computes
nothing.
"""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.cm import ScalarMappable
from matplotlib.colors import LogNorm, Normalize
from matplotlib.figure import Figure

from ...dynamics import VehicleRegions
from ...memo.charts import VEHICLE_CHART_GAMMA_MAX
from .labels import plain_log_ticks
from .layout import axes_with_colorbar

__all__ = ["vehicle_region_chart", "vehicle_chart_top", "HEADROOM", "LOG_COLOURS_ABOVE"]

_TO_HZ = 1.0 / (2.0 * np.pi)
#: The chart's top gamma is this times the larger of the traced top and the case's gamma: the
#: case's gamma and its dots below the legend, never on the frame.
HEADROOM = 1.35
#: Growth rates spanning more than this ratio are coloured on a logarithmic scale.
LOG_COLOURS_ABOVE = 100.0


def _key(k: int, kind: str, order: int, modes: tuple) -> tuple:
    return int(k), str(kind), int(order), tuple(int(m) for m in modes)


def _top(regions) -> float:
    """The chart's top gamma as the pipeline stored it (else the constant)."""
    top = getattr(regions, "chart_gamma_max", None)
    return VEHICLE_CHART_GAMMA_MAX if top is None else float(top)


def vehicle_chart_top(regions: VehicleRegions) -> float:
    """The chart's top gamma: :data:`HEADROOM` times the larger of the traced top
    (:data:`~flexbooster.memo.charts.VEHICLE_CHART_GAMMA_MAX` or the stored one) and the
    case's gamma.

    Parameters
    ----------
    regions : VehicleRegions
        The stored regions.
    """
    return HEADROOM * max(VEHICLE_CHART_GAMMA_MAX, float(regions.gamma), _top(regions))


def vehicle_region_chart(regions: VehicleRegions, ax: Axes | None = None) -> Figure:
    """Shade each region between its boundary curves, Omega in Hz (log) against gamma, coloured by
    the largest growth rate (1/s) at the case's gamma (grey where it does not reach it), the
    case's gamma dashed (Bolotin 1964, ch. 1, sec. 6).

    Parameters
    ----------
    regions : VehicleRegions
        The stored regions and curves (rad/s, drawn in Hz).
    ax : matplotlib.axes.Axes, optional
        Axes to draw on; a new figure is made when None.
    """
    fig, ax, cax = axes_with_colorbar(ax, (6.4, 4.8), colorbar=bool(regions.regions))
    growth = {_key(r.k, r.kind, r.order, tuple(m.index for m in r.modes)): r.growth_rate_max
              for r in regions.regions}
    g_max = max(growth.values(), default=0.0)
    g_min = min((g for g in growth.values() if g > 0.0), default=0.0)
    log = g_min > 0.0 and g_max / g_min > LOG_COLOURS_ABOVE
    norm = LogNorm(max(g_min, g_max / 1e6), g_max) if log else \
        Normalize(0.0, g_max if g_max > 0.0 else 1.0)
    cmap = ScalarMappable(norm=norm, cmap="YlOrRd")
    grey_done = False
    for c in regions.curves:
        x = np.concatenate([c.omega_lo, c.omega_hi[::-1]]) * _TO_HZ
        y = np.concatenate([c.gamma, c.gamma[::-1]])
        rate = growth.get(_key(c.k, c.kind, c.order, c.modes))
        if rate is None:  # the region does not reach the case's gamma
            ax.fill(x, y, color="0.7", alpha=0.5, lw=0.5, ec="0.45",
                    label=None if grey_done else "stable at the case's gamma")
            grey_done = True
        else:
            ax.fill(x, y, color=cmap.to_rgba(rate), alpha=0.85, lw=0.5, ec="C3")
    gamma = float(regions.gamma)
    ax.axhline(gamma, color="C0", ls="--", lw=1.0, label=f"case's gamma = {gamma:g}")
    if regions.regions:
        xs = np.array([r.Omega_at_max for r in regions.regions]) * _TO_HZ
        rates = np.array([r.growth_rate_max for r in regions.regions])
        ax.scatter(xs, np.full(xs.size, gamma), c=cmap.to_rgba(rates), s=22, ec="k", lw=0.4,
                   zorder=3, label="regions at the case's gamma")
        fig.colorbar(cmap, ax=ax, cax=cax, label="largest growth rate at the case's gamma (1/s"
                     + (", log)" if log else ")"))
    if not regions.curves and not regions.regions:
        ax.text(0.5, 0.5, f"no instability region in the range up to gamma = "
                f"{_top(regions):.3g}\n(damping ratio {regions.damping_ratio:g})",
                transform=ax.transAxes, ha="center", va="center", fontsize=9)
    ks = [h.k for h in regions.harmonics]
    ax.set_xscale("log")
    plain_log_ticks(ax.xaxis)
    ax.set_xlim(regions.omega_min * _TO_HZ, regions.omega_max * _TO_HZ)
    ax.set_ylim(0.0, vehicle_chart_top(regions))
    ax.set_xlabel("thrust frequency Omega (Hz)")
    ax.set_ylabel("gamma (pulsation amplitude)")
    ax.set_title("Vehicle parametric instability regions"
                 + (f" (k = {min(ks)}..{max(ks)}, damping ratio {regions.damping_ratio:g})"
                    if ks else ""), fontsize=10)
    ax.legend(loc="upper left", fontsize=8, framealpha=0.9)
    return fig
