"""The analysis report: one self-contained HTML file (``report.html``).

It formats what the analysis computed: inline style sheet, inline SVG figures (ids prefixed
per figure), no script; every text escaped, a non-finite number shown as "n/a"; the markup
is well-formed XML (polyglot HTML5). Sections by ``id``: ``summary``, ``inputs``,
``mass-properties``, ``frequencies``, ``beam-modes``, ``rigid-body``, ``beam-action``,
``shell-frequencies``, ``nodal-patterns``, ``unstable-frequencies``, ``campbell``,
``vehicle-regions``, ``verification``, ``warnings``.
"""

from __future__ import annotations

import html
import math
import os
import re
from collections.abc import Callable, Mapping, Sequence
from datetime import UTC, datetime
from pathlib import Path

import numpy as np

from .. import __version__
from ..memo.charts import (
    BAND_CHART_GAMMA_MAX,
    BEAM_ACTION_CHART_LEVELS,
    BEAM_ACTION_CHART_MAX_ORDER,
    BEAM_ACTION_CHART_RTOL,
    PITCH_BAND_CHART_LEVELS,
    VEHICLE_CHART_GAMMA_MAX,
    VEHICLE_CHART_LEVELS,
)
from ..results import Results
from .flight import FLIGHT_FIGURES, flight_report_html
from .forced import (
    FORCED_CSV,
    FORCED_FIGURES,
    FORCED_HEADER,
    FORCED_ZERO,
    forced_basis_text,
    forced_rows,
    forced_worst_lines,
)
from .io import write_text_atomic
from .rows import (
    BAND_COLUMNS,
    BAND_MEASURE_HEADER,
    DANGER_HEADER,
    FIRST_SCREEN_BANDS,
    FIRST_SCREEN_MODES,
    FORCED_AXIAL_HEADER,
    MEMO_ROOT_HEADER,
    REGION_HEADER,
    ROUND_OFF,
    band_measure_rows,
    band_rows,
    danger_rows,
    danger_scope,
    forced_axial_rows,
    frequency_rows,
    headline_lines,
    input_rows,
    mass_rows,
    memo_root_rows,
    not_applicable_text,
    ranking,
    severity_caption,
    slosh_rows,
    vehicle_region_rows,
    vehicle_region_table,
    vehicle_region_verdict,
    verdict_rows,
)

__all__ = [
    "SECTIONS",
    "FIGURES",
    "VERIFICATION",
    "VEHICLE_VERIFICATION",
    "FORCED_VERIFICATION",
    "FLIGHT_VERIFICATION",
    "verification_rows",
    "MAX_UNSTABLE_ROWS",
    "MEMO_SECTIONS",
    "ROUND_OFF",
    "inline_svg",
    "render_report",
    "write_report",
]

#: Section ids and titles, in the order of the report.
SECTIONS: tuple[tuple[str, str], ...] = (
    ("summary", "Summary"),
    ("inputs", "Inputs"),
    ("mass-properties", "Mass properties"),
    ("frequencies", "Reference frequencies and dimensionless groups"),
    ("beam-modes", "Free-free beam modes"),
    ("rigid-body", "Rigid-body pitch"),
    ("beam-action", "Beam action"),
    ("shell-frequencies", "Shell natural frequencies"),
    ("nodal-patterns", "Shell nodal patterns"),
    ("unstable-frequencies", "Unstable thrust frequencies"),
    ("campbell", "Campbell diagram"),
    ("vehicle-regions", "Vehicle parametric instability regions"),
    ("forced-response", "Forced response to the thrust oscillation"),
    ("verification", "Verification summary"),
    ("warnings", "Warnings"),
)
#: The sections of the memo's method alone: left out of the report of a
#: ``[[vehicle.segments]]`` case (its summary names them and says why).
MEMO_SECTIONS = ("beam-modes", "beam-action", "shell-frequencies", "nodal-patterns",
                 "unstable-frequencies", "campbell")

