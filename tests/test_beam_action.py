"""Tests of flexbooster.memo.beam_action: exact limits, literature values, two methods agree."""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest
from scipy.integrate import quad, solve_ivp
from scipy.optimize import brentq
from scipy.special import mathieu_a, mathieu_b

from flexbooster.memo import beam, beam_action, pitch
from flexbooster.memo.beam_action import (
    beam_action_analysis,
    beam_action_system,
    follower_flutter_load,
    hill_exponents,
    loaded_frequencies,
    monodromy_exponents,
    natural_branch,
    reduced_exponents,
    stability_chart,
    uniform_beam_system,
)
from flexbooster.present.plotting.beam_action import plot_stability_chart

LAM1 = beam.free_free_eigenvalues(1)[0]
DATA = Path(__file__).parent / "data"


def _mathieu_trace(a: float, q: float) -> float:
    """y1(pi) of y'' + (a - 2 q cos 2t) y = 0, y1(0) = 1, y1'(0) = 0 (= cos(pi nu)).

    Independent reference: scipy solve_ivp (DOP853, rtol 1e-12); Abramowitz & Stegun 20.3.
    """
    sol = solve_ivp(lambda t, y: [y[1], -(a - 2 * q * np.cos(2 * t)) * y[0]], (0.0, np.pi),
                    [1.0, 0.0], method="DOP853", rtol=1e-12, atol=1e-14)
    return float(sol.y[0, -1])


# ----------------------------------------------------------------------------------------------
# Tier 1: exact limits
# ----------------------------------------------------------------------------------------------
def test_mode_end_values_and_modal_integral_against_quad():
    # phi_n(0) = 2 and dphi_n/dzeta(0) = -lambda_n alpha_n for the free-free mode (Blevins 1979,
    # table 8-1 form); G_nk = int_0^2 (1 - zeta/2) phi_n' phi_k' dzeta against scipy quad
    # (epsabs 1e-13) for a few entries.
    G, phi0, dphi0, lam = beam_action._modal_integrals(6)
    np.testing.assert_allclose(phi0, 2.0, rtol=1e-12)
    np.testing.assert_allclose(dphi0, -lam * beam.free_free_alpha(6), rtol=1e-12)
    for n, k in [(1, 1), (1, 2), (3, 5), (6, 6)]:
        def f(z, n=n, k=k):
            dn = beam.mode_shape(n, z, 1) * lam[n - 1] / 2
            dk = beam.mode_shape(k, z, 1) * lam[k - 1] / 2
            return (1 - z / 2) * dn * dk
        ref, _ = quad(f, 0.0, 2.0, epsabs=1e-13, epsrel=1e-13, limit=200)
        assert G[n - 1, k - 1] == pytest.approx(ref, rel=1e-10, abs=1e-10)


@pytest.mark.parametrize("Omega_bar", [0.37, 1.3, 4.1])
def test_gamma_zero_exponents_are_steady_thrust_frequencies(Omega_bar):
    # gamma = 0: alpha_r Omega_bar equals the natural frequencies of the constant system,
    # the square roots of the eigenvalues of Lambda + B (independent eigenproblem, numpy eigvals);
    # both Floquet methods, 1e-10.
    system = uniform_beam_system(20.0, 1.0, 5)
    w_ref = np.sort(np.sqrt(np.linalg.eigvals(np.diag(system.Lambda) + system.B).real))
    hill = hill_exponents(system, Omega_bar, 0.0, 4)
    alpha = natural_branch(reduced_exponents(hill.alpha), np.array([Omega_bar]),
                           loaded_frequencies(system))
    np.testing.assert_allclose(np.sort(alpha[0].real) * Omega_bar, w_ref, rtol=1e-10, atol=1e-12)
    mono = monodromy_exponents(system, Omega_bar, 0.0)
    alpha_m = natural_branch(reduced_exponents(mono), np.array([Omega_bar]),
                             loaded_frequencies(system))
    np.testing.assert_allclose(np.sort(alpha_m[0].real) * Omega_bar, w_ref, rtol=1e-10,
                               atol=1e-12)
    assert np.all(np.abs(alpha_m.imag) < 1e-10)


