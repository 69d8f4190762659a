"""The ranked danger bands (flexbooster.danger) and the one band type (flexbooster.bands).

Tiers: exact (synthetic bands whose fields and order are known by construction), the default
case (the top band agrees with the beam action's own largest growth rate: two paths to one
number), invariants (ranking unchanged by the order of the inputs; a search with a gap is never
"stable").
"""

from __future__ import annotations

import json
import math

import pytest

from flexbooster.bands import MECHANISMS, Band, BandMode, SearchGap
from flexbooster.danger import (
    STEADY_CAUSE,
    RankedBand,
    danger_bands,
    danger_summary,
    mechanism_verdicts,
)
from flexbooster.memo.beam_action import band_modes
from flexbooster.memo.pitch import PITCH_MODE
from flexbooster.memo.severity import FAMILY_CAUSES, shell_mode

OPERATING = (10.0, 100.0)


@pytest.fixture(scope="module")
def memo_results():
    from flexbooster.analysis import analyze
    from flexbooster.case import memo_case

    return analyze(memo_case(), stability=False, figures=False)


def _band(mechanism, lo, hi, g=0.0, *, kind="simple", order=1, modes=(), **extra):
    return Band(mechanism=mechanism, Omega_lo=lo, Omega_hi=hi, kind=kind, order=order,
                modes=modes, growth_rate_max=g, Omega_at_max=0.5 * (lo + hi),
                Omega_center=0.5 * (lo + hi), **extra)


def _ba(lo, hi, g, kind="sum", modes=(0, 1), order=1):
    return _band("beam_action", lo, hi, g, kind=kind, order=order, modes=band_modes(modes))


def _res(lo, hi, severity, family=3):
    return _band("resonance", lo, hi, kind="resonance", order=family,
                 modes=(shell_mode(1, 1, 0, 1, "axial"),), severity=severity,
                 cause=FAMILY_CAUSES[family])


def test_pitch_band_fields_exact():
    # exact: the fields are copied; Hz = rad/s / (2 pi) to 1e-15 relative
    band = _band("pitch", 40.0, 42.0, 0.25, modes=(PITCH_MODE,))
    (d,) = danger_bands([band], operating_range=OPERATING)
    assert (d.mechanism, d.Omega_lo, d.Omega_hi, d.growth_rate, d.severity) == (
        "pitch", 40.0, 42.0, 0.25, None)
    assert d.mode_text == "rigid pitch" and d.cause_text == \
        "instability region (Mathieu tongue 1)"
    assert d.hz == pytest.approx((40.0 / (2 * math.pi), 42.0 / (2 * math.pi)), rel=1e-15)
    assert d.in_operating_range and d.band is band


def test_beam_action_band_words():
    # the modes named (0 = rigid pitch), the kind and order in words
    (d,) = danger_bands([_ba(50.0, 51.0, 0.1, kind="sum", modes=(0, 2), order=1)],
                        operating_range=OPERATING)
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
    (d,) = danger_bands([_ba(lo, hi, 0.1)], operating_range=OPERATING)
    assert d.in_operating_range is inside


def test_ranking_exact_and_independent_of_input_order():
    # by construction: in range before out of range; then by status (docs/theory/verdicts.md:
    # unstable, marginal, ...); within a status growth rate (largest first) before resonances
    # (largest severity first). Undamped, no duration: growth 0.5 1/s (e-folding 2 s) and the
    # resonances are unstable, 0.01 1/s (100 s) marginal
    bands = [_ba(20.0, 21.0, 0.01), _ba(30.0, 31.0, 0.5), _ba(200.0, 201.0, 9.0),
             _res(60.0, 60.5, 3.0), _res(70.0, 70.5, 30.0)]
    ranked = danger_bands(bands, operating_range=OPERATING)
    order = [(b.mechanism, b.Omega_lo) for b in ranked]
    assert order == [("beam_action", 30.0), ("resonance", 70.0), ("resonance", 60.0),
                     ("beam_action", 20.0), ("beam_action", 200.0)]
    assert danger_bands(bands[::-1], operating_range=OPERATING) == ranked
    assert danger_bands(bands, operating_range=OPERATING, limit=2) == ranked[:2]


