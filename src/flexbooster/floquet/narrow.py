"""Narrow instability regions of q'' + (A + B cos Omega t) q = 0, resolved linearly in width.

Round-off hides regions narrower than ~sqrt(eps) of their centre from the monodromy. Here
the two colliding exponents are isolated from Hill's equations in the modal frame (the rest
eliminated exactly: Schur complement, Loewdin partitioning) and D(Omega) = (lambda_1 -
lambda_2)^2 is > 0 inside, 0 on the edges (docs/theory/floquet.md sec. 4).

References: V. V. Bolotin, 1964, sec. 7-8; W. Magnus, S. Winkler, 1966, ch. 2;
P.-O. Loewdin, J. Mol. Spectrosc. 10 (1963) 12-33; C. S. Hsu, J. Appl. Mech. 30 (1963).
"""

from __future__ import annotations

import numpy as np

__all__: list[str] = []

_EPS = np.finfo(float).eps
#: Harmonic margins L tried on each side of the resonant pair (blocks s_min = min(s_a, s_b) - L
#: .. max(s_a, s_b) + L); the result of L is accepted when L + 2 agrees with it.
_MARGINS = (2, 4, 6, 8, 10, 12)
#: Largest relative width handled here; wider regions are the monodromy search's (the
#: linearisation about the pair's midpoint errs by ~ width / Omega relative).
MAX_WIDTH = 1e-6
#: Smallest relative width reported (~50 eps: below it the width is not resolved in double
#: precision, and no Omega grid of floating-point numbers could hold a point inside).
MIN_WIDTH = 1e-14


