"""End-to-end speed of ``flexbooster run`` against the code before the redesign (issue 11).

The baseline is commit ``BASELINE`` (the last commit before the redesign), checked out side by
side with ``git worktree`` into a temporary folder and run with the same Python and packages
in the same session, alternating with the current code (``REPEATS`` rounds, each running
every code once, so that a slow spell of the machine falls on all alike; best and median of
the wall clock, subprocess, the summary printed to a pipe), as a user runs it
(OPENBLAS_NUM_THREADS unset: the library limits the BLAS threads itself since the redesign)
and as ``make run`` does (OPENBLAS_NUM_THREADS=1); the speed-up is given as best over best,
median over median and the median of each round's ratio.  The current code is timed with its
default worker processes (``--jobs``: the usable CPUs) and with ``--jobs 1`` (everything in
one process, as the baseline); CPU time is the sum over the process and its workers.  It also
checks that both write the same numbers (``compare_results.py``, 1e-12 relative).

Run from the repository root (needs git and the project's venv)::

    .venv/bin/python benchmarks/bench_run.py [--baseline REV] [--repeats N]

``--baseline REV`` times another commit instead of ``BASELINE`` (e.g. main before a change).
"""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from baseline_checkout import baseline_checkout

__all__ = ["BASELINE", "main"]

#: The last commit before the redesign of issue 11.
BASELINE = "045ce06"
REPEATS = 3
ROOT = Path(__file__).resolve().parents[1]


def _run_once(src: Path, args: list[str], out: Path, threads: str | None) -> tuple[float, float]:
    """Wall and CPU seconds (the process and its workers) of one ``flexbooster run``."""
    env = dict(os.environ, PYTHONPATH=str(src))
    env.pop("OPENBLAS_NUM_THREADS", None)
    # byte-compiled modules cached as an installed package has them (some shells export
    # PYTHONDONTWRITEBYTECODE=1, which makes every run compile every module from source);
    # the first of the repeats writes the cache
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    if threads is not None:
        env["OPENBLAS_NUM_THREADS"] = threads
    # the summary printed, as `make run` prints it (to a pipe here: no progress bar); the
    # measurements of sessions 1-7 used -q, which skips it in both codes
    cmd = [sys.executable, "-c", "from flexbooster.cli import main; main()", "run", *args,
           "-o", str(out)]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run(cmd, env=env, check=True, cwd=out.parent, stdout=subprocess.DEVNULL)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime


def _compare(codes: dict[str, tuple[Path, list[str]]], out: Path, threads: str | None,
             repeats: int) -> dict[str, list[tuple[float, float]]]:
    """Every code in turn, ``repeats`` rounds: a slow spell of the machine (other jobs, the
    host) then falls on all of them alike instead of on one block of repeats."""
    times: dict[str, list[tuple[float, float]]] = {name: [] for name in codes}
    for _ in range(repeats):
        for name, (src, args) in codes.items():
            times[name].append(_run_once(src, args, out / name, threads))
    return times


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--baseline", default=BASELINE, help="commit to compare with")
    ap.add_argument("--repeats", type=int, default=REPEATS,
                    help="rounds (each runs every code once); best and median reported")
    opts = ap.parse_args()
    baseline, repeats = opts.baseline, max(1, opts.repeats)
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        with baseline_checkout(baseline, tmp / "baseline") as base:
            rows = []
            for threads in (None, "1"):
                for label, args in (("run", []), ("run --no-figures", ["--no-figures"])):
                    t = _compare({"old": (base / "src", args), "new": (ROOT / "src", args),
                                  "one": (ROOT / "src", [*args, "--jobs", "1"])},
                                 tmp, threads, repeats)
                    env = "unset" if threads is None else threads
                    rows.append((f"{label}, OPENBLAS_NUM_THREADS {env}", t["old"], t["new"]))
                    rows.append((f"{label} --jobs 1, OPENBLAS_NUM_THREADS {env}", t["old"],
                                 t["one"]))
            same = subprocess.run([sys.executable, str(ROOT / "benchmarks/compare_results.py"),
                                   str(tmp / "old/results.json"), str(tmp / "new/results.json")],
                                  capture_output=True, text=True)
    print(f"flexbooster run, default case, {repeats} interleaved rounds, baseline {baseline}: "
          f"wall s best / median (CPU s best), load average {os.getloadavg()[0]:.2f}")
    for label, old, new in rows:
        (ow, oc), (nw, nc) = (min(x[0] for x in old), min(x[1] for x in old)), \
            (min(x[0] for x in new), min(x[1] for x in new))
        om, nm = statistics.median(x[0] for x in old), statistics.median(x[0] for x in new)
        # each round's own ratio (the two codes run back to back), then their median: a slow
        # spell of the machine that spans a round cancels
        paired = statistics.median(o[0] / n[0] for o, n in zip(old, new, strict=True))
        print(f"  {label:50s} baseline {ow:6.2f} / {om:6.2f} ({oc:5.2f})   now {nw:6.2f} / "
              f"{nm:6.2f} ({nc:5.2f})   speed-up {ow / nw:4.1f}x best, {om / nm:4.1f}x median, "
              f"{paired:4.1f}x per round, {oc / nc:4.1f}x CPU")
    print(same.stdout.strip())


if __name__ == "__main__":
    main()
