"""Mathieu's equation y'' + (a - 2 q cos 2t) y = 0: characteristic exponent, tongues, damping.

Solutions e^(+-i beta t) P(t), P pi-periodic, cos(pi beta) = y1(pi); beta by a Magnus
monodromy or by Hill's determinant (a continuant with its tail summed analytically), on the
branch beta -> sqrt(a) as q -> 0; tongue r followed along the ray q = g x / 2, x = a.
Theory: docs/theory/beam-pitch.md, docs/theory/bands.md.

References: N. W. McLachlan, *Theory and Application of Mathieu Functions*, 1947, ch. IV;
E. T. Whittaker, G. N. Watson, *A Course of Modern Analysis*, 1927, 19.41-19.42;
Abramowitz & Stegun, ch. 20; S. Blanes, F. Casas, J. Ros, BIT 40 (2000) 434-450 (Magnus);
V. V. Bolotin, *The Dynamic Stability of Elastic Systems*, 1964, sec. 6.
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any

import numpy as np
from scipy import special

from ..checks import count
from .optimize import expand_bracket

__all__ = ["MATHIEU_SCALE_MAX", "characteristic_exponent", "floquet_discriminant",
           "beta_from_discriminants", "transition_curves", "characteristic_value",
           "tongue_edges", "damped_tongue", "tongue_critical_gamma",
           "tongue_critical_damping", "ZETA_SEARCH_MAX", "hill_order"]

_METHODS = ("floquet", "hill")
#: Largest sqrt(|a| + 2|q|) of both methods: their cost grows like it (24 + 16 sqrt(a)
#: Magnus steps, 4 sqrt(a) Hill rows), so it is bounded (a up to about 1e6).
MATHIEU_SCALE_MAX = 1000.0
#: Matrix entries per batch of :func:`transition_curves` (32 MB of float64).
_TRANSITION_ENTRIES = 1 << 22
_EPS = np.finfo(float).eps


def _as_grid(a: Any, q: Any) -> tuple[np.ndarray, np.ndarray]:
    a = np.asarray(a, dtype=float)
    q = np.asarray(q, dtype=float)
    if not np.all(np.isfinite(a)):
        raise ValueError("a: every value must be finite")
    if not np.all(np.isfinite(q)):
        raise ValueError("q: every value must be finite")
    try:
        a, q = np.broadcast_arrays(a, q)
    except ValueError:
        raise ValueError(f"a, q: shapes {a.shape} and {q.shape} must broadcast together"
                         ) from None
    return a, np.abs(q)  # the exponent is even in q (shift tau_1 by pi/2)


def hill_order(a: Any, q: Any) -> int:
    """Truncation N of the Hill matrices (|m| <= 2N + 1): |a| <= (2N)^2 / 16 and (2N) >= 22 sqrt(q)
    keep the O(eps^3) remainder, eps = q^2 / (2N)^4, below 1e-15 (mpmath, tests, q <= 20); the
    continuant's work per point grows like N. ValueError past MATHIEU_SCALE_MAX.

    Parameters
    ----------
    a, q : array_like
        Mathieu parameters (dimensionless); their largest |a| and q decide.
    """
    a, q = np.asarray(a, dtype=float), np.asarray(q, dtype=float)
    amax = float(np.max(np.abs(a))) if a.size else 0.0
    qmax = float(np.max(q)) if q.size else 0.0
    if np.sqrt(amax + 2.0 * qmax) > MATHIEU_SCALE_MAX:  # bounded cost
        raise ValueError(f"a = {amax:.6g}, q = {qmax:.6g}: sqrt(|a| + 2|q|) exceeds "
                         f"{MATHIEU_SCALE_MAX:g} (Hill's matrices would need more than "
                         f"{int(8 * MATHIEU_SCALE_MAX)} rows)")
    m_needed = max(4.0 * np.sqrt(amax), 22.0 * np.sqrt(qmax))
    return int(np.ceil(m_needed / 2.0)) + 6


def _chain_series(m0: int, factors: tuple[tuple[int, int], ...], kmax: int) -> np.ndarray:
    """Coefficients c_k (k = 0..kmax) of sum_(m = m0, m0+2, ...) prod ((m + 2s)^2 - a)^-p over the
    pairs (s, p) of ``factors``: each factor expanded in a, summed over 2000 m (remainder < 1e-18).
    """
    m = m0 + 2.0 * np.arange(2000)
    k = np.arange(kmax + 1)[:, None]
    total = None
    for s, p in factors:
        inv = 1.0 / (m + 2.0 * s) ** 2
        binom = special.comb(k + p - 1, p - 1)
        ser = binom * inv ** (k + p)  # (kmax + 1, M)
        if total is None:
            total = ser
        else:
            prod = np.zeros_like(total)
            for i in range(kmax + 1):
                prod[i:] += total[i] * ser[: kmax + 1 - i]
            total = prod
    return np.sum(total, axis=1)


@lru_cache(maxsize=64)  # a function of (m0, kmax) alone: few pairs per run, ~1 ms each
def _tail_coefficients(m0: int, kmax: int) -> dict[str, np.ndarray]:
    """Power series in a of the Hill continuant's tails beyond |m| = m0 - 2 (m = m0 - 2, m0, ...):
    "diag" sum log(1 - a/m^2); "link" sum 1/((m^2 - a)((m+2)^2 - a)); "sq" the same squared;
    "adj" sum 1/((m^2 - a)((m+2)^2 - a)^2 ((m+4)^2 - a)).
    """
    k = np.arange(kmax + 1)
    diag = np.zeros(kmax + 1)
    # sum_(m = m0, m0+2, ...) m^(-2k) = 4^(-k) zeta(2k, m0/2) (Hurwitz zeta)
    diag[1:] = -special.zeta(2.0 * k[1:], m0 / 2.0) / (4.0 ** k[1:] * k[1:])
    ml = m0 - 2  # first neglected link: rows m0 - 2 (kept) and m0 (dropped)
    link = _chain_series(ml, ((0, 1), (1, 1)), kmax)
    # leading term exact: 1/(m^2 (m+2)^2) = [m^-2 + (m+2)^-2 - 2/(m (m+2))] / 4, telescoping
    link[0] = 0.25 * (
        special.zeta(2.0, ml / 2.0) / 4.0 + special.zeta(2.0, ml / 2.0 + 1.0) / 4.0 - 1.0 / ml
    )
    out = {
        "diag": diag,
        "link": link,
        "sq": _chain_series(ml, ((0, 2), (1, 2)), kmax),
        "adj": _chain_series(ml, ((0, 1), (1, 2), (2, 1)), kmax),
    }
    for c in out.values():  # shared by every call (cached): read-only
        c.setflags(write=False)
    return out


def _series_order(a: np.ndarray, m0: int) -> int:
    """Number of terms of the tail series in a/m0^2 for 1e-18 (at most 60)."""
    ratio = float(np.max(np.abs(a))) / m0**2 if a.size else 0.0
    if ratio <= 0.0:
        return 1
    return int(min(60, np.ceil(np.log(1e-18) / np.log(ratio)) + 1))


def _series(coef: np.ndarray, a: np.ndarray) -> np.ndarray:
    """Horner evaluation of sum_k coef_k a^k."""
    out = np.full(a.shape, coef[-1])
    for kk in range(coef.size - 2, -1, -1):
        out *= a
        out += coef[kk]
    return out


def _log_tail(a: np.ndarray, q: np.ndarray, m_last: int, kmax: int) -> np.ndarray:
    """log of the factor the rows |m| > m_last contribute to Hill's determinant: with links
    eps(m) = q^2/((m^2 - a)((m+2)^2 - a)), log det = sum log d - sum eps - (1/2) sum eps^2 -
    sum_(adjacent) eps eps' + O(eps^3), one side summed and doubled.
    """
    tail = _tail_coefficients(m_last + 2, kmax)
    q2 = q * q
    eps_core = q2 / (((m_last - 2) ** 2 - a) * (m_last**2 - a))  # last kept link
    eps_first = q2 / ((m_last**2 - a) * ((m_last + 2) ** 2 - a))  # first dropped link
    one_side = (
        _series(tail["diag"], a)
        - q2 * _series(tail["link"], a)
        - 0.5 * q2 * q2 * _series(tail["sq"], a)
        - q2 * q2 * _series(tail["adj"], a)
        - eps_core * eps_first
    )
    return 2.0 * one_side


def _hill(a: np.ndarray, q: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """1 - cos(pi beta), 1 + cos(pi beta) and the number of characteristic values below a.

    1 - cos(pi beta) = 2 sin^2(pi sqrt(a)/2) Delta_even(0), 1 + cos(pi beta) =
    2 cos^2(pi sqrt(a)/2) Delta_odd (Whittaker & Watson 19.42); row m scaled by (1 - a/m^2) (row 0
    by a), so no entry is singular; the pivot recurrence also gives the Sturm count; the rows
    beyond m_N by :func:`_log_tail`.
    """
    N = hill_order(a, q)
    shape = a.shape
    a = a.ravel().astype(float)
    q = q.ravel().astype(float)
    tiny = 1e-150  # pivot floor: |off * prev_off| / tiny stays far below 1e308
    e_buf = np.empty(a.shape, dtype=np.intc)  # np.frexp's exponents
    neg = np.empty(a.shape, dtype=bool)

    def continuant(ms: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        # det = mantissa * 2**exponent (np.frexp after each row: exact, and no overflow at
        # large a, where the rows (1 - a/m^2) of small m multiply up past 1e308)
        det = np.ones_like(a)
        exponent = np.zeros(a.shape, dtype=np.int64)
        count = np.zeros(a.shape, dtype=np.int64)
        piv = None
        prev_off = None
        rows = {}  # rows m and -m are the same: computed once
        for m in ms:
            if m == 0:
                diag, off = a, -q  # row 0 of Delta times a: [-q, a, -q]
            elif abs(m) in rows:
                diag, off = rows.pop(abs(m))
            else:
                diag, off = 1.0 - a / m**2, q / m**2  # row m times (1 - a/m^2)
                if -m in ms:
                    rows[abs(m)] = diag, off
            # Hill rows: diag 1, off -q/(a - m^2), times the factor above
            piv = diag if piv is None else diag - off * prev_off / piv
            # a pivot of (nearly) zero: a floor keeps the next off^2 / piv finite (the product
            # of the two, which the determinant needs, tends to -off^2 for any small floor)
            small = np.abs(piv) < tiny
            if small.any():
                piv = np.where(small, np.where(piv < 0.0, -tiny, tiny), piv)
            det, e = np.frexp(det * piv, out=(det, e_buf))
            exponent += e
            # negative pivot of H - a I (row 0 was multiplied by a: there a positive one)
            np.add(count, np.greater(piv, 0.0, out=neg) if m == 0 else
                   np.less(piv, 0.0, out=neg), out=count)
            prev_off = off
        return det, exponent, count

    m_even, m_odd = 2 * N, 2 * N + 1  # largest |m| kept
    det_e, exp_e, cnt_e = continuant(2 * np.arange(-N, N + 1))
    det_o, exp_o, cnt_o = continuant(2 * np.arange(-N - 1, N + 1) + 1)
    kmax = _series_order(a, m_even)
    log_e = _log_tail(a, q, m_even, kmax) + exp_e * np.log(2.0)  # the tail times 2**exponent
    log_o = _log_tail(a, q, m_odd, kmax) + exp_o * np.log(2.0)
    one_minus = 0.5 * np.pi**2 * np.exp(log_e) * det_e  # 2 sin^2(pi sqrt(a)/2) Delta_even
    one_plus = 2.0 * np.exp(log_o) * det_o  # 2 cos^2(pi sqrt(a)/2) Delta_odd
    return one_minus.reshape(shape), one_plus.reshape(shape), (cnt_e + cnt_o).reshape(shape)


def _magnus(a: np.ndarray, q: np.ndarray, n_steps: int | None) -> tuple[np.ndarray, np.ndarray]:
    """1 - cos(pi beta), 1 + cos(pi beta) from the fundamental matrix at pi/2: Magnus-4 with n and
    2n steps, Richardson (16 F(2n) - F(n)) / 15; n defaults to 24 + 16 max sqrt(|a| + 2|q|).
    """
    if n_steps is None:
        scale = float(np.max(np.sqrt(np.abs(a) + 2.0 * q))) if a.size else 0.0
        if scale > MATHIEU_SCALE_MAX:  # 24 + 16 scale steps: bounded cost
            raise ValueError(f"a = {float(np.max(np.abs(a))):.6g}, q = {float(np.max(q)):.6g}: "
                             f"sqrt(|a| + 2|q|) = {scale:.6g} exceeds {MATHIEU_SCALE_MAX:g} "
                             "(the Magnus integration would need more than "
                             f"{int(24 + 16 * MATHIEU_SCALE_MAX)} steps)")
        n_steps = int(np.ceil(24.0 + 16.0 * scale))
    n_steps = int(n_steps)
    if not 1 <= n_steps <= 10**6:
        raise ValueError(f"n_steps = {n_steps!r}: must be an integer in 1..1000000")
    m1, p1 = _magnus_pass(a, q, n_steps)
    m2, p2 = _magnus_pass(a, q, 2 * n_steps)
    return (16.0 * m2 - m1) / 15.0, (16.0 * p2 - p1) / 15.0


def _magnus_pass(a: np.ndarray, q: np.ndarray, n_steps: int) -> tuple[np.ndarray, np.ndarray]:
    """One Magnus-4 pass over [0, pi/2] with n_steps equal steps; see :func:`_magnus`."""
    h = 0.5 * np.pi / n_steps
    c_comm = np.sqrt(3.0) * h**2 / 12.0
    off = h / (2.0 * np.sqrt(3.0))
    y11 = np.ones_like(a)  # y1
    y21 = np.zeros_like(a)  # y1'
    y12 = np.zeros_like(a)  # y2
    y22 = np.ones_like(a)  # y2'
    for i in range(n_steps):
        tm = (i + 0.5) * h
        c1, c2 = np.cos(2.0 * (tm - off)), np.cos(2.0 * (tm + off))  # two Gauss nodes
        wbar = a - q * (c1 + c2)  # mean of w = a - 2 q cos 2t over the nodes, eq. (4.2-3)
        cd = c_comm * (2.0 * q * (c2 - c1))  # sqrt(3) h^2/12 (w1 - w2)
        z = h * h * wbar - cd * cd  # Omega^2 = -z I for the traceless Magnus matrix
        root = np.sqrt(np.abs(z))
        pos = z >= 0.0
        if np.all(pos) and np.all(root > 0.0):  # oscillatory everywhere: the common case
            cc = np.cos(root)
            ss = np.sin(root) / root
        else:
            cc = np.where(pos, np.cos(root), np.cosh(root))
            safe = np.where(root == 0.0, 1.0, root)
            ss = np.where(root == 0.0, 1.0, np.where(pos, np.sin(root), np.sinh(root)) / safe)
        # exp(Omega) = cc I + ss Omega, Omega = [[-cd, h], [-h wbar, cd]]
        e11, e12, e21, e22 = cc - ss * cd, ss * h, -ss * h * wbar, cc + ss * cd
        y11, y21 = e11 * y11 + e12 * y21, e21 * y11 + e22 * y21
        y12, y22 = e11 * y12 + e12 * y22, e21 * y12 + e22 * y22
    return -2.0 * y21 * y12, 2.0 * y11 * y22


def beta_from_discriminants(one_minus: np.ndarray, one_plus: np.ndarray,
                            count: np.ndarray) -> np.ndarray:
    """Complex beta on the branch beta -> sqrt(a): real r < beta < r + 1 in a stable band, r + i mu
    inside tongue r.

    Parameters
    ----------
    one_minus, one_plus : numpy.ndarray
        1 - cos(pi beta), 1 + cos(pi beta), computed without cancellation.
    count : numpy.ndarray
        Characteristic values below a (a Sturm count): 2 r + 1 in stable band r.
    """
    even_tongue = one_minus < 0.0  # cos(pi beta) > 1
    odd_tongue = one_plus < 0.0  # cos(pi beta) < -1
    stable = ~(even_tongue | odd_tongue)
    half = count / 2.0
    # stable band r: count = 2 r + 1; a count that rounding made even is taken as the band above
    r_band = np.floor(half)
    frac = (
        2.0
        / np.pi
        * np.arctan2(np.sqrt(np.maximum(one_minus, 0.0)), np.sqrt(np.maximum(one_plus, 0.0)))
    )
    beta_stable = np.where(r_band % 2 == 0, r_band + frac, r_band + 1.0 - frac)
    r_even = 2.0 * np.round(half / 2.0)  # nearest even integer to count/2
    r_odd = 2.0 * np.round((half - 1.0) / 2.0) + 1.0  # nearest odd integer to count/2
    y = np.where(even_tongue, -one_minus, np.where(odd_tongue, -one_plus, 0.0))
    mu = np.log1p(y + np.sqrt(y * (y + 2.0))) / np.pi  # arccosh(1 + y) / pi
    re = np.where(stable, beta_stable, np.where(even_tongue, r_even, r_odd))
    return re + 1j * np.where(stable, 0.0, mu)


def _discriminants(a: np.ndarray, q: np.ndarray, method: str, n_steps: int | None
                   ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """1 - cos(pi beta), 1 + cos(pi beta) and the Sturm count (validated a, q)."""
    if method == "hill":
        return _hill(a, q)
    if method == "floquet":
        one_minus, one_plus = _magnus(a.ravel(), q.ravel(), n_steps)
        return one_minus.reshape(a.shape), one_plus.reshape(a.shape), _hill(a, q)[2]
    raise ValueError(f"method = {method!r}: must be one of {_METHODS}")


def floquet_discriminant(a: Any, q: Any, method: str = "floquet",
                         n_steps: int | None = None) -> np.ndarray:
    """cos(pi beta) = y1(pi) of Mathieu's equation, shaped like the broadcast of a and q.

    Parameters
    ----------
    a, q : array_like
        Mathieu parameters (dimensionless), broadcast together.
    method, n_steps
        As :func:`characteristic_exponent`.
    """
    a, q = _as_grid(a, q)
    if method == "floquet":
        one_minus, one_plus = _magnus(a.ravel(), q.ravel(), n_steps)
        return (0.5 * (one_plus - one_minus)).reshape(a.shape)
    one_minus, one_plus, _ = _discriminants(a, q, method, n_steps)
    return 0.5 * (one_plus - one_minus)


def characteristic_exponent(a: Any, q: Any, method: str = "floquet",
                            n_steps: int | None = None) -> np.ndarray:
    """Characteristic exponent beta of y'' + (a - 2 q cos 2t) y = 0, complex.

    Real where bounded (r < beta < r + 1 above tongue r), r + i mu (mu > 0) inside tongue r;
    accurate near integers, to about the square root of the discriminant's accuracy at a
    transition curve.

    Parameters
    ----------
    a, q : array_like
        Mathieu parameters (dimensionless), real, broadcast together; beta is even in q.
    method : {"floquet", "hill"}
        Monodromy by Magnus integration, or Hill's determinant (faster).
    n_steps : int, optional
        Magnus steps over [0, pi/2] ("floquet"; default 24 + 16 max sqrt(|a| + 2|q|)).
    """
    a, q = _as_grid(a, q)
    return beta_from_discriminants(*_discriminants(a, q, method, n_steps))


def transition_curves(q: Any, r_max: int = 4) -> dict[str, np.ndarray]:
    """Characteristic values {"a0".."a{r_max}", "b1".."b{r_max}"}: eigenvalues of the four
    tridiagonal matrices of A&S 20.2.21-20.2.25, batched over q; tongue r lies between b_r, a_r.

    Parameters
    ----------
    q : array_like
        q >= 0 (dimensionless), 1-D.
    r_max : int
        Highest order, 1..MATHIEU_SCALE_MAX; q with sqrt(2 q) <= MATHIEU_SCALE_MAX (bounded
        work: matrices of r_max + 12 + sqrt(q) rows, solved in batches of bounded memory).
    """
    q = np.atleast_1d(np.asarray(q, dtype=float))
    if q.ndim != 1 or not np.all(np.isfinite(q)) or np.any(q < 0):
        raise ValueError(f"q = {q!r}: must be a 1-D array of finite values >= 0")
    r_max = count("r_max", r_max, 1, int(MATHIEU_SCALE_MAX))  # a_r ~ r^2: bounded like a
    q_max = float(np.max(q)) if q.size else 0.0
    if np.sqrt(2.0 * q_max) > MATHIEU_SCALE_MAX:
        raise ValueError(f"q = {q_max:.6g} (the largest): sqrt(2 q) exceeds "
                         f"{MATHIEU_SCALE_MAX:g}")
    size = r_max + 12 + int(np.ceil(np.sqrt(q_max)))
    chunk = max(1, _TRANSITION_ENTRIES // (size * size))  # bounded memory per eigen-solve

    def eig(diag: np.ndarray, first: Any, off_first: Any) -> np.ndarray:
        first = np.broadcast_to(np.asarray(first, dtype=float), q.shape)
        out = np.empty((q.size, size))
        idx = np.arange(size)
        for lo in range(0, q.size, chunk):
            qc = q[lo:lo + chunk]
            mats = np.zeros((qc.size, size, size))
            mats[:, idx, idx] = diag
            mats[:, idx[:-1], idx[1:]] = qc[:, None]
            mats[:, idx[1:], idx[:-1]] = qc[:, None]
            mats[:, 0, 0] += first[lo:lo + chunk]
            mats[:, 0, 1] *= off_first
            mats[:, 1, 0] *= off_first
            out[lo:lo + chunk] = np.linalg.eigvalsh(mats)
        return out

    n = np.arange(size)
    a_even = eig((2.0 * n) ** 2, 0.0, np.sqrt(2.0))  # a_0, a_2, a_4, ...: cos 2nt, A&S 20.2.21
    b_even = eig((2.0 * n + 2.0) ** 2, 0.0, 1.0)  # b_2, b_4, ...: sin 2nt
    a_odd = eig((2.0 * n + 1.0) ** 2, q, 1.0)  # a_1, a_3, ...: cos (2n+1)t, (0,0) = 1 + q
    b_odd = eig((2.0 * n + 1.0) ** 2, -q, 1.0)  # b_1, b_3, ...: sin (2n+1)t, (0,0) = 1 - q
    out: dict[str, np.ndarray] = {}
    for r in range(r_max + 1):
        out[f"a{r}"] = (a_even if r % 2 == 0 else a_odd)[:, r // 2]
        if r >= 1:
            out[f"b{r}"] = b_even[:, r // 2 - 1] if r % 2 == 0 else b_odd[:, r // 2]
    return out


def characteristic_value(kind: str, r: int, q: float) -> float:
    """a_r(q) or b_r(q) at one q (A&S 20.2).

    Parameters
    ----------
    kind : {"a", "b"}
        The curve.
    r : int
        Order (r >= 1 for "b").
    q : float
        q >= 0.
    """
    return float(transition_curves(np.array([q]), r)[f"{kind}{r}"][0])


def _bracket(f, x0: float, f0: float, direction: float, step: float, limit: float) -> float:
    """First x = x0 + direction step 2^k (clipped to ``limit``) where f changes sign."""
    _, _, x_out, _, clipped = expand_bracket(
        lambda x, idx: np.array([f(float(v)) for v in x]), np.array([x0]), np.array([f0]),
        np.array([step]), direction, np.array([limit]), factor=2.0, max_iter=200)
    if clipped[0]:
        raise ValueError(f"x0 = {x0!r}: no sign change of the edge function towards {limit!r} "
                         "(tongue edge not bracketed)")
    return float(x_out[0])


def tongue_edges(r: int, g: float) -> tuple[float, float] | None:
    """(x_b, x_a), x_b < x_a: where the ray q = g x / 2 crosses b_r(q) and a_r(q) (x = a); None
    when a_r - b_r is below the curves' round-off. From the tip x = r^2 the midline is solved,
    then each edge outward in steps of the tongue's width.

    Parameters
    ----------
    r : int
        Tongue order, >= 1.
    g : float
        Slope of the ray (dimensionless), >= 0.
    """
    from scipy import optimize  # here: its import is a sixth of a run's (unused by most)

    def mid(x: float) -> float:
        q = 0.5 * g * x
        return x - 0.5 * (characteristic_value("a", r, q) + characteristic_value("b", r, q))

    x0 = float(r * r)
    f0 = mid(x0)
    if f0 == 0.0:
        xm = x0
    else:
        direction = -1.0 if f0 > 0.0 else 1.0
        # downwards as far as x = 0, where mid = -r^2 < 0 (a_r(0) = b_r(0) = r^2): a steep ray
        # (g >> 1, a heavily damped tongue) crosses the midline far below r^2
        limit = 0.0 if direction < 0 else 4.0 * x0 + 4.0
        x1 = _bracket(mid, x0, f0, direction, 0.01 * x0, limit)
        xm = optimize.brentq(mid, min(x0, x1), max(x0, x1), xtol=1e-15 * x0, rtol=4 * _EPS)
    qm = 0.5 * g * xm
    width = characteristic_value("a", r, qm) - characteristic_value("b", r, qm)
    if not width > 64.0 * _EPS * max(xm, 1.0):
        return None

    def ha(x: float) -> float:
        return x - characteristic_value("a", r, 0.5 * g * x)  # the ray on a_r (A&S 20.2)

    def hb(x: float) -> float:
        return x - characteristic_value("b", r, 0.5 * g * x)  # the ray on b_r

    xa_far = _bracket(ha, xm, ha(xm), 1.0, width, 4.0 * xm + 4.0)
    xb_far = _bracket(hb, xm, hb(xm), -1.0, width, 0.0)
    xa = optimize.brentq(ha, xm, xa_far, xtol=1e-15 * xm, rtol=4 * _EPS)
    xb = optimize.brentq(hb, xb_far, xm, xtol=1e-15 * xm, rtol=4 * _EPS)
    return xb, xa


def _mu(x: float, g: float) -> float:
    """Im beta at a = x, q = g x / 2 (Hill's determinant)."""
    return float(np.imag(characteristic_exponent(x, 0.5 * g * x, "hill")))


def damped_tongue(x_b: float, x_a: float, g: float, zeta: float) -> tuple | None:
    """Edges and growth peak of a tongue with damping (Bolotin 1964, sec. 6).

    y'' + 2 c y' + (a - 2 q cos 2t) y = 0, c = zeta sqrt(a), is Mathieu's equation for
    u = e^(c t) y with x = a (1 - zeta^2); y grows where f(x) = mu(x) - zeta sqrt(x / (1 -
    zeta^2)) > 0. Returns (x_lo, x_hi, x_m, f_m): the edges f = 0, the maximiser of
    f / sqrt(x) and f there; None when f <= 0 throughout.

    Parameters
    ----------
    x_b, x_a : float
        The undamped tongue on the ray q = g x / 2 (:func:`tongue_edges`).
    g : float
        Slope of the ray (dimensionless).
    zeta : float
        Damping ratio, 0 <= zeta < 1.
    """
    from scipy import optimize  # here: its import is a sixth of a run's (unused by most)
    s = 1.0 / (1.0 - zeta * zeta)

    def f(x: float) -> float:
        return _mu(x, g) - zeta * np.sqrt(x * s)  # growth minus damping

    res = optimize.minimize_scalar(lambda x: -f(x) / np.sqrt(x), bounds=(x_b, x_a),
                                   method="bounded",
                                   options={"xatol": 1e-10 * x_a, "maxiter": 500})
    x_m = float(res.x)
    f_m = f(x_m)
    if zeta == 0.0:
        return x_b, x_a, x_m, f_m
    if not f_m > 0.0:
        return None
    lo = optimize.brentq(f, x_b, x_m, xtol=1e-15 * x_m, rtol=4 * _EPS)
    hi = optimize.brentq(f, x_m, x_a, xtol=1e-15 * x_m, rtol=4 * _EPS)
    return lo, hi, x_m, f_m


def _tongue_peak(r: int, gamma: float, zeta: float) -> float:
    """Largest growth minus damping f = mu(x) - zeta sqrt(x / (1 - zeta^2)) over damped tongue r
    on the ray q = gamma x / (2 (1 - zeta^2)) (> 0: the tongue is open; Bolotin 1964, sec. 6);
    -zeta r / sqrt(1 - zeta^2) where the undamped tongue is below round-off."""
    from scipy import optimize  # here: its import is a sixth of a run's (unused by most)
    s = 1.0 / (1.0 - zeta * zeta)
    g = gamma * s
    edges = tongue_edges(r, g)
    if edges is None:
        return -zeta * np.sqrt(r * r * s)
    res = optimize.minimize_scalar(
        lambda x: -(_mu(x, g) - zeta * np.sqrt(x * s)), bounds=edges, method="bounded",
        options={"xatol": 1e-10 * edges[1], "maxiter": 500})
    return -float(res.fun)


def tongue_critical_gamma(r: int, gamma: float, zeta: float) -> float:
    """Smallest amplitude at which damped tongue r opens: brentq in gamma on the largest f of
    :func:`damped_tongue`; 0 when open down to 1e-12 gamma (Bolotin 1964, sec. 6).

    Parameters
    ----------
    r : int
        Tongue order, >= 1.
    gamma : float
        An amplitude at which the tongue is open (ray q = gamma x / (2 (1 - zeta^2))), > 0.
    zeta : float
        Damping ratio, 0 < zeta < 1.
    """
    from scipy import optimize  # here: its import is a sixth of a run's (unused by most)

    def peak(gam: float) -> float:
        return _tongue_peak(r, gam, zeta)

    g_lo = 1e-3 * gamma
    while peak(g_lo) > 0.0:
        g_lo *= 0.1
        if g_lo < 1e-12:
            return 0.0
    return float(optimize.brentq(peak, g_lo, gamma, xtol=1e-10 * gamma, rtol=1e-12,
                                 maxiter=200))


#: Largest damping ratio :func:`tongue_critical_damping` searches (zeta < 1).
ZETA_SEARCH_MAX = 0.999


def tongue_critical_damping(r: int, gamma: float) -> float:
    """Smallest damping ratio that closes tongue r at amplitude gamma: brentq in zeta on the
    largest f of :func:`damped_tongue` (Bolotin 1964, sec. 6); 0 where the undamped tongue is
    below round-off, :data:`ZETA_SEARCH_MAX` where that damping does not close it.

    Parameters
    ----------
    r : int
        Tongue order, >= 1.
    gamma : float
        Amplitude (ray q = gamma x / (2 (1 - zeta^2))), 0 < gamma < 1.
    """
    from scipy import optimize  # here: its import is a sixth of a run's (unused by most)

    def peak(zeta: float) -> float:
        return _tongue_peak(r, gamma, zeta)

    if not peak(0.0) > 0.0:
        return 0.0
    z_hi = gamma
    while peak(z_hi) > 0.0:  # bracket upwards: zeta_cr ~ gamma / 4 for r = 1, less above
        if z_hi >= ZETA_SEARCH_MAX:
            return ZETA_SEARCH_MAX
        z_hi = min(2.0 * z_hi, ZETA_SEARCH_MAX)
    z_lo = 0.5 * z_hi
    while peak(z_lo) <= 0.0:  # zeta_cr ~ q^r: down by decades
        z_hi, z_lo = z_lo, 0.1 * z_lo
        if z_lo < 1e-300:
            return 0.0
    return float(optimize.brentq(peak, z_lo, z_hi, xtol=1e-13 * z_lo, rtol=1e-12,
                                 maxiter=200))
