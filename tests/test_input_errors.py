"""Bad input: one line, exit 2, the field named once; loads beyond the structure are case errors.

Source of the buckling load: 2 pi E h^2 / sqrt(3 (1 - nu^2)) (Timoshenko & Gere 1961,
eq. 11-17).
"""

from __future__ import annotations

import math
import os
from pathlib import Path

import pytest

import flexbooster
from conftest import case_with, dump_toml, run_cli
from flexbooster import cost
from flexbooster.analysis import analyze
from flexbooster.case import memo_case_text
from flexbooster.errors import CaseError
from flexbooster.model import model_from_case
from test_case import BAD_INPUTS, _set

nan, inf = math.nan, math.inf
SRC = str(Path(flexbooster.__file__).parents[1])


# --------------------------------------------------------------------------------------------
@pytest.mark.parametrize(("F0", "word"), [(1e12, "flutter"), (1e10, "divergence")],
                         ids=["F0=1e12-flutter", "F0=1e10-divergence"])
def test_load_beyond_the_structure_is_a_case_error(memo_case_dict, F0, word):
    """Source: the eigenvalues of the steady system Lambda + B (complex at 1e12 N, negative
    at 1e10 N for the default booster): a CaseError naming thrust.F0, not a LinAlgError."""
    with pytest.raises(CaseError) as info:
        analyze(case_with(memo_case_dict, thrust__F0=F0), figures=False)
    assert info.value.field == "thrust.F0" and word in str(info.value)


def test_shell_buckling_is_a_named_warning(memo_case_dict):
    """Source: 2 pi E h^2 / sqrt(3 (1 - nu^2)) (Timoshenko & Gere 11-17), exact formula."""
    model = model_from_case(case_with(memo_case_dict))
    f_cr = 2 * math.pi * model.E * model.h**2 / math.sqrt(3 * (1 - model.nu**2))
    assert cost.physical_warnings(model) == []
    above = model_from_case(case_with(memo_case_dict, thrust__F0=1.01 * f_cr))
    assert [w.code for w in cost.physical_warnings(above)] == ["shell-buckling"]


# --------------------------------------------------------------------------------------------
# The bad-input CLI table (74 probes, each exit 2, one line, the field named once)
# --------------------------------------------------------------------------------------------
#: Extra probes of a review's list (the rest is tests/test_case.py's table).
EXTRA_PROBES = [
    ("booster.cylinder1.radius", 1e300, "booster"),  # once an OverflowError
    ("booster.thickness", 1e-300, "booster.thickness"),  # units.MAGNITUDE_RANGE
    ("booster.rho", 1e-300, "booster.rho"),  # omega_1 overflows: units.MAGNITUDE_RANGE
    ("thrust.F0", 1e300, "thrust.F0"),
    ("thrust.F0", 1e12, "thrust.F0"),
    ("thrust.K", 1e300, "thrust.F0"),  # dimensionless: no magnitude range, the load check
    ("thrust.n_omega", 10**400, "thrust.n_omega"),  # a 400-digit integer literal
    ("thrust.gamma", nan, "thrust.gamma"),
    ("thrust.omega_max", inf, "thrust.omega_max"),
    ("booster.E", "1e999 Pa", "booster.E"),
    ("max_seconds", -1.0, "max_seconds"),
    ("max_seconds", 1e-9, "max_seconds"),
]
_PROBES = [(p, v, f) for p, v, f, _ in BAD_INPUTS] + EXTRA_PROBES


@pytest.mark.parametrize(("path", "value", "field"), _PROBES,
                         ids=[f"{p}={'<deleted>' if type(v) is object else repr(v)}"[:40]
                              for p, v, _ in _PROBES])  # stable ids (pytest-xdist collects twice)
