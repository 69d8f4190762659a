"""The HTML report: every section and figure, self-contained, strictly parseable, escaped.

The report is polyglot HTML5 (well-formed XML), so the strict check here is the standard
library's XML parser (any unclosed tag, bad nesting or unescaped ``<``/``&`` fails it); when
``html5lib`` (a test dependency) is installed its strict HTML5 parser runs as well.  The
browser rendering is tests/test_browser.py.
"""

from __future__ import annotations

import dataclasses
import math
import re
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from flexbooster.errors import AnalysisWarning
from flexbooster.memo.charts import nodal_lines, nodal_pattern_data
from flexbooster.present.plotting.patterns import nodal_pattern, nodal_patterns
from flexbooster.present.report import (
    FIGURES,
    FLIGHT_VERIFICATION,
    FORCED_VERIFICATION,
    MAX_UNSTABLE_ROWS,
    SECTIONS,
    VEHICLE_VERIFICATION,
    VERIFICATION,
    inline_svg,
    render_report,
    verification_rows,
    write_report,
)

XHTML = "{http://www.w3.org/1999/xhtml}"
SVG = "{http://www.w3.org/2000/svg}"


@pytest.fixture(scope="module")
def results(memo_results):
    return memo_results


@pytest.fixture(scope="module")
def svgs(memo_svgs):
    return memo_svgs


@pytest.fixture(scope="module")
def page(results, svgs):
    return render_report(results, svgs, generated="2026-01-01 00:00:00 UTC")


def parse(text: str) -> ET.Element:
    """Strict XML parse of the document (the DOCTYPE line is HTML5's, not XML's)."""
    assert text.startswith("<!DOCTYPE html>\n")
    return ET.fromstring(text.split("\n", 1)[1])


def local(tag: str) -> str:
    return tag.rsplit("}", 1)[-1]


def visible_text(root: ET.Element) -> str:
    """The text of the page outside the figures and the style sheet."""
    out = []

    def walk(el):
        if local(el.tag) in ("svg", "style"):
            return
        out.append(el.text or "")
        for child in el:
            walk(child)
            out.append(child.tail or "")

    walk(root)
    return " ".join(out)


def cells(root: ET.Element, section: str) -> list[list[str]]:
    sec = root.find(f".//*[@id='{section}']")
    return [["".join(td.itertext()) for td in tr] for tr in sec.iter() if local(tr.tag) == "tr"]


def test_strict_xml_parse_and_document_basics(page):
    root = parse(page)
    assert local(root.tag) == "html" and root.get("lang") == "en"
    assert page.count("<!DOCTYPE") == 1 and "<?xml" not in page
    metas = [el for el in root.iter() if local(el.tag) == "meta"]
    assert any(m.get("charset") == "utf-8" for m in metas)


def test_html5lib_strict_parse(page):
    html5lib = pytest.importorskip(
        "html5lib", reason="html5lib not installed (pip install -e '.[test]')"
    )
    html5lib.HTMLParser(strict=True).parse(page)  # raises ParseError on any parse error


def test_every_section_present_in_order(page):
    root = parse(page)
    found = [el.get("id") for el in root.iter() if local(el.tag) == "section"]
    assert found == [sid for sid, _ in SECTIONS]
    for sid, title in SECTIONS:
        heading = root.find(f".//*[@id='{sid}']/{XHTML}h2")
        assert heading is not None and heading.text == title


def test_every_figure_is_inline_svg_in_its_section(page):
    root = parse(page)
    svgs = [el for el in root.iter() if local(el.tag) == "svg"]
    assert len(svgs) == len(FIGURES)
    for name, (section, _) in FIGURES.items():
        figure = root.find(f".//*[@id='{section}']//*[@id='fig-{name}']")
        assert figure is not None, name
        assert figure.find(f"{SVG}svg") is not None, name
        assert "<img" not in page


