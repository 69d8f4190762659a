"""Parametric instability regions of the pre-stressed shell-of-revolution vehicle.

The thrust T(t) = F0 (1 - gamma cos Omega t) acts on the vehicle of
:mod:`flexbooster.shell_of_revolution`.  Its geometric stiffness is linear in the thrust, so
for each circumferential harmonic k the modal equations of :func:`modal_system` are

    q'' + (K_e + (T(t) / F0) K_g) q = 0
      = q'' + (K_e + K_g) q - gamma cos(Omega t) K_g q = 0

(Bolotin 1964, sec. 8, in modal form).  The basis is the modes loaded by the steady thrust
(eigenvectors V of (K_e + K_g, M) of the full model, mass-normalised): with omega_L the loaded
frequencies,

    M = I,  A = diag(omega_L^2),  B = -gamma V^T K_g V,  C = 2 zeta diag(omega_L),

the modal damping acting on the loaded modes.  A mode's own terms (omega_L, B_ii), which set
the first-order width of its regions, are then those of the full model whatever the basis
size; the basis only enters through the couplings.  The regions in Omega are those of
:func:`flexbooster.floquet.instability_regions` (candidates 2 omega_i / j,
(omega_i +- omega_k) / j); the critical amplitude from :func:`flexbooster.floquet.
critical_amplitude` and the boundary curves in (Omega, gamma) from
:func:`flexbooster.floquet.region_boundaries`.

References
----------
.. [1] V. V. Bolotin, *The Dynamic Stability of Elastic Systems*, Holden-Day, 1964, ch. 1-2,
   sec. 6 (damping, mu_cr = Delta / pi), sec. 8 (modal reduction of a parametrically loaded
   elastic system).
.. [2] C. S. Hsu, J. Appl. Mech. 30 (1963) 367-372 (combination resonances).
.. [3] D. Bushnell, Computers & Structures 4 (1974) 399-435 (shells of revolution, BOSOR).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from .. import floquet
from ..checks import count, finite, nonnegative, positive
from ..shell_of_revolution import (
    DEFAULT_ORDER,
    Vehicle,
    buckling_load,
    labelled_modal_system,
)
from ..shell_of_revolution.prestress import load_path
from .axial import ForcedAxial, forced_axial

__all__ = [
    "RegionMode",
    "HarmonicSystem",
    "VehicleRegion",
    "RegionCurve",
    "VehicleRegions",
    "harmonic_system",
    "vehicle_regions",
    "region_curves",
    "search_seconds",
    "harmonic_search_seconds",
    "HARMONIC_BUILD_SECONDS",
]

#: Largest harmonic accepted (as :mod:`flexbooster.shell_of_revolution`).
K_MAX = 200

# Cost model of one harmonic's region search (s, one core, the shared 2-core machine).
# Up front (search_seconds, no FE solved): measured 2026-12-02 on the default case's vehicle
# (memo cylinders, 263 FE DOFs), k = 3, gamma = 0.05, undamped, Omega 5..2000 rad/s:
# n = 4 modes 0.11 s, 8: 0.53 s, 12: 1.43 s, 20: 9.6 s (-> 0.1 + 6e-5 n^4: 0.12, 0.35, 1.34,
# 9.7 s); n = 20 over Omega 5..500: 8.0 s (-> the log-range factor: 7.5 s).  It does not see
# the frequencies: the README's [vehicle] example (a short stiff vehicle, modes up to
# 4000 rad/s against Omega_min = 5), k = 2, 8 modes, undamped, took 6.3 s against 0.35 s.
_SEARCH_FIXED = 0.1
_SEARCH_PER_N4 = 6e-5
_SEARCH_LOG_RANGE = float(np.log(400.0))
# Per harmonic (harmonic_search_seconds, from floquet.search_work once the harmonic is
# built): the undamped search costs ~1.64e-4 s per candidate step plus ~3.1e-8 s per
# candidate step x n^3 (fit to the undamped runs above and to the README example, k = 2,
# n = 8: 6.3 s, estimated 6.3 s; the free-free default vehicle, k = 1, n = 7: 0.32 s,
# estimated 0.28 s; default vehicle k = 8, n = 12: 1.75 s, estimated 2.7 s).
_STEP_SECONDS = 1.64e-4
_STEP_N3_SECONDS = 3.1e-8
#: Damped but not certified: the undamped seeds, the damped search of those that hold an
#: undamped region and the critical gamma (tip search) of every damped region.  Per harmonic:
#: measured 2.6-8.3x the undamped estimate of the same candidates since the damped step counts
#: were fixed (branch damped1, 2026-12-02: README example k = 2, 20 modes: 12.1 s; free-free
#: default vehicle k = 1, 19 modes: 6.5 s; default vehicle k = 3, 10 modes, gamma = 0.5,
#: zeta = 0.001: 1.0 s; 1.2-2.4x with the former, too coarse, damped counts).
_DAMPED_SEARCH_FACTOR = 5.0
#: Up front (search_seconds, blind to the frequencies and the candidates): kept at 3, 2.4x
#: (README example k = 2) and 3.8x (free-free default vehicle k = 1) the measured damped
#: searches above.
_DAMPED_UPFRONT_FACTOR = 3.0
#: Up front, with the chart's curves: the search and 3 more levels (the tips are cheap).
_BOUNDARY_SEARCH_FACTOR = 4.0
#: Building one harmonic (FE modal system, labels, certificate) on the default case's mesh:
#: k = 1..20, 20 modes, damped and certified, 0.02 s per harmonic (measured 2026-12-02).
HARMONIC_BUILD_SECONDS = 0.02


def search_seconds(n_modes: int, omega_min: float, omega_max: float, *, damped: bool,
                   boundaries: bool = False) -> float:
    """Estimated time of the region search of one harmonic that is not certified stable.

    Parameters
    ----------
    n_modes : int
        Modes of the harmonic's system (dimensionless), >= 1.
    omega_min, omega_max : float
        Omega range (rad/s), 0 < omega_min < omega_max.
    damped : bool
        Damping > 0 (the damped search and the critical gamma of each region).
    boundaries : bool
        The pipeline's chart curves are traced as well.

    Returns
    -------
    float
        Seconds on one core: (0.1 + 6e-5 n^4) ln(omega_max / omega_min) / ln(400), x 3
        damped, x 4 with boundaries (the chart's 3 levels and the tips; calibration in the
        comments above: good to a factor of about 2 on the memo vehicle, optimistic by up to
        ~20 on a short stiff vehicle whose frequencies are far above omega_min, which
        :func:`harmonic_search_seconds` sees).

    References
    ----------
    Measured, see the module's comments; docs/theory/vehicle-regions.md, section 3d.
    """
    n = count("n_modes", n_modes, 1, 100_000)
    lo, hi = positive("omega_min", omega_min), positive("omega_max", omega_max)
    if lo >= hi:
        raise ValueError(f"omega_min = {omega_min!r}: must be < omega_max = {omega_max!r}")
    t = (_SEARCH_FIXED + _SEARCH_PER_N4 * float(n) ** 4) * max(
        np.log(hi / lo) / _SEARCH_LOG_RANGE, 0.05)
    return float(t * (_DAMPED_UPFRONT_FACTOR if damped else 1.0)
                 * (_BOUNDARY_SEARCH_FACTOR if boundaries else 1.0))


def harmonic_search_seconds(work: floquet.SearchWork, *, levels: int = 1) -> float:
    """Estimated time of one harmonic's region search from what it will integrate.

    Parameters
    ----------
    work : flexbooster.floquet.SearchWork
        From :func:`flexbooster.floquet.search_work` on the harmonic's system (candidates
        after the certificate and the damping filter, their step counts).
    levels : int
        Searches of the same cost (dimensionless), >= 1: 1 for the map, the number of
        amplitude levels for the chart's curves.

    Returns
    -------
    float
        Seconds on one core: 0 for a certified or steadily unstable system; else
        levels x (1.64e-4 + 3.1e-8 n^3) x the candidates' undamped step count, x 5 with
        damping (the seeds, the damped search of the survivors and their critical gamma).
        Calibration in this module's comments (within a factor of about 2 on the vehicles
        measured).

    References
    ----------
    Measured, see the module's comments; docs/theory/vehicle-regions.md, section 3d.
    """
    if not isinstance(work, floquet.SearchWork):
        raise ValueError(f"work = {type(work).__name__}: must be a floquet.SearchWork")
    levels = count("levels", levels, 1, 100_000)
    if work.steady or work.certified:
        return 0.0
    per_step = _STEP_SECONDS + _STEP_N3_SECONDS * float(work.n) ** 3
    damped = work.damped_steps > 0
    return float(levels * per_step * work.undamped_steps
                 * (_DAMPED_SEARCH_FACTOR if damped else 1.0))


@dataclass(frozen=True)
class RegionMode:
    """One loaded mode taking part in a region.

    Attributes
    ----------
    k : int
        Circumferential wave number (dimensionless).
    index : int
        Index of the loaded mode in its harmonic, ascending frequency (dimensionless).
    order : int
        Sign changes along the meridian of the basis mode that dominates it (for k >= 2 the
        loaded mode itself; :func:`~flexbooster.shell_of_revolution.vehicle_modes` label;
        dimensionless).
    type : str
        Type of that mode ("axial", "torsional", "radial"; "bending", "rigid-pitch" for k = 1).
    omega_loaded : float
        Frequency under the steady thrust F0 (rad/s).
    share : float
        Share of the dominating basis mode in the loaded one (dimensionless; 1 for k >= 2).
    """

    k: int
    index: int
    order: int
    type: str
    omega_loaded: float
    share: float

    def to_dict(self) -> dict:
        """JSON-ready mapping."""
        return {"k": int(self.k), "index": int(self.index), "order": int(self.order),
                "type": str(self.type), "omega_loaded": float(self.omega_loaded),
                "share": float(self.share)}


class _ModalMatrices:
    """The (M, C, A, B) of a periodic modal system with fields mass, damping, stiffness and
    excitation (:class:`HarmonicSystem` and :class:`.bending.BendingSystem`)."""

    __slots__ = ()

    def matrices(self, gamma: float) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """(M, C, A, B) of the periodic system for pulsation amplitude gamma.

        Parameters
        ----------
        gamma : float
            Pulsation amplitude (dimensionless), 0 <= gamma < 1.

        Returns
        -------
        tuple of ndarray
            M (dimensionless), C (1/s), A (1/s^2), B = gamma B1 (1/s^2).

        References
        ----------
        Bolotin (1964), sec. 8: B = gamma B1 for T = F0 (1 - gamma cos Omega t).
        """
        gamma = _gamma(gamma)
        return self.mass, self.damping, self.stiffness, gamma * self.excitation


@dataclass(frozen=True)
class HarmonicSystem(_ModalMatrices):
    """Periodic modal system of one harmonic: M q'' + C q' + (A + gamma B1 cos Omega t) q = 0.

    Attributes
    ----------
    k : int
        Circumferential wave number (dimensionless).
    F0 : float
        Steady thrust (N).
    damping_ratio : float
        Modal damping ratio zeta of the loaded modes (dimensionless).
    omega_unloaded : ndarray, shape (n,)
        The harmonic's lowest natural frequencies without thrust, as many (rad/s).
    omega_loaded : ndarray, shape (n,)
        Frequencies under the steady thrust F0 (rad/s), ascending.
    basis : ndarray, shape (n, n)
        Column j = steady mode j in the basis coordinates (the identity: the basis modes are
        the loaded modes).
    mass : ndarray, shape (n, n)
        M = I (modal mass, mass-normalised modes).
    damping : ndarray, shape (n, n)
        C = 2 zeta diag(omega_loaded) (1/s).
    stiffness : ndarray, shape (n, n)
        A = diag(omega_loaded^2) = V^T (K_e + K_g) V (1/s^2).
    excitation : ndarray, shape (n, n)
        B1 = -V^T K_g V (1/s^2): B = gamma B1 for T = F0 (1 - gamma cos Omega t).
    mode_order, mode_type : ndarray, shape (n,)
        Labels of the basis mode dominating each steady mode (as
        :func:`~flexbooster.shell_of_revolution.vehicle_modes` labels a mode).
    mode_share : ndarray, shape (n,)
        Its share (dimensionless; 1 for k >= 2).

    Notes
    -----
    k = 1 (:func:`.bending.bending_harmonic`: bending, rigid pitch, gimbaled follower thrust)
    is written in the basis of the rigid motions and the unloaded elastic modes (the rigid
    translation dropped, and the neutral rigid pitch without gimbal gain): A =
    diag(omega^2) + K_g - F0 y (beta + K psi)^T is not diagonal and not symmetric, C =
    2 zeta diag(omega_unloaded) (0 on the rigid pitch), ``omega_loaded`` are the square roots
    of the real parts of the eigenvalues of A (ascending; the steady frequencies), ``basis``
    the real parts of its unit eigenvectors, and the labels those of the basis mode that
    dominates each steady mode (type "rigid-pitch" for the rigid rotation).

    References
    ----------
    Bolotin (1964), sec. 8; Beal (1965), eq. 4 (k = 1).
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

    def mode(self, index: int) -> RegionMode:
        """Label of loaded mode ``index`` (see :class:`RegionMode`).

        Parameters
        ----------
        index : int
            Loaded mode index (dimensionless), 0..n-1.

        Returns
        -------
        RegionMode
        """
        index = count("index", index, 0, self.omega_loaded.size - 1)
        return RegionMode(k=self.k, index=index, order=int(self.mode_order[index]),
                          type=str(self.mode_type[index]),
                          omega_loaded=float(self.omega_loaded[index]),
                          share=float(self.mode_share[index]))

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


