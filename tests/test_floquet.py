"""flexbooster.floquet: monodromy, Hill's method, instability regions (docs/theory/floquet.md).

Tiers: (1) exact limits and closed forms (Mathieu edges from scipy.special, steady propagator,
det = 1), (2) literature / independent models (damped Mathieu threshold of Bolotin, Hsu's
combination resonances, solve_ivp monodromy, brute-force scans), (3) invariants (Hill vs
monodromy, harmonic balance vs monodromy, truncation, range independence), and bad input.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq
from scipy.special import mathieu_a, mathieu_b

import flexbooster.floquet.regions as regions_module
from flexbooster.floquet import (
    converged_periodic_boundaries,
    critical_amplitude,
    floquet_exponents,
    floquet_multipliers,
    golden_section_max,
    growth_rate,
    hill_exponents,
    instability_regions,
    monodromy,
    periodic_boundaries,
    region_boundaries,
    resonance_kinds,
    search_work,
    stability_certificate,
    steady_frequencies,
    step_counts,
)
from flexbooster.floquet.multipliers import half_period_maps, periodic_system
from flexbooster.floquet.regions import (
    _candidates,
    _modal_decay_rates,
    _options,
    _shifted_frequencies,
)
from harness import ivp_growth_rate, ivp_monodromy

ONE = [[1.0]]


def mathieu_edges(mu: float, r: int, qfac: float = 4.0) -> tuple[float, float]:
    """Exact edges in theta of region r of f'' + (1 - 2 mu cos theta t) f = 0.

    x = theta t / 2 maps it to y'' + (a - 2 q cos 2x) y = 0 with a = 4 / theta^2 and
    q = 4 mu / theta^2 (derived here; q = 2 mu / theta^2, qfac = 2, is the map for
    f'' + (1 - mu cos theta t) f = 0 and does not give the reference mu = 0.1 numbers, see
    test_mathieu_mapping); the edges are a = a_r(q), a = b_r(q) (DLMF 28.2(v)).
    """
    c = 2.0 / r
    out = [brentq(lambda th, f=f: 4.0 / th**2 - f(r, qfac * mu / th**2), 0.55 * c, 1.6 * c,
                  xtol=1e-15) for f in (mathieu_a, mathieu_b)]
    return min(out), max(out)


def mathieu(mu: float, eps: float = 0.0):
    """(M, C, A, B) of f'' + 2 eps f' + (1 - 2 mu cos theta t) f = 0."""
    return ONE, [[2.0 * eps]], ONE, [[-2.0 * mu]]


def random_system(n: int, seed: int, damped: bool, scale: float = 0.4):
    """Non-symmetric M, A, B (like a follower force), frequencies near 1, 2, 3, ..."""
    rng = np.random.default_rng(seed)
    M = np.eye(n) + 0.05 * rng.standard_normal((n, n))
    A = np.diag(np.arange(1, n + 1, dtype=float) ** 2) + 0.2 * rng.standard_normal((n, n))
    B = scale * rng.standard_normal((n, n))
    C = 0.05 * np.eye(n) + 0.01 * rng.standard_normal((n, n)) if damped else None
    return M, C, A, B


# --------------------------------------------------------------------------------------------
# Tier 1: exact limits and closed forms
# --------------------------------------------------------------------------------------------
def test_mathieu_mapping():
    # The reference mu = 0.1 -> [1.898848, 2.098688] (6 digits): a = 4/theta^2 with
    # q = 4 mu/theta^2 reproduces it to 1e-6, q = 2 mu/theta^2 misses by 0.05.
    lo, hi = mathieu_edges(0.1, 1)
    assert abs(lo - 1.898848) < 1e-6 and abs(hi - 2.098688) < 1e-6
    lo2, hi2 = mathieu_edges(0.1, 1, qfac=2.0)
    assert abs(lo2 - 1.898848) > 1e-2 and abs(hi2 - 2.098688) > 1e-2


@pytest.mark.parametrize("mu", [0.05, 0.1, 0.2, 0.3, 0.5])
def test_mathieu_principal_region(mu):
    # exact edges: scipy.special.mathieu_a / mathieu_b (mathieu_edges), tolerance 1e-6
    regions = instability_regions(*mathieu(mu), 1.2, 3.2)
    assert [(r.kind, r.order, r.modes) for r in regions] == [("simple", 1, (0,))]
    lo, hi = mathieu_edges(mu, 1)
    assert regions[0].omega_lo == pytest.approx(lo, abs=1e-6)
    assert regions[0].omega_hi == pytest.approx(hi, abs=1e-6)


@pytest.mark.parametrize("mu", [0.1, 0.3])
def test_mathieu_second_region(mu):
    # exact edges a = a_2(q), b_2(q) (scipy.special), theta near 1, tolerance 1e-5
    regions = instability_regions(*mathieu(mu), 0.8, 1.3)
    (r,) = [r for r in regions if r.order == 2]
    lo, hi = mathieu_edges(mu, 2)
    assert (r.omega_lo, r.omega_hi) == pytest.approx((lo, hi), abs=1e-5)


@pytest.mark.parametrize("period,r", [("2T", 1), ("T", 2)], ids=["principal-2T", "second-T"])
def test_harmonic_balance_boundaries_mathieu(period, r):
    # Bolotin ch. 1 harmonic balance, converged with K = 8 harmonics, against the exact edges
    # (scipy.special) to 1e-9
    roots = periodic_boundaries(*mathieu(0.1), period=period, n_harmonics=8)
    lo, hi = mathieu_edges(0.1, r)
    assert np.min(np.abs(roots - lo)) < 1e-9 and np.min(np.abs(roots - hi)) < 1e-9


@pytest.mark.parametrize("period,r", [("2T", 1), ("T", 2), ("2T", 3)],
                         ids=["principal", "second", "third"])
def test_harmonic_balance_raised_until_converged(period, r):
    # harmonics raised until the roots in [0.5, 2.6] settle (rtol 1e-12): the edges of
    # regions 1..3 of Mathieu mu = 0.2 against scipy.special to 1e-9
    roots, K = converged_periodic_boundaries(*mathieu(0.2), period=period, omega_min=0.5,
                                             omega_max=2.6, rtol=1e-12)
    lo, hi = mathieu_edges(0.2, r)
    assert 8 <= K <= 64
    assert np.min(np.abs(roots - lo)) < 1e-9 and np.min(np.abs(roots - hi)) < 1e-9


@pytest.mark.parametrize("seed", [0, 1])
def test_half_period_map_does_not_depend_on_the_batch(seed):
    # a point's Phi(T/2) is the same to the last bit whether it is integrated alone or in a
    # batch of points with other step counts (blocks, shrinking batch, one matmul per stage):
    # the searches rely on it to give the same regions however they group their points;
    # undamped 4 DOF, real and complex modal frames (seed 1: A with negative eigenvalues)
    M, _, A, B = random_system(4, seed, damped=False)
    if seed == 1:
        A = A - 6.0 * np.eye(4)
    system = periodic_system(M, None, A, B)
    om = np.random.default_rng(seed).uniform(0.5, 6.0, 70)
    steps = step_counts(system, om)
    with np.errstate(all="ignore"):
        batch = half_period_maps(system, om, steps)
        alone = [half_period_maps(system, om[i:i + 1], steps[i:i + 1]) for i in range(om.size)]
    assert np.array_equal(batch, np.concatenate(alone), equal_nan=True)


def test_steady_propagator_exact():
    # B = 0: the Lawson scheme propagates the steady system exactly; multipliers
    # exp(+-i omega T) with omega = 1, 2, 3 (closed form) to 1e-12, whatever the step count
    A = np.diag([1.0, 4.0, 9.0])
    Om = np.array([0.7, 1.3, 2.9])
    rho = floquet_multipliers(np.eye(3), None, A, np.zeros((3, 3)), Om, n_steps=8)
    T = 2.0 * np.pi / Om
    expect = np.exp(1j * np.array([1.0, 2.0, 3.0])[None, :] * T[:, None])
    for p in range(Om.size):
        for e in np.concatenate([expect[p], expect[p].conj()]):
            assert np.min(np.abs(rho[p] - e)) < 1e-12
    # exponents: Re = 0 and Im = +-omega modulo Omega (1e-12); Hill (S = 3) gives +-i omega
    lam = floquet_exponents(np.eye(3), None, A, np.zeros((3, 3)), Om, n_steps=8)
    assert np.max(np.abs(lam.real)) < 1e-12
    lam_h = hill_exponents(np.eye(3), None, A, np.zeros((3, 3)), Om, n_harmonics=3)
    for p in range(Om.size):
        for w in (1.0, 2.0, 3.0):
            for sign in (1.0, -1.0):
                d = np.abs(np.angle(np.exp(1j * (lam[p].imag - sign * w) * T[p])))
                assert np.min(d) < 1e-10
                assert np.min(np.abs(lam_h[p] - 1j * sign * w
                                     - 1j * Om[p] * np.round((lam_h[p].imag - sign * w)
                                                             / Om[p]))) < 1e-12


def test_undamped_monodromy_determinant_is_one():
    # Liouville: tr(L(t)) = 0 without damping, so det Phi(T) = 1 (tolerance 1e-10)
    M, _, A, B = random_system(3, 1, damped=False)
    Phi = monodromy(M, None, A, B, [0.9, 2.1, 4.4])
    assert np.linalg.det(Phi) == pytest.approx(np.ones(3), abs=1e-10)


def test_damped_monodromy_determinant_liouville():
    # Liouville: det Phi(T) = exp(-tr(M^-1 C) T) exactly (tolerance 1e-8 relative: the
    # integration error at the default step_phase, measured 6e-10)
    M, C, A, B = random_system(3, 2, damped=True)
    Om = np.array([1.1, 2.5])
    Phi = monodromy(M, C, A, B, Om)
    expect = np.exp(-np.trace(np.linalg.solve(M, C)) * 2.0 * np.pi / Om)
    assert np.linalg.det(Phi) == pytest.approx(expect, rel=1e-8)


# --------------------------------------------------------------------------------------------
# Tier 2: independent models and literature
# --------------------------------------------------------------------------------------------
@pytest.mark.parametrize("mu,eps", [(0.1, 0.0), (0.3, 0.0), (0.1, 0.01)])
def test_growth_rate_against_solve_ivp(mu, eps):
    # theta = 2 (centre of the principal region): growth rate against an independent
    # monodromy (solve_ivp DOP853, rtol 1e-12), tolerance 1e-6 (1/s)
    sysm = mathieu(mu, eps)
    Phi = ivp_monodromy(*sysm, 2.0)
    ref = np.log(np.max(np.abs(np.linalg.eigvals(Phi)))) / np.pi
    assert growth_rate(*sysm, [2.0])[0] == pytest.approx(ref, abs=1e-6)
    assert np.max(np.abs(monodromy(*sysm, [2.0])[0] - Phi)) < 1e-7


def test_monodromy_against_solve_ivp_nonsymmetric():
    # 3 DOF, non-symmetric A and B, with and without damping: monodromy matrix against
    # solve_ivp (rtol 1e-12), tolerance 1e-7 (entries are O(1))
    for damped in (False, True):
        M, C, A, B = random_system(3, 4, damped)
        Phi = monodromy(M, C, A, B, [1.7])[0]
        ref = ivp_monodromy(M, np.zeros((3, 3)) if C is None else C, A, B, 1.7)
        assert np.max(np.abs(Phi - ref)) < 1e-7


