"""Physical displacement fields u, v, w in metres (memo 5.2-1 with 5.3-4) and edge conditions."""

from __future__ import annotations

from typing import Any

import numpy as np

from ...checks import count, finite_array
from ..shell_coefficients import ShellParameters
from .modal import beam_shapes_at, edge_argument
from .result import SimulationResult

__all__ = [
    "displacement_fields",
    "edge_conditions",
]

def _axial_shape(p: ShellParameters, d: int, j: np.ndarray, xi: np.ndarray, kind: str,
                 phase: str, order: int) -> np.ndarray:
    """order-th xi-derivative of cos s (kind "cos") or sin s ("sin") of modes j at xi."""
    j = np.asarray(j)
    alpha = j * np.pi * p.L / (2.0 * p.half_length(d))
    s = (edge_argument(p, d, j, phase)[:, None]
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
    """u, v, w (xi_bar, theta, instant) in metres, each (nx, nq, ni), from the modal sums (5.2-1)
    and the beam part (4.1-3..7, 5.3-4); axial, circumferential, radial inward (memo 3.0).

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
        Derivative order 0..4 in xi_bar (metres per unit xi_bar^order).
    part : {"total", "shell", "beam"}
        The modal sums, the beam part u*, v*, w*, or both.
    junction : {"forward", "aft"}
        Which cylinder's modes the junction xi = c takes (the fields jump there).
    """
    p = result.params
    xi = np.atleast_1d(finite_array("xi", xi))
    theta = np.atleast_1d(finite_array("theta", theta))
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
        bs = beam_shapes_at(p, xi, ex.N)
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
    """How well the rebuilt fields meet the edge conditions (5.3-1) at the ends and junction:
    largest values over the instants and angles (theta derivatives by FFT).

    Keys: ``shell_v_edges``, ``shell_w_edges`` (m), ``shell_u_xi_edges``,
    ``shell_w_xixi_edges`` (zero in the zero phase), ``scale`` (largest |u|, |v|, |w|),
    ``v_xi_ends``, ``w_xi_ends`` (5.3-1a, b), ``N_aft_error``, ``N_nose`` (5.3-1d, e; Donnell
    N_x, Leissa 1973 eq. 1.3), ``M_shell_ends``, ``M_beam_ends`` (5.3-1c, m^-1).

    Parameters
    ----------
    result : SimulationResult
        The simulation.
    n_theta : int
        Angles at which the conditions are sampled.
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
