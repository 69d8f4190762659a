"""CPU of the analysis stages that ``flexbooster run`` computes in its parent process, against
another commit (default ``main``).

On the default case, each stage on its own, best of ``--repeats`` (``time.process_time``, one
process, OPENBLAS_NUM_THREADS=1):

* ``monodromy_exponents``: the beam-action exponents on the 400-point Omega grid (the Lawson
  march of ``beam_action_analysis``);
* ``unstable_frequencies``: the stability table (~42,000 roots);
* ``severity_analysis``: the severity of every root (the Floquet vectors of the beam roots);
* ``hill_check``: Hill's determinant at three grid points (in a worker during a run);
* ``pitch_analysis``: the pitch exponents on the grid (Hill's continuant).

The other commit is checked out side by side with ``git worktree`` into a temporary folder
and timed with the same Python and packages, alternating with the current code (the inputs of
each stage are computed once per process, by that process's code).  The stages' outputs are
compared bit for bit (they must be identical: the changes keep every floating-point
operation).

Run from the repository root (needs git and the project's venv)::

    .venv/bin/python benchmarks/bench_parent_stages.py [--baseline REV] [--repeats 5] [--rounds 3]
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

from baseline_checkout import baseline_checkout

__all__ = ["STAGES", "main"]

ROOT = Path(__file__).resolve().parents[1]
#: The stages timed, in the order of a run.
STAGES = ("monodromy_exponents", "pitch_analysis", "unstable_frequencies",
          "severity_analysis", "hill_check")

#: The timing script run in a fresh interpreter with PYTHONPATH = the source tree timed.
_CHILD = r"""
import hashlib, json, pickle, sys, time
import numpy as np
from flexbooster import cost
from flexbooster.case import default_case
from flexbooster.memo.beam_action import (_grid, beam_action_analysis, beam_system, hill_check,
                                          monodromy_exponents)
from flexbooster.memo.pitch import pitch_analysis
from flexbooster.memo.responses.excitation import excitation_parameters
from flexbooster.memo.severity import severity_analysis
from flexbooster.memo.shell import natural_frequencies
from flexbooster.memo.stability import ShellModes, unstable_frequencies

repeats = int(sys.argv[1])
case = default_case()
model = cost.derived_model(case)
system = beam_system(model)
Ob, gam, _ = _grid(model.Omega, float(model.gamma), system.omega_1)
action = beam_action_analysis(model, bands=())
shell = natural_frequencies(model)
modes = ShellModes(shell.cylinder, shell.j, shell.k, shell.branch, shell.omega_bar)
params = excitation_parameters(model, action)
lo, hi = model.omega_range
n = model.truncation
table = unstable_frequencies(modes, params, Omega_bar_range=(lo / model.omega_1,
                             hi / model.omega_1), omega_1=model.omega_1, R=n.R, S=n.S,
                             gamma=model.gamma, K=model.K)
sv = case.severity
calls = {
    "monodromy_exponents": lambda: monodromy_exponents(system, Ob * system.omega_1, gam),
    "pitch_analysis": lambda: pitch_analysis(model.Omega, model.omega_psi, model.gamma,
                                             damping_ratio=model.pitch_damping_ratio),
    "unstable_frequencies": lambda: unstable_frequencies(
        modes, params, Omega_bar_range=(lo / model.omega_1, hi / model.omega_1),
        omega_1=model.omega_1, R=n.R, S=n.S, gamma=model.gamma, K=model.K),
    "severity_analysis": lambda: severity_analysis(
        model, table, params, psi0=sv.psi0, beam_amplitude=sv.beam_amplitude,
        threshold=sv.threshold, resolution=sv.resolution),
    "hill_check": lambda: hill_check(model),
}
out = {}
for name in sys.argv[2:]:
    best = float("inf")
    for _ in range(repeats):
        t0 = time.process_time()
        result = calls[name]()
        best = min(best, time.process_time() - t0)
    digest = hashlib.sha256(pickle.dumps(result)).hexdigest()
    out[name] = (best, digest)
print(json.dumps(out))
"""


def _run(src: Path, repeats: int) -> dict:
    env = dict(os.environ, PYTHONPATH=str(src), OPENBLAS_NUM_THREADS="1")
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    done = subprocess.run([sys.executable, "-c", _CHILD, str(repeats), *STAGES], env=env,
                          check=True, capture_output=True, text=True)
    return json.loads(done.stdout.strip().splitlines()[-1])


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--baseline", default="main", help="commit to compare with")
    ap.add_argument("--repeats", type=int, default=5, help="timings per stage and process")
    ap.add_argument("--rounds", type=int, default=3, help="alternating process pairs")
    args = ap.parse_args()
    load = os.getloadavg()
    with tempfile.TemporaryDirectory() as tmp:
        with baseline_checkout(args.baseline, Path(tmp) / "baseline") as base:
            old: dict = {}
            new: dict = {}
            for _ in range(args.rounds):  # alternating: the same load on both
                for src, best in ((base / "src", old), (ROOT / "src", new)):
                    for name, (t, digest) in _run(src, args.repeats).items():
                        prev = best.get(name, (float("inf"), digest))
                        best[name] = (min(prev[0], t), digest)
    print(f"parent-process stages, default case: {args.baseline} against this tree, CPU "
          f"seconds, best of {args.rounds} x {args.repeats}; load average "
          f"{load[0]:.2f} {load[1]:.2f} {load[2]:.2f}")
    print(f"{'stage':<22}{args.baseline:>10}{'now':>10}{'ratio':>8}  same output")
    total_old = total_new = 0.0
    for name in STAGES:
        (t_old, d_old), (t_new, d_new) = old[name], new[name]
        total_old += t_old
        total_new += t_new
        print(f"{name:<22}{t_old:>10.3f}{t_new:>10.3f}{t_old / t_new:>8.2f}  "
              f"{'yes' if d_old == d_new else 'NO'}")
    print(f"{'total':<22}{total_old:>10.3f}{total_new:>10.3f}{total_old / total_new:>8.2f}")


if __name__ == "__main__":
    main()
