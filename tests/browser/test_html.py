"""Every page of the built book, opened in headless Chromium the way a reader opens it.

The pages are loaded from ``file://`` URLs, as a reader who opens ``_build/html`` offline
does, in Debian's Chromium with the flags of this machine's notes (no sandbox as root, no GPU,
no background networking); CI has no network beyond the package registries, so anything the
book fetched from the internet would show as a failed or foreign request here.

How the browser is driven, and why
----------------------------------
Through the Chrome DevTools Protocol over ``--remote-debugging-pipe`` (``cdp_pipe.py`` beside
this file, standard library only). The alternative, ``chromium --headless --dump-dom`` plus a
separate ``--screenshot`` run with ``--virtual-time-budget``, only guesses when MathJax is
done and cannot ask the page anything; over the protocol the test

* waits for the real end of typesetting (``MathJax.startup.promise``), for the fonts
  (``document.fonts.ready``) and for every image, instead of a time budget;
* reads the live DOM: ``naturalWidth`` of every ``<img>``, the ``mjx-container`` elements
  MathJax produced, the text left visible;
* records every request the page made, and every uncaught JavaScript exception;
* takes a full-page screenshot (``captureBeyondViewport``) of the very state it checked;
* runs one browser for all pages (a few seconds in all), with no TCP port and no WebSocket
  library to install.

What is checked, page by page
-----------------------------
* images: every ``<img>`` has finished loading with ``naturalWidth > 0`` (an SVG without an
  intrinsic size may report 0: it must then be an existing, well-formed SVG file), and the
  page shows at least as many images as its HTML file holds;
* equations: on a page with math, MathJax 3 was loaded from the book's own
  ``_static/mathjax/`` (never a CDN), every math node (``span.math``, ``div.math``) holds an
  ``mjx-container``, the number of containers equals the number of math nodes of the HTML
  file, no TeX error is shown (an ``merror``, or an undefined macro, which MathJax draws in
  red), and no raw TeX (``\\(``, ``\\[``, ``$$``,
  ``\\begin{``, ``$...\\cmd...$``) is left in the visible text outside code;
* links: every relative ``href``/``src`` (links, scripts, style sheets, images, downloads)
  resolves to a file inside ``_build/html``, and every ``#anchor`` exists in its target page;
* offline: every request is to a ``file:``/``data:`` URL, none failed, no uncaught JavaScript
  exception;
* the figures of the method chapters each link their data as a CSV file;
* fit: no element of the text column (printed output, code, table, display math, image) is
  wider than the column or hides part of itself behind a scroll bar, at the 1280 px window
  the screenshots are taken at;
* no placeholder is left in the text ("to come", "TODO", "FIXME", "TBD", "XXX");
* figure text: every figure of the column (an image in a figure or a cell's output; not the
  theme's icons) is a PNG saved at the resolution the figures' rule
  assumes (``rotorlyap.chapters.style.BOOK_DPI``, read from its ``pHYs`` chunk) and is shown at
  least as wide as the rule assumes (its natural width, or the 672 px column if wider), so that
  its smallest text, which ``rotorlyap.chapters.style.finish`` checked when the figure was made,
  is displayed at least ``MIN_TEXT_PX`` (8 px) high; the height is computed from the image's
  file and its displayed width;
* shape: at both widths every figure is drawn with its file's aspect ratio (scaled, not
  squeezed, when a phone's column narrows it);
* a screenshot of the whole page is saved under ``_build/screenshots/`` (same path as the
  page, ``.jpg``) for a person to look at: of the book's own pages, and with
  ``ROTORLYAP_SCREENSHOTS=all`` of the API reference and the indexes too.

Without ``_build/html`` (the plain test run happens before the book is built) or without
Chromium the tests skip with the reason; ``ROTORLYAP_REQUIRE_BROWSER=1`` (set by ``.ci/run``)
turns those skips into failures (see ``conftest.py``).
"""

from __future__ import annotations

import os
import re
import struct
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from functools import lru_cache
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import unquote, urlsplit

import pytest
import yaml

ROOT = Path(__file__).resolve().parents[2]
HTML = ROOT / "_build" / "html"
SCREENSHOTS = ROOT / "_build" / "screenshots"

BOOK_PDF = HTML / "_downloads" / "rotorlyap-book.pdf"
"""The book's PDF (``tools/make_pdf.py``, which ``.ci/run`` runs while this test runs): the
links to it are checked by ``test_pdf.py``, once it is printed."""
SKIP_DIRS = {"_static", "_sources", "_images", "_downloads"}
MATHJAX_SCRIPT = "_static/mathjax/tex-chtml.js"
# Chapters whose every figure must link its data as CSV (issue 6).
CSV_FIGURE_PAGES = ("book/01_technical_stability.html", "book/02_algorithm.html")


