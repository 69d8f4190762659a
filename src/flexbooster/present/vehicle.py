"""Presentation of the vehicle modes: rich tables, the CSV, modes.json and the figures.

A thin layer over a stored :class:`~flexbooster.shell_of_revolution.survey.VehicleSurvey`
(``flexbooster modes``; ``Results.vehicle`` of ``flexbooster run``); it computes nothing.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
from rich.console import Console
from rich.markup import escape
from rich.table import Table

from ..shell_of_revolution.survey import VehicleSurvey
from .io import write_csv_atomic, write_json_atomic

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = [
    "VEHICLE_FIGURES",
    "vehicle_figure_names",
    "print_vehicle_modes",
    "print_vehicle_summary",
    "vehicle_figures",
    "write_vehicle_files",
]

#: Figure file stems of the vehicle modes and their captions.
VEHICLE_FIGURES = {
    "vehicle-mode-shapes": "Vehicle mode shapes: the deformed meridian (plane theta = 0) of the "
                           "lowest modes of the lowest harmonics k",
    "vehicle-unrolled": "Vehicle modes on the unrolled surface: normal displacement "
                        "w(s, theta) of the lowest mode of the lowest harmonics",
}


def _g(x: float) -> str:
    return f"{x:.6g}"


def _header(survey: VehicleSurvey, console: Console) -> None:
    what = ("[[vehicle.segments]]" if survey.source == "vehicle"
            else "the memo vehicle built from [booster] (memo-bulkhead junction)")
    v = survey.vehicle
    console.print(f"[bold]Vehicle modes[/bold] of {escape(what)}: {len(v.segments)} segments, ends "
                  f"{v.aft_end} / {v.fwd_end}, {v.theory} theory, k = 0..{survey.k_max}, "
                  f"{len(survey.modes)} modes")
    console.print(escape(f"Frequencies {survey.note}."))
    for w in survey.modes.warnings:
        console.print("  [yellow]warning[/yellow] " + escape(f"[{w.code}] {w.message}"))


def print_vehicle_modes(survey: VehicleSurvey, console: Console | None = None) -> None:
    """Print one table of modes per harmonic k (``flexbooster modes``; fits 80 columns).

    Parameters
    ----------
    survey : VehicleSurvey
        The stored vehicle modes.
    console : rich.console.Console, optional
        Where to print; a new console on standard output by default.
    """
    console = console or Console()
    _header(survey, console)
    m = survey.modes
    for kk in np.unique(m.k):
        rows = np.flatnonzero(m.k == kk)
        table = Table(title=f"k = {kk}: {rows.size} modes", title_justify="left",
                      header_style="bold")
        for col in ("#", "Hz", "rad/s", "order", "type", "segment", "kinetic u/v/w"):
            table.add_column(col, justify="left" if col == "type" else "right")
        for n, i in enumerate(rows):
            share = "/".join(f"{x:.2f}" for x in m.kinetic_share[i])
            table.add_row(str(n + 1), _g(m.hz[i]), _g(m.omega[i]), str(m.order[i]),
                          str(m.type[i]), str(m.segment[i]), share)
        console.print(table)
    if not len(m):
        console.print("No modes in the requested range.")


def print_vehicle_summary(survey: VehicleSurvey, console: Console) -> None:
    """Print the lowest mode of each harmonic k in one table (``flexbooster run``).

    Parameters
    ----------
    survey : VehicleSurvey
        The stored vehicle modes.
    console : rich.console.Console
        Where to print.
    """
    _header(survey, console)
    m = survey.modes
    table = Table(title="Vehicle modes (shell of revolution): the lowest of each k "
                  "(all in vehicle-modes.csv)", title_justify="left", header_style="bold")
    for col in ("k", "modes", "lowest Hz", "rad/s", "type", "order", "segment"):
        table.add_column(col, justify="left" if col == "type" else "right")
    for kk in np.unique(m.k):
        rows = np.flatnonzero(m.k == kk)
        i = int(rows[np.argmin(m.hz[rows])])
        table.add_row(str(kk), str(rows.size), _g(m.hz[i]), _g(m.omega[i]), str(m.type[i]),
                      str(m.order[i]), str(m.segment[i]))
    console.print(table)


def vehicle_figure_names(survey: VehicleSurvey) -> tuple[str, ...]:
    """The names of the figures :func:`vehicle_figures` draws for these modes.

    Parameters
    ----------
    survey : VehicleSurvey
        The stored vehicle modes.

    Returns
    -------
    tuple of str
        ``vehicle-mode-shapes`` and, when modes were selected for it, ``vehicle-unrolled``;
        empty without stored views.
    """
    if survey.views is None:
        return ()
    if survey.views.unrolled_index.size:
        return ("vehicle-mode-shapes", "vehicle-unrolled")
    return ("vehicle-mode-shapes",)


def vehicle_figures(survey: VehicleSurvey, *, names=None) -> dict[str, Figure]:
    """The figures of the vehicle modes, drawn from the stored views.

    Parameters
    ----------
    survey : VehicleSurvey
        The stored vehicle modes; no figure without ``views``.
    names : iterable of str, optional
        Only these of :func:`vehicle_figure_names` (default all).

    Returns
    -------
    dict of str to matplotlib.figure.Figure
        ``vehicle-mode-shapes`` and, when modes were selected for it, ``vehicle-unrolled``.
    """
    available = vehicle_figure_names(survey)
    wanted = [n for n in (available if names is None else names) if n in available]
    if not wanted:
        return {}
    import matplotlib

    matplotlib.use("Agg")
    from .plotting.vehicle import meridian_shapes, unrolled_modes

    draw = {"vehicle-mode-shapes": meridian_shapes, "vehicle-unrolled": unrolled_modes}
    return {name: draw[name](survey.views) for name in wanted}


def write_vehicle_files(survey: VehicleSurvey, folder: str | Path, *,
                        figures: bool = True) -> list[Path]:
    """Write ``modes.json``, ``vehicle-modes.csv`` and the figures (``flexbooster modes -o``).

    Parameters
    ----------
    survey : VehicleSurvey
        The stored vehicle modes.
    folder : str or pathlib.Path
        Output folder (created if needed).
    figures : bool
        Also draw the figures (SVG and PNG).

    Returns
    -------
    list of pathlib.Path
        The files written.
    """
    from .outputs import save_figure

    folder = Path(folder)
    written = [write_json_atomic(folder / "modes.json", survey.to_dict()),
               write_csv_atomic(folder / "vehicle-modes.csv", survey.to_columns())]
    if figures:
        for name, fig in vehicle_figures(survey).items():
            written += save_figure(fig, folder / name)
    return written
