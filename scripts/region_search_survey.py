"""The region search against a brute-force growth-rate scan on random strongly coupled systems
(docs/theory/floquet.md, "What is still missed").

Each system has 3-5 modes, w uniform in [1, 5] (sorted) and B = gamma r w_a w_b with r
symmetric, entries uniform in [-0.25, 0.25] (numpy ``default_rng(seed)``), M = I, A =
diag(w^2), gamma 0.1 and 0.3, undamped or, with ``--zeta``, C = 2 zeta diag(w).
``instability_regions`` searches Omega in [0.5, 2.2 max w]; the scan evaluates the growth rate
(the monodromy kernel, checked against solve_ivp in tests/test_floquet.py) at ``--points``
(4,000) equally spaced points of that range. A system is listed when a
point with growth rate > 1e-9 lies outside every region found. Prints each such system and
the count, with the search's CPU time.

Usage::

    OPENBLAS_NUM_THREADS=1 PYTHONPATH=src python scripts/region_search_survey.py [--seed 7]
        [--systems 30] [--zeta 0] [--points 4000]
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from flexbooster.floquet import growth_rate, instability_regions


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seed", type=int, default=7)
    parser.add_argument("--systems", type=int, default=30)
    parser.add_argument("--zeta", type=float, default=0.0, help="modal damping ratio")
    parser.add_argument("--points", type=int, default=4000)
    args = parser.parse_args()
    rng = np.random.default_rng(args.seed)
    missed, cpu = 0, 0.0
    for case in range(args.systems):
        n = int(rng.integers(3, 6))
        w = np.sort(rng.uniform(1.0, 5.0, n))
        r = rng.uniform(-0.25, 0.25, (n, n))
        r = 0.5 * (r + r.T)
        for gamma in (0.1, 0.3):
            M, A, B = np.eye(n), np.diag(w**2), gamma * r * np.outer(w, w)
            C = np.diag(2.0 * args.zeta * w) if args.zeta > 0.0 else None
            lo, hi = 0.5, 2.2 * float(w.max())
            start = time.process_time()
            regions = instability_regions(M, C, A, B, lo, hi)
            cpu += time.process_time() - start
            grid = np.linspace(lo, hi, args.points)
            unstable = grid[growth_rate(M, C, A, B, grid) > 1e-9]
            inside = np.zeros(unstable.size, dtype=bool)
            for q in regions:
                inside |= (unstable >= q.omega_lo) & (unstable <= q.omega_hi)
            out = unstable[~inside]
            if out.size:
                missed += 1
                print(f"system {case} ({n} modes, w {np.round(w, 4)}), gamma {gamma}: "
                      f"{out.size} unstable points outside the regions, "
                      f"{out.min():.5f}..{out.max():.5f}")
    print(f"{missed} of {2 * args.systems} systems with an unstable point outside the regions; "
          f"search CPU {cpu:.1f} s")


if __name__ == "__main__":
    main()
