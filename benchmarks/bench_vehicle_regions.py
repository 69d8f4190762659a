"""Benchmark: flexbooster.vehicle.vehicle_regions on the default case's vehicle (issue 15).

The vehicle of ``flexbooster.model.vehicle_from_case(flexbooster.default_case())`` (the memo's
two cylinders, memo bulkhead, shear-diaphragm ends, inertia relief), F0 = 2.8 MN, k = 1..20
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
  4. ``--cost``: the per-harmonic cost model (``flexbooster.vehicle.harmonic_search_seconds``
     of ``floquet.search_work``, issue 18) and the up-front one (``search_seconds``) against
     the measured search of undamped k = 3 maps with 4, 8 and 12 modes (``--cost-modes``),
     and of the damped harmonics that are not certified: the README example's k = 2 and the
     free-free default vehicle's k = 1 (20 modes); the ratio estimate / measured.

  5. ``--leftovers`` (issue 15 leftovers, branch vk2): the pipeline's stage
     ``analysis.analyze_vehicle_regions(case, boundaries=True)`` (what ``flexbooster run``
     runs, no budget) on the default case, the README's ``[vehicle]`` example and the default
     vehicle with free ends, k = 1..10 and k = 1..20, against the same run's baseline: the
     previous stage (a second full map with ``boundaries=True`` for the chart's curves, the
     damped seeds refined to rtol: ``floquet.regions._monodromy_search(seeds=False)``); the
     regions of both must be equal (kind, modes, order; edges to 1e-6 relative).  ``--run``
     adds ``flexbooster run -j 1`` of the default case and of the README example (wall, CPU
     of the child).
  6. ``--damped-counts`` (branch damped1): the same stage on the same three cases, k = 1..20,
     and the ``--hard`` case, against the same run's baseline: the damped step counts of
     main before the fix of ``floquet.multipliers._rates`` (:func:`_previous_rates`, a copy
     of main 308388d's function patched in); the time and how far the regions moved (edges
     and growth rates, relative).

Usage::

    OPENBLAS_NUM_THREADS=1 PYTHONPATH=src python benchmarks/bench_vehicle_regions.py \
        [--n-modes 20] [--k-max 20] [--repeat 3] [--sample 16] [--hard] [--cost] \
        [--leftovers] [--run] [--damped-counts]
"""

from __future__ import annotations

import argparse
import dataclasses
import resource
import subprocess
import sys
import tempfile
import time
import tomllib
from pathlib import Path

import numpy as np

import flexbooster
from flexbooster import floquet
from flexbooster.analysis import analyze_vehicle_regions
from flexbooster.case import default_case_text, load_case
from flexbooster.floquet import growth_rate
from flexbooster.floquet import regions as floquet_regions
from flexbooster.model import vehicle_from_case
from flexbooster.vehicle import (
    bending_harmonic,
    harmonic_search_seconds,
    harmonic_system,
    search_seconds,
    vehicle_regions,
)
from flexbooster.vehicle.regions import _floquet_options, _harmonic_regions

F0, GAMMA, LO, HI = 2.8e6, 0.05, 5.0, 2000.0

#: The README's ``[vehicle]`` example (appended to the default case).
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
    ap.add_argument("--leftovers", action="store_true", help="the pipeline stage, vk2")
    ap.add_argument("--run", action="store_true", help="flexbooster run of two cases")
    ap.add_argument("--damped-counts", action="store_true",
                    help="the damped step counts against main's (branch damped1)")
    args = ap.parse_args()
    print(f"load average {Path('/proc/loadavg').read_text().split()[:3]} at start")
    veh = vehicle_from_case(flexbooster.default_case())
    kw = dict(F0=F0, gamma=GAMMA, omega_min=LO, omega_max=HI, k_min=1, k_max=args.k_max,
              n_modes=args.n_modes, gimbal_gain=0.5)
    res, t_map, c_map = best_of(lambda: vehicle_regions(veh, **kw), args.repeat)
    print(f"default case vehicle, k = 1..{args.k_max}, {args.n_modes} modes per k, "
          f"Omega = {LO:g}..{HI:g} rad/s, gamma = {GAMMA}, zeta = 0.01")
    _, t_10, c_10 = best_of(lambda: vehicle_regions(veh, **{**kw, "k_max": 10}), args.repeat)
    print(f"k = 1..10 (the former cap), same run: {t_10:.3f} s wall, {c_10:.3f} s CPU")
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
    if args.leftovers:
        leftovers(args.repeat)
    if args.run:
        cli_runs()
    if args.damped_counts:
        damped_counts(args.repeat)


def _case(text: str):
    return load_case(tomllib.loads(text))


