"""Forced response of the vehicle to the thrust oscillation: g, N and N m at every station.

Delta F(t) = gamma F0 cos(Omega t) along a thrust line misaligned by delta loads the aft edge
axially (k = 0, cos delta) and laterally (k = 1, sin delta); per harmonic the reduced model
of :mod:`.forced_model`. Stations: the edges, the junctions and the caller's (the vehicle is
cut there). Peaks come from the resonances, not the grid: 65 points across each damped
resonance, then golden section. Theory: docs/theory/forced-response.md.

References: L. Meirovitch, *Elements of Vibration Analysis*, 1986, ch. 7; R. R. Craig,
A. J. Kurdila, *Fundamentals of Structural Dynamics*, 2006.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..checks import count, finite, finite_array, nonnegative, positive
from ..shell_of_revolution import DEFAULT_ORDER, Vehicle, mesh_vehicle
from .forced_model import ROWS, ModalModel, basis_size, cut_vehicle, mesh_nodes, modal_model

__all__ = ["STANDARD_GRAVITY", "QUANTITIES", "UNITS", "ThrustSpectrum", "Station",
           "ForcedPeak", "LoadEnvelope", "ForcedResponse", "UndampedResonanceError",
           "forced_response", "basis_sizes", "window_peaks", "ModePeak", "mode_peaks",
           "PEAK_WINDOW", "MIN_PARTICIPATION", "peak_half_width"]

#: Standard acceleration of gravity g (m/s^2), exact by definition (3rd CGPM, 1901).
STANDARD_GRAVITY = 9.80665
#: Response quantities and their SI units.
QUANTITIES = ("displacement", "acceleration", "axial_force", "shear_force", "bending_moment")
UNITS = {"displacement": "m", "acceleration": "m/s^2", "axial_force": "N", "shear_force": "N",
         "bending_moment": "N m"}
#: A pole counts as undamped if Re lambda >= -UNDAMPED_RTOL |lambda| (an effective damping
#: ratio below 1e-6: a resonant amplification above 5e5, or a growing mode).
UNDAMPED_RTOL = 1e-6
#: Peak search: points at a pole +- (half-power half-width) j / CLUSTER_DENSITY, |j| <=
#: CLUSTER, then GOLDEN_STEPS golden-section steps in the bracket of the largest sample (its
#: width x 0.618^24 = 1e-5: the peak value to about 1e-10 relative).
CLUSTER, CLUSTER_DENSITY, GOLDEN_STEPS = 32, 8, 24
#: Half-width of the window around a mode's frequency in which its forced peak is sought, in
#: damping ratios: a mode's resonant peak lies within zeta^2 omega of omega and its half-power
#: band is omega (1 -+ zeta) (Meirovitch 1986, sec. 3.4); at most 1/2.
PEAK_WINDOW = 4.0
#: Modes whose participation f^2 in the thrust oscillation (f the generalised force of the
#: mass-normalised mode per newton) is below this fraction of the largest of their harmonic are
#: not forced by the thrust (torsion; :data:`flexbooster.dynamics.axial.MIN_SHARE`).
MIN_PARTICIPATION = 1e-8


class UndampedResonanceError(ValueError):
    """A mode not damped has its resonance in the Omega range (or on a line): no bounded steady
    response. ``parameter`` is the damping that would bound it ("damping_ratio" or
    "pitch_damping_ratio"), ``k`` the harmonic, ``omega`` the mode's frequency (rad/s).
    """

    def __init__(self, message: str, parameter: str, k: int, omega: float):
        super().__init__(message)
        self.parameter, self.k, self.omega = parameter, k, omega

    def __reduce__(self):
        return type(self), (str(self), self.parameter, self.k, self.omega)


def _complex(a) -> dict:
    return {"real": np.real(a).tolist(), "imag": np.imag(a).tolist()}


@dataclass(frozen=True)
class ThrustSpectrum:
    """Lines of the thrust oscillation: Delta F(t) = F0 sum_j a_j cos(Omega_j t).

    Parameters
    ----------
    frequency : array_like
        Omega_j (rad/s), > 0, strictly increasing.
    amplitude : array_like
        a_j as a fraction of F0, [0, 1), one per line.
    """

    frequency: np.ndarray
    amplitude: np.ndarray

    def __post_init__(self) -> None:
        f = finite_array("spectrum.frequency", self.frequency, positive=True).ravel()
        a = finite_array("spectrum.amplitude", self.amplitude).ravel()
        if np.any(np.diff(f) <= 0.0):
            raise ValueError("spectrum.frequency: must be strictly increasing")
        if a.shape != f.shape or np.any(a < 0.0) or np.any(a >= 1.0):
            raise ValueError(f"spectrum.amplitude: must hold {f.size} values in [0, 1)")
        object.__setattr__(self, "frequency", f)
        object.__setattr__(self, "amplitude", a)

    def to_dict(self) -> dict:
        """JSON-ready mapping."""
        return {"frequency": self.frequency.tolist(), "amplitude": self.amplitude.tolist()}


@dataclass(frozen=True)
class Station:
    """A station of the forced response.

    Attributes
    ----------
    name : str
        "aft-edge", "forward-edge", "junction-i" (between segments i - 1 and i) or the caller's.
    x : float
        Axial distance from the aft edge (m).
    kind : str
        "edge", "junction" or "user".
    """

    name: str
    x: float
    kind: str

    def to_dict(self) -> dict:
        """JSON-ready mapping."""
        return {"name": self.name, "station_m": float(self.x), "kind": self.kind}


@dataclass(frozen=True)
class ForcedPeak:
    """Peak of |quantity| over the Omega range at a station (spectrum: sum over the lines).

    Attributes
    ----------
    k : int
        Harmonic (0: axial, 1: lateral).
    station, station_m : str, float
        Station name and its axial distance from the aft edge (m).
    quantity, unit : str
        One of :data:`QUANTITIES` and its SI unit.
    value : float
        Peak amplitude (unit).
    omega : float
        Omega where it occurs (rad/s); spectrum: the line contributing most; a harmonic not
        forced: value 0 at the lowest Omega.
    """

    k: int
    station: str
    station_m: float
    quantity: str
    unit: str
    value: float
    omega: float

    def to_dict(self) -> dict:
        """JSON-ready mapping."""
        return {"k": self.k, "station": self.station, "station_m": float(self.station_m),
                "quantity": self.quantity, "unit": self.unit, "value": float(self.value),
                "omega": float(self.omega)}


@dataclass(frozen=True)
class LoadEnvelope:
    """An internal load along the vehicle, at every node of the mesh.

    Attributes
    ----------
    k : int
        Harmonic.
    quantity, unit : str
        "axial_force" (k = 0), "shear_force" or "bending_moment" (k = 1), SI unit.
    x : ndarray
        Axial distance of the nodes from the aft edge (m), non-decreasing.
    peak, peak_omega : ndarray
        Peak |load| at each node (unit) and its Omega (rad/s), as :class:`ForcedPeak`.
    worst_omega : float
        Omega of the largest peak (rad/s).
    at_worst : ndarray, complex
        The load at every node at ``worst_omega`` (unit).
    """

    k: int
    quantity: str
    unit: str
    x: np.ndarray
    peak: np.ndarray
    peak_omega: np.ndarray
    worst_omega: float
    at_worst: np.ndarray

    def to_dict(self) -> dict:
        """JSON-ready mapping."""
        return {"k": self.k, "quantity": self.quantity, "unit": self.unit,
                "x": self.x.tolist(), "peak": self.peak.tolist(),
                "peak_omega": self.peak_omega.tolist(), "worst_omega": float(self.worst_omega),
                "at_worst": _complex(self.at_worst)}


@dataclass(frozen=True)
class ForcedResponse:
    """Steady forced response of the vehicle to the thrust oscillation.

    Attributes
    ----------
    omega, amplitude : ndarray, shape (n,)
        Omega grid (rad/s: the sweep's or the spectrum's lines) and gamma at each.
    combination : str
        "sweep" (peaks: the maximum over the range) or "spectrum" (peaks: the sum of the lines'
        amplitudes, the supremum of a sum of incommensurate sinusoids).
    F0, damping_ratio, pitch_damping_ratio, misalignment, gimbal_gain : float
        Steady thrust (N), zeta, zeta_psi, delta (rad) and K.
    harmonics : tuple of int
        The k of the first axis of the arrays (0 axial, 1 lateral).
    stations : tuple of Station
        Aft to forward.
    displacement, acceleration, axial_force, shear_force, bending_moment : ndarray, complex
        Shape (len(harmonics), len(stations), n): amplitudes X of Re(X e^{i Omega t}) (m, m/s^2,
        N (tension > 0), N, N m); 0 where the quantity does not belong to the harmonic.
    peaks : tuple of ForcedPeak
        Per harmonic, station and quantity of the harmonic.
    envelopes : tuple of LoadEnvelope
        k = 0 axial force, k = 1 shear force and bending moment along the vehicle.
    models : tuple of ModalModel
        The reduced model of each harmonic.
    station_nodes : tuple of int
        The mesh node of each station (the models' node rows).
    """

    omega: np.ndarray
    amplitude: np.ndarray
    combination: str
    F0: float
    damping_ratio: float
    pitch_damping_ratio: float
    misalignment: float
    gimbal_gain: float
    harmonics: tuple
    stations: tuple
    displacement: np.ndarray
    acceleration: np.ndarray
    axial_force: np.ndarray
    shear_force: np.ndarray
    bending_moment: np.ndarray
    peaks: tuple
    envelopes: tuple
    models: tuple
    station_nodes: tuple = ()

    @property
    def acceleration_g(self) -> np.ndarray:
        """Acceleration in units of g = :data:`STANDARD_GRAVITY` (complex, dimensionless)."""
        return self.acceleration / STANDARD_GRAVITY

    def peak(self, k: int, station: str, quantity: str) -> ForcedPeak:
        """The :class:`ForcedPeak` of harmonic k, station name and quantity (KeyError if none)."""
        for p in self.peaks:
            if (p.k, p.station, p.quantity) == (k, station, quantity):
                return p
        raise KeyError((k, station, quantity))

    def to_dict(self, *, models: bool = False) -> dict:
        """JSON-ready mapping (``models=True`` adds the reduced models)."""
        out = {"omega": self.omega.tolist(), "amplitude": self.amplitude.tolist(),
               "combination": self.combination, "F0": float(self.F0),
               "damping_ratio": float(self.damping_ratio),
               "pitch_damping_ratio": float(self.pitch_damping_ratio),
               "misalignment": float(self.misalignment), "gimbal_gain": float(self.gimbal_gain),
               "harmonics": list(self.harmonics), "standard_gravity": STANDARD_GRAVITY,
               "stations": [s.to_dict() for s in self.stations],
               "peaks": [p.to_dict() for p in self.peaks],
               "envelopes": [e.to_dict() for e in self.envelopes]}
        out.update({q: _complex(getattr(self, q)) for q in QUANTITIES})
        if models:
            out["models"] = [m.to_dict() for m in self.models]
        return out




def _stations(vehicle: Vehicle, stations) -> list:
    """(Station, junction index or None) of the edges, junctions and the caller's stations,
    aft to forward (an automatic station first where they coincide)."""
    out, x = [(Station("aft-edge", 0.0, "edge"), None)], 0.0
    for i, seg in enumerate(vehicle.segments[:-1]):
        x += seg.length
        out.append((Station(f"junction-{i + 1}", x, "junction"), i + 1))
    out.append((Station("forward-edge", vehicle.total_length, "edge"), None))
    names = {s.name for s, _ in out}
    for j, item in enumerate(stations):
        if not isinstance(item, tuple | list) or len(item) != 2:
            raise ValueError(f"stations[{j}] = {item!r}: must be a (name, station_m) pair")
        name, xs = item
        if not isinstance(name, str) or not name.strip() or name in names:
            raise ValueError(f"stations[{j}].name = {name!r}: must be a non-empty name that "
                             "no other station has")
        xs = finite(f"stations[{j}].station_m", xs)
        if not 0.0 <= xs <= vehicle.total_length:
            raise ValueError(f"stations[{j}].station_m = {xs!r}: must be in [0, "
                             f"{vehicle.total_length!r}] m (the vehicle's length)")
        names.add(name)
        out.append((Station(name, xs, "user"), None))
    return sorted(out, key=lambda item: item[0].x)


def _omega(amplitude, Omega) -> tuple[np.ndarray, np.ndarray, str]:
    """(Omega, gamma of each, combination) of a sweep (gamma, grid) or a spectrum."""
    if isinstance(amplitude, ThrustSpectrum):
        if Omega is not None:
            raise ValueError("Omega: must be None with a spectrum (its lines are the Omega)")
        return amplitude.frequency, amplitude.amplitude, "spectrum"
    gamma = nonnegative("amplitude", amplitude)
    if gamma >= 1.0:
        raise ValueError(f"amplitude = {amplitude!r}: must be in [0, 1)")
    om = finite_array("Omega", Omega if Omega is not None else [], positive=True).ravel()
    if om.size > 100_000 or np.any(np.diff(om) <= 0.0):
        raise ValueError("Omega: must be strictly increasing, at most 100000 points")
    return om, np.full(om.size, gamma), "sweep"


def _undamped(model: ModalModel, om: np.ndarray, spectrum: bool) -> tuple | None:
    """(lambda, dominant basis mode) of a pole not damped (Re lambda >= -UNDAMPED_RTOL |lambda|)
    with Im lambda in the Omega range (sweep) or on a line (spectrum).
    """
    poles, mode = model.poles()
    for lam, j in zip(poles, mode, strict=True):
        c = lam.imag
        if c <= 0.0 or lam.real < -UNDAMPED_RTOL * abs(lam):
            continue
        if (np.any(np.abs(om - c) <= UNDAMPED_RTOL * c) if spectrum else om[0] <= c <= om[-1]):
            return complex(lam), int(j)
    return None


def _golden(model: ModalModel, a, b, node, row, power):
    """Maximum of Omega^power |row| in [a, b] per entry by golden section (value, Omega),
    GOLDEN_STEPS steps (Kiefer 1953).
    """
    r = (math.sqrt(5.0) - 1.0) / 2.0

    def f(om):
        return om**power * np.abs(model.pointwise(om, node, row))

    c, d = b - r * (b - a), a + r * (b - a)
    fc, fd = f(c), f(d)
    for _ in range(GOLDEN_STEPS):
        left = fc >= fd  # the maximum is in [a, d]: d <- c; else in [c, b]: c <- d
        a, b = np.where(left, a, c), np.where(left, d, b)
        c_new = np.where(left, b - r * (b - a), d)
        d_new = np.where(left, c, a + r * (b - a))
        fnew = f(np.where(left, c_new, d_new))
        fc, fd = np.where(left, fnew, fd), np.where(left, fc, fnew)
        c, d = c_new, d_new
    return np.where(fc >= fd, fc, fd), np.where(fc >= fd, c, d)


def _peaks(model: ModalModel, om, scale, objectives, spectrum: bool):
    """Peak of each objective (row, power) at every node and its Omega: arrays (p, n_obj)."""
    rows = np.array([o[1] for o in objectives])
    power = np.array([o[2] for o in objectives])

    def magnitude(w, s):  # (n, p, n_obj): s Omega^power |row|
        return s[:, None, None] * w[:, None, None] ** power * np.abs(
            model.response(w)[:, :, rows])

    if spectrum:  # sup_t |sum_j X_j cos(Omega_j t + phi_j)| = sum_j |X_j| (incommensurate)
        mag = magnitude(om, scale)
        return mag.sum(axis=0), om[np.argmax(mag, axis=0)]
    poles = model.poles()[0]
    up = poles[poles.imag > 0.0]
    steps = np.arange(-CLUSTER, CLUSTER + 1) / CLUSTER_DENSITY
    pts = (up.imag[:, None] + np.abs(up.real)[:, None] * steps).ravel()
    grid = np.unique(np.concatenate([om, pts[(pts >= om[0]) & (pts <= om[-1])]]))
    mag = magnitude(grid, np.ones(grid.size))  # per unit scale: the sweep's gamma is constant
    node, obj = (x.ravel() for x in np.indices(mag.shape[1:]))
    value, at = _refined_max(model, grid, mag.reshape(grid.size, -1), node, rows[obj],
                             power[obj])
    return scale[0] * value.reshape(mag.shape[1:]), at.reshape(mag.shape[1:])


def _refined_max(model: ModalModel, grid, mag, node, row, power):
    """Largest of Omega^power |row| per column of ``mag`` (its samples on ``grid``, (g, m);
    column j is row ``row[j]`` of node ``node[j]``): the largest sample, then :func:`_golden`
    between its neighbours, whichever is larger (value (m,), Omega (m,))."""
    i = np.argmax(mag, axis=0)
    lo, hi = grid[np.maximum(i - 1, 0)], grid[np.minimum(i + 1, grid.size - 1)]
    val, at = _golden(model, lo, hi, node, row, power)
    best = mag.max(axis=0)
    better = val > best
    return np.where(better, val, best), np.where(better, at, grid[i])


def _harmonic(model: ModalModel, om, scale, spectrum: bool, stations, at):
    """(node rows (n, p, rows), peaks at the stations, envelopes) of one harmonic; scale: Delta F
    of each Omega (N), 0 for a harmonic not forced.
    """
    k = model.k
    objectives = [("displacement", 0, 0), ("acceleration", 0, 2)] + [
        (q, i, 0) for i, q in enumerate(ROWS[k]) if i > 0]
    p = model.node_x.size
    if not np.any(scale):  # not forced: zero, its peaks at the lowest Omega
        vals = np.zeros((om.size, p, len(ROWS[k])), dtype=complex)
        value, where = np.zeros((p, len(objectives))), np.full((p, len(objectives)), om[0])
    else:
        vals = model.response(om) * scale[:, None, None]
        value, where = _peaks(model, om, scale, objectives, spectrum)
    peaks, envelopes = [], []
    for j, (q, row, _) in enumerate(objectives):
        peaks += [ForcedPeak(k=k, station=s.name, station_m=s.x, quantity=q, unit=UNITS[q],
                             value=float(value[a, j]), omega=float(where[a, j]))
                  for s, a in zip(stations, at, strict=True)]
        if q in ROWS[k][1:]:  # an internal load: its envelope along the vehicle
            n = int(np.argmax(value[:, j]))
            w = float(where[n, j])
            line = np.nonzero(om == w)[0]  # a spectrum's line (sweep: gamma is constant)
            worst = model.response([w])[0, :, row] * scale[line[0] if line.size else 0]
            envelopes.append(LoadEnvelope(k=k, quantity=q, unit=UNITS[q], x=model.node_x,
                                          peak=value[:, j], peak_omega=where[:, j],
                                          worst_omega=w, at_worst=worst))
    return vals, peaks, envelopes


def _station_mesh(vehicle: Vehicle, listed, elements_per_segment, order: int,
                  refinement: int) -> tuple:
    """(the vehicle cut at the user's stations, its mesh, the segment starting at each
    station or None) of :func:`forced_response`."""
    counts = elements_per_segment
    if counts is not None and not isinstance(counts, tuple | list):
        counts = (counts,) * len(vehicle.segments)
    cut, counts, starts = cut_vehicle(vehicle, [s.x for s, _ in listed if s.kind == "user"],
                                      counts)
    mesh = mesh_vehicle(cut, elements_per_segment=counts, order=order, refinement=refinement)
    return cut, mesh, starts


def basis_sizes(vehicle: Vehicle, *, F0: float, omega_max: float, stations=(),
                harmonics: tuple = (0, 1), supported_forward_end: bool = False,
                elements_per_segment: int | tuple | None = None, order: int = DEFAULT_ORDER,
                refinement: int = 1) -> tuple[int, ...]:
    """The modes of each harmonic's basis in :func:`forced_response` with ``n_modes`` None
    (rigid ones included; the number of Omega-independent modal coordinates), counted up
    front without an eigenvector (:func:`.forced_model.basis_size`, Sylvester's law of
    inertia), for the cost estimate. ValueError for bad input.

    Parameters
    ----------
    vehicle, F0, stations, harmonics, supported_forward_end, elements_per_segment, order, \
refinement
        As :func:`forced_response`.
    omega_max : float
        The highest Omega of the grid or of the spectrum's lines (rad/s), > 0.
    """
    if not isinstance(vehicle, Vehicle):
        raise ValueError(f"vehicle = {vehicle!r}: must be a Vehicle")
    F0, omega_max = positive("F0", F0), positive("omega_max", omega_max)
    if (not isinstance(harmonics, tuple | list) or not set(harmonics) <= {0, 1}):
        raise ValueError(f"harmonics = {harmonics!r}: must be values among (0, 1)")
    cut, mesh, _ = _station_mesh(vehicle, _stations(vehicle, stations), elements_per_segment,
                                 order, refinement)
    return tuple(basis_size(cut, mesh, int(k), F0=F0, omega_max=omega_max,
                            supported_forward_end=supported_forward_end) for k in harmonics)


def forced_response(
    vehicle: Vehicle, *, F0: float, amplitude: float | ThrustSpectrum, Omega=None,
    damping_ratio: float = 0.01, misalignment: float = 0.0, gimbal_gain: float = 0.0,
    pitch_damping_ratio: float = 0.0, stations=(), harmonics: tuple = (0, 1),
    n_modes: int | None = None, static_correction: bool = True,
    supported_forward_end: bool = False, elements_per_segment: int | tuple | None = None,
    order: int = DEFAULT_ORDER, refinement: int = 1,
) -> ForcedResponse:
    """Steady response to Delta F(t) = gamma F0 cos(Omega t) at the aft edge. ValueError for bad
    input, a thrust that buckles a harmonic, or an undamped resonance in the range or on a line.

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle (:class:`flexbooster.shell_of_revolution.Vehicle`).
    F0 : float
        Steady thrust (N), > 0.
    amplitude : float or ThrustSpectrum
        gamma (fraction of F0), [0, 1), swept over ``Omega``; or the spectrum's lines (``Omega``
        None).
    Omega : array_like
        Strictly increasing Omega grid (rad/s), > 0, 1..100000 points (sweep only).
    damping_ratio, pitch_damping_ratio : float
        zeta of the elastic modes and zeta_psi of the gimbaled rigid pitch, [0, 1).
    misalignment : float
        Thrust misalignment delta (rad), |delta| < pi/2.
    gimbal_gain : float
        K >= 0: the thrust turns by K psi (memo 2.2-2).
    stations : sequence of (str, float)
        (name, axial distance from the aft edge in m) of the caller's stations.
    harmonics : tuple of int
        Among (0, 1).
    n_modes : int, optional
        Elastic basis modes per harmonic, 1..2000; default every mode below 4 max Omega (>= 4).
    static_correction : bool
        The static correction of the truncated modes (False: mode displacement only).
    supported_forward_end, elements_per_segment, order, refinement
        Prestress and mesh (see :func:`flexbooster.shell_of_revolution.mesh_vehicle`).
    """
    if not isinstance(vehicle, Vehicle):
        raise ValueError(f"vehicle = {vehicle!r}: must be a Vehicle")
    F0 = positive("F0", F0)
    zeta, zpsi = (nonnegative(n, v) for n, v in (("damping_ratio", damping_ratio),
                                                 ("pitch_damping_ratio", pitch_damping_ratio)))
    for name, val in (("damping_ratio", zeta), ("pitch_damping_ratio", zpsi)):
        if val >= 1.0:
            raise ValueError(f"{name} = {val!r}: must be in [0, 1)")
    K = nonnegative("gimbal_gain", gimbal_gain)
    delta = finite("misalignment", misalignment)
    if abs(delta) >= math.pi / 2.0:
        raise ValueError(f"misalignment = {misalignment!r}: must be in (-pi/2, pi/2) rad")
    if (not isinstance(harmonics, tuple | list) or not harmonics
            or len(set(harmonics)) != len(harmonics) or not set(harmonics) <= {0, 1}):
        raise ValueError(f"harmonics = {harmonics!r}: must be distinct values among (0, 1)")
    harmonics = tuple(sorted(int(k) for k in harmonics))
    if n_modes is not None:
        n_modes = count("n_modes", n_modes, 1, 2000)
    om, gam, combination = _omega(amplitude, Omega)
    listed = _stations(vehicle, stations)
    cut, mesh, starts = _station_mesh(vehicle, listed, elements_per_segment, order, refinement)
    x_nodes = mesh_nodes(mesh)[2]
    first = np.concatenate(([0], np.cumsum(mesh.elements_per_segment)))  # a segment's node
    tol = 1e-9 * vehicle.total_length
    at = np.array([first[starts[j]] if j is not None else x_nodes.size - 1
                   if s.name == "forward-edge" else int(np.argmax(np.abs(x_nodes - s.x) <= tol))
                   for s, j in listed])
    rows_s = [s for s, _ in listed]
    share = {0: math.cos(delta), 1: math.sin(delta)}
    shape = (len(harmonics), len(rows_s), om.size)
    out = {q: np.zeros(shape, dtype=complex) for q in QUANTITIES}
    peaks, envelopes, models = [], [], []
    for ik, k in enumerate(harmonics):
        model = modal_model(cut, mesh, k, F0=F0, share=share[k], n_modes=n_modes,
                            omega_max=float(om[-1]), gimbal_gain=K, damping_ratio=zeta,
                            pitch_damping_ratio=zpsi,
                            supported_forward_end=supported_forward_end,
                            static_correction=static_correction)
        models.append(model)
        if share[k] != 0.0:
            hit = _undamped(model, om, combination == "spectrum")
            if hit is not None:  # the rigid pitch, or an elastic mode
                hit, j = hit
                name, val = ("pitch_damping_ratio", zpsi) if j < model.n_rigid else (
                    "damping_ratio", zeta)
                place = "on a line" if combination == "spectrum" else "in the Omega range"
                raise UndampedResonanceError(
                    f"{name} = {val!r}: the k = {k} mode at {hit.imag:.6g} rad/s {place} is "
                    f"not damped (growth rate {hit.real:.3g} 1/s): no bounded steady response",
                    name, k, float(hit.imag))
        vals, found, loads = _harmonic(model, om, gam * F0 * (share[k] != 0.0),
                                       combination == "spectrum", rows_s, at)
        for i, q in enumerate(ROWS[k]):
            out[q][ik] = vals[:, at, i].T
        out["acceleration"][ik] = -(om**2) * out["displacement"][ik]
        peaks += found
        envelopes += loads
    arrays = list(out.values()) + [p.value for p in peaks] + [e.at_worst for e in envelopes]
    if not all(np.all(np.isfinite(a)) for a in arrays):
        raise ValueError(f"Omega = {om[0]!r}: the response is not finite (the rigid-body "
                         "displacement grows like 1 / Omega^2)")
    return ForcedResponse(omega=om, amplitude=gam, combination=combination, F0=F0,
                          damping_ratio=zeta, pitch_damping_ratio=zpsi, misalignment=delta,
                          gimbal_gain=K, harmonics=harmonics, stations=tuple(rows_s),
                          peaks=tuple(peaks), envelopes=tuple(envelopes),
                          models=tuple(models), station_nodes=tuple(int(a) for a in at),
                          **out)


def window_peaks(response: ForcedResponse, *, k: int, omega, half_width: float
                 ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The peak steady acceleration over the stations near each frequency of ``omega``: the
    largest |a| at any station for Omega in omega (1 -+ half_width), 2 CLUSTER + 1 points
    across the window then GOLDEN_STEPS golden-section steps around the largest (Kiefer 1953),
    as the peaks of :func:`forced_response`. A sweep's amplitude gamma, Delta F = gamma F0
    along the misaligned thrust line (Meirovitch 1986, ch. 7).

    Parameters
    ----------
    response : ForcedResponse
        A sweep (one gamma) holding harmonic ``k``.
    k : int
        The harmonic, 0 or 1.
    omega : array_like
        Centres of the windows (rad/s), > 0, shape (n,).
    half_width : float
        Relative half-width of each window, in (0, 1).

    Returns
    -------
    peak : ndarray, shape (n,)
        Peak acceleration amplitude (m/s^2), 0 where the harmonic is not forced.
    at : ndarray, shape (n,)
        Omega of the peak (rad/s).
    station : ndarray of int, shape (n,)
        Index into ``response.stations`` of the station where it is.
    """
    if not isinstance(response, ForcedResponse) or response.combination != "sweep":
        raise ValueError("response: must be the ForcedResponse of a sweep")
    if k not in response.harmonics:
        raise ValueError(f"k = {k!r}: must be one of the response's harmonics "
                         f"{response.harmonics}")
    om = finite_array("omega", omega, positive=True).ravel()
    w = finite("half_width", half_width)
    if not 0.0 < w < 1.0:
        raise ValueError(f"half_width = {half_width!r}: must be in (0, 1)")
    model = response.models[response.harmonics.index(k)]
    share = math.cos(response.misalignment) if k == 0 else math.sin(response.misalignment)
    # the model is per newton of Delta F along the thrust line: its share is in its load
    scale = float(response.amplitude[0]) * response.F0 * (share != 0.0)
    node = np.asarray(response.station_nodes, dtype=int)
    n, s = om.size, node.size
    if om.size == 0 or scale == 0.0:
        return np.zeros(n), om.copy(), np.zeros(n, dtype=int)
    steps = np.arange(-CLUSTER, CLUSTER + 1) / CLUSTER
    peak, at, station = np.zeros(n), np.zeros(n), np.zeros(n, dtype=int)
    for c, centre in enumerate(om):  # a few tracked modes: one window each
        grid = centre * (1.0 + w * steps)
        mag = grid[:, None] ** 2 * np.abs(model.response(grid)[:, node, 0])  # |a| = W^2 |u|
        value, place = _refined_max(model, grid, mag, node, np.zeros(s, dtype=int), 2)
        station[c] = int(np.argmax(value))
        peak[c], at[c] = scale * value[station[c]], place[station[c]]
    return peak, at, station