def test_resonance_band_in_words():
    # a resonance band of the severity module as the ranking shows it: the most severe root's
    # mode and its family's cause, the Omega edges and the severity copied exactly
    band = _band("resonance", 379.1, 379.3, kind="resonance", order=3,
                 modes=(shell_mode(1, 1, 0, 1, "axial"), shell_mode(1, 1, 1, 1, "radial")),
                 severity=6.4e-3, severity_rel=1.0, n_roots=2, families=(3, 7),
                 cause="thrust pulsation at the aft edge")
    (d,) = danger_bands([band], operating_range=OPERATING)
    assert (d.Omega_lo, d.Omega_hi, d.severity, d.growth_rate) == (379.1, 379.3, 6.4e-3, None)
    assert d.mode_text.startswith("cylinder 1 shell mode j = 1, k = 0, m = 1 (axial)")
    # engineering words on the first screen; the memo's family stays in the severity table
    assert d.cause_text == "forced resonance: thrust pulsation at the aft edge"


def test_vehicle_region_in_words():
    # a vehicle region: harmonic k, kind, order j and the loaded modes' type and meridian
    # order in the words
    modes = (BandMode("radial 1", index=0, k=2, order=1, type="radial", omega=50.0),
             BandMode("axial 2", index=1, k=2, order=2, type="axial", omega=70.0))
    (d,) = danger_bands([_band("vehicle", 60.0, 61.0, 0.3, kind="sum", modes=modes, k=2)],
                        operating_range=OPERATING)
    assert (d.mechanism, d.Omega_lo, d.Omega_hi, d.growth_rate) == ("vehicle", 60.0, 61.0, 0.3)
    assert d.mode_text == "k = 2: radial 1 + axial 2"
    assert d.cause_text == "instability region (sum combination, order 1; vehicle model)"


@pytest.mark.parametrize(
    ("make", "words"),
    [
        pytest.param(lambda: danger_bands([], operating_range=(100.0, 10.0)),
                     "operating_range", id="range-order"),
        pytest.param(lambda: danger_bands([], operating_range=(0.0, math.inf)),
                     "operating_range", id="range-inf"),
        pytest.param(lambda: danger_bands([], operating_range=OPERATING, limit=-1), "limit",
                     id="limit"),
        pytest.param(lambda: _band("vehicle", 3.0, 2.0, 1.0), "Omega_lo <= Omega_hi",
                     id="edges-reversed"),
        pytest.param(lambda: _band("vehicle", 1.0, 2.0, math.nan), "finite", id="growth-nan"),
        pytest.param(lambda: _band("shells", 1.0, 2.0), "mechanism", id="mechanism"),
        pytest.param(lambda: _band("vehicle", 1.0, 2.0, kind="flutter"), "kind", id="kind"),
        pytest.param(lambda: danger_summary(operating_range=OPERATING, bands={"x": []}),
                     "unknown mechanism", id="summary-key"),
    ],
)
def test_bad_arguments_raise(make, words):
    with pytest.raises(ValueError, match=words):
        make()


def test_verdicts_not_computed_stable_unstable():
    # exact: one line per mechanism in MECHANISMS order
    bands = danger_bands([_ba(20.0, 21.0, 0.01), _ba(30.0, 31.0, 0.5), _ba(300.0, 301.0, 0.9)],
                         operating_range=OPERATING)
    v = mechanism_verdicts(bands, computed={"pitch": True, "beam_action": True})
    assert [k for k, _, _ in v] == [k for k, _ in MECHANISMS]
    text = {k: t for k, _, t in v}
    assert text["pitch"] == "stable in the operating range"
    assert text["beam_action"] == ("unstable: 2 instability regions in the operating range, "
                                   "largest growth rate 0.5 1/s")  # 300 rad/s is outside
    assert text["vehicle"] == text["resonance"] == "not computed"
    res = danger_bands([_res(50, 51, 2.0)], operating_range=OPERATING)
    (r,) = [t for k, _, t in mechanism_verdicts(res, computed={"resonance": True})
            if k == "resonance"]
    assert r == "unstable: 1 resonance in the operating range, largest severity 2 m/s"


