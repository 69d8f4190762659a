"""CPU per integration step of one point of the dense full-period monodromy kernel (the damped
steps of a region search) against the estimate's laws (docs/theory/robustness.md, "How far
the estimates are from the run").

For random damped systems of n = 2..40 modes (frequencies 1-20 rad/s, 2 % damping, coupling
5 % of the stiffness), the full-period maps of 64 points at Omega = 2..6 rad/s with the
kernel's own step counts, best of three; printed per step and point with
``cost.dense_step_seconds`` (the law of the damped steps) and ``cost.search_step_seconds``
(the law of the undamped steps, fitted on whole searches). Run on an idle core: the law of the
damped steps is 1.3x a fit of these figures.

Usage::

    OPENBLAS_NUM_THREADS=1 PYTHONPATH=src python scripts/dense_step_cost.py
"""

from __future__ import annotations

import time

import numpy as np

from flexbooster import cost
from flexbooster.floquet.multipliers import period_maps, periodic_system, step_counts


def main() -> None:
    rng = np.random.default_rng(1)
    print(f"{'n':>3} {'steps':>7} {'us/step':>8} {'dense law':>9} {'search law':>10}")
    for n in (2, 5, 11, 19, 30, 40):
        w = np.sort(rng.uniform(1.0, 20.0, n))
        r = 0.05 * rng.uniform(-1.0, 1.0, (n, n))
        r = r + r.T
        system = periodic_system(np.eye(n), np.diag(0.02 * w), np.diag(w**2),
                                 r * np.outer(w, w))
        om = np.linspace(2.0, 6.0, 64)
        steps = step_counts(system, om, step_phase=0.12)
        period_maps(system, om[:4], steps[:4])  # warm
        best = np.inf
        for _ in range(3):
            start = time.process_time()
            period_maps(system, om, steps)
            best = min(best, time.process_time() - start)
        per = best / float(np.sum(steps))
        print(f"{n:3d} {int(np.sum(steps)):7d} {per * 1e6:8.2f} "
              f"{cost.dense_step_seconds(n) * 1e6:9.2f} {cost.search_step_seconds(n) * 1e6:10.2f}",
              flush=True)


if __name__ == "__main__":
    main()
