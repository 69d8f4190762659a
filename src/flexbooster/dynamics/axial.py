"""k = 0: the axial modes of the vehicle forced directly by the thrust pulsation.

The pulsating part of T(t) = F0 (1 - gamma cos Omega t), -gamma F0 cos Omega t, is an axial
ring load at the aft edge.  In the modes of harmonic k = 0 loaded by the steady thrust
(q = V p, as :func:`.regions.harmonic_system`; mass-normalised, modal damping zeta on the
loaded frequencies omega_n) it is the generalised force -gamma F0 cos(Omega t) phi_n, with
phi_n = (V^T a)_n and a_m the axial displacement of basis mode m at the aft edge
(:class:`flexbooster.shell_of_revolution.ModalSystem` ``aft_axial``; the basis modes are the
loaded modes, V = I):

    p_n'' + 2 zeta omega_n p_n' + omega_n^2 p_n = -gamma F0 phi_n cos Omega t.

Its steady state is a forced (secular, not parametric) response: a resonance at
Omega = omega_n (the memo's family 3, Tech Memo 104 eqs. 7.3-4, 7.3-5) with the aft-edge
amplitude per unit gamma F0 phi_n^2 / (2 zeta omega_n^2) (m/N) and the receptance
u_x(aft) / (gamma F0) = sum_n phi_n^2 / (omega_n^2 - Omega^2 + 2 i zeta omega_n Omega) of
the elastic modes (the rigid translation, the flight itself, is left out).

References
----------
.. [1] Tech Memo 104, sec. 7.3 (family 3: Omega = omega_j0, the axial shell modes).
.. [2] L. Meirovitch, *Elements of Vibration Analysis*, 2nd ed., McGraw-Hill, 1986, sec. 7.4
   (modal analysis of the forced response; steady-state amplitude 1 / (2 zeta) x static at
   resonance), sec. 5.4 (the free-free rod: omega_n = n pi c / L, c = sqrt(E / rho)).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..checks import count, positive
from ..shell_of_revolution import DEFAULT_ORDER, Vehicle
from .harmonic import in_unit_interval, loaded_modes

__all__ = ["AxialResonance", "ForcedAxial", "forced_axial"]

#: Modes whose participation phi_n^2 is below this fraction of the largest are not forced
#: (torsional k = 0 modes: phi = 0 to round-off).
MIN_SHARE = 1e-8


@dataclass(frozen=True)
class AxialResonance:
    """One forced resonance Omega = omega_n of a k = 0 mode.

    Attributes
    ----------
    index : int
        Loaded k = 0 mode, ascending frequency (dimensionless).
    order, type : int, str
        Meridian order and type of the basis mode dominating it (labels of
        :func:`flexbooster.shell_of_revolution.vehicle_modes`).
    omega : float
        Resonance Omega = omega_n, the loaded frequency (rad/s).
    participation : float
        phi_n, axial aft-edge displacement of the mass-normalised mode (m / sqrt(kg)).
    flexibility : float
        phi_n^2 / omega_n^2: static modal flexibility at the aft edge (m/N).
    amplitude : float or None
        Aft-edge axial amplitude per unit gamma F0 at Omega = omega_n, phi_n^2 /
        (2 zeta omega_n^2) (m/N; Meirovitch 1986, sec. 7.4); None without damping.
    """

    index: int
    order: int
    type: str
    omega: float
    participation: float
    flexibility: float
    amplitude: float | None

    def to_dict(self) -> dict:
        """JSON-ready mapping."""
        return {"k": 0, "index": int(self.index), "order": int(self.order),
                "type": str(self.type), "omega": float(self.omega),
                "participation": float(self.participation),
                "flexibility": float(self.flexibility),
                "amplitude": None if self.amplitude is None else float(self.amplitude)}


@dataclass(frozen=True)
class ForcedAxial:
    """The k = 0 forced response to the thrust pulsation.

    Attributes
    ----------
    resonances : tuple of AxialResonance
        The forced modes with omega_n in [omega_min, omega_max], ascending.
    omega_loaded : ndarray
        All loaded k = 0 frequencies of the basis (rad/s).
    participation : ndarray
        phi_n of each (m / sqrt(kg)).
    F0 : float
        Steady thrust (N).
    damping_ratio : float
        Modal damping ratio (dimensionless).
    omega_min, omega_max : float
        Omega range (rad/s).
    """

    resonances: tuple
    omega_loaded: np.ndarray
    participation: np.ndarray
    F0: float
    damping_ratio: float
    omega_min: float
    omega_max: float

    def receptance(self, Omega) -> np.ndarray:
        """Aft-edge axial receptance u_x / (gamma F0) of the elastic modes at Omega (rad/s,
        > 0): sum_n phi_n^2 / (omega_n^2 - Omega^2 + 2 i zeta omega_n Omega) (m/N, complex;
        the displacement is Re(receptance e^{i Omega t}) times -gamma F0; Meirovitch 7.4)."""
        om = np.atleast_1d(np.asarray(Omega, dtype=float))
        if not np.all(np.isfinite(om)) or np.any(om <= 0.0):
            raise ValueError(f"Omega = {Omega!r}: must be finite and > 0")
        w = self.omega_loaded[None, :]
        z = self.damping_ratio
        den = w**2 - om[:, None] ** 2 + 2j * z * w * om[:, None]  # modal FRF (Meirovitch 7.4)
        if np.any(den == 0.0):
            raise ValueError(f"Omega = {Omega!r}: on an undamped resonance (unbounded)")
        return np.sum(self.participation[None, :] ** 2 / den, axis=1)

    def to_dict(self) -> dict:
        """JSON-ready mapping."""
        return {"F0": float(self.F0), "damping_ratio": float(self.damping_ratio),
                "omega_min": float(self.omega_min), "omega_max": float(self.omega_max),
                "omega_loaded": self.omega_loaded.tolist(),
                "participation": self.participation.tolist(),
                "resonances": [r.to_dict() for r in self.resonances]}


def forced_axial(
    vehicle: Vehicle, *, F0: float, omega_min: float, omega_max: float, n_modes: int = 20,
    damping_ratio: float = 0.01, supported_forward_end: bool | None = None,
    elements_per_segment: int | tuple | None = None, order: int = DEFAULT_ORDER,
) -> ForcedAxial:
    """Forced resonances of the k = 0 modes under T(t) = F0 (1 - gamma cos Omega t).

    Raises :class:`~flexbooster.shell_of_revolution.BucklingError` when F0 buckles k = 0.
    Meirovitch (1986), sec. 7.4; Tech Memo 104, sec. 7.3 (family 3).

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    F0 : float
        Steady thrust (N), > 0 (it prestresses the modes).
    omega_min, omega_max : float
        Omega range (rad/s), 0 < omega_min < omega_max.
    n_modes : int
        Loaded k = 0 modes in the basis (dimensionless), 1..2000.
    damping_ratio : float
        Modal damping ratio of the loaded modes (dimensionless), [0, 1).
    supported_forward_end : bool or None
        Load path of the thrust: None from the vehicle's ends
        (:func:`flexbooster.shell_of_revolution.prestress.load_path`).
    elements_per_segment, order
        Mesh (see :func:`flexbooster.shell_of_revolution.mesh_vehicle`).

    Returns
    -------
    ForcedAxial

    Raises
    ------
    ValueError
        Bad input (naming it), or the steady thrust buckles k = 0.

    References
    ----------
    Meirovitch (1986), sec. 7.4; Tech Memo 104, sec. 7.3 (family 3).
    """
    if not isinstance(vehicle, Vehicle):
        raise ValueError(f"vehicle = {vehicle!r}: must be a Vehicle")
    F0 = positive("F0", F0)
    lo, hi = positive("omega_min", omega_min), positive("omega_max", omega_max)
    if lo >= hi:
        raise ValueError(f"omega_min = {omega_min!r}: must be < omega_max = {omega_max!r}")
    n_modes = count("n_modes", n_modes, 1, 2000)
    zeta = in_unit_interval("damping_ratio", damping_ratio)
    ms, labels, w2, V = loaded_modes(vehicle, 0, n_modes, F0,
                                     supported_forward_end=supported_forward_end,
                                     elements_per_segment=elements_per_segment, order=order)
    omega = np.sqrt(w2)
    # generalised force per unit axial aft load of the loaded modes; a mode is defined up to
    # its sign: each is taken with phi_n >= 0 (else the sign depends on round-off, e.g. the
    # same case in SI and in inch-pound units)
    phi = np.abs(V.T @ ms.aft_axial)
    mode_order, mode_type = labels()  # as vehicle_modes(k_min=0, k_max=0, n_modes) labels
    dom = np.argmax(V**2, axis=0)
    forced = phi**2 > MIN_SHARE * float(np.max(phi**2)) if np.any(phi) else np.zeros_like(
        phi, dtype=bool)
    res = []
    for n in np.nonzero(forced & (omega >= lo) & (omega <= hi))[0]:  # a few modes
        flex = float(phi[n] ** 2 / w2[n])
        res.append(AxialResonance(
            index=int(n), order=int(mode_order[dom[n]]), type=str(mode_type[dom[n]]),
            omega=float(omega[n]), participation=float(phi[n]), flexibility=flex,
            amplitude=flex / (2.0 * zeta) if zeta > 0.0 else None))  # 1/(2 zeta) x static
    return ForcedAxial(resonances=tuple(res), omega_loaded=omega, participation=phi, F0=F0,
                       damping_ratio=zeta, omega_min=lo, omega_max=hi)
