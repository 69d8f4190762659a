"""Modal time responses (memo 6.1, 6.2) and the verification of the stability roots (memo 7).

References used below:
* the forcing's definition: the shell equations 3.0-2 with F1..F3 of 3.0-3 and the beam part
  5.3-4, projected on the shape functions 5.3-2/3 by a 2-D quadrature written here
  independently (Gauss-Legendre in xi, the trapezoid rule in theta, theta derivatives by FFT);
* numerical integration: scipy solve_ivp DOP853 (rtol 1e-10) of M x'' + K x = F(tau) with the
  forcing evaluated in the time domain;
* exact limits of the Duhamel integral (Meirovitch, Elements of Vibration Analysis, 1986,
  ch. 4): x'' + w^2 x = e^{i w tau} from rest is -i tau e^{i w tau}/(2 w) + i sin(w tau)/(2 w^2).
"""

from __future__ import annotations

import collections
import json
import tomllib

import numpy as np
import pytest
from numpy.polynomial.legendre import leggauss

from flexbooster.case import load_case, memo_case, memo_case_text
from flexbooster.memo import beam
from flexbooster.memo import responses as r
from flexbooster.memo.beam_action import beam_action_analysis
from flexbooster.memo.responses import closed_form
from flexbooster.memo.stability import ShellModes, unstable_frequencies
from flexbooster.model import model_from_case


def small_case(**thrust):
    """Derived model of the default geometry, few modes; optional thrust overrides (gamma, K)."""
    d = tomllib.loads(memo_case_text())
    d["thrust"].update(thrust)
    d["truncation"].update(M1=2, N1=3, M2=2, N2=3, N=2, S=2, R=2)
    return model_from_case(load_case(d))


@pytest.fixture(scope="module")
def strong_model():
    """Strong pulsation and gimbal gain so that every forcing term is well above round-off
    (q = gamma a / 2 up to 0.02: the Omega_1, Omega_3 terms of psi are not negligible)."""
    return small_case(gamma=0.4, K=4.0)


@pytest.fixture(scope="module")
def strong(strong_model):
    ex = r.make_excitation(strong_model, 300.0, psi0=0.01, beam_amplitude=1e-4)
    groups = r.modal_groups(strong_model.shell, (2, 2), (3, 3), ex.N)
    return strong_model, ex, groups


# --------------------------------------------------------------------------------------------
# Tier 1: exact limits
# --------------------------------------------------------------------------------------------
def test_resonance_safe_kernel_limits():
    """Off resonance the kernel is the bracket of 6.2-3; at nu = omega its exact limit."""
    tau = np.linspace(0.0, 40.0, 81)
    w = np.array([1.3])
    nu = np.array([0.4, -2.1, 1.3 * (1 + 1e-3)])
    k = closed_form._kernel(w, nu, tau)[0]
    memo = (np.exp(1j * nu[:, None] * tau) - np.cos(w * tau)
            - 1j * (nu[:, None] / w) * np.sin(w * tau)) / (w**2 - nu[:, None] ** 2)
    np.testing.assert_allclose(k, memo, rtol=0, atol=1e-9 * np.abs(memo).max())  # cancellation
    at = closed_form._kernel(w, w, tau)[0, 0]
    exact = -1j * tau * np.exp(1j * 1.3 * tau) / (2 * 1.3) + 1j * np.sin(1.3 * tau) / (2 * 1.3**2)
    np.testing.assert_allclose(at, exact, rtol=0, atol=1e-13)  # Meirovitch ch. 4, resonance


