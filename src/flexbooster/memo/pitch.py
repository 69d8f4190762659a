"""Rigid-body pitch of the booster under the gimbaled pulsating thrust (memo section 4.2).

For small psi, eq. (4.2-1) with the lever arm d2 (erratum E2) is

    psi'' + (2 pi R1 d2 K T(t) / I_cm) psi = 0,  T(t) = T0 (1 - gamma cos Omega t),

and with tau_1 = Omega t / 2 it becomes the Mathieu equation (4.2-3)
psi'' + (a - 2 q cos 2 tau_1) psi = 0 with (4.2-4)

    a = 8 pi R1 d2 K T0 / (I_cm Omega^2) = 4 omega_psi^2 / Omega^2,   q = gamma a / 2,

where omega_psi = sqrt(2 pi R1 d2 K T0 / I_cm) is the rigid-body pitch frequency under the
steady thrust.

Stability is decided by the characteristic (Floquet) exponent beta: the equation has the
solutions e^(+-i beta tau_1) P(tau_1) with P pi-periodic, and cos(pi beta) = y1(pi) for the
even solution y1(0) = 1, y1'(0) = 0.  :func:`characteristic_exponent` computes beta

* ``"floquet"``: from the monodromy matrix, integrated over half a period with a fourth-order
  Magnus scheme (exact 2 x 2 exponentials), vectorised over all (a, q) at once, using
  1 - cos(pi beta) = -2 y1'(pi/2) y2(pi/2) and 1 + cos(pi beta) = 2 y1(pi/2) y2'(pi/2);
* ``"hill"``: from Hill's infinite determinant (Whittaker & Watson 19.42), a tridiagonal
  continuant here, for the pi-periodic and the pi-antiperiodic Fourier bases;
* ``"memo"``: the small-q formula (4.2-9) corrected per erratum E4; ``"memo-printed"``: as
  printed (sin(pi sqrt(a)/2)).

The branch of beta is the one that tends to sqrt(a) as q -> 0: in the stable band between the
characteristic values a_r(q) and b_(r+1)(q), r < beta < r + 1; inside the tongue between
b_r(q) and a_r(q), beta = r + i mu with mu > 0, and the solution grows like
e^(mu tau_1) = e^(mu Omega t / 2).  The band index r comes from a Sturm count of the Hill
matrices (the number of characteristic values below a).

References
----------
.. [1] Tech Memo 104, eqs. (2.2-2c), (4.2-1)..(4.2-9).
.. [2] N. W. McLachlan, *Theory and Application of Mathieu Functions*, Oxford, 1947, ch. IV.
.. [3] E. T. Whittaker, G. N. Watson, *A Course of Modern Analysis*, 4th ed., Cambridge, 1927,
   sec. 19.41-19.42 (Hill's determinant).
.. [4] M. Abramowitz, I. A. Stegun, *Handbook of Mathematical Functions*, NBS, 1964, ch. 20
   (20.2.21-20.2.25 characteristic values and stability chart; 20.3.15 small-q expansion).
.. [5] S. Blanes, F. Casas, J. Ros, "Improved high order integrators based on the Magnus
   expansion", BIT 40 (2000) 434-450 (fourth-order Magnus with two Gauss nodes).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import Any

import numpy as np
from scipy import special

from ..checks import count

__all__ = [
    "pitch_frequency",
    "mathieu_parameters",
    "characteristic_exponent",
    "floquet_discriminant",
    "transition_curves",
    "psi_three_term",
    "psi_numerical",
    "three_term_error",
    "PITCH_MAX_TONGUE",
    "MATHIEU_SCALE_MAX",
    "PitchBand",
    "pitch_band_edges",
    "pitch_tongue_omega_bound",
    "pitch_bands",
    "PitchResult",
    "pitch_analysis",
]

_METHODS = ("floquet", "hill", "memo", "memo-printed")
#: Largest sqrt(|a| + 2|q|) of the Floquet and Hill methods (a up to about 1e6): their cost
#: grows like it (24 + 16 sqrt(a) Magnus steps, 4 sqrt(a) Hill rows), so it is bounded
#: (issue 18); in the pipeline a = 4 omega_psi^2 / Omega^2 above it is a CaseError.
MATHIEU_SCALE_MAX = 1000.0


def pitch_frequency(F0: float, d2: float, K: float, I_cm: float) -> float:
    """Rigid-body pitch frequency omega_psi under the steady thrust (rad/s).

    Parameters
    ----------
    F0 : float
        Total steady thrust, F0 = 2 pi R1 T0 (N), >= 0.
    d2 : float
        Lever arm, CM to the aft edge (m) (erratum E2), > 0.
    K : float
        Gimbal gain (dimensionless, >= 0): the thrust turns by K psi.
    I_cm : float
        Pitch moment of inertia about the CM (kg m^2), > 0.

    Returns
    -------
    float
        omega_psi = sqrt(F0 d2 K / I_cm) (rad/s); zero when K = 0.

    References
    ----------
    Tech Memo 104, eq. (4.2-1) linearised, with erratum E2.
    """
    for name, value, positive in (
        ("F0", F0, False),
        ("d2", d2, True),
        ("K", K, False),
        ("I_cm", I_cm, True),
    ):
        ok = np.isfinite(value) and (value > 0 if positive else value >= 0)
        if not ok:
            rule = "> 0" if positive else ">= 0"
            raise ValueError(f"{name} = {value!r}: must be finite and {rule}")
    return float(np.sqrt(F0 * d2 * K / I_cm))  # eq. (4.2-1), sin(K psi) ~ K psi


def mathieu_parameters(
    Omega: np.ndarray, omega_psi: float, gamma: float
) -> tuple[np.ndarray, np.ndarray]:
    """Mathieu parameters a(Omega), q(Omega) of the rigid-body pitch equation.

    Parameters
    ----------
    Omega : array_like
        Thrust pulsation frequency (rad/s), > 0.
    omega_psi : float
        Rigid-body pitch frequency (rad/s), >= 0, see :func:`pitch_frequency`.
    gamma : float
        Relative amplitude of the thrust pulsation (dimensionless), >= 0.

    Returns
    -------
    a, q : numpy.ndarray
        a = 4 omega_psi^2 / Omega^2 = 8 pi R1 d2 K T0 / (I_cm Omega^2) and q = gamma a / 2
        (eq. 4.2-4), dimensionless, shaped like ``Omega``.

    References
    ----------
    Tech Memo 104, eq. (4.2-4) with erratum E2.
    """
    Omega = np.asarray(Omega, dtype=float)
    if Omega.size == 0 or not np.all(np.isfinite(Omega)) or np.any(Omega <= 0):
        raise ValueError(f"Omega = {Omega!r}: every value must be finite and > 0")
    if not (np.isfinite(omega_psi) and omega_psi >= 0):
        raise ValueError(f"omega_psi = {omega_psi!r}: must be finite and >= 0")
    if not (np.isfinite(gamma) and gamma >= 0):
        raise ValueError(f"gamma = {gamma!r}: must be finite and >= 0")
    a = 4.0 * omega_psi**2 / Omega**2  # eq. (4.2-4): 8 pi R1 d2 K T0 / (I_cm Omega^2)
    q = gamma * a / 2.0  # eq. (4.2-4)
    return a, q


# --------------------------------------------------------------------------------------------
# Characteristic exponent
# --------------------------------------------------------------------------------------------


def _as_grid(a: Any, q: Any) -> tuple[np.ndarray, np.ndarray]:
    a = np.asarray(a, dtype=float)
    q = np.asarray(q, dtype=float)
    if not np.all(np.isfinite(a)):
        raise ValueError("a: every value must be finite")
    if not np.all(np.isfinite(q)):
        raise ValueError("q: every value must be finite")
    a, q = np.broadcast_arrays(a, q)
    return a, np.abs(q)  # the exponent is even in q (shift tau_1 by pi/2)


def _hill_order(a: np.ndarray, q: np.ndarray) -> int:
    """Truncation N of the Hill matrices (Fourier indices |m| <= 2N + 1) for these a, q.

    N makes |a| <= (2N)^2 / 16 (the tail series in a converge fast) and the neglected links
    small: with the tail included to second order, the remainder is O(eps^3),
    eps = q^2 / (2N)^4, and (2N) >= 22 sqrt(q) keeps it below 1e-15 (checked against mpmath
    up to q = 20 in the tests).
    """
    amax = float(np.max(np.abs(a))) if a.size else 0.0
    qmax = float(np.max(q)) if q.size else 0.0
    if np.sqrt(amax + 2.0 * qmax) > MATHIEU_SCALE_MAX:  # bounded cost (issue 18)
        raise ValueError(f"a = {amax:.6g}, q = {qmax:.6g}: sqrt(|a| + 2|q|) exceeds "
                         f"{MATHIEU_SCALE_MAX:g} (Hill's matrices would need more than "
                         f"{int(8 * MATHIEU_SCALE_MAX)} rows)")
    m_needed = max(4.0 * np.sqrt(amax), 22.0 * np.sqrt(qmax))
    return int(np.ceil(m_needed / 2.0)) + 6


def _chain_series(m0: int, factors: tuple[tuple[int, int], ...], kmax: int) -> np.ndarray:
    """Coefficients c_k (k = 0..kmax) of sum_(m = m0, m0+2, ...) prod ((m + 2s)^2 - a)^-p.

    ``factors`` are pairs (s, p).  Each factor is the series
    sum_k binom(k + p - 1, p - 1) a^k x^-(k + p), x = (m + 2s)^2; the product is truncated at
    a^kmax and summed explicitly over 2000 values of m (the terms fall at least like m^-6:
    remainder below 1e-18).
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
    """Power series in a of the tails of the Hill continuant beyond |m| = m0 - 2.

    Keys: ``"diag"``: sum_(m >= m0) log(1 - a/m^2) (Hurwitz zeta values);
    ``"link"``: sum_(m >= m0 - 2) 1/((m^2 - a)((m+2)^2 - a)) (exact partial-fraction leading
    term); ``"sq"``: the same with both factors squared; ``"adj"``: sum_(m >= m0 - 2)
    1/((m^2 - a)((m+2)^2 - a)^2 ((m+4)^2 - a)); m runs over m0 - 2, m0, m0 + 2, ...
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
    """log of the factor that the rows |m| > m_last contribute to the Hill determinant.

    Rows scaled to diagonal 1 - a/m^2 have link products eps(m) = q^2/((m^2 - a)((m+2)^2 - a))
    between rows m and m + 2; expanding log det in the links,
    log det = sum log d - sum eps - (1/2) sum eps^2 - sum_(adjacent) eps eps' + O(eps^3).
    The terms that involve a dropped row are summed here for one side (m > 0) and doubled.
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

    Hill's determinant in the pi-periodic basis e^(2 i n t) gives (Whittaker & Watson 19.42)
    1 - cos(pi beta) = 2 sin^2(pi sqrt(a)/2) Delta_even(0); in the antiperiodic basis
    e^(i (2n+1) t), 1 + cos(pi beta) = 2 cos^2(pi sqrt(a)/2) Delta_odd.  Each row m of Delta
    (diagonal 1, off-diagonal -q / (a - m^2)) is multiplied by (1 - a/m^2) (row m = 0 by a),
    which absorbs the product formulas of sin and cos, so no entry is singular at a = m^2;
    the continuant is evaluated by its pivot recurrence, whose signs also give the Sturm
    count of the symmetric matrices (diag m^2, off-diagonal q).  The rows |m| > m_N are
    accounted for analytically (:func:`_log_tail`: the tails of the sin/cos products and the
    links to second order); the truncated determinant alone converges only like q^2 / m_N^3.
    """
    N = _hill_order(a, q)
    shape = a.shape
    a = a.ravel().astype(float)
    q = q.ravel().astype(float)
    tiny = 1e-150  # pivot floor: |off * prev_off| / tiny stays far below 1e308
    e_buf = np.empty(a.shape, dtype=np.intc)  # np.frexp's exponents
    neg = np.empty(a.shape, dtype=bool)

    def continuant(ms: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        # det = mantissa * 2**exponent (np.frexp after each row: exact, and no overflow at
        # large a, where the rows (1 - a/m^2) of small m multiply up past 1e308; issue 18)
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
    """1 - cos(pi beta), 1 + cos(pi beta) from the fundamental matrix at pi/2.

    Fourth-order Magnus with n and 2n steps, combined by Richardson extrapolation
    (16 F(2n) - F(n)) / 15 (sixth order); n defaults to 24 + 16 max sqrt(|a| + 2|q|).
    """
    if n_steps is None:
        scale = float(np.max(np.sqrt(np.abs(a) + 2.0 * q))) if a.size else 0.0
        if scale > MATHIEU_SCALE_MAX:  # 24 + 16 scale steps: bounded cost (issue 18)
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


def _count(a: np.ndarray, q: np.ndarray) -> np.ndarray:
    return _hill(a, q)[2]


def _beta_from(one_minus: np.ndarray, one_plus: np.ndarray, count: np.ndarray) -> np.ndarray:
    """Complex beta on the branch beta -> sqrt(a) (q -> 0) from 1 -+ cos(pi beta)."""
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


def floquet_discriminant(
    a: Any, q: Any, method: str = "floquet", n_steps: int | None = None
) -> np.ndarray:
    """The Floquet discriminant cos(pi beta) = y1(pi) of the Mathieu equation (4.2-3).

    Parameters
    ----------
    a : array_like
        Mathieu parameter a (dimensionless).
    q : array_like
        Mathieu parameter q (dimensionless), broadcast against ``a``.
    method : {"floquet", "hill", "memo", "memo-printed"}
        See :func:`characteristic_exponent`.
    n_steps : int, optional
        Magnus steps over [0, pi/2] for ``"floquet"`` (the scheme also runs 2 n_steps and
        extrapolates); default 24 + 16 max sqrt(|a| + 2|q|).

    Returns
    -------
    numpy.ndarray
        cos(pi beta) (dimensionless), shaped like the broadcast of ``a`` and ``q``.

    References
    ----------
    McLachlan (1947) ch. IV; Whittaker & Watson (1927) 19.42; Tech Memo 104, eq. (4.2-9).
    """
    a, q = _as_grid(a, q)
    one_minus, one_plus, _ = _discriminants(a, q, method, n_steps)
    return 0.5 * (one_plus - one_minus)


def _discriminants(
    a: np.ndarray, q: np.ndarray, method: str, n_steps: int | None
) -> tuple[np.ndarray, np.ndarray, np.ndarray | None]:
    if method == "hill":
        return _hill(a, q)
    if method == "floquet":
        one_minus, one_plus = _magnus(a.ravel(), q.ravel(), n_steps)
        return one_minus.reshape(a.shape), one_plus.reshape(a.shape), None
    if method in ("memo", "memo-printed"):
        if np.any(a <= 0.0):
            raise ValueError(f"a = {a!r}: method {method!r} (eq. 4.2-9) needs every a > 0")
        if np.any(a == 1.0):
            raise ValueError("a = 1: eq. (4.2-9) is singular at a = 1 (factor 1/(a - 1))")
        sa = np.sqrt(a)
        if method == "memo":
            s_term = np.sin(np.pi * sa)  # eq. (4.2-9) corrected, erratum E4
        else:
            s_term = np.sin(np.pi * sa / 2.0)  # eq. (4.2-9) as printed
        # eq. (4.2-9): cos(beta pi) = cos(pi a^1/2) + pi q^2 / (4 a^1/2 (a - 1)) sin(...)
        corr = np.pi * q**2 / (4.0 * sa * (a - 1.0)) * s_term
        # 1 -+ cos(pi beta) with 1 -+ cos(pi sqrt a) written as 2 sin^2, 2 cos^2 (no cancellation)
        one_minus = 2.0 * np.sin(0.5 * np.pi * sa) ** 2 - corr
        one_plus = 2.0 * np.cos(0.5 * np.pi * sa) ** 2 + corr
        return one_minus, one_plus, None
    raise ValueError(f"method = {method!r}: must be one of {_METHODS}")


def characteristic_exponent(
    a: Any, q: Any, method: str = "floquet", n_steps: int | None = None
) -> np.ndarray:
    """Characteristic exponent beta of psi'' + (a - 2 q cos 2 tau_1) psi = 0 (eq. 4.2-3).

    Parameters
    ----------
    a : array_like
        Mathieu parameter a = 4 omega_psi^2 / Omega^2 (dimensionless, eq. 4.2-4); any real.
    q : array_like
        Mathieu parameter q = gamma a / 2 (dimensionless), broadcast against ``a``; beta is
        even in q.
    method : {"floquet", "hill", "memo", "memo-printed"}
        ``"floquet"``: monodromy matrix by a vectorised fourth-order Magnus integration;
        ``"hill"``: Hill's determinant (fastest; the benchmark method);
        ``"memo"``: eq. (4.2-9) with erratum E4, cos(pi beta) = cos(pi sqrt a)
        + pi q^2 / (4 sqrt(a) (a - 1)) sin(pi sqrt a), valid for small q away from a = 1
        (memo range 0 < a < 1, 0 < q <= 0.05, eq. 4.2-5); needs a > 0, a != 1;
        ``"memo-printed"``: eq. (4.2-9) as printed, with sin(pi sqrt(a) / 2).
    n_steps : int, optional
        Number of Magnus steps over [0, pi/2] (``"floquet"`` only).

    Returns
    -------
    numpy.ndarray of complex
        beta, shaped like the broadcast of ``a`` and ``q``.  Real (imaginary part 0) where the
        solutions are bounded, r < beta < r + 1 in the stable band above the tongue r;
        r + i mu with mu > 0 inside the tongue r (between b_r(q) and a_r(q); r = 0 for
        a < a_0(q)), where the solution grows like e^(mu tau_1).  The band index r is the
        Sturm count of the Hill matrices for every method (for ``"memo"`` it is the
        q -> 0 band, floor(sqrt a)).

    Notes
    -----
    cos(pi beta) = y1(pi) (McLachlan ch. IV).  Both 1 - cos(pi beta) and 1 + cos(pi beta) are
    computed without cancellation (as products, see :func:`floquet_discriminant`), so beta is
    accurate near integers; at a transition curve beta has a square-root singularity in a
    and q, so there its accuracy is about the square root of the discriminant's.

    References
    ----------
    Tech Memo 104, eqs. (4.2-3), (4.2-9) (erratum E4); McLachlan (1947) ch. IV;
    Whittaker & Watson (1927) 19.42; Abramowitz & Stegun (1964) 20.3.15.
    """
    a, q = _as_grid(a, q)
    if method in ("memo", "memo-printed"):
        one_minus, one_plus, _ = _discriminants(a, q, method, n_steps)
        count = 2.0 * np.floor(np.sqrt(a)) + 1.0  # q -> 0 band r = floor(sqrt a)
        return _beta_from(one_minus, one_plus, count)
    one_minus, one_plus, count = _discriminants(a, q, method, n_steps)
    if count is None:
        count = _count(a, q)
    return _beta_from(one_minus, one_plus, count)


def transition_curves(q: Any, r_max: int = 4) -> dict[str, np.ndarray]:
    """Mathieu characteristic values a_r(q) (r = 0..r_max) and b_r(q) (r = 1..r_max).

    Parameters
    ----------
    q : array_like
        Mathieu parameter q >= 0 (dimensionless), 1-D.
    r_max : int
        Highest order (>= 1).

    Returns
    -------
    dict
        ``"a0"``..``"a{r_max}"`` and ``"b1"``..``"b{r_max}"``: arrays shaped like ``q``, the
        transition curves of the Ince-Strutt chart (dimensionless); tongue r lies between
        b_r and a_r.

    Notes
    -----
    Eigenvalues of the four symmetric tridiagonal matrices of A&S 20.2 (bases cos 2nt,
    sin 2nt, cos (2n+1)t, sin (2n+1)t), batched over q with ``numpy.linalg.eigvalsh``.

    References
    ----------
    Abramowitz & Stegun (1964) 20.2.21-20.2.25; McLachlan (1947) ch. III.
    """
    q = np.atleast_1d(np.asarray(q, dtype=float))
    if q.ndim != 1 or not np.all(np.isfinite(q)) or np.any(q < 0):
        raise ValueError(f"q = {q!r}: must be a 1-D array of finite values >= 0")
    if int(r_max) != r_max or r_max < 1:
        raise ValueError(f"r_max = {r_max!r}: must be an integer >= 1")
    r_max = int(r_max)
    size = r_max + 12 + int(np.ceil(np.sqrt(float(np.max(q)) if q.size else 0.0)))

    def eig(diag: np.ndarray, first: Any, off_first: Any) -> np.ndarray:
        mats = np.zeros((q.size, size, size))
        idx = np.arange(size)
        mats[:, idx, idx] = diag
        mats[:, idx[:-1], idx[1:]] = q[:, None]
        mats[:, idx[1:], idx[:-1]] = q[:, None]
        mats[:, 0, 0] += first
        mats[:, 0, 1] *= off_first
        mats[:, 1, 0] *= off_first
        return np.linalg.eigvalsh(mats)

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


# --------------------------------------------------------------------------------------------
# psi(tau): the memo's three-term solution and direct integration
# --------------------------------------------------------------------------------------------


def _scalar_aq(a: Any, q: Any) -> tuple[float, float]:
    a, q = float(a), float(q)
    if not np.isfinite(a):
        raise ValueError(f"a = {a!r}: must be finite")
    if not np.isfinite(q):
        raise ValueError(f"q = {q!r}: must be finite")
    return a, q


def psi_three_term(
    tau1: Any, a: float, q: float, psi0: float = 1.0, beta: float | None = None
) -> np.ndarray:
    """The memo's three-term solution psi = sum_(i=1..3) A_i cos(Omega_i tau) (4.2-6..8).

    Parameters
    ----------
    tau1 : array_like
        Mathieu time tau_1 = Omega t / 2 (dimensionless).  The memo's tau = omega_1 t is
        tau = (2 omega_1 / Omega) tau_1 (4.2-6a), and Omega_i tau = (2 - beta) tau_1,
        beta tau_1, (2 + beta) tau_1 (4.2-7e..g).
    a, q : float
        Mathieu parameters (dimensionless), in the stable region.
    psi0 : float
        psi(0) (rad) (4.2-8a).
    beta : float, optional
        The exponent to use; default the exact (Floquet) exponent.  Must be real.

    Returns
    -------
    numpy.ndarray
        psi(tau_1) (rad), shaped like ``tau1``; psi'(0) = 0.

    References
    ----------
    Tech Memo 104, eqs. (4.2-6), (4.2-7), (4.2-8a).
    """
    a, q = _scalar_aq(a, q)
    if beta is None:
        b = complex(characteristic_exponent(a, q, "floquet"))
        if b.imag != 0.0:
            raise ValueError(
                f"a = {a}, q = {q}: unstable (beta = {b}); the three-term form "
                "(4.2-6) needs a real beta"
            )
        beta = b.real
    if not np.isfinite(beta):
        raise ValueError(f"beta = {beta!r}: must be finite and real")
    tau1 = np.asarray(tau1, dtype=float)
    den1 = a - (beta - 2.0) ** 2
    den3 = a - (2.0 + beta) ** 2
    if den1 == 0.0 or den3 == 0.0:
        raise ValueError(f"a = {a}, beta = {beta}: a - (2 -+ beta)^2 = 0 in eq. (4.2-7)")
    A2 = psi0 / (1.0 + q * (1.0 / den3 + 1.0 / den1))  # eq. (4.2-7c)
    A1 = A2 * q / den1  # eq. (4.2-7b)
    A3 = A2 * q / den3  # eq. (4.2-7d)
    return (
        A1 * np.cos((2.0 - beta) * tau1)  # eq. (4.2-6), (4.2-7e)
        + A2 * np.cos(beta * tau1)  # eq. (4.2-7f)
        + A3 * np.cos((2.0 + beta) * tau1)  # eq. (4.2-7g)
    )


def psi_numerical(tau1: Any, a: Any, q: Any, psi0: float = 1.0) -> np.ndarray:
    """psi(tau_1) by direct integration of eq. (4.2-3), psi(0) = psi0, psi'(0) = 0.

    Parameters
    ----------
    tau1 : array_like
        Increasing output times tau_1 >= 0 (dimensionless), 1-D.
    a, q : array_like
        Mathieu parameters (dimensionless); 1-D arrays of equal length (or scalars) give one
        solution per pair, integrated together as one system.
    psi0 : float
        Initial angle (rad).

    Returns
    -------
    numpy.ndarray
        Shape (len(a), len(tau1)) (or (len(tau1),) for scalar a, q), psi in rad.

    Notes
    -----
    scipy.integrate.solve_ivp, DOP853, rtol 1e-12, atol 1e-14 |psi0|.

    References
    ----------
    Tech Memo 104, eq. (4.2-3).
    """
    scalar = np.ndim(a) == 0 and np.ndim(q) == 0
    _as_grid(a, q)  # validation only: psi, unlike beta, depends on the sign of q
    a, q = np.broadcast_arrays(
        np.atleast_1d(np.asarray(a, dtype=float)), np.atleast_1d(np.asarray(q, dtype=float))
    )
    a, q = a.ravel(), q.ravel()
    tau1 = np.atleast_1d(np.asarray(tau1, dtype=float))
    if not np.all(np.isfinite(tau1)):
        raise ValueError("tau1: every time must be finite")
    if tau1.ndim == 1 and tau1.size and tau1[-1] * np.sqrt(np.max(np.abs(a) + 2 * np.abs(q),
                                                                  initial=0.0)) > 1e5:
        raise ValueError(f"tau1 = {tau1[-1]!r}: tau1_max sqrt(|a| + 2|q|) must be <= 1e5 "
                         "(about 16000 oscillations; a longer integration would not end)")
    if tau1.ndim != 1 or np.any(tau1 < 0) or np.any(np.diff(tau1) < 0):
        raise ValueError("tau1: must be a 1-D non-decreasing array of values >= 0")
    if not (np.isfinite(psi0) and psi0 != 0):
        raise ValueError(f"psi0 = {psi0!r}: must be finite and non-zero")
    m = a.size

    def rhs(t: float, y: np.ndarray) -> np.ndarray:
        return np.concatenate([y[m:], -(a - 2.0 * q * np.cos(2.0 * t)) * y[:m]])  # eq. (4.2-3)

    y0 = np.concatenate([np.full(m, float(psi0)), np.zeros(m)])
    t_end = float(tau1[-1])
    if t_end == 0.0:
        out = np.full((m, tau1.size), float(psi0))
    else:
        from scipy import integrate  # only here: its import is a tenth of a run's imports

        sol = integrate.solve_ivp(
            rhs, (0.0, t_end), y0, method="DOP853", t_eval=tau1, rtol=1e-12, atol=1e-14 * abs(psi0)
        )
        out = sol.y[:m]
    return out[0] if scalar else out


def three_term_error(
    a: float, q: Any, tau1_max: float = 20.0 * np.pi, n_times: int = 2001
) -> np.ndarray:
    """Error of the memo's three-term psi against direct integration, as a function of q.

    Parameters
    ----------
    a : float
        Mathieu parameter a (dimensionless), 0 < a < 1 (memo range, eq. 4.2-5).
    q : array_like
        Values of q (dimensionless), 1-D; each must lie in the stable region.
    tau1_max : float
        Length of the comparison in Mathieu time tau_1 (dimensionless).
    n_times : int
        Number of comparison times.

    Returns
    -------
    numpy.ndarray
        max over tau_1 in [0, tau1_max] of |psi_3 - psi| / |psi0|, shaped like ``q``, with the
        exact (Floquet) beta in the three-term form: the truncation error of (4.2-6), O(q^2).

    References
    ----------
    Tech Memo 104, eqs. (4.2-3), (4.2-6)..(4.2-8).
    """
    q = np.atleast_1d(np.asarray(q, dtype=float))
    if not (np.isfinite(tau1_max) and tau1_max > 0):
        raise ValueError(f"tau1_max = {tau1_max!r}: must be finite and > 0")
    tau = np.linspace(0.0, tau1_max, count("n_times", n_times, 2, 10**6))
    exact = psi_numerical(tau, np.full(q.shape, float(a)), q)
    betas = characteristic_exponent(float(a), q, "floquet")
    if np.any(betas.imag != 0.0):
        raise ValueError(f"q = {q!r}: every (a, q) must be stable for the three-term form")
    approx = np.stack(
        [psi_three_term(tau, a, qi, 1.0, float(b.real)) for qi, b in zip(q, betas, strict=True)]
    )
    return np.max(np.abs(approx - exact), axis=1)


# --------------------------------------------------------------------------------------------
# Exact instability bands in Omega (the operating path crossing the transition curves)
# --------------------------------------------------------------------------------------------
#: Largest tongue order r searched; tongues narrower than the round-off of a_r - b_r end the
#: search earlier (their width falls like (gamma / 8)^r).
PITCH_MAX_TONGUE = 60
_EPS = np.finfo(float).eps


@dataclass(frozen=True)
class PitchBand:
    """One instability band of the rigid-body pitch in Omega (Mathieu tongue r, memo 4.2).

    Attributes
    ----------
    omega_lo, omega_hi : float
        Band edges (rad/s): where the operating path a = 4 omega_psi^2 / Omega^2,
        q = gamma a / 2 (4.2-4) crosses a_r(q) (lower edge) and b_r(q) (upper edge); with
        damping, where the growth rate is zero.
    growth_rate_max : float
        Largest amplitude growth rate of psi inside the band (1/s).
    omega_at_max : float
        Omega where it occurs (rad/s).
    tongue : int
        Order r of the Mathieu tongue (Omega ~ 2 omega_psi / r).
    critical_gamma : float
        Smallest gamma at which the band exists (dimensionless); 0 without damping.
    clipped : bool
        True when an edge is an end of the Omega range asked for.

    References
    ----------
    Tech Memo 104, eqs. (4.2-3), (4.2-4); Abramowitz & Stegun (1964) 20.2; Bolotin (1964),
    sec. 6 (damping).
    """

    omega_lo: float
    omega_hi: float
    growth_rate_max: float
    omega_at_max: float
    tongue: int
    critical_gamma: float = 0.0
    clipped: bool = False

    @property
    def width(self) -> float:
        """omega_hi - omega_lo (rad/s)."""
        return self.omega_hi - self.omega_lo

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready mapping (plain floats, ints and bools)."""
        return {"omega_lo": float(self.omega_lo), "omega_hi": float(self.omega_hi),
                "width": float(self.width), "growth_rate_max": float(self.growth_rate_max),
                "omega_at_max": float(self.omega_at_max), "tongue": int(self.tongue),
                "critical_gamma": float(self.critical_gamma), "clipped": bool(self.clipped)}


