"""Chapter 6 of the book, forward flight (``book/06_forward_flight.ipynb``, the paper's Figs
6-8): the loads the reused hover equilibrium leaves unbalanced, ``W`` on spheres, ``W'``
against the azimuth, the regions of instability in both readings, the hover flutter check,
the practical threshold, the sensitivity and convergence of Fig. 8, and the claims table.

The conventions every chapter's module follows (data objects, ``summary()``, ``facts()``,
``plot_*`` and ``figure_*``) are in :mod:`rotorlyap.chapters`. Every quantity computed in a reading carries
that reading's label, :data:`rotorlyap.chapters.cases.READING_LABELS`. The cases and their
parameters, Fig. 8's grids and the energy-balanced norm scales, which chapter 5 and the
command line share or the book cites there, are in
:mod:`rotorlyap.chapters.cases`.

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
