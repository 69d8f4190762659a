"""The quantity / value / unit rows shown by both the terminal summary and the report.

One definition of each row: :mod:`flexbooster.present.summary` and
:mod:`flexbooster.present.report` format the same rows (values are numbers, integers or
text; each presentation formats numbers its own way).
"""

from __future__ import annotations

import math

from ..danger import FIRST_SCREEN_WORDS, ResponsePeak, edges_text, g_text
from ..dynamics import STANDARD_GRAVITY
from ..results import Results

__all__ = [
    "Row",
    "input_rows",
    "mass_rows",
    "mass_title",
    "vehicle_mass_rows",
    "slosh_rows",
    "frequency_rows",
    "not_applicable_text",
    "REGION_HEADER",
    "MEMO_ROOT_HEADER",
    "region_modes_words",
    "vehicle_region_verdict",
    "vehicle_region_rows",
    "vehicle_region_table",
    "FORCED_AXIAL_HEADER",
    "forced_axial_rows",
    "memo_root_rows",
    "ROUND_OFF",
    "with_us_units",
    "FIRST_SCREEN_BANDS",
    "FIRST_SCREEN_MODES",
    "BAND_MEASURE_HEADER",
    "band_measure_rows",
    "short_mode_text",
    "danger_scope",
    "range_text",
    "verdict_rows",
    "danger_rows",
    "headline_lines",
    "ranking",
    "DANGER_HEADER",
    "BAND_COLUMNS",
    "band_rows",
    "severity_caption",
]

#: A value smaller than this in magnitude is round-off and shown as 0 by the summary and the
#: report (values are SI; no quantity they show is physically this small).
ROUND_OFF = 1e-14
#: Bands listed on the first screen (terminal and report); all are in results.json.
FIRST_SCREEN_BANDS = 8
#: Modes of a band named on a first screen (the rest counted; all in the report's sections
#: and results.json).
FIRST_SCREEN_MODES = 2
#: Column headings of :func:`danger_rows`.
DANGER_HEADER = ("#", "Omega (rad/s)", "Omega (Hz)", "growth (1/s) / response",
                 "in range", "mode", "mechanism")

#: (quantity, value, unit): the value is a float, an int or text.
Row = tuple[str, object, str]


def input_rows(results: Results) -> list[Row]:
    """The case's input in SI, as (quantity, value, unit) rows.

    Parameters
    ----------
    results : Results
        The analysis.
    """
    case = results.case
    if case.booster is None:
        return with_us_units(results, _segment_input_rows(results))
    b, t, n = case.booster, case.thrust, case.truncation
    rows: list[Row] = [
        ("cylinder 1 (aft) radius R1", b.cylinder1.radius, "m"),
        ("cylinder 1 half-length L1", b.cylinder1.half_length, "m"),
        ("cylinder 2 (forward) radius R2", b.cylinder2.radius, "m"),
        ("cylinder 2 half-length L2", b.cylinder2.half_length, "m"),
        ("shell thickness h", b.thickness, "m"),
        ("Young's modulus E", b.E, "Pa"),
        ("Poisson's ratio nu", b.nu, "-"),
        ("density rho", b.rho, "kg/m^3"),
        ("steady thrust F0", case.F0, "N"),
        ("thrust per unit circumference T0 = F0 / (2 pi R1)", case.T0, "N/m"),
        ("pulsation amplitude gamma, T = T0 (1 - gamma cos Omega t)", t.gamma, "-"),
        ("gimbal gain K", t.K, "-"),
        ("Omega grid: lowest", t.omega_min, "rad/s"),
        ("Omega grid: highest", t.omega_max, "rad/s"),
        ("Omega grid: points", t.n_omega, "-"),
        ("shell modes, cylinder 1: j = 0..M1, k = 0..N1", f"{n.M1}, {n.N1}", "-"),
        ("shell modes, cylinder 2: j = 0..M2, k = 0..N2", f"{n.M2}, {n.N2}", "-"),
        ("beam modes N / Floquet harmonics S / exponents R", f"{n.N} / {n.S} / {n.R}", "-"),
    ]
    damping = getattr(case, "damping", None)
    if damping is not None:
        rows.append(("damping ratio: beam modes / vehicle modes / rigid-body pitch",
                     f"{damping.beam_ratio:g} / {case.vehicle_damping_ratio:g} / "
                     f"{damping.pitch_ratio:g}", "-"))
    return with_us_units(results, rows)


