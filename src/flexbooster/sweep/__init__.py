"""Design sweeps: one analysis per point of a grid over case fields, on Dask, to an xarray Dataset.

``flexbooster.sweep.sweep("base.toml", {"thrust.gamma": [0.0, 0.05]})``; modules :mod:`.spec`,
:mod:`.run`, :mod:`.store`, :mod:`.plot`, :mod:`.page`, :mod:`.command`. The package is
callable as :func:`flexbooster.sweep.run.sweep` (a function of that name would be shadowed by
the package once a submodule is imported); importing it imports neither dask nor xarray.
"""

from __future__ import annotations

import sys
import types
from importlib import import_module

__all__ = ["sweep", "run_sweep", "load_sweep", "make_spec"]

_LAZY = {
    "sweep": "run",
    "run_sweep": "run",
    "load_sweep": "spec",
    "make_spec": "spec",
}


def __getattr__(name: str):
    if name in _LAZY:
        return getattr(import_module(f".{_LAZY[name]}", __name__), name)
    raise AttributeError(f"module 'flexbooster.sweep' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(__all__)


class _CallableModule(types.ModuleType):
    """This package, callable as :func:`flexbooster.sweep.run.sweep`."""

    def __call__(self, *args, **kwargs):
        from .run import sweep

        return sweep(*args, **kwargs)


sys.modules[__name__].__class__ = _CallableModule