def _char_value(kind: str, r: int, q: float) -> float:
    """a_r(q) or b_r(q) (A&S 20.2) at one q >= 0."""
    return float(transition_curves(np.array([q]), r)[f"{kind}{r}"][0])


def _expand(f: Any, x0: float, f0: float, direction: float, step: float,
            limit: float) -> float:
    """First x = x0 + direction step 2^k (clipped to ``limit``) with sign f(x) != sign f0."""
    for k in range(200):
        x = x0 + direction * step * 2.0**k
        x = min(x, limit) if direction > 0 else max(x, limit)
        if np.sign(f(x)) != np.sign(f0):
            return x
        if x == limit:
            break
    raise ValueError(f"x0 = {x0!r}: no sign change of the edge function towards {limit!r} "
                     "(tongue edge not bracketed)")


def _tongue_edges(r: int, g: float) -> tuple[float, float] | None:
    """(x_b, x_a): where the ray q = g x / 2 crosses b_r and a_r in the (q, a) plane.

    Started at the analytic tongue position x = r^2 (Omega = 2 omega_psi / r): the midline
    x = (a_r + b_r) / 2 is bracketed outward from there and solved (brentq); inside the tongue
    x - a_r < 0 < x - b_r, and each edge is bracketed outward from the midline with steps of
    the tongue's width.  None when a_r - b_r is below the round-off of the characteristic
    values (the tongue cannot be resolved).
    """
    from scipy import optimize  # here: its import is a sixth of a run's (unused by most)

    def mid(x: float) -> float:
        q = 0.5 * g * x
        return x - 0.5 * (_char_value("a", r, q) + _char_value("b", r, q))

    x0 = float(r * r)
    f0 = mid(x0)
    if f0 == 0.0:
        xm = x0
    else:
        direction = -1.0 if f0 > 0.0 else 1.0
        limit = 0.25 * x0 if direction < 0 else 4.0 * x0 + 4.0
        x1 = _expand(mid, x0, f0, direction, 0.01 * x0, limit)
        xm = optimize.brentq(mid, min(x0, x1), max(x0, x1), xtol=1e-15 * x0, rtol=4 * _EPS)
    qm = 0.5 * g * xm
    ar, br = _char_value("a", r, qm), _char_value("b", r, qm)
    width = ar - br
    if not width > 64.0 * _EPS * max(xm, 1.0):
        return None

    def ha(x: float) -> float:
        return x - _char_value("a", r, 0.5 * g * x)  # path on a_r: eq. (4.2-4), A&S 20.2

    def hb(x: float) -> float:
        return x - _char_value("b", r, 0.5 * g * x)  # path on b_r

    xa_far = _expand(ha, xm, ha(xm), 1.0, width, 4.0 * xm + 4.0)
    xb_far = _expand(hb, xm, hb(xm), -1.0, width, 0.0)
    xa = optimize.brentq(ha, xm, xa_far, xtol=1e-15 * xm, rtol=4 * _EPS)
    xb = optimize.brentq(hb, xb_far, xm, xtol=1e-15 * xm, rtol=4 * _EPS)
    return xb, xa


