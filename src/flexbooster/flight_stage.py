"""The flight stage of :func:`flexbooster.analysis.analyze`: the vehicle at each frozen time of
the case's ``[flight]`` (fills, thrust and oscillation from the schedule), its modes tracked
across times, its parametric regions and k = 0 axial resonances, and the events where the
oscillation band meets them, the worst first. The frozen times are independent
(:func:`frozen_time`, pure, picklable results): one plain loop over them here, or a map on Dask
in the sweep layer (:mod:`flexbooster.sweep.flight`); then :func:`assemble_flight` tracks,
follows and ranks across them (docs/theory/flight.md, "Use in the pipeline").
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from . import cost, floquet
from ._threads import blas_threads
from .bands import SearchGap
from .case import Case
from .checks import FieldValueError
from .dynamics import (
    MIN_PARTICIPATION,
    SLOSH_VALIDITY_FACTOR,
    STANDARD_GRAVITY,
    ForcedAxial,
    IllConditionedError,
    UndampedResonanceError,
    VehicleRegions,
    below_slosh,
    forced_axial,
    forced_response,
    peak_half_width,
    vehicle_regions,
    window_peaks,
    window_regions,
)
from .errors import AnalysisWarning, CaseError
from .flight import (
    KNOWN_FREQUENCY_MARGIN,
    MAX_PASS_OVER_SEARCHES,
    PASS_OVER_REACH,
    band_events,
    band_key,
    band_rate,
    flight_omega_range,
    mac_matrix,
    meeting_intervals,
    pass_over_windows,
    resonance_events,
    track_modes,
    worst_first,
)
from .flight_results import FlightHarmonic, FlightResults, verdict_order
from .model import flight_times, forced_stations, timeline_from_case, vehicle_from_case
from .shell_of_revolution import BucklingError, shared_shell, slosh_modes
from .shell_of_revolution.mass_properties import MassProperties, mass_properties
from .shell_of_revolution.modes import (
    VehicleModes,
    mode_vectors,
    shared_harmonics,
    vehicle_modes,
)
from .shell_of_revolution.survey import has_flat_plate

__all__ = ["flight_stage", "frozen_time", "assemble_flight", "check_fills", "FrozenTime",
           "flight_omega_range", "slosh_warning",
           "KNOWN_FREQUENCY_MARGIN", "MATCH_RTOL", "BASIS_MATCH_RTOL"]

#: A region's mode and a computed mode of the same harmonic are the same mode when their
#: loaded frequencies agree to this relative tolerance (the same eigenproblem solved twice).
MATCH_RTOL = 1e-6
#: A tracked mode and a basis mode of the forced model (its own mesh, cut at the stations) are
#: the same mode when their frequencies agree to this relative tolerance.
BASIS_MATCH_RTOL = 1e-3


def _column(omegas: np.ndarray, omega: float | None) -> int | None:
    """The column of ``omegas`` equal to ``omega`` within :data:`MATCH_RTOL`, or None."""
    if omega is None or omegas.size == 0:
        return None
    i = int(np.argmin(np.abs(omegas - omega)))
    return i if abs(omegas[i] - omega) <= MATCH_RTOL * abs(omega) else None


@dataclass(frozen=True)
class FrozenTime:
    """Everything computed at one frozen time of a flight (:func:`frozen_time`): independent of
    the other times, picklable (numpy arrays and frozen dataclasses), the input of
    :func:`assemble_flight`.

    Attributes
    ----------
    index : int
        Position among the case's frozen times (:func:`flexbooster.model.flight_times`).
    time : float
        The frozen time (s).
    mass : MassProperties
        The vehicle's mass properties with that time's fills.
    modes : VehicleModes
        Its lowest modes per k = 0..k_max under that time's F0.
    regions : VehicleRegions or None
        Its parametric regions of k = 1..k_max (None for k_max = 0).
    axial : ForcedAxial
        Its k = 0 axial resonances and their aft-edge participations.
    vectors : tuple of numpy.ndarray
        Per k = 0..k_max, the modes' DOF vectors (n_dof, n_modes) on the shell's DOFs.
    structural_mass : tuple of numpy.ndarray or None
        Per k, the structure's mass matrix (shell and lumped masses, kg), a weight of the
        MAC: the same at every fill, so held by the frozen time of index 0 only (None at the
        others: a long flight sends it once).
    liquid_mass : tuple of scipy.sparse.csr_matrix
        Per k, the tanks' added mass at this time's fills (kg; nonzero on the wetted walls'
        DOFs only), the other weight of the MAC.
    slosh : tuple of SloshMode
        Each partly filled tank's first slosh mode under this time's acceleration F0 / m.
    """

    index: int
    time: float
    mass: MassProperties
    modes: VehicleModes
    regions: VehicleRegions | None
    axial: ForcedAxial
    vectors: tuple[np.ndarray, ...]
    structural_mass: tuple[np.ndarray, ...] | None
    liquid_mass: tuple = ()
    slosh: tuple = ()


@dataclass(frozen=True)
class _Plan:
    """What every frozen time of a case's flight shares (built from the case alone)."""

    times: np.ndarray
    points: tuple
    base: Any
    k_max: int
    n_modes: int
    omega_range: tuple
    zeta: float
    gain: float


