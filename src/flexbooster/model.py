"""From a validated case to the derived model: the one place where the input layer meets the core.

References
----------
.. [1] Tech Memo 104, sections 2.2, 3.0, 4.2 (see :mod:`flexbooster.memo.model`).
.. [2] Tech Memo 104, sec. 5.3 and Fig. 1 (the memo vehicle of :func:`vehicle_from_case`).
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
    """The derived model of a validated case, built once.

    Parameters
    ----------
    case : Case
        From :func:`flexbooster.load_case` or :func:`flexbooster.default_case` (SI).

    Returns
    -------
    BoosterModel
        Mass properties, omega_1, omega_psi, shell parameters, T0_bar, thrust, truncation and
        the Omega grid (rad/s).

    Raises
    ------
    CaseError
        Field ``booster`` when a derived quantity overflows double precision (e.g. a radius
        of 1e300 m), with the message naming it.
    """
    b, t, n = case.booster, case.thrust, case.truncation
    try:
        with np.errstate(over="raise", invalid="raise"):
            return booster_model(
                R1=b.cylinder1.radius, L1=b.cylinder1.half_length, R2=b.cylinder2.radius,
                L2=b.cylinder2.half_length, h=b.thickness, E=b.E, nu=b.nu, rho=b.rho,
                F0=case.F0, gamma=t.gamma, K=t.K, Omega=case.omega_grid(),
                truncation=Truncation(M1=n.M1, N1=n.N1, M2=n.M2, N2=n.N2, N=n.N, S=n.S, R=n.R),
                beam_damping_ratio=case.damping.beam_modal_ratio,
                pitch_damping_ratio=case.damping.pitch_ratio,
            )
    except (ValueError, FloatingPointError, OverflowError, ZeroDivisionError) as exc:
        raise CaseError("booster", "(derived model)",
                        f"the case cannot be modelled in double precision: {exc}") from None


def vehicle_from_case(case: Case) -> Vehicle:
    """The vehicle of a case as one shell of revolution (``flexbooster.shell_of_revolution``).

    With ``[[vehicle.segments]]``: those segments, aft to forward, each with its own material
    or the ``[vehicle]`` table's or the ``[booster]``'s, the junction at each segment's aft
    edge (default ``"continuous"``) and the table's ends (default ``"free"``).  Otherwise the
    memo's vehicle (Tech Memo 104, Fig. 1): cylinder 1 (R1, length 2 L1) aft and cylinder 2
    (R2, 2 L2) forward, thickness h and the material of ``[booster]``, joined by the memo's
    rigid weightless disc (``"memo-bulkhead"``) with the memo's end bulkheads
    (``"shear-diaphragm"`` ends: v = w = 0, memo eqs. 5.3-2, 5.3-3); a ``[vehicle]`` table
    without segments may override the junction, the ends and the theory.

    Parameters
    ----------
    case : Case
        A validated case (SI).

    Returns
    -------
    Vehicle
        The validated vehicle (its ``warnings`` list the segments with h/R > 1/20).

    References
    ----------
    .. [1] Tech Memo 104, sec. 2.2, 5.3 (eqs. 5.3-1 to 5.3-3), Fig. 1.
    .. [2] D. Bushnell, Computers & Structures 4, 1974 (BOSOR segments and junctions).
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
