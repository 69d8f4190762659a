"""A rigorous stability certificate of M q'' + C q' + (A + B cos Omega t) q = 0 at every Omega.

In the steady first-order eigenbasis, y' = (Lambda + cos(Omega t) G) y; the weighted
logarithmic norm mu_d = max_i (-delta_i + sum_j |G_ij| d_j / d_i) bounds every Floquet
exponent; the Perron vector of Q = diag(1 / delta) |G| is the best d, and mu_d < 0 exactly
when rho(Q) < 1 (docs/theory/floquet.md sec. 4). Conservative; its work is bounded: two
2n x 2n eigenproblems with vectors, a condition number and a solve (about
:data:`CERTIFICATE_FLOPS_PER_N3` (2n)^3 floating-point operations), whatever the system.

References: G. Dahlquist (1959), logarithmic norm; C. A. Desoer, M. Vidyasagar, *Feedback
Systems*, 1975, sec. 2.8; R. A. Horn, C. R. Johnson, *Matrix Analysis*, 1985, sec. 8.3.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .multipliers import LinearPeriodicSystem, periodic_system

__all__ = ["StabilityCertificate", "stability_certificate", "CERTIFICATE_FLOPS_PER_N3"]

#: Floating-point operations of :func:`stability_certificate` per (2n)^3, LAPACK's counts
#: (Golub & Van Loan, sec. 7.5.6 and 8.6): eig with vectors 25, twice; the SVD of the condition
#: number 12; the solve and the product G = W^-1 N W 3.
CERTIFICATE_FLOPS_PER_N3 = 65.0

#: Largest condition number of the steady eigenvector matrix W accepted (beyond it the
#: round-off of G = W^-1 N W could spoil the bound: no certificate).
_MAX_COND = 1e8


@dataclass(frozen=True)
class StabilityCertificate:
    """Weighted logarithmic-norm bound of the Floquet exponents, valid at every Omega.

    Attributes
    ----------
    rho, growth_bound : float
        Spectral radius of Q and mu_d with the Perron weights (1 / time unit); inf without a bound.
    certified : bool
        growth_bound < 0: asymptotically stable at every Omega.
    amplitude_factor : float
        1 / rho: how far B may be scaled and stay certified.
    """

    rho: float
    growth_bound: float
    certified: bool
    amplitude_factor: float

    def to_dict(self) -> dict:
        """JSON-ready mapping (inf as the string "inf")."""
        def num(v):
            return float(v) if np.isfinite(v) else "inf"

        return {"rho": num(self.rho), "growth_bound": num(self.growth_bound),
                "certified": bool(self.certified),
                "amplitude_factor": num(self.amplitude_factor)}


_NONE = StabilityCertificate(rho=np.inf, growth_bound=np.inf, certified=False,
                             amplitude_factor=0.0)


def stability_certificate(M, C, A, B) -> StabilityCertificate:
    """Bound of every Floquet exponent at any Omega; not ``certified`` without damping, with an
    undamped or unstable steady mode, or a modal frame of condition above 1e8.

    Parameters
    ----------
    M, C, A, B : array_like
        The system, each (n, n), C may be None; or a LinearPeriodicSystem as M.
    """
    system = M if isinstance(M, LinearPeriodicSystem) else periodic_system(M, C, A, B)
    if not system.damped:
        return _NONE
    n = system.n
    L0 = np.block([[np.zeros((n, n)), np.eye(n)], [-system.K0, -system.Kc]])
    lam, W = np.linalg.eig(L0)
    delta = -lam.real  # decay rates of the steady modes
    if np.any(delta <= 0.0):
        return _NONE
    cond = float(np.linalg.cond(W))
    if cond > _MAX_COND:
        return _NONE
    if not np.any(system.Kb):  # steady and damped: decays at the slowest steady rate
        return StabilityCertificate(rho=0.0, growth_bound=-float(np.min(delta)),
                                    certified=True, amplitude_factor=np.inf)
    N = np.block([[np.zeros((n, n)), np.zeros((n, n))], [-system.Kb, np.zeros((n, n))]])
    G = np.abs(np.linalg.solve(W, N @ W))  # |W^-1 N W|
    G = G + 16.0 * cond * np.finfo(float).eps * float(np.max(G))  # round-off of G
    Q = G / delta[:, None]  # diag(1 / delta) |G|
    ev, vec = np.linalg.eig(Q)  # Q > 0 entrywise (round-off term): Perron vector > 0
    p = int(np.argmax(ev.real))
    d = np.abs(vec[:, p].real)
    d = np.maximum(d, 1e-300)
    rho = float(np.max(np.abs(ev)))  # the same spectrum: no second eigenproblem
    # mu_d = max_i (-delta_i + (|G| d)_i / d_i)   (Desoer & Vidyasagar sec. 2.8, infinity norm)
    mu = float(np.max(-delta + (G @ d) / d))
    return StabilityCertificate(rho=rho, growth_bound=mu, certified=bool(mu < 0.0),
                                amplitude_factor=1.0 / rho if rho > 0.0 else np.inf)
