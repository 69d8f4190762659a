"""Up-front cost of the vehicle stages (flexbooster.cost) and the verdict of a search with gaps.

Interface tiers: a ``[vehicle]`` case whose regions cannot fit the budget (undamped, 40 modes
per k, k_max = 40) is refused before any solver runs with a ``CaseError`` on ``max_seconds``
that gives the estimate and the fields that drive it; the memo case and a damped 40-mode
case (certified stable: no search) are not refused; a map with a SearchGap and no region is
not "stable".  The calibration (measured times) is in the comments of flexbooster/cost.py;
estimate against measured time in benchmarks/bench_vehicle_regions.py (``--cost``), not here.
"""

from __future__ import annotations

import dataclasses
import tomllib
from pathlib import Path

import pytest

from flexbooster import cost
from flexbooster.analysis import analyze
from flexbooster.bands import SearchGap
from flexbooster.case import load_case, memo_case_text
from flexbooster.errors import CaseError
from flexbooster.model import model_from_case, vehicle_from_case
from flexbooster.shell_of_revolution import mesh_vehicle, rigid_motion_count

DATA = Path(__file__).parent / "data"


def _case(**vehicle):
    data = tomllib.loads(memo_case_text())
    if vehicle:
        data["vehicle"] = dict(vehicle)
        if "segments" in vehicle:  # one vehicle per case: the segments, the booster's material
            booster = data.pop("booster")
            data["vehicle"].update({k: booster[k] for k in ("E", "nu", "rho")})
    return load_case(data)


def test_big_undamped_vehicle_case_is_refused_up_front():
    """k_max = 40, n_modes = 40, undamped: the regions' searches (k = 1..40, each searched: no
    certificate without damping; their candidates counted) are estimated at thousands of
    seconds, over the default budget of 300 s: analyze refuses before any solver runs
    (CaseError on max_seconds) and the message has the estimate and the driving fields
    (vehicle.n_modes, damping.modal_ratio, vehicle.k_max, thrust.omega_min)."""
    case = _case(k_max=40, n_modes=40, damping_ratio=0.0)
    with pytest.raises(CaseError) as info:
        analyze(case, beam_action=False, figures=False)
    exc = info.value
    assert exc.field == "max_seconds" and "\n" not in str(exc)
    msg = str(exc)
    assert cost.UNDAMPED_SEARCH_PART in msg and "estimated run time" in msg
    for name in ("vehicle.n_modes", "damping.modal_ratio", "vehicle.k_max",
                 "thrust.omega_min"):
        assert name in msg
    est = cost.estimate_vehicle_cost(case)
    assert est.parts[cost.UNDAMPED_SEARCH_PART] > case.max_seconds
    # without the vehicle regions (--no-vehicle) the same case fits
    assert cost.estimate_vehicle_cost(case, regions=False).seconds < case.max_seconds


@pytest.mark.parametrize("vehicle", [{}, {"k_max": 40, "n_modes": 40}],
                         ids=["default", "damped-40-modes"])
