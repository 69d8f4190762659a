"""Print the tables of docs/theory/memo-vs-vehicle.md from the current code.

The memo case with the pipeline's own settings: the memo table of ``analyze`` (its
``active`` flag is severity_rel >= threshold), the vehicle regions of the
pipeline's stage (``analyze_vehicle_regions``: k = 1..10, ``vehicle.n_modes`` = 20 modes per k,
damping ratio 0.01, k = 1 with the gimbal gain), the same map undamped and with small damping
ratios, and the memo roots inside the undamped regions (``memo_roots_in_regions``).

Usage (about 5-10 minutes on one core with 20 modes; ``--n-modes 8`` for a quick look)::

    OPENBLAS_NUM_THREADS=1 PYTHONPATH=src python scripts/memo_vs_vehicle.py [--n-modes 20]
        [--zetas 1e-4 3e-4 1e-3]
"""

from __future__ import annotations

import argparse
import time
from collections import Counter

import numpy as np

from flexbooster import memo_case
from flexbooster.analysis import (
    VEHICLE_REGIONS_K_MIN,
    analyze,
    analyze_vehicle_regions,
    memo_roots_in_regions,
)
from flexbooster.dynamics import vehicle_regions
from flexbooster.model import vehicle_from_case

__all__ = ["main"]


def _regions_line(vr) -> str:
    regs = vr.regions
    if not regs:
        return "0 regions"
    kinds = Counter(r.kind for r in regs)
    orders = Counter(r.order for r in regs)
    worst = max(regs, key=lambda r: r.growth_rate_max)
    m = worst.modes[0]
    return (f"{len(regs)} regions ({', '.join(f'{v} {k}' for k, v in sorted(kinds.items()))}; "
            f"orders {dict(sorted(orders.items()))}; by k "
            f"{dict(sorted(Counter(r.k for r in regs).items()))}); widest "
            f"{max(r.width for r in regs):.3g} rad/s, total width "
            f"{sum(r.width for r in regs):.3g} rad/s; largest growth "
            f"{worst.growth_rate_max:.3g} 1/s at k = {worst.k} ({worst.kind}, j = "
            f"{worst.order}, mode {m.index} {m.type} order {m.order}, omega_L = "
            f"{m.omega_loaded:.5g} rad/s), Omega {worst.omega_lo:.6g}..{worst.omega_hi:.6g}")


def main() -> None:
    """Print the tables."""
    ap = argparse.ArgumentParser()
    ap.add_argument("--n-modes", type=int, default=20)
    ap.add_argument("--k-max", type=int, default=10,
                    help="highest harmonic of the damping sweep (the pipeline: vehicle.k_max)")
    ap.add_argument("--zetas", type=float, nargs="*", default=[1e-4, 3e-4, 1e-3])
    args = ap.parse_args()
    case = memo_case()
    t = case.thrust
    t0 = time.perf_counter()
    res = analyze(case, figures=False, vehicle=False)
    table = res.stability
    active = np.asarray(table.active, bool)
    k = np.asarray(table.k)
    print(f"memo table: {len(table.Omega)} roots in [{t.omega_min:g}, {t.omega_max:g}] rad/s, "
          f"{int(active.sum())} active (severity_rel >= {case.severity.threshold:g}); active "
          f"by k: {dict(sorted(Counter(k[active].tolist()).items()))}; active by family: "
          f"{dict(sorted(Counter(np.asarray(table.family)[active].tolist()).items()))} "
          f"({time.perf_counter() - t0:.1f} s)")
    sh = res.shell
    for kk in (1, 3, 10):
        sel = np.asarray(sh.k) == kk
        if np.any(sel):
            low = float(np.min(sh.omega_bar[sel])) * sh.omega_1
            print(f"memo shells, k = {kk}: lowest {low:.5g} rad/s (each cylinder alone)")
    t0 = time.perf_counter()
    damped = analyze_vehicle_regions(case, boundaries=False)
    print(f"pipeline stage (k = {VEHICLE_REGIONS_K_MIN}..{damped.harmonics[-1].k}, "
          f"{damped.harmonics[-1].omega_loaded.size} modes, zeta = {damped.damping_ratio:g}): "
          f"{_regions_line(damped)}; certified {sum(c.certified for c in damped.certificates)}"
          f" of {len(damped.certificates)} ({time.perf_counter() - t0:.1f} s)")
    for h, c in zip(damped.harmonics, damped.certificates, strict=True):
        b = np.abs(np.diag(h.excitation)) / np.maximum(h.omega_loaded, 1e-300) ** 2
        print(f"  k = {h.k}: omega_L[0] = {h.omega_loaded[0]:.5g} rad/s (unloaded "
              f"{h.omega_unloaded[h.omega_unloaded > 0][0]:.5g}), max |B1_ii|/omega_i^2 = "
              f"{b.max():.4g}, certified up to gamma = "
              f"{damped.gamma * c.amplitude_factor:.3g}")
    v = vehicle_from_case(case)
    kw = dict(F0=case.F0, gamma=t.gamma, omega_min=t.omega_min, omega_max=t.omega_max,
              k_min=VEHICLE_REGIONS_K_MIN, k_max=args.k_max, n_modes=args.n_modes,
              gimbal_gain=t.K, axial=False)
    sweep = {}
    for zeta in [0.0, *args.zetas]:
        t0 = time.perf_counter()
        sweep[zeta] = vehicle_regions(v, damping_ratio=zeta, **kw)
        print(f"vehicle, zeta = {zeta:g}, {args.n_modes} modes: {_regions_line(sweep[zeta])} "
              f"({time.perf_counter() - t0:.1f} s)", flush=True)
    undamped = sweep[0.0]
    for r in sorted(undamped.regions, key=lambda r: -r.growth_rate_max)[:5]:
        print(f"  growth {r.growth_rate_max:.3g} 1/s, k = {r.k}, {r.kind} j = {r.order}, modes "
              f"{[(m.index, m.type, m.order, round(m.omega_loaded, 3)) for m in r.modes]}, "
              f"growth / omega_L = {r.growth_rate_max / r.modes[0].omega_loaded:.2g}")
    k1 = [r for r in undamped.regions if r.k == 1]
    print(f"k = 1 undamped: {len(k1)} regions, largest growth "
          f"{max((r.growth_rate_max for r in k1), default=0.0):.3g} 1/s")
    for rtol in (0.0, 1e-3, 1e-2):
        m = memo_roots_in_regions(table, undamped, rtol=rtol)
        fam = Counter(m.family[m.active].tolist())
        print(f"roots in undamped regions, rtol {rtol:g}: {len(m)} roots, "
              f"{int(m.active.sum())} active (families {dict(sorted(fam.items()))}), "
              f"{int(np.sum(m.active & m.same_k))} active of the region's k; regions without "
              f"an active root {m.without_active_root.size} of {m.n_regions}")
    sk = np.asarray(table.k)
    for kk in (1, 2):
        om = np.asarray(table.Omega)[active & (sk == kk)]
        regs = [r for r in undamped.regions if r.k == kk]
        if om.size and regs:
            d = min(float(np.min(np.maximum(0.0, np.maximum(r.omega_lo - om, om - r.omega_hi))))
                    for r in regs)
            print(f"  active k = {kk} roots: {om.size}; nearest to a k = {kk} region: {d:.3g} "
                  "rad/s")


if __name__ == "__main__":
    main()