def _plan(case: Case) -> _Plan | None:
    """The flight's shared data, None without ``[flight]``; TypeError naming ``case`` unless
    it is a validated Case."""
    from .vehicle_case import VehicleTable

    if not isinstance(case, Case):
        raise TypeError(f"case = {case!r:.60}: must be a Case, not {type(case).__name__}")

    timeline = timeline_from_case(case)
    if timeline is None:
        return None
    times = flight_times(case)
    table = case.vehicle if case.vehicle is not None else VehicleTable()
    base = vehicle_from_case(case)
    return _Plan(times=times, points=tuple(timeline.at(float(t)) for t in times), base=base,
                 k_max=table.k_max,
                 n_modes=cost.region_modes(case, base, k_max=max(table.k_max, 1))[0],
                 omega_range=flight_omega_range(timeline), zeta=case.vehicle_damping_ratio,
                 gain=case.thrust.K)


def frozen_time(case: Case, index: int) -> FrozenTime:
    """The vehicle of ``case`` at its frozen time ``index``
    (:func:`flexbooster.model.flight_times`): that time's fills (the shell and its mesh
    unchanged), its mass properties, its lowest ``vehicle.n_modes`` modes per k = 0..k_max
    under that time's F0, the parametric regions of k = 1..k_max at that time's F0 and gamma
    over the union of the oscillation bands (:func:`flight_omega_range`), the k = 0 axial
    participations and the modes' DOF vectors. Each harmonic's matrices and eigenpairs are
    computed once for all of them. A pure function of its arguments: the frozen times may run
    in any order, in any process (one BLAS thread, as :func:`flexbooster.analysis.analyze`).
    CaseError on ``flight.points`` where the thrust buckles the vehicle at that time;
    ValueError on ``index`` outside the frozen times or a case without ``[flight]``.

    Parameters
    ----------
    case : Case
        The validated case (SI), with ``[flight]``.
    index : int
        0 .. (number of frozen times - 1).
    """
    plan = _plan(case)
    if plan is None:
        raise ValueError("case: has no [flight], so no frozen time")
    if isinstance(index, bool) or not isinstance(index, (int, np.integer)) or not (
            0 <= index < plan.times.size):
        raise ValueError(f"index = {index!r}: must be an integer in 0..{plan.times.size - 1}")
    return _frozen_at(plan, int(index))


def check_fills(case: Case) -> None:
    """CaseError on ``flight.points`` where a frozen time's fills (the schedule's, linear
    between its points) are not a tank state the vehicle accepts (a liquid depth between 0
    and 1e-5 of the largest radius); nothing without ``[flight]``. Before any solver runs.

    Parameters
    ----------
    case : Case
        The validated case (SI).
    """
    plan = _plan(case)
    for p in () if plan is None else plan.points:
        _tanks_at(plan.base, p)


def _tanks_at(base, p):
    """:func:`_vehicle_at` of frozen point ``p``, or the CaseError of :func:`check_fills`."""
    try:
        return _vehicle_at(base, p.fill)
    except FieldValueError as exc:
        raise CaseError("flight.points", f"fill = {list(p.fill)} at t = {p.time:.6g} s",
                        f"not a tank state at this frozen time ({exc})") from None


