"""Parametric instability regions of the pre-stressed shell-of-revolution vehicle.

Tiers:

* exact: a shear-diaphragm (SD-SD) Donnell cylinder under a uniform pulsating axial load,
  one mode per harmonic, is one Mathieu equation f'' + w_L^2 (1 - 2 mu cos Omega t) f = 0
  (Bolotin 1964, ch. 1): its region edges are scipy's Mathieu characteristic values; damped,
  the threshold mu_cr = Delta / pi = 2 zeta (Bolotin sec. 6, first order);
* independent model: Floquet monodromy of the full multi-mode system
  (``floquet.growth_rate``) inside and outside the regions of a cylinder-cone-cylinder of the
  memo case's size;
* invariants: gamma -> 0 (widths linear in gamma, none with damping), JSON, bad input.

Closed forms used below (written out, not imported): the SD-SD Donnell cylinder, mode
u = A cos(lam x) cos(k t), v = B sin(lam x) sin(k t), w = C sin(lam x) cos(k t),
lam = m pi / L, has the 3x3 stiffness of Leissa (NASA SP-288, 1973, sec. 2.1-2.3, eq. 2.20)
and mass rho h I; a uniform axial compression N (N/m) adds -N lam^2 to K_CC (Brush & Almroth
1975, ch. 5).  With one mode per harmonic (the lowest loaded mode x = (A, B, C) at P0), the
one-mode system is q'' + (w_L^2 + (P(t) - P0) d w_L^2 / dP) q = 0, d w_L^2 / dP =
-lam^2 C^2 / (2 pi R rho h |x|^2) (Hellmann-Feynman).
"""

from __future__ import annotations

import json

import numpy as np
import pytest
from scipy.optimize import brentq
from scipy.special import mathieu_a, mathieu_b

import flexbooster
from flexbooster import floquet
from flexbooster.dynamics import (
    bending_regions,
    bending_system,
    follower_flutter_thrust,
    forced_axial,
    harmonic_system,
    region_curves,
    vehicle_regions,
)
from flexbooster.memo.beam_action import uniform_beam_system
from flexbooster.model import vehicle_from_case
from flexbooster.shell_of_revolution import (
    BucklingError,
    Cone,
    Cylinder,
    Vehicle,
    buckling_load,
    vehicle_modes,
)
from harness import ivp_growth_rate

STEEL = {"E": 210e9, "nu": 0.3, "rho": 7850.0}
# memo_case.toml: E = 10.5e6 psi, rho = 2.59e-4 lbf s^2/in^4
ALU = {"E": 72.4e9, "nu": 0.33, "rho": 2768.0}
L_SD, R_SD, H_SD = 2.0, 1.0, 0.01
SD_MESH = 12  # elements: SD frequencies within 1e-10 of the closed form (measured)


def sd_vehicle() -> Vehicle:
    return Vehicle([Cylinder(R_SD, L_SD, H_SD, **STEEL)], theory="donnell",
                   aft_end="shear-diaphragm", fwd_end="shear-diaphragm")


def sd_loaded_mode(k: int) -> tuple[float, float, float]:
    """(P0, w_L, s) of the lowest SD-SD Donnell mode of harmonic k under uniform compression
    (closed form, above): P0 (N, total thrust) = half the one-mode Rayleigh quotient P_cr =
    2 pi R rho h w^2 |x|^2 / (lam^2 C^2) of the lowest unloaded mode (over m = 1..39); w_L
    (rad/s) the lowest frequency over m of the loaded problem (K - N lam^2 e_C e_C^T) x =
    w^2 rho h x, N = P0 / (2 pi R); s = -d w_L^2 / dP = lam^2 C^2 / (2 pi R rho h |x|^2) of its
    vector (Hellmann-Feynman).  The one loaded mode under P(t) = P0 (1 - gamma cos W t) is
    q'' + w_L^2 (1 - 2 mu cos W t) q = 0 with mu = gamma P0 s / (2 w_L^2)."""
    E, nu, rho = STEEL["E"], STEEL["nu"], STEEL["rho"]
    a = E * H_SD / (1 - nu**2)
    d = E * H_SD**3 / (12 * (1 - nu**2))
    cm = np.array([[1, nu, 0], [nu, 1, 0], [0, 0, (1 - nu) / 2]])
    stiff = []
    for m in range(1, 40):
        lam = m * np.pi / L_SD
        mem = np.array([[-lam, 0, 0], [0, k / R_SD, 1 / R_SD], [-k / R_SD, lam, 0]])
        ben = np.array([[0, 0, lam**2], [0, 0, k**2 / R_SD**2], [0, 0, 2 * k * lam / R_SD]])
        stiff.append((lam, a * mem.T @ cm @ mem + d * ben.T @ cm @ ben))
    w2, x, lam = min(((*np.linalg.eigh(K / (rho * H_SD)), lam) for lam, K in stiff),
                     key=lambda t: t[0][0])
    p0 = 0.5 * 2 * np.pi * R_SD * rho * H_SD * w2[0] / (lam**2 * x[2, 0] ** 2)
    best = None
    for lam, K in stiff:
        K = K.copy()
        K[2, 2] -= p0 / (2 * np.pi * R_SD) * lam**2
        w2, x = np.linalg.eigh(K / (rho * H_SD))
        if best is None or w2[0] < best[0]:
            best = (w2[0], x[:, 0], lam)
    w2, x, lam = best
    return float(p0), float(np.sqrt(w2)), float(lam**2 * x[2]**2 / (2 * np.pi * R_SD * rho * H_SD))


def mathieu_edges(mu: float, j: int) -> tuple[float, float]:
    """Edges theta = Omega / w_L of region j of f'' + (1 - 2 mu cos theta t) f = 0.

    x = theta t / 2 gives f_xx + (a - 2 q cos 2x) f = 0 with a = 4 / theta^2, q = 4 mu / theta^2
    (DLMF 28.2.1); region j lies between b_j(q) and a_j(q) (scipy.special.mathieu_b/_a).
    """
    out = [brentq(lambda th, f=f: 4 / th**2 - f(j, 4 * mu / th**2), 0.7 * 2 / j, 1.3 * 2 / j,
                  xtol=1e-14) for f in (mathieu_b, mathieu_a)]
    return min(out), max(out)


# --------------------------------------------------------------------------- tier 1: Mathieu


@pytest.mark.parametrize("k", [4, 6])
@pytest.mark.parametrize("mu", [0.05, 0.1, 0.2])
def test_sd_cylinder_regions_are_mathieu_regions(k, mu):
    """SD-SD Donnell cylinder, uniform compression P0, one loaded mode: regions j = 1, 2
    equal the exact Mathieu regions with w_L and mu = gamma P0 s / (2 w_L^2) of the loaded
    closed form (sd_loaded_mode).  Source: scipy.special.mathieu_a/b (map in mathieu_edges);
    tolerance 1e-6 (j = 1) and 1e-5 (j = 2) on Omega / w_L (measured ~4e-9)."""
    P0, w_l, slope = sd_loaded_mode(k)
    gamma = 2 * mu * w_l**2 / (P0 * slope)
    res = vehicle_regions(sd_vehicle(), F0=P0, gamma=gamma, omega_min=0.7 * w_l,
                          omega_max=2.6 * w_l, k_min=k, k_max=k, n_modes=1, damping_ratio=0.0,
                          supported_forward_end=True, elements_per_segment=SD_MESH)
    np.testing.assert_allclose(res.harmonic(k).omega_loaded[0], w_l, rtol=1e-8)  # closed form
    assert sorted(r.order for r in res.regions) == [1, 2]
    for r in res.regions:
        lo, hi = mathieu_edges(mu, r.order)
        tol = 1e-6 if r.order == 1 else 1e-5
        assert r.kind == "simple" and r.k == k and r.critical_gamma == 0.0
        assert abs(r.Omega_lo / w_l - lo) < tol and abs(r.Omega_hi / w_l - hi) < tol
        assert r.modes[0].type == "radial" and r.modes[0].order == 0  # m = 1: no sign change


