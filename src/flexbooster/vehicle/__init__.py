"""Dynamic stability of the whole vehicle (shell of revolution) under the pulsating thrust.

:func:`vehicle_regions` builds, per circumferential harmonic k >= 1, the periodic modal system
q'' + C q' + (A + B cos Omega t) q = 0 of the pre-stressed shell of revolution under
T(t) = F0 (1 - gamma cos Omega t) and returns its parametric instability regions in Omega
(:mod:`.regions`), and for k = 0 the axial modes forced directly by the pulsation
(:mod:`.axial`); for k = 1 the bending system with the rigid modes and the follower thrust
(:mod:`.bending`).  Numerical core: numpy, scipy and flexbooster core packages only.  Theory:
``docs/theory/vehicle-regions.md``.
"""

from .axial import AxialResonance, ForcedAxial, forced_axial
from .bending import (
    BendingSystem,
    bending_harmonic,
    bending_regions,
    bending_system,
    follower_flutter_thrust,
)
from .forced import ForcedPeak, ForcedResponse, LoadEnvelope, ThrustSpectrum, forced_response
from .regions import (
    HARMONIC_BUILD_SECONDS,
    HarmonicSystem,
    RegionCurve,
    RegionMode,
    VehicleRegion,
    VehicleRegions,
    harmonic_search_seconds,
    harmonic_system,
    region_curves,
    search_seconds,
    vehicle_regions,
)

__all__ = [
    "HARMONIC_BUILD_SECONDS",
    "AxialResonance",
    "BendingSystem",
    "bending_harmonic",
    "ForcedAxial",
    "HarmonicSystem",
    "RegionCurve",
    "RegionMode",
    "VehicleRegion",
    "VehicleRegions",
    "bending_regions",
    "bending_system",
    "follower_flutter_thrust",
    "forced_axial",
    "ForcedPeak", "ForcedResponse", "LoadEnvelope", "ThrustSpectrum", "forced_response",
    "harmonic_search_seconds",
    "harmonic_system",
    "region_curves",
    "search_seconds",
    "vehicle_regions",
]
