"""Benchmark: the figures on the memo case.

Times, in the same run (best of ``--repeat``), rendering to SVG + PNG with the pipeline's own
renderer (``present.outputs._render``):
  1. the Campbell diagram (the roots with active forcing and their shell frequencies) against
     the baseline, the diagram that drew everything (every one of the ~42,000 roots and all
     ~660 shell frequencies, redrawn here as it was);
  2. the danger map, and the ranking itself (``danger_summary``) on the memo case's bands.
Also prints the SVG sizes.

``--figures`` instead times the CPU of drawing and saving (SVG + PNG) every figure of the
memo case, as ``flexbooster run`` does it (``present.outputs._figure_files``), now against
``--baseline REV`` (default ``main``) checked out side by side with ``git worktree``: each
code analyses the case once (pickled, not timed), then, alternating, best of ``--repeat``:

* one process drawing the figures one after the other (matplotlib imported first, untimed:
  the first figure still pays matplotlib's warm-up);
* each figure in a fresh process of its own (after the import), as a drawing process of
  ``flexbooster run`` draws its first figure.

Usage::

    OPENBLAS_NUM_THREADS=1 PYTHONPATH=src python benchmarks/bench_presentation.py [--repeat 3]
    OPENBLAS_NUM_THREADS=1 .venv/bin/python benchmarks/bench_presentation.py --figures \
        [--baseline main] [--repeat 3]
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import matplotlib
from baseline_checkout import baseline_checkout

matplotlib.use("Agg")

import numpy as np  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from flexbooster.analysis import analyze  # noqa: E402
from flexbooster.case import memo_case  # noqa: E402
from flexbooster.danger import danger_summary  # noqa: E402
from flexbooster.present.outputs import _render  # noqa: E402
from flexbooster.present.plotting.danger import danger_map  # noqa: E402
from flexbooster.present.plotting.stability import campbell_diagram  # noqa: E402


def _old_campbell(data) -> Figure:
    """The Campbell diagram as drawn with everything (every root, every shell line)."""
    fig = Figure(figsize=(8.0, 6.0))
    ax = fig.add_subplot()
    x = data.Omega_bar
    y_max = float(max(np.max(data.shell_omega_bar, initial=1.0), 1.0)) * 1.05
    segments = [np.column_stack([[x[0], x[-1]], [w, w]]) for w in data.shell_omega_bar]
    ax.add_collection(LineCollection(segments, colors="0.8", linewidths=0.5, zorder=0))
    for c in range(data.curves.shape[0]):
        ax.plot(x, data.curves[c], lw=0.8)
    act = data.root_active
    ax.plot(data.root_Omega_bar[act], data.root_shell_omega_bar[act], "o", ms=3)
    ax.plot(data.root_Omega_bar[~act], data.root_shell_omega_bar[~act], "o", ms=3, mfc="none")
    ax.set_xlim(x[0], x[-1])
    ax.set_ylim(0.0, y_max)
    ax.legend(["curves"], loc="upper left")
    return fig


def _best(fn, repeat: int) -> tuple[float, object]:
    best, out = float("inf"), None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return best, out


ROOT = Path(__file__).resolve().parents[1]
#: Run by each code (PYTHONPATH=its src): "analyse PATH" pickles the memo case's results;
#: "draw PATH [NAMES]" prints the CPU seconds of drawing each figure (JSON).
_CHILD = r"""
import json, pickle, sys, time
mode, path = sys.argv[1], sys.argv[2]
if mode == "analyse":
    from flexbooster.analysis import analyze
    from flexbooster.case import memo_case
    with open(path, "wb") as f:
        pickle.dump(analyze(memo_case()), f)
    raise SystemExit
with open(path, "rb") as f:
    results = pickle.load(f)
from flexbooster.present import outputs
draw = getattr(outputs, "_figure_files", None) or outputs._figure_task  # now, or before
t = time.process_time()
import matplotlib
matplotlib.use("Agg")
import matplotlib.backends.backend_agg, matplotlib.backends.backend_svg
prepare = time.process_time() - t
names = sys.argv[3].split(",") if len(sys.argv) > 3 else list(outputs.figure_names(results))
cpu = {}
for name in names:
    t = time.process_time()
    draw(results, name)
    cpu[name] = time.process_time() - t
