"""Benchmark: the pitch and beam-action stages against a baseline commit, in the same run.

Times ``pitch_analysis`` and ``beam_action_analysis`` (exponents on the grid, bands, Hill
check) of the memo case and of the inch-pound Titan-class case (tests/data), in this tree
and in commit ``--baseline`` (default 66f93aa, the code before the sequential pipeline), each
in a child process with one BLAS thread, alternating tree and baseline ``--rounds`` times;
prints the best CPU time of each (less sensitive than wall time to other processes on the
machine) and the ratio baseline / this tree (> 1: this tree is faster).

Usage (repository root)::

    python benchmarks/bench_beam_action.py [--rounds 3] [--baseline 66f93aa]
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

from baseline_checkout import ROOT, baseline_checkout

__all__ = ["CASES", "main"]

#: The cases timed: the memo case and the Titan-class case of the regression tests.
CASES = {"default": None, "titan": ROOT / "tests" / "data" / "cases" / "titan-inch-pound.toml"}

_CHILD = r"""
import json, sys, time
from flexbooster.case import memo_case, load_case
from flexbooster.memo.beam_action import beam_action_analysis
from flexbooster.memo.pitch import pitch_analysis
from flexbooster.model import model_from_case

path = sys.argv[1]
model = model_from_case(memo_case() if path == "-" else load_case(path))
t0 = time.process_time()
pitch_analysis(model.Omega, model.omega_psi, model.gamma,
               damping_ratio=model.pitch_damping_ratio)
t1 = time.process_time()
action = beam_action_analysis(model)
t2 = time.process_time()
print(json.dumps({"pitch": t1 - t0, "beam_action": t2 - t1, "bands": len(action.bands)}))
"""


def _run(src: Path, case: Path | None) -> dict:
    env = dict(os.environ, PYTHONPATH=str(src), OPENBLAS_NUM_THREADS="1")
    out = subprocess.run([sys.executable, "-c", _CHILD, "-" if case is None else str(case)],
                         env=env, check=True, capture_output=True, text=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--baseline", default="66f93aa", help="commit to compare with")
    args = parser.parse_args()
    best: dict = {}
    with tempfile.TemporaryDirectory() as tmp:
        with baseline_checkout(args.baseline, Path(tmp) / "baseline") as base:
            for _ in range(args.rounds):
                for name, case in CASES.items():
                    for tree, src in (("new", ROOT / "src"), ("old", base / "src")):
                        got = _run(src, case)
                        key = (name, tree)
                        best[key] = {k: min(v, best.get(key, got)[k]) for k, v in got.items()}
    print(f"best of {args.rounds} rounds, CPU time (s), baseline {args.baseline}:")
    print(f"{'case':>8} {'stage':>12} {'this tree':>10} {'baseline':>10} {'ratio':>7}")
    for name in CASES:
        new, old = best[(name, "new")], best[(name, "old")]
        for stage in ("pitch", "beam_action"):
            print(f"{name:>8} {stage:>12} {new[stage]:10.3f} {old[stage]:10.3f} "
                  f"{old[stage] / new[stage]:7.2f}")
        print(f"{name:>8} {'bands':>12} {new['bands']:10d} {old['bands']:10d}")


if __name__ == "__main__":
    main()
