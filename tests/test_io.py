"""Atomic writes: an interrupted write leaves the old file (or none), never half a file."""

from __future__ import annotations

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


def test_csv_by_columns_is_the_csv_by_rows(tmp_path):
    # the reference: the literal CSV (RFC 4180 quoting of a comma and a quote), by rows
    rows = [{"j": 1, "hz": 2.5, "s": "a,b"}, {"j": 2, "hz": 1e-300, "s": 'say "x"'}]
    by_rows = fio.write_csv_atomic(tmp_path / "rows.csv", rows).read_text()
    columns = {name: [row[name] for row in rows] for name in rows[0]}
    assert by_rows == 'j,hz,s\n1,2.5,"a,b"\n2,1e-300,"say ""x"""\n'
    assert fio.write_csv_atomic(tmp_path / "columns.csv", columns).read_text() == by_rows


def test_a_nan_in_the_stability_table_is_named_and_nothing_is_published(tmp_path):
    """A NaN in a result is refused with its path in results.json (the walk of check_finite)
    and no file of the set is published."""
    import dataclasses

    from flexbooster import analysis
    from flexbooster.case import load_case, memo_case
    from flexbooster.present.outputs import write_outputs

    data = memo_case().model_dump(exclude_none=True)
    data["thrust"]["n_omega"] = 40
    data["truncation"].update(M1=6, N1=6, M2=6, N2=6, N=4, S=4, R=3)
    results = analysis.analyze(load_case(data), figures=False, vehicle=False)
    severity = results.stability.severity.copy()
    severity[3] = np.nan
    bad = dataclasses.replace(
        results, stability=dataclasses.replace(results.stability, severity=severity))
    out = tmp_path / "out"
    with pytest.raises(ValueError, match=r"results\.stability\.table\.severity\[3\] = nan"):
        write_outputs(bad, out, figures=False)
    assert list(out.iterdir()) == []
