"""Tests of flexbooster.memo.beam: free-free beam functions and appendix-B coefficient integrals.

Tiers: exact limits (free-end conditions, phi'''' = phi, the limits of the beam coordinate),
literature values (reading guide section 6 / Blevins table 8-1), invariants and two methods
agreeing (orthogonality, closed form vs quadrature, limit values vs integrated derivatives).
"""

from __future__ import annotations

import json

import numpy as np
import pytest

from flexbooster.memo import beam
from flexbooster.memo.geometry import mass_properties
from harness import Reference, check_reference  # noqa: E402
from reference import appendix_b

# Geometries (R1, L1, R2, L2) in m, h = 20 mm, rho = 2768 kg/m^3:
# the memo case (Saturn-class), a short forward stage, and one with L/L2 = 7/4, for which
# j pi L / L2 = 3.5 j pi hits lambda_n ~ (n + 1/2) pi whenever 7 j / 2 = n + 1/2, where the
# memo's factor 2/B^- is singular (exactly, in double precision, for n >= 10).
GEOMETRIES = {
    "default": (5.05, 21.0, 3.30, 9.0),
    "short-forward": (2.0, 5.0, 0.5, 1.0),
    "resonant": (1.0, 3.0, 1.5, 4.0),
}


def props(name: str):
    R1, L1, R2, L2 = GEOMETRIES[name]
    return mass_properties(R1, L1, R2, L2, 0.02, 2768.0)


# --------------------------------------------------------------------------------------------
# Tier 1: exact limits
# --------------------------------------------------------------------------------------------


@pytest.mark.parametrize("zeta", [0.0, 2.0])
@pytest.mark.parametrize("derivative", [2, 3])
def test_free_ends_moment_and_shear_vanish(zeta, derivative):
    # Free-free beam: phi'' = phi''' = 0 at both ends (Blevins 1979, table 8-1 boundary
    # conditions); phi is O(2) there, so 1e-9 absolute allows for n up to 200.
    n = np.arange(1, 201)
    values = beam.mode_shape(n, np.full(n.shape, zeta), derivative)
    assert np.all(np.abs(values) < 1e-9)


def test_fourth_derivative_equals_function():
    # (C-5), (C-15), (C-20 corrected): phi'''' = phi exactly (the ODE phi'''' = phi in X).
    n = np.arange(1, 201)[:, None]
    zeta = np.linspace(0.0, 2.0, 41)[None, :]
    np.testing.assert_allclose(
        beam.mode_shape(n, zeta, 4), beam.mode_shape(n, zeta, 0), rtol=0, atol=1e-11
    )


def test_limit_coordinates_are_beam_ends_and_junction():
    # (C-7)..(C-9) with d2 + d4 = L, d4 - d1 = L - 2 L1, d4 - d3 = -L (reading guide 2):
    # zeta = 0, 2 L1 / L, 2.
    p = props("default")
    lim = appendix_b.limit_values(p, 3)
    assert lim.zeta_a == pytest.approx(0.0, abs=1e-15)
    assert lim.zeta_c == pytest.approx(2 * 21.0 / 30.0, rel=1e-15)
    assert lim.zeta_b == pytest.approx(2.0, rel=1e-15)


@pytest.mark.parametrize("phase", ["zero", "memo"])
@pytest.mark.parametrize("cylinder", [1, 2])
def test_r_integral_exact(phase, cylinder):
    # (B-1)/(B-7): r_j = (2 L_d / (j pi L)) [cos theta_j(start) - cos theta_j(end)] exactly
    # (antiderivative of sin); zero phase: (2 L_d/(j pi L)) (1 - (-1)^j).
    p = props("default")
    L_d = 21.0 if cylinder == 1 else 9.0
    j = np.arange(1, 21)
    if phase == "zero":
        th_lo, th_hi = 0.0 * j, j * np.pi
    elif cylinder == 1:
        th_lo, th_hi = j * np.pi * (p.d1 - p.d2) / (2 * 21.0), j * np.pi * p.d1 / 21.0  # B-1
    else:
        th_lo = j * np.pi * (2 * p.d1 - 21.0) / (2 * 9.0)  # B-7
        th_hi = j * np.pi * (p.d1 + p.d3 - 21.0) / (2 * 9.0)
    expected = 2 * L_d / (j * np.pi * 30.0) * (np.cos(th_lo) - np.cos(th_hi))
    got = appendix_b.coefficient_integrals(p, 20, 1, cylinder, "closed", phase).r[:, 0]
    np.testing.assert_allclose(got, expected, rtol=0, atol=1e-14)


