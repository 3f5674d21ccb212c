"""The bibliography and the citations of the book agree (issue 42).

``book/references.md`` lists every entry of ``references.bib`` (``:all:``), so an entry that
no page cites is a reference the reader cannot place, and a citation key missing from the file
is a broken link. The paper itself was once listed twice under two keys; entries whose details
were "from memory, not re-checked" were listed as if checked.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
BOOK = ROOT / "book"

ENTRY = re.compile(r"@(\w+)\s*\{\s*([^,\s]+)\s*,", re.MULTILINE)
CITE = re.compile(r"\{cite(?::[a-z]+)?\}`([^`]+)`")


def bib_entries(text: str) -> dict[str, str]:
    """{key: body} of every entry of a BibTeX file (the body up to the next entry)."""
    matches = list(ENTRY.finditer(text))
    return {m.group(2): text[m.end(): (matches[i + 1].start() if i + 1 < len(matches) else len(text))]
            for i, m in enumerate(matches)}


def title_of(body: str) -> str:
    """An entry's title, lower case, letters and digits only (braces and accents dropped)."""
    m = re.search(r"^\s*title\s*=\s*\{(.*?)\},?\s*$", body, re.MULTILINE | re.DOTALL)
    return re.sub(r"[^a-z0-9]", "", m.group(1).lower()) if m else ""


def page_texts() -> dict[str, str]:
    """{page: text} of the book's MyST pages and of the notebooks' markdown cells and Markdown
    outputs (a glued table may cite)."""
    texts = {p.name: p.read_text(encoding="utf-8") for p in sorted(BOOK.glob("*.md"))}
    for nb_path in sorted(BOOK.glob("*.ipynb")):
        nb = json.loads(nb_path.read_text(encoding="utf-8"))
        parts = []
        for cell in nb["cells"]:
            if cell["cell_type"] == "markdown":
                parts.append("".join(cell["source"]))
            for out in cell.get("outputs", []):
                for mime, data in out.get("data", {}).items():
                    if mime.endswith("text/markdown"):
                        parts.append("".join(data) if isinstance(data, list) else str(data))
        texts[nb_path.name] = "\n".join(parts)
    return texts


def cited_keys(texts: dict[str, str]) -> dict[str, set[str]]:
    """{key: pages citing it}."""
    keys: dict[str, set[str]] = {}
    for page, text in texts.items():
        for group in CITE.findall(text):
            for key in group.split(","):
                keys.setdefault(key.strip(), set()).add(page)
    return keys


@pytest.fixture(scope="module")
def bib() -> dict[str, str]:
    return bib_entries((ROOT / "references.bib").read_text(encoding="utf-8"))


@pytest.fixture(scope="module")
def cited() -> dict[str, set[str]]:
    return cited_keys(page_texts())


def test_the_parser_finds_entries_and_citations():
    """The helpers themselves: a two-entry file and a page with a grouped and a role citation."""
    text = "@book{a1,\n  title = {One {T}itle},\n}\n\n@article{b2,\n  title = {Two},\n}\n"
    entries = bib_entries(text)
    assert list(entries) == ["a1", "b2"] and title_of(entries["a1"]) == "onetitle"
    assert cited_keys({"p": "see {cite}`a1,b2` and {cite:p}`c3`"}) == {"a1": {"p"}, "b2": {"p"}, "c3": {"p"}}


def test_the_references_page_lists_every_entry(bib):
    """The premise of the next test: the page shows the whole file."""
    assert ":all:" in (BOOK / "references.md").read_text(encoding="utf-8")
    assert len(bib) > 20


def test_every_citation_key_exists_in_the_bibliography(bib, cited):
    missing = {key: sorted(pages) for key, pages in cited.items() if key not in bib}
    assert not missing, f"citations of keys not in references.bib: {missing}"


def test_every_listed_entry_is_cited_somewhere_in_the_book(bib, cited):
    uncited = sorted(set(bib) - set(cited))
    assert not uncited, f"entries shown on the references page that no page cites: {uncited}"


def test_no_entry_duplicates_another_entrys_title(bib):
    seen: dict[str, str] = {}
    for key, body in bib.items():
        title = title_of(body)
        assert title, f"{key} has no title"
        assert title not in seen, f"{key} repeats the title of {seen[title]}"
        seen[title] = key


def test_no_entry_is_marked_unchecked_as_if_it_were_checked(bib):
    """An entry whose details were not verified says so plainly; "from memory" is not a label
    a reader can act on."""
    for key, body in bib.items():
        assert "from memory" not in body.lower(), key