def _pair_layout(kind: np.ndarray, j: np.ndarray, L: int):
    """Block indices (p_a, p_b), signs (sig_a, sig_b) and the lowest harmonic s_min.

    simple / sum: lambda + i s_a Omega = +i omega_i, lambda + i s_b Omega = -i omega_k,
    s_a - s_b = j; difference: both +, s_b - s_a = j (omega_k > omega_i).
    """
    diff = kind == 2
    s_a = np.where(diff, -(j // 2), (j + 1) // 2)
    s_b = np.where(diff, s_a + j, s_a - j)
    s_min = np.minimum(s_a, s_b) - L
    return s_a - s_min, s_b - s_min, np.ones(kind.size), np.where(diff, 1.0, -1.0), s_min


def _block_factor(Dg, Up, Lo):
    """Block LU (block Thomas, no inter-block pivoting) of the batched block-tridiagonal matrices:
    diagonal Dg (B, h, n, n), Up / Lo the blocks above / below. Returns the inverse pivots.
    """
    h = Dg.shape[1]
    Di = np.empty_like(Dg)
    Di[:, 0] = _inv(Dg[:, 0])
    for p in range(1, h):
        Di[:, p] = _inv(Dg[:, p] - Lo[:, p - 1] @ (Di[:, p - 1] @ Up[:, p - 1]))
    return Di


def _inv(A: np.ndarray) -> np.ndarray:
    """Batched inverse; a singular entry (a component of Q exactly resonant at lambda_0) gives
    NaN there, so that candidate is reported as not resolved instead of failing the batch."""
    try:
        return np.linalg.inv(A)
    except np.linalg.LinAlgError:
        out = np.full_like(A, np.nan)
        for b in range(A.shape[0]):  # rare: only after a failed batch
            try:
                out[b] = np.linalg.inv(A[b])
            except np.linalg.LinAlgError:
                pass
        return out


def _block_solve(Di, Up, Lo, R):
    """T X = R with the factors of :func:`_block_factor` (R: (B, h, n, r))."""
    h = Di.shape[1]
    Rp = np.empty_like(R)
    Rp[:, 0] = R[:, 0]
    for p in range(1, h):
        Rp[:, p] = R[:, p] - Lo[:, p - 1] @ (Di[:, p - 1] @ Rp[:, p - 1])
    X = np.empty_like(R)
    X[:, h - 1] = Di[:, h - 1] @ Rp[:, h - 1]
    for p in range(h - 2, -1, -1):
        X[:, p] = Di[:, p] @ (Rp[:, p] - Up[:, p] @ X[:, p + 1])
    return X


def _block_solve_t(Di, Up, Lo, R):
    """T^T Y = R with the same factors: U^T z = R forward, then L^T Y = z backward."""
    h = Di.shape[1]
    DiT = np.swapaxes(Di, -1, -2)
    Z = np.empty_like(R)
    Z[:, 0] = DiT[:, 0] @ R[:, 0]
    for p in range(1, h):
        Z[:, p] = DiT[:, p] @ (R[:, p] - np.swapaxes(Up[:, p - 1], -1, -2) @ Z[:, p - 1])
    Y = np.empty_like(R)
    Y[:, h - 1] = Z[:, h - 1]
    for p in range(h - 2, -1, -1):  # (Lo_p D'_p^-1)^T = D'_p^-T Lo_p^T
        Y[:, p] = Z[:, p] - DiT[:, p] @ (np.swapaxes(Lo[:, p], -1, -2) @ Y[:, p + 1])
    return Y


def _discriminant(mu, Bt, om, nu0, ia, ib, pa, pb, s_min, h, n_fix):
    """D(Omega), the pair's midpoint nu0 and D's round-off error for a batch (lambda = i nu).

    Hill's blocks diag(mu) - (nu + s Omega)^2 are real for an undamped real frame; with
    det(S_0 + y S') = a y^2 + b y + c, D = -(nu_1 - nu_2)^2 = -(b^2 - 4 a c) / a^2.
    """
    B = om.size
    n = mu.size
    rows = np.arange(B)
    s = s_min[:, None] + np.arange(h)[None, :]  # (B, h) absolute harmonics
    dtype = np.result_type(Bt, nu0, float)
    half = 0.5 * Bt.astype(dtype)
    symmetric = bool(np.all(Bt == Bt.T))
    for _ in range(n_fix + 1):
        z = nu0[:, None] + s * om[:, None]  # nu + s Omega, (B, h)
        diag = mu[None, None, :] - z[:, :, None] ** 2  # Hill's blocks, Bolotin (1964) sec. 7-8
        dd = -2.0 * z[:, :, None] * np.ones(n)[None, None, :]  # d/d nu of the diagonal
        Dg = np.zeros((B, h, n, n), dtype=dtype)
        idx = np.arange(n)
        Dg[:, :, idx, idx] = diag
        Up = np.broadcast_to(half, (B, h - 1, n, n)).copy()
        Lo = Up.copy()
        # T~: the P rows and columns replaced by the identity (T~^-1 restricted to Q = T_QQ^-1)
        for p_, i_ in ((pa, ia), (pb, ib)):
            Dg[rows, p_, i_, :] = 0.0
            Dg[rows, p_, :, i_] = 0.0
            Dg[rows, p_, i_, i_] = 1.0
            up = p_ < h - 1  # block (p, p + 1): row i; block (p + 1, p): column i
            Up[rows[up], p_[up], i_[up], :] = 0.0
            Lo[rows[up], p_[up], :, i_[up]] = 0.0
            dn = p_ > 0  # block (p - 1, p): column i; block (p, p - 1): row i
            Up[rows[dn], p_[dn] - 1, :, i_[dn]] = 0.0
            Lo[rows[dn], p_[dn] - 1, i_[dn], :] = 0.0
        # T_QP (columns of the P components, P rows zero) and T_PQ^T
        R = np.zeros((B, h, n, 2), dtype=dtype)
        Lt = np.zeros((B, h, n, 2), dtype=dtype)
        for c, (p_, i_) in enumerate(((pa, ia), (pb, ib))):
            for dp in (-1, 1):
                q = p_ + dp
                ok = (q >= 0) & (q < h)
                R[rows[ok], q[ok], :, c] = half[:, i_[ok]].T
                Lt[rows[ok], q[ok], :, c] = half[i_[ok], :]
        for p_, i_ in ((pa, ia), (pb, ib)):  # P rows of the right sides: 0
            R[rows, p_, i_, :] = 0.0
            Lt[rows, p_, i_, :] = 0.0
        Di = _block_factor(Dg, Up, Lo)
        X = _block_solve(Di, Up, Lo, R)  # T_QQ^-1 T_QP
        if symmetric:  # T = T^T: (T_PQ T_QQ^-1)^T = T_QQ^-1 T_QP
            Y = X
        else:
            Y = _block_solve_t(Di, Up, Lo, Lt)  # (T_PQ T_QQ^-1)^T
        # S_0 = T_PP - T_PQ X, S' = T_PP' + Y^T diag(T_QQ') X  (Loewdin partitioning)
        tpp = np.zeros((B, 2, 2), dtype=dtype)
        tpp[:, 0, 0] = diag[rows, pa, ia]
        tpp[:, 1, 1] = diag[rows, pb, ib]
        adj = (pa - pb == 1) | (pb - pa == 1)  # j = 1: the pair couples directly
        tpp[:, 0, 1] = np.where(adj, half[ia, ib], 0.0)
        tpp[:, 1, 0] = np.where(adj, half[ib, ia], 0.0)
        S0 = tpp - np.einsum("bhnc,bhnd->bcd", Lt, X)  # Loewdin (1963) partitioning
        dpp = np.zeros((B, 2, 2), dtype=dtype)
        dpp[:, 0, 0] = dd[rows, pa, ia]
        dpp[:, 1, 1] = dd[rows, pb, ib]
        mask = np.ones((B, h, n))
        mask[rows, pa, ia] = 0.0
        mask[rows, pb, ib] = 0.0
        S1 = dpp + np.einsum("bhnc,bhn,bhnd->bcd", Y, dd * mask, X)
        # det(S0 + y S1) = a y^2 + b y + c
        a = S1[:, 0, 0] * S1[:, 1, 1] - S1[:, 0, 1] * S1[:, 1, 0]
        b = (S0[:, 0, 0] * S1[:, 1, 1] + S1[:, 0, 0] * S0[:, 1, 1]
             - S0[:, 0, 1] * S1[:, 1, 0] - S1[:, 0, 1] * S0[:, 1, 0])
        p11, p12 = S0[:, 0, 0] * S0[:, 1, 1], S0[:, 0, 1] * S0[:, 1, 0]
        c = p11 - p12
        with np.errstate(divide="ignore", invalid="ignore"):  # a = 0: NaN, left unresolved
            ym = -b / (2.0 * a)
        nu0 = nu0 + ym  # the pair's midpoint (fixed point; the last one is returned)
    with np.errstate(divide="ignore", invalid="ignore"):
        D = -(b * b - 4.0 * a * c) / (a * a)  # (lambda_1 - lambda_2)^2, module docstring
        err = 16.0 * _EPS * (np.abs(b) ** 2 + 4.0 * np.abs(a) * (np.abs(p11) + np.abs(p12))) \
            / np.abs(a) ** 2
    return D, nu0, err


def _evaluate(mu, Bt, w, cand, om, L, nu0=None, n_fix=1):
    """D at om (one per candidate entry) with harmonic margin L, from the midpoint nu0
    (lambda = i nu; default: the midpoint of the two unperturbed exponents)."""
    kind, i, k, j = cand["kind"], cand["i"], cand["k"], cand["j"]
    pa, pb, sga, sgb, s_min = _pair_layout(kind, j, L)
    h = int(np.max(j)) + 1 + 2 * L
    if nu0 is None:
        nu0 = 0.5 * ((sga * w[i] - (s_min + pa) * om) + (sgb * w[k] - (s_min + pb) * om))
    return _discriminant(mu, Bt, om, nu0, i, k, pa, pb, s_min, h, n_fix)


def _slope(cand, L):
    """d nu_mid / d Omega of the unperturbed pair (lambda = i nu): -(s_a + s_b) / 2."""
    pa, pb, _, _, s_min = _pair_layout(cand["kind"], cand["j"], L)
    return -0.5 * ((s_min + pa) + (s_min + pb))


def narrow_search(mu: np.ndarray, Bt: np.ndarray, cand: dict, *, max_iter: int = 16) -> dict:
    """Vertex and width of D(Omega) near each candidate (one batch per order j).

    ``mu`` squared steady frequencies, ``Bt`` the modal coupling, ``cand`` arrays kind, i, k, j,
    centre, window (rad per time unit); ``max_iter`` Newton steps per harmonic margin. Returns
    arrays found, converged, lo, hi, growth (sqrt(D) / 2) and omega_at_max (the vertex).
    """
    w = np.sqrt(mu)
    size = cand["centre"].size
    out = {key: np.zeros(size) for key in ("lo", "hi", "growth", "omega_at_max")}
    out["found"] = np.zeros(size, dtype=bool)
    out["converged"] = np.zeros(size, dtype=bool)
    for jj in np.unique(cand["j"]):  # a handful of orders
        sel = np.nonzero(cand["j"] == jj)[0]
        prev = None
        for L in _MARGINS:  # harmonics raised until two margins agree (found ones only)
            sub = {key: v[sel] for key, v in cand.items()}
            Ov, hw, found, g = _vertex(mu, Bt, w, sub, L, max_iter)
            out["lo"][sel], out["hi"][sel] = Ov - hw, Ov + hw
            out["growth"][sel], out["omega_at_max"][sel] = g, Ov
            out["found"][sel] = found
            if prev is not None:
                scale = np.maximum(hw, 1e-15 * sub["centre"])
                tol = 4.0 * _EPS * sub["centre"]
                conv = (np.abs(Ov - prev[0]) <= 1e-3 * scale + tol) & (
                    np.abs(hw - prev[1]) <= 1e-2 * scale + tol) & (found == prev[2])
                out["converged"][sel[conv]] = True
                keep = ~conv
            else:
                out["converged"][sel[~found]] = True  # no pair separation: nothing to refine
                keep = found
            if not keep.any():
                break
            sel, prev = sel[keep], (Ov[keep], hw[keep], found[keep])
    return out


def _vertex(mu, Bt, w, sub, L, max_iter):
    """(vertex, half-width, found, growth) of D on each candidate's window, margin L, by successive
    parabolic interpolation (D is a parabola in Omega to leading order); stops below 1e-3 of the
    half-width, or with D_v < 0 below 1/8 of the points' spread (no region).
    """
    Oc = sub["centre"]
    win = sub["window"]
    P = Oc.size
    h = np.minimum(0.25 * win, 1e-3 * Oc)
    tiny = 1e-14 * Oc
    slope = _slope(sub, L)
    x3 = np.stack([Oc - h, Oc, Oc + h], axis=1)  # (P, 3) the latest points
    # the centre from the unperturbed midpoint (two fixed-point passes), the sides from the
    # centre's midpoint moved along the unperturbed slope (one pass, as the later points)
    Dc, nu, ec = _evaluate(mu, Bt, w, sub, Oc, L, None, n_fix=1)  # nu: lambda = i nu
    nu = np.where(np.isfinite(nu), nu, 0.0)  # a degenerate pair (a = 0): D NaN, unresolved
    a2 = np.concatenate([np.arange(P)] * 2)
    Ds, _, es = _evaluate(mu, Bt, w, {key: v[a2] for key, v in sub.items()},
                          np.concatenate([Oc - h, Oc + h]), L,
                          np.concatenate([nu - slope * h, nu + slope * h]), n_fix=0)
    D3 = np.stack([Ds[:P].real, Dc.real, Ds[P:].real], axis=1)
    e3 = np.stack([es[:P], ec, es[P:]], axis=1)
    nu_x = Oc.copy()
    xv = Oc.copy()
    Dv = np.full(P, -np.inf)
    half = np.zeros(P)
    errv = np.zeros(P)
    act = np.arange(P)
    with np.errstate(divide="ignore", invalid="ignore"):
        for _ in range(max_iter):
            if act.size == 0:
                break
            X, Y = x3[act], D3[act]
            # parabola D = c2 x^2 + c1 x + c0 through the three points (divided differences)
            f01 = (Y[:, 1] - Y[:, 0]) / (X[:, 1] - X[:, 0])
            f12 = (Y[:, 2] - Y[:, 1]) / (X[:, 2] - X[:, 1])
            c2 = (f12 - f01) / (X[:, 2] - X[:, 0])
            c1 = f01 - c2 * (X[:, 0] + X[:, 1])
            xn = -c1 / (2.0 * c2)
            ok = np.isfinite(xn) & (c2 < 0.0)
            xn = np.clip(np.where(ok, xn, Oc[act]), Oc[act] - win[act], Oc[act] + win[act])
            spread = np.max(X, axis=1) - np.min(X, axis=1)
            near = np.min(np.abs(X - xn[:, None]), axis=1)
            fresh = ok & (near > tiny[act])  # a new point (else: converged on a point)
            ev = act[fresh]
            if ev.size:
                start = nu[ev] + slope[ev] * (xn[fresh] - nu_x[ev])
                Dn, mn, en = _evaluate(mu, Bt, w, {key: v[ev] for key, v in sub.items()},
                                       xn[fresh], L, start, n_fix=0)
                rows = np.nonzero(fresh)[0]
                far = np.argmax(np.abs(X[rows] - xn[rows, None]), axis=1)  # replaced
                X[rows, far], Y[rows, far] = xn[rows], Dn.real
                e = e3[act]
                e[rows, far] = en
                x3[act], D3[act], e3[act] = X, Y, e
                nu[ev], nu_x[ev] = mn, xn[fresh]
            # D at the vertex: the point nearest to it
            at = np.argmin(np.abs(X - xn[:, None]), axis=1)
            Dn_all = Y[np.arange(act.size), at]
            errv[act] = e3[act][np.arange(act.size), at]  # round-off of D there
            moved = np.abs(xn - xv[act])
            hf = np.where(ok, np.sqrt(np.abs(Dn_all) / -np.where(ok, c2, -1.0)), 0.0)
            xv[act] = xn
            Dv[act] = np.where(ok, Dn_all, -np.inf)
            half[act] = np.where(ok & (Dn_all > 0.0), hf, 0.0)
            done = ~ok | ~fresh | (moved <= 1e-3 * np.maximum(hf, tiny[act])) | (
                (Dn_all < 0.0) & (hf >= spread) & (moved <= 0.125 * spread))
            act = act[~done]
    found = (Dv > 64.0 * errv) & (2.0 * half >= MIN_WIDTH * Oc) & (
        2.0 * half <= MAX_WIDTH * Oc)
    growth = np.where(found, 0.5 * np.sqrt(np.maximum(Dv, 0.0)), 0.0)
    return xv, np.where(found, half, 0.0), found, growth
