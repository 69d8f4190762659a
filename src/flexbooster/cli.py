"""Command line: ``flexbooster run``, ``stability``, ``simulate``, ``modes``, ``init``.

Exit codes: 0 success; 1 an unexpected internal error or a file that cannot be written;
2 invalid input (a one-line message naming the field, the value and the rule, no traceback);
130 interrupted.  ``run`` and ``stability`` show progress bars (rich, on standard error, only on
a terminal), ``--quiet`` silences everything but errors and ``--format json`` prints
``results.to_dict()`` as JSON on standard output.
"""

from __future__ import annotations

import math
import os
import signal
import sys
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path

import click
from rich.console import Console

from . import __version__
from .errors import CaseError

__all__ = ["main", "cli"]

EXIT_OK, EXIT_INTERNAL, EXIT_INPUT, EXIT_INTERRUPTED = 0, 1, 2, 130


def _fail(message: str, code: int) -> None:
    click.echo(f"flexbooster: error: {message}", err=True)
    sys.exit(code)


_EXIT_CODES = """\b
Exit codes:
  0    success
  1    internal error, or an output file that cannot be written
  2    invalid input: one line naming the field, the value and the rule
  130  interrupted (Ctrl-C)"""


@click.group(
    context_settings={"help_option_names": ["-h", "--help"], "max_content_width": 100},
    epilog=_EXIT_CODES,
)
@click.version_option(__version__, prog_name="flexbooster")
def cli() -> None:
    """Dynamic stability of a flexible two-cylinder booster under a gimbaled, pulsating thrust
    (Tech Memo 104): mass properties, beam and shell frequencies, rigid-body and beam stability
    and the thrust frequencies at which the structure goes unstable.

    \b
    Examples:
      flexbooster run                         # the default case -> flexbooster-results/
      flexbooster init my-booster.toml        # write the default case, commented, to edit
      flexbooster run my-booster.toml -o out  # summary; out/results.json, CSV, report.html
      flexbooster run -q --format json > r.json   # results as JSON on standard output
      flexbooster stability --omega-min 10 --omega-max "20 Hz"
      flexbooster simulate --omega 300 --tau-max 50
      flexbooster modes my-booster.toml --k-max 8  # vehicle modes (shell of revolution)
    """


def _load(case_file: Path | None):
    from .case import default_case, load_case

    return default_case() if case_file is None else load_case(case_file)


_CASE_ARG = click.argument(
    "case_file", required=False, type=click.Path(dir_okay=False, path_type=Path)
)
def _check_output(ctx: click.Context, param: click.Parameter, value: Path) -> Path:
    """The output folder, checked before any analysis: not a file, under no file, writable."""
    rule = None
    if value.exists() and not value.is_dir():
        rule = "is a file, not a folder"
    else:
        parent = value
        while not parent.exists() and parent != parent.parent:
            parent = parent.parent
        if not parent.is_dir():
            rule = f"cannot be created: {parent} is a file"
        elif not os.access(parent, os.W_OK | os.X_OK):
            rule = f"cannot be written: {parent} is not writable"
    if rule:
        raise CaseError("--output", str(value), rule)
    return value


_OUTPUT = click.option(
    "-o",
    "--output",
    "output",
    default="flexbooster-results",
    show_default=True,
    type=click.Path(path_type=Path),
    callback=_check_output,
    help="Folder for the results.",
)


_JOBS = click.option(
    "-j",
    "--jobs",
    type=click.IntRange(1, 64),
    default=None,
    help="Worker processes for the independent stages and the figures (default: the usable "
    "CPUs, at most 8; 1: none). The numbers are the same for any value.",
)
_QUIET = click.option(
    "-q", "--quiet", is_flag=True, help="Print nothing but errors (no summary, no progress)."
)
_FORMAT = click.option(
    "--format",
    "fmt",
    type=click.Choice(["table", "json"]),
    default="table",
    show_default=True,
    help="table: readable summary; json: results.to_dict() as JSON on standard output.",
)


