"""Figures of the reproduction chapters (the paper's Figs 4-8): a data function and a drawing
function each.

Data functions return frozen dataclasses of arrays (no plotting) and take their grids as
arguments, so that the notebooks, the benchmark and the tests can choose the resolution;
drawing functions (``plot_*``) take that data and matplotlib ``Axes``, and ``figure_*``
functions create, draw, lay out and return the whole figure of a chapter (closed in pyplot,
so that a notebook shows it only where it is glued). The data objects of chapters 5 and 6
have a ``summary()`` (the text its chapter prints, rounded to the digits the computation
determines) and a ``facts()`` (the numbers its chapter quotes, ``{glue name: value}``, for
:func:`rotorlyap.chapters.export.glue_facts`). Every quantity computed in a
reading carries that reading's label, :data:`READING_LABELS`: the strict reading (suprema
and infima over whole spheres, the theorem as stated) is a certificate as far as the search
is exhaustive; the practical reading (``W`` and ``W'`` only along test disturbances) is an
indicator, never a certificate.

Conventions (``.notes/BLADE_SPEC.md``): azimuth ``psi = 0`` with the blade pointing aft
(over the tail), rotation counter-clockwise seen from above, so ``psi = 90 deg`` is the
advancing side and ``psi = 270 deg`` the retreating side.
"""

from __future__ import annotations

import re

from dataclasses import dataclass, replace

import numpy as np
from scipy.optimize import brentq

from ..analysis.functions import energy_function, energy_rate_terms
from ..analysis.stability import blade_stability
from ..conventions import DEFAULT_A, DEFAULT_SCALES, PAPER_TEST_DISTURBANCES
from ..errors import TrimError
from ..methods.sampling import sphere_extremum, unit_sphere_points
from ..model.blade import Blade
from ..model.modes import Mode, hover_modes, least_damped, pitch_mode
from ..model.parameters import CG_POSITIONS, BladeParameters
from ..model.trim import hover_trim
from ..reporting import Rounded, decade_above, format_small
from .export import markdown_table  # the claims table; also re-exported for the chapters
from .style import (CATEGORY_COLORS, CATEGORY_HATCHES, CG_COLORS, CG_MARKERS, HATCH_COLOR, HATCH_LINEWIDTH,
                    HINGE_COLORS, HINGE_LINESTYLES, draw_categories, figure, finish, subplots)

__all__ = [
    "READING_LABELS", "CASES", "MU_GRID", "MU_GRID_STRICT", "STATE_LABELS",
    "FLAP_LAG_TEST_DISTURBANCES", "AXES_AND_DIAGONALS", "THRESHOLD_TEST_SETS",
    "case_params", "cg_sweep", "balanced_scales", "practical_threshold_mu", "reverse_flow_boundary",
    "disturbance_names", "category_legend_handles", "REVERSE_FLOW_HATCH",
    "HoverSweep", "hover_sweep",
    "HoverTrimData", "hover_trim_data", "plot_hover_trim", "figure_hover_trim",
    "TrimLimitData", "trim_limit_data",
    "HoverModesData", "hover_modes_data",
    "HoverReadingsData", "hover_readings_data", "SearchCheckData", "search_check",
    "HoverRateData", "hover_rate_data", "plot_hover_rate", "figure_hover_rate",
    "HoverDivergenceData", "hover_divergence_data",
    "UnbalancedLoadsData", "unbalanced_loads_data",
    "WSpheresData", "w_spheres_data", "plot_w_spheres", "figure_w_spheres",
    "RateAzimuthData", "rate_azimuth_data", "plot_rate_azimuth", "figure_rate_azimuth",
    "RegionsData", "regions_data", "plot_regions_polar", "plot_regions_plane",
    "RegionMaps", "region_maps", "figure_regions_polar", "figure_regions_plane",
    "HoverFlutterCheck", "hover_flutter_check", "ThresholdData", "practical_threshold_data",
    "CATEGORY_NAMES", "SensitivityData", "sensitivity_data", "plot_sensitivity", "figure_sensitivity",
    "ConvergenceData", "convergence_data", "plot_convergence", "figure_convergence",
    "CLAIMS_HEADER", "ClaimsTable", "claims_table",
    "markdown_table",
]

#: How each reading is labelled everywhere in the book.
READING_LABELS = {
    "strict": "strict (numerical certificate)",
    "practical": "practical (indicator, not a certificate)",
}

def _plain(tex: str) -> str:
    """A state or axis name of a plot label (``"+\\beta'"``, ``"$\\zeta$"``) in plain text for a
    printout (``"+beta'"``, ``"zeta"``): TeX is for the figures only."""
    return tex.replace("$", "").replace("\\", "")


#: The paper's three cases (Table I computation parameters), in order.
CASES = ("forward", "neutral", "backward")

#: Advance ratios of Fig. 8 in the practical reading: 0 to 0.25, finer near hover.
MU_GRID = (0.0, 0.0125, 0.025, 0.05, 0.075, 0.1, 0.125, 0.15, 0.175, 0.2, 0.225, 0.25)

#: Advance ratios of Fig. 8 in the strict reading (each costs a sphere search per azimuth).
MU_GRID_STRICT = (0.0, 0.05, 0.1, 0.15, 0.2, 0.25)

# TeX labels of the six state components (plot labels; kept out of the API page).
STATE_LABELS = (r"$\beta$", r"$\zeta$", r"$\theta$", r"$\beta'$", r"$\zeta'$", r"$\theta'$")

#: Test disturbances without the pitch rate: the eight signed flap and lag axes.
FLAP_LAG_TEST_DISTURBANCES = PAPER_TEST_DISTURBANCES[[0, 1, 3, 4, 6, 7, 9, 10]]
FLAP_LAG_TEST_DISTURBANCES.setflags(write=False)

#: The 12 signed axes and the 60 signed diagonals of the coordinate planes.
AXES_AND_DIAGONALS = unit_sphere_points(6, 0)

_HINGES = ("flap", "lag", "pitch")


def case_params(cg, **overrides) -> BladeParameters:
    """Table I parameters for a named case ("forward", ...) or a C.G. position (fraction of chord)."""
    if isinstance(cg, str):
        return BladeParameters.table_i(cg, **overrides)
    return replace(BladeParameters.table_i("forward", **overrides), cg_position=float(cg))


def _colormaps():
    import matplotlib

    return matplotlib.colormaps


class _Count:
    """Wrap a vectorised ``g(psi, x)`` and count the states it is evaluated at."""

    def __init__(self, fun):
        self.fun, self.n = fun, 0

    def __call__(self, psi, x):
        self.n += int(np.asarray(x).shape[0])
        return self.fun(psi, x)


def balanced_scales(params: BladeParameters, scales=None) -> np.ndarray:
    """Norm scales that give every signed axis the same energy ``W`` at ``||x|| = 1``.

    Each ``a_i`` of ``scales`` (default :data:`DEFAULT_SCALES`) is multiplied by
    ``sqrt(W_ref / W_i)``, with ``W_i`` the mean of ``W`` at ``+a_i e_i`` and ``-a_i e_i``
    about the hover equilibrium and ``W_ref`` their geometric mean (``W`` is nearly
    quadratic at these amplitudes, so one correction suffices).
    """
    a = np.array(DEFAULT_SCALES if scales is None else scales, dtype=float)
    blade = Blade(params, 0.0)
    fun = energy_function(blade)
    eye = np.eye(6)
    w = 0.5 * (fun.W(0.0, eye * a) + fun.W(0.0, -eye * a))
    ref = float(np.exp(np.mean(np.log(w))))
    return a * np.sqrt(ref / w)


def reverse_flow_boundary(params: BladeParameters, psi: np.ndarray) -> np.ndarray:
    """Advance ratio above which reverse flow reaches the blade root, at each azimuth.

    The reverse-flow region is ``r/R < mu |sin psi|`` on the retreating side
    (``180 < psi < 360`` deg); it reaches the aerodynamic span, which starts at
    ``r/R = (R - R1)/R``, when ``mu > (R - R1)/(R |sin psi|)``. Returns ``inf`` on the
    advancing side.
    """
    psi = np.asarray(psi, dtype=float)
    s = -np.sin(psi)
    with np.errstate(divide="ignore"):
        return np.where(s > 1e-12, params.root_r_over_R / np.where(s > 1e-12, s, 1.0), np.inf)


def cg_sweep(step: float = 0.01, n_side: int = 4) -> np.ndarray:
    """C.G. positions from ``n_side`` steps ahead of the neutral C.G. to ``n_side`` behind it.

    Parameters
    ----------
    step : float
        Spacing, fraction of chord.
    n_side : int
        Steps on either side of the neutral C.G.

    Returns
    -------
    numpy.ndarray
        ``2 n_side + 1`` positions, fraction of chord behind the leading edge, rounded to
        0.001 c (the sweep is an input, stated exactly).
    """
    return np.round(CG_POSITIONS["neutral"] + step * np.arange(-n_side, n_side + 1), 3)


def disturbance_names(test_disturbances) -> tuple[str, ...]:
    """TeX names (without ``$``) of test disturbances along signed axes, ``"+\\beta'"`` etc.

    Each direction is named after its largest component and that component's sign.
    """
    names = []
    for d in np.asarray(test_disturbances, dtype=float):
        k = int(np.argmax(np.abs(d)))
        names.append(("+" if d[k] > 0 else "-") + STATE_LABELS[k].strip("$"))
    return tuple(names)


def _line(*parts) -> str:
    """One printed line, the way ``print(*parts)`` writes it."""
    return " ".join(str(p) for p in parts)


#: Hatch of the region where reverse flow reaches the blade root, drawn over the verdict maps
#: with an outline: vertical lines, unlike the diagonal and dotted hatches of the verdicts
#: (:data:`rotorlyap.chapters.style.CATEGORY_HATCHES`).
REVERSE_FLOW_HATCH = "||"



def category_legend_handles(reverse_flow_label: str = "reverse flow reaches the blade root", *,
                            wrap: int | None = None) -> list:
    """Legend handles of the region maps: one patch per :data:`CATEGORY_NAMES`, in its colour and
    hatch, and the outlined, hatched reverse-flow region; ``wrap`` breaks the labels into lines
    of at most that many characters."""
    import textwrap

    from matplotlib.patches import Patch

    def lab(text):
        return text if wrap is None else "\n".join(textwrap.wrap(text, wrap))

    handles = [Patch(facecolor=c, hatch=h, edgecolor="0.3", hatchcolor=HATCH_COLOR, lw=0.6, label=lab(n),
                     hatch_linewidth=HATCH_LINEWIDTH)
               for c, h, n in zip(CATEGORY_COLORS, CATEGORY_HATCHES, CATEGORY_NAMES)]
    handles.append(Patch(facecolor="none", edgecolor="k", hatch=REVERSE_FLOW_HATCH, hatchcolor="k", lw=1.5,
                         label=lab(reverse_flow_label)))
    return handles


# --------------------------------------------------------------------------------------
# Chapter 5: the inputs
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class HoverSweep:
    """The inputs of the hover chapter: the cases, the C.G. sweep, the sphere and the readings.

    Attributes
    ----------
    cg : numpy.ndarray
        C.G. positions of the sweep, fraction of chord behind the leading edge, (k,).
    case_names : tuple of str
        The paper's cases.
    case_cg : numpy.ndarray
        Their C.G. positions, fraction of chord, (3,).
    A : float
        Radius of the sphere ``||x|| = A`` examined (scaled norm), -.
    scales : numpy.ndarray
        Norm scales ``a_i``: rad for the angles, rad/rad for the rates, (6,).
    """

    cg: np.ndarray
    case_names: tuple
    case_cg: np.ndarray
    A: float
    scales: np.ndarray

    def summary(self) -> str:
        """The cases, the sweep, the scales (deg, deg/rad) and ``A``."""
        lines = [
            "C.G. of the cases (c): " + ", ".join(f"{k} {c:.3f}" for k, c in zip(self.case_names, self.case_cg)),
            _line("C.G. sweep (c):", self.cg),
            _line("scales a_i (deg, deg/rad):", np.round(np.degrees(self.scales), 2), "; A =", self.A),
        ]
        return "\n".join(lines)

    def facts(self) -> dict:
        """``ch5_cg_<case>`` (fraction of chord) and the ends of the sweep ``ch5_sweep_lo/hi``."""
        out = {f"ch5_cg_{name}": round(float(c), 3) for name, c in zip(self.case_names, self.case_cg)}
        out["ch5_sweep_lo"] = float(self.cg[0])
        out["ch5_sweep_hi"] = float(self.cg[-1])
        return out


def hover_sweep(step: float = 0.01, n_side: int = 4, *, cases=CASES, A: float = DEFAULT_A,
                scales=None) -> HoverSweep:
    """The hover chapter's inputs: :func:`cg_sweep` ``(step, n_side)``, the cases, ``A`` and the
    scales (default :data:`rotorlyap.conventions.DEFAULT_SCALES`)."""
    return HoverSweep(
        cg=cg_sweep(step, n_side), case_names=tuple(cases),
        case_cg=np.array([CG_POSITIONS[c] for c in cases]), A=float(A),
        scales=np.array(DEFAULT_SCALES if scales is None else scales, dtype=float),
    )


# --------------------------------------------------------------------------------------
# Fig. 4: hover trim
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class HoverTrimData:
    """Hover trim (thrust = weight) against the section C.G. position.

    Attributes
    ----------
    cg : numpy.ndarray
        Section C.G. positions of the sweep, fraction of chord behind the leading edge, (k,).
    collective : numpy.ndarray
        Trimmed collective pitch, rad, (k,).
    equilibrium : numpy.ndarray
        Equilibrium flap, lag and pitch angles, rad, (k, 3).
    thrust : numpy.ndarray
        Rotor thrust at the trimmed equilibrium, N, (k,).
    weight : float
        Helicopter weight, N.
    case_names : tuple of str
        The paper's cases.
    case_cg, case_collective, case_thrust : numpy.ndarray
        The same for the cases, (3,).
    case_equilibrium : numpy.ndarray
        (3, 3), rad.
    pitch_axis, aerodynamic_centre : float
        Chordwise positions (fraction of chord) marked on the figure.
    thrust_coefficient, inflow : float
        ``C_T`` and the hover inflow ratio (the same for every C.G.).
    """

    cg: np.ndarray
    collective: np.ndarray
    equilibrium: np.ndarray
    thrust: np.ndarray
    weight: float
    case_names: tuple
    case_cg: np.ndarray
    case_collective: np.ndarray
    case_equilibrium: np.ndarray
    case_thrust: np.ndarray
    pitch_axis: float
    aerodynamic_centre: float
    thrust_coefficient: float
    inflow: float

    @property
    def max_trim_error(self) -> float:
        """Largest ``|thrust - weight|`` over the sweep and the cases, N."""
        return float(np.abs(np.concatenate([self.thrust, self.case_thrust]) - self.weight).max())

    def summary(self) -> str:
        """The cases' collective and equilibrium angles (deg) with the trim check, the sweep's
        collective and pitch angle (deg), the weight, ``C_T``, ``lambda_0`` and the marked
        chordwise positions."""
        lines = ["case       C.G.    collective  beta   zeta   theta (deg)   thrust - weight (N)"]
        for i, name in enumerate(self.case_names):
            ok = abs(self.case_thrust[i] - self.weight) < 1e-6
            lines.append(f"{name:9s}  {self.case_cg[i]:.3f}  {np.degrees(self.case_collective[i]):8.2f}  "
                         + "  ".join(f"{v:5.2f}" for v in np.degrees(self.case_equilibrium[i]))
                         + f"   {'below 1e-6' if ok else 'TRIM ERROR'}")
        lines += [
            _line("sweep collective (deg):", np.round(np.degrees(self.collective), 2)),
            _line("sweep theta (deg):     ", np.round(np.degrees(self.equilibrium[:, 2]), 3)),
            "weight %.1f N; |thrust - weight| < 1e-6 N for every trim: %s; C_T = %.5f, inflow ratio lambda_i = %.4f" % (
                self.weight, self.max_trim_error < 1e-6, self.thrust_coefficient, self.inflow),
            "pitch axis %.3f c, aerodynamic centre %.3f c" % (self.pitch_axis, self.aerodynamic_centre),
        ]
        return "\n".join(lines)

    def facts(self) -> dict:
        """Chapter 5's trim numbers: ``ch5_col_<case>``, ``ch5_beta/zeta/theta_<case>`` (deg, 0.01),
        ``ch5_eq_spread`` (largest spread of an equilibrium angle over the cases, deg),
        ``ch5_weight`` (kN), ``ch5_ct``, ``ch5_lambda0``, ``ch5_pitch_axis`` and ``ch5_ac``
        (fraction of chord) and ``ch5_col_slope`` (collective change per 0.01 c of C.G., deg,
        from a straight-line fit over the sweep)."""
        out = {}
        for i, name in enumerate(self.case_names):
            out[f"ch5_col_{name}"] = Rounded(np.degrees(self.case_collective[i]), 2)
            for j, q in enumerate(("beta", "zeta", "theta")):
                out[f"ch5_{q}_{name}"] = Rounded(np.degrees(self.case_equilibrium[i, j]), 2)
        out["ch5_eq_spread"] = round(float(np.degrees(np.ptp(self.case_equilibrium, axis=0)).max()), 2)
        out["ch5_weight"] = round(self.weight / 1000, 2)
        out["ch5_ct"] = round(self.thrust_coefficient, 5)
        out["ch5_lambda0"] = round(self.inflow, 4)
        out["ch5_pitch_axis"] = round(self.pitch_axis, 3)
        out["ch5_ac"] = round(self.aerodynamic_centre, 3)
        slope = np.polyfit(self.cg, np.degrees(self.collective), 1)[0] / 100
        out["ch5_col_slope"] = round(float(slope), 3)
        return out


