"""Severity of the roots of the stability table, bands, truncation independence.

Tiers: exact limits and scalings (gamma = 0, linearity in gamma, psi0, beam amplitude);
independent models (direct solve_ivp integration of the forced modal ODE with the forcing built
by quadrature from its definition; an independent monodromy of the beam for the Floquet
sidebands; a free-free bar driven by a pulsating edge load for family 3; the project's own
``secular_rates``); invariants (S = 3 against S = 10, exact against first-order continued
fractions, bands partition the active roots).  Every expected value names its source and
tolerance.
"""

from __future__ import annotations

import io
import tomllib
from dataclasses import replace

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import flexbooster
from flexbooster.case import memo_case_text
from flexbooster.memo.beam_action import beam_system, hill_exponents, loaded_frequencies
from flexbooster.memo.responses import (
    excitation_parameters,
    make_excitation,
    modal_groups,
    secular_rates,
)
from flexbooster.memo.severity import (
    FAMILY_CAUSES,
    floquet_vectors,
    resonance_bands,
    root_severity,
)
from harness import assert_close

#: Basis rows (responses.BASIS, then q_b, q_b'') that carry each family's forcing (memo 6.2).
_THRUST, _PSI, _PSI_SQ, _T_PSI = (0, 1, 2), (3, 5), (4,), (5,)
SOURCE = {1: _PSI, 3: _THRUST, 4: _PSI_SQ, 5: _PSI_SQ, 6: _PSI_SQ, 7: _PSI, 8: _T_PSI,
          9: _T_PSI, 10: _PSI_SQ, 11: _PSI_SQ, 12: _PSI_SQ}  # 2 and 13: the beam rows


def _case_dict(**truncation):
    d = tomllib.loads(memo_case_text())
    if truncation:
        d["thrust"]["n_omega"] = 120
        d["truncation"] = truncation
    return d


@pytest.fixture(scope="module")
def small():
    """A reduced memo case (fast): 120 Omega points, M = 6, N = 4 shell modes, N = 4, S = 3."""
    case = flexbooster.load_case(_case_dict(M1=6, N1=4, M2=6, N2=4, N=4, S=3, R=3))
    res = flexbooster.analyze(case, figures=False, vehicle=False)
    return res, excitation_parameters(res.model, res.beam_action)


@pytest.fixture(scope="module")
def default():
    """The memo case (S = 10) and the same with S = 3."""
    out = {}
    for S in (10, 3):
        d = _case_dict()
        d["truncation"]["S"] = S
        out[S] = flexbooster.analyze(flexbooster.load_case(d), figures=False, vehicle=False)
    return out


def _mode(model, d, j, k, N):
    """Modal system of one shell mode from the quadrature of the definitions (modal_groups)."""
    tr = model.truncation
    kind = "0k" if j == 0 else ("j0" if k == 0 else "jk")
    g = [x for x in modal_groups(model.shell, (tr.M1, tr.M2), (tr.N1, tr.N2), N)
         if x.cylinder == d and x.kind == kind][0]
    idx = int(np.flatnonzero((g.j == j) & (g.k == k))[0])
    lam, vec = np.linalg.eig(np.linalg.solve(g.mass[idx], g.stiff[idx]))
    order = np.argsort(lam.real)
    Phi = vec.real[:, order]
    P = np.linalg.solve(Phi, np.linalg.inv(g.mass[idx]))  # y'' + omega^2 y = P F
    return np.sqrt(lam.real[order]), Phi, P, g.forcing[:, idx, :]


def _fit_slope(tau, z):
    """|weighted least-squares slope| of z(tau), window sin^4(pi tau / tau_max)."""
    w = np.sin(np.pi * tau / tau[-1]) ** 4
    tc = tau - np.sum(w * tau) / np.sum(w)
    return abs(np.sum(w * tc * z) / np.sum(w * tc**2))