def built_pages() -> list[str]:
    if not (HTML / "index.html").is_file():
        return []
    return sorted(
        p.relative_to(HTML).as_posix() for p in HTML.rglob("*.html")
        if not SKIP_DIRS.intersection(p.relative_to(HTML).parts[:-1])
    )


PAGES = built_pages() or [pytest.param(
    None, id="no-build",
    marks=pytest.mark.skip(reason=f"no built book in {HTML}: build it first with "
                                  "`jupyter-book build . --all -W --keep-going`"))]


# ---------------------------------------------------------------------------------------
# The HTML files as written by Sphinx (what the page must show once scripts have run)

class _StaticScan(HTMLParser):
    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.ids: set[str] = set()
        self.math = 0
        self.images = 0
        self.refresh: str | None = None
        self.scripts: list[str] = []

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if a.get("id"):
            self.ids.add(a["id"])
        if tag == "a" and a.get("name"):
            self.ids.add(a["name"])
        if tag in ("span", "div") and "math" in (a.get("class") or "").split():
            self.math += 1
        if tag == "img":
            self.images += 1
        if tag == "script" and a.get("src"):
            self.scripts.append(a["src"])
        if tag == "meta" and (a.get("http-equiv") or "").lower() == "refresh":
            m = re.search(r"url=(.+)$", a.get("content") or "", re.I)
            self.refresh = m.group(1).strip(" '\"") if m else None


@lru_cache(maxsize=None)
def static_scan(path: Path) -> _StaticScan:
    scan = _StaticScan()
    scan.feed(path.read_text(encoding="utf-8"))
    return scan


# ---------------------------------------------------------------------------------------
# The page as the browser shows it

