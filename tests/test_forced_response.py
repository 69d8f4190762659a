"""Forced response of the vehicle to the thrust oscillation (flexbooster.dynamics.forced).

Evidence, by tier:

* exact: a free-free thin cylinder under an axial end force against the rod solution with the
  membrane-shell wave speed; a free-free slender tube under a lateral end force against the
  Timoshenko beam (transfer matrix, expm); a resonance against the single-mode closed form;
  the static limit against Newton's inertia relief (axial force, lateral shear and moment);
* independent computation: a direct solve of the full finite-element model (its own static
  inertia-relief solve; the full damped model per Omega); the reduced equations integrated in
  time (solve_ivp) to steady state; the k = 1 system of ``bending_system``;
* convergence: doubling the modes; the static correction against none;
* contract: spectrum lines, stations, bad input, finite output, JSON.

Closed forms written out here (not imported from the code under test):

* axisymmetric membrane waves in a cylinder (radius R; membrane equations with the hoop
  resultant, radial inertia kept, wall bending left out): N_x = E_eff A u', with
  E_eff = E / (1 - nu^2) (1 - nu^2 / (1 - Omega^2 / Omega_r^2)), Omega_r^2 =
  E / (rho (1 - nu^2) R^2) the ring frequency; below it, E_eff -> E as Omega -> 0 (the
  ring free to contract: the bar value); the free-free rod under Delta F cos(Omega t)
  forward at x = 0: u(x) = -Delta F cos(kappa (L - x)) / (E_eff A kappa sin(kappa L)),
  kappa = Omega sqrt(rho / E_eff), N(x) = -Delta F sin(kappa (L - x)) / sin(kappa L)
  (Meirovitch 1986, sec. 5.4 for the rod);
* Timoshenko beam z = (w, phi, M, S), S = dM/dx statically: w' = phi - S / (kappa_s G A),
  phi' = M / (E I), M' = S - rho I Omega^2 phi, S' = rho A Omega^2 w; free ends (M = 0),
  S(0) = P, S(L) = 0; thin tube A = 2 pi R h, I = pi R^3 h, kappa_s = 2 (1 + nu) / (4 + 3
  nu) (G. R. Cowper, J. Appl. Mech. 33 (1966) 335-340, thin-walled round tube);
* inertia relief of a free body under an end force P: rigid accelerations a = P / m and
  theta'' = -P x_cg / J; the part ahead of x carries S(x) = int_x^L mu a and M(x) =
  -int_x^L ((xi - x) mu a + j theta'') d xi (Newton's second law for the part ahead).
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
import scipy.linalg as sla
from scipy.integrate import solve_ivp

from flexbooster.dynamics import ThrustSpectrum, basis_sizes, bending_system, forced_response
from flexbooster.dynamics.forced import QUANTITIES, STANDARD_GRAVITY
from flexbooster.shell_of_revolution import (
    Cone,
    Cylinder,
    Vehicle,
    eigenvalues_below,
    mesh_vehicle,
    system_matrices,
)
from flexbooster.shell_of_revolution.assembly import dof_map, element_set, thrust_prestate

ALU = {"E": 70e9, "nu": 0.3, "rho": 2700.0}
# the thin rod-like cylinder (ring frequency 5340 rad/s, first axial mode 1592 rad/s)
R_ROD, H_ROD, L_ROD = 1.0, 0.01, 10.0
# the slender tube (L / R = 100; first bending modes 80, 220, 429 rad/s)
R_TUBE, H_TUBE, L_TUBE = 0.1, 0.002, 10.0


def rod() -> Vehicle:
    return Vehicle(segments=(Cylinder(R_ROD, L_ROD, H_ROD, **ALU),))


def tube() -> Vehicle:
    return Vehicle(segments=(Cylinder(R_TUBE, L_TUBE, H_TUBE, **ALU),))


def readme_vehicle() -> Vehicle:
    """README.md's [vehicle] example: cylinder 1.5 m x 6 m, cone to 1.0 m over 1 m, 16 mm."""
    return Vehicle(segments=(Cylinder(1.5, 6.0, 0.016, **ALU),
                             Cone(1.5, 1.0, 1.0, 0.016, **ALU)))


def index(res, name: str) -> int:
    return [s.name for s in res.stations].index(name)


def membrane_modulus(om):
    """E_eff of axisymmetric membrane waves in the rod-like cylinder (module docstring)."""
    E, nu, rho = ALU["E"], ALU["nu"], ALU["rho"]
    ring2 = E / (rho * (1.0 - nu**2) * R_ROD**2)
    return E / (1.0 - nu**2) * (1.0 - nu**2 / (1.0 - om**2 / ring2))


# ------------------------------------------------------------------------------- exact


def test_axial_end_force_matches_the_membrane_rod():
    """k = 0: edge displacements and mid-length axial force vs the rod solution, 1 %."""
    om = np.array([500.0, 1200.0, 2200.0])  # below the ring frequency, off resonance
    F0, gamma = 1e3, 0.1  # prestress F0 / (E A) = 2e-7: no effect
    res = forced_response(rod(), F0=F0, amplitude=gamma, Omega=om, damping_ratio=1e-5,
                          harmonics=(0,), stations=[("mid", L_ROD / 2)])
    dF, A = gamma * F0, 2 * np.pi * R_ROD * H_ROD
    Ee = membrane_modulus(om)
    kap = om * np.sqrt(ALU["rho"] / Ee)

    def u(x):
        return -dF * np.cos(kap * (L_ROD - x)) / (Ee * A * kap * np.sin(kap * L_ROD))

    N_mid = -dF * np.sin(kap * L_ROD / 2) / np.sin(kap * L_ROD)
    for name, exact in (("aft-edge", u(0.0)), ("forward-edge", u(L_ROD))):
        np.testing.assert_allclose(res.displacement[0, index(res, name)], exact, rtol=1e-2)
    np.testing.assert_allclose(res.axial_force[0, index(res, "mid")], N_mid, rtol=1e-2)
    # the wave speed matters: with the bar modulus E the aft edge is > 1 % off at 1200, 2200
    kb = om * np.sqrt(ALU["rho"] / ALU["E"])
    bar = -dF / (ALU["E"] * A * kb * np.tan(kb * L_ROD))
    assert np.all(np.abs(res.displacement[0, 0, 1:].real / bar[1:] - 1.0) > 1e-2)


