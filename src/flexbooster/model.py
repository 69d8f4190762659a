"""From a validated case to the derived model: the one place where the input layer meets the
core (Tech Memo 104, sec. 2.2, 3.0, 4.2, 5.3, Fig. 1).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from .checks import FieldValueError
from .errors import CaseError
from .flight.timeline import FlightPoint, Timeline, frozen_times
from .memo.model import BoosterModel, Truncation, booster_model
from .shell_of_revolution.assembly import MAX_ELEMENTS, auto_element_counts
from .shell_of_revolution.geometry import (
    Cone,
    Cylinder,
    LumpedMass,
    Stiffeners,
    Vehicle,
    VehicleTank,
)
from .shell_of_revolution.shared import shared_value

if TYPE_CHECKING:
    from .case import Case

__all__ = ["MEMO_NOT_APPLICABLE", "forced_stations", "frozen_case", "check_memo_applies",
           "model_from_case", "vehicle_from_case", "timeline_from_case", "flight_times"]

#: Why the memo's method (beam, Galerkin shells, beam action, the 13-family table, its charts)
#: does not apply to a case whose vehicle is ``[[vehicle.segments]]``.
MEMO_NOT_APPLICABLE = ("the memo's method (Tech Memo 104: free-free beam, Galerkin shells, beam "
                       "action, the 13-family table) models the two bare cylinders of [booster] "
                       "only")


def check_memo_applies(case: Case) -> None:
    """CaseError on ``booster`` (with :data:`MEMO_NOT_APPLICABLE`) for a case whose vehicle is
    ``[[vehicle.segments]]``: the memo's method needs ``[booster]``.

    Parameters
    ----------
    case : Case
        A validated case.
    """
    if case.booster is None:
        raise CaseError("booster", None, f"{MEMO_NOT_APPLICABLE} (this case's vehicle is "
                        "[[vehicle.segments]])")


def model_from_case(case: Case) -> BoosterModel:
    """The derived model of a validated case, built once (mass properties, omega_1, omega_psi,
    shell parameters, T0_bar, thrust, truncation, Omega grid); CaseError on ``booster`` when a
    derived quantity overflows.

    Parameters
    ----------
    case : Case
        From :func:`flexbooster.load_case` or :func:`flexbooster.default_case` (SI).
    """
    check_memo_applies(case)
    b, t, n = case.booster, case.thrust, case.truncation
    try:
        with np.errstate(over="raise", invalid="raise"):
            return booster_model(
                R1=b.cylinder1.radius, L1=b.cylinder1.half_length, R2=b.cylinder2.radius,
                L2=b.cylinder2.half_length, h=b.thickness, E=b.E, nu=b.nu, rho=b.rho,
                F0=case.F0, gamma=t.gamma, K=t.K, Omega=case.omega_grid(),
                truncation=Truncation(M1=n.M1, N1=n.N1, M2=n.M2, N2=n.N2, N=n.N, S=n.S, R=n.R),
                beam_damping_ratio=case.damping.beam_ratio,
                pitch_damping_ratio=case.damping.pitch_ratio,
            )
    except (ValueError, FloatingPointError, OverflowError, ZeroDivisionError) as exc:
        raise CaseError("booster", "(derived model)",
                        f"the case cannot be modelled in double precision: {exc}") from None


def vehicle_from_case(case: Case) -> Vehicle:
    """The vehicle of a case as one shell of revolution: its ``[[vehicle.segments]]`` (material
    from the segment, ``[vehicle]`` or ``[booster]``), or the memo vehicle (Fig. 1): the two
    cylinders of ``[booster]`` joined by a "memo-bulkhead" with "shear-diaphragm" ends (5.3-2,
    5.3-3), junction, ends and theory overridable by ``[vehicle]``. CaseError on a segment's
    length when its automatic mesh needs more than ``MAX_ELEMENTS`` elements (a segment over
    about 1200 radii long).

    Within :func:`flexbooster.shell_of_revolution.shared_harmonics`, built once per case (the
    same object for the estimate and every stage, so that they share its mesh and harmonics).

    Parameters
    ----------
    case : Case
        A validated case (SI).
    """
    return shared_value(("vehicle", id(case)), (case,), lambda: _vehicle(case))


def _vehicle(case: Case) -> Vehicle:
    """:func:`vehicle_from_case`, built."""
    from .vehicle_case import MEMO_END, MEMO_JUNCTION

    table, b = case.vehicle, case.booster
    if table is None or table.segments is None:
        mat = dict(E=b.E, nu=b.nu, rho=b.rho)
        c1, c2 = b.cylinder1, b.cylinder2
        segments = [Cylinder(c1.radius, 2.0 * c1.half_length, b.thickness, **mat),  # Fig. 1
                    Cylinder(c2.radius, 2.0 * c2.half_length, b.thickness, **mat)]
        return _meshable(Vehicle(segments,
                                 junctions=((table.junction if table else None)
                                            or MEMO_JUNCTION,),
                                 aft_end=(table.aft_end if table else None) or MEMO_END,
                                 fwd_end=(table.fwd_end if table else None) or MEMO_END,
                                 theory=table.theory if table else "sanders"),
                         [(f"booster.cylinder{i}.half_length", c.half_length)
                          for i, c in ((1, c1), (2, c2))])
    segments = []
    for seg in table.segments:
        mat = {name: next(v for v in (getattr(seg, name), getattr(table, name),
                                      getattr(b, name, None)) if v is not None)
               for name in ("E", "nu", "rho")}
        wall = {"nonstructural_mass": seg.nonstructural_mass, "pressure": seg.pressure,
                **{name: None if st is None else Stiffeners(
                    spacing=st.spacing, area=st.area, inertia=st.inertia,
                    eccentricity=st.eccentricity)
                   for name, st in (("rings", seg.rings), ("stringers", seg.stringers))}}
        if seg.kind == "cylinder":
            segments.append(Cylinder(seg.radius, seg.length, seg.thickness, **mat, **wall))
        else:
            segments.append(Cone(seg.radius_aft, seg.radius_fwd, seg.length, seg.thickness,
                                 **mat, **wall))
    junctions = tuple(seg.junction or "continuous" for seg in table.segments[1:])
    masses = tuple(LumpedMass(m.station, m.mass, transverse_inertia=m.transverse_inertia,
                              offset=m.offset, name=m.name or f"mass {i}")
                   for i, m in enumerate(table.masses))
    tanks = tuple(VehicleTank(t.aft, t.fwd, t.fill, t.density, name=t.name or f"tank {i}")
                  for i, t in enumerate(table.tanks))
    try:
        vehicle = Vehicle(segments, junctions=junctions, aft_end=table.aft_end or "free",
                          fwd_end=table.fwd_end or "free", theory=table.theory, masses=masses,
                          tanks=tanks)
    except FieldValueError as exc:  # a station that does not fit the segments
        raise CaseError(f"vehicle.{exc.field}", exc.value, exc.rule) from None
    return _meshable(vehicle, [(f"vehicle.segments[{i}].length", seg.length)
                               for i, seg in enumerate(table.segments)])


def _meshable(vehicle: Vehicle, lengths: list[tuple[str, float]]) -> Vehicle:
    """``vehicle``, or CaseError on the first segment (its length field and value) whose
    automatic mesh needs more than ``MAX_ELEMENTS`` elements."""
    for (field, value), n, seg in zip(lengths, auto_element_counts(vehicle), vehicle.segments,
                                      strict=True):
        if n > MAX_ELEMENTS:
            radius = max(seg.radius_aft, seg.radius_fwd)
            raise CaseError(field, value, f"a segment {seg.length / radius:.4g} radii long needs "
                            f"{n} shell elements, more than {MAX_ELEMENTS}: shorten it or "
                            "split it into [[vehicle.segments]]")
    return vehicle


def timeline_from_case(case: Case) -> Timeline | None:
    """The flight schedule of a case's ``[flight]`` table (None without one): its points, linear
    in time between them (docs/theory/flight.md).

    Parameters
    ----------
    case : Case
        A validated case (SI).
    """
    table = case.flight
    if table is None:
        return None
    return Timeline(tuple(FlightPoint(time=p.time, F0=p.F0, fill=p.fill,
                                      oscillation=p.oscillation, gamma=p.gamma)
                          for p in table.points))


def flight_times(case: Case) -> np.ndarray:
    """The frozen times (s) of a case's flight: ``flight.times`` or ``flight.stations``
    equally spaced ones, with the points' own times (:func:`flexbooster.flight.frozen_times`);
    empty without ``[flight]``.

    Parameters
    ----------
    case : Case
        A validated case (SI).
    """
    from .flight_case import FLIGHT_STATIONS

    timeline = timeline_from_case(case)
    if timeline is None:
        return np.zeros(0)
    table = case.flight
    if table.times is not None:
        return frozen_times(timeline, times=table.times, include_points=True)
    return frozen_times(timeline, n=table.stations or FLIGHT_STATIONS, include_points=True)


def frozen_case(case: Case, time: float) -> Case:
    """The case of the flight at its frozen time ``time`` (s), as the flight stage analyses it:
    that time's tank fills, F0 and gamma, Omega over the flight's range
    (:func:`flexbooster.flight.flight_omega_range`), no ``[flight]``. ValueError without
    ``[flight]`` or for a time outside the flight.

    Parameters
    ----------
    case : Case
        A validated case (SI) with ``[flight]``.
    time : float
        Time (s) within the flight.
    """
    from .flight import flight_omega_range

    timeline = timeline_from_case(case)
    if timeline is None:
        raise ValueError("case: has no [flight], so no frozen time")
    p = timeline.at(time)
    lo, hi = flight_omega_range(timeline)
    thrust = case.thrust.model_copy(update=dict(F0=p.F0, T0=None, gamma=p.gamma, omega_min=lo,
                                                omega_max=hi, spectrum=None))
    vehicle = case.vehicle
    if vehicle is not None and vehicle.tanks:
        vehicle = vehicle.model_copy(update=dict(tanks=tuple(
            tank.model_copy(update=dict(fill=f))
            for tank, f in zip(vehicle.tanks, p.fill, strict=True))))
    return case.model_copy(update=dict(thrust=thrust, vehicle=vehicle, flight=None))


def forced_stations(case: Case, vehicle=None) -> tuple[tuple[tuple[str, float], ...], tuple]:
    """The caller's stations of the forced response: every lumped mass of the vehicle (its name,
    else "mass-i") then every ``[[output.stations]]``, as (name, station in m); and the names of
    the masses' stations. The edges and junctions are added by
    :func:`flexbooster.dynamics.forced_response`.

    Parameters
    ----------
    case : Case
        The validated case.
    vehicle : Vehicle, optional
        Its vehicle (:func:`flexbooster.model.vehicle_from_case`), when already built.
    """
    vehicle = vehicle_from_case(case) if vehicle is None else vehicle
    users = [(st.name, st.station) for st in case.output.stations]
    taken = {name for name, _ in users}
    masses = []
    for i, m in enumerate(vehicle.masses):
        name = m.name or f"mass-{i + 1}"
        if name in taken:
            name = f"{name} (mass {i + 1})"
        taken.add(name)
        masses.append((name, float(m.station)))
    return tuple(masses + users), tuple(name for name, _ in masses)
