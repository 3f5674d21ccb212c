"""Figures, tables and printed numbers of the blade-model and Table I chapters.

One data function (returning a frozen dataclass, no plotting) and one drawing function (taking
that data and a matplotlib ``Axes``) per figure panel, as in :mod:`rotorlyap.chapters.theory`,
and one function per figure that creates the whole matplotlib ``Figure`` from the data
(``figure_*``). Every data object a chapter prints or quotes has

* ``summary()``: the text the chapter prints, rounded to the digits the computation
  determines (README, "What a committed output may print");
* ``facts()``: ``{glue name: value}``, the numbers the chapter's text quotes, rounded the same
  way (glued with :func:`rotorlyap.chapters.export.glue_facts`);
* ``markdown()`` for a table, and ``export()`` where the CSV of a figure is not the
  dataclass itself (:func:`rotorlyap.chapters.export.figure_csv`).

Chapter 3, the blade model:

* :func:`schematic_data` with :func:`plot_blade_top_view`, :func:`plot_hub_top_view`,
  :func:`plot_hub_side_view`, :func:`plot_section` and :func:`figure_blade_schematic`: the
  drawn blade (our reading of the paper's lost Fig. 3), dimensions in metres computed from
  the parameters.
* :func:`closed_form_data`, :func:`hinge_balance_data`, :func:`pitch_flap_coupling_data`,
  :func:`pitch_damping_data`: closed-form frequencies, the moments at the hover equilibrium,
  the pitch-flap coupling and the aerodynamic pitch damping of the hover pitch mode.
* :func:`coefficient_data` with :func:`plot_coefficient` and
  :func:`figure_airfoil_coefficients`: airfoil coefficients on the full angle range.
* :func:`angle_of_attack_data` with :func:`plot_angle_of_attack` and
  :func:`figure_angle_of_attack`: section angles of attack along the span at the hover
  equilibrium, in hover and forward flight.
* :func:`generated_code_check`, :func:`positivity_data`: the generated code against sympy,
  and the local positivity of the energy function.

Chapter 4, Table I:

* :func:`markdown_table`, :func:`table_i_rows`, :func:`table_i_markdown`,
  :func:`assumption_rows`, :func:`assumption_data`, :func:`airfoil_table_data`: the Table I,
  assumption and airfoil tables as Markdown.
* :func:`choices_data`: the readings of the missing data (the helicopter, the blade mass,
  "neutral" C.G., the hub element e2).
* :func:`derived_table_data`, :func:`vacuum_modes_data`, :func:`air_modes_data`,
  :func:`hover_stability_data`: derived quantities and hover modes of the three C.G. cases.
* :func:`sensitivity_data`, :func:`variants_data`: hover stability under the two readings
  and switched-off ingredients.
* :func:`cg_sweep_data` with :func:`plot_cg_sweep`, :func:`cg_sweep_pair_data` and
  :func:`figure_cg_sweep`: hover eigenvalues against the chordwise C.G. position, with and
  without the aerodynamic pitch damping.
"""

from __future__ import annotations

import inspect
import math
import re
from collections.abc import Mapping
from dataclasses import dataclass, fields, replace
from typing import Any, Sequence

import numpy as np
from matplotlib.figure import Figure
from matplotlib.patches import Circle, FancyArrowPatch, Polygon, Rectangle

from ..analysis.functions import energy_function
from ..conventions import HINGES
from ..model.airfoil import NACA23012, NACA23012_SOURCES
from ..model.blade import Blade
from ..model.modes import (
    ClosedForms,
    DerivedQuantities,
    Mode,
    chordwise_lag_offset_angle,
    closed_forms,
    derived_quantities,
    hover_modes,
    least_damped,
    pitch_mode,
)
from ..model.parameters import CG_POSITIONS, THIN_AIRFOIL_CM_Q, BladeParameters, parameter_table
from ..reporting import Rounded
from .export import markdown_table as _markdown_table
from .style import CG_COLORS, CG_MARKERS, CG_ROMAN, HINGE_COLORS, figure, finish

__all__ = [
    # chapter 3
    "SchematicData", "schematic_data", "figure_blade_schematic",
    "plot_blade_top_view", "plot_hub_top_view", "plot_hub_side_view", "plot_section",
    "ClosedFormData", "closed_form_data",
    "HingeBalanceData", "hinge_balance_data",
    "PitchFlapCouplingData", "pitch_flap_coupling_data", "effective_flap_frequency",
    "PitchDampingData", "pitch_damping_data", "pitch_damping_estimate",
    "CoefficientData", "coefficient_data", "plot_coefficient", "figure_airfoil_coefficients",
    "AngleOfAttackData", "angle_of_attack_data", "plot_angle_of_attack", "figure_angle_of_attack",
    "GeneratedCodeCheck", "generated_code_check",
    "PositivityData", "positivity_data",
    # chapter 4
    "TABLE_I_LABELS", "format_value", "markdown_table", "table_i_rows", "table_i_markdown",
    "assumption_rows", "AssumptionData", "assumption_data",
    "AirfoilTableData", "airfoil_table_data",
    "ChoicesData", "choices_data", "pitch_axis_reading",
    "HoverCasesData", "DerivedTableData", "derived_table_data",
    "VacuumModesData", "vacuum_modes_data", "AirModesData", "air_modes_data",
    "HoverStabilityData", "hover_stability_data",
    "SensitivityCase", "SensitivityData", "sensitivity_data",
    "VariantsData", "variants_data",
    "CGSweepData", "cg_sweep_data", "plot_cg_sweep",
    "CGSweepPairData", "cg_sweep_pair_data", "figure_cg_sweep",
    "CASE_SHORT", "READINGS", "DAMPINGS", "CG_SWEEP_GRID",
]

#: Short names of the C.G. cases in the glue names of chapter 4 (``ch4_pitch_fwd``).
CASE_SHORT = {"forward": "fwd", "neutral": "neu", "backward": "bwd"}

