"""Writing an analysis to a folder: results.json, CSV tables and figures (SVG and PNG).

A thin layer over :mod:`flexbooster.io` (atomic writes) and :mod:`flexbooster.plotting`.
"""

from __future__ import annotations

import io as _io
from pathlib import Path

from .analysis import Results
from .io import write_bytes_atomic, write_csv_atomic, write_json_atomic

__all__ = ["write_outputs", "save_figure"]


def save_figure(fig, path_stem: Path, formats: tuple[str, ...] = ("svg", "png")) -> list[Path]:
    """Save a matplotlib figure atomically as ``path_stem.<format>`` for each format.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure.
    path_stem : pathlib.Path
        Destination without suffix.
    formats : tuple of str
        Image formats.

    Returns
    -------
    list of pathlib.Path
        The files written.
    """
    paths = []
    for fmt in formats:
        buffer = _io.BytesIO()
        fig.savefig(buffer, format=fmt, dpi=150, bbox_inches="tight")
        paths.append(write_bytes_atomic(path_stem.with_suffix(f".{fmt}"), buffer.getvalue()))
    return paths


def write_outputs(results: Results, folder: str | Path, figures: bool = True) -> list[Path]:
    """Write every output of an analysis into ``folder``.

    Parameters
    ----------
    results : Results
        The analysis.
    folder : str or pathlib.Path
        Output folder (created if needed).
    figures : bool
        Also draw and save the figures (SVG and PNG).

    Returns
    -------
    list of pathlib.Path
        The files written: results.json, shell-frequencies.csv, unstable-frequencies.csv (when
        the stability table was computed) and the figures.
    """
    folder = Path(folder)
    written = [write_json_atomic(folder / "results.json", results.to_dict())]
    written.append(write_csv_atomic(folder / "shell-frequencies.csv", results.shell.to_rows()))
    if results.stability is not None:
        written.append(
            write_csv_atomic(folder / "unstable-frequencies.csv", results.stability.to_rows())
        )
    if figures:
        written += _figures(results, folder)
    return written


def _figures(results: Results, folder: Path) -> list[Path]:
    import matplotlib

    matplotlib.use("Agg")
    from .plotting.beam import mode_shape_plot
    from .plotting.pitch import ince_strutt_chart
    from .plotting.shell import frequency_curves

    written = []
    written += save_figure(
        ince_strutt_chart(path=(results.pitch.a, results.pitch.q)), folder / "ince-strutt"
    )
    written += save_figure(
        mode_shape_plot(N=min(4, results.case.truncation.N), props=results.mass),
        folder / "beam-modes",
    )
    for d in (1, 2):
        written += save_figure(
            frequency_curves(results.shell, d), folder / f"shell-frequencies-cylinder{d}"
        )
    if results.stability is not None and results.beam_action is not None:
        import numpy as np

        from .analysis import stability_parameters
        from .plotting.stability import campbell_diagram

        t = results.case.thrust
        x = np.geomspace(t.omega_min, t.omega_max, 600) / results.omega_1
        beta, alpha = stability_parameters(
            results.omega_psi, t.gamma, results.omega_1, results.beam_action
        )(x)
        fig = campbell_diagram(
            x,
            beta,
            alpha,
            results.shell.omega_bar,
            results.stability,
            results.case.truncation.R,
            results.case.truncation.S,
        )
        written += save_figure(fig, folder / "campbell")
    return written
