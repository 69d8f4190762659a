"""The overall verdict and the per-band measures (flexbooster.danger, docs/theory/verdicts.md).

Tiers: an independent model (the damped Mathieu equation's Floquet multipliers from a monodromy
integrated by scipy's solve_ivp, its critical damping and critical gamma by brentq, written
here) against the pitch bands' critical values; exact rules on synthetic bands (the statuses
and the overall verdict follow from the stated floors); the damping input (defaults, the
deprecated keys' warning reaching results.json).
"""

from __future__ import annotations

import dataclasses
import json
import math
import tomllib

import numpy as np
import pytest
from scipy import integrate, optimize

from flexbooster.analysis import analyze
from flexbooster.bands import Band, SearchGap
from flexbooster.case import load_case, memo_case, memo_case_text
from flexbooster.danger import (
    NEGLIGIBLE_GROWTH,
    UNSTABLE_E_FOLDING,
    RankedBand,
    ResponsePeak,
    axial_resonance_peaks,
    band_measures,
    band_status,
    danger_bands,
    danger_summary,
    event_status,
    flight_verdict,
    g_text,
    hz_text,
    merge_responses,
)
from flexbooster.dynamics import STANDARD_GRAVITY
from flexbooster.dynamics.axial import AxialResonance
from flexbooster.flight import FlightEvent, band_events
from flexbooster.memo.beam_action import band_modes
from flexbooster.memo.pitch import PITCH_MODE, pitch_bands
from flexbooster.memo.severity import FAMILY_CAUSES, shell_mode

OPERATING = (10.0, 100.0)


# --------------------------------------------------------------------------------------------
# Independent model: the damped Mathieu equation by direct integration
# --------------------------------------------------------------------------------------------
def _log_rho(Omega: float, w: float, gamma: float, zeta: float) -> float:
    """ln of the largest |Floquet multiplier| of psi'' + 2 zeta w psi' + w^2 (1 - gamma
    cos Omega t) psi = 0: the monodromy over T = 2 pi / Omega by solve_ivp (DOP853, rtol
    1e-12), both columns at once."""
    def rhs(t, y):
        k = w * w * (1.0 - gamma * math.cos(Omega * t))
        return [y[1], -2.0 * zeta * w * y[1] - k * y[0], y[3], -2.0 * zeta * w * y[3] - k * y[2]]

    T = 2.0 * math.pi / Omega
    sol = integrate.solve_ivp(rhs, (0.0, T), [1.0, 0.0, 0.0, 1.0], method="DOP853",
                              rtol=1e-12, atol=1e-14)
    Phi = sol.y[:, -1].reshape(2, 2).T
    return float(np.log(np.max(np.abs(np.linalg.eigvals(Phi)))))


def _peak(w: float, gamma: float, zeta: float) -> float:
    """Largest ln|rho| over Omega about the principal tongue's centre 2 w sqrt(1 - zeta^2)."""
    c = 2.0 * w
    res = optimize.minimize_scalar(lambda om: -_log_rho(om, w, gamma, zeta),
                                   bounds=(c * (1.0 - 0.3 * gamma), c * (1.0 + 0.3 * gamma)),
                                   method="bounded", options={"xatol": 1e-9 * c})
    return -float(res.fun)


def test_pitch_principal_region_critical_damping_and_gamma_against_direct_floquet():
    """The rigid-pitch principal region (Mathieu tongue 1) of a damped case: its critical
    damping ratio (the smallest closing it at gamma) and its critical gamma at the case's
    damping against an independent computation (monodromy by solve_ivp, the largest
    multiplier maximised over Omega, brentq on |rho| = 1), to 1e-4 relative."""
    w, gamma, zeta = 10.0, 0.1, 0.01
    (band,) = [b for b in pitch_bands(w, gamma, omega_min=15.0, omega_max=25.0,
                                      damping_ratio=zeta) if b.order == 1]
    zeta_cr = optimize.brentq(lambda z: _peak(w, gamma, z), 1e-3, 0.1, xtol=1e-10)
    gamma_cr = optimize.brentq(lambda g: _peak(w, g, zeta), 1e-3, gamma, xtol=1e-10)
    measured = band_measures(band, gamma=gamma, duration=None)  # as danger_summary does
    assert measured.critical_damping_ratio == pytest.approx(zeta_cr, rel=1e-4)
    assert band.critical_gamma == pytest.approx(gamma_cr, rel=1e-4)
    # and its margin at the case's gamma is gamma_cr / gamma (< 1: open)
    assert measured.margin == pytest.approx(gamma_cr / gamma, rel=1e-4)