def hover_trim_data(cg_values=np.linspace(0.195, 0.275, 9), cases=CASES, **overrides) -> HoverTrimData:
    """Trim every C.G. of the sweep and every case (:func:`rotorlyap.hover_trim`)."""
    def trims(values):
        out = [hover_trim(case_params(v, **overrides)) for v in values]
        return (np.array([t.collective for t in out]), np.array([t.equilibrium[:3] for t in out]),
                np.array([t.thrust for t in out]), out)

    col, eq, thr, _ = trims(cg_values)
    ccol, ceq, cthr, ctr = trims(cases)
    p = case_params(cases[0], **overrides)
    return HoverTrimData(
        cg=np.asarray(cg_values, dtype=float), collective=col, equilibrium=eq, thrust=thr,
        weight=float(ctr[0].weight), case_names=tuple(cases),
        case_cg=np.array([case_params(c, **overrides).cg_position for c in cases]),
        case_collective=ccol, case_equilibrium=ceq, case_thrust=cthr,
        pitch_axis=float(p.pitch_axis), aerodynamic_centre=float(p.aerodynamic_centre),
        thrust_coefficient=float(ctr[0].thrust_coefficient), inflow=float(ctr[0].inflow),
    )


def plot_hover_trim(data: HoverTrimData, axes) -> None:
    """Left: the cases' angles as grouped bars, each labelled with its value; right: the C.G.
    sweep (deg), the collective in black and each hinge in its colour and line style."""
    ax, ax2 = axes
    names = ("collective", r"flap $\beta$", r"lag $\zeta$", r"pitch $\theta$")
    vals = np.degrees(np.column_stack([data.case_collective, data.case_equilibrium]))
    n = len(data.case_names)
    w = 0.9 / n
    xs = np.arange(len(names))
    for i, case in enumerate(data.case_names):
        bars = ax.bar(xs + (i - (n - 1) / 2) * w, vals[i], w, color=CG_COLORS.get(case, "0.6"), edgecolor="k",
                      lw=0.5, label=f"{case} C.G. ({data.case_cg[i]:.3g} c)")
        for b, v in zip(bars, vals[i]):
            ax.text(b.get_x() + b.get_width() / 2, v + 0.15, f"{v:.1f}", ha="center", fontsize=8)
    ax.set_xticks(xs, names, fontsize=9)
    ax.set_ylabel("angle (deg)", fontsize=9)
    ax.set_title("hover trim of the three cases (thrust = weight)", fontsize=10)
    ax.legend(fontsize=8, loc="upper left")
    ax.set_ylim(0, 1.4 * vals.max())
    ax.tick_params(axis="y", labelsize=8)
    series = (np.degrees(data.collective),) + tuple(np.degrees(data.equilibrium.T))
    styles = [("k", "-", "o")] + [(HINGE_COLORS[h], HINGE_LINESTYLES[h], m)
                                  for h, m in zip(_HINGES, ("s", "^", "d"))]
    for s, name, (c, ls, m) in zip(series, names, styles):
        ax2.plot(data.cg, s, color=c, ls=ls, marker=m, ms=4, label=name)
    ax2.axvline(data.pitch_axis, color="0.5", ls="--", lw=0.8)
    ax2.axvline(data.aerodynamic_centre, color="0.2", ls=":", lw=1.2)
    lo, hi = ax2.get_ylim()
    ax2.set_ylim(lo, hi + 0.12 * (hi - lo))
    ax2.text(data.pitch_axis, 0.98, " pitch axis", fontsize=8, va="top", color="0.4",
             transform=ax2.get_xaxis_transform())
    ax2.text(data.aerodynamic_centre, 0.98, "aero. centre ", fontsize=8, va="top", ha="right", color="0.2",
             transform=ax2.get_xaxis_transform())
    ax2.set_xlabel("section C.G. (fraction of chord behind the leading edge)", fontsize=9)
    ax2.set_ylabel("angle (deg)", fontsize=9)
    ax2.set_title("C.G. sweep", fontsize=10)
    ax2.tick_params(labelsize=8)
    # in the band between the lag and pitch angles, right of the collective's crossing
    y_leg = (ax2.transScale + ax2.transLimits).transform((0.0, 0.5 * (series[2].min() + series[3].max())))[1]
    ax2.legend(fontsize=8, loc="center right", bbox_to_anchor=(1.0, y_leg), framealpha=0.9)


def figure_hover_trim(data: HoverTrimData, figsize=(9.0, 4.2)):
    """The book's Fig. 4 (:func:`plot_hover_trim` on two panels), laid out and checked
    (:func:`rotorlyap.chapters.style.finish`); returns the Figure."""
    fig, axes = subplots(1, 2, figsize=figsize, gridspec_kw=dict(width_ratios=(1.2, 1)))
    plot_hover_trim(data, axes)
    return finish(fig)


@dataclass(frozen=True)
class TrimLimitData:
    """The aft end of the C.G.s that :func:`rotorlyap.model.trim.hover_trim` can trim.

    Behind it the branch of equilibria that starts at the unloaded blade already gives more
    thrust than the weight at zero collective, and the trim (positive collective only) fails.

    Attributes
    ----------
    cg_limit : float
        Largest C.G. found trimmable: the front end of the final bisection bracket, fraction
        of chord.
    cg_untrimmable : float
        Its back end (not trimmable), fraction of chord.
    tol : float
        Width of the final bracket, fraction of chord.
    """

    cg_limit: float
    cg_untrimmable: float
    tol: float

    def summary(self) -> str:
        """The limit, to 0.001 c."""
        return "hover trim with positive collective exists up to a C.G. of %.3f c" % self.cg_limit

    def facts(self) -> dict:
        """``ch5_trim_limit`` (fraction of chord, 0.001)."""
        return {"ch5_trim_limit": round(self.cg_limit, 3)}


def trim_limit_data(cg_lo: float, cg_hi: float = 0.30, *, tol: float = 1e-4, **overrides) -> TrimLimitData:
    """Bisect for the aft end of the trimmable C.G.s between ``cg_lo`` and ``cg_hi``.

    Parameters
    ----------
    cg_lo, cg_hi : float
        A trimmable and an untrimmable C.G., fraction of chord.
    tol : float
        Width of the final bracket, fraction of chord.
    **overrides
        Further :class:`~rotorlyap.model.parameters.BladeParameters` fields.

    Raises
    ------
    ValueError
        If ``cg_lo`` cannot be trimmed or ``cg_hi`` can (no limit between them).
    """
    def trims(cg: float) -> bool:
        try:
            hover_trim(case_params(float(cg), **overrides))
            return True
        except TrimError:
            return False

    lo, hi = float(cg_lo), float(cg_hi)
    if not trims(lo) or trims(hi):
        raise ValueError(f"trim_limit_data: need a trimmable cg_lo and an untrimmable cg_hi, got {lo:g}, {hi:g}")
    while hi - lo > tol:
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if trims(mid) else (lo, mid)
    return TrimLimitData(cg_limit=lo, cg_untrimmable=hi, tol=float(tol))


# --------------------------------------------------------------------------------------
# Chapter 5: linear modes in hover
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class HoverModesData:
    """Linear modes of the cases at their hover equilibria, with and without the aerodynamic
    pitch damping (:func:`rotorlyap.model.modes.hover_modes`).

    Eigenvalues are per radian of azimuth (units of Omega); each complex pair counts once.

    Attributes
    ----------
    case_names : tuple of str
    case_cg : numpy.ndarray
        Fraction of chord, (3,).
    modes : tuple of tuple of rotorlyap.model.modes.Mode
        Per case, least damped (largest growth rate) first.
    modes_without_pitch_damping : tuple of tuple of rotorlyap.model.modes.Mode
        The same with ``cm_pitch_rate = 0``.
    """

    case_names: tuple
    case_cg: np.ndarray
    modes: tuple
    modes_without_pitch_damping: tuple

    def _index(self, case: str) -> int:
        return self.case_names.index(case)

    def least_damped(self, case: str) -> Mode:
        """The mode with the largest growth rate of ``case``."""
        return least_damped(self.modes[self._index(case)])

    def pitch(self, case: str, pitch_damping: bool = True) -> Mode:
        """The pitch mode of ``case`` (:func:`rotorlyap.model.modes.pitch_mode`)."""
        modes = self.modes if pitch_damping else self.modes_without_pitch_damping
        return pitch_mode(modes[self._index(case)])

    def decay_revolutions(self, case: str) -> float:
        """Revolutions in which the least-damped mode of ``case`` decays by a factor e, rev."""
        return 1.0 / (2 * np.pi * abs(self.least_damped(case).growth_rate))

    def summary(self, decay_case: str = "backward") -> str:
        """The modes table (eigenvalue; sizes of the flap, lag and pitch angles, largest = 1),
        the decay time of ``decay_case``'s least-damped mode and the pitch modes without the
        aerodynamic pitch damping (3 decimals per rev)."""
        lines = ["case       C.G.   eigenvalue (per rev, i.e. in units of Omega; freq. in /rev)     "
                 "|beta| |zeta| |theta|"]
        for name, cg, modes in zip(self.case_names, self.case_cg, self.modes):
            for m in modes:
                z, s = m.eigenvalue, m.shape
                kind = "real root" if z.imag == 0 else "pair"
                lines.append(f"{name:9s}  {cg:.3f}  {z.real:+.3f} {'+-' if z.imag else '  '} {z.imag:.3f}j  {kind:9s}"
                             f"                   {s[0]:4.2f}   {s[1]:4.2f}   {s[2]:4.2f}")
        lines.append(f"{decay_case} C.G.: the least-damped mode decays by a factor e in "
                     f"{self.decay_revolutions(decay_case):.0f} rev")
        lines.append("pitch mode without the aerodynamic pitch damping (cm_pitch_rate = 0), real part:")
        for name in self.case_names:
            z = self.pitch(name, pitch_damping=False).eigenvalue
            lines.append(f"  {name:9s} {z.real:+.3f} +- {z.imag:.3f}j")
        return "\n".join(lines)

    def facts(self) -> dict:
        """Chapter 5's linear numbers (per rev): ``ch5_re_<case>`` (least-damped growth rate),
        ``ch5_pitch_re_<case>`` and ``ch5_pitch_freq_<case>`` (pitch mode),
        ``ch5_freq_forward`` and ``ch5_lag_share_forward`` (frequency of the forward C.G.'s
        least-damped mode and the larger of its flap and pitch parts), ``ch5_tau_backward``
        (rev, :meth:`decay_revolutions`) and ``ch5_pitch_re0_<case>`` (pitch mode without the
        aerodynamic pitch damping)."""
        out = {}
        for name in self.case_names:
            pm = self.pitch(name)
            out[f"ch5_re_{name}"] = round(float(self.least_damped(name).growth_rate), 3)
            out[f"ch5_pitch_re_{name}"] = Rounded(pm.growth_rate, 2)
            out[f"ch5_pitch_freq_{name}"] = Rounded(pm.frequency, 2)
        fwd = self.least_damped("forward")
        out["ch5_freq_forward"] = round(float(fwd.frequency), 3)
        out["ch5_lag_share_forward"] = round(float(max(fwd.shape[0], fwd.shape[2])), 2)
        out["ch5_tau_backward"] = round(float(self.decay_revolutions("backward")))
        for name in self.case_names:
            out[f"ch5_pitch_re0_{name}"] = round(float(self.pitch(name, pitch_damping=False).growth_rate), 3)
        return out


def hover_modes_data(cases=CASES) -> HoverModesData:
    """Linear modes in hover of each case, with the aerodynamic pitch damping and without it
    (``cm_pitch_rate = 0``)."""
    def ordered(params):
        return tuple(sorted(hover_modes(params), key=lambda m: -m.growth_rate))

    return HoverModesData(
        case_names=tuple(cases), case_cg=np.array([CG_POSITIONS[c] for c in cases]),
        modes=tuple(ordered(case_params(c)) for c in cases),
        modes_without_pitch_damping=tuple(ordered(case_params(c, cm_pitch_rate=0.0)) for c in cases),
    )


# --------------------------------------------------------------------------------------
# Chapter 5: the algorithm in hover, both readings
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class HoverReadingsData:
    """The whole algorithm (:func:`rotorlyap.analysis.stability.blade_stability`) in hover for
    each case, in both readings.

    Attributes
    ----------
    case_names : tuple of str
    strict : tuple of TechnicalStabilityResult
        Whole spheres, per case.
    practical : tuple of TechnicalStabilityResult
        Along the test disturbances, per case.
    """

    case_names: tuple
    strict: tuple
    practical: tuple

    def summary(self) -> str:
        """Per case: each reading's verdict; the strict maximiser of ``W'`` in scaled
        coordinates; the practical bound, start region and largest ``W'`` on the shells (J/rad)."""
        lines = []
        for name, s, q in zip(self.case_names, self.strict, self.practical):
            lines += [
                f"{name} C.G.",
                f"  {READING_LABELS[s.reading]}: {s.message}",
                f"     argmax of W' on the sphere, x_i/a_i: {np.round(s.argmax_dW[0] / s.scales, 2) + 0.0}",
                f"  {READING_LABELS[q.reading]}: {q.message}; A = {q.A:.2f}, "
                f"lambda0 = {q.lambda0.min():.4f}, max W' on the shells = {q.max_dW.max():.1f} J/rad",
            ]
        return "\n".join(lines)

    def facts(self) -> dict:
        """``ch5_step3_<case>`` (strict step-3 maximum of ``W'``, J/rad, 0.1),
        ``ch5_prac_stable_<case>`` (practical stable azimuths) and ``ch5_prac_lambda0`` (the
        forward C.G.'s practical start region, 0.001)."""
        out = {}
        for name, s, q in zip(self.case_names, self.strict, self.practical):
            out[f"ch5_step3_{name}"] = Rounded(s.step3_max_dW, 1)
            out[f"ch5_prac_stable_{name}"] = int(q.stable.sum())
        out["ch5_prac_lambda0"] = round(float(self.practical[self.case_names.index("forward")].lambda0.min()), 3)
        return out


def hover_readings_data(cases=CASES, *, n_psi: int = 24,
                        test_disturbances=PAPER_TEST_DISTURBANCES) -> HoverReadingsData:
    """Run the algorithm in hover for each case: strict (the engine's default search) and
    practical (along ``test_disturbances``), on ``n_psi`` azimuths (nothing depends on the
    azimuth in hover)."""
    strict, practical = [], []
    for name in cases:
        p = case_params(name)
        strict.append(blade_stability(p, 0.0, n_psi=n_psi))
        practical.append(blade_stability(p, 0.0, n_psi=n_psi, test_disturbances=test_disturbances))
    return HoverReadingsData(case_names=tuple(cases), strict=tuple(strict), practical=tuple(practical))


