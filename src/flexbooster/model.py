"""From a validated case to the derived model: the one place where the input layer meets the core.

References
----------
.. [1] Tech Memo 104, sections 2.2, 3.0, 4.2 (see :mod:`flexbooster.memo.model`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .memo.model import BoosterModel, Truncation, booster_model

if TYPE_CHECKING:
    from .case import Case

__all__ = ["model_from_case"]


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
    """
    b, t, n = case.booster, case.thrust, case.truncation
    return booster_model(
        R1=b.cylinder1.radius, L1=b.cylinder1.half_length, R2=b.cylinder2.radius,
        L2=b.cylinder2.half_length, h=b.thickness, E=b.E, nu=b.nu, rho=b.rho, F0=case.F0,
        gamma=t.gamma, K=t.K, Omega=case.omega_grid(),
        truncation=Truncation(M1=n.M1, N1=n.N1, M2=n.M2, N2=n.N2, N=n.N, S=n.S, R=n.R),
        beam_damping_ratio=case.damping.beam_modal_ratio,
        pitch_damping_ratio=case.damping.pitch_ratio,
    )
