"""The danger map: every unstable band of Omega of every mechanism on one frequency axis.

Parametric instability regions are shaded bands from 0 up to their growth rate (1/s), coloured
by it; memo resonances (a severity, no growth rate) are stems on a logarithmic severity axis;
the operating range of the thrust frequency is the white field between grey margins.  Each band
and stem carries a group id (``danger-band-N``); :func:`add_svg_titles` puts an SVG ``<title>``
(a tooltip in any browser, no script) in each group of the saved SVG.
"""

from __future__ import annotations

import html
import math
import re

import numpy as np
from matplotlib import colormaps
from matplotlib.axes import Axes
from matplotlib.cm import ScalarMappable
from matplotlib.collections import PolyCollection
from matplotlib.colors import Normalize
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Rectangle

from ...danger import DangerSummary, RankedBand
from .labels import plain_log_ticks, power_log_ticks
from .layout import axes_with_colorbar

__all__ = ["danger_map", "band_tooltip", "add_svg_titles",
           "SVG_TITLES_ATTRIBUTE"]

#: Attribute of the figure holding {group id: tooltip text} for :func:`add_svg_titles`.
SVG_TITLES_ATTRIBUTE = "flexbooster_svg_titles"
#: Smallest drawn width of a band, as a fraction of a decade of the logarithmic Hz axis.
_MIN_DECADES = 0.012


def band_tooltip(rank: int, band: RankedBand) -> str:
    """The tooltip of one band: rank, edges in rad/s and Hz, growth rate or severity, words.

    Parameters
    ----------
    rank : int
        1-based rank in the danger list.
    band : RankedBand
        The band.
    """
    lo_hz, hi_hz = band.hz
    amp = band.band.steady_amplitude
    level = (f"growth rate {band.growth_rate:.3g} 1/s" if band.growth_rate is not None
             else f"steady response {1e3 * amp:.3g} mm (severity {band.severity:.3g})"
             if amp is not None else f"severity {band.severity:.3g}")
    where = "in the operating range" if band.in_operating_range else "outside the operating range"
    return (f"#{rank}: Omega {band.Omega_lo:.6g}-{band.Omega_hi:.6g} rad/s "
            f"({lo_hz:.6g}-{hi_hz:.6g} Hz); {level}; {band.mode_text}; {band.cause_text}; "
            f"{where}")