def test_steady_frequencies_against_continuous_beam_shooting():
    # Uniform free-free beam, constant follower end force p = P l^2/EI = 50, K = 0: natural
    # frequencies of the continuous problem w'''' + p((1 - s) w')' = W^2 w, w''= w''' = 0 at both
    # ends (the follower force gives w'''(0) = 0), by shooting with scipy solve_ivp (DOP853, rtol
    # 1e-12) and brentq; omega / omega_1 = W / lambda_1^2.  Galerkin with N = 16 converges from
    # above to within 2e-5 (see the convergence table in docs/theory/beam-action.md).
    p = 50.0

    def det(W2):
        def f(x, y):
            return [y[1], y[2], y[3], -p * ((1 - x) * y[2] - y[1]) + W2 * y[0]]
        ends = [solve_ivp(f, (0, 1), y0, method="DOP853", rtol=1e-12, atol=1e-14).y[2:, -1]
                for y0 in ([1, 0, 0, 0], [0, 1, 0, 0])]
        return np.linalg.det(np.array(ends))

    w = loaded_frequencies(uniform_beam_system(p, 0.0, 16))
    assert abs(w[0]) < 1e-6  # rigid pitch without gimbal: zero frequency
    for est in w[1:3].real:
        W2 = (est * LAM1**2) ** 2
        ref = np.sqrt(brentq(det, 0.98 * W2, 1.02 * W2, xtol=1e-14, rtol=1e-13)) / LAM1**2
        assert est == pytest.approx(ref, rel=2e-5)
        assert est >= ref * (1 - 1e-9)  # Galerkin (Rayleigh-Ritz-like) from above


@pytest.mark.parametrize(
    "a, q",
    [
        (0.6, 0.05),  # stable, memo range (4.2-5)
        (0.9, 0.3),   # inside the first instability region b_1(q) < a < a_1(q)
        (1.0, 0.2),   # inside, near the centre of the region
        (3.5, 0.8),   # stable, between a_1 and b_2
        (4.0, 0.6),   # inside the second region b_2 < a < a_2
        (0.25, 0.05),  # stable, small a
    ],
)
def test_rigid_rotation_alone_is_mathieu_of_pitch_module(a, q):
    # Elastic modes removed (N = 0): the rigid rotation of the composite must obey (4.2-3) with
    # a, q of pitch.mathieu_parameters; reference cos(pi nu) = y1(pi) by solve_ivp (rtol 1e-12),
    # Magnus & Winkler (1966) thm 1.1; multipliers e^{2 pi i alpha} = e^{i pi nu} hence
    # cos(2 pi alpha) = y1(pi).  Composite numbers of the memo case's order of magnitude.
    mass, L, d2, I_cm, F0, K, omega_1 = 9.4e4, 30.0, 27.6, 2.7e7, 2.8e6, 0.5, 113.5
    omega_psi = pitch.pitch_frequency(F0, d2, K, I_cm)
    Omega = 2.0 * omega_psi / np.sqrt(a)
    gamma = 2.0 * q / a
    a_p, q_p = pitch.mathieu_parameters(np.array([Omega]), omega_psi, gamma)
    assert a_p[0] == pytest.approx(a, rel=1e-12) and q_p[0] == pytest.approx(q, rel=1e-12)
    system = beam_action_system(omega_1, mass, L, d2, I_cm, F0, K, 0)
    # nu from cos(pi nu) = y1(pi) (complex inside a region); alpha = nu / 2, folded
    ref = beam_action._fold(np.array([np.arccos(complex(_mathieu_trace(a, q))) / (2 * np.pi)]))
    for alpha in (hill_exponents(system, Omega, gamma, 24).alpha,
                  monodromy_exponents(system, Omega, gamma)):
        np.testing.assert_allclose(reduced_exponents(alpha)[0], ref, rtol=0, atol=1e-8)


