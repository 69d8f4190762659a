"""Beam action under a gimbaled pulsating end thrust: Floquet exponents alpha_r (memo 4.1).

A uniform free-free beam of the composite's mass, length 2L and first frequency omega_1
(4.2-8b) under F0 (1 - gamma cos Omega t) turned by K psi (2.2-2): with tau = omega_1 t,
q'' + [Lambda + f(tau) B] q = 0, q = (q_1 .. q_N, q_B) (4.1-12). Exponents from the monodromy
checked by Hill's determinant; bands from their boundaries, below omega_1 / 4 the rigid-pitch
tongues by harmonic balance. Theory: docs/theory/beam-action.md.

References: Tech Memo 104, sec. 2.2, 4.1, 4.2; V. L. Beal, AIAA J. 3 (1965) 486-494;
V. V. Bolotin, *The Dynamic Stability of Elastic Systems*, 1964; W. Magnus, S. Winkler,
*Hill's Equation*, 1966; J. D. Lawson, SIAM J. Numer. Anal. 4 (1967) 372-380.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

import numpy as np

from ..bands import CRITICAL_DAMPING_COUNT, NEGLIGIBLE_GROWTH, Band, BandMode, SearchGap, gaps_text
from ..checks import count, nonnegative, positive
from ..floquet import (
    REAL_ROOT_RTOL,
    LinearPeriodicSystem,
    PeriodMapOverflowError,
    critical_amplitude,
    critical_damping,
    floquet_multipliers,
    golden_section_max,
    hill_modes,
    instability_regions,
    periodic_boundaries,
    periodic_system,
    step_counts,
)
from ..floquet import hill_exponents as floquet_hill_exponents
from . import beam

if TYPE_CHECKING:
    from .model import BoosterModel

__all__ = ["PeriodMapOverflowError", "BeamActionSystem", "beam_action_system", "beam_system",
           "uniform_beam_system", "follower_flutter_load", "loaded_frequencies", "HillResult",
           "hill_exponents", "monodromy_exponents", "monodromy_steps", "MONODROMY_MAX_STEPS",
           "reduced_exponents", "natural_branch", "BAND_RTOL", "BAND_MAX_ORDER",
           "BAND_MAX_CANDIDATES", "BAND_OMEGA_BAR_MIN", "TONGUE_MAX_HARMONICS",
           "TONGUE_HILL_HARMONICS", "TONGUE_GAMMA_RTOL", "TONGUE_RTOL_FLOOR",
           "TONGUE_FLOOR_OMEGA_BAR", "TONGUE_MAX_ORDER", "TongueEdgesError",
           "tongue_hill_harmonics", "pitch_mode", "pitch_guide", "band_modes", "modal_damping",
           "beam_action_bands", "pitch_tongue_bands", "pipeline_bands", "BeamActionResult",
           "beam_action_analysis", "StabilityChart", "stability_chart", "band_critical_damping",
           ]

_STABLE_TOL = 1e-6  # |Im alpha| below which an exponent counts as real (see docs)

#: Cap on the automatic step count of :func:`monodromy_exponents` per half period: the
#: largest count the memo case uses.
MONODROMY_MAX_STEPS = 8192


# --------------------------------------------------------------------------------------------
# The model
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class BeamActionSystem:
    """The normalised beam-action system q'' + [Lambda + f(tau) B] q = 0 (tau = omega_1 t).

    Attributes
    ----------
    Lambda, B : numpy.ndarray
        (lambda_n / lambda_1)^4 and 0 for q_B, shape (N + 1,); the thrust matrix per unit f(tau),
        (N + 1, N + 1), non-symmetric (dimensionless).
    omega_1 : float
        First free-free frequency (rad/s) normalising time.
    load, K : float
        F0 / (M L omega_1^2) (P l^2 / EI = lambda_1^4 load / 2) and the gimbal gain.
    N : int
        Elastic modes.
    """

    Lambda: np.ndarray
    B: np.ndarray
    omega_1: float
    load: float
    K: float
    N: int

    @property
    def A0(self) -> np.ndarray:
        """Steady-thrust matrix Lambda + B (gamma = 0)."""
        return np.diag(self.Lambda) + self.B

    @property
    def p(self) -> float:
        """Steady thrust as P l^2 / EI (dimensionless)."""
        return float(beam.free_free_eigenvalues(1)[0] ** 4 * self.load / 2.0)

    def to_dict(self) -> dict:
        """JSON-ready mapping of the matrices and parameters."""
        return {
            "Lambda": self.Lambda.tolist(),
            "B": self.B.tolist(),
            "omega_1": float(self.omega_1),
            "load": float(self.load),
            "p": self.p,
            "K": float(self.K),
            "N": int(self.N),
        }


def _modal_integrals(N: int, n_quad: int | None = None) -> tuple[np.ndarray, ...]:
    """G_nk = int_0^2 (1 - zeta/2) phi_n,zeta phi_k,zeta dzeta, phi_n(0), phi_n,zeta(0)."""
    if N == 0:
        empty = np.zeros(0)
        return np.zeros((0, 0)), empty, empty, empty
    lam = beam.free_free_eigenvalues(N)
    n_quad = max(64, 8 * N + 32) if n_quad is None else int(n_quad)
    x, w = np.polynomial.legendre.leggauss(n_quad)
    zeta = x + 1.0  # Gauss-Legendre on zeta in [0, 2]
    n = np.arange(1, N + 1)
    dphi = beam.mode_shape(n[:, None], zeta[None, :], 1) * (lam[:, None] / 2.0)  # d phi / d zeta
    G = (dphi * ((1.0 - zeta / 2.0) * w)) @ dphi.T  # axial compression N(x) = F (1 - x/l)
    phi0 = beam.mode_shape(n, np.zeros(N), 0)  # phi_n at the aft end (= 2)
    dphi0 = beam.mode_shape(n, np.zeros(N), 1) * lam / 2.0  # slope at the aft end (= -lambda alpha)
    return G, phi0, dphi0, lam


def _assemble(load: float, K: float, rho_I: float, delta: float, N: int,
              n_quad: int | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Lambda and B of the normalised system (see :func:`beam_action_system`)."""
    G, phi0, dphi0, lam = _modal_integrals(N, n_quad)
    lam1 = beam.free_free_eigenvalues(1)[0]
    Lam = np.zeros(N + 1)
    Lam[:N] = (lam / lam1) ** 4  # omega_n^2 / omega_1^2, eq. (4.2-8b) normalisation
    B = np.zeros((N + 1, N + 1))
    # elastic rows: -eps [G_nk + phi_n(0) phi_k'(0)] q_k - eps K phi_n(0) q_B (Galerkin, Beal 1965)
    B[:N, :N] = -load * (G + np.outer(phi0, dphi0))
    B[:N, N] = -load * K * phi0
    # rigid row: moment balance about the composite CM, I_cm psi'' = -F [K d2 psi + sum ...] (4.2-1)
    B[N, :N] = load * rho_I * (phi0 + delta * dphi0)
    B[N, N] = load * rho_I * K * delta  # = omega_psi^2 / omega_1^2, eq. (4.2-1) with E2
    return Lam, B


