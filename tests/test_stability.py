"""The 13 families of stability equations (memo 7.3): every root found once, none missed.

The reference is a brute-force scan independent of the vectorised solver: for every curve and
every shell frequency separately, the scalar function excitation(Omega) - omega_shell is sampled
on a grid 20 times finer than the solver's and every sign change is refined by
scipy.optimize.brentq (xtol 1e-14).  The excitation of each family is written there directly
from eqs. 7.2-1..7.2-3 (Omega_1 = (1 - beta/2) Omega_bar, Omega_2 = beta Omega_bar / 2,
Omega_3 = (1 + beta/2) Omega_bar), not from the solver's coefficient table.
"""

from __future__ import annotations

import re
from types import SimpleNamespace

import numpy as np
import pytest
from scipy.optimize import brentq

from flexbooster.memo.stability import (
    FAMILIES,
    ShellModes,
    TooManyRootsError,
    excitation,
    excitation_curves,
    unstable_frequencies,
)

OMEGA_1 = 113.5  # rad/s, of the order of the memo case's omega_1
W_PSI = 1.2 / OMEGA_1  # pitch frequency in units of omega_1
LOADED = np.array([1.0, 2.76, 5.40])  # synthetic loaded-beam frequencies alpha_r Omega_bar


def params(x):
    """Smooth synthetic beta(Omega) ~ sqrt(a) = 2 omega_psi / Omega (plus a q^2-like term) and
    alpha_r = loaded_r / Omega_bar (the gamma -> 0 behaviour of the beam exponents)."""
    x = np.asarray(x, dtype=float)
    beta = 2 * W_PSI / x * (1 + 0.01 * (2 * W_PSI / x) ** 2)
    return beta, LOADED[None, :] / x[:, None]


def omegas(x):
    """Omega_1..3 from eqs. (7.2-1)..(7.2-3) as printed there (vectorised over x)."""
    b = params(x)[0]
    return {1: (1 - b / 2) * x, 2: b * x / 2, 3: (1 + b / 2) * x}


def family_excitation(fam, i, p, r, s, x):
    """Left-hand side of each family, written from the memo's equations (7.3-*) directly."""
    x = np.asarray(x, dtype=float)
    om = omegas(x)
    if fam in (1, 7):
        return om[i]
    if fam in (2, 13):
        return np.abs((params(x)[1][:, r - 1] + s) * x)
    if fam == 3:
        return x
    if fam in (4, 12):
        return 2 * om[i]
    if fam in (5, 10):
        return np.abs(om[i] + om[p])
    if fam in (6, 11):
        return np.abs(om[i] - om[p])
    return np.abs(x + om[i]) if fam == 8 else np.abs(x - om[i])


def small_modes():
    """A handful of shell modes of each set, spread over the range of the excitations."""
    rows = []
    for d in (1, 2):
        for j, k, m, w in [
            (0, 1, 1, 0.7),
            (0, 2, 1, 3.1),
            (1, 0, 1, 0.9),
            (2, 0, 2, 4.3),
            (1, 0, 2, 11.7),
            (1, 1, 1, 1.3),
            (1, 2, 2, 2.2),
            (2, 1, 3, 6.9),
            (3, 2, 1, 9.4),
            (2, 3, 1, 15.2),
        ]:
            rows.append((d, j, k, m, w * (1.0 if d == 1 else 1.37)))
    c = np.array(rows)
    return ShellModes(
        c[:, 0].astype(int), c[:, 1].astype(int), c[:, 2].astype(int), c[:, 3].astype(int), c[:, 4]
    )


RANGE = (5.0, 2000.0)  # rad/s, the memo case's Omega range
R, S = 3, 4
#: Keyword arguments of unstable_frequencies for the synthetic case (Omega in units of omega_1).
SOLVE = dict(Omega_bar_range=(RANGE[0] / OMEGA_1, RANGE[1] / OMEGA_1), omega_1=OMEGA_1, R=R, S=S,
             gamma=0.05, K=0.5)


def brute_force(modes):
    curves = excitation_curves(R, S)
    x = np.geomspace(RANGE[0] / OMEGA_1, RANGE[1] / OMEGA_1, 40_001)
    roots = set()
    for c in range(len(curves)):
        idx = tuple(int(getattr(curves, f)[c]) for f in ("family", "i", "p", "r", "s"))
        sampled = family_excitation(*idx, x)
        for t in modes.subset(FAMILIES[idx[0]][1]):
            target = modes.omega_bar[t]
            e = sampled - target
            for n in np.flatnonzero(np.sign(e[:-1]) * np.sign(e[1:]) < 0):
                root = brentq(
                    lambda xx, idx=idx, target=target: (
                        float(family_excitation(*idx, np.array([xx]))[0]) - target
                    ),
                    x[n],
                    x[n + 1],
                    xtol=1e-14,
                    rtol=1e-15,
                )
                roots.add((int(t), round(root, 9)))
    return roots


