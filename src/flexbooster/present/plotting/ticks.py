"""Cheaper ticks of the logarithmic axes: only those in the view (:func:`in_view_log_locator`),
the minor ones as one line of markers (:class:`MinorTickMarks`, no tick objects); the ticks
drawn are the same.
"""

from __future__ import annotations

import math

import numpy as np
from matplotlib import lines as mlines
from matplotlib import rcParams
from matplotlib.artist import Artist
from matplotlib.ticker import LogLocator, MaxNLocator, NullFormatter, NullLocator

__all__ = ["in_view_log_locator", "plain_log_locator", "MinorTickMarks", "log_minor_ticks",
           "MIN_LABELLED_TICKS"]

#: Relative tolerance (of the axis' span in decades) within which a tick at the edge of the
#: view is drawn: matplotlib's (``Axis._update_ticks``, ``_interval_contains_close``).
_EDGE_RTOL = 1e-10
#: The locator's tolerance, ten times matplotlib's: it keeps every tick that matplotlib draws.
_LOCATOR_RTOL = 10.0 * _EDGE_RTOL
#: Tolerance (of the span in decades) within which a minor tick on a major one is dropped:
#: matplotlib's (``Axis.get_minorticklocs``).
_OVERLAP_RTOL = 1e-5

# matplotlib's tick markers by axis and direction: (tick1 (bottom/left), tick2 (top/right));
# matplotlib.axis.XTick._apply_tickdir and YTick._apply_tickdir
_MARKERS = {
    "x": {"out": (mlines.TICKDOWN, mlines.TICKUP), "in": (mlines.TICKUP, mlines.TICKDOWN),
          "inout": ("|", "|")},
    "y": {"out": (mlines.TICKLEFT, mlines.TICKRIGHT), "in": (mlines.TICKRIGHT, mlines.TICKLEFT),
          "inout": ("_", "_")},
}


def _in_view(locs: np.ndarray, view: tuple[float, float], rtol: float) -> np.ndarray:
    """The positive ``locs`` within ``rtol`` (of the span in decades) of the interval."""
    lo, hi = sorted(view)
    locs = np.asarray(locs, dtype=float)
    if not (lo > 0.0 and math.isfinite(hi)) or locs.size == 0:
        return locs
    e_lo, e_hi = math.log10(lo), math.log10(hi)
    tol = rtol * (e_hi - e_lo)
    with np.errstate(divide="ignore", invalid="ignore"):
        e = np.log10(locs)
    return locs[(e >= e_lo - tol) & (e <= e_hi + tol)]


class _InViewLogLocator(LogLocator):
    """matplotlib's ``LogLocator`` returning only the ticks in the axis' view."""

    def __call__(self):
        """The tick locations in the view (as ``LogLocator``, less those beyond the view)."""
        return _in_view(super().__call__(), self.axis.get_view_interval(), _LOCATOR_RTOL)


#: Fewest labelled ticks of a logarithmic axis: a view narrower than a decade that holds fewer
#: of 1, 2 and 5 x 10^n gets round linear steps instead (8, 10, 12, 14 Hz).
MIN_LABELLED_TICKS = 3


class _PlainLogLocator(_InViewLogLocator):
    """1, 2 and 5 per decade in the view; where those are fewer than
    :data:`MIN_LABELLED_TICKS`, the round numbers of ``MaxNLocator`` (steps 1, 2, 2.5, 5)."""

    def __call__(self):
        """The tick locations in the view."""
        locs = super().__call__()
        lo, hi = sorted(self.axis.get_view_interval())
        if len(locs) >= MIN_LABELLED_TICKS or not (lo > 0.0 and math.isfinite(hi)):
            return locs
        linear = MaxNLocator(nbins=6, steps=[1, 2, 2.5, 5, 10]).tick_values(lo, hi)
        return _in_view(linear[linear > 0.0], (lo, hi), _LOCATOR_RTOL)


