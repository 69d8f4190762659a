"""Plotting layer (matplotlib): figures of flexbooster results.

Every function takes ``ax=None`` (a new figure is made when it is None), returns the figure and
never calls ``show``.  The numerical core never imports this package.
"""

__all__: list[str] = []
