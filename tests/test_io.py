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
