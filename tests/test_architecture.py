"""House rules that a test can enforce (docs/architecture.md).

* the layers and which may import which (static: every ``import`` of every module);
* the numerical core imports numpy and scipy only (at run time, in a fresh interpreter);
* presentation takes result types only: from the core it imports classes (result dataclasses)
  and constants, never a function;
* every module has an explicit ``__all__`` and no star import; plotting never calls ``show``;
* every public function and class of the package documents every parameter (numpydoc).
"""

from __future__ import annotations

import ast
import importlib
import inspect
import re
import subprocess
import sys
from pathlib import Path

import pytest

import flexbooster

PACKAGE = Path(flexbooster.__file__).parent

#: Layer of each top-level module or subpackage of flexbooster (docs/architecture.md).
LAYER = {
    "errors": "input", "units": "input", "checks": "input", "case": "input",
    "vehicle_case": "input", "flight_case": "input",
    "memo": "core", "floquet": "core", "bands": "core", "shell_of_revolution": "core",
    "dynamics": "core", "flight": "core",
    "model": "model", "cost": "model", "_threads": "pipeline",
    "results": "results", "danger": "results", "flight_results": "results",
    "analysis": "pipeline", "flight_stage": "pipeline",
    "present": "present", "sweep": "sweep", "cli": "cli", "__init__": "api", "__main__": "cli",
}
#: Which layers a layer may import (itself included).
ALLOWED = {
    "input": {"input"},
    "infra": {"infra"},
    "core": {"core", "checks"},
    "model": {"model", "core", "input"},
    "results": {"results", "core", "input"},
    "pipeline": {"pipeline", "infra", "results", "model", "core", "input"},
    "present": {"present", "infra", "results", "core-types", "input", "api"},
    "sweep": {"sweep", "infra", "pipeline", "results", "model", "core", "input", "present",
              "api"},
    "cli": {"cli", "infra", "sweep", "present", "pipeline", "results", "model", "core", "input",
            "api"},
    "api": {"api"},
}
CORE_THIRD_PARTY = {"numpy", "scipy"}
FORBIDDEN_IN_CORE = ("pydantic", "pint", "matplotlib", "rich", "click", "mpmath", "sympy",
                     "dask", "xarray", "threadpoolctl")
MODULES = sorted(p for p in PACKAGE.rglob("*.py"))


def _name(path: Path) -> str:
    rel = path.relative_to(PACKAGE.parent).with_suffix("")
    parts = list(rel.parts)
    if parts[-1] == "__init__":
        parts = parts[:-1]
    return ".".join(parts)


def _layer(module: str) -> str:
    parts = module.split(".")
    top = parts[1] if len(parts) > 1 else "__init__"
    if top == "checks":
        return "checks"
    return LAYER[top]


