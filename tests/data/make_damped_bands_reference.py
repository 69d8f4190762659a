"""Write damped_bands_reference.json: the damped beam-action bands of the memo's default case.

The memo's two-cylinder case (the embedded default case text at the time of writing, stored
in the file so that the test reads the very case that was searched) with its default modal
damping (beam 1 %, pitch 0), and the bands of :func:`flexbooster.memo.beam_action.pipeline_bands`
as computed by the dense Lawson kernel stepping one RK4 step at a time (commit 2ffa6ec): edges,
growth-rate maxima, where they are, critical gamma.  The regression test checks that a faster
algorithm finds the same bands to the search's own tolerances (edges 1e-9 of the centre,
growth maxima and critical gamma to their tolerances).

Run from the repository root at that commit:
``OPENBLAS_NUM_THREADS=1 PYTHONPATH=src python tests/data/make_damped_bands_reference.py``
(about 20 s).
"""

from __future__ import annotations

import json
import subprocess
import tomllib
from pathlib import Path

import flexbooster
from flexbooster.case import memo_case_text
from flexbooster.memo.beam_action import pipeline_bands
from flexbooster.model import model_from_case

OUT = Path(__file__).parent / "damped_bands_reference.json"


def main() -> None:
    case = tomllib.loads(memo_case_text())
    model = model_from_case(flexbooster.load_case(case))
    bands = pipeline_bands(model)
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True, check=False).stdout.strip()
    OUT.write_text(json.dumps({"commit": commit, "case": case,
                               "bands": [b.to_dict() for b in bands]}, indent=1) + "\n")
    print(f"{len(bands)} bands -> {OUT}")


if __name__ == "__main__":
    main()