def test_default_and_damped_cases_are_not_refused(vehicle):
    """The memo case (no [vehicle]: k = 1..20, 20 modes, zeta = 0.01) and a damped
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


def _three_long_segments(k_max: int = 15, **vehicle):
    """A fuzz case: three long segments, n_modes 247, k_max 15, zeta 1e-4, whose run spends
    over 60 s inside the stability certificates."""
    segment = {"kind": "cylinder", "radius": 5.05, "length": 60.0, "thickness": 0.02}
    return _case(k_max=k_max, n_modes=247, damping_ratio=1e-4,
                 segments=[segment, dict(segment), dict(segment)], **vehicle)


@pytest.mark.slow
def test_certificates_are_counted_and_refused_up_front():
    """Source: the certificate's bounded work (floquet.bounds: CERTIFICATE_FLOPS_PER_N3
    (2n)^3 operations per call, three calls per damped harmonic with the chart); the estimate
    has a "vehicle certificates" part, growing like n^3 (8x for twice the modes, exact), and a
    20 s budget (the fuzz's) refuses that case before any solver runs, naming the part
    and vehicle.n_modes. (k_max = 3 instead of 15: the estimate builds each harmonic's modal
    system, and the n^3 law and the refusal do not depend on the number of harmonics.)"""
    case = _three_long_segments(k_max=3)
    used = cost.region_modes(case, k_max=3)[0]
    est = cost.estimate_vehicle_cost(case)
    assert est.parts["vehicle certificates"] > 0.0
    half = cost.estimate_vehicle_cost(_case(
        k_max=3, n_modes=used // 2, damping_ratio=1e-4,
        segments=[{"kind": "cylinder", "radius": 5.05, "length": 60.0, "thickness": 0.02}] * 3))
    ratio = est.parts["vehicle certificates"] / half.parts["vehicle certificates"]
    assert ratio == pytest.approx((used / (used // 2)) ** 3, rel=1e-12)
    small = case.model_copy(update={"max_seconds": 20.0})
    with pytest.raises(CaseError) as info:
        analyze(small, beam_action=False, stability=False)
    msg = str(info.value)
    # the refusal names the largest parts (the searches of k >= 2 and of k = 1 lead here, the
    # certificates counted above) and the field that drives them
    assert info.value.field == "max_seconds" and "vehicle k >= 2 searches" in msg
    assert "vehicle.n_modes" in msg and "\n" not in msg
def _tank_case(n_tanks: int, n_masses: int = 0):
    """The memo case with a [vehicle] of three 2 m cylinders (R 1.5 m, 4 mm aluminium) and
    the first ``n_tanks`` of its three segments filled to 60 %, ``n_masses`` masses of 500 kg."""
    data = tomllib.loads(memo_case_text())
    del data["booster"]  # one vehicle per case: the segments
    cyl = {"kind": "cylinder", "radius": 1.5, "length": 2.0, "thickness": 0.004}
    data["vehicle"] = {
        "E": 70e9, "nu": 0.3, "rho": 2700.0, "segments": [dict(cyl) for _ in range(3)],
        "tanks": [{"aft": 2.0 * i, "fwd": 2.0 * i + 2.0, "fill": 0.6, "density": 1140.0}
                  for i in range(n_tanks)],
        "masses": [{"station": 1.0 * i, "mass": 500.0} for i in range(n_masses)]}
    return load_case(data)


@pytest.mark.slow
def test_vehicle_estimate_grows_with_the_tanks_and_the_masses():
    """Each tank adds its liquid mesh and an added mass per harmonic to the modes and the
    regions, each lumped mass its matrices of k <= 1 (the estimate is monotone in both; the
    fields that drive it are named)."""
    est = [cost.estimate_vehicle_cost(_tank_case(n)) for n in range(4)]
    for part in ("vehicle modes", "vehicle regions"):
        values = [e.parts[part] for e in est]
        assert all(b > a for a, b in zip(values, values[1:], strict=False)), (part, values)
        assert "vehicle.tanks" in est[1].drivers[part]
        assert "vehicle.tanks" not in est[0].drivers[part]
    with_masses = cost.estimate_vehicle_cost(_tank_case(1, 3))
    # the masses' matrices (the k = 1 search part, if any, depends on the harmonic's spectrum)
    assert with_masses.parts["vehicle modes"] > est[1].parts["vehicle modes"]
    assert "vehicle.masses" in with_masses.drivers["vehicle modes"]


@pytest.mark.parametrize("aft_end,rigid", [("free", (2, 2, 0)), ("hinged", (0, 0, 0))])
def test_dense_survey_harmonics_are_those_with_rigid_motions(aft_end, rigid):
    """The estimate prices the survey harmonics and the regions' builds with rigid-body
    motions by their own laws (``cost._SURVEY_DENSE_LAW``, ``_BUILD_DENSE_LAW``: their modes
    are solved on the complement of those motions). A free-free shell of revolution has two
    at k = 0 (axial translation, rotation about the axis) and two at k = 1 (lateral
    translation, pitch), none at k >= 2 (Kraus 1967, the rigid-body motions of a shell of
    revolution); the tests/data tube's hinged aft end (u = v = w = 0 there) admits none."""
    data = tomllib.loads((DATA / "long_tube_case.toml").read_text())
    data["vehicle"].update(aft_end=aft_end, k_max=2)
    data["vehicle"]["segments"][0]["length"] = "45 m"
    data["output"]["stations"][0]["station"] = 45.0
    case = load_case(data)
    vehicle = vehicle_from_case(case)
    mesh = mesh_vehicle(vehicle)
    assert tuple(rigid_motion_count(vehicle, mesh, k) for k in range(3)) == rigid
    dense = tuple(k for k in range(2) if rigid[k])
    assert cost._dense_harmonics(vehicle, mesh, 2) == dense
    assert cost._dense_harmonics(vehicle, mesh, 0) == tuple(k for k in dense if k == 0)
