"""Ince-Strutt stability chart of the rigid-body pitch equation (memo section 4.2)."""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure

from ...memo.charts import InceStruttData
from .labels import subscript as _sub
from .layout import new_axes

__all__ = ["ince_strutt_chart", "ince_strutt_view", "beta_comparison_plot", "PATH_MARGIN"]


#: The Ince-Strutt chart's view: the operating path's extent widened by this fraction of it on
#: each side (q from 0: the path's q tends to 0 as Omega grows).
PATH_MARGIN = 0.1
#: Smallest span of a in the view (a path of one point or of constant a).
_MIN_A_SPAN = 0.02


def ince_strutt_view(data: InceStruttData) -> tuple[tuple[float, float], tuple[float, float]]:
    """The chart's view ((q_lo, q_hi), (a_lo, a_hi)), zoomed to the operating path: q from 0 to
    (1 + :data:`PATH_MARGIN`) max q_path, a over the path's range widened by
    :data:`PATH_MARGIN` of it on each side (at least ``_MIN_A_SPAN`` wide).

    Parameters
    ----------
    data : InceStruttData
        The stored chart (its path).
    """
    q_max = float(np.max(data.q_path)) if data.q_path.size else 0.0
    q_hi = (1.0 + PATH_MARGIN) * q_max if q_max > 0.0 else float(data.q[-1])
    a_min, a_max = (float(np.min(data.a_path)), float(np.max(data.a_path))) \
        if data.a_path.size else (0.0, 1.0)
    pad = PATH_MARGIN * max(a_max - a_min, _MIN_A_SPAN)
    return (0.0, q_hi), (a_min - pad, a_max + pad)


def ince_strutt_chart(data: InceStruttData, ax: Axes | None = None, *,
                      Omega: np.ndarray | None = None) -> Figure:
    """Ince-Strutt chart (a against q) zoomed to the operating path (4.2-4,
    :func:`ince_strutt_view`): the tongues shaded from their boundaries, the path's unstable
    points red, labelled in Hz with ``Omega``, the lowest tongue above the view named (A&S fig.
    20.1).

    Parameters
    ----------
    data : InceStruttData
        From :func:`flexbooster.memo.charts.ince_strutt_data`.
    ax : matplotlib.axes.Axes, optional
        Axes to draw on; a new figure is made when None.
    Omega : numpy.ndarray, optional
        Shape like ``data.a_path``: the thrust frequency (rad/s) of each point of the path.
    """
    fig, ax = new_axes(ax, (6.4, 4.8))
    q, curves = data.q, data.curves
    (q_lo, q_hi), (a_lo, a_hi) = ince_strutt_view(data)
    in_q = q <= q_hi * (1.0 + 1e-12)
    floor = min(a_lo, float(np.min(curves["a0"]))) - 1.0  # below the view: fill to here
    ax.fill_between(q, floor, curves["a0"], color="C3", alpha=0.25, lw=0)
    r = 1
    while f"a{r}" in curves:
        lower = np.minimum(curves[f"a{r}"], curves[f"b{r}"])
        upper = np.maximum(curves[f"a{r}"], curves[f"b{r}"])
        ax.fill_between(q, lower, upper, color="C3", alpha=0.25, lw=0,
                        label="unstable (tongues)" if r == 1 else None)
        r += 1
    above = []
    for name, values in curves.items():
        ax.plot(q, values, "-" if name.startswith("a") else "--", color="k", lw=0.8)
        visible = in_q & (values > a_lo) & (values < a_hi)
        if np.any(visible):
            i = np.flatnonzero(visible)[-1]
            ax.annotate(_sub(name[0], name[1:]), (q[i], values[i]), fontsize=8,
                        xytext=(-2, 2), textcoords="offset points", ha="right")
        elif np.all(values[in_q] >= a_hi):
            above.append((float(np.min(values[in_q])), name))
    if above:
        a_next, name = min(above)
        ax.text(0.98, 0.98, f"next boundary above the view: {_sub(name[0], name[1:])} at "
                f"a ≥ {a_next:.3g}", transform=ax.transAxes, ha="right", va="top", fontsize=7,
                color="0.3")
    ok = data.path_stable
    ax.plot(data.q_path, data.a_path, "-", color="C0", lw=1.2, label="operating path")
    ax.plot(data.q_path[ok], data.a_path[ok], "o", color="C0", ms=2.5)
    if np.any(~ok):
        ax.plot(data.q_path[~ok], data.a_path[~ok], "o", color="C3", ms=3.5, label="unstable")
    if Omega is not None and np.shape(Omega) == np.shape(data.a_path):
        _label_path(ax, data, np.asarray(Omega, dtype=float) / (2.0 * np.pi),
                    ((q_lo, q_hi), (a_lo, a_hi)))
    ax.legend(loc="upper left", fontsize=8)
    ax.set_xlim(q_lo, q_hi)
    ax.set_ylim(a_lo, a_hi)
    ax.set_xlabel("q")
    ax.set_ylabel("a")
    ax.set_title("Ince-Strutt chart, ψ″ + (a − 2q cos 2τ₁) ψ = 0, at the operating path",
                 fontsize=10)
    return fig


