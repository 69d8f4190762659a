"""Benchmark: band search and damped chart of the memo case against the code before them.

Times, in the same run (best of ``--repeat``, wall and CPU of a child
process), in this tree and in commit ``BASELINE`` (checked out side by side with
``git worktree`` into a temporary folder and run with the same Python, as
``benchmarks/bench_run.py`` does):

1. the pipeline's beam-action band search of the memo case (``beam_action_bands`` over
   [max(omega_min, omega_1 / 4), omega_max], no damping): the new one adds the narrow regions
   below the monodromy floor (``floquet/narrow.py``); the band counts are printed;
2. the damped beam-action (Omega, gamma) chart, memo case with
   ``[damping] beam_modal_ratio = 0.01`` (``flexbooster.memo.charts.beam_action_chart``:
   boundaries from ``floquet.region_boundaries``, tips from ``critical_amplitude``); the
   baseline's tips come from brentq over gamma of full region searches (biased upward by the
   chart's rtol 1e-4), the new ones from ``floquet.regions._tips``.

``--baseline REV`` compares with another commit (branch damped1: main 308388d, before the fix
of the damped step counts; the damped chart is the work the fix changes, the band search is
undamped).

Usage (repository root)::

    OPENBLAS_NUM_THREADS=1 python benchmarks/bench_bands_vs_baseline.py [--repeat 2] \
        [--baseline REV]
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

__all__ = ["BASELINE", "main"]

#: main at the start of this work (before the new tip search).
BASELINE = "46541ca"
ROOT = Path(__file__).resolve().parents[1]

_CHILD = r"""
import json, sys, time, tomllib
from flexbooster.case import memo_case_text, load_case
from flexbooster.memo import charts
from flexbooster.memo.beam_action import BAND_OMEGA_BAR_MIN, beam_action_bands, beam_system
from flexbooster.model import model_from_case


def best(fn, repeat):
    b, bc, out = 1e300, 1e300, None
    for _ in range(repeat):
        t0, c0 = time.perf_counter(), time.process_time()
        out = fn()
        b, bc = min(b, time.perf_counter() - t0), min(bc, time.process_time() - c0)
    return out, b, bc


repeat = int(sys.argv[1])
data = tomllib.loads(memo_case_text())
model = model_from_case(load_case(data))
system = beam_system(model)
w1 = float(system.omega_1)
lo, hi = max(model.omega_range[0], BAND_OMEGA_BAR_MIN * w1), model.omega_range[1]
bands, tb, cb = best(lambda: beam_action_bands(system, model.gamma, omega_min=lo,
                                               omega_max=hi), repeat)
data.setdefault("damping", {})["beam_modal_ratio"] = 0.01
damped = model_from_case(load_case(data))
chart, tc, cc = best(lambda: charts.beam_action_chart(damped), repeat)
tips = [[r.label, float(r.gamma[0]), float(r.omega_lo[0])] for r in chart.regions]
print(json.dumps({"bands": len(bands), "band_wall": tb, "band_cpu": cb, "wall": tc,
                  "cpu": cc, "tips": tips}))
"""


def _run(src: Path, repeat: int) -> dict:
    env = dict(os.environ, PYTHONPATH=str(src), OPENBLAS_NUM_THREADS="1")
    out = subprocess.run([sys.executable, "-c", _CHILD, str(repeat)], env=env, check=True,
                         capture_output=True, text=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=1)
    parser.add_argument("--baseline", default=BASELINE, help="commit to compare with")
    args = parser.parse_args()
    new = _run(ROOT / "src", args.repeat)
    with tempfile.TemporaryDirectory() as tmp:
        with baseline_checkout(args.baseline, Path(tmp) / "baseline") as base:
            old = _run(base / "src", args.repeat)
    print(f"memo case, best of {args.repeat}, baseline {args.baseline}:")
    print(f"1. band search: new {new['bands']} bands, {new['band_wall']:.3f} s wall "
          f"({new['band_cpu']:.3f} s CPU); baseline {old['bands']} bands, "
          f"{old['band_wall']:.3f} s wall ({old['band_cpu']:.3f} s CPU)")
    print(f"2. damped chart (beam_modal_ratio 0.01): new {new['wall']:.2f} s wall "
          f"({new['cpu']:.2f} s CPU); baseline {old['wall']:.2f} s wall ({old['cpu']:.2f} s "
          f"CPU); ratio {old['wall'] / new['wall']:.2f} (wall), {old['cpu'] / new['cpu']:.2f} "
          "(CPU)  (target >= 3)")
    print(f"{'region':>22} {'tip gamma new':>14} {'baseline':>12}")
    for (lab, g_new, _), (_, g_old, _) in zip(new["tips"], old["tips"], strict=False):
        print(f"{lab:>22} {g_new:14.3e} {g_old:12.3e}")


if __name__ == "__main__":
    main()
