"""Modal time responses of the two shells (memo sections 5.4, 6.1, 6.2) and their verification.

Every cylinder's Galerkin modes obey M x'' + K x = F (6.1-2..6.1-4), the forcing built from
its definition (3.0-2, 3.0-3 with the beam part 5.2-1, 5.3-4) by quadrature, linearised in
K psi (6.2): a fixed combination of the time functions T, T'', psi'', psi'^2, T psi, q_n,
q_n'' (:data:`BASIS`). Responses three ways: :func:`integrate` (solve_ivp or Duhamel), the
memo's closed forms 6.2-3, 6.2-8/9, 6.2-20 with errata fixed, and :func:`harmonic_response`
(resonance-safe, used by :func:`simulate`). Modules: ``excitation``, ``modal``,
``integrate``, ``closed_form``, ``fields``, ``simulate``, ``secular``. Theory:
docs/theory/responses.md.

References: Tech Memo 104, sec. 3.0, 4.1, 4.2, 5.2-5.4, 6.1, 6.2; V. V. Bolotin, *The
Dynamic Stability of Elastic Systems*, 1964, ch. 1; L. Meirovitch, *Elements of Vibration
Analysis*, 1986, ch. 4.
"""

from __future__ import annotations

from .closed_form import (
    closed_form_0k,
    closed_form_j0,
    closed_form_jk,
    harmonic_response,
)
from .excitation import (
    BASIS,
    Excitation,
    ExcitationParameters,
    excitation_parameters,
    make_excitation,
)
from .fields import (
    displacement_fields,
    edge_conditions,
)
from .integrate import (
    integrate,
)
from .modal import (
    ModalGroup,
    forcing_harmonics,
    modal_basis,
    modal_groups,
)
from .result import SimulationResult
from .secular import (
    SecularGrowth,
    modal_forcing_spectrum,
    secular_growth,
    secular_rates,
)
from .simulate import simulate

__all__ = [
    "BASIS",
    "Excitation",
    "ExcitationParameters",
    "excitation_parameters",
    "make_excitation",
    "closed_form_0k",
    "closed_form_j0",
    "closed_form_jk",
    "harmonic_response",
    "displacement_fields",
    "edge_conditions",
    "integrate",
    "ModalGroup",
    "modal_groups",
    "modal_basis",
    "forcing_harmonics",
    "SecularGrowth",
    "secular_growth",
    "modal_forcing_spectrum",
    "secular_rates",
    "SimulationResult",
    "simulate",
]