def timoshenko(om: float, P: float, xs) -> np.ndarray:
    """z = (w, phi, M, S) of the free-free Timoshenko tube at the stations xs (docstring)."""
    E, nu, rho = ALU["E"], ALU["nu"], ALU["rho"]
    A, Iy = 2 * np.pi * R_TUBE * H_TUBE, np.pi * R_TUBE**3 * H_TUBE
    kGA = 2 * (1 + nu) / (4 + 3 * nu) * E / (2 * (1 + nu)) * A
    B = np.array([[0, 1, 0, -1 / kGA], [0, 0, 1 / (E * Iy), 0], [0, -rho * Iy * om**2, 0, 1],
                  [rho * A * om**2, 0, 0, 0]])
    T = sla.expm(B * L_TUBE)
    w0, p0 = np.linalg.solve(T[2:, :2], -T[2:, 3] * P)  # M(L) = S(L) = 0
    return np.array([sla.expm(B * x) @ np.array([w0, p0, 0.0, P]) for x in xs])


def test_lateral_end_force_matches_the_timoshenko_tube():
    """k = 1: lateral displacement, shear and moment vs the Timoshenko tube, 1 % (of the
    largest magnitude along the tube for the loads, which pass through zero)."""
    om = np.array([40.0, 150.0, 330.0])  # below, between and above the first bending modes
    F0, gamma, delta = 1.0, 0.5, 0.2  # F0 L^2 / EI = 2e-4: prestress and follower negligible
    res = forced_response(tube(), F0=F0, amplitude=gamma, Omega=om, damping_ratio=1e-5,
                          misalignment=delta, harmonics=(1,),
                          stations=[("quarter", L_TUBE / 4), ("mid", L_TUBE / 2)])
    xs = [s.x for s in res.stations]
    for j, w in enumerate(om):
        z = timoshenko(w, gamma * F0 * math.sin(delta), xs)
        np.testing.assert_allclose(res.displacement[0, :, j], z[:, 0], rtol=1e-2)
        for q, col in (("bending_moment", 2), ("shear_force", 3)):
            err = np.abs(getattr(res, q)[0, :, j] - z[:, col])
            assert np.max(err) <= 1e-2 * np.max(np.abs(z[:, col])), (w, q, err)


def test_resonance_peak_matches_the_single_mode_closed_form():
    """k = 0 at the first axial resonance, zeta = 0.01: the aft-edge peak against
    F_modal phi / (2 zeta omega^2 m_modal) of the model's mode (mass-normalised, m_modal = 1),
    and the peak acceleration against the membrane cylinder's Delta F phi(0)^2 / (2 zeta):
    u = a cos(kappa x), kappa = pi / L, with the Poisson radial motion w = -nu R u' / (1 -
    omega^2 / Omega_r^2) in the kinetic energy, phi(0)^2 = 2 / (m (1 + (nu R kappa / (1 -
    omega^2 / Omega_r^2))^2)) (the rod's 2 / m, 1.1 % less), 1 %."""
    zeta, F0, gamma = 0.01, 1e3, 0.1
    res = forced_response(rod(), F0=F0, amplitude=gamma, Omega=np.linspace(1200, 2000, 41),
                          damping_ratio=zeta, harmonics=(0,))
    model = res.models[0]
    n = model.n_rigid  # the first elastic mode: the resonance in the range
    w = model.omega_modes[n]
    phi_aft = model.stiffness_map[0, 0, n]  # mode's aft-edge displacement (symmetric k = 0)
    single = gamma * F0 * abs(model.load[n] * phi_aft) / (2 * zeta * w**2)
    peak = res.peak(0, "aft-edge", "displacement")
    assert peak.value == pytest.approx(single, rel=1e-2)
    assert peak.omega == pytest.approx(w, rel=1e-3)
    mass = 2 * np.pi * R_ROD * H_ROD * L_ROD * ALU["rho"]
    acc = res.peak(0, "aft-edge", "acceleration")
    ring2 = ALU["E"] / (ALU["rho"] * (1 - ALU["nu"] ** 2) * R_ROD**2)
    radial = ALU["nu"] * R_ROD * (np.pi / L_ROD) / (1 - w**2 / ring2)
    assert acc.value == pytest.approx(gamma * F0 / (zeta * mass * (1 + radial**2)), rel=1e-2)
    np.testing.assert_allclose(res.acceleration_g, res.acceleration / 9.80665, rtol=1e-15)


