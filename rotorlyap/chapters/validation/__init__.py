"""Figures of the chapter "Validation and beyond": a data function and a drawing function each.

The conventions every chapter's module follows (data objects, ``summary()``, ``facts()``,
``plot_*`` and ``figure_*``) are in :mod:`rotorlyap.chapters`. The chain is

1. :func:`~rotorlyap.chapters.validation.steady.steady_motions`: the true periodic motion of
   every case at every advance ratio (:func:`rotorlyap.model.steady.periodic_motion`), computed
   once and reused;
2. :func:`~rotorlyap.chapters.validation.steady.floquet_data`: Floquet modes about it and about
   the hover equilibrium (:mod:`rotorlyap.analysis.floquet`);
3. :func:`~rotorlyap.chapters.validation.scan.scan_data`: the engine's verdict on a (psi, mu)
   grid for several Liapunov functions and steady motions
   (:data:`~rotorlyap.chapters.validation.scan.CANDIDATES`): the certificate counterpart of the
   paper's Fig. 8;
4. :func:`~rotorlyap.chapters.validation.simulations.validation_data`: simulated motions against
   those verdicts (:mod:`rotorlyap.methods.validation`);
5. :func:`~rotorlyap.chapters.validation.motions.motion_data`: what the motion does where a
   reading marks instability.

Beside them, the chapter's smaller computations:
:func:`~rotorlyap.chapters.validation.steady.inflow_data` (the distance of the hover equilibrium
from the periodic motion with two inflow models),
:func:`~rotorlyap.chapters.validation.steady.fold_data` (the end of the backward-C.G. branch),
:func:`~rotorlyap.chapters.validation.functions.quadratic_data` (the quadratic Liapunov
functions), :func:`~rotorlyap.chapters.validation.functions.origin_data` (``W'`` near the
origin), :func:`~rotorlyap.chapters.validation.checks.search_check` (the certificates with a
finer search), :func:`~rotorlyap.chapters.validation.simulations.validation_set` (every simulated
motion of the chapter), :func:`~rotorlyap.chapters.validation.motions.flutter_cycle` and
:func:`~rotorlyap.chapters.validation.motions.far_motion` (the limit cycle and the distant
periodic motion of the long simulations).

The chapter's modules, whose names this package re-exports (``from rotorlyap.chapters import
validation as fv``): :mod:`~rotorlyap.chapters.validation.common` (the cases and grids),
:mod:`~rotorlyap.chapters.validation.steady` (sections 1 and 2: the steady motions, inflow, fold,
Floquet), :mod:`~rotorlyap.chapters.validation.functions` (the quadratic functions, ``W'`` near
the origin), :mod:`~rotorlyap.chapters.validation.scan` (section 3, the scans),
:mod:`~rotorlyap.chapters.validation.checks` (the certificates checked: finer search, one cell's
system, the rule changed), :mod:`~rotorlyap.chapters.validation.simulations` (section 4, the
validation set) and :mod:`~rotorlyap.chapters.validation.motions` (section 5, the motions, the
flutter cycle). The scans' container and figure, shared with chapter 8, are in
:mod:`rotorlyap.chapters.scans`.
"""

from ..scans import SCAN_CATEGORY_NAMES, ScanData, figure_scan, plot_scan, scan_legend_handles
from .common import CASES, MU_FLOQUET, MU_SCAN, SCAN_OPTIONS, grid_summary, max_distance
from .steady import (FloquetData, FoldData, InflowData, SteadyMotions, figure_floquet, figure_steady_motions,
                     floquet_data, floquet_legend_handles, fold_data, inflow_data, plot_floquet, plot_steady_motions,
                     settings_facts, steady_motions)
from .functions import OriginData, QuadraticData, figure_origin, origin_data, plot_origin, quadratic_data
from .scan import CANDIDATES, Candidate, scan_data
from .checks import CellSystem, RuleChanges, SearchCheck, cell_system, rule_changes, search_check
from .simulations import (CONFUSION_HEADER, ValidationData, confusion_rows, figure_validation, plot_validation,
                          validation_data, validation_set)
from .motions import (FarMotion, FlutterCycle, MotionData, far_motion, figure_motions, flutter_cycle, motion_data,
                      plot_motions, points_per_revolution)

__all__ = [
    "CASES", "MU_FLOQUET", "MU_SCAN", "CANDIDATES", "Candidate", "SCAN_CATEGORY_NAMES",
    "CONFUSION_HEADER", "grid_summary", "max_distance", "SteadyMotions", "steady_motions",
    "plot_steady_motions", "figure_steady_motions", "InflowData", "inflow_data", "FoldData",
    "fold_data", "FloquetData", "floquet_data", "plot_floquet", "figure_floquet",
    "floquet_legend_handles", "QuadraticData", "quadratic_data", "OriginData", "origin_data",
    "plot_origin", "figure_origin", "ScanData", "scan_data", "plot_scan", "figure_scan",
    "scan_legend_handles", "SCAN_OPTIONS", "CellSystem", "cell_system", "RuleChanges",
    "rule_changes", "SearchCheck", "search_check", "validation_data", "confusion_rows",
    "plot_validation", "ValidationData", "validation_set", "figure_validation", "MotionData",
    "motion_data", "plot_motions", "figure_motions", "points_per_revolution", "FlutterCycle",
    "flutter_cycle", "FarMotion", "far_motion", "settings_facts"
]
