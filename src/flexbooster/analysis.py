"""The analysis pipeline: a validated case in, a :class:`Results` out.

This is the layer that strings the numerical modules together in the memo's order
(reading guide section 1): geometry and mass properties, the equivalent beam (omega_1), the
rigid-body pitch (Mathieu parameters along the Omega grid).  It also produces the warnings
under which the analysis goes on: thin-shell limit exceeded, Mathieu parameters outside the
memo's range (4.2-5).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from . import __version__
from .beam import first_bending_frequency
from .case import Case
from .errors import AnalysisWarning
from .geometry import DimensionlessGroups, MassProperties, dimensionless_groups, mass_properties
from .pitch import mathieu_parameters, pitch_frequency

__all__ = [
    "Results",
    "analyze",
    "SCHEMA_VERSION",
    "THIN_SHELL_LIMIT",
    "MATHIEU_A_RANGE",
    "MATHIEU_Q_MAX",
]

#: Version of the layout of results.json; bumped when a key changes meaning or disappears.
SCHEMA_VERSION = "1.0"
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
    "pitch.Omega": "rad/s",
    "pitch.a, q": "1",
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
    Omega : numpy.ndarray
        The thrust pulsation frequencies analysed (rad/s).
    a, q : numpy.ndarray
        Mathieu parameters along ``Omega`` (eq. 4.2-4).
    warnings : tuple of AnalysisWarning
        Conditions the user must know about.
    """

    case: Case
    mass: MassProperties
    omega_1: float
    omega_psi: float
    groups: DimensionlessGroups
    Omega: np.ndarray
    a: np.ndarray
    q: np.ndarray
    warnings: tuple[AnalysisWarning, ...] = field(default_factory=tuple)

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
            "pitch": {
                "Omega": self.Omega.tolist(),
                "a": self.a.tolist(),
                "q": self.q.tolist(),
            },
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


def analyze(case: Case) -> Results:
    """Run the analysis of a validated case.

    Parameters
    ----------
    case : Case
        From :func:`flexbooster.load_case` or :func:`flexbooster.default_case`.

    Returns
    -------
    Results
        Mass properties, omega_1, the pitch frequency, the dimensionless groups, the Mathieu
        parameters along the Omega grid and the warnings.
    """
    b, t = case.booster, case.thrust
    c1, c2 = b.cylinder1, b.cylinder2
    mass = mass_properties(c1.radius, c1.half_length, c2.radius, c2.half_length, b.thickness, b.rho)
    omega_1 = first_bending_frequency(mass.L, c1.radius, b.E, b.rho)
    omega_psi = pitch_frequency(case.F0, mass.d2, t.K, mass.I_cm)
    groups = dimensionless_groups(
        mass.L, c1.radius, c2.radius, b.thickness, b.E, b.rho, omega_1, case.T0
    )
    Omega = case.omega_grid()
    a, q = mathieu_parameters(Omega, omega_psi, t.gamma)
    return Results(
        case=case,
        mass=mass,
        omega_1=omega_1,
        omega_psi=omega_psi,
        groups=groups,
        Omega=Omega,
        a=a,
        q=q,
        warnings=tuple(_warnings(case, Omega, a, q, omega_psi)),
    )
