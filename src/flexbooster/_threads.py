"""BLAS thread limits around the small batched eigen-solves (threadpoolctl).

Multithreaded OpenBLAS makes the many small eigenproblems of the pipeline 2-100x slower (the
threads spin and contend): measured 6.0 s instead of 2.5 s for the default case with
OPENBLAS_NUM_THREADS unset (issue 11).  :func:`analyze` therefore runs with one BLAS thread;
the user's setting is restored afterwards.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager

__all__ = ["blas_threads"]


@contextmanager
def blas_threads(limit: int = 1) -> Iterator[None]:
    """Limit the BLAS thread pools (OpenBLAS, MKL, BLIS) inside the ``with`` block.

    Parameters
    ----------
    limit : int
        Threads per BLAS pool (>= 1).

    Yields
    ------
    None
    """
    from threadpoolctl import threadpool_limits

    with threadpool_limits(limits=int(limit), user_api="blas"):
        yield
