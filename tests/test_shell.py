"""Shell natural frequencies (memo 5.4, 6.2, appendix D) and Donnell's reference (Leissa).

Tiers: exact limits (D-IV: L2 -> 0, L1 -> 0; wave speeds and the ring frequency in
Donnell's cubic), literature (App. D-II = Donnell's determinant, Leissa NASA SP-288 eqs.
2.20-2.22; the memo's closed forms), invariants (symmetric functions of the batched
eigenvalues, mode counts up to 200, output formats, bad input).
"""

from __future__ import annotations

import json
from pathlib import Path

import matplotlib
import mpmath
import numpy as np
import pytest

from flexbooster.case import memo_case
from flexbooster.memo.beam import first_bending_frequency
from flexbooster.memo.shell import (
    METHODS,
    composite_frequencies,
    cylinder_coefficients,
    generalized_eigen,
    natural_frequencies,
)
from flexbooster.memo.shell_coefficients import shell_parameters
from flexbooster.model import model_from_case
from reference.donnell import (
    donnell_cubic,
    donnell_frequencies,
    donnell_reference,
    memo_roots_j0,
    single_cylinder_frequencies,
    single_cylinder_matrix,
    single_cylinder_roots_j0,
    single_cylinder_symmetric_functions,
    symmetric_functions_j0,
    symmetric_functions_jk,
)

matplotlib.use("Agg")

E, NU, RHO = 72.39e9, 0.33, 2768.0
#: Single cylinders (R, L half-length, h) in m: default cylinders 1 and 2, a short thick one,
#: a long very thin one (the worst-conditioned), a stubby one.
SINGLE = [(5.05, 21.0, 0.02), (3.3, 9.0, 0.02), (1.0, 2.0, 0.01), (2.0, 30.0, 0.003),
          (0.5, 0.4, 0.02)]
DEFAULT = (5.05, 21.0, 3.3, 9.0, 0.02)  # R1, L1, R2, L2, h of the memo case
#: Donnell's determinant expanded by sympy and its roots by mpmath at 30 digits (the script
#: tests/data/make_donnell_reference.py, which names the method and the points).
DONNELL = json.loads((Path(__file__).parent / "data" / "donnell_reference.json").read_text())


def omega1(L, R1):
    return first_bending_frequency(L, R1, E, RHO)


def composite(R1, L1, R2, L2, h, M=20, N=20, method="zero-phase"):
    return composite_frequencies(R1, L1, R2, L2, h, E, NU, RHO, omega1(L1 + L2, R1),
                                 M, N, M, N, method)


# --- literature: App. D-II is Donnell's determinant -------------------------------------


@pytest.mark.parametrize(("R", "L", "h"), SINGLE)
def test_d2_equals_donnell_determinant(R, L, h):
    # D-6..D-8 (symmetric functions of omega_bar^2 from C^{jk}) against Leissa's cubic
    # (NASA SP-288 eqs. 2.21-2.22) in the memo's units, omega_bar^2 = lam^2 Delta /
    # ((1 - nu^2) mu): both in mpmath at 40 digits (the determinant D-8 cancels by up to 1e5
    # in floating point), agreement 1e-12 relative (the acceptance figure; observed ~1e-35).
    mpmath.mp.dps = 40
    mp = mpmath.mpf
    w1 = omega1(L, R)
    lam, sigma, mu, nu = mp(L) / R, mp(h) / L, mp(RHO) * L**2 * mp(w1) ** 2 / E, mp(NU)
    j, k = np.meshgrid(np.arange(1, 13), np.arange(0, 13), indexing="ij")
    jo, ko = j.astype(object), k.astype(object)
    jo = np.vectorize(mp, otypes=[object])(jo)
    ko = np.vectorize(mp, otypes=[object])(ko)
    s1, s2, s3 = single_cylinder_symmetric_functions(
        single_cylinder_matrix(lam, sigma, mu, nu, jo, ko))
    K2, K1, K0 = donnell_cubic(jo * mpmath.pi / 2 / lam, ko, mp(h) ** 2 / (12 * mp(R) ** 2), nu)
    scale = lam**2 / ((1 - nu**2) * mu)
    for got, want in ((s1, -K2 * scale), (s2, K1 * scale**2), (s3, -K0 * scale**3)):
        rel = np.vectorize(lambda a, b: float(abs(a / b - 1)))(got, want)
        assert rel.max() <= 1e-12
    mpmath.mp.dps = 15


