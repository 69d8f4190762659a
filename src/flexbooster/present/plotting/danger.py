"""The danger map: every unstable band of Omega of every mechanism on one frequency axis.

One panel per quantity, on one logarithmic axis of the thrust frequency (Hz): the parametric
instability regions as bars up to their growth rate (1/s, log), coloured by mechanism, with
the growth below which a band is negligible dotted; the forced resonances as stems up to their
damped steady amplitude (mm, log; their undamped severity in m/s without damping); the
vehicle's bounded forced responses as stems up to their acceleration (g, log); the
operating range of the thrust frequency is the white field between grey margins.  The five
most dangerous items are numbered with their rank in the list (``danger.ranking``), the
numbers stacked where they would overprint.  Each band and stem carries a group id
(``danger-band-N``, ``danger-response-N``); :func:`add_svg_titles` puts an SVG ``<title>``
(a tooltip in any browser, no script) in each group of the saved SVG.
"""

from __future__ import annotations

import html
import math
import re

from matplotlib.axes import Axes
from matplotlib.collections import PolyCollection
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Patch, Rectangle

from ...bands import MECHANISMS
from ...danger import NEGLIGIBLE_GROWTH, DangerSummary, RankedBand
from .labels import plain_log_ticks, power_log_ticks
from .layout import panel_axes

__all__ = ["danger_map", "band_tooltip", "add_svg_titles", "danger_quantities",
           "SVG_TITLES_ATTRIBUTE", "RANKS_NUMBERED"]

#: Attribute of the figure holding {group id: tooltip text} for :func:`add_svg_titles`.
SVG_TITLES_ATTRIBUTE = "flexbooster_svg_titles"
#: The most dangerous bands numbered on the map (their rank in the danger list).
RANKS_NUMBERED = 5
#: Smallest drawn width of a band, as a fraction of a decade of the logarithmic Hz axis.
_MIN_DECADES = 0.012
#: Colour of each mechanism's regions.
_COLOURS = {"pitch": "C0", "beam_action": "C3", "vehicle": "C1", "resonance": "C2",
            "response": "C4"}
#: A rank number's box (points): numbers closer than this in x and y are stacked.
_NUMBER_W, _NUMBER_H = 12.0, 10.0
#: Headroom above the largest value (decades): this fraction of the panel's span, at least
#: :data:`_HEADROOM_MIN` (raised where the numbers need it).
_HEADROOM, _HEADROOM_MIN = 0.08, 0.25


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


def danger_quantities(danger: DangerSummary) -> tuple[tuple[str, str], ...]:
    """The panels of the danger map, top to bottom, as (key, y-axis label): ``"growth"`` when a
    band has a growth rate, ``"response"`` (damped steady amplitude, mm) or ``"severity"``
    (undamped, m/s) when a band is a forced resonance, ``"acceleration"`` (g) when the vehicle
    has bounded forced responses (``danger.responses``); one ``"none"`` panel without any.

    Parameters
    ----------
    danger : DangerSummary
        ``results.danger``.
    """
    bands = danger.bands
    out = []
    if any(b.growth_rate is not None for b in bands):
        out.append(("growth", "growth rate (1/s)"))
    stems = [b for b in bands if b.growth_rate is None]
    if stems and all(b.band.steady_amplitude is not None for b in stems):
        out.append(("response", "resonance: damped response (mm)"))
    elif stems:
        out.append(("severity", "resonance: undamped severity (m/s)"))
    if danger.responses:
        out.append(("acceleration", "forced response:\nacceleration (g)"))
    return tuple(out) or (("none", ""),)


def _value(key: str, band: RankedBand) -> float:
    """The band's height in the panel ``key`` (1/s, mm or m/s)."""
    if key == "growth":
        return float(band.growth_rate)
    if key == "response":
        return 1e3 * float(band.band.steady_amplitude)
    return float(band.severity or 0.0)


def _centre(band: RankedBand) -> float:
    lo, hi = band.hz
    return math.sqrt(max(lo, 1e-300) * hi)


def _number_levels(points: list[tuple[float, float]], size: tuple[float, float]) -> list[int]:
    """For numbers at ``points`` (axes fractions), placed in order: the stacking level of each
    (0: just above its point; one number height per level) such that no two boxes overlap on
    an axes of ``size`` (points)."""
    placed: list[tuple[float, float]] = []
    levels = []
    for fx, fy in points:
        x, y = fx * size[0], fy * size[1]
        level = 0
        while any(abs(x - px) < _NUMBER_W and abs(y + level * _NUMBER_H - py) < _NUMBER_H
                  for px, py in placed):
            level += 1
        placed.append((x, y + level * _NUMBER_H))
        levels.append(level)
    return levels


