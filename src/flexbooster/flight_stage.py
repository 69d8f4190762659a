"""The flight stage of :func:`flexbooster.analysis.analyze`: the vehicle at each frozen time of
the case's ``[flight]`` (fills, thrust and oscillation from the schedule), its modes tracked
across times, its parametric regions and k = 0 axial resonances, and the events where the
oscillation band meets them, the worst first. One plain loop over the frozen times, then one
call per mechanism (docs/theory/flight.md, "Use in the pipeline").
"""

from __future__ import annotations

import dataclasses

import numpy as np

from . import cost, floquet
from .case import Case
from .dynamics import STANDARD_GRAVITY, forced_axial, forced_response, vehicle_regions
from .errors import AnalysisWarning, CaseError
from .flight import (
    band_events,
    band_key,
    band_rate,
    mac_matrix,
    resonance_events,
    track_modes,
    worst_first,
)
from .flight_results import FlightHarmonic, FlightResults
from .model import flight_times, timeline_from_case, vehicle_from_case
from .shell_of_revolution import BucklingError
from .shell_of_revolution.mass_properties import mass_properties
from .shell_of_revolution.modes import mode_vectors, shared_harmonics, vehicle_modes

__all__ = ["flight_stage", "flight_omega_range", "KNOWN_FREQUENCY_MARGIN",
           "MATCH_RTOL", "MIN_PARTICIPATION"]

#: A flight whose oscillation is one constant frequency: the regions are searched over that
#: frequency times (1 -+ this), so that a region holding it is found with its edges.
KNOWN_FREQUENCY_MARGIN = 0.05
#: A region's mode and a computed mode of the same harmonic are the same mode when their
#: loaded frequencies agree to this relative tolerance (the same eigenproblem solved twice).
MATCH_RTOL = 1e-6
#: k = 0 modes whose aft-edge participation phi^2 is below this fraction of the largest are
#: not forced by the thrust (torsion; :data:`flexbooster.dynamics.axial.MIN_SHARE`).
MIN_PARTICIPATION = 1e-8


def flight_omega_range(timeline) -> tuple[float, float]:
    """The Omega range (rad/s) searched at every frozen time: the union of the oscillation
    bands, widened by :data:`KNOWN_FREQUENCY_MARGIN` around one constant frequency.

    Parameters
    ----------
    timeline : flexbooster.flight.Timeline
        The flight's schedule (:func:`flexbooster.model.timeline_from_case`).
    """
    lo = min(p.oscillation[0] for p in timeline.points)
    hi = max(p.oscillation[1] for p in timeline.points)
    if hi <= lo:
        return lo * (1.0 - KNOWN_FREQUENCY_MARGIN), hi * (1.0 + KNOWN_FREQUENCY_MARGIN)
    return lo, hi


def _column(omegas: np.ndarray, omega: float | None) -> int | None:
    """The column of ``omegas`` equal to ``omega`` within :data:`MATCH_RTOL`, or None."""
    if omega is None or omegas.size == 0:
        return None
    i = int(np.argmin(np.abs(omegas - omega)))
    return i if abs(omegas[i] - omega) <= MATCH_RTOL * abs(omega) else None