@pytest.mark.parametrize(("R", "L", "h"), SINGLE)
def test_d2_frequencies_equal_donnell_frequencies(R, L, h):
    # D-II frequencies (eigenvalues of C in memo units) times omega_1 against
    # donnell_frequencies (Leissa's cubic in physical units, Viete + Newton), j <= 20,
    # k <= 20.  Tolerance 1e-10: the bending root from a 3x3 eigensolver carries
    # eps * omega_max^2 / omega_min^2 (up to 2e-11 for the long thin shell).
    w1 = omega1(L, R)
    j, k = np.meshgrid(np.arange(1, 21), np.arange(0, 21), indexing="ij")
    memo = single_cylinder_frequencies(L / R, h / L, RHO * L**2 * w1**2 / E, NU, j, k)
    np.testing.assert_allclose(memo * w1 / (2 * np.pi),
                               donnell_frequencies(2 * L, R, h, E, NU, RHO, j, k), rtol=1e-10)


@pytest.mark.parametrize(("R", "L", "h"), SINGLE)
def test_d1_closed_form_equals_donnell_k0(R, L, h):
    # D-1..D-5 (printed closed form, k = 0) against the two coupled roots of Leissa's cubic
    # at n = 0 (the third is the uncoupled torsional root); rtol 1e-10 as above.
    w1 = omega1(L, R)
    j = np.arange(1, 31)
    lo, hi = single_cylinder_roots_j0(L / R, h / L, RHO * L**2 * w1**2 / E, NU, j)
    f = donnell_frequencies(2 * L, R, h, E, NU, RHO, j, 0)
    tors = j * np.pi / (2 * L) * np.sqrt(E / (2 * (1 + NU) * RHO)) / (2 * np.pi)
    coupled = np.sort(np.where(np.isclose(f, tors[:, None], rtol=1e-9), np.inf, f), axis=1)
    got = np.sqrt(np.stack([lo, hi], 1)) * w1 / (2 * np.pi)
    np.testing.assert_allclose(got, coupled[:, :2], rtol=1e-10)


# --- exact limits of Donnell's cubic ----------------------------------------------------


def test_donnell_torsional_root_is_shear_wave():
    # n = 0: the torsional mode is uncoupled, omega = (m pi / length) sqrt(G / rho) exactly
    # (shear wave in a tube; Leissa sec. 2.3, Graff, Wave Motion in Elastic Solids, 1975,
    # sec. 2.x).  The cubic root agrees to 1e-13.
    m = np.arange(1, 11)
    f = donnell_frequencies(10.0, 1.0, 0.01, E, NU, RHO, m, 0)
    want = m * np.pi / 10.0 * np.sqrt(E / (2 * (1 + NU) * RHO)) / (2 * np.pi)
    assert np.all(np.min(np.abs(f / want[:, None] - 1), axis=1) <= 1e-13)


def test_donnell_long_wave_limits_n0():
    # n = 0, m pi R / length -> 0: the axial root tends to the bar wave,
    # omega = (m pi / length) sqrt(E / rho), and the radial root to the ring (breathing)
    # frequency sqrt(E / (rho (1 - nu^2))) / R (Leissa sec. 2.3; Delta -> (1 - nu^2) lam^2 and
    # Delta -> 1).  At lam = 1e-4 the corrections are O(lam^2) = 1e-8; tolerance 1e-7.
    length, R = 1e4 * np.pi, 1.0  # lam = pi R / length = 1e-4 for m = 1
    f = donnell_frequencies(length, R, 0.01, E, NU, RHO, 1, 0)
    bar = np.pi / length * np.sqrt(E / RHO) / (2 * np.pi)
    ring = np.sqrt(E / (RHO * (1 - NU**2))) / R / (2 * np.pi)
    np.testing.assert_allclose(f[1], bar, rtol=1e-7)  # f[0]: torsional, sqrt((1-nu)/2) lam
    np.testing.assert_allclose(f[2], ring, rtol=1e-7)


