"""Geometry and mass properties of the two-cylinder composite (memo section 2.2, Fig. 1-2).

Cylinder 1 (R1, L1) is aft and carries the thrust, cylinder 2 (R2, L2) forward; x runs from
the aft edge (0) to the nose (2 L); thickness h, density rho, weightless rigid bulkheads.
From the CM: d2 = x_cm (aft edge), d1 = 2 L1 - x_cm (junction, signed), d3 = 2 L - x_cm
(nose), d4 = L - x_cm; xi_bar = (x - x_cm) / L runs from a = -d2/L through c = d1/L to
b = d3/L (reading guide section 2).

References: Tech Memo 104, sec. 2.2 and 4.2, Fig. 1-2; W. Weaver, S. P. Timoshenko,
D. H. Young, *Vibration Problems in Engineering*, 1990, appendix (thin tube inertia).
"""

from __future__ import annotations

from dataclasses import asdict, dataclass

import numpy as np

from ..checks import choice, nonnegative, positive

__all__ = [
    "DimensionlessGroups",
    "MassProperties",
    "dimensionless_groups",
    "mass_properties",
    "moment_of_inertia_memo",
]


@dataclass(frozen=True)
class MassProperties:
    """Mass properties and axial coordinates of the composite (all SI).

    Attributes
    ----------
    L : float
        Half-length of the composite, L = L1 + L2 (m).
    x_cm : float
        Position of the centre of mass from the aft edge (m).
    d1, d2, d3, d4 : float
        Distances of Fig. 1 (m): CM to junction (signed), to aft edge, to nose, geometric centre
        minus CM.
    a, c, b : float
        xi_bar of the aft edge, the junction and the nose.
    m1, m2, mass : float
        Shell masses of cylinder 1 and 2 and the total (kg).
    I_cm : float
        Pitch moment of inertia about the CM, thin-shell formula (kg m^2), erratum E1.
    cm_cylinder : int
        The cylinder (1 or 2) that holds the CM; 1 on the junction.
    """

    L: float
    x_cm: float
    d1: float
    d2: float
    d3: float
    d4: float
    a: float
    c: float
    b: float
    m1: float
    m2: float
    mass: float
    I_cm: float
    cm_cylinder: int

    def to_dict(self) -> dict[str, float | int]:
        """Return the properties as a JSON-ready mapping."""
        return asdict(self)


def mass_properties(
    R1: float, L1: float, R2: float, L2: float, h: float, rho: float
) -> MassProperties:
    """Mass properties of two joined thin cylindrical shells (memo 2.2-3, 4.2-2b, Fig. 1).

    m_d = 2 pi rho h R_d (2 L_d); I_cm = sum_d m_d (R_d^2/2 + L_d^2/3 + e_d^2), e_1 = d2 - L1,
    e_2 = d3 - L2 (erratum E1: the tube's own inertia plus the parallel-axis term).

    Parameters
    ----------
    R1, R2 : float
        Mid-surface radii of cylinder 1 (aft) and 2 (forward) (m).
    L1, L2 : float
        Half-lengths of cylinder 1 and 2 (m); ``L2 = 0`` gives the single cylinder.
    h : float
        Shell thickness (m), 0 < h < R1 and R2 (where R2 > 0).
    rho : float
        Mass density (kg/m^3).
    """
    R1, L1, h, rho = (positive(n, v) for n, v in (("R1", R1), ("L1", L1), ("h", h),
                                                   ("rho", rho)))
    R2, L2 = nonnegative("R2", R2), nonnegative("L2", L2)  # 0: the single-cylinder limit
    for name, radius in (("R1", R1), ("R2", R2)):
        if radius > 0.0 and not h < radius:  # a thin shell: the wall inside the radius
            raise ValueError(f"h = {h!r}: must be < {name} = {radius!r} (a thin shell)")
    m1 = 2.0 * np.pi * rho * h * R1 * (2.0 * L1)
    m2 = 2.0 * np.pi * rho * h * R2 * (2.0 * L2)
    mass = m1 + m2
    with np.errstate(over="ignore"):
        scale = np.float64(mass) * np.float64(R1 + R2 + L1 + L2) ** 2  # the size of I_cm
    if not np.isfinite(scale):
        raise ValueError(f"R1, L1, R2, L2, h, rho = {(R1, L1, R2, L2, h, rho)!r}: the mass "
                         "properties overflow double precision")
    L = L1 + L2
    x_cm = (m1 * L1 + m2 * (2.0 * L1 + L2)) / mass  # first moment of the two shells
    d2 = x_cm
    d1 = 2.0 * L1 - x_cm
    d3 = 2.0 * L - x_cm
    d4 = L - x_cm
    e1 = d2 - L1  # CM to the centre of cylinder 1
    e2 = d3 - L2  # CM to the centre of cylinder 2
    # Erratum E1 (memo eqs. 2.2-3 / 4.2-2b): thin tube about a transverse axis.
    I_cm = m1 * (R1**2 / 2.0 + L1**2 / 3.0 + e1**2) + m2 * (R2**2 / 2.0 + L2**2 / 3.0 + e2**2)
    return MassProperties(
        L=float(L),
        x_cm=float(x_cm),
        d1=float(d1),
        d2=float(d2),
        d3=float(d3),
        d4=float(d4),
        a=float(-d2 / L),
        c=float(d1 / L),
        b=float(d3 / L),
        m1=float(m1),
        m2=float(m2),
        mass=float(mass),
        I_cm=float(I_cm),
        cm_cylinder=1 if x_cm <= 2.0 * L1 else 2,
    )