def test_monodromy_batch_of_different_step_counts_against_solve_ivp():
    # the modal kernel integrates a batch of points with their own step counts (8..512 here)
    # together, each leaving the batch when its count is done: every map against solve_ivp
    # (rtol 1e-12), 1e-8 of its largest entry (measured 3e-9), and the same map computed
    # alone (one point per call), 1e-13 relative (bookkeeping: no point stored early, late
    # or in the wrong place, across chunks of 4)
    M, C, A, B = random_system(3, 4, False)
    om = np.array([4.0, 0.35, 7.5, 1.7, 0.9, 2.6])
    assert len(set(step_counts(periodic_system(M, C, A, B), om))) == om.size
    Phi = monodromy(M, C, A, B, om, chunk=4)
    for i, o in enumerate(om):
        ref = ivp_monodromy(M, np.zeros((3, 3)), A, B, o)
        assert np.max(np.abs(Phi[i] - ref)) < 1e-8 * np.max(np.abs(ref))
        alone = monodromy(M, C, A, B, [o])[0]
        assert np.max(np.abs(Phi[i] - alone)) <= 1e-13 * np.max(np.abs(alone))


def _exponent_distance(rho, ref, Omega: float) -> float:
    """Largest distance |log(rho / rho_ref)| / T between two sets of multipliers, each to its
    nearest partner both ways (Hausdorff), T = 2 pi / Omega: the error of the characteristic
    exponents (1/time), Im lambda taken modulo Omega."""
    d = np.abs(np.log(np.asarray(rho, complex)[:, None] / np.asarray(ref, complex)[None, :]))
    return float(max(d.min(axis=1).max(), d.min(axis=0).max()) * Omega / (2.0 * np.pi))


@pytest.mark.parametrize("unit", [1e-2, 1.0, 1e2])
@pytest.mark.parametrize("eps", [0.0, 0.01])
def test_damped_mathieu_exponents_against_solve_ivp_in_any_time_unit(eps, unit):
    # f'' + 2 eps w f' + w^2 (1 - 2 mu cos(theta t)) f = 0 with w = unit: the same damped
    # Mathieu equation in another time unit (its exponents scale with w); mu = 0.1 (above
    # Bolotin's threshold mu_cr = 2 eps: theta = 2 is unstable), theta / w = 0.7, 1, 2, 2.1,
    # 4, the default step_phase 0.06.  Every exponent against the independent monodromy of
    # solve_ivp (tests/harness.py, DOP853, rtol 1e-12): |d lambda| <= 1e-9 Omega, damped
    # (eps = 0.01) as undamped (eps = 0) (measured 3.2e-10 for both, in every unit).  The
    # cost model of the damped kernel used to depend on the time unit (a rate divided by a
    # frequency once too often): at w = 100 it took 4x fewer steps and erred by 8e-8 Omega
    w, mu = unit, 0.1
    M, C, A, B = ONE, [[2.0 * eps * w]], [[w * w]], [[-2.0 * mu * w * w]]
    for om in np.array([0.7, 1.0, 2.0, 2.1, 4.0]) * w:
        rho = floquet_multipliers(M, C if eps else None, A, B, [om])[0]
        ref = np.linalg.eigvals(ivp_monodromy(M, C, A, B, om))
        assert _exponent_distance(rho, ref, om) <= 1e-9 * om, om


def test_damped_step_counts_do_not_depend_on_the_time_unit():
    # the cost model is dimensionless: the damped Mathieu system (mu = 0.1, eps = 0.01) in
    # time units where w = 1e-2, 1, 1e2 gets the same step counts at the same theta / w, and
    # as C -> 0 (eps = 1e-9) the damped full-period count is the undamped half-period count
    # x 2 (the same step; +-1 from the rounding of the counts up to 2^(k/2))
    theta = np.array([0.3, 0.7, 1.0, 2.0, 4.0, 9.0])
    counts = [step_counts(periodic_system(ONE, [[0.02 * w]], [[w * w]], [[-0.2 * w * w]]),
                          theta * w) for w in (1e-2, 1.0, 1e2)]
    np.testing.assert_array_equal(counts[0], counts[1])
    np.testing.assert_array_equal(counts[2], counts[1])
    for sysm in (mathieu(0.1), random_system(3, 4, False)):
        M, _, A, B = sysm
        undamped = step_counts(periodic_system(M, None, A, B), theta)
        damped = step_counts(periodic_system(M, 1e-9 * np.eye(len(M)), A, B), theta)
        assert np.all(np.abs(damped - 2 * undamped) <= 1), (damped, undamped)


#: A 3-DOF system (steady frequencies 3, 40, 250 rad/s, M != I, non-symmetric B, damping of
#: ratio ~zeta or none) and its multipliers from the monodromy of solve_ivp (DOP853, rtol
#: 1e-12), stored by tests/data/make_floquet_reference.py, which names the system and method.
THREE_MODES = json.loads((Path(__file__).parent / "data" / "floquet_three_modes.json")
                         .read_text())["systems"]


@pytest.mark.parametrize("stored", THREE_MODES, ids=lambda system: f"zeta={system['zeta']}")
def test_multimode_exponents_against_solve_ivp_damped_as_undamped(stored):
    # THREE_MODES at Omega = 4 (156 steps of the fast mode per period), 43 (sum of modes 1,
    # 2), 80 (2 w2), 250, 500 (2 w3) rad/s, default step_phase 0.06: every exponent against
    # the independent monodromy of solve_ivp (DOP853, rtol 1e-12, stored), |d lambda| <=
    # 5e-9 Omega for the damped system (zeta = 0.01) as for the undamped one (measured:
    # 3.4e-9 Omega at Omega = 4 for both, <= 1e-10 Omega above 40)
    M, C, A, B = (None if stored[x] is None else np.array(stored[x]) for x in "MCAB")
    assert len(stored["multipliers"]) == 5
    for om, ref in stored["multipliers"].items():
        rho = floquet_multipliers(M, C, A, B, [float(om)])[0]
        ref = np.array([complex(*z) for z in ref])
        assert _exponent_distance(rho, ref, float(om)) <= 5e-9 * float(om), om


@pytest.mark.parametrize("eps", [0.005, 0.01])
def test_damped_mathieu_threshold(eps):
    # Bolotin (1964) sec. 6: principal region of f'' + 2 eps f' + (1 - 2 mu cos theta t) f = 0
    # exists only for mu > mu_cr = Delta / pi = 2 eps (Delta = 2 pi eps), to first order
    mu_cr = 2.0 * eps
    above = instability_regions(*mathieu(1.1 * mu_cr, eps), 1.5, 2.5)
    below = instability_regions(*mathieu(0.9 * mu_cr, eps), 1.5, 2.5)
    assert [(r.kind, r.order) for r in above] == [("simple", 1)]
    assert above[0].omega_lo < 2.0 < above[0].omega_hi
    assert below == ()
    (crit,) = critical_amplitude(ONE, [[2.0 * eps]], ONE, [[-2.0]], gamma_max=3.0 * mu_cr,
                                 omega_min=1.5, omega_max=2.5)
    # first-order accuracy: relative error O(eps), asserted < eps (measured ~1e-5)
    assert abs(crit.gamma_cr / mu_cr - 1.0) < eps
    assert crit.omega_cr == pytest.approx(2.0, abs=10 * eps**2)


def test_damped_region_against_harmonic_balance():
    # damped Mathieu mu = 0.1, eps = 0.01: region edges (monodromy, |rho| = 1) against the
    # damped harmonic balance for period 2T (quadratic eigenproblem in Omega, K = 8),
    # tolerance 5e-8 at the search's default step_phase 0.12 (measured 1.6e-8), 1e-8 at 0.06
    sysm = mathieu(0.1, 0.01)
    roots = periodic_boundaries(*sysm, period="2T", n_harmonics=8)
    for step_phase, tol in ((0.12, 5e-8), (0.06, 1e-8)):
        (r,) = instability_regions(*sysm, 1.5, 2.5, step_phase=step_phase)
        assert np.min(np.abs(roots - r.omega_lo)) < tol
        assert np.min(np.abs(roots - r.omega_hi)) < tol


def test_damped_march_stays_inside_the_range():
    # reproducer of the fuzz failure (tests/test_fuzz_reproducers.py _FUZZ_FLOQUET): the damped
    # search marched 4 undamped widths below a wide region and evaluated the monodromy at
    # Omega < 0 (ValueError).  Damped Mathieu mu = 0.8, eps = 0.01 on [1, 3]: the principal
    # region (undamped width ~1.4) and the j = 2 region (unstable down to the range end).
    # Expected: no error; the j = 2 region clipped at omega_min; the unclipped edges on the
    # damped harmonic balance (quadratic eigenproblem, K = 12) to 1e-7 (step_phase 0.12)
    sysm = mathieu(0.8, 0.01)
    regions = instability_regions(*sysm, 1.0, 3.0)
    assert [(r.order, r.clipped) for r in regions] == [(2, True), (1, False)]
    assert regions[0].omega_lo == 1.0
    roots = np.concatenate([periodic_boundaries(*sysm, period=p, n_harmonics=12)
                            for p in ("T", "2T")])
    for edge in (regions[0].omega_hi, regions[1].omega_lo, regions[1].omega_hi):
        assert np.min(np.abs(roots - edge)) < 1e-7 * edge


W1, W2 = 1.0, 2.3


def test_damped_region_wider_than_its_undamped_seed_is_marched_to_its_edges():
    # a sum region of two modes with very unequal damping (C = diag(2 d1, 2 d2), d1 << d2:
    # like the vehicle's nearly undamped rigid pitch against a damped bending mode) is much
    # wider with damping than without: first-order averaging (Hsu 1963) gives the half-width
    # (d1 + d2) sqrt(L / (d1 d2) - 1), L = eps^2 b12 b21 / (16 w1 w2): 0.0653 here against
    # the undamped half-width 0.0066 (the search used to stop its march 4 undamped widths
    # out, at Omega = 3.2407 where the growth rate is still +5.2e-6, and report that as an
    # edge).  Checks: each edge is a |rho|_max = 1 point of an independent monodromy
    # (solve_ivp DOP853, rtol 1e-12): growth < 0 just outside and > 0 just inside, at
    # +-1e-6 relative; the half-width within 1e-2 of Hsu's first order (measured 6e-4); the
    # growth rate at the reported maximum to 1e-6 relative (measured 3e-7)
    eps, d1, d2 = 0.02, 2.5e-5, 0.01
    M, _, A, B = hsu(eps, 1.0, 1.0)
    C = np.diag([2.0 * d1, 2.0 * d2])
    (r,) = instability_regions(M, C, A, B, 2.5, 4.0, max_order=1)
    assert (r.kind, r.modes, r.clipped) == ("sum", (0, 1), False)

    def growth(x):
        return ivp_growth_rate(M, C, A, B, x)

    for edge, inward in ((r.omega_lo, 1.0), (r.omega_hi, -1.0)):
        assert growth(edge * (1.0 - inward * 1e-6)) < 0.0 < growth(edge * (1.0 + inward * 1e-6))
    lam = eps**2 / (16.0 * W1 * W2)
    half = (d1 + d2) * np.sqrt(lam / (d1 * d2) - 1.0)
    assert r.width / 2.0 == pytest.approx(half, rel=1e-2)
    assert r.width > 9.0 * eps / np.sqrt(W1 * W2)  # past the former march limit
    assert r.growth_rate_max == pytest.approx(growth(r.omega_at_max), rel=1e-6)


