"""Drop the duplicated inline ``<script>`` blocks Sphinx 7.4 writes into every page.

Sphinx 7.4's HTML builder adds the scripts registered after ``Builder.init()`` a second time
at the start of writing (``registry.js_files`` re-added with ``filename or ''``); for an inline
script, registered with ``filename=None``, the copy has ``''`` and is not recognised as the
same script, so it is written twice. Two such scripts come with Jupyter Book's extensions:
``var togglebuttonSelector = ...`` (harmless twice) and sphinx-thebe's
``const THEBE_JS_URL = ...``, whose second copy throws ``SyntaxError: Identifier
'THEBE_JS_URL' has already been declared`` on every page (found by the browser test,
``tests/browser``). This extension keeps the first of identical scripts on each page.
"""

from __future__ import annotations

from sphinx.application import Sphinx


def _key(js) -> tuple:
    attrs = getattr(js, "attributes", {}) or {}
    return (getattr(js, "filename", js) or "", tuple(sorted((k, str(v)) for k, v in attrs.items())))


def _dedupe(app: Sphinx, pagename: str, templatename: str, context: dict, doctree) -> None:
    scripts = context.get("script_files")
    if not isinstance(scripts, list):
        return
    seen, kept = set(), []
    for js in scripts:
        key = _key(js)
        if key in seen:
            continue
        seen.add(key)
        kept.append(js)
    if len(kept) != len(scripts):
        context["script_files"] = kept


def setup(app: Sphinx) -> dict:
    # late, so that the scripts other handlers add to the page are seen too
    app.connect("html-page-context", _dedupe, priority=900)
    return {"version": "1", "parallel_read_safe": True, "parallel_write_safe": True}
