"""Benchmark: flexbooster.vehicle.vehicle_regions on a vehicle of the default case's size.

Cylinder-cone-cylinder (R1 = 5.05 m, 42 m; 5 m cone; R2 = 3.3 m, 18 m; h = 20 mm; aluminium;
free-free, inertia relief), F0 = 2.8 MN, gamma = 0.05, Omega = 5..2000 rad/s, k = 2..k_max.
Times, in the same run,

  1. the map ``vehicle_regions`` with the default damping 0.01 (the deliverable) and undamped
     (zeta = 0, where the regions exist at gamma = 0.05);
  2. the baseline: a uniform monodromy scan (``floquet.growth_rate`` of the full damped
     system of every k) with a spacing of a third of the narrowest *undamped* region (the
     coarsest grid that puts two points in every region that damping could leave), timed on
     a sample of points per k and extrapolated to the whole grid (as bench_floquet.py).

Usage::

    OPENBLAS_NUM_THREADS=1 PYTHONPATH=src python benchmarks/bench_vehicle_regions.py \
        [--n-modes 8] [--k-max 10] [--repeat 1] [--sample 16]
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from flexbooster.floquet import growth_rate
from flexbooster.shell_of_revolution import Cone, Cylinder, Vehicle
from flexbooster.vehicle import vehicle_regions

ALU = {"E": 72.4e9, "nu": 0.33, "rho": 2768.0}


def default_size_vehicle() -> Vehicle:
    return Vehicle([Cylinder(5.05, 42.0, 0.02, **ALU), Cone(5.05, 3.3, 5.0, 0.02, **ALU),
                    Cylinder(3.3, 18.0, 0.02, **ALU)])


def best_of(fn, repeat: int):
    """Best wall time (perf_counter) and CPU time (process_time) of ``repeat`` runs."""
    best, best_cpu, out = np.inf, np.inf, None
    for _ in range(repeat):
        t0, c0 = time.perf_counter(), time.process_time()
        out = fn()
        best = min(best, time.perf_counter() - t0)
        best_cpu = min(best_cpu, time.process_time() - c0)
    return out, best, best_cpu


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--n-modes", type=int, default=8)
    ap.add_argument("--k-max", type=int, default=10)
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--sample", type=int, default=16, help="scan points timed per k")
    args = ap.parse_args()
    veh = default_size_vehicle()
    kw = dict(F0=2.8e6, gamma=0.05, omega_min=5.0, omega_max=2000.0, k_min=2,
              k_max=args.k_max, n_modes=args.n_modes)
    damped, t_d, c_d = best_of(lambda: vehicle_regions(veh, **kw), args.repeat)
    undamped, t_u, c_u = best_of(lambda: vehicle_regions(veh, damping_ratio=0.0, **kw),
                                 args.repeat)
    print(f"k = 2..{args.k_max}, {args.n_modes} modes per k, Omega = 5..2000 rad/s, "
          "gamma = 0.05")
    print(f"map, zeta = 0.01: {len(damped.regions)} regions in {t_d:.2f} s wall, "
          f"{c_d:.2f} s CPU")
    print(f"map, zeta = 0:    {len(undamped.regions)} regions in {t_u:.2f} s wall, "
          f"{c_u:.2f} s CPU")
    widths = np.array([r.width for r in undamped.regions])
    spacing = float(np.min(widths)) / 3.0
    n_grid = int(np.ceil((2000.0 - 5.0) / spacing)) + 1
    rng = np.random.default_rng(0)
    t_scan = 0.0
    for h in damped.harmonics:  # a handful of harmonics
        M, C, A, B = h.matrices(0.05)
        sample = np.sort(rng.uniform(5.0, 2000.0, args.sample))
        _, t_s, _ = best_of(lambda M=M, C=C, A=A, B=B, s=sample: growth_rate(M, C, A, B, s), 1)
        t_scan += t_s * n_grid / sample.size
    print(f"scan baseline: spacing {spacing:.3e} rad/s (a third of the narrowest undamped "
          f"region) -> {n_grid} points per k; extrapolated {t_scan:.3e} s")
    print(f"ratio scan / map (zeta = 0.01) = {t_scan / t_d:.3g}  (targets: map < 5 s, "
          "ratio >= 50)")


if __name__ == "__main__":
    main()
