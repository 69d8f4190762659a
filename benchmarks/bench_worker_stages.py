"""CPU of the analysis stages that ``flexbooster run`` hands to worker processes, now vs a
baseline commit (branch wrknum).

In ``flexbooster run`` (default case, figures on) three stages run in worker processes:

1. the beam-action (Omega, gamma) chart, ``memo.charts.beam_action_chart(model)``;
2. the beam-action band search, ``memo.beam_action.pipeline_band_search(model)``;
3. the vehicle's instability regions, ``analysis._vehicle_regions_stage(case,
   boundaries=True)``,

with ``model = flexbooster.cost.derived_model(case)``.  Each stage is timed (CPU,
``time.process_time``) in a fresh interpreter per measurement: the stage runs once untimed
(lazy imports, first-call caches of the library), the caches that a worker would not have
filled yet are emptied (the stability certificates of ``floquet.bounds``, where the code has
them), then the stage runs timed; with ``--cold`` the first call is timed instead, as a
worker makes it (with the one-time costs: lazy imports inside the stage, caches filled, fresh
memory paged in).  The baseline is checked out side by side with
``git worktree`` into a temporary folder and run with the same Python and packages; the two
alternate, best and median of ``--repeat`` each.  OPENBLAS_NUM_THREADS=1 (as the workers
run: one BLAS thread each).

Run from the repository root::

    .venv/bin/python benchmarks/bench_worker_stages.py [--baseline main] [--repeat 5]
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

from baseline_checkout import baseline_checkout

__all__ = ["STAGES", "main"]

ROOT = Path(__file__).resolve().parents[1]

#: Stage name -> the Python expression that runs it (names from ``_PRELUDE``).
STAGES = {
    "beam-action chart": "charts.beam_action_chart(model)",
    "beam-action band search": "pipeline_band_search(model)",
    "vehicle regions": "analysis._vehicle_regions_stage(case, boundaries=True)",
}

_PRELUDE = """
import sys, time
import flexbooster.cost as cost
import flexbooster.floquet.bounds as bounds
from flexbooster import analysis
from flexbooster.case import default_case
from flexbooster.memo import charts
from flexbooster.memo.beam_action import pipeline_band_search
case = default_case()
model = cost.derived_model(case)
run = lambda: {stage}
if not {cold}:
    run()
    getattr(bounds, "_RECENT", {{}}).clear()
t = time.process_time()
run()
print(time.process_time() - t)
"""


def _cpu(src: Path, stage: str, cold: bool) -> float:
    env = dict(os.environ, PYTHONPATH=str(src), OPENBLAS_NUM_THREADS="1")
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    code = _PRELUDE.format(stage=STAGES[stage], cold=cold)
    out = subprocess.run([sys.executable, "-c", code],
                         env=env, check=True, capture_output=True, text=True)
    return float(out.stdout.split()[-1])


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--baseline", default="main", help="commit to compare with")
    ap.add_argument("--repeat", type=int, default=5, help="measurements per stage and code")
    ap.add_argument("--cold", action="store_true",
                    help="time the first call (as a worker makes it: with the one-time costs, "
                         "fresh memory) instead of the second")
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        with baseline_checkout(args.baseline, Path(tmp) / "baseline") as base:
            times: dict = {(s, c): [] for s in STAGES for c in ("old", "new")}
            for _ in range(args.repeat):  # alternating, so that the load hits both alike
                for stage in STAGES:
                    times[stage, "old"].append(_cpu(base / "src", stage, args.cold))
                    times[stage, "new"].append(_cpu(ROOT / "src", stage, args.cold))
    print(f"worker stages of flexbooster run (default case), CPU s of the "
          f"{'first' if args.cold else 'second'} call, best / median of {args.repeat}, "
          f"baseline {args.baseline}, load average {os.getloadavg()[0]:.2f}")
    total = {"old": 0.0, "new": 0.0}
    for stage in STAGES:
        old, new = times[stage, "old"], times[stage, "new"]
        total["old"] += min(old)
        total["new"] += min(new)
        print(f"  {stage:26s} baseline {min(old):6.3f} / {statistics.median(old):6.3f}   "
              f"now {min(new):6.3f} / {statistics.median(new):6.3f}   "
              f"{100.0 * (1.0 - min(new) / min(old)):5.1f} % less (best)")
    print(f"  {'all three':26s} baseline {total['old']:6.3f}            now {total['new']:6.3f}"
          f"            {100.0 * (1.0 - total['new'] / total['old']):5.1f} % less")


if __name__ == "__main__":
    main()
