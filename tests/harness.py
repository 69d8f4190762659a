"""The shared reference harness of the test suite (in the style of SciPy's ``FuncData`` and
``assert_mpmath_equal``).

Every expected value names its source and tolerance.  A :class:`Reference` is a table of
points with their expected values, the source they come from and the tolerance at which the
program must agree; :func:`check_reference` evaluates a function on the whole table and
reports the worst points with the source; :func:`assert_mpmath_equal` compares a function with
an mpmath reference evaluated at high precision; :func:`assert_close` is the scalar/array form
with the source in the message.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

__all__ = ["Reference", "assert_close", "check_reference", "assert_mpmath_equal",
           "ivp_monodromy", "ivp_growth_rate"]


@dataclass(frozen=True)
class Reference:
    """A reference table.

    Attributes
    ----------
    name : str
        What is compared (for messages).
    source : str
        Where the expected values come from (paper, closed form, independent computation).
    points : tuple
        Arguments, one tuple per row.
    expected : tuple
        Expected value per row (float or complex).
    rtol, atol : float
        Tolerance: |actual - expected| <= atol + rtol |expected|.
    """

    name: str
    source: str
    points: tuple
    expected: tuple
    rtol: float
    atol: float = 0.0

    def __post_init__(self) -> None:
        if len(self.points) != len(self.expected):
            raise ValueError(f"{self.name}: {len(self.points)} points, "
                             f"{len(self.expected)} expected values")


def _report(name: str, source: str, rows: Sequence[tuple], bad: np.ndarray,
            actual: np.ndarray, expected: np.ndarray, rtol: float, atol: float) -> str:
    lines = [f"{name}: {int(bad.sum())} of {bad.size} points outside "
             f"atol {atol:g} + rtol {rtol:g} |expected| (source: {source})"]
    for n in np.flatnonzero(bad)[:8]:
        err = abs(actual[n] - expected[n])
        lines.append(f"  at {rows[n]!r}: got {actual[n]!r}, expected {expected[n]!r} "
                     f"(error {err:.3g})")
    return "\n".join(lines)


def assert_close(actual: Any, expected: Any, *, rtol: float, atol: float = 0.0,
                 source: str, name: str = "value") -> None:
    """Assert |actual - expected| <= atol + rtol |expected| elementwise, naming the source.

    Parameters
    ----------
    actual, expected : array_like
        Computed and reference values (broadcast).
    rtol, atol : float
        Tolerance.
    source : str
        Where ``expected`` comes from.
    name : str
        What is compared.
    """
    a, e = np.broadcast_arrays(np.asarray(actual), np.asarray(expected))
    a, e = a.ravel(), e.ravel()
    bad = ~(np.abs(a - e) <= atol + rtol * np.abs(e))
    if bad.any():
        raise AssertionError(_report(name, source, [(i,) for i in range(a.size)], bad, a, e,
                                     rtol, atol))


def check_reference(func: Callable[..., Any], ref: Reference) -> None:
    """Evaluate ``func(*point)`` on every row of ``ref`` and compare (worst rows reported).

    Parameters
    ----------
    func : callable
        The function under test, called once per row with the row's arguments.
    ref : Reference
        The table.
    """
    actual = np.array([complex(func(*p)) for p in ref.points])
    expected = np.array([complex(e) for e in ref.expected])
    if np.all(actual.imag == 0) and np.all(expected.imag == 0):
        actual, expected = actual.real, expected.real
    bad = ~(np.abs(actual - expected) <= ref.atol + ref.rtol * np.abs(expected))
    if bad.any():
        raise AssertionError(_report(ref.name, ref.source, list(ref.points), bad, actual,
                                     expected, ref.rtol, ref.atol))


def assert_mpmath_equal(func: Callable[..., Any], mpfunc: Callable[..., Any],
                        points: Sequence[tuple], *, rtol: float, atol: float = 0.0,
                        dps: int = 30, name: str = "value") -> None:
    """Compare ``func`` with an mpmath reference computed at ``dps`` digits.

    Parameters
    ----------
    func : callable
        The function under test, ``func(*point)``.
    mpfunc : callable
        The reference, ``mpfunc(*point)`` evaluated under ``mpmath.workdps(dps)``.
    points : sequence of tuple
        Arguments.
    rtol, atol : float
        Tolerance.
    dps : int
        Decimal digits of the reference.
    name : str
        What is compared.
    """
    import mpmath

    with mpmath.workdps(dps):
        expected = tuple(complex(mpfunc(*p)) for p in points)
    check_reference(func, Reference(name=name, source=f"mpmath at {dps} digits",
                                    points=tuple(points), expected=expected, rtol=rtol,
                                    atol=atol))


def ivp_monodromy(M, C, A, B, Omega: float) -> np.ndarray:
    """Independent monodromy of M q'' + C q' + (A + B cos Omega t) q = 0: scipy solve_ivp
    (DOP853, rtol 1e-12, atol 1e-14) over one period, column by column (C may be 0)."""
    from scipy.integrate import solve_ivp

    M, C, A, B = (np.atleast_2d(np.asarray(x, dtype=float)) for x in (M, C, A, B))
    n = M.shape[0]
    Mi = np.linalg.inv(M)

    def rhs(t, z):
        q, v = z[:n], z[n:]
        return np.concatenate([v, -Mi @ (C @ v + (A + B * np.cos(Omega * t)) @ q)])

    T = 2.0 * np.pi / Omega
    cols = [solve_ivp(rhs, (0.0, T), e, method="DOP853", rtol=1e-12, atol=1e-14).y[:, -1]
            for e in np.eye(2 * n)]
    return np.array(cols).T


def ivp_growth_rate(M, C, A, B, Omega: float) -> float:
    """log|rho|_max / T (1/time unit) from :func:`ivp_monodromy`."""
    rho = np.linalg.eigvals(ivp_monodromy(M, C, A, B, Omega))
    return float(np.log(np.max(np.abs(rho))) * Omega / (2.0 * np.pi))
