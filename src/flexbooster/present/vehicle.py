"""Presentation of the vehicle modes: rich tables, the CSV, modes.json and the figures.

A thin layer over a stored :class:`~flexbooster.shell_of_revolution.survey.VehicleSurvey`
(``flexbooster modes``; ``Results.vehicle`` of ``flexbooster run``); it computes nothing.
Also the vehicle's parametric instability regions (``Results.vehicle_regions``):
``vehicle-regions.csv`` (:func:`vehicle_region_columns`), the summary section
(:func:`print_vehicle_regions`) and the chart (:func:`vehicle_region_figures`).
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
from rich.console import Console
from rich.markup import escape
from rich.table import Table

from ..dynamics import VehicleRegions
from ..results import Results
from ..shell_of_revolution.survey import VehicleSurvey
from .io import write_csv_atomic, write_json_atomic
from .rows import (
    MEMO_ROOT_HEADER,
    REGION_HEADER,
    memo_root_rows,
    region_modes_words,
    slosh_rows,
    vehicle_mass_rows,
    vehicle_region_rows,
    vehicle_region_table,
)

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = [
    "VEHICLE_FIGURES",
    "vehicle_figure_names",
    "VEHICLE_REGION_CSV_COLUMNS",
    "SUMMARY_REGION_ROWS",
    "vehicle_region_columns",
    "print_vehicle_regions",
    "vehicle_region_figures",
    "print_vehicle_modes",
    "print_vehicle_summary",
    "print_vehicle_mass",
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
    print_vehicle_mass(survey, console)


def _rows_table(title: str, rows) -> Table:
    table = Table(title=title, title_justify="left", header_style="bold")
    for col in ("quantity", "value", "unit"):
        table.add_column(col, justify="right" if col == "value" else "left")
    for quantity, value, unit in rows:
        table.add_row(escape(quantity), escape(value if isinstance(value, str) else _g(value)),
                      unit)
    return table


def print_vehicle_mass(survey: VehicleSurvey, console: Console, *, mass: bool = True) -> None:
    """Print the vehicle's mass properties (each contribution) and each tank's first slosh
    mode, where the survey has them.

    Parameters
    ----------
    survey : VehicleSurvey
        Its ``mass_properties`` and ``slosh`` are printed.
    console : rich.console.Console
        The output.
    mass : bool
        Also the mass properties (``run`` prints them in its own table).
    """
    mp = getattr(survey, "mass_properties", None)
    if mass and mp is not None:
        console.print(_rows_table("Mass properties of the vehicle (from the aft edge)",
                                  vehicle_mass_rows(mp)))
    slosh = getattr(survey, "slosh", ())
    if slosh:
        console.print(_rows_table("Slosh: each tank's first mode under the thrust's "
                                  "acceleration (Abramson, NASA SP-106)", slosh_rows(slosh)))


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
    print_vehicle_mass(survey, console, mass=False)


def vehicle_figure_names(survey: VehicleSurvey) -> tuple[str, ...]:
    """The names of the figures :func:`vehicle_figures` draws: ``vehicle-mode-shapes`` and, with
    selected modes, ``vehicle-unrolled``; empty without stored views.

    Parameters
    ----------
    survey : VehicleSurvey
        The stored vehicle modes.
    """
    if survey.views is None:
        return ()
    if survey.views.unrolled_index.size:
        return ("vehicle-mode-shapes", "vehicle-unrolled")
    return ("vehicle-mode-shapes",)


def vehicle_figures(survey: VehicleSurvey, *, names=None) -> dict[str, Figure]:
    """The figures of the vehicle modes, drawn from the stored views, by name.

    Parameters
    ----------
    survey : VehicleSurvey
        The stored vehicle modes; no figure without ``views``.
    names : iterable of str, optional
        Only these of :func:`vehicle_figure_names` (default all).
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
    """Write ``modes.json``, ``vehicle-modes.csv`` and the figures (``flexbooster modes -o``);
    returns the files written.

    Parameters
    ----------
    survey : VehicleSurvey
        The stored vehicle modes.
    folder : str or pathlib.Path
        Output folder (created if needed).
    figures : bool
        Also draw the figures (SVG and PNG).
    """
    from .figure_files import save_figure

    folder = Path(folder)
    written = [write_json_atomic(folder / "modes.json", survey.to_dict()),
               write_csv_atomic(folder / "vehicle-modes.csv", survey.to_columns())]
    if figures:
        for name, fig in vehicle_figures(survey).items():
            written += save_figure(fig, folder / name)
    return written