def _frozen_at(plan: _Plan, index: int) -> FrozenTime:
    """:func:`frozen_time` of the plan's frozen time ``index``."""
    p = plan.points[index]
    vehicle = _tanks_at(plan.base, p)
    with blas_threads(1):
        mass = mass_properties(vehicle)
        try:
            modes, found, axial, vectors = _frozen_time(
                vehicle, p, k_max=plan.k_max, n_modes=plan.n_modes,
                omega_range=plan.omega_range, zeta=plan.zeta, gain=plan.gain)
        except BucklingError as exc:
            raise CaseError("flight.points", f"F0 = {p.F0:.6g} N at t = {p.time:.6g} s",
                            f"the thrust buckles the vehicle at this frozen time ({exc})"
                            ) from None
        slosh = slosh_modes(vehicle, acceleration=p.F0 / mass.mass_kg) if p.F0 > 0.0 else ()
    ks = range(plan.k_max + 1)
    return FrozenTime(index=index, time=float(plan.times[index]), mass=mass, modes=modes,
                      regions=found, axial=axial, vectors=tuple(vectors[k][0] for k in ks),
                      structural_mass=tuple(vectors[k][1] for k in ks) if index == 0 else None,
                      liquid_mass=tuple(vectors[k][2] for k in ks), slosh=slosh)


def flight_stage(case: Case, *, frozen: Sequence[FrozenTime] | None = None
                 ) -> tuple[FlightResults | None, list[AnalysisWarning]]:
    """The vehicle through the flight of ``case`` (None and no warnings without ``[flight]``):
    :func:`frozen_time` at every frozen time, one after the other in this process, then
    :func:`assemble_flight`.

    Parameters
    ----------
    case : Case
        The validated case (SI).
    frozen : sequence of FrozenTime, optional
        The frozen times already computed elsewhere (``frozen_time(case, i)`` for every i, in
        order; e.g. on Dask, :func:`flexbooster.sweep.flight.frozen_times_on_dask`): then only
        :func:`assemble_flight` runs here. None: computed here.
    """
    plan = _plan(case)
    if plan is None:
        if frozen is not None:
            raise ValueError("frozen: given for a case without [flight]")
        return None, []
    if has_flat_plate(plan.base):  # as the vehicle's regions: the prestress cannot be made
        return None, [AnalysisWarning(
            "flight-skipped", "vehicle.segments",
            "a flat annular plate (a cone of length 0) cannot carry the thrust as a membrane, "
            "so no frozen time has its prestress: the flight is not computed (give the plate an "
            "axial length: a cone)")]
    if frozen is None:
        with shared_shell():  # the shell's mesh and matrices once for every frozen time
            frozen = [_frozen_at(plan, i) for i in range(plan.times.size)]
    return _assemble(case, plan, frozen)


def assemble_flight(case: Case, frozen: Sequence[FrozenTime]
                    ) -> tuple[FlightResults, list[AnalysisWarning]]:
    """The flight of ``case`` from its frozen times: the modes tracked across times by the MAC
    of their DOF vectors weighted by the mean of the two times' mass matrices (Allemang 2003;
    shell, lumped masses and the liquid's added mass, in which each time's modes are
    orthonormal; :func:`flexbooster.flight.track_modes`), the
    regions followed by their tracked modes (:func:`flexbooster.flight.band_events`, rates by
    :func:`flexbooster.flight.band_rate`), the forced resonances at the stations
    (:func:`_forced_events`, in this process), the events worst first, the search gaps and
    the warnings. ValueError on ``frozen`` unless it is :func:`frozen_time` of this case at
    every frozen time, in order.

    Parameters
    ----------
    case : Case
        The validated case (SI), with ``[flight]``.
    frozen : sequence of FrozenTime
        ``frozen_time(case, i)`` for i = 0 .. (number of frozen times - 1).
    """
    plan = _plan(case)
    if plan is None:
        raise ValueError("case: has no [flight] to assemble")
    return _assemble(case, plan, frozen)


