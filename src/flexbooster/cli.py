"""Command line: ``flexbooster run``, ``stability``, ``simulate``, ``modes``, ``init``.

Exit codes: 0 success; 1 an unexpected internal error; 2 invalid input (a one-line message
naming the field, the value and the rule, no traceback) or an output that cannot be written
(the path named);
130 interrupted.  ``run`` and ``stability`` show progress bars (rich, on standard error, only on
a terminal), ``--quiet`` silences everything but errors and ``--format json`` prints
``results.to_dict()`` as JSON on standard output.
"""

from __future__ import annotations

import functools
import math
import os
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
  1    internal error
  2    invalid input: one line naming the field, the value and the rule;
       or an output that cannot be written: one line naming the path
  130  interrupted (Ctrl-C)"""


class _Interrupted(Exception):
    """A KeyboardInterrupt (Ctrl-C, or SIGTERM) carried past click, which would print an
    empty line before its own Abort."""


class _Group(click.Group):
    def invoke(self, ctx: click.Context):
        try:
            return super().invoke(ctx)
        except KeyboardInterrupt:
            raise _Interrupted from None


@click.group(
    cls=_Group,
    context_settings={"help_option_names": ["-h", "--help"], "max_content_width": 100},
    epilog=_EXIT_CODES,
)
@click.version_option(__version__, prog_name="flexbooster")
def cli() -> None:
    """Whether a launch vehicle is safe under its oscillating thrust: the vehicle as one shell
    of revolution (tanks, masses, pressure, stiffeners), its parametric instability regions and
    forced response (g, N) through its flight, the severities and one overall verdict; the
    memo's two bare cylinders (Tech Memo 104: rigid pitch, beam action, shell resonances) one
    option away.

    \b
    Examples:
      flexbooster run                         # the default case -> flexbooster-results/
      flexbooster run --memo                  # the memo's two-cylinder case
      flexbooster init my-booster.toml        # write the default case, commented, to edit
      flexbooster run my-booster.toml -o out  # summary; out/results.json, CSV, report.html
      flexbooster run -q --format json > r.json   # results as JSON on standard output
      flexbooster stability --omega-min 10 --omega-max "20 Hz"
      flexbooster simulate --omega 300 --tau-max 50
      flexbooster modes my-booster.toml --k-max 8  # vehicle modes (shell of revolution)
    """


def _load(case_file: Path | None, memo: bool = False):
    """The case of CASE_FILE, else the embedded memo case with ``memo``, else the default."""
    from .case import default_case, load_case, memo_case

    if case_file is not None and memo:
        raise CaseError("--memo", str(case_file), "give a case file or --memo, not both")
    if case_file is not None:
        return load_case(case_file)
    return memo_case() if memo else default_case()


_CASE_ARG = click.argument(
    "case_file", required=False, type=click.Path(dir_okay=False, path_type=Path)
)
_MEMO = click.option("--memo", is_flag=True,
                     help="The embedded memo case (the memo's two bare cylinders) instead of "
                          "the default case.")


def _check_output(ctx: click.Context, param: click.Parameter, value: str) -> Path:
    """The output folder, checked before any analysis
    (:func:`flexbooster.present.outputs.check_output_folder`: not empty, not a file, under no
    file, a folder can be made there); each command then checks the names it writes."""
    from .present.outputs import check_output_folder

    return check_output_folder(value, (), field="--output")


def _check_names(output: Path, names: tuple[str, ...]) -> None:
    """Before the analysis: no file name of the command's output is taken by a folder."""
    from .present.outputs import check_output_folder

    check_output_folder(output, names, field="--output")


_OUTPUT = click.option(
    "-o",
    "--output",
    "output",
    default="flexbooster-results",
    show_default=True,
    type=click.Path(),
    callback=_check_output,
    help="Folder for the results.",
)


def _check_budget(ctx: click.Context, param: click.Parameter, value: str | None) -> float | None:
    """--max-seconds: a finite number of seconds > 0 (None: the case's max_seconds)."""
    if value is None:
        return None
    try:
        result = float(value)
    except ValueError:
        result = math.nan
    if not (math.isfinite(result) and result > 0.0):
        raise CaseError("--max-seconds", value, "must be a finite number of seconds > 0")
    return result


_BUDGET = click.option(
    "--max-seconds", "max_seconds", default=None, callback=_check_budget,
    help="Budget (s): a case whose estimated run time exceeds it is refused before it starts "
         "[default: the case's max_seconds, 300].")


