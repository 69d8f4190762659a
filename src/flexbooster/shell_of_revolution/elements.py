"""Conical frustum shell elements for one Fourier harmonic k (Sanders-Koiter or Donnell).

A straight piece of meridian at the angle phi with u = U cos k theta, v = V sin k theta,
w = W cos k theta; U, V C0 Lagrange of degree p on the GLL points, W C1 (w, dw/ds at the
ends, p - 3 interior GLL values). DOF order: end 1 (u, v, w, dw/ds), end 2, interior u, v, w.
Strains of a cone (Kraus 1967 ch. 2, Sanders 1959; c = 1 Sanders, 0 Donnell), the
constitutive law A, D (Kraus ch. 3), consistent mass rho h (U^2 + V^2 + W^2), and the
geometric stiffness of the membrane prestress (Brush & Almroth 1975 ch. 5); the theta
integral gives pi (k >= 1) or 2 pi (k = 0). Equations: docs/theory/shell-of-revolution.md.

References: H. Kraus, *Thin Elastic Shells*, 1967, ch. 2-3; J. L. Sanders, NASA TR R-24,
1959; D. O. Brush, B. O. Almroth, *Buckling of Bars, Plates and Shells*, 1975, ch. 5;
O. C. Zienkiewicz, R. L. Taylor, *The Finite Element Method*, vol. 2, 2000, ch. 10.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np
from numpy.polynomial import legendre as leg

from ..checks import count

__all__ = ["ElementFields", "ReferenceElement", "element_energies", "element_fields",
           "field_matrices", "geometric_matrices", "reference_element",
           "theta_weight"]


@lru_cache(maxsize=64)
def _path(subscripts: str, *shapes: tuple) -> list:
    """The contraction order ``np.einsum(..., optimize=True)`` chooses, found once per shapes."""
    return np.einsum_path(subscripts, *(np.empty(s) for s in shapes), optimize=True)[0]


def einsum(subscripts: str, *operands: np.ndarray) -> np.ndarray:
    """``np.einsum(subscripts, *operands, optimize=True)`` with the contraction order cached (the
    same contractions in the same order: the same result).
    """
    return np.einsum(subscripts, *operands,
                     optimize=_path(subscripts, *(np.shape(a) for a in operands)))


@dataclass(frozen=True)
class ReferenceElement:
    """Shape functions of order p on xi in [-1, 1] at the Gauss points (read-only arrays).

    Attributes
    ----------
    order, n_dof : int
        Polynomial degree p >= 3 and DOFs per element, 3 (p + 1).
    xi, weight : ndarray, shape (g,)
        Gauss-Legendre points and weights.
    nuv, duv : ndarray, shape (g, p + 1)
        U/V shape functions and d/dxi.
    nw, dw, d2w : ndarray, shape (g, p + 1)
        W shape functions and d/dxi, d^2/dxi^2 (slope DOFs in units of dw/dxi).
    iu, iv, iw : ndarray of int, shape (p + 1,)
        Positions of the U, V, W coefficients in the element DOF vector.
    slope : ndarray of int, shape (2,)
        Positions (within ``iw``) of the two slope DOFs.
    xi_nodes_uv, xi_nodes_w : ndarray
        Reference points of the U/V and of the interior W DOFs.
    """

    order: int
    n_dof: int
    xi: np.ndarray
    weight: np.ndarray
    nuv: np.ndarray
    duv: np.ndarray
    nw: np.ndarray
    dw: np.ndarray
    d2w: np.ndarray
    iu: np.ndarray
    iv: np.ndarray
    iw: np.ndarray
    slope: np.ndarray
    xi_nodes_uv: np.ndarray
    xi_nodes_w: np.ndarray

    def evaluate(self, xi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """U/V and W shape functions at arbitrary points ``xi`` (slopes in d/dxi units)."""
        xi = np.asarray(xi, dtype=float)
        cuv, cw = _coefficients(self.order)
        return leg.legvander(xi, self.order) @ cuv, leg.legvander(xi, self.order) @ cw


def _gll(p: int) -> np.ndarray:
    """Gauss-Lobatto-Legendre points of degree p (p + 1 points, ascending)."""
    inner = np.sort(leg.Legendre.basis(p).deriv().roots().real) if p >= 2 else np.empty(0)
    return np.concatenate(([-1.0], inner, [1.0]))


@lru_cache(maxsize=16)
def _coefficients(p: int) -> tuple[np.ndarray, np.ndarray]:
    """Legendre coefficients (p + 1, p + 1) of the U/V and W bases (columns)."""
    x_uv = _gll(p)
    cuv = np.linalg.inv(leg.legvander(x_uv, p))  # Lagrange at the GLL points
    x_w = _gll(p - 2)[1:-1]
    vd = leg.legvander(np.array([-1.0, 1.0]), p)
    dcoef = leg.legder(np.eye(p + 1), axis=0)  # rows: derivative coefficients of P_j
    dv = leg.legvander(np.array([-1.0, 1.0]), p - 1) @ dcoef
    rows = [vd[0], dv[0], vd[1], dv[1]] + list(leg.legvander(x_w, p))
    cw = np.linalg.inv(np.array(rows))  # functionals: w(-1), w'(-1), w(1), w'(1), w(x_w)
    cuv.setflags(write=False)
    cw.setflags(write=False)
    return cuv, cw


@lru_cache(maxsize=16)
def reference_element(order: int) -> ReferenceElement:
    """Shape functions and quadrature of the order-p element (cached, read-only; Canuto et al. 2006
    sec. 2.3; Zienkiewicz & Taylor vol. 1, sec. 8.5).

    Parameters
    ----------
    order : int
        Polynomial degree p of U, V and W, 3 <= p <= 12.
    """
    p = int(order)
    if not 3 <= p <= 12:
        raise ValueError(f"order = {order!r}: must be an integer in 3..12")
    cuv, cw = _coefficients(p)
    xi, wt = leg.leggauss(p + 3)  # exact for the polynomial (cylinder) integrands of degree 2p
    vand = leg.legvander(xi, p)
    d1 = leg.legder(np.eye(p + 1), axis=0)
    d2 = leg.legder(np.eye(p + 1), m=2, axis=0)
    nuv = vand @ cuv
    duv = leg.legvander(xi, p - 1) @ (d1 @ cuv)
    nw = vand @ cw
    dw = leg.legvander(xi, p - 1) @ (d1 @ cw)
    d2w = leg.legvander(xi, p - 2) @ (d2 @ cw)
    # DOF positions: end 1 (u, v, w, w'), end 2 (u, v, w, w'), interior u, v, w
    ni = p - 1
    iu = np.concatenate(([0], 8 + np.arange(ni), [4]))
    iv = np.concatenate(([1], 8 + ni + np.arange(ni), [5]))
    iw = np.concatenate(([2, 3, 6, 7], 8 + 2 * ni + np.arange(p - 3)))
    arrays = dict(xi=xi, weight=wt, nuv=nuv, duv=duv, nw=nw, dw=dw, d2w=d2w, iu=iu, iv=iv,
                  iw=iw, slope=np.array([1, 3]), xi_nodes_uv=_gll(p),
                  xi_nodes_w=_gll(p - 2)[1:-1])
    for val in arrays.values():
        val.setflags(write=False)
    return ReferenceElement(order=p, n_dof=3 * (p + 1), **arrays)


def theta_weight(k: int) -> float:
    """Integral over theta of cos^2 k theta: pi for k >= 1, 2 pi for k = 0.

    Parameters
    ----------
    k : int
        Circumferential harmonic (>= 0).
    """
    return 2.0 * np.pi if count("k", k, 0, None) == 0 else np.pi


def _operators(ref: ReferenceElement, length: np.ndarray):
    """U, V, W values and s-derivatives at the Gauss points, shape (e, g, n_dof) each."""
    ne = length.size
    jac = 0.5 * length[:, None, None]  # ds/dxi
    nd = ref.n_dof
    shape = (ne, ref.xi.size, nd)
    U, dU, V, dV, W, dW, d2W = (np.zeros(shape) for _ in range(7))
    U[:, :, ref.iu] = ref.nuv
    dU[:, :, ref.iu] = ref.duv / jac
    V[:, :, ref.iv] = ref.nuv
    dV[:, :, ref.iv] = ref.duv / jac
    scale = np.ones((ne, 1, ref.iw.size))
    scale[:, :, ref.slope] = jac  # slope DOFs are dw/ds: w = ... + (l/2) (dw/ds) N_xi
    W[:, :, ref.iw] = ref.nw * scale
    dW[:, :, ref.iw] = ref.dw * scale / jac
    d2W[:, :, ref.iw] = ref.d2w * scale / jac**2
    return U, dU, V, dV, W, dW, d2W


@dataclass(frozen=True)
class ElementFields:
    """Strain, rotation and displacement operators of all elements at the Gauss points.

    Attributes
    ----------
    strains : ndarray, shape (e, g, 6, n_dof)
        (eps_s, eps_theta, gamma, kappa_s, kappa_theta, tau) of each element DOF.
    material : ndarray, shape (e, 6, 6)
        Constitutive matrix diag(A, D) (N/m, N m).
    displacement : ndarray, shape (e, g, 3, n_dof)
        (U, V, W).
    meridional_rotation, hoop_rotation : ndarray, shape (e, g, 2, n_dof)
        (beta_s, c Phi) and (beta_theta, c Phi): the rotations of the geometric stiffness.
    volume : ndarray, shape (e, g)
        Quadrature weight times theta weight times r ds (m^2).
    """

    strains: np.ndarray
    material: np.ndarray
    displacement: np.ndarray
    meridional_rotation: np.ndarray
    hoop_rotation: np.ndarray
    volume: np.ndarray


def element_fields(
    ref: ReferenceElement,
    k: int,
    *,
    r1: np.ndarray,
    length: np.ndarray,
    sin_phi: np.ndarray,
    cos_phi: np.ndarray,
    thickness: np.ndarray,
    E: np.ndarray,
    nu: np.ndarray,
    theory: str = "sanders",
    stiffening: np.ndarray | None = None,
) -> ElementFields:
    """The operators of :func:`field_matrices` and :func:`geometric_matrices` (Sanders or
    Donnell).

    Parameters
    ----------
    ref : ReferenceElement
        Shape functions (:func:`reference_element`).
    k : int
        Circumferential wave number, >= 0.
    r1, length : ndarray, shape (e,)
        Radius at the aft end (m, > 0 along the element) and meridian length (m, > 0).
    sin_phi, cos_phi : ndarray, shape (e,)
        Meridian angle of each element: dr/ds and dx/ds.
    thickness, E, nu : ndarray, shape (e,)
        Wall thickness (m), Young's modulus (Pa), Poisson's ratio.
    theory : str
        ``"sanders"`` or ``"donnell"``.
    stiffening : ndarray, shape (e, 6, 6), optional
        Added to the constitutive matrix (smeared stiffeners, Baruch-Singer 1963).
    """
    c = 1.0 if theory == "sanders" else 0.0
    U, dU, V, dV, W, dW, d2W = _operators(ref, length)
    jac = 0.5 * length[:, None]
    r = r1[:, None] + (1.0 + ref.xi[None, :]) * jac * sin_phi[:, None]  # r = r1 + s sin(phi)
    sa = sin_phi[:, None, None]
    ca = cos_phi[:, None, None]
    rr = r[:, :, None]
    B = (c * ca * V + k * W) / rr  # beta_theta amplitude (Kraus ch. 2, Sanders)
    dB = (c * ca * dV + k * dW) / rr - B * sa / rr  # d/ds of B, r' = sin(phi)
    phi_n = 0.5 * (dV + V * sa / rr + k * U / rr)  # rotation about the normal (Sanders)
    strains = np.stack([
        dU,  # eps_s = u'
        (k * V + U * sa + W * ca) / rr,  # eps_theta = (v_theta + u sin + w cos) / r
        dV - V * sa / rr - k * U / rr,  # gamma = r (v/r)' + u_theta / r
        -d2W,  # kappa_s = beta_s', beta_s = -w'
        (k * B - dW * sa) / rr,  # kappa_theta = (beta_theta,theta + beta_s sin) / r
        dB - B * sa / rr + k * dW / rr + c * (ca / rr) * phi_n,  # Sanders twist 2 kappa_st
    ], axis=2)  # (e, g, 6, n_dof)
    a = E * thickness / (1.0 - nu**2)
    d = E * thickness**3 / (12.0 * (1.0 - nu**2))
    mat = np.zeros((length.size, 6, 6))
    for off, val in ((0, a), (3, d)):  # Kraus ch. 3: N = A eps, M = D kappa
        mat[:, off, off] = mat[:, off + 1, off + 1] = val
        mat[:, off, off + 1] = mat[:, off + 1, off] = nu * val
        mat[:, off + 2, off + 2] = 0.5 * (1.0 - nu) * val
    if stiffening is not None:
        mat = mat + stiffening
    return ElementFields(
        strains=strains, material=mat, displacement=np.stack([U, V, W], axis=2),
        meridional_rotation=np.stack([-dW, c * phi_n], axis=2),  # beta_s, Phi (Sanders)
        hoop_rotation=np.stack([B, c * phi_n], axis=2),  # beta_theta, Phi
        volume=theta_weight(k) * ref.weight[None, :] * jac * r)  # theta weight * r ds


def field_matrices(f: ElementFields, areal_mass: np.ndarray, *,
                   fixed_prestress: tuple | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Consistent mass (kg) and elastic stiffness (N/m) of all elements from their fields
    (:func:`element_fields`), each (e, n_dof, n_dof) in the local DOFs: int mu N^T N dV and
    int B^T D B dV by the fields' Gauss quadrature (Bathe 1996, sec. 5.3).

    Parameters
    ----------
    f : ElementFields
        The elements' fields of harmonic k.
    areal_mass : ndarray, shape (e,)
        Mass per unit wall area (kg/m^2).
    fixed_prestress : (ndarray, ndarray), optional
        (N_s, N_theta) at the Gauss points (N/m) of loads that do not scale with the thrust
        (internal pressure): their geometric stiffness is added to the elastic one.
    """
    stiff = einsum("egia,eij,egjb,eg->eab", f.strains, f.material, f.strains, f.volume)
    mass = einsum("egia,egib,eg->eab", f.displacement, f.displacement,
                  areal_mass[:, None] * f.volume)
    if fixed_prestress is not None:
        stiff = stiff + geometric_matrices(f, *fixed_prestress)
    return mass, stiff


