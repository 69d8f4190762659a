"""Benchmark: one ``flexbooster run`` of a flight case against separate runs of its frozen
cases.

The example ``examples/flight-two-stage.toml`` with ``--stations`` frozen times, ``--k-max``
and ``--n-modes``, timed in the same run, each command a child process (wall and CPU, the CPU
of the children included, e.g. the figure workers):
  1. the work: ``flexbooster run`` of the flight case (the single case, then every frozen
     time, the tracking and the events, the figures and the files);
  2. the baseline: ``flexbooster run`` of the frozen case of each time (that time's fills, F0
     and gamma, Omega over the range the flight searches, no ``[flight]``), the same command
     and options. ``--baseline-runs N`` runs N of them, the middle times of N equal blocks of
     the flight, and scales their sum to every frozen time (the output says so).
The ratios baseline / work are printed (and, with ``--stage``, the flight stage alone
in-process, for the record). With ``--scheduler local`` (or a scheduler's address) the work
is also run with its frozen times on Dask, and the ratio one process / Dask is printed. The
target is 50 frozen times, k <= 20, 20 modes per k,
the work under 60 s wall and >= 10x; the defaults are those sizes (many minutes on a shared
machine; pass smaller ones for a quick look).

Usage::

    OPENBLAS_NUM_THREADS=1 PYTHONPATH=src python benchmarks/bench_flight.py \
        [--stations 50] [--k-max 20] [--n-modes 20] [--baseline-runs 5] [--no-figures] \
        [--stage] [--scheduler local]
"""

from __future__ import annotations

import argparse
import copy
import json
import os
import resource
import subprocess
import sys
import tempfile
import time
import tomllib
from pathlib import Path

import numpy as np

from flexbooster.case import load_case
from flexbooster.flight_stage import flight_omega_range, flight_stage
from flexbooster.model import flight_times, timeline_from_case

EXAMPLE = Path(__file__).resolve().parent.parent / "examples" / "flight-two-stage.toml"


def toml_text(data: dict, prefix: str = "") -> str:
    """The case as TOML: plain keys, arrays (of tables inline), then the sub-tables."""
    def value(v) -> str:
        if isinstance(v, dict):
            return "{" + ", ".join(f"{k} = {value(x)}" for k, x in v.items()) + "}"
        if isinstance(v, list | tuple):
            return "[" + ", ".join(value(x) for x in v) + "]"
        return json.dumps(v)

    out = [f"{k} = {value(v)}" for k, v in data.items() if not isinstance(v, dict)]
    for k, v in data.items():
        if isinstance(v, dict):
            name = f"{prefix}.{k}" if prefix else k
            out += [f"[{name}]", toml_text(v, name)]
    return "\n".join(out)


def frozen_case(data: dict, point, omega_range) -> dict:
    """The case of one frozen time: its fills, F0, gamma; Omega over ``omega_range``."""
    out = copy.deepcopy(data)
    out.pop("flight")
    for tank, fill in zip(out["vehicle"]["tanks"], point.fill, strict=True):
        tank["fill"] = fill
    out["thrust"].update(F0=point.F0, gamma=point.gamma, omega_min=omega_range[0],
                         omega_max=omega_range[1])
    return out


def run(path: Path, out: Path, extra: list[str]) -> tuple[float, float]:
    """(wall, CPU) seconds of ``flexbooster run path -o out -q`` in a child process."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run([sys.executable, "-m", "flexbooster", "run", str(path), "-o", str(out),
                    "-q", *extra], check=True, env=os.environ.copy())
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--stations", type=int, default=50)
    parser.add_argument("--k-max", type=int, default=20)
    parser.add_argument("--n-modes", type=int, default=20)
    parser.add_argument("--baseline-runs", type=int, default=5,
                        help="frozen cases run for the baseline, scaled to every time "
                             "(default 5; 0: all)")
    parser.add_argument("--no-figures", action="store_true", help="pass --no-figures to "
                        "every run (work and baseline alike)")
    parser.add_argument("--stage", action="store_true",
                        help="also time the flight stage alone, in-process")
    parser.add_argument("--scheduler", default=None,
                        help="also run the work with --scheduler (local or an address)")
    args = parser.parse_args()
    data = tomllib.loads(EXAMPLE.read_text())
    data["vehicle"].update(k_max=args.k_max, n_modes=args.n_modes)
    data["flight"]["stations"] = args.stations
    data["max_seconds"] = 1e6
    case = load_case(data)
    times = flight_times(case)
    T = times.size
    extra = ["--no-figures"] if args.no_figures else []
    print(f"{T} frozen times, k <= {args.k_max}, {args.n_modes} modes per k; every command "
          f"`flexbooster run -q{' --no-figures' if extra else ''}` in a child process; "
          f"load average {os.getloadavg()[0]:.1f} at the start")

    if args.stage:
        start, cpu0 = time.perf_counter(), time.process_time()
        flight, _ = flight_stage(case)
        stage_wall, stage_cpu = time.perf_counter() - start, time.process_time() - cpu0
        print(f"flight stage alone (in-process): {stage_wall:.1f} s wall, {stage_cpu:.1f} s "
              f"CPU ({stage_cpu / T:.2f} s CPU per frozen time), {len(flight.events)} events")

    timeline = timeline_from_case(case)
    omega_range = flight_omega_range(timeline)  # what the flight stage searches at every time
    n = T if args.baseline_runs <= 0 else min(args.baseline_runs, T)
    chosen = sorted({int((i + 0.5) * T / n) for i in range(n)})
    with tempfile.TemporaryDirectory(prefix="bench-flight-") as tmp:
        tmp = Path(tmp)
        (tmp / "flight.toml").write_text(toml_text(data))
        work_wall, work_cpu = run(tmp / "flight.toml", tmp / "flight-out", extra)
        print(f"work, one run of the flight case: {work_wall:.1f} s wall, {work_cpu:.1f} s "
              "CPU")
        if args.scheduler:
            dask_wall, dask_cpu = run(tmp / "flight.toml", tmp / "flight-dask-out",
                                      extra + ["--scheduler", args.scheduler])
            print(f"work on Dask (--scheduler {args.scheduler}): {dask_wall:.1f} s wall, "
                  f"{dask_cpu:.1f} s CPU (a running cluster's workers not counted); ratio one "
                  f"process / Dask: {work_wall / dask_wall:.2f}x wall")
        walls, cpus = [], []
        for i in chosen:
            path = tmp / f"frozen-{i}.toml"
            path.write_text(toml_text(frozen_case(data, timeline.at(float(times[i])),
                                                  omega_range)))
            w, c = run(path, tmp / f"frozen-{i}-out", extra)
            walls.append(w)
            cpus.append(c)
    scale = T / len(chosen)
    base_wall, base_cpu = scale * sum(walls), scale * sum(cpus)
    how = "" if len(chosen) == T else (
        f" (scaled x {scale:.2f} from {len(chosen)} runs at frozen times "
        f"{', '.join(f'{times[i]:.1f}' for i in chosen)} s)")
    print(f"baseline, {T} separate runs: {base_wall:.1f} s wall, {base_cpu:.1f} s CPU{how}; "
          f"per run {np.mean(walls):.2f} s wall, {np.mean(cpus):.2f} s CPU")
    print(f"ratio baseline / work: {base_wall / work_wall:.2f}x wall, "
          f"{base_cpu / work_cpu:.2f}x CPU; load average {os.getloadavg()[0]:.1f} at the end")


if __name__ == "__main__":
    main()
