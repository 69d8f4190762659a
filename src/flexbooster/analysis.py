"""The analysis pipeline: a validated case in, a :class:`~flexbooster.results.Results` out.

A plain sequence of stages in the memo's order, each from the one model built from the case
(:func:`flexbooster.model.model_from_case`): beam modes, rigid-body pitch, shell frequencies,
beam action, unstable thrust frequencies (memo 7.3) and their severity, figure data, then the
vehicle's modes and parametric instability regions (:mod:`flexbooster.dynamics`) with the
memo-table roots inside each region; and the warnings under which the analysis goes on. For a
``[[vehicle.segments]]`` case the memo's stages do not apply: the vehicle's mass properties, its
rigid-body pitch, modes and regions (``Results.not_applicable`` holds the reason).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Sequence

import numpy as np

from . import cost, floquet
from ._threads import blas_threads
from .bands import NEGLIGIBLE_GROWTH
from .case import Case, deprecation_warnings
from .checks import count, finite, positive
from .danger import (
    axial_resonance_peaks,
    danger_summary,
    flight_verdict,
    merge_responses,
)
from .dynamics import (
    IllConditionedError,
    ThrustSpectrum,
    UndampedResonanceError,
    VehicleRegions,
    below_slosh,
    forced_response,
    mode_peaks,
    region_critical_damping,
    region_curves,
    vehicle_regions,
)
from .errors import AnalysisWarning
from .flight_stage import FrozenTime, check_fills, flight_stage, slosh_warning
from .memo import charts
from .memo.beam import beam_modes
from .memo.beam_action import PeriodMapOverflowError, beam_action_analysis
from .memo.model import BoosterModel
from .memo.pitch import pitch_analysis, pitch_frequency
from .memo.responses import SimulationResult, excitation_parameters, simulate
from .memo.severity import severity_analysis
from .memo.shell import natural_frequencies
from .memo.stability import ShellModes, StabilityTable, TooManyRootsError, unstable_frequencies
from .model import MEMO_NOT_APPLICABLE, forced_stations, model_from_case, vehicle_from_case
from .results import SCHEMA_VERSION, UNITS, ForcedLoads, MemoRootsInRegions, Results
from .shell_of_revolution import BucklingError, mass_properties, shared_harmonics
from .shell_of_revolution.survey import VehicleSurvey, has_flat_plate, vehicle_survey

__all__ = [
    "analyze",
    "analyze_vehicle",
    "vehicle_warnings",
    "slosh_warnings",
    "analyze_vehicle_regions",
    "analyze_forced_response",
    "forced_settings",
    "modal_damping_ratio",
    "memo_roots_in_regions",
    "simulate_case",
    "SCHEMA_VERSION",
    "UNITS",
    "STAGES",
    "VEHICLE_STAGE",
    "VEHICLE_REGIONS_STAGE",
    "FORCED_STAGE",
    "VEHICLE_REGIONS_K_MIN",
    "THIN_SHELL_LIMIT",
    "MATHIEU_A_RANGE",
    "MATHIEU_Q_MAX",
]

#: The stages of :func:`analyze`, in order, as passed to its ``progress`` callback.
STAGES = (
    "mass properties and beam modes",
    "rigid-body pitch",
    "shell frequencies",
    "beam action",
    "unstable thrust frequencies",
    "figure data",
)
#: The stage announced after :data:`STAGES` for a case with ``[vehicle]`` only.
VEHICLE_STAGE = "vehicle modes"
#: The stage announced last, unless ``analyze(..., vehicle=False)``: the vehicle's parametric
#: instability regions (every case: ``[vehicle]`` or the memo's two cylinders).
VEHICLE_REGIONS_STAGE = "vehicle instability regions"
#: The stage announced after :data:`VEHICLE_REGIONS_STAGE`, unless ``analyze(..., vehicle=False)``:
#: the vehicle's forced response to the thrust oscillation (k = 0 and 1).
FORCED_STAGE = "vehicle forced response"
#: Harmonics k of the vehicle regions: k = VEHICLE_REGIONS_K_MIN..vehicle.k_max (default 20,
#: also for the memo vehicle of a case without ``[vehicle]``); k = 1 is the bending harmonic
#: with the rigid pitch, the gimbal control and the follower thrust
#: (:func:`flexbooster.dynamics.bending_regions`), k = 0 the forced axial resonances.
VEHICLE_REGIONS_K_MIN = 1
#: Thin-shell theory (Donnell, memo 2.3) is trusted for h/R up to 1/20.
THIN_SHELL_LIMIT = 1.0 / 20.0
#: The memo's range for the Mathieu parameters (eq. 4.2-5): 0 < a < 1, 0 < q <= 0.05.
MATHIEU_A_RANGE = (0.0, 1.0)
MATHIEU_Q_MAX = 0.05


def _range_text(Omega: np.ndarray, mask: np.ndarray) -> str:
    lo, hi = Omega[mask].min(), Omega[mask].max()
    return f"{int(mask.sum())} of {mask.size} grid points, Omega in [{lo:.6g}, {hi:.6g}] rad/s"


def _warnings(model: BoosterModel, a: np.ndarray, q: np.ndarray) -> list[AnalysisWarning]:
    """Thin-shell limit exceeded; Mathieu a, q outside the memo's range (eq. 4.2-5)."""
    out = [AnalysisWarning("thin-shell", f"booster.cylinder{d}",
                           f"h/R{d} = {model.h / radius:.4g} exceeds 1/20: thin-shell (Donnell) "
                           "theory of memo 2.3 is not reliable")
           for d, radius in ((1, model.R1), (2, model.R2)) if model.h / radius > THIN_SHELL_LIMIT]
    return out + _mathieu_warnings(model.Omega, model.omega_psi, a, q)