def beam_action_system(omega_1: float, mass: float, L: float, d2: float, I_cm: float,
                       F0: float, K: float, N: int,
                       n_quad: int | None = None) -> BeamActionSystem:
    """The normalised beam-action system of the composite (memo 2.2-2, 4.1-1, 4.1-3, 4.2-1).

    With eps = F0 / (M L omega_1^2), G_nk = int_0^2 (1 - zeta/2) phi_n' phi_k' dzeta:
    B_nk = -eps [G_nk + phi_n(0) phi_k'(0)], B_nB = -eps K phi_n(0),
    B_Bk = eps (M L^2 / I_cm) [phi_k(0) + (d2 / L) phi_k'(0)], B_BB = (omega_psi / omega_1)^2.

    Parameters
    ----------
    omega_1 : float
        First free-free bending frequency (rad/s), > 0 (4.2-8b).
    mass, L, d2, I_cm : float
        Mass (kg), half-length (m), lever arm CM to aft edge (m, erratum E2) and pitch inertia
        about the CM (kg m^2, erratum E1), > 0.
    F0, K : float
        Steady thrust (N) and gimbal gain, >= 0.
    N : int
        Elastic free-free modes, 0..500 (0: pure rigid pitch).
    n_quad : int, optional
        Gauss-Legendre points of the modal integrals (default max(64, 8 N + 32)).
    """
    omega_1 = positive("omega_1", omega_1)
    mass = positive("mass", mass)
    L = positive("L", L)
    d2 = positive("d2", d2)
    I_cm = positive("I_cm", I_cm)
    F0 = nonnegative("F0", F0)
    K = nonnegative("K", K)
    N = count("N", N, 0)
    n_quad = None if n_quad is None else count("n_quad", n_quad, 1, 100_000)
    load = F0 / (mass * L * omega_1**2)  # eps = F0 / (M L omega_1^2)
    Lam, B = _assemble(load, K, mass * L**2 / I_cm, d2 / L, N, n_quad)
    return BeamActionSystem(Lambda=Lam, B=B, omega_1=omega_1, load=load, K=K, N=N)


def beam_system(model: BoosterModel, N: int | None = None) -> BeamActionSystem:
    """:func:`beam_action_system` of a booster's derived model.

    Parameters
    ----------
    model : BoosterModel
        The derived model (omega_1, mass properties, F0, K).
    N : int, optional
        Elastic modes (default the model's truncation N).
    """
    m = model.mass
    return beam_action_system(model.omega_1, m.mass, m.L, m.d2, m.I_cm, model.F0, model.K,
                              model.truncation.N if N is None else N)


def uniform_beam_system(p: float, K: float, N: int, omega_1: float = 1.0) -> BeamActionSystem:
    """A uniform free-free beam under the steady thrust p = P l^2 / EI (Beal 1965, eq. 4).

    :func:`beam_action_system` with d2 = L, I_cm = M L^2 / 3, eps = 2 p / lambda_1^4.

    Parameters
    ----------
    p, K : float
        Steady thrust P l^2 / EI and gimbal gain, >= 0.
    N : int
        Elastic modes, >= 0.
    omega_1 : float
        First bending frequency (rad/s) normalising time.
    """
    p = nonnegative("p", p)
    K = nonnegative("K", K)
    N = count("N", N, 0)
    omega_1 = positive("omega_1", omega_1)
    load = 2.0 * p / beam.free_free_eigenvalues(1)[0] ** 4  # P/(M L omega_1^2) = 2 p / lambda_1^4
    Lam, B = _assemble(load, K, 3.0, 1.0, N)
    return BeamActionSystem(Lambda=Lam, B=B, omega_1=omega_1, load=load, K=K, N=N)


def follower_flutter_load(n_modes: int = 12, p_max: float = 1000.0,
                          rtol: float = 1e-12) -> float:
    """Flutter load P l^2 / EI of the free-free beam under a steady follower end force.

    The smallest p at which two squared frequencies of the steady system (K = 0) coalesce;
    109.69 in the limit, approached from above (Beal 1965, fig. 2).

    Parameters
    ----------
    n_modes : int
        Elastic modes of the Galerkin model, 2..200.
    p_max : float
        Upper end of the search, > 0 (ValueError if no flutter below it).
    rtol : float
        Relative tolerance of the bisection, > 0.
    """
    n_modes = count("n_modes", n_modes, 2, 200)
    p_max = positive("p_max", p_max)
    rtol = positive("rtol", rtol)
    G, phi0, dphi0, lam = _modal_integrals(n_modes)
    Lam = np.diag((lam / lam[0]) ** 4)
    Be = -(G + np.outer(phi0, dphi0)) * 2.0 / lam[0] ** 4  # elastic block per unit p, K = 0

    def unstable(p: np.ndarray) -> np.ndarray:
        mu = np.linalg.eigvals(Lam[None] + p[:, None, None] * Be[None])  # squared frequencies
        scale = np.max(np.abs(mu), axis=-1)
        return np.any((np.abs(mu.imag) > 1e-7 * scale[:, None]) | (mu.real <= 0.0), axis=-1)

    grid = np.linspace(0.0, p_max, 401)
    flags = unstable(grid)
    if not flags.any():
        raise ValueError(f"p_max = {p_max}: no flutter below it with n_modes = {n_modes}")
    i = int(np.argmax(flags))
    lo, hi = grid[i - 1], grid[i]
    while hi - lo > rtol * hi:  # bisection on the onset of complex squared frequencies
        mid = 0.5 * (lo + hi)
        if unstable(np.array([mid]))[0]:
            hi = mid
        else:
            lo = mid
    return float(0.5 * (lo + hi))


def loaded_frequencies(system: BeamActionSystem) -> np.ndarray:
    """omega_r / omega_1 under the steady thrust: sqrt of the eigenvalues of Lambda + B (complex:
    flutter), shape (N + 1,), sorted by real part (memo 4.1-11).

    Parameters
    ----------
    system : BeamActionSystem
        The normalised system.
    """
    w = np.sqrt(np.linalg.eigvals(system.A0).astype(complex))
    return w[np.argsort(w.real, kind="stable")]


# --------------------------------------------------------------------------------------------
# Exponents: canonical forms
# --------------------------------------------------------------------------------------------
def _fold(alpha: np.ndarray) -> np.ndarray:
    """Representative of {+-alpha + k, conj}: 0 <= Re <= 1/2, Im >= 0."""
    re = alpha.real - np.round(alpha.real)
    return np.abs(re) + 1j * np.abs(alpha.imag)


def reduced_exponents(alpha: np.ndarray) -> np.ndarray:
    """The n canonical representatives of 2n exponents, shape (..., n), sorted by real part.

    Each exponent folded to 0 <= Re <= 1/2, Im >= 0 (the set is invariant under -alpha,
    alpha + 1, conj), then the means of the n pairs (Magnus & Winkler 1966, ch. 1).

    Parameters
    ----------
    alpha : numpy.ndarray
        Shape (..., 2n), finite exponents (4.1-10/11).
    """
    alpha = np.asarray(alpha)
    if alpha.ndim == 0 or alpha.shape[-1] == 0 or alpha.shape[-1] % 2:
        raise ValueError(f"alpha: shape {alpha.shape}: the last axis must hold 2n >= 2 exponents")
    if not np.all(np.isfinite(alpha)):
        raise ValueError("alpha: every exponent must be finite")
    f = _fold(alpha)
    key = f.real + 1e-3 * f.imag
    f = np.take_along_axis(f, np.argsort(key, axis=-1), axis=-1)
    return 0.5 * (f[..., 0::2] + f[..., 1::2])


