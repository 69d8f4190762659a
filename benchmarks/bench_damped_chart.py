"""Benchmark: the damped beam-action (Omega, gamma) chart of the default case (issue 12 leftovers).

The default case with ``[damping] beam_modal_ratio = 0.01``; the chart is
``flexbooster.memo.charts.beam_action_chart`` (boundaries from
``flexbooster.floquet.region_boundaries``, the tips from ``critical_amplitude``).  Times, in the
same run (best of ``--repeat``, wall and CPU of the child process):

1. this tree;
2. the baseline: the same call in commit ``BASELINE`` (the code before the tip search of
   ``floquet.regions._tips``: brentq over gamma of full region searches, the gamma_max search
   done twice), checked out side by side with ``git worktree`` into a temporary folder and run
   with the same Python (as ``benchmarks/bench_run.py`` does).

It prints the ratio and the tip gammas of both (the baseline's are biased upward by its search
tolerance; the new ones follow ``critical_amplitude`` at its default options).

Usage (repository root)::

    OPENBLAS_NUM_THREADS=1 python benchmarks/bench_damped_chart.py [--repeat 1]
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

__all__ = ["BASELINE", "main"]

#: main at the start of this work (before the new tip search).
BASELINE = "46541ca"
ROOT = Path(__file__).resolve().parents[1]

_CHILD = r"""
import json, sys, time, tomllib
from flexbooster.case import default_case_text, load_case
from flexbooster.memo import charts
from flexbooster.model import model_from_case
data = tomllib.loads(default_case_text())
data.setdefault("damping", {})["beam_modal_ratio"] = 0.01
model = model_from_case(load_case(data))
best, best_cpu, chart = 1e300, 1e300, None
for _ in range(int(sys.argv[1])):
    t0, c0 = time.perf_counter(), time.process_time()
    chart = charts.beam_action_chart(model)
    best = min(best, time.perf_counter() - t0)
    best_cpu = min(best_cpu, time.process_time() - c0)
tips = [[r.label, float(r.gamma[0]), float(r.omega_lo[0])] for r in chart.regions]
print(json.dumps({"wall": best, "cpu": best_cpu, "tips": tips}))
"""


def _run(src: Path, repeat: int) -> dict:
    env = dict(os.environ, PYTHONPATH=str(src), OPENBLAS_NUM_THREADS="1")
    out = subprocess.run([sys.executable, "-c", _CHILD, str(repeat)], env=env, check=True,
                         capture_output=True, text=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=1)
    args = parser.parse_args()
    new = _run(ROOT / "src", args.repeat)
    with tempfile.TemporaryDirectory() as tmp:
        base = Path(tmp) / "baseline"
        subprocess.run(["git", "-C", str(ROOT), "worktree", "add", "-q", "--detach", str(base),
                        BASELINE], check=True)
        try:
            old = _run(base / "src", args.repeat)
        finally:
            subprocess.run(["git", "-C", str(ROOT), "worktree", "remove", "--force", str(base)],
                           check=True)
    print(f"damped beam-action chart, default case, beam_modal_ratio 0.01, best of "
          f"{args.repeat}:")
    print(f"  new     : {new['wall']:.2f} s wall, {new['cpu']:.2f} s CPU")
    print(f"  baseline: {old['wall']:.2f} s wall, {old['cpu']:.2f} s CPU ({BASELINE})")
    print(f"  ratio   : {old['wall'] / new['wall']:.2f} (wall), {old['cpu'] / new['cpu']:.2f} "
          "(CPU)  (target >= 3)")
    print(f"{'region':>22} {'tip gamma new':>14} {'baseline':>12} {'rel. diff':>10}")
    for (lab, g_new, _), (_, g_old, _) in zip(new["tips"], old["tips"], strict=False):
        print(f"{lab:>22} {g_new:14.8f} {g_old:12.8f} {(g_old - g_new) / g_new:10.2e}")


if __name__ == "__main__":
    main()
