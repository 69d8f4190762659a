"""Natural modes, loaded frequencies, modal systems and buckling of a shell-of-revolution vehicle.

Per harmonic k the eigenproblem (K_e [+ K_g]) x = omega^2 M x is solved densely on the
M-orthogonal complement of the admissible rigid motions (k = 0, 1); omega^2 are the Rayleigh
quotients of the eigenvectors (monotone under refinement). Modes are labelled by ``k``,
``order`` (sign changes of the dominant component), ``type`` (largest kinetic-energy share)
and ``segment`` (largest strain-energy share). Theory: docs/theory/shell-of-revolution.md.

References: K.-J. Bathe, *Finite Element Procedures*, 1996, sec. 10.2; Brush & Almroth 1975,
ch. 5 (linear buckling: K_e x = -lambda K_g x).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from ..checks import count, finite, positive
from .assembly import (
    DEFAULT_ORDER,
    DofMap,
    Mesh,
    dof_map,
    harmonic_matrices,
    mesh_vehicle,
    node_transform,
    rigid_body_fields,
    ring_matrix,
    thrust_prestate,
)
from .elements import ElementFields, element_energies, reference_element
from .geometry import Vehicle
from .prestress import Prestate, load_path, pressure_resultants, pressure_rings
from .shared import shared_harmonics, shared_value, shell_value
from .wetted_wall import tank_added_mass

__all__ = [
    "MODE_TYPES",
    "BAND_FACTOR",
    "VehicleModes",
    "ModalSystem",
    "BucklingLoad",
    "vehicle_modes",
    "modal_system",
    "labelled_modal_system",
    "buckling_load",
    "BucklingError",
    "shared_harmonics",
    "mode_vectors",
    "eigenvalues_below",
    "rigid_motion_count",
]

class BucklingError(ValueError):
    """The thrust prestress buckles harmonic ``k`` (a loaded omega^2 <= 0): a result of the case.
    ``F0`` (N) is the thrust, ``load_factor`` the lowest lambda of :func:`buckling_load` or None.
    """

    def __init__(self, message: str, k: int, F0: float, load_factor: float | None = None):
        super().__init__(message)
        self.k, self.F0, self.load_factor = k, F0, load_factor

    def __reduce__(self):
        return type(self), (str(self), self.k, self.F0, self.load_factor)


#: Mode type names (see the module docstring).
MODE_TYPES = ("axial", "torsional", "breathing", "bending", "radial")
#: Default band: frequencies up to this multiple of the lowest elastic one.
BAND_FACTOR = 5.0
#: Largest harmonic accepted.
K_MAX = 200
#: Mode shape samples within this fraction of the peak magnitude count as the peak for the sign.
SIGN_TIE_RTOL = 1e-6
#: The lowest modes of a harmonic without rigid motions by sparse shift-invert Lanczos
#: (:func:`_lowest_sparse`) from this many DOFs on, when at most an eighth of them is wanted.
SPARSE_MIN_DOFS = 200
#: Krylov steps of the Lanczos of :func:`_lowest_sparse` before it hands over to ARPACK: at most
#: this many times the pairs wanted, and at least LANCZOS_EXTRA more than them. A long
#: ring-stiffened tube (248 m, 851 DOFs per harmonic) has the lowest eigenvalues of each
#: k >= 2 within 1e-4 of each other: 106 steps left 16 of its 20 harmonics to ARPACK (tol = 0, 20
#: Lanczos vectors: 2-3 s CPU and some 13,000 solves each), 400 steps converge them all (0.6 s;
#: a harmonic that converged in fewer steps is unchanged).
LANCZOS_FACTOR, LANCZOS_EXTRA = 4, 400
#: Lanczos vectors of the ARPACK restarts beyond the pairs wanted (scipy's default, max(2 count
#: + 1, 20), restarts a clustered spectrum thousands of times: a 400 m ring-stiffened tube,
#: 2,908 DOFs, k = 5, its lowest 6 eigenvalues within 2e-5 of each other: 5.1 s CPU with 20
#: vectors, 1.9 s with 66, the same eigenvalues to machine precision).
ARPACK_EXTRA = 60
#: Shape samples per element of the labels of :func:`labelled_modal_system` (the default
#: ``points_per_element`` of :func:`vehicle_modes`, whose labels it reproduces).
_LABEL_POINTS = 9


@dataclass(frozen=True)
class VehicleModes:
    """Natural modes of a vehicle, one row per mode (sorted by k, then frequency).

    Attributes
    ----------
    k, order, segment : ndarray of int, shape (n,)
        Circumferential wave number, sign changes of the dominant component along the
        meridian, segment with the largest strain-energy share.
    omega, hz : ndarray, shape (n,)
        Frequency (rad/s, Hz).
    type : ndarray of str, shape (n,)
        Mode type (:data:`MODE_TYPES`).
    kinetic_share : ndarray, shape (n, 3)
        Kinetic-energy shares of u (meridional), v, w (normal).
    s, x, r : ndarray, shape (n_pts,)
        Meridian coordinate, axial station and radius of the shape samples (m).
    shapes : ndarray, shape (n, 3, n_pts)
        Local (u, v, w) amplitudes, max |.| = 1.
    rigid_modes : dict
        ``{k: n}``: rigid-body modes removed for k = 0 and 1.
    prestress_F0 : float
        Thrust (N) of the prestress (0: unloaded).
    load_path : str
        What balances the thrust (:data:`~.prestress.LOAD_PATHS`).
    theory : str
        Shell theory.
    elements_per_segment, element_order : tuple of int, int
        Mesh used.
    warnings : tuple of ShellWarning
        Warnings of the vehicle.
    """

    k: np.ndarray
    omega: np.ndarray
    hz: np.ndarray
    order: np.ndarray
    type: np.ndarray
    segment: np.ndarray
    kinetic_share: np.ndarray
    s: np.ndarray
    x: np.ndarray
    r: np.ndarray
    shapes: np.ndarray
    rigid_modes: dict
    prestress_F0: float
    load_path: str
    theory: str
    elements_per_segment: tuple
    element_order: int
    warnings: tuple = field(default=(), repr=False)

    def __len__(self) -> int:
        return int(self.k.size)

    def select(self, k: int | None = None) -> np.ndarray:
        """Boolean mask (n,) of the modes of one harmonic.

        Parameters
        ----------
        k : int, optional
            Circumferential wave number; None selects all.
        """
        return np.ones(len(self), bool) if k is None else self.k == k

    def to_dict(self, *, shapes: bool = True) -> dict:
        """JSON-ready mapping of plain lists and floats (``shapes=False`` omits the shapes)."""
        out = {
            "columns": ["k", "omega", "hz", "order", "type", "segment"],
            "k": self.k.tolist(), "omega": self.omega.tolist(), "hz": self.hz.tolist(),
            "order": self.order.tolist(), "type": self.type.tolist(),
            "segment": self.segment.tolist(), "kinetic_share": self.kinetic_share.tolist(),
            "rigid_modes": {str(key): int(val) for key, val in self.rigid_modes.items()},
            "prestress_F0": float(self.prestress_F0), "load_path": self.load_path,
            "theory": self.theory,
            "elements_per_segment": list(self.elements_per_segment),
            "element_order": int(self.element_order),
            "warnings": [w.to_dict() for w in self.warnings],
        }
        if shapes:
            out.update(s=self.s.tolist(), x=self.x.tolist(), r=self.r.tolist(),
                       shapes=self.shapes.tolist())
        return out


@dataclass(frozen=True)
class ModalSystem:
    """One harmonic in the basis of its modes: q'' + (K_e + (T(t)/F0) K_g) q = 0, with
    K_e + K_g = diag(omega^2) on the elastic modes (loaded basis) or K_e = diag(omega^2).

    Attributes
    ----------
    k : int
        Circumferential wave number.
    omega : ndarray, shape (n,)
        Natural frequencies of the basis modes (rad/s), loaded or not; 0 for the rigid ones.
    omega_unloaded : ndarray, shape (n,) or (0,)
        The harmonic's lowest frequencies without thrust (rad/s); empty when not asked for
        (:func:`labelled_modal_system` ``unloaded_frequencies=False``).
    mass, stiffness, geometric : ndarray, shape (n, n)
        Modal mass (identity), K_e and K_g of the thrust F0 (1/s^2).
    F0 : float
        Thrust of the prestress (N).
    n_rigid : int
        Rigid-body motions first in the basis (0 unless asked for).
    aft_edge : ndarray, shape (n, 4)
        (u_x, v, u_r) (m per sqrt(kg)) and chi (rad per sqrt(kg)) of the aft edge per mode.
    """

    k: int
    omega: np.ndarray
    omega_unloaded: np.ndarray
    mass: np.ndarray
    stiffness: np.ndarray
    geometric: np.ndarray
    F0: float
    n_rigid: int
    aft_edge: np.ndarray

    @property
    def aft_axial(self) -> np.ndarray:
        """u_x at the aft edge of each basis mode (m per sqrt(kg)): an axial ring load F there
        has the generalised force F * aft_axial (k = 0)."""
        return self.aft_edge[:, 0]

    def to_dict(self) -> dict:
        """JSON-ready mapping."""
        return {"k": self.k, "omega": self.omega.tolist(),
                "omega_unloaded": self.omega_unloaded.tolist(), "mass": self.mass.tolist(),
                "stiffness": self.stiffness.tolist(), "geometric": self.geometric.tolist(),
                "F0": float(self.F0), "n_rigid": int(self.n_rigid),
                "aft_edge": self.aft_edge.tolist()}


@dataclass(frozen=True)
class BucklingLoad:
    """Linear buckling of one harmonic under the thrust prestress.

    Attributes
    ----------
    k : int
        Circumferential wave number.
    load_factor, critical_thrust : ndarray, shape (n,)
        Smallest positive lambda of K_e x = -lambda K_g(F0) x, ascending, and lambda F0 (N).
    s : ndarray, shape (n_pts,)
        Meridian coordinate of the shape samples (m).
    shapes : ndarray, shape (n, 3, n_pts)
        Local (u, v, w) buckling modes, max |.| = 1.
    """

    k: int
    load_factor: np.ndarray
    critical_thrust: np.ndarray
    s: np.ndarray
    shapes: np.ndarray

    def to_dict(self) -> dict:
        """JSON-ready mapping."""
        return {"k": self.k, "load_factor": self.load_factor.tolist(),
                "critical_thrust": self.critical_thrust.tolist(), "s": self.s.tolist(),
                "shapes": self.shapes.tolist()}


# ------------------------------------------------------------------------- shared work

def _readonly(*arrays) -> None:
    for arr in arrays:
        if isinstance(arr, np.ndarray):
            arr.setflags(write=False)


def _mesh(vehicle: Vehicle, elements_per_segment, order: int, refinement: int = 1) -> Mesh:
    """:func:`~.assembly.mesh_vehicle` (a function of the segments alone), once per segments
    within :func:`shared_harmonics`, or across vehicles within :func:`.shared.shared_shell`."""
    counts = tuple(elements_per_segment) if isinstance(elements_per_segment, list | np.ndarray) \
        else elements_per_segment
    return shell_value(("mesh", id(vehicle.segments), counts, order, refinement),
                       (vehicle.segments,),
                       lambda: mesh_vehicle(vehicle, elements_per_segment=elements_per_segment,
                                            order=order, refinement=refinement))


# ----------------------------------------------------------------------------- helpers


@dataclass(frozen=True)
class _Harmonic:
    """Matrices of one harmonic, with the rigid-free basis Q (None: no rigid motions); M with
    the tanks' liquid, ``structural_mass`` without it (the shell and the lumped masses);
    ``reflectors``: Q as the trailing columns of a product of Householder reflectors (LAPACK
    ``geqrf`` form (qr, tau)), or None when Q is not one."""

    k: int
    mesh: Mesh
    theory: str
    prestate: Prestate | None
    M: np.ndarray
    K: np.ndarray
    G: np.ndarray | None
    Q: np.ndarray | None
    R: np.ndarray
    dmap: DofMap
    elem_k: np.ndarray
    structural_mass: np.ndarray
    fields: ElementFields
    reflectors: tuple | None = None

    @property
    def n_rigid(self) -> int:
        """Admissible rigid-body motions (dimensionless)."""
        return int(self.R.shape[1])


def rigid_motion_count(vehicle: Vehicle, mesh: Mesh, k: int) -> int:
    """The rigid-body motions of harmonic k that the vehicle's ends admit (0-2; k = 0: axial
    translation and rotation, k = 1: lateral translation and pitch; Kraus 1967): where there
    are any, the modes are solved on their M-orthogonal complement (a dense projection and
    dense solves).

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    mesh : Mesh
        Its mesh (:func:`.assembly.mesh_vehicle`).
    k : int
        The harmonic, 0..200.
    """
    k = count("k", k, 0, 200)
    return int(_rigid_subspace(mesh, dof_map(vehicle, mesh, k), k).shape[1])


def _rigid_subspace(mesh: Mesh, dmap, k: int) -> np.ndarray:
    """Admissible rigid-body vectors in reduced DOFs, shape (n, m) (m may be 0)."""
    fields = rigid_body_fields(mesh, k)
    if fields.shape[0] == 0:
        return np.zeros((dmap.n, 0))
    # project each full field onto the constrained space: average over aliases
    idx = dmap.index
    keep = idx >= 0
    red = np.zeros((fields.shape[0], dmap.n))
    den = np.bincount(idx[keep], weights=dmap.coef[keep] ** 2, minlength=dmap.n)
    for i in range(fields.shape[0]):  # least-squares fit of full = coef * reduced
        red[i] = np.bincount(idx[keep], weights=(fields[i] * dmap.coef)[keep],
                             minlength=dmap.n) / den
    resid = dmap.expand(red) - fields  # (m, n_full): violation of the constraints
    scale = np.linalg.norm(fields, axis=1).max()
    # combinations c with resid^T c = 0 are admissible
    _, sv, vt = np.linalg.svd(resid.T, full_matrices=True)
    sv = np.concatenate([sv, np.zeros(fields.shape[0] - sv.size)])
    null = vt[sv <= 1e-9 * scale]
    return (null @ red).T


def _harmonic(vehicle: Vehicle, mesh: Mesh, k: int, *, F0: float, supported: bool | None,
              geometric: bool) -> _Harmonic:
    """The matrices of harmonic k (:class:`_Harmonic`), once within :func:`shared_harmonics`."""
    return shared_value(("harmonic", id(vehicle), id(mesh), k, F0, supported, geometric),
                        (vehicle, mesh), lambda: _new_harmonic(vehicle, mesh, k, F0=F0,
                                                               supported=supported,
                                                               geometric=geometric))


def _new_harmonic(vehicle: Vehicle, mesh: Mesh, k: int, *, F0: float, supported: bool | None,
                  geometric: bool) -> _Harmonic:
    pre = shared_value(("prestate", id(vehicle), id(mesh), F0, supported), (vehicle, mesh),
                       lambda: thrust_prestate(vehicle, mesh, F0, supported_forward_end=supported)
                       ) if geometric else None  # k-independent: once for every harmonic
    hm = harmonic_matrices(vehicle, mesh, k, prestate=pre)
    M, K, G, dmap, ke = hm.mass, hm.stiffness, hm.geometric, hm.dmap, hm.element_stiffness
    R = _rigid_subspace(mesh, dmap, k)
    liquid = tank_added_mass(vehicle, mesh, k)
    Z = None
    if liquid is not None:
        M = M + liquid.matrix
        Z = liquid.basis  # the volume-keeping motions of full closed tanks (k = 0), or None
    Q, reflectors = Z, None
    if R.shape[1]:
        MR = M @ R if Z is None else Z.T @ M @ R
        q_full, _ = np.linalg.qr(MR, mode="complete")
        # Q^T M R = 0: the M-orthogonal complement (Bathe 10.2), within the admissible motions
        Q = q_full[:, R.shape[1]:] if Z is None else Z @ q_full[:, R.shape[1]:]
        if Z is None:  # the same reflectors (geqrf of the same matrix)
            reflectors = sla.qr(MR, mode="raw")[0]
            _readonly(*reflectors)
    _readonly(M, K, G, Q, R, ke, hm.mass)
    return _Harmonic(k=k, mesh=mesh, theory=vehicle.theory, prestate=pre, M=M, K=K, G=G, Q=Q,
                     R=R, dmap=dmap, elem_k=ke, structural_mass=hm.mass,
                     fields=hm.shell.fields, reflectors=reflectors)


def _project(h: _Harmonic, mat: np.ndarray) -> np.ndarray:
    """Q^T mat Q, symmetrised; with Householder reflectors, (H^T mat H) without its first
    n_rigid rows and columns: O(n^2 n_rigid) instead of two dense products (Golub & Van Loan
    2013, sec. 5.1.6)."""
    if h.Q is None:
        return mat
    if h.reflectors is None:
        out = h.Q.T @ mat @ h.Q
    else:
        qr, tau = h.reflectors
        ormqr, = sla.get_lapack_funcs(("ormqr",), (qr,))
        lwork = 64 * mat.shape[0]
        left, _, info = ormqr("L", "T", qr, tau, mat, lwork)
        both, _, info2 = ormqr("R", "N", qr, tau, left, lwork, overwrite_c=1)
        if info or info2:
            raise ValueError(f"_project: LAPACK ormqr failed (info {info}, {info2})")
        out = both[h.n_rigid:, h.n_rigid:]
    return 0.5 * (out + out.T)


def _lowest_sparse(A: np.ndarray, B: np.ndarray, count: int) -> tuple | None:
    """The ``count`` lowest eigenpairs of A x = lambda B x (symmetric, B positive definite),
    B-normalised, ascending, when A is positive definite (None otherwise), to machine
    precision, in shift-invert mode about 0 on a symmetric sparse LU of A: Lanczos with full
    reorthogonalisation (:func:`_lanczos`), accepted when Sylvester's law of inertia counts
    exactly ``count`` eigenvalues below a shift between its last wanted and its next Ritz
    value (none missed, e.g. a multiple one; else the dense ``eigh``); not converged within
    its steps, implicitly restarted Lanczos (ARPACK; R. B. Lehoucq, D. C. Sorensen, C. Yang,
    *ARPACK Users' Guide*, 1998, sec. 3.2; tol = 0).
    The pairs of the dense ``eigh``; one sparse factorisation of the banded FE matrix (dense
    only in the liquid's blocks) instead of a dense tridiagonal reduction. Positive
    definiteness by the same law: the pivots of the symmetric factorisation (no row
    interchange) are all positive.
    """
    As = _sparse(A.T).T  # CSC: the CSR of the transpose
    lu = spla.splu(As, permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0,
                   options={"SymmetricMode": True})
    if np.any(lu.perm_r != lu.perm_c) or np.any(lu.U.diagonal() <= 0.0):
        return None
    Bs = _sparse(B)
    found = _lanczos(lu.solve, Bs, count)
    below = -1 if found is None else _count_below(As - found[2] * Bs)
    if below == count:
        vals, vecs = found[0], found[1]
    elif found is not None:  # one missed (a multiple eigenvalue) or undecided: dense
        vals, vecs = sla.eigh(A, B, subset_by_index=(0, count - 1), driver="gvx")
    else:
        op = spla.LinearOperator(A.shape, matvec=lu.solve, dtype=float)
        vals, vecs = spla.eigsh(As, k=count, M=Bs, sigma=0.0, OPinv=op, which="LM", tol=0.0,
                                v0=np.ones(A.shape[0]),
                                ncv=min(A.shape[0], max(2 * count + 1, count + ARPACK_EXTRA)))
    order = np.argsort(vals)
    vals, vecs = vals[order], vecs[:, order]
    return vals, vecs / np.sqrt(np.einsum("ij,ij->j", vecs, B @ vecs))


def _sparse(A: np.ndarray) -> sp.csr_matrix:
    """``scipy.sparse.csr_matrix(A)`` of a dense 2-D array, the same arrays (row-major order of
    the nonzeros, sorted, no duplicates), without the coordinate form and its sort."""
    n_rows, n_cols = A.shape
    flat = np.ravel(A)
    nz = np.flatnonzero(flat)
    indptr = np.zeros(n_rows + 1, dtype=np.int32)
    np.cumsum(np.bincount(nz // n_cols, minlength=n_rows), out=indptr[1:])
    return sp.csr_matrix((flat[nz], (nz % n_cols).astype(np.int32), indptr), shape=A.shape)


def _lanczos(solve: Callable, B, count: int) -> tuple | None:
    """(lambda (count,), x (n, count), shift) of A x = lambda B x by Lanczos on A^-1 B in the B
    inner product from x0 = 1, every new vector B-orthogonalised twice against all the
    previous ones (B. N. Parlett, *The Symmetric Eigenvalue Problem*, 1998, sec. 13.4;
    T. Ericsson, A. Ruhe, Math. Comp. 35 (1980) 1251-1268), converged when the residual
    |beta_m s_mi| of each of the count + 1 largest Ritz values theta_i of 1 / lambda is at
    most machine epsilon x theta_i (ARPACK's test at tol = 0); the shift is halfway between
    the count-th and the next lambda. None when not converged within the step limit
    (:data:`LANCZOS_FACTOR`, :data:`LANCZOS_EXTRA`) or on a breakdown.
    """
    n = B.shape[0]
    limit = min(n, max(LANCZOS_FACTOR * count, count + LANCZOS_EXTRA))
    if limit < count + 2:
        return None
    Q, BQ = np.zeros((limit, n)), np.zeros((limit, n))
    alpha, beta = np.zeros(limit), np.zeros(limit)
    v = np.ones(n)
    bv = B @ v
    norm = np.sqrt(v @ bv)
    Q[0], BQ[0] = v / norm, bv / norm
    check = count + 20
    eps = np.finfo(float).eps
    for j in range(limit):
        w = solve(BQ[j])
        alpha[j] = w @ BQ[j]
        for _ in range(2):
            w -= Q[:j + 1].T @ (BQ[:j + 1] @ w)
        bw = B @ w
        beta[j] = np.sqrt(max(float(w @ bw), 0.0))
        m = j + 1
        if m >= min(check, limit):
            theta, S = sla.eigh_tridiagonal(alpha[:m], beta[:m - 1])
            theta, S = theta[::-1], S[:, ::-1]
            want = slice(0, count + 1)
            if np.all(np.abs(beta[j] * S[-1, want]) <= eps * np.abs(theta[want])) and \
                    theta[count] > 0.0:
                lam = 1.0 / theta[:count + 1]
                return lam[:count], Q[:m].T @ S[:, :count], 0.5 * (lam[count - 1] + lam[count])
            check = m + 10
        if m == limit or beta[j] <= eps * abs(alpha[j]):
            return None
        Q[m], BQ[m] = w / beta[j], bw / beta[j]
    return None


def _count_below(shifted) -> int:
    """The number of eigenvalues of A x = lambda B x below a shift s from ``shifted`` = A - s B
    (sparse): the negative pivots of its symmetric factorisation (Sylvester's law of
    inertia); -1 when it needs a row interchange or a pivot is zero (undecided)."""
    try:
        lu = spla.splu(sp.csc_matrix(shifted), permc_spec="MMD_AT_PLUS_A",
                       diag_pivot_thresh=0.0, options={"SymmetricMode": True})
    except RuntimeError:
        return -1
    d = lu.U.diagonal()
    if np.any(lu.perm_r != lu.perm_c) or np.any(d == 0.0):
        return -1
    return int(np.count_nonzero(d < 0.0))


def eigenvalues_below(stiffness: np.ndarray, mass: np.ndarray, w2: float) -> int:
    """The number of eigenvalues of K x = lambda M x below ``w2``: the negative eigenvalues of
    K - w2 M (Sylvester's law of inertia; B. N. Parlett, *The Symmetric Eigenvalue Problem*,
    1998, sec. 3.3), from the pivots of its sparse symmetric factorisation
    (:func:`_count_below`) or, when that needs an interchange, of the dense Bunch-Kaufman
    LDL^T (its 1 x 1 and 2 x 2 blocks: a symmetric tridiagonal D).

    Parameters
    ----------
    stiffness, mass : numpy.ndarray
        K symmetric and M symmetric positive definite, shape (n, n).
    w2 : float
        The shift, in the units of K / M (1/s^2 for N/m and kg).
    """
    shifted = np.asarray(stiffness, dtype=float) - w2 * np.asarray(mass, dtype=float)
    below = _count_below(shifted)
    if below >= 0:
        return below
    _, d, _ = sla.ldl(shifted, lower=True)
    lam = sla.eigvalsh_tridiagonal(np.diag(d).copy(), np.diag(d, -1).copy())
    return int(np.count_nonzero(lam < 0.0))


def _solve(h: _Harmonic, *, loaded: bool, n_modes: int | None, w2_max: float | None):
    """Lowest eigenpairs (omega^2, reduced vectors (n, m), M-orthonormal) of K_e x = omega^2
    M x, or of (K_e + K_g) x = omega^2 M x when ``loaded``, on the complement of the rigid
    motions; omega^2 are the Rayleigh quotients of the vectors (:func:`_rayleigh`). Once per
    harmonic and arguments within :func:`shared_harmonics`."""
    def make():
        vals, vecs = _new_solve(h, loaded=loaded, n_modes=n_modes, w2_max=w2_max)
        _readonly(vals, vecs)
        return vals, vecs

    return shared_value(("solve", id(h), loaded, n_modes, w2_max), (h,), make)


def _new_solve(h: _Harmonic, *, loaded: bool, n_modes: int | None, w2_max: float | None):
    stiff = h.K + h.G if loaded else h.K
    if n_modes is None and w2_max is not None and h.Q is None and eigenvalues_below(
            stiff, h.M, w2_max) == 0:
        return np.zeros(0), np.zeros((stiff.shape[0], 0))
    A = _project(h, stiff)
    B = _project(h, h.M)
    # symmetric diagonal scaling (unit mass diagonal): better-conditioned Cholesky reduction
    scale = 1.0 / np.sqrt(np.diag(B))
    A = A * scale[:, None] * scale[None, :]
    B = B * scale[:, None] * scale[None, :]
    n = A.shape[0]
    kw: dict = {"driver": "gvx"}
    if n_modes is not None:
        kw["subset_by_index"] = (0, min(n, n_modes) - 1)
    sparse = None
    if n_modes is not None and h.Q is None and n >= SPARSE_MIN_DOFS and n_modes <= n // 8:
        sparse = _lowest_sparse(A, B, n_modes)
    if sparse is not None:
        vals, vecs = sparse
        if w2_max is not None:
            sel = vals <= w2_max
            vals, vecs = vals[sel], vecs[:, sel]
    elif w2_max is not None:
        if n_modes is not None:
            vals, vecs = sla.eigh(A, B, **kw)
            sel = vals <= w2_max
            vals, vecs = vals[sel], vecs[:, sel]
        else:
            kw["subset_by_value"] = (-np.inf, w2_max)
            vals, vecs = sla.eigh(A, B, **kw)
    else:
        vals, vecs = sla.eigh(A, B, **kw)
    vecs = vecs * scale[:, None]
    if h.Q is not None:
        vecs = h.Q @ vecs
    if vals.size:
        vals = _rayleigh(h, vecs, loaded=loaded)
        order = np.argsort(vals, kind="stable")
        vals, vecs = vals[order], vecs[:, order]
    return vals, vecs


def _local(mesh: Mesh, dmap: DofMap, vecs: np.ndarray) -> np.ndarray:
    """Element DOFs in the element frames of reduced vectors (n, m): shape (m, e, n_dof)."""
    q = dmap.expand(vecs.T)[:, mesh.dofs]
    return np.einsum("eij,mej->mei", node_transform(mesh), q)


def _rayleigh(h: _Harmonic, vecs: np.ndarray, *, loaded: bool) -> np.ndarray:
    """Rayleigh quotients (1/s^2) of reduced vectors (n, m): strain energy from the Gauss-point
    strains over x^T M x; accurate to round-off relative to themselves and an upper bound of
    the mesh's eigenvalue (Bathe 1996, sec. 10.2.5).
    """
    mesh = h.mesh
    fields = h.fields
    pre = h.prestate if loaded else None
    resultants = [] if pre is None else [(pre.meridional, pre.hoop)]
    fixed = pressure_resultants(mesh)
    if fixed is not None:
        resultants.append(fixed)
    ns0 = sum(n for n, _ in resultants) if resultants else None
    nt0 = sum(n for _, n in resultants) if resultants else None
    energy = element_energies(fields, _local(mesh, h.dmap, vecs), ns0=ns0, nt0=nt0)
    if pre is not None and pre.ring_node.size:
        ring = ring_matrix(h.theory, h.dmap, pre, h.k)
        energy = energy + np.einsum("am,am->m", vecs, ring @ vecs)
    rings = pressure_rings(mesh)  # the pressure's junction rings, part of K_e
    if rings is not None:
        ring = ring_matrix(h.theory, h.dmap, rings, h.k)
        energy = energy + np.einsum("am,am->m", vecs, ring @ vecs)
    return energy / np.einsum("am,am->m", vecs, h.M @ vecs)  # matrix products (BLAS)


def _sample(mesh: Mesh, dmap, vecs: np.ndarray, xi: np.ndarray):
    """Local (U, V, W) of reduced vectors (n, m) at points xi of every element: (m, 3, e, q)."""
    ref = reference_element(mesh.order)
    q = _local(mesh, dmap, vecs)
    nuv, nw = ref.evaluate(xi)
    scale = np.ones((mesh.n_elements, ref.iw.size))
    scale[:, ref.slope] = 0.5 * mesh.length[:, None]
    U = np.einsum("qi,mei->meq", nuv, q[:, :, ref.iu])
    V = np.einsum("qi,mei->meq", nuv, q[:, :, ref.iv])
    W = np.einsum("qi,mei->meq", nw, q[:, :, ref.iw] * scale[None])
    return np.stack([U, V, W], axis=1)


def _labels(mesh: Mesh, h: _Harmonic, vecs: np.ndarray, k: int, n_pts_per_el: int):
    """(kinetic shares, segment, meridian order, type, sampled shapes) of the modes ``vecs``,
    once per harmonic, vectors and sampling within :func:`shared_harmonics` (read-only)."""
    def make():
        out = _new_labels(mesh, h, vecs, k, n_pts_per_el)
        _readonly(*out)
        return out

    return shared_value(("labels", id(mesh), id(h), id(vecs), k, n_pts_per_el),
                        (mesh, h, vecs), make)


def _new_labels(mesh: Mesh, h: _Harmonic, vecs: np.ndarray, k: int, n_pts_per_el: int):
    ref = reference_element(mesh.order)
    m = vecs.shape[1]
    # kinetic shares by Gauss quadrature of rho h r (U^2, V^2, W^2)
    gs = _sample(mesh, h.dmap, vecs, ref.xi)  # (m, 3, e, g)
    r_g = mesh.r1[:, None] + 0.5 * (1 + ref.xi)[None, :] * mesh.length[:, None] * \
        mesh.sin_phi[:, None]
    wgt = (mesh.wall_mass * 0.5 * mesh.length)[:, None] * ref.weight[None] * r_g
    kin = np.einsum("mceg,eg->mc", gs**2, wgt)
    share = kin / kin.sum(axis=1, keepdims=True)
    # strain energy per segment
    full = h.dmap.expand(vecs.T)[:, mesh.dofs]  # (m, e, nd)
    e_el = np.einsum("mei,eij,mej->me", full, h.elem_k, full)
    nseg = len(mesh.elements_per_segment)
    e_seg = np.zeros((m, nseg))
    np.add.at(e_seg.T, mesh.segment, e_el.T)
    segment = np.argmax(e_seg, axis=1)
    # shapes and order
    xi = np.linspace(-1.0, 1.0, n_pts_per_el)
    sh = _sample(mesh, h.dmap, vecs, xi).reshape(m, 3, -1)
    peak = np.abs(sh).max(axis=(1, 2))
    peak[peak == 0] = 1.0
    sh = sh / peak[:, None, None]
    flat = sh.reshape(m, -1)
    # sign: the first sample within SIGN_TIE_RTOL of the peak is positive (a tie, e.g. a
    # breathing lobe of +1 and one of -1, decided by position, not by round-off)
    first = np.argmax(np.abs(flat) >= 1.0 - SIGN_TIE_RTOL, axis=1)
    sign = np.sign(flat[np.arange(m), first])
    sh = sh * sign[:, None, None]
    dom = np.argmax(share, axis=1)
    comp = sh[np.arange(m), dom]  # (m, pts)
    amp = np.abs(comp).max(axis=1, keepdims=True)
    sig = np.where(np.abs(comp) > 1e-3 * amp, np.sign(comp), 0.0)
    # carry the last nonzero sign forward over the negligible samples, count sign changes
    last = np.maximum.accumulate(np.where(sig != 0, np.arange(sig.shape[1])[None, :], 0), axis=1)
    filled = np.take_along_axis(sig, last, axis=1)
    order = np.count_nonzero(filled[:, 1:] * filled[:, :-1] < 0, axis=1)
    if k == 0:
        names = np.array(["axial", "torsional", "breathing"])[dom]
    elif k == 1:
        names = np.where(share[:, 0] > 0.5, "axial", "bending")
    else:
        names = np.array(["axial", "torsional", "radial"])[dom]
    return share, segment, order, names.astype(str), sh


def _check_common(vehicle, k_max, prestress_F0):
    if not isinstance(vehicle, Vehicle):
        raise ValueError(f"vehicle = {vehicle!r}: must be a Vehicle")
    k_max = count("k_max", k_max, 0, K_MAX)
    return k_max, finite("prestress_F0", prestress_F0)


def vehicle_modes(
    vehicle: Vehicle,
    *,
    k_max: int,
    k_min: int = 0,
    f_max: float | None = None,
    n_modes: int | None = None,
    band_factor: float = BAND_FACTOR,
    prestress_F0: float = 0.0,
    supported_forward_end: bool | None = None,
    elements_per_segment: int | tuple | None = None,
    order: int = DEFAULT_ORDER,
    points_per_element: int = 9,
    tolerance: float | None = None,
    refinement: int = 1,
) -> VehicleModes:
    """Natural frequencies and labelled mode shapes for k = k_min..k_max (Bathe 1996 sec. 10.2).

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    k_max, k_min : int
        Highest circumferential wave number, 0..200, and the lowest, 0..k_max.
    f_max : float, optional
        Keep the elastic modes up to this frequency (Hz), > 0.
    n_modes : int, optional
        Keep at most this many elastic modes per k, 1..2000.
    band_factor : float
        Without ``f_max`` and ``n_modes``: keep modes up to this times the lowest elastic
        frequency over all k, >= 1.
    prestress_F0 : float
        Thrust (N) of the steady prestress (0: unloaded).
    supported_forward_end : bool or None
        Load path of the thrust (:func:`~.assembly.thrust_prestate`).
    elements_per_segment, order : see :func:`~.assembly.mesh_vehicle`.
    points_per_element : int
        Shape samples per element, 2..50.
    tolerance : float, optional
        Target relative accuracy, 1e-9..0.1: every element split in 2, 4, 8 until no frequency
        changes by more than this (ValueError if not reached at 8).
    refinement : int
        Split every element into this many equal ones first, 1..64.
    """
    k_max, F0 = _check_common(vehicle, k_max, prestress_F0)
    k_min = count("k_min", k_min, 0, k_max)
    if f_max is not None:
        f_max = positive("f_max", f_max)
    if n_modes is not None:
        n_modes = count("n_modes", n_modes, 1, 2000)
    band_factor = finite("band_factor", band_factor)
    if band_factor < 1.0:
        raise ValueError(f"band_factor = {band_factor!r}: must be >= 1")
    points_per_element = count("points_per_element", points_per_element, 2, 50)
    opts = dict(k_min=k_min, k_max=k_max, f_max=f_max, n_modes=n_modes, band_factor=band_factor,
                F0=F0, supported=supported_forward_end, points_per_element=points_per_element)
    refinement = count("refinement", refinement, 1, 64)
    if tolerance is None:
        mesh = _mesh(vehicle, elements_per_segment, order, refinement)
        return _modes_on_mesh(vehicle, mesh, **opts)
    tolerance = positive("tolerance", tolerance)
    if not 1e-9 <= tolerance <= 0.1:
        raise ValueError(f"tolerance = {tolerance!r}: must be in [1e-9, 0.1]")
    previous, change = None, np.inf
    for split in (1, 2, 4, 8):
        mesh = mesh_vehicle(vehicle, elements_per_segment=elements_per_segment, order=order,
                            refinement=split * refinement)
        current = _modes_on_mesh(vehicle, mesh, **opts)
        if previous is not None:
            change = _max_change(previous, current)
            if change <= tolerance:
                return current
        previous = current
    raise ValueError(f"tolerance = {tolerance!r}: not reached with every element split in 8 "
                     f"(last change {change:.3g})")


def _max_change(coarse: VehicleModes, fine: VehicleModes) -> float:
    """Largest relative change of the frequencies of each k (matched in order)."""
    change = 0.0
    for kk in np.unique(np.concatenate([coarse.k, fine.k])):
        a, b = coarse.omega[coarse.k == kk], fine.omega[fine.k == kk]
        n = min(a.size, b.size)
        if n:  # (a mode that crossed the band edge has no partner and is not compared)
            change = max(change, float(np.max(np.abs(a[:n] / b[:n] - 1.0))))
    return change


def _modes_on_mesh(vehicle: Vehicle, mesh: Mesh, *, k_min: int, k_max: int,
                   f_max: float | None, n_modes: int | None, band_factor: float, F0: float,
                   supported: bool | None, points_per_element: int) -> VehicleModes:
    """The work of :func:`vehicle_modes` on one mesh (arguments already checked)."""
    supported_forward_end = supported
    loaded = F0 != 0.0
    ks = list(range(k_min, k_max + 1))
    band = f_max is None and n_modes is None
    if band:  # likely lowest harmonics first, so that the band bound is found early
        ks.sort(key=lambda kk: (kk == 0, abs(kk - 2)))
    w2_bound = None if f_max is None else (2.0 * np.pi * f_max) ** 2
    results = {}
    for kk in ks:
        h = _harmonic(vehicle, mesh, kk, F0=F0, supported=supported_forward_end,
                      geometric=loaded)
        if band and w2_bound is None:
            vals, vecs = _solve(h, loaded=loaded, n_modes=min(12, h.M.shape[0]), w2_max=None)
            positive_vals = vals[vals > 0]
            if positive_vals.size:
                w2_bound = band_factor**2 * positive_vals[0]
                if vals[-1] < w2_bound:
                    vals, vecs = _solve(h, loaded=loaded, n_modes=None, w2_max=w2_bound)
        else:
            vals, vecs = _solve(h, loaded=loaded, n_modes=n_modes, w2_max=w2_bound)
        if band and vals.size and vals[0] > 0:
            w2_bound = min(w2_bound, band_factor**2 * vals[0])
        results[kk] = (h, vals, vecs)
    rows = []
    s_pts = None
    for kk in sorted(results):
        h, vals, vecs = results[kk]
        if band and w2_bound is not None:  # None: no harmonic has a positive omega^2 (the
            keep = vals <= w2_bound  # prestress buckles them all: the check below says so)
            vals, vecs = vals[keep], vecs[:, keep]
        _check_positive(vals, F0, kk)
        if vals.size == 0:
            continue
        share, seg, ordr, names, sh = _labels(mesh, h, vecs, kk, points_per_element)
        rows.append((np.full(vals.size, kk), np.sqrt(vals), ordr, names, seg, share, sh))
    xi = np.linspace(-1.0, 1.0, points_per_element)
    t = 0.5 * (1 + xi)[None, :] * mesh.length[:, None]
    s_pts = (mesh.s1[:, None] + t).ravel()
    x_pts = (mesh.x1[:, None] + t * mesh.cos_phi[:, None]).ravel()
    r_pts = (mesh.r1[:, None] + t * mesh.sin_phi[:, None]).ravel()
    rigid = {kk: results[kk][0].n_rigid for kk in results if kk in (0, 1)}
    if rows:
        cat = [np.concatenate([row[i] for row in rows]) for i in range(7)]
    else:
        cat = [np.zeros(0, int), np.zeros(0), np.zeros(0, int), np.zeros(0, str),
               np.zeros(0, int), np.zeros((0, 3)), np.zeros((0, 3, s_pts.size))]
    omega = cat[1]
    _check_finite(omega, cat[5], cat[6])
    return VehicleModes(k=cat[0].astype(int), omega=omega, hz=omega / (2.0 * np.pi),
                        order=cat[2].astype(int), type=cat[3].astype(str),
                        segment=cat[4].astype(int), kinetic_share=cat[5], s=s_pts, x=x_pts,
                        r=r_pts, shapes=cat[6], rigid_modes=rigid, prestress_F0=F0,
                        load_path=load_path(vehicle, supported), theory=vehicle.theory,
                        elements_per_segment=mesh.elements_per_segment,
                        element_order=mesh.order, warnings=vehicle.warnings)


def _check_positive(vals: np.ndarray, F0: float, k: int) -> None:
    if np.any(vals <= 0):
        raise BucklingError(f"prestress_F0 = {F0!r}: k = {k} has a non-positive omega^2 "
                            f"({vals.min():.4g} 1/s^2): the prestress exceeds a buckling load",
                            k, F0)


def _check_finite(*arrays: np.ndarray) -> None:
    for arr in arrays:
        if not np.all(np.isfinite(arr)):
            raise ValueError("vehicle_modes: non-finite result (mesh or input out of range)")


def modal_system(
    vehicle: Vehicle, k: int, n_modes: int, F0: float, *,
    supported_forward_end: bool | None = None, rigid: bool = False, loaded: bool = True,
    elements_per_segment: int | tuple | None = None, order: int = DEFAULT_ORDER,
) -> ModalSystem:
    """Harmonic k in the basis of its lowest n_modes modes loaded by the steady thrust F0 (Bolotin
    1964, sec. 8).

    The steady part is exact and the own-mode terms of the pulsating part are those of the
    full model; ``loaded=False``: the unloaded modes (when the conservative thrust alone would
    buckle the harmonic, as the follower thrust's k = 1).

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    k : int
        Circumferential wave number, 0..200.
    n_modes : int
        Modes in the basis, 1..2000 (the rigid ones included with ``rigid``).
    F0 : float
        Thrust (N) of the prestress.
    supported_forward_end : bool or None
        Load path of the thrust (:func:`~.assembly.thrust_prestate`).
    rigid : bool
        Put the admissible rigid-body motions (k = 0, 1) first, M-orthonormal.
    loaded : bool
        Elastic basis modes of K_e + K_g (True) or of K_e.
    elements_per_segment, order : see :func:`~.assembly.mesh_vehicle`.
    """
    return labelled_modal_system(vehicle, k, n_modes, F0,
                                 supported_forward_end=supported_forward_end, rigid=rigid,
                                 loaded=loaded, elements_per_segment=elements_per_segment,
                                 order=order)[0]


def labelled_modal_system(
    vehicle: Vehicle, k: int, n_modes: int, F0: float, *,
    supported_forward_end: bool | None = None, rigid: bool = False, loaded: bool = True,
    elements_per_segment: int | tuple | None = None, order: int = DEFAULT_ORDER,
    unloaded_frequencies: bool = True,
) -> tuple[ModalSystem, Callable[[], tuple[np.ndarray, np.ndarray]]]:
    """:func:`modal_system` and ``labels() -> (order, type)`` of its elastic basis modes, each
    (n - n_rigid,), evaluated when called (an omega^2 <= 0 raises then).

    Parameters
    ----------
    vehicle, k, n_modes, F0, supported_forward_end, rigid, loaded, elements_per_segment, order
        As :func:`modal_system`.
    unloaded_frequencies : bool
        With ``loaded``, also solve the unloaded eigenproblem for ``omega_unloaded``; False
        skips it (``omega_unloaded`` then empty; every other field the same).
    """
    _, F0 = _check_common(vehicle, 0, F0)
    k = count("k", k, 0, K_MAX)
    n_modes = count("n_modes", n_modes, 1, 2000)
    mesh = _mesh(vehicle, elements_per_segment, order)
    h = _harmonic(vehicle, mesh, k, F0=F0, supported=supported_forward_end, geometric=True)
    n_rigid = h.n_rigid if rigid else 0
    n_elastic = n_modes - n_rigid
    if n_elastic < 0:
        raise ValueError(f"n_modes = {n_modes}: fewer than the {n_rigid} rigid modes of k = {k}")
    vals, vecs = np.zeros(0), np.zeros((h.M.shape[0], 0))
    unloaded = np.zeros(0)
    if n_elastic:
        vals, vecs = _solve(h, loaded=loaded, n_modes=n_elastic, w2_max=None)
        if not loaded:
            unloaded = vals
        elif unloaded_frequencies:
            unloaded = _solve(h, loaded=False, n_modes=n_elastic, w2_max=None)[0]
    if vals.size < n_elastic:
        raise ValueError(f"n_modes = {n_modes}: the mesh has only {vals.size + n_rigid} modes "
                         f"for k = {k}")
    basis = vecs
    if n_rigid:  # M-orthonormal rigid motions, M-orthogonal to the elastic modes
        chol = np.linalg.cholesky(h.R.T @ h.M @ h.R)
        basis = np.hstack([np.linalg.solve(chol, h.R.T).T, vecs])
    kg = basis.T @ h.G @ basis
    kg = 0.5 * (kg + kg.T)
    stiff = np.zeros_like(kg)
    el = slice(n_rigid, None)
    stiff[el, el] = np.diag(vals) - (kg[el, el] if loaded else 0.0)  # V^T K_e V, no round-off
    node, frame = mesh.end_nodes[0], mesh.frame[0, 0]
    a, v, b, chi = h.dmap.expand(basis.T)[:, node:node + 4].T
    aft = np.stack([a * np.cos(frame) - b * np.sin(frame), v,
                    a * np.sin(frame) + b * np.cos(frame), chi], axis=1)  # global frame
    zeros = np.zeros(n_rigid)
    ms = ModalSystem(k=k, omega=np.concatenate([zeros, np.sqrt(np.maximum(vals, 0.0))]),
                     omega_unloaded=np.concatenate([zeros, np.sqrt(np.maximum(unloaded, 0.0))])
                     if unloaded_frequencies or not loaded else np.zeros(0),
                     mass=np.eye(n_modes), stiffness=stiff, geometric=kg, F0=F0,
                     n_rigid=n_rigid, aft_edge=aft)

    def labels() -> tuple[np.ndarray, np.ndarray]:
        _check_positive(vals, F0 if loaded else 0.0, k)
        share, _, ordr, names, sh = _labels(mesh, h, vecs, k, _LABEL_POINTS)
        _check_finite(np.sqrt(vals), share, sh)
        return ordr, names

    return ms, labels


def mode_vectors(
    vehicle: Vehicle, k: int, n_modes: int, F0: float, *,
    supported_forward_end: bool | None = None, elements_per_segment: int | tuple | None = None,
    order: int = DEFAULT_ORDER,
) -> tuple[np.ndarray, np.ndarray, sp.csr_matrix]:
    """(X, M_s, M_l): the lowest ``n_modes`` elastic modes of harmonic k (loaded by F0;
    unloaded at F0 = 0) as columns on the reduced DOFs, in the order of the rows of k of
    :func:`vehicle_modes` with ``n_modes`` (orthonormal in M_s + M_l), the structure's mass
    matrix M_s (shell and lumped masses: the same for every fill; kg) and the tanks' liquid
    M_l (its added mass, sparse: nonzero on the wetted walls' DOFs only; kg), the weights of
    a mass-weighted modal assurance criterion (Allemang 2003). Within
    :func:`shared_harmonics`, the eigenproblem that :func:`vehicle_modes` solved.

    Parameters
    ----------
    vehicle, k, F0, supported_forward_end, elements_per_segment, order
        As :func:`modal_system` (F0 = 0: the unloaded modes).
    n_modes : int
        Elastic modes, 1..2000.
    """
    _, F0 = _check_common(vehicle, 0, F0)
    k = count("k", k, 0, K_MAX)
    n_modes = count("n_modes", n_modes, 1, 2000)
    mesh = _mesh(vehicle, elements_per_segment, order)
    loaded = F0 != 0.0
    h = _harmonic(vehicle, mesh, k, F0=F0, supported=supported_forward_end, geometric=loaded)
    X = _solve(h, loaded=loaded, n_modes=n_modes, w2_max=None)[1]
    return X, h.structural_mass, _sparse(h.M - h.structural_mass)


def buckling_load(
    vehicle: Vehicle, k: int, *, F0: float = 1.0, n_modes: int = 1,
    supported_forward_end: bool | None = None, elements_per_segment: int | tuple | None = None,
    order: int = DEFAULT_ORDER, points_per_element: int = 9,
) -> BucklingLoad:
    """Linear buckling load factors of harmonic k, K_e x = -lambda K_g(F0) x (Brush & Almroth
    1975, ch. 5); ValueError with fewer than ``n_modes`` positive factors.

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    k : int
        Circumferential wave number, 0..200.
    F0 : float
        Reference thrust (N), > 0.
    n_modes : int
        Number of load factors returned, 1..200.
    supported_forward_end : bool or None
        Load path of the thrust (:func:`~.assembly.thrust_prestate`).
    elements_per_segment, order : see :func:`~.assembly.mesh_vehicle`.
    points_per_element : int
        Shape samples per element, 2..50.
    """
    F0 = positive("F0", F0)
    k = count("k", k, 0, K_MAX)
    n_modes = count("n_modes", n_modes, 1, 200)
    points_per_element = count("points_per_element", points_per_element, 2, 50)
    if not isinstance(vehicle, Vehicle):
        raise ValueError(f"vehicle = {vehicle!r}: must be a Vehicle")
    mesh = mesh_vehicle(vehicle, elements_per_segment=elements_per_segment, order=order)
    h = _harmonic(vehicle, mesh, k, F0=F0, supported=supported_forward_end, geometric=True)
    A = _project(h, -h.G)
    B = _project(h, h.K)
    n = A.shape[0]
    # mu = 1/lambda; the largest mu give the smallest positive lambda
    mu, vecs = sla.eigh(A, B, subset_by_index=(max(0, n - n_modes), n - 1), driver="gvx")
    mu, vecs = mu[::-1], vecs[:, ::-1]
    scale = np.abs(mu).max() if mu.size else 0.0
    good = mu > 1e-12 * max(scale, 1e-300)
    if np.count_nonzero(good) < n_modes:
        raise ValueError(f"k = {k}: fewer than n_modes = {n_modes} positive load factors "
                         "(the prestress does not compress this harmonic)")
    if h.Q is not None:
        vecs = h.Q @ vecs
    lam = 1.0 / mu
    xi = np.linspace(-1.0, 1.0, points_per_element)
    sh = _sample(mesh, h.dmap, vecs, xi).reshape(vecs.shape[1], 3, -1)
    peak = np.abs(sh).max(axis=(1, 2))
    sh = sh / peak[:, None, None]
    s_pts = (mesh.s1[:, None] + 0.5 * (1 + xi)[None, :] * mesh.length[:, None]).ravel()
    return BucklingLoad(k=k, load_factor=lam, critical_thrust=lam * F0, s=s_pts, shapes=sh)