def _mu(x: float, g: float) -> float:
    """Im beta of psi'' + (x - 2 q cos 2 tau_1) psi = 0 at q = g x / 2 (Hill's determinant)."""
    return float(np.imag(characteristic_exponent(x, 0.5 * g * x, "hill")))


def _damped_band(x_b: float, x_a: float, g: float, zeta: float) -> tuple | None:
    """Edges and growth peak of f(x) = mu(x) - zeta sqrt(x / (1 - zeta^2)) in (x_b, x_a).

    f > 0 is growth of the damped pitch: with c = zeta sqrt(a) the substitution
    psi = e^(-c tau_1) u turns the damped equation into Mathieu's with x = a (1 - zeta^2).
    The growth rate in 1/s is f Omega / 2 with Omega proportional to x^(-1/2): the peak is
    that of f / sqrt(x).
    """
    from scipy import optimize  # here: its import is a sixth of a run's (unused by most)
    s = 1.0 / (1.0 - zeta * zeta)

    def f(x: float) -> float:
        return _mu(x, g) - zeta * np.sqrt(x * s)  # growth minus damping, see above

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


def _critical_gamma(r: int, gamma: float, zeta: float) -> float:
    """Smallest gamma at which tongue r of the damped pitch opens (brentq on the peak)."""
    from scipy import optimize  # here: its import is a sixth of a run's (unused by most)
    s = 1.0 / (1.0 - zeta * zeta)

    def peak(gam: float) -> float:
        g = gam * s
        edges = _tongue_edges(r, g)
        if edges is None:
            return -zeta * np.sqrt(r * r * s)
        res = optimize.minimize_scalar(
            lambda x: -(_mu(x, g) - zeta * np.sqrt(x * s)), bounds=edges, method="bounded",
            options={"xatol": 1e-10 * edges[1], "maxiter": 500})
        return -float(res.fun)

    g_lo = 1e-3 * gamma
    while peak(g_lo) > 0.0:
        g_lo *= 0.1
        if g_lo < 1e-12:
            return 0.0
    return float(optimize.brentq(peak, g_lo, gamma, xtol=1e-10 * gamma, rtol=1e-12,
                                 maxiter=200))