def _basis(ex, rows):
    """The basis functions of the rows at time t from their definitions (responses.BASIS):
    T = 1 - gamma cos(Omega_bar tau) (4.2-1a), psi = sum A_i cos(Omega_i tau) (4.2-6), the beam
    coordinates q = Re sum_s C^(s) e^{i nu_s tau} (4.1-10/11) and q''."""
    Ob, g, A, W = ex.Omega_bar, ex.gamma, ex.A, ex.Omega_i
    C, nu = ex.beam_amp, ex.beam_freq

    def basis(t):
        out = np.zeros(rows.size)
        T = 1.0 - g * np.cos(Ob * t)
        for n, row in enumerate(rows):
            if row < 3:
                out[n] = (0.5 * ex.T0_bar * T, ex.strain * T,
                          ex.strain * g * Ob**2 * np.cos(Ob * t))[row]
            elif row == 3:
                out[n] = -np.sum(A * W**2 * np.cos(W * t))
            elif row == 4:
                out[n] = np.sum(A * W * np.sin(W * t)) ** 2
            elif row == 5:
                out[n] = 0.5 * ex.K * ex.T0_bar * T * np.sum(A * np.cos(W * t))
        if rows[0] >= 6:  # the beam rows q_b, then q_b''
            e = np.exp(1j * nu * t)
            q = np.real(e @ C)
            qdd = np.real((-(nu**2) * e) @ C)
            out = np.concatenate([q, qdd])[rows - 6]
        return out

    return basis


def _direct_rate(res, params, n):
    """Growth of the normal coordinate's amplitude per unit tau by solve_ivp (DOP853).

    The forcing is f(tau) = P_m F^T b(tau): F from the Gauss-Legendre quadrature of the
    definitions (modal_groups), b(tau) the time functions of the excitation (psi, T, beam
    coordinates evaluated in the time domain; the beam Floquet vector from Hill's determinant),
    restricted to the family's source rows; then Z = (y' + i omega y) e^{-i omega tau} and the
    envelope slope |dZ/dtau| / omega.
    """
    st, model, sv = res.stability, res.model, res.case.severity
    fam = int(st.family[n])
    ex = make_excitation(model, float(st.Omega[n]), psi0=sv.psi0,
                         beam_amplitude=sv.beam_amplitude, beam_mode=max(int(st.r[n]), 1),
                         params=params)
    omega, _, P, F = _mode(model, int(st.cylinder[n]), int(st.j[n]), int(st.k[n]), ex.N)
    m = int(st.branch[n]) - 1
    w = omega[m]
    nq = ex.N + 1
    rows = np.array(SOURCE.get(fam, tuple(range(6, 6 + 2 * nq))))
    coef = F[rows] @ P[m]  # (rows,): forcing of y per unit basis function
    nu, c = ex.harmonics()
    amp = np.abs(coef @ c[rows])
    other = (amp > 1e-12 * amp.max()) & (np.abs(np.abs(nu) - w) > 1e-6 * w)
    gap = np.min(np.abs(np.abs(nu[other]) - w)) if other.any() else w
    tau_max = min(max(40 * np.pi / w, 8.0 / gap), 2000.0)
    basis = _basis(ex, rows)

    def rhs(t, z):
        return [z[1], -(w**2) * z[0] + coef @ basis(t)]

    tau = np.linspace(0.0, tau_max, 4001)
    scale = np.abs(coef @ np.abs(c[rows])).sum() / w**2
    sol = solve_ivp(rhs, (0.0, tau_max), [0.0, 0.0], method="DOP853", t_eval=tau,
                    rtol=1e-9, atol=1e-12 * scale)
    y, yd = sol.y
    z = (yd + 1j * w * y) * np.exp(-1j * w * tau)
    # Z = Z0 + (G/2) tau + bounded terms at the known detunings of the other harmonics
    freqs = np.unique(np.abs(nu[other]))
    cols = [np.ones_like(tau), tau, np.exp(-2j * w * tau)]
    cols += [np.exp(1j * (f - w) * tau) for f in freqs] + [np.exp(-1j * (f + w) * tau)
                                                           for f in freqs]
    fit = np.linalg.lstsq(np.stack(cols, axis=1), z, rcond=None)[0]
    return abs(fit[1]) / w


@pytest.mark.slow
@pytest.mark.parametrize("family", [1, 2, 3, 4, 5, 6, 7, 8, 10, 11, 12, 13])
def test_severity_against_direct_integration(small, family):
    """Most severe root of each family (reduced memo case) against solve_ivp of the forced
    modal ODE, forcing by quadrature of its definition: envelope slope within 2 % (the
    required accuracy); family 9 has no root in the range."""
    res, params = small
    st, rate = res.stability, res.severity.roots.rate
    cand = np.flatnonzero((st.family == family) & (rate > 0))
    assert cand.size, f"family {family}: no forced root"
    n = cand[np.argmax(rate[cand])]
    assert_close(rate[n], _direct_rate(res, params, n), rtol=0.02,
                 source="solve_ivp DOP853 of the forced modal ODE (envelope slope)",
                 name=f"family {family} rate at Omega = {st.Omega[n]:.6g} rad/s")