def _mathieu_warnings(Omega: np.ndarray, omega_psi: float, a: np.ndarray, q: np.ndarray
                      ) -> list[AnalysisWarning]:
    """Mathieu a, q of the rigid pitch outside the memo's range (eq. 4.2-5)."""
    out = []
    bad_a = ~((a > MATHIEU_A_RANGE[0]) & (a < MATHIEU_A_RANGE[1]))
    if bad_a.any():
        out.append(AnalysisWarning(
            "mathieu-a-range", "thrust",
            f"Mathieu a outside the memo's range 0 < a < 1 (eq. 4.2-5) at "
            f"{_range_text(Omega, bad_a)}; a = 4 omega_psi^2/Omega^2 with "
            f"omega_psi = {omega_psi:.6g} rad/s"))
    bad_q = ~((q > 0.0) & (q <= MATHIEU_Q_MAX))
    if bad_q.any():
        out.append(AnalysisWarning(
            "mathieu-q-range", "thrust",
            f"Mathieu q outside the memo's range 0 < q <= 0.05 (eq. 4.2-5) at "
            f"{_range_text(Omega, bad_q)}; q = gamma a / 2"))
    return out


def _check_case(case: object) -> None:
    """TypeError naming ``case`` unless it is a validated :class:`~flexbooster.case.Case`."""
    if not isinstance(case, Case):
        raise TypeError(f"case = {case!r:.60}: must be a Case (flexbooster.load_case or "
                        f"default_case), not {type(case).__name__}")


def analyze(
    case: Case,
    beam_action: bool = True,
    stability: bool = True,
    progress: Callable[[str], None] | None = None,
    figures: bool = True,
    *,
    vehicle: bool = True,
    on_estimate: Callable[[cost.CostEstimate, float], None] | None = None,
    frozen: Sequence[FrozenTime] | None = None,
) -> Results:
    """Run the analysis of a validated case: the stages of :data:`STAGES` in order.

    Parameters
    ----------
    case : Case
        From :func:`flexbooster.load_case` or :func:`flexbooster.default_case`.
    beam_action : bool
        Compute the beam action (memo 4.1); ``stability`` needs it.
    stability : bool
        Compute the unstable thrust frequencies (memo 7.3) and their severity.
    progress : callable, optional
        Called with the name of each stage as it starts.
    figures : bool
        Compute the data of the figures (``results.figures``; None without).
    vehicle : bool
        Compute the vehicle's parametric instability regions and the memo roots inside them.
    on_estimate : callable, optional
        Called before any solver runs with the cost estimate and ``case.max_seconds`` (s).
    frozen : sequence of FrozenTime, optional
        For a case with ``[flight]``: its frozen times already computed
        (:func:`flexbooster.flight_stage.frozen_time` at every index, in order; on Dask by
        :func:`flexbooster.sweep.flight.analyze_on_dask`). The flight stage then assembles
        them (:func:`flexbooster.flight_stage.assemble_flight`) and the cost estimate leaves
        them out; the results are those of ``frozen=None``, which computes them here.
    """
    _check_case(case)
    if frozen is not None and not vehicle:
        raise ValueError("frozen: given with vehicle=False, which computes no flight")
    step = progress or (lambda stage: None)
    case.required_thrust()  # a one-line CaseError on thrust before any stage
    if case.has_segments:  # the memo's method does not apply: the vehicle's stages only
        return _analyze_segments(case, step, figures=figures, regions=vehicle,
                                 on_estimate=on_estimate, frozen=frozen)
    # many small eigenproblems: one BLAS thread is the fastest; the case's vehicle and its
    # harmonics built once for the estimate and every stage
    with blas_threads(1), shared_harmonics():
        step(STAGES[0])
        model = model_from_case(case)
        if vehicle:  # every frozen time's tanks, before the estimate builds any
            check_fills(case)
        est, extra = _feasibility(case, model, beam_action=beam_action, stability=stability,
                                  figures=figures, with_regions=vehicle,
                                  with_flight=frozen is None)
        if on_estimate is not None:
            on_estimate(est, case.max_seconds)
        n = model.truncation
        beam = beam_modes(n.N, model.mass.L, model.R1, model.E, model.rho)
        step(STAGES[1])
        pitch = pitch_analysis(model.Omega, model.omega_psi, model.gamma,
                               damping_ratio=model.pitch_damping_ratio)
        step(STAGES[2])
        shell = natural_frequencies(model)
        action = table = params = severity = None
        if beam_action:
            step(STAGES[3])
            action = _beam_action(model)
            extra += [AnalysisWarning("beam-action-not-fully-searched", gap.limit, gap.reason)
                      for gap in action.gaps]
        if stability and beam_action:
            step(STAGES[4])
            params = excitation_parameters(model, action)
            table, skipped = _stability_table(model, shell, params)
            extra += skipped
        if table is not None:  # how bad each root is; active = severity_rel >= threshold
            sv = case.severity
            table, severity = severity_analysis(
                model, table, params, psi0=sv.psi0, beam_amplitude=sv.beam_amplitude,
                threshold=sv.threshold, resolution=sv.resolution)
        data = None
        if figures:
            step(STAGES[5])
            data = _figure_data(model, pitch, shell, action, table, params)
        survey = None
        if case.vehicle is not None:  # only a case with [vehicle]
            step(VEHICLE_STAGE)
            survey = analyze_vehicle(case, views=figures)
            extra += vehicle_warnings(survey)
        regions = matches = None
        if vehicle:
            step(VEHICLE_REGIONS_STAGE)
            regions, skipped = _vehicle_regions_stage(case, boundaries=figures)
            extra += skipped
            if regions is not None and table is not None:
                matches = memo_roots_in_regions(table, regions)
        forced = None
        if vehicle:
            step(FORCED_STAGE)
            forced, skipped = _forced_stage(case)
            extra += skipped
        # [flight] only
        flight, skipped = flight_stage(case, frozen=frozen) if vehicle else (None, [])
        extra += skipped
    return Results(
        case=case,
        mass=model.mass,
        omega_1=model.omega_1,
        omega_psi=model.omega_psi,
        groups=model.groups,
        beam=beam,
        pitch=pitch,
        shell=shell,
        model=model,
        figures=data,
        beam_action=action,
        stability=table,
        warnings=tuple(deprecation_warnings(case) + _warnings(model, pitch.a, pitch.q)
                       + extra),
        vehicle=survey,
        vehicle_regions=regions,
        memo_roots_in_regions=matches,
        danger=_danger(model, pitch, action, regions, severity, case=case,
                       more=_bounded_and_flight(regions, forced, flight, model.omega_range)),
        severity=severity,
        forced_response=forced,
        flight=flight,
    )


