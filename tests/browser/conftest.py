"""Fixtures of the browser test: the built book, one headless Chromium, the rendered pages.

The browser test needs the built book (``_build/html``) and Chromium. Where either is
missing its tests skip with the reason, which is what the plain ``python -m pytest`` run
before the book build wants. Set ``ROTORLYAP_REQUIRE_BROWSER=1`` (``.ci/run`` does, after the
build) and every skip of these tests becomes a failure instead, so CI cannot pass without
having looked at the pages.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
HTML = ROOT / "_build" / "html"
SCREENSHOTS = ROOT / "_build" / "screenshots"
REQUIRE = os.environ.get("ROTORLYAP_REQUIRE_BROWSER", "") not in ("", "0")


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item, call):
    outcome = yield
    report = outcome.get_result()
    if REQUIRE and report.skipped:
        reason = report.longrepr[2] if isinstance(report.longrepr, tuple) else str(report.longrepr)
        report.outcome = "failed"
        report.longrepr = f"ROTORLYAP_REQUIRE_BROWSER=1, but this browser test was skipped: {reason}"


@pytest.fixture(scope="session")
def html_root() -> Path:
    if not (HTML / "index.html").is_file():
        pytest.skip(f"no built book in {HTML}: build it first with "
                    "`jupyter-book build . --all -W --keep-going`")
    return HTML


@pytest.fixture(scope="session")
def browser(html_root):
    from cdp_pipe import Browser, find_chromium

    exe = find_chromium()
    if exe is None:
        pytest.skip("Chromium not found (Debian: `apt-get install chromium`, or set ROTORLYAP_CHROMIUM)")
    b = Browser(exe)
    try:
        yield b
    finally:
        b.close()


@pytest.fixture(scope="session")
def tab(browser):
    page = browser.new_page(width=1280, height=900)
    yield page
