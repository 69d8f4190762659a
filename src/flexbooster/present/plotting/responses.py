"""Modal time responses (memo 6.2): amplitudes against tau and the deformed booster."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from ...memo.responses import SimulationResult

__all__ = ["modal_amplitudes", "deformed_booster"]


def modal_amplitudes(result: SimulationResult, top: int = 8, ax=None) -> Figure:
    """The largest modal amplitudes U_jk, V_jk, W_jk against tau (memo 6.2).

    Parameters
    ----------
    result : SimulationResult
        From :func:`flexbooster.memo.responses.simulate`.
    top : int
        Number of coordinates drawn (those with the largest peak |amplitude|), >= 1.
    ax : matplotlib.axes.Axes, optional
        Where to draw; a new figure when None.

    Returns
    -------
    matplotlib.figure.Figure
        One line per coordinate, amplitude in millimetres against tau = omega_1 t.

    References
    ----------
    Tech Memo 104, eqs. (6.2-3), (6.2-11), (6.2-12), (6.2-20).
    """
    if int(top) < 1:
        raise ValueError(f"top = {top!r}: must be >= 1")
    if ax is None:
        fig = Figure(figsize=(8, 4.5))
        ax = fig.add_subplot(1, 1, 1)
    else:
        fig = ax.figure
    L = result.params.L
    if result.amplitude.shape[0]:
        peak = np.abs(result.amplitude).max(axis=1)
        order = np.argsort(peak)[::-1][: int(top)]
        labels = result.labels()
        for c in order:
            ax.plot(result.tau, result.amplitude[c] * L * 1e3, lw=1.0, label=labels[c])
        ax.legend(fontsize="small", ncol=2)
    ax.set_xlabel(r"$\tau = \omega_1 t$")
    ax.set_ylabel("modal amplitude (mm)")
    ax.set_title(rf"$\Omega$ = {result.Omega:.4g} rad/s ({result.method})")
    ax.grid(True, alpha=0.3)
    return fig


def deformed_booster(result: SimulationResult, instant: int = -1, scale: float | None = None,
                     ax=None) -> Figure:
    """Side view (theta = 0 and pi) of the booster deformed at one snapshot instant.

    Parameters
    ----------
    result : SimulationResult
        With snapshots (``n_snapshots >= 1`` in :func:`flexbooster.memo.responses.simulate`).
    instant : int
        Index into the snapshots (default the last).
    scale : float, optional
        Displacement magnification (default: largest displacement drawn as 5 % of L).
    ax : matplotlib.axes.Axes, optional
        Where to draw; a new figure when None.

    Returns
    -------
    matplotlib.figure.Figure
        The undeformed outline (grey) and the deformed one: x = x_cm + L xi + s u,
        z = +-(R_d - s w) (w positive inward, memo 3.0), in metres.

    References
    ----------
    Tech Memo 104, eqs. (5.2-1), (5.3-4).
    """
    snaps = result.snapshots
    if not snaps or len(snaps["index"]) == 0:
        raise ValueError("result: has no snapshots (simulate with n_snapshots >= 1)")
    if ax is None:
        fig = Figure(figsize=(9, 3.5))
        ax = fig.add_subplot(1, 1, 1)
    else:
        fig = ax.figure
    p = result.params
    xi, th = np.asarray(snaps["xi"]), np.asarray(snaps["theta"])
    u, w = np.asarray(snaps["u"])[instant], np.asarray(snaps["w"])[instant]
    peak = max(np.abs(u).max(), np.abs(w).max())
    if scale is None:
        scale = 0.05 * p.L / peak if peak > 0 else 1.0
    R = np.where(xi < p.c, result.radii[0], result.radii[1])
    x = (xi - p.a) * p.L  # from the aft edge
    for t0, sign in ((0.0, 1.0), (np.pi, -1.0)):
        q = int(np.argmin(np.abs(np.angle(np.exp(1j * (th - t0))))))
        ax.plot(x, sign * R, color="0.7", lw=1.0)
        ax.plot(x + scale * u[:, q], sign * (R - scale * w[:, q]), color="C0", lw=1.5)
    tau = float(result.tau[snaps["index"][instant]])
    ax.set_xlabel("x from the aft edge (m)")
    ax.set_ylabel("z (m)")
    ax.set_title(rf"$\tau$ = {tau:.4g}, displacements x {scale:.3g}")
    ax.set_aspect("equal", adjustable="datalim")
    return fig