def flight_stage(case: Case) -> tuple[FlightResults | None, list[AnalysisWarning]]:
    """The vehicle through the flight of ``case`` (None and no warnings without ``[flight]``).

    At each frozen time (:func:`flexbooster.model.flight_times`) the vehicle with that time's
    fills (the shell and its mesh unchanged), its mass properties, its lowest
    ``vehicle.n_modes`` modes per k = 0..k_max under that time's F0, the parametric regions of
    k = 1..k_max at that time's F0 and gamma over the union of the oscillation bands, and the
    k = 0 axial participations. Each time's harmonic matrices and eigenpairs are computed once
    for the modes, the regions and the resonances. The modes are tracked across times by the
    MAC of their DOF vectors weighted by the structure's mass matrix (Allemang 2003; shell
    and lumped masses, the same at every time; :func:`flexbooster.flight.track_modes`), the
    regions followed by their tracked modes
    (:func:`flexbooster.flight.band_events`, rates by :func:`flexbooster.flight.band_rate`) and
    the k = 0 resonances by :func:`flexbooster.flight.resonance_events`. CaseError on
    ``flight.points`` where the thrust buckles the vehicle at a frozen time.

    Parameters
    ----------
    case : Case
        The validated case (SI).
    """
    from .vehicle_case import VehicleTable

    timeline = timeline_from_case(case)
    if timeline is None:
        return None, []
    times = flight_times(case)
    table = case.vehicle if case.vehicle is not None else VehicleTable()
    base = vehicle_from_case(case)
    k_max = table.k_max
    n_modes = cost.region_modes(case, base, k_max=max(k_max, 1))[0]
    zeta = case.vehicle_damping_ratio
    lo, hi = flight_omega_range(timeline)
    points = [timeline.at(float(t)) for t in times]
    masses, regions_per_time, found_per_time, modes_per_time = [], [], [], []
    macs: dict[int, list] = {k: [] for k in range(k_max + 1)}
    previous = None
    for p in points:
        vehicle = _vehicle_at(base, p.fill)
        masses.append(mass_properties(vehicle))
        try:
            modes, found, axial, vectors = _frozen_time(
                vehicle, p, k_max=k_max, n_modes=n_modes, omega_range=(lo, hi), zeta=zeta,
                gain=case.thrust.K)
        except BucklingError as exc:
            raise CaseError("flight.points", f"F0 = {p.F0:.6g} N at t = {p.time:.6g} s",
                            f"the thrust buckles the vehicle at this frozen time ({exc})"
                            ) from None
        if previous is not None:  # MAC weighted by the structure's mass (fill-independent)
            for k, (X, M) in vectors.items():
                macs[k].append(mac_matrix(previous[k], X, mass=M))
        previous = {k: X for k, (X, _) in vectors.items()}
        modes_per_time.append(modes)
        found_per_time.append((found, axial))
        regions_per_time.append(() if found is None else found.regions)
    harmonics = _track(times, modes_per_time, k_max, macs)
    osc = np.array([p.oscillation for p in points])
    events = _region_events(times, points, found_per_time, harmonics, modes_per_time, osc)
    notes = ["the forced response of the bending harmonic k = 1 along the flight is not in "
             "the events; the k = 0 axial resonances are (peak at the aft edge)"]
    warnings = _forced_response_check(_vehicle_at(base, points[0].fill), points[0], zeta,
                                      case.thrust.K)
    if zeta > 0.0:
        events += _axial_events(times, points, found_per_time, harmonics, osc, zeta)
    else:
        notes.append("no k = 0 resonance peaks: damping.modal_ratio = 0 (undamped)")
    gaps = {}
    for found, _ in found_per_time:
        for g in () if found is None else found.gaps:
            gaps.setdefault((g.limit, g.k), g)
    warnings += [AnalysisWarning("flight-not-fully-searched", "flight", g.reason)
                 for g in gaps.values()]
    result = FlightResults(
        times=times, F0=np.array([p.F0 for p in points]),
        gamma=np.array([p.gamma for p in points]),
        fill=np.array([p.fill for p in points]).reshape(len(points), len(base.tanks)),
        oscillation=osc, tank_names=tuple(t.name for t in base.tanks), mass=tuple(masses),
        harmonics=harmonics, regions=tuple(regions_per_time), omega_range=(lo, hi),
        events=tuple(worst_first(events)), gaps=tuple(gaps.values()), notes=tuple(notes))
    return result, warnings


def _frozen_time(vehicle, p, *, k_max: int, n_modes: int, omega_range: tuple, zeta: float,
                 gain: float) -> tuple:
    """(modes, regions or None, k = 0 axial resonances, {k: (X, M)}) of ``vehicle`` at frozen
    point ``p``: :func:`vehicle_modes` and :func:`flexbooster.dynamics.vehicle_regions`
    (k >= 1) or :func:`flexbooster.dynamics.forced_axial` (k_max = 0) of that time, and per k
    the modes' DOF vectors and mass matrix (:func:`mode_vectors`), each harmonic's matrices
    and eigenpairs computed once for all of them
    (:func:`flexbooster.shell_of_revolution.shared_harmonics`: the numbers of separate calls)."""
    lo, hi = omega_range
    with shared_harmonics():
        modes = vehicle_modes(vehicle, k_max=k_max, n_modes=n_modes, prestress_F0=p.F0)
        vectors = {k: mode_vectors(vehicle, k, n_modes, p.F0) for k in range(k_max + 1)}
        if k_max < 1:
            return modes, None, forced_axial(vehicle, F0=p.F0, omega_min=lo, omega_max=hi,
                                             n_modes=n_modes, damping_ratio=zeta), vectors
        found = vehicle_regions(vehicle, F0=p.F0, gamma=p.gamma, omega_min=lo, omega_max=hi,
                                k_min=1, k_max=k_max, n_modes=n_modes, damping_ratio=zeta,
                                gimbal_gain=gain)
    return modes, found, found.forced_axial, vectors


def _vehicle_at(base, fill: tuple):
    """The vehicle with its tanks filled to ``fill`` (the shell, masses and mesh unchanged)."""
    return dataclasses.replace(base, tanks=tuple(
        dataclasses.replace(tank, fill=f) for tank, f in zip(base.tanks, fill, strict=True)))


def _forced_response_check(vehicle, point, zeta: float, gain: float
                           ) -> list[AnalysisWarning]:
    """A ``flight-forced-response`` warning where :func:`flexbooster.dynamics.forced_response`
    refuses the vehicle (e.g. its masses or tanks): the forced response is then not computed
    along the flight; none where it accepts it (one evaluation at the band's lower edge)."""
    try:
        forced_response(vehicle, F0=point.F0, amplitude=point.gamma,
                        Omega=np.array([point.oscillation[0]]), damping_ratio=max(zeta, 1e-3),
                        gimbal_gain=gain)
    except ValueError as exc:
        return [AnalysisWarning("flight-forced-response", "vehicle",
                                f"forced response not computed along the flight: {exc}")]
    return []


