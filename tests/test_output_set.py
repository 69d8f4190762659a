"""The output folder is one consistent set: signals, interrupts and concurrent runs.
"""

from __future__ import annotations

import json
import math
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

import flexbooster
from conftest import dump_toml, run_cli
from flexbooster.analysis import FORCED_STAGE, STAGES, VEHICLE_REGIONS_STAGE
from flexbooster.present.outputs import (
    MANIFEST,
    OUTPUT_STAGES,
    STAGING_PREFIX,
    check_output_set,
)

nan, inf = math.nan, math.inf
SRC = str(Path(flexbooster.__file__).parents[1])


def _small_case(tmp_path: Path, memo_case_dict: dict, name: str, n_omega: int = 30) -> Path:
    d = json.loads(json.dumps(memo_case_dict))
    d["name"] = name
    d["truncation"].update(M1=3, N1=3, M2=3, N2=3, N=3, S=2, R=2)
    d["thrust"]["n_omega"] = n_omega
    path = tmp_path / f"{name}.toml"
    path.write_text(dump_toml(d))
    return path


def _cli(*args: str) -> subprocess.Popen:
    env = dict(os.environ, PYTHONPATH=SRC, OPENBLAS_NUM_THREADS="1")
    return subprocess.Popen([sys.executable, "-m", "flexbooster", "run", "-q", *args],
                            stderr=subprocess.PIPE, text=True, env=env)


#: A driver of ``flexbooster run`` (the real entry point, flexbooster.__main__.main) that sends
#: itself a signal when a given progress stage starts: deterministic moments, no sleeps.
#: ``sync``: os.kill from the main thread at the stage's start (the interrupt is raised
#: there, before the stage's work); ``thread``: from a thread started then, so that the signal
#: lands while the main thread works in the stage.
_DRIVER = r"""
import contextlib, os, signal, sys, threading
import flexbooster.cli as cli
stage, sig, how = sys.argv[1], getattr(signal, sys.argv[2]), sys.argv[3]
real = cli._progress

def kill():
    os.kill(os.getpid(), sig)

@contextlib.contextmanager
def progress(stages, quiet):
    with real(stages, quiet) as step:
        def hooked(name):
            step(name)
            if name == stage:
                kill() if how == "sync" else threading.Thread(target=kill).start()
        yield hooked

cli._progress = progress
from flexbooster.__main__ import main
main(["run", "-q", *sys.argv[4:]])
"""


def _driven(stage: str, sig: str, how: str, *args: str) -> subprocess.Popen:
    env = dict(os.environ, PYTHONPATH=SRC, OPENBLAS_NUM_THREADS="1")
    return subprocess.Popen([sys.executable, "-c", _DRIVER, stage, sig, how, *args],
                            stderr=subprocess.PIPE, text=True, env=env)


def _set_name(folder: Path) -> str:
    """The case of the set in ``folder``: results.json and report.html must agree."""
    check_output_set(folder)
    name = json.loads((folder / "results.json").read_text())["case"]["name"]
    assert name in (folder / "report.html").read_text(), "mixed set: report of another case"
    return name


def _no_leftovers(folder: Path) -> None:
    names = [p.name for p in folder.rglob("*")]
    assert not [n for n in names if n.endswith(".part") or n.startswith(STAGING_PREFIX)], names


#: The moments of a run at which a signal is sent: the start of every stage of analyze
#: (analysis.STAGES, then the vehicle regions and forced response) and of write_outputs.
MOMENTS = (*STAGES, VEHICLE_REGIONS_STAGE, FORCED_STAGE, *OUTPUT_STAGES)


@pytest.mark.slow
def test_signal_at_ten_moments_no_part_file_never_a_mixed_set(tmp_path, memo_case_dict):
    """SIGTERM and SIGINT (alternately) at the 10 moments above, over a complete previous set,
    each sent by the process to itself from a thread when the stage starts (the signal lands
    inside the stage's work).  Each run must end by exit 130 with one line "interrupted" and
    no traceback, leave no .part file and no staging folder, and leave one whole set
    (results.json and report.html of one case, manifest verified)."""
    out = tmp_path / "out"
    assert _cli(str(_small_case(tmp_path, memo_case_dict, "old-case")), "-o", str(out)).wait(
        timeout=300) == 0
    new = _small_case(tmp_path, memo_case_dict, "new-case")
    for i, moment in enumerate(MOMENTS):
        sig = "SIGTERM" if i % 2 else "SIGINT"
        proc = _driven(moment, sig, "thread", str(new), "-o", str(out))
        _, err = proc.communicate(timeout=300)
        assert proc.returncode == 130, (moment, sig, err)
        assert err == "flexbooster: error: interrupted\n", (moment, err)
        _no_leftovers(out)
        # before the report stage the new set cannot be complete; in it the signal may land
        # during the renames (held back): then exit 130 with the new set whole
        allowed = ("old-case",) if moment != OUTPUT_STAGES[-1] else ("old-case", "new-case")
        assert _set_name(out) in allowed, moment