@pytest.mark.parametrize("k", [4, 6])
def test_sd_cylinder_damped_threshold(k):
    """Damped Mathieu threshold (Bolotin 1964 sec. 6, first order): mu_cr = Delta / pi = 2 zeta,
    i.e. gamma_cr = 4 zeta w_L^2 / (P0 s) (sd_loaded_mode); relative tolerance zeta (measured
    1e-5).  The region exists at 1.1 gamma_cr and not at 0.9 gamma_cr."""
    zeta = 0.01
    P0, w_l, slope = sd_loaded_mode(k)
    g_cr = 4 * zeta * w_l**2 / (P0 * slope)
    kw = dict(F0=P0, omega_min=1.5 * w_l, omega_max=2.5 * w_l, k_min=k, k_max=k, n_modes=1,
              damping_ratio=zeta, supported_forward_end=True, elements_per_segment=SD_MESH,
              max_order=1)
    above = vehicle_regions(sd_vehicle(), gamma=1.1 * g_cr, **kw)
    assert len(above.regions) == 1
    assert abs(above.regions[0].critical_gamma / g_cr - 1) < zeta
    assert vehicle_regions(sd_vehicle(), gamma=0.9 * g_cr, **kw).regions == ()


def test_sd_cylinder_boundary_curves_are_mathieu():
    """Boundary curves (boundaries=True) of the principal region at gamma levels 0.1..0.3:
    exact Mathieu edges (scipy.special), tolerance 1e-6 on Omega / w_L; tip at gamma = 0 on
    the centre 2 w_L (undamped: Bolotin ch. 1)."""
    k = 4
    P0, w_l, slope = sd_loaded_mode(k)
    res = vehicle_regions(sd_vehicle(), F0=P0, gamma=0.2, omega_min=1.5 * w_l,
                          omega_max=2.5 * w_l, k_min=k, k_max=k, n_modes=1, damping_ratio=0.0,
                          supported_forward_end=True, elements_per_segment=SD_MESH,
                          boundaries=True, gamma_max=0.3, n_gamma=4, max_order=1)
    (curve,) = res.curves
    np.testing.assert_allclose(curve.gamma, [0.0, 0.1, 0.2, 0.3], atol=1e-15)
    assert curve.omega_lo[0] == curve.omega_hi[0] == pytest.approx(2 * w_l, rel=1e-9)
    for g, a, b in zip(curve.gamma[1:], curve.omega_lo[1:], curve.omega_hi[1:], strict=True):
        lo, hi = mathieu_edges(g * P0 * slope / (2 * w_l**2), 1)
        assert abs(a / w_l - lo) < 1e-6 and abs(b / w_l - hi) < 1e-6


def test_sd_modal_system_decouples_in_m():
    """Why one mode per k is exact: for the SD-SD cylinder the modes of different m are
    orthogonal in K_g too (sin(m pi x / L) products), so K_g in the modal basis couples only
    the branches of the same m.  Checked: |B1_ij| < 1e-8 max|B1| between the lowest mode
    (m = 1) and every mode of another axial order (labels from vehicle_modes)."""
    k = 4
    h = harmonic_system(sd_vehicle(), k, F0=1e6, n_modes=8, damping_ratio=0.0,
                        supported_forward_end=True, elements_per_segment=SD_MESH)
    B1 = h.excitation
    other = h.mode_order != h.mode_order[0]
    assert np.any(other)
    assert np.max(np.abs(B1[0, other])) < 1e-8 * np.max(np.abs(B1))
    # the axial thrust is a dead load: M = I, A = diag(omega^2), B1 = -V^T K_g V symmetric,
    # so the harmonic is canonical and only its simple and sum centres can open a region
    # (Krein 1955; flexbooster.floquet.resonance_kinds); the k = 1 follower thrust is not
    assert floquet.resonance_kinds(*h.periodic(0.1)) == ("simple", "sum")


# --------------------------------------------------------------------------- tier 2: vehicle


def default_size_vehicle() -> Vehicle:
    """Cylinder-cone-cylinder of the memo case's size (memo_case.toml: R1 = 5.05 m,
    42 m; R2 = 3.3 m, 18 m; h = 20 mm; aluminium); a 5 m cone joins them; free-free."""
    return Vehicle([Cylinder(5.05, 42.0, 0.02, **ALU), Cone(5.05, 3.3, 5.0, 0.02, **ALU),
                    Cylinder(3.3, 18.0, 0.02, **ALU)])


F0_DEFAULT = 2.8e6  # N (memo_case.toml)


@pytest.fixture(scope="module")
def vehicle_map():
    """k = 3, 10 modes, Omega 10..100 rad/s, gamma = 0.05, undamped (the regions of the default
    damping 0.01 are all suppressed at gamma = 0.05: test_default_damping_...)."""
    return vehicle_regions(default_size_vehicle(), F0=F0_DEFAULT, gamma=0.05, omega_min=10.0,
                           omega_max=100.0, k_min=3, k_max=3, n_modes=10, damping_ratio=0.0,
                           max_order=2)


def _check_against_monodromy(res, gamma, n_regions, k=3):
    """Widest regions: floquet.growth_rate (monodromy of the full system, step phase 0.06) at
    the reported maximum = growth_rate_max to 1e-6 relative; positive at the region's middle;
    stable (< 1e-6 of the region's growth) halfway to the next region or one width beyond."""
    regs = sorted(res.regions, key=lambda r: -r.width)[:n_regions]
    assert len(regs) == n_regions
    M, C, A, B = res.harmonic(k).matrices(gamma)
    C = C if res.damping_ratio > 0 else None
    edges = sorted((r.Omega_lo, r.Omega_hi) for r in res.regions)
    for r in regs:
        g = floquet.growth_rate(M, C, A, B, np.array([r.Omega_at_max]))[0]
        assert abs(g / r.growth_rate_max - 1) < 1e-6
        i = edges.index((r.Omega_lo, r.Omega_hi))
        nxt = edges[i + 1][0] if i + 1 < len(edges) else r.Omega_hi + 2 * r.width
        out = floquet.growth_rate(M, C, A, B, np.array([0.5 * (r.Omega_hi + nxt)]))[0]
        assert out < 1e-6 * r.growth_rate_max
        mid = floquet.growth_rate(M, C, A, B, np.array([0.5 * (r.Omega_lo + r.Omega_hi)]))
        assert mid[0] > 0.0


def test_vehicle_growth_rates_against_monodromy(vehicle_map):
    """Undamped 10-mode k = 3 system, three widest regions (simple 2, sum (2, 3), sum (0, 2)):
    see _check_against_monodromy (tolerance 1e-6 relative)."""
    _check_against_monodromy(vehicle_map, 0.05, 3)


