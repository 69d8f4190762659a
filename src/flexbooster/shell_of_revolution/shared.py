"""The store of work shared within a block: a vehicle's mesh, its harmonics' matrices, their
eigenpairs and the wetted walls' quadrature, computed once and reused (by input identity)."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from contextlib import contextmanager
from contextvars import ContextVar

__all__ = ["shared_harmonics", "shared_value"]

#: Within :func:`shared_harmonics`: the meshes, harmonic matrices and eigenpairs computed so
#: far, keyed by the identity of their inputs (each entry keeps those inputs alive).
_SHARED: ContextVar[dict | None] = ContextVar("shared_harmonics", default=None)


@contextmanager
def shared_harmonics(*, isolated: bool = False) -> Iterator[None]:
    """Within the block, a vehicle's mesh, each harmonic's matrices (shell, liquid, prestress),
    each of its eigenproblems and the wetted walls' quadrature are computed once and reused by
    :func:`~.modes.vehicle_modes`, :func:`~.modes.modal_system`,
    :func:`~.modes.labelled_modal_system` and the stages built on them: the same numbers as
    computing them again (the same operations on the same inputs), at the cost of one
    computation. Inputs are matched by identity (the same :class:`Vehicle` object) and value
    (k, thrust, load path, mesh options); the cached arrays are read-only. Nested blocks share
    the outermost one's store, unless ``isolated``: then the block has a store of its own,
    released at its end (work on another vehicle that nothing after the block reuses, e.g. a
    frozen time of a flight).

    Parameters
    ----------
    isolated : bool
        A store of the block's own, even within another block.
    """
    if _SHARED.get() is not None and not isolated:
        yield
        return
    token = _SHARED.set({})
    try:
        yield
    finally:
        _SHARED.reset(token)


def shared_value(key: tuple, keep: tuple, make: Callable):
    """``make()``, or its stored value within :func:`shared_harmonics`.

    Parameters
    ----------
    key : tuple
        Hashable key: a kind name, the identities of the inputs in ``keep``, their values.
    keep : tuple
        The inputs whose identities are in ``key``, held so that they outlive the entry.
    make : callable
        Computes the value (read-only arrays).
    """
    store = _SHARED.get()
    if store is None:
        return make()
    if key not in store:
        store[key] = (keep, make())
    return store[key][1]
