"""One harmonic's periodic modal system q'' + C q' + (A + gamma B1 cos Omega t) q = 0 (Bolotin
1964, sec. 8), its labelled modes and its regions with their critical amplitudes (sec. 6);
shared by :mod:`.regions` (k >= 2) and :mod:`.bending` (k = 1).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .. import floquet
from ..bands import Band, BandMode, SearchGap
from ..checks import count, finite, nonnegative, positive
from ..shell_of_revolution import BucklingError, buckling_load, labelled_modal_system

__all__ = ["ModalMatrices", "HarmonicSystem", "LIMIT_ERRORS",
           "floquet_options", "harmonic_regions", "limit_gap", "in_unit_interval", "loaded_modes"]

#: The toolkit's size limits: past one a harmonic is a :class:`~flexbooster.bands.SearchGap`.
LIMIT_ERRORS = (floquet.TooManyCandidatesError, floquet.StepLimitError,
                floquet.PeriodMapOverflowError)


class ModalMatrices:
    """Base of a periodic modal system with fields mass, damping, stiffness, excitation."""

    __slots__ = ()

    def matrices(self, gamma: float) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """(M, C, A, B = gamma B1) for T = F0 (1 - gamma cos Omega t), 0 <= gamma < 1
        (-, 1/s, 1/s^2, 1/s^2)."""
        gamma = in_unit_interval("gamma", gamma)
        return self.mass, self.damping, self.stiffness, gamma * self.excitation


@dataclass(frozen=True)
class HarmonicSystem(ModalMatrices):
    """Periodic modal system of one harmonic: M q'' + C q' + (A + gamma B1 cos Omega t) q = 0.

    k >= 2: the loaded basis, M = I, A = diag(omega_loaded^2), B1 = -V^T K_g V, C = 2 zeta
    diag(omega_loaded); k = 1: the unloaded basis with the rigid pitch (A neither diagonal nor
    symmetric), ``omega_loaded`` sqrt(Re eig A), ``basis`` its unit eigenvectors' real parts.

    Attributes
    ----------
    k : int
        Circumferential wave number.
    F0 : float
        Steady thrust (N).
    damping_ratio : float
        Modal damping ratio zeta.
    omega_unloaded, omega_loaded : ndarray, shape (n,)
        Basis frequencies without thrust and steady frequencies under F0 (rad/s).
    basis : ndarray, shape (n, n)
        Column j: steady mode j in the basis coordinates.
    mass, damping, stiffness, excitation : ndarray, shape (n, n)
        M, C (1/s), A and B1 (1/s^2).
    mode_order, mode_type, mode_share : ndarray, shape (n,)
        Labels of the basis mode dominating each steady mode, and its share.
    """

    k: int
    F0: float
    damping_ratio: float
    omega_unloaded: np.ndarray
    omega_loaded: np.ndarray
    basis: np.ndarray
    mass: np.ndarray
    damping: np.ndarray
    stiffness: np.ndarray
    excitation: np.ndarray
    mode_order: np.ndarray
    mode_type: np.ndarray
    mode_share: np.ndarray

    def mode(self, index: int) -> BandMode:
        """Label of steady mode ``index``: type, meridian order, k, loaded frequency (rad/s) and the
        share of its dominant basis mode.
        """
        index = count("index", index, 0, self.omega_loaded.size - 1)
        order, kind = int(self.mode_order[index]), str(self.mode_type[index])
        return BandMode(label=f"{kind} {order}", index=index, k=self.k, order=order,
                        type=kind, omega=float(self.omega_loaded[index]),
                        share=float(self.mode_share[index]))

    @property
    def damping_per_ratio(self) -> np.ndarray:
        """C per unit damping ratio (1/s): 2 diag(omega) of the basis (the loaded one for
        k >= 2, the unloaded one with 0 on the rigid modes for k = 1), so that C = zeta times
        this."""
        omega = self.omega_unloaded if self.k == 1 else self.omega_loaded
        return 2.0 * np.diag(omega)  # C = 2 zeta diag(omega) (Meirovitch 1986, sec. 4.10)

    def periodic(self, gamma: float) -> tuple:
        """(M, C or None when undamped, A, B) for :mod:`flexbooster.floquet`."""
        M, C, A, B = self.matrices(gamma)
        return M, (C if self.damping_ratio > 0.0 else None), A, B

    def to_dict(self) -> dict:
        """JSON-ready mapping."""
        return {"k": int(self.k), "F0": float(self.F0),
                "damping_ratio": float(self.damping_ratio),
                "omega_unloaded": self.omega_unloaded.tolist(),
                "omega_loaded": self.omega_loaded.tolist(), "basis": self.basis.tolist(),
                "damping": self.damping.tolist(), "stiffness": self.stiffness.tolist(),
                "excitation": self.excitation.tolist(),
                "mode_order": [int(v) for v in self.mode_order],
                "mode_type": [str(v) for v in self.mode_type],
                "mode_share": self.mode_share.tolist()}


def in_unit_interval(name: str, value) -> float:
    """A dimensionless value checked to lie in [0, 1) (ValueError naming it).

    Parameters
    ----------
    name : str
        The argument's name.
    value : float
        The value.
    """
    x = nonnegative(name, value)
    if x >= 1.0:
        raise ValueError(f"{name} = {value!r}: must be in [0, 1)")
    return x


def loaded_modes(vehicle, k: int, n_modes: int, F0: float, *,
                 supported_forward_end: bool | None,
                 elements_per_segment, order, unloaded_frequencies: bool = True) -> tuple:
    """(modal system, its labels, w2, V): eigenpairs of K_e + K_g in the mass-normalised loaded
    basis (V = I to round-off); BucklingError with the load factor when a loaded omega^2 <= 0.

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    k, n_modes : int
        Harmonic; loaded modes in the basis.
    F0 : float
        Steady thrust (N), > 0.
    supported_forward_end, elements_per_segment, order
        As :func:`.regions.harmonic_system`.
    unloaded_frequencies : bool
        Also the unloaded frequencies (``ms.omega_unloaded``; False: empty, one eigenproblem
        fewer; :func:`flexbooster.shell_of_revolution.labelled_modal_system`).
    """
    mesh = {"elements_per_segment": elements_per_segment, "order": order}
    ms, labels = labelled_modal_system(vehicle, k, n_modes, F0,
                                       supported_forward_end=supported_forward_end,
                                       unloaded_frequencies=unloaded_frequencies, **mesh)
    w2, V = np.linalg.eigh(ms.stiffness + ms.geometric)
    if w2[0] <= 0.0:
        lam = float(buckling_load(vehicle, k, F0=F0, supported_forward_end=supported_forward_end,
                                  **mesh).load_factor[0])
        raise BucklingError(f"F0 = {F0!r}: the steady thrust buckles harmonic k = {k} (load "
                            f"factor lambda = {lam:.6g} <= 1, critical thrust {lam * F0:.6g} "
                            f"N; loaded omega^2 = {w2[0]:.4g} 1/s^2)", k, F0, lam)
    return ms, labels, w2, V


def floquet_options(rtol=1e-9, step_phase=0.12, max_order=None,
                    damping_margin=floquet.DAMPING_MARGIN) -> dict:
    """Checked options of :func:`flexbooster.floquet.instability_regions`.

    Parameters
    ----------
    rtol, step_phase, max_order, damping_margin
        Edge tolerance and step phase (dimensionless), largest order j (None or 1..10000),
        damping filter (None or >= 1).
    """
    opts = {"rtol": finite("rtol", rtol), "step_phase": positive("step_phase", step_phase)}
    if damping_margin is not None:
        if isinstance(damping_margin, bool) or finite("damping_margin", damping_margin) < 1:
            raise ValueError(f"damping_margin = {damping_margin!r}: must be None or >= 1")
        damping_margin = float(damping_margin)
    opts["damping_margin"] = damping_margin
    if max_order is not None:
        opts["max_order"] = count("max_order", max_order, 1, 10_000)
    return opts


def harmonic_regions(h: HarmonicSystem, gamma: float, lo: float, hi: float,
                     opts: dict) -> list[Band]:
    """The regions of one harmonic with the critical gamma of each non-"steady" one (0 without
    damping); raises :data:`LIMIT_ERRORS` past the toolkit's size limits.

    Parameters
    ----------
    h : HarmonicSystem
        The harmonic.
    gamma : float
        Pulsation amplitude, [0, 1).
    lo, hi : float
        Omega range (rad/s).
    opts : dict
        :func:`floquet_options`.
    """
    M, C, A, B = h.periodic(gamma)
    found = floquet.instability_regions(M, C, A, B, lo, hi, **opts)
    crit = {}
    if C is not None and any(r.kind != "steady" for r in found):
        crit = {(c.kind, c.modes, c.order): c.gamma_cr for c in floquet.critical_amplitude(
            M, C, A, h.excitation, gamma_max=gamma, omega_min=lo, omega_max=hi,
            regions=found, **opts)}
    rows = []
    for r in found:
        key = (r.kind, r.modes, r.order)
        if C is not None and r.kind != "steady" and key not in crit:
            raise ValueError(f"gamma = {gamma!r}: k = {h.k}, region {key} found but its "
                             "critical amplitude was not (inconsistent searches)")
        rows.append(Band(
            mechanism="vehicle", k=h.k, kind=r.kind, order=r.order,
            modes=tuple(h.mode(i) for i in r.modes), Omega_lo=r.omega_lo,
            Omega_hi=r.omega_hi, growth_rate_max=r.growth_rate_max,
            Omega_at_max=r.omega_at_max, Omega_center=r.omega_center,
            critical_gamma=float(crit.get(key, 0.0)), clipped=r.clipped))
    return rows


def limit_gap(h: HarmonicSystem, lo: float, hi: float, exc: Exception,
              what: str = "not searched") -> SearchGap:
    """The SearchGap of a harmonic past a size limit of the toolkit.

    Parameters
    ----------
    h : HarmonicSystem
        The harmonic.
    lo, hi : float
        Omega range left out (rad/s).
    exc : Exception
        One of :data:`LIMIT_ERRORS`.
    what : str
        What was left out ("not searched", "not traced for the chart").
    """
    limit = ("max_candidates" if isinstance(exc, floquet.TooManyCandidatesError) else
             "floating_point" if isinstance(exc, floquet.PeriodMapOverflowError) else "max_steps")
    return SearchGap(
        stage="vehicle", limit=limit, k=int(h.k), Omega_lo=float(lo), Omega_hi=float(hi),
        reason=(f"harmonic k = {h.k} {what}: {exc} ({h.omega_loaded.size} modes up to "
                f"{float(np.max(h.omega_loaded)):.6g} rad/s)"))
