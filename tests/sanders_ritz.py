"""An independent model of the vehicle for the tests: Sanders' shell of revolution by a global
Legendre-Ritz method, its membrane prestate in closed form, and Hill's method for the regions.

Written from the equations, not from ``flexbooster``'s code (which uses p-version conical
finite elements, node frames and a DOF map):

* each segment (cylinder or cone of meridian angle phi, dr/ds = sin(phi), dx/ds = cos(phi)) has
  u = U(s) cos k t (meridional), v = V(s) sin k t, w = W(s) cos k t (normal), U, V, W Legendre
  series of degree ``degree`` in xi in [-1, 1] over the segment's meridian;
* Sanders' linear strains of a shell of revolution with the Lame parameters A1 = 1, A2 = r and
  the curvatures 1/R1 = 0, 1/R2 = cos(phi) / r (Sanders, NASA TR R-24, 1959; Kraus, Thin
  Elastic Shells, 1967, ch. 2):
  e1 = U', e2 = (k V + sin U + cos W) / r, g = r (V / r)' - k U / r,
  b1 = -W' (meridional rotation), b2 = (k W + cos V) / r, f = (r V)' / (2 r) + k U / (2 r),
  k1 = b1', k2 = (k b2 + sin b1) / r, t = r (b2 / r)' - k b1 / r + cos f / r;
  N = E h / (1 - nu^2) [[1, nu, 0], [nu, 1, 0], [0, 0, (1 - nu) / 2]] e, M the same with
  E h^3 / 12 / (1 - nu^2); kinetic energy rho h (U^2 + V^2 + W^2); the theta integral pi;
* the junctions by constraints on the coefficients (their null space): axial and radial
  displacement u_x = U cos - W sin, u_r = U sin + W cos, V and the rotation W' equal on both
  sides; ends free, shear-diaphragm (V = W = 0) or clamped (U = V = W = W' = 0);
* the membrane prestate of the thrust F0 at the aft edge (Flügge, Stresses in Shells, 1973,
  sec. 2.2): inertia relief a = F0 / m, the axial force F = F0 (1 - m_behind / m), N_s =
  -F / (2 pi r cos), the normal component rho h a sin of the inertia load gives N_theta =
  rho h a r tan; where the meridian turns, a ring of hoop force r (N_s sin of the shell ahead
  - N_s sin of the shell behind) with the second-order strain ((k u_x)^2 + (k u_r + V)^2) /
  (2 r^2); ``uniform``: F = F0 throughout, no N_theta; Sanders' geometric stiffness
  N_s (b1^2 + f^2) + N_theta (b2^2 + f^2) (Brush & Almroth, 1975, ch. 5);
* the regions j = 1 of the modal system q'' + (diag(w^2) + gamma B1 cos W t) q = 0 in the loaded
  modes, B1 = -V^T K_g V: Hill's method, the 2T-periodic solutions sum a_m cos(m W t / 2) +
  b_m sin(m W t / 2), m odd up to 2 n_hill - 1, whose determinants vanish at the edges (Bolotin,
  The Dynamic Stability of Elastic Systems, 1964, ch. 1).
"""

from __future__ import annotations

import numpy as np
import scipy.linalg as sla
from numpy.polynomial import legendre as leg
from scipy.optimize import brentq


def _segment(seg) -> dict:
    """Geometry of a flexbooster Cylinder or Cone (read as data)."""
    r1 = getattr(seg, "radius_aft", getattr(seg, "radius", None))
    r2 = getattr(seg, "radius_fwd", getattr(seg, "radius", None))
    lm = float(np.hypot(seg.length, r2 - r1))
    return {"r1": r1, "len": lm, "sin": (r2 - r1) / lm, "cos": seg.length / lm,
            "h": seg.thickness, "E": seg.E, "nu": seg.nu, "rho": seg.rho}


def _basis(degree: int, xi: np.ndarray, half: float) -> tuple[np.ndarray, ...]:
    """Legendre P_0..P_degree at xi and their first two s-derivatives (ds/dxi = half)."""
    eye = np.eye(degree + 1)
    p0 = leg.legvander(xi, degree)
    p1 = leg.legval(xi, leg.legder(eye, 1)).T / half
    p2 = leg.legval(xi, leg.legder(eye, 2)).T / half**2
    return p0, p1, p2


