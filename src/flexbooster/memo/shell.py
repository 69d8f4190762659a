"""Natural frequencies of the shell modes of the two cylinders (memo 5.4, 6.2, appendix D).

omega_0k (5.4-4, j = 0), omega_j0^{1,2} (6.2-5..7, k = 0) and omega_jk^{1,2,3} (6.2-15..17)
as the eigenvalues of K x = omega_bar^2 M x, all (d, j, k) in one batched call, in units of
omega_1, each labelled axial, torsional or radial by its largest component. Methods:
"zero-phase" (default; equals Donnell's shear-diaphragm cylinders), "galerkin" (printed
phase, errata corrected), "memo" (appendix A as printed). Theory: docs/theory/shell.md.

References: Tech Memo 104, sec. 5.4, 6.2, appendix D; A. W. Leissa, *Vibration of Shells*,
NASA SP-288, 1973, sec. 2.1-2.3.
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
    cylinder, j, k, branch : ndarray of int
        Cylinder 1 (aft) or 2, axial and circumferential indices (j = 0: omega_0k), branch
        m = 1..3 ascending.
    omega_bar, rad_s, hz : ndarray of float
        Frequency in units of omega_1, rad/s and Hz.
    mode_type : ndarray of str
        ``"axial"``, ``"torsional"`` or ``"radial"``.
    method : str
        Source of the coefficients (:data:`METHODS`).
    omega_1 : float
        Reference frequency (rad/s).
    excluded : dict of str to ndarray
        Modes without a real positive omega^2 (printed-phase methods only): parallel arrays
        ``cylinder, j, k, branch, omega_sq_real, omega_sq_imag`` (units of omega_1^2).
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
    """Batched eigenvalues omega^2 (complex, ascending real part) and eigenvector component
    moduli (columns scaled to unit maximum) of K x = omega^2 M x (memo 6.2-5, 6.2-15).

    Parameters
    ----------
    mass, stiff : ndarray, shape (..., n, n)
        Mass and stiffness matrices, M invertible.
    symmetric : bool
        Take M as its diagonal and K as its symmetric part and solve D^-1/2 K D^-1/2 with
        ``eigh`` (the zero-phase systems).
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
    """Coefficients of cylinder ``d`` for a frequency ``method`` (memo appendix A).

    Parameters
    ----------
    p : ShellParameters
        The shell parameters.
    d : int
        Cylinder, 1 or 2.
    M, N : int
        Largest j and k.
    method : {"zero-phase", "galerkin", "memo"}
        The source of the coefficients.
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
    """Shell natural frequencies of both cylinders from primitive arguments; rows by cylinder,
    then omega_0k, omega_j0 (2 branches), omega_jk (j-major, 3 branches). A mode with complex or
    non-positive omega^2 goes to ``excluded``. Memo (5.4-4), (6.2-5..7), (6.2-15..17), (D-9..D-20).

    Parameters
    ----------
    R1, R2 : float
        Radii of cylinder 1 (aft) and 2 (forward) (m).
    L1, L2 : float
        Half-lengths (m).
    h : float
        Thickness (m).
    E, nu, rho : float
        Young's modulus (Pa), Poisson's ratio, density (kg/m^3).
    omega_1 : float
        Reference frequency (rad/s), memo 4.2-8b.
    M1, N1, M2, N2 : int
        Largest j and k of cylinder 1 and 2, 1..500.
    method : {"zero-phase", "galerkin", "memo"}
        Source of the modal coefficients.
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
    """Shell natural frequencies of the booster's two cylinders (memo 5.4, 6.2, appendix D).

    Parameters
    ----------
    model : BoosterModel
        The derived model: shell parameters, omega_1 and the truncation M1, N1, M2, N2.
    method : {"zero-phase", "galerkin", "memo"}
        Source of the modal coefficients.
    """
    t = model.truncation
    return composite_frequencies(model.R1, model.L1, model.R2, model.L2, model.h, model.E,
                                 model.nu, model.rho, model.omega_1, t.M1, t.N1, t.M2, t.N2,
                                 method)