def test_amplification_is_exp_growth_times_duration():
    """Exact: amplification = exp(growth_rate_max x duration), e-folding time = 1 / growth;
    None without a duration; sigma T past 700 stores the exponent only (no inf)."""
    (band,) = [b for b in pitch_bands(10.0, 0.1, omega_min=15.0, omega_max=25.0,
                                      damping_ratio=0.01) if b.order == 1]
    m = band_measures(band, gamma=0.1, duration=150.0)
    assert m.amplification == math.exp(band.growth_rate_max * 150.0)
    assert m.e_folding_s == 1.0 / band.growth_rate_max
    assert band_measures(band, gamma=0.1, duration=None).amplification is None
    huge = band_measures(band, gamma=0.1, duration=1e6)
    assert huge.amplification is None and huge.growth_exponent == band.growth_rate_max * 1e6
    assert json.loads(json.dumps(huge.to_dict()))["amplification"] is None


# --------------------------------------------------------------------------------------------
# Rules (exact, synthetic bands)
# --------------------------------------------------------------------------------------------
def _band(lo, hi, g, mechanism="beam_action", **extra):
    modes = (PITCH_MODE,) if mechanism == "pitch" else band_modes((0, 1))
    return Band(mechanism=mechanism, Omega_lo=lo, Omega_hi=hi, kind="sum", order=1,
                modes=modes, growth_rate_max=g, Omega_at_max=0.5 * (lo + hi),
                Omega_center=0.5 * (lo + hi), **extra)


def _res(lo, hi, severity):
    return Band(mechanism="resonance", Omega_lo=lo, Omega_hi=hi, kind="resonance", order=3,
                modes=(shell_mode(1, 1, 0, 1, "axial"),), growth_rate_max=0.0,
                Omega_at_max=lo, Omega_center=lo, severity=severity, cause=FAMILY_CAUSES[3])


@pytest.mark.parametrize(("g", "duration", "status"), [
    pytest.param(0.5 * NEGLIGIBLE_GROWTH, None, "negligible", id="e-folding-over-1e6s"),
    pytest.param(0.5 * NEGLIGIBLE_GROWTH, 1e9, "negligible", id="floor-even-for-long-T"),
    pytest.param(1.0 / (2.0 * UNSTABLE_E_FOLDING), None, "marginal", id="slow-no-T"),
    pytest.param(2.0 / UNSTABLE_E_FOLDING, None, "unstable", id="fast-no-T"),
    pytest.param(math.log(1.05) / 150.0, 150.0, "negligible", id="x1.05-in-T"),
    pytest.param(math.log(5.0) / 150.0, 150.0, "marginal", id="x5-in-T"),
    pytest.param(math.log(20.0) / 150.0, 150.0, "unstable", id="x20-in-T"),
])
def test_band_status_follows_the_stated_floors(g, duration, status):
    """The rules of docs/theory/verdicts.md, each on one side of its floor (exact)."""
    assert band_status(_band(20.0, 21.0, g), duration=duration) == status


def test_no_band_with_e_folding_over_1e6_s_is_unstable():
    """Regions of negligible growth never make a mechanism or the whole "unstable"."""
    s = danger_summary(operating_range=OPERATING, bands={
        "beam_action": [_band(20.0, 21.0, 9.9e-13), _band(30.0, 31.0, 5e-7)]})
    assert s.verdict.overall == "STABLE"
    (text,) = [v for k, _, v in s.verdicts if k == "beam_action"]
    assert text.startswith("stable in the operating range (2 regions of negligible growth")