@pytest.mark.parametrize(
    "curve, order",
    [(mathieu_b, 1), (mathieu_a, 1), (mathieu_b, 2), (mathieu_a, 2), (mathieu_b, 3)],
)
def test_rigid_rotation_on_mathieu_transition_curves(curve, order):
    # On the transition curves a_r(q), b_r(q) (scipy.special.mathieu_a/b; Abramowitz & Stegun
    # 20.1) nu = r, so e^{2 pi i alpha} = e^{i pi r}: cos(2 pi alpha) = (-1)^r.  The multiplier
    # is double there, so alpha itself is resolved only to ~sqrt(eps); its cosine (the trace of
    # the monodromy, smooth) is compared instead, 1e-8 (Hill, S = 24).  q = 0.25 keeps
    # gamma = 2 q / a < 1 on b_1.
    q = 0.25
    a = float(curve(order, q))
    system = uniform_beam_system(1.0, 1.0, 0, omega_1=1.0)
    kappa = system.B[0, 0]  # (omega_psi / omega_1)^2, the only coefficient when N = 0
    Omega = 2.0 * np.sqrt(kappa / a)
    gamma = 2.0 * q / a
    alpha = hill_exponents(system, Omega, gamma, 24).alpha[0]
    np.testing.assert_allclose(np.cos(2 * np.pi * alpha), (-1.0) ** order, rtol=0, atol=1e-8)


# ----------------------------------------------------------------------------------------------
# Tier 2: literature values
# ----------------------------------------------------------------------------------------------
@pytest.mark.parametrize("n_modes", [8, 10, 12, 16])
def test_follower_flutter_load_beal(n_modes):
    # Beal, AIAA J. 3 (1965): free-free uniform beam under a constant follower end force
    # flutters at P l^2 / EI = 109.69; acceptance 0.1 %.
    assert follower_flutter_load(n_modes=n_modes) == pytest.approx(109.69, rel=1e-3)


def test_follower_flutter_load_converges_from_above():
    # Galerkin with more modes can only lower the coalescence load here (observed monotone, see
    # the convergence table in docs); the 16-mode value is within 1e-4 of Beal's 109.69.
    loads = [follower_flutter_load(n_modes=n) for n in (4, 6, 8, 12, 16)]
    assert np.all(np.diff(loads) < 0)
    assert loads[-1] == pytest.approx(109.69, rel=1e-4)


def test_steady_thrust_just_below_and_above_flutter():
    # Below the flutter load all steady frequencies are real; above, two coalesce into a complex
    # pair (Beal 1965, fig. 2): checked with the full system (rigid pitch included, K = 0).
    p_f = follower_flutter_load(n_modes=8)
    below = loaded_frequencies(uniform_beam_system(0.999 * p_f, 0.0, 8))
    above = loaded_frequencies(uniform_beam_system(1.001 * p_f, 0.0, 8))
    assert np.max(np.abs(below.imag)) < 1e-8
    assert np.sum(np.abs(above.imag) > 1e-3) == 2
    # the same through the Floquet machinery at gamma = 0 (monodromy): real below, growth above
    for factor, unstable in ((0.999, False), (1.001, True)):
        red = reduced_exponents(monodromy_exponents(
            uniform_beam_system(factor * p_f, 0.0, 8), 0.7, 0.0))
        assert (np.max(red.imag) > 1e-3) == unstable


# ----------------------------------------------------------------------------------------------
# Tier 3: two methods agree, invariants
# ----------------------------------------------------------------------------------------------
# uniform beam, p = 20, K = 1: omega_psi ~ 0.229, omega_2 ~ 0.943, omega_3 ~ 2.59 (in omega_1);
# the points include the principal pitch region (2 omega_psi ~ 0.46), the combination region
# omega_psi + omega_2 ~ 1.17 and the principal region of the first elastic mode (~1.89).
AGREE_POINTS = np.concatenate([np.linspace(0.3, 6.0, 18), [0.46, 0.47, 1.17, 1.88, 1.9, 5.2]])


def test_hill_and_monodromy_agree_1e8_including_unstable_points():
    system = uniform_beam_system(20.0, 1.0, 4)
    gamma = 0.6
    hill = reduced_exponents(hill_exponents(system, AGREE_POINTS, gamma, 10).alpha)
    mono = reduced_exponents(monodromy_exponents(system, AGREE_POINTS, gamma))
    assert AGREE_POINTS.size >= 20
    np.testing.assert_allclose(hill, mono, rtol=0, atol=1e-8)
    n_unstable = np.sum(np.max(hill.imag, axis=1) > 1e-3)
    assert n_unstable >= 3  # the comparison covers instability regions


