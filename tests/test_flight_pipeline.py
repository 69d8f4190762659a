"""The flight in the pipeline: the [flight] table (flexbooster.flight_case), the flight stage
(flexbooster.flight_stage) inside analyze, and its files (flexbooster.present.flight).

Evidence: an exact limit (a constant vehicle and a constant oscillation: the flight equals the
single-case analysis and the e-folds are rate x duration), an independent physical fact for
the tracking (an inviscid liquid adds no torsional mass: the torsional mode stays put while the
axial modes rise through it), the file columns the README lists, and bad-field probes.
"""

from __future__ import annotations

import copy
import csv
import dataclasses
import json
import math
import tomllib

import numpy as np
import pytest

from conftest import dump_toml
from flexbooster.analysis import analyze
from flexbooster.case import default_case_text, load_case
from flexbooster.cli import main
from flexbooster.dynamics import PEAK_WINDOW, STANDARD_GRAVITY, forced_response
from flexbooster.errors import CaseError
from flexbooster.flight import mac_matrix
from flexbooster.flight_stage import flight_stage, frozen_time
from flexbooster.model import forced_stations, vehicle_from_case
from flexbooster.present.flight import flight_lines, write_flight_csvs

#: A free-free aluminium cylinder (E = 70 GPa, rho = 2700 kg/m^3) with one LOX tank
#: (1141 kg/m^3) and a nose mass; small sizes so that a frozen time takes a fraction of a second.
CASE = {
    "name": "flight test",
    "thrust": {"F0": 2e5, "gamma": 0.15, "K": 0.0, "omega_min": 15.0, "omega_max": 60.0,
               "n_omega": 20},
    "vehicle": {"k_max": 2, "n_modes": 4, "damping_ratio": 0.002,
                "E": 7e10, "nu": 0.3, "rho": 2700.0,
                "segments": [{"kind": "cylinder", "radius": 1.0, "length": 8.0,
                              "thickness": 0.004}],
                "masses": [{"station": 8.0, "mass": 500.0}],
                "tanks": [{"aft": 0.0, "fwd": 8.0, "fill": 0.5, "density": 1141.0}]},
    "flight": {"stations": 2, "points": [
        {"time": 0.0, "F0": 2e5, "fill": [0.5], "oscillation": [15.0, 60.0], "gamma": 0.15},
        {"time": 40.0, "F0": 2e5, "fill": [0.5], "oscillation": [15.0, 60.0], "gamma": 0.15}]},
}




@pytest.fixture(scope="module")
def constant():
    """The constant flight analysed once (analyze: the single case and its flight)."""
    return analyze(load_case(CASE), beam_action=False, stability=False, figures=False)


# ------------------------------------------------------------------ exact limit: constant flight

@pytest.mark.slow
def test_constant_flight_equals_the_single_case(constant):
    """Exact limit: fills, F0, gamma constant and the oscillation band = the case's Omega range,
    so every frozen time is the case itself: the regions equal those of the single-case
    analysis (dataclass equality, bit for bit, but for the critical damping ratio, a measure of
    the single case's verdict that the flight does not compute) and the k = 2 frequencies equal
    its harmonic's loaded frequencies (rel. 1e-12)."""
    fl = constant.flight
    single = tuple(dataclasses.replace(r, critical_damping_ratio=None)
                   for r in constant.vehicle_regions.regions)
    assert single, "the case must have regions for the comparison to mean anything"
    for bands in fl.regions:
        assert bands == single
    h2 = next(h for h in fl.harmonics if h.k == 2)
    expected = np.sort(constant.vehicle_regions.harmonic(2).omega_loaded)
    for t in range(fl.times.size):
        assert h2.frequencies[t][np.isfinite(h2.frequencies[t])] == pytest.approx(
            expected, rel=1e-12)