def test_same_roots_as_brute_force_scan():
    modes = small_modes()
    table = unstable_frequencies(modes, params, **SOLVE)
    mode_id = {
        (d, j, k, m): n
        for n, (d, j, k, m) in enumerate(
            zip(modes.cylinder, modes.j, modes.k, modes.branch, strict=True)
        )
    }
    found = {
        (mode_id[(d, j, k, m)], round(x, 9))
        for d, j, k, m, x in zip(
            table.cylinder, table.j, table.k, table.branch, table.Omega_bar, strict=True
        )
    }
    reference = brute_force(modes)
    assert len(table) > 50  # the test exercises many families
    assert found == reference


def test_every_root_satisfies_its_equation():
    """Residual below 1e-9 in Omega/omega_1, re-evaluated from the memo's equations."""
    modes = small_modes()
    table = unstable_frequencies(modes, params, **SOLVE)
    for n in range(len(table)):
        lhs = family_excitation(
            int(table.family[n]),
            int(table.i[n]),
            int(table.p[n]),
            int(table.r[n]),
            int(table.s[n]),
            np.array([table.Omega_bar[n]]),
        )[0]
        assert abs(lhs - table.shell_omega_bar[n]) < 1e-9
    assert np.all((table.Omega >= RANGE[0]) & (table.Omega <= RANGE[1]))
    assert np.all(np.diff(table.Omega) >= 0)


def test_coincident_curves_are_reported_once():
    """Omega_bar + Omega_2 = Omega_3 and |Omega_bar - Omega_2| = Omega_1 identically (7.2-1..3):
    family 8 (i = 2) and 9 (i = 2) give the same roots as family 7 (i = 3, i = 1)."""
    modes = small_modes()
    table = unstable_frequencies(modes, params, **SOLVE)
    key = list(
        zip(
            table.cylinder,
            table.j,
            table.k,
            table.branch,
            np.round(table.Omega_bar, 9),
            strict=True,
        )
    )
    assert len(key) == len(set(key))
    fam7 = table.family == 7
    # every family-7 root through Omega_1 is also a family-9 (i = 2) root, through Omega_3 a
    # family-8 (i = 2) root (the shell frequencies here are far above Omega_2 ~ 0.02)
    for i, partner in ((1, "9(i=2)"), (3, "8(i=2)")):
        rows = np.flatnonzero(fam7 & (table.i == i))
        assert rows.size > 0
        assert all(partner in table.also[n] for n in rows)
    assert not np.any(np.isin(table.family, (8, 9)) & np.isin(table.i, (2,)))


def test_curve_table_counts():
    """Families 1, 4, 7, 8, 9, 12: i = 1..3; 5, 6, 10, 11: pairs i < p (3 each); 3: one curve;
    2, 13: R (2S + 1) curves each."""
    curves = excitation_curves(R=2, S=3)
    counts = {f: int((curves.family == f).sum()) for f in FAMILIES}
    assert counts == {
        1: 3,
        2: 14,
        3: 1,
        4: 3,
        5: 3,
        6: 3,
        7: 3,
        8: 3,
        9: 3,
        10: 3,
        11: 3,
        12: 3,
        13: 14,
    }


def test_excitation_matches_memo_equations_on_a_grid():
    curves = excitation_curves(R, S)
    x = np.geomspace(0.05, 15, 7)
    beta, alpha = params(x)
    E = excitation(curves, x, beta, alpha)
    for c in range(len(curves)):
        fam, i, p, r, s = (int(getattr(curves, f)[c]) for f in ("family", "i", "p", "r", "s"))
        expected = family_excitation(fam, i, p, r, s, x)
        # differences such as Omega_3 - Omega_1 cancel: absolute 1e-13 in units of omega_1
        np.testing.assert_allclose(E[c], expected, rtol=1e-14, atol=1e-13)


