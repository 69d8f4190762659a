"""Dynamic stability of the whole vehicle (shell of revolution) under the pulsating thrust: per
harmonic k >= 1 the periodic modal system and its parametric regions (:mod:`.harmonic`,
:mod:`.regions`, k = 1 :mod:`.bending`), k = 0 the forced axial modes (:mod:`.axial`), and
the forced response (:mod:`.forced`). Theory: docs/theory/vehicle-regions.md.
"""

from .axial import AxialResonance, ForcedAxial, forced_axial
from .bending import (
    BendingSystem,
    bending_harmonic,
    bending_regions,
    bending_system,
    follower_flutter_thrust,
)
from .forced import (
    MIN_PARTICIPATION,
    PEAK_WINDOW,
    STANDARD_GRAVITY,
    ForcedPeak,
    ForcedResponse,
    LoadEnvelope,
    ModePeak,
    ThrustSpectrum,
    UndampedResonanceError,
    basis_sizes,
    forced_response,
    mode_peaks,
    peak_half_width,
    window_peaks,
)
from .forced_model import IllConditionedError
from .harmonic import HarmonicSystem
from .regions import (
    SLOSH_VALIDITY_FACTOR,
    RegionCurve,
    VehicleRegions,
    below_slosh,
    harmonic_system,
    region_critical_damping,
    region_curves,
    vehicle_regions,
    window_regions,
)

__all__ = [
    "IllConditionedError",
    "STANDARD_GRAVITY",
    "AxialResonance",
    "BendingSystem",
    "ForcedAxial",
    "HarmonicSystem",
    "RegionCurve",
    "VehicleRegions",
    "bending_harmonic",
    "bending_regions",
    "bending_system",
    "follower_flutter_thrust",
    "ForcedPeak",
    "ForcedResponse",
    "LoadEnvelope",
    "ThrustSpectrum",
    "UndampedResonanceError",
    "forced_response",
    "basis_sizes",
    "window_peaks",
    "ModePeak",
    "mode_peaks",
    "peak_half_width",
    "PEAK_WINDOW",
    "MIN_PARTICIPATION",
    "forced_axial",
    "harmonic_system",
    "region_critical_damping",
    "window_regions",
    "region_curves",
    "vehicle_regions",
    "below_slosh",
    "SLOSH_VALIDITY_FACTOR",
]