def _assemble(case: Case, plan: _Plan, frozen: Sequence[FrozenTime]
              ) -> tuple[FlightResults, list[AnalysisWarning]]:
    """:func:`assemble_flight` with the case's plan."""
    frozen = list(frozen)
    times, points, base, k_max, zeta = plan.times, plan.points, plan.base, plan.k_max, plan.zeta
    lo, hi = plan.omega_range
    if len(frozen) != times.size or any(
            not isinstance(f, FrozenTime) or f.index != i or f.time != times[i]
            for i, f in enumerate(frozen)) or frozen[0].structural_mass is None or any(
            len(f.liquid_mass) != k_max + 1 for f in frozen):
        raise ValueError(f"frozen = {len(frozen)} frozen times: must be frozen_time(case, i) "
                         f"for i = 0..{times.size - 1} of this case, in order")
    structure = frozen[0].structural_mass  # the same at every fill
    macs: dict[int, list] = {k: [] for k in range(k_max + 1)}
    # the MAC between neighbouring times, weighted by the mean of their eigenproblems' masses
    # (structure and liquid), in which each time's modes are orthonormal
    for before, after in zip(frozen[:-1], frozen[1:], strict=True):
        for k in range(k_max + 1):
            weight = structure[k] + (0.5 * (before.liquid_mass[k] + after.liquid_mass[k])).toarray()
            macs[k].append(mac_matrix(before.vectors[k], after.vectors[k], mass=weight))
    masses = [f.mass for f in frozen]
    modes_per_time = [f.modes for f in frozen]
    found_per_time = [(f.regions, f.axial) for f in frozen]
    harmonics = _track(times, modes_per_time, k_max, macs)
    osc = np.array([p.oscillation for p in points])
    extra, pass_gaps, notes = _pass_over_search(times, frozen, harmonics, (lo, hi))
    events = _region_events(times, points, found_per_time, harmonics, modes_per_time, osc,
                            extra)
    warnings: list[AnalysisWarning] = []
    if zeta > 0.0:
        forced, more, note = _forced_events(case, base, times, points, harmonics, osc,
                                            zeta=zeta, omega_range=(lo, hi))
        events += forced
        warnings += more
        notes += note
    else:
        notes.append("no forced resonance peaks: damping.modal_ratio = 0 (undamped)")
    gaps = {}
    for g in [g for found, _ in found_per_time for g in (() if found is None else found.gaps)
              ] + pass_gaps:
        gaps.setdefault((g.limit, g.k), g)
    warnings += [AnalysisWarning("flight-not-fully-searched", "flight", g.reason)
                 for g in gaps.values()]
    regions_per_time = [tuple(sorted((() if f.regions is None else f.regions.regions) + more,
                                     key=lambda r: (r.Omega_lo, r.k)))
                        for f, more in zip(frozen, extra, strict=True)]
    warnings += _slosh_warnings(frozen, regions_per_time)
    result = FlightResults(
        times=times, F0=np.array([p.F0 for p in points]),
        gamma=np.array([p.gamma for p in points]),
        fill=np.array([p.fill for p in points]).reshape(len(points), len(base.tanks)),
        oscillation=osc, tank_names=tuple(t.name for t in base.tanks), mass=tuple(masses),
        harmonics=harmonics, regions=tuple(regions_per_time), omega_range=(lo, hi),
        events=verdict_order(worst_first(events)), gaps=tuple(gaps.values()), notes=tuple(notes))
    return result, warnings