@dataclass(frozen=True)
class ModePeak:
    """The forced peak near one mode: the largest steady acceleration over the stations within
    the mode's window (:func:`mode_peaks`).

    Attributes
    ----------
    k : int
        Circumferential harmonic (0 axial, 1 lateral).
    omega : float
        The mode's natural frequency in the forced model's basis (rad/s).
    Omega : float
        Where the peak is (rad/s).
    acceleration : float
        Peak acceleration amplitude (m/s^2).
    station : int
        Index into ``ForcedResponse.stations`` of the station where it is.
    """

    k: int
    omega: float
    Omega: float
    acceleration: float
    station: int


def mode_peaks(response: ForcedResponse, *, omega_min: float, omega_max: float
               ) -> tuple[ModePeak, ...]:
    """Per forced harmonic of a sweep, one :class:`ModePeak` per basis mode with its frequency
    in [omega_min, omega_max] that the thrust forces (participation f^2 at least
    :data:`MIN_PARTICIPATION` of its harmonic's largest): :func:`window_peaks` over omega (1 -+
    min(PEAK_WINDOW zeta, 1/2)), kept where that peak lies in the range; by harmonic, then
    frequency. Every resonance in the range, also one that is no station's largest peak.
    () for a spectrum.

    Parameters
    ----------
    response : ForcedResponse
        The forced response.
    omega_min, omega_max : float
        The range (rad/s), 0 < omega_min <= omega_max.
    """
    if not isinstance(response, ForcedResponse):
        raise ValueError("response: must be a ForcedResponse")
    lo, hi = finite("omega_min", omega_min), finite("omega_max", omega_max)
    if not 0.0 < lo <= hi:
        raise ValueError(f"omega_min, omega_max = {lo!r}, {hi!r}: must satisfy 0 < min <= max")
    if response.combination != "sweep":
        return ()
    w = peak_half_width(float(response.damping_ratio))
    out = []
    for k, model in zip(response.harmonics, response.models, strict=True):
        basis = model.omega_modes[model.n_rigid:]
        f2 = model.load[model.n_rigid:] ** 2
        if not basis.size or not np.any(f2 > 0.0):
            continue
        keep = (basis >= lo) & (basis <= hi) & (f2 >= MIN_PARTICIPATION * float(f2.max()))
        if not keep.any() or w <= 0.0:
            continue
        peak, at, station = window_peaks(response, k=int(k), omega=basis[keep], half_width=w)
        out += [ModePeak(k=int(k), omega=float(om), Omega=float(a), acceleration=float(g),
                         station=int(st))
                for om, g, a, st in zip(basis[keep], peak, at, station, strict=True)
                if lo <= a <= hi and g > 0.0]
    return tuple(out)


def peak_half_width(zeta: float) -> float:
    """The relative half-width of the window in which a mode's forced peak is sought:
    min(PEAK_WINDOW zeta, 1/2) (:data:`PEAK_WINDOW`).

    Parameters
    ----------
    zeta : float
        The modal damping ratio, >= 0.
    """
    return min(PEAK_WINDOW * nonnegative("zeta", zeta), 0.5)