@dataclass(frozen=True)
class VehicleRegion:
    """One parametric instability region of harmonic k.

    Attributes
    ----------
    k : int
        Circumferential wave number (dimensionless).
    kind : str
        "simple" (Omega near 2 omega_i / j), "sum" ((omega_i + omega_k) / j) or "difference";
        "steady" (k = 1 only, :func:`.bending.bending_regions`: the steady system itself is
        not stable).
    order : int
        j of the resonance centre (dimensionless; not the meridian order of the modes).
    modes : tuple of RegionMode
        The loaded modes involved (one for "simple", two otherwise).
    omega_lo, omega_hi : float
        Boundaries in Omega (rad/s) at the requested gamma, |rho|_max = 1 there.
    growth_rate_max : float
        Largest growth rate log|rho|_max / T inside (1/s).
    omega_at_max : float
        Omega where it occurs (rad/s).
    omega_center : float
        Analytic centre (rad/s).
    critical_gamma : float
        Amplitude below which damping suppresses the region (dimensionless; 0 without
        damping).
    clipped : bool
        A boundary is an end of the Omega range.

    References
    ----------
    Bolotin (1964), ch. 1-2, sec. 6; Hsu (1963).
    """

    k: int
    kind: str
    order: int
    modes: tuple
    omega_lo: float
    omega_hi: float
    growth_rate_max: float
    omega_at_max: float
    omega_center: float
    critical_gamma: float
    clipped: bool = False

    @property
    def width(self) -> float:
        """omega_hi - omega_lo (rad/s)."""
        return self.omega_hi - self.omega_lo

    def to_dict(self) -> dict:
        """JSON-ready mapping."""
        return {"k": int(self.k), "kind": self.kind, "order": int(self.order),
                "modes": [m.to_dict() for m in self.modes], "omega_lo": float(self.omega_lo),
                "omega_hi": float(self.omega_hi), "width": float(self.width),
                "growth_rate_max": float(self.growth_rate_max),
                "omega_at_max": float(self.omega_at_max),
                "omega_center": float(self.omega_center),
                "critical_gamma": float(self.critical_gamma), "clipped": bool(self.clipped)}