COLLECT = r"""
(async () => {
  const t0 = performance.now();
  const wait = (ms) => new Promise(r => setTimeout(r, ms));
  const mjScript = document.querySelector('script[src*="mathjax"]');
  let mathjaxError = null;
  if (mjScript) {
    while (!(window.MathJax && MathJax.startup && MathJax.startup.promise)) {
      if (performance.now() - t0 > 30000) { mathjaxError = 'MathJax did not start within 30 s'; break; }
      await wait(50);
    }
    if (!mathjaxError) {
      try { await MathJax.startup.promise; } catch (e) { mathjaxError = String(e); }
    }
  }
  // TeX that MathJax could not read: an merror, or an undefined macro (drawn in red by the
  // noundefined extension of tex-chtml.js instead of an merror)
  const texErrors = [];
  if (!mathjaxError && window.MathJax && MathJax.startup && MathJax.startup.document && MathJax.startup.toMML) {
    for (const item of MathJax.startup.document.math) {
      const mml = MathJax.startup.toMML(item.root);
      if (/<merror|<mtext mathcolor="red">\\/.test(mml)) texErrors.push(String(item.math).slice(0, 160));
    }
  }
  await document.fonts.ready;
  await Promise.all([...document.images].map(img => img.complete ? null :
      new Promise(r => { img.addEventListener('load', r); img.addEventListener('error', r); })));

  const skip = 'pre, code, script, style, textarea, kbd, samp, noscript, template, mjx-container, .highlight';
  const texRe = /\\\(|\\\)|\\\[|\\\]|\$\$|\\begin\{|\\end\{|\$[^$\s][^$]*?\\[A-Za-z]+[^$]*?\$/;
  const rawTex = [];
  const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
  for (let n = walker.nextNode(); n; n = walker.nextNode()) {
    const el = n.parentElement;
    if (!el || el.closest(skip) || !el.checkVisibility()) continue;
    if (texRe.test(n.data)) rawTex.push(n.data.trim().slice(0, 160));
  }
  const mathNodes = [...document.querySelectorAll('span.math, div.math')];
  const links = [...document.querySelectorAll('a[href], link[href], script[src], img[src], source[src], iframe[src]')]
      .map(e => [e.tagName.toLowerCase(), e.getAttribute('href') ?? e.getAttribute('src')]);
  const figures = [...document.querySelectorAll('figure, div.figure')].map(f => ({
      id: f.id || (f.querySelector('[id]') || {}).id || '',
      csv: [...f.querySelectorAll('a[href]')].map(a => a.getAttribute('href')).filter(h => /\.csv$/.test(h)),
      // each image of the figure: its file and the link around it (book/_static/rotorlyap.js)
      images: [...f.querySelectorAll('img')].map(i => [i.getAttribute('src'), i.closest('a') ? i.closest('a').getAttribute('href') : null])}));
  // what a reader sees cut off: an element of the text column wider than the column, or wider
  // than its own box (content behind a scroll bar): printed outputs, code, tables, display math
  const column = document.querySelector('article') || document.body;
  const right = column.getBoundingClientRect().right;
  const overflowing = [];
  for (const el of column.querySelectorAll('pre, table, div.math, mjx-container[display="true"], img, .cell_output')) {
    if (!el.checkVisibility()) continue;
    const hidden = el.scrollWidth - el.clientWidth;
    const beyond = el.getBoundingClientRect().right - right;
    if (hidden > 1 || beyond > 1)
      overflowing.push({tag: el.tagName.toLowerCase(), hidden: Math.round(hidden), beyond: Math.round(beyond),
                        text: (el.textContent || el.getAttribute('src') || '').trim().replace(/\s+/g, ' ').slice(0, 100)});
  }
  const placeholders = (column.innerText.match(/\b(to come|TODO|FIXME|TBD|XXX)\b/g) || []);

  // words split across lines inside a table cell: each word's DOM Range, its client rects
  // grouped into lines (rects that overlap vertically are one line: a subscript stays on its
  // word's line); a word with a hyphen may break after it
  const splitWords = [];
  const blockOf = (n) => n.parentElement && n.parentElement.closest('p, div, li, td, th, dd, dt, br');
  for (const cell of column.querySelectorAll('table th, table td')) {
    if (!cell.checkVisibility()) continue;
    const chars = [];  // [node, offset] of every character of the cell's visible text
    let text = '', lastBlock = null;
    const tw = document.createTreeWalker(cell, NodeFilter.SHOW_TEXT);
    for (let n = tw.nextNode(); n; n = tw.nextNode()) {
      if (!n.parentElement || !n.parentElement.checkVisibility() || n.parentElement.closest('mjx-container, script, style')) continue;
      const block = blockOf(n);
      if (lastBlock !== null && block !== lastBlock) { text += ' '; chars.push(null); }
      lastBlock = block;
      for (let i = 0; i < n.data.length; i++) { text += n.data[i]; chars.push([n, i]); }
    }
    for (const m of text.matchAll(/\S+/g)) {
      const word = m[0];
      if (word.length < 2 || /[-\u2010\u2011\u2013\u2014\u00ad\/]/.test(word)) continue;
      const a = chars[m.index], b = chars[m.index + word.length - 1];
      if (!a || !b) continue;
      const r = document.createRange();
      r.setStart(a[0], a[1]); r.setEnd(b[0], b[1] + 1);
      const lines = [];
      for (const rect of r.getClientRects()) {
        if (rect.width < 0.5 || rect.height < 0.5) continue;
        const line = lines.find(l => rect.top < l.bottom - 1 && rect.bottom > l.top + 1);
        if (line) { line.top = Math.min(line.top, rect.top); line.bottom = Math.max(line.bottom, rect.bottom); }
        else lines.push({top: rect.top, bottom: rect.bottom});
      }
      if (lines.length > 1) splitWords.push(word.slice(0, 60));
    }
  }

  // template words in the text a reader sees (prose and printed outputs; not source code, code
  // literals or the API's signatures): "None" as a word, "(s)" glued to a noun
  // "None" is Python's value printed where a word belongs unless it opens a sentence and is
  // followed by more of it ("None of them", "None comes near"): a "None" in mid-sentence, or one
  // that stands alone (a table cell, "None," or "None =") is a template word. The API's object
  // descriptions (dl.py) document Python's None and are left out.
  const templateWords = [];
  const codeLike = 'script, style, noscript, template, mjx-container, nav, .cell_input, code, kbd, samp, .sig, .headerlink, dl.py';
  const blockSel = 'p, li, td, th, dt, dd, figcaption, caption, h1, h2, h3, h4, h5, h6, pre, div';
  const tw2 = document.createTreeWalker(column, NodeFilter.SHOW_TEXT);
  for (let n = tw2.nextNode(); n; n = tw2.nextNode()) {
    const el = n.parentElement;
    if (!el || el.closest(codeLike) || !el.checkVisibility()) continue;
    if (el.closest('div.highlight, pre') && !el.closest('.cell_output, .output')) continue;  // code examples
    for (const m of n.data.matchAll(/\bNone\b|[A-Za-z]\(s\)/g)) {
      const shown = n.data.slice(Math.max(0, m.index - 40), m.index + 40).replace(/\s+/g, ' ').trim();
      if (m[0] === 'None') {
        const block = el.closest(blockSel) || column;
        const r = document.createRange();
        r.setStart(block, 0); r.setEnd(n, m.index);
        const before = r.toString().trim();
        const after = n.data.slice(m.index + 4);
        const opensSentence = before === '' || /[.!?]["\u201d)]?$/.test(before);
        const standsAlone = /^\s*([,;:=)\]]|$)/.test(after);
        if (opensSentence && !standsAlone) continue;
      }
      templateWords.push(shown);
    }
  }

  // anything wider than the screen outside its own scroll box (the page would scroll sideways):
  // the outermost such elements; an element inside a box that clips or scrolls sideways, or
  // inside a fixed drawer of the theme, is not
  const vw = document.documentElement.clientWidth;
  const sideways = [];
  const clippedOrFixed = (el) => {
    for (let a = el.parentElement; a && a !== document.documentElement; a = a.parentElement) {
      const cs = getComputedStyle(a);
      if (cs.position === 'fixed') return true;
      if (cs.overflowX !== 'visible' && a.getBoundingClientRect().right <= vw + 1) return true;
    }
    return false;
  };
  for (const el of document.body.querySelectorAll('*')) {
    const rect = el.getBoundingClientRect();
    if (rect.right <= vw + 1 || rect.width === 0 || rect.height === 0) continue;
    if (getComputedStyle(el).position === 'fixed' || !el.checkVisibility()) continue;
    if (clippedOrFixed(el)) continue;
    if (el.parentElement && sideways.some(o => o.el.contains(el))) continue;
    sideways.push({el, tag: el.tagName.toLowerCase() + (el.className && typeof el.className === 'string' ? '.' + el.className.split(' ')[0] : ''),
                   right: Math.round(rect.right),
                   text: (el.textContent || '').trim().replace(/\s+/g, ' ').slice(0, 80)});
  }

  return {
    splitWords,
    templateWords,
    sideways: sideways.map(o => ({tag: o.tag, right: o.right, text: o.text})),
    viewportWidth: vw,
    scrollWidth: document.documentElement.scrollWidth,
    pageHeight: Math.max(document.documentElement.scrollHeight, document.body.scrollHeight),
    overflowing,
    placeholders,
    href: location.href,
    title: document.title,
    mathjaxVersion: (window.MathJax && MathJax.version) || null,
    mathjaxScript: mjScript ? mjScript.getAttribute('src') : null,
    mathjaxError,
    mathNodes: mathNodes.length,
    mathNodesUntypeset: mathNodes.filter(m => !m.querySelector('mjx-container'))
        .map(m => m.textContent.trim().slice(0, 160)),
    containers: document.querySelectorAll('mjx-container').length,
    merrors: [...document.querySelectorAll('mjx-merror')].map(e => e.getAttribute('data-mjx-error') || e.textContent),
    texErrors,
    rawTex,
    images: [...document.images].map(i => ({src: i.getAttribute('src'), complete: i.complete,
                                            width: i.naturalWidth, height: i.naturalHeight,
                                            shown: i.getBoundingClientRect().width,
                                            shownHeight: i.getBoundingClientRect().height,
                                            inFigure: column.contains(i) && i.checkVisibility() && !!i.closest('figure, div.figure, .cell_output')})),
    links,
    ids: [...document.querySelectorAll('[id]')].map(e => e.id)
        .concat([...document.querySelectorAll('a[name]')].map(e => e.getAttribute('name'))),
    figures,
    seconds: (performance.now() - t0) / 1000,
  };
})()
"""


