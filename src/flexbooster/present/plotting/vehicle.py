"""Figures of the vehicle modes: deformed meridians per harmonic and the unrolled surface.

Draws the stored :class:`~flexbooster.shell_of_revolution.survey.ModeShapeViews` only (the
displaced meridian and the field w(s, theta) are computed in the core).
"""

from __future__ import annotations

import math

import numpy as np
from matplotlib.figure import Figure

from ...shell_of_revolution.survey import ModeShapeViews
from .layout import new_figure

__all__ = ["meridian_shapes", "unrolled_modes"]


def meridian_shapes(views: ModeShapeViews) -> Figure:
    """Deformed meridians (theta = 0) of the lowest modes, one panel per harmonic k, displaced by
    ``views.scale`` (m) over the undeformed one (Kraus 1967, ch. 2).

    Parameters
    ----------
    views : ModeShapeViews
        The stored figure data.
    """
    ks = [int(k) for k in views.harmonics]
    ncol = min(2, max(1, len(ks)))
    nrow = max(1, math.ceil(len(ks) / ncol))
    fig = new_figure((5.0 * ncol, 2.6 * nrow))
    for n, kk in enumerate(ks):
        ax = fig.add_subplot(nrow, ncol, n + 1)
        ax.plot(views.x, views.r, "--", color="0.6", lw=1.0, label="undeformed")
        for j in np.flatnonzero(views.k == kk):
            ax.plot(views.x_deformed[j], views.r_deformed[j], lw=1.2,
                    label=f"{views.hz[j]:.4g} Hz")
        ax.set_title(f"k = {kk}", fontsize=9)
        ax.set_xlabel("x from aft edge (m)", fontsize=8)
        ax.set_ylabel("r (m)", fontsize=8)
        ax.set_ylim(bottom=0.0)
        ax.tick_params(labelsize=7)
        ax.legend(fontsize=6, loc="lower right")
    fig.suptitle(f"Vehicle mode shapes at theta = 0 (displacement scale {views.scale:.3g} m)",
                 fontsize=10)
    return fig


def unrolled_modes(views: ModeShapeViews) -> Figure:
    """Normal displacement w(s, theta) of a few modes on the unrolled surface, one panel each.

    Parameters
    ----------
    views : ModeShapeViews
        The stored figure data (``theta``, ``s``, ``w``).
    """
    n = max(1, views.unrolled_index.size)
    fig = new_figure((3.2 * n, 3.6))
    for j in range(views.unrolled_index.size):
        ax = fig.add_subplot(1, n, j + 1)
        field = views.w[j]
        lim = float(np.max(np.abs(field))) or 1.0
        ax.pcolormesh(np.degrees(views.theta), views.s, field, cmap="RdBu_r", vmin=-lim,
                      vmax=lim, shading="nearest")
        ax.set_title(views.unrolled_label[j], fontsize=7)
        ax.set_xlabel("theta (deg)", fontsize=8)
        ax.set_ylabel("meridian s from aft edge (m)", fontsize=8)
        ax.tick_params(labelsize=7)
    title = "Vehicle modes on the unrolled surface: normal displacement w"
    # one panel is narrower than the title: two lines (else its ends are cut off)
    fig.suptitle(title if n > 1 else title.replace(": ", ":\n"), fontsize=10)
    return fig