#: Figure name (the file stem written by
#: :func:`flexbooster.present.outputs.write_outputs`) -> section
#: and caption.
FIGURES: dict[str, tuple[str, str]] = {
    **{name: ("forced-response", caption) for name, caption in FORCED_FIGURES.items()},
    "danger-map": (
        "summary",
        "Danger map: every unstable or resonant band of the thrust frequency Omega (Hz, "
        "logarithmic) of every mechanism computed, one panel per quantity: instability regions "
        "as bars up to their largest growth rate (1/s, logarithmic; coloured by mechanism; "
        "dotted: the growth below which a band is negligible; bands narrower than 1.2 % of a "
        "decade drawn that wide), forced resonances as stems up to their damped steady "
        "response (mm; undamped: their severity), the vehicle's forced responses as stems up "
        "to their acceleration (g); the five most dangerous numbered as in the list above; "
        "grey: outside the operating range. Hover a band or stem for its values.",
    ),
    "beam-modes": (
        "beam-modes",
        "Free-free mode shapes phi_n of the equivalent beam (appendix C) against the station "
        "x = L zeta from the aft edge (m); dashed: the junction of the cylinders, dotted: the "
        "centre of mass.",
    ),
    "ince-strutt": (
        "rigid-body",
        "Ince-Strutt chart of the pitch equation (4.2-3), zoomed to the operating path "
        "(a(Omega), q(Omega)) of eq. (4.2-4), its points labelled in Hz; shaded: unstable; red "
        "points: unstable grid points; the next transition curve above the view is named.",
    ),
    "shell-frequencies-cylinder1": (
        "shell-frequencies",
        "Shell frequencies of cylinder 1 (aft) against the circumferential wave number k, one "
        "line per axial index j (branch 1).",
    ),
    "shell-frequencies-cylinder2": (
        "shell-frequencies",
        "Shell frequencies of cylinder 2 (forward), as for cylinder 1.",
    ),
    "nodal-patterns": (
        "nodal-patterns",
        "Nodal patterns on the unrolled surfaces, as in memo Fig. 4: cylinder 1 j = 4, k = 3; "
        "cylinder 2 j = 6, k = 2 (or the largest indices of the truncation), with the lowest "
        "frequency of that (j, k).  Radial displacement sin(j pi s/2) cos(k theta) (eqs. 5.3-2d, "
        "5.3-3d) positive in red, negative in blue; nodal lines black.",
    ),
    "pitch-band-chart": (
        "rigid-body",
        "Instability tongues of the rigid-body pitch in the plane of the thrust frequency Omega "
        "(Hz) and the pulsation amplitude gamma: edges where the path (4.2-4) crosses the "
        f"transition curves a_r, b_r, at {PITCH_BAND_CHART_LEVELS} levels of gamma in "
        f"[0, {BAND_CHART_GAMMA_MAX:g}] at the case's pitch damping; dashed: the case's gamma, "
        "on it (thick) the tongues open there.",
    ),
    "beam-action-chart": (
        "beam-action",
        "Instability regions of the beam-action system (memo 4.1) in the plane of the thrust "
        "frequency Omega (Hz) and the pulsation amplitude gamma, traced from their boundaries "
        f"(|rho| = 1) at {BEAM_ACTION_CHART_LEVELS - 1} levels of gamma up to "
        f"{BAND_CHART_GAMMA_MAX:g} and the tip; resonances of order <= "
        f"{BEAM_ACTION_CHART_MAX_ORDER} wider than {BEAM_ACTION_CHART_RTOL:g} of "
        "their centre, at the case's damping (in the title); dashed: the case's gamma, on it "
        "(thick) the regions open there at that damping (their edges also put into the "
        "outlines); grey: below the searched range.",
    ),
    "campbell": (
        "campbell",
        "Excitation curves of memo 7.3 against the thrust frequency (Hz, logarithmic; "
        "Omega/omega_1 on top), one colour per family; thin grey lines: the shell frequencies "
        "on which an active root lies; red points: the active roots (severity_rel at or above "
        "the threshold; the other listed roots are in unstable-frequencies.csv, not drawn).",
    ),
    "vehicle-regions": (
        "vehicle-regions",
        "Parametric instability regions of the vehicle (shell of revolution under "
        "T = F0 (1 - gamma cos Omega t), modal damping) in the plane of the thrust frequency "
        "Omega (Hz) and the pulsation amplitude gamma, traced from their boundaries "
        f"(|rho| = 1) at {VEHICLE_CHART_LEVELS - 1} levels of gamma up to "
        f"{VEHICLE_CHART_GAMMA_MAX:g} (or the case's gamma if larger) and the tip at the "
        "critical gamma; coloured by the largest "
        "growth rate at the case's gamma (dashed; dots: the regions there; a logarithmic "
        "colour scale when the rates span more than two decades), grey where the region does "
        "not reach it.",
    ),
}

#: Largest number of rows of the unstable-frequency table shown (all are in the CSV).
MAX_UNSTABLE_ROWS = 200
#: Shell frequencies listed per cylinder (all are in shell-frequencies.csv).
_SHELL_ROWS = 12

#: What each result was checked against: (quantity, reference, tolerance, test).
VERIFICATION: tuple[tuple[str, str, str, str], ...] = (
    ("mass, x_cm, I_cm", "surface quadrature (Gauss-Legendre 20 points per cylinder x 64 "
     "trapezoidal points in theta), four boosters", "1e-12 relative",
     "test_geometry::test_mass_properties_against_surface_quadrature"),
    ("d1..d4, a, c, b", "the relations of memo Fig. 1", "1e-12 relative",
     "test_geometry::test_distances_and_coordinates_follow_figure_1"),
    ("I_cm (erratum E1)", "single-cylinder limit m (R^2/2 + (2 L1)^2/12)", "1e-12 relative",
     "test_geometry::test_single_cylinder_limit"),
    ("lambda_n (free-free beam)", "Blevins / Young & Felgar tables; mpmath root of "
     "cos cosh = 1", "1e-9 relative", "test_beam::test_lambda_reference_values"),
    ("omega_1 (4.2-8b)", "section properties of a thin tube, EI / (rho A)", "1e-9 relative",
     "test_beam::test_omega_1_from_section_properties"),
    ("beam modes orthonormal", "Gram matrix by quadrature, N up to 200", "1e-10 absolute",
     "test_beam::test_modes_orthonormal_up_to_n_200"),
    ("Mathieu exponent beta", "mpmath 50-digit Taylor series of y1(pi)", "1e-8 in beta",
     "test_pitch::test_exponent_against_mpmath"),
    ("transition curves a_r, b_r", "scipy.special.mathieu_a / mathieu_b", "1e-10 absolute",
     "test_pitch::test_transition_curves_match_scipy"),
    ("pitch growth rate", "direct integration (solve_ivp, rtol 1e-12)", "see test",
     "test_pitch::test_growth_rate_matches_direct_integration"),
    ("beta memo formula (4.2-9, E4)", "exact exponent: error O(q^4) corrected, O(q^2) printed",
     "slope", "test_pitch::test_memo_formula_error_is_order_q4_and_printed_is_order_q2"),
    ("shell frequencies", "Donnell shear-diaphragm frequencies (Leissa, NASA SP-288, eq. 2.20)",
     "1e-10 relative", "test_shell::test_d2_frequencies_equal_donnell_frequencies"),
    ("shell frequencies (roots)", "mpmath roots of the Donnell cubic", "see test",
     "test_shell::test_donnell_roots_against_mpmath"),
    ("follower flutter load", "Beal (1965), P l^2/EI = 109.69", "1e-3 relative",
     "test_beam_action::test_follower_flutter_load_beal"),
    ("loaded-beam frequencies", "continuous beam by shooting (solve_ivp DOP853, rtol 1e-12)",
     "2e-5 relative", "test_beam_action::test_steady_frequencies_against_continuous_beam_shooting"),
    ("alpha_r: Hill against monodromy", "two methods, stable and unstable points",
     "1e-8 absolute",
     "test_beam_action::test_hill_and_monodromy_agree_1e8_including_unstable_points"),
    ("unstable thrust frequencies", "brute-force scan of every excitation curve",
     "same roots, 1e-9", "test_stability::test_same_roots_as_brute_force_scan"),
    ("root residuals", "the memo's equations 7.3 re-evaluated", "1e-9 in Omega/omega_1",
     "test_stability::test_every_root_satisfies_its_equation"),
    ("vehicle region edges", "exact Mathieu edges (scipy mathieu_a / mathieu_b), "
     "shear-diaphragm cylinder", "1e-6 relative",
     "test_vehicle_regions::test_sd_cylinder_regions_are_mathieu_regions"),
    ("vehicle region growth rates", "Floquet monodromy of the full multi-mode system",
     "1e-6 relative", "test_vehicle_regions::test_vehicle_growth_rates_against_monodromy"),
    ("memo roots inside the regions", "hand-made table and regions with known answers",
     "exact", "test_vehicle_pipeline::test_memo_roots_in_regions_hand_made_table"),
)