@pytest.mark.slow
def test_constant_flight_efolds_are_rate_times_duration(constant):
    """Exact limit: a region held for the whole flight inside the oscillation band grows at its
    largest rate throughout, so e-folds = growth_rate_max x duration (40 s) and amplification
    = exp(e-folds) (rel. 1e-12); the rate is the single case's region's (independent call)."""
    fl = constant.flight
    regions = [e for e in fl.events if e.mechanism == "vehicle"]
    assert len(regions) == len(constant.vehicle_regions.regions)
    for band in constant.vehicle_regions.regions:
        (event,) = [e for e in regions if e.k == band.k and e.modes == band.mode_text]
        assert (event.t_start_s, event.t_end_s) == (0.0, 40.0)
        assert event.efolds == pytest.approx(band.growth_rate_max * 40.0, rel=1e-12)
        assert event.amplification == pytest.approx(np.exp(event.efolds), rel=1e-12)
    assert fl.worst.efolds == max(e.efolds for e in fl.events)  # worst first
    assert fl.events[0] is fl.worst and flight_lines(fl)[0].startswith("Worst moment")


@pytest.mark.slow
def test_flight_files_have_the_documented_columns(constant, tmp_path):
    """flight-modes.csv (time_s, k, mode, hz, type) and flight-events.csv (mechanism, k,
    modes, t_start_s, t_end_s, max_growth_1_s, efolds, amplification, peak_acceleration_g,
    station), spelled out here from the README; one mode row per frozen time and present
    mode."""
    modes, events = write_flight_csvs(constant.flight, tmp_path)
    with modes.open() as f:
        rows = list(csv.reader(f))
    assert rows[0] == ["time_s", "k", "mode", "hz", "type"]
    present = sum(int(np.isfinite(h.frequencies).sum()) for h in constant.flight.harmonics)
    assert len(rows) - 1 == present
    # "mode" is the tracked identity j + 1 (1-based, as "mode N" in the summary's words)
    h = constant.flight.harmonics[0]
    first = next(r for r in rows[1:] if r[1] == str(h.k) and r[2] == "1")
    assert float(first[0]) == constant.flight.times[0]
    assert float(first[3]) == pytest.approx(h.frequencies[0, 0] / (2 * np.pi), rel=1e-12)
    with events.open() as f:
        rows = list(csv.reader(f))
    assert rows[0] == ["mechanism", "k", "modes", "t_start_s", "t_end_s", "max_growth_1_s",
                       "efolds", "amplification", "peak_acceleration_g", "station"]
    assert len(rows) - 1 == len(constant.flight.events)
    data = constant.to_dict()["flight"]
    assert data["worst"] == constant.flight.events[0].to_dict()
    assert len(data["mass_properties"]) == constant.flight.times.size


def test_no_flight_changes_nothing():
    """Without [flight] the stage returns nothing and results.json has no "flight" key."""
    data = copy.deepcopy(CASE)
    data.pop("flight")
    case = load_case(data)
    assert flight_stage(case) == (None, [])
    assert "flight" not in case.to_si_dict()


# ------------------------------------------------------------- tracking: a crossing kept apart

