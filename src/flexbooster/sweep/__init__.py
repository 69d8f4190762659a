"""Design sweeps: one analysis per point of a grid over case fields, on Dask, to an xarray Dataset.

::

    import flexbooster.sweep
    ds = flexbooster.sweep.sweep("base.toml", {"thrust.gamma": [0.0, 0.05], "thrust.K": [0.2, 1]})
    ds["max_growth_rate"]                 # xarray.DataArray over (thrust.gamma, thrust.K)

Modules: :mod:`.spec` (sweep files, validation), :mod:`.run` (execution, serial or on Dask),
:mod:`.store` (netCDF / zarr, resume), :mod:`.plot` (figure), :mod:`.page` (HTML page),
:mod:`.command` (the ``flexbooster sweep`` command).

The package itself is callable, ``flexbooster.sweep(base_case, axes, client=None)`` being
:func:`flexbooster.sweep.run.sweep`: importing any submodule binds the attribute
``flexbooster.sweep`` to this package, so a lazily exposed top-level *function* of the same
name would be shadowed by it after the first use.  Importing this package imports neither dask
nor xarray (they come with :mod:`.run`).
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
