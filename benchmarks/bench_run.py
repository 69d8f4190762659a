"""End-to-end speed of ``flexbooster run`` against the code before the redesign (issue 11).

The baseline is commit ``BASELINE`` (the last commit before the redesign), checked out side by
side with ``git worktree`` into a temporary folder and run with the same Python and packages
in the same session, alternating with the current code; each command is timed best of
``REPEATS`` (wall clock, subprocess), as a user runs it (OPENBLAS_NUM_THREADS unset: the
library limits the BLAS threads itself since the redesign) and as ``make run`` does
(OPENBLAS_NUM_THREADS=1).  The current code is timed with its default worker processes
(``--jobs``: the usable CPUs) and with ``--jobs 1`` (everything in one process, as the
baseline); CPU time is the sum over the process and its workers.  It also checks that both
write the same numbers (``compare_results.py``, 1e-12 relative).

Run from the repository root (needs git and the project's venv)::

    .venv/bin/python benchmarks/bench_run.py [--baseline REV]

``--baseline REV`` times another commit instead of ``BASELINE`` (e.g. main before a change).
"""

from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from baseline_checkout import baseline_checkout

__all__ = ["BASELINE", "main"]

#: The last commit before the redesign of issue 11.
BASELINE = "045ce06"
REPEATS = 2
ROOT = Path(__file__).resolve().parents[1]


def _time(src: Path, args: list[str], out: Path, threads: str | None) -> tuple[float, float]:
    env = dict(os.environ, PYTHONPATH=str(src))
    env.pop("OPENBLAS_NUM_THREADS", None)
    # byte-compiled modules cached as an installed package has them (some shells export
    # PYTHONDONTWRITEBYTECODE=1, which makes every run compile every module from source);
    # the first of the repeats writes the cache
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    if threads is not None:
        env["OPENBLAS_NUM_THREADS"] = threads
    cmd = [sys.executable, "-c", "from flexbooster.cli import main; main()", "run", *args,
           "-q", "-o", str(out)]
    best, cpu = float("inf"), float("inf")
    for _ in range(REPEATS):
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        start = time.perf_counter()
        subprocess.run(cmd, env=env, check=True, cwd=out.parent)
        best = min(best, time.perf_counter() - start)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = min(cpu, after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime)
    return best, cpu


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--baseline", default=BASELINE, help="commit to compare with")
    baseline = ap.parse_args().baseline
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        with baseline_checkout(baseline, tmp / "baseline") as base:
            rows = []
            for threads in (None, "1"):
                for label, args in (("run", []), ("run --no-figures", ["--no-figures"])):
                    old = _time(base / "src", args, tmp / "old", threads)
                    new = _time(ROOT / "src", args, tmp / "new", threads)
                    one = _time(ROOT / "src", [*args, "--jobs", "1"], tmp / "one", threads)
                    env = "unset" if threads is None else threads
                    rows.append((f"{label}, OPENBLAS_NUM_THREADS {env}", old, new))
                    rows.append((f"{label} --jobs 1, OPENBLAS_NUM_THREADS {env}", old, one))
            same = subprocess.run([sys.executable, str(ROOT / "benchmarks/compare_results.py"),
                                   str(tmp / "old/results.json"), str(tmp / "new/results.json")],
                                  capture_output=True, text=True)
    print(f"flexbooster run, default case, best of {REPEATS}, baseline {baseline}: "
          f"wall s (CPU s), load average {os.getloadavg()[0]:.2f}")
    for label, (old, old_cpu), (new, new_cpu) in rows:
        print(f"  {label:42s} baseline {old:6.2f} ({old_cpu:5.2f})   now {new:6.2f} "
              f"({new_cpu:5.2f})   speed-up {old / new:4.1f}x wall, {old_cpu / new_cpu:4.1f}x CPU")
    print(same.stdout.strip())


if __name__ == "__main__":
    main()
