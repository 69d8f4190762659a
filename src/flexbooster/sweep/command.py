"""``flexbooster sweep SWEEP.toml -o OUT [--scheduler ADDRESS] [--workers N] [--resume]``.

Every point is validated before anything runs (an invalid one stops the sweep with exit 2);
then the points run on a local Dask cluster (one worker process per core, the default), on an
existing cluster (``--scheduler tcp://host:8786`` or ``DASK_SCHEDULER_ADDRESS``), or in this
process (``--workers 0``).  Results go to OUT (``.nc``: netCDF; ``.zarr``: zarr, streamed per
batch), with OUT's stem ``.svg`` (the sweep figure) and ``.html`` (the sweep page) beside it.

Exit codes as for every flexbooster command: 0 success (also when some points failed: they are
recorded in the output's ``status``/``message``), 1 internal error, 2 invalid input or a file
that cannot be written (its path named), 130 interrupted (what was finished is stored:
``--resume``).
"""

from __future__ import annotations

import contextlib
import importlib.util
import logging
import os
import signal
import sys
import threading
from collections.abc import Iterator
from contextlib import ExitStack, contextmanager
from pathlib import Path

import click
from rich.console import Console
from rich.progress import (
    BarColumn,
    MofNCompleteColumn,
    Progress,
    ProgressColumn,
    TextColumn,
    TimeElapsedColumn,
    TimeRemainingColumn,
)
from rich.text import Text

from ..errors import CaseError

__all__ = ["sweep_command", "main", "local_cluster_config", "start_client"]

# the exit codes of flexbooster.cli (kept equal; see its module docstring)
EXIT_OK, EXIT_INTERNAL, EXIT_INPUT, EXIT_INTERRUPTED = 0, 1, 2, 130

_EPILOG = """\b
Sweep file (TOML):
  case = "base.toml"          # relative to the sweep file, or an inline [case] table
  mode = "product"            # or "zip"
  [axes]                      # any case field by its dotted name; units as in case files
  "thrust.gamma" = [0.0, 0.05, 0.1]
  "thrust.K" = {start = 0.2, stop = 1.0, num = 5}       # also scale = "log"
  "booster.thickness" = ["10 mm", "20 mm"]

\b
Examples:
  flexbooster sweep study.toml -o study.zarr             # local cluster, one worker per core
  flexbooster sweep study.toml -o study.zarr --resume    # after an interruption
  flexbooster sweep study.toml -o study.nc --scheduler tcp://10.0.0.5:8786

\b
Exit codes:
  0    success (failed points are recorded in the output, not fatal)
  1    internal error
  2    invalid input: one line naming the field (axis), the value, the rule and the point;
       or an output file that cannot be written: one line naming its path
  130  interrupted (Ctrl-C); the finished points are stored, rerun with --resume"""


class _RateColumn(ProgressColumn):
    """Points per second."""

    def render(self, task) -> Text:  # noqa: ANN001
        speed = task.finished_speed or task.speed
        return Text("" if speed is None else f"{speed:.3g} points/s")


def local_cluster_config() -> dict:
    """Dask settings (for ``dask.config.set``) of the local cluster, for less bookkeeping CPU: no
    statistical profiler on the workers, ``MALLOC_TRIM_THRESHOLD_`` left unset (glibc heap
    churn: +15 % CPU measured), the one-thread BLAS settings kept, and the event loops' periodic
    work spaced out (admin tick 200 ms, memory monitor 1 s, system monitor 2 s).
    """
    import dask

    environ = dict(dask.config.get("distributed.nanny.pre-spawn-environ", default={}) or {})
    environ.pop("MALLOC_TRIM_THRESHOLD_", None)
    return {
        "distributed.worker.profile.enabled": False,
        "distributed.nanny.pre-spawn-environ": environ,
        "distributed.admin.tick.interval": "200ms",
        "distributed.worker.memory.monitor-interval": "1s",
        "distributed.admin.system-monitor.interval": "2s",
    }


def start_client(stack: ExitStack, scheduler: str | None, workers: int | None):
    """A Dask client: to ``scheduler``, or to a new local cluster of ``workers`` processes
    (one thread each, SIGINT ignored in them: on Ctrl-C or an error this process kills them).
    CaseError on ``--scheduler`` when it cannot connect.

    Parameters
    ----------
    stack : contextlib.ExitStack
        Closes the client (and the local cluster) when it exits.
    scheduler : str or None
        Address of a running scheduler, e.g. ``tcp://host:8786``; None: a local cluster.
    workers : int or None
        Worker processes of the local cluster (None: one per core).
    """
    import dask
    from distributed import Client, LocalCluster

    if scheduler:
        try:
            return stack.enter_context(Client(scheduler, timeout="10s"))
        except (OSError, TimeoutError) as exc:
            raise CaseError("--scheduler", scheduler, f"cannot connect ({exc})") from None
    n = workers or os.cpu_count() or 1
    stack.enter_context(dask.config.set(local_cluster_config()))
    with _sigint_ignored():  # inherited by the worker processes spawned meanwhile
        cluster = LocalCluster(
            n_workers=n,
            threads_per_worker=1,
            processes=True,
            host="127.0.0.1",
            dashboard_address=":0",  # a free port: never collides with another cluster
        )
    stack.push(lambda kind, error, trace: _close_cluster(cluster, kind is not None))
    client = stack.enter_context(Client(cluster))
    stack.push(lambda kind, error, trace: _stop_workers(cluster, kind is not None))
    return client


