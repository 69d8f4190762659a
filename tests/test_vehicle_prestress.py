"""The vehicle's prestate under the thrust, its load path and the regions it sets.

Tiers:

* mechanics: the membrane prestate (meridional and hoop resultants, ring forces where the
  meridian turns) is in equilibrium with the thrust and the inertia loads, so a rigid
  rotation of a free vehicle under the follower thrust is neutral: the rigid pitch's
  frequency under the steady thrust is omega_psi^2 = F0 d K / I_cm (Tech Memo 104 eq. 4.2-1),
  d and I_cm from the shell's geometry by quadrature;
* independent model: a Sanders shell-of-revolution Legendre-Ritz model with the membrane
  prestate in closed form and Hill's method for the principal regions (``sanders_ritz.py``);
* exact: a one-mode system is a Mathieu equation (scipy.special.mathieu_a/b), its parameter
  from the finite-element frequency and its thrust derivative (Hellmann-Feynman);
* the load path from the ends, through the case: a clamped forward end reacts the thrust
  (uniform compression), a free one lets the vehicle accelerate (inertia relief).
"""

from __future__ import annotations

import tomllib

import numpy as np
import pytest
from scipy.optimize import brentq
from scipy.special import mathieu_a, mathieu_b

import sanders_ritz as ritz
from flexbooster.analysis import analyze_vehicle_regions
from flexbooster.case import load_case, memo_case_text
from flexbooster.dynamics import bending_system, harmonic_system, vehicle_regions
from flexbooster.shell_of_revolution import Cone, Cylinder, Vehicle, mesh_vehicle, vehicle_modes
from flexbooster.shell_of_revolution.assembly import thrust_prestate
from flexbooster.shell_of_revolution.elements import reference_element

ALU = {"E": 70e9, "nu": 0.3, "rho": 2700.0}  # README.md's [vehicle] example
STEEL = {"E": 210e9, "nu": 0.3, "rho": 7850.0}
F0 = 2.8e6  # N, the memo case's thrust (flexbooster init)


def readme_vehicle() -> Vehicle:
    """README.md's [vehicle] example: a 6 m cylinder (R 1.5 m) and a 1 m cone to R 1.0 m,
    16 mm aluminium walls, free ends."""
    return Vehicle([Cylinder(1.5, 6.0, 0.016, **ALU), Cone(1.5, 1.0, 1.0, 0.016, **ALU)])


def two_cone_vehicle() -> Vehicle:
    """Four segments, two cones (both narrowing forward at 18.4 degrees), aluminium walls
    thinning forward, free ends."""
    return Vehicle([Cylinder(1.5, 4.0, 0.012, **ALU), Cone(1.5, 1.1, 1.2, 0.010, **ALU),
                    Cylinder(1.1, 3.0, 0.008, **ALU), Cone(1.1, 0.6, 1.5, 0.006, **ALU)])


VEHICLES = {"readme": (readme_vehicle, F0), "two-cone": (two_cone_vehicle, 1.0e6)}


def mass_properties(vehicle: Vehicle) -> tuple[float, float]:
    """(d, I_cm): the distance (m) from the aft edge to the centre of mass and the pitch
    moment of inertia about it (kg m^2) of the shell, a ring of radius r contributing
    (x - x_cm)^2 + r^2 / 2 per unit mass; Gauss-Legendre on each generator (exact: the
    integrands are polynomials of degree 3 in s)."""
    xs, ws = np.polynomial.legendre.leggauss(4)
    x0, rows = 0.0, []
    for seg in vehicle.segments:
        r1 = getattr(seg, "radius_aft", getattr(seg, "radius", None))
        r2 = getattr(seg, "radius_fwd", getattr(seg, "radius", None))
        lm = np.hypot(seg.length, r2 - r1)
        s = 0.5 * (xs + 1) * lm
        r, x = r1 + s * (r2 - r1) / lm, x0 + s * seg.length / lm
        dm = 2 * np.pi * seg.rho * seg.thickness * r * 0.5 * lm * ws
        rows.append((dm, x, r))
        x0 += seg.length
    dm, x, r = (np.concatenate(c) for c in zip(*rows, strict=True))
    xcm = (dm * x).sum() / dm.sum()
    return float(xcm), float((dm * ((x - xcm) ** 2 + r**2 / 2)).sum())


# --------------------------------------------------------------------------- the rigid pitch


