"""Figures and tables of the blade-model and Table I chapters.

One data function (returning a frozen dataclass, no plotting) and one drawing function (taking
that data and a matplotlib ``Axes``) per figure panel, as in :mod:`rotorlyap.figures.theory`.
Notebooks call both and print a rounded summary of the data.

* :func:`schematic_data` with :func:`plot_blade_top_view`, :func:`plot_hub_top_view`,
  :func:`plot_hub_side_view`, :func:`plot_section`: the drawn blade (our reading of the
  paper's lost Fig. 3), dimensions in metres computed from the parameters.
* :func:`coefficient_data` with :func:`plot_coefficient`: airfoil coefficients on the full
  angle range.
* :func:`angle_of_attack_data` with :func:`plot_angle_of_attack`: section angles of attack
  along the span at the hover equilibrium, in hover and forward flight.
* :func:`cg_sweep_data` with :func:`plot_cg_sweep`: hover eigenvalues against the chordwise
  C.G. position.
* :func:`markdown_table`, :func:`table_i_rows`, :func:`assumption_rows`: the Table I and
  assumption tables as Markdown.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Any, Sequence

import numpy as np
from matplotlib.patches import Circle, FancyArrowPatch, Polygon, Rectangle

from ..conventions import HINGES
from ..model.blade import Blade
from ..model.modes import hover_modes
from ..model.parameters import CG_POSITIONS, BladeParameters, parameter_table
from .export import markdown_table as _markdown_table
from .style import CG_COLORS, CG_ROMAN, HINGE_COLORS

__all__ = [
    "SchematicData", "schematic_data",
    "plot_blade_top_view", "plot_hub_top_view", "plot_hub_side_view", "plot_section",
    "CoefficientData", "coefficient_data", "plot_coefficient",
    "AngleOfAttackData", "angle_of_attack_data", "plot_angle_of_attack",
    "CGSweepData", "cg_sweep_data", "plot_cg_sweep",
    "TABLE_I_LABELS", "format_value", "markdown_table", "table_i_rows", "assumption_rows",
    "HINGE_COLORS",
]

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
         offset=(0, -0.52))
    _dim(ax, (0, 0), (data.root_cutout, 0), f"$R - R_1$ = {data.root_cutout:.3f} m",
         offset=(0, 0.45), text_offset=(0.1, 0.17))
    _dim(ax, (data.radius + 0.15, y_te), (data.radius + 0.15, y_le), f"$c$ = {c:.2f} m",
         text_offset=(0.42, 0.0))
    # labels
    ax.annotate("massless cuff", (0.5 * (x_ph + data.root_cutout), 0.5 * y_te), (0.9, -0.95),
                fontsize=8, arrowprops=dict(arrowstyle="-", color="0.4", lw=0.6))
    ax.annotate("pitch (feathering) axis, %.2f$c$ behind the leading edge" % xp, (3.6, 0.0),
                (2.3, 0.62), fontsize=8,
                color="tab:red", arrowprops=dict(arrowstyle="-", color="tab:red", lw=0.6))
    ax.annotate("%d aerodynamic stations (Gauss-Legendre)" % len(data.stations),
                (data.stations[-4], 0.0), (4.3, 1.05), fontsize=8,
                arrowprops=dict(arrowstyle="-", color="0.2", lw=0.6))
    ax.text(3.0, y_le + 0.05, "leading edge", fontsize=8, va="bottom")
    ax.text(3.0, y_te - 0.03, "trailing edge", fontsize=8, va="top")
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
                 fontsize=9, loc="left")


def _hub_x_dims(ax, data: SchematicData, y: float, step: float) -> None:
    """Dimension lines of e1, e3, e4 stacked downwards from ``y``, labels right of each."""
    e1, _e2, e3, e4, _e5 = data.hub_lengths
    x1, x2, x3 = data.flap_hinge[0], data.lag_hinge[0], data.pitch_hinge[0]
    for k, (a, b, lab, e) in enumerate(((0.0, x1, "e_1", e1), (x1, x2, "e_3", e3), (x2, x3, "e_4", e4))):
        yy = y - k * step
        _dim(ax, (a, yy), (b, yy), "")
        ax.plot([a, a], [yy - 0.3 * step, yy + 0.3 * step], color="0.15", lw=0.5)
        ax.plot([b, b], [yy - 0.3 * step, yy + 0.3 * step], color="0.15", lw=0.5)
        ax.text(b + 0.01, yy, f"${lab}$ = {e:.4f} m", fontsize=7, ha="left", va="center")


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
    ax.text(data.root_cutout + 0.02, y_te + 0.02, "blade\nroot", fontsize=7, va="bottom")
    ax.text(0.5 * (x3 + data.root_cutout) + 0.05, -0.05, "cuff\n(massless)", fontsize=7,
            ha="center", va="top", color="0.35")
    _hub_x_dims(ax, data, -0.12, 0.075)
    _dim(ax, (0, 0.25), (data.root_cutout, 0.25), f"$R - R_1$ = {data.root_cutout:.3f} m",
         fontsize=7, text_offset=(0, 0.045))
    ax.text(0.0, 0.16, f"$e_5$ = {data.hub_lengths[4]:.3f} m: the pitch axis passes through the pitch hinge",
            fontsize=7, ha="left", va="center", color="tab:red")
    ax.text(x1, 0.065, "flap", fontsize=7, ha="center", color=HINGE_COLORS["flap"])
    ax.text(x2, 0.03, "lag", fontsize=7, ha="center", va="bottom", color=HINGE_COLORS["lag"])
    ax.text(x3, 0.03, "pitch", fontsize=7, ha="center", va="bottom", color=HINGE_COLORS["pitch"])
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
    ax.text(0.01, 0.075, "shaft", fontsize=7, va="top")
    ax.plot([0, x1], [0, 0], color="k", lw=2.2, solid_capstyle="butt")
    ax.plot([x1, x2, x2], [0, 0, z2], color="k", lw=2.2, solid_capstyle="butt")
    ax.plot([x2, x3 + 0.1], [z2, z2], color="k", lw=2.2, solid_capstyle="butt")
    ax.add_patch(Circle((x1, 0), 0.012, fc="white", ec=HINGE_COLORS["flap"], lw=2.2, zorder=4))
    ax.plot([x2, x2], [z2 - 0.02, z2 + 0.02], color=HINGE_COLORS["lag"], lw=4, solid_capstyle="butt",
            zorder=4)
    ax.add_patch(Rectangle((x3 - 0.03, z2 - 0.01), 0.06, 0.02, fc=HINGE_COLORS["pitch"], ec="k",
                           lw=0.6, zorder=4))
    ax.text(x1, 0.018, "flap", fontsize=7, ha="center", va="bottom", color=HINGE_COLORS["flap"])
    ax.text(x2 + 0.012, z2 - 0.022, "lag", fontsize=7, ha="left", va="top", color=HINGE_COLORS["lag"])
    ax.text(x3, z2 - 0.014, "pitch", fontsize=7, ha="center", va="top", color=HINGE_COLORS["pitch"])
    _dim(ax, (x2 + 0.03, 0), (x2 + 0.03, z2), "")
    ax.text(x2 + 0.045, 0.045, f"$e_2$ = {data.hub_lengths[1]:.4f} m\n(lag hinge below the flap hinge)",
            fontsize=7, va="center")
    ax.plot([x1, x3 + 0.1], [0, 0], color="0.6", lw=0.6, ls=":")
    _hub_x_dims(ax, data, -0.085, 0.035)
    # flap sense
    _arrow(ax, (x3 + 0.07, z2 - 0.003), (x3 + 0.09, z2 + 0.035), color=HINGE_COLORS["flap"], lw=1.2,
           connectionstyle="arc3,rad=0.3")
    ax.text(x3 + 0.095, z2 + 0.03, r"$\beta > 0$" + "\n(tip up)", fontsize=7, color=HINGE_COLORS["flap"],
            va="center")
    _axes_triad(ax, (x3 + 0.08, -0.17), (1, 0), (0, 1), ("$x_H$", "$z_H$"), 0.035)
    ax.set_xlim(-0.04, x3 + 0.17)
    ax.set_ylim(-0.2, 0.085)
    ax.set_aspect("equal")
    ax.set_xlabel("$x_H$ (m)")
    ax.set_ylabel("$z_H$ (m)")
    ax.set_title("(c) hub, side view from the trailing edge", fontsize=9, loc="left")


def plot_section(data: SchematicData, ax) -> None:
    """A blade section seen from the tip (y_B to the leading edge, right; z_B up): pitch axis,
    aerodynamic centre, the three C.G. positions, and the senses of pitch and air flow."""
    c = data.chord
    xp = data.pitch_axis
    out = _airfoil_outline()
    y = (xp - out[:, 0]) * c  # leading edge (x = 0) at +xp c, pitch axis at 0
    z = out[:, 1] * c
    ax.fill(y, z, fc="0.9", ec="k", lw=0.9)
    ax.plot([xp * c, -(1 - xp) * c], [0, 0], color="0.5", lw=0.6, ls=":")
    # points on the chord
    ax.plot(0, 0, "o", ms=9, mfc="white", mec="tab:red", mew=1.8, zorder=5)
    ax.plot(0, 0, "+", ms=9, color="tab:red", mew=1.5, zorder=6)
    ya = (xp - data.aerodynamic_centre) * c
    ax.plot(ya, 0, "^", ms=7, color="tab:orange", zorder=6)
    ax.annotate(f"pitch axis {xp:.2f}$c$", (0, 0), (-0.12, 0.11), fontsize=7.5, color="tab:red",
                ha="right", arrowprops=dict(arrowstyle="-", color="tab:red", lw=0.6))
    ax.annotate(f"aerodynamic centre {data.aerodynamic_centre:.3f}$c$", (ya, 0), (-0.05, 0.13),
                fontsize=7.5, color="tab:orange", ha="left",
                arrowprops=dict(arrowstyle="-", color="tab:orange", lw=0.6))
    text_at = {"forward": ((0.07, -0.1), "left"), "neutral": ((0.0, -0.13), "center"),
               "backward": ((-0.07, -0.1), "right")}
    for name, xc in data.cg_positions.items():
        yc = (xp - xc) * c
        ax.plot(yc, 0, "o", ms=3.5, color=CG_COLORS[name], zorder=7)
        (tx, ty), ha = text_at.get(name, ((yc, -0.1), "center"))
        ax.annotate(f"C.G. {CG_ROMAN[name]} ({name}) {xc:.3g}$c$", (yc, 0), (tx, ty), fontsize=7,
                    color=CG_COLORS[name], ha=ha,
                    arrowprops=dict(arrowstyle="-", color=CG_COLORS[name], lw=0.6))
    ax.text(xp * c + 0.01, 0.0, "LE", fontsize=7.5, va="center")
    ax.text(-(1 - xp) * c - 0.01, 0.0, "TE", fontsize=7.5, va="center", ha="right")
    # senses
    _axes_triad(ax, (-0.34, 0.05), (1, 0), (0, 1), ("$y_B$", "$z_B$"), 0.05)
    _arrow(ax, (0.125, 0.005), (0.105, 0.05), color=HINGE_COLORS["pitch"], lw=1.2,
           connectionstyle="arc3,rad=0.3")
    ax.text(0.125, 0.05, r"$\theta > 0$: nose up", fontsize=7.5, color=HINGE_COLORS["pitch"],
            ha="left", va="bottom")
    _arrow(ax, (0.28, -0.035), (0.16, -0.035), color="tab:blue", lw=1.0)
    ax.text(0.22, -0.045, "air (hover)", fontsize=7, color="tab:blue", ha="center", va="top")
    ax.set_xlim(-0.38, 0.3)
    ax.set_ylim(-0.15, 0.16)
    ax.set_aspect("equal")
    ax.set_xlabel("$y_B$ from the pitch axis (m)")
    ax.set_ylabel("$z_B$ (m)")
    ax.set_title("(d) section seen from the tip ($x_B$ towards the viewer)", fontsize=9, loc="left")


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
    """

    alpha: np.ndarray
    names: tuple
    cl: np.ndarray
    cd: np.ndarray
    cm: np.ndarray


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
    return CoefficientData(alpha=alpha, names=names, cl=np.array(cl), cd=np.array(cd), cm=np.array(cm))


