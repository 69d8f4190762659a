"""Up-front cost of the vehicle stages (flexbooster.cost) and the verdict of a search with gaps.

Interface tiers: a ``[vehicle]`` case whose regions cannot fit the budget (undamped, 40 modes
per k, k_max = 40) is refused before any solver runs with a ``CaseError`` on ``max_seconds``
that gives the estimate and the fields that drive it; the default case and a damped 40-mode
case (certified stable: no search) are not refused; a map with a SearchGap and no region is
not "stable".  The calibration (measured times) is in the comments of flexbooster/cost.py;
estimate against measured time in benchmarks/bench_vehicle_regions.py (``--cost``), not here.
"""

from __future__ import annotations

import dataclasses
import tomllib

import pytest

from flexbooster import cost
from flexbooster.analysis import analyze
from flexbooster.bands import SearchGap
from flexbooster.case import default_case_text, load_case
from flexbooster.errors import CaseError
from flexbooster.model import model_from_case


def _case(**vehicle):
    data = tomllib.loads(default_case_text())
    if vehicle:
        data["vehicle"] = dict(vehicle)
    return load_case(data)


def test_big_undamped_vehicle_case_is_refused_up_front():
    """k_max = 40, n_modes = 40, undamped: the regions (k = 1..40, each searched: no
    certificate without damping) are estimated at thousands of seconds, over the default
    budget of 300 s: analyze refuses before any solver runs (CaseError on max_seconds) and the
    message has the estimate and the driving fields (vehicle.n_modes, damping.modal_ratio,
    vehicle.k_max, thrust.omega_min)."""
    case = _case(k_max=40, n_modes=40, damping_ratio=0.0)
    with pytest.raises(CaseError) as info:
        analyze(case, beam_action=False, figures=False)
    exc = info.value
    assert exc.field == "max_seconds" and "\n" not in str(exc)
    msg = str(exc)
    assert "vehicle regions" in msg and "estimated run time" in msg
    for name in ("vehicle.n_modes", "damping.modal_ratio", "vehicle.k_max",
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
    certified lower bound (building each harmonic)."""
    case = _case(**vehicle)
    model = model_from_case(case)
    est = cost.check_case_cost(model, case.max_seconds, vehicle=cost.estimate_vehicle_cost(
        case), beam_action=True, stability=True,
        figures=True)
    assert est.parts["vehicle regions"] < 5.0 and est.seconds < case.max_seconds
    upper = cost.estimate_vehicle_cost(case, certified=False)
    assert upper.parts["vehicle regions"] > est.parts["vehicle regions"]


def test_verdict_is_not_stable_when_a_harmonic_is_a_gap():
    """No region found but a harmonic past a size limit: the verdict is not "stable"
    (present.rows.vehicle_region_verdict reads only the stored result)."""
    from types import SimpleNamespace

    from flexbooster.dynamics import VehicleRegions
    from flexbooster.present.rows import vehicle_region_verdict

    vr = VehicleRegions(regions=(), harmonics=(), curves=(), F0=1.0, gamma=0.1,
                        damping_ratio=0.0, omega_min=1.0, omega_max=10.0,
                        supported_forward_end=False,
                        gaps=(SearchGap(stage="vehicle", reason="harmonic k = 2 ...",
                                        limit="max_steps", k=2),))
    text, stable = vehicle_region_verdict(SimpleNamespace(vehicle_regions=vr))
    assert not stable and text.startswith("not fully searched: 1 harmonic(s) not searched")
    text, stable = vehicle_region_verdict(SimpleNamespace(
        vehicle_regions=dataclasses.replace(vr, gaps=())))
    assert stable and text.startswith("stable:")