@dataclass
class Rendered:
    page: str
    info: dict
    requests: list[str] = field(default_factory=list)
    failed: list[str] = field(default_factory=list)
    exceptions: list[str] = field(default_factory=list)
    screenshot: Path | None = None
    screenshot_size: tuple[int, int] = (0, 0)


_rendered: dict[str, Rendered] = {}


def _record(events: list[dict], into: Rendered, urls: dict[str, str]) -> None:
    for ev in events:
        method, params = ev["method"], ev.get("params", {})
        if method == "Network.requestWillBeSent":
            urls[params["requestId"]] = params["request"]["url"]
            into.requests.append(params["request"]["url"])
        elif method == "Network.loadingFailed" and not params.get("canceled"):
            into.failed.append(f"{urls.get(params['requestId'], '?')}: {params.get('errorText')}")
        elif method == "Runtime.exceptionThrown":
            d = params.get("exceptionDetails", {})
            into.exceptions.append(d.get("exception", {}).get("description") or d.get("text", "?"))


WIDTHS = (1280, 390)
"""Browser windows every page is opened at, CSS px: the desktop window of the screenshots and a
phone's (a 390 px wide phone in portrait)."""

MAX_PAGE_HEIGHT = 40_000
"""Tallest page, CSS px, a reader is asked to scroll through (at 1280 px; issue 42: the API
reference was one page 495,000 px tall)."""


def _is_api_page(page) -> bool:
    """A page of the API reference (or its indexes), generated from docstrings about Python,
    where ``None`` is the value documented."""
    return isinstance(page, str) and (page.startswith(("book/api/", "genindex", "py-modindex"))
                                      or page == "book/api.html")


SCREENSHOT_ALL = os.environ.get("ROTORLYAP_SCREENSHOTS", "") == "all"
"""``ROTORLYAP_SCREENSHOTS=all``: a screenshot of every page, the API reference's and the
indexes' too; by default only of the book's own pages (:func:`screenshot_wanted`)."""


def screenshot_wanted(page) -> bool:
    """Whether :func:`render` saves a screenshot of ``page``: the book's own pages always, the
    API reference and the indexes (generated from docstrings, 113 of the 131 pages) only with
    :data:`SCREENSHOT_ALL`. A screenshot is for a person to look at and checks nothing the page's
    tests do not; it took more than half of the browser test's time (measured 2026-12-05: 128 s
    of 220 s for the 262 page loads, against 80 s loading and 11 s checking)."""
    return SCREENSHOT_ALL or not _is_api_page(page)


