"""Print the whole built book to one PDF with headless Chromium (no LaTeX).

    python tools/make_pdf.py [--html _build/html] [--out _build/html/_downloads/rotorlyap-book.pdf]

Run after the build (``.ci/run`` does, before the browser test). Every page of the book is
opened in the order of its navigation (the sidebar of the first page, which follows
``_toc.yml``), the way the browser test opens it: from ``file://`` URLs, MathJax's typesetting,
the fonts and the images awaited. Each page's article (its typeset HTML, every relative link
made absolute) and MathJax's stylesheet are collected; the first page is then given all the
articles, each chapter starting on a new sheet, and printed by the DevTools protocol's
``Page.printToPDF`` (A4, page numbers in the footer, the document outline from the headings).
The browser is driven by ``tests/browser/cdp_pipe.py``, standard library only.

The file is written where ``book/_ext/pdf_download.py`` links it from every page's download
menu (:data:`DEFAULT_OUT`). Exits with status 1 and one line on standard error if the book is
not built, Chromium is missing, or a page does not load.
"""

from __future__ import annotations

import argparse
import base64
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests" / "browser"))

from cdp_pipe import Browser, CDPError, find_chromium  # noqa: E402

DEFAULT_HTML = ROOT / "_build" / "html"
DEFAULT_OUT = DEFAULT_HTML / "_downloads" / "rotorlyap-book.pdf"

# The pages in reading order: the first page, then every link of the book's navigation.
NAV_PAGES = r"""
(() => {
  const seen = new Set([location.href.split('#')[0]]);
  const out = [location.href.split('#')[0]];
  for (const a of document.querySelectorAll('nav.bd-docs-nav a.reference.internal, .bd-sidebar-primary nav a.reference.internal')) {
    const url = a.href.split('#')[0];
    if (!seen.has(url)) { seen.add(url); out.push(url); }
  }
  return out;
})()
"""

# Wait for MathJax, the fonts and the images; then return the article with absolute links and
# MathJax's stylesheet.
COLLECT = r"""
(async () => {
  const t0 = performance.now();
  const wait = (ms) => new Promise(r => setTimeout(r, ms));
  if (document.querySelector('script[src*="mathjax"]')) {
    while (!(window.MathJax && MathJax.startup && MathJax.startup.promise)) {
      if (performance.now() - t0 > 30000) throw new Error('MathJax did not start within 30 s');
      await wait(50);
    }
    await MathJax.startup.promise;
  }
  await document.fonts.ready;
  await Promise.all([...document.images].map(img => img.complete ? null :
      new Promise(r => { img.addEventListener('load', r); img.addEventListener('error', r); })));
  const article = document.querySelector('article.bd-article') || document.querySelector('article');
  if (!article) throw new Error('no article on ' + location.href);
  const copy = article.cloneNode(true);
  copy.querySelectorAll('script, .headerlink, .toggle-button, button').forEach(e => e.remove());
  for (const [sel, attr] of [['[src]', 'src'], ['[href]', 'href']]) {
    for (const e of copy.querySelectorAll(sel)) {
      const v = e.getAttribute(attr);
      if (v && !/^(#|[a-z]+:)/i.test(v)) e.setAttribute(attr, new URL(v, location.href).href);
    }
  }
  const mjx = [...document.querySelectorAll('style')].filter(s => /mjx-/.test(s.textContent))
      .map(s => s.textContent).join('\n');
  return {html: copy.innerHTML, mathjaxCss: mjx, title: document.title};
})()
"""

PRINT_CSS = """
@page { size: A4; margin: 14mm 12mm 16mm 12mm; }
html, body { background: #fff !important; }
.bd-header, .bd-sidebar-primary, .bd-sidebar-secondary, .bd-header-article, .prev-next-area,
.bd-footer, .bd-footer-content, .bd-footer-article, footer, .header-article, #pst-back-to-top,
.pst-async-banner-revealer, .search-button-field, #jb-print-docs-body { display: none !important; }
/* the theme's print style hides each page's first h1 (it prints the title in a header of its
   own); here each chapter's heading is its title */
.bd-main .bd-content .bd-article h1:first-of-type { display: block !important; }
.bd-main, .bd-content, .bd-article-container, .bd-page-width { max-width: none !important;
  width: 100% !important; padding: 0 !important; margin: 0 !important; }
section.rotorlyap-pdf-page + section.rotorlyap-pdf-page { break-before: page; }
figure, img, table, div.math, pre { break-inside: avoid; }
h1, h2, h3 { break-after: avoid; }
"""