# --------------------------------------------------------------------------------------
# Fig. 5: W' in hover against the C.G.
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class HoverRateData:
    """``W'`` in hover against the C.G. position, in both readings, with the linear verdict.

    Attributes
    ----------
    cg : numpy.ndarray
        C.G. positions, (k,).
    A : float
        Radius of the sphere examined.
    scales : numpy.ndarray
        Norm scales.
    strict_max : numpy.ndarray
        Largest ``W'`` found on the sphere ``||x|| = A`` (sampling + refinement), (k,), J/rad.
    strict_argmax : numpy.ndarray
        Where, in scaled coordinates ``x_i / a_i``, (k, 6).
    strict_positive_fraction : numpy.ndarray
        Fraction of ``n_fraction`` quasi-random points of the sphere with ``W' > 0``, (k,).
    terms_damping, terms_aero : numpy.ndarray
        :func:`rotorlyap.analysis.stability.energy_rate_terms` at the argmax: work rates of the
        dampers and of the aerodynamic load change on each hinge, (k, 3), J/rad.
    practical_dW : numpy.ndarray
        ``W'`` at ``A`` times each test disturbance, (k, n_test), J/rad.
    practical_max : numpy.ndarray
        Largest of them, (k,).
    practical_shell_max : numpy.ndarray
        The engine's step-6 ``max W'`` on the shell along the test disturbances, (k,).
    test_disturbances : numpy.ndarray
        The practical reading's directions, (n_test, 6).
    eig_max_real, eig_freq : numpy.ndarray
        Largest real part of the eigenvalues of the linearised hover equations (per
        radian of azimuth, i.e. in units of Omega) and the frequency of that mode (/rev), (k,).
    eig_real_root : numpy.ndarray
        Largest real eigenvalue (a divergence when > 0), (k,); nan if none is real.
    slice_cg : float
        The C.G. of the slice.
    slice_theta, slice_betadot : numpy.ndarray
        Axes of the slice: the plane of pitch displacement and flap rate, scaled units.
    slice_dW : numpy.ndarray
        ``W'`` on that plane, (len(slice_betadot), len(slice_theta)), J/rad.
    strict_label, practical_label : str
        :data:`READING_LABELS` of the two readings.
    n_evaluations : int
        States at which ``W'`` was evaluated.
    """

    cg: np.ndarray
    A: float
    scales: np.ndarray
    strict_max: np.ndarray
    strict_argmax: np.ndarray
    strict_positive_fraction: np.ndarray
    terms_damping: np.ndarray
    terms_aero: np.ndarray
    practical_dW: np.ndarray
    practical_max: np.ndarray
    practical_shell_max: np.ndarray
    test_disturbances: np.ndarray
    eig_max_real: np.ndarray
    eig_freq: np.ndarray
    eig_real_root: np.ndarray
    slice_cg: float
    slice_theta: np.ndarray
    slice_betadot: np.ndarray
    slice_dW: np.ndarray
    strict_label: str
    practical_label: str
    n_evaluations: int

    def case_index(self, case: str) -> int:
        """Index in :attr:`cg` of a named case's C.G.

        Raises
        ------
        ValueError
            If the sweep does not contain it.
        """
        hit = np.flatnonzero(np.isclose(self.cg, CG_POSITIONS[case]))
        if hit.size == 0:
            raise ValueError(f"the C.G. sweep {self.cg} does not contain the {case} C.G. {CG_POSITIONS[case]}")
        return int(hit[0])

    @property
    def slice_positive_fraction(self) -> float:
        """Fraction of the points of the (pitch, flap-rate) slice where ``W' > 0``."""
        return float(np.mean(self.slice_dW > 0))

    def summary(self) -> str:
        """The sweep in both readings (J/rad) with the linear verdict (per rev); at the forward
        C.G. the strict maximiser (scaled coordinates) and the work rates there (J/rad); the
        range of ``W'`` on the slice."""
        i = self.case_index("forward")
        c = f"{self.cg[i]:.3f} c"
        return "\n".join([
            _line("C.G. (c):                    ", self.cg),
            _line("strict max W' (J/rad):       ", np.round(self.strict_max, 2)),
            _line("strict fraction W' > 0:      ", np.round(self.strict_positive_fraction, 3)),
            _line("practical max W' (J/rad):    ", np.round(self.practical_max, 2) + 0.0),
            _line("practical shell max (J/rad): ", np.round(self.practical_shell_max, 2) + 0.0),
            _line("eigen max real part:         ", np.round(self.eig_max_real, 3)),
            _line("  its frequency (/rev):      ", np.round(self.eig_freq, 3) + 0.0),
            _line(f"argmax x_i/a_i at {c}:    ", np.round(self.strict_argmax[i], 2) + 0.0),
            _line(f"aero work rates at argmax, flap/lag/pitch (J/rad), {c}:", np.round(self.terms_aero[i], 2) + 0.0),
            _line(f"damper work rates at argmax (J/rad), {c}:              ",
                  np.round(self.terms_damping[i], 3) + 0.0),
            "W' on the (theta, beta') slice: %.0f to %.0f J/rad; positive on %.3f of the disc" % (
                self.slice_dW.min(), self.slice_dW.max(), self.slice_positive_fraction),
        ])

    def facts(self) -> dict:
        """Chapter 5's Fig. 5 numbers: ``ch5_smax_<case>`` (strict maximum, J/rad, 0.1),
        ``ch5_smax_change`` (its change over the sweep, %), ``ch5_frac_pct`` and
        ``ch5_frac_spread`` (sphere fraction with ``W' > 0``, mean and spread, %),
        ``ch5_pmax`` (magnitude of the practical maximum, J/rad, text of :func:`rotorlyap.reporting.format_small`), the forward C.G.'s maximiser ``ch5_arg_*``
        and work rates ``ch5_aero_flap/lag``, ``ch5_damp_lag`` (J/rad), ``ch5_slice_frac``
        (%), and the linear verdict along the sweep: ``ch5_cg_most_stable`` (fraction of
        chord), ``ch5_eig_min/lo/hi`` (largest real part there and at the ends, per rev)."""
        out = {}
        for name in CASES:
            out[f"ch5_smax_{name}"] = Rounded(self.strict_max[self.case_index(name)], 1)
        out["ch5_smax_change"] = round(float(100 * (self.strict_max[-1] / self.strict_max[0] - 1)), 2)
        out["ch5_frac_pct"] = round(float(100 * self.strict_positive_fraction.mean()), 1)
        out["ch5_frac_spread"] = round(float(100 * np.ptp(self.strict_positive_fraction)), 2)
        out["ch5_pmax"] = format_small(float(np.abs(self.practical_max).max()))
        i = self.case_index("forward")
        am = self.strict_argmax[i]
        out["ch5_arg_theta"] = Rounded(am[2], 2)
        out["ch5_arg_beta"] = Rounded(am[0], 2)
        out["ch5_arg_betadot"] = Rounded(am[3], 2)
        out["ch5_aero_flap"] = round(float(self.terms_aero[i, 0]), 1)
        out["ch5_aero_lag"] = round(float(self.terms_aero[i, 1]), 2)
        out["ch5_damp_lag"] = round(float(self.terms_damping[i, 1]), 3)
        out["ch5_slice_frac"] = round(float(100 * np.mean(self.slice_dW > 0)), 1)
        k = int(np.argmin(self.eig_max_real))
        out["ch5_cg_most_stable"] = float(self.cg[k])
        out["ch5_eig_min"] = round(float(self.eig_max_real[k]), 3)
        out["ch5_eig_lo"] = round(float(self.eig_max_real[0]), 3)
        out["ch5_eig_hi"] = round(float(self.eig_max_real[-1]), 3)
        return out


def hover_rate_data(
    cg_values=np.linspace(0.195, 0.275, 9),
    *,
    A: float = DEFAULT_A,
    scales=None,
    test_disturbances=PAPER_TEST_DISTURBANCES,
    n_sphere: int = 4096,
    n_refine: int = 16,
    n_fraction: int = 16384,
    slice_cg: float = CG_POSITIONS["forward"],
    n_grid: int = 121,
    seed: int = 0,
) -> HoverRateData:
    """Compute :class:`HoverRateData`.

    The hover problem has no explicit azimuth dependence (constant steady motion, no cyclic,
    no inflow variation), so the spheres are searched at ``psi = 0``. The strict search
    samples the structured directions and ``n_sphere`` Sobol' directions and refines the
    ``n_refine`` best by local ascent (:func:`rotorlyap.methods.sampling.sphere_extremum`).
    """
    a = np.array(DEFAULT_SCALES if scales is None else scales, dtype=float)
    tests = np.asarray(test_disturbances, dtype=float)
    tests = tests / np.linalg.norm(tests, axis=1, keepdims=True)
    dirs = unit_sphere_points(6, n_sphere, seed)
    frac_dirs = unit_sphere_points(6, n_fraction, seed + 1)
    psi0 = np.array([0.0])
    rows = []
    n_eval = 0
    for cg in cg_values:
        p = case_params(float(cg))
        blade = Blade(p, 0.0)
        xi = blade.equilibrium()
        fun = energy_function(blade, xi)
        dw = _Count(fun.dW)
        ext = sphere_extremum(dw, psi0, A, a, dirs, n_refine=n_refine, n_iter=60)
        x = ext.x[0]
        terms = energy_rate_terms(blade, xi, 0.0, x)
        frac = float(np.mean(dw(np.zeros(len(frac_dirs)), A * frac_dirs * a) > 0.0))
        pdw = dw(np.zeros(len(tests)), A * tests * a)
        prac = blade_stability(p, 0.0, A=A, scales=a, n_psi=4, test_disturbances=tests)
        ev = np.linalg.eigvals(blade.jacobian(0.0, xi))
        j = int(np.argmax(ev.real))
        real = ev.real[np.abs(ev.imag) < 1e-9]
        rows.append(dict(
            smax=float(ext.value[0]), sarg=x / a, frac=frac, td=terms["damping"], ta=terms["aerodynamic"],
            pdw=pdw, pmax=float(pdw.max()), pshell=float(prac.max_dW.max()),
            emax=float(ev.real[j]), efreq=float(abs(ev.imag[j])),
            eroot=float(real.max()) if real.size else np.nan,
        ))
        n_eval += dw.n + prac.n_evaluations
    # the slice: W' on the plane of pitch displacement and flap rate at slice_cg
    blade = Blade(case_params(float(slice_cg)), 0.0)
    fun = energy_function(blade)
    t = np.linspace(-1.2 * A, 1.2 * A, n_grid)
    T, B = np.meshgrid(t, t)
    xs = np.zeros(T.shape + (6,))
    xs[..., 2] = T * a[2]
    xs[..., 3] = B * a[3]
    sl = fun.dW(0.0, xs.reshape(-1, 6)).reshape(T.shape)
    n_eval += sl.size
    col = lambda k: np.array([r[k] for r in rows])  # noqa: E731
    return HoverRateData(
        cg=np.asarray(cg_values, dtype=float), A=float(A), scales=a,
        strict_max=col("smax"), strict_argmax=col("sarg"), strict_positive_fraction=col("frac"),
        terms_damping=col("td"), terms_aero=col("ta"), practical_dW=col("pdw"),
        practical_max=col("pmax"), practical_shell_max=col("pshell"), test_disturbances=tests,
        eig_max_real=col("emax"), eig_freq=col("efreq"), eig_real_root=col("eroot"),
        slice_cg=float(slice_cg), slice_theta=t, slice_betadot=t, slice_dW=sl,
        strict_label=READING_LABELS["strict"], practical_label=READING_LABELS["practical"], n_evaluations=int(n_eval),
    )


def _label_line_ends(ax, x: float, ys, labels, *, min_gap: float = 0.075, **text_kw) -> None:
    """Label curves at their right end ``x``: curves that end at the same height (within 0.02 of
    the axes height) share one label (``+q`` and ``-q`` become ``±q``; ``labels`` are TeX
    without the ``$``), and the labels are spread to at least ``min_gap`` of the axes height
    apart, so that none overlaps another. The axes' scale and limits must be final."""
    from matplotlib.transforms import ScaledTranslation, blended_transform_factory

    to_axes = ax.transScale + ax.transLimits
    frac = np.array([to_axes.transform((x, float(y)))[1] for y in ys])
    groups: list[list[int]] = []
    for i in np.argsort(frac):
        if groups and frac[i] - frac[groups[-1][-1]] < 0.02:
            groups[-1].append(int(i))
        else:
            groups.append([int(i)])
    texts, pos = [], []
    for g in groups:
        names = [labels[i] for i in g]
        bodies = {n.lstrip("+-") for n in names}
        if len(g) > 1 and len(bodies) == 1 and {n[0] for n in names} == {"+", "-"}:
            texts.append(r"$\pm " + bodies.pop() + "$")
        else:
            texts.append(", ".join(f"${n}$" for n in names))
        pos.append(float(np.mean(frac[g])))
    for j in range(1, len(pos)):
        pos[j] = max(pos[j], pos[j - 1] + min_gap)
    over = pos[-1] - 0.97 if pos else 0.0
    if over > 0:
        pos = [max(p - over, 0.03 + k * min_gap) for k, p in enumerate(pos)]
    tr = blended_transform_factory(ax.transData, ax.transAxes) + ScaledTranslation(
        4 / 72, 0, ax.figure.dpi_scale_trans)
    for t, p in zip(texts, pos):
        ax.text(x, p, t, transform=tr, va="center", **text_kw)


def plot_hover_rate(data: HoverRateData, axes) -> None:
    """Four panels: (a) ``W'`` against the C.G. in both readings; (b) the linear verdict;
    (c) the sign of ``W'`` on the (pitch, flap-rate) plane; (d) which work rates make the
    strict maximum positive, one point per C.G. and work rate."""
    ax_a, ax_b, ax_c, ax_d = axes
    cg = data.cg
    span = cg[-1] - cg[0] if cg.size > 1 else 0.01
    ax_a.plot(cg, data.strict_max, "o-", color="tab:red",
              label=f"{data.strict_label}:\nmax $W'$ on the sphere")
    ax_a.plot(cg, data.practical_max, "s-", color="tab:blue",
              label=f"{data.practical_label}:\nmax $W'$ over the 12 axes")
    rate_idx = [i for i, d in enumerate(data.test_disturbances) if np.abs(d[3:]).max() > 0.5]
    for i in rate_idx:
        ax_a.plot(cg, data.practical_dW[:, i], ":", lw=1.2, color="tab:blue", alpha=0.7)
    ax_a.set_yscale("symlog", linthresh=10.0)
    ax_a.axhline(0, color="k", lw=0.6)
    lo = min(float(np.min(data.practical_dW)), -10.0)
    hi = max(float(np.max(data.strict_max)), 10.0)
    # two decades above the data, for the legend
    ax_a.set_ylim(2.0 * lo, 150.0 * hi)
    ax_a.set_xlim(cg[0] - 0.05 * span, cg[-1] + 0.16 * span)
    _label_line_ends(ax_a, float(cg[-1]), data.practical_dW[-1, rate_idx],
                     [disturbance_names(data.test_disturbances[i:i + 1])[0] for i in rate_idx],
                     fontsize=8.5, color="tab:blue")
    ax_a.set_xlabel("section C.G. (fraction of chord)", fontsize=9)
    ax_a.set_ylabel(r"$W'$ on $\|x\| = A$ (J/rad)", fontsize=9)
    ax_a.set_title("(a) $W'$ in hover; dotted: each rate axis (practical)", fontsize=9)
    ax_a.legend(fontsize=8, loc="upper left")
    real_root = np.asarray(data.eig_freq) < 0.005
    ax_b.plot(cg, data.eig_max_real, "o-", color="k", label="least-damped mode (largest real part),\n"
              "labelled with its frequency (per rev)" + ("\nunlabelled: a real root" if real_root.any() else ""))
    if np.isfinite(data.eig_real_root).any():
        ax_b.plot(cg, data.eig_real_root, "^--", color="tab:purple", label="largest real root (divergence if > 0)")
    ax_b.axhline(0, color="k", lw=0.6)
    top = max(0.05, 1.1 * float(np.nanmax(data.eig_max_real)))
    ax_b.fill_between(cg, 0, top, color="tab:red", alpha=0.07)
    for c, r, f, real in zip(cg, data.eig_max_real, data.eig_freq, real_root):
        if real:
            continue
        ax_b.annotate(f"{f:.2f}", (c, r), fontsize=8, xytext=(0, -6), textcoords="offset points", ha="center",
                      va="top")
    lo_b = float(np.nanmin(data.eig_max_real))
    ax_b.set_ylim(lo_b - 0.35 * (top - lo_b), top + 0.6 * (top - lo_b))
    ax_b.set_xlabel("section C.G. (fraction of chord)", fontsize=9)
    ax_b.set_ylabel("growth rate (per rev)", fontsize=9)
    ax_b.set_title("(b) linearised hover: unstable above zero", fontsize=9)
    ax_b.legend(fontsize=8, loc="upper left")
    ext = [data.slice_theta[0], data.slice_theta[-1], data.slice_betadot[0], data.slice_betadot[-1]]
    from matplotlib.colors import TwoSlopeNorm

    lo, hi = float(data.slice_dW.min()), float(data.slice_dW.max())
    norm = TwoSlopeNorm(vmin=min(lo, -1e-9), vcenter=0.0, vmax=max(hi, 1e-9))
    im = ax_c.imshow(data.slice_dW, origin="lower", extent=ext, cmap="RdBu_r", norm=norm, aspect="equal")
    ax_c.contour(data.slice_theta, data.slice_betadot, data.slice_dW, levels=[0.0], colors="k", linewidths=1)
    ax_c.contourf(data.slice_theta, data.slice_betadot, data.slice_dW > 0, levels=[0.5, 1.5], colors="none",
                  hatches=["...."])
    t = np.linspace(0, 2 * np.pi, 361)
    ax_c.plot(data.A * np.cos(t), data.A * np.sin(t), color="tab:green", lw=1.5, label=r"$\|x\| = A$")
    ax_c.set_aspect("equal")  # the sphere ||x|| = A is a circle in the scaled coordinates
    ax_c.set_xlabel(r"pitch displacement $\theta / a_\theta$", fontsize=9)
    ax_c.set_ylabel(r"flap rate $\beta' / a_{\beta'}$", fontsize=9)
    ax_c.set_title(f"(c) $W'$ on the ($\\theta$, $\\beta'$) plane, C.G. {data.slice_cg:.3g} c\n"
                   "dotted: $W' > 0$", fontsize=9)
    ax_c.legend(fontsize=8, loc="upper right")
    cb = ax_c.figure.colorbar(im, ax=ax_c, shrink=0.9)
    cb.set_label("$W'$ (J/rad); a linear scale\neach side of 0", fontsize=9)
    cb.set_ticks([lo, 0.5 * lo, 0.0, 0.5 * hi, hi])
    cb.set_ticklabels([f"{v:.0f}" for v in (lo, 0.5 * lo, 0.0, 0.5 * hi, hi)])
    cb.ax.tick_params(labelsize=8)
    vals = np.concatenate([data.terms_aero, data.terms_damping], axis=1)
    names = [f"aero {h}" for h in _HINGES] + [f"damper {h}" for h in _HINGES]
    colors = [HINGE_COLORS[h] for h in _HINGES] * 2
    markers = ["o", "s", "^"] * 2
    scale = float(np.abs(vals).max()) or 1.0
    zero = [k for k in range(vals.shape[1]) if np.abs(vals[:, k]).max() < 1e-6 * scale]
    for k in range(vals.shape[1]):
        if k in zero:
            continue
        aero = k < 3
        ax_d.plot(cg, vals[:, k], ls="-" if aero else "--", marker=markers[k], ms=4.5, color=colors[k],
                  mfc=colors[k] if aero else "white", label=names[k])
    if zero:
        kinds = {names[k].split()[0] for k in zero}
        words = (f"{kinds.pop()} " + " and ".join(names[k].split()[1] for k in zero) if len(kinds) == 1
                 else ", ".join(names[k] for k in zero))
        ax_d.plot(cg, np.zeros_like(cg), ls=":", color="0.4", label=f"{words}: 0")
    ax_d.set_yscale("symlog", linthresh=0.01)
    ax_d.axhline(0, color="k", lw=0.6)
    ax_d.set_ylim(-3 * max(float(-vals.min()), 0.01), 10 * max(float(vals.max()), 0.01))
    ax_d.set_xlabel("section C.G. (fraction of chord)", fontsize=9)
    ax_d.set_ylabel("work rate at the strict argmax (J/rad)", fontsize=9)
    ax_d.set_title("(d) why $W' > 0$: work rates per hinge\n(solid: aerodynamic load change; dashed: damper)",
                   fontsize=9)
    # the legend in the empty band between the small terms and the large one, centred on 0.3 J/rad
    y_leg = (ax_d.transScale + ax_d.transLimits).transform((0.0, 0.3))[1]
    ax_d.legend(fontsize=8, loc="center", bbox_to_anchor=(0.5, y_leg), ncol=2)
    for ax in (ax_a, ax_b, ax_d):
        ax.tick_params(labelsize=8)
        ax.set_xticks(cg[::2])
    ax_c.tick_params(labelsize=8)