@pytest.mark.slow
def test_vehicle_damped_growth_rate_against_monodromy():
    """Damped (zeta = 0.002, gamma = 0.3) 10-mode k = 3 system: the region that survives (simple,
    loaded mode 2) against the damped monodromy, tolerance 1e-6 relative; its critical gamma
    lies in (0, 0.3) and above Bolotin's first-order estimate 4 zeta w_i^2 / |B1_ii| (damped
    Mathieu mu_cr = 2 zeta, mu = gamma |B1_ii| / (2 w_i^2)) within a factor 1.5 (higher-order
    and coupling terms)."""
    res = vehicle_regions(default_size_vehicle(), F0=F0_DEFAULT, gamma=0.3, omega_min=10.0,
                          omega_max=100.0, k_min=3, k_max=3, n_modes=10, damping_ratio=0.002,
                          max_order=1, step_phase=0.06)
    _check_against_monodromy(res, 0.3, 1)
    (r,) = res.regions
    h = res.harmonic(3)
    i = r.modes[0].index
    first = 4 * 0.002 * h.omega_loaded[i] ** 2 / abs(h.excitation[i, i])
    assert 0.0 < r.critical_gamma < 0.3
    assert abs(r.critical_gamma / first - 1) < 0.5


def test_vehicle_labels_and_loaded_frequencies(vehicle_map):
    """Loaded frequencies equal vehicle_modes(prestress_F0=F0) (full FE) to 1e-3 (10-mode
    truncation; shell-of-revolution docs: 12 modes within 1e-3); every region's modes carry
    k, the meridian order and the type of vehicle_modes."""
    h = vehicle_map.harmonic(3)
    full = vehicle_modes(default_size_vehicle(), k_min=3, k_max=3, n_modes=10,
                         prestress_F0=F0_DEFAULT)
    np.testing.assert_allclose(h.omega_loaded[:3], full.omega[:3], rtol=1e-3)
    assert np.all(h.omega_loaded < h.omega_unloaded)  # compression softens
    for r in vehicle_map.regions:
        assert all(m.k == 3 and m.type in ("axial", "torsional", "radial") for m in r.modes)


# --------------------------------------------------------------------------- tier 3


def test_without_unloaded_frequencies_the_map_is_the_same(vehicle_map):
    """unloaded_frequencies=False skips the unloaded eigenproblem of k >= 2, which gives only
    omega_unloaded: the regions, the loaded frequencies and the periodic matrices are those of
    the full map exactly (the same operations on the same inputs); omega_unloaded is empty."""
    fast = vehicle_regions(default_size_vehicle(), F0=F0_DEFAULT, gamma=0.05, omega_min=10.0,
                           omega_max=100.0, k_min=3, k_max=3, n_modes=10, damping_ratio=0.0,
                           max_order=2, unloaded_frequencies=False)
    assert fast.regions == vehicle_map.regions and fast.regions
    full, h = vehicle_map.harmonic(3), fast.harmonic(3)
    for name in ("omega_loaded", "stiffness", "excitation", "damping", "basis"):
        np.testing.assert_array_equal(getattr(h, name), getattr(full, name))
    assert h.omega_unloaded.shape == (0,) and full.omega_unloaded.shape == (10,)


def test_gamma_to_zero():
    """gamma -> 0: undamped first-order simple regions shrink linearly (width ratio 2 between
    gamma = 2e-3 and 1e-3 within 1e-2: Bolotin's first-order width gamma |B1_ii| / w_i);
    gamma = 0 gives none; damped (zeta = 0.01) none at gamma = 1e-3."""
    kw = dict(F0=F0_DEFAULT, omega_min=15.0, omega_max=60.0, k_min=3, k_max=3, n_modes=4,
              max_order=1)
    veh = default_size_vehicle()
    a = vehicle_regions(veh, gamma=1e-3, damping_ratio=0.0, **kw)
    b = vehicle_regions(veh, gamma=2e-3, damping_ratio=0.0, **kw)
    wa = {(r.kind, tuple(m.index for m in r.modes)): r.width for r in a.regions}
    wb = {(r.kind, tuple(m.index for m in r.modes)): r.width for r in b.regions}
    simple = [key for key in wa if key[0] == "simple"]
    assert simple
    for key in simple:
        assert abs(wb[key] / wa[key] - 2.0) < 1e-2
        h = a.harmonic(3)
        i = key[1][0]
        first = 1e-3 * abs(h.excitation[i, i]) / h.omega_loaded[i]  # Bolotin first order
        assert abs(wa[key] / first - 1) < 1e-2
    assert vehicle_regions(veh, gamma=0.0, damping_ratio=0.0, **kw).regions == ()
    assert vehicle_regions(veh, gamma=1e-3, damping_ratio=0.01, **kw).regions == ()


def test_modal_truncation_converges():
    """Invariant under truncation: the three first-order simple regions of k = 3 (Omega 15..50
    rad/s, gamma = 0.05) with 10 and 14 loaded modes per k: edges within 1e-5 relative
    (measured 2e-9: the loaded frequencies are the full model's), widths and growth rates
    within 1e-3 (measured 1.4e-8; 6 -> 14 modes: 1e-8)."""
    kw = dict(F0=F0_DEFAULT, gamma=0.05, omega_min=15.0, omega_max=50.0, k_min=3, k_max=3,
              damping_ratio=0.0, max_order=1)
    veh = default_size_vehicle()
    a, b = (vehicle_regions(veh, n_modes=n, **kw) for n in (10, 14))
    ra = {r.modes[0].index: r for r in a.regions if r.kind == "simple"}
    rb = {r.modes[0].index: r for r in b.regions if r.kind == "simple"}
    assert sorted(ra) == sorted(rb) == [0, 1, 2]
    for i in ra:
        assert abs(ra[i].Omega_lo / rb[i].Omega_lo - 1) < 1e-5
        assert abs(ra[i].Omega_hi / rb[i].Omega_hi - 1) < 1e-5
        assert abs(ra[i].width / rb[i].width - 1) < 1e-3
        assert abs(ra[i].growth_rate_max / rb[i].growth_rate_max - 1) < 1e-3


def test_default_damping_suppresses_memo_case_regions():
    """Default zeta = 0.01 at gamma = 0.05: the principal region of the lowest k = 3 mode
    (undamped growth ~ gamma B1_00 / (4 w_0) ~ 2e-3 1/s < zeta w_0 ~ 0.09 1/s) does not
    survive (3 modes, Omega around 2 w_0)."""
    veh = default_size_vehicle()
    h = harmonic_system(veh, 3, F0=F0_DEFAULT, n_modes=3)
    w0 = h.omega_loaded[0]
    res = vehicle_regions(veh, F0=F0_DEFAULT, gamma=0.05, omega_min=1.8 * w0,
                          omega_max=2.2 * w0, k_min=3, k_max=3, n_modes=3, max_order=1)
    assert res.regions == () and res.damping_ratio == 0.01


def test_json_ready(vehicle_map):
    """to_dict() of the map and of a harmonic serialise with json (plain lists/floats)."""
    text = json.dumps(vehicle_map.to_dict())
    back = json.loads(text)
    assert len(back["regions"]) == len(vehicle_map.regions)
    json.dumps(vehicle_map.harmonic(3).to_dict())


