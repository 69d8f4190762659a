"""Result types of an analysis: what :func:`flexbooster.analyze` returns and results.json holds.

The presentation layer (:mod:`flexbooster.present`) reads these objects only.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from . import __version__
from .danger import DangerSummary, ResponsePeak
from .dynamics import ForcedResponse, VehicleRegions
from .dynamics.forced import STANDARD_GRAVITY
from .errors import AnalysisWarning
from .flight_results import FlightResults
from .memo.beam import BeamModes
from .memo.beam_action import BeamActionResult
from .memo.charts import FigureData
from .memo.geometry import DimensionlessGroups, MassProperties
from .memo.model import BoosterModel
from .memo.pitch import PitchResult
from .memo.severity import SeverityResult
from .memo.shell import ShellFrequencies
from .memo.stability import StabilityTable
from .shell_of_revolution.mass_properties import MassProperties as VehicleMassProperties
from .shell_of_revolution.survey import VehicleSurvey

if TYPE_CHECKING:
    from .case import Case

__all__ = ["Results", "MemoRootsInRegions", "ForcedLoads", "ForcedLoadPeak", "SCHEMA_VERSION",
           "UNITS", "MEMO_SECTIONS"]

#: Version of the layout of results.json; bumped when a key changes meaning or disappears.
SCHEMA_VERSION = "1.0"
#: Units of every number in results.json, by dotted key.
UNITS: dict[str, str] = {
    "case.booster.cylinder*.radius": "m",
    "case.booster.cylinder*.half_length": "m",
    "case.booster.thickness": "m",
    "case.booster.E": "Pa",
    "case.booster.nu": "1",
    "case.booster.rho": "kg/m^3",
    "case.thrust.F0": "N",
    "case.thrust.T0": "N/m",
    "case.thrust.gamma": "1",
    "case.thrust.K": "1",
    "case.thrust.omega_min": "rad/s",
    "case.thrust.omega_max": "rad/s",
    "mass_properties.L": "m",
    "mass_properties.x_cm": "m",
    "mass_properties.d1..d4": "m",
    "mass_properties.a, c, b": "1 (xi_bar = (x - x_cm)/L)",
    "mass_properties.m1, m2, mass": "kg",
    "mass_properties.I_cm": "kg m^2",
    "frequencies.omega_1": "rad/s",
    "frequencies.omega_1_hz": "Hz",
    "frequencies.omega_psi": "rad/s",
    "frequencies.omega_psi_hz": "Hz",
    "dimensionless.*": "1",
    "beam_modes.lambda_n, alpha_n": "1",
    "beam_modes.omega_n, omega_1": "rad/s",
    "pitch.Omega": "rad/s",
    "pitch.omega_psi": "rad/s",
    "pitch.a, q, beta_*": "1",
    "pitch.growth_rate, max_growth_rate": "1/s (amplitude e-folding rate of psi)",
    "pitch.unstable_intervals": "rad/s",
    "pitch.damping_ratio": "1",
    "shell_frequencies.omega_bar": "1 (units of omega_1)",
    "shell_frequencies.rad_s": "rad/s",
    "shell_frequencies.hz": "Hz",
    "beam_action.Omega": "rad/s",
    "beam_action.Omega_bar, alpha_*, frequencies_*": "1 (alpha_r Omega_bar in units of omega_1)",
    "beam_action.growth_rate, max_growth_rate": "1/s",
    "beam_action.unstable_intervals, band_range": "rad/s",
    "beam_action.*_damping_ratio": "1",
    "case.damping.*": "1",
    "stability.rows.Omega_rad_s, shell_rad_s": "rad/s",
    "stability.rows.Omega_hz, shell_hz": "Hz",
    "stability.rows.Omega_over_omega1, shell_omega_bar": "1 (units of omega_1)",
    "stability.table.severity": "m/s (growth rate of the mode's surface displacement)",
    "stability.table.severity_rel, stability.severity.threshold, resolution": "1",
    "stability.severity.psi0": "rad",
    "stability.severity.beam_amplitude": "1 (units of L)",
    "stability.severity.max_severity, bands.severity": "m/s",
        "figures.*.Omega_bar, curves, shell_omega_bar, root_*": "1 (units of omega_1)",
    "figures.beam_action_chart.regions.omega_lo, omega_hi, omega_min, omega_max": "rad/s",
    "figures.pitch_band_chart.regions.omega_lo, omega_hi, omega_min, omega_max": "rad/s",
    "figures.*_chart.regions.gamma, gamma_operating, gamma_max": "1",
    "figures.nodal_patterns.radius, half_length": "m",
    "figures.nodal_patterns.hz": "Hz",
    "figures.ince_strutt.*, beam_modes.*": "1",
    "vehicle_regions.F0": "N",
    "vehicle_regions.gamma, damping_ratio": "1",
    "vehicle_regions.omega_min, omega_max": "rad/s",
        "vehicle_regions.harmonics.omega_unloaded, omega_loaded": "rad/s",
    "vehicle_regions.curves.gamma": "1",
    "vehicle_regions.curves.omega_lo, omega_hi": "rad/s",
    "vehicle_regions.gimbal_gain": "1 (K of the k = 1 harmonic)",
    "vehicle_regions.memo_roots.Omega": "rad/s",
    "vehicle_regions.memo_roots.rtol": "1 (relative to each region's centre)",
    "danger.operating_range, danger.bands.Omega_lo, Omega_hi": "rad/s",
    "danger.bands.Omega_lo_hz, Omega_hi_hz": "Hz",
    "danger.bands.growth_rate": "1/s",
    "danger.bands.severity": "m/s (memo resonances)",
    "danger.bands.e_folding_s": "s",
    "danger.bands.growth_exponent, amplification, critical_gamma, margin": "1",
    "danger.bands.critical_damping_ratio": "1",
    "danger.bands.steady_amplitude": "m",
    "danger.bands.steady_acceleration": "m/s^2",
    "forced_response.F0, peaks.axial_force_N, peaks.shear_force_N": "N",
    "forced_response.amplitude, damping_ratio, pitch_damping_ratio, gimbal_gain": "1",
    "forced_response.misalignment": "rad",
    "forced_response.omega, peaks.Omega, envelopes.worst_Omega": "rad/s",
    "forced_response.omega_hz, peaks.Omega_hz, envelopes.worst_Omega_hz": "Hz",
    "forced_response.stations.station_m, peaks.station_m, envelopes.station_m": "m",
    "forced_response.peaks.displacement_m": "m",
    "forced_response.peaks.acceleration_g, acceleration_g_per_percent": "1 (units of g)",
    "forced_response.peaks.bending_moment_Nm": "N m",
    "forced_response.envelopes.peak, at_worst": "N (axial, shear force) or N m (moment)",
    "forced_response.convergence.max_change": "1 (relative to the largest peak)",
    "danger.responses.Omega, danger.ranking.Omega": "rad/s (a bounded response)",
    "danger.responses.acceleration_g, verdict.largest_response.acceleration_g": "1 (units of g)",
    "danger.responses.displacement_m, station_m, load_station_m": "m",
    "danger.responses.load": "N (axial force) or N m (bending moment), see load_unit",
    "verdict.flight.t_start_s, t_end_s": "s",
}
UNITS.update({
    "mass_properties.mass_kg, contributions.mass_kg": "kg ([vehicle] segments)",
    "mass_properties.cm_m, contributions.cm_m": "m from the aft edge ([vehicle] segments)",
    "mass_properties.I_cm_kg_m2, contributions.I_cm_kg_m2": "kg m^2 ([vehicle] segments)",
})
#: The results.json keys of the memo's method alone: for a case whose vehicle is
#: ``[[vehicle.segments]]`` each holds ``{"not_applicable": "<reason>"}`` (as do
#: ``frequencies.omega_1`` and ``frequencies.omega_1_hz``).
MEMO_SECTIONS = ("dimensionless", "beam_modes", "shell_frequencies", "beam_action", "stability",
                 "figures")
# The bands of every mechanism (flexbooster.bands.Band.to_dict), wherever they are stored.
for _where in ("pitch.bands", "beam_action.bands", "vehicle_regions.regions",
               "stability.severity.bands"):
    UNITS.update({
        f"{_where}.Omega_lo, Omega_hi, width, Omega_at_max, Omega_center, modes.omega": "rad/s",
        f"{_where}.Omega_lo_hz, Omega_hi_hz": "Hz",
        f"{_where}.growth_rate_max": "1/s (amplitude e-folding rate)",
        f"{_where}.critical_gamma, severity_rel, modes.share": "1",
        f"{_where}.severity": "m/s (memo resonances)",
    })
del _where


@dataclass(frozen=True)
class Results:
    """Everything one analysis produced (all SI).

    Attributes
    ----------
    case : Case
        The validated input.
    mass : MassProperties or None
        Geometry and mass properties (memo 2.2, Fig. 1-2); None where the memo's method does
        not apply (``not_applicable``).
    omega_1 : float or None
        First free-free bending frequency (4.2-8b, rad/s); None as ``mass``.
    omega_psi : float
        Rigid pitch frequency sqrt(F0 d K / I_cm) (4.2-1, rad/s), of the memo's cylinders or of
        ``vehicle_mass``.
    groups : DimensionlessGroups or None
        mu, lambda_d, sigma, T0_bar (memo 3.0); None as ``mass``.
    beam : BeamModes or None
        lambda_n, alpha_n, omega_n of the first N free-free modes (appendix C); None as ``mass``.
    pitch : PitchResult
        The rigid-body pitch (4.2).
    shell : ShellFrequencies or None
        Shell natural frequencies of both cylinders (5.4, 6.2); None as ``mass``.
    model : BoosterModel
        The derived model the stages were computed from.
    figures : FigureData
        The data every figure draws.
    beam_action, stability : BeamActionResult or None, StabilityTable or None
        Beam action (4.1) and unstable thrust frequencies (7.3); None if not computed.
    warnings : tuple of AnalysisWarning
        Conditions the user must know about.
    vehicle : VehicleSurvey or None
        The vehicle modes, only for a case with ``[vehicle]``.
    vehicle_regions : VehicleRegions or None
        The vehicle's parametric instability regions (with the chart's curves when the figures
        were computed); None when not asked for or not computable (see the warnings).
    memo_roots_in_regions : MemoRootsInRegions or None
        The memo-table roots inside each region.
    danger : DangerSummary or None
        One verdict per mechanism and the ranked bands (the first screen).
    flight : FlightResults or None
        The vehicle through the case's [flight] (:mod:`flexbooster.flight_stage`).
    severity : SeverityResult or None
        Severity of the roots and their bands (results.json ``stability.severity``).
    vehicle_mass : shell_of_revolution.MassProperties or None
        Mass properties of a ``[[vehicle.segments]]`` vehicle, each contribution listed
        (results.json ``mass_properties``); None for ``[booster]``.
    not_applicable : str or None
        Why the memo's method does not apply (a ``[[vehicle.segments]]`` vehicle): its results
        are None and its results.json keys (:data:`MEMO_SECTIONS`) hold
        ``{"not_applicable": reason}``; None for ``[booster]``.
    forced_response : ForcedLoads or None
        The vehicle's forced response to the thrust oscillation; None when not asked for or
        not computable (see the warnings).
    """

    case: Case
    mass: MassProperties | None
    omega_1: float | None
    omega_psi: float
    groups: DimensionlessGroups | None
    beam: BeamModes | None
    pitch: PitchResult
    shell: ShellFrequencies | None
    model: BoosterModel | None = None
    figures: FigureData | None = None
    beam_action: BeamActionResult | None = None
    stability: StabilityTable | None = None
    warnings: tuple[AnalysisWarning, ...] = field(default_factory=tuple)
    vehicle: VehicleSurvey | None = None
    vehicle_regions: VehicleRegions | None = None
    memo_roots_in_regions: MemoRootsInRegions | None = None
    danger: DangerSummary | None = None
    severity: SeverityResult | None = None
    vehicle_mass: VehicleMassProperties | None = None
    not_applicable: str | None = None
    forced_response: ForcedLoads | None = None
    flight: FlightResults | None = None  # only for a case with [flight]

    @property
    def Omega(self) -> np.ndarray:
        """The thrust pulsation frequencies analysed (rad/s)."""
        return self.pitch.Omega

    @property
    def a(self) -> np.ndarray:
        """Mathieu parameter a along ``Omega`` (eq. 4.2-4)."""
        return self.pitch.a

    @property
    def q(self) -> np.ndarray:
        """Mathieu parameter q along ``Omega`` (eq. 4.2-4)."""
        return self.pitch.q

    def to_dict(self) -> dict[str, Any]:
        """What results.json holds: schema version, units, inputs and every result."""
        out = {
            "schema_version": SCHEMA_VERSION,
            "flexbooster_version": __version__,
            "units": dict(UNITS),
            "case": self.case.to_si_dict(),
            "mass_properties": None if self.mass is None else self.mass.to_dict(),
            "frequencies": {
                "omega_1": self.omega_1,
                "omega_1_hz": None if self.omega_1 is None else self.omega_1 / (2.0 * np.pi),
                "omega_psi": self.omega_psi,
                "omega_psi_hz": self.omega_psi / (2.0 * np.pi),
            },
            "dimensionless": None if self.groups is None else self.groups.to_dict(),
            "beam_modes": None if self.beam is None else self.beam.to_dict(),
            "pitch": self.pitch.to_dict(),
            "shell_frequencies": None if self.shell is None else self.shell.to_dict(),
            "beam_action": None if self.beam_action is None else self.beam_action.to_dict(),
            "stability": None if self.stability is None else self.stability.to_dict(),
            "warnings": [w.to_dict() for w in self.warnings],
            "figures": None if self.figures is None else self.figures.to_dict(),
        }
        out["danger"] = None if self.danger is None else self.danger.to_dict()
        out["verdict"] = None if self.danger is None or self.danger.verdict is None \
            else self.danger.verdict.to_dict()
        if out["stability"] is not None and self.severity is not None:
            out["stability"]["severity"] = self.severity.to_dict()
        if self.vehicle is not None:  # only for a case with [vehicle] (units inside)
            out["vehicle_modes"] = self.vehicle.to_dict()
        out["vehicle_regions"] = self._vehicle_regions_dict()
        out["forced_response"] = (None if self.forced_response is None
                                  else self.forced_response.to_dict())
        if self.flight is not None:  # only for a case with [flight]
            out["flight"] = self.flight.to_dict()
        return out if self.not_applicable is None else self._memo_not_applicable(out)

    def _memo_not_applicable(self, out: dict[str, Any]) -> dict[str, Any]:
        """results.json of a ``[[vehicle.segments]]`` case: the vehicle's mass properties; the
        memo's keys present, each ``{"not_applicable": reason}``."""
        na = {"not_applicable": f"not applicable: {self.not_applicable}"}
        out["mass_properties"] = self.vehicle_mass.to_dict()
        out["frequencies"].update(omega_1=dict(na), omega_1_hz=dict(na))
        out.update({key: dict(na) for key in MEMO_SECTIONS})
        return out

    def _vehicle_regions_dict(self) -> dict[str, Any] | None:
        """results.json ``vehicle_regions``: :meth:`VehicleRegions.to_dict` and ``memo_roots``."""
        if self.vehicle_regions is None:
            return None
        out = self.vehicle_regions.to_dict()
        m = self.memo_roots_in_regions
        out["memo_roots"] = None if m is None else m.to_dict()
        return out


