"""The readable summary printed by ``flexbooster run`` (rich tables).

A thin layer: it formats a :class:`~flexbooster.analysis.Results` and computes nothing.
"""

from __future__ import annotations

import numpy as np
from rich.console import Console
from rich.table import Table

from .analysis import Results

__all__ = ["print_summary"]


def _table(title: str, rows: list[tuple[str, str, str]]) -> Table:
    table = Table(title=title, title_justify="left", show_header=True, header_style="bold")
    table.add_column("quantity")
    table.add_column("value", justify="right")
    table.add_column("unit")
    for row in rows:
        table.add_row(*row)
    return table


def _g(x: float) -> str:
    return f"{x:.6g}"


def print_summary(results: Results, console: Console | None = None) -> None:
    """Print the summary tables of an analysis.

    Parameters
    ----------
    results : Results
        The analysis to summarise.
    console : rich.console.Console, optional
        Where to print; a new console on standard output by default.
    """
    console = console or Console()
    case, m = results.case, results.mass
    b, t = case.booster, case.thrust
    console.print(f"[bold]flexbooster[/bold] - {case.name}")
    console.print(
        _table(
            "Input (SI)",
            [
                (
                    "cylinder 1 radius R1 / half-length L1",
                    f"{_g(b.cylinder1.radius)} / {_g(b.cylinder1.half_length)}",
                    "m",
                ),
                (
                    "cylinder 2 radius R2 / half-length L2",
                    f"{_g(b.cylinder2.radius)} / {_g(b.cylinder2.half_length)}",
                    "m",
                ),
                ("thickness h", _g(b.thickness), "m"),
                ("E / nu / rho", f"{_g(b.E)} / {_g(b.nu)} / {_g(b.rho)}", "Pa / - / kg/m^3"),
                (
                    "thrust F0 (T0 per unit circumference)",
                    f"{_g(case.F0)} ({_g(case.T0)})",
                    "N (N/m)",
                ),
                ("gamma / gimbal gain K", f"{_g(t.gamma)} / {_g(t.K)}", "-"),
                (
                    "Omega range (points)",
                    f"{_g(t.omega_min)} .. {_g(t.omega_max)} ({t.n_omega})",
                    "rad/s",
                ),
            ],
        )
    )
    console.print(
        _table(
            "Mass properties (memo 2.2, Fig. 1; I_cm per erratum E1)",
            [
                ("half-length L", _g(m.L), "m"),
                ("masses m1 / m2 / total", f"{_g(m.m1)} / {_g(m.m2)} / {_g(m.mass)}", "kg"),
                ("CM from aft edge x_cm (in cylinder)", f"{_g(m.x_cm)} ({m.cm_cylinder})", "m"),
                ("d1 / d2 / d3 / d4", f"{_g(m.d1)} / {_g(m.d2)} / {_g(m.d3)} / {_g(m.d4)}", "m"),
                ("coordinates a / c / b", f"{_g(m.a)} / {_g(m.c)} / {_g(m.b)}", "-"),
                ("pitch inertia I_cm", _g(m.I_cm), "kg m^2"),
            ],
        )
    )
    g = results.groups
    console.print(
        _table(
            "Frequencies and dimensionless groups (memo 3.0, 4.2)",
            [
                (
                    "first bending frequency omega_1 (4.2-8b)",
                    f"{_g(results.omega_1)} ({_g(results.omega_1 / (2 * np.pi))} Hz)",
                    "rad/s",
                ),
                (
                    "rigid-body pitch frequency omega_psi",
                    f"{_g(results.omega_psi)} ({_g(results.omega_psi / (2 * np.pi))} Hz)",
                    "rad/s",
                ),
                ("mu = rho L^2 omega_1^2 / E", _g(g.mu), "-"),
                ("lambda_1 = L/R1, lambda_2 = L/R2", f"{_g(g.lambda1)}, {_g(g.lambda2)}", "-"),
                ("sigma = h/L", _g(g.sigma), "-"),
                ("T0_bar = T0 / (rho h L^2 omega_1^2)", _g(g.T0_bar), "-"),
                (
                    "Mathieu a over the Omega grid",
                    f"{_g(results.a.min())} .. {_g(results.a.max())}",
                    "-",
                ),
                (
                    "Mathieu q over the Omega grid",
                    f"{_g(results.q.min())} .. {_g(results.q.max())}",
                    "-",
                ),
            ],
        )
    )
    if results.warnings:
        console.print(f"[bold yellow]Warnings ({len(results.warnings)}):[/bold yellow]")
        for w in results.warnings:
            console.print(f"  [yellow]warning[/yellow] [{w.code}] {w.field}: {w.message}")
    else:
        console.print("No warnings.")