def test_buckling_raises_with_load_factor():
    """F0 ten times the default on k = 2 (load factor ~6.8 at 2.8 MN): a BucklingError (a
    ValueError) with k = 2 and the load factor, which is that of buckling_load at the default
    F0 over 10 (linear buckling: lambda F0 is the critical thrust; rtol 1e-9)."""
    veh = default_size_vehicle()
    with pytest.raises(BucklingError, match=r"F0 = .*buckles harmonic k = 2.*load factor") \
            as info:
        vehicle_regions(veh, F0=10 * F0_DEFAULT, gamma=0.05, omega_min=5.0, omega_max=50.0,
                        k_min=2, k_max=2, n_modes=4)
    exc = info.value
    assert isinstance(exc, ValueError) and (exc.k, exc.F0) == (2, 10 * F0_DEFAULT)
    lam = buckling_load(veh, 2, F0=F0_DEFAULT).load_factor[0]
    assert exc.load_factor == pytest.approx(lam / 10.0, rel=1e-9) and exc.load_factor < 1.0


GOOD = dict(F0=1e6, gamma=0.05, omega_min=5.0, omega_max=50.0, k_max=2, n_modes=2)


@pytest.mark.parametrize("name, value", [
    ("vehicle", "cyl"), ("F0", 0.0), ("F0", np.nan), ("gamma", 1.0), ("gamma", -0.1),
    ("omega_min", -1.0), ("omega_max", np.inf), ("k_max", 0), ("k_min", 0), ("n_modes", 0),
    ("damping_ratio", -0.01), ("damping_ratio", 1.5), ("boundaries", "yes"),
    ("rtol", np.nan), ("max_order", 0), ("damping_margin", 0.5), ("damping_margin", True),
    ("axial", "no"), ("gimbal_gain", -0.5), ("gimbal_gain", np.nan),
    ("unloaded_frequencies", "no"),
])
def test_bad_input_names_argument(name, value):
    """Bad input: ValueError whose message starts with the argument's name."""
    kw = dict(GOOD)
    veh = sd_vehicle()
    if name == "vehicle":
        veh = value
    else:
        kw[name] = value
    with pytest.raises(ValueError, match=rf"^{name} = "):
        vehicle_regions(veh, **kw)


def test_bad_range_order():
    """omega_min >= omega_max: ValueError naming omega_min."""
    with pytest.raises(ValueError, match=r"^omega_min = "):
        vehicle_regions(sd_vehicle(), **{**GOOD, "omega_min": 60.0})


# --------------------------------------------------------------------------- the memo case


@pytest.fixture(scope="module")
def memo_vehicle() -> Vehicle:
    """The vehicle of the memo case (the memo's two cylinders, memo bulkhead, SD ends)."""
    return vehicle_from_case(flexbooster.memo_case())


def test_memo_case_map_is_certified_stable(memo_vehicle):
    """The memo case's vehicle map (k <= 10, 20 modes per k, Omega 5..2000 rad/s,
    gamma = 0.05, zeta = 0.01): every harmonic is certified stable at every Omega by the
    weighted logarithmic norm (floquet.stability_certificate; a theorem, Desoer & Vidyasagar
    sec. 2.8), so no region exists.  Checked independently for k = 3: the damped 20-mode
    monodromy at 12 Omega in 20..2000 rad/s lies below the certified growth bound (< 0)."""
    res = vehicle_regions(memo_vehicle, F0=F0_DEFAULT, gamma=0.05, omega_min=5.0,
                          omega_max=2000.0, k_max=10, n_modes=20)
    assert res.regions == ()
    assert [h.k for h in res.harmonics] == list(range(2, 11))
    assert len(res.certificates) == 9 and all(c.certified for c in res.certificates)
    M, C, A, B = res.harmonic(3).matrices(0.05)
    g = floquet.growth_rate(M, C, A, B, np.geomspace(20.0, 2000.0, 12))
    assert np.all(g <= res.certificates[1].growth_bound + 1e-9)
    json.dumps(res.to_dict())


def test_default_vehicle_regions_against_full_monodromy(memo_vehicle):
    """Acceptance: the default vehicle, k = 3, the full 20-mode system, undamped
    (the default damping leaves no region), gamma = 0.05, Omega 30..130 rad/s, first-order
    regions: the three widest (simple 2, simple 0, simple 1) against floquet.growth_rate of the
    full system inside (at the reported maximum, 1e-6 relative; positive at the middle) and
    outside (halfway to the next region: < 1e-6 x growth), see _check_against_monodromy."""
    res = vehicle_regions(memo_vehicle, F0=F0_DEFAULT, gamma=0.05, omega_min=30.0,
                          omega_max=130.0, k_min=3, k_max=3, n_modes=20, damping_ratio=0.0,
                          max_order=1, axial=False)
    assert res.harmonic(3).omega_loaded.size == 20
    _check_against_monodromy(res, 0.05, 3)


def test_default_vehicle_gamma_to_zero_gives_no_region(memo_vehicle):
    """gamma -> 0 on the default vehicle (20 modes): undamped gamma = 0 no region (k = 3,
    Omega 30..130); damped (default zeta) gamma = 1e-3, k = 2..10, Omega 5..2000: none, and
    certified with a bound ~ -zeta omega_1 (no coupling left: within 10 %)."""
    kw = dict(F0=F0_DEFAULT, n_modes=20, axial=False)
    assert vehicle_regions(memo_vehicle, gamma=0.0, omega_min=30.0, omega_max=130.0, k_min=3,
                           k_max=3, damping_ratio=0.0, max_order=1, **kw).regions == ()
    res = vehicle_regions(memo_vehicle, gamma=1e-3, omega_min=5.0, omega_max=2000.0, k_max=10,
                          **kw)
    assert res.regions == ()
    for h, c in zip(res.harmonics, res.certificates, strict=True):
        assert c.certified
        assert abs(c.growth_bound / (-0.01 * h.omega_loaded[0]) - 1) < 0.1


@pytest.mark.slow
def test_damping_filter_keeps_the_regions_of_the_unfiltered_search(memo_vehicle):
    """Invariant: the damping filter (default margin 4) against the unfiltered search
    (damping_margin=None) where damping leaves a region: default vehicle, k = 3, 6 modes,
    gamma = 0.5, zeta = 0.001, Omega 10..300, orders <= 2: the same regions, edges within 1e-8
    relative and critical gamma within 1e-6 relative (the brentq tolerance)."""
    kw = dict(F0=F0_DEFAULT, gamma=0.5, omega_min=10.0, omega_max=300.0, k_min=3, k_max=3,
              n_modes=6, damping_ratio=0.001, max_order=2, axial=False)
    fast = vehicle_regions(memo_vehicle, **kw)
    full = vehicle_regions(memo_vehicle, damping_margin=None, **kw)
    assert full.regions and len(fast.regions) == len(full.regions)
    for a, b in zip(fast.regions, full.regions, strict=True):
        assert (a.kind, a.order, a.modes) == (b.kind, b.order, b.modes)
        assert (a.Omega_lo, a.Omega_hi) == pytest.approx((b.Omega_lo, b.Omega_hi), rel=1e-8)
        assert a.critical_gamma == pytest.approx(b.critical_gamma, rel=1e-6)