def danger_map(danger: DangerSummary, *, omega_1: float | None = None,
               ax: Axes | None = None) -> Figure:
    """Draw the danger map from a :class:`~flexbooster.danger.DangerSummary`: log Omega (Hz) over
    the operating range, regions as bands of height and colour their growth rate, the five most
    dangerous numbered, resonances as stems on a log severity axis; the figure's
    :data:`SVG_TITLES_ATTRIBUTE` maps each group id to its tooltip.

    Parameters
    ----------
    danger : DangerSummary
        ``results.danger``: operating range (rad/s) and the ranked bands.
    omega_1 : float, optional
        First bending frequency (rad/s), > 0: adds a secondary x axis Omega / omega_1.
    ax : matplotlib.axes.Axes, optional
        Axes to draw on; a new figure is made when None.
    """
    bands = danger.bands
    regions = [(n, b) for n, b in enumerate(bands) if b.growth_rate is not None]
    stems = [(n, b) for n, b in enumerate(bands) if b.growth_rate is None]
    fig, ax, cax = axes_with_colorbar(ax, (9.0, 4.2), colorbar=bool(regions))
    to_hz = 1.0 / (2.0 * math.pi)
    op_lo, op_hi = (v * to_hz for v in danger.operating_range)
    lo_all = min([op_lo] + [b.hz[0] for b in bands if b.hz[0] > 0])
    hi_all = max([op_hi] + [b.hz[1] for b in bands])
    x_lo, x_hi = lo_all / 1.15, hi_all * 1.15
    ax.set_xscale("log")
    ax.set_xlim(x_lo, x_hi)
    ax.axvspan(x_lo, op_lo, color="0.88", lw=0)
    ax.axvspan(op_hi, x_hi, color="0.88", lw=0)
    ax.axvline(op_lo, color="0.4", lw=1.0, ls="--")
    ax.axvline(op_hi, color="0.4", lw=1.0, ls="--", label="operating range (edges)")
    titles: dict[str, str] = {}
    g_max = max((b.growth_rate for _, b in regions), default=1.0) or 1.0
    norm = Normalize(0.0, g_max)
    cmap = colormaps["plasma_r"]
    factor = 10.0 ** _MIN_DECADES
    shade = []  # each region's edges and colour, shaded faintly over the full height
    for n, b in regions:
        lo, hi = b.hz
        centre = math.sqrt(max(lo, 1e-300) * hi)
        if hi / max(lo, 1e-300) < factor:  # narrower than the eye sees: widen about the centre
            lo, hi = centre / math.sqrt(factor), centre * math.sqrt(factor)
        colour = cmap(norm(b.growth_rate))
        gid = f"danger-band-{n + 1}"
        # the bar of ax.bar(centre, growth_rate, width=hi - lo): one patch, its own group
        ax.add_patch(Rectangle((centre - 0.5 * (hi - lo), 0.0), hi - lo, b.growth_rate,
                               facecolor=colour, lw=0, gid=gid))
        shade.append(((lo, hi), colour))
        titles[gid] = band_tooltip(n + 1, b)
        if n < 5:
            ax.annotate(str(n + 1), (centre, b.growth_rate), xytext=(0, 3),
                        textcoords="offset points", ha="center", fontsize=8)
    if shade:  # as ax.axvspan(lo, hi) each, in one artist under the bars
        ax.add_collection(PolyCollection(
            [[(lo, 0.0), (lo, 1.0), (hi, 1.0), (hi, 0.0)] for (lo, hi), _ in shade],
            facecolors=[c for _, c in shade], alpha=0.18, lw=0, zorder=0.9,
            transform=ax.get_xaxis_transform()), autolim=False)
    if regions:
        ax.set_ylim(0.0, g_max * 1.15)
        fig.colorbar(ScalarMappable(norm=norm, cmap=cmap), ax=ax, cax=cax, pad=0.01,
                     label="growth rate (1/s)")
    else:
        ax.set_ylim(0.0, 1.0)
        ax.text(0.5, 0.6, "no instability region in the mechanisms computed",
                transform=ax.transAxes, ha="center", va="center")
    ax.set_ylabel("growth rate of the amplitude (1/s)")
    ax.set_xlabel("thrust frequency Omega (Hz)")
    if stems:
        ax2 = ax.twinx()
        sev = np.array([b.severity for _, b in stems], dtype=float)
        sev_lo = float(np.min(sev[sev > 0])) if np.any(sev > 0) else 1.0
        ax2.set_yscale("log")
        ax2.set_ylim(sev_lo / 3.0, float(np.max(sev)) * 3.0)
        for (n, b), s in zip(stems, sev, strict=True):
            x = math.sqrt(max(b.hz[0], 1e-300) * b.hz[1])
            gid = f"danger-band-{n + 1}"
            # the stem and its head (a dot at the severity) in one line, one group
            ax2.add_line(Line2D([x, x], [sev_lo / 3.0, s], color="C2", lw=1.2,
                                solid_capstyle="butt", marker="o", ms=4, markevery=[1],
                                gid=gid))
            titles[gid] = band_tooltip(n + 1, b)
        power_log_ticks(ax2.yaxis)
        ax2.set_ylabel("resonance severity (memo 7; log)", color="C2")
    if omega_1 is not None and omega_1 > 0:
        w1_hz = omega_1 * to_hz
        sec = ax.secondary_xaxis("top", functions=(lambda f: f / w1_hz, lambda r: r * w1_hz))
        sec.set_xlabel("Omega / omega_1")
        plain_log_ticks(sec.xaxis)
    plain_log_ticks(ax.xaxis)
    ax.legend(loc="upper left", fontsize=8, framealpha=0.9)
    ax.set_title("Danger map: unstable thrust-frequency bands, all mechanisms", fontsize=10)
    setattr(fig, SVG_TITLES_ATTRIBUTE, titles)
    return fig


def add_svg_titles(svg: str, titles: dict[str, str]) -> str:
    """The SVG with ``<title>text</title>`` as the first child of each ``<g>`` of a given id.

    Parameters
    ----------
    svg : str
        SVG text from ``Figure.savefig(format="svg")``.
    titles : dict of str to str
        Group id (``Artist.set_gid``) -> tooltip text.
    """
    if not titles:
        return svg

    def put(match: re.Match) -> str:
        gid = match.group(1)
        text = titles.get(gid)
        if text is None:
            return match.group(0)
        return f"{match.group(0)}<title>{html.escape(text, quote=False)}</title>"

    return re.sub(r'<g id="([^"]+)"[^>]*>', put, svg)
