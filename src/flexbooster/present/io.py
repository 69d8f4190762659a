"""Writing results: atomic file writes and JSON with a schema version.

Every file is written to a temporary name in the destination folder, flushed to disk and then
renamed over the destination (``os.replace`` is atomic on POSIX and Windows), so an interrupted
run never leaves a half-written result.
"""

from __future__ import annotations

import csv
import hashlib
import io
import json
import math
import os
import tempfile
from collections.abc import Iterable, Iterator, Mapping
from contextlib import contextmanager
from pathlib import Path
from typing import Any

__all__ = [
    "check_finite",
    "dumps_finite",
    "hold_signals",
    "locked_folder",
    "sha256_file",
    "write_bytes_atomic",
    "write_csv_atomic",
    "write_json_atomic",
    "write_text_atomic",
]


def write_bytes_atomic(path: str | Path, data: bytes) -> Path:
    """Write ``data`` to ``path`` atomically (temporary file, fsync, rename); returns the path.
    An OSError names ``path`` (a full disk: ``OSError.filename``).

    Parameters
    ----------
    path : str or pathlib.Path
        Destination file; its folder is created if needed.
    data : bytes
        Content.
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".part", dir=path.parent)
    try:
        os.chmod(tmp, 0o666 & ~_umask())  # mkstemp makes 0600; give the usual permissions
        with os.fdopen(fd, "wb") as handle:
            handle.write(data)
            handle.flush()
            os.fsync(handle.fileno())
        os.replace(tmp, path)
    except OSError as exc:  # a full disk raises from write() without a file name: name it
        Path(tmp).unlink(missing_ok=True)
        if exc.filename is None:
            raise OSError(exc.errno, exc.strerror or str(exc), str(path)) from None
        raise
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return path


def sha256_file(path: str | Path) -> str:
    """The SHA-256 of a file's bytes, in hex.

    Parameters
    ----------
    path : str or pathlib.Path
        The file.
    """
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


@contextmanager
def locked_folder(folder: str | Path) -> Iterator[None]:
    """An exclusive lock on ``folder`` (``fcntl.flock`` on ``folder/.flexbooster.lock``; a no-op
    without ``fcntl``): concurrent writers publish their sets one after the other.

    Parameters
    ----------
    folder : str or pathlib.Path
        The folder (it must exist).
    """
    try:
        import fcntl
    except ImportError:  # pragma: no cover - Windows
        yield
        return
    with open(Path(folder) / ".flexbooster.lock", "a") as handle:
        fcntl.flock(handle.fileno(), fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(handle.fileno(), fcntl.LOCK_UN)


@contextmanager
def hold_signals() -> Iterator[None]:
    """Hold SIGINT and SIGTERM back for a few renames, then deliver the first one held (Python
    handlers that only record the signal: a thread mask would let another thread take it). In
    the main thread only; elsewhere a no-op.
    """
    import signal
    import threading

    if threading.current_thread() is not threading.main_thread():
        yield
        return
    pending: list[int] = []

    def record(signum: int, frame: object) -> None:
        pending.append(signum)

    previous = {}
    for signum in (signal.SIGINT, signal.SIGTERM):
        if signal.getsignal(signum) is not None:  # None: a handler not set from Python
            previous[signum] = signal.signal(signum, record)
    try:
        yield
    finally:
        for signum, handler in previous.items():
            signal.signal(signum, handler)
        if pending:
            signal.raise_signal(pending[0])  # to the handler restored above


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def write_text_atomic(path: str | Path, text: str) -> Path:
    """Write UTF-8 ``text`` to ``path`` atomically (:func:`write_bytes_atomic`); returns the path.

    Parameters
    ----------
    path : str or pathlib.Path
        Destination file; its folder is created if needed.
    text : str
        Content.
    """
    return write_bytes_atomic(path, text.encode("utf-8"))


def check_finite(data: Any, where: str = "results") -> None:
    """Raise ``ValueError`` naming the first NaN or infinite number found in ``data``.

    Parameters
    ----------
    data : object
        Nested mappings, lists and numbers.
    where : str
        Dotted path used in the message.
    """
    if isinstance(data, float):
        if not math.isfinite(data):
            raise ValueError(f"{where} = {data!r}: a result must be finite (internal error)")
    elif isinstance(data, Mapping):
        for key, value in data.items():
            check_finite(value, f"{where}.{key}")
    elif isinstance(data, list | tuple):
        for i, value in enumerate(data):
            check_finite(value, f"{where}[{i}]")


def dumps_finite(data: Any, **kwargs: Any) -> str:
    """``json.dumps`` that refuses NaN and infinity with a ValueError naming the first offending
    path (:func:`check_finite`).

    Parameters
    ----------
    data : object
        JSON-ready data (mappings, lists, numbers, strings).
    **kwargs
        Passed to :func:`json.dumps`.
    """
    try:
        return json.dumps(data, allow_nan=False, **kwargs)
    except ValueError:
        check_finite(data)
        raise


def write_json_atomic(path: str | Path, data: Mapping[str, Any]) -> Path:
    """Write a mapping as JSON atomically, NaN and infinity refused; returns the path.

    Parameters
    ----------
    path : str or pathlib.Path
        Destination file.
    data : Mapping
        JSON-ready data (plain lists, floats, strings).
    """
    # compact: results hold long arrays, which indentation would put one number per line
    return write_text_atomic(path, dumps_finite(data, separators=(",", ":")) + "\n")


def write_csv_atomic(path: str | Path,
                     table: Iterable[Mapping[str, Any]] | Mapping[str, list]) -> Path:
    """Write a table as CSV atomically; returns the path.

    Parameters
    ----------
    path : str or pathlib.Path
        Destination file.
    table : Mapping of str to list, or iterable of Mapping
        By columns (name -> values of one length) or by rows (the first row's keys are the
        header).
    """
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    if isinstance(table, Mapping):
        if table:
            writer.writerow(list(table))
            writer.writerows(zip(*table.values(), strict=True))
    else:
        rows = list(table)
        if rows:
            names = list(rows[0])
            writer.writerow(names)
            writer.writerows([row[n] for n in names] for row in rows)
    return write_text_atomic(path, buffer.getvalue())