def moment_of_inertia_memo(
    R1: float, L1: float, R2: float, L2: float, h: float, rho: float, form: str = "2.2-3"
) -> float:
    """I_cm as printed in the memo (kg m^2), kept for comparison (erratum E1, docs/memo-errata.md):
    2 pi rho h {R1 [2L1 (R1^2/4 + L1^2/k) + (d2 - L1)^3] + R2 [2L2 (R2^2/4 + L2^2/k) +
    (d3 - L2)^3]}, not the shells' moment of inertia.

    Parameters
    ----------
    R1, R2 : float
        Radii (m).
    L1, L2 : float
        Half-lengths (m).
    h : float
        Thickness (m).
    rho : float
        Density (kg/m^3).
    form : {"2.2-3", "4.2-2b"}
        Which printed form: eq. (2.2-3) has L_d^2/3, eq. (4.2-2b) L_d^2/4.
    """
    divisor = {"2.2-3": 3.0, "4.2-2b": 4.0}[choice("form", form, ("2.2-3", "4.2-2b"))]
    p = mass_properties(R1, L1, R2, L2, h, rho)
    return float(
        2.0
        * np.pi
        * rho
        * h
        * (
            R1 * (2.0 * L1 * (R1**2 / 4.0 + L1**2 / divisor) + (p.d2 - L1) ** 3)
            + R2 * (2.0 * L2 * (R2**2 / 4.0 + L2**2 / divisor) + (p.d3 - L2) ** 3)
        )
    )


@dataclass(frozen=True)
class DimensionlessGroups:
    """The dimensionless groups of memo section 3.0.

    Attributes
    ----------
    mu : float
        rho L^2 omega_1^2 / E (notation list; erratum E3 of 3.0-4a).
    lambda1, lambda2 : float
        lambda_d = L / R_d (eq. 3.0-1).
    sigma : float
        h / L (eq. 3.0-1).
    T0_bar : float
        T0 / (rho h L^2 omega_1^2) (eq. 3.0-4b).
    """

    mu: float
    lambda1: float
    lambda2: float
    sigma: float
    T0_bar: float

    def to_dict(self) -> dict[str, float]:
        """Return the groups as a JSON-ready mapping."""
        return asdict(self)


def dimensionless_groups(
    L: float, R1: float, R2: float, h: float, E: float, rho: float, omega_1: float, T0: float
) -> DimensionlessGroups:
    """The dimensionless groups mu, lambda_d, sigma, T0_bar (memo 3.0-1, 3.0-4, erratum E3).

    Parameters
    ----------
    L : float
        Half-length of the composite (m).
    R1, R2 : float
        Radii of cylinder 1 and 2 (m).
    h : float
        Shell thickness (m).
    E, rho : float
        Young's modulus (Pa) and density (kg/m^3).
    omega_1 : float
        First free-free bending frequency, eq. (4.2-8b) (rad/s).
    T0 : float
        Steady thrust per unit circumference of the aft edge (N/m).
    """
    for name, value in (("L", L), ("R1", R1), ("R2", R2), ("h", h), ("E", E), ("rho", rho),
                        ("omega_1", omega_1)):
        positive(name, value)
    nonnegative("T0", T0)
    return DimensionlessGroups(
        mu=float(rho * L**2 * omega_1**2 / E),  # notation list (eq. 3.0-4a corrected, E3)
        lambda1=float(L / R1),  # eq. (3.0-1)
        lambda2=float(L / R2),  # eq. (3.0-1)
        sigma=float(h / L),  # eq. (3.0-1)
        T0_bar=float(T0 / (rho * h * L**2 * omega_1**2)),  # eq. (3.0-4b)
    )
