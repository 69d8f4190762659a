"""Pipeline entry: time histories of every forced shell mode at one thrust frequency (memo 6.2).

Part of :mod:`flexbooster.memo.responses`; see its docstring for the model.

References
----------
.. [1] Tech Memo 104, sections 4.1, 4.2, 5.2-5.4, 6.1, 6.2, 7.1.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from ...checks import count, finite, positive
from ..model import BoosterModel
from ..shell_coefficients import ShellParameters
from .closed_form import harmonic_response
from .excitation import Excitation, ExcitationParameters, make_excitation
from .fields import displacement_fields
from .integrate import integrate
from .modal import modal_groups

__all__ = [
    "SimulationResult",
    "simulate",
]

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


def simulate(model: BoosterModel, Omega: float, tau_max: float, n_out: int = 401,
             modes: tuple[int, int, int, int] | None = None, psi0: float = 0.01,
             beam_amplitude: float = 1e-4, beam_mode: int = 1, initial: dict | None = None,
             method: str = "closed-form", n_snapshots: int = 4, n_xi: int = 61,
             n_theta: int = 49, phase: str = "zero",
             params: ExcitationParameters | None = None) -> SimulationResult:
    """Time histories of every forced shell mode at the thrust frequency Omega (pipeline entry).

    Parameters
    ----------
    model : BoosterModel
        The derived model; ``truncation.M1, N1, M2, N2, N, S`` are used.
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
    params : ExcitationParameters, optional
        The pipeline's parameter function (beta, alpha_r), as used by the stability roots:
        with it a simulation at a root of the table is exactly resonant (see
        :func:`make_excitation`).

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
