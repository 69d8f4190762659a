"""Presentation of the vehicle's forced response (``Results.forced_response``): the rows shared by
the terminal summary and the report, the summary section, ``forced-response.csv`` and the
figures. A thin layer over the stored :class:`~flexbooster.results.ForcedLoads`; it computes
nothing.
"""

from __future__ import annotations

import io
from typing import TYPE_CHECKING

import numpy as np
from rich import box
from rich.console import Console
from rich.markup import escape
from rich.table import Table

from ..results import Results

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["FORCED_CSV", "FORCED_FIGURES", "FORCED_HEADER", "FORCED_ZERO", "forced_basis_text",
           "forced_rows", "forced_worst_lines", "forced_figure_names", "forced_figures",
           "print_forced_response"]

#: File of the curves (long format: one row per harmonic, station and Omega).
FORCED_CSV = "forced-response.csv"
#: Figures of the forced response: file stem -> caption.
FORCED_FIGURES = {
    "forced-acceleration": "Acceleration amplitude in g at every station against the thrust "
                           "oscillation frequency (log scale), each station's peak marked",
    "forced-envelopes": "Axial force and bending moment amplitudes along the vehicle at the "
                        "Omega where each is largest, and their peak over the range",
}
#: Said instead of the table when no harmonic is forced.
FORCED_ZERO = ("No thrust oscillation (gamma = 0, or every spectrum line of amplitude 0): the "
               "forced response is zero.")
#: Columns of :func:`forced_rows`.
FORCED_HEADER = ("station", "x (m)", "k", "peak acceleration (g)", "per 1 % of F0 (g)",
                 "at (Hz)", "peak axial force (N)", "at (Hz)", "peak bending moment (N m)",
                 "at (Hz)")

_TO_HZ = 1.0 / (2.0 * np.pi)
#: The terminal's columns (80 wide): the report's, with one load column per harmonic.
_TERMINAL_HEADER = ("station", "x (m)", "k", "peak (g)", "per 1 %", "at (Hz)", "peak load",
                    "at (Hz)")


def forced_basis_text(results: Results) -> str:
    """One line on the basis and its convergence, e.g. "k = 0: 95 modes + static correction
    (peaks change 2.5e-05 of the largest with 47 modes)"; "" without a forced response.

    Parameters
    ----------
    results : Results
        The analysis.
    """
    f = results.forced_response
    if f is None:
        return ""
    parts = []
    for k, n, c in zip(f.response.harmonics, f.n_modes, f.convergence, strict=True):
        text = f"k = {k}: {n} modes + static correction"
        text += (" (not forced)" if c is None else
                 f" (peaks change {c[1]:.2g} of the largest with {c[0]} modes)")
        parts.append(text)
    return "; ".join(parts)


def forced_rows(results: Results) -> list[tuple]:
    """One row per forced harmonic and station (:data:`FORCED_HEADER`), aft to forward: the peak
    acceleration (g), per 1 % of F0 of thrust oscillation ("-" for a spectrum or gamma = 0,
    where the report and the summary drop the column), its
    Omega (Hz), the peak axial force (k = 0) and bending moment (k = 1) and their Omega.

    Parameters
    ----------
    results : Results
        The analysis.
    """
    f = results.forced_response
    if f is None:
        return []
    scale = f.per_percent
    by_station = {(p.k, p.station): p for p in f.ranked_peaks()}
    rows = []
    for k in f.response.harmonics:
        for s in f.response.stations:
            p = by_station.get((k, s.name))
            if p is None:
                continue
            rows.append((s.name, s.x, k, p.acceleration_g,
                         "-" if scale is None else p.acceleration_g * scale, p.Omega * _TO_HZ,
                         p.axial_force_N if k == 0 else "-",
                         p.Omega_axial_force * _TO_HZ if k == 0 else "-",
                         p.bending_moment_Nm if k == 1 else "-",
                         p.Omega_bending_moment * _TO_HZ if k == 1 else "-"))
    return rows


def forced_worst_lines(results: Results) -> list[str]:
    """The largest internal loads along the whole vehicle: one line per envelope, "axial force
    4.1e+05 N at 12.3 m, Omega = 13.1 Hz".

    Parameters
    ----------
    results : Results
        The analysis.
    """
    f = results.forced_response
    if f is None:
        return []
    out = []
    forced = {k: c is not None for k, c in zip(f.response.harmonics, f.convergence,
                                                strict=True)}
    for e in f.response.envelopes:
        if not forced.get(e.k, False) or not e.peak.size:
            continue
        i = int(np.argmax(e.peak))
        out.append(f"largest {e.quantity.replace('_', ' ')} (k = {e.k}): {e.peak[i]:.4g} "
                   f"{e.unit} at {e.x[i]:.4g} m from the aft edge, Omega = "
                   f"{e.peak_omega[i] * _TO_HZ:.4g} Hz")
    return out


