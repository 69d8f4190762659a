"""Benchmark: flexbooster.dynamics.vehicle_regions on the memo case's vehicle.

The vehicle of ``flexbooster.model.vehicle_from_case(flexbooster.memo_case())`` (the memo's
two cylinders, memo bulkhead, shear-diaphragm ends, inertia relief), F0 = 2.8 MN, k = 1..20
(k = 1: bending with the gimbal gain K = 0.5 of the memo case), 20 modes per k, Omega =
5..2000 rad/s, gamma = 0.05, damping ratio 0.01 (the memo case).  Times, in the same run,

  1. the map ``vehicle_regions`` (the deliverable: < 5 s), with the k = 0 forced resonances,
     and its k = 1 part alone (the cost that k = 1 adds to ``flexbooster run``);
  2. the baseline: a uniform monodromy scan (``floquet.growth_rate`` of the full damped
     20-mode system of every k) with a spacing of a third of the narrowest *first-order*
     undamped region (Bolotin's |B_ii| / omega_i and Hsu's sqrt(|B_ik B_ki| / (omega_i
     omega_k)), the coarsest grid that puts two points in every first-order region that
     damping could leave; the higher-order ones are narrower still, so this favours the scan),
     timed on a sample of points per k and extrapolated;
  3. ``--hard``: a case where damping leaves a region (k = 3, 10 modes, Omega 10..300 rad/s,
     gamma = 0.5, zeta = 0.001) with the damping filter (default) and without
     (``damping_margin=None``), to show what the filter alone saves;
  4. ``--cost``: the up-front estimate (``flexbooster.cost.search_seconds``) against the
     measured search of undamped k = 3 harmonics with 4, 8 and 12 modes (``--cost-modes``)
     and of the damped harmonics that are not certified: the README example's k = 2 and the
     free-free default vehicle's k = 1 (20 modes); the ratio estimate / measured;
  5. ``--limits``: a harmonic whose resonance centres of every order in the range number
     over 200,000 (the README example, k = 2, 8 modes, undamped, Omega 1..2000 rad/s): the
     candidates examined (the orders whose width estimate passes the floor) and the time of
     the search.

Usage::

    OPENBLAS_NUM_THREADS=1 PYTHONPATH=src python benchmarks/bench_vehicle_regions.py \
        [--n-modes 20] [--k-max 20] [--repeat 3] [--sample 16] [--hard] [--cost] [--limits]
"""

from __future__ import annotations

import argparse
import time
import tomllib
from pathlib import Path

import numpy as np

import flexbooster
from flexbooster import floquet
from flexbooster.case import load_case, memo_case_text
from flexbooster.cost import search_seconds
from flexbooster.dynamics import vehicle_regions
from flexbooster.floquet import growth_rate
from flexbooster.model import vehicle_from_case

F0, GAMMA, LO, HI = 2.8e6, 0.05, 5.0, 2000.0

#: The README's ``[vehicle]`` example (appended to the memo case).
README_VEHICLE = """
[vehicle]
E = "70 GPa"
nu = 0.3
rho = "2700 kg/m^3"
aft_end = "free"
fwd_end = "free"
theory = "sanders"
k_max = 20
[[vehicle.segments]]
kind = "cylinder"
radius = "1.5 m"
length = "6 m"
thickness = "16 mm"
[[vehicle.segments]]
kind = "cone"
radius_aft = "1.5 m"
radius_fwd = "1.0 m"
length = "1 m"
thickness = "16 mm"
junction = "continuous"
"""
#: The default vehicle with free ends.
FREE_ENDS = """
[vehicle]
aft_end = "free"
fwd_end = "free"
"""


def best_of(fn, repeat: int):
    """Best wall time (perf_counter) and CPU time (process_time) of ``repeat`` runs."""
    best, best_cpu, out = np.inf, np.inf, None
    for _ in range(repeat):
        t0, c0 = time.perf_counter(), time.process_time()
        out = fn()
        best = min(best, time.perf_counter() - t0)
        best_cpu = min(best_cpu, time.process_time() - c0)
    return out, best, best_cpu


