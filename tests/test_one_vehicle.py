"""One vehicle per case: ``[booster]`` or ``[vehicle]`` with segments.

Tiers:

* exact limits: the memo case written as an equivalent ``[vehicle]`` (two cylinder
  segments, a "memo-bulkhead" junction, "shear-diaphragm" ends, [booster]'s material) gives
  the vehicle modes and the vehicle regions of the memo vehicle that ``model.vehicle_from_case``
  builds from ``[booster]`` (rel. 1e-12: the same shell of revolution reached two ways);
* independent model: its rigid-body pitch omega_psi = sqrt(F0 d K / I_cm) from the vehicle's
  quadrature mass properties equals the memo's closed-form mass properties of the two
  cylinders (memo 2.2, eq. 4.2-1; rel. 1e-12), and so do the Mathieu exponents of the pitch;
* interfaces: both tables, neither, a missing material: one CaseError line naming the field
  (exit 2); the memo's results.json keys hold ``{"not_applicable": reason}`` and its verdicts
  are never "stable"; the summary and the report say "not applicable" and list every mass
  contribution; ``modes`` without ``[thrust]`` gives the unloaded modes, ``run`` without it
  is one line naming ``thrust``.
"""

from __future__ import annotations

import copy
import dataclasses
import json
import math
import re
import tomllib
from pathlib import Path

import numpy as np
import pytest
from rich.console import Console

from conftest import run_cli
from flexbooster.analysis import analyze, analyze_vehicle, analyze_vehicle_regions
from flexbooster.case import load_case, memo_case, memo_case_text
from flexbooster.errors import CaseError
from flexbooster.memo.pitch import pitch_analysis
from flexbooster.model import MEMO_NOT_APPLICABLE, model_from_case, vehicle_from_case
from flexbooster.present.report import render_report
from flexbooster.present.summary import print_summary
from flexbooster.results import MEMO_SECTIONS
from flexbooster.shell_of_revolution import (
    Cylinder,
    LumpedMass,
    Vehicle,
    VehicleTank,
    mass_properties,
)

SEGMENT_TOML = """
name = "the memo case as vehicle segments"
[thrust]
F0 = "2.8 MN"
gamma = 0.05
K = 0.5
omega_min = "5 rad/s"
omega_max = "2000 rad/s"
n_omega = 400
[vehicle]
E = "10.5e6 psi"
nu = 0.33
rho = "2.59e-4 lbf*s^2/in^4"
aft_end = "shear-diaphragm"
fwd_end = "shear-diaphragm"
[[vehicle.segments]]
kind = "cylinder"
radius = "5.05 m"
length = "42 m"
thickness = "20 mm"
[[vehicle.segments]]
kind = "cylinder"
radius = "3.30 m"
length = "18 m"
thickness = "20 mm"
junction = "memo-bulkhead"
"""


#: The [vehicle] tables of SEGMENT_TOML alone (no name, no [thrust]).
VEHICLE_TOML = SEGMENT_TOML[SEGMENT_TOML.index("[vehicle]"):]


def _segments() -> dict:
    """The memo case (src/flexbooster/data/memo_case.toml) as its equivalent [vehicle]:
    cylinder 1 (R1 = 5.05 m, 2 L1 = 42 m), cylinder 2 (R2 = 3.30 m, 2 L2 = 18 m), h = 20 mm,
    the same material and thrust."""
    return tomllib.loads(SEGMENT_TOML)


def _close(a, b, rtol: float, where: str = "") -> None:
    """Two JSON-like trees equal: numbers to rtol (relative), everything else exactly."""
    if isinstance(a, dict):
        assert isinstance(b, dict) and a.keys() == b.keys(), where
        for key in a:
            _close(a[key], b[key], rtol, f"{where}.{key}")
    elif isinstance(a, (list, tuple)):
        assert isinstance(b, (list, tuple)) and len(a) == len(b), where
        for i, (x, y) in enumerate(zip(a, b, strict=True)):
            _close(x, y, rtol, f"{where}[{i}]")
    elif isinstance(a, float) and not isinstance(b, bool):
        assert b == pytest.approx(a, rel=rtol, abs=0.0, nan_ok=True), where
    else:
        assert a == b, where



# --------------------------------------------------------------------------- the case


