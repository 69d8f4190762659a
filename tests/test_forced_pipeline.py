"""The forced response wired into the case, the pipeline and the outputs.

The numbers themselves are checked in tests/test_forced_response.py (closed forms, direct
integration); here the evidence is that the case's fields reach the solver unchanged and the
outputs hold the solver's numbers: each stage value against a direct call of
:func:`flexbooster.dynamics.forced_response` with arguments written out by hand from the
case (exact equality: the same computation), the linearity of the response in gamma (an
independent second computation, 1e-12 relative), the input probes (exit 2, one line naming
the field) and the figures' data against the stored results (exact).
"""

from __future__ import annotations

import csv
import json
import math
import re
import types
from pathlib import Path

import numpy as np
import pytest
from rich.console import Console

import flexbooster
from flexbooster.analysis import (
    FORCED_STAGE,
    analyze,
    analyze_forced_response,
    forced_settings,
)
from flexbooster.case import load_case, memo_case_text
from flexbooster.cli import main
from flexbooster.cost import estimate_vehicle_cost
from flexbooster.dynamics import ThrustSpectrum, basis_sizes, forced_response
from flexbooster.dynamics.forced import STANDARD_GRAVITY
from flexbooster.errors import CaseError
from flexbooster.model import forced_stations, vehicle_from_case
from flexbooster.present.forced import FORCED_CSV
from flexbooster.shell_of_revolution import Cone, Cylinder, Vehicle

EXAMPLE = Path(__file__).parents[1] / "examples" / "ares-i-like.toml"
ALU = {"E": 70e9, "nu": 0.3, "rho": 2700.0}
#: README.md's [vehicle] example, written out by hand (not through the case).
README_VEHICLE = Vehicle(segments=(Cylinder(1.5, 6.0, 0.016, **ALU),
                                   Cone(1.5, 1.0, 1.0, 0.016, **ALU)))
README_TABLE = """
[vehicle]
E = "70 GPa"
nu = 0.3
rho = "2700 kg/m^3"
[[vehicle.segments]]
kind = "cylinder"
radius = "1.5 m"
length = "6 m"
thickness = "16 mm"
[[vehicle.segments]]
kind = "cone"
radius_aft = "1.5 m"
radius_fwd = "1.0 m"
length = "1 m"
thickness = "16 mm"
"""
STATIONS = """
[[output.stations]]
name = "payload"
station = "6.5 m"
[[output.stations]]
name = "mid"
station = "300 cm"
"""


def _case_text(thrust: str = "", damping: str = "pitch_ratio = 0.02", extra: str = "") -> str:
    """The memo case with README's [vehicle], thrust lines inserted after [thrust], a
    [damping] table and extra tables (TOML text: arrays of tables need no writer)."""
    text = memo_case_text().replace("[thrust]\n", f"[thrust]\n{thrust}\n", 1)
    # one vehicle per case: README's [vehicle] segments replace the memo's [booster]
    text = text[:text.index("[booster]")] + text[text.index("[thrust]"):]
    text = re.sub(r"^\[damping\][^\[]*", "", text, flags=re.M)  # the test's own [damping]
    for key in ("M1", "N1", "M2", "N2", "N"):  # small memo truncation: the stages run fast
        text = re.sub(rf"^{key} = \d+", f"{key} = 3", text, flags=re.M)
    return text + f"\n[damping]\n{damping}\n" + README_TABLE + extra


def _load(tmp_path, text: str, name: str = "case.toml"):
    path = tmp_path / name
    path.write_text(text)
    return load_case(path), path


HAND = {"F0": 2.8e6, "damping_ratio": 0.01, "gimbal_gain": 0.5,
        "stations": [("payload", 6.5), ("mid", 3.0)]}


