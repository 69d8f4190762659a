"""Appendix B and C-III of the memo: beam-mode values at the limits and coefficient integrals.

Verification-only (the pipeline's Galerkin coefficients are computed by quadrature in
:mod:`flexbooster.memo.shell_coefficients`): the closed forms of the integrals of appendix B,
the memo's printed forms, and a quadrature reference, tested against each other in
``tests/test_beam.py``.

References
----------
.. [1] Tech Memo 104, appendices B and C (eqs. B-1..B-12, C-6..C-10).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from flexbooster.checks import count
from flexbooster.memo.beam import (
    alpha_from_eigenvalues,
    free_free_eigenvalues,
    mode_shape,
    one_minus_alpha_scaled,
)

_METHODS = ("closed", "memo", "memo-corrected", "quadrature")
_PHASES = ("memo", "zero")

__all__ = [
    "LimitValues",
    "limit_values",
    "shell_phase",
    "CoefficientIntegrals",
    "coefficient_integrals",
]

# --------------------------------------------------------------------------------------------
# Values at the limits a, c, b (appendix C-III)
# --------------------------------------------------------------------------------------------


def _geometry(props: Any) -> tuple[float, float, float, float, float, float]:
    """(L, L1, L2, d1, d2, d3, d4) consistency-checked from a MassProperties-like object."""
    try:
        L, d1, d2, d3, d4 = (float(getattr(props, k)) for k in ("L", "d1", "d2", "d3", "d4"))
    except AttributeError as exc:
        raise ValueError(
            f"props = {props!r}: needs attributes L, d1, d2, d3, d4 "
            "(flexbooster.memo.geometry.MassProperties)"
        ) from exc
    if not (np.isfinite(L) and L > 0):
        raise ValueError(f"props.L = {L!r}: must be finite and > 0")
    if not all(np.isfinite(v) for v in (d1, d2, d3, d4)):
        raise ValueError("props.d1..d4: must be finite")
    L1 = 0.5 * (d1 + d2)  # reading guide 2: d1 + d2 = 2 L1
    L2 = L - L1
    if L1 <= 0:
        raise ValueError(f"props: L1 = (d1 + d2)/2 = {L1!r}: must be > 0")
    return L, L1, L2, d1, d2, d3, d4


@dataclass(frozen=True)
class LimitValues:
    """phi_n^(k) at the aft edge a, the junction c and the nose b (memo C-III).

    Attributes
    ----------
    derivative : int
        Order k of the derivative with respect to the argument X (memo prime convention).
    zeta_a, zeta_c, zeta_b : float
        Beam coordinates of a, c, b: (C-7) (L - (d2 + d4))/L = 0, (C-8) (L - (d4 - d1))/L =
        2 L1 / L, (C-9) (L - (d4 - d3))/L = 2 (dimensionless).
    at_a, at_c, at_b : numpy.ndarray
        Shape (N,), phi_n^(k) at the three points (dimensionless).
    """

    derivative: int
    zeta_a: float
    zeta_c: float
    zeta_b: float
    at_a: np.ndarray
    at_c: np.ndarray
    at_b: np.ndarray

    @property
    def cylinder1(self) -> np.ndarray:
        """phi_n^(k)|_a^c, eqs. (C-11)..(C-15)."""
        return self.at_c - self.at_a

    @property
    def cylinder2(self) -> np.ndarray:
        """phi_n^(k)|_c^b, eqs. (C-16)..(C-20)."""
        return self.at_b - self.at_c

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready mapping of the values (lists of floats)."""
        return {
            "derivative": self.derivative,
            "zeta_a": self.zeta_a,
            "zeta_c": self.zeta_c,
            "zeta_b": self.zeta_b,
            "at_a": [float(v) for v in self.at_a],
            "at_c": [float(v) for v in self.at_c],
            "at_b": [float(v) for v in self.at_b],
        }