def _check_lever_arm(case: Case, cm: float) -> None:
    """CaseError when a gimbal (K > 0) turns the thrust about a centre of mass at or aft of the
    aft edge: the lever arm d <= 0 makes omega_psi^2 = F0 d K / I_cm <= 0 (memo eq. 4.2-1), the
    rigid pitch diverges instead of oscillating."""
    from .errors import CaseError

    if case.thrust.K > 0.0 and not cm > 0.0:
        masses = case.vehicle is not None and case.vehicle.masses
        raise CaseError("vehicle.masses" if masses else "vehicle.segments",
                        f"centre of mass at {cm:.6g} m",
                        "lies at or aft of the aft edge: with a gimbal gain thrust.K > 0 the "
                        "rigid pitch diverges (omega_psi^2 = F0 d K / I_cm <= 0, memo eq. "
                        "4.2-1); move the masses forward or set K = 0")


def _analyze_segments(case: Case, step: Callable[[str], None], *, figures: bool,
                      regions: bool, on_estimate: Callable | None,
                      frozen: Sequence[FrozenTime] | None) -> Results:
    """:func:`analyze` of a ``[[vehicle.segments]]`` case: the vehicle's mass properties, its
    rigid-body pitch (omega_psi = sqrt(F0 d K / I_cm), memo eq. 4.2-1, d the centre of mass
    from the aft edge, on the memo's Mathieu numerics), modes and regions; the memo's stages
    are not applicable (``Results.not_applicable``)."""
    with blas_threads(1), shared_harmonics():  # the vehicle and its harmonics built once
        step(STAGES[0])
        structure = vehicle_from_case(case)
        if regions:  # every frozen time's tanks, before the estimate builds any
            check_fills(case)
        mass = mass_properties(structure)
        t, Omega = case.thrust, case.omega_grid()
        _check_lever_arm(case, mass.cm_m)
        omega_psi = 0.0 if t.K == 0.0 else pitch_frequency(  # eq. (4.2-1)
            case.F0, mass.cm_m, t.K, mass.I_cm_kg_m2)
        cost.check_pitch_range(F0=case.F0, omega_psi=omega_psi, omega_min=float(Omega.min()),
                               gamma=t.gamma)
        vehicle_cost = cost.estimate_vehicle_cost(case, regions=regions, figures=figures,
                                                  forced=regions)
        pitch_cost = cost.estimate_pitch_cost(omega_psi=omega_psi, Omega=Omega, gamma=t.gamma,
                                              pitch_ratio=case.damping.pitch_ratio)
        if frozen is None:  # [flight], unless its frozen times are given
            vehicle_cost = cost.with_flight(case, vehicle_cost)
        est = cost.check_case_cost(None, case.max_seconds,
                                   vehicle=cost.combined(pitch_cost, vehicle_cost))
        if on_estimate is not None:
            on_estimate(est, case.max_seconds)
        step(STAGES[1])
        pitch = pitch_analysis(Omega, omega_psi, t.gamma, damping_ratio=case.damping.pitch_ratio)
        extra = _mathieu_warnings(Omega, omega_psi, pitch.a, pitch.q)
        step(VEHICLE_STAGE)
        survey = analyze_vehicle(case, views=figures)
        extra += vehicle_warnings(survey)
        found = None
        if regions:
            step(VEHICLE_REGIONS_STAGE)
            found, skipped = _vehicle_regions_stage(case, boundaries=figures)
            extra += skipped + slosh_warnings(survey, found)
        forced = None
        if regions:
            step(FORCED_STAGE)
            forced, skipped = _forced_stage(case)
            extra += skipped
        # [flight] only
        flight, skipped = flight_stage(case, frozen=frozen) if regions else (None, [])
        extra += skipped
    danger = danger_summary(
        operating_range=(t.omega_min, t.omega_max),
        bands={"pitch": pitch.bands, **({} if found is None else {"vehicle": found.regions})},
        gaps=list(pitch.gaps) + ([] if found is None else list(found.gaps)),
        gamma=t.gamma, duration=t.duration, modal_ratio=case.vehicle_damping_ratio,
        pitch_ratio=case.damping.pitch_ratio, certified=_certified(found),
        **_bounded_and_flight(found, forced, flight, (t.omega_min, t.omega_max)))
    memo = {"beam_action", "resonance"}  # the memo's mechanisms: not applicable, never stable
    verdicts = tuple((key, words, "not applicable: the memo's method models the two bare "
                      "cylinders of [booster] only" if key in memo else verdict)
                     for key, words, verdict in danger.verdicts)
    danger = dataclasses.replace(danger, verdicts=verdicts, verdict=dataclasses.replace(
        danger.verdict, mechanisms=tuple((k, v) for k, _, v in verdicts)))
    return Results(case=case, mass=None, omega_1=None, omega_psi=omega_psi, groups=None,
                   beam=None, pitch=pitch, shell=None, warnings=tuple(extra), vehicle=survey,
                   vehicle_regions=found, danger=danger, vehicle_mass=mass,
                   not_applicable=MEMO_NOT_APPLICABLE, forced_response=forced,
                   flight=flight)


