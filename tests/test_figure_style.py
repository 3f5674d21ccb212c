"""The figures' legibility rule (rotorlyap.chapters.style) and that every figure obeys it.

Facts checked: the displayed size of a font follows from the figure's width and the book's
column (a 14 in figure shrunk to 672 px shows 8 pt at 5.3 px); the checker refuses small text
and overlapping labels and accepts a figure that keeps to the rule; every function of the
package that makes a figure passes it through ``finish`` (which runs the checker), so a figure
that breaks the rule cannot reach the book.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

import rotorlyap.chapters as figures_pkg
from rotorlyap.chapters.style import (MIN_TEXT_PX, PAGE_WIDTH_PX, CATEGORY_COLORS, CATEGORY_HATCHES,
                                     FigureLayoutError, check_legible, enlarge_small_text, finish,
                                     max_width_in, use_retina_inline,
                                     shown_text_px, subplots)


def test_displayed_font_size_follows_from_width_and_column():
    # full size below the column width: 8 pt at 100 dpi is 11.1 px
    assert shown_text_px(8, 5.0) == pytest.approx(8 / 72 * 100)
    # a 14 in figure is shrunk to the 672 px column: 8 pt -> 8/72*672/14 = 5.33 px
    assert shown_text_px(8, 14.0) == pytest.approx(8 / 72 * PAGE_WIDTH_PX / 14)
    # the widest figure for a given smallest font shows it at exactly the minimum
    assert shown_text_px(7, max_width_in(7)) == pytest.approx(MIN_TEXT_PX)
    with pytest.raises(ValueError, match="positive"):
        shown_text_px(8, 0)
    with pytest.raises(ValueError, match="at least"):
        max_width_in(4)


def test_small_text_in_a_wide_figure_is_refused_with_the_fix():
    fig, ax = subplots(figsize=(14, 3))
    ax.plot([0, 1], [0, 1])
    ax.set_xlabel("azimuth (deg)", fontsize=8)
    fig.tight_layout()
    with pytest.raises(FigureLayoutError, match=r"use at least .* pt here, or make the figure at most"):
        check_legible(fig)


def test_finish_raises_small_text_to_the_rule_and_leaves_large_text():
    fig, ax = subplots(figsize=(14, 3))
    ax.plot([0, 1], [0, 1])
    ax.set_xlabel("azimuth (deg)", fontsize=8)
    ax.set_title("a title", fontsize=30)
    finish(fig)
    assert check_legible(fig) >= MIN_TEXT_PX - 1e-9
    assert ax.xaxis.label.get_fontsize() > 8
    assert ax.title.get_fontsize() == 30
    # a figure already legible is not touched
    fig2, ax2 = subplots(figsize=(4, 3))
    ax2.set_xlabel("x", fontsize=10)
    assert enlarge_small_text(fig2) == 0 and ax2.xaxis.label.get_fontsize() == 10
    with pytest.raises(ValueError, match="round"):
        enlarge_small_text(fig2, rounds=0)


def test_retina_is_selected_only_inside_a_kernel():
    # a plain Python process (the tests) has no IPython shell: nothing is changed
    from IPython.core.interactiveshell import InteractiveShell
    if InteractiveShell.initialized():
        pytest.skip("an IPython shell is running in this process")
    assert use_retina_inline() is False


def test_a_figure_for_the_column_passes():
    fig, axes = subplots(1, 2, figsize=(7.5, 3))
    for ax in axes:
        ax.plot([0, 1], [0, 1], label="flap")
        ax.set_xlabel("azimuth (deg)")
        ax.legend(fontsize=8)
    assert check_legible(finish(fig)) >= MIN_TEXT_PX


def test_overlapping_labels_are_refused():
    fig, ax = subplots(figsize=(5, 3))
    ax.text(0.5, 0.5, r"$+\theta'$")
    ax.text(0.5, 0.5, r"$-\theta'$")
    with pytest.raises(FigureLayoutError, match="overlap"):
        finish(fig)


def test_every_category_has_a_second_cue():
    # the stable verdict may be plain; the others differ from one another in hatch as well as colour
    assert len(set(CATEGORY_HATCHES)) == len(CATEGORY_HATCHES) == len(CATEGORY_COLORS)
    assert len(set(CATEGORY_COLORS)) == len(CATEGORY_COLORS)


def _calls(node) -> set[str]:
    out = set()
    for n in ast.walk(node):
        if isinstance(n, ast.Call):
            f = n.func
            out.add(f.id if isinstance(f, ast.Name) else f.attr if isinstance(f, ast.Attribute) else "")
    return out


def test_every_figure_of_the_package_goes_through_finish():
    """A function that makes a figure (``subplots(...)``/``figure(...)``/``plt.subplots``) returns it
    through ``finish``, which checks it; a plotting helper that receives axes makes none."""
    offenders = []
    for path in sorted(Path(figures_pkg.__file__).parent.rglob("*.py")):  # with the validation package
        if path.name == "style.py":
            continue
        tree = ast.parse(path.read_text())
        for fn in ast.walk(tree):
            if isinstance(fn, ast.FunctionDef):
                calls = _calls(fn)
                if calls & {"subplots", "figure"} and "finish" not in calls:
                    offenders.append(f"{path.name}:{fn.lineno} {fn.name}")
    assert not offenders, "figures made without finish (not checked for legibility): %s" % offenders