def hsu(eps: float, b12: float, b21: float):
    """q'' + diag(w1^2, w2^2) q + eps cos(theta t) b q = 0, b with zero diagonal (Hsu 1963)."""
    return np.eye(2), None, np.diag([W1**2, W2**2]), eps * np.array([[0.0, b12], [b21, 0.0]])


@pytest.mark.parametrize("b12,b21,kind,centre", [
    (1.0, 1.0, "sum", W1 + W2),
    (0.5, 2.0, "sum", W1 + W2),
    (1.0, -1.0, "difference", W2 - W1),
    (-0.5, 2.0, "difference", W2 - W1),
], ids=["b12b21>0", "b12b21>0-asym", "b12b21<0", "b12b21<0-asym"])
def test_hsu_combination_type_and_width(b12, b21, kind, centre):
    # Hsu (1963): b12 b21 > 0 -> only a sum-type region near w1 + w2; < 0 -> only a
    # difference-type region near w2 - w1; first-order width eps sqrt(|b12 b21| / (w1 w2)):
    # ratio within 1% at eps = 0.01 (measured 1 - 1e-6) and closer to 1 as eps -> 0
    ratios = []
    for eps in (0.02, 0.01):
        regions = instability_regions(*hsu(eps, b12, b21), 0.5, 4.0, max_order=1)
        comb = [r for r in regions if r.kind in ("sum", "difference")]
        assert [(r.kind, r.modes) for r in comb] == [(kind, (0, 1))]
        assert comb[0].omega_lo < centre < comb[0].omega_hi
        ratios.append(comb[0].width / (eps * np.sqrt(abs(b12 * b21) / (W1 * W2))))
    assert abs(ratios[1] - 1.0) < 0.01
    assert abs(ratios[1] - 1.0) <= abs(ratios[0] - 1.0) + 1e-9


def _scan_edges(fun, lo: float, hi: float, n: int, tol: float) -> tuple[float, float]:
    """Brute force: unstable points on a uniform grid, edges bisected to tol."""
    grid = np.linspace(lo, hi, n)
    bad = fun(grid) > 0.0
    k = np.nonzero(bad)[0]
    assert k.size and not bad[0] and not bad[-1]

    def bisect(a, b):  # fun(a) <= 0 < fun(b) or the reverse
        sa = fun(np.array([a]))[0] > 0.0
        while b - a > tol:
            m = 0.5 * (a + b)
            if (fun(np.array([m]))[0] > 0.0) == sa:
                a = m
            else:
                b = m
        return 0.5 * (a + b)

    return bisect(grid[k[0] - 1], grid[k[0]]), bisect(grid[k[-1]], grid[k[-1] + 1])


@pytest.mark.parametrize("b12,b21", [(1.0, 1.0), (1.0, -1.0)], ids=["sum", "difference"])
def test_hsu_edges_against_bruteforce_scan(b12, b21):
    # exact edges: brute-force scan of log|rho|_max from the eigenvalues of the full monodromy
    # matrix (41 points over 1.6 widths, each bracket bisected), tolerance 1e-8 (the scan
    # threshold 1e-9 on log|rho| moves an edge by ~1e-10 here)
    eps = 0.02
    sysm = hsu(eps, b12, b21)
    regions = instability_regions(*sysm, 0.5, 4.0, max_order=1)
    (r,) = [r for r in regions if r.kind != "simple"]
    w = r.width

    def unstable(x):
        rho = np.linalg.eigvals(monodromy(*sysm, x))
        return np.log(np.max(np.abs(rho), axis=1)) - 1e-9

    lo, hi = _scan_edges(unstable, r.omega_lo - 0.3 * w, r.omega_hi + 0.3 * w, 41, 1e-11)
    assert (r.omega_lo, r.omega_hi) == pytest.approx((lo, hi), abs=1e-8)


def test_canonical_flag_and_resonance_kinds():
    # Krein's theorem needs M, A, B symmetric and M, A positive definite (Yakubovich and
    # Starzhinskii 1975, ch. VI): the symmetric modal systems of a structure under a dead
    # load are canonical, with or without damping; a non-symmetric B (Hsu's b12 b21 < 0), an
    # A with a negative eigenvalue, a non-symmetric M are not; an asymmetry of round-off size
    # (1e-14 of the largest entry) is ignored, one of 1e-9 is not (SYMMETRY_RTOL = 1e-12)
    M, C, A, B = weakly_coupled(3, 0.3, 0.01)
    assert periodic_system(M, None, A, B).canonical and periodic_system(M, C, A, B).canonical
    assert resonance_kinds(M, C, A, B) == ("simple", "sum")
    assert resonance_kinds(*hsu(0.02, 1.0, 1.0)) == ("simple", "sum")
    assert resonance_kinds(*hsu(0.02, 1.0, -1.0)) == ("simple", "sum", "difference")
    assert resonance_kinds(*hsu(0.02, 0.5, 2.0)) == ("simple", "sum", "difference")
    skew = np.zeros((4, 4))
    skew[0, 1], skew[1, 0] = 1.0, -1.0
    big = np.max(np.abs(B))
    assert periodic_system(M, None, A, B + 1e-14 * big * skew).canonical
    assert not periodic_system(M, None, A, B + 1e-9 * big * skew).canonical
    assert not periodic_system(M, None, A - 1.5 * np.eye(4), B).canonical  # w_0^2 = -0.5
    assert not periodic_system(M + 0.1 * np.abs(skew) * np.tri(4), None, A, B).canonical


def _difference_centres(w: np.ndarray, lo: float, hi: float, orders: int) -> np.ndarray:
    """(w_k - w_i) / j for i < k, j = 1..orders, inside [lo, hi]."""
    i, k = np.triu_indices(w.size, 1)
    c = np.concatenate([(w[k] - w[i]) / j for j in range(1, orders + 1)])
    return np.sort(c[(c >= lo) & (c <= hi)])


def test_canonical_system_is_stable_at_its_difference_centres():
    # Krein (1955): at a difference centre (w_k - w_i) / j of a canonical system the colliding
    # multipliers are of the same kind and stay on the unit circle. Independent integration
    # (solve_ivp, DOP853, rtol 1e-12) of the 4-mode symmetric system at gamma = 0.5 (couplings
    # up to an eighth of w_a w_b): at each first-order difference centre in [0.3, 4] |rho|_max
    # = 1 to 1e-8 (the integration's error). The counterpart with one coupling of opposite
    # sign (B non-symmetric, b_01 b_10 < 0) is unstable at its own difference centre w_1 - w_0
    # (Hsu 1963), so the check can fail.
    M, _, A, B = weakly_coupled(3, 0.5, 0.0)
    w = np.sqrt(np.diag(A))
    centres = _difference_centres(w, 0.3, 4.0, 1)
    assert centres.size >= 5
    for c in centres:
        assert abs(ivp_growth_rate(M, 0 * M, A, B, c)) * 2 * np.pi / c < 1e-8
    Bn = B.copy()
    Bn[1, 0] = -Bn[0, 1]
    assert ivp_growth_rate(M, 0 * M, A, Bn, w[1] - w[0]) > 1e-4


def four_modes(gamma: float, zeta: float, w3: float = 4.15):
    """:func:`weakly_coupled` (seed 3) with its last frequency moved to ``w3``: at 4.1 the
    centres 2 w_2 / 3 and (w_1 + w_3) / 3 coincide (2 x 2.9 = 1.7 + 4.1)."""
    M, C, A, B = weakly_coupled(3, gamma, zeta)
    w0 = np.sqrt(np.diag(A))
    w = np.array([w0[0], w0[1], w0[2], w3])
    scale = np.outer(w, w) / np.outer(w0, w0)
    return M, 2 * zeta * np.diag(w), np.diag(w**2), B * scale


def _unstable_outside(M, C, A, B, regions, lo: float, hi: float, n: int) -> np.ndarray:
    """Points of a uniform grid of n over [lo, hi] with growth rate > 1e-9 (the monodromy
    kernel, checked against solve_ivp above) outside every region."""
    grid = np.linspace(lo, hi, n)
    unstable = grid[growth_rate(M, C, A, B, grid) > 1e-9]
    inside = np.zeros(unstable.size, dtype=bool)
    for r in regions:
        inside |= (unstable >= r.omega_lo) & (unstable <= r.omega_hi)
    assert unstable.size
    return unstable[~inside]


@pytest.mark.parametrize("zeta", [0.0, 0.01], ids=["undamped", "damped"])
def test_canonical_search_without_difference_candidates_finds_every_region(zeta):
    # invariant: a canonical system searched without its difference candidates against the
    # same system made non-canonical by an antisymmetric 1e-10 part of B (the full search,
    # every difference candidate examined; asserted by search_work): the same regions (edges
    # within 1e-8 relative), none of them of difference kind; gamma = 0.3, every order, Omega
    # 0.3..9. A region the full search labels "difference" is the one its difference
    # candidate reached first: a sum or simple region of another order, with the same edges.
    # And a brute-force scan over 3,000 points of [0.3, 9]: no unstable point outside the
    # regions.
    M, C, A, B = four_modes(0.3, zeta)
    C = C if zeta else None
    skew = np.zeros((4, 4))
    skew[0, 1], skew[1, 0] = 1.0, -1.0
    Bp = B + 1e-10 * np.max(np.abs(B)) * skew
    assert periodic_system(M, C, A, B).canonical and not periodic_system(M, C, A, Bp).canonical
    fast = search_work(M, C, A, B, 0.3, 9.0)
    full = search_work(M, C, A, Bp, 0.3, 9.0)
    assert full.n_candidates >= fast.n_candidates + 5
    mine = instability_regions(M, C, A, B, 0.3, 9.0)
    ref = instability_regions(M, C, A, Bp, 0.3, 9.0)
    assert len(mine) == len(ref) >= 4
    assert all(r.kind != "difference" for r in mine)
    for a, b in zip(sorted(mine, key=lambda r: r.omega_lo),
                    sorted(ref, key=lambda r: r.omega_lo), strict=True):
        assert (a.omega_lo, a.omega_hi) == pytest.approx((b.omega_lo, b.omega_hi), rel=1e-8)
        assert b.kind == "difference" or (a.kind, a.modes, a.order) == (b.kind, b.modes,
                                                                         b.order)
    assert _unstable_outside(M, C, A, B, mine, 0.3, 9.0, 3000).size == 0