def prestate(segments, F0: float, uniform: bool = False) -> list[dict]:
    """Per segment: callables F(s), N_s(s), N_theta(s) (s from the segment's aft edge) and the
    ring hoop forces at its aft and forward edges (N)."""
    geo = [_segment(seg) for seg in segments]
    mass = [2 * np.pi * g["rho"] * g["h"] * (g["r1"] + 0.5 * g["sin"] * g["len"]) * g["len"]
            for g in geo]
    total = sum(mass)
    accel = 0.0 if uniform else F0 / total
    out, behind = [], 0.0
    for g, m in zip(geo, mass, strict=True):
        def force(s, g=g, before=behind):
            m_s = 2 * np.pi * g["rho"] * g["h"] * (g["r1"] * s + 0.5 * g["sin"] * s**2)
            return F0 - accel * (before + m_s)

        def ns(s, g=g, force=force):
            return -force(s) / (2 * np.pi * (g["r1"] + g["sin"] * s) * g["cos"])

        def nt(s, g=g):  # p_n = rho h a sin(phi) (the inertia load -rho h a e_x on n)
            return g["rho"] * g["h"] * accel * g["sin"] * (g["r1"] + g["sin"] * s) / g["cos"]

        r2 = g["r1"] + g["sin"] * g["len"]
        out.append({"F": force, "Ns": ns, "Nt": nt,
                    "ring_aft": g["r1"] * ns(0.0) * g["sin"],
                    "ring_fwd": -r2 * ns(g["len"]) * g["sin"]})
        behind += m
    return out


def matrices(segments, k: int, *, degree: int, ends: tuple[str, str], F0: float = 0.0,
             uniform: bool = False) -> tuple[np.ndarray, ...]:
    """(K, M, G, Z): stiffness, mass and geometric stiffness of harmonic k >= 1 in the
    Legendre coefficients, and the null-space basis Z of the end and junction constraints."""
    geo = [_segment(seg) for seg in segments]
    pre = prestate(segments, F0, uniform)
    nq = 3 * degree + 10
    xq, wq = leg.leggauss(nq)
    nf = degree + 1
    n = 3 * nf * len(geo)
    K, M, G = np.zeros((n, n)), np.zeros((n, n)), np.zeros((n, n))
    rows = []
    edge = {}
    for i, (g, p) in enumerate(zip(geo, pre, strict=True)):
        half = 0.5 * g["len"]
        s = (1 + xq) * half
        r = g["r1"] + g["sin"] * s
        P, dP, d2P = _basis(degree, xq, half)
        Z = np.zeros_like(P)
        off = 3 * nf * i
        sl = slice(off, off + 3 * nf)
        U, V, W = (np.hstack([P if j == f else Z for j in range(3)]) for f in range(3))
        dU, dV, dW = (np.hstack([dP if j == f else Z for j in range(3)]) for f in range(3))
        d2W = np.hstack([Z, Z, d2P])
        sn, cs, rc = g["sin"], g["cos"], r[:, None]
        b1, b2 = -dW, (k * W + cs * V) / rc
        db1 = -d2W
        db2 = (k * dW + cs * dV) / rc - sn * b2 / rc
        f = (dV + sn * V / rc) / 2 + k * U / (2 * rc)
        eps = [dU, (k * V + sn * U + cs * W) / rc, dV - sn * V / rc - k * U / rc,
               db1, (k * b2 + sn * b1) / rc, db2 - sn * b2 / rc - k * b1 / rc + cs * f / rc]
        a = g["E"] * g["h"] / (1 - g["nu"] ** 2)
        d = a * g["h"] ** 2 / 12
        nu = g["nu"]
        wt = np.pi * wq * half * r
        for base, c in ((0, a), (3, d)):
            e1, e2, e3 = eps[base:base + 3]
            K[sl, sl] += c * ((e1.T * wt) @ e1 + (e2.T * wt) @ e2
                              + nu * ((e1.T * wt) @ e2 + (e2.T * wt) @ e1)
                              + 0.5 * (1 - nu) * (e3.T * wt) @ e3)
        M[sl, sl] += g["rho"] * g["h"] * sum((x.T * wt) @ x for x in (U, V, W))
        ns, nt = p["Ns"](s) * wt, p["Nt"](s) * wt
        G[sl, sl] += (b1.T * ns) @ b1 + (b2.T * nt) @ b2 + (f.T * (ns + nt)) @ f
        for end, x in (("aft", -1.0), ("fwd", 1.0)):
            pv, dv, _ = _basis(degree, np.array([x]), half)
            zv = np.zeros_like(pv)
            u, v, w = (np.hstack([pv if j == fi else zv for j in range(3)]) for fi in range(3))
            chi = np.hstack([zv, zv, dv])
            full = np.zeros((4, n))
            full[:, sl] = np.vstack([u * cs - w * sn, v, u * sn + w * cs, chi])[:, :]
            local = np.zeros((4, n))
            local[:, sl] = np.vstack([u, v, w, chi])
            edge[(i, end)] = (full, local)
            ring = p["ring_" + end]
            rr = g["r1"] + (g["sin"] * g["len"] if end == "fwd" else 0.0)
            if ring != 0.0:
                gx, gr = k * full[0], k * full[2] + full[1]
                G += np.pi * ring / rr * (np.outer(gx, gx) + np.outer(gr, gr))
    for i in range(len(geo) - 1):
        rows.append(edge[(i, "fwd")][0] - edge[(i + 1, "aft")][0])
    for (i, end), cond in zip(((0, "aft"), (len(geo) - 1, "fwd")), ends, strict=True):
        local = edge[(i, end)][1]
        if cond == "shear-diaphragm":
            rows.append(local[[1, 2]])
        elif cond == "clamped":
            rows.append(local)
    Zc = sla.null_space(np.vstack(rows)) if rows else np.eye(n)
    return K, M, G, Zc


