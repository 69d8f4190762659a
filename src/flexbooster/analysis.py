"""The analysis pipeline: a validated case in, a :class:`Results` out.

This is the layer that strings the numerical modules together in the memo's order
(reading guide section 1): geometry and mass properties, the equivalent beam (omega_1 and the
free-free modes), the rigid-body pitch (Mathieu a, q and the exponent beta along the Omega
grid), the shell natural frequencies, the beam action (exponents alpha_r) and the unstable
thrust frequencies (the 13 families of memo 7.3).  It also produces the warnings
under which the analysis goes on: thin-shell limit exceeded, Mathieu parameters outside the
memo's range (4.2-5).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from . import __version__
from .beam import BeamModes, beam_modes, first_bending_frequency
from .beam_action import BeamActionResult, beam_action_analysis
from .case import Case
from .errors import AnalysisWarning
from .geometry import DimensionlessGroups, MassProperties, dimensionless_groups, mass_properties
from .pitch import (
    PitchResult,
    characteristic_exponent,
    mathieu_parameters,
    pitch_analysis,
    pitch_frequency,
)
from .shell import ShellFrequencies, natural_frequencies
from .stability import ShellModes, StabilityTable, unstable_frequencies

__all__ = [
    "Results",
    "stability_parameters",
    "analyze",
    "SCHEMA_VERSION",
    "STAGES",
    "THIN_SHELL_LIMIT",
    "MATHIEU_A_RANGE",
    "MATHIEU_Q_MAX",
]

#: Version of the layout of results.json; bumped when a key changes meaning or disappears.
SCHEMA_VERSION = "1.0"
#: The stages of :func:`analyze`, in order, as passed to its ``progress`` callback.
STAGES = (
    "mass properties and beam modes",
    "rigid-body pitch",
    "shell frequencies",
    "beam action",
    "unstable thrust frequencies",
)
#: Thin-shell theory (Donnell, memo 2.3) is trusted for h/R up to 1/20.
THIN_SHELL_LIMIT = 1.0 / 20.0
#: The memo's range for the Mathieu parameters (eq. 4.2-5): 0 < a < 1, 0 < q <= 0.05.
MATHIEU_A_RANGE = (0.0, 1.0)
MATHIEU_Q_MAX = 0.05

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
    "shell_frequencies.omega_bar": "1 (units of omega_1)",
    "shell_frequencies.rad_s": "rad/s",
    "shell_frequencies.hz": "Hz",
    "beam_action.Omega": "rad/s",
    "beam_action.Omega_bar, alpha_*, frequencies_*": "1 (alpha_r Omega_bar in units of omega_1)",
    "beam_action.growth_rate, max_growth_rate": "1/s",
    "stability.rows.Omega_rad_s, shell_rad_s": "rad/s",
    "stability.rows.Omega_hz, shell_hz": "Hz",
    "stability.rows.Omega_over_omega1, shell_omega_bar": "1 (units of omega_1)",
}


@dataclass(frozen=True)
class Results:
    """Everything one analysis produced (all SI).

    Attributes
    ----------
    case : Case
        The validated input.
    mass : MassProperties
        Geometry and mass properties (memo 2.2, Fig. 1-2).
    omega_1 : float
        First free-free bending frequency of the equivalent beam, eq. (4.2-8b) (rad/s).
    omega_psi : float
        Rigid-body pitch frequency under the steady thrust, sqrt(F0 d2 K / I_cm) (rad/s).
    groups : DimensionlessGroups
        mu, lambda_d, sigma, T0_bar (memo 3.0).
    beam : BeamModes
        lambda_n, alpha_n, omega_n of the first N free-free modes (appendix C).
    pitch : PitchResult
        Mathieu a, q, the exponent beta (exact and memo) and the rigid-body verdict (4.2).
    shell : ShellFrequencies
        Shell natural frequencies of both cylinders (5.4, 6.2, appendix A).
    beam_action : BeamActionResult or None
        Beam-action exponents alpha_r and verdict (4.1); None if not computed.
    stability : StabilityTable or None
        Unstable thrust frequencies (7.3); None if not computed.
    warnings : tuple of AnalysisWarning
        Conditions the user must know about.
    """

    case: Case
    mass: MassProperties
    omega_1: float
    omega_psi: float
    groups: DimensionlessGroups
    beam: BeamModes
    pitch: PitchResult
    shell: ShellFrequencies
    beam_action: BeamActionResult | None = None
    stability: StabilityTable | None = None
    warnings: tuple[AnalysisWarning, ...] = field(default_factory=tuple)

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
        return {
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
        }


def _range_text(Omega: np.ndarray, mask: np.ndarray) -> str:
    lo, hi = Omega[mask].min(), Omega[mask].max()
    return f"{int(mask.sum())} of {mask.size} grid points, Omega in [{lo:.6g}, {hi:.6g}] rad/s"


def _warnings(
    case: Case, Omega: np.ndarray, a: np.ndarray, q: np.ndarray, omega_psi: float
) -> list[AnalysisWarning]:
    out = []
    b = case.booster
    for d, cyl in ((1, b.cylinder1), (2, b.cylinder2)):
        ratio = b.thickness / cyl.radius
        if ratio > THIN_SHELL_LIMIT:
            out.append(
                AnalysisWarning(
                    "thin-shell",
                    f"booster.cylinder{d}",
                    f"h/R{d} = {ratio:.4g} exceeds 1/20: thin-shell (Donnell) theory of memo 2.3 "
                    "is not reliable",
                )
            )
    bad_a = ~((a > MATHIEU_A_RANGE[0]) & (a < MATHIEU_A_RANGE[1]))
    if bad_a.any():
        out.append(
            AnalysisWarning(
                "mathieu-a-range",
                "thrust",
                f"Mathieu a outside the memo's range 0 < a < 1 (eq. 4.2-5) at "
                f"{_range_text(Omega, bad_a)}; a = 4 omega_psi^2/Omega^2 with "
                f"omega_psi = {omega_psi:.6g} rad/s",
            )
        )
    bad_q = ~((q > 0.0) & (q <= MATHIEU_Q_MAX))
    if bad_q.any():
        out.append(
            AnalysisWarning(
                "mathieu-q-range",
                "thrust",
                f"Mathieu q outside the memo's range 0 < q <= 0.05 (eq. 4.2-5) at "
                f"{_range_text(Omega, bad_q)}; q = gamma a / 2",
            )
        )
    return out


def stability_parameters(
    omega_psi: float, gamma: float, omega_1: float, beam_action: BeamActionResult
):
    """params(Omega_bar) -> (beta, alpha) for :func:`stability.unstable_frequencies`.

    Parameters
    ----------
    omega_psi : float
        Rigid-body pitch frequency (rad/s).
    gamma : float
        Thrust pulsation amplitude.
    omega_1 : float
        Reference frequency (rad/s).
    beam_action : BeamActionResult
        Beam-action exponents on the case's Omega grid.

    Returns
    -------
    callable
        beta is the exact characteristic exponent (Hill's determinant; real part, i.e. the
        band index inside a pitch tongue) at any Omega; alpha_r comes from the beam-action
        exponents on the case's Omega grid, interpolated as alpha_r Omega_bar (nearly constant:
        it tends to the loaded-beam frequency as gamma -> 0) by a cubic spline, held constant
        outside the grid.
    """
    from scipy.interpolate import CubicSpline

    x = beam_action.Omega_bar
    order = np.argsort(x)
    spline = CubicSpline(x[order], (beam_action.alpha.real * x[:, None])[order], axis=0)

    def params(Omega_bar: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        a, q = mathieu_parameters(Omega_bar * omega_1, omega_psi, gamma)
        beta = characteristic_exponent(a, q, method="hill").real
        alpha = spline(np.clip(Omega_bar, x.min(), x.max())) / Omega_bar[:, None]
        return beta, alpha

    return params


def analyze(
    case: Case,
    beam_action: bool = True,
    stability: bool = True,
    progress: Callable[[str], None] | None = None,
) -> Results:
    """Run the analysis of a validated case.

    Parameters
    ----------
    case : Case
        From :func:`flexbooster.load_case` or :func:`flexbooster.default_case`.
    beam_action : bool
        Compute the beam-action exponents alpha_r (memo 4.1; the slowest stage).
    stability : bool
        Compute the table of unstable thrust frequencies (memo 7.3); needs ``beam_action``.
    progress : callable, optional
        Called with the name of each stage (:data:`STAGES`) as it starts, e.g. to drive a
        progress bar; stages that are not computed are skipped.

    Returns
    -------
    Results
        Mass properties, omega_1, beam modes, rigid-body pitch, shell frequencies, beam action,
        the unstable thrust frequencies and the warnings.
    """
    step = progress or (lambda stage: None)
    b, t, n = case.booster, case.thrust, case.truncation
    c1, c2 = b.cylinder1, b.cylinder2
    step(STAGES[0])
    mass = mass_properties(c1.radius, c1.half_length, c2.radius, c2.half_length, b.thickness, b.rho)
    omega_1 = first_bending_frequency(mass.L, c1.radius, b.E, b.rho)
    omega_psi = pitch_frequency(case.F0, mass.d2, t.K, mass.I_cm)
    groups = dimensionless_groups(
        mass.L, c1.radius, c2.radius, b.thickness, b.E, b.rho, omega_1, case.T0
    )
    beam = beam_modes(n.N, mass.L, c1.radius, b.E, b.rho)
    Omega = case.omega_grid()
    step(STAGES[1])
    pitch = pitch_analysis(Omega, omega_psi, t.gamma)
    step(STAGES[2])
    shell = natural_frequencies(case)
    action = None
    if beam_action:
        step(STAGES[3])
        action = beam_action_analysis(
            Omega,
            omega_1,
            mass.mass,
            mass.L,
            mass.d2,
            mass.I_cm,
            case.F0,
            t.gamma,
            t.K,
            n.N,
            n.S,
            n.R,
        )
    table = None
    extra: list[AnalysisWarning] = []
    if stability and action is not None:
        step(STAGES[4])
        modes = ShellModes(shell.cylinder, shell.j, shell.k, shell.branch, shell.omega_bar)
        params = stability_parameters(omega_psi, t.gamma, omega_1, action)
        try:
            table = unstable_frequencies(
                modes, params, (t.omega_min, t.omega_max), omega_1, n.R, n.S, t.gamma, t.K
            )
        except ValueError as exc:  # too many roots for memory: the rest of the analysis stands
            extra.append(AnalysisWarning("stability-skipped", "truncation", str(exc)))
    return Results(
        case=case,
        mass=mass,
        omega_1=omega_1,
        omega_psi=omega_psi,
        groups=groups,
        beam=beam,
        pitch=pitch,
        shell=shell,
        beam_action=action,
        stability=table,
        warnings=tuple(_warnings(case, Omega, pitch.a, pitch.q, omega_psi) + extra),
    )