def test_closed_form_j0_initial_values_and_printed_form(strong):
    """Unforced, U(0) = u0, W(0) = w0 (the definition of the initial values, 6.2-4).

    The printed 6.2-8/9 lack the factor 1/(a) = 1/(a_j0 j_j0) (erratum R-3): U(0) = (a) u0.
    """
    g = strong[2][1]  # cylinder 1, j0
    M, K = g.mass, g.stiff
    c = dict(a=M[:, 0, 0], b=M[:, 0, 1], j=M[:, 1, 1], c=K[:, 0, 0], d=K[:, 0, 1],
             h=K[:, 1, 0], k=K[:, 1, 1])
    u0, w0 = np.array([1e-6, -2e-6]), np.array([3e-7, 5e-7])
    zero = np.zeros((2, 1))
    U, W = r.closed_form_j0(c, u0, w0, [0.5], zero, zero, [0.0])
    np.testing.assert_allclose(U[:, 0], u0, rtol=1e-12)
    np.testing.assert_allclose(W[:, 0], w0, rtol=1e-12)
    Up, _ = r.closed_form_j0(c, u0, w0, [0.5], zero, zero, [0.0], form="printed")
    np.testing.assert_allclose(Up[:, 0], c["a"] * c["j"] * u0, rtol=1e-12)  # (a) u0, R-3
    assert not np.allclose(Up[:, 0], u0, rtol=1e-3)


def test_edge_conditions_of_the_rebuilt_fields():
    """Shell part: v = w = u' = w'' = 0 at every edge (zero phase, 5.3-2/3); the axial force
    is N = -T(tau) T0 at the aft edge and 0 at the nose (5.3-1d, e), from u* (5.3-4a)."""
    res = r.simulate(small_case(), 250.0, 60.0, n_out=7, modes=(3, 3, 3, 3),
                     n_snapshots=0)
    ec = r.edge_conditions(res)
    scale = ec["scale"]
    assert scale > 1e-4  # metres: a visible response
    for key in ("shell_v_edges", "shell_w_edges"):
        assert ec[key] < 1e-14 * scale  # sin(0), sin(j pi) ~ j 1e-16
    assert ec["shell_u_xi_edges"] < 1e-13 * scale
    assert ec["shell_w_xixi_edges"] < 1e-12 * scale
    assert ec["N_aft_error"] < 1e-10  # relative to T0 T(tau)
    assert ec["N_nose"] < 1e-10  # relative to T0
    # what the shape functions do not give (reported in docs/theory/responses.md): v', w' at
    # the free ends (5.3-1a, b) and the beam part's bending moment nu g* cos theta / R^2
    assert ec["v_xi_ends"] > 1e-3 * scale and ec["w_xi_ends"] > 1e-3 * scale
    assert ec["M_shell_ends"] < 1e-14