@contextmanager
def _progress(stages: int, quiet: bool) -> Iterator[Callable[[str], None]]:
    """A rich progress bar on standard error (a terminal only), advanced once per stage."""
    from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn

    console = Console(stderr=True)
    bar = Progress(
        TextColumn("[bold]{task.description:<32}"),
        BarColumn(),
        TextColumn("{task.completed}/{task.total}"),
        TimeElapsedColumn(),
        console=console,
        transient=True,
        disable=quiet or not console.is_terminal,
    )
    with bar:
        task = bar.add_task("starting", total=stages)
        started = [False]

        def step(stage: str) -> None:
            if started[0]:
                bar.advance(task)
            started[0] = True
            bar.update(task, description=stage)

        yield step
        bar.update(task, completed=stages)


def _report(results, fmt: str, quiet: bool, printer: Callable) -> None:
    """The summary (table) or the JSON document (json) on standard output."""
    if fmt == "json":
        from .present.io import dumps_finite

        click.echo(dumps_finite(results.to_dict(), indent=2))
    elif not quiet:
        printer(results, Console())


def _wrote(paths, fmt: str, quiet: bool) -> None:
    if not quiet:
        for path in paths:
            click.echo(f"wrote {path}", err=fmt == "json")


@cli.command(epilog=_EXIT_CODES)
@_CASE_ARG
@_OUTPUT
@click.option("--no-figures", is_flag=True, help="Do not draw the figures (faster).")
@click.option("--no-vehicle", is_flag=True,
              help="Skip the vehicle's parametric instability regions (shell of revolution).")
@_JOBS
@_QUIET
@_FORMAT
def run(case_file: Path | None, output: Path, no_figures: bool, no_vehicle: bool,
        jobs: int | None, quiet: bool,
        fmt: str) -> None:
    """Analyse CASE_FILE (TOML; the embedded default case if omitted).

    Prints a summary and writes OUTPUT/results.json, the CSV tables, the figures and
    OUTPUT/report.html, one self-contained page to read in a browser or send (each file is
    written to a temporary name and renamed, so an interrupted run never leaves a half-written
    file).

    \b
    Examples:
      flexbooster run                        # default case -> flexbooster-results/report.html
      flexbooster run my.toml -o out/ --no-figures
      flexbooster run my.toml --no-vehicle   # without the vehicle's instability regions
      flexbooster run -q --format json | python -m json.tool | head
    """
    from ._parallel import default_workers
    from .analysis import STAGES, analyze
    from .present.outputs import OUTPUT_STAGES, write_outputs
    from .present.summary import print_summary

    case = _load(case_file)
    workers = default_workers() if jobs is None else jobs
    n_stages = len(STAGES) + (case.vehicle is not None) + (not no_vehicle) + len(OUTPUT_STAGES)
    with _progress(n_stages, quiet) as step:
        results = analyze(case, progress=step, figures=not no_figures, vehicle=not no_vehicle,
                          workers=workers)
        paths = write_outputs(results, output, figures=not no_figures, progress=step,
                              workers=workers)
    _report(results, fmt, quiet, print_summary)
    _wrote(paths, fmt, quiet)


@cli.command(epilog=_EXIT_CODES)
@_CASE_ARG
@click.option("--omega-min", required=True, help='Lowest Omega, e.g. 10 or "2 Hz" (rad/s bare).')
@click.option("--omega-max", required=True, help="Highest Omega (rad/s if no unit).")
@_OUTPUT
@_QUIET
@_FORMAT
def stability(
    case_file: Path | None, omega_min: str, omega_max: str, output: Path, quiet: bool, fmt: str
) -> None:
    """Unstable thrust frequencies (memo 7.3) of CASE_FILE for Omega in [OMEGA_MIN, OMEGA_MAX].

    Writes OUTPUT/unstable-frequencies.csv.

    \b
    Examples:
      flexbooster stability --omega-min 100 --omega-max "20 Hz"
      flexbooster stability my.toml --omega-min 5 --omega-max 500 -o out/
    """
    from .analysis import STAGES, analyze
    from .case import load_case
    from .present.io import write_csv_atomic
    from .present.summary import print_stability

    def number(text: str) -> float | str:
        try:
            return float(text)
        except ValueError:
            return text

    data = _load(case_file).model_dump(exclude_none=True)
    data["thrust"].update(omega_min=number(omega_min), omega_max=number(omega_max))
    case = load_case(data)
    with _progress(len(STAGES), quiet) as step:  # the memo table only: no vehicle regions
        results = analyze(case, progress=step, vehicle=False)
    _report(results, fmt, quiet, print_stability)
    path = write_csv_atomic(output / "unstable-frequencies.csv", results.stability.to_columns())
    _wrote([path], fmt, quiet)


