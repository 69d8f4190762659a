"""Free-free beam mode shapes (memo appendix C)."""

from __future__ import annotations

from matplotlib.axes import Axes
from matplotlib.figure import Figure

from ...memo.charts import BeamModeShapes
from .labels import subscript as _sub
from .layout import new_axes

__all__ = ["mode_shape_plot"]


def mode_shape_plot(data: BeamModeShapes, ax: Axes | None = None) -> Figure:
    """phi_n against the station x = L zeta (m) from the aft edge, junction and CM marked
    (memo 4.1-2, C-1, C-6..C-9); against zeta when the data hold no length.

    Parameters
    ----------
    data : BeamModeShapes
        From :func:`flexbooster.memo.charts.beam_mode_shapes`.
    ax : matplotlib.axes.Axes, optional
        Axes to draw on; a new figure is made when None.
    """
    fig, ax = new_axes(ax, (6.4, 3.6))
    scale = float(data.half_length) if data.half_length > 0.0 else 1.0  # zeta -> m
    x = data.zeta * scale
    for n, (phi, lam) in enumerate(zip(data.phi, data.lambda_n, strict=True), start=1):
        ax.plot(x, phi, label=f"{_sub('φ', n)}, λ = {lam:.4f}")
    ax.axvline(data.zeta_junction * scale, color="0.5", ls="--", lw=0.8, label="junction")
    ax.axvline(data.zeta_cm * scale, color="0.5", ls=":", lw=0.8, label="CM")
    ax.axhline(0.0, color="k", lw=0.5)
    ax.set_xlim(float(x[0]), float(x[-1]))
    if data.half_length > 0.0:
        ax.set_xlabel("station x from the aft edge (m)")
    else:  # plain text, no mathtext (labels.py): ξ with a combining macron, d with subscript 4
        ax.set_xlabel(f"ζ = ξ\u0304 − {_sub('d', 4)}/L + 1 (aft edge 0, nose 2)")
    ax.set_ylabel("φₙ (mode shape)")
    ax.set_title("Free-free beam modes along the booster")
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
    return fig