# --------------------------------------------------------------------------------------------
# Tier 2: literature values
# --------------------------------------------------------------------------------------------

# Reading guide section 6 (= Blevins 1979, table 8-1, free-free): roots of cos cosh = 1,
# printed to 10 significant digits -> 1e-9 relative is the table's own resolution.
LAMBDA_REF = Reference(
    name="free-free beam eigenvalue lambda_n", source="Blevins (1979) table 8-1",
    points=tuple((n,) for n in range(1, 6)),
    expected=(4.730040745, 7.853204624, 10.99560784, 14.13716549, 17.27875966), rtol=1e-9)
# Reading guide section 6: alpha_n to 6 decimals -> half a unit of the last digit.
ALPHA_REF = Reference(
    name="free-free beam alpha_n", source="reading guide section 6 (6 decimals)",
    points=((1,), (2,), (3,)), expected=(0.982502, 1.000777, 0.999966), rtol=0.0, atol=5e-7)


def test_lambda_reference_values():
    check_reference(lambda n: beam.free_free_eigenvalues(5)[n - 1], LAMBDA_REF)


def test_alpha_reference_values():
    check_reference(lambda n: beam.free_free_alpha(3)[n - 1], ALPHA_REF)


def test_lambda_satisfies_frequency_equation_in_high_precision():
    # mpmath 30 digits: cos(lambda) cosh(lambda) - 1 at the double-precision root is of the
    # size of its derivative times half an ulp, i.e. the root is correct to ~1 ulp.
    mpmath = pytest.importorskip("mpmath")
    mpmath.mp.dps = 30
    lam = beam.free_free_eigenvalues(200)
    for n in (1, 2, 7, 50, 200):
        x = mpmath.mpf(float(lam[n - 1]))
        f = mpmath.cos(x) * mpmath.cosh(x) - 1
        fprime = -mpmath.sin(x) * mpmath.cosh(x) + mpmath.cos(x) * mpmath.sinh(x)
        assert abs(f / fprime) < 4e-16 * float(x)


def test_large_n_asymptote_and_memo_approximation_off_by_one():
    # Exact asymptote lambda_n -> (2n + 1) pi / 2 (Blevins table 8-1 note); the memo's C-IV
    # "(2n - 1) pi / 2" is one index low (erratum C-IV-a): it misses by pi.
    n = np.arange(10, 201)
    lam = beam.free_free_eigenvalues(200)[9:]
    np.testing.assert_allclose(lam, (2 * n + 1) * np.pi / 2, rtol=0, atol=1e-12)
    assert np.all(np.abs(lam - (2 * n - 1) * np.pi / 2 - np.pi) < 1e-12)
    np.testing.assert_allclose(beam.free_free_alpha(200)[9:], 1.0, rtol=0, atol=1e-12)


def test_memo_table_truncates_the_exact_values_except_lambda4():
    # Memo C-IV table (4 decimals): every entry is the exact value truncated (not rounded) to
    # 4 decimals (17.278759 -> 17.2787, 0.999966 -> 0.9999), except lambda_4 = 14.1377
    # (exact 14.137165, truncated 14.1371): erratum C-IV-b.
    memo_lambda = np.array([4.7300, 7.8532, 10.9956, 14.1377, 17.2787])
    memo_alpha = np.array([0.9825, 1.0007, 0.9999, 1.0000, 0.9999])
    lam = beam.free_free_eigenvalues(5)
    alpha = beam.free_free_alpha(5)
    lam_ok = np.abs(np.floor(lam * 1e4) / 1e4 - memo_lambda) < 1e-9
    alpha_ok = np.abs(np.floor(alpha * 1e4) / 1e4 - memo_alpha) < 1e-9
    assert lam_ok.tolist() == [True, True, True, False, True]
    assert alpha_ok.all()
    assert abs(lam[3] - 14.1377) > 5e-4