def test_overall_verdict_unstable_marginal_stable():
    """UNSTABLE with a band past the floor, MARGINAL with only marginal ones, STABLE with
    none; the reason names the fastest band's edges in Hz and the damping."""
    kw = dict(operating_range=OPERATING, duration=150.0, modal_ratio=0.01, gamma=0.05)
    fast = _band(20.0, 21.0, math.log(100.0) / 150.0)
    slow = _band(40.0, 41.0, math.log(3.0) / 150.0)
    u = danger_summary(bands={"beam_action": [fast, slow]}, **kw).verdict
    assert u.overall == "UNSTABLE" and u.line.startswith("UNSTABLE: at 1 % modal damping")
    assert hz_text(20.0 / (2 * math.pi), 21.0 / (2 * math.pi)) in u.reason
    assert "x 100 in 150 s" in u.reason
    m = danger_summary(bands={"beam_action": [slow]}, **kw).verdict
    assert m.overall == "MARGINAL" and "x 3 in 150 s" in m.reason
    st = danger_summary(bands={"beam_action": [], "resonance": [_res(50.0, 51.0, 1.0)]},
                        **kw).verdict
    assert st.overall == "STABLE" and "1 forced resonance bounded by damping" in st.reason
    d = json.loads(json.dumps(st.to_dict()))
    assert d["overall"] == "STABLE" and d["damping"]["modal_ratio"] == 0.01
    assert d["mechanisms"]["pitch"] == "not computed"
    assert d["mechanisms"]["resonance"].startswith("bounded by damping: 1 resonance")


def test_undamped_resonances_are_unstable():
    """Without modal damping a memo resonance grows secularly (memo 7): unstable."""
    s = danger_summary(operating_range=OPERATING, modal_ratio=0.0,
                       bands={"resonance": [_res(50.0, 51.0, 1.0)]})
    assert s.verdict.overall == "UNSTABLE"


def test_not_fully_searched_is_never_stable():
    """A computed mechanism with a gap: the overall verdict is at best MARGINAL and says
    "not fully searched"; its mechanism line keeps the gap's reason."""
    gap = SearchGap(stage="vehicle", reason="harmonic k = 19 not searched: max_steps",
                    limit="max_steps", k=19)
    s = danger_summary(operating_range=OPERATING, bands={"vehicle": [], "pitch": []},
                       gaps=[gap], modal_ratio=0.01)
    assert s.verdict.overall == "MARGINAL"
    assert "not fully searched: vehicle parametric regions" in s.verdict.reason
    assert dict(s.verdict.mechanisms)["vehicle"].startswith("not fully searched: harmonic")


def test_hz_text_distinguishes_the_edges():
    """Edges printed to the digits that tell them apart (at least 4 significant)."""
    assert hz_text(18.25, 18.31) == "18.25-18.31 Hz"
    lo, hi = hz_text(45.200132, 45.200214).removesuffix(" Hz").split("-")
    assert lo != hi and float(lo) == pytest.approx(45.200132, rel=1e-6)


def test_g_text_keeps_three_significant_digits():
    """An acceleration in g to 3 significant digits with its trailing zeros: a peak of 1.997 g
    reads "2.00 g", never "2 g" (which an engineer takes for a rounded input)."""
    assert g_text(1.9966831040214328) == "2.00 g"
    assert g_text(50.0) == "50.0 g"
    assert g_text(0.91774) == "0.918 g"
    assert g_text(120.4) == "120 g"
    assert g_text(3.2e-5) == "3.20e-05 g"


