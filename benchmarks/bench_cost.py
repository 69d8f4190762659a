"""Benchmark: the cost model against the measured run time, and the low-Omega cap.

Times, in the same run, for a few cases:
  * the estimate (``flexbooster.cost.estimate_cost``: no solver is run),
  * the baseline: the analysis itself (``analyze``, best of ``--repeat``),
and prints both, the ratio estimate / measured (the model's accuracy) and the time of the
estimate.  Then the monodromy of one low grid point (Omega = 0.05 rad/s, where the step rule
asks about 1e6 steps per half period) with the cap, against the uncapped cost predicted by the
step rule.  Then the rigid-pitch tongue search below omega_1 / 4 (``pitch_tongue_bands``, CPU
time) against its term of the estimate (``cost.TONGUE_PART``): the default booster with its
range lowered, N = 4, 6, 10, with and without damping, and ``--spread M`` fuzz-like boosters
(seeded; the ratio's spread).  Usage::

    python benchmarks/bench_cost.py [--repeat 1] [--spread 0] [--tongues-only]
"""

from __future__ import annotations

import argparse
import math
import os
import time
import tomllib

import numpy as np

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import flexbooster  # noqa: E402
from flexbooster._threads import blas_threads  # noqa: E402
from flexbooster.analysis import analyze  # noqa: E402
from flexbooster.case import memo_case_text  # noqa: E402
from flexbooster.cost import (  # noqa: E402
    TONGUE_PART,
    check_physical,
    estimate_cost,
)
from flexbooster.errors import CaseError  # noqa: E402
from flexbooster.memo import beam_action as ba  # noqa: E402
from flexbooster.model import model_from_case  # noqa: E402

CASES = {
    "default": ({}, True),
    "default, no figures": ({}, False),
    "small truncation": ({"truncation": dict(M1=4, N1=4, M2=4, N2=4, N=4, S=3, R=3)}, True),
    "N = 20": ({"truncation": dict(N=20, R=4)}, False),
}


#: The default booster (omega_1 = 113.5 rad/s, pitch tips 2.39 / r rad/s) below omega_1 / 4.
_LOW = {"thrust": dict(omega_min=0.5, omega_max=20.0, n_omega=4, gamma=0.5)}
TONGUE_CASES = {
    "N = 4": {"truncation": dict(N=4)},
    "N = 4, pitch damping 0.02": {"truncation": dict(N=4), "damping": dict(pitch_ratio=0.02)},
    "N = 6": {"truncation": dict(N=6)},
    "N = 6, pitch damping 0.02": {"truncation": dict(N=6), "damping": dict(pitch_ratio=0.02)},
    "N = 10": {},
    "N = 10, pitch damping 0.02": {"damping": dict(pitch_ratio=0.02)},
    "N = 10, beam damping 0.01": {"damping": dict(beam_modal_ratio=0.01)},
}


def _tongue_time(model) -> float:
    """CPU time (s) of the pipeline's tongue search of a model (as beam_action_analysis)."""
    system = ba.beam_system(model)
    lo = max(float(np.min(model.Omega)), ba.BAND_OMEGA_BAR_MIN * float(system.omega_1))
    hi = float(np.max(model.Omega))
    low = float(np.min(model.Omega))
    t = time.process_time()
    with blas_threads(1):
        ba.pitch_tongue_bands(system, model.gamma, omega_min=low, omega_max=min(lo, hi),
                              beam_ratio=model.beam_damping_ratio,
                              pitch_ratio=model.pitch_damping_ratio)
    return time.process_time() - t


def _fuzz_like(rng) -> dict:
    """A booster as tests/test_fuzz.py draws them, with its range below omega_1 / 4 likely."""
    def lu(a, b):
        return 10.0 ** rng.uniform(math.log10(a), math.log10(b))

    r1, r2 = lu(0.2, 50.0), lu(0.2, 50.0)
    om = lu(0.05, 20.0)
    n = int(rng.integers(1, 5))
    return {"name": "spread", "max_seconds": 1e6,
            "booster": {"cylinder1": {"radius": r1, "half_length": lu(0.5, 100.0)},
                        "cylinder2": {"radius": r2, "half_length": lu(0.5, 100.0)},
                        "thickness": min(r1, r2) * lu(1e-4, 0.5), "E": lu(1e8, 1e12),
                        "nu": rng.uniform(0.01, 0.49), "rho": lu(10.0, 2e4)},
            "thrust": {"gamma": rng.uniform(0.0, 0.95), "K": rng.uniform(0.0, 5.0),
                       "omega_min": om, "omega_max": om * lu(1.01, 1000.0),
                       "n_omega": int(rng.integers(2, 13)), "F0": lu(1e2, 1e12)},
            "truncation": {"M1": 1, "N1": 1, "M2": 1, "N2": 1, "N": n, "S": 0, "R": 1},
            "damping": {"beam_modal_ratio": float(rng.choice([0.0, 0.0, 0.01, 0.2])),
                        "pitch_ratio": float(rng.choice([0.0, 0.0, 0.02, 0.5]))}}