def figure_hover_rate(data: HoverRateData, figsize=(9.0, 8.8)):
    """The book's Fig. 5 (:func:`plot_hover_rate` on a 2 x 2 grid), laid out and checked
    (:func:`rotorlyap.chapters.style.finish`); returns the Figure."""
    fig, axes = subplots(2, 2, figsize=figsize)
    plot_hover_rate(data, axes.ravel())
    return finish(fig)


@dataclass(frozen=True)
class SearchCheckData:
    """The strict maximum of ``W'`` on the sphere in hover: the engine's default search (step 3)
    against the refined search of Fig. 5, per case.

    Attributes
    ----------
    case_names : tuple of str
    engine : numpy.ndarray
        Step 3's largest ``W'`` on ``||x|| = A``, (3,), J/rad.
    refined : numpy.ndarray
        :attr:`HoverRateData.strict_max` at the case, (3,), J/rad.
    """

    case_names: tuple
    engine: np.ndarray
    refined: np.ndarray

    @property
    def gap(self) -> float:
        """Largest ``|refined - engine|`` over the cases, J/rad."""
        return float(max(abs(r - e) for r, e in zip(self.refined, self.engine)))

    def summary(self) -> str:
        """Both maxima per case, J/rad (0.01), under a header that names the two searches."""
        return "\n".join(["largest W' on the sphere (J/rad): engine step 3 (default) | refined (Fig. 5)"]
                         + [f"{name:9s} {e:8.2f} {r:8.2f}"
                            for name, e, r in zip(self.case_names, self.engine, self.refined)])

    def facts(self) -> dict:
        """``ch5_search_gap`` (:attr:`gap`, J/rad, 0.01)."""
        return {"ch5_search_gap": round(self.gap, 2)}


def search_check(readings: HoverReadingsData, rate: HoverRateData) -> SearchCheckData:
    """Compare the engine's step-3 maximum of each case with the refined maximum of Fig. 5."""
    return SearchCheckData(
        case_names=readings.case_names,
        engine=np.array([s.step3_max_dW for s in readings.strict], dtype=float),
        refined=np.array([rate.strict_max[rate.case_index(n)] for n in readings.case_names]),
    )


# --------------------------------------------------------------------------------------
# Chapter 5: linear divergence along the C.G. sweep
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class HoverDivergenceData:
    """Linear theory along the C.G. sweep of Fig. 5: where the least-damped root crosses zero,
    the practical reading at the C.G.s of the sweep behind it, and the pitch mode.

    Attributes
    ----------
    cg : numpy.ndarray
        The sweep, fraction of chord, (k,).
    least_damped_re : numpy.ndarray
        Largest real part of the linearised hover eigenvalues, per rev, (k,).
    pitch_re : numpy.ndarray
        Real part of the pitch mode (:func:`rotorlyap.model.modes.pitch_mode`), per rev, (k,).
    cg_cross : float
        C.G. where the least-damped growth rate crosses zero (Brent's method between the
        sweep points around the first unstable one, to ``xtol``), fraction of chord.
    cross_mode : rotorlyap.model.modes.Mode
        The least-damped mode there.
    practical : tuple of TechnicalStabilityResult
        The practical reading in hover at each C.G. of the sweep from the first unstable one.
    backward_cg, pitch_axis : float
        The backward case's C.G. and the pitch axis, fraction of chord.
    """

    cg: np.ndarray
    least_damped_re: np.ndarray
    pitch_re: np.ndarray
    cg_cross: float
    cross_mode: Mode
    practical: tuple
    backward_cg: float
    pitch_axis: float

    @property
    def unstable_cg(self) -> np.ndarray:
        """The C.G.s of the sweep that linear theory finds unstable (a tail of the sweep), (d,)."""
        return self.cg[len(self.cg) - len(self.practical):]

    def summary(self) -> str:
        """The crossing (0.0001 c) and what the root is there; the practical verdict at each
        linearly unstable C.G.; the pitch mode's real part along the sweep (per rev)."""
        m = self.cross_mode
        lines = ["the least-damped root crosses zero at a C.G. of %.4f c (there: %s, frequency %.3f/rev)" % (
            self.cg_cross, "an oscillatory pair" if m.oscillatory else "a real root", m.eigenvalue.imag)]
        d = len(self.practical)
        for c, r, q in zip(self.unstable_cg, self.least_damped_re[-d:], self.practical):
            lines.append(f"{c:.3f} c: linear theory: unstable (largest real part {r:+.3f}); "
                         f"{READING_LABELS[q.reading]}: {q.message}")
        lines.append(_line("pitch mode (the fast pair) real part along the sweep:", np.round(self.pitch_re, 3)))
        return "\n".join(lines)

    def facts(self) -> dict:
        """``ch5_cg_div`` (crossing, 0.001 c), ``ch5_div_behind_backward`` and
        ``ch5_div_behind_pa`` (its distance behind the backward C.G. and the pitch axis,
        fraction of chord), ``ch5_n_div`` (unstable C.G.s of the sweep),
        ``ch5_n_div_prac_min`` (fewest practical stable azimuths among them) and
        ``ch5_pitch_re_lo/hi`` (pitch mode real part at the ends of the sweep, per rev, 0.01)."""
        n_stable = [int(q.stable.sum()) for q in self.practical]
        return {
            "ch5_cg_div": round(float(self.cg_cross), 3),
            "ch5_div_behind_backward": round(float(self.cg_cross - self.backward_cg), 4),
            "ch5_div_behind_pa": round(float(self.cg_cross - self.pitch_axis), 3),
            "ch5_n_div": len(n_stable),
            "ch5_n_div_prac_min": min(n_stable),
            "ch5_pitch_re_lo": round(float(self.pitch_re[0]), 2),
            "ch5_pitch_re_hi": round(float(self.pitch_re[-1]), 2),
        }


def hover_divergence_data(rate: HoverRateData, *, n_psi: int = 24, test_disturbances=PAPER_TEST_DISTURBANCES,
                          xtol: float = 1e-6) -> HoverDivergenceData:
    """Find where linear theory turns unstable along the sweep of ``rate`` (its
    :attr:`HoverRateData.eig_max_real`) and run the practical reading there.

    Raises
    ------
    ValueError
        If the sweep is not stable at its first C.G. and unstable at a later one.
    """
    def growth(cg) -> float:
        return least_damped(hover_modes(case_params(cg))).growth_rate

    unstable = np.flatnonzero(rate.eig_max_real > 0)
    if unstable.size == 0 or unstable[0] == 0:
        raise ValueError("hover_divergence_data: the sweep must start stable and turn unstable")
    j = int(unstable[0])
    cross = brentq(growth, rate.cg[j - 1], rate.cg[j], xtol=xtol)
    practical = tuple(blade_stability(case_params(float(c)), 0.0, n_psi=n_psi, test_disturbances=test_disturbances)
                      for c in rate.cg[j:])
    pitch_re = np.array([pitch_mode(hover_modes(case_params(c))).growth_rate for c in rate.cg])
    return HoverDivergenceData(
        cg=rate.cg, least_damped_re=rate.eig_max_real, pitch_re=pitch_re, cg_cross=float(cross),
        cross_mode=least_damped(hover_modes(case_params(cross))), practical=practical,
        backward_cg=float(CG_POSITIONS["backward"]), pitch_axis=float(case_params("forward").pitch_axis),
    )


# --------------------------------------------------------------------------------------
# Chapter 6: the loads the reused hover equilibrium leaves unbalanced
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class UnbalancedLoadsData:
    """``Delta Q(psi, 0)``: the forward-flight aerodynamic hinge moments at the hover
    equilibrium minus the hover ones that hold it in balance.

    Attributes
    ----------
    cg : str or float
        The case.
    mu : float
        Advance ratio.
    psi : numpy.ndarray
        Azimuths, rad, (n,).
    delta_q : numpy.ndarray
        Flap, lag and pitch moments, N m, (n, 3).
    """

    cg: object
    mu: float
    psi: np.ndarray
    delta_q: np.ndarray

    def summary(self) -> str:
        """Smallest and largest moment over the azimuth per hinge (N m, 0.1) and where (deg)."""
        lines = [f"Delta Q(psi, x = 0) at mu = {self.mu:g}, {self.cg} C.G., amplitude over the azimuth (N m):"]
        for h, name in enumerate(_HINGES):
            q = self.delta_q[:, h]
            lines.append(f"  {name:5s}: from {q.min():8.1f} (psi = {np.degrees(self.psi[np.argmin(q)]):3.0f} deg) "
                         f"to {q.max():8.1f} (psi = {np.degrees(self.psi[np.argmax(q)]):3.0f} deg)")
        return "\n".join(lines)

    def facts(self) -> dict:
        """``ch6_dq_<hinge>_min/max``: the range over the azimuth, N m, to 3 significant
        figures (as printed by :meth:`summary` below 100 N m)."""
        out = {}
        for h, name in enumerate(_HINGES):
            out[f"ch6_dq_{name}_min"] = float(f"{self.delta_q[:, h].min():.3g}")
            out[f"ch6_dq_{name}_max"] = float(f"{self.delta_q[:, h].max():.3g}")
        return out


def unbalanced_loads_data(cg="forward", mu: float = 0.15, *, psi_step_deg: float = 5.0) -> UnbalancedLoadsData:
    """Compute :class:`UnbalancedLoadsData` every ``psi_step_deg`` degrees of azimuth."""
    p = case_params(cg)
    hover = Blade(p, 0.0)
    xi = hover.equilibrium()
    psi = np.radians(np.arange(0, 360, psi_step_deg))
    dq = (Blade(p, mu).aerodynamic_forces(psi, np.broadcast_to(xi, (psi.size, 6)))
          - hover.aerodynamic_forces(0.0, xi))
    return UnbalancedLoadsData(cg=cg, mu=float(mu), psi=psi, delta_q=dq)


# --------------------------------------------------------------------------------------
# Fig. 6: W(psi, x) at mu = 0.15 for several bounds A
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class WSpheresData:
    """Infimum and supremum of ``W`` over spheres ``||x|| = A`` at each azimuth.

    Attributes
    ----------
    cg : str or float
        The case.
    mu : float
        Advance ratio.
    psi : numpy.ndarray
        Azimuths, (n,).
    A_values : numpy.ndarray
        Radii, (m,).
    strict_inf, strict_sup : numpy.ndarray
        Over the whole sphere (sampling + refinement), (m, n), J.
    practical_min, practical_max : numpy.ndarray
        Over the test disturbances only, (m, n), J.
    strict_label, practical_label : str
    n_evaluations : int
    axis_W : numpy.ndarray
        ``W`` at ``psi = 0`` along each positive scaled axis on the unit sphere
        (``x = a_i e_i``), (6,), J: which axis has the least energy.
    scales : numpy.ndarray
        The norm scales ``a_i`` of the spheres, (6,), rad and rad/rad.
    """

    cg: object
    mu: float
    psi: np.ndarray
    A_values: np.ndarray
    strict_inf: np.ndarray
    strict_sup: np.ndarray
    practical_min: np.ndarray
    practical_max: np.ndarray
    strict_label: str
    practical_label: str
    n_evaluations: int
    axis_W: np.ndarray
    scales: np.ndarray

    @property
    def azimuth_variation(self) -> float:
        """Largest relative variation over the azimuth of the infimum or supremum on a sphere, -."""
        return max(float(np.ptp(a, axis=1).max() / a.mean()) for a in (self.strict_inf, self.strict_sup))

    def summary(self) -> str:
        """Azimuth means of the four extrema (J) and of the strict ones over ``A^2``, the
        variation over the azimuth and :attr:`axis_W` (J)."""
        A2 = self.A_values ** 2
        return "\n".join([
            _line("A:                          ", self.A_values),
            _line("inf W over sphere (J):      ", np.round(self.strict_inf.mean(axis=1), 3)),
            _line("sup W over sphere (J):      ", np.round(self.strict_sup.mean(axis=1), 1)),
            _line("min W over 12 axes (J):     ", np.round(self.practical_min.mean(axis=1), 3)),
            _line("max W over 12 axes (J):     ", np.round(self.practical_max.mean(axis=1), 1)),
            _line("inf W / A^2:                ", np.round(self.strict_inf.mean(axis=1) / A2, 4)),
            _line("sup W / A^2:                ", np.round(self.strict_sup.mean(axis=1) / A2, 1)),
            "largest relative variation over the azimuth: %.1e" % self.azimuth_variation,
            "W along each axis at ||x|| = 1 (J): " + ", ".join(
                f"{_plain(n)} {v:.2f}" for n, v in zip(STATE_LABELS, self.axis_W)),
        ])

    def facts(self) -> dict:
        """Chapter 6's Fig. 6 numbers: ``ch6_w_theta`` and ``ch6_w_fl_min`` (``W`` along the
        pitch axis and the least along a flap or lag axis, J), ``ch6_w_var`` (variation over
        the azimuth, one digit, "< 1e-12" at round-off, :func:`rotorlyap.reporting.format_small`), ``ch6_winf_<i>`` and ``ch6_wsup_<i>`` (azimuth means per
        ``A``, J), ``ch6_rinf_change``, ``ch6_rsup_change`` (change of ``W/A^2`` from the
        smallest to the largest ``A``, %), ``ch6_A_values`` (the radii, in words) and
        ``ch6_A_max_flap`` (the flap angle of the largest sphere's flap axis, deg)."""
        A = [f"{v:g}" for v in self.A_values]
        out = {
            "ch6_A_values": ", ".join(A[:-1]) + " and " + A[-1] if len(A) > 1 else A[0],
            "ch6_A_max_flap": float(f"{np.degrees(self.A_values[-1] * self.scales[0]):.2g}"),
            "ch6_w_theta": round(float(self.axis_W[2]), 1),
            "ch6_w_fl_min": round(float(self.axis_W[[0, 1, 3, 4]].min()), 0),
            "ch6_w_var": format_small(float(self.azimuth_variation), 1e-12),
        }
        for i in range(len(self.A_values)):
            out[f"ch6_winf_{i}"] = round(float(self.strict_inf[i].mean()), 3)
            out[f"ch6_wsup_{i}"] = round(float(self.strict_sup[i].mean()), 0)
        r_inf = self.strict_inf.mean(axis=1) / self.A_values ** 2
        r_sup = self.strict_sup.mean(axis=1) / self.A_values ** 2
        out["ch6_rinf_change"] = round(float(100 * (r_inf[-1] / r_inf[0] - 1)), 1)
        out["ch6_rsup_change"] = round(float(100 * (r_sup[-1] / r_sup[0] - 1)), 1)
        return out


def w_spheres_data(cg="forward", mu: float = 0.15, A_values=(0.5, 1.0, 2.0, 4.0, 8.0), *, n_psi: int = 72,
                   n_sphere: int = 1024, scales=None, test_disturbances=PAPER_TEST_DISTURBANCES,
                   seed: int = 0) -> WSpheresData:
    """Compute :class:`WSpheresData` for the energy function about the hover equilibrium."""
    a = np.array(DEFAULT_SCALES if scales is None else scales, dtype=float)
    p = case_params(cg)
    hover = Blade(p, 0.0)
    xi = hover.equilibrium()
    axis_W = energy_function(hover, xi).W(np.zeros(6), np.eye(6) * a)
    fun = energy_function(Blade(p, mu), xi)
    w = _Count(fun.W)
    psi = 2 * np.pi * np.arange(n_psi) / n_psi
    dirs = unit_sphere_points(6, n_sphere, seed)
    tests = np.asarray(test_disturbances, dtype=float)
    tests = tests / np.linalg.norm(tests, axis=1, keepdims=True)
    out = {k: [] for k in ("inf", "sup", "pmin", "pmax")}
    for A in A_values:
        out["sup"].append(sphere_extremum(w, psi, A, a, dirs, kind="max").value)
        out["inf"].append(sphere_extremum(w, psi, A, a, dirs, kind="min").value)
        vals = w(np.repeat(psi, len(tests)), np.tile(A * tests * a, (n_psi, 1))).reshape(n_psi, -1)
        out["pmin"].append(vals.min(axis=1))
        out["pmax"].append(vals.max(axis=1))
    return WSpheresData(cg=cg, mu=float(mu), psi=psi, A_values=np.asarray(A_values, dtype=float),
                        strict_inf=np.array(out["inf"]), strict_sup=np.array(out["sup"]),
                        practical_min=np.array(out["pmin"]), practical_max=np.array(out["pmax"]),
                        strict_label=READING_LABELS["strict"], practical_label=READING_LABELS["practical"],
                        n_evaluations=w.n, axis_W=axis_W, scales=a)