def test_ranked_bands_carry_the_measures():
    """danger_summary applies band_measures to every band it ranks."""
    s = danger_summary(operating_range=OPERATING, duration=10.0, gamma=0.05,
                       bands={"beam_action": [_band(20.0, 21.0, 0.1, critical_gamma=0.02)]})
    (b,) = s.bands
    assert b.band.amplification == math.exp(0.1 * 10.0) and b.band.margin == 0.02 / 0.05
    assert danger_bands([b.band], operating_range=OPERATING)[0].band is b.band


# --------------------------------------------------------------------------------------------
# Damping input
# --------------------------------------------------------------------------------------------
def test_damping_defaults():
    """1 % on every elastic mode (beam and vehicle), the rigid pitch undamped."""
    c = memo_case()
    assert (c.damping.modal_ratio, c.damping.pitch_ratio) == (0.01, 0.0)
    assert c.damping.beam_ratio == 0.01 and c.vehicle_damping_ratio == 0.01


@pytest.mark.parametrize(("table", "key", "value"), [
    ("damping", "beam_modal_ratio", 0.02), ("vehicle", "damping_ratio", 0.03)])
def test_deprecated_key_is_used_and_warned_in_results_json(table, key, value):
    """An old key keeps working, with a ``deprecated-key`` warning naming damping.modal_ratio
    in Results.warnings and results.json; given beside damping.modal_ratio it is used for its
    modes (a case dumped and loaded again keeps its meaning)."""
    d = tomllib.loads(memo_case_text())
    del d["damping"]
    d.setdefault(table, {})[key] = value
    case = load_case(d)
    used = case.damping.beam_ratio if table == "damping" else case.vehicle_damping_ratio
    assert used == value
    r = analyze(case, beam_action=False, stability=False, figures=False, vehicle=False)
    (w,) = [w for w in json.loads(json.dumps(r.to_dict()))["warnings"]
            if w["code"] == "deprecated-key"]
    assert w["field"] == f"{table}.{key}" and "damping.modal_ratio" in w["message"]
    again = load_case(case.model_dump(exclude_none=True))
    assert (again.damping.beam_ratio, again.vehicle_damping_ratio) == (
        case.damping.beam_ratio, case.vehicle_damping_ratio)


def test_the_same_tongue_from_pitch_and_beam_action_is_listed_once():
    """Exact: the rigid-pitch tongue r found by the pitch (memo 4.2) and by the beam action
    ("rigid pitch", simple, order r, overlapping) is one ranked band naming both mechanisms,
    with the coupled model's edges; a pitch tongue the beam action does not overlap stays."""
    pitch1 = _band(40.0, 42.0, 0.2, mechanism="pitch")
    pitch2 = _band(20.0, 20.5, 0.1, mechanism="pitch")
    coupled = Band(mechanism="beam_action", Omega_lo=40.1, Omega_hi=42.1, kind="simple",
                   order=1, modes=band_modes((0,)), growth_rate_max=0.21, Omega_at_max=41.0,
                   Omega_center=41.0)
    s = danger_summary(operating_range=OPERATING,
                       bands={"pitch": [pitch1, pitch2], "beam_action": [coupled]})
    assert [(b.band.Omega_lo, b.mechanisms) for b in s.bands] == [
        (40.1, ("beam_action", "pitch")), (20.0, ("pitch",))]
    assert "also the rigid-body pitch's Mathieu tongue 1" in s.bands[0].cause_text
    text = dict((k, v) for k, _, v in s.verdicts)
    assert text["pitch"].startswith("unstable: 2 instability regions")
    assert text["beam_action"].startswith("unstable: 1 instability region ")