@pytest.mark.slow
def test_tracking_keeps_a_torsional_mode_through_rising_axial_modes():
    """Independent fact: an inviscid liquid loads the wall normally and axially, never in
    torsion, so as the tank drains (fill 0.9 -> 0.3) the k = 0 axial modes rise while the
    torsional mode keeps its frequency (rel. 1e-6 over the flight; F0 = 1 N, so that the
    thrust's prestress, redistributed by inertia relief as the mass drains, is negligible).
    Where an axial identity crosses the torsional one, both keep their type at every time
    and the MAC between neighbouring times stays > 0.9 within two steps of the crossing
    (the MAC weighted by the mean of both times' masses, structure and
    liquid, falls as the square of the step: 61 frozen times, a fill step of 0.01, keep it
    above 0.9 where 41 give 0.89)."""
    data = copy.deepcopy(CASE)
    data["vehicle"].update(k_max=0, n_modes=8,
                           segments=[{"kind": "cylinder", "radius": 1.5, "length": 30.0,
                                      "thickness": 0.005}],
                           masses=[{"station": 30.0, "mass": 500.0}],
                           tanks=[{"aft": 0.0, "fwd": 30.0, "fill": 0.9, "density": 1141.0}])
    data["thrust"]["F0"] = 1.0  # a negligible prestress: no inertia-relief change of torsion
    data["flight"] = {"stations": 61, "points": [
        {"time": 0.0, "F0": 1.0, "fill": [0.9], "oscillation": [20.0, 40.0], "gamma": 0.01},
        {"time": 100.0, "F0": 1.0, "fill": [0.3], "oscillation": [20.0, 40.0],
         "gamma": 0.01}]}
    fl, _ = flight_stage(load_case(data))
    (h0,) = fl.harmonics
    f = h0.frequencies
    crossings = []
    for i in range(f.shape[1]):
        for j in range(i + 1, f.shape[1]):
            d = f[:, i] - f[:, j]
            both = np.isfinite(d[:-1]) & np.isfinite(d[1:])
            steps = np.flatnonzero(both & (d[:-1] * d[1:] < 0.0))
            crossings += [(i, j, s) for s in steps]
    pairs = [(i, j, s) for i, j, s in crossings
             if {h0.types[np.isfinite(f[:, i]), i][0], h0.types[np.isfinite(f[:, j]), j][0]}
             == {"axial", "torsional"}]
    assert pairs, "the example must have an axial mode crossing the torsional one"
    for i, j, s in pairs:
        for ident in (i, j):
            alive = np.isfinite(f[:, ident])
            assert len(set(h0.types[alive, ident])) == 1  # keeps its type
            near = h0.mac[max(s - 2, 0):s + 3, ident]  # two steps either side of the crossing
            near = near[np.isfinite(near)]
            assert near.size >= 3 and near.min() > 0.9
        tors = i if h0.types[np.isfinite(f[:, i]), i][0] == "torsional" else j
        alive = f[np.isfinite(f[:, tors]), tors]
        assert alive.max() / alive.min() - 1.0 < 1e-6


# --------------------------------------------------------------------------- bad-field probes

BAD = [  # (change to the [flight] table, field named, words of the rule)
    (lambda f: f["points"][1].update(fill=[0.5, 0.4]), "flight.points[1].fill",
     "needs 1 values"),
    (lambda f: f["points"][0].update(fill=[1.5]), "flight.points[0].fill", "[0, 1]"),
    (lambda f: f["points"][0].update(oscillation=[60.0, 20.0]),
     "flight.points[0].oscillation", "lo <= hi"),
    (lambda f: f["points"][0].update(oscillation=[1.0, 2.0, 3.0]),
     "flight.points[0].oscillation", "band"),
    (lambda f: f["points"][1].update(time=0.0), "flight.points[1].time", "later"),
    (lambda f: f["points"][1].update(gamma=1.0), "flight.points[1].gamma", "[0, 1)"),
    (lambda f: f["points"][1].update(F0="3 m"), "flight.points[1].F0", "wrong dimension"),
    (lambda f: f["points"][1].pop("F0"), "flight.points[1].F0", "missing"),
    (lambda f: f.update(duration=30.0), "flight.duration", "span"),
    (lambda f: f.update(stations=1), "flight.stations", "2.."),
    (lambda f: f.update(times=[0.0, 50.0], stations=None), "flight.times", "within"),
    (lambda f: f.update(times=[0.0, 30.0]), "flight.stations", "not both"),
    (lambda f: f.update(point=[]), "flight.point", "unknown key"),
    (lambda f: f.update(points=f["points"][:1]), "flight.points", "at least 2"),
]


