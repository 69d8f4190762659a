"""Secular growth of a shell mode at a root of the stability table (memo 7.1)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...checks import count, finite, positive
from ..model import BoosterModel
from .excitation import (
    Excitation,
    ExcitationParameters,
    beam_exponents_on,
    excitation_at,
    make_excitation,
)
from .integrate import integrate
from .modal import ModalGroup, cylinder_groups, forcing_harmonics, modal_basis

__all__ = [
    "SecularGrowth",
    "secular_growth",
    "modal_forcing_spectrum",
    "secular_rates",
]

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
        |least-squares slope| of Z = (y' + i omega y) e^{-i omega tau} against tau, weighted by
        sin^4(pi tau / tau_max) (a detuned harmonic leaks like (Delta tau_max)^-5).
    predicted_slope : float
        The same from the forcing's harmonics: |sum of the amplitudes at nu = +-omega| / 2.
    growth_rate : float
        slope / omega: growth of the amplitude of y per unit tau.
    index : float
        slope tau_max / max |Z - Z(0)|: about 1 for secular growth, << 1 bounded.
    envelope_ratio : float
        max |y| over the last quarter over that of the first (about 4 for growth like tau).
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


def secular_growth(model: BoosterModel, Omega: float, cylinder: int, j: int, k: int, branch: int,
                   tau_max: float, n_out: int = 2001, psi0: float = 0.01,
                   beam_amplitude: float = 1e-4, beam_mode: int = 1, N: int | None = None,
                   S: int | None = None, phase: str = "zero",
                   resonance_tol: float = 1e-8,
                   params: ExcitationParameters | None = None) -> SecularGrowth:
    """Integrate one shell mode's forced modal ODE at Omega (:func:`integrate`, "duhamel") and
    measure the drift of Z' = f e^{-i omega tau}: linear at a resonant harmonic (memo 7.1).

    Parameters
    ----------
    model : BoosterModel
        The derived model.
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
        |nu -+ omega| / omega below which a harmonic counts as resonant for ``predicted_slope``.
    params : ExcitationParameters, optional
        The pipeline's parameter function (as the stability roots use it).
    """
    tau_max = positive("tau_max", tau_max)
    n_out = count("n_out", n_out, 16, 200_000)
    g, ex, branch = _single_mode(model, Omega, cylinder, j, k, branch, psi0, beam_amplitude,
                                 beam_mode, N, S, phase, params)
    d = g.cylinder
    tau = np.linspace(0.0, tau_max, n_out)
    _, Z = integrate(g, ex, tau, method="duhamel", return_normal=True)
    omega = modal_basis(g)[0]
    w = float(omega[0, branch - 1])
    z = Z[0, branch - 1]
    wgt = np.sin(np.pi * tau / tau_max) ** 4  # smooth window: leakage ~ (detuning tau_max)^-5
    tc = tau - np.sum(wgt * tau) / np.sum(wgt)
    slope = complex(np.sum(wgt * tc * z) / np.sum(wgt * tc**2))  # weighted least squares
    nu, gh, _ = modal_forcing_spectrum(model, Omega, cylinder, j, k, branch, psi0,
                                       beam_amplitude, beam_mode, N, S, phase, params=params)
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


def _single_mode(model: BoosterModel, Omega: float, cylinder: int, j: int, k: int, branch: int,
                 psi0: float, beam_amplitude: float, beam_mode: int, N: int | None,
                 S: int | None, phase: str, params: ExcitationParameters | None
                 ) -> tuple[ModalGroup, Excitation, int]:
    d = count("cylinder", cylinder, 1, 2)
    j = count("j", j, 0)
    k = count("k", k, 0)
    if j == 0 and k == 0:
        raise ValueError("j = k = 0: the rigid mode U_00 has no frequency (6.2.1)")
    ex = make_excitation(model, Omega, psi0=psi0, beam_amplitude=beam_amplitude,
                         beam_mode=beam_mode, N=N, S=S, params=params)
    kind = "0k" if j == 0 else ("j0" if k == 0 else "jk")
    groups = cylinder_groups(model.shell, d, max(j, 1), max(k, 1), ex.N, phase)
    g = [x for x in groups if x.kind == kind][0]
    g = g.select(np.flatnonzero((g.j == j) & (g.k == k)))
    branch = count("branch", branch, 1, g.mass.shape[-1])
    return g, ex, branch


def modal_forcing_spectrum(model: BoosterModel, Omega: float, cylinder: int, j: int, k: int,
                           branch: int, psi0: float = 0.01, beam_amplitude: float = 1e-4,
                           beam_mode: int = 1, N: int | None = None, S: int | None = None,
                           phase: str = "zero", params: ExcitationParameters | None = None
                           ) -> tuple[np.ndarray, np.ndarray, float]:
    """Harmonics of the forcing of one normal coordinate, f = Re sum_h g_h e^{i nu_h tau}: nu (H,)
    (units of omega_1), g (H,) (units of L omega_1^2) and the branch's omega (memo 7.1).

    Parameters
    ----------
    model, Omega, cylinder, j, k, branch, psi0, beam_amplitude, beam_mode, N, S, phase, params :
        As :func:`secular_growth`.
    """
    g, ex, branch = _single_mode(model, Omega, cylinder, j, k, branch, psi0, beam_amplitude,
                                 beam_mode, N, S, phase, params)
    omega, _, P = modal_basis(g)
    nu, f = forcing_harmonics(g, ex)
    gh = np.einsum("ij,jh->ih", P[0], f[0])[branch - 1]
    return nu, gh, float(omega[0, branch - 1])


def secular_rates(model: BoosterModel, rows: list[dict], psi0: float = 0.01,
                  beam_amplitude: float = 1e-4, N: int | None = None, S: int | None = None,
                  phase: str = "zero", params: ExcitationParameters | None = None
                  ) -> list[dict]:
    """Resonant forcing of the shell mode at every root of a stability table (memo 6.2, 7.1), the
    beam exponents of all roots from one batched Hill computation.

    Per row: ``secular_rate`` (|resonant forcing| / (2 omega), units of L per unit tau),
    ``relative`` (over the largest forcing harmonic of all the rows' modes: ~1e-19 for a
    structural zero, above 1e-15 for genuine weak terms) and ``forced`` (relative > 1e-18).

    Parameters
    ----------
    model : BoosterModel
        The derived model.
    rows : list of dict
        :meth:`flexbooster.memo.stability.StabilityTable.to_rows`.
    psi0 : float
        Initial pitch angle (rad) of the rigid-body forcing.
    beam_amplitude : float
        Norm of the beam Floquet vector (units of L).
    N, S : int, optional
        Beam modes and harmonics (default: the case's truncation).
    phase : {"zero", "printed"}
        Shape-function phase.
    params : ExcitationParameters, optional
        The pipeline's parameter function (as the stability roots use it).
    """
    N = count("N", model.truncation.N if N is None else N, 0)
    S = count("S", model.truncation.S if S is None else S, 0)
    psi0, beam_amplitude = finite("psi0", psi0), finite("beam_amplitude", beam_amplitude)
    if not rows:
        return []
    Om = np.array([float(x["Omega_rad_s"]) for x in rows])
    pre = None
    if beam_amplitude != 0.0:
        hill, nat = beam_exponents_on(model, Om / model.omega_1, N, S)
    groups_cache: dict[tuple, ModalGroup] = {}
    out = []
    for n, x in enumerate(rows):
        if beam_amplitude != 0.0:
            pre = (hill.alpha[n], hill.C[n], nat[n])
        ex = excitation_at(model, Om[n], psi0, beam_amplitude, max(int(x.get("r", 0)), 1),
                              N, S, params, pre)
        d, j, k, m = (int(x[key]) for key in ("cylinder", "j", "k", "branch"))
        kind = "0k" if j == 0 else ("j0" if k == 0 else "jk")
        key = (d, j, k)
        if key not in groups_cache:
            groups = cylinder_groups(model.shell, d, max(j, 1), max(k, 1), N, phase)
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