def cost_check(modes) -> None:
    """Estimate / measured CPU time of single harmonics' searches (item 4 of the docstring)."""
    opts = _floquet_options(1e-9, 0.12, None, floquet.DAMPING_MARGIN)
    memo = vehicle_from_case(flexbooster.default_case())
    cases = [(f"default vehicle, k = 3, {n} modes, undamped", memo, 3, n, 0.0) for n in modes]
    cases += [("README example, k = 2, 20 modes, zeta = 0.01",
               vehicle_from_case(_case(default_case_text() + README_VEHICLE)), 2, 20, 0.01),
              ("free-free default vehicle, k = 1, 20 modes, zeta = 0.01",
               vehicle_from_case(_case(default_case_text() + FREE_ENDS)), 1, 20, 0.01)]
    for name, veh, k, n, zeta in cases:  # a handful of harmonics
        h = (bending_harmonic(veh, F0=F0, n_modes=n, damping_ratio=zeta, gimbal_gain=0.5)
             if k == 1 else harmonic_system(veh, k, F0=F0, n_modes=n, damping_ratio=zeta))
        M, C, A, B = h.matrices(GAMMA)
        work = floquet.search_work(M, C if zeta > 0 else None, A, B, LO, HI, **opts)
        (rows, *_), _, cpu = best_of(lambda h=h: _harmonic_regions(h, GAMMA, LO, HI, opts), 1)
        est = harmonic_search_seconds(work)
        up = search_seconds(A.shape[0], LO, HI, damped=zeta > 0)
        print(f"cost model, {name}: measured {cpu:.2f} s CPU ({len(rows)} regions, "
              f"{work.n_candidates} candidates); per harmonic {est:.2f} s (ratio "
              f"{est / cpu:.2f}); up front {up:.2f} s (ratio {up / cpu:.2f})")


def _previous_stage(case):
    """The stage before vk2 (same numerics otherwise): the map, then the chart's curves by a
    second full map with boundaries=True up to the chart's gamma; the damped seeds refined to
    rtol (seeds=False); no budget."""
    from flexbooster.analysis import _chart_gamma
    from flexbooster.memo import charts
    from flexbooster.vehicle_case import VehicleTable

    table = case.vehicle if case.vehicle is not None else VehicleTable()
    t = case.thrust
    settings = dict(F0=case.F0, omega_min=t.omega_min, omega_max=t.omega_max, k_min=1,
                    k_max=table.k_max, n_modes=table.n_modes,
                    damping_ratio=table.damping_ratio, gimbal_gain=t.K)
    real = floquet_regions._monodromy_search

    def no_seeds(*a, seeds=False, **k):
        return real(*a, seeds=False, **k)

    floquet_regions._monodromy_search = no_seeds
    try:
        veh = vehicle_from_case(case)
        found = vehicle_regions(veh, gamma=t.gamma, **settings)
        top = _chart_gamma(found)
        if top > 0.0 and (top == t.gamma and found.regions or top > t.gamma and
                          vehicle_regions(veh, gamma=top, **settings).regions):
            curved = vehicle_regions(veh, gamma=t.gamma, boundaries=True, gamma_max=top,
                                     n_gamma=charts.VEHICLE_CHART_LEVELS, **settings)
            found = dataclasses.replace(found, curves=curved.curves)
        return found
    finally:
        floquet_regions._monodromy_search = real


def _same_regions(a, b) -> bool:
    key = [(r.k, r.kind, r.order, tuple(m.index for m in r.modes)) for r in a.regions]
    if key != [(r.k, r.kind, r.order, tuple(m.index for m in r.modes)) for r in b.regions]:
        return False
    return all(abs(x.omega_lo - y.omega_lo) <= 1e-6 * y.omega_center
               and abs(x.omega_hi - y.omega_hi) <= 1e-6 * y.omega_center
               for x, y in zip(a.regions, b.regions, strict=True))


def leftovers(repeat: int) -> None:
    """Item 5 of the docstring: the stage, now and before, k = 1..10 and 1..20."""
    cases = {"default case": default_case_text(),
             "README [vehicle] example": default_case_text() + README_VEHICLE,
             "default vehicle, free ends": default_case_text() + FREE_ENDS}
    for name, text in cases.items():  # three cases
        for k_max in (10, 20):
            # no budget (max_seconds 1e9): the work itself; the vehicle table's k_max
            body = ("max_seconds = 1e9\n" + text).replace("k_max = 20", f"k_max = {k_max}")
            if "k_max =" not in body.split("[vehicle]")[-1]:
                body += ("" if "[vehicle]" in body else "\n[vehicle]\n") + f"k_max = {k_max}\n"
            case = _case(body)
            now, t_now, c_now = best_of(
                lambda case=case: analyze_vehicle_regions(case, boundaries=True), repeat)
            old, t_old, c_old = best_of(lambda case=case: _previous_stage(case), 1)
            print(f"{name}, k = 1..{k_max}: stage {t_now:.2f} s wall / {c_now:.2f} s CPU "
                  f"(best of {repeat}; {len(now.regions)} regions, {len(now.curves)} curves, "
                  f"skipped {len(now.skipped)}); previous stage {t_old:.2f} s / {c_old:.2f} s "
                  f"CPU ({len(old.curves)} curves); CPU ratio {c_old / c_now:.2f}; same "
                  f"regions: {_same_regions(now, old)}", flush=True)


