"""Integration: the ``[vehicle]`` case table, ``flexbooster modes``, vehicle modes in run.

Tiers:

* exact: unit conversions of the example table (pint, rel. 1e-12); defaults; the memo
  vehicle built from ``[booster]`` is the hand-built ``Vehicle`` (two cylinders R1, 2 L1 and
  R2, 2 L2, Tech Memo 104 Fig. 1), and its k >= 2 frequencies are those of
  ``shell_of_revolution.vehicle_modes`` on that Vehicle (rel. 1e-12: the same computation
  reached through the case; the physics is tested in tests/test_shell_of_revolution.py);
* independent model: the memo vehicle with Donnell theory, unloaded, k = 2..4 below 30 Hz
  equals the memo path's shell frequencies (``flexbooster.memo.shell.natural_frequencies``,
  each cylinder with shear-diaphragm edges, the Donnell cubic; rel. 1e-5);
* invariants and interfaces: every bad field gives one CaseError line naming it; the CLI
  ``modes`` table, JSON and files; ``run`` with a ``[vehicle]`` case adds the key, the CSV,
  the report section and its figures; the memo case's results.json gains no key.
"""

from __future__ import annotations

import copy
import csv
import json
import math
import tomllib
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from conftest import run_cli
from flexbooster.analysis import analyze, analyze_vehicle
from flexbooster.case import load_case, memo_case, memo_case_text
from flexbooster.errors import CaseError
from flexbooster.model import vehicle_from_case
from flexbooster.shell_of_revolution import Cone, Cylinder, Vehicle, vehicle_modes

#: The specification's example ``[vehicle]`` table, verbatim.
EXAMPLE_TABLE = """
[vehicle]
E = "70 GPa"
nu = 0.3
rho = "2700 kg/m^3"
aft_end = "free"          # free | shear-diaphragm | clamped
fwd_end = "free"
theory = "sanders"        # sanders | donnell
k_max = 20                # circumferential harmonics k = 0..k_max
[[vehicle.segments]]      # listed from the aft edge forward
kind = "cylinder"
radius = "1.5 m"
length = "6 m"
thickness = "8 mm"
[[vehicle.segments]]
kind = "cone"             # a conical frustum; length 0 is a flat annular plate
radius_aft = "1.5 m"
radius_fwd = "1.0 m"
length = "1 m"            # along the axis
thickness = "8 mm"
"""

#: A small, fast analysis (the vehicle stage is what is tested, not the memo stages).
SMALL = {"n_omega": 40, "truncation": dict(M1=3, N1=3, M2=3, N2=3, N=3, S=2, R=2)}


def _base() -> dict:
    return copy.deepcopy(tomllib.loads(memo_case_text()))


def _small(data: dict) -> dict:
    data["thrust"]["n_omega"] = SMALL["n_omega"]
    data["truncation"] = dict(SMALL["truncation"])
    return data


def _with_example_table(**changes) -> dict:
    """The memo case with the example [vehicle] table in place of [booster] (one vehicle per
    case) and F0 = 0.3 MN (2.8 MN would exceed the k = 2 buckling load of this small free-free
    vehicle)."""
    data = _base()
    del data["booster"]
    data["thrust"]["F0"] = "0.3 MN"
    data.update(tomllib.loads(EXAMPLE_TABLE))
    data["vehicle"].update(changes)
    return data



def _toml_value(value):
    if isinstance(value, str):
        return json.dumps(value)
    if isinstance(value, bool):
        return "true" if value else "false"
    return repr(value)


def dump_case(data: dict) -> str:
    """TOML text of a case mapping, with [vehicle] and [[vehicle.segments]]."""
    lines = [f"name = {_toml_value(data.get('name', 'case'))}"]

    def table(name, body):
        lines.append(f"[{name}]")
        subs = []
        for key, value in body.items():
            if isinstance(value, dict):
                subs.append((f"{name}.{key}", value))
            elif isinstance(value, list) and value and isinstance(value[0], dict):
                subs.append((f"{name}.{key}", value))
            else:
                lines.append(f"{key} = {_toml_value(value)}")
        for sub, value in subs:
            if isinstance(value, dict):
                table(sub, value)
            else:
                for item in value:
                    lines.append(f"[[{sub}]]")
                    lines.extend(f"{k} = {_toml_value(v)}" for k, v in item.items())

    for name in ("booster", "thrust", "truncation", "vehicle"):
        if name in data:
            table(name, data[name])
    return "\n".join(lines) + "\n"


