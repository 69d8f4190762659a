"""Modal time responses (memo 6.2): amplitudes against tau and the deformed booster."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from ...memo.responses import SimulationResult
from .layout import new_axes

__all__ = ["modal_amplitudes", "deformed_booster", "mode_names", "mode_verdicts",
           "GROWTH_RATIO"]

#: A coordinate is "growing" when its peak |amplitude| over the last third of the window
#: exceeds this multiple of its peak over the first third (a display rule, not a stability
#: criterion: the Floquet and secular analyses are in ``flexbooster run``).
GROWTH_RATIO = 1.5
_COMPONENT_WORDS = {"U": "axial", "V": "circumferential", "W": "radial"}


def mode_names(result: SimulationResult) -> list[str]:
    """The modal coordinates in words, one per row of ``result.amplitude``, e.g. "cylinder 1
    radial W, j = 2, k = 0".

    Parameters
    ----------
    result : SimulationResult
        From :func:`flexbooster.memo.responses.simulate`.
    """
    return [f"cylinder {d} {_COMPONENT_WORDS.get(str(c), str(c))} {c}, j = {j}, k = {k}"
            for c, d, j, k in zip(result.component, result.cylinder, result.j, result.k,
                                  strict=True)]


def mode_verdicts(result: SimulationResult) -> list[tuple[str, str, float]]:
    """(name, "growing" or "bounded", peak |amplitude| in m) per modal coordinate: growing when the
    peak of the last third exceeds :data:`GROWTH_RATIO` times that of the first.

    Parameters
    ----------
    result : SimulationResult
        From :func:`flexbooster.memo.responses.simulate` (at least 3 output times).
    """
    amp = np.abs(np.asarray(result.amplitude, dtype=float)) * result.params.L  # units of L -> m
    n = amp.shape[1] if amp.ndim == 2 else 0
    out = []
    for name, row in zip(mode_names(result), amp, strict=True):
        third = max(1, n // 3)
        first, last = float(row[:third].max()), float(row[-third:].max())
        growing = last > GROWTH_RATIO * first and last > 0.0
        out.append((name, "growing" if growing else "bounded", float(row.max())))
    return out


def modal_amplitudes(result: SimulationResult, top: int = 8, ax=None) -> Figure:
    """The largest modal amplitudes (mm) against t (s), tau on the top axis (memo 6.2).

    Parameters
    ----------
    result : SimulationResult
        From :func:`flexbooster.memo.responses.simulate`.
    top : int
        Number of coordinates drawn (the largest peaks), >= 1.
    ax : matplotlib.axes.Axes, optional
        Where to draw; a new figure when None.
    """
    if int(top) < 1:
        raise ValueError(f"top = {top!r}: must be >= 1")
    fig, ax = new_axes(ax, (9, 4.5))
    L = result.params.L
    if result.amplitude.shape[0]:
        peak = np.abs(result.amplitude).max(axis=1)
        order = np.argsort(peak)[::-1][: int(top)]
        labels = mode_names(result)
        for c in order:
            ax.plot(result.t, result.amplitude[c] * L * 1e3, lw=1.0, label=labels[c])
        ax.legend(fontsize="small", loc="upper left", bbox_to_anchor=(1.01, 1.0),
                  borderaxespad=0.0)
        sec = ax.secondary_xaxis("top", functions=(lambda t: t * result.omega_1,
                                                   lambda tau: tau / result.omega_1))
        sec.set_xlabel("τ = ω₁t")
    ax.set_xlabel("time t (s)")
    ax.set_ylabel("modal amplitude (mm)")
    ax.set_title(f"Ω = {result.Omega:.4g} rad/s ({result.method})")
    ax.grid(True, alpha=0.3)
    return fig


def deformed_booster(result: SimulationResult, instant: int = -1, scale: float | None = None,
                     ax=None) -> Figure:
    """Side view (theta = 0 and pi) of the booster at one snapshot: outline grey, deformed
    x = x_cm + L xi + s u, z = +-(R_d - s w) (m; memo 5.2-1, 5.3-4).

    Parameters
    ----------
    result : SimulationResult
        With snapshots (``n_snapshots >= 1``).
    instant : int
        Index into the snapshots (default the last).
    scale : float, optional
        Displacement magnification; default a round number drawing the largest displacement
        as about 10 % of the smaller radius.
    ax : matplotlib.axes.Axes, optional
        Where to draw; a new figure when None.
    """
    snaps = result.snapshots
    if not snaps or len(snaps["index"]) == 0:
        raise ValueError("result: has no snapshots (simulate with n_snapshots >= 1)")
    fig, ax = new_axes(ax, (9, 3.5))
    p = result.params
    xi, th = np.asarray(snaps["xi"]), np.asarray(snaps["theta"])
    u, w = np.asarray(snaps["u"])[instant], np.asarray(snaps["w"])[instant]
    peak = max(np.abs(u).max(), np.abs(w).max())
    if scale is None:
        scale = _round_scale(0.1 * min(result.radii) / peak) if peak > 0 else 1.0
    R = np.where(xi < p.c, result.radii[0], result.radii[1])
    x = (xi - p.a) * p.L  # from the aft edge
    for t0, sign in ((0.0, 1.0), (np.pi, -1.0)):
        q = int(np.argmin(np.abs(np.angle(np.exp(1j * (th - t0))))))
        ax.plot(x, sign * R, color="0.7", lw=1.0)
        ax.plot(x + scale * u[:, q], sign * (R - scale * w[:, q]), color="C0", lw=1.5)
    tau = float(result.tau[snaps["index"][instant]])
    ax.set_xlabel("x from the aft edge (m)")
    ax.set_ylabel("z (m)")
    t = float(result.t[snaps["index"][instant]])
    ax.set_title(f"t = {t:.4g} s (τ = {tau:.4g}); displacements magnified x {scale:.3g}")
    ax.set_aspect("equal", adjustable="datalim")
    return fig


def _round_scale(x: float) -> float:
    """The largest of 1, 2, 5 times a power of ten not above x (x > 0)."""
    e = np.floor(np.log10(x))
    for m in (5.0, 2.0, 1.0):
        if m * 10.0 ** e <= x:
            return float(m * 10.0 ** e)
    return float(10.0 ** e)