def test_bad_case_probe_exit_2_one_line(memo_case_dict, tmp_path, capsys, path, value, field):
    _set(memo_case_dict, path, value)
    case = tmp_path / "bad.toml"
    case.write_text(dump_toml(memo_case_dict))
    assert run_cli(["run", str(case), "-q", "--no-figures", "-o", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and err.startswith("flexbooster: error: ")
    assert err.count(field) >= 1
    head = err.removeprefix("flexbooster: error: ").split(" = ")[0]
    assert err.count(head + " ") + err.count(head + ":") <= 2  # the field once (plus rule)


#: Bad values that a unit parser reads silently wrong or that overflow in a solver: (path,
#: value, the rule's words). Source of each "silently wrong" reading: pint 0.24 ("5,05 m" -> 505 m,
#: "mm 20" -> 0.02 m, "5\u200b m" -> 5 m, "psi" -> 1 psi).
BAD_VALUE_PROBES = [
    ("booster.cylinder2.radius", "5,05 m", "comma"),
    ("booster.cylinder2.radius", "mm 20", "must start with a number"),
    ("booster.cylinder2.radius", "5\u200b m", "invisible"),
    ("booster.E", "psi", "must start with a number"),
    ("booster.E", 1.7e308, "magnitude"),  # was 7 lines: RuntimeWarning, internal error
    ("booster.E", 1e80, "magnitude"),  # was an overflow in the Floquet step count
    ("booster.rho", "1e-300 kg/m^3", "magnitude"),
]


@pytest.mark.parametrize(("path", "value", "rule"), BAD_VALUE_PROBES,
                         ids=[f"{p}={v!r}" for p, v, _ in BAD_VALUE_PROBES])
def test_bad_value_is_one_line_naming_field_value_rule(memo_case_dict, tmp_path, capsys,
                                                               path, value, rule):
    """Source: the list above; each refused before any solver (exit 2, one line, no
    RuntimeWarning) with the field, the value as written and the rule."""
    _set(memo_case_dict, path, value)
    case = tmp_path / "bad.toml"
    case.write_text(dump_toml(memo_case_dict))
    assert run_cli(["run", str(case), "-q", "--no-figures", "-o", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1, err
    assert err.startswith(f"flexbooster: error: {path} = {value!r}: ") and rule in err


CLI_PROBES = [
    (["run", "--format", "xml"], "--format"),
    (["run", "--bogus"], "--bogus"),
    (["run", "--max-seconds", "abc"], "--max-seconds"),
    (["run", "--max-seconds", "nan"], "--max-seconds"),
    (["stability", "--omega-min", "3000"], "--omega-min"),  # above the case's omega_max
    (["modes", "--k-max", "999"], "--k-max"),
    (["modes", "--f-max", "-3"], "--f-max"),
    # the rest of the command-line probes ({tmp}: a folder with the files of _probe_files)
    (["nosuch"], "nosuch"),
    (["--bogus"], "--bogus"),
    (["stability", "--omega-min"], "--omega-min"),  # an option without its argument
    (["run", "--format"], "--format"),
    (["run", "--jobs", "2"], "--jobs"),  # no such option: one line, exit 2
    (["run", "--max-seconds", "inf"], "--max-seconds"),
    (["run", "--max-seconds", "-1"], "--max-seconds"),
    (["run", "{tmp}/nonexistent.toml"], "case file"),
    (["run", "{tmp}/badsyntax.toml"], "case file"),
    (["run", "{tmp}/binary.toml"], "case file"),
    (["run", "{tmp}/empty.toml"], "booster ="),
    (["stability", "--omega-max", "5 kg"], "--omega-max"),
    (["stability", "--omega-min", "-5"], "--omega-min"),
    (["simulate"], "--omega"),
    (["simulate", "--omega", "-1", "--tau-max", "10"], "--omega"),
    (["simulate", "--omega", "300"], "--t-max/--tau-max"),
    (["simulate", "--omega", "300", "--t-max", "-1"], "--t-max"),
    (["simulate", "--omega", "300", "--tau-max", "nan"], "--tau-max"),
    (["simulate", "--omega", "300", "--tau-max", "10", "--n-out", "1"], "--n-out"),
    (["modes", "--k-max", "abc"], "--k-max"),
    (["init", "{tmp}/existing"], "PATH"),
    (["run", "-o", "{tmp}/afile"], "--output"),
]


def _probe_files(folder: Path) -> None:
    (folder / "badsyntax.toml").write_text('name = "x"\n[thrust\n')
    (folder / "binary.toml").write_bytes(b"\xff\xfe\x00 not text")
    (folder / "empty.toml").write_text("")
    (folder / "existing").write_text("x")
    (folder / "afile").write_text("x")


@pytest.mark.parametrize(("argv", "field"), CLI_PROBES, ids=[" ".join(a) for a, _ in CLI_PROBES])
def test_bad_option_probe_exit_2_one_line(capsys, tmp_path, argv, field):
    _probe_files(tmp_path)
    assert run_cli([a.replace("{tmp}", str(tmp_path)) for a in argv]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and err.startswith("flexbooster: error: ")
    assert err.count(field) == 1, err


def test_the_bad_input_table_has_its_74_probes():
    """Acceptance "74/74 one line, exit 2, field named once": the case-field probes
    (test_case.BAD_INPUTS and EXTRA_PROBES), the command-line probes (CLI_PROBES) and the two
    paths of test_directory_as_case_file_and_file_as_output, each a parametrized test."""
    assert len(_PROBES) + len(CLI_PROBES) + 2 == 74


def test_directory_as_case_file_and_file_as_output(tmp_path, capsys):
    afile = tmp_path / "afile"
    afile.write_text("x")
    for argv in (["run", str(tmp_path)], ["run", "-o", str(afile / "sub")]):
        assert run_cli(argv) == 2
        assert len(capsys.readouterr().err.strip().splitlines()) == 1




# --------------------------------------------------------------------------------------------
# Case files that are not plain files: one line, exit 2, never a block
# --------------------------------------------------------------------------------------------
def _special_case_file(folder: Path, kind: str) -> Path:
    path = folder / f"{kind}.toml"
    if kind == "symlink-loop":
        path.symlink_to(folder / "other.toml")
        (folder / "other.toml").symlink_to(path)
    elif kind == "fifo":
        os.mkfifo(path)
    elif kind == "device":
        path = Path("/dev/zero")
    return path


@pytest.mark.parametrize("kind", ["symlink-loop", "fifo", "device"])
def test_case_file_that_is_not_a_regular_file_is_refused(tmp_path, capsys, alarm, kind):
    """Source: POSIX (open() of a FIFO blocks until a writer; a symlink loop is ELOOP): the path
    is refused before it is opened, exit 2, one line naming the case file (the alarm fixture
    turns a block into a failure)."""
    path = _special_case_file(tmp_path, kind)
    assert run_cli(["run", str(path), "-q", "-o", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and err.startswith("flexbooster: error: case file = ")
    assert str(path) in err


def test_case_file_with_a_utf8_byte_order_mark_is_read(tmp_path):
    """Source: the Unicode standard (U+FEFF at the start of a UTF-8 file is a signature, not
    content): the same case as without the mark, field for field."""
    text = memo_case_text()
    path = tmp_path / "bom.toml"
    path.write_bytes(b"\xef\xbb\xbf" + text.encode("utf-8"))
    assert flexbooster.load_case(path) == flexbooster.memo_case()


@pytest.mark.parametrize("source", [42, None, 3.5, b"case.toml"])
def test_load_case_of_a_wrong_type_is_a_type_error_naming_source(source):
    """Source: the signature (a path or a mapping): TypeError naming ``source``."""
    with pytest.raises(TypeError, match=r"^source = "):
        flexbooster.load_case(source)
