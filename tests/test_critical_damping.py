"""The critical damping ratio of an instability region (flexbooster.floquet.critical_damping and
flexbooster.dynamics.region_critical_damping): against an independent damped-Mathieu Floquet
computation (scipy's solve_ivp monodromy, its growth maximised by scipy and the root in zeta by
brentq), against Bolotin's first-order threshold on a loaded cylinder, and its invariants."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq, minimize_scalar

from flexbooster import floquet
from flexbooster.bands import NEGLIGIBLE_GROWTH
from flexbooster.dynamics import region_critical_damping, vehicle_regions
from test_vehicle_regions import SD_MESH, sd_loaded_mode, sd_vehicle

W, GAMMA = 10.0, 0.1  # q'' + 2 zeta W q' + W^2 (1 - GAMMA cos Omega t) q = 0


def _growth_ivp(zeta: float, omega: float) -> float:
    """log|rho|_max / T of the 1-DOF damped Mathieu equation: the monodromy by solve_ivp
    (DOP853, rtol 1e-12), independent of the toolkit's Lawson kernel."""
    T = 2.0 * np.pi / omega

    def rhs(t, y):
        return [y[1], -2.0 * zeta * W * y[1] - W * W * (1.0 - GAMMA * np.cos(omega * t)) * y[0]]

    cols = [solve_ivp(rhs, (0.0, T), e, method="DOP853", rtol=1e-12, atol=1e-14).y[:, -1]
            for e in ([1.0, 0.0], [0.0, 1.0])]
    rho = np.linalg.eigvals(np.column_stack(cols))
    return float(np.log(np.max(np.abs(rho))) / T)


def test_mathieu_critical_damping_against_an_independent_floquet_computation():
    # the principal region about Omega = 2 W; the reference: brentq in zeta of the growth
    # maximised over Omega (scipy, bounded, xatol 1e-7) with the solve_ivp monodromy; the
    # required accuracy, 1e-4 relative
    lo, hi = 19.4, 20.6  # contains the undamped region (19.497..20.497, the toolkit's search)
    regions = floquet.instability_regions(np.eye(1), None, np.array([[W * W]]),
                                          np.array([[-GAMMA * W * W]]), 15.0, 25.0)
    assert len(regions) == 1 and lo < regions[0].omega_lo < regions[0].omega_hi < hi

    def peak(zeta):
        best = minimize_scalar(lambda om: -_growth_ivp(zeta, om), bounds=(lo, hi),
                               method="bounded", options={"xatol": 1e-7})
        return -best.fun

    reference = brentq(peak, 0.02, 0.03, xtol=1e-9)
    found = floquet.critical_damping(np.eye(1), np.array([[2.0 * W]]), np.array([[W * W]]),
                                     np.array([[-GAMMA * W * W]]),
                                     omega_lo=regions[0].omega_lo, omega_hi=regions[0].omega_hi)
    assert found == pytest.approx(reference, rel=1e-4)
    # Bolotin's first approximation (1964, sec. 6): mu_cr = 2 zeta with mu = GAMMA / 2, so
    # zeta_cr = GAMMA / 4, to O(GAMMA) relative
    assert found == pytest.approx(GAMMA / 4.0, rel=GAMMA)


def test_critical_damping_from_a_damped_start_is_the_same_threshold():
    # starting from a damping at which the region is still open (half the threshold) gives
    # the same root: the threshold does not depend on where the search starts (invariant)
    M, C1, A = np.eye(1), np.array([[2.0 * W]]), np.array([[W * W]])
    B = np.array([[-GAMMA * W * W]])
    undamped = floquet.critical_damping(M, C1, A, B, omega_lo=19.49, omega_hi=20.5)
    half = 0.5 * undamped
    (region,) = floquet.instability_regions(M, half * C1, A, B, 15.0, 25.0)
    damped = floquet.critical_damping(M, C1, A, B, omega_lo=region.omega_lo,
                                      omega_hi=region.omega_hi, zeta=half)
    assert damped == pytest.approx(undamped, rel=1e-5)


def test_still_open_at_the_largest_damping_searched_is_none():
    # zeta_max = 1e-3 is far below the threshold GAMMA / 4 (above): no root in (0, 1e-3]
    assert floquet.critical_damping(np.eye(1), np.array([[2.0 * W]]), np.array([[W * W]]),
                                    np.array([[-GAMMA * W * W]]), omega_lo=19.49,
                                    omega_hi=20.5, zeta_max=1e-3) is None


