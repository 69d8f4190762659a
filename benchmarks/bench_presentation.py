"""Benchmark: the figures of issue 17 on the default case.

Times, in the same run (best of ``--repeat``), rendering to SVG + PNG with the pipeline's own
renderer (``present.outputs._render``):
  1. the new Campbell diagram (the roots with active forcing and their shell frequencies) against
     the baseline, the diagram before issue 17 (every one of the ~42,000 roots and all ~660 shell
     frequencies, redrawn here as it was);
  2. the danger map, and the ranking itself (``danger_summary``) on the default case's bands.
Also prints the SVG sizes.

Usage::

    OPENBLAS_NUM_THREADS=1 PYTHONPATH=src python benchmarks/bench_presentation.py [--repeat 3]
"""

from __future__ import annotations

import argparse
import time

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from flexbooster.analysis import analyze  # noqa: E402
from flexbooster.case import default_case  # noqa: E402
from flexbooster.danger import danger_summary  # noqa: E402
from flexbooster.present.outputs import _render  # noqa: E402
from flexbooster.present.plotting.danger import danger_map  # noqa: E402
from flexbooster.present.plotting.stability import campbell_diagram  # noqa: E402


def _old_campbell(data) -> Figure:
    """The Campbell diagram as drawn before issue 17 (every root, every shell line)."""
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


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    results = analyze(default_case())
    data = results.figures.campbell
    print(f"default case: {data.root_active.size} roots, {int(data.root_active.sum())} active, "
          f"{data.shell_omega_bar.size} shell frequencies")
    t_old, (svg_old, _) = _best(lambda: _render(_old_campbell(data)), args.repeat)
    t_new, (svg_new, _) = _best(lambda: _render(campbell_diagram(data)), args.repeat)
    print(f"Campbell, before issue 17 (baseline): {t_old:.3f} s, SVG {len(svg_old) / 1e3:.0f} kB")
    print(f"Campbell, issue 17:                   {t_new:.3f} s, SVG {len(svg_new) / 1e3:.0f} kB")
    print(f"  ratio baseline / new: {t_old / t_new:.2f}")
    t_rank, summary = _best(lambda: danger_summary(
        operating_range=results.model.omega_range, pitch=results.pitch,
        beam_action=results.beam_action), args.repeat)
    t_map, (svg_map, _) = _best(lambda: _render(danger_map(summary, omega_1=results.omega_1)),
                                args.repeat)
    print(f"danger_summary ({len(summary.bands)} bands): {t_rank * 1e3:.3f} ms")
    print(f"danger map render: {t_map:.3f} s, SVG {len(svg_map) / 1e3:.0f} kB")


if __name__ == "__main__":
    main()
