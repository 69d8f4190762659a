"""The data of every figure, computed by the pipeline (compute -> data -> plot): the
Ince-Strutt chart, the Campbell diagram, the (Omega, gamma) band charts, the beam mode
shapes and the shells' nodal lines; the grids are named once here.

References: Abramowitz & Stegun, 20.2, fig. 20.1; Tech Memo 104, eqs. (4.2-3)..(4.2-5),
(5.3-2d), (5.3-3d), (7.3-1)..(7.3-35), (C-1), (C-6)..(C-9), Fig. 4; V. V. Bolotin, 1964, ch. 3.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..checks import count, positive
from ..floquet import region_boundaries, transition_curves
from .beam import free_free_eigenvalues, mode_shape
from .beam_action import BAND_OMEGA_BAR_MIN, beam_system, modal_damping
from .geometry import MassProperties
from .pitch import (
    PITCH_MAX_TONGUE,
    PITCH_MODE,
    PitchResult,
    pitch_band_edges,
    pitch_tongue_omega_bound,
)
from .shell import ShellFrequencies
from .stability import StabilityTable, excitation, excitation_curves

__all__ = ["INCE_STRUTT_Q_POINTS", "INCE_STRUTT_ORDERS", "CAMPBELL_POINTS", "CAMPBELL_S_MAX",
           "BAND_CHART_GAMMA_MAX", "PITCH_BAND_CHART_LEVELS", "BEAM_ACTION_CHART_LEVELS",
           "BEAM_ACTION_CHART_RTOL", "BEAM_ACTION_CHART_MAX_ORDER", "BEAM_ACTION_CHART_STEP_PHASE",
           "VEHICLE_CHART_LEVELS", "VEHICLE_CHART_GAMMA_MAX", "MODE_SHAPE_POINTS",
           "MODE_SHAPE_COUNT", "InceStruttData", "ince_strutt_data", "CampbellData",
           "campbell_data", "RegionCurves", "BandChart", "pitch_band_chart", "beam_action_chart",
           "BeamModeShapes", "beam_mode_shapes", "NodalPattern", "nodal_lines",
           "nodal_pattern_data", "FigureData"]

#: q points of the Ince-Strutt transition curves, uniform on [0, q_max].
INCE_STRUTT_Q_POINTS = 300
#: Highest order r of the transition curves a_r, b_r drawn.
INCE_STRUTT_ORDERS = 3
#: Points of the Campbell diagram, logarithmic over the case's Omega range.
CAMPBELL_POINTS = 600
#: Harmonics |s| <= this of the (alpha_r + s) curves drawn in the Campbell diagram (all are
#: solved for in the stability table).
CAMPBELL_S_MAX = 2
#: Largest gamma of the (Omega, gamma) band charts (pitch and beam action).
BAND_CHART_GAMMA_MAX = 0.9
#: gamma levels of the pitch band chart, uniform on [0, BAND_CHART_GAMMA_MAX].
PITCH_BAND_CHART_LEVELS = 46
#: gamma levels of the beam-action band chart (``n_gamma`` of
#: :func:`flexbooster.floquet.region_boundaries`, the tip at gamma = 0 included).
BEAM_ACTION_CHART_LEVELS = 4
#: Boundary tolerance of the chart (relative): regions narrower than this are not drawn.
BEAM_ACTION_CHART_RTOL = 1e-4
#: Resonance orders j drawn in the beam-action chart (j = 1: Omega = 2 omega_i,
#: omega_i +- omega_k).
BEAM_ACTION_CHART_MAX_ORDER = 1
#: Monodromy step parameter of the chart's boundary search (see
#: :func:`flexbooster.floquet.instability_regions`).
BEAM_ACTION_CHART_STEP_PHASE = 0.25
#: gamma levels of the vehicle's (Omega, gamma) region chart (``n_gamma`` of
#: :func:`flexbooster.dynamics.vehicle_regions`, the tip at the critical gamma included), up to
#: :data:`VEHICLE_CHART_GAMMA_MAX`.
VEHICLE_CHART_LEVELS = 4
#: Largest gamma of the vehicle's region chart, raised to the case's gamma when that is larger
#: (the search cost grows fast with gamma: at 0.5 the memo vehicle's 20-mode search takes a
#: minute where the stability certificate fails, at 0.2 the certificate holds for every k and
#: it takes 0.3 s).
VEHICLE_CHART_GAMMA_MAX = 0.2
#: Points per beam mode shape.
MODE_SHAPE_POINTS = 400
#: Beam modes drawn (at most the truncation N).
MODE_SHAPE_COUNT = 4


def _arrays(obj: Any) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for key, value in obj.__dict__.items():
        if isinstance(value, np.ndarray):
            out[key] = value.tolist()
        elif isinstance(value, dict):
            out[key] = {k: np.asarray(v).tolist() for k, v in value.items()}
        else:
            out[key] = value
    return out


@dataclass(frozen=True)
class InceStruttData:
    """The Ince-Strutt chart: transition curves and the operating path (memo 4.2).

    Attributes
    ----------
    q, curves : numpy.ndarray, dict
        The q grid and "a0".."a{r}", "b1".."b{r}" on it (tongue r between b_r and a_r).
    a_path, q_path, path_stable : numpy.ndarray
        The path (a, |q|) of eq. (4.2-4) and beta real on it.
    """

    q: np.ndarray
    curves: dict
    a_path: np.ndarray
    q_path: np.ndarray
    path_stable: np.ndarray

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready mapping (plain lists)."""
        return _arrays(self)


