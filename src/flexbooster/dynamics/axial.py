"""k = 0: the axial modes of the vehicle forced directly by the thrust pulsation.

-gamma F0 cos Omega t is an axial ring load at the aft edge: in the loaded k = 0 modes,
p_n'' + 2 zeta omega_n p_n' + omega_n^2 p_n = -gamma F0 phi_n cos Omega t, phi_n the aft-edge
axial displacement of mode n. A forced resonance at Omega = omega_n (memo family 3, 7.3-4,
7.3-5) with amplitude phi_n^2 / (2 zeta omega_n^2) per unit gamma F0, receptance
sum_n phi_n^2 / (omega_n^2 - Omega^2 + 2 i zeta omega_n Omega) (elastic modes only).

References: Tech Memo 104, sec. 7.3; L. Meirovitch, *Elements of Vibration Analysis*, 1986,
sec. 5.4, 7.4.
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
        Loaded k = 0 mode, ascending frequency.
    order, type : int, str
        Meridian order and type of the dominating basis mode.
    omega : float
        Resonance Omega = omega_n, the loaded frequency (rad/s).
    participation : float
        phi_n, axial aft-edge displacement of the mass-normalised mode (m / sqrt(kg)).
    flexibility : float
        phi_n^2 / omega_n^2: static modal flexibility at the aft edge (m/N).
    amplitude : float or None
        phi_n^2 / (2 zeta omega_n^2) (m/N) at resonance; None without damping.
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
    omega_loaded, participation : ndarray
        All loaded k = 0 frequencies of the basis (rad/s) and their phi_n (m / sqrt(kg)).
    F0, damping_ratio : float
        Steady thrust (N) and modal damping ratio.
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
        """Aft-edge axial receptance u_x / (gamma F0) of the elastic modes at Omega (rad/s, > 0),
        complex (m/N); the displacement is Re(receptance e^{i Omega t}) times -gamma F0.
        """
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
    """Forced resonances of the k = 0 modes under T(t) = F0 (1 - gamma cos Omega t); ValueError for
    bad input, BucklingError when F0 buckles k = 0.

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    F0 : float
        Steady thrust (N), > 0 (it prestresses the modes).
    omega_min, omega_max : float
        Omega range (rad/s), 0 < omega_min < omega_max.
    n_modes : int
        Loaded k = 0 modes in the basis, 1..2000.
    damping_ratio : float
        Modal damping ratio of the loaded modes, [0, 1).
    supported_forward_end : bool or None
        Load path of the thrust: None from the vehicle's ends.
    elements_per_segment, order
        Mesh (see :func:`flexbooster.shell_of_revolution.mesh_vehicle`).
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
                                     elements_per_segment=elements_per_segment, order=order,
                                     unloaded_frequencies=False)  # not used here
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
