"""Benchmark: flexbooster.vehicle.vehicle_regions on the default case's vehicle (issue 15).

The vehicle of ``flexbooster.model.vehicle_from_case(flexbooster.default_case())`` (the memo's
two cylinders, memo bulkhead, shear-diaphragm ends, inertia relief), F0 = 2.8 MN, k = 1..10
(k = 1: bending with the gimbal gain K = 0.5 of the default case), 20 modes per k, Omega =
5..2000 rad/s, gamma = 0.05, damping ratio 0.01 (the default case).  Times, in the same run,

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
  4. ``--cost``: the cost model of the searches (``flexbooster.vehicle.search_seconds`` plus
     ``HARMONIC_BUILD_SECONDS``, issue 18) against the measured time of undamped k = 3 maps
     with 4, 8 and 12 modes (``--cost-modes`` to change), the ratio estimate / measured.

Usage::

    OPENBLAS_NUM_THREADS=1 PYTHONPATH=src python benchmarks/bench_vehicle_regions.py \
        [--n-modes 20] [--k-max 10] [--repeat 3] [--sample 16] [--hard] [--cost]
"""

from __future__ import annotations

import argparse
import time

import numpy as np

import flexbooster
from flexbooster.floquet import growth_rate
from flexbooster.model import vehicle_from_case
from flexbooster.vehicle import HARMONIC_BUILD_SECONDS, search_seconds, vehicle_regions

F0, GAMMA, LO, HI = 2.8e6, 0.05, 5.0, 2000.0


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
    ap.add_argument("--k-max", type=int, default=10)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--sample", type=int, default=16, help="scan points timed per k")
    ap.add_argument("--hard", action="store_true", help="also the filter-only case")
    ap.add_argument("--cost", action="store_true", help="also the cost model check")
    ap.add_argument("--cost-modes", type=int, nargs="+", default=[4, 8, 12])
    args = ap.parse_args()
    veh = vehicle_from_case(flexbooster.default_case())
    kw = dict(F0=F0, gamma=GAMMA, omega_min=LO, omega_max=HI, k_min=1, k_max=args.k_max,
              n_modes=args.n_modes, gimbal_gain=0.5)
    res, t_map, c_map = best_of(lambda: vehicle_regions(veh, **kw), args.repeat)
    print(f"default case vehicle, k = 1..{args.k_max}, {args.n_modes} modes per k, "
          f"Omega = {LO:g}..{HI:g} rad/s, gamma = {GAMMA}, zeta = 0.01")
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
        for n in args.cost_modes:  # a handful of sizes
            ck = dict(F0=F0, gamma=GAMMA, omega_min=LO, omega_max=HI, k_min=3, k_max=3,
                      n_modes=n, damping_ratio=0.0, axial=False)
            got, t_c, _ = best_of(lambda ck=ck: vehicle_regions(veh, **ck), 1)
            est = HARMONIC_BUILD_SECONDS + search_seconds(n, LO, HI, damped=False)
            print(f"cost model, undamped k = 3, {n} modes: measured {t_c:.2f} s, estimated "
                  f"{est:.2f} s, ratio {est / t_c:.2f} ({len(got.regions)} regions)")


if __name__ == "__main__":
    main()