def _with_budget(case, max_seconds: float | None):
    return case if max_seconds is None else case.model_copy(update={"max_seconds": max_seconds})


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


def _estimate_text(seconds: float, max_seconds: float) -> str:
    """The progress bar's estimate column: ``est. 7.5 s``, or over half the budget
    ``est. 200 s of the 300 s budget`` (in yellow; the run also has a ``cost-estimate``
    warning)."""
    if seconds > 0.5 * max_seconds:
        return f"[yellow]est. {seconds:.3g} s of the {max_seconds:g} s budget[/]"
    return f"est. {seconds:.3g} s"


@contextmanager
def _progress(stages: int, quiet: bool) -> Iterator[Callable[[str], None]]:
    """A rich progress bar on standard error (a terminal only), advanced once per stage.

    The step function it yields has an ``estimate(estimate, max_seconds)`` attribute, for
    :func:`flexbooster.analysis.analyze`'s ``on_estimate``: the bar then shows the run's
    estimated time beside the elapsed one."""
    from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn

    console = Console(stderr=True)
    bar = Progress(
        TextColumn("[bold]{task.description:<32}"),
        BarColumn(),
        TextColumn("{task.completed}/{task.total}"),
        TimeElapsedColumn(),
        TextColumn("{task.fields[estimate]}"),
        console=console,
        transient=True,
        disable=quiet or not console.is_terminal,
    )
    with bar:
        task = bar.add_task("starting", total=stages, estimate="")
        started = [False]

        def step(stage: str) -> None:
            if started[0]:
                bar.advance(task)
            started[0] = True
            bar.update(task, description=stage)

        def estimate(est, max_seconds: float) -> None:
            bar.update(task, estimate=_estimate_text(est.seconds, max_seconds))

        step.estimate = estimate  # type: ignore[attr-defined]
        yield step
        bar.update(task, completed=stages)


def _report(results, fmt: str, quiet: bool, printer: Callable) -> None:
    """The summary (table: ``printer(results, console)``) or the JSON document (json) on
    standard output."""
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
@click.option("--full", is_flag=True,
              help="Print every table (the report and results.json always hold them).")
@_MEMO
@_BUDGET
@click.option("--scheduler", default=None, metavar="ADDRESS|local",
              help="A case with [flight]: run its frozen times on Dask, on the scheduler at "
                   "ADDRESS (e.g. tcp://host:8786) or on a local cluster (one worker per "
                   "core); the results are the same as without [default: one process].")
@_QUIET
@_FORMAT
def run(case_file: Path | None, output: Path, no_figures: bool, no_vehicle: bool,
        full: bool, memo: bool, max_seconds: float | None, scheduler: str | None, quiet: bool,
        fmt: str) -> None:
    """Analyse CASE_FILE (TOML; if omitted, the embedded default case: a launch vehicle through
    its flight, or with --memo the memo's two-cylinder case).

    Prints a short summary (the overall verdict, the damping, one line per mechanism, the
    ranked bands, the warnings; every table with --full) and writes OUTPUT/results.json, the
    CSV tables, the figures and
    OUTPUT/report.html, one self-contained page to read in a browser or send (each file is
    written to a temporary name and renamed, so an interrupted run never leaves a half-written
    file).

    \b
    Examples:
      flexbooster run                        # default case -> flexbooster-results/report.html
      flexbooster run --memo -o memo/        # the memo's two-cylinder case
      flexbooster run my.toml -o out/ --no-figures
      flexbooster run my.toml --no-vehicle   # without the vehicle's instability regions
      flexbooster run flight.toml --scheduler local   # the flight's frozen times on Dask
      flexbooster run -q --format json | python -m json.tool | head
    """
    from .analysis import STAGES, analyze
    from .present.outputs import OUTPUT_STAGES, SET_NAMES, write_outputs
    from .present.summary import print_summary

    _check_names(output, SET_NAMES)
    case = _with_budget(_load(case_file, memo), max_seconds)
    if scheduler is not None:
        _check_scheduler(case, scheduler, no_vehicle=no_vehicle, figures=not no_figures)
    n_stages = (len(STAGES) + (case.vehicle is not None) + 2 * (not no_vehicle)
                + len(OUTPUT_STAGES) + (scheduler is not None))
    with _progress(n_stages, quiet) as step:
        options = dict(progress=step, figures=not no_figures,
                       on_estimate=getattr(step, "estimate", None))
        if scheduler is None:
            results = analyze(case, vehicle=not no_vehicle, **options)
        else:
            results = _run_on_dask(case, scheduler, **options)
        paths = write_outputs(results, output, figures=not no_figures, progress=step)
    _report(results, fmt, quiet, functools.partial(print_summary, full=full))
    report = [p for p in paths if Path(p).name == "report.html"]
    if full or fmt == "json" or not paths:
        _wrote(paths, fmt, quiet)
    elif not quiet:  # the short summary: one line for the files, then the report
        click.echo(f"wrote {len(paths)} files to {output}")
    if report and fmt != "json" and not quiet:
        click.echo(f"open {report[0]}")