@pytest.mark.parametrize(
    ("gamma", "K", "family", "k", "active"),
    [
        (0.05, 0.5, 1, 1, True),  # psi'' drives k = 1 (delta_1k)
        (0.05, 0.5, 1, 2, False),
        (0.05, 0.5, 7, 1, True),
        (0.05, 0.5, 12, 2, True),  # psi-dot^2 drives k = 2 (delta_2k)
        (0.05, 0.5, 12, 1, False),
        (0.05, 0.5, 4, 0, True),  # psi-dot^2 drives k = 0
        (0.0, 0.5, 3, 0, False),  # no pulsation: no cos(Omega tau) forcing
        (0.05, 0.5, 3, 0, True),
        (0.05, 0.0, 8, 1, False),  # T0 gamma sin(K psi) vanishes with K = 0
    ],
)
def test_active_versus_listed(gamma, K, family, k, active):
    from flexbooster.memo.stability import _active

    i = np.array([2]) if family in (1, 7, 12, 4, 8) else np.array([0])
    got = _active(np.array([family]), i, np.array([0]), np.array([1]), np.array([k]), gamma, K)
    assert bool(got[0]) is active


def test_no_pulsation_silences_omega_1_and_3():
    """A_1, A_3 are proportional to q = gamma a / 2 (4.2-7b, d): with gamma = 0 only Omega_2
    terms of psi remain, so roots through Omega_1 or Omega_3 are 'listed'."""
    from flexbooster.memo.stability import _active

    fam = np.array([7, 7, 7])
    got = _active(
        fam, np.array([1, 2, 3]), np.zeros(3, int), np.ones(3, int), np.ones(3, int), 0.0, 0.5
    )
    assert got.tolist() == [False, True, False]


@pytest.mark.slow
def test_active_flags_match_the_forcing_computed_from_its_definition(memo_results):
    """The 'active' column of the memo case against the resonant forcing of each root
    computed by quadrature of the forcing functions (3.0-3, 5.3-4) on the shape functions
    (responses.secular_rates): active roots have a relative forcing above 1e-17, the others
    below 1e-22 (round-off). Families 2 and 13 (beam harmonics, one Hill solve per root) are
    left out here; their selection is delta_1k only.  (The pipeline's table replaces this
    structural flag by severity_rel >= threshold: tests/test_severity.py.)"""
    from flexbooster.memo.responses import excitation_parameters, secular_rates

    res = memo_results
    n, (lo, hi) = res.model.truncation, res.model.omega_range
    modes = ShellModes(res.shell.cylinder, res.shell.j, res.shell.k, res.shell.branch,
                       res.shell.omega_bar)
    table = unstable_frequencies(  # the structural flag, as the solver sets it
        modes, excitation_parameters(res.model, res.beam_action),
        Omega_bar_range=(lo / res.omega_1, hi / res.omega_1), omega_1=res.omega_1, R=n.R,
        S=n.S, gamma=res.model.gamma, K=res.model.K)
    rows = [row for row in table.to_rows() if row["family"] not in (2, 13)]
    rates = secular_rates(res.model, rows, beam_amplitude=0.0)
    for row, rate in zip(rows, rates, strict=True):
        if row["forcing"] == "active":
            assert rate["relative"] > 1e-17, row
        elif row["k"] <= 2:  # 'listed' with a forcing that could exist: must be round-off
            assert rate["relative"] < 1e-22, row


def test_campbell_diagram_draws_the_significant_roots_and_their_shell_lines():
    """The figure's data, not its picture: one marker per significant root (default:
    active forcing) at (Omega, shell frequency) in Hz (= units of omega_1 x omega_1 / 2 pi,
    exact to 1e-15), one horizontal line per shell frequency holding such a root; another mask
    (a severity threshold) selects other roots; a mask of the wrong shape is refused."""
    import pytest

    from flexbooster.memo.charts import campbell_data
    from flexbooster.present.plotting.stability import campbell_diagram

    modes = small_modes()
    table = unstable_frequencies(modes, params, **SOLVE)
    shell = SimpleNamespace(omega_bar=modes.omega_bar)
    data = campbell_data(params=params, omega_range=RANGE, omega_1=OMEGA_1, shell=shell,
                         table=table, R=R, S=S, n_points=300)
    hz = OMEGA_1 / (2 * np.pi)
    for mask in (None, ~data.root_active):
        chosen = data.root_active if mask is None else mask
        fig = campbell_diagram(data, significant=mask)
        ax = fig.axes[0]
        (roots,) = [line for line in ax.get_lines() if "root" in line.get_label()]
        assert len(roots.get_xdata()) == int(chosen.sum())
        np.testing.assert_allclose(roots.get_ydata(), data.root_shell_omega_bar[chosen] * hz,
                                   rtol=1e-15)
        segments = ax.collections[0].get_segments()
        np.testing.assert_allclose(sorted(seg[0, 1] for seg in segments),
                                   np.unique(data.root_shell_omega_bar[chosen]) * hz,
                                   rtol=1e-15)
    with pytest.raises(ValueError, match="significant.shape"):
        campbell_diagram(data, significant=np.ones(3, dtype=bool))