# ------------------------------------------------------------------------------ case fields
def test_case_fields_in_si(tmp_path):
    """Source: the unit definitions (1 deg = pi/180 rad, 1 Hz = 2 pi rad/s, 100 cm = 1 m);
    exact to 1e-15 relative (pint's conversion factors)."""
    case, _ = _load(tmp_path, _case_text(
        'misalignment = "0.25 deg"', extra=STATIONS + '[[thrust.spectrum]]\nfrequency = "13 Hz"'
        '\namplitude = 0.01\n[[thrust.spectrum]]\nfrequency = "90 rad/s"\namplitude = '
        '"0.5 percent"\n'))
    t = case.thrust
    assert t.misalignment == pytest.approx(0.25 * math.pi / 180.0, rel=1e-15)
    assert t.spectrum[0].frequency == pytest.approx(26.0 * math.pi, rel=1e-15)
    assert t.spectrum[1].frequency == 90.0 and t.spectrum[1].amplitude == pytest.approx(0.005)
    assert [(s.name, s.station) for s in case.output.stations] == [("payload", 6.5),
                                                                   ("mid", 3.0)]


def test_defaults_leave_results_case_unchanged(memo_case_dict):
    """Without the fields: misalignment 0, no spectrum, no stations; ``output`` stays out of
    results.json's case as before (source: Case.to_si_dict's rule for the default table)."""
    case = flexbooster.load_case(memo_case_dict)
    assert case.thrust.misalignment == 0.0 and case.thrust.spectrum is None
    assert case.output.stations == () and "output" not in case.to_si_dict()


PROBES = [
    ('misalignment = "90 deg"', "", "thrust.misalignment"),
    ("misalignment = -1.6", "", "thrust.misalignment"),
    ('misalignment = "1 m"', "", "thrust.misalignment"),
    ("", '[[thrust.spectrum]]\nfrequency = "13 Hz"\namplitude = 1.0',
     "thrust.spectrum[0].amplitude"),
    ("", "[[thrust.spectrum]]\nfrequency = -3.0\namplitude = 0.01",
     "thrust.spectrum[0].frequency"),
    ("", '[[thrust.spectrum]]\nfrequency = "13 Hz"\namplitude = 0.01\n[[thrust.spectrum]]\n'
     'frequency = "12 Hz"\namplitude = 0.01', "thrust.spectrum[1].frequency"),
    ("", '[[thrust.spectrum]]\nfreq = "13 Hz"\namplitude = 0.01', "thrust.spectrum[0].freq"),
    ("", '[[output.stations]]\nname = "p"\nstation = "7.5 m"', "output.stations[0].station"),
    ("", '[[output.stations]]\nname = "p"\nstation = "-1 m"', "output.stations[0].station"),
    ("", '[[output.stations]]\nname = "junction-1"\nstation = "2 m"',
     "output.stations[0].name"),
    ("", '[[output.stations]]\nname = " "\nstation = "2 m"', "output.stations[0].name"),
    ("", '[[output.stations]]\nname = "p"\nstation = "2 m"\n[[output.stations]]\nname = "p"\n'
     'station = "3 m"', "output.stations[1].name"),
]


@pytest.mark.parametrize(("thrust", "extra", "field"), PROBES,
                         ids=[p[2] + f"-{i}" for i, p in enumerate(PROBES)])
def test_bad_fields_exit_2_one_line(tmp_path, capsys, thrust, extra, field):
    """Source: the rules of README's table (|delta| < pi/2; 0 <= a < 1; frequencies > 0 and
    increasing; a station on the 7 m vehicle, its name its own): exit 2, one line naming the
    field, no traceback."""
    path = tmp_path / "bad.toml"
    path.write_text(_case_text(thrust, extra="\n" + extra + "\n"))
    with pytest.raises(SystemExit) as info:
        main(["run", str(path), "-o", str(tmp_path / "out"), "-q"])
    err = capsys.readouterr().err.strip()
    assert info.value.code == 2
    assert len(err.splitlines()) == 1 and field in err and "Traceback" not in err


# ------------------------------------------------------------------------------ the stage
@pytest.fixture(scope="module")
def readme_loads(tmp_path_factory):
    """The stage on README's vehicle with a misalignment of 0.01 rad (k = 0 and 1 forced)."""
    tmp = tmp_path_factory.mktemp("forced")
    case, _ = _load(tmp, _case_text("misalignment = 0.01", extra=STATIONS))
    return case, analyze_forced_response(case)


