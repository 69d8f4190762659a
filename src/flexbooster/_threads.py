"""BLAS thread limit around the analysis (threadpoolctl): its many small batched eigenproblems
run fastest with one BLAS thread; the user's setting is restored afterwards."""

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
    """
    from threadpoolctl import threadpool_limits

    with threadpool_limits(limits=int(limit), user_api="blas"):
        yield