#: ``flexbooster --version`` through the real entry point, with one import stalled: the
#: process says "importing" when it reaches ``rich.console`` (imported by flexbooster.cli)
#: and sleeps there, so that the signal deterministically lands while the modules load.
_STALLED_IMPORT = r"""
import importlib.abc, sys, time
class Stall(importlib.abc.MetaPathFinder):
    def find_spec(self, name, path=None, target=None):
        if name == "rich.console":
            sys.stderr.write("importing\n")
            sys.stderr.flush()
            time.sleep(60)
        return None
sys.meta_path.insert(0, Stall())
from flexbooster.__main__ import main
main(["--version"])
"""


@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM], ids=["SIGINT", "SIGTERM"])
def test_signal_during_the_imports_is_one_line_exit_130(sig):
    """Ctrl-C in the first second of `flexbooster run` (while click, rich, numpy
    load) printed a traceback.  Expected: exactly one line, exit 130 (no sleep: the signal
    is sent once the child has said it is inside the import)."""
    env = dict(os.environ, PYTHONPATH=SRC)
    proc = subprocess.Popen([sys.executable, "-c", _STALLED_IMPORT], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, env=env)
    assert proc.stderr.readline() == "importing\n"
    proc.send_signal(sig)
    out, err = proc.communicate(timeout=30)
    assert proc.returncode == 130 and out == ""
    assert err == "flexbooster: error: interrupted\n"


#: A signal after the outcome of the command is decided: `flexbooster --version` (exit 0)
#: whose cli.main sends itself SIGINT after returning (the bytecodes between its handlers
#: and the exit: a KeyboardInterrupt escaping main used to end the process by SIGINT, -2),
#: or whose atexit handler sends SIGINT and SIGTERM (during the interpreter's exit).
_LATE_SIGNAL = r"""
import atexit, os, signal, sys
import flexbooster.cli as cli
when = sys.argv[1]
real = cli.main
def late(argv):
    try:
        real(argv)
    finally:
        if when == "after-main":
            os.kill(os.getpid(), signal.SIGINT)
cli.main = late
if when == "atexit":
    atexit.register(lambda: (os.kill(os.getpid(), signal.SIGINT),
                             os.kill(os.getpid(), signal.SIGTERM)))
from flexbooster.__main__ import main
main(["--version"])
"""


@pytest.mark.parametrize(("when", "code"), [("after-main", 130), ("atexit", 0)])
def test_late_signal_never_ends_the_process_by_the_signal(when, code):
    """(The status -2 once seen): a signal in the last bytecodes of main is
    an interrupt (130, one line); one after the status is fixed is ignored (0).  Never a
    negative status (death by the signal) and never a traceback."""
    env = dict(os.environ, PYTHONPATH=SRC)
    proc = subprocess.run([sys.executable, "-c", _LATE_SIGNAL, when], capture_output=True,
                          text=True, env=env, timeout=60)
    assert proc.returncode == code, proc
    assert "Traceback" not in proc.stderr
    if code == 130:
        assert proc.stderr.endswith("flexbooster: error: interrupted\n")


@pytest.mark.slow
def test_interrupt_at_each_file_of_the_set_keeps_the_previous_set(tmp_path, memo_case_dict,
                                                                  capsys, monkeypatch):
    """Ctrl-C while the n-th file of the new set is being written (a KeyboardInterrupt from
    its fsync: the temporary file exists, half the set is staged), for every n, in-process
    over a complete previous set: exit 130 and one line, no .part file and no staging folder,
    the previous set whole (manifest verified) and nothing of the new one."""
    out = tmp_path / "out"
    args = ["run", "-q", "--no-vehicle", "--no-figures", "-o", str(out)]
    assert run_cli([*args, str(_small_case(tmp_path, memo_case_dict, "old-case"))]) == 0
    old = check_output_set(out)
    new = str(_small_case(tmp_path, memo_case_dict, "new-case"))
    real = os.fsync
    for n in range(1, len(old) + 1):  # the set's files less the manifest, and the report
        calls = []

        def fsync(fd, n=n, calls=calls):
            calls.append(fd)
            if len(calls) == n:
                raise KeyboardInterrupt
            real(fd)

        monkeypatch.setattr(os, "fsync", fsync)
        assert run_cli([*args, new]) == 130, n
        monkeypatch.setattr(os, "fsync", real)
        assert capsys.readouterr().err == "flexbooster: error: interrupted\n"
        _no_leftovers(out)
        assert check_output_set(out) == old and _set_name(out) == "old-case"


