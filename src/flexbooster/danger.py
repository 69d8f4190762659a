"""The most dangerous thrust-frequency bands of an analysis, across every mechanism.

One frozen :class:`DangerBand` per band of Omega in which the booster goes unstable, whatever
computed it, and :func:`danger_bands`, which gathers and ranks them: the first screen of the
summary and of the report, and the danger-map figure, draw these and nothing else.

Sources (each optional, ``None`` when not computed):

* ``pitch`` -- :class:`flexbooster.memo.pitch.PitchResult` (its ``bands``, Mathieu tongues of the
  rigid-body pitch, memo 4.2);
* ``beam_action`` -- :class:`flexbooster.memo.beam_action.BeamActionResult` (its ``bands``,
  parametric resonances of the gimbaled beam, memo 4.1);
* ``vehicle_regions`` -- any sequence of objects with ``Omega_lo``, ``Omega_hi`` (rad/s) and
  ``growth_rate_max`` (1/s), optionally ``label`` / ``mode`` (text, e.g. "k = 2, modes 1+3"):
  the instability regions of the vehicle model; a
  :class:`flexbooster.vehicle.VehicleRegion` (``k``, ``kind``, ``order``, ``modes`` with
  ``type`` and ``order``) is described from those fields;
* ``resonance_bands`` -- any sequence of objects with ``Omega_lo``, ``Omega_hi`` (rad/s) and
  ``severity`` (dimensionless, > 0), optionally ``growth_rate_max`` (1/s) and ``label`` /
  ``family``: the resonances (secular roots) of memo 7.3.

The adapters accept the lower-case spelling ``omega_lo`` / ``omega_hi`` too.  This module is in
the results layer (numpy only): the pipeline calls it, the presentation reads its output.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

__all__ = ["DangerBand", "DangerSummary", "MECHANISMS", "STEADY_CAUSE", "danger_bands",
           "danger_summary", "mechanism_verdicts"]

#: The mechanisms, in the order of the verdict lines: (key, words).
MECHANISMS: tuple[tuple[str, str], ...] = (
    ("pitch", "rigid-body pitch (memo 4.2)"),
    ("beam_action", "beam action (memo 4.1)"),
    ("vehicle", "vehicle parametric regions"),
    ("resonance", "memo resonances (memo 7.3)"),
)

_KIND_WORDS = {
    "simple": "simple",
    "sum": "sum combination",
    "difference": "difference combination",
    "steady": "steady thrust",
}
#: The cause of a "steady" region: the system under the steady thrust alone (gamma = 0) is
#: unstable (flutter or divergence: Beal 1965 for the follower thrust; with the gimbal loop and
#: damping also a slow growth of the rigid pitch), over the whole range; not parametric.
STEADY_CAUSE = "unstable without pulsation"


def _region_cause(kind: str, order: object, model: str = "") -> str:
    """The cause in words of an instability region of ``kind`` and ``order`` (j)."""
    if kind == "steady":
        return f"{STEADY_CAUSE} (the steady thrust alone, gamma = 0{model})"
    return f"instability region ({_KIND_WORDS.get(kind, kind)}, order {order}{model})"


@dataclass(frozen=True)
class DangerBand:
    """One band of thrust frequencies Omega in which a mechanism is unstable.

    Attributes
    ----------
    mechanism : str
        One of the keys of :data:`MECHANISMS`: ``"pitch"``, ``"beam_action"``, ``"vehicle"``,
        ``"resonance"``.
    Omega_lo, Omega_hi : float
        Band edges (rad/s), ``Omega_lo <= Omega_hi``.
    growth_rate : float or None
        Largest amplitude growth rate inside the band (1/s); None where the source gives none
        (a memo resonance).
    severity : float or None
        Severity of a resonance (m/s: the secular growth rate of the resonant shell mode's
        surface displacement, :mod:`flexbooster.memo.severity`); None for a parametric region.
    mode_text : str
        The mode(s) in words, e.g. "rigid pitch + bending 1" (bending r: the r-th loaded
        bending mode of the beam-action system, memo 4.1).
    cause_text : str
        The mechanism in words, e.g. "instability region (sum combination, order 1)" or
        "resonance (memo 7)".
    in_operating_range : bool
        True when the band overlaps the operating range [omega_min, omega_max] of the case.

    References
    ----------
    Tech Memo 104, secs. 4.1, 4.2, 7.3; Bolotin (1964), ch. 1-2 (instability regions).
    """

    mechanism: str
    Omega_lo: float
    Omega_hi: float
    growth_rate: float | None
    severity: float | None
    mode_text: str
    cause_text: str
    in_operating_range: bool

    @property
    def hz(self) -> tuple[float, float]:
        """The edges in Hz."""
        return self.Omega_lo / (2.0 * math.pi), self.Omega_hi / (2.0 * math.pi)

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready mapping (plain floats, str, bool; None kept)."""
        lo_hz, hi_hz = self.hz
        return {
            "mechanism": self.mechanism,
            "Omega_lo": float(self.Omega_lo),
            "Omega_hi": float(self.Omega_hi),
            "Omega_lo_hz": float(lo_hz),
            "Omega_hi_hz": float(hi_hz),
            "growth_rate": None if self.growth_rate is None else float(self.growth_rate),
            "severity": None if self.severity is None else float(self.severity),
            "mode_text": self.mode_text,
            "cause_text": self.cause_text,
            "in_operating_range": bool(self.in_operating_range),
        }