def test_donnell_cubic_is_determinant_expansion():
    # Leissa eqs. 2.21-2.22 are the expansion of Donnell's 3x3 determinant (eq. 2.20): the
    # expansion by sympy with exact rationals (DONNELL["cubic"], stored) evaluated exactly
    # (fractions) at 200 points, lam, k, nu in (0.05, 2), (0, 1), (0, 0.5), n = 0..8, against
    # donnell_cubic in floating point: 1e-13 relative (sums of like-signed terms, no
    # cancellation; a wrong coefficient misses by O(1)).
    from fractions import Fraction

    rng = np.random.default_rng(2021)
    points = np.column_stack([rng.uniform(0.05, 2, 200), rng.integers(0, 9, 200),
                              rng.uniform(0, 1, 200), rng.uniform(0, 0.5, 200)])
    for lam, n, k, nu in points:
        got = donnell_cubic(lam, n, k, nu)
        x = [Fraction(v) for v in (lam, n, k, nu)]
        for name, value in zip(("K2", "K1", "K0"), got, strict=True):
            want = float(sum(Fraction(c) * x[0] ** e[0] * x[1] ** e[1] * x[2] ** e[2]
                             * x[3] ** e[3] for e, c in DONNELL["cubic"][name]))
            assert value == pytest.approx(want, rel=1e-13), (name, lam, n, k, nu)


# --- D-IV limiting cases ------------------------------------------------------------------


def _single_reference(f, sel, L, R, h, w1):
    """D-II omega_bar of the lone cylinder (L, R) for the rows ``sel`` of table ``f``."""
    lam, sigma, mu = L / R, h / L, RHO * L**2 * w1**2 / E
    out = np.empty(sel.sum())
    j, k, br = f.j[sel], f.k[sel], f.branch[sel]
    pos = k > 0
    out[pos] = single_cylinder_frequencies(lam, sigma, mu, NU, j[pos], k[pos])[
        np.arange(pos.sum()), br[pos] - 1]
    lo, hi = single_cylinder_roots_j0(lam, sigma, mu, NU, j[~pos])
    out[~pos] = np.sqrt(np.where(br[~pos] == 1, lo, hi))
    return out


@pytest.mark.parametrize("method", METHODS)
def test_limit_l2_to_zero(method):
    # D-IV-1: L2 -> 0 (here L2 = 1e-13 L1), cylinder 1 tends to the single cylinder of
    # half-length L1 (D-II), j, k <= 20, all three methods: 1e-9 relative (the acceptance
    # figure; the printed-phase terms vanish like L2/L1 since d1 - d2 -> 0).
    R1, L1, R2, _, h = DEFAULT
    f = composite(R1, L1, R2, 1e-13 * L1, h, method=method)
    assert not np.any(f.excluded["cylinder"] == 1)
    sel = (f.cylinder == 1) & (f.j > 0)
    ref = _single_reference(f, sel, L1, R1, h, f.omega_1)
    np.testing.assert_allclose(f.omega_bar[sel], ref, rtol=1e-9)


@pytest.mark.parametrize("method", ["zero-phase", "galerkin"])
def test_limit_l1_to_zero(method):
    # D-IV-2: L1 -> 0 (L1 = 1e-13 L2), cylinder 2 tends to the single cylinder of
    # half-length L2: 1e-9 relative (omega_1 keeps the radius R1 of 4.2-8b, the same for
    # both sides).
    R1, _, R2, L2, h = DEFAULT
    f = composite(R1, 1e-13 * L2, R2, L2, h, method=method)
    assert not np.any(f.excluded["cylinder"] == 2)
    sel = (f.cylinder == 2) & (f.j > 0)
    ref = _single_reference(f, sel, L2, R2, h, f.omega_1)
    np.testing.assert_allclose(f.omega_bar[sel], ref, rtol=1e-9)