def _track(times: np.ndarray, modes_per_time: list, k_max: int,
           macs: dict) -> tuple[FlightHarmonic, ...]:
    """Per k, the modes tracked across the frozen times by ``macs[k]``, the mass-weighted MAC
    between neighbouring times (common DOFs and structural mass: the mesh does not depend on
    the fills)."""
    out = []
    for k in range(k_max + 1):
        masks = [m.select(k) for m in modes_per_time]
        if not all(mask.any() for mask in masks):
            continue
        shapes = [m.shapes[mask].reshape(int(mask.sum()), -1).T
                  for m, mask in zip(modes_per_time, masks, strict=True)]
        omegas = [m.omega[mask] for m, mask in zip(modes_per_time, masks, strict=True)]
        tracked = track_modes(shapes, omegas, macs=macs[k])
        kinds = [m.type[mask] for m, mask in zip(modes_per_time, masks, strict=True)]
        types = np.array([[kinds[t][c] if c >= 0 else "" for c in tracked.order[t]]
                          for t in range(times.size)], dtype=object).astype(str)
        out.append(FlightHarmonic(k=k, frequencies=tracked.frequencies, types=types,
                                  mac=tracked.mac, order=tracked.order))
    return tuple(out)


def _identity(harmonics: dict, modes, t: int, k: int, omega: float | None) -> int | None:
    """The tracked identity at time t of the mode of harmonic k with loaded frequency omega."""
    h = harmonics.get(k)
    if h is None:
        return None
    mask = modes.select(k)
    c = _column(modes.omega[mask], omega)
    if c is None:
        return None
    hit = np.flatnonzero(h.order[t] == c)
    return int(hit[0]) if hit.size else None


def _region_events(times, points, found_per_time, harmonics, modes_per_time, osc) -> list:
    """The parametric regions met by the oscillation band, with their accumulated growth."""
    by_k = {h.k: h for h in harmonics}
    keys: dict[int, tuple] = {}
    bands_per_time, rates_per_time = [], []
    for t, ((found, _), p) in enumerate(zip(found_per_time, points, strict=True)):
        bands = [] if found is None else list(found.regions)
        seen = set()
        rates = []
        for b in bands:
            ids = tuple(_identity(by_k, modes_per_time[t], t, b.k, m.omega) for m in b.modes)
            key = (b.mechanism, b.k, b.kind, b.order,
                   tuple(("mode", j) if j is not None else ("label", m.label, m.index)
                         for j, m in zip(ids, b.modes, strict=True)))
            if key in seen:  # two regions the identities cannot tell apart: keep both
                key = band_key(b) + (len(seen),)
            seen.add(key)
            keys[id(b)] = key
            h = found.harmonic(b.k)
            system = h.periodic(p.gamma)
            rates.append(band_rate(b, *osc[t], growth_at=lambda W, s=system: float(
                floquet.growth_rate(*s, np.array([W]))[0])))
        bands_per_time.append(bands)
        rates_per_time.append(rates)
    if not any(bands_per_time):
        return []
    return list(band_events(times, bands_per_time, osc, rates_per_time=rates_per_time,
                            key=lambda b: keys[id(b)]))


def _axial_events(times, points, found_per_time, harmonics, osc, zeta: float) -> list:
    """The k = 0 forced resonances the oscillation band crosses, with the peak aft-edge
    acceleration: steady peak phi^2 gamma F0 / (2 zeta) (m/s^2; Meirovitch 1986, the modal
    FRF at resonance) at each frozen time, non-stationary where a known frequency crosses."""
    h0 = next((h for h in harmonics if h.k == 0), None)
    if h0 is None:
        return []
    T, N = h0.frequencies.shape
    phi2 = np.zeros((T, N))
    for t, (_, axial) in enumerate(found_per_time):
        for j in range(N):
            c = _column(axial.omega_loaded, None if not np.isfinite(h0.frequencies[t, j])
                        else float(h0.frequencies[t, j]))
            if c is not None:
                phi2[t, j] = axial.participation[c] ** 2
    forced = phi2.max(axis=0) >= MIN_PARTICIPATION * max(float(phi2.max()), 1e-300)
    F0 = np.array([p.F0 for p in points])
    gamma = np.array([p.gamma for p in points])
    events = []
    for j in np.flatnonzero(forced & (phi2.max(axis=0) > 0.0)):
        present = np.isfinite(h0.frequencies[:, j])
        # every run of consecutive frozen times where identity j is present
        edges = np.flatnonzero(np.diff(np.concatenate([[0], present.astype(int), [0]])))
        for a, b in zip(edges[::2], edges[1::2], strict=True):
            if b - a < 2:
                continue
            peak_g = phi2[a:b, j] * gamma[a:b] * F0[a:b] / (2.0 * zeta) / STANDARD_GRAVITY
            kind = h0.types[a, j]
            events += resonance_events(
                times[a:b], h0.frequencies[a:b, j], osc[a:b], zeta=zeta, steady_peak_g=peak_g,
                modes=f"{kind} (k = 0, mode {j})", k=0, station="aft-edge")
    return events