def _stop_workers(cluster, failed: bool) -> None:  # noqa: ANN001
    """On an error or Ctrl-C, before the client and the cluster close: kill the worker
    processes (SIGKILL, no restart) and silence the shutdown's log lines; a graceful close
    would wait for the running tasks and print each cancelled one."""
    if not failed:
        return
    for name in ("distributed", "tornado"):  # tornado: a callback of a killed worker's comm
        logging.getLogger(name).setLevel(logging.CRITICAL)
    for nanny in list(cluster.workers.values()):
        nanny.auto_restart = False
        pid = getattr(getattr(nanny, "process", None), "pid", None)
        if pid:
            with contextlib.suppress(ProcessLookupError):
                os.kill(pid, signal.SIGKILL)


def _close_cluster(cluster, failed: bool) -> None:  # noqa: ANN001
    """Close the local cluster: gracefully after a finished sweep, within
    :data:`_STOP_SECONDS` after an error or Ctrl-C, also one during the graceful close (its
    workers killed first: the rest lives in this process and ends with it). A close cut short
    leaves the cluster open, and distributed's exit handler would close it again for up to
    10 s: it is told not to."""
    try:
        if not failed:
            cluster.close()
    except BaseException:  # Ctrl-C during the graceful close: as after an interrupt
        failed = True
        raise
    finally:
        if failed:
            _stop_workers(cluster, True)
            with contextlib.suppress(Exception):
                cluster.close(timeout=_STOP_SECONDS)
            cluster.shutdown_on_close = False  # distributed.deploy.spec.close_clusters skips it


#: Longest wait (s) for the local cluster's close after an error or Ctrl-C.
_STOP_SECONDS = 0.5


