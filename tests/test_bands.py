"""Instability bands from their boundaries: rigid-body pitch and beam action.

Tiers: exact limits and closed forms (series of the transition curves, the Mathieu tongue
centres, Bolotin's critical amplitude), reference values (the band specification's Titan-class
numbers, Beal's follower flutter load), invariants (the band edges against a fine local scan
with an independent integrator; the pitch from the transition curves against the Floquet
toolkit with 1 x 1 matrices).  Every expected value names its source and tolerance.
"""

from __future__ import annotations

import json
import tomllib
from pathlib import Path

import numpy as np
import pytest

from flexbooster.case import load_case, memo_case
from flexbooster.errors import CaseError
from flexbooster.floquet import (
    critical_amplitude,
    growth_rate,
    hill_exponents,
    instability_regions,
    mathieu,
)
from flexbooster.floquet.multipliers import periodic_system
from flexbooster.memo import pitch
from flexbooster.memo.beam_action import (
    BAND_OMEGA_BAR_MIN,
    beam_action_bands,
    beam_system,
    follower_flutter_load,
    loaded_frequencies,
    monodromy_exponents,
    pipeline_bands,
    pitch_tongue_bands,
    uniform_beam_system,
)
from flexbooster.model import model_from_case

TITAN = Path(__file__).parent / "data" / "cases" / "titan-inch-pound.toml"


def _titan(**thrust):
    data = tomllib.loads(TITAN.read_text())
    data["thrust"]["n_omega"] = 40  # the bands must not depend on the grid
    data["thrust"].update(thrust)
    data["damping"] = {"modal_ratio": 0.0}  # the memo's undamped idealisation
    return load_case(data)


@pytest.fixture(scope="module")
def titan_model():
    return model_from_case(_titan())


# --------------------------------------------------------------------------------------------
# Rigid-body pitch
# --------------------------------------------------------------------------------------------
def _series_edge(gamma: float, sign: float) -> float:
    """x on the path x = a_1 (sign +1) or b_1 (sign -1) at q = gamma x / 2, A&S 20.2.25."""
    x = 1.0
    for _ in range(100):
        q = gamma * x / 2.0
        x = 1.0 + sign * q - q**2 / 8.0 - sign * q**3 / 64.0 - q**4 / 1536.0
    return x


@pytest.mark.parametrize("gamma", [0.002, 0.01, 0.02])
def test_first_tongue_edges_match_series_of_transition_curves(gamma):
    # A&S 20.2.25: a_1, b_1 = 1 +- q - q^2/8 -+ q^3/64 - q^4/1536 - ...; the omitted q^5 term
    # (coefficient ~1e-5) is below 1e-12 for q <= 0.01: edges to 1e-11 relative
    w = 3.7
    (band,) = pitch.pitch_bands(w, gamma, omega_min=5.0, omega_max=10.0)
    assert band.order == 1 and not band.clipped
    assert band.Omega_lo == pytest.approx(2 * w / np.sqrt(_series_edge(gamma, 1.0)), rel=1e-11)
    assert band.Omega_hi == pytest.approx(2 * w / np.sqrt(_series_edge(gamma, -1.0)), rel=1e-11)


def test_tongue_tips_at_gamma_zero_are_2_omega_psi_over_r():
    # exact limit: q = 0 makes the tongues the points a = r^2, Omega = 2 omega_psi / r
    w = 6.0
    for r in (1, 2, 3):
        assert pitch.pitch_band_edges(w, 0.0, tongue=r) == (2 * w / r, 2 * w / r)
    assert pitch.pitch_bands(w, 0.0, omega_min=1.0, omega_max=100.0) == ()


def test_titan_pitch_bands_specified_numbers(titan_model):
    # the band specification (Titan-class case, gamma = 0.05): pitch unstable 11.88-12.17 rad/s
    # with growth 0.075 1/s (to its rounding: +-0.005 rad/s, +-0.0005 1/s); tongues 2, 3 near
    # 2 omega_psi / 2 and 2 omega_psi / 3 (omega_psi = 6.013 rad/s) are also in the range
    res = pitch.pitch_analysis(titan_model.Omega, titan_model.omega_psi, titan_model.gamma)
    bands = {b.order: b for b in res.bands}
    assert sorted(bands) == [1, 2, 3]
    b1 = bands[1]
    assert b1.Omega_lo == pytest.approx(11.88, abs=0.005)
    assert b1.Omega_hi == pytest.approx(12.17, abs=0.006)
    assert b1.growth_rate_max == pytest.approx(0.075, abs=0.0005)
    assert res.unstable_intervals() == [(b.Omega_lo, b.Omega_hi) for b in res.bands]
    assert "UNSTABLE" in res.verdict
    d = json.loads(json.dumps(res.to_dict(), allow_nan=False))
    assert d["bands"][2]["order"] == 1 and d["unstable_intervals"][2] == [b1.Omega_lo,
                                                                            b1.Omega_hi]