print(json.dumps({"prepare": prepare, "cpu": cpu}))
"""


def _child(src: Path, *args: str) -> dict:
    env = dict(os.environ, PYTHONPATH=str(src), OPENBLAS_NUM_THREADS="1")
    env.pop("PYTHONDONTWRITEBYTECODE", None)  # byte-compiled modules, as installed
    out = subprocess.run([sys.executable, "-c", _CHILD, *args], env=env, check=True,
                         capture_output=True, text=True).stdout
    return json.loads(out) if out.strip() else {}


def _best(into: dict, cpu: dict) -> None:
    for name, t in cpu.items():
        into[name] = min(into.get(name, float("inf")), t)


def figures_against(baseline: str, repeat: int) -> None:
    """Print the figures' CPU now and at ``baseline`` (one process; a fresh one per figure)."""
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        with baseline_checkout(baseline, tmp / "baseline") as base:
            codes = {"baseline": base / "src", "now": ROOT / "src"}
            for label, src in codes.items():
                _child(src, "analyse", str(tmp / f"{label}.pkl"))
            warm = {label: {} for label in codes}
            fresh = {label: {} for label in codes}
            prepare = dict.fromkeys(codes, float("inf"))
            for _ in range(repeat):
                for label, src in codes.items():  # alternating
                    pkl = str(tmp / f"{label}.pkl")
                    run = _child(src, "draw", pkl)
                    _best(warm[label], run["cpu"])
                    prepare[label] = min(prepare[label], run["prepare"])
                    for name in run["cpu"]:
                        _best(fresh[label], _child(src, "draw", pkl, name)["cpu"])
    print(f"figures of the memo case, CPU s of drawing each (SVG + PNG), best of {repeat}, "
          f"baseline {baseline}, load average {os.getloadavg()[0]:.2f}")
    print(f"  {'figure':30s} {'one process':>22s} {'fresh process each':>26s}")
    print(f"  {'':30s} {'baseline':>10s} {'now':>10s}   {'baseline':>10s} {'now':>10s}")
    for name in warm["baseline"]:
        print(f"  {name:30s} {warm['baseline'][name]:10.3f} {warm['now'].get(name, 0):10.3f}"
              f"   {fresh['baseline'][name]:10.3f} {fresh['now'].get(name, 0):10.3f}")
    for title, data in (("one process", warm), ("fresh process each", fresh)):
        old, new = sum(data["baseline"].values()), sum(data["now"].values())
        print(f"  total, {title:22s} baseline {old:6.3f}   now {new:6.3f}   "
              f"now / baseline {new / old:5.3f} ({1 - new / old:.0%} less)")
    print(f"  import matplotlib: baseline {prepare['baseline']:.3f}   "
          f"now {prepare['now']:.3f}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--figures", action="store_true",
                        help="the CPU of every figure now against --baseline")
    parser.add_argument("--baseline", default="main", help="commit for --figures")
    args = parser.parse_args()
    if args.figures:
        figures_against(args.baseline, args.repeat)
        return
    results = analyze(memo_case())
    data = results.figures.campbell
    print(f"memo case: {data.root_active.size} roots, {int(data.root_active.sum())} active, "
          f"{data.shell_omega_bar.size} shell frequencies")
    t_old, (svg_old, _) = _best(lambda: _render(_old_campbell(data)), args.repeat)
    t_new, (svg_new, _) = _best(lambda: _render(campbell_diagram(data)), args.repeat)
    print(f"Campbell, everything (baseline):   {t_old:.3f} s, SVG {len(svg_old) / 1e3:.0f} kB")
    print(f"Campbell, significant roots:        {t_new:.3f} s, SVG {len(svg_new) / 1e3:.0f} kB")
    print(f"  ratio baseline / new: {t_old / t_new:.2f}")
    t_rank, summary = _best(lambda: danger_summary(
        operating_range=results.model.omega_range, pitch=results.pitch,
        beam_action=results.beam_action), args.repeat)
    t_map, (svg_map, _) = _best(lambda: _render(danger_map(summary)),
                                args.repeat)
    print(f"danger_summary ({len(summary.bands)} bands): {t_rank * 1e3:.3f} ms")
    print(f"danger map render: {t_map:.3f} s, SVG {len(svg_map) / 1e3:.0f} kB")


if __name__ == "__main__":
    main()