def pitch_tongue_omega_bound(omega_psi: float, gamma: float, *, tongue: int,
                             damping_ratio: float = 0.0) -> float:
    """An upper bound (rad/s) on the thrust frequencies of Mathieu tongue r, without a solve.

    Parameters
    ----------
    omega_psi : float
        Rigid-body pitch frequency (rad/s), >= 0.
    gamma : float
        Pulsation amplitude (dimensionless), 0 <= gamma < 1.
    tongue : int
        Tongue order r >= 1.
    damping_ratio : float
        Pitch damping ratio zeta (dimensionless), 0 <= zeta < 1.

    Returns
    -------
    float
        2 omega_psi sqrt((1 - zeta^2) (1 + g)) / r with g = gamma / (1 - zeta^2): every band
        edge of :func:`pitch_band_edges` (damped or not) at this gamma is at or below it, and
        so is every higher tongue's.

    Notes
    -----
    ``|a_r(q) - r^2|`` and ``|b_r(q) - r^2|`` are at most ``2|q|``: the term ``2 q cos 2 tau``
    of Mathieu's operator has norm ``2|q|``, and Weyl's inequality bounds the shift of each
    eigenvalue of a self-adjoint operator by the norm of the perturbation, in each parity class
    apart [1]_.  On the path ``q = g x / 2`` the tongue therefore starts at
    ``x_b >= r^2 / (1 + g)``, i.e. ``Omega = 2 omega_psi sqrt((1 - zeta^2) / x) <=`` the bound;
    the damped band lies inside the undamped tongue.

    References
    ----------
    .. [1] T. Kato, *Perturbation Theory for Linear Operators*, Springer, 1966, V.4.3.
    """
    for name, value in (("omega_psi", omega_psi), ("gamma", gamma),
                        ("damping_ratio", damping_ratio)):
        if not (np.isfinite(value) and value >= 0.0):
            raise ValueError(f"{name} = {value!r}: must be finite and >= 0")
    if not (gamma < 1.0 and damping_ratio < 1.0):
        raise ValueError(f"gamma = {gamma!r}, damping_ratio = {damping_ratio!r}: must be < 1")
    if isinstance(tongue, bool) or int(tongue) != tongue or tongue < 1:
        raise ValueError(f"tongue = {tongue!r}: must be an integer >= 1")
    s = 1.0 - damping_ratio * damping_ratio
    return float(2.0 * omega_psi * np.sqrt(s * (1.0 + gamma / s)) / tongue)


