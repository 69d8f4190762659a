"""The readable summary printed by ``flexbooster run`` (rich tables).

A thin layer: it formats a :class:`~flexbooster.analysis.Results` and computes nothing.
"""

from __future__ import annotations

import textwrap

import numpy as np
from rich import box
from rich.console import Console
from rich.markup import escape
from rich.table import Table

from ..results import Results
from .rows import (
    BAND_COLUMNS,
    ROUND_OFF,
    band_rows,
    danger_rows,
    danger_scope,
    frequency_rows,
    headline_lines,
    input_rows,
    mass_rows,
    mass_title,
    not_applicable_text,
    range_text,
    ranking,
    severity_caption,
    short_mode_text,
    verdict_rows,
)

__all__ = ["print_summary", "print_stability", "print_first_screen", "TERMINAL_BANDS"]

#: Bands listed on the terminal's first screen (the report lists more; all in results.json).
TERMINAL_BANDS = 8


_OVERALL_STYLE = {"UNSTABLE": "bold red", "MARGINAL": "bold yellow", "STABLE": "bold green"}


def print_first_screen(results: Results, console: Console, *, full: bool = True) -> None:
    """The answer first: the overall verdict and the damping and duration it holds for, one
    verdict per mechanism, the ranked dangerous bands, the warnings.

    Parameters
    ----------
    results : Results
        The analysis.
    console : rich.console.Console
        Where to print.
    full : bool
        The full summary follows (the warnings' details at its end); False: the short one.
    """
    verdict = None if results.danger is None else results.danger.verdict
    if verdict is not None:
        style = _OVERALL_STYLE[verdict.overall]
        console.print(f"[{style}]{verdict.overall}[/{style}]: {escape(verdict.reason)}")
    console.print(f"[bold]flexbooster[/bold] - {escape(results.case.name)}")
    if verdict is not None:
        duration = ("none given (verdict from e-folding times)" if verdict.duration is None
                    else f"{verdict.duration:g} s")
        console.print(f"damping: {verdict.damping_text}; excitation duration: {duration}",
                      highlight=False)
    verdicts = Table(title="Verdicts", title_justify="left", box=box.SIMPLE_HEAD,
                     header_style="bold", pad_edge=False)
    verdicts.add_column("mechanism", ratio=1)
    verdicts.add_column("verdict", ratio=2)
    for words, verdict in verdict_rows(results):
        style = "red" if verdict.startswith("unstable") else (
            "green" if verdict.startswith(("stable", "bounded")) else (
                "yellow" if verdict.startswith("marginal") else ""))
        verdicts.add_row(escape(words), f"[{style}]{escape(verdict)}[/{style}]" if style
                         else escape(verdict))
    console.print(verdicts)
    rows = danger_rows(results, TERMINAL_BANDS)
    n_all = len(ranking(results))
    if rows:
        console.print(f"[bold]Most dangerous thrust frequencies[/bold] ({len(rows)} of "
                      f"{n_all}; all in results.json{escape(danger_scope(results))})")
        console.print(_band_block(rows, console.width), highlight=False, markup=False)
    elif n_all == 0 and results.danger is not None:
        console.print("No unstable band in any mechanism computed.")
    for line in headline_lines(results):
        console.print(escape(textwrap.fill(line, width=max(40, console.width - 1),
                                           subsequent_indent="    ")), highlight=False)
    if results.warnings:
        where = "details at the end" if full else "details in the report"
        console.print(f"[bold yellow]Warnings ({len(results.warnings)}; {where}):"
                      "[/bold yellow]")
        for w in results.warnings:
            console.print(f"  [yellow]warning[/yellow] {escape(f'[{w.code}] {w.field}')}")


def _table(title: str, rows: list[tuple[str, str, str]]) -> Table:
    table = Table(title=title, title_justify="left", show_header=True, header_style="bold")
    table.add_column("quantity")
    table.add_column("value", justify="right")
    table.add_column("unit")
    for row in rows:
        table.add_row(*row)
    return table


def _g(x: object) -> str:
    if isinstance(x, int):
        return str(x)
    if abs(x) < ROUND_OFF:  # round-off shown as 0, as in the report
        return "0"
    return f"{x:.6g}"


#: Narrowest column of words beside the ranked bands' numbers; narrower, the words go below.
BAND_TEXT_MIN = 48


