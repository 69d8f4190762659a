"""Running a sweep: every point is one :func:`flexbooster.analyze`, serially or on Dask.

Points are validated up front, then analysed in batches of about
:data:`TARGET_TASK_SECONDS` per Dask task; an exception or non-finite result in a point (or
a dead worker's batch) is recorded in its ``status`` / ``message`` and the sweep goes on.
Each point is bit-identical to a serial ``analyze(case)``.
"""

from __future__ import annotations

import contextlib
import inspect
import math
import time
from collections import deque
from collections.abc import Callable, Iterator, Mapping, Sequence
from pathlib import Path
from typing import Any

from .spec import SweepSpec, make_spec, point_cases
from .store import STATUS_ERROR, STATUS_OK, PointResult, build_template, open_sink

__all__ = [
    "RESULT_VARIABLES",
    "TARGET_TASK_SECONDS",
    "result_variables",
    "point_scalars",
    "analyze_point",
    "analyze_batch",
    "run_sweep",
    "sweep",
]

#: Wall time one Dask task aims at (s): large enough to hide the per-task overhead
#: (about 1 ms), small enough to stream results and balance the workers.
TARGET_TASK_SECONDS = 0.5
#: Tasks kept in flight per worker.
_IN_FLIGHT_PER_WORKER = 2

#: Scalar results stored per point: name -> (units, description with the memo's section).
RESULT_VARIABLES: dict[str, tuple[str, str]] = {
    "omega_1": ("rad/s", "first free-free bending frequency of the equivalent beam (memo 4.2-8b)"),
    "omega_psi": ("rad/s", "rigid-body pitch frequency sqrt(F0 d2 K / I_cm) (memo 4.2)"),
    "shell_min_frequency": ("rad/s", "lowest shell natural frequency (memo 5.4, 6.2)"),
    "pitch_max_growth_rate": ("1/s", "largest rigid-body pitch growth rate over its bands"),
    "pitch_unstable_regions": ("1", "instability bands of the rigid-body pitch (4.2), from "
                                    "their edges"),
    "beam_action_max_growth_rate": ("1/s", "largest beam-action growth rate over its bands"),
    "beam_action_unstable_bands": ("1", "instability bands of the beam action (4.1), from "
                                        "their edges"),
    "beam_action_Omega_at_max": ("rad/s", "Omega of the largest beam-action growth rate"),
    "max_growth_rate": ("1/s", "largest of the pitch and beam-action growth rates"),
    "stability_count": ("1", "unstable thrust frequencies (roots of memo 7.3) in the range"),
    "stability_active": ("1", "of which with active forcing (memo 7.3)"),
    "n_warnings": ("1", "analysis warnings of the point"),
}
_BEAM_ACTION_VARIABLES = {
    "beam_action_max_growth_rate",
    "beam_action_unstable_bands",
    "beam_action_Omega_at_max",
}
_STABILITY_VARIABLES = {"stability_count", "stability_active"}


def result_variables(*, beam_action: bool = True, stability: bool = True) -> dict:
    """Name -> (units, description) of the result variables a sweep with these stages stores.

    Parameters
    ----------
    beam_action, stability : bool
        The stages computed; stability needs beam_action.
    """
    skip = set()
    if not beam_action:
        skip |= _BEAM_ACTION_VARIABLES | _STABILITY_VARIABLES
    if not stability:
        skip |= _STABILITY_VARIABLES
    return {k: v for k, v in RESULT_VARIABLES.items() if k not in skip}


def point_scalars(data: Mapping[str, Any]) -> dict[str, float]:
    """The scalar results of one analysis (SI: rad/s, 1/s, counts), read from results.json: the
    one place that maps its schema to the sweep's variables.

    Parameters
    ----------
    data : Mapping
        ``flexbooster.analyze(case).to_dict()``.
    """
    freq, pitch = data["frequencies"], data["pitch"]
    if isinstance(freq["omega_1"], Mapping):  # {"not_applicable": reason}: a segments case
        raise ValueError(f"omega_1: the sweep's variables are the memo's, "
                         f"{freq['omega_1']['not_applicable']}")
    # instability from the bands (exact edges), never from grid samples
    out = {
        "omega_1": float(freq["omega_1"]),
        "omega_psi": float(freq["omega_psi"]),
        "shell_min_frequency": float(min(data["shell_frequencies"]["rad_s"])),
        "pitch_max_growth_rate": float(max((b["growth_rate_max"] for b in pitch["bands"]),
                                           default=0.0)),
        "pitch_unstable_regions": float(len(pitch["bands"])),
        "n_warnings": float(len(data["warnings"])),
    }
    growth = [out["pitch_max_growth_rate"]]
    action = data.get("beam_action")
    if action is not None:
        peak = max(action["bands"], key=lambda b: b["growth_rate_max"], default=None)
        out["beam_action_max_growth_rate"] = 0.0 if peak is None else float(peak["growth_rate_max"])
        out["beam_action_unstable_bands"] = float(len(action["bands"]))
        out["beam_action_Omega_at_max"] = 0.0 if peak is None else float(peak["Omega_at_max"])
        growth.append(out["beam_action_max_growth_rate"])
    out["max_growth_rate"] = max(growth)
    table = data.get("stability")
    if table is not None:
        out["stability_count"] = float(table["count"])
        out["stability_active"] = float(table["active"])
    return out