@contextmanager
def _sigint_ignored() -> Iterator[None]:
    """SIGINT ignored while the block runs (in the main thread; elsewhere a no-op). A process
    spawned meanwhile starts with SIGINT ignored, and Python then installs no KeyboardInterrupt
    handler in it: a Ctrl-C at the terminal, which signals the whole process group, reaches
    this process alone, which stops the workers itself (no worker tracebacks)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)




def _dashboard(client) -> str | None:  # noqa: ANN001
    services = client.scheduler_info().get("services", {})
    return client.dashboard_link if "dashboard" in services else None


@click.command(
    "sweep",
    epilog=_EPILOG,
    context_settings={"help_option_names": ["-h", "--help"], "max_content_width": 100},
)
@click.argument("sweep_file", type=click.Path(dir_okay=False, path_type=Path))
@click.option(
    "-o",
    "--output",
    required=True,
    type=click.Path(path_type=Path),
    help="Result file: OUT.nc (netCDF) or OUT.zarr (zarr, streamed as points finish).",
)
@click.option(
    "--scheduler",
    envvar="DASK_SCHEDULER_ADDRESS",
    default=None,
    help="Address of a running Dask scheduler, e.g. tcp://host:8786 "
    "(default: $DASK_SCHEDULER_ADDRESS, else a local cluster).",
)
@click.option(
    "--workers",
    type=click.IntRange(min=0),
    default=None,
    help="Worker processes of the local cluster (default: one per core; 0: no Dask, serial).",
)
@click.option("--resume", is_flag=True, help="Keep the points stored in OUT; compute the rest.")
@click.option(
    "--batch-size",
    type=click.IntRange(min=1),
    default=None,
    help="Points per Dask task (default: automatic, about 0.5 s of work per task).",
)
@click.option("--no-report", is_flag=True, help="Do not write the figure and the HTML page.")
@click.option("-q", "--quiet", is_flag=True, help="Print nothing but errors.")
def sweep_command(
    sweep_file: Path,
    output: Path,
    scheduler: str | None,
    workers: int | None,
    resume: bool,
    batch_size: int | None,
    no_report: bool,
    quiet: bool,
) -> None:
    """Run the design sweep SWEEP_FILE: one analysis per point, results to OUTPUT.

    Every point is validated first; an invalid value stops the sweep before anything runs.
    A point whose analysis fails is recorded (status "error" and its message) and the sweep
    goes on.  The output has one dimension per axis (SI values, units as attributes) and a
    variable per scalar result; OUTPUT's stem .svg and .html are the sweep figure and page.
    """
    from .run import run_sweep
    from .spec import load_sweep, point_cases

    if output.suffix.lower() not in (".nc", ".zarr"):
        raise CaseError("-o", str(output), "the output must end in .nc (netCDF) or .zarr (zarr)")
    if scheduler and workers is not None:
        raise CaseError("--workers", workers, "not with --scheduler (the cluster has its workers)")
    spec = load_sweep(sweep_file)
    cases = point_cases(spec)  # every point validated before anything runs
    err = Console(stderr=True)
    say = (lambda text: None) if quiet else (lambda text: err.print(text, highlight=False))
    say(f"sweep: {spec.n_points} points over {', '.join(a.name for a in spec.axes)}")
    with ExitStack() as stack:
        serial = workers == 0 and not scheduler
        client = None if serial else start_client(stack, scheduler, workers)
        if client is not None:
            n = len(client.scheduler_info().get("workers", {}))
            say(f"dask: {n} workers, scheduler {client.scheduler.address}")
            link = _dashboard(client)
            if link:
                has_bokeh = importlib.util.find_spec("bokeh") is not None
                note = "" if has_bokeh else " (needs bokeh: pip install bokeh)"
                say(f"dask dashboard: {link}{note}")
        bar = Progress(
            TextColumn("[bold]points"),
            BarColumn(),
            MofNCompleteColumn(),
            TextColumn("{task.fields[failed]} failed"),
            _RateColumn(),
            TimeElapsedColumn(),
            TextColumn("ETA"),
            TimeRemainingColumn(),
            console=err,
            disable=quiet or not err.is_terminal,
        )
        with bar:
            task = bar.add_task("points", total=spec.n_points, failed=0)
            first = [True]

            def progress(done: int, failed: int, total: int) -> None:
                if first[0]:  # what a resumed store already holds is not part of the rate
                    bar.reset(task, total=total, completed=done, failed=failed)
                    first[0] = False
                    if resume and done:
                        say(f"resume: {done} points stored, {total - done} to compute")
                else:
                    bar.update(task, completed=done, failed=failed)

            ds = run_sweep(
                spec,
                client=client,
                store=output,
                resume=resume,
                progress=progress,
                batch_size=batch_size,
                cases=cases,
            )
    status = ds["status"].values.reshape(-1).tolist()
    failed = status.count("error")
    say(
        f"{spec.n_points} points: {spec.n_points - failed} ok, {failed} failed "
        f"({ds.attrs['points_computed_this_run']} computed in this run)"
    )
    if failed:
        first = status.index("error")
        values = ", ".join(
            f"{axis.name} = {value!r}"
            for axis, value in zip(spec.axes, spec.point_values(first), strict=True)
        )
        message = ds["message"].values.reshape(-1)[first]
        say(f"first failure: point {first} ({values}): {message}")
    written = [output]
    if not no_report:
        written += _write_report(ds, output)
    for path in written:
        say(f"wrote {path}")


def _write_report(ds, output: Path) -> list[Path]:  # noqa: ANN001
    import matplotlib

    matplotlib.use("Agg")
    from ..present.io import write_text_atomic
    from .page import sweep_page
    from .plot import figure_svg, sweep_figure

    fig = sweep_figure(ds)
    svg = figure_svg(fig)
    paths = [
        write_text_atomic(output.with_suffix(".svg"), svg),
        write_text_atomic(output.with_suffix(".html"), sweep_page(ds, svg=svg)),
    ]
    return paths


def main(argv: list[str] | None = None) -> None:
    """Entry point of ``python -m flexbooster.sweep.command`` (the CLI's exit codes).

    Parameters
    ----------
    argv : list of str, optional
        Command-line arguments (default: ``sys.argv[1:]``).
    """
    try:
        sweep_command.main(args=argv, prog_name="flexbooster sweep", standalone_mode=False)
    except CaseError as exc:
        _fail(str(exc), EXIT_INPUT)
    except (click.exceptions.Abort, KeyboardInterrupt):
        _fail("interrupted (the finished points are stored; rerun with --resume)", EXIT_INTERRUPTED)
    except click.ClickException as exc:
        exc.show()
        sys.exit(EXIT_INPUT if isinstance(exc, click.UsageError) else exc.exit_code)
    except OSError as exc:  # an output that cannot be written: its path named
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


def _fail(message: str, code: int) -> None:
    click.echo(f"flexbooster: error: {message}", err=True)
    sys.exit(code)


if __name__ == "__main__":  # pragma: no cover
    main()