def test_stage_equals_direct_library_call(readme_loads):
    """Source: forced_response on README's vehicle written out by hand (F0 = 2.8 MN, gamma =
    0.05, 400 points of 5..2000 rad/s, zeta = 0.01 = vehicle.damping_ratio's default, zeta_psi
    = 0.02, K = 0.5, delta = 0.01 rad, the two stations); exact equality of every curve and
    peak: the case reaches the solver unchanged."""
    _, loads = readme_loads
    direct = forced_response(README_VEHICLE, amplitude=0.05, Omega=np.linspace(5.0, 2000.0, 400),
                             misalignment=0.01, pitch_damping_ratio=0.02, **HAND)
    r = loads.response
    for q in ("displacement", "acceleration", "axial_force", "shear_force", "bending_moment"):
        assert np.array_equal(getattr(r, q), getattr(direct, q)), q
    assert [p.to_dict() for p in r.peaks] == [p.to_dict() for p in direct.peaks]
    assert [s.name for s in r.stations] == ["aft-edge", "mid", "junction-1", "payload",
                                           "forward-edge"]
    assert loads.n_modes == tuple(m.omega_modes.size - m.n_rigid for m in direct.models)


def test_csv_columns_units_and_values(readme_loads):
    """Source: the direct call's arrays: |X| in m, m/s^2 / 9.80665 (g, exact by definition), N,
    N m; Omega / (2 pi) in Hz; long format, one row per (k, station, Omega); exact."""
    _, loads = readme_loads
    r = loads.response
    cols = loads.csv_columns()
    assert list(cols)[:8] == ["Omega_hz", "station", "station_m", "k", "displacement_m",
                              "acceleration_g", "axial_force_N", "bending_moment_Nm"]
    n = r.omega.size
    assert len(cols["k"]) == 2 * len(r.stations) * n
    i = 1 * len(r.stations) * n + 3 * n + 17  # k = 1, station 3 (payload), Omega index 17
    assert (cols["k"][i], cols["station"][i], cols["station_m"][i]) == (1, "payload", 6.5)
    assert cols["Omega_hz"][i] == r.omega[17] / (2.0 * np.pi)
    assert cols["acceleration_g"][i] == np.abs(r.acceleration[1, 3])[17] / STANDARD_GRAVITY
    assert cols["bending_moment_Nm"][i] == np.abs(r.bending_moment[1, 3])[17]
    assert cols["axial_force_N"][i] == 0.0  # k = 1 carries no axial force
    j = 2 * n + 5  # k = 0, junction-1
    assert cols["axial_force_N"][j] == np.abs(r.axial_force[0, 2])[5]


def test_results_json_peaks(readme_loads):
    """Source: the ForcedPeak of the solver for each station and quantity (value and Omega,
    exact); per 1 % = value x 0.01 / gamma (to the round-off of three products in another
    order, 1e-15); ranked by decreasing acceleration."""
    _, loads = readme_loads
    d = json.loads(json.dumps(loads.to_dict()))
    r = loads.response
    row = next(p for p in d["peaks"] if p["k"] == 0 and p["station"] == "payload")
    acc = r.peak(0, "payload", "acceleration")
    assert row["acceleration_g"] == acc.value / STANDARD_GRAVITY
    assert row["Omega_acceleration"] == acc.omega
    assert row["acceleration_g_per_percent"] == pytest.approx(
        acc.value / STANDARD_GRAVITY * 0.01 / 0.05, rel=1e-15, abs=0.0)
    assert row["axial_force_N"] == r.peak(0, "payload", "axial_force").value
    assert d["basis"]["static_correction"] is True and d["basis"]["n_modes"] == list(
        loads.n_modes)
    ranked = d["ranked"]
    assert [p["acceleration_g"] for p in ranked] == sorted(
        (p["acceleration_g"] for p in ranked), reverse=True)
    assert len(ranked) == 2 * len(r.stations)  # k = 0 and 1 both forced


