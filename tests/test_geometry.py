"""Geometry and mass properties against an independent integration of the shell mass.

The reference is a direct numerical integration of the mass distribution of the two shells over
their surfaces (x, theta): Gauss-Legendre in x (20 points per cylinder, exact for the
polynomials of degree <= 39 that appear) and the trapezoidal rule in theta (64 points, exact
for the trigonometric polynomials of degree < 64 that appear), mass element rho h R dtheta dx.
Nothing of geometry.py's closed forms is used.
"""

from __future__ import annotations

import math
import re

import numpy as np
import pint
import pytest

from flexbooster.memo.geometry import dimensionless_groups, mass_properties, moment_of_inertia_memo
from harness import assert_close  # noqa: E402

RTOL = 1e-12  # acceptance: agreement to 1e-12 relative


def integrate_shells(R1, L1, R2, L2, h, rho, n_x=20, n_theta=64):
    """Mass, CM and transverse moment of inertia by quadrature over both shell surfaces."""
    xg, wg = np.polynomial.legendre.leggauss(n_x)
    theta = 2 * np.pi * np.arange(n_theta) / n_theta
    parts = []
    for R, x0, x1 in ((R1, 0.0, 2 * L1), (R2, 2 * L1, 2 * L1 + 2 * L2)):
        if x1 == x0:
            continue
        x = 0.5 * (x1 - x0) * xg + 0.5 * (x1 + x0)
        wx = 0.5 * (x1 - x0) * wg
        X, T = np.meshgrid(x, theta, indexing="ij")
        dm = rho * h * R * np.outer(wx, np.full(n_theta, 2 * np.pi / n_theta))
        parts.append((X, R * np.cos(T), dm))
    mass = sum(dm.sum() for _, _, dm in parts)
    x_cm = sum((X * dm).sum() for X, _, dm in parts) / mass
    # inertia about the transverse axis through the CM: distance^2 = y^2 + (x - x_cm)^2
    inertia = sum(((Y**2 + (X - x_cm) ** 2) * dm).sum() for X, Y, dm in parts)
    return mass, x_cm, inertia


BOOSTERS = {
    # name: (R1, L1, R2, L2, h, rho)
    "symmetric": (3.0, 10.0, 3.0, 10.0, 0.01, 2700.0),
    "asymmetric, CM in cylinder 1": (5.05, 21.0, 3.3, 9.0, 0.02, 2768.0),
    "CM in cylinder 2": (1.0, 4.0, 6.0, 12.0, 0.015, 7800.0),
    "short heavy top, CM in cylinder 2": (2.0, 3.0, 8.0, 3.5, 0.03, 4500.0),
}


@pytest.mark.parametrize("name", BOOSTERS)
def test_mass_properties_against_surface_quadrature(name):
    R1, L1, R2, L2, h, rho = BOOSTERS[name]
    p = mass_properties(R1, L1, R2, L2, h, rho)
    mass, x_cm, inertia = integrate_shells(R1, L1, R2, L2, h, rho)
    assert_close([p.mass, p.x_cm, p.I_cm, p.m1 + p.m2], [mass, x_cm, inertia, mass],
                 rtol=RTOL, source="Gauss-Legendre x trapezoid quadrature over the shells",
                 name=f"mass, x_cm, I_cm, m1 + m2 ({name})")


@pytest.mark.parametrize("name", BOOSTERS)
def test_distances_and_coordinates_follow_figure_1(name):
    """Identities of the reading guide section 2 (d1 + d2 = 2 L1, d2 + d3 = 2 L, ...)."""
    R1, L1, R2, L2, h, rho = BOOSTERS[name]
    p = mass_properties(R1, L1, R2, L2, h, rho)
    _, x_cm, _ = integrate_shells(R1, L1, R2, L2, h, rho)
    L = L1 + L2
    assert p.d1 + p.d2 == pytest.approx(2 * L1, rel=RTOL)
    assert p.d2 + p.d3 == pytest.approx(2 * L, rel=RTOL)
    assert p.d4 == pytest.approx(L - x_cm, rel=1e-12, abs=1e-12 * L)
    # (c - a)/2 = L1/L and (b - c)/2 = L2/L (reading guide section 2)
    assert (p.c - p.a) / 2 == pytest.approx(L1 / L, rel=RTOL)
    assert (p.b - p.c) / 2 == pytest.approx(L2 / L, rel=RTOL)
    expected_cylinder = 1 if x_cm <= 2 * L1 else 2
    assert p.cm_cylinder == expected_cylinder
    assert (p.d1 < 0) == (expected_cylinder == 2)  # d1 negative when the CM is in cylinder 2


def test_cm_in_cylinder_2_is_detected():
    p = mass_properties(*BOOSTERS["CM in cylinder 2"])
    assert p.cm_cylinder == 2 and p.d1 < 0 and p.x_cm > 2 * 4.0