# --------------------------------------------------------------------------------------------
# Forced resonances: the damped steady amplitude
# --------------------------------------------------------------------------------------------
def test_resonance_steady_amplitude_closed_form_and_direct_integration():
    """A single mode y'' + 2 zeta w y' + w^2 y = (F / m) cos(w t) at resonance: the undamped
    secular rate (severity) v = F / (2 m w) (docs/theory/severity.md), and band_measures'
    damped steady amplitude against the closed form F / (2 zeta w^2 m) and against direct
    integration (solve_ivp to steady state, the last period's peak), to 1 %."""
    w, zeta, m, F = 2 * math.pi * 45.2, 0.01, 3.0, 50.0
    v = F / (2.0 * m * w)  # severity: the undamped envelope grows like v t
    mode = shell_mode(1, 1, 0, 1, "axial")
    band = Band(mechanism="resonance", Omega_lo=w, Omega_hi=w, kind="resonance", order=3,
                modes=(dataclasses.replace(mode, omega=w),), growth_rate_max=0.0,
                Omega_at_max=w, Omega_center=w, severity=v, cause=FAMILY_CAUSES[3])
    got = band_measures(band, gamma=0.05, duration=None, modal_ratio=zeta)
    closed = F / (2.0 * zeta * w * w * m)
    assert got.steady_amplitude == pytest.approx(closed, rel=1e-12)
    assert got.steady_acceleration == pytest.approx(closed * w * w, rel=1e-12)
    T = 2 * math.pi / w
    n_settle = int(12.0 / (zeta * w * T))  # 12 time constants 1 / (zeta w)

    def rhs(t, y):
        return [y[1], F / m * math.cos(w * t) - 2 * zeta * w * y[1] - w * w * y[0]]

    sol = integrate.solve_ivp(rhs, (0.0, (n_settle + 1) * T), [0.0, 0.0], method="DOP853",
                              rtol=1e-9, atol=1e-12, dense_output=True)
    tail = sol.sol(np.linspace(n_settle * T, (n_settle + 1) * T, 2001))[0]
    assert got.steady_amplitude == pytest.approx(np.max(np.abs(tail)), rel=1e-2)
    undamped = band_measures(band, gamma=0.05, duration=None, modal_ratio=0.0)
    assert undamped.steady_amplitude is None  # undamped: no steady state (secular growth)


def test_damped_resonances_rank_by_steady_acceleration():
    """Exact: of two damped resonances the larger steady acceleration v w / zeta ranks first
    (the one scale, in g, of every bounded response; docs/theory/verdicts.md), though its
    severity v and its displacement v / (zeta w) are the smaller; the reason names it."""
    mode = shell_mode(1, 1, 0, 1, "axial")

    def res(lo, v, w):
        return Band(mechanism="resonance", Omega_lo=lo, Omega_hi=lo, kind="resonance",
                    order=3, modes=(dataclasses.replace(mode, omega=w),), growth_rate_max=0.0,
                    Omega_at_max=lo, Omega_center=lo, severity=v, cause=FAMILY_CAUSES[3])

    # res(20): 20 m, 2e3 m/s^2; res(30): 0.1 m, 1e5 m/s^2 = 1.02e4 g at 1000 / 2 pi Hz
    s = danger_summary(operating_range=OPERATING, modal_ratio=0.01,
                       bands={"resonance": [res(20.0, 2.0, 10.0), res(30.0, 1.0, 1000.0)]})
    assert [b.Omega_lo for b in s.bands] == [30.0, 20.0]
    assert "largest response 100 mm (1.02e+04 g) at 159.2 Hz" in s.verdict.reason


