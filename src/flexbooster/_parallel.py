"""Independent pieces of work in worker processes: the pipeline's and the outputs' parallelism.

The costly stages of a run are independent once the derived model exists (the beam-action
exponents, the beam-action chart's boundary tracing, the vehicle regions) and so are the
figures once the results exist: matplotlib draws one figure on one core, and the numerical
stages are loops of small batched numpy operations that hold the GIL between them, so
threads do not help; processes do.  :class:`TaskPool` runs functions in ``fork``-ed worker
processes (the parent's imports and data are inherited, nothing is re-imported) and falls back
to running them in the calling process when one worker is asked for, when the platform has no
``fork``, or inside a daemonic process (a Dask or multiprocessing worker may not have
children).  Each task is a pure function of its arguments, so the numbers are the same either
way, bit for bit (a test checks it).

Interrupts: the workers ignore SIGINT (Ctrl-C reaches the whole process group; the parent
alone decides) and are terminated when the ``with`` block is left by an exception, so Ctrl-C or
SIGTERM in the parent stops them at once and leaves no orphan.
"""

from __future__ import annotations

import multiprocessing
import os
import pickle
import signal
import threading
import warnings
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

__all__ = ["TaskPool", "default_workers", "using_pool", "beside", "MAX_WORKERS"]

#: Most worker processes a pool starts (the pipeline has at most a few independent stages).
MAX_WORKERS = 8


def default_workers() -> int:
    """Worker processes worth starting here: the usable CPUs, at most :data:`MAX_WORKERS`.

    Returns
    -------
    int
        ``len(os.sched_getaffinity(0))`` where available (the CPUs this process may run on,
        e.g. under ``taskset`` or a container's CPU set), else ``os.cpu_count()``; at least 1.
    """
    try:
        n = len(os.sched_getaffinity(0))
    except (AttributeError, OSError):  # not Linux
        n = os.cpu_count() or 1
    return max(1, min(n, MAX_WORKERS))


def _usable(workers: int) -> bool:
    return (workers > 1 and "fork" in multiprocessing.get_all_start_methods()
            and not multiprocessing.current_process().daemon)


def _ignore_interrupts() -> None:  # worker initialiser: the parent handles Ctrl-C
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)


class _Done:
    """A task run in the calling process: its value (or its exception) when asked for."""

    def __init__(self, fn: Callable[..., Any], args: tuple, kwargs: dict):
        self._fn, self._args, self._kwargs = fn, args, kwargs

    def result(self) -> Any:
        fn, self._fn = self._fn, None
        if fn is not None:  # run on first demand, once
            self._value = fn(*self._args, **self._kwargs)
        return self._value


class _Async:
    def __init__(self, handle):
        self._handle = handle

    def result(self) -> Any:
        return self._handle.get()


class TaskPool:
    """Run independent functions in worker processes (a context manager).

    Parameters
    ----------
    workers : int
        Worker processes (dimensionless), >= 1; 1 runs every task in the calling process,
        when its result is asked for.

    Examples
    --------
    >>> from flexbooster._parallel import TaskPool
    >>> with TaskPool(2) as pool:
    ...     job = pool.submit(sum, [1, 2, 3])
    ...     job.result()
    6

    Notes
    -----
    Functions and arguments must be picklable (module-level functions; dataclasses of numpy
    arrays); results come back by pickle.  The pool is created on the first :meth:`submit`
    (a ``with`` block with nothing submitted costs nothing).
    """

    def __init__(self, workers: int):
        if isinstance(workers, bool) or not isinstance(workers, int) or workers < 1:
            raise ValueError(f"workers = {workers!r}: must be an integer >= 1")
        self.workers = min(int(workers), MAX_WORKERS)
        self._pool = None
        self._lock = threading.Lock()  # the pool's result thread runs the callbacks
        self._running = 0  # tasks sent to the workers and not finished
        self._idle: list[tuple[Callable[..., Any], tuple, dict]] = []

    @property
    def parallel(self) -> bool:
        """Whether tasks run in worker processes (False: in the calling process)."""
        return _usable(self.workers)

    def submit(self, fn: Callable[..., Any], /, *args: Any, **kwargs: Any):
        """Start ``fn(*args, **kwargs)``; returns an object whose ``result()`` waits for it.

        Parameters
        ----------
        fn : callable
            A module-level (picklable) function.
        *args, **kwargs
            Its arguments.

        Returns
        -------
        object
            With a ``result()`` method: the return value, or the task's exception raised.
        """
        if not self.parallel:
            return _Done(fn, args, kwargs)
        with self._lock:
            return _Async(self._send(fn, args, kwargs))

    def submit_when_idle(self, fn: Callable[..., Any], /, *args: Any, **kwargs: Any) -> None:
        """Run ``fn(*args, **kwargs)`` in a worker that has finished a task and has no other.

        For preparation off the critical path (e.g. importing what later tasks need while the
        workers would wait for the parent): the task is held back until a worker finishes a
        task while fewer are running than there are workers, so it never delays a task
        submitted before or after it that could run then.  Its result is dropped; one still
        held back when the ``with`` block ends is not run, nor is any without worker
        processes.

        Parameters
        ----------
        fn : callable
            A module-level (picklable) function.
        *args, **kwargs
            Its arguments.
        """
        if self.parallel:
            with self._lock:
                self._idle.append((fn, args, kwargs))

    def _send(self, fn, args, kwargs):  # with the lock held
        if self._pool is None:
            self._pool = multiprocessing.get_context("fork").Pool(
                self.workers, initializer=_ignore_interrupts)
        self._running += 1
        return self._pool.apply_async(fn, args, kwargs, callback=self._finished,
                                      error_callback=self._finished)

    def _finished(self, _: object) -> None:  # in the pool's result thread
        with self._lock:
            self._running -= 1
            if self._idle and self._running < self.workers and self._pool is not None:
                self._send(*self._idle.pop(0))  # a worker has nothing to do

    def map(self, fn: Callable[[Any], Any], items) -> list:
        """``[fn(x) for x in items]``, the items spread over the workers (in order).

        Parameters
        ----------
        fn : callable
            A module-level (picklable) function of one argument.
        items : iterable
            Its arguments.

        Returns
        -------
        list
            The results, in the order of ``items``.
        """
        jobs = [self.submit(fn, x) for x in items]
        return [j.result() for j in jobs]

    def share(self, fn: Callable[[Any], Any], items) -> list:
        """``[fn(x) for x in items]``: the first item computed in this process while the
        workers compute the others (all of them here without workers).

        Parameters
        ----------
        fn : callable
            A module-level (picklable) function of one argument.
        items : sequence
            Its arguments; the first one for this process.

        Returns
        -------
        list
            The results, in the order of ``items``.
        """
        items = list(items)
        jobs = [self.submit(fn, x) for x in items[1:]]
        return [fn(items[0]), *(j.result() for j in jobs)] if items else []

    def __enter__(self) -> TaskPool:
        return self

    def __exit__(self, exc_type, exc, tb) -> None:
        with self._lock:
            self._idle.clear()
            pool, self._pool = self._pool, None
        if pool is None:
            return
        if exc_type is None:
            pool.close()
        else:  # an error or an interrupt in the parent: stop the workers now
            pool.terminate()
        pool.join()


