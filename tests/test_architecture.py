"""House rules that a test can enforce: the numerical core imports numpy and scipy only."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

import flexbooster

PACKAGE = Path(flexbooster.__file__).parent
#: Layers allowed to use the input/plotting/report libraries.
THIN_LAYERS = {
    "__init__",
    "analysis",
    "case",
    "cli",
    "io",
    "outputs",
    "summary",
    "units",
    "report",
    "errors",
}
CORE = sorted(p.stem for p in PACKAGE.glob("*.py") if p.stem not in THIN_LAYERS)
FORBIDDEN = ("pydantic", "pint", "matplotlib", "rich", "click", "mpmath", "sympy")


def test_core_modules_exist():
    assert {"geometry", "beam", "pitch"} <= set(CORE)


@pytest.mark.parametrize("module", CORE)
def test_core_imports_numpy_and_scipy_only(module):
    code = (
        f"import sys, flexbooster.{module}\n"
        f"bad = sorted({{m.split('.')[0] for m in sys.modules}} & set({FORBIDDEN!r}))\n"
        "print(','.join(bad))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "", f"flexbooster.{module} pulls in {out.stdout.strip()}"


@pytest.mark.parametrize("path", sorted(PACKAGE.rglob("*.py")), ids=lambda p: p.stem)
def test_explicit_all_and_no_star_imports(path):
    text = path.read_text()
    assert "import *" not in text
    if path.name != "__main__.py":
        assert "__all__" in text, f"{path} lacks __all__"


def test_plotting_never_calls_show():
    for path in (PACKAGE / "present" / "plotting").rglob("*.py"):
        assert ".show(" not in path.read_text(), path