_NUMBER_WORDS = ("none", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten")


def _how_many(n: int, total: int) -> str:
    """``n`` of ``total`` cases in words, as the text quotes it: "none", "two", "all three"."""
    word = _NUMBER_WORDS[n] if n < len(_NUMBER_WORDS) else str(n)
    return f"all {word}" if n == total and total > 2 else word


def _r3(x: float) -> float:
    """Rounded to 3 decimals, without a negative zero: the value both printed and glued."""
    return round(float(x), 3) + 0.0


def _dash_list(values, decimals: int) -> str:
    """Values to ``decimals`` decimals in brackets, "-" where a value is NaN (none exists)."""
    return "[" + " ".join("-" if not np.isfinite(v) else f"{round(float(v), decimals) + 0.0:.{decimals}f}"
                          for v in np.ravel(values)) + "]"


def _boundary_words(x: float, grid) -> str:
    """A boundary on a C.G. grid in words: "from 0.2564 c", or "none on the grid (0.200 c to
    0.280 c)" when there is none (NaN)."""
    if np.isfinite(x):
        return "from %.4f c" % x
    return "none on the grid (%.3f c to %.3f c)" % (float(np.min(grid)), float(np.max(grid)))


def _r4(x: float) -> float:
    """Rounded to 4 decimals for printing, without a negative zero."""
    return round(float(x), 4) + 0.0


def _kind(m: Mode) -> str:
    """"lag-dominated, real": the dominant hinge and the kind of a mode."""
    return "%s-dominated, %s" % (m.dominant_hinge, "oscillatory" if m.oscillatory else "real")


def _case_name(params: BladeParameters) -> str:
    """"forward C.G." for a Table I C.G. position, else "C.G. 0.24c"."""
    for name, x in CG_POSITIONS.items():
        if isinstance(params.cg_position, float) and params.cg_position == x:
            return f"{name} C.G."
    return "C.G. %.3gc" % float(params.cg_position_at(0.75))

# --------------------------------------------------------------------------------------
# Drawing helpers
# --------------------------------------------------------------------------------------


def _dim(ax, p0, p1, text, *, offset=(0.0, 0.0), text_offset=(0.0, 0.0), color="0.15",
         fontsize=8, ha="center", va="center", rotation=0.0) -> None:
    """A dimension line with arrows at both ends from ``p0`` to ``p1`` (shifted by ``offset``)."""
    a = np.asarray(p0, float) + offset
    b = np.asarray(p1, float) + offset
    ax.add_patch(FancyArrowPatch(a, b, arrowstyle="<|-|>", mutation_scale=7, lw=0.8,
                                 color=color, shrinkA=0, shrinkB=0))
    m = 0.5 * (a + b) + np.asarray(text_offset, float)
    ax.text(m[0], m[1], text, fontsize=fontsize, ha=ha, va=va, color=color, rotation=rotation,
            bbox=dict(boxstyle="round,pad=0.12", fc="white", ec="none", alpha=0.85))


def _arrow(ax, p0, p1, color="k", lw=1.0, style="-|>", scale=9, connectionstyle=None) -> None:
    kw = {} if connectionstyle is None else {"connectionstyle": connectionstyle}
    ax.add_patch(FancyArrowPatch(p0, p1, arrowstyle=style, mutation_scale=scale, lw=lw,
                                 color=color, shrinkA=0, shrinkB=0, **kw))


def _axes_triad(ax, origin, e1, e2, labels, length, color="0.35") -> None:
    o = np.asarray(origin, float)
    for e, lab in zip((e1, e2), labels):
        tip = o + length * np.asarray(e, float)
        _arrow(ax, o, tip, color=color, lw=0.9, scale=7)
        ax.text(*(o + 1.22 * length * np.asarray(e, float)), lab, fontsize=8, color=color,
                ha="center", va="center")


def _airfoil_outline(n: int = 120, thickness: float = 0.12, camber: float = 0.02,
                     camber_at: float = 0.15) -> np.ndarray:
    """Drawing-only section outline (NACA 4-digit thickness with a simple camber line),
    in chord fractions: x from the leading edge (0) to the trailing edge (1), z up."""
    t = 0.5 * (1 - np.cos(np.linspace(0, np.pi, n)))
    yt = 5 * thickness * (0.2969 * np.sqrt(t) - 0.1260 * t - 0.3516 * t**2 + 0.2843 * t**3
                          - 0.1036 * t**4)
    p = camber_at
    yc = np.where(t < p, camber / p**2 * (2 * p * t - t**2),
                  camber / (1 - p) ** 2 * ((1 - 2 * p) + 2 * p * t - t**2))
    upper = np.stack([t, yc + yt], 1)
    lower = np.stack([t, yc - yt], 1)[::-1]
    return np.concatenate([upper, lower])


# --------------------------------------------------------------------------------------
# The schematic (our reading of the lost Fig. 3)
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class SchematicData:
    """Geometry of the blade and hub for the schematic, in metres (zero hinge angles).

    Attributes
    ----------
    radius, blade_length, root_cutout : float
        R, R1 and R - R1, m.
    chord : float
        Chord at the root, m.
    hub_elements : tuple of 5 float
        e1..e5 as fractions of R1 (Table I).
    hub_lengths : tuple of 5 float
        e1..e5 in metres.
    flap_hinge : tuple of 2 float
        (x, z) of the flap hinge, m.
    lag_hinge : tuple of 2 float
        (x, z) of the lag hinge, m.
    pitch_hinge : tuple of 2 float
        (x, z) of the pitch hinge, m.
    pitch_axis, aerodynamic_centre : float
        Fractions of chord behind the leading edge.
    cg_positions : dict
        Name -> C.G. fraction of chord behind the leading edge (the three Table I cases).
    stations : numpy.ndarray
        Aerodynamic quadrature station radii, m.
    """

    radius: float
    blade_length: float
    root_cutout: float
    chord: float
    hub_elements: tuple
    hub_lengths: tuple
    flap_hinge: tuple
    lag_hinge: tuple
    pitch_hinge: tuple
    pitch_axis: float
    aerodynamic_centre: float
    cg_positions: dict
    stations: np.ndarray

    def export(self) -> dict:
        """The fields for :func:`~rotorlyap.chapters.export.figure_csv`, without the C.G. mapping
        (its values are in the chapter's text and in Table I)."""
        return {f.name: getattr(self, f.name) for f in fields(self) if f.name != "cg_positions"}

    def summary(self) -> str:
        """Hub dimensions (m, to 0.1 mm), root cutout and cuff, the stations and the chordwise
        reference points, as chapter 3 prints them."""
        cg = ", ".join("%s %.3g" % kv for kv in self.cg_positions.items())
        return "\n".join([
            f"hub elements e1..e5 (m): {np.round(self.hub_lengths, 4)}",
            "flap hinge x = %.4f m; lag hinge (x, z) = (%.4f, %.4f) m; pitch hinge x = %.4f m"
            % (self.flap_hinge[0], *self.lag_hinge, self.pitch_hinge[0]),
            "root cutout R - R1 = %.3f m; massless cuff from the pitch hinge to the root: %.3f m"
            % (self.root_cutout, self.root_cutout - self.pitch_hinge[0]),
            "%d aerodynamic stations from r/R = %.4f to %.4f"
            % (len(self.stations), self.stations[0] / self.radius, self.stations[-1] / self.radius),
            "chordwise positions (fraction of chord behind the leading edge): pitch axis %.3g, "
            "aerodynamic centre %.3g, C.G. %s" % (self.pitch_axis, self.aerodynamic_centre, cg),
        ])

    def facts(self) -> dict[str, Any]:
        """Hub elements e1..e4 (m, 4 decimals), pitch hinge, cutout and cuff (m, 3 decimals),
        the number of stations, and the chordwise positions (fractions of chord, as given)."""
        e = self.hub_lengths
        out: dict[str, Any] = {f"ch3_e{k + 1}": round(e[k], 4) for k in range(4)}
        out.update(ch3_pitch_hinge=round(self.pitch_hinge[0], 3), ch3_cutout=round(self.root_cutout, 3),
                   ch3_cuff=round(self.root_cutout - self.pitch_hinge[0], 3),
                   ch3_n_stations=len(self.stations), ch3_xc_pitch_axis=self.pitch_axis,
                   ch3_xc_ac=self.aerodynamic_centre)
        out.update({"ch3_xc_cg_" + name: x for name, x in self.cg_positions.items()})
        out["ch3_cg_step"] = round(self.cg_positions["backward"] - self.cg_positions["neutral"], 3)
        return out


def schematic_data(params: BladeParameters) -> SchematicData:
    """Geometry of ``params`` for the schematic (BLADE_SPEC reading of the hub elements)."""
    d = params.hub_element_lengths
    ro = params.root_r_over_R
    return SchematicData(
        radius=params.radius, blade_length=params.blade_length, root_cutout=params.root_cutout,
        chord=float(params.chord_at(ro)), hub_elements=tuple(params.hub_elements),
        hub_lengths=tuple(d), flap_hinge=(d[0], 0.0), lag_hinge=(d[0] + d[2], d[1]),
        pitch_hinge=(d[0] + d[2] + d[3], d[1]), pitch_axis=params.pitch_axis,
        aerodynamic_centre=float(params.aerodynamic_centre_at(ro)),
        cg_positions=dict(CG_POSITIONS), stations=params.stations()[0] * params.radius,
    )


def figure_blade_schematic(data: SchematicData) -> Figure:
    """The four panels of the schematic in one figure, 9 x 10 in: (a) the blade from above
    (top row), (b) the hub from above and (c) from the side (middle row), (d) a section
    (bottom row); labels of 8 pt."""
    fig = figure(figsize=(9, 10))
    gs = fig.add_gridspec(3, 2, height_ratios=[1.0, 0.95, 1.35])
    plot_blade_top_view(data, fig.add_subplot(gs[0, :]))
    plot_hub_top_view(data, fig.add_subplot(gs[1, 0]))
    plot_hub_side_view(data, fig.add_subplot(gs[1, 1]))
    plot_section(data, fig.add_subplot(gs[2, :]))
    return finish(fig)


def plot_blade_top_view(data: SchematicData, ax) -> None:
    """The whole blade seen from above, true scale: shaft, hub, cuff, blade, stations."""
    c, xp = data.chord, data.pitch_axis
    y_le, y_te = xp * c, -(1 - xp) * c  # pitch axis at y = 0 (e5 = 0)
    x_ph = data.pitch_hinge[0]
    ax.add_patch(Circle((0, 0), 0.09, fc="0.6", ec="k", lw=0.8, zorder=3))
    ax.plot([0, x_ph], [0, 0], color="k", lw=2.0, solid_capstyle="butt", zorder=2)
    # massless cuff from the pitch hinge to the blade root
    ax.add_patch(Polygon([(x_ph, 0.35 * y_le), (data.root_cutout, y_le), (data.root_cutout, y_te),
                          (x_ph, 0.35 * y_te)], closed=True, fc="none", ec="0.45", lw=0.9, ls="--"))
    ax.add_patch(Rectangle((data.root_cutout, y_te), data.blade_length, c, fc="0.88", ec="k", lw=0.9))
    ax.plot([x_ph, data.radius], [0, 0], color="tab:red", lw=0.8, ls="-.", zorder=2)
    ax.plot(data.stations, np.zeros_like(data.stations), "|", color="k", ms=6, mew=0.9, zorder=4)
    # dimensions
    _dim(ax, (0, 0), (data.radius, 0), f"$R$ = {data.radius:.3f} m", offset=(0, -0.75))
    _dim(ax, (data.root_cutout, 0), (data.radius, 0), f"$R_1$ = {data.blade_length:.3f} m",
         offset=(0, -0.52), text_offset=(1.2, 0.0))
    _dim(ax, (0, 0), (data.root_cutout, 0), f"$R - R_1$ = {data.root_cutout:.3f} m",
         offset=(0, 0.45), text_offset=(0.1, 0.17))
    _dim(ax, (data.radius + 0.15, y_te), (data.radius + 0.15, y_le), f"$c$ = {c:.2f} m",
         text_offset=(0.42, 0.0))
    # labels (each with its leader clear of the others)
    ax.annotate("massless cuff", (0.5 * (x_ph + data.root_cutout), 0.5 * y_te), (0.9, -0.95),
                fontsize=8, arrowprops=dict(arrowstyle="-", color="0.4", lw=0.6))
    ax.annotate("pitch (feathering) axis, %.2f$c$" % xp, (1.9, 0.0), (1.55, 0.5), fontsize=8,
                color="tab:red", arrowprops=dict(arrowstyle="-", color="tab:red", lw=0.6))
    ax.annotate("%d aerodynamic stations" % len(data.stations), (data.stations[-5], y_le),
                (5.3, 0.55), fontsize=8, arrowprops=dict(arrowstyle="-", color="0.2", lw=0.6))
    ax.text(4.1, y_le + 0.05, "leading edge", fontsize=8, va="bottom")
    ax.text(4.1, y_te - 0.03, "trailing edge", fontsize=8, va="top")
    ax.text(0.0, -0.17, "shaft", fontsize=8, ha="center", va="top")
    # frames and senses
    _axes_triad(ax, (-0.55, -0.95), (1, 0), (0, 1), ("$x_H$", "$y_H$"), 0.45)
    _arrow(ax, (1.6, 0.9), (1.6, 1.35), color="tab:blue", lw=1.3)
    ax.text(1.68, 1.12, r"rotation $\Omega$ (leading edge first)", fontsize=8, color="tab:blue",
            va="center")
    _arrow(ax, (7.3, 0.55), (7.3, 0.3), color=HINGE_COLORS["lag"], lw=1.3)
    ax.text(7.38, 0.45, r"$\zeta > 0$ (lag)", fontsize=8, color=HINGE_COLORS["lag"], va="center")
    ax.set_xlim(-0.9, data.radius + 0.8)
    ax.set_ylim(-1.25, 1.5)
    ax.set_aspect("equal")
    ax.set_xlabel("radial distance from the shaft, $x_H$ (m)")
    ax.set_ylabel("$y_H$ (m)")
    ax.set_title("(a) top view, true scale (seen from above; blade at $\\psi = 0$, pointing aft)",
                 fontsize=9.5, loc="left")


def _hub_x_dims(ax, data: SchematicData, y: float, step: float) -> None:
    """Dimension lines of e1, e3, e4 stacked downwards from ``y``, labels right of each."""
    e1, _e2, e3, e4, _e5 = data.hub_lengths
    x1, x2, x3 = data.flap_hinge[0], data.lag_hinge[0], data.pitch_hinge[0]
    for k, (a, b, lab, e) in enumerate(((0.0, x1, "e_1", e1), (x1, x2, "e_3", e3), (x2, x3, "e_4", e4))):
        yy = y - k * step
        _dim(ax, (a, yy), (b, yy), "")
        ax.plot([a, a], [yy - 0.3 * step, yy + 0.3 * step], color="0.15", lw=0.5)
        ax.plot([b, b], [yy - 0.3 * step, yy + 0.3 * step], color="0.15", lw=0.5)
        ax.text(b + 0.01, yy, f"${lab}$ = {e:.4f} m", fontsize=8, ha="left", va="center")


def plot_hub_top_view(data: SchematicData, ax) -> None:
    """The hub seen from above, enlarged: flap, lag and pitch hinges, cuff and blade root."""
    x1, x2, x3 = data.flap_hinge[0], data.lag_hinge[0], data.pitch_hinge[0]
    c, xp = data.chord, data.pitch_axis
    y_le, y_te = xp * c, -(1 - xp) * c
    ax.add_patch(Circle((0, 0), 0.035, fc="0.6", ec="k", lw=0.8, zorder=3))
    ax.plot([0, x3], [0, 0], color="k", lw=2.2, solid_capstyle="butt", zorder=2)
    # flap hinge: axis along y_H
    ax.plot([x1, x1], [-0.05, 0.05], color=HINGE_COLORS["flap"], lw=4, solid_capstyle="butt", zorder=4)
    # lag hinge: vertical axis, seen end-on
    ax.add_patch(Circle((x2, 0), 0.018, fc="white", ec=HINGE_COLORS["lag"], lw=2.2, zorder=4))
    ax.plot(x2, 0, ".", color=HINGE_COLORS["lag"], zorder=5)
    # pitch hinge: bearing along x
    ax.add_patch(Rectangle((x3 - 0.03, -0.022), 0.06, 0.044, fc=HINGE_COLORS["pitch"], ec="k",
                           lw=0.6, zorder=4))
    ax.plot([x3, data.root_cutout + 0.1], [0, 0], color="tab:red", lw=0.8, ls="-.", zorder=3)
    ax.add_patch(Polygon([(x3 + 0.03, 0.3 * y_le), (data.root_cutout, y_le), (data.root_cutout, y_te),
                          (x3 + 0.03, 0.3 * y_te)], closed=True, fc="none", ec="0.45", lw=0.9, ls="--"))
    ax.add_patch(Rectangle((data.root_cutout, y_te), 0.2, c, fc="0.88", ec="k", lw=0.9))
    ax.text(data.root_cutout + 0.02, y_te + 0.02, "blade\nroot", fontsize=8, va="bottom")
    ax.text(0.5 * (x3 + data.root_cutout) + 0.05, -0.05, "cuff\n(massless)", fontsize=8,
            ha="center", va="top", color="0.35")
    _hub_x_dims(ax, data, -0.12, 0.075)
    _dim(ax, (0, 0.25), (data.root_cutout, 0.25), f"$R - R_1$ = {data.root_cutout:.3f} m",
         fontsize=8, text_offset=(0, 0.045))
    ax.text(0.0, 0.16, f"$e_5$ = {data.hub_lengths[4]:.3g} m: pitch axis through the pitch hinge",
            fontsize=8, ha="left", va="center", color="tab:red")
    ax.text(x1, 0.065, "flap", fontsize=8, ha="center", color=HINGE_COLORS["flap"])
    ax.text(x2, 0.03, "lag", fontsize=8, ha="center", va="bottom", color=HINGE_COLORS["lag"])
    ax.text(x3, 0.03, "pitch", fontsize=8, ha="center", va="bottom", color=HINGE_COLORS["pitch"])
    ax.set_xlim(-0.08, data.root_cutout + 0.22)
    ax.set_ylim(-0.38, 0.34)
    ax.set_aspect("equal")
    ax.set_xlabel("$x_H$ (m)")
    ax.set_ylabel("$y_H$ (m)")
    ax.set_title("(b) hub, top view (enlarged, true scale)", fontsize=9, loc="left")


def plot_hub_side_view(data: SchematicData, ax) -> None:
    """The hub seen from the trailing-edge side (x right, z up), enlarged, with e2 vertical."""
    x1, x2, x3 = data.flap_hinge[0], data.lag_hinge[0], data.pitch_hinge[0]
    z2 = data.lag_hinge[1]
    ax.plot([0, 0], [-0.2, 0.085], color="0.5", lw=5, solid_capstyle="butt")
    ax.text(0.01, 0.075, "shaft", fontsize=8, va="top")
    ax.plot([0, x1], [0, 0], color="k", lw=2.2, solid_capstyle="butt")
    ax.plot([x1, x2, x2], [0, 0, z2], color="k", lw=2.2, solid_capstyle="butt")
    ax.plot([x2, x3 + 0.1], [z2, z2], color="k", lw=2.2, solid_capstyle="butt")
    ax.add_patch(Circle((x1, 0), 0.012, fc="white", ec=HINGE_COLORS["flap"], lw=2.2, zorder=4))
    ax.plot([x2, x2], [z2 - 0.02, z2 + 0.02], color=HINGE_COLORS["lag"], lw=4, solid_capstyle="butt",
            zorder=4)
    ax.add_patch(Rectangle((x3 - 0.03, z2 - 0.01), 0.06, 0.02, fc=HINGE_COLORS["pitch"], ec="k",
                           lw=0.6, zorder=4))
    ax.text(x1, 0.018, "flap", fontsize=8, ha="center", va="bottom", color=HINGE_COLORS["flap"])
    ax.text(x2 - 0.008, z2 - 0.008, "lag", fontsize=8, ha="right", va="center", color=HINGE_COLORS["lag"])
    ax.text(x3, z2 - 0.014, "pitch", fontsize=8, ha="center", va="top", color=HINGE_COLORS["pitch"])
    _dim(ax, (x2 + 0.03, 0), (x2 + 0.03, z2), "")
    ax.text(x2 + 0.045, 0.058, f"$e_2$ = {data.hub_lengths[1]:.4f} m: lag hinge\nbelow the flap hinge",
            fontsize=8, va="center")
    ax.plot([x1, x3 + 0.1], [0, 0], color="0.6", lw=0.6, ls=":")
    _hub_x_dims(ax, data, -0.085, 0.035)
    # flap sense
    _arrow(ax, (x3 + 0.07, z2 - 0.003), (x3 + 0.09, z2 + 0.035), color=HINGE_COLORS["flap"], lw=1.2,
           connectionstyle="arc3,rad=0.3")
    ax.text(x3 + 0.105, z2 + 0.03, r"$\beta > 0$" + "\n(tip up)", fontsize=8, color=HINGE_COLORS["flap"],
            va="center")
    _axes_triad(ax, (0.02, -0.19), (1, 0), (0, 1), ("$x_H$", "$z_H$"), 0.038)
    ax.set_xlim(-0.04, x3 + 0.2)
    ax.set_ylim(-0.2, 0.085)
    ax.set_aspect("equal")
    ax.set_xlabel("$x_H$ (m)")
    ax.set_ylabel("$z_H$ (m)")
    ax.set_title("(c) hub, side view from the trailing edge", fontsize=9, loc="left")


def plot_section(data: SchematicData, ax) -> None:
    """A blade section seen from the tip (y_B to the leading edge, right; z_B up): pitch axis,
    aerodynamic centre, the three C.G. positions (in an enlarged inset of the chord, since they
    lie within 0.04 chord of one another), and the senses of pitch and air flow."""
    c = data.chord
    xp = data.pitch_axis
    out = _airfoil_outline()
    y = (xp - out[:, 0]) * c  # leading edge (x = 0) at +xp c, pitch axis at 0
    z = out[:, 1] * c
    ax.fill(y, z, fc="0.9", ec="k", lw=0.9)
    ax.plot([xp * c, -(1 - xp) * c], [0, 0], color="0.5", lw=0.6, ls=":")
    ax.plot(0, 0, "+", ms=7, color="tab:red", mew=1.2, zorder=6)
    ax.text(xp * c + 0.01, 0.0, "LE", fontsize=8, va="center")
    ax.text(-(1 - xp) * c - 0.01, 0.0, "TE", fontsize=8, va="center", ha="right")
    # senses
    _axes_triad(ax, (0.2, -0.145), (1, 0), (0, 1), ("$y_B$", "$z_B$"), 0.05)
    _arrow(ax, (0.125, 0.005), (0.105, 0.05), color=HINGE_COLORS["pitch"], lw=1.2,
           connectionstyle="arc3,rad=0.3")
    ax.text(0.125, 0.05, r"$\theta > 0$: nose up", fontsize=8, color=HINGE_COLORS["pitch"],
            ha="left", va="bottom")
    _arrow(ax, (0.28, -0.035), (0.16, -0.035), color="tab:blue", lw=1.0)
    ax.text(0.22, -0.045, "air (hover)", fontsize=8, color="tab:blue", ha="center", va="top")
    ax.set_xlim(-0.38, 0.3)
    ax.set_ylim(-0.16, 0.09)
    ax.set_aspect("equal")
    ax.set_xlabel("$y_B$ from the pitch axis (m)")
    ax.set_ylabel("$z_B$ (m)")
    ax.set_title("(d) section seen from the tip ($x_B$ towards the viewer); below, the chord near "
                 "the pitch axis enlarged", fontsize=9.5, loc="left")
    # the chord from 0.20c to 0.29c behind the leading edge, enlarged (x only)
    lo, hi = (xp - 0.29) * c, (xp - 0.20) * c
    ins = ax.inset_axes([-0.32, -0.15, 0.44, 0.09], transform=ax.transData)
    ins.set_xlim(lo, hi)
    ins.set_ylim(-0.003, 0.003)
    ins.set_xticks([])
    ins.set_yticks([])
    ins.axhline(0, color="0.5", lw=0.8, ls=":")
    ax.indicate_inset_zoom(ins, edgecolor="0.4", lw=0.6)
    above = ins.get_xaxis_transform()  # x in metres, y a fraction of the inset's height
    ya = (xp - data.aerodynamic_centre) * c
    ins.plot(0, 0, "o", ms=10, mfc="white", mec="tab:red", mew=1.8, zorder=5)
    ins.plot(0, 0, "+", ms=10, color="tab:red", mew=1.5, zorder=6)
    ins.plot(ya, 0, "|", ms=16, mew=2.0, color="tab:orange", zorder=4)
    ins.plot([0, 0], [0.6, 0.72], color="tab:red", lw=0.6, transform=above)
    ins.text(0.0005, 0.75, f"pitch axis {xp:.2f}$c$", transform=above, fontsize=8, color="tab:red",
             ha="right", va="bottom")
    ins.plot([ya, ya], [0.65, 0.72], color="tab:orange", lw=0.6, transform=above)
    ins.text(ya - 0.0005, 0.75, f"aerodynamic centre {data.aerodynamic_centre:.3f}$c$", transform=above,
             fontsize=8, color="tab:orange", ha="left", va="bottom")
    # C.G. labels under the chord, the one nearest the pitch axis lower down
    for name, xc in data.cg_positions.items():
        yc = (xp - xc) * c
        ins.plot(yc, 0, CG_MARKERS[name], ms=6, color=CG_COLORS[name], mec="k", mew=0.5, zorder=7)
        low = name == "neutral"
        ins.plot([yc, yc], [0.4, 0.12 if low else 0.3], color=CG_COLORS[name], lw=0.6, transform=above)
        ha = {"forward": "left", "backward": "right"}.get(name, "center")
        ins.text(yc + {"left": -0.0005, "right": 0.0005}.get(ha, 0.0), 0.1 if low else 0.28,
                 f"C.G. {CG_ROMAN[name]} ({name}) {xc:.3g}$c$", transform=above, fontsize=8,
                 color=CG_COLORS[name], ha=ha, va="top")


# --------------------------------------------------------------------------------------
# Chapter 3: closed forms, the moments at the equilibrium, pitch-flap coupling, pitch damping
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class ClosedFormData:
    """Closed-form rotating frequencies of a blade in vacuum at zero pitch, eq. (closed forms).

    Attributes
    ----------
    closed_forms : rotorlyap.model.modes.ClosedForms
        The frequencies (per rev) and the inertias about the hinges (kg m^2).
    """

    closed_forms: ClosedForms

    def summary(self) -> str:
        """The three frequencies (per rev) and inertias (kg m^2), as chapter 3 prints them."""
        cf = self.closed_forms
        return "\n".join([
            "closed forms (zero pitch): nu_beta = %.4f, nu_zeta = %.4f, nu_theta = %.3f per rev"
            % (cf.flap_frequency, cf.lag_frequency, cf.pitch_frequency),
            "I_beta = %.1f kg m^2, I_zeta = %.1f kg m^2, I_theta = %.4f kg m^2"
            % (cf.flap_inertia, cf.lag_inertia, cf.pitch_inertia),
        ])

    def facts(self) -> dict[str, float]:
        """nu_beta (4 decimals), nu_zeta (3) and nu_theta (2), per rev."""
        cf = self.closed_forms
        return {"ch3_nu_beta": round(cf.flap_frequency, 4), "ch3_nu_zeta": round(cf.lag_frequency, 3),
                "ch3_nu_theta": round(cf.pitch_frequency, 2)}


def closed_form_data(params: BladeParameters) -> ClosedFormData:
    """:func:`rotorlyap.model.modes.closed_forms` of ``params`` at zero pitch."""
    return ClosedFormData(closed_forms(params))


@dataclass(frozen=True)
class HingeBalanceData:
    """The generalised forces about each hinge at the hover equilibrium (they balance).

    Attributes
    ----------
    case : str
        "forward C.G." (a Table I case) or "C.G. 0.24c".
    equilibrium : numpy.ndarray
        ``(beta, zeta, theta)``, rad.
    conservative, aerodynamic, damping : numpy.ndarray
        Moments about the flap, lag and pitch hinges, N m, shape (3,): centrifugal, Coriolis,
        gravity and springs; air loads; hinge dampers.
    """

    case: str
    equilibrium: np.ndarray
    conservative: np.ndarray
    aerodynamic: np.ndarray
    damping: np.ndarray

    def summary(self) -> str:
        """Equilibrium angles (deg, 3 decimals) and the moments (N m, 0.1 N m), the unit once in
        the header; the sum is at round-off level and prints as 0.0."""
        lines = ["hover equilibrium, %s: beta = %.3f, zeta = %.3f, theta = %.3f deg"
                 % (self.case, *np.degrees(self.equilibrium)),
                 "moments about the hinges (N m): conservative, aerodynamic, damping, sum"]
        for k, hinge in enumerate(HINGES):
            c, a, d = self.conservative[k], self.aerodynamic[k], self.damping[k]
            lines.append("%-5s %9.1f %9.1f %4.1f %4.1f"
                         % (hinge, c, a, d + 0.0, round(c + a + d, 1) + 0.0))
        return "\n".join(lines)

    def facts(self) -> dict[str, int]:
        """The aerodynamic flap and lag moments, N m to 10 N m."""
        return {"ch3_flap_aero": int(round(self.aerodynamic[0], -1)),
                "ch3_lag_aero": int(round(self.aerodynamic[1], -1))}


def hinge_balance_data(blade: Blade) -> HingeBalanceData:
    """Generalised forces of ``blade`` at its hover equilibrium (``Blade.generalised_forces``)."""
    z = blade.equilibrium()
    gf = blade.generalised_forces(0.0, z)
    return HingeBalanceData(case=_case_name(blade.params), equilibrium=np.array(z[:3]),
                            conservative=np.asarray(gf["conservative"]),
                            aerodynamic=np.asarray(gf["aerodynamic"]), damping=np.asarray(gf["damping"]))


def effective_flap_frequency(flap_frequency: float, lock_number: float, pitch_flap_coupling: float) -> float:
    """Classical hover flap frequency with pitch-flap coupling, ``sqrt(nu_beta^2 + gamma/8 k3)``,
    per rev (Johnson 1980; ``k3 = tan(delta3)``, the pitch change per flap being ``-k3``).

    Parameters
    ----------
    flap_frequency : float
        ``nu_beta``, per rev.
    lock_number : float
        ``gamma``, -.
    pitch_flap_coupling : float
        ``tan(delta3)``, -.
    """
    return math.sqrt(flap_frequency ** 2 + lock_number / 8 * pitch_flap_coupling)


@dataclass(frozen=True)
class PitchFlapCouplingData:
    """The pitch-flap coupling of a blade and its classical effect on the hover flap frequency.

    Attributes
    ----------
    pitch_flap_coupling : float
        ``tan(delta3)``, -.
    lock_number : float
        ``gamma``, -.
    flap_frequency : float
        Closed-form rotating flap frequency ``nu_beta`` in vacuum, per rev.
    """

    pitch_flap_coupling: float
    lock_number: float
    flap_frequency: float

    @property
    def delta3(self) -> float:
        """``delta3``, rad."""
        return math.atan(self.pitch_flap_coupling)

    @property
    def effective_flap_frequency(self) -> float:
        """``nu_e`` (:func:`effective_flap_frequency`), per rev."""
        return effective_flap_frequency(self.flap_frequency, self.lock_number, self.pitch_flap_coupling)

    def summary(self) -> str:
        """tan(delta3), delta3 (deg), the Lock number and nu_e, as chapter 3 prints them."""
        return ("tan(delta3) = %.2f, delta3 = %.1f deg; Lock number %.3f; nu_e = %.3f per rev"
                % (self.pitch_flap_coupling, math.degrees(self.delta3), self.lock_number,
                   self.effective_flap_frequency))

    def facts(self) -> dict[str, float]:
        """tan(delta3) (as given), delta3 (deg, 0.1), K_P = -tan(delta3), nu_e and gamma (2 decimals)."""
        k3 = self.pitch_flap_coupling
        return {"ch3_tan_delta3": k3, "ch3_delta3_deg": round(math.degrees(self.delta3), 1),
                "ch3_kp": round(-k3, 2), "ch3_nu_e": round(self.effective_flap_frequency, 2),
                "ch3_lock": round(self.lock_number, 2)}


def pitch_flap_coupling_data(params: BladeParameters) -> PitchFlapCouplingData:
    """Pitch-flap coupling, Lock number and closed-form flap frequency of ``params``."""
    return PitchFlapCouplingData(pitch_flap_coupling=params.pitch_flap_coupling,
                                 lock_number=params.lock_number,
                                 flap_frequency=closed_forms(params).flap_frequency)


def pitch_damping_estimate(params: BladeParameters) -> float:
    """Growth-rate change of a blade pitching alone from the pitch-damping couple, per rev.

    ``rho c^3 c_mq (R^2 - R0^2) / (16 I_theta)``, with ``U = Omega r``, ``q = Omega theta'``,
    ``R0 = R - R1`` the root radius, ``I_theta`` the pitch inertia (closed forms) and ``c`` the
    chord at 0.75 R (the chord of an untapered blade).
    """
    chord = float(params.chord_at(0.75))
    return (params.air_density * chord ** 3 * params.cm_pitch_rate
            * (params.radius ** 2 - params.root_cutout ** 2) / (16 * closed_forms(params).pitch_inertia))


@dataclass(frozen=True)
class PitchDampingData:
    """The hover pitch mode of each C.G. case with and without the pitch-damping couple.

    Attributes
    ----------
    cases : tuple of str
        C.G. case names (Table I).
    with_couple, without_couple : tuple of Mode
        The oscillatory pitch-dominated hover mode (:func:`rotorlyap.model.modes.pitch_mode`)
        with the thin-airfoil ``cm_pitch_rate`` and with ``cm_pitch_rate = 0``; eigenvalues
        per rev.
    estimate : tuple of float
        :func:`pitch_damping_estimate` of each case, per rev.
    """

    cases: tuple
    with_couple: tuple
    without_couple: tuple
    estimate: tuple

    def summary(self) -> str:
        """Growth rates (3 decimals) and frequencies (2), their difference and the estimate
        (2 decimals), per rev, as chapter 3 prints them."""
        lines = ["hover pitch mode, growth rate (frequency) per rev:"]
        for cg, on, off, est in zip(self.cases, self.with_couple, self.without_couple, self.estimate):
            lines.append("%-8s C.G.: with the couple %+.3f (%.2f); without %+.3f (%.2f); "
                         "difference %+.2f, estimate %+.2f"
                         % (cg, on.growth_rate, on.frequency, off.growth_rate, off.frequency,
                            on.growth_rate - off.growth_rate, est))
        return "\n".join(lines)

    def facts(self) -> dict[str, Any]:
        """Per case the growth rates with and without the couple (3 decimals), their difference
        and the estimate (2 decimals), per rev; how many cases decay with and without."""
        out: dict[str, Any] = {}
        for cg, on, off, est in zip(self.cases, self.with_couple, self.without_couple, self.estimate):
            out["ch3_pitch_on_" + cg] = round(on.growth_rate, 3)
            out["ch3_pitch_off_" + cg] = round(off.growth_rate, 3)
            out["ch3_pitch_diff_" + cg] = round(on.growth_rate - off.growth_rate, 2)
            out["ch3_pitch_est_" + cg] = round(est, 2)
        n = len(self.cases)
        out["ch3_n_pitch_decay_on"] = _how_many(sum(m.growth_rate < 0 for m in self.with_couple), n)
        out["ch3_n_pitch_decay_off"] = _how_many(sum(m.growth_rate < 0 for m in self.without_couple), n)
        return out


def pitch_damping_data(cases: Sequence[str] = tuple(CG_POSITIONS)) -> PitchDampingData:
    """Hover pitch mode of each Table I C.G. case with its ``cm_pitch_rate`` and with 0."""
    on, off, est = [], [], []
    for cg in cases:
        p = BladeParameters.table_i(cg)
        on.append(pitch_mode(hover_modes(p)))
        off.append(pitch_mode(hover_modes(replace(p, cm_pitch_rate=0.0))))
        est.append(pitch_damping_estimate(p))
    return PitchDampingData(cases=tuple(cases), with_couple=tuple(on), without_couple=tuple(off),
                            estimate=tuple(est))


# --------------------------------------------------------------------------------------
# Airfoil coefficients
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class CoefficientData:
    """Airfoil coefficients on the full angle range.

    Attributes
    ----------
    alpha : numpy.ndarray
        Angle of attack, deg, shape (n,).
    names : tuple of str
        Airfoil labels.
    cl, cd, cm : numpy.ndarray
        Coefficients, shape (n_airfoils, n); ``cm`` about each model's aerodynamic centre.
    lift_slope : tuple of float
        Lift-curve slope of each airfoil (its ``lift_slope``), 1/rad; NaN if it has none.
    """

    alpha: np.ndarray
    names: tuple
    cl: np.ndarray
    cd: np.ndarray
    cm: np.ndarray
    lift_slope: tuple = ()

    def summary(self) -> str:
        """Lift, drag and moment landmarks of the first airfoil on the angle grid (to the grid
        step), and the lift slopes, as chapter 3 prints them."""
        cl, cd, cm = self.cl[0], self.cd[0], self.cm[0]
        a = self.alpha
        i0 = np.argmin(np.abs(a))
        a0 = self.lift_slope[0] if self.lift_slope else float("nan")
        others = "; ".join(f"{n}: the same" if s == a0 else f"{n}: {s:.3f} /rad"
                           for n, s in zip(self.names[1:], self.lift_slope[1:]))
        return "\n".join([
            "%s model: cl(0) = %.3f, max cl = %.2f at %.1f deg, min cl = %.2f at %.1f deg"
            % (self.names[0], cl[i0], cl.max(), a[cl.argmax()], cl.min(), a[cl.argmin()]),
            "  min cd = %.4f, max cd = %.2f at %.0f deg; cm(0) = %.3f; cm from %.2f to %.2f"
            % (cd.min(), cd.max(), a[cd.argmax()], cm[i0], cm.min(), cm.max()),
            "  lift slope %.3f /rad = %.4f /deg" % (a0, math.radians(a0)) + (f" ({others})" if others else ""),
        ])


def coefficient_data(airfoils: Sequence[Any], n: int = 1441) -> CoefficientData:
    """Evaluate ``coefficients`` of each airfoil on ``n`` angles from -180 to 180 deg."""
    alpha = np.linspace(-180.0, 180.0, n)
    rad = np.radians(alpha)
    cl, cd, cm = [], [], []
    for a in airfoils:
        l, d, m = a.coefficients(rad)
        cl.append(l)
        cd.append(d)
        cm.append(m)
    names = tuple(getattr(a, "name", repr(a)) for a in airfoils)
    slopes = tuple(float(getattr(a, "lift_slope", float("nan"))) for a in airfoils)
    return CoefficientData(alpha=alpha, names=names, cl=np.array(cl), cd=np.array(cd), cm=np.array(cm),
                           lift_slope=slopes)


_COEFF_LABELS = {"cl": "$c_l$", "cd": "$c_d$", "cm": "$c_m$ about the a.c."}
_AIRFOIL_STYLES = (dict(color="k", lw=1.3), dict(color="tab:orange", lw=1.2, ls="--"))


def plot_coefficient(data: CoefficientData, ax, coefficient: str = "cl",
                     alpha_range: tuple[float, float] = (-180.0, 180.0),
                     ylim: tuple[float, float] | None = None, legend: bool = True,
                     band_labels: bool = True) -> None:
    """One coefficient (``"cl"``, ``"cd"`` or ``"cm"``) of every airfoil against alpha (deg); on
    the full range, the reverse-flow bands (named unless ``band_labels`` is False)."""
    values = getattr(data, coefficient)
    for k, name in enumerate(data.names):
        v = values[k].astype(float)
        a = data.alpha.astype(float)
        jumps = np.nonzero(np.abs(np.diff(v)) > 1.0)[0] + 1  # a model wrapping at +-180 deg
        ax.plot(np.insert(a, jumps, np.nan), np.insert(v, jumps, np.nan), label=name,
                **_AIRFOIL_STYLES[k % len(_AIRFOIL_STYLES)])
    lo, hi = alpha_range
    if hi - lo > 200:
        for s in (-1, 1):
            ax.axvspan(s * 90, s * 180, color="tab:blue", alpha=0.06, lw=0)
            if band_labels:
                ax.text(s * 135, 0.96, "reverse flow", transform=ax.get_xaxis_transform(), fontsize=8,
                        ha="center", va="top", color="tab:blue")
        ax.set_xticks(np.arange(-180, 181, 90))
        ax.set_xticks(np.arange(-180, 181, 45), minor=True)
    ax.axhline(0, color="0.6", lw=0.5)
    ax.axvline(0, color="0.6", lw=0.5)
    ax.set_xlim(lo, hi)
    if ylim is not None:
        ax.set_ylim(*ylim)
    ax.set_ylabel(_COEFF_LABELS[coefficient])
    ax.grid(alpha=0.3)
    if legend:
        ax.legend(fontsize=8, loc="lower left")


def figure_airfoil_coefficients(data: CoefficientData) -> Figure:
    """c_l, c_d and c_m (rows) over the full angle range (left) and around attached flow and
    stall, -25 to 30 deg (right), 8.6 x 7.6 in."""
    fig = figure(figsize=(8.6, 7.6))
    axes = fig.subplots(3, 2, sharex="col", gridspec_kw=dict(width_ratios=[1.6, 1]))
    limits = {"cl": ((-2.0, 2.2), (-1.5, 2.0)), "cd": ((0.0, 2.2), (0.0, 0.4)),
              "cm": ((-0.65, 0.65), (-0.1, 0.05))}
    for i, c in enumerate(("cl", "cd", "cm")):
        plot_coefficient(data, axes[i, 0], c, ylim=limits[c][0], legend=(i == 0), band_labels=(i == 0))
        plot_coefficient(data, axes[i, 1], c, alpha_range=(-25, 30), ylim=limits[c][1], legend=False)
    for ax in axes[-1]:
        ax.set_xlabel(r"angle of attack $\alpha_a$ (deg)")
    axes[0, 0].set_title("full range", fontsize=10)
    axes[0, 1].set_title("attached flow and stall", fontsize=10)
    return finish(fig)


# --------------------------------------------------------------------------------------
# Angle of attack along the span
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class AngleOfAttackData:
    """Section angles of attack along the span at the hover equilibrium state.

    Attributes
    ----------
    r_over_R : numpy.ndarray
        Fine spanwise grid, shape (n,).
    stations : numpy.ndarray
        The model's quadrature stations, r/R, shape (n_stations,).
    cases : tuple of (float, float)
        (advance ratio, azimuth in deg) of each curve.
    alpha : numpy.ndarray
        Angle of attack on the fine grid, deg, shape (n_cases, n).
    alpha_stations : numpy.ndarray
        At the quadrature stations, deg, shape (n_cases, n_stations).
    equilibrium : numpy.ndarray
        The state used, ``(beta, zeta, theta, 0, 0, 0)``, rad.
    root_r_over_R : float
        Blade root, ``(R - R1)/R``.
    """

    r_over_R: np.ndarray
    stations: np.ndarray
    cases: tuple
    alpha: np.ndarray
    alpha_stations: np.ndarray
    equilibrium: np.ndarray
    root_r_over_R: float

    def summary(self) -> str:
        """The stations (r/R, 3 decimals) and the angle of attack at each (deg, 0.1 deg) for
        every case, as chapter 3 prints them."""
        lines = [f"stations r/R: {np.round(self.stations, 3)}"]
        for (mu, psi), a in zip(self.cases, self.alpha_stations):
            lines.append("mu = %.2f, psi = %3.0f deg: AoA (deg) = " % (mu, psi) + str(np.round(a, 1)))
        return "\n".join(lines)

    def facts(self) -> dict[str, Any]:
        """Angle of attack at the innermost and outermost station of the first case (hover by
        default), deg to 0.1, and the number of stations in reverse flow (``|alpha| > 90`` deg) in
        the last case."""
        return {"ch3_alpha_root": round(float(self.alpha_stations[0, 0]), 1),
                "ch3_alpha_tip": round(float(self.alpha_stations[0, -1]), 1),
                "ch3_n_reverse": int((np.abs(self.alpha_stations[-1]) > 90).sum())}


def angle_of_attack_data(params: BladeParameters,
                         cases: Sequence[tuple[float, float]] = ((0.0, 0.0), (0.25, 90.0),
                                                                 (0.25, 180.0), (0.25, 270.0)),
                         n_fine: int = 96) -> AngleOfAttackData:
    """Angles of attack at the hover equilibrium (the paper's steady motion) for each
    (advance ratio, azimuth) case, on the model's stations and on a fine spanwise grid."""
    hover = Blade(params)
    z = hover.equilibrium()
    fine_params = replace(hover.params, n_stations=n_fine)
    a_fine, a_st = [], []
    for mu, psi_deg in cases:
        psi = math.radians(psi_deg)
        a_st.append(np.degrees(Blade(hover.params, mu=mu).angle_of_attack(psi, z)))
        a_fine.append(np.degrees(Blade(fine_params, mu=mu).angle_of_attack(psi, z)))
    return AngleOfAttackData(r_over_R=fine_params.stations()[0], stations=hover.r_over_R,
                             cases=tuple((float(m), float(p)) for m, p in cases),
                             alpha=np.array(a_fine), alpha_stations=np.array(a_st), equilibrium=z,
                             root_r_over_R=params.root_r_over_R)


def plot_angle_of_attack(data: AngleOfAttackData, ax, alpha_range: tuple[float, float] | None = None,
                         legend: bool = True) -> None:
    """Angle of attack (deg) against r/R for each case; dots mark the quadrature stations.

    ``alpha_range`` (deg) zooms the vertical axis; default: the full circle. Each case has its
    colour (Okabe-Ito) and line style."""
    colors = ("k", "#D55E00", "#E69F00", "#0072B2", "#CC79A7", "#009E73")
    styles = ("-", "--", "-.", ":")
    for k, (mu, psi) in enumerate(data.cases):
        label = "hover" if mu == 0 else rf"$\mu$ = {mu:g}, $\psi$ = {psi:.0f}$^\circ$"
        # break the line where alpha wraps through +-180 deg
        a_plot = data.alpha[k].astype(float)
        r_plot = data.r_over_R.astype(float)
        idx = np.nonzero(np.abs(np.diff(a_plot)) > 180)[0] + 1
        a_plot = np.insert(a_plot, idx, np.nan)
        r_plot = np.insert(r_plot, idx, np.nan)
        ax.plot(r_plot, a_plot, color=colors[k % len(colors)], ls=styles[k % len(styles)], lw=1.4,
                label=label)
        ax.plot(data.stations, data.alpha_stations[k], "o", color=colors[k % len(colors)], ms=3.5)
    ax.axhline(0, color="0.6", lw=0.5)
    ax.axvspan(0, data.root_r_over_R, color="0.85", lw=0)
    if alpha_range is None:
        for s in (-1, 1):
            ax.axhspan(s * 90, s * 180, color="tab:blue", alpha=0.06, lw=0)
            ax.text(0.99, s * 135, "reverse flow", fontsize=8, color="tab:blue", ha="right",
                    va="center")
        ax.text(0.5 * data.root_r_over_R, 0, "root cutout", fontsize=8, ha="center",
                va="center", rotation=90)
        ax.set_yticks(np.arange(-180, 181, 45))
        ax.set_ylim(-185, 185)
    else:
        ax.set_ylim(*alpha_range)
    ax.set_xlim(0, 1)
    ax.set_xlabel("$r/R$")
    ax.set_ylabel(r"angle of attack $\alpha_a$ (deg)")
    ax.grid(alpha=0.3)
    if legend:
        ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(0.16, 1.0), handlelength=2.5)


