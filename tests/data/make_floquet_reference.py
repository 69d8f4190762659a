"""Write floquet_three_modes.json: a 3-DOF periodic system and its Floquet multipliers.

The system M q'' + C q' + (A + B cos Omega t) q = 0 (SI-like units, t in s) of ``three_modes``:
steady frequencies 3, 40, 250 rad/s, M != I, a non-symmetric B (0.05 w_i w_k in the modal
frame), and for zeta = 0.01 a non-proportional damping C (zeta = 0: C = 0).  For each zeta and
each Omega of OMEGAS (rad/s): the multipliers, eigenvalues of the monodromy matrix integrated
by scipy.integrate.solve_ivp (DOP853, rtol 1e-12, atol 1e-14, column by column over one period:
tests/harness.py ``ivp_monodromy``), independent of flexbooster.  The matrices are stored
with the multipliers, so that the test reads the very system that was integrated.

Run from the repository root: ``python tests/data/make_floquet_reference.py`` (about a
minute: the 250 rad/s mode over the 1.6 s period of Omega = 4 rad/s).
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parents[1]))
from harness import ivp_monodromy  # noqa: E402

#: Omega (rad/s): 156 steps of the fast mode per period, the sum of modes 1 and 2, 2 w2, w3, 2 w3.
OMEGAS = (4.0, 43.0, 80.0, 250.0, 500.0)


def three_modes(zeta: float):
    """M, C (None without damping), A, B of the module docstring, seeded (default_rng(0))."""
    rng = np.random.default_rng(0)
    wn = np.array([3.0, 40.0, 250.0])
    Q, _ = np.linalg.qr(rng.standard_normal((3, 3)))
    X = rng.standard_normal((3, 3))
    M = np.eye(3) + 0.1 * X @ X.T / 3.0
    T = np.linalg.cholesky(M) @ Q  # M^-1 A = T^-T diag(wn^2) T^T: frequencies wn exactly
    A = T @ np.diag(wn**2) @ T.T
    Cm = np.diag(2.0 * wn) + np.sqrt(np.outer(wn, wn)) * rng.uniform(-0.5, 0.5, (3, 3))
    B = 0.05 * T @ (np.outer(wn, wn) * rng.standard_normal((3, 3))) @ T.T
    return M, (zeta * T @ Cm @ T.T if zeta else None), A, B


def main() -> None:
    systems = []
    for zeta in (0.0, 0.01):
        M, C, A, B = three_modes(zeta)
        C0 = np.zeros((3, 3)) if C is None else C
        rho = {str(om): [[z.real, z.imag] for z in np.linalg.eigvals(ivp_monodromy(M, C0, A, B,
                                                                                    om))]
               for om in OMEGAS}
        systems.append({"zeta": zeta, "M": M.tolist(), "C": None if C is None else C.tolist(),
                        "A": A.tolist(), "B": B.tolist(), "multipliers": rho})
    data = {
        "equation": "M q'' + C q' + (A + B cos Omega t) q = 0",
        "source": "scipy solve_ivp DOP853 (rtol 1e-12, atol 1e-14) monodromy, numpy eigvals",
        "script": "tests/data/make_floquet_reference.py",
        "systems": systems,
    }
    path = Path(__file__).with_name("floquet_three_modes.json")
    path.write_text(json.dumps(data, indent=1) + "\n")


if __name__ == "__main__":
    main()
