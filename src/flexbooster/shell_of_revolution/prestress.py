"""The axisymmetric membrane prestate of a vehicle under its thrust and other axisymmetric loads.

A load case is an axial force on the aft edge plus surface loads p_x, p_r at the Gauss
points; the load path (:data:`LOAD_PATHS`) balances them by inertia relief or an end support.
The membrane state is then statically determinate: F(s) = F(0) + int_0^s 2 pi r p_x ds',
N_s = -F / (2 pi r cos(phi)), N_theta = r p_n / cos(phi), and where the meridian turns a ring
carries H = r (N_s^fwd sin(phi_fwd) - N_s^aft sin(phi_aft)). Every K_g of the package is built
from (N_s, N_theta, H). Theory: docs/theory/shell-of-revolution.md.

References: W. Fluegge, *Stresses in Shells*, 1973, sec. 2.2; D. O. Brush, B. O. Almroth,
*Buckling of Bars, Plates and Shells*, 1975, sec. 5.3.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import TYPE_CHECKING

import numpy as np
from numpy.polynomial import legendre as leg

from ..checks import finite, finite_array
from .elements import reference_element
from .geometry import tank_liquid
from .mesh import Mesh

if TYPE_CHECKING:
    from .geometry import Vehicle

__all__ = ["AXIAL_SUPPORTS", "LOAD_PATHS", "Prestate", "AttachedLoads", "attached_loads",
           "load_path", "membrane_prestate", "pressure_resultants", "pressure_rings",
           "total_mass"]

#: End conditions that restrain the axial motion of an edge (u = 0).
AXIAL_SUPPORTS = ("hinged", "clamped")
#: What balances the axial loads (see the module docstring).
LOAD_PATHS = ("inertia relief", "forward support", "aft support")


def load_path(vehicle: Vehicle, supported_forward_end: bool | None = None) -> str:
    """The load path of the thrust, one of :data:`LOAD_PATHS`.

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle (its ``aft_end`` and ``fwd_end``).
    supported_forward_end : bool or None
        None: from the ends (aft end in :data:`AXIAL_SUPPORTS`: "aft support"; else forward end
        in it: "forward support"; else "inertia relief"). True: "forward support" whatever the
        ends; False: "inertia relief".
    """
    if supported_forward_end is not None:
        if not isinstance(supported_forward_end, bool | np.bool_):
            raise ValueError(f"supported_forward_end = {supported_forward_end!r}: must be "
                             "None or a bool")
        return "forward support" if supported_forward_end else "inertia relief"
    if vehicle.aft_end in AXIAL_SUPPORTS:
        return "aft support"
    return "forward support" if vehicle.fwd_end in AXIAL_SUPPORTS else "inertia relief"


@dataclass(frozen=True)
class Prestate:
    """Membrane prestate of a vehicle: resultants at the Gauss points, ring forces at nodes.

    Attributes
    ----------
    load_path : str
        One of :data:`LOAD_PATHS`.
    force : ndarray, shape (e, g)
        Axial force carried by the shell, compression positive (N).
    meridional, hoop : ndarray, shape (e, g)
        N_s and N_theta (N/m, tension positive).
    ring_node : ndarray of int, shape (m,)
        Full DOF index of the first DOF of each ring's node.
    ring_frame, ring_radius, ring_force : ndarray, shape (m,)
        Angle of the node's frame (rad; 0 global, phi local), radius (m) and hoop force H (N,
        tension positive) of each ring.
    """

    load_path: str
    force: np.ndarray
    meridional: np.ndarray
    hoop: np.ndarray
    ring_node: np.ndarray
    ring_frame: np.ndarray
    ring_radius: np.ndarray
    ring_force: np.ndarray


@lru_cache(maxsize=16)
def _cumulative(order: int) -> np.ndarray:
    """(g, g) matrix S: int_{-1}^{xi_i} f dxi = S @ f(xi) for f of degree < g at the Gauss
    points of ``reference_element(order)`` (exact for those polynomials)."""
    xi = reference_element(order).xi
    coef = np.linalg.inv(leg.legvander(xi, xi.size - 1))  # Lagrange basis at the points
    out = leg.legval(xi, leg.legint(coef, lbnd=-1.0)).T
    out.setflags(write=False)
    return out


def membrane_prestate(mesh: Mesh, path: str, *, aft_force: float,
                      axial: np.ndarray | None = None, radial: np.ndarray | None = None,
                      point_forces: tuple = ()) -> Prestate:
    """Membrane resultants and ring forces of one axisymmetric load case (Fluegge 1973, sec. 2.2);
    ValueError for a loaded flat plate (no membrane state) or bad input.

    Parameters
    ----------
    mesh : Mesh
        Mesh of the vehicle (:func:`~.assembly.mesh_vehicle`).
    path : str
        Load path, one of :data:`LOAD_PATHS`.
    aft_force : float
        Axial force on the aft edge (N), forward positive (the thrust F0).
    axial, radial : ndarray, shape (e, g), optional
        Surface loads p_x, p_r at the Gauss points (Pa), integrated as polynomials of degree < g.
    point_forces : sequence of (float, float)
        Axial forces (N, forward positive) on the wall's ring at axial stations (m): the
        d'Alembert loads of attached masses, a tank's liquid on its aft end.
    """
    if path not in LOAD_PATHS:
        raise ValueError(f"path = {path!r}: must be one of {LOAD_PATHS}")
    aft_force = finite("aft_force", aft_force)
    ref = reference_element(mesh.order)
    half = 0.5 * mesh.length[:, None]
    t = (1.0 + ref.xi)[None, :] * half
    r = mesh.r1[:, None] + t * mesh.sin_phi[:, None]
    zeros = np.zeros_like(r)
    px = zeros if axial is None else finite_array("axial", axial) * np.ones_like(r)
    pr = zeros if radial is None else finite_array("radial", radial) * np.ones_like(r)

    def integral(f):  # int 2 pi r f ds over each element (Gauss: exact for r f of degree < 2g)
        return (2.0 * np.pi * r * f * half) @ ref.weight

    points = np.array([(finite("point_forces", x), finite("point_forces", f))
                       for x, f in point_forces]).reshape(-1, 2)
    x_g = mesh.x1[:, None] + t * mesh.cos_phi[:, None]
    x_end = mesh.x1 + mesh.length * mesh.cos_phi

    def carried(x, strict=False):  # the point forces aft of x (or at x), summed (N)
        aft = points[:, 0] < x[..., None] if strict else points[:, 0] <= x[..., None]
        return (points[:, 1] * aft).sum(axis=-1)

    if path == "inertia relief":  # a = P / m: the body load -rho h a (d'Alembert)
        rho_h = mesh.wall_mass
        accel = ((aft_force + integral(px).sum() + points[:, 1].sum())
                 / integral(rho_h[:, None] + zeros).sum())
        px = px - rho_h[:, None] * accel
    line = 2.0 * np.pi * r * px  # axial load per unit meridian length (N/m)
    total = integral(px)
    before = np.concatenate(([0.0], np.cumsum(total)[:-1]))
    start = -total.sum() - points[:, 1].sum() if path == "aft support" else aft_force
    # F just ahead of the aft edge, then the distributed and the point loads aft of each point
    force = start + before[:, None] + half * (line @ _cumulative(mesh.order).T)
    if points.size:
        force = force + carried(x_g)
    p_n = -px * mesh.sin_phi[:, None] + pr * mesh.cos_phi[:, None]
    flat = np.abs(mesh.cos_phi) < 1e-12
    scale = max(abs(aft_force), float(np.max(np.abs(line), initial=0.0)) * mesh.length.sum())
    loaded = np.any(np.abs(force[flat]) > 1e-12 * scale) or np.any(p_n[flat] != 0.0)
    if np.any(flat) and loaded:
        raise ValueError("cos_phi = 0 (a flat annular plate): cannot carry the axial load as a "
                         "membrane (N_s = -F / (2 pi r cos(phi)))")
    cos = np.where(flat, 1.0, mesh.cos_phi)[:, None]
    meridional = np.where(flat[:, None], 0.0, -force / (2.0 * np.pi * r * cos))  # Flügge 2.2
    hoop = np.where(flat[:, None], 0.0, r * p_n / cos)  # normal equilibrium, 1/R_s = 0
    # rings where the meridian turns: each segment's edges (inside a segment phi is constant)
    f_end = start + before + total + (carried(x_end, True) if points.size else 0.0)

    def edge_ns(e, end, rad, cos_e):  # N_s of the axial force carried at the edge
        fax = f_end[e] if end else start + before[e] + (
            carried(np.asarray(mesh.x1[e])) if points.size else 0.0)
        return -fax / (2.0 * np.pi * rad * cos_e)

    rings = _junction_rings(mesh, edge_ns)
    return Prestate(load_path=path, force=force, meridional=meridional, hoop=hoop,
                    ring_node=rings[0], ring_frame=rings[1], ring_radius=rings[2],
                    ring_force=rings[3])


def _junction_rings(mesh: Mesh, edge_ns) -> tuple:
    """(node, frame, radius, H) arrays of the rings at both edges of every cone segment (inside
    a segment phi is constant): H = r N_s sin(phi) of the shell beyond the edge, N_s =
    ``edge_ns(element, end, r, cos(phi))`` (end 0 aft, 1 forward).
    """
    r_end = mesh.r1 + mesh.length * mesh.sin_phi
    nodes, frames, radii, hoops = [], [], [], []
    for i in range(len(mesh.elements_per_segment)):
        el = np.nonzero(mesh.segment == i)[0]
        first, last = el[0], el[-1]
        sin, cos_i = mesh.sin_phi[first], mesh.cos_phi[first]
        if sin == 0.0 or abs(cos_i) < 1e-12:
            continue
        for e, end, node, frame, rad, sign in (
                (first, 0, mesh.dofs[first, 0], mesh.frame[first, 0], mesh.r1[first], 1.0),
                (last, 1, mesh.dofs[last, 4], mesh.frame[last, 1], r_end[last], -1.0)):
            nodes.append(node)
            frames.append(frame)
            radii.append(rad)
            hoops.append(sign * rad * edge_ns(e, end, rad, cos_i) * sin)
    return (np.array(nodes, dtype=int), np.array(frames), np.array(radii), np.array(hoops))


def pressure_resultants(mesh: Mesh) -> tuple[np.ndarray, np.ndarray] | None:
    """Membrane resultants (N_s, N_theta) at the Gauss points (N/m) of each element's internal
    gauge pressure p in a closed tank: N_theta = p r / cos(phi), N_s = p r / (2 cos(phi))
    (Fluegge 1973, sec. 2.2; 0 on a flat plate, which carries its pressure in bending); None
    without pressure.

    Parameters
    ----------
    mesh : Mesh
        Mesh of the vehicle (its ``pressure``).
    """
    if mesh.pressure is None:
        return None
    ref = reference_element(mesh.order)
    r = mesh.r1[:, None] + (0.5 * (1.0 + ref.xi))[None, :] * (mesh.length * mesh.sin_phi)[:, None]
    flat = np.abs(mesh.cos_phi) < 1e-12
    hoop = np.where(flat, 0.0, mesh.pressure / np.where(flat, 1.0, mesh.cos_phi))[:, None] * r
    return 0.5 * hoop, hoop


def pressure_rings(mesh: Mesh) -> Prestate | None:
    """The rings of the internal pressure where the meridian turns: at each edge of a
    pressurised cone the meridional resultant N_s = p r / (2 cos(phi)) of
    :func:`pressure_resultants` has the radial component N_s sin(phi), which the junction
    carries as a hoop force H = r N_s sin(phi) = p r^2 tan(phi) / 2 (aft edge; the opposite
    sign at the forward edge: the cone lies on the other side), tension positive (membrane
    equilibrium of the junction ring, Fluegge 1973, sec. 2.2; a cone converging forward puts
    its aft junction in compression). A :class:`Prestate` with these rings and no resultants
    (load path "pressure"; its K_g is fixed, as the pressure's), None without a pressurised
    cone.

    Parameters
    ----------
    mesh : Mesh
        Mesh of the vehicle (its ``pressure``).
    """
    if mesh.pressure is None:
        return None
    rings = _junction_rings(mesh, lambda e, end, rad, cos_e: mesh.pressure[e] * rad
                            / (2.0 * cos_e))
    on = rings[3] != 0.0  # the pressurised cones
    if not np.any(on):
        return None
    nodes, frames, radii, hoops = (a[on] for a in rings)
    zeros = np.zeros((mesh.n_elements, reference_element(mesh.order).xi.size))
    return Prestate(load_path="pressure", force=zeros, meridional=zeros, hoop=zeros,
                    ring_node=nodes, ring_frame=frames, ring_radius=radii, ring_force=hoops)


def _gauss_points(mesh: Mesh) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Axial station x, radius r (m) and weight 2 pi r ds (m^2) of every element's Gauss points,
    each (e, g)."""
    ref = reference_element(mesh.order)
    t = (0.5 * (1.0 + ref.xi))[None, :] * mesh.length[:, None]
    r = mesh.r1[:, None] + t * mesh.sin_phi[:, None]
    x = mesh.x1[:, None] + t * mesh.cos_phi[:, None]
    return x, r, 2.0 * np.pi * r * (0.5 * mesh.length)[:, None] * ref.weight[None, :]


def total_mass(vehicle: Vehicle, mesh: Mesh) -> float:
    """Mass of the walls (Gauss quadrature of the areal mass, exact), the lumped masses and the
    tanks' liquid (kg).

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    mesh : Mesh
        Its mesh.
    """
    wall = float((mesh.wall_mass[:, None] * _gauss_points(mesh)[2]).sum())
    return (wall + sum(m.mass for m in vehicle.masses)
            + sum(tank_liquid(vehicle, t).liquid_mass() for t in vehicle.tanks))


@dataclass(frozen=True)
class AttachedLoads:
    """Loads on the wall of the masses and liquid attached to it under an axial acceleration.

    Attributes
    ----------
    axial, radial : ndarray, shape (e, g)
        Surface loads p_x, p_r (Pa) at the Gauss points (the liquid's hydrostatic head).
    point_forces : tuple of (float, float)
        (station m, axial force N, forward positive): -m a of each lumped mass at its station,
        -p(x_a) A(x_a) of each tank's liquid on its aft end.
    """

    axial: np.ndarray
    radial: np.ndarray
    point_forces: tuple


def attached_loads(vehicle: Vehicle, mesh: Mesh, *, acceleration: float) -> AttachedLoads:
    """d'Alembert loads of the lumped masses and the hydrostatic head p = rho_L a (x_s - x) of
    each tank's liquid on its wetted wall (normal pressure: p_x = -p sin(phi),
    p_r = p cos(phi)) and aft end, under the forward acceleration a (Abramson 1966, ch. 1;
    Fluegge 1973, sec. 2.2). The liquid's loads sum to -m_L a (divergence theorem).

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle (its masses and tanks).
    mesh : Mesh
        Its mesh.
    acceleration : float
        Forward axial acceleration a (m/s^2).
    """
    a = finite("acceleration", acceleration)
    x, _, _ = _gauss_points(mesh)
    axial, radial = np.zeros_like(x), np.zeros_like(x)
    points = [(m.station, -m.mass * a) for m in vehicle.masses]
    x_end = mesh.x1 + mesh.length * mesh.cos_phi
    tol = 1e-9 * max(float(x_end.max()), 1e-300)
    for t in vehicle.tanks:
        if t.fill == 0.0:
            continue
        liquid = tank_liquid(vehicle, t)
        wall = (mesh.cos_phi > 1e-12) & (mesh.x1 >= t.aft - tol) & (x_end <= t.fwd + tol)
        p = np.where(wall[:, None], t.density * a * np.clip(liquid.surface - x, 0.0, None), 0.0)
        axial -= p * mesh.sin_phi[:, None]
        radial += p * mesh.cos_phi[:, None]
        r_a = float(liquid.radius(t.aft))
        points.append((t.aft, -t.density * a * (liquid.surface - t.aft) * np.pi * r_a**2))
    return AttachedLoads(axial=axial, radial=radial, point_forces=tuple(points))