def figure_angle_of_attack(data: AngleOfAttackData) -> Figure:
    """Angle of attack along the span on the full circle (left) and zoomed on attached flow,
    -15 to 15 deg (right), 8.6 x 4 in."""
    fig = figure(figsize=(8.6, 4.0))
    axes = fig.subplots(1, 2, gridspec_kw=dict(width_ratios=[1.3, 1]))
    plot_angle_of_attack(data, axes[0])
    plot_angle_of_attack(data, axes[1], alpha_range=(-15, 15), legend=False)
    axes[0].set_title("full circle", fontsize=10)
    axes[1].set_title("zoom on attached flow", fontsize=10)
    return finish(fig)


# --------------------------------------------------------------------------------------
# Chapter 3: the generated code, and the local positivity of the energy function
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class GeneratedCodeCheck:
    """Two checks of the cached generated code against the derivation, in miniature.

    Attributes
    ----------
    functions : tuple of str
        Names of the generated functions.
    hash_current : bool
        The cached code records the hash of the current derivation.
    mass_matrix_agrees : bool
        The generated mass matrix at a random state equals sympy's, largest difference below
        1e-12 of the largest entry.
    """

    functions: tuple
    hash_current: bool
    mass_matrix_agrees: bool

    def summary(self) -> str:
        """The functions and the two pass/fail results, as chapter 3 prints them."""
        return "\n".join([
            "generated functions: " + ", ".join(self.functions),
            f"cached code matches the current derivation hash: {self.hash_current}",
            "mass matrix at a random state, generated vs sympy, largest relative difference < 1e-12: "
            f"{self.mass_matrix_agrees}",
        ])