def test_hill_and_monodromy_agree_with_ten_modes():
    # N = 10 (the default truncation), strong thrust p = 20, two points, one unstable.
    system = uniform_beam_system(20.0, 1.0, 10)
    Om = np.array([0.45, 2.2])  # 0.45: principal pitch region (2 omega_psi = 0.453 for N = 10)
    hill = reduced_exponents(hill_exponents(system, Om, 0.6, 8).alpha)
    mono = reduced_exponents(monodromy_exponents(system, Om, 0.6))
    np.testing.assert_allclose(hill, mono, rtol=0, atol=1e-8)
    assert hill[0].imag.max() > 1e-3


@pytest.mark.parametrize("Omega_bar", [0.47, 1.17, 3.0])
def test_monodromy_against_solve_ivp_full_period(Omega_bar):
    # The reversibility shortcut (half period) and Lawson's integrator against a plain
    # full-period integration of q'' + [Lambda + f B] q = 0 in the original coordinates with
    # scipy solve_ivp (DOP853, rtol 1e-12): multipliers compared as sets, 1e-8.
    system = uniform_beam_system(20.0, 1.0, 3)
    gamma = 0.6
    n = system.N + 1
    A0, B = np.diag(system.Lambda) + system.B, system.B

    def f(t, y):
        Y = y.reshape(2 * n, 2 * n)
        Q, V = Y[:n], Y[n:]
        A = A0 - gamma * np.cos(Omega_bar * t) * B
        return np.concatenate([V, -A @ Q]).ravel()

    T = 2 * np.pi / Omega_bar
    sol = solve_ivp(f, (0, T), np.eye(2 * n).ravel(), method="DOP853", rtol=1e-12, atol=1e-13)
    rho_ref = np.linalg.eigvals(sol.y[:, -1].reshape(2 * n, 2 * n))
    ref = reduced_exponents(np.log(rho_ref.astype(complex)) / (2j * np.pi))[None]
    got = reduced_exponents(monodromy_exponents(system, Omega_bar, gamma))
    np.testing.assert_allclose(got, ref, rtol=0, atol=1e-8)


def test_hill_converges_with_harmonics():
    # Hill's truncation: S = 8 and S = 16 agree to 1e-10 at moderate gamma (Fourier coefficients
    # of the Floquet solutions decay geometrically; Bolotin 1964, sec. 7).
    system = uniform_beam_system(20.0, 1.0, 3)
    Om = np.array([0.5, 1.5, 4.0])
    a8 = reduced_exponents(hill_exponents(system, Om, 0.3, 8).alpha)
    a16 = reduced_exponents(hill_exponents(system, Om, 0.3, 16).alpha)
    np.testing.assert_allclose(a8, a16, rtol=0, atol=1e-10)


def test_multiplier_invariants():
    # det(monodromy) = 1 (trace of the first-order system is zero, Liouville) and the set of
    # multipliers is closed under rho -> 1/rho (time reversibility, A(tau) even): exponents
    # sum to an integer and come in +- pairs.  Checked on the raw monodromy exponents.
    system = uniform_beam_system(20.0, 1.0, 3)
    alpha = monodromy_exponents(system, np.array([0.46, 1.9, 3.3]), 0.6)
    total = np.sum(alpha, axis=1)
    np.testing.assert_allclose(np.abs(np.exp(2j * np.pi * total)), 1.0, atol=1e-9)
    folded = beam_action._fold(alpha)
    for row in folded:  # every folded value appears an even number of times
        d = np.abs(row[:, None] - row[None, :])
        assert np.all(np.sum(d < 1e-7, axis=1) >= 2)


def test_natural_branch_small_gamma_tracks_loaded_frequencies():
    # gamma -> 0: alpha_r Omega_bar -> omega_r / omega_1 (the branch definition); the shift is
    # O(gamma^2) away from resonances (Bolotin 1964, sec. 8): 1e-6 at gamma = 1e-3.
    system = uniform_beam_system(20.0, 1.0, 4)
    Om = np.array([0.8, 2.6, 3.7])
    w = loaded_frequencies(system)
    alpha = natural_branch(reduced_exponents(hill_exponents(system, Om, 1e-3, 6).alpha), Om, w)
    np.testing.assert_allclose(alpha.real * Om[:, None], np.tile(w.real, (3, 1)), atol=1e-5)


