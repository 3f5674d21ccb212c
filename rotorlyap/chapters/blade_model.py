"""Figures, tables and printed numbers of chapter 3, the blade model.

The conventions every chapter's module follows (data objects, ``summary()``, ``facts()``,
``plot_*`` and ``figure_*``) are in :mod:`rotorlyap.chapters`.

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

Chapter 4 (Table I) is in :mod:`rotorlyap.chapters.table_i`; the classical flap frequency with
pitch-flap coupling, which both chapters quote, in :mod:`rotorlyap.chapters.blade_formulas`.
"""

from __future__ import annotations

import inspect
import math
from dataclasses import dataclass, fields, replace
from typing import Any, Sequence

import numpy as np
from matplotlib.figure import Figure
from matplotlib.patches import Circle, FancyArrowPatch, Polygon, Rectangle

from ..analysis.functions import energy_function
from ..conventions import HINGES
from ..model.blade import Blade
from ..model.modes import ClosedForms, closed_forms, hover_modes, pitch_mode
from ..model.parameters import CG_POSITIONS, BladeParameters
from .blade_formulas import effective_flap_frequency
from .style import CG_COLORS, CG_MARKERS, CG_ROMAN, HINGE_COLORS, figure, finish

__all__ = [
    "SchematicData", "schematic_data", "figure_blade_schematic",
    "plot_blade_top_view", "plot_hub_top_view", "plot_hub_side_view", "plot_section",
    "ClosedFormData", "closed_form_data",
    "HingeBalanceData", "hinge_balance_data",
    "PitchFlapCouplingData", "pitch_flap_coupling_data",
    "PitchDampingData", "pitch_damping_data", "pitch_damping_estimate",
    "CoefficientData", "coefficient_data", "plot_coefficient", "figure_airfoil_coefficients",
    "AngleOfAttackData", "angle_of_attack_data", "plot_angle_of_attack", "figure_angle_of_attack",
    "GeneratedCodeCheck", "generated_code_check",
    "PositivityData", "positivity_data",
]

_NUMBER_WORDS = ("none", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten")


def _how_many(n: int, total: int) -> str:
    """``n`` of ``total`` cases in words, as the text quotes it: "none", "two", "all three"."""
    word = _NUMBER_WORDS[n] if n < len(_NUMBER_WORDS) else str(n)
    return f"all {word}" if n == total and total > 2 else word


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
        """``nu_e`` (:func:`~rotorlyap.chapters.blade_formulas.effective_flap_frequency`), per rev."""
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