def ince_strutt_data(pitch: PitchResult, *, n_q: int = INCE_STRUTT_Q_POINTS,
                     r_max: int = INCE_STRUTT_ORDERS) -> InceStruttData:
    """Transition curves over the q range of the operating path, and the path (A&S 20.2; memo
    4.2-3..4.2-5).

    Parameters
    ----------
    pitch : PitchResult
        The rigid-body pitch (a, q along the grid).
    n_q : int
        q points, on [0, max(0.1, 1.3 max |q|)], 2..100000.
    r_max : int
        Highest order, 1..50.
    """
    n_q = count("n_q", n_q, 2, 100_000)
    r_max = count("r_max", r_max, 1, 50)
    q_path = np.abs(pitch.q)
    q_max = max(0.1, 1.3 * float(np.max(q_path)))
    q = np.linspace(0.0, q_max, n_q)
    return InceStruttData(q=q, curves=transition_curves(q, r_max), a_path=pitch.a.copy(),
                          q_path=q_path, path_stable=pitch.stable.copy())


@dataclass(frozen=True)
class CampbellData:
    """The Campbell diagram: excitation curves (memo 7.3), shell frequencies and the roots.

    Attributes
    ----------
    Omega_bar, curves, family, s : numpy.ndarray
        Omega / omega_1 (n,), the drawn curves (C, n), their family (memo 7.4) and harmonic.
    shell_omega_bar, root_Omega_bar, root_shell_omega_bar, root_active : numpy.ndarray
        Shell frequencies, the roots of the stability table, active forcing at each root.
    omega_1 : float
        Reference frequency (rad/s); frequencies are in its units.
    """

    Omega_bar: np.ndarray
    curves: np.ndarray
    family: np.ndarray
    s: np.ndarray
    shell_omega_bar: np.ndarray
    root_Omega_bar: np.ndarray
    root_shell_omega_bar: np.ndarray
    root_active: np.ndarray
    omega_1: float

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready mapping (plain lists)."""
        return _arrays(self)


#: Families drawn in the Campbell diagram (memo 7.4 numbering).
_CAMPBELL_FAMILIES = (7, 12, 8, 9, 10, 11, 13, 3)


def campbell_data(*, params: Any, omega_range: tuple[float, float], omega_1: float,
                  shell: ShellFrequencies, table: StabilityTable, R: int, S: int,
                  n_points: int = CAMPBELL_POINTS, s_max: int = CAMPBELL_S_MAX) -> CampbellData:
    """Excitation curves (memo 7.3) on a logarithmic Omega grid, with the shell frequencies and
    roots.

    Parameters
    ----------
    params : callable
        ``params(Omega_bar) -> (beta, alpha)``, the pipeline's parameter function.
    omega_range : (float, float)
        Omega range (rad/s).
    omega_1 : float
        Reference frequency (rad/s).
    shell, table : ShellFrequencies, StabilityTable
        The shell frequencies and the roots.
    R, S : int
        Beam exponents and harmonics of the case.
    n_points : int
        Omega points, 2..100000.
    s_max : int
        Harmonics |s| <= s_max of the (alpha_r + s) curves drawn.
    """
    n_points = count("n_points", n_points, 2, 100_000)
    s_max = count("s_max", s_max, 0, None)
    x = np.geomspace(omega_range[0], omega_range[1], n_points) / omega_1
    beta, alpha = params(x)
    ec = excitation_curves(R, S)
    keep = np.isin(ec.family, _CAMPBELL_FAMILIES) & (np.abs(ec.s) <= s_max)
    E = excitation(ec, x, beta, alpha)[keep]
    return CampbellData(
        Omega_bar=x, curves=E, family=ec.family[keep], s=ec.s[keep],
        shell_omega_bar=shell.omega_bar.copy(), root_Omega_bar=table.Omega_bar.copy(),
        root_shell_omega_bar=table.shell_omega_bar.copy(), root_active=table.active.copy(),
        omega_1=float(omega_1))


@dataclass(frozen=True)
class RegionCurves:
    """The boundary curves of one instability region in the (Omega, gamma) plane.

    Attributes
    ----------
    label : str
        "tongue r" (pitch) or "kind modes j" (beam action).
    gamma, omega_lo, omega_hi : numpy.ndarray
        Amplitudes ascending from the tip (the critical gamma) and the edges (rad/s).
    key : tuple
        (kind, mode indices, order) of the region, as the :class:`~flexbooster.bands.Band` of
        the same region has them (``kind``, ``modes[i].index``, ``order``); () if unknown.
    """

    label: str
    gamma: np.ndarray
    omega_lo: np.ndarray
    omega_hi: np.ndarray
    key: tuple = ()

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready mapping (plain lists)."""
        return _arrays(self)


