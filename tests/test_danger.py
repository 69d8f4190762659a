"""The ranked danger bands (flexbooster.danger): adapters, ranking, verdicts, JSON.

Tiers: exact (synthetic bands whose fields and order are known by construction), the default
case (the top band agrees with the beam action's own largest growth rate: two paths to one
number), invariants (ranking unchanged by the order of the inputs; duck-typed sources).
"""

from __future__ import annotations

import json
import math
from types import SimpleNamespace

import pytest

from flexbooster.danger import (
    MECHANISMS,
    STEADY_CAUSE,
    DangerBand,
    danger_bands,
    danger_summary,
    mechanism_verdicts,
)
from flexbooster.memo.beam_action import BeamActionBand
from flexbooster.memo.pitch import PitchBand
from flexbooster.memo.severity import ResonanceBand

OPERATING = (10.0, 100.0)


@pytest.fixture(scope="module")
def default_results():
    from flexbooster.analysis import analyze
    from flexbooster.case import default_case

    return analyze(default_case(), stability=False, figures=False)


def _pitch(*bands):
    return SimpleNamespace(bands=tuple(bands))


def _ba(lo, hi, g, kind="sum", modes=(0, 1), order=1):
    return BeamActionBand(lo, hi, g, 0.5 * (lo + hi), kind, modes, order, 0.5 * (lo + hi))


def test_pitch_adapter_fields_exact():
    # exact: the fields are copied; Hz = rad/s / (2 pi) to 1e-15 relative
    band = PitchBand(40.0, 42.0, 0.25, 41.0, tongue=1)
    (d,) = danger_bands(operating_range=OPERATING, pitch=_pitch(band))
    assert (d.mechanism, d.Omega_lo, d.Omega_hi, d.growth_rate, d.severity) == (
        "pitch", 40.0, 42.0, 0.25, None)
    assert d.mode_text == "rigid pitch" and d.cause_text.startswith("instability region")
    assert d.hz == pytest.approx((40.0 / (2 * math.pi), 42.0 / (2 * math.pi)), rel=1e-15)
    assert d.in_operating_range


def test_beam_action_adapter_words():
    # the words of issue 17: "instability region", the modes named (0 = rigid pitch)
    (d,) = danger_bands(operating_range=OPERATING, beam_action=SimpleNamespace(
        bands=(_ba(50.0, 51.0, 0.1, kind="sum", modes=(0, 2), order=1),)))
    assert d.mode_text == "rigid pitch + bending 2"
    assert d.cause_text == "instability region (sum combination, order 1)"


@pytest.mark.parametrize(
    ("lo", "hi", "inside"),
    [
        pytest.param(5.0, 9.0, False, id="below"),
        pytest.param(5.0, 10.0, True, id="touches-lower-edge"),
        pytest.param(100.0, 120.0, True, id="touches-upper-edge"),
        pytest.param(101.0, 120.0, False, id="above"),
        pytest.param(1.0, 500.0, True, id="spans-range"),
    ],
)
def test_in_operating_range_is_interval_overlap(lo, hi, inside):
    # exact: closed-interval overlap with [10, 100] rad/s
    (d,) = danger_bands(operating_range=OPERATING,
                        beam_action=SimpleNamespace(bands=(_ba(lo, hi, 0.1),)))
    assert d.in_operating_range is inside


def test_ranking_exact_and_independent_of_input_order():
    # by construction: in range before out of range; growth rate (largest first) before
    # severity only (largest first)
    ba = [_ba(20.0, 21.0, 0.01), _ba(30.0, 31.0, 0.5), _ba(200.0, 201.0, 9.0)]
    res = [SimpleNamespace(Omega_lo=60.0, Omega_hi=60.5, severity=3.0),
           SimpleNamespace(omega_lo=70.0, omega_hi=70.5, severity=30.0)]
    ranked = danger_bands(operating_range=OPERATING, beam_action=SimpleNamespace(bands=ba),
                          resonance_bands=res)
    order = [(b.mechanism, b.Omega_lo) for b in ranked]
    assert order == [("beam_action", 30.0), ("beam_action", 20.0), ("resonance", 70.0),
                     ("resonance", 60.0), ("beam_action", 200.0)]
    swapped = danger_bands(operating_range=OPERATING,
                           beam_action=SimpleNamespace(bands=ba[::-1]),
                           resonance_bands=res[::-1])
    assert swapped == ranked
    assert danger_bands(operating_range=OPERATING, beam_action=SimpleNamespace(bands=ba),
                        limit=2) == ranked[:2]