def _mode_name(m: int) -> str:
    # steady modes in ascending frequency; 0 is the rigid pitch for a small thrust (4.1)
    return "rigid pitch" if m == 0 else f"bending {m}"


def _overlaps(lo: float, hi: float, operating: tuple[float, float]) -> bool:
    return hi >= operating[0] and lo <= operating[1]


def _attr(obj: object, *names: str, default: Any = None) -> Any:
    for name in names:
        value = getattr(obj, name, None)
        if value is not None:
            return value
    return default


def _edges(obj: object, source: str, n: int) -> tuple[float, float]:
    lo = _attr(obj, "Omega_lo", "omega_lo")
    hi = _attr(obj, "Omega_hi", "omega_hi")
    if lo is None or hi is None:
        raise ValueError(f"{source}[{n}] = {obj!r}: needs Omega_lo and Omega_hi (rad/s)")
    lo, hi = float(lo), float(hi)
    if not (math.isfinite(lo) and math.isfinite(hi) and 0.0 <= lo <= hi):
        raise ValueError(f"{source}[{n}] = ({lo!r}, {hi!r}): need finite 0 <= Omega_lo <= "
                         "Omega_hi (rad/s)")
    return lo, hi


def _finite_or_none(value: object, what: str) -> float | None:
    if value is None:
        return None
    x = float(value)
    if not math.isfinite(x):
        raise ValueError(f"{what} = {x!r}: must be finite")
    return x


def _pitch_bands(pitch, operating) -> list[DangerBand]:
    # Mathieu tongue r: Omega ~ 2 omega_psi / r (memo eqs. 4.2-3, 4.2-4; A&S 20.2)
    return [
        DangerBand("pitch", float(b.omega_lo), float(b.omega_hi), float(b.growth_rate_max),
                   None, "rigid pitch",
                   f"instability region (Mathieu tongue {b.tongue})",
                   _overlaps(b.omega_lo, b.omega_hi, operating))
        for b in pitch.bands
    ]


def _beam_action_bands(beam_action, operating) -> list[DangerBand]:
    out = []
    for b in beam_action.bands:
        modes = " + ".join(_mode_name(int(m)) for m in b.modes)
        # centres 2 omega_i / j or (omega_i +- omega_k) / j (Bolotin 1964, ch. 2; Hsu 1963)
        out.append(DangerBand("beam_action", float(b.omega_lo), float(b.omega_hi),
                              float(b.growth_rate_max), None, modes,
                              _region_cause(b.kind, b.order),
                              _overlaps(b.omega_lo, b.omega_hi, operating)))
    return out


