"""The most dangerous thrust-frequency bands of an analysis, across every mechanism (memo 4.1,
4.2, 7.3 and the vehicle's regions): :func:`danger_summary` ranks their
:class:`flexbooster.bands.Band` and gives one verdict per mechanism, reading the
:class:`flexbooster.bands.SearchGap` (a mechanism with a gap is never "stable"). The first
screen and the danger map draw this and nothing else.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from .bands import (
    CRITICAL_DAMPING_COUNT,
    MECHANISMS,
    NEGLIGIBLE_GROWTH,
    Band,
    SearchGap,
    gaps_text,
)
from .dynamics import STANDARD_GRAVITY
from .flight import FlightEvent
from .floquet import tongue_critical_damping

__all__ = ["RankedBand", "DangerSummary", "Verdict", "ResponsePeak", "FlightVerdict",
           "STEADY_CAUSE", "NEGLIGIBLE_GROWTH", "NEGLIGIBLE_AMPLIFICATION",
           "UNSTABLE_AMPLIFICATION", "UNSTABLE_E_FOLDING", "AMPLIFICATION_EXPONENT_MAX",
           "FIRST_SCREEN_WORDS", "MEASURES", "band_measures", "band_status", "danger_bands",
           "danger_summary", "edges_text", "g_text", "hz_text", "mechanism_verdicts",
           "overall_verdict", "event_status", "flight_verdict", "axial_resonance_peaks",
           "merge_responses"]

_KIND_WORDS = {"simple": "simple", "sum": "sum combination",
               "difference": "difference combination"}
#: The cause of a "steady" band: the system under the steady thrust alone (gamma = 0) is not
#: stable (flutter or divergence, Beal 1965; a slow growth of the rigid pitch), not parametric.
STEADY_CAUSE = "unstable without pulsation"


#: With a duration T: amplification exp(sigma T) below which a band is negligible (the motion
#: grows less than 10 % over the whole excitation).
NEGLIGIBLE_AMPLIFICATION = 1.1
#: With a duration T: amplification exp(sigma T) above which an open band is unstable.
UNSTABLE_AMPLIFICATION = 10.0
#: Without a duration: e-folding time 1 / sigma (s) below which an open band is unstable.
UNSTABLE_E_FOLDING = 10.0
#: Largest sigma T whose exp is stored (exp(700) ~ 1e304); above it amplification is None.
AMPLIFICATION_EXPONENT_MAX = 700.0
#: The mechanisms in engineering words, for the first screen (the memo's section numbers
#: stay in :data:`flexbooster.bands.MECHANISMS` and the detailed sections).
FIRST_SCREEN_WORDS = {"pitch": "rigid-body pitch", "beam_action": "beam bending under thrust",
                      "vehicle": "vehicle parametric regions",
                      "resonance": "shell resonances"}


def band_measures(band: Band, *, gamma: float, duration: float | None,
                  modal_ratio: float = 0.0, critical_damping: bool = True) -> Band:
    """The band with its margin critical_gamma / gamma (where gamma > 0 and the band is
    damped), its growth exponent sigma T and amplification exp(sigma T) over the duration T
    (None without one) and, for a rigid-pitch tongue that is not negligible
    (:func:`band_status`), its critical damping ratio; a resonance with its damped steady
    amplitude.

    A resonance of memo 7 grows undamped like (|G| / 2 omega) t (docs/theory/severity.md: the
    severity v, m/s); with modal damping zeta its steady amplitude is |G| / (2 zeta omega^2) =
    v / (zeta omega) (m) and its acceleration that times omega^2, omega the resonant mode's
    frequency (rad/s; Meirovitch 1986, sec. 3.3).

    Parameters
    ----------
    band : Band
        A band of any mechanism.
    gamma : float
        The case's pulsation amplitude, >= 0.
    duration : float or None
        Duration of the excitation T (s), > 0, or None.
    modal_ratio : float
        Modal damping ratio zeta of the elastic modes, 0 <= zeta < 1.
    critical_damping : bool
        Compute a rigid-pitch tongue's critical damping ratio (False: left None;
        :func:`danger_summary` asks it for the CRITICAL_DAMPING_COUNT fastest only).
    """
    if band.mechanism == "resonance":
        w = band.modes[0].omega if band.modes else None
        if modal_ratio <= 0.0 or band.severity is None or not w:
            return band
        amplitude = band.severity / (modal_ratio * w)  # v / (zeta omega)
        return dataclasses.replace(band, steady_amplitude=amplitude,
                                   steady_acceleration=amplitude * w * w)
    margin = band.critical_gamma / gamma if gamma > 0.0 and band.critical_gamma > 0.0 else None
    exponent = amplification = None
    if duration is not None:
        exponent = band.growth_rate_max * float(duration)  # sigma T
        if exponent <= AMPLIFICATION_EXPONENT_MAX:
            amplification = math.exp(exponent)
    zeta_cr = band.critical_damping_ratio
    if zeta_cr is None and critical_damping and band.mechanism == "pitch" and \
            0.0 < gamma < 1.0 and band_status(band, duration=duration) != "negligible":
        # Mathieu tongue r: the smallest pitch damping closing it (Bolotin 1964, sec. 6);
        # only where the band counts (each costs a few Hill maximisations)
        zeta_cr = tongue_critical_damping(band.order, gamma)
    return dataclasses.replace(band, margin=margin, growth_exponent=exponent,
                               amplification=amplification, critical_damping_ratio=zeta_cr)


def band_status(band: Band, *, duration: float | None, modal_ratio: float = 0.0) -> str:
    """How a band counts in the verdict (docs/theory/verdicts.md): ``"unstable"``,
    ``"marginal"``, ``"negligible"`` or, for a damped forced resonance, ``"bounded"``.

    A region: negligible when sigma < :data:`NEGLIGIBLE_GROWTH` or (with T) exp(sigma T) <
    :data:`NEGLIGIBLE_AMPLIFICATION`; unstable when exp(sigma T) > :data:`UNSTABLE_AMPLIFICATION`
    or (without T) 1 / sigma < :data:`UNSTABLE_E_FOLDING`; marginal otherwise. A resonance of
    memo 7: unstable (secular growth) without modal damping, bounded with it.

    Parameters
    ----------
    band : Band
        The band (with :func:`band_measures` applied where a duration is given).
    duration : float or None
        Duration of the excitation T (s), or None.
    modal_ratio : float
        The case's modal damping ratio of the elastic modes.
    """
    if band.mechanism == "resonance":
        return "bounded" if modal_ratio > 0.0 else "unstable"
    sigma = band.growth_rate_max
    if sigma < NEGLIGIBLE_GROWTH:
        return "negligible"
    if duration is not None:
        exponent = sigma * float(duration)
        if exponent < math.log(NEGLIGIBLE_AMPLIFICATION):
            return "negligible"
        return "unstable" if exponent > math.log(UNSTABLE_AMPLIFICATION) else "marginal"
    return "unstable" if 1.0 / sigma < UNSTABLE_E_FOLDING else "marginal"


#: The forcing of a memo resonance in engineering words, by family (memo 7.3; the memo's terms
#: stay in the severity table, docs/theory/severity.md).
_FORCING_WORDS = {1: "pitch acceleration", 2: "beam bending", 3: "thrust pulsation at the aft edge",
                  4: "pitch rate (centrifugal)", 5: "pitch rate (centrifugal)",
                  6: "pitch rate (centrifugal)", 7: "pitch and gimbal side force",
                  8: "pulsating gimbal side force", 9: "pulsating gimbal side force",
                  10: "pitch rate (centrifugal)", 11: "pitch rate (centrifugal)",
                  12: "pitch rate (centrifugal)", 13: "beam bending"}


def _cause(band: Band) -> str:
    """The mechanism of a band in words."""
    if band.mechanism == "resonance":
        return f"forced resonance: {_FORCING_WORDS.get(band.order, band.cause)}"
    if band.mechanism == "pitch":
        return f"instability region (Mathieu tongue {band.order})"
    model = "; vehicle model" if band.mechanism == "vehicle" else ""
    if band.kind == "steady":
        return f"{STEADY_CAUSE} (the steady thrust alone, gamma = 0{model})"
    return f"instability region ({_KIND_WORDS[band.kind]}, order {band.order}{model})"


def _mode_text(band: Band) -> str:
    """The modes of a band in words (a vehicle region: "k = 2: radial 0 + radial 2")."""
    if band.mechanism == "vehicle":
        return f"k = {band.k}" + (f": {band.mode_text}" if band.modes else "")
    return band.mode_text


#: The measures of a band (:func:`band_measures`) that a ranked band carries into results.json.
MEASURES = ("e_folding_s", "growth_exponent", "amplification", "critical_gamma", "margin",
            "critical_damping_ratio", "steady_amplitude", "steady_acceleration")


@dataclass(frozen=True)
class RankedBand:
    """A band of the danger ranking: the band and whether the operating range reaches it.

    Attributes
    ----------
    band : Band
        The band (Omega in rad/s).
    in_operating_range : bool
        True when the band overlaps the case's operating range [omega_min, omega_max].
    also : tuple of str
        Other mechanisms that found the same physical band (listed once, under ``band``).
    """

    band: Band
    in_operating_range: bool
    also: tuple[str, ...] = ()

    @property
    def mechanisms(self) -> tuple[str, ...]:
        """Every mechanism that found the band, its own first."""
        return (self.band.mechanism, *self.also)

    @property
    def mechanism(self) -> str:
        """The band's mechanism (a key of :data:`flexbooster.bands.MECHANISMS`)."""
        return self.band.mechanism

    @property
    def Omega_lo(self) -> float:
        """Lower edge (rad/s)."""
        return self.band.Omega_lo

    @property
    def Omega_hi(self) -> float:
        """Upper edge (rad/s)."""
        return self.band.Omega_hi

    @property
    def hz(self) -> tuple[float, float]:
        """The edges in Hz."""
        return self.band.hz

    @property
    def growth_rate(self) -> float | None:
        """Largest growth rate inside (1/s); None for a resonance."""
        return None if self.band.mechanism == "resonance" else self.band.growth_rate_max

    @property
    def severity(self) -> float | None:
        """Severity of a resonance (m/s); None for a region."""
        return self.band.severity

    @property
    def mode_text(self) -> str:
        """The modes in words."""
        return _mode_text(self.band)

    @property
    def cause_text(self) -> str:
        """The mechanism in words (and the other mechanisms that found the band)."""
        if "pitch" in self.also:
            return f"{_cause(self.band)}; also the rigid-body pitch's Mathieu tongue " \
                   f"{self.band.order}"
        return _cause(self.band)

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready mapping (plain floats, str, bool; None kept)."""
        lo_hz, hi_hz = self.hz
        return {"mechanism": self.mechanism, "mechanisms": list(self.mechanisms),
                "Omega_lo": float(self.Omega_lo),
                "Omega_hi": float(self.Omega_hi), "Omega_lo_hz": float(lo_hz),
                "Omega_hi_hz": float(hi_hz),
                "growth_rate": None if self.growth_rate is None else float(self.growth_rate),
                "severity": None if self.severity is None else float(self.severity),
                "mode_text": self.mode_text, "cause_text": self.cause_text,
                "in_operating_range": bool(self.in_operating_range),
                **{key: value for key, value in self.band.to_dict().items() if key in MEASURES}}


@dataclass(frozen=True)
class ResponsePeak:
    """A bounded forced response of the vehicle in the ranking: its largest acceleration at
    one resonance, with the station, Omega and internal load (docs/theory/verdicts.md).

    Attributes
    ----------
    source : str
        ``"forced response"`` (the steady response at the stations, results
        ``forced_response``) or ``"axial resonance"`` (a k = 0 mode's single-mode resonant
        amplitude at the aft edge, ``vehicle_regions.forced_axial``).
    k : int
        Circumferential harmonic (0 axial, 1 lateral).
    Omega : float
        Thrust-oscillation frequency of the peak (rad/s).
    acceleration_g : float
        Peak acceleration amplitude (units of g = :data:`STANDARD_GRAVITY`), >= 0.
    station : str
        Where the acceleration peaks.
    station_m : float
        Its distance from the aft edge (m).
    displacement_m : float or None
        Displacement amplitude there (m).
    modes : str
        The modes in words ("k = 0", "k = 0 mode 1 (axial, order 1)").
    load_quantity, load_unit : str or None
        The largest internal load near this Omega ("axial force", N; "bending moment", N m).
    load, load_station_m : float or None
        Its amplitude and where along the vehicle (m from the aft edge).
    in_operating_range : bool
        Omega lies in the case's operating range.
    also : tuple of str
        The same resonance found by another source (listed once, here).
    at_range_end : bool
        Omega is an end of the computed Omega range: the response is largest there, still
        rising (larger beyond the range), not at a peak.
    """

    source: str
    k: int
    Omega: float
    acceleration_g: float
    station: str
    station_m: float
    displacement_m: float | None = None
    modes: str = ""
    load_quantity: str | None = None
    load_unit: str | None = None
    load: float | None = None
    load_station_m: float | None = None
    in_operating_range: bool = True
    also: tuple[str, ...] = ()
    at_range_end: bool = False

    def __post_init__(self) -> None:
        for name in ("Omega", "acceleration_g", "station_m"):
            v = float(getattr(self, name))
            if not math.isfinite(v) or (name != "station_m" and v < 0.0):
                raise ValueError(f"{name} = {v!r}: must be finite and >= 0")

    @property
    def hz(self) -> float:
        """Omega in Hz."""
        return self.Omega / (2.0 * math.pi)

    @property
    def text(self) -> str:
        """ "3.99 g at aft edge (0 m, k = 0), 12.07 Hz, axial force 3.44e+06 N at 64.3 m"."""
        out = (f"{g_text(self.acceleration_g)} at {self.station} ({self.station_m:.4g} m, "
               f"k = {self.k}), {self.hz:.4g} Hz")
        if self.load is not None:
            out += (f", {self.load_quantity} {self.load:.3g} {self.load_unit} at "
                    f"{self.load_station_m:.4g} m")
        if self.at_range_end:
            out += " (at the end of the Omega range: larger beyond it)"
        return out

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready mapping (None kept; Omega also in Hz)."""
        def opt(v: float | None) -> float | None:
            return None if v is None else float(v)

        return {"source": self.source, "k": int(self.k), "Omega": float(self.Omega),
                "Omega_hz": float(self.hz), "acceleration_g": float(self.acceleration_g),
                "station": self.station, "station_m": float(self.station_m),
                "displacement_m": opt(self.displacement_m), "modes": self.modes,
                "load_quantity": self.load_quantity, "load_unit": self.load_unit,
                "load": opt(self.load), "load_station_m": opt(self.load_station_m),
                "in_operating_range": bool(self.in_operating_range), "also": list(self.also),
                "at_range_end": bool(self.at_range_end)}


