"""A link to the PDF of the whole book in every page's download menu.

The PDF is printed by headless Chromium from the built HTML after the build
(``tools/make_pdf.py``, called by ``.ci/run``; no LaTeX) and written to
:data:`PDF_PATH` inside ``_build/html``. This extension adds an entry for it, first, to the
sphinx-book-theme's download dropdown of every page (the theme fills ``header_buttons`` at
``html-page-context``, priority 501; this runs after it). The theme's own ".pdf" entry
(``window.print()``, the one page) is kept, renamed so that the two are told apart.
The browser test fails if the linked file is missing (every relative link must resolve).
"""

from __future__ import annotations

from sphinx.application import Sphinx

PDF_PATH = "_downloads/rotorlyap-book.pdf"
"""Where ``tools/make_pdf.py`` writes the book's PDF, relative to the HTML output folder."""


def _add_pdf_button(app: Sphinx, pagename: str, templatename: str, context: dict, doctree) -> None:
    for group in context.get("header_buttons") or []:
        if group.get("label") != "download-buttons":
            continue
        buttons = group.setdefault("buttons", [])
        for button in buttons:
            if button.get("label") == "download-pdf-button":
                button["text"] = ".pdf (this page)"
        buttons.insert(0, {
            "type": "link",
            "url": context["pathto"](PDF_PATH, 1),
            "text": "book .pdf",
            "tooltip": "Download the whole book as one PDF",
            "icon": "fas fa-book",
            "label": "download-book-pdf-button",
        })


def setup(app: Sphinx):
    """Add the entry after the theme made the dropdown (priority 600 > 501)."""
    app.connect("html-page-context", _add_pdf_button, priority=600)
    return {"version": "1.0", "parallel_read_safe": True, "parallel_write_safe": True}
