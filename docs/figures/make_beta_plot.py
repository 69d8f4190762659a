"""Write docs/figures/beta-memo-vs-exact.svg: eq. (4.2-9) against the exact exponent.

The corrected small-q formula (erratum E4) differs from the exact Floquet exponent by O(q^4),
the printed one by O(q^2), over the memo's range 0 < a < 1, 0 < q <= 0.05 (eq. 4.2-5).
Run from the repository root::

    python docs/figures/make_beta_plot.py
"""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
matplotlib.rcParams["svg.fonttype"] = "none"  # text as text: small, diffable SVG
matplotlib.rcParams["svg.hashsalt"] = "flexbooster"  # reproducible ids

import numpy as np  # noqa: E402

from flexbooster.floquet import characteristic_exponent  # noqa: E402
from flexbooster.memo.pitch import memo_exponent  # noqa: E402
from flexbooster.present.plotting.pitch import beta_comparison_plot  # noqa: E402

OUT = Path(__file__).with_name("beta-memo-vs-exact.svg")


def main() -> None:
    q = np.geomspace(0.05 / 100.0, 0.05, 30)
    errors = {}
    for a in (0.2, 0.5, 0.8):
        exact = characteristic_exponent(a, q, "hill")
        errors[a] = (np.abs(memo_exponent(a, q) - exact),
                     np.abs(memo_exponent(a, q, printed=True) - exact))
    fig = beta_comparison_plot(q, errors)
    fig.savefig(OUT, format="svg", metadata={"Date": None, "Creator": None})
    print(f"wrote {OUT} ({OUT.stat().st_size} bytes)")


if __name__ == "__main__":
    main()
