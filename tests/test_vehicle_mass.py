"""Mass properties of a vehicle (shell_of_revolution.mass_properties) against an independent
adaptive quadrature (scipy.integrate.quad) of every contribution's defining integrals."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad

from flexbooster.shell_of_revolution import (
    Cone,
    Cylinder,
    LumpedMass,
    Stiffeners,
    Vehicle,
    VehicleTank,
    mass_properties,
)

MAT = {"E": 7.0e10, "nu": 0.3, "rho": 2700.0}
RTOL = 1e-10


def _vehicle() -> Vehicle:
    rings = Stiffeners(spacing=0.5, area=4e-4, inertia=2e-8, eccentricity=0.02)
    stringers = Stiffeners(spacing=0.2, area=1e-4, inertia=1e-9, eccentricity=-0.01)
    segs = (Cylinder(1.5, 6.0, 0.004, **MAT, nonstructural_mass=3.0, rings=rings),
            Cylinder(1.5, 4.0, 0.003, **MAT, pressure=2e5, stringers=stringers),
            Cone(1.5, 1.0, 2.0, 0.002, **MAT, nonstructural_mass=1.0),
            Cone(1.0, 0.3, 0.0, 0.002, **MAT),  # flat annular plate
            Cone(0.3, 0.5, 1.0, 0.002, **MAT))
    masses = (LumpedMass(0.0, 2000.0, transverse_inertia=800.0, offset=-1.2, name="engine"),
              LumpedMass(13.0, 500.0, transverse_inertia=50.0, offset=0.4, name="payload"))
    tanks = (VehicleTank(0.0, 6.0, 0.7, 1140.0, name="lox"),
             VehicleTank(6.0, 12.0, 1.0, 800.0, name="rp1"))
    return Vehicle(segs, junctions=("continuous", "continuous", "continuous", "continuous"),
                   masses=masses, tanks=tanks)


def _segment_integrals(seg, x0: float, mu: float) -> tuple[float, float, float]:
    """int dm, int x dm, int (x^2 + r^2/2) dm over the wall, dm = mu 2 pi r ds (quad)."""
    lm = math.hypot(seg.length, seg.radius_fwd - seg.radius_aft)

    def r(s):
        return seg.radius_aft + s / lm * (seg.radius_fwd - seg.radius_aft)

    def x(s):
        return x0 + s / lm * seg.length

    out = []
    for f in (lambda s: 1.0, x, lambda s: x(s) ** 2 + 0.5 * r(s) ** 2):
        out.append(quad(lambda s, f=f: f(s) * mu * 2.0 * math.pi * r(s), 0.0, lm,
                        epsabs=0.0, epsrel=1e-13)[0])
    return tuple(out)


def _liquid_integrals(tank, xs, rs) -> np.ndarray:
    """int dm, int x dm, int (x^2 + r^2/4) dm of the liquid, dm = rho pi r^2 dx (quad)."""
    top = tank.aft + tank.fill * (tank.fwd - tank.aft)

    def rad(x):
        return float(np.interp(x, xs, rs))  # the tank walls here are cylinders and cones

    return np.array([quad(lambda x, f=f: f(x) * tank.density * math.pi * rad(x) ** 2, tank.aft,
                          top, points=list(xs[(xs > tank.aft) & (xs < top)]), epsabs=0.0,
                          epsrel=1e-13)[0]
                     for f in (lambda x: 1.0, lambda x: x, lambda x: x**2 + 0.25 * rad(x) ** 2)])


def _expected(vehicle: Vehicle) -> dict:
    """Independent moments (m, S_x, S_xx) per kind from quad, then x_c and I_cm."""
    kinds: dict[str, np.ndarray] = {}
    x0 = 0.0
    for seg in vehicle.segments:
        stiff = sum(seg.rho * st.area / st.spacing for st in (seg.rings, seg.stringers)
                    if st is not None)
        for kind, mu in (("shell", seg.rho * seg.thickness),
                         ("nonstructural", seg.nonstructural_mass), ("stiffeners", stiff)):
            if mu:
                kinds[kind] = kinds.get(kind, 0.0) + np.array(_segment_integrals(seg, x0, mu))
        x0 += seg.length
    for lm in vehicle.masses:
        xc = lm.station + lm.offset
        kinds[lm.name] = np.array([lm.mass, lm.mass * xc, lm.mass * xc**2
                                   + lm.transverse_inertia])
    xs = vehicle.boundaries()
    rs = [s.radius_aft for s in vehicle.segments] + [vehicle.segments[-1].radius_fwd]
    for tank in vehicle.tanks:
        kinds[tank.name] = _liquid_integrals(tank, xs, rs)
    return kinds


def _cm_inertia(mom: np.ndarray) -> tuple[float, float, float]:
    m, sx, sxx = mom
    return m, sx / m, sxx - sx**2 / m


def test_mass_properties_match_an_independent_quadrature():
    """Every contribution and the total: mass, centre of mass and pitch inertia about the centre
    of mass equal scipy.integrate.quad of dm = mu 2 pi r ds (walls, j = r^2/2: thin ring about a
    diameter), dm = rho pi r^2 dx (liquid, j = r^2/4: disc about a diameter) and the lumped
    masses' parallel-axis terms. Source: the defining integrals; tolerance 1e-10 relative."""
    vehicle = _vehicle()
    props = mass_properties(vehicle)
    expected = _expected(vehicle)
    assert [c.name for c in props.contributions] == list(expected)
    for c in props.contributions:
        m, xc, i_cm = _cm_inertia(expected[c.name])
        assert c.mass_kg == pytest.approx(m, rel=RTOL)
        assert c.cm_m == pytest.approx(xc, rel=RTOL)
        assert c.I_cm_kg_m2 == pytest.approx(i_cm, rel=RTOL)
    m, xc, i_cm = _cm_inertia(sum(expected.values()))
    assert props.mass_kg == pytest.approx(m, rel=RTOL)
    assert props.cm_m == pytest.approx(xc, rel=RTOL)
    assert props.I_cm_kg_m2 == pytest.approx(i_cm, rel=RTOL)


