"""The figures' layout, made once per figure before the SVG and the PNG are drawn.

:func:`new_figure` gives a tight layout engine and :func:`axes_with_colorbar` a colour bar
column of its own; :func:`lay_out_once` runs the engine once, fixes the titles and labels
where it placed them and removes it, so each save draws without a layout pass.
"""

from __future__ import annotations

from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.layout_engine import TightLayoutEngine

__all__ = ["new_figure", "new_axes", "panel_axes", "axes_with_colorbar", "lay_out_once",
           "LAYOUT_PAD", "SUBPLOT_PAD", "COLORBAR_WIDTH"]

#: Space between the labels and the figure's edge, in units of the font size (matplotlib's
#: default 1.08 is a wide frame; this is about the 3 pt of constrained layout).
LAYOUT_PAD = 0.3
#: Space between the labels of neighbouring axes (and an axes and its colour bar), in units of
#: the font size.
SUBPLOT_PAD = 1.0
#: Width of a colour bar as a fraction of the width of its axes (matplotlib's colour bar of
#: aspect 20 beside an axes about as high as a third of its width).
COLORBAR_WIDTH = 0.025


def _engine() -> TightLayoutEngine:
    # rect=None: one measuring pass (the default rect, the whole figure, makes a second one
    # that only respects that rect)
    return TightLayoutEngine(pad=LAYOUT_PAD, h_pad=SUBPLOT_PAD, w_pad=SUBPLOT_PAD, rect=None)


def new_figure(figsize: tuple[float, float]) -> Figure:
    """A figure of ``figsize`` inches with the package's tight layout engine.

    Parameters
    ----------
    figsize : tuple of float
        Width and height (in).
    """
    return Figure(figsize=figsize, layout=_engine())


def new_axes(ax: Axes | None, figsize: tuple[float, float]) -> tuple[Figure, Axes]:
    """(figure, axes): ``ax`` and its figure, or a new figure with one axes.

    Parameters
    ----------
    ax : matplotlib.axes.Axes or None
        Axes to draw on; a new figure is made when None.
    figsize : tuple of float
        Size of the new figure (in).
    """
    if ax is None:
        fig = new_figure(figsize)
        return fig, fig.add_subplot()
    return ax.figure, ax


def panel_axes(ax: Axes | None, n: int, figsize: tuple[float, float]) -> tuple[Figure, list[Axes]]:
    """(figure, ``n`` axes stacked top to bottom): a new figure of ``figsize``, or the place of
    ``ax`` (its subplot cell) split into ``n`` rows, ``ax`` itself removed.

    Parameters
    ----------
    ax : matplotlib.axes.Axes or None
        Axes whose place is split; a new figure is made when None.
    n : int
        Number of panels, >= 1.
    figsize : tuple of float
        Size of the new figure (in).
    """
    if ax is None:
        fig = new_figure(figsize)
        return fig, list(fig.subplots(n, 1, squeeze=False)[:, 0])
    fig = ax.figure
    spec = ax.get_subplotspec()
    if spec is None:  # an axes placed by hand: its rectangle split
        box = ax.get_position()
        ax.remove()
        h = box.height / n
        return fig, [fig.add_axes((box.x0, box.y0 + (n - 1 - i) * h, box.width, 0.85 * h))
                     for i in range(n)]
    ax.remove()
    grid = spec.subgridspec(n, 1)
    return fig, [fig.add_subplot(grid[i, 0]) for i in range(n)]


def axes_with_colorbar(ax: Axes | None, figsize: tuple[float, float], *,
                       colorbar: bool = True) -> tuple[Figure, Axes, Axes | None]:
    """(figure, axes, colour bar axes): for a new figure the colour bar in a column to the right;
    None for a given ``ax`` (the colour bar takes its space from it) or without a colour bar.

    Parameters
    ----------
    ax : matplotlib.axes.Axes or None
        Axes to draw on; a new figure is made when None.
    figsize : tuple of float
        Size of the new figure (in).
    colorbar : bool
        False: no colour bar.
    """
    if ax is not None or not colorbar:
        return (*new_axes(ax, figsize), None)
    fig = new_figure(figsize)
    ax, cax = fig.subplots(1, 2, width_ratios=(1.0, COLORBAR_WIDTH))
    return fig, ax, cax


def lay_out_once(fig: Figure, dpi: float | None = None) -> None:
    """Lay ``fig`` out once and remove its layout engine, keeping the axes, titles and axis labels
    at the places the engine measured (as distances from the axes' edges); axes the engine
    does not measure keep the automatic placement.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        A figure (without an engine: the package's tight layout; another engine lays it out).
    dpi : float, optional
        Resolution of the PNG save: the figure's ``dpi`` is set to it and the layout measured
        with the Agg renderer the save reuses.
    """
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    engine = fig.get_layout_engine()
    if engine is None:
        engine = _engine()
    if dpi is not None:
        fig.dpi = dpi
    FigureCanvasAgg(fig)
    measured = [ax for ax in fig.axes if ax.get_subplotspec() is not None]
    before = {ax: ax.get_window_extent().frozen() for ax in measured}  # pixels
    engine.execute(fig)
    fig.set_layout_engine(None)
    if isinstance(engine, TightLayoutEngine):
        for ax in measured:
            _keep_label_places(ax, before[ax])


def _keep_label_places(ax: Axes, before) -> None:
    """Fix the title and axis labels of ``ax`` at their distances from its edges, as placed
    by the layout's measuring pass when the axes had the extent ``before`` (pixels)."""
    after = ax.get_window_extent()
    if before.width <= 0 or before.height <= 0 or after.width <= 0 or after.height <= 0:
        return
    titles = [t for t in (ax.title, getattr(ax, "_left_title", None),
                          getattr(ax, "_right_title", None)) if t is not None]
    if hasattr(ax, "_autotitlepos") and ax._autotitlepos:  # private: skip if it is gone
        for title in titles:  # y is a fraction of the axes' height, the pad in points
            title.set_y(1.0 + (title.get_position()[1] - 1.0) * before.height / after.height)
        ax._autotitlepos = False
    for axis, pos in ((ax.xaxis, ax.xaxis.get_label_position()),
                      (ax.yaxis, ax.yaxis.get_label_position())):
        label = axis.label
        if not (label.get_visible() and label.get_text()):
            continue
        x, y = label.get_position()  # one coordinate a fraction, the other one in pixels
        if pos == "bottom":
            axis.set_label_coords(x, (y - before.y0) / after.height)
        elif pos == "top":
            axis.set_label_coords(x, 1.0 + (y - before.y1) / after.height)
        elif pos == "left":
            axis.set_label_coords((x - before.x0) / after.width, y)
        elif pos == "right":
            axis.set_label_coords(1.0 + (x - before.x1) / after.width, y)