def pitch_band_edges(omega_psi: float, gamma: float, *, tongue: int,
                     damping_ratio: float = 0.0) -> tuple[float, float] | None:
    """Edges (omega_lo, omega_hi) (rad/s) of Mathieu tongue r on the operating path.

    Parameters
    ----------
    omega_psi : float
        Rigid-body pitch frequency (rad/s), > 0.
    gamma : float
        Pulsation amplitude (dimensionless), 0 <= gamma < 1.
    tongue : int
        Tongue order r >= 1 (Omega ~ 2 omega_psi / r).
    damping_ratio : float
        Pitch damping ratio zeta (dimensionless), 0 <= zeta < 1.

    Returns
    -------
    (float, float) or None
        The band edges as in :func:`pitch_bands` (not clipped to a range); (Omega_r, Omega_r)
        with Omega_r = 2 omega_psi sqrt(1 - zeta^2) / r at gamma = 0 without damping; None where
        the band does not exist (below the critical gamma with damping) or is narrower than
        round-off.

    References
    ----------
    Tech Memo 104, eqs. (4.2-3), (4.2-4); Abramowitz & Stegun (1964) 20.2; Bolotin (1964),
    sec. 6.
    """
    if not (np.isfinite(omega_psi) and omega_psi > 0.0):
        raise ValueError(f"omega_psi = {omega_psi!r}: must be finite and > 0")
    if not (np.isfinite(gamma) and 0.0 <= gamma < 1.0):
        raise ValueError(f"gamma = {gamma!r}: must satisfy 0 <= gamma < 1")
    if not (np.isfinite(damping_ratio) and 0.0 <= damping_ratio < 1.0):
        raise ValueError(f"damping_ratio = {damping_ratio!r}: must satisfy 0 <= zeta < 1")
    if isinstance(tongue, bool) or int(tongue) != tongue or not 1 <= tongue <= PITCH_MAX_TONGUE:
        raise ValueError(f"tongue = {tongue!r}: must be an integer in 1..{PITCH_MAX_TONGUE}")
    r, zeta = int(tongue), float(damping_ratio)
    s = 1.0 - zeta * zeta
    w = float(omega_psi)
    if gamma == 0.0:
        return None if zeta > 0.0 else (2.0 * w * np.sqrt(s) / r,) * 2
    g = gamma / s
    edges = _tongue_edges(r, g)
    if edges is None:
        return None
    if zeta > 0.0:
        band = _damped_band(edges[0], edges[1], g, zeta)
        if band is None:
            return None
        edges = band[:2]
    return (float(2.0 * w * np.sqrt(s / edges[1])), float(2.0 * w * np.sqrt(s / edges[0])))