ASSEMBLE = r"""
((pages, css) => {
  const article = document.querySelector('article.bd-article') || document.querySelector('article');
  article.innerHTML = pages.map(p => '<section class="rotorlyap-pdf-page">' + p + '</section>').join('\n');
  const style = document.createElement('style');
  style.textContent = css;
  document.head.appendChild(style);
  return article.querySelectorAll('section.rotorlyap-pdf-page').length;
})
"""

WAIT_IMAGES = r"""
(async () => {
  await document.fonts.ready;
  await Promise.all([...document.images].map(img => img.complete ? null :
      new Promise(r => { img.addEventListener('load', r); img.addEventListener('error', r); })));
  return [...document.images].filter(i => !i.naturalWidth).map(i => i.src);
})()
"""

FOOTER = ('<div style="font-size:8px; width:100%; text-align:center; color:#555;">'
          '<span class="title"></span> &middot; <span class="pageNumber"></span> / '
          '<span class="totalPages"></span></div>')


def book_pages(tab, first: Path) -> list[str]:
    """The URLs of the book's pages in reading order, starting at ``first``."""
    tab.navigate(first.as_uri(), timeout=60)
    return tab.evaluate(NAV_PAGES, timeout=30)


def make_pdf(html: Path = DEFAULT_HTML, out: Path = DEFAULT_OUT, *, executable: str | None = None,
             log=print) -> tuple[Path, int]:
    """Print the book built in ``html`` to ``out``; return the path and the number of pages of
    the book (HTML pages) it holds.

    Raises
    ------
    FileNotFoundError
        If the book is not built (no ``html/book/intro.html``) or Chromium is not found.
    RuntimeError
        If a page cannot be read or an image of the assembled book does not load.
    """
    html = Path(html)
    first = html / "book" / "intro.html"
    if not first.is_file():
        raise FileNotFoundError(f"no built book in {html} (missing {first}): build it first")
    exe = executable or find_chromium()
    if exe is None:
        raise FileNotFoundError("Chromium not found (Debian: apt-get install chromium, or set ROTORLYAP_CHROMIUM)")
    t0 = time.monotonic()
    browser = Browser(exe, timeout=120)
    try:
        tab = browser.new_page(width=1280, height=900)
        urls = book_pages(tab, first)
        if len(urls) < 2:
            raise RuntimeError(f"the navigation of {first} lists no other page")
        articles, styles = [], []
        for url in urls:
            try:
                tab.navigate(url, timeout=60)
                got = tab.evaluate(COLLECT, timeout=120)
            except CDPError as exc:
                raise RuntimeError(f"could not read {url}: {exc}") from exc
            articles.append(got["html"])
            if got["mathjaxCss"]:
                styles.append(got["mathjaxCss"])
        # the assembled book: the first page given every article, and the print style
        tab.navigate(first.as_uri(), timeout=60)
        tab.evaluate(COLLECT, timeout=120)
        n = tab.evaluate(f"({ASSEMBLE})(%s, %s)" % (_js(articles), _js("\n".join(styles) + PRINT_CSS)),
                         timeout=120)
        broken = tab.evaluate(WAIT_IMAGES, timeout=300)
        if broken:
            raise RuntimeError(f"{len(broken)} images of the assembled book did not load: {broken[:5]}")
        reply = tab.send("Page.printToPDF", {
            "printBackground": True, "preferCSSPageSize": True,
            "displayHeaderFooter": True, "headerTemplate": "<div></div>", "footerTemplate": FOOTER,
            "generateDocumentOutline": True, "generateTaggedPDF": False,
        }, timeout=900)
    finally:
        browser.close()
    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_bytes(base64.b64decode(reply["data"]))
    log(f"{out}: {n} pages of the book, {out.stat().st_size / 1e6:.1f} MB, {time.monotonic() - t0:.0f} s")
    return out, n


def _js(value) -> str:
    import json
    return json.dumps(value)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--html", type=Path, default=DEFAULT_HTML, help="the built book (default: %(default)s)")
    parser.add_argument("--out", type=Path, default=None,
                        help="the PDF to write (default: <html>/_downloads/rotorlyap-book.pdf)")
    args = parser.parse_args(argv)
    out = args.out or args.html / "_downloads" / "rotorlyap-book.pdf"
    try:
        make_pdf(args.html, out)
    except (FileNotFoundError, RuntimeError, CDPError) as exc:
        print(f"make_pdf: {exc}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