# --------------------------------------------------------------------------------------------
# Tier 2/3: the forcing against its definition, closed forms against integration
# --------------------------------------------------------------------------------------------
def _definition_projection(cp, ex, d, tau):
    """Forcing of every (j, k) of cylinder d by a 2-D quadrature of its definition.

    forcing = -1/((1-nu^2) mu theta_int) int int phi [F + (1-nu^2) mu (u*,v*,w*)_tt
              - L(u*, v*, w*)], with L the left side of 3.0-2.
    """
    p = cp.shell
    nu, mu, sg, lam = p.nu, p.mu, p.sigma, p.lam(d)
    lo, hi = p.edges(d)
    x, wx = leggauss(160)
    xi = lo + (hi - lo) / 2 * (x + 1)
    wx = wx * (hi - lo) / 2
    th = np.linspace(0, 2 * np.pi, 64, endpoint=False)
    wth = 2 * np.pi / th.size
    X, TH = np.meshgrid(xi, th, indexing="ij")
    psi, psid, psidd = (float(ex.psi(tau, o)) for o in (0, 1, 2))
    T, Tdd = float(ex.thrust(tau)), float(ex.thrust(tau, 2))
    c1 = (1 - nu**2) * mu
    Tb = ex.T0_bar
    br = -Tb / 2 * T * ex.K * psi + psid**2 / lam * np.cos(TH) - psidd * X  # sin K psi ~ K psi
    F1 = c1 * (Tb / 2 * T - psidd / lam * np.cos(TH) - psid**2 * X)  # (3.0-3a), cos K psi ~ 1
    F2, F3 = c1 * br * np.sin(TH), c1 * br * np.cos(TH)  # (3.0-3b, c)
    # beam part (4.1-3, 5.3-4) with its xi-derivatives from the free-free modes directly
    N = ex.N
    q, qdd = ex.beam(np.array([tau]))[:, 0], ex.beam(np.array([tau]), 2)[:, 0]
    zeta = xi - p.a
    half = beam.free_free_eigenvalues(N) / 2
    n = np.arange(1, N + 1)

    def g(order, coef):
        modes = half[:, None] ** order * beam.mode_shape(n[:, None], zeta[None, :], order)
        lin = (xi if order == 0 else np.ones_like(xi) if order == 1 else 0 * xi)
        return coef[:N] @ modes + coef[N] * lin

    g0, g1, g2, g4, gdd = g(0, q), g(1, q), g(2, q), g(4, q), g(0, qdd)
    eps = ex.strain
    Xi = X - 0.5 * (X - p.b + 1) ** 2
    u_s = -eps / 2 * T * Xi
    u_s1 = -eps / 2 * T * (p.b - X)
    u_s2 = eps / 2 * T + 0 * X
    v_s, w_s = g0[:, None] * np.sin(TH), g0[:, None] * np.cos(TH)

    def dth(f, o):
        k = np.fft.fftfreq(th.size, 1 / th.size)
        return np.real(np.fft.ifft((1j * k) ** o * np.fft.fft(f, axis=1), axis=1))

    Lu = u_s2 + (1 - nu) * lam**2 / 2 * dth(u_s, 2) + (1 + nu) * lam / 2 * dth(
        g1[:, None] * np.sin(TH), 1) - nu * lam * g1[:, None] * np.cos(TH)
    Lv = (1 + nu) * lam / 2 * dth(u_s1, 1) + (1 - nu) / 2 * g2[:, None] * np.sin(TH) \
        + lam**2 * dth(v_s, 2) - lam**2 * dth(w_s, 1)
    lap = (g4[:, None] * np.cos(TH) + 2 * lam**2 * dth(g2[:, None] * np.cos(TH), 2)
           + lam**4 * dth(w_s, 4))
    Lw = nu * lam * u_s1 + lam**2 * dth(v_s, 1) - lam**2 * w_s - sg**2 / 12 * lap
    acc_u = -eps / 2 * Tdd * Xi
    Ru = F1 + c1 * acc_u - Lu
    Rv = F2 + c1 * gdd[:, None] * np.sin(TH) - Lv
    Rw = F3 + c1 * gdd[:, None] * np.cos(TH) - Lw
    out = {}
    for j in range(0, 3):
        s = j * np.pi * p.L / (2 * p.half_length(d)) * (X - lo)
        for k in range(0, 4):
            if j == 0 and k == 0:
                continue
            tint = 2 * np.pi if k == 0 else np.pi
            vals = []
            for comp, R_, test in (("U", Ru, np.cos(s) * np.cos(k * TH)),
                                   ("V", Rv, np.sin(s) * np.sin(k * TH)),
                                   ("W", Rw, np.sin(s) * np.cos(k * TH))):
                if (j == 0 and comp != "U") or (k == 0 and comp == "V"):
                    continue
                vals.append(-np.sum(test * R_ * wx[:, None]) * wth / (c1 * tint))
            out[(j, k)] = np.array(vals)
    return out


@pytest.mark.parametrize("d", [1, 2])
def test_forcing_equals_projection_of_definition(strong, d):
    """P, Q of 5.4-3..9 (as forcing_harmonics builds them) = the 2-D quadrature of the
    definition (3.0-2, 3.0-3, 5.3-4) at two instants; rows k >= 3 are zero (delta_1k,
    delta_2k of 6.2).  Tolerance 1e-9 of the largest row (quadrature error ~1e-13)."""
    cp, ex, groups = strong
    for tau in (0.7, 13.3):
        ref = _definition_projection(cp, ex, d, tau)
        scale = max(np.abs(v).max() for v in ref.values())
        for g in groups[3 * (d - 1): 3 * d]:
            nu, f = r.forcing_harmonics(g, ex)
            val = np.real(f @ np.exp(1j * nu * tau))
            for i in range(len(g)):
                key = (int(g.j[i]), int(g.k[i]))
                if key in ref:
                    np.testing.assert_allclose(val[i], ref[key], rtol=0, atol=1e-9 * scale,
                                               err_msg=f"{g.kind} {key} tau={tau}")


