"""The vehicle's parametric instability regions in the pipeline and outputs.

Tiers:

* exact (hand-made answers): :func:`flexbooster.analysis.memo_roots_in_regions` on a
  hand-made stability table and hand-made regions (which roots fall inside which region, the
  regions with none, the severity hook), tolerance: exact (integer indices, booleans);
* interface invariants: the pipeline passes the case's settings (F0, gamma, Omega range,
  ``vehicle.damping_ratio``, ``vehicle.n_modes``, k = 1..min(k_max, 10), defaults without a
  ``[vehicle]`` table) to :func:`flexbooster.dynamics.vehicle_regions` and stores its result
  unchanged (exact: the same call made directly); results.json round trip of the new keys
  (exact, JSON floats are repr round trips); vehicle-regions.csv columns against the result
  objects (exact); the chart and the report drawn from the Results alone with every core
  solver patched to raise; CaseError one-liners for the new fields; ``--no-vehicle``; the
  stage's warnings (k_max < 2, buckling) instead of a failed run.

The physics of the regions (Mathieu edges, monodromy growth rates) is tested in
tests/test_vehicle_regions.py; the cases here are small (3 modes per k, k = 2..3) so that the
file runs in well under a minute on the shared machine.
"""

from __future__ import annotations

import csv
import dataclasses
import importlib
import inspect
import json
import pkgutil
import tomllib
from pathlib import Path

import numpy as np
import pytest

from flexbooster.analysis import (
    VEHICLE_REGIONS_STAGE,
    analyze,
    analyze_vehicle_regions,
    memo_roots_in_regions,
)
from flexbooster.bands import NEGLIGIBLE_GROWTH, Band, BandMode, SearchGap
from flexbooster.case import load_case, memo_case_text
from flexbooster.cli import main
from flexbooster.dynamics import (
    RegionCurve,
    VehicleRegions,
    region_critical_damping,
    vehicle_regions,
)
from flexbooster.errors import CaseError
from flexbooster.memo.charts import VEHICLE_CHART_GAMMA_MAX, VEHICLE_CHART_LEVELS
from flexbooster.memo.stability import StabilityTable
from flexbooster.model import vehicle_from_case
from flexbooster.present.io import dumps_finite
from flexbooster.present.vehicle import VEHICLE_REGION_CSV_COLUMNS, vehicle_region_columns
from flexbooster.results import MemoRootsInRegions
from flexbooster.shell_of_revolution import BucklingError

#: The small memo analysis of the tests (the vehicle stage is what is tested).
SMALL_TRUNCATION = dict(M1=3, N1=3, M2=3, N2=3, N=3, S=2, R=2)


def small_case_data(**vehicle) -> dict:
    """The memo case, 40 Omega points, a small truncation, and ``[vehicle]`` fields."""
    data = tomllib.loads(memo_case_text())
    data["thrust"]["n_omega"] = 40
    data["truncation"] = dict(SMALL_TRUNCATION)
    if vehicle:
        data["vehicle"] = dict(vehicle)
    return data


#: Undamped, 3 modes per k, k = 2..3, gamma = 0.3: regions exist at the case's gamma and at
#: the chart's gamma, so the curves are traced.
REGION_CASE = dict(k_max=3, n_modes=3, damping_ratio=0.0)


def _case_with_regions(gamma: float = 0.3):
    data = small_case_data(**REGION_CASE)
    data["thrust"]["gamma"] = gamma
    return load_case(data)


@pytest.fixture(scope="module")
def results():
    return analyze(_case_with_regions())


# --------------------------------------------------------------------------- hand-made table


def _region(k, lo, hi, *, kind="simple", order=1, growth=0.1):
    mode = BandMode("radial 0", index=0, k=k, order=0, type="radial", omega=(lo + hi) / 4,
                    share=1.0)
    return Band(mechanism="vehicle", k=k, kind=kind, order=order, modes=(mode,), Omega_lo=lo,
                Omega_hi=hi, growth_rate_max=growth, Omega_at_max=(lo + hi) / 2,
                Omega_center=(lo + hi) / 2, critical_gamma=0.0)


