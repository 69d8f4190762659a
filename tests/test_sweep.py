"""Design sweeps (flexbooster.sweep): parsing, validation, Dask execution, stores, resume, figure.

Reference values: every point of a sweep is compared with a serial ``flexbooster.analyze`` of
the same case, built here independently of the sweep code (the case mapping edited by hand),
and read from ``Results.to_dict()`` (the results.json schema).  The brief asks for 1e-12
relative; the same code runs on the workers (one BLAS thread, as ``make test`` sets here), so
the tests check bit-identity (==), on the LocalCluster, the ``dask worker`` subprocess and in
this process alike; the resumed sweep is compared with 1e-12.  Grids are checked against
numpy.linspace / numpy.logspace, unit conversions against the README's rules (SI; Hz = 2 pi
rad/s).

The Dask tests start a real LocalCluster (2 worker processes on 127.0.0.1) and, separately, a
``dask scheduler`` plus a ``dask worker`` as subprocesses on free ports of 127.0.0.1, always
torn down.  Cases are tiny (8 Omega points, 2-3 modes) so that the whole file runs in well
under a minute.
"""

from __future__ import annotations

import contextlib
import copy
import inspect
import itertools
import math
import os
import re
import signal
import socket
import subprocess
import sys
import time
import tomllib
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("distributed")
pytest.importorskip("xarray")
pytest.importorskip("zarr")
pytest.importorskip("h5netcdf")

import xarray as xr  # noqa: E402

import flexbooster  # noqa: E402
from flexbooster.errors import CaseError  # noqa: E402
from flexbooster.sweep import command  # noqa: E402
from flexbooster.sweep.spec import load_sweep, make_spec, parse_axes, point_cases  # noqa: E402

SRC = str(Path(flexbooster.__file__).parents[1])

RTOL = 1e-12  # sweep point vs serial analyze: same code on the workers (brief: 1e-12)
GOOD_E, BAD_E = "10.5e6 psi", "1e-15 Pa"  # BAD_E: valid for the case model (E > 0), but the
# analysis refuses it (the thrust is above the divergence load of the steady system)
SOFT_E = "1e8 Pa"  # a soft booster: strong beam-action bands (growth 0.1 1/s at gamma = 0.3)


def tiny_case() -> dict:
    """The memo case with a coarse Omega grid and a small truncation (about 0.1 s)."""
    from flexbooster.case import memo_case_text

    data = tomllib.loads(memo_case_text())
    data["name"] = "tiny"
    data["thrust"].update(n_omega=8)
    data["truncation"] = {"M1": 2, "N1": 2, "M2": 2, "N2": 2, "N": 2, "S": 2, "R": 2}
    return data


def serial_reference(case_data: dict, *, stability: bool = True) -> dict:
    """The numbers the sweep must hold for one point, from a serial analyze (results.json)."""
    options = {"stability": stability}
    if "figures" in inspect.signature(flexbooster.analyze).parameters:
        options["figures"] = False  # the figure data: not needed, and slow
    if "vehicle" in inspect.signature(flexbooster.analyze).parameters:
        options["vehicle"] = False  # the vehicle regions: not a sweep variable
    d = flexbooster.analyze(flexbooster.load_case(case_data), **options).to_dict()
    # the bands (exact edges), never grid samples: their count and largest growth
    pitch, action = d["pitch"]["bands"], d["beam_action"]["bands"]
    peak = max(action, key=lambda b: b["growth_rate_max"], default=None)
    out = {
        "omega_1": d["frequencies"]["omega_1"],
        "omega_psi": d["frequencies"]["omega_psi"],
        "pitch_max_growth_rate": max((b["growth_rate_max"] for b in pitch), default=0.0),
        "pitch_unstable_regions": len(pitch),
        "beam_action_max_growth_rate": 0.0 if peak is None else peak["growth_rate_max"],
        "beam_action_Omega_at_max": 0.0 if peak is None else peak["Omega_at_max"],
        "beam_action_unstable_bands": len(action),
        "n_warnings": len(d["warnings"]),
        "shell_min_frequency": min(d["shell_frequencies"]["rad_s"]),
    }
    out["max_growth_rate"] = max(out["pitch_max_growth_rate"], out["beam_action_max_growth_rate"])
    if stability:
        out["stability_count"] = d["stability"]["count"]
        out["stability_active"] = d["stability"]["active"]
    return out