def generated_code_check(model: Any, blade: Blade, seed: int = 1) -> GeneratedCodeCheck:
    """Compare the cached generated code with a fresh derivation.

    Parameters
    ----------
    model : rotorlyap.model.derivation.BladeModel
        The symbolic model (:func:`rotorlyap.model.derivation.derive`).
    blade : Blade
        Supplies the parameter values and the generated mass matrix.
    seed : int
        Seed of the random state: angles uniform in +-0.5 rad, rates in +-1.
    """
    import sympy as sp

    from ..model import derivation
    from ..model._generated import blade_model as generated

    rng = np.random.default_rng(seed)
    z = np.concatenate([rng.uniform(-0.5, 0.5, 3), rng.uniform(-1, 1, 3)])
    m_sym = sp.lambdify([*model.q, *model.params], model.M, "numpy")(*z[:3], *blade.parameter_values)
    m_gen = blade.mass_matrix(z)
    return GeneratedCodeCheck(
        functions=tuple(n for n, _ in inspect.getmembers(generated, inspect.isfunction)),
        hash_current=generated.DERIVATION_HASH == derivation.derivation_hash(),
        mass_matrix_agrees=bool(np.abs(m_gen - m_sym).max() < 1e-12 * np.abs(m_sym).max()),
    )


@dataclass(frozen=True)
class PositivityData:
    """Local positivity of the energy function about the hover equilibrium of each C.G. case.

    Attributes
    ----------
    cases : tuple of str
        C.G. case names (Table I).
    reports : tuple of rotorlyap.analysis.functions.PositivityReport
        Eigenvalues of the Hessian of ``U`` (J/rad^2) and of ``Omega^2 M`` (J), and the verdict.
    """

    cases: tuple
    reports: tuple

    def summary(self) -> str:
        """Extreme eigenvalues (J/rad^2 and J, to 1 or 0.1) and the verdict per case."""
        return "\n".join(
            "%-8s C.G.: Hessian of U, eigenvalues %7.0f to %9.0f J/rad^2; Omega^2 M, %6.1f to %9.0f J; "
            "positive definite: %s" % (cg, r.potential_eigenvalues.min(), r.potential_eigenvalues.max(),
                                       r.kinetic_eigenvalues.min(), r.kinetic_eigenvalues.max(),
                                       r.positive_definite)
            for cg, r in zip(self.cases, self.reports))

    def facts(self) -> dict[str, Any]:
        """Smallest stiffness per case (J/rad^2, to 1) and in how many cases W is positive definite."""
        out: dict[str, Any] = {"ch3_hessU_min_" + cg: int(round(r.potential_eigenvalues.min()))
                               for cg, r in zip(self.cases, self.reports)}
        out["ch3_n_posdef"] = _how_many(sum(bool(r.positive_definite) for r in self.reports), len(self.cases))
        return out


