"""Benchmark: shell natural frequencies, batched eigenproblems against a plain Python loop.

M = N = 100 per cylinder (2 x (100 + 2*100 + 3*100*100) = 60,600 frequencies), memo case,
default method (zero-phase).  The vectorised path is
:func:`flexbooster.memo.shell.composite_frequencies` (coefficients by quadrature, one batched
``eigh`` per system size).  The baseline, measured in the same run, computes the same
coefficients and then loops in Python over every (cylinder, j, k), solving each 2x2 or 3x3
generalized problem with ``scipy.linalg.eigh(K, M)`` and sorting, as a straightforward
implementation would.  Both results are compared before the times are printed.

Run:  python benchmarks/bench_shell.py   (prints both times, the ratio and the agreement)
"""

from __future__ import annotations

import os
import time

import numpy as np
import scipy.linalg

from flexbooster.case import memo_case
from flexbooster.memo.beam import first_bending_frequency
from flexbooster.memo.shell import composite_frequencies, cylinder_coefficients
from flexbooster.memo.shell_coefficients import shell_parameters

__all__: list[str] = []

M = N = 100


def _arguments():
    case = memo_case()
    b = case.booster
    R1, L1 = b.cylinder1.radius, b.cylinder1.half_length
    R2, L2 = b.cylinder2.radius, b.cylinder2.half_length
    w1 = first_bending_frequency(L1 + L2, R1, b.E, b.rho)
    return (R1, L1, R2, L2, b.thickness, b.E, b.nu, b.rho, w1)


def vectorised(args):
    return composite_frequencies(*args, M, N, M, N, "zero-phase").omega_bar


def loop(args):
    """Same coefficients, then one scipy generalized eigenproblem per (cylinder, j, k)."""
    p = shell_parameters(*args)
    out = []
    for d in (1, 2):
        coef = cylinder_coefficients(p, d, M, N, "zero-phase")
        lam = p.lam(d)
        for k in range(1, N + 1):
            out.append(np.sqrt(lam**2 * k**2 / (2 * (1 + p.nu) * p.mu)))
        m2, k2 = coef.matrices_j0()
        for j in range(M):
            w = scipy.linalg.eigh(k2[j], np.diag(np.diag(m2[j])), eigvals_only=True)
            out.extend(np.sqrt(np.sort(w)))
        m3, k3 = coef.matrices_jk()
        for j in range(M):
            for k in range(N):
                w = scipy.linalg.eigh(k3[j, k], np.diag(np.diag(m3[j, k])), eigvals_only=True)
                out.extend(np.sqrt(np.sort(w)))
    return np.asarray(out)


def best_of(func, args, repeat):
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        result = func(args)
        times.append(time.perf_counter() - t0)
    return min(times), result


def main() -> None:
    args = _arguments()
    vectorised(args)  # warm-up (imports, quadrature nodes)
    t_vec, fast = best_of(vectorised, args, 5)
    t_loop, slow = best_of(loop, args, 1)
    agree = np.max(np.abs(fast / slow - 1.0))
    print(f"shell frequencies, M = N = {M} per cylinder: {fast.size} frequencies "
          f"(os.cpu_count() = {os.cpu_count()})")
    print(f"  vectorised (batched eigh), best of 5 : {t_vec:8.3f} s")
    print(f"  plain Python loop (scipy eigh each)  : {t_loop:8.3f} s")
    print(f"  ratio loop / vectorised              : {t_loop / t_vec:8.1f}")
    print(f"  max relative difference              : {agree:8.1e}")


if __name__ == "__main__":
    main()
