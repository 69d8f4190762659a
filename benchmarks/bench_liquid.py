"""Benchmark: the added mass of a tank's liquid for k = 0..20 (shell_of_revolution.liquid).

Tank: the aft cylinder (R 1.5 m, 6 m) and cone (1.5 -> 1.0 m over 1.5 m) of a free-free
aluminium cylinder-cone-cylinder, 80 % full of LOX-like liquid (1140 kg/m^3, surface in the
cone).  The wall data (quadrature and the shell's normal displacement of the reduced DOFs that
move the wetted wall or the aft end, as a vehicle's modes use them) are made once per k before
timing; the work timed is what a modal analysis does per tank: :func:`liquid_mesh` once, then
:func:`added_mass` for every k = 0..20 (the element matrices reused for every k, each element's
interior condensed statically, one sparse factorisation of the element-edge skeleton per k and
a solve for the DOFs' columns of G), plus the first slosh mode.

Two baselines in the same run, the same mesh and the same result:

1. the previous method: the boundary block of H^-1 by one solve per boundary node (the
   branch :func:`added_mass` takes with at least as many DOFs as boundary nodes, reached here
   by padding the DOFs with zero columns; the products with those zero columns are included,
   a few per cent at most);
2. per k the element matrices made again (``liquid_mesh``), the global H = A + k^2 B assembled
   over all nodes (no condensation), and a dense Cholesky solve of H X = G.

The largest relative differences of M_a are printed (round-off only).

Run:  python benchmarks/bench_liquid.py
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # before numpy loads OpenBLAS

import numpy as np  # noqa: E402
import scipy.linalg as sla  # noqa: E402
from bench_shell_of_revolution import REPEATS, best_of  # noqa: E402 (benchmarks/)

from flexbooster.shell_of_revolution import Cone, Cylinder, Vehicle, mesh_vehicle  # noqa: E402
from flexbooster.shell_of_revolution.elements import theta_weight  # noqa: E402
from flexbooster.shell_of_revolution.liquid import added_mass, liquid_mesh  # noqa: E402
from flexbooster.shell_of_revolution.liquid_mesh import (  # noqa: E402
    radial_moments,
    wall_trace,
)
from flexbooster.shell_of_revolution.slosh import slosh_mode  # noqa: E402
from flexbooster.shell_of_revolution.wetted_wall import vehicle_tank, wetted_wall  # noqa: E402

__all__: list[str] = []

ALU = {"E": 70e9, "nu": 0.33, "rho": 2800.0}
VEHICLE = Vehicle([Cylinder(1.5, 6.0, 0.006, **ALU), Cone(1.5, 1.0, 1.5, 0.005, **ALU),
                   Cylinder(1.0, 3.0, 0.005, **ALU)])
TANK = vehicle_tank(VEHICLE, aft=0.0, fwd=7.5, fill=0.8, density=1140.0)
K_MAX = 20


def moving(w):
    """The DOFs that move the wetted wall or the aft end (as the vehicle's modes take them)."""
    return np.flatnonzero(np.any(w.displacement != 0.0, axis=0) | (w.aft_end != 0.0))


def work(walls):
    lm = liquid_mesh(TANK)
    mats = []
    for k, w in enumerate(walls):
        cols = moving(w)
        mats.append(added_mass(lm, k, w.wall, w.displacement[:, cols],
                               aft_end=w.aft_end[cols]).matrix)
    return mats, slosh_mode(lm, 9.81 * 3.0)


def previous(walls):
    """The boundary-inverse branch: the same DOFs padded with zero columns to the number of
    boundary nodes (nodes on the wall and the aft end), the padding's rows dropped."""
    lm = liquid_mesh(TANK)
    nx, ny = lm.shape
    mats = []
    for k, w in enumerate(walls):
        cols = moving(w)
        pad = max(0, nx + ny - cols.size)
        N = np.hstack([w.displacement[:, cols], np.zeros((w.wall.x.size, pad))])
        aft = np.concatenate([w.aft_end[cols], np.zeros(pad)])
        mats.append(added_mass(lm, k, w.wall, N, aft_end=aft).matrix[:cols.size, :cols.size])
    return mats, slosh_mode(lm, 9.81 * 3.0)


def baseline(walls):
    """Per k: element matrices again, global H over all nodes, dense Cholesky."""
    mats = []
    for k, w in enumerate(walls):
        lm = liquid_mesh(TANK)
        nx, ny = lm.shape
        i, j = np.divmod(np.arange(nx * ny), ny)
        free = i < nx - 1  # Phi = 0 on the free surface ...
        if k >= 1:
            free &= j > 0  # ... and on the axis
        H = np.zeros((nx * ny, nx * ny))
        e = lm.nodes
        np.add.at(H, (e[:, :, None], e[:, None, :]), lm.gradient + k * k * lm.hoop)
        axial, val = wall_trace(lm, w.wall.x)
        cols = moving(w)
        G = np.zeros((nx * ny, cols.size))
        np.add.at(G, axial * ny + ny - 1,
                  (val * (w.wall.weight * w.wall.r)[:, None])[:, :, None]
                  * w.displacement[:, None, cols])
        G[:ny] -= TANK.radii[0] ** (k + 2) * np.outer(radial_moments(lm, k + 1),
                                                       w.aft_end[cols])
        X = sla.cho_solve(sla.cho_factor(H[np.ix_(free, free)]), G[free])
        mats.append(TANK.density * theta_weight(k) * G[free].T @ X)
    return mats


def main() -> None:
    mesh = mesh_vehicle(VEHICLE)
    walls = [wetted_wall(VEHICLE, mesh, TANK, k, breaks=liquid_mesh(TANK).x_breaks)
             for k in range(K_MAX + 1)]
    lm = liquid_mesh(TANK)
    counts = sorted({moving(w).size for w in walls})
    print(f"tank: {TANK.liquid_mass():.0f} kg, liquid mesh {lm.shape[0]} x {lm.shape[1]} "
          f"nodes (order {lm.order}), {counts[0]}..{counts[-1]} of "
          f"{walls[0].displacement.shape[1]} shell DOFs move the wall, "
          f"{walls[0].wall.x.size} wall points; OPENBLAS_NUM_THREADS="
          f"{os.environ.get('OPENBLAS_NUM_THREADS')}")
    t_work, (mats, slosh) = best_of(lambda: work(walls))
    t_prev, (prev, _) = best_of(lambda: previous(walls))
    t_base, base = best_of(lambda: baseline(walls), repeats=1)

    def diff(ref):
        return max(np.abs(a - b).max() / np.abs(b).max() for a, b in zip(mats, ref, strict=True))

    print(f"first slosh mode at 3 g: {slosh.hz:.3f} Hz, slosh mass {slosh.mass:.0f} kg")
    print(f"added mass k = 0..{K_MAX} + slosh (liquid_mesh once, condensed, G's columns): "
          f"{t_work:.3f} s (best of {REPEATS})")
    print(f"baseline 1, previous method (boundary block of H^-1): {t_prev:.3f} s "
          f"(best of {REPEATS}): ratio {t_prev / t_work:.2f}; max relative difference of M_a "
          f"{diff(prev):.1e}")
    print(f"baseline 2 (per k: element matrices, all nodes, dense Cholesky): {t_base:.3f} s: "
          f"ratio {t_base / t_work:.1f}; max relative difference of M_a {diff(base):.1e}")


if __name__ == "__main__":
    main()