# --------------------------------------------------------------------------- case parsing


def test_example_table_units_and_defaults():
    """The example table: pint conversions (70 GPa = 7e10 Pa, 8 mm = 0.008 m, rel. 1e-12),
    segment material = the table's, one continuous junction, the ends and theory given."""
    case = load_case(_with_example_table())
    veh = vehicle_from_case(case)
    assert veh.junctions == ("continuous",)
    assert (veh.aft_end, veh.fwd_end, veh.theory) == ("free", "free", "sanders")
    cyl, cone = veh.segments
    assert isinstance(cyl, Cylinder) and isinstance(cone, Cone)
    np.testing.assert_allclose([cyl.radius, cyl.length, cyl.thickness], [1.5, 6.0, 0.008],
                               rtol=1e-12)
    np.testing.assert_allclose([cone.radius_aft, cone.radius_fwd, cone.length],
                               [1.5, 1.0, 1.0], rtol=1e-12)
    for seg in veh.segments:
        np.testing.assert_allclose([seg.E, seg.nu, seg.rho], [70e9, 0.3, 2700.0], rtol=1e-12)
    assert case.vehicle.k_max == 20


def test_defaults_material_fallback_and_rigid_bulkhead():
    """A segment without material takes [vehicle]'s (70 GPa, 0.3, 2700 kg/m^3, rel. 1e-12); a
    per-segment E overrides; ends default "free", k_max 20, theory sanders; junction =
    "rigid-bulkhead" joins radii that differ (1.5 m to 1.2 m)."""
    data = _base()
    del data["booster"]
    data["vehicle"] = {"E": "70 GPa", "nu": 0.3, "rho": "2700 kg/m^3", "segments": [
        {"kind": "cylinder", "radius": "1.5 m", "length": "6 m", "thickness": "8 mm"},
        {"kind": "cylinder", "radius": "1.2 m", "length": "3 m", "thickness": "6 mm",
         "E": "200 GPa", "junction": "rigid-bulkhead"}]}
    case = load_case(data)
    veh = vehicle_from_case(case)
    np.testing.assert_allclose([veh.segments[0].E, veh.segments[0].nu, veh.segments[0].rho],
                               [70e9, 0.3, 2700.0], rtol=1e-12)
    assert veh.segments[1].E == pytest.approx(200e9, rel=1e-12)
    assert veh.junctions == ("rigid-bulkhead",)
    assert (veh.aft_end, veh.fwd_end, veh.theory, case.vehicle.k_max) == (
        "free", "free", "sanders", 20)


def test_memo_vehicle_from_booster():
    """Without [vehicle]: cylinder 1 (R1, 2 L1) aft, cylinder 2 (R2, 2 L2), h, E, nu, rho of
    [booster] (memo Fig. 1), memo-bulkhead junction, shear-diaphragm ends (the memo's end
    bulkheads, eqs. 5.3-2/3); [vehicle] without segments overrides ends and theory."""
    case = memo_case()
    b = case.booster
    veh = vehicle_from_case(case)
    expect = [(b.cylinder1.radius, 2 * b.cylinder1.half_length),
              (b.cylinder2.radius, 2 * b.cylinder2.half_length)]
    assert [(s.radius, s.length) for s in veh.segments] == expect
    assert all(s.thickness == b.thickness and s.E == b.E and s.rho == b.rho
               for s in veh.segments)
    assert veh.junctions == ("memo-bulkhead",)
    assert (veh.aft_end, veh.fwd_end) == ("shear-diaphragm", "shear-diaphragm")
    data = _base()
    data["vehicle"] = {"aft_end": "free", "theory": "donnell", "junction": "rigid-bulkhead"}
    veh = vehicle_from_case(load_case(data))
    assert (veh.aft_end, veh.fwd_end, veh.theory, veh.junctions) == (
        "free", "shear-diaphragm", "donnell", ("rigid-bulkhead",))
    data["booster"]["cylinder2"]["radius"] = data["booster"]["cylinder1"]["radius"]
    data["vehicle"] = {"junction": "continuous"}
    assert vehicle_from_case(load_case(data)).junctions == ("continuous",)


def _seg(data, i, **changes):
    data["vehicle"]["segments"][i].update(changes)
    for key, value in list(changes.items()):
        if value is None:
            del data["vehicle"]["segments"][i][key]
    return data