def _regions(*regs):
    return VehicleRegions(regions=tuple(regs), harmonics=(), curves=(), F0=1.0, gamma=0.1,
                          damping_ratio=0.0, omega_min=1.0, omega_max=100.0,
                          supported_forward_end=False)


def _table(Omega, k, active, cls=StabilityTable, **extra):
    n = len(Omega)
    ints = np.zeros(n, dtype=int)
    return cls(Omega=np.asarray(Omega, float), Omega_bar=np.asarray(Omega, float) / 10.0,
               family=np.arange(1, n + 1), i=ints, p=ints, r=ints, s=ints,
               equation=("7.3-1",) * n, also=("",) * n, cylinder=np.ones(n, dtype=int),
               j=np.arange(n), k=np.asarray(k), branch=np.ones(n, dtype=int),
               shell_omega_bar=np.ones(n), active=np.asarray(active, dtype=bool),
               residual=np.zeros(n), omega_1=10.0, **extra)


#: Regions [10, 12] (k = 3), [20, 20.5] (k = 4), [50, 51] (k = 2); roots at
#: 9.9 (k 3, active), 11 (k 3, active), 11.5 (k 5, listed), 12 (k 3, listed: on the edge),
#: 20.6 (k 4, active: 0.1 above the edge), 70 (k 2, active: in no region).
HAND_REGIONS = (_region(3, 10.0, 12.0), _region(4, 20.0, 20.5), _region(2, 50.0, 51.0))
HAND_ROOTS = dict(Omega=[11.5, 9.9, 20.6, 11.0, 70.0, 12.0], k=[5, 3, 4, 3, 2, 3],
                  active=[False, True, True, True, True, False])


@pytest.mark.parametrize(
    "rtol, pairs, same_k, without_root, without_active",
    [  # answers by hand from HAND_REGIONS / HAND_ROOTS (exact)
        (0.0, [(0, 3), (0, 0), (0, 5)], [True, False, True], [1, 2], [1, 2]),
        # rtol 0.01 widens by 0.11 / 0.2025 / 0.505: 9.9 joins region 0, 20.6 region 1
        (0.01, [(0, 1), (0, 3), (0, 0), (0, 5), (1, 2)], [True, True, False, True, True],
         [2], [2]),
    ], ids=["rtol0-by-hand", "rtol1e-2-by-hand"])
def test_memo_roots_in_regions_hand_made_table(rtol, pairs, same_k, without_root,
                                               without_active):
    m = memo_roots_in_regions(_table(**HAND_ROOTS), _regions(*HAND_REGIONS), rtol=rtol)
    assert isinstance(m, MemoRootsInRegions) and m.n_regions == 3 and len(m) == len(pairs)
    assert list(zip(m.region.tolist(), m.root.tolist(), strict=True)) == pairs
    assert m.same_k.tolist() == same_k
    assert m.Omega.tolist() == [HAND_ROOTS["Omega"][r] for _, r in pairs]
    assert m.active.tolist() == [HAND_ROOTS["active"][r] for _, r in pairs]
    assert m.family.tolist() == [r + 1 for _, r in pairs] and m.j.tolist() == [r for _, r in
                                                                              pairs]
    assert m.without_root.tolist() == without_root
    assert m.without_active_root.tolist() == without_active
    assert m.severity is None  # today's StabilityTable has no severity column
    json.dumps(m.to_dict())  # JSON-ready


@pytest.mark.parametrize("rtol", [0.0, 1e-3])
def test_memo_roots_in_regions_equal_a_brute_force_matrix(rtol):
    """Invariant: the bisection over sorted roots gives the pairs of the plain
    roots x regions comparison (random overlapping regions, ties in Omega; exact)."""
    rng = np.random.default_rng(15)
    lo = rng.uniform(5.0, 500.0, 40)
    regs = _regions(*(_region(int(rng.integers(2, 6)), a, a + w)
                      for a, w in zip(lo, rng.uniform(0.0, 20.0, 40), strict=True)))
    Omega = np.round(rng.uniform(1.0, 520.0, 400), 1)  # rounded: repeated values
    table = _table(Omega, rng.integers(0, 6, 400), rng.random(400) < 0.3)
    m = memo_roots_in_regions(table, regs, rtol=rtol)
    centre = np.array([r.Omega_center for r in regs.regions])
    a = np.array([r.Omega_lo for r in regs.regions]) - rtol * centre
    b = np.array([r.Omega_hi for r in regs.regions]) + rtol * centre
    inside = (Omega[:, None] >= a) & (Omega[:, None] <= b)
    expected = sorted((g, Omega[r], r) for r, g in zip(*np.nonzero(inside), strict=True))
    assert list(zip(m.region.tolist(), m.root.tolist(), strict=True)) == [
        (g, r) for g, _, r in expected]
    assert m.without_root.tolist() == np.flatnonzero(~inside.any(axis=0)).tolist()
    assert m.without_active_root.tolist() == np.flatnonzero(
        ~(inside & table.active[:, None]).any(axis=0)).tolist()