@cli.command(epilog=_EXIT_CODES)
@_CASE_ARG
@click.option(
    "--omega", required=True, help='Thrust frequency Omega, e.g. 300 or "50 Hz" (rad/s bare).'
)
@click.option(
    "--tau-max", required=True, type=float, help="Last dimensionless time tau = omega_1 t."
)
@click.option("--n-out", default=401, show_default=True, type=int, help="Output times.")
@click.option(
    "--psi0", default=0.01, show_default=True, type=float, help="Initial pitch angle (rad)."
)
@_OUTPUT
def simulate(
    case_file: Path | None, omega: str, tau_max: float, n_out: int, psi0: float, output: Path
) -> None:
    """Modal time responses of CASE_FILE at one thrust frequency (memo 6.2).

    Writes OUTPUT/time-histories.csv, OUTPUT/simulation.json and figures of the modal
    amplitudes and of the deformed booster at a few instants.

    \b
    Example:
      flexbooster simulate --omega "50 Hz" --tau-max 100 -o sim/
    """
    from .analysis import simulate_case
    from .memo.responses import edge_conditions
    from .present.io import write_csv_atomic, write_json_atomic
    from .present.outputs import save_figure
    from .units import to_si

    case = _load(case_file)
    try:
        value = float(omega)
    except ValueError:
        value = omega
    Omega = to_si("--omega", value, "angular_frequency")
    try:
        res = simulate_case(case, Omega, tau_max=tau_max, n_out=n_out, psi0=psi0)
    except ValueError as exc:
        raise CaseError("simulate", f"--omega {omega} --tau-max {tau_max}", str(exc)) from None
    for warning in res.warnings:
        click.echo(f"warning: {warning}")
    data = res.to_dict()
    data["edge_conditions"] = edge_conditions(res)
    written = [
        write_csv_atomic(output / "time-histories.csv", res.to_rows()),
        write_json_atomic(output / "simulation.json", data),
    ]
    import matplotlib

    matplotlib.use("Agg")
    from .present.plotting.responses import deformed_booster, modal_amplitudes

    written += save_figure(modal_amplitudes(res), output / "modal-amplitudes")
    for i in range(len(res.snapshots.get("index", []))):
        written += save_figure(deformed_booster(res, instant=i), output / f"deformed-{i}")
    peak = res.max_displacement()
    click.echo("max displacement (m): " + ", ".join(f"{c} {v:.4g}" for c, v in peak.items()))
    for path in written:
        click.echo(f"wrote {path}")


def _f_max(text: str | None) -> float | None:
    """--f-max in Hz: a bare number is Hz, a string with units is converted ("1 kHz")."""
    from .units import to_si

    if text is None:
        return None
    try:
        value = float(text)
    except ValueError:
        value = to_si("--f-max", text, "angular_frequency") / (2.0 * math.pi)
    if not (math.isfinite(value) and value > 0.0):
        raise CaseError("--f-max", text, "must be a positive frequency (Hz if no unit)")
    return value


@cli.command(epilog=_EXIT_CODES)
@_CASE_ARG
@click.option("--k-max", type=int, default=None,
              help="Highest circumferential wave number k (0..200) [default: vehicle.k_max, 20].")
@click.option("--f-max", default=None,
              help='Keep the modes up to this frequency, e.g. 50 or "1 kHz" (Hz if no unit) '
                   "[default: up to 5x the lowest elastic frequency].")
@click.option("--no-prestress", is_flag=True,
              help="Unloaded frequencies (default: prestressed by the thrust F0, inertia relief).")
@click.option("-o", "--output", "output", default=None, type=click.Path(path_type=Path),
              callback=lambda ctx, param, value: None if value is None
              else _check_output(ctx, param, value),
              help="Also write OUTPUT/modes.json, OUTPUT/vehicle-modes.csv and the figures.")
@_QUIET
@click.option("--format", "fmt", type=click.Choice(["table", "json"]), default="table",
              show_default=True,
              help='table: one table per k; json: {"modes": [...], ...} on standard output.')