def test_severity_against_secular_rates(small):
    """20 roots (the most severe and a random sample) against the project's secular_rates
    (Excitation.harmonics with the beam vector from Hill's determinant, per root): 1e-6."""
    res, params = small
    st, rate = res.stability, res.severity.roots.rate
    rng = np.random.default_rng(13)
    forced = np.flatnonzero(rate > 1e-9 * rate.max())  # above secular_rates' round-off
    pick = np.unique(np.concatenate([np.argsort(-rate)[:10], rng.choice(forced, 10)]))
    rows = [st.to_rows()[n] for n in pick]
    ref = [x["secular_rate"] for x in secular_rates(res.model, rows, params=params)]
    assert_close(rate[pick], ref, rtol=1e-6, source="responses.secular_rates (per root)")


def test_surface_severity_is_the_rate_in_metres_per_second(small):
    """severity = rate L omega_1 max |Phi_c| (tau = omega_1 t, x = Phi y in units of L, unit
    shape-function maximum): checked against the eigenvectors of one mode, 1e-9."""
    res, _ = small
    st, sv = res.stability, res.severity.roots
    n = int(np.argmax(sv.severity))
    _, Phi, _, _ = _mode(res.model, int(st.cylinder[n]), int(st.j[n]), int(st.k[n]), 4)
    phi = Phi[:, int(st.branch[n]) - 1]
    expected = sv.rate[n] * res.model.mass.L * res.omega_1 * np.abs(phi).max() / \
        np.linalg.norm(phi)  # np.linalg.eig normalises to unit length, as modal_basis
    assert_close(sv.severity[n], expected, rtol=1e-9, source="definition (docs/theory/severity.md)")


@pytest.mark.slow
def test_family_3_is_the_pulsating_edge_load_of_a_free_free_bar():
    """Family 3 against an independent model: the axial (k = 0) modes of a free-free cylinder
    (a bar: rho h u_tt = E h / (1 - nu^2) u_xx, N_x = -T(t) at the aft edge, 0 at the other)
    driven by the edge load, integrated directly (solve_ivp).  Memo case with cylinder 2 a thin
    ring of the same radius (L2 = L1 / 500) and nu = 0.01 (Poisson coupling to W ~ nu^2):
    growth of the axial amplitude within 2 %, frequency within 1 %."""
    d = _case_dict(M1=4, N1=2, M2=2, N2=2, N=4, S=2, R=2)
    d["booster"]["nu"] = 0.01
    d["booster"]["cylinder2"] = {"radius": "5.05 m", "half_length": "0.042 m"}
    d["thrust"].update(omega_min="5 rad/s", omega_max="1500 rad/s")
    res = flexbooster.analyze(flexbooster.load_case(d), figures=False, vehicle=False)
    st, sv, case = res.stability, res.severity.roots, res.case
    b = case.booster
    E, nu, rho, h, l1 = b.E, b.nu, b.rho, b.thickness, 2 * b.cylinder1.half_length
    c = np.sqrt(E / (rho * (1 - nu**2)))
    m_j = rho * h * l1 / 2  # modal mass per unit circumference of cos(j pi x / l1)
    g, T0 = case.thrust.gamma, case.T0
    checked = 0
    for j in (1, 2, 3):
        sel = np.flatnonzero((st.family == 3) & (st.cylinder == 1) & (st.j == j)
                             & (np.asarray(sv.mode_type) == "axial"))
        assert sel.size == 1, f"j = {j}: one axial family-3 root of cylinder 1"
        n = sel[0]
        w = j * np.pi * c / l1  # free-free bar frequency (rad/s)
        assert_close(st.Omega[n], w, rtol=0.01, source="free-free bar frequency j pi c / l")

        def rhs(t, z, w=w):  # m q'' + m w^2 q = -T(t) phi(0), phi(0) = 1 (edge-load work)
            return [z[1], -(w**2) * z[0] + T0 * (1 - g * np.cos(w * t)) / m_j]

        t = np.linspace(0.0, 400 * np.pi / w, 4001)
        sol = solve_ivp(rhs, (0, t[-1]), [0.0, 0.0], method="DOP853", t_eval=t, rtol=1e-10,
                        atol=1e-14)
        z = (sol.y[1] + 1j * w * sol.y[0]) * np.exp(-1j * w * t)
        growth = _fit_slope(t, z) / w  # m/s: the amplitude of u grows like t
        assert_close(sv.severity[n], growth, rtol=0.02,
                     source="free-free bar under a pulsating edge load, solve_ivp")
        assert_close(growth, g * T0 / (2 * m_j * w), rtol=1e-3,
                     source="closed form gamma T0 / (2 m_j omega_j) (the integration itself)")
        checked += 1
    assert checked == 3