def test_omega_1_from_section_properties():
    # Euler-Bernoulli (Blevins table 8-1): omega_1 = (lambda_1 / l)^2 sqrt(E I / m) with
    # l = 2L, I = pi R^3 h, m = 2 pi R h rho (thin tube), independent of eq. (4.2-8b)'s form.
    L, R, E, rho, h = 30.0, 5.05, 72.4e9, 2768.0, 0.02
    expected = (4.730040745 / (2 * L)) ** 2 * np.sqrt(
        E * np.pi * R**3 * h / (2 * np.pi * R * h * rho)
    )
    assert beam.first_bending_frequency(L, R, E, rho) == pytest.approx(expected, rel=1e-9)
    modes = beam.beam_modes(4, L, R, E, rho)
    assert modes.omega_1 == pytest.approx(expected, rel=1e-9)


# --------------------------------------------------------------------------------------------
# Tier 3: invariants, two methods agree
# --------------------------------------------------------------------------------------------


def _gauss(lo: float, hi: float, panels: int, order: int = 20):
    x, w = np.polynomial.legendre.leggauss(order)
    edges = np.linspace(lo, hi, panels + 1)
    half = 0.5 * np.diff(edges)[:, None]
    nodes = (0.5 * (edges[:-1] + edges[1:])[:, None] + half * x).ravel()
    return nodes, (half * w).ravel()


def test_modes_orthonormal_up_to_n_200():
    # Free-free modes are orthogonal on [0, 2] with int phi_n^2 = 2 (Meirovitch 1986, 7.4);
    # quadrature: 20-point Gauss-Legendre on 400 panels (about 0.8 rad of X per panel).
    zeta, w = _gauss(0.0, 2.0, 400)
    phi = beam.mode_shape(np.arange(1, 201)[:, None], zeta[None, :])
    assert np.all(np.isfinite(phi))
    gram = (phi * w) @ phi.T / 2.0
    off = gram - np.diag(np.diag(gram))
    assert np.max(np.abs(off)) < 1e-10
    np.testing.assert_allclose(np.diag(gram), 1.0, rtol=0, atol=1e-10)


def test_modes_orthogonal_to_rigid_body_motion():
    # Free-free elastic modes carry no net momentum or angular momentum:
    # int phi_n = int (zeta - 1) phi_n = 0 on [0, 2] (Meirovitch 1986, 7.4); same quadrature.
    zeta, w = _gauss(0.0, 2.0, 400)
    phi = beam.mode_shape(np.arange(1, 201)[:, None], zeta[None, :])
    assert np.max(np.abs(phi @ w)) < 1e-10
    assert np.max(np.abs(phi @ (w * (zeta - 1.0)))) < 1e-10


@pytest.mark.parametrize("derivative", [0, 1, 2, 3])
@pytest.mark.parametrize("cylinder", [1, 2])
def test_limit_values_match_integrated_derivative(derivative, cylinder):
    # (C-11..C-14), (C-16..C-19): phi^(k)|_lo^hi = (lambda_n/2) int phi^(k+1) d xi_bar
    # (fundamental theorem; quadrature 20-point Gauss on 300 panels).
    p = props("default")
    lim = appendix_b.limit_values(p, 60, derivative)
    lo, hi = (lim.zeta_a, lim.zeta_c) if cylinder == 1 else (lim.zeta_c, lim.zeta_b)
    zeta, w = _gauss(lo, hi, 300)
    n = np.arange(1, 61)
    lam = beam.free_free_eigenvalues(60)
    integral = lam / 2 * (beam.mode_shape(n[:, None], zeta[None, :], derivative + 1) @ w)
    diff = lim.cylinder1 if cylinder == 1 else lim.cylinder2
    np.testing.assert_allclose(diff, integral, rtol=0, atol=1e-10)