def test_static_limit_is_newtons_inertia_relief():
    """Omega -> 0: axial force = -Delta F m_ahead / m (k = 0, with the prestress of F0 on the
    README vehicle, 1e-4) and lateral shear and moment of the free tube (k = 1, 1e-4 of the
    largest)."""
    v = readme_vehicle()
    h, rho = 0.016, ALU["rho"]
    m_cyl = 2 * np.pi * 1.5 * 6.0 * h * rho

    def frustum(x):  # shell mass of the cone ahead of x >= 6 m (r from 1.5 to 1.0 m)
        r = 1.5 - 0.5 * (x - 6.0)
        return np.pi * (r + 1.0) * math.hypot(7.0 - x, r - 1.0) * h * rho

    def ahead(x):  # shell mass ahead of x (kg)
        return m_cyl * (6.0 - x) / 6.0 + frustum(6.0) if x <= 6.0 else frustum(x)

    total = m_cyl + frustum(6.0)
    kw = {"F0": 2.8e6, "amplitude": 0.05, "Omega": np.array([0.5]), "n_modes": 3,
          "harmonics": (0,), "stations": [("s3", 3.0), ("cone", 6.5)]}
    res = forced_response(v, **kw)
    exact = np.array([-0.05 * 2.8e6 * ahead(s.x) / total for s in res.stations])
    got = res.axial_force[0, :, 0]
    assert np.max(np.abs(got - exact)) <= 1e-4 * 0.05 * 2.8e6
    # k = 1: the free tube (F0 L^2 / EI = 2e-4), lateral force P at the aft edge
    P = 0.5 * math.sin(0.2)
    res = forced_response(tube(), F0=1.0, amplitude=0.5, misalignment=0.2, n_modes=3,
                          Omega=np.array([0.3]), harmonics=(1,),
                          stations=[(f"x{i}", 2.0 * i) for i in range(1, 5)])
    mu = 2 * np.pi * R_TUBE * H_TUBE * rho
    j = mu * R_TUBE**2 / 2  # rotary inertia per length of the thin tube (kg m)
    m, J = mu * L_TUBE, mu * L_TUBE**3 / 12 + j * L_TUBE
    a0, th = P / m, -P * (L_TUBE / 2) / J
    x = np.array([s.x for s in res.stations])
    S = mu * (a0 * (L_TUBE - x) + th * ((L_TUBE - L_TUBE / 2) ** 2 - (x - L_TUBE / 2) ** 2) / 2)
    d = L_TUBE - x  # int_x^L (xi - x) (a0 + th (xi - L/2)) dxi, then + j th (L - x)
    M = -(mu * (a0 * d**2 / 2 + th * (d**3 / 3 + d**2 / 2 * (x - L_TUBE / 2))) + j * th * d)
    assert np.max(np.abs(res.shear_force[0, :, 0] - S)) <= 1e-4 * P
    assert np.max(np.abs(res.bending_moment[0, :, 0] - M)) <= 1e-4 * np.max(np.abs(M))


# ----------------------------------------------------------------- independent computation


def full_k0(v: Vehicle, F0: float):
    """M, K_e + K_g of k = 0 and the axial displacement u_x of the aft and forward edges as
    vectors over the reduced DOFs (node DOFs (a, v, b, chi) in the frame of angle phi:
    u_x = a cos(phi) - b sin(phi))."""
    mesh = mesh_vehicle(v)
    M, K, G = system_matrices(v, 0, prestress_F0=F0, mesh=mesh)
    dmap = dof_map(v, mesh, 0)
    ends = []
    for node, phi in zip(mesh.end_nodes[:2], (mesh.frame[0, 0], mesh.frame[-1, 1]),
                         strict=True):
        e = np.zeros(K.shape[0])
        for dof, w in ((node, math.cos(phi)), (node + 2, -math.sin(phi))):
            if dmap.index[dof] >= 0:
                e[dmap.index[dof]] += w * dmap.coef[dof]
        ends.append(e)
    return M, K + G, ends


def test_static_stretch_matches_a_direct_inertia_relief_solve():
    """k = 0 with the prestress: u(fwd) - u(aft) at Omega -> 0 against the full model's static
    inertia-relief solve (bordered by its two rigid modes), 1e-4; without the static
    correction (3 or 10 modes) it is more than 20 % short."""
    F0, gamma = 2e7, 0.05
    v = Vehicle(segments=(Cylinder(1.5, 6.0, 0.016, **ALU),))
    M, K, ends = full_k0(v, F0)
    w2, R = sla.eigh(K, M, subset_by_index=(0, 2))  # axial translation and torsion
    assert np.all(np.abs(w2[:2]) < 1e-9 * w2[2])
    R = R[:, :2]
    f = gamma * F0 * ends[0]  # the generalised force of the aft-edge load
    rel = f - M @ R @ (R.T @ f)  # minus the rigid inertia force (inertia relief)
    sol = np.linalg.solve(np.block([[K, M @ R], [R.T @ M, np.zeros((2, 2))]]),
                          np.concatenate([rel, np.zeros(2)]))
    stretch = (ends[1] - ends[0]) @ sol[:K.shape[0]]
    for n_modes, correction in ((3, True), (3, False), (10, False)):
        res = forced_response(v, F0=F0, amplitude=gamma, Omega=np.array([1.0]),
                              n_modes=n_modes, harmonics=(0,), static_correction=correction)
        got = (res.displacement[0, -1, 0] - res.displacement[0, 0, 0]).real
        if correction:
            assert got == pytest.approx(stretch, rel=1e-4)
        else:
            assert abs(got / stretch - 1.0) > 0.2


def test_k0_agrees_with_the_full_damped_model_per_omega():
    """README vehicle, k = 0: edge displacements against a direct solve of the full model per
    Omega, (K - Omega^2 M + i Omega M V D V^T M) X = F with the loaded modes V below
    4 max Omega damped (D = 2 zeta omega), 1e-4 of the largest amplitude.  The junction's
    axial force (force summation over the part ahead) against the other method on the
    full model's solution, the nodal force (K_e + K_g - Omega^2 M) x_e of the element ahead,
    1e-4 (zeta = 1e-5: the methods differ by the damping forces of the part ahead, O(zeta))."""
    F0, gamma = 2.8e6, 0.05
    om = np.linspace(50.0, 2000.0, 40)  # below the first axial mode (2020 rad/s)
    v = readme_vehicle()
    M, K, ends = full_k0(v, F0)
    w2, V = sla.eigh(K, M, subset_by_value=(1.0, (4 * om[-1]) ** 2))
    mesh = mesh_vehicle(v)
    m_el, k_el, g_el = element_set(v, mesh, 0, prestate=thrust_prestate(v, mesh, F0))
    e = mesh.elements_per_segment[0]  # the first element of the cone: ahead of the junction
    for zeta in (0.02, 1e-5):
        MV = M @ V
        C = MV @ np.diag(2 * zeta * np.sqrt(w2)) @ MV.T
        f = gamma * F0 * ends[0]
        X = np.array([np.linalg.solve(K - w**2 * M + 1j * w * C, f) for w in om])
        res = forced_response(v, F0=F0, amplitude=gamma, Omega=om, damping_ratio=zeta,
                              harmonics=(0,))
        direct = X @ np.array(ends).T
        got = res.displacement[0, [0, -1]].T
        assert np.max(np.abs(got - direct)) <= 1e-4 * np.max(np.abs(direct))
    xe = dof_map(v, mesh, 0).expand(X)[:, mesh.dofs[e]]
    nodal = np.array([((k_el[e] + g_el[e] - w**2 * m_el[e]) @ x)[0] for w, x in zip(
        om, xe, strict=True)])  # the junction node: global frame, DOF 0 = u_x
    N = res.axial_force[0, index(res, "junction-1")]
    assert np.max(np.abs(N + nodal)) <= 1e-4 * np.max(np.abs(nodal))


