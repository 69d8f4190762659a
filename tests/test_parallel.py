"""Worker processes (flexbooster._parallel): same results as in-process, clean interrupts.

Tier 3 (invariants): an analysis and its files with workers = 2 equal those with workers = 1
bit for bit (the tasks are pure functions; the reference is the in-process run).
"""

from __future__ import annotations

import multiprocessing
import os
import time

import pytest

from flexbooster import analysis
from flexbooster._parallel import MAX_WORKERS, TaskPool, default_workers
from flexbooster.case import default_case, load_case
from flexbooster.present.outputs import write_outputs

PARALLEL = TaskPool(2).parallel  # False on a platform without fork


def _pid(_: object = None) -> int:
    return os.getpid()


def _fail(message: str) -> None:
    raise ZeroDivisionError(message)


def test_default_workers_is_between_one_and_the_cap():
    assert 1 <= default_workers() <= MAX_WORKERS


@pytest.mark.parametrize("bad", [0, -1, 1.5, True, "2"])
def test_bad_worker_counts_are_refused(bad):
    with pytest.raises(ValueError, match="workers"):
        TaskPool(bad)


def test_one_worker_runs_in_this_process():
    with TaskPool(1) as pool:
        assert not pool.parallel
        assert pool.submit(_pid).result() == os.getpid()
        assert pool.map(abs, [-1, 2, -3]) == [1, 2, 3]


@pytest.mark.skipif(not PARALLEL, reason="no fork on this platform")
def test_two_workers_run_elsewhere_and_keep_the_order():
    with TaskPool(2) as pool:
        assert pool.parallel
        assert os.getpid() not in pool.map(_pid, range(4))
        assert pool.map(abs, [-5, 4, -3, 2, -1]) == [5, 4, 3, 2, 1]
    assert not multiprocessing.active_children()


@pytest.mark.parametrize("workers", [1, 2])
def test_share_computes_the_first_item_here_and_keeps_the_order(workers):
    with TaskPool(workers) as pool:
        pids = pool.share(_pid, range(5))
        assert pool.share(abs, [-4, 3, -2]) == [4, 3, 2] and pool.share(abs, []) == []
    assert pids[0] == os.getpid()
    assert all((pid != os.getpid()) == pool.parallel for pid in pids[1:])
    assert not multiprocessing.active_children()


@pytest.mark.parametrize("workers", [1, 2])
def test_a_task_error_reaches_the_caller(workers):
    with pytest.raises(ZeroDivisionError, match="boom"):
        with TaskPool(workers) as pool:
            pool.submit(_fail, "boom").result()
    assert not multiprocessing.active_children()


@pytest.mark.skipif(not PARALLEL, reason="no fork on this platform")
def test_leaving_by_an_interrupt_stops_the_workers():
    """KeyboardInterrupt in the parent (Ctrl-C) terminates the running tasks: no orphan."""
    with pytest.raises(KeyboardInterrupt):
        with TaskPool(2) as pool:
            pool.submit(time.sleep, 600)
            pool.submit(_pid).result()  # the workers are up
            raise KeyboardInterrupt
    assert not multiprocessing.active_children()


def _logged(log: str, label: str, seconds: float) -> None:
    """A task that records its start and end (CLOCK_MONOTONIC: one clock for all processes)."""
    start = time.monotonic()
    time.sleep(seconds)
    with open(log, "a") as handle:
        handle.write(f"{label} {start!r} {time.monotonic()!r}\n")


def _events(log) -> dict:
    rows = [line.split() for line in open(log)]
    return {label: (float(a), float(b)) for label, a, b in rows}


@pytest.mark.skipif(not PARALLEL, reason="no fork on this platform")
def test_a_task_for_idle_workers_waits_until_one_is_idle(tmp_path):
    """submit_when_idle: with 2 workers and 3 tasks, the held-back task may start only when a
    worker has nothing left to take: after the second task has ended (the third keeps the
    other worker), never before; and it runs (the tasks after it are not delayed either)."""
    log = str(tmp_path / "log")
    with TaskPool(2) as pool:
        pool.submit_when_idle(_logged, log, "idle", 0.0)
        jobs = [pool.submit(_logged, log, f"t{i}", 0.3) for i in range(3)]
        [job.result() for job in jobs]
        time.sleep(0.5)  # the held-back task, sent from the pool's result thread
        late = pool.submit(_logged, log, "late", 0.0)
        late.result()
    events = _events(log)
    second_end = sorted(end for label, (_, end) in events.items() if label.startswith("t"))[1]
    assert set(events) == {"t0", "t1", "t2", "idle", "late"}
    assert events["idle"][0] >= second_end