@dataclass(frozen=True)
class RegionCurve:
    """Boundary curves of one region of harmonic k in the (Omega, gamma) plane.

    Attributes
    ----------
    k : int
        Circumferential wave number (dimensionless).
    kind : str
        Region kind (see :class:`VehicleRegion`).
    order : int
        j of the resonance centre (dimensionless).
    modes : tuple of int
        Loaded mode indices in harmonic k.
    gamma : ndarray
        Amplitudes (dimensionless), ascending from the critical one.
    omega_lo, omega_hi : ndarray
        Boundaries at each gamma (rad/s).

    References
    ----------
    Bolotin (1964), ch. 1, sec. 6.
    """

    k: int
    kind: str
    order: int
    modes: tuple
    gamma: np.ndarray
    omega_lo: np.ndarray
    omega_hi: np.ndarray

    def to_dict(self) -> dict:
        """JSON-ready mapping."""
        return {"k": int(self.k), "kind": self.kind, "order": int(self.order),
                "modes": [int(m) for m in self.modes], "gamma": self.gamma.tolist(),
                "omega_lo": self.omega_lo.tolist(), "omega_hi": self.omega_hi.tolist()}


@dataclass(frozen=True)
class VehicleRegions:
    """Instability map of the vehicle: regions of every harmonic k_min..k_max.

    Attributes
    ----------
    regions : tuple of VehicleRegion
        Sorted by omega_lo, then k.
    harmonics : tuple of HarmonicSystem
        The periodic system of each harmonic (k ascending).
    curves : tuple of RegionCurve
        Boundary curves (empty unless ``boundaries=True``).
    F0 : float
        Steady thrust (N).
    gamma : float
        Pulsation amplitude (dimensionless).
    damping_ratio : float
        Modal damping ratio (dimensionless).
    omega_min, omega_max : float
        Omega range (rad/s).
    supported_forward_end : bool
        The nose reacts the thrust (uniform compression; ``load_path`` "forward support").
    load_path : str
        What balances the thrust in the prestress: "inertia relief", "forward support" or
        "aft support" (:data:`flexbooster.shell_of_revolution.prestress.LOAD_PATHS`).
    forced_axial : ForcedAxial or None
        k = 0: the axial modes forced directly by the thrust pulsation, resonances
        Omega = omega_n with their amplitude per unit gamma F0 (:mod:`.axial`; the memo's
        family 3); None when not asked for.
    certificates : tuple of StabilityCertificate
        Per harmonic (as ``harmonics``): the all-Omega stability bound of
        :func:`flexbooster.floquet.stability_certificate` at gamma (never certified without
        damping).
    chart_gamma_max : float or None
        Largest gamma of the (Omega, gamma) chart the pipeline asked for (dimensionless); None
        when not set.
    gimbal_gain : float
        Gimbal gain K of the k = 1 harmonic (dimensionless; unused without k = 1).
    skipped : tuple of str
        Harmonics not searched because their estimated search time would pass the budget
        (``max_seconds`` of :func:`vehicle_regions`) or their resonance candidates the
        toolkit's limit (the line starts with ``thrust.omega_min``), one line each; their
        regions are unknown.
    estimated_seconds : float
        The cost model's estimate of the work done (s, one core): the harmonics built and
        searched (:data:`HARMONIC_BUILD_SECONDS`, :func:`harmonic_search_seconds`; the
        searches only when a budget was given), without the curves.
    """

    regions: tuple
    harmonics: tuple
    curves: tuple
    F0: float
    gamma: float
    damping_ratio: float
    omega_min: float
    omega_max: float
    supported_forward_end: bool
    load_path: str = "inertia relief"
    forced_axial: ForcedAxial | None = None
    certificates: tuple = ()
    chart_gamma_max: float | None = None
    gimbal_gain: float = 0.0
    skipped: tuple = ()
    estimated_seconds: float = 0.0

    def harmonic(self, k: int) -> HarmonicSystem:
        """The system of harmonic k.

        Parameters
        ----------
        k : int
            Circumferential wave number (dimensionless), one of those computed.

        Returns
        -------
        HarmonicSystem
        """
        for h in self.harmonics:
            if h.k == k:
                return h
        raise ValueError(f"k = {k!r}: not computed (k = {[h.k for h in self.harmonics]})")

    def to_dict(self) -> dict:
        """JSON-ready mapping (the matrices of each harmonic only through
        :meth:`HarmonicSystem.to_dict`)."""
        return {"F0": float(self.F0), "gamma": float(self.gamma),
                "damping_ratio": float(self.damping_ratio),
                "omega_min": float(self.omega_min), "omega_max": float(self.omega_max),
                "supported_forward_end": bool(self.supported_forward_end),
                "load_path": self.load_path,
                "regions": [r.to_dict() for r in self.regions],
                "harmonics": [{"k": int(h.k), "omega_unloaded": h.omega_unloaded.tolist(),
                               "omega_loaded": h.omega_loaded.tolist(),
                               "mode_order": [int(v) for v in h.mode_order],
                               "mode_type": [str(v) for v in h.mode_type]}
                              for h in self.harmonics],
                "curves": [c.to_dict() for c in self.curves],
                "chart_gamma_max": (None if self.chart_gamma_max is None
                                    else float(self.chart_gamma_max)),
                "forced_axial": (None if self.forced_axial is None
                                 else self.forced_axial.to_dict()),
                "certificates": [dict(c.to_dict(), k=int(h.k)) for h, c in
                                 zip(self.harmonics, self.certificates, strict=True)],
                "gimbal_gain": float(self.gimbal_gain),
                "skipped": [str(w) for w in self.skipped],
                "estimated_seconds": float(self.estimated_seconds)}