def _check_scheduler(case, scheduler: str, *, no_vehicle: bool, figures: bool) -> None:
    """--scheduler: only for a case with [flight] and the vehicle's stages; the budget checked
    before a cluster starts."""
    from .sweep.flight import check_flight_budget

    if case.flight is None:
        raise CaseError("--scheduler", scheduler, "only for a case with [flight] (its frozen "
                        "times run on Dask); this case has none: run it without --scheduler")
    if no_vehicle:
        raise CaseError("--scheduler", scheduler, "not with --no-vehicle (without the "
                        "vehicle's stages there is no flight to run on Dask)")
    check_flight_budget(case, figures=figures)


def _run_on_dask(case, scheduler: str, **options):
    """The analysis with the flight's frozen times on Dask: a local cluster for ``local``, else
    the scheduler at that address (closed, its tasks cancelled, on any exit)."""
    from contextlib import ExitStack

    from .sweep.command import start_client
    from .sweep.flight import analyze_on_dask

    with ExitStack() as stack:
        client = start_client(stack, None if scheduler == "local" else scheduler, None)
        return analyze_on_dask(case, client, **options)


#: Files written by ``flexbooster stability`` (names of its own: never half of a ``run``).
STABILITY_FILES = ("stability-unstable-frequencies.csv", "stability.json")


def _case_with_range(case, omega_min: str | None, omega_max: str | None):
    """The case with --omega-min / --omega-max (when given) as its Omega range; an error
    names the option, not the case field."""
    from .case import load_case
    from .units import to_si

    def number(text: str) -> float | str:
        try:
            return float(text)
        except ValueError:
            return text

    given = {key: (opt, text) for key, opt, text in (("omega_min", "--omega-min", omega_min),
                                                      ("omega_max", "--omega-max", omega_max))
             if text is not None}
    if not given:
        return case
    data = case.model_dump(exclude_none=True)
    for key, (opt, text) in given.items():
        data["thrust"][key] = to_si(opt, number(text), "angular_frequency")
    try:
        return load_case(data)
    except CaseError as exc:
        key = exc.field.removeprefix("thrust.")
        if key in given:
            opt, text = given[key]
            other = "omega_max" if key == "omega_min" else "omega_min"
            rule = exc.rule.replace(f"thrust.{other}", given.get(other, (f"thrust.{other}",))[0])
            raise CaseError(opt, text, rule) from None
        raise


@cli.command(epilog=_EXIT_CODES)
@_CASE_ARG
@click.option("--omega-min", default=None,
              help='Lowest Omega, e.g. 10 or "2 Hz" (rad/s bare) [default: the case\'s '
                   "thrust.omega_min].")
@click.option("--omega-max", default=None,
              help="Highest Omega (rad/s if no unit) [default: the case's thrust.omega_max].")
