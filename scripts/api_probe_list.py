"""List the public functions of flexbooster (the ``__all__`` of every module) and whether
tests/test_api_validation.py probes them with a bad argument.

Run: ``PYTHONPATH=src python scripts/api_probe_list.py``.  A function counts as probed when
its name is called (``name(``) in BAD_CALLS or API_CALLS of tests/test_api_validation.py.  The
command line (cli), the presentation layer (present) and the sweep layer are left out: their
inputs are the case file and the options, probed through the command.
"""

from __future__ import annotations

import importlib
import inspect
import pkgutil
import re
from pathlib import Path

import flexbooster

__all__ = ["public_functions"]

SKIP = (".present", ".sweep", ".cli", "__main__")


def public_functions() -> list[tuple[str, str, list[str]]]:
    """(module, name, parameters) of every public function of flexbooster.

    Returns
    -------
    list of tuple
        One entry per function in a module's ``__all__`` defined in that module.
    """
    rows = []
    for info in pkgutil.walk_packages(flexbooster.__path__, "flexbooster."):
        if any(part in info.name for part in SKIP):
            continue
        module = importlib.import_module(info.name)
        for attr in getattr(module, "__all__", []):
            obj = getattr(module, attr, None)
            if inspect.isfunction(obj) and obj.__module__ == info.name:
                rows.append((info.name, attr, list(inspect.signature(obj).parameters)))
    return rows


def main() -> None:
    """Print one line per public function: probed (Y) or not (-), module, name, parameters."""
    tests = (Path(__file__).parents[1] / "tests" / "test_api_validation.py").read_text()
    rows = public_functions()
    probed = 0
    for module, name, params in rows:
        hit = re.search(rf"\b{name}\(", tests) is not None
        probed += hit
        print(f"{'Y' if hit else '-'} {module}.{name}({', '.join(params)})")
    print(f"{probed} of {len(rows)} public functions probed")


if __name__ == "__main__":
    main()
