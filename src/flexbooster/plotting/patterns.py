"""Nodal patterns of the shell modes on the unrolled cylinder surfaces (memo Fig. 4).

The radial shape function of cylinder d is h_jk = sin(j pi s / 2) cos(k theta) (eqs. 5.3-2d,
5.3-3d) with the local axial coordinate s = 0 at the cylinder's aft edge and s = 2 at its
forward edge (the zero-phase default of :mod:`flexbooster.shell`; erratum E10 explains why the
printed phase is not used).  Its nodal lines are the j + 1 circles s = 2 i / j (edges included)
and the 2k generators theta = (2 i + 1) pi / (2 k); the surface between them is divided into
j x 2k cells of alternating sign, the chequerboard of memo Fig. 4.
"""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure

__all__ = ["nodal_lines", "nodal_pattern", "nodal_patterns"]


def _check_index(name: str, value: int, low: int) -> int:
    if isinstance(value, bool) or int(value) != value or value < low:
        raise ValueError(f"{name} = {value!r}: must be an integer >= {low}")
    return int(value)


def nodal_lines(j: int, k: int) -> tuple[np.ndarray, np.ndarray]:
    """Nodal lines of the radial shape sin(j pi s / 2) cos(k theta) (eqs. 5.3-2d, 5.3-3d).

    Parameters
    ----------
    j : int
        Axial index (>= 1; j half-waves along the cylinder).
    k : int
        Circumferential index (>= 0; k full waves around the circumference).

    Returns
    -------
    s : numpy.ndarray
        Axial nodal circles s = 2 i / j, i = 0..j, in the local coordinate s in [0, 2]
        (0 = aft edge, 2 = forward edge).
    theta : numpy.ndarray
        Nodal generators theta = (2 i + 1) pi / (2 k), i = 0..2k - 1 (rad); empty for k = 0.

    References
    ----------
    Tech Memo 104, eqs. (5.3-2d), (5.3-3d), Fig. 4.
    """
    j = _check_index("j", j, 1)
    k = _check_index("k", k, 0)
    s = 2.0 * np.arange(j + 1) / j  # sin(j pi s / 2) = 0, eq. (5.3-2d)
    theta = (2.0 * np.arange(2 * k) + 1.0) * np.pi / (2.0 * k) if k else np.empty(0)  # cos k theta
    return s, theta


def nodal_pattern(
    j: int,
    k: int,
    radius: float,
    half_length: float,
    cylinder: int = 1,
    label: str | None = None,
    ax: Axes | None = None,
) -> Figure:
    """The (j, k) nodal pattern of one cylinder on its unrolled surface (memo Fig. 4).

    Parameters
    ----------
    j, k : int
        Axial (>= 1) and circumferential (>= 0) indices of the mode.
    radius : float
        Cylinder radius R_d (m); the vertical axis is the arc length R_d theta (m).
    half_length : float
        Cylinder half-length L_d (m); the horizontal axis runs from the aft edge, 0, to 2 L_d (m).
    cylinder : int
        1 (aft) or 2 (forward), for the title.
    label : str, optional
        Extra text for the title, e.g. the frequency.
    ax : matplotlib.axes.Axes, optional
        Axes to draw on; a new figure is made when None.

    Returns
    -------
    matplotlib.figure.Figure
        Cells where w > 0 shaded red, w < 0 blue; nodal lines in black.

    References
    ----------
    Tech Memo 104, eqs. (5.3-2d), (5.3-3d), Fig. 4.
    """
    s_nodes, theta_nodes = nodal_lines(j, k)
    if cylinder not in (1, 2):
        raise ValueError(f"cylinder = {cylinder!r}: must be 1 or 2")
    for name, value in (("radius", radius), ("half_length", half_length)):
        if not (np.isfinite(value) and value > 0):
            raise ValueError(f"{name} = {value!r}: must be finite and > 0 (m)")
    if ax is None:
        fig = Figure(figsize=(6.4, 3.4), layout="constrained")
        ax = fig.add_subplot()
    else:
        fig = ax.figure
    # One flat cell between neighbouring nodal lines, coloured by the sign of w at its centre.
    theta_edges = np.concatenate(([0.0], theta_nodes, [2.0 * np.pi]))
    s_mid = 0.5 * (s_nodes[1:] + s_nodes[:-1])
    theta_mid = 0.5 * (theta_edges[1:] + theta_edges[:-1])
    w = np.sin(j * np.pi * s_mid[None, :] / 2.0) * np.cos(k * theta_mid[:, None])  # (5.3-2d)
    ax.pcolormesh(s_nodes * half_length, theta_edges * radius, np.sign(w), shading="flat",
                  cmap="RdBu_r", vmin=-1.6, vmax=1.6)
    for xs in s_nodes * half_length:
        ax.axvline(xs, color="k", lw=1.2)
    for th in theta_nodes * radius:
        ax.axhline(th, color="k", lw=1.2)
    ax.set_xlim(0.0, 2.0 * half_length)
    ax.set_ylim(0.0, 2.0 * np.pi * radius)
    ax.set_xlabel(f"x from the aft edge of cylinder {cylinder} (m)")
    ax.set_ylabel(r"arc $R\theta$ (m)")
    title = f"cylinder {cylinder}: nodal pattern j = {j}, k = {k}"
    ax.set_title(title + (f" ({label})" if label else ""), fontsize=9)
    return fig


def nodal_patterns(shell, radii: tuple[float, float], half_lengths: tuple[float, float],
                   modes: dict | None = None) -> Figure:
    """Nodal patterns of one mode of each cylinder, side by side (memo Fig. 4a, 4b).

    Parameters
    ----------
    shell : flexbooster.shell.ShellFrequencies
        The frequency table; it gives the frequency printed with each pattern.
    radii : (float, float)
        R1, R2 (m).
    half_lengths : (float, float)
        L1, L2 (m).
    modes : dict of int to (int, int), optional
        Cylinder -> (j, k) drawn.  By default the lowest-frequency mode with j >= 1 and k >= 1
        of each cylinder (a true chequerboard, as in Fig. 4).

    Returns
    -------
    matplotlib.figure.Figure
        Two panels, cylinder 1 (aft) on top.

    References
    ----------
    Tech Memo 104, Fig. 4, eqs. (5.3-2d), (5.3-3d).
    """
    modes = dict(modes or {})
    fig = Figure(figsize=(7.0, 6.0), layout="constrained")
    axes = fig.subplots(2, 1)
    for d, ax in zip((1, 2), axes, strict=True):
        if d in modes:
            j, k = modes[d]
            rows = np.flatnonzero(shell.select(cylinder=d, j=j, k=k))
        else:
            rows = np.flatnonzero((shell.cylinder == d) & (shell.j >= 1) & (shell.k >= 1))
            if rows.size == 0:
                rows = np.flatnonzero((shell.cylinder == d) & (shell.j >= 1))
            if rows.size == 0:
                raise ValueError(f"shell: cylinder {d} has no mode with j >= 1")
            lowest = rows[np.argmin(shell.hz[rows])]
            j, k = int(shell.j[lowest]), int(shell.k[lowest])
            rows = np.flatnonzero(shell.select(cylinder=d, j=j, k=k))
        label = None
        if rows.size:
            label = f"{float(np.min(shell.hz[rows])):.4g} Hz"
        nodal_pattern(j, k, radii[d - 1], half_lengths[d - 1], cylinder=d, label=label, ax=ax)
    return fig