@pytest.mark.parametrize("which", sorted(VEHICLES))
def test_rigid_pitch_under_the_follower_thrust(which):
    """Free vehicle with cones, inertia relief: the rigid rotation (first basis mode of
    bending_system, mass-normalised: psi = 1 / sqrt(I_cm)) has A_psi,psi = F0 d K / I_cm to
    1e-6 relative at K = 0.5, and |A_psi,psi| <= 1e-6 F0 d / I_cm at K = 0 (d, I_cm:
    mass_properties; measured 1e-14); the rigid translation's column of A is 0 (< 1e-9
    max|A|); and the map of k = 1 at gamma = 0 and K = 0 has no region (damped and
    undamped): no 'steady' false instability."""
    make, thrust = VEHICLES[which]
    veh = make()
    d, inertia = mass_properties(veh)
    scale = thrust * d / inertia
    for gain in (0.0, 0.5):
        bs = bending_system(veh, F0=thrust, n_modes=8, gimbal_gain=gain)
        assert bs.n_rigid == 2
        np.testing.assert_allclose(bs.aft_rotation[0] ** 2, 1 / inertia, rtol=1e-9)
        assert abs(bs.stiffness[0, 0] - gain * scale) <= 1e-6 * scale
        assert np.max(np.abs(bs.stiffness[:, 1])) < 1e-9 * np.max(np.abs(bs.stiffness))
    for zeta in (0.0, 0.01):
        res = vehicle_regions(veh, F0=thrust, gamma=0.0, omega_min=0.1, omega_max=500.0,
                              k_min=1, k_max=1, n_modes=12, damping_ratio=zeta, axial=False)
        assert res.regions == () and res.load_path == "inertia relief"


@pytest.mark.parametrize("which", sorted(VEHICLES))
def test_prestate_is_in_equilibrium_with_the_rigid_rotation(which):
    """The geometric stiffness of a rigid rotation psi about the centre of mass is the work of
    the rotated loads: psi^T K_g psi = -F0 d psi^2 (the inertia loads, rotated, do no work on
    it; the thrust's couple F0 d), exactly when the hoop resultants and the ring forces close
    the equilibrium (rel. 1e-9)."""
    from flexbooster.shell_of_revolution import modal_system

    make, thrust = VEHICLES[which]
    veh = make()
    d, inertia = mass_properties(veh)
    ms = modal_system(veh, 1, 3, thrust, rigid=True, loaded=False)
    beta = -ms.aft_edge[:, 0] / veh.segments[0].radius_aft
    rot = beta[:2] / np.hypot(*beta[:2])  # the pure rotation in the rigid pair
    kg = rot @ ms.geometric[:2, :2] @ rot
    np.testing.assert_allclose(kg, -thrust * d / inertia, rtol=1e-9)


# --------------------------------------------------------------------------- the modal basis


README_K = (2, 3, 4, 5, 6)
GAMMA = 0.05


def _principal_regions(veh, k, n_modes):
    """The program's principal (j = 1, simple) regions of the loaded modes 0, 1, 2 of k,
    undamped, gamma = GAMMA: {i: (omega_lo, omega_hi)} and the loaded frequencies."""
    out = {}
    omega = harmonic_system(veh, k, F0=F0, n_modes=n_modes, damping_ratio=0.0).omega_loaded
    for i in range(3):
        w = omega[i]
        res = vehicle_regions(veh, F0=F0, gamma=GAMMA, omega_min=2 * w * 0.97,
                              omega_max=2 * w * 1.03, k_min=k, k_max=k, n_modes=n_modes,
                              damping_ratio=0.0, axial=False, max_order=1)
        (reg,) = [r for r in res.regions if r.kind == "simple" and r.modes[0].index == i]
        out[i] = (reg.Omega_lo, reg.Omega_hi)
    return out, omega


@pytest.mark.slow
def test_readme_region_widths_converge_and_match_an_independent_model():
    """README vehicle, F0 = 2.8 MN, gamma = 0.05, undamped, k = 2..6, the principal regions of
    the three lowest loaded modes (relative widths 1e-4..1.6e-2): (a) doubling the basis
    (10 -> 20 loaded modes) changes no width by more than 0.5 % (measured < 9e-6); (b) every
    edge is within 2e-4 relative, and every width within 0.5 %, of the independent
    Sanders-Ritz model (Legendre degree 30 per segment, 10 loaded modes) with Hill's method
    (6 harmonics) (measured: edges < 3.4e-5, the automatic mesh's frequency error; widths
    < 2e-4)."""
    veh = readme_vehicle()
    for k in README_K:
        coarse, _ = _principal_regions(veh, k, 10)
        fine, omega = _principal_regions(veh, k, 20)
        w_ref, b1 = ritz.loaded_modes(veh.segments, k, 10, F0, degree=30)
        np.testing.assert_allclose(w_ref[:3], omega[:3], rtol=1e-4)
        for i in range(3):
            width = fine[i][1] - fine[i][0]
            assert abs((coarse[i][1] - coarse[i][0]) / width - 1) < 5e-3, (k, i)
            lo, hi = ritz.principal_edges(w_ref, GAMMA * b1, i)
            assert abs(fine[i][0] / lo - 1) < 2e-4 and abs(fine[i][1] / hi - 1) < 2e-4, (k, i)
            assert abs(width / (hi - lo) - 1) < 5e-3, (k, i)


# --------------------------------------------------------------------------- the load path


L_C, R_C, H_C = 2.0, 1.0, 0.01


