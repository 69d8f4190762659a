"""Benchmark: the flight stage against separate analyses of its frozen cases (issue 35 item 5).

Times, in the same run (wall), the example ``examples/flight-two-stage.toml`` with
``--stations`` frozen times, ``--k-max`` and ``--n-modes``:
  1. ``flight_stage`` of the case (the work: every frozen time, tracking, events);
  2. baseline: one ``analyze`` per frozen time of the frozen case (the time's fills, F0 and
     gamma, Omega over the union of the oscillation bands, no [flight]), without the memo's
     beam action and stability and without figure data (cheaper than ``flexbooster run``).
The ratio baseline / work is printed. The issue's target is 50 frozen times, k <= 20, 20 modes
per k, under 60 s and >= 10x; the defaults are those sizes (several minutes on a shared
machine; pass smaller ones for a quick look).

Usage::

    OPENBLAS_NUM_THREADS=1 PYTHONPATH=src python benchmarks/bench_flight.py \
        [--stations 50] [--k-max 20] [--n-modes 20] [--baseline-times N]
"""

from __future__ import annotations

import argparse
import copy
import time
import tomllib
from pathlib import Path

from flexbooster.analysis import analyze
from flexbooster.case import load_case
from flexbooster.flight_stage import flight_stage
from flexbooster.model import flight_times, timeline_from_case

EXAMPLE = Path(__file__).resolve().parent.parent / "examples" / "flight-two-stage.toml"


def frozen_case(data: dict, point, omega_range) -> dict:
    """The case of one frozen time: its fills, F0, gamma; Omega over ``omega_range``."""
    out = copy.deepcopy(data)
    out.pop("flight")
    for tank, fill in zip(out["vehicle"]["tanks"], point.fill, strict=True):
        tank["fill"] = fill
    out["thrust"].update(F0=point.F0, gamma=point.gamma, omega_min=omega_range[0],
                         omega_max=omega_range[1])
    out["max_seconds"] = 1e6
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--stations", type=int, default=50)
    parser.add_argument("--k-max", type=int, default=20)
    parser.add_argument("--n-modes", type=int, default=20)
    parser.add_argument("--baseline-times", type=int, default=None,
                        help="analyse only this many frozen cases and scale (default all)")
    args = parser.parse_args()
    data = tomllib.loads(EXAMPLE.read_text())
    data["vehicle"].update(k_max=args.k_max, n_modes=args.n_modes)
    data["flight"]["stations"] = args.stations
    data["max_seconds"] = 1e6
    case = load_case(data)
    times = flight_times(case)
    print(f"{times.size} frozen times, k <= {args.k_max}, {args.n_modes} modes per k")

    start = time.perf_counter()
    flight, _ = flight_stage(case)
    work = time.perf_counter() - start
    print(f"flight_stage: {work:.2f} s ({work / times.size:.3f} s per frozen time), "
          f"{len(flight.events)} events")

    timeline = timeline_from_case(case)
    chosen = list(times) if args.baseline_times is None else list(times)[:args.baseline_times]
    start = time.perf_counter()
    for t in chosen:
        analyze(load_case(frozen_case(data, timeline.at(float(t)), flight.omega_range)),
                beam_action=False, stability=False, figures=False)
    base = (time.perf_counter() - start) * times.size / len(chosen)
    scaled = "" if len(chosen) == times.size else f" (scaled from {len(chosen)})"
    print(f"baseline, {times.size} separate analyses: {base:.2f} s{scaled}")
    print(f"ratio baseline / flight_stage: {base / work:.2f}x")


if __name__ == "__main__":
    main()
