"""Tanks in the vehicle (Vehicle ``tanks``, VehicleTank): the liquid in the vehicle's modes, its
loads in the thrust prestate, and each tank's slosh mode.

Evidence:
* a full tank between rigid bulkheads in a shear-diaphragm cylinder, at vehicle level
  (vehicle_modes), against the cosine-series Galerkin of tests/test_liquid.py
  (bulkhead_series_reference: separation of variables of the potential); 0.5 %;
* the long-wave limit n = 1, lam R -> 0: the liquid moves with the tank, mass rho_L pi R^2 per
  unit length: the first bending frequency of a slender full tube against the independent
  Timoshenko beam (tests/reference/timoshenko.py) with that mass; 1 %;
* the slosh frequency of a closed cylindrical tank, Abramson SP-106:
  omega^2 = (a xi_1 / R) tanh(xi_1 h / R), xi_1 = 1.8412; 0.1 %;
* the hydrostatic head and the axial load in the prestate: p = rho_L a (x_s - x),
  N_theta = p R, and the axial force from Newton's law on the parts aft of a station; 1e-9.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.special import jnp_zeros

from flexbooster.shell_of_revolution import (
    Cylinder,
    LumpedMass,
    Vehicle,
    VehicleTank,
    mesh_vehicle,
    vehicle_modes,
)
from flexbooster.shell_of_revolution.assembly import thrust_prestate
from flexbooster.shell_of_revolution.elements import reference_element
from flexbooster.shell_of_revolution.wetted_wall import slosh_modes
from reference.timoshenko import tube_bending_frequencies
from test_liquid import (
    RHO,
    SD,
    STEEL,
    WATER,
    H,
    L,
    R,
    bulkhead_series_reference,
)

XI_1 = jnp_zeros(1, 1)[0]


@pytest.mark.parametrize("n", [2, 3])
def test_full_tank_between_bulkheads_vehicle_level(n):
    """SD-SD cylinder full of water (VehicleTank 0..L, fill 1): the lowest 4 wet frequencies
    of harmonic n from vehicle_modes equal the cosine-series Galerkin with the bulkheads at rest
    (for n >= 2 the ends do not move axially); 0.5 %."""
    veh = Vehicle([Cylinder(R, L, H, **STEEL)], **SD,
                  tanks=(VehicleTank(0.0, L, 1.0, WATER),))
    got = vehicle_modes(veh, k_min=n, k_max=n, n_modes=4).omega
    np.testing.assert_allclose(got, bulkhead_series_reference(n)[:4], rtol=5e-3)


@pytest.mark.slow
def test_slender_full_tube_bending_tends_to_liquid_moving_with_tank():
    """Free-free tube, R = 0.25 m, L = 20 m (lam R = 0.06 for the first mode), full of water:
    the first k = 1 frequency equals the Timoshenko beam with rho_L pi R^2 added per unit length
    (the n = 1, lam R -> 0 limit of the added mass); 1 %."""
    radius, length, h, e_mod, rho = 0.25, 20.0, 0.005, 70e9, 2700.0
    veh = Vehicle([Cylinder(radius, length, h, E=e_mod, nu=0.3, rho=rho)],
                  tanks=(VehicleTank(0.0, length, 1.0, WATER),))
    got = vehicle_modes(veh, k_min=1, k_max=1, n_modes=1).omega[0]
    ref = tube_bending_frequencies(radius=radius, length=length, thickness=h, E=e_mod, nu=0.3,
                                   rho=rho, extra_mass_per_length=WATER * math.pi * radius**2,
                                   count=1)[0]
    assert got == pytest.approx(ref, rel=1e-2)
    dry = vehicle_modes(Vehicle([Cylinder(radius, length, h, E=e_mod, nu=0.3, rho=rho)]),
                        k_min=1, k_max=1, n_modes=1).omega[0]
    assert got < 0.5 * dry  # the liquid (3.7 times the wall's mass) matters


@pytest.mark.parametrize("fill", [0.1, 0.5, 0.8])
def test_slosh_modes_of_a_closed_cylindrical_tank(fill):
    """Tank 1..5 m in a cylinder of radius 1 m, depth h = 4 fill, a = 29.4 m/s^2:
    omega^2 = (a xi_1 / R) tanh(xi_1 h / R) (Abramson SP-106 ch. 2); 0.1 %; the mode carries
    the tank's name."""
    a = 29.4
    veh = Vehicle([Cylinder(R, 1.0, H, **STEEL), Cylinder(R, 4.0, H, **STEEL)],
                  junctions=("rigid-bulkhead",),
                  tanks=(VehicleTank(1.0, 5.0, fill, 1140.0, name="lox"),))
    (mode,) = slosh_modes(veh, acceleration=a)
    h = 4.0 * fill
    expected = math.sqrt(a * XI_1 / R * math.tanh(XI_1 * h / R))
    assert mode.omega == pytest.approx(expected, rel=1e-3)
    assert mode.tank == "lox"
    assert mode.mass_kg == mode.mass