def _analysis_options(analyze: Callable, *, beam_action: bool, stability: bool) -> dict:
    """Keyword arguments of ``analyze`` for a sweep point: the stages, no figure data and no
    vehicle regions (not stored by a sweep).
    """
    options = {"beam_action": beam_action, "stability": stability}
    parameters = inspect.signature(analyze).parameters
    if "figures" in parameters:
        options["figures"] = False
    if "vehicle" in parameters:  # the vehicle's parametric regions: not a sweep variable yet
        options["vehicle"] = False
    return options


def analyze_point(
    index: int, case: Any, *, beam_action: bool = True, stability: bool = True
) -> PointResult:
    """Analyse one point: ``ok`` with :func:`point_scalars`, or ``error`` with ``"ExceptionType:
    message"`` (also for a non-finite number).

    Parameters
    ----------
    index : int
        Flat index of the point.
    case : flexbooster.Case
        The validated case.
    beam_action, stability : bool
        Stages passed to :func:`flexbooster.analyze`.
    """
    from ..analysis import analyze

    start = time.perf_counter()
    try:
        options = _analysis_options(analyze, beam_action=beam_action, stability=stability)
        data = analyze(case, **options).to_dict()
        values = point_scalars(data)
        # only the stored numbers are checked (walking the whole results.json would cost
        # about a fifth of the analysis time)
        bad = [name for name, value in values.items() if not math.isfinite(value)]
        if bad:
            raise ValueError(f"{bad[0]} = {values[bad[0]]!r}: a result must be finite")
    except Exception as exc:  # recorded per point: one failure does not stop the sweep
        message = f"{type(exc).__name__}: {exc}".replace("\n", " ")
        return PointResult(index, STATUS_ERROR, message, {}, time.perf_counter() - start)
    return PointResult(index, STATUS_OK, "", values, time.perf_counter() - start)


def analyze_batch(
    indices: Sequence[int], cases: Sequence[Any], *, beam_action: bool, stability: bool
) -> list[PointResult]:
    """Analyse a batch of points (one Dask task), one PointResult per point in order.

    Parameters
    ----------
    indices : sequence of int
        Flat indices of the points.
    cases : sequence of flexbooster.Case
        Their validated cases.
    beam_action, stability : bool
        Stages passed to :func:`flexbooster.analyze`.
    """
    return [
        analyze_point(i, c, beam_action=beam_action, stability=stability)
        for i, c in zip(indices, cases, strict=True)
    ]


def _serial(
    todo: Sequence[int], cases: Sequence[Any], spec: SweepSpec, batch_size: int | None
) -> Iterator[list[PointResult]]:
    batch: list[PointResult] = []
    last = time.perf_counter()
    for i in todo:
        batch.append(
            analyze_point(i, cases[i], beam_action=spec.beam_action, stability=spec.stability)
        )
        full = len(batch) >= batch_size if batch_size else time.perf_counter() - last >= 1.0
        if full:
            yield batch
            batch, last = [], time.perf_counter()
    if batch:
        yield batch


def _n_workers(client: Any) -> int:
    workers = client.scheduler_info().get("workers", {})
    if workers:
        return len(workers)
    client.wait_for_workers(1, timeout=60)
    return max(1, len(client.scheduler_info().get("workers", {})))


def _distributed(
    todo: Sequence[int],
    cases: Sequence[Any],
    spec: SweepSpec,
    client: Any,
    batch_size: int | None,
) -> Iterator[list[PointResult]]:
    from distributed import as_completed

    n_workers = _n_workers(client)
    queue = deque(todo)
    measured = [0.0, 0]  # seconds, points
    batches: dict[Any, list[int]] = {}

    def take() -> list[int]:
        if batch_size:
            n = batch_size
        elif measured[1] == 0:
            n = 1  # first tasks: one point each, to measure the time per point
        else:
            per_point = max(measured[0] / measured[1], 1e-6)
            n = max(1, round(TARGET_TASK_SECONDS / per_point))
            # the tail: keep every worker busy until the end
            n = min(n, max(1, math.ceil(len(queue) / (_IN_FLIGHT_PER_WORKER * n_workers))))
        return [queue.popleft() for _ in range(min(n, len(queue)))]

    def submit(ac: Any) -> None:
        indices = take()
        if indices:
            future = client.submit(
                analyze_batch,
                indices,
                [cases[i] for i in indices],
                beam_action=spec.beam_action,
                stability=spec.stability,
                pure=False,
                key=f"flexbooster-sweep-{indices[0]}-{time.monotonic_ns()}",
            )
            batches[future] = indices
            ac.add(future)

    ac = as_completed()
    try:
        for _ in range(_IN_FLIGHT_PER_WORKER * n_workers):
            submit(ac)
        for future in ac:
            indices = batches.pop(future)
            try:
                results = future.result()
            except Exception as exc:  # the task itself failed (a worker died): record it
                message = f"task failed: {type(exc).__name__}: {exc}".replace("\n", " ")
                results = [PointResult(i, STATUS_ERROR, message, {}, 0.0) for i in indices]
            measured[0] += sum(r.seconds for r in results)
            measured[1] += len(results)
            submit(ac)
            yield results
    finally:
        if batches:
            client.cancel(list(batches))