def natural_branch(reduced: np.ndarray, Omega_bar: np.ndarray,
                   frequencies: np.ndarray) -> np.ndarray:
    """alpha_r on the branch continuous from gamma = 0 (alpha_r Omega_bar -> omega_r / omega_1).

    Representatives are assigned to modes greedily by the distance of fold(omega_r / Omega_bar)
    to Re alpha_j; mode r gets the member of its orbit nearest omega_r / Omega_bar, Im >= 0.
    Returns shape (G, n).

    Parameters
    ----------
    reduced : numpy.ndarray
        Shape (G, n), from :func:`reduced_exponents`.
    Omega_bar : numpy.ndarray
        Shape (G,), Omega / omega_1, > 0.
    frequencies : numpy.ndarray
        Shape (n,), omega_r / omega_1 (:func:`loaded_frequencies`).
    """
    reduced = np.asarray(reduced)
    Omega_bar = np.asarray(Omega_bar, dtype=float)
    if Omega_bar.ndim != 1 or not np.all(np.isfinite(Omega_bar)) or np.any(Omega_bar <= 0):
        raise ValueError("Omega_bar: must be 1-D, finite and > 0 (dimensionless)")
    if reduced.shape != (Omega_bar.size, np.size(frequencies)) or not np.all(
            np.isfinite(reduced)):
        raise ValueError(f"reduced: shape {reduced.shape}: must be finite, (len(Omega_bar), "
                         "len(frequencies))")
    x = np.real(frequencies)[None, :] / Omega_bar[:, None]  # (G, n)
    k0 = np.round(x)
    y = x - k0
    cost = np.abs(np.abs(y)[:, :, None] - reduced.real[:, None, :])  # (G, r, j)
    G, n = x.shape
    assigned = np.zeros((G, n), dtype=int)
    free = np.ones((G, n, n), dtype=bool)
    rows = np.arange(G)
    for _ in range(n):  # greedy assignment, n steps vectorised over the grid
        c = np.where(free, cost, np.inf).reshape(G, -1)
        best = np.argmin(c, axis=1)
        r, j = np.divmod(best, n)
        assigned[rows, r] = j
        free[rows, r, :] = False
        free[rows, :, j] = False
    rep = np.take_along_axis(reduced, assigned, axis=1)
    sign = np.where(y < 0.0, -1.0, 1.0)
    return k0 + sign * rep.real + 1j * rep.imag


# --------------------------------------------------------------------------------------------
# Hill's determinant
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class HillResult:
    """Hill's exponents of the beam action with their Fourier vectors (4.1-10..12).

    Attributes
    ----------
    alpha, centroid : numpy.ndarray
        Shape (G, 2n): the exponents whose vectors are most central, sum_s s |C^(s)|^2.
    C : numpy.ndarray
        Shape (G, 2n, 2S + 1, n), unit Fourier vectors C^(s) of (4.1-12), rows q_1..q_N, q_B.
    """

    alpha: np.ndarray
    C: np.ndarray
    centroid: np.ndarray

    def to_dict(self) -> dict:
        """JSON-ready mapping (real and imaginary parts as plain lists)."""
        return {
            "alpha_real": self.alpha.real.tolist(),
            "alpha_imag": self.alpha.imag.tolist(),
            "C_real": self.C.real.tolist(),
            "C_imag": self.C.imag.tolist(),
            "centroid": self.centroid.tolist(),
        }


def _grid(Omega: np.ndarray, gamma: np.ndarray, omega_1: float) -> tuple[np.ndarray, ...]:
    Omega = np.asarray(Omega, dtype=float)
    gamma = np.asarray(gamma, dtype=float)
    if Omega.size == 0 or not np.all(np.isfinite(Omega)) or np.any(Omega <= 0.0):
        raise ValueError(f"Omega = {Omega!r}: must be non-empty, finite and > 0 (rad/s)")
    if not np.all(np.isfinite(gamma)) or np.any(gamma < 0.0) or np.any(gamma >= 1.0):
        raise ValueError(f"gamma = {gamma!r}: must satisfy 0 <= gamma < 1")
    try:
        Omega, gamma = np.broadcast_arrays(Omega, gamma)
    except ValueError:
        raise ValueError(f"Omega, gamma: shapes {Omega.shape} and {gamma.shape} must broadcast "
                         "together") from None
    return Omega.ravel() / omega_1, gamma.ravel(), Omega.shape


def hill_exponents(system: BeamActionSystem, Omega: np.ndarray, gamma: np.ndarray,
                   S: int, chunk: int = 8) -> HillResult:
    """The 2n exponents with the most central Fourier vectors, by Hill's determinant.

    (alpha + s)^2 Omega_bar^2 C^(s) = A0 C^(s) - (gamma / 2) B (C^(s-1) + C^(s+1)), s = -S..S
    (memo 4.1-10..12; :func:`flexbooster.floquet.hill_modes`).

    Parameters
    ----------
    system : BeamActionSystem
        The normalised system.
    Omega, gamma : array_like
        Thrust frequencies (rad/s, > 0) and amplitudes (0 <= gamma < 1), broadcast together.
    S : int
        Harmonics, 0..500.
    chunk : int
        Grid points per batched eigen-solve (memory).
    """
    S = count("S", S, 0)
    chunk = count("chunk", chunk, 1, 10**6)
    Ob, gam, _ = _grid(Omega, gamma, system.omega_1)
    modes = hill_modes(_unit_system(system), None, None, None, Ob, n_harmonics=S, chunk=chunk,
                       amplitude=gam, real_form=True)
    return HillResult(alpha=(-1j * modes.exponents) / Ob[:, None], C=modes.vectors,
                      centroid=modes.centroid)  # alpha = mu / Omega_bar, lambda = i mu


def _unit_system(system: BeamActionSystem) -> LinearPeriodicSystem:
    """q'' + (A0 - cos(Omega_bar tau) B) q = 0, the toolkit's system of unit amplitude."""
    return periodic_system(np.eye(system.N + 1), None, system.A0, -system.B)


# --------------------------------------------------------------------------------------------
# Monodromy matrix
# --------------------------------------------------------------------------------------------
def monodromy_steps(system: BeamActionSystem, Omega: np.ndarray, gamma: np.ndarray,
                    step_phase: float = 0.06, *, max_steps: int | None = None) -> np.ndarray:
    """Steps per half period of :func:`monodromy_exponents`: the coupling-weighted rule of
    :func:`flexbooster.floquet.step_counts` (error ~ step_phase^4), rounded up to 2^(k/4).

    Parameters
    ----------
    system, Omega, gamma
        As :func:`hill_exponents`.
    step_phase : float
        Accuracy of the rule, > 0.
    max_steps : int, optional
        Cap of the counts (default none).
    """
    Ob, gam, _ = _grid(Omega, gamma, system.omega_1)
    return step_counts(_unit_system(system), Ob, step_phase=positive("step_phase", step_phase),
                       amplitude=gam, levels_per_octave=4, clip=True,
                       max_steps=np.iinfo(np.int64).max if max_steps is None else max_steps)


def monodromy_exponents(system: BeamActionSystem, Omega: np.ndarray, gamma: np.ndarray,
                        n_steps: int | None = None, step_phase: float = 0.06,
                        chunk: int = 256, *,
                        max_steps: int = MONODROMY_MAX_STEPS) -> np.ndarray:
    """Floquet exponents alpha = log(rho) / (2 pi i) from the monodromy, shape (G, 2n),
    Re alpha in (-1/2, 1/2] (memo 4.1-10/11).

    Parameters
    ----------
    system, Omega, gamma
        As :func:`hill_exponents`.
    n_steps : int, optional
        Steps per half period of every point (default :func:`monodromy_steps`).
    step_phase : float
        Accuracy of the step rule, > 0; 0.06 gives about 1e-9 on alpha.
    chunk : int
        Grid points per batch (memory).
    max_steps : int
        Cap on the automatic step count, 8..10^7 (:data:`MONODROMY_MAX_STEPS`: alpha to about
        3e-6 at Omega_bar = 4.4e-4, docs/theory/robustness.md).

    Raises
    ------
    flexbooster.floquet.PeriodMapOverflowError
        Where the period map overflows, naming Omega (rad/s) and gamma.
    """
    Ob, gam, _ = _grid(Omega, gamma, system.omega_1)
    chunk = count("chunk", chunk, 1, 10**6)
    max_steps = count("max_steps", max_steps, 8, 10**7)
    steps = (monodromy_steps(system, Omega, gamma, step_phase, max_steps=max_steps)
             if n_steps is None else count("n_steps", n_steps, 1, 10**7))
    try:
        rho = floquet_multipliers(_unit_system(system), None, None, None, Ob, n_steps=steps,
                                  max_steps=10**7, chunk=chunk, amplitude=gam)
    except PeriodMapOverflowError as exc:
        i = int(np.argmin(np.abs(Ob - exc.Omega)))
        raise PeriodMapOverflowError(
            f"Omega = {float(Ob[i] * system.omega_1):.6g} rad/s, gamma = {float(gam[i]):.6g}: "
            "the period map overflowed or is singular to working precision (a growth over one "
            "thrust period beyond ~1e15)", exc.Omega) from None
    return np.log(rho) / (2j * np.pi)


