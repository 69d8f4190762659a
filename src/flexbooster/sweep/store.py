"""Where sweep results go: memory, a netCDF file (h5netcdf) or a zarr store streamed per batch.

One layout for all three (docs/sweeps.md): a dimension per axis (or ``point`` in zip mode),
a float64 variable per scalar result (NaN: failed or pending), ``status``, ``message``,
``computed``, and the attributes ``sweep_json`` and ``sweep_fingerprint`` (``--resume``
refuses another sweep's store). A zarr store takes each batch at once (status last, Ctrl-C
held); a netCDF file is written atomically at the end or on interruption, unfinished points
``pending``.
"""

from __future__ import annotations

import json
import os
import shutil
import signal
import tempfile
import threading
from collections.abc import Iterator, Mapping, Sequence
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import xarray as xr

from .. import __version__
from ..errors import CaseError
from .spec import SweepSpec, si_value

__all__ = [
    "LAYOUT_VERSION",
    "STATUS_PENDING",
    "STATUS_OK",
    "STATUS_ERROR",
    "PointResult",
    "MemorySink",
    "NetcdfSink",
    "ZarrSink",
    "build_template",
    "open_sink",
]

#: Version of the dataset layout; a store of another layout is not resumed.
LAYOUT_VERSION = "1"
STATUS_PENDING, STATUS_OK, STATUS_ERROR = "pending", "ok", "error"


@dataclass(frozen=True)
class PointResult:
    """The outcome of one point: flat index, status, message and scalar results.

    Attributes
    ----------
    index : int
        Flat (C-order) index of the point.
    status : str
        ``"ok"`` or ``"error"``.
    message : str
        The error message (``""`` when ok).
    values : dict
        Scalar result name -> float (SI).
    seconds : float
        Wall time of the analysis on the worker (s), to size batches; not stored.
    """

    index: int
    status: str
    message: str
    values: dict = field(default_factory=dict)
    seconds: float = 0.0

    def to_dict(self) -> dict:
        """JSON-ready form."""
        return {
            "index": int(self.index),
            "status": self.status,
            "message": self.message,
            "values": {k: float(v) for k, v in self.values.items()},
            "seconds": float(self.seconds),
        }


def _coordinate(values: Sequence) -> np.ndarray:
    if all(isinstance(v, int | float) and not isinstance(v, bool) for v in values):
        return np.asarray(values)
    return np.asarray([str(v) for v in values], dtype=object)


def build_template(
    spec: SweepSpec, cases: Sequence, *, variables: Mapping[str, tuple[str, str]]
) -> xr.Dataset:
    """The empty result dataset of a sweep: result variables NaN, ``status`` ``"pending"``,
    ``message`` ``""``, ``computed`` 0 (CF ``units`` / ``long_name`` attributes).

    Parameters
    ----------
    spec : SweepSpec
        The sweep.
    cases : sequence of flexbooster.Case
        The validated case of every point (flat C order), for the SI axis values.
    variables : Mapping
        Result variable name -> (units, description).
    """
    shape, dims = spec.shape, spec.dims
    coords: dict[str, xr.Variable] = {}
    if spec.mode == "zip":
        coords["point"] = xr.Variable(("point",), np.arange(shape[0]), {"units": "1"})
        for axis in spec.axes:
            data = _coordinate([si_value(case, axis.name) for case in cases])
            coords[axis.name] = xr.Variable(("point",), data, _axis_attrs(axis))
    else:
        strides = [int(np.prod(shape[i + 1 :])) for i in range(len(shape))]
        for axis, stride, n in zip(spec.axes, strides, shape, strict=True):
            data = _coordinate([si_value(cases[k * stride], axis.name) for k in range(n)])
            coords[axis.name] = xr.Variable((axis.name,), data, _axis_attrs(axis))
    data_vars = {
        name: xr.Variable(dims, np.full(shape, np.nan), {"units": units, "long_name": text})
        for name, (units, text) in variables.items()
    }
    data_vars["status"] = xr.Variable(
        dims, np.full(shape, STATUS_PENDING, dtype=object), {"long_name": "pending, ok or error"}
    )
    data_vars["message"] = xr.Variable(
        dims, np.full(shape, "", dtype=object), {"long_name": "error message of the point"}
    )
    data_vars["computed"] = xr.Variable(
        dims,
        np.zeros(shape, dtype=np.int32),
        {"units": "1", "long_name": "times the point was analysed (1 after a complete sweep)"},
    )
    attrs = {
        "title": "flexbooster design sweep (Tech Memo 104)",
        "flexbooster_version": __version__,
        "layout_version": LAYOUT_VERSION,
        "sweep_mode": spec.mode,
        "sweep_fingerprint": spec.fingerprint(),
        "sweep_json": json.dumps(spec.to_dict(), default=str),
        "points_total": spec.n_points,
    }
    return xr.Dataset(data_vars, coords=coords, attrs=attrs)


