"""The pipeline: Mathieu parameters against the untransformed pitch equation, warnings, the
results dictionary, and unit-system independence."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pint
import pytest
from scipy.integrate import solve_ivp

from flexbooster import analyze, load_case

INCH = 0.0254  # exact (international inch)
LBF = 4.4482216152605  # N, exact (NIST SP 811)


def test_mathieu_parameters_reproduce_the_pitch_equation(memo_case_dict):
    """Eqs. (4.2-1) -> (4.2-3): integrate the linearised pitch equation in physical time,
    psi'' + (2 pi R1 d2 K T(t) / I_cm) psi = 0 (E2: lever arm d2), and the Mathieu equation
    y'' + (a - 2q cos 2 tau1) y = 0 with the pipeline's a, q in tau1 = Omega t / 2; the two
    solutions from the same initial state must coincide (solve_ivp DOP853, rtol 1e-11)."""
    memo_case_dict["thrust"]["gamma"] = 0.3  # a sizeable modulation makes a wrong q visible
    case = load_case(memo_case_dict)
    res = analyze(case, beam_action=False, stability=False, figures=False, vehicle=False)
    c1 = case.booster.cylinder1
    k_phys = 2 * math.pi * c1.radius * res.mass.d2 * case.thrust.K * case.T0 / res.mass.I_cm
    for i in (0, 50, 399):
        Omega, a, q = res.Omega[i], res.a[i], res.q[i]
        t_end = 6 * 2 * math.pi / Omega

        def physical(t, y, Omega=Omega):
            return [y[1], -k_phys * (1 - case.thrust.gamma * math.cos(Omega * t)) * y[0]]

        def mathieu(s, y, a=a, q=q):
            return [y[1], -(a - 2 * q * math.cos(2 * s)) * y[0]]

        t = np.linspace(0, t_end, 7)
        ref = solve_ivp(
            physical, (0, t_end), [1e-3, 0.0], t_eval=t, rtol=1e-11, atol=1e-16, method="DOP853"
        )
        mat = solve_ivp(
            mathieu,
            (0, Omega * t_end / 2),
            [1e-3, 0.0],
            t_eval=Omega * t / 2,
            rtol=1e-11,
            atol=1e-16,
            method="DOP853",
        )
        np.testing.assert_allclose(mat.y[0], ref.y[0], rtol=1e-7, atol=1e-12)


def test_memo_moment_without_lever_arm_is_not_an_angular_acceleration():
    """Erratum E2: 2 pi R1 T0 sin(K psi) / I_cm (eq. 2.2-2c as printed) has the dimension
    1/(m s^2); with the lever arm d2 (eq. 4.2-1) it is 1/s^2 (pint)."""
    u = pint.UnitRegistry()
    R1, d2, T0, inertia = 1 * u.m, 1 * u.m, 1 * u("N/m"), 1 * u("kg*m^2")
    printed = (2 * math.pi * R1 * T0 / inertia).to_base_units()
    corrected = (2 * math.pi * R1 * d2 * T0 / inertia).to_base_units()
    assert printed.dimensionality == (u.s**-2 / u.m).dimensionality
    assert corrected.dimensionality == (u.s**-2).dimensionality


def test_memo_case_in_memo_range_without_warnings(memo_results):
    """The memo case is chosen so that 0 < a < 1 and 0 < q <= 0.05 on its Omega grid (4.2-5)
    and h/R <= 1/20."""
    res = memo_results
    assert res.warnings == ()
    assert np.all((res.a > 0) & (res.a < 1)) and np.all((res.q > 0) & (res.q <= 0.05))


@pytest.mark.parametrize(
    ("changes", "codes"),
    [
        ({"thrust": {"K": 0.0}}, {"mathieu-a-range", "mathieu-q-range"}),
        pytest.param({"thrust": {"omega_min": "1 rad/s"}}, {"mathieu-a-range", "mathieu-q-range"},
                     marks=pytest.mark.slow),  # the beam action down to 1 rad/s
        ({"thrust": {"gamma": 0.0}}, {"mathieu-q-range"}),
        ({"booster": {"thickness": "0.3 m"}}, {"thin-shell"}),
    ],
)
def test_warnings(memo_case_dict, changes, codes):
    # a small truncation and grid: the warnings come from the inputs and the pitch stage, the
    # whole pipeline still runs (no NaN or inf in results.json even with K = 0)
    memo_case_dict["truncation"].update(M1=3, N1=3, M2=3, N2=3, N=3, S=2, R=2)
    memo_case_dict["thrust"]["n_omega"] = 40
    for table, values in changes.items():
        memo_case_dict[table].update(values)
    res = analyze(load_case(memo_case_dict))
    assert {w.code for w in res.warnings} == codes
    data = res.to_dict()
    assert {w["code"] for w in data["warnings"]} == codes
    json.dumps(data, allow_nan=False)  # no NaN or inf even with K = 0


#: The results computed by solvers, not in closed form (keys of results.json): the beam-action
#: exponents come from eigenvalues of non-normal Floquet matrices whose own accuracy is about
#: 1e-9 (Hill vs monodromy agree to 1e-8; docs/theory/beam-action.md), and the stability
#: roots and figure data (Campbell curves, chart) inherit it; the vehicle regions are FE
#: eigenvalues of the shell of revolution (~2e-9 between two unit systems) and edges refined
#: to 1e-9 of each centre; the danger bands are the bands of those stages ranked; the forced
#: response is FE eigenvectors and a Schur form of the same shell of revolution.
SOLVED = (".beam_action.", ".stability.", ".figures.", ".vehicle_regions.", ".danger.",
          ".forced_response.")
#: Absolute tolerance of the forced response's internal loads (N, N m): each is a sum of the
#: element forces of the part ahead, of order the default F0 = 2.8 MN, to 1e-8 of it (near the
#: aft edge the sum cancels to gamma F0: 2.6e-3 N apart between the two unit systems).
FORCED_LOAD_ATOL = 1e-8 * 2.8e6


def _tolerance(key: str) -> tuple[float, float] | None:
    """(rel, abs) for one number of results.json (pytest.approx's rule), None: not compared.

    Closed-form quantities (geometry, omega_1, a, q, beta, shell frequencies): 1e-12; the
    solved ones (SOLVED): 1e-8, 1e-12 absolute; the peak growth log|rho| / T of a band:
    multipliers from the monodromy eigenvalues, accurate to ~1e-10, i.e. ~1e-7 1/s at
    omega_1 ~ 100 rad/s; not compared: hill_monodromy_difference (an error estimate of the
    eigen-solvers, ~1e-11), a band's width (omega_hi - omega_lo of two edges compared) and its
    e-folding time, growth exponent and amplification (functions of its growth rate); the
    forced response's half-basis change (a difference of two equal peaks: an error estimate)
    and a critical damping ratio to 1e-5 (a root to 1e-6 of itself in each unit system);
    and the Omega of a peak (the peak values are compared; at the edges the axial force is
    gamma F0 or 0 at every Omega, so where it peaks is round-off); its loads to
    FORCED_LOAD_ATOL.
    """
    band = ".bands[" in key or ".ranking[" in key  # a band, or one in the one ranking
    if key.endswith("hill_monodromy_difference") or (band and key.endswith(".width")):
        return None
    if band and key.endswith((".e_folding_s", ".growth_exponent", ".amplification")):
        return None  # 1/growth, growth T, exp(growth T): the growth itself is compared below
    if key.startswith(".forced_response."):
        if key.endswith("max_change") or ".Omega" in key:
            return None
        if key.startswith(".forced_response.envelopes") or key.endswith(("_N", "_Nm")):
            return 1e-8, FORCED_LOAD_ATOL
    rel, tol = (1e-8, 1e-12) if key.startswith(SOLVED) else (1e-12, 1e-300)
    if band and key.endswith(("growth_rate_max", ".growth_rate")):
        tol = 1e-7
    if key.endswith(".critical_damping_ratio"):
        # a root in zeta to rtol 1e-6 of itself (floquet.critical_damping), in each system
        rel = 1e-5
    return rel, tol


def _differences(a, b, key=""):
    """The numbers of two results.json trees that differ beyond :func:`_tolerance`, as
    (key, a, b); a whole list of numbers (a column) is compared at once."""
    if isinstance(a, dict):
        assert isinstance(b, dict) and a.keys() == b.keys(), key
        for k in a:
            yield from _differences(a[k], b[k], f"{key}.{k}")
    elif isinstance(a, list):
        assert isinstance(b, list) and len(a) == len(b), key
        if a and all(type(v) in (float, int) for v in a):
            rel, tol = _tolerance(f"{key}[0]")
            x, y = np.array(a, dtype=float), np.array(b, dtype=float)
            ok = (x == y) | (np.abs(y - x) <= np.maximum(rel * np.abs(x), tol))
            yield from ((f"{key}[{i}]", x[i], y[i]) for i in np.flatnonzero(~ok))
        else:
            for i, (u, v) in enumerate(zip(a, b, strict=True)):
                yield from _differences(u, v, f"{key}[{i}]")
    elif isinstance(a, float | int) and not isinstance(a, bool):
        limits = _tolerance(key)
        if limits is not None and not (a == b or abs(b - a) <= max(limits[0] * abs(a),
                                                                   limits[1])):
            yield key, a, b


@pytest.mark.slow
def test_same_case_in_si_and_inch_pound_units(memo_case_dict):
    """The memo case written in inch-pound units (exact conversion factors) gives the same
    results to 1e-12 relative (the solved ones to 1e-8); at a reduced truncation (5 shell modes
    each way, 5 beam modes, 4 Floquet harmonics: every field and stage kept, the conversion
    does not depend on the truncation). Both undamped (modal_ratio = 0): the
    edges of a damped region whose growth barely exceeds 0 are ill-conditioned (a shallow
    maximum crossing zero), so round-off moves them by up to 1e-3 relative between the two unit
    systems, as it would between two machines."""
    undamped = {**memo_case_dict,
                "damping": {**memo_case_dict.get("damping", {}), "modal_ratio": 0.0},
                "truncation": {"M1": 5, "N1": 5, "M2": 5, "N2": 5, "N": 5, "S": 4, "R": 4}}
    si_results = analyze(load_case(undamped), vehicle=False)  # undamped regions: over budget
    si = si_results.case
    b, t = si.booster, si.thrust
    ip = {
        "name": si.name,
        "booster": {
            "thickness": f"{b.thickness / INCH!r} in",
            "E": f"{b.E / (LBF / INCH**2)!r} psi",
            "nu": b.nu,
            "rho": f"{b.rho / (LBF / INCH**4)!r} lbf*s^2/in^4",
            "cylinder1": {
                "radius": f"{b.cylinder1.radius / INCH!r} in",
                "half_length": f"{b.cylinder1.half_length / 12 / INCH!r} ft",
            },
            "cylinder2": {
                "radius": f"{b.cylinder2.radius / INCH!r} in",
                "half_length": f"{b.cylinder2.half_length / 12 / INCH!r} ft",
            },
        },
        "thrust": {
            "F0": f"{t.F0 / LBF!r} lbf",
            "gamma": t.gamma,
            "K": t.K,
            "omega_min": f"{t.omega_min / (2 * math.pi)!r} Hz",
            "omega_max": f"{t.omega_max * 60 / (2 * math.pi)!r} rpm",
            "n_omega": t.n_omega,
            "duration": f"{t.duration / 60.0!r} min",  # the memo case's 150 s
        },
        "truncation": undamped["truncation"],
        "damping": undamped["damping"],
    }
    bad = list(_differences(si_results.to_dict(),
                            analyze(load_case(ip), vehicle=False).to_dict()))
    assert not bad, bad[:8]


@pytest.mark.slow
def test_oversized_stability_table_becomes_a_warning(memo_case_dict, monkeypatch):
    """A truncation whose table would not fit in memory: the analysis goes on without the table
    and says so (warning in the results), instead of crashing."""
    from flexbooster.memo import stability

    original = stability.unstable_frequencies

    def small_limit(*args, **kwargs):
        return original(*args, **kwargs, max_roots=100)

    monkeypatch.setattr("flexbooster.analysis.unstable_frequencies", small_limit)
    res = analyze(load_case(memo_case_dict))
    assert res.stability is None
    codes = [w["code"] for w in res.to_dict()["warnings"]]
    assert codes == ["stability-skipped"]


def test_harmonics_left_out_are_one_warning_per_limit():
    """A low omega_min can leave out dozens of harmonics: one warning per limit names them all
    as ranges and quotes the first reason; a single one stays as it is (the reference: the
    gaps' own k and reasons)."""
    from flexbooster.analysis import _gap_warnings
    from flexbooster.bands import SearchGap

    def steps(k):
        return SearchGap("vehicle", f"harmonic k = {k} not searched: past max_steps",
                         "max_steps", k=k)

    cand = SearchGap("vehicle", "harmonic k = 19 not searched: past max_candidates",
                     "max_candidates", k=19)
    merged = _gap_warnings([steps(k) for k in (2, 3, 4, 7, 9, 10)] + [cand])
    assert [(w.code, w.field) for w in merged] == [("vehicle-regions-skipped",
                                                     "thrust.omega_min")] * 2
    assert merged[0].message == (
        "6 harmonics left out (k = 2-4, 7, 9-10); the first, harmonic k = 2 not searched: "
        "past max_steps; each one's reason is in vehicle_regions.gaps of results.json")
    assert merged[1].message == cand.reason
    assert [w.message for w in _gap_warnings([steps(5)])] == [steps(5).reason]


def test_a_run_builds_each_harmonic_of_its_vehicle_once(monkeypatch, tmp_path):
    """The estimate, the modes survey and the regions and forced stages of one run share the
    case's vehicle and its harmonics (one shared_harmonics block over the run): each harmonic
    k's matrices are assembled once per load state (counter on the assembly; before the block,
    the estimate and each stage assembled them again), and a second run of the same case
    gives results equal to the first (the same numbers, key by key)."""
    import tomllib

    from conftest import dump_toml
    from flexbooster.shell_of_revolution import modes

    root = Path(__file__).resolve().parents[1]
    data = tomllib.loads((root / "examples" / "two-stage-liquid.toml").read_text())
    data["vehicle"].update(k_max=3, n_modes=6)
    path = tmp_path / "case.toml"
    path.write_text(dump_toml(data))
    case = load_case(path)
    calls = []
    real = modes.harmonic_matrices

    def counted(vehicle, mesh, k, *, prestate=None):
        calls.append((id(vehicle), k, prestate is None))
        return real(vehicle, mesh, k, prestate=prestate)

    monkeypatch.setattr(modes, "harmonic_matrices", counted)
    first = analyze(case, figures=False)
    assert calls and len(calls) == len(set(calls)), sorted(calls)
    assert len({c[0] for c in calls}) == 1  # one vehicle object for every stage
    again = analyze(case, figures=False)
    assert json.dumps(again.to_dict()) == json.dumps(first.to_dict())