def _bounded_and_flight(regions, forced, flight, operating_range) -> dict:
    """The overall verdict's inputs beyond the bands: the vehicle's bounded responses (its
    forced response's peaks and its k = 0 axial resonances, each resonance once) and the
    flight's events that count."""
    fa = None if regions is None else regions.forced_axial
    axial = () if fa is None else axial_resonance_peaks(
        fa.resonances, load=regions.gamma * regions.F0, operating_range=operating_range)
    peaks = () if forced is None else forced.response_peaks()
    zeta = forced.response.damping_ratio if forced is not None else (
        fa.damping_ratio if fa is not None else 0.0)
    return {"responses": merge_responses(peaks, axial, damping_ratio=zeta),
            "flight": None if flight is None else flight_verdict(
                flight.events, times=(float(flight.times[0]), float(flight.times[-1])),
                gaps=len(flight.gaps))}


def _danger(model: BoosterModel, pitch, action, regions, severity, *, case: Case,
            more: dict):
    """The ranked bands, the verdicts of every mechanism computed (with their gaps) and the
    overall verdict at the case's damping and duration, with ``more`` (the vehicle's
    responses and the flight, :func:`_bounded_and_flight`)."""
    found = {"pitch": pitch.bands}
    gaps = list(pitch.gaps)
    if action is not None:
        found["beam_action"] = action.bands
        gaps += action.gaps
    if regions is not None:
        found["vehicle"] = regions.regions
        gaps += regions.gaps
    if severity is not None:
        found["resonance"] = severity.bands
    return danger_summary(operating_range=model.omega_range, bands=found, gaps=gaps,
                          gamma=model.gamma, duration=case.thrust.duration,
                          # the least damped elastic modes (a deprecated key may set one)
                          modal_ratio=min(case.damping.beam_ratio, case.vehicle_damping_ratio),
                          pitch_ratio=case.damping.pitch_ratio,
                          certified=_certified(regions), **more)


def _certified(regions: VehicleRegions | None) -> dict[str, float]:
    """{"vehicle": the regions' certified margin} where there is one."""
    bound = None if regions is None else regions.certified_margin
    return {} if bound is None else {"vehicle": bound}


def _stability_table(model: BoosterModel, shell, params
                     ) -> tuple[StabilityTable | None, list[AnalysisWarning]]:
    """The unstable thrust frequencies (memo 7.3), or None and a warning where the table is
    past its memory limit (the rest of the analysis stands)."""
    n = model.truncation
    modes = ShellModes(shell.cylinder, shell.j, shell.k, shell.branch, shell.omega_bar)
    lo, hi = model.omega_range
    try:
        return unstable_frequencies(
            modes, params, Omega_bar_range=(lo / model.omega_1, hi / model.omega_1),
            omega_1=model.omega_1, R=n.R, S=n.S, gamma=model.gamma, K=model.K), []
    except TooManyRootsError as exc:
        return None, [AnalysisWarning("stability-skipped", "truncation", str(exc))]


def _feasibility(case: Case, model: BoosterModel, *, with_regions: bool = True,
                 with_flight: bool = True,
                 **stages: bool) -> tuple[cost.CostEstimate, list[AnalysisWarning]]:
    """Refuse a case past its budget or past what the structure carries, before any solver
    runs; the estimate, and the warnings of the budget and of the load."""
    cost.check_physical(model)
    # the vehicle stages too: modes survey, regions (lower bound with damping)
    veh = dict(regions=with_regions, forced=with_regions, figures=stages.get("figures", True))
    vehicle = cost.estimate_vehicle_cost(case, **veh)
    if with_flight:  # [flight], unless its frozen times are given
        vehicle = cost.with_flight(case, vehicle)
    est = cost.check_case_cost(model, case.max_seconds, vehicle=vehicle, **stages)
    out = cost.physical_warnings(model) + cost.capped_steps_warning(est, model)
    if est.seconds > 0.5 * case.max_seconds:
        out.append(AnalysisWarning("cost-estimate", "max_seconds",
                                   f"estimated run time {est.seconds:.3g} s is over half the "
                                   f"budget max_seconds = {case.max_seconds:g} s: "
                                   f"{est.describe()}"))
    return est, out


def _figure_data(model, pitch, shell, action, table, params) -> charts.FigureData:
    """The data of every figure (compute -> data -> plot), on the grids of :mod:`charts`."""
    n = model.truncation
    return charts.FigureData(
        ince_strutt=charts.ince_strutt_data(pitch),
        beam_modes=charts.beam_mode_shapes(model.mass, N=min(charts.MODE_SHAPE_COUNT, n.N)),
        nodal_patterns=tuple(  # the modes of memo Fig. 4, within the truncation
            charts.nodal_pattern_data(shell, cylinder=d, j=j, k=k, radius=R, half_length=L)
            for d, j, k, R, L in ((1, min(4, n.M1), min(3, n.N1), model.R1, model.L1),
                                  (2, min(6, n.M2), min(2, n.N2), model.R2, model.L2))),
        beam_action_chart=None if action is None else charts.beam_action_chart(model),
        campbell=None if table is None else charts.campbell_data(
            params=params, omega_range=model.omega_range, omega_1=model.omega_1, shell=shell,
            table=table, R=n.R, S=n.S),
        pitch_band_chart=charts.pitch_band_chart(model),
    )