def _segment_input_rows(results: Results) -> list[Row]:
    """The input of a ``[[vehicle.segments]]`` case: the thrust and the vehicle's size (its
    segments are listed with the vehicle modes)."""
    case = results.case
    t, table = case.thrust, case.vehicle
    rows: list[Row] = [
        ("vehicle: [[vehicle.segments]] from the aft edge", str(len(table.segments)), "-"),
        ("vehicle length", sum(seg.length for seg in table.segments), "m"),
        ("aft radius R_aft (the thrust acts around its edge)", case.aft_radius, "m"),
        ("steady thrust F0", case.F0, "N"),
        ("thrust per unit circumference T0 = F0 / (2 pi R_aft)", case.T0, "N/m"),
        ("pulsation amplitude gamma, T = T0 (1 - gamma cos Omega t)", t.gamma, "-"),
        ("gimbal gain K", t.K, "-"),
        ("Omega grid: lowest", t.omega_min, "rad/s"),
        ("Omega grid: highest", t.omega_max, "rad/s"),
        ("Omega grid: points", t.n_omega, "-"),
        ("damping ratio: rigid-body pitch", case.damping.pitch_ratio, "-"),
    ]
    return rows


def not_applicable_text(results: Results) -> str | None:
    """"not applicable: <reason>" for the memo's sections of a ``[[vehicle.segments]]`` case;
    None where the memo's method applies (``[booster]``).

    Parameters
    ----------
    results : Results
        The analysis.
    """
    reason = results.not_applicable
    return None if reason is None else f"not applicable: {reason}"


def with_us_units(results: Results, rows: list[Row]) -> list[Row]:
    """The rows with the inch-pound value beside SI ("5.05 (198.819 in)") when the case asks
    ``[output] units = "US"``; unchanged otherwise or for units without a US counterpart.

    Parameters
    ----------
    results : Results
        The analysis (its ``case.output.units``).
    rows : list of (str, object, str)
        Quantity / value / SI unit rows.
    """
    output = getattr(results.case, "output", None)
    if output is None or output.units != "US":
        return rows
    from ..units import to_us

    out: list[Row] = []
    for quantity, value, unit in rows:
        try:  # a value whose inch-pound figure is beyond the float range: SI alone
            us = to_us(value, unit) if isinstance(value, float) else None
        except ValueError:
            us = None
        if us is not None:
            value = f"{value:.6g} ({us[0]:.6g} {us[1]})"
        out.append((quantity, value, unit))
    return out


def mass_rows(results: Results) -> list[Row]:
    """Geometry and mass properties (memo 2.2, Fig. 1; I_cm per erratum E1).

    Parameters
    ----------
    results : Results
        The analysis.
    """
    if results.vehicle_mass is not None:
        return with_us_units(results, vehicle_mass_rows(results.vehicle_mass))
    m = results.mass

    def g(x: float) -> str:
        return f"{x:.6g}"

    rows: list[Row] = [
        ("half-length of the booster L = L1 + L2", m.L, "m"),
        ("mass of cylinder 1 / cylinder 2", f"{g(m.m1)} / {g(m.m2)}", "kg"),
        ("total mass", m.mass, "kg"),
        ("centre of mass from the aft edge x_cm", m.x_cm, "m"),
        ("cylinder holding the centre of mass", str(m.cm_cylinder), "-"),
        ("d1 / d2 / d3 / d4 (Fig. 1)", " / ".join(g(v) for v in (m.d1, m.d2, m.d3, m.d4)), "m"),
        ("aft edge a / junction c / nose b in xi_bar = (x - x_cm)/L",
         " / ".join(g(v) for v in (m.a, m.c, m.b)), "-"),
        ("pitch moment of inertia about the CM, I_cm (erratum E1)", m.I_cm, "kg m^2"),
    ]
    return with_us_units(results, rows)


