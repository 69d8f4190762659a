"""Tests of flexbooster.memo.pitch: Mathieu parameters, characteristic exponent, psi(tau).

Tiers: exact limits (q = 0, symmetry), literature values (scipy/A&S characteristic values,
an independent 50-digit mpmath Taylor-series monodromy, stored in tests/data), invariants and
methods agreeing (Floquet vs Hill, O(q^4) of the corrected memo formula, O(q^2) of the
three-term psi, growth rate against direct integration).
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from scipy import integrate, special

from flexbooster.floquet import mathieu
from flexbooster.memo import pitch
from harness import assert_close  # noqa: E402

DATA = Path(__file__).parent / "data"


# --------------------------------------------------------------------------------------------
# Independent references
# --------------------------------------------------------------------------------------------

#: (a, q) -> (y1(pi), beta): the discriminant by a 50-digit mpmath Taylor series and the
#: exponent with its band index from scipy's characteristic values, independent of both
#: methods (tests/data/make_mathieu_reference.py: memo range, first-tongue interior, a < a_0,
#: higher tongues and stable bands, q = 0; no point within 1e-4 of a transition curve).
REFERENCES = {
    (p["a"], p["q"]): (p["discriminant"], complex(*p["beta"]))
    for p in json.loads((DATA / "mathieu_reference.json").read_text())["points"]
}
EXPONENT_POINTS = list(REFERENCES)


# --------------------------------------------------------------------------------------------
# Tier 1: exact limits
# --------------------------------------------------------------------------------------------


@pytest.mark.parametrize("method", ["floquet", "hill"])
def test_q_zero_gives_sqrt_a(method):
    # q = 0: psi'' + a psi = 0, beta = sqrt(a) exactly (a > 0), i sqrt(-a) for a < 0.
    a = np.array([0.01, 0.3, 0.81, 1.7, 3.9, 8.5, 15.0, 24.2])
    beta = mathieu.characteristic_exponent(a, 0.0, method)
    np.testing.assert_allclose(beta.real, np.sqrt(a), rtol=0, atol=1e-11)
    assert np.all(beta.imag == 0)
    neg = mathieu.characteristic_exponent(np.array([-0.5, -2.0]), 0.0, method)
    np.testing.assert_allclose(neg.imag, np.sqrt([0.5, 2.0]), rtol=1e-11)
    np.testing.assert_allclose(neg.real, 0.0, atol=0)


@pytest.mark.parametrize("method", ["floquet", "hill", "memo"])
def test_even_in_q(method):
    # Shifting tau_1 by pi/2 maps q to -q, so beta(a, -q) = beta(a, q) (McLachlan ch. IV).
    a = np.array([0.3, 0.6, 0.95])
    q = np.array([0.01, 0.04, 0.05])
    def beta(q):
        return (pitch.memo_exponent(a, q) if method == "memo"
                else mathieu.characteristic_exponent(a, q, method))

    np.testing.assert_array_equal(beta(-q), beta(q))


def test_mathieu_parameters_definition():
    # (4.2-4) with omega_psi^2 = 2 pi R1 d2 K T0 / I_cm: a = 8 pi R1 d2 K T0 / (I_cm Omega^2).
    R1, d2, K, T0, I_cm, gamma = 5.05, 27.6, 0.5, 8.8e4, 2.7e7, 0.05
    omega_psi = pitch.pitch_frequency(2 * np.pi * R1 * T0, d2, K, I_cm)
    Omega = np.array([5.0, 50.0])
    a, q = pitch.mathieu_parameters(Omega, omega_psi, gamma)
    np.testing.assert_allclose(a, 8 * np.pi * R1 * d2 * K * T0 / (I_cm * Omega**2), rtol=1e-14)
    np.testing.assert_allclose(q, gamma * a / 2, rtol=1e-15)


def test_psi_numerical_q_zero_is_cosine():
    # q = 0: psi = psi0 cos(sqrt(a) tau_1) exactly; solve_ivp at rtol 1e-12.
    tau = np.linspace(0, 30, 301)
    np.testing.assert_allclose(
        pitch.psi_numerical(tau, 0.49, 0.0, psi0=0.1), 0.1 * np.cos(0.7 * tau), rtol=0, atol=1e-11
    )


# --------------------------------------------------------------------------------------------
# Tier 2: literature values
# --------------------------------------------------------------------------------------------


def test_transition_curves_match_scipy():
    # A&S 20.2 characteristic values, scipy.special.mathieu_a / mathieu_b (same q convention
    # as eq. 4.2-3: y'' + (a - 2q cos 2t) y = 0); 1e-10 absolute on values O(1..30).
    q = np.linspace(0.0, 10.0, 41)
    curves = mathieu.transition_curves(q, r_max=5)
    for r in range(6):
        assert_close(curves[f"a{r}"], special.mathieu_a(r, q), rtol=0, atol=1e-10,
                     source="scipy.special.mathieu_a (A&S 20.2)", name=f"a{r}(q)")
        if r >= 1:
            assert_close(curves[f"b{r}"], special.mathieu_b(r, q), rtol=0, atol=1e-10,
                         source="scipy.special.mathieu_b (A&S 20.2)", name=f"b{r}(q)")


def test_small_q_characteristic_values():
    # A&S 20.2.25: a_1 = 1 + q - q^2/8 - q^3/64 + ..., b_1 = 1 - q - q^2/8 + q^3/64 + ...,
    # truncation error O(q^4) ~ 1e-8 at q = 0.05.
    q = np.array([0.01, 0.05])
    curves = mathieu.transition_curves(q, r_max=1)
    np.testing.assert_allclose(curves["a1"], 1 + q - q**2 / 8 - q**3 / 64, atol=1e-7)
    np.testing.assert_allclose(curves["b1"], 1 - q - q**2 / 8 + q**3 / 64, atol=1e-7)


def test_reference_points_cover_both_regions():
    # The acceptance asks for points inside and outside the tongues: at least 8 of each.
    imag = np.array([ref[1].imag for ref in REFERENCES.values()])
    assert np.sum(imag > 0) >= 8 and np.sum(imag == 0) >= 8


@pytest.mark.parametrize("method", ["floquet", "hill"])
@pytest.mark.parametrize("point", EXPONENT_POINTS)
def test_exponent_against_mpmath(point, method):
    # Reference: 50-digit mpmath Taylor series of y1(pi) (independent of both methods), band
    # index from scipy's characteristic values (REFERENCES, stored).  cos(pi beta) to 1e-11
    # relative, beta to 1e-8 (no point lies within 1e-4 of a transition curve, where beta
    # has a square-root singularity, so 1e-11 in cos(pi beta) is < 1e-8 in beta).
    a, q = point
    D_ref, beta_ref = REFERENCES[point]
    D = float(mathieu.floquet_discriminant(a, q, method))
    assert abs(D - D_ref) <= 1e-11 * max(1.0, abs(D_ref))
    beta = complex(mathieu.characteristic_exponent(a, q, method))
    assert_close(beta, beta_ref, rtol=0, atol=1e-8, name=f"beta{point}",
                 source="50-digit mpmath Taylor series of y1(pi), scipy band index")
    assert (beta.imag == 0) == (beta_ref.imag == 0)


@pytest.mark.parametrize("r", [1, 2, 3])
@pytest.mark.parametrize("q", [0.05, 0.5, 2.0])
def test_tongue_structure_from_scipy_curves(r, q):
    # Between b_r(q) and a_r(q) (scipy): Re beta = r, Im beta > 0; just outside: real beta
    # within 1e-3 of r (square-root approach); midway to the next curve: r < beta < r + 1.
    b_r, a_r = special.mathieu_b(r, q), special.mathieu_a(r, q)
    inside = mathieu.characteristic_exponent(0.5 * (a_r + b_r), q, "hill")
    assert inside.real == r and inside.imag > 0
    above = mathieu.characteristic_exponent(a_r + 1e-7, q, "hill")
    below = mathieu.characteristic_exponent(b_r - 1e-7, q, "hill")
    assert above.imag == 0 and r < above.real < r + 1e-3
    assert below.imag == 0 and r - 1e-3 < below.real < r
    band = mathieu.characteristic_exponent(0.5 * (a_r + special.mathieu_b(r + 1, q)), q, "floquet")
    assert band.imag == 0 and r < band.real < r + 1


@pytest.mark.parametrize("r", [1, 2, 3, 5])
@pytest.mark.parametrize("gamma", [0.05, 0.4, 0.9])
@pytest.mark.parametrize("zeta", [0.0, 0.02])
def test_tongue_omega_bound_is_above_every_band_edge(r, gamma, zeta):
    # Weyl's inequality (Kato 1966, V.4.3): |b_r(q) - r^2| <= 2|q|, so the upper edge of
    # tongue r on the operating path lies below 2 omega_psi sqrt((1 - zeta^2)(1 + g)) / r;
    # the edges are those solved from scipy-checked transition curves (pitch_band_edges)
    w = 3.7
    bound = pitch.pitch_tongue_omega_bound(w, gamma, tongue=r, damping_ratio=zeta)
    edges = pitch.pitch_band_edges(w, gamma, tongue=r, damping_ratio=zeta)
    if edges is not None:
        assert edges[0] < edges[1] <= bound
    b_r = special.mathieu_b(r, 0.5 * gamma * r * r)  # b_r near the tongue's tip (q ~ g r^2 / 2)
    assert b_r >= r * r - gamma * r * r  # the inequality itself at one point, from scipy


def test_tongues_below_the_range_are_not_solved(monkeypatch):
    # the default booster's pitch (omega_psi = 1.2 rad/s, gamma = 0.05) against Omega >= 5 rad/s:
    # 2 omega_psi sqrt(1 + gamma) = 2.46 rad/s < 5 rad/s, so every
    # tongue lies below the range by the bound, and no edge is solved (no root finder: the
    # run does not import scipy.optimize)
    def refused(*args):
        raise AssertionError("a tongue edge was solved")

    monkeypatch.setattr(mathieu, "tongue_edges", refused)
    assert pitch.pitch_bands(1.2, 0.05, omega_min=5.0, omega_max=2000.0) == ()


@pytest.mark.slow
def test_tongues_past_the_order_limit_are_a_gap_not_a_stable_verdict():
    # omega_psi = 1 rad/s, gamma = 0.9 over Omega in [0.02, 0.03] rad/s: the tongues with
    # tips 2 / r in the range have r = 67..100; every tongue r <= PITCH_MAX_TONGUE = 60 lies
    # above it, so the search ends at its order limit with no band: the result holds one
    # SearchGap from r = 61 on, and the verdict is "not fully searched".
    res = pitch.pitch_analysis(np.linspace(0.02, 0.03, 5), 1.0, 0.9)
    assert res.bands == ()
    (gap,) = res.gaps
    assert (gap.stage, gap.limit, gap.order) == ("pitch", "PITCH_MAX_TONGUE",
                                                 pitch.PITCH_MAX_TONGUE + 1)
    assert gap.Omega_lo == 0.02 and gap.Omega_hi == 0.03
    assert res.verdict.startswith("rigid-body pitch not fully searched: the Mathieu tongues")
    assert "stable" not in res.verdict
    assert res.to_dict()["gaps"] == [gap.to_dict()]
    # the same search without the limit in its way: no gap
    assert pitch.pitch_analysis(np.linspace(0.5, 3.0, 5), 1.0, 0.9).gaps == ()


# --------------------------------------------------------------------------------------------
# Tier 3: invariants, methods agree
# --------------------------------------------------------------------------------------------


def test_floquet_and_hill_agree_on_memo_range_grid():
    # Two independent routes (Magnus-4 + Richardson vs Hill's determinant) on 60 x 40 points
    # of the memo range (4.2-5) and beyond a = 1: beta to 1e-9 (the grid avoids no curve, so
    # points within 1e-6 of b_1 or a_1 are dropped: there beta ~ sqrt(distance)).
    a, q = np.meshgrid(np.linspace(0.01, 1.5, 60), np.linspace(0.001, 0.05, 40))
    near = (np.abs(a - special.mathieu_a(1, q)) < 1e-6) | (
        np.abs(a - special.mathieu_b(1, q)) < 1e-6
    )
    bf = mathieu.characteristic_exponent(a, q, "floquet")
    bh = mathieu.characteristic_exponent(a, q, "hill")
    assert np.max(np.abs(bf - bh)[~near]) < 1e-9


def test_hill_even_and_odd_determinants_are_consistent():
    # 1 - cos(pi beta) (pi-periodic determinant) and 1 + cos(pi beta) (antiperiodic one) are
    # computed independently; they must add to 2 (1e-13 in the memo range).
    a, q = np.meshgrid(np.linspace(-0.5, 1.5, 50), np.linspace(0.0, 0.05, 20))
    one_minus, one_plus, _ = mathieu._hill(a, q)
    assert np.max(np.abs(one_minus + one_plus - 2.0)) < 1e-13


def _slope(x, y):
    return np.polyfit(np.log(x), np.log(y), 1)[0]


@pytest.mark.parametrize("a", [0.1, 0.3, 0.5, 0.7])
def test_memo_formula_error_is_order_q4_and_printed_is_order_q2(a):
    # Erratum E4: with sin(pi sqrt a) eq. (4.2-9) is the small-q expansion
    # nu^2 = a - q^2/(2(a - 1)) + O(q^4) (A&S 20.3.15), so its error against the exact beta
    # (Hill) falls like q^4; as printed (sin(pi sqrt(a)/2)) like q^2.  Slopes on q in
    # [0.05/16, 0.05] within 0.25 of 4 and 2.
    q = 0.05 / 2.0 ** np.arange(5)
    exact = mathieu.characteristic_exponent(a, q, "hill")
    corrected = np.abs(pitch.memo_exponent(a, q) - exact)
    printed = np.abs(pitch.memo_exponent(a, q, printed=True) - exact)
    assert abs(_slope(q, corrected) - 4.0) < 0.25
    assert abs(_slope(q, printed) - 2.0) < 0.25
    assert np.all(corrected < printed)


def test_three_term_psi_error_is_order_q2():
    # The truncation of (4.2-6) drops the Floquet harmonics c_(+-4) ~ q^2; against solve_ivp
    # (DOP853, rtol 1e-12) over 10 periods the error falls like q^2 (slope within 0.2 of 2),
    # and vanishes (< 1e-9) at q = 0.
    q = np.array([0.05, 0.025, 0.0125, 0.00625])
    err = pitch.three_term_error(0.5, q)
    assert abs(_slope(q, err) - 2.0) < 0.2
    assert pitch.three_term_error(0.5, [0.0])[0] < 1e-9


def test_three_term_psi_memo_coefficients():
    # (4.2-7): psi(0) = A1 + A2 + A3 = psi0 and psi'(0) = 0 (cosines); exact beta by default.
    tau = np.array([0.0, 1e-6])
    psi = pitch.psi_three_term(tau, 0.5, 0.05, psi0=0.2)
    assert psi[0] == pytest.approx(0.2, rel=1e-15)
    assert abs(psi[1] - psi[0]) < 1e-12


def test_growth_rate_matches_direct_integration():
    # Inside the first tongue (a = 1, q = 0.05) psi grows like e^(mu tau_1), mu = Im beta;
    # solve_ivp (DOP853, rtol 1e-12) over 60 periods: the log growth per period, fitted over
    # the last 30 periods, equals pi mu to 1e-4 relative.
    a, q = 1.0, 0.05
    mu = complex(mathieu.characteristic_exponent(a, q, "floquet")).imag
    tau = np.pi * np.arange(61)

    def rhs(t, y):
        return [y[1], -(a - 2 * q * np.cos(2 * t)) * y[0]]

    sol = integrate.solve_ivp(
        rhs, (0, tau[-1]), [1.0, 0.0], t_eval=tau, method="DOP853", rtol=1e-12, atol=1e-14
    )
    amp = np.hypot(sol.y[0], sol.y[1])
    rate = np.polyfit(tau[30:], np.log(amp[30:]), 1)[0]
    assert rate == pytest.approx(mu, rel=1e-4)


def test_pitch_analysis_flags_first_tongue():
    # Omega near 2 omega_psi puts a = 1 inside the first tongue (b_1(q) < 1 < a_1(q) for
    # q = gamma/2 = 0.025): unstable with growth rate Im(beta) Omega / 2; Omega = 4 omega_psi
    # (a = 1/4) is stable.
    omega_psi, gamma = 3.0, 0.05
    Omega = np.array([12.0, 6.0])
    res = pitch.pitch_analysis(Omega, omega_psi, gamma)
    assert res.stable.tolist() == [True, False]
    beta = complex(mathieu.characteristic_exponent(1.0, 0.025, "hill"))
    assert res.growth_rate[1] == pytest.approx(beta.imag * 6.0 / 2.0, rel=1e-9)
    assert "UNSTABLE" in res.verdict
    # the exact band over [6, 12]: lower edge (a = a_1) clipped at Omega = 6; upper edge where
    # the path a = 36/Omega^2, q = gamma a / 2 meets b_1(q) = 1 - q - q^2/8 + q^3/64 - q^4/1536
    # (A&S 20.2.25; the q^5 term ~ 1e-10 at q = 0.025, so 1e-9 relative)
    (lo, hi), = res.unstable_intervals()
    assert lo == 6.0
    x = 1.0
    for _ in range(50):  # fixed point of a = b_1(gamma a / 2)
        q = gamma * x / 2.0
        x = 1.0 - q - q**2 / 8.0 + q**3 / 64.0 - q**4 / 1536.0
    assert hi == pytest.approx(2.0 * omega_psi / np.sqrt(x), rel=1e-9)
    assert res.bands[0].order == 1 and res.bands[0].clipped
    data = json.loads(json.dumps(res.to_dict(), allow_nan=False))
    assert data["stable"] == [True, False]
    assert data["max_growth_rate"] == pytest.approx(res.growth_rate[1])


def test_pitch_analysis_stable_default_like_case():
    # Omega well above 2 omega_psi (a < 1/4, q <= 0.05/8): inside the memo range, stable,
    # memo beta within 1e-6 of the exact one (its O(q^4) error).
    res = pitch.pitch_analysis(np.linspace(10.0, 100.0, 30), 2.0, 0.05)
    assert res.all_stable and res.max_growth_rate == 0.0
    assert np.all(res.in_memo_range)
    np.testing.assert_allclose(res.beta_memo_real, res.beta_real, rtol=0, atol=1e-6)
    assert "stable" in res.verdict


@pytest.mark.parametrize(
    ("call", "match"),
    [
        (lambda: mathieu.characteristic_exponent(0.5, 0.1, "exact"), "method"),
        (lambda: mathieu.characteristic_exponent(np.nan, 0.1), "a:"),
        (lambda: mathieu.characteristic_exponent(0.5, np.inf), "q:"),
        (lambda: pitch.memo_exponent(-0.5, 0.1), "a > 0"),
        (lambda: pitch.memo_exponent(1.0, 0.01), "a = 1"),
        (lambda: pitch.mathieu_parameters([0.0, 1.0], 1.0, 0.05), "Omega"),
        (lambda: pitch.mathieu_parameters([1.0], 1.0, -0.05), "gamma"),
        (lambda: pitch.pitch_frequency(1.0, -2.0, 0.5, 1.0), "d2 = -2.0"),
        (lambda: mathieu.transition_curves([-1.0]), "q ="),
        (lambda: pitch.psi_three_term([0.0], 1.0, 0.05), "unstable"),
        (lambda: pitch.psi_numerical([1.0, 0.5], 0.5, 0.01), "tau1"),
    ],
)
def test_bad_input_raises_value_error(call, match):
    with pytest.raises(ValueError, match=match):
        call()


def test_ince_strutt_chart_draws_curves_and_path():
    # The chart's transition curves are those of transition_curves (checked against scipy
    # above) and the operating path is drawn as given; points inside a tongue are marked.
    from matplotlib.figure import Figure

    from flexbooster.memo.charts import InceStruttData
    from flexbooster.present.plotting.pitch import ince_strutt_chart

    a_path = np.array([0.5, 1.0, 1.2])
    q_path = np.array([0.0125, 0.025, 0.03])
    q = np.linspace(0, 0.1, 40)
    stable = np.imag(mathieu.characteristic_exponent(a_path, q_path, "hill")) == 0
    data = InceStruttData(q=q, curves=mathieu.transition_curves(q, 2), a_path=a_path,
                          q_path=q_path, path_stable=stable)
    fig = ince_strutt_chart(data)
    assert isinstance(fig, Figure)
    ax = fig.axes[0]
    lines = {line.get_label(): line for line in ax.get_lines()}
    np.testing.assert_array_equal(lines["operating path"].get_ydata(), a_path)
    np.testing.assert_array_equal(lines["unstable"].get_ydata(), [1.0])  # b_1 < 1 < a_1
    a1 = mathieu.transition_curves(np.linspace(0, 0.1, 40), 2)["a1"]
    assert any(np.allclose(line.get_ydata(), a1) for line in ax.get_lines())


def test_psi_depends_on_sign_of_q_beta_does_not():
    # Replacing q by -q shifts the solution by half a forcing period (tau_1 -> tau_1 + pi/2),
    # so psi changes while beta does not; the three-term form (4.2-7, A1, A3 ~ q) and the
    # direct integration must follow the same sign (error O(q^2) ~ 5e-4 at q = 0.05).
    tau = np.linspace(0.0, 20.0, 201)
    for q in (0.05, -0.05):
        num = pitch.psi_numerical(tau, 0.5, q)
        three = pitch.psi_three_term(tau, 0.5, q)
        assert np.max(np.abs(num - three)) < 2e-3
    diff = pitch.psi_numerical(tau, 0.5, 0.05) - pitch.psi_numerical(tau, 0.5, -0.05)
    assert np.max(np.abs(diff)) > 0.05