def _generic(items: Sequence, source: str, mechanism: str, operating,
             need_severity: bool) -> list[DangerBand]:
    out = []
    for n, item in enumerate(items):
        lo, hi = _edges(item, source, n)
        growth = _finite_or_none(_attr(item, "growth_rate_max", "growth_rate"),
                                 f"{source}[{n}].growth_rate_max")
        severity = _finite_or_none(_attr(item, "severity"), f"{source}[{n}].severity")
        if need_severity and severity is None and growth is None:
            raise ValueError(f"{source}[{n}] = {item!r}: needs severity or growth_rate_max")
        if not need_severity and growth is None:
            raise ValueError(f"{source}[{n}] = {item!r}: needs growth_rate_max (1/s)")
        mode = str(_attr(item, "mode_text", "mode", "label", default="-"))
        kind = getattr(item, "kind", None)
        if mechanism == "vehicle" and kind is not None and hasattr(item, "k"):
            # flexbooster.vehicle.VehicleRegion: harmonic k, loaded modes, kind and order j
            modes = " + ".join(f"{getattr(m, 'type', 'mode')} {getattr(m, 'order', '')}".strip()
                               for m in getattr(item, "modes", ()))
            mode = f"k = {item.k}" + (f": {modes}" if modes else "")
            item_cause = _region_cause(kind, getattr(item, "order", "?"), "; vehicle model")
        else:
            item_cause = None
        if mechanism == "resonance":
            family = _attr(item, "cause_text", "family")
            cause = "resonance (memo 7)" + (f": {family}" if family is not None else "")
        else:
            cause = item_cause or str(_attr(item, "cause_text",
                                            default="instability region (vehicle model)"))
        out.append(DangerBand(mechanism, lo, hi, growth, severity, mode, cause,
                              _overlaps(lo, hi, operating)))
    return out


def danger_bands(*, operating_range: tuple[float, float], pitch=None, beam_action=None,
                 vehicle_regions: Sequence | None = None,
                 resonance_bands: Sequence | None = None,
                 limit: int | None = None) -> tuple[DangerBand, ...]:
    """Every unstable band of Omega from the mechanisms computed, most dangerous first.

    Parameters
    ----------
    operating_range : (float, float)
        The case's operating range of the thrust frequency [omega_min, omega_max] (rad/s),
        finite, 0 <= omega_min < omega_max.
    pitch : PitchResult, optional
        Rigid-body pitch (its ``bands``); None when not computed.
    beam_action : BeamActionResult, optional
        Beam action (its ``bands``); None when not computed.
    vehicle_regions : sequence, optional
        Vehicle instability regions: objects with ``Omega_lo``, ``Omega_hi`` (rad/s) and
        ``growth_rate_max`` (1/s); optional ``mode_text`` / ``mode`` / ``label``.
    resonance_bands : sequence, optional
        Memo 7.3 resonance bands: objects with ``Omega_lo``, ``Omega_hi`` (rad/s) and
        ``severity`` (dimensionless) or ``growth_rate_max`` (1/s); optional ``family`` and
        ``mode_text`` / ``label``.
    limit : int, optional
        Keep the first ``limit`` bands (>= 0); all by default.

    Returns
    -------
    tuple of DangerBand
        Ranked: bands reached by the operating range first; then those with a growth rate,
        largest first; then those with a severity only, largest first; ties by Omega_lo.
        A growth rate (1/s) and a severity (dimensionless) are not comparable, so a band with
        a growth rate ranks above one with a severity only.

    Raises
    ------
    ValueError
        A bad operating range, limit, or a source item without edges / growth rate / severity.

    References
    ----------
    Tech Memo 104, secs. 4.1, 4.2, 7.3; Bolotin, The Dynamic Stability of Elastic Systems
    (1964), ch. 1-2, sec. 6; Hsu, J. Appl. Mech. 30 (1963) 367 (combination resonances).
    """
    lo, hi = (float(v) for v in operating_range)
    if not (math.isfinite(lo) and math.isfinite(hi) and 0.0 <= lo < hi):
        raise ValueError(f"operating_range = {operating_range!r}: need finite "
                         "0 <= omega_min < omega_max (rad/s)")
    if limit is not None and (not isinstance(limit, int) or limit < 0):
        raise ValueError(f"limit = {limit!r}: must be a non-negative integer")
    operating = (lo, hi)
    bands: list[DangerBand] = []
    if pitch is not None:
        bands += _pitch_bands(pitch, operating)
    if beam_action is not None:
        bands += _beam_action_bands(beam_action, operating)
    if vehicle_regions is not None:
        bands += _generic(vehicle_regions, "vehicle_regions", "vehicle", operating, False)
    if resonance_bands is not None:
        bands += _generic(resonance_bands, "resonance_bands", "resonance", operating, True)

    def key(b: DangerBand) -> tuple:
        if b.growth_rate is not None:
            return (not b.in_operating_range, 0, -b.growth_rate, b.Omega_lo)
        return (not b.in_operating_range, 1, -(b.severity or 0.0), b.Omega_lo)

    ranked = tuple(sorted(bands, key=key))
    return ranked if limit is None else ranked[:limit]


