"""Spectral-element discretisation of a tank's liquid (the meridional domain 0 <= r <= R(x)).

Per harmonic k the potential Phi(x, r) cos k theta has H = A + k^2 B, A = int grad psi .
grad psi r dr dx and B = int psi psi / r dr dx independent of k; tensor-product GLL elements
on the exact map (x, eta) -> (x, R(x) eta), geometric layers towards the corners, interior
nodes condensed per k. Theory: docs/theory/liquid.md.

References: C. Canuto et al., *Spectral Methods*, 2006, sec. 2.3, ch. 6; B. Szabo,
I. Babuska, *Finite Element Analysis*, 1991, ch. 14.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cache

import numpy as np
import scipy.sparse as sp
from numpy.polynomial import legendre as leg
from scipy.special import roots_jacobi

from ..checks import choice, count, finite_array, positive

__all__ = ["TANK_ENDS", "LIQUID_ORDER", "Tank", "LiquidMesh", "liquid_mesh", "dof_index",
           "condensed_operator", "radial_moments", "radial_mass", "wall_trace"]

#: Conditions of a tank end for the liquid: a rigid flat wall, or an open end (p = 0).
TANK_ENDS = ("rigid", "pressure-release")
#: Default polynomial degree of the liquid elements.
LIQUID_ORDER = 8
#: Geometric grading towards a corner: ratio of neighbouring element lengths, and layers.
GRADING, LAYERS = 0.3, 2
#: Longest element of the liquid mesh (axially), in tank radii.
MAX_ELEMENT_RADII = 1.0
#: Smallest liquid depth, in units of the tank's largest radius (thinner films: 0 or refused;
#: at 1e-5 the slosh frequency is still within 1e-5 of Abramson's).
MIN_DEPTH_RADII = 1e-5
#: Largest number of axial elements of a liquid mesh.
MAX_AXIAL_ELEMENTS = 4000
#: Radial breakpoints of eta = r / R(x) (graded towards the wall, where the high harmonics and
#: the corners live).
ETA_BREAKS = (0.0, 0.5, 0.8, 0.96, 1.0)
#: Largest aspect ratio (longer over shorter side) of the elements of a mesh whose interiors
#: are condensed through the decomposition of their pencil; a mesh with a flatter element (a
#: film of liquid) is condensed by direct solves, which round off less where the Schur
#: complement cancels most of the element's operator.
PENCIL_MAX_ASPECT = 1e3


@dataclass(frozen=True)
class Tank:
    """The liquid of one tank of revolution.

    Parameters
    ----------
    stations : sequence of float
        Axial stations x of the wall's breakpoints (m), strictly increasing; the first and the
        last are the tank's ends.
    radii : sequence of float
        Wall radius at each station (m), > 0 (0 allowed at an end: an apex).
    fill : float
        Liquid height as a fraction of the tank's length, 0..1, settled aft.
    density : float
        Liquid density rho_L (kg/m^3), > 0.
    ends : (str, str)
        Aft and forward end for the liquid, each in :data:`TANK_ENDS` (default rigid walls).
    """

    stations: tuple
    radii: tuple
    fill: float
    density: float
    ends: tuple = ("rigid", "rigid")

    def __post_init__(self) -> None:
        x = finite_array("stations", self.stations)
        r = finite_array("radii", self.radii)
        if x.ndim != 1 or x.size < 2 or r.shape != x.shape:
            raise ValueError(f"radii = {self.radii!r:.60}: need one radius per station, >= 2")
        if np.any(np.diff(x) <= 0.0):
            raise ValueError(f"stations = {self.stations!r:.60}: must increase strictly")
        if np.any(r[1:-1] <= 0.0) or np.any(r < 0.0) or r.max() <= 0.0:
            raise ValueError(f"radii = {self.radii!r:.60}: must be > 0 (0 only at an end)")
        fill = (float(self.fill) if isinstance(self.fill, int | float | np.integer | np.floating)
                and not isinstance(self.fill, bool) else None)
        if fill is None or not 0.0 <= fill <= 1.0:
            raise ValueError(f"fill = {self.fill!r}: must be a number in [0, 1]")
        ends = tuple(self.ends)
        if len(ends) != 2:
            raise ValueError(f"ends = {self.ends!r}: must be (aft, forward)")
        for end in ends:
            choice("ends", end, TANK_ENDS)
        object.__setattr__(self, "stations", tuple(float(v) for v in x))
        object.__setattr__(self, "radii", tuple(float(v) for v in r))
        object.__setattr__(self, "fill", fill)
        object.__setattr__(self, "density", positive("density", self.density))
        object.__setattr__(self, "ends", ends)
        if r[0] == 0.0 and ends[0] != "rigid" or r[-1] == 0.0 and ends[1] != "rigid":
            raise ValueError(f"ends = {ends!r}: an apex (radius 0) has no open end")
        depth = fill * (x[-1] - x[0])
        if 0.0 < depth < MIN_DEPTH_RADII * r.max():
            raise ValueError(f"fill = {fill!r}: the liquid depth {float(depth):.6g} m must be 0 "
                             f"or at least {MIN_DEPTH_RADII:g} of the largest radius "
                             f"{float(r.max()):.6g} m")
        if fill > 0.0 and self.radius(self.surface) <= 0.0:
            raise ValueError(f"fill = {fill!r}: the free surface cannot be at an apex")

    @property
    def aft(self) -> float:
        """Aft end station x_a (m)."""
        return self.stations[0]

    @property
    def fwd(self) -> float:
        """Forward end station x_f (m)."""
        return self.stations[-1]

    @property
    def surface(self) -> float:
        """Station of the free surface x_s = x_a + fill (x_f - x_a) (m)."""
        return self.aft + self.fill * (self.fwd - self.aft)

    def radius(self, x: np.ndarray) -> np.ndarray:
        """Wall radius R(x) (m) at stations ``x`` (m), linear between the breakpoints."""
        return np.interp(x, self.stations, self.radii)

    def wetted(self) -> tuple[np.ndarray, np.ndarray]:
        """Breakpoints (x, R) of the wetted wall, x_a .. x_s (m)."""
        x = np.asarray(self.stations)
        inner = x[(x > self.aft) & (x < self.surface)]
        xs = np.concatenate(([self.aft], inner, [self.surface]))
        return xs, self.radius(xs)

    def liquid_mass(self) -> float:
        """Mass of the liquid rho_L pi int_{x_a}^{x_s} R^2 dx (kg), exact for the frustums."""
        xs, rs = self.wetted()
        vol = np.pi * np.diff(xs) * (rs[:-1] ** 2 + rs[:-1] * rs[1:] + rs[1:] ** 2) / 3.0
        return float(self.density * vol.sum())


@dataclass(frozen=True)
class LiquidMesh:
    """Spectral-element mesh of a tank's liquid and its k-independent matrices.

    Attributes
    ----------
    tank : Tank
        The tank.
    order : int
        Polynomial degree p.
    x_breaks, eta_breaks : ndarray
        Element boundaries: stations (m, x_a .. x_s) and eta = r / R(x) (0 .. 1).
    x_nodes, eta_nodes : ndarray
        Node lines; node (i, j) at (x_nodes[i], R(x_nodes[i]) eta_nodes[j]), index
        i * eta_nodes.size + j.
    nodes : ndarray of int, shape (e, (p + 1)^2)
        Node of every element's local node, the 4 p edge nodes first.
    gradient, hoop : ndarray, shape (e, (p + 1)^2, (p + 1)^2)
        int grad psi . grad psi r dr dx (m^2) and int psi psi / r dr dx (m) per element.
    interior_values : ndarray, shape (e, (p - 1)^2), or None
        lambda of the element interiors' pencil A_ii v = lambda B_ii v (1/m), v^T B_ii v = 1
        (the condensation of every k from one decomposition, :func:`condensed_operator`);
        None when an element is flatter than :data:`PENCIL_MAX_ASPECT`.
    coupling_gradient, coupling_hoop : ndarray, shape (e, 4 p, (p - 1)^2), or None
        A_bi V and B_bi V, V the columns v (m^2, m per sqrt(m)).
    """

    tank: Tank
    order: int
    x_breaks: np.ndarray
    eta_breaks: np.ndarray
    x_nodes: np.ndarray
    eta_nodes: np.ndarray
    nodes: np.ndarray = field(repr=False)
    gradient: np.ndarray = field(repr=False)
    hoop: np.ndarray = field(repr=False)
    interior_values: np.ndarray = field(repr=False, default=None)
    coupling_gradient: np.ndarray = field(repr=False, default=None)
    coupling_hoop: np.ndarray = field(repr=False, default=None)

    @property
    def shape(self) -> tuple[int, int]:
        """Node lines (axial, radial)."""
        return self.x_nodes.size, self.eta_nodes.size


@cache
def _gll(p: int) -> np.ndarray:
    """Gauss-Lobatto-Legendre points of degree p: +-1 and the zeros of P_p' (Jacobi(1, 1));
    once per degree (read-only)."""
    out = np.concatenate(([-1.0], np.sort(roots_jacobi(p - 1, 1.0, 1.0)[0]), [1.0]))
    out.setflags(write=False)
    return out


@cache
def _legendre_to_lagrange(p: int) -> tuple[np.ndarray, np.ndarray]:
    """The Legendre coefficients of the degree-p Lagrange basis on the GLL points and the
    Legendre derivative matrix (degree p -> p - 1), once per degree (read-only)."""
    coef = np.linalg.inv(leg.legvander(_gll(p), p))
    deriv = leg.legder(np.eye(p + 1), axis=0)
    for arr in (coef, deriv):
        arr.setflags(write=False)
    return coef, deriv


@cache
def _gauss(n: int) -> tuple[np.ndarray, np.ndarray]:
    """Gauss-Legendre points and weights of ``n`` points, once per n (read-only)."""
    out = leg.leggauss(n)
    for arr in out:
        arr.setflags(write=False)
    return out


def _lagrange(p: int, xi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Values and d/dxi of the degree-p Lagrange basis on the GLL points at ``xi``."""
    coef, deriv = _legendre_to_lagrange(p)
    return leg.legvander(xi, p) @ coef, (leg.legvander(xi, p - 1) @ deriv) @ coef