def tongues(spread: int) -> None:
    print(f"\n{'pitch tongues (default booster, Omega 0.5..20 rad/s, gamma 0.5)':<44} "
          f"{'estimate s':>10} {'measured s':>10} {'ratio':>6}")
    for name, update in TONGUE_CASES.items():
        d = tomllib.loads(memo_case_text())
        for key, value in {**_LOW, **update}.items():
            d.setdefault(key, {}).update(value)
        model = model_from_case(flexbooster.load_case(d))
        est = estimate_cost(model, figures=False).parts.get(TONGUE_PART, 0.0)
        measured = _tongue_time(model)
        print(f"{name:<44} {est:10.2f} {measured:10.2f} {est / measured:6.2f}")
    if not spread:
        return
    rng = np.random.default_rng(2026)
    rows = []
    while len(rows) < spread:
        try:
            model = model_from_case(flexbooster.load_case(_fuzz_like(rng)))
            check_physical(model)
        except CaseError:
            continue
        est = estimate_cost(model, figures=False).parts.get(TONGUE_PART, 0.0)
        if est == 0.0:
            continue
        rows.append((est, _tongue_time(model)))
    est, meas = np.array(rows).T
    big = meas > 0.3
    ratio = est[big] / meas[big]
    print(f"{spread} fuzz-like boosters (seed 2026): measured {meas.sum():.1f} s in all, "
          f"estimated {est.sum():.1f} s; the {big.sum()} over 0.3 s: estimate / measured "
          f"median {np.median(ratio):.2f}, 10% {np.percentile(ratio, 10):.2f}, 90% "
          f"{np.percentile(ratio, 90):.2f}, min {ratio.min():.2f}, max {ratio.max():.2f}; "
          f"largest measured {meas.max():.2f} s (estimate {est[np.argmax(meas)]:.2f} s)")


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
    parser.add_argument("--spread", type=int, default=0)
    parser.add_argument("--tongues-only", action="store_true")
    args = parser.parse_args()
    with open("/proc/loadavg") as f:
        print(f"load average {f.read().split()[0]}; CPU times of this process")
    if args.tongues_only:
        tongues(args.spread)
        return
    print(f"{'case':<22} {'estimate s':>10} {'measured s':>10} {'ratio':>6} {'est. time':>9}")
    for name, (update, figures) in CASES.items():
        d = tomllib.loads(memo_case_text())
        for key, value in update.items():
            d[key].update(value)
        case = flexbooster.load_case(d)
        model = model_from_case(case)
        t_est = best(lambda m=model, f=figures: estimate_cost(m, figures=f), 3)
        est = estimate_cost(model, figures=figures).seconds
        measured = best(lambda c=case, f=figures: analyze(c, figures=f), args.repeat)
        print(f"{name:<22} {est:10.2f} {measured:10.2f} {est / measured:6.2f} {t_est:9.4f}")
    model = model_from_case(flexbooster.memo_case())
    system = ba.beam_system(model)
    Om = np.array([0.05])
    raw = int(ba.monodromy_steps(system, Om, model.gamma)[0])
    t_cap = best(lambda: ba.monodromy_exponents(system, Om, model.gamma), args.repeat)
    per_step = t_cap / ba.MONODROMY_MAX_STEPS
    print(f"monodromy at Omega = 0.05 rad/s: capped {ba.MONODROMY_MAX_STEPS} steps "
          f"{t_cap:.2f} s; the rule asks {raw} steps, ~{raw * per_step:.0f} s uncapped "
          f"(ratio {raw / ba.MONODROMY_MAX_STEPS:.0f}x)")
    tongues(args.spread)


if __name__ == "__main__":
    main()