def _printed_limits(p, N: int, printed_c13: bool) -> list[np.ndarray]:
    """(C-11)..(C-14) written out literally (cosh/sinh unscaled, fine for n <= 6)."""
    L = p.L
    lam = beam.free_free_eigenvalues(N)
    al = beam.free_free_alpha(N)
    zc = (L - (p.d4 - p.d1)) / L  # (C-8)
    za = (L - (p.d2 + p.d4)) / L  # (C-7)

    def at(z, sinh_arg=None):
        x = lam / 2 * z
        xs = x if sinh_arg is None else sinh_arg
        return [
            np.cosh(x) + np.cos(x) - al * (np.sinh(x) + np.sin(x)),  # C-11
            np.sinh(x) - np.sin(x) - al * (np.cosh(x) + np.cos(x)),  # C-12
            np.cosh(x) - np.cos(x) - al * (np.sinh(xs) - np.sin(x)),  # C-13
            np.sinh(x) + np.sin(x) - al * (np.cosh(x) - np.cos(x)),  # C-14
        ]

    top = at(zc, sinh_arg=zc * np.ones(N) if printed_c13 else None)
    bottom = at(za)
    return [t - b for t, b in zip(top, bottom, strict=True)]


def test_c11_to_c14_literal_forms_and_c13_misprint():
    # (C-11)..(C-14) as written (with lambda_n/2 in every argument) equal the scaled
    # evaluation phi^(k)|_a^c; unscaled cosh ~ 1e8 for n = 6 limits the check to 1e-6.
    # Erratum C-13: the printed sinh[(L - (d4 - d1))/L] (no lambda_n/2) is far off.
    p = props("default")
    literal = _printed_limits(p, 6, printed_c13=False)
    for k in range(4):
        np.testing.assert_allclose(
            literal[k], appendix_b.limit_values(p, 6, k).cylinder1, rtol=0, atol=1e-6
        )
    printed = _printed_limits(p, 6, printed_c13=True)
    assert np.min(np.abs(printed[2] - literal[2])) > 1.0


CASES = [(g, c, ph) for g in GEOMETRIES for c in (1, 2) for ph in ("zero", "memo")]


@pytest.mark.parametrize(("geometry", "cylinder", "phase"), CASES)
def test_closed_form_matches_quadrature_n50_j50(geometry, cylinder, phase):
    # Acceptance: every n <= 50, j <= 50, all five integrals (B-2..B-6 / B-8..B-12).
    # Reference: composite 16-point Gauss-Legendre (about 1.5 rad per panel), checked against
    # itself with 16 x 700 nodes below 1e-14.  The integrals are O(0.1..1); the tolerance is
    # 1e-10 relative to max(|I|, 1e-3): entries below 1e-3 (down to 1e-14, structurally
    # near zero) are held to 1e-13 absolute; observed absolute differences are ~1e-14.
    p = props(geometry)
    quad = appendix_b.coefficient_integrals(p, 50, 50, cylinder, "quadrature", phase)
    closed = appendix_b.coefficient_integrals(p, 50, 50, cylinder, "closed", phase)
    for key in "stxyz":
        ref = getattr(quad, key)
        err = np.abs(getattr(closed, key) - ref) / np.maximum(np.abs(ref), 1e-3)
        assert np.max(err) < 1e-10, (key, float(np.max(err)))


def test_quadrature_converged():
    # The quadrature default (~16 x 170 nodes here) against 16 x 700 nodes: below 1e-14.
    p = props("default")
    coarse = appendix_b.coefficient_integrals(p, 50, 50, 1, "quadrature", "zero")
    fine = appendix_b.coefficient_integrals(p, 50, 50, 1, "quadrature", "zero", n_points=16 * 700)
    for key in "stxyz":
        assert np.max(np.abs(getattr(coarse, key) - getattr(fine, key))) < 1e-14


