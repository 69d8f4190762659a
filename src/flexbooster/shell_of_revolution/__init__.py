"""The whole vehicle as one thin shell of revolution (BOSOR-class Fourier-harmonic FE).

A :class:`Vehicle` of :class:`Cylinder` and :class:`Cone` segments; :func:`vehicle_modes`
(frequencies and labelled shapes, optionally prestressed), :func:`system_matrices` (M, K_e,
K_g of one harmonic), :func:`modal_system` / :func:`labelled_modal_system` (reduced to the
lowest loaded modes), :func:`buckling_load`. Theory: docs/theory/shell-of-revolution.md.

References: H. Kraus, *Thin Elastic Shells*, 1967; A. W. Leissa, NASA SP-288, 1973;
D. Bushnell, Computers & Structures 4 (1974) (BOSOR).
"""

from __future__ import annotations

from .assembly import DEFAULT_ORDER, Mesh, mesh_vehicle, system_matrices
from .geometry import (
    END_CONDITIONS,
    JUNCTIONS,
    THEORIES,
    Cone,
    Cylinder,
    LumpedMass,
    ShellWarning,
    Stiffeners,
    Vehicle,
    VehicleTank,
)
from .mass_properties import MassContribution, MassProperties, mass_properties
from .modes import (
    BAND_FACTOR,
    MODE_TYPES,
    BucklingError,
    BucklingLoad,
    ModalSystem,
    VehicleModes,
    buckling_load,
    eigenvalues_below,
    labelled_modal_system,
    modal_system,
    mode_vectors,
    rigid_motion_count,
    shared_harmonics,
    vehicle_modes,
)
from .shared import shared_shell
from .slosh import SloshMode
from .wetted_wall import slosh_modes

__all__ = [
    "BAND_FACTOR",
    "DEFAULT_ORDER",
    "END_CONDITIONS",
    "JUNCTIONS",
    "MODE_TYPES",
    "THEORIES",
    "BucklingError",
    "BucklingLoad",
    "Cone",
    "Cylinder",
    "LumpedMass",
    "MassContribution",
    "MassProperties",
    "Mesh",
    "ModalSystem",
    "ShellWarning",
    "SloshMode",
    "Stiffeners",
    "Vehicle",
    "VehicleTank",
    "VehicleModes",
    "buckling_load",
    "eigenvalues_below",
    "labelled_modal_system",
    "mass_properties",
    "mesh_vehicle",
    "modal_system",
    "mode_vectors",
    "rigid_motion_count",
    "shared_harmonics",
    "shared_shell",
    "slosh_modes",
    "system_matrices",
    "vehicle_modes",
]
