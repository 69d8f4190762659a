"""The ``flexbooster`` command's entry point: ``python -m flexbooster`` and the console script.

Thin on purpose (issue 18): before its ``try`` it imports nothing but the standard library's
``signal`` and ``sys``, so that Ctrl-C or SIGTERM while the command's modules load (click,
rich, then numpy, scipy, pydantic: the first ~0.3-1 s of ``flexbooster run``) ends like an
interrupt later on -- one line ``flexbooster: error: interrupted`` and exit 130 -- instead of
a Python traceback.

It also decides how the process ends.  Once :func:`flexbooster.cli.main` has returned or
raised, every clean-up of the run has been done (the ``finally`` blocks: the staging folder
removed, the worker processes terminated and joined, no ``.part`` file); from then on SIGINT
and SIGTERM are ignored and the process exits with the status chosen, through the normal
interpreter exit (atexit handlers, flushed streams).  Without that, a signal that lands after
the outcome is decided -- in the last bytecodes of ``main`` or after the interpreter has
restored the default SIGINT action during its finalisation -- ends the process *by* the
signal (status -2 or -15 instead of 0 or 130), which ``os._exit(130)`` used to paper over for
the interrupted path only; and an interrupt that left a library's ``exec`` of a string (scipy's,
while it is imported) made the interpreter end by SIGINT too (:func:`_forget_interrupted_exec`).
The one window left is Python's own start-up, before this module runs (a few tens of
milliseconds).
"""

import signal
import sys

__all__ = ["main", "EXIT_INTERRUPTED", "INTERRUPTED_MESSAGE"]

#: Exit status of an interrupted command (128 + SIGINT, the shell's convention).
EXIT_INTERRUPTED = 130
#: The one line printed on standard error when the command is interrupted.
INTERRUPTED_MESSAGE = "flexbooster: error: interrupted"


def _terminate(signum: int, frame: object) -> None:
    raise KeyboardInterrupt  # SIGTERM while the modules load: like Ctrl-C


def _finishing() -> None:
    """The outcome is decided and the clean-up done: no signal may change the exit status.

    ``SIG_IGN`` (not a thread's signal mask) so that it holds for the whole process, whichever
    thread the kernel picks, and through the interpreter's finalisation.
    """
    for signum in (signal.SIGINT, signal.SIGTERM):
        signal.signal(signum, signal.SIG_IGN)


def _forget_interrupted_exec() -> None:
    """Clear CPython's note of an interrupt that left ``exec`` of a string.

    CPython marks a KeyboardInterrupt that propagates out of ``exec()`` or ``eval()`` of a
    *string* as unhandled, and under ``python -m`` kills the process with SIGINT at exit
    (status -2) even when the interrupt was caught further up; the next ``exec`` of a string
    clears the mark (``run_eval_code_obj`` in CPython's pythonrun.c; measured with 3.11).
    scipy's array-API layer runs ``exec`` on a string (a star import of numpy) while it is
    imported, so Ctrl-C or SIGTERM in that part of the start ended with -2 instead of 130 (5
    of 39 runs with SIGTERM sent 0.3-5 s after the start; tests/test_cli.py).  Run once the
    outcome is decided and the signals ignored.
    """
    exec("")  # noqa: S102 - the empty string: the point is the interpreter's bookkeeping


def main(argv: list[str] | None = None) -> None:
    """Run the ``flexbooster`` command and exit: 0, 1, 2 or 130 (see ``flexbooster --help``).

    Parameters
    ----------
    argv : list of str, optional
        Command-line arguments (default: ``sys.argv[1:]``).

    Returns
    -------
    None
        It does not return: it raises ``SystemExit`` with the command's exit status, with
        SIGINT and SIGTERM ignored from the moment the status is known (the process owns its
        signals: call it as a program's entry point, not from a library).
    """
    code: int | str | None = EXIT_INTERRUPTED
    try:
        try:
            signal.signal(signal.SIGTERM, _terminate)
            from .cli import main as cli_main  # click, rich, ... : Ctrl-C here is handled too

            cli_main(argv)  # always raises SystemExit (its own handlers print the errors)
            code = 0
        except SystemExit as exc:
            code = exc.code
        finally:
            _finishing()  # first, before anything else can be interrupted
    except KeyboardInterrupt:  # during the imports, or between cli.main's handlers and here
        _finishing()
        code = EXIT_INTERRUPTED
        print(INTERRUPTED_MESSAGE, file=sys.stderr)
    _forget_interrupted_exec()
    sys.exit(code)


if __name__ == "__main__":
    main()