def test_pitch_bands_do_not_depend_on_the_grid(titan_model):
    # the bands come from the range only: 40 and 4000 grid points give identical
    # edges and growth rates (exact equality)
    w, g = titan_model.omega_psi, titan_model.gamma
    lo, hi = titan_model.omega_range
    coarse = pitch.pitch_analysis(np.linspace(lo, hi, 40), w, g).bands
    fine = pitch.pitch_analysis(np.linspace(lo, hi, 4000), w, g).bands
    assert coarse == fine and len(coarse) == 3


def test_titan_pitch_band_at_gamma_0_3():
    # the band specification: with gamma = 0.3 the first band is "~11.11-12.89 rad/s"
    # (approximate: +-0.025)
    m = model_from_case(_titan(gamma=0.3))
    b1 = [b for b in pitch.pitch_analysis(m.Omega, m.omega_psi, 0.3).bands if b.order == 1][0]
    assert b1.Omega_lo == pytest.approx(11.11, abs=0.025)
    assert b1.Omega_hi == pytest.approx(12.89, abs=0.025)


def _scan_edge(stable, edge: float, width: float, rel: float = 1e-6) -> float:
    """The stability change on a local grid edge (1 + rel k), |k| <= min(20, 0.4 width/rel)."""
    half = int(min(20, max(2, np.floor(0.4 * width / (rel * edge)))))
    x = edge * (1.0 + rel * np.arange(-half, half + 1))
    flags = stable(x)
    change = np.flatnonzero(flags[1:] != flags[:-1])
    assert change.size == 1, f"no single stability change near {edge}"
    return 0.5 * (x[change[0]] + x[change[0] + 1])


def test_titan_pitch_bands_match_fine_scan(titan_model):
    # invariant: each exact edge against a local scan of the Floquet exponent (Magnus
    # integration, method "floquet": independent of the transition curves) with spacing 1e-6
    # relative: they agree to one spacing (1e-6 relative), as required of a fine scan
    w, g = titan_model.omega_psi, titan_model.gamma
    res = pitch.pitch_analysis(titan_model.Omega, w, g)

    def stable(om):
        a, q = pitch.mathieu_parameters(om, w, g)
        return np.imag(mathieu.characteristic_exponent(a, q, "floquet")) == 0.0

    for b in res.bands:
        for edge in (b.Omega_lo, b.Omega_hi):
            assert _scan_edge(stable, edge, b.width) == pytest.approx(edge, rel=1e-6)


@pytest.mark.parametrize(("gamma", "zeta"), [(0.05, 0.0), (0.3, 0.0), (0.3, 0.02)],
                         ids=["g0.05", "g0.3", "g0.3-damped"])
def test_pitch_bands_agree_with_floquet_toolkit_1x1(gamma, zeta):
    # invariant (two methods): psi'' + 2 zeta w psi' + w^2 (1 - gamma cos Omega t) psi = 0 as
    # the toolkit's M = 1, C = 2 zeta w, A = w^2, B = -gamma w^2; its edges are refined on
    # |rho| = 1 to rtol 1e-9 of the centre: agreement to 1e-7 relative
    w = 6.013
    lo, hi = 3.5, 20.0
    ours = pitch.pitch_bands(w, gamma, omega_min=lo, omega_max=hi, damping_ratio=zeta)
    C = None if zeta == 0.0 else [[2 * zeta * w]]
    theirs = instability_regions([[1.0]], C, [[w * w]], [[-gamma * w * w]], lo, hi)
    assert len(ours) == len(theirs) >= 1
    for b, r in zip(ours, theirs, strict=True):
        assert r.order == b.order
        assert b.Omega_lo == pytest.approx(r.omega_lo, rel=1e-7)
        assert b.Omega_hi == pytest.approx(r.omega_hi, rel=1e-7)
        assert b.growth_rate_max == pytest.approx(r.growth_rate_max, rel=1e-5)