def test_full_and_empty_tanks_have_no_slosh_mode():
    """A full tank (no free surface) and an empty one give no slosh mode."""
    veh = Vehicle([Cylinder(R, 1.0, H, **STEEL), Cylinder(R, 4.0, H, **STEEL)],
                  junctions=("rigid-bulkhead",),
                  tanks=(VehicleTank(0.0, 1.0, 1.0, 800.0), VehicleTank(1.0, 5.0, 0.0, 800.0)))
    assert slosh_modes(veh, acceleration=9.81) == ()


def test_prestate_hydrostatic_head_and_axial_load():
    """Free cylinder (inertia relief), an engine of 2 t at the aft edge, a tank 0..6 m half
    full of LOX, a payload of 0.5 t at the nose; thrust F0: a = F0 / m_total; at every Gauss
    point of the wetted wall N_theta = rho_L a (x_s - x) R (and 0 above the surface), and the
    compressive force F(x) = F0 - a (m_engine + m_liquid + m_wall(0..x)) (Newton on the parts
    aft of x, the liquid carried by the aft end); rel. 1e-9."""
    length, radius, h = 10.0, 1.5, 0.004
    veh = Vehicle([Cylinder(radius, 6.0, h, **STEEL), Cylinder(radius, 4.0, h, **STEEL)],
                  junctions=("rigid-bulkhead",),
                  masses=(LumpedMass(0.0, 2000.0), LumpedMass(length, 500.0)),
                  tanks=(VehicleTank(0.0, 6.0, 0.5, 1140.0),))
    mesh = mesh_vehicle(veh)
    mu = RHO * h * 2.0 * math.pi * radius  # wall mass per unit length
    m_liquid = 1140.0 * math.pi * radius**2 * 3.0
    m_total = mu * length + 2000.0 + 500.0 + m_liquid
    F0 = 1.0e6
    a = F0 / m_total
    pre = thrust_prestate(veh, mesh, F0)
    xi = reference_element(mesh.order).xi
    x = mesh.x1[:, None] + 0.5 * (1.0 + xi)[None, :] * mesh.length[:, None]
    hoop = 1140.0 * a * np.clip(3.0 - x, 0.0, None) * radius
    np.testing.assert_allclose(pre.hoop, hoop, rtol=1e-9, atol=1e-9 * hoop.max())
    force = F0 - a * (2000.0 + m_liquid + mu * x)
    np.testing.assert_allclose(pre.force, force, rtol=1e-9)
    assert pre.force[-1, -1] == pytest.approx(a * (500.0 + mu * (length - x[-1, -1])), rel=1e-9)


