"""300 bad inputs of every kind through the command line: each one line on stderr, exit 2,
naming the field (or option, or path), the value as written and the rule; none accepted.

The kinds (a review's list of what pint and the file system would take other than as meant):
a decimal comma, a unit before the number, an invisible or non-standard space character, a
unit without a number, a wrong dimension, an unknown unit, a non-finite or overflowing number
(E = 1.7e308, 1e400 written out), a number outside its field's range, a wrong type (boolean,
list, table, empty string); a case file that is not a readable TOML file (symlink loop, FIFO,
device, folder, missing, binary, bad syntax, a UTF-8 BOM before bad syntax); outputs that
cannot be written (an empty name, /proc, a results.json that is a folder, a folder under a
file). Each is applied to fields of the memo case (``[booster]``) and of the default case
(``[[vehicle.segments]]``, masses, tanks, ``[flight]``), so every table is reached.

Source of every expectation: the rules of ``flexbooster/case.py`` and ``flexbooster/units.py``
(each field's documented range) and the exit codes of ``flexbooster --help`` (2: bad input).
"""

from __future__ import annotations

import copy
import itertools
import os
import tomllib
from pathlib import Path

import numpy as np
import pytest

from conftest import dump_toml, run_cli
from flexbooster.case import default_case_text, memo_case_text

#: 300 command-line runs (about 9 s on one core): the whole suite, not the edit loop
pytestmark = pytest.mark.slow

#: Positive dimensional fields (dotted path into the case; a number in a list is its index).
POSITIVE = {
    "memo": ["booster.cylinder1.radius", "booster.cylinder2.half_length", "booster.thickness",
             "booster.E", "booster.rho", "thrust.F0", "thrust.omega_min", "thrust.omega_max",
             "thrust.duration"],
    "default": ["vehicle.E", "vehicle.rho", "vehicle.segments.0.radius",
                "vehicle.segments.1.length", "vehicle.segments.2.thickness",
                "vehicle.segments.0.rings.spacing", "vehicle.segments.2.stringers.area",
                "vehicle.masses.2.mass", "vehicle.tanks.1.density", "flight.duration",
                "flight.points.1.F0", "thrust.F0"],
}
#: Fractions and ratios: a number in [0, 1) or (0, 0.5) (gamma, nu, fills, damping ratios).
FRACTIONS = {
    "memo": ["thrust.gamma", "booster.nu", "damping.modal_ratio", "damping.pitch_ratio"],
    "default": ["vehicle.nu", "vehicle.tanks.0.fill", "flight.points.0.gamma",
                "damping.modal_ratio"],
}
#: Values no positive dimensional field accepts, by kind (the unit where one is needed).
BAD_QUANTITIES = [
    ("comma", "5,05 m"), ("comma", "1,5e6 Pa"), ("comma", "2,0"),
    ("unit-first", "m 5"), ("unit-first", "mm 20"), ("unit-first", "Pa 7e10"),
    ("invisible", "5\u200b m"), ("invisible", "5\u2060m"), ("invisible", "5\u00a0m"),
    ("invisible", "\ufeff5 m"), ("invisible", "5 m\u200e"), ("invisible", "5\u202fm"),
    ("invisible", "5\u00ad m"), ("invisible", "5\tm\x00"),
    ("no-number", "m"), ("no-number", "psi"), ("no-number", "kg/m^3"), ("no-number", " "),
    ("no-number", ""), ("no-number", "e5 m"),
    ("unknown-unit", "5 furlongz"), ("unknown-unit", "5 m m m x"),
    ("non-finite", "nan"), ("non-finite", "inf m"), ("non-finite", float("nan")),
    ("non-finite", float("inf")), ("overflow", 1.7e308), ("overflow", "1e400"),
    ("overflow", 10**400), ("range", -1.0), ("range", "-5 m"), ("range", 1e-300),
    ("type", True), ("type", [5.0]), ("type", {"value": 5.0}),
]
#: Values no fraction accepts (gamma, nu, fill, damping ratios: at most [0, 1]).
BAD_FRACTIONS = [
    ("comma", "0,5"), ("invisible", "0.5\u200b"), ("unit-first", "% 5"), ("range", 1.5),
    ("range", -0.1), ("non-finite", float("nan")), ("wrong-dimension", "0.5 m"),
    ("type", "half"), ("type", True),
]


def _cases() -> list[tuple[str, str, str, object]]:
    """(base case, field, kind, bad value): every positive field with every bad quantity,
    every fraction with every bad fraction."""
    out = [(base, field, kind, value) for base, fields in POSITIVE.items() for field in fields
           for kind, value in BAD_QUANTITIES]
    out += [(base, field, kind, value) for base, fields in FRACTIONS.items() for field in fields
            for kind, value in BAD_FRACTIONS]
    return out


_ALL = _cases()
#: 282 of the field probes, drawn once with a fixed seed (every field and every kind kept: the
#: last test checks), and the 18 file and output probes below: 300.
FIELD_CASES = [_ALL[i] for i in sorted(
    np.random.default_rng(36).choice(len(_ALL), 300 - 18, replace=False))]


def _set(data: dict, dotted: str, value: object) -> None:
    keys = [int(k) if k.isdigit() else k for k in dotted.split(".")]
    for key in keys[:-1]:
        data = data[key]
    data[keys[-1]] = value


def _named(dotted: str) -> str:
    """The field's name in a message: ``vehicle.segments[0].radius``."""
    return ".".join(f"[{k}]" if k.isdigit() else k for k in dotted.split(".")).replace(".[", "[")