def simulate_case(case: Case, Omega: float, *, tau_max: float, n_out: int = 401,
                  psi0: float = 0.01) -> SimulationResult:
    """Modal time responses of a case at one thrust frequency, with the parameter function of the
    stability table (a simulation at a root is exactly resonant).

    Parameters
    ----------
    case : Case
        The validated case.
    Omega : float
        Thrust frequency (rad/s), > 0.
    tau_max : float
        Last time tau = omega_1 t, > 0.
    n_out : int
        Output times, 2..100000.
    psi0 : float
        Initial pitch angle (rad).
    """
    # the cheap argument checks of simulate first, before the beam-action analysis
    _check_case(case)
    Omega, tau_max, psi0 = (positive("Omega", Omega), positive("tau_max", tau_max),
                            finite("psi0", psi0))
    n_out = count("n_out", n_out, 2, 100_000)
    with blas_threads(1):
        model = model_from_case(case)
        cost.check_physical(model)  # a load beyond the structure: a CaseError
        params = excitation_parameters(model, _beam_action(model))
        return simulate(model, Omega, tau_max, n_out=n_out, psi0=psi0, params=params)


def _beam_action(model: BoosterModel):
    """:func:`beam_action_analysis` with its refusals as one-line CaseErrors (a period-map overflow
    is the load's; a search past the toolkit's limits the truncation's).
    """
    from .errors import CaseError

    try:
        return beam_action_analysis(model)
    except PeriodMapOverflowError as exc:
        raise CaseError("thrust.F0", model.F0,
                        f"the beam action grows beyond the floating-point range ({exc}): far "
                        "past what the booster carries at this gamma; lower thrust.F0 or "
                        "thrust.gamma, or raise thrust.omega_min") from exc
    except (floquet.TooManyCandidatesError, floquet.StepLimitError) as exc:
        raise CaseError("truncation.N", model.truncation.N,
                        f"the beam-action band search is past a limit of the Floquet toolkit "
                        f"({exc}): reduce truncation.N") from exc


def analyze_vehicle(case: Case, *, k_max: int | None = None, f_max: float | None = None,
                    prestress: bool = True, views: bool = True) -> VehicleSurvey:
    """The vehicle modes of a case (``flexbooster modes``), unloaded for a case without
    ``[thrust]``; CaseError on ``thrust.F0`` when the prestress exceeds a buckling load
    (docs/theory/vehicle-case.md).

    Parameters
    ----------
    case : Case
        The validated case; its ``[vehicle]`` table or the memo vehicle.
    k_max : int, optional
        Highest circumferential wave number, 0..200; default ``vehicle.k_max``.
    f_max : float, optional
        Keep the modes up to this frequency (Hz), > 0; default the band up to 5 times the
        lowest elastic frequency.
    prestress : bool
        Prestress by the case's steady thrust F0.
    views : bool
        Compute the figure data of the mode shapes.
    """
    from .errors import CaseError

    _check_case(case)
    table = case.vehicle
    k_max = (table.k_max if table is not None else 20) if k_max is None else k_max
    source = "vehicle" if table is not None and table.segments is not None else "memo"
    with blas_threads(1):
        vehicle = vehicle_from_case(case)
        try:
            F0 = None if case.thrust is None else case.F0  # no [thrust]: unloaded
            return vehicle_survey(vehicle, k_max=k_max, F0=F0, f_max=f_max,
                                  prestress=prestress, views=views, source=source)
        except BucklingError as exc:
            raise CaseError("thrust.F0", case.F0, "the thrust prestress exceeds a "
                            f"buckling load of the vehicle ({exc}); use --no-prestress "
                            "for the unloaded modes") from None


def vehicle_warnings(survey: VehicleSurvey) -> list[AnalysisWarning]:
    """The warnings of the vehicle modes: ``thick-shell`` per segment with h/R > 1/20, and
    ``vehicle-prestress`` when a flat plate forced the unloaded modes.

    Parameters
    ----------
    survey : VehicleSurvey
        From :func:`analyze_vehicle`.
    """
    out = []
    for w in survey.modes.warnings:
        field = (f"vehicle.segments[{w.segment}]" if survey.source == "vehicle"
                 else f"booster.cylinder{w.segment + 1}")
        out.append(AnalysisWarning(w.code, field, w.message))
    if "flat plate" in survey.note:
        out.append(AnalysisWarning("vehicle-prestress", "vehicle.segments", survey.note))
    return out


def slosh_warnings(survey: VehicleSurvey | None,
                   found: VehicleRegions | None) -> list[AnalysisWarning]:
    """One ``liquid-below-slosh`` warning when a parametric region has a mode below
    :data:`flexbooster.dynamics.SLOSH_VALIDITY_FACTOR` times the highest first slosh frequency
    of the partly filled tanks (``survey.slosh``, under the thrust's acceleration): there the
    liquid's added mass, the high-frequency limit of a free surface at p = 0
    (docs/theory/liquid.md), leaves out slosh masses that move with the tank, and that mode's
    frequency, so the region's place, is approximate. None without slosh modes or regions.

    Parameters
    ----------
    survey : VehicleSurvey or None
        From :func:`analyze_vehicle`.
    found : VehicleRegions or None
        From :func:`analyze_vehicle_regions`.
    """
    slosh = () if survey is None else survey.slosh
    low = () if found is None else below_slosh(found.regions, slosh)
    return [slosh_warning(f"{len(low)} parametric region(s) hold", low, slosh)] if low else []