def _band_block(rows: list[tuple[str, ...]], width: int) -> str:
    """Fixed-width text of the ranked bands: numbers in columns never cut, words wrapped."""
    heads = ("#", "Omega rad/s", "Omega Hz", "growth/resp.", "in range")
    widths = [max(len(r[i]) for r in [*rows, heads]) for i in range(5)]
    lead = sum(widths) + 2 * len(widths)
    # the words on their own line(s) where beside the numbers they would wrap into a narrow
    # column (under BAND_TEXT_MIN characters)
    below = width - lead < BAND_TEXT_MIN
    indent = widths[0] + 2 if below else lead
    text_width = max(20, width - indent - 1)

    def line(cells: tuple[str, ...], text: str) -> list[str]:
        nums = "  ".join(c.rjust(w) if i < 4 else c.ljust(w)
                         for i, (c, w) in enumerate(zip(cells, widths, strict=True)))
        wrapped = textwrap.wrap(text, text_width) or [""]
        if below:
            return [nums.rstrip()] + [" " * indent + t for t in wrapped]
        return [f"{nums}  {wrapped[0]}".rstrip()] + [" " * indent + t for t in wrapped[1:]]

    out = line(heads, "mode; mechanism")
    out.append("-" * min(width - 1, lead + 72))
    for r in rows:
        out += line(r[:5], f"{short_mode_text(r[5])}; {r[6]}")
    return "\n".join(out)


def print_summary(results: Results, console: Console | None = None, *,
                  full: bool = True) -> None:
    """Print the summary of an analysis: the first screen (:func:`print_first_screen`) and,
    with ``full``, every table.

    Parameters
    ----------
    results : Results
        The analysis to summarise.
    console : rich.console.Console, optional
        Where to print; a new console on standard output by default.
    full : bool
        Every table after the first screen (``flexbooster run --full``).
    """
    console = console or Console()
    print_first_screen(results, console, full=full)
    if not full:
        return
    for title, rows in (("Input (SI)", input_rows(results)),
                        (mass_title(results), mass_rows(results)),
                        ("Frequencies and dimensionless groups (memo 3.0, 4.2)",
                         frequency_rows(results))):
        console.print(_table(title, [(q, escape(v) if isinstance(v, str) else _g(v), u)
                                     for q, v, u in rows]))
    na = not_applicable_text(results)
    if na is not None:  # a [[vehicle.segments]] case: the memo's sections say why not
        for title in ("Free-free beam modes", "Shell natural frequencies", "Beam action",
                      "Unstable thrust frequencies (memo 7.3)"):
            console.print(f"{title}: {escape(na)}.")
        _print_pitch(results, console)
    else:
        _print_beam_and_pitch(results, console)
        _print_shell(results, console)
        _print_beam_action(results, console)
        print_stability(results, console)
    if results.vehicle is not None:  # a case with [vehicle] only
        from .vehicle import print_vehicle_summary

        print_vehicle_summary(results.vehicle, console)
    from .vehicle import print_vehicle_regions

    print_vehicle_regions(results, console)
    from .forced import print_forced_response

    print_forced_response(results, console)
    if results.flight is not None:  # a case with [flight] only
        from .flight import flight_lines

        console.print("[bold]Flight[/bold] (worst moment first)")
        for line in flight_lines(results.flight):
            console.print("  " + escape(line))
    if results.warnings:
        console.print(f"[bold yellow]Warnings ({len(results.warnings)}):[/bold yellow]")
        for w in results.warnings:
            console.print(f"  [yellow]warning[/yellow] "
                          f"{escape(f'[{w.code}] {w.field}: {w.message}')}")
    else:
        console.print("No warnings.")


def _print_beam_and_pitch(results: Results, console: Console) -> None:
    beam = results.beam
    n_show = min(5, beam.lambda_n.size)
    rows = [
        (
            f"mode {n + 1}: lambda_n / alpha_n",
            f"{beam.lambda_n[n]:.9g} / {beam.alpha_n[n]:.9g}",
            f"{_g(beam.omega_n[n])} rad/s" if beam.omega_n is not None else "-",
        )
        for n in range(n_show)
    ]
    console.print(
        _table(f"Free-free beam modes (appendix C; first {n_show} of {beam.lambda_n.size})", rows)
    )
    _print_pitch(results, console)