@pytest.mark.parametrize("change, field, rule", BAD, ids=[b[1] + ": " + b[2] for b in BAD])
def test_bad_flight_field_is_one_line_naming_it(change, field, rule, tmp_path, capsys):
    """Rule 4: a CaseError naming the field and the rule, exit 2 with one line."""
    data = copy.deepcopy(CASE)
    change(data["flight"])
    data["flight"] = {k: v for k, v in data["flight"].items() if v is not None}
    with pytest.raises(CaseError) as info:
        load_case(data)
    assert info.value.field == field and rule in info.value.rule
    path = tmp_path / "bad.toml"
    path.write_text(dump_toml(data))
    with pytest.raises(SystemExit) as code:
        main(["run", str(path), "-o", str(tmp_path / "out")])
    assert code.value.code == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and field in err


@pytest.mark.slow
def test_summary_and_report_show_the_flight_worst_first(constant):
    """The summary's "Flight" part and the report's section open with the worst moment, the
    first event of results.json's flight (the same event in every output)."""
    import io

    from rich.console import Console

    from flexbooster.present.flight import event_text
    from flexbooster.present.report import render_report
    from flexbooster.present.summary import print_summary

    buffer = io.StringIO()
    print_summary(constant, Console(file=buffer, width=400))
    text = buffer.getvalue()
    worst = "Worst moment: " + event_text(constant.flight.events[0])
    assert "Flight (worst moment first)" in text and worst in text
    page = render_report(constant)
    assert '<section id="flight">' in page
    flight = page[page.index('<section id="flight">'):]
    assert worst.replace("'", "&#x27;") in flight
    first = page[page.index('id="first-screen"'):page.index('<section id="inputs"')]
    assert worst.replace("'", "&#x27;") in first  # the first screen says the same
    # the list of the most dangerous frequencies says it is the case's one state, the flight
    # apart, in the summary and on the first screen (and says nothing of it without a flight)
    from flexbooster.present.rows import danger_scope

    scope = danger_scope(constant)
    assert "one vehicle state" in scope and "under Flight" in scope
    line = next(x for x in text.splitlines() if x.startswith("Most dangerous thrust"))
    assert line.endswith(f"all in results.json{scope})")
    html_scope = scope.replace("'", "&#x27;")
    assert f"<code>danger</code>{html_scope})</h3>" in first
    assert danger_scope(dataclasses.replace(constant, flight=None)) == ""



def test_verification_names_the_vehicle_checks_not_the_memo_cylinders(constant):
    """The report's verification summary of a [[vehicle.segments]] case with a flight lists
    the vehicle model's checks (liquid, slosh, stiffeners, the rigid pitch's Mathieu
    numerics) and the flight's, and none of the memo's two-cylinder checks (geometry of four
    boosters, beam, Donnell shells, the memo's roots)."""
    from flexbooster.present.report import (
        FLIGHT_VERIFICATION,
        render_report,
        verification_rows,
    )

    tests = [row[3] for row in verification_rows(constant)]
    assert tests[-len(FLIGHT_VERIFICATION):] == [row[3] for row in FLIGHT_VERIFICATION]
    for want in ("test_liquid::test_slosh_cylinder_abramson",
                 "test_stiffeners::test_stiffened_cylinder_matches_smeared_closed_form",
                 "test_pitch::test_exponent_against_mpmath"):
        assert want in tests
    assert not [t for t in tests if t.split("::")[0] in (
        "test_geometry", "test_beam", "test_shell", "test_beam_action", "test_stability",
        "test_vehicle_pipeline")]
    page = render_report(constant)
    section = page[page.index('<section id="verification">'):]
    section = section[:section.index("</section>")]
    assert [t for t in tests if t not in section] == []
    assert "test_geometry::" not in section

def test_a_bare_shell_flight_has_no_forced_response_warning():
    """The forced resonances along the flight need no tanks or masses: a bare shell (k_max = 0,
    the k = 0 modes only, for speed) gives no ``flight-forced-response`` warning."""
    data = copy.deepcopy(CASE)
    data["vehicle"]["k_max"] = 0
    data["vehicle"].pop("tanks")
    data["vehicle"].pop("masses")
    for p in data["flight"]["points"]:
        p["fill"] = []
    _, warnings = flight_stage(load_case(data))
    assert "flight-forced-response" not in [w.code for w in warnings]