def _closed(g, x0, nu, f, tau):
    """The memo's closed form for the group's kind (6.2-3, 6.2-8/9, 6.2-20)."""
    if g.kind == "0k":
        m = g.mass[:, 0, 0]
        w = np.sqrt(g.stiff[:, 0, 0] / m)
        return r.closed_form_0k(w, x0[:, 0], nu, f[:, 0, :] / m[:, None], tau)[:, None, :]
    if g.kind == "j0":
        M, K = g.mass, g.stiff
        c = dict(a=M[:, 0, 0], b=M[:, 0, 1], j=M[:, 1, 1], c=K[:, 0, 0], d=K[:, 0, 1],
                 h=K[:, 1, 0], k=K[:, 1, 1])
        U, W = r.closed_form_j0(c, x0[:, 0], x0[:, 1], nu, f[:, 0], f[:, 1], tau)
        return np.stack([U, W], axis=1)
    return r.closed_form_jk(g.mass, g.stiff, x0, nu, f, tau)


@pytest.mark.parametrize("d", [1, 2])
@pytest.mark.parametrize("kind", ["0k", "j0", "jk"])
@pytest.mark.slow
def test_closed_form_matches_integration(strong, kind, d):
    """U_0k (6.2-3), U_j0/W_j0 (6.2-8/9), U/V/W_jk (6.2-20) with initial displacements,
    Omega = 300 rad/s (off resonance), against scipy DOP853 (rtol 1e-10): 1e-6 relative."""
    cp, ex, groups = strong
    g = groups[3 * (d - 1) + ("0k", "j0", "jk").index(kind)]
    g = g.select(np.flatnonzero(g.forced())[:3])
    x0 = 1e-6 * np.cos(np.arange(len(g) * g.mass.shape[-1])).reshape(len(g), -1)
    tau = np.linspace(0.0, 12.0, 49)
    nu, f = r.forcing_harmonics(g, ex)
    closed = _closed(g, x0, nu, f, tau)
    num = r.integrate(g, ex, tau, x0, method="DOP853", rtol=1e-10)
    scale = np.abs(num).max()
    np.testing.assert_allclose(closed, num, rtol=0, atol=1e-6 * scale)  # the acceptance criterion
    # and the resonance-safe form used by simulate, and the Duhamel integrator
    np.testing.assert_allclose(r.harmonic_response(g, ex, tau, x0), closed, rtol=0,
                               atol=1e-10 * scale)
    np.testing.assert_allclose(r.integrate(g, ex, tau, x0, method="duhamel"), num, rtol=0,
                               atol=1e-8 * scale)


def test_printed_phase_has_no_normal_coordinates():
    """With the printed phase (E10) low modes have complex/negative omega^2: modal_basis
    refuses them (docs/theory/shell.md section 3), the zero phase does not."""
    shell = model_from_case(memo_case()).shell
    printed = r.modal_groups(shell, (2, 2), (4, 4), 2, phase="printed")
    with pytest.raises(ValueError, match="printed phase"):
        for g in printed:
            r.modal_basis(g)
    for g in r.modal_groups(shell, (2, 2), (4, 4), 2):
        assert np.all(r.modal_basis(g)[0] > 0)


# --------------------------------------------------------------------------------------------
# Secular growth at the roots of the stability table
# --------------------------------------------------------------------------------------------
NB, SB, RB = 2, 2, 2
TAU_MAX = 3000.0
@pytest.fixture(scope="module")
def params(strong_model):
    """The pipeline's parameter function of the strong case (beta by Hill, alpha_r splined from
    the beam action on the case's Omega grid): the roots and the forcing below both use it."""
    return r.excitation_parameters(strong_model, beam_action_analysis(strong_model))