def danger_map(danger: DangerSummary, ax: Axes | None = None) -> Figure:
    """Draw the danger map from a :class:`~flexbooster.danger.DangerSummary`: one panel per
    quantity (:func:`danger_quantities`) over log Omega (Hz); the figure's
    :data:`SVG_TITLES_ATTRIBUTE` maps each group id to its tooltip.

    Parameters
    ----------
    danger : DangerSummary
        ``results.danger``: operating range (rad/s) and the ranked bands.
    ax : matplotlib.axes.Axes, optional
        Its place is split into the panels; a new figure is made when None.
    """
    bands, responses = danger.bands, danger.responses
    quantities = danger_quantities(danger)
    fig, axes = panel_axes(ax, len(quantities), (9.0, 1.2 + 2.6 * len(quantities)))
    to_hz = 1.0 / (2.0 * math.pi)
    op_lo, op_hi = (v * to_hz for v in danger.operating_range)
    lo_all = min([op_lo] + [b.hz[0] for b in bands if b.hz[0] > 0]
                 + [r.hz for r in responses if r.hz > 0])
    hi_all = max([op_hi] + [b.hz[1] for b in bands] + [r.hz for r in responses])
    x_lo, x_hi = lo_all / 1.15, hi_all * 1.15
    titles: dict[str, str] = {}
    factor = 10.0 ** _MIN_DECADES
    # the numbers are the ranks of the list (bands and responses in one ranking)
    listed = danger.ranking or bands
    rank = {id(x): n for n, x in enumerate(listed)}
    numbers: list[tuple[Axes, int, float, float]] = []
    for panel, (key, label) in zip(axes, quantities, strict=True):
        panel.set_xscale("log")
        panel.set_xlim(x_lo, x_hi)
        panel.axvspan(x_lo, op_lo, color="0.88", lw=0)
        panel.axvspan(op_hi, x_hi, color="0.88", lw=0)
        panel.axvline(op_lo, color="0.4", lw=1.0, ls="--")
        panel.axvline(op_hi, color="0.4", lw=1.0, ls="--")
        plain_log_ticks(panel.xaxis)
        if key == "none":
            panel.set_yticks([])
            panel.text(0.5, 0.5, "no unstable or resonant band in the mechanisms computed",
                       transform=panel.transAxes, ha="center", va="center")
            continue
        if key == "acceleration":
            _responses(panel, label, responses, rank, titles, numbers)
            continue
        mine = [(n, b) for n, b in enumerate(bands)
                if (b.growth_rate is not None) == (key == "growth")]
        values = [max(_value(key, b), 1e-300) for _, b in mine]
        top = max(values)
        floor = min(values) / 3.0
        if key == "growth":
            top, floor = max(top, NEGLIGIBLE_GROWTH), min(floor, NEGLIGIBLE_GROWTH / 3.0)
        span = math.log10(top / floor)
        y_lo, y_hi = floor, top * 10.0 ** max(_HEADROOM * span, _HEADROOM_MIN)
        panel.set_yscale("log")
        shade = []
        for (n, b), v in zip(mine, values, strict=True):
            gid = f"danger-band-{n + 1}"
            titles[gid] = band_tooltip(rank.get(id(b), n) + 1, b)
            colour = _COLOURS.get(b.mechanism, "C7")
            x = _centre(b)
            if key == "growth":
                lo, hi = b.hz
                if hi / max(lo, 1e-300) < factor:  # narrower than the eye sees: widened
                    lo, hi = x / math.sqrt(factor), x * math.sqrt(factor)
                # the bar of ax.bar(x, v - y_lo, bottom=y_lo): one patch, its own group
                panel.add_patch(Rectangle((lo, y_lo), hi - lo, v - y_lo, facecolor=colour,
                                          lw=0, gid=gid))
                shade.append((lo, hi, colour))
            else:  # the stem and its head (a dot at the value) in one line, one group
                panel.add_line(Line2D([x, x], [y_lo, v], color=colour, lw=1.2,
                                      solid_capstyle="butt", marker="o", ms=4, markevery=[1],
                                      gid=gid))
            if rank.get(id(b), RANKS_NUMBERED) < RANKS_NUMBERED:
                numbers.append((panel, rank[id(b)], x, v))
        if shade:  # faintly over the full height, in one artist under the bars
            panel.add_collection(PolyCollection(
                [[(lo, 0.0), (lo, 1.0), (hi, 1.0), (hi, 0.0)] for lo, hi, _ in shade],
                facecolors=[c for *_, c in shade], alpha=0.15, lw=0, zorder=0.9,
                transform=panel.get_xaxis_transform()), autolim=False)
        panel.set_ylim(y_lo, y_hi)
        power_log_ticks(panel.yaxis)
        panel.set_ylabel(label, fontsize=9)
        handles = [Patch(color="0.88", label="outside the operating range")]
        if key == "growth":
            panel.axhline(NEGLIGIBLE_GROWTH, color="0.3", lw=0.8, ls=":")
            handles.insert(0, Line2D([], [], color="0.3", lw=0.8, ls=":",
                                     label=f"negligible below {NEGLIGIBLE_GROWTH:g} 1/s"))
            words = dict(MECHANISMS)
            for mech in dict.fromkeys(b.mechanism for _, b in mine):
                handles.insert(0, Patch(color=_COLOURS.get(mech, "C7"),
                                        label=words.get(mech, mech).split(" (")[0]))
        else:
            handles.insert(0, Line2D([], [], color=_COLOURS["resonance"], marker="o", ms=4,
                                     label="forced resonance"))
        panel.legend(handles=handles, loc="upper left", bbox_to_anchor=(1.01, 1.0),
                     fontsize=7, borderaxespad=0.0)
    _number(fig, numbers)
    for panel in axes[:-1]:
        panel.tick_params(axis="x", labelbottom=False)
    axes[-1].set_xlabel("thrust frequency Omega (Hz)")
    axes[0].set_title("Danger map: unstable and resonant thrust-frequency bands, all mechanisms",
                      fontsize=10)
    setattr(fig, SVG_TITLES_ATTRIBUTE, titles)
    return fig