def assert_matches_serial(ds: xr.Dataset, points: list[tuple[dict, dict]], *, exact: bool):
    """Every (index selection, case mapping) point of ``ds`` against a serial analysis."""
    for selection, case_data in points:
        point = ds.isel(selection)
        try:
            reference = serial_reference(case_data, stability="stability_count" in ds)
        except Exception as exc:  # the serial analysis fails: the sweep must record it
            assert str(point["status"].values) == "error"
            assert str(point["message"].values) == f"{type(exc).__name__}: {exc}"
            assert np.isnan(float(point["omega_1"]))
            continue
        assert str(point["status"].values) == "ok", str(point["message"].values)
        for name, expected in reference.items():
            got = float(point[name])
            if exact:
                assert got == expected, (selection, name)
            else:
                np.testing.assert_allclose(got, expected, rtol=RTOL, atol=0, err_msg=name)


def with_fields(base: dict, **fields) -> dict:
    """A copy of ``base`` with dotted fields (keyword: '__' for '.') set by hand."""
    data = copy.deepcopy(base)
    for dotted, value in fields.items():
        table, key = dotted.split("__")
        data[table][key] = value
        if key in ("F0", "T0"):
            data[table].pop("T0" if key == "F0" else "F0", None)
    return data


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def stop(process: subprocess.Popen) -> None:
    if process.poll() is None:
        process.terminate()
        try:
            process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait(timeout=10)


def write_sweep(tmp_path, axes_toml: str, *, case: dict | None = None, extra: str = "") -> str:
    from conftest import dump_toml

    (tmp_path / "base.toml").write_text(dump_toml(case or tiny_case()))
    path = tmp_path / "sweep.toml"
    path.write_text(f'case = "base.toml"\n{extra}\n[axes]\n{axes_toml}\n')
    return str(path)


def run_main(argv: list[str], capsys) -> tuple[int, str]:
    """``python -m flexbooster.sweep.command ARGV`` in this process: (exit code, stderr)."""
    with pytest.raises(SystemExit) as exit_info:
        command.main(argv)
    return exit_info.value.code, capsys.readouterr().err


# ---------------------------------------------------------------- Dask clusters (fixtures)


@pytest.fixture(scope="module")
def local_client():
    """A real LocalCluster: 2 worker processes, 1 thread each, on 127.0.0.1."""
    from distributed import Client, LocalCluster

    cluster = LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1", dashboard_address=":0"
    )
    client = Client(cluster)
    try:
        yield client
    finally:
        client.close()
        cluster.close()


@pytest.fixture(scope="module")
def scheduler_address():
    """``dask scheduler`` and one ``dask worker`` as subprocesses on free 127.0.0.1 ports."""
    from distributed import Client

    port = free_port()
    address = f"tcp://127.0.0.1:{port}"
    dask = [sys.executable, "-m", "dask"]
    quiet = {"stdout": subprocess.DEVNULL, "stderr": subprocess.DEVNULL}
    processes = []
    try:
        processes.append(
            subprocess.Popen(
                [*dask, "scheduler", "--host", "127.0.0.1", "--port", str(port)]
                + ["--dashboard-address", f"127.0.0.1:{free_port()}"],
                **quiet,
            )
        )
        processes.append(
            subprocess.Popen(
                [*dask, "worker", address, "--nworkers", "1", "--nthreads", "1"]
                + ["--host", "127.0.0.1", "--no-dashboard"],
                **quiet,
            )
        )
        with Client(address, timeout="30s") as client:
            client.wait_for_workers(1, timeout=60)
        yield address
    finally:
        for process in reversed(processes):
            stop(process)


# ---------------------------------------------------------------- tier 1: exact, closed forms


