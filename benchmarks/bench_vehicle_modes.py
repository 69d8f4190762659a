"""Benchmark: the modes of a two-stage liquid launch vehicle with its tanks.

Times, in the same run (best of ``--repeat``, wall and CPU), k = 0..20, 20 modes each:
  1. ``vehicle_modes`` of the wet vehicle (four tanks, lumped engines and payload, pressures,
     ring-stiffened skirts): the liquid mesh of each tank built once and its added mass
     condensed per k (the work; target under 2 s);
  2. baseline: the same liquid per k with the liquid meshes rebuilt for every harmonic
     (``wet_system_matrices`` without ``liquid_meshes``) and a dense ``eigh`` of the full wet
     system (no rigid-mode deflation, every eigenvalue);
  3. the dry vehicle (no tanks): the cost of the shell alone, for scale;
  4. ``vehicle_modes`` with the dense partial ``eigh`` for every harmonic (the sparse
     shift-invert Lanczos of the harmonics without rigid motions switched off:
     ``modes.SPARSE_MIN_DOFS`` above the DOFs), the method it replaces.
The ratios baseline / work and dense / work are printed; the lowest frequencies of 1. and 2.
are compared for each k >= 2, and every frequency and mode shape of 1. and 4. (same model:
they agree to round-off).

Usage::

    OPENBLAS_NUM_THREADS=1 PYTHONPATH=src python benchmarks/bench_vehicle_modes.py [--repeat 2]
"""

from __future__ import annotations

import argparse
import dataclasses
import time

import numpy as np
import scipy.linalg as sla

from flexbooster.shell_of_revolution import (
    Cone,
    Cylinder,
    LumpedMass,
    Stiffeners,
    Vehicle,
    VehicleTank,
    mesh_vehicle,
    vehicle_modes,
)
from flexbooster.shell_of_revolution import modes as modes_module
from flexbooster.shell_of_revolution.geometry import tank_liquid
from flexbooster.shell_of_revolution.wetted_wall import wet_system_matrices

K_MAX, N_MODES = 20, 20
AL = {"E": 71e9, "nu": 0.33, "rho": 2800.0}


def two_stage_vehicle() -> Vehicle:
    """A Titan-II-like two-stage vehicle, radius 1.525 m (60 in), 31 m long (public-domain-like
    round numbers): aft skirt, fuel and oxidizer tanks of each stage, interstage, fairing."""
    rings = Stiffeners(spacing=0.5, area=3e-4, inertia=4e-8, eccentricity=0.03)
    R = 1.525
    segs = (Cylinder(R, 2.0, 0.004, **AL, rings=rings),                   # aft skirt 0..2
            Cylinder(R, 7.0, 0.006, **AL, pressure=2.0e5),                 # fuel 1 2..9
            Cylinder(R, 10.0, 0.006, **AL, pressure=2.0e5),                # oxidizer 1 9..19
            Cylinder(R, 2.5, 0.004, **AL, rings=rings),                    # interstage 19..21.5
            Cylinder(R, 2.5, 0.004, **AL, pressure=1.5e5),                 # fuel 2 21.5..24
            Cylinder(R, 3.5, 0.004, **AL, pressure=1.5e5),                 # oxidizer 2 24..27.5
            Cone(R, 0.6, 3.5, 0.003, **AL, nonstructural_mass=5.0))       # fairing 27.5..31
    junctions = ("rigid-bulkhead",) * 5 + ("continuous",)
    masses = (LumpedMass(0.0, 3000.0, transverse_inertia=2000.0, offset=-1.0, name="engines 1"),
              LumpedMass(19.0, 700.0, transverse_inertia=300.0, offset=-0.8, name="engine 2"),
              LumpedMass(27.5, 2500.0, transverse_inertia=1500.0, offset=1.5, name="payload"))
    tanks = (VehicleTank(2.0, 9.0, 0.95, 900.0, name="fuel 1"),
             VehicleTank(9.0, 19.0, 0.9, 1440.0, name="oxidizer 1"),
             VehicleTank(21.5, 24.0, 1.0, 900.0, name="fuel 2"),
             VehicleTank(24.0, 27.5, 0.7, 1440.0, name="oxidizer 2"))
    return Vehicle(segs, junctions=junctions, masses=masses, tanks=tanks)