#: The same for a ``[[vehicle.segments]]`` case: the rigid pitch (the memo's Mathieu numerics),
#: then the vehicle model (mass, liquid, slosh, pressure, stiffeners, prestate, regions).
VEHICLE_VERIFICATION: tuple[tuple[str, str, str, str], ...] = (
    *(row for row in VERIFICATION if row[3].startswith("test_pitch::test_")
      and "memo_formula" not in row[3]),
    ("vehicle mass, centre of mass, I_cm", "the defining integrals by an independent "
     "quadrature, each contribution and the total", "1e-10 relative",
     "test_vehicle_mass::test_mass_properties_match_an_independent_quadrature"),
    ("rigid pitch under the follower thrust", "F0 d K / I_cm (memo eq. 4.2-1) from the mass "
     "properties", "1e-6 relative",
     "test_vehicle_prestress::test_rigid_pitch_under_the_follower_thrust"),
    ("liquid added mass", "separation of variables, rho_L I_n / (lambda I_n'), cylinder with "
     "pressure-release ends", "1e-5 relative",
     "test_liquid::test_pressure_release_added_mass_closed_form"),
    ("wet frequencies of a full tank", "series solution of the potential between rigid "
     "bulkheads, shear-diaphragm cylinder", "0.5 %",
     "test_liquid::test_sd_cylinder_between_rigid_bulkheads"),
    ("lateral added mass with a free surface", "liquid mass minus all slosh masses "
     "(Abramson, NASA SP-106, series)", "1e-4 relative",
     "test_liquid::test_free_surface_lateral_added_mass_is_liquid_minus_all_slosh_masses"),
    ("first slosh frequency and mass", "Abramson, NASA SP-106: omega^2 = (a xi_1 / R) "
     "tanh(xi_1 h / R)", "1e-3 (frequency), 1e-2 (mass) relative",
     "test_liquid::test_slosh_cylinder_abramson"),
    ("pressurised shell frequencies", "Donnell 3x3 eigenproblem with N_x = p R / 2, "
     "N_theta = p R", "0.5 %", "test_pressure::test_pressurised_cylinder_matches_3x3_eigenproblem"),
    ("stiffened shell frequencies", "smeared rings and stringers (Baruch-Singer), Sanders 3x3 "
     "eigenproblem", "0.5 %",
     "test_stiffeners::test_stiffened_cylinder_matches_smeared_closed_form"),
    *(row for row in VERIFICATION if row[3].startswith("test_vehicle_regions::")),
)

#: The forced response's checks (a case with one).
FORCED_VERIFICATION: tuple[tuple[str, str, str, str], ...] = (
    ("forced axial response (k = 0)", "membrane rod driven at its end", "1 %",
     "test_forced_response::test_axial_end_force_matches_the_membrane_rod"),
    ("forced lateral response (k = 1)", "Timoshenko tube driven at its end", "1 %",
     "test_forced_response::test_lateral_end_force_matches_the_timoshenko_tube"),
    ("forced resonance peak", "solve_ivp of the reduced equations to steady state (rtol "
     "1e-10)", "1e-6 relative",
     "test_forced_response::test_peak_matches_time_integration_of_the_modal_equations"),
)

#: The flight's checks (a case with ``[flight]``).
FLIGHT_VERIFICATION: tuple[tuple[str, str, str, str], ...] = (
    ("frozen-time regions", "the single-case analysis of the same vehicle", "bit for bit",
     "test_flight_pipeline::test_constant_flight_equals_the_single_case"),
    ("e-folds over the flight", "growth rate x duration, a constant vehicle", "1e-12 relative",
     "test_flight_pipeline::test_constant_flight_efolds_are_rate_times_duration"),
    ("slow passage through a region", "direct integration of the non-periodic equation "
     "(solve_ivp DOP853, rtol 1e-10)", "5 % in log amplitude",
     "test_flight_passage::test_slow_passage_through_the_principal_region_matches_direct_"
     "integration"),
    ("peak of a sweep through resonance", "direct integration (solve_ivp DOP853, rtol 1e-10)",
     "2 %", "test_flight_passage::test_sweep_peak_matches_direct_integration"),
    ("mode tracking through a crossing", "two-DOF system with fixed shapes (closed form)",
     "1e-10 relative", "test_flight_tracking::test_two_dof_crossing_frequencies_keep_identities"),
)


def verification_rows(results: Results) -> tuple[tuple[str, str, str, str], ...]:
    """The verification summary's rows for these results: the memo's checks for a
    ``[booster]`` case, the vehicle model's for a ``[[vehicle.segments]]`` one, then those of
    the forced response and of the flight where the case has them.

    Parameters
    ----------
    results : Results
        The analysis.
    """
    rows = VERIFICATION if results.not_applicable is None else VEHICLE_VERIFICATION
    if results.forced_response is not None:
        rows += FORCED_VERIFICATION
    if results.flight is not None:
        rows += FLIGHT_VERIFICATION
    return rows


