"""Free-free beam mode shapes (memo appendix C)."""

from __future__ import annotations

from matplotlib.axes import Axes
from matplotlib.figure import Figure

from ...memo.charts import BeamModeShapes
from .labels import subscript as _sub
from .layout import new_axes

__all__ = ["mode_shape_plot"]


def mode_shape_plot(data: BeamModeShapes, ax: Axes | None = None) -> Figure:
    """phi_n(zeta) over the beam coordinate zeta in [0, 2], junction and CM marked (memo 4.1-2,
    C-1, C-6..C-9).

    Parameters
    ----------
    data : BeamModeShapes
        From :func:`flexbooster.memo.charts.beam_mode_shapes`.
    ax : matplotlib.axes.Axes, optional
        Axes to draw on; a new figure is made when None.
    """
    fig, ax = new_axes(ax, (6.4, 3.6))
    for n, (phi, lam) in enumerate(zip(data.phi, data.lambda_n, strict=True), start=1):
        ax.plot(data.zeta, phi, label=f"{_sub('φ', n)}, λ = {lam:.4f}")
    ax.axvline(data.zeta_junction, color="0.5", ls="--", lw=0.8, label="junction")
    ax.axvline(data.zeta_cm, color="0.5", ls=":", lw=0.8, label="CM")
    ax.axhline(0.0, color="k", lw=0.5)
    # plain text, no mathtext (labels.py): ξ with a combining macron, d with subscript 4
    ax.set_xlabel(f"ζ = ξ\u0304 − {_sub('d', 4)}/L + 1 (aft edge 0, nose 2)")
    ax.set_ylabel("φₙ")
    ax.set_title("Free-free beam modes")
    ax.legend(fontsize=7)
    return fig