# --------------------------------------------------------------------------------------------
# Instability bands in Omega from their boundaries (Floquet toolkit)
# --------------------------------------------------------------------------------------------
#: Boundary tolerance of the band search, relative to each region's centre (dimensionless).
BAND_RTOL = 1e-9
#: Largest resonance order j (Omega = 2 omega_i / j, (omega_i +- omega_k) / j) searched; None:
#: every order whose estimated width is above the tolerance (the toolkit's default).
BAND_MAX_ORDER = None
#: Cap on the resonance centres enumerated (a small omega_min / omega_1 makes many).
BAND_MAX_CANDIDATES = 1_000_000
#: Lower end of the band search (units of omega_1): below it an elastic resonance has order
#: j >= 8 (simple) or 4 (combinations), narrower than round-off, while the monodromy costs
#: ~omega_max / Omega steps; the pitch tongues there come from :func:`pitch_tongue_bands`.
BAND_OMEGA_BAR_MIN = 0.25


def band_modes(modes) -> tuple[BandMode, ...]:
    """The steady modes of a band by index (ascending frequency) as
    :class:`flexbooster.bands.BandMode`: "rigid pitch" (index 0) and "bending m".

    Parameters
    ----------
    modes : iterable of int
        Indices of the steady modes.
    """
    return tuple(BandMode(label="rigid pitch" if int(m) == 0 else f"bending {int(m)}",
                          index=int(m)) for m in modes)


def _pitch_column(V: np.ndarray) -> int:
    """Column of the steady eigenvectors V with the largest relative q_B (rigid rotation,
    last in q) component: the rigid-pitch mode."""
    return int(np.argmax(np.abs(V[-1, :]) / np.linalg.norm(V, axis=0)))


def modal_damping(system: BeamActionSystem, *, beam_ratio: float = 0.0,
                  pitch_ratio: float = 0.0) -> np.ndarray | None:
    """Damping matrix C = V diag(2 zeta_k omega_k) V^-1 (A0 = V diag(omega_k^2) V^-1), or None
    when both ratios are 0: each steady mode decays like exp(-zeta_k omega_k tau) (Bolotin
    1964, sec. 6).

    Parameters
    ----------
    system : BeamActionSystem
        The normalised system.
    beam_ratio, pitch_ratio : float
        Damping ratios of the elastic modes and of the rigid-pitch mode (largest relative q_B
        component), 0 <= zeta < 1.
    """
    zb = nonnegative("beam_ratio", beam_ratio)
    zp = nonnegative("pitch_ratio", pitch_ratio)
    for name, z in (("beam_ratio", zb), ("pitch_ratio", zp)):
        if z >= 1.0:
            raise ValueError(f"{name} = {z!r}: must satisfy 0 <= zeta < 1")
    if zb == 0.0 and zp == 0.0:
        return None
    mu, V = np.linalg.eig(system.A0)
    V = V.astype(complex)
    zeta = np.full(mu.size, zb)
    zeta[_pitch_column(V)] = zp
    w = np.sqrt(mu.astype(complex))
    C = (V * (2.0 * zeta * w)[None, :]) @ np.linalg.inv(V)  # C = V diag(2 zeta w) V^-1
    return np.ascontiguousarray(C.real)


def beam_action_bands(system: BeamActionSystem, gamma: float, *, omega_min: float,
                      omega_max: float, beam_ratio: float = 0.0, pitch_ratio: float = 0.0,
                      rtol: float = BAND_RTOL, max_order: int | None = BAND_MAX_ORDER,
                      step_phase: float = 0.12) -> tuple[Band, ...]:
    """Every instability band of the beam action in [omega_min, omega_max] (rad/s), by Omega_lo.

    :func:`flexbooster.floquet.instability_regions` of q'' + C q' + [A0 - gamma cos(Omega_bar
    tau) B] q = 0 in units of omega_1, converted to rad/s and 1/s; with damping each band
    carries its critical gamma.

    Parameters
    ----------
    system : BeamActionSystem
        The normalised system.
    gamma : float
        Pulsation amplitude, 0 <= gamma < 1.
    omega_min, omega_max : float
        Omega range (rad/s), 0 < omega_min < omega_max.
    beam_ratio, pitch_ratio : float
        Modal damping ratios (:func:`modal_damping`).
    rtol : float
        Edge tolerance relative to each band's centre.
    max_order : int or None
        Largest resonance order j (None: the toolkit's width estimate).
    step_phase : float
        Monodromy accuracy.
    """
    gamma = nonnegative("gamma", gamma)
    if gamma >= 1.0:
        raise ValueError(f"gamma = {gamma!r}: must satisfy 0 <= gamma < 1")
    lo = positive("omega_min", omega_min)
    hi = positive("omega_max", omega_max)
    if not lo < hi:
        raise ValueError(f"omega_min = {lo!r}: must be < omega_max = {hi!r}")
    n = system.Lambda.size
    w1 = float(system.omega_1)
    C = modal_damping(system, beam_ratio=beam_ratio, pitch_ratio=pitch_ratio)
    opts = {"rtol": rtol, "max_order": max_order, "max_candidates": BAND_MAX_CANDIDATES,
            "step_phase": step_phase}
    regions = instability_regions(np.eye(n), C, system.A0, -gamma * system.B, lo / w1,
                                  hi / w1, **opts)
    crit: dict = {}
    if C is not None and gamma > 0.0 and any(r.kind != "steady" for r in regions):
        for c in critical_amplitude(np.eye(n), C, system.A0, -system.B, gamma_max=gamma,
                                    omega_min=lo / w1, omega_max=hi / w1,
                                    regions=regions, **opts):  # the search above, reused
            crit[(c.kind, c.modes, c.order)] = c.gamma_cr
    out = []
    for r in regions:
        out.append(Band(
            mechanism="beam_action", Omega_lo=r.omega_lo * w1,  # Omega_bar -> rad/s
            Omega_hi=r.omega_hi * w1, growth_rate_max=r.growth_rate_max * w1,  # 1/tau -> 1/s
            Omega_at_max=r.omega_at_max * w1, kind=r.kind, modes=band_modes(r.modes),
            order=int(r.order), Omega_center=r.omega_center * w1, clipped=bool(r.clipped),
            critical_gamma=float(crit.get((r.kind, tuple(r.modes), r.order), 0.0))))
    return tuple(out)


