"""The 60 free-free ``[vehicle]`` cases of the k = 1 cost model (docs/theory/robustness.md):
heavy damping (0.3, 0.99), n_modes 1-2, a low Omega range (omega_min 0.1-6 rad/s), gimbal gain
K in {0, 0.5, 2}, 1-3 cylinders of the default booster's material; fixed seed.

For each case (or the indices given) it prints the up-front estimate of the k = 1 search
(``cost.bending_search_steps``) and, with ``--run``, the monodromy steps the search integrates
(a counter on ``floquet.regions.step_counts``) and the CPU time, stopped after ``--limit`` s.

Usage::

    OPENBLAS_NUM_THREADS=1 PYTHONPATH=src python scripts/free_free_damped_cases.py [--run]
        [--limit 120] [INDEX ...]
"""

from __future__ import annotations

import argparse
import math
import random
import signal
import time
import tomllib

import numpy as np

import flexbooster
import flexbooster.floquet.regions as floquet_regions
from flexbooster import cost, floquet
from flexbooster.analysis import analyze_vehicle_regions
from flexbooster.case import memo_case_text
from flexbooster.dynamics import bending_harmonic
from flexbooster.dynamics.harmonic import floquet_options
from flexbooster.model import vehicle_from_case


def free_free_cases(n: int = 60, seed: int = 36, max_seconds: float = 300.0) -> list[dict]:
    """The case dictionaries (load with ``flexbooster.load_case``)."""
    rng = random.Random(seed)
    booster = tomllib.loads(memo_case_text())["booster"]

    def lu(lo: float, hi: float) -> float:
        return 10 ** rng.uniform(math.log10(lo), math.log10(hi))

    out = []
    for _ in range(n):
        r = lu(0.5, 5.0)
        segs = [{"kind": "cylinder", "radius": r, "length": lu(2, 60),
                 "thickness": r * lu(1e-3, 2e-2)} for _ in range(rng.randint(1, 3))]
        om = lu(0.1, 6.0)
        out.append({"name": "free-free", "max_seconds": max_seconds,
                    "thrust": {"F0": lu(1e4, 1e6), "gamma": rng.uniform(0.05, 0.5),
                               "K": rng.choice([0.0, 0.5, 2.0]), "omega_min": om,
                               "omega_max": om * lu(1.5, 100)},
                    "vehicle": {"k_max": rng.choice([1, 2, 3]), "n_modes": rng.choice([1, 2]),
                                "damping_ratio": rng.choice([0.3, 0.99]), "aft_end": "free",
                                "fwd_end": "free", "segments": segs,
                                # one vehicle per case: the default booster's material
                                **{key: booster[key] for key in ("E", "nu", "rho")}}})
    return out


def k1_work(case) -> floquet.SearchWork:
    """The toolkit's count of the k = 1 search of a case (as the cost estimate takes it)."""
    t = case.thrust
    vehicle = vehicle_from_case(case)
    n = cost.region_modes(case, vehicle, k_max=case.vehicle.k_max)[0]
    h = bending_harmonic(vehicle, F0=case.F0, n_modes=max(n, 3),
                         damping_ratio=case.vehicle_damping_ratio, gimbal_gain=t.K)
    return floquet.search_work(*h.periodic(t.gamma), t.omega_min, t.omega_max,
                               **floquet_options())


class StepCounter:
    """Context manager: ``steps`` is the sum of the monodromy steps (per period or half period,
    over the evaluated points) that the region search asks of the kernel inside the block (the
    step counts of ``floquet.regions``: work, not time)."""

    def __enter__(self) -> StepCounter:
        self.steps = 0
        self._original = original = floquet_regions.step_counts

        def counting(system, Omega, **kw):
            steps = original(system, Omega, **kw)
            self.steps += int(np.sum(steps))
            return steps

        floquet_regions.step_counts = counting
        return self

    def __exit__(self, *exc) -> None:
        floquet_regions.step_counts = self._original


class _Stop(Exception):
    pass


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("index", type=int, nargs="*")
    parser.add_argument("--run", action="store_true")
    parser.add_argument("--limit", type=int, default=120)
    args = parser.parse_args()

    def stop(signum, frame):
        raise _Stop

    signal.signal(signal.SIGALRM, stop)
    cases = free_free_cases()
    for i in args.index or range(len(cases)):
        case = flexbooster.load_case(cases[i])
        est_steps, est_s = cost.bending_search_steps(
            k1_work(case), damping_ratio=case.vehicle_damping_ratio)
        line = f"{i:3d} estimate {est_steps:12.0f} steps {est_s:8.2f} s"
        if args.run:
            start = time.process_time()
            signal.alarm(args.limit)
            with StepCounter() as counter:
                try:
                    analyze_vehicle_regions(case, boundaries=False)
                    state = "done"
                except _Stop:
                    state = "stopped"
                finally:
                    signal.alarm(0)
            line += (f"  measured {counter.steps:12d} steps {time.process_time() - start:8.2f} "
                     f"s CPU ({state}), ratio {counter.steps / max(est_steps, 1.0):.2f}")
        print(line, flush=True)


if __name__ == "__main__":
    main()
