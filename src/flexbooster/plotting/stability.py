"""Campbell-style diagram of the stability equations (memo section 7)."""

from __future__ import annotations

import numpy as np
from matplotlib.collections import LineCollection
from matplotlib.figure import Figure

from ..stability import ExcitationCurves, StabilityTable, excitation, excitation_curves

__all__ = ["campbell_diagram"]

_STYLE = {  # family -> (label, colour)
    7: ("$\\Omega_i$", "C0"),
    12: ("$2\\Omega_i$", "C1"),
    8: ("$\\bar\\Omega + \\Omega_i$", "C2"),
    9: ("$|\\bar\\Omega - \\Omega_i|$", "C3"),
    10: ("$\\Omega_i + \\Omega_p$", "C4"),
    11: ("$|\\Omega_i - \\Omega_p|$", "C5"),
    13: ("$|\\alpha_r + s|\\,\\bar\\Omega$", "C7"),
    3: ("$\\bar\\Omega$", "k"),
}


def campbell_diagram(
    Omega_bar: np.ndarray,
    beta: np.ndarray,
    alpha: np.ndarray,
    shell_omega_bar: np.ndarray,
    table: StabilityTable,
    R: int,
    S: int,
    s_max: int = 2,
    ax=None,
) -> Figure:
    """Excitation curves against Omega, shell frequencies as horizontal lines, roots marked.

    Parameters
    ----------
    Omega_bar : numpy.ndarray
        Thrust frequencies Omega / omega_1 at which the curves are drawn.
    beta, alpha : numpy.ndarray
        beta(Omega), shape (n,), and alpha_r(Omega), shape (n, R).
    shell_omega_bar : numpy.ndarray
        Shell natural frequencies (units of omega_1), drawn as horizontal lines.
    table : StabilityTable
        Roots to mark (filled: active forcing; open: listed only).
    R, S : int
        Beam exponents and harmonics of the case.
    s_max : int
        Only harmonics |s| <= s_max of the (alpha_r + s) curves are drawn, to keep the figure
        readable (all are solved for).
    ax : matplotlib.axes.Axes, optional
        Where to draw; a new figure when None.

    Returns
    -------
    matplotlib.figure.Figure
    """
    if ax is None:
        fig = Figure(figsize=(8.0, 6.0))
        ax = fig.add_subplot()
    else:
        fig = ax.figure
    curves: ExcitationCurves = excitation_curves(R, S)
    E = excitation(curves, Omega_bar, beta, alpha)
    y_max = float(max(np.max(shell_omega_bar, initial=1.0), 1.0)) * 1.05
    segments = [
        np.column_stack([[Omega_bar[0], Omega_bar[-1]], [w, w]])
        for w in shell_omega_bar
        if w <= y_max
    ]
    ax.add_collection(LineCollection(segments, colors="0.8", linewidths=0.5, zorder=0))
    for fam, (label, colour) in _STYLE.items():
        rows = np.flatnonzero((curves.family == fam) & (np.abs(curves.s) <= s_max))
        for n, c in enumerate(rows):
            ax.plot(Omega_bar, E[c], color=colour, lw=0.8, label=label if n == 0 else None)
    if len(table):
        act = table.active
        ax.plot(
            table.Omega_bar[act],
            table.shell_omega_bar[act],
            "o",
            ms=3,
            color="crimson",
            label="root, active",
        )
        ax.plot(
            table.Omega_bar[~act],
            table.shell_omega_bar[~act],
            "o",
            ms=3,
            mfc="none",
            color="0.4",
            label="root, listed",
        )
    ax.set_xlim(Omega_bar[0], Omega_bar[-1])
    ax.set_ylim(0.0, y_max)
    ax.set_xlabel("thrust frequency $\\Omega/\\omega_1$")
    ax.set_ylabel("frequency / $\\omega_1$")
    ax.set_title("Campbell diagram: excitations (memo 7.3) and shell frequencies")
    ax.legend(loc="upper left", fontsize="small", ncol=2)
    return fig
