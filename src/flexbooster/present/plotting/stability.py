"""Campbell-style diagram of the stability equations (memo section 7)."""

from __future__ import annotations

import numpy as np
from matplotlib.collections import LineCollection
from matplotlib.figure import Figure

from ...memo.charts import CampbellData

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


def campbell_diagram(data: CampbellData, ax=None) -> Figure:
    """Excitation curves against Omega, shell frequencies as horizontal lines, roots marked.

    Parameters
    ----------
    data : CampbellData
        From :func:`flexbooster.memo.charts.campbell_data`.
    ax : matplotlib.axes.Axes, optional
        Where to draw; a new figure when None.

    Returns
    -------
    matplotlib.figure.Figure

    References
    ----------
    Tech Memo 104, eqs. (7.3-1)..(7.3-35).
    """
    if ax is None:
        fig = Figure(figsize=(8.0, 6.0))
        ax = fig.add_subplot()
    else:
        fig = ax.figure
    x = data.Omega_bar
    y_max = float(max(np.max(data.shell_omega_bar, initial=1.0), 1.0)) * 1.05
    segments = [np.column_stack([[x[0], x[-1]], [w, w]]) for w in data.shell_omega_bar
                if w <= y_max]
    ax.add_collection(LineCollection(segments, colors="0.8", linewidths=0.5, zorder=0))
    for fam, (label, colour) in _STYLE.items():
        for n, c in enumerate(np.flatnonzero(data.family == fam)):
            ax.plot(x, data.curves[c], color=colour, lw=0.8, label=label if n == 0 else None)
    act = data.root_active
    if act.size:
        ax.plot(data.root_Omega_bar[act], data.root_shell_omega_bar[act], "o", ms=3,
                color="crimson", label="root, active")
        ax.plot(data.root_Omega_bar[~act], data.root_shell_omega_bar[~act], "o", ms=3,
                mfc="none", color="0.4", label="root, listed")
    ax.set_xlim(x[0], x[-1])
    ax.set_ylim(0.0, y_max)
    ax.set_xlabel("thrust frequency $\\Omega/\\omega_1$")
    ax.set_ylabel("frequency / $\\omega_1$")
    ax.set_title("Campbell diagram: excitations (memo 7.3) and shell frequencies")
    ax.legend(loc="upper left", fontsize="small", ncol=2)
    return fig
