"""The command line: exit codes, one-line messages, files written atomically."""

from __future__ import annotations

import json
import re
import subprocess
import sys

import pytest

from conftest import dump_toml, run_cli
from test_case import BAD_INPUTS, _set


@pytest.mark.slow
def test_run_memo_writes_results(tmp_path, capsys):
    assert run_cli(["run", "--memo", "-o", str(tmp_path), "--full"]) == 0  # --full: every table
    out = capsys.readouterr().out
    assert "Mass properties" in out and "omega_1" in out
    data = json.loads((tmp_path / "results.json").read_text())
    # the overall verdict of results.json is the summary's first line (docs/theory/verdicts.md)
    assert out.splitlines()[0].startswith(data["verdict"]["overall"] + ": ")
    assert data["case"]["booster"]["cylinder1"]["radius"] == 5.05  # the memo case's R1
    assert data["schema_version"] == "1.0" and "units" in data
    assert data["mass_properties"]["I_cm"] > 0
    names = {p.name for p in tmp_path.iterdir()}
    assert {"results.json", "shell-frequencies.csv", "unstable-frequencies.csv"} <= names
    assert {"ince-strutt.svg", "ince-strutt.png", "campbell.svg"} <= names
    assert {"report.html", "nodal-patterns.svg"} <= names
    report = (tmp_path / "report.html").read_text()
    assert {"pitch-band-chart.svg", "beam-action-chart.svg"} <= names  # the band charts
    assert {"vehicle-regions.csv", "vehicle-regions.svg"} <= names  # the vehicle regions
    assert {"forced-response.csv", "forced-acceleration.svg", "forced-envelopes.svg"} <= names
    # 9 figures + the danger map + the forced response's two
    assert report.count("<svg") == 12 and 'id="unstable-frequencies"' in report
    assert not [n for n in names if n.endswith(".part")]  # no temporary leftovers


