"""Meridian mesh, DOF map with the end and junction constraints, and global matrices per k.

Segments are cut into conical elements; node DOFs (a, v, b, chi) are element-local (u, w)
inside a segment and at the ends, global (u_x, u_r) at junction nodes (each segment keeps
its own), chi = dw/ds (Zienkiewicz & Taylor vol. 2, sec. 10.3). Constraints map every full
DOF to one reduced DOF with a coefficient +-1, or eliminate it: ends "free",
"shear-diaphragm", "hinged", "clamped"; junctions "continuous", "rigid-bulkhead" (a rigid
weightless disc hinged to both edges) and "memo-bulkhead" (rigid in its plane only: a shear
diaphragm for k >= 2, memo appendix D-II). Kinematics table: docs/theory/shell-of-revolution.md.

References: O. C. Zienkiewicz, R. L. Taylor, *The Finite Element Method*, vol. 2, 2000,
sec. 10.3; D. Bushnell, Computers & Structures 4 (1974) 399-435 (BOSOR); Tech Memo 104,
Fig. 1 and appendix D-II.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields

import numpy as np

from ..checks import count, finite
from .elements import (
    ElementFields,
    einsum,
    element_fields,
    field_matrices,
    geometric_matrices,
    reference_element,
    theta_weight,
)
from .geometry import Cylinder, Vehicle, stiffener_matrix, wall_masses
from .mesh import Mesh
from .prestress import (
    Prestate,
    attached_loads,
    load_path,
    membrane_prestate,
    pressure_resultants,
    pressure_rings,
    total_mass,
)
from .shared import shell_value

__all__ = [
    "DEFAULT_ORDER",
    "Mesh",
    "DofMap",
    "mesh_vehicle",
    "dof_map",
    "assemble",
    "system_matrices",
    "rigid_body_fields",
    "element_set",
    "ring_matrix",
    "ring_rows",
    "lumped_mass_matrix",
    "pressure_ring_matrix",
    "node_transform",
    "auto_element_counts",
    "MAX_ELEMENTS",
    "thrust_prestate",
    "HarmonicMatrices",
    "harmonic_matrices",
    "ShellHarmonic",
    "shell_harmonic",
]

#: Default polynomial degree of the elements.
DEFAULT_ORDER = 6
#: Largest element count per segment.
MAX_ELEMENTS = 400
#: Growth ratio of the element lengths of the automatic mesh away from segment ends.
GRADING = 2.5
#: Longest element of the automatic mesh, in radii.
MAX_ELEMENT_RADII = 3.0
#: First element at a segment end of the automatic mesh, in units of sqrt(R h) (at p = 6).
EDGE_ELEMENT = 3.0


def _auto_breaks(seg, meridian: float, order: int) -> np.ndarray:
    """Graded element breakpoints (0..meridian, m) of a segment: first element l_b = 2 sqrt(R h)
    (6 / p) at each end (Kraus sec. 7.3), growing by GRADING up to MAX_ELEMENT_RADII R_max.
    """
    rmax = max(seg.radius_aft, seg.radius_fwd)
    l_b = EDGE_ELEMENT * math.sqrt(rmax * seg.thickness) * 6.0 / order
    l_max = max(l_b, MAX_ELEMENT_RADII * rmax)
    sizes = []
    total, size = 0.0, l_b
    while 2.0 * (total + size) < meridian and size < l_max:
        sizes.append(size)
        total += size
        size *= GRADING
    middle = meridian - 2.0 * total
    n_mid = max(1, math.ceil(middle / l_max - 1e-9)) if middle > 1e-12 * meridian else 0
    lengths = sizes + [middle / n_mid] * n_mid + sizes[::-1]
    if len(lengths) < 2:
        lengths = [meridian / 2.0] * 2
    breaks = np.concatenate(([0.0], np.cumsum(lengths)))
    breaks[-1] = meridian
    return breaks


def auto_element_counts(vehicle: Vehicle, *, order: int = DEFAULT_ORDER) -> tuple[int, ...]:
    """Element count per segment of the automatic (graded) mesh of :func:`mesh_vehicle`,
    without building it: a segment longer than about ``MAX_ELEMENTS * MAX_ELEMENT_RADII`` radii
    needs more than :data:`MAX_ELEMENTS`, which :func:`mesh_vehicle` refuses.

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    order : int
        Polynomial degree p, 3..12.
    """
    order = count("order", order, 3, 12)
    return tuple(_auto_breaks(seg, lm, order).size - 1
                 for seg, lm in zip(vehicle.segments, vehicle.meridian_lengths(), strict=True))


def mesh_vehicle(
    vehicle: Vehicle, *, elements_per_segment: int | tuple | None = None,
    order: int = DEFAULT_ORDER, refinement: int = 1,
) -> Mesh:
    """Cut the meridian into conical elements of degree ``order``.

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    elements_per_segment : int or sequence of int, optional
        Elements per segment, 1..400, one for all or one per segment; None: a graded mesh
        (docs/theory/shell-of-revolution.md; Kraus 1967, sec. 7.3).
    order : int
        Polynomial degree p, 3..12.
    refinement : int
        Split every element into this many equal ones, 1..64.
    """
    order = count("order", order, 3, 12)
    refinement = count("refinement", refinement, 1, 64)
    ref = reference_element(order)
    segs = vehicle.segments
    nseg = len(segs)
    if elements_per_segment is None:
        breaks = [_auto_breaks(seg, lm, order)
                  for seg, lm in zip(segs, vehicle.meridian_lengths(), strict=True)]
    else:
        raw = (elements_per_segment,) * nseg if not isinstance(
            elements_per_segment, tuple | list) else tuple(elements_per_segment)
        if len(raw) != nseg:
            raise ValueError(f"elements_per_segment = {elements_per_segment!r}: need one "
                             f"value or {nseg}")
        counts = tuple(count("elements_per_segment", c, 1, MAX_ELEMENTS) for c in raw)
        breaks = [np.linspace(0.0, lm, c + 1)
                  for c, lm in zip(counts, vehicle.meridian_lengths(), strict=True)]
    if refinement > 1:
        frac = np.arange(refinement) / refinement
        breaks = [np.append((b[:-1, None] + frac[None, :] * np.diff(b)[:, None]).ravel(), b[-1])
                  for b in breaks]
    counts = tuple(b.size - 1 for b in breaks)
    if max(counts) > MAX_ELEMENTS:
        raise ValueError(f"refinement = {refinement}: more than {MAX_ELEMENTS} elements in a "
                         "segment")
    n_int = 3 * order - 5
    cols = {key: [] for key in ("segment", "s1", "x1", "r1", "length", "sin", "cos",
                                 "h", "E", "nu", "rho")}
    dofs, frames, end_nodes = [], [], []
    offset, s0, x0 = 0, 0.0, 0.0
    for i, (seg, ne) in enumerate(zip(segs, counts, strict=True)):
        r_a, r_f = seg.radius_aft, seg.radius_fwd
        lm = math.hypot(seg.length, r_f - r_a)
        sa, ca = (r_f - r_a) / lm, seg.length / lm
        if isinstance(seg, Cylinder):
            sa, ca = 0.0, 1.0
        t = breaks[i][:-1]
        cols["segment"].append(np.full(ne, i))
        cols["s1"].append(s0 + t)
        cols["x1"].append(x0 + t * ca)
        cols["r1"].append(r_a + t * sa)
        cols["length"].append(np.diff(breaks[i]))
        cols["sin"].append(np.full(ne, sa))
        cols["cos"].append(np.full(ne, ca))
        for key, val in (("h", seg.thickness), ("E", seg.E), ("nu", seg.nu), ("rho", seg.rho)):
            cols[key].append(np.full(ne, val))
        node = offset + 4 * np.arange(ne)
        inner = offset + 4 * (ne + 1) + n_int * np.arange(ne)
        el = np.concatenate([node[:, None] + np.arange(4), node[:, None] + 4 + np.arange(4),
                             inner[:, None] + np.arange(n_int)], axis=1)
        dofs.append(el)
        phi = math.atan2(sa, ca)
        fr = np.full((ne, 2), phi)
        if i > 0:
            fr[0, 0] = 0.0  # junction node: global frame
        if i < nseg - 1:
            fr[-1, 1] = 0.0
        frames.append(fr)
        end_nodes.append((offset, offset + 4 * ne))
        offset += 4 * (ne + 1) + n_int * ne
        s0 += lm
        x0 += seg.length
    cat = {key: np.concatenate(val) for key, val in cols.items()}
    ends = (end_nodes[0][0], end_nodes[-1][1]) + tuple(
        (end_nodes[i][1], end_nodes[i + 1][0]) for i in range(nseg - 1))
    assert ref.n_dof == dofs[0].shape[1]
    seg_of = cat["segment"].astype(int)
    return Mesh(**_wall_extras(segs, seg_of), order=order, segment=seg_of, s1=cat["s1"],
                x1=cat["x1"],
                r1=cat["r1"], length=cat["length"], sin_phi=cat["sin"], cos_phi=cat["cos"],
                phi=np.arctan2(cat["sin"], cat["cos"]), thickness=cat["h"], E=cat["E"],
                nu=cat["nu"], rho=cat["rho"], elements_per_segment=counts,
                dofs=np.concatenate(dofs), frame=np.concatenate(frames), n_full=offset,
                end_nodes=ends)


def _wall_extras(segs, seg_of: np.ndarray) -> dict:
    """Mesh fields of the optional wall data (areal mass, pressure, stiffening), only where a
    segment has them (the bare shell's arrays stay None)."""
    out = {}
    areal = np.array([sum(wall_masses(seg)) for seg in segs])
    if any(seg.nonstructural_mass or seg.rings or seg.stringers for seg in segs):
        out["areal_mass"] = areal[seg_of]
    if any(seg.pressure for seg in segs):
        out["pressure"] = np.array([seg.pressure for seg in segs])[seg_of]
    stiff = [stiffener_matrix(seg) for seg in segs]
    if any(m is not None for m in stiff):
        out["stiffening"] = np.array([np.zeros((6, 6)) if m is None else m
                                      for m in stiff])[seg_of]
    return out


@dataclass(frozen=True)
class DofMap:
    """Full DOF -> reduced DOF map for one harmonic.

    Attributes
    ----------
    index : ndarray of int, shape (n_full,)
        Reduced DOF of every full DOF, -1 where eliminated.
    coef : ndarray of float, shape (n_full,)
        Coefficient (+1 or -1) of the full DOF in terms of its reduced DOF.
    n : int
        Number of reduced DOFs.
    """

    index: np.ndarray
    coef: np.ndarray
    n: int

    def expand(self, reduced: np.ndarray) -> np.ndarray:
        """Full DOF values (..., n_full) of reduced vectors (..., n), 0 where eliminated.

        Parameters
        ----------
        reduced : ndarray, shape (..., n)
            Reduced DOF values (m or rad).
        """
        reduced = np.asarray(reduced)
        pad = np.concatenate([reduced, np.zeros(reduced.shape[:-1] + (1,))], axis=-1)
        return pad[..., self.index] * self.coef


def _k_class(k: int) -> int:
    return min(k, 2)


def dof_map(vehicle: Vehicle, mesh: Mesh, k: int) -> DofMap:
    """Constraint map of the end conditions and junctions for harmonic k (Leissa 1973 sec. 1.6).

    Parameters
    ----------
    vehicle : Vehicle
        End conditions and junction types.
    mesh : Mesh
        Mesh of the vehicle.
    k : int
        Circumferential wave number, >= 0.
    """
    k = count("k", k, 0, 200)
    segs = vehicle.segments
    radii = tuple((segs[i].radius_fwd, segs[i + 1].radius_aft) for i in range(len(segs) - 1))
    return _dof_map(vehicle.aft_end, vehicle.fwd_end, vehicle.junctions, mesh.end_nodes,
                    mesh.n_full, _k_class(k), radii)


def _dof_map(aft_end, fwd_end, junctions, end_nodes, n_full, kc, radii) -> DofMap:
    alias: dict[int, tuple[int, float]] = {}
    elim: set[int] = set()
    # node DOF order (a, v, b, chi): 0 = u or u_x, 1 = v, 2 = w or u_r, 3 = chi
    for node, cond in ((end_nodes[0], aft_end), (end_nodes[1], fwd_end)):
        if cond == "shear-diaphragm":
            elim.update((node + 1, node + 2))  # v = w = 0 (Leissa 1.6)
        elif cond == "hinged":
            elim.update((node, node + 1, node + 2))  # u = v = w = 0
        elif cond == "clamped":
            elim.update(node + j for j in range(4))
    for (na, nb), kind, (ra, rb) in zip(end_nodes[2:], junctions, radii, strict=True):
        if kind == "continuous":
            for j in range(4):
                alias[nb + j] = (na + j, 1.0)
            continue
        # rigid weightless disc, hinged to both edges (chi free on each side)
        if kc == 0:  # axial translation u_x and rotation about the axis v = r omega_x
            alias[nb] = (na, 1.0)
            alias[nb + 1] = (na + 1, rb / ra)
            elim.update((na + 2, nb + 2))  # no radial expansion
        elif kc == 1:  # lateral translation u_r = -v = D, tilt u_x = -r psi
            alias[nb] = (na, rb / ra)
            alias[na + 2] = (na + 1, -1.0)
            alias[nb + 1] = (na + 1, 1.0)
            alias[nb + 2] = (na + 1, -1.0)
        else:  # rigid in its plane: u_r = v = 0; rigid-bulkhead also out of plane
            elim.update((na + 1, na + 2, nb + 1, nb + 2))
            if kind == "rigid-bulkhead":
                elim.update((na, nb))
    index = np.full(n_full, -1, dtype=int)
    coef = np.ones(n_full)
    src = np.array(sorted(alias), dtype=int)
    tgt = np.array([alias[f][0] for f in src], dtype=int)
    primary = np.ones(n_full, dtype=bool)
    primary[list(elim)] = False
    primary[src] = False
    n = int(np.count_nonzero(primary))
    index[primary] = np.arange(n)
    if src.size:  # every alias points at a primary DOF of the aft-side node
        index[src] = index[tgt]
        coef[src] = [alias[f][1] for f in src]
    index.setflags(write=False)
    coef.setflags(write=False)
    return DofMap(index=index, coef=coef, n=n)


def node_transform(mesh: Mesh) -> np.ndarray:
    """Node-frame -> element-local rotation of the (u, w) pairs, shape (e, n_dof, n_dof).

    Parameters
    ----------
    mesh : Mesh
        The mesh (its node frames and element meridian angles).
    """
    ne = mesh.n_elements
    nd = mesh.dofs.shape[1]
    T = np.broadcast_to(np.eye(nd), (ne, nd, nd)).copy()
    for end, (iu, iw) in enumerate(((0, 2), (4, 6))):
        delta = mesh.phi - mesh.frame[:, end]
        c, s = np.cos(delta), np.sin(delta)
        T[:, iu, iu] = c  # u = a cos(delta) + b sin(delta)
        T[:, iu, iw] = s
        T[:, iw, iu] = -s  # w = -a sin(delta) + b cos(delta)
        T[:, iw, iw] = c
    return T


def thrust_prestate(vehicle: Vehicle, mesh: Mesh, F0: float, *,
                    supported_forward_end: bool | None = None) -> Prestate:
    """The membrane prestate of the steady thrust F0 at the aft edge (:mod:`.prestress`); under
    inertia relief with lumped masses or tanks, their loads at the acceleration
    a = F0 / m_total (:func:`.prestress.attached_loads`: the liquid's hydrostatic head).

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle (its ends give the load path).
    mesh : Mesh
        Mesh of the vehicle.
    F0 : float
        Thrust at the aft edge (N).
    supported_forward_end : bool or None
        Load path (:func:`.prestress.load_path`): None from the ends, True the nose reacts the
        thrust, False inertia relief.
    """
    F0 = finite("prestress_F0", F0)
    path = load_path(vehicle, supported_forward_end)
    if F0 != 0.0 and np.any(np.abs(mesh.cos_phi) < 1e-12):
        raise ValueError(f"prestress_F0 = {F0!r}: a flat annular plate cannot carry the axial "
                         "force as a membrane (N_s = -F / (2 pi r cos(phi)))")
    if path != "inertia relief" or not (vehicle.masses or vehicle.tanks):
        return membrane_prestate(mesh, path, aft_force=F0)
    loads = attached_loads(vehicle, mesh, acceleration=F0 / total_mass(vehicle, mesh))
    return membrane_prestate(mesh, path, aft_force=F0, axial=loads.axial, radial=loads.radial,
                             point_forces=loads.point_forces)


def element_set(vehicle: Vehicle, mesh: Mesh, k: int, *, prestate: Prestate | None = None):
    """Element matrices M (kg), K_e, K_g (N/m) of harmonic k in the node frames (T^T K T), each
    (e, n_dof, n_dof); K_g None without ``prestate`` (rings: :func:`ring_matrix`). K_e holds
    the geometric stiffness of the internal pressure (:func:`.prestress.pressure_resultants`),
    which does not scale with the thrust.

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle (its theory).
    mesh : Mesh
        Mesh of the vehicle.
    k : int
        Circumferential wave number, >= 0.
    prestate : Prestate, optional
        Membrane prestate of the geometric stiffness (None: no K_g).
    """
    f = _element_fields(vehicle, mesh, k)
    T = node_transform(mesh)
    return _shell_elements(mesh, f, T) + (
        None if prestate is None else _geometric_elements(f, T, prestate),)


def _shell_elements(mesh: Mesh, f: ElementFields, T: np.ndarray) -> tuple:
    """(M, K_e) of every element in the node frames (K_e with the pressure's prestress)."""
    return tuple(_node_frames(T, mat) for mat in field_matrices(
        f, _areal_mass(mesh), fixed_prestress=pressure_resultants(mesh)))


def _geometric_elements(f: ElementFields, T: np.ndarray, prestate: Prestate) -> np.ndarray:
    """K_g of every element in the node frames, of the prestate's membrane resultants."""
    return _node_frames(T, geometric_matrices(f, prestate.meridional, prestate.hoop))


def _element_fields(vehicle: Vehicle, mesh: Mesh, k: int) -> ElementFields:
    """:func:`.elements.element_fields` of the mesh's elements, harmonic k."""
    return element_fields(reference_element(mesh.order), k, r1=mesh.r1, length=mesh.length,
                          sin_phi=mesh.sin_phi, cos_phi=mesh.cos_phi, thickness=mesh.thickness,
                          E=mesh.E, nu=mesh.nu, theory=vehicle.theory,
                          stiffening=mesh.stiffening)


def _areal_mass(mesh: Mesh) -> np.ndarray:
    """The wall's mass per unit area (kg/m^2): rho h, or the mesh's own (stiffeners, etc.)."""
    return mesh.rho * mesh.thickness if mesh.areal_mass is None else mesh.areal_mass


def _node_frames(T: np.ndarray, mat: np.ndarray) -> np.ndarray:
    """Element matrices (e, n_dof, n_dof) from the element-local DOFs to the node frames."""
    return einsum("eia,eij,ejb->eab", T, mat, T)


def ring_matrix(theory: str, dmap: DofMap, prestate: Prestate, k: int) -> np.ndarray:
    """Geometric stiffness (N/m) of the prestate's rings for harmonic k, reduced (n, n):
    K_g,ring = theta_weight(k) (H / r) [c k^2 U_x^2 + (k U_r + c V)^2], c = 1 Sanders,
    0 Donnell (Kraus 1967 ch. 2; Fluegge 1973 sec. 2.2).

    Parameters
    ----------
    theory : str
        ``"sanders"`` or ``"donnell"`` (the vehicle's).
    dmap : DofMap
        Constraint map of harmonic k.
    prestate : Prestate
        The prestate (its rings).
    k : int
        Circumferential wave number, >= 0.
    """
    c = 1.0 if theory == "sanders" else 0.0
    out = np.zeros((dmap.n, dmap.n))
    for node, frame, rad, hoop in zip(prestate.ring_node, prestate.ring_frame,
                                      prestate.ring_radius, prestate.ring_force, strict=True):
        cf, sf = np.cos(frame), np.sin(frame)  # u_x = a cos f - b sin f, u_r = a sin f + b cos f
        grads = np.array([[c * k * cf, 0.0, -c * k * sf], [k * sf, c, k * cf]])  # (a, v, b)
        local = theta_weight(k) * hoop / rad * (grads.T @ grads)
        idx = dmap.index[node:node + 3]
        cof = dmap.coef[node:node + 3]
        keep = idx >= 0  # (two DOFs of a bulkhead's edge may share one reduced DOF)
        sel = idx[keep]
        vals = (local * cof[:, None] * cof[None, :])[np.ix_(keep, keep)]
        np.add.at(out, (np.repeat(sel, sel.size), np.tile(sel, sel.size)), vals.ravel())
    return out


def pressure_ring_matrix(vehicle: Vehicle, mesh: Mesh, dmap: DofMap, k: int) -> np.ndarray | None:
    """Fixed geometric stiffness (N/m, reduced (n, n)) of the internal pressure's junction rings
    (:func:`.prestress.pressure_rings`, :func:`ring_matrix`), part of K_e; None without them.

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle (its theory).
    mesh : Mesh
        Mesh of the vehicle.
    dmap : DofMap
        Constraint map of harmonic k.
    k : int
        Circumferential wave number, >= 0.
    """
    rings = pressure_rings(mesh)
    return None if rings is None else ring_matrix(vehicle.theory, dmap, rings, k)


def ring_rows(mesh: Mesh, dmap: DofMap, station: float) -> tuple[np.ndarray, float]:
    """Rows (3, n) over the reduced DOFs giving the amplitudes (u_x, u_r, v) of the wall's ring
    at an axial station (m from the aft edge), from the shape functions of the (first) non-flat
    element that contains it, and the ring's radius (m).

    Parameters
    ----------
    mesh : Mesh
        Mesh of the vehicle.
    dmap : DofMap
        Constraint map of the harmonic.
    station : float
        Axial station x (m), within the vehicle.
    """
    x2 = mesh.x1 + mesh.length * mesh.cos_phi
    tol = 1e-9 * x2.max()
    at = np.flatnonzero((mesh.x1 - tol <= station) & (station <= x2 + tol) & (mesh.cos_phi > 0))
    if at.size == 0:
        raise ValueError(f"station = {station!r}: not on the vehicle's wall")
    e = int(at[0])
    ref = reference_element(mesh.order)
    xi = np.clip(2.0 * (station - mesh.x1[e]) / (x2[e] - mesh.x1[e]) - 1.0, -1.0, 1.0)
    nuv, nw = (a[0] for a in ref.evaluate(np.array([xi])))
    nw = nw.copy()
    nw[ref.slope] *= 0.5 * mesh.length[e]  # slope DOFs are dw/ds
    u, v, w = (np.zeros(ref.n_dof) for _ in range(3))
    u[ref.iu], v[ref.iv], w[ref.iw] = nuv, nuv, nw
    c, sn = mesh.cos_phi[e], mesh.sin_phi[e]
    local = np.array([u * c - w * sn, u * sn + w * c, v])  # (u_x, u_r, v) in the element frame
    rows = local @ node_transform(mesh)[e]
    idx, cof = dmap.index[mesh.dofs[e]], dmap.coef[mesh.dofs[e]]
    keep = idx >= 0
    out = np.zeros((3, dmap.n))
    for i in range(3):
        np.add.at(out[i], idx[keep], (rows[i] * cof)[keep])
    return out, float(mesh.r1[e] + 0.5 * (1.0 + xi) * mesh.length[e] * sn)


def lumped_mass_matrix(vehicle: Vehicle, mesh: Mesh, dmap: DofMap, k: int) -> np.ndarray | None:
    """Mass matrix (kg, reduced (n, n)) of the vehicle's rigid lumped masses for harmonic k, or
    None (no masses, or k >= 2). Each mass m, attached to the ring at its station with its
    centre of mass ``offset`` forward, adds m u_x^2 for k = 0 (axial translation) and
    m (D + e psi)^2 + I psi^2 for k = 1, D = (u_r - v) / 2 the ring's lateral translation and
    psi = -u_x / r its tilt (the amplitudes of the rigid-body fields of
    :func:`rigid_body_fields`; theta weights as the shell's, so that a rigid motion's
    q^T M q is its kinetic energy times 2).

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle (its ``masses``).
    mesh : Mesh
        Mesh of the vehicle.
    dmap : DofMap
        Constraint map of harmonic k.
    k : int
        Circumferential wave number.
    """
    if not vehicle.masses or k >= 2:
        return None
    out = np.zeros((dmap.n, dmap.n))
    for lm in vehicle.masses:
        (ux, ur, v), r = ring_rows(mesh, dmap, lm.station)
        if k == 0:
            out += lm.mass * np.outer(ux, ux)
            continue
        psi = -ux / r
        t = 0.5 * (ur - v) + lm.offset * psi
        out += lm.mass * np.outer(t, t) + lm.transverse_inertia * np.outer(psi, psi)
    return out


def assemble(mesh: Mesh, dmap: DofMap, element: np.ndarray) -> np.ndarray:
    """Scatter element matrices (node frames) into the dense reduced matrix (n, n).

    Parameters
    ----------
    mesh : Mesh
        Mesh (its ``dofs``).
    dmap : DofMap
        Constraint map.
    element : ndarray, shape (e, n_dof, n_dof)
        Element matrices.
    """
    idx = dmap.index[mesh.dofs]
    cf = dmap.coef[mesh.dofs]
    keep = idx >= 0
    pair = keep[:, :, None] & keep[:, None, :]
    flat = (idx[:, :, None] * dmap.n + idx[:, None, :])[pair]
    vals = (element * cf[:, :, None] * cf[:, None, :])[pair]
    out = np.bincount(flat, weights=vals, minlength=dmap.n * dmap.n).reshape(dmap.n, dmap.n)
    return 0.5 * (out + out.T)


@dataclass(frozen=True)
class ShellHarmonic:
    """What of harmonic k depends on the shell alone (not on its tanks' fills nor on the
    thrust), :func:`shell_harmonic`; read-only arrays.

    Attributes
    ----------
    k : int
        Circumferential wave number.
    dmap : DofMap
        Constraint map.
    mass, stiffness : ndarray, shape (n, n)
        M with the lumped masses (kg) and K_e with the pressure's rings (N/m), reduced.
    element_stiffness : ndarray, shape (e, n_dof, n_dof)
        K_e of every element in the node frames (N/m).
    fields : ElementFields
        The elements' fields (:func:`.elements.element_fields`).
    transform : ndarray, shape (e, n_dof, n_dof)
        The elements' node-frame rotation (:func:`node_transform`).
    """

    k: int
    dmap: DofMap
    mass: np.ndarray
    stiffness: np.ndarray
    element_stiffness: np.ndarray
    fields: ElementFields
    transform: np.ndarray


@dataclass(frozen=True)
class HarmonicMatrices:
    """The assembled matrices of one harmonic (reduced DOFs) and what they were built from:
    the shell's part and the prestate's geometric stiffness.

    Attributes
    ----------
    shell : ShellHarmonic
        The shell's part: ``k``, ``dmap``, ``mass`` (M, kg), ``stiffness`` (K_e, N/m) and
        ``element_stiffness`` are its own, also read as attributes of this one.
    geometric : ndarray, shape (n, n) or None
        K_g of the prestate (N/m): elements and rings; None without a prestate.
    """

    shell: ShellHarmonic
    geometric: np.ndarray | None

    @property
    def k(self) -> int:
        """Circumferential wave number."""
        return self.shell.k

    @property
    def dmap(self) -> DofMap:
        """Constraint map."""
        return self.shell.dmap

    @property
    def mass(self) -> np.ndarray:
        """M (kg), reduced (n, n)."""
        return self.shell.mass

    @property
    def stiffness(self) -> np.ndarray:
        """K_e (N/m), reduced (n, n)."""
        return self.shell.stiffness

    @property
    def element_stiffness(self) -> np.ndarray:
        """K_e of every element in the node frames (N/m), (e, n_dof, n_dof)."""
        return self.shell.element_stiffness


def harmonic_matrices(vehicle: Vehicle, mesh: Mesh, k: int, *,
                      prestate: Prestate | None = None) -> HarmonicMatrices:
    """M (with the lumped masses, :func:`lumped_mass_matrix`), K_e and K_g (elements and rings)
    of harmonic k on a mesh: :func:`shell_harmonic` and the prestate's K_g.

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    mesh : Mesh
        Mesh of the vehicle.
    k : int
        Circumferential wave number, 0..200.
    prestate : Prestate, optional
        The prestate of K_g (:func:`thrust_prestate`); None: no K_g.
    """
    k = count("k", k, 0, 200)
    shell = shell_harmonic(vehicle, mesh, k)
    geo = None
    if prestate is not None:
        kg = _geometric_elements(shell.fields, shell.transform, prestate)
        geo = assemble(mesh, shell.dmap, kg) + ring_matrix(vehicle.theory, shell.dmap,
                                                           prestate, k)
    return HarmonicMatrices(shell=shell, geometric=geo)


def shell_harmonic(vehicle: Vehicle, mesh: Mesh, k: int) -> ShellHarmonic:
    """The shell's part of harmonic k on a mesh (:class:`ShellHarmonic`): once for every vehicle
    of the same shell (segments, ends, junctions, theory, lumped masses) within
    :func:`.shared.shared_shell`, else once per :func:`.shared.shared_harmonics` block.

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle (its tanks are not read).
    mesh : Mesh
        Mesh of the vehicle.
    k : int
        Circumferential wave number, 0..200.
    """
    k = count("k", k, 0, 200)
    key = ("shell harmonic", id(mesh), k, vehicle.theory, vehicle.aft_end, vehicle.fwd_end,
           vehicle.junctions, id(vehicle.segments), id(vehicle.masses))
    return shell_value(key, (mesh, vehicle.segments, vehicle.masses),
                       lambda: _new_shell_harmonic(vehicle, mesh, k))


def _new_shell_harmonic(vehicle: Vehicle, mesh: Mesh, k: int) -> ShellHarmonic:
    dmap = dof_map(vehicle, mesh, k)
    f = _element_fields(vehicle, mesh, k)
    T = node_transform(mesh)
    m, ke = _shell_elements(mesh, f, T)
    mass = assemble(mesh, dmap, m)
    stiffness = assemble(mesh, dmap, ke)
    rings = pressure_ring_matrix(vehicle, mesh, dmap, k)
    if rings is not None:
        stiffness = stiffness + rings
    lumped = lumped_mass_matrix(vehicle, mesh, dmap, k)
    if lumped is not None:
        mass = mass + lumped
    for arr in (T, mass, stiffness, ke, *(getattr(f, x.name) for x in fields(f))):
        arr.setflags(write=False)
    return ShellHarmonic(k=k, dmap=dmap, mass=mass, stiffness=stiffness, element_stiffness=ke,
                         fields=f, transform=T)


def system_matrices(
    vehicle: Vehicle, k: int, *, prestress_F0: float = 0.0,
    supported_forward_end: bool | None = None, elements_per_segment: int | tuple | None = None,
    order: int = DEFAULT_ORDER, mesh: Mesh | None = None,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Mass (kg), elastic and geometric stiffness (N/m) of harmonic k, reduced (n, n): the loaded
    system is M q'' + (K_e + K_g) q = 0, K_g linear in ``prestress_F0`` (Brush & Almroth 1975,
    ch. 5).

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    k : int
        Circumferential wave number, 0..200.
    prestress_F0 : float
        Thrust (N) whose steady prestress K_g represents (0: K_g = 0).
    supported_forward_end : bool or None
        Load path of the thrust (:func:`thrust_prestate`).
    elements_per_segment, order : see :func:`mesh_vehicle`.
    mesh : Mesh, optional
        A mesh made by :func:`mesh_vehicle` (overrides the two above).
    """
    k = count("k", k, 0, 200)
    F0 = finite("prestress_F0", prestress_F0)
    if mesh is None:
        mesh = mesh_vehicle(vehicle, elements_per_segment=elements_per_segment, order=order)
    pre = thrust_prestate(vehicle, mesh, F0, supported_forward_end=supported_forward_end)
    h = harmonic_matrices(vehicle, mesh, k, prestate=pre)
    return h.mass, h.stiffness, h.geometric


def rigid_body_fields(mesh: Mesh, k: int) -> np.ndarray:
    """Rigid-body motions of harmonic k as full DOF vectors (m, n_full): k = 0 axial translation
    and rotation, k = 1 lateral translation and pitch about x = 0, none otherwise (Kraus 1967).

    Parameters
    ----------
    mesh : Mesh
        Mesh of the vehicle.
    k : int
        The harmonic.
    """
    k = count("k", k, 0, 200)
    ref = reference_element(mesh.order)
    if k not in (0, 1):
        return np.zeros((0, mesh.n_full))
    # fields (u_x, u_r, v, chi) as functions of (x, r)
    if k == 0:
        fields = (lambda x, r: (np.ones_like(x), 0 * x, 0 * x, 0 * x),
                  lambda x, r: (0 * x, 0 * x, r, 0 * x))
    else:
        fields = (lambda x, r: (0 * x, np.ones_like(x), -np.ones_like(x), 0 * x),
                  lambda x, r: (-r, x, -x, np.ones_like(x)))
    out = np.zeros((len(fields), mesh.n_full))
    ca, sa = mesh.cos_phi[:, None], mesh.sin_phi[:, None]
    for i, fn in enumerate(fields):
        for end in (0, 1):
            xi = -1.0 + 2.0 * end
            t = 0.5 * (1 + xi) * mesh.length
            x = mesh.x1 + t * mesh.cos_phi
            r = mesh.r1 + t * mesh.sin_phi
            ux, ur, v, chi = fn(x, r)
            fr = mesh.frame[:, end]
            a = ux * np.cos(fr) + ur * np.sin(fr)
            b = -ux * np.sin(fr) + ur * np.cos(fr)
            base = 4 * end
            for j, val in enumerate((a, v, b, chi)):
                out[i, mesh.dofs[:, base + j]] = val
        p = mesh.order
        xu = ref.xi_nodes_uv[1:-1][None, :]
        xw = ref.xi_nodes_w[None, :]
        for pts, comps, start in ((xu, ("u", "v"), 8), (xw, ("w",), 8 + 2 * (p - 1))):
            t = 0.5 * (1 + pts) * mesh.length[:, None]
            x = mesh.x1[:, None] + t * ca
            r = mesh.r1[:, None] + t * sa
            ux, ur, v, _ = fn(x, r)
            local = {"u": ux * ca + ur * sa, "v": v, "w": -ux * sa + ur * ca}
            for c_i, comp in enumerate(comps):
                cols = start + c_i * (p - 1) + np.arange(pts.shape[1])
                out[i, mesh.dofs[:, cols]] = local[comp]
    return out
