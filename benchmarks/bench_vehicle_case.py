"""Benchmark: the vehicle stage of the pipeline against its baselines, same run.

Work timed (best of REPEATS, ``time.perf_counter``):

1. ``analyze_vehicle`` on the memo case's vehicle (two cylinders from ``[booster]``,
   memo-bulkhead, k = 0..20, prestressed by F0 = 2.8 MN, with the figure data), against the
   bare ``shell_of_revolution.vehicle_modes`` on the same Vehicle: the overhead of the case
   layer and of the figure data (ratio close to 1 is the goal);
2. the ``vehicle modes`` stage inside ``analyze`` of the memo case with ``[vehicle]`` (the
   memo vehicle, k_max 20; timed through the progress callback) against ``analyze`` of the
   memo case as shipped (no ``[vehicle]``: no vehicle stage): the share the stage adds to
   ``flexbooster run`` when asked for (the default run does not run it).  The two analyses
   are interleaved, so that a change of machine load affects both.

Run:  PYTHONPATH=src python benchmarks/bench_vehicle_case.py
"""

from __future__ import annotations

import copy
import os
import time
import tomllib

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

from flexbooster.analysis import analyze, analyze_vehicle  # noqa: E402
from flexbooster.case import load_case, memo_case, memo_case_text  # noqa: E402
from flexbooster.model import vehicle_from_case  # noqa: E402
from flexbooster.shell_of_revolution import vehicle_modes  # noqa: E402

__all__: list[str] = []

REPEATS = 3


def best(fn, repeats=REPEATS) -> float:
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return min(times)


def main() -> None:
    case = memo_case()
    vehicle = vehicle_from_case(case)
    t_stage = best(lambda: analyze_vehicle(case, k_max=20, views=True))
    t_bare = best(lambda: vehicle_modes(vehicle, k_max=20, prestress_F0=case.F0))
    print(f"analyze_vehicle (k 0..20, views): {t_stage:.3f} s; bare vehicle_modes: "
          f"{t_bare:.3f} s; ratio {t_stage / t_bare:.2f}")
    data = copy.deepcopy(tomllib.loads(memo_case_text()))
    data["vehicle"] = {"k_max": 20}
    with_vehicle = load_case(data)
    stage, total, default = [], [], []
    for _ in range(REPEATS):
        marks = {}
        start = time.perf_counter()
        analyze(with_vehicle,
                progress=lambda name, m=marks: m.setdefault(name, time.perf_counter()))
        end = time.perf_counter()
        stage.append(end - marks["vehicle modes"])
        total.append(end - start)
        default.append(best(lambda: analyze(case), repeats=1))
    print(f"vehicle stage in analyze: {min(stage):.3f} s of {min(total):.3f} s; memo case "
          f"(no vehicle stage): {min(default):.3f} s; stage / default run "
          f"{min(stage) / min(default):.3f}")


if __name__ == "__main__":
    main()