def test_no_resonant_peak_above_the_critical_damping_ratio():
    """A damping ratio past 1/sqrt(2): |H(Omega)| of a mode falls monotonically from Omega = 0
    (no resonant peak, Meirovitch 1986, sec. 3.4): no forced event, and a note saying why
    (the forced case of the next tests with zeta = 0.75, k_max = 0)."""
    data = _forced_case(0.0)
    data["vehicle"].update(k_max=0, damping_ratio=0.75)
    flight, warnings = flight_stage(load_case(data))
    assert not [e for e in flight.events if e.mechanism == "forced"]
    assert any("1/sqrt(2)" in n for n in flight.notes)
    assert "flight-forced-response" not in [w.code for w in warnings]


def _forced_case(misalignment: float) -> dict:
    """CASE with k = 0..1 and an oscillation band [200, 300] rad/s for the 40 s: it holds the
    first axial mode (253.9 rad/s, k = 0) and the first bending mode (216.3 rad/s, k = 1) of the
    frozen vehicle; a thrust misaligned by ``misalignment`` rad forces k = 1."""
    data = copy.deepcopy(CASE)
    data["vehicle"]["k_max"] = 1
    data["thrust"].update(omega_min=200.0, omega_max=300.0, misalignment=misalignment)
    for p in data["flight"]["points"]:
        p["oscillation"] = [200.0, 300.0]
    return data


@pytest.fixture(scope="module")
def forced_flight():
    """The flight of :func:`_forced_case` at misalignments 0.01 and 0.02 rad."""
    return {d: flight_stage(load_case(_forced_case(d)))[0] for d in (0.01, 0.02)}


def test_forced_event_peaks_are_the_steady_peaks_of_the_frozen_vehicle(forced_flight):
    """Independent search on the frozen vehicle: a constant vehicle and band, so each forced
    event's peak is the largest steady |acceleration| over the stations within its mode's window
    omega (1 -+ PEAK_WINDOW zeta). forced_response of the frozen case (the single case's
    settings and the flight's range widened by the window, hence the same modal basis) with a
    4001-point grid over that window, the maximum over the grid and the stations: the event is
    at least that (1e-12) and at most 1e-4 above it (a grid spacing of 4e-6 omega across a
    peak of half-width zeta omega = 2e-3 omega misses at most (1e-3)^2 / 2 of it); the station
    named is where the grid's maximum is."""
    fl = forced_flight[0.01]
    case = load_case(_forced_case(0.01))
    vehicle = vehicle_from_case(case)
    zeta = case.vehicle_damping_ratio
    forced = {e.k: e for e in fl.events if e.mechanism == "forced"}
    assert set(forced) == {0, 1}, "both the axial and the bending resonance are in the band"
    for k, expected_hz in ((0, 253.85), (1, 216.27)):
        h = next(h for h in fl.harmonics if h.k == k)
        omega = float(h.frequencies[0, 0])
        assert omega == pytest.approx(expected_hz, rel=1e-4)
        w = PEAK_WINDOW * zeta
        grid = np.concatenate([[200.0 * (1.0 - w)], omega * (1.0 + w * np.linspace(
            -1.0, 1.0, 4001)), [300.0 * (1.0 + w)]])
        r = forced_response(vehicle, F0=case.F0, amplitude=case.thrust.gamma, Omega=grid,
                            damping_ratio=zeta, misalignment=0.01, gimbal_gain=case.thrust.K,
                            stations=forced_stations(case, vehicle)[0], harmonics=(k,))
        a = np.abs(r.acceleration[0]) / STANDARD_GRAVITY  # (stations, grid)
        event = forced[k]
        assert event.modes == f"mode 1 ({h.types[0, 0]})"  # 1-based, as every "mode N"
        assert (event.t_start_s, event.t_end_s) == (0.0, 40.0)
        assert a.max() * (1 - 1e-12) <= event.peak_acceleration_g <= a.max() * (1 + 1e-4)
        assert event.station == r.stations[int(np.argmax(a.max(axis=1)))].name