def _pass_over_search(times: np.ndarray, frozen: Sequence[FrozenTime], harmonics,
                      omega_range: tuple) -> tuple[list[tuple], list[SearchGap], list[str]]:
    """The combinations of tracked modes whose centre passes over the searched Omega range
    between two frozen times (:func:`flexbooster.flight.passes_over`), in a harmonic searched
    without a stability certificate at either time (a certified harmonic has no region at any
    Omega), of a kind that can open a region there (:func:`flexbooster.floquet.resonance_kinds`),
    searched at both times in the window centre (1 -+ :data:`flexbooster.flight.PASS_OVER_WINDOW`)
    outside the range (:func:`flexbooster.dynamics.window_regions`; windows merged per time
    and harmonic, within :data:`flexbooster.flight.PASS_OVER_REACH` of the range, at most
    :data:`flexbooster.flight.MAX_PASS_OVER_SEARCHES`), so that their regions are followed
    across the step like any other. Returns, per frozen time, the regions found outside the
    range; the search gaps (windows past the limit or the toolkit's limits); the notes."""
    lo, hi = omega_range
    open_k = [set() for _ in frozen]  # per time: the harmonics searched and not certified
    for t, f in enumerate(frozen):
        if f.regions is not None:
            open_k[t] = {int(h.k) for h, c in zip(f.regions.harmonics, f.regions.certificates,
                                                   strict=True) if not c.certified}
    kinds_at: dict[tuple[int, int], tuple[str, ...]] = {}

    def kinds(t: int, k: int) -> tuple[str, ...]:  # what can open a region of k at time t
        if (t, k) not in kinds_at:
            found = frozen[t].regions
            system = None if found is None else next(
                (x for x in found.harmonics if x.k == k), None)
            kinds_at[(t, k)] = (floquet.RESONANCE_KINDS if system is None else
                                floquet.resonance_kinds(*system.periodic(found.gamma)))
        return kinds_at[(t, k)]

    windows: dict[tuple[int, int], list] = {}  # (time, k) -> merged windows (a, b)
    far: list[tuple] = []  # windows beyond the reach: (k, time, lo, hi)
    count = 0
    for h in harmonics:
        def kinds_between(s: int, k: int = h.k) -> tuple[str, ...]:
            if k not in open_k[s] | open_k[s + 1]:
                return ()
            return tuple(set(kinds(s, k)) | set(kinds(s + 1, k)))

        n, spans, out = pass_over_windows(times, h.frequencies, lo, hi, kinds_at=kinds_between)
        count += n
        windows.update({(t, h.k): v for t, v in spans.items()})
        far += [(h.k, t, a, b) for t, a, b in out]
    extra: list[tuple] = [() for _ in frozen]

    def gap(limit: str, k: int, t: int, a: float, b: float, why: str) -> SearchGap:
        return SearchGap(stage="vehicle", limit=limit, k=k, Omega_lo=a, Omega_hi=b, reason=(
            f"harmonic k = {k} at t = {times[t]:.6g} s not searched in "
            f"{a / (2.0 * math.pi):.4g}-{b / (2.0 * math.pi):.4g} Hz, where a combination "
            f"passes over the oscillation band before or after the next frozen time: {why} "
            "(more flight.stations shorten the steps)"))

    gaps = [gap("PASS_OVER_REACH", k, t, a, b,
                f"beyond PASS_OVER_REACH = {PASS_OVER_REACH:g} x the searched range")
            for k, t, a, b in far]
    searched = 0
    for (t, k), merged in sorted(windows.items()):
        for a, b in merged:
            if searched == MAX_PASS_OVER_SEARCHES:
                gaps.append(gap("MAX_PASS_OVER_SEARCHES", k, t, a, b, "more than "
                                f"MAX_PASS_OVER_SEARCHES = {MAX_PASS_OVER_SEARCHES} such "
                                "windows"))
                continue
            searched += 1
            bands, more = window_regions(frozen[t].regions, k, a, b)
            gaps += list(more)
            # those that reach the range are the range's own search's
            extra[t] += tuple(r for r in bands if r.Omega_hi < lo or r.Omega_lo > hi)
    notes = [] if not count else [
        f"{count} combination(s) of tracked modes pass over the searched Omega range between "
        f"two frozen times: searched at both in {searched} window(s) outside the range, "
        f"{sum(len(e) for e in extra)} region(s) found there"]
    return extra, gaps, notes


def slosh_warning(lead: str, low, slosh) -> AnalysisWarning:
    """The ``liquid-below-slosh`` warning: ``lead`` (where, and "hold(s)"), then the lowest of
    ``low`` (:func:`flexbooster.dynamics.below_slosh` of ``slosh``) and why it is approximate.

    Parameters
    ----------
    lead : str
        The words before "a mode below ...", e.g. "2 parametric region(s) hold".
    low : sequence of (float, str, int)
        :func:`flexbooster.dynamics.below_slosh`, not empty.
    slosh : sequence of SloshMode
        The slosh modes it was made with.
    """
    w, label, k = low[0]
    top = max(slosh, key=lambda m: m.omega)
    return AnalysisWarning("liquid-below-slosh", "vehicle.tanks", (
        f"{lead} a mode below {SLOSH_VALIDITY_FACTOR:g} x the first slosh frequency "
        f"{top.hz:.4g} Hz (tank {top.tank}), the lowest k = {k} {label} at "
        f"{w / (2.0 * math.pi):.4g} Hz: the liquid's added mass is its high-frequency limit "
        "(free surface p = 0, the slosh masses left out), so those modes' frequencies and the "
        "regions' places are approximate there"))


