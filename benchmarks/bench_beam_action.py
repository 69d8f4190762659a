"""Benchmark: beam-action Floquet exponents, Hill's determinant against the monodromy matrix.

Times, in the same run,
  1. Hill's determinant (``hill_exponents``) against the monodromy matrix
     (``monodromy_exponents``, Lawson RK4, 1e-8 setting) for the same points as N and S grow,
     with the largest difference between the two (a strong-thrust uniform beam, p = 20, K = 1,
     gamma = 0.6, where the coupling is strong and the monodromy needs many steps; and the
     default case, weak coupling);
  2. the (Omega, gamma) stability chart of the default case on --n x --n points with N = 10
     (``stability_chart``) against the baseline Hill (S = 10) per point, timed on a subsample
     and extrapolated to the full grid.

Usage::

    python benchmarks/bench_beam_action.py [--n 200] [--sample 6]
"""

from __future__ import annotations

import argparse
import os
import time

import numpy as np

from flexbooster.case import default_case
from flexbooster.memo import beam, geometry
from flexbooster.memo.beam_action import (
    beam_action_system,
    hill_exponents,
    monodromy_exponents,
    reduced_exponents,
    stability_chart,
    uniform_beam_system,
)


def default_system(N: int):
    case = default_case()
    b = case.booster
    mp = geometry.mass_properties(b.cylinder1.radius, b.cylinder1.half_length,
                                  b.cylinder2.radius, b.cylinder2.half_length, b.thickness,
                                  b.rho)
    w1 = beam.first_bending_frequency(mp.L, b.cylinder1.radius, b.E, b.rho)
    return case, beam_action_system(w1, mp.mass, mp.L, mp.d2, mp.I_cm, case.F0,
                                    case.thrust.K, N)


def timed(fn, *args, **kwargs):
    t0 = time.perf_counter()
    out = fn(*args, **kwargs)
    return out, time.perf_counter() - t0


def scaling(label: str, make, Omega_bar: np.ndarray, gamma: float) -> None:
    print(f"\n[1] {label}: {Omega_bar.size} points, Omega_bar = {np.round(Omega_bar, 3)}")
    print(f"{'N':>3} {'S':>3} {'Hill (s)':>10} {'monodromy (s)':>14} {'Hill/mono':>10} "
          f"{'max |diff|':>11}")
    for N in (2, 4, 6, 10):
        system = make(N)
        Om = Omega_bar * system.omega_1
        mono, t_m = timed(monodromy_exponents, system, Om, gamma)
        red_m = reduced_exponents(mono)
        for S in (4, 8, 12):
            hill, t_h = timed(hill_exponents, system, Om, gamma, S)
            diff = np.max(np.abs(reduced_exponents(hill.alpha) - red_m))
            print(f"{N:>3} {S:>3} {t_h:>10.3f} {t_m:>14.3f} {t_h / t_m:>10.1f} {diff:>11.1e}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=200, help="chart points per axis")
    parser.add_argument("--sample", type=int, default=6, help="baseline subsample size")
    args = parser.parse_args()
    print(f"cpu count {os.cpu_count()}, OMP_NUM_THREADS={os.environ.get('OMP_NUM_THREADS')}, "
          f"OPENBLAS_NUM_THREADS={os.environ.get('OPENBLAS_NUM_THREADS')}")

    scaling("strong thrust, uniform beam p = 20, K = 1, gamma = 0.6",
            lambda N: uniform_beam_system(20.0, 1.0, N), np.array([0.45, 1.2, 2.5, 4.0]), 0.6)
    case, _ = default_system(2)
    w1 = default_system(2)[1].omega_1
    scaling("default case, gamma = 0.05", lambda N: default_system(N)[1],
            np.array([5.0, 300.0, 1000.0, 2000.0]) / w1, 0.05)

    case, system = default_system(10)
    Omega = np.linspace(case.thrust.omega_min, case.thrust.omega_max, args.n)
    gamma = np.linspace(0.0, 0.9, args.n)
    chart, t_chart = timed(stability_chart, system, Omega, gamma)
    rng = np.random.default_rng(0)
    iO = rng.integers(0, args.n, args.sample)
    ig = rng.integers(0, args.n, args.sample)
    hill, t_base = timed(hill_exponents, system, Omega[iO], gamma[ig], 10)
    red = reduced_exponents(hill.alpha)
    flags = np.max(red.imag, axis=1) <= 1e-6
    agree = np.array_equal(flags, chart.stable[ig, iO])
    t_full = t_base / args.sample * Omega.size * gamma.size
    print(f"\n[2] chart, default case, N = 10, {args.n} x {args.n} = {args.n**2} points, "
          f"Omega {Omega[0]:.0f}..{Omega[-1]:.0f} rad/s, gamma 0..0.9")
    print(f"  stability_chart (monodromy, step_phase 0.25): {t_chart:8.2f} s "
          f"({np.mean(~chart.stable) * 100:.2f} % unstable)")
    print(f"  baseline Hill S = 10 per point: {t_base / args.sample:.3f} s/point, "
          f"extrapolated {t_full:8.1f} s")
    print(f"  ratio baseline / chart: {t_full / t_chart:8.1f}   "
          f"flags agree on the {args.sample}-point subsample: {agree}")


if __name__ == "__main__":
    main()