@pytest.mark.parametrize("zeta", [0.002, 0.01])
def test_damped_pitch_critical_gamma_is_bolotin_delta_over_pi(zeta):
    # Bolotin (1964) sec. 6: the principal region of f'' + 2 eps f' + w^2 (1 - 2 mu cos) f = 0
    # exists for mu > mu_cr = Delta / pi, Delta = 2 pi zeta (logarithmic decrement, first order
    # in zeta); here 2 mu = gamma, so gamma_cr = 4 zeta (1 + O(zeta)): tolerance 2 zeta relative
    (b1,) = [b for b in pitch.pitch_bands(6.0, 0.05, omega_min=10.0, omega_max=14.0,
                                         damping_ratio=zeta)]
    assert b1.critical_gamma == pytest.approx(4.0 * zeta, rel=2.0 * zeta)
    # the damped band lies inside the undamped one (damping shrinks the regions)
    (u1,) = pitch.pitch_bands(6.0, 0.05, omega_min=10.0, omega_max=14.0)
    assert u1.Omega_lo < b1.Omega_lo < b1.Omega_hi < u1.Omega_hi
    assert b1.growth_rate_max < u1.growth_rate_max
    # just below the critical gamma the band is gone, just above it exists (1e-3 relative)
    below = pitch.pitch_band_edges(6.0, b1.critical_gamma * 0.999, tongue=1,
                                   damping_ratio=zeta)
    above = pitch.pitch_band_edges(6.0, b1.critical_gamma * 1.001, tongue=1,
                                   damping_ratio=zeta)
    assert below is None and above is not None


def test_damped_pitch_grid_flags_agree_with_the_bands():
    # invariant (two methods): the grid's damped stability (beta of a' = a (1 - zeta^2),
    # unstable where Im beta > zeta sqrt(a), Magnus integration) against the band edges
    # (Hill's determinant + brentq): a grid point is unstable iff it lies inside a band
    # (exact on a grid that avoids the edges by > 1e-9 relative)
    w, g, zeta = 6.0, 0.3, 0.02
    Omega = np.linspace(3.0, 20.0, 2001)
    res = pitch.pitch_analysis(Omega, w, g, damping_ratio=zeta)
    assert res.bands and res.damping_ratio == zeta
    inside = np.zeros(Omega.size, bool)
    for b in res.bands:
        assert np.min(np.abs(Omega - b.Omega_lo)) > 1e-9 * b.Omega_lo
        inside |= (Omega > b.Omega_lo) & (Omega < b.Omega_hi)
    assert np.array_equal(~res.stable, inside)
    assert np.all(res.growth_rate[~inside] == 0.0) and np.all(res.growth_rate[inside] > 0.0)


def test_damped_pitch_critical_gamma_agrees_with_toolkit():
    # invariant (two methods): floquet.critical_amplitude on the 1 x 1 system, gamma_rtol 1e-6
    w, zeta = 6.0, 0.01
    (b1,) = pitch.pitch_bands(w, 0.05, omega_min=10.0, omega_max=14.0, damping_ratio=zeta)
    (c,) = critical_amplitude([[1.0]], [[2 * zeta * w]], [[w * w]], [[-w * w]], gamma_max=0.05,
                              omega_min=10.0, omega_max=14.0)
    assert c.gamma_cr == pytest.approx(b1.critical_gamma, rel=1e-5)


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [({"gamma": 1.0}, "gamma"), ({"damping_ratio": -0.1}, "damping_ratio"),
     ({"omega_min": 5.0, "omega_max": 5.0}, "omega_min"), ({"omega_min": np.nan}, "omega_min")],
    ids=["gamma>=1", "zeta<0", "empty-range", "nan"],
)
def test_pitch_bands_validate_arguments(kwargs, match):
    args = {"gamma": 0.05, "omega_min": 1.0, "omega_max": 10.0} | kwargs
    with pytest.raises(ValueError, match=match):
        pitch.pitch_bands(6.0, args.pop("gamma"), **args)


# --------------------------------------------------------------------------------------------
# Beam action
# --------------------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def titan_beam_bands(titan_model):
    # the pipeline's band range, Omega >= omega_1 / 4 (BAND_OMEGA_BAR_MIN; 33 rad/s here);
    # below it the monodromy's cost grows as 1 / Omega (see docs/theory/bands.md)
    system = beam_system(titan_model)
    return system, beam_action_bands(system, titan_model.gamma,
                                     omega_min=BAND_OMEGA_BAR_MIN * system.omega_1,
                                     omega_max=titan_model.omega_range[1])


