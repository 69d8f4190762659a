"""Campbell-style diagram of the stability equations (memo section 7)."""

from __future__ import annotations

import numpy as np
from matplotlib.collections import LineCollection
from matplotlib.figure import Figure

from ...memo.charts import CampbellData
from .labels import plain_log_ticks
from .layout import new_axes

__all__ = ["campbell_diagram"]

_STYLE = {  # family (memo 7.4 numbering) -> (label, colour)
    7: ("family 7: Ωᵢ", "C0"),
    12: ("family 12: 2Ωᵢ", "C1"),
    8: ("family 8: Ω + Ωᵢ", "C2"),
    9: ("family 9: |Ω − Ωᵢ|", "C3"),
    10: ("family 10: Ωᵢ + Ωₚ", "C4"),
    11: ("family 11: |Ωᵢ − Ωₚ|", "C5"),
    13: ("family 13: |αᵣ + s| Ω", "C8"),
    3: ("family 3: Ω", "k"),
}


def campbell_diagram(data: CampbellData, ax=None, *, significant=None) -> Figure:
    """Excitation curves against Omega (Hz, log), one colour per family, the shell frequencies of
    the significant roots grey and the roots red (memo 7.3).

    Parameters
    ----------
    data : CampbellData
        From :func:`flexbooster.memo.charts.campbell_data`.
    ax : matplotlib.axes.Axes, optional
        Where to draw; a new figure when None.
    significant : numpy.ndarray of bool, optional
        Shape like ``data.root_active``: the roots to draw (default the active ones).
    """
    fig, ax = new_axes(ax, (9.0, 5.6))
    mask = data.root_active if significant is None else np.asarray(significant, dtype=bool)
    if mask.shape != data.root_active.shape:
        raise ValueError(f"significant.shape = {mask.shape}: must be {data.root_active.shape}")
    hz = data.omega_1 / (2.0 * np.pi)  # units of omega_1 -> Hz
    x = data.Omega_bar * hz
    roots_x, roots_y = data.root_Omega_bar[mask] * hz, data.root_shell_omega_bar[mask] * hz
    lines = np.unique(roots_y)
    y_top = (float(roots_y.max()) if roots_y.size else float(x[-1])) * 1.3
    y_bottom = min(float(np.min(data.shell_omega_bar, initial=1.0)) * hz, float(x[0])) / 1.3
    segments = [np.column_stack([[x[0], x[-1]], [w, w]]) for w in lines]
    ax.add_collection(LineCollection(segments, colors="0.85", linewidths=0.5, zorder=0,
                                     label="shell frequency with a root"))
    for fam, (label, colour) in _STYLE.items():
        for n, c in enumerate(np.flatnonzero(data.family == fam)):
            y = np.where(data.curves[c] > 0.0, data.curves[c], np.nan) * hz  # log axis
            ax.plot(x, y, color=colour, lw=0.9, alpha=0.85, label=label if n == 0 else None)
    if roots_x.size:
        ax.plot(roots_x, roots_y, "o", ms=2.5, color="crimson", zorder=3,
                label=f"root with active forcing ({roots_x.size} of {mask.size})"
                if significant is None else f"significant root ({roots_x.size})")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlim(x[0], x[-1])
    ax.set_ylim(y_bottom, y_top)
    ax.set_xlabel("thrust frequency Omega (Hz)")
    ax.set_ylabel("excitation / shell frequency (Hz)")
    sec = ax.secondary_xaxis("top", functions=(lambda f: f / hz, lambda r: r * hz))
    sec.set_xlabel("Omega / omega_1")
    for axis in (ax.xaxis, ax.yaxis, sec.xaxis):
        plain_log_ticks(axis)
    ax.set_title("Campbell diagram: excitations (memo 7.3, family numbers) and shell modes",
                 fontsize=10)
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize="small",
              borderaxespad=0.0)
    return fig