_CSS = """
body{font-family:system-ui,-apple-system,"Segoe UI",Roboto,Helvetica,Arial,sans-serif;
margin:0 auto;max-width:1300px;padding:1em 2em;color:#1d1d1f;line-height:1.4}
h1{font-size:1.6em;margin:0.2em 0}h2{border-bottom:2px solid #d0d7de;padding-bottom:0.2em;
margin-top:1.6em}
nav ol{font-size:0.82em;margin:0.3em 0;padding:0;list-style:none;counter-reset:s}
nav li{display:inline;counter-increment:s;margin-right:1.1em;white-space:nowrap}
nav li::before{content:counter(s) ". "}
table{border-collapse:collapse;margin:0.6em 0;font-size:0.88em}
th,td{border:1px solid #d0d7de;padding:0.25em 0.6em;vertical-align:top}
th{background:#f3f5f7;text-align:left}
td.num{text-align:right;font-variant-numeric:tabular-nums;white-space:nowrap}
tr.active td{background:#fff1f0}
.verdict{font-weight:bold}.ok{color:#116329}.bad{color:#a40e26}
.warn{background:#fff8c5;border-left:4px solid #d4a72c;padding:0.4em 0.8em;margin:0.4em 0}
.note{color:#57606a;font-size:0.9em}
figure{margin:1em 0}figcaption{font-size:0.88em;color:#57606a;max-width:60em}
figure svg{max-width:100%;height:auto;display:block}
svg.figure *{stroke-linejoin:round;stroke-linecap:butt}
.first{font-size:0.95em}.first h3{margin:0.6em 0 0.2em}
.first table{margin:0.3em 0}.first p{margin:0.35em 0}.first th{white-space:nowrap}
.first td{padding:0.15em 0.5em}#summary h2{margin-top:0.8em}
.first ul.warnings{margin:0.2em 0;padding-left:1.2em}
@media print{
body{max-width:none;padding:0;font-size:10pt;color:#000}
nav{display:none}
a{color:inherit;text-decoration:none}
h2{break-after:avoid;page-break-after:avoid}
section{break-inside:auto}
table,figure,.warn{break-inside:avoid;page-break-inside:avoid}
tr.active td{background:none;font-weight:bold}
th{background:none}
figure svg{max-height:22cm}
@page{size:A4;margin:15mm}
}
"""


def _fmt(x: object, digits: int = 6) -> str:
    """A number as text; anything not finite becomes "n/a" (never NaN)."""
    if x is None:
        return "n/a"
    if isinstance(x, bool | np.bool_):
        return "yes" if x else "no"
    if isinstance(x, int | np.integer):
        return str(int(x))
    try:
        value = float(x)
    except (TypeError, ValueError):
        return str(x)
    if not math.isfinite(value):
        return "n/a"
    if abs(value) < ROUND_OFF:
        return "0"
    return f"{value:.{digits}g}"


def _e(text: object) -> str:
    return html.escape(str(text), quote=True)


def _table(header: Sequence[str], rows: Sequence[Sequence[object]],
           numeric: Sequence[bool] | None = None, row_class: Sequence[str] | None = None) -> str:
    numeric = numeric or [False] * len(header)
    out = ["<table>", "<thead><tr>"]
    out += [f"<th>{_e(h)}</th>" for h in header]
    out.append("</tr></thead><tbody>")
    for n, row in enumerate(rows):
        cls = f' class="{_e(row_class[n])}"' if row_class and row_class[n] else ""
        cells = []
        for value, num in zip(row, numeric, strict=True):
            text = _fmt(value) if num else str(value)
            cells.append(f'<td class="num">{_e(text)}</td>' if num else f"<td>{_e(text)}</td>")
        out.append(f"<tr{cls}>" + "".join(cells) + "</tr>")
    out.append("</tbody></table>")
    return "".join(out)


def _qvu(rows: Sequence[tuple[str, object, str]]) -> str:
    """Quantity / value / unit table; values are numbers or text."""
    body = [(q, v if isinstance(v, str) else _fmt(v), u) for q, v, u in rows]
    return _table(("quantity", "value", "unit"), body, (False, False, False))


def _hz(rad_s: float) -> float:
    return rad_s / (2.0 * np.pi)


def inline_svg(svg: str, prefix: str, label: str) -> str:
    """The ``<svg>`` element of a matplotlib SVG document, embeddable in HTML: declaration,
    DOCTYPE, metadata and global style dropped, every ``id`` prefixed, ``role="img"``, an
    ``aria-label`` and the class ``figure`` on the root.

    Parameters
    ----------
    svg : str
        SVG text as written by ``Figure.savefig(format="svg")``.
    prefix : str
        Prefix of the ids, e.g. the figure name.
    label : str
        Accessible name of the image.
    """
    start = svg.find("<svg")
    if start < 0:
        raise ValueError(f"svg = {svg[:40]!r}...: not an SVG document (no <svg element)")
    body = svg[start:]
    body = re.sub(r"<metadata>.*?</metadata>", "", body, flags=re.S)
    body = re.sub(r"<style[^>]*>.*?</style>", "", body, flags=re.S)
    # every id attribute (XML puts white space before an attribute), href="#..." and
    # url(#...): plain replacements, 7x faster than the equivalent regular expressions (the
    # same text: tests/test_report.py)
    for space in " \n\t\r":
        body = body.replace(f'{space}id="', f'{space}id="{prefix}-')
    body = body.replace('href="#', f'href="#{prefix}-').replace("url(#", f"url(#{prefix}-")
    return body.replace(
        "<svg ", f'<svg class="figure" role="img" aria-label="{_e(label)}" ', 1
    )


def _figure(name: str, svgs: Mapping[str, str] | None, caption: str | None = None, *,
            drawable: bool = True) -> str:
    """The figure ``name`` inline with its caption; without its SVG a note that it was not
    drawn, and nothing where this case has no such figure (``drawable`` false: its data is not
    part of the results)."""
    if not drawable:
        return ""
    caption = FIGURES[name][1] if caption is None else caption
    if not svgs or name not in svgs:
        return f'<p class="note">Figure "{_e(name)}" was not drawn (run without --no-figures).</p>'
    return (
        f'<figure id="fig-{_e(name)}">{inline_svg(svgs[name], f"fig-{name}", caption)}'
        f"<figcaption>{_e(caption)}</figcaption></figure>"
    )


def _inputs(results: Results) -> str:
    return _qvu(input_rows(results))