@pytest.mark.parametrize("workers", [1, 2])
def test_a_task_for_idle_workers_is_dropped_when_none_becomes_idle(tmp_path, workers):
    """Nothing else submitted (no worker ever finished a task), or no worker process at
    all: the held-back task does not run, and leaving the block does not wait for it."""
    log = tmp_path / "log"
    with TaskPool(workers) as pool:
        pool.submit_when_idle(_logged, str(log), "idle", 0.0)
    assert not log.exists()
    assert not multiprocessing.active_children()


@pytest.fixture(scope="module")
def small_case():
    data = default_case().model_dump(exclude_none=True)
    data["thrust"]["n_omega"] = 40
    data["truncation"].update(M1=6, N1=6, M2=6, N2=6, N=4, S=4, R=3)
    return load_case(data)


@pytest.mark.slow
@pytest.mark.skipif(not PARALLEL, reason="no fork on this platform")
def test_analysis_and_files_are_the_same_with_workers(small_case, tmp_path):
    one = analysis.analyze(small_case, workers=1)
    two = analysis.analyze(small_case, workers=2)
    assert one.to_dict() == two.to_dict()
    write_outputs(one, tmp_path / "one", workers=1)
    write_outputs(two, tmp_path / "two", workers=2)
    files = sorted(p.name for p in (tmp_path / "one").iterdir())
    assert files == sorted(p.name for p in (tmp_path / "two").iterdir())
    assert "campbell.svg" in files and "beam-action-chart.png" in files
    for name in files:
        one_bytes = (tmp_path / "one" / name).read_bytes()
        assert one_bytes == (tmp_path / "two" / name).read_bytes(), name


@pytest.mark.slow
@pytest.mark.skipif(not PARALLEL, reason="no fork on this platform")
def test_files_without_figures_are_the_same_with_workers(small_case, tmp_path):
    """``run --no-figures``: the workers are free, and one writes the stability table's CSV
    while this process writes results.json: the same bytes as one process writing both."""
    results = analysis.analyze(small_case, workers=1, figures=False)
    write_outputs(results, tmp_path / "one", figures=False, workers=1)
    write_outputs(results, tmp_path / "two", figures=False, workers=2)
    files = sorted(p.name for p in (tmp_path / "one").iterdir())
    assert "unstable-frequencies.csv" in files
    assert files == sorted(p.name for p in (tmp_path / "two").iterdir())
    for name in files:
        assert (tmp_path / "one" / name).read_bytes() == (tmp_path / "two" / name).read_bytes()
    assert not multiprocessing.active_children()


@pytest.mark.slow
@pytest.mark.skipif(not PARALLEL, reason="no fork on this platform")
def test_one_pool_shared_by_the_analysis_and_the_files(small_case, tmp_path):
    """flexbooster run's arrangement: one TaskPool for analyze and write_outputs (the
    figures drawn by workers forked before the results existed, which reach them by pickle),
    matplotlib prepared in the idle workers: the same results and byte-identical files as
    everything in one process."""
    from flexbooster.present.outputs import prepare_figures

    one = analysis.analyze(small_case, workers=1)
    write_outputs(one, tmp_path / "one", workers=1)
    with TaskPool(2) as pool:
        for _ in range(pool.workers):
            pool.submit_when_idle(prepare_figures)
        shared = analysis.analyze(small_case, workers=pool)
        write_outputs(shared, tmp_path / "shared", workers=pool)
        assert pool.parallel
    assert one.to_dict() == shared.to_dict()
    for path in sorted((tmp_path / "one").iterdir()):
        assert path.read_bytes() == (tmp_path / "shared" / path.name).read_bytes(), path.name
    assert not multiprocessing.active_children()


@pytest.mark.slow
@pytest.mark.parametrize("workers, figures", [(1, False), (2, False), (2, True)])
def test_while_waiting_is_called_once_before_the_set_is_published(small_case, tmp_path,
                                                                  workers, figures):
    """write_outputs calls ``while_waiting`` (``flexbooster run`` renders its summary then)
    exactly once, while the files are still in the staging folder and before the report."""
    results = analysis.analyze(small_case, workers=1, figures=figures, vehicle=False)
    out = tmp_path / "out"
    seen = []

    def meanwhile():
        staged = [p.name for p in out.glob(".flexbooster-staging-*/*")]
        seen.append(("report.html" in staged, (out / "results.json").exists()))

    write_outputs(results, out, figures=figures, workers=workers, while_waiting=meanwhile)
    assert seen == [(False, False)]
    assert (out / "report.html").exists()