def band_critical_damping(system: BeamActionSystem, bands, *, gamma: float,
                          beam_ratio: float = 0.0, pitch_ratio: float = 0.0,
                          growth_floor: float = NEGLIGIBLE_GROWTH,
                          limit: int = CRITICAL_DAMPING_COUNT) -> tuple[Band, ...]:
    """The bands with the critical damping ratio of the elastic modes (the smallest
    ``beam_ratio`` closing the band at gamma, the rigid pitch keeping ``pitch_ratio``; Bolotin
    1964, sec. 6) on the ``limit`` fastest-growing ones that grow faster than ``growth_floor``,
    are not clipped and hold an elastic mode (only elastic modes when the pitch is undamped:
    no elastic damping closes a combination with an undamped mode); None on the others and
    where a ratio of 1 does not close the band.

    Parameters
    ----------
    system : BeamActionSystem
        The normalised system.
    bands : sequence of Band
        Its bands at gamma (:func:`beam_action_bands`, rad/s).
    gamma : float
        Pulsation amplitude, 0 < gamma < 1.
    beam_ratio, pitch_ratio : float
        The damping ratios at which the bands were found (:func:`modal_damping`).
    growth_floor : float
        Bands growing slower than this (1/s) are left out, >= 0.
    limit : int
        At most this many bands, >= 0.
    """
    floor = nonnegative("growth_floor", growth_floor)
    limit = count("limit", limit, 0, 10_000)
    bands = tuple(bands)
    w1 = float(system.omega_1)
    # a band of the pitch alone is the pitch's; with an undamped pitch no elastic damping
    # closes a combination holding it (threshold lambda^2 > delta_i delta_k = 0, Hsu 1963):
    # its growth only falls towards round-off
    elastic = (lambda b: all(m.index != 0 for m in b.modes)) if pitch_ratio == 0.0 else (
        lambda b: any(m.index != 0 for m in b.modes))
    chosen = sorted((i for i, b in enumerate(bands)
                     if b.kind != "steady" and not b.clipped and b.growth_rate_max > floor
                     and elastic(b)),
                    key=lambda i: -bands[i].growth_rate_max)[:limit]
    if not chosen:
        return bands
    half = 0.5  # C is linear in the elastic ratio: C1 = (C(1/2) - C(0)) / (1/2)
    C0 = modal_damping(system, beam_ratio=0.0, pitch_ratio=pitch_ratio)
    C1 = (modal_damping(system, beam_ratio=half, pitch_ratio=pitch_ratio)
          - (0.0 if C0 is None else C0)) / half
    n = system.Lambda.size
    out = list(bands)
    for i in chosen:
        b = bands[i]
        zeta_cr = critical_damping(np.eye(n), C1, system.A0, -gamma * system.B,
                                   omega_lo=b.Omega_lo / w1, omega_hi=b.Omega_hi / w1,
                                   zeta=beam_ratio, C0=C0, omega_start=b.Omega_at_max / w1)
        out[i] = replace(b, critical_damping_ratio=zeta_cr)
    return tuple(out)


# --------------------------------------------------------------------------------------------
# Pipeline result and chart
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class BeamActionResult:
    """Beam-action exponents along the Omega grid and the bands (memo 4.1-10/11).

    Attributes
    ----------
    Omega, Omega_bar : numpy.ndarray
        Shape (G,), the grid (rad/s) and Omega / omega_1.
    alpha : numpy.ndarray
        Shape (G, R), alpha_r on the natural branch (Im >= 0).
    frequencies : numpy.ndarray
        Shape (R,), steady omega_r / omega_1 (complex in general).
    stable, growth_rate : numpy.ndarray
        Shape (G,): every |Im alpha| <= 1e-6, and max |Im alpha| Omega (1/s), undamped.
    max_growth_rate, Omega_at_max : float
        The largest of the bands' and the grid's maxima (1/s) and where (rad/s); 0 when stable.
    hill_monodromy_difference : float
        Largest difference of Hill's and the monodromy's representatives at the check points.
    verdict : str
        "unstable" with a band, else "stable", or "not fully searched: ..." with a gap.
    gamma, K, N, S, R, p : float, float, int, int, int, float
        Inputs; p = P l^2 / EI.
    bands, gaps : tuple
        The bands (:func:`pipeline_bands`) and what a limit left out.
    beam_damping_ratio, pitch_damping_ratio : float
        Damping ratios of the band search.
    band_range : (float, float)
        Omega range of the band search (rad/s); below it the pitch tongues.
    """

    Omega: np.ndarray
    Omega_bar: np.ndarray
    alpha: np.ndarray
    frequencies: np.ndarray
    stable: np.ndarray
    growth_rate: np.ndarray
    max_growth_rate: float
    Omega_at_max: float
    hill_monodromy_difference: float
    verdict: str
    gamma: float
    K: float
    N: int
    S: int
    R: int
    p: float
    bands: tuple = ()
    beam_damping_ratio: float = 0.0
    pitch_damping_ratio: float = 0.0
    band_range: tuple = (0.0, 0.0)
    gaps: tuple = ()

    def unstable_intervals(self) -> list[tuple[float, float]]:
        """The bands as (Omega_lo, Omega_hi) (rad/s)."""
        return [(float(b.Omega_lo), float(b.Omega_hi)) for b in self.bands]

    def to_dict(self) -> dict:
        """JSON-ready mapping (plain lists and floats, no NaN)."""
        return {
            "Omega": self.Omega.tolist(),
            "Omega_bar": self.Omega_bar.tolist(),
            "alpha_real": self.alpha.real.tolist(),
            "alpha_imag": self.alpha.imag.tolist(),
            "frequencies_real": self.frequencies.real.tolist(),
            "frequencies_imag": self.frequencies.imag.tolist(),
            "stable": self.stable.tolist(),
            "growth_rate": self.growth_rate.tolist(),
            "max_growth_rate": float(self.max_growth_rate),
            "Omega_at_max": float(self.Omega_at_max),
            "hill_monodromy_difference": float(self.hill_monodromy_difference),
            "verdict": self.verdict,
            "gamma": float(self.gamma),
            "K": float(self.K),
            "N": int(self.N),
            "S": int(self.S),
            "R": int(self.R),
            "p": float(self.p),
            "unstable_intervals": [list(iv) for iv in self.unstable_intervals()],
            "bands": [b.to_dict() for b in self.bands],
            "beam_damping_ratio": float(self.beam_damping_ratio),
            "pitch_damping_ratio": float(self.pitch_damping_ratio),
            "band_range": [float(v) for v in self.band_range],
            "gaps": [g.to_dict() for g in self.gaps],
        }


#: Harmonics of the harmonic balance of the low-frequency pitch tongues: K = 4, 8, .. up to
#: this, until two successive K give the same edges to :data:`BAND_RTOL`.
TONGUE_MAX_HARMONICS = 24
#: Far below the beam modes the pitch roots of the harmonic balance wander by
#: ~eps (omega_beam / Omega)^2 relative (1e-8 at Omega_bar ~ 1e-3, 1e-6 at 1e-5): the edges
#: of the two successive K that agree best are used when they agree to this (relative).
TONGUE_RTOL_FLOOR = 1e-4
#: Below this Omega_bar the harmonic balance meets that round-off floor.
TONGUE_FLOOR_OMEGA_BAR = 3e-3
#: The pitch roots' round-off wander, relative: eps (omega_top / Omega)^2 with omega_top the
#: truncation's highest steady frequency (measured: 5e-9 against 6.9e-9 at Omega_bar = 8.7e-3,
#: omega_top = 48.6, N = 10; 1e-10..1.6e-9 against 1.2e-9 for the memo case). Two successive
#: K agree to the larger of rtol and this factor times it: closer agreement is chance.
TONGUE_ROUNDOFF_FACTOR = 10.0
#: Relative tolerance of the critical gamma of a damped pitch tongue (bisection).
TONGUE_GAMMA_RTOL = 1e-6
#: Hill harmonics of the growth rate inside the pitch tongues r <= 4
#: (:func:`tongue_hill_harmonics`).
TONGUE_HILL_HARMONICS = 4
#: Highest rigid-pitch tongue order r searched below omega_1 / 4.
TONGUE_MAX_ORDER = 63


class TongueEdgesError(ValueError):
    """The edges of a pitch tongue did not converge within :data:`TONGUE_MAX_HARMONICS`."""


def tongue_hill_harmonics(r: int) -> int:
    """Hill harmonics S of the growth rate inside pitch tongue r: max(4, 2 r - 4).

    Against the rigid-pitch Mathieu tongues, r = 1..4 converge at S = 4, r = 5..9 first at
    S = 6, 6, 10, 8, 12; the value at the maximum is taken at S + 4.

    Parameters
    ----------
    r : int
        Tongue order, >= 1.
    """
    return max(TONGUE_HILL_HARMONICS, 2 * r - 4)


