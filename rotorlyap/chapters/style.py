"""The figures' shared style and the rules that keep them legible in the book.

Colours: one per hinge, per C.G. case and per verdict, in every chapter, so that a reader who
has learnt that flap is blue in chapter 3 finds it blue in chapter 7 too. They are taken from
the Okabe-Ito palette (Okabe & Ito 2008, "Color Universal Design"), which stays distinct for
the common forms of colour-blindness; categories carry a second cue as well (a hatch pattern
for the verdict maps, a marker for the C.G. cases), so that a map also reads in grey print.

Size: the book shows a figure in its text column, :data:`PAGE_WIDTH_PX` pixels wide (the
sphinx-book-theme column at the 1280 px window of the browser test), shrinking any figure that
is wider. A font of ``f`` points in a figure saved at :data:`BOOK_DPI` and ``w`` inches wide is
therefore shown ``f / 72 * min(BOOK_DPI, PAGE_WIDTH_PX / w)`` pixels high; :func:`finish`
refuses a figure whose smallest text would be shown below :data:`MIN_TEXT_PX`, or whose
annotations overlap, so every figure of the package is checked each time it is made. Before it
checks, :func:`finish` raises any text below the rule to the smallest font the figure's width
allows (:func:`enlarge_small_text`), so the rule is kept here, once, not in each figure.
The browser test checks the same rule on the published pages from the images' own size,
resolution and displayed width.

Resolution: one inch of a figure is :data:`BOOK_DPI` CSS pixels, and the notebooks render it at
twice that many device pixels (:data:`DEVICE_PIXEL_RATIO`, IPython's ``retina`` PNG: an image
:data:`BOOK_DPI` x 2 dots per inch whose declared width is half its pixel width), so figures stay
sharp on screens with two device pixels per CSS pixel. :func:`subplots` and :func:`figure` select
that format in a running IPython kernel (:func:`use_retina_inline`); nothing is set per notebook.
"""

from __future__ import annotations

import numpy as np

__all__ = [
    "BOOK_DPI", "CATEGORY_COLORS", "CATEGORY_HATCHES", "CG_COLORS", "CG_MARKERS", "CG_ROMAN",
    "HINGE_COLORS", "HINGE_LINESTYLES", "MIN_FONT_PT", "MIN_TEXT_PX", "PAGE_WIDTH_PX",
    "SCAN_EXTRA_COLORS", "SCAN_EXTRA_HATCHES", "HATCH_COLOR", "HATCH_LINEWIDTH", "FigureLayoutError",
    "DEVICE_PIXEL_RATIO", "check_legible", "draw_categories", "enlarge_small_text", "figure",
    "finish", "max_width_in", "shown_text_px", "subplots", "use_retina_inline",
]

# Okabe-Ito palette
_BLUE, _ORANGE, _SKY, _GREEN, _YELLOW, _VERMILLION, _PURPLE = (
    "#0072B2", "#E69F00", "#56B4E9", "#009E73", "#F0E442", "#D55E00", "#CC79A7")

HINGE_COLORS = {"flap": _BLUE, "lag": _GREEN, "pitch": _VERMILLION}
"""Colour of each hinge (and of the modes named after it)."""

HINGE_LINESTYLES = {"flap": "-", "lag": "--", "pitch": "-."}
"""Line style of each hinge, the second cue where the three hinges share a panel."""

CG_COLORS = {"forward": _GREEN, "neutral": "0.3", "backward": _PURPLE}
"""Colour of each Table I C.G. case."""

CG_MARKERS = {"forward": "o", "neutral": "s", "backward": "^"}
"""Marker of each Table I C.G. case, the second cue to its colour."""

CG_ROMAN = {"forward": "I", "neutral": "II", "backward": "III"}
"""The paper's numbering of the C.G. cases."""

CATEGORY_COLORS = (_GREEN, _SKY, _YELLOW, _VERMILLION)
"""Colours of the four verdicts of a region map: stable; stable only in the bound's shell;
the practical reading's 'stable' where W' > 0 somewhere; unstable
(rotorlyap.chapters.forward_flight.regions.CATEGORY_NAMES)."""

