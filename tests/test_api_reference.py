"""The book's API reference documents every public module of the package: a module added to
``rotorlyap/`` without its page (``book/api.md`` links one page per module, which
``book/_ext/api_pages.py`` writes at build time with the module's ``automodule`` entry) would be
missing from the pages a reader looks the names up in."""

import importlib.util
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]

#: Public modules the reference leaves out, with the reason (none since issue 42: the float-ball
#: module ``rotorlyap.methods.balls`` has its page, written by ``book/_ext/api_pages.py``'s
#: ``SPECIAL`` entries).
LEFT_OUT: set = set()


def _public_modules() -> set[str]:
    names = set()
    for path in (ROOT / "rotorlyap").rglob("*.py"):
        parts = path.relative_to(ROOT).with_suffix("").parts
        if any(p.startswith("_") for p in parts):  # __init__, __main__, _checks, _generated, ...
            continue
        names.add(".".join(parts))
    return names


def _api_pages():
    """The book's page generator (``book/_ext/api_pages.py``), imported from its file."""
    spec = importlib.util.spec_from_file_location("api_pages", ROOT / "book" / "_ext" / "api_pages.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules.setdefault("api_pages", module)
    spec.loader.exec_module(module)
    return module


def _documented(tmp_path) -> set[str]:
    """Modules with an ``automodule`` entry in the pages the build would write (written to a
    copy of the overview under ``tmp_path``) and in the overview itself."""
    api_pages = _api_pages()
    (tmp_path / "book").mkdir()
    overview = (ROOT / "book" / "api.md").read_text(encoding="utf-8")
    (tmp_path / "book" / "api.md").write_text(overview, encoding="utf-8")
    pages = api_pages.write_pages(tmp_path)
    text = overview + "".join(p.read_text(encoding="utf-8") for p in pages)
    return {line.split("::", 1)[1].strip() for line in text.splitlines()
            if line.strip().startswith((".. automodule::", ".. py:module::"))}


def test_every_public_module_has_an_automodule_entry(tmp_path):
    documented = _documented(tmp_path)
    missing = sorted(_public_modules() - documented - LEFT_OUT)
    assert not missing, f"modules without a page (a line in book/api.md) in the API reference: {missing}"
    assert "rotorlyap.methods.band" in documented  # the check sees sub-packages' modules
    assert LEFT_OUT <= _public_modules()  # a module left out still exists
    assert "rotorlyap.methods.balls" in documented


def test_each_module_page_holds_only_its_module(tmp_path):
    api_pages = _api_pages()
    documented = _documented(tmp_path)
    pages = sorted((tmp_path / "book" / "api").glob("*.md"))
    assert len(pages) == len(documented - {"rotorlyap", "rotorlyap.methods", "rotorlyap.model",
                                            "rotorlyap.analysis", "rotorlyap.chapters"})
    for page in pages:
        text = page.read_text(encoding="utf-8")
        entries = [line for line in text.splitlines() if "automodule::" in line or "py:module::" in line]
        assert entries in ([f".. automodule:: {page.stem}"], [f".. py:module:: {page.stem}"]), page.name
        # every name documented on a page is the page's module's own
        for line in text.splitlines():
            if line.startswith((".. autoclass::", ".. autofunction::", ".. autodata::")):
                assert line.split("::", 1)[1].strip().startswith(page.stem + "."), (page.name, line)
    # the float-ball class is documented once, on its own module's page (not again under intervals)
    intervals = (tmp_path / "book" / "api" / "rotorlyap.methods.intervals.md").read_text(encoding="utf-8")
    balls = (tmp_path / "book" / "api" / "rotorlyap.methods.balls.md").read_text(encoding="utf-8")
    assert ":exclude-members: Balls" in intervals and ".. autoclass:: rotorlyap.methods.balls.Balls" in balls
    # a page whose module the overview no longer links is removed; a file not generated stays
    (tmp_path / "book" / "api" / "rotorlyap.gone.md").write_text(api_pages.MARK + "\n# gone\n")
    (tmp_path / "book" / "api" / "notes.md").write_text("# a person's file\n")
    api_pages.write_pages(tmp_path)
    assert not (tmp_path / "book" / "api" / "rotorlyap.gone.md").exists()
    assert (tmp_path / "book" / "api" / "notes.md").exists()


def test_bad_overview_lines_are_refused():
    api_pages = _api_pages()
    with pytest.raises(Exception, match="not the page's module"):
        api_pages.linked_modules("- {doc}`rotorlyap.a <api/rotorlyap.b>`: A")
    with pytest.raises(Exception, match="linked twice"):
        api_pages.linked_modules("- {doc}`rotorlyap.a <api/rotorlyap.a>`: A\n"
                                 "- {doc}`rotorlyap.a <api/rotorlyap.a>`: A")
    with pytest.raises(ValueError, match="description"):
        api_pages.page_text("rotorlyap.a", "")