def _responses(panel: Axes, label: str, responses, rank: dict, titles: dict[str, str],
               numbers: list) -> None:
    """The vehicle's bounded forced responses (:class:`flexbooster.danger.ResponsePeak`) as
    stems up to their acceleration (g, log) at their Omega, numbered by ``rank``."""
    values = [max(r.acceleration_g, 1e-300) for r in responses]
    top, floor = max(values), min(values) / 3.0
    span = math.log10(top / floor)
    y_lo, y_hi = floor, top * 10.0 ** max(_HEADROOM * span, _HEADROOM_MIN)
    panel.set_yscale("log")
    for i, (r, v) in enumerate(zip(responses, values, strict=True)):
        gid = f"danger-response-{i + 1}"
        n = rank.get(id(r))
        where = "in the operating range" if r.in_operating_range else \
            "outside the operating range"
        titles[gid] = (f"{'' if n is None else f'#{n + 1}: '}{r.source} of the vehicle: "
                       f"{r.text}; Omega {r.Omega:.6g} rad/s; {r.modes}; {where}")
        panel.add_line(Line2D([r.hz, r.hz], [y_lo, v], color=_COLOURS["response"], lw=1.2,
                              solid_capstyle="butt", marker="o", ms=4, markevery=[1], gid=gid))
        if n is not None and n < RANKS_NUMBERED:
            numbers.append((panel, n, r.hz, v))
    panel.set_ylim(y_lo, y_hi)
    plain_log_ticks(panel.yaxis)  # g: plain numbers (0.2, 0.5, 1, 2)
    panel.set_ylabel(label, fontsize=9)
    handles = [Line2D([], [], color=_COLOURS["response"], marker="o", ms=4,
                      label="vehicle forced response"),
               Patch(color="0.88", label="outside the operating range")]
    panel.legend(handles=handles, loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=7,
                 borderaxespad=0.0)


def _number(fig: Figure, numbers: list[tuple[Axes, int, float, float]]) -> None:
    """Write each rank of ``numbers`` (panel, rank, x in Hz, value) above its bar or stem,
    stacked where two would overprint."""
    by_panel: dict[int, list] = {}
    for item in numbers:
        by_panel.setdefault(id(item[0]), []).append(item)
    width, height = fig.get_size_inches() * 72.0  # points
    for items in by_panel.values():
        panel = items[0][0]
        box = panel.get_position()
        size = (box.width * width, box.height * height)
        x0, x1 = (math.log10(v) for v in panel.get_xlim())
        y0, y1 = (math.log10(v) for v in panel.get_ylim())
        at = [(math.log10(x), math.log10(max(v, 1e-300))) for _, _, x, v in items]
        for _ in range(4):  # raise the top until every number lies inside the panel
            points = [((x - x0) / (x1 - x0), (y - y0) / (y1 - y0)) for x, y in at]
            levels = _number_levels(points, size)
            need = max(y0 + (y - y0) / (0.98 - (2.0 + (lev + 1) * _NUMBER_H) / size[1])
                       for (_, y), lev in zip(at, levels, strict=True))
            if need <= y1:
                break
            y1 = need
            panel.set_ylim(10.0 ** y0, 10.0 ** y1)
        for (_, n, x, v), level in zip(items, levels, strict=True):
            panel.annotate(str(n + 1), (x, v), xytext=(0, 2 + level * _NUMBER_H),
                           textcoords="offset points", ha="center", va="bottom", fontsize=8,
                           fontweight="bold")


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