@pytest.mark.parametrize("kwargs, name", [
    ({"omega_lo": 2.0, "omega_hi": 1.0}, "omega_lo"),
    ({"omega_lo": 19.5, "omega_hi": 20.5, "zeta": 0.5, "zeta_max": 0.4}, "zeta"),
    ({"omega_lo": 19.5, "omega_hi": 20.5, "rtol": 0.5}, "rtol"),
    ({"omega_lo": 19.5, "omega_hi": 20.5, "zeta_max": 2.0}, "zeta_max"),
])
def test_bad_arguments_are_named(kwargs, name):
    with pytest.raises(ValueError, match=name):
        floquet.critical_damping(np.eye(1), np.array([[2.0 * W]]), np.array([[W * W]]),
                                 np.array([[-GAMMA * W * W]]), **kwargs)


def test_a_closed_region_is_refused():
    # at zeta = 0.05 > GAMMA / 4 the principal region is closed: nothing to close
    with pytest.raises(ValueError, match="not open"):
        floquet.critical_damping(np.eye(1), np.array([[2.0 * W]]), np.array([[W * W]]),
                                 np.array([[-GAMMA * W * W]]), omega_lo=19.5, omega_hi=20.5,
                                 zeta=0.05)


@pytest.mark.parametrize("k", [4, 6])
def test_loaded_cylinder_region_against_bolotin_first_order(k):
    # one loaded shear-diaphragm mode: q'' + 2 zeta w q' + w^2 (1 - 2 mu cos Omega t) q = 0
    # with mu = gamma P0 s / (2 w^2) (sd_loaded_mode, closed form); Bolotin 1964, sec. 6:
    # zeta_cr = mu / 2 to first order, here within mu relative
    P0, w_l, slope = sd_loaded_mode(k)
    gamma = 0.02
    mu = gamma * P0 * slope / (2.0 * w_l**2)
    found = vehicle_regions(sd_vehicle(), gamma=gamma, F0=P0, omega_min=1.5 * w_l,
                            omega_max=2.5 * w_l, k_min=k, k_max=k, n_modes=1, damping_ratio=0.0,
                            supported_forward_end=True, elements_per_segment=SD_MESH,
                            max_order=1)
    (region,) = region_critical_damping(found).regions
    assert region.critical_damping_ratio == pytest.approx(mu / 2.0, rel=mu)
    (h,) = found.harmonics
    # the damping per unit ratio is the one the harmonic's C is built from: C = zeta C1
    damped = vehicle_regions(sd_vehicle(), gamma=gamma, F0=P0, omega_min=1.5 * w_l,
                             omega_max=2.5 * w_l, k_min=k, k_max=k, n_modes=1,
                             damping_ratio=0.003, supported_forward_end=True,
                             elements_per_segment=SD_MESH, max_order=1)
    np.testing.assert_allclose(0.003 * damped.harmonics[0].damping_per_ratio,
                               damped.harmonics[0].damping, rtol=1e-14)
    assert h.damping_per_ratio.shape == (1, 1)


def test_the_limit_and_floor_leave_regions_without_a_value():
    P0, w_l, _ = sd_loaded_mode(4)
    found = vehicle_regions(sd_vehicle(), gamma=0.02, F0=P0, omega_min=1.5 * w_l,
                            omega_max=2.5 * w_l, k_min=4, k_max=4, n_modes=1, damping_ratio=0.0,
                            supported_forward_end=True, elements_per_segment=SD_MESH,
                            max_order=1)
    assert region_critical_damping(found, limit=0).regions[0].critical_damping_ratio is None
    top = found.regions[0].growth_rate_max
    assert region_critical_damping(found, growth_floor=2.0 * top).regions[0] \
        .critical_damping_ratio is None