BAD = [  # (change, field, words of the rule); the rule texts are those of vehicle_case.py
    (lambda d: _seg(d, 1, radius_aft="1.4 m"), "vehicle.segments[1].radius_aft", "must equal"),
    (lambda d: _seg(d, 0, radius=0), "vehicle.segments[0].radius", "positive"),
    (lambda d: _seg(d, 0, radius="-1.5 m"), "vehicle.segments[0].radius", "positive"),
    (lambda d: _seg(d, 1, radius_fwd=-1.0), "vehicle.segments[1].radius_fwd", "positive"),
    (lambda d: _seg(d, 0, thickness="0 mm"), "vehicle.segments[0].thickness", "positive"),
    (lambda d: _seg(d, 0, thickness="2 m"), "vehicle.segments[0].thickness", "smaller than"),
    (lambda d: _seg(d, 1, length="-1 m"), "vehicle.segments[1].length", ">= 0"),
    (lambda d: _seg(d, 0, length=0.0), "vehicle.segments[0].length", "must be > 0"),
    (lambda d: _seg(d, 1, length=0.0, radius_fwd="1.5 m"), "vehicle.segments[1].radius_fwd",
     "flat plate"),
    (lambda d: _seg(d, 0, kind="sphere"), "vehicle.segments[0].kind", "must be one of"),
    (lambda d: _seg(d, 1, radius="1.5 m"), "vehicle.segments[1].radius", "two radii"),
    (lambda d: _seg(d, 0, radius_aft="1.5 m"), "vehicle.segments[0].radius_aft", "one radius"),
    (lambda d: _seg(d, 1, radius_fwd=None), "vehicle.segments[1].radius_fwd", "missing"),
    (lambda d: _seg(d, 0, thickness=None), "vehicle.segments[0].thickness", "missing"),
    (lambda d: _seg(d, 0, junction="rigid-bulkhead"), "vehicle.segments[0].junction",
     "first (aft) segment"),
    (lambda d: _seg(d, 1, junction="welded"), "vehicle.segments[1].junction", "must be one of"),
    (lambda d: _seg(d, 1, E="70 m"), "vehicle.segments[1].E", "wrong dimension"),
    (lambda d: _seg(d, 1, nu=0.6), "vehicle.segments[1].nu", "(0, 0.5)"),
    (lambda d: _seg(d, 0, colour="red"), "vehicle.segments[0].colour", "unknown key"),
    (lambda d: d["vehicle"].update(aft_end="pinned"), "vehicle.aft_end", "must be one of"),
    (lambda d: d["vehicle"].update(theory="flugge"), "vehicle.theory", "must be one of"),
    (lambda d: d["vehicle"].update(k_max=201), "vehicle.k_max", "[0, 200]"),
    (lambda d: d["vehicle"].update(k_max=2.5), "vehicle.k_max", "whole number"),
    (lambda d: d["vehicle"].update(rho="-1 kg/m^3"), "vehicle.rho", "positive"),
    (lambda d: d["vehicle"].update(junction="continuous"), "vehicle.junction", "only without"),
    (lambda d: d["vehicle"].update(segments=[]), "vehicle.segments", "at least one"),
]


@pytest.mark.parametrize("change, field, rule", BAD, ids=[b[1] + ": " + b[2] for b in BAD])
def test_bad_vehicle_field_is_one_line_naming_it(change, field, rule):
    data = _with_example_table()
    change(data)
    _assert_one_line_error(data, field, rule)


def _assert_one_line_error(data: dict, field: str, rule: str) -> None:
    with pytest.raises(CaseError) as info:
        load_case(data)
    assert info.value.field == field
    assert rule in info.value.rule
    assert "\n" not in str(info.value) and str(info.value).startswith(field)


@pytest.mark.parametrize("table, field, rule", [
    ({"junction": "continuous"}, "vehicle.junction", "continuous junction needs"),
    ({"E": "70 GPa"}, "vehicle.E", "only with [[vehicle.segments]]"),
], ids=["continuous with R1 != R2", "material without segments"])
def test_bad_memo_vehicle_table(table, field, rule):
    data = _base()
    data["vehicle"] = table
    with pytest.raises(CaseError) as info:
        load_case(data)
    assert info.value.field == field and rule in info.value.rule


def test_bad_vehicle_in_a_file_exits_2(tmp_path, capsys):
    """The CLI prints the CaseError as one line and exits 2 (`run` and `modes`)."""
    path = tmp_path / "bad.toml"
    path.write_text(dump_case(_seg(_with_example_table(), 1, radius_aft="1.4 m")))
    for command in ("run", "modes"):
        assert run_cli([command, str(path), "-o", str(tmp_path / "out")]) == 2
        err = capsys.readouterr().err.strip()
        assert err.startswith("flexbooster: error: vehicle.segments[1].radius_aft = 1.4")
        assert "\n" not in err
    assert not (tmp_path / "out").exists()