def _vehicle_regions_stage(case: Case, *, boundaries: bool
                           ) -> tuple[VehicleRegions | None, list[AnalysisWarning]]:
    """The regions of :func:`analyze_vehicle_regions`, or None and a warning where they cannot be
    computed; the harmonics left out are ``vehicle-regions-skipped`` warnings.
    """
    from .errors import CaseError
    from .vehicle_case import VehicleTable

    table = case.vehicle
    k_max = (table if table is not None else VehicleTable()).k_max
    if k_max < VEHICLE_REGIONS_K_MIN:
        return None, [AnalysisWarning(
            "vehicle-regions-skipped", "vehicle.k_max",
            f"vehicle.k_max = {k_max} < {VEHICLE_REGIONS_K_MIN}: the parametric regions are "
            f"computed for k >= {VEHICLE_REGIONS_K_MIN} only (k = 0 gives forced, not "
            "parametric, resonances)")]
    try:
        found = analyze_vehicle_regions(case, boundaries=boundaries)
        used, dofs = cost.region_modes(case, k_max=k_max)
        clipped = [] if table is None or used == table.n_modes else [AnalysisWarning(
            "vehicle-modes-clipped", "vehicle.n_modes",
            f"vehicle.n_modes = {table.n_modes}: more than the {dofs} modes the vehicle's "
            f"mesh has in a harmonic: {used} modes per harmonic (all of them) are used")]
        return found, clipped + _gap_warnings(found.gaps + found.chart_gaps)
    except CaseError as exc:  # the thrust buckles the vehicle: a result, not a bad input
        return None, [AnalysisWarning("vehicle-regions-skipped", exc.field, exc.rule)]


def _gap_warnings(gaps) -> list[AnalysisWarning]:
    """One ``vehicle-regions-skipped`` warning per limit naming every harmonic left out (k = 2-9,
    12) and the first one's reason (each reason stays in ``VehicleRegions.gaps``).
    """
    groups: dict[str, list] = {}
    for g in gaps:
        groups.setdefault(g.limit, []).append(g)
    out = []
    for group in groups.values():
        if len(group) == 1 or any(g.k is None for g in group):
            out += [AnalysisWarning("vehicle-regions-skipped", "thrust.omega_min", g.reason)
                    for g in group]
            continue
        ks = sorted({int(g.k) for g in group})
        out.append(AnalysisWarning("vehicle-regions-skipped", "thrust.omega_min", (
            f"{len(group)} harmonics left out (k = {_ranges(ks)}); the first, "
            f"{group[0].reason}; each one's reason is in vehicle_regions.gaps of "
            "results.json")))
    return out


def _ranges(ks: list[int]) -> str:
    """Sorted integers as ranges: [2, 3, 4, 7, 9, 10] -> "2-4, 7, 9-10"."""
    runs: list[list[int]] = []
    for k in ks:
        if runs and k == runs[-1][1] + 1:
            runs[-1][1] = k
        else:
            runs.append([k, k])
    return ", ".join(f"{a}" if a == b else f"{a}-{b}" for a, b in runs)


def analyze_vehicle_regions(case: Case, *, k_min: int = VEHICLE_REGIONS_K_MIN,
                            k_max: int | None = None, boundaries: bool = True
                            ) -> VehicleRegions:
    """The parametric instability regions of the case's vehicle at its thrust, gamma and Omega range
    (damping and modes per harmonic from ``[vehicle]`` or their defaults); CaseError on
    ``thrust.F0`` (buckling), ``vehicle.k_max`` (no harmonic) or ``vehicle.segments`` (a flat
    plate). Bolotin 1964; docs/theory/vehicle-regions.md.

    Parameters
    ----------
    case : Case
        The validated case (SI).
    k_min : int
        Lowest harmonic, >= 1 (k = 1: gimbal gain ``thrust.K``, rigid pitch, follower thrust).
    k_max : int, optional
        Highest harmonic; default ``vehicle.k_max``.
    boundaries : bool
        Also the boundary curves in (Omega, gamma) for the chart, up to the top gamma of
        :func:`_chart_gamma`.
    """
    from .errors import CaseError
    from .vehicle_case import VehicleTable

    _check_case(case)
    table = case.vehicle if case.vehicle is not None else VehicleTable()
    k_max = table.k_max if k_max is None else k_max
    if k_max < k_min:
        raise CaseError("vehicle.k_max", table.k_max,
                        f"the parametric regions need k_max >= {k_min}")
    t = case.thrust
    vehicle = vehicle_from_case(case)
    if has_flat_plate(vehicle):  # the modes survey goes on unloaded; the regions cannot
        raise CaseError("vehicle.segments", "a cone of length 0",
                        "a flat annular plate cannot carry the thrust as a membrane, so the "
                        "prestress the parametric regions need is not defined: no regions "
                        "(give the plate an axial length: a cone)")
    # at most the DOFs of a harmonic's mesh (a vehicle.n_modes up to 500 is valid input)
    n_modes = cost.region_modes(case, vehicle, k_max=k_max)[0]
    settings = dict(F0=case.F0, omega_min=t.omega_min, omega_max=t.omega_max, k_min=k_min,
                    k_max=k_max, n_modes=n_modes, damping_ratio=case.vehicle_damping_ratio,
                    gimbal_gain=t.K)
    with blas_threads(1):
        try:
            found = vehicle_regions(vehicle, gamma=t.gamma, **settings)
            # the damping that would close each region that counts (docs/theory/verdicts.md)
            found = region_critical_damping(found, growth_floor=NEGLIGIBLE_GROWTH)
            top = _chart_gamma(found)
            if boundaries and top > 0.0:
                # the harmonics that can have a region at the chart's top (above the case's
                # gamma every harmonic is certified: none), in the budget the map left
                curves, gaps = region_curves(
                    found, gamma_max=top, n_gamma=charts.VEHICLE_CHART_LEVELS)
                found = dataclasses.replace(found, curves=curves, chart_gaps=gaps)
            found = dataclasses.replace(found, chart_gamma_max=top if boundaries else None)
        except BucklingError as exc:
            raise CaseError("thrust.F0", case.F0, "the steady thrust buckles the vehicle "
                            f"({exc}): no parametric regions") from None
    return found