def _cell(value: object) -> str:
    if isinstance(value, str):
        return value
    if isinstance(value, int | np.integer):
        return str(int(value))
    return f"{float(value):.4g}"


def _forced_table(title: str, header: list[str], cells: list[list[str]]) -> Table:
    """The terminal's table: numbers and names never folded."""
    table = Table(title=title, title_justify="left", header_style="bold", box=box.SIMPLE_HEAD,
                  pad_edge=False, collapse_padding=True)
    for col in header:
        table.add_column(col, justify="left" if col == "station" else "right", no_wrap=True)
    for c in cells:
        table.add_row(*(escape(v) for v in c))
    return table


def _natural_width(header: list[str], cells: list[list[str]]) -> int:
    """The widest line of the table (without its title) on an unbounded terminal."""
    wide = Console(width=100_000, file=io.StringIO(), record=True, color_system=None)
    wide.print(_forced_table("", header, cells))
    return max((len(line.rstrip()) for line in wide.export_text().splitlines()), default=0)


def print_forced_response(results: Results, console: Console) -> None:
    """Print the section "Forced response to the thrust oscillation" (``flexbooster run``).

    Parameters
    ----------
    results : Results
        The analysis ("not computed" without a forced response).
    console : rich.console.Console
        Where to print.
    """
    f = results.forced_response
    if f is None:
        console.print("Forced response to the thrust oscillation: not computed (see the "
                      "warnings).")
        return
    r = f.response
    per = f.per_percent
    # the "per 1 %" column where it says something: not for a spectrum (its lines have their
    # own amplitudes) nor at gamma = 1 % (it repeats the peak; the title says so)
    show_per = per is not None and abs(per - 1.0) > 1e-12
    load = ("the spectrum's lines as given" if r.combination == "spectrum" else
            f"gamma = {r.amplitude[0]:g} over the Omega range"
            + ("" if show_per or per is None else ": the peaks are per 1 % of F0"))
    cells = []
    for row in forced_rows(results):  # the load of the harmonic: axial force or bending moment
        load_cells = row[6:8] if row[2] == 0 else row[8:10]
        cells.append([_cell(v) for v in (*row[:4], *(row[4:5] if show_per else ()), row[5],
                                         *load_cells)])
    header = [h for h in _TERMINAL_HEADER if show_per or h != "per 1 %"]
    title = (f"Forced response to the thrust oscillation ({load}, zeta = {r.damping_ratio:g}, "
             f"misalignment {r.misalignment:g} rad; accelerations in g, per 1 % of F0 where "
             f"given; load: axial force in N for k = 0, bending "
             f"moment in N m for k = 1; curves in {FORCED_CSV})")
    table = _forced_table(title, header, cells)
    # the station names fit beside the numbers (never folded); names too long for the
    # terminal are shortened with "~", the full names being in the CSV
    excess = _natural_width(header, cells) - (console.width - 1)
    longest = max((len(c[0]) for c in cells), default=0)
    if cells and excess > 0:
        room = max(8, longest - excess)
        for c in cells:
            c[0] = c[0] if len(c[0]) <= room else c[0][:room - 1] + "~"
        table = _forced_table(title, header, cells)
    console.print(table if cells else FORCED_ZERO)
    if cells and excess > 0:
        console.print(f"(station names shortened with ~; full names in {FORCED_CSV})")
    console.print(escape(f"Basis: {forced_basis_text(results)}"), highlight=False)
    for line in forced_worst_lines(results):
        console.print(escape(line), highlight=False)


def forced_figure_names(results: Results) -> tuple[str, ...]:
    """The forced response's figure names (file stems), or () without one.

    Parameters
    ----------
    results : Results
        The analysis.
    """
    return () if results.forced_response is None else tuple(FORCED_FIGURES)


def forced_figures(results: Results, *, names=None) -> dict[str, Figure]:
    """Draw the forced response's figures from the stored results, by file stem.

    Parameters
    ----------
    results : Results
        The analysis, with a forced response.
    names : iterable of str, optional
        Draw only these (from :data:`FORCED_FIGURES`); default all.
    """
    from .plotting.forced import forced_acceleration_chart, forced_envelope_chart

    makers = {"forced-acceleration": forced_acceleration_chart,
              "forced-envelopes": forced_envelope_chart}
    wanted = tuple(FORCED_FIGURES) if names is None else tuple(names)
    return {name: makers[name](results.forced_response) for name in wanted}
