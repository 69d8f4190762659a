"""Shell frequency curves: frequency against circumferential wave number k for each j."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from ...memo.shell import ShellFrequencies
from .labels import plain_log_ticks
from .layout import new_axes

__all__ = ["frequency_curves"]


def frequency_curves(
    table: ShellFrequencies,
    cylinder: int,
    branch: int = 1,
    unit: str = "hz",
    ax=None,
) -> Figure:
    """The shell frequency curves of one cylinder, f(k) on a log axis, one line per j >= 1 (gaps
    where ``table.excluded``); ValueError for a bad cylinder, branch or unit.

    Parameters
    ----------
    table : ShellFrequencies
        From :func:`flexbooster.memo.shell.natural_frequencies`.
    cylinder : int
        1 (aft) or 2 (forward).
    branch : int
        Which root per (j, k) to draw (1 = lowest).
    unit : {"hz", "rad_s", "omega_bar"}
        Frequency axis.
    ax : matplotlib.axes.Axes, optional
        Where to draw; a new figure when None.
    """
    if cylinder not in (1, 2):
        raise ValueError(f"cylinder = {cylinder!r}: must be 1 or 2")
    if branch not in (1, 2, 3):
        raise ValueError(f"branch = {branch!r}: must be 1, 2 or 3")
    labels = {"hz": "frequency (Hz)", "rad_s": "frequency (rad/s)",
              "omega_bar": "ω/ω₁ (units of ω₁)"}
    if unit not in labels:
        raise ValueError(f"unit = {unit!r}: must be one of {tuple(labels)}")
    fig, ax = new_axes(ax, (7.0, 5.0))
    values = getattr(table, unit)
    sel = (table.cylinder == cylinder) & (table.branch == branch) & (table.j >= 1)
    for j in np.unique(table.j[sel]):
        rows = np.flatnonzero(sel & (table.j == j))
        rows = rows[np.argsort(table.k[rows])]
        ax.plot(table.k[rows], values[rows], marker="o", ms=2.5, lw=0.9, label=f"j = {j}")
    ax.set_yscale("log")
    plain_log_ticks(ax.yaxis, minor_marks=False)  # the grid lines at the minor ticks too
    ax.set_xlabel("circumferential wave number k")
    ax.set_ylabel(labels[unit])
    ax.set_title(f"cylinder {cylinder}, branch {branch} ({table.method})")
    ax.grid(True, which="both", lw=0.3, alpha=0.5)
    if np.unique(table.j[sel]).size <= 12:
        ax.legend(fontsize="small", ncol=2)
    return fig