@_OUTPUT
@_BUDGET
@_QUIET
@_FORMAT
def stability(
    case_file: Path | None, omega_min: str | None, omega_max: str | None, output: Path,
    max_seconds: float | None, quiet: bool, fmt: str
) -> None:
    """Unstable thrust frequencies (memo 7.3) of CASE_FILE (the memo's two cylinders; the
    embedded memo case if omitted) for Omega in [OMEGA_MIN, OMEGA_MAX] (the case's Omega range
    by default).

    Writes OUTPUT/stability-unstable-frequencies.csv and OUTPUT/stability.json: names of its
    own, so that it never replaces one half of an earlier `flexbooster run` in the same folder
    (whose results.json and report.html keep their numbers).

    \b
    Examples:
      flexbooster stability                      # the memo case's Omega range
      flexbooster stability --omega-min 100 --omega-max "20 Hz"
      flexbooster stability my.toml --omega-min 5 --omega-max 500 -o out/
    """
    from .analysis import STAGES, analyze
    from .model import check_memo_applies
    from .present.io import write_csv_atomic, write_json_atomic
    from .present.summary import print_stability

    _check_names(output, STABILITY_FILES)
    case = _with_budget(_case_with_range(_load(case_file, memo=case_file is None), omega_min,
                                         omega_max), max_seconds)
    check_memo_applies(case)  # the memo's table: [booster] only
    with _progress(len(STAGES), quiet) as step:
        results = analyze(case, progress=step, vehicle=False,  # the memo table only
                          on_estimate=getattr(step, "estimate", None))
    _report(results, fmt, quiet, lambda res, console: print_stability(
        res, console, roots_file=STABILITY_FILES[0], bands_file=None))
    if results.stability is None:  # a resource limit: the warning says which
        raise CaseError("truncation", "stability", "; ".join(w.message for w in results.warnings
                                                          if w.code == "stability-skipped"))
    paths = [write_csv_atomic(output / STABILITY_FILES[0], results.stability.to_columns()),
             write_json_atomic(output / STABILITY_FILES[1], results.to_dict())]
    _wrote(paths, fmt, quiet)


def _option_error(message: str, options: dict, given: str) -> CaseError:
    """The CaseError of a library ``ValueError("name = value: rule")``, on the option that
    gave ``name`` (as the user wrote it), else on the command's arguments ``given``."""
    name, sep, rest = message.partition(" = ")
    rule = rest.partition(": ")[2]
    if sep and rule and name in options:
        option, text = options[name]
        return CaseError(option, text, rule)
    return CaseError("simulate", given, message)


def _tau_max(case, t_max: str | None, tau_max: float | None) -> float:
    """tau_max from --t-max (a time: "2 s", "500 ms"; seconds if bare) or --tau-max."""
    from .model import model_from_case
    from .units import to_si

    if (t_max is None) == (tau_max is None):
        raise CaseError("--t-max/--tau-max", "both" if t_max else "neither",
                        'give exactly one: --t-max "2 s" (a time) or --tau-max 50 '
                        "(tau = omega_1 t)")
    if tau_max is not None:
        return tau_max
    try:
        seconds = float(t_max)
    except ValueError:
        seconds = to_si("--t-max", t_max, "time")
    if not (math.isfinite(seconds) and seconds > 0.0):
        raise CaseError("--t-max", t_max, "must be a positive time (s if no unit)")
    return seconds * model_from_case(case).omega_1  # tau = omega_1 t (memo 3.0)


#: Files written by ``flexbooster simulate`` (and deformed-<i>.svg/.png per snapshot).
SIMULATE_FILES = ("time-histories.csv", "simulation.json", "modal-amplitudes.svg",
                  "modal-amplitudes.png")


@cli.command(epilog=_EXIT_CODES)
@_CASE_ARG
@click.option(
    "--omega", required=True, help='Thrust frequency Omega, e.g. 300 or "50 Hz" (rad/s bare).'
)
@click.option("--t-max", default=None,
              help='Last time, e.g. "2 s" or "500 ms" (seconds if no unit).')
@click.option(
    "--tau-max", default=None, type=float,
    help="Or the last dimensionless time tau = omega_1 t (give one of --t-max, --tau-max)."
)
@click.option("--n-out", default=401, show_default=True, type=int, help="Output times.")
@click.option(
    "--psi0", default=0.01, show_default=True, type=float, help="Initial pitch angle (rad)."
)
@_OUTPUT
@_QUIET
@click.option("--format", "fmt", type=click.Choice(["table", "json"]), default="table",
              show_default=True,
              help="table: a verdict per mode; json: simulation.json on standard output.")