def test_ids_unique_and_internal_links_resolve(page):
    root = parse(page)
    ids = [el.get("id") for el in root.iter() if el.get("id") is not None]
    assert len(ids) == len(set(ids)), "duplicate ids (figures must not share ids)"
    refs = set()
    for el in root.iter():
        for key, value in el.attrib.items():
            if local(key) == "href" and value.startswith("#"):
                refs.add(value[1:])
        for attr in el.attrib.values():
            refs.update(re.findall(r"url\(#([^)]+)\)", attr))
    assert refs and refs <= set(ids)


def test_no_external_resource(page):
    root = parse(page)
    for el in root.iter():
        assert local(el.tag) not in ("script", "link", "iframe", "object", "embed"), el.tag
        for key, value in el.attrib.items():
            if local(key) in ("href", "src", "srcset", "data", "action"):
                assert value.startswith(("#", "data:")), (key, value)
    assert not re.search(r"(src|href)\s*=\s*[\"']?\s*(https?:)?//", page)
    assert not re.search(r"url\(\s*[\"']?(https?:)?//", page)
    assert "@import" not in page


def test_verification_rows_name_real_tests(results, page):
    """Each row of every verification table names a test that exists in tests/; the memo
    case's summary shows the memo's rows first."""
    from pathlib import Path

    tests = Path(__file__).parent
    for quantity, reference, tolerance, test in (VERIFICATION + VEHICLE_VERIFICATION
                                                 + FORCED_VERIFICATION + FLIGHT_VERIFICATION):
        module, name = test.split("::")
        assert f"def {name}(" in (tests / f"{module}.py").read_text(), test
        assert all((quantity, reference, tolerance))
    rows = cells(parse(page), "verification")[1:]
    assert [r[3] for r in rows] == [v[3] for v in verification_rows(results)]
    assert [r[3] for r in rows][:len(VERIFICATION)] == [v[3] for v in VERIFICATION]


def test_inputs_and_results_shown_with_units(results, page):
    root = parse(page)
    inputs = {row[0]: row[1:] for row in cells(root, "inputs")}
    # the memo case file: R1 = 5.05 m, gamma = 0.05 (flexbooster/data/memo_case.toml)
    assert inputs["cylinder 1 (aft) radius R1"] == ["5.05", "m"]
    assert inputs["pulsation amplitude gamma, T = T0 (1 - gamma cos Omega t)"] == ["0.05", "-"]
    mass = {row[0]: row[1:] for row in cells(root, "mass-properties")}
    value, unit = mass["pitch moment of inertia about the CM, I_cm (erratum E1)"]
    # printed to 6 significant digits: relative rounding error below 5e-6
    assert float(value) == pytest.approx(results.mass.I_cm, rel=5e-6) and unit == "kg m^2"


def test_unstable_table_active_first_and_capped(results, page):
    """The 10 most severe bands first, then the roots, most severe first, capped."""
    st = results.stability
    rows = cells(parse(page), "unstable-frequencies")[1:]
    bands = rows[:10]  # the bands table (its header row is rows[0] of the section)
    assert [b[0] for b in bands] == [str(n) for n in range(1, 11)]
    top = results.severity.bands[0]
    assert float(bands[0][1]) == pytest.approx(top.Omega_at_max, rel=5e-6)
    assert bands[0][-1] == top.cause
    rows = rows[11:]  # after the roots' header row
    assert len(rows) == min(len(st), MAX_UNSTABLE_ROWS)
    n_active = int(st.active.sum())
    assert len(st) > MAX_UNSTABLE_ROWS  # the memo case exercises the cap
    assert f"The first {MAX_UNSTABLE_ROWS} of {len(st)}" in page
    expected = ["active"] * min(n_active, len(rows)) + ["listed"] * (len(rows) - n_active)
    assert [r[-1] for r in rows] == expected
    # the active roots, most severe first, to the 6 printed digits
    shown = np.array([float(r[0]) for r in rows[: min(n_active, len(rows))]])
    order = np.lexsort((st.Omega, -st.severity))[: shown.size]
    np.testing.assert_allclose(shown, st.Omega[order], rtol=5e-6)


