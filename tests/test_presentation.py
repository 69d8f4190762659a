"""The answer first: the terminal summary and the report's first screen, the danger
map, the number formats.

The memo case is analysed once (about 12 s); every check reads that analysis.
"""

from __future__ import annotations

import dataclasses
import re
import xml.etree.ElementTree as ET

import pytest
from rich.console import Console

from flexbooster.danger import ResponsePeak
from flexbooster.errors import AnalysisWarning
from flexbooster.present.report import ROUND_OFF, render_report
from flexbooster.present.rows import FIRST_SCREEN_BANDS, range_text
from flexbooster.present.summary import TERMINAL_BANDS, print_summary


@pytest.fixture(scope="module")
def results(memo_results):
    return memo_results


def _summary_text(results, width: int, *, full: bool = True) -> str:
    console = Console(width=width, record=True, color_system=None)
    print_summary(results, console, full=full)
    return console.export_text()


@pytest.mark.slow
@pytest.mark.parametrize("width", [80, 160])
def test_summary_fits_without_a_cut_cell(results, width):
    # acceptance: at 80 columns no cell is cut (rich marks a cut with an ellipsis)
    # and no line is wider than the terminal
    for full in (True, False):
        text = _summary_text(results, width, full=full)
        assert "\u2026" not in text and "..." not in text.replace(" .. ", "")
        assert max(len(line) for line in text.splitlines()) <= width


def test_first_screen_is_verdicts_then_ranked_bands(results):
    # acceptance: line 1 is the overall verdict, the damping is stated, then
    # the verdict of every mechanism and the top bands; the short summary (flexbooster run
    # without --full) is at most 60 lines of an 80-column terminal and the full summary starts
    # with the same first screen
    short = _summary_text(results, 80, full=False)
    lines = short.splitlines()
    assert len(lines) <= 60
    assert re.match(r"^(UNSTABLE|MARGINAL|STABLE): ", lines[0])
    assert "1 % modal damping" in short and "Input (SI)" not in short
    for words in ("rigid-body pitch", "beam bending under thrust", "vehicle parametric regions",
                  "shell resonances", "Most dangerous thrust frequencies"):
        assert words in short, words
    assert short.index("Verdicts") < short.index("Most dangerous")
    # engineering words only: the memo's terms stay in the detailed sections
    for internal in ("issue", "memo roots", "certified", "family 3 (3,13)", "via u*", "(memo 4",
                     "(memo 7"):
        assert internal not in short, internal
    after = lines[next(i for i, x in enumerate(lines) if x.startswith("Most dangerous")):]
    ranked = [line for line in after if re.match(r"^\d+ ", line)]
    assert len(ranked) == min(TERMINAL_BANDS, len(results.danger.ranking))
    # the top item's Omega (rad/s) as the table prints it: a band's range, a response's Omega
    top = results.danger.ranking[0]
    text = (f"{top.Omega:.6g}" if isinstance(top, ResponsePeak)
            else range_text(top.Omega_lo, top.Omega_hi))
    assert text in ranked[0]
    full = _summary_text(results, 80)
    assert full.startswith(short.split("Warnings")[0]) and "Input (SI)" in full
    assert "unstable frequencies:" not in full.lower()


@pytest.mark.parametrize(
    ("lo", "hi", "text"),
    [
        pytest.param(114.67288, 114.68423, "114.67-114.68", id="4-digits-differ"),
        pytest.param(113.482994, 113.483021, "113.48299-113.48302", id="needs-8-digits"),
        pytest.param(2.0, 2.0, "2", id="equal-edges"),
    ],
)
def test_range_text_digits(lo, hi, text):
    # exact: the fewest significant digits (>= 4) that tell the two edges apart
    assert range_text(lo, hi) == text