def positivity_data(cases: Sequence[str] = tuple(CG_POSITIONS)) -> PositivityData:
    """:meth:`EnergyFunction.positivity` about the hover equilibrium of each Table I C.G. case."""
    reports = []
    for cg in cases:
        blade = Blade(BladeParameters.table_i(cg))
        reports.append(energy_function(blade, blade.equilibrium()).positivity())
    return PositivityData(cases=tuple(cases), reports=tuple(reports))


# --------------------------------------------------------------------------------------
# Hover eigenvalues against the C.G. position
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class CGSweepData:
    """Hover eigenvalues of the trimmed blade against the chordwise C.G. position.

    Attributes
    ----------
    cg : numpy.ndarray
        C.G. positions, fraction of chord behind the leading edge, shape (n,).
    eigenvalues : numpy.ndarray
        Modes' eigenvalues (Im >= 0 member of each pair), per rev, shape (n, 4), complex; NaN
        where a case has fewer modes (each pair counts once).
    hinges : numpy.ndarray
        Dominant hinge index (0 flap, 1 lag, 2 pitch) of each mode, shape (n, 4), -1 for none.
    pitch_growth : numpy.ndarray
        Growth rate of the oscillatory pitch-dominated mode, per rev, shape (n,).
    largest_real : numpy.ndarray
        Largest real (non-oscillatory) eigenvalue, per rev, shape (n,).
    flutter_cg, divergence_cg : float
        C.G. positions where ``pitch_growth`` and ``largest_real`` first cross zero upwards
        (NaN if they do not cross on the grid).
    aerodynamic_centre, pitch_axis : float
        Fractions of chord, for reference lines.
    """

    cg: np.ndarray
    eigenvalues: np.ndarray
    hinges: np.ndarray
    pitch_growth: np.ndarray
    largest_real: np.ndarray
    flutter_cg: float
    divergence_cg: float
    aerodynamic_centre: float
    pitch_axis: float


def _hover_rates(params: BladeParameters) -> tuple[tuple, float, float]:
    """Modes of the trimmed hover blade, growth of its oscillatory pitch-dominated mode and its
    largest real eigenvalue (NaN where there is none)."""
    modes = hover_modes(params)
    osc_pitch = [m.growth_rate for m in modes if m.oscillatory and m.dominant_hinge == "pitch"]
    reals = [m.growth_rate for m in modes if not m.oscillatory]
    return modes, (max(osc_pitch) if osc_pitch else np.nan), (max(reals) if reals else np.nan)


def _crossing(x: np.ndarray, y: np.ndarray, g=None, xtol: float | None = None) -> float:
    """First upward zero crossing of the sampled ``y(x)``: linear interpolation between the
    grid points, or Brent's method on ``g`` to ``xtol`` if both are given."""
    s = np.nonzero((y[:-1] < 0) & (y[1:] >= 0))[0]
    if not s.size:
        return float("nan")
    i = s[0]
    if g is not None and xtol is not None:
        from scipy.optimize import brentq

        return float(brentq(g, x[i], x[i + 1], xtol=xtol))
    return float(x[i] - y[i] * (x[i + 1] - x[i]) / (y[i + 1] - y[i]))


def cg_sweep_data(cg_positions: Sequence[float], base: BladeParameters | None = None,
                  xtol: float | None = None) -> CGSweepData:
    """Trim and linearise the hover blade for each C.G. position (other data from ``base``,
    default Table I).

    The flutter and divergence boundaries are interpolated linearly between the grid points,
    or, with ``xtol`` (fraction of chord), located by Brent's method (a trim per evaluation).
    """
    base = BladeParameters.table_i() if base is None else base
    cg = np.asarray(cg_positions, dtype=float)
    ev = np.full((cg.size, 4), np.nan + 0j)
    hi = np.full((cg.size, 4), -1)
    pg = np.full(cg.size, np.nan)
    lr = np.full(cg.size, np.nan)
    for i, x in enumerate(cg):
        modes, pg[i], lr[i] = _hover_rates(replace(base, cg_position=float(x)))
        for k, m in enumerate(modes[:4]):
            ev[i, k] = m.eigenvalue
            hi[i, k] = HINGES.index(m.dominant_hinge)

    def rate(k):
        return lambda x: np.nan_to_num(_hover_rates(replace(base, cg_position=float(x)))[k], nan=-1.0)

    flutter = _crossing(cg, np.nan_to_num(pg, nan=-1.0), rate(1), xtol)
    divergence = _crossing(cg, np.nan_to_num(lr, nan=-1.0), rate(2), xtol)
    ro = base.root_r_over_R
    return CGSweepData(cg=cg, eigenvalues=ev, hinges=hi, pitch_growth=pg, largest_real=lr,
                       flutter_cg=flutter, divergence_cg=divergence,
                       aerodynamic_centre=float(base.aerodynamic_centre_at(ro)),
                       pitch_axis=base.pitch_axis)


#: Marker of the modes dominated by each hinge in the C.G. sweep, the second cue to the colour.
_HINGE_MARKERS = {"flap": "o", "lag": "D", "pitch": "v"}


def plot_cg_sweep(data: CGSweepData, ax, part: str = "real", case_labels: bool = True) -> None:
    """Real parts (``part="real"``) or frequencies (``"imag"``) of the hover modes against the
    C.G. position, coloured and marked by dominant hinge; the Table I cases (I, II, III) named
    above the axes unless ``case_labels`` is False."""
    f = np.real if part == "real" else np.imag
    for h, name in enumerate(HINGES):
        sel = data.hinges == h
        xs = np.broadcast_to(data.cg[:, None], data.hinges.shape)[sel]
        ax.plot(xs, f(data.eigenvalues[sel]), _HINGE_MARKERS[name], ms=4.5, color=HINGE_COLORS[name],
                mec="k", mew=0.3, label=f"{name}-dominated mode")
    if part == "real":
        ax.plot(data.cg, data.pitch_growth, "-", color=HINGE_COLORS["pitch"], lw=0.8, alpha=0.6,
                label="oscillatory pitch mode")
        ax.plot(data.cg, data.largest_real, ":", color="0.3", lw=0.8, label="largest real eigenvalue")
        ax.axhline(0, color="k", lw=0.8)
        ax.set_ylabel(r"growth rate Re $s$ (per rev)")
        for x, lab in ((data.flutter_cg, "flutter"), (data.divergence_cg, "divergence")):
            if np.isfinite(x):
                ax.axvline(x, color="0.3", lw=0.8, ls="--")
                ax.text(x, 0.97, f" {lab}\n {x:.3f}$c$", transform=ax.get_xaxis_transform(),
                        fontsize=8, va="top")
    else:
        ax.set_ylabel(r"frequency Im $s$ (per rev)")
        ax.set_yscale("symlog", linthresh=0.1)
    ax.axvline(data.aerodynamic_centre, color="tab:orange", lw=1.0,
               label=f"aerodynamic centre {data.aerodynamic_centre:.3f}$c$")
    ax.axvline(data.pitch_axis, color="tab:red", lw=1.0, ls="-.",
               label=f"pitch axis {data.pitch_axis:.2f}$c$")
    if case_labels:
        for name, x in CG_POSITIONS.items():
            ax.text(x, 1.01, CG_ROMAN[name], transform=ax.get_xaxis_transform(), ha="center",
                    va="bottom", fontsize=9, color=CG_COLORS[name])
    ax.set_xlabel("section C.G., fraction of chord behind the leading edge")
    ax.grid(alpha=0.3)


#: The C.G. grid of chapter 4's sweep: 0.20c to 0.28c in steps of 0.01c and the three Table I
#: cases, fractions of chord behind the leading edge.
CG_SWEEP_GRID = np.union1d(np.round(np.arange(0.20, 0.2801, 0.01), 2), list(CG_POSITIONS.values()))


@dataclass(frozen=True)
class CGSweepPairData:
    """The hover C.G. sweep with and without the aerodynamic pitch damping.

    Attributes
    ----------
    with_damping : CGSweepData
        With the base parameters' ``cm_pitch_rate`` (the thin-airfoil value in Table I).
    without_damping : CGSweepData
        With ``cm_pitch_rate = 0``.
    """

    with_damping: CGSweepData
    without_damping: CGSweepData

    def export(self) -> dict[str, np.ndarray]:
        """Every array of both sweeps for :func:`~rotorlyap.chapters.export.figure_csv`; those of
        the second prefixed ``no_pitch_damping_``, complex eigenvalues split into ``_real`` and
        ``_imag``."""
        cols: dict[str, np.ndarray] = {}
        for prefix, data in (("", self.with_damping), ("no_pitch_damping_", self.without_damping)):
            for f in fields(data):
                a = np.asarray(getattr(data, f.name))
                if np.iscomplexobj(a):
                    cols[prefix + f.name + "_real"], cols[prefix + f.name + "_imag"] = a.real, a.imag
                else:
                    cols[prefix + f.name] = a
        return cols

    def summary(self) -> str:
        """Pitch-mode growth and largest real eigenvalue on the grid (per rev, 3 decimals; "-"
        where there is none) and the boundaries (fraction of chord, 4 decimals; "none on the
        grid" where there is none), as chapter 4 prints them."""
        lines = [f"C.G.: {self.with_damping.cg}"]
        for label, s in (("with pitch damping", self.with_damping),
                         ("without pitch damping", self.without_damping)):
            lines += [label,
                      f"  growth of the oscillatory pitch mode: {_dash_list(s.pitch_growth, 3)}",
                      f"  largest real eigenvalue (-: no real root): {_dash_list(s.largest_real, 3)}",
                      "  flutter: %s; divergence: %s (linear interpolation)"
                      % (_boundary_words(s.flutter_cg, s.cg), _boundary_words(s.divergence_cg, s.cg))]
        return "\n".join(lines)

    def facts(self) -> dict[str, float]:
        """Divergence and flutter boundaries (fraction of chord, 3 decimals; linear interpolation
        between grid points), the grid's ends and the pitch-mode growth at its aft end (per rev,
        2 decimals)."""
        s, s0 = self.with_damping, self.without_damping
        return {"ch4_divergence_cg": round(s.divergence_cg, 3), "ch4_divergence_cg0": round(s0.divergence_cg, 3),
                "ch4_flutter_cg0": round(s0.flutter_cg, 3),
                "ch4_flutter0_behind_ac": round(s0.flutter_cg - s0.aerodynamic_centre, 3),
                "ch4_grid_lo": round(float(s.cg[0]), 2), "ch4_grid_hi": round(float(s.cg[-1]), 2),
                "ch4_pitch_grid_hi": round(float(s.pitch_growth[-1]), 2)}


