"""Atomic writes: an interrupted write leaves the old file (or none), never half a file."""

from __future__ import annotations

import json
import os

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