def _cylinder(fwd_end: str) -> Vehicle:
    """The Donnell steel cylinder of the SD-SD Mathieu test (L 2 m, R 1 m, h 10 mm), a shear
    diaphragm at the aft end."""
    return Vehicle([Cylinder(R_C, L_C, H_C, **STEEL)], theory="donnell",
                   aft_end="shear-diaphragm", fwd_end=fwd_end)


def _mathieu_edges(mu: float, j: int) -> tuple[float, float]:
    """Edges Omega / w of region j of f'' + w^2 (1 - 2 mu cos Omega t) f = 0: with
    x = Omega t / 2, a = 4 / theta^2, q = 4 mu / theta^2 (DLMF 28.2.1), between b_j(q) and
    a_j(q) (scipy.special)."""
    out = [brentq(lambda th, f=f: 4 / th**2 - f(j, 4 * mu / th**2), 0.7 * 2 / j, 1.3 * 2 / j,
                  xtol=1e-14) for f in (mathieu_b, mathieu_a)]
    return min(out), max(out)


@pytest.mark.parametrize("fwd_end, path", [("clamped", "forward support"),
                                           ("free", "inertia relief")])
def test_load_path_from_the_ends_and_its_mathieu_regions(fwd_end, path):
    """The SD cylinder with a clamped forward end carries the thrust as uniform compression
    (N_s = -F0 / (2 pi R) everywhere), free at the forward end by inertia relief (N_s =
    -F0 (1 - x / L) / (2 pi R)); both 1e-12.  Its one-mode (n_modes = 1) regions j = 1, 2 are
    the exact Mathieu regions of f'' + w_L^2 (1 - 2 mu cos Omega t) f = 0 with w_L the loaded
    FE frequency and mu = gamma F0 |d w_L^2 / dF| / (2 w_L^2), the derivative by central
    differences of vehicle_modes at F0 (1 +- 1e-4) (Hellmann-Feynman: the mode's own K_g);
    1e-6 on Omega / w_L (j = 1), 1e-5 (j = 2).  The results name the load path."""
    veh = _cylinder(fwd_end)
    thrust, k = 2.0e7, 4
    mesh = mesh_vehicle(veh, elements_per_segment=12)
    pre = thrust_prestate(veh, mesh, thrust)
    ref = reference_element(mesh.order)
    x = mesh.x1[:, None] + 0.5 * (1 + ref.xi)[None, :] * mesh.length[:, None]
    force = thrust * (1 - x / L_C) if path == "inertia relief" else thrust + 0 * x
    assert pre.load_path == path
    np.testing.assert_allclose(pre.meridional, -force / (2 * np.pi * R_C), atol=1e-12 * thrust)

    def w2(f):
        return vehicle_modes(veh, k_min=k, k_max=k, n_modes=1, prestress_F0=f,
                             elements_per_segment=12).omega[0] ** 2

    slope = (w2(thrust * (1 + 1e-4)) - w2(thrust * (1 - 1e-4))) / (2e-4 * thrust)
    w_l = np.sqrt(w2(thrust))
    gamma = 0.3
    mu = gamma * thrust * abs(slope) / (2 * w_l**2)
    res = vehicle_regions(veh, F0=thrust, gamma=gamma, omega_min=0.7 * w_l,
                          omega_max=2.6 * w_l, k_min=k, k_max=k, n_modes=1, damping_ratio=0.0,
                          elements_per_segment=12, max_order=2, axial=False)
    assert res.load_path == path and res.supported_forward_end == (path == "forward support")
    modes = vehicle_modes(veh, k_min=k, k_max=k, n_modes=1, prestress_F0=thrust)
    assert modes.load_path == path and modes.to_dict(shapes=False)["load_path"] == path
    assert sorted(r.order for r in res.regions) == [1, 2]
    for r in res.regions:
        lo, hi = _mathieu_edges(mu, r.order)
        tol = 1e-6 if r.order == 1 else 1e-5
        assert abs(r.Omega_lo / w_l - lo) < tol and abs(r.Omega_hi / w_l - hi) < tol


@pytest.mark.parametrize("fwd_end, path", [("clamped", "forward support"),
                                           ("hinged", "forward support"),
                                           ("shear-diaphragm", "inertia relief")])
def test_the_case_passes_the_ends_to_the_load_path(fwd_end, path):
    """Through the case (model.vehicle_from_case, the pipeline's analyze_vehicle_regions):
    an axially restrained forward end (clamped, hinged) reacts the thrust, a shear diaphragm
    (axially free) does not; results.json's vehicle_regions say which."""
    data = tomllib.loads(memo_case_text())
    b = data.pop("booster")  # one vehicle per case: the segment, [booster]'s material
    data["vehicle"] = {"E": b["E"], "nu": b["nu"], "rho": b["rho"],
                       "aft_end": "shear-diaphragm", "fwd_end": fwd_end, "k_max": 2,
                       "n_modes": 2, "segments": [{"kind": "cylinder", "radius": 1.0,
                                                   "length": 2.0, "thickness": 0.01}]}
    found = analyze_vehicle_regions(load_case(data), k_min=2, boundaries=False)
    assert found.load_path == path and found.to_dict()["load_path"] == path