@dataclass(frozen=True)
class MemoRootsInRegions:
    """The memo-table roots (memo 7.3) inside the vehicle's parametric regions, one row per
    (region, root) pair, sorted by region then Omega (:func:`flexbooster.analysis.
    memo_roots_in_regions`; docs/theory/memo-vs-vehicle.md).

    Attributes
    ----------
    region, root : numpy.ndarray of int
        Index of the region in ``VehicleRegions.regions`` and row of the root in the table.
    Omega : numpy.ndarray
        Thrust frequency of the root (rad/s).
    family, cylinder, j, k, branch : numpy.ndarray of int
        The root's family (memo 7.4) and shell mode.
    active, same_k : numpy.ndarray of bool
        The root has active forcing; its shell k is the region's k.
    severity : tuple or None
        The root's ``severity`` where the table has that column.
    without_root, without_active_root : numpy.ndarray of int
        Regions with no root inside, and with no root of active forcing inside.
    n_regions : int
        Number of regions compared.
    rtol : float
        Widening of each region relative to its centre.
    """

    region: np.ndarray
    root: np.ndarray
    Omega: np.ndarray
    family: np.ndarray
    cylinder: np.ndarray
    j: np.ndarray
    k: np.ndarray
    branch: np.ndarray
    active: np.ndarray
    same_k: np.ndarray
    severity: tuple | None
    without_root: np.ndarray
    without_active_root: np.ndarray
    n_regions: int
    rtol: float

    def __len__(self) -> int:
        return int(self.root.size)

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready mapping (one list per column)."""
        return {
            "count": len(self), "n_regions": int(self.n_regions), "rtol": float(self.rtol),
            "region": self.region.tolist(), "root": self.root.tolist(),
            "Omega": self.Omega.tolist(), "family": self.family.tolist(),
            "cylinder": self.cylinder.tolist(), "j": self.j.tolist(), "k": self.k.tolist(),
            "branch": self.branch.tolist(), "active": self.active.tolist(),
            "same_k": self.same_k.tolist(),
            "severity": None if self.severity is None else list(self.severity),
            "without_root": self.without_root.tolist(),
            "without_active_root": self.without_active_root.tolist(),
        }




#: Quantities of the forced response in the outputs: (name in ForcedResponse, column, divisor).
_FORCED_COLUMNS = (("displacement", "displacement_m", 1.0),
                   ("acceleration", "acceleration_g", STANDARD_GRAVITY),
                   ("axial_force", "axial_force_N", 1.0),
                   ("bending_moment", "bending_moment_Nm", 1.0),
                   ("shear_force", "shear_force_N", 1.0))


@dataclass(frozen=True)
class ForcedLoadPeak:
    """The forced peaks at one station and harmonic, in the form the overall verdict ranks.

    Attributes
    ----------
    k : int
        Harmonic (0 axial, 1 lateral).
    station, station_m : str, float
        Station name and its axial distance from the aft edge (m).
    Omega : float
        Omega of the acceleration peak (rad/s).
    acceleration_g : float
        Peak acceleration amplitude (units of g = 9.80665 m/s^2).
    axial_force_N, bending_moment_Nm : float
        Peak internal axial force (N; k = 0) and bending moment (N m; k = 1) at the station,
        0 where the harmonic has none.
    Omega_axial_force, Omega_bending_moment : float
        Omega of those peaks (rad/s).
    in_operating_range : bool
        Omega lies in [omega_min, omega_max] of the case (always, for a sweep).
    """

    k: int
    station: str
    station_m: float
    Omega: float
    acceleration_g: float
    axial_force_N: float
    bending_moment_Nm: float
    Omega_axial_force: float
    Omega_bending_moment: float
    in_operating_range: bool

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready mapping (Omega also in Hz)."""
        return {"k": self.k, "station": self.station, "station_m": float(self.station_m),
                "Omega": float(self.Omega), "Omega_hz": float(self.Omega / (2.0 * np.pi)),
                "acceleration_g": float(self.acceleration_g),
                "axial_force_N": float(self.axial_force_N),
                "bending_moment_Nm": float(self.bending_moment_Nm),
                "Omega_axial_force": float(self.Omega_axial_force),
                "Omega_bending_moment": float(self.Omega_bending_moment),
                "in_operating_range": bool(self.in_operating_range)}


