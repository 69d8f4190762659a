"""The report in a real browser: headless Chromium (Debian's ``chromium`` + ``chromium-driver``)
driven by selenium, at 1400 x 900 CSS pixels.

``.ci/run`` and ``make test-browser`` install both and run this file.  Without selenium or a
Chromium binary the tests are skipped and the reason says which is missing (``pytest -rs``
lists it).  Checked: the first screen holds the verdicts and the ranked table, every figure is
visible and its screenshot is not blank (pixel variance), no console error, nothing fetched.
"""

from __future__ import annotations

import os
import shutil

import pytest

from flexbooster.present.outputs import write_outputs
from flexbooster.present.report import FIGURES, SECTIONS


def _chromium() -> tuple[str | None, str | None]:
    binary = os.environ.get("CHROMIUM") or next(
        (p for p in map(shutil.which, ("chromium", "chromium-browser", "google-chrome")) if p),
        None,
    )
    driver = os.environ.get("CHROMEDRIVER") or shutil.which("chromedriver")
    return binary, driver


def _skip_reason() -> str | None:
    try:
        import selenium  # noqa: F401
    except ImportError:
        return "selenium not installed (make test-browser installs it: pip install -e '.[browser]')"
    binary, driver = _chromium()
    if binary is None:
        return "no Chromium binary on PATH (make test-browser: apt-get install chromium)"
    if driver is None:
        return "no chromedriver on PATH (make test-browser: apt-get install chromium-driver)"
    return None


pytestmark = [pytest.mark.skipif(_skip_reason() is not None, reason=str(_skip_reason())),
              pytest.mark.slow]  # Chromium's start and the memo case's report: `make test`


@pytest.fixture(scope="module")
def report(tmp_path_factory, memo_results):
    folder = tmp_path_factory.mktemp("report")
    write_outputs(memo_results, folder)
    return folder / "report.html"


@pytest.fixture(scope="module")
def browser():
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    binary, driver = _chromium()
    options = webdriver.ChromeOptions()
    options.binary_location = binary
    for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                "--window-size=1400,900", "--hide-scrollbars", "--force-device-scale-factor=1"):
        options.add_argument(arg)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    chrome = webdriver.Chrome(service=Service(executable_path=driver), options=options)
    # the viewport itself is 1400 x 900 CSS pixels (the window size includes the browser's own
    # bars, which differ between Chromium versions)
    chrome.execute_cdp_cmd("Emulation.setDeviceMetricsOverride",
                           {"width": 1400, "height": 900, "deviceScaleFactor": 1,
                            "mobile": False})
    yield chrome
    chrome.quit()


@pytest.fixture(scope="module")
def loaded(browser, report):
    browser.get(report.as_uri())
    return browser


def test_title_and_no_console_error(loaded):
    assert loaded.title.startswith("flexbooster report")
    severe = [e for e in loaded.get_log("browser") if e["level"] in ("SEVERE", "ERROR")]
    assert severe == [], severe


def test_every_section_rendered(loaded):
    for sid, title in SECTIONS:
        size = loaded.execute_script(
            "const s = document.getElementById(arguments[0]);"
            "if (!s) return null; const r = s.getBoundingClientRect();"
            "return [r.width, r.height, s.querySelector('h2').textContent];",
            sid,
        )
        assert size is not None, sid
        width, height, heading = size
        assert width > 300 and height > 30 and heading == title, (sid, size)


def test_every_figure_rendered(loaded):
    for name in FIGURES:
        box = loaded.execute_script(
            "const f = document.getElementById('fig-' + arguments[0]);"
            "if (!f) return null; const s = f.querySelector('svg');"
            "const r = s.getBoundingClientRect();"
            "return [r.width, r.height, s.querySelectorAll('path, image, text').length];",
            name,
        )
        assert box is not None, name
        width, height, n_marks = box
        assert width > 200 and height > 100 and n_marks > 10, (name, box)


