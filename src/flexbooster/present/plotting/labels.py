"""Plain-text labels and tick formats shared by the figures (no mathtext).

Unicode sub- and superscripts (all in matplotlib's bundled DejaVu Sans) instead of TeX-like
mathtext: the figures read the same, and each label is laid out as plain text, which costs a
fraction of mathtext's parse and layout (about 1 s of CPU over the figures of a default run).
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["subscript", "superscript", "plain_log_ticks", "power_log_ticks"]

_SUB = str.maketrans("0123456789+-aeijklmnoprstuvx", "₀₁₂₃₄₅₆₇₈₉₊₋ₐₑᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓ")
_SUP = str.maketrans("0123456789+-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻")


def subscript(base: str, index: object) -> str:
    """``base`` with ``index`` written as Unicode subscripts, e.g. ("φ", 2) -> "φ₂".

    Parameters
    ----------
    base : str
        The symbol.
    index : object
        The index (its ``str``); characters without a subscript form follow an underscore.

    Returns
    -------
    str
        The label.
    """
    text = str(index)
    sub = text.translate(_SUB)
    return base + sub if sub != text or not text else f"{base}_{text}"


def superscript(text: object) -> str:
    """``text`` (digits and signs) as Unicode superscripts, e.g. -8 -> "⁻⁸".

    Parameters
    ----------
    text : object
        The exponent (its ``str``).

    Returns
    -------
    str
        The superscript.
    """
    return str(text).translate(_SUP)


def plain_log_ticks(axis) -> None:
    """Plain numbers ("0.5", "10", "200") on a logarithmic axis, no minor labels.

    Parameters
    ----------
    axis : matplotlib.axis.Axis
        E.g. ``ax.xaxis`` of an axes with a log scale.

    Notes
    -----
    Easier to read than 10^n and faster to draw (no mathtext layout).
    """
    from matplotlib.ticker import FuncFormatter, NullFormatter

    axis.set_major_locator(_in_view_log_locator(subs=(1.0, 2.0, 5.0)))
    axis.set_minor_locator(_in_view_log_locator(subs="auto"))
    axis.set_major_formatter(FuncFormatter(lambda v, _pos: f"{v:g}"))
    axis.set_minor_formatter(NullFormatter())


def power_log_ticks(axis) -> None:
    """Decades written 10⁻⁸, 10⁰, 10³ (plain text) on a logarithmic axis spanning many decades.

    Parameters
    ----------
    axis : matplotlib.axis.Axis
        E.g. ``ax2.yaxis`` of an axes with a log scale.
    """
    from matplotlib.ticker import FuncFormatter, NullFormatter

    def label(v, _pos):
        if not (v > 0.0 and math.isfinite(v)):
            return ""
        e = math.log10(v)
        return f"10{superscript(round(e))}" if abs(e - round(e)) < 1e-9 else ""

    axis.set_major_locator(_in_view_log_locator(subs=(1.0,)))
    axis.set_minor_locator(_in_view_log_locator(subs="auto"))
    axis.set_major_formatter(FuncFormatter(label))
    axis.set_minor_formatter(NullFormatter())


#: Relative margin (of the axis' span in decades) within which a tick beyond the view is kept;
#: matplotlib draws the ticks within 1e-10 of the span (``_interval_contains_close``).
_VIEW_MARGIN = 1e-9


def _in_view_log_locator(subs):
    """matplotlib's ``LogLocator(base=10, subs=subs)`` returning only the ticks in the view.

    ``LogLocator`` returns a decade more on each side, which the axis then makes tick objects
    for, updates at every draw and does not draw: about a third of the ticks of a log axis.
    The ticks drawn are the same.
    """
    from matplotlib.ticker import LogLocator

    class InViewLogLocator(LogLocator):
        def __call__(self):
            locs = np.asarray(super().__call__(), dtype=float)
            lo, hi = sorted(self.axis.get_view_interval())
            if not (lo > 0.0 and np.isfinite(hi)) or locs.size == 0:
                return locs
            span = max(math.log10(hi / lo), 1.0) * _VIEW_MARGIN
            with np.errstate(divide="ignore", invalid="ignore"):
                e = np.log10(locs)
            return locs[(e >= math.log10(lo) - span) & (e <= math.log10(hi) + span)]

    return InViewLogLocator(base=10.0, subs=subs)