def test_titan_beam_action_band_at_2_omega_1(titan_beam_bands):
    # the band specification: beam action unstable near 264.87 rad/s = 2 omega_1 (simple
    # resonance of the first elastic mode, order 1); to its rounding: +-0.01 rad/s
    system, bands = titan_beam_bands
    simple = [b for b in bands
              if b.kind == "simple" and b.order == 1 and [m.index for m in b.modes] == [1]]
    assert len(simple) == 1
    b = simple[0]
    assert b.Omega_lo == pytest.approx(264.87, abs=0.01)
    assert b.Omega_lo < 2.0 * float(np.real(loaded_frequencies(system)[1])) * system.omega_1 \
        < b.Omega_hi
    assert b.growth_rate_max > 0.0 and b.critical_gamma == 0.0


def test_titan_beam_action_bands_match_fine_scan(titan_beam_bands):
    # invariant: each edge against a local scan (spacing 1e-6 relative) of the multipliers from
    # the beam-action module's own monodromy (Lawson RK4 over the half period, independent of
    # the toolkit's kernel); unstable where max Im alpha > 1e-9 (round-off of the stable
    # exponents is ~1e-12): the edges agree to one spacing, 1e-6 relative
    system, bands = titan_beam_bands
    assert len(bands) >= 4

    def stable(om):
        alpha = monodromy_exponents(system, om, np.full(om.shape, 0.05), step_phase=0.03)
        return np.max(np.abs(alpha.imag), axis=1) <= 1e-9

    for b in bands:
        if b.width < 1e-5 * b.Omega_lo:  # fewer than 10 scan points across
            continue
        for edge in (b.Omega_lo, b.Omega_hi):
            assert _scan_edge(stable, edge, b.width) == pytest.approx(edge, rel=1e-6)


@pytest.fixture(scope="module")
def titan_tongues(titan_model):
    system = beam_system(titan_model)
    return system, pitch_tongue_bands(system, titan_model.gamma,
                                      omega_min=titan_model.omega_range[0],
                                      omega_max=BAND_OMEGA_BAR_MIN * system.omega_1)


@pytest.mark.slow
def test_titan_coupled_pitch_tongue_against_the_monodromy(titan_tongues):
    # below omega_1 / 4 the coupled pitch tongue (harmonic balance + Hill) against the
    # beam-action module's own monodromy (Lawson RK4, step_phase 0.03; neither harmonic
    # balance nor Hill): unstable just inside each edge and stable just outside (1e-7
    # relative), and the growth rate at the maximum to 1e-6 relative
    system, tongues = titan_tongues
    (b,) = [t for t in tongues if t.order == 1]
    assert (b.kind, [m.index for m in b.modes]) == ("simple", [0])
    assert b.Omega_lo < b.Omega_center < b.Omega_hi
    om = np.array([b.Omega_lo * (1 - 1e-7), b.Omega_lo * (1 + 1e-7),
                   b.Omega_hi * (1 - 1e-7), b.Omega_hi * (1 + 1e-7), b.Omega_at_max])
    alpha = monodromy_exponents(system, om, np.full(om.size, 0.05), step_phase=0.03)
    growth = np.max(np.abs(alpha.imag), axis=1) * om  # 1/s (Im alpha Omega, as the module)
    assert list(growth[:4] > 1e-9) == [False, True, True, False]
    assert b.growth_rate_max == pytest.approx(growth[4], rel=1e-6)
    # and the uncoupled pitch tongue (memo 4.2, exact Mathieu) is 0.5 % away: coupling
    assert b.Omega_lo == pytest.approx(11.875, rel=0.01)


def test_titan_second_pitch_tongue_is_inside_its_window(titan_tongues):
    # tongue r = 2 near Omega = omega_p (period T): narrow (width ~ gamma^2), tip inside
    system, tongues = titan_tongues
    (b,) = [t for t in tongues if t.order == 2]
    assert b.Omega_lo < b.Omega_center < b.Omega_hi
    assert b.width < 1e-2 * b.Omega_center
    assert 0.0 < b.growth_rate_max < [t for t in tongues if t.order == 1][0].growth_rate_max