def test_limit_l1_to_zero_fails_for_memo_k0():
    # Erratum E9: with lambda^4 in (k_j0)_2 (A-36 as printed) the memo-literal k = 0
    # frequencies of cylinder 2 do not tend to D-II (relative miss > 0.5 for some j), while
    # its k >= 1 frequencies do (1e-9), so D-IV-2 fails only through E9.
    R1, _, R2, L2, h = DEFAULT
    f = composite(R1, 1e-13 * L2, R2, L2, h, method="memo")
    sel = (f.cylinder == 2) & (f.j > 0)
    ref = _single_reference(f, sel, L2, R2, h, f.omega_1)
    k0 = f.k[sel] == 0
    assert np.max(np.abs(f.omega_bar[sel][k0] / ref[k0] - 1)) > 0.5
    np.testing.assert_allclose(f.omega_bar[sel][~k0], ref[~k0], rtol=1e-9)


# --- the composite against the isolated cylinders (question 4.3) --------------------------


@pytest.mark.parametrize("geometry", [DEFAULT, (3.0, 12.0, 2.0, 6.0, 0.008)])
def test_zero_phase_equals_isolated_donnell(geometry):
    # The default method reproduces Donnell's shear-diaphragm frequencies of each cylinder
    # alone (Leissa's cubic, physical units) for every row, j, k <= 20: 1e-11 relative
    # (conditioning of the 3x3 bending root, as in the D-II test).
    R1, L1, R2, L2, h = geometry
    f = composite(*geometry)
    ref = donnell_reference(f, R1, L1, R2, L2, h, E, NU, RHO)
    np.testing.assert_allclose(f.hz, ref, rtol=1e-11)


def test_printed_phase_moves_frequencies():
    # Reading guide 4.3 (reproduced): with the printed phase the composite frequencies of the
    # memo case leave the isolated-cylinder values by tens of percent (j, k <= 10), and
    # some low modes lose their real frequency altogether.  Reference: donnell_reference.
    R1, L1, R2, L2, h = DEFAULT
    for method in ("galerkin", "memo"):
        f = composite(*DEFAULT, M=10, N=10, method=method)
        r = f.hz / donnell_reference(f, R1, L1, R2, L2, h, E, NU, RHO)
        assert r.min() < 0.7 and r.max() > 1.25, method
        assert f.excluded["j"].size > 0, method


# --- invariants ---------------------------------------------------------------------------


@pytest.mark.parametrize("method", METHODS)
def test_symmetric_functions_of_eigenvalues(method):
    # The batched eigenvalues satisfy the memo's forms: sum and product of omega^2 are
    # (b)/(a), (c)/(a) for k = 0 (6.2-7) and B/A, C/A, D/A for k >= 1 (6.2-16/17), for the
    # printed-phase (non-symmetric) systems too.  Tolerance 1e-9 of the scale |omega^2|^p
    # (rounding in the expanded products).
    p = shell_parameters(*DEFAULT[:4], DEFAULT[4], E, NU, RHO, omega1(30.0, DEFAULT[0]))
    for d in (1, 2):
        coef = cylinder_coefficients(p, d, 12, 12, method)
        mass, stiff = coef.matrices_j0()
        w, _ = generalized_eigen(mass, stiff)
        a, b, c = symmetric_functions_j0(mass, stiff)
        sc = np.max(np.abs(w), axis=-1)
        assert np.all(np.abs(w.sum(-1) - b / a) <= 1e-9 * sc)
        assert np.all(np.abs(w.prod(-1) - c / a) <= 1e-9 * sc**2)
        mass, stiff = coef.matrices_jk()
        w, _ = generalized_eigen(mass, stiff)
        A, B, C, D = symmetric_functions_jk(mass, stiff)
        sc = np.max(np.abs(w), axis=-1)
        pair = w[..., 0] * w[..., 1] + w[..., 1] * w[..., 2] + w[..., 0] * w[..., 2]
        assert np.all(np.abs(w.sum(-1) - B / A) <= 1e-9 * sc)
        assert np.all(np.abs(pair - C / A) <= 1e-9 * sc**2)
        assert np.all(np.abs(w.prod(-1) - D / A) <= 1e-9 * sc**3)


