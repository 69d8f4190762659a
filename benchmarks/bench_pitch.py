"""Benchmark: the characteristic exponent beta on a 1000 x 1000 (a, q) grid.

Times, in the same run,
  * Hill's determinant (``characteristic_exponent(method="hill")``), vectorised,
  * the vectorised Magnus-4 monodromy (``method="floquet"``),
  * the baseline: one scipy.integrate.solve_ivp (DOP853, rtol 1e-10, atol 1e-12) per grid
    point over one period [0, pi], timed on a random subsample of points and extrapolated to
    the full grid (the full baseline would take tens of minutes),
and prints the times, the ratios and the largest differences between the methods on the
subsample.  Usage::

    python benchmarks/bench_pitch.py [--n 1000] [--sample 300] [--range memo|wide]

``memo``: 0 < a <= 1, 0 <= q <= 0.05 (eq. 4.2-5, plus the edge of the first tongue);
``wide``: -1 <= a <= 10, 0 <= q <= 5 (five tongues).
"""

from __future__ import annotations

import argparse
import os
import time

import numpy as np
from scipy.integrate import solve_ivp

from flexbooster.floquet import characteristic_exponent, floquet_discriminant


def baseline_discriminant(a: float, q: float) -> float:
    """cos(pi beta) = y1(pi) by one solve_ivp call (the per-point baseline)."""

    def rhs(t: float, y: np.ndarray) -> list[float]:
        return [y[1], -(a - 2.0 * q * np.cos(2.0 * t)) * y[0]]

    sol = solve_ivp(rhs, (0.0, np.pi), [1.0, 0.0], method="DOP853", rtol=1e-10, atol=1e-12)
    return float(sol.y[0, -1])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=1000, help="grid points per axis")
    parser.add_argument("--sample", type=int, default=300, help="baseline subsample size")
    parser.add_argument("--range", choices=("memo", "wide"), default="memo")
    parser.add_argument("--skip-floquet", action="store_true")
    args = parser.parse_args()

    if args.range == "memo":
        a_axis, q_axis = np.linspace(1e-3, 1.0, args.n), np.linspace(0.0, 0.05, args.n)
    else:
        a_axis, q_axis = np.linspace(-1.0, 10.0, args.n), np.linspace(0.0, 5.0, args.n)
    a, q = np.meshgrid(a_axis, q_axis)
    print(
        f"grid {args.n} x {args.n} = {a.size} points, range {args.range}; "
        f"cpu count {os.cpu_count()}, OMP_NUM_THREADS={os.environ.get('OMP_NUM_THREADS')}"
    )

    t0 = time.perf_counter()
    beta_hill = characteristic_exponent(a, q, "hill")
    t_hill = time.perf_counter() - t0
    print(f"hill     : {t_hill:8.3f} s for the grid")

    t_floq = None
    if not args.skip_floquet:
        t0 = time.perf_counter()
        beta_floq = characteristic_exponent(a, q, "floquet")
        t_floq = time.perf_counter() - t0
        print(f"floquet  : {t_floq:8.3f} s for the grid")
        print(
            f"  max |beta_hill - beta_floquet| on the grid: "
            f"{np.max(np.abs(beta_hill - beta_floq)):.2e}"
        )

    rng = np.random.default_rng(12345)
    idx = rng.choice(a.size, size=min(args.sample, a.size), replace=False)
    a_s, q_s = a.ravel()[idx], q.ravel()[idx]
    t0 = time.perf_counter()
    d_base = np.array([baseline_discriminant(x, y) for x, y in zip(a_s, q_s, strict=True)])
    t_sample = time.perf_counter() - t0
    t_base = t_sample / idx.size * a.size
    print(
        f"baseline : {t_sample:8.3f} s for {idx.size} points -> {t_base:8.1f} s extrapolated "
        f"to the grid ({t_sample / idx.size * 1e3:.2f} ms per point)"
    )
    d_hill = floquet_discriminant(a_s, q_s, "hill")
    rel = np.abs(d_hill - d_base) / np.maximum(1.0, np.abs(d_base))
    print(
        f"  max |cos(pi beta)| difference hill vs baseline on the sample, relative to "
        f"max(1, |cos(pi beta)|): {np.max(rel):.2e} (baseline rtol 1e-10)"
    )
    print(f"speed-up hill    : {t_base / t_hill:10.0f} x")
    if t_floq is not None:
        print(f"speed-up floquet : {t_base / t_floq:10.0f} x")


if __name__ == "__main__":
    main()