def test_a_fixed_damping_part_adds_to_the_scaled_one():
    # C0 + zeta C1 with C0 = 0.01 C1 is the damping (zeta + 0.01) C1: the threshold in zeta is
    # the one without C0 less 0.01 (exact, the same equation)
    M, C1, A = np.eye(1), np.array([[2.0 * W]]), np.array([[W * W]])
    B = np.array([[-GAMMA * W * W]])
    plain = floquet.critical_damping(M, C1, A, B, omega_lo=19.49, omega_hi=20.5)
    (region,) = floquet.instability_regions(M, 0.01 * C1, A, B, 15.0, 25.0)
    shifted = floquet.critical_damping(M, C1, A, B, omega_lo=region.omega_lo,
                                       omega_hi=region.omega_hi, C0=0.01 * C1)
    assert shifted == pytest.approx(plain - 0.01, rel=1e-5)


@pytest.mark.slow
def test_beam_action_simple_band_against_the_first_order_damping_shift():
    # a uniform free-free beam under thrust (Beal 1965), undamped: in a narrow simple region of
    # order j of bending mode m the growth at modal damping zeta is sigma - zeta omega_m to
    # first order (the substitution q = exp(-zeta omega_m t) y, Bolotin 1964, sec. 6), so the
    # band closes at zeta_cr = sigma_max / omega_m, omega_m = j Omega_center / 2; the bands are
    # ~1e-5 wide relative, first-order error well under the 5e-3 asked
    from flexbooster.memo.beam_action import (
        band_critical_damping,
        beam_action_bands,
        uniform_beam_system,
    )

    system = uniform_beam_system(2.0, K=0.5, N=3, omega_1=100.0)
    found = beam_action_bands(system, 0.05, omega_min=150.0, omega_max=500.0)
    done = band_critical_damping(system, found, gamma=0.05)
    simple = [b for b in done if b.kind == "simple" and b.modes[0].index != 0]
    counted = [b for b in simple if b.growth_rate_max > NEGLIGIBLE_GROWTH]
    assert counted and len(counted) <= 8
    # below the floor (an e-folding time over 1e6 s) nothing is computed
    assert all(b.critical_damping_ratio is None for b in simple if b not in counted)
    for b in counted:
        assert b.critical_damping_ratio == pytest.approx(
            b.growth_rate_max / (0.5 * b.order * b.Omega_center), rel=5e-3)
    # a band holding the undamped rigid pitch: no elastic damping closes it (None)
    with_pitch = [b for b in done if any(m.index == 0 for m in b.modes)]
    assert with_pitch and all(b.critical_damping_ratio is None for b in with_pitch)


def test_certified_margin_is_a_lower_bound_of_the_closed_form_threshold():
    # one loaded shear-diaphragm mode with modal damping zeta: its principal region opens at
    # gamma_cr = 4 zeta w^2 / (P0 s) (Bolotin 1964, sec. 6, first order; sd_loaded_mode closed
    # form, checked to 1e-5 in test_vehicle_regions); the stability certificate's margin is a
    # lower bound of gamma_cr / gamma, and the danger verdict states it
    from flexbooster.danger import danger_summary

    zeta, gamma = 0.01, 0.002
    P0, w_l, slope = sd_loaded_mode(4)
    g_cr = 4.0 * zeta * w_l**2 / (P0 * slope)
    found = vehicle_regions(sd_vehicle(), gamma=gamma, F0=P0, omega_min=1.5 * w_l,
                            omega_max=2.5 * w_l, k_min=4, k_max=4, n_modes=1,
                            damping_ratio=zeta, supported_forward_end=True,
                            elements_per_segment=SD_MESH, max_order=1)
    assert found.regions == () and gamma < g_cr
    margin = found.certified_margin
    assert margin is not None and 1.0 < margin <= (g_cr / gamma) * (1.0 + zeta)
    summary = danger_summary(operating_range=(1.5 * w_l, 2.5 * w_l), bands={"vehicle": ()},
                             gamma=gamma, modal_ratio=zeta, certified={"vehicle": margin})
    (words,) = [v for k, _, v in summary.verdicts if k == "vehicle"]
    assert words.startswith("stable")
    assert f"margin on gamma at least {margin:.3g} at every Omega" in words
    # undamped: nothing is certified
    undamped = vehicle_regions(sd_vehicle(), gamma=gamma, F0=P0, omega_min=1.5 * w_l,
                               omega_max=2.5 * w_l, k_min=4, k_max=4, n_modes=1,
                               damping_ratio=0.0, supported_forward_end=True,
                               elements_per_segment=SD_MESH, max_order=1)
    assert undamped.certified_margin is None