def first_order_widths(h, gamma: float) -> np.ndarray:
    """First-order undamped widths (rad/s) of the simple and combination regions of h that are
    wider than the toolkit's detection floor (1e-7 of their centre, floquet.md sec. 6)."""
    w = h.omega_loaded
    B = gamma * np.abs(h.excitation)
    ii, kk = np.triu_indices(w.size, 1)
    width = np.concatenate([np.diag(B) / w, np.sqrt(B[ii, kk] * B[kk, ii] / (w[ii] * w[kk])),
                            np.sqrt(B[ii, kk] * B[kk, ii] / (w[ii] * w[kk]))])
    centre = np.concatenate([2.0 * w, w[ii] + w[kk], np.abs(w[kk] - w[ii])])
    keep = (width > 1e-7 * centre) & (centre + width >= LO) & (centre - width <= HI)
    return width[keep]


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--n-modes", type=int, default=20)
    ap.add_argument("--k-max", type=int, default=20)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--sample", type=int, default=16, help="scan points timed per k")
    ap.add_argument("--hard", action="store_true", help="also the filter-only case")
    ap.add_argument("--cost", action="store_true", help="also the cost model check")
    ap.add_argument("--cost-modes", type=int, nargs="+", default=[4, 8, 12])
    ap.add_argument("--limits", action="store_true", help="a former candidate-count case")
    args = ap.parse_args()
    print(f"load average {Path('/proc/loadavg').read_text().split()[:3]} at start")
    veh = vehicle_from_case(flexbooster.memo_case())
    kw = dict(F0=F0, gamma=GAMMA, omega_min=LO, omega_max=HI, k_min=1, k_max=args.k_max,
              n_modes=args.n_modes, gimbal_gain=0.5)
    res, t_map, c_map = best_of(lambda: vehicle_regions(veh, **kw), args.repeat)
    print(f"memo case vehicle, k = 1..{args.k_max}, {args.n_modes} modes per k, "
          f"Omega = {LO:g}..{HI:g} rad/s, gamma = {GAMMA}, zeta = 0.01")
    _, t_10, c_10 = best_of(lambda: vehicle_regions(veh, **{**kw, "k_max": 10}), args.repeat)
    print(f"k = 1..10, same run: {t_10:.3f} s wall, {c_10:.3f} s CPU")
    _, t_k1, c_k1 = best_of(lambda: vehicle_regions(veh, **{**kw, "k_max": 1}, axial=False),
                            args.repeat)
    print(f"k = 1 alone (bending, gimbal gain 0.5): {t_k1:.3f} s wall, {c_k1:.3f} s CPU")
    print(f"map: {len(res.regions)} regions, {sum(c.certified for c in res.certificates)} of "
          f"{len(res.certificates)} harmonics certified stable, "
          f"{len(res.forced_axial.resonances)} k = 0 forced resonances; "
          f"{t_map:.3f} s wall, {c_map:.3f} s CPU (best of {args.repeat})")
    widths = np.concatenate([first_order_widths(h, GAMMA) for h in res.harmonics])
    spacing = float(np.min(widths)) / 3.0
    n_grid = int(np.ceil((HI - LO) / spacing)) + 1
    rng = np.random.default_rng(0)
    t_scan = 0.0
    for h in res.harmonics:  # a handful of harmonics
        M, C, A, B = h.matrices(GAMMA)
        sample = np.sort(rng.uniform(LO, HI, args.sample))
        _, t_s, _ = best_of(lambda M=M, C=C, A=A, B=B, s=sample: growth_rate(M, C, A, B, s), 1)
        t_scan += t_s * n_grid / sample.size
    print(f"scan baseline: spacing {spacing:.3e} rad/s (a third of the narrowest first-order "
          f"region above the detection floor) -> {n_grid} points per k; extrapolated "
          f"{t_scan:.3e} s")
    print(f"ratio scan / map = {t_scan / t_map:.3g}  (targets: map < 5 s, ratio >= 50)")
    t_coarse = t_scan * 4000 / n_grid
    print(f"for scale: a 4000-point scan per k (far too coarse to find the regions) would take "
          f"{t_coarse:.1f} s, ratio {t_coarse / t_map:.3g}")
    if args.hard:
        hk = dict(F0=F0, gamma=0.5, omega_min=10.0, omega_max=300.0, k_min=3, k_max=3,
                  n_modes=10, damping_ratio=0.001, axial=False)
        fast, t_f, c_f = best_of(lambda: vehicle_regions(veh, **hk), 1)
        full, t_u, c_u = best_of(lambda: vehicle_regions(veh, damping_margin=None, **hk), 1)
        same = [(r.kind, r.order, r.omega_lo) for r in fast.regions] == [
            (r.kind, r.order, r.omega_lo) for r in full.regions]
        print(f"hard case (k = 3, 10 modes, gamma = 0.5, zeta = 0.001): filter {t_f:.2f} s wall"
              f" / {c_f:.2f} s CPU, unfiltered {t_u:.2f} s / {c_u:.2f} s CPU, ratio "
              f"{t_u / t_f:.2f}; {len(fast.regions)} region(s), same as unfiltered: {same}")
    if args.cost:
        cost_check(args.cost_modes)
    if args.limits:
        limits(args.repeat)