def cg_sweep_pair_data(cg_positions: Sequence[float] = CG_SWEEP_GRID,
                       base: BladeParameters | None = None) -> CGSweepPairData:
    """:func:`cg_sweep_data` with ``base`` (default Table I) and with its ``cm_pitch_rate = 0``."""
    base = BladeParameters.table_i() if base is None else base
    return CGSweepPairData(with_damping=cg_sweep_data(cg_positions, base),
                           without_damping=cg_sweep_data(cg_positions, replace(base, cm_pitch_rate=0.0)))


def figure_cg_sweep(data: CGSweepPairData) -> Figure:
    """Growth rates (top) and frequencies (bottom) of the hover modes against the C.G. position,
    with the pitch mode without pitch damping (dashed) and its flutter boundary, one legend
    under both, 7.6 x 7.4 in."""
    s, s0 = data.with_damping, data.without_damping
    pitch = HINGE_COLORS["pitch"]
    fig = figure(figsize=(7.6, 7.4))
    axes = fig.subplots(2, 1, sharex=True)
    plot_cg_sweep(s, axes[0], "real")
    axes[0].plot(s0.cg, s0.pitch_growth, "--", color=pitch, lw=1.3, label="pitch mode without pitch damping")
    axes[0].axvline(s0.flutter_cg, color=pitch, lw=0.8, ls="--")
    # between the flutter line and the pitch axis
    axes[0].text(s0.flutter_cg, 0.30, " flutter\n without\n pitch\n damping\n %.3f$c$" % s0.flutter_cg,
                 transform=axes[0].get_xaxis_transform(), fontsize=8, va="top", color=pitch)
    axes[0].set_xlabel("")
    plot_cg_sweep(s, axes[1], "imag", case_labels=False)
    axes[1].legend(*axes[0].get_legend_handles_labels(), fontsize=8, loc="upper center",
                   bbox_to_anchor=(0.5, -0.17), ncol=3, frameon=False)
    return finish(fig)


# --------------------------------------------------------------------------------------
# Tables
# --------------------------------------------------------------------------------------

# Names of the Table I quantities as the paper gives them (LaTeX labels for the book).
TABLE_I_LABELS: dict[str, str] = {
    "radius": "rotor radius $R$",
    "blade_length": "blade length $R_1$",
    "hub_elements": "hub elements $e_1 \\ldots e_5$ / $R_1$",
    "chord": "chord $c$ (constant)",
    "twist": "blade twist",
    "pitch_flap_coupling": "pitch-flap coupling $\\tan\\delta_3$",
    "rotor_speed": "rotor speed $\\Omega$",
    "pitch_stiffness": "pitch hinge stiffness $K_\\theta$",
    "lag_damping": "lag hinge damping $C_\\zeta$",
    "aerodynamic_centre": "aerodynamic centre (behind the leading edge)",
    "cg_position": "section C.G. (computation parameter)",
}


def format_value(value: Any) -> str:
    """Short, deterministic text for a parameter value."""
    if value is None:
        return "None"
    if isinstance(value, tuple):
        return "(" + ", ".join(format_value(v) for v in value) + ")"
    if isinstance(value, float):
        return f"{value:.6g}"
    return str(value)


def markdown_table(header: Sequence[str], rows: Sequence[Sequence[Any]]) -> str:
    """A Markdown pipe table, numbers written by :func:`format_value`
    (:func:`rotorlyap.chapters.export.markdown_table`)."""
    return _markdown_table(header, rows, fmt=format_value)


def table_i_rows(params: BladeParameters) -> list[tuple[str, str, str, str]]:
    """(quantity, field, value, unit) for the fields whose source is Table I."""
    rows = []
    for name, value, unit, source in parameter_table(params):
        if source.startswith("Table I"):
            v = (" / ".join(f"{x:g}" for x in CG_POSITIONS.values()) + " (I / II / III)"
                 if name == "cg_position" else format_value(value))
            rows.append((TABLE_I_LABELS.get(name, name), f"`{name}`", v, unit))
    return rows


NOT_GIVEN = {
    "wind_point": "not given: the aerodynamic centre",
    "inflow_ratio": "not given: computed (momentum theory)",
    "collective": "not given: computed (hover trim)",
}
"""What a field left at ``None`` means, as the assumptions table prints it (a printed ``None``
says nothing to a reader)."""

REFERENCE_NAMES = {
    "AbbottEtAl1945": "Abbott, von Doenhoff and Stivers (1945)",
    "Abbott1959": "Abbott and von Doenhoff (1959)",
    "Hoerner1965": "Hoerner (1965)",
    "JacobsClay1935": "Jacobs and Clay (1935)",
    "Prouty1986": "Prouty (1986)",
    "SheldahlKlimas1981": "Sheldahl and Klimas (1981)",
    "ViternaCorrigan1982": "Viterna and Corrigan (1982)",
}
"""Bibliography keys that the package's recorded sources use, as the printed tables name them
(authors and year; chapter 4 cites each entry in its text)."""


def readable_source(source: str) -> str:
    """A recorded source as a table prints it: bibliography keys become authors and year, and
    an ``assumed: None ...`` prefix loses the ``None`` (the value column says what it means).

    Examples
    --------
    >>> readable_source("assumed: None = momentum theory with thrust = weight")
    'assumed: momentum theory with thrust = weight'
    >>> readable_source("Abbott1959: cm_ac = -0.014")
    'Abbott and von Doenhoff (1959): cm_ac = -0.014'
    """
    text = re.sub(r"^assumed: None(?:,| =) ", "assumed: ", source)
    for key, name in REFERENCE_NAMES.items():
        text = re.sub(rf"\b{key}\b", name, text)
    return text


def assumption_rows(params: BladeParameters) -> list[tuple[str, str, str, str]]:
    """(field, value, unit, source) for every field whose source contains "assumed"; a value
    left at ``None`` is printed as what it means (:data:`NOT_GIVEN`), sources by
    :func:`readable_source`."""
    return [(f"`{name}`", NOT_GIVEN.get(name, "not given") if value is None else format_value(value),
             unit, readable_source(source))
            for name, value, unit, source in parameter_table(params) if "assumed" in source]


def table_i_markdown(params: BladeParameters) -> str:
    """The Table I quantities of ``params`` as a Markdown table (:func:`table_i_rows`)."""
    return markdown_table(("quantity", "field", "value", "unit"), table_i_rows(params))


@dataclass(frozen=True)
class AssumptionData:
    """The fields of a parameter set whose values rest on an assumption.

    Attributes
    ----------
    rows : tuple of (str, str, str, str)
        (field, value, unit, source or reason) of each assumed field (:func:`assumption_rows`).
    n_fields : int
        Number of fields of the parameter set.
    """

    rows: tuple
    n_fields: int

    def markdown(self) -> str:
        """The rows as a Markdown table."""
        return markdown_table(("field", "value", "unit", "source or reason"), self.rows)

    def summary(self) -> str:
        """How many fields rest on an assumption."""
        return "%d of %d fields rest wholly or partly on an assumption" % (len(self.rows), self.n_fields)


def assumption_data(params: BladeParameters) -> AssumptionData:
    """The assumed fields of ``params`` (:func:`rotorlyap.model.parameters.parameter_table`)."""
    return AssumptionData(rows=tuple(assumption_rows(params)), n_fields=len(parameter_table(params)))


def _airfoil_row(airfoil: Any, name: str, source: str) -> tuple[str, float, str, str]:
    """(field, value, unit, source) with angles in deg and slopes in 1/deg, 4 decimals."""
    v = getattr(airfoil, name)
    if "alpha" in name or name in ("stall_blend", "reverse_stall_angle"):
        return f"`{name}`", round(math.degrees(v), 4), "deg", source
    if name.endswith("slope"):
        return f"`{name}`", round(math.radians(v), 4), "1/deg", source
    return f"`{name}`", round(v, 4), "", source


@dataclass(frozen=True)
class AirfoilTableData:
    """The numbers of an airfoil model with their recorded sources, and the blade's airfoil.

    Attributes
    ----------
    rows : tuple of (str, float, str, str)
        (parameter, value, unit, source as recorded); angles in deg, slopes in 1/deg.
    blade_airfoil : str
        Name of the airfoil the blade uses.
    aerodynamic_centre : float
        Its moment reference, fraction of chord behind the leading edge.
    cm_ac : float
        Its moment coefficient about that point, -.
    """

    rows: tuple
    blade_airfoil: str
    aerodynamic_centre: float
    cm_ac: float

    def markdown(self) -> str:
        """The rows as a Markdown table."""
        return markdown_table(("parameter", "value", "unit", "source as recorded"), self.rows)

    def summary(self) -> str:
        """The blade's airfoil, its moment reference (3 decimals) and c_m there (3 decimals)."""
        return ("model used by the blade: %s with its moment reference moved to %.3f c (Table I), cm_ac = %.3f"
                % (self.blade_airfoil, self.aerodynamic_centre, self.cm_ac))


def airfoil_table_data(params: BladeParameters, airfoil: Any = NACA23012,
                       sources: Mapping[str, str] = NACA23012_SOURCES) -> AirfoilTableData:
    """The numbers of ``airfoil`` named in ``sources`` (default the NACA 23012 model and its
    attributions), and the airfoil of ``params``."""
    return AirfoilTableData(rows=tuple(_airfoil_row(airfoil, n, readable_source(s)) for n, s in sources.items()),
                            blade_airfoil=params.airfoil.name,
                            aerodynamic_centre=params.airfoil.aerodynamic_centre, cm_ac=params.airfoil.cm_ac)


# --------------------------------------------------------------------------------------
# Chapter 4: the readings of the missing data
# --------------------------------------------------------------------------------------


def pitch_axis_reading(params: BladeParameters) -> dict[str, float]:
    """The Table I C.G. offsets read about the pitch axis instead of the aerodynamic centre
    (this book's earlier reading), fraction of chord behind the leading edge, 3 decimals."""
    return {cg: round(params.pitch_axis + x - params.aerodynamic_centre, 3) for cg, x in CG_POSITIONS.items()}


@dataclass(frozen=True)
class ChoicesData:
    """The numbers behind the chapter's choices for the data Table I leaves out.

    Attributes
    ----------
    tip_speed : float
        ``Omega R``, m/s.
    blade_mass, flap_inertia, lock_number : float
        kg, kg m^2 (about the flap hinge), -.
    hub_lengths : tuple of 5 float
        e1..e5, m.
    pitch_hinge_radius, root_cutout : float
        ``(e1 + e3 + e4) R1`` and ``R - R1``, m.
    chordwise_lag_angle : float
        The lag angle a chordwise e2 would impose by centrifugal force alone, rad.
    coning, lag : float
        Hover equilibrium flap and lag angles (vertical e2), rad.
    coning_without_e2 : float
        Hover coning with ``e2 = 0``, rad.
    pitch_flap_coupling : float
        ``tan(delta3)``, -.
    pitch_axis, aerodynamic_centre : float
        Fractions of chord behind the leading edge.
    cg_positions, cg_about_pitch_axis : dict
        Case -> C.G. with "neutral" at the aerodynamic centre (this book) and at the pitch axis
        (:func:`pitch_axis_reading`), fractions of chord.
    cm_pitch_rate : float
        The pitch-damping coefficient ``c_mq``, -.
    """

    tip_speed: float
    blade_mass: float
    flap_inertia: float
    lock_number: float
    hub_lengths: tuple
    pitch_hinge_radius: float
    root_cutout: float
    chordwise_lag_angle: float
    coning: float
    lag: float
    coning_without_e2: float
    pitch_flap_coupling: float
    pitch_axis: float
    aerodynamic_centre: float
    cg_positions: dict
    cg_about_pitch_axis: dict
    cm_pitch_rate: float

    def summary(self) -> str:
        """The two readings of e2 (deg) and of the C.G. (fractions of chord), as chapter 4
        prints them."""
        he = self.hub_lengths
        deg = math.degrees
        return "\n".join([
            "chordwise reading of e2: lag angle atan(%.4f / %.4f) = %.2f deg from centrifugal force alone"
            % (abs(he[1]), he[0] + he[2], deg(self.chordwise_lag_angle)),
            "vertical reading: hover coning %.3f deg with e2 = %.4f m, %.3f deg with e2 = 0 (difference %.2f deg)"
            % (deg(self.coning), he[1], deg(self.coning_without_e2), deg(self.coning - self.coning_without_e2)),
            "hover lag angle with air (vertical reading): %.2f deg" % deg(self.lag),
            "C.G. about the a.c. (%.3f c): %s; the same offsets about the pitch axis (%.2f c): %s"
            % (self.aerodynamic_centre, ", ".join("%s %.3f c" % kv for kv in self.cg_positions.items()),
               self.pitch_axis, ", ".join("%s %.3f c" % kv for kv in self.cg_about_pitch_axis.items())),
        ])

    def facts(self) -> dict[str, Any]:
        """Angles in deg, lengths in m (cm for e2), mass data, the C.G. readings and c_mq, each
        rounded as the text quotes it."""
        he = self.hub_lengths
        chordwise = math.degrees(self.chordwise_lag_angle)
        out: dict[str, Any] = {
            "ch4_chordwise_deg": round(chordwise, 1),
            "ch4_e2_precone": round(math.degrees(self.coning - self.coning_without_e2), 2),
            "ch4_reach": round(self.pitch_hinge_radius, 3),
            "ch4_cutout": round(self.root_cutout, 3),
            "ch4_mass": round(self.blade_mass, 1),
            "ch4_I_beta": int(round(self.flap_inertia)),
            "ch4_lag_sum": round(chordwise + math.degrees(self.lag), 0),
            "ch4_lock": round(self.lock_number, 2),
            "ch4_tip_speed": round(self.tip_speed, 1),
            "ch4_ac_ahead": round(self.pitch_axis - self.aerodynamic_centre, 3),
            "ch4_e2_cm": round(100 * abs(he[1]), 1),
            "ch4_lag_radius": round(he[0] + he[2], 2),
            "ch4_k3_pitch": round(-self.pitch_flap_coupling * math.degrees(self.coning), 1),
        }
        for cg in self.cg_positions:
            out["ch4_cg_" + CASE_SHORT[cg]] = self.cg_positions[cg]
            out["ch4_oldcg_" + CASE_SHORT[cg]] = self.cg_about_pitch_axis[cg]
        out["ch4_bwd_behind_pa"] = round(self.cg_positions["backward"] - self.pitch_axis, 3)
        out["ch4_cmq"] = round(self.cm_pitch_rate, 4)
        return out


