"""The sweep page: one self-contained HTML file (inline SVG, inline CSS, no script).

It holds the sweep's axes (SI values and as written), the counts of ok / failed / pending
points, the sweep figure, the most unstable points, every failed point with its message and the
range of each result variable.
"""

from __future__ import annotations

import html
import json

import numpy as np

__all__ = ["sweep_page"]

_STYLE = """
body{font-family:system-ui,sans-serif;max-width:70rem;margin:2rem auto;padding:0 1rem;color:#222}
table{border-collapse:collapse;margin:0.5rem 0 1.5rem}
th,td{border:1px solid #ccc;padding:0.2rem 0.5rem;text-align:left;font-size:0.9rem}
th{background:#f2f2f2} td.num{text-align:right;font-variant-numeric:tabular-nums}
figure{margin:0} svg{max-width:100%;height:auto}
"""


def _e(value) -> str:  # noqa: ANN001
    return html.escape(str(value), quote=True)


def _text(values) -> np.ndarray:  # noqa: ANN001
    """Flat array of str (object dtype) from text read back from any store (StringDType too)."""
    return np.asarray([str(v) for v in np.asarray(values).reshape(-1).tolist()], dtype=object)


def _fmt(value) -> str:  # noqa: ANN001
    if isinstance(value, float | np.floating):
        return "" if not np.isfinite(value) else f"{value:.6g}"
    return str(value)


def _table(header: list[str], rows: list[list], numeric: set[int] = frozenset()) -> str:
    head = "".join(f"<th>{_e(h)}</th>" for h in header)
    body = "".join(
        "<tr>"
        + "".join(
            f'<td class="num">{_e(_fmt(v))}</td>' if i in numeric else f"<td>{_e(_fmt(v))}</td>"
            for i, v in enumerate(row)
        )
        + "</tr>"
        for row in rows
    )
    return f"<table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"


def _axes(ds) -> list[str]:  # noqa: ANN001
    dims = list(ds["status"].dims)
    if dims == ["point"]:
        return [c for c in ds.coords if c != "point" and ds[c].dims == ("point",)]
    return dims


def _point_label(ds, flat: int) -> list:  # noqa: ANN001
    shape = ds["status"].shape
    index = np.unravel_index(flat, shape)
    out = []
    for name in _axes(ds):
        coord = ds[name]
        position = index[list(ds["status"].dims).index(coord.dims[0])]
        out.append(coord.values[position])
    return out


def sweep_page(ds, *, svg: str | None = None, title: str | None = None, max_rows: int = 50) -> str:  # noqa: ANN001
    """The sweep report as one self-contained HTML page (no script, no external resource).

    Parameters
    ----------
    ds : xarray.Dataset
        A sweep result (:func:`flexbooster.sweep.run.sweep`).
    svg : str, optional
        The sweep figure as SVG text (:func:`flexbooster.sweep.plot.figure_svg`), inlined.
    title : str, optional
        Page title (default: from the dataset).
    max_rows : int
        Most rows of the "most unstable" and "failed" tables, >= 1.
    """
    if not isinstance(max_rows, int) or max_rows < 1:
        raise ValueError(f"max_rows = {max_rows!r}: must be a positive integer")
    title = title or ds.attrs.get("title", "flexbooster sweep")
    status = _text(ds["status"].values)
    n = status.size
    ok, failed = int((status == "ok").sum()), int((status == "error").sum())
    pending = n - ok - failed
    axes = _axes(ds)
    parts = [
        "<!DOCTYPE html>",
        '<html lang="en"><head><meta charset="utf-8">',
        f"<title>{_e(title)}</title><style>{_STYLE}</style></head><body>",
        f"<h1>{_e(title)}</h1>",
        f"<p>{n} points ({_e(ds.attrs.get('sweep_mode', 'product'))} of {len(axes)} axes): "
        f"<strong>{ok} ok</strong>, <strong>{failed} failed</strong>"
        + (f", {pending} not computed" if pending else "")
        + f". flexbooster {_e(ds.attrs.get('flexbooster_version', ''))}.</p>",
        "<h2>Axes</h2>",
    ]
    rows = []
    for name in axes:
        coord = ds[name]
        written = json.loads(coord.attrs.get("values_as_written", "[]"))
        values = ", ".join(_fmt(v) for v in coord.values)
        rows.append([name, coord.attrs.get("units", ""), values, ", ".join(map(str, written))])
    parts.append(_table(["field", "SI unit", "values (SI)", "as written"], rows))
    if svg:
        start = svg.find("<svg")
        parts += ["<h2>Figure</h2>", f"<figure>{svg[start:] if start >= 0 else ''}</figure>"]
    if "max_growth_rate" in ds:
        growth = np.asarray(ds["max_growth_rate"].values, dtype=float).reshape(-1)
        unstable = np.flatnonzero(np.isfinite(growth) & (growth > 0.0))
        order = unstable[np.argsort(-growth[unstable], kind="stable")][:max_rows]
        parts.append("<h2>Most unstable points</h2>")
        if order.size:
            units = ds["max_growth_rate"].attrs.get("units", "")
            rows = [[int(i), *_point_label(ds, int(i)), float(growth[i])] for i in order]
            header = ["point", *axes, f"largest growth rate ({units})"]
            parts.append(_table(header, rows, numeric={0, len(header) - 1}))
        else:
            parts.append("<p>No unstable point: every computed point is stable.</p>")
    parts.append("<h2>Failed points</h2>")
    bad = np.flatnonzero(status == "error")[:max_rows]
    if bad.size:
        messages = _text(ds["message"].values)
        rows = [[int(i), *_point_label(ds, int(i)), messages[i]] for i in bad]
        parts.append(_table(["point", *axes, "message"], rows, numeric={0}))
        if failed > bad.size:
            parts.append(f"<p>... and {failed - bad.size} more (see the dataset).</p>")
    else:
        parts.append("<p>None.</p>")
    parts.append("<h2>Result variables</h2>")
    rows = []
    for name, var in ds.data_vars.items():
        if name in ("status", "message"):
            continue
        values = np.asarray(var.values, dtype=float)
        finite = values[np.isfinite(values)]
        lo, hi = (float(finite.min()), float(finite.max())) if finite.size else (np.nan, np.nan)
        rows.append([name, var.attrs.get("units", ""), var.attrs.get("long_name", ""), lo, hi])
    parts.append(_table(["variable", "unit", "meaning", "min", "max"], rows, numeric={3, 4}))
    parts.append("</body></html>")
    return "\n".join(parts) + "\n"
