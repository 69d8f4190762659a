"""Benchmark: the vehicle-regions stage of the README's ``[vehicle]`` example against a baseline
commit, same run.

The example (:data:`VEHICLE_EXAMPLE`, the ``[vehicle]`` table of README.md at
:data:`BASELINE`: a 1.5 m cylinder of 6 m and a cone to 1.0 m, 16 mm walls, k = 0..20) with
the baseline's default case (F0 = 2.8 MN, gamma = 0.05, Omega 5..2000 rad/s, damping 0.01,
20 modes per k). ``analyze_vehicle_regions(case, boundaries=True)`` (the stage ``flexbooster
run`` runs, k = 1..20) is timed in a child process per tree, alternating (``--rounds``), CPU
seconds of the call alone (imports and case loading excluded). The baseline reads the memo
case with the ``[vehicle]`` table appended (its vehicle stage came after the memo's stages);
this tree reads the same table without ``[booster]`` (one geometry per case). Printed: best
CPU of each, the ratio baseline / now (goal >= 1: at least as fast) and the regions found.

Run from the repository root::

    .venv/bin/python benchmarks/bench_vehicle_stage.py [--rounds 3] [--baseline REV]
"""

from __future__ import annotations

import argparse
import os
import subprocess
from pathlib import Path

from baseline_checkout import ROOT, alternate, best, child_json
from bench_vehicle_regions import README_VEHICLE

#: The code before the pipeline became a plain sequence of stages.
BASELINE = "66f93aa"
#: The ``[vehicle]`` example of README.md at :data:`BASELINE` (the regions benchmark's).
VEHICLE_EXAMPLE = README_VEHICLE

CHILD = """
import json, sys, time, tomllib
from pathlib import Path
from flexbooster.analysis import analyze_vehicle_regions
from flexbooster.case import load_case
data = tomllib.loads(Path(sys.argv[1]).read_text())
if sys.argv[2] == "new":
    data.pop("booster")  # one geometry per case: the [vehicle] table alone
case = load_case(data)
start = time.process_time()
found = analyze_vehicle_regions(case, boundaries=True)
cpu = time.process_time() - start
def edge(r, name):  # the baseline's region type spells its edges omega_lo, omega_hi
    return round(getattr(r, name, getattr(r, name.lower(), 0.0)), 6)
print(json.dumps({"cpu": cpu, "regions": [[r.k, r.kind, edge(r, "Omega_lo"), edge(r, "Omega_hi")]
                                          for r in found.regions]}))
"""


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--baseline", default=BASELINE)
    opts = ap.parse_args()
    case_path = Path(os.environ.get("TMPDIR", "/tmp")) / f"bench-vehicle-stage-{os.getpid()}.toml"

    # the baseline's default (memo) case + the example, read by both trees
    text = subprocess.run(["git", "-C", str(ROOT), "show",
                           f"{opts.baseline}:src/flexbooster/data/default_case.toml"],
                          capture_output=True, text=True, check=True).stdout
    case_path.write_text(text + VEHICLE_EXAMPLE)

    def run(src: Path) -> dict:
        return child_json(src, CHILD, str(case_path), "new" if src == ROOT / "src" else "old")

    try:
        runs = alternate(opts.baseline, opts.rounds, run)
    finally:
        case_path.unlink(missing_ok=True)
    old, new = best(runs)
    print(f"vehicle-regions stage of the README [vehicle] example, best CPU of {opts.rounds}, "
          f"load average {os.getloadavg()[0]:.1f}: baseline {opts.baseline} {old:.2f} s, now "
          f"{new:.2f} s; baseline / now {old / new:.2f} (goal >= 1: "
          f"{'met' if old >= new else 'NOT met'})")
    for tree in ("old", "new"):
        print(f"  {tree} regions (k, kind, Omega_lo, Omega_hi): {runs[tree][0]['regions']}")


if __name__ == "__main__":
    main()