# ----------------------------------------------------------------------------- checks


def _gamma(gamma) -> float:
    gamma = nonnegative("gamma", gamma)
    if gamma >= 1.0:
        raise ValueError(f"gamma = {gamma!r}: must be in [0, 1)")
    return gamma


def _zeta(damping_ratio) -> float:
    zeta = nonnegative("damping_ratio", damping_ratio)
    if zeta >= 1.0:
        raise ValueError(f"damping_ratio = {damping_ratio!r}: must be in [0, 1)")
    return zeta


def _vehicle(vehicle) -> Vehicle:
    if not isinstance(vehicle, Vehicle):
        raise ValueError(f"vehicle = {vehicle!r}: must be a Vehicle")
    return vehicle


# ----------------------------------------------------------------------------- systems


def harmonic_system(
    vehicle: Vehicle, k: int, *, F0: float, n_modes: int = 20, damping_ratio: float = 0.01,
    supported_forward_end: bool | None = None, elements_per_segment: int | tuple | None = None,
    order: int = DEFAULT_ORDER,
) -> HarmonicSystem:
    """Periodic modal system of harmonic k under T(t) = F0 (1 - gamma cos Omega t).

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle (:class:`flexbooster.shell_of_revolution.Vehicle`).
    k : int
        Circumferential wave number (dimensionless), 2..200 (k = 0, 1 are not modelled here).
    F0 : float
        Steady thrust (N), > 0.
    n_modes : int
        Loaded modes in the basis (dimensionless), 1..2000.
    damping_ratio : float
        Modal damping ratio zeta of the loaded modes (dimensionless), 0 <= zeta < 1.
    supported_forward_end : bool or None
        Load path of the thrust: None from the vehicle's ends (a hinged or clamped forward
        end reacts it: uniform compression; else inertia relief), True uniform compression,
        False inertia relief (:func:`flexbooster.shell_of_revolution.prestress.load_path`).
    elements_per_segment, order
        Mesh (see :func:`flexbooster.shell_of_revolution.mesh_vehicle`).

    Returns
    -------
    HarmonicSystem

    Raises
    ------
    ValueError
        Bad input (naming it), or the steady thrust buckles the harmonic (a loaded
        omega^2 <= 0): the message gives the load factor of :func:`buckling_load`.

    References
    ----------
    Bolotin (1964), sec. 8 (modal form of the parametrically loaded system).
    """
    vehicle = _vehicle(vehicle)
    k = count("k", k, 2, K_MAX)
    F0 = positive("F0", F0)
    n_modes = count("n_modes", n_modes, 1, 2000)
    zeta = _zeta(damping_ratio)
    load_path(vehicle, supported_forward_end)  # checks the flag
    mesh = {"elements_per_segment": elements_per_segment, "order": order}
    ms, labels = labelled_modal_system(vehicle, k, n_modes, F0,
                                       supported_forward_end=supported_forward_end, **mesh)
    # steady part K_e + K_g (T = F0); M = I (Bolotin sec. 8)
    w2, V = np.linalg.eigh(ms.stiffness + ms.geometric)
    if w2[0] <= 0.0:
        lam = buckling_load(vehicle, k, F0=F0, supported_forward_end=supported_forward_end,
                            **mesh).load_factor[0]
        raise ValueError(f"F0 = {F0!r}: the steady thrust buckles harmonic k = {k} (load "
                         f"factor lambda = {lam:.6g} <= 1, critical thrust {lam * F0:.6g} N; "
                         f"loaded omega^2 = {w2[0]:.4g} 1/s^2)")
    omega_l = np.sqrt(w2)
    n = omega_l.size
    mode_order, mode_type = labels()  # as vehicle_modes(k_min=k, k_max=k, n_modes) labels
    dom = np.argmax(V**2, axis=0)  # basis mode dominating each loaded one (V = I)
    kg = V.T @ ms.geometric @ V
    return HarmonicSystem(
        k=k, F0=F0, damping_ratio=zeta, omega_unloaded=ms.omega_unloaded, omega_loaded=omega_l,
        basis=V, mass=np.eye(n),
        damping=2.0 * zeta * np.diag(omega_l),  # modal damping of the loaded modes
        stiffness=np.diag(w2),  # A = V^T (K_e + K_g) V
        excitation=-0.5 * (kg + kg.T),  # B = -gamma K_g: T/F0 = 1 - gamma cos Omega t
        mode_order=mode_order[dom].astype(int), mode_type=mode_type[dom].astype(str),
        mode_share=(V**2)[dom, np.arange(n)])


