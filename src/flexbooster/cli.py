"""Command line: ``flexbooster run``, ``flexbooster init``.

Exit codes: 0 success; 1 an unexpected internal error; 2 invalid input (a one-line message
naming the field, the value and the rule, no traceback); 130 interrupted.
"""

from __future__ import annotations

import os
import sys
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


@click.group(context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, prog_name="flexbooster")
def cli() -> None:
    """Dynamic stability of a flexible two-cylinder booster under a gimbaled, pulsating thrust.

    \b
    Examples:
      flexbooster run                      # analyse the embedded default case
      flexbooster init my-booster.toml     # write the default case to edit
      flexbooster run my-booster.toml -o results/
    """


def _load(case_file: Path | None):
    from .case import default_case, load_case

    return default_case() if case_file is None else load_case(case_file)


_CASE_ARG = click.argument(
    "case_file", required=False, type=click.Path(dir_okay=False, path_type=Path)
)
_OUTPUT = click.option(
    "-o",
    "--output",
    "output",
    default="flexbooster-results",
    show_default=True,
    type=click.Path(file_okay=False, path_type=Path),
    help="Folder for the results.",
)


@cli.command()
@_CASE_ARG
@_OUTPUT
@click.option("--no-figures", is_flag=True, help="Do not draw the figures (faster).")
def run(case_file: Path | None, output: Path, no_figures: bool) -> None:
    """Analyse CASE_FILE (TOML; the embedded default case if omitted).

    Prints a summary and writes OUTPUT/results.json, the CSV tables and the figures (each
    written to a temporary name and renamed, so an interrupted run never leaves a half-written
    file).
    """
    from .analysis import analyze
    from .outputs import write_outputs
    from .summary import print_summary

    results = analyze(_load(case_file))
    print_summary(results, Console())
    for path in write_outputs(results, output, figures=not no_figures):
        click.echo(f"wrote {path}")


@cli.command()
@_CASE_ARG
@click.option("--omega-min", required=True, help='Lowest Omega, e.g. 10 or "2 Hz" (rad/s bare).')
@click.option("--omega-max", required=True, help="Highest Omega (rad/s if no unit).")
@_OUTPUT
def stability(case_file: Path | None, omega_min: str, omega_max: str, output: Path) -> None:
    """Unstable thrust frequencies (memo 7.3) of CASE_FILE for Omega in [OMEGA_MIN, OMEGA_MAX]."""
    from .analysis import analyze
    from .case import load_case
    from .io import write_csv_atomic
    from .summary import print_stability

    def number(text: str) -> float | str:
        try:
            return float(text)
        except ValueError:
            return text

    data = _load(case_file).model_dump(exclude_none=True)
    data["thrust"].update(omega_min=number(omega_min), omega_max=number(omega_max))
    results = analyze(load_case(data))
    print_stability(results, Console())
    path = write_csv_atomic(output / "unstable-frequencies.csv", results.stability.to_rows())
    click.echo(f"wrote {path}")


@cli.command()
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
    """
    from .io import write_csv_atomic, write_json_atomic
    from .outputs import save_figure
    from .responses import edge_conditions
    from .responses import simulate as run_simulation
    from .units import to_si

    case = _load(case_file)
    try:
        value = float(omega)
    except ValueError:
        value = omega
    Omega = to_si("--omega", value, "angular_frequency")
    try:
        res = run_simulation(case, Omega, tau_max, n_out=n_out, psi0=psi0)
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
    from .plotting.responses import deformed_booster, modal_amplitudes

    written += save_figure(modal_amplitudes(res), output / "modal-amplitudes")
    for i in range(len(res.snapshots.get("index", []))):
        written += save_figure(deformed_booster(res, instant=i), output / f"deformed-{i}")
    peak = res.max_displacement()
    click.echo("max displacement (m): " + ", ".join(f"{c} {v:.4g}" for c, v in peak.items()))
    for path in written:
        click.echo(f"wrote {path}")


@cli.command()
@click.argument(
    "path",
    required=False,
    default="flexbooster-case.toml",
    type=click.Path(dir_okay=False, path_type=Path),
)
@click.option("--force", is_flag=True, help="Overwrite an existing file.")
def init(path: Path, force: bool) -> None:
    """Write the embedded default case, with a comment on every field, to PATH."""
    from .case import default_case_text
    from .io import write_text_atomic

    if path.exists() and not force:
        raise CaseError("PATH", str(path), "file exists (use --force to overwrite)")
    write_text_atomic(path, default_case_text())
    click.echo(f"wrote {path}")


def main(argv: list[str] | None = None) -> None:
    """Entry point of the ``flexbooster`` command."""
    try:
        cli.main(args=argv, prog_name="flexbooster", standalone_mode=False)
    except CaseError as exc:
        _fail(str(exc), EXIT_INPUT)
    except click.exceptions.Abort:
        _fail("interrupted", EXIT_INTERRUPTED)
    except KeyboardInterrupt:
        _fail("interrupted", EXIT_INTERRUPTED)
    except click.ClickException as exc:
        exc.show()
        sys.exit(EXIT_INPUT if isinstance(exc, click.UsageError) else exc.exit_code)
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
    sys.exit(EXIT_OK)


if __name__ == "__main__":  # pragma: no cover
    main()