#: Columns of ``vehicle-regions.csv`` (one region a row, sorted by Omega_lo then k).
VEHICLE_REGION_CSV_COLUMNS = (
    "k", "kind", "order", "modes", "mode_indices", "Omega_lo_rad_s", "Omega_hi_rad_s",
    "Omega_lo_hz", "Omega_hi_hz", "width_rad_s", "growth_rate_max", "Omega_at_max_rad_s",
    "Omega_center_rad_s", "critical_gamma", "clipped",
)
#: Regions listed in the terminal summary (all are in vehicle-regions.csv).
SUMMARY_REGION_ROWS = 15


def vehicle_region_columns(regions: VehicleRegions) -> dict[str, list]:
    """The regions by columns (:data:`VEHICLE_REGION_CSV_COLUMNS`) for ``vehicle-regions.csv``:
    growth rate in 1/s, modes in words, ``mode_indices`` 0-based joined by "+".

    Parameters
    ----------
    regions : VehicleRegions
        The stored regions (rad/s).
    """
    two_pi = 2.0 * np.pi
    rs = regions.regions
    cols = {
        "k": [int(r.k) for r in rs],
        "kind": [str(r.kind) for r in rs],
        "order": [int(r.order) for r in rs],
        "modes": [region_modes_words(r) for r in rs],
        "mode_indices": ["+".join(str(m.index) for m in r.modes) for r in rs],
        "Omega_lo_rad_s": [float(r.Omega_lo) for r in rs],
        "Omega_hi_rad_s": [float(r.Omega_hi) for r in rs],
        "Omega_lo_hz": [float(r.Omega_lo) / two_pi for r in rs],
        "Omega_hi_hz": [float(r.Omega_hi) / two_pi for r in rs],
        "width_rad_s": [float(r.width) for r in rs],
        "growth_rate_max": [float(r.growth_rate_max) for r in rs],
        "Omega_at_max_rad_s": [float(r.Omega_at_max) for r in rs],
        "Omega_center_rad_s": [float(r.Omega_center) for r in rs],
        "critical_gamma": [float(r.critical_gamma) for r in rs],
        "clipped": [bool(r.clipped) for r in rs],
    }
    return {name: cols[name] for name in VEHICLE_REGION_CSV_COLUMNS}


def print_vehicle_regions(results: Results, console: Console) -> None:
    """Print the section "Vehicle parametric instability regions" (``flexbooster run``).

    Parameters
    ----------
    results : Results
        The analysis ("not computed" without regions).
    console : rich.console.Console
        Where to print.
    """
    if results.vehicle_regions is None:
        console.print("Vehicle parametric instability regions: not computed.")
        return
    table = Table(title="Vehicle parametric instability regions (shell of revolution, "
                  "all in vehicle-regions.csv)", title_justify="left",
                  header_style="bold")
    for col in ("quantity", "value", "unit"):
        table.add_column(col, justify="right" if col == "value" else "left")
    for q, v, u in vehicle_region_rows(results):
        table.add_row(escape(q), escape(v if isinstance(v, str) else _value(v)), escape(u))
    console.print(table)
    rows = vehicle_region_table(results)
    if rows:
        regions = Table(title=f"Regions by growth rate (first {min(len(rows), SUMMARY_REGION_ROWS)}"
                        f" of {len(rows)})", title_justify="left", header_style="bold")
        for col in REGION_HEADER:
            regions.add_column(col, justify="left" if col in ("modes", "kind") else "right")
        for row in rows[:SUMMARY_REGION_ROWS]:
            regions.add_row(*(escape(_value(v)) for v in row))
        console.print(regions)
    roots = memo_root_rows(results)
    m = results.memo_roots_in_regions
    if m is not None and results.vehicle_regions.regions:
        console.print(escape(f"Memo-table roots inside a region: {len(roots)} "
                             f"({int(np.sum(m.active))} with active forcing); regions no "
                             f"active memo root explains: {m.without_active_root.size} of "
                             f"{m.n_regions}."))
        if roots:
            t = Table(title=f"Memo roots inside the regions (first {min(len(roots), 15)})",
                      title_justify="left", header_style="bold")
            for col in MEMO_ROOT_HEADER:
                t.add_column(col)
            for row in roots[:15]:
                t.add_row(*(escape(_value(v)) for v in row))
            console.print(t)


def _value(v: object) -> str:
    if isinstance(v, str):
        return v
    if isinstance(v, bool | np.bool_ | int | np.integer):
        return str(v)
    return _g(float(v))


def vehicle_region_figures(results: Results) -> dict[str, Figure]:
    """The vehicle region chart ``vehicle-regions``, drawn from the stored regions and curves.

    Parameters
    ----------
    results : Results
        The analysis; no figure without ``results.vehicle_regions``.
    """
    if results.vehicle_regions is None:
        return {}
    import matplotlib

    matplotlib.use("Agg")
    from .plotting.vehicle_regions import vehicle_region_chart

    return {"vehicle-regions": vehicle_region_chart(results.vehicle_regions)}
