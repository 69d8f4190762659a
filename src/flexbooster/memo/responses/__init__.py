"""Modal time responses of the two shells (memo sections 5.4, 6.1, 6.2) and their verification.

The Galerkin equations of every cylinder d and mode (j, k) are linear with constant
coefficients (6.1-1..6.1-4),

    k = 0, j = 0 ... k >= 1:   U_0k'' + omega_0k^2 U_0k = P_0k                       (6.1-2)
    j >= 1, k = 0:             M x'' + K x = (P_1, P_2),      x = (U_j0, W_j0)       (6.1-3)
    j >= 1, k >= 1:            M x'' + K x = (Q_1, Q_2, Q_3), x = (U_jk, V_jk, W_jk)  (6.1-4)

with M, K from :func:`flexbooster.memo.shell_coefficients.galerkin_coefficients` (zero phase by
default, erratum E10).  The forcing is built from its definition, not from the memo's
evaluated forms: the shell equations (3.0-2) with the trial displacement shell part + beam part
(5.2-1, 5.3-4) give, per test function phi (the shape functions 5.3-2/3),

    forcing = -1 / ((1 - nu^2) mu theta_int) int int phi [F + (1 - nu^2) mu (u*, v*, w*)_tt
              - L(u*, v*, w*)] dxi dtheta,

F = (F1, F2, F3) of (3.0-3), L the operator of the left side of (3.0-2), u* of (5.3-4a) with
N_xixi = T(tau), v* = g* sin theta, w* = g* cos theta (5.3-4b, c) and g* of (4.1-3).  The xi
integrals are done by Gauss-Legendre quadrature, the theta integrals by orthogonality.  With
sin K psi ~ K psi, cos K psi ~ 1 (the memo's linearisation, 6.2) the forcing of a mode is a
fixed combination of the time functions

    T(tau) = 1 - gamma cos(Omega_bar tau),  T''(tau),  psi'',  psi'^2,  T psi,  q_n, q_n''

(:data:`BASIS`), with psi = sum_i A_i cos(Omega_i tau) (4.2-6..8) and the beam coordinates
q_n, q_B of (4.1-10/11).  The responses are computed three ways:

* :func:`integrate`: numerical integration, ``"DOP853"`` / ``"Radau"`` (scipy solve_ivp on the
  stacked modal systems, forcing evaluated in the time domain) or ``"duhamel"`` (exact
  propagation of each normal coordinate with the Duhamel integral done by 8-point
  Gauss-Legendre quadrature on every step: fast for long times);
* :func:`closed_form_0k`, :func:`closed_form_j0`, :func:`closed_form_jk`: the memo's closed
  forms 6.2-3, 6.2-8/9 (6.2-11/12) and 6.2-20 (6.2-28..30), errata fixed (see
  ``docs/memo-errata.md``), for a forcing written as a sum of harmonics;
* :func:`harmonic_response`: the same closed forms with the resonance-safe kernel (finite at
  exact resonance, where it grows like tau) used by :func:`simulate`.

Modules: ``excitation`` (psi, T, beam coordinates; the parameter function),
``modal`` (modal systems and their forcing), ``integrate`` (numerical integration),
``closed_form`` (the memo's closed forms), ``fields`` (displacements in metres),
``simulate`` (the pipeline entry) and ``secular`` (growth at a root).

References
----------
.. [1] Tech Memo 104, sections 3.0, 4.1, 4.2, 5.2-5.4, 6.1, 6.2 (eqs. 3.0-2, 3.0-3, 4.1-3..11,
   4.2-6..8, 5.2-1, 5.3-2..4, 5.4-1..9, 6.1-1..4, 6.2-1..30).
.. [2] V. V. Bolotin, *The Dynamic Stability of Elastic Systems*, Holden-Day, 1964, ch. 1
   (forced and combination resonances: secular growth).
.. [3] L. Meirovitch, *Elements of Vibration Analysis*, 2nd ed., McGraw-Hill, 1986, ch. 4
   (Duhamel integral, modal analysis of undamped systems).
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