def plot_w_spheres(data: WSpheresData, axes) -> None:
    """(a) inf and sup of ``W`` against azimuth for each ``A`` (log scale); (b) the same
    divided by ``A^2``, against ``A``. Each legend to the right of its panel."""
    ax, ax2 = axes
    deg = np.degrees(data.psi)
    cmap = _colormaps()["plasma"]
    m = len(data.A_values)
    for i, A in enumerate(data.A_values):
        c = cmap(0.1 + 0.75 * i / max(m - 1, 1))
        ax.fill_between(deg, data.strict_inf[i], data.strict_sup[i], color=c, alpha=0.18, lw=0)
        ax.plot(deg, data.strict_inf[i], "-", color=c, lw=1.5, label=f"A = {A:g}")
        ax.plot(deg, data.strict_sup[i], "-", color=c, lw=1.5)
        ax.plot(deg, data.practical_min[i], "--", color=c, lw=1)
        ax.plot(deg, data.practical_max[i], "--", color=c, lw=1)
    ax.plot([], [], "k-", label="inf / sup over the whole sphere\n(strict search)")
    ax.plot([], [], "k--", label="min / max over the 12 signed axes\n(practical)")
    ax.set_yscale("log")
    ax.set_xlabel(r"azimuth $\psi$ (deg)", fontsize=9)
    ax.set_ylabel(r"$W(\psi, x)$ on $\|x\| = A$ (J)", fontsize=9)
    ax.set_xticks(np.arange(0, 361, 45))
    ax.set_xlim(0, 360)
    ax.set_title(f"(a) $W$ at $\\mu$ = {data.mu:g}, {data.cg} C.G.", fontsize=9)
    ax.legend(fontsize=8, loc="center left", bbox_to_anchor=(1.01, 0.5))
    A = data.A_values
    # strict: solid, large open markers; practical: dashed, small filled ones (they often coincide)
    for arr, c, strict, lab in ((data.strict_inf, "#0072B2", True, "inf (sphere)"),
                                (data.strict_sup, "#D55E00", True, "sup (sphere)"),
                                (data.practical_min, "#0072B2", False, "min (12 axes)"),
                                (data.practical_max, "#D55E00", False, "max (12 axes)")):
        ax2.plot(A, arr.mean(axis=1) / A ** 2, "-" if strict else "--", marker="o" if strict else "s",
                 ms=8 if strict else 3.5, mfc="none" if strict else c, color=c, label=lab)
    ax2.set_xscale("log", base=2)
    ax2.set_yscale("log")
    ax2.set_xticks(A, [f"{v:g}" for v in A])
    ax2.set_xlabel("bound $A$", fontsize=9)
    ax2.set_ylabel(r"azimuth mean of $W / A^2$ (J)", fontsize=9)
    ax2.set_title("(b) $W / A^2$: nearly constant, so $W \\propto A^2$", fontsize=9)
    ax2.legend(fontsize=8, loc="center left", bbox_to_anchor=(1.01, 0.5))
    for a in (ax, ax2):
        a.tick_params(labelsize=8)


def figure_w_spheres(data: WSpheresData, figsize=(8.6, 6.6)):
    """The book's Fig. 6 (:func:`plot_w_spheres`, the azimuth panel above the other), laid out
    and checked (:func:`rotorlyap.chapters.style.finish`); returns the Figure."""
    fig, axes = subplots(2, 1, figsize=figsize, gridspec_kw=dict(height_ratios=(1.4, 1)))
    plot_w_spheres(data, axes)
    return finish(fig)


# --------------------------------------------------------------------------------------
# Fig. 7: W' against azimuth in forward flight
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class RateAzimuthData:
    """Largest ``W'`` on the sphere ``||x|| = A`` at each azimuth, for several advance ratios.

    Attributes
    ----------
    cg : str or float
    A : float
    mu_values : numpy.ndarray
        (m,).
    psi : numpy.ndarray
        (n,).
    strict_max : numpy.ndarray
        Over the whole sphere (sampling + refinement), (m, n), J/rad.
    practical_max : numpy.ndarray
        Over the test disturbances, (m, n), J/rad.
    practical_argmax : numpy.ndarray
        Index of the test disturbance giving the practical maximum, (m, n).
    test_disturbances : numpy.ndarray
    strict_label, practical_label : str
    n_evaluations : int
    axis_max : numpy.ndarray
        Largest ``W'`` over the azimuth along each test disturbance, (m, n_test), J/rad.
    """

    cg: object
    A: float
    mu_values: np.ndarray
    psi: np.ndarray
    strict_max: np.ndarray
    practical_max: np.ndarray
    practical_argmax: np.ndarray
    test_disturbances: np.ndarray
    strict_label: str
    practical_label: str
    n_evaluations: int
    axis_max: np.ndarray

    def summary(self) -> str:
        """Per advance ratio: the extremes over the azimuth of both maxima (J/rad), the
        azimuths with a positive practical maximum, where and along which axis the practical
        maximum lies; at the second advance ratio, :attr:`axis_max` (J/rad, 0.1)."""
        names = disturbance_names(self.test_disturbances)
        lines = [
            _line("mu                              ", self.mu_values),
            _line("strict: max over psi of max W'  ", np.round(self.strict_max.max(axis=1), 0)),
            _line("strict: min over psi of max W'  ", np.round(self.strict_max.min(axis=1), 1)),
            _line("practical: max over psi         ", np.round(self.practical_max.max(axis=1), 0)),
            _line("practical: min over psi         ", np.round(self.practical_max.min(axis=1), 3)),
            _line("practical: azimuths with W' > 0 ", (self.practical_max > 0).sum(axis=1)),
        ]
        for i, mu in enumerate(self.mu_values):
            j = int(np.argmax(self.practical_max[i]))
            lines.append(f"  mu = {mu:.2f}: practical maximum at psi = {np.degrees(self.psi[j]):3.0f} deg "
                         f"along {_plain(names[self.practical_argmax[i, j]])}")
        lines.append(f"mu = {self.mu_values[1]:.2f}: largest W' over the azimuth along each axis (J/rad):")
        lines.append("  " + ", ".join(f"{_plain(n)} {v:.1f}" for n, v in zip(names, self.axis_max[1])))
        return "\n".join(lines)

    def facts(self) -> dict:
        """Chapter 6's Fig. 7 numbers, at the second advance ratio (``_005``) and the last
        (``_025``): the largest ``W'`` along the flap and pitch rates (J/rad), the azimuths
        with practical ``W' > 0`` and without, the smallest practical maximum, the strict
        maximum in hover and at the last ``mu`` (J/rad), the practical maximum there and
        its azimuth (deg)."""
        ax = dict(zip(disturbance_names(self.test_disturbances), self.axis_max[1]))
        return {
            "ch6_f7_ax_betadot": round(float(max(ax["+\\beta'"], ax["-\\beta'"])), 0),
            "ch6_f7_ax_thetadot": round(float(max(ax["+\\theta'"], ax["-\\theta'"])), 1),
            "ch6_f7_nzero_005": int((self.practical_max[1] <= 0).sum()),
            "ch6_f7_smax_025": round(float(self.strict_max[-1].max()), 0),
            "ch6_f7_smax_0": round(float(self.strict_max[0].max()), 1),
            "ch6_f7_pmax_025": round(float(self.practical_max[-1].max()), 0),
            "ch6_f7_psi_pmax_025": int(round(np.degrees(self.psi[np.argmax(self.practical_max[-1])]))),
            "ch6_f7_pmin_005": round(float(self.practical_max[1].min()), 3),
            "ch6_f7_npos_005": int((self.practical_max[1] > 0).sum()),
        }


def rate_azimuth_data(cg="forward", mu_values=(0.0, 0.05, 0.1, 0.15, 0.2, 0.25), *, A: float = DEFAULT_A,
                      n_psi: int = 72, n_sphere: int = 1024, scales=None,
                      test_disturbances=PAPER_TEST_DISTURBANCES, seed: int = 0) -> RateAzimuthData:
    """Compute :class:`RateAzimuthData` (the steady motion is the hover equilibrium at every mu)."""
    a = np.array(DEFAULT_SCALES if scales is None else scales, dtype=float)
    p = case_params(cg)
    xi = Blade(p, 0.0).equilibrium()
    psi = 2 * np.pi * np.arange(n_psi) / n_psi
    dirs = unit_sphere_points(6, n_sphere, seed)
    tests = np.asarray(test_disturbances, dtype=float)
    tests = tests / np.linalg.norm(tests, axis=1, keepdims=True)
    smax, pmax, parg, amax, n_eval = [], [], [], [], 0
    for mu in mu_values:
        dw = _Count(energy_function(Blade(p, mu), xi).dW)
        smax.append(sphere_extremum(dw, psi, A, a, dirs).value)
        vals = dw(np.repeat(psi, len(tests)), np.tile(A * tests * a, (n_psi, 1))).reshape(n_psi, -1)
        pmax.append(vals.max(axis=1))
        parg.append(vals.argmax(axis=1))
        amax.append(vals.max(axis=0))
        n_eval += dw.n
    return RateAzimuthData(cg=cg, A=float(A), mu_values=np.asarray(mu_values, dtype=float), psi=psi,
                           strict_max=np.array(smax), practical_max=np.array(pmax),
                           practical_argmax=np.array(parg), test_disturbances=tests,
                           strict_label=READING_LABELS["strict"], practical_label=READING_LABELS["practical"],
                           n_evaluations=n_eval, axis_max=np.array(amax))


def plot_rate_azimuth(data: RateAzimuthData, axes) -> None:
    """One panel per reading: max ``W'`` against azimuth, one curve per advance ratio."""
    cmap = _colormaps()["viridis"]
    deg = np.degrees(data.psi)
    m = len(data.mu_values)
    for ax, arr, reading in zip(axes, (data.strict_max, data.practical_max), ("strict", "practical")):
        for i, mu in enumerate(data.mu_values):
            ax.plot(deg, arr[i], "-", color=cmap(0.9 * i / max(m - 1, 1)), lw=1.4, label=rf"$\mu$ = {mu:g}")
        ax.axhline(0, color="k", lw=0.6)
        ax.set_yscale("symlog", linthresh=1.0)
        ax.axvspan(0, 180, color="tab:orange", alpha=0.05)
        ax.axvspan(180, 360, color="tab:blue", alpha=0.05)
        ax.text(90, 0.02, "advancing", transform=ax.get_xaxis_transform(), ha="center", fontsize=8, color="tab:orange")
        ax.text(270, 0.02, "retreating", transform=ax.get_xaxis_transform(), ha="center", fontsize=8, color="tab:blue")
        ax.set_xticks(np.arange(0, 361, 90))
        ax.set_xlim(0, 360)
        ax.set_xlabel(r"azimuth $\psi$ (deg)", fontsize=9)
        where = "the sphere" if reading == "strict" else "the 12 axes"
        label = data.strict_label if reading == "strict" else data.practical_label
        ax.set_title(f"{label}:\nmax $W'$ over {where}", fontsize=9)
        ax.tick_params(labelsize=8)
    axes[0].set_ylabel(r"max $W'$ on $\|x\| = A$ (J/rad)", fontsize=9)
    # the legend in the empty decade below the hover line of the strict panel, centred on 10 J/rad
    y_leg = (axes[0].transScale + axes[0].transLimits).transform((0.0, 10.0))[1]
    axes[0].legend(fontsize=8, ncol=3, loc="center", bbox_to_anchor=(0.5, y_leg), handlelength=1.5,
                   columnspacing=1.0)


def figure_rate_azimuth(data: RateAzimuthData, figsize=(9.0, 4.2)):
    """The book's Fig. 7 (:func:`plot_rate_azimuth`, one panel per reading, shared ``W'`` axis),
    laid out and checked (:func:`rotorlyap.chapters.style.finish`); returns the Figure."""
    fig, axes = subplots(1, 2, figsize=figsize, sharey=True)
    plot_rate_azimuth(data, axes)
    return finish(fig)


# --------------------------------------------------------------------------------------
# Fig. 8: regions of instability
# --------------------------------------------------------------------------------------

#: Categories of a (mu, psi) cell in :class:`RegionsData`.
CATEGORY_NAMES = (
    "passes: step 6 holds",
    "step 6 fails at this azimuth",
    "step 3 failed elsewhere (A1 = 0); W' <= 0 here on ||x|| = A",
    "step 3 failed (A1 = 0) and W' > 0 here on ||x|| = A",
)


@dataclass(frozen=True)
class RegionsData:
    """The engine's verdict on a grid of advance ratios and azimuths, in one reading.

    Attributes
    ----------
    reading : str
        "strict" or "practical".
    label : str
        ``READING_LABELS[reading]``.
    cases : tuple
        C.G. cases (names or positions).
    mu_values : numpy.ndarray
        (m,).
    psi : numpy.ndarray
        (n,).
    stable : numpy.ndarray
        ``result.stable``, (k, m, n).
    category : numpy.ndarray
        Index into :data:`CATEGORY_NAMES`, (k, m, n).
    max_dW : numpy.ndarray
        ``result.max_dW``: on the shell after step 3, or on the requested sphere when step 3
        found no bound, (k, m, n), J/rad.
    A_used : numpy.ndarray
        Bound after step 3, (k, m).
    lambda0 : numpy.ndarray
        (k, m, n).
    A : float
        Requested bound.
    root_r_over_R : float
        Blade root station, for the reverse-flow mark.
    n_evaluations : int
    """

    reading: str
    label: str
    cases: tuple
    mu_values: np.ndarray
    psi: np.ndarray
    stable: np.ndarray
    category: np.ndarray
    max_dW: np.ndarray
    A_used: np.ndarray
    lambda0: np.ndarray
    A: float
    root_r_over_R: float
    n_evaluations: int

    def unstable_fraction(self) -> np.ndarray:
        """Fraction of azimuths not stable, (k, m)."""
        return 1.0 - self.stable.mean(axis=-1)

    def positive_side_fractions(self, case_index: int = 0) -> tuple[np.ndarray, np.ndarray]:
        """Fractions of the advancing (0 to 180 deg) and retreating (180 to 360 deg) azimuths
        with ``W' > 0`` on the requested sphere (category 3), per advance ratio, (m,) each."""
        pos = self.category[case_index] == 3
        adv = (self.psi > 0) & (self.psi < np.pi)
        ret = self.psi > np.pi
        return (np.array([pos[i, adv].mean() for i in range(self.mu_values.size)]),
                np.array([pos[i, ret].mean() for i in range(self.mu_values.size)]))

    def summary(self) -> str:
        """The reading, the advance ratios, per case the stable azimuths and the bound after
        step 3 per ``mu``, and the cells with ``W' > 0`` on the requested sphere."""
        lines = [self.label, _line("  mu:", self.mu_values)]
        for k, case in enumerate(self.cases):
            lines.append(_line(f"  {case:9s} azimuths passing:", self.stable[k].sum(axis=1),
                               " A after step 3:", np.round(self.A_used[k], 3)))
        lines.append(_line("  cells with W' > 0 on the sphere (step 3 failed):", int((self.category == 3).sum()),
                           "of", self.category.size))
        return "\n".join(lines)

    def side_summary(self) -> str:
        """Whether the per-azimuth picture (``W' > 0`` on the sphere) is the same for every
        case, and its fractions on the advancing and retreating sides per ``mu`` (0.01)."""
        pos = self.category == 3
        adv, ret = self.positive_side_fractions(0)
        lines = [_line(f"{self.reading}, W' > 0 on the sphere: the same map for every C.G.:",
                       all(np.array_equal(pos[0], pos[k]) for k in range(len(self.cases)))),
                 f"{self.reading}, fraction of azimuths with W' > 0 on the sphere, advancing / retreating side:"]
        lines += [f"  mu = {mu:.4f}: {a:.2f} / {r:.2f}" for mu, a, r in zip(self.mu_values, adv, ret)]
        return "\n".join(lines)

    def export(self) -> list:
        """One row per (case, mu, psi) cell for :func:`rotorlyap.chapters.export.figure_csv`:
        case index, ``mu``, ``psi`` (deg), category, stable and ``max_dW`` (J/rad)."""
        k, m, n = self.category.shape
        return [("case", np.repeat(np.arange(k), m * n)),
                ("mu", np.tile(np.repeat(self.mu_values, n), k)),
                ("psi_deg", np.tile(np.degrees(self.psi), k * m)),
                ("category", self.category.ravel()), ("stable", self.stable.ravel()),
                ("max_dW", self.max_dW.ravel())]


def _category(res) -> np.ndarray:
    if res.A > 0:
        return np.where(res.stable, 0, 1)
    return np.where(res.max_dW > res.tol, 3, 2)