def cli_runs() -> None:
    """flexbooster run -j 1 of the default case and of the README example (wall, child CPU)."""
    for name, text in (("default case", default_case_text()),
                       ("README [vehicle] example", default_case_text() + README_VEHICLE)):
        with tempfile.TemporaryDirectory() as tmp:
            path = Path(tmp) / "case.toml"
            path.write_text(text)
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            t0 = time.perf_counter()
            subprocess.run([sys.executable, "-m", "flexbooster", "run", str(path), "-q",
                            "-j", "1", "-o", str(Path(tmp) / "out")], check=True)
            wall = time.perf_counter() - t0
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
            print(f"flexbooster run -j 1, {name}: {wall:.1f} s wall, {cpu:.1f} s CPU")


def _previous_rates(system):
    """``floquet.multipliers._rates`` of main 308388d (before branch damped1): the damped
    frame's |G_jk| (1/time, columns of W of unit norm in (q, q')), which ``step_counts`` then
    divides by max(w_j, Omega / 2): a dimensionless "rate", ~(2 omega)^(1/4) fewer steps."""
    if not system.damped and system.Bt is not None:
        return np.abs(np.sqrt(system.mu)), np.abs(system.Bt)
    n = system.n
    L0 = np.block([[np.zeros((n, n)), np.eye(n)], [-system.K0, -system.Kc]])
    lam, W = np.linalg.eig(L0)
    Nmat = np.block([[np.zeros((n, n)), np.zeros((n, n))], [-system.Kb, np.zeros((n, n))]])
    if np.linalg.cond(W) < 1e8:
        G = np.abs(np.linalg.solve(W, Nmat @ W))
    else:
        G = np.full((2 * n, 2 * n), np.max(np.abs(Nmat)))
    return np.abs(lam), G


def _with_previous_counts(fn):
    """fn() with main's damped step counts (:func:`_previous_rates` patched in)."""
    from flexbooster.floquet import multipliers

    real = multipliers._rates
    multipliers._rates = _previous_rates
    try:
        return fn()
    finally:
        multipliers._rates = real


def _moved(now, old) -> str:
    """How far the regions moved: same keys, largest relative change of edges and growth."""
    key = [(r.k, r.kind, r.order, tuple(m.index for m in r.modes)) for r in now.regions]
    if key != [(r.k, r.kind, r.order, tuple(m.index for m in r.modes)) for r in old.regions]:
        return f"regions differ: {len(now.regions)} now, {len(old.regions)} before"
    if not now.regions:
        return "same (no region)"
    edge = max(max(abs(x.omega_lo / y.omega_lo - 1), abs(x.omega_hi / y.omega_hi - 1))
               for x, y in zip(now.regions, old.regions, strict=True))
    grow = max(abs(x.growth_rate_max / y.growth_rate_max - 1)
               for x, y in zip(now.regions, old.regions, strict=True))
    gcr = max(abs(x.critical_gamma - y.critical_gamma) / max(y.critical_gamma, 1e-300)
              for x, y in zip(now.regions, old.regions, strict=True))
    return (f"same {len(key)} regions; edges moved <= {edge:.1e}, growth rates <= {grow:.1e}, "
            f"critical gamma <= {gcr:.1e} relative")


def damped_counts(repeat: int) -> None:
    """Item 6 of the docstring: the stage and the hard case, now and with main's counts."""
    cases = {"default case": default_case_text(),
             "README [vehicle] example": default_case_text() + README_VEHICLE,
             "default vehicle, free ends": default_case_text() + FREE_ENDS}
    for name, text in cases.items():  # three cases
        case = _case("max_seconds = 1e9\n" + text)  # no budget: the work itself
        now, t_now, c_now = best_of(
            lambda case=case: analyze_vehicle_regions(case, boundaries=True), repeat)
        old, t_old, c_old = best_of(lambda case=case: _with_previous_counts(
            lambda: analyze_vehicle_regions(case, boundaries=True)), repeat)
        print(f"{name}, k = 1..20, stage: {t_now:.2f} s wall / {c_now:.2f} s CPU; main's "
              f"damped counts {t_old:.2f} s / {c_old:.2f} s CPU; CPU ratio now / main "
              f"{c_now / c_old:.2f}; {_moved(now, old)}", flush=True)
    veh = vehicle_from_case(flexbooster.default_case())
    hk = dict(F0=F0, gamma=0.5, omega_min=10.0, omega_max=300.0, k_min=3, k_max=3,
              n_modes=10, damping_ratio=0.001, axial=False)
    now, t_now, c_now = best_of(lambda: vehicle_regions(veh, **hk), repeat)
    old, t_old, c_old = best_of(lambda: _with_previous_counts(
        lambda: vehicle_regions(veh, **hk)), repeat)
    print(f"hard case (k = 3, 10 modes, gamma = 0.5, zeta = 0.001): {t_now:.2f} s wall / "
          f"{c_now:.2f} s CPU; main's damped counts {t_old:.2f} s / {c_old:.2f} s CPU; CPU "
          f"ratio now / main {c_now / c_old:.2f}; {_moved(now, old)}", flush=True)


if __name__ == "__main__":
    main()