@pytest.mark.parametrize("L2", [0.0, 1e-9])
def test_single_cylinder_limit(L2):
    """L2 -> 0: a single thin tube, m = 2 pi rho h R (2 L1), x_cm = L1,
    I = m (R^2/2 + (2 L1)^2 / 12) (thin-walled tube about a transverse diameter through its
    centre; Weaver, Timoshenko & Young, Vibration Problems in Engineering, appendix)."""
    R, L1, h, rho = 2.5, 8.0, 0.012, 2800.0
    p = mass_properties(R, L1, 1.7, L2, h, rho)
    m = 2 * np.pi * rho * h * R * 2 * L1
    tol = 1e-8 if L2 else RTOL  # the 1e-9 m cylinder perturbs the values by ~1e-10 relative
    assert p.mass == pytest.approx(m, rel=tol)
    assert p.x_cm == pytest.approx(L1, rel=tol)
    assert p.I_cm == pytest.approx(m * (R**2 / 2 + (2 * L1) ** 2 / 12), rel=tol)
    assert p.c == pytest.approx(p.b, rel=tol)  # the junction is the nose


@pytest.mark.parametrize("name", BOOSTERS)
def test_memo_printed_inertia_is_not_the_inertia(name):
    """Erratum E1: the printed 2.2-3 / 4.2-2b forms disagree with the quadrature reference and
    with each other; for a single cylinder (e = 0) 2.2-3 gives m (R^2/4 + L^2/3), short of the
    thin tube's m (R^2/2 + L^2/3) by m R^2/4."""
    R1, L1, R2, L2, h, rho = BOOSTERS[name]
    _, _, inertia = integrate_shells(R1, L1, R2, L2, h, rho)
    printed_a = moment_of_inertia_memo(R1, L1, R2, L2, h, rho, form="2.2-3")
    printed_b = moment_of_inertia_memo(R1, L1, R2, L2, h, rho, form="4.2-2b")
    # far beyond the 1e-12 agreement of the corrected formula (some geometries land within 1 %)
    assert abs(printed_a / inertia - 1) > 1e-3
    assert abs(printed_b / inertia - 1) > 1e-3
    assert printed_a != pytest.approx(printed_b, rel=1e-3)
    # single cylinder: the deficit is exactly m R^2 / 4
    R, L = 2.0, 6.0
    # R2 = 0 as well: the printed R2 (d3 - L2)^3 term does not vanish with L2 alone
    single = moment_of_inertia_memo(R, L, 0.0, 0.0, h, rho, form="2.2-3")
    _, _, reference = integrate_shells(R, L, 1.0, 0.0, h, rho)
    m = 2 * np.pi * rho * h * R * 2 * L
    assert reference - single == pytest.approx(m * R**2 / 4, rel=1e-10)


def test_dimensionless_groups_are_dimensionless():
    """Erratum E3: mu as printed in 3.0-4a (rho L omega^2 / E) has the dimension 1/length; the
    notation list's rho L^2 omega^2 / E, which the code uses, is dimensionless. Checked with pint
    on the formulas' units."""
    u = pint.UnitRegistry()
    rho, L, w, E = 1 * u("kg/m^3"), 1 * u.m, 1 * u("rad/s"), 1 * u.Pa
    h, T0 = 1 * u.m, 1 * u("N/m")
    assert (rho * L * w**2 / E).to_base_units().dimensionality == u.m.dimensionality**-1
    assert (rho * L**2 * w**2 / E).to_base_units().dimensionless
    assert (T0 / (rho * h * L**2 * w**2)).to_base_units().dimensionless


def test_dimensionless_groups_values():
    """Definitions of memo 3.0-1, 3.0-4 (notation list) evaluated by hand for round numbers."""
    g = dimensionless_groups(
        L=10.0, R1=2.0, R2=4.0, h=0.01, E=2.0e11, rho=8000.0, omega_1=50.0, T0=1.0e4
    )
    assert g.mu == pytest.approx(8000 * 100 * 2500 / 2e11, rel=1e-15)  # = 0.1
    assert g.lambda1 == 5.0 and g.lambda2 == 2.5 and g.sigma == pytest.approx(1e-3, rel=1e-15)
    assert g.T0_bar == pytest.approx(1e4 / (8000 * 0.01 * 100 * 2500), rel=1e-15)  # = 0.5


@pytest.mark.parametrize(
    ("call", "words"),
    [
        (lambda: mass_properties(math.nan, 1, 1, 1, 0.01, 1), "R1 = nan"),
        (lambda: mass_properties(-5.0, 1, 1, 1, 0.01, 1), "R1 = -5.0"),
        (lambda: mass_properties(1, 1, 1, 1, math.inf, 1), "h = inf"),
        (lambda: mass_properties(1, 1, 1, -1.0, 0.01, 1), "L2 = -1.0"),
        (lambda: mass_properties(1e300, 1, 1, 1, 0.01, 1), "overflow"),
        (lambda: dimensionless_groups(1, 1, 1, 0.01, math.nan, 1, 1, 1), "E = nan"),
    ],
)
def test_bad_arguments_raise_naming_the_parameter(call, words):
    # no NaN returned silently, no garbage accepted
    with pytest.raises(ValueError, match=re.escape(words)):
        call()
