"""The sweep figure: the largest growth rate (1/s) over the first two axes (further axes
reduced by the maximum; stable cells green, failed or pending grey), or the pitch and
beam-action growth rates along one axis (failed points marked).
"""

from __future__ import annotations

import io

import numpy as np

__all__ = ["sweep_figure", "figure_svg"]

_STABLE_COLOR = "#bfe3b4"
_MISSING_COLOR = "#d0d0d0"


def _label(ds, name: str) -> str:  # noqa: ANN001
    units = ds[name].attrs.get("units", "")
    return f"{name} ({units})" if units and units != "1" else name


def _ticks(values: np.ndarray) -> list[str]:
    out = []
    for v in values:
        out.append(f"{v:.4g}" if isinstance(v, float | np.floating) else str(v))
    return out


def _map(ds, variable: str, ax) -> None:  # noqa: ANN001
    from matplotlib.colors import ListedColormap
    from matplotlib.patches import Patch

    data = ds[variable]
    xdim, ydim = data.dims[1], data.dims[0]
    extra = [d for d in data.dims if d not in (xdim, ydim)]
    if extra:
        data = data.max(dim=extra, skipna=True)
    values = np.asarray(data.transpose(ydim, xdim).values, dtype=float)
    ny, nx = values.shape
    missing = ~np.isfinite(values)
    stable = np.isfinite(values) & (values <= 0.0)
    ax.imshow(
        np.where(missing, 1.0, np.where(stable, 0.0, np.nan)),
        cmap=ListedColormap([_STABLE_COLOR, _MISSING_COLOR]),
        vmin=0.0,
        vmax=1.0,
        origin="lower",
        aspect="auto",
        interpolation="nearest",
    )
    unstable = np.where(np.isfinite(values) & (values > 0.0), values, np.nan)
    handles = [Patch(color=_STABLE_COLOR, label="stable")]
    if np.isfinite(unstable).any():
        image = ax.imshow(
            unstable, cmap="magma_r", origin="lower", aspect="auto", interpolation="nearest"
        )
        ax.figure.colorbar(image, ax=ax, label=f"largest growth rate ({data.attrs['units']})")
    if missing.any():
        handles.append(Patch(color=_MISSING_COLOR, label="failed / not computed"))
    ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(0.0, -0.14), ncols=2)
    ax.set_xticks(range(nx), _ticks(ds[xdim].values), rotation=45 if nx > 6 else 0)
    ax.set_yticks(range(ny), _ticks(ds[ydim].values))
    ax.set_xlabel(_label(ds, xdim))
    ax.set_ylabel(_label(ds, ydim))
    title = "largest growth rate over the plane"
    if extra:
        title += f" (maximum over {', '.join(extra)})"
    if not np.isfinite(unstable).any() and not missing.all():
        title += ": stable everywhere"
    ax.set_title(title)


def _curves(ds, variable: str, ax) -> None:  # noqa: ANN001
    data = ds[variable]
    dim = data.dims[0]
    xname = dim
    if dim == "point":  # zip sweep: the first axis is the abscissa
        axes = [c for c in ds.coords if c != "point" and ds[c].dims == ("point",)]
        xname = axes[0] if axes else "point"
    x = ds[xname].values
    numeric = np.issubdtype(np.asarray(x).dtype, np.number)
    xs = np.asarray(x, dtype=float) if numeric else np.arange(len(x))
    order = np.argsort(xs, kind="stable")
    names = [n for n in ("pitch_max_growth_rate", "beam_action_max_growth_rate") if n in ds]
    for name in names:
        ys = np.asarray(ds[name].values, dtype=float)
        ax.plot(xs[order], ys[order], marker="o", label=name.replace("_max_growth_rate", ""))
    failed = ~np.isfinite(np.asarray(ds[variable].values, dtype=float))
    if failed.any():
        ax.plot(xs[failed], np.zeros(failed.sum()), "x", color="k", label="failed")
    if not numeric:
        ax.set_xticks(xs, _ticks(x))
    ax.set_xlabel(_label(ds, xname))
    ax.set_ylabel(f"largest growth rate ({ds[variable].attrs['units']})")
    ax.axhline(0.0, color="0.6", lw=0.8)
    ax.legend()
    values = np.asarray(ds[variable].values, dtype=float)
    stable_all = np.all(values[np.isfinite(values)] <= 0.0)
    ax.set_title("growth rates" + (": stable everywhere" if stable_all else ""))


def sweep_figure(ds, *, variable: str = "max_growth_rate", ax=None):  # noqa: ANN001
    """Draw the sweep figure (map over two axes, curves over one).

    Parameters
    ----------
    ds : xarray.Dataset
        A sweep result (:func:`flexbooster.sweep.run.sweep`).
    variable : str
        The growth-rate variable of the map (1/s), default the largest of pitch and beam action.
    ax : matplotlib.axes.Axes, optional
        Axes to draw in; a new figure if omitted.
    """
    if variable not in ds:
        raise ValueError(f"variable = {variable!r}: not in the dataset")
    if ax is None:
        from matplotlib.figure import Figure

        fig = Figure(figsize=(7.0, 5.0), layout="constrained")
        ax = fig.add_subplot()
    if ds[variable].ndim >= 2:
        _map(ds, variable, ax)
    else:
        _curves(ds, variable, ax)
    return ax.figure


def figure_svg(fig) -> str:  # noqa: ANN001
    """The figure as a standalone SVG document (no date in its metadata: reproducible).

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure.
    """
    buffer = io.StringIO()
    fig.savefig(buffer, format="svg", metadata={"Date": None})  # reproducible: no date
    return buffer.getvalue()
