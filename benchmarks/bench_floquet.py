"""Benchmark: flexbooster.floquet.instability_regions on the beam-action system of the memo case.

Times, in the same run,
  1. the candidate-driven region search (``instability_regions``) on the normalised beam-action
     system (N = 10 elastic modes + rigid pitch) over the default Omega range
     t.omega_min..t.omega_max at gamma = t.gamma (target < 1 s);
  2. the baseline: a uniform monodromy scan (``growth_rate`` on a grid) fine enough to find the
     same bands: its spacing is a third of the narrowest region found, so that each region has
     at least two grid points inside; timed on a sample of points and extrapolated to the whole
     grid (target ratio >= 50).
It also checks on the sample that the scan sees no instability outside the regions found, and
compares the regions with those of the search before the bands3 speed-ups (commit 1254c51,
``benchmarks/reference/bench_floquet_regions_1254c51.json``): every region found again, no new
one, and the largest differences of the edges (relative to the centre, the toolkit's rtol),
of the widths and of the growth rates.  With ``--baseline REV`` (default: that commit) it also
times the search of commit REV in the same run: its ``src`` is exported with ``git archive``
into a temporary folder (the repository is only read) and both searches run alternately in
child processes (best of ``--repeat`` each, wall and CPU).

Usage::

    OPENBLAS_NUM_THREADS=1 PYTHONPATH=src python benchmarks/bench_floquet.py [--repeat 3]
        [--baseline 1254c51 | --baseline none]
"""

from __future__ import annotations

import argparse
import io
import json
import os
import subprocess
import sys
import tarfile
import tempfile
import time
from pathlib import Path

import numpy as np

import flexbooster
from flexbooster.floquet import growth_rate, instability_regions
from flexbooster.memo.beam_action import beam_system
from flexbooster.model import model_from_case


def default_system(N: int = 10):
    """(M, C, A, B), Omega_bar range, omega_1 and gamma of the memo case's beam action."""
    case = flexbooster.memo_case()
    t = case.thrust
    sys_ = beam_system(model_from_case(case), N)
    w1 = float(sys_.omega_1)
    # normalised time tau = omega_1 t:  q'' + [A0 - gamma cos(Omega_bar tau) B] q = 0
    n = N + 1
    M, C, A = np.eye(n), None, sys_.A0
    B = -t.gamma * sys_.B
    return (M, C, A, B), t.omega_min / w1, t.omega_max / w1, w1, t.gamma


REFERENCE = Path(__file__).parent / "reference" / "bench_floquet_regions_1254c51.json"
ROOT = Path(__file__).resolve().parents[1]

#: The search in a child process: argv = src folder, benchmarks folder, repeat.
_CHILD = r"""
import sys, time
sys.path[:0] = [sys.argv[1], sys.argv[2]]
from bench_floquet import default_system
from flexbooster.floquet import instability_regions
mats, lo, hi, w1, gamma = default_system(10)
wall = cpu = float("inf")
for _ in range(int(sys.argv[3])):
    t0, c0 = time.perf_counter(), time.process_time()
    regions = instability_regions(*mats, lo, hi)
    wall, cpu = min(wall, time.perf_counter() - t0), min(cpu, time.process_time() - c0)
print(len(regions), wall, cpu)
"""