def test_full_tank_k0_volume_constraint_with_rigid_motion():
    """k = 0 of a shear-diaphragm cylinder full of water (u free at the ends: the axial
    translation is rigid, the tank's end walls move with the edges): vehicle_modes, which seeks
    the modes among the volume-keeping motions M-orthogonal to the rigid ones, gives the
    nonzero eigenvalues of the constrained wet system of wet_system_matrices (the null space of
    the volume constraint, no deflation; the liquid-level tests check it against the series):
    the lowest 4 elastic frequencies, rel. 1e-8; one rigid mode, the axial translation (v = 0
    at the diaphragms: no rigid torsion)."""
    import scipy.linalg as sla

    from flexbooster.shell_of_revolution.geometry import tank_liquid
    from flexbooster.shell_of_revolution.wetted_wall import wet_system_matrices

    veh = Vehicle([Cylinder(R, L, H, **STEEL)], **SD,
                  tanks=(VehicleTank(0.0, L, 1.0, WATER),))
    modes = vehicle_modes(veh, k_min=0, k_max=0, n_modes=4)
    ws = wet_system_matrices(veh, 0, [tank_liquid(veh, veh.tanks[0])], mesh=mesh_vehicle(veh))
    w = np.sqrt(np.abs(sla.eigh(ws.stiffness, ws.mass, eigvals_only=True)))
    ref = np.sort(w[w > 1e-6 * w.max()])[:4]
    np.testing.assert_allclose(modes.omega, ref, rtol=1e-8)
    assert modes.rigid_modes[0] == 1


def test_shared_harmonics_gives_the_numbers_of_separate_calls():
    """Within shared_harmonics the thrust prestate (k-independent) is made once for every
    harmonic and a harmonic's labels once for vehicle_modes and labelled_modal_system: every
    frequency, shape and label equals that of separate calls outside the block exactly (the
    same operations on the same inputs). Free cylinder with masses and a half-full tank under
    inertia relief (the prestate holds the liquid's head), k = 0..3, 6 modes."""
    from flexbooster.shell_of_revolution import labelled_modal_system, shared_harmonics

    veh = Vehicle([Cylinder(1.5, 6.0, 0.004, **STEEL), Cylinder(1.5, 4.0, 0.004, **STEEL)],
                  junctions=("rigid-bulkhead",),
                  masses=(LumpedMass(0.0, 2000.0), LumpedMass(10.0, 500.0)),
                  tanks=(VehicleTank(0.0, 6.0, 0.5, 1140.0),))
    F0 = 1.0e6
    alone = vehicle_modes(veh, k_max=3, n_modes=6, prestress_F0=F0)
    labels_alone = [labelled_modal_system(veh, k, 6, F0)[1]() for k in range(4)]
    with shared_harmonics():
        shared = vehicle_modes(veh, k_max=3, n_modes=6, prestress_F0=F0)
        labels_shared = [labelled_modal_system(veh, k, 6, F0)[1]() for k in range(4)]
    for name in ("k", "omega", "order", "type", "segment", "kinetic_share", "shapes"):
        np.testing.assert_array_equal(getattr(shared, name), getattr(alone, name))
    for (o1, t1), (o2, t2) in zip(labels_shared, labels_alone, strict=True):
        np.testing.assert_array_equal(o1, o2)
        np.testing.assert_array_equal(t1, t2)


