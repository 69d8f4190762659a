"""A tank's liquid on the shell-of-revolution model: the wetted wall in the shell's reduced DOFs
(quadrature, normal displacement, the ends' axial motion) and the wet system M + M_a.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import lru_cache

import numpy as np
from numpy.polynomial import legendre as leg

from ..checks import count
from .assembly import Mesh, dof_map, mesh_vehicle, system_matrices
from .elements import reference_element
from .geometry import STATION_RTOL, Vehicle, tank_liquid, tank_wall
from .liquid import LiquidMesh, Tank, WallQuadrature, added_mass, liquid_mesh
from .shared import shared_value
from .slosh import SloshMode, slosh_mode

__all__ = ["WettedWall", "WetSystem", "vehicle_tank", "wetted_wall", "wet_system_matrices",
           "TankMass", "tank_added_mass", "slosh_modes"]



def vehicle_tank(vehicle: Vehicle, *, aft: float, fwd: float, fill: float, density: float,
                 ends: tuple = ("rigid", "rigid")) -> Tank:
    """The :class:`.liquid.Tank` whose wall is the vehicle's meridian between two stations.

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    aft, fwd : float
        Tank end stations (m from the aft edge), segment boundaries or vehicle ends, aft < fwd;
        the wall between them continuous (no plate, no radius step).
    fill, density, ends
        As :class:`.liquid.Tank`.
    """
    stations, radii = tank_wall(vehicle, aft, fwd)
    return Tank(stations=stations, radii=radii, fill=fill, density=density, ends=ends)


@dataclass(frozen=True)
class WettedWall:
    """The wetted wall of a tank in the reduced shell DOFs of one harmonic.

    Attributes
    ----------
    wall : WallQuadrature
        The quadrature points.
    displacement : ndarray, shape (n_points, n)
        Normal displacement w (m per unit reduced DOF) at the points.
    aft_end, fwd_end : ndarray, shape (n,)
        Axial displacement u_x / r^k of the shell edge at the tank's ends (k <= 1; else zero).
    element : ndarray of int, shape (n_points,)
        The shell element of each point.
    end_element : tuple of int
        The shell elements whose edges are the tank's aft and forward ends (-1 for k >= 2).
    """

    wall: WallQuadrature
    displacement: np.ndarray
    aft_end: np.ndarray
    fwd_end: np.ndarray
    element: np.ndarray
    end_element: tuple


def wetted_wall(vehicle: Vehicle, mesh: Mesh, tank: Tank, k: int, *,
                breaks: np.ndarray = (), points: int = 10) -> WettedWall:
    """Quadrature of the wetted meridian (x_a .. x_s) and the shell's w at its points.

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    mesh : Mesh
        The shell's mesh (:func:`.assembly.mesh_vehicle`).
    tank : Tank
        Its wall must be the vehicle's (:func:`vehicle_tank`).
    k : int
        Circumferential harmonic, 0..200.
    breaks : array_like
        Further stations (m) at which to cut the quadrature (the liquid mesh's ``x_breaks``).
    points : int
        Gauss points per interval, 1..40.
    """
    k = count("k", k, 0, 200)
    points = count("points", points, 1, 40)
    ref = reference_element(mesh.order)
    wall, el, local = _wall_rows(mesh, tank, np.ravel(np.asarray(breaks, dtype=float)), points)
    x2 = mesh.x1 + mesh.length * mesh.cos_phi
    dmap = dof_map(vehicle, mesh, k)
    N = _reduce(dmap, mesh.dofs[el], local)
    ends = [np.zeros(dmap.n), np.zeros(dmap.n)]
    end_el = [-1, -1]
    if k <= 1:
        for i, (station, end) in enumerate(((tank.aft, 0), (tank.fwd, 1))):
            edge = (mesh.x1, x2)[end]  # the element that starts (ends) the tank's wall
            at = np.flatnonzero((np.abs(edge - station) <= STATION_RTOL * x2.max())
                                & (mesh.cos_phi > 0))
            if at.size == 0:
                raise ValueError(f"tank end at {station!r} m: not an element end of the "
                                 "shell's mesh (make the tank with vehicle_tank)")
            e = int(at[-end])
            end_el[i] = e
            r = mesh.r1[e] + end * mesh.length[e] * mesh.sin_phi[e]
            fr = mesh.frame[e, end]  # u_x = a cos(frame) - b sin(frame)
            row = np.zeros((1, ref.n_dof))
            row[0, 4 * end], row[0, 4 * end + 2] = np.cos(fr) / r**k, -np.sin(fr) / r**k
            ends[i] = _reduce(dmap, mesh.dofs[e][None], row)[0]
    return WettedWall(wall, N, ends[0], ends[1], el, tuple(end_el))


def _wall_rows(mesh: Mesh, tank: Tank, breaks: np.ndarray, points: int):
    """(WallQuadrature, element of each point, w per element DOF of each point) of the wetted
    meridian x_a .. x_s: the same for every harmonic, computed once per mesh, wetted interval,
    cuts and points within :func:`~.shared.shared_harmonics` (read-only arrays)."""
    return shared_value(("wall rows", id(mesh), tank.aft, tank.surface, breaks.tobytes(), points),
                        (mesh,), lambda: _new_wall_rows(mesh, tank, breaks, points))


def _new_wall_rows(mesh: Mesh, tank: Tank, breaks: np.ndarray, points: int):
    ref = reference_element(mesh.order)
    g, gw = leg.leggauss(points)
    x2 = mesh.x1 + mesh.length * mesh.cos_phi
    cuts = np.unique(np.concatenate(([tank.aft, tank.surface], breaks)))
    xi, wt, els = [], [], []
    # the elements that overlap the wetted wall by more than the round-off of their computed
    # ends (x2 = x1 + l cos phi): not the neighbour that ends at x_a within it
    tol = STATION_RTOL * x2.max()
    wet = (x2 > tank.aft + tol) & (mesh.x1 < tank.surface - tol) & (mesh.cos_phi > 0)
    for e in np.flatnonzero(wet):
        lo, hi = max(mesh.x1[e], tank.aft), min(x2[e], tank.surface)
        c = np.concatenate(([lo], cuts[(cuts > lo) & (cuts < hi)], [hi]))
        mid, half = 0.5 * (c[1:] + c[:-1]), 0.5 * np.diff(c)
        x = (mid[:, None] + half[:, None] * g[None, :]).ravel()
        xi.append(2.0 * (x - mesh.x1[e]) / (x2[e] - mesh.x1[e]) - 1.0)
        wt.append((half[:, None] * gw[None, :]).ravel() / mesh.cos_phi[e])  # ds = dx / cos
        els.append(np.full(x.size, e))
    xi, wt, el = (np.concatenate(a) if a else np.zeros(0) for a in (xi, wt, els))
    el = el.astype(int)
    s = 0.5 * (1.0 + xi) * mesh.length[el]
    # w in the element's local DOFs (slope DOFs dw/ds: d/dxi times l / 2) ...
    nw = ref.evaluate(xi)[1]
    nw[:, ref.slope] *= 0.5 * mesh.length[el, None]
    local = np.zeros((xi.size, ref.n_dof))
    local[:, ref.iw] = nw
    # ... then in the node frames: w_local = -a sin(delta) + b cos(delta) at both ends
    for end, (ia, ib) in enumerate(((0, 2), (4, 6))):
        delta = mesh.phi[el] - mesh.frame[el, end]
        local[:, ia] = -np.sin(delta) * local[:, ib]
        local[:, ib] *= np.cos(delta)
    wall = WallQuadrature(x=mesh.x1[el] + s * mesh.cos_phi[el],
                          r=mesh.r1[el] + s * mesh.sin_phi[el],
                          normal=np.stack([-mesh.sin_phi[el], mesh.cos_phi[el]], axis=1),
                          weight=wt)
    for arr in (el, local, wall.x, wall.r, wall.normal, wall.weight):
        arr.setflags(write=False)
    return wall, el, local


def _reduce(dmap, dofs: np.ndarray, rows: np.ndarray) -> np.ndarray:
    """Rows over element DOFs (full indices ``dofs``) -> rows over the reduced DOFs."""
    idx = dmap.index[dofs]
    keep = idx >= 0
    out = np.zeros((rows.shape[0], dmap.n))
    np.add.at(out, (np.broadcast_to(np.arange(rows.shape[0])[:, None], idx.shape)[keep],
                    idx[keep]), (rows * dmap.coef[dofs])[keep])
    return out


@dataclass(frozen=True)
class WetSystem:
    """The shell with its tanks' liquid, one harmonic.

    Attributes
    ----------
    mass, stiffness, geometric : ndarray, shape (m, m)
        M + M_a (kg), K_e and K_g (N/m) on the coordinates q = basis @ q_c.
    added_mass : ndarray, shape (n, n)
        Sum of the tanks' M_a on the reduced shell DOFs (kg).
    basis : ndarray, shape (n, m), or None
        Orthonormal basis of the motions that keep every closed full tank's volume (k = 0);
        None when no tank constrains the motion.
    """

    mass: np.ndarray
    stiffness: np.ndarray
    geometric: np.ndarray
    added_mass: np.ndarray
    basis: np.ndarray | None


def wet_system_matrices(vehicle: Vehicle, k: int, tanks: tuple, *, mesh: Mesh | None = None,
                        liquid_meshes: tuple | None = None, prestress_F0: float = 0.0,
                        supported_forward_end: bool = False) -> WetSystem:
    """:func:`.assembly.system_matrices` with the tanks' added mass (and volume constraints).

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    k : int
        Circumferential harmonic, 0..200.
    tanks : sequence of Tank
        The tanks (:func:`vehicle_tank`).
    mesh : Mesh, optional
        The shell's mesh (default :func:`.assembly.mesh_vehicle`).
    liquid_meshes : sequence of LiquidMesh, optional
        One per tank (default :func:`.liquid.liquid_mesh`), to reuse over k.
    prestress_F0, supported_forward_end
        As :func:`.assembly.system_matrices`.
    """
    mesh = mesh_vehicle(vehicle) if mesh is None else mesh
    tanks = tuple(tanks)
    lms = tuple(liquid_mesh(t) for t in tanks) if liquid_meshes is None else tuple(
        liquid_meshes)
    if len(lms) != len(tanks) or not all(
            isinstance(lm, LiquidMesh) and lm.tank == t for lm, t in zip(lms, tanks, strict=True)):
        raise ValueError("liquid_meshes: need one LiquidMesh of each tank, in order")
    M, K, G = system_matrices(vehicle, k, mesh=mesh, prestress_F0=prestress_F0,
                              supported_forward_end=supported_forward_end)
    wet = _added(vehicle, mesh, k, tanks, lms, M.shape[0])
    Ma = wet.matrix
    if wet.basis is None:
        return WetSystem(M + Ma, K, G, Ma, None)
    Z = wet.basis
    return WetSystem(Z.T @ (M + Ma) @ Z, Z.T @ K @ Z, Z.T @ G @ Z, Ma, Z)


@dataclass(frozen=True)
class TankMass:
    """The liquid of a vehicle's tanks on the shell's reduced DOFs, one harmonic.

    Attributes
    ----------
    matrix : ndarray, shape (n, n)
        Sum of the tanks' added-mass matrices M_a (kg).
    basis : ndarray, shape (n, m), or None
        Orthonormal basis of the motions that keep every closed full tank's volume (k = 0);
        None when no tank constrains the motion.
    constraint : ndarray, shape (n_c, n), or None
        The volume change per unit DOF of each constraining tank (m^3): ``constraint @ q = 0``.
    parts : tuple of (WettedWall, AddedMass, ndarray)
        Per tank: its wetted wall, its added mass on the DOFs ``columns`` (the third item) and
        so the split of its inertia force by where the pressure acts (force summation).
    """

    matrix: np.ndarray
    basis: np.ndarray | None
    constraint: np.ndarray | None = None
    parts: tuple = ()


def _added(vehicle: Vehicle, mesh: Mesh, k: int, tanks: tuple, lms: tuple, n: int) -> TankMass:
    """Added mass and volume-constraint basis of the tanks ``tanks`` (their liquid meshes)."""
    Ma = np.zeros((n, n))
    cons, parts = [], []
    for t, lm in zip(tanks, lms, strict=True):
        ww = wetted_wall(vehicle, mesh, t, k, breaks=lm.x_breaks)
        # only the DOFs that move the wetted wall or the tank's ends (the rest add zeros)
        cols = np.flatnonzero(np.any(ww.displacement != 0.0, axis=0) | (ww.aft_end != 0.0)
                              | (ww.fwd_end != 0.0))
        am = added_mass(lm, k, ww.wall, ww.displacement[:, cols], aft_end=ww.aft_end[cols],
                        fwd_end=ww.fwd_end[cols])
        Ma[np.ix_(cols, cols)] += am.matrix
        parts.append((ww, am, cols))
        if am.constraint is not None:
            full = np.zeros(n)
            full[cols] = am.constraint
            cons.append(full)
    if not cons:
        return TankMass(Ma, None, None, tuple(parts))
    C = np.array(cons)
    Q = np.linalg.qr(C.T, mode="complete")[0]
    # the motions with C q = 0
    return TankMass(Ma, Q[:, np.linalg.matrix_rank(C):], C, tuple(parts))


@lru_cache(maxsize=32)
def _liquid_mesh(tank: Tank) -> LiquidMesh:
    """The liquid mesh of a tank, built once per tank (k-independent)."""
    return liquid_mesh(tank)


def tank_added_mass(vehicle: Vehicle, mesh: Mesh, k: int) -> TankMass | None:
    """The liquid of the vehicle's tanks (``Vehicle.tanks``, rigid ends, free surface p = 0) on
    the reduced DOFs of harmonic k: added mass per k through the wall pressure, the ends'
    axial motion for k <= 1 (the liquid on the aft bulkhead, moving with the tank in bending)
    and the volume constraint of a full closed tank at k = 0; None without liquid
    (docs/theory/liquid.md; Abramson 1966, ch. 2).

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    mesh : Mesh
        Its mesh (:func:`.assembly.mesh_vehicle`).
    k : int
        Circumferential harmonic, 0..200.
    """
    tanks = tuple(tank_liquid(vehicle, t) for t in vehicle.tanks if t.fill > 0.0)
    if not tanks:
        return None
    return _added(vehicle, mesh, k, tanks, tuple(_liquid_mesh(t) for t in tanks),
                  dof_map(vehicle, mesh, k).n)


def slosh_modes(vehicle: Vehicle, *, acceleration: float) -> tuple[SloshMode, ...]:
    """The first lateral slosh mode of each partly filled tank of the vehicle under the axial
    acceleration (Abramson 1966, NASA SP-106, ch. 2 and 6: spring-mass analogy; for a flat-
    bottomed cylinder omega^2 = (a xi_1 / R) tanh(xi_1 h / R), xi_1 = 1.8412), labelled with
    the tank's name; a full or empty tank has none.

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    acceleration : float
        Axial acceleration a (m/s^2), > 0.
    """
    out = []
    for i, t in enumerate(vehicle.tanks):
        if 0.0 < t.fill < 1.0:
            mode = slosh_mode(_liquid_mesh(tank_liquid(vehicle, t)), acceleration)
            out.append(replace(mode, tank=t.name or f"tank {i}"))
    return tuple(out)
