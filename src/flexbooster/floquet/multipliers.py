"""Monodromy matrix, Floquet multipliers, growth rates of M q'' + C q' + (A + B cos Omega t) q = 0.

Lawson (integrating-factor) RK4 with the steady system (B = 0) propagated exactly. C = 0: in
the steady modal frame over half a period, Phi(T) = R Phi(T/2)^-1 R Phi(T/2), R = diag(I, -I)
(reversibility); C != 0: first-order form over the period. Point p may carry its own
amplitude a_p B and step count. Theory: docs/theory/floquet.md.

References: V. V. Bolotin, *The Dynamic Stability of Elastic Systems*, 1964, ch. 1-2;
W. Magnus, S. Winkler, *Hill's Equation*, 1966, ch. 1-2; J. D. Lawson, SIAM J. Numer. Anal.
4 (1967) 372-380.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.linalg

__all__ = ["MAX_STEPS", "SYMMETRY_RTOL", "LinearPeriodicSystem", "periodic_system",
           "steady_frequencies", "as_omega", "step_counts", "StepLimitError",
           "PeriodMapOverflowError", "half_period_maps", "period_maps", "s_matrices",
           "s_value_sets", "largest_multiplier", "monodromy", "floquet_multipliers",
           "floquet_exponents", "growth_rate"]

#: Default cap on the steps per integrated period (half period when C = 0).
MAX_STEPS = 200_000
#: Bytes of the work arrays of one block of points of the modal Lawson march (1 MiB: within
#: the L2 cache of one core of current x86 and ARM processors, 1-2 MiB).
_MODAL_BLOCK_BYTES = 1 << 20


class StepLimitError(ValueError):
    """A monodromy would need more steps than ``max_steps`` (Omega too small for the system's
    frequencies): a computation past a resource limit, not a wrong argument.
    """


class PeriodMapOverflowError(ValueError):
    """The period map left the floating-point range (the system is far past a divergence or
    flutter load there); ``Omega`` is the first such pulsation.
    """

    def __init__(self, message: str, Omega: float) -> None:
        super().__init__(message)
        self.Omega = float(Omega)


def _matrix(name: str, value, n: int | None) -> np.ndarray:
    if np.iscomplexobj(value):  # float() would drop the imaginary part
        raise ValueError(f"{name} = {_one_line(value)}: must be a real square matrix (complex "
                         "entries)")
    try:
        a = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"{name} = {_one_line(value)}: must be a real square matrix") from None
    if a.ndim == 0 and n is not None and a == 0.0:
        return np.zeros((n, n))
    if a.ndim != 2 or a.shape[0] != a.shape[1] or a.shape[0] == 0:
        raise ValueError(f"{name} = shape {a.shape}: must be a non-empty square matrix")
    if n is not None and a.shape[0] != n:
        raise ValueError(f"{name} = shape {a.shape}: must be ({n}, {n}) like M")
    if not np.all(np.isfinite(a)):
        bad = np.argwhere(~np.isfinite(a))[0]
        raise ValueError(f"{name} = a matrix with {name}[{bad[0]}, {bad[1]}] = "
                         f"{a[tuple(bad)]!r}: must be finite")
    return a


def _one_line(value) -> str:
    """repr of a value on one line, cut to 60 characters (error messages: one line)."""
    text = " ".join(repr(value).split())
    return text if len(text) <= 60 else text[:57] + "..."


@dataclass(frozen=True)
class LinearPeriodicSystem:
    """Validated system M q'' + C q' + (A + B cos Omega t) q = 0 in the form q'' = ...

    Attributes
    ----------
    K0, Kc, Kb : numpy.ndarray
        M^-1 A, M^-1 C, M^-1 B, (n, n).
    damped : bool
        C != 0.
    mu, V, Bt : numpy.ndarray
        Eigenvalues of M^-1 A (ascending), its eigenvectors and V^-1 M^-1 B V (V, Bt None when
        V is ill-conditioned: the dense kernel is used).
    canonical : bool
        M, A and B symmetric, M and A positive definite (:func:`periodic_system`): with C = 0
        the system is canonical with a positive Hamiltonian, whose multipliers leave the unit
        circle only at the simple and sum resonances (Krein 1955).
    """

    K0: np.ndarray
    Kc: np.ndarray
    Kb: np.ndarray
    damped: bool
    mu: np.ndarray
    V: np.ndarray | None
    Bt: np.ndarray | None
    canonical: bool = False

    @property
    def n(self) -> int:
        """Number of degrees of freedom."""
        return int(self.K0.shape[0])

    def to_dict(self) -> dict:
        """JSON-ready mapping of the matrices."""
        return {"K0": self.K0.tolist(), "Kc": self.Kc.tolist(), "Kb": self.Kb.tolist(),
                "damped": bool(self.damped), "mu_real": self.mu.real.tolist(),
                "mu_imag": self.mu.imag.tolist()}


def periodic_system(M, C, A, B) -> LinearPeriodicSystem:
    """Validate and pre-process M q'' + C q' + (A + B cos Omega t) q = 0 (ValueError naming the
    argument for non-finite entries, wrong shapes, a singular M).

    Parameters
    ----------
    M, C, A, B : array_like
        Each (n, n), any consistent units; C None or 0 for no damping.
    """
    M = _matrix("M", M, None)
    n = M.shape[0]
    C = np.zeros((n, n)) if C is None else _matrix("C", C, n)
    A = _matrix("A", A, n)
    B = _matrix("B", B, n)
    if np.linalg.cond(M) > 1e12:
        raise ValueError(f"M = {M.tolist()!r}: must be invertible (condition number > 1e12)")
    K0 = np.linalg.solve(M, A)
    Kc = np.linalg.solve(M, C)
    Kb = np.linalg.solve(M, B)
    mu, V = np.linalg.eig(K0)
    scale = max(float(np.max(np.abs(mu))), 1e-300)
    if np.all(np.abs(mu.imag) <= 1e-13 * scale):
        mu = mu.real.astype(complex)
        V = V.real if np.all(np.abs(V.imag) <= 1e-13) else V
    order = np.lexsort((mu.imag, mu.real))  # ascending squared frequency
    mu, V = mu[order], V[:, order]
    Bt = None
    if np.linalg.cond(V) < 1e8:
        Bt = np.linalg.solve(V, Kb @ V)
    else:
        V = None
    return LinearPeriodicSystem(K0=K0, Kc=Kc, Kb=Kb, damped=bool(np.any(Kc != 0.0)), mu=mu,
                                V=V, Bt=Bt, canonical=_canonical(M, A, B, mu))


#: Largest asymmetry max |X - X^T| / max |X| of M, A, B still taken as symmetric (round-off of
#: assembly): a multiplier moves off the unit circle by about this, relative, far below the
#: monodromy's detection floor (1e-7 in |rho|; :mod:`.regions`).
SYMMETRY_RTOL = 1e-12


def _canonical(M: np.ndarray, A: np.ndarray, B: np.ndarray, mu: np.ndarray) -> bool:
    """M, A, B symmetric (to :data:`SYMMETRY_RTOL`), M positive definite and every eigenvalue of
    M^-1 A real and > 0 (A positive definite): M q'' + (A + B cos Omega t) q = 0 is then a
    canonical system with a positive definite Hamiltonian (Yakubovich and Starzhinskii 1975,
    ch. VI)."""
    for X in (M, A, B):
        if np.max(np.abs(X - X.T)) > SYMMETRY_RTOL * np.max(np.abs(X)):
            return False
    try:
        np.linalg.cholesky(0.5 * (M + M.T))
    except np.linalg.LinAlgError:
        return False
    return bool(np.all(mu.imag == 0.0) and np.all(mu.real > 0.0))


def steady_frequencies(M, A, *, C=None) -> np.ndarray:
    """Frequencies of the steady system, sqrt(eig(M^-1 A)), shape (n,), complex, ascending in the
    square; a non-real or zero value means flutter or divergence (Bolotin 1964, sec. 2).

    Parameters
    ----------
    M, A : array_like
        Mass and steady stiffness, (n, n).
    C : array_like, optional
        Damping (only validated).
    """
    system = periodic_system(M, C, A, np.zeros_like(np.asarray(M, dtype=float)))
    return np.sqrt(system.mu)


def as_omega(Omega) -> np.ndarray:
    """``Omega`` as a non-empty 1-D float array of finite values > 0.

    Parameters
    ----------
    Omega : array_like
        Pulsation frequencies (rad per time unit); ValueError otherwise.
    """
    try:
        om = np.atleast_1d(np.asarray(Omega, dtype=float))
    except (TypeError, ValueError):
        raise ValueError(f"Omega = {Omega!r}: must be real numbers") from None
    if om.ndim != 1 or om.size == 0 or not np.all(np.isfinite(om)) or np.any(om <= 0.0):
        raise ValueError(f"Omega = {Omega!r}: must be a non-empty 1-D array, finite and > 0")
    return om


def _rates(system: LinearPeriodicSystem) -> tuple[np.ndarray, np.ndarray]:
    """Steady frequencies w (m,) and coupling magnitudes b (m, m) of :func:`step_counts`: undamped
    w = |omega_j|, b = |Bt|; damped from the first-order modal frame, b_jk = 2 |lambda_j| |G_jk|
    (docs/theory/floquet.md sec. 2); a defective steady operator gets b = max |M^-1 B|.
    """
    if not system.damped and system.Bt is not None:
        return np.abs(np.sqrt(system.mu)), np.abs(system.Bt)
    n = system.n
    L0 = np.block([[np.zeros((n, n)), np.eye(n)], [-system.K0, -system.Kc]])
    lam, W = np.linalg.eig(L0)
    w = np.abs(lam)
    if np.linalg.cond(W) >= 1e8:  # defective steady operator: the largest entry of M^-1 B
        return w, np.full((2 * n, 2 * n), np.max(np.abs(system.Kb)))
    W = W / np.linalg.norm(W[:n], axis=0)  # unit q-part of each column, like V's columns
    Nmat = np.block([[np.zeros((n, n)), np.zeros((n, n))], [-system.Kb, np.zeros((n, n))]])
    G = np.abs(np.linalg.solve(W, Nmat @ W))  # |G_jk| (1/time)
    return w, 2.0 * w[:, None] * G  # b_jk = 2 |lambda_j| |G_jk| -> |B~_jk| as C -> 0


def step_counts(system: LinearPeriodicSystem, Omega, *, step_phase: float = 0.06,
                max_steps: int = MAX_STEPS, amplitude=None, levels_per_octave: int = 2,
                clip: bool = False) -> np.ndarray:
    """Steps per integrated interval (half period if C = 0, else one period), shape (P,).

    A fourth-order step errs by about g (h nu)^4 / nu, with nu_jk = w_j + w_k + Omega and
    g_jk = a b_jk / max(w_j, Omega / 2), so h max nu^(3/4) g^(1/4) <= step_phase (Lawson 1967).

    Parameters
    ----------
    system : LinearPeriodicSystem
        From :func:`periodic_system`.
    Omega : array_like
        Shape (P,), rad per time unit, > 0.
    step_phase : float
        > 0; error on the exponents ~ step_phase^4 (about 1e-9 of the largest frequency at 0.06).
    max_steps : int
        Cap: :class:`StepLimitError` beyond it, or with ``clip`` the cap itself.
    amplitude : array_like, optional
        Shape (P,), the amplitude a of each point (default 1).
    levels_per_octave : int
        Counts rounded up to 2^(k / levels_per_octave): few batches.
    clip : bool
        Cap the counts instead of raising.
    """
    om = as_omega(Omega)
    if not (np.isfinite(step_phase) and step_phase > 0.0):
        raise ValueError(f"step_phase = {step_phase!r}: must be finite and > 0")
    w, b = _rates(system)
    interval = (2.0 if system.damped else 1.0) * np.pi / om  # full or half period
    nu = w[:, None] + w[None, :] + om[:, None, None]
    if amplitude is not None:
        b = np.abs(np.broadcast_to(np.asarray(amplitude, dtype=float), om.shape))[:, None,
                                                                                 None] * b
    g = b / np.maximum(w[None, :, None], 0.5 * om[:, None, None])
    rate = np.max(nu**0.75 * g**0.25, axis=(1, 2))
    steps = np.maximum(8.0, np.ceil(interval * rate / step_phase))
    k = float(levels_per_octave)  # 2^(j/k): few batches
    steps = np.ceil(2.0 ** (np.ceil(k * np.log2(steps)) / k))
    if clip:
        return np.minimum(steps, max_steps).astype(int)
    worst = int(np.argmax(steps))
    if steps[worst] > max_steps:
        raise StepLimitError(f"Omega = {float(om[worst]):.6g}: needs about {int(steps[worst])} "
                             f"steps per period, more than max_steps = {max_steps} (Omega too "
                             "small for the frequencies of the system)")
    return steps.astype(int)


def _rotation(mu: np.ndarray, t: np.ndarray) -> tuple[np.ndarray, ...]:
    """cos(w t), sin(w t)/w, -w sin(w t), w^2 = mu: exact propagator of eta'' + mu eta = 0."""
    w = np.sqrt(mu)
    wt = w * t
    small = np.abs(wt) < 1e-4
    sn = np.where(small, t * (1.0 - wt**2 / 6.0), np.sin(wt) / np.where(small, 1.0, w))
    return np.cos(wt), sn, -mu * sn


def _half_modal(system: LinearPeriodicSystem, om: np.ndarray, n_steps: np.ndarray,
                amp: np.ndarray) -> np.ndarray:
    """Phi(T/2) in modal coordinates (eta, eta'), shape (P, 2n, 2n); point p with amp[p] B and its
    own (descending) step count.
    """
    mu, Bt = system.mu, system.Bt
    real = np.all(mu.imag == 0.0) and np.isrealobj(Bt) and np.all(mu.real > 0.0)
    if real:
        mu = mu.real
    n, P = mu.size, om.size
    h = (np.pi / om) / n_steps
    c1, s1, m1 = (e.T[:, :, None] for e in _rotation(mu[None, :], h[:, None]))  # E(h)
    c2, s2, _ = (e.T[:, :, None] for e in _rotation(mu[None, :], 0.5 * h[:, None]))  # E(h/2)
    dtype = complex if not real else float
    z = np.zeros((2, n, P, 2 * n), dtype=dtype)  # z[0] = eta, z[1] = eta' of every column
    idx = np.arange(n)
    z[0, idx, :, idx] = 1.0
    z[1, idx, :, n + idx] = 1.0
    with np.errstate(over="ignore", invalid="ignore"):  # overflow is reported by _finite
        z = _lawson_modal(z, Bt, om * (0.5 * h), amp, n_steps, c1, s1, m1, c2, s2,
                          h[None, :, None])
    return z.reshape(2 * n, P, 2 * n).transpose(1, 0, 2)


def _lawson_modal(z, Bt, phase, amp, n_steps, c1, s1, m1, c2, s2, hh):
    """The Lawson RK4 loop of :func:`_half_modal` (returns the final z of every point).

    eta'' = -mu eta - a cos(Omega t) Bt eta; ``z`` (2, n, P, 2n) holds eta and eta', ``phase``
    is Omega h / 2; the batch is a prefix that shrinks as the points finish. Each operation is
    the one of the step written out: a point's result does not depend on its batch.
    """
    out = np.empty_like(z)
    n, p = z.shape[1], z.shape[2]  # p: the points still integrating
    steps = int(n_steps[0]) if p else 0
    h6 = hh / 6.0
    # -a cos(Omega t) at every stage time t = m h / 2, m = 0 .. 2 steps, shape (2 steps + 1, P)
    f = -(amp * np.cos(phase[None, :] * np.arange(2 * steps + 1)[:, None]))
    k2 = 2 * np.arange(steps)[:, None]
    # per step the force of each coefficient below: f0 (stage t = k h) x 3, f1 ((k + 1/2) h)
    # x 3, f2 ((k + 1) h)
    force = f[k2 + np.array([0, 0, 0, 1, 1, 1, 2])][:, :, None, :, None]
    cf = np.stack(np.broadcast_arrays(0.5 * hh * s2, h6 * s1, h6 * c1, hh * s2,
                                      2.0 * h6 * s2, 2.0 * h6 * c2, h6))
    # the steady propagators E(h/2) (position row) and E(h) = [[c1, s1], [m1, c1]] over the
    # 2n columns: a product of equal shapes is a single loop, a broadcast one a loop per
    # (mode, point)
    full = (z.shape[1], z.shape[2], z.shape[3])
    c2, s2 = np.broadcast_to(c2, full).copy(), np.broadcast_to(s2, full).copy()
    cm1 = np.broadcast_to(np.stack([c1, m1]), z.shape).copy()
    sc1 = np.broadcast_to(np.stack([s1, c1]), z.shape).copy()
    bufs = None
    for k in range(steps):  # Lawson (1967) integrating-factor RK4
        q = p
        while q > 0 and n_steps[q - 1] <= k:  # points whose own steps are done
            q -= 1
        if q < p:  # store them, shrink the batch
            out[:, :, q:p] = z[:, :, q:p]
            p = q
            z = np.ascontiguousarray(z[:, :, :p])
            force, cf = force[..., :p, :], cf[..., :p, :]
            c2, s2, cm1, sc1 = (np.ascontiguousarray(a[..., :p, :]) for a in (c2, s2, cm1, sc1))
            bufs = None
        if bufs is None:  # views of the work arrays of this batch (they are updated in place)
            a = np.empty(cf.shape, dtype=np.result_type(cf, force))
            y, g, zf = np.empty_like(z), np.empty_like(z), np.empty_like(z)
            g1, t = np.empty_like(z[0]), np.empty_like(z[0])
            bufs = (a, a[0], a[1:3], a[3], a[4:6], a[6], z[0], z[1], y[0], y[1], g[0], g[1],
                    zf[0], z[0].reshape(n, -1), g1.reshape(n, -1), y.reshape(2, n, -1),
                    g.reshape(2, n, -1), t.reshape(n, -1), y[0].reshape(n, -1))
        (a, a0h, a0z, a1h, a1z, a2, x, v, y0, y1, gg2, gg3, xf, x_, g1_, y_, g_, t_,
         y0_) = bufs
        np.multiply(cf, force[k], out=a)  # coefficient x force of the stage
        np.matmul(Bt, x_, out=g1_)  # k1 = N(t) z = f0 g1
        np.multiply(c2, x, out=y1)  # E(h/2) z (position part)
        y1 += np.multiply(s2, v, out=t)
        np.multiply(a0h, g1, out=y0)
        y0 += y1
        np.matmul(Bt, y_, out=g_)  # k2 = N E(h/2)(z + h/2 k1) = f1 g2 and
        #                            k3 = N [E(h/2) z + h/2 k2] = f1 g3 (k2 has no position part)
        np.multiply(cm1, x, out=zf)  # E(h) z
        zf += np.multiply(sc1, v, out=y)
        np.multiply(a1h, gg3, out=t)
        t += xf
        np.matmul(Bt, t_, out=y0_)  # k4 = N [E(h) z + h E(h/2) k3] = f2 y0
        gg2 += gg3
        # z_new = E(h) z + h/6 [E(h) k1 + 2 E(h/2)(k2 + k3) + k4]   (Lawson 1967)
        np.multiply(a0z, g1, out=z)
        z += zf
        z += np.multiply(a1z, gg2, out=zf)
        v += np.multiply(a2, y0, out=t)
    out[:, :, :p] = z
    return out


#: Bytes of the step matrices held at once by the dense kernel (:func:`_period_dense`).
_DENSE_BLOCK_BYTES = 1 << 25


def _step_coefficients(system: LinearPeriodicSystem, h: np.ndarray
                       ) -> tuple[np.ndarray, np.ndarray]:
    """E(h) and the five matrices of one Lawson RK4 step of each point, shapes (P, 2n, 2n) and
    (P, 5, 2n, 2n): the step is S = E(h) + f0 M1 + f1 M2 + f2 M3 + f0 f1 M4 + f1 f2 M5 with
    f0, f1, f2 the amplitude a cos(Omega t) at t = k h, (k + 1/2) h, (k + 1) h.

    With N(t) = f(t) Nb, Nb = [[0, 0], [-M^-1 B, 0]] nilpotent (Nb^2 = 0), the stages
    k1 = N0 z, k2 = N1 E2 (z + h/2 k1), k3 = N1 (E2 z + h/2 k2) = N1 E2 z,
    k4 = N2 (E1 z + h E2 k3) of z+ = E1 z + h/6 (E1 k1 + 2 E2 (k2 + k3) + k4) give
    M1 = h/6 E1 Nb, M2 = 4 h/6 E2 Nb E2, M3 = h/6 Nb E1, M4 = h^2/6 E2 Nb E2 Nb,
    M5 = h^2/6 Nb E2 Nb E2 (Lawson 1967: the step itself, regrouped).
    """
    n = system.n
    L0 = np.block([[np.zeros((n, n)), np.eye(n)], [-system.K0, -system.Kc]])
    E1 = scipy.linalg.expm(L0[None] * h[:, None, None])  # exact steady propagator E(h)
    E2 = scipy.linalg.expm(L0[None] * (0.5 * h)[:, None, None])
    Nb = np.zeros((2 * n, 2 * n))
    Nb[n:, :n] = -system.Kb
    h6 = (h / 6.0)[:, None, None]
    NE2 = Nb @ E2
    E2NE2 = E2 @ NE2
    M = np.stack([h6 * (E1 @ Nb), 4.0 * h6 * E2NE2, h6 * (Nb @ E1),
                  (h[:, None, None] * h6) * (E2NE2 @ Nb),
                  (h[:, None, None] * h6) * (NE2 @ NE2)], axis=1)
    return E1, M


def _ordered_product(S: np.ndarray) -> np.ndarray:
    """S[:, m-1] ... S[:, 1] S[:, 0] of a stack (P, m, k, k), by pairs (log2 m batched rounds)."""
    while S.shape[1] > 1:
        even = S.shape[1] - S.shape[1] % 2  # a last odd one is carried to the next round
        pairs = S[:, 1:even:2] @ S[:, 0:even:2]
        S = pairs if even == S.shape[1] else np.concatenate([pairs, S[:, even:]], axis=1)
    return S[:, 0]


def _period_dense(system: LinearPeriodicSystem, om: np.ndarray, n_steps: int,
                  half: bool, amp: np.ndarray) -> np.ndarray:
    """Phi over one period (or half period) in (q, q'), shape (P, 2n, 2n); dense Lawson RK4.

    Point p has the excitation amp[p] B. Each step is a matrix affine in the forcing samples
    (:func:`_step_coefficients`): the step matrices of a block of steps are formed at once and
    multiplied by pairs, in time order.
    """
    m, P = 2 * system.n, om.size
    h = ((1.0 if half else 2.0) * np.pi / om) / n_steps
    E1, M = _step_coefficients(system, h)
    Mflat = M.reshape(P, 5, m * m)
    block = max(1, min(n_steps, _DENSE_BLOCK_BYTES // (3 * 8 * P * m * m)))
    z = np.broadcast_to(np.eye(m), (P, m, m)).copy()
    with np.errstate(over="ignore", invalid="ignore"):  # overflow is reported by _finite
        for start in range(0, n_steps, block):
            k = np.arange(start, min(start + block, n_steps))
            t = h[:, None] * k[None, :]  # (P, b)
            f0 = amp[:, None] * np.cos(om[:, None] * t)
            f1 = amp[:, None] * np.cos(om[:, None] * (t + 0.5 * h[:, None]))
            f2 = amp[:, None] * np.cos(om[:, None] * (t + h[:, None]))
            coef = np.stack([f0, f1, f2, f0 * f1, f1 * f2], axis=-1)  # (P, b, 5)
            S = (coef @ Mflat).reshape(P, k.size, m, m) + E1[:, None]
            z = _ordered_product(S) @ z
    return z


def _merge_steps(steps: np.ndarray, n: int) -> np.ndarray:
    """Raise step counts so that small batches share one loop: a loop of s steps over p points
    costs about s (c0 + c1 p n^2), c0 / c1 ~ 2000; a group is merged upward when cheaper.
    """
    steps = steps.copy()
    ratio = 2000.0
    while True:
        counts = np.unique(steps)
        if counts.size < 2:
            return steps
        lo, hi = counts[0], counts[1]
        p = np.count_nonzero(steps == lo)
        if hi * p * n * n > lo * (ratio + p * n * n):  # merging costs more than one loop
            return steps
        steps[steps == lo] = hi


def _amplitudes(amplitude, om: np.ndarray) -> np.ndarray:
    if amplitude is None:
        return np.ones(om.size)
    amp = np.broadcast_to(np.asarray(amplitude, dtype=float), om.shape)
    if not np.all(np.isfinite(amp)):
        raise ValueError(f"amplitude = {amplitude!r:.60}: must be finite")
    return amp


def _dense_maps(system: LinearPeriodicSystem, om: np.ndarray, steps: np.ndarray, chunk: int,
                half: bool, amp: np.ndarray, out: np.ndarray) -> np.ndarray:
    """The dense kernel batched by equal (merged) step counts, into ``out``."""
    steps = _merge_steps(steps, system.n)
    for ns in np.unique(steps):
        where = np.nonzero(steps == ns)[0]
        for start in range(0, where.size, chunk):
            sel = where[start:start + chunk]
            out[sel] = _period_dense(system, om[sel], int(ns), half, amp[sel])
    return _finite(out, om)


def half_period_maps(system: LinearPeriodicSystem, Omega, steps: np.ndarray, *,
                     chunk: int = 256, amplitude=None) -> np.ndarray:
    """Phi(T/2) of an undamped system, in its modal frame when it has one (complex), shape
    (P, 2n, 2n); :class:`PeriodMapOverflowError` where one overflows.

    Parameters
    ----------
    system : LinearPeriodicSystem
        From :func:`periodic_system`.
    Omega : array_like
        Shape (P,), rad per time unit of the matrices, > 0.
    steps : numpy.ndarray
        Shape (P,), integration steps of each point (:func:`step_counts`).
    chunk : int
        Points per batch of the dense kernel (memory).
    amplitude : array_like, optional
        Shape (P,): point p has the excitation amplitude[p] B (default 1).
    """
    om = as_omega(Omega)
    amp = _amplitudes(amplitude, om)
    steps = np.broadcast_to(np.asarray(steps), om.shape)
    n = system.n
    out = np.empty((om.size, 2 * n, 2 * n), dtype=complex)
    if system.Bt is None:
        return _dense_maps(system, om, steps, chunk, True, amp, out)
    order = np.argsort(-steps, kind="stable")
    # blocks of points whose work arrays (16 of n x 2n per point, 8 bytes each) stay in
    # a core's cache: a step of 256 points at n = 11 takes 15 % longer per point
    block = max(1, min(chunk, _MODAL_BLOCK_BYTES // (256 * n * n)))
    for start in range(0, order.size, block):
        sel = order[start:start + block]
        out[sel] = _half_modal(system, om[sel], steps[sel], amp[sel])
    return _finite(out, om)


def period_maps(system: LinearPeriodicSystem, Omega, steps: np.ndarray, *, chunk: int = 256,
                amplitude=None) -> np.ndarray:
    """Phi(T) in (q, q') by the dense kernel (damped systems), shape (P, 2n, 2n), real.

    Parameters
    ----------
    system, Omega, steps, chunk, amplitude
        As :func:`half_period_maps` (:class:`PeriodMapOverflowError` likewise).
    """
    om = as_omega(Omega)
    n = system.n
    steps = np.broadcast_to(np.asarray(steps), om.shape)
    return _dense_maps(system, om, steps, chunk, False, _amplitudes(amplitude, om),
                       np.empty((om.size, 2 * n, 2 * n)))


def _finite(Phi: np.ndarray, om: np.ndarray) -> np.ndarray:
    """Raise instead of returning an overflowed (inf / NaN) map."""
    bad = ~np.all(np.isfinite(Phi), axis=(-2, -1))
    if np.any(bad):
        raise PeriodMapOverflowError(
            f"Omega = {om[bad][:5]!r}: the monodromy overflowed (growth over one period beyond "
            "floating point)", om[bad][0])
    return Phi


def _reflection(n: int) -> np.ndarray:
    return np.concatenate([np.ones(n), -np.ones(n)])


def s_matrices(Phi: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """2 U_11, 2 (U_11 - I), 2 (U_11 + I): matrices whose eigenvalues are s = rho + 1/rho, s - 2
    and s + 2, each (P, n, n).

    U = Phi R Phi^-1 (Phi = Phi(T/2)), W = U R is similar to Phi(T) and W + W^-1 =
    diag(2 U_11, -2 U_22) (Magnus & Winkler 1966, sec. 2.2); s - 2 = eig(-4 Phi_12 P_21),
    s + 2 = eig(4 Phi_11 P_11), P = Phi^-1: near rho = +-1 a product of small factors.

    Parameters
    ----------
    Phi : numpy.ndarray
        Shape (P, 2n, 2n), from :func:`half_period_maps`.
    """
    n = Phi.shape[-1] // 2
    if np.iscomplexobj(Phi) and not np.any(Phi.imag):
        Phi = Phi.real  # real eigenvalues come out exactly real (s of a real system)
    Pinv = np.linalg.solve(Phi, np.broadcast_to(np.eye(2 * n), Phi.shape))
    Xm = 4.0 * Phi[:, :n, :n] @ Pinv[:, :n, :n]  # 2 (U_11 + I)
    Xp = -4.0 * Phi[:, :n, n:] @ Pinv[:, n:, :n]  # 2 (U_11 - I)
    S = 0.5 * (Xp + Xm)  # 2 U_11
    return S, Xp, Xm


def s_value_sets(Phi: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """s, s - 2 and s + 2 (each (P, n), each set in its own order) from the half-period map.

    Parameters
    ----------
    Phi : numpy.ndarray
        Shape (P, 2n, 2n): the eigenvalues of the matrices of :func:`s_matrices`.
    """
    S, Xp, Xm = s_matrices(Phi)
    return np.linalg.eigvals(S), np.linalg.eigvals(Xp), np.linalg.eigvals(Xm)


def largest_multiplier(xp: np.ndarray, xm: np.ndarray) -> np.ndarray:
    """|rho|_max, shape (P,): rho = s/2 + sqrt((s/2 - 1)(s/2 + 1)) with the small factor from s - 2
    (where Re s >= 0) or s + 2.

    Parameters
    ----------
    xp, xm : numpy.ndarray
        Shape (P, n): s - 2 and s + 2 (:func:`s_value_sets`).
    """
    xp = xp.astype(complex)
    xm = xm.astype(complex)
    sp = 2.0 + xp
    rp = np.sqrt(0.5 * xp * (2.0 + 0.5 * xp))  # (s/2 - 1)(s/2 + 1), s = 2 + xp
    ap = np.maximum(np.abs(0.5 * sp + rp), np.abs(0.5 * sp - rp))
    sm = xm - 2.0
    rm = np.sqrt(0.5 * xm * (0.5 * xm - 2.0))  # s = xm - 2
    am = np.maximum(np.abs(0.5 * sm + rm), np.abs(0.5 * sm - rm))
    ap = np.where(sp.real >= 0.0, ap, 0.0)
    am = np.where(sm.real < 0.0, am, 0.0)
    return np.maximum(np.max(ap, axis=-1), np.max(am, axis=-1))


def _reversible_multipliers(Phi: np.ndarray, om: np.ndarray) -> np.ndarray:
    """The 2n multipliers: eigenvalues of Phi(T/2) R Phi(T/2)^-1 R (QZ of the pencil (Phi R, R Phi)
    where Phi is singular); unpaired rho, 1/rho raise PeriodMapOverflowError.
    """
    R = _reflection(Phi.shape[-1] // 2)
    PhiR = Phi * R[None, None, :]
    with np.errstate(all="ignore"):
        try:
            inv = np.linalg.solve(Phi, np.broadcast_to(np.diag(R), Phi.shape))  # Phi^-1 R
            rho = np.linalg.eigvals(PhiR @ inv)
            bad = ~np.all(np.isfinite(rho) & (rho != 0.0), axis=-1)
        except np.linalg.LinAlgError:  # some point singular: each by the pencil below
            rho = np.zeros(Phi.shape[:-1], dtype=complex)
            bad = np.ones(Phi.shape[0], dtype=bool)
        for i in np.flatnonzero(bad):  # (Phi R) u = rho (R Phi) u
            rho[i] = scipy.linalg.eigvals(PhiR[i], R[:, None] * Phi[i])
        logs = np.log(np.abs(rho))
        unpaired = np.abs(np.sum(logs, axis=-1)) > 1e-6 * (1.0 + np.max(np.abs(logs), axis=-1))
    bad = ~np.all(np.isfinite(rho) & (rho != 0.0), axis=-1) | unpaired
    if np.any(bad):
        raise PeriodMapOverflowError(
            f"Omega = {float(om[bad][0]):.6g}: the period map is singular to working precision "
            "(a growth over one period beyond ~1e15)", om[bad][0])
    return rho


def _prepare(M, C, A, B, Omega, n_steps, step_phase, max_steps, chunk, amplitude):
    system = M if isinstance(M, LinearPeriodicSystem) else periodic_system(M, C, A, B)
    om = as_omega(Omega)
    if not isinstance(chunk, int | np.integer) or chunk < 1:
        raise ValueError(f"chunk = {chunk!r}: must be an integer >= 1")
    if n_steps is None:
        steps = step_counts(system, om, step_phase=step_phase, max_steps=max_steps,
                            amplitude=amplitude)
    else:
        steps = np.broadcast_to(np.asarray(n_steps), om.shape)
        if steps.dtype.kind not in "iu" or np.any(steps < 1) or np.any(steps > max_steps):
            raise ValueError(f"n_steps = {n_steps!r:.60}: must be integers in 1..{max_steps}")
    return system, om, steps, _amplitudes(amplitude, om)


def monodromy(M, C, A, B, Omega, *, n_steps=None, step_phase: float = 0.06,
              max_steps: int = MAX_STEPS, chunk: int = 256, amplitude=None) -> np.ndarray:
    """Monodromy matrices Phi(T), T = 2 pi / Omega: z(T) = Phi(T) z(0), z = (q, q'), shape
    (P, 2n, 2n), real (Bolotin 1964, sec. 2-3).

    Parameters
    ----------
    M, C, A, B : array_like
        The system, each (n, n), C may be None; or a :class:`LinearPeriodicSystem` as M.
    Omega : array_like
        Shape (P,), rad per time unit of the matrices, > 0.
    n_steps : int or array_like of int, optional
        Steps per interval, for all or per point (default :func:`step_counts`).
    step_phase, max_steps : float, int
        Accuracy and cap of :func:`step_counts`.
    chunk : int
        Points per batch (memory).
    amplitude : array_like, optional
        Shape (P,): point p has the excitation amplitude[p] B (default 1).
    """
    system, om, steps, amp = _prepare(M, C, A, B, Omega, n_steps, step_phase, max_steps,
                                      chunk, amplitude)
    n = system.n
    if system.damped:
        return period_maps(system, om, steps, chunk=chunk, amplitude=amp)
    Phi = half_period_maps(system, om, steps, chunk=chunk, amplitude=amp)
    R = _reflection(n)
    Mon = R[:, None] * np.linalg.solve(Phi, Phi * R[:, None])  # R Phi^-1 R Phi (reversibility)
    if system.Bt is not None:  # modal -> physical: blockdiag(V) Mon blockdiag(V)^-1
        T = scipy.linalg.block_diag(system.V, system.V)
        Mon = T @ Mon @ np.linalg.inv(T)
    if np.max(np.abs(Mon.imag)) <= 1e-10 * max(float(np.max(np.abs(Mon))), 1e-300):
        return Mon.real.copy()
    return Mon


def floquet_multipliers(M, C, A, B, Omega, *, n_steps=None, step_phase: float = 0.06,
                        max_steps: int = MAX_STEPS, chunk: int = 256,
                        amplitude=None) -> np.ndarray:
    """Floquet multipliers rho, the eigenvalues of the monodromy, shape (P, 2n), complex.

    Parameters
    ----------
    M, C, A, B, Omega, n_steps, step_phase, max_steps, chunk, amplitude
        As :func:`monodromy`.
    """
    system, om, steps, amp = _prepare(M, C, A, B, Omega, n_steps, step_phase, max_steps,
                                      chunk, amplitude)
    if system.damped:
        return np.linalg.eigvals(period_maps(system, om, steps, chunk=chunk, amplitude=amp))
    return _reversible_multipliers(half_period_maps(system, om, steps, chunk=chunk,
                                                    amplitude=amp), om)


def floquet_exponents(M, C, A, B, Omega, **options) -> np.ndarray:
    """Characteristic exponents log(rho) / T (principal log), shape (P, 2n), 1 / time unit.

    Parameters
    ----------
    M, C, A, B, Omega, **options
        As :func:`floquet_multipliers`.
    """
    rho = floquet_multipliers(M, C, A, B, Omega, **options)
    return np.log(rho) * (as_omega(Omega) / (2.0 * np.pi))[:, None]  # lambda = log(rho) / T


def growth_rate(M, C, A, B, Omega, *, n_steps=None, step_phase: float = 0.06,
                max_steps: int = MAX_STEPS, chunk: int = 256, amplitude=None) -> np.ndarray:
    """Largest real part of the characteristic exponents, log|rho|_max / T (1 / time unit), shape
    (P,); > 0 means unstable.

    Parameters
    ----------
    M, C, A, B, Omega, n_steps, step_phase, max_steps, chunk, amplitude
        As :func:`monodromy`.
    """
    system, om, steps, amp = _prepare(M, C, A, B, Omega, n_steps, step_phase, max_steps,
                                      chunk, amplitude)
    if system.damped:
        rho = np.linalg.eigvals(period_maps(system, om, steps, chunk=chunk, amplitude=amp))
        rho_max = np.max(np.abs(rho), -1)
    else:
        _, xp, xm = s_value_sets(half_period_maps(system, om, steps, chunk=chunk,
                                                  amplitude=amp))
        rho_max = largest_multiplier(xp, xm)
    return np.log(rho_max) * om / (2.0 * np.pi)  # log|rho|_max / T