def _slosh_warnings(frozen: Sequence[FrozenTime], regions_per_time) -> list[AnalysisWarning]:
    """:func:`slosh_warning` when a frozen time's region holds a mode below
    :data:`flexbooster.dynamics.SLOSH_VALIDITY_FACTOR` times that time's highest first slosh
    frequency, named at the first such time (as the single case's)."""
    hits = [(f, low) for f, regions in zip(frozen, regions_per_time, strict=True)
            if (low := below_slosh(regions, f.slosh))]
    if not hits:
        return []
    f, low = hits[0]
    return [slosh_warning(f"at {len(hits)} of {len(frozen)} frozen times (the first t = "
                          f"{f.time:.6g} s) a parametric region holds", low, f.slosh)]


def _frozen_time(vehicle, p, *, k_max: int, n_modes: int, omega_range: tuple, zeta: float,
                 gain: float) -> tuple:
    """(modes, regions or None, k = 0 axial resonances, {k: (X, M)}) of ``vehicle`` at frozen
    point ``p``: :func:`vehicle_modes` and :func:`flexbooster.dynamics.vehicle_regions`
    (k >= 1) or :func:`flexbooster.dynamics.forced_axial` (k_max = 0) of that time, and per k
    the modes' DOF vectors and mass matrix (:func:`mode_vectors`), each harmonic's matrices
    and eigenpairs computed once for all of them
    (:func:`flexbooster.shell_of_revolution.shared_harmonics`: the numbers of separate calls;
    a store of its own, released at the end: no other time has this vehicle)."""
    lo, hi = omega_range
    with shared_harmonics(isolated=True):
        modes = vehicle_modes(vehicle, k_max=k_max, n_modes=n_modes, prestress_F0=p.F0)
        vectors = {k: mode_vectors(vehicle, k, n_modes, p.F0) for k in range(k_max + 1)}
        if k_max < 1:
            return modes, None, forced_axial(vehicle, F0=p.F0, omega_min=lo, omega_max=hi,
                                             n_modes=n_modes, damping_ratio=zeta), vectors
        found = vehicle_regions(vehicle, F0=p.F0, gamma=p.gamma, omega_min=lo, omega_max=hi,
                                k_min=1, k_max=k_max, n_modes=n_modes, damping_ratio=zeta,
                                gimbal_gain=gain, unloaded_frequencies=False)
    return modes, found, found.forced_axial, vectors


def _vehicle_at(base, fill: tuple):
    """The vehicle with its tanks filled to ``fill`` (the shell, masses and mesh unchanged)."""
    return dataclasses.replace(base, tanks=tuple(
        dataclasses.replace(tank, fill=f) for tank, f in zip(base.tanks, fill, strict=True)))


def _track(times: np.ndarray, modes_per_time: list, k_max: int,
           macs: dict) -> tuple[FlightHarmonic, ...]:
    """Per k, the modes tracked across the frozen times by ``macs[k]``, the mass-weighted MAC
    between neighbouring times (common DOFs: the mesh does not depend on the fills)."""
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


def _region_events(times, points, found_per_time, harmonics, modes_per_time, osc,
                   extra) -> list:
    """The parametric regions met by the oscillation band, with their accumulated growth
    (``extra``: per frozen time, the regions found outside the searched range)."""
    by_k = {h.k: h for h in harmonics}
    keys: dict[int, tuple] = {}
    bands_per_time, rates_per_time = [], []
    for t, ((found, _), p) in enumerate(zip(found_per_time, points, strict=True)):
        bands = ([] if found is None else list(found.regions)) + list(extra[t])
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


