"""Write donnell_reference.json: Donnell's frequency determinant, expanded, and its roots.

Donnell's equations for a shear-diaphragm cylinder (Leissa, NASA SP-288, 1973, eq. 2.20): the
frequency parameter Delta = rho (1 - nu^2) R^2 omega^2 / E is an eigenvalue of the symmetric

    C = [[lam^2 + (1 - nu)/2 n^2,  -(1 + nu)/2 lam n,        nu lam                 ],
         [-(1 + nu)/2 lam n,       (1 - nu)/2 lam^2 + n^2,   -n                     ],
         [nu lam,                  -n,                       1 + k (lam^2 + n^2)^2  ]]

with lam = m pi R / length, n the circumferential wave number, k = h^2 / (12 R^2).

* ``cubic``: -det(C - Delta I) = Delta^3 + K2 Delta^2 + K1 Delta + K0 expanded symbolically
  (sympy, exact rationals): K2, K1, K0 as lists of monomials [[e_lam, e_n, e_k, e_nu], "p/q"];
* ``roots``: for each shell of SHELLS, m = 1..6, n = 0..6, the three frequencies (Hz,
  ascending) sqrt(Delta E / (rho (1 - nu^2) R^2)) / (2 pi), Delta the eigenvalues of C by
  mpmath.eigsy at 30 significant digits (the material of MATERIAL).

Independent of flexbooster (sympy and mpmath only).  Run from the repository root:
``python tests/data/make_donnell_reference.py`` (a few seconds); the output is deterministic.
"""

from __future__ import annotations

import json
from pathlib import Path

import mpmath
import sympy as sp

DPS = 30
MATERIAL = {"E": 72.39e9, "nu": 0.33, "rho": 2768.0}  # Pa, -, kg/m^3 (tests/test_shell.py)
#: (length, R, h) in m: a very long thin tube (lam = 1e-4 at m = 1), a long thin shell, a
#: short thick one, the default cylinder 1.
SHELLS = [(31415.926535897932, 1.0, 0.01), (60.0, 2.0, 0.003), (0.8, 0.5, 0.02),
          (42.0, 5.05, 0.02)]


def donnell_matrix(lam, n, k, nu, one=1):
    """Leissa's eq. 2.20 matrix C in the number type of ``one`` (sympy or mpmath)."""
    half = one / 2
    return [[lam**2 + (1 - nu) * half * n**2, -(1 + nu) * half * lam * n, nu * lam],
            [-(1 + nu) * half * lam * n, (1 - nu) * half * lam**2 + n**2, -n],
            [nu * lam, -n, 1 + k * (lam**2 + n**2) ** 2]]


def cubic() -> dict:
    """K2, K1, K0 of -det(C - Delta I) as monomials in (lam, n, k, nu) with exact rationals."""
    lam, n, k, nu, delta = sp.symbols("lam n k nu Delta")
    C = sp.Matrix(donnell_matrix(lam, n, k, nu, one=sp.Integer(1)))
    poly = sp.Poly(sp.expand(-(C - delta * sp.eye(3)).det()), delta)
    assert poly.coeff_monomial(delta**3) == 1
    out = {}
    for name, power in (("K2", 2), ("K1", 1), ("K0", 0)):
        terms = sp.Poly(poly.coeff_monomial(delta**power), lam, n, k, nu).terms()
        out[name] = [[list(e), str(sp.Rational(c))] for e, c in sorted(terms)]
    return out


def roots() -> list:
    """The three frequencies (Hz) of every (shell, m, n) of the module docstring."""
    E, nu, rho = (mpmath.mpf(MATERIAL[key]) for key in ("E", "nu", "rho"))
    rows = []
    with mpmath.workdps(DPS):
        for length, R, h in SHELLS:
            R_, k = mpmath.mpf(R), mpmath.mpf(h) ** 2 / (12 * mpmath.mpf(R) ** 2)
            for m in range(1, 7):
                lam = m * mpmath.pi * R_ / mpmath.mpf(length)
                for n in range(7):
                    delta = mpmath.eigsy(mpmath.matrix(donnell_matrix(
                        lam, mpmath.mpf(n), k, nu, one=mpmath.mpf(1))), eigvals_only=True)
                    hz = sorted(float(mpmath.sqrt(d * E / (rho * (1 - nu**2) * R_**2))
                                      / (2 * mpmath.pi)) for d in delta)
                    rows.append({"length": length, "R": R, "h": h, "m": m, "n": n, "hz": hz})
    return rows


def main() -> None:
    data = {
        "equation": "Donnell's shear-diaphragm cylinder, Leissa NASA SP-288 eq. 2.20",
        "source": f"sympy expansion of -det(C - Delta I); mpmath.eigsy at {DPS} digits",
        "script": "tests/data/make_donnell_reference.py",
        "material": MATERIAL,
        "cubic": cubic(),
        "roots": roots(),
    }
    text = json.dumps(data, indent=None, separators=(",", ":"))
    text = text.replace('{"length"', '\n {"length"')  # one (shell, m, n) per line
    Path(__file__).with_name("donnell_reference.json").write_text(text + "\n")


if __name__ == "__main__":
    main()
