"""The ``flexbooster`` command's entry point: ``python -m flexbooster`` and the console script.

It imports only ``signal`` and ``sys`` before the command's modules, so that Ctrl-C or SIGTERM
while they load ends like an interrupt later on: one line and exit 130.
"""

import signal
import sys

__all__ = ["main"]


def _interrupt(signum: int, frame: object) -> None:
    raise KeyboardInterrupt  # SIGTERM cleans up like Ctrl-C


def main(argv: list[str] | None = None) -> None:
    """Run the ``flexbooster`` command and exit: 0, 1, 2 or 130 (see ``flexbooster --help``).

    Parameters
    ----------
    argv : list of str, optional
        Command-line arguments (default: ``sys.argv[1:]``).

    Returns
    -------
    None
        It raises ``SystemExit``; once the status is known SIGINT and SIGTERM are ignored, so
        that a late signal cannot change it (call it as a program's entry point only).
    """
    signal.signal(signal.SIGTERM, _interrupt)
    try:
        from .cli import main as cli_main

        cli_main(argv)  # raises SystemExit, after its clean-up
    except SystemExit as exc:
        code = exc.code
    except KeyboardInterrupt:  # while the modules load, or past cli.main's handlers
        print("flexbooster: error: interrupted", file=sys.stderr)
        code = 130
    for signum in (signal.SIGINT, signal.SIGTERM):
        signal.signal(signum, signal.SIG_IGN)
    if code == _INTERRUPTED and "distributed" in sys.modules:  # a sweep on a Dask cluster
        _exit_now(code)
    sys.exit(code)


#: The exit status of an interrupt (``flexbooster --help``).
_INTERRUPTED = 130


def _exit_now(code: int) -> None:
    """End an interrupted sweep at once: every ``finally`` of the command has run (its store
    closed, its workers killed, its cluster closed within 0.5 s); the atexit handlers run and
    the streams are flushed, then the process ends without the interpreter's finalization,
    which tears down every module the sweep loaded (dask, distributed, xarray, zarr: 1.3 s
    measured on a free core, up to 2 s on a loaded machine) and so held a Ctrl-C's exit past
    its 2 s.  Other commands exit normally (their executors' threads are joined first)."""
    import atexit
    import contextlib
    import os

    atexit._run_exitfuncs()  # noqa: SLF001 - what a normal exit runs, without finalization
    for stream in (sys.stdout, sys.stderr):
        with contextlib.suppress(Exception):  # a closed or broken stream: nothing to flush
            stream.flush()
    os._exit(code)


if __name__ == "__main__":
    main()