def _forced_events(case: Case, base, times, points, harmonics, osc, *, zeta: float,
                   omega_range: tuple) -> tuple[list, list[AnalysisWarning], list[str]]:
    """The forced resonances the oscillation band crosses: every tracked mode of k = 0 (axial)
    and, with a misaligned thrust, k = 1 (lateral) that the thrust forces, over each run of
    frozen times where it is present, with the peak steady acceleration at the stations near
    its frequency (:func:`flexbooster.dynamics.window_peaks` of that time's
    :func:`flexbooster.dynamics.forced_response`, the case's stations, damping and gimbal)
    and the non-stationary peak where a known frequency crosses it
    (:func:`flexbooster.flight.resonance_events`). Returns (events, warnings, notes)."""
    t = case.thrust
    ks = (0, 1) if t.misalignment != 0.0 else (0,)
    notes = [] if len(ks) == 2 else [
        "no lateral (k = 1) forced resonances: thrust.misalignment = 0 (no lateral force)"]
    if zeta >= math.sqrt(0.5):  # |H| falls monotonically from Omega = 0: no resonant peak
        return [], [], notes + [f"no forced resonance peaks: modal damping ratio {zeta:g} >= "
                                "1/sqrt(2) (no resonant peak)"]
    w = peak_half_width(zeta)
    lo, hi = omega_range
    stations = forced_stations(case, base)[0]
    by_k = {h.k: h for h in harmonics if h.k in ks}
    # the (k, mode, run) whose half-power band meets the oscillation band somewhere, and the
    # frozen times that bound the segments where it does (the events read those alone)
    runs = []
    for k, h in by_k.items():
        for j in range(h.frequencies.shape[1]):
            present = np.isfinite(h.frequencies[:, j])
            edges = np.flatnonzero(np.diff(np.concatenate([[0], present.astype(int), [0]])))
            for a, b in zip(edges[::2], edges[1::2], strict=True):
                om = h.frequencies[a:b, j]
                pieces = [] if b - a < 2 else meeting_intervals(
                    times[a:b], om * (1.0 - zeta), om * (1.0 + zeta), osc[a:b, 0], osc[a:b, 1])
                if pieces:
                    runs.append((k, j, a, b, {a + i + d for _, _, i in pieces for d in (0, 1)}))
    peak = {(k, j): np.zeros(times.size) for k, j, *_ in runs}
    place = {(k, j): np.zeros(times.size, dtype=int) for k, j, *_ in runs}
    share = {(k, j): 0.0 for k, j, *_ in runs}
    names: list[str] = []
    failed: dict[int, str] = {}
    for i, p in enumerate(points):
        for k in ks:
            want = [j for kk, j, _, _, need in runs if kk == k and i in need]
            if not want or k in failed:
                continue
            centres = by_k[k].frequencies[i, want]
            # the model's basis follows the grid's top (its modes below 4 Omega_max): the range
            # searched, widened to every window, the same at every time it covers
            grid = np.array([min(lo, centres.min()) * (1.0 - w),
                             max(hi, centres.max()) * (1.0 + w)])
            try:
                with shared_harmonics(isolated=True):  # that time's vehicle: released after
                    r = forced_response(_vehicle_at(base, p.fill), F0=p.F0, amplitude=p.gamma,
                                        Omega=grid, damping_ratio=zeta,
                                        misalignment=t.misalignment, gimbal_gain=t.K,
                                        pitch_damping_ratio=case.damping.pitch_ratio,
                                        stations=stations, harmonics=(k,))
            except (UndampedResonanceError, IllConditionedError, BucklingError,
                    ValueError) as exc:
                failed[k] = f"at t = {p.time:.6g} s: {exc}"
                continue
            names = [st.name for st in r.stations]
            a_max, _, where = window_peaks(r, k=k, omega=centres, half_width=w)
            model = r.models[0]
            f2 = model.load[model.n_rigid:] ** 2
            basis = model.omega_modes[model.n_rigid:]
            for j, c_j, g, st in zip(want, centres, a_max, where, strict=True):
                peak[(k, j)][i], place[(k, j)][i] = g / STANDARD_GRAVITY, st
                c = int(np.argmin(np.abs(basis - c_j))) if basis.size else -1
                matched = c >= 0 and abs(basis[c] - c_j) <= BASIS_MATCH_RTOL * c_j
                # a mode the forced model does not resolve counts as forced (conservative)
                f = f2[c] / max(float(f2.max()), 1e-300) if matched else 1.0
                share[(k, j)] = max(share[(k, j)], f)
    warnings = [AnalysisWarning("flight-forced-response", "vehicle",
                                f"the k = {k} forced resonances are not computed along the "
                                f"flight ({why})") for k, why in sorted(failed.items())]
    events = []
    for k, j, a, b, _ in runs:
        if k in failed or share[(k, j)] < MIN_PARTICIPATION:
            continue  # not computed (the warning says why), or not forced by the thrust
        h = by_k[k]
        events += resonance_events(
            times[a:b], h.frequencies[a:b, j], osc[a:b], zeta=zeta,
            steady_peak_g=peak[(k, j)][a:b], modes=f"mode {j + 1} ({h.types[a, j]})",
            k=k, station=[names[c] for c in place[(k, j)][a:b]])
    return events, warnings, notes