def simulate(
    case_file: Path | None, omega: str, t_max: str | None, tau_max: float | None, n_out: int,
    psi0: float, output: Path, quiet: bool, fmt: str
) -> None:
    """Modal time responses of CASE_FILE (the memo's two cylinders; the embedded memo case if
    omitted) at one thrust frequency (memo 6.2).

    Prints, per modal coordinate, whether it grows over the window; writes
    OUTPUT/time-histories.csv, OUTPUT/simulation.json and figures of the modal amplitudes
    and of the deformed booster at a few instants.

    \b
    Examples:
      flexbooster simulate --omega "50 Hz" --t-max "2 s" -o sim/
      flexbooster simulate --omega 300 --tau-max 100 -q
      flexbooster simulate --omega 300 --t-max 1 --format json | python -m json.tool | head
    """
    from .analysis import simulate_case
    from .memo.responses import edge_conditions
    from .present.figure_files import save_figure
    from .present.io import dumps_finite, write_csv_atomic, write_json_atomic
    from .units import to_si

    _check_names(output, SIMULATE_FILES)
    case = _load(case_file, memo=case_file is None)
    try:
        value = float(omega)
    except ValueError:
        value = omega
    Omega = to_si("--omega", value, "angular_frequency")
    tau = _tau_max(case, t_max, tau_max)
    try:
        res = simulate_case(case, Omega, tau_max=tau, n_out=n_out, psi0=psi0)
    except CaseError:
        raise
    except ValueError as exc:  # a library check "name = value: rule": name the option
        raise _option_error(str(exc), {
            "Omega": ("--omega", omega), "n_out": ("--n-out", n_out), "psi0": ("--psi0", psi0),
            "tau_max": ("--t-max", t_max) if t_max is not None else ("--tau-max", tau_max),
        }, f"--omega {omega} --tau-max {tau:.6g}") from None
    data = res.to_dict()
    data["edge_conditions"] = edge_conditions(res)
    written = [
        write_csv_atomic(output / "time-histories.csv", res.to_rows()),
        write_json_atomic(output / "simulation.json", data),
    ]
    import matplotlib

    matplotlib.use("Agg")
    from .present.plotting.responses import deformed_booster, modal_amplitudes, mode_verdicts

    written += save_figure(modal_amplitudes(res), output / "modal-amplitudes")
    for i in range(len(res.snapshots.get("index", []))):
        written += save_figure(deformed_booster(res, instant=i), output / f"deformed-{i}")
    if fmt == "json":
        click.echo(dumps_finite(data, indent=2))
    elif not quiet:
        for warning in res.warnings:
            click.echo(f"warning: {warning}")
        click.echo(f"Omega = {Omega:.6g} rad/s ({Omega / (2 * math.pi):.6g} Hz), "
                   f"t = 0..{res.t[-1]:.4g} s (tau = 0..{res.tau[-1]:.4g})")
        verdicts = sorted(mode_verdicts(res), key=lambda v: -v[2])
        largest = verdicts[0][2] if verdicts else 0.0
        relevant = [v for v in verdicts if v[2] > 1e-9 * largest]  # not round-off
        n_grow = sum(v[1] == "growing" for v in relevant)
        click.echo(f"{n_grow} of {len(relevant)} modal coordinates growing over the window\n"
                   f"({len(verdicts) - len(relevant)} below 1e-9 of the largest left out); "
                   f"the {min(10, len(relevant))} largest:")
        for name, verdict, peak in relevant[:10]:
            click.echo(f"  {name}: {verdict} (peak {peak:.3g} m)")
        below = [v for v in relevant[10:] if v[1] == "growing"]
        if below:  # one line after the list, never more rows in it
            click.echo(f"{len(below)} growing below these (the largest: {below[0][0]}, peak "
                       f"{below[0][2]:.3g} m); every coordinate in time-histories.csv")
        peak = res.max_displacement()
        click.echo("max displacement (m): " + ", ".join(f"{c} {v:.4g}" for c, v in peak.items()))
    _wrote(written, fmt, quiet)


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


#: Data files written by ``flexbooster modes -o`` (and the figures).
MODES_FILES = ("modes.json", "vehicle-modes.csv")


@cli.command(epilog=_EXIT_CODES)
@_CASE_ARG
@click.option("--k-max", type=int, default=None,
              help="Highest circumferential wave number k (0..200) [default: vehicle.k_max, 20].")
@click.option("--f-max", default=None,
              help='Keep the modes up to this frequency, e.g. 50 or "1 kHz" (Hz if no unit) '
                   "[default: up to 5x the lowest elastic frequency].")
@click.option("--no-prestress", is_flag=True,
              help="Unloaded frequencies (default: prestressed by the thrust F0, inertia relief).")
@click.option("-o", "--output", "output", default=None, type=click.Path(),
              callback=lambda ctx, param, value: None if value is None
              else _check_output(ctx, param, value),
              help="Also write OUTPUT/modes.json, OUTPUT/vehicle-modes.csv and the figures.")
@_MEMO
@_QUIET
@click.option("--format", "fmt", type=click.Choice(["table", "json"]), default="table",
              show_default=True,
              help='table: one table per k; json: {"modes": [...], ...} on standard output.')