def _mass(results: Results) -> str:
    return _qvu(mass_rows(results))


def _frequencies(results: Results) -> str:
    return _qvu(frequency_rows(results))


def _beam(results: Results, svgs: Mapping[str, str] | None) -> str:
    beam = results.beam
    rows = []
    for n in range(beam.lambda_n.size):
        omega = None if beam.omega_n is None else beam.omega_n[n]
        rows.append((n + 1, beam.lambda_n[n], beam.alpha_n[n], omega,
                     None if omega is None else _hz(omega)))
    table = _table(("n", "lambda_n", "alpha_n", "omega_n (rad/s)", "f_n (Hz)"), rows,
                   (True, True, True, True, True))
    return table + _figure("beam-modes", svgs)


def _has_chart(results: Results, part: str) -> bool:
    """Whether the case has the memo's figure ``part`` (a field of its figure data): never in a
    ``[[vehicle.segments]]`` case (the memo's method not applicable), always in a run without
    figure data (its note says so), else where that stage's chart was computed."""
    if results.not_applicable is not None:
        return False
    return results.figures is None or getattr(results.figures, part) is not None


def _verdict(text: str, stable: bool) -> str:
    cls = "ok" if stable else "bad"
    return f'<p>Verdict: <span class="verdict {cls}">{_e(text)}</span></p>'


def _pitch(results: Results, svgs: Mapping[str, str] | None) -> str:
    p = results.pitch
    rows = [
        ("Mathieu a over the grid (4.2-4)", f"{_fmt(p.a.min())} .. {_fmt(p.a.max())}", "-"),
        ("Mathieu q over the grid (4.2-4)", f"{_fmt(p.q.min())} .. {_fmt(p.q.max())}", "-"),
        ("exponent beta (exact, Hill) over the grid",
         f"{_fmt(p.beta_real.min())} .. {_fmt(p.beta_real.max())}", "-"),
        ("largest |beta memo (4.2-9, E4) - beta exact|",
         _fmt(float(np.max(np.abs(p.beta_memo_real - p.beta_real)))), "-"),
        ("largest growth rate of psi", p.max_growth_rate if p.bands else "-", "1/s"),
        ("grid points in the memo's range 0 < a < 1, 0 < q <= 0.05",
         f"{int(np.sum(p.in_memo_range))} of {p.in_memo_range.size}", "-"),
    ]
    bands = p.bands
    out = _verdict(p.verdict, not bands) + _qvu(rows)
    if bands:
        out += "<p>Instability bands of Omega (exact edges):</p>" + _table(
            ("tongue", "from (rad/s)", "to (rad/s)", "from (Hz)", "to (Hz)",
             "max growth (1/s)", "critical gamma"),
            [(b.order, b.Omega_lo, b.Omega_hi, _hz(b.Omega_lo), _hz(b.Omega_hi),
              b.growth_rate_max, b.critical_gamma) for b in bands[:50]], (True,) * 7)
        if len(bands) > 50:
            out += f'<p class="note">First 50 of {len(bands)} bands.</p>'
    return out + _figure("ince-strutt", svgs, drawable=_has_chart(results, "ince_strutt")) + \
        _figure("pitch-band-chart", svgs, drawable=_has_chart(results, "pitch_band_chart"))


def _beam_action(results: Results) -> str:
    ba = results.beam_action
    if ba is None:
        return '<p class="note">Not computed.</p>'
    rows = [
        ("largest growth rate", ba.max_growth_rate if ba.bands else "-", "1/s"),
        ("Omega at the largest growth rate", ba.Omega_at_max if ba.bands else "-", "rad/s"),
        ("steady thrust P l^2 / EI (follower flutter at 109.69)", ba.p, "-"),
        ("Hill against monodromy exponents, largest difference", ba.hill_monodromy_difference,
         "-"),
        ("stable grid points", f"{int(np.sum(ba.stable))} of {ba.stable.size}", "-"),
        ("Omega range searched for every band (below it: the pitch tongues)",
         f"{_fmt(ba.band_range[0])} .. {_fmt(ba.band_range[1])}", "rad/s"),
        ("instability bands", len(ba.bands), "-"),
    ]
    rows += [
        (f"alpha_{r + 1} Omega_bar at gamma -> 0 (loaded frequency)",
         float(np.real(ba.frequencies[r])), "omega_1")
        for r in range(np.size(ba.frequencies))
    ]
    out = _verdict(ba.verdict, not ba.bands and not ba.gaps) + _qvu(rows)
    if ba.bands:
        out += "<p>Instability bands of Omega (edges on |rho| = 1):</p>" + _table(
            ("kind", "modes", "j", "from (rad/s)", "to (rad/s)", "max growth (1/s)",
             "critical gamma"),
            [(b.kind, "+".join(str(m.index) for m in b.modes), b.order, b.Omega_lo, b.Omega_hi,
              b.growth_rate_max, b.critical_gamma) for b in ba.bands[:50]],
            (False, False, True, True, True, True, True))
        if len(ba.bands) > 50:
            out += f'<p class="note">First 50 of {len(ba.bands)} bands.</p>'
    return out


def _shell(results: Results, svgs: Mapping[str, str] | None) -> str:
    sh = results.shell
    out = [f"<p>Method: {_e(sh.method)}; {len(sh)} frequencies in all (every one is in "
           "shell-frequencies.csv). The lowest of each cylinder:</p>"]
    for d in (1, 2):
        rows_d = np.flatnonzero(sh.cylinder == d)
        rows_d = rows_d[np.argsort(sh.hz[rows_d], kind="stable")][:_SHELL_ROWS]
        out.append(f"<h3>Cylinder {d} ({'aft' if d == 1 else 'forward'})</h3>")
        out.append(_table(
            ("j", "k", "branch m", "type", "omega_bar (omega_1)", "rad/s", "Hz"),
            [(sh.j[i], sh.k[i], sh.branch[i], sh.mode_type[i], sh.omega_bar[i], sh.rad_s[i],
              sh.hz[i]) for i in rows_d],
            (True, True, True, False, True, True, True)))
    out.append(_figure("shell-frequencies-cylinder1", svgs))
    out.append(_figure("shell-frequencies-cylinder2", svgs))
    return "".join(out)