@pytest.mark.parametrize(
    "scale, expected",
    [
        ("linear", np.linspace(0.2, 1.0, 5)),  # numpy.linspace, rel 1e-15
        ("log", np.logspace(np.log10(0.2), 0.0, 5)),  # numpy.logspace, rel 1e-15
    ],
    ids=["linspace", "logspace"],
)
def test_range_axis_matches_numpy(scale, expected):
    (axis,) = parse_axes({"thrust.K": {"start": 0.2, "stop": 1.0, "num": 5, "scale": scale}})
    np.testing.assert_allclose(axis.values, expected, rtol=1e-15, atol=0)
    assert axis.values[0] == 0.2 and axis.values[-1] == 1.0  # end points exact


def test_range_axis_with_units_converts_to_si():
    spec = make_spec(
        tiny_case(),
        {"booster.thickness": {"start": "10 mm", "stop": "30 mm", "num": 3}},
        stability=False,
    )
    ds = flexbooster.sweep.run_sweep(spec)
    # 10, 20, 30 mm in metres (pint; rel 1e-15), units attribute from the case schema
    np.testing.assert_allclose(ds["booster.thickness"].values, [0.01, 0.02, 0.03], rtol=1e-15)
    assert ds["booster.thickness"].attrs["units"] == "m"
    assert (ds["status"].values.astype(str) == "ok").all()


def test_product_order_and_zip_pairs():
    axes = {"thrust.gamma": [0.0, 0.1, 0.2], "thrust.K": [0.5, 1.0]}
    spec = make_spec(tiny_case(), axes)
    assert spec.shape == (3, 2) and spec.dims == ("thrust.gamma", "thrust.K")
    # C order = itertools.product (exact)
    assert [spec.point_values(i) for i in range(6)] == list(itertools.product(*axes.values()))
    zipped = make_spec(
        tiny_case(), {"thrust.gamma": [0.0, 0.1], "thrust.K": [0.5, 1.0]}, mode="zip"
    )
    assert zipped.shape == (2,) and zipped.point_values(1) == (0.1, 1.0)
    with pytest.raises(CaseError, match="as many values"):
        make_spec(tiny_case(), axes, mode="zip")


def test_hertz_axis_is_cyclic_and_T0_replaces_F0():
    spec = make_spec(tiny_case(), {"thrust.omega_max": ["2 Hz"], "thrust.T0": ["100 kN/m"]})
    (case,) = point_cases(spec)
    assert case.thrust.omega_max == pytest.approx(4.0 * math.pi, rel=1e-15)  # README: Hz = 2 pi
    assert case.thrust.F0 is None and case.T0 == pytest.approx(1e5, rel=1e-15)
    r1 = case.booster.cylinder1.radius
    assert case.F0 == pytest.approx(2.0 * math.pi * r1 * 1e5, rel=1e-15)  # F0 = 2 pi R1 T0


def test_points_equal_cases_validated_from_the_raw_file():
    # invariant: the base validated once (SI) then the axis set == the raw mapping validated
    base = tiny_case()
    axes = {"booster.thickness": ["10 mm", 0.03], "thrust.omega_max": ["300 Hz"]}
    cases = point_cases(make_spec(base, axes))
    raw = [
        with_fields(base, booster__thickness=h, thrust__omega_max="300 Hz") for h in ("10 mm", 0.03)
    ]
    assert cases == [flexbooster.load_case(d) for d in raw]  # pydantic equality: every field
    # a base that is incomplete on its own, completed by an axis, is valid point by point
    del base["thrust"]["gamma"]
    (case,) = point_cases(make_spec(base, {"thrust.gamma": [0.1]}))
    assert case.thrust.gamma == 0.1


