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
from dataclasses import dataclass
from pathlib import Path
from typing import Any

__all__ = [
    "JSONText",
    "TableTexts",
    "check_finite",
    "csv_text",
    "dumps_finite",
    "hold_signals",
    "locked_folder",
    "sha256_file",
    "table_texts",
    "write_bytes_atomic",
    "write_csv_atomic",
    "write_json_atomic",
    "write_text_atomic",
]


def write_bytes_atomic(path: str | Path, data: bytes) -> Path:
    """Write ``data`` to ``path`` atomically (temporary file, fsync, rename).

    Parameters
    ----------
    path : str or pathlib.Path
        Destination file; its folder is created if needed.
    data : bytes
        Content.

    Returns
    -------
    pathlib.Path
        The destination path.
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

    Returns
    -------
    str
        64 hex digits.
    """
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


@contextmanager
def locked_folder(folder: str | Path) -> Iterator[None]:
    """An exclusive lock on ``folder`` (``fcntl.flock`` on ``folder/.flexbooster.lock``).

    Concurrent writers of one output folder publish their sets one after the other.  Without
    ``fcntl`` (Windows) the lock is a no-op.

    Parameters
    ----------
    folder : str or pathlib.Path
        The folder (it must exist).

    Yields
    ------
    None
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
    """Hold SIGINT and SIGTERM back for a few renames, then deliver the first one held.

    The Python handlers are replaced by one that only records the signal (not a thread's
    ``pthread_sigmask``: with another thread alive, e.g. the progress bar's refresh thread,
    the kernel hands a process-directed signal to that thread and the interrupt still breaks
    into the renames).  In the main thread only; elsewhere a no-op.

    Yields
    ------
    None
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
    """Write UTF-8 ``text`` to ``path`` atomically (see :func:`write_bytes_atomic`).

    Parameters
    ----------
    path : str or pathlib.Path
        Destination file; its folder is created if needed.
    text : str
        Content.

    Returns
    -------
    pathlib.Path
        The destination path.
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


#: Shortest list whose floats :func:`_float_texts` formats once per distinct value.
_REPEATED_MIN = 1024
#: Most distinct values, as a fraction of the list, for which that is faster (measured:
#: 42,000 floats with 1.5 % distinct values take 0.010 s against 0.045 s; with 12 %, no gain).
_REPEATED_FRACTION = 1 / 32


def _float_texts(values: list, *, for_json: bool = False) -> list[str] | None:
    """The text of each float of a long list of floats with few distinct values.

    ``repr`` of each distinct value once (the text that ``json`` and ``csv`` write: the
    shortest round-trip repr), then looked up: a table of tens of thousands of roots holds a
    few hundred shell frequencies, and the formatting of floats is most of the time spent in
    writing results.  Zeros are formatted one by one (0.0 == -0.0 as keys).  None (the
    encoders format the list themselves) for a short list, one that holds anything but
    floats, or one with more distinct values than :data:`_REPEATED_FRACTION`.  With
    ``for_json``, a NaN or an infinity among the values is a ValueError (as json's).
    """
    n = len(values)
    if n < _REPEATED_MIN or type(values[0]) is not float:
        return None
    if 2 * len(set(values[:_REPEATED_MIN])) > _REPEATED_MIN:  # mostly distinct: at once
        return None
    if set(map(type, values)) != {float}:
        return None
    distinct = set(values)
    if len(distinct) > _REPEATED_FRACTION * n:
        return None
    if for_json:
        _refuse_non_finite(distinct)
    texts = {value: repr(value) for value in distinct}
    return [texts[value] if value else repr(value) for value in values]


def _refuse_non_finite(values) -> None:
    """A ValueError, as json's ``allow_nan=False``, if a float of ``values`` is NaN or
    infinite (the distinct values where they are at hand: a column of repeated floats)."""
    if not all(map(math.isfinite, values)):
        raise ValueError("Out of range float values are not JSON compliant")


@dataclass(frozen=True)
class JSONText:
    """A value already encoded as compact JSON, which :func:`dumps_finite` with
    ``separators=(",", ":")`` (the form of results.json) writes as it is: e.g. a column of
    the stability table that :func:`table_texts` formatted in a worker process.  The other
    forms of :func:`dumps_finite` do not accept it.

    Attributes
    ----------
    text : str
        The JSON text (already checked finite).
    """

    text: str


def _compact_json(data: Any) -> str:
    """``json.dumps(data, allow_nan=False, separators=(",", ":"))``, the same text: mappings
    with string keys are encoded entry by entry so that long lists of repeated floats are
    formatted by :func:`_float_texts` (a ValueError for NaN or infinity, as json's), and a
    :class:`JSONText` is written as it is."""
    if type(data) is JSONText:
        return data.text
    if type(data) is dict and all(type(key) is str for key in data):
        return "{" + ",".join(f"{json.dumps(key)}:{_compact_json(value)}"
                              for key, value in data.items()) + "}"
    if type(data) is list:
        texts = _float_texts(data, for_json=True)
        if texts is not None:
            return "[" + ",".join(texts) + "]"
    return json.dumps(data, allow_nan=False, separators=(",", ":"))


def dumps_finite(data: Any, **kwargs: Any) -> str:
    """``json.dumps`` that refuses NaN and infinity, naming the first offending path.

    Parameters
    ----------
    data : object
        JSON-ready data (mappings, lists, numbers, strings).
    **kwargs
        Passed to :func:`json.dumps` (e.g. ``indent``, ``separators``).

    Returns
    -------
    str
        The JSON text.

    Raises
    ------
    ValueError
        ``"<path> = nan: a result must be finite (internal error)"``: the fast
        ``allow_nan=False`` encoder failed, and the walk of :func:`check_finite` (run only
        then) names the value.
    """
    try:
        if kwargs == {"separators": (",", ":")}:  # compact, as results.json is written
            return _compact_json(data)
        return json.dumps(data, allow_nan=False, **kwargs)
    except ValueError:
        check_finite(data)
        raise


def write_json_atomic(path: str | Path, data: Mapping[str, Any]) -> Path:
    """Write a mapping as JSON atomically; NaN and infinity are refused.

    Parameters
    ----------
    path : str or pathlib.Path
        Destination file.
    data : Mapping
        JSON-ready data (plain lists, floats, strings).

    Returns
    -------
    pathlib.Path
        The destination path.
    """
    # compact: results hold long arrays, which indentation would put one number per line
    return write_text_atomic(path, dumps_finite(data, separators=(",", ":")) + "\n")


def _csv_field(text: str) -> str:
    """The csv module's text of the string ``text`` as one field of a row of several
    (quoted where it holds a comma, a quote or a line break), asked of the module itself."""
    buffer = io.StringIO()
    csv.writer(buffer, lineterminator="\n").writerow((text, ""))
    return buffer.getvalue()[:-2]  # less the empty second field and the line's end


def _cell_texts(values: list, with_json: bool) -> tuple[list[str], list[str]] | None:
    """The CSV text and the JSON text of each value of one column of a table, each distinct
    value formatted once; None for a column of mixed or other types (the encoders format
    it).  Floats: ``repr`` in both (what csv's ``str`` and json write; a ValueError for NaN
    or infinity when the JSON is asked for, as json's); ints: ``repr`` in both; strings: as
    csv quotes them, as json escapes them.  A number's text never needs quoting in CSV."""
    kinds = set(map(type, values))
    if kinds == {float}:
        texts = _float_texts(values, for_json=with_json)
        if texts is None:
            if with_json:  # mostly distinct values: checked as they are
                _refuse_non_finite(values)
            texts = list(map(float.__repr__, values))
        return texts, texts
    if kinds == {int}:
        distinct = {value: int.__repr__(value) for value in set(values)}
        texts = [distinct[value] for value in values]
        return texts, texts
    if kinds == {str}:
        distinct = set(values)
        in_csv = {value: _csv_field(value) for value in distinct}
        in_json = {value: json.dumps(value) for value in distinct} if with_json else {}
        return [in_csv[v] for v in values], [in_json[v] for v in values] if with_json else []
    return None


@dataclass(frozen=True)
class TableTexts:
    """A table by columns as text: its CSV and the JSON text of each column.

    What :func:`table_texts` returns for a table or for a slice of its rows; the texts of
    consecutive slices joined (:meth:`join`) are those of the whole table, byte for byte.

    Attributes
    ----------
    csv : str
        The CSV text of the rows (:func:`csv_text`), with the header if asked for.
    json_items : dict of str to str
        Column name -> the JSON text of the column's values, comma-separated, without the
        brackets: ``"[" + json_items[name] + "]"`` is ``json.dumps(column,
        separators=(",", ":"))``.
    """

    csv: str
    json_items: dict[str, str]

    @staticmethod
    def join(parts: Iterable[TableTexts]) -> TableTexts:
        """The texts of consecutive slices of a table's rows, as one table (the header is
        that of the first slice).

        Parameters
        ----------
        parts : iterable of TableTexts
            The slices in the order of their rows, all with the same columns.

        Returns
        -------
        TableTexts
        """
        parts = list(parts)
        names = parts[0].json_items if parts else {}
        return TableTexts(csv="".join(p.csv for p in parts),
                          json_items={name: ",".join(p.json_items[name] for p in parts
                                                     if p.json_items[name])
                                      for name in names})


def _table_texts(table: Mapping[str, list], header: bool,
                 with_json: bool) -> tuple[str, dict[str, str]]:
    """The CSV text and (if asked) the JSON items of a table by columns: each cell formatted
    once (:func:`_cell_texts`) and the rows joined, or csv.writer's rows and json's text
    where a column is of mixed type or the table has a single column (whose empty string
    csv writes as a quoted ``""``)."""
    if not table:
        return "", {}
    names = list(table)
    cells = [_cell_texts(values, with_json) for values in table.values()] if len(names) > 1 \
        else [None]
    if any(c is None for c in cells):  # the encoders format each value
        buffer = io.StringIO()
        writer = csv.writer(buffer, lineterminator="\n")
        if header:
            writer.writerow(names)
        # the same text as the numbers themselves (csv writes str(x), repr for floats)
        writer.writerows(zip(*(_float_texts(column) or column for column in table.values()),
                             strict=True))
        items = ({name: _compact_json(column)[1:-1] for name, column in table.items()}
                 if with_json else {})
        return buffer.getvalue(), items
    lines = list(map(",".join, zip(*(csv_cells for csv_cells, _ in cells), strict=True)))
    if header:
        lines.insert(0, ",".join(map(_csv_field, names)))
    items = ({name: ",".join(json_cells)
              for name, (_, json_cells) in zip(names, cells, strict=True)}
             if with_json else {})
    return "\n".join(lines) + "\n" if lines else "", items


def table_texts(table: Mapping[str, list], *, header: bool = True) -> TableTexts:
    """A table by columns as CSV and JSON text, each value formatted once for both.

    The CSV is :func:`csv_text`'s and each column's JSON that of ``json.dumps(column,
    allow_nan=False, separators=(",", ":"))``, byte for byte; a stability table of tens of
    thousands of roots is in results.json and in its CSV, and the formatting of its floats
    is most of the time spent in writing results.

    Parameters
    ----------
    table : Mapping of str to list
        Column name -> values, all of one length.
    header : bool
        Start the CSV with the names of the columns; without it, the rows alone (the texts
        of consecutive slices of the rows join into those of the whole: :meth:`TableTexts.join`).

    Returns
    -------
    TableTexts

    Raises
    ------
    ValueError
        A NaN or infinite float (JSON does not hold them; :func:`check_finite` names it).
    """
    text, items = _table_texts(table, header, with_json=True)
    return TableTexts(csv=text, json_items=items)


def csv_text(table: Iterable[Mapping[str, Any]] | Mapping[str, list], *,
             header: bool = True) -> str:
    """A table as CSV text (the text of :func:`write_csv_atomic`).

    Parameters
    ----------
    table : Mapping of str to list, or iterable of Mapping
        By columns (name -> values, all of one length: the fast form) or by rows (mappings
        with the same keys; the keys of the first row are the header).
    header : bool
        Start with the names of the columns; without it, the rows alone: the texts of
        consecutive slices of the rows joined are the text of the whole, byte for byte.

    Returns
    -------
    str
        One line per row, ``\\n``-terminated; numbers as ``str`` writes them (the text of
        ``csv.writer``).
    """
    if isinstance(table, Mapping):
        return _table_texts(table, header, with_json=False)[0]
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    rows = list(table)
    if rows:
        names = list(rows[0])
        if header:
            writer.writerow(names)
        writer.writerows([row[n] for n in names] for row in rows)
    return buffer.getvalue()


def write_csv_atomic(path: str | Path,
                     table: Iterable[Mapping[str, Any]] | Mapping[str, list]) -> Path:
    """Write a table as CSV atomically.

    Parameters
    ----------
    path : str or pathlib.Path
        Destination file.
    table : Mapping of str to list, or iterable of Mapping
        By columns (name -> values, all of one length: the fast form) or by rows (mappings
        with the same keys; the keys of the first row are the header).

    Returns
    -------
    pathlib.Path
        The destination path.
    """
    return write_text_atomic(path, csv_text(table))