def _label_path(ax: Axes, data: InceStruttData, hz: np.ndarray,
                view: tuple[tuple[float, float], tuple[float, float]]) -> None:
    """'f Hz' at the points of the path nearest to round frequencies (1-2-5 steps), no two
    closer than a label's size in the view."""
    (q_lo, q_hi), (a_lo, a_hi) = view
    inside = ((data.a_path > a_lo) & (data.a_path < a_hi) & (data.q_path >= q_lo)
              & (data.q_path <= q_hi))
    if not np.any(inside):
        return
    lo, hi = float(hz[inside].min()), float(hz[inside].max())
    marks = [m * 10.0 ** e for e in range(-3, 6) for m in (1, 2, 5) if lo <= m * 10.0 ** e <= hi]
    idx = np.flatnonzero(inside)
    span_q = (q_hi - q_lo) or 1.0
    span_a = (a_hi - a_lo) or 1.0
    placed: list[tuple[float, float]] = []
    for f in marks:  # low Omega (high a) first: the labels near the origin crowd together
        i = idx[np.argmin(np.abs(np.log(hz[idx] / f)))]
        pos = ((data.q_path[i] - q_lo) / span_q, (data.a_path[i] - a_lo) / span_a)
        if any(abs(pos[0] - p[0]) < 0.12 and abs(pos[1] - p[1]) < 0.05 for p in placed):
            continue
        placed.append(pos)
        ax.annotate(f"{f:g} Hz", (data.q_path[i], data.a_path[i]), fontsize=7, color="C0",
                    xytext=(4, -2), textcoords="offset points")
        ax.plot([data.q_path[i]], [data.a_path[i]], "s", color="C0", ms=3)


def beta_comparison_plot(q: np.ndarray, errors: dict, ax: Axes | None = None) -> Figure:
    """|beta_memo - beta_exact| against q (log-log) for eq. (4.2-9) corrected (E4, slope 4, solid)
    and as printed (slope 2, dashed), with q^4 and q^2 guides.

    Parameters
    ----------
    q : numpy.ndarray
        Shape (n,), Mathieu q, > 0.
    errors : dict of float to (numpy.ndarray, numpy.ndarray)
        a -> (|corrected - exact|, |printed - exact|), each shape (n,).
    ax : matplotlib.axes.Axes, optional
        Axes to draw on; a new figure is made when None.
    """
    fig, ax = new_axes(ax, (5.6, 4.2))
    q = np.asarray(q, dtype=float)
    q_max = float(q.max())
    for i, (a, (corr, printed)) in enumerate(errors.items()):
        ax.loglog(q, np.maximum(corr, 1e-17), "-", color=f"C{i}", label=f"a = {a:g}, corrected")
        ax.loglog(q, printed, "--", color=f"C{i}", label=f"a = {a:g}, as printed")
    ax.loglog(q, 0.5 * (q / q_max) ** 4 * 1e-6, ":", color="0.4", label="∝ q⁴")
    ax.loglog(q, (q / q_max) ** 2 * 1e-3, ":", color="0.7", label="∝ q²")
    ax.set_xlabel("q")
    ax.set_ylabel("|β(memo) − β(exact)|")
    ax.set_title("Eq. (4.2-9) against the exact Floquet exponent")
    ax.legend(fontsize=7, ncol=2)
    return fig
