"""The liquid of a propellant tank: its potential-flow added mass on the wall (virtual mass).

An inviscid incompressible liquid settled aft in an axisymmetric tank; per harmonic k the
potential Phi cos k theta solves Laplace's equation with dPhi/dn the wall's normal
displacement and Phi = 0 on the free surface (the high-frequency limit): M_a = rho_L c_k
G^T H^-1 G, H = A + k^2 B (:mod:`.liquid_mesh`). The slosh condition: :mod:`.slosh`. Theory:
docs/theory/liquid.md.

References: H. N. Abramson (ed.), NASA SP-106, 1966, ch. 2, 6; F. T. Dodge, SwRI, 2000,
ch. 1-3; R. A. Ibrahim, *Liquid Sloshing Dynamics*, 2005, ch. 2, 9.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
from scipy.sparse.linalg import splu

from ..checks import count, finite_array
from .elements import theta_weight
from .liquid_mesh import (
    LiquidMesh,
    Tank,
    condensed_operator,
    dof_index,
    liquid_mesh,
    radial_moments,
    wall_trace,
)

__all__ = ["WALL_RTOL", "Tank", "LiquidMesh", "liquid_mesh", "WallQuadrature", "AddedMass",
           "added_mass"]

#: Relative tolerance of the wall points on the wall R(x) and inside [x_a, x_s].
WALL_RTOL = 1e-6


@dataclass(frozen=True)
class WallQuadrature:
    """Quadrature points on the wetted wall (x_a < x < x_s) of a tank.

    Parameters
    ----------
    x, r : array_like, shape (n,)
        Station and radius of each point (m), on the wall R(x).
    normal : array_like, shape (n, 2)
        Unit normal (n_x, n_r) out of the liquid.
    weight : array_like, shape (n,)
        Meridian arc-length weights (m): int f ds = sum weight f.
    """

    x: np.ndarray
    r: np.ndarray
    normal: np.ndarray
    weight: np.ndarray

    def __post_init__(self) -> None:
        x = finite_array("wall.x", self.x, nonempty=False)
        n = x.size
        for name, shape in (("r", (n,)), ("normal", (n, 2)), ("weight", (n,))):
            val = finite_array(f"wall.{name}", getattr(self, name), nonempty=False)
            if val.shape != shape:
                raise ValueError(f"wall.{name}: shape {val.shape}, need {shape}")
            object.__setattr__(self, name, val)
        object.__setattr__(self, "x", x)
        if np.any(np.abs(np.hypot(*self.normal.T) - 1.0) > WALL_RTOL):
            raise ValueError("wall.normal: must be unit vectors")


def _check_wall(tank: Tank, wall: WallQuadrature) -> None:
    """The points lie on the wetted wall: x_a <= x <= x_s, r = R(x), normal out of it."""
    scale = max(tank.fwd - tank.aft, max(tank.radii))
    tol = WALL_RTOL * scale
    bad = (wall.x < tank.aft - tol) | (wall.x > tank.surface + tol)
    bad |= np.abs(wall.r - tank.radius(wall.x)) > tol
    xs, rs = np.asarray(tank.stations), np.asarray(tank.radii)
    slopes = np.diff(rs) / np.diff(xs)
    ok = np.zeros(wall.x.size, dtype=bool)
    for side in ("left", "right"):  # at a breakpoint either piece's normal is accepted
        s = slopes[np.clip(np.searchsorted(xs, wall.x, side=side) - 1, 0, slopes.size - 1)]
        nx_, nr_ = wall.normal.T
        ok |= (np.abs(nx_ + s * nr_) <= 1e-6 * np.hypot(1.0, s)) & (nr_ - s * nx_ > 0.0)
    bad |= ~ok
    if np.any(bad):
        i = int(np.argmax(bad))
        raise ValueError(f"wall point {i} = (x {wall.x[i]!r}, r {wall.r[i]!r}, normal "
                         f"{tuple(wall.normal[i])!r}): not on the wetted wall of the tank "
                         f"(x_a {tank.aft!r} .. x_s {tank.surface!r}, R(x) "
                         f"{float(tank.radius(wall.x[i]))!r}, outward normal)")


@dataclass(frozen=True)
class AddedMass:
    """Added mass of a tank's liquid for one harmonic.

    Attributes
    ----------
    k : int
        Circumferential harmonic.
    matrix : ndarray, shape (n, n)
        M_a (kg, in the DOFs' units), symmetric positive semi-definite (kinetic energy
        q' M_a q' / 2, theta integral c_k included).
    constraint : ndarray, shape (n,), or None
        Closed full tank, k = 0: volume change per unit DOF (m^3); the motion must satisfy
        ``constraint @ q = 0``. None otherwise.
    point_force : ndarray, shape (n_points, n), or None
        The liquid's pressure force at each wall point per unit DOF acceleration (N s^2 / m per
        m of normal displacement): ``matrix = displacement.T @ point_force + aft_end[:, None]
        * end_force[0] + fwd_end[:, None] * end_force[1]``, the split of the inertia force by
        where the pressure acts (force summation over a part of the wall). None: no liquid.
    end_force : ndarray, shape (2, n), or None
        The same on the rigid aft and forward ends (per unit u_x / r^k of the end).
    point_volume, end_volume : ndarray, shape (n_points,) and (2,), or None
        Closed full tank, k = 0: ``constraint = displacement.T @ point_volume + aft_end *
        end_volume[0] + fwd_end * end_volume[1]`` (m^2, m^3 per unit u_x); None otherwise.
    """

    k: int
    matrix: np.ndarray
    constraint: np.ndarray | None
    point_force: np.ndarray | None = None
    end_force: np.ndarray | None = None
    point_volume: np.ndarray | None = None
    end_volume: np.ndarray | None = None


def _end_row(name: str, value, n: int) -> np.ndarray:
    row = np.zeros(n) if value is None else finite_array(name, value, nonempty=False)
    if row.shape != (n,):
        raise ValueError(f"{name}: shape {row.shape}, need ({n},)")
    return row


def added_mass(mesh: LiquidMesh, k: int, wall: WallQuadrature, displacement: np.ndarray, *,
               aft_end: np.ndarray | None = None, fwd_end: np.ndarray | None = None
               ) -> AddedMass:
    """Added-mass matrix of the liquid on the wall DOFs for harmonic k (free surface p = 0;
    Abramson 1966 ch. 2; Ibrahim 2005 ch. 9).

    Parameters
    ----------
    mesh : LiquidMesh
        The tank's liquid (:func:`liquid_mesh`), reused for every k.
    k : int
        Circumferential harmonic, 0..200.
    wall : WallQuadrature
        Quadrature of the wetted wall, x_a .. x_s.
    displacement : array_like, shape (n_points, n)
        Normal wall displacement (m per unit DOF, out of the liquid) of each DOF at the points.
    aft_end, fwd_end : array_like, shape (n,), optional
        Axial displacement of the rigid aft / forward end per unit DOF, u_x = r^k cos k theta
        (row @ q), k <= 1 only; ``fwd_end`` only with ``fill = 1``.
    """
    k = count("k", k, 0, 200)
    N = finite_array("displacement", displacement, nonempty=False)
    if N.ndim != 2 or N.shape[0] != wall.x.size:
        raise ValueError(f"displacement: shape {N.shape}, need ({wall.x.size}, n)")
    n = N.shape[1]
    rows = [_end_row(name, val, n) * (k <= 1)
            for name, val in (("aft_end", aft_end), ("fwd_end", fwd_end))]
    tank = mesh.tank
    _check_wall(tank, wall)
    if mesh.nodes.size == 0:  # no liquid
        return AddedMass(k, np.zeros((n, n)), None)
    nx, ny = mesh.shape
    index, n_dof = dof_index(mesh, k, open_surface=True)
    # W[node] = int_boundary psi_node w_n r ds per unit DOF: the wall by the given points,
    # the ends d Phi / dn = -u_x (aft), +u_x (fwd) by quadrature
    axial, val = wall_trace(mesh, wall.x)
    trace = np.zeros((nx, wall.x.size))
    np.add.at(trace, (axial, np.arange(wall.x.size)[:, None]),
              val * (wall.weight * wall.r)[:, None])
    nodes, W = [np.arange(nx) * ny + ny - 1], [trace @ N]
    moment = radial_moments(mesh, k + 1)
    ends = [(0, -1.0, rows[0])] + [(nx - 1, 1.0, rows[1])] * (tank.fill == 1.0)
    end_weight = []  # per end: the weight of its nodes (sign R^(k+2) moment)
    for line, sign, row in ends:
        nodes.append(line * ny + np.arange(ny))
        end_weight.append(sign * float(tank.radius(mesh.x_nodes[line])) ** (k + 2) * moment)
        W.append(np.outer(end_weight[-1], row))
    nodes, W = np.concatenate(nodes), np.concatenate(W)
    keep = index[nodes] >= 0
    bd, inv = np.unique(index[nodes][keep], return_inverse=True)
    Gb = sp.csr_matrix((np.ones(inv.size), (inv, np.arange(inv.size))),
                       shape=(bd.size, inv.size)) @ W[keep]
    if bd.size == 0:
        return AddedMass(k, np.zeros((n, n)), None)
    H = condensed_operator(mesh, k, index, n_dof)
    constraint = None
    if k == 0 and tank.fill == 1.0 and tank.ends == ("rigid", "rigid"):  # pure Neumann
        constraint = theta_weight(0) * W.sum(axis=0)  # int w_n dS (partition of unity)
        border = np.zeros(n_dof)  # gauge: the sum of Phi over the boundary nodes is 0
        border[bd] = 1.0
        H = sp.bmat([[H, border[:, None]], [border[None, :], None]]).tocsc()
    lu = splu(H, permc_spec="MMD_AT_PLUS_A")
    # node pressures x weights P = rho c_k Z G, Z the boundary block of H^-1
    if n < bd.size:  # fewer DOFs than boundary nodes: solve H X = G directly (n columns)
        rhs = np.zeros((H.shape[0], n))
        rhs[bd] = Gb
        P = tank.density * theta_weight(k) * lu.solve(rhs)[bd]
    else:  # Z by its bd.size columns, symmetrised
        rhs = np.zeros((H.shape[0], bd.size))
        rhs[bd, np.arange(bd.size)] = 1.0
        Z = lu.solve(rhs)[bd]
        P = tank.density * theta_weight(k) * (0.5 * (Z + Z.T)) @ Gb
    M = Gb.T @ P
    # the same product split by where the pressure acts: per wall point, per end
    node_p = np.zeros((nodes.size, n))
    node_p[keep] = P[inv]
    wr = val * (wall.weight * wall.r)[:, None]  # the nonzeros of trace, point by point
    point_force = np.einsum("pj,pjn->pn", wr, node_p[:nx][axial])
    end_force = np.zeros((2, n))
    point_volume = end_volume = None
    if constraint is not None:
        point_volume = theta_weight(0) * wall.weight * wall.r
        end_volume = np.zeros(2)
    for i, ((_, _, _), wgt) in enumerate(zip(ends, end_weight, strict=True)):
        end_force[i] = wgt @ node_p[nx + i * ny:nx + (i + 1) * ny]
        if constraint is not None:
            end_volume[i] = theta_weight(0) * wgt.sum()
    return AddedMass(k, 0.5 * (M + M.T), constraint, point_force, end_force, point_volume,
                     end_volume)