def screenshot_path(page: str, width: int) -> Path:
    """Where the screenshot of ``page`` at ``width`` px is saved (a JPEG: see
    :meth:`cdp_pipe.Page.screenshot`): ``_build/screenshots/<page>.jpg`` at 1280 px,
    ``_build/screenshots/<width>px/<page>.jpg`` otherwise."""
    name = page[:-len(".html")] + ".jpg"
    return SCREENSHOTS / name if width == WIDTHS[0] else SCREENSHOTS / f"{width}px" / name


def render(tab, page: str, width: int = WIDTHS[0]) -> Rendered:
    """Load one page at a window ``width`` px wide (once per session), check-ready it, screenshot
    it (:func:`screenshot_wanted`), return what it showed."""
    if (page, width) in _rendered:
        return _rendered[(page, width)]
    if tab.width != width:
        tab.set_viewport(width, 900)
    path = HTML / page
    out = Rendered(page, {})
    urls: dict[str, str] = {}
    events = tab.navigate(path.as_uri())
    _record(events, out, urls)
    if static_scan(path).refresh and not any(e["method"] == "Page.loadEventFired" for e in events):
        # a redirect page (index.html): wait for the page it sends the browser to
        tab.browser.wait_event("Page.loadEventFired", session=tab.session, timeout=30)
    out.info = tab.evaluate(COLLECT, timeout=90)
    _record(tab.browser.drain_events(tab.session), out, urls)
    if screenshot_wanted(page):
        out.screenshot = screenshot_path(page, width)
        out.screenshot_size = tab.screenshot(out.screenshot, max_height=200_000)
        _record(tab.browser.drain_events(tab.session), out, urls)
    _rendered[(page, width)] = out
    return out


@pytest.fixture
def shown(tab, request) -> Rendered:
    """The page at the 1280 px window."""
    page = request.node.callspec.params["page"]
    return render(tab, page)


@pytest.fixture
def shown_at(tab, request) -> Rendered:
    """The page at the window width of the test's ``width`` parameter."""
    params = request.node.callspec.params
    return render(tab, params["page"], params["width"])


# ---------------------------------------------------------------------------------------
# The checks

def _toc_files(node) -> list[str]:
    files = []
    if isinstance(node, dict):
        for key in ("root", "file"):
            if key in node:
                files.append(node[key])
        for value in node.values():
            if isinstance(value, (list, dict)):
                files += _toc_files(value)
    elif isinstance(node, list):
        for item in node:
            files += _toc_files(item)
    return files


def test_every_page_of_the_toc_was_built(html_root):
    toc = yaml.safe_load((ROOT / "_toc.yml").read_text())
    expected = {f"{Path(f).with_suffix('').as_posix()}.html" for f in _toc_files(toc)}
    expected |= {"index.html", "genindex.html", "search.html"}
    assert "book/api.html" in expected
    missing = sorted(p for p in expected if not (html_root / p).is_file())
    assert not missing, f"pages of _toc.yml missing from the build: {missing}"
    assert expected <= set(built_pages())


def test_mathjax_is_served_from_the_book(html_root):
    local = html_root / MATHJAX_SCRIPT
    assert local.is_file(), f"{local} missing: the offline MathJax extension did not run"
    assert (html_root / "_static/mathjax/output/chtml/fonts/woff-v2").is_dir()
    for page in built_pages():
        html = (html_root / page).read_text(encoding="utf-8")
        assert not re.search(r"cdn\.jsdelivr|cdnjs|mathjax@|polyfill\.io", html), (
            f"{page} refers to a CDN")
        for src in static_scan(html_root / page).scripts:
            if "mathjax" in src.lower():
                assert not urlsplit(src).scheme, f"{page} loads MathJax from {src}"
                resolved = ((html_root / page).parent / urlsplit(src).path).resolve()
                assert resolved == local.resolve(), f"{page} loads MathJax from {src}"


def shown_file(page: str) -> Path:
    """The HTML file the browser ends on for ``page``: the target of a redirect page (the
    book's ``index.html`` sends the reader to the intro), else the page itself."""
    path = HTML / page
    refresh = static_scan(path).refresh
    if refresh and not urlsplit(refresh).scheme:
        return (path.parent / urlsplit(refresh).path).resolve()
    return path


@pytest.mark.parametrize("page", PAGES)
def test_images_load(shown, page):
    bad = [img for img in shown.info["images"] if not img["complete"] or img["width"] <= 0]
    for img in list(bad):
        src = urlsplit(img["src"] or "").path
        target = ((HTML / page).parent / unquote(src)).resolve()
        if img["complete"] and src.endswith(".svg") and target.is_file():
            if ET.parse(target).getroot().tag.endswith("svg"):
                bad.remove(img)  # an SVG without an intrinsic size
    assert not bad, f"images that did not load on {page}: {bad}"
    assert len(shown.info["images"]) >= static_scan(shown_file(page)).images


