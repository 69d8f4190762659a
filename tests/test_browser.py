"""The report in a real browser: headless Chromium (Debian's ``chromium`` + ``chromium-driver``)
driven by selenium.

``make test-browser`` installs both and runs this file.  Without selenium or a Chromium binary
the tests are skipped and the reason says which is missing (``pytest -rs`` lists it).
"""

from __future__ import annotations

import os
import shutil

import pytest

from flexbooster.analysis import analyze
from flexbooster.case import default_case
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


pytestmark = pytest.mark.skipif(_skip_reason() is not None, reason=str(_skip_reason()))


@pytest.fixture(scope="module")
def report(tmp_path_factory):
    folder = tmp_path_factory.mktemp("report")
    write_outputs(analyze(default_case()), folder)
    return folder / "report.html"


@pytest.fixture(scope="module")
def browser():
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    binary, driver = _chromium()
    options = webdriver.ChromeOptions()
    options.binary_location = binary
    for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                "--window-size=1280,1000"):
        options.add_argument(arg)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    chrome = webdriver.Chrome(service=Service(executable_path=driver), options=options)
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