def _axis_attrs(axis) -> dict:
    return {
        "units": axis.units,
        "long_name": f"case field {axis.name}",
        "values_as_written": json.dumps(list(axis.values)),
    }


@contextmanager
def _deferred_sigint() -> Iterator[None]:
    """Hold Ctrl-C (SIGINT) until the block is done, then raise KeyboardInterrupt."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    received: list[int] = []
    previous = signal.signal(signal.SIGINT, lambda signum, frame: received.append(signum))
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)
    if received:
        raise KeyboardInterrupt


class MemorySink:
    """Results held in memory (flat arrays); the base of the file sinks.

    Parameters
    ----------
    template : xarray.Dataset
        From :func:`build_template`.
    """

    def __init__(self, template: xr.Dataset) -> None:
        self.template = template
        self.shape = tuple(template.sizes[d] for d in template["status"].dims)
        self.variables = [
            name for name in template.data_vars if name not in ("status", "message", "computed")
        ]
        self.arrays = {
            name: np.asarray(template[name].values).reshape(-1).copy()
            for name in [*self.variables, "status", "message", "computed"]
        }
        self.computed_now = 0

    def _load(self, stored: xr.Dataset, where: str) -> None:
        """Take the points of a stored dataset of the same sweep (resume)."""
        for key in ("sweep_fingerprint", "layout_version"):
            if stored.attrs.get(key) != self.template.attrs[key]:
                raise CaseError(
                    "--resume",
                    where,
                    f"the store holds another sweep ({key} differs); drop --resume to start over",
                )
        for name, array in self.arrays.items():
            values = np.asarray(stored[name].values).reshape(-1)
            if array.dtype == object:
                values = np.asarray([str(v) for v in values], dtype=object)
            array[...] = values

    def pending(self) -> list[int]:
        """Flat indices of the points not yet stored."""
        return [int(i) for i in np.flatnonzero(self.arrays["status"] == STATUS_PENDING)]

    def counts(self) -> tuple[int, int]:
        """(points stored, of which failed)."""
        status = self.arrays["status"]
        return int(np.sum(status != STATUS_PENDING)), int(np.sum(status == STATUS_ERROR))

    def write(self, results: Sequence[PointResult]) -> None:
        """Record a batch of finished points.

        Parameters
        ----------
        results : sequence of PointResult
            Finished points.
        """
        for r in results:
            for name in self.variables:
                self.arrays[name][r.index] = r.values.get(name, np.nan)
            self.arrays["status"][r.index] = r.status
            self.arrays["message"][r.index] = r.message
            self.arrays["computed"][r.index] += 1
        self.computed_now += len(results)

    def dataset(self) -> xr.Dataset:
        """The results as an :class:`xarray.Dataset` (the template's layout)."""
        ds = self.template.copy(deep=True)
        for name, array in self.arrays.items():
            ds[name].values = array.reshape(self.shape).copy()
        return ds

    def close(self) -> None:
        """Finish writing (nothing to do in memory)."""


def _tmp_path(path: Path) -> Path:
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".part", dir=path.parent)
    os.close(fd)
    return Path(tmp)


class NetcdfSink(MemorySink):
    """Results in memory, written to a netCDF file (h5netcdf) when the sweep ends or stops.

    Parameters
    ----------
    template : xarray.Dataset
        From :func:`build_template`.
    path : pathlib.Path
        The ``.nc`` file.
    resume : bool
        Take the points already stored in ``path`` (if it exists) instead of starting over.
    """

    def __init__(self, template: xr.Dataset, path: Path, *, resume: bool) -> None:
        super().__init__(template)
        self.path = path
        if resume and path.exists():
            try:
                with xr.open_dataset(path, engine="h5netcdf") as stored:
                    self._load(stored.load(), str(path))
            except (OSError, KeyError, ValueError) as exc:
                if isinstance(exc, CaseError):
                    raise
                raise CaseError("--resume", str(path), f"not a sweep netCDF file ({exc})") from None

    def close(self) -> None:
        """Write the file atomically (temporary name in the same folder, then rename)."""
        self.path.parent.mkdir(parents=True, exist_ok=True)
        tmp = _tmp_path(self.path)
        try:
            with _deferred_sigint():
                self.dataset().to_netcdf(tmp, engine="h5netcdf")
                os.replace(tmp, self.path)
        finally:
            tmp.unlink(missing_ok=True)


