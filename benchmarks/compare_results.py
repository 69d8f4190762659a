"""Compare two results.json files key by key (no number changed beyond a tolerance).

Usage::

    python benchmarks/compare_results.py OLD/results.json NEW/results.json [--rtol 1e-12]

Every key of OLD must be in NEW with the same value: strings and booleans equal, numbers to
``rtol`` relative (absolute for |value| < 1e-300... see ``close``); keys only in NEW are listed
as added.  Exit status 1 when anything differs.
"""

from __future__ import annotations

import argparse
import json
import math
import sys

__all__ = ["compare"]


def close(a: float, b: float, rtol: float) -> bool:
    """|a - b| <= rtol max(|a|, |b|), or both tiny (below rtol in absolute value)."""
    return a == b or abs(a - b) <= rtol * max(abs(a), abs(b)) or max(abs(a), abs(b)) < rtol


def compare(old, new, rtol: float, path: str = "", out: list | None = None) -> list:
    """Differences between ``old`` and ``new`` (nested dicts and lists) as (path, text) pairs."""
    out = [] if out is None else out
    if isinstance(old, dict):
        if not isinstance(new, dict):
            out.append((path, "not a mapping any more"))
            return out
        for key in old:
            if key not in new:
                out.append((f"{path}.{key}", "missing"))
            else:
                compare(old[key], new[key], rtol, f"{path}.{key}", out)
        return out
    if isinstance(old, list):
        if not isinstance(new, list) or len(new) != len(old):
            out.append((path, f"length {len(old)} -> {len(new) if isinstance(new, list) else new}"))
            return out
        for n, (x, y) in enumerate(zip(old, new, strict=True)):
            compare(x, y, rtol, f"{path}[{n}]", out)
        return out
    if isinstance(old, bool) or isinstance(old, str) or old is None:
        if old != new:
            out.append((path, f"{old!r} -> {new!r}"))
        return out
    if not (isinstance(new, int | float) and not isinstance(new, bool)):
        out.append((path, f"{old!r} -> {new!r}"))
    elif not close(float(old), float(new), rtol) or math.isnan(float(new)):
        out.append((path, f"{old!r} -> {new!r}"))
    return out


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("--rtol", type=float, default=1e-12)
    ap.add_argument("--ignore", action="append", default=["flexbooster_version", "units"],
                    help="top-level keys not compared (default: flexbooster_version, units)")
    args = ap.parse_args()
    with open(args.old) as f:
        old = json.load(f)
    with open(args.new) as f:
        new = json.load(f)
    for key in args.ignore:
        old.pop(key, None)
    diffs = compare(old, new, args.rtol)
    added = sorted(set(new) - set(old) - set(args.ignore))
    print(f"{args.old} vs {args.new}: {len(diffs)} differences at rtol {args.rtol:g}; "
          f"added keys: {', '.join(added) or 'none'}")
    for path, text in diffs[:20]:
        print(f"  {path}: {text}")
    return 1 if diffs else 0


if __name__ == "__main__":
    sys.exit(main())