@pytest.mark.slow
@pytest.mark.parametrize("gamma", [0.3, 0.6])
@pytest.mark.parametrize("zeta", [5e-4, 2e-3])
@pytest.mark.parametrize("which", ["memo", "cone"])
def test_damping_filter_finds_every_region_of_the_unfiltered_search(memo_vehicle, which, zeta,
                                                                     gamma):
    """Verification of the damping filter (it is a first-order estimate
    with a safety factor 4, not a proof): on a grid of small damped systems that keep 0 to 8
    regions -- the memo case's vehicle (Omega 10..300 rad/s) and the cylinder-cone-cylinder
    of the same size (10..100 rad/s), k = 3, 5 modes, orders <= 2, zeta = 5e-4 and 2e-3,
    gamma = 0.3 and 0.6 -- floquet.instability_regions with the filter (damping_margin = 4)
    finds exactly the regions of the unfiltered search (damping_margin = None: every
    candidate examined): the same (kind, modes, order), edges within 1e-8 relative (measured
    1e-13)."""
    veh, hi = (memo_vehicle, 300.0) if which == "memo" else (default_size_vehicle(), 100.0)
    M, C, A, B = harmonic_system(veh, 3, F0=F0_DEFAULT, n_modes=5,
                                 damping_ratio=zeta).matrices(gamma)
    fast = floquet.instability_regions(M, C, A, B, 10.0, hi, max_order=2)
    full = floquet.instability_regions(M, C, A, B, 10.0, hi, max_order=2, damping_margin=None)
    assert [(r.kind, r.modes, r.order) for r in fast] == [(r.kind, r.modes, r.order)
                                                          for r in full]
    for a, b in zip(fast, full, strict=True):
        assert (a.omega_lo, a.omega_hi) == pytest.approx((b.omega_lo, b.omega_hi), rel=1e-8)


# --------------------------------------------------------------------------- k = 0 forced


def slender_tube() -> Vehicle:
    """Free-free steel tube R = 5 cm, L = 5 m, h = 1 mm: a rod below its ring frequency."""
    return Vehicle([Cylinder(0.05, 5.0, 0.001, **STEEL)])


def test_forced_axial_of_a_tube_is_the_free_free_rod():
    """Independent model: the free-free uniform rod under a pulsating end load (Meirovitch
    1986 sec. 5.4, 7.4): resonances at n pi c / L, c = sqrt(E / rho), with mass-normalised
    end displacement phi_n^2 = 2 / m and the resonant amplitude per unit force
    phi_n^2 / (2 zeta omega_n^2) = 1 / (m zeta omega_n^2).  The tube differs from the rod by
    the Poisson coupling with its ring mode (~ nu^2 (omega / omega_ring)^2): tolerance 1e-3
    for n = 1..3 (measured 4.5e-5, 3.6e-4, 4e-4 on omega; 1e-4..8e-4 on phi^2).  Torsional
    k = 0 modes are not forced."""
    zeta = 0.01
    m = 2 * np.pi * 0.05 * 0.001 * 5.0 * STEEL["rho"]
    c = np.sqrt(STEEL["E"] / STEEL["rho"])
    fa = forced_axial(slender_tube(), F0=1.0, omega_min=100.0, omega_max=10_000.0,
                      n_modes=12, damping_ratio=zeta)
    assert [r.type for r in fa.resonances] == ["axial"] * 3
    for n, r in enumerate(fa.resonances, start=1):
        assert r.omega == pytest.approx(n * np.pi * c / 5.0, rel=1e-3)
        assert r.participation**2 * m == pytest.approx(2.0, rel=1e-3)
        assert r.amplitude * m * zeta * r.omega**2 == pytest.approx(1.0, rel=1e-3)
    torsional = fa.omega_loaded < 0.7 * np.pi * c / 5.0  # the lowest torsional mode
    assert np.all(np.abs(fa.participation[torsional]) < 1e-6 * np.max(np.abs(fa.participation)))


def test_forced_axial_in_the_map_and_json(memo_vehicle):
    """The map carries the k = 0 forced resonances (the memo's family 3): the lowest is the
    first axial mode (order 1); the receptance at a resonance equals the resonant modal term
    plus the off-resonant ones (the resonant term dominates: within 5 %); JSON-ready; without
    damping the resonant amplitude is None (unbounded)."""
    res = vehicle_regions(memo_vehicle, F0=F0_DEFAULT, gamma=0.05, omega_min=5.0,
                          omega_max=2000.0, k_min=2, k_max=2, n_modes=20)
    fa = res.forced_axial
    first = fa.resonances[0]
    assert first.type == "axial" and first.order == 1
    assert abs(fa.receptance(first.omega)[0]) == pytest.approx(first.amplitude, rel=0.05)
    back = json.loads(json.dumps(res.to_dict()))
    assert back["forced_axial"]["resonances"][0]["omega"] == first.omega
    undamped = forced_axial(memo_vehicle, F0=F0_DEFAULT, omega_min=5.0, omega_max=2000.0,
                            damping_ratio=0.0)
    assert all(r.amplitude is None for r in undamped.resonances)


@pytest.mark.parametrize("name, value", [
    ("vehicle", "tube"), ("F0", -1.0), ("omega_min", 0.0), ("n_modes", 0),
    ("damping_ratio", 1.0),
])
def test_forced_axial_bad_input(name, value):
    """Bad input: ValueError whose message starts with the argument's name."""
    kw = dict(F0=1.0, omega_min=10.0, omega_max=1e4, n_modes=4)
    veh = slender_tube()
    if name == "vehicle":
        veh = value
    else:
        kw[name] = value
    with pytest.raises(ValueError, match=rf"^{name} = "):
        forced_axial(veh, **kw)


# --------------------------------------------------------------------------- k = 1 follower


@pytest.mark.parametrize("radius, thickness, tol", [(0.02, 0.001, 2e-3), (0.05, 0.002, 1e-2)],
                         ids=["L/R=250", "L/R=100"])
def test_k1_follower_flutter_is_beals(radius, thickness, tol):
    """k = 1 steady limit (gamma -> 0, zero gimbal gain, no damping): a free-free steel tube
    (L = 5 m) under a follower end thrust flutters at Beal's 109.69 EI / l^2 (Beal 1965, the
    Euler-Bernoulli free-free beam; EI = E pi R^3 h).  The shell differs from the beam by
    terms ~ (R / L)^2 (shear, rotary inertia, the shell's cross-section): tolerance 2e-3 at
    L/R = 250 (measured 7.7e-4), 1e-2 at L/R = 100 (measured 7.4e-3); 10 basis modes (2 rigid),
    40 elements."""
    veh = Vehicle([Cylinder(radius, 5.0, thickness, **STEEL)])
    EI = STEEL["E"] * np.pi * radius**3 * thickness
    T = follower_flutter_thrust(veh, thrust_max=200 * EI / 25.0, n_modes=10,
                                elements_per_segment=40)
    assert T / (EI / 25.0) == pytest.approx(109.69, rel=tol)


def test_k1_bending_system_rigid_modes_and_follower_term():
    """The k = 1 basis of a free-free tube holds the 2 rigid modes (omega = 0) and the beam's
    first bending frequency 4.7300^2 sqrt(EI / (m L^4)) (free-free beam, READING-GUIDE sec. 6;
    tolerance 5e-3 at L/R = 100: shell vs Euler-Bernoulli beam, measured 2.6e-3); the follower
    term makes A non-symmetric; JSON-ready."""
    R, L, h = 0.05, 5.0, 0.002
    veh = Vehicle([Cylinder(R, L, h, **STEEL)])
    bs = bending_system(veh, F0=1e3, n_modes=6, elements_per_segment=40)
    EI = STEEL["E"] * np.pi * R**3 * h
    m = STEEL["rho"] * 2 * np.pi * R * h
    assert bs.n_rigid == 2 and np.all(bs.omega_unloaded[:2] == 0.0)
    assert bs.omega_unloaded[2] == pytest.approx(4.730040745**2 * np.sqrt(EI / (m * L**4)),
                                                 rel=5e-3)
    M, C, A, B = bs.matrices(0.1)
    assert np.max(np.abs(A - A.T)) > 1e-6 * np.max(np.abs(A))
    assert floquet.resonance_kinds(M, C, A, B) == ("simple", "sum", "difference")
    json.dumps(bs.to_dict())
    with pytest.raises(ValueError, match="^F0 = "):
        bending_system(veh, F0=0.0)