def steady_amplitude(model, load: float, om: float, t_end: float, out) -> complex:
    """Complex amplitude at Omega of out(t, q, q'') over the last 10 periods of the reduced
    equations q'' + C q' + A q = f load cos(Omega t) integrated from rest (DOP853, rtol
    1e-10): 2/T int out e^{-i Omega t} dt."""
    A, C, f = model.stiffness, model.damping, model.load * load
    m = f.size
    S = np.block([[np.zeros((m, m)), np.eye(m)], [-A, -C]])
    b = np.concatenate([np.zeros(m), f])

    def rhs(t, z):
        return S @ z + b * np.cos(om * t)

    sol = solve_ivp(rhs, (0.0, t_end), np.zeros(2 * m), method="DOP853", rtol=1e-10,
                    atol=1e-16, dense_output=True)
    assert sol.success
    t = np.linspace(t_end - 10 * 2 * np.pi / om, t_end, 4001)
    z = sol.sol(t)
    ddq = (S @ z + np.outer(b, np.cos(om * t)))[m:]
    y = out(t, z[:m], ddq) * np.exp(-1j * om * t)
    return 2.0 * np.trapezoid(y, t) / (t[-1] - t[0])


def test_peak_matches_time_integration_of_the_modal_equations():
    """The k = 0 resonance peak (aft acceleration, zeta = 0.2) and a k = 1 bending moment with
    the gimbal (non-symmetric A) against solve_ivp of the reduced equations to steady state
    (one elastic mode and the static correction), 1e-6 (the integration: rtol 1e-10)."""
    F0, gamma = 1e3, 0.1
    res = forced_response(rod(), F0=F0, amplitude=gamma, n_modes=1, damping_ratio=0.2,
                          Omega=np.linspace(1000, 2500, 31), harmonics=(0,))
    mdl, peak = res.models[0], res.peak(0, "aft-edge", "acceleration")
    om = peak.omega
    assert 1200.0 < om < 2000.0  # the first axial resonance, 1592 rad/s

    def aft_acc(t, q, ddq):  # displacement row: map q + static part (Delta F cos)
        return (mdl.stiffness_map[0, 0] @ ddq
                - om**2 * mdl.static_stiffness[0, 0] * gamma * F0 * np.cos(om * t))

    amp = steady_amplitude(mdl, gamma * F0, om, 0.1, aft_acc)  # e^{-0.2 x 1592 x 0.1}
    assert abs(amp) == pytest.approx(peak.value, rel=1e-6)
    # k = 1, gimbal K = 0.5, damped pitch: the bending moment at mid-length
    F0, om = 3e4, 60.0
    res = forced_response(tube(), F0=F0, amplitude=gamma, Omega=np.array([om]), n_modes=1,
                          damping_ratio=0.1, pitch_damping_ratio=0.3, gimbal_gain=0.5,
                          misalignment=0.1, harmonics=(1,), stations=[("mid", 5.0)])
    mdl = res.models[0]
    node = int(np.argmin(np.abs(mdl.node_x - 5.0)))
    assert not np.allclose(mdl.stiffness, mdl.stiffness.T)  # the follower and gimbal terms

    def moment(t, q, ddq):  # (stiffness_map - Omega^2 mass_map) q: q'' for -Omega^2 q
        c = gamma * F0 * np.cos(om * t)
        return (mdl.stiffness_map[node, 2] @ q + mdl.mass_map[node, 2] @ ddq
                + (mdl.static_stiffness[node, 2] - om**2 * mdl.static_mass[node, 2]) * c)

    amp = steady_amplitude(mdl, gamma * F0, om, 3.5, moment)  # pitch: 0.3 x 16 rad/s, e^{-15}
    want = res.bending_moment[0, index(res, "mid"), 0]
    assert abs(amp - want) <= 1e-6 * abs(want)


def test_k1_system_is_bending_systems():
    """Without the static correction the k = 1 reduced stiffness is ``bending_system``'s
    (same basis size): equal eigenvalues, 1e-8 relative to the largest."""
    v, F0, K = readme_vehicle(), 2.8e6, 0.5
    res = forced_response(v, F0=F0, amplitude=0.05, Omega=np.array([100.0]), n_modes=10,
                          misalignment=0.01, gimbal_gain=K, pitch_damping_ratio=0.1,
                          harmonics=(1,), static_correction=False)
    mine = np.sort_complex(np.linalg.eigvals(res.models[0].stiffness))
    theirs = np.sort_complex(np.linalg.eigvals(
        bending_system(v, F0=F0, n_modes=12, gimbal_gain=K).stiffness))
    assert np.max(np.abs(mine - theirs)) <= 1e-8 * np.max(np.abs(theirs))


def test_gimbaled_pitch_resonance_is_the_rigid_pitch_frequency():
    """Free tube, gimbal K: the rigid pitch stiffness of the modal system is K F0 x_cg / J
    (x_cg = L/2, J = m (L^2/12 + R^2/2); memo eq. 2.2-2 linearised), 1e-6; with the static
    correction the elastic deformation under the gimbal force lowers it (1.6 % at
    F0 L^2 / EI = 6.8); at F0 L^2 / EI = 0.07 the damped forward-edge displacement peaks
    there: the aft-edge acceleration (zeta_psi = 0.02: |H| peaks within zeta^2 of omega),
    2e-3."""
    m = 2 * np.pi * R_TUBE * H_TUBE * ALU["rho"] * L_TUBE
    K = 0.5
    for F0, correction, rtol in ((3e4, False, 1e-6), (3e4, True, 2e-2), (3e2, True, 2e-4)):
        w_psi = math.sqrt(K * F0 * (L_TUBE / 2) / (m * (L_TUBE**2 / 12 + R_TUBE**2 / 2)))
        res = forced_response(tube(), F0=F0, amplitude=0.1, misalignment=0.1, gimbal_gain=K,
                              Omega=np.linspace(0.3, 3.0, 28) * w_psi, harmonics=(1,),
                              pitch_damping_ratio=0.02, static_correction=correction)
        assert res.models[0].stiffness[0, 0] == pytest.approx(w_psi**2, rel=rtol)
    peak = res.peak(1, "aft-edge", "acceleration")
    assert peak.omega == pytest.approx(w_psi, rel=2e-3)


