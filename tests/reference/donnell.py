"""Single-cylinder references: appendix D-II of the memo and Donnell's shear-diaphragm cylinder.

Verification-only: the memo's symmetric-function forms (D-9, D-10, D-14..D-16), the printed
roots, the single-cylinder matrix of D-II, and the Donnell-Mushtari frequency determinant of a
shear-diaphragm cylinder (Leissa), against which ``tests/test_shell.py`` checks the pipeline's
batched eigen-solution of :mod:`flexbooster.memo.shell`.

References
----------
.. [1] Tech Memo 104, section 6.2 and appendix D.
.. [2] A. W. Leissa, *Vibration of Shells*, NASA SP-288, 1973, sec. 2.1-2.3 (eqs. 2.20-2.22).
"""

from __future__ import annotations

import numpy as np

from flexbooster.memo.shell import ShellFrequencies

__all__ = [
    "donnell_frequencies",
    "donnell_cubic",
    "donnell_reference",
    "single_cylinder_symmetric_functions",
    "single_cylinder_roots_j0",
    "single_cylinder_matrix",
    "single_cylinder_frequencies",
    "symmetric_functions_j0",
    "symmetric_functions_jk",
    "memo_roots_j0",
    "sd_cylinder_stiffness",
]

# --------------------------------------------------------------------------------------------
# Single cylinder: appendix D-II and Donnell's determinant (Leissa)
# --------------------------------------------------------------------------------------------


def single_cylinder_matrix(lam: float, sigma: float, mu: float, nu: float,
                           j: np.ndarray, k: np.ndarray) -> np.ndarray:
    """Matrix C^{jk} of appendix D-II (single cylinder, Donnell, memo units).

    Parameters
    ----------
    lam : float
        lambda = L / R (L the cylinder's half-length).
    sigma : float
        sigma = h / L.
    mu : float
        mu = rho L^2 omega_1^2 / E.
    nu : float
        Poisson's ratio.
    j, k : array_like of int
        Axial half-wave index (j >= 1: j half-waves over 2L) and circumferential wave number.

    Returns
    -------
    ndarray, shape broadcast(j, k) + (3, 3)
        Symmetric C with omega_bar^2 its eigenvalues (D-1..D-8); unknowns (U, V, W).

    Notes
    -----
    With alpha = j pi / 2 and g = 1 / ((1 - nu^2) mu), from 3.0-2 and u = cos(alpha (xi+1)),
    v, w = sin(alpha (xi+1)) (shear diaphragm):
    C11 = g [alpha^2 + (1-nu)/2 lam^2 k^2], C12 = -g (1+nu)/2 lam k alpha,
    C13 = g nu lam alpha, C22 = g [(1-nu)/2 alpha^2 + lam^2 k^2], C23 = -g lam^2 k,
    C33 = g [lam^2 + sigma^2/12 (alpha^2 + lam^2 k^2)^2].  For k = 0 the (U, W) block gives
    D-4 and D-5 (C11 + C22 -> C11 + C33 there).  The memo cites p. 60-62 of its ref. 3 for
    these; the entries are derived here from 3.0-2.

    References
    ----------
    Tech Memo 104, appendix D-II, eqs. (D-1)..(D-8), (3.0-2).
    """
    j, k = np.broadcast_arrays(np.asarray(j), np.asarray(k))  # object arrays (mpmath) pass
    al = j * np.pi / 2.0
    g = 1.0 / ((1.0 - nu**2) * mu)
    c11 = g * (al**2 + (1 - nu) / 2 * lam**2 * k**2)
    c12 = -g * (1 + nu) / 2 * lam * k * al
    c13 = g * nu * lam * al
    c22 = g * ((1 - nu) / 2 * al**2 + lam**2 * k**2)
    c23 = -g * lam**2 * k
    c33 = g * (lam**2 + sigma**2 / 12 * (al**2 + lam**2 * k**2) ** 2)
    return np.stack([np.stack([c11, c12, c13], -1), np.stack([c12, c22, c23], -1),
                     np.stack([c13, c23, c33], -1)], -2)