def test_response_is_linear_in_gamma(tmp_path, readme_loads):
    """Source: linearity of the steady response (M X'' + C X' + K X = gamma F0 ...): a second,
    independent run at gamma = 0.01 equals the gamma = 0.05 run x 0.2 (per_percent) to 1e-12
    relative of the largest value; this is what the summary's "per 1 %" column reports."""
    _, loads = readme_loads
    case, _ = _load(tmp_path, _case_text("misalignment = 0.01", extra=STATIONS).replace(
        "\ngamma = 0.05", "\ngamma = 0.01", 1))
    small = analyze_forced_response(case)
    assert loads.per_percent == pytest.approx(0.2, rel=1e-15)
    for a, b in zip(loads.ranked_peaks(), small.ranked_peaks(), strict=True):
        assert b.acceleration_g == pytest.approx(a.acceleration_g * 0.2, rel=1e-12)
        assert b.bending_moment_Nm == pytest.approx(a.bending_moment_Nm * 0.2, rel=1e-12,
                                                    abs=1e-12 * max(1.0, a.bending_moment_Nm))


def test_convergence_of_the_basis_is_reported(readme_loads):
    """Source: the static correction makes the truncation error of the modes above 4 Omega_max
    small: halving the basis changes no station peak by more than 1 % of the largest (the
    reported change, computed by a second solve)."""
    _, loads = readme_loads
    assert all(c is not None and c[0] >= 1 and 0.0 <= c[1] < 1e-2 for c in loads.convergence)


def test_spectrum_lines(tmp_path):
    """Source: forced_response with the ThrustSpectrum written out by hand (lines 13 Hz = 81.7
    rad/s at 1 % and 90 rad/s at 0.5 %): the same peaks (the sum over the lines), exact."""
    case, _ = _load(tmp_path, _case_text(extra='\n[[thrust.spectrum]]\nfrequency = "13 Hz"'
                                         '\namplitude = 0.01\n[[thrust.spectrum]]\nfrequency'
                                         ' = "90 rad/s"\namplitude = 0.005\n'))
    loads = analyze_forced_response(case)
    spec = ThrustSpectrum(frequency=np.array([26.0 * math.pi, 90.0]),
                          amplitude=np.array([0.01, 0.005]))
    direct = forced_response(README_VEHICLE, amplitude=spec, pitch_damping_ratio=0.02,
                             **dict(HAND, stations=()))
    assert loads.response.combination == "spectrum" and loads.per_percent is None
    assert np.array_equal(loads.response.omega, direct.omega)
    assert [p.to_dict() for p in loads.response.peaks] == [p.to_dict() for p in direct.peaks]


@pytest.mark.parametrize(("damping", "field"),
                         [("pitch_ratio = 0.0", "damping.pitch_ratio")],
                         ids=["undamped-pitch"])
def test_undamped_resonance_is_a_warning(tmp_path, damping, field):
    """README's vehicle with the gimbal (K = 0.5), a misalignment and no pitch damping: its
    rigid pitch resonates undamped inside 5..2000 rad/s (source: the k = 1 pole with zero real
    part, tests/test_forced_response.py) -> the stage is a one-line CaseError naming the field,
    and in the pipeline a ``forced-response-skipped`` warning; never a crash."""
    from flexbooster.analysis import _forced_stage  # noqa: PLC2701 - the stage's own wrapper

    case, _ = _load(tmp_path, _case_text("misalignment = 0.01", damping=damping))
    with pytest.raises(CaseError) as info:
        analyze_forced_response(case)
    assert info.value.field == field and "\n" not in str(info.value)
    found, warnings = _forced_stage(case)
    assert found is None and [(w.code, w.field) for w in warnings] == [
        ("forced-response-skipped", field)]