def pitch_bands(omega_psi: float, gamma: float, *, omega_min: float, omega_max: float,
                damping_ratio: float = 0.0) -> tuple[PitchBand, ...]:
    """Every instability band of the rigid-body pitch in [omega_min, omega_max], exactly.

    Parameters
    ----------
    omega_psi : float
        Rigid-body pitch frequency (rad/s), >= 0 (:func:`pitch_frequency`).
    gamma : float
        Pulsation amplitude (dimensionless), 0 <= gamma < 1.
    omega_min, omega_max : float
        Range of the thrust frequency Omega (rad/s), 0 < omega_min < omega_max.
    damping_ratio : float
        zeta of psi'' + 2 zeta omega_psi psi' + omega_psi^2 (1 - gamma cos Omega t) psi = 0
        (dimensionless), 0 <= zeta < 1.

    Returns
    -------
    tuple of PitchBand
        Sorted by Omega.  Without damping the edges are the Omega where the operating path
        a(Omega) = 4 omega_psi^2 / Omega^2, q = gamma a / 2 (4.2-4) crosses a_r(q) and b_r(q),
        r = 1, 2, ... (every tongue the range reaches; a > 0 > a_0 so the region a < a_0 is
        never reached), solved by brentq from the analytic positions Omega ~ 2 omega_psi / r;
        with damping, psi = e^(-c tau_1) u (c = 2 zeta omega_psi / Omega) gives Mathieu's
        equation for u with a' = a (1 - zeta^2), and the edges are the roots of
        Im beta(a', q) = c inside the undamped tongue of the path (a', q).  The growth rate
        Im beta Omega / 2 - zeta omega_psi (1/s) is maximised inside each band (bounded
        scalar maximiser).  Tongues narrower than the round-off of a_r - b_r (about
        1e-14 r^2) are not reported.

    References
    ----------
    Tech Memo 104, eqs. (4.2-3), (4.2-4); Abramowitz & Stegun (1964) 20.2.21-20.2.25;
    McLachlan (1947) ch. IV; Bolotin (1964), sec. 6 (damped Mathieu equation).
    """
    for name, value, low in (("omega_psi", omega_psi, 0.0), ("gamma", gamma, 0.0),
                             ("damping_ratio", damping_ratio, 0.0)):
        if not (np.isfinite(value) and value >= low):
            raise ValueError(f"{name} = {value!r}: must be finite and >= 0")
    if gamma >= 1.0:
        raise ValueError(f"gamma = {gamma!r}: must be < 1")
    if damping_ratio >= 1.0:
        raise ValueError(f"damping_ratio = {damping_ratio!r}: must be < 1")
    for name, value in (("omega_min", omega_min), ("omega_max", omega_max)):
        if not (np.isfinite(value) and value > 0.0):
            raise ValueError(f"{name} = {value!r}: must be finite and > 0")
    if not omega_min < omega_max:
        raise ValueError(f"omega_min = {omega_min!r}: must be < omega_max = {omega_max!r}")
    if omega_psi == 0.0 or gamma == 0.0:
        return ()  # q = 0: a = r^2 are isolated points, no band
    zeta = float(damping_ratio)
    s = 1.0 - zeta * zeta
    g = gamma / s  # the path in (q, a') = (q, a (1 - zeta^2)): q = g a' / 2
    w = float(omega_psi)

    def omega(x: float) -> float:
        return 2.0 * w * np.sqrt(s / x)  # a' = x = 4 omega_psi^2 (1 - zeta^2) / Omega^2

    r_first = max(1, int(np.floor(2.0 * w / omega_max * 0.5)))
    bands = []
    for r in range(r_first, PITCH_MAX_TONGUE + 1):
        # a tongue wholly below omega_min by this bound (and every higher one) ends the search
        # before an edge is solved
        if pitch_tongue_omega_bound(w, gamma, tongue=r, damping_ratio=zeta) < omega_min:
            break
        edges = _tongue_edges(r, g)
        if edges is None:
            break  # this and every higher tongue is below round-off
        x_b, x_a = edges
        if omega(x_b) < omega_min:  # the whole tongue lies below the range, and higher ones
            break
        if omega(x_a) > omega_max:
            continue
        band = _damped_band(x_b, x_a, g, zeta)
        if band is None:
            continue
        x_lo, x_hi, x_m, f_m = band
        lo, hi = omega(x_hi), omega(x_lo)  # larger x is smaller Omega
        clipped = lo < omega_min or hi > omega_max
        lo, hi = max(lo, omega_min), min(hi, omega_max)
        om_m = omega(x_m)
        if not omega_min <= om_m <= omega_max:  # the peak is outside the clipped band
            om_m = lo if om_m < lo else hi
            x_m = 4.0 * w * w * s / om_m**2
            f_m = _mu(x_m, g) - zeta * np.sqrt(x_m / s)
        # growth of psi: e^((mu - c) tau_1), tau_1 = Omega t / 2, c = zeta sqrt(a)
        growth = max(f_m, 0.0) * om_m / 2.0
        crit = _critical_gamma(r, gamma, zeta) if zeta > 0.0 else 0.0
        bands.append(PitchBand(omega_lo=float(lo), omega_hi=float(hi),
                               growth_rate_max=float(growth), omega_at_max=float(om_m),
                               tongue=r, critical_gamma=crit, clipped=bool(clipped)))
    return tuple(sorted(bands, key=lambda b: b.omega_lo))


