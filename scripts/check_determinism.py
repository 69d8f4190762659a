"""Acceptance "two runs of the default case: every output file byte-identical".

Runs ``python -m flexbooster run -q -o DIR`` (the embedded default case, figures, vehicle
regions, the default worker count) twice into two temporary folders and compares every file
byte for byte; prints the file count, the differing files (none expected) and the run times.
The test suite checks the same on a reduced case (tests/test_cli.py
::test_two_runs_write_byte_identical_files); this script is the full-size check (about a
minute).  Run: ``PYTHONPATH=src python scripts/check_determinism.py``.
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

__all__ = ["compare_runs"]


def compare_runs(folder: Path) -> tuple[list[str], list[str], list[float]]:
    """Two runs of the default case into ``folder``/a and ``folder``/b.

    Parameters
    ----------
    folder : pathlib.Path
        An empty folder.

    Returns
    -------
    tuple
        (every file name, the names whose bytes differ or that only one run wrote, the two
        run times in s).
    """
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1")
    times = []
    for name in ("a", "b"):
        start = time.perf_counter()
        subprocess.run([sys.executable, "-m", "flexbooster", "run", "-q", "-o",
                        str(folder / name)], check=True, env=env)
        times.append(time.perf_counter() - start)
    files = sorted({p.name for p in (folder / "a").iterdir()}
                   | {p.name for p in (folder / "b").iterdir()})
    differ = [n for n in files if not ((folder / "a" / n).is_file()
                                       and (folder / "b" / n).is_file()
                                       and (folder / "a" / n).read_bytes()
                                       == (folder / "b" / n).read_bytes())]
    return files, differ, times


def main() -> None:
    """Print the comparison; exit 1 when a file differs."""
    with tempfile.TemporaryDirectory() as tmp:
        files, differ, times = compare_runs(Path(tmp))
    print(f"{len(files)} files, {len(differ)} differ {differ}; runs "
          f"{times[0]:.1f} s and {times[1]:.1f} s")
    sys.exit(1 if differ else 0)


if __name__ == "__main__":
    main()