# ------------------------------------------------------------------------------ convergence


def relative_change(a, b) -> float:
    """Largest |peak change| over the stations, relative to the largest peak of the same
    harmonic and quantity (a load passing through zero has no relative accuracy)."""
    out = 0.0
    for p, q in zip(a.peaks, b.peaks, strict=True):
        top = max(r.value for r in b.peaks if (r.k, r.quantity) == (q.k, q.quantity))
        out = max(out, abs(p.value - q.value) / top)
    return out


def test_doubling_the_modes_changes_the_peaks_by_less_than_1e_3():
    """README vehicle, Omega 5..2000 rad/s: the default basis (every mode below 4 max Omega:
    29 axial, 34 lateral) and twice as many give the same peaks to 1e-3 (measured 1.2e-4,
    5e-5); without the static correction the axial ones move by more (measured 4e-3)."""
    v = readme_vehicle()
    kw = {"F0": 2.8e6, "amplitude": 0.05, "Omega": np.linspace(5.0, 2000.0, 400),
          "misalignment": 0.01, "gimbal_gain": 0.5, "pitch_damping_ratio": 0.02,
          "stations": [("payload", 6.5)]}
    base = forced_response(v, **kw)
    counts = [md.omega_modes.size - md.n_rigid for md in base.models]
    assert counts == [29, 34]
    double = [forced_response(v, n_modes=2 * n, harmonics=(k,), **kw)
              for k, n in zip((0, 1), counts, strict=True)]
    for k, other in zip((0, 1), double, strict=True):
        one = forced_response(v, n_modes=counts[k], harmonics=(k,), **kw)
        assert relative_change(one, other) < 1e-3
    bare = [forced_response(v, n_modes=n, harmonics=(0,), static_correction=False, **kw)
            for n in (counts[0], 2 * counts[0])]
    assert relative_change(*bare) > 1e-3


@pytest.mark.parametrize(("vehicle", "top"), [
    (readme_vehicle, 2000.0), (lambda: tank_vehicle(1.0), 900.0),
    (lambda: tank_vehicle(0.6), 900.0), (tube, 60.0)])
def test_counted_basis_is_the_solvers_basis(vehicle, top):
    """The basis counted up front for the cost estimate (Sylvester's law of inertia on
    K - (4 Omega_max)^2 M, no eigenvector) equals the basis the response takes (LAPACK's
    eigenpairs by value below the same bound, rigid ones included; at least 6): the README
    vehicle (29 + 1 axial, 34 + 2 lateral), the closed full tank (volume-keeping motions at
    k = 0), the part-full one, and the slender tube below its first bending mode (the minimum
    6). Exact integers."""
    v = vehicle()
    kw = {"F0": 2.8e5, "stations": [("payload", 6.5)]}
    res = forced_response(v, amplitude=0.05, Omega=np.linspace(5.0, top, 20),
                          damping_ratio=0.02, misalignment=0.01, **kw)
    sizes = basis_sizes(v, omega_max=top, **kw)
    assert sizes == tuple(md.omega_modes.size for md in res.models)


def test_eigenvalues_below_dense_path_counts_an_indefinite_pencil():
    """Sylvester's count when the sparse factorisation needs an interchange: K - w2 M with a
    zero diagonal ([[0, B], [B^T, 0]]: every first pivot is zero, so the dense Bunch-Kaufman
    path), against the count of numpy's eigvalsh of M^-1/2 K M^-1/2 (independent; 20
    negative of 40), at three shifts."""
    rng = np.random.default_rng(3)
    B = rng.standard_normal((20, 20))
    K = np.block([[np.zeros((20, 20)), B], [B.T, np.zeros((20, 20))]])
    M = np.diag(1.0 + rng.random(40))
    lam = np.linalg.eigvalsh(np.diag(np.diag(M) ** -0.5) @ K @ np.diag(np.diag(M) ** -0.5))
    for w2 in (-3.0, 0.0, 4.0):
        assert eigenvalues_below(K + w2 * M, M, w2) == int(np.count_nonzero(lam < 0.0))


# --------------------------------------------------------------------------------- contract


def test_spectrum_is_the_sum_of_its_lines():
    """Each line's response is the sweep's at its Omega times its amplitude (linearity); a
    station's peak is the sum of the lines' amplitudes (incommensurate lines)."""
    v = readme_vehicle()
    lines = ThrustSpectrum(frequency=[300.0, 1100.0, 1500.0], amplitude=[0.01, 0.02, 0.005])
    kw = {"F0": 2.8e6, "misalignment": 0.01}
    spec = forced_response(v, amplitude=lines, **kw)
    sweep = forced_response(v, amplitude=0.1, Omega=lines.frequency, **kw)
    assert spec.combination == "spectrum"
    for q in QUANTITIES:
        np.testing.assert_allclose(getattr(spec, q), getattr(sweep, q) * lines.amplitude / 0.1,
                                   rtol=1e-12, atol=0.0)
    for p in spec.peaks:
        row = getattr(spec, p.quantity)[spec.harmonics.index(p.k), index(spec, p.station)]
        assert p.value == pytest.approx(np.sum(np.abs(row)), rel=1e-12)
        assert p.omega == lines.frequency[np.argmax(np.abs(row))]