def loaded_modes(segments, k: int, n_modes: int, F0: float, *, degree: int,
                 ends: tuple[str, str] = ("free", "free"), uniform: bool = False):
    """(omega_L (rad/s), B1 = -V^T K_g V (1/s^2)) of the lowest n_modes modes loaded by F0."""
    K, M, G, Z = matrices(segments, k, degree=degree, ends=ends, F0=F0, uniform=uniform)
    A, B, Gr = (Z.T @ X @ Z for X in (K + G, M, G))
    scale = 1 / np.sqrt(np.diag(A))
    A, B = A * np.outer(scale, scale), B * np.outer(scale, scale)
    nn = A.shape[0]
    mu, X = sla.eigh(B, A, subset_by_index=(nn - n_modes, nn - 1))  # inverse: 1 / omega^2
    X = (X * scale[:, None])[:, ::-1]
    X = X / np.sqrt(np.einsum("ai,ab,bi->i", X, Z.T @ M @ Z, X))
    return np.sqrt(1 / mu[::-1]), -(X.T @ Gr @ X)


def principal_edges(omega: np.ndarray, B: np.ndarray, i: int, *, n_hill: int = 6,
                    span: float = 0.2) -> tuple[float, float]:
    """Edges (rad/s) of the principal region (j = 1) of mode i of q'' + (diag(omega^2) +
    B cos W t) q = 0 (B = gamma B1): the two zeros of the cosine and sine Hill determinants
    within 2 omega_i (1 +- span) (Bolotin 1964, ch. 1)."""
    n = omega.size
    A = np.diag(omega**2)

    def hill(W, sign):
        H = np.zeros((n * n_hill, n * n_hill))
        for j in range(n_hill):
            m = 2 * j + 1
            H[j * n:(j + 1) * n, j * n:(j + 1) * n] = A - (m * W / 2) ** 2 * np.eye(n)
            if j + 1 < n_hill:
                H[j * n:(j + 1) * n, (j + 1) * n:(j + 2) * n] = B / 2
                H[(j + 1) * n:(j + 2) * n, j * n:(j + 1) * n] = B / 2
        H[:n, :n] += sign * B / 2  # cos(W t / 2) cos(W t) holds cos(W t / 2) / 2
        sgn, logdet = np.linalg.slogdet(H)
        return sgn * np.exp(logdet / H.shape[0])

    lo, hi = 2 * omega[i] * (1 - span), 2 * omega[i] * (1 + span)
    roots = []
    for sign in (1.0, -1.0):
        grid = np.linspace(lo, hi, 801)
        val = np.array([hill(W, sign) for W in grid])
        # the zero nearest 2 omega_i (other modes' zeros lie farther at these amplitudes)
        cross = np.nonzero(np.sign(val[:-1]) != np.sign(val[1:]))[0]
        c = cross[np.argmin(np.abs(grid[cross] - 2 * omega[i]))]
        roots.append(brentq(hill, grid[c], grid[c + 1], args=(sign,), xtol=1e-13 * hi))
    return min(roots), max(roots)