@pytest.mark.slow
def test_k1_regions_match_the_memo_beam_action_model():
    """Independent model: the memo's beam-action system of a uniform free-free beam
    (flexbooster.memo.beam_action.uniform_beam_system: Euler-Bernoulli modes, rigid pitch
    about the CM, follower thrust turned by the gimbal angle K psi; Beal 1965, memo 4.1-4.2)
    against the shell's k = 1 system of a slender steel tube (L/R = 250), p = F0 l^2 / EI = 20,
    K = 0.5, gamma = 0.1, undamped, Omega / omega_1 in 0.25..2.0, first-order regions wider
    than 1e-3 (relative): the same regions (kind), edges in Omega / omega_1 within 2e-3
    (shell vs beam; measured 2e-4 for the pitch regions, 1.4e-3 for the second mode), and the
    rigid pitch frequency^2 = 6 F0 K / (m l) (memo 4.2-1 for the uniform beam) to 1e-3."""
    R, L, h = 0.02, 5.0, 0.001
    veh = Vehicle([Cylinder(R, L, h, **STEEL)])
    EI = STEEL["E"] * np.pi * R**3 * h
    m = STEEL["rho"] * 2 * np.pi * R * h * L
    p, K, g = 20.0, 0.5, 0.1
    F0 = p * EI / L**2
    bs = bending_system(veh, F0=F0, n_modes=5, gimbal_gain=K, elements_per_segment=40,
                        damping_ratio=0.0)
    assert bs.stiffness[0, 0] == pytest.approx(6 * F0 * K / (m * L), rel=1e-3)
    w1 = bs.omega_unloaded[2]
    shell = bending_regions(veh, F0=F0, gamma=g, omega_min=0.25 * w1, omega_max=2.0 * w1,
                            gimbal_gain=K, n_modes=5, elements_per_segment=40,
                            damping_ratio=0.0, max_order=1)
    beam_sys = uniform_beam_system(p, K, 3)
    beam = floquet.instability_regions(np.eye(4), None, beam_sys.A0, -g * beam_sys.B, 0.25,
                                       2.0, max_order=1)

    def wide(regs, scale):  # (kind, lo, hi) of the regions wider than 1e-3 relative
        return [(kind, lo / scale, hi / scale) for kind, lo, hi in regs
                if (hi - lo) / scale > 1e-3 * hi / scale]

    ws = wide([(r.kind, r.Omega_lo, r.Omega_hi) for r in shell], w1)
    wb = wide([(r.kind, r.omega_lo, r.omega_hi) for r in beam], 1.0)
    assert [k for k, _, _ in ws] == [k for k, _, _ in wb] and len(ws) >= 4
    for (_, a, b), (_, c, d) in zip(ws, wb, strict=True):
        assert (a, b) == pytest.approx((c, d), rel=2e-3)
    assert shell[0].modes[0].type == "rigid-pitch"


def test_k1_no_flutter_below_beal_and_bad_input():
    """Below Beal's load (thrust_max = 100 EI / l^2 < 109.69 EI / l^2) no flutter: inf;
    bad input raises ValueError naming the argument."""
    R, h = 0.05, 0.002
    veh = Vehicle([Cylinder(R, 5.0, h, **STEEL)])
    EI = STEEL["E"] * np.pi * R**3 * h
    assert follower_flutter_thrust(veh, thrust_max=100 * EI / 25.0, n_modes=6,
                                   elements_per_segment=20) == np.inf
    for name, value in (("thrust_max", -1.0), ("n_modes", 1), ("n_scan", 1), ("rtol", 0.1)):
        kw = dict(thrust_max=1e3, n_modes=6, elements_per_segment=20)
        kw[name] = value
        with pytest.raises(ValueError, match=rf"^{name} = "):
            follower_flutter_thrust(veh, **kw)
    with pytest.raises(ValueError, match="^gimbal_gain = "):
        bending_system(veh, F0=1.0, gimbal_gain=-1.0)


@pytest.mark.slow
def test_k1_in_the_map_against_the_full_bending_monodromy():
    """k = 1 in vehicle_regions (k_min = 1): a free-free steel tube (R 5 cm, L 5 m, h 2 mm,
    20 elements), p = F0 l^2 / EI = 20, gimbal gain K = 0.5, gamma = 0.1, undamped, 5 basis
    modes, Omega / omega_1 in 0.25..2, first order.  Independent path: the monodromy
    (floquet.growth_rate, step phase 0.06) of the *full* bending_system, the rigid translation
    kept (the map drops it: a zero column, multiplier 1), at each region's reported maximum:
    growth rates agree to 1e-6 relative (measured 2e-8) plus 1e-5 1/s (the translation's
    double multiplier 1, split by round-off, adds 4.5e-6 at 112 rad/s); the map's system is
    stable (< 1e-6 of the growth) halfway to the next region.  The regions include the rigid
    pitch's own (2 omega_psi, the memo's pitch tongue), its sum with the first bending mode
    and their difference, 1.45e-5 rad/s wide at 111.83 rad/s (growth 1.478e-5 1/s: solve_ivp
    of the map's system at its maximum, to 1e-4; stable 1e-5 rad/s beyond either edge; found
    since a combination candidate that finds nothing is searched again with more s-values
    paired); the map stores gimbal_gain."""
    R, L, h = 0.05, 5.0, 0.002
    veh = Vehicle([Cylinder(R, L, h, **STEEL)])
    F0 = 20.0 * STEEL["E"] * np.pi * R**3 * h / L**2
    full = bending_system(veh, F0=F0, n_modes=5, gimbal_gain=0.5, elements_per_segment=20,
                          damping_ratio=0.0)
    w1 = full.omega_unloaded[2]
    res = vehicle_regions(veh, F0=F0, gamma=0.1, omega_min=0.25 * w1, omega_max=2.0 * w1,
                          k_min=1, k_max=1, n_modes=5, elements_per_segment=20,
                          damping_ratio=0.0, max_order=1, gimbal_gain=0.5, axial=False)
    assert [h.k for h in res.harmonics] == [1] and res.gimbal_gain == 0.5
    assert res.harmonic(1).omega_unloaded.size == 4  # the translation dropped
    kinds = [(r.kind, tuple(m.type for m in r.modes)) for r in res.regions]
    assert ("simple", ("rigid-pitch",)) in kinds and ("sum", ("rigid-pitch", "bending")) in kinds
    M, _, A, B = full.matrices(0.1)
    at = np.array([r.Omega_at_max for r in res.regions])
    g = floquet.growth_rate(M, None, A, B, at)
    np.testing.assert_allclose(g, [r.growth_rate_max for r in res.regions], rtol=1e-6,
                               atol=1e-5)
    # outside: the map's own (reduced) system; the full one has the translation's double
    # multiplier 1 (a Jordan block, free drift), which round-off splits by ~1e-4
    Mr, _, Ar, Br = res.harmonic(1).matrices(0.1)
    (narrow,) = [r for r in res.regions if r.kind == "difference"
                 and tuple(m.type for m in r.modes) == ("rigid-pitch", "bending")]
    assert narrow.Omega_hi - narrow.Omega_lo < 1e-6 * narrow.Omega_lo
    assert ivp_growth_rate(Mr, 0 * Mr, Ar, Br, narrow.Omega_at_max) == pytest.approx(
        narrow.growth_rate_max, rel=1e-4)
    for x in (narrow.Omega_lo - 1e-5, narrow.Omega_hi + 1e-5):
        assert ivp_growth_rate(Mr, 0 * Mr, Ar, Br, x) < 1e-10
    edges = [(r.Omega_lo, r.Omega_hi) for r in res.regions]
    gaps = np.array([0.5 * (a[1] + b[0]) for a, b in zip(edges, edges[1:], strict=False)])
    out = floquet.growth_rate(Mr, None, Ar, Br, gaps)
    assert np.all(out < 1e-6 * np.array([r.growth_rate_max for r in res.regions[:-1]]))
    json.dumps(res.to_dict())