def test_forced_event_peaks_scale_with_the_thrust_line(forced_flight):
    """Linearity (Meirovitch 1986, ch. 7): the thrust line misaligned by delta loads k = 0 by
    cos delta and k = 1 by sin delta, so doubling delta from 0.01 to 0.02 rad scales the
    lateral peak by sin 0.02 / sin 0.01 and the axial one by cos 0.02 / cos 0.01 (1e-9); without
    a misalignment there is no k = 1 event and the flight says why."""
    one, two = ({e.k: e for e in forced_flight[d].events if e.mechanism == "forced"}
                for d in (0.01, 0.02))
    assert two[1].peak_acceleration_g / one[1].peak_acceleration_g == pytest.approx(
        np.sin(0.02) / np.sin(0.01), rel=1e-9)
    assert two[0].peak_acceleration_g / one[0].peak_acceleration_g == pytest.approx(
        np.cos(0.02) / np.cos(0.01), rel=1e-9)
    none, _ = flight_stage(load_case(dict(_forced_case(0.0), vehicle=dict(
        _forced_case(0.0)["vehicle"], k_max=0))))
    assert [e.k for e in none.events if e.mechanism == "forced"] == [0]
    assert any("thrust.misalignment = 0" in n for n in none.notes)


@pytest.mark.slow
def test_the_overall_verdict_is_the_worst_over_the_flight(constant):
    """Exact limit (constant flight): every region of the single case lasts the whole 40 s, so
    its e-folds are growth x 40 s; those past ln 10 make the flight, and so the overall
    verdict, UNSTABLE; results.json, the terminal's first line and the report's first screen
    carry the same verdict. A negligible event (1e-7 1/s) added to the flight is dropped,
    counted, and never the worst moment."""
    import dataclasses
    import io
    import math

    from rich.console import Console

    from flexbooster.flight import FlightEvent
    from flexbooster.present.report import render_report
    from flexbooster.present.summary import print_summary

    expected = sorted(b.growth_rate_max * 40.0 for b in constant.vehicle_regions.regions
                      if b.growth_rate_max * 40.0 > math.log(1.1))
    v = constant.danger.verdict
    assert sorted(e.efolds for e in v.flight.events) == pytest.approx(expected, rel=1e-12)
    assert v.overall == "UNSTABLE" and v.flight.status() == "unstable"
    data = json.loads(json.dumps(constant.to_dict()))["verdict"]
    assert data == json.loads(json.dumps(v.to_dict()))
    buffer = io.StringIO()
    print_summary(constant, Console(file=buffer, width=2000), full=False)
    assert buffer.getvalue().splitlines()[0] == f"UNSTABLE: {v.reason}"
    page = render_report(constant)
    first = page[page.index('id="first-screen"'):page.index('<section id="inputs"')]
    assert v.reason.replace("'", "&#x27;") in first
    slow = FlightEvent(mechanism="vehicle", k=1, modes="bending 1", t_start_s=0.0,
                       t_end_s=40.0, max_growth_1_s=1e-7, efolds=4e-6, amplification=1.000004)
    fl = dataclasses.replace(constant.flight, events=(slow, *constant.flight.events))
    assert fl.dropped == 1 and fl.worst is constant.flight.events[0]
    lines = flight_lines(fl)
    assert lines[0].startswith("Worst moment: vehicle k = 2") and any(
        line.startswith("1 event of negligible growth dropped") for line in lines)
    assert json.loads(json.dumps(fl.to_dict()))["events_dropped"] == 1