def test_undamped_elastic_mode_names_the_modal_damping(tmp_path):
    """vehicle.damping_ratio = 0 and a misalignment: the first bending mode of README's vehicle
    (1410 rad/s, inside 5..2000 rad/s) is undamped -> a CaseError naming vehicle.damping_ratio
    (source: the k = 1 pole on the imaginary axis)."""
    text = _case_text("misalignment = 0.01").replace(
        'rho = "2700 kg/m^3"\n[[', 'rho = "2700 kg/m^3"\ndamping_ratio = 0.0\n[[', 1)
    case, _ = _load(tmp_path, text)
    with pytest.raises(CaseError) as info:
        analyze_forced_response(case)
    assert info.value.field == "vehicle.damping_ratio"


def test_lumped_mass_stations_are_named():
    """Each lumped mass of the vehicle is a station (its name, else "mass-i"), before the
    user's; a name a user station has is made distinct (source: the rule of forced_stations).
    A stand-in vehicle carries the masses (the case file's [[vehicle.masses]] is not merged)."""
    case = flexbooster.memo_case()
    mass = types.SimpleNamespace
    stand_in = types.SimpleNamespace(masses=(mass(name="", station=3.0),
                                             mass(name="payload", station=50.0)))
    case = case.model_copy(update={"output": case.output.model_copy(update={
        "stations": (type(case.output).model_fields["stations"].annotation.__args__[0](
            name="payload", station=10.0),)})})
    stations, masses = forced_stations(case, stand_in)
    assert stations == (("mass-1", 3.0), ("payload (mass 2)", 50.0), ("payload", 10.0))
    assert masses == ("mass-1", "payload (mass 2)")


# ------------------------------------------------------------------------------ cost, pipeline
def test_cost_counts_the_forced_stage(tmp_path):
    """The estimate's "vehicle forced response" part is the law of cost.py on the bases the
    run then takes (counted up front by inertia: equal to the run's models), larger when the
    lateral harmonic is forced too (its peak search); none when the stage is not run. Source:
    the calibration in cost.py; the counted basis against the run's, exact integers."""
    case0, _ = _load(tmp_path, _case_text())
    case1, _ = _load(tmp_path, _case_text("misalignment = 0.01"), "c1.toml")
    p0 = estimate_vehicle_cost(case0, forced=True).parts["vehicle forced response"]
    p1 = estimate_vehicle_cost(case1, forced=True).parts["vehicle forced response"]
    assert 0.0 < p0 < p1
    assert "vehicle forced response" not in estimate_vehicle_cost(case0).parts
    vehicle = vehicle_from_case(case1)
    settings = forced_settings(case1)
    stations = forced_stations(case1, vehicle)[0]
    run = forced_response(vehicle, stations=stations, **settings)
    assert basis_sizes(vehicle, F0=case1.F0, omega_max=float(settings["Omega"].max()),
                       stations=stations) == tuple(m.omega_modes.size for m in run.models)


def test_cost_bounds_the_forced_stage_of_a_large_mesh_without_counting(tmp_path, monkeypatch):
    """Past cost.FORCED_COUNT_MAX_DOFS the estimate does not assemble the dense matrices to
    count the basis (a case refused for its size must not pay for them): the part is the
    DOFs-cubed bound of cost.forced_seconds (source: its calibration), and no count is made
    (a counter on basis_sizes). The README vehicle's cylinder repeated until its mesh passes
    the limit."""
    from flexbooster import cost, dynamics
    from flexbooster.shell_of_revolution import mesh_vehicle

    calls = []
    monkeypatch.setattr(dynamics, "basis_sizes", lambda *a, **k: calls.append(1) or (6, 6))
    text = _case_text()
    cylinder = ('[[vehicle.segments]]\nkind = "cylinder"\nradius = "1.5 m"\nlength = "6 m"\n'
                'thickness = "16 mm"\n')
    assert cylinder in text
    for copies in range(2, 40):
        case, _ = _load(tmp_path, text.replace(cylinder, cylinder * copies), f"c{copies}.toml")
        vehicle = vehicle_from_case(case)
        if mesh_vehicle(vehicle).n_full > cost.FORCED_COUNT_MAX_DOFS:
            break
    assert mesh_vehicle(vehicle).n_full > cost.FORCED_COUNT_MAX_DOFS  # the premise
    part = cost.forced_run_seconds(case, vehicle)  # the estimate's "vehicle forced response"
    assert part == cost.forced_seconds(vehicle, case.thrust.n_omega)
    assert not calls