@dataclass(frozen=True)
class BandChart:
    """Instability regions traced from their boundaries, in Omega (rad/s), against the case's
    gamma.

    Attributes
    ----------
    title : str
        What is charted.
    regions : tuple of RegionCurves
        The traced regions.
    gamma_operating, omega_min, omega_max, gamma_max : float
        The case's gamma and Omega range (rad/s), the top of the chart.
    """

    title: str
    regions: tuple
    gamma_operating: float
    omega_min: float
    omega_max: float
    gamma_max: float

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready mapping (plain lists and floats)."""
        return {"title": self.title, "regions": [r.to_dict() for r in self.regions],
                "gamma_operating": float(self.gamma_operating),
                "omega_min": float(self.omega_min), "omega_max": float(self.omega_max),
                "gamma_max": float(self.gamma_max)}


def pitch_band_chart(model: Any, *, n_gamma: int = PITCH_BAND_CHART_LEVELS,
                     gamma_max: float = BAND_CHART_GAMMA_MAX) -> BandChart:
    """The pitch tongues in the (Omega, gamma) plane: one region per tongue reaching the range at
    gamma_max, edges of :func:`flexbooster.memo.pitch.pitch_band_edges`.

    Parameters
    ----------
    model : BoosterModel
        The derived model (omega_psi, gamma, Omega range, pitch damping ratio).
    n_gamma : int
        gamma levels, uniform on [0, gamma_max], 2..1000.
    gamma_max : float
        Largest gamma, 0 < gamma_max < 1.
    """
    n_gamma = count("n_gamma", n_gamma, 2, 1000)
    gamma_max = positive("gamma_max", gamma_max)
    if gamma_max >= 1.0:
        raise ValueError(f"gamma_max = {gamma_max!r}: must be < 1")
    lo, hi = model.omega_range
    w, zeta = float(model.omega_psi), float(model.pitch_damping_ratio)
    levels = np.linspace(0.0, gamma_max, n_gamma)
    regions = []
    if w > 0.0:
        for r in range(1, PITCH_MAX_TONGUE + 1):
            if pitch_tongue_omega_bound(w, gamma_max, tongue=r, damping_ratio=zeta) < lo:
                break  # this and every higher tongue lie below the range (no solve)
            top = pitch_band_edges(w, gamma_max, tongue=r, damping_ratio=zeta)
            if top is None:  # below round-off (or the critical gamma): so are higher tongues
                break
            if top[1] < lo:  # this and every higher tongue lie below the range
                break
            if top[0] > hi:
                continue
            rows = [(g, *e) for g in levels
                    if (e := pitch_band_edges(w, float(g), tongue=r, damping_ratio=zeta))]
            if rows:
                g_, a_, b_ = (np.array(c) for c in zip(*rows, strict=True))
                regions.append(RegionCurves(label=f"tongue {r}", gamma=g_, omega_lo=a_,
                                            omega_hi=b_,
                                            key=("simple", (PITCH_MODE.index,), r)))
    return BandChart(title="Rigid-body pitch: Mathieu tongues", regions=tuple(regions),
                     gamma_operating=float(model.gamma), omega_min=lo, omega_max=hi,
                     gamma_max=gamma_max)


def beam_action_chart(model: Any, *, n_gamma: int = BEAM_ACTION_CHART_LEVELS,
                      gamma_max: float = BAND_CHART_GAMMA_MAX,
                      rtol: float = BEAM_ACTION_CHART_RTOL,
                      max_order: int | None = BEAM_ACTION_CHART_MAX_ORDER,
                      step_phase: float = BEAM_ACTION_CHART_STEP_PHASE) -> BandChart:
    """The beam-action regions in the (Omega, gamma) plane at gamma_max, above max(omega_min,
    omega_1 / 4), edges in rad/s (Bolotin 1964, ch. 1, sec. 6).

    Parameters
    ----------
    model : BoosterModel
        The derived model (Omega range, beam-action system, damping ratios).
    n_gamma : int
        Amplitude levels of :func:`flexbooster.floquet.region_boundaries`, 2..1000.
    gamma_max : float
        Largest gamma, 0 < gamma_max < 1.
    rtol, max_order, step_phase
        Edge tolerance (narrower regions not drawn), highest order, monodromy accuracy.
    """
    n_gamma = count("n_gamma", n_gamma, 2, 1000)
    gamma_max = positive("gamma_max", gamma_max)
    if gamma_max >= 1.0:
        raise ValueError(f"gamma_max = {gamma_max!r}: must be < 1")
    lo, hi = model.omega_range
    system = beam_system(model)
    w1 = float(system.omega_1)
    n = system.Lambda.size
    C = modal_damping(system, beam_ratio=model.beam_damping_ratio,
                      pitch_ratio=model.pitch_damping_ratio)
    lo_search = max(lo, BAND_OMEGA_BAR_MIN * w1)  # as the band search of the pipeline
    curves = () if not hi > lo_search else region_boundaries(
                               np.eye(n), C, system.A0, -system.B, gamma_max=gamma_max,
                               omega_min=lo_search / w1, omega_max=hi / w1, n_gamma=n_gamma,
                               rtol=rtol, max_order=max_order, step_phase=step_phase,
                               max_candidates=5_000_000)
    regions = tuple(
        RegionCurves(label=f"{c.kind} {'+'.join(str(m) for m in c.modes)} j={c.order}",
                     gamma=np.asarray(c.gamma, dtype=float),
                     omega_lo=np.asarray(c.omega_lo) * w1,  # Omega_bar -> rad/s
                     omega_hi=np.asarray(c.omega_hi) * w1,
                     key=(str(c.kind), tuple(int(m) for m in c.modes), int(c.order)))
        for c in curves if c.kind != "steady")
    return BandChart(title="Beam action: instability regions", regions=regions,
                     gamma_operating=float(model.gamma), omega_min=lo, omega_max=hi,
                     gamma_max=gamma_max)


@dataclass(frozen=True)
class BeamModeShapes:
    """Free-free beam mode shapes phi_n(zeta) (appendix C).

    Attributes
    ----------
    zeta, phi, lambda_n : numpy.ndarray
        Coordinate (n,), 0 at the aft edge, 2 at the nose; shapes (N, n); eigenvalues (N,).
    zeta_junction, zeta_cm : float
        zeta of the junction (C-8) and of the CM.
    half_length : float
        L (m): the station x = L zeta from the aft edge (C-6 with xi_bar = (x - x_cm) / L,
        d4 = L - x_cm); 0 if unknown.
    """

    zeta: np.ndarray
    phi: np.ndarray
    lambda_n: np.ndarray
    zeta_junction: float
    zeta_cm: float
    half_length: float = 0.0

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready mapping (plain lists)."""
        return _arrays(self)