@pytest.mark.parametrize("page", PAGES)
def test_equations_are_typeset(shown, page):
    info = shown.info
    expected = static_scan(shown_file(page)).math
    assert info["mathNodes"] == expected
    if expected:
        assert info["mathjaxError"] is None, info["mathjaxError"]
        assert (info["mathjaxVersion"] or "").startswith("3."), "MathJax 3 did not load"
        assert info["mathjaxScript"] and not urlsplit(info["mathjaxScript"]).scheme
        assert not info["mathNodesUntypeset"], f"math not typeset: {info['mathNodesUntypeset'][:5]}"
        assert info["containers"] == expected, (
            f"{info['containers']} mjx-container elements for {expected} math nodes")
    assert not info["merrors"], f"TeX errors shown: {info['merrors'][:5]}"
    assert not info["texErrors"], f"TeX MathJax could not read: {info['texErrors'][:5]}"
    assert not info["rawTex"], f"raw TeX left in the visible text: {info['rawTex'][:5]}"


@lru_cache(maxsize=None)
def _ids_of(path: Path) -> frozenset:
    return frozenset(static_scan(path).ids)


@pytest.mark.parametrize("page", PAGES)
def test_internal_links_resolve(shown, page):
    # links are relative to the page the browser ended on (index.html redirects)
    here = Path(unquote(urlsplit(shown.info["href"]).path))
    own_ids = set(shown.info["ids"]) | _ids_of(here)
    broken = []
    for tag, ref in shown.info["links"]:
        parts = urlsplit(ref)
        if parts.scheme or ref.startswith("//"):
            continue  # external (http, https, mailto, data, javascript): not fetched offline
        path, frag = unquote(parts.path), unquote(parts.fragment)
        target = (here.parent / path).resolve() if path else here.resolve()
        if target == BOOK_PDF.resolve():
            continue  # printed after the build, beside this test: test_pdf.py checks these links
        if not target.is_file():
            broken.append(f"<{tag}> {ref}: no file {target}")
            continue
        if HTML.resolve() not in target.parents:
            broken.append(f"<{tag}> {ref}: outside the built book")
            continue
        if frag and target.suffix == ".html":
            ids = own_ids if target == here.resolve() else _ids_of(target)
            if frag not in ids:
                broken.append(f"<{tag}> {ref}: no id {frag!r} in {target.relative_to(HTML.resolve())}")
    refresh = static_scan(HTML / page).refresh
    if refresh:
        target = ((HTML / page).parent / urlsplit(refresh).path).resolve()
        if not target.is_file():
            broken.append(f"redirect to {refresh}: no such page")
        assert shown.info["href"] == target.as_uri(), "the redirect was not followed"
    assert not broken, f"{len(broken)} broken internal links on {page}:\n" + "\n".join(broken[:20])


@pytest.mark.parametrize("page", PAGES)
def test_works_offline(shown, page):
    foreign = [u for u in shown.requests if urlsplit(u).scheme not in ("file", "data", "blob", "about")]
    assert not foreign, f"{page} requested {foreign[:10]}"
    assert not shown.failed, f"{page}: failed loads {shown.failed[:10]}"
    assert not shown.exceptions, f"{page}: uncaught JavaScript exceptions {shown.exceptions[:5]}"


@pytest.mark.parametrize("page", [p for p in CSV_FIGURE_PAGES if p in built_pages()] or [
    pytest.param(None, id="no-build", marks=pytest.mark.skip(reason="no built book"))])
def test_every_figure_links_its_data_as_csv(shown, page):
    figures = shown.info["figures"]
    assert figures, f"no figures on {page}"
    missing = [f["id"] for f in figures if not f["csv"]]
    assert not missing, f"figures without a CSV download on {page}: {missing}"
    for f in figures:
        for href in f["csv"]:
            assert "_downloads/" in href and (HTML / page).parent.joinpath(unquote(href)).is_file()


@pytest.mark.parametrize("page", PAGES)
def test_a_click_on_a_figure_opens_it_at_full_size(shown, page):
    """Every image of a figure is a link to its own file (book/_static/rotorlyap.js), so that a
    multi-panel figure shrunk to a phone's column is read at full size in a tab of its own (a
    page without figures has nothing to check)."""
    images = [img for f in shown.info["figures"] for img in f["images"]]
    unlinked = [src for src, href in images if href != src]
    assert not unlinked, f"{page}: figure images that do not open at full size: {unlinked[:5]}"


def _png_dpi(path: Path) -> float | None:
    """Horizontal resolution of a PNG from its ``pHYs`` chunk, dots per inch (None without one)."""
    data = path.read_bytes()
    pos = 8
    while pos + 8 <= len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        if kind == b"pHYs":
            x_per_unit, _, unit = struct.unpack(">IIB", data[pos + 8:pos + 17])
            return x_per_unit * 0.0254 if unit == 1 else None
        if kind in (b"IDAT", b"IEND"):
            return None
        pos += 12 + length
    return None