def test_memo_roots_severity_hook_and_empty_inputs():
    """A table with a ``severity`` column (as a severity stage may add): the matched roots carry
    it (exact); no region / no root: empty answers, no error."""

    @dataclasses.dataclass(frozen=True)
    class WithSeverity(StabilityTable):
        severity: tuple = ()

    sev = ("low", "high", "medium", "high", "none", "low")
    m = memo_roots_in_regions(_table(**HAND_ROOTS, cls=WithSeverity, severity=sev),
                              _regions(*HAND_REGIONS))
    assert m.severity == ("high", "low", "low")  # roots 3, 0, 5 of region 0
    assert m.to_dict()["severity"] == ["high", "low", "low"]
    empty = memo_roots_in_regions(_table(**HAND_ROOTS), _regions())
    assert len(empty) == 0 and empty.n_regions == 0 and empty.without_root.size == 0
    none = memo_roots_in_regions(_table([], [], []), _regions(*HAND_REGIONS))
    assert len(none) == 0 and none.without_active_root.tolist() == [0, 1, 2]


@pytest.mark.parametrize("call, word", [
    (lambda: memo_roots_in_regions(None, _regions()), "table"),
    (lambda: memo_roots_in_regions(_table(**HAND_ROOTS), None), "regions"),
    (lambda: memo_roots_in_regions(_table(**HAND_ROOTS), _regions(), rtol=-1.0), "rtol"),
    (lambda: memo_roots_in_regions(_table(**HAND_ROOTS), _regions(), rtol=np.nan), "rtol"),
])
def test_memo_roots_bad_input_names_it(call, word):
    with pytest.raises(ValueError, match=word):
        call()


# --------------------------------------------------------------------------- case fields


@pytest.mark.parametrize("field, value, rule", [
    ("damping_ratio", -0.1, "[0, 1)"),
    ("damping_ratio", 1.0, "[0, 1)"),
    ("damping_ratio", "fast", "damping_ratio"),
    ("damping_ratio", float("nan"), "finite"),
    ("n_modes", 0, "[1, 500]"),
    ("n_modes", 501, "[1, 500]"),
    ("n_modes", 2.5, "integer"),
    ("n_modes", "4", "integer"),
])
def test_bad_region_field_is_one_case_error_line(field, value, rule):
    with pytest.raises(CaseError) as info:
        load_case(small_case_data(**{field: value}))
    text = str(info.value)
    assert info.value.field == f"vehicle.{field}" and "\n" not in text and rule in text


def test_region_fields_and_defaults():
    """Defaults: damping ratio 0.01, 20 modes per k; 0 damping allowed; the memo
    vehicle's [vehicle] table (no segments) may set them."""
    case = load_case(small_case_data(damping_ratio=0, n_modes=4))
    assert case.vehicle_damping_ratio == 0.0 and case.vehicle.n_modes == 4
    case = load_case(small_case_data(theory="donnell"))  # damping.modal_ratio
    assert case.vehicle.damping_ratio is None and case.vehicle_damping_ratio == 0.01
    assert case.vehicle.n_modes == 20


# --------------------------------------------------------------------------- settings


CHART_GAP = SearchGap(stage="vehicle", reason="harmonic k = 3 not traced for the chart: ...",
                      limit="max_steps", k=3)