# --------------------------------------------------------------------------------------------
# The memo case (acceptance)
# --------------------------------------------------------------------------------------------
@pytest.mark.slow
def test_memo_case_verdict_acceptance(memo_results):
    """The memo case: results.json holds the verdict (overall, reason, mechanisms) at 1 %
    modal damping and 150 s; no band with an e-folding time above 1e6 s counts as unstable
    (nor its mechanism's line); no band is listed twice (no two ranked bands of one mechanism
    with the same edges, no pitch tongue beside the beam action's rigid-pitch band of the same
    order that overlaps it)."""
    r = memo_results
    d = json.loads(json.dumps(r.to_dict()))["verdict"]
    assert d["overall"] in ("UNSTABLE", "MARGINAL", "STABLE") and d["reason"]
    assert d["damping"] == {"modal_ratio": 0.01, "pitch_ratio": 0.0} and d["duration"] == 150.0
    assert set(d["mechanisms"]) == {"pitch", "beam_action", "vehicle", "resonance"}
    slow = [b for b in r.danger.bands if b.band.e_folding_s is not None
            and b.band.e_folding_s > 1e6]
    for b in slow:
        assert band_status(b.band, duration=150.0, modal_ratio=0.01) == "negligible"
    for key in {b.mechanism for b in slow}:
        assert not d["mechanisms"][key].startswith("unstable")
    keys = [(b.mechanism, b.Omega_lo, b.Omega_hi) for b in r.danger.bands]
    assert len(keys) == len(set(keys))
    pitch = [b for b in r.danger.bands if b.mechanism == "pitch"]
    tongues = [b for b in r.danger.bands if b.mechanism == "beam_action"
               and b.band.kind == "simple" and b.mode_text == "rigid pitch"]
    assert not any(p.band.order == t.band.order and p.Omega_lo <= t.Omega_hi
                   and t.Omega_lo <= p.Omega_hi for p in pitch for t in tongues)


def test_ranked_bands_carry_their_measures_into_results_json():
    # a region growing at 0.02 1/s for T = 100 s: e-folding 1 / 0.02 = 50 s, growth exponent
    # 2 and amplification exp(2) (closed form, exactly); margin = critical gamma / gamma =
    # 0.01 / 0.05 = 0.2 (open); a resonance of severity 1e-3 m/s at omega = 100 rad/s with
    # zeta = 0.01: steady amplitude v / (zeta omega) = 1e-3 m (docs/theory/verdicts.md)
    region = _band(40.0, 41.0, 0.02, mechanism="vehicle", k=3, critical_gamma=0.01,
                   critical_damping_ratio=0.004)
    res = _res(100.0, 100.0, 1e-3)
    omega = 100.0  # the resonant shell mode's frequency (rad/s), given to its label
    res = dataclasses.replace(res, modes=(dataclasses.replace(res.modes[0], omega=omega),))
    bands = {"vehicle": [region], "resonance": [res]}
    found = danger_summary(operating_range=(1.0, 1000.0), bands=bands, gamma=0.05,
                           duration=100.0, modal_ratio=0.01)
    by = {b["mechanism"]: b for b in found.to_dict()["bands"]}
    v = by["vehicle"]
    assert v["e_folding_s"] == pytest.approx(50.0, rel=1e-15)
    assert v["growth_exponent"] == pytest.approx(2.0, rel=1e-15)
    assert v["amplification"] == pytest.approx(math.exp(2.0), rel=1e-15)
    assert v["margin"] == pytest.approx(0.2, rel=1e-15)
    assert v["critical_damping_ratio"] == 0.004
    assert by["resonance"]["steady_amplitude"] == pytest.approx(1e-3 / (0.01 * omega),
                                                                rel=1e-15)
    assert by["resonance"]["steady_acceleration"] == pytest.approx(1e-3 * omega / 0.01,
                                                                   rel=1e-14)


# --------------------------------------------------------------------------------------------
# Everything computed in one verdict: the vehicle's bounded responses and the flight
# --------------------------------------------------------------------------------------------
def _response(acc_g, Omega, *, k=0, station="payload", station_m=10.0, **extra):
    extra.setdefault("modes", f"k = {k}")
    return ResponsePeak(source="forced response", k=k, Omega=Omega, acceleration_g=acc_g,
                        station=station, station_m=station_m, **extra)


