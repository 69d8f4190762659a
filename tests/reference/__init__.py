"""Verification-only references: closed forms and independent models that the tests use.

Nothing in flexbooster imports this package (tests/test_architecture.py). Each module is
itself tested against quadrature or the literature.
"""

__all__: list[str] = []