def mass_title(results: Results) -> str:
    """The title of the mass-properties table: the memo's (``[booster]``) or the vehicle's.

    Parameters
    ----------
    results : Results
        The analysis.
    """
    if results.vehicle_mass is not None:
        return "Mass properties of the vehicle (each contribution; from the aft edge)"
    return "Mass properties (memo 2.2, Fig. 1; I_cm per erratum E1)"


def vehicle_mass_rows(mp) -> list[Row]:
    """Total mass, centre of mass, pitch inertia and every contribution of the vehicle.

    Parameters
    ----------
    mp : flexbooster.shell_of_revolution.MassProperties
        The vehicle's mass properties.
    """
    rows: list[Row] = [
        ("total mass", mp.mass_kg, "kg"),
        ("centre of mass from the aft edge", mp.cm_m, "m"),
        ("pitch moment of inertia about the centre of mass, I_cm", mp.I_cm_kg_m2, "kg m^2"),
    ]
    rows.append(("each contribution below: mass / its centre of mass / its own I_cm", "-",
                 "kg / m / kg m^2"))
    rows += [(c.kind if c.name == c.kind else f"{c.kind}: {c.name}",
              f"{c.mass_kg:.6g} / {c.cm_m:.6g} / {c.I_cm_kg_m2:.6g}", "kg / m / kg m^2")
             for c in mp.contributions]
    return rows


def slosh_rows(slosh) -> list[Row]:
    """Each tank's first slosh frequency under the thrust's acceleration and its slosh mass
    (Abramson, NASA SP-106, spring-mass analogy).

    Parameters
    ----------
    slosh : sequence of SloshMode
        ``VehicleSurvey.slosh``.
    """
    return [(f"tank {m.tank}: first slosh frequency / slosh mass",
             f"{m.hz:.6g} / {m.mass_kg:.6g}", "Hz / kg") for m in slosh]


def frequency_rows(results: Results) -> list[Row]:
    """omega_1, omega_psi and the dimensionless groups (memo 3.0, 4.2).

    Parameters
    ----------
    results : Results
        The analysis.
    """
    two_pi = 2.0 * math.pi
    na = not_applicable_text(results)
    if na is not None:
        return [
            ("first free-free bending frequency omega_1 (4.2-8b)", na, "-"),
            ("rigid-body pitch frequency omega_psi = sqrt(F0 d K / I_cm), d = centre of mass "
             "from the aft edge", results.omega_psi, "rad/s"),
            ("  in Hz", results.omega_psi / two_pi, "Hz"),
            ("Mathieu a over the Omega grid",
             f"{float(results.a.min()):.6g} .. {float(results.a.max()):.6g}", "-"),
            ("Mathieu q over the Omega grid",
             f"{float(results.q.min()):.6g} .. {float(results.q.max()):.6g}", "-"),
        ]
    g = results.groups
    return [
        ("first free-free bending frequency omega_1 (4.2-8b)", results.omega_1, "rad/s"),
        ("  in Hz", results.omega_1 / two_pi, "Hz"),
        ("rigid-body pitch frequency omega_psi = sqrt(F0 d2 K / I_cm)", results.omega_psi,
         "rad/s"),
        ("  in Hz", results.omega_psi / two_pi, "Hz"),
        ("mu = rho L^2 omega_1^2 / E", g.mu, "-"),
        ("lambda_1 = L/R1, lambda_2 = L/R2", f"{g.lambda1:.6g}, {g.lambda2:.6g}", "-"),
        ("sigma = h/L", g.sigma, "-"),
        ("T0_bar = T0 / (rho h L^2 omega_1^2)", g.T0_bar, "-"),
        ("Mathieu a over the Omega grid",
         f"{float(results.a.min()):.6g} .. {float(results.a.max()):.6g}", "-"),
        ("Mathieu q over the Omega grid",
         f"{float(results.q.min()):.6g} .. {float(results.q.max()):.6g}", "-"),
    ]


def range_text(lo: float, hi: float) -> str:
    """'lo-hi' with the fewest significant digits (4..10) that tell the edges apart
    (:func:`flexbooster.danger.edges_text`).

    Parameters
    ----------
    lo, hi : float
        Edges (any unit).
    """
    return edges_text(lo, hi)


