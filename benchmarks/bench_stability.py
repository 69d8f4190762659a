"""Benchmark: the table of unstable thrust frequencies (memo 7.3), vectorised against a
per-equation brentq baseline.

Case: the default booster with M1 = N1 = M2 = N2 = 30, N = 10, S = 10 (R = 4), over the default
Omega range.  Timed: the shell frequencies and the whole stability table (all 13 families, all
curves, all shell frequencies: bracketing on one scan grid, one vectorised Illinois refinement),
given the beam-action exponents (computed once beforehand; their own benchmark is
bench_beam_action.py).

Baseline, measured in the same run: each equation (one excitation curve against one shell
frequency) solved on its own, as a straightforward implementation would: sample it on the same
scan grid (beta and alpha evaluated for that equation), then scipy.optimize.brentq on every sign
change.  There are about 1.5 million such equations, so the baseline is timed on a random sample
of them and extrapolated (the extrapolation is printed).  The roots of the sample are compared with
the vectorised table.

Run:  python benchmarks/bench_stability.py
"""

from __future__ import annotations

import os
import time

import numpy as np
from scipy.optimize import brentq

from flexbooster.analysis import analyze
from flexbooster.case import load_case, memo_case
from flexbooster.memo.responses import excitation_parameters
from flexbooster.memo.shell import natural_frequencies
from flexbooster.memo.stability import (
    FAMILIES,
    ShellModes,
    excitation,
    excitation_curves,
    unstable_frequencies,
)

__all__: list[str] = []

SAMPLE = 150  # equations of the baseline actually solved


def main() -> None:
    data = memo_case().model_dump(exclude_none=True)
    data["truncation"].update(M1=30, N1=30, M2=30, N2=30, N=10, S=10, R=4)
    case = load_case(data)
    t = case.thrust
    base = analyze(case, stability=False)  # beam action etc., not timed
    params = excitation_parameters(base.model, base.beam_action)
    n = case.truncation

    start = time.perf_counter()
    shell = natural_frequencies(base.model)
    modes = ShellModes(shell.cylinder, shell.j, shell.k, shell.branch, shell.omega_bar)
    table = unstable_frequencies(
        modes, params, Omega_bar_range=(t.omega_min / base.omega_1, t.omega_max / base.omega_1),
        omega_1=base.omega_1, R=n.R, S=n.S, gamma=t.gamma, K=t.K)
    vectorised = time.perf_counter() - start

    curves = excitation_curves(n.R, n.S)
    pairs = [
        (c, m) for c in range(len(curves)) for m in modes.subset(FAMILIES[int(curves.family[c])][1])
    ]
    rng = np.random.default_rng(0)
    sample = [pairs[i] for i in rng.choice(len(pairs), size=SAMPLE, replace=False)]
    grid = np.geomspace(t.omega_min, t.omega_max, 2001) / base.omega_1
    found = []
    start = time.perf_counter()
    for c, m in sample:
        one = type(curves)(*(getattr(curves, f)[c : c + 1] for f in curves.__dataclass_fields__))
        target = modes.omega_bar[m]

        def f(x, one=one, target=target):
            beta, alpha = params(np.atleast_1d(x))
            return excitation(one, np.atleast_1d(x), beta, alpha)[0] - target

        values = f(grid)
        for i in np.flatnonzero(np.sign(values[:-1]) * np.sign(values[1:]) < 0):
            found.append(
                (m, brentq(lambda x, f=f: float(f(x)[0]), grid[i], grid[i + 1], xtol=1e-13))
            )
    per_equation = (time.perf_counter() - start) / SAMPLE
    baseline = per_equation * len(pairs)

    rows = {(int(m), round(float(x), 7)) for m, x in found}
    key = {}
    for d, jj, kk, br, x in zip(
        table.cylinder, table.j, table.k, table.branch, table.Omega_bar, strict=True
    ):
        key.setdefault((int(d), int(jj), int(kk), int(br)), set()).add(round(float(x), 7))
    missing = [
        (m, x)
        for m, x in rows
        if x
        not in key.get(
            (int(modes.cylinder[m]), int(modes.j[m]), int(modes.k[m]), int(modes.branch[m])), set()
        )
    ]
    print(f"BLAS threads: OPENBLAS_NUM_THREADS={os.environ.get('OPENBLAS_NUM_THREADS', 'unset')}")
    print(
        f"equations (curve x shell frequency): {len(pairs)}; roots in the table: {len(table)} "
        f"({int(table.active.sum())} active); shell frequencies: {len(shell)}"
    )
    print(f"vectorised (shell frequencies + whole table): {vectorised:.3f} s")
    print(
        f"baseline: {per_equation * 1e3:.3f} ms per equation on {SAMPLE} sampled equations "
        f"-> {baseline:.1f} s extrapolated to all {len(pairs)}"
    )
    print(f"ratio baseline / vectorised: {baseline / vectorised:.0f}")
    print(f"sampled roots: {len(rows)}, missing from the table: {len(missing)}")


if __name__ == "__main__":
    main()
