"""The baseline commit of a benchmark, checked out side by side (shared by the bench scripts).

A benchmark times the current code against a baseline commit in the same run: the commit is
checked out with ``git worktree`` into a folder of its own, run with the same Python and
packages (``PYTHONPATH=<folder>/src``), and removed afterwards.
"""

from __future__ import annotations

import subprocess
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

__all__ = ["ROOT", "baseline_checkout"]

#: The repository root.
ROOT = Path(__file__).resolve().parents[1]


@contextmanager
def baseline_checkout(rev: str, folder: str | Path) -> Iterator[Path]:
    """Check out ``rev`` (detached) into ``folder`` for the ``with`` block, then remove it.

    Parameters
    ----------
    rev : str
        A commit, branch or tag of the repository.
    folder : str or pathlib.Path
        A folder that does not exist yet (e.g. inside a temporary directory).

    Yields
    ------
    pathlib.Path
        ``folder``, holding the baseline's working tree.
    """
    folder = Path(folder)
    subprocess.run(["git", "-C", str(ROOT), "worktree", "add", "-q", "--detach", str(folder),
                    rev], check=True)
    try:
        yield folder
    finally:
        subprocess.run(["git", "-C", str(ROOT), "worktree", "remove", "--force", str(folder)],
                       check=False)