def test_region_of_coincident_centres_shifted_off_them_is_found():
    # 2 w_2 / 3 = (w_1 + w_3) / 3 = 1.9333 at w_3 = 4.1 (coincident centres): the simple j = 3
    # region of mode 2 lies 0.4 % below them at gamma = 0.3, 1.9243-1.9291 (as at w_3 = 4.15,
    # where the centres are apart; unstable at the grid points 1.9245 and 1.9274 by solve_ivp,
    # growth 1.5e-3 and 3.0e-3), outside a window of twice its estimated width. Each of the
    # coincident candidates has the window to the nearest distinct centre: found, and a
    # 3,000-point growth-rate scan finds nothing outside the regions.
    M, _, A, B = four_modes(0.3, 0.0, w3=4.1)
    regions = instability_regions(M, None, A, B, 0.3, 9.0)
    (r,) = [r for r in regions if (r.kind, r.modes, r.order) == ("simple", (2,), 3)]
    assert (r.omega_lo, r.omega_hi) == pytest.approx((1.9243, 1.9291), abs=2e-4)
    assert ivp_growth_rate(M, 0 * M, A, B, 0.5 * (r.omega_lo + r.omega_hi)) > 1e-3
    assert _unstable_outside(M, None, A, B, regions, 0.3, 9.0, 3000).size == 0


#: Two random symmetric systems (w, r; B = gamma r w_a w_b) found by a 4,000-point growth-rate
#: scan of 24 such systems, each with a region moved off its analytic centre by the
#: second-order frequency shifts (numpy default_rng(7); rounded).
SHIFTED_4 = (np.array([1.15874567, 1.76501072, 3.29757899, 3.44300314]),
             np.array([[0.151, 0.075, 0.163, -0.205], [0.075, -0.091, -0.143, 0.098],
                       [0.163, -0.143, 0.181, 0.17], [-0.205, 0.098, 0.17, -0.151]]))
SHIFTED_5 = (np.array([1.20281622, 1.44962297, 1.85163278, 4.36067527, 4.66185759]),
             np.array([[0.052, 0.11, -0.086, -0.057, 0.056], [0.11, -0.017, 0.01, 0.137, -0.192],
                       [-0.086, 0.01, 0.132, 0.154, -0.06], [-0.057, 0.137, 0.154, 0.189, -0.114],
                       [0.056, -0.192, -0.06, -0.114, -0.124]]))


def _shifted_system(system, gamma):
    w, r = system
    return np.eye(w.size), np.diag(w**2), gamma * r * np.outer(w, w)


def test_moved_centre_against_mathieu_third_tongue():
    # one mode, x'' + (1 + b cos Omega t) x = 0: in Mathieu's form (t' = Omega t / 2) a =
    # 4 / Omega^2, q = -2 b / Omega^2, and the third tongue lies between a_3(q) and b_3(q)
    # (scipy.special.mathieu_a/b; a_3(-q) = b_3(q)). Its centre lies 7e-4 (b = 0.1) and
    # 6.6e-3 (b = 0.3) below Omega_c = 2 / 3; the second-order frequency (DLMF 28.15.1,
    # nu^2 = a - q^2 / (2 (a - 1))) after two fixed-point steps puts it within 1e-5 and 4e-4
    # of Omega_c.
    for b, tol in ((0.1, 1e-5), (0.3, 4e-4)):
        edges = [brentq(lambda om, f=f, b=b: 4 / om**2 - f(3, 2 * b / om**2), 0.5, 0.8)
                 for f in (mathieu_a, mathieu_b)]
        centre = 0.5 * sum(edges)
        Oc = np.array([2.0 / 3.0])
        om = Oc
        for _ in range(2):
            om = 2.0 * _shifted_frequencies(np.array([1.0]), np.array([[b]]), np.array([0]),
                                            om, Oc) / 3.0
        assert abs(om[0] - centre) <= tol * Oc[0] < abs(Oc[0] - centre)


def test_region_moved_off_its_window_by_second_order_shifts():
    # SHIFTED_4 at gamma = 0.1: the simple j = 3 region of mode 3 (multipliers at -1) lies at
    # about 2.2887-2.2911, 0.2 % below its centre 2 w_3 / 3 = 2.2953 (growth 1.4e-3 1/s,
    # unstable by solve_ivp below), beyond the window about the centre (0.45 x 0.0056 on either
    # side: the next centre, (w_0 + w_3) / 2 = 2.3009). The second window reaches to the centre
    # moved by the second-order shifts (2.280: it overshoots, a difference centre w_3 - w_0 =
    # 2.284 is nearly resonant). A 4,000-point scan finds nothing outside the regions.
    M, A, B = _shifted_system(SHIFTED_4, 0.1)
    assert ivp_growth_rate(M, 0 * M, A, B, 2.2903) > 1e-3
    regions = instability_regions(M, None, A, B, 0.5, 7.6)
    (r,) = [q for q in regions if (q.kind, q.modes, q.order) == ("simple", (3,), 3)]
    assert r.omega_lo < 2.2903 < r.omega_hi and r.omega_hi < 2 * SHIFTED_4[0][3] / 3
    assert _unstable_outside(M, None, A, B, regions, 0.5, 7.6, 4000).size == 0


def test_principal_region_moved_off_its_window_by_second_order_shifts():
    # SHIFTED_5 at gamma = 0.1: the principal region of mode 1 lies at about 2.8910-2.8922,
    # 0.28 % below 2 w_1 = 2.8992, farther than twice its first-order width (|B11| / w_1 =
    # 0.0025) below. Its own first-order term is resonant and left out of the shift; the others
    # move the centre to 2.893, and the second window holds the region: unstable by solve_ivp,
    # and a 2,001-point scan of 2.88-2.90 finds nothing outside the regions.
    M, A, B = _shifted_system(SHIFTED_5, 0.1)
    regions = instability_regions(M, None, A, B, 0.5, 10.3)
    (r,) = [q for q in regions if (q.kind, q.modes, q.order) == ("simple", (1,), 1)
            and q.omega_hi < 2 * SHIFTED_5[0][1]]  # its part above: the test below
    assert r.omega_hi < 2 * SHIFTED_5[0][1] - 2 * abs(B[1, 1]) / SHIFTED_5[0][1]
    assert ivp_growth_rate(M, 0 * M, A, B, 0.5 * (r.omega_lo + r.omega_hi)) > 2e-4
    assert _unstable_outside(M, None, A, B, regions, 2.88, 2.90, 2001).size == 0


@pytest.mark.parametrize("system,mode,gamma", [(SHIFTED_4, 0, 0.2), (SHIFTED_4, 0, 0.3),
                                               (SHIFTED_5, 1, 0.1), (SHIFTED_5, 1, 0.2),
                                               (SHIFTED_5, 1, 0.3)],
                         ids=["4-modes-0.2", "4-modes-0.3", "5-modes-0.1", "5-modes-0.2",
                              "5-modes-0.3"])
def test_principal_region_split_by_a_near_resonance(system, mode, gamma):
    # The principal region of mode i lies in two parts, one on either side of w_3 - w_i (a
    # pole of its second-order frequency: mode 3 resonates with mode i there; SHIFTED_4:
    # 2.2843, SHIFTED_5: 2.9111, where four multipliers are near -1 at once). Both parts are
    # found, each unstable by solve_ivp at its middle (growth >= 1.7e-4 1/s there), and a
    # 4,001-point scan of 2 w_i (1 +- 5 %) finds no unstable point outside the regions. The
    # search by the analytic and moved centres alone found one part only (the other, e.g.
    # 2.9127-2.9139 for SHIFTED_5 at gamma = 0.1, lay beyond every window).
    M, A, B = _shifted_system(system, gamma)
    w = system[0]
    pole = w[3] - w[mode]
    regions = instability_regions(M, None, A, B, 0.5, 2.2 * w[-1])
    parts = sorted((q for q in regions if (q.kind, q.modes, q.order) == ("simple", (mode,), 1)),
                   key=lambda q: q.omega_lo)
    assert len(parts) == 2 and parts[0].omega_lo < pole < parts[1].omega_lo
    for q in parts:
        assert ivp_growth_rate(M, 0 * M, A, B, 0.5 * (q.omega_lo + q.omega_hi)) > 1e-4
    assert _unstable_outside(M, None, A, B, regions, 1.9 * w[mode], 2.1 * w[mode],
                             4001).size == 0


#: A random symmetric system (w, r; B = gamma r w_a w_b; numpy default_rng(7), rounded) whose
#: modes 2 and 3 are nearly degenerate (w within 0.05 %).
DEGENERATE_4 = (np.array([2.68097049, 2.89468805, 4.31031699, 4.31219567]),
                np.array([[0.134, -0.085, -0.142, -0.098], [-0.085, -0.092, 0.11, 0.113],
                          [-0.142, 0.11, 0.159, -0.077], [-0.098, 0.113, -0.077, 0.072]]))


def test_combination_region_with_a_nearly_degenerate_partner():
    # DEGENERATE_4 at gamma = 0.3: the sum (0, 2) and (0, 3) j = 2 centres lie 1e-3 apart,
    # within each other's estimated width (7e-3), and two s-values sit near p_2 = p_3. The pair
    # indicator that takes the s nearest to each prediction followed the wrong one and missed
    # the region at 3.4921-3.4959 (growth 1.9e-3 1/s by solve_ivp at 3.494) and one at
    # 3.6005-3.6013 (4.1e-4 at 3.6009). Both are found, and a 4,001-point scan of 3.45..3.65
    # finds no unstable point outside the regions.
    M, A, B = _shifted_system(DEGENERATE_4, 0.3)
    regions = instability_regions(M, None, A, B, 0.5, 2.2 * DEGENERATE_4[0][-1])
    for omega, growth in ((3.494, 1.5e-3), (3.6009, 3e-4)):
        assert ivp_growth_rate(M, 0 * M, A, B, omega) > growth
        assert any(q.omega_lo < omega < q.omega_hi for q in regions)
    assert _unstable_outside(M, None, A, B, regions, 3.45, 3.65, 4001).size == 0


#: Random symmetric systems (as DEGENERATE_4: default_rng(7) of
#: scripts/region_search_survey.py, its systems 12 and 28, rounded) with a combination region
#: where another mode's prediction p = 2 cos(2 pi w / Omega) meets one of the pair's.
COINCIDENT_5 = (np.array([1.40439587, 1.53488476, 2.52233905, 3.62897565, 3.64978489]),
                np.array([[0.165, -0.094, -0.012, -0.082, -0.12],
                          [-0.094, -0.085, -0.061, -0.197, 0.146],
                          [-0.012, -0.061, -0.211, -0.039, -0.062],
                          [-0.082, -0.197, -0.039, 0.203, -0.136],
                          [-0.12, 0.146, -0.062, -0.136, -0.033]]))
COINCIDENT_4 = (np.array([1.73708892, 2.21567212, 2.7900629, 4.71198631]),
                np.array([[-0.111, 0.075, -0.044, 0.03], [0.075, -0.248, 0.147, 0.046],
                          [-0.044, 0.147, 0.093, -0.13], [0.03, 0.046, -0.13, 0.101]]))


@pytest.mark.parametrize("system,omega", [(COINCIDENT_5, 2.0626), (DEGENERATE_4, 2.3293),
                                          (COINCIDENT_4, 2.4966)],
                         ids=["5-modes", "degenerate-4", "4-modes"])