def test_resonance_and_vehicle_adapters_duck_typed():
    vehicle = [SimpleNamespace(Omega_lo=15.0, Omega_hi=16.0, growth_rate_max=0.2,
                               label="k = 2, modes 1+3")]
    res = [SimpleNamespace(Omega_lo=80.0, Omega_hi=80.0, severity=5.0, family="family 3")]
    ranked = danger_bands(operating_range=OPERATING, vehicle_regions=vehicle,
                          resonance_bands=res)
    v, r = ranked
    assert (v.mechanism, v.growth_rate, v.mode_text) == ("vehicle", 0.2, "k = 2, modes 1+3")
    assert v.cause_text.startswith("instability region")
    assert (r.mechanism, r.severity, r.growth_rate) == ("resonance", 5.0, None)
    assert r.cause_text == "resonance (memo 7): family 3"


def test_resonance_band_of_the_severity_module_in_words():
    # a ResonanceBand (memo.severity) as the danger ranking shows it: the most severe root's
    # mode and its family's cause, Omega edges and severity copied exactly
    band = ResonanceBand(Omega_lo=379.1, Omega_hi=379.3, Omega_peak=379.2, severity=6.4e-3,
                         severity_rel=1.0, n_roots=2, families=(3, 7),
                         modes=((1, 1, 0, 1, "axial"), (1, 1, 1, 1, "radial")), family=3,
                         cause="thrust pulsation at the aft edge")
    (d,) = danger_bands(operating_range=OPERATING, resonance_bands=[band])
    assert (d.Omega_lo, d.Omega_hi, d.severity) == (379.1, 379.3, 6.4e-3)
    assert d.mode_text == "cylinder 1 shell mode j = 1, k = 0, m = 1 (axial)"
    assert d.cause_text == "resonance (memo 7): family 3: thrust pulsation at the aft edge"


@pytest.mark.parametrize(
    ("kwargs", "words"),
    [
        pytest.param({"operating_range": (100.0, 10.0)}, "operating_range", id="range-order"),
        pytest.param({"operating_range": (0.0, math.inf)}, "operating_range", id="range-inf"),
        pytest.param({"operating_range": OPERATING, "limit": -1}, "limit", id="limit"),
        pytest.param({"operating_range": OPERATING,
                      "resonance_bands": [SimpleNamespace(Omega_lo=1.0, Omega_hi=2.0)]},
                     "severity", id="resonance-without-level"),
        pytest.param({"operating_range": OPERATING,
                      "vehicle_regions": [SimpleNamespace(Omega_lo=3.0, Omega_hi=2.0,
                                                          growth_rate_max=1.0)]},
                     "Omega_lo <= Omega_hi", id="edges-reversed"),
        pytest.param({"operating_range": OPERATING,
                      "vehicle_regions": [SimpleNamespace(Omega_lo=1.0, Omega_hi=2.0,
                                                          growth_rate_max=math.nan)]},
                     "finite", id="growth-nan"),
    ],
)
def test_bad_arguments_raise(kwargs, words):
    with pytest.raises(ValueError, match=words):
        danger_bands(**kwargs)


def test_verdicts_not_computed_stable_unstable():
    # exact: one line per mechanism in MECHANISMS order; wording of issue 17
    bands = danger_bands(operating_range=OPERATING, beam_action=SimpleNamespace(
        bands=(_ba(20.0, 21.0, 0.01), _ba(30.0, 31.0, 0.5), _ba(300.0, 301.0, 0.9))))
    v = mechanism_verdicts(bands, computed={"pitch": True, "beam_action": True})
    assert [k for k, _, _ in v] == [k for k, _ in MECHANISMS]
    text = {k: t for k, _, t in v}
    assert text["pitch"] == "stable in the operating range"
    assert text["beam_action"] == ("unstable: 2 instability regions in the operating range, "
                                   "largest growth rate 0.5 1/s")  # 300 rad/s is outside
    assert text["vehicle"] == text["resonance"] == "not computed"
    res = danger_bands(operating_range=OPERATING,
                       resonance_bands=[SimpleNamespace(Omega_lo=50, Omega_hi=51, severity=2)])
    (r,) = [t for k, _, t in mechanism_verdicts(res, computed={"resonance": True})
            if k == "resonance"]
    assert r == "unstable: 1 resonance (memo 7) in the operating range, largest severity 2 m/s"