def single_cylinder_frequencies(lam: float, sigma: float, mu: float, nu: float,
                                j: np.ndarray, k: np.ndarray) -> np.ndarray:
    """omega_bar of the single cylinder (appendix D-II), ascending, shape (..., 3).

    Parameters
    ----------
    lam, sigma, mu, nu : float
        As in :func:`single_cylinder_matrix`.
    j, k : array_like of int
        Indices, j >= 1.

    Returns
    -------
    ndarray
        Square roots of the eigenvalues of C^{jk} (for k = 0 the middle one is the
        torsional root (1 - nu)/2 alpha^2 g, uncoupled and absent from the memo's D-II-1).

    References
    ----------
    Tech Memo 104, eqs. (D-1)..(D-8).
    """
    c = single_cylinder_matrix(lam, sigma, mu, nu, j, k)
    return np.sqrt(np.linalg.eigvalsh(c))  # D-6..D-8: symmetric functions of these


def single_cylinder_symmetric_functions(c: np.ndarray) -> tuple:
    """Right-hand sides of (D-6), (D-7), (D-8) from the matrix C^{jk}, as printed.

    Parameters
    ----------
    c : ndarray, shape (..., 3, 3)
        :func:`single_cylinder_matrix` (float, or object arrays of mpmath numbers).

    Returns
    -------
    s1, s2, s3 : ndarray
        Sum, pairwise-product sum and product of the three omega_bar^2.

    References
    ----------
    Tech Memo 104, eqs. (D-6)..(D-8).
    """
    C = {(r + 1, q + 1): c[..., r, q] for r in range(3) for q in range(3)}
    s1 = C[1, 1] + C[2, 2] + C[3, 3]  # (D-6)
    s2 = ((C[2, 2] * C[3, 3] - C[3, 2] * C[2, 3]) + (C[1, 1] * C[3, 3] - C[3, 1] * C[1, 3])
          + (C[1, 1] * C[2, 2] - C[2, 1] * C[1, 2]))  # (D-7)
    s3 = (C[1, 1] * C[2, 2] * C[3, 3] + C[2, 1] * C[3, 2] * C[1, 3] + C[3, 1] * C[1, 2] * C[2, 3]
          - C[3, 1] * C[2, 2] * C[1, 3] - C[2, 1] * C[1, 2] * C[3, 3]
          - C[1, 1] * C[3, 2] * C[2, 3])  # (D-8)
    return s1, s2, s3