def test_booster_and_segments_is_one_line_error(tmp_path, capsys):
    """[booster] and [[vehicle.segments]] together: a CaseError naming both tables (exit 2,
    one line)."""
    data = tomllib.loads(memo_case_text())
    data["vehicle"] = _segments()["vehicle"]
    with pytest.raises(CaseError) as info:
        load_case(data)
    assert info.value.field == "booster/vehicle.segments"
    assert "[booster]" in info.value.rule and "[[vehicle.segments]]" in info.value.rule
    path = tmp_path / "both.toml"
    path.write_text(memo_case_text() + "\n" + VEHICLE_TOML)
    assert run_cli(["modes", str(path)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("flexbooster: error: booster/vehicle.segments = 'both'")
    assert "\n" not in err


def test_neither_booster_nor_segments_names_booster():
    """No [booster] and a [vehicle] without segments (or none): booster is missing."""
    data = _segments()
    del data["vehicle"]["segments"]
    for case in (data, {k: v for k, v in data.items() if k != "vehicle"}):
        with pytest.raises(CaseError) as info:
            load_case(case)
        assert info.value.field == "booster" and "vehicle.segments" in info.value.rule


@pytest.mark.parametrize("name", ["E", "nu", "rho"])
def test_segments_without_a_material_name_the_field(name):
    """Without [booster] every segment needs E, nu, rho (its own or [vehicle]'s): the first
    segment without one is named; a value on every segment is enough."""
    data = _segments()
    value = data["vehicle"].pop(name)
    with pytest.raises(CaseError) as info:
        load_case(data)
    assert info.value.field == f"vehicle.segments[0].{name}"
    assert f"vehicle.{name}" in info.value.rule
    data["vehicle"]["segments"][0][name] = value
    with pytest.raises(CaseError) as info:
        load_case(data)
    assert info.value.field == f"vehicle.segments[1].{name}"
    data["vehicle"]["segments"][1][name] = value
    assert getattr(vehicle_from_case(load_case(data)).segments[1], name) == getattr(
        memo_case().booster, name)


def test_t0_is_per_unit_circumference_of_the_first_segment():
    """T0 of a [vehicle] case: F0 = 2 pi R_aft T0 with R_aft the first segment's aft radius
    (5.05 m; exact to rel. 1e-15), and results.json records both."""
    data = _segments()
    data["thrust"]["T0"] = 1000.0
    del data["thrust"]["F0"]
    case = load_case(data)
    assert case.F0 == pytest.approx(2.0 * math.pi * 5.05 * 1000.0, rel=1e-15)
    si = case.to_si_dict()
    assert "booster" not in si and si["thrust"]["F0"] == case.F0


# --------------------------------------------------------------------------- acceptance


@pytest.mark.slow
def test_equivalent_vehicle_gives_the_memo_vehicle_modes_and_regions():
    """Acceptance: the memo case as [booster] and as its equivalent [vehicle]
    give the same vehicle modes (k = 0..20, prestressed by F0) and the same vehicle regions
    (every number of VehicleRegions.to_dict) to rel. 1e-12. Source: the memo vehicle built
    from [booster] by model.vehicle_from_case."""
    memo, seg = memo_case(), load_case(_segments())
    assert vehicle_from_case(memo) == vehicle_from_case(seg)
    a, b = analyze_vehicle(memo, views=False), analyze_vehicle(seg, views=False)
    assert (a.source, b.source) == ("memo", "vehicle")
    np.testing.assert_array_equal(a.modes.k, b.modes.k)
    np.testing.assert_allclose(b.modes.hz, a.modes.hz, rtol=1e-12, atol=0.0)
    ra = analyze_vehicle_regions(memo, boundaries=False)
    rb = analyze_vehicle_regions(seg, boundaries=False)
    _close(ra.to_dict(), rb.to_dict(), 1e-12, "vehicle_regions")


@pytest.fixture(scope="module")
def segment_results():
    return analyze(load_case(_segments()), figures=False)


def test_vehicle_pitch_equals_the_memo_pitch(segment_results):
    """omega_psi = sqrt(F0 d K / I_cm) from the vehicle's mass properties (Gauss quadrature of
    the walls, d = the centre of mass from the aft edge) equals the memo's (closed-form mass
    properties of the two cylinders, memo 2.2, eq. 4.2-1, erratum E1/E2) to rel. 1e-12, and
    the pitch's Mathieu exponents and bands equal the memo's to rel. 1e-12."""
    model = model_from_case(memo_case())
    res = segment_results
    assert res.omega_psi == pytest.approx(model.omega_psi, rel=1e-12)
    m = res.vehicle_mass
    assert (m.mass_kg, m.cm_m, m.I_cm_kg_m2) == pytest.approx(
        (model.mass.mass, model.mass.x_cm, model.mass.I_cm), rel=1e-12)
    ref = pitch_analysis(model.Omega, model.omega_psi, model.gamma)
    _close(ref.to_dict(), res.pitch.to_dict(), 1e-12, "pitch")


def test_results_json_memo_keys_not_applicable(segment_results):
    """results.json of a [vehicle]-segments case: every memo key present as
    {"not_applicable": "not applicable: <reason>"} (frequencies.omega_1 and omega_1_hz too);
    mass_properties = MassProperties.to_dict() of the vehicle; the memo's verdicts "not
    applicable", never "stable"; finite JSON."""
    res = segment_results
    out = json.loads(json.dumps(res.to_dict(), allow_nan=False))
    na = {"not_applicable": f"not applicable: {MEMO_NOT_APPLICABLE}"}
    for key in MEMO_SECTIONS:
        assert out[key] == na, key
    assert out["frequencies"]["omega_1"] == na and out["frequencies"]["omega_1_hz"] == na
    assert out["frequencies"]["omega_psi"] == res.omega_psi
    assert out["mass_properties"] == mass_properties(vehicle_from_case(res.case)).to_dict()
    assert "booster" not in out["case"]
    verdicts = {v["mechanism"]: v["verdict"] for v in out["danger"]["verdicts"]}
    assert verdicts["beam_action"].startswith("not applicable")
    assert verdicts["resonance"].startswith("not applicable")
    assert verdicts["pitch"] == "stable in the operating range"  # computed: the vehicle's pitch
    assert out["vehicle_modes"]["source"] == "vehicle" and out["vehicle_regions"] is not None


def test_summary_and_report_say_not_applicable_and_list_the_masses(segment_results):
    """The summary and the report: each memo section says "not applicable" with the reason;
    the mass table lists every contribution (shell, non-structural, lumped, each tank) of a
    vehicle with masses and tanks (mass_properties of a hand-built Vehicle)."""
    mat = dict(E=70e9, nu=0.3, rho=2700.0)
    vehicle = Vehicle((Cylinder(1.5, 6.0, 0.004, nonstructural_mass=5.0, **mat),
                       Cylinder(1.5, 4.0, 0.004, **mat)), junctions=("rigid-bulkhead",),
                      masses=(LumpedMass(0.0, 2000.0, name="engines"),
                              LumpedMass(10.0, 500.0, name="payload")),
                      tanks=(VehicleTank(0.0, 6.0, 0.5, 1140.0, name="oxidiser"),
                             VehicleTank(6.0, 10.0, 0.9, 800.0, name="fuel")))
    res = dataclasses.replace(segment_results, vehicle_mass=mass_properties(vehicle))
    console = Console(record=True, width=140)
    print_summary(res, console)
    text = console.export_text()
    html = render_report(res)
    for name in ("shell", "nonstructural", "lumped: engines", "lumped: payload",
                 "tank: oxidiser", "tank: fuel"):
        assert f"│ {name} " in text and f"<td>{name}</td>" in html, name
    assert " ".join(text.split()).count(f"not applicable: {MEMO_NOT_APPLICABLE}") >= 4
    # the report leaves the memo's six sections out and says so once, with the reason; the
    # verdicts of its two mechanisms say "not applicable" (the section ids spelled out)
    assert html.count("not applicable: the memo&#x27;s method") >= 2
    assert "Sections of the memo's method left out (not applicable: the memo&#x27;s" in html
    for sid in ("beam-modes", "beam-action", "shell-frequencies", "nodal-patterns",
                "unstable-frequencies", "campbell"):
        assert f'id="{sid}"' not in html and f'href="#{sid}"' not in html, sid
    # the rigid-body pitch section has none of the memo's figures (Ince-Strutt, band chart):
    # no note that they were "not drawn"; the notes name only this case's figures
    from flexbooster.present.outputs import figure_names

    assert "ince-strutt" not in figure_names(res)
    assert 'Figure "ince-strutt"' not in html and 'Figure "pitch-band-chart"' not in html
    notes = re.findall(r'Figure &quot;([a-z0-9-]+)&quot; was not drawn|Figure "([a-z0-9-]+)" '
                       r"was not drawn", html)
    assert {a or b for a, b in notes} <= set(figure_names(res))


# --------------------------------------------------------------------------- command line


def test_modes_without_thrust_is_unloaded(tmp_path, capsys):
    """`flexbooster modes` on a case without [thrust]: exit 0, the unloaded modes, equal to
    the modes of the same vehicle with --no-prestress (rel. 1e-12); `run` on it is one line
    naming thrust (exit 2), for [vehicle] and for [booster] cases alike."""
    data = _segments()
    del data["thrust"]
    case = load_case(data)
    got = analyze_vehicle(case, k_max=3, views=False)
    ref = analyze_vehicle(load_case(_segments()), k_max=3, prestress=False, views=False)
    assert not got.prestressed and got.note == "unloaded: the case has no thrust"
    np.testing.assert_allclose(got.modes.hz, ref.modes.hz, rtol=1e-12, atol=0.0)
    path = tmp_path / "nothrust.toml"
    path.write_text(VEHICLE_TOML)
    booster = tmp_path / "booster.toml"
    text = memo_case_text()
    booster.write_text(text[:text.index("[thrust]")] + text[text.index("[truncation]"):])
    for file in (path, booster):
        assert run_cli(["modes", str(file), "--k-max", "2", "--format", "json"]) == 0
        out = json.loads(capsys.readouterr().out)
        assert out["note"] == "unloaded: the case has no thrust" and not out["prestressed"]
        assert run_cli(["run", str(file), "-o", str(tmp_path / "out"), "-q"]) == 2
        err = capsys.readouterr().err.strip()
        assert err.startswith("flexbooster: error: thrust = None: required field is missing")
        assert "\n" not in err
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("command", [["stability"], ["simulate", "--omega", "300",
                                                     "--tau-max", "1"]])
def test_memo_commands_on_segments_name_booster(tmp_path, capsys, command):
    """`stability` and `simulate` are the memo's method: on a [vehicle]-segments case one
    line naming booster with the reason (exit 2)."""
    path = tmp_path / "seg.toml"
    path.write_text(SEGMENT_TOML)
    assert run_cli([*command, str(path), "-o", str(tmp_path / "out"), "-q"]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("flexbooster: error: booster = None:") and MEMO_NOT_APPLICABLE in err
    assert "\n" not in err


@pytest.mark.slow
def test_run_a_segment_case_writes_its_files(tmp_path, capsys):
    """`flexbooster run` on a [vehicle]-segments case: exit 0; results.json, the vehicle CSVs
    and the report; no memo shell CSV."""
    path = tmp_path / "seg.toml"
    data = copy.deepcopy(SEGMENT_TOML).replace("n_omega = 400", "n_omega = 40")
    path.write_text(data)
    assert run_cli(["run", str(path), "-o", str(tmp_path / "out"), "--no-figures", "-q"]) == 0
    names = {p.name for p in (tmp_path / "out").iterdir()}
    assert {"results.json", "vehicle-modes.csv", "vehicle-regions.csv", "report.html"} <= names
    assert "shell-frequencies.csv" not in names
    out = json.loads((tmp_path / "out" / "results.json").read_text())
    assert out["beam_action"]["not_applicable"].startswith("not applicable")


# --------------------------------------------------------------------------- the example

EXAMPLE = Path(__file__).parents[1] / "examples" / "two-stage-liquid.toml"


@pytest.mark.slow
def test_example_two_stage_liquid_modes(capsys):
    """`flexbooster modes examples/two-stage-liquid.toml`: exit 0; k = 0..20, finite positive
    frequencies; the mass properties list the three lumped masses (2000, 600, 3600 kg, exact)
    and the four tanks, each liquid pi R^2 (fwd - aft) fill rho within 1 % (R = 1.52 m, the
    mid-surface: the liquid's radius lies between it and the inner wall, h / R = 0.26 %);
    one slosh mode per tank; the table output lists the masses and the slosh."""
    assert run_cli(["modes", str(EXAMPLE), "--format", "json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["k_max"] == 20 and {m["k"] for m in out["modes"]} <= set(range(21))
    assert all(math.isfinite(m["hz"]) and m["hz"] > 0.0 for m in out["modes"])
    parts = {c["name"]: c for c in out["mass_properties"]["contributions"]}
    for name, mass in (("first-stage engine (LR87)", 2000.0),
                       ("second-stage engine (LR91)", 600.0), ("payload", 3600.0)):
        assert parts[name]["mass_kg"] == pytest.approx(mass, rel=1e-12)
    for name, length, fill, rho in (("stage-1 fuel", 6.5, 0.94, 903.0),
                                    ("stage-1 oxidiser", 8.0, 0.96, 1440.0),
                                    ("stage-2 fuel", 2.0, 0.80, 903.0),
                                    ("stage-2 oxidiser", 2.5, 0.80, 1440.0)):
        liquid = math.pi * 1.52**2 * length * fill * rho
        assert parts[name]["mass_kg"] == pytest.approx(liquid, rel=0.01)
    assert [m["tank"] for m in out["slosh"]] == ["stage-1 fuel", "stage-1 oxidiser",
                                                 "stage-2 fuel", "stage-2 oxidiser"]
    assert run_cli(["modes", str(EXAMPLE), "--k-max", "1"]) == 0
    text = " ".join(capsys.readouterr().out.split())
    assert "lumped: payload" in text and "tank stage-2 oxidiser: first slosh" in text


def test_sweep_scalars_of_a_segments_case_name_the_reason(segment_results):
    """A sweep's variables are the memo's (omega_1, shell frequencies, beam action, table): a
    segments case's point is a ValueError naming omega_1 and the reason (recorded per point by
    the sweep), not a TypeError on the not-applicable mapping."""
    from flexbooster.sweep.run import point_scalars

    with pytest.raises(ValueError, match=r"^omega_1: .*not applicable: the memo's method"):
        point_scalars(segment_results.to_dict())