@pytest.mark.parametrize(
    "axes, field, text",
    [
        ({"thrust.gamma": [0.0, 1.5]}, "axes.thrust.gamma", "sweep point 1 (thrust.gamma = 1.5)"),
        ({"thrust.foo": [1.0]}, "axes.thrust.foo", "unknown key"),
        ({"booster.cylinder2.radius": ["10 mm"]}, "booster.thickness", "sweep point 0"),
        ({"truncation.N": [2, 2.5]}, "axes.truncation.N", "whole number"),
        ({"thrust.K": []}, "axes.thrust.K", "at least one value"),
        ({"thrust.K": {"start": 0, "stop": 1, "num": 0}}, "axes.thrust.K.num", "integer"),
        (
            {"thrust.K": {"start": 0, "stop": 1, "num": 3, "scale": "log"}},
            "axes.thrust.K.start",
            "> 0",
        ),
        ({"thrust.F0": [1.0], "thrust.T0": [1.0]}, "axes.thrust.T0", "not both"),
    ],
    ids=["range", "unknown-field", "cross-check", "integer", "empty", "num", "log", "F0-T0"],
)
def test_invalid_points_are_found_up_front(axes, field, text):
    # the case model's rules (README "Case files"): raised before any analysis, naming the
    # axis (or the field the cross-check names) and the point
    with pytest.raises(CaseError) as info:
        point_cases(make_spec(tiny_case(), axes))
    assert info.value.field == field and text in str(info.value)


@pytest.mark.parametrize(
    "text, message",
    [
        ('case = "base.toml"\nfoo = 1\n[axes]\n"thrust.K" = [1.0]\n', "foo = 1: unknown key"),
        ('case = "base.toml"\nmode = "grid"\n[axes]\n"thrust.K" = [1.0]\n', "mode = 'grid'"),
        ('case = "missing.toml"\n[axes]\n"thrust.K" = [1.0]\n', "file not found"),
        ('case = "base.toml"\n[axes]\n"thrust.gamma" = [2.0]\n', "axes.thrust.gamma = 2.0"),
    ],
    ids=["unknown-key", "mode", "case-file", "bad-point"],
)
def test_cli_input_errors_exit_2_with_one_line(tmp_path, capsys, text, message):
    from conftest import dump_toml

    (tmp_path / "base.toml").write_text(dump_toml(tiny_case()))
    (tmp_path / "sweep.toml").write_text(text)
    out = tmp_path / "out.zarr"
    code, err = run_main([str(tmp_path / "sweep.toml"), "-o", str(out), "--workers", "0"], capsys)
    assert code == 2  # README: exit 2 = invalid input
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("flexbooster: error: ") and message in lines[0]
    assert not out.exists()  # nothing ran, nothing written


def test_mode_inside_axes_table_and_inline_case(tmp_path):
    data = {
        "case": tiny_case(),
        "axes": {"mode": "zip", "thrust.K": [0.5, 1.0], "thrust.gamma": [0.0, 0.1]},
    }
    spec = load_sweep(data)
    assert spec.mode == "zip" and [a.name for a in spec.axes] == ["thrust.K", "thrust.gamma"]


def test_output_suffix_and_scheduler_workers_are_checked(tmp_path, capsys):
    path = write_sweep(tmp_path, '"thrust.K" = [0.5]')
    code, err = run_main([path, "-o", str(tmp_path / "out.csv")], capsys)
    assert code == 2 and "must end in .nc" in err
    code, err = run_main(
        [path, "-o", str(tmp_path / "o.nc"), "--scheduler", "tcp://x:1", "--workers", "2"], capsys
    )
    assert code == 2 and "--workers" in err
    (tmp_path / "plain.zarr").mkdir()
    (tmp_path / "plain.zarr" / "keep.txt").write_text("x")
    code, err = run_main([path, "-o", str(tmp_path / "plain.zarr"), "--workers", "0"], capsys)
    assert code == 2 and "not a zarr store" in err
    assert (tmp_path / "plain.zarr" / "keep.txt").exists()  # never deleted
    (tmp_path / "cut.zarr").mkdir()  # a store cut short while being created
    (tmp_path / "cut.zarr" / ".zgroup").write_text("{}")
    argv = [path, "-o", str(tmp_path / "cut.zarr"), "--workers", "0", "--resume"]
    code, err = run_main(argv, capsys)
    assert code == 2 and "cannot be read as a sweep store" in err


# ---------------------------------------------------- tier 2: against serial analyze (Dask)


