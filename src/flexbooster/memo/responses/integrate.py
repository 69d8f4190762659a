"""Numerical integration of the modal systems: solve_ivp and the exact-propagation Duhamel scheme
(Meirovitch 1986, ch. 4; Hairer, Norsett, Wanner 1993, DOP853).
"""

from __future__ import annotations

from typing import Any

import numpy as np
from scipy.special import roots_legendre

from .excitation import Excitation, checked_times
from .modal import ModalGroup, modal_basis

_GAUSS = 8  # Gauss-Legendre nodes per step of the Duhamel integrator

__all__ = [
    "integrate",
]

def integrate(group: ModalGroup, ex: Excitation, tau: Any, x0: Any = None,
              method: str = "DOP853", rtol: float = 1e-12, atol: float | None = None,
              return_normal: bool = False) -> np.ndarray:
    """Response of every mode of a group by numerical integration from rest in velocity: U, (U, W)
    or (U, V, W) (units of L), shape (n, p, nt) (and Z if requested) (memo 6.1-2..6.1-4).

    Parameters
    ----------
    group : ModalGroup
        The stacked systems.
    ex : Excitation
        The time functions.
    tau : array_like
        Output times tau = omega_1 t, non-decreasing, >= 0 (integration starts at 0).
    x0 : array_like, optional
        Shape (n, p), initial displacements (units of L); default zero.
    method : {"DOP853", "Radau", "duhamel"}
        solve_ivp on the stacked first-order system, or each normal coordinate propagated
        exactly with the Duhamel integral by 8-point Gauss-Legendre on steps of phase <= 2 rad.
    rtol : float
        Relative tolerance of solve_ivp.
    atol : float, optional
        Absolute tolerance of solve_ivp (default rtol 1e-3 max |M^-1 F| / min omega^2).
    return_normal : bool
        ``"duhamel"`` only: also return Z = (y' + i omega y) e^{-i omega tau}, (n, p, nt).
    """
    tau = checked_times(tau)
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
    from scipy import integrate as sp_integrate  # only here: a tenth of a run's imports

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
