"""The flight's frozen times on Dask (flexbooster.sweep.flight, ``flexbooster run --scheduler``).

Evidence: the one-process path of the same case (``analyze(case)``, ``flight_stage``) is the
reference, and the comparison is exact (results.json text equal, arrays equal bit for bit):
both paths call the same deterministic functions on the same inputs, each process with one BLAS
thread (threadpoolctl), so no rounding may differ; a tolerance would hide a real difference
(a time computed with another fill, a lost mass matrix). The refusals follow the house rule
(one line naming the option, exit 2); an interrupt follows the sweeps' (tasks cancelled, no
output written).
"""

from __future__ import annotations

import copy
import time

import numpy as np
import pytest

from conftest import dump_toml, run_cli
from flexbooster.analysis import analyze
from flexbooster.case import load_case
from flexbooster.errors import CaseError
from flexbooster.flight_stage import assemble_flight, flight_stage, frozen_time
from flexbooster.present.io import dumps_finite
from flexbooster.sweep.flight import analyze_on_dask, frozen_times_on_dask
from test_flight_pipeline import CASE
from test_sweep import local_client  # noqa: F401 - the sweeps' LocalCluster fixture

#: The flight test case with a draining tank (fill 0.5 -> 0.2) over 3 frozen times, so that
#: every time differs (masses, modes, regions) and the tracking has two steps.
DRAINING = copy.deepcopy(CASE)
DRAINING["flight"] = {"stations": 3, "points": [
    {"time": 0.0, "F0": 2e5, "fill": [0.5], "oscillation": [15.0, 60.0], "gamma": 0.15},
    {"time": 40.0, "F0": 1.8e5, "fill": [0.2], "oscillation": [20.0, 50.0], "gamma": 0.1}]}
STAGES = dict(beam_action=False, stability=False, figures=False)


def _flight_arrays(fl) -> list[np.ndarray]:
    """Every array of a FlightResults, the tracked harmonics' included."""
    out = [fl.times, fl.F0, fl.gamma, fl.fill, fl.oscillation]
    for h in fl.harmonics:
        out += [h.frequencies, h.mac, h.order, h.types]
    return out


@pytest.mark.slow
def test_dask_path_equals_one_process_bit_for_bit(local_client):  # noqa: F811
    """Reference: analyze(case) in this process. The Dask path's results.json is the same
    text (floats written with repr: equal text is equal bits), its FlightResults' arrays are
    equal (NaN where absent in both), and the regions and events compare equal."""
    case = load_case(DRAINING)
    one = analyze(case, **STAGES)
    dask = analyze_on_dask(case, local_client, **STAGES)
    assert one.flight is not None and one.flight.events, "the comparison needs events"
    assert dumps_finite(dask.to_dict()) == dumps_finite(one.to_dict())
    for a, b in zip(_flight_arrays(dask.flight), _flight_arrays(one.flight), strict=True):
        assert a.dtype == b.dtype
        np.testing.assert_array_equal(a, b)
    assert dask.flight.regions == one.flight.regions
    assert dask.flight.events == one.flight.events
    assert dask.warnings == one.warnings


@pytest.mark.slow
def test_frozen_times_in_any_process_assemble_to_the_flight_stage(local_client):  # noqa: F811
    """The frozen times from Dask (other processes) assembled here give flight_stage's
    FlightResults and warnings (reference: the one-process stage), and each Dask frozen time
    is picklable data equal to the one computed here (modes' frequencies, DOF vectors)."""
    case = load_case(DRAINING)
    frozen = frozen_times_on_dask(case, local_client)
    assert [f.index for f in frozen] == [0, 1, 2]
    assert frozen[0].structural_mass is not None
    assert all(f.structural_mass is None for f in frozen[1:])  # sent once
    here = frozen_time(case, 1)
    np.testing.assert_array_equal(frozen[1].modes.omega, here.modes.omega)
    for a, b in zip(frozen[1].vectors, here.vectors, strict=True):
        np.testing.assert_array_equal(a, b)
    fl, warnings = assemble_flight(case, frozen)
    ref, ref_warnings = flight_stage(case)
    assert dumps_finite(fl.to_dict()) == dumps_finite(ref.to_dict())
    assert warnings == ref_warnings


def test_assemble_refuses_frozen_times_of_another_flight():
    """Rule: the frozen times must be those of the case, all of them, in order (a ValueError
    naming ``frozen``, never a flight assembled from the wrong vehicle); a bad index or case
    is an error naming it."""
    case = load_case(DRAINING)
    frozen = [frozen_time(case, i) for i in range(3)]
    for bad in (frozen[:2], frozen[::-1], [frozen[1], frozen[0], frozen[2]]):
        with pytest.raises(ValueError, match="frozen"):
            assemble_flight(case, bad)
    with pytest.raises(ValueError, match="index"):
        frozen_time(case, 3)
    with pytest.raises(TypeError, match="case"):
        frozen_time(DRAINING, 0)  # the raw mapping, not a validated Case
    with pytest.raises(ValueError, match="frozen"):  # no flight stage to take them
        analyze(case, vehicle=False, frozen=frozen)


