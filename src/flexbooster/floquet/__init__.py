"""Numerics of linear periodic systems M q'' + C q' + (A + B cos Omega t) q = 0.

Floquet multipliers and growth rates (:mod:`.multipliers`), Hill's method and the harmonic
balance of the periodic boundaries (:mod:`.hill`), a rigorous all-Omega stability certificate
for damped systems (:mod:`.bounds`), and the instability regions in Omega with
their amplitude dependence (:mod:`.regions`), Mathieu's equation (:mod:`.mathieu`) and the
vectorised scalar solvers they share (:mod:`.optimize`).  Numerical core: numpy and scipy
only.  Theory: ``docs/theory/floquet.md``.
"""

from .bounds import StabilityCertificate, stability_certificate
from .critical_damping import CLOSED_GROWTH, critical_damping
from .hill import (
    REAL_ROOT_RTOL,
    HillModes,
    converged_periodic_boundaries,
    hill_exponents,
    hill_modes,
    periodic_boundaries,
)
from .mathieu import (
    MATHIEU_SCALE_MAX,
    ZETA_SEARCH_MAX,
    beta_from_discriminants,
    characteristic_exponent,
    characteristic_value,
    damped_tongue,
    floquet_discriminant,
    hill_order,
    tongue_critical_damping,
    tongue_critical_gamma,
    tongue_edges,
    transition_curves,
)
from .multipliers import (
    MAX_STEPS,
    LinearPeriodicSystem,
    PeriodMapOverflowError,
    StepLimitError,
    floquet_exponents,
    floquet_multipliers,
    growth_rate,
    monodromy,
    periodic_system,
    steady_frequencies,
    step_counts,
)
from .optimize import (
    NoConvergenceError,
    brent_max,
    expand_bracket,
    golden_section_max,
    illinois_root,
)
from .regions import (
    DAMPING_MARGIN,
    RESONANCE_KINDS,
    CriticalAmplitude,
    InstabilityRegion,
    RegionBoundary,
    SearchWork,
    TooManyCandidatesError,
    critical_amplitude,
    instability_regions,
    region_boundaries,
    resonance_kinds,
    search_work,
)

__all__ = ["MATHIEU_SCALE_MAX", "beta_from_discriminants", "characteristic_exponent", "hill_order",
           "characteristic_value", "damped_tongue", "floquet_discriminant",
           "tongue_critical_gamma", "tongue_critical_damping",
           "ZETA_SEARCH_MAX", "tongue_edges", "transition_curves", "DAMPING_MARGIN",
           "CriticalAmplitude", "InstabilityRegion", "RegionBoundary", "TooManyCandidatesError",
           "converged_periodic_boundaries", "critical_amplitude", "NoConvergenceError",
           "brent_max", "expand_bracket", "golden_section_max", "illinois_root",
           "instability_regions", "region_boundaries", "resonance_kinds", "RESONANCE_KINDS",
           "SearchWork", "search_work",
           "LinearPeriodicSystem", "StepLimitError", "MAX_STEPS", "PeriodMapOverflowError",
           "floquet_exponents", "floquet_multipliers", "growth_rate", "hill_exponents",
           "HillModes", "hill_modes", "monodromy", "periodic_boundaries", "REAL_ROOT_RTOL",
           "periodic_system",
           "steady_frequencies", "step_counts", "StabilityCertificate", "stability_certificate",
           "CLOSED_GROWTH", "critical_damping"]
