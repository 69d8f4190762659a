"""A flight's frozen times on Dask: one task per frozen time, then the pipeline.

The frozen times of a ``[flight]`` are independent (:func:`flexbooster.flight_stage.frozen_time`,
a pure function of the case and the index). :func:`frozen_times_on_dask` maps it over the
times on a Dask client (the sweeps' clusters: ``flexbooster run CASE --scheduler ADDRESS`` or
``--scheduler local``); :func:`analyze_on_dask` then runs :func:`flexbooster.analyze` with
them (its ``frozen`` input), which assembles the flight in this process
(:func:`flexbooster.flight_stage.assemble_flight`). The results are those of
``analyze(case)`` in one process, bit for bit: the same functions on the same inputs, one BLAS
thread in every process.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import Any

from .. import cost
from ..analysis import analyze
from ..case import Case
from ..errors import CaseError
from ..flight_stage import FrozenTime, frozen_time
from ..model import flight_times, model_from_case, vehicle_from_case
from ..results import Results
from ..shell_of_revolution.survey import has_flat_plate

__all__ = ["FLIGHT_ON_DASK", "check_flight_budget", "frozen_times_on_dask", "analyze_on_dask"]

#: The stage announced by :func:`analyze_on_dask` before the frozen times run on Dask.
FLIGHT_ON_DASK = "flight frozen times (Dask)"


def check_flight_budget(case: Case, *, beam_action: bool = True, stability: bool = True,
                        figures: bool = True) -> cost.CostEstimate:
    """The case's whole estimate, its flight counted as in one process (an upper bound of the
    wall time on a cluster), or a ``CaseError`` on ``max_seconds`` past the budget: the refusal
    up front, before a cluster starts. TypeError unless ``case`` is a validated Case;
    CaseError on ``flight`` for a case without ``[flight]``.

    Parameters
    ----------
    case : Case
        The validated case (SI).
    beam_action, stability, figures : bool
        The stages of :func:`flexbooster.analyze` that will run.
    """
    if not isinstance(case, Case):
        raise TypeError(f"case = {case!r:.60}: must be a Case, not {type(case).__name__}")
    if case.flight is None:
        raise CaseError("flight", None, "the case has no [flight]: no frozen times to run on "
                        "Dask (run it in one process)")
    case.required_thrust()  # a one-line CaseError on thrust before anything
    vehicle = cost.with_flight(case, cost.estimate_vehicle_cost(case, regions=True, forced=True,
                                                                figures=figures))
    model = None if case.has_segments else model_from_case(case)
    stages = {} if model is None else dict(beam_action=beam_action, stability=stability,
                                            figures=figures)
    return cost.check_case_cost(model, case.max_seconds, vehicle=vehicle, **stages)


def frozen_times_on_dask(case: Case, client: Any) -> tuple[FrozenTime, ...]:
    """``frozen_time(case, i)`` for every frozen time i of the case's flight, one Dask task
    each, in order. The first failing time's error is raised as in one process (a CaseError
    on ``flight.points`` where the thrust buckles the vehicle); on any exit with tasks left
    (an error, Ctrl-C) they are cancelled.

    Parameters
    ----------
    case : Case
        The validated case (SI), with ``[flight]``.
    client : distributed.Client
        The Dask client (:func:`flexbooster.sweep.command.start_client`).
    """
    n = int(flight_times(case).size)
    if n == 0:
        raise CaseError("flight", None, "the case has no [flight]: no frozen times")
    if has_flat_plate(vehicle_from_case(case)):  # the flight stage skips it, with a warning
        return ()
    stamp = time.monotonic_ns()
    futures = [client.submit(frozen_time, case, i, pure=False,
                             key=f"flexbooster-flight-{i}-{stamp}") for i in range(n)]
    done = False
    try:
        frozen = tuple(f.result() for f in futures)
        done = True
    finally:
        if not done:  # closed here, while the client is open: nothing left running
            client.cancel(futures)
    return frozen


def analyze_on_dask(case: Case, client: Any, *, beam_action: bool = True,
                    stability: bool = True, progress: Callable[[str], None] | None = None,
                    figures: bool = True,
                    on_estimate: Callable[[cost.CostEstimate, float], None] | None = None
                    ) -> Results:
    """:func:`flexbooster.analyze` of a case with ``[flight]``, its frozen times on Dask
    (:func:`frozen_times_on_dask`), the rest in this process: the results of
    ``analyze(case, ...)``, bit for bit. The budget is checked first
    (:func:`check_flight_budget`).

    Parameters
    ----------
    case : Case
        The validated case (SI), with ``[flight]``.
    client : distributed.Client
        The Dask client.
    beam_action, stability, figures : bool
        As :func:`flexbooster.analyze`.
    progress : callable, optional
        Called with :data:`FLIGHT_ON_DASK` as the frozen times start, then with each stage
        of :func:`flexbooster.analyze`.
    on_estimate : callable, optional
        As :func:`flexbooster.analyze` (the estimate without the flight, computed already).
    """
    check_flight_budget(case, beam_action=beam_action, stability=stability, figures=figures)
    if progress is not None:
        progress(FLIGHT_ON_DASK)
    frozen = frozen_times_on_dask(case, client)
    return analyze(case, beam_action=beam_action, stability=stability, progress=progress,
                   figures=figures, on_estimate=on_estimate, frozen=frozen)