def test_no_resource_fetched(loaded):
    # Everything is inline: no element that loads a resource, only inline style sheets, and
    # the browser's resource timing list is empty.
    found = loaded.execute_script(
        "return [document.querySelectorAll("
        "'img, script, link, iframe, object, embed, video, audio, source, image[href^=\"http\"]'"
        ").length, Array.from(document.styleSheets).filter(s => s.href !== null).length,"
        " performance.getEntriesByType('resource').length];"
    )
    assert found == [0, 0, 0]


def test_navigation_links_reach_sections(loaded):
    hrefs = loaded.execute_script(
        "return Array.from(document.querySelectorAll('nav a')).map(a => a.getAttribute('href'));"
    )
    assert hrefs == [f"#{sid}" for sid, _ in SECTIONS]


def _viewport(browser) -> tuple[int, int]:
    return tuple(browser.execute_script("return [window.innerWidth, window.innerHeight];"))


def test_first_screen_holds_verdicts_and_ranked_table(loaded):
    # acceptance: at 1400 x 900 the first screen (no scrolling) shows the verdict
    # table and the whole ranked-band table; the viewport height is what the window leaves
    # (about 900 px minus the browser chrome, none in headless mode)
    loaded.execute_script("window.scrollTo(0, 0);")
    height = _viewport(loaded)[1]
    boxes = loaded.execute_script(
        "const f = document.getElementById('first-screen');"
        "const t = f.querySelectorAll('table');"
        "return Array.from(t).map(x => {const r = x.getBoundingClientRect();"
        " return [r.top, r.bottom, x.rows.length];});")
    assert len(boxes) == 2, boxes  # verdicts, ranked bands
    (v_top, v_bottom, v_rows), (b_top, b_bottom, b_rows) = boxes
    assert v_rows == 5 and b_rows >= 2, boxes  # header + 4 mechanisms; header + bands
    assert 0 <= v_top < v_bottom <= b_top < b_bottom <= height, (boxes, height)
    text = loaded.execute_script("return document.getElementById('first-screen').innerText;")
    # the overall verdict first and the damping it holds for (the verdicts' acceptance)
    assert text.split(":")[0] in ("UNSTABLE", "MARGINAL", "STABLE"), text[:80]
    assert "Damping: " in text
    # the mechanisms in engineering words (the memo's terms stay in the detailed sections)
    for words in ("rigid-body pitch", "beam bending under thrust", "vehicle parametric regions",
                  "shell resonances"):
        assert words in text, words
    assert "unstable frequencies:" not in text.lower()


def _variance(png: bytes) -> float:
    """Pixel variance of a PNG screenshot (grey levels 0..255), by matplotlib's PNG reader."""
    import io

    import matplotlib.image as mpimg
    import numpy as np

    img = mpimg.imread(io.BytesIO(png), format="png")
    grey = np.asarray(img[..., :3], dtype=float).mean(axis=-1) * 255.0
    return float(grey.var())


@pytest.mark.slow
def test_every_figure_visible_and_not_blank(loaded):
    # a blank (one-colour) element has variance 0; a drawn chart has far more than 50 grey
    # levels^2 of variance (threshold: an order of magnitude below the least busy figure,
    # the beam mode shapes)
    from selenium.webdriver.common.by import By

    for name in FIGURES:
        element = loaded.find_element(By.CSS_SELECTOR, f"#fig-{name} svg")
        loaded.execute_script("arguments[0].scrollIntoView({block: 'center'});", element)
        assert element.is_displayed(), name
        assert _variance(element.screenshot_as_png) > 50.0, name


def test_first_screen_screenshot_not_blank(loaded):
    loaded.execute_script("window.scrollTo(0, 0);")
    assert _variance(loaded.get_screenshot_as_png()) > 50.0


def test_danger_map_has_tooltips(loaded):
    # one <title> per band of results.danger (18 for the memo case: the beam-action bands
    # of test_beam_action; the pitch is stable), inside the figure's SVG
    n = loaded.execute_script(
        "return document.querySelectorAll('#fig-danger-map svg g > title').length;")
    assert n >= 1
