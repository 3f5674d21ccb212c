"""The bibliography's labels in the form of the book's citations (issue 42).

The text cites author-year (``bibtex_reference_style: author_year``, "[Narkiewicz and
Lucjanek, 1989]"), but pybtex's ``plain`` style numbers the list ([1], [2], ...), so a reader
cannot find a citation in the list, and "reference [4]" of the paper's own list read as the
book's [4]. This extension registers the pybtex style ``plain_author_year``: the ``plain``
style, entries sorted by their labels, with the label "Author, year", "A and B,
year" or "A et al., year", as the citations print it; without an author the title stands in,
without a year "n.d.". Two entries with the same label get "a", "b" after the year.
"""

from __future__ import annotations

from collections import Counter

import pybtex.plugin
from pybtex.richtext import Text
from pybtex.style.formatting import toplevel
from pybtex.style.formatting.plain import Style as PlainStyle
from pybtex.style.formatting.unsrt import date, pages
from pybtex.style.labels import BaseLabelStyle
from pybtex.style.sorting import BaseSortingStyle
from pybtex.style.template import field, first_of, join, optional, optional_field, sentence, tag, words


def _plain_text(latex: str) -> str:
    """A BibTeX field (braces, accents) as plain text."""
    return Text.from_latex(latex).render_as("text")


class AuthorYearLabelStyle(BaseLabelStyle):
    """Labels "Last, year", "Last and Last, year", "Last et al., year"."""

    def format_label(self, entry) -> str:
        persons = entry.persons.get("author") or entry.persons.get("editor") or []
        names = [_plain_text(" ".join(p.prelast_names + p.last_names)) for p in persons]
        if not names:
            who = _plain_text(entry.fields.get("title", entry.key))
        elif len(names) == 1:
            who = names[0]
        elif len(names) == 2:  # "A and others" too, as sphinxcontrib-bibtex's citations print it
            who = f"{names[0]} and {names[1]}"
        else:
            who = f"{names[0]} et al."
        year = _plain_text(entry.fields.get("year", "")) or "n.d."
        return f"{who}, {year}"

    def format_labels(self, sorted_entries):
        labels = [self.format_label(e) for e in sorted_entries]
        count = Counter(labels)
        seen: Counter = Counter()
        for label in labels:
            if count[label] > 1:
                seen[label] += 1
                yield label + "abcdefghijklmnopqrstuvwxyz"[seen[label] - 1]
            else:
                yield label


class AuthorYearSortingStyle(BaseSortingStyle):
    """Entries in the order of their labels, case aside (then title): an entry without an author,
    labelled by its title, stands where its label does, not before every other entry."""

    def sorting_key(self, entry):
        return (AuthorYearLabelStyle().format_label(entry).casefold(), entry.fields.get("title", ""))


class Style(PlainStyle):
    """pybtex's ``plain`` style with :class:`AuthorYearLabelStyle` labels, and an article's
    volume and number shown when its pages are not known (``plain`` drops them)."""

    default_label_style = AuthorYearLabelStyle

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self.label_style = AuthorYearLabelStyle()
        self.format_labels = self.label_style.format_labels
        self.sorting_style = AuthorYearSortingStyle()
        self.sort = self.sorting_style.sort

    def get_article_template(self, e):
        volume_and_pages = first_of[
            optional[join[field("volume"), optional["(", field("number"), ")"], ":", pages]],
            optional[join[field("volume"), optional["(", field("number"), ")"]]],
            words["pages", pages],
        ]
        return toplevel[
            self.format_names("author"),
            self.format_title(e, "title"),
            sentence[tag("em")[field("journal")], optional[volume_and_pages], date],
            sentence[optional_field("note")],
            self.format_web_refs(e),
        ]


pybtex.plugin.register_plugin("pybtex.style.formatting", "plain_author_year", Style)


def setup(app):
    """Nothing to set up beyond the registration at import (before sphinxcontrib.bibtex reads
    ``bibtex_default_style``)."""
    return {"parallel_read_safe": True, "parallel_write_safe": True}