def _labels(table):
    """Every (shell mode, family, i, p, r, s) of the table, the merged 'also' entries included."""
    import re

    out = {}
    for n in range(len(table)):
        mode = (int(table.cylinder[n]), int(table.j[n]), int(table.k[n]), int(table.branch[n]))
        names = [
            (
                int(table.family[n]),
                int(table.i[n]),
                int(table.p[n]),
                int(table.r[n]),
                int(table.s[n]),
            )
        ]
        for item in filter(None, table.also[n].split(", ")):
            fam = int(re.match(r"\d+", item).group())
            idx = dict(re.findall(r"\((\w)=(-?\d+)\)", item))
            names.append((fam, *(int(idx.get(c, 0)) for c in "iprs")))
        for name in names:
            out.setdefault((mode, name), []).append(float(table.Omega_bar[n]))
    return out


@pytest.mark.slow
def test_memo_case_same_roots_as_brute_force_on_sampled_curves(memo_results):
    """Acceptance on the memo case: for two curves of every family (sampled with a
    fixed seed), every root against every shell frequency of its set found by a brute-force
    scan -- the equation sampled on a grid ten times finer than the solver's, scipy brentq on each
    sign change -- is in the table (its own row or merged into a coinciding family's), and the
    table has no other root of those curves."""
    from flexbooster.memo.responses import excitation_parameters

    res = memo_results
    case = res.case
    t, n = case.thrust, case.truncation
    prm = excitation_parameters(res.model, res.beam_action)
    modes = ShellModes(
        res.shell.cylinder, res.shell.j, res.shell.k, res.shell.branch, res.shell.omega_bar
    )
    table = res.stability
    found = _labels(table)
    curves = excitation_curves(n.R, n.S)
    rng = np.random.default_rng(6)
    chosen = [int(c) for f in FAMILIES for c in rng.choice(np.flatnonzero(curves.family == f), 2)]
    x = np.geomspace(t.omega_min, t.omega_max, 20_001) / res.omega_1
    beta, alpha = prm(x)
    E = excitation(curves, x, beta, alpha)
    checked = 0
    for c in chosen:
        name = tuple(int(getattr(curves, f)[c]) for f in ("family", "i", "p", "r", "s"))
        one = type(curves)(*(getattr(curves, f)[c : c + 1] for f in curves.__dataclass_fields__))
        for m in modes.subset(FAMILIES[name[0]][1]):
            target = modes.omega_bar[m]
            e = E[c] - target
            mode = (int(modes.cylinder[m]), int(modes.j[m]), int(modes.k[m]), int(modes.branch[m]))
            brute = []
            for k in np.flatnonzero(np.sign(e[:-1]) * np.sign(e[1:]) < 0):

                def g(xx, one=one, target=target):
                    b_, a_ = prm(np.array([xx]))
                    return float(excitation(one, np.array([xx]), b_, a_)[0, 0]) - target

                brute.append(brentq(g, x[k], x[k + 1], xtol=1e-13))
            ours = sorted(found.get((mode, name), []))
            assert len(ours) == len(brute), (name, mode, ours, brute)
            np.testing.assert_allclose(ours, sorted(brute), rtol=1e-9)
            checked += len(brute)
    assert checked > 100


def test_too_many_roots_is_a_clear_error_not_a_memory_crash():
    modes = small_modes()
    with pytest.raises(TooManyRootsError, match=r"exceed max_roots = 10; reduce the shell modes"):
        unstable_frequencies(modes, params, **SOLVE, max_roots=10)


@pytest.mark.parametrize(
    ("call", "words"),
    [
        (lambda: excitation_curves(2, -1), "S = -1"),
        (lambda: excitation_curves(-1, 2), "R = -1"),
        (lambda: excitation(excitation_curves(1, 1), np.array([1.0]), np.array([np.nan]),
                            np.zeros((1, 1))), "beta: must be finite"),
        (lambda: excitation(excitation_curves(1, 1), np.array([1.0, 2.0]), np.array([0.1]),
                            np.zeros((2, 1))), "beta: shape"),
    ],
)
def test_bad_arguments_raise_naming_the_parameter(call, words):
    # no NaN returned silently, no garbage accepted
    with pytest.raises(ValueError, match=re.escape(words)):
        call()
