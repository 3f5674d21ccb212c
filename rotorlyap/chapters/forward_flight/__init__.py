"""Chapter 6 of the book, forward flight (``book/06_forward_flight.ipynb``, the paper's Figs
6-8): the loads the reused hover equilibrium leaves unbalanced, ``W`` on spheres, ``W'``
against the azimuth, the regions of instability in both readings, the hover flutter check,
the practical threshold, the sensitivity and convergence of Fig. 8, and the claims table.

Data functions return frozen dataclasses of arrays (no plotting) and take their grids as
arguments, so that the notebooks, the benchmark and the tests can choose the resolution;
drawing functions (``plot_*``) take that data and matplotlib ``Axes``, and ``figure_*``
functions create, draw, lay out and return the whole figure of the chapter (closed in pyplot,
so that a notebook shows it only where it is glued). The data objects have a ``summary()``
(the text the chapter prints, rounded to the digits the computation determines) and a
``facts()`` (the numbers the chapter quotes, ``{glue name: value}``, for
:func:`rotorlyap.chapters.export.glue_facts`). Every quantity computed in a reading carries
that reading's label, :data:`rotorlyap.chapters.cases.READING_LABELS`. The cases and their
parameters, Fig. 8's grids and the energy-balanced norm scales, which chapter 5 and the
command line share or the book cites there, are in
:mod:`rotorlyap.chapters.cases`.

Conventions (``.notes/BLADE_SPEC.md``): azimuth ``psi = 0`` with the blade pointing aft
(over the tail), rotation counter-clockwise seen from above, so ``psi = 90 deg`` is the
advancing side and ``psi = 270 deg`` the retreating side.

The chapter's modules, whose names this package re-exports (``from rotorlyap.chapters import
forward_flight``): :mod:`~rotorlyap.chapters.forward_flight.loads` (the unbalanced loads,
``W`` on spheres and ``W'`` against the azimuth: the paper's Figs 6 and 7),
:mod:`~rotorlyap.chapters.forward_flight.regions` (the region maps of Fig. 8 with their
categories, legend and reverse-flow mark, and the hover flutter check),
:mod:`~rotorlyap.chapters.forward_flight.checks` (the practical threshold, the sensitivity and
the convergence of Fig. 8, with the test-disturbance sets) and
:mod:`~rotorlyap.chapters.forward_flight.claims` (the claims table).
"""

from ..cases import CASES, MU_GRID, MU_GRID_STRICT, balanced_scales
from .loads import (RateAzimuthData, UnbalancedLoadsData, WSpheresData, figure_rate_azimuth, figure_w_spheres,
                    plot_rate_azimuth, plot_w_spheres, rate_azimuth_data, unbalanced_loads_data, w_spheres_data)
from .regions import (CATEGORY_NAMES, REVERSE_FLOW_HATCH, HoverFlutterCheck, RegionMaps, RegionsData,
                      category_legend_handles, figure_regions_plane, figure_regions_polar, hover_flutter_check,
                      plot_regions_plane, plot_regions_polar, region_maps, regions_data, reverse_flow_boundary)
from .checks import (AXES_AND_DIAGONALS, CONVERGENCE_N_REFINE, FLAP_LAG_TEST_DISTURBANCES, THRESHOLD_TEST_SETS,
                     ConvergenceData, SensitivityData, ThresholdData, convergence_data,
                     figure_convergence, figure_sensitivity, plot_convergence, plot_sensitivity,
                     practical_threshold_data, practical_threshold_mu, sensitivity_data)
from .claims import CLAIMS_HEADER, ClaimsTable, claims_table, markdown_table, myst_math

__all__ = [
    "CASES", "MU_GRID", "MU_GRID_STRICT",
    "UnbalancedLoadsData", "unbalanced_loads_data",
    "WSpheresData", "w_spheres_data", "plot_w_spheres", "figure_w_spheres",
    "RateAzimuthData", "rate_azimuth_data", "plot_rate_azimuth", "figure_rate_azimuth",
    "CATEGORY_NAMES", "REVERSE_FLOW_HATCH", "reverse_flow_boundary", "category_legend_handles",
    "RegionsData", "regions_data", "plot_regions_polar", "plot_regions_plane",
    "RegionMaps", "region_maps", "figure_regions_polar", "figure_regions_plane",
    "HoverFlutterCheck", "hover_flutter_check",
    "FLAP_LAG_TEST_DISTURBANCES", "AXES_AND_DIAGONALS", "balanced_scales",
    "THRESHOLD_TEST_SETS", "practical_threshold_mu", "ThresholdData", "practical_threshold_data",
    "SensitivityData", "sensitivity_data", "plot_sensitivity", "figure_sensitivity",
    "ConvergenceData", "CONVERGENCE_N_REFINE", "convergence_data", "plot_convergence", "figure_convergence",
    "CLAIMS_HEADER", "ClaimsTable", "myst_math", "claims_table",
    "markdown_table",
]
