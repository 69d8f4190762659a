"""Rigid lumped masses on the shell of revolution (Vehicle ``masses``, LumpedMass).

Evidence: a free-free slender tube with a lumped mass at each end.
* k = 0 against the exact rod with end masses: (mu_1 mu_2 z^2 - 1) sin z = (mu_1 + mu_2) z
  cos z, z = omega L / c, mu_i = M_i / (rho A L) (separation of variables; Poisson's ratio 0,
  so that the shell's axial motion is exactly the rod's), brentq; 1 %.
* k = 1 against an independent Timoshenko beam (tests/reference/timoshenko.py: linear w and
  theta, one-point shear integration, rotary inertia, Cowper's thin-tube shear coefficient)
  with the end masses, their offsets and transverse inertias; 1 %.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from flexbooster.shell_of_revolution import Cylinder, LumpedMass, Vehicle, vehicle_modes
from flexbooster.shell_of_revolution.assembly import (
    dof_map,
    harmonic_matrices,
    mesh_vehicle,
    rigid_body_fields,
)
from reference.timoshenko import tube_bending_frequencies

E, RHO = 70e9, 2700.0
R, L, H = 0.5, 20.0, 0.005


def _tube(nu: float, masses) -> Vehicle:
    return Vehicle([Cylinder(R, L, H, E=E, nu=nu, rho=RHO)], masses=masses)


def _rod_roots(mu1: float, mu2: float, count: int) -> np.ndarray:
    """First ``count`` positive roots z of the rod-with-end-masses frequency equation."""
    def f(z):
        return (mu1 * mu2 * z * z - 1.0) * math.sin(z) - (mu1 + mu2) * z * math.cos(z)

    grid = np.linspace(1e-6, 40.0, 40001)
    vals = np.array([f(z) for z in grid])
    idx = np.flatnonzero(np.sign(vals[:-1]) != np.sign(vals[1:]))
    return np.array([brentq(f, grid[i], grid[i + 1], xtol=1e-14) for i in idx[:count]])


def test_axial_k0_matches_rod_with_end_masses():
    """k = 0 elastic frequencies 1-3 of the tube (nu = 0) with 300 kg aft and 120 kg forward
    equal c z_i / L from the exact rod equation with end masses; 1 %."""
    masses = (LumpedMass(0.0, 300.0), LumpedMass(L, 120.0))
    area = 2.0 * math.pi * R * H
    mu1, mu2 = (m.mass / (RHO * area * L) for m in masses)
    z = _rod_roots(mu1, mu2, 3)
    expected = math.sqrt(E / RHO) * z / L
    modes = vehicle_modes(_tube(0.0, masses), k_min=0, k_max=0, n_modes=12)
    axial = modes.omega[modes.type == "axial"][:3]
    np.testing.assert_allclose(axial, expected, rtol=1e-2)


def test_bending_k1_matches_timoshenko_beam_with_end_masses():
    """k = 1 elastic frequencies 1-3 of the tube (nu = 0.3) with an engine-like aft mass
    (400 kg, centre 0.6 m aft, 90 kg m^2) and a payload-like forward mass (150 kg, 0.8 m
    forward, 40 kg m^2) equal the independent Timoshenko beam model; 1 %."""
    masses = (LumpedMass(0.0, 400.0, transverse_inertia=90.0, offset=-0.6),
              LumpedMass(L, 150.0, transverse_inertia=40.0, offset=0.8))
    expected = tube_bending_frequencies(radius=R, length=L, thickness=H, E=E, nu=0.3, rho=RHO,
                                        bodies=[(0, (400.0, -0.6, 90.0)),
                                                (800, (150.0, 0.8, 40.0))])
    modes = vehicle_modes(_tube(0.3, masses), k_min=1, k_max=1, n_modes=3)
    np.testing.assert_allclose(modes.omega[:3], expected, rtol=1e-2)


def test_masses_do_not_touch_k2():
    """No effect for k >= 2 (a rigid mass on the ring does not follow ovalisation): exact
    equality of the k = 2 frequencies with and without masses."""
    masses = (LumpedMass(0.0, 400.0, transverse_inertia=90.0), LumpedMass(L, 150.0))
    a = vehicle_modes(_tube(0.3, masses), k_min=2, k_max=2, n_modes=3).omega
    b = vehicle_modes(_tube(0.3, ()), k_min=2, k_max=2, n_modes=3).omega
    assert np.array_equal(a, b)


@pytest.mark.parametrize("station", [7.3, 10.0])
def test_rigid_k1_mass_centre(station):
    """A mid-span mass: the k = 1 rigid-body motions span lateral translation and pitch; the
    kinetic form of a unit lateral translation equals the total mass (shell + lumped), the
    Newton check of the ring-row kinematics (exact up to round-off, 1e-9)."""
    veh = _tube(0.3, (LumpedMass(station, 250.0, offset=0.3, transverse_inertia=5.0),))
    mesh = mesh_vehicle(veh)
    dmap = dof_map(veh, mesh, 1)
    hm = harmonic_matrices(veh, mesh, 1)
    full = rigid_body_fields(mesh, 1)[0]  # lateral translation, full DOFs
    red = np.zeros(dmap.n)
    keep = dmap.index >= 0
    red[dmap.index[keep]] = (full * dmap.coef)[keep]
    total = veh.mass() + 250.0
    assert red @ hm.mass @ red == pytest.approx(total, rel=1e-9)