@pytest.mark.slow
def test_damped_pitch_tongue_has_bolotins_critical_gamma(titan_model):
    # Bolotin (1964) sec. 6: the principal tongue of q'' + 2 zeta w q' + w^2 (1 - gamma cos) q
    # exists above gamma_cr = 4 zeta to first order (mu_cr = Delta / pi, 2 mu = gamma,
    # Delta = 2 pi zeta); the coupled pitch mode is nearly the rigid one: 5 %; and the damped
    # tongue lies inside the undamped one
    system = beam_system(titan_model)
    args = {"omega_min": 10.0, "omega_max": 14.0}
    (u,) = pitch_tongue_bands(system, 0.05, **args)
    (d,) = pitch_tongue_bands(system, 0.05, beam_ratio=0.001, pitch_ratio=0.002, **args)
    assert u.Omega_lo < d.Omega_lo < d.Omega_hi < u.Omega_hi
    assert d.critical_gamma == pytest.approx(4 * 0.002, rel=0.05)
    assert d.growth_rate_max < u.growth_rate_max
    assert pitch_tongue_bands(system, 0.9 * d.critical_gamma, beam_ratio=0.001,
                              pitch_ratio=0.002, **args) == ()


@pytest.mark.slow
@pytest.mark.slow
def test_pipeline_bands_hold_the_coupled_tongue_below_omega_1_over_4(titan_model):
    # The coupled rigid-pitch tongues r = 3, 2, 1 below omega_1 / 4 (harmonic balance).  Tongue
    # 3 lies wholly below its tip 2 omega_p / 3 (Mathieu a_3, b_3 = 9 + q^2/16 +- q^3/64, A&S
    # 20.2.25); it was missed until the search followed the pitch-only tongue.  Independent
    # check: the toolkit's monodromy of the full system (floquet.growth_rate) is 0 at 1e-6
    # outside each edge, > 0 at 1e-6 inside, and equals the reported largest growth rate at
    # omega_at_max to 1e-6 relative (measured 2e-8).
    bands = pipeline_bands(titan_model)
    s = beam_system(titan_model)
    w1, n = float(s.omega_1), s.A0.shape[0]
    low = [b for b in bands if b.Omega_hi < BAND_OMEGA_BAR_MIN * w1]
    assert [b.order for b in low] == [3, 2, 1]  # the resolved tongues, by omega_lo
    assert [b.Omega_lo for b in bands] == sorted(b.Omega_lo for b in bands)
    mats = (np.eye(n), None, s.A0, -titan_model.gamma * s.B)
    for b in low:
        pts = np.array([b.Omega_lo * (1 - 1e-6), b.Omega_lo * (1 + 1e-6), b.Omega_at_max,
                        b.Omega_hi * (1 - 1e-6), b.Omega_hi * (1 + 1e-6)]) / w1
        g = growth_rate(*mats, pts) * w1  # 1/tau -> 1/s
        assert g[0] < 1e-12 and g[4] < 1e-12 and g[1] > 0.0 and g[3] > 0.0
        assert g[2] == pytest.approx(b.growth_rate_max, rel=1e-6)


@pytest.mark.slow
def test_memo_case_narrow_bands_confirmed_by_hill():
    # the memo case's bands over [omega_1 / 4, omega_max]: 50 (18 before the narrow-region
    # search; those 18 are unchanged, bitwise).  The 33 narrower than 6e-8 / j of their centre
    # (relative widths 1e-14 .. 5e-8; all but one, sum 2+5 j = 1 at 5.3e-8, from the
    # harmonic-balance pair of floquet/narrow.py): Hill's method (S = 8, an independent
    # eigenproblem of the full system) gives the same growth rate at each vertex, to 1 % for
    # widths >= 1e-12 (measured 3e-3) and 30 % below (Hill's round-off, ~1e-14 / tau, is
    # comparable there; the band at 3.5e-14 relative, growth 9e-15, below it, is skipped)
    model = model_from_case(memo_case())
    s = beam_system(model)
    w1, n = float(s.omega_1), s.A0.shape[0]
    lo = max(model.omega_range[0], BAND_OMEGA_BAR_MIN * w1)
    mats = (np.eye(n), None, s.A0, -model.gamma * s.B)
    regions = instability_regions(*mats, lo / w1, model.omega_range[1] / w1)
    narrow = [r for r in regions if r.width < 6e-8 / r.order * r.omega_center]
    assert len(regions) == 50 and len(narrow) == 33
    g = np.max(hill_exponents(*mats, [r.omega_at_max for r in narrow], n_harmonics=8).real, -1)
    for r, gh in zip(narrow, g, strict=True):
        if r.growth_rate_max < 2e-14:
            continue
        rel = 0.01 if r.width >= 1e-12 * r.omega_center else 0.3
        assert r.growth_rate_max == pytest.approx(gh, rel=rel)


