"""k = 1: the bending harmonic with the rigid modes and the follower direction of the thrust.

Basis: the admissible rigid motions (first) and the lowest unloaded elastic modes of
(K_e, M), mass-normalised. T(t) = F0 (1 - gamma cos Omega t) at the aft edge follows the aft
cross-section (rotation beta = -U_x / r) turned by the gimbal K psi (memo 2.2-2); its lateral
component works on y = (W - V) / 2, so

    q'' + C q' + (diag(omega^2) + (T(t) / F0) (K_g - F0 y (beta + K psi)^T)) q = 0,

non-symmetric (Beal 1965, eq. 4 in Galerkin form). The rigid translation (and the pitch
without gain) does not act back and is dropped; the pitch frequency is omega_psi^2 =
F0 K d / I_cm (memo 4.2-1). Theory: docs/theory/vehicle-regions.md.

References: V. L. Beal, AIAA J. 3 (1965) 486-494; V. V. Bolotin, *Nonconservative Problems
of the Theory of Elastic Stability*, 1963, ch. 1.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..checks import count, nonnegative, positive
from ..shell_of_revolution import DEFAULT_ORDER, Vehicle, labelled_modal_system
from ..shell_of_revolution.prestress import load_path
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
        Modal damping ratio of the elastic basis modes (0 on the rigid ones).
    omega_unloaded : ndarray, shape (n,)
        Frequencies of the basis modes without thrust (rad/s); 0 for the rigid ones.
    n_rigid : int
        Rigid modes in the basis.
    aft_lateral, aft_rotation : ndarray, shape (n,)
        y and beta of each mode at the aft edge (m / sqrt(kg), rad / sqrt(kg)).
    mass, damping, stiffness, excitation : ndarray, shape (n, n)
        M = I, C = 2 zeta diag(omega) (1/s), A = diag(omega^2) + K_g - F0 y (beta + K psi)^T and
        B1 = -(K_g - F0 y (beta + K psi)^T) (1/s^2).
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


@dataclass(frozen=True)
class _Basis:
    """The k = 1 basis in modal coordinates (see :func:`_basis`)."""

    omega: np.ndarray
    stiffness: np.ndarray
    geometric: np.ndarray
    lateral: np.ndarray
    rotation: np.ndarray
    psi: np.ndarray
    n_rigid: int
    labels: object


def _basis(vehicle, n_modes, F0, supported_forward_end, elements_per_segment, order) -> _Basis:
    """The k = 1 basis: the rigid motions first (a free-free pair turned into the pure rotation,
    then the translation), then the unloaded elastic modes, with K_g of the thrust F0;
    y = (u_r - v) / 2 and beta = -u_x / r at the aft edge, psi_j the rigid pitch angle.
    """
    ms, labels = labelled_modal_system(vehicle, 1, n_modes, F0, rigid=True, loaded=False,
                                       supported_forward_end=supported_forward_end,
                                       elements_per_segment=elements_per_segment, order=order)
    turn = np.eye(n_modes)
    r_aft = vehicle.segments[0].radius_aft
    beta = -ms.aft_edge[:, 0] / r_aft
    if ms.n_rigid == 2:  # free-free: rotation, translation
        b = beta[:2]
        turn[:2, :2] = np.array([[b[0], b[1]], [b[1], -b[0]]]) / np.hypot(b[0], b[1])
    aft = turn.T @ ms.aft_edge
    lateral, beta = 0.5 * (aft[:, 2] - aft[:, 1]), -aft[:, 0] / r_aft
    psi = np.zeros(n_modes)
    if ms.n_rigid == 2:
        beta[1] = 0.0  # pure translation (round-off)
        psi[0] = beta[0]
    return _Basis(omega=ms.omega, stiffness=turn.T @ ms.stiffness @ turn,
                  geometric=turn.T @ ms.geometric @ turn, lateral=lateral, rotation=beta,
                  psi=psi, n_rigid=ms.n_rigid, labels=labels)


def bending_system(
    vehicle: Vehicle, *, F0: float, n_modes: int = 12, damping_ratio: float = 0.01,
    gimbal_gain: float = 0.0, supported_forward_end: bool | None = None,
    elements_per_segment: int | tuple | None = None, order: int = DEFAULT_ORDER,
) -> BendingSystem:
    """The k = 1 periodic system with rigid modes and the follower thrust; for a free-free vehicle
    the rigid rotation first, then the translation (its column of A and B is 0).

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    F0 : float
        Steady thrust (N), > 0.
    n_modes : int
        Basis modes of k = 1, rigid ones included, 2..2000.
    damping_ratio : float
        Modal damping ratio of the elastic basis modes, [0, 1).
    gimbal_gain : float
        K >= 0: the thrust turns by K psi from the aft tangent (memo 2.2-2).
    supported_forward_end : bool
        Uniform compression F0 reacted at the nose instead of inertia relief.
    elements_per_segment, order
        Mesh (see :func:`flexbooster.shell_of_revolution.mesh_vehicle`).
    """
    return _bending(vehicle, F0=F0, n_modes=n_modes, damping_ratio=damping_ratio,
                    gimbal_gain=gimbal_gain, supported_forward_end=supported_forward_end,
                    elements_per_segment=elements_per_segment, order=order)[0]


def _bending(vehicle, *, F0, n_modes, damping_ratio, gimbal_gain, supported_forward_end,
             elements_per_segment, order) -> tuple[BendingSystem, _Basis]:
    """:func:`bending_system` and its basis (for the labels of its elastic modes)."""
    if not isinstance(vehicle, Vehicle):
        raise ValueError(f"vehicle = {vehicle!r}: must be a Vehicle")
    F0 = positive("F0", F0)
    n_modes = count("n_modes", n_modes, 2, 2000)
    zeta = in_unit_interval("damping_ratio", damping_ratio)
    K = nonnegative("gimbal_gain", gimbal_gain)
    b = _basis(vehicle, n_modes, F0, supported_forward_end, elements_per_segment, order)
    # prestress + lateral force T (beta + K psi) of the thrust turned from the aft tangent
    # by the gimbal angle K psi (Beal eq. 4; Tech Memo 104 eq. 2.2-2)
    load = b.geometric - F0 * np.outer(b.lateral, b.rotation + K * b.psi)
    bs = BendingSystem(F0=F0, damping_ratio=zeta, omega_unloaded=b.omega, n_rigid=b.n_rigid,
                       aft_lateral=b.lateral, aft_rotation=b.rotation, mass=np.eye(n_modes),
                       damping=2.0 * zeta * np.diag(b.omega), stiffness=b.stiffness + load,
                       excitation=-load)  # T/F0 = 1 - gamma cos Omega t
    return bs, b


def follower_flutter_thrust(
    vehicle: Vehicle, *, thrust_max: float, n_modes: int = 12, n_scan: int = 64,
    supported_forward_end: bool | None = None, elements_per_segment: int | tuple | None = None,
    order: int = DEFAULT_ORDER, rtol: float = 1e-9,
) -> float:
    """Smallest steady thrust (N) at which the undamped k = 1 system flutters (two frequencies of
    diag(omega^2) + T (K_g - y beta^T) coalesce; Beal 1965, fig. 2), inf if none up to
    thrust_max: a scan, refined by brentq on max |Im lambda| / max |lambda| = 1e-9.

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    thrust_max : float
        Largest thrust examined (N), > 0.
    n_modes : int
        Basis modes of k = 1, rigid ones included, 2..2000.
    n_scan : int
        Scan points, 2..10000.
    supported_forward_end, elements_per_segment, order
        As :func:`bending_system`.
    rtol : float
        Relative tolerance on the thrust, (0, 1e-2].
    """
    if not isinstance(vehicle, Vehicle):
        raise ValueError(f"vehicle = {vehicle!r}: must be a Vehicle")
    tmax = positive("thrust_max", thrust_max)
    n_modes = count("n_modes", n_modes, 2, 2000)
    n_scan = count("n_scan", n_scan, 2, 10_000)
    rtol = positive("rtol", rtol)
    if rtol > 1e-2:
        raise ValueError(f"rtol = {rtol!r}: must be <= 1e-2")
    b = _basis(vehicle, n_modes, 1.0, supported_forward_end, elements_per_segment, order)
    load = b.geometric - np.outer(b.lateral, b.rotation)

    def excess(T):  # > 0 once a complex pair exists (flutter)
        lam = np.linalg.eigvals(b.stiffness + T * load)
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
    supported_forward_end: bool | None = None, elements_per_segment: int | tuple | None = None,
    order: int = DEFAULT_ORDER, **options,
) -> tuple:
    """Parametric instability regions of k = 1 as Bands sorted by Omega_lo (those of
    ``vehicle_regions(..., k_min=1)`` for k = 1, through :func:`bending_harmonic`); critical
    gamma with damping (Bolotin 1964, ch. 1-2).

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    F0 : float
        Steady thrust (N), > 0.
    gamma : float
        Pulsation amplitude, [0, 1).
    omega_min, omega_max : float
        Omega range (rad/s), 0 < omega_min < omega_max.
    gimbal_gain : float
        K >= 0 (0: the rigid pitch of a free-free vehicle is neutral and dropped).
    n_modes : int
        Basis modes of k = 1, rigid ones included, 3..2000.
    damping_ratio : float
        Modal damping ratio of the elastic modes, [0, 1) (none on the rigid pitch).
    supported_forward_end, elements_per_segment, order
        As :func:`bending_system`.
    **options
        Passed to :func:`flexbooster.floquet.instability_regions`.
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
    return tuple(sorted(rows, key=lambda r: r.Omega_lo))