def test_stations_and_cut_segments():
    """Stations aft to forward (edges, junctions, the caller's); cutting the vehicle at a user
    station leaves the edges' response unchanged (1e-5: the mesh differs); a station in a
    cone."""
    v = readme_vehicle()
    kw = {"F0": 2.8e6, "amplitude": 0.05, "Omega": np.array([100.0, 400.0, 800.0]),
          "misalignment": 0.01}
    plain = forced_response(v, **kw)
    cut = forced_response(v, stations=[("payload", 6.5), ("tank", 2.0)], **kw)
    assert [(s.name, s.x, s.kind) for s in cut.stations] == [
        ("aft-edge", 0.0, "edge"), ("tank", 2.0, "user"), ("junction-1", 6.0, "junction"),
        ("payload", 6.5, "user"), ("forward-edge", 7.0, "edge")]
    for q in ("displacement", "acceleration"):
        a, b = getattr(plain, q)[:, [0, -1]], getattr(cut, q)[:, [0, -1]]
        assert np.max(np.abs(a - b)) <= 1e-5 * np.max(np.abs(a))
    # element counts per segment are shared by its pieces in proportion to their lengths
    res = forced_response(v, elements_per_segment=(4, 2), stations=[("tank", 3.0)], **kw)
    np.testing.assert_allclose(res.models[0].node_x, [0, 1.5, 3, 4.5, 6, 6.5, 7], atol=1e-12)
    # envelopes: one per internal load, every mesh node, x non-decreasing
    assert [(e.k, e.quantity) for e in cut.envelopes] == [
        (0, "axial_force"), (1, "shear_force"), (1, "bending_moment")]
    for e in cut.envelopes:
        assert np.all(np.diff(e.x) >= 0.0) and e.x[0] == 0.0 and e.x[-1] == 7.0
        assert np.max(np.abs(e.at_worst)) == pytest.approx(np.max(e.peak), rel=1e-9)


def test_no_misalignment_no_lateral_response_and_json():
    """delta = 0: k = 1 exactly zero; every array finite; to_dict is JSON."""
    res = forced_response(readme_vehicle(), F0=2.8e6, amplitude=0.05,
                          Omega=np.linspace(5.0, 2000.0, 50))
    for q in QUANTITIES:
        arr = getattr(res, q)
        assert np.all(np.isfinite(arr))
        assert np.all(arr[1] == 0.0)
    assert np.all(res.shear_force[0] == 0.0) and np.all(res.bending_moment[0] == 0.0)
    assert all(p.value == 0.0 for p in res.peaks if p.k == 1)
    text = json.dumps(res.to_dict(models=True))
    back = json.loads(text)
    assert back["standard_gravity"] == STANDARD_GRAVITY
    assert len(back["peaks"]) == len(res.peaks)


@pytest.mark.parametrize(("kwargs", "name"), [
    ({"F0": float("nan")}, "F0"),
    ({"F0": -1.0}, "F0"),
    ({"amplitude": 1.0}, "amplitude"),
    ({"amplitude": float("inf")}, "amplitude"),
    ({"Omega": [100.0, float("nan")]}, "Omega"),
    ({"Omega": [200.0, 100.0]}, "Omega"),
    ({"Omega": [0.0, 100.0]}, "Omega"),
    ({"Omega": []}, "Omega"),
    ({"damping_ratio": 1.0}, "damping_ratio"),
    ({"damping_ratio": -0.1}, "damping_ratio"),
    ({"pitch_damping_ratio": float("nan")}, "pitch_damping_ratio"),
    ({"misalignment": 2.0}, "misalignment"),
    ({"gimbal_gain": -1.0}, "gimbal_gain"),
    ({"stations": [("x", 8.0)]}, "stations[0].station_m"),
    ({"stations": [("aft-edge", 1.0)]}, "stations[0].name"),
    ({"stations": [("a", 1.0), ("a", 2.0)]}, "stations[1].name"),
    ({"stations": ["a"]}, "stations[0]"),
    ({"harmonics": (2,)}, "harmonics"),
    ({"n_modes": 0}, "n_modes"),
    ({"amplitude": ThrustSpectrum([1.0], [0.1])}, "Omega"),
])
def test_bad_input_names_the_parameter(kwargs, name):
    args = {"F0": 1e6, "amplitude": 0.05, "Omega": [100.0, 200.0]} | kwargs
    with pytest.raises(ValueError, match=r"^" + name.replace("[", r"\[").replace("]", r"\]")):
        forced_response(readme_vehicle(), **args)


def test_spectrum_lines_are_checked():
    with pytest.raises(ValueError, match="spectrum.frequency"):
        ThrustSpectrum([2.0, 1.0], [0.1, 0.1])
    with pytest.raises(ValueError, match="spectrum.amplitude"):
        ThrustSpectrum([1.0, 2.0], [0.1, 1.5])


def test_an_undamped_resonance_in_the_range_is_refused():
    """zeta = 0 with the first axial mode (1592 rad/s) in the range: unbounded, refused
    naming damping_ratio; out of the range: finite.  The gimbaled pitch (1.6 rad/s) without
    pitch damping: refused naming pitch_damping_ratio; a bending mode with zeta = 1e-7 (below
    the 1e-6 that counts as damped): naming damping_ratio."""
    kw = {"F0": 1e3, "amplitude": 0.1, "damping_ratio": 0.0, "harmonics": (0,)}
    with pytest.raises(ValueError, match=r"^damping_ratio = 0\.0: the k = 0 mode at 159"):
        forced_response(rod(), Omega=np.linspace(1000.0, 2000.0, 11), **kw)
    ok = forced_response(rod(), Omega=np.linspace(100.0, 1500.0, 11), **kw)
    assert all(np.isfinite(p.value) for p in ok.peaks)
    with pytest.raises(ValueError, match=r"^pitch_damping_ratio = 0\.0: the k = 1 mode at 1\."):
        forced_response(tube(), F0=3e2, amplitude=0.1, Omega=np.linspace(0.5, 4.0, 8),
                        misalignment=0.1, gimbal_gain=0.5, harmonics=(1,))
    with pytest.raises(ValueError, match=r"^damping_ratio = 1e-07: the k = 1 mode at 80\."):
        forced_response(tube(), F0=1.0, amplitude=0.1, Omega=[40.0, 150.0], misalignment=0.1,
                        damping_ratio=1e-7, harmonics=(1,))  # an effective ratio < 1e-6
    spec = ThrustSpectrum([1000.0, 1591.8792155], [0.01, 0.01])  # a line on the resonance
    with pytest.raises(ValueError, match=r"^damping_ratio = 0\.0: .* on a line"):
        forced_response(rod(), F0=1e3, amplitude=spec, damping_ratio=0.0, harmonics=(0,))


