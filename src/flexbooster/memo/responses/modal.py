"""Modal systems of the shells and their forcing, by quadrature (memo 5.2-5.4, 6.1)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.special import roots_legendre

from ...checks import count
from .. import beam as beam_mod
from ..shell_coefficients import ShellParameters, galerkin_coefficients
from .excitation import N_BASIS, Excitation

__all__ = [
    "cylinder_groups",
    "edge_argument",
    "beam_shapes_at",
    "ModalGroup",
    "modal_groups",
    "modal_basis",
    "forcing_harmonics",
]

@dataclass(frozen=True)
class ModalGroup:
    """Stacked modal systems of one kind of one cylinder, M x'' + K x = sum_b F_b f_b(tau).

    Attributes
    ----------
    kind : str
        ``"0k"`` (x = U_0k, 6.1-2), ``"j0"`` (U, W; 6.1-3) or ``"jk"`` (U, V, W; 6.1-4).
    cylinder : int
        1 (aft) or 2 (forward).
    j, k : numpy.ndarray
        Shape (n,), mode indices.
    mass, stiff : numpy.ndarray
        Shape (n, p, p), mass and stiffness matrices (appendix A normalisation).
    forcing : numpy.ndarray
        Shape (6 + 2(N + 1), n, p): the forcing per unit basis function.
    components : tuple of str
        Names of the p unknowns.
    """

    kind: str
    cylinder: int
    j: np.ndarray
    k: np.ndarray
    mass: np.ndarray
    stiff: np.ndarray
    forcing: np.ndarray
    components: tuple[str, ...]

    def __len__(self) -> int:
        return int(self.j.size)

    def forced(self) -> np.ndarray:
        """Boolean mask (n,) of the modes with a structurally non-zero forcing."""
        return np.any(self.forcing != 0.0, axis=(0, 2))

    def select(self, mask: np.ndarray) -> ModalGroup:
        """The sub-group of the modes in ``mask`` (boolean or integer index)."""
        return ModalGroup(self.kind, self.cylinder, self.j[mask], self.k[mask], self.mass[mask],
                          self.stiff[mask], self.forcing[:, mask], self.components)


def _quad_nodes(p: ShellParameters, d: int, M: int, N: int) -> tuple[np.ndarray, np.ndarray]:
    lam_N = float(beam_mod.free_free_eigenvalues(N)[-1]) if N > 0 else 0.0
    n = int(2 * M + lam_N + 64)  # the integrands turn through up to j pi and lambda_N / 2 rad
    t, w = roots_legendre(n)
    lo, hi = p.edges(d)
    half = (hi - lo) / 2.0
    return lo + half * (t + 1.0), w * half


def beam_shapes_at(p: ShellParameters, xi: np.ndarray, N: int) -> dict[str, np.ndarray]:
    """g and its xi-derivatives of each beam coordinate (rows q_1..q_N, q_B) (4.1-3..7): keys
    "g", "g1".."g4", each (N + 1, len(xi)).

    Parameters
    ----------
    p : ShellParameters
        Shell parameters (coordinates a, c, b).
    xi : numpy.ndarray
        Axial coordinate xi_bar.
    N : int
        Elastic beam modes.
    """
    xi = np.asarray(xi, dtype=float)
    zeta = xi - p.a  # zeta = xi_bar - d4/L + 1 = xi_bar + x_cm / L (C-6)
    out = {key: np.zeros((N + 1, xi.size)) for key in ("g", "g1", "g2", "g3", "g4")}
    if N > 0:
        n = np.arange(1, N + 1)
        half = beam_mod.free_free_eigenvalues(N)[:, None] / 2.0
        for key, order in (("g", 0), ("g1", 1), ("g2", 2), ("g3", 3), ("g4", 4)):
            # d^k phi_n / d xi^k = (lambda_n / 2)^k phi_n^(k) (4.1-4..7)
            out[key][:N] = half**order * beam_mod.mode_shape(n[:, None], zeta[None, :], order)
    out["g"][N] = xi  # q_B xi_bar (4.1-3)
    out["g1"][N] = 1.0  # (4.1-4)
    return out


def edge_argument(p: ShellParameters, d: int, j: np.ndarray, phase: str) -> np.ndarray:
    """The argument (rad) of the axial shape functions at the aft edge of cylinder d, per j.

    Parameters
    ----------
    p : ShellParameters
        Shell parameters.
    d : int
        Cylinder, 1 or 2.
    j : numpy.ndarray
        Axial indices.
    phase : str
        Phase convention of :func:`flexbooster.memo.shell_coefficients.edge_arguments`.
    """
    from ..shell_coefficients import edge_arguments

    return np.asarray(edge_arguments(p, d, j, phase)[0], dtype=float) + 0.0 * j


def modal_groups(p: ShellParameters, M: tuple[int, int], Nk: tuple[int, int], N: int,
                 phase: str = "zero") -> tuple[ModalGroup, ...]:
    """Modal systems 6.1-2..4 of both cylinders with their forcing built from its definition
    (3.0-2, 3.0-3, 4.1-3..7, 5.2-1, 5.3-4, 5.4-3..9): (0k, j0, jk) of cylinder 1, then 2. The
    forcing per basis function is tabulated in docs/theory/responses.md.

    Parameters
    ----------
    p : ShellParameters
        From :func:`flexbooster.memo.shell_coefficients.shell_parameters`.
    M, Nk : (int, int)
        Largest axial index j and circumferential index k of cylinders 1 and 2, 1..500.
    N : int
        Beam modes in g* (0..500).
    phase : {"zero", "printed"}
        Shape-function phase (erratum E10), also of the forcing projections.
    """
    N = count("N", N, 0)
    out: list[ModalGroup] = []
    for d in (1, 2):
        Md = count(f"M{d}", M[d - 1], 1)
        Nd = count(f"N{d}", Nk[d - 1], 1)
        out.extend(cylinder_groups(p, d, Md, Nd, N, phase))
    return tuple(out)


def cylinder_groups(p: ShellParameters, d: int, M: int, Nk: int, N: int,
                     phase: str) -> list[ModalGroup]:
    """The modal groups of cylinder d: every (j, k) with its modal matrices (memo 6.1).

    Parameters
    ----------
    p : ShellParameters
        Shell parameters.
    d : int
        Cylinder, 1 or 2.
    M, Nk : int
        Largest axial index j and circumferential index k.
    N : int
        Elastic beam modes.
    phase : str
        Phase convention of the axial shape functions.
    """
    nu, mu, sg = p.nu, p.mu, p.sigma
    lam = p.lam(d)
    g0 = 1.0 / ((1.0 - nu**2) * mu)
    coef = galerkin_coefficients(p, d, M, Nk, phase=phase)
    xi, wq = _quad_nodes(p, d, M, N)
    j = np.arange(1, M + 1)
    alpha = j * np.pi * p.L / (2.0 * p.half_length(d))
    s = (edge_argument(p, d, j, phase)[:, None]
         + alpha[:, None] * (xi - p.edges(d)[0])[None, :])  # argument of 5.3-2/3
    C, S = np.cos(s), np.sin(s)
    bs = beam_shapes_at(p, xi, N)
    Xi = xi - 0.5 * (xi - p.b + 1.0) ** 2  # bracket of eq. (5.3-4a)
    IC, IS = C @ wq, S @ wq
    IxC, IxS = (C * xi) @ wq, (S * xi) @ wq
    IXiC, IbS = (C * Xi) @ wq, (S * (p.b - xi)) @ wq
    G1C = (C * wq) @ bs["g1"].T  # (M, N + 1): int g_b' C
    GS = (S * wq) @ bs["g"].T
    G2S = (S * wq) @ bs["g2"].T
    DelS = (S * wq) @ (bs["g4"] - 2.0 * lam**2 * bs["g2"] + lam**4 * bs["g"]).T  # Lap^4 g*
    nb = N_BASIS + 2 * (N + 1)
    qb = slice(N_BASIS, N_BASIS + N + 1)  # rows q_b
    qdd = slice(N_BASIS + N + 1, nb)  # rows q_b''
    kF, kU, kUdd, kPdd, kPd2, kTP = range(N_BASIS)
    groups = []

    # 0k: U_0k'' + omega_0k^2 U_0k = P_0k (5.4-4, 6.1-2), mass = cylinder length ell
    kk = np.arange(1, Nk + 1)
    ell = p.edges(d)[1] - p.edges(d)[0]
    F = np.zeros((nb, Nk, 1))
    F[kPdd, 0, 0] = ell / lam  # -(-psi''/lambda cos theta) of F1 (3.0-3a), k = 1
    F[qb, 0, 0] = lam / (2.0 * (1.0 + nu) * mu) * (bs["g1"] @ wq)  # int g*' (5.4-4)
    groups.append(ModalGroup(
        "0k", d, np.zeros(Nk, dtype=int), kk, np.full((Nk, 1, 1), ell),
        (ell * lam**2 * kk**2 / (2.0 * (1.0 + nu) * mu))[:, None, None],  # eq. (5.4-4)
        F, ("U",)))

    # j0: (U, W), eqs. (5.4-6), (5.4-7), (6.1-3)
    m0, k0 = coef.matrices_j0()
    F = np.zeros((nb, M, 2))
    F[kF, :, 0] = -IC  # -(T0_bar/2 T cos K psi) of F1 (3.0-3a), cos K psi ~ 1
    F[kU, :, 0] = 0.5 * g0 * IC  # u*'' = eps T / 2 (5.3-4a)
    F[kUdd, :, 0] = 0.5 * IXiC  # -u*_tt = eps T'' Xi / 2 (5.3-4a)
    F[kPd2, :, 0] = IxC  # -(-psi'^2 xi) of F1 (3.0-3a)
    F[kPd2, :, 1] = -IS / (2.0 * lam)  # psi'^2 cos^2 theta / lambda of F3 (3.0-3c), k = 0
    F[kU, :, 1] = -0.5 * nu * lam * g0 * IbS  # nu lambda u*' (5.3-4a), u*' = -eps T (b - xi)/2
    groups.append(ModalGroup("j0", d, j, np.zeros(M, dtype=int), m0, k0, F, ("U", "W")))

    # jk: (U, V, W), eqs. (5.4-8), (5.4-9), (6.1-4)
    mk, kk3 = coef.matrices_jk()
    jj, kj = np.meshgrid(j, kk, indexing="ij")
    F = np.zeros((nb, M, Nk, 3))
    F[kPdd, :, 0, 0] = IC / lam  # psi'' cos theta / lambda of F1, delta_1k
    F[qb, :, 0, 0] = lam / (2.0 * (1.0 + nu) * mu) * G1C.T  # (1-nu) lambda/2 g*' (5.4-9a)
    for r in (1, 2):  # F2, F3 (3.0-3b, c): [-T0_bar/2 T K psi - psi'' xi] sin/cos theta
        F[kTP, :, 0, r] = IS
        F[kPdd, :, 0, r] = IxS
        F[qdd, :, 0, r] = -GS.T  # -(1 - nu^2) mu g*_tt (5.4-9b, c)
    F[qb, :, 0, 1] = g0 * (1.0 - nu) / 2.0 * G2S.T  # (1-nu)/2 g*'' (5.4-9b, erratum R-6)
    F[qb, :, 0, 2] = -g0 * sg**2 / 12.0 * DelS.T  # sigma^2/12 Lap^4 g* (5.4-9c, erratum R-7)
    if Nk >= 2:  # delta_2k: psi'^2 cos theta sin theta / lambda, cos^2 theta / lambda
        F[kPd2, :, 1, 1] = -IS / (2.0 * lam)
        F[kPd2, :, 1, 2] = -IS / (2.0 * lam)
    groups.append(ModalGroup("jk", d, jj.ravel(), kj.ravel(), mk.reshape(-1, 3, 3),
                             kk3.reshape(-1, 3, 3), F.reshape(nb, -1, 3), ("U", "V", "W")))
    return groups


def modal_basis(group: ModalGroup) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Natural frequencies omega (n, p) (units of omega_1, ascending), eigenvectors Phi (x = Phi y)
    and P = Phi^-1 M^-1 (y'' + omega^2 y = P F) of stacked systems (6.2-5, 6.2-15). ValueError
    for a complex or non-positive omega^2 (printed phase only).

    Parameters
    ----------
    group : ModalGroup
        The stacked systems.
    """
    Minv = np.linalg.inv(group.mass)
    lam, vec = np.linalg.eig(Minv @ group.stiff)
    if np.any(np.abs(lam.imag) > 1e-10 * np.abs(lam)) or np.any(lam.real <= 0):
        raise ValueError("group: a modal system has a complex or non-positive omega^2 "
                         "(printed phase, erratum E10); it has no normal coordinates")
    order = np.argsort(lam.real, axis=-1)
    lam = np.take_along_axis(lam.real, order, axis=-1)
    Phi = np.take_along_axis(vec.real, order[:, None, :], axis=-1)
    return np.sqrt(lam), Phi, np.linalg.solve(Phi, Minv)


def forcing_harmonics(group: ModalGroup, ex: Excitation) -> tuple[np.ndarray, np.ndarray]:
    """The forcing of every mode as Re sum_h f_h e^{i nu_h tau}: nu (H,) (units of omega_1) and
    f (n, p, H) (4.2-6, 4.1-10/11, 5.4-3..9).

    Parameters
    ----------
    group : ModalGroup
        The stacked systems.
    ex : Excitation
        The time functions.
    """
    nu, c = ex.harmonics()
    if c.shape[0] != group.forcing.shape[0]:
        raise ValueError(f"ex: N = {ex.N} does not match the group's beam modes "
                         f"({(group.forcing.shape[0] - N_BASIS) // 2 - 1})")
    return nu, np.einsum("bh,bnp->nph", c, group.forcing)