def test_signal_is_held_during_the_renames_with_another_thread_alive():
    """publish_set holds SIGINT back while it renames (never a mixed set).  With a
    second thread alive (the progress bar's, in a terminal) a pthread_sigmask of the main
    thread did not: the kernel gave the signal to the other thread and the interrupt broke in.
    Expected: the body runs to its end, then the KeyboardInterrupt is delivered."""
    import threading

    from flexbooster.present.io import hold_signals

    stop = threading.Event()
    other = threading.Thread(target=stop.wait, args=(30,), daemon=True)
    other.start()
    reached = []
    try:
        with pytest.raises(KeyboardInterrupt):
            with hold_signals():
                os.kill(os.getpid(), signal.SIGINT)
                for _ in range(20):
                    time.sleep(0.005)  # the interrupt would be raised here
                reached.append("end")
    finally:
        stop.set()
    assert reached == ["end"]


@pytest.mark.slow
def test_two_concurrent_runs_give_one_consistent_set(tmp_path, memo_case_dict):
    out = tmp_path / "out"
    procs = [_cli(str(_small_case(tmp_path, memo_case_dict, name)), "--no-figures", "-o", str(out))
             for name in ("case-a", "case-b")]
    for proc in procs:
        _, err = proc.communicate(timeout=180)
        assert proc.returncode == 0, err
    _no_leftovers(out)
    assert _set_name(out) in ("case-a", "case-b")
    assert set(json.loads((out / MANIFEST).read_text())["files"]) <= {
        p.name for p in out.iterdir()}


# --------------------------------------------------------------------------------------------
# Outputs checked before the analysis: one line, the path, exit 2
# --------------------------------------------------------------------------------------------
def _no_analysis(*args, **kwargs):
    raise AssertionError("the analysis started before the output was checked")


@pytest.mark.parametrize(("command", "kind"), [
    ("run", "empty"), ("run", "proc"), ("run", "results.json"), ("run", "report.html"),
    ("run", "danger-map.svg"), ("stability", "stability.json"), ("stability", "proc"),
    ("simulate", "simulation.json"),
])
def test_unwritable_output_is_refused_before_the_analysis(tmp_path, capsys, monkeypatch,
                                                          command, kind):
    """Source: POSIX (os.replace onto a folder fails, nothing can be made in /proc, '' is no
    path): each refused at once (the analysis is replaced by a failure), exit 2, one line with
    --output and the path."""
    import flexbooster.analysis

    monkeypatch.setattr(flexbooster.analysis, "analyze", _no_analysis)
    monkeypatch.setattr(flexbooster.analysis, "simulate_case", _no_analysis)
    out = tmp_path / "out"
    if kind == "empty":
        target = ""
    elif kind == "proc":
        target = "/proc/flexbooster-x"
    else:
        (out / kind).mkdir(parents=True)
        target = str(out)
    extra = ["--omega", "300", "--tau-max", "10"] if command == "simulate" else ["-q"]
    assert run_cli([command, *extra, "-o", target]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and err.startswith("flexbooster: error: --output = ")
    assert f"'{target}'" in err and (kind in err or kind in ("empty", "proc"))


@pytest.mark.slow
def test_run_output_names_are_all_checked_up_front(tmp_path, small_memo_case_file):
    """Source: the files a real run writes (every stage, figures included): each is one of
    SET_NAMES, the names check_output_folder looks at before the analysis."""
    from flexbooster.present.outputs import SET_NAMES

    out = tmp_path / "out"
    assert run_cli(["run", str(small_memo_case_file), "-q", "-o", str(out)]) == 0
    written = {p.name for p in out.iterdir()}
    assert written - set(SET_NAMES) == set() and "danger-map.svg" in written


def test_full_disk_names_the_file_exit_2(tmp_path, capsys, monkeypatch, small_memo_case_file):
    """Source: POSIX write(2)/fsync(2) report ENOSPC without a file name; the message names the
    file being written (exit 2, one line) and the folder keeps no part file."""
    import errno

    import flexbooster.present.io as io

    def full(fd):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(io.os, "fsync", full)
    out = tmp_path / "out"
    assert run_cli(["run", str(small_memo_case_file), "-q", "--no-figures", "-o", str(out)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1, err
    assert err.startswith("flexbooster: error: ") and err.endswith(
        "results.json: No space left on device")
    assert not list(out.rglob("*.part"))
