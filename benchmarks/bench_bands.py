"""Benchmark: the band search and the band charts on the memo case.

Times, in the same run (best of ``--repeat``, wall and CPU):
  1. the pipeline's beam-action band search (``beam_action_bands`` over
     [max(omega_min, omega_1 / 4), omega_max] at the case's gamma) against the baseline, a
     uniform monodromy scan (``monodromy_exponents``, the beam-action module's own kernel) of
     ``--scan`` points over the same range, which the exact band search replaced (20,000
     points; it misses the regions narrower than its spacing: the count is printed);
  2. the beam-action chart (``charts.beam_action_chart``: boundaries from
     ``floquet.region_boundaries``) against the monodromy grid chart it replaced
     (``stability_chart`` on 80 log-spaced Omega x 30 gamma in [0, 0.9], step_phase 0.25);
  3. the pitch bands and the pitch band chart;
  4. one ``analyze(memo_case())``, and the same without figures.

Usage::

    OPENBLAS_NUM_THREADS=1 PYTHONPATH=src python benchmarks/bench_bands.py [--repeat 2] \
        [--scan 20000]
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from flexbooster.analysis import analyze
from flexbooster.case import memo_case
from flexbooster.memo import charts
from flexbooster.memo.beam_action import (
    BAND_OMEGA_BAR_MIN,
    beam_action_bands,
    beam_system,
    monodromy_exponents,
    stability_chart,
)
from flexbooster.memo.pitch import pitch_analysis
from flexbooster.model import model_from_case


def best_of(fn, repeat: int):
    """(result, best wall time, best CPU time) of ``repeat`` runs."""
    best, best_cpu, out = np.inf, np.inf, None
    for _ in range(repeat):
        t0, c0 = time.perf_counter(), time.process_time()
        out = fn()
        best = min(best, time.perf_counter() - t0)
        best_cpu = min(best_cpu, time.process_time() - c0)
    return out, best, best_cpu


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=2)
    parser.add_argument("--scan", type=int, default=20_000)
    args = parser.parse_args()
    case = memo_case()
    model = model_from_case(case)
    system = beam_system(model)
    w1 = system.omega_1
    lo = max(model.omega_range[0], BAND_OMEGA_BAR_MIN * w1)
    hi = model.omega_range[1]
    g = model.gamma

    print(f"memo case: omega_1 = {w1:.6g} rad/s, band range [{lo:.6g}, {hi:.6g}] rad/s")
    bands, t_b, c_b = best_of(lambda: beam_action_bands(system, g, omega_min=lo, omega_max=hi),
                              args.repeat)
    grid = np.linspace(lo, hi, args.scan)

    def scan():
        alpha = monodromy_exponents(system, grid, np.full(grid.shape, g))
        return np.max(np.abs(alpha.imag), axis=1) > 1e-9

    flags, t_s, c_s = best_of(scan, 1)
    seen = sum(bool(np.any(flags[(grid >= b.Omega_lo) & (grid <= b.Omega_hi)])) for b in bands)
    print(f"1. band search: {len(bands)} bands, {t_b:.3f} s wall ({c_b:.3f} s CPU)")
    print(f"   baseline scan of {args.scan} points: {t_s:.3f} s wall ({c_s:.3f} s CPU), "
          f"sees {seen} of the {len(bands)} bands; ratio scan / search = {t_s / t_b:.1f}")

    new, t_new, c_new = best_of(lambda: charts.beam_action_chart(model), args.repeat)
    _, t_old, c_old = best_of(lambda: stability_chart(
        system, np.geomspace(*model.omega_range, 80), np.linspace(0.0, 0.9, 30),
        step_phase=0.25), args.repeat)
    print(f"2. beam-action chart from boundaries: {len(new.regions)} regions, {t_new:.3f} s "
          f"wall ({c_new:.3f} s CPU); old 80 x 30 monodromy grid: {t_old:.3f} s wall "
          f"({c_old:.3f} s CPU); ratio old / new = {t_old / t_new:.2f}")

    _, t_p, _ = best_of(lambda: pitch_analysis(model.Omega, model.omega_psi, g), args.repeat)
    _, t_pc, _ = best_of(lambda: charts.pitch_band_chart(model), args.repeat)
    print(f"3. pitch analysis with bands: {t_p:.3f} s; pitch band chart: {t_pc:.3f} s")

    _, t_a, c_a = best_of(lambda: analyze(case), args.repeat)
    _, t_n, c_n = best_of(lambda: analyze(case, figures=False), args.repeat)
    print(f"4. analyze(memo_case()): {t_a:.3f} s wall ({c_a:.3f} s CPU); without figures "
          f"{t_n:.3f} s wall ({c_n:.3f} s CPU)")
    print(f"   before the band search (none, the old chart instead of the two new ones), "
          f"estimated from the CPU times above: {c_a - c_b - c_new + c_old:.3f} s CPU")


if __name__ == "__main__":
    main()