def test_a_steady_region_is_named_unstable_without_pulsation():
    """A "steady" region (the system under the steady thrust alone is unstable: Beal's
    follower flutter, or the slow growth of a gimballed rigid pitch with damped elastic modes,
    the README's [vehicle] example at 9.9e-7 1/s) is not a parametric region: its cause says
    so, and the verdict names it with its e-folding time 1 / growth (exact)."""
    bands = danger_bands(operating_range=OPERATING, beam_action=SimpleNamespace(
        bands=(_ba(OPERATING[0], OPERATING[1], 2.0e-3, kind="steady", modes=(0,), order=0),
               _ba(30.0, 31.0, 0.5))))
    steady = [b for b in bands if b.cause_text.startswith(STEADY_CAUSE)]
    assert len(steady) == 1 and "gamma = 0" in steady[0].cause_text
    assert "instability region" not in steady[0].cause_text
    (text,) = [t for k, _, t in mechanism_verdicts(bands, computed={"beam_action": True})
               if k == "beam_action"]
    assert text == ("unstable: 2 instability regions in the operating range, largest growth "
                    "rate 0.5 1/s (1 of them unstable without pulsation: growth rate 0.002 "
                    "1/s, e-folding time 500 s)")


def test_summary_to_dict_is_json():
    s = danger_summary(operating_range=OPERATING, pitch=_pitch(PitchBand(40, 42, 0.25, 41, 1)))
    d = json.loads(json.dumps(s.to_dict()))
    assert d["operating_range"] == [10.0, 100.0]
    assert d["bands"][0]["Omega_lo_hz"] == pytest.approx(40 / (2 * math.pi), rel=1e-15)
    assert [v["verdict"] for v in d["verdicts"]][2:] == ["not computed", "not computed"]
    assert isinstance(s.bands[0], DangerBand)


@pytest.mark.slow
def test_default_case_top_band_is_the_beam_action_maximum(default_results):
    # two paths to one number: the first ranked band's growth rate equals the beam action's
    # own largest growth rate (memo 4.1 bands, exact maxima; 1e-12 relative), and every band
    # of the pitch and the beam action is listed once
    r = default_results
    assert r.danger is not None
    top = r.danger.bands[0]
    assert top.mechanism == "beam_action"
    assert top.growth_rate == pytest.approx(r.beam_action.max_growth_rate, rel=1e-12)
    assert len(r.danger.bands) == len(r.pitch.bands) + len(r.beam_action.bands)
    assert json.loads(json.dumps(r.to_dict()["danger"]))["bands"][0]["mechanism"] == \
        "beam_action"


def test_vehicle_region_adapter_describes_the_region():
    # flexbooster.vehicle.VehicleRegion (issue 15): harmonic k, kind, order j and the loaded
    # modes' type and meridian order in the words; the fields copied exactly
    from flexbooster.vehicle import RegionMode, VehicleRegion

    modes = (RegionMode(k=2, index=0, order=1, type="radial", omega_loaded=50.0, share=0.9),
             RegionMode(k=2, index=1, order=2, type="axial", omega_loaded=70.0, share=0.8))
    region = VehicleRegion(k=2, kind="sum", order=1, modes=modes, omega_lo=60.0, omega_hi=61.0,
                           growth_rate_max=0.3, omega_at_max=60.5, omega_center=60.0,
                           critical_gamma=0.0)
    (d,) = danger_bands(operating_range=OPERATING, vehicle_regions=[region])
    assert (d.mechanism, d.Omega_lo, d.Omega_hi, d.growth_rate) == ("vehicle", 60.0, 61.0, 0.3)
    assert d.mode_text == "k = 2: radial 1 + axial 2"
    assert d.cause_text == "instability region (sum combination, order 1; vehicle model)"