def test_axial_resonance_peak_against_direct_integration():
    """A k = 0 mode p'' + 2 zeta w p' + w^2 p = phi dF cos(w t) (mass-normalised, aft-edge
    displacement u = phi p): axial_resonance_peaks' displacement and acceleration (g) against
    the closed form phi^2 dF / (2 zeta w^2) and against direct integration (solve_ivp to steady
    state, the last period's peak), to 1 %."""
    w, zeta, phi, dF = 2 * math.pi * 12.07, 0.01, 2.0e-3, 1.0e5
    res = AxialResonance(index=0, order=1, type="axial", omega=w, participation=phi,
                         flexibility=phi**2 / w**2, amplitude=phi**2 / (2 * zeta * w**2))
    (p,) = axial_resonance_peaks([res], load=dF, operating_range=(70.0, 90.0))
    closed = phi**2 * dF / (2.0 * zeta * w * w)
    assert p.displacement_m == pytest.approx(closed, rel=1e-12)
    T = 2 * math.pi / w
    n_settle = int(12.0 / (zeta * w * T))  # 12 time constants 1 / (zeta w)

    def rhs(t, y):
        return [y[1], phi * dF * math.cos(w * t) - 2 * zeta * w * y[1] - w * w * y[0]]

    sol = integrate.solve_ivp(rhs, (0.0, (n_settle + 1) * T), [0.0, 0.0], method="DOP853",
                              rtol=1e-9, atol=1e-14, dense_output=True)
    t = np.linspace(n_settle * T, (n_settle + 1) * T, 2001)
    y, v = sol.sol(t)
    acc = phi * (phi * dF * np.cos(w * t) - 2 * zeta * w * v - w * w * y)  # u'' from the ODE
    assert p.displacement_m == pytest.approx(phi * np.max(np.abs(y)), rel=1e-2)
    assert p.acceleration_g == pytest.approx(np.max(np.abs(acc)) / STANDARD_GRAVITY, rel=1e-2)
    assert p.in_operating_range and p.station == "aft-edge"


def test_a_bounded_response_never_worsens_the_verdict_and_is_named():
    """Exact rules (docs/theory/verdicts.md): a forced response, however large, is bounded:
    STABLE stays STABLE and the reason names the largest response in g with its station, Omega
    (Hz) and load; in the one ranking it comes after an unstable region and before a region of
    negligible growth; results.json's verdict carries it."""
    big = _response(50.0, 2 * math.pi * 12.0, load_quantity="axial force", load_unit="N",
                load=3.0e6, load_station_m=40.0)
    small = _response(0.5, 2 * math.pi * 30.0, station="aft-edge", station_m=0.0)
    s = danger_summary(operating_range=(10.0, 300.0), modal_ratio=0.01,
                       bands={"vehicle": [_band(20.0, 21.0, 1e-9, mechanism="vehicle")]},
                       responses=[small, big])
    assert s.verdict.overall == "STABLE"
    assert s.verdict.reason.endswith("largest response 50.0 g at payload (10 m, k = 0), 12 Hz, "
                                      "axial force 3e+06 N at 40 m")
    assert s.responses == (big, small)
    assert [type(x).__name__ for x in s.ranking] == ["ResponsePeak", "ResponsePeak",
                                                    "RankedBand"]
    u = danger_summary(operating_range=(10.0, 300.0), modal_ratio=0.01, responses=[big],
                       bands={"vehicle": [_band(20.0, 21.0, 1.0, mechanism="vehicle")]})
    assert u.verdict.overall == "UNSTABLE" and isinstance(u.ranking[0], RankedBand)
    d = json.loads(json.dumps(s.to_dict()))
    assert d["verdict"]["largest_response"]["acceleration_g"] == 50.0
    assert [x["item"] for x in d["ranking"]] == ["response", "response", "band"]


def test_a_resonance_found_twice_is_listed_once():
    """Exact: a k = 0 axial resonance whose half-power band omega (1 -+ zeta) holds a k = 0
    forced-response peak is that peak (named in its ``also``); one outside stays."""
    w1, w2 = 2 * math.pi * 12.0, 2 * math.pi * 20.0
    forced = [_response(4.0, w1 * (1 + 0.5 * 0.01))]  # inside the half-power band at zeta = 1 %
    axial = [_response(3.9, w1, station="aft-edge", modes="k = 0 mode 1"),
             _response(0.2, w2, station="aft-edge", modes="k = 0 mode 2")]
    axial = [dataclasses.replace(a, source="axial resonance") for a in axial]
    merged = merge_responses(forced, axial, damping_ratio=0.01)
    assert [(m.source, m.Omega, m.also) for m in merged] == [
        ("forced response", forced[0].Omega, ("k = 0 mode 1",)),
        ("axial resonance", w2, ())]


