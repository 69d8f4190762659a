"""Harmonic balance of M q'' + C q' + (A + B cos Omega t) q = 0: Hill's exponents (a linear
eigenproblem in the exponent per Omega) and the T- / 2T-periodic boundaries of the simple
regions (an eigenproblem in Omega). Bolotin 1964, ch. 1 sec. 3-5, ch. 2 sec. 7-8; Magnus &
Winkler 1966, ch. 2.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.linalg

from .multipliers import LinearPeriodicSystem, as_omega, periodic_system

__all__ = ["HillModes", "hill_exponents", "hill_modes", "periodic_boundaries",
           "converged_periodic_boundaries", "REAL_ROOT_RTOL"]

#: A root of :func:`periodic_boundaries` is real when |Im| <= this x |Omega| (the eigensolver's
#: round-off on well-conditioned roots).
REAL_ROOT_RTOL = 1e-9


def _system(M, C, A, B) -> LinearPeriodicSystem:
    return M if isinstance(M, LinearPeriodicSystem) else periodic_system(M, C, A, B)


def _harmonics(name: str, value, low: int = 0, high: int = 200) -> int:
    if isinstance(value, bool) or not isinstance(value, int | np.integer) or not (
            low <= value <= high):
        raise ValueError(f"{name} = {value!r}: must be an integer in {low}..{high}")
    return int(value)


@dataclass(frozen=True)
class HillModes:
    """Exponents and Fourier vectors from Hill's truncated determinant.

    Attributes
    ----------
    exponents : numpy.ndarray
        Shape (P, k), lambda (1 / time unit of the matrices).
    vectors : numpy.ndarray
        Shape (P, k, 2S + 1, n), unit Fourier vectors c_s (s = -S..S) of
        q = exp(lambda t) sum_s c_s exp(i s Omega t).
    centroid : numpy.ndarray
        Shape (P, k), sum_s s |c_s|^2.
    """

    exponents: np.ndarray
    vectors: np.ndarray
    centroid: np.ndarray


def _spectra(system: LinearPeriodicSystem, om: np.ndarray, S: int, chunk: int,
             amplitude: np.ndarray | None, real_form: bool):
    """Per chunk of points: (slice, lambda (P, 2m), c-parts (P, 2S + 1, n, 2m), centroids).

    With y_s = (lambda + i s Omega) c_s: lambda [c; y] = [[-D, I], [-M^-1 H, -D - M^-1 C]] [c; y],
    D = diag(i s Omega), H the Hill matrix (Bolotin 1964, eq. 7.4); ``real_form``: the undamped
    real form mu [c; y'] = [[-D', I], [M^-1 H, -D']] [c; y'], lambda = i mu (a third of the work).
    """
    n = system.n
    h = 2 * S + 1
    m = n * h
    s = np.arange(-S, S + 1)
    K0 = np.kron(np.eye(h), system.K0)  # blocks coupling s and s +- 1 below
    Kb = np.kron(np.eye(h, k=1) + np.eye(h, k=-1), 0.5 * system.Kb)
    Cm = np.kron(np.eye(h), system.Kc)
    idx = np.arange(m)
    for start in range(0, om.size, chunk):
        sl = slice(start, start + chunk)
        ob = om[sl]
        P = ob.size
        Hm = K0[None] + (Kb[None] if amplitude is None else amplitude[sl, None, None] * Kb[None])
        D = np.repeat(s, n)[None, :] * ob[:, None]  # (P, m)
        real = real_form and not system.damped
        if not real:
            Mat = np.zeros((P, 2 * m, 2 * m), dtype=complex)
            Mat[:, m:, :m] = -Hm
            Mat[:, m:, m:] = -Cm[None]
            D = 1j * D
        else:
            Mat = np.zeros((P, 2 * m, 2 * m))
            Mat[:, m:, :m] = Hm
        Mat[:, idx, idx] = -D
        Mat[:, idx, m + idx] = 1.0
        Mat[:, m + idx, m + idx] -= D
        lam, vec = np.linalg.eig(Mat)
        if real:
            lam = 1j * lam
        C = vec[:, :m, :].reshape(P, h, n, 2 * m)
        w = np.sum(np.abs(C) ** 2, axis=2)  # (P, h, 2m)
        cen = np.einsum("s,psk->pk", s.astype(float), w / np.sum(w, axis=1, keepdims=True))
        yield sl, lam, C, cen


def _hill_arguments(M, C, A, B, Omega, n_harmonics, chunk, amplitude):
    system = _system(M, C, A, B)
    om = as_omega(Omega)
    S = _harmonics("n_harmonics", n_harmonics, 0, 500)
    if not isinstance(chunk, int | np.integer) or chunk < 1:
        raise ValueError(f"chunk = {chunk!r}: must be an integer >= 1")
    if amplitude is not None:
        amplitude = np.broadcast_to(np.asarray(amplitude, dtype=float), om.shape)
        if not np.all(np.isfinite(amplitude)):
            raise ValueError(f"amplitude = {amplitude!r}: must be finite")
    return system, om, S, amplitude


def hill_exponents(M, C, A, B, Omega, *, n_harmonics: int = 8, chunk: int = 8,
                   amplitude=None, real_form: bool = False) -> np.ndarray:
    """Characteristic exponents lambda (1 / time unit), shape (P, 2n), by Hill's determinant.

    M (lambda + i s Omega)^2 c_s + C (lambda + i s Omega) c_s + A c_s + (B / 2)(c_(s-1) +
    c_(s+1)) = 0, s = -S..S: the 2n distinct eigenvalues (modulo i Omega) whose Fourier vectors
    are most central (Bolotin 1964, sec. 7-8).

    Parameters
    ----------
    M, C, A, B : array_like
        The system, each (n, n), C may be None; or a LinearPeriodicSystem as M.
    Omega : array_like
        Shape (P,), rad per time unit of the matrices, > 0.
    n_harmonics : int
        S, 0..500.
    chunk : int
        Points per batched eigen-solve (memory).
    amplitude : array_like, optional
        Shape (P,): point p has the excitation amplitude[p] B (default 1).
    real_form : bool
        Solve an undamped system in its real form (lambda = i mu): a third of the work.
    """
    system, om, S, amplitude = _hill_arguments(M, C, A, B, Omega, n_harmonics, chunk,
                                               amplitude)
    out = np.empty((om.size, 2 * system.n), dtype=complex)
    for sl, lam, _, cen in _spectra(system, om, S, chunk, amplitude, real_form):
        out[sl] = _distinct_central(lam, cen, om[sl], 2 * system.n)
    return out


def _distinct_central(lam: np.ndarray, cen: np.ndarray, om: np.ndarray,
                      count: int) -> np.ndarray:
    """The ``count`` most central exponents, distinct modulo i Omega: each moved by
    i round(centroid) Omega and copies dropped.
    """
    P, m2 = lam.shape
    top = min(m2, 4 * count)
    order = np.argsort(np.abs(cen), axis=1, kind="stable")[:, :top]
    lam = np.take_along_axis(lam, order, axis=1)
    cen = np.take_along_axis(cen, order, axis=1)
    lam = lam + 1j * np.round(cen) * om[:, None]  # relabel to the central Fourier vector
    half = 0.5 * om[:, None]
    im = np.mod(lam.imag + half, om[:, None]) - half  # fold Im to [-Omega/2, Omega/2)
    im = np.where(np.abs(im + half) <= 1e-7 * half, half[:, :1] * np.ones_like(im), im)
    key = lam.real + 1j * im
    scale = np.maximum(np.max(np.abs(key), axis=1), om)[:, None, None]
    close = np.abs(key[:, :, None] - key[:, None, :]) <= 1e-7 * scale
    dup = np.any(np.tril(close, k=-1), axis=2)  # equal to a more central one
    rank = np.where(dup, np.inf, np.arange(top)[None, :].astype(float))
    pick = np.argsort(rank, axis=1, kind="stable")[:, :count]
    return np.take_along_axis(lam, pick, axis=1)


def hill_modes(M, C, A, B, Omega, *, n_harmonics: int = 8, chunk: int = 8,
               amplitude=None, real_form: bool = False) -> HillModes:
    """The 2n eigenvalues of Hill's determinant whose Fourier vectors are most central, not
    shifted, with their unit vectors and centroids.

    Parameters
    ----------
    M, C, A, B, Omega, n_harmonics, chunk, amplitude, real_form
        As :func:`hill_exponents`.
    """
    system, om, S, amplitude = _hill_arguments(M, C, A, B, Omega, n_harmonics, chunk,
                                               amplitude)
    k = 2 * system.n
    lams, vecs, cents = [], [], []
    for _, lam, Cv, cen in _spectra(system, om, S, chunk, amplitude, real_form):
        P = lam.shape[0]
        sel = np.argsort(np.abs(cen), axis=1, kind="stable")[:, :k]
        vec = np.take_along_axis(Cv, sel[:, None, None, :], axis=3)
        vec = vec / np.linalg.norm(vec.reshape(P, -1, k), axis=1)[:, None, None, :]
        lams.append(np.take_along_axis(lam, sel, axis=1))
        vecs.append(np.moveaxis(vec, 3, 1))
        cents.append(np.take_along_axis(cen, sel, axis=1))
    return HillModes(exponents=np.concatenate(lams), vectors=np.concatenate(vecs),
                     centroid=np.concatenate(cents))


def periodic_boundaries(M, C, A, B, *, period: str = "2T", n_harmonics: int = 8,
                        omega_max: float | None = None,
                        imag_rtol: float = REAL_ROOT_RTOL) -> np.ndarray:
    """Omega at which a T- or 2T-periodic solution exists (simple-region boundaries): sorted real
    roots (|Im| > ``imag_rtol`` |Omega| dropped) of the truncated problem.

    [A - (k Omega / 2)^2 M + i (k Omega / 2) C] c_k + (B / 2)(c_(k-2) + c_(k+2)) = 0: an
    eigenproblem in Omega^2 (undamped) or quadratic in Omega (Bolotin 1964, ch. 1 sec. 3-5).

    Parameters
    ----------
    M, C, A, B : array_like
        The system, each (n, n), C may be None; or a LinearPeriodicSystem as M.
    period : {"2T", "T"}
        k odd (regions near 2 omega / j, j odd) or even (j even).
    n_harmonics : int
        K, |k| <= 2K, 1..100; the boundaries of order j need K well above j / 2.
    omega_max : float, optional
        Only roots 0 < Omega <= omega_max.
    imag_rtol : float
        A root is real when |Im| <= imag_rtol |Omega| (the eigensolver's round-off:
        :data:`REAL_ROOT_RTOL`, more where the roots are ill-conditioned), in (0, 1).
    """
    system = _system(M, C, A, B)
    K = _harmonics("n_harmonics", n_harmonics, 1, 100)
    if not (np.isfinite(imag_rtol) and 0.0 < imag_rtol < 1.0):
        raise ValueError(f"imag_rtol = {imag_rtol!r}: must be in (0, 1)")
    if period == "2T":
        k = np.arange(-(2 * K - 1), 2 * K, 2)
    elif period == "T":
        k = np.arange(-2 * K, 2 * K + 1, 2)
    else:
        raise ValueError(f"period = {period!r}: must be '2T' or 'T'")
    n = system.n
    h = k.size
    P0 = np.kron(np.eye(h), system.K0) + np.kron(np.eye(h, k=1) + np.eye(h, k=-1),
                                                 0.5 * system.Kb)  # Bolotin eq. (3.4)
    P1 = np.kron(np.diag(1j * k / 2.0), system.Kc)
    P2 = np.kron(np.diag(-(k / 2.0) ** 2), np.eye(n))  # -(k / 2)^2 (M^-1 M)
    if not system.damped:
        ev = scipy.linalg.eigvals(P0, -P2)  # Omega^2; k = 0 blocks give infinite values
        ev = ev[np.isfinite(ev)]
        ok = (np.abs(ev.imag) <= imag_rtol * np.abs(ev)) & (ev.real > 0.0)
        roots = np.sqrt(ev.real[ok])
    else:
        m = n * h
        Z, Id = np.zeros((m, m)), np.eye(m)
        Lhs = np.block([[Z, Id], [-P0, -P1]])  # linearisation of (Omega^2 P2 + Omega P1 + P0)
        Rhs = np.block([[Id, Z], [Z, P2]])
        ev = scipy.linalg.eigvals(Lhs, Rhs)
        ev = ev[np.isfinite(ev)]
        ok = (np.abs(ev.imag) <= imag_rtol * np.abs(ev)) & (ev.real > 0.0)
        roots = ev.real[ok]
    roots = np.sort(roots)
    if omega_max is not None:
        if not np.isfinite(omega_max) or omega_max <= 0.0:
            raise ValueError(f"omega_max = {omega_max!r}: must be finite and > 0")
        roots = roots[roots <= float(omega_max)]
    return roots


def converged_periodic_boundaries(M, C, A, B, *, period: str = "2T", omega_min: float,
                                  omega_max: float, rtol: float = 1e-10,
                                  max_harmonics: int = 64) -> tuple[np.ndarray, int]:
    """:func:`periodic_boundaries` with K = 4, 8, .. raised until two successive K agree; returns
    the roots in the range and the K used.

    Parameters
    ----------
    M, C, A, B, period
        As :func:`periodic_boundaries`.
    omega_min, omega_max : float
        Range of the roots (rad per time unit), 0 < omega_min < omega_max.
    rtol : float
        Agreement relative to omega_max, with as many roots.
    max_harmonics : int
        Largest K, 8..100 (ValueError past it).
    """
    for name, v in (("omega_min", omega_min), ("omega_max", omega_max), ("rtol", rtol)):
        if not np.isfinite(v) or v <= 0.0:
            raise ValueError(f"{name} = {v!r}: must be finite and > 0")
    if omega_min >= omega_max:
        raise ValueError(f"omega_min = {omega_min!r}: must be < omega_max = {omega_max!r}")
    Kmax = _harmonics("max_harmonics", max_harmonics, 8, 100)
    system = _system(M, C, A, B)

    def roots(K):
        r = periodic_boundaries(system, None, None, None, period=period, n_harmonics=K,
                                omega_max=omega_max)
        return r[r >= omega_min]

    prev = roots(4)
    for K in range(8, Kmax + 1, 4):
        cur = roots(K)
        if cur.size == prev.size and (cur.size == 0 or np.max(np.abs(cur - prev))
                                      <= rtol * omega_max):
            return cur, K
        prev = cur
    raise ValueError(f"max_harmonics = {max_harmonics!r}: the {period} boundaries in "
                     f"[{omega_min}, {omega_max}] did not converge to rtol = {rtol}")
