"""Internal pressure of a segment (Cylinder/Cone ``pressure``): membrane pre-stress
N_theta = p R, N_x = p R / 2 in the stiffness of the modes.

Evidence: the shear-diaphragm cylinder's 3x3 eigenproblem of the same shell theory (Donnell)
with that pre-stress (tests/reference/donnell.py: sd_cylinder_stiffness; Leissa 1973 sec. 2.1;
Brush and Almroth 1975 sec. 5.3), and the monotone rise with p.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexbooster.shell_of_revolution import Cylinder, Vehicle, vehicle_modes
from reference.donnell import sd_cylinder_stiffness

E, NU, RHO = 210e9, 0.3, 7850.0
R, L, H = 1.0, 3.0, 0.004
SD = {"aft_end": "shear-diaphragm", "fwd_end": "shear-diaphragm", "theory": "donnell"}


def _closed_form(n: int, p: float) -> float:
    """Lowest omega (rad/s) over m = 1..12 of |K - omega^2 rho h I| = 0, N = (p R / 2, p R)."""
    w2 = [np.linalg.eigvalsh(sd_cylinder_stiffness(L, R, H, E, NU, m, n, "donnell",
                                                   prestress=(0.5 * p * R, p * R)))[0]
          for m in range(1, 13)]
    return float(np.sqrt(min(w2) / (RHO * H)))


def _fe(n: int, p: float) -> float:
    veh = Vehicle([Cylinder(R, L, H, E=E, nu=NU, rho=RHO, pressure=p)], **SD)
    return float(vehicle_modes(veh, k_min=n, k_max=n, n_modes=1).omega[0])


@pytest.mark.parametrize("n", [2, 4, 7])
def test_pressurised_cylinder_matches_3x3_eigenproblem(n):
    """Lowest frequency of harmonic n at p = 0.2 MPa equals the Donnell 3x3 eigenproblem with
    N_x = p R / 2, N_theta = p R (sd_cylinder_stiffness with the pre-stress); 0.5 %."""
    p = 2.0e5
    assert _fe(n, p) == pytest.approx(_closed_form(n, p), rel=5e-3)


def test_frequencies_rise_with_pressure():
    """omega of n = 5 rises strictly with p (tension stiffening), 0 -> 50 kPa -> 200 kPa; at
    p = 0 the closed form without pre-stress (0.5 %)."""
    w = [_fe(5, p) for p in (0.0, 5.0e4, 2.0e5)]
    assert w[0] == pytest.approx(_closed_form(5, 0.0), rel=5e-3)
    assert w[0] < w[1] < w[2]


def test_pressure_free_vehicle_is_unchanged():
    """pressure = 0 gives bit-identical frequencies to a segment without the field (the default
    path adds nothing): exact equality."""
    a = vehicle_modes(Vehicle([Cylinder(R, L, H, E=E, nu=NU, rho=RHO)], **SD), k_max=3,
                      n_modes=2)
    b = vehicle_modes(Vehicle([Cylinder(R, L, H, E=E, nu=NU, rho=RHO, pressure=0.0)], **SD),
                      k_max=3, n_modes=2)
    assert np.array_equal(a.omega, b.omega)


# ------------------------------------------------- the junction rings of a pressurised cone


def _cone_cylinder(p: float, **kw) -> Vehicle:
    """Cylinder R 1 m x 3 m, then a cone to 0.6 m over 1 m (tan(phi) = -0.4), both at p."""
    from flexbooster.shell_of_revolution import Cone

    mat = {"E": E, "nu": NU, "rho": RHO, "pressure": p}
    return Vehicle([Cylinder(R, L, H, **mat), Cone(R, 0.6, 1.0, H, **mat)], **kw)


def test_pressure_rings_closed_form_and_axial_equilibrium():
    """The cone's meridional resultant N_s = p r / (2 cos(phi)) has the radial component
    N_s sin(phi) at its edges, carried as the junction ring's hoop force H = p r^2 tan(phi) / 2
    (aft edge, r = 1 m: -0.2 p, compression) and -p r^2 tan(phi) / 2 at the forward edge
    (r = 0.6 m: +0.072 p) (membrane equilibrium of the ring; Fluegge 1973, sec. 2.2), 1e-12; the
    cylinder carries none. Axial equilibrium of the closed vessel: at every Gauss point of both
    segments 2 pi r N_s cos(phi) = p pi r^2 (the pressure on the closure ahead), 1e-12."""
    from flexbooster.shell_of_revolution import mesh_vehicle
    from flexbooster.shell_of_revolution.elements import reference_element
    from flexbooster.shell_of_revolution.prestress import pressure_resultants, pressure_rings

    p = 3.0e5
    mesh = mesh_vehicle(_cone_cylinder(p))
    rings = pressure_rings(mesh)
    np.testing.assert_allclose(rings.ring_radius, [1.0, 0.6], rtol=1e-12)
    np.testing.assert_allclose(rings.ring_force, [-0.2 * p, 0.072 * p], rtol=1e-12)
    ns, _ = pressure_resultants(mesh)
    xi = reference_element(mesh.order).xi
    r = mesh.r1[:, None] + (0.5 * (1 + xi))[None] * (mesh.length * mesh.sin_phi)[:, None]
    axial = 2 * np.pi * r * ns * mesh.cos_phi[:, None]
    np.testing.assert_allclose(axial, p * np.pi * r**2, rtol=1e-12)
    assert pressure_rings(mesh_vehicle(_cone_cylinder(0.0))) is None


@pytest.mark.parametrize("k", [0, 3])
def test_pressure_rings_are_in_the_stiffness_and_the_rayleigh_quotients(k):
    """The rings join K_e (system_matrices) and the modes' Rayleigh quotients alike: the modes of
    a pressurised cone-cylinder (clamped aft) equal the dense eigenvalues of its matrices, 1e-9;
    the rings matter: without them the first eigenvalue differs by more than 1 % at k = 3
    (the free nose's ring, in tension, stiffens its lobes) and by more than 1e-5 at k = 0
    (only the rings' torsion term acts)."""
    import scipy.linalg as sla

    from flexbooster.shell_of_revolution import mesh_vehicle, system_matrices
    from flexbooster.shell_of_revolution.assembly import dof_map, pressure_ring_matrix

    veh = _cone_cylinder(2.0e5, aft_end="clamped")
    mesh = mesh_vehicle(veh)
    modes = vehicle_modes(veh, k_min=k, k_max=k, n_modes=4)
    M, K, _ = system_matrices(veh, k, mesh=mesh)
    w2 = sla.eigh(K, M, eigvals_only=True, subset_by_index=(0, 3))
    np.testing.assert_allclose(modes.omega, np.sqrt(w2), rtol=1e-9)
    rings = pressure_ring_matrix(veh, mesh, dof_map(veh, mesh, k), k)
    bare = sla.eigh(K - rings, M, eigvals_only=True, subset_by_index=(0, 3))
    assert abs(w2[0] / bare[0] - 1.0) > (1e-2 if k == 3 else 1e-5)