# ----------------------------------------------------------------------------- regions


def _floquet_options(rtol, step_phase, max_order, damping_margin) -> dict:
    opts = {"rtol": finite("rtol", rtol), "step_phase": positive("step_phase", step_phase)}
    if damping_margin is not None:
        if isinstance(damping_margin, bool):
            raise ValueError(f"damping_margin = {damping_margin!r}: must be None or a number "
                             ">= 1")
        damping_margin = finite("damping_margin", damping_margin)
        if damping_margin < 1.0:
            raise ValueError(f"damping_margin = {damping_margin!r}: must be None or >= 1")
    opts["damping_margin"] = damping_margin
    if max_order is not None:
        opts["max_order"] = count("max_order", max_order, 1, 10_000)
    return opts


def _harmonic_regions(h: HarmonicSystem, gamma: float, lo: float, hi: float, opts: dict,
                      budget: tuple | None = None) -> tuple[list, object, str | None, float]:
    """The regions of one harmonic (VehicleRegion rows), its certificate, and the budget.

    The certificate (Desoer & Vidyasagar sec. 2.8) is of the system at gamma, none without
    damping; the critical gamma of each region that is not "steady" is
    :func:`flexbooster.floquet.critical_amplitude` (Bolotin sec. 6: the amplitude where the
    damped region's edges meet), 0 without damping.  ``budget`` = (max_seconds, seconds
    estimated so far): a harmonic whose search (:func:`harmonic_search_seconds` of
    :func:`flexbooster.floquet.search_work`) would take the estimate past max_seconds is not
    searched: no rows, and the reason (naming max_seconds and the drivers) as the third item
    (else None).  A search past the toolkit's candidate limit
    (:class:`flexbooster.floquet.TooManyCandidatesError`) is not searched either, the reason
    naming thrust.omega_min.  The fourth item is the estimate of what was searched (s; 0
    without budget).
    """
    M, C, A, B = h.matrices(gamma)
    Cf = C if h.damping_ratio > 0.0 else None
    cert = floquet.stability_certificate(M, Cf, A, B)  # none without damping
    est = 0.0
    try:  # the candidates are enumerated by search_work and by the search itself
        if budget is not None and not cert.certified and gamma > 0.0:
            max_s, spent = budget
            work = floquet.search_work(M, Cf, A, B, lo, hi, **opts)
            est = harmonic_search_seconds(work)
            if spent + est > max_s:
                return [], cert, (
                    f"max_seconds = {max_s:g}: harmonic k = {h.k} not searched, its region "
                    f"search is estimated at {est:.3g} s ({A.shape[0]} modes, "
                    f"{work.n_candidates} candidates, Omega {lo:.6g}..{hi:.6g} rad/s, damping "
                    f"ratio {h.damping_ratio:g}" + ("" if Cf is None else ", not certified "
                                                    "stable by the damping")
                    + f"; {spent:.3g} s before it): reduce vehicle.n_modes or the Omega "
                    "range, raise vehicle.damping_ratio, or raise the budget"), 0.0
        found = floquet.instability_regions(M, Cf, A, B, lo, hi, **opts)
        crit = {}
        if Cf is not None and any(r.kind != "steady" for r in found):  # Bolotin sec. 6
            crit = {(c.kind, c.modes, c.order): c.gamma_cr for c in floquet.critical_amplitude(
                M, Cf, A, h.excitation, gamma_max=gamma, omega_min=lo, omega_max=hi,
                regions=found, **opts)}
    except (floquet.TooManyCandidatesError, floquet.StepLimitError) as exc:
        return [], cert, _past_a_limit(h, lo, exc), est  # a resource limit (issue 18): named
    rows = []
    for r in found:
        key = (r.kind, r.modes, r.order)
        if Cf is not None and r.kind != "steady" and key not in crit:
            raise ValueError(f"gamma = {gamma!r}: k = {h.k}, region {key} found but its "
                             "critical amplitude was not (inconsistent searches)")
        rows.append(VehicleRegion(
            k=h.k, kind=r.kind, order=r.order, modes=tuple(h.mode(i) for i in r.modes),
            omega_lo=r.omega_lo, omega_hi=r.omega_hi, growth_rate_max=r.growth_rate_max,
            omega_at_max=r.omega_at_max, omega_center=r.omega_center,
            critical_gamma=float(crit.get(key, 0.0)), clipped=r.clipped))
    return rows, cert, None, est