def verdict_rows(results: Results) -> list[tuple[str, str]]:
    """(mechanism in words, verdict) for each mechanism; "not computed" where absent.

    Parameters
    ----------
    results : Results
        The analysis.
    """
    if results.danger is None:
        return [("all mechanisms", "not computed")]
    return [(FIRST_SCREEN_WORDS.get(key, words), verdict)
            for key, words, verdict in results.danger.verdicts]


def headline_lines(results: Results) -> list[str]:
    """The first screen's lines of the forced response (the largest acceleration, the largest
    loads) and of the flight (its worst moment that counts), when the case has them.

    Parameters
    ----------
    results : Results
        The analysis.
    """
    from .forced import forced_worst_lines

    out = []
    f = results.forced_response
    peaks = () if f is None else f.ranked_peaks()
    if peaks:
        p = peaks[0]
        out.append(f"Forced response: largest acceleration {p.acceleration_g:.4g} g at "
                   f"{p.station} ({p.station_m:.4g} m, k = {p.k}), Omega = "
                   f"{p.Omega / (2.0 * math.pi):.4g} Hz")
        out += ["  " + line for line in forced_worst_lines(results)]
    if results.flight is not None:
        from .flight import flight_lines

        lines = flight_lines(results.flight)
        out.append("Flight: " + lines[0])
        out += ["  " + line for line in lines if "negligible growth dropped" in line]
    return out


def ranking(results: Results) -> tuple:
    """The bands and the vehicle's bounded responses in one ranking
    (:attr:`flexbooster.danger.DangerSummary.ranking`; the bands alone where it is empty).

    Parameters
    ----------
    results : Results
        The analysis.
    """
    if results.danger is None:
        return ()
    return results.danger.ranking or results.danger.bands


def danger_scope(results: Results) -> str:
    """What the list of the most dangerous thrust frequencies covers, for a case with
    ``[flight]`` (its single analysis is of the case's own ``[vehicle]`` and ``[thrust]``, one
    state, while the flight's events are listed apart); "" otherwise.

    Parameters
    ----------
    results : Results
        The analysis.
    """
    if results.flight is None:
        return ""
    return ("; the case's [vehicle] and [thrust] as given, one vehicle state; the flight's "
            "events are under Flight")


def short_mode_text(text: str, keep: int = FIRST_SCREEN_MODES) -> str:
    """A band's modes ("A + B + C + D") with the first ``keep`` named and the rest counted:
    "A + B + 2 more".

    Parameters
    ----------
    text : str
        The modes joined by " + ".
    keep : int
        Modes named, >= 1.
    """
    modes = text.split(" + ")
    if len(modes) > keep:
        modes = [*modes[:keep], f"{len(modes) - keep} more"]
    return " + ".join(modes)


def danger_rows(results: Results, limit: int = FIRST_SCREEN_BANDS,
                modes: int | None = None) -> list[tuple[str, ...]]:
    """The most dangerous bands and bounded responses, ranked, as text cells (columns
    :data:`DANGER_HEADER`; a response: its acceleration in g, station and load).

    Parameters
    ----------
    results : Results
        The analysis.
    limit : int
        Rows shown, >= 0.
    modes : int or None
        Modes named per band (:func:`short_mode_text`); None names all.
    """
    if results.danger is None:
        return []
    out = []
    for n, b in enumerate(ranking(results)[:limit]):
        if isinstance(b, ResponsePeak):  # a bounded forced response of the vehicle
            also = "".join(f"; also {a}" for a in b.also)
            load = "" if b.load is None else (f", {b.load_quantity} {b.load:.3g} {b.load_unit}"
                                               f" at {b.load_station_m:.4g} m")
            end = "; at the end of the Omega range: larger beyond it" * b.at_range_end
            out.append((str(n + 1), f"{b.Omega:.6g}", f"{b.hz:.6g}", g_text(b.acceleration_g),
                        "yes" if b.in_operating_range else "no",
                        f"{b.station} ({b.station_m:.4g} m), k = {b.k}",
                        f"{b.source} of the vehicle{load}{also}{end}"))
            continue
        lo_hz, hi_hz = b.hz
        if b.growth_rate is not None:
            level = f"{b.growth_rate:.3g}"
        elif b.band.steady_acceleration is not None:  # damped: the steady response, in g
            level = g_text(b.band.steady_acceleration / STANDARD_GRAVITY)
        elif b.severity is not None:
            level = f"sev. {b.severity:.3g}"
        else:
            level = "-"
        out.append((str(n + 1), range_text(b.Omega_lo, b.Omega_hi), range_text(lo_hz, hi_hz),
                    level, "yes" if b.in_operating_range else "no",
                    b.mode_text if modes is None else short_mode_text(b.mode_text, modes),
                    b.cause_text))
    return out