def limit_values(props: Any, N: int, derivative: int = 0) -> LimitValues:
    """phi_n^(k) at xi_bar = a, c, b for n = 1..N (memo eqs. C-7..C-20).

    Parameters
    ----------
    props : flexbooster.memo.geometry.MassProperties
        Geometry: L (m) and the distances d1..d4 (m) of Fig. 1.
    N : int
        Number of modes (>= 1).
    derivative : int
        Order k >= 0 of the derivative with respect to X = lambda_n zeta / 2 (C-2..C-5).

    Returns
    -------
    LimitValues
        The values at a, c, b; ``.cylinder1`` and ``.cylinder2`` are the differences of
        (C-11..C-15) and (C-16..C-20).

    Notes
    -----
    The arguments are those of (C-7)..(C-9); they are 0, 2 L1 / L and 2 exactly, so the
    aft edge and the nose are the beam's free ends.

    References
    ----------
    Tech Memo 104, appendix C-II and C-III (errata C-13, C-20 in docs/memo-errata.md).
    """
    L, L1, _L2, d1, d2, d3, d4 = _geometry(props)
    N = count("N", N, low=1, high=None)
    derivative = count("derivative", derivative, low=0, high=None)
    zeta_a = (L - (d2 + d4)) / L  # eq. (C-7)
    zeta_c = (L - (d4 - d1)) / L  # eq. (C-8)
    zeta_b = (L - (d4 - d3)) / L  # eq. (C-9)
    n = np.arange(1, N + 1)
    vals = mode_shape(n[:, None], np.array([zeta_a, zeta_c, zeta_b])[None, :], derivative)
    return LimitValues(
        derivative=derivative,
        zeta_a=float(zeta_a),
        zeta_c=float(zeta_c),
        zeta_b=float(zeta_b),
        at_a=vals[:, 0],
        at_c=vals[:, 1],
        at_b=vals[:, 2],
    )


# --------------------------------------------------------------------------------------------
# Coefficient integrals (appendix B)
# --------------------------------------------------------------------------------------------


def shell_phase(
    props: Any, cylinder: int, phase: str = "memo"
) -> tuple[float, float, float, float]:
    """The shell-function phase theta_j(xi_bar) = j (p xi_bar + theta0) on one cylinder.

    Parameters
    ----------
    props : flexbooster.memo.geometry.MassProperties
        Geometry: L (m), d1..d4 (m).
    cylinder : {1, 2}
        Cylinder 1 (xi_bar in [a, c]) or cylinder 2 (xi_bar in [c, b]).
    phase : {"memo", "zero"}
        ``"memo"``: the printed argument of 5.3-2 ((L/L1) xi_bar - r1 + 1) or 5.3-3
        ((L/L2) xi_bar + r2 + 1) times pi/2 (erratum E10); ``"zero"``: 0 at the cylinder's aft
        edge.

    Returns
    -------
    p, theta0, start, end : float
        p = pi L / (2 L_d) and theta0 (dimensionless, per unit j), and the limits of
        integration in xi_bar.

    References
    ----------
    Tech Memo 104, eqs. (5.3-2b..e), (5.3-3b..e); reading guide erratum E10.
    """
    L, L1, L2, d1, d2, d3, _d4 = _geometry(props)
    if phase not in _PHASES:
        raise ValueError(f"phase = {phase!r}: must be one of {_PHASES}")
    a, c, b = -d2 / L, d1 / L, d3 / L
    if cylinder == 1:
        p = np.pi * L / (2.0 * L1)
        r1 = (L1 - d1) / L1  # eq. (5.3-2e)
        theta0 = np.pi / 2.0 * (1.0 - r1) if phase == "memo" else -p * a  # eq. (5.3-2b..d)
        return float(p), float(theta0), float(a), float(c)
    if cylinder == 2:
        if L2 <= 0:
            raise ValueError(f"cylinder = 2: L2 = {L2!r} must be > 0")
        p = np.pi * L / (2.0 * L2)
        r2 = (d1 - (L1 + L2)) / L2  # eq. (5.3-3e)
        theta0 = np.pi / 2.0 * (r2 + 1.0) if phase == "memo" else -p * c  # eq. (5.3-3b..d)
        return float(p), float(theta0), float(c), float(b)
    raise ValueError(f"cylinder = {cylinder!r}: must be 1 or 2")