def _past_a_limit(h: HarmonicSystem, lo: float, exc: Exception,
                  what: str = "not searched") -> str:
    """The one line naming a harmonic past a limit of the toolkit (issue 18): its resonance
    candidates (:class:`flexbooster.floquet.TooManyCandidatesError`) or the integration steps
    of a monodromy (:class:`flexbooster.floquet.StepLimitError`), both growing as omega_min
    falls below the harmonic's frequencies."""
    why = (str(exc).split(": ", 1)[-1] if isinstance(exc, floquet.TooManyCandidatesError)
           else str(exc))
    return (f"thrust.omega_min = {lo:.6g}: harmonic k = {h.k} {what}, {why} "
            f"({h.omega_loaded.size} modes up to {float(np.max(h.omega_loaded)):.6g} rad/s); "
            "raise thrust.omega_min or reduce vehicle.n_modes")


def _instability_region(r: VehicleRegion) -> floquet.InstabilityRegion:
    """The toolkit's region of a row (for :func:`flexbooster.floquet.region_boundaries`)."""
    return floquet.InstabilityRegion(
        omega_lo=r.omega_lo, omega_hi=r.omega_hi, growth_rate_max=r.growth_rate_max,
        omega_at_max=r.omega_at_max, kind=r.kind, modes=tuple(m.index for m in r.modes),
        order=r.order, omega_center=r.omega_center, clipped=r.clipped)