@contextmanager
def using_pool(workers: int | TaskPool) -> Iterator[TaskPool]:
    """The pool to run a stage's tasks in: ``workers`` itself when it is a :class:`TaskPool`
    (one pool shared by several stages, closed by its owner), else a new one for the block.

    Parameters
    ----------
    workers : int or TaskPool
        Worker processes (dimensionless, >= 1), or a pool opened by the caller.

    Yields
    ------
    TaskPool
    """
    if isinstance(workers, TaskPool):
        yield workers
    else:
        with TaskPool(workers) as pool:
            yield pool


class _Beside:
    """``fn(*args)`` in a forked child process; :meth:`result` reads its value back, or calls
    ``fn(*args)`` in this process where the child could not give one."""

    def __init__(self, fn: Callable[..., Any], args: tuple):
        self._fn, self._args = fn, args
        self._pid = self._fd = None
        if not _usable(2) or threading.active_count() > 1:
            return
        read, write = os.pipe()
        pid = os.fork()
        if pid == 0:  # the child: the value pickled into the pipe, or an exit status of 1
            status = 1
            try:
                os.close(read)  # Ctrl-C or SIGTERM ends it (its handlers are the parent's)
                with warnings.catch_warnings(record=True) as caught:  # the filters as here
                    data = pickle.dumps(fn(*args), protocol=pickle.HIGHEST_PROTOCOL)
                if not caught:  # a warning is the parent's to show: it computes it again
                    view = memoryview(data)
                    while view:
                        view = view[os.write(write, view):]
                    status = 0
            except BaseException:  # noqa: BLE001, S110 - any failure: the parent computes it
                pass
            finally:
                os._exit(status)  # no atexit handlers, no flush of the parent's buffers
        os.close(write)
        self._pid, self._fd = pid, read

    def result(self) -> Any:
        pid, self._pid = self._pid, None
        fn, self._fn = self._fn, None
        if fn is None:  # asked for again
            return self._value
        data = b""
        if pid is not None:
            try:
                with os.fdopen(self._fd, "rb") as pipe:
                    data = pipe.read()
            except BaseException:  # an interrupt here: the child goes too
                os.kill(pid, signal.SIGKILL)
                raise
            finally:
                _, status = os.waitpid(pid, 0)
            data = data if status == 0 else b""
        self._value = pickle.loads(data) if data else fn(*self._args)
        return self._value


def beside(fn: Callable[..., Any], /, *args: Any) -> _Beside:
    """Start ``fn(*args)`` in a child process forked now, while this process goes on.

    For work at the start of a command that needs few modules, while this process imports the
    many that the rest needs (``flexbooster run``: the case file read and validated, pint
    imported, while this process imports numpy, scipy and the analysis): on two cores the
    second one is otherwise idle then.

    Parameters
    ----------
    fn : callable
        A function of ``args`` whose value pickles; pure: it may run twice (in the child,
        then here where the child gave no value).
    *args
        Its arguments.

    Returns
    -------
    object
        With a ``result()`` method: the child's value.  Where there is no child (no ``fork``,
        a daemonic process, a process with other threads, one of which might hold a lock that
        the child would wait for) or it gave no value (an exception, a warning, a signal),
        ``result()`` calls ``fn(*args)`` in this process, so that an error or a warning is
        raised or shown here, as without the child.
    """
    return _Beside(fn, args)