@pytest.mark.slow
def test_local_cluster_matches_serial_and_records_failures(local_client, tmp_path):
    base = tiny_case()
    # SOFT_E: a soft booster with strong beam-action bands (non-zero growth rates)
    axes = {"booster.E": [GOOD_E, SOFT_E, BAD_E], "thrust.gamma": [0.0, 0.3], "thrust.K": [0.5, 2]}
    ds = flexbooster.sweep(base, axes, local_client, store=tmp_path / "s.zarr")
    points = [
        (
            {"booster.E": i, "thrust.gamma": j, "thrust.K": k},
            with_fields(base, booster__E=e, thrust__gamma=g, thrust__K=kk),
        )
        for (i, e), (j, g), (k, kk) in itertools.product(
            enumerate([GOOD_E, SOFT_E, BAD_E]), enumerate([0.0, 0.3]), enumerate([0.5, 2])
        )
    ]
    assert_matches_serial(ds, points, exact=True)  # bit-identical: the same code on the workers
    status = ds["status"].values.astype(str)
    assert (status == "error").sum() == 4 and (status == "ok").sum() == 8  # the rest complete
    assert float(ds["max_growth_rate"].isel({"booster.E": 1}).max()) > 0.0  # not all trivial
    assert (ds["computed"].values == 1).all()
    # invariant: batching does not change a bit (one point per task vs automatic batches)
    single = flexbooster.sweep(base, axes, local_client, batch_size=1)
    xr.testing.assert_equal(single, ds)  # exact, NaN == NaN
    # invariant: what the zarr store holds is what the call returned
    stored = xr.open_zarr(tmp_path / "s.zarr").load()
    for name in ("status", "message"):  # zarr reads text back as numpy's StringDType
        stored[name] = stored[name].astype(object)
    xr.testing.assert_equal(stored, ds)
    assert stored.attrs["sweep_fingerprint"] == ds.attrs["sweep_fingerprint"]


@pytest.mark.slow
def test_dask_scheduler_subprocess_via_cli(scheduler_address, tmp_path, capsys):
    base = tiny_case()
    path = write_sweep(
        tmp_path,
        '"thrust.gamma" = [0.0, 0.3]\n"booster.thickness" = ["10 mm", "20 mm", "30 mm"]',
        case=base,
    )
    out = tmp_path / "sweep.nc"
    code, err = run_main([path, "-o", str(out), "--scheduler", scheduler_address], capsys)
    assert code == 0, err
    assert f"scheduler {scheduler_address}" in err and "6 ok, 0 failed" in err
    ds = xr.open_dataset(out, engine="h5netcdf").load()
    points = [
        (
            {"thrust.gamma": i, "booster.thickness": j},
            with_fields(base, thrust__gamma=g, booster__thickness=h),
        )
        for (i, g), (j, h) in itertools.product(
            enumerate([0.0, 0.3]), enumerate(["10 mm", "20 mm", "30 mm"])
        )
    ]
    assert_matches_serial(ds, points, exact=True)  # bit-identical (the brief asks 1e-12)
    assert ds["booster.thickness"].attrs["units"] == "m"
    assert (tmp_path / "sweep.svg").exists() and (tmp_path / "sweep.html").exists()


@pytest.mark.slow
def test_scheduler_from_environment_variable(scheduler_address, tmp_path, capsys, monkeypatch):
    monkeypatch.setenv("DASK_SCHEDULER_ADDRESS", scheduler_address)
    path = write_sweep(tmp_path, '"thrust.K" = [0.5]', extra="stability = false")
    code, err = run_main([path, "-o", str(tmp_path / "o.zarr"), "--no-report"], capsys)
    assert code == 0 and f"scheduler {scheduler_address}" in err


