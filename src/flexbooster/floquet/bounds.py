"""A rigorous stability certificate for damped periodic systems (any Omega).

M q'' + C q' + (A + B cos Omega t) q = 0: a bound of every Floquet exponent.

In the eigenbasis of the steady first-order operator L0 = [[0, I], [-M^-1 A, -M^-1 C]]
(z = W y, L0 W = W Lambda) the system is y' = (Lambda + cos(Omega t) G) y with
G = W^-1 N W, N = [[0, 0], [-M^-1 B, 0]].  With positive weights d the logarithmic norm of
Lambda + c G in the weighted maximum norm ||y|| = max_i |y_i| / d_i (|c| <= 1) is at most

    mu_d = max_i ( -delta_i + sum_j |G_ij| d_j / d_i ),    delta_i = -Re Lambda_i,

(Dahlquist 1959; Desoer & Vidyasagar 1975, ch. 2, sec. 2.8: the matrix measure of the
infinity norm), and every solution obeys ||y(t)|| <= exp(mu_d t) ||y(0)||: every Floquet
exponent, at *every* Omega, has Re lambda <= mu_d.  The best weights are the Perron vector of
Q = diag(1 / delta) |G| (Perron-Frobenius); then mu_d < 0 exactly when rho(Q) < 1, and the
system is stable for all Omega and for every amplitude B' = g B with g < 1 / rho(Q).

The bound ignores the phases of the coupling (no averaging), so it is conservative: for the
damped Mathieu equation it certifies mu < zeta / 2 against the true threshold 2 zeta
(Bolotin 1964, sec. 6), a factor 4.  Where damping dominates the coupling (the vehicle at the
default damping) it proves, at the cost of one 2n x 2n eigenproblem, that no region exists.

References
----------
.. [1] G. Dahlquist, "Stability and error bounds in the numerical integration of ordinary
   differential equations", Trans. Roy. Inst. Technol. Stockholm 130 (1959) (logarithmic norm).
.. [2] C. A. Desoer, M. Vidyasagar, *Feedback Systems: Input-Output Properties*, Academic
   Press, 1975, ch. 2, sec. 2.8 (matrix measure, the bound ||x(t)|| <= exp(int mu) ||x(0)||).
.. [3] R. A. Horn, C. R. Johnson, *Matrix Analysis*, Cambridge, 1985, sec. 8.3 (Perron
   vector; rho(Q) < 1 iff Q d < d for some d > 0).
.. [4] V. V. Bolotin, *The Dynamic Stability of Elastic Systems*, Holden-Day, 1964, sec. 6.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .multipliers import LinearPeriodicSystem, periodic_system

__all__ = ["StabilityCertificate", "stability_certificate"]

#: Largest condition number of the steady eigenvector matrix W accepted (beyond it the
#: round-off of G = W^-1 N W could spoil the bound: no certificate).
_MAX_COND = 1e8


@dataclass(frozen=True)
class StabilityCertificate:
    """Weighted logarithmic-norm bound of the Floquet exponents, valid at every Omega.

    ``rho``: spectral radius of Q = diag(1 / delta) |G|; ``growth_bound``: mu_d with the Perron
    weights (1 / time unit), every Re lambda at every Omega is below it (both inf without a
    bound); ``certified``: growth_bound < 0; ``amplitude_factor`` = 1 / rho, how far B may be
    scaled and stay certified (Dahlquist 1959; Desoer & Vidyasagar 1975, sec. 2.8).
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
    """Bound of every Floquet exponent of M q'' + C q' + (A + B cos Omega t) q = 0, any Omega.

    The system as :func:`flexbooster.floquet.periodic_system` (or a LinearPeriodicSystem as M);
    without damping, or with an undamped or unstable steady mode or a modal frame of condition
    above 1e8, no bound (``certified`` False).
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
    rho = float(np.max(np.abs(np.linalg.eigvals(Q))))
    # mu_d = max_i (-delta_i + (|G| d)_i / d_i)   (Desoer & Vidyasagar sec. 2.8, infinity norm)
    mu = float(np.max(-delta + (G @ d) / d))
    return StabilityCertificate(rho=rho, growth_bound=mu, certified=bool(mu < 0.0),
                                amplitude_factor=1.0 / rho if rho > 0.0 else np.inf)
