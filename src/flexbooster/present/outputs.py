"""Writing an analysis to a folder: results.json, CSV tables, figures (SVG, PNG), report.html.

A thin layer over :mod:`flexbooster.present.io` (atomic writes) and
:mod:`flexbooster.present.plotting`.
"""

from __future__ import annotations

import io as _io
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING

from ..results import Results
from .io import write_bytes_atomic, write_csv_atomic, write_json_atomic, write_text_atomic

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["OUTPUT_STAGES", "write_outputs", "save_figure", "make_figures", "figure_svgs"]

#: The stages of :func:`write_outputs`, as passed to its ``progress`` callback.
OUTPUT_STAGES = ("results.json and CSV", "figures", "report.html")


def save_figure(fig, path_stem: Path) -> list[Path]:
    """Save a matplotlib figure atomically as ``path_stem.svg`` and ``path_stem.png``.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure.
    path_stem : pathlib.Path
        Destination without suffix.

    Returns
    -------
    list of pathlib.Path
        The two files written.
    """
    svg, png = _render(fig)
    return [
        write_text_atomic(path_stem.with_suffix(".svg"), svg),
        write_bytes_atomic(path_stem.with_suffix(".png"), png),
    ]


def write_outputs(
    results: Results,
    folder: str | Path,
    figures: bool = True,
    progress: Callable[[str], None] | None = None,
) -> list[Path]:
    """Write every output of an analysis into ``folder``.

    Parameters
    ----------
    results : Results
        The analysis.
    folder : str or pathlib.Path
        Output folder (created if needed).
    figures : bool
        Also draw and save the figures (SVG and PNG); the report then embeds them.
    progress : callable, optional
        Called with the name of each stage (:data:`OUTPUT_STAGES`) as it starts.

    Returns
    -------
    list of pathlib.Path
        The files written: results.json, shell-frequencies.csv, unstable-frequencies.csv and
        resonance-bands.csv (when the stability table was computed), the figures and
        report.html (last).
    """
    from .report import write_report

    step = progress or (lambda stage: None)
    folder = Path(folder)
    step(OUTPUT_STAGES[0])
    written = [write_json_atomic(folder / "results.json", results.to_dict())]
    written.append(write_csv_atomic(folder / "shell-frequencies.csv", results.shell.to_rows()))
    if results.stability is not None:
        written.append(
            write_csv_atomic(folder / "unstable-frequencies.csv", results.stability.to_columns())
        )
    if results.severity is not None:  # issue 13: every band, most severe first
        written.append(write_csv_atomic(folder / "resonance-bands.csv",
                                        results.severity.band_rows()))
    if results.vehicle is not None:  # a case with [vehicle] only
        written.append(write_csv_atomic(folder / "vehicle-modes.csv",
                                        results.vehicle.to_columns()))
    svgs: dict[str, str] = {}
    if figures and results.figures is not None:
        step(OUTPUT_STAGES[1])
        for name, fig in make_figures(results).items():
            svg, png = _render(fig)
            svgs[name] = svg
            written.append(write_text_atomic(folder / f"{name}.svg", svg))
            written.append(write_bytes_atomic(folder / f"{name}.png", png))
    step(OUTPUT_STAGES[2])
    written.append(write_report(results, folder / "report.html", svgs))
    return written


def _render(fig) -> tuple[str, bytes]:
    """SVG text (reproducible ids) and PNG bytes of a figure.

    The figure is laid out once by matplotlib's constrained layout (set here when the figure
    has no layout engine) instead of ``bbox_inches="tight"``, which draws every figure twice.
    """
    import matplotlib
    import numpy as np
    from matplotlib.collections import LineCollection, QuadMesh

    for ax in fig.axes:  # dense meshes and line bundles as an embedded image: small, fast SVG
        for artist in ax.collections:
            if isinstance(artist, QuadMesh | LineCollection):
                artist.set_rasterized(True)
        many = len(ax.lines) > 40  # many curves: one embedded image
        for line in ax.lines:  # and every line with thousands of points or markers
            if many or np.size(line.get_xdata()) > 2000:
                line.set_rasterized(True)
    if fig.get_layout_engine() is None:
        fig.set_layout_engine("constrained")
    with matplotlib.rc_context({"svg.hashsalt": "flexbooster"}):
        svg = _io.StringIO()
        fig.savefig(svg, format="svg", dpi=150, metadata={"Date": None})
    fig.set_layout_engine("none")  # laid out by the first save: keep the positions
    png = _io.BytesIO()
    fig.savefig(png, format="png", dpi=120)
    return svg.getvalue(), png.getvalue()


def figure_svgs(results: Results) -> dict[str, str]:
    """SVG text of every figure of :func:`make_figures`, by name (for the report).

    Parameters
    ----------
    results : Results
        The analysis.

    Returns
    -------
    dict of str to str
        Figure name -> SVG document.
    """
    return {name: _render(fig)[0] for name, fig in make_figures(results).items()}


def make_figures(results: Results) -> dict[str, Figure]:
    """Draw the figures of an analysis (matplotlib, Agg backend) from its stored data.

    Parameters
    ----------
    results : Results
        The analysis; ``results.figures`` holds every curve drawn (nothing is recomputed).

    Returns
    -------
    dict of str to matplotlib.figure.Figure
        By file stem: ``ince-strutt``, ``beam-modes``, ``shell-frequencies-cylinder1``,
        ``shell-frequencies-cylinder2``, ``nodal-patterns``, ``pitch-band-chart`` and,
        when they were computed, ``beam-action-chart`` and ``campbell``; for a case with
        ``[vehicle]`` also ``vehicle-mode-shapes`` and ``vehicle-unrolled``.
    """
    import matplotlib

    matplotlib.use("Agg")
    from .plotting.bands import plot_band_chart
    from .plotting.beam import mode_shape_plot
    from .plotting.patterns import nodal_patterns
    from .plotting.pitch import ince_strutt_chart
    from .plotting.shell import frequency_curves
    from .plotting.stability import campbell_diagram

    data = results.figures
    if data is None:
        raise ValueError("results.figures: no figure data (the results were not made by analyze)")
    figs: dict[str, Figure] = {
        "ince-strutt": ince_strutt_chart(data.ince_strutt),
        "beam-modes": mode_shape_plot(data.beam_modes),
    }
    for d in (1, 2):
        figs[f"shell-frequencies-cylinder{d}"] = frequency_curves(results.shell, d)
    figs["nodal-patterns"] = nodal_patterns(data.nodal_patterns)
    if data.pitch_band_chart is not None:
        figs["pitch-band-chart"] = plot_band_chart(data.pitch_band_chart)
    if data.beam_action_chart is not None:
        figs["beam-action-chart"] = plot_band_chart(data.beam_action_chart)
    if data.campbell is not None:
        figs["campbell"] = campbell_diagram(data.campbell)
    if results.vehicle is not None:  # a case with [vehicle] only
        from .vehicle import vehicle_figures

        figs.update(vehicle_figures(results.vehicle))
    return figs