def test_combination_region_where_another_mode_shares_a_prediction(system, omega):
    # gamma = 0.3. Each system is unstable at omega (growth >= 1.9e-4 1/s by solve_ivp), in a
    # region of a combination candidate (i, k) whose pair indicator, taking the s nearest to
    # p_i and to p_k, pairs a wrong s there: COINCIDENT_4, another mode's prediction meets
    # p_1 (w_3 - w_1 = 2.4963, 0.8 estimated widths below the sum (1, 2) j = 2 at 2.5029);
    # the other two, j = 3 regions moved 5 and 14 estimated widths off their centres, whose
    # complex pair (s, conj s) sits at one prediction while the real s nearest the other
    # prediction is another mode's. The search missed all three (no region within 5e-3 of
    # omega); a candidate that finds nothing is searched again with those s-values paired as
    # well (the second pass of the search). A 2,001-point scan of omega +- 5e-3 finds no
    # unstable point outside the regions.
    M, A, B = _shifted_system(system, 0.3)
    assert ivp_growth_rate(M, 0 * M, A, B, omega) > 1.5e-4
    regions = instability_regions(M, None, A, B, 0.5, 2.2 * system[0][-1])
    assert any(q.omega_lo < omega < q.omega_hi for q in regions)
    assert _unstable_outside(M, None, A, B, regions, omega - 5e-3, omega + 5e-3,
                             2001).size == 0


#: A random symmetric system with two close modes (w, r as DEGENERATE_4; default_rng(11) of
#: scripts/region_search_survey.py, its system 5, rounded).
CLUSTER_4 = (np.array([1.57448577, 1.5989407, 3.50452063, 4.71001039]),
             np.array([[-0.028, -0.045, 0.01, 0.157], [-0.045, -0.07, -0.148, 0.159],
                       [0.01, -0.148, -0.071, -0.195], [0.157, 0.159, -0.195, -0.001]]))


@pytest.mark.parametrize("zeta,growth", [(0.0, 1e-2), (0.005, 8e-4)], ids=["undamped", "damped"])
def test_second_region_in_the_window_of_a_cluster_candidate(zeta, growth):
    # gamma = 0.3, C = 2 zeta diag(w). Modes 0 and 1 are 1.5 % apart: the window of the simple
    # j = 1 candidate of mode 1 (centre 3.198, +- 0.067) holds the regions 3.1418-3.1522 (sum
    # (0, 3) j = 2), 3.1902-3.1940 (sum (0, 1)) and its own, moved to 3.2028-3.2370, the
    # strongest (growth 1.04e-2 1/s undamped, 8.7e-4 with zeta = 0.005, by solve_ivp at 3.22).
    # Its indicator (the s nearest its prediction, which changes with Omega in the cluster) is
    # positive in more than one of them, and the maximisation stops at the first: without the
    # search of the rest of the window the region is missed (489 of the scan's 594 unstable
    # points outside undamped, all 197 damped). A 2,001-point scan of 3.15-3.29 finds no
    # unstable point outside the regions.
    w, r = CLUSTER_4
    M, A, B = _shifted_system(CLUSTER_4, 0.3)
    C = np.diag(2.0 * zeta * w) if zeta else None
    assert ivp_growth_rate(M, 0 * M if C is None else C, A, B, 3.22) > growth
    regions = instability_regions(M, C, A, B, 0.5, 2.2 * w[-1])
    assert any(q.omega_lo < 3.22 < q.omega_hi for q in regions)
    assert _unstable_outside(M, C, A, B, regions, 3.15, 3.29, 2001).size == 0


#: Random symmetric systems with modal damping (w, r as DEGENERATE_4; numpy default_rng(8)
#: and (9), the 15th and 12th systems drawn as scripts/region_search_survey.py draws them,
#: rounded), each with two pairs of close modes.
DAMPED_4 = (np.array([2.74640804, 2.75900998, 3.92802488, 3.95733192]),
            np.array([[0.129, -0.021, -0.031, 0.082], [-0.021, 0.121, 0.083, -0.128],
                      [-0.031, 0.083, -0.118, 0.03], [0.082, -0.128, 0.03, 0.041]]))
DAMPED_5 = (np.array([2.22720348, 2.74701391, 3.13206557, 3.15996801, 4.12509992]),
            np.array([[0.248, 0.005, -0.013, -0.076, 0.118],
                      [0.005, -0.208, -0.06, -0.085, -0.222],
                      [-0.013, -0.06, -0.134, -0.053, 0.061],
                      [-0.076, -0.085, -0.053, 0.002, 0.016],
                      [0.118, -0.222, 0.061, 0.016, -0.083]]))
# seed 7, system 3 of scripts/region_search_survey.py, w to 8 and r to 3 decimals
DAMPED_INTERNAL = (np.array([1.52646326, 3.64885895, 4.38029728, 4.4963081]),
                   np.array([[0.222, 0.024, 0.113, -0.111], [0.024, 0.214, 0.048, -0.145],
                             [0.113, 0.048, 0.035, -0.146], [-0.111, -0.145, -0.146, 0.188]]))


@pytest.mark.parametrize("system,gamma,zeta,omega,span", [
    (DAMPED_4, 0.1, 0.002, 6.6845, (6.66, 6.70)), (DAMPED_5, 0.3, 0.01, 6.265, (6.2, 6.33)),
    (DAMPED_INTERNAL, 0.3, 0.002, 2.984, (2.95, 3.02))],
    ids=["two-damped-regions-in-one-seed", "damped-region-beside-its-seed",
         "order-3-through-an-internal-resonance"])
def test_damped_region_inside_overlapping_undamped_regions(system, gamma, zeta, omega, span):
    # C = 2 zeta diag(w). DAMPED_4: the undamped sum regions of (0, 2), (0, 3), (1, 2) and
    # (1, 3) overlap in one, 6.663-6.741; with damping two regions remain, 6.6807-6.6886
    # (growth 3.7e-4 1/s) and 6.6923-6.7372, both inside the seed of the sum (1, 2), whose
    # nine samples are positive in both: the march from the largest found the second only.
    # DAMPED_5: the undamped simple regions of the close modes 2 and 3 overlap in one,
    # 6.197-6.399, but the seeds (each candidate's own pair, 6.298-6.327) do not reach the
    # damped region 6.239-6.290 (growth 2.6e-3 1/s). Now every positive sample outside the
    # regions found starts a march, and a seed spans the overlapping regions (the whole
    # system's indicator beyond its own edges). Unstable by solve_ivp at omega; a 2,001-point
    # scan of the span finds no unstable point outside the regions (both missed before: 396
    # and 826 of the scan's unstable points outside).
    # DAMPED_INTERNAL: the simple j = 3 region of mode 3 (centre 2 w_3 / 3 = 2.9975; damped
    # 2.978-2.989, growth 3e-3 1/s) has an undamped growth of 9.7e-3 1/s, 30 times the damping
    # filter's path estimate: its chain passes nu = w_3 - Omega = 1.499 beside w_0 = 1.526 (a
    # small denominator, a_1 = a_2 = 28). The filter without the small-denominator factors
    # leaves it out (312 of the scan's unstable points outside).
    w, r = system
    M, A, B = _shifted_system(system, gamma)
    C = np.diag(2.0 * zeta * w)
    assert ivp_growth_rate(M, C, A, B, omega) > 3e-4
    regions = instability_regions(M, C, A, B, 0.5, 2.2 * w[-1])
    assert any(q.omega_lo < omega < q.omega_hi for q in regions)
    assert _unstable_outside(M, C, A, B, regions, *span, 2001).size == 0


def test_search_work_counts_the_second_windows(monkeypatch):
    # the estimate's candidates and step counts are those the search integrates in its first
    # pass, second windows included, and every second window lies inside the searched range
    # (SHIFTED_4, gamma = 0.1, on 2.285..3.0: the second window of the simple j = 3 region of
    # mode 3 is clipped at 2.285, above the moved centre 2.280). The second pass (combination
    # candidates that found nothing, searched again with more s-values paired; here one of 9)
    # is counted apart, for every candidate it may search
    M, A, B = _shifted_system(SHIFTED_4, 0.1)
    seen = []
    original = regions_module._batched_search

    def counting(system, w, cand, lo, hi, opt, seeds):
        seen.append(cand)
        return original(system, w, cand, lo, hi, opt, seeds)

    monkeypatch.setattr(regions_module, "_batched_search", counting)
    found = instability_regions(M, None, A, B, 2.285, 3.0)
    first, *again = seen
    assert len(again) == 1 and again[0]["centre"].size == 1 and again[0]["kind"][0] != 0
    middle, half, shifted = first["middle"], first["half"], first["shifted"]
    work = search_work(M, None, A, B, 2.285, 3.0)
    assert work.n_candidates == middle.size and np.count_nonzero(shifted) >= 1
    # the second pass searches only candidates counted as its own (an upper bound)
    assert again[0]["centre"].size <= work.n_retry
    assert int(np.sum(step_counts(periodic_system(M, None, A, B), again[0]["middle"],
                                  step_phase=0.12))) <= work.retry_steps
    assert work.undamped_steps == int(np.sum(step_counts(periodic_system(M, None, A, B), middle,
                                                         step_phase=0.12)))
    assert np.all(middle[shifted] - half[shifted] >= 2.285 * (1 - 1e-12))
    assert np.all(middle[shifted] + half[shifted] <= 3.0 * (1 + 1e-12))
    assert any((q.kind, q.modes, q.order) == ("simple", (3,), 3) for q in found)


def test_damped_combination_against_exact_shift():
    # C = 2 eps I: q = exp(-eps t) p maps the system exactly onto the undamped one with
    # A - eps^2 I, so the damped sum-region edges are where that system's growth rate equals
    # eps (brentq on the undamped modal kernel; the damped search uses the dense kernel):
    # tolerance 1e-8
    eps_d = 0.002
    M, _, A, B = hsu(0.05, 1.0, 1.0)
    (r,) = instability_regions(M, 2 * eps_d * np.eye(2), A, B, 2.5, 4.0, max_order=1)
    assert r.kind == "sum"

    def excess(x):
        return growth_rate(M, None, A - eps_d**2 * np.eye(2), B, [x])[0] - eps_d

    lo = brentq(excess, r.omega_lo - 1e-3, r.omega_center, xtol=1e-13)
    hi = brentq(excess, r.omega_center, r.omega_hi + 1e-3, xtol=1e-13)
    assert (r.omega_lo, r.omega_hi) == pytest.approx((lo, hi), abs=1e-8)
    # critical coupling: growth (gamma / 4) sqrt(b12 b21 / (w1 w2)) = eps (Hsu 1963 first
    # order with the shift above): gamma_cr = 4 eps sqrt(w1 w2 / (b12 b21)), rel. tol 1e-4
    (c,) = critical_amplitude(M, 2 * eps_d * np.eye(2), A, B / 0.05, gamma_max=0.05,
                              omega_min=2.5, omega_max=4.0, max_order=1)
    assert c.gamma_cr == pytest.approx(4 * eps_d * np.sqrt(W1 * W2), rel=1e-4)