def choices_data(params: BladeParameters) -> ChoicesData:
    """The chapter's readings for ``params`` (a Table I case): mass data and the hover
    equilibrium from :func:`rotorlyap.model.modes.derived_quantities`, with e2 as given and
    with e2 = 0."""
    e = params.hub_elements
    dq = derived_quantities(params)
    dq0 = derived_quantities(replace(params, hub_elements=(e[0], 0.0, *e[2:])))
    return ChoicesData(
        tip_speed=params.tip_speed, blade_mass=dq.blade_mass, flap_inertia=dq.flap_inertia,
        lock_number=dq.lock_number, hub_lengths=tuple(params.hub_element_lengths),
        pitch_hinge_radius=params.pitch_hinge_radius, root_cutout=params.root_cutout,
        chordwise_lag_angle=chordwise_lag_offset_angle(params), coning=dq.equilibrium[0], lag=dq.equilibrium[1],
        coning_without_e2=dq0.equilibrium[0], pitch_flap_coupling=params.pitch_flap_coupling,
        pitch_axis=params.pitch_axis, aerodynamic_centre=params.aerodynamic_centre,
        cg_positions=dict(CG_POSITIONS), cg_about_pitch_axis=pitch_axis_reading(params),
        cm_pitch_rate=params.cm_pitch_rate)


# --------------------------------------------------------------------------------------
# Chapter 4: derived quantities and hover modes of the three C.G. cases
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class HoverCasesData:
    """Derived quantities of the Table I C.G. cases in hover (the base of the chapter 4 tables).

    Attributes
    ----------
    cases : tuple of str
        C.G. case names.
    params : tuple of BladeParameters
        ``BladeParameters.table_i(case)``.
    quantities : tuple of DerivedQuantities
        :func:`rotorlyap.model.modes.derived_quantities` of each.
    """

    cases: tuple
    params: tuple
    quantities: tuple

    def __getitem__(self, case: str) -> DerivedQuantities:
        """The derived quantities of one case."""
        return self.quantities[self.cases.index(case)]


def _hover_cases(cases: Sequence[str]) -> tuple[tuple, tuple, tuple]:
    params = tuple(BladeParameters.table_i(cg) for cg in cases)
    return tuple(cases), params, tuple(derived_quantities(p) for p in params)


@dataclass(frozen=True)
class DerivedTableData(HoverCasesData):
    """The derived quantities table of chapter 4 (trim, equilibrium, blade-element theory)."""

    @property
    def gravity_droop(self) -> float:
        """Classical gravity droop of the forward case, ``m g r_G / (I_beta Omega^2 nu_beta^2)``
        with ``r_G`` the mid-blade radius from the flap hinge, rad."""
        p, f = self.params[self.cases.index("forward")], self["forward"]
        return p.blade_mass * p.gravity * (0.5 * (p.root_cutout + p.radius) - p.flap_hinge_offset) / (
            f.flap_inertia * p.rotor_speed ** 2 * f.closed_forms.flap_frequency ** 2)

    def markdown(self) -> str:
        """One row per quantity, one column per case; angles in deg (2 decimals, trailing zeros
        kept)."""
        deg = math.degrees
        q = self.quantities
        rows = [("Lock number $\\gamma$", "-", *(round(d.lock_number, 3) for d in q)),
                ("solidity $\\sigma = N c / (\\pi R)$", "-", *(round(d.solidity, 4) for d in q)),
                ("hover thrust coefficient $C_T$", "-", *(round(d.thrust_coefficient, 5) for d in q)),
                ("$C_T / \\sigma$", "-", *(round(d.ct_over_sigma, 4) for d in q)),
                ("hover inflow ratio $\\lambda_i = \\sqrt{C_T/2}$", "-", *(round(d.inflow_ratio, 4) for d in q)),
                ("trimmed collective $\\theta_0$", "deg", *(f"{deg(d.collective):.2f}" for d in q)),
                ("coning (flap) angle $\\beta$", "deg", *(f"{deg(d.equilibrium[0]):.2f}" for d in q)),
                ("lag angle $\\zeta$", "deg", *(f"{deg(d.equilibrium[1]):.2f}" for d in q)),
                ("pitch-hinge angle $\\theta$", "deg", *(f"{deg(d.equilibrium[2]):.2f}" for d in q)),
                ("chord pitch to the hub plane", "deg", *(f"{deg(d.chord_pitch):.2f}" for d in q)),
                ("blade-element pitch for $C_T$", "deg", *(f"{deg(d.blade_element_pitch):.2f}" for d in q)),
                ("blade-element coning", "deg", *(f"{deg(d.blade_element_coning):.2f}" for d in q))]
        return markdown_table(("quantity", "unit", *(f"{CG_ROMAN[c]} {c}" for c in self.cases)), rows)

    def summary(self) -> str:
        """Mass data and thrust of the forward case, and the gravity droop estimate (deg)."""
        f = self["forward"]
        return "\n".join([
            "blade mass %.2f kg, flap inertia %.1f kg m^2, lift slope %.4f /rad, rotor thrust %.0f N"
            % (f.blade_mass, f.flap_inertia, f.lift_slope, f.thrust),
            "gravity droop estimate m g r_G / (I_beta Omega^2 nu^2) = %.2f deg" % math.degrees(self.gravity_droop),
        ])

    def facts(self) -> dict[str, float]:
        """The forward case's hover numbers (angles in deg; ``ch4_chord_minus_hinge`` the chord
        pitch less the pitch-hinge angle) and the three collectives."""
        deg = math.degrees
        f = self["forward"]
        out = {"ch4_solidity": round(f.solidity, 4), "ch4_ct": round(f.thrust_coefficient, 5),
               "ch4_ct_sigma": round(f.ct_over_sigma, 4), "ch4_inflow": round(f.inflow_ratio, 4),
               "ch4_beta_fwd": Rounded(deg(f.equilibrium[0]), 2), "ch4_lag_fwd": Rounded(deg(f.equilibrium[1]), 1),
               "ch4_theta_fwd": Rounded(deg(f.equilibrium[2]), 2), "ch4_chord_pitch": Rounded(deg(f.chord_pitch), 2),
               "ch4_bet_pitch": Rounded(deg(f.blade_element_pitch), 2),
               "ch4_bet_coning": Rounded(deg(f.blade_element_coning), 2),
               "ch4_g_droop": Rounded(deg(self.gravity_droop), 2),
               "ch4_chord_minus_hinge": Rounded(deg(f.chord_pitch - f.equilibrium[2]), 2)}
        out.update({"ch4_coll_" + CASE_SHORT[c]: Rounded(deg(d.collective), 2) for c, d in zip(self.cases, self.quantities)})
        return out


def derived_table_data(cases: Sequence[str] = tuple(CG_POSITIONS)) -> DerivedTableData:
    """Derived quantities of the Table I C.G. cases."""
    return DerivedTableData(*_hover_cases(cases))


def _mode_lines(modes: Sequence[Mode], label: str) -> list[str]:
    """``label``, then one line per mode: eigenvalue and ``|s|`` (per rev, 4 decimals), damping
    ratio (3) and shape (3)."""
    lines = [label]
    for m in modes:
        ratio = "%7.3f" % _r4(m.damping_ratio) if m.oscillatory else "   real"
        lines.append("  %-5s  s = %8.4f %+8.4fi   |s| = %6.4f   damping ratio %s   shape (flap, lag, pitch) = "
                     "(%.3f, %.3f, %.3f)" % (m.dominant_hinge, _r4(m.eigenvalue.real), _r4(m.eigenvalue.imag),
                                             m.natural_frequency, ratio, *m.shape))
    return lines


def _mode_rows(modes: Sequence[Mode], case: str, closed_form: dict | None = None) -> list[tuple]:
    """Rows of :func:`_modes_markdown` for one case: the same numbers as :func:`_mode_lines`."""
    rows = []
    for m in modes:
        ratio = "%.3f" % _r4(m.damping_ratio) if m.oscillatory else "real"
        row = [case, m.dominant_hinge, "%.4f %s %.4f i" % (_r4(m.eigenvalue.real), "+-"[m.eigenvalue.imag < 0],
                                                          abs(_r4(m.eigenvalue.imag))),
               "%.4f" % m.natural_frequency]
        if closed_form is not None:
            row.append(closed_form.get(m.dominant_hinge, ""))
        rows.append(tuple(row + [ratio, "%.3f, %.3f, %.3f" % tuple(m.shape)]))
    return rows


def _modes_markdown(rows: list[tuple], closed_form: bool) -> str:
    """A Markdown table of modes: case, dominant hinge, eigenvalue, |s| (per rev), damping ratio,
    shape (flap, lag, pitch), with the closed-form frequency if ``closed_form``."""
    header = ["C.G.", "mode", "eigenvalue $s$ (per rev)", r"$\lvert s \rvert$ (per rev)"]
    header += ["closed form (per rev)"] if closed_form else []
    header += ["damping ratio", "shape (flap, lag, pitch)"]
    return markdown_table(header, rows)


@dataclass(frozen=True)
class VacuumModesData(HoverCasesData):
    """The rotating modes in vacuum of the Table I C.G. cases, with the closed forms."""

    def summary(self) -> str:
        """Modes of each case with the closed-form frequencies (per rev), as chapter 4 prints them."""
        lines = []
        for cg, d in zip(self.cases, self.quantities):
            cf = d.closed_forms
            lines += _mode_lines(d.vacuum_modes, "%s C.G., vacuum (closed forms: flap %.4f, lag %.4f with decay "
                                 "%.4f, pitch %.3f)" % (cg, cf.flap_frequency, cf.lag_frequency,
                                                       cf.lag_decay_rate, cf.pitch_frequency))
        return "\n".join(lines)

    def markdown(self) -> str:
        """The modes of :meth:`summary` as a Markdown table, with each mode's closed-form frequency
        (the lag mode's undamped one)."""
        rows = []
        for cg, d in zip(self.cases, self.quantities):
            cf = d.closed_forms
            closed = {"flap": "%.4f" % cf.flap_frequency, "lag": "%.4f" % cf.lag_frequency,
                      "pitch": "%.3f" % cf.pitch_frequency}
            rows += _mode_rows(d.vacuum_modes, cg, closed)
        return _modes_markdown(rows, closed_form=True)

    def facts(self) -> dict[str, float]:
        """The forward case's vacuum frequencies (per rev), lag damping ratio and flap-mode
        pitch amplitude; per case the pitch frequency above its closed form, per cent."""
        f = self["forward"]
        vac = {m.dominant_hinge: m for m in f.vacuum_modes}
        out = {"ch4_nu_flap_vac": round(vac["flap"].frequency, 4),
               "ch4_nu_lag_vac": round(vac["lag"].natural_frequency, 3),
               "ch4_zeta_lag_vac": round(vac["lag"].damping_ratio, 2),
               "ch4_nu_pitch_vac": round(vac["pitch"].frequency, 2),
               "ch4_nu_pitch_cf": round(f.closed_forms.pitch_frequency, 2),
               "ch4_flap_pitch_shape": round(vac["flap"].shape[2], 2)}
        for cg, d in zip(self.cases, self.quantities):
            vp = d.modes("pitch", air=False)[0]
            out["ch4_pitch_shift_" + CASE_SHORT[cg]] = round(100 * (vp.frequency / d.closed_forms.pitch_frequency - 1), 2)
        return out


def vacuum_modes_data(cases: Sequence[str] = tuple(CG_POSITIONS)) -> VacuumModesData:
    """Vacuum modes of the Table I C.G. cases."""
    return VacuumModesData(*_hover_cases(cases))


