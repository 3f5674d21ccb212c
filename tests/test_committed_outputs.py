"""The committed notebook outputs follow the rule of what may be printed (README, "What a
committed output may print"; :mod:`rotorlyap.reporting`).

nbval compares these outputs as text with a fresh execution on the reader's machine. A digit
that only one machine reproduces (round-off, an unrounded float, a memory address) makes that
comparison fail elsewhere, and an image compared byte by byte fails for the same reason; a
notebook committed without outputs, out of order or with an error compares nothing. These
tests read the committed files only; they execute nothing.
"""

from __future__ import annotations

import json
import re
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOKS = sorted((ROOT / "book").glob("*.ipynb"))
sys.path.insert(0, str(ROOT / "book" / "_ext"))
from notebook_execution import IMAGE_MIMES  # noqa: E402

from rotorlyap.reporting import ROUNDOFF_FLOOR, format_small, format_small_array  # noqa: E402

TEXT_MIMES = ("text/plain", "text/markdown", "text/latex", "text/html",
              "application/papermill.record/text/plain", "application/papermill.record/text/markdown")
"""Output MIME types compared as text."""

_NUMBER = re.compile(r"(?<![\w.])[-+]?(\d+\.?\d*|\.\d+)(?:[eE]([-+]?\d+))?(?![\w.])")
_BOUND = re.compile(r"(<|<=|≤|below|under|less than)\s*$")


def _code_cells(path: Path) -> list[dict]:
    nb = json.loads(path.read_text(encoding="utf-8"))
    return [c for c in nb["cells"] if c["cell_type"] == "code"]


def _texts(cell: dict):
    """(label, text) of every text output of a code cell."""
    for out in cell.get("outputs", []):
        if out.get("output_type") == "stream":
            yield out.get("name", "stream"), "".join(out.get("text", ""))
        for mime, value in out.get("data", {}).items():
            if mime in TEXT_MIMES:
                yield mime, "".join(value) if isinstance(value, list) else str(value)


def roundoff_numbers(text: str) -> list[str]:
    """Numbers in ``text`` smaller in magnitude than ``ROUNDOFF_FLOOR`` (but not zero) that are
    not stated as a bound (preceded by ``<``, ``below``, ...)."""
    found = []
    for m in _NUMBER.finditer(text):
        value = float(m.group(0))
        if value != 0.0 and abs(value) < ROUNDOFF_FLOOR and not _BOUND.search(text[max(0, m.start() - 12):m.start()]):
            found.append(m.group(0))
    return found


def unrounded_numbers(text: str, max_digits: int = 9) -> list[str]:
    """Decimal numbers with more than ``max_digits`` significant digits (unrounded floats)."""
    found = []
    for m in _NUMBER.finditer(text):
        mantissa = m.group(1)
        if "." not in mantissa:
            continue
        digits = mantissa.replace(".", "").lstrip("0")
        if len(digits) > max_digits:
            found.append(m.group(0))
    return found


def test_the_scanners_catch_what_the_rule_forbids_and_pass_what_it_allows():
    # raw round-off: the residuals that broke the comparison on another machine (issue 10)
    assert roundoff_numbers("relative residual 2.6e-15") == ["2.6e-15"]
    assert roundoff_numbers("residual: [6e-13 5e-08]") == ["6e-13"]
    assert roundoff_numbers("tiny 0.00000000000042") == ["0.00000000000042"]
    # bounds and ordinary results pass
    assert roundoff_numbers(f"relative residual {format_small(2.6e-15)}") == []
    assert roundoff_numbers(format_small_array([6e-13, 5e-8, float("nan")])) == []
    assert roundoff_numbers("growth -0.1446/rev, A = 1, mu = 1e-07, 0.0") == []
    # unrounded floats
    assert unrounded_numbers("x = 0.30000000000000004") == ["0.30000000000000004"]
    assert unrounded_numbers("lambda0 in [0.2623, 0.2959], 1234567.5") == []


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_committed_outputs_print_no_roundoff_unrounded_float_or_address(path):
    problems = []
    for k, cell in enumerate(_code_cells(path)):
        for label, text in _texts(cell):
            for kind, found in (("raw round-off-level number", roundoff_numbers(text)),
                                ("unrounded float", unrounded_numbers(text)),
                                ("memory address", re.findall(r"\bat 0x[0-9a-fA-F]{6,}", text))):
                if found:
                    problems.append(f"cell {k} ({label}): {kind} {found[:3]}")
    assert not problems, (f"{path.name} prints digits that change from machine to machine; print a "
                          "bound (rotorlyap.reporting.format_small) or round:\n  " + "\n  ".join(problems))


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_committed_notebook_was_executed_once_top_to_bottom_without_errors(path):
    cells = [c for c in _code_cells(path) if "".join(c["source"]).strip()]
    counts = [c.get("execution_count") for c in cells]
    assert counts == list(range(1, len(cells) + 1)), (
        f"{path.name}: execution counts {counts}: execute it from a fresh kernel, top to bottom "
        "(python tools/run_notebooks.py), and commit it with its outputs")
    errors = [k for k, c in enumerate(cells) if any(o.get("output_type") == "error" for o in c.get("outputs", []))]
    assert not errors, f"{path.name}: cells {errors} stored an error"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_every_output_is_compared_as_text_or_is_an_image_nbval_skips(path):
    unknown = {mime for cell in _code_cells(path) for out in cell.get("outputs", [])
               for mime in out.get("data", {}) if mime not in TEXT_MIMES + IMAGE_MIMES}
    assert not unknown, (f"{path.name}: output MIME types {sorted(unknown)} are neither compared as text "
                         "nor skipped as images: add them to TEXT_MIMES here or to IMAGE_MIMES in "
                         "book/_ext/notebook_execution.py")


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_every_glued_figure_carries_its_image(path):
    """A figure glued without pyplot's inline backend is stored as text only ("<Figure ...>")
    and silently missing from the book; nbval, which never compares images, cannot see it."""
    missing = []
    for k, cell in enumerate(_code_cells(path)):
        for out in cell.get("outputs", []):
            data = out.get("data", {})
            text = "".join(data.get("application/papermill.record/text/plain", ""))
            if text.startswith("<Figure") and "application/papermill.record/image/png" not in data:
                missing.append(f"cell {k}: {out.get('metadata', {}).get('scrapbook', {}).get('name')}")
    assert not missing, f"{path.name}: glued figures without an image: {missing}"


