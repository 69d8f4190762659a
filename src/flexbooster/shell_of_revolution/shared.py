"""The stores of work shared within a block: a vehicle's harmonics' matrices, their eigenpairs
and the wetted walls' quadrature; and, across the vehicles of one shell (the frozen times of a
flight, whose tanks' fills differ), the shell's mesh and each harmonic's fill-independent
matrices. Computed once and reused (by input identity)."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from contextlib import contextmanager
from contextvars import ContextVar

__all__ = ["shared_harmonics", "shared_shell", "shared_value", "shell_value"]

#: Within :func:`shared_harmonics`: the meshes, harmonic matrices and eigenpairs computed so
#: far, keyed by the identity of their inputs (each entry keeps those inputs alive).
_SHARED: ContextVar[dict | None] = ContextVar("shared_harmonics", default=None)
#: Within :func:`shared_shell`: the meshes and the harmonics' shell matrices computed so far.
_SHELL: ContextVar[dict | None] = ContextVar("shared_shell", default=None)


@contextmanager
def shared_harmonics(*, isolated: bool = False) -> Iterator[None]:
    """Within the block, a vehicle's mesh, each harmonic's matrices (shell, liquid, prestress),
    each of its eigenproblems and the wetted walls' quadrature are computed once and reused by
    :func:`~.modes.vehicle_modes`, :func:`~.modes.modal_system`,
    :func:`~.modes.labelled_modal_system` and the stages built on them: the same numbers as
    computing them again (the same operations on the same inputs), at the cost of one
    computation. Inputs are matched by identity (the same :class:`Vehicle` object; a mesh by
    the same segments) and value (k, thrust, load path, mesh options); the cached arrays are
    read-only. Nested blocks share the outermost one's store, unless ``isolated``: then the
    block has a store of its own, released at its end (work on another vehicle that nothing
    after the block reuses, e.g. a frozen time of a flight).

    Parameters
    ----------
    isolated : bool
        A store of the block's own, even within another block.
    """
    with _block(_SHARED, isolated=isolated):
        yield


@contextmanager
def _block(store: ContextVar, *, isolated: bool) -> Iterator[None]:
    """A new empty ``store`` for the block, unless one is open and not ``isolated``."""
    if store.get() is not None and not isolated:
        yield
        return
    token = store.set({})
    try:
        yield
    finally:
        store.reset(token)


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
    return make() if store is None else _stored(store, key, keep, make)


def _stored(store: dict, key: tuple, keep: tuple, make: Callable):
    """The value of ``key`` in ``store``, made and stored (with ``keep``) the first time."""
    if key not in store:
        store[key] = (keep, make())
    return store[key][1]


@contextmanager
def shared_shell() -> Iterator[None]:
    """Within the block, what depends on the shell alone (its segments, ends, junctions, theory
    and lumped masses, not its tanks) is computed once for every vehicle that shares it, even
    across :func:`shared_harmonics` blocks of their own: the mesh (by the identity of the
    segments) and each harmonic's DOF map, element fields, mass and elastic stiffness
    (:func:`~.assembly.shell_harmonic`). The same numbers as computing them again; e.g. the
    frozen times of a flight, each vehicle a block of its own. Nested blocks share the
    outermost one's store."""
    with _block(_SHELL, isolated=False):
        yield


def shell_value(key: tuple, keep: tuple, make: Callable):
    """``make()``, or its stored value: within :func:`shared_shell` from its store, else as
    :func:`shared_value`.

    Parameters
    ----------
    key, keep, make
        As :func:`shared_value` (``key`` holds only what the shell's value depends on).
    """
    store = _SHELL.get()
    return shared_value(key, keep, make) if store is None else _stored(store, key, keep, make)
