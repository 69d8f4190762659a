"""Natural frequencies of the shell modes of the two cylinders (memo 5.4, 6.2, appendix D).

For each cylinder d (1 aft, 2 forward) the memo's modal equations give

* omega_0k (5.4-4): j = 0, k >= 1, a uniform axial (u = cos k theta) mode, one frequency;
* omega_j0^{1,2} (6.2-5..7, D-9, D-10): j >= 1, k = 0, the (U, W) system of 5.4-6;
* omega_jk^{1,2,3} (6.2-15..17, D-14..D-16): j, k >= 1, the (U, V, W) system of 5.4-8.

They are computed here as the eigenvalues of the generalized problems K x = omega_bar^2 M x
(:meth:`~flexbooster.memo.shell_coefficients.CylinderCoefficients.matrices_j0`, ``matrices_jk``),
all (d, j, k) stacked into one array and solved by one batched call of ``numpy.linalg``; the
memo's symmetric-function forms serve as tests.  Frequencies are dimensionless, in units of
omega_1 (4.2-8b); rad/s = omega_bar omega_1 and Hz = rad/s / (2 pi).  Each is labelled axial,
torsional (circumferential) or radial from the largest component of its eigenvector (U, V, W).

Methods (where the coefficients come from):

* ``"zero-phase"`` (default): the Galerkin integrals with the shape functions' argument 0 at
  each cylinder's aft edge.  They equal Donnell's shear-diaphragm coefficients of each
  cylinder alone (appendix D-II with L_d for L), so the composite frequencies are those of the
  isolated cylinders; see ``docs/theory/shell.md`` for why this is the consistent default.
* ``"galerkin"``: the Galerkin integrals of the printed phase (5.3-2/3, erratum E10) with the
  memo's one-sided edge terms: appendix A with its errata corrected.
* ``"memo"``: appendix A as printed (memo-literal), errata included.

References
----------
.. [1] Tech Memo 104, sections 5.4, 6.2 and appendix D.
.. [2] A. W. Leissa, *Vibration of Shells*, NASA SP-288, 1973, sec. 2.1-2.3 (Donnell-Mushtari
   theory, shear-diaphragm edges: frequency determinant eq. 2.20 and its cubic, eqs. 2.21-2.22).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from ..checks import count
from .shell_coefficients import (
    CylinderCoefficients,
    ShellParameters,
    galerkin_coefficients,
    memo_coefficients,
    shell_parameters,
)

if TYPE_CHECKING:
    from .model import BoosterModel

__all__ = [
    "METHODS",
    "MODE_TYPES",
    "MAX_COUNT",
    "ShellFrequencies",
    "natural_frequencies",
    "composite_frequencies",
    "cylinder_coefficients",
    "generalized_eigen",
]

#: Sources of the modal coefficients, see the module docstring.
METHODS = ("zero-phase", "galerkin", "memo")
#: Mode types, indexed by the dominant component U, V, W.
MODE_TYPES = ("axial", "torsional", "radial")
#: Largest mode count per index accepted by the public functions.
MAX_COUNT = 500


@dataclass(frozen=True)
class ShellFrequencies:
    """Table of shell natural frequencies, one row per (cylinder, j, k, branch).

    Attributes
    ----------
    cylinder : ndarray of int
        1 (aft) or 2 (forward).
    j, k : ndarray of int
        Axial and circumferential indices (j = 0 rows are omega_0k).
    branch : ndarray of int
        m = 1, 2, 3 in ascending frequency within (cylinder, j, k).
    omega_bar : ndarray of float
        Frequency in units of omega_1.
    rad_s : ndarray of float
        Circular frequency (rad/s).
    hz : ndarray of float
        Frequency (Hz).
    mode_type : ndarray of str
        ``"axial"``, ``"torsional"`` or ``"radial"``.
    method : str
        Source of the coefficients (:data:`METHODS`).
    omega_1 : float
        Reference frequency (rad/s).
    excluded : dict of str to ndarray
        Modes whose modal system has no real positive omega^2 (possible only for the
        non-symmetric printed-phase systems, ``"galerkin"`` and ``"memo"``): parallel arrays
        ``cylinder, j, k, branch, omega_sq_real, omega_sq_imag`` (omega_bar^2, units of
        omega_1^2).  Empty for ``"zero-phase"``.
    """

    cylinder: np.ndarray
    j: np.ndarray
    k: np.ndarray
    branch: np.ndarray
    omega_bar: np.ndarray
    rad_s: np.ndarray
    hz: np.ndarray
    mode_type: np.ndarray
    method: str
    omega_1: float
    excluded: dict = field(default_factory=dict, repr=False)

    def __len__(self) -> int:
        return int(self.cylinder.size)

    def to_dict(self) -> dict:
        """JSON-ready mapping of parallel lists (plus ``method`` and ``omega_1``)."""
        return {
            "method": self.method,
            "omega_1": float(self.omega_1),
            "columns": ["cylinder", "j", "k", "branch", "omega_bar", "rad_s", "hz", "mode_type"],
            "cylinder": self.cylinder.tolist(),
            "j": self.j.tolist(),
            "k": self.k.tolist(),
            "branch": self.branch.tolist(),
            "omega_bar": self.omega_bar.tolist(),
            "rad_s": self.rad_s.tolist(),
            "hz": self.hz.tolist(),
            "mode_type": self.mode_type.tolist(),
            "excluded": {key: np.asarray(val).tolist() for key, val in self.excluded.items()},
        }

    def to_rows(self) -> list[dict]:
        """One dict per row (for CSV), keys as in :meth:`to_dict` ``columns``."""
        cols = zip(self.cylinder.tolist(), self.j.tolist(), self.k.tolist(),
                   self.branch.tolist(), self.omega_bar.tolist(), self.rad_s.tolist(),
                   self.hz.tolist(), self.mode_type.tolist(), strict=True)
        names = ("cylinder", "j", "k", "branch", "omega_bar", "rad_s", "hz", "mode_type")
        return [dict(zip(names, row, strict=True)) for row in cols]

    def select(self, cylinder: int | None = None, j: int | None = None,
               k: int | None = None, branch: int | None = None) -> np.ndarray:
        """Boolean mask of the rows that match the given indices (``None`` matches all)."""
        mask = np.ones(len(self), dtype=bool)
        for arr, val in ((self.cylinder, cylinder), (self.j, j), (self.k, k),
                         (self.branch, branch)):
            if val is not None:
                mask &= arr == val
        return mask


def _check_count(name: str, value: int) -> int:
    return count(name, value, 1, MAX_COUNT)


def _check_method(method: str) -> None:
    if method not in METHODS:
        raise ValueError(f"method = {method!r}: must be one of {METHODS}")


def generalized_eigen(
    mass: np.ndarray, stiff: np.ndarray, symmetric: bool = False
) -> tuple[np.ndarray, np.ndarray]:
    """Batched eigenvalues omega^2 and eigenvectors of K x = omega^2 M x.

    Parameters
    ----------
    mass, stiff : ndarray, shape (..., n, n)
        Mass and stiffness matrices (dimensionless), M invertible.
    symmetric : bool
        If true, M is taken as its diagonal D (positive) and K as its symmetric part, and the
        problem is solved as the symmetric D^-1/2 K D^-1/2 y = omega^2 y (``eigh``: real
        eigenvalues by construction).  For the zero-phase systems, whose off-diagonal mass
        terms are quadrature zeros (|.| < 1e-15) and whose K is symmetric.

    Returns
    -------
    omega_sq : ndarray of complex, shape (..., n)
        Eigenvalues of M^-1 K, ordered by ascending real part along the last axis.
    vectors : ndarray of float, shape (..., n, n)
        Moduli of the matching eigenvector components (columns), each column scaled to unit
        maximum, for classifying the mode.

    Notes
    -----
    One ``numpy.linalg.solve`` and one ``numpy.linalg.eig`` over the stacked systems
    (memo 6.2-5 and 6.2-15: Delta(s) = det(M s^2 + K) = 0 at s^2 = -omega^2).  For the
    symmetric zero-phase systems the eigenvalues are real and positive; the printed-phase
    systems are not symmetric and may have complex or negative omega^2 (see
    :func:`composite_frequencies`).
    """
    mass, stiff = np.asarray(mass, dtype=float), np.asarray(stiff, dtype=float)
    for name, mat in (("mass", mass), ("stiff", stiff)):
        if mat.ndim < 2 or mat.shape[-1] != mat.shape[-2] or mat.shape != mass.shape:
            raise ValueError(f"{name}: shape {mat.shape}: must be square (..., n, n) and "
                             "match the other matrix")
        if not np.all(np.isfinite(mat)):
            raise ValueError(f"{name}: every entry must be finite")
    if symmetric:
        dm = np.sqrt(np.diagonal(mass, axis1=-2, axis2=-1))
        ks = 0.5 * (stiff + np.swapaxes(stiff, -1, -2))
        lam, vec = np.linalg.eigh(ks / dm[..., :, None] / dm[..., None, :])
        vec = vec / dm[..., :, None]  # x = D^-1/2 y
        vec = np.abs(vec) / np.max(np.abs(vec), axis=-2, keepdims=True)
        return lam.astype(complex), vec
    a = np.linalg.solve(mass, stiff)  # M^-1 K, batched
    lam, vec = np.linalg.eig(a)
    order = np.argsort(lam.real, axis=-1, kind="stable")
    lam = np.take_along_axis(lam, order, axis=-1)
    vec = np.abs(np.take_along_axis(vec, order[..., None, :], axis=-1))
    vec = vec / np.max(vec, axis=-2, keepdims=True)
    return lam.astype(complex), vec


def _real_positive(omega_sq: np.ndarray) -> np.ndarray:
    """Mask of eigenvalues that are real (|Im| <= 1e-9 max |lambda|) and positive."""
    scale = np.max(np.abs(omega_sq), axis=-1, keepdims=True)
    return (np.abs(omega_sq.imag) <= 1e-9 * scale) & (omega_sq.real > 0.0) & np.isfinite(
        omega_sq.real)


def cylinder_coefficients(p: ShellParameters, d: int, M: int, N: int,
                          method: str = "zero-phase") -> CylinderCoefficients:
    """Coefficients of cylinder ``d`` for a frequency ``method``.

    Parameters
    ----------
    p : ShellParameters
    d : int
        Cylinder, 1 or 2.
    M, N : int
        Largest j and k.
    method : {"zero-phase", "galerkin", "memo"}

    Returns
    -------
    CylinderCoefficients

    References
    ----------
    Tech Memo 104, appendix A; :mod:`flexbooster.memo.shell_coefficients`.
    """
    _check_method(method)
    if method == "memo":
        return memo_coefficients(p, d, M, N)
    phase = "zero" if method == "zero-phase" else "printed"
    return galerkin_coefficients(p, d, M, N, phase=phase, delta="one-sided")


def composite_frequencies(
    R1: float, L1: float, R2: float, L2: float, h: float, E: float, nu: float, rho: float,
    omega_1: float, M1: int, N1: int, M2: int, N2: int, method: str = "zero-phase",
) -> ShellFrequencies:
    """Shell natural frequencies of both cylinders from primitive arguments.

    Parameters
    ----------
    R1, R2 : float
        Radii of cylinder 1 (aft) and 2 (forward) (m).
    L1, L2 : float
        Half-lengths (m).
    h : float
        Thickness (m).
    E : float
        Young's modulus (Pa).
    nu : float
        Poisson's ratio.
    rho : float
        Density (kg/m^3).
    omega_1 : float
        Reference frequency (rad/s), memo 4.2-8b.
    M1, N1, M2, N2 : int
        Largest j and k of cylinder 1 and 2, 1..500.
    method : {"zero-phase", "galerkin", "memo"}
        Source of the modal coefficients (module docstring).

    Returns
    -------
    ShellFrequencies
        Rows ordered by cylinder, then omega_0k (k = 1..N), omega_j0 (j = 1..M, 2 branches),
        omega_jk (j-major, 3 branches).

    Raises
    ------
    ValueError
        Bad parameter (the message names it).

    Notes
    -----
    omega_0k^2 = lambda_d^2 k^2 / (2 (1 + nu) mu) (5.4-4) is the 1x1 case K/M.  The 2x2 and
    3x3 problems of all (d, j, k) are solved in one batched call (:func:`generalized_eigen`).
    A mode whose omega^2 is complex or not positive (the printed-phase systems are not
    symmetric) has no natural frequency: it goes to ``excluded``, never into the table.

    References
    ----------
    Tech Memo 104, eqs. (5.4-4), (6.2-5)..(6.2-7), (6.2-15)..(6.2-17), (D-9)..(D-20).
    """
    counts = [_check_count(n, v) for n, v in (("M1", M1), ("N1", N1), ("M2", M2), ("N2", N2))]
    _check_method(method)
    p = shell_parameters(R1, L1, R2, L2, h, E, nu, rho, omega_1)
    blocks = []
    m2, k2, m3, k3 = [], [], [], []
    for d, (M, N) in ((1, counts[:2]), (2, counts[2:])):
        coef = cylinder_coefficients(p, d, M, N, method)
        a, b = coef.matrices_j0()
        m2.append(a)
        k2.append(b)
        a, b = coef.matrices_jk()
        m3.append(a.reshape(-1, 3, 3))
        k3.append(b.reshape(-1, 3, 3))
        blocks.append((d, M, N))
    sym = method == "zero-phase"
    w2, v2 = generalized_eigen(np.concatenate(m2), np.concatenate(k2), sym)
    w3, v3 = generalized_eigen(np.concatenate(m3), np.concatenate(k3), sym)
    type2 = np.array([0, 2])[np.argmax(v2, axis=-2)]  # (U, W) -> axial, radial
    type3 = np.argmax(v3, axis=-2)  # (U, V, W) -> axial, torsional, radial
    ok2 = _real_positive(w2)
    ok3 = _real_positive(w3)

    cyl, jj, kk, br, om2, typ, ok = [], [], [], [], [], [], []
    o2 = o3 = 0
    for d, M, N in blocks:
        lam = p.lam(d)
        k = np.arange(1, N + 1)
        cyl.append(np.full(N, d))
        jj.append(np.zeros(N, int))
        kk.append(k)
        br.append(np.ones(N, int))
        om2.append((lam**2 * k**2 / (2.0 * (1.0 + p.nu) * p.mu)).astype(complex))  # (5.4-4)
        typ.append(np.zeros(N, int))
        ok.append(np.ones(N, bool))
        j = np.arange(1, M + 1)
        cyl.append(np.full(2 * M, d))
        jj.append(np.repeat(j, 2))
        kk.append(np.zeros(2 * M, int))
        br.append(np.tile([1, 2], M))
        om2.append(w2[o2:o2 + M].ravel())
        typ.append(type2[o2:o2 + M].ravel())
        ok.append(ok2[o2:o2 + M].ravel())
        o2 += M
        jg, kg = np.meshgrid(j, k, indexing="ij")
        cyl.append(np.full(3 * M * N, d))
        jj.append(np.repeat(jg.ravel(), 3))
        kk.append(np.repeat(kg.ravel(), 3))
        br.append(np.tile([1, 2, 3], M * N))
        om2.append(w3[o3:o3 + M * N].ravel())
        typ.append(type3[o3:o3 + M * N].ravel())
        ok.append(ok3[o3:o3 + M * N].ravel())
        o3 += M * N
    cyl_a, j_a, k_a, br_a = (np.concatenate(x).astype(int) for x in (cyl, jj, kk, br))
    om2_a, typ_a, ok_a = np.concatenate(om2), np.concatenate(typ), np.concatenate(ok)
    omega_bar = np.sqrt(om2_a.real[ok_a])
    rad_s = omega_bar * p.omega_1
    bad = ~ok_a
    return ShellFrequencies(
        cylinder=cyl_a[ok_a],
        j=j_a[ok_a],
        k=k_a[ok_a],
        branch=br_a[ok_a],
        omega_bar=omega_bar,
        rad_s=rad_s,
        hz=rad_s / (2.0 * np.pi),
        mode_type=np.asarray(MODE_TYPES)[typ_a[ok_a]],
        method=method,
        omega_1=float(p.omega_1),
        excluded={"cylinder": cyl_a[bad], "j": j_a[bad], "k": k_a[bad], "branch": br_a[bad],
                  "omega_sq_real": om2_a.real[bad], "omega_sq_imag": om2_a.imag[bad]},
    )


def natural_frequencies(model: BoosterModel, *, method: str = "zero-phase") -> ShellFrequencies:
    """Shell natural frequencies of the booster's two cylinders.

    Parameters
    ----------
    model : BoosterModel
        The derived model: shell parameters (R_d, L_d (m), h (m), E (Pa), nu, rho (kg/m^3)),
        omega_1 (rad/s, eq. 4.2-8b) and the truncation M1, N1, M2, N2.
    method : {"zero-phase", "galerkin", "memo"}
        Source of the modal coefficients; ``"zero-phase"`` is the pipeline default.

    Returns
    -------
    ShellFrequencies

    References
    ----------
    Tech Memo 104, sections 5.4, 6.2, appendix D.
    """
    t = model.truncation
    return composite_frequencies(model.R1, model.L1, model.R2, model.L2, model.h, model.E,
                                 model.nu, model.rho, model.omega_1, t.M1, t.N1, t.M2, t.N2,
                                 method)