#: Column headings of :func:`band_measure_rows`.
BAND_MEASURE_HEADER = ("#", "Omega (Hz)", "mechanism", "growth (1/s)", "e-folding (s)",
                       "amplification", "critical gamma", "margin", "critical damping ratio",
                       "steady response")


def _g(value: float | None, unit: str = "") -> str:
    """4 significant digits, or "-" for None."""
    return "-" if value is None else f"{value:.4g}{unit}"


def band_measure_rows(results: Results, limit: int = 50) -> list[tuple[str, ...]]:
    """The measures of the ranked bands (docs/theory/verdicts.md) as text cells, numbered as
    :func:`danger_rows`: growth rate, e-folding time, amplification over the duration,
    critical gamma at the case's damping, margin critical gamma / gamma, critical damping
    ratio, and a resonance's damped steady response (columns :data:`BAND_MEASURE_HEADER`).

    Parameters
    ----------
    results : Results
        The analysis.
    limit : int
        Rows shown, >= 0.
    """
    if results.danger is None:
        return []
    out = []
    for n, rb in enumerate(results.danger.bands[:limit]):
        b = rb.band
        region = b.mechanism != "resonance"
        steady = "-" if b.steady_amplitude is None else (
            f"{1e3 * b.steady_amplitude:.3g} mm "
            f"({g_text(b.steady_acceleration / STANDARD_GRAVITY)})")
        out.append((str(n + 1), range_text(*rb.hz), b.mechanism.replace("_", " "),
                    _g(b.growth_rate_max) if region else "-",
                    _g(b.e_folding_s) if region else "-", _g(b.amplification),
                    _g(b.critical_gamma) if region and b.critical_gamma > 0.0 else "-",
                    _g(b.margin), _g(b.critical_damping_ratio), steady))
    return out


#: Columns of :func:`vehicle_region_table` (summary and report).
REGION_HEADER = ("Omega from (rad/s)", "to (rad/s)", "from (Hz)", "to (Hz)", "k", "modes",
                 "kind", "j", "max growth (1/s)", "critical gamma", "active memo root inside")
#: Columns of :func:`memo_root_rows`.
MEMO_ROOT_HEADER = ("region (k, kind, j, Omega rad/s)", "root Omega (rad/s)", "family",
                    "shell mode d, j, k, m", "forcing", "same k", "severity")


def region_modes_words(region) -> str:
    """The modes of a vehicle region in words, e.g. "mode 1 (radial, order 0) + mode 2 (axial,
    order 1)" (1-based loaded-mode index within its harmonic k).

    Parameters
    ----------
    region : Band
        One region of :class:`flexbooster.dynamics.VehicleRegions`.
    """
    return " + ".join(f"mode {m.index + 1} ({m.type}, order {m.order})" for m in region.modes)


def _hz(x: float) -> float:
    return x / (2.0 * math.pi)


def vehicle_region_verdict(results: Results) -> tuple[str, bool]:
    """(verdict line, stable) of the vehicle's parametric regions; stable when no region reaches
    the Omega range (or none was computed).

    Parameters
    ----------
    results : Results
        The analysis.
    """
    vr = results.vehicle_regions
    if vr is None:
        return "not computed", True
    where = (f"Omega in [{vr.omega_min:.6g}, {vr.omega_max:.6g}] rad/s at gamma = "
             f"{vr.gamma:g}, damping ratio {vr.damping_ratio:g}")
    if not vr.regions and vr.gaps:
        return (f"not fully searched: {len(vr.gaps)} harmonic(s) not searched; no region in "
                f"the others at {where}"), False
    if not vr.regions:
        return f"stable: no parametric instability region reaches {where}", True
    worst = max(vr.regions, key=lambda r: r.growth_rate_max)
    n = len(vr.regions)
    what = f"{n} parametric instability regions reach" if n > 1 else \
        "1 parametric instability region reaches"
    return (f"unstable: {what} {where}; worst growth rate {worst.growth_rate_max:.4g} 1/s "
            f"(k = {worst.k}, {worst.kind}, Omega {worst.Omega_lo:.6g}.."
            f"{worst.Omega_hi:.6g} rad/s)"), False