def single_cylinder_roots_j0(lam: float, sigma: float, mu: float, nu: float,
                             j: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(omega_j0^1)^2 and (omega_j0^2)^2 of the single cylinder, closed form (D-1)..(D-5).

    Parameters
    ----------
    lam, sigma, mu, nu : float
        As in :func:`single_cylinder_matrix`.
    j : array_like of int
        Axial index, >= 1.

    Returns
    -------
    lower, upper : ndarray
        Squared dimensionless frequencies.

    References
    ----------
    Tech Memo 104, eqs. (D-1)..(D-5).
    """
    j = np.asarray(j)
    a = 1.0  # (D-3)
    c11 = j**2 * np.pi**2 / (4 * (1 - nu**2) * mu)
    c22 = (192 * lam**2 + j**4 * np.pi**4 * sigma**2) / (192 * (1 - nu**2) * mu)
    b = c11 + c22  # (D-4)
    c = c11 * c22 - (nu * lam * j * np.pi / (2 * (1 - nu**2) * mu)) ** 2  # (D-5)
    root = np.sqrt(b**2 - 4 * a * c) / (2 * a)
    return b / (2 * a) - root, b / (2 * a) + root  # (D-1), (D-2)


def symmetric_functions_j0(mass: np.ndarray, stiff: np.ndarray) -> tuple:
    """(a), (b), (c) of eq. (6.2-7) / (D-11..D-13) from 2x2 mass and stiffness matrices.

    Parameters
    ----------
    mass, stiff : ndarray, shape (..., 2, 2)
        M = [[a, b], [0, j]], K = [[c, d], [h, k]] (coefficient names of 5.4-6).

    Returns
    -------
    a, b, c : ndarray
        Delta(s) = a s^4 + b s^2 + c (6.2-5), so omega^2 sum b/a and product c/a.

    References
    ----------
    Tech Memo 104, eqs. (6.2-7), (D-11)..(D-13).
    """
    a_, b_, j_ = mass[..., 0, 0], mass[..., 0, 1], mass[..., 1, 1]
    c_, d_, h_, k_ = stiff[..., 0, 0], stiff[..., 0, 1], stiff[..., 1, 0], stiff[..., 1, 1]
    return (a_ * j_,  # (6.2-7a)
            c_ * j_ + a_ * k_ - h_ * b_,  # (6.2-7b)
            c_ * k_ - h_ * d_)  # (6.2-7c)


def symmetric_functions_jk(mass: np.ndarray, stiff: np.ndarray) -> tuple:
    """(A), (B), (C), (D) of eq. (6.2-17) / (D-17..D-20) from 3x3 mass and stiffness.

    Parameters
    ----------
    mass, stiff : ndarray, shape (..., 3, 3)
        M = [[a, b, c], [0, h, 0], [0, 0, n]], K = [[d, e, f], [g, j, k], [l, m, p]].

    Returns
    -------
    A, B, C, D : ndarray
        Sum, pairwise sum and product of omega^2 are B/A, C/A, D/A (6.2-16).

    References
    ----------
    Tech Memo 104, eqs. (6.2-16), (6.2-17) ("(i_jk)" in 6.2-17d read as (j_jk)).
    """
    a, b, c, h, n = (mass[..., 0, 0], mass[..., 0, 1], mass[..., 0, 2], mass[..., 1, 1],
                     mass[..., 2, 2])
    d, e, f = stiff[..., 0, 0], stiff[..., 0, 1], stiff[..., 0, 2]
    g, j, k = stiff[..., 1, 0], stiff[..., 1, 1], stiff[..., 1, 2]
    l, m, p = stiff[..., 2, 0], stiff[..., 2, 1], stiff[..., 2, 2]  # noqa: E741
    A = a * h * n  # (6.2-17a)
    B = a * j * n + a * h * p + d * h * n - l * h * c - g * b * n  # (6.2-17b)
    C = (a * j * p + d * j * n + d * h * p + g * m * c + k * l * b - k * m * a
         - l * j * c - l * f * h - g * e * n - g * b * p)  # (6.2-17c)
    D = d * j * p + g * m * f + k * l * e - k * m * d - l * j * f - g * e * p  # (6.2-17d)
    return A, B, C, D


def memo_roots_j0(a: np.ndarray, b: np.ndarray, c: np.ndarray,
                  form: str = "D-9") -> tuple[np.ndarray, np.ndarray]:
    """The two k = 0 roots from (a), (b), (c): D-9/D-10 or 6.2-6 as printed.

    Parameters
    ----------
    a, b, c : ndarray
        Coefficients of 6.2-7.
    form : {"D-9", "6.2-6"}
        ``"D-9"``: omega^2 = b/(2a) -+ sqrt(b^2 - 4ac)/(2a) (D-9, D-10; returns omega^2);
        ``"6.2-6"``: the printed b/(2a) -+ sqrt(b^2 - 4ac) (erratum E6; what it calls omega).

    Returns
    -------
    lower, upper : ndarray

    References
    ----------
    Tech Memo 104, eqs. (6.2-6), (D-9), (D-10); reading guide erratum E6.
    """
    if form == "D-9":
        root = np.sqrt(b**2 - 4 * a * c) / (2 * a)  # (D-9), (D-10)
    elif form == "6.2-6":
        root = np.sqrt(b**2 - 4 * a * c)  # (6.2-6) as printed
    else:
        raise ValueError(f"form = {form!r}: must be 'D-9' or '6.2-6'")
    return b / (2 * a) - root, b / (2 * a) + root


def donnell_cubic(lam_l: np.ndarray, n: np.ndarray, k: float, nu: float) -> tuple:
    """Coefficients of Donnell's frequency cubic (Leissa, NASA SP-288, eqs. 2.21-2.22).

    Parameters
    ----------
    lam_l : array_like
        lambda = m pi R / length.
    n : array_like
        Circumferential wave number.
    k : float
        h^2 / (12 R^2).
    nu : float
        Poisson's ratio.

    Returns
    -------
    K2, K1, K0 : ndarray
        Delta^3 + K2 Delta^2 + K1 Delta + K0 = 0, Delta = rho (1 - nu^2) R^2 omega^2 / E.
        Plain arithmetic only, so mpmath numbers pass through.

    References
    ----------
    A. W. Leissa, *Vibration of Shells*, NASA SP-288, 1973, eqs. (2.20)-(2.22).
    """
    s = lam_l**2 + n**2
    K2 = -(1.0 + 0.5 * (3.0 - nu) * s + k * s**2)
    K1 = 0.5 * (1.0 - nu) * ((3.0 + 2.0 * nu) * lam_l**2 + n**2 + s**2
                             + (3.0 - nu) / (1.0 - nu) * k * s**3)
    K0 = -0.5 * (1.0 - nu) * ((1.0 - nu**2) * lam_l**4 + k * s**4)
    return K2, K1, K0


def donnell_frequencies(
    length: float, radius: float, thickness: float, E: float, nu: float, rho: float,
    m: int | np.ndarray, n: int | np.ndarray,
) -> np.ndarray:
    """Donnell's shear-diaphragm frequencies of a single cylinder, in Hz.

    Parameters
    ----------
    length : float
        Total length of the cylinder (m), > 0 (2 L_d for cylinder d).
    radius : float
        Mid-surface radius R (m), > 0.
    thickness : float
        Wall thickness h (m), 0 < h < R.
    E : float
        Young's modulus (Pa), > 0.
    nu : float
        Poisson's ratio, 0 <= nu < 0.5.
    rho : float
        Density (kg/m^3), > 0.
    m : array_like of int
        Axial half-waves, >= 1.
    n : array_like of int
        Circumferential waves, >= 0.

    Returns
    -------
    ndarray, shape broadcast(m, n) + (3,)
        The three frequencies (Hz), ascending.

    Notes
    -----
    With lambda = m pi R / length, k = h^2 / (12 R^2) and the frequency parameter
    Delta = rho (1 - nu^2) R^2 omega^2 / E, Donnell's frequency determinant (Leissa eq. 2.20)
    expands to the cubic Delta^3 + K2 Delta^2 + K1 Delta + K0 = 0 with (Leissa 2.21-2.22)

    K2 = -[1 + (3 - nu)(n^2 + lambda^2)/2 + k (n^2 + lambda^2)^2],
    K1 = (1 - nu)/2 [(3 + 2 nu) lambda^2 + n^2 + (n^2 + lambda^2)^2
         + (3 - nu)/(1 - nu) k (n^2 + lambda^2)^3],
    K0 = -(1 - nu)/2 [(1 - nu^2) lambda^4 + k (n^2 + lambda^2)^4].

    The largest root comes from the trigonometric (Viete) formula, polished by Newton steps;
    the other two from Vieta's relations (product -K0/Delta_3, sum (K1 - product)/Delta_3)
    and the stable quadratic formula, so the small (bending, torsional, axial) roots keep
    full relative precision even when they are 1e-8 of the largest.

    References
    ----------
    A. W. Leissa, *Vibration of Shells*, NASA SP-288, 1973, eqs. (2.20)-(2.22).
    """
    for name, value in (("length", length), ("radius", radius), ("thickness", thickness),
                        ("E", E), ("rho", rho)):
        if not (np.isfinite(value) and value > 0.0):
            raise ValueError(f"{name} = {value!r}: must be a finite positive number")
    if not thickness < radius:
        raise ValueError(f"thickness = {thickness!r}: must be smaller than radius = {radius!r}")
    if not (np.isfinite(nu) and 0.0 <= nu < 0.5):
        raise ValueError(f"nu = {nu!r}: must satisfy 0 <= nu < 0.5")
    m_arr, n_arr = np.broadcast_arrays(np.asarray(m), np.asarray(n))
    if m_arr.size and (np.any(m_arr < 1) or np.any(m_arr != np.round(m_arr))):
        raise ValueError(f"m = {m!r}: must be integers >= 1 (axial half-waves)")
    if n_arr.size and (np.any(n_arr < 0) or np.any(n_arr != np.round(n_arr))):
        raise ValueError(f"n = {n!r}: must be integers >= 0 (circumferential waves)")
    lam_l = m_arr.astype(float) * np.pi * radius / length
    nn = n_arr.astype(float)
    kk = thickness**2 / (12.0 * radius**2)
    K2, K1, K0 = donnell_cubic(lam_l, nn, kk, nu)
    # Largest root by Viete (Delta = t - K2/3, t^3 + P t + Q = 0, three real roots), which
    # the trigonometric form gives to full relative precision; then Newton-polished.
    P = K1 - K2**2 / 3.0
    Q = 2.0 * K2**3 / 27.0 - K2 * K1 / 3.0 + K0
    r = np.sqrt(np.maximum(-P / 3.0, 0.0))
    arg = np.clip(-Q / (2.0 * np.where(r > 0, r, 1.0) ** 3), -1.0, 1.0)
    big = 2.0 * r * np.cos(np.arccos(arg) / 3.0) - K2 / 3.0
    for _ in range(2):
        val = ((big + K2) * big + K1) * big + K0
        der = (3.0 * big + 2.0 * K2) * big + K1
        big = big - np.where(der > 0.0, val / np.where(der > 0.0, der, 1.0), 0.0)
    # The other two from Vieta without cancellation: product -K0/big, sum (K1 - product)/big,
    # then the stable quadratic formula (smaller root = product / larger root).
    prod = -K0 / big
    summ = (K1 - prod) / big
    mid = 0.5 * (summ + np.sqrt(np.maximum(summ**2 - 4.0 * prod, 0.0)))
    low = np.where(mid > 0.0, prod / np.where(mid > 0.0, mid, 1.0), 0.0)
    roots = np.stack([low, mid, big], -1)
    roots = np.maximum(roots, 0.0)
    omega = np.sqrt(roots * E / (rho * (1.0 - nu**2) * radius**2))
    return np.sort(omega, axis=-1) / (2.0 * np.pi)


def donnell_reference(table: ShellFrequencies, R1: float, L1: float, R2: float, L2: float,
                      h: float, E: float, nu: float, rho: float) -> np.ndarray:
    """Isolated-cylinder frequencies (Hz) matching each row of a composite table.

    Parameters
    ----------
    table : ShellFrequencies
        Composite frequencies (any method).
    R1, L1, R2, L2 : float
        Radii and half-lengths (m).
    h, E, nu, rho : float
        Thickness (m), modulus (Pa), Poisson's ratio, density (kg/m^3).

    Returns
    -------
    ndarray
        For j >= 1 rows Donnell's shear-diaphragm frequency of cylinder d alone (length
        2 L_d, m = j, n = k, :func:`donnell_frequencies`), branch-th of the roots that the
        memo's system carries (for k = 0 the uncoupled torsional root is left out); for
        j = 0 rows the uniform axial mode of the cylinder alone,
        omega^2 = E k^2 / (2 (1 + nu) rho R_d^2) (5.4-4 in physical units).

    References
    ----------
    Leissa, NASA SP-288, eqs. (2.20)-(2.22); Tech Memo 104, eq. (5.4-4).
    """
    out = np.empty(len(table))
    for d, R, Ld in ((1, R1, L1), (2, R2, L2)):
        sel = table.cylinder == d
        j, k, br = table.j[sel], table.k[sel], table.branch[sel]
        res = np.sqrt(E * k**2 / (2.0 * (1.0 + nu) * rho * R**2)) / (2.0 * np.pi)
        pos = j >= 1
        f3 = donnell_frequencies(2.0 * Ld, R, h, E, nu, rho, j[pos], k[pos])
        lam_l = j[pos] * np.pi * R / (2.0 * Ld)
        f_tors = np.sqrt((1.0 - nu) / 2.0 * lam_l**2 * E
                         / (rho * (1.0 - nu**2) * R**2)) / (2.0 * np.pi)
        drop = np.argmin(np.abs(f3 - f_tors[:, None]), axis=-1)  # torsional root (k = 0)
        idx = np.arange(3)[None, :]
        keep = np.where(k[pos, None] == 0, idx + (idx >= drop[:, None]), idx)
        pick = np.take_along_axis(f3, np.minimum(keep, 2), axis=-1)
        res[pos] = pick[np.arange(pick.shape[0]), br[pos] - 1]
        out[sel] = res
    return out


def sd_cylinder_stiffness(length: float, radius: float, thickness: float, E: float, nu: float,
                          m: int, n: int, theory: str = "sanders", *,
                          stiffening: np.ndarray | None = None,
                          prestress: tuple[float, float] = (0.0, 0.0)) -> np.ndarray:
    """Stiffness per unit area of the shear-diaphragm cylinder's mode (m, n), Sanders or Donnell.

    Parameters
    ----------
    length, radius, thickness : float
        L, R, h (m).
    E, nu : float
        Young's modulus (Pa), Poisson's ratio.
    m, n : int
        Axial half-waves (>= 0) and circumferential waves (>= 0).
    theory : {"sanders", "donnell"}
    stiffening : ndarray, shape (6, 6), optional
        Added to diag(A, D) in the strain order (eps_x, eps_t, gamma, kappa_x, kappa_t, tau):
        smeared stiffeners (Baruch and Singer 1963).
    prestress : (float, float)
        Membrane resultants (N_x, N_theta) (N/m, tension > 0): the Donnell geometric stiffness
        N_x w_x^2 + N_theta (w_t / R)^2 adds N_x lam^2 + N_theta n^2 / R^2 to K[2, 2]
        (Brush and Almroth 1975, sec. 5.3).

    Returns
    -------
    ndarray, shape (3, 3)
        K (N/m^3) on the amplitudes (A, B, C) of u = A cos(lam x) cos(n t),
        v = B sin(lam x) sin(n t), w = C sin(lam x) cos(n t), lam = m pi / L: the strain
        energy per unit area is (A, B, C) K (A, B, C) / 4 and, with the inertia rho h per unit
        area, |K - omega^2 diag(rho h, rho h, rho h)| = 0 (m = 0: the u-only mode, K[0, 0]).

    Notes
    -----
    Strain amplitudes (Leissa 1973 sec. 2.1; Donnell drops the starred terms):
    eps_x = -lam A, eps_t = (n B + C) / R, gamma = lam B - n A / R, kappa_x = lam^2 C,
    kappa_t = (n^2 C + *n B) / R^2, tau = (2 n lam C + *1.5 lam B + *0.5 n A / R) / R;
    K = E h / (1 - nu^2) mem^T C mem + E h^3 / (12 (1 - nu^2)) ben^T C ben.

    References
    ----------
    A. W. Leissa, *Vibration of Shells*, NASA SP-288, 1973, sec. 2.1-2.3.
    """
    lam = m * np.pi / length
    c = 1.0 if theory == "sanders" else 0.0
    R = radius
    a = E * thickness / (1.0 - nu**2)
    d = E * thickness**3 / (12.0 * (1.0 - nu**2))
    mem = np.array([[-lam, 0, 0], [0, n / R, 1 / R], [-n / R, lam, 0]])
    ben = np.array([[0, 0, lam**2], [0, c * n / R**2, n**2 / R**2],
                    [c * 0.5 * n / R**2, c * 1.5 * lam / R, 2 * n * lam / R]])
    cm = np.array([[1, nu, 0], [nu, 1, 0], [0, 0, (1 - nu) / 2]])
    out = a * mem.T @ cm @ mem + d * ben.T @ cm @ ben
    if stiffening is not None:
        strains = np.vstack([mem, ben])
        out = out + strains.T @ stiffening @ strains
    out[2, 2] += prestress[0] * lam**2 + prestress[1] * n**2 / R**2
    return out
