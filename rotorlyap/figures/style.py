"""The figures' shared style: one colour per hinge, per C.G. case and per verdict, in every chapter.

A reader who has learnt that flap is blue in chapter 3 finds it blue in chapter 7 too; the
verdict maps of chapters 6 and 7 use the same colours for the same categories.
"""

from __future__ import annotations

__all__ = ["CATEGORY_COLORS", "CG_COLORS", "CG_ROMAN", "HINGE_COLORS", "SCAN_EXTRA_COLORS", "figure", "finish", "subplots"]

HINGE_COLORS = {"flap": "tab:blue", "lag": "tab:green", "pitch": "tab:red"}
"""Colour of each hinge (and of the modes named after it)."""

CG_COLORS = {"forward": "tab:green", "neutral": "0.3", "backward": "tab:purple"}
"""Colour of each Table I C.G. case."""

CG_ROMAN = {"forward": "I", "neutral": "II", "backward": "III"}
"""The paper's numbering of the C.G. cases."""

CATEGORY_COLORS = ("#4daf4a", "#ff7f00", "#fdd0a2", "#d7301f")
"""Colours of the four verdicts of a region map: stable; stable only in the bound's shell;
the practical reading's 'stable' where W' > 0 somewhere; unstable (rotorlyap.figures.paper.CATEGORY_NAMES)."""

SCAN_EXTRA_COLORS = ("#969696", "#f0f0f0")
"""Two more categories of the validation scans: no quadratic function (unstable linearisation)
and no periodic motion found."""


def subplots(*args, **kwargs):
    """``matplotlib.pyplot.subplots``, the figure closed in pyplot at once.

    Made by pyplot, the figure is drawn by the current backend (in a notebook, pyplot's import
    turns on the inline display that renders it where it is glued); closed at once, it is
    returned to the caller and never shown by itself. Returns ``(figure, axes)``.
    """
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(*args, **kwargs)
    plt.close(fig)
    return fig, axes


def figure(**kwargs):
    """``matplotlib.pyplot.figure``, closed in pyplot at once (see :func:`subplots`)."""
    import matplotlib.pyplot as plt

    fig = plt.figure(**kwargs)
    plt.close(fig)
    return fig


def finish(fig, **layout):
    """Lay out a figure made by :func:`subplots` or :func:`figure` (``tight_layout(**layout)``)
    and return it."""
    fig.tight_layout(**layout)
    return fig