def run_sweep(
    spec: SweepSpec,
    *,
    client: Any = None,
    store: str | Path | None = None,
    resume: bool = False,
    progress: Callable[[int, int, int], None] | None = None,
    batch_size: int | None = None,
    cases: Sequence[Any] | None = None,
) -> Any:
    """Run a parsed sweep: validate every point, analyse the ones not stored, store the results
    (layout in :mod:`flexbooster.sweep.store`). CaseError before anything runs for an invalid
    point or a store of another sweep; ValueError for a bad ``batch_size``.

    Parameters
    ----------
    spec : SweepSpec
        From :func:`flexbooster.sweep.spec.load_sweep` or :func:`make_spec`.
    client : distributed.Client, optional
        Run on this Dask cluster; None: serially in this process.
    store : str or pathlib.Path, optional
        ``*.nc`` or ``*.zarr`` output (zarr: streamed per batch); None: memory only.
    resume : bool
        Keep the points already in ``store`` (of the same sweep).
    progress : callable, optional
        ``progress(done, failed, total)``, at the start and after each batch.
    batch_size : int, optional
        Points per task, >= 1; default about :data:`TARGET_TASK_SECONDS` per task.
    cases : sequence of flexbooster.Case, optional
        The points' validated cases if already made by :func:`point_cases`.
    """
    if batch_size is not None and (
        isinstance(batch_size, bool) or not isinstance(batch_size, int) or batch_size < 1
    ):
        raise ValueError(f"batch_size = {batch_size!r}: must be a positive integer")
    cases = point_cases(spec) if cases is None else list(cases)
    if len(cases) != spec.n_points:
        raise ValueError(f"cases = {len(cases)} cases: the sweep has {spec.n_points} points")
    variables = result_variables(beam_action=spec.beam_action, stability=spec.stability)
    sink = open_sink(store, build_template(spec, cases, variables=variables), resume=resume)
    report = progress or (lambda done, failed, total: None)
    try:
        todo = sink.pending()
        report(*sink.counts(), spec.n_points)
        if client is None:
            batches = _serial(todo, cases, spec, batch_size)
        else:
            batches = _distributed(todo, cases, spec, client, batch_size)
        # closed here, on any exit (Ctrl-C included): its tasks are cancelled while the
        # client is open, never later by the garbage collector
        with contextlib.closing(batches):
            for results in batches:
                sink.write(results)
                report(*sink.counts(), spec.n_points)
    finally:
        sink.close()
    ds = sink.dataset()
    ds.attrs["points_computed_this_run"] = sink.computed_now
    return ds


def sweep(
    base_case: Any,
    axes: Mapping[str, Any],
    client: Any = None,
    *,
    mode: str = "product",
    beam_action: bool = True,
    stability: bool = True,
    store: str | Path | None = None,
    resume: bool = False,
    progress: Callable[[int, int, int], None] | None = None,
    batch_size: int | None = None,
) -> Any:
    """A design sweep: the base case analysed at every point of the axes, as an xarray Dataset
    (one dimension per axis, a variable per scalar result, ``status``, ``message``,
    ``computed``); CaseError before anything runs for an invalid value (docs/sweeps.md).

    Parameters
    ----------
    base_case : flexbooster.Case or Mapping or str or pathlib.Path
        The base case: validated, a raw mapping (units allowed) or a case file.
    axes : Mapping
        Dotted case field -> list of values, or ``{start, stop, num}`` with ``scale = "log"``.
    client : distributed.Client, optional
        Run on this Dask cluster; None: serially in this process.
    mode : str
        ``"product"`` (one dimension per axis) or ``"zip"``.
    beam_action, stability : bool
        Stages passed to :func:`flexbooster.analyze` for every point.
    store : str or pathlib.Path, optional
        ``*.nc`` or ``*.zarr`` file to write (zarr: streamed per batch).
    resume : bool
        Keep the points already in ``store``.
    progress : callable, optional
        ``progress(done, failed, total)``.
    batch_size : int, optional
        Points per Dask task (default: automatic, about 0.5 s per task).
    """
    spec = make_spec(base_case, axes, mode=mode, beam_action=beam_action, stability=stability)
    return run_sweep(
        spec, client=client, store=store, resume=resume, progress=progress, batch_size=batch_size
    )
