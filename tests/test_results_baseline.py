"""Stored baselines: no number changed unintentionally, and every figure is drawn from
the results alone.

The baselines ``tests/data/baseline/*.json.gz`` are the results.json of three cases written by
commit 045ce06 with the script in the docstring of
:func:`_case`: the memo case, a case with the CM in cylinder 2 and an inch-pound case, each
with a reduced truncation (60 Omega points; M = N = 4 shell modes, N = 4 beam modes, S = 3,
R = 3) so that the files stay small.  Every key of the baseline must be in today's results
with the same value to 1e-12 relative (added keys, such as ``figures``, are allowed).
"""

from __future__ import annotations

import gzip
import importlib
import inspect
import json
import pkgutil
import tomllib
from pathlib import Path

import pytest

import flexbooster
from flexbooster.case import memo_case_text

DATA = Path(__file__).parent / "data"
CASES = {"default": None, "cm-in-cylinder2": "cases/cm-in-cylinder2.toml",
         "titan-inch-pound": "cases/titan-inch-pound.toml"}


def _case(name: str, *, undamped: bool = True):
    """The reduced case of a baseline (as generated at commit 045ce06, undamped: the default
    modal damping set to 0 explicitly)::

        d["thrust"]["n_omega"] = 60
        d["truncation"] = dict(M1=4, N1=4, M2=4, N2=4, N=4, S=3, R=3)
    """
    path = CASES[name]
    d = tomllib.loads(memo_case_text() if path is None else (DATA / path).read_text())
    d["thrust"]["n_omega"] = 60
    d["truncation"] = dict(M1=4, N1=4, M2=4, N2=4, N=4, S=3, R=3)
    if undamped:  # the baselines are the memo's undamped idealisation
        d["damping"] = dict(modal_ratio=0.0)
    return flexbooster.load_case(d)


#: Keys changed on purpose when bands became exact: the intervals are the exact band edges
#: (not runs of unstable grid points), the verdicts and the largest growth rates follow from
#: the bands (docs/theory/bands.md).
CHANGED_EXACT_BANDS = {".pitch.unstable_intervals", ".pitch.verdict", ".beam_action.verdict",
                       ".pitch.max_growth_rate", ".beam_action.max_growth_rate",
                       ".beam_action.Omega_at_max"}

#: Keys changed on purpose by the secular severity: "active" is severity_rel >= threshold
#: (the secular growth rate of each root, docs/theory/severity.md), no longer the
#: Kronecker deltas and parity alone; the table gained the columns severity and severity_rel.
CHANGED_SEVERITY = {".stability.active", ".stability.columns", ".stability.table.forcing"}


#: Keys compared to an absolute tolerance instead of 1e-12 relative: the beam-action exponents
#: are eigenvalues of a monodromy matrix built from thousands of steps, and the BLAS/LAPACK
#: kernels that OpenBLAS picks for the CPU change them by round-off (measured on an AMD EPYC
#: against the baselines: 1.2e-12 in alpha_real ~ 0.24, every alpha_imag ~ 1e-16 of round-off
#: changed wholly); 1e-10 is far below the method's own accuracy (Hill against monodromy:
#: about 1e-9, hill_monodromy_difference) and far above that round-off.
PLATFORM_ROUND_OFF = {".beam_action.alpha_real": 1e-10, ".beam_action.alpha_imag": 1e-10,
                      ".beam_action.frequencies_real": 1e-10,
                      ".beam_action.hill_monodromy_difference": 1e-10}


#: The memo's case is no longer the embedded default (the launch vehicle with its flight is):
#: its name says "memo case" instead of "default".
CHANGED_NAME = {".case.name"}


def _diff(old, new, path="", atol=0.0):
    if path in CHANGED_EXACT_BANDS | CHANGED_SEVERITY | CHANGED_NAME:
        return
    atol = PLATFORM_ROUND_OFF.get(path, atol)
    if isinstance(old, dict):
        assert isinstance(new, dict), path
        for key, value in old.items():
            assert key in new, f"{path}.{key} missing"
            yield from _diff(value, new[key], f"{path}.{key}", atol)
    elif isinstance(old, list):
        assert isinstance(new, list) and len(new) == len(old), f"{path}: length"
        for n, (x, y) in enumerate(zip(old, new, strict=True)):
            yield from _diff(x, y, f"{path}[{n}]", atol)
    elif isinstance(old, bool | str) or old is None:
        if old != new:
            yield path, old, new
    elif not (old == new or abs(old - new) <= max(1e-12 * max(abs(old), abs(new)), atol)):
        yield path, old, new


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(CASES))
def test_results_equal_the_baseline_before_the_redesign(name):
    with gzip.open(DATA / "baseline" / f"{name}.json.gz", "rt") as f:
        old = json.load(f)
    # the baselines hold no vehicle regions: undamped, their search is past the budget
    new = flexbooster.analyze(_case(name), vehicle=False).to_dict()
    for key in ("flexbooster_version", "units"):  # metadata, not results
        old.pop(key)
    diffs = list(_diff(old, new))
    assert not diffs, f"{len(diffs)} values changed, e.g. {diffs[:3]}"
    # added since: the figure data, the vehicle's parametric regions, the ranked danger bands,
    # the vehicle's forced response, the overall verdict
    assert set(new) - set(old) - {"flexbooster_version", "units"} == {"figures",
                                                                       "vehicle_regions",
                                                                       "danger",
                                                                       "forced_response",
                                                                       "verdict"}


def _solver_modules():
    for package in ("flexbooster.memo", "flexbooster.floquet", "flexbooster.dynamics"):
        pkg = importlib.import_module(package)
        for info in pkgutil.walk_packages(pkg.__path__, prefix=f"{package}."):
            yield importlib.import_module(info.name)


@pytest.mark.slow
def test_every_figure_is_drawn_from_the_results_alone(monkeypatch):
    """Patch every function of the numerical core to raise, then draw every figure and the
    report from a Results computed before: nothing may call a solver."""
    from flexbooster.present.outputs import figure_svgs
    from flexbooster.present.report import render_report

    results = flexbooster.analyze(_case("default", undamped=False))
    patched = 0
    for module in list(_solver_modules()):
        for name, obj in list(vars(module).items()):
            if inspect.isfunction(obj) and obj.__module__ == module.__name__:

                def boom(*args, _name=f"{module.__name__}.{name}", **kwargs):
                    raise AssertionError(f"presentation called the solver {_name}")

                monkeypatch.setattr(module, name, boom)
                patched += 1
    assert patched > 100  # the patch reached the core
    svgs = figure_svgs(results)
    assert set(svgs) == {"ince-strutt", "beam-modes", "shell-frequencies-cylinder1",
                         "shell-frequencies-cylinder2", "nodal-patterns",
                         "pitch-band-chart", "beam-action-chart", "campbell",
                         "vehicle-regions", "danger-map", "forced-acceleration",
                         "forced-envelopes"}
    html = render_report(results, svgs)
    assert "<svg" in html