def best_of(fn, repeat: int):
    """(result, best wall time, best CPU time) of ``repeat`` runs."""
    best, best_cpu, out = np.inf, np.inf, None
    for _ in range(repeat):
        t0, c0 = time.perf_counter(), time.process_time()
        out = fn()
        best = min(best, time.perf_counter() - t0)
        best_cpu = min(best_cpu, time.process_time() - c0)
    return out, best, best_cpu


def baseline(vehicle: Vehicle) -> dict:
    """Lowest elastic frequencies (rad/s) per k of the wet system, liquid meshes rebuilt per k,
    dense eigh of every eigenvalue."""
    mesh = mesh_vehicle(vehicle)
    tanks = [tank_liquid(vehicle, t) for t in vehicle.tanks if t.fill > 0.0]
    out = {}
    for k in range(K_MAX + 1):
        ws = wet_system_matrices(vehicle, k, tanks, mesh=mesh)
        w2 = sla.eigh(ws.stiffness, ws.mass, eigvals_only=True)
        w = np.sqrt(np.abs(w2))
        out[k] = np.sort(w[w > 1e-6 * w.max()])[:N_MODES]  # without the rigid modes (~ 0)
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=2)
    args = parser.parse_args()
    wet = two_stage_vehicle()
    dry = dataclasses.replace(wet, tanks=())
    modes, t_w, c_w = best_of(lambda: vehicle_modes(wet, k_max=K_MAX, n_modes=N_MODES),
                              args.repeat)
    _, t_d, c_d = best_of(lambda: vehicle_modes(dry, k_max=K_MAX, n_modes=N_MODES), args.repeat)
    base, t_b, c_b = best_of(lambda: baseline(wet), 1)
    print(f"two-stage vehicle, {len(wet.tanks)} tanks, k = 0..{K_MAX}, {N_MODES} modes each")
    print(f"1. wet vehicle_modes: {t_w:.3f} s wall ({c_w:.3f} s CPU), {len(modes)} modes")
    print(f"2. baseline (liquid meshes per k, dense eigh): {t_b:.3f} s wall ({c_b:.3f} s CPU); "
          f"ratio baseline / work = {t_b / t_w:.2f} (CPU {c_b / c_w:.2f})")
    print(f"3. dry vehicle_modes: {t_d:.3f} s wall ({c_d:.3f} s CPU); wet / dry = "
          f"{t_w / t_d:.2f}")
    worst = max(abs(modes.omega[modes.k == k][0] / base[k][0] - 1.0)
                for k in range(2, K_MAX + 1))
    print(f"lowest frequency per k >= 2, work vs baseline: largest relative difference "
          f"{worst:.2e}")
    sparse_min = modes_module.SPARSE_MIN_DOFS
    modes_module.SPARSE_MIN_DOFS = 10**9  # every harmonic by the dense partial eigh
    try:
        dense, t_e, c_e = best_of(lambda: vehicle_modes(wet, k_max=K_MAX, n_modes=N_MODES),
                                  args.repeat)
    finally:
        modes_module.SPARSE_MIN_DOFS = sparse_min
    print(f"4. dense partial eigh per harmonic: {t_e:.3f} s wall ({c_e:.3f} s CPU); ratio "
          f"dense / work = {t_e / t_w:.2f} (CPU {c_e / c_w:.2f})")
    shape = np.max(np.abs(modes.shapes - dense.shapes))
    print(f"work vs dense: frequencies {np.max(np.abs(modes.omega / dense.omega - 1.0)):.2e} "
          f"relative, mode shapes {shape:.2e} (unit peak)")


if __name__ == "__main__":
    main()