def modes(case_file: Path | None, k_max: int | None, f_max: str | None, no_prestress: bool,
          output: Path | None, memo: bool, quiet: bool, fmt: str) -> None:
    """Natural modes of the vehicle of CASE_FILE as one shell of revolution, k = 0..K_MAX.

    The vehicle is the case's [vehicle] table, or, without one, the memo's: the two cylinders
    of [booster] joined by the memo's rigid weightless disc, with shear-diaphragm ends.  The
    frequencies include the prestress of the steady thrust F0 (inertia relief) unless
    --no-prestress is given; the output says which.

    \b
    Examples:
      flexbooster modes                               # the default case's vehicle
      flexbooster modes --memo                        # the memo case's two cylinders
      flexbooster modes my.toml --k-max 8 --f-max 40
      flexbooster modes my.toml --format json | python -m json.tool | head
      flexbooster modes my.toml -o out/               # modes.json, CSV, mode-shape figures
    """
    from .analysis import analyze_vehicle

    if output is not None:
        _check_names(output, MODES_FILES)
    case = _load(case_file, memo)
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
@_MEMO
def init(path: Path, force: bool, memo: bool) -> None:
    """Write the embedded default case (a launch vehicle with its tanks, through its flight),
    or with --memo the memo case (the memo's two bare cylinders), with a comment on every
    field, to PATH.

    \b
    Examples:
      flexbooster init my-vehicle.toml && flexbooster run my-vehicle.toml
      flexbooster init --memo my-booster.toml  # the memo's two-cylinder case
    """
    from .case import default_case_text, memo_case_text
    from .present.io import write_text_atomic

    if path.exists() and not force:
        raise CaseError("PATH", str(path), "file exists (use --force to overwrite)")
    write_text_atomic(path, memo_case_text() if memo else default_case_text())
    click.echo(f"wrote {path}")


def _register_sweep() -> None:
    from .sweep.command import sweep_command  # click and rich only; dask is loaded when it runs

    cli.add_command(sweep_command, name="sweep")


_register_sweep()


#: The BLAS libraries' thread-count variables that the command sets to one when the user has
#: set none of them: read once, when numpy loads its BLAS.
_BLAS_THREAD_VARIABLES = ("OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "OMP_NUM_THREADS")


def _one_blas_thread() -> None:
    """One BLAS thread for the command's process, as the analysis runs anyway
    (:func:`flexbooster._threads.blas_threads`), unless the user chose (any of
    :data:`_BLAS_THREAD_VARIABLES` set) or numpy is loaded already."""
    if "numpy" not in sys.modules and not any(os.environ.get(v) for v in _BLAS_THREAD_VARIABLES):
        for name in _BLAS_THREAD_VARIABLES:
            os.environ[name] = "1"


def main(argv: list[str] | None = None) -> None:
    """The ``flexbooster`` command, in-process (the console script calls it through
    :func:`flexbooster.__main__.main`, which also handles Ctrl-C while the modules load).

    Parameters
    ----------
    argv : list of str, optional
        Command-line arguments (default: ``sys.argv[1:]``).
    """
    _one_blas_thread()
    try:
        cli.main(args=argv, prog_name="flexbooster", standalone_mode=False)
    except CaseError as exc:
        _fail(str(exc), EXIT_INPUT)
    except (_Interrupted, click.exceptions.Abort, KeyboardInterrupt):
        _fail("interrupted", EXIT_INTERRUPTED)
    except click.ClickException as exc:  # usage errors: one line, exit 2
        message = " ".join(exc.format_message().split())
        ctx = getattr(exc, "ctx", None)
        if isinstance(exc, click.UsageError) and ctx is not None:
            message += f" (see '{ctx.command_path} --help')"
        _fail(message, EXIT_INPUT if isinstance(exc, click.UsageError) else exc.exit_code)
    except OSError as exc:  # an output that cannot be written (a full disk): the path named
        _fail(f"{exc.filename or 'output'}: {exc.strerror or exc}", EXIT_INPUT)
    except Exception as exc:  # pragma: no cover - a bug; keep the traceback reachable
        if os.environ.get("FLEXBOOSTER_DEBUG"):
            raise
        _fail(
            f"internal error: {type(exc).__name__}: {exc} "
            "(set FLEXBOOSTER_DEBUG=1 for a traceback)",
            EXIT_INTERNAL,
        )
    sys.exit(EXIT_OK)
