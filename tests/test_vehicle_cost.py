"""Bounded cost of the vehicle stages (issue 18 item 1 for issue 15's map).

Tiers:

* exact (interface): a ``[vehicle]`` case whose vehicle regions cannot fit the budget
  (undamped, 40 modes per k, k_max = 40) is refused up front through the API with a
  ``CaseError`` on ``max_seconds`` that gives the estimate and names the fields that drive it;
  the default case and a damped 40-mode case (certified stable: no search) are not refused;
* invariant: a harmonic that the budget leaves out is not searched and is named in
  ``VehicleRegions.skipped``; the harmonics searched give the same rows as without a budget
  (exact), and the pipeline turns each skipped one into a warning.

The calibration of the estimates (measured times) is in the comments of
flexbooster/vehicle/regions.py and flexbooster/cost.py; estimate against measured time is in
benchmarks/bench_vehicle_regions.py (``--cost``), not here (no timed assertions).
"""

from __future__ import annotations

import dataclasses
import tomllib

import pytest

import flexbooster
from flexbooster import cost, floquet
from flexbooster.analysis import _vehicle_regions_stage, analyze
from flexbooster.case import default_case_text, load_case
from flexbooster.errors import CaseError
from flexbooster.model import model_from_case, vehicle_from_case
from flexbooster.vehicle import (
    HARMONIC_BUILD_SECONDS,
    harmonic_search_seconds,
    vehicle_regions,
)


def _case(**vehicle):
    data = tomllib.loads(default_case_text())
    if vehicle:
        data["vehicle"] = dict(vehicle)
    return load_case(data)


def test_big_undamped_vehicle_case_is_refused_up_front():
    """k_max = 40, n_modes = 40, undamped: the regions (k = 1..40, each searched: no
    certificate without damping) are estimated at thousands of seconds, over the default
    budget of 300 s: analyze refuses before any solver runs (CaseError on max_seconds) and the
    message has the estimate and the driving fields (vehicle.n_modes, vehicle.damping_ratio,
    vehicle.k_max, thrust.omega_min)."""
    case = _case(k_max=40, n_modes=40, damping_ratio=0.0)
    with pytest.raises(CaseError) as info:
        analyze(case, beam_action=False, figures=False)
    exc = info.value
    assert exc.field == "max_seconds" and "\n" not in str(exc)
    msg = str(exc)
    assert "vehicle regions" in msg and "estimated run time" in msg
    for name in ("vehicle.n_modes", "vehicle.damping_ratio", "vehicle.k_max",
                 "thrust.omega_min"):
        assert name in msg
    est = cost.estimate_vehicle_cost(case)
    assert est.parts["vehicle regions"] > case.max_seconds
    # without the vehicle regions (--no-vehicle) the same case fits
    assert cost.estimate_vehicle_cost(case, regions=False).seconds < case.max_seconds


@pytest.mark.parametrize("vehicle", [{}, {"k_max": 40, "n_modes": 40}],
                         ids=["default", "damped-40-modes"])
def test_default_and_damped_cases_are_not_refused(vehicle):
    """The default case (no [vehicle]: k = 1..20, 20 modes, zeta = 0.01) and a damped
    40-mode [vehicle] case (k = 1..40) fit the budget: with damping the estimate is the
    certified lower bound (building each harmonic), the budget is then enforced per harmonic
    (next test)."""
    case = _case(**vehicle)
    model = model_from_case(case)
    est = cost.check_case_cost(model, case.max_seconds, vehicle=cost.estimate_vehicle_cost(
        case), beam_action=True, stability=True,
        figures=True)
    assert est.parts["vehicle regions"] < 5.0 and est.seconds < case.max_seconds
    upper = cost.estimate_vehicle_cost(case, certified=False)
    assert upper.parts["vehicle regions"] > est.parts["vehicle regions"]