CODE_SHARE_LIMIT = 0.25
"""Largest share of a chapter's source characters that is code: the chapters are prose with
calls into the package (QuantEcon's lectures: 13-23 %)."""

CODE_IS_THE_LESSON = {"09_your_own_blade.ipynb": 0.35}
"""Chapters whose code a reader is meant to copy: chapter 11 shows the package's API on a
blade of the reader's own."""


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_chapters_are_prose_with_calls_into_the_package(path):
    nb = json.loads(path.read_text(encoding="utf-8"))
    size = {kind: sum(len("".join(c["source"])) for c in nb["cells"] if c["cell_type"] == kind)
            for kind in ("code", "markdown")}
    share = size["code"] / (size["code"] + size["markdown"])
    limit = CODE_IS_THE_LESSON.get(path.name, CODE_SHARE_LIMIT)
    assert share <= limit, (f"{path.name}: code is {share:.0%} of the chapter (limit {limit:.0%}): move the "
                            "logic into its rotorlyap.chapters module (facts(), summary(), a figure function)")
    private = sorted({m.group(0) for c in nb["cells"] if c["cell_type"] == "code"
                      for m in re.finditer(r"\b[a-z_][a-z0-9_]*\._[a-zA-Z]\w*", "".join(c["source"]))})
    assert not private, f"{path.name} uses private names of the package: {private}"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_code_is_hidden_where_it_is_not_the_lesson_and_glue_is_never_shown(path):
    """A reader of the HTML sees prose, tables and figures: in a chapter whose code is not the
    lesson every code cell is hidden behind a toggle (``hide-input``) or removed
    (``remove-input``); in every chapter a cell shown as it is never calls ``glue`` (gluing numbers
    for the text is bookkeeping, done in a removed cell)."""
    nb = json.loads(path.read_text(encoding="utf-8"))
    shown = [c for c in nb["cells"] if c["cell_type"] == "code"
             and not {"hide-input", "remove-input", "remove-cell"} & set(c.get("metadata", {}).get("tags", []))]
    if path.name not in CODE_IS_THE_LESSON:
        assert not shown, f"{path.name}: {len(shown)} code cells shown (tag them hide-input or remove-input)"
    glued = [k for k, c in enumerate(shown) if re.search(r"\bglue(_facts)?\(", "".join(c["source"]))]
    assert not glued, f"{path.name}: shown code cells call glue: {glued}"


PRINTED_ARRAY = re.compile(r"\[\s*[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?(\s+[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?){2,}\s*\]?")
"""A numpy array as ``print`` writes it: three or more numbers in brackets, separated by blanks."""


def printed_arrays(text: str) -> list[str]:
    """The numpy arrays printed in ``text`` (:data:`PRINTED_ARRAY`)."""
    return [m.group(0) for m in PRINTED_ARRAY.finditer(text)]


def test_the_array_scanner_finds_numpy_arrays_and_not_prose():
    assert printed_arrays("mu: [0.   0.05 0.1  0.15]") == ["[0.   0.05 0.1  0.15]"]
    assert printed_arrays("C.G.: [0.2   0.21  0.215 0.22  0.23") != []  # wrapped at numpy's line width
    assert printed_arrays("forward C.G. at 0.215 c, stable [see (a)]; a list [1, 2, 3]") == []


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_printed_arrays_are_not_shown_as_prose(path):
    """A printed numpy array is the numeric summary nbval checks a figure by, not something a reader
    reads: its cell's output is collapsed behind a toggle (``hide-output``) or removed; what the
    reader needs of it is in the figure and, glued, in the text."""
    nb = json.loads(path.read_text(encoding="utf-8"))
    shown = []
    for k, c in enumerate(nb["cells"]):
        tags = set(c.get("metadata", {}).get("tags", []))
        if c["cell_type"] != "code" or {"hide-output", "remove-output", "remove-cell"} & tags:
            continue
        found = [a for _, text in _texts(c) for a in printed_arrays(text)]
        if found:
            shown.append(f"cell {k}: {found[0][:50]}")
    assert not shown, f"{path.name}: printed arrays shown on the page (tag the cells hide-output): {shown}"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_markdown_outputs_are_rendered_as_myst(path):
    """A cell that displays Markdown (a table, math) carries ``mystnb.markdown_format: myst``:
    myst-nb's default renders outputs as plain CommonMark, which shows a table as raw pipes."""
    nb = json.loads(path.read_text(encoding="utf-8"))
    plain = [k for k, c in enumerate(nb["cells"]) if c["cell_type"] == "code"
             and any("text/markdown" in o.get("data", {}) for o in c.get("outputs", []))
             and c.get("metadata", {}).get("mystnb", {}).get("markdown_format") != "myst"]
    assert not plain, f"{path.name}: cells {plain} display Markdown without mystnb.markdown_format = myst"