@dataclass(frozen=True)
class AirModesData(HoverCasesData):
    """The hover modes with air of the Table I C.G. cases."""

    def summary(self) -> str:
        """Modes of each case, as chapter 4 prints them."""
        lines = []
        for cg, d in zip(self.cases, self.quantities):
            lines += _mode_lines(d.air_modes, "%s C.G., hover with air" % cg)
        return "\n".join(lines)

    def markdown(self) -> str:
        """The modes of :meth:`summary` as a Markdown table."""
        rows = []
        for cg, d in zip(self.cases, self.quantities):
            rows += _mode_rows(d.air_modes, cg)
        return _modes_markdown(rows, closed_form=False)

    def facts(self) -> dict[str, Any]:
        """The forward case's flap, lag and pitch modes with air (frequencies per rev, damping
        ratios, the flap mode's decay rate ``ch4_flap_air_decay`` per rev, shapes), gamma/16
        (the classical flap-alone decay rate, per rev) and the classical nu_e."""
        f = self["forward"]
        p = self.params[self.cases.index("forward")]
        fl = {m.dominant_hinge: m for m in f.air_modes}
        nu_e = effective_flap_frequency(f.closed_forms.flap_frequency, f.lock_number, p.pitch_flap_coupling)
        return {"ch4_flap_air": round(fl["flap"].natural_frequency, 2),
                "ch4_flap_air_zeta": round(fl["flap"].damping_ratio, 2),
                "ch4_flap_air_decay": Rounded(-fl["flap"].growth_rate, 2),
                "ch4_pitch_air": round(fl["pitch"].frequency, 2),
                "ch4_pitch_air_zeta": round(fl["pitch"].damping_ratio, 3),
                "ch4_gamma16": round(f.lock_number / 16, 2),
                "ch4_nu_e": round(nu_e, 2),
                "ch4_flap_air_shape": "(%.2f, %.2f, %.2f)" % fl["flap"].shape,
                "ch4_lag_air_zeta": round(fl["lag"].damping_ratio, 2),
                "ch4_lag_air_flap": round(fl["lag"].shape[0], 2)}


def air_modes_data(cases: Sequence[str] = tuple(CG_POSITIONS)) -> AirModesData:
    """Hover modes with air of the Table I C.G. cases."""
    return AirModesData(*_hover_cases(cases))


@dataclass(frozen=True)
class HoverStabilityData(HoverCasesData):
    """Linear hover stability of the Table I C.G. cases: pitch mode and least-damped mode."""

    def summary(self) -> str:
        """Verdict, pitch-mode eigenvalue and largest growth rate (per rev, 3 decimals) per case."""
        lines = []
        for cg, p, d in zip(self.cases, self.params, self.quantities):
            pm, sm = pitch_mode(d.air_modes), least_damped(d.air_modes)
            lines.append("%-8s C.G. %.3fc: %s; pitch mode s = %.3f %+.3fi; largest growth rate %.3f (%s)"
                         % (cg, p.cg_position, "linearly stable" if not d.unstable_air_modes else "UNSTABLE",
                            _r3(pm.eigenvalue.real), _r3(pm.eigenvalue.imag), _r3(sm.growth_rate), _kind(sm)))
        return "\n".join(lines)

    def facts(self) -> dict[str, Any]:
        """Per case the pitch mode (growth rate, frequency per rev and damping ratio, 2 decimals)
        and the largest growth rate (3 decimals); the backward case's slowest mode shape and
        its halving time, rev (``ln 2 / (2 pi |sigma|)``: the growth rate ``sigma`` is per rad of
        azimuth), one decimal."""
        out: dict[str, Any] = {}
        for cg, d in zip(self.cases, self.quantities):
            pm, sm = pitch_mode(d.air_modes), least_damped(d.air_modes)
            s = CASE_SHORT[cg]
            out["ch4_pitch_" + s] = round(pm.growth_rate, 2)
            out["ch4_pitchf_" + s] = round(pm.frequency, 2)
            out["ch4_pitchz_" + s] = round(pm.damping_ratio, 2)
            out["ch4_slow_" + s] = _r3(sm.growth_rate)
        sm = least_damped(self["backward"].air_modes)
        out["ch4_slow_bwd_shape"] = "(%.2f, %.2f, %.2f)" % sm.shape
        # the growth rate is per rad of azimuth (in units of Omega): one revolution is 2 pi of it
        out["ch4_slow_bwd_halving"] = round(math.log(2) / (2 * math.pi * -sm.growth_rate), 1)
        return out


def hover_stability_data(cases: Sequence[str] = tuple(CG_POSITIONS)) -> HoverStabilityData:
    """Hover stability of the Table I C.G. cases."""
    return HoverStabilityData(*_hover_cases(cases))


# --------------------------------------------------------------------------------------
# Chapter 4: what the hover stability rests on
# --------------------------------------------------------------------------------------

#: The two readings of the C.G. positions: (label, short name in the glue names).
READINGS = (("a.c.", "ac"), ("pitch axis", "pa"))
#: The two pitch dampings: (label, ``cm_pitch_rate``, short name in the glue names).
DAMPINGS = (("thin airfoil", THIN_AIRFOIL_CM_Q, "q"), ("none", 0.0, "0"))


@dataclass(frozen=True)
class SensitivityCase:
    """The hover modes of one C.G. case under one reading and one pitch damping.

    Attributes
    ----------
    reading : str
        "a.c." or "pitch axis": what "neutral" C.G. is read as.
    damping : str
        "thin airfoil" or "none".
    case : str
        C.G. case name.
    cg_position : float
        Fraction of chord behind the leading edge.
    cm_pitch_rate : float
        ``c_mq``, -.
    pitch_mode, least_damped : Mode
        The oscillatory pitch-dominated mode and the mode of largest growth rate, per rev.
    """

    reading: str
    damping: str
    case: str
    cg_position: float
    cm_pitch_rate: float
    pitch_mode: Mode
    least_damped: Mode

    @property
    def glue_key(self) -> str:
        """``ch4_s_<reading>_<damping>_<case>``, e.g. ``ch4_s_ac_q_fwd``."""
        r = dict(READINGS)[self.reading]
        d = {name: short for name, _, short in DAMPINGS}[self.damping]
        return f"ch4_s_{r}_{d}_{CASE_SHORT[self.case]}"


@dataclass(frozen=True)
class SensitivityData:
    """Hover stability of the three C.G. cases under both readings of "neutral" and with and
    without the aerodynamic pitch damping (twelve cases).

    Attributes
    ----------
    rows : tuple of SensitivityCase
    """

    rows: tuple

    def summary(self) -> str:
        """One line per case: pitch-mode growth rate and largest growth rate (per rev, 3
        decimals), the latter's mode and the verdict."""
        lines = ["%-10s  %-19s  %-8s  %-6s  %-15s  %-42s  %s" % (
            "C.G. about", "pitch damping c_m_q", "case", "C.G./c", "pitch mode Re s", "largest Re s (its mode)",
            "hover")]
        for r in self.rows:
            pm, sm = r.pitch_mode, r.least_damped
            lines.append("%-10s  %-19s  %-8s  %-6.3f  %+-15.3f  %-42s  %s" % (
                r.reading, "%s %.3f" % (r.damping, r.cm_pitch_rate) if r.cm_pitch_rate else "none 0", r.case,
                r.cg_position, _r3(pm.growth_rate), "%+.3f (%s)" % (_r3(sm.growth_rate), _kind(sm)),
                "unstable" if sm.unstable else "stable"))
        return "\n".join(lines)

    def markdown(self) -> str:
        """The table of :meth:`summary` in Markdown."""
        rows = []
        for r in self.rows:
            pm, sm = r.pitch_mode, r.least_damped
            rows.append((r.reading, "%s %.3f" % (r.damping, r.cm_pitch_rate) if r.cm_pitch_rate else "none (0)",
                         r.case, "%.3f" % r.cg_position, "%+.3f" % _r3(pm.growth_rate),
                         "%+.3f (%s)" % (_r3(sm.growth_rate), _kind(sm)),
                         "**unstable**" if sm.unstable else "stable"))
        return markdown_table(["C.G. measured from", "pitch damping $c_{m_q}$", "case", "C.G./$c$",
                               "pitch mode Re $s$ (per rev)", "largest Re $s$ (its mode)", "hover"], rows)

    def facts(self) -> dict[str, float]:
        """Per case the pitch-mode and largest growth rates (per rev, 3 decimals); the forward
        case's pitch damping ratio without pitch damping."""
        out: dict[str, float] = {}
        for r in self.rows:
            out[r.glue_key + "_pitch"] = _r3(r.pitch_mode.growth_rate)
            out[r.glue_key + "_max"] = _r3(r.least_damped.growth_rate)
        ref = next(r for r in self.rows if r.reading == "a.c." and r.damping == "none" and r.case == "forward")
        out["ch4_pitch_air_zeta0"] = _r3(ref.pitch_mode.damping_ratio)
        return out


def sensitivity_data(base: BladeParameters | None = None) -> SensitivityData:
    """Hover modes of ``base`` (default Table I) for each reading, pitch damping and C.G. case,
    in that order of loops."""
    base = BladeParameters.table_i() if base is None else base
    readings = {"a.c.": dict(CG_POSITIONS), "pitch axis": pitch_axis_reading(base)}
    rows = []
    for reading, _ in READINGS:
        for damping, cmq, _ in DAMPINGS:
            for cg, x in readings[reading].items():
                modes = hover_modes(replace(base, cg_position=x, cm_pitch_rate=cmq))
                rows.append(SensitivityCase(reading=reading, damping=damping, case=cg, cg_position=x,
                                            cm_pitch_rate=cmq, pitch_mode=pitch_mode(modes),
                                            least_damped=least_damped(modes)))
    return SensitivityData(rows=tuple(rows))


@dataclass(frozen=True)
class VariantsData:
    """One C.G. case with one ingredient changed at a time, with and without pitch damping.

    Attributes
    ----------
    case : str
        C.G. case name.
    cg_position : float
        Fraction of chord behind the leading edge.
    labels : tuple of str
        The variants, the first the unchanged Table I blade.
    pitch_growth : numpy.ndarray
        Growth rate of the oscillatory pitch-dominated mode, per rev, shape (n_variants, 2):
        with the thin-airfoil pitch damping, without.
    largest_real : numpy.ndarray
        Largest real eigenvalue, per rev, same shape; NaN where all are complex.
    lag_stiffness : float
        The lag spring of the lag-spring variant, N m/rad.
    """

    case: str
    cg_position: float
    labels: tuple
    pitch_growth: np.ndarray
    largest_real: np.ndarray
    lag_stiffness: float

    def markdown(self) -> str:
        """The growth rates as a table (per rev, 3 decimals): one row per variant, the pitch
        mode and the largest real root with the pitch damping and without; "no real root" where
        all eigenvalues are complex."""
        def root(x: float) -> str:
            return "no real root" if np.isnan(x) else "%+.3f" % _r3(x)

        rows = [(label, "%+.3f" % _r3(pg[0]), root(lr[0]), "%+.3f" % _r3(pg[1]), root(lr[1]))
                for label, pg, lr in zip(self.labels, self.pitch_growth, self.largest_real)]
        return markdown_table(("%s C.G. (%.3f c): variant" % (self.case, self.cg_position),
                               "pitch mode, with pitch damping", "largest real root, with",
                               "pitch mode, without", "largest real root, without"), rows)

    def summary(self) -> str:
        """Growth rates per variant (per rev, 3 decimals), as chapter 4 prints them."""
        lines = ["%s C.G. (%.3f c): growth rates per rev" % (self.case, self.cg_position)]
        for label, pg, lr in zip(self.labels, self.pitch_growth, self.largest_real):
            out = ["%s: pitch mode %+.3f, %s" % (name, _r3(g), "no real root" if np.isnan(x)
                                                    else "largest real root %+.3f" % _r3(x))
                   for name, g, x in zip(("with pitch damping", "without"), pg, lr)]
            lines.append("  %-52s %s" % (label, "; ".join(out)))
        return "\n".join(lines)

    def facts(self) -> dict[str, float]:
        """The largest real eigenvalue of the unchanged blade with and without pitch damping,
        per rev, 3 decimals."""
        return {"ch4_bwd_real_q": _r3(self.largest_real[0, 0]), "ch4_bwd_real_0": _r3(self.largest_real[0, 1])}


def variants_data(case: str = "backward", lag_frequency: float = 0.6, reference: str = "forward") -> VariantsData:
    """Hover modes of the Table I ``case`` unchanged, without pitch-flap coupling, with a lag
    spring for ``lag_frequency`` per rev, and with the wind point at 0.75 c.

    The lag spring is ``(nu^2 - nu_zeta^2) I_zeta Omega^2`` with the closed-form lag frequency
    and inertia of the ``reference`` case (the chordwise C.G. hardly changes them).
    """
    params = BladeParameters.table_i(case)
    cf = derived_quantities(BladeParameters.table_i(reference)).closed_forms
    k_lag = (lag_frequency ** 2 - cf.lag_frequency ** 2) * cf.lag_inertia * params.rotor_speed ** 2
    variants = [("Table I", {}), ("no pitch-flap coupling, tan(delta3) = 0", {"pitch_flap_coupling": 0.0}),
                ("lag spring for nu_zeta = %.1f/rev (K = %.0f N m/rad)" % (lag_frequency, k_lag),
                 {"lag_stiffness": k_lag}),
                ("wind point at 0.75 c", {"wind_point": 0.75})]
    growth = np.full((len(variants), len(DAMPINGS)), np.nan)
    real = np.full_like(growth, np.nan)
    for i, (_, change) in enumerate(variants):
        for j, (_, cmq, _) in enumerate(DAMPINGS):
            modes = hover_modes(replace(params, cm_pitch_rate=cmq, **change))
            growth[i, j] = pitch_mode(modes).growth_rate
            reals = [m.growth_rate for m in modes if not m.oscillatory]
            if reals:
                real[i, j] = max(reals)
    return VariantsData(case=case, cg_position=params.cg_position, labels=tuple(label for label, _ in variants),
                        pitch_growth=growth, largest_real=real, lag_stiffness=k_lag)
