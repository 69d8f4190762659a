"""The baseline commit of a benchmark, checked out side by side (shared by the bench scripts).

A benchmark times the current code against a baseline commit in the same run: the commit is
checked out with ``git worktree`` into a folder of its own, run with the same Python and
packages (``PYTHONPATH=<folder>/src``), and removed afterwards.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path

__all__ = ["ROOT", "baseline_checkout", "alternate", "child_json", "best"]

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


def alternate(rev: str, rounds: int, run: Callable[[Path], dict]) -> dict[str, list[dict]]:
    """``run(src)`` on this tree's ``src`` and on commit ``rev``'s, alternating, ``rounds`` times.

    Parameters
    ----------
    rev : str
        The baseline commit.
    rounds : int
        Rounds (each runs both trees once).
    run : callable
        Takes the ``src`` folder, returns the measurements of one run.

    Returns
    -------
    dict
        ``{"new": [...], "old": [...]}``: the runs of this tree and of the baseline, in order.
    """
    out: dict[str, list[dict]] = {"new": [], "old": []}
    with tempfile.TemporaryDirectory() as tmp, baseline_checkout(rev, Path(tmp) / "base") as base:
        for _ in range(rounds):
            for tree, src in (("new", ROOT / "src"), ("old", base / "src")):
                out[tree].append(run(src))
    return out


def child_json(src: Path, code: str, *args: str) -> dict:
    """Run ``python -c code args`` with ``PYTHONPATH=src`` and one BLAS thread; the JSON object
    on the last line of its output (SystemExit with its last error line if it fails).

    Parameters
    ----------
    src : pathlib.Path
        The ``src`` folder of the tree to run.
    code : str
        The child's program; it prints one JSON object last.
    *args : str
        Its arguments.
    """
    env = dict(os.environ, PYTHONPATH=str(src), OPENBLAS_NUM_THREADS="1")
    done = subprocess.run([sys.executable, "-c", code, *args], env=env, capture_output=True,
                          text=True)
    if done.returncode:
        raise SystemExit(f"{src}: {done.stderr.strip().splitlines()[-1]}")
    return json.loads(done.stdout.strip().splitlines()[-1])


def best(runs: dict[str, list[dict]], key: str = "cpu") -> tuple[float, float]:
    """(baseline, this tree): the smallest ``key`` of each tree's runs from :func:`alternate`."""
    return min(r[key] for r in runs["old"]), min(r[key] for r in runs["new"])