def test_damped_combination_with_an_undamped_mode_has_a_zero_tip():
    # mode 1 undamped, mode 2 damped (C = diag(0, 2 eps)): the first-order threshold of the sum
    # region is c^2 b12 b21 / (16 w1 w2) > delta_1 delta_2 = 0 (Hsu 1963), so the region holds
    # down to gamma = 0 and its tip is reported within gamma_rtol x gamma_max of 0; with mode 1
    # damped as well (delta_1 = delta_2 = eps) the tip is the closed form 4 eps
    # sqrt(w1 w2 / (b12 b21)) of the test above (rel. 1e-4): the probe at gamma_rtol does not
    # stop there
    eps_d = 0.002
    M, _, A, B = hsu(0.05, 1.0, 1.0)
    opts = dict(gamma_max=0.05, omega_min=2.5, omega_max=4.0, max_order=1, gamma_rtol=1e-6)
    (c,) = critical_amplitude(M, np.diag([0.0, 2 * eps_d]), A, B / 0.05, **opts)
    assert c.kind == "sum" and 0.0 <= c.gamma_cr <= 1e-6 * 0.05
    (c,) = critical_amplitude(M, 2 * eps_d * np.eye(2), A, B / 0.05, **opts)
    assert c.gamma_cr == pytest.approx(4 * eps_d * np.sqrt(W1 * W2), rel=1e-4)


def test_region_boundaries_hsu_width_linear_in_gamma():
    # Hsu (1963): the sum region widens like gamma sqrt(b12 b21 / (w1 w2)) from its centre
    # w1 + w2 at gamma = 0; traced widths / gamma within 0.1% of it for gamma <= 0.02
    M, _, A, _ = hsu(1.0, 1.0, 1.0)
    (rb,) = region_boundaries(M, None, A, np.array([[0.0, 1.0], [1.0, 0.0]]), gamma_max=0.02,
                              omega_min=2.5, omega_max=4.0, max_order=1, n_gamma=3)
    assert rb.kind == "sum" and rb.omega_lo[0] == rb.omega_hi[0] == W1 + W2
    ratio = (rb.omega_hi[1:] - rb.omega_lo[1:]) / rb.gamma[1:] / np.sqrt(1.0 / (W1 * W2))
    assert np.all(np.abs(ratio - 1.0) < 1e-3)


# --------------------------------------------------------------------------------------------
# Tier 3: invariants
# --------------------------------------------------------------------------------------------
@pytest.mark.parametrize("damped", [False, True], ids=["undamped", "damped"])
def test_hill_agrees_with_monodromy(damped):
    # two methods: Hill's determinant (S = 16) and the monodromy, 3 DOF non-symmetric,
    # growth rates on 6 points (stable and unstable), tolerance 1e-8 (1/s)
    M, C, A, B = random_system(3, 7, damped)
    Om = np.array([0.6, 1.0, 1.9, 2.6, 4.1, 6.0])
    g_m = growth_rate(M, C, A, B, Om)
    lam = hill_exponents(M, C, A, B, Om, n_harmonics=16)
    g_h = np.max(lam.real, axis=-1)
    assert np.max(np.abs(g_m - g_h)) < 1e-8
    assert lam.shape == (6, 6)


def test_harmonic_balance_converges_with_harmonics():
    # truncation: the principal and second boundaries do not move (1e-12) from K = 8 to 12
    for period in ("2T", "T"):
        r8 = periodic_boundaries(*mathieu(0.2), period=period, n_harmonics=8)
        r12 = periodic_boundaries(*mathieu(0.2), period=period, n_harmonics=12)
        top8, top12 = r8[-2:], r12[-2:]
        assert np.max(np.abs(top8 - top12)) < 1e-12


@pytest.mark.slow
def test_regions_unchanged_under_truncation_and_accuracy():
    # strongly coupled 3-DOF system (overlapping regions): every interval found with orders
    # j <= 3 is found again, edges to 1e-8 relative, when orders up to 5 are examined and when
    # the integration is refined (step_phase 0.12 (the default) -> 0.03)
    M, _, A, B = random_system(3, 11, damped=False)
    base = instability_regions(M, None, A, B, 1.0, 7.0, max_order=3)
    more = instability_regions(M, None, A, B, 1.0, 7.0, max_order=5)
    fine = instability_regions(M, None, A, B, 1.0, 7.0, max_order=3, step_phase=0.03)
    assert len(base) >= 8
    for other in (more, fine):
        edges = np.array([(r.omega_lo, r.omega_hi) for r in other])
        for r in base:
            d = np.max(np.abs(edges - [r.omega_lo, r.omega_hi]), axis=1)
            assert np.min(d) < 1e-8 * r.omega_hi, r


@pytest.mark.slow
def test_regions_are_unstable_inside_and_bounded_by_unit_multipliers():
    # invariant on the same system: growth rate > 0 at 9 interior points of every region, and
    # just outside each edge (1e-7 relative) the point is stable unless another region covers
    # it; the union of the regions equals the unstable set of a 4000-point scan except
    # within 1e-3 of an edge (brute force, grid spacing 1.5e-3)
    M, _, A, B = random_system(3, 11, damped=False)
    regions = instability_regions(M, None, A, B, 1.0, 7.0, max_order=4)
    iv = np.array([(r.omega_lo, r.omega_hi) for r in regions])

    def covered(x):
        return np.any((x[:, None] > iv[None, :, 0]) & (x[:, None] < iv[None, :, 1]), axis=1)

    for r in regions:
        inner = np.linspace(r.omega_lo, r.omega_hi, 11)[1:-1]
        assert np.all(growth_rate(M, None, A, B, inner) > 0.0), r
    out = np.concatenate([iv[:, 0] * (1 - 1e-7), iv[:, 1] * (1 + 1e-7)])
    out = out[~covered(out) & (out > 1.0) & (out < 7.0)]
    assert np.all(growth_rate(M, None, A, B, out) < 1e-9)
    grid = np.linspace(1.0, 7.0, 4000)
    unstable = growth_rate(M, None, A, B, grid) > 1e-9
    near = np.min(np.abs(grid[:, None] - iv.ravel()[None, :]), axis=1) < 1e-3
    assert np.array_equal(unstable[~near], covered(grid)[~near])


def test_regions_match_harmonic_balance_multidof():
    # simple-region edges from the monodromy against the T / 2T harmonic balance (K = 10) for
    # a weakly coupled 3-DOF non-symmetric system (separate regions), principal (j = 1) and
    # second (j = 2) regions, tolerance 1e-8
    M, _, A, B = random_system(3, 11, damped=False, scale=0.1)
    regions = instability_regions(M, None, A, B, 1.0, 7.0, max_order=2)
    hb = {1: periodic_boundaries(M, None, A, B, period="2T", n_harmonics=10),
          2: periodic_boundaries(M, None, A, B, period="T", n_harmonics=10)}
    simple = [r for r in regions if r.kind == "simple" and not r.clipped]
    assert len(simple) >= 3
    for r in simple:
        roots = hb[r.order]
        assert np.min(np.abs(roots - r.omega_lo)) < 1e-8
        assert np.min(np.abs(roots - r.omega_hi)) < 1e-8


@pytest.mark.parametrize("omega_min,omega_max", [(1.99, 2.01), (0.2, 20.0), (0.05, 60.0)])
def test_narrow_region_found_in_wide_range(omega_min, omega_max):
    # a 1e-4-wide principal region (Mathieu mu = 5e-5: width 2 mu theta-units = 1e-4) is found
    # whatever the range (no user grid): edges equal in all ranges to 1e-10 and against
    # scipy.special to 1e-9
    mu = 5e-5
    regions = instability_regions(*mathieu(mu), omega_min, omega_max)
    (r,) = [r for r in regions if r.order == 1]
    lo, hi = mathieu_edges(mu, 1)
    assert r.width == pytest.approx(1e-4, rel=1e-3)
    assert (r.omega_lo, r.omega_hi) == pytest.approx((lo, hi), abs=1e-9)


def test_narrow_combination_region_two_modes_wide_range():
    # a ~1e-4-wide sum region of Hsu's system (eps = 3.03e-4) found with a 100x wider range
    eps = 1e-4 / np.sqrt(1.0 / (W1 * W2))
    regions = instability_regions(*hsu(eps, 1.0, 1.0), 0.1, 10.0)
    (r,) = [r for r in regions if r.kind == "sum" and r.order == 1]
    assert r.width == pytest.approx(1e-4, rel=1e-3)  # Hsu first-order width, small-eps limit


def mathieu_series_width(mu: float, r: int) -> float:
    """Width in theta of region r of f'' + (1 - 2 mu cos theta t) f = 0 at small mu.

    a_r - b_r = 2^(3 - 2r) q^r / ((r - 1)!)^2 (1 + O(q^2)) (Abramowitz & Stegun 20.2.25,
    McLachlan 1947 sec. 2.151; checked against the exact r = 1, 2, 3 expansions 2q, q^2/2,
    q^3/32), with a = 4 / theta^2, q = 4 mu / theta^2 = mu r^2 at theta = 2 / r and
    d theta = theta da / (2a).
    """
    import math

    theta, a, q = 2.0 / r, float(r * r), mu * r * r
    return theta / (2.0 * a) * 2.0 ** (3 - 2 * r) * q**r / math.factorial(r - 1) ** 2


@pytest.mark.parametrize("mu,r", [(1e-3, 3), (1e-3, 4), (3e-3, 4), (3e-3, 5)],
                         ids=["r3-w1e-9", "r4-w2e-12", "r4-w1e-10", "r5-w6e-13"])
@pytest.mark.parametrize("omega_min,omega_max", [(0.05, 60.0), (0.3, 3.0)],
                         ids=["range-0.05-60", "range-0.3-3"])
def test_narrow_mathieu_regions_found_below_the_monodromy_floor(mu, r, omega_min, omega_max):
    # regions of relative width 1e-9 .. 6e-13, below the monodromy indicators' round-off floor
    # (6e-8 / j), found with any range (no user grid) by the harmonic-balance pair of
    # floquet/narrow.py.  Edges: scipy.special mathieu_a / mathieu_b (DLMF 28.2(v)), 1e-9
    # relative (measured 1e-15); width: the small-q series (A&S 20.2.25), 3 % (its O(q^2)
    # remainder: q <= 0.075; measured 2e-4); growth rate: Hill's method (S = 12) at the
    # vertex, 1e-3 relative
    regions = instability_regions(*mathieu(mu), omega_min, omega_max)
    (reg,) = [q for q in regions if q.order == r]
    assert reg.kind == "simple" and not reg.clipped
    lo, hi = mathieu_edges(mu, r)
    assert reg.omega_lo == pytest.approx(lo, rel=1e-9)
    assert reg.omega_hi == pytest.approx(hi, rel=1e-9)
    assert reg.width == pytest.approx(mathieu_series_width(mu, r), rel=0.03)
    g = np.max(hill_exponents(*mathieu(mu), [reg.omega_at_max], n_harmonics=12).real)
    assert reg.growth_rate_max == pytest.approx(g, rel=1e-3)