# --------------------------------------------------------------------------- k = 1, damped


def _cone_vehicle() -> Vehicle:
    """A free-free steel cylinder-cone-cylinder (R 0.5 m / 0.35 m, 4 m + 1 m cone + 3 m,
    h 4 / 4 / 3 mm) with a continuous cone junction and a rigid bulkhead at the second."""
    return Vehicle([Cylinder(0.5, 4.0, 0.004, **STEEL), Cone(0.5, 0.35, 1.0, 0.004, **STEEL),
                    Cylinder(0.35, 3.0, 0.003, **STEEL)],
                   junctions=["continuous", "rigid-bulkhead"])


def _tube_vehicle() -> Vehicle:
    return Vehicle([Cylinder(0.05, 5.0, 0.002, **STEEL)])


#: (vehicle, F0 (N), basis modes, elements per segment): the tube of the undamped k = 1 test
#: at p = F0 l^2 / EI = 20; the cone vehicle at 2e5 N.
K1_DAMPED = {
    "tube": (_tube_vehicle, 20.0 * STEEL["E"] * np.pi * 0.05**3 * 0.002 / 25.0, 5, 20),
    "cone-junction": (_cone_vehicle, 2e5, 6, 8),
}


def _edge_is_a_zero(growth, edge: float, inward: float, peak: float) -> bool:
    """An edge to 1e-6 relative: the reference growth changes sign across edge (1 -+ 1e-6)
    (a steep edge), or it is zero at the edge to 1e-6 of the region's peak growth (a flat
    edge, where the growth stays within round-off of 0 over more than 1e-6 of Omega)."""
    out, inside = (growth(edge * (1.0 - inward * 1e-6)), growth(edge * (1.0 + inward * 1e-6)))
    return (out <= 0.0 < inside) or abs(growth(edge)) <= 1e-6 * peak


@pytest.mark.slow
@pytest.mark.parametrize("which", sorted(K1_DAMPED))
def test_k1_damped_regions_against_an_independent_monodromy(which):
    """The damped k = 1 search (zeta = 0.01 on the elastic modes, none on the rigid pitch),
    K = 0.5, gamma = 0.1, Omega / omega_1 in 0.25..2, first order, on a uniform free-free
    tube and on a free-free cylinder-cone-cylinder with a rigid bulkhead.  Independent
    reference: the monodromy by scipy solve_ivp (DOP853, rtol 1e-12; tests/harness.py) of the
    full bending_system (the rigid translation kept) for the growth rates, of the map's system
    at the edges; for the critical gamma a bounded scipy maximisation over Omega of the
    toolkit's monodromy at a fixed 1024 steps per period (converged to ~3e-8 in the growth).
    Checks, at the default settings (step_phase 0.12): at least one region with the rigid
    pitch (damped sum regions of the nearly undamped pitch are many times wider than
    undamped: the march to the range ends); growth at each reported maximum to 1e-6 relative
    (the acceptance threshold; measured: tube 1.8e-8, 6.7e-9; cone 2.8e-8); each edge a zero of
    the reference growth to 1e-6 (sign change across +-1e-6 relative, measured at all five
    edges, or |growth| <= 1e-6 of the peak where an edge is flat); each region absent at
    0.999 gamma_cr and present at 1.001 gamma_cr (maximal growth over Omega < 0 and > 0).
    Before the damped cost model was fixed (docs/theory/floquet.md sec. 2) this test ran at
    step_phase 0.06 and 0.03: at 0.12 the tube's growth erred by 1.8e-6, its rigid-pitch
    edges by up to 1.2e-6 relative, the cone's growth by 4.8e-5 and its upper edge by
    3e-4 relative (567.457 against 567.642 rad/s)."""
    from scipy.optimize import minimize_scalar

    from harness import ivp_growth_rate

    make, F0, n_modes, eps = K1_DAMPED[which]
    veh = make()
    kw = dict(F0=F0, n_modes=n_modes, gimbal_gain=0.5, elements_per_segment=eps,
              damping_ratio=0.01)
    full = bending_system(veh, **kw)
    w1 = full.omega_unloaded[2]
    res = vehicle_regions(veh, gamma=0.1, omega_min=0.25 * w1, omega_max=2.0 * w1, k_min=1,
                          k_max=1, max_order=1, axial=False, **kw)
    assert not res.certificates[0].certified  # the rigid pitch is undamped
    assert any(m.type == "rigid-pitch" for r in res.regions for m in r.modes)
    Mf, Cf, Af, Bf = full.matrices(0.1)
    h = res.harmonic(1)
    M, C, A, B = h.matrices(0.1)
    for r in res.regions:
        peak = ivp_growth_rate(Mf, Cf, Af, Bf, r.Omega_at_max)
        assert r.growth_rate_max == pytest.approx(peak, rel=1e-6)
        for edge, inward in ((r.Omega_lo, 1.0), (r.Omega_hi, -1.0)):
            assert _edge_is_a_zero(lambda x: ivp_growth_rate(M, C, A, B, x), edge, inward,
                                   peak), (r.kind, edge)

        def max_growth(gamma, r=r):  # scipy's bounded Brent over the region at gamma = 0.1
            B1 = h.excitation * gamma
            best = minimize_scalar(
                lambda x: -floquet.growth_rate(M, C, A, B1, [x], n_steps=1024)[0],
                bounds=(r.Omega_lo, r.Omega_hi), method="bounded",
                options={"xatol": 1e-9 * r.Omega_hi})
            return -best.fun

        assert r.critical_gamma > 0.0
        assert max_growth(0.999 * r.critical_gamma) < 0.0 < max_growth(1.001 * r.critical_gamma)
    json.dumps(res.to_dict())


# --------------------------------------------------------------------------- chart curves