def test_warnings_shown_and_escaped(results, svgs):
    nasty = '<script>alert("x")</script> & h/R > 1/20'
    res = dataclasses.replace(
        results,
        warnings=(
            AnalysisWarning("thin-shell", "booster.cylinder2", nasty),
            AnalysisWarning("mathieu-a-range", "thrust", "a outside 0 < a < 1"),
        ),
    )
    root = parse(render_report(res, svgs))
    assert not [el for el in root.iter() if local(el.tag) == "script"]
    text = "".join(root.find(".//*[@id='warnings']").itertext())
    assert nasty in text and "[thin-shell]" in text and "[mathieu-a-range]" in text


def test_no_warnings_said_so(results):
    res = dataclasses.replace(results, warnings=())
    root = parse(render_report(res, None))
    text = "".join(root.find(".//*[@id='warnings']").itertext())
    assert "No warnings" in text


def test_bad_value_never_shown_as_nan(results):
    mass = dataclasses.replace(results.mass, I_cm=math.nan, x_cm=math.inf)
    res = dataclasses.replace(results, mass=mass, omega_psi=math.nan)
    root = parse(render_report(res, None))
    text = visible_text(root)
    assert not re.search(r"\b(nan|inf|infinity)\b", text, re.I)
    mass_rows = {row[0]: row[1] for row in cells(root, "mass-properties")}
    assert mass_rows["pitch moment of inertia about the CM, I_cm (erratum E1)"] == "n/a"


def test_without_figures_every_section_still_there(results):
    page = render_report(results, None)
    root = parse(page)
    assert "<svg" not in page
    assert [el.get("id") for el in root.iter() if local(el.tag) == "section"] == [
        sid for sid, _ in SECTIONS
    ]
    assert page.count("was not drawn") == len(FIGURES)


def test_write_report_atomic(results, tmp_path):
    path = write_report(results, tmp_path / "sub" / "report.html")
    assert path == tmp_path / "sub" / "report.html"
    parse(path.read_text(encoding="utf-8"))
    assert [p.name for p in path.parent.iterdir()] == ["report.html"]  # no .part leftover


def test_inline_svg_prefixes_ids_and_references():
    svg = (
        '<?xml version="1.0"?>\n<!DOCTYPE svg>\n<svg xmlns="http://www.w3.org/2000/svg" '
        'xmlns:xlink="http://www.w3.org/1999/xlink"><metadata>x</metadata>'
        '<defs><style type="text/css">*{stroke:red}</style><clipPath id="c1"/></defs>'
        '<g id="g1" clip-path="url(#c1)"><use xlink:href="#g1"/></g></svg>'
    )
    out = inline_svg(svg, "fig-a", 'A & "B"')
    root = ET.fromstring(out)
    assert out.startswith("<svg") and "<metadata" not in out and "<style" not in out
    assert {el.get("id") for el in root.iter()} - {None} == {"fig-a-c1", "fig-a-g1"}
    assert 'url(#fig-a-c1)' in out and 'xlink:href="#fig-a-g1"' in out
    wrapped = inline_svg('<svg xmlns="http://www.w3.org/2000/svg">'
                         '<g\nid="a"/><g\tid="b"/><g grid="c"/></svg>', "p", "x")
    assert {el.get("id") for el in ET.fromstring(wrapped).iter()} - {None} == {"p-a", "p-b"}
    assert 'grid="c"' in wrapped
    assert root.get("aria-label") == 'A & "B"' and root.get("role") == "img"
    with pytest.raises(ValueError, match="svg"):
        inline_svg("<html></html>", "p", "x")


def test_inline_svg_of_every_figure_keeps_each_reference_resolved(svgs):
    """On the real figures (matplotlib's SVG: thousands of ids, glyph uses, clip paths): every
    id of the document, and nothing else, comes out prefixed, and every reference
    (xlink:href="#...", url(#...)) names an id of the result (the XML parsed independently of
    the text replacements)."""
    xlink = "{http://www.w3.org/1999/xlink}href"
    for name, svg in svgs.items():
        before = ET.fromstring(svg.encode("utf-8"))
        after = ET.fromstring(inline_svg(svg, f"fig-{name}", name))
        ids = {el.get("id") for el in before.iter()} - {None}
        new_ids = {el.get("id") for el in after.iter()} - {None}
        assert ids and new_ids == {f"fig-{name}-{i}" for i in ids}, name
        refs = [el.get(xlink)[1:] for el in after.iter()
                if (el.get(xlink) or "").startswith("#")]  # not the embedded images' data:
        refs += [m for el in after.iter() for v in el.attrib.values()
                 for m in re.findall(r"url\(#([^)]+)\)", v)]
        assert refs, name
        assert set(refs) <= new_ids, name