def pitch_mode(system: BeamActionSystem) -> int:
    """Index (ascending frequency) of the steady mode with the largest rigid-rotation share.

    Parameters
    ----------
    system : BeamActionSystem
        The normalised system.
    """
    mu, V = np.linalg.eig(system.A0)
    w = np.sqrt(mu.astype(complex))
    return int(np.flatnonzero(np.argsort(w.real, kind="stable") == _pitch_column(V))[0])


def pitch_guide(system: BeamActionSystem, C: np.ndarray | None) -> tuple[float, float, float]:
    """(mu_p, b_p, c_p) of the pitch mode alone in the steady modal frame (units of omega_1):
    eta'' + c_p eta' + (mu_p - b_p f(tau)) eta = 0, a damped Mathieu equation.

    Parameters
    ----------
    system : BeamActionSystem
        The normalised system.
    C : numpy.ndarray or None
        The damping matrix (:func:`modal_damping`).
    """
    mu, V = np.linalg.eig(system.A0)
    ip = _pitch_column(V)
    Vi = np.linalg.inv(V)
    return (float(mu[ip].real), float((Vi @ system.B @ V)[ip, ip].real),
            0.0 if C is None else float((Vi @ C @ V)[ip, ip].real))


def _nearest_pair(r: np.ndarray, ref: tuple[float, float]) -> tuple[float, float] | None:
    """The roots of ``r`` nearest to each edge of ``ref`` (None unless two distinct ones)."""
    if r.size < 2:
        return None
    i, k = int(np.argmin(np.abs(r - ref[0]))), int(np.argmin(np.abs(r - ref[1])))
    return (float(r[i]), float(r[k])) if i < k else None


def _pitch_only_edges(mu_p: float, b_p: float, c_p: float, *, period: str, centre: float,
                      window: tuple[float, float]) -> tuple[float, float] | None:
    """Edges of tongue r of the pitch mode alone (a damped Mathieu equation): the two boundary
    roots in the window nearest the centre 2 omega_p / r, converged in the harmonics.  For
    r >= 3 the tongue lies below its tip (A&S 20.2.25): the guide of the coupled search.
    """
    A, B = np.array([[mu_p]]), np.array([[-b_p]])
    C = None if c_p == 0.0 else np.array([[c_p]])
    prev = None
    for K in range(4, TONGUE_MAX_HARMONICS + 1, 4):
        r = periodic_boundaries(np.eye(1), C, A, B, period=period, n_harmonics=K,
                                omega_max=window[1])
        r = r[r >= window[0]]
        cur = (None if r.size < 2 else
               tuple(float(x) for x in np.sort(r[np.argsort(np.abs(r - centre))[:2]])))
        if cur is not None and prev is not None and max(
                abs(cur[0] - prev[0]), abs(cur[1] - prev[1])) <= BAND_RTOL * centre:
            return cur
        if cur is None and prev is None and K >= 8:
            return None
        prev = cur
    return prev


def _tongue_edges(A, C, B, *, period: str, centre: float, window: tuple[float, float],
                  rtol: float, harmonics=None, guess: tuple[float, float] | None = None
                  ) -> tuple[tuple[float, float] | None, int]:
    """Edges of the tongue about ``centre`` from the T / 2T-periodic boundaries (Bolotin 1964,
    sec. 4-5), harmonics K = 4, 8, .. raised until two successive K agree to rtol * centre
    (above :data:`TONGUE_FLOOR_OMEGA_BAR`, to the roots' round-off wander where that is larger:
    :data:`TONGUE_ROUNDOFF_FACTOR`; below it, to :data:`TONGUE_RTOL_FLOOR` where round-off
    stops that).

    Root pairs closer than rtol * centre are dropped; the edges are the nearest remaining roots
    about the centre (or ``guess``), tracked from K to K. ``harmonics`` = (K,): that truncation
    as it is. Returns the edges (None: no tongue) and the smaller K of the two that agree;
    :class:`TongueEdgesError` when they do not converge with :data:`TONGUE_MAX_HARMONICS`.
    """
    n = A.shape[0]
    # two K agree, and a root is real, to rtol or, above the floor's Omega_bar, to the roots'
    # round-off wander where that is larger (below it the floor's closest agreement decides)
    agree = rtol
    if centre >= TONGUE_FLOOR_OMEGA_BAR:
        top = float(np.max(np.abs(np.linalg.eigvals(A))))
        agree = max(rtol, TONGUE_ROUNDOFF_FACTOR * np.finfo(float).eps * top / centre**2)
    prev = None
    best = (np.inf, None, 0)  # the closest agreement of two successive K (round-off floor)
    Ks = tuple(range(4, TONGUE_MAX_HARMONICS + 1, 4)) if harmonics is None else harmonics
    for K in Ks:
        r = periodic_boundaries(np.eye(n), C, A, B, period=period, n_harmonics=K,
                                omega_max=window[1], imag_rtol=max(agree, REAL_ROOT_RTOL))
        r = r[r >= window[0]]
        close = np.diff(r) <= rtol * centre
        drop = np.zeros(r.size, dtype=bool)
        drop[:-1] |= close
        drop[1:] |= close
        r = r[~drop]
        below, above = r[r <= centre], r[r > centre]
        if prev is not None:  # track the edges of the previous K
            cur = _nearest_pair(r, prev)
        elif guess is not None:  # from the pitch-only tongue
            cur = _nearest_pair(r, guess)
        elif below.size == 0 or above.size == 0:
            cur = None
        else:
            cur = (float(below[-1]), float(above[0]))
        if len(Ks) == 1:
            return cur, K
        if cur is not None and prev is not None and max(abs(cur[0] - prev[0]),
                                                        abs(cur[1] - prev[1])) <= agree * centre:
            return (cur if cur[1] - cur[0] > rtol * centre else None), K - 4
        if cur is None and prev is None and K >= 8:
            return None, K  # no tongue at two successive K: below round-off or damped out
        if cur is not None and prev is not None:
            diff = max(abs(cur[0] - prev[0]), abs(cur[1] - prev[1]))
            if diff < best[0]:
                best = (diff, cur, K - 4)
            elif best[0] <= TONGUE_RTOL_FLOOR * centre and centre < TONGUE_FLOOR_OMEGA_BAR:
                break  # worse after reaching the floor, far below the beam: round-off now
                # grows with K, and a later close agreement would be by chance (keep the best)
        prev = cur
    if best[0] <= TONGUE_RTOL_FLOOR * centre:  # converged to round-off, not to rtol
        cur = best[1]  # a tongue when it is wider than twice the wander of its edges
        return (cur if cur[1] - cur[0] > 2.0 * max(best[0], rtol * centre) else None), best[2]
    raise TongueEdgesError(f"pitch tongue near Omega_bar = {centre!r}: its edges did not "
                           f"converge with {TONGUE_MAX_HARMONICS} harmonics")


def _hill_growth(A, C, B, om: np.ndarray, S: int) -> np.ndarray:
    ev = floquet_hill_exponents(np.eye(A.shape[0]), C, A, B, om, n_harmonics=S)
    return np.max(ev.real, axis=1)