def _chart_gamma(found: VehicleRegions) -> float:
    """Top gamma of the vehicle's chart: the case's gamma, raised towards VEHICLE_CHART_GAMMA_MAX
    only as far as the stability certificate proves every harmonic free of regions.
    """
    certified = 0.0
    if found.damping_ratio > 0.0 and found.harmonics:
        # the certificate of gamma B1 has rho = gamma rho_1 (Q is linear in B): it certifies
        # gamma' < gamma / rho = gamma * amplitude_factor; reused from the search, recomputed
        # per unit gamma only where there is none (gamma = 0)
        reuse = found.gamma > 0.0 and len(found.certificates) == len(found.harmonics)
        certified = min(
            found.gamma * c.amplitude_factor if reuse
            else floquet.stability_certificate(h.mass, h.damping, h.stiffness,
                                               h.excitation).amplitude_factor
            for h, c in zip(found.harmonics, found.certificates if reuse
                            else (None,) * len(found.harmonics), strict=True))
    return float(max(found.gamma, min(charts.VEHICLE_CHART_GAMMA_MAX, 0.999 * certified)))


def memo_roots_in_regions(table: StabilityTable, regions: VehicleRegions, *,
                          rtol: float = 0.0) -> MemoRootsInRegions:
    """The memo-table roots inside each vehicle region, and the regions with none.

    A root falls inside when Omega_lo - rtol Omega_c <= Omega <= Omega_hi + rtol Omega_c, found by
    bisection on the sorted roots; each match says whether the root's shell mode has the
    region's k (docs/theory/memo-vs-vehicle.md).

    Parameters
    ----------
    table : StabilityTable
        The memo's unstable thrust frequencies (Omega in rad/s).
    regions : VehicleRegions
        The vehicle's parametric regions (Omega in rad/s).
    rtol : float
        Widening of each region relative to its centre, >= 0.
    """
    from .checks import nonnegative

    if not isinstance(table, StabilityTable):
        raise ValueError(f"table = {type(table).__name__}: must be a StabilityTable")
    if not isinstance(regions, VehicleRegions):
        raise ValueError(f"regions = {type(regions).__name__}: must be a VehicleRegions")
    rtol = nonnegative("rtol", rtol)
    regs = regions.regions
    lo = np.array([r.Omega_lo for r in regs], dtype=float)
    hi = np.array([r.Omega_hi for r in regs], dtype=float)
    pad = rtol * np.array([r.Omega_center for r in regs], dtype=float)
    region_k = np.array([r.k for r in regs], dtype=int)
    Omega = np.asarray(table.Omega, dtype=float)
    by_omega = np.argsort(Omega, kind="stable")  # the roots inside a region are a run of it
    first = np.searchsorted(Omega[by_omega], lo - pad, side="left")
    stop = np.searchsorted(Omega[by_omega], hi + pad, side="right")
    n_in = np.maximum(stop - first, 0)
    region = np.repeat(np.arange(len(regs)), n_in)  # pairs by region, then Omega
    offset = np.arange(int(n_in.sum())) - np.repeat(np.cumsum(n_in) - n_in, n_in)
    root = by_omega[np.repeat(first, n_in) + offset]
    active = np.asarray(table.active, dtype=bool)
    n_active = np.concatenate(([0], np.cumsum(active[by_omega])))
    has_active = n_active[first + n_in] - n_active[first] > 0
    k = np.asarray(table.k, dtype=int)
    severity = getattr(table, "severity", None)  # the severity column, where the table has it
    return MemoRootsInRegions(
        region=region.astype(int), root=root.astype(int), Omega=Omega[root],
        family=np.asarray(table.family, dtype=int)[root],
        cylinder=np.asarray(table.cylinder, dtype=int)[root],
        j=np.asarray(table.j, dtype=int)[root], k=k[root],
        branch=np.asarray(table.branch, dtype=int)[root], active=active[root],
        same_k=k[root] == region_k[region],
        severity=None if severity is None else tuple(np.asarray(severity)[root].tolist()),
        without_root=np.flatnonzero(n_in == 0).astype(int),
        without_active_root=np.flatnonzero(~has_active).astype(int),
        n_regions=len(regs), rtol=rtol)


def modal_damping_ratio(case: Case) -> float:
    """The modal damping ratio zeta of the vehicle's elastic modes in the forced response:
    ``damping.modal_ratio`` (or the deprecated ``vehicle.damping_ratio`` where given).

    Parameters
    ----------
    case : Case
        The validated case.
    """
    return case.vehicle_damping_ratio