def _unstable(results: Results) -> str:
    st = results.stability
    if st is None:
        return '<p class="note">Not computed (see the warnings).</p>'
    bands = band_rows(results, 10)
    out = ""
    if st.severity is not None:  # the most severe bands first, then the roots
        out = (f"<p>The 10 most severe bands of unstable thrust frequencies. "
               f"{_e(severity_caption(results))} All bands are in resonance-bands.csv.</p>"
               + _table(BAND_COLUMNS, bands, [False] * len(BAND_COLUMNS)))
        order = np.lexsort((st.Omega, -st.severity))  # most severe first
    else:
        order = np.lexsort((st.Omega, ~np.asarray(st.active, dtype=bool)))  # active first
    shown = order[:MAX_UNSTABLE_ROWS]
    n_active = int(np.sum(st.active))
    head = (f"<p>{len(st)} roots of the equations of memo 7.3 in the Omega range, "
            f"{n_active} active (highlighted), "
            + ("most severe first. " if st.severity is not None else "listed first. "))
    if len(st) > shown.size:
        head += f"The first {shown.size} of {len(st)} are shown; all are in "
    else:
        head += "All are shown; they are also in "
    head += "unstable-frequencies.csv.</p>"
    sev = st.severity if st.severity is not None else np.zeros(len(st))
    rows = [
        (st.Omega[n], _hz(st.Omega[n]), st.Omega_bar[n], f"{st.family[n]} ({st.equation[n]})",
         st.cylinder[n], st.j[n], st.k[n], st.branch[n],
         f"{st.i[n]}, {st.p[n]}, {st.r[n]}, {st.s[n]}",
         _hz(st.shell_omega_bar[n] * st.omega_1), float(sev[n]),
         "active" if st.active[n] else "listed")
        for n in shown
    ]
    table = _table(
        ("Omega (rad/s)", "Omega (Hz)", "Omega/omega_1", "family (eq.)", "d", "j", "k", "m",
         "i, p, r, s", "shell (Hz)", "severity (m/s)", "forcing"),
        rows, (True, True, True, False, True, True, True, True, False, True, True, False),
        ["active" if st.active[n] else "" for n in shown])
    return out + head + table


def _vehicle(results: Results, svgs: Mapping[str, str] | None) -> str:
    """The vehicle modes (a case with [vehicle] only): settings, lowest mode per k, figures."""
    from .vehicle import VEHICLE_FIGURES

    sv = results.vehicle
    m, v = sv.modes, sv.vehicle
    kinds = ", ".join(type(g).__name__.lower() for g in v.segments)
    out = [f"<p>{len(v.segments)} segments ({_e(kinds)}), "
           f"junctions {_e(', '.join(v.junctions) or 'none')}, ends {_e(v.aft_end)} / "
           f"{_e(v.fwd_end)}, {_e(v.theory)} theory, k = 0..{sv.k_max}; frequencies "
           f"{_e(sv.note)}. {len(m)} modes in all (every one is in vehicle-modes.csv); the "
           "lowest of each k:</p>"]
    rows = []
    for kk in np.unique(m.k):
        idx = np.flatnonzero(m.k == kk)
        i = int(idx[np.argmin(m.hz[idx])])
        rows.append((kk, idx.size, m.hz[i], m.omega[i], m.type[i], m.order[i], m.segment[i]))
    out.append(_table(("k", "modes", "lowest Hz", "rad/s", "type", "order", "segment"), rows,
                      (True, True, True, True, False, True, True)))
    if getattr(sv, "slosh", ()):
        out.append("<p>Slosh: each tank's first mode under the thrust's acceleration "
                   "(Abramson, NASA SP-106):</p>" + _qvu(slosh_rows(sv.slosh)))
    for name, caption in VEHICLE_FIGURES.items():
        if svgs and name in svgs:
            svg = inline_svg(svgs[name], f"fig-{name}", caption)
            out.append(f'<figure id="fig-{_e(name)}">{svg}'
                       f"<figcaption>{_e(caption)}</figcaption></figure>")
    if not svgs or "vehicle-mode-shapes" not in svgs:
        out.append('<p class="note">The vehicle figures were not drawn (run without '
                   "--no-figures).</p>")
    return "".join(out)


def _vehicle_regions(results: Results, svgs: Mapping[str, str] | None) -> str:
    """The vehicle's parametric regions: verdict, settings, regions by growth rate, the memo
    roots inside them, the chart."""
    vr = results.vehicle_regions
    if vr is None:
        return ('<p class="note">Not computed (run without --no-vehicle; see the '
                "warnings).</p>")
    verdict, stable = vehicle_region_verdict(results)
    out = [_verdict(verdict, stable), _qvu(vehicle_region_rows(results)[1:])]
    rows = vehicle_region_table(results)
    if rows:
        out.append(f"<p>The regions by decreasing growth rate (first {min(len(rows), 50)} of "
                   f"{len(rows)}; all are in vehicle-regions.csv):</p>")
        out.append(_table(REGION_HEADER, rows[:50],
                          (True, True, True, True, True, False, False, True, True, True,
                           False)))
    m = results.memo_roots_in_regions
    if m is not None and vr.regions:
        roots = memo_root_rows(results)
        out.append(f"<p>Memo-table roots (memo 7.3) inside a region: {len(roots)}, "
                   f"{int(np.sum(m.active))} with active forcing. Regions no memo root with "
                   f"active forcing explains: {m.without_active_root.size} of {m.n_regions}"
                   + ("" if m.severity is not None else
                      " (the stability table has no severity column: shown as -)") + ".</p>")
        if roots:
            out.append(_table(MEMO_ROOT_HEADER, roots[:MAX_UNSTABLE_ROWS],
                              (False, True, True, False, False, False, False)))
    elif m is None and vr.regions:
        out.append('<p class="note">The memo table was not computed: no comparison with '
                   "its roots.</p>")
    axial = forced_axial_rows(results)
    if axial:
        out.append("<p>Forced (not parametric) resonances: the k = 0 axial and breathing modes "
                   "that the thrust pulsation gamma F0 drives directly at Omega = omega_n (the "
                   "memo's family 3), aft-edge axial amplitude with the modal damping:</p>")
        out.append(_table(FORCED_AXIAL_HEADER, axial, (True, True, False, True, True, True)))
    return "".join(out) + _figure("vehicle-regions", svgs)