def _print_pitch(results: Results, console: Console) -> None:
    p = results.pitch
    rows = [
        ("verdict", p.verdict, ""),
        ("max growth rate of psi", _g(p.max_growth_rate) if p.bands else "-", "1/s"),
        ("beta (exact) over the grid", f"{_g(p.beta_real.min())} .. {_g(p.beta_real.max())}", "-"),
        (
            "|beta memo (4.2-9, E4) - exact|, max",
            _g(float(np.max(np.abs(p.beta_memo_real - p.beta_real)))),
            "-",
        ),
    ]
    for b in p.bands[:5]:
        rows += [(f"tongue {b.order}: Omega (exact edges)", range_text(b.Omega_lo, b.Omega_hi),
                  "rad/s"),
                 (f"tongue {b.order}: growth rate", _g(b.growth_rate_max), "1/s")]
    console.print(_table("Rigid-body pitch (memo 4.2, Floquet exponent)", rows))


def _print_shell(results: Results, console: Console) -> None:
    sh = results.shell
    rows = []
    for d in (1, 2):
        mask = sh.cylinder == d
        i = int(np.flatnonzero(mask)[np.argmin(sh.hz[mask])])
        rows.append((f"cylinder {d}: lowest frequency", _g(sh.hz[i]), "Hz"))
        rows.append((f"cylinder {d}: its (j, k, m, type)",
                     f"{sh.j[i]}, {sh.k[i]}, {sh.branch[i]}, {sh.mode_type[i]}", "-"))
        rows.append((f"cylinder {d}: its omega_bar", _g(sh.omega_bar[i]), "omega_1"))
        rows.append((f"cylinder {d}: frequencies computed", str(int(mask.sum())), ""))
    title = f"Shell natural frequencies (memo 5.4, 6.2; method {sh.method}; all in the CSV)"
    console.print(_table(title, rows))


def _print_beam_action(results: Results, console: Console) -> None:
    ba = results.beam_action
    if ba is None:
        console.print("Beam action: not computed.")
        return
    rows = [
        ("verdict", ba.verdict, ""),
        ("max growth rate", _g(ba.max_growth_rate) if ba.bands else "-", "1/s"),
        ("steady thrust P l^2 / EI (flutter at 109.69)", _g(ba.p), "-"),
        ("Hill vs monodromy exponents, max difference", _g(ba.hill_monodromy_difference), "-"),
        ("instability bands in the range", str(len(ba.bands)), ""),
    ]
    rows.append(("the bands", "see the ranked table at the top", ""))
    rows += [
        (
            f"alpha_{r + 1} Omega_bar at gamma -> 0 (loaded frequency)",
            _g(float(ba.frequencies.real[r])),
            "omega_1",
        )
        for r in range(ba.frequencies.size)
    ]
    console.print(_table("Beam action (memo 4.1, Floquet exponents alpha_r)", rows))


def print_stability(results: Results, console: Console, *,
                    roots_file: str = "unstable-frequencies.csv",
                    bands_file: str | None = "resonance-bands.csv") -> None:
    """Print the 10 most severe bands of unstable thrust frequencies.

    Parameters
    ----------
    results : Results
        The analysis.
    console : rich.console.Console
        Where to print.
    roots_file, bands_file : str, str or None
        The names of the files that hold every root and every band (None: not written), as
        the caption names them.
    """
    st = results.stability
    if st is None:
        console.print("Unstable thrust frequencies: not computed.")
        return
    rows = band_rows(results, 10)
    table = Table(
        title=(
            "Unstable thrust frequencies (memo 7.3), the 10 most severe bands: "
            f"{severity_caption(results)} All roots in {roots_file}"
            + (f", all bands in {bands_file}." if bands_file else ".")
        ),
        title_justify="left",
        header_style="bold",
        box=box.SIMPLE_HEAD,
        pad_edge=False,
    )
    words = ("cause", "mode (cyl, j, k, m, type)")
    keep = [n for n, col in enumerate(BAND_COLUMNS)  # the band's range only where it fits
            if console.width >= 120 or col != "band rad/s"]
    for n in keep:  # numbers never cut (no wrap); the words wrap
        col = BAND_COLUMNS[n]
        table.add_column(col, justify="left" if col in words else "right",
                         no_wrap=col not in words, overflow="fold")
    for row in rows:
        table.add_row(*(row[n] for n in keep))
    console.print(table)