def geometric_matrices(f: ElementFields, ns0: np.ndarray, nt0: np.ndarray | None) -> np.ndarray:
    """Geometric stiffness (N/m) N_s (beta_s^2 + c Phi^2) + N_theta (beta_theta^2 + c Phi^2) of
    all elements from their fields (:func:`element_fields`), (e, n_dof, n_dof) in the local
    DOFs (Brush & Almroth 1975, ch. 5).

    Parameters
    ----------
    f : ElementFields
        The elements' fields of harmonic k.
    ns0, nt0 : ndarray, shape (e, g)
        Meridional and hoop prestress resultants at the Gauss points (N/m, compression < 0);
        ``nt0`` None: 0.
    """
    rot = f.meridional_rotation
    geo = einsum("egia,egib,eg->eab", rot, rot, ns0 * f.volume)
    if nt0 is not None:
        rot = f.hoop_rotation
        geo = geo + einsum("egia,egib,eg->eab", rot, rot, nt0 * f.volume)
    return geo


def element_energies(fields: ElementFields, local: np.ndarray, *,
                     ns0: np.ndarray | None = None, nt0: np.ndarray | None = None
                     ) -> np.ndarray:
    """q^T K_e q (+ q^T K_g q) of m fields, shape (m,), summed over the elements from the strains
    at the Gauss points: accurate to round-off relative to itself, unlike the assembled
    quadratic form (Bathe 1996 sec. 10.2.5).

    Parameters
    ----------
    fields : ElementFields
        From :func:`element_fields`.
    local : ndarray, shape (m, e, n_dof)
        Element DOFs (local frame) of m fields.
    ns0, nt0 : ndarray, shape (e, g), optional
        Prestress resultants (N/m): adds the geometric energy.
    """
    eps = np.einsum("egia,mea->megi", fields.strains, local)
    out = np.einsum("megi,eij,megj,eg->m", eps, fields.material, eps, fields.volume)
    for rot, res in ((fields.meridional_rotation, ns0), (fields.hoop_rotation, nt0)):
        if res is not None:
            val = np.einsum("egia,mea->megi", rot, local)
            out = out + np.einsum("megi,megi,eg->m", val, val, res * fields.volume)
    return out