@dataclass(frozen=True)
class ForcedLoads:
    """The forced response stage: the response, its basis and its convergence.

    Attributes
    ----------
    response : ForcedResponse
        :func:`flexbooster.dynamics.forced_response` of the case's vehicle.
    n_modes : tuple of int
        Elastic basis modes of each harmonic (``response.harmonics``), with the static
        correction of the truncated ones.
    convergence : tuple of (int, float) or None
        Per harmonic: the elastic modes of a half basis and the largest change of a station
        peak with it, relative to the largest peak of that quantity (None: harmonic not forced).
    mass_stations : tuple of str
        The stations that are lumped masses.
    operating_range : tuple of float
        (omega_min, omega_max) of the case (rad/s).
    mode_peaks : tuple of ModePeak
        The peak near each forced mode in the operating range
        (:func:`flexbooster.dynamics.mode_peaks`).
    """

    response: ForcedResponse
    n_modes: tuple
    convergence: tuple
    mass_stations: tuple = ()
    operating_range: tuple = (0.0, np.inf)
    mode_peaks: tuple = ()

    @property
    def per_percent(self) -> float | None:
        """Factor from the case's loads to those per 1 % of F0 of thrust oscillation (a sweep
        with gamma > 0; None for a spectrum or gamma = 0): the response is linear in gamma."""
        r = self.response
        if r.combination != "sweep" or not r.amplitude.size or r.amplitude[0] <= 0.0:
            return None
        factor = 0.01 / float(r.amplitude[0])
        # a gamma so small (subnormal) that 1 % of F0 over it overflows: the loads are round-off
        return factor if np.isfinite(factor) else None

    def peak_value(self, k: int, station: str, quantity: str) -> tuple[float, float]:
        """(peak, Omega in rad/s) of a quantity at a station; (0, nan) where k is not computed."""
        if k not in self.response.harmonics:
            return 0.0, float("nan")
        p = self.response.peak(k, station, quantity)
        return p.value, p.omega

    def ranked_peaks(self) -> tuple[ForcedLoadPeak, ...]:
        """One :class:`ForcedLoadPeak` per forced harmonic and station, by decreasing peak
        acceleration."""
        r, (lo, hi) = self.response, self.operating_range
        out = []
        for ik, k in enumerate(r.harmonics):
            if self.convergence[ik] is None:  # not forced
                continue
            for s in r.stations:
                acc, w = self.peak_value(k, s.name, "acceleration")
                ax, wa = self.peak_value(k, s.name, "axial_force") if k == 0 else (0.0, w)
                bm, wb = self.peak_value(k, s.name, "bending_moment") if k == 1 else (0.0, w)
                out.append(ForcedLoadPeak(
                    k=k, station=s.name, station_m=s.x, Omega=w,
                    acceleration_g=acc / STANDARD_GRAVITY, axial_force_N=ax,
                    bending_moment_Nm=bm, Omega_axial_force=wa, Omega_bending_moment=wb,
                    in_operating_range=bool(lo <= w <= hi)))
        return tuple(sorted(out, key=lambda p: -p.acceleration_g))

    def response_peaks(self) -> tuple[ResponsePeak, ...]:
        """The forced response in the overall verdict's ranking: per forced harmonic, one
        :class:`~flexbooster.danger.ResponsePeak` per resonance (the stations whose peak
        accelerations lie within zeta Omega of each other are one resonance, shown at the
        largest; one at an end of the Omega range, still rising there, marked ``at_range_end``),
        then each resonance of :attr:`mode_peaks` that is no station's largest (at its own
        peak, displacement |a| / Omega^2), with the largest internal load along the vehicle
        (axial force for k = 0, bending moment for k = 1) whose peak lies within zeta Omega of
        it; the largest acceleration first."""
        r = self.response
        tol = max(float(r.damping_ratio), 1e-3)
        ends = (float(r.omega.min()), float(r.omega.max())) if r.omega.size else ()
        taken: list[tuple[int, float]] = []
        out = []
        for p in self.ranked_peaks():  # the largest acceleration first
            if any(k == p.k and abs(w - p.Omega) <= tol * p.Omega for k, w in taken):
                continue
            taken.append((p.k, p.Omega))
            disp, _ = self.peak_value(p.k, p.station, "displacement")
            out.append(ResponsePeak(
                source="forced response", k=int(p.k), Omega=float(p.Omega),
                acceleration_g=float(p.acceleration_g), station=p.station,
                station_m=float(p.station_m), displacement_m=float(disp), modes=f"k = {p.k}",
                in_operating_range=p.in_operating_range,
                at_range_end=any(abs(p.Omega - e) <= 1e-12 * e for e in ends),
                **self._load_near(p.k, p.Omega, tol)))
        # the resonances that are no station's largest peak, each at its own peak
        for m in self.mode_peaks:
            if any(k == m.k and abs(w - m.Omega) <= tol * m.Omega for k, w in taken):
                continue
            taken.append((m.k, m.Omega))
            s = r.stations[m.station]
            out.append(ResponsePeak(
                source="forced response", k=int(m.k), Omega=float(m.Omega),
                acceleration_g=float(m.acceleration / STANDARD_GRAVITY), station=s.name,
                station_m=float(s.x), displacement_m=float(m.acceleration / m.Omega**2),
                modes=f"k = {m.k}", in_operating_range=True,
                **self._load_near(m.k, m.Omega, tol)))
        return tuple(sorted(out, key=lambda q: -q.acceleration_g))

    def _load_near(self, k: int, Omega: float, tol: float) -> dict:
        """The largest internal load along the vehicle (axial force for k = 0, bending moment
        for k = 1) whose peak lies within tol Omega of ``Omega``, as ResponsePeak fields."""
        quantity = "axial_force" if k == 0 else "bending_moment"
        load = None
        for e in self.response.envelopes:
            if e.k != k or e.quantity != quantity or not e.peak.size:
                continue
            near = np.abs(e.peak_omega - Omega) <= tol * Omega
            if near.any():
                i = int(np.argmax(np.where(near, e.peak, -np.inf)))
                load = (quantity.replace("_", " "), e.unit, float(e.peak[i]), float(e.x[i]))
        return {"load_quantity": None if load is None else load[0],
                "load_unit": None if load is None else load[1],
                "load": None if load is None else load[2],
                "load_station_m": None if load is None else load[3]}

    def csv_columns(self) -> dict[str, list]:
        """forced-response.csv in long format: one row per harmonic, station and Omega;
        amplitudes |X| (the acceleration in g)."""
        r = self.response
        cols: dict[str, list] = {"Omega_hz": [], "station": [], "station_m": [], "k": []}
        cols.update({c: [] for _, c, _ in _FORCED_COLUMNS})
        hz = (r.omega / (2.0 * np.pi)).tolist()
        for ik, k in enumerate(r.harmonics):
            for js, s in enumerate(r.stations):
                cols["Omega_hz"] += hz
                cols["station"] += [s.name] * r.omega.size
                cols["station_m"] += [float(s.x)] * r.omega.size
                cols["k"] += [int(k)] * r.omega.size
                for q, c, f in _FORCED_COLUMNS:
                    cols[c] += (np.abs(getattr(r, q)[ik, js]) / f).tolist()
        return cols

    def to_dict(self) -> dict[str, Any]:
        """results.json ``forced_response``: settings, basis and convergence, stations, the peak
        of every quantity per harmonic and station with its Omega, the load envelopes along the
        vehicle at the worst Omega and the ranked peaks."""
        r = self.response
        scale = self.per_percent
        peaks = []
        for k in r.harmonics:
            for s in r.stations:
                row = {"k": int(k), "station": s.name, "station_m": float(s.x)}
                for q, c, f in _FORCED_COLUMNS:
                    try:
                        p = r.peak(k, s.name, q)
                    except KeyError:  # not a quantity of this harmonic
                        continue
                    row[c] = p.value / f
                    row[f"Omega_{q}"] = p.omega
                    row[f"Omega_{q}_hz"] = p.omega / (2.0 * np.pi)
                if scale is not None:  # None where the product is not a number (round-off)
                    value = row["acceleration_g"] * scale
                    row["acceleration_g_per_percent"] = value if np.isfinite(value) else None
                peaks.append(row)
        return {
            "combination": r.combination, "F0": float(r.F0),
            "omega": r.omega.tolist(), "omega_hz": (r.omega / (2.0 * np.pi)).tolist(),
            "amplitude": r.amplitude.tolist(), "damping_ratio": float(r.damping_ratio),
            "pitch_damping_ratio": float(r.pitch_damping_ratio),
            "misalignment": float(r.misalignment), "gimbal_gain": float(r.gimbal_gain),
            "harmonics": list(r.harmonics), "standard_gravity": STANDARD_GRAVITY,
            "basis": {"n_modes": [int(n) for n in self.n_modes], "static_correction": True},
            "convergence": [None if c is None else {"n_modes": int(c[0]),
                                                    "max_change": float(c[1])}
                            for c in self.convergence],
            "stations": [dict(s.to_dict(), kind="mass" if s.name in self.mass_stations
                              else s.kind) for s in r.stations],
            "peaks": peaks,
            "envelopes": [{"k": e.k, "quantity": e.quantity, "unit": e.unit,
                           "station_m": e.x.tolist(), "peak": e.peak.tolist(),
                           "worst_Omega": float(e.worst_omega),
                           "worst_Omega_hz": float(e.worst_omega / (2.0 * np.pi)),
                           "at_worst": np.abs(e.at_worst).tolist()} for e in r.envelopes],
            "ranked": [p.to_dict() for p in self.ranked_peaks()],
        }