def test_no_vehicle_skips_the_stage(small_memo_case_file):
    """``analyze(vehicle=False)`` (``--no-vehicle``) neither announces nor computes it."""
    seen = []
    res = analyze(load_case(small_memo_case_file), progress=seen.append, vehicle=False,
                  figures=False)
    assert FORCED_STAGE not in seen and res.forced_response is None
    assert res.to_dict()["forced_response"] is None


@pytest.mark.slow
def test_summary_report_and_figures_read_the_stored_data(memo_case_dict, tmp_path):
    """The summary and report sections show the stored peaks; the figures draw the stored
    curves (compute -> data -> plot): the acceleration lines equal |a| / g at the stations, the
    envelope line |N| at the worst Omega (exact)."""
    from flexbooster.present.outputs import make_figures
    from flexbooster.present.report import render_report
    from flexbooster.present.summary import print_summary

    memo_case_dict["truncation"].update(M1=3, N1=3, M2=3, N2=3, N=3, S=2, R=2)
    memo_case_dict["thrust"]["n_omega"] = 40
    res = analyze(flexbooster.load_case(memo_case_dict))
    loads = res.forced_response
    console = Console(record=True, width=200)
    print_summary(res, console)
    text = console.export_text()
    assert "Forced response to the thrust oscillation" in text
    assert "modes + static correction" in text
    html = render_report(res)
    assert 'id="forced-response"' in html and "forced-response.csv" in html
    figs = make_figures(res, names=("forced-acceleration", "forced-envelopes"))
    ax = figs["forced-acceleration"].axes[0]
    assert ax.get_yscale() == "log"
    curves = [line for line in ax.lines if line.get_linestyle() == "-"]
    r = loads.response
    assert len(curves) == len(r.stations)  # k = 0 only: no misalignment
    for line, js in zip(curves, range(len(r.stations)), strict=True):
        y = np.abs(r.acceleration[0, js]) / STANDARD_GRAVITY
        assert np.array_equal(np.asarray(line.get_ydata()), np.where(y > 0.0, y, np.nan),
                              equal_nan=True)
    env = next(e for e in r.envelopes if e.quantity == "axial_force")
    line = figs["forced-envelopes"].axes[0].lines[0]
    assert np.array_equal(line.get_ydata(), np.abs(env.at_worst))


# ------------------------------------------------------------------------------ the example
@pytest.mark.slow
def test_example_crew_module_acceleration_per_percent(tmp_path):
    """``flexbooster run examples/ares-i-like.toml``: the crew-module acceleration per 1 % of
    thrust oscillation in results.json is finite, positive and equals the library call's peak
    (forced_response of the case's vehicle at gamma = 0.01 over 12-14 Hz, the example's
    damping, gimbal and misalignment, written out by hand; exact), and forced-response.csv is in
    the manifest with the same curve (exact: CSV floats are repr)."""
    out = tmp_path / "out"
    with pytest.raises(SystemExit) as info:
        main(["run", str(EXAMPLE), "-o", str(out), "-q", "--no-figures"])
    assert info.value.code == 0
    data = json.loads((out / "results.json").read_text())["forced_response"]
    row = next(p for p in data["peaks"] if p["k"] == 0 and p["station"] == "crew-module")
    value = row["acceleration_g_per_percent"]
    assert math.isfinite(value) and value > 0.0
    case = load_case(EXAMPLE)
    direct = forced_response(
        vehicle_from_case(case), F0=10e6, amplitude=0.01,
        Omega=np.linspace(24.0 * math.pi, 28.0 * math.pi, 201), damping_ratio=0.01,
        misalignment=0.25 * math.pi / 180.0, gimbal_gain=0.5, pitch_damping_ratio=0.05,
        stations=[("crew-module", 88.6), ("first-stage-forward", 53.0)])
    assert value == direct.peak(0, "crew-module", "acceleration").value / STANDARD_GRAVITY
    assert "forced-response.csv" in json.loads((out / "manifest.json").read_text())["files"]
    with (out / "forced-response.csv").open() as fh:
        rows = [r for r in csv.DictReader(fh) if r["station"] == "crew-module" and r["k"] == "0"]
    js = [s.name for s in direct.stations].index("crew-module")
    assert [float(r["acceleration_g"]) for r in rows] == (
        np.abs(direct.acceleration[0, js]) / STANDARD_GRAVITY).tolist()