def _case(text: str):
    return load_case(tomllib.loads(text))


def cost_check(modes) -> None:
    """Up-front estimate / measured CPU time of single harmonics' searches (item 4)."""
    memo = vehicle_from_case(flexbooster.memo_case())
    cases = [(f"default vehicle, k = 3, {n} modes, undamped", memo, 3, n, 0.0) for n in modes]
    cases += [("README example, k = 2, 20 modes, zeta = 0.01",
               vehicle_from_case(_case(memo_case_text() + README_VEHICLE)), 2, 20, 0.01),
              ("free-free default vehicle, k = 1, 20 modes, zeta = 0.01",
               vehicle_from_case(_case(memo_case_text() + FREE_ENDS)), 1, 20, 0.01)]
    for name, veh, k, n, zeta in cases:  # a handful of harmonics
        kw = dict(F0=F0, gamma=GAMMA, omega_min=LO, omega_max=HI, k_min=k, k_max=k,
                  n_modes=n, damping_ratio=zeta, gimbal_gain=0.5, axial=False)
        found, _, cpu = best_of(lambda kw=kw, veh=veh: vehicle_regions(veh, **kw), 1)
        up = search_seconds(found.harmonics[0].omega_loaded.size, LO, HI, damped=zeta > 0)
        print(f"cost model, {name}: measured {cpu:.2f} s CPU ({len(found.regions)} regions); "
              f"up front {up:.2f} s (ratio {up / cpu:.2f})")


def limits(repeat: int) -> None:
    """Item 5: the README example, k = 2, 8 modes, undamped, Omega 1..2000 rad/s."""
    veh = vehicle_from_case(_case(memo_case_text() + README_VEHICLE))
    kw = dict(F0=F0, gamma=GAMMA, omega_min=1.0, omega_max=HI, k_min=2, k_max=2, n_modes=8,
              damping_ratio=0.0, axial=False)
    found, t_map, c_map = best_of(lambda: vehicle_regions(veh, **kw), repeat)
    M, _, A, B = found.harmonics[0].matrices(GAMMA)
    work = floquet.search_work(M, None, A, B, 1.0, HI)
    w = found.harmonics[0].omega_loaded
    i, k = np.triu_indices(w.size, 1)
    base = np.concatenate([2 * w, w[i] + w[k], w[k] - w[i]])
    every = int(np.sum(np.floor(base / 0.5) - np.maximum(1, np.ceil(base / (2 * HI))) + 1))
    print(f"README example k = 2, 8 modes, undamped, Omega 1..{HI:g} rad/s: {every} centres "
          f"of every order in [Omega_min / 2, 2 Omega_max], {work.n_candidates} examined by "
          f"the monodromy and {work.n_narrow} by harmonic balance; map {t_map:.2f} s wall, "
          f"{c_map:.2f} s CPU (best of {repeat}), {len(found.regions)} regions, "
          f"{len(found.gaps)} gaps")


if __name__ == "__main__":
    main()
