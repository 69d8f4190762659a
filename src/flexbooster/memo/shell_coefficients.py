"""Galerkin coefficients of the shell modes of each cylinder (memo 5.2-5.4, appendix A).

The Galerkin procedure turns the Donnell equations (3.0-2) of cylinder d (1 aft, 2 forward)
and mode (j, k) into the modal equations (5.4-6) (k = 0, unknowns U, W) and (5.4-8) (k >= 1,
U, V, W), with coefficients ``(a..m)_j0`` and ``(a..p)_jk``, given two ways:
:func:`memo_coefficients`, appendix A as printed (A-1..A-52, OCR slips read as meant), and
:func:`galerkin_coefficients`, the integrals they stand for, by quadrature. The edge terms of
the step functions' derivatives follow ``delta``: "one-sided" (H(0) = 1), "symmetric"
(H(0) = 1/2) or "none"; the shape-function phase is the printed one (5.3-2/3) or zero
(erratum E10). Coefficients are divided by the theta integral of the test function and the
stiffness ones by (1 - nu^2) mu, as in appendix A. Theory: docs/theory/shell.md;
docs/memo-errata.md.

References: Tech Memo 104, sec. 3.0, 5.2-5.4, appendix A; A. W. Leissa, *Vibration of
Shells*, NASA SP-288, 1973, ch. 2.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
from scipy.special import roots_legendre

from ..checks import positive
from .geometry import mass_properties

__all__ = [
    "J0_NAMES",
    "JK_NAMES",
    "PHASES",
    "DELTA_CONVENTIONS",
    "ShellParameters",
    "CylinderCoefficients",
    "shell_parameters",
    "memo_coefficients",
    "galerkin_coefficients",
    "edge_arguments",
    "overlap_matrices",
]

#: Names of the k = 0 coefficients of eqs. (5.4-6/7), appendix A-II-1 / A-III-1.
J0_NAMES = ("a", "b", "c", "d", "e", "f", "g", "h", "j", "k", "l", "m")
#: Names of the k >= 1 coefficients of eqs. (5.4-8), appendix A-II-2 / A-III-2.
JK_NAMES = ("a", "b", "c", "d", "e", "f", "g", "h", "j", "k", "l", "m", "n", "p")
#: Phase of the shape functions: ``"printed"`` (5.3-2/3, erratum E10) or ``"zero"``.
PHASES = ("printed", "zero")
#: Treatment of the edge terms from G_d' (see the module docstring).
DELTA_CONVENTIONS = ("one-sided", "symmetric", "none")
_DELTA_WEIGHTS = {"one-sided": (1.0, 0.0), "symmetric": (0.5, -0.5), "none": (0.0, 0.0)}


@dataclass(frozen=True)
class ShellParameters:
    """Dimensionless parameters of the two shells (memo 3.0-1, 3.0-4; reading guide 2).

    Attributes
    ----------
    L, L1, L2 : float
        Half-lengths of the composite and of cylinders 1, 2 (m).
    d1, d2, d3 : float
        CM to junction (signed), CM to aft edge, CM to nose (m), Fig. 1.
    a, c, b : float
        xi_bar of the aft edge, the junction and the nose.
    lam1, lam2, sigma, mu, nu : float
        L / R_d, h / L, rho L^2 omega_1^2 / E (erratum E3) and Poisson's ratio.
    omega_1 : float
        Reference frequency (rad/s); frequencies are in its units.
    """

    L: float
    L1: float
    L2: float
    d1: float
    d2: float
    d3: float
    a: float
    c: float
    b: float
    lam1: float
    lam2: float
    sigma: float
    mu: float
    nu: float
    omega_1: float

    def lam(self, d: int) -> float:
        """lambda_d = L / R_d of cylinder ``d``."""
        return self.lam1 if d == 1 else self.lam2

    def half_length(self, d: int) -> float:
        """Half-length L_d of cylinder ``d`` (m)."""
        return self.L1 if d == 1 else self.L2

    def edges(self, d: int) -> tuple[float, float]:
        """xi_bar of the aft and forward edges of cylinder ``d``."""
        return (self.a, self.c) if d == 1 else (self.c, self.b)

    def to_dict(self) -> dict[str, float]:
        """JSON-ready mapping of the parameters."""
        return {k: float(v) for k, v in self.__dict__.items()}


def shell_parameters(
    R1: float,
    L1: float,
    R2: float,
    L2: float,
    h: float,
    E: float,
    nu: float,
    rho: float,
    omega_1: float,
) -> ShellParameters:
    """Dimensionless shell parameters of the composite (memo 3.0-1, 3.0-4 with erratum E3);
    ValueError naming a parameter that breaks its rule.

    Parameters
    ----------
    R1, R2 : float
        Radii of cylinder 1 (aft) and 2 (forward) (m), > 0.
    L1, L2 : float
        Half-lengths of cylinder 1 and 2 (m), > 0.
    h : float
        Shell thickness (m), 0 < h < min(R1, R2).
    E, nu, rho : float
        Young's modulus (Pa) > 0, Poisson's ratio in [0, 0.5), density (kg/m^3) > 0.
    omega_1 : float
        Reference frequency (rad/s), > 0 (4.2-8b).
    """
    for name, value in (("R1", R1), ("L1", L1), ("R2", R2), ("L2", L2), ("h", h), ("E", E),
                        ("rho", rho), ("omega_1", omega_1)):
        positive(name, value)
    if not (np.isfinite(nu) and 0.0 <= nu < 0.5):
        raise ValueError(f"nu = {nu!r}: must satisfy 0 <= nu < 0.5")
    if not h < min(R1, R2):
        raise ValueError(f"h = {h!r}: must be smaller than both radii ({R1!r}, {R2!r})")
    p = mass_properties(R1, L1, R2, L2, h, rho)
    L = p.L
    return ShellParameters(
        L=L, L1=float(L1), L2=float(L2), d1=p.d1, d2=p.d2, d3=p.d3, a=p.a, c=p.c, b=p.b,
        lam1=L / R1, lam2=L / R2,  # eq. (3.0-1): lambda = L / r
        sigma=h / L,  # eq. (3.0-1)
        mu=rho * L**2 * omega_1**2 / E,  # eq. (3.0-4a), erratum E3
        nu=float(nu), omega_1=float(omega_1),
    )


@dataclass(frozen=True)
class CylinderCoefficients:
    """Coefficients of eqs. (5.4-6) and (5.4-8) for one cylinder.

    Attributes
    ----------
    cylinder : int
        1 (aft) or 2 (forward).
    j, k : ndarray
        Axial indices, shape (M,), and circumferential indices (>= 1), shape (N,).
    j0, jk : dict of str to ndarray
        ``(a..m)_j0``, shape (M,), keyed by :data:`J0_NAMES`; ``(a..p)_jk``, shape (M, N), keyed
        by :data:`JK_NAMES`.
    source : str
        ``"memo"`` or ``"galerkin/<phase>/<delta>"``.
    """

    cylinder: int
    j: np.ndarray
    k: np.ndarray
    j0: dict = field(repr=False)
    jk: dict = field(repr=False)
    source: str = "memo"

    def matrices_j0(self) -> tuple[np.ndarray, np.ndarray]:
        """Mass and stiffness of eq. (5.4-6), shape (M, 2, 2), unknowns (U, W):
        M = [[a, b], [0, j]], K = [[c, d], [h, k]], M x'' + K x = P (6.2-5).
        """
        c = self.j0
        zero = np.zeros_like(c["a"])
        mass = np.stack([np.stack([c["a"], c["b"]], -1), np.stack([zero, c["j"]], -1)], -2)
        stiff = np.stack([np.stack([c["c"], c["d"]], -1), np.stack([c["h"], c["k"]], -1)], -2)
        return mass, stiff

    def matrices_jk(self) -> tuple[np.ndarray, np.ndarray]:
        """Mass and stiffness of eq. (5.4-8), shape (M, N, 3, 3), unknowns (U, V, W):
        M = [[a, b, c], [0, h, 0], [0, 0, n]], K = [[d, e, f], [g, j, k], [l, m, p]] (6.2-15).
        """
        c = self.jk
        zero = np.zeros_like(c["a"])
        mass = np.stack(
            [np.stack(r, -1) for r in ((c["a"], c["b"], c["c"]), (zero, c["h"], zero),
                                       (zero, zero, c["n"]))], -2)
        stiff = np.stack(
            [np.stack(r, -1) for r in ((c["d"], c["e"], c["f"]), (c["g"], c["j"], c["k"]),
                                       (c["l"], c["m"], c["p"]))], -2)
        return mass, stiff

    def to_dict(self) -> dict:
        """JSON-ready mapping (plain lists)."""
        return {
            "cylinder": self.cylinder,
            "source": self.source,
            "j": self.j.tolist(),
            "k": self.k.tolist(),
            "j0": {n: self.j0[n].tolist() for n in J0_NAMES},
            "jk": {n: self.jk[n].tolist() for n in JK_NAMES},
        }


def _indices(M: int, N: int) -> tuple[np.ndarray, np.ndarray]:
    for name, value in (("M", M), ("N", N)):
        if isinstance(value, bool) or not isinstance(value, int | np.integer) or value < 1:
            raise ValueError(f"{name} = {value!r}: must be an integer >= 1")
    return np.arange(1, M + 1, dtype=float), np.arange(1, N + 1, dtype=float)


def _check_cylinder(d: int) -> None:
    if d not in (1, 2):
        raise ValueError(f"d = {d!r}: must be 1 (aft cylinder) or 2 (forward cylinder)")


def edge_arguments(p: ShellParameters, d: int, j: np.ndarray, phase: str) -> tuple:
    """Shape-function arguments (s_aft, s_fwd) (rad) at the edges of cylinder ``d``;
    s_fwd - s_aft = j pi in both phases.

    Parameters
    ----------
    p : ShellParameters
        The shell parameters.
    d : int
        Cylinder, 1 or 2.
    j : ndarray
        Axial indices.
    phase : {"printed", "zero"}
        "printed": eqs. (5.3-2b..e), (5.3-3b..e) (erratum E10); "zero": 0 .. j pi.
    """
    _check_cylinder(d)
    if phase not in PHASES:
        raise ValueError(f"phase = {phase!r}: must be one of {PHASES}")
    if phase == "zero":
        return 0.0 * j, j * np.pi
    if d == 1:
        s_aft = j * np.pi / 2.0 * (p.d1 - p.d2) / p.L1  # eq. (5.3-2b) at xi_bar = a
    else:
        s_aft = j * np.pi / 2.0 * (2.0 * p.d1 - p.L1) / p.L2  # eq. (5.3-3b) at xi_bar = c
    return s_aft, s_aft + j * np.pi


# --------------------------------------------------------------------------------------------
# Appendix A as printed
# --------------------------------------------------------------------------------------------


def memo_coefficients(p: ShellParameters, d: int, M: int, N: int) -> CylinderCoefficients:
    """Appendix A coefficients as printed, j = 1..M, k = 1..N (``source = "memo"``).

    Term by term in the printed phase (E10). Kept as printed: E9 (lambda^4 in A-36), the sign
    of the k^3 term of A-17, L1 in A-33, the missing term of A-42, the half angles of A-44. Read
    as meant (OCR): "2 I_2" for 2 L2 in A-27/A-28, 1/(nu (1 - nu^2)) for 1/(mu (1 - nu^2)) in
    A-16. Every difference from :func:`galerkin_coefficients` is in docs/memo-errata.md.

    Parameters
    ----------
    p : ShellParameters
        Dimensionless parameters (:func:`shell_parameters`).
    d : int
        Cylinder: 1 (A-1..A-26) or 2 (A-27..A-52).
    M, N : int
        Largest axial and circumferential index, >= 1.
    """
    _check_cylinder(d)
    jj, kk = _indices(M, N)
    j = jj[:, None]
    k = kk[None, :]
    nu, mu, sg, L = p.nu, p.mu, p.sigma, p.L
    lam = p.lam(d)
    g0 = 1.0 / (mu * (1.0 - nu**2))
    nl = nu * lam  # nu L / R
    if d == 1:
        Ld = p.L1
        arg_aft = (p.d1 - p.d2) / p.L1
        arg_fwd = 2.0 * p.d1 / p.L1
        half = (p.c - p.a) / 2.0
        xa, xf = p.d2 / L, p.d1 / L  # the printed f, m brackets use +d2/L at the aft edge
    else:
        Ld = p.L2
        arg_aft = (2.0 * p.d1 - p.L1) / p.L2
        arg_fwd = (p.d1 + p.d3 - p.L1) / p.L2
        half = (p.b - p.c) / 2.0
        xa, xf = p.d1 / L, p.d3 / L
    q = j * np.pi * L / (2.0 * Ld)  # (j pi L / 2 L_d)
    r = 2.0 * Ld / (j * np.pi * L)  # (2 L_d / j pi L)
    s1a = np.sin(j * np.pi * arg_aft)  # full angles
    s1f = np.sin(j * np.pi * arg_fwd)
    sa, sf = np.sin(j * np.pi / 2 * arg_aft), np.sin(j * np.pi / 2 * arg_fwd)  # half angles
    ca, cf = np.cos(j * np.pi / 2 * arg_aft), np.cos(j * np.pi / 2 * arg_fwd)
    Icc = half + Ld / (2.0 * j * np.pi * L) * (s1f - s1a)
    Iss = half - Ld / (2.0 * j * np.pi * L) * (s1f - s1a)
    b3 = p.d3 / L
    c0: dict[str, np.ndarray] = {}
    ck: dict[str, np.ndarray] = {}
    if d == 1:
        shift = r * (sf - sa) * ((p.L1 / L - 1.0) * (ca - cf))
        c0["a"] = Icc + shift
        c0["b"] = nl * r**2 * (sf - sa) * (ca - cf)
        c0["c"] = g0 * q * (s1a + q * Icc)
        c0["d"] = nl * g0 * (0.5 * s1a + q * Icc)
        c0["e"] = r * (sf - sa)
        c0["f"] = r**2 * (cf + q * xf * sf - ca + q * xa * sa)
        Qf = p.d1 / L - b3 + 1.0
        Qa = -p.d2 / L - b3 + 1.0
        c0["g"] = (r * 0.5 * Qf**2 * sf + r**2 * Qf * cf - r**3 * sf
                   - r * 0.5 * Qa**2 * sa - r**2 * Qa * ca + r**3 * sa)
        c0["h"] = -nl * g0 * (0.5 * s1a - q * Iss)
        c0["j"] = Iss
        c0["k"] = g0 * ((sg**2 / 12 * q**4 + lam**2) * Iss
                        - sg**2 / 12 * q**3 * (2.0 * s1a))
        c0["l"] = r * b3 * (cf - ca)
        c0["m"] = r**2 * (sf - q * xf * cf - sa - q * xa * ca)
        ck["a"] = Icc + shift + 0.0 * k
        ck["b"] = nl * r**2 * k * (sf - sa) * (cf - ca)
        ck["c"] = nl * r**2 * (sf - sa) * (ca - cf) + 0.0 * k
        # printed 1/(nu (1 - nu^2)): OCR for mu
        ck["d"] = g0 * (q * (s1a + q * Icc) + (1 - nu) / 2 * lam**2 * k**2 * (Icc + shift))
        ck["e"] = g0 * ((1 - nu) / 2 * lam**2 * nl * r**2 * k**3 * (sf - sa) * (ca - cf)
                        - (1 + nu) / 2 * lam * k * (0.5 * s1a + q * Icc))
        ck["f"] = g0 * ((1 - nu) / 2 * lam**2 * nl * r**2 * k**2 * (sf - sa) * (ca - cf)
                        + nl * (0.5 * s1a + q * Icc))
        ck["g"] = lam * k / (2 * (1 - nu) * mu) * (0.5 * s1a - q * Iss)
        ck["h"] = Iss + 0.0 * k
        ck["j"] = g0 * (((1 - nu) / 2 * q**2 + lam**2 * k**2) * Iss
                        - (1 - nu) / 2 * q * s1a)
        ck["k"] = -lam**2 * k * g0 * Iss
        ck["l"] = nl * g0 * (q * Iss - 0.5 * s1a) + 0.0 * k
        ck["m"] = lam**2 * k * g0 * (p.L1 / (2 * j * np.pi * L) * (s1f - s1a) - half)
        ck["n"] = Iss + 0.0 * k
        ck["p"] = g0 * ((sg**2 / 12 * (lam**4 * k**4 + 2 * lam**2 * k**2 * q**2 + q**4)
                         + lam**2) * Iss
                        - sg**2 / 12 * 4 * q * (q**2 + lam**2 * k**2) * (0.5 * s1a))
    else:
        shift = r * (sf - sa) * ((p.L2 / L - 1.0) * (ca - cf))
        c0["a"] = Icc + shift  # "2 I_2" read as 2 L2
        c0["b"] = nl * r**2 * (sf - sa) * (ca - cf)
        c0["c"] = g0 * q * (s1a + q * Icc)
        c0["d"] = nl * g0 * (0.5 * s1a + q * Icc)
        c0["e"] = r * (sf - sa)
        c0["f"] = r**2 * (cf + q * xf * sf - ca - q * xa * sa)
        Qa = p.d1 / L - b3 + 1.0
        r_printed = 2.0 * p.L1 / (j * np.pi * L)  # prints 2 L1 in the fourth term
        c0["g"] = (r * 0.5 * 1.0**2 * sf + r**2 * 1.0 * cf - r**3 * sf
                   - r_printed * 0.5 * Qa**2 * sa - r**2 * Qa * ca + r**3 * sa)
        c0["h"] = -nl * g0 * (0.5 * s1a - q * Iss)
        c0["j"] = Iss
        c0["k"] = g0 * ((sg**2 / 12 * q**4 + lam**4) * Iss
                        - sg**2 / 12 * q**3 * (2.0 * s1a))  # as printed (E9: lambda^4)
        c0["l"] = r * b3 * (cf - ca)
        c0["m"] = r**2 * (sf - q * xf * cf - sa + q * xa * ca)
        ck["a"] = Icc + shift + 0.0 * k
        ck["b"] = nl * r**2 * k * (sf - sa) * (cf - ca)
        ck["c"] = nl * r**2 * (sf - sa) * (ca - cf) + 0.0 * k
        ck["d"] = g0 * ((q**2 + (1 - nu) / 2 * lam**2 * k**2) * Icc
                        + (1 - nu) / 2 * lam**2 * k**2 * shift)  # as printed
        ck["e"] = g0 * ((1 - nu) / 2 * lam**2 * nl * r**2 * k**3 * (sf - sa) * (cf - ca)
                        - (1 + nu) / 2 * lam * k * (0.5 * s1a + q * Icc))
        Icc_half = half + Ld / (2.0 * j * np.pi * L) * (sf - sa)  # half angles
        ck["f"] = g0 * ((1 - nu) / 2 * lam**2 * nl * r**2 * k**2 * (sf - sa) * (ca - cf)
                        + nl * (0.5 * s1a + q * Icc_half))  # as printed
        ck["g"] = lam * k / (2 * (1 - nu) * mu) * (0.5 * s1a - q * Iss)
        ck["h"] = Iss + 0.0 * k
        ck["j"] = g0 * (((1 - nu) / 2 * q**2 + lam**2 * k**2) * Iss
                        - (1 - nu) / 2 * q * s1a)
        ck["k"] = -lam**2 * k * g0 * Iss
        ck["l"] = nl * g0 * (q * Iss - 0.5 * s1a) + 0.0 * k
        ck["m"] = lam**2 * k * g0 * (p.L2 / (2 * j * np.pi * L) * (s1f - s1a) - half)
        ck["n"] = Iss + 0.0 * k
        ck["p"] = g0 * ((sg**2 / 12 * (lam**4 * k**4 + 2 * lam**2 * k**2 * q**2 + q**4)
                         + lam**2) * Iss
                        - sg**2 / 12 * 4 * q * (q**2 + lam**2 * k**2) * (0.5 * s1a))
    return CylinderCoefficients(
        cylinder=d, j=jj.astype(int), k=kk.astype(int),
        j0={n: _frozen(c0[n][:, 0]) for n in J0_NAMES},
        jk={n: _frozen(np.broadcast_to(ck[n], (M, N)).copy()) for n in JK_NAMES},
        source="memo",
    )


def _frozen(x: np.ndarray) -> np.ndarray:
    x = np.ascontiguousarray(x, dtype=float)
    x.setflags(write=False)
    return x


# --------------------------------------------------------------------------------------------
# The Galerkin integrals, by quadrature
# --------------------------------------------------------------------------------------------


def _quadrature_points(M: int, n_points: int | None) -> int:
    if n_points is None:
        # the integrands oscillate with total phase up to 2 M pi over the cylinder
        return int(np.ceil(2.0 * M)) + 48
    if isinstance(n_points, bool) or not isinstance(n_points, int | np.integer) or n_points < 8:
        raise ValueError(f"n_points = {n_points!r}: must be an integer >= 8")
    return int(n_points)


def galerkin_coefficients(
    p: ShellParameters,
    d: int,
    M: int,
    N: int,
    phase: str = "zero",
    delta: str = "one-sided",
    n_points: int | None = None,
) -> CylinderCoefficients:
    """Coefficients of eqs. (5.4-6/8) as the Galerkin integrals of 5.2-2..5.2-5, by quadrature.

    Trial functions (5.2-1 with the axial shift of 5.2-2/3, in the mass and the d^2/dtheta^2
    terms only): u = G f U + A_d [(L_d/L - 1) U - (nu lambda / alpha)(k V - W)] cos k theta,
    v = G g V, w = G h W, A_d = cos s_aft - cos s_fwd; test functions G f, G g, G h; the
    operators of 3.0-2 (Donnell, inward w). Stiffness = minus the integral of test x operator,
    mass = integral of test x trial, both over the theta integral; forcing e = int f,
    f = int xi f, g = int (xi - b + 1)^2 f / 2, l = -b int h, m = int xi h (5.4-7).
    Returns ``source = "galerkin/<phase>/<delta>"``.

    Parameters
    ----------
    p : ShellParameters
        Dimensionless parameters (:func:`shell_parameters`).
    d : int
        Cylinder, 1 or 2.
    M, N : int
        Largest axial and circumferential index, >= 1.
    phase : {"zero", "printed"}
        Shape-function phase (:func:`edge_arguments`).
    delta : {"one-sided", "symmetric", "none"}
        Treatment of the edge terms from G_d'.
    n_points : int, optional
        Gauss-Legendre points on the cylinder (default 2 M + 48).
    """
    _check_cylinder(d)
    if delta not in DELTA_CONVENTIONS:
        raise ValueError(f"delta = {delta!r}: must be one of {DELTA_CONVENTIONS}")
    jj, kk = _indices(M, N)
    n = _quadrature_points(M, n_points)
    w_aft, w_fwd = _DELTA_WEIGHTS[delta]
    nu, mu, sg, L = p.nu, p.mu, p.sigma, p.L
    lam = p.lam(d)
    Ld = p.half_length(d)
    xi_aft, xi_fwd = p.edges(d)
    s_aft, s_fwd = edge_arguments(p, d, jj, phase)
    alpha = jj * np.pi * L / (2.0 * Ld)  # d s / d xi_bar

    # Gauss-Legendre nodes on [xi_aft, xi_fwd]; s(xi) = s_aft + alpha (xi - xi_aft)
    t, w = roots_legendre(n)
    half = (xi_fwd - xi_aft) / 2.0
    xi = xi_aft + half * (t + 1.0)
    wq = w * half
    s = s_aft[:, None] + alpha[:, None] * (xi - xi_aft)[None, :]
    C, S = np.cos(s), np.sin(s)

    def quad(values: np.ndarray) -> np.ndarray:
        return values @ wq

    def edge(func: Callable[[np.ndarray], np.ndarray]) -> np.ndarray:  # G' point terms
        return w_aft * func(s_aft) + w_fwd * func(s_fwd)

    # test function x operator(trial) pieces (per unit amplitude, theta factors removed)
    Icc = quad(C * C)  # int f f
    Iss = quad(S * S)  # int h h = int g g
    If = quad(C)  # int f
    Ih = quad(S)  # int h
    # f (G f)'' = f [G f'' + 2 G' f'], f' = -alpha sin s, f'' = -alpha^2 cos s
    u_uxx = (quad(C * (-alpha[:, None] ** 2 * C))
             + 2.0 * edge(lambda x: np.cos(x) * -np.sin(x)) * alpha)
    # f (G g)' with g_theta -> k sin s: [G' h + G h'] per unit k
    u_vxt = edge(lambda x: np.cos(x) * np.sin(x)) + quad(C * (alpha[:, None] * C))
    u_wx = u_vxt  # f (G h)' has the same value
    # g (G f)' with f_theta -> -k cos s: -[G' f + G f'] per unit k, f' = -alpha sin s
    v_uxt = -(edge(lambda x: np.sin(x) * np.cos(x)) + quad(S * (-alpha[:, None] * S)))
    # g (G g)'' = g [G g'' + 2 G' g'], g' = alpha cos s
    v_vxx = (quad(S * (-alpha[:, None] ** 2 * S))
             + 2.0 * edge(lambda x: np.sin(x) * np.cos(x)) * alpha)
    w_ux = edge(lambda x: np.sin(x) * np.cos(x)) + quad(S * (-alpha[:, None] * S))
    w_wxx = v_vxx  # h (G h)'' (h has the xi-shape of g)
    # h (G h)'''' = h [G h'''' + 4 G' h'''], h''' = -alpha^3 cos s, h'''' = alpha^4 sin s
    w_wxxxx = (quad(S * (alpha[:, None] ** 4 * S))
               + 4.0 * edge(lambda x: np.sin(x) * -np.cos(x)) * alpha**3)
    A_d = np.cos(s_aft) - np.cos(s_fwd)  # A(theta)_d of eq. (5.2-3), theta factor removed
    chi = (Ld / L - 1.0) * A_d  # -A - (-1)^d (m pi/2) B, eq. (5.2-2)
    beta = -nu * lam * A_d / alpha  # (-1)^d (nu L/R) B, eq. (5.2-2)

    g0 = 1.0 / (mu * (1.0 - nu**2))
    col = (slice(None), None)
    j_ = {key: val[col] for key, val in dict(
        Icc=Icc, Iss=Iss, If=If, u_uxx=u_uxx, u_vxt=u_vxt, u_wx=u_wx, v_uxt=v_uxt,
        v_vxx=v_vxx, w_ux=w_ux, w_wxx=w_wxx, w_wxxxx=w_wxxxx, chi=chi, beta=beta).items()}

    def coefficients(k: np.ndarray, J: dict) -> dict[str, np.ndarray]:
        k2 = k**2
        mass_u = J["Icc"] + J["chi"] * J["If"]  # int f (f + chi)
        out = {
            "a": mass_u + 0.0 * k,  # mass, u row, U
            "b": J["beta"] * k * J["If"],  # mass, u row, V  (beta k V)
            "c": -J["beta"] * J["If"] + 0.0 * k,  # mass, u row, W  (-beta W)
            # u row stiffness: -[u'' + (1-nu) lam^2/2 u_tt + (1+nu) lam/2 v'_t - nu lam w']
            "d": -g0 * (J["u_uxx"] - (1 - nu) / 2 * lam**2 * k2 * mass_u),
            "e": -g0 * ((1 + nu) / 2 * lam * k * J["u_vxt"]
                        - (1 - nu) / 2 * lam**2 * k2 * J["beta"] * k * J["If"]),
            "f": -g0 * (-nu * lam * J["u_wx"]
                        + (1 - nu) / 2 * lam**2 * k2 * J["beta"] * J["If"]),
            # v row: (1+nu) lam/2 u'_t + (1-nu)/2 v'' + lam^2 v_tt - lam^2 w_t
            "g": -g0 * (1 + nu) / 2 * lam * k * J["v_uxt"],
            "h": J["Iss"] + 0.0 * k,
            "j": -g0 * ((1 - nu) / 2 * J["v_vxx"] - lam**2 * k2 * J["Iss"]),
            "k": -g0 * lam**2 * k * J["Iss"],  # -lam^2 w_t: w_t -> -k sin s sin k theta
            # w row: nu lam u' + lam^2 v_t - lam^2 w - sigma^2/12 Lap^4 w
            "l": -g0 * nu * lam * J["w_ux"] + 0.0 * k,
            "m": -g0 * lam**2 * k * J["Iss"],
            "n": J["Iss"] + 0.0 * k,
            "p": g0 * (lam**2 * J["Iss"] + sg**2 / 12 * (
                J["w_wxxxx"] - 2 * lam**2 * k2 * J["w_wxx"] + lam**4 * k2**2 * J["Iss"])),
        }
        return out

    ck = coefficients(kk[None, :], j_)
    c0_full = coefficients(np.zeros((1, 1)), j_)
    xq = xi[None, :]
    c0 = {
        "a": c0_full["a"], "b": c0_full["c"], "c": c0_full["d"], "d": c0_full["f"],
        "h": c0_full["l"], "j": c0_full["n"], "k": c0_full["p"],
        "e": If[:, None],  # int f
        "f": quad(xq * C)[:, None],  # int xi f
        "g": quad(0.5 * (xq - p.b + 1.0) ** 2 * C)[:, None],  # int (xi - b + 1)^2 f / 2
        "l": (-p.b * Ih)[:, None],  # -b int h
        "m": quad(xq * S)[:, None],  # int xi h
    }
    return CylinderCoefficients(
        cylinder=d, j=jj.astype(int), k=kk.astype(int),
        j0={name: _frozen(c0[name][:, 0]) for name in J0_NAMES},
        jk={name: _frozen(np.broadcast_to(ck[name], (M, N)).copy()) for name in JK_NAMES},
        source=f"galerkin/{phase}/{delta}",
    )


def overlap_matrices(
    p: ShellParameters, d: int, M: int, phase: str, n_points: int | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """Gram matrices int cos s_j cos s_j' and int sin s_j sin s_j' dxi_bar (M, M) of the axial
    shape functions on cylinder ``d``; the per-(j, k) decoupling (5.2-6, 5.3) needs them
    diagonal.

    Parameters
    ----------
    p : ShellParameters
        The shell parameters.
    d : int
        Cylinder, 1 or 2.
    M : int
        Largest axial index j (rows and columns j = 1..M).
    phase : {"printed", "zero"}
        Shape-function phase (:func:`edge_arguments`).
    n_points : int, optional
        Gauss-Legendre points (default 2 M + 48).
    """
    _check_cylinder(d)
    jj, _ = _indices(M, 1)
    n = _quadrature_points(M, n_points)
    xi_aft, xi_fwd = p.edges(d)
    s_aft, _ = edge_arguments(p, d, jj, phase)
    alpha = jj * np.pi * p.L / (2.0 * p.half_length(d))
    t, w = roots_legendre(n)
    half = (xi_fwd - xi_aft) / 2.0
    xi = xi_aft + half * (t + 1.0)
    s = s_aft[:, None] + alpha[:, None] * (xi - xi_aft)[None, :]
    C, S = np.cos(s), np.sin(s)
    wq = w * half
    return (C * wq) @ C.T, (S * wq) @ S.T