def child_search(src: Path, repeat: int) -> tuple[int, float, float]:
    """(regions, best wall, best CPU) of the search with the package in ``src``."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    out = subprocess.run([sys.executable, "-c", _CHILD, str(src), str(Path(__file__).parent),
                          str(repeat)], env=env, check=True, capture_output=True, text=True)
    n, wall, cpu = out.stdout.split()
    return int(n), float(wall), float(cpu)


def same_run_baseline(rev: str, repeat: int, rounds: int = 2) -> None:
    """Time the search of commit ``rev`` and of this tree alternately, print both."""
    data = subprocess.run(["git", "-C", str(ROOT), "archive", rev, "src"], check=True,
                          capture_output=True).stdout
    with tempfile.TemporaryDirectory() as tmp:
        with tarfile.open(fileobj=io.BytesIO(data)) as tar:
            tar.extractall(tmp, filter="data")
        runs: dict = {rev: [], "this tree": []}
        for _ in range(rounds):
            runs[rev].append(child_search(Path(tmp) / "src", repeat))
            runs["this tree"].append(child_search(ROOT / "src", repeat))
    best = {k: (v[0][0], min(r[1] for r in v), min(r[2] for r in v)) for k, v in runs.items()}
    for k, (n, wall, cpu) in best.items():
        print(f"  search at {k}: {n} regions, {wall:.3f} s wall, {cpu:.3f} s CPU "
              f"(best of {rounds} x {repeat}, child processes)")
    print(f"  speed-up (CPU) {best[rev][2] / best['this tree'][2]:.2f}, (wall) "
          f"{best[rev][1] / best['this tree'][1]:.2f}; load average {load_average()}")


def load_average() -> str:
    """The 1-minute load average (Linux /proc/loadavg), or "n/a"."""
    try:
        return Path("/proc/loadavg").read_text().split()[0]
    except OSError:
        return "n/a"


def compare_regions(regions, reference: list[dict]) -> dict:
    """Match the regions to the reference ones by (kind, modes, order) and nearest edges.

    Returns the counts (missing, new) and the largest differences: edges |d| / omega_center,
    widths |d| / width, growth rates |d| / growth (each with the region it occurs in), the
    last two also over the regions at least 1e-12 of their centre wide (narrower ones have
    edges a few ulp apart: their widths are round-off-limited, docs/theory/floquet.md).
    """
    def key(kind, modes, order):
        return kind, tuple(int(m) for m in modes), int(order)

    new = [r for r in regions]
    worst = {"edge": (0.0, None), "width": (0.0, None), "growth": (0.0, None),
             "width_1e-12": (0.0, None), "growth_1e-12": (0.0, None)}
    missing = 0
    for ref in reference:
        same = [r for r in new if key(r.kind, r.modes, r.order)
                == key(ref["kind"], ref["modes"], ref["order"])]
        if not same:
            missing += 1
            continue
        r = min(same, key=lambda q: abs(q.omega_lo - ref["omega_lo"]))
        new.remove(r)
        label = f"{r.kind} {r.modes} j = {r.order}"
        w_ref = ref["omega_hi"] - ref["omega_lo"]
        diffs = {"edge": max(abs(r.omega_lo - ref["omega_lo"]), abs(r.omega_hi - ref["omega_hi"]))
                 / ref["omega_center"],
                 "width": abs(r.width - w_ref) / w_ref,
                 "growth": abs(r.growth_rate_max - ref["growth_rate_max"])
                 / ref["growth_rate_max"]}
        if w_ref >= 1e-12 * ref["omega_center"]:  # widths above the round-off of the edges
            diffs["width_1e-12"], diffs["growth_1e-12"] = diffs["width"], diffs["growth"]
        for name, d in diffs.items():
            if d > worst[name][0]:
                worst[name] = (d, label)
    return {"missing": missing, "new": len(new), **worst}


def best_of(fn, repeat: int, cpu: list | None = None):
    """Best wall time (perf_counter) of ``repeat`` runs; the best CPU time goes to ``cpu``."""
    best, best_cpu, out = np.inf, np.inf, None
    for _ in range(repeat):
        t0, c0 = time.perf_counter(), time.process_time()
        out = fn()
        best = min(best, time.perf_counter() - t0)
        best_cpu = min(best_cpu, time.process_time() - c0)
    if cpu is not None:
        cpu.append(best_cpu)
    return out, best


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--sample", type=int, default=200, help="scan points timed")
    ap.add_argument("--baseline", default="1254c51",
                    help="commit whose search is timed in the same run ('none': skip)")
    args = ap.parse_args()
    mats, lo, hi, w1, gamma = default_system(10)
    cpu: list = []
    regions, t_search = best_of(lambda: instability_regions(*mats, lo, hi), args.repeat, cpu)
    print(f"memo case, N = 10 (n = 11), gamma = {gamma}, Omega_bar = {lo:.4f}..{hi:.3f} "
          f"(Omega = {lo * w1:.1f}..{hi * w1:.1f} rad/s), omega_1 = {w1:.3f} rad/s")
    print(f"region search: {len(regions)} regions in {t_search:.3f} s wall, {cpu[0]:.3f} s CPU "
          f"(best of {args.repeat}); load average {load_average()}")
    print(f"{'kind':>10} {'modes':>8} {'j':>2} {'Omega_lo (rad/s)':>17} {'Omega_hi (rad/s)':>17}"
          f" {'width/centre':>12} {'max growth (1/s)':>16}")
    for r in regions:
        print(f"{r.kind:>10} {str(r.modes):>8} {r.order:>2} {r.omega_lo * w1:17.9f} "
              f"{r.omega_hi * w1:17.9f} {r.width / r.omega_center:12.3e} "
              f"{r.growth_rate_max * w1:16.6e}")
    n_narrow = sum(r.width < 6e-8 / r.order * r.omega_center for r in regions)
    print(f"{n_narrow} regions narrower than the monodromy floor 6e-8 / j (harmonic-balance pair)")
    # the scan baseline resolves the narrowest region the monodromy search itself can see
    widths = np.array([r.width for r in regions if r.width >= 6e-8 / r.order * r.omega_center])
    narrow = float(np.min(widths)) if widths.size else (hi - lo) / 1e4
    spacing = narrow / 3.0
    n_grid = int(np.ceil((hi - lo) / spacing)) + 1
    rng = np.random.default_rng(0)
    sample = np.sort(rng.uniform(lo, hi, args.sample))
    g, t_sample = best_of(lambda: growth_rate(*mats, sample), 1)
    t_scan = t_sample * n_grid / sample.size
    inside = np.zeros(sample.size, dtype=bool)
    for r in regions:
        inside |= (sample >= r.omega_lo) & (sample <= r.omega_hi)
    print(f"scan baseline: spacing {spacing:.3e} (a third of the narrowest region) -> "
          f"{n_grid} points; {sample.size} timed in {t_sample:.3f} s -> {t_scan:.1f} s "
          "extrapolated")
    print(f"ratio scan / search = {t_scan / t_search:.0f}  (targets: search < 1 s, ratio >= 50)")
    print(f"sample points unstable outside the regions: {int(np.sum((g > 1e-9) & ~inside))}")
    ref = json.loads(REFERENCE.read_text())
    c = compare_regions(regions, ref["regions"])
    print(f"vs the search at {ref['commit']} ({len(ref['regions'])} regions, {REFERENCE.name}): "
          f"{c['missing']} missing, {c['new']} new")
    for name, text in (("edge", "edges |d| / centre"), ("width", "widths |d| / width"),
                       ("growth", "growth rates |d| / growth"),
                       ("width_1e-12", "widths |d| / width, regions >= 1e-12 of the centre"),
                       ("growth_1e-12", "growth rates |d| / growth, same regions")):
        d, where = c[name]
        print(f"  max {text}: {d:.2e}" + (f" ({where})" if where else ""))
    if args.baseline != "none":
        print(f"same-run baseline: the search at {args.baseline} against this tree")
        same_run_baseline(args.baseline, args.repeat)


if __name__ == "__main__":
    main()
