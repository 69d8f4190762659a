"""Plain-text labels and tick formats shared by the figures (no mathtext).

Unicode sub- and superscripts (all in matplotlib's bundled DejaVu Sans) instead of TeX-like
mathtext: the figures read the same, and each label is laid out as plain text, which costs a
fraction of mathtext's parse and layout (about 1 s of CPU over the figures of a default run).
"""

from __future__ import annotations

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
    from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

    axis.set_major_locator(LogLocator(base=10.0, subs=(1.0, 2.0, 5.0)))
    axis.set_major_formatter(FuncFormatter(lambda v, _pos: f"{v:g}"))
    axis.set_minor_formatter(NullFormatter())


def power_log_ticks(axis) -> None:
    """Decades written 10⁻⁸, 10⁰, 10³ (plain text) on a logarithmic axis spanning many decades.

    Parameters
    ----------
    axis : matplotlib.axis.Axis
        E.g. ``ax2.yaxis`` of an axes with a log scale.
    """
    import math

    from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

    def label(v, _pos):
        if not (v > 0.0 and math.isfinite(v)):
            return ""
        e = math.log10(v)
        return f"10{superscript(round(e))}" if abs(e - round(e)) < 1e-9 else ""

    axis.set_major_locator(LogLocator(base=10.0))
    axis.set_major_formatter(FuncFormatter(label))
    axis.set_minor_formatter(NullFormatter())