def plain_log_locator() -> _PlainLogLocator:
    """The major ticks of a logarithmic axis with plain labels: 1, 2, 5 x 10^n in the view, or
    round linear steps over a view too narrow for :data:`MIN_LABELLED_TICKS` of them."""
    return _PlainLogLocator(base=10.0, subs=(1.0, 2.0, 5.0))


def in_view_log_locator(subs) -> _InViewLogLocator:
    """``LogLocator(base=10, subs=subs)`` returning only the ticks in the view.

    Parameters
    ----------
    subs : sequence of float or {"auto", "all"}
        As ``matplotlib.ticker.LogLocator``'s.
    """
    return _InViewLogLocator(base=10.0, subs=subs)


class MinorTickMarks(Artist):
    """The minor ticks of a logarithmic axis as one line of tick markers, drawn with the axis: the
    locations of ``LogLocator(subs="auto")`` in the view less the major ones, with matplotlib's
    minor tick marker, size, width and colour (rcParams); no label, no grid line.

    Parameters
    ----------
    axis : matplotlib.axis.Axis
        A logarithmic x or y axis; its minor locator should be a ``NullLocator``.
    """

    def __init__(self, axis):
        super().__init__()
        self._axis = axis
        self._name = axis.axis_name  # "x" or "y"
        self._locator = in_view_log_locator(subs="auto")
        self._locator.set_axis(axis)
        self.set_zorder(axis.get_zorder())
        self.set_label("_nolegend_")

    def _locs(self) -> np.ndarray:
        view = self._axis.get_view_interval()
        minor = _in_view(self._locator(), view, _EDGE_RTOL)
        major = _in_view(self._axis.get_majorticklocs(), view, _EDGE_RTOL)
        if minor.size == 0 or major.size == 0:
            return minor
        lo, hi = sorted(view)
        tol = _OVERLAP_RTOL * abs(math.log10(hi / lo))
        e_minor, e_major = np.log10(minor), np.log10(major)
        on_major = np.any(np.abs(e_minor[:, None] - e_major[None, :]) <= tol, axis=1)
        return minor[~on_major]

    def draw(self, renderer):
        """Draw the marks (nothing when this artist or its axis is hidden)."""
        if not (self.get_visible() and self._axis.get_visible()):
            return
        ax, name = self.axes, self._name
        locs = self._locs()
        if locs.size == 0:
            return
        tick = self._axis.majorTicks[0]  # the sides: where the major ticks are
        marks = _MARKERS[name][rcParams[f"{name}tick.direction"]]
        colour = rcParams[f"{name}tick.color"]
        for side, shown in enumerate((tick.tick1line.get_visible(),
                                      tick.tick2line.get_visible())):
            if not shown:
                continue
            at = np.full(locs.size, float(side))  # the spine: 0 bottom/left, 1 top/right
            which = f"tick{side + 1}"
            data, transform = ((locs, at), ax.get_xaxis_transform(which)) if name == "x" \
                else ((at, locs), ax.get_yaxis_transform(which))
            line = mlines.Line2D(*data, linestyle="none", marker=marks[side],
                                 markersize=rcParams[f"{name}tick.minor.size"],
                                 markeredgewidth=rcParams[f"{name}tick.minor.width"],
                                 color=colour, markeredgecolor=colour, clip_on=False,
                                 transform=transform)
            line.set_figure(self.figure)
            line.draw(renderer)


def log_minor_ticks(axis, *, marks: bool = True) -> None:
    """Unlabelled minor ticks of a logarithmic axis, in the view only.

    Parameters
    ----------
    axis : matplotlib.axis.Axis
        A logarithmic axis.
    marks : bool
        True: a :class:`MinorTickMarks` instead of tick objects; False: matplotlib's.
    """
    axis.set_minor_formatter(NullFormatter())
    if not marks:
        axis.set_minor_locator(in_view_log_locator(subs="auto"))
        return
    axis.set_minor_locator(NullLocator())
    axis.axes.add_artist(MinorTickMarks(axis))
