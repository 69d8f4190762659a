"""End-to-end speed of ``flexbooster run`` on the memo case (or ``--case``) against a baseline
commit.

The baseline (default: commit 66f93aa, the code with worker processes) is checked out
side by side with ``git worktree`` and run with the same Python and packages, alternating with
the current code (``--repeats`` rounds, each running every code once, so that a slow spell of
the machine falls on all alike), as a user runs it (OPENBLAS_NUM_THREADS unset, the summary
printed to a pipe).  Printed: wall and CPU seconds (best and median) of each code, the ratio
now / baseline (best over best, median over median, median of each round's ratio) against the
goal :data:`GOAL` (at most 1.5 times the baseline), and whether both wrote the same numbers
(``compare_results.py``, 1e-12 relative).

Run from the repository root (needs git and the project's venv)::

    .venv/bin/python benchmarks/bench_run.py [--baseline REV] [--repeats N] [--case PATH]
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

__all__ = ["BASELINE", "GOAL", "main"]

#: The code before the pipeline became a plain sequence of stages.
BASELINE = "66f93aa"
#: The largest ratio of the wall time now over the baseline's that meets the goal.
GOAL = 1.5
REPEATS = 3
ROOT = Path(__file__).resolve().parents[1]


def _run_once(src: Path, args: list[str], out: Path) -> tuple[float, float]:
    """Wall and CPU seconds (the process and its children) of one ``flexbooster run``."""
    env = dict(os.environ, PYTHONPATH=str(src))
    env.pop("OPENBLAS_NUM_THREADS", None)
    # byte-compiled modules cached as an installed package has them; the first of the
    # repeats writes the cache
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    # the summary printed, as `make run` prints it (to a pipe here: no progress bar)
    cmd = [sys.executable, "-c", "from flexbooster.cli import main; main()", "run", *args,
           "-o", str(out)]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run(cmd, env=env, check=True, cwd=out.parent, stdout=subprocess.DEVNULL)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--baseline", default=BASELINE, help="commit to compare with")
    ap.add_argument("--repeats", type=int, default=REPEATS,
                    help="rounds (each runs every code once); best and median reported")
    ap.add_argument("--case", type=Path, default=None,
                    help="a case file run by both codes (default: the memo case)")
    opts = ap.parse_args()
    case = [] if opts.case is None else [str(opts.case.resolve())]
    baseline, repeats = opts.baseline, max(1, opts.repeats)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        with baseline_checkout(baseline, tmp / "baseline") as base:
            for label, args in (("run", []), ("run --no-figures", ["--no-figures"])):
                times: dict[str, list[tuple[float, float]]] = {"old": [], "new": []}
                for _ in range(repeats):  # alternating: a slow spell falls on both codes
                    # the baseline's default case is the memo case; now it is `--memo`
                    for name, src, memo in (("old", base / "src", case),
                                            ("new", ROOT / "src", case or ["--memo"])):
                        times[name].append(_run_once(src, [*memo, *args], tmp / name))
                rows.append((label, times["old"], times["new"]))
                same = subprocess.run(
                    [sys.executable, str(ROOT / "benchmarks/compare_results.py"),
                     str(tmp / "old/results.json"), str(tmp / "new/results.json")],
                    capture_output=True, text=True)
                rows[-1] += (same.stdout.strip(),)
    what = "memo case" if opts.case is None else opts.case.name
    print(f"flexbooster run, {what}, {repeats} alternating rounds, baseline {baseline}: "
          f"wall s best / median (CPU s best), load average {os.getloadavg()[0]:.2f}")
    for label, old, new, same in rows:
        ow, nw = min(x[0] for x in old), min(x[0] for x in new)
        oc, nc = min(x[1] for x in old), min(x[1] for x in new)
        om, nm = statistics.median(x[0] for x in old), statistics.median(x[0] for x in new)
        paired = statistics.median(n[0] / o[0] for o, n in zip(old, new, strict=True))
        print(f"  {label:18s} baseline {ow:6.2f} / {om:6.2f} ({oc:5.2f})   now {nw:6.2f} / "
              f"{nm:6.2f} ({nc:5.2f})   now / baseline {nw / ow:4.2f} best, {nm / om:4.2f} "
              f"median, {paired:4.2f} per round (goal <= {GOAL}: "
              f"{'met' if paired <= GOAL else 'NOT met'})")
        print(f"    {same}")


if __name__ == "__main__":
    main()