def test_hill_fourier_vectors_solve_the_truncated_equations():
    # (4.1-10/11) residual: (mu + s Omega)^2 C^(s) = A0 C^(s) - gamma/2 B (C^(s-1) + C^(s+1)) for
    # the returned vectors (the definition of Hill's eigenproblem), 1e-9 relative.
    system = uniform_beam_system(20.0, 1.0, 3)
    Ob, gamma, S = 1.3, 0.4, 6
    res = hill_exponents(system, Ob, gamma, S)
    json.dumps(res.to_dict(), allow_nan=False)  # JSON-ready (house style)
    A0, B = np.diag(system.Lambda) + system.B, system.B
    for j in range(res.alpha.shape[1]):
        mu = res.alpha[0, j] * Ob
        C = res.C[0, j]
        Cp = np.vstack([C[1:], np.zeros((1, C.shape[1]))])
        Cm = np.vstack([np.zeros((1, C.shape[1])), C[:-1]])
        s = np.arange(-S, S + 1)[:, None]
        lhs = (mu + s * Ob) ** 2 * C
        rhs = C @ A0.T - 0.5 * gamma * (Cm + Cp) @ B.T
        assert np.max(np.abs(lhs - rhs)) < 1e-9 * max(1.0, np.max(np.abs(lhs)))


def test_chart_classification_matches_hill():
    # The chart uses a coarser monodromy step; its stable/unstable flags must equal Hill's
    # (S = 10) on a grid across the principal pitch and first elastic regions.
    system = uniform_beam_system(20.0, 1.0, 3)
    Om = np.linspace(0.35, 2.1, 10)
    gam = np.array([0.15, 0.45, 0.75])
    chart = stability_chart(system, Om, gam)
    OO, GG = np.meshgrid(Om, gam)
    hill = reduced_exponents(hill_exponents(system, OO, GG, 10).alpha)
    flags = (np.max(hill.imag, axis=1) <= 1e-6).reshape(OO.shape)
    assert chart.stable.shape == (3, 10)
    assert np.array_equal(chart.stable, flags)
    assert not chart.stable.all() and chart.stable.any()
    assert np.isfinite(chart.growth_rate).all()
    json.dumps(chart.to_dict(), allow_nan=False)


def _model(Omega, N, S, R):
    """Derived model of the default booster with the given Omega grid and truncation."""
    from flexbooster.case import memo_case
    from flexbooster.memo.model import Truncation
    from flexbooster.model import model_from_case

    m = model_from_case(memo_case())
    return dataclasses.replace(m, Omega=np.asarray(Omega, dtype=float),
                               truncation=Truncation(M1=1, N1=1, M2=1, N2=1, N=N, S=S, R=R))


def test_analysis_result_is_json_ready_and_consistent():
    # Pipeline entry point on a composite of the memo case's magnitude with a small grid;
    # both methods must agree (1e-8), alpha_r Omega_bar stays near omega_r for the weak
    # coupling of a realistic thrust (p ~ 0.02), and to_dict() is strict JSON.
    res = beam_action_analysis(_model(np.linspace(10.0, 600.0, 8), N=4, S=6, R=3), n_hill=3)
    assert res.alpha.shape == (8, 3)
    assert res.hill_monodromy_difference < 1e-8
    assert res.verdict in ("stable", "unstable")
    np.testing.assert_allclose(res.alpha.real * res.Omega_bar[:, None],
                               np.tile(res.frequencies.real, (8, 1)), rtol=1e-3)
    text = json.dumps(res.to_dict(), allow_nan=False)
    assert "alpha_real" in text


def test_plot_returns_figure():
    import matplotlib.pyplot as plt

    system = uniform_beam_system(20.0, 1.0, 2)
    chart = stability_chart(system, np.linspace(0.35, 0.6, 4), np.array([0.2, 0.6]))
    fig = plot_stability_chart(chart)
    assert fig.axes[0].get_xlabel() != ""
    plt.close(fig)
    fig2, ax = plt.subplots()
    assert plot_stability_chart(chart, ax=ax) is fig2
    plt.close(fig2)