@pytest.mark.slow
def test_failed_task_marks_its_points_and_the_rest_complete(monkeypatch):
    # a task that raises instead of returning (what a dead worker's KilledWorker does) records
    # its points as errors; the other tasks complete. The worker is a process of its own
    # (the patched task reaches it by value, cloudpickle), sharing no thread or garbage
    # collector with the test
    from distributed import Client, LocalCluster

    import flexbooster.sweep.run as run

    original = run.analyze_batch

    def crashing(indices, cases, **options):
        if 0 in indices:
            raise RuntimeError("worker lost")
        return original(indices, cases, **options)

    monkeypatch.setattr(run, "analyze_batch", crashing)
    with (
        LocalCluster(
            n_workers=1, threads_per_worker=1, processes=True, dashboard_address=":0"
        ) as cluster,
        Client(cluster) as client,
    ):
        ds = flexbooster.sweep(
            tiny_case(), {"thrust.K": [0.5, 1.0, 2.0]}, client, batch_size=1, stability=False
        )
    assert ds["status"].values.tolist() == ["error", "ok", "ok"]
    assert ds["message"].values[0] == "task failed: RuntimeError: worker lost"


def test_cli_runtime_failure_is_recorded_not_fatal(tmp_path, capsys):
    # a valid point whose analysis raises: exit 0, the failure counted and shown, stored
    path = write_sweep(
        tmp_path, f'"booster.E" = ["{GOOD_E}", "{BAD_E}"]', extra="stability = false"
    )
    out = tmp_path / "f.nc"
    code, err = run_main([path, "-o", str(out), "--workers", "0", "--no-report"], capsys)
    assert code == 0, err
    assert "2 points: 1 ok, 1 failed" in err
    assert f"first failure: point 1 (booster.E = '{BAD_E}'): CaseError: thrust.F0" in err
    assert "divergence load" in " ".join(err.split())  # the message, wrapped by the terminal
    stored = xr.open_dataset(out, engine="h5netcdf").load()
    assert stored["status"].values.tolist() == ["ok", "error"]


def test_serial_sweep_is_bit_identical_to_analyze():
    base = tiny_case()
    ds = flexbooster.sweep(base, {"thrust.gamma": [0.0, 0.3], "booster.E": [GOOD_E, BAD_E]})
    points = [
        ({"thrust.gamma": i, "booster.E": j}, with_fields(base, thrust__gamma=g, booster__E=e))
        for (i, g), (j, e) in itertools.product(enumerate([0.0, 0.3]), enumerate([GOOD_E, BAD_E]))
    ]
    assert_matches_serial(ds, points, exact=True)  # same process, same code: bit-identical


# ---------------------------------------------------------------- interrupt and resume


def _stored_count(path) -> int:
    import zarr

    status = np.asarray(zarr.open_group(str(path), mode="r")["status"][...]).reshape(-1)
    return sum(s != "pending" for s in status.tolist())


#: ``flexbooster sweep`` (flexbooster.sweep.command.main) that presses Ctrl-C on itself (SIGINT
#: to its own process, from the main thread) once its progress reports four points stored: a
#: deterministic moment, whatever the machine's speed or load.
_INTERRUPTED_AFTER_FOUR = r"""
import os, signal, sys
import flexbooster.sweep.run as run
real = run.run_sweep

def run_sweep(*args, progress, **kwargs):
    def hooked(done, failed, total):
        progress(done, failed, total)
        if done >= 4:
            os.kill(os.getpid(), signal.SIGINT)
    return real(*args, progress=hooked, **kwargs)

run.run_sweep = run_sweep
from flexbooster.sweep.command import main
main(sys.argv[1:])
"""