@pytest.mark.parametrize(
    ("geometry", "cylinder", "phase"), [c for c in CASES if c[0] != "resonant"]
)
def test_memo_brackets_evaluated_as_difference_of_products_match_quadrature(
    geometry, cylinder, phase
):
    # Erratum B-13/B-19: the memo's brackets are right, its evaluation at the limits is not;
    # evaluated as [w(theta) P(X)]_lo^hi they equal the quadrature (tolerance as above, away
    # from jpiL/L_d = lambda_n where 2/B^- amplifies rounding).
    p = props(geometry)
    quad = appendix_b.coefficient_integrals(p, 50, 50, cylinder, "quadrature", phase)
    fixed = appendix_b.coefficient_integrals(p, 50, 50, cylinder, "memo-corrected", phase)
    for key in "stxyz":
        ref = getattr(quad, key)
        err = np.abs(getattr(fixed, key) - ref) / np.maximum(np.abs(ref), 1e-3)
        assert np.max(err) < 1e-10, (key, float(np.max(err)))


def test_memo_form_singular_at_resonance_closed_form_is_not():
    # Geometry "resonant", cylinder 2: j pi L / L2 = 3.5 j pi equals lambda_45 = 45.5 pi (to
    # double precision, e^-143) at j = 26, so (B^-)_2 = 0 in (B-19..B-24): the memo forms are
    # 0/0 there (returned as 0), the stable closed form matches quadrature (which is O(0.5)).
    p = props("resonant")
    quad = appendix_b.coefficient_integrals(p, 26, 45, 2, "quadrature", "zero")
    fixed = appendix_b.coefficient_integrals(p, 26, 45, 2, "memo-corrected", "zero")
    closed = appendix_b.coefficient_integrals(p, 26, 45, 2, "closed", "zero")
    assert abs(quad.s[25, 44]) > 0.5
    assert fixed.s[25, 44] == 0.0
    assert abs(closed.s[25, 44] - quad.s[25, 44]) < 1e-12


@pytest.mark.parametrize("cylinder", [1, 2])
def test_memo_printed_closed_form_disagrees_with_quadrature(cylinder):
    # Erratum B-13..B-17 / B-19..B-23 as printed: products of differences,
    # {w(theta)}|_lo^hi [P(X)]|_lo^hi.  With the zero phase the cos-differences are
    # (-1)^j - 1 and the sin-differences 0, so the printed s, t, x, y vanish for every even j,
    # while the integrals (quadrature) do not.
    p = props("default")
    printed = appendix_b.coefficient_integrals(p, 10, 10, cylinder, "memo", "zero")
    quad = appendix_b.coefficient_integrals(p, 10, 10, cylinder, "quadrature", "zero")
    for key in "stxy":
        assert np.max(np.abs(getattr(printed, key)[1::2, :])) < 1e-14
        assert np.max(np.abs(getattr(quad, key)[1::2, :])) > 0.05
    rel = np.abs(printed.s - quad.s) / np.maximum(np.abs(quad.s), 1e-3)
    assert np.median(rel) > 0.5


def test_cylinder2_x_integral_needs_L_over_L2():
    # Erratum B-10: printed argument (L/L1) xi_bar; the closed form B-21 and B-8, B-9, B-11,
    # B-12 use L/L2.  Quadrature (20-point Gauss, 200 panels) with L/L2 matches B-21 (memo
    # brackets, corrected evaluation); with the printed L/L1 it does not.
    p = props("default")
    L, L1, L2 = 30.0, 21.0, 9.0
    r2 = (p.d1 - (L1 + L2)) / L2
    c, b = p.d1 / L, p.d3 / L
    xi, w = _gauss(c, b, 200)
    zeta = xi - p.d4 / L + 1.0
    n = np.arange(1, 11)
    phi2 = beam.mode_shape(n[:, None], zeta[None, :], 2)
    j = np.arange(1, 11)[:, None]
    ref = appendix_b.coefficient_integrals(p, 10, 10, 2, "memo-corrected", "memo").x
    with_l2 = (np.sin(j * np.pi / 2 * (L / L2 * xi + r2 + 1)) * w) @ phi2.T
    with_l1 = (np.sin(j * np.pi / 2 * (L / L1 * xi + r2 + 1)) * w) @ phi2.T
    np.testing.assert_allclose(with_l2, ref, rtol=0, atol=1e-12)
    assert np.max(np.abs(with_l1 - ref)) > 0.1