def forced_settings(case: Case) -> dict:
    """The keyword arguments of :func:`flexbooster.dynamics.forced_response` for a case, but the
    vehicle and its stations: F0; gamma over the case's Omega grid or the ``[[thrust.spectrum]]``
    lines; the modal damping (:func:`modal_damping_ratio`), ``damping.pitch_ratio``,
    ``thrust.misalignment`` and the gimbal gain ``thrust.K``; k = 0 and 1.

    Parameters
    ----------
    case : Case
        The validated case (SI).
    """
    t = case.thrust
    if t.spectrum is not None:
        load = dict(amplitude=ThrustSpectrum(
            frequency=np.array([line.frequency for line in t.spectrum]),
            amplitude=np.array([line.amplitude for line in t.spectrum])), Omega=None)
    else:
        load = dict(amplitude=t.gamma, Omega=case.omega_grid())
    return dict(F0=case.F0, damping_ratio=modal_damping_ratio(case),
                misalignment=t.misalignment, gimbal_gain=t.K,
                pitch_damping_ratio=case.damping.pitch_ratio, harmonics=(0, 1), **load)


def _convergence(vehicle, settings: dict, stations, found) -> tuple:
    """Per harmonic: (elastic modes of half the basis, the largest change of a station peak with
    that basis relative to the largest peak of its quantity), None where it is not forced."""
    out = []
    for model in found.models:
        k = model.k
        n = model.omega_modes.size - model.n_rigid
        share = np.cos(settings["misalignment"]) if k == 0 else np.sin(settings["misalignment"])
        if share == 0.0 or not np.any(found.amplitude):
            out.append(None)
            continue
        half = max(1, n // 2)
        small = forced_response(vehicle, **dict(settings, harmonics=(k,), n_modes=half),
                                stations=stations)
        change = 0.0
        for q in {p.quantity for p in small.peaks}:
            a = np.array([found.peak(k, s.name, q).value for s in found.stations])
            b = np.array([small.peak(k, s.name, q).value for s in found.stations])
            if a.max() > 0.0:
                change = max(change, float(np.max(np.abs(a - b)) / a.max()))
        out.append((half, change))
    return tuple(out)


def analyze_forced_response(case: Case) -> ForcedLoads:
    """The forced response of the case's vehicle to the thrust oscillation (k = 0 and 1) at its
    stations (the edges, junctions, lumped masses and ``[[output.stations]]``), all the modes
    below 4 Omega_max (at least 4) with the static correction of the others, and its convergence
    against half the basis; CaseError on ``thrust.F0`` (the thrust buckles the vehicle),
    ``damping.modal_ratio`` or ``damping.pitch_ratio`` (an undamped resonance in the range)
    or ``vehicle.segments`` (a flat plate). Theory: docs/theory/forced-response.md.

    Parameters
    ----------
    case : Case
        The validated case (SI).
    """
    from .errors import CaseError

    vehicle = vehicle_from_case(case)
    if has_flat_plate(vehicle):
        raise CaseError("vehicle.segments", "a cone of length 0",
                        "a flat annular plate cannot carry the thrust as a membrane: no "
                        "forced response (give the plate an axial length: a cone)")
    settings = forced_settings(case)
    stations, masses = forced_stations(case, vehicle)
    with blas_threads(1):
        try:
            found = forced_response(vehicle, stations=stations, **settings)
            convergence = _convergence(vehicle, settings, stations, found)
        except BucklingError as exc:
            raise CaseError("thrust.F0", case.F0, "the steady thrust buckles the vehicle "
                            f"({exc}): no forced response") from None
        except IllConditionedError as exc:
            field, value = (("booster", "the two cylinders") if case.vehicle is None
                            or case.vehicle.segments is None else
                            ("vehicle.segments", f"{len(case.vehicle.segments)} segments"))
            raise CaseError(field, value, f"{exc}: the geometry and material are too extreme "
                            "for the forced response (its residual modes); none "
                            "computed") from None
        except UndampedResonanceError as exc:
            deprecated = case.vehicle is not None and case.vehicle.damping_ratio is not None
            field = ("damping.pitch_ratio" if exc.parameter == "pitch_damping_ratio"
                     else "vehicle.damping_ratio" if deprecated else "damping.modal_ratio")
            value = (case.damping.pitch_ratio if exc.parameter == "pitch_damping_ratio"
                     else modal_damping_ratio(case))
            raise CaseError(field, value, f"the k = {exc.k} mode at {exc.omega:.6g} rad/s "
                            f"({exc.omega / (2.0 * np.pi):.6g} Hz) is not damped and resonates "
                            "in the thrust's range: no bounded forced response; give it "
                            "damping > 0") from None
    n_modes = tuple(m.omega_modes.size - m.n_rigid for m in found.models)
    t = case.thrust
    return ForcedLoads(response=found, n_modes=n_modes, convergence=convergence,
                       mass_stations=masses, operating_range=(t.omega_min, t.omega_max),
                       mode_peaks=mode_peaks(found, omega_min=t.omega_min,
                                             omega_max=t.omega_max))


def _forced_stage(case: Case) -> tuple[ForcedLoads | None, list[AnalysisWarning]]:
    """:func:`analyze_forced_response`, or None and a ``forced-response-skipped`` warning naming
    the field where it cannot be computed (the rest of the analysis stands)."""
    from .errors import CaseError

    try:
        loads = analyze_forced_response(case)
    except CaseError as exc:
        return None, [AnalysisWarning("forced-response-skipped", exc.field,
                                      f"{exc.field} = {exc.value!r}: {exc.rule}")]
    aft = vehicle_from_case(case).aft_end
    if case.thrust.misalignment != 0.0 and aft != "free":
        # a supported aft edge reacts the lateral thrust there: the k = 1 response is zero
        return loads, [AnalysisWarning(
            "misalignment-reacted", "thrust.misalignment",
            f"the aft end is {aft!r} (the memo's shell ends unless vehicle.aft_end says "
            "otherwise): it reacts the thrust's lateral component, so the lateral (k = 1) "
            "forced response is zero; set vehicle.aft_end = \"free\" for the vehicle in "
            "flight")]
    return loads, []