def test_thin_cylinder_closed_form():
    """A bare thin cylinder: m = 2 pi R L rho h, x_c = L/2, I_cm = m (R^2/2 + L^2/12)
    (thin cylindrical shell about a transverse diameter, Meriam & Kraige app. B); 1e-12."""
    R, L, h = 2.0, 9.0, 0.01
    props = mass_properties(Vehicle((Cylinder(R, L, h, **MAT),)))
    m = 2.0 * math.pi * R * L * MAT["rho"] * h
    assert props.mass_kg == pytest.approx(m, rel=1e-12)
    assert props.cm_m == pytest.approx(L / 2, rel=1e-12)
    assert props.I_cm_kg_m2 == pytest.approx(m * (R**2 / 2 + L**2 / 12), rel=1e-12)
    assert [c.kind for c in props.contributions] == ["shell"]


def test_to_dict_keys():
    """The JSON mapping carries the keys other modules read (mass_kg, cm_m, I_cm_kg_m2,
    contributions with name, kind, mass_kg, cm_m, I_cm_kg_m2)."""
    d = mass_properties(_vehicle()).to_dict()
    assert set(d) == {"mass_kg", "cm_m", "I_cm_kg_m2", "contributions"}
    assert set(d["contributions"][0]) == {"name", "kind", "mass_kg", "cm_m", "I_cm_kg_m2"}
    assert [c["kind"] for c in d["contributions"]] == [
        "shell", "nonstructural", "stiffeners", "lumped", "lumped", "tank", "tank"]


@pytest.mark.parametrize("field,kwargs", [
    ("tanks[0].aft", {"tanks": (VehicleTank(1.0, 6.0, 0.5, 1000.0),)}),
    ("masses[0].station", {"masses": (LumpedMass(99.0, 1.0),)}),
])
def test_vehicle_refuses_bad_stations(field, kwargs):
    """A tank end off a segment boundary, a mass off the vehicle: ValueError naming the field."""
    with pytest.raises(ValueError, match=field.replace("[", r"\[").replace("]", r"\]")):
        Vehicle((Cylinder(1.5, 6.0, 0.004, **MAT), Cylinder(1.5, 4.0, 0.004, **MAT)), **kwargs)