def _forced_response(results: Results, svgs: Mapping[str, str] | None) -> str:
    """The forced response: the peaks per station, the basis, the largest loads, the figures."""
    f = results.forced_response
    if f is None:
        return ('<p class="note">Not computed (run without --no-vehicle; see the '
                "warnings).</p>")
    r = f.response
    load = ("the lines of thrust.spectrum" if r.combination == "spectrum" else
            f"gamma = {_fmt(r.amplitude[0])} over the Omega range")
    out = [f"<p>Steady response of the vehicle to the thrust oscillation ({_e(load)}) at the "
           "aft edge, axial (k = 0) and, with a thrust misalignment of "
           f"{_e(_fmt(r.misalignment))} rad, lateral (k = 1) with the gimbal gain "
           f"{_e(_fmt(r.gimbal_gain))}; modal damping {_e(_fmt(r.damping_ratio))}. Peaks are "
           f"amplitudes over the range; every curve is in {FORCED_CSV}.</p>",
           _forced_table(results) if forced_rows(results) else f"<p>{_e(FORCED_ZERO)}</p>",
           f"<p>Basis: {_e(forced_basis_text(results))}.</p>"]
    lines = forced_worst_lines(results)
    if lines:
        out.append("<ul>" + "".join(f"<li>{_e(x)}</li>" for x in lines) + "</ul>")
    return "".join(out) + "".join(_figure(name, svgs) for name in FORCED_FIGURES)


def _forced_table(results: Results) -> str:
    """The peaks per station; without "per 1 % of F0" where it is not defined (a spectrum,
    whose lines have their own amplitudes)."""
    keep = [i for i in range(len(FORCED_HEADER))
            if i != 4 or results.forced_response.per_percent is not None]
    note = "" if len(keep) == len(FORCED_HEADER) else (
        '<p class="note">A spectrum: the peaks are the response to its lines as given (no '
        '"per 1 % of F0": each line has its own amplitude).</p>')
    return note + _table(tuple(FORCED_HEADER[i] for i in keep),
                         [tuple(row[i] for i in keep) for row in forced_rows(results)],
                         tuple(i > 0 for i in keep))


def _verification(results: Results) -> str:
    return ("<p>Every number of this report is produced by code that the test suite checks "
            "against an independent computation (not against the memo, which prints no "
            "numbers). Run <code>make test</code> to repeat the checks.</p>"
            + _table(("quantity", "checked against", "tolerance", "test (tests/...)"),
                     verification_rows(results), (False,) * 4))


def _warnings(results: Results) -> str:
    items = [(w.code, w.field, w.message) for w in results.warnings]
    if not items:
        return "<p>No warnings.</p>"
    return "".join(
        f'<div class="warn"><strong>[{_e(code)}]</strong> {_e(field)}: {_e(msg)}</div>'
        for code, field, msg in items
    )


def _first_screen(results: Results, svgs: Mapping[str, str] | None) -> str:
    """The overall verdict and the damping it holds for, the verdicts, the ranked bands, the
    warnings (named) and the danger map: the answer first."""
    out = ['<div class="first" id="first-screen">']
    verdict = None if results.danger is None else results.danger.verdict
    if verdict is not None:
        duration = ("none given (verdict from e-folding times)" if verdict.duration is None
                    else f"{verdict.duration:g} s")
        out.append(f'<p class="overall {"bad" if verdict.overall == "UNSTABLE" else ""}">'
                   f"<strong>{_e(verdict.overall)}</strong>: {_e(verdict.reason)}</p>"
                   f"<p>Damping: {_e(verdict.damping_text)}; excitation duration: "
                   f"{_e(duration)}.</p>")
    out += ['<h3>Verdicts</h3>',
           _table(("mechanism", "verdict"), verdict_rows(results), (False, False),
                  ["bad" if v.startswith("unstable") else "" for _, v in
                   verdict_rows(results)])]
    rows = danger_rows(results, FIRST_SCREEN_BANDS, modes=FIRST_SCREEN_MODES)
    n_all = len(ranking(results))
    if rows:
        out.append(f"<h3>Most dangerous thrust frequencies ({len(rows)} of {n_all}; all "
                   f"in results.json <code>danger</code>{_e(danger_scope(results))})</h3>")
        out.append(_table(DANGER_HEADER, rows, (True, True, True, True, False, False, False)))
    elif results.danger is not None:
        out.append("<p>No unstable band in any mechanism computed.</p>")
    heads = headline_lines(results)
    if heads:  # the forced response's peaks and the flight's worst moment
        out.append('<ul class="headline">' + "".join(f"<li>{_e(line.strip())}</li>"
                                                      for line in heads) + "</ul>")
    if results.warnings:
        out.append(f'<p><strong>Warnings ({len(results.warnings)})</strong> (details in '
                   '<a href="#warnings">Warnings</a>):</p><ul class="warnings">')
        out += [f"<li>[{_e(w.code)}] {_e(w.field)}: {_e(w.message)}</li>"
                for w in results.warnings]
        out.append("</ul>")
    else:
        out.append("<p>No warnings.</p>")
    out.append("</div>")
    if results.danger is not None:
        out.append(_figure("danger-map", svgs))
        measures = band_measure_rows(results)
        if measures:
            out.append("<h3>Measures of the ranked bands</h3><p class=\"note\">Numbered as "
                       "above; e-folding time 1 / growth, amplification exp(growth x duration), "
                       "margin = critical gamma / gamma (below 1: open), the critical damping "
                       "ratio closes the band at the case's gamma (docs/theory/verdicts.md); "
                       "- where it does not apply or was not computed.</p>")
            out.append(_table(BAND_MEASURE_HEADER, measures,
                              (True, True, False) + (True,) * 7))
    return "".join(out)


