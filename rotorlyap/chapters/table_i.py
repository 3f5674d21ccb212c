"""Figures, tables and printed numbers of chapter 4, Table I.

The conventions every chapter's module follows (data objects, ``summary()``, ``facts()``,
``plot_*`` and ``figure_*``) are in :mod:`rotorlyap.chapters`.

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

Chapter 3 (the blade model) is in :mod:`rotorlyap.chapters.blade_model`; the classical flap
frequency with pitch-flap coupling, which both chapters quote, in
:mod:`rotorlyap.chapters.blade_formulas`.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from dataclasses import dataclass, fields, replace
from typing import Any, Sequence

import numpy as np
from matplotlib.figure import Figure

from ..conventions import HINGES
from ..model.airfoil import NACA23012, NACA23012_SOURCES
from ..model.modes import (
    DerivedQuantities,
    Mode,
    chordwise_lag_offset_angle,
    derived_quantities,
    hover_modes,
    least_damped,
    pitch_mode,
)
from ..model.parameters import CG_POSITIONS, THIN_AIRFOIL_CM_Q, BladeParameters, parameter_table
from ..reporting import Rounded
from .blade_formulas import effective_flap_frequency
from .export import markdown_table as _markdown_table
from .style import CG_COLORS, CG_ROMAN, HINGE_COLORS, figure, finish

__all__ = [
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