def regions_data(cases=CASES, mu_values=MU_GRID, *, reading: str = "practical", n_psi: int = 72,
                 A: float | None = None, scales=None, test_disturbances=PAPER_TEST_DISTURBANCES,
                 params_overrides: dict | None = None, **engine_options) -> RegionsData:
    """Run :func:`rotorlyap.analysis.stability.blade_stability` for every case and advance ratio.

    ``reading="strict"`` ignores ``test_disturbances`` (whole spheres); ``engine_options``
    (``n_sphere``, ...) go to the engine. A strict search at reduced resolution can only
    miss positive ``W'``, never invent one: where it reports failure, failure is certain.
    """
    if reading not in READING_LABELS:
        raise ValueError(f"reading must be one of {tuple(READING_LABELS)}, got {reading!r}")
    tests = None if reading == "strict" else test_disturbances
    stable, cat, mdw, aused, lam, n_eval = [], [], [], [], [], 0
    psi = None
    overrides = params_overrides or {}
    for cg in cases:
        p = case_params(cg, **overrides)
        row = []
        for mu in mu_values:
            res = blade_stability(p, float(mu), A=A, scales=scales, n_psi=n_psi, test_disturbances=tests,
                                  **engine_options)
            assert res.reading == reading
            row.append(res)
            n_eval += res.n_evaluations
            psi = res.psi
        stable.append([r.stable for r in row])
        cat.append([_category(r) for r in row])
        mdw.append([r.max_dW for r in row])
        aused.append([r.A for r in row])
        lam.append([r.lambda0 for r in row])
    p0 = case_params(cases[0], **overrides)
    return RegionsData(
        reading=reading, label=READING_LABELS[reading], cases=tuple(cases),
        mu_values=np.asarray(mu_values, dtype=float), psi=np.asarray(psi),
        stable=np.array(stable), category=np.array(cat), max_dW=np.array(mdw),
        A_used=np.array(aused), lambda0=np.array(lam),
        A=float(DEFAULT_A if A is None else A), root_r_over_R=float(p0.root_r_over_R),
        n_evaluations=int(n_eval),
    )


def _edges(values: np.ndarray, lo: float | None = None, hi: float | None = None) -> np.ndarray:
    v = np.asarray(values, dtype=float)
    mid = 0.5 * (v[1:] + v[:-1])
    first = v[0] - (mid[0] - v[0]) if lo is None else lo
    last = v[-1] + (v[-1] - mid[-1]) if hi is None else hi
    return np.concatenate([[first], mid, [last]])


def _reverse_flow(ax, th, rb, top) -> None:
    """Hatch (:data:`REVERSE_FLOW_HATCH`) and outline the region ``rb <= r <= top`` over the
    azimuths ``th`` where ``rb <= top``: where reverse flow reaches the blade root."""
    import matplotlib.patheffects as pe

    ok = rb <= top
    if not ok.any():
        return
    ax.fill_between(th[ok], rb[ok], top, facecolor="none", edgecolor="k", hatch=REVERSE_FLOW_HATCH, lw=0.0)
    t, r = th[ok], rb[ok]
    # the outline: the boundary, then back along the rim (white-edged, to stand out on any colour)
    ax.plot(np.concatenate([t, np.linspace(t[-1], t[0], 90)]), np.concatenate([r, np.full(90, top)]),
            "k-", lw=1.5, path_effects=[pe.withStroke(linewidth=3.0, foreground="w")], clip_on=False)


def plot_regions_polar(data: RegionsData, ax, case_index: int = 0, *, title: str | None = None) -> None:
    """The verdict on the rotor disc seen from above: azimuth as angle, radius = mu.

    ``psi = 0`` points to the tail (bottom), rotation counter-clockwise, so the advancing
    side (``psi = 90 deg``) is on the right; each verdict in its colour and hatch; hatched
    with vertical lines and outlined: where reverse flow reaches the blade root
    (``mu |sin psi| > (R - R1)/R`` on the retreating side). A ``mu = 0`` row (hover) is drawn
    as a central disc below ``r = 0``, so that the radius of every other row is exactly its
    advance ratio.
    """
    import matplotlib.patheffects as pe

    ax.set_theta_zero_location("S")
    ax.set_theta_direction(1)
    mu = data.mu_values
    step = 2 * np.pi / data.psi.size
    th_edges = np.concatenate([data.psi - step / 2, [data.psi[-1] + step / 2]])
    r_edges = _edges(mu, lo=0.0)
    hole = 0.0
    if mu[0] == 0.0:
        # hover has no extent on the disc: draw it as a central disc of radius `hole`
        # below r = 0 (the radial axis starts at -hole), so that radius = mu stays exact.
        hole = 0.12 * r_edges[-1]
        r_edges = np.concatenate([[-hole], r_edges[1:]])
    draw_categories(ax, th_edges, r_edges, data.category[case_index], CATEGORY_COLORS, CATEGORY_HATCHES)
    th = np.linspace(np.pi, 2 * np.pi, 361)
    rb = data.root_r_over_R / np.maximum(-np.sin(th), 1e-9)
    rmax = r_edges[-1]
    _reverse_flow(ax, th, rb, rmax)
    ax.set_ylim(-hole, rmax)
    ticks = [m for m in (0.05, 0.1, 0.15, 0.2, 0.25) if m <= rmax]
    ax.set_yticks(ticks)
    ax.set_yticklabels([f"{m:g}" for m in ticks])
    ax.tick_params(axis="y", labelsize=8)
    ax.set_rlabel_position(157.5)
    names = {0: "0°\ntail", 90: "90°\nadvancing", 180: "nose\n180°", 270: "retreating\n270°"}
    ax.set_xticks(np.radians(np.arange(0, 360, 45)))
    ax.set_xticklabels([names.get(d, f"{d}°") for d in range(0, 360, 45)], fontsize=8)
    ax.tick_params(axis="x", pad=2)
    for lab in ax.get_xticklabels():
        # the side labels are wide: anchor them at their inner edge, clear of the disc
        if "advancing" in lab.get_text():
            lab.set(color="tab:orange", ha="left")
        elif "retreating" in lab.get_text():
            lab.set(color="tab:blue", ha="right")
    for lab in ax.get_yticklabels():
        lab.set_path_effects([pe.withStroke(linewidth=2.5, foreground="w")])
    case = data.cases[case_index]
    ax.set_title(title or f"{case} C.G.", fontsize=9, pad=20)


def plot_regions_plane(data: RegionsData, ax, case_index: int = 0, *, title: str | None = None,
                       legend: bool = True) -> None:
    """The verdict in the (psi, mu) plane, each verdict in its colour and hatch, with the
    reverse-flow region (hatched with vertical lines and outlined)."""
    deg = np.degrees(data.psi)
    step = deg[1] - deg[0]
    top = _edges(data.mu_values, lo=0.0)[-1]
    draw_categories(ax, np.concatenate([deg - step / 2, [deg[-1] + step / 2]]), _edges(data.mu_values, lo=0.0),
                     data.category[case_index], CATEGORY_COLORS, CATEGORY_HATCHES)
    th = np.linspace(180, 360, 361)
    rb = data.root_r_over_R / np.maximum(-np.sin(np.radians(th)), 1e-9)
    _reverse_flow(ax, th, rb, top)
    ax.axvline(180, color="k", lw=1.2, ls=":", zorder=5)  # on top of the hatching
    ax.text(90, 1.01, "advancing", transform=ax.get_xaxis_transform(), ha="center", fontsize=8, color="tab:orange")
    ax.text(270, 1.01, "retreating", transform=ax.get_xaxis_transform(), ha="center", fontsize=8, color="tab:blue")
    ax.set_xlim(0, 360)
    ax.set_ylim(0, top)
    ax.set_xticks(np.arange(0, 361, 90))
    ax.set_xlabel(r"azimuth $\psi$ (deg)", fontsize=9)
    ax.set_ylabel(r"advance ratio $\mu$", fontsize=9)
    ax.tick_params(labelsize=8)
    ax.set_title(title or f"{data.cases[case_index]} C.G.", fontsize=9, pad=14)
    if legend:
        ax.legend(handles=category_legend_handles(wrap=34), fontsize=8, loc="upper left", bbox_to_anchor=(1.02, 1.0))


@dataclass(frozen=True)
class RegionMaps:
    """The Fig. 8 maps of chapter 6 in both readings.

    Attributes
    ----------
    practical, strict : RegionsData
    """

    practical: RegionsData
    strict: RegionsData

    def summary(self) -> str:
        """Both maps' :meth:`RegionsData.summary`, then the practical per-azimuth picture."""
        return "\n".join([self.practical.summary(), self.strict.summary(), self.practical.side_summary()])

    def facts(self) -> dict:
        """Chapter 6's Fig. 8 numbers: practical ``ch6_p_hover_stable`` of ``ch6_p_n_hover``
        (case, azimuth) pairs in hover, ``ch6_p_mu1`` (first ``mu > 0``), ``ch6_p_fw_stable``
        (stable cells in forward flight), ``ch6_p_lambda0`` (forward C.G. in hover),
        ``ch6_p_adv/ret_<1, mid, last>`` (side fractions of ``W' > 0`` at the first ``mu > 0``,
        at ``mu`` = ``ch6_p_mu_mid`` = 0.1 and at the last); strict ``ch6_s_stable`` of
        ``ch6_s_cells``; ``ch6_root`` (blade root station ``r/R``)."""
        p, s = self.practical, self.strict
        out = {
            "ch6_p_hover_stable": int(p.stable[:, 0].sum()),
            "ch6_p_n_hover": int(p.stable[:, 0].size),
            "ch6_p_mu1": float(p.mu_values[1]),
            "ch6_p_fw_stable": int(p.stable[:, 1:].sum()),
            "ch6_s_stable": int(s.stable.sum()),
            "ch6_s_cells": int(s.stable.size),
            "ch6_root": round(p.root_r_over_R, 3),
            "ch6_p_lambda0": round(float(p.lambda0[0, 0].min()), 3),
        }
        adv, ret = p.positive_side_fractions(0)
        i_mid = int(np.flatnonzero(np.isclose(p.mu_values, 0.1))[0])
        for tag, i in (("1", 1), ("mid", i_mid), ("last", -1)):
            out[f"ch6_p_adv_{tag}"] = round(float(adv[i]), 2)
            out[f"ch6_p_ret_{tag}"] = round(float(ret[i]), 2)
        out["ch6_p_mu_mid"] = float(p.mu_values[i_mid])
        return out


def region_maps(cases=CASES, mu_practical=MU_GRID, mu_strict=MU_GRID_STRICT, *, n_psi: int = 72,
                n_sphere_strict: int = 64) -> RegionMaps:
    """:func:`regions_data` in the practical reading on ``mu_practical`` and in the strict
    reading on ``mu_strict`` (``n_sphere_strict`` quasi-random directions per sphere)."""
    return RegionMaps(
        practical=regions_data(cases, mu_practical, reading="practical", n_psi=n_psi),
        strict=regions_data(cases, mu_strict, reading="strict", n_psi=n_psi, n_sphere=n_sphere_strict),
    )