def test_a_mechanism_with_a_gap_is_never_stable():
    """No band found but a part of the search left out by a limit: "not fully searched" with
    the gap's reason, never "stable"; with bands found the gap is appended to the verdict."""
    gap = SearchGap(stage="vehicle", reason="harmonic k = 19 not searched: max_steps",
                    limit="max_steps", k=19)
    v = dict((k, t) for k, _, t in mechanism_verdicts(
        (), computed={"vehicle": True, "pitch": True}, gaps=[gap]))
    assert v["vehicle"] == "not fully searched: harmonic k = 19 not searched: max_steps"
    assert v["pitch"] == "stable in the operating range"
    # growth 1 1/s: e-folding 1 s, unstable (docs/theory/verdicts.md)
    bands = danger_bands([_band("vehicle", 20.0, 21.0, 1.0, k=2)], operating_range=OPERATING)
    (text,) = [t for k, _, t in mechanism_verdicts(bands, computed={"vehicle": True},
                                                   gaps=[gap]) if k == "vehicle"]
    assert text.startswith("unstable: 1 instability region") and text.endswith(
        "; not fully searched: harmonic k = 19 not searched: max_steps")


def test_a_steady_region_is_named_unstable_without_pulsation():
    """A "steady" region (the system under the steady thrust alone is unstable: Beal's
    follower flutter, or the slow growth of a gimballed rigid pitch with damped elastic modes)
    is not a parametric region: its cause says so, and the verdict names it with its
    e-folding time 1 / growth (exact)."""
    bands = danger_bands([_ba(OPERATING[0], OPERATING[1], 2.0e-3, kind="steady", modes=(0,),
                              order=0), _ba(30.0, 31.0, 0.5)], operating_range=OPERATING)
    steady = [b for b in bands if b.cause_text.startswith(STEADY_CAUSE)]
    assert len(steady) == 1 and "gamma = 0" in steady[0].cause_text
    assert "instability region" not in steady[0].cause_text
    (text,) = [t for k, _, t in mechanism_verdicts(bands, computed={"beam_action": True})
               if k == "beam_action"]
    assert text == ("unstable: 2 instability regions in the operating range, largest growth "
                    "rate 0.5 1/s (1 of them unstable without pulsation: growth rate 0.002 "
                    "1/s, e-folding time 500 s)")


def test_summary_to_dict_is_json():
    s = danger_summary(operating_range=OPERATING,
                       bands={"pitch": [_band("pitch", 40, 42, 0.25, modes=(PITCH_MODE,))]})
    d = json.loads(json.dumps(s.to_dict()))
    assert d["operating_range"] == [10.0, 100.0]
    assert d["bands"][0]["Omega_lo_hz"] == pytest.approx(40 / (2 * math.pi), rel=1e-15)
    assert [v["verdict"] for v in d["verdicts"]][1:] == ["not computed"] * 3
    assert isinstance(s.bands[0], RankedBand)
    band = json.loads(json.dumps(s.bands[0].band.to_dict()))
    assert band["modes"] == [PITCH_MODE.to_dict()] and band["width"] == 2.0


@pytest.mark.slow
def test_memo_case_top_band_is_the_beam_action_maximum(memo_results):
    # two paths to one number: the first ranked band's growth rate equals the beam action's
    # own largest growth rate (memo 4.1 bands, exact maxima; 1e-12 relative), and every band
    # of the pitch and the beam action is listed once
    r = memo_results
    assert r.danger is not None
    top = r.danger.bands[0]
    assert top.mechanism == "beam_action"
    assert top.growth_rate == pytest.approx(r.beam_action.max_growth_rate, rel=1e-12)
    n_vehicle = 0 if r.vehicle_regions is None else len(r.vehicle_regions.regions)
    assert len(r.danger.bands) == len(r.pitch.bands) + len(r.beam_action.bands) + n_vehicle
    assert json.loads(json.dumps(r.to_dict()["danger"]))["bands"][0]["mechanism"] == \
        "beam_action"