@pytest.mark.slow
def test_tracking_with_the_liquid_follows_the_veering_pair_of_the_default_case():
    """Independent reference: the same flight tracked at 41 frozen times (3.9 s apart) instead
    of 11 (15.6 s). The default case's two lowest axial modes (13.15 and 13.53 Hz at 46.8 s)
    veer into 13.88 and 14.87 Hz at 62.4 s; the coarse tracking must continue its identities 0
    and 1 into that same pair (in either order: across a veering the shapes exchange), the
    frozen problems at those times being the same (1e-12). Weighted by the structure's mass
    alone (the liquid left out), identity 0 continued into a 39 Hz mode (MAC 0.90 against
    0.59). Also exact: the MAC of two modes of one time, weighted by that time's structure
    and liquid, is 0 (orthonormal in the eigenproblem's mass), to 1e-10."""
    def k0(stations):
        data = tomllib.loads(default_case_text())
        data["vehicle"]["k_max"] = 0  # the axial modes alone
        data["flight"]["stations"] = stations
        case = load_case(data)
        fl, _ = flight_stage(case)
        (h,) = fl.harmonics
        a, b = (int(np.argmin(abs(fl.times - t))) for t in (46.8, 62.4))
        assert fl.times[[a, b]] == pytest.approx([46.8, 62.4], rel=1e-12)
        return case, a, h.frequencies[[a, b]][:, :2] / (2 * np.pi)

    case, a, coarse = k0(11)
    _, _, fine = k0(41)
    np.testing.assert_allclose(coarse[0], fine[0], rtol=1e-12)  # identities 0, 1 at 46.8 s
    np.testing.assert_allclose(np.sort(coarse[1]), np.sort(fine[1]), rtol=1e-12)
    assert np.all(coarse[1] < 20.0)  # no jump to the 39 Hz mode
    frozen = frozen_time(case, a)
    weight = frozen_time(case, 0).structural_mass[0] + frozen.liquid_mass[0].toarray()
    mac = mac_matrix(frozen.vectors[0], frozen.vectors[0], mass=weight)
    np.testing.assert_allclose(mac, np.eye(mac.shape[0]), atol=1e-10)


@pytest.mark.slow
def test_flight_regions_below_the_slosh_frequency_are_warned_about():
    """Independent value: Abramson's first lateral slosh frequency of a flat-bottomed
    cylinder (NASA SP-106, ch. 2), omega^2 = (a xi_1 / R) tanh(xi_1 h / R), a = F0(t) / m(t).
    The default flight, k = 1: from 93.6 s a region holds the rigid pitch (0.33 Hz, the
    liquid's high-frequency added mass) below twice the slosh frequency: one
    ``liquid-below-slosh`` warning names the first such frozen time, and the slosh it cites
    is the stage-1 oxidiser's there (R = 1.52 m, h = its fill x 8 m), to 1 %."""
    from scipy.special import jnp_zeros

    from flexbooster.dynamics import SLOSH_VALIDITY_FACTOR

    data = tomllib.loads(default_case_text())
    data["vehicle"]["k_max"] = 1
    case = load_case(data)
    fl, warnings = flight_stage(case)
    (w,) = [w for w in warnings if w.code == "liquid-below-slosh"]
    t = float(w.message.split("t = ")[1].split(" s")[0])
    i = int(np.argmin(abs(fl.times - t)))
    assert fl.times[i] == pytest.approx(t, rel=1e-5)
    xi = float(jnp_zeros(1, 1)[0])
    a = fl.F0[i] / fl.mass[i].mass_kg
    h = fl.fill[i, list(fl.tank_names).index("stage-1 oxidiser")] * 8.0
    hz = math.sqrt(a * xi / 1.52 * math.tanh(xi * h / 1.52)) / (2.0 * math.pi)
    cited = float(w.message.split("first slosh frequency ")[1].split(" Hz")[0])
    assert cited == pytest.approx(hz, rel=1e-2) and "(tank stage-1 oxidiser)" in w.message
    pitch = [m.omega for r in fl.regions[i] for m in r.modes if m.type == "rigid-pitch"]
    assert pitch and min(pitch) < SLOSH_VALIDITY_FACTOR * 2.0 * math.pi * hz
    assert all(not [m for r in fl.regions[j] for m in r.modes if m.type == "rigid-pitch"]
               for j in range(i))  # the first such time