def _regions_grid(readings) -> tuple[int, int, list]:
    """Panels of the region figures: with two or more readings one column per reading and one
    row per case; with one reading its cases two to a row. Returns ``(nrows, ncols, panels)``,
    ``panels`` a list of ``(index in the grid, reading, case index)``."""
    ncases = max(len(r.cases) for r in readings)
    if len(readings) > 1:
        ncols, nrows = len(readings), ncases
        panels = [(k * ncols + j, reg, k) for j, reg in enumerate(readings) for k in range(len(reg.cases))]
    else:
        ncols = min(2, ncases)
        nrows = -(-ncases // ncols)
        panels = [(k, readings[0], k) for k in range(len(readings[0].cases))]
    return nrows, ncols, panels


def _region_legend(fig, ncols: int, empty_ax=None):
    """The category legend of a region figure: in ``empty_ax`` (a spare grid cell) if given,
    else below the panels, two columns wide if the figure has two; returns the layout's
    ``rect`` keyword."""
    if empty_ax is not None:
        empty_ax.axis("off")
        fig.legend(handles=category_legend_handles(wrap=34), loc="center", fontsize=8,
                   bbox_to_anchor=(0.5, 0.5), bbox_transform=empty_ax.transAxes)
        return {}
    two = ncols > 1
    fig.legend(handles=category_legend_handles(wrap=None if two else 40), loc="lower center",
               ncol=2 if two else 1, fontsize=8)
    height = 3 * 0.2 + 0.15 if two else 5 * 0.2 + 0.4  # legend rows of 8 pt, 0.2 in each, and margins
    return {"rect": (0, height / fig.get_size_inches()[1], 1, 1)}


def figure_regions_polar(*readings: RegionsData, figsize=None):
    """The book's Fig. 8 on the rotor disc (:func:`plot_regions_polar`): with two readings one
    column per reading and one row per case, with one reading its cases two to a row; the
    category legend below (or in a spare cell). ``figsize`` defaults to 4.3 in per column and
    3.75 in per row plus the legend (8.6 x 12.0 in for the book's two readings of three cases).
    Laid out and checked (:func:`rotorlyap.chapters.style.finish`); returns the Figure."""
    nrows, ncols, panels = _regions_grid(readings)
    spare = len(readings) == 1 and nrows * ncols > len(panels)
    if figsize is None:
        figsize = (4.3 * ncols, 3.75 * nrows + (0 if spare else 0.75 if ncols > 1 else 1.4))
    fig = figure(figsize=figsize)
    for idx, reg, k in panels:
        ax = fig.add_subplot(nrows, ncols, idx + 1, projection="polar")
        plot_regions_polar(reg, ax, k, title=f"{reg.cases[k]} C.G., {reg.label}")
    empty = fig.add_subplot(nrows, ncols, nrows * ncols) if spare else None
    return finish(fig, **_region_legend(fig, ncols, empty))


def figure_regions_plane(*readings: RegionsData, figsize=None):
    """The maps of :func:`figure_regions_polar` in the (psi, mu) plane
    (:func:`plot_regions_plane`), in the same grid; ``figsize`` defaults to 4.3 in per column
    and 2.75 in per row plus the legend (8.6 x 9.0 in for the book's two readings of three
    cases). Laid out and checked (:func:`rotorlyap.chapters.style.finish`); returns the Figure."""
    nrows, ncols, panels = _regions_grid(readings)
    spare = len(readings) == 1 and nrows * ncols > len(panels)
    if figsize is None:
        figsize = (4.3 * ncols, 2.75 * nrows + (0 if spare else 0.75 if ncols > 1 else 1.4))
    fig, axes = subplots(nrows, ncols, figsize=figsize, sharex=True, squeeze=False)
    axes = axes.ravel()
    for idx, reg, k in panels:
        ax = axes[idx]
        plot_regions_plane(reg, ax, k, title=f"{reg.cases[k]} C.G., {reg.label}", legend=False)
        if not ax.get_subplotspec().is_last_row():
            ax.set_xlabel("")
        if not ax.get_subplotspec().is_first_col():
            ax.set_ylabel("")
    empty = axes[-1] if spare else None
    return finish(fig, **_region_legend(fig, ncols, empty))


@dataclass(frozen=True)
class HoverFlutterCheck:
    """Linear theory against the practical reading in hover: the largest growth rate of each
    case, and a blade that flutters (a case without the aerodynamic pitch damping,
    ``cm_pitch_rate = 0``) in the practical reading.

    Attributes
    ----------
    case_names : tuple of str
    growth_rate : numpy.ndarray
        Largest real part of the linearised hover eigenvalues of each case, per rev, (3,).
    flutter_case : str
    flutter_growth_rate : float
        The same for the fluttering blade, per rev.
    flutter_stable : int
        Azimuths the practical reading calls stable for it, of ``n_psi``.
    n_psi : int
    """

    case_names: tuple
    growth_rate: np.ndarray
    flutter_case: str
    flutter_growth_rate: float
    flutter_stable: int
    n_psi: int

    def summary(self) -> str:
        """The fluttering blade's growth rate (per rev, 0.001) and practical verdict."""
        return (f"{self.flutter_case} C.G. without pitch damping, hover: largest real part "
                f"{self.flutter_growth_rate:+.3f}, practical (indicator): passes at {self.flutter_stable} of {self.n_psi} azimuths")

    def facts(self) -> dict:
        """``ch6_flut_re`` (signed text, per rev) and ``ch6_flut_stable`` (azimuths)."""
        return {"ch6_flut_re": f"{self.flutter_growth_rate:+.3f}", "ch6_flut_stable": self.flutter_stable}


def hover_flutter_check(cases=CASES, flutter_case: str = "backward", *, n_psi: int = 72,
                        test_disturbances=PAPER_TEST_DISTURBANCES) -> HoverFlutterCheck:
    """Compute :class:`HoverFlutterCheck` (:func:`rotorlyap.model.modes.hover_modes`, then the
    practical reading of the fluttering blade on ``n_psi`` azimuths)."""
    p_flut = case_params(flutter_case, cm_pitch_rate=0.0)
    stable = blade_stability(p_flut, 0.0, n_psi=n_psi, test_disturbances=test_disturbances).stable
    return HoverFlutterCheck(
        case_names=tuple(cases),
        growth_rate=np.array([least_damped(hover_modes(case_params(c))).growth_rate for c in cases]),
        flutter_case=flutter_case, flutter_growth_rate=float(least_damped(hover_modes(p_flut)).growth_rate),
        flutter_stable=int(stable.sum()), n_psi=int(n_psi),
    )


def practical_threshold_mu(cg="forward", *, mu_lo: float = 1e-6, mu_hi: float = 0.05, n_bisect: int = 20,
                           n_psi: int = 72, test_disturbances=PAPER_TEST_DISTURBANCES,
                           params_overrides: dict | None = None, **options) -> float:
    """Smallest advance ratio at which the practical reading stops reporting every azimuth
    stable: geometric bisection between ``mu_lo`` (must be stable at every azimuth) and
    ``mu_hi`` (must not be); returns the upper end of the final bracket. Returns ``mu_lo``
    if ``mu_lo`` is already not stable everywhere (the threshold is below it)."""
    p = case_params(cg, **(params_overrides or {}))

    def ok(mu):
        return bool(blade_stability(p, mu, n_psi=n_psi, test_disturbances=test_disturbances, **options).stable.all())

    lo, hi = float(mu_lo), float(mu_hi)
    if not ok(lo):
        return lo
    if ok(hi):
        raise ValueError(f"practical_threshold_mu: every azimuth is stable at mu_hi = {hi:g}")
    for _ in range(n_bisect):
        mid = float(np.sqrt(lo * hi))
        lo, hi = (mid, hi) if ok(mid) else (lo, mid)
    return hi


#: Test-disturbance sets of the threshold study, by name, with the short tag of their glue names.
THRESHOLD_TEST_SETS = {
    "12 axes": ("12", PAPER_TEST_DISTURBANCES),
    "flap and lag axes": ("fl", FLAP_LAG_TEST_DISTURBANCES),
}


@dataclass(frozen=True)
class ThresholdData:
    """The practical threshold (:func:`practical_threshold_mu`) for several inflow models and
    test-disturbance sets, and for one model the hover start region and the flight speed.

    Attributes
    ----------
    cg : str or float
    models : tuple of str
        Inflow models.
    test_sets : tuple of str
        Keys of :data:`THRESHOLD_TEST_SETS`.
    threshold : numpy.ndarray
        Advance ratio up to which the practical reading passes at every azimuth,
        (len(models), len(test_sets)).
    speed_model : str
        The model of :attr:`hover_lambda0` and :attr:`speed`.
    hover_lambda0 : numpy.ndarray
        Practical start region in hover, per test set, -.
    speed : numpy.ndarray
        Threshold flight speed ``mu Omega R``, per test set, m/s.
    mu_lo : float
        The smallest advance ratio the bisection tried; a threshold equal to it means the
        indicator already fails there.
    """

    cg: object
    models: tuple
    test_sets: tuple
    threshold: np.ndarray
    speed_model: str
    hover_lambda0: np.ndarray
    speed: np.ndarray
    mu_lo: float = 1e-7

    def threshold_of(self, model: str, test_set: str) -> float:
        """The threshold of one inflow model and test set."""
        return float(self.threshold[self.models.index(model), self.test_sets.index(test_set)])

    def _threshold_words(self, thr: float) -> str:
        """The threshold in words: where the bisection ran, the advance ratio below which the
        indicator passes at every azimuth; where it already fails at the smallest advance ratio
        tried (:func:`practical_threshold_mu` then returns that ratio), that."""
        if thr <= self.mu_lo:
            return f"fails already at mu = {self.mu_lo:.2g} (threshold below it)"
        return f"passes at every azimuth below mu = {thr:.2g}"

    def summary(self) -> str:
        """Every threshold (2 digits), then the start region (0.001) and threshold speed (m/s,
        2 digits) of :attr:`speed_model`."""
        lines = [f"inflow {model:8s}, {tname:18s}: " + self._threshold_words(self.threshold_of(model, tname))
                 for model in self.models for tname in self.test_sets]
        lines += [f"inflow {self.speed_model:8s}, {tname:18s}: hover start region lambda0 = {lam:.3f}; "
                  f"threshold flight speed {v:.2g} m/s"
                  for tname, lam, v in zip(self.test_sets, self.hover_lambda0, self.speed)]
        return "\n".join(lines)

    def facts(self) -> dict:
        """For :attr:`speed_model` (tag: its first two letters) and each test set (tag of
        :data:`THRESHOLD_TEST_SETS`): ``ch6_thr_<m>_<t>`` (2 digits), ``ch6_lam_<m>_<t>``
        (0.001) and ``ch6_v_<m>_<t>`` (m/s, 2 digits)."""
        m = self.speed_model[:2]
        out = {}
        for tname in self.test_sets:
            thr = self.threshold_of(self.speed_model, tname)
            out[f"ch6_thr_{m}_{THRESHOLD_TEST_SETS[tname][0]}"] = float("%.2g" % thr)
        for tname, lam, v in zip(self.test_sets, self.hover_lambda0, self.speed):
            tag = THRESHOLD_TEST_SETS[tname][0]
            out[f"ch6_lam_{m}_{tag}"] = round(float(lam), 3)
            out[f"ch6_v_{m}_{tag}"] = float("%.2g" % v)
        return out


def practical_threshold_data(cg="forward", models=("glauert", "drees"), test_sets=tuple(THRESHOLD_TEST_SETS), *,
                             speed_model: str = "drees", mu_lo: float = 1e-7, n_psi: int = 72,
                             n_bisect: int = 20) -> ThresholdData:
    """Bisect the practical threshold for each inflow model and test set (``mu_lo``, ``n_psi``
    and ``n_bisect`` go to :func:`practical_threshold_mu`), and for ``speed_model`` the hover
    start region (4 azimuths: nothing depends on the azimuth in hover) and the speed."""
    thr = np.array([[practical_threshold_mu(cg, mu_lo=mu_lo, n_psi=n_psi, n_bisect=n_bisect,
                                            test_disturbances=THRESHOLD_TEST_SETS[t][1],
                                            params_overrides=dict(inflow_model=model))
                     for t in test_sets] for model in models])
    p = case_params(cg, inflow_model=speed_model)
    lam = np.array([float(blade_stability(p, 0.0, n_psi=4, test_disturbances=THRESHOLD_TEST_SETS[t][1]).lambda0.min())
                    for t in test_sets])
    speed = thr[list(models).index(speed_model)] * p.rotor_speed * p.radius
    return ThresholdData(cg=cg, models=tuple(models), test_sets=tuple(test_sets), threshold=thr,
                         speed_model=speed_model, hover_lambda0=lam, speed=speed, mu_lo=float(mu_lo))


# --------------------------------------------------------------------------------------
# Sensitivity of Fig. 8
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class SensitivityData:
    """Fig. 8 (practical reading, one case) under several choices of A, a_i and test directions.

    Attributes
    ----------
    names : tuple of str
        The variants.
    regions : tuple of RegionsData
        One per variant (one case each).
    scales : tuple of numpy.ndarray
        The scales of each variant.
    n_tests : tuple of int
        Number of test disturbances of each variant.
    """

    names: tuple
    regions: tuple
    scales: tuple
    n_tests: tuple

    @property
    def n_evaluations(self) -> int:
        return int(sum(r.n_evaluations for r in self.regions))

    def first_unstable(self, tol_fraction: float = 0.0) -> list[tuple[float, float, float]]:
        """For each variant: the smallest mu > 0 with an azimuth not stable, and the fractions
        of its unstable azimuths on the advancing (0-180 deg) and retreating sides."""
        out = []
        for r in self.regions:
            row = (np.nan, np.nan, np.nan)
            for i, mu in enumerate(r.mu_values):
                bad = ~r.stable[0, i]
                if mu > 0 and bad.mean() > tol_fraction:
                    adv = (r.psi > 0) & (r.psi < np.pi)
                    ret = r.psi > np.pi
                    row = (float(mu), float(bad[adv].mean()), float(bad[ret].mean()))
                    break
            out.append(row)
        return out

    def variant(self, name: str) -> RegionsData:
        """The map of one variant."""
        return self.regions[self.names.index(name)]

    def stable_forward_flight(self, name: str) -> tuple[int, float, list[int]]:
        """Of one variant: the stable cells with ``mu > 0``, the first such ``mu`` and its stable
        azimuths (deg); ``(0, nan, [])`` if there are none."""
        r = self.variant(name)
        rows = np.flatnonzero(r.stable[0, 1:].any(axis=1)) + 1
        if rows.size == 0:
            return 0, float("nan"), []
        i = int(rows[0])
        return (int(r.stable[0, 1:].sum()), float(r.mu_values[i]),
                [int(v) for v in np.round(np.degrees(r.psi[r.stable[0, i]]))])

    def summary(self) -> str:
        """Per variant: test disturbances, hover start region, bound after step 3 and stable
        azimuths per ``mu``; whether the flap-and-lag variant gives the default map; where the
        ``A = 4`` variant keeps its bound and is stable in forward flight (default variants of
        :func:`sensitivity_data`)."""
        lines = [_line("mu:", self.regions[0].mu_values),
                 "variant                        tests  hover lambda0  A after step 3 (per mu)            "
                 "azimuths passing (per mu)"]
        for name, r, n in zip(self.names, self.regions, self.n_tests):
            lines.append(f"{name:30s} {n:4d}  {r.lambda0[0, 0].min():12.3f}  {np.round(r.A_used[0], 3)}  "
                         f"{r.stable[0].sum(axis=1)}")
        fl = self.variant("flap and lag axes only (8)")
        lines.append(_line("flap and lag axes only: the same map as the default, cell by cell:",
                           np.array_equal(fl.category[0, :, :], self.regions[0].category[0, :, :])))
        r4 = self.variant("A = 4")
        ok4 = np.flatnonzero(r4.A_used[0] > 0)
        i4 = np.flatnonzero(r4.stable[0, 1:].any(axis=1)) + 1
        lines.append(_line("A = 4: step 3 keeps A up to mu =", r4.mu_values[ok4[-1]], "; passing cells with mu > 0 at",
                           [(float(r4.mu_values[i]), [int(v) for v in np.round(np.degrees(r4.psi[r4.stable[0, i]]))])
                            for i in i4],
                           "; lambda0 =", np.round(np.unique(r4.lambda0[0, 1:ok4[-1] + 1]), 3)))
        return "\n".join(lines)

    def facts(self) -> dict:
        """Chapter 6's sensitivity numbers (default variants of :func:`sensitivity_data`):
        ``ch6_a4_*`` (the ``A = 4`` variant: last ``mu`` where step 3 keeps ``A``, the next,
        its stable cells with ``mu > 0``, the first such ``mu`` and its azimuths, its start
        region), ``ch6_bal_lambda0``, ``ch6_def_lambda0`` (hover start regions, 0.001),
        ``ch6_diag_A0`` (hover bound with the diagonals), ``ch6_sens_fw_stable`` (stable
        cells with ``mu > 0`` over all variants) and ``ch6_bal_scales`` (the balanced scales,
        deg and deg/rad, as text)."""
        r4 = self.variant("A = 4")
        ok4 = np.flatnonzero(r4.A_used[0] > 0)
        n4, mu4, psi4 = self.stable_forward_flight("A = 4")
        bal = self.names.index("energy-balanced a_i")
        return {
            "ch6_a4_mu_last": float(r4.mu_values[ok4[-1]]),
            "ch6_a4_mu_fail": float(r4.mu_values[ok4[-1] + 1]),
            "ch6_a4_stable": n4,
            "ch6_a4_stable_mu": mu4,
            "ch6_a4_stable_psi": ", ".join(str(v) for v in psi4),
            "ch6_a4_lambda0": round(float(r4.lambda0[0, 1].min()), 3),
            "ch6_bal_lambda0": round(float(self.regions[bal].lambda0[0, 0].min()), 3),
            "ch6_def_lambda0": round(float(self.regions[0].lambda0[0, 0].min()), 3),
            "ch6_diag_A0": round(float(self.variant("axes + diagonals (72)").A_used[0, 0]), 4),
            "ch6_sens_fw_stable": int(sum(r.stable[0, 1:].sum() for r in self.regions)),
            "ch6_bal_scales": ", ".join(f"{v:.2f}" for v in np.degrees(self.scales[bal])),
        }

    def export(self) -> list:
        """Named columns for :func:`rotorlyap.chapters.export.figure_csv`: ``v<k>_category``
        (mu, psi) and ``v<k>_A_used`` (mu) of variant ``k``, then ``mu`` and ``psi_deg``."""
        return ([(f"v{i}_" + k, v) for i, r in enumerate(self.regions)
                 for k, v in (("category", r.category[0]), ("A_used", r.A_used[0]))]
                + [("mu", self.regions[0].mu_values), ("psi_deg", np.degrees(self.regions[0].psi))])


def sensitivity_data(cg="forward", mu_values=(0.0, 0.0125, 0.025, 0.05, 0.1, 0.15, 0.2, 0.25), variants: dict | None = None, *, n_psi: int = 72) -> SensitivityData:
    """Run the practical Fig. 8 for each variant: ``{name: dict(A=, scales=, test_disturbances=)}``.

    Default variants: the report's default (12 axes, A = 1, default scales); A = 0.5, 2 and 4;
    energy-balanced scales (:func:`balanced_scales`); the axes and pairwise diagonals; the
    flap and lag axes only (no pitch rate).
    """
    if variants is None:
        variants = {
            "default: 12 axes, A = 1": {},
            "A = 0.5": dict(A=0.5),
            "A = 2": dict(A=2.0),
            "A = 4": dict(A=4.0),
            "energy-balanced a_i": dict(scales=balanced_scales(case_params(cg))),
            "axes + diagonals (72)": dict(test_disturbances=AXES_AND_DIAGONALS),
            "flap and lag axes only (8)": dict(test_disturbances=FLAP_LAG_TEST_DISTURBANCES),
        }
    regs, scales, ntest = [], [], []
    for name, kw in variants.items():
        kw = dict(kw)
        tests = kw.pop("test_disturbances", PAPER_TEST_DISTURBANCES)
        regs.append(regions_data((cg,), mu_values, reading="practical", n_psi=n_psi, test_disturbances=tests, **kw))
        scales.append(np.array(DEFAULT_SCALES if kw.get("scales") is None else kw["scales"], dtype=float))
        ntest.append(int(np.asarray(tests).shape[0]))
    return SensitivityData(names=tuple(variants), regions=tuple(regs), scales=tuple(scales), n_tests=tuple(ntest))


def plot_sensitivity(data: SensitivityData, axes) -> None:
    """One (psi, mu) map per variant; the first spare axes, if any, holds the category legend.
    Axis labels only on the outer panels of a grid."""
    axes = np.ravel(axes)
    for i, (ax, name, reg) in enumerate(zip(axes, data.names, data.regions)):
        plot_regions_plane(reg, ax, 0, title=name, legend=False)
        spec = ax.get_subplotspec()
        if spec is None:
            continue
        if not spec.is_first_col():
            ax.set_ylabel("")
        if i + spec.get_gridspec().ncols < len(data.names):
            ax.set_xlabel("")  # another map below
        else:
            ax.tick_params(labelbottom=True)  # the lowest map of its column
    for ax in axes[len(data.names):]:
        ax.axis("off")
        ax.legend(handles=category_legend_handles("reverse flow reaches the root", wrap=34), fontsize=8, loc="center")
        break


def figure_sensitivity(data: SensitivityData, figsize=(8.6, 10.4)):
    """The book's sensitivity figure (:func:`plot_sensitivity` on a grid two panels wide, shared
    axes, the legend in the spare cell), laid out and checked
    (:func:`rotorlyap.chapters.style.finish`); returns the Figure."""
    nrows = (len(data.names) + 2) // 2
    fig, axes = subplots(nrows, 2, figsize=figsize, sharex=True, sharey=True)
    plot_sensitivity(data, axes)
    return finish(fig)


# --------------------------------------------------------------------------------------
# Convergence
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class ConvergenceData:
    """Numbers of Figs 5 and 8 against the resolution parameters.

    Attributes
    ----------
    n_sphere : numpy.ndarray
        Quasi-random directions per sphere, (p,).
    sup_dW_hover : numpy.ndarray
        Strict ``max W'`` on the sphere ``A`` in hover for each case, (3, p), J/rad.
    n_stations : numpy.ndarray
        Spanwise stations, (s,).
    collective : numpy.ndarray
        Trimmed collective for each case, (3, s), rad.
    sup_dW_stations : numpy.ndarray
        Strict ``max W'`` in hover (forward C.G.), (s,), J/rad.
    practical_rate_stations : numpy.ndarray
        Practical max ``W'`` over the 12 axes at ``mu_check`` averaged over the azimuths, (s,).
    n_psi : numpy.ndarray
        Azimuth grids, (q,).
    unstable_fraction_psi : numpy.ndarray
        Unstable fraction of azimuths of the practical Fig. 8 (forward C.G., variant
        ``variant``) at each mu, (q, m).
    positive_fraction_psi : numpy.ndarray
        Fraction of azimuths of the same maps where ``W' > 0`` on the requested sphere
        (category 3: the per-azimuth picture), (q, m).
    mu_values : numpy.ndarray
        (m,).
    mu_check : float
    variant : str
    """

    n_sphere: np.ndarray
    sup_dW_hover: np.ndarray
    n_stations: np.ndarray
    collective: np.ndarray
    sup_dW_stations: np.ndarray
    practical_rate_stations: np.ndarray
    n_psi: np.ndarray
    unstable_fraction_psi: np.ndarray
    positive_fraction_psi: np.ndarray
    mu_values: np.ndarray
    mu_check: float
    variant: str

    @property
    def default_stations_index(self) -> int:
        """Index in :attr:`n_stations` of the model's default number of stations."""
        return int(np.flatnonzero(self.n_stations == case_params("forward").n_stations)[0])

    def deviations(self) -> tuple[float, float, float]:
        """Largest relative deviations from the finest resolution: of the strict hover maxima
        with 64 or more directions (the second column on), of the three quantities at the
        default number of stations, and (absolute) of the per-azimuth fraction with
        ``W' > 0`` on coarser azimuth grids."""
        dev_ns = np.abs(self.sup_dW_hover[:, 1:] / self.sup_dW_hover[:, -1:] - 1).max()
        i = self.default_stations_index
        dev_st = max(abs(self.sup_dW_stations[i] / self.sup_dW_stations[-1] - 1),
                     abs(self.practical_rate_stations[i] / self.practical_rate_stations[-1] - 1),
                     np.abs(self.collective[:, i] / self.collective[:, -1] - 1).max())
        dev_psi = np.abs(self.positive_fraction_psi[:-1] - self.positive_fraction_psi[-1]).max()
        return float(dev_ns), float(dev_st), float(dev_psi)

    def bounds(self) -> tuple[float, float]:
        """The first two :meth:`deviations` in percent, as the power of ten they stay below
        (:func:`rotorlyap.reporting.decade_above`)."""
        dev_ns, dev_st, _ = self.deviations()
        return decade_above(max(100 * dev_ns, 1e-6)), decade_above(max(100 * dev_st, 1e-6))

    def summary(self) -> str:
        """Every convergence number (J/rad, deg, fractions) and the deviation bounds."""
        bound_ns, bound_st = self.bounds()
        i = self.default_stations_index
        return "\n".join([
            _line("n_sphere:", self.n_sphere),
            _line("strict hover max W' (J/rad):\n", np.round(self.sup_dW_hover, 2)),
            _line("n_stations:", self.n_stations),
            _line("collective (deg):\n", np.round(np.degrees(self.collective), 3)),
            _line("strict hover max W' (J/rad):", np.round(self.sup_dW_stations, 2)),
            _line(f"practical max W' at mu = {self.mu_check:g}, azimuth mean (J/rad):",
                  np.round(self.practical_rate_stations, 1)),
            _line("fraction of azimuths that do not pass (flap and lag axes) per mu, for n_psi =", self.n_psi),
            str(np.round(self.unstable_fraction_psi, 3)),
            "W' > 0 on the sphere (flap and lag axes), fraction of azimuths per mu:",
            str(np.round(self.positive_fraction_psi, 3)),
            f"largest deviation: n_sphere >= {self.n_sphere[1]}: < {bound_ns:.0e} %; "
            f"{self.n_stations[i]} stations vs {self.n_stations[-1]}: < {bound_st:.0e} %",
            "per-azimuth fraction, largest difference from %d azimuths: %.3f" % (self.n_psi[-1], self.deviations()[2]),
        ])

    def facts(self) -> dict:
        """``ch6_dev_ns``, ``ch6_dev_st`` (:meth:`bounds`, %) and ``ch6_dev_psi`` (0.001)."""
        bound_ns, bound_st = self.bounds()
        return {"ch6_dev_ns": bound_ns, "ch6_dev_st": bound_st, "ch6_dev_psi": round(self.deviations()[2], 3)}


#: Refined starts of every strict search of :func:`convergence_data`.
CONVERGENCE_N_REFINE = 16


def convergence_data(n_sphere_values=(0, 64, 256, 1024, 4096), n_stations_values=(6, 8, 12, 16, 24),
                     n_psi_values=(36, 72, 144), mu_values=MU_GRID, *, mu_check: float = 0.15,
                     test_disturbances=FLAP_LAG_TEST_DISTURBANCES,
                     variant: str = "flap and lag axes only (8)") -> ConvergenceData:
    """Compute :class:`ConvergenceData` (strict hover searches and practical maps)."""
    a = DEFAULT_SCALES
    psi0 = np.array([0.0])
    sup = np.zeros((len(CASES), len(n_sphere_values)))
    for i, cg in enumerate(CASES):
        fun = energy_function(Blade(case_params(cg), 0.0))
        for j, ns in enumerate(n_sphere_values):
            sup[i, j] = sphere_extremum(fun.dW, psi0, DEFAULT_A, a, unit_sphere_points(6, int(ns)),
                                        n_refine=CONVERGENCE_N_REFINE, n_iter=60).value[0]
    col = np.zeros((len(CASES), len(n_stations_values)))
    sup_st = np.zeros(len(n_stations_values))
    prac = np.zeros(len(n_stations_values))
    tests = PAPER_TEST_DISTURBANCES
    psi = 2 * np.pi * np.arange(72) / 72
    for j, ns in enumerate(n_stations_values):
        for i, cg in enumerate(CASES):
            col[i, j] = hover_trim(case_params(cg, n_stations=int(ns))).collective
        p = case_params("forward", n_stations=int(ns))
        blade = Blade(p, 0.0)
        xi = blade.equilibrium()
        fun = energy_function(blade, xi)
        sup_st[j] = sphere_extremum(fun.dW, psi0, DEFAULT_A, a, unit_sphere_points(6, 1024),
                                    n_refine=CONVERGENCE_N_REFINE, n_iter=60).value[0]
        dwf = energy_function(Blade(p, mu_check), xi).dW
        vals = dwf(np.repeat(psi, len(tests)), np.tile(tests * a, (psi.size, 1))).reshape(psi.size, -1)
        prac[j] = vals.max(axis=1).mean()
    frac, pos = [], []
    for npsi in n_psi_values:
        reg = regions_data(("forward",), mu_values, reading="practical", n_psi=int(npsi),
                           test_disturbances=test_disturbances)
        frac.append(reg.unstable_fraction()[0])
        pos.append((reg.category[0] == 3).mean(axis=-1))
    return ConvergenceData(
        n_sphere=np.asarray(n_sphere_values), sup_dW_hover=sup, n_stations=np.asarray(n_stations_values),
        collective=col, sup_dW_stations=sup_st, practical_rate_stations=prac,
        n_psi=np.asarray(n_psi_values), unstable_fraction_psi=np.array(frac),
        positive_fraction_psi=np.array(pos),
        mu_values=np.asarray(mu_values, dtype=float), mu_check=float(mu_check), variant=variant,
    )


def plot_convergence(data: ConvergenceData, axes) -> None:
    """(a) strict hover sup against n_sphere; (b) against n_stations, with the collective;
    (c) the practical unstable fraction against mu for each azimuth grid. Each C.G. case in
    its colour and marker."""
    ax_a, ax_b, ax_c = axes
    ns = np.where(data.n_sphere == 0, 1, data.n_sphere)
    tick_labels = ["0" if v == 0 else f"{v // 1024}k" if v >= 1024 and v % 1024 == 0 else f"{v:d}"
                   for v in data.n_sphere]
    dev = lambda v, ref: 100.0 * (v / ref - 1.0)  # noqa: E731
    for i, cg in enumerate(CASES):
        ax_a.plot(ns, dev(data.sup_dW_hover[i], data.sup_dW_hover[i, -1]), "-", marker=CG_MARKERS[cg], ms=5,
                  color=CG_COLORS[cg], label=f"{cg} C.G.")
    ax_a.set_xscale("log", base=2)
    ax_a.set_xticks(ns, tick_labels)
    ax_a.axhline(0, color="0.5", lw=0.6)
    ax_a.set_xlabel("quasi-random directions per sphere\n(0 = structured only)", fontsize=9)
    ax_a.set_ylabel("strict max $W'$ in hover:\ndeviation from finest (%)", fontsize=9)
    ax_a.set_title("(a) sampling resolution", fontsize=9)
    ax_a.legend(fontsize=8)
    st = data.n_stations
    ax_b.plot(st, dev(data.sup_dW_stations, data.sup_dW_stations[-1]), "o-", color="k", ms=4,
              label="strict max $W'$, hover")
    ax_b.plot(st, dev(data.practical_rate_stations, data.practical_rate_stations[-1]), "D-", color="#0072B2", ms=4,
              label=f"practical max $W'$, $\\mu$ = {data.mu_check:g}\n(azimuth mean)")
    for i, cg in enumerate(CASES):
        ax_b.plot(st, dev(data.collective[i], data.collective[i, -1]), "--", marker=CG_MARKERS[cg], ms=4,
                  color=CG_COLORS[cg], label=f"collective, {cg} C.G.")
    ax_b.axhline(0, color="0.5", lw=0.6)
    ax_b.set_xticks(st)
    ax_b.set_xlabel("spanwise stations", fontsize=9)
    ax_b.set_ylabel(f"deviation from {st[-1]} stations (%)", fontsize=9)
    ax_b.set_title("(b) spanwise stations", fontsize=9)
    lo, hi = ax_b.get_ylim()
    ax_b.set_ylim(lo, hi + 0.75 * (hi - lo))  # room for the legend above the curves
    ax_b.legend(fontsize=8, loc="upper right")
    for k, npsi in enumerate(data.n_psi):
        line, = ax_c.plot(data.mu_values, data.unstable_fraction_psi[k], "o-", ms=3,
                          label=f"does not pass, {npsi} azimuths")
        ax_c.plot(data.mu_values, data.positive_fraction_psi[k], "s--", ms=3, color=line.get_color(),
                  label=f"$W' > 0$ on the sphere, {npsi} azimuths")
    ax_c.set_xlabel(r"advance ratio $\mu$", fontsize=9)
    ax_c.set_ylabel("fraction of azimuths", fontsize=9)
    ax_c.set_title(f"(c) azimuth grid (practical, {data.variant})", fontsize=9)
    ax_c.legend(fontsize=8, loc="center left", bbox_to_anchor=(1.01, 0.5))
    for ax in axes:
        ax.tick_params(labelsize=8)


def figure_convergence(data: ConvergenceData, figsize=(9.0, 7.4)):
    """The book's convergence figure (:func:`plot_convergence`: (a) and (b) side by side, (c)
    below them), laid out and checked (:func:`rotorlyap.chapters.style.finish`); returns the
    Figure."""
    fig = figure(figsize=figsize)
    grid = fig.add_gridspec(2, 2, height_ratios=(1.1, 1))
    axes = [fig.add_subplot(grid[0, 0]), fig.add_subplot(grid[0, 1]), fig.add_subplot(grid[1, :])]
    plot_convergence(data, axes)
    return finish(fig)


# --------------------------------------------------------------------------------------
# Tables
# --------------------------------------------------------------------------------------



#: Header of chapter 6's claims table.
CLAIMS_HEADER = ("claim (the paper's figure numbers)", "strict (numerical certificate)",
                 "practical (indicator, not a certificate)", "evidence", "where we differ, and why")


@dataclass(frozen=True)
class ClaimsTable:
    """Each claim of the paper's section 5 with the verdict in each reading, the evidence and
    where we differ (chapter 6).

    Attributes
    ----------
    header : tuple of str
    rows : tuple of tuple of str
        One per claim, in the order of ``header`` (the evidence cells hold MyST roles).
    """

    header: tuple
    rows: tuple

    def markdown(self) -> str:
        """The table in Markdown (:func:`rotorlyap.chapters.export.markdown_table`), its symbols
        typeset (:func:`myst_math`)."""
        return markdown_table([myst_math(h) for h in self.header],
                              [[myst_math(c) for c in r] for r in self.rows])

    def summary(self) -> str:
        """One line per claim: its start and the start of each reading's verdict."""
        lines = []
        for r in self.rows:
            strict, practical = r[1].split(":")[0], r[2].split(":")[0]
            lines.append(f"{r[0][:60]:60s} | strict: {strict[:30]:30s} | practical: {practical[:30]}")
        return "\n".join(lines)


_PLAIN_SYMBOLS = re.compile(r"\b(?:(max|min|inf|sup) )?W\b('?)|\bmu\b|\bA\^2\b|\bx = 0\b|\b1e-7\b")
_KEEP = re.compile(r"(\$[^$]*\$|\{[a-z:]+\}`[^`]*`)")


def myst_math(text: str) -> str:
    """``text`` with its plain-text symbols typeset as MyST math: ``W'``, ``max W'``, ``inf W``,
    ``mu``, ``A^2``, ``x = 0``, ``1e-7``; math and roles already in ``text`` are left alone."""
    def sub(m: re.Match) -> str:
        t = m.group(0)
        if t == "mu":
            return r"$\mu$"
        if t == "1e-7":
            return r"$10^{-7}$"
        if m.group(1):
            return "$\\%s W%s$" % (m.group(1), m.group(2))
        return f"${t}$"
    parts = _KEEP.split(text)
    return "".join(p if i % 2 else _PLAIN_SYMBOLS.sub(sub, p) for i, p in enumerate(parts))


def claims_table(convergence: ConvergenceData, w_spheres: WSpheresData, rate: RateAzimuthData,
                 regions: RegionMaps, flutter: HoverFlutterCheck, threshold: ThresholdData,
                 sensitivity: SensitivityData) -> ClaimsTable:
    """The claims table of chapter 6 from the chapter's results (nothing is recomputed)."""
    i12 = convergence.default_stations_index
    col = np.degrees(convergence.collective[:, i12])
    smax_h = convergence.sup_dW_hover[:, -1]
    reg_p, reg_s = regions.practical, regions.strict
    hover_p, hover_s = reg_p.stable[:, 0], reg_s.stable[:, 0]
    n4, mu4, _ = sensitivity.stable_forward_flight("A = 4")
    adv1, ret1 = (a[1] for a in reg_p.positive_side_fractions(0))
    adv_last, ret_last = (a[-1] for a in reg_p.positive_side_fractions(0))
    wsph = w_spheres
    rows = [
        ("paper's Fig. 4: hover equilibrium angles for the three C.G. positions (a code test)",
         "reproduced (a computation, no Liapunov reading involved)",
         "reproduced (a computation, no Liapunov reading involved)",
         "collective " + " / ".join(f"{c:.2f}" for c in col) + " deg for forward / neutral / backward; "
         "equilibrium angles nearly equal; thrust = weight ({numref}`fig-hover-trim`)",
         "the paper's figure is lost: the computation, not its numbers, can be compared"),
        ("paper's Fig. 5: W' in hover against C.G.: stability decreases as the C.G. moves aft",
         "not reproduced: max W' on the sphere " + " / ".join(f"{v:.1f}" for v in smax_h)
         + " J/rad (flat, slightly decreasing aft; nothing certified)",
         "not reproduced: max W' over the 12 axes is 0 at every C.G.",
         "{numref}`fig-hover-rate`; linear theory agrees with the paper: largest real part "
         + " / ".join(f"{e:+.3f}" for e in flutter.growth_rate) + " (forward / neutral / backward)",
         "the statement is true of the model (all three stable, the damping margin shrinking aft), but the "
         "energy cannot see it: its W' > 0 comes from the flap moment due to pitch, which does not depend on the C.G."),
        ("paper's Fig. 6: W at mu = 0.15 (forward C.G.) against azimuth and A: W decreases as A increases",
         f"not reproduced: inf W = {wsph.strict_inf[0].mean():.3f} ... {wsph.strict_inf[-1].mean():.2f} J for A = "
         f"{wsph.A_values[0]:g} ... {wsph.A_values[-1]:g}",
         f"not reproduced: min W over the axes = {wsph.practical_min[0].mean():.3f} ... "
         f"{wsph.practical_min[-1].mean():.2f} J",
         "{numref}`fig-w-spheres`: W grows as A^2 and does not depend on the azimuth",
         "an energy about a constant steady state has no azimuth in it and scales as A^2; the paper's figure "
         "must show another, or a normalised, quantity (unknown)"),
        ("paper's Fig. 7: W' in forward flight (no separate statement)",
         f"W' > 0 at every azimuth for mu > 0; up to {rate.strict_max[-1].max():.0f} J/rad at mu = 0.25",
         f"W' > 0 at {int((rate.practical_max[1] > 0).sum())} of 72 azimuths already at mu = 0.05",
         "{numref}`fig-rate-azimuth`",
         "W' is the work of the forward-flight loads left unbalanced by the reused hover equilibrium"),
        ("paper's Fig. 8: \"stable\" at every azimuth in hover",
         f"not reproduced: nothing certified ({int(hover_s.sum())} of {hover_s.size} (case, azimuth) pairs)",
         f"reproduced: {int(hover_p.sum())} of {hover_p.size} (case, azimuth) pairs pass (indicator)",
         "{numref}`fig-regions-polar`, {numref}`fig-regions-plane`",
         "agrees with linear theory for these blades (all stable), but is an indicator, not a certificate: "
         f"it also passes the hover of a blade that flutters (backward C.G. without pitch damping, "
         f"largest real part {flutter.flutter_growth_rate:+.3f}: {flutter.flutter_stable} of 72 azimuths)"),
        ("paper's Fig. 8: as mu grows, a region of instability appears first on the retreating side (stall flutter)",
         f"not reproduced: nothing certified at any mu ({int(reg_s.stable.sum())} certified cells)",
         f"not reproduced: no azimuth passes from mu = {reg_p.mu_values[1]:g} on, for every C.G. "
         f"({int(reg_p.stable[:, 1:].sum())} passing cells); with A = 4, {n4} of 72 azimuths "
         f"at mu = {mu4:g} and none beyond",
         "{numref}`fig-regions-plane`, {numref}`fig-sensitivity`; per azimuth, W' > 0 on the sphere appears on both "
         f"sides at once ({adv1:.2f} of the advancing and {ret1:.2f} of the "
         f"retreating azimuths at mu = {reg_p.mu_values[1]:g}); threshold below 1e-7 (Glauert inflow), "
         f"{threshold.threshold_of('drees', '12 axes'):.2g} (Drees inflow)",
         "the hover equilibrium is not a forward-flight motion: the unbalanced loads make W' > 0 near x = 0 "
         "at once; our quasi-steady model has no stall-flutter mechanism (no dynamic stall; the pitch-damping "
         "couple has a constant coefficient)"),
        ("paper's Fig. 8: at mu = 0.25 also a region on the advancing side",
         "not reproduced", "not reproduced (the whole disc already fails)",
         f"per azimuth: W' > 0 on the sphere on {adv_last:.2f} of the advancing and "
         f"{ret_last:.2f} of the retreating side at mu = {reg_p.mu_values[-1]:g}",
         "as above"),
    ]
    return ClaimsTable(header=CLAIMS_HEADER, rows=tuple(rows))