class _Recorder:
    """Stands in for vehicle_regions and region_curves: records the calls, returns empty
    regions and, for the curves, one curve and one gap."""

    def __init__(self):
        self.calls = []
        self.curve_calls = []

    def __call__(self, vehicle, **kw):
        self.calls.append(kw)
        return dataclasses.replace(_regions(), gamma=kw["gamma"])

    def curves(self, found, **kw):
        self.curve_calls.append((found, kw))
        curve = RegionCurve(k=2, kind="simple", order=1, modes=(0,), gamma=np.array([0.1]),
                            omega_lo=np.array([10.0]), omega_hi=np.array([11.0]))
        return (curve,), (CHART_GAP,)


def test_stage_passes_the_case_settings_and_defaults(monkeypatch):
    """Without [vehicle]: damping 0.01, 20 modes, k = 1..20 (the defaults, vehicle.k_max
    of the memo vehicle), the case's F0, gamma, Omega range and gimbal gain K (for k = 1) in
    one search, no budget; the chart's curves from the stored map (vehicle.region_curves) up
    to the chart's gamma with the chart's levels; their curves and gaps reach the result; a
    [vehicle] k_max is passed as it is."""
    import flexbooster.analysis as analysis

    rec = _Recorder()
    monkeypatch.setattr(analysis, "vehicle_regions", rec)
    monkeypatch.setattr(analysis, "region_curves", rec.curves)
    # the chart's top gamma as far as the certificate allows (tested below): here the constant
    monkeypatch.setattr(analysis, "_chart_gamma", lambda found: VEHICLE_CHART_GAMMA_MAX)
    case = load_case(small_case_data())
    found = analyze_vehicle_regions(case, boundaries=True)
    expected = dict(F0=case.F0, omega_min=5.0, omega_max=2000.0, k_min=1, k_max=20,
                    n_modes=20, damping_ratio=0.01, gimbal_gain=case.thrust.K)
    (first,) = rec.calls
    assert first == {**expected, "gamma": 0.05}
    ((mapped, kw),) = rec.curve_calls
    assert mapped.gamma == 0.05
    assert kw == {"gamma_max": VEHICLE_CHART_GAMMA_MAX, "n_gamma": VEHICLE_CHART_LEVELS}
    assert [c.k for c in found.curves] == [2] and found.chart_gamma_max == VEHICLE_CHART_GAMMA_MAX
    assert found.gaps == () and found.chart_gaps == (CHART_GAP,)
    rec.calls.clear()
    rec.curve_calls.clear()
    analyze_vehicle_regions(load_case(small_case_data(k_max=4, n_modes=5, damping_ratio=0.2)),
                            boundaries=False)
    (only,) = rec.calls
    assert (only["k_max"], only["n_modes"], only["damping_ratio"]) == (4, 5, 0.2)
    assert rec.curve_calls == []
    rec.calls.clear()
    analyze_vehicle_regions(load_case(small_case_data(k_max=40)), k_min=3, boundaries=False)
    assert (rec.calls[0]["k_min"], rec.calls[0]["k_max"]) == (3, 40)


@pytest.mark.parametrize("path", [None, "titan-inch-pound.toml"], ids=["default", "titan"])
def test_chart_top_gamma_is_certified_free_of_regions(path):
    """The chart's top gamma (analysis._chart_gamma) is the case's gamma raised only as far as
    the all-Omega stability certificate holds: a search at that gamma finds every harmonic
    certified (floquet.stability_certificate of the scaled system, an independent call) and
    no region; the default vehicle reaches the constant, the thin Titan shells stop below.
    The top reuses the search's certificates (scaled by gamma): checked against the
    certificate per unit gamma."""
    import flexbooster.analysis as analysis
    from flexbooster.dynamics import vehicle_regions as regions_of

    data = (small_case_data() if path is None else
            tomllib.loads((Path(__file__).parent / "data" / "cases" / path).read_text()))
    data["vehicle"] = {"n_modes": 6, "k_max": 4}
    case = load_case(data)
    found = analyze_vehicle_regions(case, boundaries=False)
    top = analysis._chart_gamma(found)
    assert case.thrust.gamma <= top <= VEHICLE_CHART_GAMMA_MAX
    # two methods agree: the search's certificate at gamma, scaled by gamma,
    # is the certificate of the excitation per unit gamma (Q linear in B), to 1e-9 relative
    from flexbooster.floquet import stability_certificate

    for h, c in zip(found.harmonics, found.certificates, strict=True):
        unit = stability_certificate(h.mass, h.damping, h.stiffness, h.excitation)
        assert found.gamma * c.amplitude_factor == pytest.approx(unit.amplitude_factor,
                                                                 rel=1e-9)
    t = case.thrust
    at_top = regions_of(vehicle_from_case(case), F0=case.F0, gamma=top, omega_min=t.omega_min,
                        omega_max=t.omega_max, k_min=1, k_max=4, n_modes=6, damping_ratio=0.01,
                        gimbal_gain=t.K)
    assert all(c.certified for c in at_top.certificates) and at_top.regions == ()
    if path is None:
        assert top == VEHICLE_CHART_GAMMA_MAX
    else:
        assert top < VEHICLE_CHART_GAMMA_MAX


