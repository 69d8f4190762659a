"""Benchmark: the damped beam-action band search against a baseline commit, in the same run.

Times :func:`flexbooster.memo.beam_action.pipeline_bands` (the damped search of the regions
and the critical gamma of each) of the memo's two-cylinder case with its default modal damping
(beam 1 %, pitch 0; the case stored in ``tests/data/damped_bands_reference.json``), in this
tree and in commit ``--baseline`` (default 2ffa6ec: the dense Lawson kernel stepping one RK4
step at a time, the critical gamma bisected down from gamma), each in a child process with one
BLAS thread, alternating ``--rounds`` times; prints the best CPU time of each, the ratio
baseline / this tree (> 1: this tree is faster), the monodromy steps each search integrated
(summed over the evaluated points) and the largest differences of the bands.

Usage (repository root)::

    python benchmarks/bench_damped_bands.py [--rounds 3] [--baseline 2ffa6ec]
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
from pathlib import Path

from baseline_checkout import ROOT, alternate

__all__ = ["CASE", "main"]

#: The stored memo case (its "case" key).
CASE = ROOT / "tests" / "data" / "damped_bands_reference.json"

_CHILD = r"""
import json, sys, time
import numpy as np
import flexbooster
import flexbooster.floquet.regions as regions
from flexbooster.memo.beam_action import pipeline_bands
from flexbooster.model import model_from_case

model = model_from_case(flexbooster.load_case(json.load(open(sys.argv[1]))["case"]))
steps = [0]
original = regions.step_counts

def counting(system, Omega, **kw):
    out = original(system, Omega, **kw)
    steps[0] += int(np.sum(out))
    return out

regions.step_counts = counting
t0 = time.process_time()
bands = pipeline_bands(model)
cpu = time.process_time() - t0
print(json.dumps({"cpu": cpu, "steps": steps[0], "bands": [b.to_dict() for b in bands]}))
"""


def _run(src: Path) -> dict:
    env = dict(os.environ, PYTHONPATH=str(src), OPENBLAS_NUM_THREADS="1")
    out = subprocess.run([sys.executable, "-c", _CHILD, str(CASE)], env=env, check=True,
                         capture_output=True, text=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def _differences(new: list, old: list) -> str:
    if len(new) != len(old):
        return f"band counts differ: {len(new)} against {len(old)}"
    pairs = list(zip(new, old, strict=True))
    lo = max(abs(a["Omega_lo"] - b["Omega_lo"]) / b["Omega_center"] for a, b in pairs)
    hi = max(abs(a["Omega_hi"] - b["Omega_hi"]) / b["Omega_center"] for a, b in pairs)
    g = max(abs(a["growth_rate_max"] / b["growth_rate_max"] - 1.0) for a, b in pairs)
    gc = max(abs(a["critical_gamma"] - b["critical_gamma"]) for a, b in pairs)
    return (f"{len(new)} bands; largest differences: lower edges {lo:.2g}, upper edges {hi:.2g} "
            f"(of the centre), growth maxima {g:.2g} (relative), critical gamma {gc:.2g}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--baseline", default="2ffa6ec", help="commit to compare with")
    args = parser.parse_args()
    runs = alternate(args.baseline, args.rounds, _run)
    best = {tree: min(got, key=lambda r: r["cpu"]) for tree, got in runs.items()}
    new, old = best["new"], best["old"]
    print(f"damped beam-action bands of the memo case, best of {args.rounds} rounds, CPU time:")
    print(f"  this tree {new['cpu']:8.3f} s  {new['steps']:9d} steps")
    print(f"  {args.baseline:>9} {old['cpu']:8.3f} s  {old['steps']:9d} steps")
    print(f"  ratio {old['cpu'] / new['cpu']:.2f} (CPU), {old['steps'] / new['steps']:.2f} "
          "(steps)")
    print("  " + _differences(new["bands"], old["bands"]))


if __name__ == "__main__":
    main()
