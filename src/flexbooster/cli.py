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


@cli.command()
@click.argument("case_file", required=False, type=click.Path(dir_okay=False, path_type=Path))
@click.option(
    "-o",
    "--output",
    "output",
    default="flexbooster-results",
    show_default=True,
    type=click.Path(file_okay=False, path_type=Path),
    help="Folder for results.json.",
)
def run(case_file: Path | None, output: Path) -> None:
    """Analyse CASE_FILE (TOML; the embedded default case if omitted).

    Prints a summary and writes OUTPUT/results.json (written to a temporary name and renamed,
    so an interrupted run never leaves a half-written file).
    """
    from .analysis import analyze
    from .case import default_case, load_case
    from .io import write_json_atomic
    from .summary import print_summary

    case = default_case() if case_file is None else load_case(case_file)
    results = analyze(case)
    print_summary(results, Console())
    path = write_json_atomic(output / "results.json", results.to_dict())
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