def test_beal_follower_flutter_is_the_gamma_zero_limit_of_the_regions():
    # Beal (1965): the free-free beam under a follower end force flutters at p = 109.69 EI/l^2;
    # the N-mode Galerkin value p_N (N = 8) converges from above.  Just above it (1e-3
    # relative) the steady system itself is unstable: one "steady" region over the whole
    # range at gamma -> 0 (1e-9); just below, no steady region, only the parametric regions of
    # order 1, ~1e-8 of their centre wide at gamma = 1e-9 (below the monodromy's round-off
    # floor: the narrow-region search finds them).  Their widths are the first-order ones,
    # Bolotin's |Bt_ii| / omega_i (simple) and Hsu's sqrt(|Bt_ik Bt_ki| / (omega_i omega_k))
    # (combination), exact to O(gamma) = 1e-9: asserted to 1e-5 relative (measured 4e-7)
    N = 8
    p_n = follower_flutter_load(N)
    assert p_n == pytest.approx(109.69, rel=0.02)
    for factor, expect_steady in ((1.001, True), (0.999, False)):
        s = uniform_beam_system(p_n * factor, K=0.0, N=N)
        A, B = s.A0[:N, :N], s.B[:N, :N]  # K = 0: the rigid rotation decouples
        regs = instability_regions(np.eye(N), None, A, -1e-9 * B, 0.5, 6.0)
        if expect_steady:
            assert [r.kind for r in regs] == ["steady"]
        else:
            ps = periodic_system(np.eye(N), None, A, -1e-9 * B)
            w, Bt = np.sqrt(ps.mu.real), ps.Bt
            assert regs and all(r.kind != "steady" and r.order == 1 for r in regs)
            for r in regs:
                i, k = r.modes[0], r.modes[-1]
                first = np.sqrt(abs(Bt[i, k] * Bt[k, i]) / (w[i] * w[k]))
                assert r.width == pytest.approx(first, rel=1e-5)


@pytest.mark.slow
def test_beam_damping_shrinks_regions_and_sets_critical_gamma():
    # Bolotin (1964) sec. 6: damping makes a region appear only above a critical gamma; for the
    # sum resonance of modes 0 + 1 of the memo case with equal modal damping rates
    # zeta_0 omega_0 = zeta_1 omega_1 = eps the region narrows (with unequal rates a
    # combination region can widen: Nayfeh & Mook 1979, sec. 5.7), and to first order in gamma
    # the growth rate is the undamped one (proportional to gamma) minus eps, so
    # gamma_cr = gamma eps / g_max(gamma) (tolerance 5 %: first order only)
    system = beam_system(model_from_case(memo_case()))
    w = np.real(loaded_frequencies(system)) * system.omega_1
    centre = w[0] + w[1]
    lo, hi = 0.999 * centre, 1.001 * centre
    (u,) = beam_action_bands(system, 0.05, omega_min=lo, omega_max=hi)
    zb = 1e-5
    eps = zb * w[1]  # 1.1e-3 1/s, below the band's growth 2.8e-3 1/s
    zp = eps / w[0]
    (d,) = beam_action_bands(system, 0.05, omega_min=lo, omega_max=hi, beam_ratio=zb,
                             pitch_ratio=zp)
    assert [(x.kind, [m.index for m in x.modes]) for x in (u, d)] == [("sum", [0, 1])] * 2
    assert u.Omega_lo < d.Omega_lo < d.Omega_hi < u.Omega_hi
    assert u.critical_gamma == 0.0
    assert d.critical_gamma == pytest.approx(0.05 * eps / u.growth_rate_max, rel=0.05)
    # below the critical amplitude (10 % margin) the band is gone
    assert beam_action_bands(system, 0.9 * d.critical_gamma, omega_min=lo, omega_max=hi,
                             beam_ratio=zb, pitch_ratio=zp) == ()