def mechanism_verdicts(bands: Sequence[DangerBand], *,
                       computed: dict[str, bool]) -> tuple[tuple[str, str, str], ...]:
    """One verdict line per mechanism of :data:`MECHANISMS`.

    Parameters
    ----------
    bands : sequence of DangerBand
        From :func:`danger_bands` (all of them, not a truncated list).
    computed : dict of str to bool
        Whether each mechanism (keys of :data:`MECHANISMS`) was computed; a missing key means
        not computed.

    Returns
    -------
    tuple of (str, str, str)
        (key, words, verdict): "not computed", "stable in the operating range", or "unstable:
        N instability regions in the operating range, largest growth rate G 1/s" (for memo
        resonances: "N resonances (memo 7) in the operating range").

    References
    ----------
    Tech Memo 104, secs. 4.1, 4.2, 7.3.
    """
    out = []
    for key, words in MECHANISMS:
        if not computed.get(key, False):
            out.append((key, words, "not computed"))
            continue
        mine = [b for b in bands if b.mechanism == key and b.in_operating_range]
        if not mine:
            out.append((key, words, "stable in the operating range"))
            continue
        noun = "resonances (memo 7)" if key == "resonance" else "instability regions"
        if len(mine) == 1:
            noun = "resonance (memo 7)" if key == "resonance" else "instability region"
        rates = [b.growth_rate for b in mine if b.growth_rate is not None]
        sev = [b.severity for b in mine if b.severity is not None]
        text = f"unstable: {len(mine)} {noun} in the operating range"
        if rates:
            text += f", largest growth rate {max(rates):.3g} 1/s"
        elif sev:
            text += f", largest severity {max(sev):.3g} m/s"
        steady = [b for b in mine if b.cause_text.startswith(STEADY_CAUSE)]
        if steady:  # not parametric: the steady system itself (its growth, e-folding time)
            g = max(b.growth_rate or 0.0 for b in steady)
            text += (f" ({len(steady)} of them {STEADY_CAUSE}: growth rate {g:.3g} 1/s"
                     + (f", e-folding time {1.0 / g:.3g} s)" if g > 0.0 else ")"))
        out.append((key, words, text))
    return tuple(out)


@dataclass(frozen=True)
class DangerSummary:
    """The first screen's data: one verdict per mechanism and the ranked bands.

    Attributes
    ----------
    operating_range : (float, float)
        The case's [omega_min, omega_max] (rad/s).
    verdicts : tuple of (str, str, str)
        (key, mechanism in words, verdict), see :func:`mechanism_verdicts`.
    bands : tuple of DangerBand
        Every band, ranked (see :func:`danger_bands`).

    References
    ----------
    Tech Memo 104, secs. 4.1, 4.2, 7.3.
    """

    operating_range: tuple[float, float]
    verdicts: tuple[tuple[str, str, str], ...]
    bands: tuple[DangerBand, ...]

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready mapping."""
        return {
            "operating_range": [float(v) for v in self.operating_range],
            "verdicts": [{"mechanism": k, "words": w, "verdict": v}
                         for k, w, v in self.verdicts],
            "bands": [b.to_dict() for b in self.bands],
        }


def danger_summary(*, operating_range: tuple[float, float], pitch=None, beam_action=None,
                   vehicle_regions: Sequence | None = None,
                   resonance_bands: Sequence | None = None) -> DangerSummary:
    """Verdicts and ranked bands of every mechanism computed (see :func:`danger_bands`).

    Parameters
    ----------
    operating_range : (float, float)
        [omega_min, omega_max] (rad/s).
    pitch : PitchResult, optional
        Rigid-body pitch; None when not computed.
    beam_action : BeamActionResult, optional
        Beam action; None when not computed.
    vehicle_regions : sequence, optional
        Vehicle instability regions (duck-typed, see the module); None when not computed.
    resonance_bands : sequence, optional
        Memo 7.3 resonance bands (duck-typed, see the module); None when not computed.

    Returns
    -------
    DangerSummary

    References
    ----------
    Tech Memo 104, secs. 4.1, 4.2, 7.3.
    """
    bands = danger_bands(operating_range=operating_range, pitch=pitch, beam_action=beam_action,
                         vehicle_regions=vehicle_regions, resonance_bands=resonance_bands)
    computed = {"pitch": pitch is not None, "beam_action": beam_action is not None,
                "vehicle": vehicle_regions is not None, "resonance": resonance_bands is not None}
    return DangerSummary((float(operating_range[0]), float(operating_range[1])),
                         mechanism_verdicts(bands, computed=computed), bands)