def test_narrow_combination_region_of_order_two():
    # Hsu (1963) system with a full coupling b = eps [[1, 1], [1, 1]]: the sum resonance of
    # order 2 at (w1 + w2) / 2 has a width c2 eps^2 (1 + O(eps^2)) (second order in the
    # coupling).  c2 from the monodromy search at eps = 0.02 (width 8e-5, edges to 1e-9);
    # at eps = 2e-4 and 2e-5 (relative widths 8e-9, 8e-11: below the monodromy floor) the
    # region is found over [0.1, 10] with width c2 eps^2 to 1e-3 (O(eps_ref^2) remainder,
    # measured 5e-5) and its growth rate equals Hill's (S = 12) at the vertex to 1e-3
    def system(eps):
        return np.eye(2), None, np.diag([W1**2, W2**2]), eps * np.ones((2, 2))

    def sum2(eps):
        (reg,) = [q for q in instability_regions(*system(eps), 0.1, 10.0)
                  if q.kind == "sum" and q.order == 2]
        return reg

    c2 = sum2(0.02).width / 0.02**2
    for eps in (2e-4, 2e-5):
        reg = sum2(eps)
        assert reg.modes == (0, 1)
        assert reg.width / reg.omega_center < 1e-8
        assert reg.width / eps**2 == pytest.approx(c2, rel=1e-3)
        g = np.max(hill_exponents(*system(eps), [reg.omega_at_max], n_harmonics=12).real)
        assert reg.growth_rate_max == pytest.approx(g, rel=1e-3)


def _damped_mathieu_tip(eps: float) -> float:
    """mu_cr of f'' + 2 eps f' + (1 - 2 mu cos theta t) f = 0, principal region.  The exact
    shift f = exp(-eps t) p gives p'' + (1 - eps^2 - 2 mu cos theta t) p = 0, so the tip is
    where max_theta (undamped growth of p) = eps; that growth from Hill's method (S = 12, an
    independent method), maximised over theta (bounded Brent, 1e-10), solved for mu (brentq,
    1e-12)."""
    from scipy.optimize import minimize_scalar

    def excess(mu):
        res = minimize_scalar(
            lambda th: -np.max(hill_exponents(ONE, None, [[1.0 - eps**2]], [[-2.0 * mu]],
                                              [th], n_harmonics=12).real),
            bounds=(1.95, 2.05), method="bounded", options={"xatol": 1e-10})
        return -res.fun - eps

    return brentq(excess, 1.5 * eps, 3.0 * eps, xtol=1e-12)


def test_damped_mathieu_tip_exact_and_independent_of_search_tolerance():
    # damped Mathieu, eps = 0.01, tip mu_cr from the exact shift and Hill's method
    # (_damped_mathieu_tip).  critical_amplitude (gamma_rtol 1e-8) to 1e-6 relative,
    # and the tip of region_boundaries with the chart's coarse options (rtol 1e-4,
    # step_phase 0.25) equal to it to 1e-6 (it used to be biased up by the search tolerance)
    eps = 0.01
    mu_cr = _damped_mathieu_tip(eps)
    (crit,) = critical_amplitude(ONE, [[2.0 * eps]], ONE, [[-2.0]], gamma_max=3.0 * mu_cr,
                                 omega_min=1.5, omega_max=2.5, gamma_rtol=1e-8)
    assert crit.gamma_cr == pytest.approx(mu_cr, rel=1e-6)
    (rb,) = region_boundaries(ONE, [[2.0 * eps]], ONE, [[-2.0]], gamma_max=3.0 * mu_cr,
                              omega_min=1.5, omega_max=2.5, n_gamma=2, rtol=1e-4,
                              step_phase=0.25)
    assert rb.gamma[0] == pytest.approx(crit.gamma_cr, rel=1e-6)


def test_damped_mathieu_tip_far_below_gamma_max():
    # damped Mathieu, eps = 0.01, gamma_max = 40 mu_cr: the principal region at gamma_max
    # spans 1.5..2.5 with its growth maximum far from the tip; below the tip's neighbourhood
    # the growth is flat (-eps) outside the narrow undamped region of the smaller amplitude.
    # The tip search used to start each growth maximum from the previous maximiser, converged
    # on that plateau and returned 2.1 mu_cr; now it starts from the best of the previous
    # maximiser, the candidate centre and 5 samples.  Reference: _damped_mathieu_tip (exact
    # shift + Hill); tolerance 1e-6 relative (gamma_rtol 1e-8)
    eps = 0.01
    mu_cr = _damped_mathieu_tip(eps)
    (crit,) = critical_amplitude(ONE, [[2.0 * eps]], ONE, [[-2.0]], gamma_max=40.0 * mu_cr,
                                 omega_min=1.5, omega_max=2.5, max_order=1, gamma_rtol=1e-8)
    assert crit.gamma_cr == pytest.approx(mu_cr, rel=1e-6)


def test_growth_rate_max_inside_region():
    # the bounded maximiser: growth_rate_max >= the growth rate at 21 points in the region
    # (tolerance 1e-9, the integration error between step_phase 0.12 and 0.06) and equal to
    # the monodromy growth at omega_at_max (1e-10)
    sysm = mathieu(0.3)
    (r,) = instability_regions(*sysm, 1.2, 3.2)
    g = growth_rate(*sysm, np.linspace(r.omega_lo, r.omega_hi, 21))
    assert r.growth_rate_max >= np.max(g) - 1e-9
    g_at = growth_rate(*sysm, [r.omega_at_max], step_phase=0.12)[0]  # the search's setting
    assert r.growth_rate_max == pytest.approx(g_at, rel=1e-10)


def test_region_boundaries_follow_exact_mathieu_edges():
    # traced boundary curves of f'' + (1 - 2 gamma cos theta t) f = 0 against scipy.special at
    # each gamma (1e-6); tip at gamma = 0 on the candidate centre 2 (exact)
    (rb,) = region_boundaries(ONE, None, ONE, [[-2.0]], gamma_max=0.3, omega_min=1.2,
                              omega_max=3.2, n_gamma=4)
    assert rb.kind == "simple" and rb.order == 1
    assert rb.gamma[0] == 0.0 and rb.omega_lo[0] == rb.omega_hi[0] == 2.0
    for g, lo, hi in zip(rb.gamma[1:], rb.omega_lo[1:], rb.omega_hi[1:], strict=True):
        assert (lo, hi) == pytest.approx(mathieu_edges(g, 1), abs=1e-6)
    json.dumps(rb.to_dict())


def test_region_boundaries_damped_tip():
    # with damping the curves start at the critical amplitude (Bolotin sec. 6) where the two
    # boundaries meet, and widen with gamma
    eps = 0.01
    (rb,) = region_boundaries(ONE, [[2 * eps]], ONE, [[-2.0]], gamma_max=0.06, omega_min=1.5,
                              omega_max=2.5, n_gamma=3)
    assert abs(rb.gamma[0] / (2 * eps) - 1.0) < eps  # first order, as above
    assert rb.omega_lo[0] == rb.omega_hi[0]
    assert np.all(np.diff(rb.omega_hi - rb.omega_lo) > 0.0)


def test_undamped_critical_amplitude_is_zero():
    crit = critical_amplitude(ONE, None, ONE, [[-2.0]], gamma_max=0.1, omega_min=0.8,
                              omega_max=2.5)
    assert [(c.order, c.gamma_cr, c.omega_cr) for c in crit] == [(2, 0.0, 1.0), (1, 0.0, 2.0)]


def test_steady_unstable_is_reported():
    # flutter of the steady system (complex eigenvalues of M^-1 A): one "steady" region over
    # the whole range with the steady growth rate Im-part sqrt (closed form), no crash
    A = np.array([[1.0, 2.0], [-2.0, 2.0]])  # eigenvalues 1.5 +- i sqrt(3.75)
    (r,) = instability_regions(np.eye(2), None, A, 0.1 * np.eye(2), 0.5, 5.0)
    assert r.kind == "steady" and (r.omega_lo, r.omega_hi) == (0.5, 5.0)
    lam = np.sqrt(-np.linalg.eigvals(A).astype(complex))
    assert r.growth_rate_max == pytest.approx(np.max(np.abs(lam.real)), rel=1e-12)
    w = steady_frequencies(np.eye(2), A)
    assert np.all(np.abs(w.imag) > 0.1)


def test_results_are_json_ready():
    (r,) = instability_regions(*mathieu(0.1), 1.2, 3.2)
    d = r.to_dict()
    json.dumps(d)
    assert d["kind"] == "simple" and d["modes"] == [0] and d["order"] == 1


# --------------------------------------------------------------------------------------------
# Cost model and bad input
# --------------------------------------------------------------------------------------------
def test_step_count_capped_as_omega_goes_to_zero():
    system = periodic_system(ONE, None, ONE, [[-0.2]])
    steps = step_counts(system, [1.0, 0.1, 0.01])
    assert steps[1] > 5 * steps[0] and steps[2] > 5 * steps[1]  # grows like 1 / Omega
    with pytest.raises(ValueError, match="max_steps"):
        monodromy(ONE, None, ONE, [[-0.2]], [1e-6])
    with pytest.raises(ValueError, match="max_candidates"):  # orders j = 1..~14 examined
        instability_regions(*mathieu(0.1), 1e-7, 3.0, max_candidates=5)


@pytest.mark.parametrize("args,name", [
    (([[np.nan]], None, ONE, ONE), "M ="),
    ((ONE, None, [[np.inf]], ONE), "A ="),
    ((ONE, None, ONE, [[1.0, 0.0]]), "B ="),
    ((np.eye(2), None, np.eye(3), np.eye(2)), "A ="),
    ((np.zeros((2, 2)), None, np.eye(2), np.eye(2)), "M ="),
    ((ONE, [[np.nan]], ONE, ONE), "C ="),
], ids=["nan-M", "inf-A", "shape-B", "shape-A", "singular-M", "nan-C"])
def test_bad_matrices(args, name):
    with pytest.raises(ValueError, match=name):
        monodromy(*args, [1.0])
    with pytest.raises(ValueError, match=name):
        instability_regions(*args, 0.5, 2.0)


@pytest.mark.parametrize("lo,hi,name", [
    (2.0, 1.0, "omega_min"), (1.0, 1.0, "omega_min"), (-1.0, 2.0, "omega_min"),
    (1.0, np.inf, "omega_max"), (np.nan, 2.0, "omega_min"),
])
def test_bad_range(lo, hi, name):
    with pytest.raises(ValueError, match=name):
        instability_regions(*mathieu(0.1), lo, hi)


@pytest.mark.slow
def test_overflow_raises_instead_of_inf():
    # a violently unstable point: the monodromy would overflow; ValueError, never inf / NaN
    for C in (None, [[0.01]]):
        with pytest.raises(ValueError, match="overflowed"):
            growth_rate(ONE, C, ONE, [[-300.0]], [0.02])