def beam_mode_shapes(mass: MassProperties, *, N: int = MODE_SHAPE_COUNT,
                     n_points: int = MODE_SHAPE_POINTS) -> BeamModeShapes:
    """phi_n(zeta), n = 1..N, with the junction and the CM (memo 4.1-2, C-1, C-6..C-9).

    Parameters
    ----------
    mass : MassProperties
        Mass properties (L, d1, d4 in m).
    N : int
        Modes, 1..500.
    n_points : int
        Points per mode, 2..100000.
    """
    N = count("N", N, 1, 500)
    n_points = count("n_points", n_points, 2, 100_000)
    zeta = np.linspace(0.0, 2.0, n_points)
    phi = np.stack([mode_shape(n, zeta) for n in range(1, N + 1)])  # eq. (C-1)
    L = float(mass.L)
    return BeamModeShapes(zeta=zeta, phi=phi, lambda_n=free_free_eigenvalues(N),
                          zeta_junction=(L - (mass.d4 - mass.d1)) / L,  # eq. (C-8)
                          zeta_cm=1.0 - mass.d4 / L, half_length=L)


def nodal_lines(j: int, k: int) -> tuple[np.ndarray, np.ndarray]:
    """Nodal lines of sin(j pi s / 2) cos(k theta) (memo 5.3-2d, 5.3-3d): circles s = 2 i / j,
    i = 0..j (s in [0, 2]) and generators theta = (2 i + 1) pi / (2 k) (rad; none for k = 0).

    Parameters
    ----------
    j, k : int
        Axial (>= 1) and circumferential (>= 0) indices.
    """
    j = count("j", j, 1, None)
    k = count("k", k, 0, None)
    s = 2.0 * np.arange(j + 1) / j  # sin(j pi s / 2) = 0, eq. (5.3-2d)
    theta = (2.0 * np.arange(2 * k) + 1.0) * np.pi / (2.0 * k) if k else np.empty(0)  # cos k theta
    return s, theta