#: Points per zarr chunk (about): a batch, consecutive points in C order, touches few chunks.
_CHUNK_POINTS = 4096


def _chunks(shape: tuple[int, ...], target: int = _CHUNK_POINTS) -> tuple[int, ...]:
    """Chunk shape of about ``target`` points: whole trailing dimensions first (C order)."""
    out, size = [], 1
    for n in reversed(shape):
        c = max(1, min(n, target // size))
        out.append(c)
        size *= c
    return tuple(reversed(out))


def _is_zarr_store(path: Path) -> bool:
    return (path / "zarr.json").is_file() or (path / ".zgroup").is_file()


class ZarrSink(MemorySink):
    """Results streamed into a zarr store, batch by batch, as they finish.

    Parameters
    ----------
    template : xarray.Dataset
        From :func:`build_template`.
    path : pathlib.Path
        The ``.zarr`` folder.
    resume : bool
        Keep the existing store's points; otherwise the store is created anew (an existing
        zarr store replaced, any other folder refused).
    """

    def __init__(self, template: xr.Dataset, path: Path, *, resume: bool) -> None:
        import zarr

        super().__init__(template)
        self.path = path
        if resume and path.exists():
            if not _is_zarr_store(path):
                raise CaseError("--resume", str(path), "not a zarr store")
            try:
                with xr.open_zarr(path, consolidated=True) as stored:
                    self._load(stored.load(), str(path))
            except CaseError:
                raise
            except Exception as exc:  # a store cut short while being created, or not a sweep's
                raise CaseError(
                    "--resume",
                    str(path),
                    f"cannot be read as a sweep store ({type(exc).__name__}: {exc}); "
                    "drop --resume to start over",
                ) from None
        else:
            if path.exists():
                if not _is_zarr_store(path):
                    raise CaseError(
                        "-o", str(path), "exists and is not a zarr store (not overwritten)"
                    )
                shutil.rmtree(path)
            path.parent.mkdir(parents=True, exist_ok=True)
            with _deferred_sigint():
                chunks = _chunks(self.shape)
                encoding = {name: {"chunks": chunks} for name in template.data_vars}
                template.to_zarr(
                    path, mode="w", consolidated=True, zarr_format=2, encoding=encoding
                )
        self.group = zarr.open_group(str(path), mode="r+")

    def write(self, results: Sequence[PointResult]) -> None:
        """Record a batch and write it into the store (status last; Ctrl-C held meanwhile).

        Parameters
        ----------
        results : sequence of PointResult
            Finished points.
        """
        if not results:
            return
        super().write(results)
        flat = np.array([r.index for r in results])
        where = np.unravel_index(flat, self.shape)
        with _deferred_sigint():
            for name in [*self.variables, "message", "computed", "status"]:
                self.group[name].vindex[where] = self.arrays[name][flat]


def open_sink(path: str | Path | None, template: xr.Dataset, *, resume: bool = False) -> MemorySink:
    """The sink for an output path by its suffix (:class:`MemorySink`, :class:`NetcdfSink` or
    :class:`ZarrSink`); CaseError for another suffix, another sweep's store, or a folder that is
    not a zarr store.

    Parameters
    ----------
    path : str or pathlib.Path or None
        ``*.nc`` (netCDF), ``*.zarr`` (zarr store) or None (memory only).
    template : xarray.Dataset
        From :func:`build_template`.
    resume : bool
        Keep the points already stored at ``path``.
    """
    if path is None:
        return MemorySink(template)
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix == ".nc":
        return NetcdfSink(template, path, resume=resume)
    if suffix == ".zarr":
        return ZarrSink(template, path, resume=resume)
    raise CaseError("-o", str(path), "the output must end in .nc (netCDF) or .zarr (zarr)")
