"""Benchmark: the vehicle-regions stage of the pipeline against its baselines, same run.

Work timed (best of ``--repeat``, ``time.perf_counter``), on the memo case's vehicle
(k = 2..10, F0 = 2.8 MN, gamma = 0.05, Omega 5..2000 rad/s, damping 0.01) with ``--n-modes``
modes per k (default 4):

1. ``analyze_vehicle_regions(case, k_min=2, k_max=10, boundaries=False)`` (the stage that
   ``analyze(..., figures=False)`` runs, on the same harmonics) against the bare
   ``flexbooster.dynamics.vehicle_regions`` with the same settings: the overhead of the case
   layer (ratio close to 1 is the goal);
2. ``analyze_vehicle_regions(case, k_min=2, k_max=10, boundaries=True)`` (the stage that
   ``flexbooster run`` runs: a search at the chart's gamma first, the boundary curves only when
   a region exists there) against ``vehicle_regions(..., boundaries=True)`` called directly
   (the curves traced unconditionally): the saving of the probe on a case where damping closes
   every region.

Run:  PYTHONPATH=src python benchmarks/bench_vehicle_pipeline.py [--n-modes 4] [--repeat 2]
"""

from __future__ import annotations

import argparse
import copy
import os
import tomllib

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

from bench_vehicle_case import best  # noqa: E402  (best of n, time.perf_counter)

from flexbooster.analysis import analyze_vehicle_regions  # noqa: E402
from flexbooster.case import load_case, memo_case_text  # noqa: E402
from flexbooster.dynamics import vehicle_regions  # noqa: E402
from flexbooster.memo.charts import VEHICLE_CHART_GAMMA_MAX, VEHICLE_CHART_LEVELS  # noqa: E402
from flexbooster.model import vehicle_from_case  # noqa: E402

__all__: list[str] = []


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n", 1)[0])
    parser.add_argument("--n-modes", type=int, default=4)
    parser.add_argument("--repeat", type=int, default=2)
    args = parser.parse_args()
    data = copy.deepcopy(tomllib.loads(memo_case_text()))
    data["vehicle"] = {"n_modes": args.n_modes}
    case = load_case(data)
    vehicle = vehicle_from_case(case)
    t = case.thrust
    kw = dict(F0=case.F0, gamma=t.gamma, omega_min=t.omega_min, omega_max=t.omega_max,
              k_min=2, k_max=10, n_modes=args.n_modes, damping_ratio=0.01)
    ks = dict(k_min=2, k_max=10)
    t_stage = best(lambda: analyze_vehicle_regions(case, boundaries=False, **ks), args.repeat)
    t_bare = best(lambda: vehicle_regions(vehicle, **kw), args.repeat)
    print(f"1. stage without curves: {t_stage:.3f} s; bare vehicle_regions: {t_bare:.3f} s; "
          f"ratio {t_stage / t_bare:.3f}")
    t_probe = best(lambda: analyze_vehicle_regions(case, boundaries=True, **ks), args.repeat)
    t_curves = best(lambda: vehicle_regions(vehicle, boundaries=True,
                                            gamma_max=VEHICLE_CHART_GAMMA_MAX,
                                            n_gamma=VEHICLE_CHART_LEVELS, **kw), args.repeat)
    print(f"2. stage with curves (probe first): {t_probe:.3f} s; curves traced directly: "
          f"{t_curves:.3f} s; ratio {t_probe / t_curves:.3f} (n_modes {args.n_modes})")


if __name__ == "__main__":
    main()
