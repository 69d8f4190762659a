"""Dynamic stability of the whole vehicle (shell of revolution) under the pulsating thrust.

Per circumferential harmonic k >= 1 the periodic modal system q'' + C q' + (A + B cos Omega t)
q = 0 of the pre-stressed shell under T(t) = F0 (1 - gamma cos Omega t) and its parametric
instability regions in Omega (:mod:`.harmonic`, :mod:`.regions`; k = 1 with the rigid modes
and the follower thrust, :mod:`.bending`); for k = 0 the axial modes forced directly by the
pulsation (:mod:`.axial`).  Numerical core.  Theory: ``docs/theory/vehicle-regions.md``.
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
from .harmonic import HarmonicSystem
from .regions import (
    RegionCurve,
    VehicleRegions,
    harmonic_system,
    region_curves,
    vehicle_regions,
)

__all__ = [
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
    "forced_response",
    "forced_axial",
    "harmonic_system",
    "region_curves",
    "vehicle_regions",
]
