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
parameters, Fig. 8's grids, the test-disturbance sets and the region maps' categories, legend
and reverse-flow mark are in :mod:`rotorlyap.chapters.cases`.

Conventions (``.notes/BLADE_SPEC.md``): azimuth ``psi = 0`` with the blade pointing aft
(over the tail), rotation counter-clockwise seen from above, so ``psi = 90 deg`` is the
advancing side and ``psi = 270 deg`` the retreating side.
"""

from __future__ import annotations

import re

from dataclasses import dataclass

import numpy as np

from ..analysis.functions import energy_function
from ..analysis.stability import blade_stability
from ..conventions import DEFAULT_A, DEFAULT_SCALES, PAPER_TEST_DISTURBANCES
from ..methods.sampling import sphere_extremum, unit_sphere_points
from ..model.blade import Blade
from ..model.modes import hover_modes, least_damped
from ..model.trim import hover_trim
from ..reporting import decade_above, format_small
from .cases import (_HINGES, AXES_AND_DIAGONALS, CASES, FLAP_LAG_TEST_DISTURBANCES, MU_GRID, MU_GRID_STRICT,
                    READING_LABELS, STATE_LABELS, _Count, _line, _plain, _reverse_flow, balanced_scales,
                    case_params, category_legend_handles, disturbance_names)
from .export import markdown_table  # the claims table; also re-exported for the chapters
from .style import CATEGORY_COLORS, CATEGORY_HATCHES, CG_COLORS, CG_MARKERS, draw_categories, figure, finish, subplots

__all__ = [
    "THRESHOLD_TEST_SETS", "practical_threshold_mu",
    "UnbalancedLoadsData", "unbalanced_loads_data",
    "WSpheresData", "w_spheres_data", "plot_w_spheres", "figure_w_spheres",
    "RateAzimuthData", "rate_azimuth_data", "plot_rate_azimuth", "figure_rate_azimuth",
    "RegionsData", "regions_data", "plot_regions_polar", "plot_regions_plane",
    "RegionMaps", "region_maps", "figure_regions_polar", "figure_regions_plane",
    "HoverFlutterCheck", "hover_flutter_check", "ThresholdData", "practical_threshold_data",
    "SensitivityData", "sensitivity_data", "plot_sensitivity", "figure_sensitivity",
    "ConvergenceData", "convergence_data", "plot_convergence", "figure_convergence",
    "CLAIMS_HEADER", "ClaimsTable", "claims_table",
    "markdown_table",
]


def _colormaps():
    import matplotlib

    return matplotlib.colormaps

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
        Index into :data:`~rotorlyap.chapters.cases.CATEGORY_NAMES`, (k, m, n).
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
    energy-balanced scales (:func:`~rotorlyap.chapters.cases.balanced_scales`); the axes and
    pairwise diagonals; the flap and lag axes only (no pitch rate).
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