def test_warnings_listed_on_the_first_screen(results):
    # the warnings are named in the summary, not only in the last section
    w = AnalysisWarning("thin-shell", "booster.cylinder1", "h/R1 = 0.06 exceeds 1/20")
    r = dataclasses.replace(results, warnings=(w,))
    text = _summary_text(r, 80)
    assert text.index("[thin-shell] booster.cylinder1") < text.index("Input (SI)")
    html = render_report(r)
    first = html[html.index('id="first-screen"'):html.index('id="inputs"')]
    assert "[thin-shell] booster.cylinder1: h/R1 = 0.06 exceeds 1/20" in first


def test_report_first_screen_and_print_css(results):
    html = render_report(results)
    ET.fromstring(html.split("\n", 1)[1])  # still well-formed XML (polyglot HTML5)
    start = html.index('id="first-screen"')
    first = html[start:html.index("</div>", start)]
    assert first.count("<table>") == 2  # verdicts, ranked bands
    n_rows = min(FIRST_SCREEN_BANDS, len(results.danger.ranking))
    ranked = first[first.index("Most dangerous"):]
    assert ranked.count("<tr>") == n_rows + 1  # header + rows
    assert "@media print" in html and "nav{display:none}" in html


def test_maximum_of_nothing_is_a_dash_and_round_off_is_zero(results):
    # the memo case's pitch is stable: its "largest growth rate" is "-", not 0;
    # a value below ROUND_OFF (1e-14) is printed as 0
    html = render_report(results)
    assert results.pitch.bands == ()
    row = re.search(r"<td>largest growth rate of psi</td><td>([^<]*)</td>", html)
    assert row is not None and row.group(1) == "-"
    from flexbooster.present.report import _fmt

    assert _fmt(ROUND_OFF / 10) == "0" and _fmt(-3e-17) == "0" and _fmt(2.5e-11) == "2.5e-11"
    from flexbooster.present.summary import _g

    assert _g(-3e-17) == "0" and _g(2.5e-11) == "2.5e-11"  # the terminal alike
    text = _summary_text(results, 160)
    assert re.search(r"max growth rate of psi\s+.\s+-\s", text)  # stable pitch: "-"


def _drawn_tick_labels(axis) -> list:
    """The visible tick labels of ``axis`` at a tick in its view (those matplotlib draws)."""
    lo, hi = sorted(axis.get_transform().transform(axis.get_view_interval()))
    tol = 1e-9 * (hi - lo)
    labels = []
    for tick in axis.get_major_ticks(len(axis.get_majorticklocs())):
        at = float(axis.get_transform().transform([tick.get_loc()])[0])
        if lo - tol <= at <= hi + tol:
            labels += [t for t in (tick.label1, tick.label2) if t.get_visible() and t.get_text()]
    return labels


@pytest.mark.slow
def test_figures_laid_out_once_keep_every_text_inside_and_apart(results):
    # the figures are laid out once (present.plotting.layout.lay_out_once) and their titles
    # and axis labels kept where that pass placed them: as drawn for the PNG, every text lies
    # inside the figure, no axis label or title overlaps a tick label of its axes, and the
    # figure has no layout engine left (the saves do not lay it out again)
    from matplotlib.text import Text

    from flexbooster.present.figure_files import render_figure
    from flexbooster.present.outputs import figure_names, make_figures

    for name in figure_names(results):
        fig = make_figures(results, names=(name,))[name]
        render_figure(fig)
        assert fig.get_layout_engine() is None, name
        renderer = fig.canvas.get_renderer()  # the PNG's (Agg, 120 dpi)
        page = fig.bbox.padded(1.0)  # one pixel of rounding
        axes = [a for ax in fig.axes for a in (ax, *ax.child_axes)]
        ticks = {id(ax): [t for axis in (ax.xaxis, ax.yaxis) for t in _drawn_tick_labels(axis)]
                 for ax in axes}
        other = [t for t in fig.findobj(Text) if t.get_visible() and t.get_text().strip()
                 and not any(t in a.xaxis.get_ticklabels(which="both")
                             or t in a.yaxis.get_ticklabels(which="both") for a in axes)]
        for text in [*other, *(t for labels in ticks.values() for t in labels)]:
            box = text.get_window_extent(renderer)
            assert (box.x0 >= page.x0 and box.y0 >= page.y0 and box.x1 <= page.x1
                    and box.y1 <= page.y1), (name, text.get_text())
        assert any(ticks.values()), name
        for ax in fig.axes:
            parts = [ax, *ax.child_axes]
            boxes = [t.get_window_extent(renderer) for a in parts for t in ticks[id(a)]]
            for label in (t for a in parts for t in (a.xaxis.label, a.yaxis.label, a.title)
                          if t.get_visible() and t.get_text()):
                box = label.get_window_extent(renderer).shrunk(0.98, 0.98)
                assert not any(box.overlaps(b) for b in boxes), (name, label.get_text())