def test_init_writes_the_launch_vehicle_and_init_memo_the_memo_case(tmp_path, capsys):
    from flexbooster.case import default_case, load_case, memo_case

    path, memo = tmp_path / "my.toml", tmp_path / "memo.toml"
    assert run_cli(["init", str(path)]) == 0
    assert run_cli(["init", str(path)]) == 2  # refuses to overwrite
    assert "file exists" in capsys.readouterr().err
    assert run_cli(["init", "--memo", str(memo)]) == 0
    vehicle = load_case(path)
    # the launch vehicle: [vehicle] segments with tanks and a [flight], no [booster]
    assert vehicle == default_case() and vehicle.booster is None
    assert vehicle.has_segments and vehicle.vehicle.tanks and vehicle.flight is not None
    # the memo case: [booster] (the memo's two cylinders), no [vehicle], no [flight]
    assert load_case(memo) == memo_case() and memo_case().booster is not None
    assert memo_case().vehicle is None and memo_case().flight is None
    # --memo with a case file: one line naming the option, exit 2
    assert run_cli(["run", str(path), "--memo", "-o", str(tmp_path / "x")]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("flexbooster: error: --memo = ") and len(err.splitlines()) == 1
    assert not (tmp_path / "x").exists()


@pytest.mark.slow
def test_init_then_run_shows_the_flight(tmp_path, capsys):
    """The newcomer's first run (`flexbooster init` + `run`): the overall verdict first, then
    the flight's worst moment in the summary; the flight's files written."""
    path, out = tmp_path / "my.toml", tmp_path / "out"
    assert run_cli(["init", str(path)]) == 0
    capsys.readouterr()
    assert run_cli(["run", str(path), "-o", str(out), "--no-figures"]) == 0
    text = capsys.readouterr().out
    data = json.loads((out / "results.json").read_text())
    # the overall verdict of results.json is the summary's first line (docs/theory/verdicts.md)
    assert text.splitlines()[0].startswith(data["verdict"]["overall"] + ": ")
    assert "Worst moment" in " ".join(text.split())
    assert {"flight-events.csv", "flight-modes.csv"} <= {p.name for p in out.iterdir()}
    # 11 frozen times over the 156 s burn (the case's [flight]), every event inside it
    assert data["flight"]["times_s"] == pytest.approx([15.6 * i for i in range(11)], abs=1e-9)
    assert data["flight"]["events"]
    assert all(0.0 <= e["t_start_s"] <= e["t_end_s"] <= 156.0 for e in data["flight"]["events"])


@pytest.mark.parametrize(("path", "value", "field", "rule"), BAD_INPUTS)
def test_bad_input_exit_code_2(memo_case_dict, tmp_path, capsys, path, value, field, rule):
    _set(memo_case_dict, path, value)
    case_file = tmp_path / "bad.toml"
    case_file.write_text(dump_toml(memo_case_dict))
    assert run_cli(["run", str(case_file), "-o", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1, err
    assert field in err and rule in err
    assert not (tmp_path / "out").exists()  # nothing written for a rejected case


def test_not_toml_exit_code_2(tmp_path, capsys):
    bad = tmp_path / "bad.toml"
    bad.write_text("this is = = not toml")
    assert run_cli(["run", str(bad)]) == 2
    assert "not a valid TOML file" in capsys.readouterr().err


def test_warning_reaches_summary_and_results(memo_case_dict, tmp_path, capsys):
    memo_case_dict["booster"]["thickness"] = "0.2 m"  # h/R2 = 0.2/3.3 > 1/20
    memo_case_dict["truncation"].update(M1=3, N1=3, M2=3, N2=3, N=3, S=2, R=2)  # a second's run
    memo_case_dict["thrust"]["n_omega"] = 40
    case_file = tmp_path / "thick.toml"
    case_file.write_text(dump_toml(memo_case_dict))
    assert run_cli(["run", str(case_file), "-o", str(tmp_path), "--no-figures"]) == 0
    assert "thin-shell" in capsys.readouterr().out
    codes = [w["code"] for w in json.loads((tmp_path / "results.json").read_text())["warnings"]]
    assert codes == ["thin-shell"]


@pytest.mark.slow
def test_real_process_no_traceback(tmp_path, memo_case_dict):
    """The installed entry point, as a user runs it: exit 2, one line and no traceback, the
    same for a case read from a file and from a pipe."""
    bad = tmp_path / "bad.toml"
    memo_case_dict["booster"]["E"] = "1 furlong"
    bad.write_text(dump_toml(memo_case_dict))
    errors = []
    for path, piped in ((bad, None), ("/dev/stdin", bad.read_text())):
        proc = subprocess.run([sys.executable, "-m", "flexbooster", "run", str(path)],
                              capture_output=True, text=True, input=piped)
        assert proc.returncode == 2
        assert "Traceback" not in proc.stderr
        assert proc.stderr.startswith("flexbooster: error:")
        assert len(proc.stderr.splitlines()) == 1 and "booster.E = '1 furlong'" in proc.stderr
        errors.append(proc.stderr)
    assert errors[0] == errors[1]


def test_version(capsys):
    assert run_cli(["--version"]) == 0
    assert "0.1.0" in capsys.readouterr().out


@pytest.mark.slow
def test_stability_command(tmp_path, capsys):
    """`flexbooster stability` on a narrow range: its table equals the rows of the full run
    that fall in that range (the same equations on the same shell frequencies)."""
    import csv

    assert (
        run_cli(["stability", "--omega-min", "100", "--omega-max", "20 Hz", "-o", str(tmp_path)])
        == 0
    )
    assert "Unstable thrust frequencies" in capsys.readouterr().out
    rows = list(csv.DictReader((tmp_path / "stability-unstable-frequencies.csv").open()))
    assert rows
    omegas = [float(r["Omega_rad_s"]) for r in rows]
    assert min(omegas) >= 100.0 and max(omegas) <= 40 * 3.141592653589793 + 1e-9


def test_stability_command_bad_range(capsys):
    # the option is named as the option, not as the case field
    assert run_cli(["stability", "--omega-min", "300", "--omega-max", "100"]) == 2
    err = capsys.readouterr().err.strip()
    assert err == ("flexbooster: error: --omega-min = '300': must be smaller than "
                   "--omega-max = 100.0 rad/s")


@pytest.mark.slow
def test_simulate_command(tmp_path, capsys):
    code = run_cli(
        ["simulate", "--omega", "300", "--tau-max", "5", "--n-out", "21", "-o", str(tmp_path)]
    )
    assert code == 0
    names = {p.name for p in tmp_path.iterdir()}
    assert {"time-histories.csv", "simulation.json", "modal-amplitudes.svg"} <= names
    lines = (tmp_path / "time-histories.csv").read_text().splitlines()
    assert len(lines) == 22  # header + n_out rows


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (["--omega", "-5", "--tau-max", "5"], "--omega = '-5'"),  # the option, as typed
        (["--omega", "5 m", "--tau-max", "5"], "wrong dimension"),
        (["--omega", "300", "--tau-max", "0"], "--tau-max = 0.0"),
    ],
)
def test_simulate_bad_input(capsys, args, words):
    assert run_cli(["simulate", *args]) == 2
    err = capsys.readouterr().err
    assert words in err and "Traceback" not in err


def test_format_json_is_results_json(tmp_path, capsys, small_memo_case_file):
    """--format json prints exactly what results.json holds, and nothing else, on stdout."""
    code = run_cli(["run", str(small_memo_case_file), "--format", "json", "--no-figures", "-o",
                    str(tmp_path / "out")])
    assert code == 0
    out, err = capsys.readouterr()
    printed = json.loads(out)  # the whole of stdout is one JSON document
    assert printed == json.loads((tmp_path / "out" / "results.json").read_text())
    assert "wrote" in err and "wrote" not in out


@pytest.mark.slow
def test_quiet_prints_nothing(tmp_path, capsys, small_memo_case_file):
    out = tmp_path / "out"
    assert run_cli(["run", str(small_memo_case_file), "-q", "--no-figures", "-o", str(out)]) == 0
    assert capsys.readouterr() == ("", "")
    assert (out / "report.html").exists()  # the work is still done
    assert run_cli(["stability", str(small_memo_case_file), "-q", "--omega-min", "100",
                    "--omega-max", "150", "-o", str(out)]) == 0
    assert capsys.readouterr() == ("", "")


def test_bad_format_is_a_usage_error(capsys):
    assert run_cli(["run", "--format", "xml"]) == 2
    assert "xml" in capsys.readouterr().err


@pytest.mark.parametrize("argv", [["--help"], ["run", "--help"], ["stability", "--help"],
                                  ["simulate", "--help"], ["init", "--help"]])
def test_help_has_examples_and_exit_codes(capsys, argv):
    assert run_cli(argv) == 0
    out = capsys.readouterr().out
    assert "Example" in out and "flexbooster " in out.split("Example", 1)[1]
    assert "Exit codes" in out and "130" in out


@pytest.mark.slow
def test_progress_reports_every_stage_in_order(small_memo_case_file):
    from flexbooster.analysis import FORCED_STAGE, STAGES, VEHICLE_REGIONS_STAGE, analyze
    from flexbooster.case import load_case

    seen = []
    analyze(load_case(small_memo_case_file), progress=seen.append)
    assert seen == [*STAGES, VEHICLE_REGIONS_STAGE, FORCED_STAGE]  # the vehicle stages last
    seen.clear()
    analyze(load_case(small_memo_case_file), beam_action=False, progress=seen.append,
            vehicle=False)
    assert seen == [*STAGES[:3], STAGES[-1]]  # the skipped stages are not announced


def _bar_text(monkeypatch, tmp_path, memo_case_dict, *options):
    """Run ``flexbooster run`` in-process with its progress bar drawn on a forced terminal;
    return what the bar printed (ANSI codes removed) and the results.json written."""
    import io

    import flexbooster.cli as cli

    buf = io.StringIO()
    real = cli.Console
    monkeypatch.setattr(cli, "Console", lambda stderr=False, **kw: real(
        file=buf, force_terminal=True, width=250) if stderr else real(**kw))
    tmp_path.mkdir()
    path = tmp_path / "small.toml"
    path.write_text(dump_toml(memo_case_dict))
    out = tmp_path / "out"
    assert run_cli(["run", str(path), "--no-figures", "--no-vehicle", "-o", str(out),
                    *options]) == 0
    return (re.sub(r"\x1b\[[0-9;?]*[A-Za-z]", "", buf.getvalue()),
            json.loads((out / "results.json").read_text()))


def test_progress_bar_shows_the_estimate_and_flags_half_the_budget(monkeypatch, tmp_path,
                                                                   memo_case_dict, capsys):
    """The bar shows the run's estimated time (cost.estimate_cost of the stages
    run, computed here independently); over half the budget it says so, and the results have
    the cost-estimate warning."""
    import flexbooster
    from flexbooster.cost import estimate_cost
    from flexbooster.model import model_from_case

    memo_case_dict["truncation"].update(M1=3, N1=3, M2=3, N2=3, N=3, S=2, R=2)
    memo_case_dict["thrust"]["n_omega"] = 40
    seconds = estimate_cost(model_from_case(flexbooster.load_case(memo_case_dict)),
                            figures=False).seconds
    text, data = _bar_text(monkeypatch, tmp_path / "a", memo_case_dict)
    assert f"est. {seconds:.3g} s" in text and "budget" not in text
    assert "cost-estimate" not in {w["code"] for w in data["warnings"]}
    budget = 1.5 * seconds  # the estimate is between half the budget and the budget
    text, data = _bar_text(monkeypatch, tmp_path / "b", memo_case_dict, "--max-seconds",
                           str(budget))
    assert f"est. {seconds:.3g} s of the {budget:g} s budget" in text
    assert "cost-estimate" in {w["code"] for w in data["warnings"]}


@pytest.mark.slow
def test_two_runs_write_byte_identical_files(tmp_path, memo_case_dict, capsys):
    """Determinism: no time stamp in report.html (unless SOURCE_DATE_EPOCH),
    no date in the SVG metadata, fixed SVG ids: two runs of one case give the same bytes."""
    memo_case_dict["truncation"].update(M1=3, N1=3, M2=3, N2=3, N=3, S=2, R=2)
    memo_case_dict["thrust"]["n_omega"] = 40
    path = tmp_path / "small.toml"
    path.write_text(dump_toml(memo_case_dict))
    for out in ("a", "b"):
        assert run_cli(["run", str(path), "-q", "-o", str(tmp_path / out)]) == 0
    names = sorted(p.name for p in (tmp_path / "a").iterdir())
    assert "report.html" in names and "campbell.svg" in names
    for name in names:
        assert (tmp_path / "a" / name).read_bytes() == (tmp_path / "b" / name).read_bytes(), name


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (["run", "--format", "xml"], "Invalid value for '--format'"),
        (["run", "--bogus"], "No such option '--bogus'"),
        (["nosuch"], "No such command 'nosuch'"),
        (["stability", "--omega-min"], "Option '--omega-min' requires an argument"),
    ],
)
def test_usage_errors_are_one_line_exit_2(capsys, args, words):
    assert run_cli(args) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and err.startswith("flexbooster: error: ") and words in err