def _growth_max(A, C, B, lo: float, hi: float, S: int = TONGUE_HILL_HARMONICS
                ) -> tuple[float, float]:
    """Largest growth rate in [lo, hi] (per unit tau) and where: Hill with S harmonics and
    golden section (to 1e-5 of the band: the maximum is flat), the value there with S + 4.
    """
    x = np.linspace(lo, hi, 9)[1:-1]
    g = _hill_growth(A, C, B, x, S)
    i = int(np.argmax(g))
    a, b = (x[i - 1] if i > 0 else lo), (x[i + 1] if i < x.size - 1 else hi)
    # golden section (Press et al. 2007, sec. 10.2) to 1e-5 of the band: the maximum is flat,
    # the growth then exact to ~1e-10
    (x0,), _ = golden_section_max(lambda om, idx: _hill_growth(A, C, B, om, S), [a], [b],
                                  xtol=1e-5 * (hi - lo), max_iter=60)
    g0 = _hill_growth(A, C, B, np.array([x0]), S + 4)[0]  # the converged value at the maximum
    return float(max(g0, 0.0)), float(x0)


def pitch_tongue_bands(system: BeamActionSystem, gamma: float, *, omega_min: float,
                       omega_max: float, beam_ratio: float = 0.0, pitch_ratio: float = 0.0,
                       rtol: float = BAND_RTOL) -> tuple[Band, ...]:
    """The rigid-pitch tongues of the coupled beam action in a low Omega range, by Omega_lo.

    Below omega_1 / 4 the only bands wider than round-off are the pitch tongues near
    2 omega_p / r: edges by harmonic balance (T- or 2T-periodic, harmonics raised until they
    converge), growth rate Hill's maximised by golden section, with damping the critical gamma
    by bisection (Bolotin 1964, ch. 1-2). Bands of kind "simple", modes (p,), order r.

    Parameters
    ----------
    system, gamma, beam_ratio, pitch_ratio
        As :func:`beam_action_bands`.
    omega_min, omega_max : float
        The low range (rad/s): tongues whose tip lies in it, clipped to it.
    rtol : float
        Edge tolerance relative to the tip.
    """
    gamma, lo, hi = _tongue_arguments(gamma, omega_min, omega_max)
    rtol = positive("rtol", rtol)
    return _tongue_search(system, gamma, lo, hi, beam_ratio=beam_ratio,
                          pitch_ratio=pitch_ratio, rtol=rtol)[0]


def _tongue_arguments(gamma, omega_min, omega_max) -> tuple[float, float, float]:
    gamma = nonnegative("gamma", gamma)
    if gamma >= 1.0:
        raise ValueError(f"gamma = {gamma!r}: must satisfy 0 <= gamma < 1")
    lo, hi = positive("omega_min", omega_min), positive("omega_max", omega_max)
    if not lo < hi:
        raise ValueError(f"omega_min = {lo!r}: must be < omega_max = {hi!r}")
    return gamma, lo, hi


def _tongue_search(system: BeamActionSystem, gamma: float, lo: float, hi: float, *,
                   beam_ratio: float, pitch_ratio: float, rtol: float = BAND_RTOL
                   ) -> tuple[tuple[Band, ...], tuple[SearchGap, ...]]:
    """:func:`pitch_tongue_bands` (validated arguments) and what its limits leave out: the
    tongues past :data:`TONGUE_MAX_ORDER`, or from the first whose edges do not converge
    within :data:`TONGUE_MAX_HARMONICS` on (one :class:`flexbooster.bands.SearchGap`)."""
    w1 = float(system.omega_1)
    p = pitch_mode(system)
    wp = complex(loaded_frequencies(system)[p])
    if gamma == 0.0 or wp.imag != 0.0 or not wp.real > 0.0:
        return (), ()  # no pulsation, or the steady system diverges / flutters
    wp = wp.real
    C = modal_damping(system, beam_ratio=beam_ratio, pitch_ratio=pitch_ratio)
    A = system.A0
    # the pitch mode alone in the steady modal frame (the guide of each tongue's search)
    mu_p, b_p, c_p = pitch_guide(system, C)
    out = []

    def done(gaps=()):
        return tuple(sorted(out, key=lambda b: b.Omega_lo)), gaps

    def gap(r: int, limit: str, why: str) -> SearchGap:
        top = 2.0 * wp * w1 / r
        return SearchGap(stage="beam_action", limit=limit, order=r, Omega_lo=lo,
                         Omega_hi=min(top, hi),
                         reason=f"the rigid-pitch tongues r >= {r} (Omega <= {top:.6g} rad/s, "
                                f"below omega_1 / 4) not searched: {why}")

    r_min = max(1, int(np.ceil(2.0 * wp * w1 / hi - 1e-12)))
    for r in range(r_min, TONGUE_MAX_ORDER + 1):
        centre = 2.0 * wp / r  # tip of tongue r (Omega_bar)
        if centre * w1 < lo:
            break
        window = (centre * (1.0 - 0.5 / (r + 1)), centre * (1.0 + 0.5 / r))  # to the next tips
        period = "2T" if r % 2 else "T"

        def edges(g, harmonics=None, centre=centre, window=window, period=period):
            guess = _pitch_only_edges(mu_p, g * b_p, c_p, period=period, centre=centre,
                                      window=window)
            if harmonics == (0,):
                return guess, 0
            try:
                return _tongue_edges(A, C, -g * system.B, period=period, centre=centre,
                                     window=window, rtol=rtol, harmonics=harmonics,
                                     guess=guess)
            except TongueEdgesError:  # round-off beyond TONGUE_RTOL_FLOOR (Omega_bar ~ 1e-6:
                if guess is None:  # the beam modes 1e6 above): the pitch mode alone, whose
                    raise  # coupling to them is O((Omega / omega_beam)^2), below round-off
                return guess, 0

        try:
            e, K = edges(gamma)
        except TongueEdgesError:
            return done((gap(r, "TONGUE_MAX_HARMONICS", "their edges do not converge with "
                             f"TONGUE_MAX_HARMONICS = {TONGUE_MAX_HARMONICS} harmonics"),))
        if e is None:
            if r > 2:
                break  # higher tongues are narrower still
            continue
        if e[1] * w1 < lo or e[0] * w1 > hi:
            continue  # tip in the range, the tongue itself outside (shifted at a large gamma)
        g_max, x_max = _growth_max(A, C, -gamma * system.B, *e, S=tongue_hill_harmonics(r))
        g_cr = 0.0
        if C is not None:  # bisection on existence (Bolotin 1964, sec. 6), K of the edges
            a, b = 0.0, gamma
            while b - a > TONGUE_GAMMA_RTOL * gamma:
                mid = 0.5 * (a + b)
                a, b = (a, mid) if edges(mid, (K,))[0] is not None else (mid, b)
            g_cr = b
        e_lo, e_hi = max(e[0] * w1, lo), min(e[1] * w1, hi)
        out.append(Band(
            mechanism="beam_action", Omega_lo=e_lo, Omega_hi=e_hi,
            growth_rate_max=g_max * w1,  # 1/tau -> 1/s
            Omega_at_max=x_max * w1, kind="simple", modes=band_modes((p,)), order=r,
            Omega_center=centre * w1, clipped=(e_lo > e[0] * w1 or e_hi < e[1] * w1),
            critical_gamma=g_cr))
    else:  # the order limit, not a stopping rule, ended the search
        r = max(r_min, TONGUE_MAX_ORDER + 1)
        if 2.0 * wp * w1 / r >= lo:
            return done((gap(r, "TONGUE_MAX_ORDER", f"TONGUE_MAX_ORDER = {TONGUE_MAX_ORDER}"),))
    return done()


def _band_range(model: BoosterModel, omega_1: float) -> tuple[float, float]:
    """The Omega range (rad/s) of the pipeline's band search: above omega_1 / 4."""
    return (max(float(np.min(model.Omega)), BAND_OMEGA_BAR_MIN * omega_1),
            float(np.max(model.Omega)))