@pytest.mark.slow
def test_combinations_passing_over_the_band_are_searched_at_both_ends():
    """Independent reference: the same flight at 41 frozen times (3.9 s apart) instead of 11
    (15.6 s). The default flight, k = 1 (no stability certificate: its rigid pitch is
    undamped), with a narrow oscillation band 10.5-10.7 Hz. (1) The count: every pair of
    tracked k = 1 modes (flight-modes.csv) whose combination centre (2 f_i, f_i + f_j,
    |f_i - f_j|, over n = 1, 2) is below the band at one frozen time and above it at the next,
    or the reverse, counted by hand, is the count of the flight's note. (2) The region
    rigid-pitch 0 + bending 3 leaves the band between 109.2 and 124.8 s: found at 124.8 s in
    the window outside the range, its event ends where its edges, linear in time, leave the
    band, within one fine step of the fine flight's end (held to 124.8 s it would end 8 s
    late). (3) A window beyond PASS_OVER_REACH of the range is a search gap (not stable)."""
    import collections
    import itertools

    def run(stations):
        data = tomllib.loads(default_case_text())
        data["vehicle"]["k_max"] = 1
        data["flight"]["stations"] = stations
        for point in data["flight"]["points"]:
            point["oscillation"] = ["10.5 Hz", "10.7 Hz"]
        return flight_stage(load_case(data))

    fl, warnings = run(11)
    hz = collections.defaultdict(dict)
    for row in fl.mode_rows():
        if row["k"] == 1:
            hz[row["mode"]][row["time_s"]] = row["hz"]
    times = list(fl.times)
    count = 0
    for a, b in itertools.combinations_with_replacement(sorted(hz), 2):
        for t0, t1 in zip(times[:-1], times[1:], strict=True):
            if not all(t in hz[m] for m in (a, b) for t in (t0, t1)):
                continue
            ends = [(2 * hz[a][t0], 2 * hz[a][t1])] if a == b else [
                (hz[a][t0] + hz[b][t0], hz[a][t1] + hz[b][t1]),
                (abs(hz[a][t0] - hz[b][t0]), abs(hz[a][t1] - hz[b][t1]))]
            for (c0, c1), n in itertools.product(ends, (1, 2)):
                c0, c1 = c0 / n, c1 / n
                count += (c0 < 10.5 and c1 > 10.7) or (c0 > 10.7 and c1 < 10.5)
    (note,) = [n for n in fl.notes if "pass over the searched Omega range" in n]
    assert count > 0 and note.startswith(f"{count} combination(s)")
    fine, _ = run(41)
    (coarse_event,) = [e for e in fl.events if e.modes == "rigid-pitch 0 + bending 3"]
    (fine_event,) = [e for e in fine.events if e.modes == "rigid-pitch 0 + bending 3"]
    assert 109.2 < coarse_event.t_end_s < 124.8
    assert coarse_event.t_end_s == pytest.approx(fine_event.t_end_s, abs=156.0 / 40)
    assert any(g.limit == "PASS_OVER_REACH" and g.k == 1 for g in fl.gaps)
    assert [w for w in warnings if w.code == "flight-not-fully-searched"]


def test_window_regions_over_the_range_are_the_frozen_times_own():
    """Exact invariant: dynamics.window_regions of a frozen time's map over that map's own
    Omega range is the same search on the same system, so it returns that harmonic's regions
    of the map, equal as dataclasses (bit for bit), for every harmonic searched."""
    from flexbooster.dynamics import window_regions

    found = frozen_time(load_case(CASE), 0).regions
    assert found.regions  # the constant case has regions
    for h in found.harmonics:
        bands, gaps = window_regions(found, h.k, found.omega_min, found.omega_max)
        assert gaps == ()
        assert bands == tuple(r for r in found.regions if r.k == h.k)