def test_phase_choice_changes_integrals():
    # E10: the printed phase is not zero at the aft edge, so the integrals differ from the
    # zero-phase ones unless d1 = d2 (cylinder 1 exactly centred on the CM).
    p = props("default")
    zero = appendix_b.coefficient_integrals(p, 5, 5, 1, "closed", "zero")
    memo = appendix_b.coefficient_integrals(p, 5, 5, 1, "closed", "memo")
    assert np.max(np.abs(zero.s - memo.s)) > 0.1
    # L2 -> 0: d1 = d2 (R2 = 0: no second shell; a thin shell needs h < R2 where R2 > 0)
    p_sym = mass_properties(1.0, 3.0, 0.0, 1e-9, 0.02, 2768.0)
    zero = appendix_b.coefficient_integrals(p_sym, 5, 5, 1, "closed", "zero")
    memo = appendix_b.coefficient_integrals(p_sym, 5, 5, 1, "closed", "memo")
    np.testing.assert_allclose(memo.s, zero.s, rtol=0, atol=1e-8)


# --------------------------------------------------------------------------------------------
# Result objects and input validation
# --------------------------------------------------------------------------------------------


def test_result_objects_are_json_ready():
    modes = beam.beam_modes(6, 30.0, 5.05, 72.4e9, 2768.0)
    text = json.dumps(modes.to_dict(), allow_nan=False)
    assert '"lambda_n"' in text
    assert beam.beam_modes(3).to_dict()["omega_1"] is None
    ci = appendix_b.coefficient_integrals(props("default"), 3, 4, 2, "closed", "zero")
    assert ci.s.shape == (3, 4)
    json.dumps(ci.to_dict(), allow_nan=False)
    json.dumps(appendix_b.limit_values(props("default"), 4, 2).to_dict(), allow_nan=False)


@pytest.mark.parametrize(
    ("call", "match"),
    [
        (lambda: beam.free_free_eigenvalues(0), "n = 0"),
        (lambda: beam.free_free_alpha(2.5), "n = 2.5"),
        (lambda: beam.mode_shape(0, 0.5), "mode numbers"),
        (lambda: beam.mode_shape(1, np.nan), "zeta"),
        (lambda: beam.mode_shape(1, 0.5, -1), "derivative"),
        (lambda: beam.beam_modes(3, L=30.0), "all four"),
        (lambda: beam.first_bending_frequency(-1.0, 1.0, 1.0, 1.0), "L = -1.0"),
        (lambda: appendix_b.coefficient_integrals(props("default"), 0, 3), "M = 0"),
        (lambda: appendix_b.coefficient_integrals(props("default"), 3, 3, 3), "cylinder = 3"),
        (lambda: appendix_b.coefficient_integrals(props("default"), 3, 3, 1, "exact"), "method"),
        (lambda: appendix_b.coefficient_integrals(props("default"), 3, 3, 1, "closed", "x"),
         "phase"),
        (lambda: appendix_b.limit_values(object(), 3), "props"),
    ],
)
def test_bad_input_raises_value_error(call, match):
    with pytest.raises(ValueError, match=match):
        call()


def test_mode_shape_plot_marks_junction():
    # The plot draws phi_1..phi_N (as mode_shape) against the station x = L zeta (m) and the
    # junction at zeta = 2 L1 / L (C-8), i.e. x = 2 L1 = 42 m from the aft edge.
    from flexbooster.memo.charts import beam_mode_shapes
    from flexbooster.present.plotting.beam import mode_shape_plot

    data = beam_mode_shapes(props("default"), N=3)
    np.testing.assert_array_equal(data.phi[2], beam.mode_shape(3, data.zeta))  # eq. (C-1)
    fig = mode_shape_plot(data)
    lines = fig.axes[0].get_lines()
    assert len([ln for ln in lines if ln.get_label().startswith("φ")]) == 3
    junction = [ln for ln in lines if ln.get_label() == "junction"][0]
    assert junction.get_xdata()[0] == pytest.approx(2 * 21.0, rel=1e-14)
