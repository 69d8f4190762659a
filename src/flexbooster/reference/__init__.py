"""Verification-only references: closed forms and independent models that the tests use.

Nothing in the product (the pipeline, the presentation, the CLI) imports this package; the
architecture test enforces it.  Each module is itself tested against quadrature or the
literature.
"""

__all__: list[str] = []