@pytest.mark.slow
def test_interrupted_zarr_sweep_resumes_without_recomputing(tmp_path, capsys):
    path = write_sweep(
        tmp_path,
        '"thrust.gamma" = {start = 0.0, stop = 0.3, num = 6}\n"thrust.K" = [0.5, 1.0, 1.5, 2.0]',
        extra="stability = false",
    )
    out = tmp_path / "run.zarr"
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1")
    process = subprocess.Popen(
        [sys.executable, "-c", _INTERRUPTED_AFTER_FOUR, path, "-o", str(out), "--workers", "1",
         "--batch-size", "1", "--no-report"],
        env=env,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        _, err = process.communicate(timeout=900)  # a hang guard, not a measurement
    finally:
        stop(process)
    assert process.returncode == 130, err  # README: 130 interrupted
    assert "dask dashboard: http://127.0.0.1:" in err
    stored = _stored_count(out)
    assert 0 < stored < 24, f"interrupt not half-way ({stored} of 24 stored)"
    code, err = run_main(
        [path, "-o", str(out), "--resume", "--workers", "0", "--no-report"], capsys
    )
    assert code == 0, err
    assert f"resume: {stored} points stored, {24 - stored} to compute" in err
    assert f"({24 - stored} computed in this run)" in err
    resumed = xr.open_zarr(out).load()
    assert (resumed["computed"].values == 1).all()  # no point computed twice, none missing
    # the result equals an uninterrupted sweep (serial, in memory), rel 1e-12
    spec = load_sweep(path)
    whole = flexbooster.sweep.run_sweep(spec)
    assert resumed["status"].values.tolist() == whole["status"].values.tolist()
    for name in whole.data_vars:
        if name not in ("status", "message"):
            np.testing.assert_allclose(resumed[name].values, whole[name].values, rtol=RTOL)


@pytest.mark.slow
def test_interrupted_netcdf_sweep_is_saved_and_resumed(tmp_path):
    base = tiny_case()
    axes = {"thrust.gamma": [0.0, 0.1, 0.2, 0.3]}
    out = tmp_path / "r.nc"
    calls = []

    def interrupt(done, failed, total):
        calls.append(done)
        if done >= 2:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        flexbooster.sweep(base, axes, store=out, batch_size=1, stability=False, progress=interrupt)
    partial = xr.open_dataset(out, engine="h5netcdf").load()
    assert partial["status"].values.tolist() == ["ok", "ok", "pending", "pending"]
    ds = flexbooster.sweep(base, axes, store=out, resume=True, stability=False)
    assert ds.attrs["points_computed_this_run"] == 2 and (ds["computed"].values == 1).all()
    whole = flexbooster.sweep(base, axes, stability=False)
    ds.attrs.pop("points_computed_this_run"), whole.attrs.pop("points_computed_this_run")
    xr.testing.assert_identical(ds, whole)  # exact, attributes included
    with pytest.raises(CaseError, match="another sweep"):  # resume refuses a different sweep
        flexbooster.sweep(base, {"thrust.gamma": [0.0]}, store=out, resume=True, stability=False)


# ---------------------------------------------------------------- invariants, house rules


def test_import_flexbooster_does_not_import_dask_or_xarray():
    code = (
        "import sys, flexbooster, flexbooster.sweep, flexbooster.sweep.spec\n"
        "heavy = {'dask', 'distributed', 'xarray', 'zarr', 'h5netcdf', 'h5py'}\n"
        "print(sorted(heavy & {m.split('.')[0] for m in sys.modules}))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"


def test_package_is_callable_as_the_sweep_function():
    import flexbooster.sweep as package

    ds = package(tiny_case(), {"thrust.K": [0.5]}, stability=False, beam_action=False)
    assert set(ds.data_vars) >= {"omega_1", "pitch_max_growth_rate", "status"}
    assert "beam_action_max_growth_rate" not in ds  # stage not computed: no variable
    # exposed lazily at top level (the lead's _LAZY entry "sweep": "sweep.run"): the first
    # access returns the function, later ones the package, which the import binds; both work
    code = (
        "import flexbooster\n"
        "flexbooster._LAZY['sweep'] = 'sweep.run'\n"
        "first, second = flexbooster.sweep, flexbooster.sweep\n"
        "print(first.__name__, type(second).__name__, callable(first), callable(second))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.split() == ["sweep", "_CallableModule", "True", "True"]


@pytest.mark.slow
def test_figure_and_page(tmp_path):
    html5lib = pytest.importorskip("html5lib")
    import matplotlib

    matplotlib.use("Agg")
    from flexbooster.sweep.page import sweep_page
    from flexbooster.sweep.plot import figure_svg, sweep_figure

    # a soft booster (SOFT_E): beam-action bands; BAD_E: the analysis refuses the point
    axes = {"thrust.gamma": [0.0, 0.3], "booster.E": [SOFT_E, BAD_E]}
    flexbooster.sweep(tiny_case(), axes, stability=False, store=tmp_path / "f.zarr")
    ds = xr.open_zarr(tmp_path / "f.zarr").load()  # as a user reads it back (text: StringDType)
    fig = sweep_figure(ds)
    assert len(fig.axes[0].images) == 2  # stable/missing layer + growth-rate layer
    svg = figure_svg(fig)
    page = sweep_page(ds, svg=svg)
    html5lib.HTMLParser(strict=True).parse(page)  # well-formed HTML5
    assert "<script" not in page and "<svg" in page and "<link" not in page
    assert not re.search(r'(src|href)\s*=\s*"(https?:|//)', page)  # no external resource
    message = str(ds["message"].values[0, 1])
    assert message and message.split(":")[0] in page  # the failure with its message
    curves = sweep_figure(ds.isel({"booster.E": 0}, drop=True))
    assert len(curves.axes[0].lines) >= 2  # pitch and beam-action curves
    stable = flexbooster.sweep(
        tiny_case(), {"thrust.K": [0.5], "thrust.gamma": [0.0]}, stability=False
    )
    assert "stable everywhere" in sweep_figure(stable).axes[0].get_title()


def _finished_count(path) -> int:
    """Points of a zarr store whose status is final ("ok" or "error"); 0 before it exists."""
    import zarr

    try:
        status = np.asarray(zarr.open_group(str(path), mode="r")["status"][...]).reshape(-1)
    except Exception:  # noqa: BLE001 - not created yet, or being created
        return 0
    return sum(s in ("ok", "error") for s in status.tolist())


@pytest.mark.slow
def test_ctrl_c_at_the_terminal_stops_the_cluster_in_one_line(tmp_path):
    """Source: a terminal's Ctrl-C (SIGINT to the whole foreground process group: the command
    and the local cluster's worker processes), sent once the store holds 5 finished points (an
    event read from the store, not a sleep). Expected (README: 130 interrupted): exit 130, with
    -q a single stderr line and no traceback (neither "IOLoop is closed" nor the workers'
    tracebacks), no process of the run left, the finished points kept for --resume."""
    psutil = pytest.importorskip("psutil")
    path = write_sweep(
        tmp_path,
        '"thrust.gamma" = {start = 0.0, stop = 0.3, num = 10}\n"thrust.K" = [0.5, 1.0, 1.5, 2.0]',
        extra="stability = false",
    )
    out = tmp_path / "run.zarr"
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", PYTHONPATH=SRC)
    process = subprocess.Popen(
        [sys.executable, "-m", "flexbooster", "sweep", path, "-o", str(out), "--workers", "2",
         "--batch-size", "1", "--no-report", "-q"],
        env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
        start_new_session=True,  # its own process group, as a terminal's foreground job
    )
    try:
        deadline = time.monotonic() + 900  # a hang guard, not a measurement
        while _finished_count(out) < 5 and process.poll() is None:
            assert time.monotonic() < deadline, "no 5 points stored"
            time.sleep(0.05)
        assert process.poll() is None, process.communicate()[1]
        family = [process.pid] + [c.pid for c in
                                  psutil.Process(process.pid).children(recursive=True)]
        os.killpg(process.pid, signal.SIGINT)
        _, err = process.communicate(timeout=900)
    finally:
        stop(process)
    assert process.returncode == 130, err
    assert err.strip().splitlines() == ["flexbooster: error: interrupted"], err
    alive = []
    for pid in family:
        with contextlib.suppress(psutil.NoSuchProcess):
            alive.append(psutil.Process(pid))
    # the resource tracker ends when it reads the end of its pipe: a moment after its parent
    _, left = psutil.wait_procs(alive, timeout=10)
    left = [p for p in left if p.status() != psutil.STATUS_ZOMBIE]
    assert left == [], [" ".join(p.cmdline()) for p in left]
    assert _finished_count(out) >= 5