@pytest.mark.parametrize("workers", [1, 2])
def test_a_nan_in_the_stability_table_is_named_and_nothing_is_published(small_case, tmp_path,
                                                                       workers):
    """The stability table's texts are formatted by the workers (or this process): a NaN is
    refused with its path in results.json, as dumps_finite names it, and no file of the set
    is published (the reference: the walk of check_finite, tests/test_io.py)."""
    import dataclasses

    import numpy as np

    results = analysis.analyze(small_case, workers=1, figures=False, vehicle=False)
    severity = results.stability.severity.copy()
    severity[3] = np.nan
    bad = dataclasses.replace(
        results, stability=dataclasses.replace(results.stability, severity=severity))
    out = tmp_path / "out"
    with pytest.raises(ValueError, match=r"results\.stability\.table\.severity\[3\] = nan"):
        write_outputs(bad, out, figures=False, workers=workers)
    assert list(out.iterdir()) == []
    assert not multiprocessing.active_children()


# --------------------------------------------------------------------------------------------
# beside: one call in a child forked at a command's start (flexbooster run: the case loaded
# while the parent imports the analysis).  A child is forked only in a process with one thread
# (pytest-xdist's workers have more), so each check runs in a fresh interpreter.
# --------------------------------------------------------------------------------------------
_BESIDE_PRELUDE = """
import os, signal, sys, threading, warnings
from flexbooster._parallel import beside
here = os.getpid()
def pid():
    return os.getpid()
def in_child(action):
    if os.getpid() != here:
        action()
    return os.getpid()
"""


def _fresh(code: str) -> str:
    """Standard output of ``code`` (after the prelude) run by a fresh interpreter."""
    import subprocess
    import sys

    done = subprocess.run([sys.executable, "-c", _BESIDE_PRELUDE + code], capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    return done.stdout


@pytest.mark.skipif(not PARALLEL, reason="no fork on this platform")
def test_beside_computes_in_a_child_and_gives_its_value_once():
    out = _fresh("job = beside(pid)\n"
                 "print(job.result() != here, job.result() == job.result())")
    assert out.split() == ["True", "True"]


@pytest.mark.skipif(not PARALLEL, reason="no fork on this platform")
def test_beside_loads_the_default_case_in_a_child_equal_to_this_process_load():
    """The use in ``flexbooster run``: the child's Case (pickled back) equals the one loaded
    here, and the child gave it (no warning, no error on the way)."""
    out = _fresh("from flexbooster.case import default_case\n"
                 "job = beside(lambda: (os.getpid(), default_case()))\n"
                 "child, case = job.result()\n"
                 "print(child != here, case == default_case(), 'pint' in sys.modules)")
    assert out.split() == ["True", "True", "True"]


@pytest.mark.skipif(not PARALLEL, reason="no fork on this platform")
@pytest.mark.parametrize("action", [
    "lambda: 1 / 0",  # an exception
    "lambda: os.kill(os.getpid(), signal.SIGKILL)",  # the child killed
    "lambda: sys.exit(0)",  # the child leaves without a value
], ids=["error", "killed", "no-value"])
def test_beside_computes_here_what_the_child_did_not_give(action):
    out = _fresh(f"print(beside(in_child, {action}).result() == here)")
    assert out.strip() == "True"


@pytest.mark.skipif(not PARALLEL, reason="no fork on this platform")
def test_beside_computes_here_a_value_that_does_not_pickle():
    out = _fresh("print(beside(lambda: threading if os.getpid() != here else here).result()"
                 " == here)")
    assert out.strip() == "True"


@pytest.mark.skipif(not PARALLEL, reason="no fork on this platform")
def test_beside_leaves_a_warning_to_this_process():
    """A warning in the child is not printed there: the call is made again here, where the
    warning is shown once (as without the child)."""
    out = _fresh("def warn():\n"
                 "    warnings.warn('shown here')\n"
                 "    return os.getpid()\n"
                 "with warnings.catch_warnings(record=True) as seen:\n"
                 "    warnings.simplefilter('always')\n"
                 "    value = beside(warn).result()\n"
                 "print(value == here, [str(w.message) for w in seen])")
    assert out.strip() == "True ['shown here']"


def test_beside_raises_here_the_error_of_the_call():
    out = _fresh("try:\n"
                 "    beside(lambda: 1 / 0).result()\n"
                 "except ZeroDivisionError as exc:\n"
                 "    print('raised', exc)")
    assert out.strip() == "raised division by zero"


def test_beside_forks_no_child_beside_other_threads():
    """Another thread might hold a lock that a forked child would wait for forever."""
    out = _fresh("import time\n"
                 "threading.Thread(target=time.sleep, args=(2,), daemon=True).start()\n"
                 "print(beside(pid).result() == here)")
    assert out.strip() == "True"