def test_flight_events_enter_the_verdict_and_negligible_ones_are_dropped():
    """A flight's region events by their accumulated e-folds (closed form: a constant growth
    rate sigma held over the dwell T gives sigma T, :func:`band_events`' exact integral): one
    at 1.85e-5 1/s over 15 s (2.8e-4 e-folds, under ln 1.1) is dropped and counted, never the
    worst moment; one at 0.2 1/s over 20 s (4 e-folds > ln 10) makes the overall verdict
    UNSTABLE though no frozen-time band counts; a forced resonance is bounded."""
    def events(rate, t1):
        band = _band(20.0, 21.0, rate, mechanism="vehicle", k=1)
        return band_events([0.0, t1], [[band], [band]], [[20.5, 20.5], [20.5, 20.5]])

    (slow,) = events(1.85e-5, 15.0)
    (fast,) = events(0.2, 20.0)
    assert slow.efolds == pytest.approx(1.85e-5 * 15.0, rel=1e-12)
    assert fast.efolds == pytest.approx(0.2 * 20.0, rel=1e-12)
    forced = FlightEvent(mechanism="forced", k=0, modes="mode 1 (axial)", t_start_s=0.0,
                         t_end_s=64.39, max_growth_1_s=0.0, efolds=0.0, amplification=1.0,
                         peak_acceleration_g=0.223, station="aft-edge")
    assert [event_status(e) for e in (slow, fast, forced)] == ["negligible", "unstable",
                                                               "bounded"]
    quiet = flight_verdict([slow, forced], times=(0.0, 150.0))
    assert quiet.worst is forced and quiet.dropped == 1
    s = danger_summary(operating_range=OPERATING, bands={"vehicle": []}, flight=quiet)
    assert s.verdict.overall == "STABLE"
    assert ("over the flight (t = 0-150 s) no region grows more than 10 %; worst moment 0.223 g "
            "at aft-edge, t = 0-64.39 s, k = 0 mode 1 (axial) (1 event of negligible growth "
            "dropped)") in s.verdict.reason
    # the largest bounded response is that forced resonance: named once, as the worst moment
    assert s.verdict.reason.endswith("the flight's worst moment is also the largest response")
    loud = flight_verdict([slow, forced, fast], times=(0.0, 150.0))
    assert loud.worst is fast
    u = danger_summary(operating_range=OPERATING, bands={"vehicle": []}, flight=loud)
    assert u.verdict.overall == "UNSTABLE" and "1 region grows more than 10-fold" in \
        u.verdict.reason
    d = json.loads(json.dumps(u.to_dict()))["verdict"]["flight"]
    assert (d["status"], d["events_counted"], d["events_dropped"]) == ("unstable", 2, 1)


@pytest.mark.slow
def test_pitch_critical_damping_only_for_the_fastest_tongues():
    # at a large gamma a hundred tongues can count, each a root search of about a second: the
    # critical damping ratio is computed for the CRITICAL_DAMPING_COUNT fastest-growing only
    # (a deterministic bound), the others keep None; ten tongues r = 1..10, growth falling with r
    from flexbooster.bands import CRITICAL_DAMPING_COUNT

    tongues = [dataclasses.replace(_band(2.0 / r, 2.0 / r + 0.01, 0.1 / r, mechanism="pitch"),
                                   kind="simple", order=r) for r in range(1, 11)]
    s = danger_summary(operating_range=(0.1, 5.0), bands={"pitch": tongues}, gamma=0.3)
    got = {b.band.order: b.band.critical_damping_ratio for b in s.bands}
    assert sorted(r for r, z in got.items() if z is not None) == \
        list(range(1, CRITICAL_DAMPING_COUNT + 1))