# ----------------------------------------------------------------------------------------------
# Nodal patterns (memo Fig. 4)
# ----------------------------------------------------------------------------------------------
@pytest.mark.parametrize(("j", "k"), [(4, 3), (6, 2), (1, 0), (3, 1)])
def test_nodal_lines_are_the_zeros_of_the_shape(j, k):
    # Zeros of sin(j pi s / 2) on [0, 2]: s = 2 i / j; of cos(k theta) on [0, 2 pi):
    # theta = (2 i + 1) pi / (2 k) -- j + 1 circles and 2 k generators (memo Fig. 4: j = 4, k = 3
    # shows 5 circles and 6 generators).
    s, theta = nodal_lines(j, k)
    assert s.size == j + 1 and theta.size == 2 * k
    np.testing.assert_allclose(np.sin(j * np.pi * s / 2), 0.0, atol=1e-14)
    np.testing.assert_allclose(np.cos(k * theta), 0.0, atol=1e-14)
    # the shape changes sign across every interior nodal line and nowhere else
    fine = np.linspace(0, 2, 20001)
    changes = np.count_nonzero(np.diff(np.sign(np.sin(j * np.pi * fine[1:-1] / 2))))
    assert changes == j - 1


def test_nodal_pattern_alternating_cells(results):
    data = nodal_pattern_data(results.shell, cylinder=1, j=4, k=3, radius=5.0, half_length=21.0)
    fig = nodal_pattern(data)
    ax = fig.axes[0]
    mesh = ax.collections[0]
    signs = np.asarray(mesh.get_array()).reshape(2 * 3 + 1, 4)
    # neighbouring cells across a nodal line have opposite signs; the first and last rows are
    # the one cell cut by theta = 0 = 2 pi, so they agree
    assert np.all(signs[:, 1:] == -signs[:, :-1])
    assert np.all(signs[1:, :] == -signs[:-1, :])
    np.testing.assert_array_equal(signs[0], signs[-1])
    assert set(np.unique(signs)) == {-1.0, 1.0}
    vertical = [ln for ln in ax.lines if np.ptp(ln.get_xdata()) == 0]
    assert len(vertical) == 5 and len(ax.lines) == 5 + 6
    assert ax.get_xlim() == pytest.approx((0.0, 42.0)) and ax.get_ylim()[1] == pytest.approx(
        10 * np.pi
    )


def test_nodal_patterns_use_the_table(results):
    fig = nodal_patterns(results.figures.nodal_patterns)
    titles = [ax.get_title() for ax in fig.axes]
    sh = results.shell
    f1 = float(sh.hz[sh.select(cylinder=1, j=4, k=3)].min())
    assert "j = 4, k = 3" in titles[0] and f"{f1:.4g} Hz" in titles[0]
    assert "cylinder 2" in titles[1] and "j = 6, k = 2" in titles[1]


def _pattern(cylinder=1, **kw):
    # the arguments are checked before the table is read: no table is needed
    return nodal_pattern_data(None, cylinder=cylinder, j=1, k=1, **kw)


@pytest.mark.parametrize(
    ("call", "word"),
    [
        (lambda: nodal_lines(0, 1), "j = 0"),
        (lambda: nodal_lines(2, -1), "k = -1"),
        (lambda: nodal_lines(1.5, 1), "j = 1.5"),
        (lambda: _pattern(radius=-1.0, half_length=1.0), "radius = -1.0"),
        (lambda: _pattern(radius=1.0, half_length=math.nan), "half_length"),
        (lambda: _pattern(radius=1.0, half_length=1.0, cylinder=3), "cylinder = 3"),
    ],
)
def test_bad_input_raises(call, word):
    with pytest.raises(ValueError, match=re.escape(word)):
        call()