def _monodromy_harmonics(system, Omega_bar, gamma, mu, S):
    """Floquet harmonics C^(s) of the beam solution with exponent near mu, independently: the
    monodromy matrix by solve_ivp over one period, its eigenvector, the solution over one
    period and the FFT of its periodic part q e^{-i mu tau} (unit norm)."""
    n = system.N + 1
    A0, B = system.A0, system.B
    T = 2 * np.pi / Omega_bar

    def rhs(t, y):
        Y = y.reshape(2 * n, -1)
        A = A0 - gamma * np.cos(Omega_bar * t) * B
        return np.concatenate([Y[n:], -A @ Y[:n]]).ravel()

    sol = solve_ivp(rhs, (0, T), np.eye(2 * n).ravel(), method="DOP853", rtol=1e-12,
                    atol=1e-14)
    mono = sol.y[:, -1].reshape(2 * n, 2 * n)
    rho, vec = np.linalg.eig(mono)
    e = np.argmin(np.abs(rho - np.exp(1j * mu * T)))
    exact = np.angle(rho[e]) / T  # the exponent itself, mod Omega_bar, nearest mu
    mu = exact + np.round((mu - exact) / Omega_bar) * Omega_bar
    M = 64
    t = np.arange(M) * T / M
    sol = solve_ivp(rhs, (0, T), vec[:, e], method="DOP853", rtol=1e-12, atol=1e-14,
                    t_eval=t)
    p = sol.y[:n] * np.exp(-1j * mu * t)[None, :]
    coef = np.fft.fft(p, axis=1) / M  # p = sum_s C_s e^{i s Omega_bar tau}
    C = np.stack([coef[:, s % M] for s in range(-S, S + 1)])
    return C / np.linalg.norm(C), mu


@pytest.mark.slow
def test_family_13_sidebands_follow_the_floquet_harmonics():
    """severity(|s| + 1) / severity(|s|) of family 13 at fixed (r, mode) against the ratio of
    the forcings built from the Floquet harmonics of an independent monodromy (solve_ivp over
    one period + FFT), each at its own root: 1 %.  A strongly pulsed case (gamma = 0.5,
    F0 = 20 MN) so that the sidebands are well above what the FFT of a solve_ivp solution
    (rtol 1e-12) resolves (harmonics below 1e-9 of the vector are skipped)."""
    d = _case_dict(M1=4, N1=3, M2=4, N2=3, N=3, S=3, R=3)
    d["thrust"].update(gamma=0.5, F0="20 MN")
    res = flexbooster.analyze(flexbooster.load_case(d), figures=False, vehicle=False)
    params = excitation_parameters(res.model, res.beam_action)
    st, model = res.stability, res.model
    sv = root_severity(model, st, params, S=8)  # the case's S = 3 truncates the sidebands
    system = beam_system(model, 3)
    nq = system.N + 1
    keys = list(zip(st.cylinder.tolist(), st.j.tolist(), st.k.tolist(), st.branch.tolist(),
                    strict=True))
    roots = {}
    for x in np.flatnonzero((st.family == 13) & (sv.rate > 0)):
        roots.setdefault((int(st.r[x]), keys[x]), {})[int(st.s[x])] = x
    checked = 0
    for (r, key), by_s in sorted(roots.items()):
        for s0 in (0, 1, -1):
            s1 = s0 + (1 if s0 >= 0 else -1)
            if s0 not in by_s or s1 not in by_s:
                continue
            omega, _, P, F = _mode(model, key[0], key[1], key[2], system.N)
            coef = F @ P[key[3] - 1]
            forcing, size = [], np.inf
            for s in (s0, s1):
                x = by_s[s]
                ob = st.Omega_bar[x]
                C, mu = _monodromy_harmonics(system, ob, model.gamma,
                                             params.alpha(ob)[0, r - 1] * ob, 3)
                f = (mu + s * ob) ** 2
                size = min(size, np.abs(C[s + 3]).max())
                forcing.append(abs(C[s + 3] @ (coef[6:6 + nq] - f * coef[6 + nq:6 + 2 * nq])))
            if size < 1e-9:
                continue
            assert_close(sv.severity[by_s[s1]] / sv.severity[by_s[s0]], forcing[1] / forcing[0],
                         rtol=0.01, source="independent monodromy Floquet harmonics",
                         name=f"r = {r}, s = {s0} -> {s1}, mode {key}")
            checked += 1
    assert checked >= 3, checked