@pytest.mark.parametrize("sub", ["", "sub"])
def test_output_that_is_a_file_is_refused_before_the_analysis(tmp_path, capsys, sub):
    afile = tmp_path / "afile"
    afile.write_text("x")
    target = afile / sub if sub else afile
    assert run_cli(["run", "-q", "-o", str(target)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and err.count("--output") == 1 and str(target) in err


def _edited_default(tmp_path, old: str, new: str):
    """The memo case file with one line edited (the error cases of test_error_lines)."""
    from flexbooster.case import memo_case_text

    text = memo_case_text()
    assert old in text
    path = tmp_path / "case.toml"
    path.write_text(text.replace(old, new, 1))
    return path


# Expected lines (the value once, the option named as the option, a misspelt
# key with a difflib suggestion, a misspelt table without dumping its contents); exact text.
@pytest.mark.parametrize(
    ("edit", "argv", "line"),
    [
        pytest.param(("radius = ", 'radius = "60 furlongz" #'), ["run", "--no-figures"],
                     "booster.cylinder1.radius = '60 furlongz': unknown unit (furlongz)",
                     id="value-once"),
        pytest.param(None, ["stability", "--omega-min", "abc"],
                     "--omega-min = 'abc': must start with a number, the unit after it (20 mm)",
                     id="option-named"),
        pytest.param(None, ["stability", "--omega-max", "5 m"],
                     "--omega-max = '5 m': wrong dimension: expected units of rad/s",
                     id="option-dimension"),
        pytest.param(("\ngamma", "\ngama"), ["run", "--no-figures"],
                     "thrust.gama: unknown key 'gama' (did you mean 'gamma'?)",
                     id="misspelt-key"),
        pytest.param(("[booster]", "[boster]"), ["run", "--no-figures"],
                     "boster: unknown table 'boster' (did you mean 'booster'?)",
                     id="misspelt-table"),
    ],
)
def test_error_lines(tmp_path, capsys, edit, argv, line):
    case = [] if edit is None else [str(_edited_default(tmp_path, *edit))]
    assert run_cli([argv[0], *case, *argv[1:], "-o", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err.strip()
    assert err == f"flexbooster: error: {line}"


@pytest.mark.slow
def test_stability_never_replaces_half_of_a_run(tmp_path, capsys, small_memo_case_file):
    # `stability -o DIR` writes files of its own, on the case's range: it never replaces the
    # CSV of a run in DIR (the run's results.json would no longer match it)
    from flexbooster.cli import STABILITY_FILES

    out = tmp_path / "out"
    assert run_cli(["run", str(small_memo_case_file), "-q", "--no-figures", "-o", str(out)]) == 0
    before = {p.name: p.read_bytes() for p in out.iterdir()}
    assert run_cli(["stability", str(small_memo_case_file), "-q", "-o", str(out)]) == 0
    after = {p.name: p.read_bytes() for p in out.iterdir()}
    assert {n: after[n] for n in before} == before  # every file of the run untouched
    assert set(after) - set(before) == set(STABILITY_FILES)
    # the default range is the case's: the same table as the run's (same equations, range)
    assert (after["stability-unstable-frequencies.csv"]
            == before["unstable-frequencies.csv"])


@pytest.mark.slow
def test_simulate_time_as_a_quantity_quiet_and_json(tmp_path, capsys):
    # --t-max "T s" is tau_max = omega_1 T (memo 3.0): the same time histories as
    # --tau-max omega_1 T (to the CSV's printed digits); --quiet prints nothing; --format json
    # prints simulation.json and nothing else on standard output
    from flexbooster.case import memo_case
    from flexbooster.model import model_from_case

    omega_1 = model_from_case(memo_case()).omega_1
    base = ["simulate", "--omega", "300", "--n-out", "11"]
    assert run_cli([*base, "--t-max", "40 ms", "-q", "-o", str(tmp_path / "a")]) == 0
    assert capsys.readouterr() == ("", "")
    assert run_cli([*base, "--tau-max", repr(0.04 * omega_1), "--format", "json",
                    "-o", str(tmp_path / "b")]) == 0
    out, err = capsys.readouterr()
    assert json.loads(out) == json.loads((tmp_path / "b" / "simulation.json").read_text())
    assert "wrote" in err
    a = (tmp_path / "a" / "time-histories.csv").read_text()
    b = (tmp_path / "b" / "time-histories.csv").read_text()
    assert a == b


@pytest.mark.parametrize(
    ("extra", "line"),
    [
        pytest.param([], "--t-max/--tau-max = 'neither': give exactly one: --t-max \"2 s\" "
                     "(a time) or --tau-max 50 (tau = omega_1 t)", id="neither"),
        pytest.param(["--t-max", "2 m"], "--t-max = '2 m': wrong dimension: expected units "
                     "of s", id="t-max-dimension"),
        pytest.param(["--t-max", "-1"], "--t-max = '-1': must be a positive time (s if no "
                     "unit)", id="t-max-negative"),
    ],
)
def test_simulate_time_errors(capsys, extra, line):
    # expected lines: time as a quantity, the option named
    assert run_cli(["simulate", "--omega", "300", *extra]) == 2
    assert capsys.readouterr().err.strip() == f"flexbooster: error: {line}"


@pytest.mark.slow
def test_simulate_prints_a_verdict_per_mode(tmp_path, capsys):
    assert run_cli(["simulate", "--omega", "300", "--tau-max", "5", "--n-out", "21",
                    "-o", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    assert "modal coordinates growing over the window" in out
    assert re.search(r"cylinder \d (axial|circumferential|radial) [UVW], j = \d+, k = \d+: "
                     r"(growing|bounded) \(peak ", out)


_BLAS_PROBE = """
import os, sys
from flexbooster import cli
try:
    cli.main(["--version"])
except SystemExit:
    pass
import numpy, threadpoolctl
blas = [i["num_threads"] for i in threadpoolctl.threadpool_info() if i["user_api"] == "blas"]
print(max(blas), os.environ.get("OPENBLAS_NUM_THREADS"), os.environ.get("MKL_NUM_THREADS"))
"""


@pytest.mark.parametrize("user, expected", [
    ({}, ["1", "1", "1"]),  # none chosen: one BLAS thread, set before numpy loads its BLAS
    ({"OPENBLAS_NUM_THREADS": "3"}, [None, "3", "None"]),  # the user's choice stands, no other
])
def test_the_command_runs_one_blas_thread_unless_the_user_chose(user, expected):
    """The command's process sets one BLAS thread before numpy loads (the reference: the
    BLAS library's own count, threadpoolctl), unless a thread variable is set."""
    import os

    env = {k: v for k, v in os.environ.items()
           if k not in ("OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "OMP_NUM_THREADS")}
    done = subprocess.run([sys.executable, "-c", _BLAS_PROBE], env={**env, **user},
                          capture_output=True, text=True, timeout=120, check=True)
    threads, *variables = done.stdout.split("\n")[-2].split()
    assert variables == expected[1:]
    if expected[0] is not None:  # (the user's count: OpenBLAS caps it at the CPUs)
        assert threads == expected[0]


@pytest.mark.slow
def test_short_summary_by_default(tmp_path, capsys, small_memo_case_file, monkeypatch):
    """flexbooster run: the overall verdict on line 1, the damping stated, no input
    table (those with --full), one line for the files and "open OUT/report.html" last; piped
    at COLUMNS=80 no line is wider than 80 columns and no cell is cut."""
    monkeypatch.setenv("COLUMNS", "80")
    out = tmp_path / "out"
    assert run_cli(["run", str(small_memo_case_file), "--no-figures", "-o", str(out)]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[0].split(":")[0] in ("UNSTABLE", "MARGINAL", "STABLE")
    assert any(line.startswith("damping: ") for line in lines[:8])
    assert not any(line.startswith("Input (SI)") for line in lines)
    assert lines[-2].startswith("wrote ") and lines[-1] == f"open {out / 'report.html'}"
    assert max(len(line) for line in lines[:-2]) <= 80  # the two path lines: as long as OUT
    assert "\u2026" not in "".join(lines)


def test_a_fault_of_the_summary_loses_no_result(tmp_path, capsys, monkeypatch,
                                                small_memo_case_file):
    """The summary is printed once the files are published: an error in it (a bug) is an
    internal error (exit 1, one line) and the set stays whole."""
    import flexbooster.present.summary as summary

    def broken(results, console, **options):  # options: full (run --full)
        raise RuntimeError("summary fault")

    monkeypatch.setattr(summary, "print_summary", broken)
    out = tmp_path / "out"
    assert run_cli(["run", str(small_memo_case_file), "--no-figures", "-o", str(out)]) == 1
    err = capsys.readouterr().err
    assert "internal error: RuntimeError: summary fault" in err
    assert json.loads((out / "results.json").read_text())["stability"]["count"] > 0
    assert (out / "manifest.json").exists()


def test_stability_names_the_files_it_writes(tmp_path, capsys, small_memo_case_file):
    """Source: the files in the output folder after ``flexbooster stability`` (it writes
    neither unstable-frequencies.csv nor resonance-bands.csv): every .csv name the summary
    prints exists there."""
    import re

    out = tmp_path / "out"
    assert run_cli(["stability", str(small_memo_case_file), "-o", str(out)]) == 0
    text = " ".join(capsys.readouterr().out.split())
    named = set(re.findall(r"[\w.-]+\.csv", text))
    assert "stability-unstable-frequencies.csv" in named
    assert named <= {p.name for p in out.iterdir()}, named


@pytest.mark.slow
def test_simulate_lists_the_10_largest_in_10_lines(tmp_path, capsys, small_memo_case_file):
    """Source: the header "the N largest": exactly min(10, relevant) indented rows follow it,
    no more."""
    out = tmp_path / "sim"
    assert run_cli(["simulate", str(small_memo_case_file), "--omega", "300", "--tau-max", "50",
                    "-o", str(out)]) == 0
    lines = capsys.readouterr().out.splitlines()
    (head,) = [i for i, x in enumerate(lines) if x.endswith("largest:")]
    n = int(lines[head].split("the ")[-1].split()[0])
    rows = [x for x in lines[head + 1:] if x.startswith("  ")]
    assert n == 10 and len(rows) == 10


def test_simulate_inside_a_beam_action_band_is_refused(tmp_path, capsys, small_memo_case_file):
    """Source: the small case's beam-action band 114.6729..114.6843 rad/s (growth 2.8e-3 1/s,
    beam_action_bands): alpha_1 is complex there, the motion grows and the bounded Floquet
    form cannot show it (its real part would show the motion bounded). One
    line naming --omega, exit 2."""
    assert run_cli(["simulate", str(small_memo_case_file), "--omega", "114.678", "--tau-max", "50",
                    "-o", str(tmp_path / "sim")]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and err.startswith("flexbooster: error: --omega = ")
    assert "instability band" in err and "grows" in err
