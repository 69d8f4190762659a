"""Severity of the unstable thrust frequencies: secular growth rate of every root (memo 7.1).

At a root one forcing harmonic of a shell mode has the mode's frequency, so its normal
coordinate grows like (|G| / (2 omega)) tau sin(omega tau + phi), G the sum of the resonant
harmonics g_h (6.2). The severity is that rate at the shell surface, |G| / (2 omega) L omega_1
max_c |Phi_c| (m/s), with the forcing of the thrust (4.2-1a, 5.3-4a), the pitch motion
(4.2-6, 4.2-7) and the beam Floquet solution (4.1-10..12, Fourier vectors by a matrix
continued fraction). The roots then merge into bands. Theory: docs/theory/severity.md.

References: Tech Memo 104, sec. 4.1, 4.2, 5.3, 5.4, 6.1, 6.2, 7.1, 7.3; V. V. Bolotin, *The
Dynamic Stability of Elastic Systems*, 1964, ch. 1; H. Risken, *The Fokker-Planck Equation*,
1989, sec. 9.3 (matrix continued fractions).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from ..bands import Band, BandMode
from ..checks import choice, finite, nonnegative, positive
from .beam_action import beam_system
from .model import BoosterModel
from .pitch import mathieu_parameters
from .responses.excitation import N_BASIS, ExcitationParameters
from .responses.modal import cylinder_groups, modal_basis
from .stability import StabilityTable

__all__ = [
    "FAMILY_CAUSES",
    "DEFAULT_THRESHOLD",
    "DEFAULT_RESOLUTION",
    "RootSeverity",
    "shell_mode",
    "SeverityResult",
    "root_severity",
    "floquet_vectors",
    "resonance_bands",
    "with_severity",
    "severity_analysis",
]

#: The forcing behind each family, in words (memo 6.2, 7.3).
FAMILY_CAUSES: dict[int, str] = {
    1: "rigid-body pitch acceleration psi'' at Omega_i (k = 1)",
    2: "beam bending harmonic (alpha_r + s) Omega of the Floquet motion (k = 1)",
    3: "thrust pulsation gamma T0 cos(Omega t) at the aft edge (via u*: axial inertia, Poisson)",
    4: "centrifugal pitch-rate term psi'^2 at 2 Omega_i (k = 0)",
    5: "centrifugal pitch-rate term psi'^2 at Omega_i + Omega_p (k = 0)",
    6: "centrifugal pitch-rate term psi'^2 at Omega_i - Omega_p (k = 0)",
    7: "rigid-body pitch psi'' and gimbal side force K T0 psi at Omega_i (k = 1)",
    8: "pulsating gimbal side force gamma K T0 psi at Omega + Omega_i (k = 1)",
    9: "pulsating gimbal side force gamma K T0 psi at Omega - Omega_i (k = 1)",
    10: "centrifugal pitch-rate term psi'^2 at Omega_i + Omega_p (k = 2)",
    11: "centrifugal pitch-rate term psi'^2 at Omega_i - Omega_p (k = 2)",
    12: "centrifugal pitch-rate term psi'^2 at 2 Omega_i (k = 2)",
    13: "beam bending harmonic (alpha_r + s) Omega of the Floquet motion (k = 1)",
}
#: Default threshold of ``severity_rel`` above which a root counts as active.
DEFAULT_THRESHOLD = 1e-6
#: Default relative resolution in Omega within which roots merge into one band.
DEFAULT_RESOLUTION = 0.005
_COMPONENTS = ("axial", "torsional", "radial")  # dominant U, V, W (as memo.shell.MODE_TYPES)
_RES_TOL = 1e-8  # |nu| = omega to this relative tolerance counts as resonant
_CHUNK = 256  # points per batch of floquet_vectors (small batches stay in cache)


@dataclass(frozen=True)
class RootSeverity:
    """Secular growth of the resonant shell mode at every root of a stability table.

    Attributes
    ----------
    severity, severity_rel : numpy.ndarray
        Shape (n,), growth rate of the mode's largest surface displacement (m/s), and over the
        table's largest.
    rate : numpy.ndarray
        Shape (n,), |G| / (2 omega): growth of the normal coordinate per unit tau (units of L).
    mode_type : tuple of str
        Per root, "axial", "torsional" or "radial": the dominant component of the mode.
    psi0, beam_amplitude : float
        Reference initial pitch angle (rad) and norm of the beam Floquet vector (units of L).
    threshold : float
        severity_rel at and above which a root is active.
    """

    severity: np.ndarray
    severity_rel: np.ndarray
    rate: np.ndarray
    mode_type: tuple[str, ...]
    psi0: float
    beam_amplitude: float
    threshold: float

    def __len__(self) -> int:
        return int(self.severity.size)

    @property
    def active(self) -> np.ndarray:
        """Boolean mask: severity_rel >= threshold."""
        return self.severity_rel >= self.threshold

    def to_dict(self) -> dict:
        """JSON-ready: the reference amplitudes and threshold (the columns are in the table)."""
        return {
            "psi0": float(self.psi0),
            "beam_amplitude": float(self.beam_amplitude),
            "threshold": float(self.threshold),
            "max_severity": float(self.severity.max()) if self.severity.size else 0.0,
            "active": int(self.active.sum()),
        }


def _pitch_amplitudes(Omega: np.ndarray, beta: np.ndarray, omega_psi: float, gamma: float,
                      psi0: float) -> np.ndarray:
    """A_1, A_2, A_3 of psi (4.2-7b..d), shape (n, 3), for psi(0) = psi0."""
    a, q = mathieu_parameters(Omega, omega_psi, gamma)  # (4.2-4)
    den1, den3 = a - (beta - 2.0) ** 2, a - (2.0 + beta) ** 2
    A2 = psi0 / (1.0 + q * (1.0 / den3 + 1.0 / den1))  # eq. (4.2-7c)
    return np.stack([A2 * q / den1, A2, A2 * q / den3], axis=-1)  # eqs. (4.2-7b, d)


def floquet_vectors(A0: np.ndarray, B: np.ndarray, mu: np.ndarray, Omega_bar: np.ndarray,
                    gamma: float, S: int, *, kappa_max: float = 1e-4,
                    chunk: int = _CHUNK, s: np.ndarray | None = None
                    ) -> tuple[np.ndarray, np.ndarray]:
    """Fourier vectors C^(s), s = -S..S, of the Floquet solution with exponent near mu.

    Hill's recursion (mu + s Omega_bar)^2 C^(s) = A0 C^(s) - (gamma/2) B (C^(s-1) + C^(s+1))
    (4.1-10..12) in the modal frame of A0: where the coupling is weak (the term left out at most
    ``kappa_max``) by the first-order continued fraction C^(s) = -D_s^-1 G C^(s -+ 1), mu refined
    once from the s = 0 row; elsewhere by the exact matrix continued fraction (R_s, L_s), C^(0)
    the null vector of D_0 + G (R_1 + L_-1), mu refined by three secant steps (Risken 1989).

    Returns C, shape (P, 2S + 1, n) (or (P, n) with ``s``) in q_1..q_N, q_B, unit norm over
    (s, n), and the refined mu, shape (P,) (units of omega_1).

    Parameters
    ----------
    A0, B : numpy.ndarray
        Shape (n, n), steady matrix Lambda + B and thrust matrix per unit f(tau).
    mu : numpy.ndarray
        Shape (P,), starting exponents alpha Omega_bar (units of omega_1).
    Omega_bar : numpy.ndarray
        Shape (P,), Omega / omega_1, > 0.
    gamma : float
        Pulsation amplitude, 0 <= gamma < 1.
    S : int
        Harmonics s = -S..S kept, >= 0.
    kappa_max : float
        Largest relative term left out by the first-order fraction; 0 solves every point exactly.
    chunk : int
        Points per batch (memory ~ chunk 2S n^2 doubles).
    s : numpy.ndarray of int, optional
        Shape (P,), one harmonic per point, |s| <= S: only C^(s) of each point is returned.
    """
    mu = np.asarray(mu, dtype=float).ravel().copy()
    Ob = np.asarray(Omega_bar, dtype=float).ravel()
    if mu.shape != Ob.shape or not (np.all(np.isfinite(mu)) and np.all(np.isfinite(Ob))):
        raise ValueError("mu, Omega_bar: must be finite 1-D arrays of one length")
    if np.any(Ob <= 0.0):
        raise ValueError("Omega_bar: must be > 0")
    gamma = nonnegative("gamma", gamma)
    kappa_max = nonnegative("kappa_max", kappa_max)
    S = int(nonnegative("S", S))
    if s is not None:
        s = np.asarray(s).ravel()
        if (s.shape != mu.shape or not np.issubdtype(s.dtype, np.integer)
                or (s.size and np.abs(s).max() > S)):
            raise ValueError(f"s: must be integers with |s| <= S = {S}, one per point")
    A0 = np.asarray(A0, dtype=float)
    B = np.asarray(B, dtype=float)
    n = A0.shape[0]
    lam, V = np.linalg.eig(A0)
    if not (np.all(np.abs(lam.imag) <= 1e-12 * np.abs(lam).max()) and np.all(np.isreal(V))):
        C, mu = _floquet_exact(A0, B, mu, Ob, gamma, S, chunk)  # a flutter-unstable beam
        return (C, mu) if s is None else (C[np.arange(mu.size), s + S], mu)
    lam, V = lam.real, V.real
    GT = (-0.5 * gamma * np.linalg.solve(V, B @ V)).T  # G in the modal frame, transposed
    out = np.zeros((mu.size, 2 * S + 1, n) if s is None else (mu.size, n))
    kappa = np.zeros(mu.size)
    tiny = np.finfo(float).tiny
    levels = np.arange(-S, S + 1)
    for start in range(0, mu.size, chunk):
        sl = slice(start, start + chunk)
        P = mu[sl].size
        rows = np.arange(P)
        r = np.argmin(np.abs(lam[None, :] - mu[sl][:, None] ** 2), axis=1)  # lambda_r ~ mu^2
        if S:  # one refinement of the exponent (error ~ kappa^2) from the levels s = -1, 0, 1
            ninv = _negative_inverse_diagonals(lam, mu[sl], Ob[sl], np.arange(-1, 2), tiny)
            e_r = np.zeros((P, n))
            e_r[rows, r] = 1.0  # C^(0) = e_r to second order
            g0 = e_r @ GT
            c1, c_1 = ninv[2] * g0, ninv[0] * g0  # C^(1), C^(-1): first-order fraction
            mu2 = lam[r] + ((c1 + c_1) @ GT)[rows, r]  # s = 0 row, Hill
            mu[sl] = np.where(mu2 > 0, np.sqrt(np.abs(mu2)), mu[sl]) * np.sign(mu[sl])
        ninv = _negative_inverse_diagonals(lam, mu[sl], Ob[sl], levels, tiny)
        modal = np.zeros((2 * S + 1, P, n))
        modal[S, rows, r] = 1.0  # C^(0) = e_r to second order
        for k in range(1, S + 1):  # first-order continued fraction, outward from s = 0
            np.multiply(ninv[S + k], modal[S + k - 1] @ GT, out=modal[S + k])
            np.multiply(ninv[S - k], modal[S - k + 1] @ GT, out=modal[S - k])
        # a-posteriori: the term left out at each s, G C^(s +- 1) (outward), relative to C^(s)
        outer = np.zeros_like(modal)
        if S:
            outer[S + 1:-1] = modal[S + 2:] @ GT
            outer[1:S] = modal[:S - 1] @ GT
            outer[S] = (modal[S + 1] + modal[S - 1]) @ GT
        outer[S, rows, r] = 0.0  # the resonant row: the exponent itself
        np.multiply(ninv, outer, out=outer)  # its sign is lost in |.| below
        err = _abs_max_last(outer) / np.maximum(_abs_max_last(modal), tiny)
        kappa[sl] = err.max(axis=0)
        q = modal @ V.T  # back to q_1..q_N, q_B: (2S+1, P, n)
        # the norm over (s, n): the same sum (order included) as over axes (1, 2) of (P, 2S+1, n)
        norm = np.sqrt(np.add.reduce(q**2, axis=(0, 2)))
        if s is None:
            out[sl] = np.moveaxis(q, 0, 1) / norm[:, None, None]
        else:
            out[sl] = q[s[sl] + S, rows] / norm[:, None]
    hard = np.flatnonzero(kappa > kappa_max)
    if hard.size:
        C, mu[hard] = _floquet_exact(A0, B, mu[hard], Ob[hard], gamma, S, chunk)
        out[hard] = C if s is None else C[np.arange(hard.size), s[hard] + S]
    return out, mu


def _negative_inverse_diagonals(lam: np.ndarray, mu: np.ndarray, Ob: np.ndarray,
                                levels: np.ndarray, tiny: float) -> np.ndarray:
    """-1 / diag(D_s), D_s = diag(lambda - (mu + s Omega_bar)^2), shape (len(levels), P, n), as
    1 / (x^2 - lambda) (exact in sign); an exact zero of D_s is replaced by ``tiny``.
    """
    x = mu[None, :] + levels[:, None] * Ob[None, :]  # (levels, P)
    neg_d = x[:, :, None] ** 2 - lam[None, None, :]
    zero = neg_d == 0.0
    if zero.any():
        neg_d[zero] = -tiny
    return np.divide(1.0, neg_d, out=neg_d)


def _abs_max_last(X: np.ndarray) -> np.ndarray:
    """max |X| over the last axis (NaN propagates) as a running np.maximum over the columns."""
    out = np.abs(X[..., 0])
    for j in range(1, X.shape[-1]):
        np.maximum(out, np.abs(X[..., j]), out=out)
    return out


def _central(A0: np.ndarray, G: np.ndarray, m: np.ndarray, ob: np.ndarray,
             S: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """R_s, L_s (s = 1..S) and the central matrix D_0 + G (R_1 + L_-1) of the exact fraction."""
    n = A0.shape[0]
    P = m.size
    eye = np.eye(n)

    def D(s: int) -> np.ndarray:
        return A0[None] - ((m + s * ob) ** 2)[:, None, None] * eye[None]  # Hill (4.1-10)

    R = np.zeros((P, S + 1, n, n))  # R[:, s] for s = 1..S
    L = np.zeros((P, S + 1, n, n))  # L[:, t] for s = -t
    Gb = np.broadcast_to(G, (P, n, n))
    if S == 0:
        return R, L, D(0)
    R[:, S] = -np.linalg.solve(D(S), Gb)
    L[:, S] = -np.linalg.solve(D(-S), Gb)
    for s in range(S - 1, 0, -1):
        R[:, s] = -np.linalg.solve(D(s) + G @ R[:, s + 1], Gb)
        L[:, s] = -np.linalg.solve(D(-s) + G @ L[:, s + 1], Gb)
    return R, L, D(0) + G @ R[:, 1] + G @ L[:, 1]


def _floquet_exact(A0: np.ndarray, B: np.ndarray, mu: np.ndarray, Ob: np.ndarray, gamma: float,
                   S: int, chunk: int) -> tuple[np.ndarray, np.ndarray]:
    """The exact matrix continued fraction of :func:`floquet_vectors` (physical frame)."""
    n = A0.shape[0]
    G = -0.5 * gamma * B
    out = np.zeros((mu.size, 2 * S + 1, n))
    mu = mu.copy()

    def small_eig(m: np.ndarray, ob: np.ndarray) -> np.ndarray:
        ev = np.linalg.eigvals(_central(A0, G, m, ob, S)[2])
        return np.take_along_axis(ev, np.argmin(np.abs(ev), axis=1)[:, None], 1)[:, 0].real

    for start in range(0, mu.size, chunk):
        sl = slice(start, start + chunk)
        ob = Ob[sl]
        m0, m1 = mu[sl], mu[sl] * (1.0 + 1e-7)
        f0, f1 = small_eig(m0, ob), small_eig(m1, ob)
        for _ in range(3):  # secant on the eigenvalue nearest zero: the exact exponent
            den = f1 - f0
            ok = np.abs(den) > 0
            m2 = np.where(ok, m1 - f1 * (m1 - m0) / np.where(ok, den, 1.0), m1)
            m2 = np.where(np.abs(m2 - mu[sl]) <= 1e-3 * np.abs(mu[sl]), m2, m1)  # stay close
            m0, f0, m1 = m1, f1, m2
            f1 = small_eig(m1, ob)
        mu[sl] = m1
        R, L, central = _central(A0, G, m1, ob, S)
        _, _, vh = np.linalg.svd(central)
        c0 = vh[:, -1, :]  # smallest singular value: the Floquet vector's C^(0)
        blk = out[sl]
        blk[:, S] = c0
        up, down = c0, c0
        for s in range(1, S + 1):
            up = np.einsum("pij,pj->pi", R[:, s], up)
            down = np.einsum("pij,pj->pi", L[:, s], down)
            blk[:, S + s] = up
            blk[:, S - s] = down
        blk /= np.sqrt(np.sum(blk**2, axis=(1, 2)))[:, None, None]
    return out, mu


def _mode_tables(model: BoosterModel, N: int, phase: str) -> dict:
    """Per (cylinder, kind): omega, unit forcing of each normal coordinate and |Phi| max."""
    tr = model.truncation
    out = {}
    for d, (M, Nk) in ((1, (tr.M1, tr.N1)), (2, (tr.M2, tr.N2))):
        for g in cylinder_groups(model.shell, d, M, Nk, N, phase):
            omega, Phi, P = modal_basis(g)
            h = np.einsum("nmp,bnp->nmb", P, g.forcing)  # y'' + w^2 y = sum_b h_b f_b (6.1-*)
            scale = np.abs(Phi).max(axis=1)  # (n, m): largest of |U|, |V|, |W| per unit y
            typ = np.abs(Phi).argmax(axis=1)
            if g.kind == "j0":
                typ = np.array([0, 2])[typ]  # (U, W)
            out[(d, g.kind)] = (omega, h, scale, typ, int(Nk))
    return out


def root_severity(model: BoosterModel, table: StabilityTable, params: ExcitationParameters, *,
                  psi0: float = 0.01, beam_amplitude: float = 1e-4,
                  threshold: float = DEFAULT_THRESHOLD, S: int | None = None,
                  phase: str = "zero") -> RootSeverity:
    """Severity (secular growth rate at the shell surface) of every root, in one pass (memo 7.1).

    Every harmonic whose |frequency| equals the mode's to 1e-8 adds to G; the pitch and beam
    motions, of undefined relative phase, add in magnitude; complex beta or alpha_r enter by
    their real parts.

    Parameters
    ----------
    model : BoosterModel
        The derived model (truncation, omega_1, omega_psi, gamma, K, L).
    table : StabilityTable
        The roots (:func:`flexbooster.memo.stability.unstable_frequencies`).
    params : ExcitationParameters
        beta(Omega_bar), alpha_r(Omega_bar): the parameter function the roots were solved with.
    psi0 : float
        Reference initial pitch angle psi(0) (rad).
    beam_amplitude : float
        Reference norm of the beam Floquet vector (units of L), >= 0.
    threshold : float
        severity_rel at and above which a root is active, >= 0.
    S : int, optional
        Harmonics of the beam Floquet vectors (default: the model's truncation S).
    phase : {"zero", "printed"}
        Shape-function phase of the modal forcing (erratum E10).
    """
    psi0 = finite("psi0", psi0)
    beam_amplitude = nonnegative("beam_amplitude", beam_amplitude)
    threshold = nonnegative("threshold", threshold)
    phase = choice("phase", phase, ("zero", "printed"))
    N = model.truncation.N
    S = model.truncation.S if S is None else int(nonnegative("S", S))
    n_root = len(table)
    if n_root == 0:
        z = np.zeros(0)
        return RootSeverity(z, z, z, (), psi0, beam_amplitude, threshold)
    tables = _mode_tables(model, N, phase)
    ob = table.Omega_bar
    d, j, k, m = table.cylinder, table.j, table.k, table.branch - 1
    nb = N_BASIS + 2 * (N + 1)
    h = np.zeros((n_root, nb))
    w = np.zeros(n_root)
    scale = np.zeros(n_root)
    typ = np.zeros(n_root, dtype=int)
    for (dd, kind), (omega, hg, sc, ty, Nk) in tables.items():
        sel = (d == dd) & {"0k": (j == 0), "j0": (j >= 1) & (k == 0),
                           "jk": (j >= 1) & (k >= 1)}[kind]
        if not sel.any():
            continue
        idx = {"0k": k[sel] - 1, "j0": j[sel] - 1,
               "jk": (j[sel] - 1) * Nk + (k[sel] - 1)}[kind]
        h[sel] = hg[idx, m[sel]]
        w[sel] = omega[idx, m[sel]]
        scale[sel] = sc[idx, m[sel]]
        typ[sel] = ty[idx, m[sel]]

    # the free motions at every root: thrust, psi (4.2-6, 4.2-7), their products
    g, K, tf, eps = model.gamma, model.K, 0.5 * model.T0_bar, model.strain
    kt = 0.5 * K * model.T0_bar
    beta = params.beta(ob).real  # the exact exponent (Hill), as the roots use it
    A = _pitch_amplitudes(table.Omega, beta, model.omega_psi, g, psi0) if psi0 else \
        np.zeros((n_root, 3))
    W = np.stack([1.0 - beta / 2.0, beta / 2.0, 1.0 + beta / 2.0], axis=-1) * ob[:, None]
    nus, amps, rows = [], [], []

    def add(freq: np.ndarray, row: int, amp: np.ndarray) -> None:
        nus.append(np.broadcast_to(freq, (n_root,)))
        amps.append(np.broadcast_to(amp, (n_root,)))
        rows.append(row)

    add(ob, 0, -g * tf * np.ones(n_root))  # T0_bar T / 2, T = 1 - gamma cos (4.2-1a)
    add(ob, 1, -g * eps * np.ones(n_root))  # eps T (5.3-4a)
    add(ob, 2, eps * g * ob**2)  # eps T'' (5.3-4a)
    for i in range(3):
        Wi, Ai = W[:, i], A[:, i]
        add(Wi, 3, -Ai * Wi**2)  # psi'' (4.2-6)
        add(Wi, 5, kt * Ai)  # K T0_bar T psi / 2 (3.0-3b, c)
        add(ob + Wi, 5, -0.5 * g * kt * Ai)
        add(ob - Wi, 5, -0.5 * g * kt * Ai)
        for p in range(3):
            half = 0.5 * Ai * A[:, p] * Wi * W[:, p]
            add(Wi - W[:, p], 4, half)  # psi'^2 = 1/2 sum A_i A_p W_i W_p [cos(-) - cos(+)]
            add(Wi + W[:, p], 4, -half)
    # built harmonic by harmonic (H, n), in place; summed per root in the (n, H) layout
    nu = np.stack(nus)  # (H, n)
    res = np.abs(nu, out=nu)
    res -= w
    np.abs(res, out=res)
    res = res <= _RES_TOL * w
    forcing = np.stack(amps)
    forcing *= h.T[rows]
    np.copyto(forcing, 0.0, where=~res)
    G = np.abs(np.sum(np.ascontiguousarray(forcing.T), axis=1))  # real amplitudes

    # the beam Floquet harmonic of the root's exponent (families 2 and 13)
    beam = (table.r >= 1) & np.isin(table.family, (2, 13)) & (beam_amplitude > 0)
    if beam.any() and np.abs(table.s[beam]).max() > S:
        raise ValueError(f"S = {S}: must be at least the table's largest |s| = "
                         f"{int(np.abs(table.s[beam]).max())}")
    if beam.any():
        system = beam_system(model, N)
        r = table.r[beam]
        alpha = params.alpha(ob[beam])[np.arange(r.size), r - 1]
        s = table.s[beam]
        Cs, mu = floquet_vectors(system.A0, system.B, alpha * ob[beam], ob[beam], g, S, s=s)
        c = beam_amplitude * Cs  # C^(s) of each root: (nbeam, N + 1), units of L
        f = mu + s * ob[beam]  # (4.1-10/11), at the exponent refined at the root
        hb = h[beam]
        qb, qdd = slice(N_BASIS, N_BASIS + N + 1), slice(N_BASIS + N + 1, nb)
        Gb = np.abs(np.sum(c * (hb[:, qb] - (f**2)[:, None] * hb[:, qdd]), axis=1))
        G[beam] += Gb  # independent motions: magnitudes add (see Notes)
    rate = G / (2.0 * w)  # y ~ |G| / (2 omega) tau sin(omega tau) (7.1)
    severity = rate * model.mass.L * model.omega_1 * scale  # m/s at the shell surface
    top = severity.max()
    rel = severity / top if top > 0 else np.zeros(n_root)
    return RootSeverity(severity=severity, severity_rel=rel, rate=rate,
                        mode_type=tuple(np.asarray(_COMPONENTS)[typ].tolist()), psi0=psi0,
                        beam_amplitude=beam_amplitude, threshold=threshold)


def shell_mode(cylinder: int, j: int, k: int, branch: int, mode_type: str) -> BandMode:
    """A memo shell mode (memo 6.1) as a :class:`flexbooster.bands.BandMode`.

    Parameters
    ----------
    cylinder : int
        Cylinder d (1 aft, 2 forward).
    j, k : int
        Axial and circumferential indices.
    branch : int
        Branch m of the modal system (1..3, ascending frequency).
    mode_type : str
        "axial", "torsional" or "radial".
    """
    return BandMode(label=f"cylinder {cylinder} shell mode j = {j}, k = {k}, m = {branch} "
                          f"({mode_type})", index=int(branch), k=int(k), order=int(j),
                    type=mode_type, cylinder=int(cylinder))


def resonance_bands(table: StabilityTable, sev: RootSeverity, *,
                    resolution: float = DEFAULT_RESOLUTION,
                    half_power: np.ndarray | None = None) -> tuple[Band, ...]:
    """Merge the active roots into bands of Omega, most severe first (memo 7.1).

    Parameters
    ----------
    table : StabilityTable
        The roots.
    sev : RootSeverity
        Their severity (:func:`root_severity`); only active roots form bands.
    resolution : float
        Relative resolution in Omega, > 0: consecutive active roots closer than
        max(resolution, half_power) Omega join one band (single linkage).
    half_power : numpy.ndarray, optional
        Shape (n,), relative half-power width of each root's mode, 2 zeta (Meirovitch 1986,
        sec. 3.3); default 0 (undamped shells).
    """
    resolution = positive("resolution", resolution)
    if len(sev) != len(table):
        raise ValueError(f"sev: {len(sev)} roots, the table has {len(table)}")
    hp = np.zeros(len(table)) if half_power is None else np.asarray(half_power, dtype=float)
    if hp.shape != (len(table),) or not np.all(np.isfinite(hp)) or np.any(hp < 0):
        raise ValueError("half_power: must be finite, >= 0, one value per root")
    idx = np.flatnonzero(sev.active)
    if idx.size == 0:
        return ()
    idx = idx[np.argsort(table.Omega[idx], kind="stable")]
    Om = table.Omega[idx]
    tol = np.maximum(resolution, hp[idx])
    start = np.ones(idx.size, dtype=bool)
    start[1:] = np.diff(Om) > np.maximum(tol[1:], tol[:-1]) * Om[:-1]
    bounds = np.append(np.flatnonzero(start), idx.size)
    bands = []
    for a, b in zip(bounds[:-1], bounds[1:], strict=True):
        members = idx[a:b][np.argsort(-sev.severity[idx[a:b]], kind="stable")]
        top = members[0]
        modes: list[tuple[int, int, int, int, str]] = []
        for n in members:
            key = (int(table.cylinder[n]), int(table.j[n]), int(table.k[n]),
                   int(table.branch[n]), sev.mode_type[n])
            if key not in modes:
                modes.append(key)
        peak = float(table.Omega[top])
        family = int(table.family[top])
        bands.append(Band(
            mechanism="resonance", kind="resonance", Omega_lo=float(Om[a]),
            Omega_hi=float(Om[b - 1]), Omega_at_max=peak, Omega_center=peak,
            growth_rate_max=0.0, order=family,
            modes=tuple(dataclasses.replace(  # the top root's mode first, with its frequency
                shell_mode(*m), omega=float(table.shell_omega_bar[top] * table.omega_1))
                if n == 0 else shell_mode(*m) for n, m in enumerate(modes)),
            severity=float(sev.severity[top]), severity_rel=float(sev.severity_rel[top]),
            n_roots=int(b - a), families=tuple(sorted({int(table.family[n]) for n in members})),
            cause=FAMILY_CAUSES[family]))
    bands.sort(key=lambda x: -x.severity)
    return tuple(bands)


@dataclass(frozen=True)
class SeverityResult:
    """The severity of a stability table: reference amplitudes, threshold and bands.

    Attributes
    ----------
    roots : RootSeverity
        Per-root severity (the table's ``severity`` and ``severity_rel`` columns).
    bands : tuple of Band
        The active roots merged into bands, most severe first.
    resolution : float
        Relative resolution in Omega of the bands.
    """

    roots: RootSeverity
    bands: tuple[Band, ...]
    resolution: float

    def to_dict(self) -> dict:
        """JSON-ready: reference amplitudes, threshold, resolution and every band."""
        return {**self.roots.to_dict(), "resolution": float(self.resolution),
                "causes": {str(k): v for k, v in FAMILY_CAUSES.items()},
                "bands": [b.to_dict() for b in self.bands]}

    def band_rows(self) -> list[dict]:
        """One flat mapping per band (the rows of resonance-bands.csv), most severe first."""
        rows = []
        for rank, b in enumerate(self.bands, start=1):
            top = b.modes[0]
            rows.append({
                "rank": rank, "Omega_lo_rad_s": b.Omega_lo, "Omega_hi_rad_s": b.Omega_hi,
                "Omega_peak_rad_s": b.Omega_at_max,
                "Omega_peak_hz": b.Omega_at_max / (2.0 * np.pi),
                "severity_m_s": b.severity, "severity_rel": b.severity_rel,
                "n_roots": b.n_roots, "family": b.order,
                "families": " ".join(str(f) for f in b.families),
                "cylinder": top.cylinder, "j": top.order, "k": top.k, "branch": top.index,
                "mode_type": top.type,
                "modes": " ".join(f"{m.cylinder}/{m.order}/{m.k}/{m.index}" for m in b.modes),
                "cause": b.cause})
        return rows


def with_severity(table: StabilityTable, sev: RootSeverity) -> StabilityTable:
    """The table with its severity columns and ``active = severity_rel >= threshold`` (memo 7.1).

    Parameters
    ----------
    table : StabilityTable
        The roots.
    sev : RootSeverity
        Their severity (:func:`root_severity` of this table).
    """
    from dataclasses import replace

    if len(sev) != len(table):
        raise ValueError(f"sev: {len(sev)} roots, the table has {len(table)}")
    return replace(table, active=sev.active, severity=sev.severity,
                   severity_rel=sev.severity_rel)


def severity_analysis(model: BoosterModel, table: StabilityTable, params: ExcitationParameters,
                      *, psi0: float = 0.01, beam_amplitude: float = 1e-4,
                      threshold: float = DEFAULT_THRESHOLD,
                      resolution: float = DEFAULT_RESOLUTION
                      ) -> tuple[StabilityTable, SeverityResult]:
    """Severity of every root, the table with it attached and the bands: (table, result) (memo
    6.2, 7.1, 7.3; pipeline stage).

    Parameters
    ----------
    model : BoosterModel
        The derived model.
    table : StabilityTable
        The roots.
    params : ExcitationParameters
        The parameter function the roots were solved with.
    psi0, beam_amplitude, threshold : float
        As :func:`root_severity`.
    resolution : float
        Relative resolution of the bands in Omega, > 0.
    """
    sev = root_severity(model, table, params, psi0=psi0, beam_amplitude=beam_amplitude,
                        threshold=threshold)
    bands = resonance_bands(table, sev, resolution=resolution)
    return with_severity(table, sev), SeverityResult(sev, bands, float(resolution))