CATEGORY_HATCHES = ("", "//", "..", "xx")
"""Hatch pattern of each verdict of :data:`CATEGORY_COLORS` (none for 'stable')."""

SCAN_EXTRA_COLORS = ("#999999", "#FFFFFF")
"""Two more categories of the validation scans: no quadratic function (unstable linearisation)
and no periodic motion found."""

SCAN_EXTRA_HATCHES = ("\\\\", "--")
"""Hatch pattern of each category of :data:`SCAN_EXTRA_COLORS`."""

HATCH_COLOR = "0.15"
"""Colour of the hatch lines of the verdict maps and their legends."""

HATCH_LINEWIDTH = 0.6
"""Width of the hatch lines, points."""


def draw_categories(ax, x_edges, y_edges, category, colors, hatches) -> None:
    """A verdict map: each cell of ``category`` (integers, shape (len(y_edges) - 1,
    len(x_edges) - 1)) in the colour ``colors[k]`` and the hatch ``hatches[k]`` of its category
    ``k``, the hatch drawn cell by cell (straight edges, as ``pcolormesh`` draws the cells, in
    polar axes too) so that it follows the cells exactly."""
    from matplotlib.collections import PolyCollection
    from matplotlib.colors import BoundaryNorm, ListedColormap

    n = len(colors)
    ax.pcolormesh(x_edges, y_edges, category, cmap=ListedColormap(colors),
                  norm=BoundaryNorm(np.arange(-0.5, n + 0.5), n), shading="flat")
    x_edges, y_edges, cat = np.asarray(x_edges), np.asarray(y_edges), np.asarray(category)
    for k, hatch in enumerate(hatches):
        rows, cols = np.nonzero(cat == k)
        if not hatch or rows.size == 0:
            continue
        x0, x1 = x_edges[cols], x_edges[cols + 1]
        y0, y1 = y_edges[rows], y_edges[rows + 1]
        verts = np.stack([np.column_stack(v) for v in ((x0, y0), (x1, y0), (x1, y1), (x0, y1))], axis=1)
        cells = PolyCollection(verts, facecolors="none", edgecolors="none", linewidths=0.0, hatch=hatch,
                               hatchcolor=HATCH_COLOR)
        cells.set_hatch_linewidth(HATCH_LINEWIDTH)
        ax.add_collection(cells, autolim=False)


PAGE_WIDTH_PX = 672
"""Width of the book's text column, CSS pixels, at a 1280 px browser window (measured by the
browser test); a wider figure is shrunk to it."""

BOOK_DPI = 100.0
"""CSS pixels per inch of a figure in the book (matplotlib-inline's default resolution); one inch
is shown :data:`BOOK_DPI` CSS pixels wide where the figure is not shrunk."""

DEVICE_PIXEL_RATIO = 2
"""Device pixels per CSS pixel of the figures the notebooks render: their PNGs are saved at
``DEVICE_PIXEL_RATIO * BOOK_DPI`` dots per inch and declared half as wide (IPython's ``retina``
format), sharp on a 2x screen."""

MIN_TEXT_PX = 9.0
"""Smallest height, CSS pixels, of a font as displayed in the book (issue 42: legends of 7 px
could not be read)."""

MIN_FONT_PT = MIN_TEXT_PX * 72.0 / BOOK_DPI
"""Smallest font, points, that any figure may use: :data:`MIN_TEXT_PX` at full size (6.48 pt); a
figure wider than the column needs larger fonts (:func:`max_width_in`)."""


class FigureLayoutError(ValueError):
    """A figure that would not be legible in the book: text too small at its displayed width,
    or overlapping annotations."""


def shown_text_px(font_pt: float, width_in: float, dpi: float = BOOK_DPI,
                  page_width_px: float = PAGE_WIDTH_PX) -> float:
    """Height, CSS pixels, at which a font of ``font_pt`` points is shown in the book in a figure
    ``width_in`` inches wide saved at ``dpi``: ``font_pt / 72 * min(dpi, page_width_px / width_in)``."""
    if font_pt <= 0 or width_in <= 0 or dpi <= 0 or page_width_px <= 0:
        raise ValueError("shown_text_px needs positive sizes, got font %r pt, width %r in, dpi %r, "
                         "page %r px" % (font_pt, width_in, dpi, page_width_px))
    return font_pt / 72.0 * min(dpi, page_width_px / width_in)