def axial_resonance_peaks(resonances: Sequence[Any], *, load: float,
                          operating_range: tuple[float, float]) -> tuple[ResponsePeak, ...]:
    """The damped k = 0 axial resonances of the vehicle as :class:`ResponsePeak`: at Omega =
    omega_n the aft-edge displacement a_n Delta F, a_n = phi_n^2 / (2 zeta omega_n^2) the
    single-mode resonant amplitude per newton (Meirovitch 1986, sec. 3.3; memo family 3), and
    the acceleration omega_n^2 times that; undamped ones (a_n None) are left out.

    Parameters
    ----------
    resonances : sequence of AxialResonance
        :attr:`flexbooster.dynamics.ForcedAxial.resonances` (``omega``, ``amplitude``,
        ``index``, ``type``, ``order``).
    load : float
        The pulsating thrust Delta F = gamma F0 (N), >= 0.
    operating_range : (float, float)
        [omega_min, omega_max] (rad/s).
    """
    if not (math.isfinite(load) and load >= 0.0):
        raise ValueError(f"load = {load!r}: must be finite and >= 0 (N)")
    lo, hi = _operating(operating_range)
    out = []
    for r in resonances:
        if r.amplitude is None:
            continue
        u = float(r.amplitude) * load  # m, at the aft edge
        out.append(ResponsePeak(
            source="axial resonance", k=0, Omega=float(r.omega),
            acceleration_g=u * r.omega**2 / STANDARD_GRAVITY, station="aft-edge", station_m=0.0,
            displacement_m=u, modes=f"k = 0 mode {r.index + 1} ({r.type}, order {r.order})",
            in_operating_range=bool(lo <= r.omega <= hi)))
    return tuple(out)