def modes(case_file: Path | None, k_max: int | None, f_max: str | None, no_prestress: bool,
          output: Path | None, quiet: bool, fmt: str) -> None:
    """Natural modes of the vehicle of CASE_FILE as one shell of revolution, k = 0..K_MAX.

    The vehicle is the case's [vehicle] table, or, without one, the memo's: the two cylinders
    of [booster] joined by the memo's rigid weightless disc, with shear-diaphragm ends.  The
    frequencies include the prestress of the steady thrust F0 (inertia relief) unless
    --no-prestress is given; the output says which.

    \b
    Examples:
      flexbooster modes                               # the default case's memo vehicle
      flexbooster modes my.toml --k-max 8 --f-max 40
      flexbooster modes my.toml --format json | python -m json.tool | head
      flexbooster modes my.toml -o out/               # modes.json, CSV, mode-shape figures
    """
    from .analysis import analyze_vehicle

    case = _load(case_file)
    if k_max is not None and not 0 <= k_max <= 200:
        raise CaseError("--k-max", k_max, "must be an integer in [0, 200]")
    survey = analyze_vehicle(case, k_max=k_max, f_max=_f_max(f_max),
                             prestress=not no_prestress, views=True)
    if fmt == "json":
        from .present.io import dumps_finite

        click.echo(dumps_finite(survey.to_dict(figures=False), indent=2))
    elif not quiet:
        from .present.vehicle import print_vehicle_modes

        print_vehicle_modes(survey, Console())
    if output is not None:
        from .present.vehicle import write_vehicle_files

        _wrote(write_vehicle_files(survey, output), fmt, quiet)


@cli.command(epilog=_EXIT_CODES)
@click.argument(
    "path",
    required=False,
    default="flexbooster-case.toml",
    type=click.Path(dir_okay=False, path_type=Path),
)
@click.option("--force", is_flag=True, help="Overwrite an existing file.")
def init(path: Path, force: bool) -> None:
    """Write the embedded default case, with a comment on every field, to PATH.

    \b
    Example:
      flexbooster init my-booster.toml && flexbooster run my-booster.toml
    """
    from .case import default_case_text
    from .present.io import write_text_atomic

    if path.exists() and not force:
        raise CaseError("PATH", str(path), "file exists (use --force to overwrite)")
    write_text_atomic(path, default_case_text())
    click.echo(f"wrote {path}")


def _register_sweep() -> None:
    from .sweep.command import sweep_command  # click and rich only; dask is loaded when it runs

    cli.add_command(sweep_command, name="sweep")


_register_sweep()


def main(argv: list[str] | None = None) -> None:
    """Entry point of the ``flexbooster`` command.

    Parameters
    ----------
    argv : list of str, optional
        Command-line arguments (default: ``sys.argv[1:]``).
    """
    previous = signal.getsignal(signal.SIGTERM)
    signal.signal(signal.SIGTERM, _terminate)  # SIGTERM cleans up like Ctrl-C
    try:
        cli.main(args=argv, prog_name="flexbooster", standalone_mode=False)
    except CaseError as exc:
        _fail(str(exc), EXIT_INPUT)
    except click.exceptions.Abort:
        _fail("interrupted", EXIT_INTERRUPTED)
    except KeyboardInterrupt:
        _fail("interrupted", EXIT_INTERRUPTED)
    except click.ClickException as exc:  # usage errors: one line, exit 2
        message = " ".join(exc.format_message().split())
        ctx = getattr(exc, "ctx", None)
        if isinstance(exc, click.UsageError) and ctx is not None:
            message += f" (see '{ctx.command_path} --help')"
        _fail(message, EXIT_INPUT if isinstance(exc, click.UsageError) else exc.exit_code)
    except OSError as exc:
        _fail(f"{exc.filename or ''}: {exc.strerror or exc}", EXIT_INTERNAL)
    except Exception as exc:  # pragma: no cover - a bug; keep the traceback reachable
        if os.environ.get("FLEXBOOSTER_DEBUG"):
            raise
        _fail(
            f"internal error: {type(exc).__name__}: {exc} "
            "(set FLEXBOOSTER_DEBUG=1 for a traceback)",
            EXIT_INTERNAL,
        )
    finally:
        signal.signal(signal.SIGTERM, previous)
    sys.exit(EXIT_OK)


def _terminate(signum: int, frame: object) -> None:
    raise KeyboardInterrupt


if __name__ == "__main__":  # pragma: no cover
    main()
