"""From a validated case to the derived model: the one place where the input layer meets the
core (Tech Memo 104, sec. 2.2, 3.0, 4.2, 5.3, Fig. 1).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from .errors import CaseError
from .memo.model import BoosterModel, Truncation, booster_model
from .shell_of_revolution.geometry import Cone, Cylinder, Vehicle

if TYPE_CHECKING:
    from .case import Case

__all__ = ["model_from_case", "vehicle_from_case"]


def model_from_case(case: Case) -> BoosterModel:
    """The derived model of a validated case, built once (mass properties, omega_1, omega_psi,
    shell parameters, T0_bar, thrust, truncation, Omega grid); CaseError on ``booster`` when a
    derived quantity overflows.

    Parameters
    ----------
    case : Case
        From :func:`flexbooster.load_case` or :func:`flexbooster.default_case` (SI).
    """
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
    5.3-3), junction, ends and theory overridable by ``[vehicle]``.

    Parameters
    ----------
    case : Case
        A validated case (SI).
    """
    from .vehicle_case import MEMO_END, MEMO_JUNCTION

    table, b = case.vehicle, case.booster
    if table is None or table.segments is None:
        mat = dict(E=b.E, nu=b.nu, rho=b.rho)
        c1, c2 = b.cylinder1, b.cylinder2
        segments = [Cylinder(c1.radius, 2.0 * c1.half_length, b.thickness, **mat),  # Fig. 1
                    Cylinder(c2.radius, 2.0 * c2.half_length, b.thickness, **mat)]
        return Vehicle(segments,
                       junctions=((table.junction if table else None) or MEMO_JUNCTION,),
                       aft_end=(table.aft_end if table else None) or MEMO_END,
                       fwd_end=(table.fwd_end if table else None) or MEMO_END,
                       theory=table.theory if table else "sanders")
    segments = []
    for seg in table.segments:
        mat = {name: next(v for v in (getattr(seg, name), getattr(table, name),
                                      getattr(b, name)) if v is not None)
               for name in ("E", "nu", "rho")}
        if seg.kind == "cylinder":
            segments.append(Cylinder(seg.radius, seg.length, seg.thickness, **mat))
        else:
            segments.append(Cone(seg.radius_aft, seg.radius_fwd, seg.length, seg.thickness,
                                 **mat))
    junctions = tuple(seg.junction or "continuous" for seg in table.segments[1:])
    return Vehicle(segments, junctions=junctions, aft_end=table.aft_end or "free",
                   fwd_end=table.fwd_end or "free", theory=table.theory)