def test_acceleration_is_minus_omega_squared_displacement():
    res = forced_response(readme_vehicle(), F0=2.8e6, amplitude=0.05, misalignment=0.02,
                          Omega=np.array([50.0, 500.0]))
    np.testing.assert_allclose(res.acceleration, -(res.omega**2) * res.displacement,
                               rtol=1e-14)
    assert STANDARD_GRAVITY == 9.80665


def test_cut_vehicle_keeps_the_wall_fields_masses_and_tanks():
    """Cutting a segment at a station (for an output station) keeps its pressure, non-structural
    mass and stiffeners in every piece and the vehicle's masses and tanks (exact equality)."""
    from flexbooster.dynamics.forced_model import cut_vehicle
    from flexbooster.shell_of_revolution import LumpedMass, Stiffeners, VehicleTank

    rings = Stiffeners(spacing=0.5, area=3e-4, inertia=4e-8, eccentricity=0.02)
    mat = {"E": 70e9, "nu": 0.3, "rho": 2700.0}
    veh = Vehicle([Cylinder(1.0, 6.0, 0.004, **mat, pressure=1e5, nonstructural_mass=2.0,
                            rings=rings),
                   Cone(1.0, 0.5, 2.0, 0.003, **mat, pressure=5e4)],
                  masses=(LumpedMass(0.0, 300.0),), tanks=(VehicleTank(0.0, 6.0, 0.5, 800.0),))
    cut, _, starts = cut_vehicle(veh, [2.5, 7.0], None)
    assert len(cut.segments) == 4 and starts == (0, 2)
    for piece, seg in zip(cut.segments, (0, 0, 1, 1), strict=True):
        src = veh.segments[seg]
        assert (piece.pressure, piece.nonstructural_mass, piece.rings, piece.stringers) == (
            src.pressure, src.nonstructural_mass, src.rings, src.stringers)
    assert cut.masses == veh.masses and cut.tanks == veh.tanks


# ------------------------------------------------------------- lumped masses and tanks

M_END = 2000.0  # kg at the rod's nose (1.2 x the rod's own 1696 kg)


def test_axial_end_force_with_an_end_mass_matches_the_rod():
    """k = 0, the rod-like cylinder with a lumped mass m at its nose: edge displacements and the
    mid-length axial force against the exact rod with an end mass, 1 %: u = a cos(kappa x) +
    b sin(kappa x), E_eff A u'(0) = -Delta F, E_eff A u'(L) = m Omega^2 u(L) (Newton for the
    mass; Meirovitch 1986, sec. 5.4), N = E_eff A u'; the nose row is the load just aft of the
    mass, N(L) = m Omega^2 u(L)."""
    from flexbooster.shell_of_revolution import LumpedMass

    om = np.array([300.0, 900.0, 1500.0])  # below the ring frequency, off resonance
    F0, gamma = 1e3, 0.1
    v = Vehicle(segments=rod().segments, masses=(LumpedMass(L_ROD, M_END),))
    res = forced_response(v, F0=F0, amplitude=gamma, Omega=om, damping_ratio=1e-5,
                          harmonics=(0,), stations=[("mid", L_ROD / 2)])
    dF, A = gamma * F0, 2 * np.pi * R_ROD * H_ROD
    Ee = membrane_modulus(om)
    kap = om * np.sqrt(ALU["rho"] / Ee)
    EA = Ee * A
    b = -dF / (EA * kap)
    c, s = np.cos(kap * L_ROD), np.sin(kap * L_ROD)
    # kap (-a s + b c) EA = m om^2 (a c + b s)
    a = b * (kap * c * EA - M_END * om**2 * s) / (kap * s * EA + M_END * om**2 * c)

    def u(x):
        return a * np.cos(kap * x) + b * np.sin(kap * x)

    def N(x):
        return EA * kap * (-a * np.sin(kap * x) + b * np.cos(kap * x))

    for name, x in (("aft-edge", 0.0), ("forward-edge", L_ROD)):
        np.testing.assert_allclose(res.displacement[0, index(res, name)], u(x), rtol=1e-2)
    np.testing.assert_allclose(res.axial_force[0, index(res, "mid")], N(L_ROD / 2), rtol=1e-2)
    nose = res.axial_force[0, index(res, "forward-edge")]
    np.testing.assert_allclose(nose, M_END * om**2 * u(L_ROD), rtol=1e-2)


def timoshenko_end_mass(om: float, P: float, m: float, J: float, xs) -> np.ndarray:
    """z = (w, phi, M, S) of the free-free Timoshenko tube (module docstring) with a rigid mass m
    and rotary inertia J at x = L: S(L) = -m Omega^2 w(L), M(L) = J Omega^2 phi(L) (the loads
    just aft of the mass, Newton for the mass)."""
    E, nu, rho = ALU["E"], ALU["nu"], ALU["rho"]
    A, Iy = 2 * np.pi * R_TUBE * H_TUBE, np.pi * R_TUBE**3 * H_TUBE
    kGA = 2 * (1 + nu) / (4 + 3 * nu) * E / (2 * (1 + nu)) * A
    B = np.array([[0, 1, 0, -1 / kGA], [0, 0, 1 / (E * Iy), 0], [0, -rho * Iy * om**2, 0, 1],
                  [rho * A * om**2, 0, 0, 0]])
    BC = np.array([[0.0, -J * om**2, 1.0, 0.0], [m * om**2, 0.0, 0.0, 1.0]]) @ sla.expm(
        B * L_TUBE)
    w0, p0 = np.linalg.solve(BC[:, :2], -BC[:, 3] * P)
    return np.array([sla.expm(B * x) @ np.array([w0, p0, 0.0, P]) for x in xs])