def _jpeg_size(path: Path) -> tuple[int, int]:
    """Width and height of a JPEG from its start-of-frame segment."""
    data = path.read_bytes()
    assert data[:2] == b"\xff\xd8", f"{path} is not a JPEG"
    pos = 2
    while pos + 4 <= len(data):
        marker, length = data[pos + 1], struct.unpack(">H", data[pos + 2:pos + 4])[0]
        if 0xC0 <= marker <= 0xCF and marker not in (0xC4, 0xC8, 0xCC):
            height, width = struct.unpack(">HH", data[pos + 5:pos + 9])
            return width, height
        pos += 2 + length
    raise AssertionError(f"{path}: no frame size in the JPEG")


@pytest.mark.parametrize("page", [p for p in PAGES if screenshot_wanted(p)])
def test_screenshot_saved(shown, page):
    width, height = _jpeg_size(shown.screenshot)
    assert (width, height) == shown.screenshot_size
    assert width == 1280 and height >= 300, f"{shown.screenshot}: {width} x {height}"


@pytest.mark.parametrize("page", PAGES)
def test_nothing_is_wider_than_the_text_column(shown, page):
    """A reader sees every output, table and equation whole: nothing runs off the column's right
    edge or hides behind a scroll bar (book/_static/rotorlyap.css wraps printed outputs and
    table cells; long equations are split into lines)."""
    assert not shown.info["overflowing"], (
        f"{page}: {len(shown.info['overflowing'])} elements wider than the text column: "
        + "; ".join(f"{o['tag']} ({o['hidden']} px hidden, {o['beyond']} px beyond): {o['text']}"
                    for o in shown.info["overflowing"][:10]))


@pytest.mark.parametrize("page", PAGES)
def test_no_placeholder_is_left_in_the_text(shown, page):
    assert not shown.info["placeholders"], f"{page}: placeholders in the text: {shown.info['placeholders']}"


@pytest.mark.parametrize("page", PAGES)
def test_figure_text_is_legible_at_the_displayed_width(shown, page):
    """Every figure's smallest text is shown at least ``MIN_TEXT_PX`` high.

    ``finish`` allows, in a figure ``n`` px wide saved at ``BOOK_DPI``, a smallest font of
    ``MIN_TEXT_PX * 72 / min(BOOK_DPI, PAGE_WIDTH_PX * BOOK_DPI / n)`` pt, that is
    ``MIN_TEXT_PX * n / min(n, PAGE_WIDTH_PX)`` CSS pixels of the figure; the PNG holds
    ``DEVICE_PIXEL_RATIO`` image pixels per CSS pixel (``n`` = its width / that ratio) and the
    browser shows it ``shown / n`` of its size, so that text is
    ``MIN_TEXT_PX * shown / min(n, PAGE_WIDTH_PX)`` px high on the page (at the 1280 px window:
    on a phone every figure is shrunk to the screen, the reader zooms). This fails if a figure was saved at another resolution than the rule
    assumes, or if the page shows it narrower than the column the rule was made for.
    """
    from rotorlyap.chapters.style import BOOK_DPI, DEVICE_PIXEL_RATIO, MIN_TEXT_PX, PAGE_WIDTH_PX

    here = Path(unquote(urlsplit(shown.info["href"]).path))
    small = []
    for img in shown.info["images"]:
        if not img["inFigure"] or not img["width"]:
            continue
        target = (here.parent / unquote(urlsplit(img["src"]).path)).resolve()
        if target.suffix.lower() != ".png":
            small.append(f"{img['src']}: not a PNG made by rotorlyap.chapters")
            continue
        dpi = _png_dpi(target)
        saved_dpi = BOOK_DPI * DEVICE_PIXEL_RATIO
        if dpi is None or abs(dpi - saved_dpi) > 0.5:
            small.append(f"{img['src']}: saved at {dpi} dpi, the rule assumes {saved_dpi:g}")
            continue
        css_width = img["width"] / DEVICE_PIXEL_RATIO  # the figure's width in CSS px at full size
        text_px = MIN_TEXT_PX * img["shown"] / min(css_width, PAGE_WIDTH_PX)
        if text_px < MIN_TEXT_PX - 0.05:
            small.append(f"{img['src']}: {img['width']} px shown at {img['shown']:.0f} px, "
                         f"its smallest text at {text_px:.1f} px")
    assert not small, f"{page}: figures whose text is shown below {MIN_TEXT_PX:g} px: " + "; ".join(small)


def _is_index_page(page) -> bool:
    """Sphinx's general and module indexes: two fixed columns of qualified Python names, which
    wrap anywhere (a name is an identifier, not a word of the text)."""
    return isinstance(page, str) and page.startswith(("genindex", "py-modindex"))


