"""Presentation layer: terminal summary, report, output files and figures.

It reads result types only (:class:`flexbooster.results.Results` and the dataclasses it holds)
and never calls a solver: every number and every curve it shows was computed by
:func:`flexbooster.analyze` and stored in the results.
"""

__all__: list[str] = []