def _summary(results: Results) -> str:
    ba, st, p = results.beam_action, results.stability, results.pitch
    na = not_applicable_text(results)
    rows = [
        ("first bending frequency omega_1", na or f"{_fmt(results.omega_1)} rad/s "
         f"({_fmt(_hz(results.omega_1))} Hz)"),
        ("rigid-body pitch", p.verdict),
        ("beam action", na or "not computed" if ba is None else ba.verdict),
        ("unstable thrust frequencies", na or "not computed (see the warnings)" if st is None else
         f"{len(st)} roots, {int(np.sum(st.active))} active"),
        ("vehicle parametric instability regions", vehicle_region_verdict(results)[0]),
        ("warnings", str(len(results.warnings))),
    ]
    return _table(("result", "value"), rows, (False, False))


def _units_note(case) -> str:
    output = getattr(case, "output", None)
    if output is not None and output.units == "US":
        return ("All quantities in SI units; the inputs and mass properties also in inch-pound "
                "units (in brackets), as the case asks ([output] units = \"US\").")
    return "All quantities in SI units."


def _source_date() -> str:
    """", YYYY-MM-DD HH:MM:SS UTC" from SOURCE_DATE_EPOCH, or "" (no time stamp)."""
    value = os.environ.get("SOURCE_DATE_EPOCH", "").strip()
    if not value.isdigit():
        return ""
    return ", " + datetime.fromtimestamp(int(value), UTC).strftime("%Y-%m-%d %H:%M:%S UTC")


def render_report(results: Results, svgs: Mapping[str, str] | None = None,
                  generated: str | None = None) -> str:
    """The report of an analysis as one HTML document (UTF-8, no external resource).

    Parameters
    ----------
    results : Results
        The analysis.
    svgs : Mapping of str to str, optional
        SVG text of the figures by name (the keys of :data:`FIGURES`), as
        :func:`flexbooster.present.outputs.figure_svgs` returns them; a missing one is a note.
    generated : str, optional
        Time stamp of the header; by default from ``SOURCE_DATE_EPOCH`` (UTC), else none (two
        runs of one case write the same file).
    """
    stamp = f", {generated}" if generated else _source_date()
    case = results.case
    body: dict[str, Callable[[], str]] = {
        "summary": lambda: _first_screen(results, svgs) + _summary(results),
        "inputs": lambda: _inputs(results),
        "mass-properties": lambda: _mass(results),
        "frequencies": lambda: _frequencies(results),
        "beam-modes": lambda: _beam(results, svgs),
        "rigid-body": lambda: _pitch(results, svgs),
        "beam-action": lambda: _beam_action(results) + _figure(
            "beam-action-chart", svgs, drawable=_has_chart(results, "beam_action_chart")),
        "shell-frequencies": lambda: _shell(results, svgs),
        "nodal-patterns": lambda: _figure("nodal-patterns", svgs),
        "unstable-frequencies": lambda: _unstable(results),
        "campbell": lambda: _figure("campbell", svgs, drawable=_has_chart(results, "campbell")),
        "vehicle-regions": lambda: _vehicle_regions(results, svgs),
        "forced-response": lambda: _forced_response(results, svgs),
        "verification": lambda: _verification(results),
        "warnings": lambda: _warnings(results),
        "vehicle-modes": lambda: _vehicle(results, svgs),
        "flight": lambda: flight_report_html(results.flight) + _figure(
            "flight-campbell", svgs, FLIGHT_FIGURES["flight-campbell"]),
    }
    na = not_applicable_text(results)
    sections = SECTIONS
    if na is not None:  # a [[vehicle.segments]] case: the memo's sections left out, named once
        left_out = [name for sid, name in SECTIONS if sid in MEMO_SECTIONS]
        sections = tuple(item for item in SECTIONS if item[0] not in MEMO_SECTIONS)
        summary = body["summary"]
        body["summary"] = lambda: summary() + (
            f'<p class="note">Sections of the memo\'s method left out ({_e(na)}): '
            f'{_e(", ".join(left_out))}.</p>')
    if results.vehicle is not None:  # a case with [vehicle]: before the verification summary
        sections = (*sections[:-2], ("vehicle-modes", "Vehicle modes (shell of revolution)"),
                    *sections[-2:])
    if results.flight is not None:  # a case with [flight]: the flight section
        sections = (*sections[:-2], ("flight", "Through the flight"), *sections[-2:])
    title = f"flexbooster report: {case.name}"
    parts = [
        "<!DOCTYPE html>",
        '<html xmlns="http://www.w3.org/1999/xhtml" lang="en"><head><meta charset="utf-8" />',
        '<meta name="viewport" content="width=device-width, initial-scale=1" />',
        f"<title>{_e(title)}</title><style>{_CSS}</style></head><body>",
        f"<header><h1>{_e(title)}</h1>",
        f'<p class="note">flexbooster {_e(__version__)}{_e(stamp)}. Dynamic stability '
        "and thrust-oscillation response of a flexible launch vehicle under a gimbaled, pulsating "
        "thrust. "
        f"{_units_note(case)}</p>",
        "<nav><ol>",
        *[f'<li><a href="#{sid}">{_e(name)}</a></li>' for sid, name in sections],
        "</ol></nav></header><main>",
    ]
    for sid, name in sections:
        parts.append(f'<section id="{sid}"><h2>{_e(name)}</h2>{body[sid]()}</section>')
    parts.append("</main></body></html>\n")
    return "\n".join(parts)


def write_report(results: Results, path: str | Path, svgs: Mapping[str, str] | None = None,
                 generated: str | None = None) -> Path:
    """Write :func:`render_report` to ``path`` atomically; returns the path.

    Parameters
    ----------
    results : Results
        The analysis.
    path : str or pathlib.Path
        Destination, usually ``<folder>/report.html``.
    svgs : Mapping of str to str, optional
        Figures by name (see :func:`render_report`).
    generated : str, optional
        Time stamp of the header.
    """
    return write_text_atomic(path, render_report(results, svgs, generated))
