"""Unstable thrust frequencies: the 13 families of stability equations (memo section 7).

Each family equates an excitation frequency |c(Omega)| Omega_bar of the shell forcing to a
shell natural frequency (7.1), c linear in beta and alpha_r (7.2-6, table :data:`FAMILIES`):
an implicit equation in Omega. All roots in the range are bracketed on one scan grid for
every curve and frequency at once, refined together by Illinois, and coincident curves are
reported once. A root is "active" where its forcing is structurally non-zero, else "listed".
Theory: docs/theory/stability.md.

References: Tech Memo 104, sec. 6.2 and 7 (7.2-1..7.2-6, 7.3-1..7.3-35), errata E7, E8;
V. V. Bolotin, *The Dynamic Stability of Elastic Systems*, 1964, ch. 1.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..checks import count, positive

__all__ = [
    "EPS",
    "SCAN_POINTS",
    "FAMILIES",
    "ExcitationCurves",
    "ShellModes",
    "StabilityTable",
    "excitation_curves",
    "excitation",
    "unstable_frequencies",
    "TooManyRootsError",
    "MAX_CURVE_INDEX",
]

#: Largest R and S of :func:`excitation_curves` (the case's truncation limit, 500).
MAX_CURVE_INDEX = 500

#: eps_i of eq. (7.2-5), i = 1, 2, 3.
EPS = (-0.5, 0.5, 0.5)

#: The 13 families: number -> (equation, shell-frequency set, source of the forcing, kind).
#: kind: "Omega_i" c = (i-2)^2 + eps_i beta; "alpha" c = alpha_r + s; "Omega" c = 1;
#: "2Omega_i" c = 2 [(i-2)^2 + eps_i beta]; "sum"/"difference" c = Omega_i +- Omega_p terms;
#: "Omega+Omega_i"/"Omega-Omega_i" c = (i-2)^2 + eps_i beta +- 1.
FAMILIES: dict[int, tuple[str, str, str, str]] = {
    1: ("7.3-1", "0k", "U_0k", "Omega_i"),
    2: ("7.3-3", "0k", "U_0k", "alpha"),
    3: ("7.3-5", "j0", "U_j0, W_j0", "Omega"),
    4: ("7.3-8 (E7)", "j0", "U_j0, W_j0", "2Omega_i"),
    5: ("7.3-11", "j0", "U_j0, W_j0", "sum"),
    6: ("7.3-14", "j0", "U_j0, W_j0", "difference"),
    7: ("7.3-17", "jk", "J_1, J_2, J_3", "Omega_i"),
    8: ("7.3-20", "jk", "J_1, J_2, J_3", "Omega+Omega_i"),
    9: ("7.3-23", "jk", "J_1, J_2, J_3", "Omega-Omega_i"),
    10: ("7.3-26 (E8)", "jk", "J_1, J_2, J_3", "sum"),
    11: ("7.3-29 (E8)", "jk", "J_1, J_2, J_3", "difference"),
    12: ("7.3-32 (E7)", "jk", "J_1, J_2, J_3", "2Omega_i"),
    13: ("7.3-35", "jk", "J_1, J_2, J_3", "alpha"),
}


@dataclass(frozen=True)
class ExcitationCurves:
    """Excitation curves |k0 + kb beta + ka alpha_r| Omega_bar of all families (parallel arrays).

    Attributes
    ----------
    family : numpy.ndarray of int
        Family number 1..13 (memo 7.4).
    i, p : numpy.ndarray of int
        Indices of Omega_i, Omega_p (0 where unused).
    r, s : numpy.ndarray of int
        Beam exponent r (1..R, 0 where unused) and harmonic s.
    k0, kb, ka : numpy.ndarray of float
        Constant, beta and alpha_r coefficients of c.
    """

    family: np.ndarray
    i: np.ndarray
    p: np.ndarray
    r: np.ndarray
    s: np.ndarray
    k0: np.ndarray
    kb: np.ndarray
    ka: np.ndarray

    def __len__(self) -> int:
        return int(self.family.size)


def excitation_curves(R: int, S: int) -> ExcitationCurves:
    """All excitation curves of the 13 families, each counted once (only i < p of the symmetric
    pairs).

    Coefficients (memo 7.3, errata E7, E8): Omega_i (7.3-1, 7.3-17) (i-2)^2 + eps_i beta;
    2 Omega_i (7.3-8, 7.3-32) twice that; Omega_i +- Omega_p (7.3-11, 7.3-26, 7.3-14, 7.3-29)
    (i-2)^2 +- (p-2)^2 + (eps_i +- eps_p) beta; Omega_bar +- Omega_i (7.3-20, 7.3-23)
    (i-2)^2 + eps_i beta +- 1; Omega_bar (7.3-5) 1; (alpha_r + s) Omega_bar (7.3-3, 7.3-35).

    Parameters
    ----------
    R : int
        Number of beam exponents alpha_r (r = 1..R), 0..MAX_CURVE_INDEX (the case's limit).
    S : int
        Harmonics s = -S..S, 0..MAX_CURVE_INDEX.
    """
    R = count("R", R, 0, MAX_CURVE_INDEX)  # bounded work: 13 + R (2 S + 1) curves at most
    S = count("S", S, 0, MAX_CURVE_INDEX)
    rows: list[tuple[int, int, int, int, int, float, float, float]] = []
    idx = (1, 2, 3)
    for fam, (_, _, _, kind) in FAMILIES.items():
        if kind == "Omega_i":
            rows += [(fam, i, 0, 0, 0, (i - 2) ** 2, EPS[i - 1], 0.0) for i in idx]  # (7.2-6)
        elif kind == "2Omega_i":
            rows += [(fam, i, 0, 0, 0, 2 * (i - 2) ** 2, 2 * EPS[i - 1], 0.0) for i in idx]  # E7
        elif kind in ("sum", "difference"):
            sign = 1 if kind == "sum" else -1
            rows += [
                (
                    fam,
                    i,
                    p,
                    0,
                    0,
                    (i - 2) ** 2 + sign * (p - 2) ** 2,
                    EPS[i - 1] + sign * EPS[p - 1],
                    0.0,
                )
                for i in idx
                for p in idx
                if i < p
            ]  # (7.3-11, -14, -26, -29) with E8
        elif kind in ("Omega+Omega_i", "Omega-Omega_i"):
            sign = 1 if kind == "Omega+Omega_i" else -1
            rows += [
                (fam, i, 0, 0, 0, (i - 2) ** 2 + sign, EPS[i - 1], 0.0) for i in idx
            ]  # (7.3-20, -23)
        elif kind == "Omega":
            rows.append((fam, 0, 0, 0, 0, 1.0, 0.0, 0.0))  # (7.3-5)
        elif kind == "alpha":
            rows += [
                (fam, 0, 0, r, s, float(s), 0.0, 1.0)
                for r in range(1, R + 1)
                for s in range(-S, S + 1)
            ]
    cols = list(zip(*rows, strict=True))
    ints = [np.array(c, dtype=int) for c in cols[:5]]
    floats = [np.array(c, dtype=float) for c in cols[5:]]
    return ExcitationCurves(*ints, *floats)


def excitation(
    curves: ExcitationCurves, Omega_bar: np.ndarray, beta: np.ndarray, alpha: np.ndarray
) -> np.ndarray:
    """Excitation frequencies of every curve on a grid, shape (C, n), units of omega_1 (7.2-6).

    Parameters
    ----------
    curves : ExcitationCurves
        Curves to evaluate (length C).
    Omega_bar : numpy.ndarray
        Thrust frequencies Omega / omega_1, shape (n,).
    beta : numpy.ndarray
        Pitch stability parameter beta(Omega) (real part), shape (n,).
    alpha : numpy.ndarray
        Beam exponents alpha_r(Omega), shape (n, R) (R may be 0).
    """
    Omega_bar = np.asarray(Omega_bar, dtype=float)
    beta = np.asarray(beta, dtype=float)
    alpha = np.asarray(alpha, dtype=float)
    r_max = int(np.max(curves.r, initial=0))
    if alpha.ndim != 2 or alpha.shape[0] != Omega_bar.size or alpha.shape[1] < r_max:
        raise ValueError(f"alpha: shape {alpha.shape} must be (n, R) with n = "
                         f"{Omega_bar.size} (Omega_bar's size) and R >= {r_max} (the curves' r)")
    for name, value in (("Omega_bar", Omega_bar), ("beta", beta), ("alpha", alpha)):
        if not np.all(np.isfinite(value)):
            raise ValueError(f"{name}: must be finite (got {value.ravel()[:4]!r} ...)")
    if beta.shape != Omega_bar.shape:
        raise ValueError(f"beta: shape {beta.shape} must equal Omega_bar's {Omega_bar.shape}")
    a_r = alpha.T[np.maximum(curves.r - 1, 0)] if alpha.shape[1] else 0.0  # (C, n)
    c = curves.k0[:, None] + curves.kb[:, None] * beta[None, :] + curves.ka[:, None] * a_r
    return np.abs(c) * Omega_bar[None, :]  # (7.2-6), (7.3-*)


def _excitation_pointwise(
    curves: ExcitationCurves, Omega_bar: np.ndarray, beta: np.ndarray, alpha: np.ndarray
) -> np.ndarray:
    """The excitation of curve n at Omega_bar[n] (all arrays of length C)."""
    alpha = np.asarray(alpha, dtype=float).reshape(Omega_bar.size, -1)
    a_r = alpha[np.arange(Omega_bar.size), np.maximum(curves.r - 1, 0)] if alpha.shape[1] else 0.0
    return np.abs(curves.k0 + curves.kb * beta + curves.ka * a_r) * Omega_bar


@dataclass(frozen=True)
class ShellModes:
    """Shell natural frequencies the excitations are compared with (parallel arrays).

    Attributes
    ----------
    cylinder, j, k, branch : numpy.ndarray of int
        Cylinder d, axial index j, circumferential index k, branch m of each frequency.
    omega_bar : numpy.ndarray of float
        Natural frequency in units of omega_1.
    """

    cylinder: np.ndarray
    j: np.ndarray
    k: np.ndarray
    branch: np.ndarray
    omega_bar: np.ndarray

    def subset(self, kind: str) -> np.ndarray:
        """Indices of the frequencies of one set: "0k" (j = 0, k >= 1), "j0", "jk"."""
        j, k = self.j, self.k
        mask = {"0k": (j == 0) & (k >= 1), "j0": (j >= 1) & (k == 0), "jk": (j >= 1) & (k >= 1)}[
            kind
        ]
        return np.flatnonzero(mask)


@dataclass(frozen=True)
class StabilityTable:
    """The unstable thrust frequencies (one row per root, parallel arrays).

    Attributes
    ----------
    Omega, Omega_bar : numpy.ndarray
        Thrust pulsation frequency at the root (rad/s) and Omega / omega_1.
    family, i, p, r, s : numpy.ndarray of int
        The (first) family and its indices (0 where unused).
    equation, also : tuple of str
        Memo equation of the family; other families whose curves coincide here ("" if none).
    cylinder, j, k, branch : numpy.ndarray of int
        The shell mode.
    shell_omega_bar : numpy.ndarray
        Its natural frequency in units of omega_1.
    active : numpy.ndarray of bool
        Forcing structurally non-zero as solved; ``severity_rel >= threshold`` once the
        severity is attached.
    residual : numpy.ndarray
        |excitation - shell frequency| at the root (units of omega_1).
    omega_1 : float
        The unit of the dimensionless frequencies (rad/s).
    severity, severity_rel : numpy.ndarray or None
        Secular growth rate of the mode at the root (m/s) and over the table's largest; None
        if not computed.
    """

    Omega: np.ndarray
    Omega_bar: np.ndarray
    family: np.ndarray
    i: np.ndarray
    p: np.ndarray
    r: np.ndarray
    s: np.ndarray
    equation: tuple[str, ...]
    also: tuple[str, ...]
    cylinder: np.ndarray
    j: np.ndarray
    k: np.ndarray
    branch: np.ndarray
    shell_omega_bar: np.ndarray
    active: np.ndarray
    residual: np.ndarray
    omega_1: float
    severity: np.ndarray | None = None
    severity_rel: np.ndarray | None = None

    def __len__(self) -> int:
        return int(self.Omega.size)

    def to_columns(self) -> dict[str, list]:
        """The table by columns (what the CSV and results.json hold), sorted by Omega."""
        two_pi = 2.0 * np.pi
        return {
            "Omega_rad_s": self.Omega.tolist(),
            "Omega_hz": (self.Omega / two_pi).tolist(),
            "Omega_over_omega1": self.Omega_bar.tolist(),
            "family": self.family.tolist(),
            "equation": list(self.equation),
            "also": list(self.also),
            "cylinder": self.cylinder.tolist(),
            "j": self.j.tolist(),
            "k": self.k.tolist(),
            "branch": self.branch.tolist(),
            "i": self.i.tolist(),
            "p": self.p.tolist(),
            "r": self.r.tolist(),
            "s": self.s.tolist(),
            "shell_omega_bar": self.shell_omega_bar.tolist(),
            "shell_rad_s": (self.shell_omega_bar * self.omega_1).tolist(),
            "shell_hz": (self.shell_omega_bar * self.omega_1 / two_pi).tolist(),
            "forcing": np.where(self.active, "active", "listed").tolist(),
            **({} if self.severity is None else {
                "severity": self.severity.tolist(),
                "severity_rel": self.severity_rel.tolist()}),
        }

    def to_rows(self) -> list[dict]:
        """One mapping per root (the rows of :meth:`to_columns`), sorted by Omega."""
        cols = self.to_columns()
        return [dict(zip(cols, values, strict=True)) for values in zip(*cols.values(), strict=True)]

    def to_dict(self) -> dict:
        """JSON-ready and compact: one list per column (:meth:`to_columns`)."""
        return {
            "count": len(self),
            "active": int(self.active.sum()),
            "columns": list(_COLUMNS) + ([] if self.severity is None else list(_SEVERITY)),
            "table": self.to_columns(),
            "warnings": [],  # kept for the results.json schema 1.0; warnings are in results
        }


_COLUMNS = (
    "Omega_rad_s",
    "Omega_hz",
    "Omega_over_omega1",
    "family",
    "equation",
    "also",
    "cylinder",
    "j",
    "k",
    "branch",
    "i",
    "p",
    "r",
    "s",
    "shell_omega_bar",
    "shell_rad_s",
    "shell_hz",
    "forcing",
)
_SEVERITY = ("severity", "severity_rel")  # when the severity is attached


ParamsFn = Callable[[np.ndarray], tuple[np.ndarray, np.ndarray]]


def _active(
    fam: np.ndarray,
    i: np.ndarray,
    p: np.ndarray,
    j: np.ndarray,
    k: np.ndarray,
    gamma: float,
    K: float,
) -> np.ndarray:
    """Structurally non-zero forcing (memo 6.2): the Kronecker deltas select k, and the zero-phase
    axial projections select odd j for the psi-dot^2 (families 4-6, 10-12) and T0 gamma
    sin(K psi) (8, 9) terms.
    """
    pulsed = gamma != 0.0
    odd_j = (j % 2) == 1
    # A_1, A_3 of psi are proportional to q = gamma a / 2 (4.2-7b, d): zero without pulsation
    amp_ok = ((i == 0) | (i == 2) | pulsed) & ((p == 0) | (p == 2) | pulsed)
    out = np.zeros(fam.shape, dtype=bool)
    out |= np.isin(fam, (1, 2, 7, 13)) & (k == 1)  # delta_1k: psi'' and beam (g*) terms
    out |= (fam == 3) & pulsed  # T0 gamma cos(Omega tau), k = 0 (6.2-11, -12)
    out |= np.isin(fam, (4, 5, 6)) & (k == 0) & odd_j  # psi-dot^2, k = 0 (6.2-11, -12)
    out |= np.isin(fam, (8, 9)) & (k == 1) & pulsed & (K != 0.0) & odd_j  # (6.2-26)
    out |= np.isin(fam, (10, 11, 12)) & (k == 2) & odd_j  # delta_2k psi-dot^2 (6.2-26)
    return out & amp_ok


class TooManyRootsError(RuntimeError):
    """The stability table would hold more roots than ``max_roots`` (a memory limit)."""


#: The equation of each family (index: family number), for the table's column.
_EQUATIONS = np.array([""] + [FAMILIES[f][0] for f in range(1, max(FAMILIES) + 1)], dtype=object)


#: Points of the geometric scan grid that brackets the stability table's roots.
SCAN_POINTS = 2001


def unstable_frequencies(
    modes: ShellModes,
    params: ParamsFn,
    *,
    Omega_bar_range: tuple[float, float],
    omega_1: float,
    R: int,
    S: int,
    gamma: float,
    K: float,
    n_scan: int = SCAN_POINTS,
    tol: float = 1e-12,
    max_roots: int = 4_000_000,
) -> StabilityTable:
    """All roots of the 13 families in an Omega range, each once, sorted by Omega (memo 7.3).

    Two crossings closer than the scan spacing (a near-tangency) may be missed, and a curve that
    only touches a frequency is not a crossing.

    Parameters
    ----------
    modes : ShellModes
        Shell natural frequencies (units of omega_1) with their (d, j, k, m).
    params : callable
        ``params(Omega_bar) -> (beta, alpha)``, real beta (n,) and alpha_r (n, R), vectorised.
    Omega_bar_range : (float, float)
        Range of Omega / omega_1.
    omega_1 : float
        Reference frequency, eq. (4.2-8b) (rad/s).
    R, S : int
        Beam exponents r = 1..R and harmonics s = -S..S (families 2 and 13).
    gamma, K : float
        Thrust pulsation amplitude and gimbal gain (decide which forcing is active).
    n_scan : int
        Points of the geometric scan grid that brackets the roots.
    tol : float
        Residual to which each root is refined (units of omega_1).
    max_roots : int
        Largest number of roots (about 0.5 kB each); more raise :class:`TooManyRootsError`.
    """
    omega_1 = positive("omega_1", omega_1)
    lo_W, hi_W = (float(x) for x in Omega_bar_range)
    if not 0.0 < lo_W < hi_W:
        raise ValueError(f"Omega_bar_range = {Omega_bar_range!r}: need 0 < min < max")
    curves = excitation_curves(R, S)
    grid = np.geomspace(lo_W, hi_W, int(n_scan))
    beta_g, alpha_g = params(grid)
    E = excitation(curves, grid, beta_g, alpha_g)  # (C, n): one pass over the scan grid
    E0, E1 = E[:, :-1], E[:, 1:]
    lo, hi = np.minimum(E0, E1), np.maximum(E0, E1)

    found_c, found_t, found_a, found_b = [], [], [], []
    for kind in ("0k", "j0", "jk"):
        targets = modes.subset(kind)
        cmask = np.isin(curves.family, [f for f, v in FAMILIES.items() if v[1] == kind])
        if targets.size == 0 or not cmask.any():
            continue
        order = np.argsort(modes.omega_bar[targets], kind="stable")
        tsorted = modes.omega_bar[targets][order]
        cidx = np.flatnonzero(cmask)
        first = np.searchsorted(tsorted, lo[cidx], side="left")  # targets in [lo, hi)
        last = np.searchsorted(tsorted, hi[cidx], side="left")
        count = (last - first).ravel()
        if count.sum() == 0:
            continue
        pair = np.repeat(np.arange(count.size), count)  # (curve, interval) of each bracket
        offset = np.arange(count.sum()) - np.repeat(np.cumsum(count) - count, count)
        c_loc, interval = np.divmod(pair, E0.shape[1])
        found_c.append(cidx[c_loc])
        found_t.append(targets[order[first.ravel()[pair] + offset]])
        found_a.append(grid[interval])
        found_b.append(grid[interval + 1])
    if not found_c:
        return _empty(omega_1)
    total = sum(x.size for x in found_c)
    if total > max_roots:
        raise TooManyRootsError(
            f"stability table: {total} roots in the Omega range exceed max_roots = {max_roots}; "
            "reduce the shell modes (M1, N1, M2, N2), R or S, or the Omega range"
        )
    c = np.concatenate(found_c)
    t = np.concatenate(found_t)
    a = np.concatenate(found_a)
    b = np.concatenate(found_b)
    sub = ExcitationCurves(
        *(getattr(curves, f)[c] for f in ("family", "i", "p", "r", "s", "k0", "kb", "ka"))
    )
    target = modes.omega_bar[t]

    def f(x: np.ndarray) -> np.ndarray:
        # params once per distinct Omega_bar (the brackets share their ends: ~2,000 distinct
        # of ~40,000 at the start), the same values as on the whole array (its set of values,
        # on which Hill's truncation depends, is the same)
        xu, where = np.unique(x, return_inverse=True)
        beta, alpha = params(xu)
        return _excitation_pointwise(sub, x, beta[where], np.asarray(alpha)[where]) - target

    root, resid = _illinois(f, a, b, tol)

    fam = sub.family
    active = _active(fam, sub.i, sub.p, modes.j[t], modes.k[t], gamma, K)
    keep, also = _merge_coincident(root, t, fam, sub.i, sub.p, sub.r, sub.s, tol)
    order = np.argsort(root[keep], kind="stable")
    keep = keep[order]
    also = np.asarray(also, dtype=object)[order].tolist()
    return StabilityTable(
        Omega=root[keep] * omega_1,
        Omega_bar=root[keep],
        family=fam[keep],
        i=sub.i[keep],
        p=sub.p[keep],
        r=sub.r[keep],
        s=sub.s[keep],
        equation=tuple(_EQUATIONS[fam[keep]].tolist()),
        also=tuple(also),
        cylinder=modes.cylinder[t][keep],
        j=modes.j[t][keep],
        k=modes.k[t][keep],
        branch=modes.branch[t][keep],
        shell_omega_bar=target[keep],
        active=active[keep],
        residual=resid[keep],
        omega_1=float(omega_1),
    )


def _empty(omega_1: float) -> StabilityTable:
    zi, zf = np.zeros(0, dtype=int), np.zeros(0)
    return StabilityTable(
        zf, zf, zi, zi, zi, zi, zi, (), (), zi, zi, zi, zi, zf, np.zeros(0, bool), zf, omega_1
    )


def _illinois(
    f: Callable[[np.ndarray], np.ndarray],
    a: np.ndarray,
    b: np.ndarray,
    tol: float,
    max_iter: int = 100,
) -> tuple[np.ndarray, np.ndarray]:
    """Vectorised Illinois (modified regula falsi) on brackets [a, b] with f(a) f(b) <= 0."""
    a, b = a.copy(), b.copy()
    fa, fb = f(a), f(b)
    x, fx = np.where(np.abs(fa) <= np.abs(fb), a, b), np.minimum(np.abs(fa), np.abs(fb))
    side = np.zeros(a.shape, dtype=int)
    for _ in range(max_iter):
        todo = (np.abs(fx) > tol) & (b - a > 4 * np.finfo(float).eps * np.abs(b))
        if not todo.any():
            break
        denom = fb - fa
        xn = np.where(
            denom != 0.0, (a * fb - b * fa) / np.where(denom != 0.0, denom, 1.0), 0.5 * (a + b)
        )
        xn = np.where((xn > np.minimum(a, b)) & (xn < np.maximum(a, b)), xn, 0.5 * (a + b))
        fn = np.where(todo, f(np.where(todo, xn, a)), 0.0)
        left = todo & (np.sign(fn) == np.sign(fa))  # root in [xn, b]
        right = todo & ~left
        a = np.where(left, xn, a)
        fa = np.where(left, fn, fa)
        fb = np.where(left & (side == 1), fb / 2, fb)  # Illinois: halve the stale end
        b = np.where(right, xn, b)
        fb = np.where(right, fn, fb)
        fa = np.where(right & (side == -1), fa / 2, fa)
        side = np.where(left, 1, np.where(right, -1, side))
        x = np.where(todo, xn, x)
        fx = np.where(todo, fn, fx)
    return x, np.abs(f(x))


def _merge_coincident(root, t, fam, i, p, r, s, tol):
    """One row per (shell mode, root), listing the other families that give it: rows sorted by
    (mode, root, family) join the previous kept row within 1e3 tol max(|root|, 1).
    """
    order = np.lexsort((fam, root, t))
    ro, to = root[order], t[order]
    thr = 1e3 * tol * np.maximum(np.abs(ro), 1.0)
    start = np.ones(order.size, dtype=bool)
    start[1:] = (to[1:] != to[:-1]) | (ro[1:] - ro[:-1] > thr[1:])
    group = np.cumsum(start) - 1
    first = np.flatnonzero(start)
    # a chain of small steps may drift past the tolerance of its first row: split it there
    drift = ~start & (ro - ro[first[group]] > thr)
    if drift.any():  # rare: fall back to the sequential rule for exactness
        return _merge_sequential(order, root, t, fam, i, p, r, s, tol)
    also = [""] * first.size
    for n in np.flatnonzero(~start):
        m = order[n]
        label = f"{fam[m]}" + "".join(
            f"({k}={v})" for k, v in (("i", i[m]), ("p", p[m]), ("r", r[m]), ("s", s[m])) if v
        )
        g = group[n]
        also[g] = f"{also[g]}, {label}" if also[g] else label
    return order[first].astype(int), also


def _merge_sequential(order, root, t, fam, i, p, r, s, tol):
    """The sequential form of :func:`_merge_coincident` (used when a chain drifts)."""
    keep, also = [], []
    scale = np.maximum(np.abs(root), 1.0)
    for n in order:
        if keep and t[keep[-1]] == t[n] and abs(root[n] - root[keep[-1]]) <= 1e3 * tol * scale[n]:
            label = f"{fam[n]}" + "".join(
                f"({k}={v})" for k, v in (("i", i[n]), ("p", p[n]), ("r", r[n]), ("s", s[n])) if v
            )
            also[-1] = f"{also[-1]}, {label}" if also[-1] else label
            continue
        keep.append(n)
        also.append("")
    return np.array(keep, dtype=int), also
