"""Smeared rings and stringers (Baruch-Singer) on the shell of revolution.

Evidence: the shear-diaphragm stiffened cylinder against the smeared-stiffener closed form of
the same theory: the Sanders 3x3 eigenproblem whose constitutive matrix carries E A / d,
E A e / d and E (I + A e^2) / d of each family and whose inertia is rho (h + A_r / d_r +
A_s / d_s) (tests/reference/donnell.py: sd_cylinder_stiffness with ``stiffening``; Baruch and
Singer, J. Mech. Eng. Sci. 5 (1963) 23-27; Leissa 1973 sec. 2.1).
"""

from __future__ import annotations

import numpy as np
import pytest

from flexbooster.shell_of_revolution import Cylinder, Stiffeners, Vehicle, vehicle_modes
from reference.donnell import sd_cylinder_stiffness

E, NU, RHO = 70e9, 0.33, 2700.0
R, L, H = 1.5, 4.0, 0.003
SD = {"aft_end": "shear-diaphragm", "fwd_end": "shear-diaphragm"}
RINGS = Stiffeners(spacing=0.4, area=3.0e-4, inertia=4.0e-8, eccentricity=0.03)
STRINGERS = Stiffeners(spacing=0.15, area=1.0e-4, inertia=2.0e-9, eccentricity=-0.012)


def _stiffening(rings, stringers) -> np.ndarray:
    """Baruch-Singer terms written out (independent of the product's stiffener_matrix)."""
    s = np.zeros((6, 6))
    for st, i in ((stringers, 0), (rings, 1)):
        if st is not None:
            d, a, j, e = st.spacing, st.area, st.inertia, st.eccentricity
            s[i, i] += E * a / d
            s[i, i + 3] += E * a * e / d
            s[i + 3, i] += E * a * e / d
            s[i + 3, i + 3] += E * (j + a * e * e) / d
    return s


def _closed_form(n: int, rings, stringers) -> float:
    mu = RHO * (H + sum(st.area / st.spacing for st in (rings, stringers) if st is not None))
    S = _stiffening(rings, stringers)
    w2 = min(np.linalg.eigvalsh(sd_cylinder_stiffness(L, R, H, E, NU, m, n, "sanders",
                                                      stiffening=S))[0] for m in range(1, 13))
    return float(np.sqrt(w2 / mu))


@pytest.mark.parametrize("rings,stringers", [(RINGS, None), (None, STRINGERS),
                                             (RINGS, STRINGERS)])
@pytest.mark.parametrize("n", [2, 5, 9])
def test_stiffened_cylinder_matches_smeared_closed_form(n, rings, stringers):
    """Lowest frequency of harmonic n of the stiffened shear-diaphragm cylinder equals the
    smeared-stiffener Sanders 3x3 eigenproblem (with the stiffener mass); 0.5 %."""
    veh = Vehicle([Cylinder(R, L, H, E=E, nu=NU, rho=RHO, rings=rings, stringers=stringers)],
                  **SD)
    fe = vehicle_modes(veh, k_min=n, k_max=n, n_modes=1).omega[0]
    assert fe == pytest.approx(_closed_form(n, rings, stringers), rel=5e-3)


def test_ring_eccentricity_sign_follows_the_closed_form():
    """Eccentricity positive outward: the same rings outside vs inside change the n = 2
    frequency, and the FE ratio w_out / w_in equals the closed form's (each within 0.5 %, the
    ratio within 0.1 %; the closed-form ratio differs from 1 by > 0.3 %)."""
    inside = Stiffeners(spacing=0.4, area=3.0e-4, inertia=4.0e-8, eccentricity=-0.03)
    fe, cf = [], []
    for rings in (RINGS, inside):
        veh = Vehicle([Cylinder(R, L, H, E=E, nu=NU, rho=RHO, rings=rings)], **SD)
        fe.append(vehicle_modes(veh, k_min=2, k_max=2, n_modes=1).omega[0])
        cf.append(_closed_form(2, rings, None))
        assert fe[-1] == pytest.approx(cf[-1], rel=5e-3)
    assert abs(cf[0] / cf[1] - 1.0) > 3e-3
    assert fe[0] / fe[1] == pytest.approx(cf[0] / cf[1], rel=1e-3)