# --------------------------------------------------------------------------- memo vehicle


@pytest.mark.parametrize("prestress", [False, True], ids=["unloaded", "prestressed"])
def test_memo_vehicle_frequencies_equal_the_package(prestress):
    """k = 2..4 of analyze_vehicle on the memo case = vehicle_modes on the hand-built
    Vehicle (R1 = 5.05 m, 42 m; R2 = 3.30 m, 18 m; h = 20 mm; 10.5e6 psi, 0.33,
    2.59e-4 lbf s^2/in^4 from memo_case.toml), F0 = 2.8 MN or 0; rel. 1e-9."""
    case = memo_case()
    survey = analyze_vehicle(case, k_max=4, prestress=prestress, f_max=40.0, views=False)
    mat = dict(E=10.5e6 * 6894.757293168361, nu=0.33,
               rho=2.59e-4 * 4.4482216152605 / 0.0254**4)
    veh = Vehicle([Cylinder(5.05, 42.0, 0.020, **mat), Cylinder(3.30, 18.0, 0.020, **mat)],
                  junctions=("memo-bulkhead",), aft_end="shear-diaphragm",
                  fwd_end="shear-diaphragm")
    ref = vehicle_modes(veh, k_min=2, k_max=4, f_max=40.0,
                        prestress_F0=2.8e6 if prestress else 0.0)
    got = survey.modes.k >= 2
    np.testing.assert_array_equal(survey.modes.k[got], ref.k)
    # 1e-9: the generalised eigen-solve of the FE model (hundreds of dofs) has a relative
    # round-off of eps ||K|| / lambda for its low modes, which the BLAS/LAPACK kernels of the CPU
    # move (measured 4e-11 at 38 Hz on an AMD EPYC, the inputs equal to 3 ulp: pint's psi)
    np.testing.assert_allclose(survey.modes.hz[got], ref.hz, rtol=1e-9)
    assert survey.prestressed is prestress and survey.source == "memo"
    assert ("prestressed by the thrust" if prestress else "unloaded") in survey.note


def test_memo_vehicle_donnell_equals_memo_shell_path():
    """Memo vehicle, [vehicle] theory = "donnell", unloaded: at k = 2, 3, 4 the modes below
    30 Hz are the union over both cylinders of the memo path's Donnell shear-diaphragm
    frequencies (flexbooster.memo.shell.natural_frequencies, Leissa SP-288 eqs. 2.20-2.22),
    rel. 1e-5 (FE mesh error of the automatic mesh)."""
    from flexbooster.memo.shell import natural_frequencies
    from flexbooster.model import model_from_case

    data = _base()
    data["vehicle"] = {"theory": "donnell", "k_max": 4}
    case = load_case(data)
    survey = analyze_vehicle(case, prestress=False, f_max=30.0, views=False)
    shell = natural_frequencies(model_from_case(case))
    for k in (2, 3, 4):
        fe = np.sort(survey.modes.hz[survey.modes.k == k])
        ref = np.sort(shell.hz[shell.k == k])
        assert fe.size >= 3 and ref[fe.size] > 30.0  # the memo truncation holds them all
        np.testing.assert_allclose(fe, ref[:fe.size], rtol=1e-5)


# --------------------------------------------------------------------------- command line


@pytest.fixture
def vehicle_case_file(tmp_path):
    path = tmp_path / "vehicle.toml"
    path.write_text(dump_case(_small(_with_example_table(k_max=3))))
    return path


def test_modes_table_fits_80_columns(vehicle_case_file, capsys, monkeypatch):
    monkeypatch.setenv("COLUMNS", "80")
    assert run_cli(["modes", str(vehicle_case_file), "--f-max", "300"]) == 0
    out = capsys.readouterr().out
    assert "prestressed by the thrust F0 = 300000 N" in out
    for k in range(4):
        assert f"k = {k}:" in out
    assert max(len(line) for line in out.splitlines()) <= 80
    assert run_cli(["modes", str(vehicle_case_file), "--no-prestress"]) == 0
    assert "unloaded: no thrust prestress" in capsys.readouterr().out


