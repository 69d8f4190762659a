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
    sys.exit(code)


if __name__ == "__main__":
    main()