def _nodes(breaks: np.ndarray, p: int) -> np.ndarray:
    """GLL node lines of the elements between ``breaks`` (shared end nodes once)."""
    lo, hi = breaks[:-1, None], breaks[1:, None]
    inner = 0.5 * (lo + hi) + 0.5 * (hi - lo) * _gll(p)[None, :-1]
    return np.append(inner.ravel(), breaks[-1])


def _gram(f: np.ndarray, weight: np.ndarray) -> np.ndarray:
    """sum_g f[e, g, a] weight[e, g] f[e, g, b] per element (BLAS on contiguous operands)."""
    fw = np.ascontiguousarray(np.swapaxes(f * weight, 1, 2))
    return fw @ np.broadcast_to(f, (fw.shape[0],) + f.shape[1:])


def _graded(a: float, b: float, radius: float, refinement: int) -> np.ndarray:
    """Breaks of [a, b]: geometric layers (ratio GRADING) towards both ends, at most
    MAX_ELEMENT_RADII radii between, every element split into ``refinement``.
    """
    zone = min(radius * MAX_ELEMENT_RADII, 0.5 * (b - a))
    layers = zone * GRADING ** np.arange(LAYERS, 0, -1)
    n_mid = max(1, math.ceil((b - a - 2.0 * zone) / (radius * MAX_ELEMENT_RADII) - 1e-9))
    mid = np.linspace(a + zone, b - zone, n_mid + 1) if b - a > 2.0 * zone else [a + zone]
    breaks = np.unique(np.concatenate(([a], a + layers, mid, b - layers, [b])))
    frac = np.arange(refinement) / refinement
    return np.append((breaks[:-1, None] + frac * np.diff(breaks)[:, None]).ravel(), b)