def test_harmonics_past_the_budget_are_skipped_and_named():
    """The default vehicle, undamped, 3 modes, k = 1..3, gamma = 0.3 (regions in every k):
    with a budget between the running estimate after k = 1 (one build and k = 1's search) and
    the one k = 2 or k = 3 would add (each harmonic's estimate from
    floquet.search_work, its candidates and step counts), k = 1 is searched and k = 2, 3 are
    named in ``skipped`` (not searched, no rows); k = 1's rows equal those of the run without
    a budget (exact)."""
    veh = vehicle_from_case(flexbooster.default_case())
    kw = dict(F0=2.8e6, gamma=0.3, omega_min=5.0, omega_max=2000.0, k_min=1, k_max=3,
              n_modes=3, damping_ratio=0.0, gimbal_gain=0.5, axial=False)
    free = vehicle_regions(veh, **kw)
    est = []
    for h in free.harmonics:
        M, _, A, B = h.matrices(0.3)
        est.append(harmonic_search_seconds(floquet.search_work(M, None, A, B, 5.0, 2000.0)))
    build = HARMONIC_BUILD_SECONDS
    budget = 2.0 * build + est[0] + 0.5 * min(est[1], est[2])
    capped = vehicle_regions(veh, max_seconds=budget, **kw)
    assert {r.k for r in free.regions} == {1, 2, 3} and free.skipped == ()
    assert [w.split(" not searched")[0] for w in capped.skipped] == [
        f"max_seconds = {budget:g}: harmonic k = 2", f"max_seconds = {budget:g}: harmonic k = 3"]
    assert all("vehicle.n_modes" in w and "estimated at" in w for w in capped.skipped)
    assert capped.regions == tuple(r for r in free.regions if r.k == 1)
    assert capped.to_dict()["skipped"] == list(capped.skipped)
    assert capped.estimated_seconds == pytest.approx(3 * build + est[0], rel=1e-12)
    with pytest.raises(ValueError, match="^max_seconds = "):
        vehicle_regions(veh, max_seconds=0.0, **kw)


def test_pipeline_warns_for_each_skipped_harmonic(monkeypatch):
    """The stage turns each harmonic a limit left out into a warning (code
    vehicle-regions-skipped, the field the reason names) and keeps the regions it has."""
    import flexbooster.analysis as analysis

    real = analysis.vehicle_regions
    why = "thrust.omega_min = 1: harmonic k = 2 not searched, past the candidate limit"

    def limited(vehicle, **kw):
        return dataclasses.replace(real(vehicle, **{**kw, "k_max": 1}), skipped=(why,))

    monkeypatch.setattr(analysis, "vehicle_regions", limited)
    found, warnings = _vehicle_regions_stage(_case(k_max=2, n_modes=3), boundaries=False)
    assert found is not None
    (w,) = warnings
    assert (w.code, w.field, w.message) == ("vehicle-regions-skipped", "thrust.omega_min", why)


def test_verdict_is_unknown_when_harmonics_were_skipped():
    """No region found but a harmonic skipped by the budget: the verdict is not "stable"
    (present.rows.vehicle_region_verdict reads only the stored result)."""
    from types import SimpleNamespace

    from flexbooster.present.rows import vehicle_region_verdict
    from flexbooster.vehicle import VehicleRegions

    vr = VehicleRegions(regions=(), harmonics=(), curves=(), F0=1.0, gamma=0.1,
                        damping_ratio=0.0, omega_min=1.0, omega_max=10.0,
                        supported_forward_end=False, skipped=("max_seconds = 1: k = 2 ...",))
    text, stable = vehicle_region_verdict(SimpleNamespace(vehicle_regions=vr))
    assert not stable and text.startswith("unknown: 1 harmonic(s) not searched")
    text, stable = vehicle_region_verdict(SimpleNamespace(
        vehicle_regions=dataclasses.replace(vr, skipped=())))
    assert stable and text.startswith("stable:")
