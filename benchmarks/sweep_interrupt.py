"""Measurement: ``flexbooster sweep`` on a local Dask cluster (2 worker processes) stopped by a
terminal's Ctrl-C at a random point, ``REPEATS`` times, then resumed.

A terminal's Ctrl-C is SIGINT to the whole foreground process group (the command and its
cluster's worker processes): the command runs in a session of its own and the signal goes to
its group (``os.killpg``), once the zarr store holds a number of finished points drawn by
``numpy.random.default_rng(seed)`` between 1 and the sweep's size - 1 (an event read from the
store, then a random extra delay of 0..0.5 s so that the signal also lands mid-task).

Per run it prints: the finished points at the signal, the time from the signal to the
command's exit (wall, s), the exit code, the number of stderr lines (and the first), the
processes of the run still alive 5 s after the exit (the command's descendants, and any
process whose command line names the run's store, as ``pgrep -f`` would), and whether
``--resume`` (serial) completes with every point final, each computed exactly once, and every
value equal to an uninterrupted serial sweep of the same points (bit for bit).

Goal (the acceptance): exit 130, one line, under 2 s, no process left, resume complete.

Run:  OPENBLAS_NUM_THREADS=1 python benchmarks/sweep_interrupt.py [--repeats 10] [--seed 5]
"""

from __future__ import annotations

import argparse
import os
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))
from conftest import dump_toml  # noqa: E402  (the tests' TOML writer: one copy)
from test_sweep import tiny_case  # noqa: E402  (the tests' tiny memo case: one copy)

__all__: list[str] = []

AXES = '"thrust.gamma" = {start = 0.0, stop = 0.3, num = 10}\n"thrust.K" = [0.5, 1.0, 1.5, 2.0]'
POINTS = 40


def finished(store: Path) -> int:
    import zarr

    try:
        status = np.asarray(zarr.open_group(str(store), mode="r")["status"][...]).reshape(-1)
    except Exception:  # noqa: BLE001 - not created yet, or being created
        return 0
    return sum(s in ("ok", "error") for s in status.tolist())


def alive_of_run(family: list[int], store: Path) -> list[str]:
    import psutil

    left = []
    for proc in psutil.process_iter(["pid", "cmdline", "status"]):
        cmd = " ".join(proc.info["cmdline"] or [])
        if proc.info["status"] == psutil.STATUS_ZOMBIE:
            continue
        if proc.info["pid"] in family or str(store) in cmd:
            left.append(f"{proc.info['pid']} {cmd[:120]}")
    return left


def one_run(folder: Path, at: int, delay: float, env: dict, reference) -> dict:
    import psutil
    import xarray as xr

    sweep = folder / "sweep.toml"
    store = folder / "run.zarr"
    cmd = [sys.executable, "-m", "flexbooster", "sweep", str(sweep), "-o", str(store),
           "--workers", "2", "--batch-size", "1", "--no-report", "-q"]
    proc = subprocess.Popen(cmd, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                            text=True, start_new_session=True)
    deadline = time.monotonic() + 600  # a hang guard
    while finished(store) < at and proc.poll() is None and time.monotonic() < deadline:
        time.sleep(0.02)
    time.sleep(delay)
    if proc.poll() is not None:
        return {"at": at, "error": f"ended before the signal: {proc.communicate()[1][-300:]}"}
    done_at = finished(store)
    family = [proc.pid] + [c.pid for c in psutil.Process(proc.pid).children(recursive=True)]
    t0 = time.perf_counter()
    os.killpg(proc.pid, signal.SIGINT)
    try:
        proc.wait(timeout=120)
    except subprocess.TimeoutExpired:
        proc.kill()
    seconds = time.perf_counter() - t0
    err = proc.stderr.read()
    time.sleep(5.0)
    left = alive_of_run(family, store)
    for line in left:  # a measurement must not leave them behind either
        try:
            os.kill(int(line.split()[0]), signal.SIGKILL)
        except ProcessLookupError:
            pass
    lines = err.strip().splitlines()
    resume = subprocess.run([*cmd[:-6], "--workers", "0", "--resume", "--no-report", "-q"],
                            env=env, capture_output=True, text=True, timeout=600)
    ds = xr.open_zarr(store).load()
    complete = (resume.returncode == 0 and (ds["computed"].values == 1).all()
                and all(s in ("ok", "error") for s in ds["status"].values.reshape(-1).tolist()))
    same = all(np.array_equal(ds[v].values.astype(reference[v].dtype), reference[v].values,
                              equal_nan=reference[v].dtype.kind == "f")
               for v in reference.data_vars if v not in ("message", "computed"))
    return {"at": done_at, "seconds": seconds, "code": proc.returncode, "lines": len(lines),
            "first": lines[0] if lines else "", "left": left,
            "resume": bool(complete and same), "resume_code": resume.returncode}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=10)
    ap.add_argument("--seed", type=int, default=5)
    args = ap.parse_args()
    import flexbooster
    from flexbooster.sweep.spec import load_sweep

    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", PYTHONPATH=str(ROOT / "src"))
    rng = np.random.default_rng(args.seed)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        base = Path(tmp)
        (base / "base.toml").write_text(dump_toml(tiny_case()))
        (base / "sweep.toml").write_text(f'case = "base.toml"\nstability = false\n'
                                         f"[axes]\n{AXES}\n")
        reference = flexbooster.sweep.run_sweep(load_sweep(str(base / "sweep.toml")))
        for i in range(args.repeats):
            folder = base / f"r{i}"
            folder.mkdir()
            for name in ("base.toml", "sweep.toml"):
                (folder / name).write_bytes((base / name).read_bytes())
            at, delay = int(rng.integers(1, POINTS)), float(rng.uniform(0.0, 0.5))
            row = one_run(folder, at, delay, env, reference)
            rows.append(row)
            print(f"run {i + 1:2d}: {row}", flush=True)
    ok = [r for r in rows if "seconds" in r]
    good = [r for r in ok if r["code"] == 130 and r["lines"] == 1 and r["seconds"] < 2.0
            and not r["left"] and r["resume"]]
    print(f"\n{len(good)}/{len(rows)} runs: exit 130, one line, under 2 s, no process left, "
          "resume complete and equal to the uninterrupted sweep")
    if ok:
        secs = sorted(r["seconds"] for r in ok)
        print("signal to exit (s): " + ", ".join(f"{s:.2f}" for s in secs)
              + f"; median {secs[len(secs) // 2]:.2f}, max {secs[-1]:.2f}")


if __name__ == "__main__":
    main()