def vehicle_region_rows(results: Results) -> list[Row]:
    """Settings and verdict of the vehicle's parametric instability regions.

    Parameters
    ----------
    results : Results
        The analysis (``results.vehicle_regions`` not None).
    """
    vr = results.vehicle_regions
    verdict, _ = vehicle_region_verdict(results)
    rows: list[Row] = [("verdict", verdict, "")]
    if vr is None:
        return rows
    ks = [h.k for h in vr.harmonics]
    n_modes = sorted({h.omega_unloaded.size for h in vr.harmonics})
    rows += [
        ("modal damping ratio zeta of the loaded shell modes (damping.modal_ratio)",
         vr.damping_ratio, "-"),
        ("harmonics k / modes per k (vehicle.n_modes)",
         f"{min(ks)}..{max(ks)} / {', '.join(str(n) for n in n_modes)}" if ks else "none", "-"),
        ("thrust load distribution", {
            "inertia relief": "inertia relief (free-free vehicle)",
            "forward support": "uniform compression (forward end supported)",
            "aft support": "none (the supported aft end takes the thrust)"}[vr.load_path],
         "-"),
        ("steady thrust F0 / pulsation amplitude gamma", f"{vr.F0:.6g} / {vr.gamma:g}", "N / -"),
        ("regions in the Omega range", len(vr.regions), "-"),
    ]
    if vr.regions:
        worst = max(vr.regions, key=lambda r: r.growth_rate_max)
        rows.append(("largest growth rate", worst.growth_rate_max, "1/s"))
    if vr.curves:
        tip = min(vr.curves, key=lambda c: float(c.gamma[0]))
        rows.append((f"lowest critical gamma of the charted regions (k = {tip.k}, {tip.kind})",
                     float(tip.gamma[0]), "-"))
    m = results.memo_roots_in_regions
    if m is not None and vr.regions:
        rows.append(("regions holding a memo-table root with active forcing",
                     f"{m.n_regions - m.without_active_root.size} of {m.n_regions}", "-"))
    fa = getattr(vr, "forced_axial", None)
    if fa is not None:
        rows.append(("k = 0 axial modes forced directly by the thrust pulsation (resonances "
                     "Omega = omega_n in the range)", len(fa.resonances), "-"))
    return rows


#: Columns of :func:`forced_axial_rows`.
FORCED_AXIAL_HEADER = ("Omega rad/s", "Omega Hz", "mode (k = 0)", "static flexibility m/N",
                       "resonant amplitude m/N", "amplitude at gamma F0, m")


def forced_axial_rows(results: Results) -> list[tuple]:
    """The k = 0 forced resonances (memo family 3), one row each: Omega (rad/s, Hz), the mode,
    phi_n^2 / omega_n^2 (m/N), the resonant amplitude per unit axial load (m/N; "-" undamped)
    and for the case's gamma F0 (m).

    Parameters
    ----------
    results : Results
        The analysis.
    """
    vr = results.vehicle_regions
    fa = None if vr is None else getattr(vr, "forced_axial", None)
    if fa is None:
        return []
    load = vr.gamma * vr.F0  # N, the pulsating part of the thrust
    return [(r.omega, _hz(r.omega), f"{r.type}, order {r.order}", r.flexibility,
             "-" if r.amplitude is None else r.amplitude,
             "-" if r.amplitude is None else r.amplitude * load) for r in fa.resonances]