def test_modes_json_and_options(vehicle_case_file, capsys):
    """--format json: a list `modes` with k, hz, rad_s, order, type, segment; hz = rad_s /
    2 pi (rel. 1e-12); --k-max and --f-max bound the list; the compressive prestress lowers
    every lowest frequency of k >= 2 (loaded < unloaded)."""
    assert run_cli(["modes", str(vehicle_case_file), "--format", "json",
                    "--k-max", "4", "--f-max", "0.2 kHz"]) == 0
    data = json.loads(capsys.readouterr().out)
    rows = data["modes"]
    assert rows and {"k", "hz", "rad_s", "order", "type", "segment"} <= set(rows[0])
    assert {r["k"] for r in rows} <= set(range(5)) and max(r["k"] for r in rows) == 4
    assert all(r["hz"] <= 200.0 for r in rows)
    np.testing.assert_allclose([r["hz"] * 2 * math.pi for r in rows],
                               [r["rad_s"] for r in rows], rtol=1e-12)
    assert data["prestressed"] is True and data["prestress_F0"] == pytest.approx(3e5, rel=1e-12)
    assert run_cli(["modes", str(vehicle_case_file), "--format", "json", "--k-max", "4",
                    "--f-max", "200", "--no-prestress"]) == 0
    free = json.loads(capsys.readouterr().out)
    assert free["prestressed"] is False
    for k in range(2, 5):
        lo = min(r["hz"] for r in rows if r["k"] == k)
        assert lo < min(r["hz"] for r in free["modes"] if r["k"] == k)