def test_stage_warns_instead_of_failing(monkeypatch):
    """k_max < 1, or a steady thrust that buckles a harmonic: a warning in the results, the
    rest of the analysis stands."""
    import flexbooster.analysis as analysis

    res = analyze(load_case(small_case_data(k_max=0)), beam_action=False, figures=False)
    assert res.vehicle_regions is None
    (w,) = [w for w in res.warnings if w.code == "vehicle-regions-skipped"]
    assert w.field == "vehicle.k_max"

    def buckles(vehicle, **kw):
        raise BucklingError("F0 = 1: the steady thrust buckles harmonic k = 2 (load factor "
                            "0.5 ...)", 2, 1.0, 0.5)

    monkeypatch.setattr(analysis, "vehicle_regions", buckles)
    res = analyze(load_case(small_case_data()), beam_action=False, figures=False)
    assert res.vehicle_regions is None and res.to_dict()["vehicle_regions"] is None
    (w,) = [w for w in res.warnings if w.code == "vehicle-regions-skipped"]
    assert w.field == "thrust.F0" and "buckles harmonic k = 2" in w.message


# --------------------------------------------------------------------------- the pipeline


def test_pipeline_stores_the_regions_of_the_case(results):
    """The stored regions are those of vehicle_regions called directly with the case's
    settings, with their critical damping ratios (exact), with curves (the chart data) for the
    regions of the chart's gamma."""
    case = results.case
    vr = results.vehicle_regions
    direct = region_critical_damping(vehicle_regions(
        vehicle_from_case(case), F0=case.F0, gamma=0.3, omega_min=5.0, omega_max=2000.0,
        k_min=1, k_max=3, n_modes=3, damping_ratio=0.0, gimbal_gain=case.thrust.K),
        growth_floor=NEGLIGIBLE_GROWTH)
    assert vr.regions == direct.regions and len(vr.regions) > 0
    assert [h.k for h in vr.harmonics] == [1, 2, 3]
    top = max(VEHICLE_CHART_GAMMA_MAX, case.thrust.gamma)  # the chart's top (the case's 0.3)
    assert vr.curves and all(c.gamma[-1] == pytest.approx(top, abs=1e-15) for c in vr.curves)
    m = results.memo_roots_in_regions
    assert m is not None and m.n_regions == len(vr.regions)
    ref = memo_roots_in_regions(results.stability, vr)
    assert m.root.tolist() == ref.root.tolist() and m.region.tolist() == ref.region.tolist()


def test_results_json_round_trip(results):
    """results.json: vehicle_regions = VehicleRegions.to_dict() plus memo_roots; every region's
    numbers equal the objects' (exact: JSON floats round-trip); units documented."""
    data = json.loads(dumps_finite(results.to_dict()))
    vr = results.vehicle_regions
    out = data["vehicle_regions"]
    assert {k: v for k, v in out.items() if k != "memo_roots"} == json.loads(
        json.dumps(vr.to_dict()))
    assert out["memo_roots"] == json.loads(json.dumps(results.memo_roots_in_regions.to_dict()))
    for got, r in zip(out["regions"], vr.regions, strict=True):
        assert (got["k"], got["kind"], got["order"]) == (r.k, r.kind, r.order)
        assert (got["Omega_lo"], got["Omega_hi"], got["growth_rate_max"],
                got["critical_gamma"]) == (r.Omega_lo, r.Omega_hi, r.growth_rate_max,
                                           r.critical_gamma)
    assert len(out["curves"]) == len(vr.curves) > 0
    assert out["gamma"] == 0.3 and out["damping_ratio"] == 0.0
    assert "vehicle_regions.regions.growth_rate_max" in data["units"]