def max_width_in(smallest_font_pt: float) -> float:
    """Widest figure, inches, whose ``smallest_font_pt`` text is still shown at
    :data:`MIN_TEXT_PX` in the book (for 8 pt: 8.3 in; for 7 pt: 7.3 in)."""
    if smallest_font_pt < MIN_FONT_PT:
        raise ValueError("a %.2f pt font is below %.2f px even at full size; use at least %.2f pt"
                         % (smallest_font_pt, MIN_TEXT_PX, MIN_FONT_PT))
    return smallest_font_pt * PAGE_WIDTH_PX / (72.0 * MIN_TEXT_PX)


def _texts(fig):
    """The visible, non-empty texts of ``fig`` with a short name for messages."""
    from matplotlib.text import Text

    out = []
    for t in fig.findobj(Text):
        if not t.get_visible() or not t.get_text().strip():
            continue
        ax = t.axes
        if ax is not None and not ax.get_visible():
            continue
        out.append(t)
    return out


def _annotations(fig):
    """Texts placed by hand (``ax.text``, ``annotate``, ``fig.text``), axis labels and titles:
    those that can collide; tick labels and legends are laid out by matplotlib."""
    items = list(fig.texts)
    if getattr(fig, "_suptitle", None) is not None:
        items.append(fig._suptitle)
    for ax in fig.axes:
        if not ax.get_visible():
            continue
        items.extend(ax.texts)
        items.extend([ax.title, ax._left_title, ax._right_title, ax.xaxis.label, ax.yaxis.label])
    return [t for t in items if t.get_visible() and t.get_text().strip()]


def check_legible(fig, *, overlap_px: float = 1.0) -> float:
    """Check that ``fig`` is legible at the size the book shows it; return its smallest text's
    displayed height (CSS px).

    The figure's width is that of its tight bounding box (what the notebook saves); each visible
    text's displayed height is :func:`shown_text_px` of its font. Texts placed by hand, axis
    labels and titles must not overlap one another by more than ``overlap_px`` pixels either way.

    Raises
    ------
    FigureLayoutError
        Naming the smallest offending text, its font and the largest font size or width that
        would pass; or the two overlapping texts.
    """
    fig.draw_without_rendering()
    renderer = fig._get_renderer()
    width_in = fig.get_tightbbox(renderer).width + 0.2  # bbox_inches="tight" pads 0.1 in a side
    texts = _texts(fig)
    if not texts:
        return np.inf
    smallest = min(texts, key=lambda t: t.get_fontsize())
    px = shown_text_px(smallest.get_fontsize(), width_in)
    if px < MIN_TEXT_PX - 1e-9:
        need = MIN_TEXT_PX * 72.0 / min(BOOK_DPI, PAGE_WIDTH_PX / width_in)
        raise FigureLayoutError(
            "text %r at %.1f pt in a figure %.1f in wide is shown %.1f px high in the book's %d px "
            "column; the smallest text must be %.1f px: use at least %.1f pt here, or make the "
            "figure at most %.1f in wide"
            % (smallest.get_text()[:40], smallest.get_fontsize(), width_in, px, PAGE_WIDTH_PX,
               MIN_TEXT_PX, need, max_width_in(max(smallest.get_fontsize(), MIN_FONT_PT))))
    placed = _annotations(fig)
    boxes = [t.get_window_extent(renderer) for t in placed]
    for i in range(len(placed)):
        for j in range(i + 1, len(placed)):
            a, b = boxes[i], boxes[j]
            dx = min(a.x1, b.x1) - max(a.x0, b.x0)
            dy = min(a.y1, b.y1) - max(a.y0, b.y0)
            if dx > overlap_px and dy > overlap_px:
                raise FigureLayoutError("texts %r and %r overlap (%.0f x %.0f px)"
                                        % (placed[i].get_text()[:40], placed[j].get_text()[:40], dx, dy))
    return px