@pytest.fixture(scope="module")
def table(strong_model, params):
    """Stability table of the small strong case (all 13 families have active roots)."""
    rows = []
    for g in r.modal_groups(strong_model.shell, (2, 2), (3, 3), NB):
        om = r.modal_basis(g)[0]
        rows += [(g.cylinder, g.j[i], g.k[i], m + 1, om[i, m])
                 for i in range(len(g)) for m in range(om.shape[1])]
    c = np.array(rows)
    modes = ShellModes(c[:, 0].astype(int), c[:, 1].astype(int), c[:, 2].astype(int),
                       c[:, 3].astype(int), c[:, 4])

    w1 = strong_model.omega_1
    return unstable_frequencies(modes, params, Omega_bar_range=(8.0 / w1, 2000.0 / w1),
                                omega_1=w1, R=RB, S=SB, gamma=strong_model.gamma,
                                K=strong_model.K,
                                n_scan=801).to_rows()


def _pick(rows, family, model, params):
    """Active roots of a family (as first family, else as a coincident one), best isolated.

    Score: the resonant forcing amplitude over the leakage of the other harmonics into the
    windowed slope, sum |g_h| / Delta_h (Delta_h TAU_MAX)^-6 (Delta_h: detuning).  Roots whose
    resonant amplitude is a structural zero (e.g. int sin s = 0 for even j in the zero phase)
    are skipped: the table's "active" flag only looks at delta_1k / delta_2k.
    """
    own = [x for x in rows if x["forcing"] == "active" and x["family"] == family]
    also = [x for x in rows if x["forcing"] == "active"
            and f"{family}(" in x["also"].replace(" ", "")]
    cand = own or also
    assert cand, f"family {family}: no active root in the test case"
    best = None
    for x in cand[:40]:
        psi0, bamp = (0.0, 1e-4) if family in (2, 13) else (0.01, 0.0)
        key = (x["cylinder"], x["j"], x["k"], x["branch"])
        nu, gh, w = r.modal_forcing_spectrum(model, x["Omega_rad_s"], *key, psi0=psi0,
                                             beam_amplitude=bamp, beam_mode=max(x["r"], 1),
                                             params=params, N=NB, S=SB)
        res = np.abs(np.abs(nu) - w) < 1e-8 * w
        pred = np.abs(gh[res].sum()) / 2
        if pred <= 1e-9 * np.abs(gh).max():
            continue  # structurally zero at this mode
        det = np.abs(np.abs(nu[~res]) - w)
        leak = np.sum(np.abs(gh[~res]) / det * (det * TAU_MAX) ** -6.0) * 1e4
        vis = pred * TAU_MAX / np.sum(np.abs(gh[~res]) / det)
        score = pred / (leak + 1e-300)
        if best is None or score > best[0]:
            best = (score, vis, x, key, psi0, bamp)
    assert best is not None, f"family {family}: every active root has a zero forcing"
    return best[1:]


@pytest.mark.parametrize("family", range(1, 14))
def test_secular_growth_at_a_root_bounded_away(strong_model, params, table, family):
    """At an active root the integrated normal coordinate has a secular term (Z drifts at the
    rate the harmonic decomposition predicts, 1e-3); in the root-free gap next to it the
    drift is < 1e-5 of that.  Where the secular term dominates (visibility > 1) the amplitude
    visibly grows like tau (last/first quarter > 2.5) and stays bounded away (< 1.5).

    Only the forcing of the family is switched on (psi terms, or the beam for 2 and 13)."""
    vis, x, key, psi0, bamp = _pick(table, family, strong_model, params)
    om = x["Omega_rad_s"]
    same = np.sort([y["Omega_rad_s"] for y in table
                    if (y["cylinder"], y["j"], y["k"], y["branch"]) == key])
    near = same[(same > 0.8 * om) & (same < 1.25 * om)]
    pts = np.concatenate([[0.8 * om], near, [1.25 * om]])
    gap = int(np.argmax(np.diff(pts)))
    away = 0.5 * (pts[gap] + pts[gap + 1])  # midpoint of the widest root-free gap
    kw = dict(tau_max=TAU_MAX, psi0=psi0, beam_amplitude=bamp, beam_mode=max(x["r"], 1),
              N=NB, S=SB, params=params)
    at = r.secular_growth(strong_model, om, *key, **kw)
    off = r.secular_growth(strong_model, away, *key, **kw)
    assert at.predicted_slope > 0
    assert at.slope == pytest.approx(at.predicted_slope, rel=1e-3)  # observed <= 1.1e-4
    assert off.predicted_slope == 0.0
    assert off.slope < 1e-5 * at.slope  # observed <= 1.5e-7
    if vis > 1.0:
        assert at.envelope_ratio > 2.5 and at.index > 0.5
        assert off.envelope_ratio < 1.5 and off.index < 0.05