def liquid_mesh(tank: Tank, *, order: int = LIQUID_ORDER, refinement: int = 1) -> LiquidMesh:
    """Mesh the liquid of ``tank`` and assemble its k-independent matrices (once per tank).

    Parameters
    ----------
    tank : Tank
        The tank.
    order : int
        Polynomial degree p, 2..16.
    refinement : int
        Split every element into this many in each direction, 1..8.
    """
    p = count("order", order, 2, 16)
    refinement = count("refinement", refinement, 1, 8)
    xs, rs = tank.wetted()
    empty = xs[-1] <= xs[0]
    frac = np.arange(refinement) / refinement
    eta = np.append((np.array(ETA_BREAKS[:-1])[:, None]
                     + frac * np.diff(ETA_BREAKS)[:, None]).ravel(), 1.0)
    xb = np.array([tank.aft]) if empty else np.unique(np.concatenate(
        [_graded(a, b, max(ra, rb), refinement)
         for a, b, ra, rb in zip(xs[:-1], xs[1:], rs[:-1], rs[1:], strict=True)]))
    if xb.size - 1 > MAX_AXIAL_ELEMENTS:
        raise ValueError(f"refinement = {refinement}: {xb.size - 1} axial elements, more than "
                         f"{MAX_AXIAL_ELEMENTS} (a tank of {xs[-1] - xs[0]:g} m and radius "
                         f"{rs.max():g} m)")
    if empty:
        none = np.zeros((0, (p + 1) ** 2, (p + 1) ** 2))
        return LiquidMesh(tank, p, xb, eta, xb, eta, none[:, 0].astype(int), none, none,
                          np.zeros((0, (p - 1) ** 2)), np.zeros((0, 4 * p, (p - 1) ** 2)),
                          np.zeros((0, 4 * p, (p - 1) ** 2)))
    x_nodes, eta_nodes = _nodes(xb, p), _nodes(eta, p)
    ny = eta_nodes.size
    # element geometry: x = xm + hx xi, eta = em + he zeta, r = R(x) eta (bilinear, exact)
    ex, ey = np.meshgrid(np.arange(xb.size - 1), np.arange(eta.size - 1), indexing="ij")
    ex, ey = ex.ravel(), ey.ravel()
    xm, hx = 0.5 * (xb[ex] + xb[ex + 1]), 0.5 * (xb[ex + 1] - xb[ex])
    em, he = 0.5 * (eta[ey] + eta[ey + 1]), 0.5 * (eta[ey + 1] - eta[ey])
    slope = (tank.radius(xb[ex + 1]) - tank.radius(xb[ex])) / (2.0 * hx)
    q, w = _gauss(p + 3)
    val, der = _lagrange(p, q)
    R = tank.radius(xm)[:, None, None] + (slope * hx)[:, None, None] * q[None, :, None]
    et = em[:, None, None] + he[:, None, None] * q[None, None, :]  # (e, g_x, g_eta)
    n_loc = (p + 1) ** 2
    d_xi = np.einsum("ga,hb->ghab", der, val).reshape(q.size, q.size, n_loc)
    d_eta = np.einsum("ga,hb->ghab", val, der).reshape(q.size, q.size, n_loc)
    phi = np.einsum("ga,hb->ghab", val, val).reshape(q.size, q.size, n_loc)
    # chain rule: f_r = f_zeta / (R he), f_x = f_xi / hx - slope eta f_r
    f_r = d_eta[None] / (R * he[:, None, None])[..., None]
    f_x = d_xi[None] / hx[:, None, None, None] - (slope[:, None, None] * et)[..., None] * f_r
    ww = np.outer(w, w)[None]
    g2 = q.size**2
    r_det = (ww * R * et * hx[:, None, None] * R * he[:, None, None]).reshape(-1, g2, 1)
    f_x, f_r = (f.reshape(-1, g2, n_loc) for f in (f_x, f_r))  # r_det: r |J| with weights
    grad = _gram(f_x, r_det) + _gram(f_r, r_det)
    hoop = _gram(phi.reshape(1, g2, n_loc), (ww * (hx * he)[:, None, None] / et).reshape(-1, g2, 1))
    a, b = np.divmod(np.arange(n_loc), p + 1)
    order = np.argsort(~((a % p == 0) | (b % p == 0)), kind="stable")  # edge nodes first
    nodes = (ex * p * ny + ey * p)[:, None] + (a * ny + b)[None, order]
    grad, hoop = (np.ascontiguousarray(m[:, order][:, :, order]) for m in (grad, hoop))
    sides = np.stack([2.0 * hx, tank.radius(xm) * 2.0 * he])  # axial, radial (m)
    pencil = (None, None, None) if np.max(sides.max(axis=0) / sides.min(axis=0)) > \
        PENCIL_MAX_ASPECT else _interior_pencil(grad, hoop, 4 * p)
    for arr in (xb, eta, x_nodes, eta_nodes, nodes, grad, hoop, *pencil):
        if arr is not None:
            arr.setflags(write=False)
    return LiquidMesh(tank, p, xb, eta, x_nodes, eta_nodes, nodes, grad, hoop, *pencil)