@pytest.mark.slow
def test_region_curves_reuse_the_map_and_equal_fresh_boundaries(memo_vehicle):
    """region_curves traces from the stored harmonic systems: at the map's own gamma it reuses
    the map's rows as the top level and skips the harmonics without a region; its curves
    equal floquet.region_boundaries of each harmonic searched afresh (every level, the top
    included), to 1e-12 relative.  Default vehicle, undamped, 3 modes, k = 2..3, gamma = 0.3,
    4 levels.  Above the map's gamma it traces every harmonic the certificate does not cover
    (none when damped and certified: the default damping at gamma = 0.05)."""
    kw = dict(F0=2.8e6, omega_min=5.0, omega_max=2000.0, k_min=2, k_max=3, n_modes=3,
              axial=False)
    found = vehicle_regions(memo_vehicle, gamma=0.3, damping_ratio=0.0, **kw)
    curves, gaps = region_curves(found, gamma_max=0.3, n_gamma=4)
    assert gaps == () and found.gaps == () and {c.k for c in curves} == {2, 3}
    for h in found.harmonics:
        M, _, A, _ = h.matrices(0.3)
        fresh = floquet.region_boundaries(M, None, A, h.excitation, gamma_max=0.3,
                                          omega_min=5.0, omega_max=2000.0, n_gamma=4)
        mine = [c for c in curves if c.k == h.k]
        assert [(c.kind, c.order, tuple(c.modes)) for c in mine] == [
            (c.kind, c.order, tuple(c.modes)) for c in fresh]
        for a, b in zip(mine, fresh, strict=True):
            for x, y in ((a.gamma, b.gamma), (a.omega_lo, b.omega_lo),
                         (a.omega_hi, b.omega_hi)):
                np.testing.assert_allclose(x, y, rtol=1e-12)
    damped = vehicle_regions(memo_vehicle, gamma=0.05, damping_ratio=0.01, **kw)
    assert region_curves(damped, gamma_max=0.1, n_gamma=4) == ((), ())
    with pytest.raises(ValueError, match="^gamma_max = "):
        region_curves(found, gamma_max=0.0)


# --------------------------------------------------------------------------- size limits


def readme_vehicle() -> Vehicle:
    """The README's [vehicle] example: a 6 m cylinder and a 1 m cone, free ends, Sanders."""
    mat = {"E": 70e9, "nu": 0.3, "rho": 2700.0}
    return Vehicle([Cylinder(1.5, 6.0, 0.016, **mat), Cone(1.5, 1.0, 1.0, 0.016, **mat)],
                   aft_end="free", fwd_end="free", theory="sanders")


@pytest.mark.slow
def test_every_harmonic_searched_past_the_former_candidate_count():
    """The README vehicle, k = 2, 8 modes, undamped, gamma = 0.05, Omega 1..2000 rad/s: the
    resonance centres of every order in [Omega_min / 2, 2 Omega_max] number more than 200,000
    (counted here from the loaded frequencies: 2 w_i, w_i +- w_k over j), the candidate count
    that left the harmonic out; now only the orders whose width estimate passes the floor are
    examined (a few hundred), in batches, and the harmonic is searched: no gap, some 90 regions
    (about 5 s on one core).  The widest three against the full monodromy (1e-6 relative,
    _check_against_monodromy)."""
    res = vehicle_regions(readme_vehicle(), F0=F0_DEFAULT, gamma=0.05, omega_min=1.0,
                          omega_max=2000.0, k_min=2, k_max=2, n_modes=8, damping_ratio=0.0,
                          axial=False)
    w = res.harmonic(2).omega_loaded
    i, k = np.triu_indices(w.size, 1)
    base = np.concatenate([2 * w, w[i] + w[k], w[k] - w[i]])
    centres = np.sum(np.floor(base / 0.5) - np.maximum(1, np.ceil(base / 4000.0)) + 1)
    assert centres > 200_000
    assert res.gaps == () and len(res.regions) > 50
    _check_against_monodromy(res, 0.05, 3, k=2)


def test_candidate_gaps_equal_the_full_enumeration():
    """The candidate table enumerates only the orders it keeps; the distance of each to the
    nearest other centre of any order in [lo / 2, 2 hi] equals that of the full enumeration
    sorted (exact): the README vehicle, k = 2, 6 modes, Omega 5..2000 rad/s, gamma = 0.3."""
    from flexbooster.floquet.regions import _candidates, _options

    h = harmonic_system(readme_vehicle(), 2, F0=F0_DEFAULT, n_modes=6, damping_ratio=0.0)
    M, _, A, B = h.matrices(0.3)
    system = floquet.periodic_system(M, None, A, B)
    w = np.sqrt(system.mu.real)
    cand = _candidates(w, system.Bt, 5.0, 2000.0, _options())
    i, k = np.triu_indices(w.size, 1)
    base = np.concatenate([2 * w, w[i] + w[k], np.abs(w[k] - w[i])])
    everything = np.sort(np.concatenate([
        b / np.arange(max(1, int(np.ceil(b / 4000.0))), int(np.floor(b / 2.5)) + 1)
        for b in base]))
    assert everything.size > 10 * cand["j"].size
    for c, g in zip(cand["centre"], cand["gap"], strict=True):
        at = np.searchsorted(everything, c)
        near = everything[max(at - 2, 0):at + 3]
        others = np.delete(near, np.argmin(np.abs(near - c)))
        assert g == np.min(np.abs(others - c))



def test_harmonics_past_the_step_limit_are_gaps():
    """An accuracy setting past the toolkit's step limit (step_phase = 1e-6: some 1e7 steps per
    period against max_steps = 200,000): every harmonic of the map and of the chart is a
    SearchGap naming max_steps and its k, no row and no curve; the harmonics are still built
    and certified."""
    res = vehicle_regions(readme_vehicle(), F0=F0_DEFAULT, gamma=0.3, omega_min=5.0,
                          omega_max=2000.0, k_min=2, k_max=3, n_modes=3, damping_ratio=0.0,
                          axial=False, step_phase=1e-6, boundaries=True, gamma_max=0.4,
                          n_gamma=3)
    assert res.regions == () and res.curves == () and len(res.certificates) == 2
    gaps = res.gaps + res.chart_gaps
    assert [(g.stage, g.k, g.limit) for g in gaps] == [("vehicle", k, "max_steps")
                                                       for k in (2, 3, 2, 3)]
    assert [g.reason.split(":")[0] for g in gaps] == [
        "harmonic k = 2 not searched", "harmonic k = 3 not searched",
        "harmonic k = 2 not traced for the chart", "harmonic k = 3 not traced for the chart"]
    assert all("max_steps = 200000" in g.reason for g in gaps)


@pytest.mark.slow
@pytest.mark.parametrize("which", [0, -1], ids=["lift-off", "burnout"])
def test_no_growth_outside_the_regions_of_an_undamped_flight_frozen_case(which):
    """Completeness of the search on a real vehicle, by an independent scan: the undamped
    flight of tests/data/flight_undamped_case.toml frozen at lift-off (gamma = 0.02) and
    burnout (0.2: 938 regions in k = 1..20). On 3,000 points of its Omega range the growth
    rate of each harmonic's periodic system (flexbooster.floquet.growth_rate, the monodromy
    kernel checked against solve_ivp in test_floquet.py) exceeds 1e-9 only inside a region
    the search reported for that harmonic, and at some points it does (the scan sees regions:
    23 points at lift-off, 236 at burnout).
    """
    from pathlib import Path

    from flexbooster.analysis import analyze_vehicle_regions
    from flexbooster.model import flight_times, frozen_case

    flight = flexbooster.load_case(Path(__file__).parent / "data" / "flight_undamped_case.toml")
    found = analyze_vehicle_regions(frozen_case(flight, float(flight_times(flight)[which])))
    grid = np.linspace(found.omega_min, found.omega_max, 3000)
    seen = 0
    for h in found.harmonics:
        g = floquet.growth_rate(*h.periodic(found.gamma), grid)
        unstable = grid[g > 1e-9]
        inside = np.zeros(unstable.size, dtype=bool)
        for r in found.regions:
            if r.k == h.k:
                inside |= (unstable >= r.Omega_lo) & (unstable <= r.Omega_hi)
        assert inside.all(), (h.k, unstable[~inside])
        seen += unstable.size
    assert seen >= 20
