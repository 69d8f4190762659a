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

from .bands import MECHANISMS, Band, SearchGap, gaps_text

__all__ = ["RankedBand", "DangerSummary", "Verdict", "STEADY_CAUSE", "NEGLIGIBLE_GROWTH",
           "NEGLIGIBLE_AMPLIFICATION", "UNSTABLE_AMPLIFICATION", "UNSTABLE_E_FOLDING",
           "AMPLIFICATION_EXPONENT_MAX", "band_measures", "band_status", "danger_bands",
           "danger_summary", "mechanism_verdicts", "overall_verdict"]

_KIND_WORDS = {"simple": "simple", "sum": "sum combination",
               "difference": "difference combination"}
#: The cause of a "steady" band: the system under the steady thrust alone (gamma = 0) is not
#: stable (flutter or divergence, Beal 1965; a slow growth of the rigid pitch), not parametric.
STEADY_CAUSE = "unstable without pulsation"


#: Growth rate below which a band is negligible (1/s): an e-folding time above 1e6 s (11.6
#: days), longer than any excitation of a launch vehicle (docs/theory/verdicts.md).
NEGLIGIBLE_GROWTH = 1e-6
#: With a duration T: amplification exp(sigma T) below which a band is negligible (the motion
#: grows less than 10 % over the whole excitation).
NEGLIGIBLE_AMPLIFICATION = 1.1
#: With a duration T: amplification exp(sigma T) above which an open band is unstable.
UNSTABLE_AMPLIFICATION = 10.0
#: Without a duration: e-folding time 1 / sigma (s) below which an open band is unstable.
UNSTABLE_E_FOLDING = 10.0
#: Largest sigma T whose exp is stored (exp(700) ~ 1e304); above it amplification is None.
AMPLIFICATION_EXPONENT_MAX = 700.0


def band_measures(band: Band, *, gamma: float, duration: float | None) -> Band:
    """The band with its margin critical_gamma / gamma (where gamma > 0 and the band is
    damped) and its growth exponent sigma T and amplification exp(sigma T) over the
    duration T (None without one). A resonance is returned unchanged.

    Parameters
    ----------
    band : Band
        A band of any mechanism.
    gamma : float
        The case's pulsation amplitude, >= 0.
    duration : float or None
        Duration of the excitation T (s), > 0, or None.
    """
    if band.mechanism == "resonance":
        return band
    margin = band.critical_gamma / gamma if gamma > 0.0 and band.critical_gamma > 0.0 else None
    exponent = amplification = None
    if duration is not None:
        exponent = band.growth_rate_max * float(duration)  # sigma T
        if exponent <= AMPLIFICATION_EXPONENT_MAX:
            amplification = math.exp(exponent)
    return dataclasses.replace(band, margin=margin, growth_exponent=exponent,
                               amplification=amplification)


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


def _cause(band: Band) -> str:
    """The mechanism of a band in words."""
    if band.mechanism == "resonance":
        return f"resonance (memo 7): family {band.order}: {band.cause}"
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