def _interior_pencil(grad: np.ndarray, hoop: np.ndarray, nb: int):
    """Per element, lambda and V of A_ii V = B_ii V diag(lambda), V^T B_ii V = I (B_ii = L L^T,
    the symmetric eigenproblem of L^-1 A_ii L^-T; Golub & Van Loan 2013, sec. 8.7.2), and
    A_bi V, B_bi V: then (A_ii + k^2 B_ii)^-1 = V diag(1 / (lambda + k^2)) V^T for every k."""
    inv = np.linalg.inv(np.linalg.cholesky(hoop[:, nb:, nb:]))
    inv_t = np.swapaxes(inv, 1, 2)
    core = inv @ grad[:, nb:, nb:] @ inv_t
    lam, vec = np.linalg.eigh(0.5 * (core + np.swapaxes(core, 1, 2)))
    vec = inv_t @ vec
    return lam, grad[:, :nb, nb:] @ vec, hoop[:, :nb, nb:] @ vec


# ------------------------------------------------------------------------ boundary integrals


def _radial_quadrature(mesh: LiquidMesh):
    """Gauss points eta (e, g), weights (e, g), Lagrange values (g, p + 1) and the radial
    node of each (e, p + 1) of the radial elements."""
    p, eb = mesh.order, mesh.eta_breaks
    q, w = _gauss(p + 3)
    em, he = 0.5 * (eb[1:] + eb[:-1]), 0.5 * (eb[1:] - eb[:-1])
    loc = p * np.arange(em.size)[:, None] + np.arange(p + 1)[None, :]
    return em[:, None] + he[:, None] * q, he[:, None] * w, _lagrange(p, q)[0], loc