_COEFF_LABELS = {"cl": "$c_l$", "cd": "$c_d$", "cm": "$c_m$ about the a.c."}
_AIRFOIL_STYLES = (dict(color="k", lw=1.3), dict(color="tab:orange", lw=1.2, ls="--"))


def plot_coefficient(data: CoefficientData, ax, coefficient: str = "cl",
                     alpha_range: tuple[float, float] = (-180.0, 180.0),
                     ylim: tuple[float, float] | None = None, legend: bool = True) -> None:
    """One coefficient (``"cl"``, ``"cd"`` or ``"cm"``) of every airfoil against alpha (deg)."""
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
        ax.text(-135, 0.96, "reverse flow", transform=ax.get_xaxis_transform(), fontsize=7,
                ha="center", va="top", color="tab:blue")
        ax.text(135, 0.96, "reverse flow", transform=ax.get_xaxis_transform(), fontsize=7,
                ha="center", va="top", color="tab:blue")
        ax.set_xticks(np.arange(-180, 181, 45))
    ax.axhline(0, color="0.6", lw=0.5)
    ax.axvline(0, color="0.6", lw=0.5)
    ax.set_xlim(lo, hi)
    if ylim is not None:
        ax.set_ylim(*ylim)
    ax.set_ylabel(_COEFF_LABELS[coefficient])
    ax.grid(alpha=0.3)
    if legend:
        ax.legend(fontsize=7, loc="lower right")


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

    ``alpha_range`` (deg) zooms the vertical axis; default: the full circle."""
    colors = ("k", "tab:red", "tab:orange", "tab:blue", "tab:purple", "tab:green")
    for k, (mu, psi) in enumerate(data.cases):
        label = "hover" if mu == 0 else rf"$\mu$ = {mu:g}, $\psi$ = {psi:.0f}$^\circ$"
        # break the line where alpha wraps through +-180 deg
        a_plot = data.alpha[k].astype(float)
        r_plot = data.r_over_R.astype(float)
        idx = np.nonzero(np.abs(np.diff(a_plot)) > 180)[0] + 1
        a_plot = np.insert(a_plot, idx, np.nan)
        r_plot = np.insert(r_plot, idx, np.nan)
        ax.plot(r_plot, a_plot, color=colors[k % len(colors)], lw=1.3, label=label)
        ax.plot(data.stations, data.alpha_stations[k], "o", color=colors[k % len(colors)], ms=3.5)
    ax.axhline(0, color="0.6", lw=0.5)
    ax.axvspan(0, data.root_r_over_R, color="0.85", lw=0)
    if alpha_range is None:
        for s in (-1, 1):
            ax.axhspan(s * 90, s * 180, color="tab:blue", alpha=0.06, lw=0)
            ax.text(0.99, s * 135, "reverse flow", fontsize=7, color="tab:blue", ha="right",
                    va="center")
        ax.text(0.5 * data.root_r_over_R, 0, "root\ncutout", fontsize=7, ha="center",
                va="center", rotation=90)
        ax.set_yticks(np.arange(-180, 181, 45))
        ax.set_ylim(-185, 185)
    else:
        ax.set_ylim(*alpha_range)
    ax.set_xlim(0, 1)
    ax.set_xlabel("$r/R$")
    ax.set_ylabel(r"angle of attack $\alpha$ (deg)")
    ax.grid(alpha=0.3)
    if legend:
        ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(0.16, 1.0))


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


def plot_cg_sweep(data: CGSweepData, ax, part: str = "real") -> None:
    """Real parts (``part="real"``) or frequencies (``"imag"``) of the hover modes against the
    C.G. position, coloured by dominant hinge."""
    f = np.real if part == "real" else np.imag
    for h, name in enumerate(HINGES):
        sel = data.hinges == h
        xs = np.broadcast_to(data.cg[:, None], data.hinges.shape)[sel]
        ax.plot(xs, f(data.eigenvalues[sel]), "o", ms=4, color=HINGE_COLORS[name],
                label=f"{name}-dominated mode")
    if part == "real":
        ax.plot(data.cg, data.pitch_growth, "-", color=HINGE_COLORS["pitch"], lw=0.8, alpha=0.6)
        ax.plot(data.cg, data.largest_real, ":", color="0.3", lw=0.8)
        ax.axhline(0, color="k", lw=0.8)
        ax.set_ylabel(r"growth rate Re $s$ (1/rev)")
        for x, lab in ((data.flutter_cg, "flutter"), (data.divergence_cg, "divergence")):
            if np.isfinite(x):
                ax.axvline(x, color="0.3", lw=0.8, ls="--")
                ax.text(x, 0.97, f" {lab}\n {x:.3f}$c$", transform=ax.get_xaxis_transform(),
                        fontsize=7, va="top")
    else:
        ax.set_ylabel(r"frequency Im $s$ (1/rev)")
        ax.set_yscale("symlog", linthresh=0.1)
    ax.axvline(data.aerodynamic_centre, color="tab:orange", lw=1.0,
               label=f"aerodynamic centre {data.aerodynamic_centre:.3f}$c$")
    ax.axvline(data.pitch_axis, color="tab:red", lw=1.0, ls="-.",
               label=f"pitch axis {data.pitch_axis:.2f}$c$")
    for name, x in CG_POSITIONS.items():
        ax.text(x, 1.01, CG_ROMAN[name], transform=ax.get_xaxis_transform(), ha="center",
                va="bottom", fontsize=8, color=CG_COLORS[name])
    ax.set_xlabel("section C.G., fraction of chord behind the leading edge")
    ax.grid(alpha=0.3)


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
    (:func:`rotorlyap.figures.export.markdown_table`)."""
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


def assumption_rows(params: BladeParameters) -> list[tuple[str, str, str, str]]:
    """(field, value, unit, source) for every field whose source contains "assumed"."""
    return [(f"`{name}`", format_value(value), unit, source)
            for name, value, unit, source in parameter_table(params) if "assumed" in source]
