"""Reduced model of one harmonic for the forced response (:mod:`.forced`).

Per harmonic k (0 axial without torsion, 1 lateral) the FE model under the steady thrust F0,
loaded at the aft edge by F cos(Omega t): M X'' + C X' + K_L X = F cos(Omega t), K_L = K_e +
K_g(F0) (+ the follower and gimbal term of :func:`.bending_system` for k = 1). Modal basis
with the static correction of the truncated modes (mode acceleration, residual flexibility
with inertia relief via the bordered system), the reduced system solved for many Omega
through the complex Schur form of its companion matrix; internal loads (N, M, S) at the
nodes by force summation over the part ahead with the consistent mass. Theory:
docs/theory/forced-response.md.

References: L. Meirovitch, *Elements of Vibration Analysis*, 1986, ch. 7; R. R. Craig,
A. J. Kurdila, *Fundamentals of Structural Dynamics*, 2006; G. H. Golub, C. F. Van Loan,
*Matrix Computations*, 2013, sec. 7.1; V. L. Beal, AIAA J. 3 (1965), eq. 4; Tech Memo 104,
eq. 2.2-2.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass, field, replace

import numpy as np
import scipy.linalg as sla

from ..shell_of_revolution import BucklingError, Cylinder, Vehicle, eigenvalues_below
from ..shell_of_revolution.assembly import (
    assemble,
    dof_map,
    element_set,
    pressure_ring_matrix,
    rigid_body_fields,
    ring_matrix,
    ring_rows,
    thrust_prestate,
)
from ..shell_of_revolution.elements import reference_element
from ..shell_of_revolution.wetted_wall import tank_added_mass

__all__ = ["ROWS", "FullModel", "ModalModel", "cut_vehicle", "full_model", "mesh_nodes",
           "modal_model", "basis_size", "IllConditionedError", "MIN_RCOND"]

#: Default basis: every mode below MODE_CUTOFF times the highest Omega (at least MIN_MODES).
MODE_CUTOFF, MIN_MODES = 4.0, 4
#: A basis mode is rigid if omega^2 <= RIGID_RTOL x the third one (k <= 1: at most two).
RIGID_RTOL = 1e-6
#: Node rows of each harmonic (the acceleration is -Omega^2 times the displacement).
ROWS = {0: ("displacement", "axial_force"), 1: ("displacement", "shear_force",
                                                  "bending_moment")}


@dataclass(frozen=True)
class ModalModel:
    """Reduced model of one harmonic: (A - Omega^2 I + i Omega C) q = f per newton of Delta F.

    Attributes
    ----------
    k : int
        Harmonic.
    omega_modes : ndarray, shape (m,)
        Basis frequencies (rad/s; 0 for the rigid modes, the first ``n_rigid``).
    n_rigid : int
        Rigid basis modes (k = 1 free-free: the rotation, then the translation).
    free : ndarray of bool, shape (m,)
        The free rigid modes (no stiffness).
    stiffness, damping : ndarray, shape (m, m)
        A (1/s^2, non-symmetric for k = 1) and C (1/s).
    load : ndarray, shape (m,)
        f per newton of Delta F (1/sqrt(kg)).
    node_x : ndarray, shape (p,)
        Axial distance of the mesh nodes from the aft edge (m).
    rows : tuple of str
        Quantities of the node rows (:data:`ROWS`).
    stiffness_map, mass_map : ndarray, shape (p, len(rows), m)
        Node row = (stiffness_map - Omega^2 mass_map) q + static_stiffness - Omega^2 static_mass.
    static_stiffness, static_mass : ndarray, shape (p, len(rows))
        The residual (static) part of the rows.
    """

    k: int
    omega_modes: np.ndarray
    n_rigid: int
    free: np.ndarray
    stiffness: np.ndarray
    damping: np.ndarray
    load: np.ndarray
    node_x: np.ndarray
    rows: tuple
    stiffness_map: np.ndarray
    mass_map: np.ndarray
    static_stiffness: np.ndarray
    static_mass: np.ndarray
    schur: tuple = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        m = self.load.size
        S = np.block([[np.zeros((m, m)), np.eye(m)], [-self.stiffness, -self.damping]])
        T, Z = sla.schur(S, output="complex")  # S = Z T Z^H (Golub & Van Loan sec. 7.1)
        g = Z.conj().T @ np.concatenate([np.zeros(m), self.load])
        object.__setattr__(self, "schur", (T, g, self.stiffness_map @ Z[:m],
                                           self.mass_map @ Z[:m]))

    def _states(self, Omega: np.ndarray) -> np.ndarray:
        """Schur coordinates y of (i Omega_j - T) y_j = g, by back substitution: (2m, n)."""
        T, g = self.schur[:2]
        s = 1j * Omega
        y = np.empty((T.shape[0], s.size), dtype=complex)
        for i in range(T.shape[0] - 1, -1, -1):
            y[i] = (g[i] + T[i, i + 1:] @ y[i + 1:]) / (s - T[i, i])
        return y

    def response(self, Omega) -> np.ndarray:
        """Node rows per newton of Delta F at each Omega (rad/s, > 0): (n, p, len(rows))."""
        om = np.atleast_1d(np.asarray(Omega, dtype=float))
        wk, wm = self.schur[2:]
        y = self._states(om)
        w2 = om[:, None, None] ** 2
        shape = (om.size,) + wk.shape[:2]
        return ((wk.reshape(-1, y.shape[0]) @ y).T.reshape(shape) - w2 * (
            wm.reshape(-1, y.shape[0]) @ y).T.reshape(shape)
            + self.static_stiffness - w2 * self.static_mass)

    def pointwise(self, Omega: np.ndarray, node: np.ndarray, row: np.ndarray) -> np.ndarray:
        """Row ``row[j]`` of node ``node[j]`` at ``Omega[j]`` per newton (complex, (n,))."""
        wk, wm = self.schur[2:]
        y = self._states(Omega)
        w2 = Omega**2
        return (np.einsum("jn,nj->n", y, wk[node, row]) - w2 * np.einsum(
            "jn,nj->n", y, wm[node, row]) + self.static_stiffness[node, row]
            - w2 * self.static_mass[node, row])

    def poles(self) -> tuple[np.ndarray, np.ndarray]:
        """Eigenvalues (1/s) of the restrained coordinates (free rigid ones left out) and the basis
        mode dominating each.
        """
        keep = np.nonzero(~self.free)[0]
        m = keep.size
        A, C = (x[np.ix_(keep, keep)] for x in (self.stiffness, self.damping))
        lam, vec = np.linalg.eig(np.block([[np.zeros((m, m)), np.eye(m)], [-A, -C]]))
        return lam, keep[np.argmax(np.abs(vec[:m]), axis=0)]

    def to_dict(self) -> dict:
        """JSON-ready mapping."""
        return {"k": self.k, "omega_modes": self.omega_modes.tolist(),
                "n_rigid": self.n_rigid, "free": self.free.tolist(),
                "stiffness": self.stiffness.tolist(),
                "damping": self.damping.tolist(), "load": self.load.tolist(),
                "node_x": self.node_x.tolist(), "rows": list(self.rows),
                "stiffness_map": self.stiffness_map.tolist(),
                "mass_map": self.mass_map.tolist(),
                "static_stiffness": self.static_stiffness.tolist(),
                "static_mass": self.static_mass.tolist()}


def cut_vehicle(vehicle: Vehicle, xs: list, counts) -> tuple[Vehicle, tuple | None, tuple]:
    """The vehicle cut at the axial stations xs inside segments ("continuous"), the element counts
    of its segments (shared in proportion to length; None) and the index of the first piece of
    every segment.

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    xs : list of float
        Axial distances from the aft edge (m).
    counts : tuple of int or None
        Elements of each segment (None: the automatic mesh).
    """
    tol = 1e-9 * vehicle.total_length
    segs, juncs, pieces, starts, x0 = [], [], [], [], 0.0
    for i, seg in enumerate(vehicle.segments):
        L = seg.length
        edges = [0.0] + sorted({x - x0 for x in xs if x0 + tol < x < x0 + L - tol}) + [L]
        starts.append(len(segs))
        for a, b in zip(edges[:-1], edges[1:], strict=True):
            if len(edges) == 2:
                piece = seg
            elif isinstance(seg, Cylinder):
                piece = replace(seg, length=b - a)  # material and wall fields kept
            else:
                r = [seg.radius_aft + (seg.radius_fwd - seg.radius_aft) * t / L for t in (a, b)]
                piece = replace(seg, radius_aft=r[0], radius_fwd=r[1], length=b - a)
            if segs:
                juncs.append(vehicle.junctions[i - 1] if a == 0.0 else "continuous")
            segs.append(piece)
            if counts is not None:
                pieces.append(counts[i] if L == 0.0 else max(1, round(counts[i] * (b - a) / L)))
        x0 += L
    cut = Vehicle(segments=tuple(segs), junctions=tuple(juncs), aft_end=vehicle.aft_end,
                  fwd_end=vehicle.fwd_end, theory=vehicle.theory, masses=vehicle.masses,
                  tanks=vehicle.tanks)
    return cut, None if counts is None else tuple(pieces), tuple(starts)


def mesh_nodes(mesh):
    """Nodes of a mesh (each element's aft node, then the nose): element, end (0 aft, 1 forward),
    axial distance from the aft edge and radius (m).

    Parameters
    ----------
    mesh : Mesh
        The mesh (:func:`flexbooster.shell_of_revolution.mesh_vehicle`).
    """
    ne = mesh.n_elements
    elem = np.append(np.arange(ne), ne - 1)
    end = np.append(np.zeros(ne, dtype=int), 1)
    x = np.append(mesh.x1, mesh.x1[-1] + mesh.length[-1] * mesh.cos_phi[-1])
    r = np.append(mesh.r1, mesh.r1[-1] + mesh.length[-1] * mesh.sin_phi[-1])
    return elem, end, x, r


def _to_global(frame: np.ndarray) -> np.ndarray:
    """Node frame (a, v, b, chi) -> global (u_x, v, u_r, chi), shape (p, 4, 4)."""
    c, s = np.cos(frame), np.sin(frame)
    W = np.zeros((frame.size, 4, 4))
    W[:, 0, 0], W[:, 0, 2], W[:, 2, 0], W[:, 2, 2] = c, -s, s, c  # u_x = a c - b s, ...
    W[:, 1, 1] = W[:, 3, 3] = 1.0
    return W


def _node_displacements(mesh, dmap, keep, elem, end) -> np.ndarray:
    """Functionals (p, 4, n_kept) of the global (u_x, v, u_r, chi) at the nodes."""
    full = dmap.expand(_embed(keep, np.eye(int(np.count_nonzero(keep)))).T)  # (n_kept, n_full)
    dofs = mesh.dofs[elem[:, None], 4 * end[:, None] + np.arange(4)]
    return np.einsum("pji,cpi->pjc", _to_global(mesh.frame[elem, end]), full[:, dofs])


def _node_loads(k, mesh, dmap, keep, x, mats, Y, extra=None, add=None) -> np.ndarray:
    """Internal loads (p, len(ROWS[k]) - 1, c) of reduced vectors Y by force summation over the
    part ahead of each node: its rigid motions times the sum of its element forces over its free
    DOFs, plus ``extra`` (k + 1, p, n_kept) @ Y (the attached masses and the liquid ahead)
    and ``add`` (k + 1, p, c); 0 at the nose.
    """
    full = dmap.expand(_embed(keep, Y).T)  # (c, n_full)
    f = np.einsum("eij,cej->eic", mats, full[:, mesh.dofs])  # element forces (e, nd, c)
    free = dmap.index[mesh.dofs] >= 0
    rigid = rigid_body_fields(mesh, k)[:1 + k][:, mesh.dofs] * free  # (k + 1, e, nd)
    part = np.einsum("fei,eic->fec", rigid, f)[:, ::-1].cumsum(axis=1)[:, ::-1]  # e' >= e
    part = np.concatenate([part, np.zeros_like(part[:, :1])], axis=1)  # (k + 1, p, c)
    if extra is not None:
        part = part + extra @ Y
    if add is not None:
        part = part + add
    return _section(k, x, part)


def _section(k, x, part):
    """Section loads (p, len(ROWS[k]) - 1, ...) from the force and moment (about x = 0) of the
    part ahead (k + 1, p, ...): N = -F_x (tension > 0); S, M = -M(x)."""
    if k == 0:
        return -part[0][:, None]
    return np.stack([part[0], x.reshape((-1,) + (1,) * (part.ndim - 2)) * part[0] - part[1]],
                    axis=1)


def _ahead(nodes, rows, p):
    """Rows (f, p, n) summed over the pieces ahead of each node: piece i (rows[i], shape (f, n))
    counted at node nodes[i] and at every node aft of it."""
    out = np.zeros((p,) + rows.shape[1:])
    np.add.at(out, np.asarray(nodes, dtype=int), rows)
    return np.moveaxis(out[::-1].cumsum(axis=0)[::-1], 0, 1)


def _attached(vehicle, mesh, dmap, keep, k, liquid):
    """Mass (n_kept, n_kept) of the lumped masses and the liquid (k <= 1), the rows (k + 1, p,
    n_kept) of their inertia forces on the rigid motions of the part ahead of each node
    (:func:`_ahead`), and the volume change (p, n_c) of the part ahead's share of each closed
    full tank's boundary under the axial translation (k = 0; None without such a tank).

    A lumped mass counts at the node of its station (a node's cut is taken just aft of it), a
    wall point at its element's aft node, a tank end at its edge's node. Lumped masses as
    :func:`.assembly.lumped_mass_matrix`; rigid fields as :func:`.assembly.rigid_body_fields`
    (k = 0: u_x = 1; k = 1: (u_x, u_r, v) = (0, 1, -1) and (-r, x, -x)); the liquid's split
    by :class:`.liquid.AddedMass` (``point_force``, ``end_force``).
    """
    n, p = dmap.n, mesh.n_elements + 1
    M = np.zeros((n, n))
    nodes, rows = [], []
    x2 = mesh.x1 + mesh.length * mesh.cos_phi
    tol = 1e-9 * float(np.max(x2))
    for lm in vehicle.masses:
        (ux, ur, v), r = ring_rows(mesh, dmap, lm.station)
        e = int(np.flatnonzero((mesh.x1 - tol <= lm.station) & (lm.station <= x2 + tol)
                               & (mesh.cos_phi > 0))[0])
        nodes.append(e + 1 if lm.station >= x2[e] - tol else e)
        if k == 0:
            M += lm.mass * np.outer(ux, ux)
            rows.append(lm.mass * ux[None])
        else:
            psi = -ux / r
            t = 0.5 * (ur - v) + lm.offset * psi
            M += lm.mass * np.outer(t, t) + lm.transverse_inertia * np.outer(psi, psi)
            rows.append(np.stack([lm.mass * t, lm.mass * (lm.station + lm.offset) * t
                                  + lm.transverse_inertia * psi]))
    volume = []
    if liquid is not None:
        M += liquid.matrix
        for ww, am, cols in liquid.parts:
            (nx, nr), xw, rw = ww.wall.normal.T, ww.wall.x, ww.wall.r
            wn = nx[:, None] if k == 0 else np.column_stack([nr, -rw * nx + xw * nr])
            ux = np.array([1.0]) if k == 0 else np.array([0.0, -1.0])  # u_x / r^k of the ends
            at = np.concatenate([ww.element, np.array(ww.end_element) + [0, 1]])
            local = np.concatenate([wn[:, :, None] * am.point_force[:, None],
                                    ux[None, :, None] * am.end_force[:, None]])
            full = np.zeros(local.shape[:2] + (n,))
            full[:, :, cols] = local
            nodes += at.tolist()
            rows += list(full)
            if am.point_volume is not None:
                vol = np.concatenate([nx * am.point_volume, am.end_volume])
                volume.append(_ahead(at, vol[:, None, None], p)[0, :, 0])
    extra = _ahead(nodes, np.array(rows), p)[:, :, keep] if rows else None
    return M[np.ix_(keep, keep)], extra, (np.array(volume).T if volume else None)


def _element_end_values(values: np.ndarray, order: int) -> np.ndarray:
    """Values (e, 2) at the element ends of a field given at the Gauss points (e, g), by the
    polynomial through them (exact for the prestate's axial force).
    """
    xi = reference_element(order).xi
    coef = np.polynomial.legendre.legfit(xi, np.asarray(values, dtype=float).T, xi.size - 1)
    return np.polynomial.legendre.legval(np.array([-1.0, 1.0]), coef)  # (e, 2)


def _reduced(dmap, full: np.ndarray) -> np.ndarray:
    """Reduced DOF vector of an admissible full DOF vector (full = coef x reduced[index])."""
    out = np.zeros(dmap.n)
    on = dmap.index >= 0
    out[dmap.index[on]] = full[on] / dmap.coef[on]
    return out


def _embed(keep, Y):
    """Vectors of the kept reduced DOFs (k = 0: no torsion) as vectors of all of them."""
    out = np.zeros((keep.size,) + Y.shape[1:], dtype=Y.dtype)
    out[keep] = Y
    return out


def _axisymmetric(mesh, dmap, k: int) -> np.ndarray:
    """Mask of the reduced DOFs kept: k = 0 all but the torsional v; k >= 1 all."""
    keep = np.ones(dmap.n, dtype=bool)
    if k == 0:  # element DOFs: end 1 (u, v, w, w'), end 2, interior u (p - 1), interior v
        p = mesh.order
        pos = np.concatenate(([1, 5], 8 + (p - 1) + np.arange(p - 1)))
        idx = dmap.index[mesh.dofs[:, pos].ravel()]
        keep[idx[idx >= 0]] = False
    return keep


def _basis(K, M, n_modes, omega_max):
    """Lowest eigenpairs (omega^2, M-normalised vectors) of K x = omega^2 M x and the number of
    rigid ones: n_modes elastic ones, or all below MODE_CUTOFF omega_max (>= MIN_MODES).
    """
    n = K.shape[0]
    scale = 1.0 / np.sqrt(np.diag(M))  # unit mass diagonal: a better-conditioned reduction
    A, B = K * np.outer(scale, scale), M * np.outer(scale, scale)
    want = None if n_modes is None else min(n, n_modes + 2)
    if want is None:
        w2, V = sla.eigh(A, B, subset_by_value=(-np.inf, (MODE_CUTOFF * omega_max) ** 2),
                         driver="gvx")
        if w2.size < MIN_MODES + 2:
            want = min(n, MIN_MODES + 2)
    if want is not None:
        w2, V = sla.eigh(A, B, subset_by_index=(0, want - 1), driver="gvx")
    n_rigid = int(np.count_nonzero(np.abs(w2) <= RIGID_RTOL * abs(w2[min(2, w2.size - 1)])))
    if n_modes is not None:
        if w2.size - n_rigid < n_modes:
            raise ValueError(f"n_modes = {n_modes}: the mesh has only {w2.size - n_rigid} "
                             "elastic modes in this harmonic")
        w2, V = w2[:n_rigid + n_modes], V[:, :n_rigid + n_modes]
    return w2, V * scale[:, None], n_rigid


#: Smallest reciprocal condition number of the static correction's bordered system: its
#: solution's relative error is at most about eps / rcond (Higham 2002, sec. 7.1), so this keeps
#: three significant digits in the residual modes' loads (the digits the results print).
MIN_RCOND = 1e3 * np.finfo(float).eps


class IllConditionedError(ValueError):
    """The static correction's bordered system is singular to working precision: its
    residual-mode loads would be round-off."""


def _condense(KL, M, Phi, F, static: bool):
    """(Psi, G_c F, A, f) of the static correction (static=False: Phi, 0, Phi^T K_L Phi, Phi^T F).
    """
    if not static:
        return Phi, np.zeros(F.size), Phi.T @ KL @ Phi, Phi.T @ F
    n, m = Phi.shape
    MPhi = M @ Phi
    s = np.max(np.abs(KL)) / np.max(np.abs(MPhi))  # rows of comparable size
    bordered = np.block([[KL, s * MPhi], [s * MPhi.T, np.zeros((m, m))]])
    rhs = np.vstack([np.column_stack([F, KL @ Phi]), np.zeros((m, m + 1))])
    # Craig & Kurdila: inertia relief.  LU with partial pivoting and LAPACK's 1-norm condition
    # estimate (getrf, gecon; Golub & Van Loan 2013, sec. 3.5.4) stated here rather than left to
    # scipy.linalg.solve, whose structure detection (symmetric: sytrf) changes the estimate
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sla.LinAlgWarning)  # an exact zero pivot: rcond 0 below
        lu, piv = sla.lu_factor(bordered, check_finite=False)
    rcond, _ = sla.lapack.dgecon(lu, np.linalg.norm(bordered, 1), norm="1")
    if not rcond >= MIN_RCOND:  # the loads of the residual modes would be round-off
        raise IllConditionedError("the static correction is singular to working precision "
                                  f"(reciprocal condition number {rcond:.3g})")
    sol = sla.lu_solve((lu, piv), rhs, check_finite=False)[:n]
    xr, Psi = sol[:, 0], Phi - sol[:, 1:]
    return Psi, xr, Phi.T @ KL @ Psi, Phi.T @ (F - KL @ xr)


def _matrices(vehicle: Vehicle, mesh, k: int, *, F0: float, share: float,
              supported_forward_end: bool) -> tuple:
    """The kept DOFs' matrices of :func:`full_model` before its basis: (dmap, prestate,
    element set, kept DOFs, M, K_L, K_e, F, node displacements, those before the volume
    constraint, T or None, mesh nodes, attached rows, volume data or None)."""
    dmap = dof_map(vehicle, mesh, k)
    pre = thrust_prestate(vehicle, mesh, F0, supported_forward_end=supported_forward_end)
    mats = element_set(vehicle, mesh, k, prestate=pre)
    keep = _axisymmetric(mesh, dmap, k)
    rings = ring_matrix(vehicle.theory, dmap, pre, k)[np.ix_(keep, keep)]
    M, Ke, Kg = (assemble(mesh, dmap, a)[np.ix_(keep, keep)] for a in mats)
    Kg = Kg + rings  # the hoop rings where the meridian turns
    fixed = pressure_ring_matrix(vehicle, mesh, dmap, k)  # and the pressure's
    if fixed is not None:
        Ke = Ke + fixed[np.ix_(keep, keep)]
    liquid = tank_added_mass(vehicle, mesh, k)
    Ma, extra, volume = _attached(vehicle, mesh, dmap, keep, k, liquid)
    M = M + Ma
    nodes = mesh_nodes(mesh)
    D = _node_displacements(mesh, dmap, keep, nodes[0], nodes[1])
    F = share * (D[0, 0] if k == 0 else 0.5 * (D[0, 2] - D[0, 1]))  # unit aft-edge load
    KL = Ke + Kg
    T, D_kept = None, D
    if liquid is not None and liquid.constraint is not None:  # closed full tanks, k = 0
        C = liquid.constraint[:, keep]
        L = np.linalg.solve(C @ C.T, C)  # mu = L r: the uniform pressures of a residual r
        volume = (volume, L, KL, M, F)
        Q = np.linalg.qr(C.T, mode="complete")[0]
        T = Q[:, np.linalg.matrix_rank(C):]  # the motions with C X = 0
        M, KL, Ke, F = T.T @ M @ T, T.T @ KL @ T, T.T @ Ke @ T, T.T @ F
        D = D @ T
    else:
        volume = None
    return dmap, pre, mats, keep, M, KL, Ke, F, D, D_kept, T, nodes, extra, volume


def basis_size(vehicle: Vehicle, mesh, k: int, *, F0: float, omega_max: float,
               supported_forward_end: bool) -> int:
    """The basis modes (rigid ones included) :func:`full_model` takes with ``n_modes`` None:
    the eigenvalues of (K_L, M) (k = 0) or (K_e, M) (k = 1) below (4 omega_max)^2, at least 6,
    counted by Sylvester's law of inertia without an eigenvector
    (:func:`flexbooster.shell_of_revolution.eigenvalues_below`).

    Parameters
    ----------
    vehicle, mesh, k, F0, omega_max, supported_forward_end
        As :func:`full_model`.
    """
    M, KL, Ke = _matrices(vehicle, mesh, k, F0=F0, share=1.0,
                          supported_forward_end=supported_forward_end)[4:7]
    below = eigenvalues_below(KL if k == 0 else Ke, M, (MODE_CUTOFF * omega_max) ** 2)
    return min(M.shape[0], max(below, MIN_MODES + 2))


@dataclass(frozen=True)
class FullModel:
    """The finite-element model of one harmonic: M X'' + K_L X = F.

    Attributes
    ----------
    k : int
        Harmonic.
    mass, stiffness : ndarray, shape (n, n)
        M (kg) and K_L (N/m; non-symmetric for k = 1) on the kept DOFs.
    load : ndarray, shape (n,)
        F per newton of Delta F.
    basis, omega2 : ndarray
        Phi (n, m), M-normalised (the rigid modes first), and omega^2 (1/s^2, 0 if rigid).
    n_rigid : int
        Rigid basis modes.
    parts : tuple
        What :meth:`node_rows` needs (mesh, DOF map, kept DOFs, element matrices, nodes, node
        functionals, steady axial load P0 at the nodes, the coordinates T (None: X = q), the
        attached masses' and liquid's force rows, the closed tanks' volume rows).
    """

    k: int
    mass: np.ndarray
    stiffness: np.ndarray
    load: np.ndarray
    basis: np.ndarray
    omega2: np.ndarray
    n_rigid: int
    parts: tuple = field(repr=False, compare=False)

    def node_rows(self, Y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Node rows (p, len(ROWS[k]), c) of vectors Y (m, c): stiffness part - Omega^2 mass
        part, the first row the displacement."""
        mesh, dmap, keep, mats, (elem, end, x, r), D, P0, T, extra, volume = self.parts
        X = Y if T is None else T @ Y
        k, disp = self.k, D[:, 0] if self.k == 0 else 0.5 * (D[:, 2] - D[:, 1])  # u_x or y
        pressure_k = pressure_m = None
        if volume is not None:  # the closed tanks' uniform pressure mu = L (K X - w^2 M X - F)
            vol, L, KL, M = volume[:4]
            pressure_k, pressure_m = -(vol @ L @ KL @ X)[None], -(vol @ L @ M @ X)[None]
        stiff = np.concatenate([(disp @ X)[:, None], _node_loads(
            k, mesh, dmap, keep, x, mats[1] + mats[2], X, add=pressure_k)], axis=1)
        mass = np.concatenate([np.zeros_like(stiff[:, :1]), _node_loads(
            k, mesh, dmap, keep, x, mats[0], X, extra=extra, add=pressure_m)], axis=1)
        if k == 1:  # shear normal to the section: less the steady load P0 tilted by beta
            stiff[:, 1] += (P0 / r)[:, None] * (D[:, 0] @ X)  # beta = -U_x / r
        return stiff, mass

    def load_rows(self) -> np.ndarray:
        """Node rows (p, len(ROWS[k])) per newton of Delta F not carried by the displacement:
        the closed full tanks' uniform pressure of the load, -L F (k = 0); 0 otherwise."""
        x, volume = self.parts[4][2], self.parts[-1]
        out = np.zeros((x.size, len(ROWS[self.k])))
        if volume is not None:
            vol, L, F = volume[0], volume[1], volume[4]
            out[:, 1:] = _section(self.k, x, (vol @ L @ F)[None, :, None])[:, :, 0]
        return out


def full_model(
    vehicle: Vehicle, mesh, k: int, *, F0: float, share: float, n_modes: int | None,
    omega_max: float, gimbal_gain: float, supported_forward_end: bool,
) -> FullModel:
    """The finite-element model of harmonic k (0 or 1) per newton of the thrust oscillation,
    with the vehicle's lumped masses and its tanks' liquid (added mass per k; at k = 0 the
    closed full tanks keep their volume: coordinates q with X = T q, T^T T = I).

    Parameters
    ----------
    vehicle, mesh : Vehicle, Mesh
        The vehicle and its mesh.
    k : int
        0 (axial) or 1 (lateral).
    F0 : float
        Steady thrust (N): prestress, follower and gimbal terms.
    share : float
        Load of this harmonic per newton of Delta F: cos(delta) (k = 0), sin(delta) (k = 1).
    n_modes : int or None
        Elastic basis modes; None: all below 4 omega_max (at least 4).
    omega_max : float
        Highest Omega (rad/s).
    gimbal_gain : float
        K.
    supported_forward_end : bool
        Prestress reacted at the nose.
    """
    dmap, pre, mats, keep, M, KL, Ke, F, D, D_kept, T, nodes, extra, volume = _matrices(
        vehicle, mesh, k, F0=F0, share=share, supported_forward_end=supported_forward_end)
    r = nodes[3]
    w2, Phi, n_rigid = _basis(KL if k == 0 else Ke, M, n_modes, omega_max)
    if np.any(w2[n_rigid:] <= 0.0):
        raise BucklingError(f"F0 = {F0!r}: the steady thrust buckles harmonic k = {k}", k, F0)
    if n_rigid == k + 1:  # the exact rigid fields (M-orthonormal) for the computed ones
        R = np.array([_reduced(dmap, f)[keep] for f in rigid_body_fields(mesh, k)[:k + 1]]).T
        R = R if T is None else T.T @ R
        Lc = np.linalg.cholesky(R.T @ M @ R)
        Phi = Phi.copy()
        Phi[:, :n_rigid] = np.linalg.solve(Lc, R.T).T
    if k == 1:
        beta = -D[0, 0] / r[0]  # aft cross-section rotation, beta = -U_x / r
        psi = np.zeros(beta.size)
        if n_rigid == 2:  # rigid pair -> rotation (beta != 0), translation (beta = 0)
            b = beta @ Phi[:, :2]
            h = float(np.hypot(b[0], b[1]))
            Phi = Phi.copy()
            Phi[:, :2] = Phi[:, :2] @ (np.array([[b[0], b[1]], [b[1], -b[0]]]) / h)
            psi = h * (M @ Phi[:, 0])  # rigid pitch angle of a displacement
        y = 0.5 * (D[0, 2] - D[0, 1])
        KL = KL - F0 * np.outer(y, beta + gimbal_gain * psi)  # Beal eq. 4, memo eq. 2.2-2
    w2[:n_rigid] = 0.0
    tilt = _element_end_values(pre.force, mesh.order)  # (e, 2) at each element's two ends
    P0 = np.append(tilt[:, 0], tilt[-1, 1])  # steady axial load at each node (N, > 0)
    return FullModel(k=k, mass=M, stiffness=KL, load=F, basis=Phi, omega2=w2,
                     n_rigid=n_rigid, parts=(mesh, dmap, keep, mats, nodes, D_kept, P0, T, extra,
                                             volume))


def modal_model(
    vehicle: Vehicle, mesh, k: int, *, F0: float, share: float, n_modes: int | None,
    omega_max: float, gimbal_gain: float, damping_ratio: float, pitch_damping_ratio: float,
    supported_forward_end: bool, static_correction: bool,
) -> ModalModel:
    """The reduced model of harmonic k (0 or 1) per newton of the thrust oscillation.

    Parameters
    ----------
    vehicle, mesh, k, F0, share, n_modes, omega_max, gimbal_gain, supported_forward_end
        As :func:`full_model`.
    damping_ratio, pitch_damping_ratio : float
        zeta, zeta_psi.
    static_correction : bool
        The static correction of the truncated modes (False: mode displacement).
    """
    fm = full_model(vehicle, mesh, k, F0=F0, share=share, n_modes=n_modes,
                    omega_max=omega_max, gimbal_gain=gimbal_gain,
                    supported_forward_end=supported_forward_end)
    Psi, xr, A, f = _condense(fm.stiffness, fm.mass, fm.basis, fm.load, static_correction)
    omega = np.sqrt(fm.omega2)
    if k == 0:  # K R = R^T K = 0 for the axial translation exactly (gradient forms): drop the
        A = A.copy()  # round-off of Phi_r^T K Psi, which 1 / Omega^2 amplifies as Omega -> 0
        A[:fm.n_rigid], A[:, :fm.n_rigid] = 0.0, 0.0
    damp = 2.0 * damping_ratio * omega
    free = np.arange(omega.size) < fm.n_rigid
    if k == 1 and fm.n_rigid == 2 and gimbal_gain > 0.0:  # the gimbaled pitch: an oscillator
        free[0] = False
        damp[0] = 2.0 * pitch_damping_ratio * np.sqrt(max(A[0, 0], 0.0))
    stiff, mass = fm.node_rows(np.column_stack([Psi, xr]))
    stiff[..., -1] += fm.load_rows()
    if k == 0:  # no elastic force in the axial translation (its round-off left out)
        stiff[:, 1:, :fm.n_rigid] = 0.0
    return ModalModel(k=k, omega_modes=omega, n_rigid=fm.n_rigid, free=free, stiffness=A,
                      damping=np.diag(damp), load=f, node_x=fm.parts[4][2], rows=ROWS[k],
                      stiffness_map=stiff[..., :-1], mass_map=mass[..., :-1],
                      static_stiffness=stiff[..., -1], static_mass=mass[..., -1])