# --------------------------------------------------------------------------------------------
# Pipeline
# --------------------------------------------------------------------------------------------
@pytest.mark.slow
def test_results_json_holds_the_bands(memo_results):
    # the verdicts follow from the bands: beam action "unstable" iff a band exists;
    # the memo case's pitch tongues lie below its range (2 omega_psi = 2.4 < 5 rad/s)
    d = json.loads(json.dumps(memo_results.to_dict(), allow_nan=False))
    ba = d["beam_action"]
    assert ba["bands"] and ba["verdict"] == "unstable"
    assert ba["unstable_intervals"] == [[b["Omega_lo"], b["Omega_hi"]] for b in ba["bands"]]
    assert {"Omega_lo", "Omega_hi", "width", "growth_rate_max", "critical_gamma", "kind",
            "modes", "order"} <= set(ba["bands"][0])
    assert d["pitch"]["bands"] == [] and d["pitch"]["unstable_intervals"] == []
    assert "stable" in d["pitch"]["verdict"]
    for b in ba["bands"]:  # inside the case's range, edges ordered
        assert 5.0 <= b["Omega_lo"] < b["Omega_hi"] <= 2000.0


@pytest.mark.slow
def test_beam_action_chart_tips_are_the_resonance_centres(memo_case_dict):
    # exact limit: without damping each region grows out of its analytic centre at gamma = 0
    # (2 omega_i or omega_i + omega_k for order 1), and widens with gamma (Bolotin 1964 ch. 1);
    # centres from the loaded frequencies to 1e-12 relative
    from flexbooster.memo.charts import beam_action_chart

    memo_case_dict["damping"] = {"modal_ratio": 0.0}  # the memo case undamped
    model = model_from_case(load_case(memo_case_dict))
    chart = beam_action_chart(model)
    system = beam_system(model)
    w = np.real(loaded_frequencies(system)) * system.omega_1
    centres = np.concatenate([2 * w, (w[:, None] + w[None, :])[np.triu_indices(w.size, 1)],
                              np.abs(w[:, None] - w[None, :])[np.triu_indices(w.size, 1)]])
    assert chart.regions
    for reg in chart.regions:
        assert reg.gamma[0] == 0.0 and reg.omega_lo[0] == reg.omega_hi[0]
        assert np.min(np.abs(centres - reg.omega_lo[0]) / reg.omega_lo[0]) < 1e-12
        assert np.all(np.diff(reg.omega_hi - reg.omega_lo) > 0.0)
    assert chart.gamma_operating == 0.05


def test_pitch_band_chart_traces_the_titan_tongues(titan_model):
    # the tongue tips are at 2 omega_psi / r (exact, gamma = 0) and at gamma = 0.3 (a level of
    # the 46-level grid) the first tongue's edges are the specified ~11.11-12.89 rad/s (+-0.025)
    from flexbooster.memo.charts import pitch_band_chart

    chart = pitch_band_chart(titan_model)
    labels = [r.label for r in chart.regions]
    assert labels[:3] == ["tongue 1", "tongue 2", "tongue 3"]
    t1 = chart.regions[0]
    assert t1.omega_lo[0] == t1.omega_hi[0] == 2.0 * titan_model.omega_psi
    k = int(np.flatnonzero(np.isclose(t1.gamma, 0.3))[0])
    assert t1.omega_lo[k] == pytest.approx(11.11, abs=0.025)
    assert t1.omega_hi[k] == pytest.approx(12.89, abs=0.025)


@pytest.mark.parametrize(("field", "value"), [("beam_modal_ratio", -0.01), ("pitch_ratio", 1.0)])
def test_damping_fields_are_validated(field, value):
    data = tomllib.loads(TITAN.read_text())
    data["damping"] = {field: value}
    with pytest.raises(CaseError, match=field):
        load_case(data)


def test_damping_fields_reach_the_model():
    data = tomllib.loads(TITAN.read_text())
    data["damping"] = {"modal_ratio": 0.03, "pitch_ratio": 0.02}
    m = model_from_case(load_case(data))
    assert (m.beam_damping_ratio, m.pitch_damping_ratio) == (0.03, 0.02)
    data["damping"] = {"beam_modal_ratio": 0.04}  # the deprecated key: used, with a warning
    m = model_from_case(load_case(data))
    assert (m.beam_damping_ratio, m.pitch_damping_ratio) == (0.04, 0.0)
    assert model_from_case(memo_case()).beam_damping_ratio == 0.01  # 1 % by default
