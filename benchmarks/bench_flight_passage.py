"""Benchmark: flexbooster.flight's sweep through a resonance (the non-stationary peak).

Times, in the same run,
  1. ``crossing_peak_ratio`` of a mode drifting through a fixed oscillation frequency
     (zeta = 0.02, eta = 1e-4 and 1e-5: about 1e5 and 1e6 steps), whose recursion
     x_{n+1} = Phi_n x_n + g_n runs as a vectorised affine scan;
  2. the baseline: the same recursion (the same step maps, the same forcing samples) as a
     plain Python loop over the steps, timed on the first 2e4 steps and extrapolated.
It prints both times, their ratio, and checks on the loop's steps that both give the same
states (largest difference relative to the largest state).

Usage::

    OPENBLAS_NUM_THREADS=1 PYTHONPATH=src python benchmarks/bench_flight_passage.py [--repeat 3]
"""

from __future__ import annotations

import argparse
import math
import time

import numpy as np

from flexbooster.flight import SWEEP_WINDOW, crossing_peak_ratio, step_maps
from flexbooster.flight.passage import sweep_response

LOOP_STEPS = 20_000


def loop_states(Phi: np.ndarray, g: np.ndarray, x0: np.ndarray, n: int) -> np.ndarray:
    """The baseline: x_{n+1} = Phi_n x_n + g_n one step at a time (plain Python floats)."""
    out = np.empty((n + 1, 2))
    q, v = float(x0[0]), float(x0[1])
    out[0] = q, v
    P = Phi[:n].tolist()
    G = g[:n].tolist()
    for i in range(n):
        (a, b), (c, d) = P[i]
        e, f = G[i]
        q, v = a * q + b * v + e, c * q + d * v + f
        out[i + 1] = q, v
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    zeta, w = 0.02, 1.0
    for eta in (1e-4, 1e-5):
        kw = dict(zeta=zeta, omega=w, omega_rate=eta * w * w, Omega_rate=0.0)
        best = float("inf")
        for _ in range(args.repeat):
            t0 = time.perf_counter()
            ratio = crossing_peak_ratio(**kw)
            best = min(best, time.perf_counter() - t0)
        # the same recursion's inputs, rebuilt as crossing_peak_ratio builds them
        span = SWEEP_WINDOW * (zeta + math.sqrt(eta)) / (eta * w)
        before, after = min(span, 0.5 / eta), span
        duration = before + after
        t, q, _ = sweep_response(omega=w - eta * before, omega_end=w + eta * after, zeta=zeta,
                                 force=1.0, Omega_start=w, Omega_end=w, duration=duration)
        steps = t.size - 1
        h = duration / steps
        Phi, Ga, Gb = step_maps(w - eta * before + eta * (t[:-1] + 0.5 * h), zeta, h)
        u = np.cos(w * t)
        g = Ga * u[:-1, None] + Gb * u[1:, None]
        H = 1.0 / ((w - eta * before) ** 2 - w * w + 2j * zeta * (w - eta * before) * w)
        x0 = np.array([H.real, (1j * w * H).real])
        n = min(LOOP_STEPS, steps)
        t0 = time.perf_counter()
        ref = loop_states(Phi, g, x0, n)
        loop = (time.perf_counter() - t0) * steps / n
        diff = np.max(np.abs(ref[:, 0] - q[:n + 1])) / np.max(np.abs(ref[:, 0]))
        print(f"eta = {eta:.0e}: {steps} steps, ratio {ratio:.6f}")
        print(f"  scan (crossing_peak_ratio, best of {args.repeat}): {best:.3f} s wall")
        print(f"  Python loop, extrapolated from {n} steps: {loop:.3f} s wall")
        print(f"  speed-up {loop / best:.1f}; same states to {diff:.1e} (relative)")


if __name__ == "__main__":
    main()
