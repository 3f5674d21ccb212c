"""Regenerate the data (CSV) and pictures (PNG) of the paper's Figs 4-8 into a folder.

Used by ``python -m rotorlyap figures --out DIR``. Each figure calls the same data and
drawing functions as the book (:mod:`rotorlyap.chapters.hover` and
:mod:`rotorlyap.chapters.forward_flight`), laid out and checked for legibility there, so the
files match the book's figures (with coarser grids under ``quick=True``); Fig 8 shows one
reading per file, its cases two to a row with the category legend.
"""

from __future__ import annotations

from pathlib import Path
from typing import Callable

import numpy as np

__all__ = ["regenerate_figures"]


def regenerate_figures(out: Path, *, quick: bool = False,
                       progress: Callable[[int, int, str], None] | None = None) -> list[Path]:
    """Compute and save Figs 4-8 (one PNG and one CSV each; Fig 8 for both readings).

    Parameters
    ----------
    out : pathlib.Path
        Output folder (must exist).
    quick : bool
        Coarse grids (a smoke test in seconds; the pictures are then not the book's).
    progress : callable, optional
        ``progress(i, n, label)`` called before each figure.

    Returns
    -------
    list of pathlib.Path
        The files written.
    """
    import matplotlib

    matplotlib.use("Agg")

    from . import forward_flight, hover
    from .cases import CASES, MU_GRID, MU_GRID_STRICT
    from .export import figure_csv

    out = Path(out)
    n_psi = 12 if quick else 72
    cg_sweep = np.linspace(0.21, 0.28, 3 if quick else 8)
    mu_grid = (0.0, 0.15, 0.25) if quick else MU_GRID
    mu_strict = (0.0, 0.25) if quick else MU_GRID_STRICT
    mu7 = (0.0, 0.15, 0.25) if quick else (0.0, 0.05, 0.1, 0.15, 0.2, 0.25)
    cases = ("forward",) if quick else CASES

    def fig4():
        data = hover.hover_trim_data(cg_sweep)
        return {"fig4_hover_trim": (data, hover.figure_hover_trim(data))}

    def fig5():
        data = hover.hover_rate_data(cg_sweep)
        return {"fig5_hover_rate": (data, hover.figure_hover_rate(data))}

    def fig6():
        data = forward_flight.w_spheres_data("forward", 0.15, (0.5, 1.0, 2.0, 4.0, 8.0), n_psi=n_psi)
        return {"fig6_w_spheres": (data, forward_flight.figure_w_spheres(data))}

    def fig7():
        data = forward_flight.rate_azimuth_data("forward", mu7, n_psi=n_psi)
        return {"fig7_rate_azimuth": (data, forward_flight.figure_rate_azimuth(data))}

    def fig8():
        made = {}
        for reading, mus in (("practical", mu_grid), ("strict", mu_strict)):
            data = forward_flight.regions_data(cases, mus, reading=reading, n_psi=n_psi)
            # the cases two to a row, with the category legend (in the spare cell, or below)
            made[f"fig8_regions_{reading}"] = (data, forward_flight.figure_regions_polar(data))
        return made

    steps = [("Fig 4: hover trim", fig4), ("Fig 5: W' in hover against C.G.", fig5),
             ("Fig 6: W over spheres at mu = 0.15", fig6), ("Fig 7: W' against azimuth", fig7),
             ("Fig 8: regions of instability, both readings", fig8)]
    written: list[Path] = []
    for i, (label, make) in enumerate(steps, start=1):
        if progress is not None:
            progress(i, len(steps), label)
        for name, (data, fig) in make().items():
            png = out / f"{name}.png"
            # the whole figure, nothing clipped: tick labels and legends outside the axes included
            fig.savefig(png, dpi=120, bbox_inches="tight")
            written += [png, Path(figure_csv(data, out / f"{name}.csv"))]
    return written