@pytest.mark.slow
@pytest.mark.slow
def test_figures_drawn_in_processes_are_the_figures_drawn_here(results):
    # write_outputs draws the figures by a concurrent.futures map over processes: the same
    # SVG and PNG bytes as one process drawing them one after the other (the reference)
    from flexbooster.present.outputs import figure_names, render_figures

    here = render_figures(results, processes=1)
    assert list(here) == list(figure_names(results)) and len(here) == 12
    assert render_figures(results, processes=2) == here


def test_danger_map_tooltips_and_axes(results, memo_svgs):
    # one SVG <title> per band and per forced response of the vehicle, no script, Omega in
    # Hz on the x axis
    svg = memo_svgs["danger-map"]
    titles = re.findall(r"<title>([^<]*)</title>", svg)
    # one tooltip per item (a stem and its head carry the same one), numbered as the list
    danger = results.danger
    assert len(set(titles)) == len(danger.bands) + len(danger.responses)
    assert {int(t[1:t.index(":")]) for t in titles} == set(range(1, len(danger.ranking) + 1))
    # the top-ranked band's tooltip is there; a region's names its growth rate, a damped
    # resonance's its steady response, a forced response its acceleration in g
    assert any(t.startswith("#1: Omega ") for t in titles)
    assert all("1/s" in t or " mm (severity " in t or " g at " in t for t in titles)
    assert "<script" not in svg
    from flexbooster.present.plotting.danger import danger_map

    fig = danger_map(results.danger)
    ax = fig.axes[-1]  # the bottom panel carries the shared frequency axis's label
    assert ax.get_xlabel() == "thrust frequency Omega (Hz)" and ax.get_xscale() == "log"
    lo, hi = (v / (2 * 3.141592653589793) for v in results.danger.operating_range)
    x0, x1 = ax.get_xlim()
    assert x0 < lo and x1 > hi  # the operating range is inside the axis


def test_us_units_beside_si(results):
    # [output] units = "US": the inch-pound value beside SI; exact conversions
    # (1 in = 0.0254 m, 1 lbf = 4.4482216152605 N: NIST SP 811 appendix B), 6 digits
    from flexbooster.case import load_case
    from flexbooster.present.rows import input_rows

    data = results.case.model_dump(exclude_none=True)
    data["output"] = {"units": "US"}
    us = dataclasses.replace(results, case=load_case(data))
    rows = {q: (v, u) for q, v, u in input_rows(us)}
    assert rows["cylinder 1 (aft) radius R1"] == (f"5.05 ({5.05 / 0.0254:.6g} in)", "m")
    assert rows["steady thrust F0"] == (f"2.8e+06 ({2.8e6 / 4.4482216152605:.6g} lbf)", "N")
    assert rows["Poisson's ratio nu"] == (0.33, "-")  # no US unit: unchanged
    assert "inch-pound" in render_report(us) and "inch-pound" not in render_report(results)
    # the SI default leaves results.json's case as it was (no "output" key)
    assert "output" not in results.case.to_si_dict()


def test_output_units_error_line(memo_case_dict):
    from flexbooster.case import load_case
    from flexbooster.errors import CaseError

    memo_case_dict["output"] = {"units": "SU"}
    with pytest.raises(CaseError) as info:
        load_case(memo_case_dict)
    assert str(info.value) == "output.units = 'SU': must be 'SI' or 'US'"
