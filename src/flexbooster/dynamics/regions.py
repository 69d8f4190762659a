"""Parametric instability regions of the pre-stressed shell-of-revolution vehicle.

Per harmonic k, in the modes loaded by F0: q'' + (K_e + K_g) q - gamma cos(Omega t) K_g q = 0
(Bolotin 1964, sec. 8), its regions by :func:`flexbooster.floquet.instability_regions`.
Theory: docs/theory/vehicle-regions.md.

References: V. V. Bolotin, *The Dynamic Stability of Elastic Systems*, 1964, ch. 1-2,
sec. 6, 8; C. S. Hsu, J. Appl. Mech. 30 (1963) 367-372; D. Bushnell, Computers & Structures
4 (1974) 399-435.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from .. import floquet
from ..bands import CRITICAL_DAMPING_COUNT
from ..checks import count, nonnegative, positive
from ..shell_of_revolution import DEFAULT_ORDER, Vehicle
from ..shell_of_revolution.prestress import load_path
from .axial import ForcedAxial, forced_axial
from .bending import bending_harmonic
from .harmonic import (
    LIMIT_ERRORS,
    HarmonicSystem,
    floquet_options,
    harmonic_regions,
    in_unit_interval,
    limit_gap,
    loaded_modes,
)

__all__ = ["RegionCurve", "VehicleRegions", "harmonic_system", "vehicle_regions",
           "window_regions", "region_curves", "region_critical_damping", "below_slosh",
           "SLOSH_VALIDITY_FACTOR"]

#: The liquid's added mass is the high-frequency limit (free surface p = 0: the slosh masses
#: left out); a slosh oscillator of mass m_1 and frequency omega_s adds m_1 omega_s^2 /
#: (omega_s^2 - omega^2) at omega, a third of m_1 at omega = 2 omega_s and more below: a mode
#: below this factor times a tank's first slosh frequency is not at the model's frequency.
SLOSH_VALIDITY_FACTOR = 2.0

#: Largest harmonic accepted (as :mod:`flexbooster.shell_of_revolution`).
K_MAX = 200


@dataclass(frozen=True)
class RegionCurve:
    """Edges of one region of harmonic k in the (Omega, gamma) plane (Bolotin 1964, ch. 1).

    Attributes
    ----------
    k, kind, order : int, str, int
        As :class:`flexbooster.bands.Band`.
    modes : tuple of int
        Steady mode indices in harmonic k.
    gamma, omega_lo, omega_hi : ndarray
        Amplitudes ascending from the critical one, and the edges there (rad/s).
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
    """Instability map of the vehicle: the regions of every harmonic k_min..k_max.

    Attributes
    ----------
    regions : tuple of Band
        Sorted by Omega_lo, then k.
    harmonics : tuple of HarmonicSystem
        The periodic system of each harmonic (k ascending).
    curves : tuple of RegionCurve
        Edges in (Omega, gamma) (empty unless asked for).
    F0, gamma, damping_ratio : float
        Steady thrust (N), pulsation amplitude and modal damping ratio.
    omega_min, omega_max : float
        Omega range (rad/s).
    supported_forward_end : bool
        The nose reacts the thrust ("forward support").
    load_path : str
        What balances the thrust (:data:`flexbooster.shell_of_revolution.prestress.LOAD_PATHS`).
    forced_axial : ForcedAxial or None
        k = 0: the axial modes forced by the pulsation (:mod:`.axial`); None when not asked.
    certificates : tuple of StabilityCertificate
        Per harmonic: :func:`flexbooster.floquet.stability_certificate` at gamma.
    chart_gamma_max : float or None
        Top gamma of the (Omega, gamma) chart asked for.
    gimbal_gain : float
        Gimbal gain K of the k = 1 harmonic.
    gaps : tuple of SearchGap
        Harmonics the size limits left out of the search: their regions are unknown.
    chart_gaps : tuple of SearchGap
        Harmonics whose boundary curves the size limits left out of the chart.
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
    gaps: tuple = ()
    chart_gaps: tuple = ()

    @property
    def certified_margin(self) -> float | None:
        """The smallest factor on gamma up to which every harmonic is certified free of
        regions at every Omega (the stability certificate's 1 / rho, Bolotin 1964, sec. 6: a
        lower bound of every region's margin critical gamma / gamma); None without damping,
        without pulsation or where a harmonic is not certified at gamma. inf when no harmonic
        is excited."""
        if self.damping_ratio <= 0.0 or self.gamma <= 0.0 or not self.certificates or \
                not all(c.certified for c in self.certificates):
            return None
        return float(min(c.amplitude_factor for c in self.certificates))

    def harmonic(self, k: int) -> HarmonicSystem:
        """The system of harmonic k (one of those computed)."""
        for h in self.harmonics:
            if h.k == k:
                return h
        raise ValueError(f"k = {k!r}: not computed (k = {[h.k for h in self.harmonics]})")

    def to_dict(self) -> dict:
        """JSON-ready mapping (the matrices only through :meth:`HarmonicSystem.to_dict`)."""
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
                "gaps": [g.to_dict() for g in self.gaps],
                "chart_gaps": [g.to_dict() for g in self.chart_gaps]}


def _vehicle(vehicle) -> Vehicle:
    if not isinstance(vehicle, Vehicle):
        raise ValueError(f"vehicle = {vehicle!r}: must be a Vehicle")
    return vehicle


def _range(omega_min, omega_max) -> tuple[float, float]:
    lo, hi = positive("omega_min", omega_min), positive("omega_max", omega_max)
    if lo >= hi:
        raise ValueError(f"omega_min = {omega_min!r}: must be < omega_max = {omega_max!r}")
    return lo, hi


def harmonic_system(
    vehicle: Vehicle, k: int, *, F0: float, n_modes: int = 20, damping_ratio: float = 0.01,
    supported_forward_end: bool | None = None, elements_per_segment: int | tuple | None = None,
    order: int = DEFAULT_ORDER, unloaded_frequencies: bool = True,
) -> HarmonicSystem:
    """Periodic modal system of harmonic k under T(t) = F0 (1 - gamma cos Omega t) (Bolotin 1964,
    sec. 8); BucklingError (with the load factor) when F0 buckles the harmonic.

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    k : int
        Circumferential wave number, 2..200.
    F0 : float
        Steady thrust (N), > 0.
    n_modes : int
        Loaded modes in the basis, 1..2000.
    damping_ratio : float
        Modal damping ratio of the loaded modes, [0, 1).
    supported_forward_end : bool or None
        Load path: None from the vehicle's ends, True uniform compression, False inertia relief
        (:func:`flexbooster.shell_of_revolution.prestress.load_path`).
    elements_per_segment, order
        The mesh (:func:`flexbooster.shell_of_revolution.mesh_vehicle`).
    unloaded_frequencies : bool
        Also solve the unloaded eigenproblem for ``omega_unloaded`` (which only describes the
        harmonic); False: ``omega_unloaded`` empty, every other field the same.
    """
    vehicle = _vehicle(vehicle)
    k = count("k", k, 2, K_MAX)
    F0 = positive("F0", F0)
    n_modes = count("n_modes", n_modes, 1, 2000)
    zeta = in_unit_interval("damping_ratio", damping_ratio)
    load_path(vehicle, supported_forward_end)  # checks the flag
    ms, labels, w2, V = loaded_modes(vehicle, k, n_modes, F0,
                                     supported_forward_end=supported_forward_end,
                                     elements_per_segment=elements_per_segment, order=order,
                                     unloaded_frequencies=unloaded_frequencies)
    omega_l = np.sqrt(w2)
    n = omega_l.size
    mode_order, mode_type = labels()
    dom = np.argmax(V**2, axis=0)  # basis mode dominating each loaded one (V = I)
    kg = V.T @ ms.geometric @ V
    return HarmonicSystem(
        k=k, F0=F0, damping_ratio=zeta, omega_unloaded=ms.omega_unloaded, omega_loaded=omega_l,
        basis=V, mass=np.eye(n), damping=2.0 * zeta * np.diag(omega_l),
        stiffness=np.diag(w2),  # A = V^T (K_e + K_g) V
        excitation=-0.5 * (kg + kg.T),  # B = -gamma K_g: T/F0 = 1 - gamma cos Omega t
        mode_order=mode_order[dom].astype(int), mode_type=mode_type[dom].astype(str),
        mode_share=(V**2)[dom, np.arange(n)])


def _toolkit_region(band) -> floquet.InstabilityRegion:
    """The toolkit's region of a band of the map (the top level of
    :func:`flexbooster.floquet.region_boundaries`).
    """
    return floquet.InstabilityRegion(
        omega_lo=band.Omega_lo, omega_hi=band.Omega_hi, growth_rate_max=band.growth_rate_max,
        omega_at_max=band.Omega_at_max, kind=band.kind, modes=tuple(m.index for m in band.modes),
        order=band.order, omega_center=band.Omega_center, clipped=band.clipped)


def region_curves(
    found: VehicleRegions, *, gamma_max: float, n_gamma: int = 11, rtol: float = 1e-9,
    step_phase: float = 0.12, max_order: int | None = None,
    damping_margin: float | None = floquet.DAMPING_MARGIN,
) -> tuple[tuple, tuple]:
    """Edges in (Omega, gamma) of the regions of a map up to gamma_max, as (curves, gaps): the
    harmonics with a non-"steady" region (gamma_max = the map's gamma) or not certified stable
    at gamma_max; a SearchGap per harmonic past a size limit (Bolotin 1964, ch. 1, sec. 6).

    Parameters
    ----------
    found : VehicleRegions
        The map (:func:`vehicle_regions`).
    gamma_max : float
        Top gamma, (0, 1).
    n_gamma : int
        Levels, 2..1000.
    rtol, step_phase, max_order, damping_margin
        As :func:`vehicle_regions` (the map's).
    """
    if not isinstance(found, VehicleRegions):
        raise ValueError(f"found = {type(found).__name__}: must be a VehicleRegions")
    gmax = in_unit_interval("gamma_max", gamma_max)
    if gmax <= 0.0:
        raise ValueError(f"gamma_max = {gamma_max!r}: must be in (0, 1)")
    n_gamma = count("n_gamma", n_gamma, 2, 1000)
    opts = floquet_options(rtol, step_phase, max_order, damping_margin)
    lo, hi = found.omega_min, found.omega_max
    curves, gaps = [], []
    for h in found.harmonics:
        M, C, A, B = h.periodic(gmax)
        top = None
        if gmax == found.gamma:  # the map's rows are the top level
            rows = [r for r in found.regions if r.k == h.k]
            if not any(r.kind != "steady" for r in rows):
                continue
            top = tuple(_toolkit_region(r) for r in rows)
        elif floquet.stability_certificate(M, C, A, B).certified:
            continue  # no region at gamma_max: nothing to trace
        try:
            traced = floquet.region_boundaries(M, C, A, h.excitation, gamma_max=gmax,
                                               omega_min=lo, omega_max=hi, n_gamma=n_gamma,
                                               regions=top, **opts)
        except LIMIT_ERRORS as exc:
            gaps.append(limit_gap(h, lo, hi, exc, "not traced for the chart"))
            continue
        curves += [RegionCurve(k=h.k, kind=c.kind, order=c.order, modes=c.modes,
                               gamma=c.gamma, omega_lo=c.omega_lo, omega_hi=c.omega_hi)
                   for c in traced]
    return tuple(curves), tuple(gaps)


def vehicle_regions(
    vehicle: Vehicle, *, F0: float, gamma: float, omega_min: float, omega_max: float,
    k_max: int, k_min: int = 2, n_modes: int = 20, damping_ratio: float = 0.01,
    supported_forward_end: bool | None = None, elements_per_segment: int | tuple | None = None,
    order: int = DEFAULT_ORDER, boundaries: bool = False, gamma_max: float = 0.5,
    n_gamma: int = 11, rtol: float = 1e-9, step_phase: float = 0.12,
    max_order: int | None = None, damping_margin: float | None = floquet.DAMPING_MARGIN,
    axial: bool = True, gimbal_gain: float = 0.0, unloaded_frequencies: bool = True,
) -> VehicleRegions:
    """Parametric instability regions of every harmonic k_min..k_max in [omega_min, omega_max];
    a harmonic past a size limit of the toolkit is a SearchGap. ValueError for bad input,
    BucklingError when the steady thrust buckles a harmonic (Bolotin 1964; Hsu 1963; Beal 1965).

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    F0, gamma : float
        T(t) = F0 (1 - gamma cos Omega t): F0 > 0 (N), gamma in [0, 1).
    omega_min, omega_max : float
        Omega range (rad/s), 0 < omega_min < omega_max.
    k_max, k_min : int
        Harmonics, 1 <= k_min <= k_max <= 200; k = 1 is the bending harmonic
        (:func:`.bending.bending_harmonic`, at least 3 basis modes).
    gimbal_gain : float
        K of the gimbal control for k = 1, >= 0.
    n_modes, damping_ratio, supported_forward_end, elements_per_segment, order
        As :func:`harmonic_system`.
    boundaries, gamma_max, n_gamma
        Also the edges in (Omega, gamma) up to gamma_max (:func:`region_curves`).
    rtol, step_phase, max_order, damping_margin
        Options of :func:`flexbooster.floquet.instability_regions`.
    axial : bool
        Also the k = 0 forced axial resonances (:func:`.axial.forced_axial`).
    unloaded_frequencies : bool
        The harmonics' ``omega_unloaded`` for k >= 2 (:func:`harmonic_system`; False: empty,
        one eigenproblem per harmonic fewer, the regions the same).
    """
    vehicle = _vehicle(vehicle)
    F0 = positive("F0", F0)
    gamma = in_unit_interval("gamma", gamma)
    zeta = in_unit_interval("damping_ratio", damping_ratio)
    lo, hi = _range(omega_min, omega_max)
    k_max = count("k_max", k_max, 1, K_MAX)
    k_min = count("k_min", k_min, 1, k_max)
    n_modes = count("n_modes", n_modes, 1, 2000)
    gimbal = nonnegative("gimbal_gain", gimbal_gain)
    for name, flag in (("boundaries", boundaries), ("axial", axial),
                       ("unloaded_frequencies", unloaded_frequencies)):
        if not isinstance(flag, bool | np.bool_):
            raise ValueError(f"{name} = {flag!r}: must be a bool")
    if boundaries:
        gmax = positive("gamma_max", gamma_max)
        if gmax >= 1.0:
            raise ValueError(f"gamma_max = {gamma_max!r}: must be in (0, 1)")
        n_gamma = count("n_gamma", n_gamma, 2, 1000)
    opts = floquet_options(rtol, step_phase, max_order, damping_margin)
    path = load_path(vehicle, supported_forward_end)  # checks the flag
    mesh = {"supported_forward_end": supported_forward_end,
            "elements_per_segment": elements_per_segment, "order": order}
    harmonics, regions, certs, gaps = [], [], [], []
    for k in range(k_min, k_max + 1):
        if k == 1:  # bending + rigid pitch + gimbaled follower thrust (Beal 1965, eq. 4)
            h = bending_harmonic(vehicle, F0=F0, n_modes=max(n_modes, 3), damping_ratio=zeta,
                                 gimbal_gain=gimbal, **mesh)
        else:
            h = harmonic_system(vehicle, k, F0=F0, n_modes=n_modes, damping_ratio=zeta,
                                unloaded_frequencies=unloaded_frequencies, **mesh)
        harmonics.append(h)
        certs.append(floquet.stability_certificate(*h.periodic(gamma)))
        if certs[-1].certified and opts["damping_margin"] is not None:
            continue  # stable at every Omega: the search's own first test, already passed
        found_k, gap_k = _search(h, gamma, lo, hi, opts)
        regions += found_k
        gaps += gap_k
    regions.sort(key=lambda r: (r.Omega_lo, r.k))
    fa = None
    if axial:
        fa = forced_axial(vehicle, F0=F0, omega_min=lo, omega_max=hi, n_modes=n_modes,
                          damping_ratio=zeta, **mesh)
    found = VehicleRegions(regions=tuple(regions), harmonics=tuple(harmonics), curves=(),
                           F0=F0, gamma=gamma, damping_ratio=zeta, omega_min=lo, omega_max=hi,
                           supported_forward_end=path == "forward support", load_path=path,
                           forced_axial=fa, certificates=tuple(certs), gimbal_gain=gimbal,
                           gaps=tuple(gaps))
    if boundaries:
        curves, more = region_curves(found, gamma_max=gmax, n_gamma=n_gamma, rtol=rtol,
                                     step_phase=step_phase, max_order=max_order,
                                     damping_margin=damping_margin)
        found = dataclasses.replace(found, curves=curves, chart_gaps=more)
    return found


def window_regions(found: VehicleRegions, k: int, omega_min: float, omega_max: float
                   ) -> tuple[tuple, tuple]:
    """The regions of harmonic k of a map in another Omega window: its harmonic system at its
    gamma, searched as :func:`vehicle_regions` searches (default options, critical gamma of
    each), e.g. a flight's frozen time outside its searched range. Returns (bands, gaps): the
    bands sorted by Omega_lo, or a SearchGap past a size limit of the toolkit.

    Parameters
    ----------
    found : VehicleRegions
        The map (its ``harmonics`` hold harmonic k).
    k : int
        Circumferential harmonic, one of the map's.
    omega_min, omega_max : float
        The window (rad/s), 0 < omega_min < omega_max.
    """
    lo, hi = _range(omega_min, omega_max)
    bands, gaps = _search(found.harmonic(k), found.gamma, lo, hi, floquet_options())
    return tuple(sorted(bands, key=lambda r: r.Omega_lo)), gaps


def _search(h: HarmonicSystem, gamma: float, lo: float, hi: float, opts: dict
            ) -> tuple[list, tuple]:
    """:func:`harmonic_regions` of one harmonic, or its SearchGap past a size limit of the
    toolkit: (bands, gaps)."""
    try:
        return harmonic_regions(h, gamma, lo, hi, opts), ()
    except LIMIT_ERRORS as exc:
        return [], (limit_gap(h, lo, hi, exc),)


def region_critical_damping(found: VehicleRegions, *, growth_floor: float = 0.0,
                            limit: int = CRITICAL_DAMPING_COUNT) -> VehicleRegions:
    """The map with the critical damping ratio (the smallest modal damping ratio that closes
    the region at the map's gamma, Bolotin 1964, sec. 6) of its ``limit`` fastest-growing
    regions that grow faster than ``growth_floor``, are not clipped by the Omega range and hold
    no (undamped) rigid mode; None on the others (and where a damping ratio of 1 does not close
    it).

    Parameters
    ----------
    found : VehicleRegions
        The map (:func:`vehicle_regions`).
    growth_floor : float
        Regions growing slower than this (1/s) are left out, >= 0.
    limit : int
        At most this many regions, >= 0.
    """
    if not isinstance(found, VehicleRegions):
        raise ValueError(f"found = {type(found).__name__}: must be a VehicleRegions")
    floor = nonnegative("growth_floor", growth_floor)
    limit = count("limit", limit, 0, 10_000)
    by_k = {h.k: h for h in found.harmonics}
    # the rigid modes of k = 1 are undamped: no modal damping closes a region holding one
    # (threshold lambda^2 > delta_i delta_k = 0, Hsu 1963), its growth only falls to round-off
    chosen = sorted((i for i, r in enumerate(found.regions)
                     if r.kind != "steady" and not r.clipped and r.k in by_k
                     and not any(m.type.startswith("rigid") for m in r.modes)
                     and r.growth_rate_max > max(floor, 2.0 * floquet.CLOSED_GROWTH * r.Omega_hi)),
                    key=lambda i: -found.regions[i].growth_rate_max)[:limit]
    regions = list(found.regions)
    for i in chosen:
        r = regions[i]
        h = by_k[r.k]
        M, _, A, B = h.matrices(found.gamma)
        zeta_cr = floquet.critical_damping(M, h.damping_per_ratio, A, B, omega_lo=r.Omega_lo,
                                           omega_hi=r.Omega_hi, zeta=found.damping_ratio,
                                           omega_start=r.Omega_at_max)
        regions[i] = dataclasses.replace(r, critical_damping_ratio=zeta_cr)
    return dataclasses.replace(found, regions=tuple(regions))


def below_slosh(regions, slosh) -> tuple[tuple[float, str, int], ...]:
    """The modes of ``regions`` below :data:`SLOSH_VALIDITY_FACTOR` times the highest first
    slosh frequency of ``slosh`` (where the liquid's high-frequency added mass leaves out
    slosh masses that move with the tank: docs/theory/liquid.md), one (omega in rad/s, label,
    k) per region that holds one (its lowest), the lowest first; () without slosh modes.

    Parameters
    ----------
    regions : sequence of Band
        Parametric regions of the vehicle (their modes' loaded frequencies ``omega``).
    slosh : sequence of SloshMode
        The first slosh mode of each partly filled tank (:func:`.slosh_modes`).
    """
    if not slosh:
        return ()
    limit = SLOSH_VALIDITY_FACTOR * max(m.omega for m in slosh)
    out = []
    for r in regions:
        low = [(m.omega, m.label, r.k) for m in r.modes
               if m.omega is not None and 0.0 < m.omega < limit]
        if low:
            out.append(min(low))
    return tuple(sorted(out))