def test_csv_columns_against_the_objects(results, tmp_path):
    """vehicle-regions.csv (write_outputs, atomic): one region a row, the README's columns,
    values equal to the objects' (exact: repr round trip)."""
    from flexbooster.present.outputs import write_outputs

    paths = write_outputs(results, tmp_path, figures=False)
    path = tmp_path / "vehicle-regions.csv"
    assert path in paths and not list(tmp_path.glob("*.part"))
    with path.open() as f:
        rows = list(csv.DictReader(f))
    assert tuple(rows[0]) == VEHICLE_REGION_CSV_COLUMNS
    assert {"k", "kind", "modes", "Omega_lo_rad_s", "Omega_hi_rad_s", "width_rad_s",
            "growth_rate_max", "critical_gamma"} <= set(VEHICLE_REGION_CSV_COLUMNS)
    regs = results.vehicle_regions.regions
    assert len(rows) == len(regs)
    for row, r in zip(rows, regs, strict=True):
        assert (int(row["k"]), row["kind"], int(row["order"])) == (r.k, r.kind, r.order)
        assert float(row["Omega_lo_rad_s"]) == r.Omega_lo
        assert float(row["Omega_hi_rad_s"]) == r.Omega_hi
        assert float(row["width_rad_s"]) == r.width
        assert float(row["growth_rate_max"]) == r.growth_rate_max
        assert float(row["critical_gamma"]) == r.critical_gamma
        assert row["mode_indices"] == "+".join(str(m.index) for m in r.modes)
        assert all(f"mode {m.index + 1} ({m.type}, order {m.order})" in row["modes"]
                   for m in r.modes)
    assert vehicle_region_columns(_regions())["k"] == []  # no region: header only


def _core_modules():
    for package in ("flexbooster.memo", "flexbooster.floquet", "flexbooster.dynamics",
                    "flexbooster.shell_of_revolution"):
        pkg = importlib.import_module(package)
        yield pkg
        for info in pkgutil.walk_packages(pkg.__path__, prefix=f"{package}."):
            yield importlib.import_module(info.name)


def test_chart_and_report_from_the_results_alone(results, monkeypatch):
    """Every function of the numerical core patched to raise: the chart, the summary and the
    report section are drawn from the stored Results (compute -> data -> plot)."""
    import matplotlib

    from flexbooster.present.figure_files import render_figure
    from flexbooster.present.plotting.vehicle_regions import vehicle_region_chart
    from flexbooster.present.report import render_report
    from flexbooster.present.summary import print_summary
    from flexbooster.present.vehicle import vehicle_region_figures

    patched = 0
    for module in list(_core_modules()):
        for name, obj in list(vars(module).items()):
            if inspect.isfunction(obj):

                def boom(*args, _name=f"{module.__name__}.{name}", **kwargs):
                    raise AssertionError(f"presentation called the solver {_name}")

                monkeypatch.setattr(module, name, boom)
                patched += 1
    assert patched > 100
    figs = vehicle_region_figures(results)
    assert set(figs) == {"vehicle-regions"}
    fig = figs["vehicle-regions"]
    ax = fig.axes[0]
    assert ax.get_xlabel().startswith("thrust frequency Omega (Hz)") and ax.get_xscale() == "log"
    assert len(ax.patches) == len(results.vehicle_regions.curves)  # one shaded region a curve
    dashed = [ln for ln in ax.lines if ln.get_linestyle() == "--"]
    assert dashed and all(np.allclose(ln.get_ydata(), 0.3) for ln in dashed)  # case's gamma
    x_hz = np.concatenate([p.get_xy()[:, 0] for p in ax.patches])
    lo = min(float(c.omega_lo.min()) for c in results.vehicle_regions.curves) / (2 * np.pi)
    assert x_hz.min() == pytest.approx(lo, rel=1e-12)  # Omega drawn in Hz
    # on a given axes, returning its figure
    other = matplotlib.figure.Figure()
    assert vehicle_region_chart(results.vehicle_regions, ax=other.add_subplot()) is other
    svgs = {"vehicle-regions": render_figure(fig)[0]}
    page = render_report(results, svgs)
    sec = page.split('<section id="vehicle-regions">', 1)[1].split("</section>", 1)[0]
    assert 'id="fig-vehicle-regions"' in sec and "<svg" in sec
    assert "damping ratio" in sec and "max growth (1/s)" in sec and "Memo-table roots" in sec
    from rich.console import Console

    console = Console(record=True, width=200)
    print_summary(results, console)
    text = console.export_text()
    assert "Vehicle parametric instability regions" in text
    assert "modal damping ratio zeta" in text and "unstable:" in text


