"""The vehicle modes of a case, with the data of their figures (meridian and unrolled views):
what ``flexbooster modes`` and ``run`` store (``results.json`` key ``vehicle_modes``).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..checks import count, finite, positive
from .geometry import Cone, Vehicle
from .mass_properties import MassProperties, mass_properties
from .modes import VehicleModes, vehicle_modes
from .prestress import load_path
from .wetted_wall import slosh_modes

__all__ = [
    "SHAPES_PER_K",
    "SHAPE_HARMONICS",
    "UNROLLED_MODES",
    "ModeShapeViews",
    "VehicleSurvey",
    "has_flat_plate",
    "mode_shape_views",
    "vehicle_survey",
]

#: Modes drawn per harmonic in the meridian view (the lowest).
SHAPES_PER_K = 3
#: Harmonics drawn in the meridian view (those with the lowest first frequency).
SHAPE_HARMONICS = 4
#: Modes drawn on the unrolled surface (the lowest of each of the first harmonics shown).
UNROLLED_MODES = 3
_PATH_NOTES = {
    "inertia relief": "inertia relief: F0 at the aft edge, 0 at the nose",
    "forward support": "the supported forward end reacts it: uniform compression F0",
    "aft support": "the supported aft end reacts it where it acts: no prestress",
}


@dataclass(frozen=True)
class ModeShapeViews:
    """Figure data of the vehicle modes (everything a plot draws, nothing to compute).

    Attributes
    ----------
    harmonics : ndarray of int, shape (n_h,)
        Harmonics k shown in the meridian view, ascending.
    index : ndarray of int, shape (n_v,)
        Row of each shown mode in :class:`VehicleModes`.
    k, hz : ndarray, shape (n_v,)
        Harmonic and frequency (Hz) of each shown mode.
    label : tuple of str
        "k = 2, 3.18 Hz, radial, order 0" for each shown mode.
    x, r : ndarray, shape (n_pts,)
        Undeformed meridian: axial station and radius of the samples (m).
    x_deformed, r_deformed : ndarray, shape (n_v, n_pts)
        The meridian at theta = 0 displaced by ``scale`` times the mode (m).
    scale : float
        Displacement of the largest modal component drawn (m): 8 % of the vehicle length.
    unrolled_index, unrolled_label : ndarray of int, tuple of str
        Rows and labels of the modes drawn on the unrolled surface.
    theta, s : ndarray
        The unrolled grid: angle (rad, 0..2 pi) and meridian arc length (m, 0 at the aft edge).
    w : ndarray, shape (n_u, n_s, n_theta)
        Normal displacement W(s) cos(k theta) (max |W| over the three components = 1).
    """

    harmonics: np.ndarray
    index: np.ndarray
    k: np.ndarray
    hz: np.ndarray
    label: tuple
    x: np.ndarray
    r: np.ndarray
    x_deformed: np.ndarray
    r_deformed: np.ndarray
    scale: float
    unrolled_index: np.ndarray
    unrolled_label: tuple
    theta: np.ndarray
    s: np.ndarray
    w: np.ndarray

    def to_dict(self) -> dict:
        """JSON-ready mapping of plain lists and floats."""
        return {"harmonics": self.harmonics.tolist(), "index": self.index.tolist(),
                "k": self.k.tolist(), "hz": self.hz.tolist(), "label": list(self.label),
                "x": self.x.tolist(), "r": self.r.tolist(),
                "x_deformed": self.x_deformed.tolist(), "r_deformed": self.r_deformed.tolist(),
                "scale": float(self.scale), "unrolled_index": self.unrolled_index.tolist(),
                "unrolled_label": list(self.unrolled_label), "theta": self.theta.tolist(),
                "s": self.s.tolist(), "w": self.w.tolist()}


def _label(modes: VehicleModes, i: int) -> str:
    return (f"k = {modes.k[i]}, {modes.hz[i]:.4g} Hz, {modes.type[i]}, "
            f"order {modes.order[i]}")


def mode_shape_views(modes: VehicleModes, *, per_k: int = SHAPES_PER_K,
                     n_harmonics: int = SHAPE_HARMONICS, n_unrolled: int = UNROLLED_MODES,
                     n_theta: int = 73, n_s: int = 61) -> ModeShapeViews:
    """The meridian (theta = 0) and unrolled views of the lowest vehicle modes; u_x = u cos phi -
    w sin phi, u_r = u sin phi + w cos phi (Kraus 1967, ch. 2).

    Parameters
    ----------
    modes : VehicleModes
        From :func:`~flexbooster.shell_of_revolution.modes.vehicle_modes` (with shapes).
    per_k : int
        Modes per harmonic in the meridian view, 1..20.
    n_harmonics : int
        Harmonics in the meridian view, 1..50: those whose lowest frequency is lowest.
    n_unrolled : int
        Modes on the unrolled surface, 0..20: the lowest of each of the first harmonics.
    n_theta, n_s : int
        Points of the unrolled grid around and along the meridian, 3..1000.
    """
    if not isinstance(modes, VehicleModes):
        raise ValueError(f"modes = {type(modes).__name__}: must be a VehicleModes")
    per_k = count("per_k", per_k, 1, 20)
    n_harmonics = count("n_harmonics", n_harmonics, 1, 50)
    n_unrolled = count("n_unrolled", n_unrolled, 0, 20)
    n_theta = count("n_theta", n_theta, 3, 1000)
    n_s = count("n_s", n_s, 3, 1000)
    n, n_pts = len(modes), modes.s.size
    if modes.shapes.shape != (n, 3, n_pts):
        raise ValueError(f"modes.shapes shape = {modes.shapes.shape}: must be ({n}, 3, {n_pts})"
                         " (vehicle_modes with shapes)")
    ks = np.unique(modes.k)
    lowest = np.array([modes.hz[modes.k == kk].min() for kk in ks]) if n else np.zeros(0)
    order_k = ks[np.argsort(lowest, kind="stable")][:n_harmonics]
    harmonics = np.sort(order_k)
    index = np.concatenate([np.flatnonzero(modes.k == kk)[
        np.argsort(modes.hz[modes.k == kk], kind="stable")][:per_k]
        for kk in harmonics]).astype(int) if n else np.zeros(0, int)
    # meridian angle of each element from its end samples (straight frustum elements)
    n_el = int(sum(modes.elements_per_segment))
    ppe = n_pts // n_el
    xe, re, se = (a.reshape(n_el, ppe) for a in (modes.x, modes.r, modes.s))
    ds = se[:, -1] - se[:, 0]
    cos_phi = np.repeat((xe[:, -1] - xe[:, 0]) / ds, ppe)  # dx/ds (Kraus ch. 2)
    sin_phi = np.repeat((re[:, -1] - re[:, 0]) / ds, ppe)  # dr/ds
    u, w = modes.shapes[index, 0], modes.shapes[index, 2]
    length = float(np.ptp(modes.x)) or float(np.ptp(modes.r)) or 1.0
    scale = 0.08 * length
    x_def = modes.x[None] + scale * (u * cos_phi - w * sin_phi)  # u_x = u cos phi - w sin phi
    r_def = modes.r[None] + scale * (u * sin_phi + w * cos_phi)  # u_r = u sin phi + w cos phi
    # unrolled: the lowest mode of each of the first harmonics (by frequency)
    firsts = [int(np.flatnonzero(modes.k == kk)[np.argmin(modes.hz[modes.k == kk])])
              for kk in order_k]
    unrolled = np.array(sorted(firsts[:n_unrolled], key=lambda i: modes.hz[i]), dtype=int)
    theta = np.linspace(0.0, 2.0 * np.pi, n_theta)
    s_grid = np.linspace(modes.s[0], modes.s[-1], n_s)
    # s is non-decreasing (element ends twice): np.interp takes the later sample at a tie
    w_s = np.array([np.interp(s_grid, modes.s, modes.shapes[i, 2]) for i in unrolled])
    w_s = w_s.reshape(unrolled.size, n_s)
    field = w_s[:, :, None] * np.cos(np.outer(modes.k[unrolled], theta))[:, None, :]  # W cos k th
    return ModeShapeViews(
        harmonics=harmonics.astype(int), index=index, k=modes.k[index], hz=modes.hz[index],
        label=tuple(_label(modes, i) for i in index), x=modes.x, r=modes.r,
        x_deformed=x_def, r_deformed=r_def, scale=scale, unrolled_index=unrolled,
        unrolled_label=tuple(_label(modes, i) for i in unrolled), theta=theta, s=s_grid,
        w=field)


@dataclass(frozen=True)
class VehicleSurvey:
    """The vehicle modes of a case, as ``flexbooster modes`` and ``run`` report them.

    Attributes
    ----------
    vehicle : Vehicle
        The vehicle analysed.
    source : str
        ``"vehicle"`` (``[[vehicle.segments]]``) or ``"memo"`` (built from ``[booster]``).
    modes : VehicleModes
        Frequencies, labels and shapes for k = 0..k_max.
    k_max : int
        Highest harmonic.
    f_max : float or None
        Frequency bound (Hz); None: the band up to 5 times the lowest elastic frequency.
    prestressed, prestress_F0 : bool, float
        Whether the frequencies include the thrust prestress, and its thrust (N).
    note : str
        One line on the prestress, for the output.
    views : ModeShapeViews or None
        Figure data; None when the figures are not wanted.
    mass_properties : MassProperties or None
        Mass, centre of mass and pitch inertia of the vehicle, by contribution.
    slosh : tuple of SloshMode
        Each partly filled tank's first slosh mode under the thrust's acceleration F0 / m.
    """

    vehicle: Vehicle
    source: str
    modes: VehicleModes
    k_max: int
    f_max: float | None
    prestressed: bool
    prestress_F0: float
    note: str
    views: ModeShapeViews | None = None
    mass_properties: MassProperties | None = None
    slosh: tuple = ()

    def rows(self) -> list[dict]:
        """One JSON-ready mapping per mode: k, hz, rad_s, order, type, segment, kinetic shares."""
        m = self.modes
        return [{"k": int(m.k[i]), "hz": float(m.hz[i]), "rad_s": float(m.omega[i]),
                 "order": int(m.order[i]), "type": str(m.type[i]),
                 "segment": int(m.segment[i]),
                 "kinetic_u": float(m.kinetic_share[i, 0]),
                 "kinetic_v": float(m.kinetic_share[i, 1]),
                 "kinetic_w": float(m.kinetic_share[i, 2])} for i in range(len(m))]

    def to_columns(self) -> dict[str, list]:
        """The table of ``vehicle-modes.csv`` as parallel columns."""
        m = self.modes
        return {"k": m.k.tolist(), "hz": m.hz.tolist(), "rad_s": m.omega.tolist(),
                "order": m.order.tolist(), "type": m.type.tolist(),
                "segment": m.segment.tolist(), "kinetic_u": m.kinetic_share[:, 0].tolist(),
                "kinetic_v": m.kinetic_share[:, 1].tolist(),
                "kinetic_w": m.kinetic_share[:, 2].tolist()}

    def to_dict(self, *, figures: bool = True) -> dict:
        """JSON-ready mapping: the vehicle, the settings, the list ``modes`` and the figures.

        Parameters
        ----------
        figures : bool
            Include the figure data (``figures``: None without it or without views).
        """
        m = self.modes
        return {
            "source": self.source, "vehicle": self.vehicle.to_dict(), "k_max": self.k_max,
            "f_max_hz": self.f_max, "prestressed": self.prestressed,
            "prestress_F0": float(self.prestress_F0), "load_path": m.load_path,
            "note": self.note,
            "theory": m.theory, "rigid_modes": {str(k): int(v)
                                                for k, v in m.rigid_modes.items()},
            "elements_per_segment": list(m.elements_per_segment),
            "element_order": int(m.element_order),
            "units": {"hz": "Hz", "rad_s": "rad/s", "prestress_F0": "N", "f_max_hz": "Hz",
                      "figures.x, r, x_deformed, r_deformed, s, scale": "m",
                      "figures.theta": "rad", "figures.w": "1 (max modal component = 1)"},
            "modes": self.rows(),
            "warnings": [w.to_dict() for w in m.warnings],
            "figures": self.views.to_dict() if figures and self.views is not None else None,
            **({} if self.mass_properties is None else
               {"mass_properties": self.mass_properties.to_dict()}),
            **({"slosh": [{"tank": m.tank, "hz": m.hz, "mass_kg": m.mass_kg}
                          for m in self.slosh]} if self.vehicle.tanks else {}),
        }


def has_flat_plate(vehicle: Vehicle) -> bool:
    """Whether a segment is a flat annular plate (a cone of axial length 0).

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    """
    return any(isinstance(seg, Cone) and seg.length == 0.0 for seg in vehicle.segments)


def vehicle_survey(vehicle: Vehicle, *, k_max: int, F0: float | None,
                   f_max: float | None = None,
                   prestress: bool = True, views: bool = True,
                   source: str = "vehicle") -> VehicleSurvey:
    """Vehicle modes for k = 0..k_max, prestressed by the thrust by default; ValueError for invalid
    arguments or a prestress beyond a buckling load (Fluegge 1973, sec. 2.2.2).

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle.
    k_max : int
        Highest circumferential wave number, 0..200.
    F0 : float or None
        Steady thrust (N), > 0, with the load path of the vehicle's ends
        (:func:`.prestress.load_path`); None: no thrust, the unloaded modes.
    f_max : float, optional
        Keep the modes up to this frequency (Hz), > 0; default the band up to 5 times the
        lowest elastic frequency.
    prestress : bool
        Include the prestress (left out, with a note, for a vehicle with a flat plate).
    views : bool
        Compute the figure data (:func:`mode_shape_views`).
    source : str
        ``"vehicle"`` or ``"memo"``, recorded in the result.
    """
    F0 = None if F0 is None else positive("F0", F0)
    if f_max is not None:
        f_max = positive("f_max", f_max)
    if source not in ("vehicle", "memo"):
        raise ValueError(f"source = {source!r}: must be 'vehicle' or 'memo'")
    load = 0.0
    if F0 is None:
        note = "unloaded: the case has no thrust"
    elif not prestress:
        note = "unloaded: no thrust prestress (--no-prestress)"
    elif has_flat_plate(vehicle):
        note = ("unloaded: the vehicle has a flat plate, which cannot carry the thrust as a "
                "membrane, so the prestress is left out")
    else:
        load = finite("F0", F0)
        note = f"prestressed by the thrust F0 = {F0:.6g} N ({_PATH_NOTES[load_path(vehicle)]})"
    modes = vehicle_modes(vehicle, k_max=k_max, f_max=f_max, prestress_F0=load)
    props = mass_properties(vehicle)
    return VehicleSurvey(vehicle=vehicle, source=source, modes=modes, k_max=int(k_max),
                         f_max=f_max, prestressed=load > 0.0, prestress_F0=load, note=note,
                         views=mode_shape_views(modes) if views and len(modes) else None,
                         mass_properties=props,
                         slosh=() if F0 is None  # no thrust: no settled liquid
                         else slosh_modes(vehicle, acceleration=F0 / props.mass_kg))
