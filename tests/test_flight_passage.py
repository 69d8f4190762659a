"""flexbooster.flight.passage: growth accumulated while a region is open, and the peak of a
sweep through a damped resonance (docs/theory/flight.md).

Evidence: (1) exact integrals of piecewise-linear rates (closed form); (2) slow passage of a
mode through the principal Mathieu region: frozen-time Floquet growth rates
(flexbooster.floquet) integrated against direct integration of the non-periodic equation
(solve_ivp DOP853, rtol 1e-10), 5 % in log amplitude; (3) sweep through resonance against
solve_ivp (rtol 1e-10), 2 %, against the undamped Fresnel-integral solution (rotating-wave
approximation, Lewis 1932), 2 %, and tending to the steady peak as the sweep slows;
(4) invariants (step count) and bad input.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import scipy.linalg
from scipy.integrate import solve_ivp
from scipy.optimize import brentq
from scipy.special import fresnel, mathieu_a, mathieu_b

from flexbooster.flight import (
    accumulated_growth,
    crossing_peak_ratio,
    peak_ratio,
    steady_peak,
    step_maps,
    sweep_passage,
    sweep_response,
)
from flexbooster.floquet import StepLimitError, growth_rate

# ---------------------------------------------------------------- exact: piecewise-linear rates


def test_constant_rate_gives_rate_times_duration():
    """Closed form: sigma = 0.37 1/s for 12.5 s gives 4.625 e-folds, amplification
    exp(4.625), dwell the whole duration; tolerance 1e-14 relative."""
    p = accumulated_growth(np.linspace(3.0, 15.5, 7), np.full(7, 0.37))
    assert p.efolds == pytest.approx(0.37 * 12.5, rel=1e-14)
    assert p.amplification == pytest.approx(math.exp(0.37 * 12.5), rel=1e-14)
    assert (p.t_start, p.t_end, p.dwell) == (3.0, 15.5, pytest.approx(12.5, rel=1e-14))
    assert p.net_efolds == pytest.approx(p.efolds, rel=1e-14)


def test_rate_crossing_zero_between_knots():
    """Closed form: sigma = 0.2 (t - 3.3) on knots 0, 2, 4, ..., 10 (the zero at 3.3 lies
    between knots) gives e-folds 0.1 (10 - 3.3)^2 = 4.489, t_start = 3.3, dwell 6.7, and the
    signed integral 0.1 (6.7^2 - 3.3^2) = 3.4; tolerance 1e-13 relative."""
    t = np.arange(0.0, 10.1, 2.0)
    p = accumulated_growth(t, 0.2 * (t - 3.3))
    assert p.efolds == pytest.approx(0.1 * 6.7 ** 2, rel=1e-13)
    assert p.t_start == pytest.approx(3.3, rel=1e-13) and p.t_end == 10.0
    assert p.dwell == pytest.approx(6.7, rel=1e-13)
    assert p.net_efolds == pytest.approx(0.1 * (6.7 ** 2 - 3.3 ** 2), rel=1e-13)
    assert p.max_growth == pytest.approx(0.2 * 6.7, rel=1e-13)


def test_two_openings_and_a_closed_rate():
    """Closed form: a triangle of height 1 on [1, 3] and one of height 2 on [5, 7]: e-folds
    1 + 2 = 3, open from 1 to 7, dwell 4; a rate <= 0 throughout has no opening."""
    t = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0]
    s = [-1.0, 0.0, 1.0, 0.0, -0.5, 0.0, 2.0, 0.0]
    p = accumulated_growth(t, s)
    assert p.efolds == pytest.approx(3.0, rel=1e-14)
    assert (p.t_start, p.t_end, p.dwell) == (1.0, 7.0, pytest.approx(4.0, rel=1e-14))
    closed = accumulated_growth(t, -np.abs(s))
    assert (closed.efolds, closed.t_start, closed.t_end, closed.dwell) == (0.0, None, None, 0.0)


def test_tolerance_removes_round_off_of_a_neutral_system():
    """Exact: rates within +-tol count as 0, so round-off of a neutrally stable frozen system
    does not open a region; the e-folds then hold the rest exactly (0.5 * 2 * 1)."""
    t = [0.0, 1.0, 2.0, 3.0, 4.0]
    s = [1e-13, -1e-13, 1.0, 1.0, 1e-13]
    p = accumulated_growth(t, s, tol=1e-9)
    assert p.t_start == pytest.approx(1.0) and p.t_end == pytest.approx(4.0)
    assert p.efolds == pytest.approx(0.5 + 1.0 + 0.5, rel=1e-14)


def test_amplification_saturates_instead_of_overflowing():
    """No inf: 2000 e-folds give the largest float as amplification, the e-folds exact."""
    p = accumulated_growth([0.0, 1000.0], [2.0, 2.0])
    assert p.efolds == 2000.0 and math.isfinite(p.amplification) and p.amplification > 1e307


# ------------------------------------------------- independent model: slow passage, direct ODE


def _passage(T: float, zeta: float, n_frozen: int = 401):
    """x'' + 2 zeta w x' + w^2 (1 - 2 mu cos(Omega t)) x = 0, w = 0.85 -> 1.15 linearly over
    T, Omega = 2, mu = 0.1: the principal region 2 w / Omega in about 1 -+ mu / 2 is crossed
    in the middle. Returns (frozen-time passage, direct log amplitude end / start)."""
    mu, Om, w0, w1 = 0.1, 2.0, 0.85, 1.15

    def w_of(t):
        return w0 + (w1 - w0) * t / T

    ts = np.linspace(0.0, T, n_frozen)
    w = w_of(ts)
    # frozen-time Floquet growth rate: sigma(w, Omega) = w sigma(1, Omega / w) (time scaling)
    sigma = w * growth_rate(np.eye(1), 2.0 * zeta * np.eye(1), np.eye(1),
                            -2.0 * mu * np.eye(1), Om / w)
    passage = accumulated_growth(ts, sigma, tol=1e-9)

    def rhs(t, y):
        wt = w_of(t)
        return [y[1], -2.0 * zeta * wt * y[1] - wt * wt * (1.0 - 2.0 * mu * math.cos(Om * t))
                * y[0]]

    sol = solve_ivp(rhs, (0.0, T), [1.0, 0.0], method="DOP853", rtol=1e-10, atol=1e-14,
                    dense_output=True)
    assert sol.success

    def amplitude(t_end):  # energy-like norm sqrt((x'^2 + w^2 x^2) / w) over one period
        tt = np.linspace(t_end - 2.0 * math.pi / Om, t_end, 200)
        x, v = sol.sol(tt)
        wt = w_of(tt)
        return math.sqrt(np.mean((v * v + wt * wt * x * x) / wt))

    return passage, math.log(amplitude(T) / amplitude(2.0 * math.pi / Om))


@pytest.mark.slow
def test_slow_passage_through_the_principal_region_matches_direct_integration():
    """Independent model: the frozen-time e-folds (integral of max(sigma, 0), 401 frozen
    times) against the log amplitude of the non-periodic equation integrated directly
    (solve_ivp DOP853, rtol 1e-10); undamped, drift 0.3 in w over 1500 s (about 160
    forcing periods inside the region, so slow against its width). Tolerance 5 % in log
    amplitude. Closed form for the dwell: with tau = Omega t / 2 the frozen equation is
    Mathieu's with a = w^2, q = mu w^2 (Omega = 2), open for b1(q) < a < a1(q)
    (scipy.special.mathieu_b, mathieu_a); t_start and t_end within one frozen-time step."""
    passage, log_amp = _passage(1500.0, 0.0)
    assert passage.efolds > 15.0
    assert log_amp == pytest.approx(passage.efolds, rel=0.05)
    w_lo = math.sqrt(brentq(lambda a: a - mathieu_b(1, 0.1 * a), 0.5, 1.0))
    w_hi = math.sqrt(brentq(lambda a: a - mathieu_a(1, 0.1 * a), 1.0, 1.5))
    step = 1500.0 / 400
    assert passage.t_start == pytest.approx((w_lo - 0.85) / 0.3 * 1500.0, abs=step)
    assert passage.t_end == pytest.approx((w_hi - 0.85) / 0.3 * 1500.0, abs=step)


@pytest.mark.slow
def test_slow_damped_passage_matches_direct_integration():
    """Independent model: with damping zeta = 0.005 the motion decays outside the region at
    zeta w, so the direct log amplitude over the whole drift is the signed integral of the
    frozen-time rate (net_efolds), and the e-folds (positive part) exceed it. solve_ivp
    DOP853 rtol 1e-10, drift over 3000 s; tolerance 5 % in log amplitude."""
    passage, log_amp = _passage(3000.0, 0.005)
    assert log_amp == pytest.approx(passage.net_efolds, rel=0.05)
    assert passage.efolds > passage.net_efolds + 5.0


# ------------------------------------------------ forced resonance: sweep at a linear rate


def _ivp_peak(omega, zeta, f, Om0, Om1, T):
    """max |q| of the same sweep by solve_ivp DOP853 (rtol 1e-10) from the same steady start,
    sampled densely (the dense output at 40 points per period)."""
    al = (Om1 - Om0) / T
    H = f / (omega ** 2 - Om0 ** 2 + 2j * zeta * omega * Om0)

    def rhs(t, y):
        return [y[1], f * math.cos(Om0 * t + 0.5 * al * t * t) - 2.0 * zeta * omega * y[1]
                - omega * omega * y[0]]

    sol = solve_ivp(rhs, (0.0, T), [H.real, (1j * Om0 * H).real], method="DOP853", rtol=1e-10,
                    atol=1e-12 * abs(H), dense_output=True)
    assert sol.success
    tt = np.linspace(0.0, T, int(40 * max(Om0, Om1, omega) * T / (2 * math.pi)) + 2)
    return float(np.max(np.abs(sol.sol(tt)[0])))


@pytest.mark.parametrize("Om0, Om1, T", [(1.5, 2.5, 300.0), (2.6, 1.4, 60.0)])
def test_sweep_peak_matches_direct_integration(Om0, Om1, T):
    """Independent model: the peak of q'' + 2 zeta w q' + w^2 q = f cos(phi), phi' linear,
    w = 2 rad/s, zeta = 0.02, f = 3, upward and a faster downward sweep, against solve_ivp
    DOP853 rtol 1e-10 from the same steady start; tolerance 2 % (the required accuracy), and the
    peak below the steady one f / (2 zeta sqrt(1 - zeta^2) w^2)."""
    r = sweep_passage(omega=2.0, zeta=0.02, force=3.0, Omega_start=Om0, Omega_end=Om1,
                      duration=T)
    assert r.peak == pytest.approx(_ivp_peak(2.0, 0.02, 3.0, Om0, Om1, T), rel=0.02)
    assert r.steady_peak == pytest.approx(3.0 / (2 * 0.02 * math.sqrt(1 - 0.02 ** 2) * 4.0))
    assert r.peak < r.steady_peak
    assert min(Om0, Om1) < r.Omega_at_peak < max(Om0, Om1)


@pytest.mark.parametrize("alpha", [1e-3, 1e-4])
def test_undamped_sweep_peak_is_the_fresnel_envelope(alpha):
    """Closed form (Lewis 1932; rotating-wave approximation, error O(sqrt(alpha) / w)): an
    undamped mode swept at Omega' = alpha through Omega = w has the envelope
    f / (2 w) sqrt(pi / alpha) |C(x) + 1/2 + i (S(x) + 1/2)| (Fresnel integrals), largest
    1.6556 at x = 1.217; tolerance 2 %."""
    x = np.linspace(-10.0, 10.0, 200_001)
    S, C = fresnel(x)
    g_max = float(np.max(np.abs(C + 0.5 + 1j * (S + 0.5))))
    half = 12.0 * math.sqrt(alpha)
    _, q, _ = sweep_response(omega=1.0, zeta=0.0, force=1.0, Omega_start=1.0 - half,
                          Omega_end=1.0 + half, duration=2.0 * half / alpha)
    assert np.max(np.abs(q)) == pytest.approx(0.5 * math.sqrt(math.pi / alpha) * g_max,
                                              rel=0.02)


def test_peak_tends_to_the_steady_peak_as_the_sweep_slows():
    """Limit (Lewis 1932; Markert & Seidler 2001): the non-stationary peak over the steady
    one rises monotonically towards 1 as the dimensionless rate eta = alpha / w^2 falls
    (zeta = 0.02; eta / zeta^2 from 25 to 0.025), within 0.5 % of 1 at the slowest; a fast
    sweep reduces the peak by more than half."""
    ratios = [peak_ratio(0.02, eta) for eta in (1e-2, 1e-3, 1e-4, 1e-5)]
    assert np.all(np.diff(ratios) > 0.0)
    assert ratios[-1] == pytest.approx(1.0, abs=0.005) and ratios[-1] <= 1.0
    assert ratios[0] < 0.5
    # the same rate downward: within 5 % of the upward one (the direction matters little)
    assert peak_ratio(0.02, -1e-3) == pytest.approx(ratios[1], rel=0.05)


@pytest.mark.parametrize("w, zeta, h", [(2.0, 0.02, 0.05), (30.0, 0.0, 0.01), (1.0, 0.3, 0.2)])
def test_step_maps_equal_the_matrix_exponential(w, zeta, h):
    """Independent method: the closed-form first-order-hold maps against
    scipy.linalg.expm of the augmented matrix [[A h, B h, 0], [0, 0, 1], [0, 0, 0]]
    (Franklin, Powell, Workman sec. 6.3: blocks Phi, F1, F2); tolerance 1e-13 absolute on
    entries of order 1 / w^2..1."""
    Phi, Ga, Gb = step_maps([w], zeta, h)
    aug = np.zeros((4, 4))
    aug[:2, :2] = np.array([[0.0, 1.0], [-w * w, -2.0 * zeta * w]]) * h
    aug[1, 2] = h
    aug[2, 3] = 1.0
    E = scipy.linalg.expm(aug)
    np.testing.assert_allclose(Phi[0], E[:2, :2], atol=1e-13)
    np.testing.assert_allclose(Gb[0], E[:2, 3], atol=1e-13)
    np.testing.assert_allclose(Ga[0], E[:2, 2] - E[:2, 3], atol=1e-13)


def test_drifting_mode_sweep_matches_direct_integration():
    """Independent model: a mode drifting from 1.6 to 2.4 rad/s under a forcing sweeping from
    2.2 down to 1.8 rad/s in 80 s (zeta = 0.03): the peak |q| and |q''| of the stepped
    drifting equation (w at each step's midpoint) against solve_ivp DOP853 rtol 1e-10;
    tolerance 2 %; crossing_peak_ratio of the same drift within 2 % of the direct peak
    acceleration over its steady value."""
    kw = dict(omega=1.6, omega_end=2.4, zeta=0.03, force=1.0, Omega_start=2.2,
              Omega_end=1.8, duration=80.0)
    r = sweep_passage(**kw)
    wr, Wr = 0.8 / 80.0, -0.4 / 80.0
    H = 1.0 / (1.6 ** 2 - 2.2 ** 2 + 2j * 0.03 * 1.6 * 2.2)

    def rhs(t, y):
        w = 1.6 + wr * t
        return [y[1], math.cos(2.2 * t + 0.5 * Wr * t * t) - 2 * 0.03 * w * y[1] - w * w * y[0]]

    sol = solve_ivp(rhs, (0.0, 80.0), [H.real, (1j * 2.2 * H).real], method="DOP853",
                    rtol=1e-10, atol=1e-14, dense_output=True)
    tt = np.linspace(0.0, 80.0, 40001)
    q, v = sol.sol(tt)
    w = 1.6 + wr * tt
    acc = np.cos(2.2 * tt + 0.5 * Wr * tt * tt) - 2 * 0.03 * w * v - w * w * q
    assert r.peak == pytest.approx(np.max(np.abs(q)), rel=0.02)
    assert r.peak_acceleration == pytest.approx(np.max(np.abs(acc)), rel=0.02)
    # the crossing: 1.6 + wr t = 2.2 + Wr t at t = 40 s, w = 2.0
    ratio = crossing_peak_ratio(zeta=0.03, omega=2.0, omega_rate=wr, Omega_rate=Wr)
    assert ratio == pytest.approx(np.max(np.abs(acc)) / r.steady_peak_acceleration, rel=0.02)


def test_sweep_window_is_wide_enough(monkeypatch):
    """Invariant (range independence): doubling SWEEP_WINDOW (the sweep's start further below
    and its end further above the resonance) changes peak_ratio and crossing_peak_ratio by
    less than 1e-3 relative (zeta = 0.02, eta = 1e-3; measured 3e-4)."""
    from flexbooster.flight import passage

    base = (peak_ratio(0.02, 1e-3),
            crossing_peak_ratio(zeta=0.02, omega=1.0, omega_rate=1e-3, Omega_rate=0.0))
    monkeypatch.setattr(passage, "SWEEP_WINDOW", 2.0 * passage.SWEEP_WINDOW)
    wide = (peak_ratio(0.02, 1e-3),
            crossing_peak_ratio(zeta=0.02, omega=1.0, omega_rate=1e-3, Omega_rate=0.0))
    np.testing.assert_allclose(base, wide, rtol=1e-3)


def test_steps_per_cycle_converges():
    """Invariant: the sampled forcing's error falls like (2 pi / steps)^2; 64 and 512 steps per
    cycle agree to 1e-3 relative."""
    kw = dict(omega=2.0, zeta=0.02, force=3.0, Omega_start=1.5, Omega_end=2.5, duration=300.0)
    coarse = sweep_passage(**kw, steps_per_cycle=64)
    fine = sweep_passage(**kw, steps_per_cycle=512)
    assert coarse.peak == pytest.approx(fine.peak, rel=1e-3)
    assert steady_peak(2.0, 0.02, 3.0) == coarse.steady_peak


def test_sweep_bad_input():
    """Bad input: ValueError naming the parameter; a sweep past the step cap is a
    floquet.StepLimitError (a limit, deterministic)."""
    kw = dict(omega=2.0, zeta=0.02, force=3.0, Omega_start=1.5, Omega_end=2.5, duration=300.0)
    with pytest.raises(ValueError, match="^zeta"):
        sweep_passage(**{**kw, "zeta": 1.0})
    with pytest.raises(ValueError, match="^Omega_start"):
        sweep_passage(**{**kw, "Omega_start": 0.0})
    with pytest.raises(ValueError, match="^duration"):
        sweep_passage(**{**kw, "duration": float("inf")})
    with pytest.raises(ValueError, match="^force"):
        sweep_passage(**{**kw, "force": 0.0})
    with pytest.raises(StepLimitError):
        sweep_passage(**kw, max_steps=1000)
    with pytest.raises(ValueError, match="^eta"):
        peak_ratio(0.02, 0.0)
    with pytest.raises(ValueError, match="^omega_rate, Omega_rate"):
        crossing_peak_ratio(zeta=0.02, omega=2.0, omega_rate=0.1, Omega_rate=0.1)
    with pytest.raises(ValueError, match="^omega_end"):
        sweep_passage(**kw, omega_end=-1.0)
    with pytest.raises(ValueError, match="^sigma"):
        accumulated_growth([0.0, 1.0], [0.0, float("nan")])
    with pytest.raises(ValueError, match="^times"):
        accumulated_growth([1.0, 0.0], [0.0, 1.0])