def region_curves(
    found: VehicleRegions, *, gamma_max: float, n_gamma: int = 11, rtol: float = 1e-9,
    step_phase: float = 0.12, max_order: int | None = None,
    damping_margin: float | None = floquet.DAMPING_MARGIN, max_seconds: float | None = None,
) -> tuple[tuple, tuple]:
    """Boundary curves in (Omega, gamma) of the regions of a map, up to gamma_max.

    Only the harmonics that can have a region at gamma_max are traced
    (:func:`flexbooster.floquet.region_boundaries` on the stored harmonic systems, no FE
    solved again): with gamma_max equal to the map's gamma, those with a region other than
    "steady" in ``found`` (whose rows are reused as the top level); otherwise those that the
    stability certificate at gamma_max does not cover.

    Parameters
    ----------
    found : VehicleRegions
        The map (:func:`vehicle_regions`).
    gamma_max : float
        Largest gamma of the curves (dimensionless), (0, 1).
    n_gamma : int
        Levels of the curves (dimensionless), 2..1000.
    rtol, step_phase, max_order, damping_margin
        As :func:`vehicle_regions` (the options the map was searched with).
    max_seconds : float or None
        Budget of the curves (s), > 0: a harmonic whose curves (:func:`harmonic_search_seconds`
        with n_gamma - 1 levels) would take the estimate past it is not traced and named.

    Returns
    -------
    tuple
        (curves, skipped): tuple of RegionCurve (k ascending) and the harmonics the budget
        left out, one line each.

    References
    ----------
    Bolotin (1964), ch. 1 (the regions in the (Omega, mu) plane), sec. 6.
    """
    if not isinstance(found, VehicleRegions):
        raise ValueError(f"found = {type(found).__name__}: must be a VehicleRegions")
    gmax = _gamma(gamma_max)
    if gmax <= 0.0:
        raise ValueError(f"gamma_max = {gamma_max!r}: must be in (0, 1)")
    n_gamma = count("n_gamma", n_gamma, 2, 1000)
    if max_seconds is not None:
        max_seconds = positive("max_seconds", max_seconds)
    opts = _floquet_options(rtol, step_phase, max_order, damping_margin)
    lo, hi = found.omega_min, found.omega_max
    curves, skipped = [], []
    spent = 0.0
    for h in found.harmonics:
        M, C, A, _ = h.matrices(gmax)
        Cf = C if h.damping_ratio > 0.0 else None
        top = None
        if gmax == found.gamma:  # the map's rows are the top level
            rows = [r for r in found.regions if r.k == h.k]
            if not any(r.kind != "steady" for r in rows):
                continue
            top = tuple(_instability_region(r) for r in rows)
        if max_seconds is not None:
            try:
                work = floquet.search_work(M, Cf, A, gmax * h.excitation, lo, hi, **opts)
            except (floquet.TooManyCandidatesError, floquet.StepLimitError) as exc:
                skipped.append(_past_a_limit(h, lo, exc, "not traced for the chart"))
                continue
            if work.steady or work.certified:
                continue  # no curve: a steady region or none at gamma_max
            est = harmonic_search_seconds(work, levels=n_gamma - (1 if top else 0))
            if spent + est > max_seconds:
                skipped.append(
                    f"max_seconds = {max_seconds:g}: harmonic k = {h.k} not searched for the "
                    f"chart's boundary curves, estimated at {est:.3g} s ({A.shape[0]} modes, "
                    f"{work.n_candidates} candidates, {n_gamma} levels up to gamma = "
                    f"{gmax:g}; {spent:.3g} s before it): reduce vehicle.n_modes or the "
                    "Omega range, raise vehicle.damping_ratio, or raise the budget")
                continue
            spent += est
        elif top is None and floquet.stability_certificate(
                M, Cf, A, gmax * h.excitation).certified:
            continue  # no region at gamma_max: nothing to trace
        try:
            traced = floquet.region_boundaries(M, Cf, A, h.excitation, gamma_max=gmax,
                                               omega_min=lo, omega_max=hi, n_gamma=n_gamma,
                                               regions=top, **opts)
        except (floquet.TooManyCandidatesError, floquet.StepLimitError) as exc:
            skipped.append(_past_a_limit(h, lo, exc, "not traced for the chart"))
            continue
        for c in traced:
            curves.append(RegionCurve(k=h.k, kind=c.kind, order=c.order, modes=c.modes,
                                      gamma=c.gamma, omega_lo=c.omega_lo,
                                      omega_hi=c.omega_hi))
    return tuple(curves), tuple(skipped)


