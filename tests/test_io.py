"""Atomic writes: an interrupted write leaves the old file (or none), never half a file."""

from __future__ import annotations

import csv
import io
import json
import os

import numpy as np
import pytest

from flexbooster.present import io as fio


def test_interrupted_write_leaves_previous_file(tmp_path, monkeypatch):
    target = tmp_path / "results.json"
    fio.write_json_atomic(target, {"old": 1.0})

    def interrupted(src, dst):
        raise KeyboardInterrupt

    monkeypatch.setattr(os, "replace", interrupted)
    with pytest.raises(KeyboardInterrupt):
        fio.write_json_atomic(target, {"new": list(range(100_000))})
    assert json.loads(target.read_text()) == {"old": 1.0}
    assert [p.name for p in tmp_path.iterdir()] == ["results.json"]  # temporary file removed


def test_interrupted_first_write_leaves_nothing(tmp_path, monkeypatch):
    monkeypatch.setattr(os, "fsync", lambda fd: (_ for _ in ()).throw(KeyboardInterrupt()))
    with pytest.raises(KeyboardInterrupt):
        fio.write_text_atomic(tmp_path / "a.txt", "x" * 10_000)
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("bad", [float("nan"), float("inf"), -float("inf")])
def test_nan_never_reaches_results(tmp_path, bad):
    with pytest.raises(ValueError, match=r"results\.pitch\.a\[1\]"):
        fio.write_json_atomic(tmp_path / "r.json", {"pitch": {"a": [0.5, bad]}})
    assert not (tmp_path / "r.json").exists()


def test_csv(tmp_path):
    path = fio.write_csv_atomic(tmp_path / "t.csv", [{"j": 1, "hz": 2.5}, {"j": 2, "hz": 3.5}])
    assert path.read_text() == "j,hz\n1,2.5\n2,3.5\n"


def _repeated_table(n=5000, seed=3):
    """Columns as a stability table holds them: distinct floats, floats with a few hundred
    values (signed zeros among them), ints, strings."""
    rng = np.random.default_rng(seed)
    shell = rng.normal(size=200) * 10.0 ** rng.integers(-8, 8, 200)
    shell[:3] = [0.0, -0.0, 1e-300]
    pick = rng.integers(0, shell.size, n)
    return {"Omega": rng.uniform(1.0, 2000.0, n).tolist(),
            "shell": shell[pick].tolist(),
            "severity": np.where(rng.random(n) < 0.9, 0.0, rng.random(n)).tolist(),
            "j": pick.tolist(),
            "forcing": np.where(pick % 2 == 0, "active", "listed").tolist()}


def test_results_json_is_json_dumps_text():
    # dumps_finite formats each distinct value of a long list of repeated floats once: the
    # text must be json.dumps's own, byte for byte (the reference: the standard library)
    data = {"stability": {"count": 5000, "table": _repeated_table()},
            "nested": [{"a": [1.5, 2.5]}, [0.1] * 2000], "flag": True, "none": None,
            "zeros": [0.0, -0.0] * 1000, "ints": list(range(3000)) + [2 ** 70]}
    expected = json.dumps(data, allow_nan=False, separators=(",", ":"))
    assert fio.dumps_finite(data, separators=(",", ":")) == expected


@pytest.mark.parametrize("bad", [float("nan"), float("inf")])
def test_nan_in_a_long_repeated_column_is_refused_with_its_path(bad):
    table = _repeated_table()
    table["shell"][4321] = bad
    with pytest.raises(ValueError, match=r"results\.table\.shell\[4321\]"):
        fio.dumps_finite({"table": table}, separators=(",", ":"))


def test_csv_text_is_csv_module_text_and_slices_join_to_the_whole():
    # the reference: csv.writer on the values themselves (repr of each float)
    table = _repeated_table()
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(list(table))
    writer.writerows(zip(*table.values(), strict=True))
    whole = fio.csv_text(table)
    assert whole == buffer.getvalue()
    cuts = [0, 1700, 3900, 5000]  # the rows in three slices, the header with the first
    parts = [fio.csv_text({k: v[lo:hi] for k, v in table.items()}, header=lo == 0)
             for lo, hi in zip(cuts[:-1], cuts[1:], strict=True)]
    assert "".join(parts) == whole


def _reference_csv(table, header=True):
    """The reference CSV text: csv.writer on the values themselves (standard library)."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    if header:
        writer.writerow(list(table))
    writer.writerows(zip(*table.values(), strict=True))
    return buffer.getvalue()


#: Strings that csv quotes (a comma, a quote, line breaks) or json escapes (a quote, a
#: backslash, non-ASCII, control characters), and the empty string.
_AWKWARD = ["a,b", 'say "x"', "", "two\nlines", "cr\r\nlf", "ünïcode", "back\\slash", "\t tab",
            " lead", "plain"]


@pytest.mark.parametrize("table", [
    _repeated_table(),
    {**_repeated_table(n=1300), "awkward": (_AWKWARD * 130)},
    {"x": [0.5, -0.0, 1e-300, 2.0 ** 70], "n": [3, -4, 2 ** 70, 0], "s": _AWKWARD[:4]},
    # mixed and other types: the encoders format them (the same path as before)
    {"mixed": [1, 2.5, "x", None], "flag": [True, False, True, None]},
    {"only": ["", "x", "a,b"]},  # one column: csv quotes an empty field there
    {"empty": [], "also": []},
], ids=["stability-like", "awkward-strings", "short", "mixed", "one-column", "no-rows"])
def test_table_texts_are_the_csv_and_json_texts_and_slices_join(table):
    # the references: csv.writer on the values and json.dumps of each column
    texts = fio.table_texts(table)
    assert texts.csv == _reference_csv(table) == fio.csv_text(table)
    for name, column in table.items():
        assert f"[{texts.json_items[name]}]" == json.dumps(column, separators=(",", ":"))
    n = len(next(iter(table.values())))
    cuts = sorted({0, min(1, n), n // 3, n // 2, n})
    parts = [fio.table_texts({k: v[lo:hi] for k, v in table.items()}, header=lo == 0)
             for lo, hi in zip(cuts[:-1], cuts[1:], strict=True)] or [texts]
    assert fio.TableTexts.join(parts) == texts


@pytest.mark.parametrize("bad", [float("nan"), float("inf")])
def test_table_texts_refuse_what_json_refuses_and_csv_text_writes_it(bad):
    table = _repeated_table()
    table["Omega"][17] = bad
    with pytest.raises(ValueError, match="not JSON compliant"):
        fio.table_texts(table)
    assert fio.csv_text(table) == _reference_csv(table)  # csv writes 'nan' / 'inf' as it is


def test_json_text_is_written_as_it_is():
    # the reference: json.dumps of the same document with the values themselves
    column = [0.1, 2.0, -3.5]
    document = {"a": {"table": {"x": fio.JSONText(json.dumps(column, separators=(",", ":")))}},
                "b": [1.5] * 3}
    expected = json.dumps({"a": {"table": {"x": column}}, "b": [1.5] * 3},
                          separators=(",", ":"))
    assert fio.dumps_finite(document, separators=(",", ":")) == expected