def _imports(path: Path) -> list[tuple[str, list[str], int]]:
    """(absolute module, imported names, line) of every import in a module (incl. lazy)."""
    tree = ast.parse(path.read_text())
    me = _name(path).split(".")
    package = me if path.name == "__init__.py" else me[:-1]
    out = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            out += [(a.name, [], node.lineno) for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package[: len(package) - node.level + 1]
                mod = ".".join(base + ([node.module] if node.module else []))
            else:
                mod = node.module or ""
            out.append((mod, [a.name for a in node.names], node.lineno))
    return out


def test_every_module_has_a_layer():
    for path in MODULES:
        assert _layer(_name(path)) in ALLOWED or _layer(_name(path)) == "checks", path


@pytest.mark.parametrize("path", MODULES, ids=lambda p: _name(p))
def test_layers_import_only_what_they_may(path):
    me = _name(path)
    mine = _layer(me)
    allowed = ALLOWED["core"] if mine == "checks" else ALLOWED[mine]
    for mod, names, line in _imports(path):
        if not mod.startswith("flexbooster"):
            if mine in ("core", "checks"):
                assert mod.split(".")[0] in CORE_THIRD_PARTY | set(sys.stdlib_module_names), (
                    f"{me}:{line} imports {mod}: the numerical core uses numpy and scipy only")
            if mine == "infra":
                assert mod.split(".")[0] in sys.stdlib_module_names, (
                    f"{me}:{line} imports {mod}: infrastructure uses the standard library only")
            continue
        if mod == "flexbooster" and names == ["__version__"]:
            continue  # the version string
        targets = [mod] if mod != "flexbooster" else [f"flexbooster.{n}" for n in names]
        for target in targets:
            theirs = _layer(target)
            if mine == "present" and theirs == "core":
                # presentation reads result types: classes and constants, never a solver
                module = importlib.import_module(target)
                assert names, f"{me}:{line} imports the core module {target} as a whole"
                for n in names:
                    obj = getattr(module, n)
                    assert not inspect.ismodule(obj), (
                        f"{me}:{line} imports the core module {target}.{n}: import its result "
                        "types by name")
                    assert inspect.isclass(obj) or not callable(obj), (
                        f"{me}:{line} imports the function {target}.{n}: presentation must "
                        "draw stored results, not compute them")
                continue
            if theirs == "checks":
                theirs = "checks" if mine in ("core", "checks") else "input"
            assert theirs in allowed or theirs == mine, (
                f"{me}:{line} ({mine}) imports {target} ({theirs}); allowed: {sorted(allowed)}")


def test_nothing_in_the_product_imports_the_tests_reference_package():
    for path in MODULES:
        for mod, _, line in _imports(path):
            assert mod.split(".")[0] != "reference", f"{_name(path)}:{line} imports {mod}"


CORE_MODULES = [_name(p) for p in MODULES if _layer(_name(p)) in ("core", "checks")]


def test_core_imports_numpy_and_scipy_only_at_run_time():
    # one interpreter imports every core module in turn and notes, after each, the forbidden
    # packages that appeared: the union is what any one of them pulls in (imports only add to
    # sys.modules), and the first module after which a package appears is the one that brings it
    code = (
        "import importlib, sys\n"
        f"forbidden = set({FORBIDDEN_IN_CORE!r})\n"
        "seen = set()\n"
        f"for name in {CORE_MODULES!r}:\n"
        "    importlib.import_module(name)\n"
        "    bad = {m.split('.')[0] for m in sys.modules} & forbidden - seen\n"
        "    seen |= bad\n"
        "    if bad:\n"
        "        print(name, 'pulls in', ','.join(sorted(bad)))\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert len(CORE_MODULES) > 40 and "flexbooster.floquet" in CORE_MODULES
    assert out.stdout.strip() == "", out.stdout


@pytest.mark.slow
def test_default_analysis_imports_neither_dask_nor_scipy_optimize():
    # a sixth and a fifth of a run's start: scipy.optimize (with scipy.interpolate)
    # is imported only where a root is solved (a pitch tongue in the range, a flutter
    # thrust), and pint without dask (flexbooster.units._pint); dask still imports afterwards
    code = (
        "import sys, tomllib\n"
        "from flexbooster import analysis, case\n"
        "d = tomllib.loads(case.memo_case_text())\n"
        "d['thrust']['n_omega'] = 60\n"
        "d['truncation'] = dict(M1=4, N1=4, M2=4, N2=4, N=4, S=3, R=3)\n"
        "analysis.analyze(case.load_case(d))\n"
        "print(sorted(m for m in ('dask', 'scipy.optimize', 'scipy.interpolate')\n"
        "             if m in sys.modules))\n"
        "import dask, pint\n"
        "print(dask.__name__, case.load_case(d).booster.E)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True)
    listed, after = out.stdout.strip().splitlines()
    assert listed == "[]"
    name, E = after.split()
    assert name == "dask"
    assert abs(float(E) / (10.5e6 * 6894.757293168361) - 1.0) < 1e-12  # psi in Pa (NIST SP 811)


def test_core_packages_exist():
    assert {"flexbooster.memo.geometry", "flexbooster.memo.beam",
            "flexbooster.memo.pitch"} <= set(CORE_MODULES)


@pytest.mark.parametrize("path", MODULES, ids=lambda p: _name(p))
def test_explicit_all_and_no_star_imports(path):
    text = path.read_text()
    assert "import *" not in text
    if path.name != "__main__.py":
        assert "__all__" in text, f"{path} lacks __all__"


def test_plotting_never_calls_show():
    for path in (PACKAGE / "present" / "plotting").rglob("*.py"):
        assert ".show(" not in path.read_text(), path


def _public_callables():
    for path in MODULES:
        name = _name(path)
        if name.endswith("__main__"):
            continue
        module = importlib.import_module(name)
        for attr in getattr(module, "__all__", []):
            obj = getattr(module, attr, None)
            if (inspect.isfunction(obj) or inspect.isclass(obj)) and obj.__module__ == name:
                yield f"{name}.{attr}", obj


def _documented(doc: str) -> set[str]:
    """Parameter names of the numpydoc 'Parameters' (and 'Attributes') sections."""
    names: set[str] = set()
    lines = inspect.cleandoc(doc).splitlines()
    section = None
    for n, line in enumerate(lines):
        nxt = lines[n + 1] if n + 1 < len(lines) else ""
        if nxt and set(nxt.strip()) == {"-"} and len(nxt.strip()) >= 3:
            section = line.strip()
            continue
        if section in ("Parameters", "Attributes", "Other Parameters") and line and \
                not line.startswith(" ") and not set(line.strip()) <= {"-"}:
            head = line.split(" : ")[0].rstrip(" :")
            for part in head.split(","):
                names.add(part.strip().lstrip("*"))
    return names


PUBLIC = list(_public_callables())


@pytest.mark.parametrize("qualname, obj", PUBLIC, ids=[q for q, _ in PUBLIC])
def test_public_parameters_are_documented(qualname, obj):
    """numpydoc: every parameter of a public function (or class constructor, documented as
    Parameters or Attributes of the class) is named in its docstring."""
    if inspect.isclass(obj) and issubclass(obj, BaseException):
        return
    target = obj
    doc = inspect.getdoc(obj) or ""
    assert doc, f"{qualname} has no docstring"
    try:
        sig = inspect.signature(target)
    except (TypeError, ValueError):
        return
    params = [p for p in sig.parameters.values()
              if p.name not in ("self", "cls") and not p.name.startswith("_")]
    if inspect.isclass(obj) and not params:
        return
    missing = [p.name for p in params if p.name not in _documented(doc)
               and p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD)]
    assert not missing, f"{qualname}: parameters not documented: {missing}"


def _module_graph() -> tuple[dict[str, set[str]], list[tuple[str, str, str, int]]]:
    """The package's import graph (every import, lazy and type-only ones included) and every
    private name (one leading underscore) imported from another module."""
    names = {_name(p) for p in MODULES}
    graph: dict[str, set[str]] = {m: set() for m in names}
    private = []
    for path in MODULES:
        me = _name(path)
        for mod, imported, line in _imports(path):
            if not mod.startswith("flexbooster"):
                continue
            for n in imported or [""]:
                target = f"{mod}.{n}" if f"{mod}.{n}" in names else mod
                if target in names and target != me:
                    graph[me].add(target)
                if n.startswith("_") and not n.startswith("__"):
                    private.append((me, mod, n, line))
    return graph, private


def test_no_private_name_is_imported_across_modules():
    _, private = _module_graph()
    assert not private, "private names imported across modules: " + "; ".join(
        f"{me}:{line} imports {mod}.{n}" for me, mod, n, line in private)


def test_no_import_cycle():
    """Tarjan's strongly connected components of the import graph: none with two modules."""
    graph, _ = _module_graph()
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on: set[str] = set()
    cycles = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in sorted(graph[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                cycles.append(sorted(comp))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    assert not cycles, f"import cycles: {cycles}"


#: Project history in prose: an issue or a session by its number (it belongs in CHANGELOG.md
#: and git); the words alone ("an issue", "a branch of the root") are not history.
_HISTORY = re.compile(r"\b(issues?|sessions?)\s+(#|no\.\s*)?\d+", re.IGNORECASE)


def test_no_project_history_in_code_tests_or_docs():
    """The sources, tests, benchmarks, scripts, docs, examples and README carry no project
    history (issue or session numbers); CHANGELOG.md is where it belongs."""
    root = Path(flexbooster.__file__).resolve().parents[2]
    files = [root / "README.md", root / "Makefile"]
    for folder, pattern in (("src", "*.py"), ("tests", "*.py"), ("benchmarks", "*.py"),
                            ("benchmarks", "*.md"), ("scripts", "*.py"), ("docs", "*.md"),
                            ("examples", "*.toml"), ("src", "*.toml")):
        files += sorted((root / folder).rglob(pattern))
    hits = [f"{path.relative_to(root)}:{n}: {line.strip()}"
            for path in files if path.is_file()
            for n, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1)
            if _HISTORY.search(line)]
    assert hits == []