def vehicle_region_table(results: Results) -> list[tuple]:
    """The vehicle regions by decreasing growth rate (:data:`REGION_HEADER`): Omega range (rad/s,
    Hz), k, modes, kind, j, growth rate (1/s), critical gamma, and whether an active memo root
    lies inside ("-": not compared).

    Parameters
    ----------
    results : Results
        The analysis.
    """
    vr = results.vehicle_regions
    if vr is None:
        return []
    m = results.memo_roots_in_regions
    unexplained = set() if m is None else {int(i) for i in m.without_active_root}
    order = sorted(range(len(vr.regions)),
                   key=lambda i: (-vr.regions[i].growth_rate_max, vr.regions[i].Omega_lo))
    rows = []
    for i in order:
        r = vr.regions[i]
        memo = "-" if m is None else ("no" if i in unexplained else "yes")
        rows.append((r.Omega_lo, r.Omega_hi, _hz(r.Omega_lo), _hz(r.Omega_hi), r.k,
                     region_modes_words(r), r.kind, r.order, r.growth_rate_max,
                     r.critical_gamma, memo))
    return rows


def memo_root_rows(results: Results) -> list[tuple]:
    """The memo-table roots inside the vehicle regions, one row per pair (:data:`MEMO_ROOT_HEADER`).

    Parameters
    ----------
    results : Results
        The analysis.
    """
    m, vr = results.memo_roots_in_regions, results.vehicle_regions
    if m is None or vr is None:
        return []
    out = []
    for n in range(len(m)):
        r = vr.regions[int(m.region[n])]
        out.append((f"k = {r.k}, {r.kind}, j = {r.order}, {r.Omega_lo:.6g}..{r.Omega_hi:.6g}",
                    float(m.Omega[n]), int(m.family[n]),
                    f"{m.cylinder[n]}, {m.j[n]}, {m.k[n]}, {m.branch[n]}",
                    "active" if m.active[n] else "listed", "yes" if m.same_k[n] else "no",
                    "-" if m.severity is None else str(m.severity[n])))
    return out


#: Columns of the table of the most severe resonance bands (summary and report).
BAND_COLUMNS = ("#", "Omega rad/s", "Hz", "band rad/s", "severity m/s", "rel.",
                "mode (cyl, j, k, m, type)", "family", "cause")


def band_rows(results: Results, limit: int = 10) -> list[tuple[str, ...]]:
    """The most severe resonance bands as text rows (:data:`BAND_COLUMNS`), most severe first;
    empty without the severity.

    Parameters
    ----------
    results : Results
        The analysis (its stored ``severity.bands``).
    limit : int
        Largest number of rows.
    """
    sev = getattr(results, "severity", None)
    if sev is None:
        return []
    out = []
    for n, b in enumerate(sev.bands[:limit], start=1):
        top = b.modes[0]
        c, j, k, m, typ = top.cylinder, top.order, top.k, top.index, top.type
        more = f" +{len(b.modes) - 1}" if len(b.modes) > 1 else ""
        fams = ",".join(str(f) for f in b.families)
        out.append((str(n), f"{b.Omega_at_max:.6g}", f"{b.Omega_at_max / (2 * math.pi):.6g}",
                    f"{b.Omega_lo:.6g}..{b.Omega_hi:.6g}", f"{b.severity:.3g}",
                    f"{b.severity_rel:.3g}", f"{c}, {j}, {k}, {m}, {typ}{more}",
                    f"{b.order} ({fams})" if len(b.families) > 1 else str(b.order),
                    b.cause))
    return out


def severity_caption(results: Results) -> str:
    """One sentence: what the severity is, its reference amplitudes and what "active" means
    (empty without the severity).

    Parameters
    ----------
    results : Results
        The analysis.
    """
    sev = getattr(results, "severity", None)
    st = results.stability
    if sev is None or st is None:
        return ""
    r = sev.roots
    return (f"{len(st)} roots, {int(r.active.sum())} active (severity_rel >= {r.threshold:g}); "
            f"{len(sev.bands)} bands (active roots within {100 * sev.resolution:g} % of Omega). "
            "Severity: secular growth rate of the resonant shell mode's surface displacement "
            f"(m/s) for gamma = {results.case.thrust.gamma:g}, psi0 = {r.psi0:g} rad and a beam "
            f"Floquet amplitude {r.beam_amplitude:g} L.")