def test_chart_without_regions_says_so():
    """No region, no curve: the chart says so (and draws the case's gamma)."""
    fig = __import__("flexbooster.present.plotting.vehicle_regions", fromlist=["x"]) \
        .vehicle_region_chart(_regions())
    texts = [t.get_text() for t in fig.axes[0].texts]
    assert any("no instability region" in t for t in texts)


def test_report_and_summary_row_order(results):
    """The regions table is sorted by decreasing growth rate, in summary and report (one row
    helper)."""
    from flexbooster.present.rows import vehicle_region_table

    rows = vehicle_region_table(results)
    rates = [row[8] for row in rows]
    assert rates == sorted(rates, reverse=True) and len(rows) == len(
        results.vehicle_regions.regions)
    m = results.memo_roots_in_regions
    assert sum(row[10] == "no" for row in rows) == m.without_active_root.size  # explained?


def test_region_table_marks_the_regions_no_memo_root_explains(results):
    """Hand-made: regions 0 and 2 hold an active root, region 1 none -> yes / no / yes
    (rows sorted by growth rate: region 1 has the largest)."""
    from flexbooster.present.rows import vehicle_region_table

    regs = _regions(_region(3, 10.0, 12.0, growth=0.1), _region(4, 20.0, 20.5, growth=0.3),
                    _region(2, 50.0, 51.0, growth=0.2))
    table = _table([11.0, 50.5, 20.2], [3, 2, 4], [True, True, False])
    res = dataclasses.replace(results, vehicle_regions=regs,
                              memo_roots_in_regions=memo_roots_in_regions(table, regs))
    assert [(row[4], row[10]) for row in vehicle_region_table(res)] == [(4, "no"), (2, "yes"),
                                                                        (3, "yes")]


def test_progress_and_no_vehicle_keyword():
    """The stage is announced last; analyze(..., vehicle=False) skips it (results key None)."""
    seen = []
    case = _case_with_regions()
    res = analyze(case, beam_action=False, figures=False, vehicle=False, progress=seen.append)
    assert VEHICLE_REGIONS_STAGE not in seen and res.vehicle_regions is None
    assert res.to_dict()["vehicle_regions"] is None and res.memo_roots_in_regions is None


def test_cli_no_vehicle(tmp_path, capsys):
    """flexbooster run --no-vehicle: no vehicle-regions.csv, results.json vehicle_regions null,
    the report's section says it was not computed; the flag is in the help."""
    from conftest import dump_toml

    path = tmp_path / "case.toml"
    path.write_text(dump_toml(small_case_data(**REGION_CASE)))
    out = tmp_path / "out"
    with pytest.raises(SystemExit) as info:
        main(["run", str(path), "-o", str(out), "--no-figures", "--no-vehicle", "-q"])
    assert info.value.code == 0
    assert json.loads((out / "results.json").read_text())["vehicle_regions"] is None
    assert not (out / "vehicle-regions.csv").exists()
    report = (out / "report.html").read_text()
    sec = report.split('<section id="vehicle-regions">', 1)[1].split("</section>", 1)[0]
    assert "Not computed" in sec
    with pytest.raises(SystemExit):
        main(["run", "--help"])
    assert "--no-vehicle" in capsys.readouterr().out