@dataclass(frozen=True)
class RankedBand:
    """A band of the danger ranking: the band and whether the operating range reaches it.

    Attributes
    ----------
    band : Band
        The band (Omega in rad/s).
    in_operating_range : bool
        True when the band overlaps the case's operating range [omega_min, omega_max].
    """

    band: Band
    in_operating_range: bool

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
        """The mechanism in words."""
        return _cause(self.band)

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready mapping (plain floats, str, bool; None kept)."""
        lo_hz, hi_hz = self.hz
        return {"mechanism": self.mechanism, "Omega_lo": float(self.Omega_lo),
                "Omega_hi": float(self.Omega_hi), "Omega_lo_hz": float(lo_hz),
                "Omega_hi_hz": float(hi_hz),
                "growth_rate": None if self.growth_rate is None else float(self.growth_rate),
                "severity": None if self.severity is None else float(self.severity),
                "mode_text": self.mode_text, "cause_text": self.cause_text,
                "in_operating_range": bool(self.in_operating_range)}


def _operating(operating_range: tuple[float, float]) -> tuple[float, float]:
    lo, hi = (float(v) for v in operating_range)
    if not (math.isfinite(lo) and math.isfinite(hi) and 0.0 <= lo < hi):
        raise ValueError(f"operating_range = {operating_range!r}: need finite "
                         "0 <= omega_min < omega_max (rad/s)")
    return lo, hi


def danger_bands(bands: Sequence[Band], *, operating_range: tuple[float, float],
                 limit: int | None = None) -> tuple[RankedBand, ...]:
    """Every band, most dangerous first: those the operating range reaches, then by growth rate,
    then resonances by severity; ties by Omega_lo.

    Parameters
    ----------
    bands : sequence of Band
        The bands of every mechanism computed (Omega in rad/s).
    operating_range : (float, float)
        [omega_min, omega_max] of the case (rad/s), finite, 0 <= omega_min < omega_max.
    limit : int, optional
        Keep the first ``limit`` (>= 0); all by default.
    """
    lo, hi = _operating(operating_range)
    if limit is not None and (not isinstance(limit, int) or limit < 0):
        raise ValueError(f"limit = {limit!r}: must be a non-negative integer")
    ranked = [RankedBand(b, b.Omega_hi >= lo and b.Omega_lo <= hi) for b in bands]

    def key(r: RankedBand) -> tuple:
        if r.growth_rate is not None:
            return (not r.in_operating_range, 0, -r.growth_rate, r.Omega_lo)
        return (not r.in_operating_range, 1, -(r.severity or 0.0), r.Omega_lo)

    ranked.sort(key=key)
    return tuple(ranked if limit is None else ranked[:limit])


def mechanism_verdicts(ranked: Sequence[RankedBand], *, computed: Mapping[str, bool],
                       gaps: Sequence[SearchGap] = ()) -> tuple[tuple[str, str, str], ...]:
    """(key, words, verdict) per mechanism of :data:`flexbooster.bands.MECHANISMS`: "not
    computed", "stable in the operating range", "not fully searched: ..." or "unstable: N ..."
    (with "; not fully searched: ..." when a gap remains).

    Parameters
    ----------
    ranked : sequence of RankedBand
        From :func:`danger_bands` (all of them).
    computed : mapping of str to bool
        Whether each mechanism was computed; a missing key means not computed.
    gaps : sequence of SearchGap
        What the searches left out (``stage`` names the mechanism).
    """
    out = []
    for key, words in MECHANISMS:
        if not computed.get(key, False):
            out.append((key, words, "not computed"))
            continue
        mine = [b for b in ranked if b.mechanism == key and b.in_operating_range]
        left = [g for g in gaps if g.stage == key]
        if not mine:
            out.append((key, words, gaps_text(left) if left else
                        "stable in the operating range"))
            continue
        resonance = key == "resonance"
        noun = ("resonance" if resonance else "instability region") + \
            ("s" if len(mine) > 1 else "") + (" (memo 7)" if resonance else "")
        text = f"unstable: {len(mine)} {noun} in the operating range"
        if resonance:
            text += f", largest severity {max(b.severity or 0.0 for b in mine):.3g} m/s"
        else:
            text += f", largest growth rate {max(b.growth_rate for b in mine):.3g} 1/s"
        steady = [b for b in mine if b.band.kind == "steady"]
        if steady:  # not parametric: the steady system itself (its growth, e-folding time)
            g = max(b.growth_rate for b in steady)
            text += (f" ({len(steady)} of them {STEADY_CAUSE}: growth rate {g:.3g} 1/s"
                     + (f", e-folding time {1.0 / g:.3g} s)" if g > 0.0 else ")"))
        if left:
            text += "; " + gaps_text(left)
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
    bands : tuple of RankedBand
        Every band, ranked (see :func:`danger_bands`).
    """

    operating_range: tuple[float, float]
    verdicts: tuple[tuple[str, str, str], ...]
    bands: tuple[RankedBand, ...]

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready mapping."""
        return {"operating_range": [float(v) for v in self.operating_range],
                "verdicts": [{"mechanism": k, "words": w, "verdict": v}
                             for k, w, v in self.verdicts],
                "bands": [b.to_dict() for b in self.bands]}


def danger_summary(*, operating_range: tuple[float, float], bands: Mapping[str, Sequence[Band]],
                   gaps: Sequence[SearchGap] = ()) -> DangerSummary:
    """Verdicts and ranked bands of every mechanism computed.

    Parameters
    ----------
    operating_range : (float, float)
        [omega_min, omega_max] (rad/s).
    bands : mapping of str to sequence of Band
        The bands of each mechanism computed, by key of :data:`flexbooster.bands.MECHANISMS`.
    gaps : sequence of SearchGap
        What the searches left out.
    """
    for key in bands:
        if key not in dict(MECHANISMS):
            raise ValueError(f"bands: unknown mechanism {key!r}")
    ranked = danger_bands([b for found in bands.values() for b in found],
                          operating_range=operating_range)
    computed = {key: True for key in bands}
    lo, hi = _operating(operating_range)
    return DangerSummary((lo, hi), mechanism_verdicts(ranked, computed=computed, gaps=gaps),
                         ranked)