def test_bad_omega_and_options():
    with pytest.raises(ValueError, match="Omega"):
        monodromy(*mathieu(0.1), [1.0, -2.0])
    with pytest.raises(ValueError, match="Omega"):
        growth_rate(*mathieu(0.1), [np.nan])
    with pytest.raises(ValueError, match="period"):
        periodic_boundaries(*mathieu(0.1), period="3T")
    with pytest.raises(ValueError, match="rtol"):
        instability_regions(*mathieu(0.1), 1.0, 3.0, rtol=0.0)
    with pytest.raises(ValueError, match="chunk"):
        instability_regions(*mathieu(0.1), 1.0, 3.0, chunk=0)
    with pytest.raises(ValueError, match="max_order"):
        instability_regions(*mathieu(0.1), 1.0, 3.0, max_order=0)
    with pytest.raises(ValueError, match="n_steps"):
        monodromy(*mathieu(0.1), [1.0], n_steps=0)
    with pytest.raises(ValueError, match="gamma_max"):
        critical_amplitude(*mathieu(0.1), gamma_max=-1.0, omega_min=1.0, omega_max=3.0)
    with pytest.raises(ValueError, match="n_gamma"):
        region_boundaries(*mathieu(0.1), gamma_max=0.1, omega_min=1.0, omega_max=3.0,
                          n_gamma=1)


# --------------------------------------------------------------------------------------------
# The damping shortcuts of the region search: certificate and candidate filter
# --------------------------------------------------------------------------------------------
def test_search_work_is_what_the_search_integrates():
    # the cost model's input, known before the search: a steady instability (A < 0) or a
    # certified damped system (Mathieu mu = 0.002 < eps sqrt(1 - eps^2) / 2, eps = 0.01) costs
    # nothing; the undamped Mathieu equation on [1.5, 2.5] has one candidate, Omega = 2 (2 w / j
    # for j = 1 only), integrated at the half-period step count of step_counts at 2, and the
    # search finds exactly that region; damped but not certified (mu = 0.1) the same candidate
    # with the damped full-period count as well
    assert search_work(ONE, None, [[-1.0]], [[0.1]], 1.5, 2.5).steady
    cert = search_work(*mathieu(0.002, 0.01), 1.5, 2.5)
    assert cert.certified and cert.n_candidates == 0 and cert.undamped_steps == 0
    w = search_work(*mathieu(0.1), 1.5, 2.5)
    assert (w.n, w.steady, w.certified, w.n_candidates, w.n_narrow, w.damped_steps) == (
        1, False, False, 1, 0, 0)
    und = periodic_system(*mathieu(0.1))
    assert w.undamped_steps == step_counts(und, [2.0], step_phase=0.12)[0]
    assert w.undamped_max_steps == w.undamped_steps  # one candidate
    (r,) = instability_regions(*mathieu(0.1), 1.5, 2.5)
    assert (r.kind, r.order, r.omega_center) == ("simple", 1, 2.0)
    d = search_work(*mathieu(0.1, 0.01), 1.5, 2.5)
    assert (d.n_candidates, d.undamped_steps) == (1, w.undamped_steps)
    assert d.damped_steps == step_counts(periodic_system(*mathieu(0.1, 0.01)), [2.0],
                                         step_phase=0.12)[0]
    assert json.dumps(d.to_dict())


def test_search_work_counts_the_candidates_between_undamped_modes():
    # two uncoupled Mathieu oscillators, w = 1 undamped and w = 1.6 damped (eps = 0.01), each
    # pumped (B diagonal): on [1.5, 3.5] mode 0's simple centres 2 w / j hold only j = 1
    # (Omega = 2; j = 2 gives 1 < 1.5), and every other candidate (mode 1's 3.2 and 1.6, the
    # combinations) involves the damped mode 1. So exactly 1 open candidate, at the damped
    # system's step count at Omega = 2 (step_counts). Hand enumeration of 2 w_i / j.
    M, C = np.eye(2), np.diag([0.0, 2.0 * 0.01 * 1.6])
    A, B = np.diag([1.0, 1.6**2]), np.diag([-0.2, -0.2 * 1.6**2])
    d = search_work(M, C, A, B, 1.5, 3.5)
    assert d.n_candidates >= 3 and d.n_open == 1
    # all candidates on [1.5, 3.5]: simple 2 w_i / j = 2 (mode 0), 3.2 and 1.6 (mode 1), the
    # combination (w_0 + w_1) / 1 = 2.6; the undamped counts are their step counts' sum and
    # the largest (the batch runs as long as its longest candidate)
    counts = step_counts(periodic_system(M, None, A, B), [1.6, 2.0, 2.6, 3.2], step_phase=0.12)
    assert d.n_candidates == 4
    assert (d.undamped_steps, d.undamped_max_steps) == (int(counts.sum()), int(counts.max()))
    assert d.open_steps == step_counts(periodic_system(M, C, A, B), [2.0],
                                       step_phase=0.12)[0]
    # undamped throughout: no damped search, so nothing open is counted
    assert search_work(*mathieu(0.1), 1.5, 2.5).n_open == 0
    # mode 0 with a damping ratio of its own, 0.5 % and 2 % of mode 1's 0.01 (either side of
    # OPEN_DAMPING_FRACTION = 1e-2 of the largest): open, then not
    for zeta0, n_open in ((0.5e-2 * 0.01, 1), (2e-2 * 0.01, 0)):
        C0 = np.diag([2.0 * zeta0 * 1.0, 2.0 * 0.01 * 1.6])
        assert search_work(M, C0, A, B, 1.5, 3.5).n_open == n_open


def test_certificate_of_damped_mathieu_closed_form():
    # f'' + 2 eps f' + (1 - 2 mu cos) f: in the steady eigenbasis |G_ij| = |b| / (2 w_d) for
    # all four entries (b = 2 mu, w_d = sqrt(1 - eps^2)), so rho = 2 mu / (w_d eps) and, with
    # the Perron weights (1, 1), the bound -eps + 2 mu / w_d (derived by hand, Desoer &
    # Vidyasagar sec. 2.8); tolerance 1e-9 relative (the round-off guard adds ~1e-15)
    eps = 0.01
    wd = np.sqrt(1 - eps**2)
    for mu in (0.002, 0.0049, 0.006):
        c = stability_certificate(*mathieu(mu, eps))
        assert c.rho == pytest.approx(2 * mu / (wd * eps), rel=1e-9)
        assert c.growth_bound == pytest.approx(-eps + 2 * mu / wd, rel=1e-9)
        assert c.certified == (mu < eps * wd / 2)
    assert not stability_certificate(*mathieu(0.002)).certified  # no damping: no bound
    assert stability_certificate(*mathieu(0.0, eps)).growth_bound == pytest.approx(-eps)


@pytest.mark.parametrize("seed", [3, 5, 8])
def test_certificate_bounds_every_monodromy_growth_rate(seed):
    # the certificate is a theorem (logarithmic norm): at every Omega the monodromy's growth
    # rate must lie below growth_bound (< 0); checked on 60 Omega in 0.3..8 for a damped
    # non-symmetric 3 DOF system scaled to be certified (integration error ~1e-9)
    M, C, A, B = random_system(3, seed, damped=True)
    c0 = stability_certificate(M, C, A, B)
    B = B * 0.5 * c0.amplitude_factor  # half the certified amplitude
    c = stability_certificate(M, C, A, B)
    assert c.certified and c.growth_bound < 0.0
    g = growth_rate(M, C, A, B, np.linspace(0.3, 8.0, 60))
    assert np.all(g <= c.growth_bound + 1e-9)
    assert instability_regions(M, C, A, B, 0.3, 8.0) == ()


def weakly_coupled(seed: int, gamma: float, zeta: float):
    """Modal system of a lightly damped structure: w = 1, 1.7, 2.9, 4.1, C = 2 zeta diag(w),
    B = gamma r_ab w_a w_b with r symmetric, |r| <= 0.25 (like the vehicle's B1)."""
    rng = np.random.default_rng(seed)
    w = np.array([1.0, 1.7, 2.9, 4.1])
    r = 0.25 * rng.uniform(-1, 1, (4, 4))
    r = 0.5 * (r + r.T)
    return np.eye(4), 2 * zeta * np.diag(w), np.diag(w**2), gamma * r * np.outer(w, w)


@pytest.mark.slow
@pytest.mark.parametrize("seed,gamma", [(3, 0.3), (1, 0.5)])
def test_damping_filter_never_drops_a_region(seed, gamma):
    # invariant: the damping filter (default margin 4) against the unfiltered search
    # (damping_margin=None), Omega 0.8..9, orders 1-2, zeta = 0.01, on systems where it drops
    # a fifth or more of the candidates (asserted; 9 of 33 and 11 of 32, fewer than without
    # the small-denominator factors: e.g. the sum (1, 2.9) j = 2 at 1.95 passes nu = 0.95 beside
    # w = 1) and regions survive the damping: the same
    # regions (kind, modes, order), edges within 1e-8 relative (10 x rtol: the batches
    # refine differently)
    M, C, A, B = weakly_coupled(seed, gamma, 0.01)
    system = periodic_system(M, C, A, B)
    w = np.sqrt(system.mu.real)
    opt = _options(max_order=2)
    n_all = _candidates(w, system.Bt, 0.4, 18.0, opt)["j"].size
    n_kept = _candidates(w, system.Bt, 0.4, 18.0, opt, rate=_modal_decay_rates(system))["j"].size
    assert n_kept <= 4 * n_all / 5
    fast = instability_regions(M, C, A, B, 0.8, 9.0, max_order=2)
    full = instability_regions(M, C, A, B, 0.8, 9.0, max_order=2, damping_margin=None)
    assert full
    assert [(r.kind, r.modes, r.order) for r in fast] == [(r.kind, r.modes, r.order)
                                                         for r in full]
    for a, b in zip(fast, full, strict=True):
        assert (a.omega_lo, a.omega_hi) == pytest.approx((b.omega_lo, b.omega_hi), rel=1e-8)


def test_golden_section_max_vectorised():
    # closed form: the maxima of -(x - c)^2 + c (c = 0.3, 1.7, -2.2 in three intervals) and
    # of sin on [0, 3] (pi / 2), each to its xtol 1e-6 (golden section keeps the maximum in
    # the final bracket while f values differ beyond round-off, i.e. down to ~sqrt(eps) |x|)
    c = np.array([0.3, 1.7, -2.2])
    seen = []

    def f(x, idx):
        seen.append(idx.size)
        return -(x - c[idx]) ** 2 + c[idx]

    x, fx = golden_section_max(f, [0.0, 1.0, -3.0], [1.0, 2.5, 0.0], xtol=1e-6)
    assert np.all(np.abs(x - c) <= 1e-6) and np.allclose(fx, c, atol=1e-12)
    (xs,), _ = golden_section_max(lambda x, idx: np.sin(x), [0.0], [3.0], xtol=1e-6)
    assert abs(xs - np.pi / 2) <= 1e-6
    for kwargs, name in (({"a": [1.0], "b": [0.0], "xtol": 1e-3}, "b"),
                         ({"a": [0.0], "b": [1.0], "xtol": 0.0}, "xtol"),
                         ({"a": [0.0], "b": [1.0], "xtol": 1e-3, "max_iter": 0}, "max_iter")):
        with pytest.raises(ValueError, match=name):
            golden_section_max(f, **kwargs)
    with pytest.raises(ValueError, match="no convergence"):
        golden_section_max(f, [0.0], [1.0], xtol=1e-12, max_iter=3)


def test_bad_damping_margin():
    for bad in (0.5, np.nan, "4", True):
        with pytest.raises(ValueError, match="^damping_margin = "):
            instability_regions(*mathieu(0.1, 0.01), 1.0, 3.0, damping_margin=bad)
