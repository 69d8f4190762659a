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