def test_forced_axial_resonances_are_reported_from_the_results(results):
    """The k = 0 forced resonances (the memo's family 3) in the report's rows: one row per
    stored resonance, Omega and Hz exact (Hz = rad/s / 2 pi), the resonant amplitude '-'
    for this undamped case (unbounded) and the report shows the table."""
    from flexbooster.present.report import render_report
    from flexbooster.present.rows import forced_axial_rows

    fa = results.vehicle_regions.forced_axial
    rows = forced_axial_rows(results)
    assert len(rows) == len(fa.resonances) > 0
    for row, r in zip(rows, fa.resonances, strict=True):
        assert row[0] == r.omega and row[1] == pytest.approx(r.omega / (2 * np.pi), rel=1e-15)
        assert row[3] == r.flexibility and row[4] == row[5] == "-"
    assert "Forced (not parametric) resonances" in render_report(results, {})


def test_pipeline_k1_rows_are_bending_regions(results):
    """Two paths for k = 1: the pipeline's k = 1 rows (vehicle_regions with k_min = 1, the
    case's gimbal gain thrust.K) equal flexbooster.dynamics.bending_regions called directly
    with the case's settings (exact); they reach the CSV columns and the memo-root matching
    (same objects)."""
    from flexbooster.dynamics import bending_regions

    case = results.case
    t = case.thrust
    direct = bending_regions(vehicle_from_case(case), F0=case.F0, gamma=t.gamma,
                             omega_min=t.omega_min, omega_max=t.omega_max, gimbal_gain=t.K,
                             n_modes=3, damping_ratio=0.0)
    vr = results.vehicle_regions
    k1 = tuple(r for r in vr.regions if r.k == 1)
    assert k1 == direct and len(k1) > 0
    assert vehicle_region_columns(vr)["k"].count(1) == len(k1)
    assert vr.to_dict()["gimbal_gain"] == t.K


_FUZZ_CANDIDATES = {
    "name": "fuzz",
    "booster": {"cylinder1": {"radius": 28.44842919443165, "half_length": 1.3954288775018648},
                "cylinder2": {"radius": 47.13013587898876, "half_length": 3.1557674301688827},
                "thickness": 0.048771811768155295, "E": 20447356474.064217,
                "nu": 0.32332789317528776, "rho": 226.8960928016897},
    "thrust": {"gamma": 0.9439478472914494, "K": 3.5018139758102595,
               "omega_min": 2.5, "omega_max": 5.617245733771596,
               "n_omega": 11, "F0": 146800443.25106373},
    "truncation": {"M1": 1, "N1": 1, "M2": 1, "N2": 1, "N": 2, "S": 0, "R": 1},
}


def test_a_case_past_a_size_limit_says_so():
    """The memo vehicle of the vehicle fuzz (two wide short cylinders, 20 modes up to 6,350
    rad/s; gamma = 0.94, Omega = 2.5..5.6 rad/s): couplings above the frequencies keep every
    order, some 263,000-321,000 simple and sum candidates to examine per harmonic (the
    harmonics are canonical: no difference candidates), past the toolkit's max_candidates
    (200,000).  Each harmonic is a SearchGap (stage vehicle, its k, the limit,
    the Omega range) in the result and in results.json, one merged warning
    (vehicle-regions-skipped, thrust.omega_min) names all 20, and the verdict is not
    "stable"."""
    import types

    import flexbooster.analysis as analysis
    from flexbooster.present.rows import vehicle_region_verdict

    case = load_case(_FUZZ_CANDIDATES)
    found, warns = analysis._vehicle_regions_stage(case, boundaries=False)
    assert found.regions == () and [g.k for g in found.gaps] == list(range(1, 21))
    t = case.thrust
    for k, gap in enumerate(found.gaps, start=1):
        assert (gap.stage, gap.limit) == ("vehicle", "max_candidates")
        assert (gap.Omega_lo, gap.Omega_hi) == (t.omega_min, t.omega_max)
        assert gap.reason.startswith(f"harmonic k = {k} not searched: ") and \
            "candidates" in gap.reason
    assert found.to_dict()["gaps"] == [g.to_dict() for g in found.gaps]
    (w,) = warns  # merged: one line for the 20, not 20 warnings burying the others
    assert (w.code, w.field) == ("vehicle-regions-skipped", "thrust.omega_min")
    assert w.message.startswith("20 harmonics left out (k = 1-20); the first, ")
    assert "harmonic k = 1 not searched" in w.message and "\n" not in w.message
    text, stable = vehicle_region_verdict(types.SimpleNamespace(vehicle_regions=found))
    assert not stable and text.startswith("not fully searched")