def test_lateral_end_force_with_a_nose_mass_matches_the_timoshenko_tube():
    """k = 1: the slender tube with a lumped mass (0.5 x the tube's 33.9 kg) and rotary inertia
    at its nose: displacement, shear and moment against the Timoshenko tube with the end mass
    (transfer matrix), 1 % (of the largest magnitude for the loads)."""
    from flexbooster.shell_of_revolution import LumpedMass

    m, J = 17.0, 2.0  # kg, kg m^2 (about its own centre of mass, at the nose)
    v = Vehicle(segments=tube().segments,
                masses=(LumpedMass(L_TUBE, m, transverse_inertia=J),))
    om = np.array([30.0, 120.0, 260.0])
    F0, gamma, delta = 1.0, 0.5, 0.2
    res = forced_response(v, F0=F0, amplitude=gamma, Omega=om, damping_ratio=1e-5,
                          misalignment=delta, harmonics=(1,),
                          stations=[("quarter", L_TUBE / 4), ("mid", L_TUBE / 2)])
    xs = [s.x for s in res.stations]
    for j, w in enumerate(om):
        z = timoshenko_end_mass(w, gamma * F0 * math.sin(delta), m, J, xs)
        np.testing.assert_allclose(res.displacement[0, :, j], z[:, 0], rtol=1e-2)
        for q, col in (("bending_moment", 2), ("shear_force", 3)):
            err = np.abs(getattr(res, q)[0, :, j] - z[:, col])
            assert np.max(err) <= 1e-2 * np.max(np.abs(z[:, col])), (w, q, err)


def tank_vehicle(fill: float) -> Vehicle:
    """Skirt 2 m, tank barrel 6 m, forward skirt 2 m (R 1 m, 6 mm aluminium), an engine of
    500 kg at the aft edge, a payload of 300 kg at 9 m, liquid (1140 kg/m^3) from 2 to 8 m."""
    from flexbooster.shell_of_revolution import LumpedMass, VehicleTank

    cyl = {"radius": 1.0, "thickness": 0.006, **ALU}
    return Vehicle(segments=(Cylinder(length=2.0, **cyl), Cylinder(length=6.0, **cyl),
                             Cylinder(length=2.0, **cyl)),
                   masses=(LumpedMass(0.0, 500.0), LumpedMass(9.0, 300.0)),
                   tanks=(VehicleTank(2.0, 8.0, fill, 1140.0),))


@pytest.mark.parametrize("fill", [1.0, 0.6])
def test_tank_static_limit_is_the_rigid_inertia_relief(fill):
    """k = 0, Omega -> 0, a full closed tank (volume kept) or a tank filled to 60 % (surface at
    5.6 m): the axial force = -Delta F (mass ahead) / (total mass) (Newton for the part ahead:
    shell 2 pi R h rho per metre, the masses, and the liquid rho_L pi R^2 h_L, whose inertia
    the aft bulkhead takes at k = 0: the cylinder wall's normal has no axial component, the
    free surface p = 0; so the liquid is ahead of a station iff the station is at or aft of the
    tank's aft end), 1e-6 of Delta F (Omega / omega_1 ~ 1e-4: the elastic share ~ 1e-8). The
    full tank is checked outside it only (between its ends the uniform pressure that keeps
    the volume loads the forward bulkhead as well)."""
    v = tank_vehicle(fill)
    mu = 2 * np.pi * 1.0 * 0.006 * ALU["rho"]
    liquid = 1140.0 * np.pi * 6.0 * fill
    total = mu * 10.0 + 800.0 + liquid

    def ahead(x):
        return (mu * (10.0 - x) + 500.0 * (x <= 0.0) + 300.0 * (x <= 9.0)
                + liquid * (x <= 2.0))

    dF = 0.05 * 1e3
    res = forced_response(v, F0=1e3, amplitude=0.05, Omega=np.array([0.05]), n_modes=4,
                          harmonics=(0,), stations=[("skirt", 1.0), ("wet", 4.0),
                                                    ("ullage", 7.0), ("nose-skirt", 9.5)])
    checked = 0
    for s in res.stations:
        if fill == 1.0 and 2.0 < s.x <= 8.0:
            continue
        exact = -dF * ahead(s.x) / total
        assert abs(res.axial_force[0, index(res, s.name), 0] - exact) <= 1e-6 * dF, s
        checked += 1
    assert checked == (5 if fill == 1.0 else 8)


@pytest.mark.parametrize("fill", [0.6, 1.0])
def test_free_ends_balance_the_inertia_of_masses_and_liquid(fill):
    """At any Omega, force summation with the masses and the liquid: the aft-edge row carries the
    applied load (N = -Delta F; k = 1: S = P, M = 0) and the nose, with nothing ahead, none
    (Newton for the whole vehicle; the rigid modes are in the basis), 1e-9 of the load (k = 1
    shear and moment 1e-7 of P and P L: the steady load's tilt P0 beta, F0 / (m Omega^2 L) ~
    1e-8, is part of them)."""
    v = tank_vehicle(fill)
    dF = 0.5 * 1.0  # F0 small: the steady load's tilt (k = 1 shear, P0 beta) negligible
    res = forced_response(v, F0=1.0, amplitude=0.5, Omega=np.array([20.0, 150.0, 400.0]),
                          misalignment=0.1, damping_ratio=0.02)
    aft, nose = index(res, "aft-edge"), index(res, "forward-edge")
    P = dF * math.sin(0.1)
    np.testing.assert_allclose(res.axial_force[0, aft], -dF * math.cos(0.1), rtol=1e-9)
    np.testing.assert_allclose(res.shear_force[1, aft], P, rtol=1e-7)
    assert np.max(np.abs(res.bending_moment[1, aft])) <= 1e-7 * P * 10.0  # P L
    for q in ("axial_force", "shear_force", "bending_moment"):
        assert np.max(np.abs(getattr(res, q)[:, nose])) <= 1e-9 * dF * 10.0, q