@dataclass(frozen=True)
class CoefficientIntegrals:
    """Appendix-B coefficient integrals of one cylinder, arrays of shape (M, N).

    Attributes
    ----------
    cylinder : int
        1 (xi_bar in [a, c]) or 2 (xi_bar in [c, b]).
    method : str
        ``"closed"``, ``"memo"`` or ``"quadrature"``.
    phase : str
        ``"memo"`` or ``"zero"`` (see :func:`shell_phase`).
    r, s, t, x, y, z : numpy.ndarray
        Shape (M, N), row j - 1, column n - 1 (dimensionless); r does not depend on n and is
        broadcast.  Eqs. (B-1..B-6) for cylinder 1, (B-7..B-12) for cylinder 2.
    """

    cylinder: int
    method: str
    phase: str
    r: np.ndarray
    s: np.ndarray
    t: np.ndarray
    x: np.ndarray
    y: np.ndarray
    z: np.ndarray

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready mapping (nested lists of floats)."""
        out: dict[str, Any] = {
            "cylinder": self.cylinder,
            "method": self.method,
            "phase": self.phase,
        }
        for key in "rstxyz":
            out[key] = np.asarray(getattr(self, key), dtype=float).tolist()
        return out


def coefficient_integrals(
    props: Any,
    M: int,
    N: int,
    cylinder: int = 1,
    method: str = "closed",
    phase: str = "zero",
    n_points: int | None = None,
) -> CoefficientIntegrals:
    """The coefficient integrals r, s, t, x, y, z of appendix B for j = 1..M, n = 1..N.

    Parameters
    ----------
    props : flexbooster.memo.geometry.MassProperties
        Geometry: L (m) and d1..d4 (m) of Fig. 1.
    M : int
        Number of axial shell indices j = 1..M (>= 1).
    N : int
        Number of beam modes n = 1..N (>= 1).
    cylinder : {1, 2}
        Cylinder 1 (B-1..B-6, B-13..B-18) or cylinder 2 (B-7..B-12, B-19..B-24).
    method : {"closed", "memo", "quadrature"}
        ``"closed"``: the antiderivative evaluated at the limits (corrected closed form);
        ``"memo"``: the closed form as printed in B-13..B-17 / B-19..B-23 (its structure is
        wrong, see docs/memo-errata.md, rows B-13 and B-19); ``"quadrature"``:
        composite Gauss-Legendre quadrature of the defining integrals (B-1..B-12).
    phase : {"zero", "memo"}
        Phase of the shell functions, see :func:`shell_phase`.
    n_points : int, optional
        Quadrature only: total number of Gauss nodes; by default enough 16-point panels that
        each spans at most 1.5 rad of the fastest oscillation.

    Returns
    -------
    CoefficientIntegrals
        The six arrays, shape (M, N).

    Notes
    -----
    Primes are derivatives with respect to X = lambda_n (xi_bar - d4/L + 1)/2 (C-2..C-4), the
    memo's convention.  For the corrected closed form write
    phi^(m) = A e^X + (-1)^m B e^-X + Re[(1 + i alpha) e^(i(X + m pi/2))] and integrate each
    exponential against e^(i theta) exactly; the trigonometric products are integrated as
    Delta sinc(w Delta / 2) trig(v_mid), which stays exact when lambda_n/2 = j p (where the
    memo's 2/B^- is singular).

    References
    ----------
    Tech Memo 104, appendix B; reading guide errata E10, section 4.3.
    """
    M = count("M", M, low=1, high=None)
    N = count("N", N, low=1, high=None)
    if method not in _METHODS:
        raise ValueError(f"method = {method!r}: must be one of {_METHODS}")
    p, theta0, lo, hi = shell_phase(props, cylinder, phase)
    L, _L1, _L2, _d1, _d2, _d3, d4 = _geometry(props)
    xi0 = d4 / L - 1.0  # X = k (xi_bar - xi0), eq. (C-6)
    lam = free_free_eigenvalues(N)
    alpha = alpha_from_eigenvalues(lam)
    j = np.arange(1, M + 1, dtype=float)
    pj = (j * p)[:, None]  # d theta_j / d xi_bar
    th0 = (j * theta0)[:, None]
    k = (lam / 2.0)[None, :]  # d X / d xi_bar
    al = alpha[None, :]
    theta_lo, theta_hi = pj * lo + th0, pj * hi + th0
    # eq. (B-1) / (B-7): r_j = int sin(theta_j) d xi_bar, exact for every phase
    r = np.broadcast_to(_int_trig(np.sin, pj, th0, lo, hi), (M, N)).copy()
    if method == "quadrature":
        s, t, x, y, z = _quadrature(lam, alpha, pj, th0, xi0, lo, hi, n_points)
    elif method == "closed":
        x_lo, x_hi = k * (lo - xi0), k * (hi - xi0)
        g = one_minus_alpha_scaled(lam)[None, :]
        bb = 0.5 * (1.0 + al)

        def closed(m: int, weight: str) -> np.ndarray:
            return _closed_form(
                m, weight, k, al, g, bb, lam[None, :], pj, th0, lo, hi, xi0, x_lo, x_hi
            )

        s = closed(0, "sin")  # eq. (B-2) / (B-8)
        t = closed(1, "sin")  # eq. (B-3) / (B-9)
        x = closed(2, "sin")  # eq. (B-4) / (B-10) with L/L2
        y = closed(3, "sin")  # eq. (B-5) / (B-11)
        z = closed(1, "cos")  # eq. (B-6) / (B-12)
    else:
        s, t, x, y, z = _memo_closed_form(
            lam,
            alpha,
            j,
            p,
            theta_lo,
            theta_hi,
            lo - xi0,
            hi - xi0,
            cylinder,
            corrected=(method == "memo-corrected"),
        )
    return CoefficientIntegrals(
        cylinder=int(cylinder), method=method, phase=phase, r=r, s=s, t=t, x=x, y=y, z=z
    )


def _int_trig(fun: Any, w: np.ndarray, v0: np.ndarray, lo: float, hi: float) -> np.ndarray:
    """int_lo^hi fun(w xi + v0) d xi for fun in {sin, cos}, exact also for w -> 0."""
    delta = hi - lo
    mid = 0.5 * (lo + hi)
    # sin(w D/2)/(w D/2) via numpy's normalised sinc
    return delta * np.sinc(w * delta / (2.0 * np.pi)) * fun(w * mid + v0)


def _closed_form(
    m: int,
    weight: str,
    k: np.ndarray,
    al: np.ndarray,
    g: np.ndarray,
    bb: np.ndarray,
    lam: np.ndarray,
    pj: np.ndarray,
    th0: np.ndarray,
    lo: float,
    hi: float,
    xi0: float,
    x_lo: np.ndarray,
    x_hi: np.ndarray,
) -> np.ndarray:
    """int_lo^hi phi^(m)(X) w(theta) d xi_bar, w = sin or cos, exact antiderivative."""
    take = np.imag if weight == "sin" else np.real
    th_lo, th_hi = pj * lo + th0, pj * hi + th0
    # growing part A e^X = g e^(X - lambda): int e^(X-lambda+i theta) = e^(...)/(k + i p)
    grow = (np.exp(x_hi - lam + 1j * th_hi) - np.exp(x_lo - lam + 1j * th_lo)) / (k + 1j * pj)
    # decaying part (-1)^m B e^-X: int e^(-X + i theta) = e^(...)/(-k + i p)
    decay = (np.exp(-x_hi + 1j * th_hi) - np.exp(-x_lo + 1j * th_lo)) / (-k + 1j * pj)
    hyper = g * take(grow) + (-1.0) ** m * bb * take(decay)
    # trigonometric part cos(u) - alpha sin(u), u = X + m pi/2 = k xi + (m pi/2 - k xi0)
    u0 = m * np.pi / 2.0 - k * xi0
    sp_w, sp_0 = pj + k, th0 + u0  # theta + u
    sm_w, sm_0 = pj - k, th0 - u0  # theta - u
    if weight == "sin":
        # (cos u - alpha sin u) sin(th)
        #   = [sin(th+u) + sin(th-u)]/2 - alpha [cos(th-u) - cos(th+u)]/2
        trig = 0.5 * (_int_trig(np.sin, sp_w, sp_0, lo, hi) + _int_trig(np.sin, sm_w, sm_0, lo, hi))
        trig -= (
            0.5
            * al
            * (_int_trig(np.cos, sm_w, sm_0, lo, hi) - _int_trig(np.cos, sp_w, sp_0, lo, hi))
        )
    else:
        # (cos u - alpha sin u) cos(th)
        #   = [cos(th+u) + cos(th-u)]/2 - alpha [sin(th+u) - sin(th-u)]/2
        trig = 0.5 * (_int_trig(np.cos, sp_w, sp_0, lo, hi) + _int_trig(np.cos, sm_w, sm_0, lo, hi))
        trig -= (
            0.5
            * al
            * (_int_trig(np.sin, sp_w, sp_0, lo, hi) - _int_trig(np.sin, sm_w, sm_0, lo, hi))
        )
    return hyper + trig


def _quadrature(
    lam: np.ndarray,
    alpha: np.ndarray,
    pj: np.ndarray,
    th0: np.ndarray,
    xi0: float,
    lo: float,
    hi: float,
    n_points: int | None,
) -> tuple[np.ndarray, ...]:
    """Composite Gauss-Legendre quadrature of (B-2..B-6); returns s, t, x, y, z (M, N)."""
    order = 16
    if n_points is None:
        phase_span = (float(np.max(pj)) + float(lam[-1]) / 2.0) * (hi - lo)
        panels = max(1, int(np.ceil(phase_span / 1.5)))
    else:
        panels = max(1, int(n_points) // order)
    nodes, weights = np.polynomial.legendre.leggauss(order)
    edges = np.linspace(lo, hi, panels + 1)
    half = 0.5 * np.diff(edges)[:, None]
    xi = (0.5 * (edges[:-1] + edges[1:])[:, None] + half * nodes[None, :]).ravel()
    w = (half * weights[None, :]).ravel()
    zeta = xi - xi0  # zeta = xi_bar - d4/L + 1, eq. (C-6)
    n = np.arange(1, lam.size + 1)[:, None]
    theta = pj * xi[None, :] + th0  # (M, Q)
    ws, wc = np.sin(theta) * w, np.cos(theta) * w
    phi = {m: mode_shape(n, zeta[None, :], m) for m in range(4)}  # (N, Q)
    return (
        ws @ phi[0].T,  # eq. (B-2)
        ws @ phi[1].T,  # eq. (B-3)
        ws @ phi[2].T,  # eq. (B-4)
        ws @ phi[3].T,  # eq. (B-5)
        wc @ phi[1].T,  # eq. (B-6)
    )


def _memo_closed_form(
    lam: np.ndarray,
    alpha: np.ndarray,
    j: np.ndarray,
    p: float,
    theta_lo: np.ndarray,
    theta_hi: np.ndarray,
    zeta_lo: float,
    zeta_hi: float,
    cylinder: int,
    corrected: bool,
) -> tuple[np.ndarray, ...]:
    """The closed forms of (B-13..B-18), cylinder 1, and (B-19..B-24), cylinder 2.

    Every bracket is a combination P(X) of cosh, sinh, cos, sin of (Arg) = X at one limit,
    multiplied by cos(theta) or sin(theta) at the limits.  As printed (``corrected=False``)
    each term is a product of two differences, {w(theta)}|_lo^hi [P(X)]|_lo^hi (cylinder 2
    prints the theta differences as value at c minus value at b); the antiderivative needs
    the difference of the products, [w(theta) P(X)]|_lo^hi (``corrected=True``).  The
    hyperbolic combinations cosh X - alpha sinh X = A e^X + B e^-X and
    sinh X - alpha cosh X = A e^X - B e^-X are evaluated in scaled form (the same numbers,
    without overflow or cancellation).
    """
    kk = (j * 2.0 * p)[:, None]  # j pi L / L_d  (B-18, B-24)
    lam_ = lam[None, :]
    al = alpha[None, :]
    g = one_minus_alpha_scaled(lam)[None, :]
    bb = 0.5 * (1.0 + al)
    a_minus = lam_**2 - kk**2  # eq. (B-18a) / (B-24a)
    a_plus = lam_**2 + kk**2  # eq. (B-18b) / (B-24b)
    b_minus = kk**4 - lam_**4  # eq. (B-18c) / (B-24c)

    def combos(zeta: float) -> dict[str, np.ndarray]:
        arg = lam_ / 2.0 * zeta  # eq. (B-18d, e) / (B-24d, e): (Arg) = (lambda_n/2)(...)
        grow, decay = g * np.exp(arg - lam_), bb * np.exp(-arg)
        co, si = np.cos(arg), np.sin(arg)
        return {
            "h": grow + decay,  # cosh - alpha sinh
            "hp": grow - decay,  # sinh - alpha cosh
            "c": co - al * si,  # cos - alpha sin
            "cp": -si - al * co,  # -sin - alpha cos
        }

    lo, hi = combos(zeta_lo), combos(zeta_hi)
    sign = 1.0 if cylinder == 1 else -1.0  # printed order of the theta differences

    def term(weight_k: Any, h1: Any, t1: Any, weight_l: Any, h2: Any, t2: Any) -> np.ndarray:
        def bracket(cmb: dict[str, np.ndarray], h: Any, t: Any) -> np.ndarray:
            return a_minus * h(cmb) + a_plus * t(cmb)

        if corrected:
            val = kk * (
                weight_k(theta_hi) * bracket(hi, h1, t1) - weight_k(theta_lo) * bracket(lo, h1, t1)
            ) + lam_ * (
                weight_l(theta_hi) * bracket(hi, h2, t2) - weight_l(theta_lo) * bracket(lo, h2, t2)
            )
        else:
            dk = sign * (weight_k(theta_hi) - weight_k(theta_lo))
            dl = sign * (weight_l(theta_hi) - weight_l(theta_lo))
            val = kk * dk * (bracket(hi, h1, t1) - bracket(lo, h1, t1)) + lam_ * dl * (
                bracket(hi, h2, t2) - bracket(lo, h2, t2)
            )
        with np.errstate(divide="ignore", invalid="ignore"):
            out = 2.0 / b_minus * val  # the factor 2 / (B^-_jn)_d of (B-13..B-17)
        return np.where(np.isfinite(out), out, 0.0)

    def h(c: dict[str, np.ndarray]) -> np.ndarray:
        return c["h"]

    def hp(c: dict[str, np.ndarray]) -> np.ndarray:
        return c["hp"]

    def mh(c: dict[str, np.ndarray]) -> np.ndarray:
        return -c["h"]

    def mhp(c: dict[str, np.ndarray]) -> np.ndarray:
        return -c["hp"]

    def tc(c: dict[str, np.ndarray]) -> np.ndarray:
        return c["c"]

    def tcp(c: dict[str, np.ndarray]) -> np.ndarray:
        return c["cp"]

    def mtc(c: dict[str, np.ndarray]) -> np.ndarray:
        return -c["c"]

    def mtcp(c: dict[str, np.ndarray]) -> np.ndarray:
        return -c["cp"]

    s = term(np.cos, h, mtc, np.sin, mhp, tcp)  # eq. (B-13) / (B-19)
    t = term(np.cos, hp, mtcp, np.sin, mh, mtc)  # eq. (B-14) / (B-20)
    x = term(np.cos, h, tc, np.sin, mhp, mtcp)  # eq. (B-15) / (B-21)
    y = term(np.cos, hp, tcp, np.sin, mh, tc)  # eq. (B-16) / (B-22)
    z = term(np.sin, mhp, tcp, np.cos, mh, mtc)  # eq. (B-17) / (B-23)
    return s, t, x, y, z