def test_fills_of_one_shell_share_its_mesh_and_matrices():
    """Within shared_shell two fills of one vehicle (its tanks replaced, as a flight's frozen
    times, each in a shared_harmonics block of its own) get one mesh object and one shell part
    per harmonic, and their modes equal those of separate calls outside any block exactly
    (the same operations on the same inputs); the two fills' modes differ (the liquid is made
    per fill). The vehicle of the test above, k = 0..3, 6 modes."""
    import dataclasses

    from flexbooster.shell_of_revolution import shared_harmonics, shared_shell
    from flexbooster.shell_of_revolution.assembly import shell_harmonic
    from flexbooster.shell_of_revolution.modes import _mesh

    base = Vehicle([Cylinder(1.5, 6.0, 0.004, **STEEL), Cylinder(1.5, 4.0, 0.004, **STEEL)],
                   junctions=("rigid-bulkhead",),
                   masses=(LumpedMass(0.0, 2000.0), LumpedMass(10.0, 500.0)),
                   tanks=(VehicleTank(0.0, 6.0, 0.5, 1140.0),))
    fills = [dataclasses.replace(base, tanks=(dataclasses.replace(base.tanks[0], fill=f),))
             for f in (0.9, 0.3)]
    F0 = 1.0e6
    alone = [vehicle_modes(v, k_max=3, n_modes=6, prestress_F0=F0) for v in fills]
    shared, meshes = [], []
    with shared_shell():
        for v in fills:
            with shared_harmonics(isolated=True):
                shared.append(vehicle_modes(v, k_max=3, n_modes=6, prestress_F0=F0))
                meshes.append(_mesh(v, None, 6))
        assert meshes[0] is meshes[1]
        assert all(shell_harmonic(fills[0], meshes[0], k) is shell_harmonic(fills[1], meshes[1], k)
                   for k in range(4))
    for a, b in zip(shared, alone, strict=True):
        for name in ("omega", "order", "type", "kinetic_share", "shapes"):
            np.testing.assert_array_equal(getattr(a, name), getattr(b, name))
    assert not np.allclose(alone[0].omega, alone[1].omega, rtol=1e-3)


@pytest.mark.slow
def test_regions_below_the_slosh_frequency_are_warned_about():
    """Independent value: Abramson's first lateral slosh frequency of a flat-bottomed cylinder
    (NASA SP-106, ch. 2), omega^2 = (a xi_1 / R) tanh(xi_1 h / R), xi_1 the first zero of J_1'
    and a = F0 / m. The two-stage liquid example, k = 1, Omega 0.3..0.9 Hz: its rigid-pitch
    region (the pitch at 0.30 Hz, with the liquid's high-frequency added mass) lies below twice
    the tanks' highest slosh frequency (the stage-1 oxidiser: R = 1.52 m, h = 0.96 x 8 m), so
    one ``liquid-below-slosh`` warning names that frequency (1 %) and the pitch mode; with the
    tanks full (no free surface, no slosh) there is none."""
    import copy
    import tomllib
    from pathlib import Path

    from flexbooster.analysis import analyze
    from flexbooster.case import load_case
    from flexbooster.dynamics import SLOSH_VALIDITY_FACTOR

    data = tomllib.loads((Path(__file__).parents[1] / "examples"
                          / "two-stage-liquid.toml").read_text())
    data["vehicle"]["k_max"] = 1
    data["thrust"].update(omega_min="0.3 Hz", omega_max="0.9 Hz", n_omega=20)
    res = analyze(load_case(data), figures=False)
    (w,) = [w for w in res.warnings if w.code == "liquid-below-slosh"]
    assert w.field == "vehicle.tanks" and "\n" not in w.message
    xi = float(jnp_zeros(1, 1)[0])
    a = res.case.F0 / res.vehicle_mass.mass_kg
    R, h = 1.52, 0.96 * 8.0
    hz = math.sqrt(a * xi / R * math.tanh(xi * h / R)) / (2.0 * math.pi)
    cited = float(w.message.split("first slosh frequency ")[1].split(" Hz")[0])
    assert cited == pytest.approx(hz, rel=1e-2) and "tank stage-1 oxidiser" in w.message
    pitch = [m for r in res.vehicle_regions.regions for m in r.modes
             if m.type == "rigid-pitch"]
    assert pitch and all(m.omega < SLOSH_VALIDITY_FACTOR * 2.0 * math.pi * hz for m in pitch)
    full = copy.deepcopy(data)
    for tank in full["vehicle"]["tanks"]:
        tank["fill"] = 1.0
    assert not [w for w in analyze(load_case(full), figures=False).warnings
                if w.code == "liquid-below-slosh"]
