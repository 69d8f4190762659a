"""Benchmark: the severity of every root of the default stability table, vectorised,
against the per-root ``responses.secular_rates`` baseline.

Case: the default booster (M = N = 10 shell modes per cylinder, N = 10 beam modes, S = 10,
R = 4; about 42,000 roots).  Timed: :func:`flexbooster.memo.severity.root_severity` on the whole
table (best of 3), given the table and the parameter function (computed once beforehand).

Baseline, measured in the same run: :func:`flexbooster.memo.responses.secular_rates` (one
Excitation with the beam Floquet vector from Hill's determinant, the harmonics and the modal
projection per root) on a random sample of roots, extrapolated to the whole table (printed).
The rates of the sample are compared with the vectorised ones.

Run:  OPENBLAS_NUM_THREADS=1 python benchmarks/bench_severity.py
"""

from __future__ import annotations

import os
import time

import numpy as np

from flexbooster.case import memo_case
from flexbooster.memo.beam_action import beam_action_analysis
from flexbooster.memo.responses import excitation_parameters, secular_rates
from flexbooster.memo.severity import root_severity
from flexbooster.memo.shell import natural_frequencies
from flexbooster.memo.stability import ShellModes, unstable_frequencies
from flexbooster.model import model_from_case

__all__: list[str] = []

SAMPLE = 40  # roots of the baseline actually computed


def main() -> None:
    model = model_from_case(memo_case())
    shell = natural_frequencies(model)
    params = excitation_parameters(model, beam_action_analysis(model))
    lo, hi = model.omega_range
    n = model.truncation
    table = unstable_frequencies(
        ShellModes(shell.cylinder, shell.j, shell.k, shell.branch, shell.omega_bar), params,
        Omega_bar_range=(lo / model.omega_1, hi / model.omega_1), omega_1=model.omega_1,
        R=n.R, S=n.S, gamma=model.gamma, K=model.K)

    runs, cpu = [], []
    for _ in range(3):
        start, c0 = time.perf_counter(), time.process_time()
        sev = root_severity(model, table, params)
        runs.append(time.perf_counter() - start)
        cpu.append(time.process_time() - c0)
    vectorised = min(runs)

    rng = np.random.default_rng(0)  # half forced roots (severity_rel > 1e-9), half any
    forced = np.flatnonzero(sev.severity_rel > 1e-9)
    pick = np.unique(np.concatenate([rng.choice(forced, SAMPLE // 2, replace=False),
                                     rng.choice(len(table), SAMPLE // 2, replace=False)]))
    rows = table.to_rows()
    start, c0 = time.perf_counter(), time.process_time()
    ref = secular_rates(model, [rows[k] for k in pick], params=params)
    baseline = (time.perf_counter() - start) / pick.size * len(table)
    baseline_cpu = (time.process_time() - c0) / pick.size * len(table)

    got = sev.rate[pick]
    want = np.array([x["secular_rate"] for x in ref])
    big = want > 1e-9 * sev.rate.max()
    err = np.max(np.abs(got[big] - want[big]) / want[big]) if big.any() else 0.0
    print(f"roots: {len(table)}, active (severity_rel >= 1e-6): {int(sev.active.sum())}")
    print(f"vectorised root_severity: best {vectorised:.3f} s wall, {min(cpu):.3f} s CPU "
          f"(runs {', '.join(f'{x:.3f}' for x in runs)})")
    print(f"baseline secular_rates: {pick.size} roots, extrapolated to all: {baseline:.0f} s "
          f"wall, {baseline_cpu:.0f} s CPU")
    print(f"speed-up: {baseline / vectorised:.0f}x wall, {baseline_cpu / min(cpu):.0f}x CPU")
    print(f"sample: {int(big.sum())} forced roots agree to {err:.2e} (relative)")
    print(f"load average: {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
