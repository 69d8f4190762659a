"""Benchmark: flexbooster.dynamics.forced_response on the README's [vehicle] example.

Work: README.md's vehicle (cylinder R 1.5 m x 6 m and a cone to R 1.0 m over 1 m, 16 mm walls,
E = 70 GPa, nu = 0.3, rho = 2700 kg/m^3, free-free, automatic mesh), F0 = 2.8 MN (the default
case), gamma = 0.05, thrust misalignment 0.01 rad, gimbal gain K = 0.5, zeta = 0.01,
zeta_psi = 0.02, k = 0 and 1, 400 Omega points 5..2000 rad/s, all stations (the edges, the
junction and a payload station at 6.5 m): the curves at every station, the peaks (Omega grid
plus the points across each resonance, then the golden-section refinement) and the load
envelopes.  Times, in the same run,

  1. ``forced_response`` (the deliverable: < 1 s): best of ``--repeat``;
  2. the baseline: a dense solve of the full finite-element model per Omega,
     (K_L - Omega^2 M + i Omega M Phi D Phi^T M) X = F with the same damped modes, at the same
     400 grid points plus the points across each resonance that the fast method samples (what
     a grid method needs to see the peaks; the golden refinement is not repeated: this favours
     the baseline), the stations' rows from the same element nodal forces;

and prints both times, their ratio and how far the two are apart (the curves at the stations
relative to the largest of each quantity; the peaks).

Usage::

    OPENBLAS_NUM_THREADS=1 PYTHONPATH=src python benchmarks/bench_forced_response.py [--repeat 5]
"""

from __future__ import annotations

import argparse
import math
import time

import numpy as np

from flexbooster.dynamics import forced_response
from flexbooster.dynamics.forced import CLUSTER, CLUSTER_DENSITY
from flexbooster.dynamics.forced_model import cut_vehicle, full_model
from flexbooster.shell_of_revolution import Cone, Cylinder, Vehicle, mesh_vehicle

ALU = {"E": 70e9, "nu": 0.3, "rho": 2700.0}
VEHICLE = Vehicle(segments=(Cylinder(1.5, 6.0, 0.016, **ALU), Cone(1.5, 1.0, 1.0, 0.016, **ALU)))
STATIONS = [("payload", 6.5)]
KW = {"F0": 2.8e6, "amplitude": 0.05, "Omega": np.linspace(5.0, 2000.0, 400),
      "damping_ratio": 0.01, "misalignment": 0.01, "gimbal_gain": 0.5,
      "pitch_damping_ratio": 0.02, "stations": STATIONS}


def fast():
    return forced_response(VEHICLE, **KW)


def baseline(res):
    """Full-model rows at the stations on the grid, and peaks over grid + resonance points."""
    om = KW["Omega"]
    cut, _, _ = cut_vehicle(VEHICLE, [x for _, x in STATIONS], None)
    mesh = mesh_vehicle(cut)
    at = [int(np.argmin(np.abs(res.models[0].node_x - s.x))) for s in res.stations]
    curves, peaks, solves = {}, {}, 0
    for k, model in zip(res.harmonics, res.models, strict=True):
        share = math.cos(KW["misalignment"]) if k == 0 else math.sin(KW["misalignment"])
        fm = full_model(cut, mesh, k, F0=KW["F0"], share=share, n_modes=None,
                        omega_max=float(om[-1]), gimbal_gain=KW["gimbal_gain"],
                        supported_forward_end=False)
        MPhi = fm.mass @ fm.basis
        C = MPhi @ model.damping @ MPhi.T  # the same modal damping, truncated modes none
        poles = model.poles()[0]
        up = poles[poles.imag > 0.0]
        steps = np.arange(-CLUSTER, CLUSTER + 1) / CLUSTER_DENSITY
        pts = (up.imag[:, None] + np.abs(up.real)[:, None] * steps).ravel()
        grid = np.unique(np.concatenate([om, pts[(pts >= om[0]) & (pts <= om[-1])]]))
        X = np.empty((fm.load.size, grid.size), dtype=complex)
        for j, w in enumerate(grid):  # the straightforward method: one full solve per Omega
            X[:, j] = np.linalg.solve(fm.stiffness - w**2 * fm.mass + 1j * w * C, fm.load)
        solves += grid.size
        stiff, mass = fm.node_rows(X)
        rows = (stiff - grid**2 * mass)[at] * KW["amplitude"] * KW["F0"]  # (s, rows, n)
        on_grid = np.searchsorted(grid, om)
        curves[k] = rows[:, :, on_grid]
        peaks[k] = np.abs(rows).max(axis=2)
        peaks[(k, "acceleration")] = (grid**2 * np.abs(rows[:, 0])).max(axis=1)
    return curves, peaks, solves, fm.load.size


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()
    times = []
    for _ in range(args.repeat):
        t0 = time.perf_counter()
        res = fast()
        times.append(time.perf_counter() - t0)
    t_fast = min(times)
    t0 = time.perf_counter()
    curves, peaks, solves, n_dof = baseline(res)
    t_base = time.perf_counter() - t0
    modes = [m.omega_modes.size for m in res.models]
    print(f"README vehicle, k = 0 and 1, {KW['Omega'].size} Omega points, "
          f"{len(res.stations)} stations; modes (rigid included) {modes}, "
          f"highest {[round(float(m.omega_modes[-1])) for m in res.models]} rad/s")
    print(f"forced_response (best of {args.repeat}): {t_fast:.3f} s")
    print(f"baseline, full model ({n_dof} DOFs for k = 1), {solves} dense solves: "
          f"{t_base:.3f} s")
    print(f"ratio baseline / forced_response: {t_base / t_fast:.1f}")
    for ik, k in enumerate(res.harmonics):
        for i, q in enumerate(("displacement",) + (("axial_force",) if k == 0 else
                                                   ("shear_force", "bending_moment"))):
            mine, base = getattr(res, q)[ik], curves[k][:, i]
            d = float(np.max(np.abs(mine - base)) / np.max(np.abs(base)))
            print(f"  k = {k} {q:15s} curves: max difference {d:.1e} of the largest")
    worst = 0.0
    for p in res.peaks:
        s = [st.name for st in res.stations].index(p.station)
        if p.quantity == "acceleration":
            ref = peaks[(p.k, "acceleration")][s]
        else:
            i = (("displacement",) + (("axial_force",) if p.k == 0 else
                                      ("shear_force", "bending_moment"))).index(p.quantity)
            ref = peaks[p.k][s, i]
        top = max(r.value for r in res.peaks if (r.k, r.quantity) == (p.k, p.quantity))
        worst = max(worst, (p.value - ref) / top)
    print(f"  peaks: forced_response above the baseline's largest sample by at most "
          f"{worst:.1e} of the largest peak (the golden-section refinement)")


if __name__ == "__main__":
    main()