# --------------------------------------------------------------------------------------------
# Pipeline: simulate
# --------------------------------------------------------------------------------------------
def test_simulate_long_time_many_modes_no_nan():
    """tau up to 1e4 and 100 x 100 modes per cylinder (10 beam modes): finite, JSON without
    NaN."""
    d = tomllib.loads(memo_case_text())
    d["truncation"].update(N=10, S=2, R=2)
    res = r.simulate(model_from_case(load_case(d)), 300.0, 1e4, n_out=101,
                     modes=(100, 100, 100, 100),
                     n_snapshots=2, n_xi=21, n_theta=13)
    assert np.all(np.isfinite(res.amplitude)) and res.amplitude.shape[1] == 101
    assert set(res.k.tolist()) <= {0, 1, 2}  # forcing only reaches k = 0, 1, 2 (6.2)
    assert res.j.max() == 100
    json.dumps(res.to_dict(), allow_nan=False)
    assert all(np.isfinite(v) for v in res.max_displacement().values())


def test_simulate_at_exact_resonance_grows_without_overflow(strong_model, params, table):
    """At a root simulate (resonance-safe closed form) equals the Duhamel integration and
    grows like tau, with no division by zero."""
    vis, x, key, psi0, bamp = _pick(table, 3, strong_model, params)
    res = r.simulate(strong_model, x["Omega_rad_s"], 400.0, n_out=201, psi0=psi0,
                     beam_amplitude=bamp, n_snapshots=0, params=params)
    num = r.simulate(strong_model, x["Omega_rad_s"], 400.0, n_out=201, psi0=psi0,
                     beam_amplitude=bamp, n_snapshots=0, method="duhamel", params=params)
    np.testing.assert_allclose(res.amplitude, num.amplitude, rtol=0,
                               atol=1e-8 * np.abs(num.amplitude).max())
    c = np.flatnonzero((res.cylinder == key[0]) & (res.j == key[1]) & (res.k == key[2]))
    a = np.abs(res.amplitude[c])
    assert a[:, -50:].max() > 3.0 * a[:, :50].max()


def test_simulate_rows_initial_and_bad_input():
    case = small_case()
    res = r.simulate(case, 300.0, 10.0, n_out=11, psi0=0.0, beam_amplitude=0.0,
                     initial={(1, 1, 3, "W"): 1e-6}, n_snapshots=1)
    # k = 3 is not forced (6.2): only the coordinate given an initial value moves there
    k3 = np.flatnonzero(res.k == 3)
    assert len(k3) == 3 and res.amplitude[k3[2], 0] == pytest.approx(1e-6, rel=1e-12)
    assert np.abs(res.amplitude[k3[:2], 0]).max() < 1e-20  # U(0) = V(0) = 0 (round-off)
    assert np.abs(res.amplitude[k3[:2]]).max() > 1e-9  # coupled to W through K
    rows = res.to_rows()
    assert len(rows) == 11 and "W_d1_j1_k3" in rows[0] and "psi_rad" in rows[0]
    for bad in (dict(Omega=-1.0), dict(tau_max=0.0), dict(method="euler"),
                dict(initial={(1, 9, 9, "W"): 1e-6}), dict(n_out=1)):
        kw = dict(Omega=300.0, tau_max=10.0) | bad
        with pytest.raises(ValueError):
            r.simulate(case, **kw)


