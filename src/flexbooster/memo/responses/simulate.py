"""Pipeline entry: time histories of every forced shell mode at one thrust frequency (memo 6.2)."""

from __future__ import annotations

from dataclasses import replace
from typing import Any

import numpy as np

from ...checks import count, finite, positive
from ..model import BoosterModel
from .closed_form import harmonic_response
from .excitation import ExcitationParameters, make_excitation
from .fields import displacement_fields
from .integrate import integrate
from .modal import modal_groups
from .result import SimulationResult

__all__ = ["simulate"]

def simulate(model: BoosterModel, Omega: float, tau_max: float, n_out: int = 401,
             modes: tuple[int, int, int, int] | None = None, psi0: float = 0.01,
             beam_amplitude: float = 1e-4, beam_mode: int = 1, initial: dict | None = None,
             method: str = "closed-form", n_snapshots: int = 4, n_xi: int = 61,
             n_theta: int = 49, phase: str = "zero",
             params: ExcitationParameters | None = None) -> SimulationResult:
    """Time histories of every forced shell mode at the thrust frequency Omega (memo 4.1-10/11,
    4.2-6, 5.2-1, 5.3-4, 6.1, 6.2); ValueError for bad input or an unbounded pitch motion.

    Parameters
    ----------
    model : BoosterModel
        The derived model; ``truncation.M1, N1, M2, N2, N, S`` are used.
    Omega : float
        Thrust pulsation frequency (rad/s), > 0.
    tau_max : float
        Last time tau = omega_1 t, > 0, at most 1e6.
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
        ``"closed-form"``: :func:`harmonic_response` (finite at resonance, any tau); the others:
        :func:`integrate`.
    n_snapshots : int
        Instants (evenly spread) at which the fields are rebuilt, 0..50.
    n_xi, n_theta : int
        Grid of the snapshots, 2..2001.
    phase : {"zero", "printed"}
        Shape-function phase (E10).
    params : ExcitationParameters, optional
        The pipeline's parameter function: with it a simulation at a root is exactly resonant.
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
    tr = model.truncation
    M1, N1, M2, N2 = (tr.M1, tr.N1, tr.M2, tr.N2) if modes is None else modes
    ex = make_excitation(model, Omega, psi0=psi0, beam_amplitude=beam_amplitude,
                         beam_mode=beam_mode, params=params)
    groups = modal_groups(model.shell, (M1, M2), (N1, N2), ex.N, phase)
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
        Omega=Omega, omega_1=model.omega_1, tau=tau, t=tau / model.omega_1, psi=ex.psi(tau),
        q=ex.beam(tau), cylinder=cat(rows_c, int), j=cat(rows_j, int), k=cat(rows_k, int),
        component=cat(rows_comp, str), amplitude=amplitude, params=model.shell, excitation=ex,
        phase=phase, method=method, T0=model.T0, radii=model.radii, warnings=ex.warnings)
    if not np.all(np.isfinite(res.amplitude)):
        raise RuntimeError("simulate: non-finite response (an internal error: report this case)")
    if n_snapshots:
        idx = np.unique(np.linspace(0, tau.size - 1, n_snapshots).round().astype(int))
        p = model.shell
        xi = np.linspace(p.a, p.b, n_xi)
        th = np.linspace(0.0, 2.0 * np.pi, n_theta)
        u, v, w = displacement_fields(res, xi, th, idx)
        snaps = {"xi": xi, "theta": th, "index": idx, "tau": tau[idx],
                 "u": np.moveaxis(u, 2, 0), "v": np.moveaxis(v, 2, 0), "w": np.moveaxis(w, 2, 0)}
        res = replace(res, snapshots=snaps)
    return res