@pytest.mark.parametrize("args, field, rule", [
    (["--k-max", "201"], "--k-max", "[0, 200]"),
    (["--f-max", "-3"], "--f-max", "positive"),
    (["--f-max", "3 m"], "--f-max", "wrong dimension"),
], ids=["k-max too large", "f-max negative", "f-max not a frequency"])
def test_modes_bad_options_exit_2(args, field, rule, capsys):
    assert run_cli(["modes", *args]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith(f"flexbooster: error: {field} = ") and rule in err


def test_modes_output_onto_a_file_exits_2(tmp_path, capsys):
    """-o naming a file is refused before any analysis (the --output rule of `run`)."""
    path = tmp_path / "a-file"
    path.write_text("x")
    assert run_cli(["modes", "-o", str(path)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("flexbooster: error: --output = ") and "is a file" in err


def test_modes_output_files(vehicle_case_file, tmp_path, capsys):
    """-o DIR: modes.json (the JSON plus the figure data), vehicle-modes.csv (one row per
    mode), the meridian and unrolled figures (SVG and PNG)."""
    out = tmp_path / "modes"
    assert run_cli(["modes", str(vehicle_case_file), "-o", str(out), "-q"]) == 0
    assert capsys.readouterr().out == ""
    names = {p.name for p in out.iterdir()}
    assert {"modes.json", "vehicle-modes.csv", "vehicle-mode-shapes.svg",
            "vehicle-mode-shapes.png", "vehicle-unrolled.svg", "vehicle-unrolled.png"} == names
    data = json.loads((out / "modes.json").read_text())
    with (out / "vehicle-modes.csv").open() as handle:
        rows = list(csv.DictReader(handle))
    assert len(rows) == len(data["modes"]) > 0
    assert [int(r["k"]) for r in rows] == [m["k"] for m in data["modes"]]
    fig = data["figures"]
    assert len(fig["x_deformed"]) == len(fig["index"]) and len(fig["w"]) == len(
        fig["unrolled_index"])


def test_modes_of_the_memo_case_vehicle(capsys):
    """No [vehicle]: `modes --memo` analyses the memo vehicle built from [booster]."""
    assert run_cli(["modes", "--memo", "--k-max", "3", "--format", "json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["source"] == "memo"
    assert data["vehicle"]["junctions"] == ["memo-bulkhead"]


# --------------------------------------------------------------------------- run


def test_run_with_vehicle_table(vehicle_case_file, tmp_path, capsys):
    """run with [vehicle] (--no-figures: fast): results.json key vehicle_modes,
    vehicle-modes.csv, the summary table, the report section with the table.  Without the
    vehicle's parametric regions (--no-vehicle: their damped search on this table took 12 s;
    they are tested through analyze in test_vehicle_pipeline.py)."""
    out = tmp_path / "run"
    assert run_cli(["run", str(vehicle_case_file), "-o", str(out), "--no-figures",
                    "--no-vehicle", "--full"]) == 0  # --full: every table
    text = capsys.readouterr().out
    assert "Vehicle modes (shell of revolution)" in text and "prestressed by the thrust" in text
    data = json.loads((out / "results.json").read_text())
    vm = data["vehicle_modes"]
    assert vm["source"] == "vehicle" and max(m["k"] for m in vm["modes"]) <= 3
    assert data["case"]["vehicle"]["segments"][1]["radius_fwd"] == 1.0
    assert (out / "vehicle-modes.csv").exists()
    report = (out / "report.html").read_text()
    assert 'id="vehicle-modes"' in report and 'href="#vehicle-modes"' in report
    assert "vehicle figures were not drawn" in report
    assert data["vehicle_modes"]["figures"] is None  # --no-figures: no figure data either


def test_report_embeds_the_vehicle_figures(vehicle_case_file):
    """With figures: make_figures adds vehicle-mode-shapes and vehicle-unrolled (drawn from
    the stored views) and the report's vehicle section embeds both."""
    from dataclasses import replace

    from flexbooster.present.figure_files import render_figure
    from flexbooster.present.report import MEMO_SECTIONS, SECTIONS, render_report
    from flexbooster.present.vehicle import vehicle_figures

    case = load_case(vehicle_case_file)
    # the report's other sections need an analysis, not the vehicle's regions (their damped
    # search of this table is the costly stage): vehicle=False
    results = analyze(case, beam_action=False, figures=False, vehicle=False)
    survey = analyze_vehicle(case, k_max=2, views=True)
    results = replace(results, vehicle=survey)
    svgs = {name: render_figure(fig)[0] for name, fig in vehicle_figures(survey).items()}
    assert set(svgs) == {"vehicle-mode-shapes", "vehicle-unrolled"}
    report = render_report(results, svgs)
    assert 'id="fig-vehicle-mode-shapes"' in report and 'id="fig-vehicle-unrolled"' in report
    assert report.index('id="vehicle-modes"') < report.index('id="verification"')
    root = ET.fromstring(report.split("\n", 1)[1])  # strict XML (after the DOCTYPE line)
    ids = [el.get("id") for el in root.iter() if el.get("id") is not None]
    assert len(ids) == len(set(ids))  # the vehicle figures' ids are prefixed, no clash
    sections = [el.get("id") for el in root.iter() if el.tag.endswith("section")]
    # a [[vehicle.segments]] case: the memo's sections left out, the vehicle's added
    expected = [sid for sid, _ in SECTIONS if sid not in MEMO_SECTIONS]
    assert sections.count("vehicle-modes") == 1 and len(sections) == len(expected) + 1
    assert set(sections) == set(expected) | {"vehicle-modes"}


@pytest.mark.slow
def test_memo_case_results_unchanged():
    """Without [vehicle]: no vehicle stage, no vehicle_modes key, no case.vehicle key (the
    top-level keys of the memo case's results.json)."""
    data = _small(_base())
    seen = []
    results = analyze(load_case(data), figures=False, progress=seen.append)
    assert results.vehicle is None and "vehicle modes" not in seen
    out = results.to_dict()
    assert "vehicle_modes" not in out and "vehicle" not in out["case"]
    assert set(out) == {"schema_version", "flexbooster_version", "units", "case",
                        "mass_properties", "frequencies", "dimensionless", "beam_modes",
                        "pitch", "shell_frequencies", "beam_action", "stability",
                        "warnings", "figures", "vehicle_regions",  # every case
                        "danger",
                        "forced_response", "verdict"}


def test_thick_shell_warning_reaches_summary_and_results(tmp_path, capsys):
    """h/R = 0.1 > 1/20 on segment 1: a warning (code thick-shell, field
    vehicle.segments[1]) in results.json and in the summary; the run goes on."""
    data = _small(_with_example_table(k_max=2))
    _seg(data, 1, thickness="0.1 m")
    path = tmp_path / "thick.toml"
    path.write_text(dump_case(data))
    assert run_cli(["run", str(path), "-o", str(tmp_path / "out"), "--no-figures"]) == 0
    text = capsys.readouterr().out
    assert "thick-shell" in text and "vehicle.segments[1]" in text
    warnings = json.loads((tmp_path / "out" / "results.json").read_text())["warnings"]
    assert {"code": "thick-shell", "field": "vehicle.segments[1]"}.items() <= next(
        w for w in warnings if w["code"] == "thick-shell").items()


def test_flat_plate_leaves_out_the_prestress():
    """A flat plate (cone of length 0) cannot carry the thrust as a membrane: the modes are
    unloaded, and the survey says so (no error)."""
    data = _with_example_table(k_max=2)
    data["vehicle"]["segments"].append({"kind": "cone", "radius_aft": "1.0 m",
                                        "radius_fwd": "0.5 m", "length": 0,
                                        "thickness": "8 mm"})
    survey = analyze_vehicle(load_case(data), views=False)
    assert survey.prestressed is False and "flat plate" in survey.note


# ------------------------------------------------ masses, tanks, pressure, stiffeners

#: A two-segment vehicle with every physics field (masses, tanks, pressure, stiffeners), in units.
PHYSICS_TABLE = """
[vehicle]
E = "70 GPa"
nu = 0.3
rho = "2700 kg/m^3"
[[vehicle.segments]]
kind = "cylinder"
radius = "1.5 m"
length = "6 m"
thickness = "4 mm"
nonstructural_mass = "0.2 lb/ft^2"
pressure = "30 psi"
rings = { spacing = "50 cm", area = "4 cm^2", inertia = "2 cm^4", eccentricity = "-2 cm" }
[[vehicle.segments]]
kind = "cylinder"
radius = "1.5 m"
length = "4 m"
thickness = "4 mm"
junction = "rigid-bulkhead"
stringers = { spacing = "0.2 m", area = 1e-4, inertia = 1e-9, eccentricity = 0.01 }
[[vehicle.masses]]
station = 0.0
mass = "2 t"
transverse_inertia = "800 kg*m^2"
offset = "-1 m"
name = "engine"
[[vehicle.masses]]
station = "10 m"
mass = 500
[[vehicle.tanks]]
aft = 0.0
fwd = "6 m"
fill = 0.6
density = "1140 kg/m^3"
name = "lox"
"""


def _physics_case(**changes) -> dict:
    data = _base()
    del data["booster"]  # one vehicle per case: the segments
    data["thrust"]["F0"] = "0.3 MN"
    data.update(tomllib.loads(PHYSICS_TABLE))
    data["vehicle"].update(changes)
    return data


def test_physics_fields_units_and_vehicle():
    """Every physics field reaches the core Vehicle in SI (pint conversions: 0.2 lb/ft^2 =
    0.976484 kg/m^2, 30 psi = 206842.7 Pa, 4 cm^2 = 4e-4 m^2, 2 cm^4 = 2e-8 m^4, 2 t = 2000 kg;
    rel. 1e-6); defaults: inertia and eccentricity 0, names "mass 1"."""
    veh = vehicle_from_case(load_case(_physics_case()))
    s0, s1 = veh.segments
    assert s0.nonstructural_mass == pytest.approx(0.2 * 0.45359237 / 0.3048**2, rel=1e-6)
    assert s0.pressure == pytest.approx(30 * 6894.757293168361, rel=1e-6)
    assert (s0.rings.spacing, s0.rings.area, s0.rings.inertia) == pytest.approx(
        (0.5, 4e-4, 2e-8), rel=1e-9)
    assert s0.rings.eccentricity == pytest.approx(-0.02, rel=1e-9) and s0.stringers is None
    assert s1.stringers.eccentricity == 0.01 and s1.rings is None and s1.pressure == 0.0
    engine, payload = veh.masses
    assert (engine.station, engine.offset, engine.name) == (0.0, -1.0, "engine")
    assert (engine.mass, engine.transverse_inertia) == pytest.approx((2000.0, 800.0), rel=1e-9)
    assert (payload.station, payload.mass, payload.transverse_inertia, payload.offset,
            payload.name) == (10.0, 500.0, 0.0, 0.0, "mass 1")
    (tank,) = veh.tanks
    assert (tank.aft, tank.fwd, tank.fill, tank.name) == (0.0, 6.0, 0.6, "lox")
    assert tank.density == pytest.approx(1140.0, rel=1e-12)


PHYSICS_BAD = [  # (table changes, field, words of the rule)
    (lambda d: d["vehicle"]["segments"][0].update(nonstructural_mass=-1.0),
     "vehicle.segments[0].nonstructural_mass", ">= 0"),
    (lambda d: d["vehicle"]["segments"][0].update(pressure="3 m"),
     "vehicle.segments[0].pressure", "wrong dimension"),
    (lambda d: d["vehicle"]["segments"][0]["rings"].update(spacing=0.0),
     "vehicle.segments[0].rings.spacing", "positive"),
    (lambda d: d["vehicle"]["segments"][0]["rings"].update(area="4 cm"),
     "vehicle.segments[0].rings.area", "wrong dimension"),
    (lambda d: d["vehicle"]["segments"][0]["rings"].update(inertia=-1e-9),
     "vehicle.segments[0].rings.inertia", ">= 0"),
    (lambda d: d["vehicle"]["segments"][1]["stringers"].update(colour="red"),
     "vehicle.segments[1].stringers.colour", "unknown key"),
    (lambda d: d["vehicle"]["masses"][0].update(mass=0), "vehicle.masses[0].mass", "positive"),
    (lambda d: d["vehicle"]["masses"][1].update(station=-1.0),
     "vehicle.masses[1].station", ">= 0"),
    (lambda d: d["vehicle"]["masses"][0].update(transverse_inertia="3 kg"),
     "vehicle.masses[0].transverse_inertia", "wrong dimension"),
    (lambda d: d["vehicle"]["tanks"][0].update(fill=1.5), "vehicle.tanks[0].fill", "[0, 1]"),
    (lambda d: d["vehicle"]["tanks"][0].update(density=0), "vehicle.tanks[0].density",
     "positive"),
    (lambda d: d["vehicle"]["tanks"][0].pop("fwd"), "vehicle.tanks[0].fwd", "missing"),
]


@pytest.mark.parametrize("change, field, rule", PHYSICS_BAD,
                         ids=[b[1] + ": " + b[2] for b in PHYSICS_BAD])
def test_bad_physics_field_is_one_line_naming_it(change, field, rule):
    """Each invalid physics field: one CaseError line naming the field and the rule."""
    data = _physics_case()
    change(data)
    _assert_one_line_error(data, field, rule)


@pytest.mark.parametrize("change, field, rule", [
    (lambda d: d["vehicle"]["tanks"][0].update(aft="1 m"), "vehicle.tanks[0].aft",
     "segment boundary"),
    (lambda d: d["vehicle"]["tanks"][0].update(aft="6 m", fwd="6 m"), "vehicle.tanks[0].fwd",
     "forward of aft"),
    (lambda d: d["vehicle"]["masses"][1].update(station="11 m"), "vehicle.masses[1].station",
     "within the vehicle"),
])
def test_stations_that_do_not_fit_the_segments(change, field, rule):
    """Stations checked against the segments when the vehicle is built: CaseError naming the
    case's field (vehicle.tanks[0].aft, ...)."""
    data = _physics_case()
    change(data)
    with pytest.raises(CaseError) as info:
        vehicle_from_case(load_case(data))
    assert info.value.field == field and rule in info.value.rule


def test_masses_need_segments():
    """[[vehicle.masses]] on the memo vehicle (no segments): CaseError naming vehicle.masses."""
    data = _base()
    data["vehicle"] = {"masses": [{"station": 1.0, "mass": 10.0}]}
    with pytest.raises(CaseError) as info:
        load_case(data)
    assert info.value.field == "vehicle.masses" and "only with" in info.value.rule


def test_modes_json_has_mass_properties_and_slosh(tmp_path, capsys):
    """`modes --format json` of the physics case: "mass_properties" equals
    shell_of_revolution.mass_properties of the case's vehicle (exact, same computation) with
    its contributions; "slosh" lists the LOX tank with Abramson's frequency at a = F0 / m
    (omega^2 = (a xi_1 / R) tanh(xi_1 h / R), h = 3.6 m, xi_1 = 1.8412; 0.1 %)."""
    from flexbooster.shell_of_revolution import mass_properties

    path = tmp_path / "physics.toml"
    data = _small(_base())
    del data["booster"]  # one vehicle per case: the segments
    data["thrust"]["F0"] = "0.3 MN"
    table = PHYSICS_TABLE.replace("[vehicle]\n", "[vehicle]\nk_max = 2\n")
    path.write_text(dump_case(data) + table)
    assert run_cli(["modes", str(path), "--format", "json", "--f-max", "60"]) == 0
    data = json.loads(capsys.readouterr().out)
    props = mass_properties(vehicle_from_case(load_case(path)))
    assert data["mass_properties"] == json.loads(json.dumps(props.to_dict()))
    assert [c["kind"] for c in data["mass_properties"]["contributions"]] == [
        "shell", "nonstructural", "stiffeners", "lumped", "lumped", "tank"]
    (slosh,) = data["slosh"]
    a = 3.0e5 / props.mass_kg
    xi = 1.8412
    hz = math.sqrt(a * xi / 1.5 * math.tanh(xi * 3.6 / 1.5)) / (2 * math.pi)
    assert slosh["tank"] == "lox" and slosh["hz"] == pytest.approx(hz, rel=1e-3)
    assert slosh["mass_kg"] > 0.0