@pytest.mark.parametrize("width", WIDTHS)
@pytest.mark.parametrize("page", [p for p in PAGES if not _is_index_page(p)])
def test_no_word_is_split_inside_a_table_cell(shown_at, page, width):
    """Headers and cells wrap between words (book/_static/rotorlyap.css), never inside one: a
    word without a hyphen is shown on one line (its DOM Range's client rects, grouped by line).
    Not on Sphinx's index pages (:func:`_is_index_page`)."""
    split = shown_at.info["splitWords"]
    assert not split, f"{page} at {width} px: {len(split)} words split across lines in table cells: {split[:20]}"


@pytest.mark.parametrize("width", WIDTHS)
@pytest.mark.parametrize("page", PAGES)
def test_raster_figures_have_two_device_pixels_per_css_pixel(shown_at, page, width):
    """Every raster figure of the column is sharp on a 2x screen: at least two image pixels
    per CSS pixel it is shown at (rotorlyap.chapters.style.DEVICE_PIXEL_RATIO; an SVG is vector)."""
    from rotorlyap.chapters.style import DEVICE_PIXEL_RATIO

    soft = [f"{img['src']}: {img['width']} px shown at {img['shown']:.0f} px"
            for img in shown_at.info["images"]
            if img["inFigure"] and img["width"] and img["shown"]
            and not urlsplit(img["src"] or "").path.lower().endswith(".svg")
            and img["width"] < DEVICE_PIXEL_RATIO * img["shown"] - 1]
    assert not soft, f"{page} at {width} px: raster figures below {DEVICE_PIXEL_RATIO}x: " + "; ".join(soft[:10])


@pytest.mark.parametrize("width", WIDTHS)
@pytest.mark.parametrize("page", PAGES)
def test_figures_keep_their_shape(shown_at, page, width):
    """Every figure is drawn with its file's aspect ratio at both widths (within 2 %): a figure
    narrowed to a phone's column is scaled, not squeezed sideways (a circle stays a circle)."""
    bent = [f"{img['src']}: file {img['width']} x {img['height']} px, drawn {img['shown']:.0f} x "
            f"{img['shownHeight']:.0f} px"
            for img in shown_at.info["images"]
            if img["inFigure"] and img["width"] and img["height"] and img["shown"] and img["shownHeight"]
            and abs((img["shownHeight"] / img["shown"]) / (img["height"] / img["width"]) - 1) > 0.02]
    assert not bent, f"{page} at {width} px: figures drawn out of shape: " + "; ".join(bent[:10])


@pytest.mark.parametrize("width", WIDTHS[:1])
@pytest.mark.parametrize("page", [p for p in PAGES if p != "genindex-all.html"])
def test_no_page_is_taller_than_a_reader_scrolls(shown_at, page, width):
    """At the 1280 px window (on a phone every page is taller by its narrow column). Not
    ``genindex-all.html``: Sphinx's whole index on one page, offered beside the index's pages
    per letter (``html_split_index``), which are measured."""
    height = shown_at.info["pageHeight"]
    assert height <= MAX_PAGE_HEIGHT, f"{page} is {height} px tall at {width} px (at most {MAX_PAGE_HEIGHT})"


TEXT_PAGES = [p for p in PAGES if not _is_api_page(p)]


@pytest.mark.parametrize("width", WIDTHS)
@pytest.mark.parametrize("page", TEXT_PAGES)
def test_no_template_words_in_the_text(shown_at, page, width):
    """No text left from a template: "None" as a word or "(s)" after a noun, in the prose and
    printed outputs a reader sees (source code, code literals and signatures excepted; not on
    the API reference's pages, whose docstrings document Python's ``None``)."""
    found = shown_at.info["templateWords"]
    assert not found, f"{page} at {width} px: template words in the text: {found[:10]}"


@pytest.mark.parametrize("width", WIDTHS)
@pytest.mark.parametrize("page", PAGES)
def test_the_page_never_scrolls_sideways(shown_at, page, width):
    """Nothing is wider than the screen outside its own scroll box (a wide table or equation
    scrolls in its box, book/_static/rotorlyap.css), so the page itself never scrolls sideways."""
    info = shown_at.info
    assert not info["sideways"], (
        f"{page} at {width} px: {len(info['sideways'])} elements run past the {info['viewportWidth']} px "
        "screen outside a scroll box: " + "; ".join(f"{o['tag']} (to {o['right']} px): {o['text']}"
                                                  for o in info["sideways"][:10]))
    assert info["scrollWidth"] <= info["viewportWidth"] + 1, (
        f"{page} at {width} px: the page is {info['scrollWidth']} px wide on a {info['viewportWidth']} px screen")


@pytest.mark.parametrize("page", [p for p in PAGES if screenshot_wanted(p)])
def test_phone_screenshot_saved(tab, page):
    out = render(tab, page, WIDTHS[1])
    width, height = _jpeg_size(out.screenshot)
    assert (width, height) == out.screenshot_size and width == WIDTHS[1] and height >= 300
