"""Write mathieu_reference.json: the Floquet discriminant and exponent of Mathieu's equation.

Equation (memo 4.2-3, A&S 20.1.1): y'' + (a - 2q cos 2t) y = 0.  For each (a, q) of POINTS:

* ``discriminant`` D = y1(pi), y1 the solution with y(0) = 1, y'(0) = 0 (so cos(pi beta) = D,
  McLachlan ch. IV), by its Taylor series about t = 0 summed at t = pi in mpmath at 50
  significant digits, the terms kept until eight in a row fall below 1e-45 of the sum (y1 is
  entire, the series converges for every t):
  c_(k+2) (k+2)(k+1) = -a c_k + 2q sum_m (-4)^m / (2m)! c_(k-2m);
* ``beta`` (real, imaginary) the characteristic exponent on its natural branch, r the band
  index from the count of characteristic values a_0, b_1, a_1, b_2, ... below a
  (scipy.special.mathieu_a / mathieu_b, A&S 20.2): r + arccos((-1)^r D) / pi in the stable
  band above tongue r, r + i arccosh|D| / pi inside tongue r.

Independent of flexbooster (mpmath and scipy.special only).  Run from the repository root:
``python tests/data/make_mathieu_reference.py`` (about 30 s); the output is deterministic.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import mpmath
import numpy as np
from scipy import special

DPS = 50
#: (a, q): memo range, first-tongue interior, a < a_0, higher tongues and stable bands,
#: q = 0; none within 1e-4 of a transition curve.
POINTS = [
    (0.2, 0.01), (0.5, 0.03), (0.9, 0.05), (0.99, 0.05), (1.0, 0.05), (1.04, 0.05),
    (0.1, 0.5), (0.5, 1.0), (2.0, 0.5), (3.0, 1.0), (4.1, 2.0), (-0.2, 0.1), (-1.0, 1.0),
    (6.0, 2.0), (9.2, 3.0), (10.0, 5.0), (16.2, 4.0), (20.0, 5.0), (25.0, 3.0), (2.5, 7.0),
    (40.0, 20.0), (0.7, 0.0), (-0.3, 0.0),
]


def discriminant(a: float, q: float, dps: int = DPS) -> float:
    """y1(pi) by the Taylor series of the module docstring, at ``dps`` digits."""
    with mpmath.workdps(dps):
        a_, q_ = mpmath.mpf(a), mpmath.mpf(q)
        cosc = []  # Taylor coefficients of cos 2t (even powers only)
        c = [mpmath.mpf(1), mpmath.mpf(0)]
        total, tk, k, quiet = c[0], mpmath.mpf(1), 0, 0
        small = mpmath.mpf(10) ** (-(dps - 5))
        while quiet < 8:
            while len(cosc) <= k // 2:
                m = len(cosc)
                cosc.append((-4) ** m / mpmath.factorial(2 * m))
            conv = mpmath.fsum(cosc[m] * c[k - 2 * m] for m in range(k // 2 + 1))
            c.append((-a_ * c[k] + 2 * q_ * conv) / ((k + 2) * (k + 1)))
            k += 1
            tk *= mpmath.pi
            term = c[k] * tk
            total += term
            quiet = quiet + 1 if abs(term) < small * max(1, abs(total)) else 0
        return float(total)


def count_below(a: float, q: float) -> int:
    """Number of characteristic values a_0, b_1, a_1, b_2, ... below a (scipy.special)."""
    n = 0
    for r in range(30):
        n += int(special.mathieu_a(r, q) < a)
        if r >= 1:
            n += int(special.mathieu_b(r, q) < a)
    return n


def exponent(D: float, count: int) -> complex:
    """beta on the natural branch from D and the band count (stable band r: count 2r + 1)."""
    if abs(D) <= 1.0:
        r = (count - 1) // 2
        return complex(r + np.arccos((-1) ** r * D) / np.pi)
    return complex(count // 2, np.arccosh(abs(D)) / np.pi)


def main() -> None:
    rows = []
    for a, q in POINTS:
        D = discriminant(a, q)
        beta = exponent(D, count_below(a, q))
        rows.append({"a": a, "q": q, "discriminant": D, "beta": [beta.real, beta.imag]})
    data = {
        "equation": "y'' + (a - 2q cos 2t) y = 0 (A&S 20.1.1)",
        "source": f"Taylor series of y1(pi) in mpmath at {DPS} digits; band index from "
                  "scipy.special.mathieu_a/mathieu_b (A&S 20.2)",
        "script": "tests/data/make_mathieu_reference.py",
        "points": rows,
    }
    text = json.dumps(data, indent=1)
    text = re.sub(r"\{\n\s+(\"a\".*?)\n\s+\}", lambda m: "{" + " ".join(m[1].split()) + "}",
                  text, flags=re.S)  # one point per line
    Path(__file__).with_name("mathieu_reference.json").write_text(text + "\n")


if __name__ == "__main__":
    main()