def use_retina_inline() -> bool:
    """Select IPython's ``retina`` PNG (:data:`DEVICE_PIXEL_RATIO` device pixels per CSS pixel)
    for every figure a running IPython kernel displays or glues; return whether a kernel was
    running (outside one nothing is changed).

    The choice is made on the inline backend's configuration (``InlineBackend.figure_formats``),
    which IPython applies again whenever the backend is activated, so a later ``%matplotlib
    inline`` keeps it.
    """
    try:
        from IPython.core.interactiveshell import InteractiveShell
    except ImportError:  # no IPython: nothing displays figures inline
        return False
    if not InteractiveShell.initialized():
        return False
    from matplotlib_inline.config import InlineBackend

    cfg = InlineBackend.instance()
    if set(cfg.figure_formats) != {"retina"}:
        cfg.figure_formats = {"retina"}
    return True


def _min_font_pt(width_in: float) -> float:
    """Smallest font, points, shown at :data:`MIN_TEXT_PX` in a figure ``width_in`` inches wide
    (rounded up to 0.1 pt)."""
    return float(np.ceil(MIN_TEXT_PX * 72.0 / min(BOOK_DPI, PAGE_WIDTH_PX / width_in) * 10.0 - 1e-6) / 10.0)


def _shown_width_in(fig) -> float:
    """Width, inches, of what the notebook saves of ``fig`` (its tight bounding box, padded)."""
    fig.draw_without_rendering()
    return fig.get_tightbbox(fig._get_renderer()).width + 0.2  # bbox_inches="tight" pads 0.1 in a side


def enlarge_small_text(fig, *, layout=None, rounds: int = 4) -> int:
    """Raise every visible text of ``fig`` shown below :data:`MIN_TEXT_PX` in the book to the
    smallest font that reaches it at the figure's width; return how many texts were changed.

    A larger font can widen the figure (a legend beside the axes, long tick labels), which
    shrinks it in the column, so the width is measured again after each round (``layout``, a
    callable taking the figure, lays it out again before each measurement) for at most
    ``rounds`` rounds. Texts already large enough are left as they are.
    """
    if rounds < 1:
        raise ValueError("enlarge_small_text needs at least one round, got %r" % (rounds,))
    changed = set()
    for _ in range(rounds):
        need = _min_font_pt(_shown_width_in(fig))
        small = [t for t in _texts(fig) if t.get_fontsize() < need - 1e-9]
        if not small:
            break
        for t in small:
            t.set_fontsize(need)
            changed.add(id(t))
        if layout is not None:
            layout(fig)
    return len(changed)


def subplots(*args, **kwargs):
    """``matplotlib.pyplot.subplots``, the figure closed in pyplot at once.

    Made by pyplot, the figure is drawn by the current backend (in a notebook, pyplot's import
    turns on the inline display that renders it where it is glued); closed at once, it is
    returned to the caller and never shown by itself. Returns ``(figure, axes)``.
    """
    import matplotlib.pyplot as plt

    use_retina_inline()
    kwargs.setdefault("dpi", BOOK_DPI)
    fig, axes = plt.subplots(*args, **kwargs)
    plt.close(fig)
    return fig, axes


def figure(**kwargs):
    """``matplotlib.pyplot.figure``, closed in pyplot at once (see :func:`subplots`)."""
    import matplotlib.pyplot as plt

    use_retina_inline()
    kwargs.setdefault("dpi", BOOK_DPI)
    fig = plt.figure(**kwargs)
    plt.close(fig)
    return fig


def finish(fig, *, layout: bool = True, **layout_kwargs):
    """Lay out a figure made by :func:`subplots` or :func:`figure` (``tight_layout(**layout_kwargs)``
    unless ``layout`` is False, for a figure laid out otherwise), raise any text below the
    book's smallest size to it (:func:`enlarge_small_text`), check the figure with
    :func:`check_legible` and return it."""
    relayout = (lambda f: f.tight_layout(**layout_kwargs)) if layout else None
    if relayout is not None:
        relayout(fig)
    enlarge_small_text(fig, layout=relayout)
    check_legible(fig)
    return fig
