"""Result records shared by every mechanism's search for unstable thrust frequencies.

:class:`SearchGap` is what a deterministic size or accuracy limit of a search left out (a
harmonic, a tongue order, a part of the Omega range).  Every search returns its gaps beside its
bands, and a verdict built from bands with a gap is "not fully searched", never "stable"
(docs/theory/bands.md).  Numerical core: the standard library only.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

__all__ = ["SearchGap", "gaps_text"]


@dataclass(frozen=True)
class SearchGap:
    """A part of a search that a size or accuracy limit left out.

    Attributes
    ----------
    stage : str
        The mechanism searched: ``"pitch"``, ``"beam_action"``, ``"vehicle"``,
        ``"resonance"``.
    reason : str
        What was left out and why, in words, naming the limit and its value.
    limit : str
        The setting that limits the search (a case field such as ``"truncation.S"`` or a
        named constant such as ``"PITCH_MAX_TONGUE"``).
    k : int or None
        Circumferential harmonic left out, where the search is per harmonic.
    order : int or None
        Order left out (a Mathieu tongue r, a resonance order j), where there is one.
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

    Returns
    -------
    str
        The words a verdict line uses for a search with gaps.
    """
    if not gaps:
        raise ValueError("gaps: empty, a fully searched mechanism has no gap text")
    return "not fully searched: " + "; ".join(g.reason for g in gaps)
