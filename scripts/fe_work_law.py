"""The FE work of the vehicle stages against its up-front estimate, on tubes of 89-3,846 DOFs
(docs/theory/robustness.md, "How far the estimates are from the run").

Each tube is ``tests/data/long_tube_case.toml`` (stiffened steel, k_max = 6, 6 modes, 1 %
damping) at another length and radius, so that the mesh grows; damping certifies its
harmonics, so the regions stage is the harmonics' builds and their certificates. For each it
prints the mesh DOFs, the CPU time of the stages "vehicle modes" and "vehicle instability
regions" of ``analyze`` (no figures) and the estimate's parts "vehicle modes" and "vehicle
regions" (``cost.estimate_vehicle_cost``), with their ratios. Run on an idle core: the laws of
``cost.py`` were fitted so that every ratio estimate / run is above 1.

Usage::

    OPENBLAS_NUM_THREADS=1 PYTHONPATH=src python scripts/fe_work_law.py [--large]
"""

from __future__ import annotations

import argparse
import copy
import tempfile
import time
import tomllib
from pathlib import Path

import flexbooster
from flexbooster.analysis import analyze
from flexbooster.model import vehicle_from_case
from flexbooster.shell_of_revolution import mesh_vehicle

ROOT = Path(__file__).resolve().parent.parent
SMALL = [(length, 1.854) for length in (8.0, 20.0, 45.0, 90.0, 150.0, 248.341)]
LARGE = [(248.341, 0.8), (400.0, 0.8), (400.0, 0.6)]  # 1,840, 2,911 and 3,846 DOFs


def _toml(data: dict) -> str:
    """The case as TOML (plain keys, inline tables, then sub-tables)."""
    def value(v) -> str:
        if isinstance(v, dict):
            return "{" + ", ".join(f"{k} = {value(x)}" for k, x in v.items()) + "}"
        if isinstance(v, list):
            return "[" + ", ".join(value(x) for x in v) + "]"
        return repr(v) if isinstance(v, bool | int | float) else f'"{v}"'

    lines = [f"{k} = {value(v)}" for k, v in data.items() if not isinstance(v, dict)]
    for name, table in data.items():
        if isinstance(table, dict):
            lines += ["", f"[{name}]"] + [f"{k} = {value(v)}" for k, v in table.items()]
    return "\n".join(lines).replace("True", "true").replace("False", "false") + "\n"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--large", action="store_true", help="the tubes of 1,840-3,846 DOFs "
                        "(about two minutes more)")
    args = parser.parse_args()
    base = tomllib.loads((ROOT / "tests/data/long_tube_case.toml").read_text())
    base["max_seconds"] = 1e5
    base["vehicle"]["k_max"] = 6
    print(f"{'DOFs':>5} {'modes run':>9} {'est':>7} {'ratio':>5} {'regions run':>11} {'est':>7} "
          f"{'ratio':>5}")
    for length, radius in SMALL + (LARGE if args.large else []):
        data = copy.deepcopy(base)
        data["vehicle"]["segments"][0].update(length=f"{length} m", radius=f"{radius} m")
        data["output"]["stations"] = [{"name": "forward", "station": length}]
        with tempfile.TemporaryDirectory() as tmp:
            path = Path(tmp) / "tube.toml"
            path.write_text(_toml(data))
            case = flexbooster.load_case(path)
        dofs = mesh_vehicle(vehicle_from_case(case)).n_full
        marks, parts = [], {}

        def progress(name: str, marks=marks) -> None:
            marks.append((name, time.process_time()))

        def on_estimate(estimate, budget, parts=parts) -> None:
            parts.update(estimate.parts)

        analyze(case, progress=progress, figures=False, on_estimate=on_estimate)
        marks.append(("end", time.process_time()))
        stage = {a[0]: b[1] - a[1] for a, b in zip(marks[:-1], marks[1:], strict=True)}
        run_m, run_r = stage["vehicle modes"], stage["vehicle instability regions"]
        est_m = parts["vehicle modes"]
        est_r = sum(v for k, v in parts.items() if k.startswith("vehicle") and k not in (
            "vehicle modes", "vehicle forced response"))
        print(f"{dofs:5d} {run_m:9.3f} {est_m:7.3f} {est_m / run_m:5.2f} {run_r:11.3f} "
              f"{est_r:7.3f} {est_r / run_r:5.2f}", flush=True)


if __name__ == "__main__":
    main()
