"""Benchmark: the vehicle-regions stage of ``examples/two-stage-liquid.toml`` against a baseline
commit, same run: the search without the difference candidates of canonical harmonics.

Every harmonic k >= 2 of the vehicle is a canonical system (M, A, B symmetric, M and A
positive definite), where a difference centre (omega_k - omega_i) / j opens no region (Krein
1955; docs/theory/floquet.md sec. 4); the baseline (:data:`BASELINE`) examined those
candidates. ``analyze_vehicle_regions(case)`` (the stage ``flexbooster run`` runs: k = 1..20,
0.5..60 Hz, damping 0.01) is timed in a child process per tree, alternating (``--rounds``),
CPU seconds of the call alone. Printed: the best CPU of each, the ratio baseline / now, the
monodromy candidates each examined, and whether the regions are the same (kind, k, modes,
order and edges to 1e-12 relative).

Run from the repository root (the baseline takes about two minutes a round)::

    .venv/bin/python benchmarks/bench_canonical.py [--rounds 1] [--baseline REV]
"""

from __future__ import annotations

import argparse
import os

from baseline_checkout import ROOT, alternate, best, child_json

__all__ = ["BASELINE", "EXAMPLE", "main"]

#: The code before the canonical systems' difference candidates were left out.
BASELINE = "287c7c5"
#: The case timed.
EXAMPLE = ROOT / "examples" / "two-stage-liquid.toml"

CHILD = """
import json, sys, time
import numpy as np
import flexbooster.floquet.regions as regions
from flexbooster.analysis import analyze_vehicle_regions
from flexbooster.case import load_case
case = load_case(sys.argv[1])
count = [0]
original = regions._undamped_search
def counting(system, w, cand, *args, **kw):
    count[0] += int(np.count_nonzero(cand["mono"]))
    return original(system, w, cand, *args, **kw)
regions._undamped_search = counting
start = time.process_time()
found = analyze_vehicle_regions(case)
cpu = time.process_time() - start
print(json.dumps({"cpu": cpu, "candidates": count[0], "regions": [
    [r.k, r.kind, [m.index for m in r.modes], r.order, r.Omega_lo, r.Omega_hi]
    for r in found.regions]}))
"""


def _same(a: list, b: list) -> bool:
    """The same regions: labels equal, edges within 1e-12 relative."""
    return len(a) == len(b) and all(
        x[:4] == y[:4] and all(abs(u - v) <= 1e-12 * max(abs(u), abs(v)) for u, v in
                               zip(x[4:], y[4:], strict=True)) for x, y in zip(a, b, strict=True))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rounds", type=int, default=1)
    ap.add_argument("--baseline", default=BASELINE)
    opts = ap.parse_args()

    runs = alternate(opts.baseline, opts.rounds,
                     lambda src: child_json(src, CHILD, str(EXAMPLE)))
    old, new = best(runs)
    print(f"vehicle-regions stage of {EXAMPLE.name}, best CPU of {opts.rounds}, load average "
          f"{os.getloadavg()[0]:.1f}: baseline {opts.baseline} {old:.2f} s "
          f"({runs['old'][0]['candidates']} monodromy candidates), now {new:.2f} s "
          f"({runs['new'][0]['candidates']}); baseline / now {old / new:.2f}")
    same = _same(runs["old"][0]["regions"], runs["new"][0]["regions"])
    print(f"  regions the same (labels, edges to 1e-12): {'yes' if same else 'NO'} "
          f"({len(runs['new'][0]['regions'])} regions)")


if __name__ == "__main__":
    main()
