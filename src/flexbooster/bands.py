"""Result records shared by every mechanism's search: :class:`Band`, a band of thrust
frequencies in which a mechanism is unstable or resonant, and :class:`SearchGap`, what a
size or accuracy limit left out (a verdict with a gap is "not fully searched", never
"stable"; docs/theory/bands.md). Standard library only.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

__all__ = ["Band", "BandMode", "KINDS", "MECHANISMS", "NEGLIGIBLE_GROWTH", "SearchGap",
           "gaps_text", "CRITICAL_DAMPING_COUNT"]

#: Growth rate below which a band is negligible (1/s): an e-folding time above 1e6 s (11.6
#: days), longer than any excitation of a launch vehicle (docs/theory/verdicts.md).
NEGLIGIBLE_GROWTH = 1e-6
#: The fastest-growing bands of each mechanism whose critical damping ratio is computed (each
#: is a root search over growth maxima, about a second): a deterministic bound on that work.
CRITICAL_DAMPING_COUNT = 8


@dataclass(frozen=True)
class SearchGap:
    """A part of a search that a size or accuracy limit left out.

    Attributes
    ----------
    stage : str
        The mechanism searched: ``"pitch"``, ``"beam_action"``, ``"vehicle"``, ``"resonance"``.
    reason : str
        What was left out and why, naming the limit and its value.
    limit : str
        The limiting setting (a case field such as ``"truncation.S"`` or a named constant).
    k, order : int or None
        Circumferential harmonic, and order (tongue r, resonance j), left out where any.
    Omega_lo, Omega_hi : float or None
        The part of the thrust-frequency range left out (rad/s), where it is one interval.
    """

    stage: str
    reason: str
    limit: str
    k: int | None = None
    order: int | None = None
    Omega_lo: float | None = None
    Omega_hi: float | None = None

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready mapping (None kept)."""
        return {"stage": self.stage, "reason": self.reason, "limit": self.limit,
                "k": None if self.k is None else int(self.k),
                "order": None if self.order is None else int(self.order),
                "Omega_lo": None if self.Omega_lo is None else float(self.Omega_lo),
                "Omega_hi": None if self.Omega_hi is None else float(self.Omega_hi)}


def gaps_text(gaps: tuple[SearchGap, ...] | list[SearchGap]) -> str:
    """The gaps of a search in one line: "not fully searched: <reason>; <reason>".

    Parameters
    ----------
    gaps : sequence of SearchGap
        At least one gap.
    """
    if not gaps:
        raise ValueError("gaps: empty, a fully searched mechanism has no gap text")
    return "not fully searched: " + "; ".join(g.reason for g in gaps)