@pytest.mark.parametrize(
    "call, name",
    [
        (lambda: beam_action_system(0.0, 1, 1, 1, 1, 1, 0, 2), "omega_1"),
        (lambda: beam_action_system(1, -1, 1, 1, 1, 1, 0, 2), "mass"),
        (lambda: beam_action_system(1, 1, 1, 1, 1, np.nan, 0, 2), "F0"),
        (lambda: beam_action_system(1, 1, 1, 1, 1, 1, -0.1, 2), "K"),
        (lambda: beam_action_system(1, 1, 1, 1, 1, 1, 0, 2.5), "N"),
        (lambda: hill_exponents(uniform_beam_system(1, 0, 1), 1.0, 0.1, -1), "S"),
        (lambda: hill_exponents(uniform_beam_system(1, 0, 1), -1.0, 0.1, 2), "Omega"),
        (lambda: monodromy_exponents(uniform_beam_system(1, 0, 1), 1.0, 1.2), "gamma"),
        (lambda: follower_flutter_load(n_modes=1), "n_modes"),
        (lambda: follower_flutter_load(n_modes=4, p_max=50.0), "p_max"),
        (lambda: beam_action_analysis(_model([10.0], N=2, S=2, R=4)), "R"),
    ],
)
def test_bad_input_raises_value_error_naming_parameter(call, name):
    with pytest.raises(ValueError, match=name):
        call()


def test_damped_bands_of_the_memo_case_match_the_one_step_kernel():
    """The damped bands of the memo's case (beam 1 %, pitch 0) against those of the kernel that
    stepped one RK4 step at a time and bisected the critical gamma down from gamma (stored by
    tests/data/make_damped_bands_reference.py at commit 2ffa6ec: an independent run of the same
    method).  Each edge agrees to 10 rtol (BAND_RTOL = 1e-9 of the centre) or is a zero of
    log|rho|_max of today's monodromy to round-off (|log|rho|| <= 1e-13 per period: the plateau
    of a region's tail whose growth is below floating point, measured 1e-15..3e-14, where any
    two roundings put the edge elsewhere); the growth maxima agree to 1e-4 (Brent to 1e-4 of
    its bracket on a peak flat to round-off); the critical gamma to its tolerance 1e-6 gamma.
    """
    import flexbooster
    from flexbooster import floquet
    from flexbooster.memo.beam_action import BAND_RTOL, beam_system, modal_damping, pipeline_bands
    from flexbooster.model import model_from_case

    ref = json.loads((DATA / "damped_bands_reference.json").read_text())
    model = model_from_case(flexbooster.load_case(ref["case"]))
    bands = pipeline_bands(model)
    assert [(b.kind, [m.index for m in b.modes], b.order) for b in bands] == [
        (r["kind"], [m["index"] for m in r["modes"]], r["order"]) for r in ref["bands"]]
    system = beam_system(model)
    w1 = system.omega_1
    C = modal_damping(system, beam_ratio=model.beam_damping_ratio,
                      pitch_ratio=model.pitch_damping_ratio)
    n = system.N + 1

    def log_rho(Omega):  # log|rho|_max per period at Omega (rad/s), the search's step phase
        om = np.atleast_1d(Omega) / w1
        g = floquet.growth_rate(np.eye(n), C, system.A0, -model.gamma * system.B, om,
                                step_phase=0.12)
        return g * 2.0 * np.pi / om

    for band, r in zip(bands, ref["bands"], strict=True):
        c = r["Omega_center"]
        for key in ("Omega_lo", "Omega_hi"):
            new, old = getattr(band, key), r[key]
            if abs(new - old) > 10.0 * BAND_RTOL * c:
                assert np.all(np.abs(log_rho(np.array([new, old]))) <= 1e-13), (key, new, old)
        assert band.growth_rate_max == pytest.approx(r["growth_rate_max"], rel=1e-4)
        assert band.critical_gamma == pytest.approx(r["critical_gamma"],
                                                    abs=1e-6 * model.gamma)
