"""A matplotlib figure as files: reproducible SVG and PNG bytes, written atomically."""

from __future__ import annotations

import io as _io
from pathlib import Path

from .io import write_bytes_atomic, write_text_atomic

__all__ = ["PNG_DPI", "render_figure", "save_figure"]

#: Resolution of the PNG files (dots per inch).
PNG_DPI = 120


def render_figure(fig) -> tuple[str, bytes]:
    """SVG text (reproducible ids) and PNG bytes of a figure, laid out once
    (:func:`flexbooster.present.plotting.layout.lay_out_once`) and drawn once per file.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure.
    """
    import matplotlib
    import numpy as np
    from matplotlib.collections import LineCollection, QuadMesh

    from .plotting.layout import lay_out_once

    for ax in fig.axes:  # dense meshes and line bundles as an embedded image: small, fast SVG
        for artist in ax.collections:  # (not the artists with a tooltip id: they stay vector)
            if isinstance(artist, QuadMesh | LineCollection) and artist.get_gid() is None:
                artist.set_rasterized(True)
        many = len(ax.lines) > 40  # many curves: one embedded image
        for line in ax.lines:  # and every line with thousands of points or markers
            if (many or np.size(line.get_xdata()) > 2000) and line.get_gid() is None:
                line.set_rasterized(True)
    lay_out_once(fig, dpi=PNG_DPI)  # measured by the renderer that draws the PNG
    with matplotlib.rc_context({"svg.hashsalt": "flexbooster"}):
        svg = _io.StringIO()
        fig.savefig(svg, format="svg", dpi=150, metadata={"Date": None})
    png = _io.BytesIO()
    fig.savefig(png, format="png", dpi=PNG_DPI)
    return svg.getvalue(), png.getvalue()


def save_figure(fig, path_stem: Path) -> list[Path]:
    """Save a figure atomically as ``path_stem.svg`` and ``path_stem.png``; returns the two paths.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure.
    path_stem : pathlib.Path
        Destination without suffix.
    """
    svg, png = render_figure(fig)
    return [
        write_text_atomic(path_stem.with_suffix(".svg"), svg),
        write_bytes_atomic(path_stem.with_suffix(".png"), png),
    ]
