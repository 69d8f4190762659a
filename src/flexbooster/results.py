"""Result types of an analysis: what :func:`flexbooster.analyze` returns and results.json holds.

The presentation layer (:mod:`flexbooster.present`) reads these objects only.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from . import __version__
from .danger import DangerSummary
from .dynamics import VehicleRegions
from .errors import AnalysisWarning
from .memo.beam import BeamModes
from .memo.beam_action import BeamActionResult
from .memo.charts import FigureData
from .memo.geometry import DimensionlessGroups, MassProperties
from .memo.model import BoosterModel
from .memo.pitch import PitchResult
from .memo.severity import SeverityResult
from .memo.shell import ShellFrequencies
from .memo.stability import StabilityTable
from .shell_of_revolution.survey import VehicleSurvey

if TYPE_CHECKING:
    from .case import Case

__all__ = ["Results", "MemoRootsInRegions", "SCHEMA_VERSION", "UNITS"]

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
}
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
    mass : MassProperties
        Geometry and mass properties (memo 2.2, Fig. 1-2).
    omega_1, omega_psi : float
        First free-free bending frequency (4.2-8b) and rigid pitch frequency (rad/s).
    groups : DimensionlessGroups
        mu, lambda_d, sigma, T0_bar (memo 3.0).
    beam : BeamModes
        lambda_n, alpha_n, omega_n of the first N free-free modes (appendix C).
    pitch : PitchResult
        The rigid-body pitch (4.2).
    shell : ShellFrequencies
        Shell natural frequencies of both cylinders (5.4, 6.2).
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
    severity : SeverityResult or None
        Severity of the roots and their bands (results.json ``stability.severity``).
    """

    case: Case
    mass: MassProperties
    omega_1: float
    omega_psi: float
    groups: DimensionlessGroups
    beam: BeamModes
    pitch: PitchResult
    shell: ShellFrequencies
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
            "mass_properties": self.mass.to_dict(),
            "frequencies": {
                "omega_1": self.omega_1,
                "omega_1_hz": self.omega_1 / (2.0 * np.pi),
                "omega_psi": self.omega_psi,
                "omega_psi_hz": self.omega_psi / (2.0 * np.pi),
            },
            "dimensionless": self.groups.to_dict(),
            "beam_modes": self.beam.to_dict(),
            "pitch": self.pitch.to_dict(),
            "shell_frequencies": self.shell.to_dict(),
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


