"""The memo's closed-form responses (6.2, errata fixed) and the resonance-safe kernel."""

from __future__ import annotations

from typing import Any

import numpy as np

from ...checks import finite_array
from .excitation import Excitation, checked_times
from .modal import ModalGroup, forcing_harmonics, modal_basis

__all__ = [
    "closed_form_0k",
    "closed_form_j0",
    "closed_form_jk",
    "harmonic_response",
]

def _convolution(omega: np.ndarray, nu: np.ndarray, f: np.ndarray, tau: np.ndarray) -> np.ndarray:
    """(1/omega) int_0^tau Re sum_h f_h e^{i nu_h eta} sin omega (tau - eta) d eta, memo form:
    the bracket of 6.2-3 / 6.2-28, omega (n,), nu (H,), f (n, H) -> (n, nt).
    """
    w = omega[:, None, None]
    v = nu[None, :, None]
    t = tau[None, None, :]
    br = (np.exp(1j * v * t) - np.cos(w * t) - 1j * (v / w) * np.sin(w * t)) / (w**2 - v**2)
    return np.real(np.einsum("nh,nht->nt", f, br))  # eqs. (6.2-3), (6.2-28)


def closed_form_0k(omega: Any, u0: Any, nu: Any, P: Any, tau: Any) -> np.ndarray:
    """U_0k(tau) (units of L), shape (n, nt), of eq. (6.2-3): U'' + omega^2 U = P, U(0) = u0,
    U'(0) = 0; errata R-1, R-2 (docs/memo-errata.md).

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
    """
    omega = np.atleast_1d(finite_array("omega", omega, positive=True))
    tau = checked_times(tau)
    nu = np.atleast_1d(finite_array("nu", nu, nonempty=False))
    P = np.asarray(P, dtype=complex)
    if P.size != omega.size * nu.size or not np.all(np.isfinite(P)):
        raise ValueError(f"P: must be finite, shape ({omega.size}, {nu.size}) (got shape "
                         f"{P.shape})")
    P = P.reshape(omega.size, nu.size)
    u0 = np.broadcast_to(finite_array("u0", u0), omega.shape)
    free = u0[:, None] * np.cos(omega[:, None] * tau)  # (u_0k) cos omega tau (6.2-3)
    return free + _convolution(omega, nu, P, tau)


def closed_form_j0(coef: dict, u0: Any, w0: Any, nu: Any, P1: Any, P2: Any,
                   tau: Any, form: str = "corrected") -> tuple[np.ndarray, np.ndarray]:
    """U_j0, W_j0 (units of L), each (n, nt), of eqs. (6.2-8), (6.2-9) (evaluated: 6.2-11, 6.2-12),
    with omega_m^2 of 6.2-6 (E6) and the convolutions I_m; errata R-3 (factor 1/(a_j0 j_j0)),
    R-4 ((b_j0) w_j0 for (h_j0) w_j0).

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
        ``"printed"``: 6.2-8/9 as printed (without the R-3, R-4 corrections).
    """
    a, b, c, d, h, j, k = (np.atleast_1d(np.asarray(coef[x], dtype=float))
                           for x in ("a", "b", "c", "d", "h", "j", "k"))
    tau = checked_times(tau)
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
    """(U, V, W)_jk (units of L), shape (n, 3, nt), of eq. (6.2-20) with the convolutions
    (6.2-25..30): x = sum_m adj(K - omega_m^2 M) / (det M D_m) [M x0 cos omega_m tau + I_m[Q]],
    D_m = prod_{i != m} (omega_i^2 - omega_m^2) (6.2-21); erratum R-5.

    Parameters
    ----------
    mass, stiff : array_like
        Shape (n, 3, 3), M and K of (5.4-8).
    x0 : array_like
        Shape (n, 3), initial displacements (units of L), zero velocities.
    nu : array_like
        Shape (H,), forcing frequencies (units of omega_1).
    Q : array_like
        Shape (n, 3, H) complex: [Q_jk]_1..3 = Re sum_h Q_h e^{i nu_h tau}.
    tau : array_like
        Output times.
    """
    mass, stiff = finite_array("mass", mass), finite_array("stiff", stiff)
    if mass.size % 9 or stiff.shape != mass.shape:
        raise ValueError(f"mass, stiff: must both have shape (n, 3, 3) (got {mass.shape}, "
                         f"{stiff.shape})")
    mass, stiff = mass.reshape(-1, 3, 3), stiff.reshape(-1, 3, 3)
    n = mass.shape[0]
    tau = checked_times(tau)
    nu = np.atleast_1d(finite_array("nu", nu, nonempty=False))
    x0 = finite_array("x0", x0)
    Q = np.asarray(Q, dtype=complex)
    if x0.size != 3 * n or Q.size != 3 * n * nu.size or not np.all(np.isfinite(Q)):
        raise ValueError(f"x0, Q: must be finite, shapes ({n}, 3) and ({n}, 3, {nu.size}) "
                         f"(got {x0.shape}, {Q.shape})")
    x0, Q = x0.reshape(n, 3), Q.reshape(n, 3, nu.size)
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
    """Response of y'' + omega^2 y = e^{i nu tau} from rest, finite for every nu:
    y = tau / (2 i omega) [e^{i omega tau} E(i(nu - omega) tau) - e^{-i omega tau}
    E(i(nu + omega) tau)], E(z) = (e^z - 1)/z (the bracket of 6.2-3 off resonance).
    """
    w = omega[..., None, None]
    v = nu[:, None]
    t = tau[None, :]
    return (t / (2j * w)) * (np.exp(1j * w * t) * _E((v - w) * t)
                             - np.exp(-1j * w * t) * _E((v + w) * t))


def harmonic_response(group: ModalGroup, ex: Excitation, tau: Any,
                      x0: Any = None) -> np.ndarray:
    """Exact response (units of L), shape (n, p, nt), of every mode of a group to the harmonic
    forcing, growing like tau at an exact resonance (6.2-3, 6.2-11, 6.2-12, 6.2-20): the bracket
    of 6.2-3 as one matrix product off resonance, :func:`_kernel` within (|nu| - omega) tau_max
    < 1e-2.

    Parameters
    ----------
    group : ModalGroup
        The stacked systems.
    ex : Excitation
        The time functions.
    tau : array_like
        Output times (>= 0).
    x0 : array_like, optional
        Shape (n, p), initial displacements (units of L), zero velocities.
    """
    tau = checked_times(tau)
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