def _band_search(model: BoosterModel, system: BeamActionSystem
                 ) -> tuple[tuple[Band, ...], tuple[SearchGap, ...]]:
    """:func:`pipeline_bands` and what the limits of the tongue search leave out."""
    lo, hi = _band_range(model, float(system.omega_1))
    gamma = float(model.gamma)
    damping = {"beam_ratio": float(model.beam_damping_ratio),
               "pitch_ratio": float(model.pitch_damping_ratio)}
    found: tuple[Band, ...] = ()
    gaps: tuple[SearchGap, ...] = ()
    if hi > lo:
        found = beam_action_bands(system, gamma, omega_min=lo, omega_max=hi, **damping)
    low = float(np.min(model.Omega))
    if min(lo, hi) > low:  # below omega_1 / 4: the pitch tongues by harmonic balance
        seen = {(b.kind, b.modes, b.order) for b in found}
        tongues, gaps = _tongue_search(system, *_tongue_arguments(gamma, low, min(lo, hi)),
                                       **damping)
        found += tuple(b for b in tongues
                       if (b.kind, b.modes, b.order) not in seen)  # a tongue across omega_1/4
    return tuple(sorted(found, key=lambda b: b.Omega_lo)), gaps


def pipeline_bands(model: BoosterModel) -> tuple[Band, ...]:
    """The bands of :func:`beam_action_analysis`: :func:`beam_action_bands` over
    [max(Omega[0], omega_1 / 4), Omega[-1]] and the pitch tongues below, by Omega_lo.

    Parameters
    ----------
    model : BoosterModel
        The derived model (Omega range, gamma, damping ratios, beam-action system).
    """
    return _band_search(model, beam_system(model))[0]


def _hill_points(n_grid: int, n_hill: int) -> np.ndarray:
    """Indices of the n_hill grid points of the Hill check (evenly spread, ends included)."""
    n_hill = min(count("n_hill", n_hill, 1, None), n_grid)
    return np.unique(np.round(np.linspace(0, n_grid - 1, n_hill)).astype(int))


def beam_action_analysis(model: BoosterModel, *, n_hill: int = 3) -> BeamActionResult:
    """alpha_r along the Omega grid, the bands, what the limits left out and the verdict
    (pipeline stage; memo 4.1-10..12).

    The monodromy exponents on the natural branch are checked by Hill's at ``n_hill`` points.

    Parameters
    ----------
    model : BoosterModel
        The derived model: Omega grid (rad/s), omega_1, mass properties, F0 (N), gamma, K,
        damping ratios, truncation N, S (Hill harmonics), R (exponents reported).
    n_hill : int
        Check points (evenly spread, ends included, clipped to the grid), >= 1.
    """
    system = beam_system(model)
    w1 = float(system.omega_1)
    S = model.truncation.S
    R = count("R", model.truncation.R, 1, system.N + 1)
    gamma = float(model.gamma)
    Ob, gam, _ = _grid(model.Omega, gamma, system.omega_1)
    pick = _hill_points(Ob.size, n_hill)
    red_m = reduced_exponents(monodromy_exponents(system, Ob * system.omega_1, gam))
    freqs = loaded_frequencies(system)
    hill = hill_exponents(system, Ob[pick] * system.omega_1, gam[pick], S)
    diff = float(np.max(np.abs(reduced_exponents(hill.alpha) - red_m[pick])))
    im = np.max(red_m.imag, axis=1)
    stable = im <= _STABLE_TOL
    # below the stability tolerance Im alpha is round-off: report a growth rate of 0 there
    growth = np.where(stable, 0.0, im * Ob * system.omega_1)  # 1/s
    i = int(np.argmax(growth))
    peak, at_peak = float(growth[i]), (float(Ob[i] * system.omega_1) if growth[i] > 0.0 else 0.0)
    found, gaps = _band_search(model, system)
    if gamma > 0.0:  # the damping that would close each band that counts
        found = band_critical_damping(system, found, gamma=gamma,
                                      beam_ratio=float(model.beam_damping_ratio),
                                      pitch_ratio=float(model.pitch_damping_ratio))
    for band in found:  # the bands' exact maxima: a grid steps over narrow bands
        if band.growth_rate_max > peak:
            peak, at_peak = float(band.growth_rate_max), float(band.Omega_at_max)
    verdict = "unstable" if found else (gaps_text(gaps) if gaps else "stable")
    return BeamActionResult(
        Omega=Ob * w1, Omega_bar=Ob, alpha=natural_branch(red_m, Ob, freqs)[:, :R],
        frequencies=freqs[:R], stable=stable, growth_rate=growth, max_growth_rate=peak,
        Omega_at_max=at_peak, hill_monodromy_difference=diff, verdict=verdict, gamma=gamma,
        K=system.K, N=system.N, S=S, R=R, p=system.p, bands=found,
        beam_damping_ratio=float(model.beam_damping_ratio),
        pitch_damping_ratio=float(model.pitch_damping_ratio),
        band_range=_band_range(model, w1), gaps=gaps)


@dataclass(frozen=True)
class StabilityChart:
    """Stability of the beam-action system on an (Omega, gamma) grid.

    Attributes
    ----------
    Omega, gamma : numpy.ndarray
        Shapes (m,) (rad/s) and (k,).
    stable, growth_rate : numpy.ndarray
        Shape (k, m): every |Im alpha| <= 1e-6, and max |Im alpha| Omega (1/s).
    omega_1 : float
        Normalising frequency (rad/s).
    """

    Omega: np.ndarray
    gamma: np.ndarray
    stable: np.ndarray
    growth_rate: np.ndarray
    omega_1: float

    def to_dict(self) -> dict:
        """JSON-ready mapping."""
        return {
            "Omega": self.Omega.tolist(),
            "gamma": self.gamma.tolist(),
            "stable": self.stable.tolist(),
            "growth_rate": self.growth_rate.tolist(),
            "omega_1": float(self.omega_1),
        }


def stability_chart(system: BeamActionSystem, Omega: np.ndarray, gamma: np.ndarray,
                    step_phase: float = 0.25, coarse_step_phase: float = 2.0,
                    collision_distance: float = 1e-3) -> StabilityChart:
    """Stability on an (Omega, gamma) grid, gamma along axis 0 (a chart, not a verdict).

    Parameters
    ----------
    system : BeamActionSystem
        The normalised system.
    Omega, gamma : array_like
        Shapes (m,) (rad/s, > 0) and (k,) (0 <= gamma < 1).
    step_phase : float
        Accuracy of the refined points (0.25: alpha to ~5e-7 at p = 20, gamma = 0.6).
    coarse_step_phase : float
        Accuracy of the first pass over every point (>= step_phase).
    collision_distance : float
        Points whose multipliers come closer than this, or unstable, are refined.
    """
    Omega = np.asarray(Omega, dtype=float).ravel()
    gamma = np.asarray(gamma, dtype=float).ravel()
    step_phase = positive("step_phase", step_phase)
    coarse_step_phase = max(positive("coarse_step_phase", coarse_step_phase), step_phase)
    collision_distance = positive("collision_distance", collision_distance)
    OO, GG = np.meshgrid(Omega, gamma)
    alpha = monodromy_exponents(system, OO, GG, step_phase=coarse_step_phase)
    if coarse_step_phase > step_phase:
        rho = np.exp(2j * np.pi * alpha)  # Floquet multipliers
        gap = np.abs(rho[:, :, None] - rho[:, None, :])
        n = rho.shape[1]
        gap[:, np.arange(n), np.arange(n)] = np.inf
        near = (gap.min(axis=(1, 2)) < collision_distance)
        near |= np.max(np.abs(alpha.imag), axis=1) > _STABLE_TOL
        if near.any():
            alpha[near] = monodromy_exponents(system, OO.ravel()[near], GG.ravel()[near],
                                              step_phase=step_phase)
    im = np.max(np.abs(alpha.imag), axis=1).reshape(OO.shape)
    return StabilityChart(Omega=Omega, gamma=gamma, stable=im <= _STABLE_TOL,
                          growth_rate=im * OO, omega_1=system.omega_1)
