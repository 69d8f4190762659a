"""Benchmark: the cost model of issue 18 against the measured run time, and the low-Omega cap.

Times, in the same run, for a few cases:
  * the estimate (``flexbooster.cost.estimate_cost``: no solver is run),
  * the baseline: the analysis itself (``analyze``, best of ``--repeat``),
and prints both, the ratio estimate / measured (the model's accuracy) and the time of the
estimate.  Then the monodromy of one low grid point (Omega = 0.05 rad/s, where the step rule
asks about 1e6 steps per half period) with the cap, against the uncapped cost predicted by the
step rule.  Usage::

    python benchmarks/bench_cost.py [--repeat 1]
"""

from __future__ import annotations

import argparse
import os
import time
import tomllib

import numpy as np

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import flexbooster  # noqa: E402
from flexbooster.analysis import analyze  # noqa: E402
from flexbooster.case import default_case_text  # noqa: E402
from flexbooster.cost import estimate_cost  # noqa: E402
from flexbooster.memo import beam_action as ba  # noqa: E402
from flexbooster.model import model_from_case  # noqa: E402

CASES = {
    "default": ({}, True),
    "default, no figures": ({}, False),
    "small truncation": ({"truncation": dict(M1=4, N1=4, M2=4, N2=4, N=4, S=3, R=3)}, True),
    "N = 20": ({"truncation": dict(N=20, R=4)}, False),
}


def best(f, repeat: int) -> float:
    out = np.inf
    for _ in range(repeat):
        t = time.perf_counter()
        f()
        out = min(out, time.perf_counter() - t)
    return out


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeat", type=int, default=1)
    args = parser.parse_args()
    print(f"{'case':<22} {'estimate s':>10} {'measured s':>10} {'ratio':>6} {'est. time':>9}")
    for name, (update, figures) in CASES.items():
        d = tomllib.loads(default_case_text())
        for key, value in update.items():
            d[key].update(value)
        case = flexbooster.load_case(d)
        model = model_from_case(case)
        t_est = best(lambda m=model, f=figures: estimate_cost(m, figures=f), 3)
        est = estimate_cost(model, figures=figures).seconds
        measured = best(lambda c=case, f=figures: analyze(c, figures=f), args.repeat)
        print(f"{name:<22} {est:10.2f} {measured:10.2f} {est / measured:6.2f} {t_est:9.4f}")
    model = model_from_case(flexbooster.default_case())
    system = ba.beam_system(model)
    Om = np.array([0.05])
    raw = int(ba.monodromy_steps(system, Om, model.gamma)[0])
    t_cap = best(lambda: ba.monodromy_exponents(system, Om, model.gamma), args.repeat)
    per_step = t_cap / ba.MONODROMY_MAX_STEPS
    print(f"monodromy at Omega = 0.05 rad/s: capped {ba.MONODROMY_MAX_STEPS} steps "
          f"{t_cap:.2f} s; the rule asks {raw} steps, ~{raw * per_step:.0f} s uncapped "
          f"(ratio {raw / ba.MONODROMY_MAX_STEPS:.0f}x)")


if __name__ == "__main__":
    main()
