"""Ince-Strutt stability chart of the rigid-body pitch equation (memo section 4.2)."""

from __future__ import annotations

from typing import Any

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure

from ..pitch import characteristic_exponent, transition_curves

__all__ = ["ince_strutt_chart", "beta_comparison_plot"]


def _axes(ax: Axes | None, figsize: tuple[float, float]) -> tuple[Figure, Axes]:
    if ax is None:
        fig = Figure(figsize=figsize, layout="constrained")
        return fig, fig.add_subplot()
    return ax.figure, ax


def ince_strutt_chart(
    q_max: float | None = None,
    a_range: tuple[float, float] | None = None,
    path: tuple[Any, Any] | None = None,
    r_max: int = 3,
    n_grid: int = 300,
    ax: Axes | None = None,
) -> Figure:
    """Ince-Strutt chart (a against q) with the booster's operating path.

    Parameters
    ----------
    q_max : float, optional
        Largest q shown (dimensionless); default 1.3 times the path's largest q, at least 0.1.
    a_range : (float, float), optional
        Range of a shown (dimensionless); default covers the path and the first tongue.
    path : (array_like, array_like), optional
        The operating path (a(Omega), q(Omega)) of eq. (4.2-4), drawn as a line with markers;
        points inside a tongue are drawn in red.
    r_max : int
        Highest transition curves a_r, b_r drawn.
    n_grid : int
        Grid points per axis for the shading of the unstable regions (growth per period,
        Im beta, from Hill's determinant).
    ax : matplotlib.axes.Axes, optional
        Axes to draw on; a new figure is made when None.

    Returns
    -------
    matplotlib.figure.Figure
        The figure; the transition curves come from
        :func:`flexbooster.pitch.transition_curves`.

    References
    ----------
    Abramowitz & Stegun (1964), fig. 20.1; Tech Memo 104, eqs. (4.2-3)..(4.2-5).
    """
    fig, ax = _axes(ax, (6.4, 4.8))
    a_path = q_path = None
    if path is not None:
        a_path = np.asarray(path[0], dtype=float)
        q_path = np.abs(np.asarray(path[1], dtype=float))
        if a_path.shape != q_path.shape:
            raise ValueError(
                f"path: a and q must have the same shape, got {a_path.shape}, {q_path.shape}"
            )
    if q_max is None:
        q_max = max(0.1, 1.3 * float(np.max(q_path))) if q_path is not None else 1.0
    if not (np.isfinite(q_max) and q_max > 0):
        raise ValueError(f"q_max = {q_max!r}: must be finite and > 0")
    if a_range is None:
        lo, hi = -0.2, 1.5
        if a_path is not None:
            lo = min(lo, float(np.min(a_path)) - 0.1)
            hi = max(hi, float(np.max(a_path)) * 1.1)
        a_range = (lo, hi)
    a_lo, a_hi = float(a_range[0]), float(a_range[1])
    if not (np.isfinite(a_lo) and np.isfinite(a_hi) and a_lo < a_hi):
        raise ValueError(f"a_range = {a_range!r}: need finite a_min < a_max")
    qg = np.linspace(0.0, q_max, n_grid)
    ag = np.linspace(a_lo, a_hi, n_grid)
    growth = characteristic_exponent(ag[:, None], qg[None, :], "hill").imag
    shade = np.ma.masked_where(growth <= 0.0, growth)
    mesh = ax.pcolormesh(qg, ag, shade, shading="auto", cmap="Reds", alpha=0.6)
    fig.colorbar(mesh, ax=ax, label=r"growth per unit $\tau_1$, Im $\beta$")
    curves = transition_curves(qg, r_max)
    for name, values in curves.items():
        style = "-" if name.startswith("a") else "--"
        ax.plot(qg, values, style, color="k", lw=0.8)
        r = int(name[1:])
        visible = (values > a_lo) & (values < a_hi)
        if np.any(visible):
            i = np.flatnonzero(visible)[-1]
            ax.annotate(
                f"${name[0]}_{r}$",
                (qg[i], values[i]),
                fontsize=8,
                xytext=(2, 2),
                textcoords="offset points",
            )
    if a_path is not None:
        ax.plot(q_path, a_path, "-", color="C0", lw=1.2, label="operating path")
        beta = characteristic_exponent(a_path, q_path, "hill")
        bad = beta.imag > 0
        ax.plot(q_path[~bad], a_path[~bad], "o", color="C0", ms=2.5)
        if np.any(bad):
            ax.plot(q_path[bad], a_path[bad], "o", color="C3", ms=3.5, label="unstable")
        ax.legend(loc="upper left", fontsize=8)
    ax.set_xlim(0.0, q_max)
    ax.set_ylim(a_lo, a_hi)
    ax.set_xlabel("q")
    ax.set_ylabel("a")
    ax.set_title(r"Ince-Strutt chart, $\psi'' + (a - 2q\cos 2\tau_1)\psi = 0$")
    return fig


def beta_comparison_plot(
    a_values: Any = (0.2, 0.5, 0.8),
    q_max: float = 0.05,
    n_q: int = 40,
    ax: Axes | None = None,
) -> Figure:
    """|beta_memo - beta_exact| against q (log-log): eq. (4.2-9) corrected and as printed.

    Parameters
    ----------
    a_values : sequence of float
        Values of a in (0, 1) (dimensionless), one pair of curves each.
    q_max : float
        Largest q (dimensionless); q runs logarithmically from q_max / 100.
    n_q : int
        Points per curve.
    ax : matplotlib.axes.Axes, optional
        Axes to draw on; a new figure is made when None.

    Returns
    -------
    matplotlib.figure.Figure
        Solid: corrected (erratum E4), slope 4; dashed: printed, slope 2; dotted guides
        proportional to q^4 and q^2.

    References
    ----------
    Tech Memo 104, eq. (4.2-9); reading guide erratum E4; A&S (1964) 20.3.15.
    """
    fig, ax = _axes(ax, (5.6, 4.2))
    q = np.geomspace(q_max / 100.0, q_max, n_q)
    for i, a in enumerate(a_values):
        exact = characteristic_exponent(a, q, "hill")
        corr = np.abs(characteristic_exponent(a, q, "memo") - exact)
        printed = np.abs(characteristic_exponent(a, q, "memo-printed") - exact)
        ax.loglog(q, np.maximum(corr, 1e-17), "-", color=f"C{i}", label=f"a = {a:g}, corrected")
        ax.loglog(q, printed, "--", color=f"C{i}", label=f"a = {a:g}, as printed")
    ax.loglog(q, 0.5 * (q / q_max) ** 4 * 1e-6, ":", color="0.4", label=r"$\propto q^4$")
    ax.loglog(q, (q / q_max) ** 2 * 1e-3, ":", color="0.7", label=r"$\propto q^2$")
    ax.set_xlabel("q")
    ax.set_ylabel(r"$|\beta_{memo} - \beta_{exact}|$")
    ax.set_title("Eq. (4.2-9) against the exact Floquet exponent")
    ax.legend(fontsize=7, ncol=2)
    return fig