def test_plots():
    import matplotlib.figure

    from flexbooster.present.plotting.responses import deformed_booster, modal_amplitudes

    res = r.simulate(small_case(), 300.0, 20.0, n_out=41, n_snapshots=2)
    fig = modal_amplitudes(res, top=3)
    assert isinstance(fig, matplotlib.figure.Figure) and len(fig.axes[0].lines) == 3
    fig = deformed_booster(res)
    assert len(fig.axes[0].lines) == 4  # two outlines, undeformed and deformed


def test_structural_zeros_of_the_zero_phase_projections(strong, params, table):
    """int cos s = 0 (j >= 1) and int sin s = 0 (even j) over a zero-phase cylinder (exact:
    int_0^{j pi} cos = 0, int_0^{j pi} sin = 1 - (-1)^j): the F1 thrust term never reaches
    U_j0 and psi'^2 never reaches k = 2 modes of even j; secular_rates finds exactly those
    "active" roots of families 10-12 unforced (round-off, < 1e-18 relative)."""
    cp, ex, groups = strong
    for g in groups:
        if g.kind == "j0":
            assert np.abs(g.forcing[0, :, 0]).max() < 1e-14 * np.abs(g.forcing).max()
        if g.kind == "jk":
            k2 = g.k == 2
            even = k2 & (g.j % 2 == 0)
            odd = k2 & (g.j % 2 == 1)
            assert np.abs(g.forcing[4][even]).max() < 1e-14 * np.abs(g.forcing[4][odd]).max()
    rows = [x for x in table if x["forcing"] == "active" and x["family"] in (10, 11, 12)]
    rates = r.secular_rates(strong[0], rows, N=NB, S=SB, params=params)
    for x, y in zip(rows, rates, strict=True):
        assert y["forced"] == (x["j"] % 2 == 1), (x, y)
        if not y["forced"]:
            assert y["relative"] < 1e-18


def test_family_counts_in_test_case(table):
    """Every family has an active root in the test case (else the test above is vacuous)."""
    fams = collections.Counter()
    for x in table:
        if x["forcing"] == "active":
            fams[x["family"]] += 1
            for a in x["also"].split(","):
                if a.strip():
                    fams[int(a.strip().split("(")[0])] += 1
    assert set(fams) == set(range(1, 14))


@pytest.mark.parametrize("n", [2, 3, 4, 5, 9, 60])
def test_cubic_spline_reproduces_cubics_and_agrees_with_scipy(n):
    # Exact limit: not-a-knot splines reproduce polynomials of degree <= 3 (de Boor 2001,
    # ch. IV; with 3 knots the spline is the parabola, with 2 the line, so the degree is
    # limited there), to 1e-12 relative.  Independent implementation:
    # scipy.interpolate.CubicSpline (the same system), to 1e-13 relative.
    from scipy.interpolate import CubicSpline

    from flexbooster.memo.responses.excitation import cubic_spline

    rng = np.random.default_rng(n)
    x = np.sort(rng.uniform(0.05, 20.0, n))
    xi = np.concatenate([x, rng.uniform(x[0], x[-1], 200), [x[0] - 0.5, x[-1] + 0.5]])
    degree = min(3, n - 1)
    coef = rng.normal(size=(degree + 1, 4))
    y = np.stack([np.polyval(c, x) for c in coef.T], axis=1)
    exact = np.stack([np.polyval(c, xi) for c in coef.T], axis=1)
    got = cubic_spline(x, y)(xi)
    scale = np.abs(exact).max()
    np.testing.assert_allclose(got, exact, rtol=0, atol=1e-12 * scale)
    y = rng.normal(size=(n, 4))  # arbitrary data
    reference = CubicSpline(x, y, axis=0)(xi)
    np.testing.assert_allclose(cubic_spline(x, y)(xi), reference, rtol=0,
                               atol=1e-13 * np.abs(reference).max())