def vehicle_regions(
    vehicle: Vehicle, *, F0: float, gamma: float, omega_min: float, omega_max: float,
    k_max: int, k_min: int = 2, n_modes: int = 20, damping_ratio: float = 0.01,
    supported_forward_end: bool | None = None, elements_per_segment: int | tuple | None = None,
    order: int = DEFAULT_ORDER, boundaries: bool = False, gamma_max: float = 0.5,
    n_gamma: int = 11, rtol: float = 1e-9, step_phase: float = 0.12,
    max_order: int | None = None, damping_margin: float | None = floquet.DAMPING_MARGIN,
    axial: bool = True, gimbal_gain: float = 0.0, max_seconds: float | None = None,
) -> VehicleRegions:
    """Parametric instability regions of every harmonic k_min..k_max in [omega_min, omega_max].

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    F0 : float
        Steady thrust (N), > 0.
    gamma : float
        Pulsation amplitude of T(t) = F0 (1 - gamma cos Omega t) (dimensionless), [0, 1).
    omega_min, omega_max : float
        Range of the pulsation frequency Omega (rad/s), 0 < omega_min < omega_max.
    k_max, k_min : int
        Harmonics (dimensionless), 1 <= k_min <= k_max <= 200; k = 1 is the bending
        harmonic with the rigid pitch, the gimbal control and the follower thrust
        (:func:`.bending.bending_harmonic`, its regions those of
        :func:`.bending.bending_regions`).
    n_modes : int
        Modes per harmonic in the modal basis (dimensionless), 1..2000: the loaded modes
        (k = 1: the rigid motions and the unloaded modes, at least 3).
    damping_ratio : float
        Modal damping ratio of the loaded modes (dimensionless), [0, 1); default 0.01.
    supported_forward_end : bool or None
        Load path of the thrust (:func:`harmonic_system`): None from the vehicle's ends.
    elements_per_segment, order
        Mesh (see :func:`flexbooster.shell_of_revolution.mesh_vehicle`).
    boundaries : bool
        Also trace the boundary curves in (Omega, gamma), gamma up to ``gamma_max``
        (:func:`region_curves`: :func:`flexbooster.floquet.region_boundaries` on the
        harmonics that can have a region at gamma_max; ``n_gamma`` searches each).
    gamma_max : float
        Largest gamma of the curves (dimensionless), (0, 1).
    n_gamma : int
        Levels of the curves (dimensionless), 2..1000.
    rtol, step_phase, max_order
        Boundary tolerance (dimensionless, relative to the centre), integration step phase
        (dimensionless) and largest resonance order j (None: by the width estimate) of
        :func:`flexbooster.floquet.instability_regions`.
    damping_margin : float or None
        Damping filter of :func:`flexbooster.floquet.instability_regions` (dimensionless,
        >= 1; default 4): harmonics certified stable at every Omega by
        :func:`flexbooster.floquet.stability_certificate` are not searched, and candidates
        whose first-order growth bound x margin is below their modes' decay rate are not
        examined.  None: every candidate is examined (the unfiltered search).
    axial : bool
        Also compute the k = 0 forced axial resonances (:func:`.axial.forced_axial`, same
        n_modes, damping and mesh) into ``forced_axial``.
    gimbal_gain : float
        K of the gimbal control (dimensionless), >= 0: used by k = 1 only (the thrust turned
        by K psi, psi the rigid pitch angle; Tech Memo 104 eq. 2.2-2).
    max_seconds : float or None
        Budget of the searches (s), > 0: before each harmonic that the stability certificate
        does not cover, its search is estimated (:func:`harmonic_search_seconds` of
        :func:`flexbooster.floquet.search_work`: its candidates and their step counts); a
        harmonic that would take the running estimate (builds and searches so far) past the
        budget is not searched (no regions, no curves) and named in ``skipped`` with the
        estimate and its drivers; the curves get what the searches left.  None: no budget.

    Returns
    -------
    VehicleRegions

    Raises
    ------
    ValueError
        Bad input (naming it) or buckling under the steady thrust (load factor named).

    References
    ----------
    Bolotin (1964), ch. 1-2, sec. 6, sec. 8; Hsu (1963); Beal (1965) (k = 1);
    ``docs/theory/floquet.md``.
    """
    from .bending import bending_harmonic  # k = 1 (bending.py imports this module)

    vehicle = _vehicle(vehicle)
    F0 = positive("F0", F0)
    gamma = _gamma(gamma)
    zeta = _zeta(damping_ratio)
    lo, hi = positive("omega_min", omega_min), positive("omega_max", omega_max)
    if lo >= hi:
        raise ValueError(f"omega_min = {omega_min!r}: must be < omega_max = {omega_max!r}")
    k_max = count("k_max", k_max, 1, K_MAX)
    k_min = count("k_min", k_min, 1, k_max)
    n_modes = count("n_modes", n_modes, 1, 2000)
    gimbal = nonnegative("gimbal_gain", gimbal_gain)
    if max_seconds is not None:
        max_seconds = positive("max_seconds", max_seconds)
    if not isinstance(boundaries, bool | np.bool_):
        raise ValueError(f"boundaries = {boundaries!r}: must be a bool")
    if boundaries:
        gmax = positive("gamma_max", gamma_max)
        if gmax >= 1.0:
            raise ValueError(f"gamma_max = {gamma_max!r}: must be in (0, 1)")
        n_gamma = count("n_gamma", n_gamma, 2, 1000)
    opts = _floquet_options(rtol, step_phase, max_order, damping_margin)
    if not isinstance(axial, bool | np.bool_):
        raise ValueError(f"axial = {axial!r}: must be a bool")
    harmonics, regions, certs, skipped = [], [], [], []
    searched = 0.0
    mesh = {"supported_forward_end": supported_forward_end,
            "elements_per_segment": elements_per_segment, "order": order}
    path = load_path(vehicle, supported_forward_end)
    for k in range(k_min, k_max + 1):  # up to 200 harmonics, each a small search or none
        if k == 1:  # bending + rigid pitch + gimbaled follower thrust (Beal 1965, eq. 4)
            h = bending_harmonic(vehicle, F0=F0, n_modes=max(n_modes, 3), damping_ratio=zeta,
                                 gimbal_gain=gimbal, **mesh)
        else:
            h = harmonic_system(vehicle, k, F0=F0, n_modes=n_modes, damping_ratio=zeta,
                                **mesh)
        harmonics.append(h)
        spent = HARMONIC_BUILD_SECONDS * len(harmonics) + searched
        rows, cert, why, est = _harmonic_regions(
            h, gamma, lo, hi, opts, budget=None if max_seconds is None else (max_seconds,
                                                                             spent))
        regions += rows
        certs.append(cert)
        searched += est
        if why is not None:
            skipped.append(why)
    regions.sort(key=lambda r: (r.omega_lo, r.k))
    fa = None
    if axial:
        fa = forced_axial(vehicle, F0=F0, omega_min=lo, omega_max=hi, n_modes=n_modes,
                          damping_ratio=zeta, supported_forward_end=supported_forward_end,
                          elements_per_segment=elements_per_segment, order=order)
    found = VehicleRegions(regions=tuple(regions), harmonics=tuple(harmonics), curves=(),
                           F0=F0, gamma=gamma, damping_ratio=zeta, omega_min=lo, omega_max=hi,
                           supported_forward_end=path == "forward support", load_path=path,
                           forced_axial=fa, certificates=tuple(certs), gimbal_gain=gimbal,
                           skipped=tuple(skipped),
                           estimated_seconds=HARMONIC_BUILD_SECONDS * len(harmonics) + searched)
    if boundaries:  # the harmonics that can have a region at gamma_max, in the budget left
        spent = found.estimated_seconds
        curves, why = region_curves(
            found, gamma_max=gmax, n_gamma=n_gamma, rtol=rtol, step_phase=step_phase,
            max_order=max_order, damping_margin=damping_margin,
            max_seconds=None if max_seconds is None else max(max_seconds - spent, 1e-9))
        found = dataclasses.replace(found, curves=curves, skipped=found.skipped + why)
    return found