def test_d9_roots_and_printed_6_2_6():
    # D-9/D-10 give omega^2 (= the eigenvalues, 1e-10); 6.2-6 as printed (erratum E6: no
    # 1/(2a) on the root, no square on the left) gives neither omega nor omega^2.
    p = shell_parameters(*DEFAULT[:4], DEFAULT[4], E, NU, RHO, omega1(30.0, DEFAULT[0]))
    coef = cylinder_coefficients(p, 1, 12, 1, "zero-phase")
    mass, stiff = coef.matrices_j0()
    w = generalized_eigen(mass, stiff)[0].real
    a, b, c = symmetric_functions_j0(mass, stiff)
    lo, hi = memo_roots_j0(a, b, c, "D-9")
    np.testing.assert_allclose(np.stack([lo, hi], -1), w, rtol=1e-10)
    plo, phi = memo_roots_j0(a, b, c, "6.2-6")
    printed = np.stack([plo, phi], -1)
    assert np.max(np.abs(printed / w - 1)) > 0.1 and np.max(np.abs(printed / np.sqrt(w) - 1)) > 0.1


def test_omega_0k_formula():
    # 5.4-4: omega_0k^2 = lambda^2 k^2 / (2 (1 + nu) mu), i.e. omega = k sqrt(G/rho) / R in
    # rad/s (shear wave around the circumference): 1e-13.
    f = composite(*DEFAULT)
    for d, R in ((1, DEFAULT[0]), (2, DEFAULT[2])):
        sel = (f.cylinder == d) & (f.j == 0)
        want = f.k[sel] * np.sqrt(E / (2 * (1 + NU) * RHO)) / R
        np.testing.assert_allclose(f.rad_s[sel], want, rtol=1e-13)
        assert set(f.mode_type[sel]) == {"axial"}


@pytest.mark.slow
@pytest.mark.parametrize("method", METHODS)
def test_mode_counts_up_to_200(method):
    # No overflow, NaN or negative squared frequency for 200 modes per index (acceptance);
    # the zero-phase table is complete, the printed-phase ones list what they drop.
    f = composite(*DEFAULT, M=200, N=200, method=method)
    assert np.all(np.isfinite(f.omega_bar)) and np.all(f.omega_bar > 0)
    assert np.all(np.isfinite(f.hz)) and np.all(np.isfinite(f.rad_s))
    n_all = 2 * (200 + 2 * 200 + 3 * 200 * 200)
    assert len(f) + f.excluded["j"].size == n_all
    if method == "zero-phase":
        assert f.excluded["j"].size == 0
    json.dumps(f.to_dict(), allow_nan=False)


def test_mode_types_follow_shell_theory():
    # Leissa sec. 2.3: for k = 0 the lower branch of a long shell is longitudinal (axial),
    # the upper the breathing (radial) mode; for k >= 2 the lowest branch is flexural
    # (radial).  Memo case, cylinder 1.
    f = composite(*DEFAULT, M=10, N=10)
    assert f.mode_type[f.select(1, 1, 0, 1)][0] == "axial"
    assert f.mode_type[f.select(1, 1, 0, 2)][0] == "radial"
    low = (f.cylinder == 1) & (f.branch == 1) & (f.k >= 2) & (f.j >= 1)
    assert set(f.mode_type[low]) == {"radial"}
    assert {"axial", "torsional", "radial"} <= set(f.mode_type)


def test_natural_frequencies_of_the_model_equal_composite_frequencies():
    # natural_frequencies(model) is composite_frequencies with the model's numbers; omega_1 is
    # beam.first_bending_frequency (4.2-8b) of L = L1 + L2.  Same table to the last bit.
    case = memo_case()
    b, t = case.booster, case.truncation
    a = natural_frequencies(model_from_case(case))
    w1 = first_bending_frequency(b.cylinder1.half_length + b.cylinder2.half_length,
                                 b.cylinder1.radius, b.E, b.rho)
    c = composite_frequencies(b.cylinder1.radius, b.cylinder1.half_length, b.cylinder2.radius,
                              b.cylinder2.half_length, b.thickness, b.E, b.nu, b.rho, w1,
                              t.M1, t.N1, t.M2, t.N2)
    np.testing.assert_array_equal(a.hz, c.hz)
    assert a.omega_1 == w1
    assert len(a) == 2 * (t.N1 + 2 * t.M1 + 3 * t.M1 * t.N1)