def test_no_oscillation_is_zero_and_said(tmp_path):
    """gamma = 0: the response is zero (source: linearity, Delta F = 0), no harmonic is ranked,
    "per 1 %" is not defined, and the summary says so instead of a table of zeros."""
    from flexbooster.present.forced import FORCED_ZERO, print_forced_response

    case, _ = _load(tmp_path, _case_text("misalignment = 0.01").replace(
        "\ngamma = 0.05", "\ngamma = 0.0", 1))
    loads = analyze_forced_response(case)
    assert not np.any(loads.response.acceleration) and loads.ranked_peaks() == ()
    assert loads.per_percent is None and loads.convergence == (None, None)
    console = Console(record=True, width=200)
    print_forced_response(types.SimpleNamespace(forced_response=loads), console)
    assert FORCED_ZERO in console.export_text().replace("\n", " ")


@pytest.mark.slow
def test_a_supported_aft_end_reacting_the_misalignment_is_a_warning(memo_case_dict):
    """The memo's vehicle has shear-diaphragm ends (memo 5.3-2): a support at the aft edge
    reacts the thrust's lateral component, so the k = 1 response is exactly zero (statics: the
    load acts on a constrained degree of freedom) and the stage says so; with free ends (the
    vehicle in flight) the same misalignment bends the vehicle and nothing is said."""
    from flexbooster.analysis import _forced_stage  # noqa: PLC2701 - the stage's own wrapper

    memo_case_dict["thrust"]["misalignment"] = 0.01
    found, warnings = _forced_stage(flexbooster.load_case(memo_case_dict))
    assert [(w.code, w.field) for w in warnings] == [("misalignment-reacted",
                                                      "thrust.misalignment")]
    k1 = found.response.harmonics.index(1)
    assert not np.any(found.response.bending_moment[k1])
    memo_case_dict["vehicle"] = {"aft_end": "free", "fwd_end": "free"}
    found, warnings = _forced_stage(flexbooster.load_case(memo_case_dict))
    assert warnings == [] and np.max(np.abs(found.response.bending_moment[k1])) > 0.0


def test_terminal_table_fits_80_columns_without_wrapped_names(tmp_path):
    """At 80 columns every line fits and no station name is folded over two lines: a name that
    fits is printed whole; one longer than the room beside the numbers is shortened with "~"
    and the note names the CSV that holds it whole (forced-response.csv's ``station``, exact).
    For a spectrum the "per 1 %" column is dropped (its lines have their own amplitudes)."""
    from flexbooster.present.forced import print_forced_response

    long_name = "aft-skirt-to-first-stage-forward-dome-attachment-ring-number-2"
    extra = ('\n[[output.stations]]\nname = "first-stage-forward"\nstation = "3 m"\n'
             f'[[output.stations]]\nname = "{long_name}"\nstation = "5 m"\n')
    case, _ = _load(tmp_path, _case_text("misalignment = 0.01", extra=extra))
    loads = analyze_forced_response(case)
    console = Console(record=True, width=80, color_system=None)
    print_forced_response(types.SimpleNamespace(forced_response=loads), console)
    text = console.export_text()
    assert max(len(line) for line in text.splitlines()) <= 80
    rows = [line for line in text.splitlines() if line.startswith(" first-stage-forward ")]
    assert len(rows) == 2  # k = 0 and k = 1, the whole name on the row
    assert long_name not in text and f"{long_name[:10]}" in text and "~" in text
    assert f"full names in {FORCED_CSV}" in text
    assert long_name in loads.csv_columns()["station"]
    (head,) = [line for line in text.splitlines() if line.startswith(" station ")]
    assert "per 1 %" in head  # gamma = 0.05: the column says something
    spec, _ = _load(tmp_path, _case_text(extra='\n[[thrust.spectrum]]\nfrequency = "13 Hz"'
                                         '\namplitude = 0.01\n'), name="spectrum.toml")
    console = Console(record=True, width=80, color_system=None)
    print_forced_response(types.SimpleNamespace(forced_response=analyze_forced_response(spec)),
                          console)
    text = console.export_text()
    (head,) = [line for line in text.splitlines() if line.startswith(" station ")]
    assert "per 1 %" not in head and "peak (g)" in head