@dataclass(frozen=True)
class NodalPattern:
    """The nodal pattern of one shell mode on its unrolled cylinder (memo Fig. 4).

    Attributes
    ----------
    cylinder, j, k : int
        The mode.
    radius, half_length, hz : float
        R_d, L_d (m) and the mode's lowest frequency (Hz; 0 if not in the table).
    s_nodes, theta_nodes, sign : numpy.ndarray
        Nodal circles (s in [0, 2]), generators (rad), the sign of w in each cell.
    """

    cylinder: int
    j: int
    k: int
    radius: float
    half_length: float
    s_nodes: np.ndarray
    theta_nodes: np.ndarray
    sign: np.ndarray
    hz: float

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready mapping (plain lists)."""
        return _arrays(self)


def nodal_pattern_data(shell: ShellFrequencies, *, cylinder: int, j: int | None = None,
                       k: int | None = None, radius: float, half_length: float) -> NodalPattern:
    """The nodal pattern of mode (j, k) of a cylinder (memo 5.3-2d, 5.3-3d, Fig. 4).

    Parameters
    ----------
    shell : ShellFrequencies
        The frequency table.
    cylinder : int
        1 or 2.
    j, k : int, optional
        The mode (default its lowest mode with j, k >= 1).
    radius, half_length : float
        R_d, L_d (m), > 0.
    """
    d = count("cylinder", cylinder, 1, 2)
    radius = positive("radius", radius)
    half_length = positive("half_length", half_length)
    if j is None or k is None:
        rows = np.flatnonzero((shell.cylinder == d) & (shell.j >= 1) & (shell.k >= 1))
        if rows.size == 0:
            rows = np.flatnonzero((shell.cylinder == d) & (shell.j >= 1))
        if rows.size == 0:
            raise ValueError(f"shell: cylinder {d} has no mode with j >= 1")
        lowest = rows[np.argmin(shell.hz[rows])]
        j, k = int(shell.j[lowest]), int(shell.k[lowest])
    s_nodes, theta_nodes = nodal_lines(j, k)
    theta_edges = np.concatenate(([0.0], theta_nodes, [2.0 * np.pi]))
    s_mid = 0.5 * (s_nodes[1:] + s_nodes[:-1])
    theta_mid = 0.5 * (theta_edges[1:] + theta_edges[:-1])
    w = np.sin(j * np.pi * s_mid[None, :] / 2.0) * np.cos(k * theta_mid[:, None])  # (5.3-2d)
    rows = np.flatnonzero(shell.select(cylinder=d, j=j, k=k))
    return NodalPattern(cylinder=d, j=int(j), k=int(k), radius=float(radius),
                        half_length=float(half_length), s_nodes=s_nodes,
                        theta_nodes=theta_nodes, sign=np.sign(w),
                        hz=float(np.min(shell.hz[rows])) if rows.size else 0.0)


@dataclass(frozen=True)
class FigureData:
    """Everything the figures draw (results.json ``figures``).

    Attributes
    ----------
    ince_strutt, beam_modes, nodal_patterns
        The Ince-Strutt chart, the beam mode shapes, one nodal pattern per cylinder.
    beam_action_chart, campbell, pitch_band_chart : optional
        None when their stage did not run.
    """

    ince_strutt: InceStruttData
    beam_modes: BeamModeShapes
    nodal_patterns: tuple
    beam_action_chart: BandChart | None = None
    campbell: CampbellData | None = None
    pitch_band_chart: BandChart | None = None

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready mapping; the grids are named in :mod:`flexbooster.memo.charts`."""
        return {
            "ince_strutt": self.ince_strutt.to_dict(),
            "beam_modes": self.beam_modes.to_dict(),
            "nodal_patterns": [p.to_dict() for p in self.nodal_patterns],
            "beam_action_chart": (None if self.beam_action_chart is None
                                  else self.beam_action_chart.to_dict()),
            "campbell": None if self.campbell is None else self.campbell.to_dict(),
            "pitch_band_chart": (None if self.pitch_band_chart is None
                                 else self.pitch_band_chart.to_dict()),
        }