_BASES = {"memo": tomllib.loads(memo_case_text()), "default": tomllib.loads(default_case_text())}


def _check_one_line(capsys, code: int, *words: str) -> str:
    err = capsys.readouterr().err
    assert code == 2, err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("flexbooster: error: "), err
    for word in words:
        assert word in lines[0], (word, lines[0])
    return lines[0]


@pytest.mark.parametrize(("base", "field", "kind", "value"), FIELD_CASES,
                         ids=[f"{i}-{b}-{f}-{k}" for i, (b, f, k, _) in enumerate(FIELD_CASES)])
def test_bad_field_is_one_line_exit_2_naming_field_value_rule(tmp_path, capsys, base, field,
                                                              kind, value):
    """Source: the field's rule (case.py, units.py): refused before any solver."""
    data = copy.deepcopy(_BASES[base])
    _set(data, field, value)
    path = tmp_path / "bad.toml"
    path.write_text(dump_toml(data))
    code = run_cli(["run", str(path), "-q", "--no-figures", "-o", str(tmp_path / "o")])
    words = [_named(field) + " = "] + ([repr(value)] if isinstance(value, str) else [])
    line = _check_one_line(capsys, code, *words)
    rule = line.split(" = ", 1)[1]
    assert ": " in rule and rule.split(": ", 1)[1].strip(), line  # value, then its rule
    assert not (tmp_path / "o").exists()  # refused before any output


# --------------------------------------------------------------------------------------------
# Case files and outputs
# --------------------------------------------------------------------------------------------
def _file(folder: Path, kind: str) -> Path:
    path = folder / f"{kind}.toml"
    memo = memo_case_text()
    if kind == "symlink-loop":
        path.symlink_to(folder / "other.toml")
        (folder / "other.toml").symlink_to(path)
    elif kind == "dangling-symlink":
        path.symlink_to(folder / "nowhere.toml")
    elif kind == "fifo":
        os.mkfifo(path)
    elif kind == "device":
        path = Path("/dev/zero")
    elif kind == "folder":
        path.mkdir()
    elif kind == "binary":
        path.write_bytes(b"\xff\xfe\x00 not text")
    elif kind == "syntax":
        path.write_text(memo.replace("[thrust]", "[thrust", 1))
    elif kind == "bom-syntax":
        path.write_bytes(b"\xef\xbb\xbf" + memo.replace("[thrust]", "[thrust", 1).encode())
    elif kind == "unknown-table":
        path.write_text(memo + "\n[boostr]\nx = 1\n")
    elif kind == "latin-1":
        path.write_bytes(memo.replace("memo case", "m\u00e9mo case").encode("latin-1"))
    return path


FILE_PROBES = ["symlink-loop", "dangling-symlink", "fifo", "device", "folder", "binary",
               "syntax", "bom-syntax", "unknown-table", "latin-1"]


@pytest.mark.parametrize("kind", FILE_PROBES)
def test_case_file_probe_is_one_line_exit_2(tmp_path, capsys, alarm, kind):
    """Source: POSIX (ELOOP, ENOENT, a FIFO blocks on open, a device never ends), TOML 1.0
    (UTF-8, its syntax); the alarm fixture turns a block into a failure."""
    path = _file(tmp_path, kind)
    code = run_cli(["run", str(path), "-q", "--no-figures", "-o", str(tmp_path / "o")])
    word = "boostr" if kind == "unknown-table" else str(path)
    _check_one_line(capsys, code, word)


def _outputs(folder: Path) -> dict[str, str]:
    (folder / "afile").write_text("x")
    (folder / "dirres" / "results.json").mkdir(parents=True)
    (folder / "csvdir" / "report.html").mkdir(parents=True)
    return {"empty": "", "proc": "/proc/x", "under-a-file": str(folder / "afile" / "sub"),
            "a-file": str(folder / "afile"), "results-a-folder": str(folder / "dirres"),
            "sys": "/sys/x", "csv-a-folder": str(folder / "csvdir"),
            "dev-null": "/dev/null"}


@pytest.mark.parametrize("kind", ["empty", "proc", "under-a-file", "a-file",
                                  "results-a-folder", "sys", "csv-a-folder", "dev-null"])
def test_unwritable_output_is_one_line_exit_2_before_the_analysis(tmp_path, capsys, kind,
                                                                   small_memo_case_file):
    """Source: POSIX (no folder in /proc or /sys, none under a file): refused before the
    analysis starts, naming --output and the path."""
    target = _outputs(tmp_path)[kind]
    code = run_cli(["run", str(small_memo_case_file), "-q", "--no-figures",
                    "--max-seconds", "1e-9", "-o", target])
    line = _check_one_line(capsys, code, "--output")
    assert "max_seconds" not in line  # the output checked before the case's budget


def test_the_bulk_table_has_300_probes():
    """Acceptance "300 bad inputs of every kind": the field probes, the case-file probes and
    the output probes, each a parametrized test above."""
    assert len(FIELD_CASES) + len(FILE_PROBES) + 8 == 300
    assert {k for _, _, k, _ in FIELD_CASES} == {k for k, _ in BAD_QUANTITIES + BAD_FRACTIONS}
    assert len({(b, f) for b, f, _, _ in FIELD_CASES}) == len(
        list(itertools.chain(*POSITIVE.values(), *FRACTIONS.values())))  # every field drawn