# --------------------------------------------------------------------------------------------
# Result object for the pipeline
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class PitchResult:
    """Rigid-body pitch stability along the Omega grid (memo section 4.2).

    Attributes
    ----------
    Omega : numpy.ndarray
        Thrust pulsation frequencies (rad/s).
    omega_psi : float
        Rigid-body pitch frequency (rad/s).
    gamma : float
        Pulsation amplitude (dimensionless).
    a, q : numpy.ndarray
        Mathieu parameters (4.2-4) (dimensionless).
    beta_real, beta_imag : numpy.ndarray
        Exact characteristic exponent (Floquet) (dimensionless).
    beta_memo_real, beta_memo_imag : numpy.ndarray
        Eq. (4.2-9) with erratum E4 (dimensionless); zero where a <= 0 or a = 1.
    growth_rate : numpy.ndarray
        Amplitude growth rate of psi, beta_imag Omega / 2 (1/s); 0 where stable.
    stable : numpy.ndarray of bool
        True where beta is real (bounded psi).
    in_memo_range : numpy.ndarray of bool
        0 < a < 1 and 0 < q <= 0.05 (eq. 4.2-5).
    verdict : str
        One-line stability verdict, from the bands.
    bands : tuple of PitchBand
        The exact instability bands in the range of the grid (:func:`pitch_bands`).
    damping_ratio : float
        zeta of the pitch damping (dimensionless).
    """

    Omega: np.ndarray
    omega_psi: float
    gamma: float
    a: np.ndarray
    q: np.ndarray
    beta_real: np.ndarray
    beta_imag: np.ndarray
    beta_memo_real: np.ndarray
    beta_memo_imag: np.ndarray
    growth_rate: np.ndarray
    stable: np.ndarray
    in_memo_range: np.ndarray
    verdict: str
    bands: tuple = ()
    damping_ratio: float = 0.0

    @property
    def all_stable(self) -> bool:
        """True when psi stays bounded over the whole grid."""
        return bool(np.all(self.stable))

    @property
    def max_growth_rate(self) -> float:
        """The largest growth rate (1/s): of the bands' exact maxima and of the grid points.

        A grid steps over narrow bands; the bands (issue 12) do not.  0 when stable.
        """
        grid = float(np.max(self.growth_rate)) if self.growth_rate.size else 0.0
        return max([grid, *(float(b.growth_rate_max) for b in self.bands)])

    def unstable_intervals(self) -> list[tuple[float, float]]:
        """The exact instability bands as (omega_lo, omega_hi) (rad/s), from :attr:`bands`."""
        return [(float(b.omega_lo), float(b.omega_hi)) for b in self.bands]

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready mapping: plain lists of floats/bools, no NaN or inf."""

        def fl(x: np.ndarray) -> list[float]:
            return [float(v) for v in np.nan_to_num(np.asarray(x, dtype=float))]

        return {
            "omega_psi": float(self.omega_psi),
            "gamma": float(self.gamma),
            "Omega": fl(self.Omega),
            "a": fl(self.a),
            "q": fl(self.q),
            "beta_real": fl(self.beta_real),
            "beta_imag": fl(self.beta_imag),
            "beta_memo_real": fl(self.beta_memo_real),
            "beta_memo_imag": fl(self.beta_memo_imag),
            "growth_rate": fl(self.growth_rate),
            "stable": [bool(v) for v in self.stable],
            "in_memo_range": [bool(v) for v in self.in_memo_range],
            "all_stable": self.all_stable,
            "max_growth_rate": self.max_growth_rate,
            "unstable_intervals": [list(iv) for iv in self.unstable_intervals()],
            "verdict": self.verdict,
            "bands": [b.to_dict() for b in self.bands],
            "damping_ratio": float(self.damping_ratio),
        }


def pitch_analysis(Omega: Any, omega_psi: float, gamma: float, *,
                   damping_ratio: float = 0.0) -> PitchResult:
    """Rigid-body pitch stability over a grid of thrust frequencies, with its exact bands.

    Parameters
    ----------
    Omega : array_like
        Thrust pulsation frequencies (rad/s), > 0, 1-D, increasing.
    omega_psi : float
        Rigid-body pitch frequency (rad/s), from :func:`pitch_frequency`.
    gamma : float
        Pulsation amplitude (dimensionless), 0 <= gamma < 1.
    damping_ratio : float
        Pitch damping ratio zeta (dimensionless), 0 <= zeta < 1:
        psi'' + 2 zeta omega_psi psi' + omega_psi^2 (1 - gamma cos Omega t) psi = 0.

    Returns
    -------
    PitchResult
        a, q (4.2-4), exact and memo beta, growth rates on the grid, the exact bands over
        [Omega[0], Omega[-1]] (:func:`pitch_bands`) and the verdict from the bands.  With
        damping the grid's beta is that of a' = a (1 - zeta^2) (psi = e^(-c tau_1) u,
        c = zeta sqrt(a)), stable where Im beta <= c and growth (Im beta - c) Omega / 2.

    References
    ----------
    Tech Memo 104, eqs. (4.2-3), (4.2-4), (4.2-5), (4.2-9); Bolotin (1964), sec. 6.
    """
    Omega = np.atleast_1d(np.asarray(Omega, dtype=float))
    if Omega.ndim != 1:
        raise ValueError(f"Omega: must be 1-D, got shape {Omega.shape}")
    if not (np.isfinite(damping_ratio) and 0.0 <= damping_ratio < 1.0):
        raise ValueError(f"damping_ratio = {damping_ratio!r}: must satisfy 0 <= zeta < 1")
    zeta = float(damping_ratio)
    a, q = mathieu_parameters(Omega, omega_psi, gamma)
    if zeta == 0.0:
        beta = characteristic_exponent(a, q, "floquet")
        stable = beta.imag == 0.0
        growth = np.where(stable, 0.0, beta.imag * Omega / 2.0)  # e^(mu tau_1), tau_1 = Omega t/2
    else:
        beta = characteristic_exponent(a * (1.0 - zeta**2), q, "floquet")  # u of psi e^(c tau_1)
        excess = beta.imag - zeta * np.sqrt(a)  # mu - c, c = 2 zeta omega_psi / Omega
        stable = excess <= 0.0
        growth = np.where(stable, 0.0, excess * Omega / 2.0)
    memo = np.zeros(a.shape, dtype=complex)
    ok = (a > 0) & (a != 1.0)
    if np.any(ok):
        memo[ok] = characteristic_exponent(a[ok], q[ok], "memo")
    in_range = (a > 0) & (a < 1) & (q > 0) & (q <= 0.05)  # eq. (4.2-5)
    lo_om, hi_om = float(Omega.min()), float(Omega.max())
    bands = ()
    if hi_om > lo_om:
        bands = pitch_bands(omega_psi, gamma, omega_min=lo_om, omega_max=hi_om,
                            damping_ratio=zeta)
    if not bands:
        verdict = (
            f"rigid-body pitch stable for all Omega in [{lo_om:.6g}, {hi_om:.6g}] rad/s "
            "(no Mathieu instability band in the range)"
        )
    else:
        top = max(bands, key=lambda b: b.growth_rate_max)
        spans = ", ".join(f"[{b.omega_lo:.6g}, {b.omega_hi:.6g}]" for b in bands[:4])
        more = f" and {len(bands) - 4} more" if len(bands) > 4 else ""
        verdict = (
            f"rigid-body pitch UNSTABLE in {len(bands)} band(s) {spans}{more} rad/s; max "
            f"growth rate {top.growth_rate_max:.6g} 1/s at Omega = {top.omega_at_max:.6g} "
            f"rad/s (tongue {top.tongue})"
        )
    if not np.all(in_range):
        verdict += f"; {int(np.sum(~in_range))} points outside the memo range (4.2-5)"
    return PitchResult(
        Omega=Omega,
        omega_psi=float(omega_psi),
        gamma=float(gamma),
        a=a,
        q=q,
        beta_real=beta.real.copy(),
        beta_imag=beta.imag.copy(),
        beta_memo_real=memo.real.copy(),
        beta_memo_imag=memo.imag.copy(),
        growth_rate=growth,
        stable=stable,
        in_memo_range=in_range,
        verdict=verdict,
        bands=bands,
        damping_ratio=zeta,
    )