def test_floquet_vectors_against_hill_eigenvectors(small):
    """Continued-fraction Floquet vectors (first-order path and exact path) against Hill's
    eigenvectors (hill_exponents, one 2n(2S+1) eigenproblem per point): |C| to 1e-6."""
    res, params = small
    system = beam_system(res.model, 4)
    Omega = np.array([20.0, 150.0, 700.0, 1900.0])
    hill = hill_exponents(system, Omega, res.model.gamma, 3)
    ob = Omega / res.omega_1
    for e in range(0, 10, 2):
        mu = hill.alpha[:, e].real * ob
        ref = np.abs(hill.C[:, e])
        for kappa in (1e-4, 0.0):  # default (first order where weak) and exact everywhere
            C, mu_got = floquet_vectors(system.A0, system.B, mu * (1 + 1e-6), ob,
                                        res.model.gamma, 3, kappa_max=kappa)
            assert_close(np.abs(C), ref, rtol=0, atol=1e-6, source="Hill eigenvectors (4.1-12)")
            assert_close(mu_got, mu, rtol=1e-9, source="Hill exponents (from mu (1 + 1e-6))")


def test_floquet_vectors_of_one_harmonic_per_point_are_those_of_the_full_solution(small):
    """floquet_vectors(s=...) (what root_severity asks for: C^(s) of each root only) returns
    the rows C[p, s_p + S] of the full solution, bit for bit, on both paths (first order and
    exact), and refuses a harmonic beyond S."""
    res, _ = small
    system = beam_system(res.model, 4)
    ob = np.array([20.0, 150.0, 700.0, 1900.0, 2400.0]) / res.omega_1
    mu = loaded_frequencies(system).real[[0, 1, 2, 1, 0]] * (1 + 1e-6)  # alpha Omega_bar
    s = np.array([0, -3, 2, 3, -1])
    for kappa in (1e-4, 0.0):
        C, mu_full = floquet_vectors(system.A0, system.B, mu, ob, res.model.gamma, 3,
                                     kappa_max=kappa)
        Cs, mu_s = floquet_vectors(system.A0, system.B, mu, ob, res.model.gamma, 3,
                                   kappa_max=kappa, s=s)
        np.testing.assert_array_equal(Cs, C[np.arange(s.size), s + 3])
        np.testing.assert_array_equal(mu_s, mu_full)
    with pytest.raises(ValueError, match="s: must be integers"):
        floquet_vectors(system.A0, system.B, mu, ob, res.model.gamma, 2, s=s)


def test_exact_limits_and_scalings(small):
    """Exact structure (memo 6.2): family 3 is linear in gamma and 0 at gamma = 0; the pitch
    terms psi'' (family 7) scale like psi0, psi'^2 (family 4) like psi0^2, the beam terms
    (13) like the beam amplitude; psi0 = 0 leaves family 3 unchanged.  1e-9."""
    res, params = small
    st, model = res.stability, res.model
    base = root_severity(model, st, params)
    f3, f4, f7, f13 = (st.family == f for f in (3, 4, 7, 13))
    twice = root_severity(replace(model, gamma=2 * model.gamma), st, params)
    assert_close(twice.rate[f3], 2 * base.rate[f3], rtol=1e-9, source="T'' ~ gamma (4.2-1a)")
    zero = root_severity(replace(model, gamma=0.0), st, params)
    assert np.all(zero.rate[f3] == 0.0)  # exact: no pulsation, no family 3
    half = root_severity(model, st, params, psi0=0.005, beam_amplitude=2e-4)
    assert_close(half.rate[f7], 0.5 * base.rate[f7], rtol=1e-9, source="psi'' ~ psi0")
    assert_close(half.rate[f4], 0.25 * base.rate[f4], rtol=1e-9, source="psi'^2 ~ psi0^2")
    assert_close(half.rate[f13], 2 * base.rate[f13], rtol=1e-9, source="q ~ beam amplitude")
    nopsi = root_severity(model, st, params, psi0=0.0)
    assert_close(nopsi.rate[f3], base.rate[f3], rtol=1e-6, source="family 3 does not need psi")


