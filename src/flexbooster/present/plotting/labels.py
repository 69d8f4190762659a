"""Plain-text labels and tick formats shared by the figures: Unicode sub- and superscripts
(DejaVu Sans) instead of mathtext, laid out as plain text.
"""

from __future__ import annotations

import math

__all__ = ["subscript", "superscript", "plain_log_ticks", "power_log_ticks"]

_SUB = str.maketrans("0123456789+-aeijklmnoprstuvx", "₀₁₂₃₄₅₆₇₈₉₊₋ₐₑᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓ")
_SUP = str.maketrans("0123456789+-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻")


def subscript(base: str, index: object) -> str:
    """``base`` with ``index`` as Unicode subscripts, e.g. ("φ", 2) -> "φ₂".

    Parameters
    ----------
    base : str
        The symbol.
    index : object
        The index (its ``str``); characters without a subscript form follow an underscore.
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
    """
    return str(text).translate(_SUP)


def plain_log_ticks(axis, *, minor_marks: bool = True) -> None:
    """Plain numbers ("0.5", "10", "200"; round linear steps over a view narrower than a decade
    with fewer than three of those) on a logarithmic axis, no minor labels, ticks in the view
    only.

    Parameters
    ----------
    axis : matplotlib.axis.Axis
        E.g. ``ax.xaxis`` of an axes with a log scale.
    minor_marks : bool
        Minor ticks as one artist of marks (:class:`~.ticks.MinorTickMarks`); False:
        matplotlib's minor ticks (for grid lines at them).
    """
    from matplotlib.ticker import FuncFormatter

    from .ticks import log_minor_ticks, plain_log_locator

    axis.set_major_locator(plain_log_locator())
    axis.set_major_formatter(FuncFormatter(lambda v, _pos: f"{v:g}"))
    log_minor_ticks(axis, marks=minor_marks)


def power_log_ticks(axis) -> None:
    """Decades written 10⁻⁸, 10⁰, 10³ (plain text) on a logarithmic axis; minor ticks as
    :func:`plain_log_ticks`.

    Parameters
    ----------
    axis : matplotlib.axis.Axis
        E.g. ``ax2.yaxis`` of an axes with a log scale.
    """
    from matplotlib.ticker import FuncFormatter

    from .ticks import in_view_log_locator, log_minor_ticks

    def label(v, _pos):
        if not (v > 0.0 and math.isfinite(v)):
            return ""
        e = math.log10(v)
        return f"10{superscript(round(e))}" if abs(e - round(e)) < 1e-9 else ""

    axis.set_major_locator(in_view_log_locator(subs=(1.0,)))
    axis.set_major_formatter(FuncFormatter(label))
    log_minor_ticks(axis)
