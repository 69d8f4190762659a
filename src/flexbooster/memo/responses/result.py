"""The result of :func:`flexbooster.memo.responses.simulate`: time histories of the forced shell
modes at one thrust frequency (memo 6.1, 6.2).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..shell_coefficients import ShellParameters
from .excitation import Excitation

__all__ = ["SimulationResult"]


@dataclass(frozen=True)
class SimulationResult:
    """Modal time histories of the two shells at one thrust frequency (memo 6.2).

    Attributes
    ----------
    Omega, omega_1 : float
        Thrust pulsation and reference frequency (rad/s); tau = omega_1 t.
    tau, t : numpy.ndarray
        Shape (nt,), dimensionless times and times (s).
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
    phase, method : str
        Shape-function phase; how the responses were computed.
    T0 : float
        Steady thrust per unit circumference (N/m).
    radii : tuple of float
        R1, R2 (m).
    snapshots : dict
        ``xi``, ``theta``, ``index``, ``u``, ``v``, ``w`` (ns, nx, nq) in metres.
    warnings : tuple of str
        Conditions of the excitation.
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
