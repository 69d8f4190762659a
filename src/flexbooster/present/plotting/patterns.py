"""Nodal patterns of the shell modes on the unrolled cylinder surfaces (memo Fig. 4): the
nodal circles and generators of sin(j pi s / 2) cos(k theta) (5.3-2d, 5.3-3d) and the
chequerboard of signs between them.
"""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure

from ...memo.charts import NodalPattern
from .layout import new_axes, new_figure

__all__ = ["nodal_pattern", "nodal_patterns"]


def nodal_pattern(data: NodalPattern, ax: Axes | None = None) -> Figure:
    """The (j, k) nodal pattern of one cylinder on its unrolled surface, w > 0 red, w < 0 blue,
    nodal lines black (memo Fig. 4).

    Parameters
    ----------
    data : NodalPattern
        The mode's nodal lines and cell signs, radius and half-length (m).
    ax : matplotlib.axes.Axes, optional
        Axes to draw on; a new figure is made when None.
    """
    fig, ax = new_axes(ax, (6.4, 3.4))
    R, L = data.radius, data.half_length
    theta_edges = np.concatenate(([0.0], data.theta_nodes, [2.0 * np.pi]))
    ax.pcolormesh(data.s_nodes * L, theta_edges * R, data.sign, shading="flat",
                  cmap="RdBu_r", vmin=-1.6, vmax=1.6)
    for xs in data.s_nodes * L:
        ax.axvline(xs, color="k", lw=1.2)
    for th in data.theta_nodes * R:
        ax.axhline(th, color="k", lw=1.2)
    ax.set_xlim(0.0, 2.0 * L)
    ax.set_ylim(0.0, 2.0 * np.pi * R)
    ax.set_xlabel(f"x from the aft edge of cylinder {data.cylinder} (m)")
    ax.set_ylabel("arc Rθ (m)")
    title = f"cylinder {data.cylinder}: nodal pattern j = {data.j}, k = {data.k}"
    label = f" ({data.hz:.4g} Hz)" if data.hz > 0 else ""
    ax.set_title(title + label, fontsize=9)
    return fig


def nodal_patterns(patterns: tuple[NodalPattern, ...] | list[NodalPattern]) -> Figure:
    """Nodal patterns of one mode of each cylinder, one above the other (memo Fig. 4a, 4b).

    Parameters
    ----------
    patterns : sequence of NodalPattern
        One per panel, cylinder 1 (aft) first.
    """
    fig = new_figure((7.0, 3.0 * len(patterns)))
    axes = np.atleast_1d(fig.subplots(len(patterns), 1))
    for data, ax in zip(patterns, axes, strict=True):
        nodal_pattern(data, ax=ax)
    return fig