def merge_responses(forced: Sequence[ResponsePeak], axial: Sequence[ResponsePeak], *,
                    damping_ratio: float) -> tuple[ResponsePeak, ...]:
    """Every bounded response once, the largest acceleration first: a k = 0 axial resonance
    whose half-power band omega_n (1 -+ zeta) holds a k = 0 peak of the forced response is
    that peak (named in its ``also``; the forced response, with its stations and loads, is
    kept).

    Parameters
    ----------
    forced : sequence of ResponsePeak
        The forced response's peaks.
    axial : sequence of ResponsePeak
        From :func:`axial_resonance_peaks`.
    damping_ratio : float
        The modal damping ratio zeta of the k = 0 modes, >= 0.
    """
    tol = max(float(damping_ratio), 1e-3)
    kept = list(forced)
    for a in axial:
        hit = [i for i, p in enumerate(kept) if p.source == "forced response" and p.k == 0
               and abs(p.Omega - a.Omega) <= tol * a.Omega]
        if hit:
            i = hit[0]
            kept[i] = dataclasses.replace(kept[i], also=(*kept[i].also, a.modes))
        else:
            kept.append(a)
    return tuple(sorted(kept, key=lambda p: (not p.in_operating_range, -p.acceleration_g,
                                             p.Omega)))


