"""Free-free beam mode shapes (memo appendix C)."""

from __future__ import annotations

from typing import Any

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure

from ..beam import free_free_eigenvalues, mode_shape

__all__ = ["mode_shape_plot"]


def mode_shape_plot(
    N: int = 4, props: Any = None, n_points: int = 400, ax: Axes | None = None
) -> Figure:
    """phi_n(zeta), n = 1..N, over the beam coordinate zeta in [0, 2] (C-1, C-6).

    Parameters
    ----------
    N : int
        Number of modes drawn (>= 1).
    props : flexbooster.geometry.MassProperties, optional
        When given, the junction (zeta = 2 L1 / L, eq. C-8) and the CM (zeta = 1 - d4/L) are
        marked.
    n_points : int
        Points per curve.
    ax : matplotlib.axes.Axes, optional
        Axes to draw on; a new figure is made when None.

    Returns
    -------
    matplotlib.figure.Figure
        The figure.

    References
    ----------
    Tech Memo 104, eqs. (4.1-2), (C-1), (C-6)..(C-9).
    """
    if int(N) != N or N < 1:
        raise ValueError(f"N = {N!r}: must be an integer >= 1")
    if ax is None:
        fig = Figure(figsize=(6.4, 3.6), layout="constrained")
        ax = fig.add_subplot()
    else:
        fig = ax.figure
    zeta = np.linspace(0.0, 2.0, n_points)
    lam = free_free_eigenvalues(int(N))
    for n in range(1, int(N) + 1):
        ax.plot(zeta, mode_shape(n, zeta), label=rf"$\phi_{n}$, $\lambda$ = {lam[n - 1]:.4f}")
    if props is not None:
        L = float(props.L)
        zeta_c = (L - (float(props.d4) - float(props.d1))) / L  # eq. (C-8)
        ax.axvline(zeta_c, color="0.5", ls="--", lw=0.8, label="junction")
        ax.axvline(1.0 - float(props.d4) / L, color="0.5", ls=":", lw=0.8, label="CM")
    ax.axhline(0.0, color="k", lw=0.5)
    ax.set_xlabel(r"$\zeta = \bar\xi - d_4/L + 1$ (aft edge 0, nose 2)")
    ax.set_ylabel(r"$\phi_n$")
    ax.set_title("Free-free beam modes")
    ax.legend(fontsize=7)
    return fig
