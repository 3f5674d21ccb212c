"""The PDF of the whole book (``tools/make_pdf.py``, printed by Chromium after the build).

It must exist where every page's download menu links it, have as many sheets as its footers
count, start each page of the book on a sheet of its own, and hold every chapter's title (and
every API page's), in the order of ``_toc.yml``. Its text is read by ``pdf_text.py`` beside
this file (standard library only). Skips without the PDF, as the other browser tests do
without a built book; ``ROTORLYAP_REQUIRE_BROWSER=1`` turns the skip into a failure.
"""

from __future__ import annotations

import html as html_lib
import re
import unicodedata
from pathlib import Path
from urllib.parse import unquote

import pytest
import yaml

from pdf_text import Pdf

ROOT = Path(__file__).resolve().parents[2]
HTML = ROOT / "_build" / "html"
PDF = HTML / "_downloads" / "rotorlyap-book.pdf"


def _norm(text: str) -> str:
    """Text compared without case, whitespace, ligatures or the kind of apostrophe (the PDF's
    runs are split where the printer placed its glyphs, not where the words end)."""
    text = unicodedata.normalize("NFKC", text).replace("\u2019", "'").replace("\u2018", "'")
    return re.sub(r"\s+", "", text).lower()


def _toc_docs() -> list[str]:
    """The book's pages in the order of ``_toc.yml`` (a glob expanded as Sphinx sorts it)."""
    toc = yaml.safe_load((ROOT / "_toc.yml").read_text())
    out: list[str] = []

    def walk(node) -> None:
        if isinstance(node, dict):
            for key in ("root", "file"):
                if key in node:
                    out.append(node[key])
            if "glob" in node:
                out.extend(sorted(p.relative_to(HTML).with_suffix("").as_posix()
                                  for p in HTML.glob(node["glob"] + ".html")))
            for key in ("parts", "chapters", "sections"):
                for item in node.get(key, []):
                    walk(item)
        elif isinstance(node, list):
            for item in node:
                walk(item)

    walk(toc)
    return out


def _title(doc: str) -> str:
    """The page's first heading as shown (its section number and permalink sign left out)."""
    text = (HTML / f"{doc}.html").read_text(encoding="utf-8")
    m = re.search(r"<h1[^>]*>(.*?)</h1>", text, re.S)
    assert m, f"{doc}.html has no <h1>"
    inner = re.sub(r'<span class="section-number">.*?</span>', "", m.group(1))
    inner = re.sub(r'<a class="headerlink".*?</a>', "", inner, flags=re.S)
    return html_lib.unescape(re.sub(r"<[^>]+>", "", inner)).strip()


@pytest.fixture(scope="module")
def pdf(html_root) -> Pdf:
    if not PDF.is_file():
        pytest.skip(f"no {PDF.relative_to(ROOT)}: make it with `python tools/make_pdf.py` after the build")
    return Pdf(PDF)


@pytest.fixture(scope="module")
def pdf_text(pdf) -> list[str]:
    return pdf.text()


def test_every_download_menu_links_the_pdf(pdf):
    """Every page with a download menu (the book's pages and the API reference; not Sphinx's
    index and search pages) links the PDF there (``book/_ext/pdf_download.py``), and the link
    resolves to it (``test_html.py`` leaves these links out: the PDF is printed while it runs)."""
    pages = {p: p.read_text(encoding="utf-8") for p in HTML.rglob("*.html")
             if not {"_static", "_sources", "_images", "_downloads"} & set(p.relative_to(HTML).parts[:-1])}
    pages = {p: text for p, text in pages.items() if "dropdown-download-buttons" in text}
    assert len(pages) > 100, f"only {len(pages)} pages with a download menu"
    missing = []
    for page, text in pages.items():
        refs = re.findall(r'href="([^"#?]*rotorlyap-book\.pdf)"', text)
        if not refs or any((page.parent / unquote(r)).resolve() != PDF.resolve() for r in refs):
            missing.append(f"{page.relative_to(HTML)}: {refs or 'no link'}")
    assert not missing, f"{len(missing)} pages without a link to {PDF.name}: {missing[:10]}"


def test_the_pdf_counts_its_sheets(pdf, pdf_text):
    n = pdf.page_count()
    docs = _toc_docs()
    assert n >= len(docs), f"{n} sheets for {len(docs)} pages of the book (each starts a sheet)"
    # every sheet's footer says "k / n", in order
    for k, text in enumerate(pdf_text, 1):
        assert f"{k}/{n}" in _norm(text), f"sheet {k} of {n}: no footer '{k} / {n}' in {text[-200:]!r}"


def test_every_chapter_title_is_in_the_pdf_in_reading_order(pdf_text):
    docs = _toc_docs()
    assert "book/api" in docs and any(d.startswith("book/api/") for d in docs), docs
    sheets = [_norm(t) for t in pdf_text]
    at = 0
    for doc in docs:
        title = _title(doc)
        key = _norm(title)
        assert key, f"{doc}: empty title"
        # each page of the book starts a sheet with its title (after its chapter number; the
        # references' floated labels "[Glauert, 1926][Johnson, 1980]..." are painted, so
        # written, before it)
        starts = re.compile(r"(\[[^\]]*\])*(\d+\.)?" + re.escape(key))
        found = next((k for k in range(at, len(sheets)) if starts.match(sheets[k])), None)
        assert found is not None, (f"{doc}: no sheet after sheet {at + 1} starts with its title {title!r} "
                                   f"(sheet {at + 1} starts {pdf_text[at][:120]!r})")
        at = found + 1


def test_the_pdf_reader_refuses_what_is_not_a_pdf(tmp_path):
    from pdf_text import PdfError

    bad = tmp_path / "x.pdf"
    bad.write_bytes(b"<html>not a pdf</html>")
    with pytest.raises(PdfError, match="%PDF"):
        Pdf(bad)