def event_status(event: FlightEvent) -> str:
    """How a flight event counts (docs/theory/verdicts.md): a forced resonance is
    ``"bounded"``; a region by its accumulated e-folds N over its interval, with the floors of
    :func:`band_status`: ``"negligible"`` when its largest growth rate is below
    :data:`NEGLIGIBLE_GROWTH` or N < ln :data:`NEGLIGIBLE_AMPLIFICATION`, ``"unstable"`` when
    N > ln :data:`UNSTABLE_AMPLIFICATION`, ``"marginal"`` otherwise.

    Parameters
    ----------
    event : FlightEvent
        An event of the flight.
    """
    if event.mechanism == "forced":
        return "bounded"
    if event.max_growth_1_s < NEGLIGIBLE_GROWTH or \
            event.efolds < math.log(NEGLIGIBLE_AMPLIFICATION):
        return "negligible"
    return "unstable" if event.efolds > math.log(UNSTABLE_AMPLIFICATION) else "marginal"


@dataclass(frozen=True)
class FlightVerdict:
    """The flight's part of the overall verdict: its events that count, the worst first.

    Attributes
    ----------
    t_start_s, t_end_s : float
        The flight's first and last frozen time (s).
    events : tuple of FlightEvent
        The events that count (:func:`event_status` not negligible), the worst first.
    dropped : int
        Events of negligible growth, left out.
    gaps : int
        Searches at frozen times cut by a limit.
    """

    t_start_s: float
    t_end_s: float
    events: tuple[FlightEvent, ...]
    dropped: int = 0
    gaps: int = 0

    @property
    def worst(self) -> FlightEvent | None:
        """The worst event that counts, None where none does."""
        return self.events[0] if self.events else None

    def status(self) -> str:
        """The worst status of its events ("unstable", "marginal", "bounded") or "stable"."""
        found = {event_status(e) for e in self.events}
        return next((s for s in ("unstable", "marginal", "bounded") if s in found), "stable")

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready mapping."""
        worst = self.worst
        return {"t_start_s": float(self.t_start_s), "t_end_s": float(self.t_end_s),
                "status": self.status(), "events_counted": len(self.events),
                "events_dropped": int(self.dropped), "gaps": int(self.gaps),
                "worst": None if worst is None else dict(worst.to_dict(),
                                                         status=event_status(worst))}


def flight_verdict(events: Sequence[FlightEvent], *, times: tuple[float, float],
                   gaps: int = 0) -> FlightVerdict:
    """The events that count over a flight, the worst first (unstable, then marginal regions
    by accumulated e-folds, then the forced resonances by peak acceleration, then the
    earliest), and how many of negligible growth were dropped.

    Parameters
    ----------
    events : sequence of FlightEvent
        Every event of the flight.
    times : (float, float)
        The flight's first and last frozen time (s).
    gaps : int
        Searches at frozen times cut by a limit (>= 0).
    """
    rank = {"unstable": 0, "marginal": 1, "bounded": 2}
    kept = [e for e in events if event_status(e) != "negligible"]
    kept.sort(key=lambda e: (rank[event_status(e)], -e.efolds,
                             -(e.peak_acceleration_g or 0.0), e.t_start_s))
    return FlightVerdict(float(times[0]), float(times[1]), tuple(kept),
                         len(events) - len(kept), int(gaps))


def _operating(operating_range: tuple[float, float]) -> tuple[float, float]:
    lo, hi = (float(v) for v in operating_range)
    if not (math.isfinite(lo) and math.isfinite(hi) and 0.0 <= lo < hi):
        raise ValueError(f"operating_range = {operating_range!r}: need finite "
                         "0 <= omega_min < omega_max (rad/s)")
    return lo, hi


def _is_pitch_tongue(band: Band) -> bool:
    """A beam-action band of the rigid pitch alone ("rigid pitch", simple): a Mathieu tongue."""
    return band.mechanism == "beam_action" and band.kind == "simple" and \
        [m.label for m in band.modes] == ["rigid pitch"]


def _same_bands(bands: Sequence[Band]) -> list[tuple[Band, tuple[str, ...]]]:
    """Each band once with the other mechanisms that found it: a rigid-pitch tongue of the
    pitch (memo 4.2) that a beam-action rigid-pitch band of the same order overlaps is that
    band (the coupled model's edges are kept)."""
    tongues = [b for b in bands if _is_pitch_tongue(b)]
    out = []
    merged: set[int] = set()
    for b in bands:
        if b.mechanism != "pitch":
            continue
        if any(t.order == b.order and t.Omega_lo <= b.Omega_hi and b.Omega_lo <= t.Omega_hi
               for t in tongues):
            merged.add(id(b))
    for b in bands:
        if id(b) in merged:
            continue
        also = ("pitch",) if _is_pitch_tongue(b) and any(
            p.mechanism == "pitch" and id(p) in merged and p.order == b.order
            and p.Omega_lo <= b.Omega_hi and b.Omega_lo <= p.Omega_hi for p in bands) else ()
        out.append((b, also))
    return out


#: Order of the statuses in the ranking (:func:`band_status`).
_STATUS_RANK = {"unstable": 0, "marginal": 1, "bounded": 2, "negligible": 3}


def danger_bands(bands: Sequence[Band], *, operating_range: tuple[float, float],
                 limit: int | None = None, duration: float | None = None,
                 modal_ratio: float = 0.0) -> tuple[RankedBand, ...]:
    """Every band once (the same physical band of two mechanisms merged, naming both), most
    dangerous first: those the operating range reaches; then by status (:func:`band_status`:
    unstable, marginal, bounded resonances, negligible growth); within one status the regions
    by growth rate before the resonances by damped steady acceleration (undamped: by
    severity); ties by Omega_lo.

    Parameters
    ----------
    bands : sequence of Band
        The bands of every mechanism computed (Omega in rad/s).
    operating_range : (float, float)
        [omega_min, omega_max] of the case (rad/s), finite, 0 <= omega_min < omega_max.
    limit : int, optional
        Keep the first ``limit`` (>= 0); all by default.
    duration : float or None
        Duration of the excitation (s), for the statuses.
    modal_ratio : float
        Modal damping ratio of the elastic modes, for the statuses.
    """
    lo, hi = _operating(operating_range)
    if limit is not None and (not isinstance(limit, int) or limit < 0):
        raise ValueError(f"limit = {limit!r}: must be a non-negative integer")
    ranked = [RankedBand(b, b.Omega_hi >= lo and b.Omega_lo <= hi, also)
              for b, also in _same_bands(bands)]

    def key(r: RankedBand) -> tuple:
        rank = _STATUS_RANK[_status(r, duration, modal_ratio)]
        if r.growth_rate is not None:
            return (not r.in_operating_range, rank, 0, -r.growth_rate, r.Omega_lo)
        # damped: the steady acceleration in g, the one scale of every bounded response
        # (:class:`ResponsePeak`); undamped: the severity
        acc = r.band.steady_acceleration
        return (not r.in_operating_range, rank, 1, -(acc / STANDARD_GRAVITY if acc is not None else
                                                      r.severity or 0.0), r.Omega_lo)

    ranked.sort(key=key)
    return tuple(ranked if limit is None else ranked[:limit])


def edges_text(lo: float, hi: float) -> str:
    """'lo-hi' with the fewest significant digits (4..10) that tell the edges apart.

    Parameters
    ----------
    lo, hi : float
        Edges (any unit).
    """
    for digits in range(4, 11):
        a, b = f"{lo:.{digits}g}", f"{hi:.{digits}g}"
        if a != b:
            return f"{a}-{b}"
    return f"{lo:.10g}"


def g_text(value: float) -> str:
    """An acceleration in g to 3 significant digits, trailing zeros kept: "2.00 g" for 1.997
    (not "2 g"), "50.0 g", "0.918 g", "120 g".

    Parameters
    ----------
    value : float
        The acceleration (g, standard gravity 9.80665 m/s^2).
    """
    return f"{f'{value:#.3g}'.rstrip('.')} g"


def hz_text(lo_hz: float, hi_hz: float) -> str:
    """Band edges in Hz to the digits that tell them apart: "18.25-18.31 Hz".

    Parameters
    ----------
    lo_hz, hi_hz : float
        The edges (Hz).
    """
    return f"{edges_text(lo_hz, hi_hz)} Hz"


def _status(ranked: RankedBand, duration: float | None, modal_ratio: float) -> str:
    return band_status(ranked.band, duration=duration, modal_ratio=modal_ratio)


def _growth_words(band: Band, duration: float | None) -> str:
    """ "e-folding time 352 s" and, with T, "x 1.53 in 150 s"."""
    e = band.e_folding_s
    text = "no growth" if e is None else f"e-folding time {e:.3g} s"
    if duration is not None and band.growth_exponent is not None:
        amp = band.amplification
        text += (f", x {amp:.3g} in {duration:g} s" if amp is not None else
                 f", x e^{band.growth_exponent:.3g} in {duration:g} s")
    return text


def mechanism_verdicts(ranked: Sequence[RankedBand], *, computed: Mapping[str, bool],
                       gaps: Sequence[SearchGap] = (), duration: float | None = None,
                       modal_ratio: float = 0.0, certified: Mapping[str, float] | None = None
                       ) -> tuple[tuple[str, str, str], ...]:
    """(key, words, verdict) per mechanism of :data:`flexbooster.bands.MECHANISMS`: "not
    computed", "stable in the operating range", "not fully searched: ...", "unstable: N ..." or
    "marginal: N ..." (with "; not fully searched: ..." when a gap remains); regions of
    negligible growth (:func:`band_status`) are counted apart, never as unstable; a damped
    resonance is "bounded by damping".

    Parameters
    ----------
    ranked : sequence of RankedBand
        From :func:`danger_bands` (all of them).
    computed : mapping of str to bool
        Whether each mechanism was computed; a missing key means not computed.
    gaps : sequence of SearchGap
        What the searches left out (``stage`` names the mechanism).
    duration : float or None
        Duration of the excitation (s), or None.
    modal_ratio : float
        Modal damping ratio of the elastic modes.
    certified : mapping of str to float, optional
        Per mechanism, the factor on gamma below which a certificate proves it free of
        regions at every Omega (a lower bound of every margin), said on a stable verdict.
    """
    certified = {} if certified is None else certified
    out = []
    for key, words in MECHANISMS:
        if not computed.get(key, False):
            out.append((key, words, "not computed"))
            continue
        inside = [b for b in ranked if key in b.mechanisms and b.in_operating_range]
        status = [_status(b, duration, modal_ratio) for b in inside]
        mine = [b for b, st in zip(inside, status, strict=True) if st != "negligible"]
        slow = [b for b, st in zip(inside, status, strict=True) if st == "negligible"]
        left = [g for g in gaps if g.stage == key]
        slow_text = "" if not slow else (
            f" ({len(slow)} region{'s' if len(slow) > 1 else ''} of negligible growth, "
            f"largest {max(b.growth_rate for b in slow):.3g} 1/s)")
        if not mine:
            bound = certified.get(key)
            margin = "" if left or bound is None else (
                "; margin on gamma at least " + (
                    f"{bound:.3g}" if math.isfinite(bound) else "infinite")
                + " at every Omega (a proven bound)")
            out.append((key, words, (gaps_text(left) if left else
                                     "stable in the operating range") + margin + slow_text))
            continue
        resonance = key == "resonance"
        noun = ("resonance" if resonance else "instability region") + \
            ("s" if len(mine) > 1 else "")
        if resonance:
            sev = max(b.severity or 0.0 for b in mine)
            text = (f"unstable: {len(mine)} {noun} in the operating range, largest severity "
                    f"{sev:.3g} m/s" if "unstable" in status else
                    f"bounded by damping: {len(mine)} {noun} in the operating range"
                    + _response_text([b.band for b in mine], ", largest steady response "))
        else:
            word = "unstable" if "unstable" in status else "marginal"
            top = max(mine, key=lambda b: b.band.growth_rate_max)
            text = (f"{word}: {len(mine)} {noun} in the operating range, largest growth rate "
                    f"{top.growth_rate:.3g} 1/s")
            if duration is not None:
                text += f" ({_growth_words(top.band, duration)})"
        steady = [b for b in mine if b.band.kind == "steady"]
        if steady:  # not parametric: the steady system itself (its growth, e-folding time)
            g = max(b.growth_rate for b in steady)
            text += (f" ({len(steady)} of them {STEADY_CAUSE}: growth rate {g:.3g} 1/s"
                     + (f", e-folding time {1.0 / g:.3g} s)" if g > 0.0 else ")"))
        text += slow_text
        if left:
            text += "; " + gaps_text(left)
        out.append((key, words, text))
    return tuple(out)


def _response_text(bands: Sequence[Band], lead: str) -> str:
    """lead + "1.6 mm (0.9 g) at 45.2 Hz" of the largest damped steady acceleration; "" if
    none."""
    damped = [b for b in bands if b.steady_acceleration is not None]
    if not damped:
        return ""
    top = max(damped, key=lambda b: b.steady_acceleration)
    f = top.modes[0].omega / (2.0 * math.pi)
    return (f"{lead}{1e3 * top.steady_amplitude:.3g} mm "
            f"({g_text(top.steady_acceleration / STANDARD_GRAVITY)}) at {f:.4g} Hz")


def _damping_text(modal_ratio: float, pitch_ratio: float) -> str:
    """ "1 % modal damping (rigid pitch undamped)"."""
    modal = f"{100.0 * modal_ratio:g} % modal damping" if modal_ratio > 0.0 else \
        "no modal damping"
    pitch = f"rigid pitch {100.0 * pitch_ratio:g} %" if pitch_ratio > 0.0 else \
        "rigid pitch undamped"
    return f"{modal} ({pitch})"


def _where(band: Band) -> str:
    """ "18.25-18.31 Hz (beam action: bending 1 + bending 2)"."""
    words = {"pitch": "rigid-body pitch", "beam_action": "beam action",
             "vehicle": "vehicle", "resonance": "memo resonance"}[band.mechanism]
    return f"{hz_text(*band.hz)} ({words}: {_mode_text(band)})"


@dataclass(frozen=True)
class Verdict:
    """The one overall answer (docs/theory/verdicts.md).

    Attributes
    ----------
    overall : str
        ``"UNSTABLE"``, ``"MARGINAL"`` or ``"STABLE"``.
    reason : str
        Why, in words.
    mechanisms : tuple of (str, str)
        (key, verdict) per mechanism (:func:`mechanism_verdicts`).
    modal_ratio, pitch_ratio : float
        The damping used.
    duration : float or None
        Duration of the excitation (s).
    largest_response : dict or None
        The largest bounded response over everything computed (acceleration in g): the
        ``to_dict`` of a :class:`ResponsePeak`, a resonance band's or a flight event's, with
        ``"source"`` naming which.
    flight : FlightVerdict or None
        The flight's part (a case with ``[flight]``).
    """

    overall: str
    reason: str
    mechanisms: tuple[tuple[str, str], ...]
    modal_ratio: float
    pitch_ratio: float
    duration: float | None
    largest_response: dict | None = None
    flight: FlightVerdict | None = None

    @property
    def line(self) -> str:
        """ "STABLE: reason"."""
        return f"{self.overall}: {self.reason}"

    @property
    def damping_text(self) -> str:
        """The damping used, in words."""
        return _damping_text(self.modal_ratio, self.pitch_ratio)

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready mapping."""
        return {"overall": self.overall, "reason": self.reason,
                "mechanisms": dict(self.mechanisms),
                "damping": {"modal_ratio": float(self.modal_ratio),
                            "pitch_ratio": float(self.pitch_ratio)},
                "duration": None if self.duration is None else float(self.duration),
                "largest_response": self.largest_response,
                "flight": None if self.flight is None else self.flight.to_dict()}


def _event_words(e: FlightEvent) -> str:
    """A flight event in a few words, with its interval."""
    what = e.modes if e.k is None else f"k = {e.k} {e.modes}"
    when = f"t = {e.t_start_s:.4g}-{e.t_end_s:.4g} s"
    if e.peak_acceleration_g is not None:
        return f"{g_text(e.peak_acceleration_g)} at {e.station}, {when}, {what}"
    amp = f"x {e.amplification:.3g}" if math.isfinite(e.amplification) and \
        e.efolds <= AMPLIFICATION_EXPONENT_MAX else f"x e^{e.efolds:.3g}"
    return f"{what}, {when}, {amp} ({e.efolds:.3g} e-folds)"


def _largest_response(bounded: Sequence[Band], responses: Sequence[ResponsePeak],
                      flight: FlightVerdict | None) -> tuple[str, dict] | None:
    """The largest bounded response in g over the damped resonances, the vehicle's responses
    in the operating range and the flight's forced resonances: (words, JSON mapping)."""
    found: list[tuple[float, str, dict]] = []
    for b in bounded:
        if b.steady_acceleration is not None:
            g = b.steady_acceleration / STANDARD_GRAVITY
            found.append((g, _response_text([b], "") + " (shell resonance)",
                          {"source": "shell resonance", "acceleration_g": g,
                           "displacement_m": float(b.steady_amplitude),
                           "Omega": float(b.modes[0].omega),
                           "Omega_hz": float(b.modes[0].omega / (2.0 * math.pi)),
                           "modes": b.mode_text}))
    for r in responses:
        if r.in_operating_range:
            found.append((r.acceleration_g, r.text, r.to_dict()))
    for e in () if flight is None else flight.events:
        if e.peak_acceleration_g is not None:
            found.append((e.peak_acceleration_g, f"{_event_words(e)} (flight)",
                          dict(e.to_dict(), source="flight", acceleration_g=e.peak_acceleration_g)))
    if not found:
        return None
    g, words, data = max(found, key=lambda f: f[0])
    return words, data


def _flight_text(flight: FlightVerdict, duration_rule: str) -> str:
    """The flight's part of the reason."""
    span = f"over the flight (t = {flight.t_start_s:g}-{flight.t_end_s:g} s)"
    status = flight.status()
    worst = flight.worst
    if status in ("unstable", "marginal"):
        n = sum(1 for e in flight.events if event_status(e) == status)
        rule = (f"grow{'s' if n == 1 else ''} more than {UNSTABLE_AMPLIFICATION:g}-fold"
                if status == "unstable" else "open")
        text = (f"{span} {n} region{'s' if n > 1 else ''} {rule}; worst "
                f"{_event_words(worst)}")
    else:
        text = f"{span} no region grows more than {duration_rule}"
        if worst is not None:
            text += f"; worst moment {_event_words(worst)}"
    if flight.dropped:
        text += (f" ({flight.dropped} event{'s' if flight.dropped > 1 else ''} of negligible "
                 "growth dropped)")
    if flight.gaps:
        text += f"; not fully searched at {flight.gaps} frozen-time search(es)"
    return text


def overall_verdict(ranked: Sequence[RankedBand], *,
                    verdicts: Sequence[tuple[str, str, str]], gaps: Sequence[SearchGap] = (),
                    duration: float | None = None, modal_ratio: float = 0.0,
                    pitch_ratio: float = 0.0, responses: Sequence[ResponsePeak] = (),
                    flight: FlightVerdict | None = None) -> Verdict:
    """The worst over everything computed: UNSTABLE when a band in the operating range or a
    flight event is unstable (:func:`band_status`, :func:`event_status`); else MARGINAL when
    one is marginal or a computed mechanism (or the flight) was not fully searched; else
    STABLE. A bounded response (a damped resonance, the vehicle's forced response, a flight's
    forced resonance) never makes the verdict worse: the largest, in g, is named in the
    reason.

    Parameters
    ----------
    ranked : sequence of RankedBand
        From :func:`danger_bands`.
    verdicts : sequence of (str, str, str)
        From :func:`mechanism_verdicts`.
    gaps : sequence of SearchGap
        What the searches left out.
    duration : float or None
        Duration of the excitation (s).
    modal_ratio, pitch_ratio : float
        The damping used.
    responses : sequence of ResponsePeak
        The vehicle's bounded forced responses (:func:`merge_responses`).
    flight : FlightVerdict or None
        The flight's events that count (:func:`flight_verdict`).
    """
    inside = [b for b in ranked if b.in_operating_range]
    by = {"unstable": [], "marginal": [], "negligible": [], "bounded": []}
    for b in inside:
        by[_status(b, duration, modal_ratio)].append(b.band)
    damping = _damping_text(modal_ratio, pitch_ratio)
    computed = {k for k, _, v in verdicts if v != "not computed"}
    cut = sorted({g.stage for g in gaps if g.stage in computed})
    names = dict(MECHANISMS)
    regions_u = [b for b in by["unstable"] if b.mechanism != "resonance"]
    res_u = [b for b in by["unstable"] if b.mechanism == "resonance"]
    fstatus = "stable" if flight is None else flight.status()
    parts: list[str] = []
    if by["unstable"] or fstatus == "unstable":
        overall = "UNSTABLE"
        if regions_u:
            top = max(regions_u, key=lambda b: b.growth_rate_max)
            rule = (f"grow more than {UNSTABLE_AMPLIFICATION:g}-fold in {duration:g} s"
                    if duration is not None else
                    f"have an e-folding time under {UNSTABLE_E_FOLDING:g} s")
            n = len(regions_u)
            parts.append(f"at {damping}, {n} region{'s' if n > 1 else ''} {rule}; "
                         f"fastest {_where(top)}, {_growth_words(top, duration)}")
        if res_u:
            parts.append(f"{len(res_u)} forced resonance{'s' if len(res_u) > 1 else ''} "
                         "grow without bound (no modal damping)")
    elif by["marginal"] or cut or fstatus == "marginal" or (flight is not None and flight.gaps):
        overall = "MARGINAL"
        if by["marginal"]:
            top = max(by["marginal"], key=lambda b: b.growth_rate_max)
            n = len(by["marginal"])
            parts.append(f"at {damping}, {n} region{'s' if n > 1 else ''} open; fastest "
                         f"{_where(top)}, {_growth_words(top, duration)}")
        if cut:
            parts.append("not fully searched: " + ", ".join(names[k] for k in cut))
    else:
        overall = "STABLE"
    if not (by["unstable"] or by["marginal"]):  # the frozen-time regions: none counts
        parts.insert(0, f"at {damping}, no region" + (
            f" grows more than {100.0 * (NEGLIGIBLE_AMPLIFICATION - 1.0):g} % in "
            f"{duration:g} s" if duration is not None else
            f" has an e-folding time under {1.0 / NEGLIGIBLE_GROWTH:.0e} s"))
    if flight is not None:
        parts.append(_flight_text(flight, f"{100.0 * (NEGLIGIBLE_AMPLIFICATION - 1.0):g} %"))
    if by["bounded"]:
        n = len(by["bounded"])
        parts.append(f"{n} forced resonance{'s' if n > 1 else ''} bounded by damping")
    top = _largest_response(by["bounded"], responses, flight)
    if top is not None:
        worst = None if flight is None else flight.worst
        same = worst is not None and top[1].get("source") == "flight" and \
            top[1] == dict(worst.to_dict(), source="flight",
                           acceleration_g=worst.peak_acceleration_g)
        parts.append("the flight's worst moment is also the largest response" if same
                     else f"largest response {top[0]}")
    return Verdict(overall, "; ".join(parts), tuple((k, v) for k, _, v in verdicts),
                   float(modal_ratio), float(pitch_ratio),
                   None if duration is None else float(duration),
                   None if top is None else top[1], flight)


#: Order of the statuses in the one ranking of bands and responses.
_ITEM_RANK = {"unstable": 0, "marginal": 1, "bounded": 2, "negligible": 3}


@dataclass(frozen=True)
class DangerSummary:
    """The first screen's data: one verdict per mechanism and the ranked bands.

    Attributes
    ----------
    operating_range : (float, float)
        The case's [omega_min, omega_max] (rad/s).
    verdicts : tuple of (str, str, str)
        (key, mechanism in words, verdict), see :func:`mechanism_verdicts`.
    bands : tuple of RankedBand
        Every band, ranked (see :func:`danger_bands`).
    verdict : Verdict or None
        The overall verdict (:func:`overall_verdict`).
    responses : tuple of ResponsePeak
        The vehicle's bounded forced responses, the largest acceleration first.
    ranking : tuple of RankedBand or ResponsePeak
        The bands and the responses in one ranking: in the operating range first, then by
        status (unstable, marginal, bounded, negligible); regions by growth rate, bounded
        responses by acceleration in g.
    """

    operating_range: tuple[float, float]
    verdicts: tuple[tuple[str, str, str], ...]
    bands: tuple[RankedBand, ...]
    verdict: Verdict | None = None
    responses: tuple[ResponsePeak, ...] = ()
    ranking: tuple = ()

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready mapping."""
        def item(x: RankedBand | ResponsePeak) -> dict[str, Any]:
            if isinstance(x, ResponsePeak):
                return dict(x.to_dict(), item="response")
            return dict(x.to_dict(), item="band")

        return {"operating_range": [float(v) for v in self.operating_range],
                "verdicts": [{"mechanism": k, "words": w, "verdict": v}
                             for k, w, v in self.verdicts],
                "bands": [b.to_dict() for b in self.bands],
                "responses": [r.to_dict() for r in self.responses],
                "ranking": [item(x) for x in self.ranking],
                "verdict": None if self.verdict is None else self.verdict.to_dict()}


def _ranking(bands: Sequence[RankedBand], responses: Sequence[ResponsePeak], *,
             duration: float | None, modal_ratio: float) -> tuple:
    """The bands and the responses in one order (:attr:`DangerSummary.ranking`)."""
    def key(x: RankedBand | ResponsePeak) -> tuple:
        if isinstance(x, ResponsePeak):
            return (not x.in_operating_range, _ITEM_RANK["bounded"], 1, -x.acceleration_g,
                    x.Omega)
        rank = _ITEM_RANK[_status(x, duration, modal_ratio)]
        if x.growth_rate is not None:
            return (not x.in_operating_range, rank, 0, -x.growth_rate, x.Omega_lo)
        acc = x.band.steady_acceleration
        return (not x.in_operating_range, rank, 1,
                -(acc / STANDARD_GRAVITY if acc is not None else x.severity or 0.0), x.Omega_lo)

    return tuple(sorted([*bands, *responses], key=key))


def danger_summary(*, operating_range: tuple[float, float], bands: Mapping[str, Sequence[Band]],
                   gaps: Sequence[SearchGap] = (), gamma: float = 0.0,
                   duration: float | None = None, modal_ratio: float = 0.0,
                   pitch_ratio: float = 0.0, responses: Sequence[ResponsePeak] = (),
                   flight: FlightVerdict | None = None,
                   certified: Mapping[str, float] | None = None) -> DangerSummary:
    """Verdicts, the overall verdict and the ranked bands (each with :func:`band_measures`)
    of every mechanism computed, with the vehicle's bounded responses and the flight.

    Parameters
    ----------
    operating_range : (float, float)
        [omega_min, omega_max] (rad/s).
    bands : mapping of str to sequence of Band
        The bands of each mechanism computed, by key of :data:`flexbooster.bands.MECHANISMS`.
    gaps : sequence of SearchGap
        What the searches left out.
    gamma : float
        The case's pulsation amplitude (the margins critical_gamma / gamma).
    duration : float or None
        Duration of the excitation (s).
    modal_ratio, pitch_ratio : float
        The damping used (the verdict's words; a damped resonance is bounded).
    responses : sequence of ResponsePeak
        The vehicle's bounded forced responses (:func:`merge_responses`).
    flight : FlightVerdict or None
        The flight's part (:func:`flight_verdict`).
    certified : mapping of str to float, optional
        Certified margins per mechanism (:func:`mechanism_verdicts`).
    """
    for key in bands:
        if key not in dict(MECHANISMS):
            raise ValueError(f"bands: unknown mechanism {key!r}")
    # the pitch tongues' critical damping for the fastest CRITICAL_DAMPING_COUNT only (at a
    # large gamma a hundred tongues count, each a root search of about a second)
    tongues = sorted((b for b in bands.get("pitch", ()) if b.critical_damping_ratio is None),
                     key=lambda b: -b.growth_rate_max)[:CRITICAL_DAMPING_COUNT]
    chosen = {id(b) for b in tongues}
    ranked = danger_bands([band_measures(b, gamma=gamma, duration=duration,
                                         modal_ratio=modal_ratio,
                                         critical_damping=id(b) in chosen)
                           for found in bands.values() for b in found],
                          operating_range=operating_range, duration=duration,
                          modal_ratio=modal_ratio)
    computed = {key: True for key in bands}
    lo, hi = _operating(operating_range)
    verdicts = mechanism_verdicts(ranked, computed=computed, gaps=gaps, duration=duration,
                                  modal_ratio=modal_ratio, certified=certified)
    responses = tuple(sorted(responses, key=lambda r: (not r.in_operating_range,
                                                       -r.acceleration_g, r.Omega)))
    verdict = overall_verdict(ranked, verdicts=verdicts, gaps=gaps, duration=duration,
                              modal_ratio=modal_ratio, pitch_ratio=pitch_ratio,
                              responses=responses, flight=flight)
    return DangerSummary((lo, hi), verdicts, ranked, verdict, responses,
                         _ranking(ranked, responses, duration=duration,
                                  modal_ratio=modal_ratio))
