"""Words that mean one thing (issue 42): a lint of the book's prose and printed outputs.

The book's terms (book/notation.md): a *numerical certificate* rests on a search attacked by
the falsifier; a *proof* rests on enclosures (ball arithmetic, Taylor models); the paper's rule
is an *indicator*. So

* "rigorous" and "guarantee(d)" appear only in a sentence about a proof (it names a proof,
  an enclosure, Taylor models or ball arithmetic) or in a negation ("no general guarantee"),
  or in a sentence of :data:`ALLOWED`, each with its reason;
* the paper's rule never "certifies";
* printed outputs carry no template words: no Python ``None``, no "(s)" plurals, no
  percentage printed as zero with decimals ("0.0 %": below the printed precision it is
  "< 0.05 %", :func:`rotorlyap.reporting.percent`).

Identifiers are not prose: code spans, MyST roles and labels (``fig-certificate-scan``) and
directive options are removed before the check.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
BOOK = ROOT / "book"

FORBIDDEN = re.compile(r"\b(rigorous(?:ly)?|guarantee[sd]?|guaranteeing)\b", re.IGNORECASE)
ABOUT_A_PROOF = re.compile(r"\b(proofs?|prove[sdn]?|proving|enclosures?|Taylor models?|ball arithmetic)\b",
                           re.IGNORECASE)
NEGATED = re.compile(r"\b(no|not|never|nor|without)\b(?:\W+\w+){0,3}?\W+(rigorous|guarantee)", re.IGNORECASE)
PAPER_RULE_CERTIFIES = re.compile(r"paper's (?:rule|algorithm),?\s+(?:\w+ly\s+)?certif(?:y|ies|ied)\b",
                                  re.IGNORECASE)
TEMPLATE_NONE = re.compile(r"\bNone\b")
TEMPLATE_PLURAL = re.compile(r"\w\(s\)")
ZERO_PERCENT = re.compile(r"(?<![\d.])0\.0+ ?%")

ALLOWED = {
    ("10_proofs.ipynb", "made rigorous by Gershgorin"):
        "part of a proof: floating-point eigenvalues enclosed by Gershgorin's theorem",
}
"""(page, part of the sentence) -> why the sentence may use a forbidden word."""


def strip_identifiers(text: str) -> str:
    """Prose only: code spans, MyST roles with their targets, labels and directive options out."""
    text = re.sub(r"\{[a-z:]+\}`[^`]*`", " ", text)          # {numref}`fig-certificate-scan`
    text = re.sub(r"```\{?[\w:-]*\}?[^\n]*", " ", text)       # directive openings
    text = re.sub(r"`[^`\n]*`", " ", text)                    # code spans
    text = re.sub(r"^\s*:[\w-]+:.*$", " ", text, flags=re.MULTILINE)   # :name: fig-...
    text = re.sub(r"^\([\w-]+\)=\s*$", " ", text, flags=re.MULTILINE)  # (label)=
    return text


def sentences(text: str) -> list[str]:
    """The sentences of a text, each on one line (blank lines and sentence ends split)."""
    out = []
    for para in re.split(r"\n\s*\n", text):
        flat = " ".join(para.split())
        out.extend(s for s in re.split(r"(?<=[.!?:;])\s+(?=[A-Z*(])", flat) if s)
    return out


def notebook_texts(path: Path) -> tuple[str, str]:
    """(markdown cells, printed outputs) of a notebook: streams and Markdown/plain text results."""
    nb = json.loads(path.read_text(encoding="utf-8"))
    prose, printed = [], []
    for cell in nb["cells"]:
        if cell["cell_type"] == "markdown":
            prose.append("".join(cell["source"]))
        for out in cell.get("outputs", []):
            if out.get("output_type") == "stream":
                printed.append("".join(out["text"]))
            for mime, data in out.get("data", {}).items():
                if mime.endswith(("text/markdown", "text/plain")):
                    printed.append("".join(data) if isinstance(data, list) else str(data))
    return "\n\n".join(prose), "\n\n".join(printed)


def pages() -> dict[str, tuple[str, str]]:
    """{page: (prose, printed outputs)} of every notebook and MyST page of the book."""
    found = {p.name: notebook_texts(p) for p in sorted(BOOK.glob("*.ipynb"))}
    found.update({p.name: (p.read_text(encoding="utf-8"), "") for p in sorted(BOOK.glob("*.md"))})
    return found


def forbidden_sentences(page: str, text: str) -> list[str]:
    """Sentences of ``text`` that use "rigorous" or "guarantee" outside a proof or a negation."""
    bad = []
    for s in sentences(strip_identifiers(text)):
        if not FORBIDDEN.search(s) or ABOUT_A_PROOF.search(s) or NEGATED.search(s):
            continue
        if any(page == p and part in s for p, part in ALLOWED):
            continue
        bad.append(s)
    return bad


def test_the_rule_fires_on_the_defects_of_issue_42_and_not_on_proofs_or_negations():
    """The lint itself, on the sentences the issue quoted and on sentences it must let pass."""
    fired = [
        "## The rigorous Fig. 8",
        "In hover, a flap disturbance of up to 0.5 deg is guaranteed to keep the motion within "
        "1.68 deg of flap for ever.",
        "the bounds the two certificates guarantee",
    ]
    passed = [
        "The Taylor-model proof is rigorous: every rounding error is enclosed.",
        "It is no general guarantee: a sampled search can miss a narrow region.",
        "The book never calls it rigorous; only a proof is.",
        "the quadratic function in the strict reading ({numref}`fig-certificate-scan`).",
    ]
    for s in fired:
        assert forbidden_sentences("x.md", s) == [s.strip()] or forbidden_sentences("x.md", s), s
    for s in passed:
        assert forbidden_sentences("x.md", s) == [], s
    assert PAPER_RULE_CERTIFIES.search("The paper's rule certifies 5 of the 24 azimuths")
    assert not PAPER_RULE_CERTIFIES.search("the paper's rule is an indicator, not a certificate")
    assert not PAPER_RULE_CERTIFIES.search("azimuths that pass the paper's rule or are certified by the sound rule")
    assert PAPER_RULE_CERTIFIES.search("the start regions the paper's rule certifies (blue)")
    assert TEMPLATE_NONE.search("`inflow_ratio` | None | -") and not TEMPLATE_NONE.search("none (0)")
    assert TEMPLATE_PLURAL.search("at 1 advance ratio(s) of the grid")
    assert ZERO_PERCENT.search("changes by at most 0.0 %") and ZERO_PERCENT.search("0.00 %")
    assert not ZERO_PERCENT.search("< 0.05 %") and not ZERO_PERCENT.search("10.0 %")


PAGES = pages()


@pytest.mark.parametrize("page", sorted(PAGES))
def test_rigorous_and_guaranteed_only_for_proofs(page):
    prose, printed = PAGES[page]
    bad = forbidden_sentences(page, prose) + forbidden_sentences(page, printed)
    assert not bad, f"{page}: 'rigorous'/'guarantee' outside a proof (a numerical certificate is neither): {bad}"


@pytest.mark.parametrize("page", sorted(PAGES))
def test_the_papers_rule_never_certifies(page):
    prose, printed = PAGES[page]
    hits = [s for s in sentences(strip_identifiers(prose + "\n\n" + printed)) if PAPER_RULE_CERTIFIES.search(s)]
    assert not hits, f"{page}: the paper's rule is an indicator, it does not certify: {hits}"


@pytest.mark.parametrize("page", sorted(p for p in PAGES if p.endswith(".ipynb")))
def test_printed_outputs_carry_no_template_words(page):
    _, printed = PAGES[page]
    for name, pattern in (("Python None", TEMPLATE_NONE), ("'(s)' plural", TEMPLATE_PLURAL),
                          ("zero per cent with decimals", ZERO_PERCENT)):
        hits = [line.strip() for line in printed.splitlines() if pattern.search(line)]
        assert not hits, f"{page}: {name} in printed output: {hits}"


@pytest.mark.parametrize("page", sorted(PAGES))
def test_prose_carries_no_template_plurals_or_zero_percentages(page):
    prose, _ = PAGES[page]
    text = strip_identifiers(prose)
    for name, pattern in (("'(s)' plural", TEMPLATE_PLURAL), ("zero per cent with decimals", ZERO_PERCENT)):
        hits = [line.strip() for line in text.splitlines() if pattern.search(line)]
        assert not hits, f"{page}: {name}: {hits}"


INDICATOR_STABLE = re.compile(r"\b(?:indicated stable|every azimuth stable|pairs? stable|azimuths? stable)\b",
                              re.IGNORECASE)


def test_the_indicator_rule_fires_on_the_printouts_of_issue_42():
    assert INDICATOR_STABLE.search("inflow glauert , 12 axes : every azimuth stable up to mu = 1e-07")
    assert INDICATOR_STABLE.search("reproduced: 216 of 216 (case, azimuth) pairs stable")
    assert INDICATOR_STABLE.search("indicated stable (practical reading, not a certificate) at 24 of 24 azimuths")
    assert not INDICATOR_STABLE.search("passes at every azimuth below mu = 0.0015")
    assert not INDICATOR_STABLE.search("what linear theory calls stable")


@pytest.mark.parametrize("page", sorted(p for p in PAGES if p.endswith(".ipynb")))
def test_printed_outputs_never_call_the_indicators_verdict_stable(page):
    """An azimuth where the paper's rule holds *passes* (book/notation.md, "Indicator")."""
    _, printed = PAGES[page]
    hits = [line.strip() for line in printed.splitlines() if INDICATOR_STABLE.search(line)]
    assert not hits, f"{page}: the indicator passes, it does not find 'stable': {hits}"