def radial_moments(mesh: LiquidMesh, power: int) -> np.ndarray:
    """int_0^1 eta^power L_j(eta) d eta for every radial node j, shape (n_eta,).

    Parameters
    ----------
    mesh : LiquidMesh
        The mesh.
    power : int
        Exponent (>= 0).
    """
    eta, wt, val, loc = _radial_quadrature(mesh)
    out = np.zeros(mesh.eta_nodes.size)
    np.add.at(out, loc, (eta**power * wt) @ val)
    return out


def radial_mass(mesh: LiquidMesh) -> np.ndarray:
    """int_0^1 L_i L_j eta d eta over the radial nodes, shape (n_eta, n_eta).

    Parameters
    ----------
    mesh : LiquidMesh
        The mesh.
    """
    eta, wt, val, loc = _radial_quadrature(mesh)
    out = np.zeros((mesh.eta_nodes.size,) * 2)
    np.add.at(out, (loc[:, :, None], loc[:, None, :]),
              np.einsum("eg,ga,gb->eab", eta * wt, val, val))
    return out


def wall_trace(mesh: LiquidMesh, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The basis on the wall (eta = 1) at stations ``x``: axial node line i of each non-zero basis
    function, (n, p + 1) (node i n_eta + n_eta - 1), and its value.

    Parameters
    ----------
    mesh : LiquidMesh
        The mesh.
    x : ndarray, shape (n,)
        Stations (m) in x_a .. x_s.
    """
    p, xb = mesh.order, mesh.x_breaks
    el = np.clip(np.searchsorted(xb, x, side="right") - 1, 0, xb.size - 2)
    xi = np.clip((2.0 * x - xb[el] - xb[el + 1]) / (xb[el + 1] - xb[el]), -1.0, 1.0)
    return p * el[:, None] + np.arange(p + 1)[None, :], _lagrange(p, xi)[0]


def dof_index(mesh: LiquidMesh, k: int, *, open_surface: bool) -> tuple[np.ndarray, int]:
    """DOF of every node on the element edges (-1: Phi = 0 there, or interior) and their number.

    Phi = 0 on the axis for k >= 1, on a pressure-release end and, with ``open_surface``, on
    the free surface; an apex's nodes share one DOF (k = 0).

    Parameters
    ----------
    mesh : LiquidMesh
        The mesh.
    k : int
        Circumferential harmonic (>= 0).
    open_surface : bool
        Phi = 0 on the free surface.
    """
    tank, p = mesh.tank, mesh.order
    nx, ny = mesh.shape
    i, j = np.divmod(np.arange(nx * ny), ny)
    top_open = (open_surface and tank.fill < 1.0
                or tank.fill == 1.0 and tank.ends[1] == "pressure-release")
    phi0 = (i == 0) & (tank.ends[0] == "pressure-release") | (i == nx - 1) & top_open
    apex = [line for line, x in ((i == 0, mesh.x_nodes[0]), (i == nx - 1, mesh.x_nodes[-1]))
            if tank.radius(x) == 0.0]
    if k >= 1:
        phi0 |= j == 0
    primary = ~phi0 & ((i % p == 0) | (j % p == 0))  # element interiors are condensed
    for line in apex:
        primary &= ~line | (j == 0)  # one node of the apex carries its DOF
    index = np.full(nx * ny, -1)
    index[primary] = np.arange(int(primary.sum()))
    for line in apex:
        index[line] = index[line & (j == 0)][0]
    return index, int(primary.sum())


def condensed_operator(mesh: LiquidMesh, k: int, index: np.ndarray, n: int) -> sp.csc_matrix:
    """H = A + k^2 B (m^2, without c_k) on the DOFs of ``index``, sparse (n, n), the element
    interiors condensed statically (H_bb - H_bi H_ii^-1 H_ib, H_ii^-1 from the mesh's
    decomposition of the interiors' pencil: W diag(1 / (lambda + k^2)) W^T, W = H_bi V; by
    direct solves without it).

    Parameters
    ----------
    mesh : LiquidMesh
        The mesh.
    k : int
        Circumferential harmonic (>= 0).
    index, n : see :func:`dof_index`.
    """
    nb = 4 * mesh.order  # element-edge nodes, first in the element's node order
    k2 = float(k * k)
    if mesh.interior_values is None:  # a flat element: direct solves
        H = mesh.gradient + k2 * mesh.hoop
        hib = H[:, nb:, :nb]
        S = H[:, :nb, :nb] - hib.transpose(0, 2, 1) @ np.linalg.solve(H[:, nb:, nb:], hib)
    else:
        W = mesh.coupling_gradient + k2 * mesh.coupling_hoop
        S = (mesh.gradient[:, :nb, :nb] + k2 * mesh.hoop[:, :nb, :nb]
             - (W / (mesh.interior_values + k2)[:, None, :]) @ np.swapaxes(W, 1, 2))
    d = index[mesh.nodes[:, :nb]]
    keep = (d[:, :, None] >= 0) & (d[:, None, :] >= 0)
    rows = np.broadcast_to(d[:, :, None], S.shape)[keep]
    cols = np.broadcast_to(d[:, None, :], S.shape)[keep]
    return sp.coo_matrix((S[keep], (rows, cols)), shape=(n, n)).tocsc()