def test_a_response_largest_at_the_end_of_the_range_is_marked(tmp_path, readme_loads):
    """Source: the stored curves. Below README's vehicle's first elastic mode (Omega 5..50
    rad/s, the axial acceleration nearly the rigid body's F / m) each station's k = 0
    acceleration is largest at an end of the grid and larger there than at the grid's next
    point: each such response of the ranking is marked ``at_range_end`` and said so in the
    list's words ("larger beyond it"); in both this and the full range (5..2000 rad/s) a
    response is marked exactly where its Omega is an end of the grid."""
    text = re.sub(r'^omega_max = .*$', 'omega_max = "50 rad/s"',
                  _case_text(extra=STATIONS), flags=re.M)
    case, _ = _load(tmp_path, text)
    low = analyze_forced_response(case)
    _, full = readme_loads
    marked = 0
    for loads in (low, full):
        r = loads.response
        ends = (r.omega[0], r.omega[-1])
        for p in loads.response_peaks():
            assert p.at_range_end == (p.Omega in ends)
            assert p.to_dict()["at_range_end"] is p.at_range_end
            if p.at_range_end:
                js = [s.name for s in r.stations].index(p.station)
                a = np.abs(r.acceleration[list(r.harmonics).index(p.k), js])
                assert (a[-1] > a[-2]) if p.Omega == ends[1] else (a[0] > a[1])
                assert "larger beyond it" in p.text
                marked += loads is low
    assert marked >= 1


def test_every_forced_resonance_in_range_is_listed(readme_loads):
    """Source: the stored curves (the grid samples the same response independently). Each
    mode of the forced model in the operating range that the thrust forces (f^2 >= 1e-8 of its
    harmonic's largest) has a response in the list within zeta Omega of its peak, whose
    acceleration is no lower than the largest grid value within the mode's half-power band
    omega (1 -+ zeta) at any station (the refined peak bounds the samples), also where that
    resonance is no station's largest peak (the list held each station's largest only)."""
    from flexbooster.dynamics import MIN_PARTICIPATION

    _, loads = readme_loads
    r = loads.response
    lo, hi = loads.operating_range
    zeta = float(r.damping_ratio)
    listed = loads.response_peaks()
    station_max = {(p.k, p.Omega) for p in loads.ranked_peaks()}
    extra = 0
    for ik, (k, model) in enumerate(zip(r.harmonics, r.models, strict=True)):
        basis = model.omega_modes[model.n_rigid:]
        f2 = model.load[model.n_rigid:] ** 2
        if not np.any(f2 > 0.0):
            continue
        for om in basis[(basis >= lo) & (basis <= hi) & (f2 >= MIN_PARTICIPATION * f2.max())]:
            band = (r.omega >= om * (1 - zeta)) & (r.omega <= om * (1 + zeta))
            grid = (np.abs(r.acceleration[ik])[:, band].max() / STANDARD_GRAVITY
                    if band.any() else 0.0)
            near = [p for p in listed if p.k == k and abs(p.Omega - om) <= 2 * zeta * om]
            assert near, (k, om)
            assert max(p.acceleration_g for p in near) >= grid * (1 - 1e-12)
            extra += not any(kk == k and abs(w - om) <= 2 * zeta * om
                             for kk, w in station_max)
    assert extra >= 1  # resonances that no station's largest peak stands for
