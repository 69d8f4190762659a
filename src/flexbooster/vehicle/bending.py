"""k = 1: the bending harmonic with the rigid modes and the follower direction of the thrust.

For k = 1 the shell's modes are the vehicle's beam-like bending modes; the rigid lateral
translation and pitch belong to the same harmonic.  The basis here is the lowest n_modes
eigenvectors of (K_e, M) of :func:`flexbooster.shell_of_revolution.system_matrices` for
k = 1, *rigid modes included* (omega = 0), mass-normalised.  The thrust T(t) = F0 (1 - gamma
cos Omega t) acts at the aft edge along the axis of the aft cross-section (a follower force,
zero gimbal gain): besides the axial prestress (geometric stiffness K_g, inertia relief) it
has the lateral component T beta, beta = -U_x / r the rotation of the aft cross-section
(U_x the cos-theta amplitude of the axial displacement at the aft edge, radius r), which
works on the lateral displacement y = (W - V) / 2 of the aft edge (W, V the u_r and v
amplitudes: the k = 1 rigid translation is W = 1, V = -1).  In modal coordinates

    q'' + C q' + (diag(omega^2) + (T(t) / F0) (K_g - F0 y beta^T)) q = 0,

non-symmetric (the follower term; Beal 1965, eq. 4 in Galerkin form; Bolotin 1963 ch. 1 for
follower forces).  At gamma = 0 the steady system of a free-free uniform tube flutters (two
bending frequencies coalesce) at Beal's T = 109.69 EI / l^2.

The gimbal control turns the thrust by K psi further (psi the rigid pitch angle; Tech Memo 104
eq. 2.2-2): the lateral force is T (beta + K psi).  The parametric regions in Omega are those
of :func:`flexbooster.floquet.instability_regions` on this system (:func:`bending_regions`)
with the rigid translation dropped (it does not act back on the others); with zero gimbal
gain the rigid pitch is neutral (omega = 0), which the toolkit reports as a "steady" region.

References
----------
.. [1] V. L. Beal, "Dynamic stability of a flexible missile under constant and pulsating
   thrusts", AIAA J. 3 (1965) 486-494 (follower flutter load 109.69 EI / l^2).
.. [2] V. V. Bolotin, *Nonconservative Problems of the Theory of Elastic Stability*,
   Pergamon, 1963, ch. 1 (follower forces, flutter by coalescence of frequencies).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.linalg

from ..checks import count, nonnegative, positive
from ..shell_of_revolution import (
    DEFAULT_ORDER,
    Vehicle,
    mesh_vehicle,
    system_matrices,
    vehicle_modes,
)
from ..shell_of_revolution.assembly import dof_map
from .harmonic import (
    HarmonicSystem,
    ModalMatrices,
    floquet_options,
    harmonic_regions,
    in_unit_interval,
)

__all__ = ["BendingSystem", "bending_system", "bending_harmonic", "bending_regions",
           "follower_flutter_thrust"]


@dataclass(frozen=True)
class BendingSystem(ModalMatrices):
    """Periodic modal system of k = 1: q'' + C q' + (A + gamma B1 cos Omega t) q = 0.

    Attributes
    ----------
    F0 : float
        Steady thrust (N).
    damping_ratio : float
        Modal damping ratio of the elastic basis modes (dimensionless; 0 on the rigid ones).
    omega_unloaded : ndarray, shape (n,)
        Frequencies of the basis modes without thrust (rad/s); 0 for the rigid ones.
    n_rigid : int
        Rigid modes in the basis (dimensionless).
    aft_lateral, aft_rotation : ndarray, shape (n,)
        y and beta of each mass-normalised mode at the aft edge (m / sqrt(kg),
        rad / sqrt(kg)).
    mass, damping, stiffness, excitation : ndarray, shape (n, n)
        M = I, C = 2 zeta diag(omega) (1/s), A = diag(omega^2) + K_g - F0 y beta^T (1/s^2,
        non-symmetric), B1 = -(K_g - F0 y beta^T) (1/s^2).

    References
    ----------
    Beal (1965), eq. 4; Bolotin (1963), ch. 1.
    """

    F0: float
    damping_ratio: float
    omega_unloaded: np.ndarray
    n_rigid: int
    aft_lateral: np.ndarray
    aft_rotation: np.ndarray
    mass: np.ndarray
    damping: np.ndarray
    stiffness: np.ndarray
    excitation: np.ndarray

    def to_dict(self) -> dict:
        """JSON-ready mapping."""
        return {"k": 1, "F0": float(self.F0), "damping_ratio": float(self.damping_ratio),
                "omega_unloaded": self.omega_unloaded.tolist(), "n_rigid": int(self.n_rigid),
                "aft_lateral": self.aft_lateral.tolist(),
                "aft_rotation": self.aft_rotation.tolist(),
                "damping": self.damping.tolist(), "stiffness": self.stiffness.tolist(),
                "excitation": self.excitation.tolist()}


def _basis(vehicle, n_modes, supported_forward_end, elements_per_segment, order):
    """Unloaded k = 1 basis with rigid modes: (w2, Kg per N, y, beta, psi, n_rigid).

    The rigid pair of eigh (any two M-orthonormal rigid motions) is rotated into the pure
    rotation (first) and the pure translation (second, beta = 0); psi_j is the rigid pitch
    angle of basis vector j (beta of the rotation mode, 0 for the others: the elastic modes
    are M-orthogonal to the rigid ones, memo 4.1.2).
    """
    mesh = mesh_vehicle(vehicle, elements_per_segment=elements_per_segment, order=order)
    M, K, G = system_matrices(vehicle, 1, prestress_F0=1.0, mesh=mesh,
                              supported_forward_end=supported_forward_end)
    if n_modes > M.shape[0]:
        raise ValueError(f"n_modes = {n_modes}: the mesh has only {M.shape[0]} DOFs for k = 1")
    w2, V = scipy.linalg.eigh(K, M, subset_by_index=(0, n_modes - 1))
    rigid = np.abs(w2) <= 1e-8 * float(np.max(np.abs(w2)))
    w2 = np.where(rigid, 0.0, w2)
    dmap = dof_map(vehicle, mesh, 1)
    a0 = mesh.end_nodes[0]
    r_aft = vehicle.segments[0].radius_aft

    def aft(vecs):  # end nodes carry global (u_x, v, u_r, chi)
        full = dmap.expand(vecs.T)
        # lateral y: rigid translation W = 1, V = -1; rotation: u_x = -r beta cos(theta)
        return 0.5 * (full[:, a0 + 2] - full[:, a0 + 1]), -full[:, a0] / r_aft

    y, beta = aft(V)
    n_rigid = int(np.count_nonzero(rigid))
    psi = np.zeros(n_modes)
    if n_rigid == 2 and np.all(rigid[:2]):  # free-free: rotation, translation
        b = beta[:2]
        rot = np.array([[b[0], b[1]], [b[1], -b[0]]]) / np.hypot(b[0], b[1])  # orthogonal
        V = V.copy()
        V[:, :2] = V[:, :2] @ rot
        y, beta = aft(V)
        beta[1] = 0.0  # pure translation (round-off)
        psi[0] = beta[0]
    kg = V.T @ G @ V
    return w2, 0.5 * (kg + kg.T), y, beta, psi, n_rigid


def bending_system(
    vehicle: Vehicle, *, F0: float, n_modes: int = 12, damping_ratio: float = 0.01,
    gimbal_gain: float = 0.0, supported_forward_end: bool = False,
    elements_per_segment: int | tuple | None = None, order: int = DEFAULT_ORDER,
) -> BendingSystem:
    """The k = 1 periodic system with rigid modes and the follower thrust (module docstring;
    Beal 1965, eq. 4 in Galerkin form).  For a free-free vehicle the first basis mode is the
    rigid rotation and the second the rigid translation (its column of A and B is 0).

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    F0 : float
        Steady thrust (N), > 0.
    n_modes : int
        Basis modes of k = 1, rigid ones included, 2..2000.
    damping_ratio : float
        Modal damping ratio of the elastic basis modes (dimensionless), [0, 1).
    gimbal_gain : float
        K (dimensionless), >= 0: the thrust turns by K psi from the aft tangent, psi the
        rigid pitch angle (Tech Memo 104, eq. 2.2-2).
    supported_forward_end, elements_per_segment, order
        As :func:`.regions.harmonic_system`.
    """
    if not isinstance(vehicle, Vehicle):
        raise ValueError(f"vehicle = {vehicle!r}: must be a Vehicle")
    F0 = positive("F0", F0)
    n_modes = count("n_modes", n_modes, 2, 2000)
    zeta = in_unit_interval("damping_ratio", damping_ratio)
    K = nonnegative("gimbal_gain", gimbal_gain)
    w2, kg, y, beta, psi, n_rigid = _basis(vehicle, n_modes, supported_forward_end,
                                           elements_per_segment, order)
    # prestress + lateral force T (beta + K psi) of the thrust turned from the aft tangent
    # by the gimbal angle K psi (Beal eq. 4; Tech Memo 104 eq. 2.2-2)
    load = F0 * (kg - np.outer(y, beta + K * psi))
    omega = np.sqrt(w2)
    return BendingSystem(F0=F0, damping_ratio=zeta, omega_unloaded=omega, n_rigid=n_rigid,
                         aft_lateral=y, aft_rotation=beta, mass=np.eye(n_modes),
                         damping=2.0 * zeta * np.diag(omega), stiffness=np.diag(w2) + load,
                         excitation=-load)  # T/F0 = 1 - gamma cos Omega t


def follower_flutter_thrust(
    vehicle: Vehicle, *, thrust_max: float, n_modes: int = 12, n_scan: int = 64,
    supported_forward_end: bool = False, elements_per_segment: int | tuple | None = None,
    order: int = DEFAULT_ORDER, rtol: float = 1e-9,
) -> float:
    """Smallest steady thrust (N; gamma = 0, no damping) at which the k = 1 system flutters,
    inf if none up to thrust_max.

    Flutter: two frequencies of diag(omega^2) + T (K_g - y beta^T) coalesce and leave the real
    axis (Bolotin 1963, ch. 1; Beal 1965, fig. 2: 109.69 EI / l^2 for the free-free uniform
    beam); located by a scan of ``n_scan`` thrusts in (0, thrust_max] and refined by brentq on
    max |Im lambda| / max |lambda| = 1e-9.

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    thrust_max : float
        Largest thrust examined (N), > 0.
    n_modes, n_scan : int
        Basis modes of k = 1, rigid ones included, 2..2000; scan points, 2..10000.
    supported_forward_end, elements_per_segment, order
        As :func:`bending_system`.
    rtol : float
        Relative tolerance on the thrust (dimensionless), (0, 1e-2].
    """
    if not isinstance(vehicle, Vehicle):
        raise ValueError(f"vehicle = {vehicle!r}: must be a Vehicle")
    tmax = positive("thrust_max", thrust_max)
    n_modes = count("n_modes", n_modes, 2, 2000)
    n_scan = count("n_scan", n_scan, 2, 10_000)
    rtol = positive("rtol", rtol)
    if rtol > 1e-2:
        raise ValueError(f"rtol = {rtol!r}: must be <= 1e-2")
    w2, kg, y, beta, _, _ = _basis(vehicle, n_modes, supported_forward_end,
                                   elements_per_segment, order)
    load = kg - np.outer(y, beta)

    def excess(T):  # > 0 once a complex pair exists (flutter)
        lam = np.linalg.eigvals(np.diag(w2) + T * load)
        return float(np.max(np.abs(lam.imag)) / np.max(np.abs(lam))) - 1e-9

    thrusts = np.linspace(tmax / n_scan, tmax, n_scan)
    values = np.array([excess(T) for T in thrusts])  # n_scan small eigenproblems
    hit = np.nonzero(values > 0.0)[0]
    if hit.size == 0:
        return float("inf")
    i = int(hit[0])
    if i == 0:
        raise ValueError(f"thrust_max = {thrust_max!r}: the system already flutters at the "
                         f"first scan point {thrusts[0]:.6g} N (raise n_scan)")
    import scipy.optimize  # here: its import is a sixth of a run's (unused by most)

    return float(scipy.optimize.brentq(excess, thrusts[i - 1], thrusts[i],
                                       xtol=rtol * thrusts[i], maxiter=200))


def bending_regions(
    vehicle: Vehicle, *, F0: float, gamma: float, omega_min: float, omega_max: float,
    gimbal_gain: float, n_modes: int = 12, damping_ratio: float = 0.01,
    supported_forward_end: bool = False, elements_per_segment: int | tuple | None = None,
    order: int = DEFAULT_ORDER, **options,
) -> tuple:
    """Parametric instability regions of k = 1 (bending, rigid pitch, gimbaled follower thrust).

    The rows of ``vehicle_regions(..., k_min=1)`` for k = 1 (:func:`bending_harmonic`, one
    code path), sorted by omega_lo; the toolkit's size-limit errors propagate.  Bolotin
    (1964), ch. 1-2, sec. 6; Beal (1965); Tech Memo 104, eq. 2.2-2.

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    F0, gamma : float
        Steady thrust (N), > 0; pulsation amplitude (dimensionless), [0, 1).
    omega_min, omega_max : float
        Omega range (rad/s), 0 < omega_min < omega_max.
    gimbal_gain : float
        K (dimensionless), >= 0 (0: the neutral rigid pitch is a "steady" region).
    n_modes : int
        Basis modes of k = 1, rigid ones included, 3..2000.
    damping_ratio, supported_forward_end, elements_per_segment, order
        As :func:`bending_system`.
    **options
        To :func:`flexbooster.floquet.instability_regions` (rtol, step_phase, max_order,
        damping_margin, ...).
    """
    gamma = in_unit_interval("gamma", gamma)
    n_modes = count("n_modes", n_modes, 3, 2000)
    omega_min, omega_max = positive("omega_min", omega_min), positive("omega_max", omega_max)
    if omega_min >= omega_max:
        raise ValueError(f"omega_min = {omega_min!r}: must be < omega_max = {omega_max!r}")
    h = bending_harmonic(vehicle, F0=F0, n_modes=n_modes, damping_ratio=damping_ratio,
                         gimbal_gain=gimbal_gain, supported_forward_end=supported_forward_end,
                         elements_per_segment=elements_per_segment, order=order)
    opts = dict(options)
    if {"rtol", "step_phase", "max_order", "damping_margin"} >= set(opts):
        opts = floquet_options(**opts)  # the options of vehicle_regions, checked alike
    rows = harmonic_regions(h, gamma, omega_min, omega_max, opts)
    return tuple(sorted(rows, key=lambda r: r.omega_lo))


def bending_harmonic(
    vehicle: Vehicle, *, F0: float, n_modes: int = 12, damping_ratio: float = 0.01,
    gimbal_gain: float = 0.0, supported_forward_end: bool = False,
    elements_per_segment: int | tuple | None = None, order: int = DEFAULT_ORDER,
) -> HarmonicSystem:
    """The k = 1 system of :func:`bending_system` as the map's harmonic k = 1.

    The rigid translation of a free-free vehicle is dropped (its column of A and B is zero:
    it is driven but does not act back); the rest stays in the basis coordinates
    (:class:`~flexbooster.vehicle.harmonic.HarmonicSystem`), each steady mode (eigenvector
    of A, ascending real part of the eigenvalue, the toolkit's mode order) labelled by the
    basis mode that dominates it.

    ``omega_unloaded`` are those of the kept basis modes, ``omega_loaded`` the steady
    frequencies sqrt(max(Re mu, 0)) of A (rad/s).  Beal (1965), eq. 4; Bolotin (1964), sec. 8.

    Parameters
    ----------
    vehicle, F0, damping_ratio, gimbal_gain, supported_forward_end, elements_per_segment, order
        As :func:`bending_system`.
    n_modes : int
        Basis modes of k = 1, rigid ones included, 3..2000.
    """
    n_modes = count("n_modes", n_modes, 3, 2000)
    bs = bending_system(vehicle, F0=F0, n_modes=n_modes, damping_ratio=damping_ratio,
                        gimbal_gain=gimbal_gain, supported_forward_end=supported_forward_end,
                        elements_per_segment=elements_per_segment, order=order)
    keep = np.ones(n_modes, dtype=bool)
    if bs.n_rigid == 2:
        keep[1] = False  # the rigid translation: zero column, it does not act back
    M, C, A, B1 = (x[np.ix_(keep, keep)] for x in (bs.mass, bs.damping, bs.stiffness,
                                                     bs.excitation))
    # steady modes: eigenvectors of A, ascending real part (the toolkit's mode order)
    mu, X = np.linalg.eig(A)
    idx = np.lexsort((mu.imag, mu.real))
    mu, X = mu[idx], X[:, idx]
    basis = np.nonzero(keep)[0]
    pos = np.argmax(np.abs(X), axis=0)  # the basis vector dominating each steady mode
    dom = basis[pos]
    labels = vehicle_modes(vehicle, k_min=1, k_max=1, n_modes=max(1, n_modes - bs.n_rigid),
                            supported_forward_end=supported_forward_end,
                            elements_per_segment=elements_per_segment, order=order)
    rigid = dom < bs.n_rigid
    e = np.where(rigid, 0, dom - bs.n_rigid)
    share = np.abs(X[pos, np.arange(pos.size)]) ** 2 / np.sum(np.abs(X) ** 2, axis=0)
    return HarmonicSystem(
        k=1, F0=bs.F0, damping_ratio=bs.damping_ratio, omega_unloaded=bs.omega_unloaded[keep],
        omega_loaded=np.sqrt(np.maximum(mu.real, 0.0)), basis=np.real(X), mass=M, damping=C,
        stiffness=A, excitation=B1,
        mode_order=np.where(rigid, 0, labels.order[e]).astype(int),
        mode_type=np.where(rigid, "rigid-pitch", labels.type[e].astype(str)).astype(str),
        mode_share=share)