@pytest.mark.slow
def test_a_frozen_time_error_on_a_worker_is_the_same_one_line(local_client):  # noqa: F811
    """A thrust that buckles the vehicle at a frozen time (F0 = 1e12 N on a 4 mm aluminium
    cylinder: far above its classical buckling load 2 pi E h^2 / sqrt(3 (1 - nu^2)) ~ 4e6 N,
    Timoshenko & Gere 1961) is a CaseError on ``flight.points`` from the worker, field, value
    and line as in one process (the error pickled whole)."""
    data = copy.deepcopy(DRAINING)
    data["flight"]["points"][1]["F0"] = 1e12
    case = load_case(data)
    with pytest.raises(CaseError) as here:
        flight_stage(case)
    with pytest.raises(CaseError) as there:
        frozen_times_on_dask(case, local_client)
    assert here.value.field == there.value.field == "flight.points"
    assert str(there.value) == str(here.value)


def test_scheduler_refused_without_flight_or_vehicle(tmp_path, capsys):
    """House rule: one line naming --scheduler, exit 2, before any analysis or cluster; a case
    without [flight] has no frozen times to distribute, --no-vehicle computes no flight."""
    data = copy.deepcopy(DRAINING)
    data.pop("flight")
    path = tmp_path / "no-flight.toml"
    path.write_text(dump_toml(data))
    assert run_cli(["run", str(path), "-o", str(tmp_path / "a"), "--scheduler", "local"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--scheduler" in err[0] and "[flight]" in err[0]
    path = tmp_path / "flight.toml"
    path.write_text(dump_toml(DRAINING))
    assert run_cli(["run", str(path), "-o", str(tmp_path / "b"), "--scheduler", "local",
                    "--no-vehicle"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--scheduler" in err[0] and "--no-vehicle" in err[0]
    assert not (tmp_path / "a").exists() and not (tmp_path / "b").exists()


class _InterruptingClient:
    """A Dask client whose futures raise KeyboardInterrupt (a Ctrl-C) on the first wait, once
    its task has finished (every task submitted, the others queued or running): the moment
    an interrupt of a real run meets."""

    def __init__(self, client):
        self.client = client
        self.futures = []  # held: a task is forgotten by the scheduler only when cancelled

    def submit(self, *args, **kwargs):
        future = self.client.submit(*args, **kwargs)
        self.futures.append(future)
        return _InterruptedFuture(future)

    def cancel(self, futures):
        self.client.cancel([f.future for f in futures])


class _InterruptedFuture:
    def __init__(self, future):
        self.future = future

    def result(self):
        from distributed import wait

        wait(self.future)  # the task is on the scheduler, done, its result held there
        raise KeyboardInterrupt


@pytest.mark.slow
def test_interrupt_cancels_the_tasks_and_writes_nothing(local_client, tmp_path,  # noqa: F811
                                                         monkeypatch):
    """As the sweeps (README: 130 interrupted): an interrupt while the frozen times run
    cancels every task of the run on the cluster, and ``flexbooster run --scheduler`` exits
    130 with one line and no output set (the outputs are written after the analysis, each
    file atomically)."""
    case = load_case(DRAINING)
    proxy = _InterruptingClient(local_client)
    with pytest.raises(KeyboardInterrupt):
        frozen_times_on_dask(case, proxy)
    assert len(proxy.futures) == 3

    def left(dask_scheduler, keys=tuple(f.key for f in proxy.futures)):
        return [k for k in keys if k in dask_scheduler.tasks]

    # the scheduler forgets a cancelled task once its release arrives: wait for that event
    deadline = time.monotonic() + 60  # a hang guard, not a measurement
    while local_client.run_on_scheduler(left):
        assert time.monotonic() < deadline, "cancelled tasks still on the scheduler"
        time.sleep(0.05)

    import flexbooster.sweep.flight as module

    real = module.frozen_times_on_dask
    monkeypatch.setattr(module, "frozen_times_on_dask",
                        lambda case, client: real(case, _InterruptingClient(client)))
    path = tmp_path / "flight.toml"
    path.write_text(dump_toml(DRAINING))
    out = tmp_path / "out"
    address = local_client.scheduler.address
    assert run_cli(["run", str(path), "-o", str(out), "--scheduler", address, "-q"]) == 130
    assert not out.exists() or not any(out.iterdir())