def test_bands_partition_the_active_roots(small):
    """Invariants of the bands: every active root in exactly one band, bands sorted by
    severity, disjoint, and consecutive roots in a band within the resolution."""
    res, _ = small
    st, sev = res.stability, res.severity
    bands = sev.bands
    assert sum(b.n_roots for b in bands) == int(sev.roots.active.sum())
    assert all(a.severity >= b.severity for a, b in zip(bands, bands[1:], strict=False))
    spans = sorted((b.Omega_lo, b.Omega_hi) for b in bands)
    assert all(a[1] < b[0] for a, b in zip(spans, spans[1:], strict=False))
    om = np.sort(st.Omega[sev.roots.active])
    inside = [om[(om >= b.Omega_lo) & (om <= b.Omega_hi)] for b in bands]
    assert all(np.all(np.diff(x) <= sev.resolution * x[:-1] * (1 + 1e-12)) for x in inside)
    assert all(b.cause == FAMILY_CAUSES[b.order] for b in bands)
    wide = resonance_bands(st, sev.roots, resolution=0.5)
    assert len(wide) <= len(bands)
    with pytest.raises(ValueError, match="resolution"):
        resonance_bands(st, sev.roots, resolution=0.0)


def test_arguments_are_validated(small):
    res, params = small
    with pytest.raises(ValueError, match="psi0"):
        root_severity(res.model, res.stability, params, psi0=float("nan"))
    with pytest.raises(ValueError, match="beam_amplitude"):
        root_severity(res.model, res.stability, params, beam_amplitude=-1.0)
    with pytest.raises(ValueError, match="S = 1"):
        root_severity(res.model, res.stability, params, S=1)
    with pytest.raises(flexbooster.CaseError, match="severity.threshold"):
        d = _case_dict()
        d["severity"]["threshold"] = 2.0
        flexbooster.load_case(d)


def _keys(res, mask):
    st = res.stability
    return {(int(st.family[n]), int(st.i[n]), int(st.p[n]), int(st.r[n]), int(st.s[n]),
             int(st.cylinder[n]), int(st.j[n]), int(st.k[n]), int(st.branch[n]))
            for n in np.flatnonzero(mask)}


@pytest.mark.slow
def test_truncation_independence(default):
    """Memo case, S = 3 against S = 10: the roots with severity_rel >= 1e-6 (Jaccard >= 0.9
    required) and the top 10 bands (same peaks and modes, severity to 1e-3)."""
    a, b = default[10], default[3]
    ka = _keys(a, a.severity.roots.severity_rel >= 1e-6)
    kb = _keys(b, b.severity.roots.severity_rel >= 1e-6)
    jaccard = len(ka & kb) / len(ka | kb)
    assert jaccard >= 0.9, f"Jaccard {jaccard:.3f}"
    top_a, top_b = a.severity.bands[:10], b.severity.bands[:10]
    assert [(x.order, x.modes[0]) for x in top_a] == [(x.order, x.modes[0]) for x in top_b]
    assert_close([x.Omega_at_max for x in top_a], [x.Omega_at_max for x in top_b], rtol=1e-9,
                 source="S = 10 (the family-3 roots do not depend on S)")
    assert_close([x.severity for x in top_a], [x.severity for x in top_b], rtol=1e-3,
                 source="S = 10")


@pytest.mark.slow
def test_default_summary_shows_the_most_severe_bands_first(default):
    """The default summary: the 10 most severe bands first, Omega in rad/s and Hz, mode
    (cylinder, j, k, branch, type), family and its cause in words."""
    from rich.console import Console

    from flexbooster.present.summary import print_stability

    res = default[10]
    console = Console(file=io.StringIO(), width=260, record=True)
    print_stability(res, console)
    text = console.export_text()
    assert "10 most severe bands" in text
    for col in ("Omega rad/s", "Hz", "severity m/s", "mode (cyl, j, k, m, type)", "cause"):
        assert col in text
    lines = [x for x in text.splitlines()  # the data rows: rank 1..10 first
             if x.split() and x.split()[0].strip("│") in {str(n) for n in range(1, 11)}]
    assert len(lines) == 10
    top = res.severity.bands[0]
    m = top.modes[0]
    assert top.order == 3 and (m.cylinder, m.order, m.k, m.index) == (1, 1, 0, 1)  # axial j = 1
    assert f"{top.Omega_at_max:.6g}" in lines[0]
    assert f"{top.Omega_at_max / (2 * np.pi):.6g}" in lines[0]
    assert "thrust pulsation" in lines[0] and "axial" in lines[0]
    sev = [b.severity for b in res.severity.bands]
    assert sev == sorted(sev, reverse=True)