@dataclass(frozen=True)
class BandMode:
    """One mode taking part in a band.

    Attributes
    ----------
    label : str
        The mode in words, e.g. "rigid pitch", "bending 2", "radial 1 (k = 3)".
    index : int
        Index in its mechanism's list of modes (ascending frequency); a memo shell's branch m.
    k, order, type : int or None, int or None, str or None
        Circumferential harmonic; sign changes along the meridian (vehicle) or axial j (memo
        shells); "axial", "torsional", "breathing", "bending", "radial", where known.
    omega, share : float or None
        Its frequency under the steady thrust (rad/s) and the dominating unloaded mode's share.
    cylinder : int or None
        The memo's cylinder d of a shell mode.
    """

    label: str
    index: int = 0
    k: int | None = None
    order: int | None = None
    type: str | None = None
    omega: float | None = None
    share: float | None = None
    cylinder: int | None = None

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready mapping (None kept)."""
        return {"label": self.label, "index": int(self.index),
                "k": None if self.k is None else int(self.k),
                "order": None if self.order is None else int(self.order),
                "type": self.type, "omega": None if self.omega is None else float(self.omega),
                "share": None if self.share is None else float(self.share),
                "cylinder": None if self.cylinder is None else int(self.cylinder)}


#: Mechanisms that produce bands: (key, words).
MECHANISMS: tuple[tuple[str, str], ...] = (
    ("pitch", "rigid-body pitch (memo 4.2)"),
    ("beam_action", "beam action (memo 4.1)"),
    ("vehicle", "vehicle parametric regions"),
    ("resonance", "memo resonances (memo 7.3)"),
)
#: Kinds of band: parametric regions ("simple": Omega near 2 omega_i / j, "sum" and
#: "difference": (omega_i +- omega_k) / j), "steady" (the system under the steady thrust alone
#: is not stable) and "resonance" (a forced resonance of memo 7.3).
KINDS = ("simple", "sum", "difference", "steady", "resonance")


@dataclass(frozen=True)
class Band:
    """A band of thrust frequencies Omega in which a mechanism is unstable or resonant.

    Attributes
    ----------
    mechanism : str
        A key of :data:`MECHANISMS`.
    Omega_lo, Omega_hi : float
        Edges (rad/s): |rho|_max = 1 (a region), or the lowest and highest root (a resonance).
    kind : str
        One of :data:`KINDS`.
    order : int
        j of 2 omega_i / j or (omega_i +- omega_k) / j (tongue r); a resonance's family.
    modes : tuple of BandMode
        The modes involved (the most severe root's shell mode first for a resonance).
    growth_rate_max, Omega_at_max, Omega_center : float
        Largest growth rate inside (1/s; 0 for a resonance), where (rad/s), analytic centre.
    critical_gamma : float
        Smallest gamma at which the band exists; 0 without damping.
    clipped : bool
        An edge is an end of the Omega range searched.
    k : int or None
        Circumferential harmonic of a vehicle region.
    severity, severity_rel : float or None
        Resonance: secular growth rate of the shell mode's surface displacement (m/s,
        docs/theory/severity.md) and over the table's largest.
    n_roots : int
        Resonance: roots of the stability table in the band; 0 for a region.
    families : tuple of int
        Resonance: families (memo 7.3) of the band's roots.
    cause : str
        The forcing or mechanism in words, where the kind alone does not say it.
    critical_damping_ratio : float or None
        Smallest modal damping ratio of the band's modes that closes it at the case's gamma;
        None where not computed.
    margin : float or None
        critical_gamma / gamma at the case's gamma (< 1: open); None where not set.
    growth_exponent, amplification : float or None
        sigma T and exp(sigma T) over the excitation's duration T (``thrust.duration``); None
        without a duration (amplification also past exp(700)).
    steady_amplitude, steady_acceleration : float or None
        Resonance: the damped steady amplitude (m) and acceleration (m/s^2) of the resonant
        mode's largest surface displacement at the case's modal damping; None undamped.
    """

    mechanism: str
    Omega_lo: float
    Omega_hi: float
    kind: str
    order: int
    modes: tuple[BandMode, ...]
    growth_rate_max: float
    Omega_at_max: float
    Omega_center: float
    critical_gamma: float = 0.0
    clipped: bool = False
    k: int | None = None
    severity: float | None = None
    severity_rel: float | None = None
    n_roots: int = 0
    families: tuple[int, ...] = ()
    cause: str = ""
    critical_damping_ratio: float | None = None
    margin: float | None = None
    growth_exponent: float | None = None
    amplification: float | None = None
    steady_amplitude: float | None = None
    steady_acceleration: float | None = None

    def __post_init__(self) -> None:
        if self.mechanism not in dict(MECHANISMS):
            raise ValueError(f"mechanism = {self.mechanism!r}: must be one of "
                             f"{', '.join(dict(MECHANISMS))}")
        if self.kind not in KINDS:
            raise ValueError(f"kind = {self.kind!r}: must be one of {', '.join(KINDS)}")
        lo, hi = float(self.Omega_lo), float(self.Omega_hi)
        if not (math.isfinite(lo) and math.isfinite(hi) and 0.0 <= lo <= hi):
            raise ValueError(f"Omega_lo, Omega_hi = {lo!r}, {hi!r}: need finite "
                             "0 <= Omega_lo <= Omega_hi (rad/s)")
        if not math.isfinite(float(self.growth_rate_max)):
            raise ValueError(f"growth_rate_max = {self.growth_rate_max!r}: must be finite")

    @property
    def width(self) -> float:
        """Omega_hi - Omega_lo (rad/s)."""
        return self.Omega_hi - self.Omega_lo

    @property
    def hz(self) -> tuple[float, float]:
        """The edges in Hz."""
        return self.Omega_lo / (2.0 * math.pi), self.Omega_hi / (2.0 * math.pi)

    @property
    def e_folding_s(self) -> float | None:
        """Time in which the largest growth multiplies the motion by e: 1 / growth_rate_max
        (s); None without growth (a resonance, a band at its edge)."""
        return 1.0 / self.growth_rate_max if self.growth_rate_max > 0.0 else None

    @property
    def mode_text(self) -> str:
        """The modes in words, joined by " + "."""
        return " + ".join(m.label for m in self.modes) or "-"

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready mapping: every attribute, the width and the edges in Hz."""
        lo_hz, hi_hz = self.hz
        return {
            "mechanism": self.mechanism, "kind": self.kind, "order": int(self.order),
            "k": None if self.k is None else int(self.k),
            "modes": [m.to_dict() for m in self.modes],
            "Omega_lo": float(self.Omega_lo), "Omega_hi": float(self.Omega_hi),
            "Omega_lo_hz": float(lo_hz), "Omega_hi_hz": float(hi_hz),
            "width": float(self.width), "growth_rate_max": float(self.growth_rate_max),
            "Omega_at_max": float(self.Omega_at_max),
            "Omega_center": float(self.Omega_center),
            "critical_gamma": float(self.critical_gamma), "clipped": bool(self.clipped),
            "severity": None if self.severity is None else float(self.severity),
            "severity_rel": None if self.severity_rel is None else float(self.severity_rel),
            "n_roots": int(self.n_roots), "families": [int(f) for f in self.families],
            "cause": self.cause, "e_folding_s": _opt(self.e_folding_s),
            "critical_damping_ratio": _opt(self.critical_damping_ratio),
            "margin": _opt(self.margin), "growth_exponent": _opt(self.growth_exponent),
            "amplification": _opt(self.amplification),
            "steady_amplitude": _opt(self.steady_amplitude),
            "steady_acceleration": _opt(self.steady_acceleration),
        }


def _opt(value: float | None) -> float | None:
    """A float for JSON, None kept."""
    return None if value is None else float(value)
