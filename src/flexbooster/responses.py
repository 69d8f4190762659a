"""Modal time responses of the two shells (memo sections 5.4, 6.1, 6.2) and their verification.

The Galerkin equations of every cylinder d and mode (j, k) are linear with constant
coefficients (6.1-1..6.1-4),

    k = 0, j = 0 ... k >= 1:   U_0k'' + omega_0k^2 U_0k = P_0k                       (6.1-2)
    j >= 1, k = 0:             M x'' + K x = (P_1, P_2),      x = (U_j0, W_j0)       (6.1-3)
    j >= 1, k >= 1:            M x'' + K x = (Q_1, Q_2, Q_3), x = (U_jk, V_jk, W_jk)  (6.1-4)

with M, K from :func:`flexbooster.shell_coefficients.galerkin_coefficients` (zero phase by
default, erratum E10).  The forcing is built from its definition, not from the memo's
evaluated forms: the shell equations (3.0-2) with the trial displacement shell part + beam part
(5.2-1, 5.3-4) give, per test function phi (the shape functions 5.3-2/3),

    forcing = -1 / ((1 - nu^2) mu theta_int) int int phi [F + (1 - nu^2) mu (u*, v*, w*)_tt
              - L(u*, v*, w*)] dxi dtheta,

F = (F1, F2, F3) of (3.0-3), L the operator of the left side of (3.0-2), u* of (5.3-4a) with
N_xixi = T(tau), v* = g* sin theta, w* = g* cos theta (5.3-4b, c) and g* of (4.1-3).  The xi
integrals are done by Gauss-Legendre quadrature, the theta integrals by orthogonality.  With
sin K psi ~ K psi, cos K psi ~ 1 (the memo's linearisation, 6.2) the forcing of a mode is a
fixed combination of the time functions

    T(tau) = 1 - gamma cos(Omega_bar tau),  T''(tau),  psi'',  psi'^2,  T psi,  q_n, q_n''

(:data:`BASIS`), with psi = sum_i A_i cos(Omega_i tau) (4.2-6..8) and the beam coordinates
q_n, q_B of (4.1-10/11).  The responses are computed three ways:

* :func:`integrate`: numerical integration, ``"DOP853"`` / ``"Radau"`` (scipy solve_ivp on the
  stacked modal systems, forcing evaluated in the time domain) or ``"duhamel"`` (exact
  propagation of each normal coordinate with the Duhamel integral done by 8-point
  Gauss-Legendre quadrature on every step: fast for long times);
* :func:`closed_form_0k`, :func:`closed_form_j0`, :func:`closed_form_jk`: the memo's closed
  forms 6.2-3, 6.2-8/9 (6.2-11/12) and 6.2-20 (6.2-28..30), errata fixed (see
  ``docs/memo-errata.md``), for a forcing written as a sum of harmonics;
* :func:`harmonic_response`: the same closed forms with the resonance-safe kernel (finite at
  exact resonance, where it grows like tau) used by :func:`simulate`.

References
----------
.. [1] Tech Memo 104, sections 3.0, 4.1, 4.2, 5.2-5.4, 6.1, 6.2 (eqs. 3.0-2, 3.0-3, 4.1-3..11,
   4.2-6..8, 5.2-1, 5.3-2..4, 5.4-1..9, 6.1-1..4, 6.2-1..30).
.. [2] V. V. Bolotin, *The Dynamic Stability of Elastic Systems*, Holden-Day, 1964, ch. 1
   (forced and combination resonances: secular growth).
.. [3] L. Meirovitch, *Elements of Vibration Analysis*, 2nd ed., McGraw-Hill, 1986, ch. 4
   (Duhamel integral, modal analysis of undamped systems).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np
from scipy import integrate as sp_integrate
from scipy.special import roots_legendre

from . import beam as beam_mod
from .beam import first_bending_frequency
from .beam_action import (
    beam_action_system,
    hill_exponents,
    loaded_frequencies,
    natural_branch,
    reduced_exponents,
)
from .checks import count, finite, positive
from .geometry import mass_properties
from .pitch import characteristic_exponent, mathieu_parameters, pitch_frequency
from .shell_coefficients import ShellParameters, galerkin_coefficients, shell_parameters

__all__ = [
    "BASIS",
    "Excitation",
    "ModalGroup",
    "SimulationResult",
    "SecularGrowth",
    "case_parameters",
    "pitch_beam_parameters",
    "make_excitation",
    "modal_groups",
    "modal_basis",
    "forcing_harmonics",
    "integrate",
    "closed_form_0k",
    "closed_form_j0",
    "closed_form_jk",
    "harmonic_response",
    "displacement_fields",
    "edge_conditions",
    "simulate",
    "secular_growth",
    "modal_forcing_spectrum",
    "secular_rates",
]

#: Time functions of the forcing (memo 3.0-3, 5.3-4, 4.1-10/11), before the beam coordinates:
#: T0_bar T / 2 (F1), eps T and eps T'' (u*, 5.3-4a), psi'', psi'^2, K T0_bar T psi / 2 (F2, F3).
BASIS = ("F_T", "u_T", "u_T_dd", "psi_dd", "psi_d_sq", "F_T_psi")
_NB = len(BASIS)
_GAUSS = 8  # Gauss-Legendre nodes per step of the Duhamel integrator


# --------------------------------------------------------------------------------------------
# Checks
# --------------------------------------------------------------------------------------------
def _times(tau: Any) -> np.ndarray:
    tau = np.atleast_1d(np.asarray(tau, dtype=float))
    if tau.ndim != 1 or tau.size == 0 or not np.all(np.isfinite(tau)) or np.any(tau < 0):
        raise ValueError("tau: must be a non-empty 1-D array of finite values >= 0")
    if np.any(np.diff(tau) < 0):
        raise ValueError("tau: must be non-decreasing")
    return tau


# --------------------------------------------------------------------------------------------
# Excitation: psi(tau), T(tau), beam coordinates
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Excitation:
    """Time functions that force the shell modes at one thrust frequency Omega.

    Attributes
    ----------
    Omega_bar : float
        Omega / omega_1 (dimensionless).
    gamma : float
        Thrust pulsation amplitude (dimensionless).
    K : float
        Gimbal gain (dimensionless).
    T0_bar : float
        T0 / (rho h L^2 omega_1^2) (3.0-4b).
    strain : float
        (1 - nu^2) T0 / (E h), the axial strain scale of u* (5.3-4a) (dimensionless).
    beta : float
        Pitch exponent beta (real, 4.2-9).
    A : numpy.ndarray
        Shape (3,), A_1..A_3 of psi (4.2-7) (rad).
    Omega_i : numpy.ndarray
        Shape (3,), Omega_i = [(i-2)^2 + eps_i beta] Omega_bar (7.2-6), units of omega_1.
    beam_freq : numpy.ndarray
        Shape (C,), (alpha_r + s) Omega_bar of the beam harmonics (4.1-10/11).
    beam_amp : numpy.ndarray
        Shape (C, N + 1) complex, C_n^(s) (rows q_1..q_N, q_B, 4.1-12); q = Re sum.
    N : int
        Beam modes.
    alpha : complex
        The beam exponent alpha_r used (its real part sets beam_freq).
    warnings : tuple of str
        Conditions under which the excitation was built (e.g. an unstable beam exponent).
    """

    Omega_bar: float
    gamma: float
    K: float
    T0_bar: float
    strain: float
    beta: float
    A: np.ndarray
    Omega_i: np.ndarray
    beam_freq: np.ndarray
    beam_amp: np.ndarray
    N: int
    alpha: complex = 0j
    warnings: tuple[str, ...] = field(default_factory=tuple)

    def thrust(self, tau: np.ndarray, derivative: int = 0) -> np.ndarray:
        """T(tau) / T0 = 1 - gamma cos(Omega_bar tau) (4.2-1a) or its second derivative."""
        tau = np.asarray(tau, dtype=float)
        c = np.cos(self.Omega_bar * tau)
        if derivative == 2:
            return self.gamma * self.Omega_bar**2 * c  # d^2/dtau^2 of (4.2-1a)
        return 1.0 - self.gamma * c  # eq. (4.2-1a)

    def psi(self, tau: np.ndarray, derivative: int = 0) -> np.ndarray:
        """psi = sum A_i cos(Omega_i tau) (4.2-6) and its derivatives (rad)."""
        ph = np.multiply.outer(np.asarray(tau, dtype=float), self.Omega_i)
        w = self.Omega_i**derivative
        trig = (np.cos, lambda x: -np.sin(x), lambda x: -np.cos(x))[derivative]
        return trig(ph) @ (self.A * w)  # eq. (4.2-6)

    def beam(self, tau: np.ndarray, derivative: int = 0) -> np.ndarray:
        """q_1..q_N, q_B (4.1-10/11): Re sum_s C^(s) e^{i nu_s tau}, shape (N + 1, nt)."""
        tau = np.atleast_1d(np.asarray(tau, dtype=float))
        if self.beam_freq.size == 0:
            return np.zeros((self.N + 1, tau.size))
        e = np.exp(1j * np.multiply.outer(self.beam_freq, tau))  # (C, nt)
        amp = self.beam_amp * ((1j * self.beam_freq[:, None]) ** derivative)
        return np.real(amp.T @ e)  # eqs. (4.1-10), (4.1-11)

    def time_functions(self, tau: np.ndarray) -> np.ndarray:
        """All basis functions evaluated in the time domain, shape (6 + 2(N + 1), nt).

        Rows: T0_bar T/2, eps T, eps T'', psi'', psi'^2, K T0_bar T psi/2 (:data:`BASIS`), then
        q_1..q_N, q_B, then their second derivatives.
        """
        tau = np.atleast_1d(np.asarray(tau, dtype=float))
        T = self.thrust(tau)
        psi = self.psi(tau)
        rows = [0.5 * self.T0_bar * T, self.strain * T, self.strain * self.thrust(tau, 2),
                self.psi(tau, 2), self.psi(tau, 1) ** 2, 0.5 * self.K * self.T0_bar * T * psi]
        return np.concatenate([np.stack(rows), self.beam(tau), self.beam(tau, 2)])

    def harmonics(self) -> tuple[np.ndarray, np.ndarray]:
        """The basis functions as sums of harmonics: f_b(tau) = Re sum_h c[b, h] e^{i nu_h tau}.

        Returns
        -------
        nu : numpy.ndarray
            Shape (H,), frequencies (units of omega_1; may be negative or zero).
        c : numpy.ndarray
            Shape (6 + 2(N + 1), H), complex amplitudes.

        Notes
        -----
        psi'^2 = sum_ip A_i A_p Omega_i Omega_p sin sin = 1/2 sum [cos(Omega_i - Omega_p)
        - cos(Omega_i + Omega_p)]; T psi = sum A_i cos Omega_i - gamma/2 sum A_i
        [cos(Omega_bar + Omega_i) + cos(Omega_bar - Omega_i)] (the products behind the
        families 4-6, 8-12 of memo 7.3).
        """
        Ob, g, A, W = self.Omega_bar, self.gamma, self.A, self.Omega_i
        tf, eps, kt = 0.5 * self.T0_bar, self.strain, 0.5 * self.K * self.T0_bar
        nb = _NB + 2 * (self.N + 1)
        nu: list[float] = []
        cols: list[tuple[int, complex]] = []

        def add(freq: float, row: int, amp: complex) -> None:
            nu.append(float(freq))
            cols.append((row, complex(amp)))

        add(0.0, 0, tf)  # T0_bar T / 2, T = 1 - gamma cos(Omega_bar tau) (4.2-1a)
        add(Ob, 0, -g * tf)
        add(0.0, 1, eps)  # eps T
        add(Ob, 1, -g * eps)
        add(Ob, 2, eps * g * Ob**2)  # eps T''
        for i in range(3):
            add(W[i], 3, -A[i] * W[i] ** 2)  # psi'' (4.2-6)
            add(W[i], 5, kt * A[i])  # K T0_bar T psi / 2
            add(Ob + W[i], 5, -0.5 * g * kt * A[i])
            add(Ob - W[i], 5, -0.5 * g * kt * A[i])
            for p in range(3):
                half = 0.5 * A[i] * A[p] * W[i] * W[p]
                add(W[i] - W[p], 4, half)  # psi'^2
                add(W[i] + W[p], 4, -half)
        for c, f in enumerate(self.beam_freq):
            for b in range(self.N + 1):
                add(f, _NB + b, self.beam_amp[c, b])  # q_b
                add(f, _NB + self.N + 1 + b, -(f**2) * self.beam_amp[c, b])  # q_b''
        out = np.zeros((nb, len(nu)), dtype=complex)
        for h, (row, amp) in enumerate(cols):
            out[row, h] = amp
        return np.asarray(nu), out


def case_parameters(case: Any) -> dict:
    """Dimensional and dimensionless parameters of a case used by this module.

    Parameters
    ----------
    case : Case-like
        Attributes of :class:`flexbooster.case.Case` (SI): ``booster.cylinder1.radius`` (m),
        ``.half_length`` (m), ``cylinder2``, ``thickness`` (m), ``E`` (Pa), ``nu``, ``rho``
        (kg/m^3); ``thrust.gamma``, ``thrust.K``; ``F0`` (N), ``T0`` (N/m); ``truncation``.

    Returns
    -------
    dict
        ``shell`` (ShellParameters), ``mass`` (MassProperties), ``omega_1`` (rad/s),
        ``omega_psi`` (rad/s), ``T0_bar``, ``strain``, ``gamma``, ``K``, ``F0`` (N), ``T0`` (N/m),
        ``radii`` (R1, R2 in m).

    References
    ----------
    Tech Memo 104, eqs. (3.0-1), (3.0-4) (erratum E3), (4.2-4), (4.2-8b).
    """
    b = case.booster
    R1, L1 = b.cylinder1.radius, b.cylinder1.half_length
    R2, L2 = b.cylinder2.radius, b.cylinder2.half_length
    mass = mass_properties(R1, L1, R2, L2, b.thickness, b.rho)
    omega_1 = first_bending_frequency(mass.L, R1, b.E, b.rho)  # eq. (4.2-8b)
    p = shell_parameters(R1, L1, R2, L2, b.thickness, b.E, b.nu, b.rho, omega_1)
    T0 = float(case.T0)
    return {
        "shell": p, "mass": mass, "omega_1": omega_1,
        "omega_psi": pitch_frequency(float(case.F0), mass.d2, case.thrust.K, mass.I_cm),
        "T0_bar": T0 / (b.rho * b.thickness * mass.L**2 * omega_1**2),  # eq. (3.0-4b)
        "strain": (1.0 - b.nu**2) * T0 / (b.E * b.thickness),  # eq. (5.3-4a) scale
        "gamma": float(case.thrust.gamma), "K": float(case.thrust.K),
        "F0": float(case.F0), "T0": T0, "radii": (float(R1), float(R2)),
    }


def pitch_beam_parameters(case: Any, Omega_bar: Any, N: int, S: int, R: int,
                          beta_method: str = "floquet") -> tuple[np.ndarray, np.ndarray]:
    """beta(Omega) and the beam exponents alpha_r(Omega) used by the forcing (vectorised).

    Parameters
    ----------
    case : Case-like
        See :func:`case_parameters`.
    Omega_bar : array_like
        Shape (n,), Omega / omega_1, > 0.
    N, S : int
        Beam modes (0..500) and Hill harmonics (0..500).
    R : int
        Number of exponents returned, 1..N + 1.
    beta_method : str
        Method of :func:`flexbooster.pitch.characteristic_exponent`.

    Returns
    -------
    beta : numpy.ndarray
        Shape (n,), Re beta (4.2-9, exact Floquet exponent by default).
    alpha : numpy.ndarray
        Shape (n, R), Re alpha_r on the natural branch (Hill's determinant, 4.1-10/11).

    Notes
    -----
    This is the ``params`` function that :func:`flexbooster.stability.unstable_frequencies`
    takes: the roots it returns and the forcing of :func:`make_excitation` then use the same
    beta and alpha_r, so a simulation at a root is exactly resonant.

    References
    ----------
    Tech Memo 104, eqs. (4.1-10), (4.1-11), (4.2-4), (4.2-9).
    """
    cp = case_parameters(case)
    x = np.atleast_1d(np.asarray(Omega_bar, dtype=float))
    if np.any(~np.isfinite(x)) or np.any(x <= 0):
        raise ValueError(f"Omega_bar = {Omega_bar!r}: must be finite and > 0")
    a, q = mathieu_parameters(x * cp["omega_1"], cp["omega_psi"], cp["gamma"])  # (4.2-4)
    beta = np.real(characteristic_exponent(a, q, beta_method))
    _, alpha = _beam_exponents(cp, x, N, S)
    R = count("R", R, 1, N + 1)
    return beta, np.real(alpha[:, :R])


def _beam_exponents(cp: dict, x: np.ndarray, N: int, S: int) -> tuple:
    m = cp["mass"]
    system = beam_action_system(cp["omega_1"], m.mass, m.L, m.d2, m.I_cm, cp["F0"], cp["K"], N)
    hill = hill_exponents(system, x * cp["omega_1"], np.full(x.shape, cp["gamma"]), S)
    nat = natural_branch(reduced_exponents(hill.alpha), x, loaded_frequencies(system))
    return hill, nat


def make_excitation(case: Any, Omega: float, psi0: float = 0.01, beam_amplitude: float = 1e-4,
                    beam_mode: int = 1, N: int | None = None, S: int | None = None,
                    beta_method: str = "floquet") -> Excitation:
    """The time functions that force the shells at the thrust frequency Omega.

    Parameters
    ----------
    case : Case-like
        See :func:`case_parameters`; ``truncation.N``, ``.S`` give the defaults of N, S.
    Omega : float
        Thrust pulsation frequency (rad/s), > 0.
    psi0 : float
        Initial pitch angle psi(0) (rad) (4.2-8a); 0 switches the rigid-body terms off.
    beam_amplitude : float
        Euclidean norm of the Floquet vector (C^(s))_s of the beam motion (dimensionless, g* is
        in units of L); 0 switches the beam terms off.
    beam_mode : int
        Which beam exponent alpha_r (r = 1..N + 1, natural branch) moves the beam.
    N, S : int, optional
        Beam modes and Hill harmonics (default: the case's truncation).
    beta_method : str
        Method of :func:`flexbooster.pitch.characteristic_exponent`.

    Returns
    -------
    Excitation

    Raises
    ------
    ValueError
        Bad input, or a pitch motion that is not bounded (complex beta: the three-term psi of
        4.2-6 does not exist).

    Notes
    -----
    A_i from (4.2-7b..d) with the exact beta; the beam vector from Hill's determinant at the
    exponent of the Hill set nearest alpha_r of the natural branch.  A beam exponent with an
    imaginary part (flutter or a parametric region of the beam) is used with its real part
    only and recorded in ``warnings``.

    References
    ----------
    Tech Memo 104, eqs. (4.1-10)..(4.1-12), (4.2-6)..(4.2-9).
    """
    cp = case_parameters(case)
    N = count("N", case.truncation.N if N is None else N, 0)
    S = count("S", case.truncation.S if S is None else S, 0)
    return _make_excitation(cp, Omega, psi0, beam_amplitude, beam_mode, N, S, beta_method)


def _make_excitation(cp: dict, Omega: float, psi0: float, beam_amplitude: float,
                     beam_mode: int, N: int, S: int, beta_method: str,
                     beam_pre: tuple | None = None) -> Excitation:
    Omega = positive("Omega", Omega)
    psi0 = finite("psi0", psi0)
    beam_amplitude = finite("beam_amplitude", beam_amplitude)
    beam_mode = count("beam_mode", beam_mode, 1, N + 1)
    Ob = Omega / cp["omega_1"]
    a, q = mathieu_parameters(np.array([Omega]), cp["omega_psi"], cp["gamma"])
    a, q = float(a[0]), float(q[0])
    beta_c = complex(characteristic_exponent(a, q, beta_method))
    if abs(beta_c.imag) > 0.0:
        raise ValueError(f"Omega = {Omega!r}: the pitch motion is unbounded (beta = {beta_c}); "
                         "psi of eq. (4.2-6) does not exist")
    beta = beta_c.real
    if psi0 != 0.0:
        den1, den3 = a - (beta - 2.0) ** 2, a - (2.0 + beta) ** 2
        A2 = psi0 / (1.0 + q * (1.0 / den3 + 1.0 / den1))  # eq. (4.2-7c)
        A = np.array([A2 * q / den1, A2, A2 * q / den3])  # eqs. (4.2-7b, d)
    else:
        A = np.zeros(3)
    Omega_i = np.array([1.0 - beta / 2.0, beta / 2.0, 1.0 + beta / 2.0]) * Ob  # (7.2-1..3)
    warnings: list[str] = []
    alpha = 0j
    if beam_amplitude != 0.0 and N >= 0:
        if beam_pre is None:
            hill, nat = _beam_exponents(cp, np.array([Ob]), N, S)
            beam_pre = (hill.alpha[0], hill.C[0], nat[0])
        cand, Cs, nat_row = beam_pre
        target = nat_row[beam_mode - 1]
        dist = np.abs(cand.real - target.real - np.round(cand.real - target.real))
        dist = dist + np.abs(cand.imag - target.imag)
        e = int(np.argmin(dist))
        alpha = complex(cand[e])
        if abs(alpha.imag) > 1e-9:
            warnings.append(f"beam exponent alpha_{beam_mode} = {alpha:.6g} is complex at "
                            f"Omega = {Omega:.6g} rad/s: its real part is used")
        s = np.arange(-S, S + 1)
        beam_freq = (alpha.real + s) * Ob  # eqs. (4.1-10), (4.1-11)
        C = Cs[e]  # (2S + 1, N + 1), unit norm
        beam_amp = beam_amplitude * C
    else:
        beam_freq = np.zeros(0)
        beam_amp = np.zeros((0, N + 1), dtype=complex)
    return Excitation(Omega_bar=Ob, gamma=cp["gamma"], K=cp["K"], T0_bar=cp["T0_bar"],
                      strain=cp["strain"], beta=beta, A=A, Omega_i=Omega_i,
                      beam_freq=beam_freq, beam_amp=beam_amp, N=N, alpha=alpha,
                      warnings=tuple(warnings))


# --------------------------------------------------------------------------------------------
# Modal systems and their forcing (by quadrature of the definitions)
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class ModalGroup:
    """Stacked modal systems of one kind of one cylinder, M x'' + K x = sum_b F_b f_b(tau).

    Attributes
    ----------
    kind : str
        ``"0k"`` (x = U_0k, 6.1-2), ``"j0"`` (x = (U, W), 6.1-3) or ``"jk"`` (x = (U, V, W),
        6.1-4).
    cylinder : int
        1 (aft) or 2 (forward).
    j, k : numpy.ndarray
        Shape (n,), mode indices.
    mass, stiff : numpy.ndarray
        Shape (n, p, p), mass and stiffness matrices (appendix A normalisation).
    forcing : numpy.ndarray
        Shape (6 + 2(N + 1), n, p): the forcing per unit basis function (:data:`BASIS`, then
        q_1..q_N, q_B, then their second derivatives).
    components : tuple of str
        Names of the p unknowns.
    """

    kind: str
    cylinder: int
    j: np.ndarray
    k: np.ndarray
    mass: np.ndarray
    stiff: np.ndarray
    forcing: np.ndarray
    components: tuple[str, ...]

    def __len__(self) -> int:
        return int(self.j.size)

    def forced(self) -> np.ndarray:
        """Boolean mask (n,) of the modes with a structurally non-zero forcing."""
        return np.any(self.forcing != 0.0, axis=(0, 2))

    def select(self, mask: np.ndarray) -> ModalGroup:
        """The sub-group of the modes in ``mask`` (boolean or integer index)."""
        return ModalGroup(self.kind, self.cylinder, self.j[mask], self.k[mask], self.mass[mask],
                          self.stiff[mask], self.forcing[:, mask], self.components)


def _quad_nodes(p: ShellParameters, d: int, M: int, N: int) -> tuple[np.ndarray, np.ndarray]:
    lam_N = float(beam_mod.free_free_eigenvalues(N)[-1]) if N > 0 else 0.0
    n = int(2 * M + lam_N + 64)  # the integrands turn through up to j pi and lambda_N / 2 rad
    t, w = roots_legendre(n)
    lo, hi = p.edges(d)
    half = (hi - lo) / 2.0
    return lo + half * (t + 1.0), w * half


def _beam_shapes(p: ShellParameters, xi: np.ndarray, N: int) -> dict[str, np.ndarray]:
    """g and its xi-derivatives of each beam coordinate (rows q_1..q_N, q_B) (4.1-3..7)."""
    xi = np.asarray(xi, dtype=float)
    zeta = xi - p.a  # zeta = xi_bar - d4/L + 1 = xi_bar + x_cm / L (C-6)
    out = {key: np.zeros((N + 1, xi.size)) for key in ("g", "g1", "g2", "g3", "g4")}
    if N > 0:
        n = np.arange(1, N + 1)
        half = beam_mod.free_free_eigenvalues(N)[:, None] / 2.0
        for key, order in (("g", 0), ("g1", 1), ("g2", 2), ("g3", 3), ("g4", 4)):
            # d^k phi_n / d xi^k = (lambda_n / 2)^k phi_n^(k) (4.1-4..7)
            out[key][:N] = half**order * beam_mod.mode_shape(n[:, None], zeta[None, :], order)
    out["g"][N] = xi  # q_B xi_bar (4.1-3)
    out["g1"][N] = 1.0  # (4.1-4)
    return out


def _edge_argument(p: ShellParameters, d: int, j: np.ndarray, phase: str) -> np.ndarray:
    from .shell_coefficients import edge_arguments

    return np.asarray(edge_arguments(p, d, j, phase)[0], dtype=float) + 0.0 * j


def modal_groups(p: ShellParameters, M: tuple[int, int], Nk: tuple[int, int], N: int,
                 phase: str = "zero") -> tuple[ModalGroup, ...]:
    """Modal systems 6.1-2..4 of both cylinders with their forcing built from its definition.

    Parameters
    ----------
    p : ShellParameters
        From :func:`flexbooster.shell_coefficients.shell_parameters`.
    M, Nk : (int, int)
        Largest axial index j and circumferential index k of cylinders 1 and 2, 1..500.
    N : int
        Beam modes in g* (0..500).
    phase : {"zero", "printed"}
        Shape-function phase (erratum E10); the forcing projections use the same phase.

    Returns
    -------
    tuple of ModalGroup
        (0k, j0, jk) of cylinder 1, then of cylinder 2.

    Notes
    -----
    Forcing per unit basis function (theta integrals by orthogonality, each row divided by
    its theta integral and by (1 - nu^2) mu; C = cos s, S = sin s on the cylinder,
    Xi = xi - (xi - b + 1)^2 / 2, g0 = 1 / ((1 - nu^2) mu)):

    * j0, u row: F_T -int C; u_T g0/2 int C (u*''); u_T_dd int Xi C / 2 (-u*_tt);
      psi'^2 int xi C;  w row: psi'^2 -int S / (2 lambda); u_T -nu lambda g0 int (b - xi) S / 2;
    * jk, k = 1: u row psi'' int C / lambda, q_b lambda/(2(1+nu) mu) int g_b' C;
      v and w rows: F_T_psi int S, psi'' int xi S, q_b'' -int g_b S; q_b: v row
      g0 (1-nu)/2 int g_b'' S, w row -g0 sigma^2/12 int (g'''' - 2 lambda^2 g'' + lambda^4 g) S;
    * jk, k = 2: v and w rows psi'^2 -int S / (2 lambda);
    * 0k, k = 1 (u = cos theta over the cylinder of length ell): psi'' ell / lambda,
      q_b lambda/(2(1+nu) mu) int g_b'.

    References
    ----------
    Tech Memo 104, eqs. (3.0-2), (3.0-3), (4.1-3..7), (5.2-1), (5.3-4), (5.4-3), (5.4-4),
    (5.4-7), (5.4-9).
    """
    N = count("N", N, 0)
    out: list[ModalGroup] = []
    for d in (1, 2):
        Md = count(f"M{d}", M[d - 1], 1)
        Nd = count(f"N{d}", Nk[d - 1], 1)
        out.extend(_cylinder_groups(p, d, Md, Nd, N, phase))
    return tuple(out)


def _cylinder_groups(p: ShellParameters, d: int, M: int, Nk: int, N: int,
                     phase: str) -> list[ModalGroup]:
    nu, mu, sg = p.nu, p.mu, p.sigma
    lam = p.lam(d)
    g0 = 1.0 / ((1.0 - nu**2) * mu)
    coef = galerkin_coefficients(p, d, M, Nk, phase=phase)
    xi, wq = _quad_nodes(p, d, M, N)
    j = np.arange(1, M + 1)
    alpha = j * np.pi * p.L / (2.0 * p.half_length(d))
    s = (_edge_argument(p, d, j, phase)[:, None]
         + alpha[:, None] * (xi - p.edges(d)[0])[None, :])  # argument of 5.3-2/3
    C, S = np.cos(s), np.sin(s)
    bs = _beam_shapes(p, xi, N)
    Xi = xi - 0.5 * (xi - p.b + 1.0) ** 2  # bracket of eq. (5.3-4a)
    IC, IS = C @ wq, S @ wq
    IxC, IxS = (C * xi) @ wq, (S * xi) @ wq
    IXiC, IbS = (C * Xi) @ wq, (S * (p.b - xi)) @ wq
    G1C = (C * wq) @ bs["g1"].T  # (M, N + 1): int g_b' C
    GS = (S * wq) @ bs["g"].T
    G2S = (S * wq) @ bs["g2"].T
    DelS = (S * wq) @ (bs["g4"] - 2.0 * lam**2 * bs["g2"] + lam**4 * bs["g"]).T  # Lap^4 g*
    nb = _NB + 2 * (N + 1)
    qb = slice(_NB, _NB + N + 1)  # rows q_b
    qdd = slice(_NB + N + 1, nb)  # rows q_b''
    kF, kU, kUdd, kPdd, kPd2, kTP = range(_NB)
    groups = []

    # 0k: U_0k'' + omega_0k^2 U_0k = P_0k (5.4-4, 6.1-2), mass = cylinder length ell
    kk = np.arange(1, Nk + 1)
    ell = p.edges(d)[1] - p.edges(d)[0]
    F = np.zeros((nb, Nk, 1))
    F[kPdd, 0, 0] = ell / lam  # -(-psi''/lambda cos theta) of F1 (3.0-3a), k = 1
    F[qb, 0, 0] = lam / (2.0 * (1.0 + nu) * mu) * (bs["g1"] @ wq)  # int g*' (5.4-4)
    groups.append(ModalGroup(
        "0k", d, np.zeros(Nk, dtype=int), kk, np.full((Nk, 1, 1), ell),
        (ell * lam**2 * kk**2 / (2.0 * (1.0 + nu) * mu))[:, None, None],  # eq. (5.4-4)
        F, ("U",)))

    # j0: (U, W), eqs. (5.4-6), (5.4-7), (6.1-3)
    m0, k0 = coef.matrices_j0()
    F = np.zeros((nb, M, 2))
    F[kF, :, 0] = -IC  # -(T0_bar/2 T cos K psi) of F1 (3.0-3a), cos K psi ~ 1
    F[kU, :, 0] = 0.5 * g0 * IC  # u*'' = eps T / 2 (5.3-4a)
    F[kUdd, :, 0] = 0.5 * IXiC  # -u*_tt = eps T'' Xi / 2 (5.3-4a)
    F[kPd2, :, 0] = IxC  # -(-psi'^2 xi) of F1 (3.0-3a)
    F[kPd2, :, 1] = -IS / (2.0 * lam)  # psi'^2 cos^2 theta / lambda of F3 (3.0-3c), k = 0
    F[kU, :, 1] = -0.5 * nu * lam * g0 * IbS  # nu lambda u*' (5.3-4a), u*' = -eps T (b - xi)/2
    groups.append(ModalGroup("j0", d, j, np.zeros(M, dtype=int), m0, k0, F, ("U", "W")))

    # jk: (U, V, W), eqs. (5.4-8), (5.4-9), (6.1-4)
    mk, kk3 = coef.matrices_jk()
    jj, kj = np.meshgrid(j, kk, indexing="ij")
    F = np.zeros((nb, M, Nk, 3))
    F[kPdd, :, 0, 0] = IC / lam  # psi'' cos theta / lambda of F1, delta_1k
    F[qb, :, 0, 0] = lam / (2.0 * (1.0 + nu) * mu) * G1C.T  # (1-nu) lambda/2 g*' (5.4-9a)
    for r in (1, 2):  # F2, F3 (3.0-3b, c): [-T0_bar/2 T K psi - psi'' xi] sin/cos theta
        F[kTP, :, 0, r] = IS
        F[kPdd, :, 0, r] = IxS
        F[qdd, :, 0, r] = -GS.T  # -(1 - nu^2) mu g*_tt (5.4-9b, c)
    F[qb, :, 0, 1] = g0 * (1.0 - nu) / 2.0 * G2S.T  # (1-nu)/2 g*'' (5.4-9b, erratum R-6)
    F[qb, :, 0, 2] = -g0 * sg**2 / 12.0 * DelS.T  # sigma^2/12 Lap^4 g* (5.4-9c, erratum R-7)
    if Nk >= 2:  # delta_2k: psi'^2 cos theta sin theta / lambda, cos^2 theta / lambda
        F[kPd2, :, 1, 1] = -IS / (2.0 * lam)
        F[kPd2, :, 1, 2] = -IS / (2.0 * lam)
    groups.append(ModalGroup("jk", d, jj.ravel(), kj.ravel(), mk.reshape(-1, 3, 3),
                             kk3.reshape(-1, 3, 3), F.reshape(nb, -1, 3), ("U", "V", "W")))
    return groups


def modal_basis(group: ModalGroup) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Natural frequencies and normal coordinates of stacked systems M x'' + K x = F.

    Parameters
    ----------
    group : ModalGroup

    Returns
    -------
    omega : numpy.ndarray
        Shape (n, p), natural frequencies (units of omega_1), ascending per mode (branch
        m = 1..p).
    Phi : numpy.ndarray
        Shape (n, p, p), eigenvectors of M^-1 K (columns): x = Phi y.
    P : numpy.ndarray
        Shape (n, p, p), Phi^-1 M^-1: y'' + omega^2 y = P F.

    Raises
    ------
    ValueError
        If a system has a complex or non-positive omega^2 (possible only with the printed
        phase, erratum E10): it has no undamped normal coordinates.

    References
    ----------
    Tech Memo 104, eqs. (6.2-5), (6.2-15) (Delta(s) = det(M s^2 + K)).
    """
    Minv = np.linalg.inv(group.mass)
    lam, vec = np.linalg.eig(Minv @ group.stiff)
    if np.any(np.abs(lam.imag) > 1e-10 * np.abs(lam)) or np.any(lam.real <= 0):
        raise ValueError("group: a modal system has a complex or non-positive omega^2 "
                         "(printed phase, erratum E10); it has no normal coordinates")
    order = np.argsort(lam.real, axis=-1)
    lam = np.take_along_axis(lam.real, order, axis=-1)
    Phi = np.take_along_axis(vec.real, order[:, None, :], axis=-1)
    return np.sqrt(lam), Phi, np.linalg.solve(Phi, Minv)


def forcing_harmonics(group: ModalGroup, ex: Excitation) -> tuple[np.ndarray, np.ndarray]:
    """The forcing of every mode of a group as a sum of harmonics, Re sum_h f_h e^{i nu_h tau}.

    Parameters
    ----------
    group : ModalGroup
    ex : Excitation

    Returns
    -------
    nu : numpy.ndarray
        Shape (H,), distinct frequencies (units of omega_1).
    f : numpy.ndarray
        Shape (n, p, H) complex, the forcing amplitudes (right-hand sides P, Q of 5.4).

    References
    ----------
    Tech Memo 104, eqs. (4.2-6), (4.1-10/11), (5.4-3..9).
    """
    nu, c = ex.harmonics()
    if c.shape[0] != group.forcing.shape[0]:
        raise ValueError(f"ex: N = {ex.N} does not match the group's beam modes "
                         f"({(group.forcing.shape[0] - _NB) // 2 - 1})")
    return nu, np.einsum("bh,bnp->nph", c, group.forcing)


# --------------------------------------------------------------------------------------------
# Numerical integration
# --------------------------------------------------------------------------------------------
def _force(group: ModalGroup, ex: Excitation, tau: np.ndarray) -> np.ndarray:
    """Forcing (n, p, nt) at the times tau, from the time functions evaluated directly."""
    return np.einsum("bt,bnp->npt", ex.time_functions(tau), group.forcing)


def integrate(group: ModalGroup, ex: Excitation, tau: Any, x0: Any = None,
              method: str = "DOP853", rtol: float = 1e-12, atol: float | None = None,
              return_normal: bool = False) -> np.ndarray:
    """Response of every mode of a group by numerical integration, zero initial velocity.

    Parameters
    ----------
    group : ModalGroup
    ex : Excitation
    tau : array_like
        Output times tau = omega_1 t, non-decreasing, >= 0 (integration starts at 0).
    x0 : array_like, optional
        Shape (n, p), initial displacements (units of L); default zero.
    method : {"DOP853", "Radau", "duhamel"}
        ``"DOP853"``/``"Radau"``: scipy solve_ivp on the stacked first-order system
        (rtol, atol); ``"duhamel"``: each normal coordinate propagated exactly, with the
        Duhamel integral int f(eta) e^{-i omega eta} d eta by 8-point Gauss-Legendre
        quadrature on steps of phase at most 2 rad (any length of time).
    rtol : float
        Relative tolerance of solve_ivp.
    atol : float, optional
        Absolute tolerance of solve_ivp (default rtol times 1e-3 of the static scale
        max |M^-1 F| / min omega^2).
    return_normal : bool
        ``"duhamel"`` only: also return Z = y' + i omega y times e^{-i omega tau}, shape
        (n, p, nt), for each normal coordinate.

    Returns
    -------
    numpy.ndarray
        Shape (n, p, nt): U, (U, W) or (U, V, W) in units of L (and Z if requested).

    References
    ----------
    Tech Memo 104, eqs. (6.1-2)..(6.1-4); Meirovitch (1986) ch. 4 (Duhamel integral);
    E. Hairer, S. P. Norsett, G. Wanner, *Solving Ordinary Differential Equations I*,
    Springer, 1993 (DOP853).
    """
    tau = _times(tau)
    n, p = group.j.size, group.mass.shape[-1]
    x0 = np.zeros((n, p)) if x0 is None else np.asarray(x0, dtype=float).reshape(n, p)
    if method == "duhamel":
        return _duhamel(group, ex, tau, x0, return_normal)
    if method not in ("DOP853", "Radau"):
        raise ValueError(f"method = {method!r}: must be 'DOP853', 'Radau' or 'duhamel'")
    Minv = np.linalg.inv(group.mass)
    A = Minv @ group.stiff
    B = np.einsum("nij,bnj->bni", Minv, group.forcing)  # M^-1 F_b
    if atol is None:
        omega2 = np.abs(np.linalg.eigvals(A)).min() if n else 1.0
        probe = np.linspace(0.0, max(tau[-1], 1.0), 64)
        scale = np.abs(np.einsum("bt,bnp->npt", ex.time_functions(probe), B)).max() / omega2
        atol = rtol * 1e-3 * max(scale, np.abs(x0).max(), 1e-300)
    m = n * p

    def rhs(t: float, y: np.ndarray) -> np.ndarray:
        x = y[:m].reshape(n, p)
        f = np.einsum("b,bnp->np", ex.time_functions(np.array([t]))[:, 0], B)
        acc = f - np.einsum("nij,nj->ni", A, x)  # eqs. (6.1-2..4): x'' = M^-1 (F - K x)
        return np.concatenate([y[m:], acc.ravel()])

    y0 = np.concatenate([x0.ravel(), np.zeros(m)])
    if tau[-1] == 0.0:
        return np.repeat(x0[:, :, None], tau.size, axis=2)
    sol = sp_integrate.solve_ivp(rhs, (0.0, float(tau[-1])), y0, method=method, t_eval=tau,
                                 rtol=rtol, atol=atol)
    if not sol.success:
        raise ValueError(f"integration failed: {sol.message}")
    return sol.y[:m].reshape(n, p, tau.size)


def _duhamel(group: ModalGroup, ex: Excitation, tau: np.ndarray, x0: np.ndarray,
             return_normal: bool) -> Any:
    omega, Phi, P = modal_basis(group)
    n, p = omega.shape
    y0 = np.linalg.solve(Phi, x0[..., None])[..., 0]
    nu_max = float(np.max(np.abs(ex.harmonics()[0])))
    h_max = 2.0 / (float(omega.max()) + nu_max)  # phase per step <= 2 rad
    bounds = [0.0]
    out_idx = np.zeros(tau.size, dtype=int)
    for i, t in enumerate(tau):  # step boundaries: every output time, subdivided uniformly
        gap = t - bounds[-1]
        if gap > 0:
            m_steps = int(np.ceil(gap / h_max))
            bounds.extend((bounds[-1] + gap * np.arange(1, m_steps + 1) / m_steps).tolist())
        out_idx[i] = len(bounds) - 1
    bounds = np.asarray(bounds)
    xg, wg = roots_legendre(_GAUSS)
    Z = np.zeros((n, p, bounds.size), dtype=complex)
    Z[..., 0] = 1j * omega * y0  # Z = (y' + i omega y) e^{-i omega tau}, y'(0) = 0
    PF = np.einsum("nij,bnj->bni", P, group.forcing)  # (nb, n, p)
    chunk = max(1, 200_000 // max(1, n * p * _GAUSS))
    acc = Z[..., 0].copy()
    n_steps = bounds.size - 1
    for start in range(0, n_steps, chunk):
        stop = min(start + chunk, n_steps)
        lo, hi = bounds[start:stop], bounds[start + 1:stop + 1]
        half = (hi - lo) / 2.0
        nodes = (lo[:, None] + half[:, None] * (xg[None, :] + 1.0)).ravel()
        g = np.einsum("bt,bnp->npt", ex.time_functions(nodes), PF)  # modal forcing
        integrand = g * np.exp(-1j * omega[..., None] * nodes)  # Duhamel integrand
        step = (integrand.reshape(n, p, -1, _GAUSS) * wg).sum(-1) * half  # Gauss-Legendre
        cum = acc[..., None] + np.cumsum(step, axis=-1)
        Z[..., start + 1:start + 1 + hi.size] = cum
        acc = cum[..., -1]
    Zo = Z[..., out_idx]
    y = np.imag(Zo * np.exp(1j * omega[..., None] * tau)) / omega[..., None]
    x = np.einsum("nij,njt->nit", Phi, y)
    return (x, Zo) if return_normal else x


# --------------------------------------------------------------------------------------------
# The memo's closed forms (errata fixed) and the resonance-safe kernel
# --------------------------------------------------------------------------------------------
def _convolution(omega: np.ndarray, nu: np.ndarray, f: np.ndarray, tau: np.ndarray) -> np.ndarray:
    """(1/omega) int_0^tau Re sum_h f_h e^{i nu_h eta} sin omega (tau - eta) d eta, memo form.

    omega (n,), nu (H,), f (n, H) -> (n, nt); the bracket of 6.2-3 / 6.2-28:
    [e^{i nu tau} - cos omega tau - i (nu/omega) sin omega tau] / (omega^2 - nu^2).
    """
    w = omega[:, None, None]
    v = nu[None, :, None]
    t = tau[None, None, :]
    br = (np.exp(1j * v * t) - np.cos(w * t) - 1j * (v / w) * np.sin(w * t)) / (w**2 - v**2)
    return np.real(np.einsum("nh,nht->nt", f, br))  # eqs. (6.2-3), (6.2-28)


def closed_form_0k(omega: Any, u0: Any, nu: Any, P: Any, tau: Any) -> np.ndarray:
    """U_0k(tau) of eq. (6.2-3), errata fixed: U'' + omega^2 U = P, U(0) = u0, U'(0) = 0.

    Parameters
    ----------
    omega : array_like
        Shape (n,), omega_0k (units of omega_1), > 0.
    u0 : array_like
        Shape (n,), initial displacements (units of L).
    nu : array_like
        Shape (H,), forcing frequencies (units of omega_1), none equal to an omega.
    P : array_like
        Shape (n, H) complex, P_0k = Re sum_h P_h e^{i nu_h tau} (per unit mass).
    tau : array_like
        Output times.

    Returns
    -------
    numpy.ndarray
        Shape (n, nt), U_0k in units of L.

    Notes
    -----
    6.2-3: u0 cos omega tau + sum_h P_h/(nu_h^2 - omega^2) [cos omega tau
    + i (nu_h/omega) sin omega tau - e^{i nu_h tau}] (real part): the psi'' terms
    (nu = Omega_i, P = -A_i Omega_i^2 / lambda) and the beam terms
    (nu = (alpha_r + s) Omega_bar, P = lambda/(2(1+nu) mu) [C_B + C_n [phi_n]_a^c / (c - a)]).
    Errata R-1 (6.2-1: g* for g*'), R-2 (6.2-3: the sum over n also multiplies C_B).

    References
    ----------
    Tech Memo 104, eqs. (6.2-1)..(6.2-3).
    """
    omega = np.atleast_1d(np.asarray(omega, dtype=float))
    tau = _times(tau)
    P = np.asarray(P, dtype=complex).reshape(omega.size, -1)
    u0 = np.broadcast_to(np.asarray(u0, dtype=float), omega.shape)
    free = u0[:, None] * np.cos(omega[:, None] * tau)  # (u_0k) cos omega tau (6.2-3)
    return free + _convolution(omega, np.asarray(nu, dtype=float), P, tau)


def closed_form_j0(coef: dict, u0: Any, w0: Any, nu: Any, P1: Any, P2: Any,
                   tau: Any, form: str = "corrected") -> tuple[np.ndarray, np.ndarray]:
    """U_j0, W_j0 of eqs. (6.2-8), (6.2-9) (evaluated: 6.2-11, 6.2-12), errata fixed.

    Parameters
    ----------
    coef : dict
        ``a, b, c, d, h, j, k`` of (5.4-6), arrays of shape (n,).
    u0, w0 : array_like
        Shape (n,), initial displacements (units of L), zero initial velocities.
    nu : array_like
        Shape (H,), forcing frequencies (units of omega_1).
    P1, P2 : array_like
        Shape (n, H) complex, [P_j0]_1 and [P_j0]_2 = Re sum_h P_h e^{i nu_h tau}.
    tau : array_like
        Output times.
    form : {"corrected", "printed"}
        ``"printed"`` keeps the memo's 6.2-8/9 as printed: no factor 1/(a) and (h_j0) w_j0 in
        the second term of 6.2-9 (errata R-3, R-4).

    Returns
    -------
    U, W : numpy.ndarray
        Shape (n, nt) each, units of L.

    Notes
    -----
    With (a) = a j, (b) = c j + a k - h b, (c) = c k - h d (6.2-7), omega_m^2 = [(b) -+
    sqrt((b)^2 - 4 (a)(c))] / (2 (a)) (6.2-6 with erratum E6), and I_m = (1/omega_m) int P
    sin omega_m (tau - eta):

    U = sum_m (-1)^m / ((omega_1^2 - omega_2^2)(a)) { [j (a3 - omega_m^2)(a u0 + b w0)
        - b (a2 - omega_m^2) j w0] cos omega_m tau + j (a3 - omega_m^2) I_m[P1]
        - b (a2 - omega_m^2) I_m[P2] }
    W = sum_m (-1)^m / ((omega_1^2 - omega_2^2)(a)) { [a (a1 - omega_m^2) j w0
        - h (a u0 + b w0)] cos omega_m tau + a (a1 - omega_m^2) I_m[P2] - h I_m[P1] }

    with b (a2 - omega^2) = d - b omega^2 etc. (so b = 0, the zero phase, is allowed).
    Errata R-3 (the factor 1/(a) = 1/(a_j0 j_j0) is missing in 6.2-8, -9, -11, -12) and R-4
    (6.2-9: (h_j0) w_j0 printed for (b_j0) w_j0).

    References
    ----------
    Tech Memo 104, eqs. (6.2-4)..(6.2-12).
    """
    a, b, c, d, h, j, k = (np.atleast_1d(np.asarray(coef[x], dtype=float))
                           for x in ("a", "b", "c", "d", "h", "j", "k"))
    tau = _times(tau)
    nu = np.asarray(nu, dtype=float)
    u0 = np.broadcast_to(np.asarray(u0, dtype=float), a.shape)
    w0 = np.broadcast_to(np.asarray(w0, dtype=float), a.shape)
    P1 = np.asarray(P1, dtype=complex).reshape(a.size, -1)
    P2 = np.asarray(P2, dtype=complex).reshape(a.size, -1)
    if form not in ("corrected", "printed"):
        raise ValueError(f"form = {form!r}: must be 'corrected' or 'printed'")
    printed = form == "printed"
    A_ = a * j  # (a)_d, eq. (6.2-7)
    B_ = c * j + a * k - h * b  # (b)_d
    C_ = c * k - h * d  # (c)_d
    root = np.sqrt(B_**2 - 4.0 * A_ * C_)
    om2 = np.stack([(B_ - root) / (2.0 * A_), (B_ + root) / (2.0 * A_)])  # (6.2-6), E6
    U = np.zeros((a.size, tau.size))
    W = np.zeros((a.size, tau.size))
    for m in (0, 1):
        w2 = om2[m]
        w = np.sqrt(w2)
        # (-1)^m / (omega1^2 - omega2^2) / (a), erratum R-3 (the printed form lacks 1/(a))
        pre = (-1.0) ** (m + 1) / ((om2[0] - om2[1]) * (1.0 if printed else A_))
        cosw = np.cos(w[:, None] * tau)
        I1 = _convolution(w, nu, P1, tau)
        I2 = _convolution(w, nu, P2, tau)
        ja3 = k - j * w2  # j (a3 - omega^2), a3 = k/j (6.2-10c)
        ba2 = d - b * w2  # b (a2 - omega^2), a2 = d/b (6.2-10b)
        aa1 = c - a * w2  # a (a1 - omega^2), a1 = c/a (6.2-10a)
        U += pre[:, None] * (((ja3 * (a * u0 + b * w0) - ba2 * j * w0)[:, None]) * cosw
                             + ja3[:, None] * I1 - ba2[:, None] * I2)  # eq. (6.2-8)
        bw = (h if printed else b) * w0  # erratum R-4: printed (h_j0) w_j0
        W += pre[:, None] * (((aa1 * j * w0 - h * (a * u0 + bw))[:, None]) * cosw
                             + aa1[:, None] * I2 - h[:, None] * I1)  # eq. (6.2-9), R-4
    return U, W


def _adjugate3(A: np.ndarray) -> np.ndarray:
    """Adjugate of stacked 3x3 matrices: columns r1 x r2, r2 x r0, r0 x r1."""
    r0, r1, r2 = A[..., 0, :], A[..., 1, :], A[..., 2, :]
    return np.stack([np.cross(r1, r2), np.cross(r2, r0), np.cross(r0, r1)], axis=-1)


def closed_form_jk(mass: Any, stiff: Any, x0: Any, nu: Any, Q: Any,
                   tau: Any) -> np.ndarray:
    """U_jk, V_jk, W_jk of eq. (6.2-20) with the convolutions (6.2-25..30), errata fixed.

    Parameters
    ----------
    mass, stiff : array_like
        Shape (n, 3, 3), M and K of (5.4-8).
    x0 : array_like
        Shape (n, 3), initial displacements (u_jk, v_jk, w_jk) (units of L), zero velocities.
    nu : array_like
        Shape (H,), forcing frequencies (units of omega_1).
    Q : array_like
        Shape (n, 3, H) complex: [Q_jk]_1..3 = Re sum_h Q_h e^{i nu_h tau}.
    tau : array_like
        Output times.

    Returns
    -------
    numpy.ndarray
        Shape (n, 3, nt), (U, V, W) in units of L.

    Notes
    -----
    The Laplace solution 6.2-14 is x(s) = adj(M s^2 + K) [Q(s) + s M x0] / Delta(s) with
    Delta = det M prod_m (s^2 + omega_m^2) (6.2-15, E6).  adj(M s^2 + K) is of degree 2 in
    s^2, so the partial fractions are

        x = sum_m adj(K - omega_m^2 M) / (det M D_m) [M x0 cos omega_m tau + I_m[Q]],
        D_m = prod_{i != m} (omega_i^2 - omega_m^2)   (6.2-21),

    the boxed numbers of 6.2-20..24 being the entries of adj(K - omega_m^2 M) M x0 and of
    adj(K - omega_m^2 M); the convolutions I_m are those of 6.2-28..30.  Errata R-5
    (6.2-20: sum over i printed for the sum over m, 1/(A)_d = 1/det M missing).

    References
    ----------
    Tech Memo 104, eqs. (6.2-13)..(6.2-30).
    """
    mass = np.asarray(mass, dtype=float).reshape(-1, 3, 3)
    stiff = np.asarray(stiff, dtype=float).reshape(-1, 3, 3)
    n = mass.shape[0]
    tau = _times(tau)
    nu = np.asarray(nu, dtype=float)
    x0 = np.asarray(x0, dtype=float).reshape(n, 3)
    Q = np.asarray(Q, dtype=complex).reshape(n, 3, -1)
    om2 = np.sort(np.linalg.eigvals(np.linalg.solve(mass, stiff)).real, axis=-1)  # (6.2-16)
    detM = np.linalg.det(mass)
    Mx0 = np.einsum("nij,nj->ni", mass, x0)
    out = np.zeros((n, 3, tau.size))
    for m in range(3):
        others = [i for i in range(3) if i != m]
        D = np.prod(om2[:, others] - om2[:, [m]], axis=1)  # eq. (6.2-21)
        R = _adjugate3(stiff - om2[:, m, None, None] * mass) / (detM * D)[:, None, None]
        w = np.sqrt(om2[:, m])
        cosw = np.cos(w[:, None] * tau)
        RQ = np.einsum("nij,njh->nih", R, Q).reshape(n * 3, -1)
        conv = _convolution(np.repeat(w, 3), nu, RQ, tau).reshape(n, 3, -1)
        out += np.einsum("nij,nj->ni", R, Mx0)[:, :, None] * cosw[:, None, :] + conv  # (6.2-20)
    return out


def _E(y: np.ndarray) -> np.ndarray:
    """(e^{iy} - 1)/(iy), finite at y = 0."""
    return np.sinc(y / np.pi) + 1j * np.sin(y / 2.0) * np.sinc(y / (2.0 * np.pi))


def _kernel(omega: np.ndarray, nu: np.ndarray, tau: np.ndarray) -> np.ndarray:
    """Response of y'' + omega^2 y = e^{i nu tau} from rest, finite for every nu.

    y = tau / (2 i omega) [e^{i omega tau} E(i(nu - omega) tau) - e^{-i omega tau}
    E(i(nu + omega) tau)], E(z) = (e^z - 1)/z: equal to the bracket of 6.2-3 off resonance,
    -i tau e^{i omega tau} / (2 omega) + i sin(omega tau) / (2 omega^2) at nu = omega.
    """
    w = omega[..., None, None]
    v = nu[:, None]
    t = tau[None, :]
    return (t / (2j * w)) * (np.exp(1j * w * t) * _E((v - w) * t)
                             - np.exp(-1j * w * t) * _E((v + w) * t))


def harmonic_response(group: ModalGroup, ex: Excitation, tau: Any,
                      x0: Any = None) -> np.ndarray:
    """Exact response of every mode of a group to the harmonic forcing, safe at resonance.

    Parameters
    ----------
    group : ModalGroup
    ex : Excitation
    tau : array_like
        Output times (>= 0).
    x0 : array_like, optional
        Shape (n, p), initial displacements (units of L), zero velocities.
    Returns
    -------
    numpy.ndarray
        Shape (n, p, nt), units of L.  At an exact resonance the response grows like tau
        (no division by zero).

    Notes
    -----
    Off resonance (|nu| - omega) tau_max >= 1e-2) the bracket of 6.2-3 is summed as one
    matrix product; the few harmonics nearer resonance use the kernel
    tau/(2 i omega) [e^{i omega tau} E(i(nu - omega) tau) - e^{-i omega tau}
    E(i(nu + omega) tau)], E(z) = (e^z - 1)/z, which is finite at nu = +-omega.

    References
    ----------
    Tech Memo 104, eqs. (6.2-3), (6.2-11), (6.2-12), (6.2-20); Meirovitch (1986) ch. 4.
    """
    tau = _times(tau)
    n, p = group.j.size, group.mass.shape[-1]
    x0 = np.zeros((n, p)) if x0 is None else np.asarray(x0, dtype=float).reshape(n, p)
    out = np.zeros((n, p, tau.size))
    if n == 0:
        return out
    omega, Phi, P = modal_basis(group)
    nu, f = forcing_harmonics(group, ex)
    keep = np.any(f != 0.0, axis=(0, 1))
    nu, f = nu[keep], f[..., keep]
    y0 = np.linalg.solve(Phi, x0[..., None])[..., 0]
    g = np.einsum("nij,njh->nih", P, f).reshape(n * p, -1)  # normal-coordinate forcing
    w = omega.reshape(-1)
    wt = np.multiply.outer(w, tau)
    y = y0.reshape(-1, 1) * np.cos(wt)
    if nu.size:
        # off resonance: the bracket of 6.2-3 / 6.2-28, factorised (one matrix product)
        near = np.abs(np.abs(nu)[None, :] - w[:, None]) * max(tau[-1], 1.0) < 1e-2
        coef = np.where(near, 0.0, g / np.where(near, 1.0, w[:, None] ** 2 - nu[None, :] ** 2))
        e_nu = np.exp(1j * np.multiply.outer(nu, tau))
        y = y + np.real(coef @ e_nu - coef.sum(1)[:, None] * np.cos(wt)
                        - 1j * (coef @ nu / w)[:, None] * np.sin(wt))
        for r_, h in zip(*np.nonzero(near), strict=True):  # near resonance: the safe kernel
            y[r_] += np.real(g[r_, h] * _kernel(w[r_:r_ + 1], nu[h:h + 1], tau)[0, 0])
    out = np.einsum("nij,njt->nit", Phi, y.reshape(n, p, -1))
    return out


# --------------------------------------------------------------------------------------------
# Physical displacement fields (5.2-1 with 5.3-4)
# --------------------------------------------------------------------------------------------
def _axial_shape(p: ShellParameters, d: int, j: np.ndarray, xi: np.ndarray, kind: str,
                 phase: str, order: int) -> np.ndarray:
    """order-th xi-derivative of cos s (kind "cos") or sin s ("sin") of modes j at xi."""
    j = np.asarray(j)
    alpha = j * np.pi * p.L / (2.0 * p.half_length(d))
    s = (_edge_argument(p, d, j, phase)[:, None]
         + alpha[:, None] * (xi - p.edges(d)[0])[None, :])  # 5.3-2/3
    shift = order * np.pi / 2.0
    base = np.cos(s + shift) if kind == "cos" else np.sin(s + shift)
    return alpha[:, None] ** order * base


def _mask(p: ShellParameters, d: int, xi: np.ndarray, side: str) -> np.ndarray:
    """G_d(xi) of 5.3-2a / 5.3-3a; the junction xi = c belongs to cylinder ``side``."""
    a, c, b = p.a, p.c, p.b
    if d == 1:
        return (xi >= a) & ((xi < c) | ((xi == c) & (side == "aft")))
    return (xi <= b) & ((xi > c) | ((xi == c) & (side != "aft")))


def displacement_fields(result: SimulationResult, xi: Any, theta: Any,
                        instants: Any = None, order: int = 0, part: str = "total",
                        junction: str = "forward") -> tuple[np.ndarray, ...]:
    """u, v, w (xi_bar, theta, tau) in metres from the modal sums (5.2-1) and the beam part (5.3-4).

    Parameters
    ----------
    result : SimulationResult
        From :func:`simulate`.
    xi : array_like
        Shape (nx,), axial coordinates xi_bar = (x - x_cm)/L in [a, b].
    theta : array_like
        Shape (nq,), circumferential angles (rad).
    instants : array_like of int, optional
        Indices into ``result.tau`` (default all).
    order : int
        Derivative order 0..4 with respect to xi_bar (metres per unit xi_bar^order).
    part : {"total", "shell", "beam"}
        The modal sums, the beam part u*, v*, w*, or both.
    junction : {"forward", "aft"}
        Which cylinder's modes the junction xi = c takes (the fields jump there).

    Returns
    -------
    u, v, w : numpy.ndarray
        Shape (nx, nq, ni), metres (axial, circumferential, radial inward, memo 3.0).

    References
    ----------
    Tech Memo 104, eqs. (4.1-3)..(4.1-7), (5.2-1), (5.3-2)..(5.3-4).
    """
    p = result.params
    xi = np.atleast_1d(np.asarray(xi, dtype=float))
    theta = np.atleast_1d(np.asarray(theta, dtype=float))
    if np.any(xi < p.a - 1e-12) or np.any(xi > p.b + 1e-12):
        raise ValueError(f"xi: must lie in [a, b] = [{p.a}, {p.b}]")
    order = count("order", order, 0, 4)
    if part not in ("total", "shell", "beam"):
        raise ValueError(f"part = {part!r}: must be 'total', 'shell' or 'beam'")
    idx = np.arange(result.tau.size) if instants is None else np.atleast_1d(instants)
    shape = (xi.size, theta.size, idx.size)
    u, v, w = np.zeros(shape), np.zeros(shape), np.zeros(shape)
    if part in ("total", "shell"):
        amp = result.amplitude[:, idx]
        for d in (1, 2):
            inside = _mask(p, d, xi, "aft" if junction == "aft" else "forward")
            for comp, target in (("U", u), ("V", v), ("W", w)):
                sel = (result.cylinder == d) & (result.component == comp)
                if not sel.any():
                    continue
                j, k = result.j[sel], result.k[sel]
                kind = "cos" if comp == "U" else "sin"
                ax = _axial_shape(p, d, np.maximum(j, 1), xi, kind, result.phase, order)
                ax = np.where((j == 0)[:, None], float(order == 0), ax)  # U_0k: cos k theta
                ax = ax * inside[None, :]
                circ = np.sin(np.multiply.outer(k, theta)) if comp == "V" else \
                    np.cos(np.multiply.outer(k, theta))
                target += np.einsum("mx,mq,mt->xqt", ax, circ, amp[sel])  # eq. (5.2-1)
    if part in ("total", "beam"):
        ex = result.excitation
        tau = result.tau[idx]
        bs = _beam_shapes(p, xi, ex.N)
        key = ("g", "g1", "g2", "g3", "g4")[order]
        g = bs[key].T @ ex.beam(tau)  # g* and its derivatives (4.1-3..7), (nx, ni)
        Xi = (xi - 0.5 * (xi - p.b + 1.0) ** 2, p.b - xi, -np.ones_like(xi),
              np.zeros_like(xi), np.zeros_like(xi))[order]
        ustar = -0.5 * ex.strain * np.outer(Xi, ex.thrust(tau))  # eq. (5.3-4a)
        u += ustar[:, None, :]
        v += g[:, None, :] * np.sin(theta)[None, :, None]  # eq. (5.3-4b)
        w += g[:, None, :] * np.cos(theta)[None, :, None]  # eq. (5.3-4c)
    return u * p.L, v * p.L, w * p.L


def edge_conditions(result: SimulationResult, n_theta: int = 24) -> dict[str, float]:
    """How well the rebuilt fields meet the edge conditions (5.3-1) at the ends and junction.

    Parameters
    ----------
    result : SimulationResult
    n_theta : int
        Angles at which the conditions are sampled.

    Returns
    -------
    dict of str to float
        Largest values over the instants and angles (metres unless said):

        * ``shell_v_edges``, ``shell_w_edges``: v, w of the modal sums at xi = a, c (both
          sides), b (zero by the shape functions: shear diaphragm);
        * ``shell_u_xi_edges`` (m per unit xi), ``shell_w_xixi_edges`` (m per unit xi^2):
          u' and w'' of the modal sums there (zero in the zero phase);
        * ``scale``: largest |u|, |v|, |w| over the cylinders;
        * ``v_xi_ends``, ``w_xi_ends``: v', w' of the total field at a and b (5.3-1a, b: the
          shape functions do not make them vanish, erratum S-531 of the shell errata);
        * ``N_aft_error``, ``N_nose``: N_xixi / (T0 T(tau)) + 1 at a and N_xixi / T0 at b
          (5.3-1d, e; Donnell N_x = E h/(1 - nu^2) [u_x + nu (v_theta - w)/R], compression
          negative);
        * ``M_shell_ends``: the modal sums' share of M_xixi / D (w_xx + nu w_thth/R^2, m^-1)
          at a and b (5.3-1c); ``M_beam_ends``: the beam part's, which is nu g* cos theta / R^2
          in magnitude (the free-free modes have g*'' = 0 at the ends, but w* = g* cos theta
          bends the section).

    Theta derivatives are spectral (FFT on n_theta >= 2 max k + 8 points).

    References
    ----------
    Tech Memo 104, eqs. (5.3-1)..(5.3-4); Leissa, NASA SP-288 (1973), eq. (1.3) (Donnell
    stress resultants).
    """
    p = result.params
    kmax = int(result.k.max()) if result.k.size else 1
    n_theta = max(count("n_theta", n_theta, 4, 4096), 2 * kmax + 8)
    th = np.linspace(0.0, 2.0 * np.pi, n_theta, endpoint=False)
    out: dict[str, float] = {}

    def fld(xi: float, order: int, part: str, junction: str = "forward") -> tuple:
        return displacement_fields(result, [xi], th, None, order, part, junction)

    edges = [(p.a, "forward"), (p.c, "aft"), (p.c, "forward"), (p.b, "forward")]
    out["shell_v_edges"] = max(np.abs(fld(x, 0, "shell", s)[1]).max() for x, s in edges)
    out["shell_w_edges"] = max(np.abs(fld(x, 0, "shell", s)[2]).max() for x, s in edges)
    out["shell_u_xi_edges"] = max(np.abs(fld(x, 1, "shell", s)[0]).max() for x, s in edges)
    out["shell_w_xixi_edges"] = max(np.abs(fld(x, 2, "shell", s)[2]).max() for x, s in edges)
    grid = np.linspace(p.a, p.b, 201)
    uu, vv, ww = displacement_fields(result, grid, th)
    out["scale"] = float(max(np.abs(uu).max(), np.abs(vv).max(), np.abs(ww).max()))
    out["v_xi_ends"] = max(np.abs(fld(x, 1, "total")[1]).max() for x in (p.a, p.b))
    out["w_xi_ends"] = max(np.abs(fld(x, 1, "total")[2]).max() for x in (p.a, p.b))
    L = p.L
    T = result.excitation.thrust(result.tau)
    Eh_1nu2 = result.T0 / result.excitation.strain  # E h / (1 - nu^2), N/m
    N_err, N_nose, M_sh, M_bm = 0.0, 0.0, 0.0, 0.0
    for x, R in ((p.a, result.radii[0]), (p.b, result.radii[1])):
        u1 = fld(x, 1, "total")[0] / L  # u_x (dimensionless)
        v, w = fld(x, 0, "total")[1:]
        vt = _dtheta(v, 1)  # v_theta (spectral: exact for k < n_theta / 2)
        Nx = Eh_1nu2 * (u1 + result.params.nu * (vt - w) / R)  # Donnell N_x
        if x == p.a:
            N_err = float(np.abs(Nx / (result.T0 * T[None, None, :]) + 1.0).max())
        else:
            N_nose = float(np.abs(Nx / result.T0).max())
        for part in ("shell", "beam"):
            w0 = fld(x, 0, part)[2]
            w2 = fld(x, 2, part)[2] / L**2
            wtt = _dtheta(w0, 2)
            m = np.abs(w2 + result.params.nu * wtt / R**2).max()  # w_xx + nu w_thth / R^2
            if part == "shell":
                M_sh = max(M_sh, float(m))
            else:
                M_bm = max(M_bm, float(m))
    out.update(N_aft_error=N_err, N_nose=N_nose, M_shell_ends=M_sh, M_beam_ends=M_bm)
    return {k: float(v) for k, v in out.items()}


def _dtheta(f: np.ndarray, order: int) -> np.ndarray:
    """order-th theta-derivative of samples on a uniform periodic grid (axis 1), by FFT."""
    n = f.shape[1]
    k = np.fft.fftfreq(n, 1.0 / n)
    shape = [1] * f.ndim
    shape[1] = n
    return np.real(np.fft.ifft((1j * k.reshape(shape)) ** order * np.fft.fft(f, axis=1), axis=1))


# --------------------------------------------------------------------------------------------
# Pipeline: simulate
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class SimulationResult:
    """Modal time histories of the two shells at one thrust frequency (memo 6.2).

    Attributes
    ----------
    Omega : float
        Thrust pulsation frequency (rad/s).
    omega_1 : float
        Reference frequency (rad/s); tau = omega_1 t.
    tau : numpy.ndarray
        Shape (nt,), dimensionless times.
    t : numpy.ndarray
        Shape (nt,), times (s).
    psi : numpy.ndarray
        Shape (nt,), rigid-body pitch angle (rad), eq. (4.2-6).
    q : numpy.ndarray
        Shape (N + 1, nt), beam coordinates q_1..q_N, q_B (units of L), eqs. (4.1-10/11).
    cylinder, j, k : numpy.ndarray of int
        Shape (nc,), the modal coordinates kept (forced or given an initial displacement).
    component : numpy.ndarray of str
        Shape (nc,), "U", "V" or "W".
    amplitude : numpy.ndarray
        Shape (nc, nt), U_jk, V_jk, W_jk (units of L).
    params : ShellParameters
        The shells' dimensionless parameters.
    excitation : Excitation
        The forcing time functions.
    phase : str
        Shape-function phase.
    method : str
        How the responses were computed.
    T0 : float
        Steady thrust per unit circumference (N/m).
    radii : tuple of float
        R1, R2 (m).
    snapshots : dict
        ``xi`` (nx,), ``theta`` (nq,), ``index`` (ns,), ``u``, ``v``, ``w`` (ns, nx, nq) in
        metres: the deformed booster at chosen instants.
    warnings : tuple of str
    """

    Omega: float
    omega_1: float
    tau: np.ndarray
    t: np.ndarray
    psi: np.ndarray
    q: np.ndarray
    cylinder: np.ndarray
    j: np.ndarray
    k: np.ndarray
    component: np.ndarray
    amplitude: np.ndarray
    params: ShellParameters
    excitation: Excitation
    phase: str
    method: str
    T0: float
    radii: tuple[float, float]
    snapshots: dict = field(default_factory=dict, repr=False)
    warnings: tuple[str, ...] = field(default_factory=tuple)

    def labels(self) -> list[str]:
        """Column names of the modal coordinates, e.g. ``W_d1_j2_k0``."""
        return [f"{c}_d{d}_j{j}_k{k}" for c, d, j, k in
                zip(self.component, self.cylinder, self.j, self.k, strict=True)]

    def to_rows(self) -> list[dict]:
        """One mapping per time (the CSV): tau, t_s, psi_rad, q_1..q_B, modal amplitudes."""
        names = self.labels()
        qn = [f"q_{n + 1}" for n in range(self.q.shape[0] - 1)] + ["q_B"]
        rows = []
        for i in range(self.tau.size):
            row = {"tau": float(self.tau[i]), "t_s": float(self.t[i]),
                   "psi_rad": float(self.psi[i])}
            row.update({n: float(self.q[b, i]) for b, n in enumerate(qn)})
            row.update({n: float(self.amplitude[c, i]) for c, n in enumerate(names)})
            rows.append(row)
        return rows

    def max_displacement(self) -> dict[str, float]:
        """Largest |u|, |v|, |w| over the snapshots (m)."""
        s = self.snapshots
        return {c: float(np.abs(s[c]).max()) if c in s and np.size(s[c]) else 0.0
                for c in ("u", "v", "w")}

    def to_dict(self) -> dict:
        """JSON-ready mapping (plain lists and floats, no NaN)."""
        s = self.snapshots
        return {
            "Omega": float(self.Omega), "Omega_hz": float(self.Omega / (2 * np.pi)),
            "omega_1": float(self.omega_1), "Omega_bar": float(self.excitation.Omega_bar),
            "beta": float(self.excitation.beta), "alpha": float(self.excitation.alpha.real),
            "phase": self.phase, "method": self.method,
            "tau": self.tau.tolist(), "t": self.t.tolist(), "psi": self.psi.tolist(),
            "q": self.q.tolist(),
            "modes": {"label": self.labels(), "cylinder": self.cylinder.tolist(),
                      "j": self.j.tolist(), "k": self.k.tolist(),
                      "component": self.component.tolist()},
            "amplitude": self.amplitude.tolist(),
            "snapshots": {key: np.asarray(s[key]).tolist() for key in s},
            "max_displacement_m": self.max_displacement(),
            "params": self.params.to_dict(),
            "warnings": list(self.warnings),
        }


def simulate(case: Any, Omega: float, tau_max: float, n_out: int = 401,
             modes: tuple[int, int, int, int] | None = None, psi0: float = 0.01,
             beam_amplitude: float = 1e-4, beam_mode: int = 1, initial: dict | None = None,
             method: str = "closed-form", n_snapshots: int = 4, n_xi: int = 61,
             n_theta: int = 49, phase: str = "zero") -> SimulationResult:
    """Time histories of every forced shell mode at the thrust frequency Omega (pipeline entry).

    Parameters
    ----------
    case : Case-like
        See :func:`case_parameters`; ``truncation.M1, N1, M2, N2, N, S`` are used.
    Omega : float
        Thrust pulsation frequency (rad/s), > 0.
    tau_max : float
        Last time tau = omega_1 t (dimensionless), > 0, at most 1e6.
    n_out : int
        Output times, uniform on [0, tau_max], 2..100000.
    modes : (M1, N1, M2, N2), optional
        Override the case's shell truncation (1..500 each).
    psi0 : float
        Initial pitch angle (rad).
    beam_amplitude : float
        Norm of the beam Floquet vector (units of L); 0 switches the beam off.
    beam_mode : int
        Beam exponent alpha_r that moves the beam (r = 1..N + 1).
    initial : dict, optional
        Initial displacements {(cylinder, j, k, component): value (units of L)}.
    method : {"closed-form", "duhamel", "DOP853", "Radau"}
        ``"closed-form"``: :func:`harmonic_response` (exact for the linearised forcing, finite
        at resonance, any tau); the others: :func:`integrate`.
    n_snapshots : int
        Instants (evenly spread over the output) at which the fields are rebuilt, 0..50.
    n_xi, n_theta : int
        Grid of the snapshots, 2..2001.
    phase : {"zero", "printed"}
        Shape-function phase (E10).

    Returns
    -------
    SimulationResult

    Raises
    ------
    ValueError
        Bad input (named), or a pitch motion that is not bounded at Omega.

    References
    ----------
    Tech Memo 104, sections 4, 5, 6 (eqs. 4.1-10/11, 4.2-6, 5.2-1, 5.3-4, 6.1-1..4, 6.2).
    """
    Omega = positive("Omega", Omega)
    tau_max = positive("tau_max", tau_max)
    if tau_max > 1e6:
        raise ValueError(f"tau_max = {tau_max!r}: must be <= 1e6")
    n_out = count("n_out", n_out, 2, 100_000)
    n_snapshots = count("n_snapshots", n_snapshots, 0, 50)
    n_xi = count("n_xi", n_xi, 2, 2001)
    n_theta = count("n_theta", n_theta, 2, 2001)
    if method not in ("closed-form", "duhamel", "DOP853", "Radau"):
        raise ValueError(f"method = {method!r}: must be 'closed-form', 'duhamel', 'DOP853' "
                         "or 'Radau'")
    tr = case.truncation
    M1, N1, M2, N2 = (tr.M1, tr.N1, tr.M2, tr.N2) if modes is None else modes
    cp = case_parameters(case)
    ex = make_excitation(case, Omega, psi0, beam_amplitude, beam_mode)
    groups = modal_groups(cp["shell"], (M1, M2), (N1, N2), ex.N, phase)
    tau = np.linspace(0.0, tau_max, n_out)
    initial = {} if initial is None else dict(initial)
    rows_c, rows_j, rows_k, rows_comp, amps = [], [], [], [], []
    used = set()
    for g in groups:
        x0 = np.zeros((len(g), g.mass.shape[-1]))
        for (d, jj, kk, comp), value in initial.items():
            if d == g.cylinder and comp in g.components:
                hit = np.flatnonzero((g.j == jj) & (g.k == kk))
                if hit.size:
                    x0[hit[0], g.components.index(comp)] = finite("initial", value)
                    used.add((d, jj, kk, comp))
        keep = g.forced() | np.any(x0 != 0.0, axis=1)
        if not keep.any():
            continue
        sub = g.select(keep)
        if method == "closed-form":
            x = harmonic_response(sub, ex, tau, x0[keep])
        else:
            x = integrate(sub, ex, tau, x0[keep], method=method)
        for c, comp in enumerate(g.components):
            rows_c.append(np.full(len(sub), g.cylinder))
            rows_j.append(sub.j)
            rows_k.append(sub.k)
            rows_comp.append(np.full(len(sub), comp))
            amps.append(x[:, c, :])
    unknown = set(initial) - used
    if unknown:
        raise ValueError(f"initial: no such modal coordinate {sorted(unknown)[0]!r} "
                         "(cylinder, j, k, component)")
    amplitude = np.concatenate(amps) if amps else np.zeros((0, tau.size))

    def cat(lst: list, dt: Any) -> np.ndarray:
        return np.concatenate(lst).astype(dt) if lst else np.zeros(0, dtype=dt)

    res = SimulationResult(
        Omega=Omega, omega_1=cp["omega_1"], tau=tau, t=tau / cp["omega_1"], psi=ex.psi(tau),
        q=ex.beam(tau), cylinder=cat(rows_c, int), j=cat(rows_j, int), k=cat(rows_k, int),
        component=cat(rows_comp, str), amplitude=amplitude, params=cp["shell"], excitation=ex,
        phase=phase, method=method, T0=cp["T0"], radii=cp["radii"], warnings=ex.warnings)
    if not np.all(np.isfinite(res.amplitude)):
        raise ValueError("simulate: non-finite response (report this case)")
    if n_snapshots:
        idx = np.unique(np.linspace(0, tau.size - 1, n_snapshots).round().astype(int))
        p = cp["shell"]
        xi = np.linspace(p.a, p.b, n_xi)
        th = np.linspace(0.0, 2.0 * np.pi, n_theta)
        u, v, w = displacement_fields(res, xi, th, idx)
        snaps = {"xi": xi, "theta": th, "index": idx, "tau": tau[idx],
                 "u": np.moveaxis(u, 2, 0), "v": np.moveaxis(v, 2, 0), "w": np.moveaxis(w, 2, 0)}
        object.__setattr__(res, "snapshots", snaps)
    return res


# --------------------------------------------------------------------------------------------
# Issue 6 item 4: secular growth at a root
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class SecularGrowth:
    """Growth of one normal coordinate of one shell mode under the forcing at Omega.

    Attributes
    ----------
    Omega : float
        Thrust frequency (rad/s).
    cylinder, j, k, branch : int
        The shell mode and its branch m (ascending frequency).
    omega_bar : float
        Its natural frequency (units of omega_1).
    tau_max : float
        Length of the simulation (tau units).
    slope : float
        |least-squares slope| of Z(tau) = (y' + i omega y) e^{-i omega tau} against tau, from
        the integration, weighted by sin^4(pi tau / tau_max): the resonant forcing amplitude.
        A harmonic detuned by Delta leaks into it like (Delta tau_max)^-5, so a bounded
        motion gives a slope near 0 and a weak secular term is measured under a large
        bounded response.
    predicted_slope : float
        The same from the harmonic decomposition of the forcing: |sum of the amplitudes at
        nu = +-omega| / 2 (0 off resonance).
    growth_rate : float
        slope / omega: growth of the amplitude of y per unit tau (like tau at a root).
    index : float
        slope tau_max / max |Z - Z(0)|: about 1 for secular growth, << 1 for a bounded
        response (about 1/(detuning tau_max)).
    envelope_ratio : float
        max |y| over the last quarter / max |y| over the first quarter of [0, tau_max] (about
        4 / 1 for growth like tau, about 1 bounded).
    amplitude : float
        max |y| over [0, tau_max] (units of L).
    """

    Omega: float
    cylinder: int
    j: int
    k: int
    branch: int
    omega_bar: float
    tau_max: float
    slope: float
    predicted_slope: float
    growth_rate: float
    index: float
    envelope_ratio: float
    amplitude: float

    def to_dict(self) -> dict:
        """JSON-ready mapping."""
        return {k: (float(v) if isinstance(v, float) else int(v))
                for k, v in self.__dict__.items()}


def secular_growth(case: Any, Omega: float, cylinder: int, j: int, k: int, branch: int,
                   tau_max: float, n_out: int = 2001, psi0: float = 0.01,
                   beam_amplitude: float = 1e-4, beam_mode: int = 1, N: int | None = None,
                   S: int | None = None, phase: str = "zero",
                   resonance_tol: float = 1e-8) -> SecularGrowth:
    """Integrate one shell mode's forced modal ODE at Omega and measure its secular growth.

    Parameters
    ----------
    case : Case-like
        See :func:`case_parameters`.
    Omega : float
        Thrust frequency (rad/s), e.g. a root of the stability table.
    cylinder, j, k, branch : int
        The shell mode (j = 0: U_0k, branch 1; k = 0: branches 1, 2; else 1..3).
    tau_max : float
        Length of the integration (tau units), > 0.
    n_out : int
        Output points for the fits, 16..200000.
    psi0, beam_amplitude, beam_mode, N, S :
        As :func:`make_excitation`.
    phase : {"zero", "printed"}
        Shape-function phase.
    resonance_tol : float
        |nu -+ omega| / omega below which a forcing harmonic counts as resonant for
        ``predicted_slope``.

    Returns
    -------
    SecularGrowth

    Notes
    -----
    The mode's system M x'' + K x = F(tau) is integrated with the ``"duhamel"`` method of
    :func:`integrate` (forcing evaluated in the time domain), and its normal coordinate y of
    the chosen branch obeys y'' + omega^2 y = f(tau), so Z' = f e^{-i omega tau}: a forcing
    harmonic at nu = omega makes Z drift linearly (y grows like tau), every other harmonic
    leaves Z bounded.

    References
    ----------
    Tech Memo 104, section 7.1 (vanishing denominators = unbounded displacements); Bolotin
    (1964) ch. 1; reading guide section 5.
    """
    tau_max = positive("tau_max", tau_max)
    n_out = count("n_out", n_out, 16, 200_000)
    g, ex, branch = _single_mode(case, Omega, cylinder, j, k, branch, psi0, beam_amplitude,
                                 beam_mode, N, S, phase)
    d = g.cylinder
    tau = np.linspace(0.0, tau_max, n_out)
    _, Z = integrate(g, ex, tau, method="duhamel", return_normal=True)
    omega = modal_basis(g)[0]
    w = float(omega[0, branch - 1])
    z = Z[0, branch - 1]
    wgt = np.sin(np.pi * tau / tau_max) ** 4  # smooth window: leakage ~ (detuning tau_max)^-5
    tc = tau - np.sum(wgt * tau) / np.sum(wgt)
    slope = complex(np.sum(wgt * tc * z) / np.sum(wgt * tc**2))  # weighted least squares
    nu, gh, _ = modal_forcing_spectrum(case, Omega, cylinder, j, k, branch, psi0,
                                       beam_amplitude, beam_mode, N, S, phase)
    res_p = np.abs(nu - w) <= resonance_tol * w
    res_m = np.abs(nu + w) <= resonance_tol * w
    predicted = abs(0.5 * gh[res_p].sum() + 0.5 * np.conj(gh[res_m]).sum())
    y = np.imag(z * np.exp(1j * w * tau)) / w
    q = max(1, n_out // 4)
    early = float(np.abs(y[:q]).max())
    late = float(np.abs(y[-q:]).max())
    spread = float(np.abs(z - z[0]).max())
    return SecularGrowth(
        Omega=float(Omega), cylinder=d, j=j, k=k, branch=branch, omega_bar=w,
        tau_max=tau_max, slope=abs(slope), predicted_slope=float(predicted),
        growth_rate=abs(slope) / w, index=abs(slope) * tau_max / spread if spread > 0 else 0.0,
        envelope_ratio=late / early if early > 0 else 0.0, amplitude=float(np.abs(y).max()))


def _single_mode(case: Any, Omega: float, cylinder: int, j: int, k: int, branch: int,
                 psi0: float, beam_amplitude: float, beam_mode: int, N: int | None,
                 S: int | None, phase: str) -> tuple[ModalGroup, Excitation, int]:
    d = count("cylinder", cylinder, 1, 2)
    j = count("j", j, 0)
    k = count("k", k, 0)
    if j == 0 and k == 0:
        raise ValueError("j = k = 0: the rigid mode U_00 has no frequency (6.2.1)")
    cp = case_parameters(case)
    ex = make_excitation(case, Omega, psi0, beam_amplitude, beam_mode, N, S)
    kind = "0k" if j == 0 else ("j0" if k == 0 else "jk")
    groups = _cylinder_groups(cp["shell"], d, max(j, 1), max(k, 1), ex.N, phase)
    g = [x for x in groups if x.kind == kind][0]
    g = g.select(np.flatnonzero((g.j == j) & (g.k == k)))
    branch = count("branch", branch, 1, g.mass.shape[-1])
    return g, ex, branch


def modal_forcing_spectrum(case: Any, Omega: float, cylinder: int, j: int, k: int,
                           branch: int, psi0: float = 0.01, beam_amplitude: float = 1e-4,
                           beam_mode: int = 1, N: int | None = None, S: int | None = None,
                           phase: str = "zero") -> tuple[np.ndarray, np.ndarray, float]:
    """Harmonics of the forcing of one normal coordinate: f(tau) = Re sum_h g_h e^{i nu_h tau}.

    Parameters
    ----------
    case, Omega, cylinder, j, k, branch, psi0, beam_amplitude, beam_mode, N, S, phase :
        As :func:`secular_growth`.

    Returns
    -------
    nu : numpy.ndarray
        Shape (H,), frequencies (units of omega_1).
    g : numpy.ndarray
        Shape (H,) complex, amplitudes (y'' + omega^2 y = f, units of L omega_1^2).
    omega : float
        The natural frequency of the branch (units of omega_1).

    References
    ----------
    Tech Memo 104, section 7.1; eqs. (6.2-3), (6.2-11), (6.2-12), (6.2-28..30).
    """
    g, ex, branch = _single_mode(case, Omega, cylinder, j, k, branch, psi0, beam_amplitude,
                                 beam_mode, N, S, phase)
    omega, _, P = modal_basis(g)
    nu, f = forcing_harmonics(g, ex)
    gh = np.einsum("ij,jh->ih", P[0], f[0])[branch - 1]
    return nu, gh, float(omega[0, branch - 1])


def secular_rates(case: Any, rows: list[dict], psi0: float = 0.01,
                  beam_amplitude: float = 1e-4, N: int | None = None, S: int | None = None,
                  phase: str = "zero") -> list[dict]:
    """Resonant forcing of the shell mode at every root of a stability table.

    Parameters
    ----------
    case : Case-like
        See :func:`case_parameters`.
    rows : list of dict
        :meth:`flexbooster.stability.StabilityTable.to_rows` (keys ``Omega_rad_s``,
        ``cylinder``, ``j``, ``k``, ``branch``, ``r``).
    psi0 : float
        Initial pitch angle (rad) of the rigid-body forcing.
    beam_amplitude : float
        Norm of the beam Floquet vector (units of L).
    N, S : int, optional
        Beam modes and harmonics (default: the case's truncation).
    phase : {"zero", "printed"}
        Shape-function phase.

    Returns
    -------
    list of dict
        Per row: ``secular_rate`` (growth of the normal coordinate's amplitude per unit tau,
        units of L: |resonant forcing| / (2 omega)), ``relative`` (resonant forcing over the
        largest forcing harmonic of all the rows' modes: about 1e-19, round-off, where the
        projection is a structural zero; above 1e-15 for genuine but weak terms such as
        q^2 A_1 A_3 or high Floquet harmonics) and ``forced`` (relative > 1e-18).

    Notes
    -----
    The stability table's "active" flag follows the Kronecker deltas of section 6 only.  The
    projections add selection rules of their own: in the zero phase int cos s = 0 for every
    j >= 1 (the thrust term of F1 and u*'' do not reach U_j0) and int sin s = 0 for even j
    (the psi'^2 terms of F2, F3 and the K T psi terms do not reach even j).  This function
    measures the resonant forcing itself, with the beam exponents of all roots from one
    batched Hill computation.

    References
    ----------
    Tech Memo 104, sections 6.2, 7.1; reading guide section 5.
    """
    cp = case_parameters(case)
    N = count("N", case.truncation.N if N is None else N, 0)
    S = count("S", case.truncation.S if S is None else S, 0)
    if not rows:
        return []
    Om = np.array([float(x["Omega_rad_s"]) for x in rows])
    pre = None
    if beam_amplitude != 0.0:
        hill, nat = _beam_exponents(cp, Om / cp["omega_1"], N, S)
    groups_cache: dict[tuple, ModalGroup] = {}
    out = []
    for n, x in enumerate(rows):
        if beam_amplitude != 0.0:
            pre = (hill.alpha[n], hill.C[n], nat[n])
        ex = _make_excitation(cp, Om[n], psi0, beam_amplitude, max(int(x.get("r", 0)), 1), N,
                              S, "floquet", pre)
        d, j, k, m = (int(x[key]) for key in ("cylinder", "j", "k", "branch"))
        kind = "0k" if j == 0 else ("j0" if k == 0 else "jk")
        key = (d, j, k)
        if key not in groups_cache:
            groups = _cylinder_groups(cp["shell"], d, max(j, 1), max(k, 1), N, phase)
            g = [y for y in groups if y.kind == kind][0]
            groups_cache[key] = g.select(np.flatnonzero((g.j == j) & (g.k == k)))
        g = groups_cache[key]
        omega, _, P = modal_basis(g)
        nu, f = forcing_harmonics(g, ex)
        gh = np.einsum("ij,jh->ih", P[0], f[0])[m - 1]
        w = float(omega[0, m - 1])
        res = np.abs(np.abs(nu) - w) <= 1e-8 * w
        amp = abs(0.5 * gh[res & (nu > 0)].sum() + 0.5 * np.conj(gh[res & (nu < 0)]).sum())
        out.append({"secular_rate": amp / w, "amplitude": amp,
                    "scale": float(np.abs(gh).max()) if gh.size else 0.0})
    top = max(max(y["scale"] for y in out), 1e-300)
    for y in out:
        y["relative"] = y.pop("amplitude") / top
        y.pop("scale")
        y["forced"] = bool(y["relative"] > 1e-18)
    return out
