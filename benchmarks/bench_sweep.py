"""Benchmark: a 64-point design sweep on a local Dask cluster, 2 workers against 1, and the
per-point overhead of the sweep machinery against a plain loop of ``analyze``.

Case: the default booster with n_omega = 16 and M1 = N1 = M2 = N2 = N = S = 4 (R = 2), about
0.1-0.15 s per analysis (beam action and stability table included); axes thrust.gamma (8 values)
x thrust.K (8 values) = 64 points.

Timed, best of ``REPEATS`` (3; env BENCH_REPEATS) interleaved runs of the three, both clusters
started and warmed up (one small sweep) beforehand, so that process start and imports are not
counted (their cost is printed apart):

* baseline: ``for case in cases: analyze(case).to_dict()`` in this process (cases validated
  beforehand, as the sweep does up front);
* ``run_sweep(spec, client=...)`` on a LocalCluster of 1 worker process, then of 2 (1 thread
  each): validation of every point, batching into tasks, transfer, result extraction, store.

Goals: speed-up 2 workers vs 1 >= 1.7; overhead per point (1 worker vs the loop) < 5 %.
Wall times on a shared machine swing with the other users' load (printed), so the CPU time of
the client, scheduler and worker processes is printed too: the machinery's cost in CPU seconds,
whatever the load; and the throughput of two concurrent pure-Python spin processes against one
(the parallelism the machine offers at that moment: 2.0 on two free cores), the ceiling of the
speed-up.

Run:  OPENBLAS_NUM_THREADS=1 python benchmarks/bench_sweep.py   (about a minute)
"""

from __future__ import annotations

import os
import time
import tomllib
from contextlib import ExitStack

from dask.config import set as dask_config

__all__: list[str] = []

REPEATS = int(os.environ.get("BENCH_REPEATS", "3"))


def _spec():
    from flexbooster.case import memo_case_text
    from flexbooster.sweep.spec import make_spec

    data = tomllib.loads(memo_case_text())
    data["thrust"]["n_omega"] = 16
    data["truncation"] = {"M1": 4, "N1": 4, "M2": 4, "N2": 4, "N": 4, "S": 4, "R": 2}
    axes = {
        "thrust.gamma": {"start": 0.0, "stop": 0.35, "num": 8},
        "thrust.K": {"start": 0.2, "stop": 2.0, "num": 8},
    }
    return make_spec(data, axes)


def _spin(n: int) -> float:
    """A pure-Python CPU-bound loop; returns its wall time (s)."""
    start = time.perf_counter()
    total = 0
    for i in range(n):
        total += i
    return time.perf_counter() - start


def _machine_parallelism(n: int = 20_000_000) -> float:
    """Throughput of 2 concurrent CPU-bound processes over 1 (2.0 on two free cores)."""
    from concurrent.futures import ProcessPoolExecutor

    with ProcessPoolExecutor(2) as pool:
        list(pool.map(_spin, [1000, 1000]))  # start both processes
        one = pool.submit(_spin, n).result()
        start = time.perf_counter()
        list(pool.map(_spin, [n, n]))
        two = time.perf_counter() - start
    return 2.0 * one / two


def main() -> None:
    from distributed import Client, LocalCluster

    from flexbooster.analysis import analyze
    from flexbooster.sweep.command import local_cluster_config
    from flexbooster.sweep.run import run_sweep
    from flexbooster.sweep.spec import point_cases

    spec = _spec()
    cases = point_cases(spec)
    n = spec.n_points
    analyze(cases[0]).to_dict()  # warm up this process (imports, caches)

    def loop() -> None:
        for case in cases:
            analyze(case).to_dict()

    def cpu(client=None) -> float:  # noqa: ANN001
        """CPU seconds of this process (client and, for a LocalCluster, its scheduler) and of
        every worker process (nannies excluded)."""
        total = time.process_time()
        if client is not None:
            total += sum(client.run(time.process_time).values())
        return total

    clients = {}
    with ExitStack() as stack:
        for workers in (1, 2):
            start = time.perf_counter()
            stack.enter_context(dask_config(local_cluster_config()))
            cluster = stack.enter_context(
                LocalCluster(
                    n_workers=workers,
                    threads_per_worker=1,
                    processes=True,
                    host="127.0.0.1",
                    dashboard_address=":0",
                )
            )
            clients[workers] = stack.enter_context(Client(cluster))
            warm = _spec_warmup(spec, clients[workers])
            print(
                f"cluster of {workers}: start + warm-up ({warm} points) "
                f"{time.perf_counter() - start:.1f} s (not timed below)"
            )
        times: dict[str, list[float]] = {"loop": [], 1: [], 2: []}
        cpus: dict[str, list[float]] = {"loop": [], 1: [], 2: []}
        for _ in range(REPEATS):  # interleaved, so that a change of machine load hits all three
            start, cpu0 = time.perf_counter(), cpu()
            loop()
            times["loop"].append(time.perf_counter() - start)
            cpus["loop"].append(cpu() - cpu0)
            for workers, client in clients.items():
                start, cpu0 = time.perf_counter(), cpu(client)
                ds = run_sweep(spec, client=client, cases=cases)
                times[workers].append(time.perf_counter() - start)
                cpus[workers].append(cpu(client) - cpu0)
                status = ds["status"].values.reshape(-1).tolist()
                assert status.count("ok") == n, "a benchmark point failed"
    best = {key: min(values) for key, values in times.items()}
    labels = (("loop", "plain loop"), (1, "sweep, 1 worker"), (2, "sweep, 2 workers"))
    for key, label in labels:
        runs = ", ".join(f"{x:.2f}" for x in times[key])
        print(
            f"{label:<16}: {n} points, best {best[key]:6.2f} s "
            f"({best[key] / n * 1e3:6.1f} ms/point; runs {runs} s)"
        )
    parallelism = _machine_parallelism()
    speedup = best[1] / best[2]
    overhead = (best[1] - best["loop"]) / best["loop"]
    cpu_best = {key: min(values) for key, values in cpus.items()}
    print(f"speed-up 2 vs 1 worker : {speedup:5.2f}  (goal >= 1.7)")
    print(
        f"machine, 2 spin processes vs 1: {parallelism:5.2f} (what 2 processes can get now; "
        "2.0 on two free cores)"
    )
    print(f"overhead per point     : {overhead * 100:+5.1f} %  (goal < 5 %, 1 worker vs loop)")
    for key in (1, 2):
        extra = (cpu_best[key] - cpu_best["loop"]) / cpu_best["loop"]
        print(
            f"CPU time, {key} worker{'s' if key > 1 else ' '}: {cpu_best[key]:6.2f} s vs loop "
            f"{cpu_best['loop']:6.2f} s: {extra * 100:+5.1f} % (less sensitive to machine load)"
        )
    print(f"load average           : {' '.join(f'{x:.2f}' for x in os.getloadavg())}")


def _spec_warmup(spec, client) -> int:
    """Run a few points on every worker (imports, caches), not timed; returns the points run."""
    from flexbooster.sweep.run import run_sweep
    from flexbooster.sweep.spec import make_spec

    workers = len(client.scheduler_info()["workers"])
    warm = make_spec(spec.base, {"thrust.gamma": [0.05] * (2 * workers)})
    run_sweep(warm, client=client, batch_size=1)
    return warm.n_points


if __name__ == "__main__":
    main()
