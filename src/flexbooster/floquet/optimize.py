"""Scalar maximisers and root finders vectorised over P independent problems: ``f(x, idx)``
evaluates the points x (P',) of the problems idx (P',) and returns (P',) values.

References: J. Kiefer, Proc. AMS 4 (1953) 502-506 (golden section); R. P. Brent,
*Algorithms for Minimization without Derivatives*, 1973, ch. 5; M. Dowell, P. Jarratt,
BIT 11 (1971) 168-174 (Illinois); Press et al., *Numerical Recipes*, 3rd ed., sec. 9.1, 10.2.
"""

from __future__ import annotations

import numpy as np

__all__ = ["NoConvergenceError", "golden_section_max", "brent_max", "illinois_root",
           "expand_bracket"]

_GOLD = 0.5 * (np.sqrt(5.0) - 1.0)


class NoConvergenceError(ValueError):
    """An iteration did not converge within its ``max_iter`` steps."""


def golden_section_max(f, a, b, *, xtol, max_iter: int = 200,
                       stop_above: float | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Maximise f on [a, b] by golden section: the best point of each interval and f there.

    Parameters
    ----------
    f : callable
        f(x, idx) -> values.
    a, b : array_like
        Interval ends, shape (P,), finite, a <= b.
    xtol : array_like
        Final interval lengths, shape (P,) or scalar, > 0.
    max_iter : int
        Cap on the steps, >= 1 (:class:`NoConvergenceError` past it).
    stop_above : float, optional
        An interval stops once f exceeds this at one of its points.
    """
    a = np.atleast_1d(np.asarray(a, dtype=float)).copy()
    b = np.atleast_1d(np.asarray(b, dtype=float)).copy()
    if a.ndim != 1 or a.shape != b.shape or not (np.all(np.isfinite(a))
                                                 and np.all(np.isfinite(b))):
        raise ValueError(f"a = {a!r}: a and b must be finite 1-D arrays of the same shape")
    if np.any(b < a):
        raise ValueError(f"b = {b!r}: must be >= a")
    xtol = np.broadcast_to(np.asarray(xtol, dtype=float), a.shape)
    if not np.all(np.isfinite(xtol)) or np.any(xtol <= 0.0):
        raise ValueError(f"xtol = {xtol!r}: must be finite and > 0")
    if isinstance(max_iter, bool) or not isinstance(max_iter, int | np.integer) or max_iter < 1:
        raise ValueError(f"max_iter = {max_iter!r}: must be an integer >= 1")
    x1 = b - _GOLD * (b - a)
    x2 = a + _GOLD * (b - a)
    every = np.arange(a.size)
    f1, f2 = f(x1, every), f(x2, every)
    for _ in range(max_iter):
        done = b - a <= xtol
        if stop_above is not None:
            done |= (f1 > stop_above) | (f2 > stop_above)
        if np.all(done):
            break
        right = f2 > f1  # max in [x1, b]
        act = np.nonzero(~done)[0]
        r_ = right[act]
        a[act] = np.where(r_, x1[act], a[act])
        b[act] = np.where(r_, b[act], x2[act])
        xn = np.where(r_, a[act] + _GOLD * (b[act] - a[act]), b[act] - _GOLD * (b[act] - a[act]))
        fn = f(xn, act)
        x1[act], f1[act], x2[act], f2[act] = (
            np.where(r_, x2[act], xn), np.where(r_, f2[act], fn),
            np.where(r_, xn, x1[act]), np.where(r_, fn, f1[act]))
    else:
        raise NoConvergenceError(f"golden section: no convergence in {max_iter} iterations")
    best = f1 >= f2
    return np.where(best, x1, x2), np.where(best, f1, f2)


def brent_max(f, a: np.ndarray, b: np.ndarray, x0: np.ndarray, xtol: np.ndarray, *,
              max_iter: int = 200,
              stop_above: float | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Maximise f on [a, b] from x0 by golden-section and parabolic steps (Brent 1973, ch. 5):
    the maximisers and f there.

    Parameters
    ----------
    f : callable
        f(x, idx) -> values.
    a, b, x0 : numpy.ndarray
        Interval ends and starting points, shape (P,), a <= x0 <= b.
    xtol : numpy.ndarray
        Absolute tolerances, shape (P,), > 0 (plus 1.5e-8 |x|).
    max_iter : int
        Cap on the steps (:class:`NoConvergenceError` past it).
    stop_above : float, optional
        A problem stops once f exceeds this at its best point.
    """
    cgold = 0.5 * (3.0 - np.sqrt(5.0))
    a, b = a.copy(), b.copy()
    x = np.clip(x0, a, b)
    fx = -f(x, np.arange(x.size))
    w, v, fw, fv = x.copy(), x.copy(), fx.copy(), fx.copy()
    d = np.zeros(x.size)
    e = np.zeros(x.size)
    done = np.zeros(x.size, dtype=bool)
    for _ in range(max_iter):
        xm = 0.5 * (a + b)
        tol1 = 1.5e-8 * np.abs(x) + xtol / 3.0
        tol2 = 2.0 * tol1
        done |= np.abs(x - xm) <= tol2 - 0.5 * (b - a)
        if stop_above is not None:
            done |= -fx > stop_above
        act = np.nonzero(~done)[0]
        if act.size == 0:
            return x, -fx
        X, W, V, FX, FW, FV = x[act], w[act], v[act], fx[act], fw[act], fv[act]
        A_, B_, D, E, T1, T2, XM = a[act], b[act], d[act], e[act], tol1[act], tol2[act], xm[act]
        r = (X - W) * (FX - FV)
        q = (X - V) * (FX - FW)
        p = (X - V) * q - (X - W) * r
        q = 2.0 * (q - r)
        p = np.where(q > 0.0, -p, p)
        q = np.abs(q)
        try_par = np.abs(E) > T1
        with np.errstate(divide="ignore", invalid="ignore"):
            par = try_par & (np.abs(p) < np.abs(0.5 * q * E)) & (p > q * (A_ - X)) & (
                p < q * (B_ - X))
            dpar = np.where(par, p / np.where(q == 0.0, 1.0, q), 0.0)
        upar = X + dpar
        near_end = ((upar - A_) < T2) | ((B_ - upar) < T2)
        dpar = np.where(near_end, np.where(XM - X >= 0.0, T1, -T1), dpar)
        egold = np.where(X >= XM, A_ - X, B_ - X)
        E_new = np.where(par, D, egold)  # e <- d (parabolic) or the golden interval
        D_new = np.where(par, dpar, cgold * egold)
        U = X + np.where(np.abs(D_new) >= T1, D_new, np.where(D_new >= 0.0, T1, -T1))
        FU = -f(U, act)
        better = FU <= FX
        a[act] = np.where(better, np.where(U >= X, X, A_), np.where(U < X, U, A_))
        b[act] = np.where(better, np.where(U >= X, B_, X), np.where(U < X, B_, U))
        c1 = ~better & ((FU <= FW) | (W == X))
        c2 = ~better & ~c1 & ((FU <= FV) | (V == X) | (V == W))
        v[act] = np.where(better | c1, W, np.where(c2, U, V))
        fv[act] = np.where(better | c1, FW, np.where(c2, FU, FV))
        w[act] = np.where(better, X, np.where(c1, U, W))
        fw[act] = np.where(better, FX, np.where(c1, FU, FW))
        x[act] = np.where(better, U, X)
        fx[act] = np.where(better, FU, FX)
        d[act], e[act] = D_new, E_new
    raise NoConvergenceError(f"maximiser: no convergence in {max_iter} iterations")


def illinois_root(f, x_in: np.ndarray, f_in: np.ndarray, x_out: np.ndarray, f_out: np.ndarray,
                  xtol: np.ndarray, *, max_iter: int = 200, bracket: bool = False):
    """Root of f between x_in (f > 0) and x_out (f <= 0) by Illinois regula falsi: the midpoints of
    the final brackets, or the brackets.

    Parameters
    ----------
    f : callable
        f(x, idx) -> values.
    x_in, f_in, x_out, f_out : numpy.ndarray
        The brackets and f at their ends, shape (P,), f_in > 0 >= f_out.
    xtol : numpy.ndarray
        Final bracket lengths, shape (P,), > 0.
    max_iter : int
        Cap on the steps; past half of it each step bisects.
    bracket : bool
        Return the final brackets (x_in, f_in, x_out, f_out) instead of their midpoints.
    """
    a, fa, b, fb = x_in.copy(), f_in.copy(), x_out.copy(), f_out.copy()
    last = np.zeros(a.size, dtype=int)  # which end moved last (+1 a, -1 b)
    for it in range(max_iter):
        act = np.nonzero(np.abs(b - a) > xtol)[0]
        if act.size == 0:
            return (a, fa, b, fb) if bracket else 0.5 * (a + b)
        A_, FA, B_, FB = a[act], fa[act], b[act], fb[act]
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            x = np.where(FA != FB, B_ - FB * (B_ - A_) / (FB - FA), 0.5 * (A_ + B_))
        if it >= max_iter // 2:  # stagnating (f at round-off): bisect
            x = 0.5 * (A_ + B_)
        lo_, hi_ = np.minimum(A_, B_), np.maximum(A_, B_)
        x = np.where((x > lo_) & (x < hi_), x, 0.5 * (A_ + B_))
        tol = 0.5 * xtol[act]  # at least xtol / 2 inside: the bracket always shrinks
        x = np.clip(x, lo_ + tol, hi_ - tol)
        fx = f(x, act)
        pos = fx > 0.0
        # Illinois: halve the value at the end that stays twice in a row
        fb[act] = np.where(pos & (last[act] == 1), 0.5 * FB, FB)
        fa[act] = np.where(~pos & (last[act] == -1), 0.5 * FA, FA)
        a[act] = np.where(pos, x, A_)
        fa[act] = np.where(pos, fx, fa[act])
        b[act] = np.where(pos, B_, x)
        fb[act] = np.where(pos, fb[act], fx)
        last[act] = np.where(pos, 1, -1)
    raise NoConvergenceError(f"boundary refinement: no convergence in {max_iter} iterations")


def expand_bracket(f, x0: np.ndarray, f0: np.ndarray, d0: np.ndarray, direction,
                   limit: np.ndarray, *, factor: float = 3.0,
                   max_iter: int = 80) -> tuple[np.ndarray, ...]:
    """March from x0 by d0 factor^m towards ``limit`` until f's sign differs from f0's.

    Returns x_in, f_in (last point with f0's sign, x0 if none), x_out, f_out (the first without;
    x0, 0 if none) and ``clipped`` (the march reached ``limit``).

    Parameters
    ----------
    f : callable
        f(x, idx) -> values.
    x0, f0, d0 : numpy.ndarray
        Starting points, f there and first steps (> 0), shape (P,).
    direction : float or numpy.ndarray
        +1 or -1 per problem.
    limit : numpy.ndarray
        End of each march (its last point).
    factor : float
        Growth of the step per point, > 1.
    max_iter : int
        Cap on the points (:class:`NoConvergenceError` past it).
    """
    x_in, f_in = x0.copy(), np.asarray(f0, dtype=float).copy()
    x_out, f_out = x0.copy(), np.zeros(x0.size)
    clipped = np.zeros(x0.size, dtype=bool)
    open_ = np.ones(x0.size, dtype=bool)
    sign = np.sign(f_in)
    d = d0.copy()
    for _ in range(max_iter):
        if not open_.any():
            return x_in, f_in, x_out, f_out, clipped
        x = x0 + direction * d
        past = direction * (x - limit) >= 0.0
        x = np.where(past, limit, x)
        idx = np.nonzero(open_)[0]
        fx = f(x[idx], idx)
        inside = np.sign(fx) == sign[idx]
        out_i, in_i = idx[~inside], idx[inside]
        x_out[out_i], f_out[out_i] = x[out_i], fx[~inside]
        x_in[in_i], f_in[in_i] = x[in_i], fx[inside]
        open_[out_i] = False
        hit = in_i[past[in_i]]
        clipped[hit] = True
        open_[hit] = False
        d = d * factor
    raise NoConvergenceError(f"bracketing: no sign change in {max_iter} expansions")