def test_table_outputs():
    # to_dict: JSON-ready parallel lists; to_rows: one dict per row with the CSV columns;
    # hz = rad_s / 2 pi = omega_bar omega_1 / 2 pi (definitions).
    f = natural_frequencies(model_from_case(memo_case()), method="galerkin")
    d = f.to_dict()
    json.dumps(d, allow_nan=False)
    assert len(d["hz"]) == len(f) and d["method"] == "galerkin"
    assert set(d["excluded"]) == {"cylinder", "j", "k", "branch", "omega_sq_real",
                                  "omega_sq_imag"}
    rows = f.to_rows()
    assert len(rows) == len(f) and list(rows[0]) == d["columns"]
    np.testing.assert_allclose(f.hz, f.omega_bar * f.omega_1 / (2 * np.pi), rtol=1e-15)


def test_frequency_curves_plot_the_table():
    # One line per j through (k, f) of branch 1, in the table's units.
    from flexbooster.present.plotting.shell import frequency_curves

    f = composite(*DEFAULT, M=4, N=6)
    fig = frequency_curves(f, 2)
    ax = fig.axes[0]
    assert len(ax.lines) == 4
    line = ax.lines[0]
    sel = f.select(2, 1, None, 1)
    order = np.argsort(f.k[sel])
    np.testing.assert_array_equal(line.get_xdata(), f.k[sel][order])
    np.testing.assert_array_equal(line.get_ydata(), f.hz[sel][order])
    with pytest.raises(ValueError, match="cylinder"):
        frequency_curves(f, 3)


@pytest.mark.parametrize(
    ("name", "value"), [("M1", 0), ("N2", 501), ("M2", 2.0), ("N1", True)]
)
def test_bad_counts_raise(name, value):
    args = dict(M1=3, N1=3, M2=3, N2=3)
    args[name] = value
    with pytest.raises(ValueError, match=name):
        composite_frequencies(*DEFAULT[:4], DEFAULT[4], E, NU, RHO, 100.0, **args)


def test_bad_method_raises():
    with pytest.raises(ValueError, match="method"):
        natural_frequencies(model_from_case(memo_case()), method="printed")


@pytest.mark.parametrize(
    ("kwargs", "word"),
    [({"m": 0}, "m = 0"), ({"n": -1}, "n = -1"), ({"thickness": 2.0}, "thickness"),
     ({"nu": 0.5}, "nu"), ({"length": -1.0}, "length"), ({"m": 1.5}, "m = 1.5")],
)
def test_donnell_bad_input(kwargs, word):
    args = dict(length=10.0, radius=1.0, thickness=0.01, E=E, nu=NU, rho=RHO, m=1, n=2)
    args.update(kwargs)
    with pytest.raises(ValueError, match=word):
        donnell_frequencies(**args)


@pytest.mark.parametrize(("length", "R", "h"), [(1e4 * np.pi, 1.0, 0.01), (60.0, 2.0, 0.003),
                                                (0.8, 0.5, 0.02), (42.0, 5.05, 0.02)])
def test_donnell_roots_against_mpmath(length, R, h):
    # The cubic's three roots against the eigenvalues of Donnell's matrix (Leissa eq. 2.20) by
    # mpmath.eigsy at 30 digits (DONNELL["roots"], stored; m = 1..6, n = 0..6): 1e-12
    # relative for every root, including bending and long-wave roots 1e-8 of the largest.
    assert DONNELL["material"] == {"E": E, "nu": NU, "rho": RHO}
    rows = [r for r in DONNELL["roots"] if (r["length"], r["R"], r["h"]) == (length, R, h)]
    assert len(rows) == 42
    m = np.array([r["m"] for r in rows])
    n = np.array([r["n"] for r in rows])
    got = donnell_frequencies(length, R, h, E, NU, RHO, m, n)
    np.testing.assert_allclose(got, [r["hz"] for r in rows], rtol=1e-12)