def bending_harmonic(
    vehicle: Vehicle, *, F0: float, n_modes: int = 12, damping_ratio: float = 0.01,
    gimbal_gain: float = 0.0, supported_forward_end: bool | None = None,
    elements_per_segment: int | tuple | None = None, order: int = DEFAULT_ORDER,
) -> HarmonicSystem:
    """The k = 1 system of :func:`bending_system` as the map's harmonic k = 1: the rigid
    translation dropped, each steady mode (eigenvector of A, ascending) labelled by its
    dominant basis mode; ``omega_loaded`` = sqrt(max(Re mu, 0)) of A (rad/s).

    Parameters
    ----------
    vehicle, F0, damping_ratio, gimbal_gain, supported_forward_end, elements_per_segment, order
        As :func:`bending_system`.
    n_modes : int
        Basis modes of k = 1, rigid ones included, 3..2000.
    """
    n_modes = count("n_modes", n_modes, 3, 2000)
    bs, b = _bending(vehicle, F0=F0, n_modes=n_modes, damping_ratio=damping_ratio,
                     gimbal_gain=gimbal_gain, supported_forward_end=supported_forward_end,
                     elements_per_segment=elements_per_segment, order=order)
    keep = np.ones(n_modes, dtype=bool)
    if bs.n_rigid == 2:
        keep[1] = False  # the rigid translation: zero column, it does not act back
        if gimbal_gain == 0.0 and load_path(vehicle, supported_forward_end) == \
                "inertia relief":  # the neutral rigid rotation (module docstring)
            keep[0] = False
    M, C, A, B1 = (x[np.ix_(keep, keep)] for x in (bs.mass, bs.damping, bs.stiffness,
                                                     bs.excitation))
    # steady modes: eigenvectors of A, ascending real part (the toolkit's mode order)
    mu, X = np.linalg.eig(A)
    idx = np.lexsort((mu.imag, mu.real))
    mu, X = mu[idx], X[:, idx]
    basis = np.nonzero(keep)[0]
    pos = np.argmax(np.abs(X), axis=0)  # the basis vector dominating each steady mode
    dom = basis[pos]
    order_, type_ = b.labels()
    rigid = dom < bs.n_rigid
    e = np.where(rigid, 0, dom - bs.n_rigid)
    share = np.abs(X[pos, np.arange(pos.size)]) ** 2 / np.sum(np.abs(X) ** 2, axis=0)
    return HarmonicSystem(
        k=1, F0=bs.F0, damping_ratio=bs.damping_ratio, omega_unloaded=bs.omega_unloaded[keep],
        omega_loaded=np.sqrt(np.maximum(mu.real, 0.0)), basis=np.real(X), mass=M, damping=C,
        stiffness=A, excitation=B1,
        mode_order=np.where(rigid, 0, order_[e]).astype(int),
        mode_type=np.where(rigid, "rigid-pitch", type_[e].astype(str)).astype(str),
        mode_share=share)
