"""Figures of the chapter "Validation and beyond": a data function and a drawing function each.

Data functions return frozen dataclasses (no plotting) and take their grids as arguments;
drawing functions take that data and matplotlib ``Axes``. The chain is

1. :func:`steady_motions`: the true periodic motion of every case at every advance ratio
   (:func:`rotorlyap.model.steady.periodic_motion`), computed once and reused;
2. :func:`floquet_data`: Floquet modes about it and about the hover equilibrium
   (:mod:`rotorlyap.analysis.floquet`);
3. :func:`scan_data`: the engine's verdict on a (psi, mu) grid for several Liapunov functions
   and steady motions (:data:`CANDIDATES`): the certificate counterpart of the paper's Fig. 8;
4. :func:`validation_data`: simulated motions against those verdicts (:mod:`rotorlyap.methods.validation`);
5. :func:`motion_data`: what the motion does where a reading marks instability.

Beside them, the chapter's smaller computations: :func:`inflow_data` (the distance of the
hover equilibrium from the periodic motion with two inflow models), :func:`fold_data` (the end
of the backward-C.G. branch), :func:`quadratic_data` (the quadratic Liapunov functions),
:func:`origin_data` (``W'`` near the origin), :func:`search_check` (the certificates with a
finer search), :func:`validation_set` (every simulated motion of the chapter),
:func:`flutter_cycle` and :func:`far_motion` (the limit cycle and the distant periodic motion
of the long simulations).

Every data object has ``summary()``, the text the chapter prints (rounded to the digits the
computation determines, README "What a committed output may print"), and ``facts()``, the
numbers the chapter's text quotes, ``{glue name: rounded value}``
(:func:`rotorlyap.chapters.export.glue_facts`). Each figure has a ``figure_*`` function that
creates, draws and returns it (closed in pyplot, so that only its glued copy is shown), and the
figure's data object an ``export()`` for :func:`rotorlyap.chapters.export.figure_csv`.

Conventions as :mod:`rotorlyap.chapters.paper`: ``psi = 0`` over the tail, ``psi = 90 deg``
the advancing side; growth rates and frequencies per rev.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING

import numpy as np

from ..analysis.floquet import blade_floquet, floquet_sweep
from ..analysis.functions import energy_function, optimised_quadratic_function, quadratic_function
from ..analysis.stability import blade_stability, psi_free_system
from ..conventions import DEFAULT_A, DEFAULT_SCALES, PAPER_TEST_DISTURBANCES
from ..errors import NotAsymptoticallyStableError, PeriodicMotionError
from ..methods.lyapunov import technical_stability
from ..methods.sampling import sphere_extremum, unit_sphere_points
from ..methods.simulation import scaled_norm, simulate
from ..methods.validation import last_revolution, long_run, validate
from ..model.blade import Blade
from ..model.inflow import GLAUERT_KX
from ..model.modes import derived_quantities
from ..model.parameters import BladeParameters
from ..model.steady import as_steady_motion, disturbed_rhs, periodic_motion, tabulate_motion
from ..reporting import Rounded, count, decade_above, format_small, format_small_array, percent
from .export import markdown_table
from .style import (CATEGORY_COLORS, CATEGORY_HATCHES, CG_COLORS, CG_MARKERS, HATCH_COLOR, HATCH_LINEWIDTH,
                    HINGE_COLORS, SCAN_EXTRA_COLORS, SCAN_EXTRA_HATCHES, draw_categories, figure, finish,
                    subplots)

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = [
    "CASES", "MU_FLOQUET", "MU_SCAN", "CANDIDATES", "Candidate", "SCAN_CATEGORY_NAMES",
    "CONFUSION_HEADER", "grid_summary", "max_distance",
    "SteadyMotions", "steady_motions", "plot_steady_motions", "figure_steady_motions",
    "InflowData", "inflow_data", "FoldData", "fold_data",
    "FloquetData", "floquet_data", "plot_floquet", "figure_floquet", "floquet_legend_handles",
    "QuadraticData", "quadratic_data",
    "OriginData", "origin_data", "plot_origin", "figure_origin",
    "ScanData", "scan_data", "plot_scan", "figure_scan", "scan_legend_handles",
    "SCAN_OPTIONS", "CellSystem", "cell_system", "RuleChanges", "rule_changes",
    "SearchCheck", "search_check",
    "validation_data", "confusion_rows", "plot_validation",
    "ValidationData", "validation_set", "figure_validation",
    "MotionData", "motion_data", "plot_motions", "figure_motions", "points_per_revolution",
    "FlutterCycle", "flutter_cycle", "FarMotion", "far_motion",
]

#: The paper's three cases.
CASES = ("forward", "neutral", "backward")

#: Advance ratios of the Floquet sweep (fine enough to follow the modes by continuity).
MU_FLOQUET = tuple(float(m) for m in np.round(np.arange(0.0, 0.2501, 0.025), 3))

#: Advance ratios of the scans (each costs a sphere search per azimuth and function).
MU_SCAN = (0.0, 0.05, 0.1, 0.15, 0.2, 0.25)

#: The engine's resolution in the chapter's scan (:func:`scan_data`): 24 azimuths and 256
#: quasi-random directions per sphere (with the structured ones). The falsifier tests attack
#: the certificates of exactly these runs.
SCAN_OPTIONS = {"n_psi": 24, "n_sphere": 256}

#: Short names of the cases in the chapter's glue names (``ch7_ncert_q_neu``, ...).
_CASE_TAGS = {"forward": "fw", "neutral": "neu", "backward": "bwd"}


#: What :func:`rotorlyap.methods.validation.classify_motion`'s verdicts say about a motion of
#: the (periodic) blade, in the chapter's words: a forced blade's "limit cycle" is the periodic
#: motion it settles on.
_VERDICT_WORDS = {"limit cycle outside A": "settles on a periodic motion outside A",
                  "limit cycle within A": "settles on a periodic motion within A"}


def _verdicts_in_words(verdicts: tuple) -> str:
    """``"both starts: settles on ..."`` when the starts agree, else each start's verdict."""
    words = [_VERDICT_WORDS.get(v, v) for v in verdicts]
    if len(set(words)) == 1:
        return f"{'both' if len(words) == 2 else 'every'} start{'s' if len(words) > 1 else ''}: {words[0]}"
    return "; ".join(f"start {i + 1}: {w}" for i, w in enumerate(words))


def _join(*parts) -> str:
    """The line ``print(*parts)`` writes, without its newline."""
    return " ".join(str(p) for p in parts)


def _mu_list(values) -> str:
    """Advance ratios as the chapter's text quotes them: ``"0.2, 0.25"``."""
    return ", ".join(f"{float(m):g}" for m in values)


def grid_summary() -> str:
    """The norm's scales (deg and deg per rad), the bound ``A`` and the advance-ratio grids.

    Returns
    -------
    str
        Three lines, as chapter 7 prints them.
    """
    return "\n".join([
        _join("scales a_i (deg, deg/rad):", np.round(np.degrees(DEFAULT_SCALES), 2), "; A =", DEFAULT_A),
        _join("advance ratios, Floquet:", MU_FLOQUET),
        _join("advance ratios, scans:  ", MU_SCAN),
    ])


def max_distance(motion, state: np.ndarray, n_psi: int = 256) -> float:
    """Largest distance of a periodic motion from a constant state in the scaled norm.

    Parameters
    ----------
    motion : object with ``xi(psi)``
        A periodic motion (:class:`~rotorlyap.model.steady.PeriodicMotion`,
        :class:`~rotorlyap.model.steady.TabulatedMotion`, ...), states in rad and rad/rad.
    state : array_like
        The constant state, shape (6,), rad and rad/rad.
    n_psi : int
        Uniform azimuths over one revolution at which the distance is evaluated.

    Returns
    -------
    float
        ``max_psi ||xi(psi) - state||`` in the scaled norm of
        :data:`rotorlyap.conventions.DEFAULT_SCALES` (norm units).
    """
    grid = 2 * np.pi * np.arange(n_psi) / n_psi
    return float(scaled_norm(motion.xi(grid) - state, DEFAULT_SCALES).max())


def _edges(values, lo=None) -> np.ndarray:
    v = np.asarray(values, dtype=float)
    mid = 0.5 * (v[1:] + v[:-1])
    first = v[0] - (mid[0] - v[0]) if lo is None else lo
    return np.concatenate([[first], mid, [v[-1] + (v[-1] - mid[-1])]])


# --------------------------------------------------------------------------------------
# 1. The true steady motion
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class SteadyMotions:
    """The periodic motion of each case at each advance ratio.

    Attributes
    ----------
    cases : tuple of str
    mu_values : numpy.ndarray
        (m,).
    found : numpy.ndarray
        Boolean (k, m): :func:`rotorlyap.model.steady.periodic_motion` converged.
    distance : numpy.ndarray
        ``max_psi ||xi(psi) - xi_hover||`` in the scaled norm of
        :data:`rotorlyap.analysis.stability.DEFAULT_SCALES`, (k, m): how far the paper's steady motion
        is from the true one. NaN where not found.
    harmonics_deg : numpy.ndarray
        Mean, cos and sin first harmonics of flap, lag, pitch, deg, (k, m, 3, 3).
    residual : numpy.ndarray
        ``max_psi ||h(psi, xi) - xi'||`` (scaled norm) of the tabulated motion on 4001
        azimuths, (k, m): ``f(psi, 0)`` of the disturbed equations.
    psi_plot : numpy.ndarray
        Azimuths of :attr:`angles_deg`, rad, (n,).
    angles_deg : numpy.ndarray
        Hinge angles of the periodic motion, deg, (k, m, n, 3); NaN where not found.
    hover_deg : numpy.ndarray
        Hover equilibrium angles, deg, (k, 3).
    messages : tuple
        Per case, per advance ratio: empty, or why not found.
    motions : dict
        ``{(case, mu): TabulatedMotion}`` for the ones found (not compared, not exported).
    """

    cases: tuple
    mu_values: np.ndarray
    found: np.ndarray
    distance: np.ndarray
    harmonics_deg: np.ndarray
    residual: np.ndarray
    psi_plot: np.ndarray
    angles_deg: np.ndarray
    hover_deg: np.ndarray
    messages: tuple
    motions: dict = field(default_factory=dict, compare=False, repr=False)

    def steady(self, case: str, mu: float):
        """The tabulated periodic motion as a :class:`~rotorlyap.model.steady.SteadyMotion`, or
        None if not found."""
        m = self.motions.get((case, round(float(mu), 6)))
        return None if m is None else m.steady

    def export(self) -> dict:
        """The arrays for :func:`rotorlyap.chapters.export.figure_csv`."""
        return {"mu": self.mu_values, "found": self.found, "distance": self.distance, "residual": self.residual,
                "harmonics_deg": self.harmonics_deg, "psi_deg": np.degrees(self.psi_plot),
                "angles_deg": self.angles_deg, "hover_deg": self.hover_deg}

    def missing(self) -> dict:
        """``{case: [advance ratios without a periodic motion]}``."""
        return {case: [float(m) for m in self.mu_values[~self.found[i]]] for i, case in enumerate(self.cases)}

    def summary(self) -> str:
        """Per case: found, distance of the hover equilibrium (norm units) and residual
        (bounded by :func:`rotorlyap.reporting.format_small`) at each advance ratio; the first
        harmonics of the forward C.G. at the last advance ratio (deg); the advance ratios
        without a periodic motion."""
        lines = [_join("mu:", self.mu_values)]
        for i, case in enumerate(self.cases):
            lines += [_join(f"{case:9s} found:   ", self.found[i].astype(int)),
                      _join(f"{'':9s} distance:", np.round(self.distance[i], 2)),
                      _join(f"{'':9s} residual:", format_small_array(self.residual[i]))]
        lines.append(f"forward C.G., mu = {self.mu_values[-1]:g}, (mean, cos, sin) harmonics (deg):")
        for name, row in zip(("flap", "lag", "pitch"), self.harmonics_deg[self.cases.index("forward"), -1]):
            lines.append(_join(f"  {name:5s}", np.round(row, 2)))
        lines.append(_join("advance ratios without a periodic motion:", self.missing()))
        return "\n".join(lines)

    def facts(self) -> dict:
        """The numbers the chapter quotes: distances of the hover equilibrium (forward C.G.,
        first non-zero and last advance ratio, norm units), largest residuals (one digit),
        harmonics at the last advance ratio (deg), how many motions were found."""
        f, n = self.cases.index("forward"), self.cases.index("neutral")
        fw, h = self.distance[f], self.harmonics_deg[f, -1]
        return {
            "ch7_dist_025": round(float(fw[1]), 1),
            "ch7_dist_25": round(float(fw[-1]), 1),
            "ch7_res_fw": float("%.1g" % np.nanmax(self.residual[f])),
            "ch7_res_all": float("%.1g" % np.nanmax(self.residual)),
            "ch7_b1s_25": round(float(h[0, 2]), 1),
            "ch7_b1c_25": round(float(h[0, 1]), 1),
            "ch7_beta0_25": round(float(h[0, 0]), 1),
            "ch7_th1s_25": round(float(h[2, 2]), 1),
            "ch7_n_mu": int(self.mu_values.size),
            "ch7_found_fn": int(self.found[[f, n]].sum()),
            "ch7_found_fn_text": (f"all {int(self.found[[f, n]].sum())}: 2 C.G. positions × {self.mu_values.size} "
                                  "advance ratios" if self.found[[f, n]].all() else
                                  f"{int(self.found[[f, n]].sum())} of 2 C.G. positions × {self.mu_values.size} "
                                  "advance ratios"),
            "ch7_kx": GLAUERT_KX,
            "ch7_miss_bwd": _mu_list(self.missing()["backward"]),
            **settings_facts(),
        }


def settings_facts() -> dict:
    """The method settings the chapter's text quotes, read from the functions' defaults: the
    collocation points of the periodic motion (the quick test of existence, the final motion),
    the azimuths of its table, the Magnus steps of the Floquet analysis and of the periodic
    Lyapunov equation, and the directions and objective evaluations of the weight optimisation."""
    import inspect

    from ..analysis.functions import DEFAULT_N_STEPS

    def default(fun, name):
        return inspect.signature(fun).parameters[name].default

    return {"ch7_colloc_test": default(periodic_motion, "n_points"),
            "ch7_colloc_n": default(steady_motions, "n_points"),
            "ch7_table_n": default(steady_motions, "n_table"),
            "ch7_floquet_steps": default(floquet_data, "n_steps"),
            "ch7_lyap_steps": DEFAULT_N_STEPS,
            "ch7_opt_dirs": default(optimised_quadratic_function, "n_directions"),
            "ch7_opt_evals": default(optimised_quadratic_function, "max_evaluations")}


def _steady_motion(task: tuple):
    """One motion of :func:`steady_motions` (module level, for worker processes): ``(case, mu,
    n_points, n_table)`` -> ``(tabulated motion, harmonics in deg)``, or the message of a
    :class:`~rotorlyap.errors.PeriodicMotionError`."""
    case, mu, n_points, n_table = task
    p = BladeParameters.table_i(case)
    try:
        pm = periodic_motion(p, mu)
        if mu > 0 and n_points != 64:
            pm = periodic_motion(p, mu, n_points=n_points)
    except PeriodicMotionError as exc:
        return str(exc)
    return tabulate_motion(pm, n_table), pm.harmonics_deg


def steady_motions(cases=CASES, mu_values=MU_FLOQUET, *, n_points: int = 256, n_table: int = 4096,
                   n_plot: int = 73, workers: int | None = None) -> SteadyMotions:
    """Periodic motions of every case at every advance ratio (failures recorded, not raised).

    Each motion is first sought with the default 64 collocation points (a quick test of
    existence), then recomputed with ``n_points``: the blade's loads have kinks (reverse flow
    at the root, stall), so the Fourier series converges slowly and between the collocation
    points the residual ``|h(psi, xi) - xi'|`` of 64 points is up to about 1e-2 in the
    scaled norm at ``mu = 0.25``, ten times less with 256. The motion is then tabulated
    (:func:`rotorlyap.model.steady.tabulate_motion`, ``n_table`` azimuths) for fast
    evaluation. :attr:`SteadyMotions.residual` is the largest scaled residual on 4001
    azimuths: the size of ``f(psi, 0)``, the part of ``W'`` linear in ``x``.

    The motions are independent: with ``workers`` other than 1 (default: every core) they are
    computed in that many fresh processes, each with one BLAS thread
    (:func:`rotorlyap.analysis.sweep.process_map`), so that their last bits, and what the
    searches about them find, do not depend on this process's BLAS threads (a motion's dense
    collocation solve rounds differently with two threads, and step 3's bound at mu = 0.25
    moved in the third digit).
    """
    from ..analysis.sweep import process_map, worker_count

    mu_values = np.asarray(mu_values, dtype=float)
    k, m = len(cases), mu_values.size
    psi = np.linspace(0.0, 2 * np.pi, n_plot)
    fine = np.linspace(0.0, 2 * np.pi, 4001)
    found = np.zeros((k, m), dtype=bool)
    dist = np.full((k, m), np.nan)
    harm = np.full((k, m, 3, 3), np.nan)
    res = np.full((k, m), np.nan)
    ang = np.full((k, m, n_plot, 3), np.nan)
    hov = np.zeros((k, 3))
    msgs, motions = [], {}
    tasks = [(case, float(mu), n_points, n_table) for case in cases for mu in mu_values]
    workers = worker_count(workers, len(tasks))
    done = process_map(_steady_motion, tasks, workers) if workers > 1 else [_steady_motion(t) for t in tasks]
    for i, case in enumerate(cases):
        p = BladeParameters.table_i(case)
        xh = Blade(p, 0.0).equilibrium()
        hov[i] = np.degrees(xh[:3])
        row = []
        for j, mu in enumerate(mu_values):
            out = done[i * m + j]
            if isinstance(out, str):
                row.append(out)
                continue
            row.append("")
            tab, harm[i, j] = out
            motions[(case, round(float(mu), 6))] = tab
            found[i, j] = True
            dist[i, j] = max_distance(tab, xh)
            blade = Blade(p, float(mu))
            res[i, j] = float(scaled_norm(blade.rhs(fine, tab.xi(fine)) - tab.dxi(fine), DEFAULT_SCALES).max())
            ang[i, j] = np.degrees(tab.xi(psi)[:, :3])
        msgs.append(tuple(row))
    return SteadyMotions(cases=tuple(cases), mu_values=mu_values, found=found, distance=dist,
                         harmonics_deg=harm, residual=res, psi_plot=psi, angles_deg=ang, hover_deg=hov,
                         messages=tuple(msgs), motions=motions)


def plot_steady_motions(data: SteadyMotions, axes, case_index: int = 0) -> None:
    """Flap, lag and pitch angles of the periodic motion of one case against azimuth (three
    panels, one line per advance ratio, dashed: the hover equilibrium), and in a fourth
    panel the distance of the hover equilibrium from it against ``mu`` for every case (colour
    and marker per case; crosses: no periodic motion found). ``axes``: four Axes, in any
    shape. The legend of the advance ratios is on the first panel (a figure may move it)."""
    import matplotlib.pyplot as plt

    axes = np.asarray(axes).ravel()
    cmap = plt.get_cmap("viridis")
    mu = data.mu_values
    names = (r"flap $\beta$", r"lag $\zeta$", r"pitch $\theta$")
    for h in range(3):
        ax = axes[h]
        for j in range(mu.size):
            if not data.found[case_index, j]:
                continue
            ax.plot(np.degrees(data.psi_plot), data.angles_deg[case_index, j, :, h],
                    color=cmap(j / max(mu.size - 1, 1)), lw=1.2, label=f"$\\mu$ = {mu[j]:g}")
        ax.axhline(data.hover_deg[case_index, h], color="k", ls="--", lw=1.2, label="hover equilibrium")
        ax.set_xlim(0, 360)
        ax.set_xticks(np.arange(0, 361, 90))
        ax.set_xlabel(r"azimuth $\psi$ (deg)")
        ax.set_ylabel(names[h] + " (deg)")
        ax.set_title(f"({'abc'[h]}) {names[h].split()[0]}, {data.cases[case_index]} C.G.", fontsize=10)
    axes[0].legend(fontsize=8, ncol=2)
    ax = axes[3]
    for i, case in enumerate(data.cases):
        ok = data.found[i]
        col, mk = CG_COLORS.get(case, "0.3"), CG_MARKERS.get(case, "o")
        ax.plot(mu, np.where(ok, data.distance[i], np.nan), "-", marker=mk, ms=5, color=col,
                label=f"{case} C.G.")  # broken where none is found
        if (~ok).any():
            ax.plot(mu[~ok], np.zeros((~ok).sum()), "x", color=col, ms=8, mew=1.5, clip_on=False,
                    label="none found")
    ax.axhline(DEFAULT_A, color="k", lw=1.0, ls="-.", label=f"$A$ = {DEFAULT_A:g}")
    ax.set_ylim(0.0, 1.45 * max(np.nanmax(data.distance), DEFAULT_A))  # room for the legend
    ax.set_xlabel(r"advance ratio $\mu$")
    ax.set_ylabel(r"$\max_\psi \|\xi(\psi) - \xi_{\mathrm{hover}}\|$ (norm units)")
    ax.set_title("(d) distance of the hover equilibrium", fontsize=10)
    ax.legend(fontsize=8, loc="upper left", ncol=2, columnspacing=1.0)


def figure_steady_motions(data: SteadyMotions, case_index: int = 0) -> Figure:
    """The figure of :func:`plot_steady_motions` (four panels in two rows, 8.6 x 7.2 in, the
    legend of the advance ratios below them), laid out and closed in pyplot.

    Returns
    -------
    matplotlib.figure.Figure
    """
    fig, axes = subplots(2, 2, figsize=(8.6, 7.2))
    plot_steady_motions(data, axes, case_index)
    handles, labels = axes[0, 0].get_legend_handles_labels()
    axes[0, 0].get_legend().remove()
    leg = fig.legend(handles, labels, loc="lower center", ncol=6, fontsize=8, frameon=False)
    return finish(fig, rect=(0, _legend_height(fig, leg), 1, 1))


def _legend_height(fig, legend, pad_in: float = 0.05) -> float:
    """Height of a figure legend placed at the bottom, as a fraction of the figure's height
    (for ``tight_layout(rect=(0, h, 1, 1))``)."""
    fig.draw_without_rendering()
    return (legend.get_window_extent().height / fig.dpi + pad_in) / fig.get_size_inches()[1]


@dataclass(frozen=True)
class InflowData:
    """Distance of the hover equilibrium from the periodic motion at small advance ratios,
    for several inflow models.

    Attributes
    ----------
    case : str
        Table I case.
    models : tuple of str
        Inflow models (``BladeParameters.inflow_model``), (k,).
    mu_values : numpy.ndarray
        Advance ratios, (m,).
    distance : numpy.ndarray
        :func:`max_distance` of the hover equilibrium from the periodic motion (64 collocation
        points), norm units, (k, m).
    """

    case: str
    models: tuple
    mu_values: np.ndarray
    distance: np.ndarray

    def summary(self) -> str:
        """One line per model: the distances, two decimals."""
        mus = _mu_list(self.mu_values)
        return "\n".join(_join(f"inflow {model:8s}: distance of the hover equilibrium at mu = {mus}:",
                               np.round(self.distance[i], 2)) for i, model in enumerate(self.models))

    def facts(self) -> dict:
        """``ch7_dist_<model>_<digits of the first mu>``: the distance at the first advance
        ratio, two decimals."""
        tag = f"{float(self.mu_values[0]):g}".split(".")[-1]
        return {f"ch7_dist_{model}_{tag}": round(float(self.distance[i, 0]), 2)
                for i, model in enumerate(self.models)}


def inflow_data(case: str = "forward", models: tuple = ("glauert", "drees"),
                mu_values: tuple = (0.0125, 0.025)) -> InflowData:
    """:func:`max_distance` of the hover equilibrium from the periodic motion
    (:func:`rotorlyap.model.steady.periodic_motion`, default collocation) for each inflow
    model at each advance ratio of ``mu_values``."""
    dist = np.zeros((len(models), len(mu_values)))
    for i, model in enumerate(models):
        p = BladeParameters.table_i(case, inflow_model=model)
        xh = Blade(p, 0.0).equilibrium()
        dist[i] = [max_distance(periodic_motion(p, float(mu)), xh) for mu in mu_values]
    return InflowData(case=case, models=tuple(models), mu_values=np.asarray(mu_values, dtype=float), distance=dist)


@dataclass(frozen=True)
class FoldData:
    """Where the branch of periodic motions through the hover equilibrium ends.

    Attributes
    ----------
    case : str
        Table I case.
    mu : float
        Advance ratio at which the periodic motion is still found.
    mean_lag_deg : float
        Its mean lag angle, deg.
    largest_real_multiplier : float
        Its largest real Floquet multiplier (above 1: statically unstable).
    fail_mu : float
        A larger advance ratio at which none is found.
    fail_message : str
        Why (:attr:`rotorlyap.analysis.floquet.BladeFloquetPoint.message`).
    hover_lag_deg : float
        Lag angle of the hover equilibrium, deg.
    """

    case: str
    mu: float
    mean_lag_deg: float
    largest_real_multiplier: float
    fail_mu: float
    fail_message: str
    hover_lag_deg: float

    def summary(self) -> str:
        """Three lines: the motion found, why none is found beyond, the hover lag."""
        return "\n".join([
            f"{self.case} C.G., mu = {self.mu:g}: mean lag {self.mean_lag_deg:.2f} deg, largest real "
            f"multiplier {self.largest_real_multiplier:.4f}",
            _join(f"{self.case} C.G., mu = {self.fail_mu:g}:", _without_stalled_residual(self.fail_message)),
            "hover equilibrium: mean lag %.2f deg" % self.hover_lag_deg,
        ])

    def facts(self) -> dict:
        """The largest real multiplier, three decimals."""
        return {"ch7_fold_0": round(float(self.largest_real_multiplier), 3)}


def _without_stalled_residual(message: str) -> str:
    """A failed solver's message without the residual it stalled at: that number is set by the
    rounding of the last iterations (1e-04 here, 2e-04 in another floating-point environment),
    not by the computation, so the book does not print it."""
    return re.sub(r"residual \S+ after", "residual above the tolerance after", message)


def fold_data(motions: SteadyMotions, case: str = "backward", mu: float = 0.005, fail_mu: float = 0.01) -> FoldData:
    """The periodic motion of ``case`` at a small advance ratio ``mu`` with its Floquet
    multipliers (:func:`rotorlyap.analysis.floquet.blade_floquet`), and the failure at
    ``fail_mu``; the hover lag is read from ``motions``."""
    p = BladeParameters.table_i(case)
    pm = periodic_motion(p, mu)
    m = blade_floquet(p, mu, steady=pm).multipliers
    fold = float(m[np.abs(m.imag) < 1e-9].real.max())
    return FoldData(case=case, mu=float(mu), mean_lag_deg=float(pm.harmonics_deg[1, 0]),
                    largest_real_multiplier=fold, fail_mu=float(fail_mu),
                    fail_message=blade_floquet(p, fail_mu).message,
                    hover_lag_deg=float(motions.hover_deg[motions.cases.index(case), 1]))


# --------------------------------------------------------------------------------------
# 2. Floquet
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class FloquetData:
    """Floquet sweeps of every case about the periodic motion and about the hover equilibrium."""

    cases: tuple
    mu_values: np.ndarray
    periodic: tuple
    hover: tuple

    def export(self) -> list:
        """Named columns for :func:`rotorlyap.chapters.export.figure_csv` (long layout)."""
        out = [("mu", self.mu_values)]
        for case, sp, sh in zip(self.cases, self.periodic, self.hover):
            for tag, sw in (("periodic", sp), ("hover", sh)):
                out += [(f"{case}_{tag}_names", list(sw.names)),
                        (f"{case}_{tag}_growth_rate", sw.growth_rate),
                        (f"{case}_{tag}_frequency", sw.frequency),
                        (f"{case}_{tag}_spectral_radius", sw.spectral_radius)]
        return out

    def sweep(self, case: str, steady: str = "periodic"):
        """The :class:`~rotorlyap.analysis.floquet.FloquetSweep` of ``case`` about the
        ``"periodic"`` motion or the ``"hover"`` equilibrium."""
        i = self.cases.index(case)
        return (self.periodic if steady == "periodic" else self.hover)[i]

    def unstable_backward(self) -> np.ndarray:
        """Indices of the advance ratios at which the backward C.G. is unstable about its
        periodic motion."""
        return np.flatnonzero(self.sweep("backward").max_growth_rate > 0)

    def summary(self) -> str:
        """Largest growth rates (1/rev, three decimals) of every case about both steady
        states; every track of the forward C.G. (growth rate and frequency, 1/rev); where the
        backward C.G. is unstable and its largest multiplier there."""
        lines = []
        for sp, sh in zip(self.periodic, self.hover):
            lines.append(_join(f"{sp.case} C.G., largest growth rate (1/rev), about the periodic motion:",
                               np.round(sp.max_growth_rate, 3)))
            lines.append(_join(f"{'':{len(sp.case)}s}                                 about the hover equilibrium:",
                               np.round(sh.max_growth_rate, 3)))
        fp = self.sweep("forward")
        lines.append(_join("forward C.G. tracks:", fp.names))
        for name in fp.names:
            t = fp.track(name)
            lines.append(_join(f"  {name:6s} growth rate", np.round(fp.growth_rate[:, t], 3), " frequency",
                               np.round(np.abs(fp.frequency[:, t]), 3)))
        sb, j_un = self.sweep("backward"), self.unstable_backward()
        lines.append(_join("backward C.G., unstable about the periodic motion at mu =", sb.mu[j_un]))
        for j in j_un:
            mj = sb.multipliers[j]
            lines.append(f"  mu = {sb.mu[j]:g}: largest multiplier {np.round(mj[np.argmax(np.abs(mj))], 3)}")
        return "\n".join(lines)

    def facts(self) -> dict:
        """Growth rates (1/rev, three decimals; four for the barely stable backward hover) and
        frequencies (1/rev, two or three decimals) the chapter quotes, all about the periodic
        motion unless named ``_hov``; the first advance ratio at which the backward C.G. is
        unstable and its multiplier there."""
        fp, sn, sb = self.sweep("forward"), self.sweep("neutral"), self.sweep("backward")
        pt, ft, lt = fp.track("pitch+"), fp.track("flap+"), fp.track("lag+")
        j_un = self.unstable_backward()
        j1 = int(j_un[0])
        m1 = sb.multipliers[j1][np.argmax(np.abs(sb.multipliers[j1]))]
        return {
            "ch7_pitch_sig0": round(float(fp.growth_rate[0, pt]), 3),
            "ch7_pitch_sig25": round(float(fp.growth_rate[-1, pt]), 3),
            "ch7_pitch_om0": round(float(fp.frequency[0, pt]), 2),
            "ch7_pitch_om25": round(float(fp.frequency[-1, pt]), 2),
            "ch7_flap_om0": round(float(fp.frequency[0, ft]), 2),
            "ch7_flap_om25": round(float(abs(fp.frequency[-1, ft])), 2),
            "ch7_flap_sig25": round(float(fp.growth_rate[-1, ft]), 3),
            "ch7_fw_maxsig": round(float(np.nanmax(fp.max_growth_rate)), 3),
            "ch7_fw_maxsig_hov": round(float(np.nanmax(self.sweep("forward", "hover").max_growth_rate)), 3),
            "ch7_lag_om0": round(float(abs(fp.frequency[0, lt])), 3),
            "ch7_lag_om25": round(float(abs(fp.frequency[-1, lt])), 2),
            "ch7_lag_sig0": round(float(fp.growth_rate[0, lt]), 3),
            "ch7_lag_sig25": round(float(fp.growth_rate[-1, lt]), 3),
            "ch7_neu_sig_min": round(float(np.nanmin(sn.max_growth_rate)), 3),
            "ch7_neu_sig_max": round(float(np.nanmax(sn.max_growth_rate)), 3),
            "ch7_flip_mu": float(sb.mu[j1]),
            "ch7_flip_m": round(float(m1.real), 3),
            "ch7_n_unstable_bwd": int(j_un.size),
            "ch7_n_unstable_bwd_text": ("this advance ratio of the grid only" if j_un.size == 1 else
                                        count(int(j_un.size), "advance ratio") + " of the grid"),
            "ch7_bwd_sig_max": round(float(np.nanmax(sb.max_growth_rate)), 3),
            "ch7_bwd_sig0": round(float(sb.max_growth_rate[0]), 4),
            "ch7_bwd_sig_last": round(float(sb.max_growth_rate[-1]), 3),
        }


def floquet_data(motions: SteadyMotions, *, n_steps: int = 1024) -> FloquetData:
    """:func:`rotorlyap.analysis.floquet.floquet_sweep` of every case of ``motions``, about the
    periodic motions found there and about the hover equilibrium."""
    per, hov = [], []
    for case in motions.cases:
        p = BladeParameters.table_i(case)
        i = motions.cases.index(case)
        given = {float(mu): (motions.steady(case, mu) if motions.found[i, j] else motions.messages[i][j])
                 for j, mu in enumerate(motions.mu_values)}
        per.append(floquet_sweep(p, motions.mu_values, steady="periodic", case=case, n_steps=n_steps,
                                 motions=given))
        hov.append(floquet_sweep(p, motions.mu_values, steady="hover", case=case, n_steps=n_steps))
    return FloquetData(cases=motions.cases, mu_values=motions.mu_values, periodic=tuple(per), hover=tuple(hov))


def _hinge(name: str) -> str:
    return name.rstrip("+-0123456789")


#: Marker of each hinge's tracks in :func:`plot_floquet` (the second cue to its colour).
_HINGE_MARKERS = {"flap": "o", "lag": "s", "pitch": "^"}


def plot_floquet(data: FloquetData, axes) -> None:
    """Growth rates (left column) and frequencies (right column, branch resolved by continuity)
    of the Floquet modes against ``mu``, one row per case. Solid with markers (colour and
    marker per hinge): about the periodic motion; dotted: about the hover equilibrium (the
    paper's steady motion); grey bands: no periodic motion found. ``axes``: (cases, 2).
    The figure legend is :func:`floquet_legend_handles`."""
    for c, case in enumerate(data.cases):
        ax_g, ax_f = axes[c, 0], axes[c, 1]
        for sw, style in ((data.periodic[c], dict(ls="-", ms=4, lw=1.3)),
                          (data.hover[c], dict(ls=":", lw=1.3))):
            for t, name in enumerate(sw.names):
                hinge = _hinge(name)
                color = HINGE_COLORS.get(hinge, "0.3")
                marker = _HINGE_MARKERS.get(hinge, "o") if sw.steady == "periodic" else None
                ax_g.plot(sw.mu, sw.growth_rate[:, t], color=color, marker=marker, label=name, **style)
                ax_f.plot(sw.mu, np.abs(sw.frequency[:, t]), color=color, marker=marker, **style)
            miss = ~sw.found
            if miss.any():
                for ax in (ax_g, ax_f):
                    for m in sw.mu[miss]:
                        ax.axvspan(m - 0.0125, m + 0.0125, color="0.85", lw=0)
        ax_g.axhline(0.0, color="k", lw=0.8)
        ax_g.set_title(f"({'abcdefgh'[2 * c]}) {case} C.G.: growth rates", fontsize=10)
        ax_f.set_title(f"({'abcdefgh'[2 * c + 1]}) {case} C.G.: frequencies", fontsize=10)
        ax_g.set_ylabel("growth rate (per rev)")
        ax_f.set_ylabel(r"frequency $|\omega|$ (per rev)")
        ax_f.set_yscale("symlog", linthresh=1.0, linscale=0.6)
        ax_f.set_ylim(-0.02, 6.0)
        ax_f.set_yticks([0, 0.25, 0.5, 1, 2, 3, 4, 5])
        ax_f.set_yticklabels(["0", "0.25", "0.5", "1", "2", "3", "4", "5"])
    for ax in axes[-1]:
        ax.set_xlabel(r"advance ratio $\mu$")


def floquet_legend_handles(data: FloquetData) -> list:
    """Legend of :func:`plot_floquet`: the hinges (colour and marker), the two steady states
    (line style), and the grey band where a periodic motion is missing."""
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    hinges = [h for h in HINGE_COLORS if any(_hinge(n) == h for sw in data.periodic for n in sw.names)]
    out = [Line2D([], [], color=HINGE_COLORS[h], marker=_HINGE_MARKERS[h], ms=5, lw=1.3, label=f"{h} modes")
           for h in hinges]
    out += [Line2D([], [], color="k", marker="o", ms=4, lw=1.3, label="about the periodic motion"),
            Line2D([], [], color="k", ls=":", lw=1.3, label="about the hover equilibrium")]
    if any((~sw.found).any() for sw in data.periodic + data.hover):
        out.append(Patch(color="0.85", label="no periodic motion found"))
    return out


def figure_floquet(data: FloquetData) -> Figure:
    """The figure of :func:`plot_floquet` (one row per case, growth rates left, frequencies
    right, 8.6 in wide, 3 in per row, the legend below), laid out and closed in pyplot.

    Returns
    -------
    matplotlib.figure.Figure
    """
    n = len(data.cases)
    fig, axes = subplots(n, 2, figsize=(8.6, 3.0 * n + 0.6), sharex=True, squeeze=False)
    plot_floquet(data, axes)
    handles = floquet_legend_handles(data)
    ncol = (len(handles) + 1) // 2
    handles = [h for pair in zip(handles[:ncol], handles[ncol:] + [None]) for h in pair if h is not None]
    leg = fig.legend(handles=handles, loc="lower center", ncol=ncol, fontsize=8.5, frameon=False)
    return finish(fig, rect=(0, _legend_height(fig, leg), 1, 1))


# --------------------------------------------------------------------------------------
# The quadratic Liapunov functions
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class QuadraticData:
    """The quadratic Liapunov functions of the chapter and their diagnostics.

    Attributes
    ----------
    case : str
        The Table I case of the main functions (``"forward"``).
    mu : float
        Advance ratio of the forward-flight function about the hover equilibrium.
    summaries : tuple of str
        ``summary()`` of the function with ``Q = I`` and of the optimised one, in hover.
    condition_number, lambda0_ratio, lambda0_ratio_optimised : float
        Of the hover functions (``lambda0_ratio``: the largest start region relative to the
        bound, ``1 / sqrt(condition_number)``).
    weights : numpy.ndarray
        Optimised weights ``w_i`` (``Q = diag(w_i / a_i**2)``), dimensionless, (6,).
    other_cases : tuple of str
        The other Table I cases, (k,).
    other_summaries : tuple of str
        ``summary()`` of their hover function with ``Q = I``, (k,).
    other_lambda0_ratio, other_condition_number, other_growth_rate : numpy.ndarray
        Their diagnostics, (k,); growth rate of the least damped mode, 1/rev.
    flutter_message : str
        Why no quadratic function exists for the backward C.G. without aerodynamic pitch
        damping (the ``ValueError`` text); empty if one exists.
    psi : numpy.ndarray
        Azimuths of the test of the term linear in ``x``, rad, (n,).
    eps : numpy.ndarray
        Sizes of the disturbance ``eps d`` (``d``: one unit of flap rate), (e,).
    dW_ratio : numpy.ndarray
        ``W'(psi, eps d) / eps`` of the function about the hover equilibrium at ``mu``,
        per rad, (e, n).
    linear_term : numpy.ndarray
        Its first-order prediction ``2 d^T P f(psi, 0)``, per rad, (n,).
    functions : dict
        The objects themselves (not compared): ``"identity"``, ``"optimised"`` (hover),
        ``"hover_equilibrium"`` (at ``mu`` about the hover equilibrium), the blades
        ``"blade_hover"``, ``"blade_mu"`` and the ``"equilibrium"`` state.
    """

    case: str
    mu: float
    summaries: tuple
    condition_number: float
    lambda0_ratio: float
    lambda0_ratio_optimised: float
    weights: np.ndarray
    other_cases: tuple
    other_summaries: tuple
    other_lambda0_ratio: np.ndarray
    other_condition_number: np.ndarray
    other_growth_rate: np.ndarray
    flutter_message: str
    psi: np.ndarray
    eps: np.ndarray
    dW_ratio: np.ndarray
    linear_term: np.ndarray
    functions: dict = field(default_factory=dict, compare=False, repr=False)

    def summary(self) -> str:
        """The functions' diagnostics, the optimised weights, the flutter case, and ``W'``
        along a small flap-rate disturbance about the hover equilibrium at ``mu`` against
        its first-order term (one decimal)."""
        lines = list(self.summaries)
        lines.append(_join("optimised weights w_i (Q = diag(w_i / a_i^2)), flap, lag, pitch, rates:",
                           np.round(self.weights, 3)))
        lines += [_join(f"{case} C.G.:", text) for case, text in zip(self.other_cases, self.other_summaries)]
        if self.flutter_message:
            lines.append(f"backward C.G., cm_pitch_rate = 0: ValueError: {self.flutter_message[:150]} ...")
        else:
            lines.append("backward C.G., cm_pitch_rate = 0: a quadratic function exists")
        lines.append(f"quadratic about the hover equilibrium at mu = {self.mu:g}, along +flap rate:")
        for eps, ratio in zip(self.eps, self.dW_ratio):
            lines.append(_join(f"  W'(psi, eps d) / eps, eps = 1e{int(round(np.log10(eps)))}:", np.round(ratio, 1)))
        lines.append(_join("  2 d^T P f(psi, 0):               ", np.round(self.linear_term, 1)))
        return "\n".join(lines)

    def facts(self) -> dict:
        """Start-region ratios (three decimals), condition numbers, the backward C.G.'s growth
        rate (1/rev, four decimals), two optimised weights and the largest linear term."""
        i_n, i_b = self.other_cases.index("neutral"), self.other_cases.index("backward")
        return {
            "ch7_q_ratio_neu": round(float(self.other_lambda0_ratio[i_n]), 3),
            "ch7_q_ratio_bwd": round(float(self.other_lambda0_ratio[i_b]), 3),
            "ch7_q_kappa_bwd": round(float(self.other_condition_number[i_b]), 0),
            "ch7_q_growth_bwd": round(float(self.other_growth_rate[i_b]), 4),
            "ch7_q_kappa": round(float(self.condition_number), 1),
            "ch7_q_ratio": round(float(self.lambda0_ratio), 3),
            "ch7_qo_ratio": round(float(self.lambda0_ratio_optimised), 3),
            "ch7_w_pitch": round(float(self.weights[2]), 3),
            "ch7_w_flaprate": round(float(self.weights[3]), 1),
            "ch7_lin_max": round(float(np.abs(self.linear_term).max()), 0),
        }

    def origin_functions(self, motions: SteadyMotions) -> dict:
        """The six functions of :func:`origin_data`, in the order its ``facts()`` reads them:
        the energy and the two quadratic functions in hover, then at ``mu`` the energy about
        the periodic motion of ``motions``, the quadratic function with ``Q = I`` about the
        hover equilibrium and about the periodic motion."""
        fn = self.functions
        b0, bmu, xh = fn["blade_hover"], fn["blade_mu"], fn["equilibrium"]
        tab = motions.motions[(self.case, round(float(self.mu), 6))]
        mu = f"{self.mu:g}"
        return {
            "energy, hover": (energy_function(b0, xh), True),
            "quadratic Q = I, hover": (fn["identity"], True),
            "quadratic, optimised Q, hover": (fn["optimised"], True),
            f"energy, mu = {mu}, periodic motion": (energy_function(bmu, tab), False),
            f"quadratic Q = I, mu = {mu}, hover equilibrium": (fn["hover_equilibrium"], False),
            f"quadratic Q = I, mu = {mu}, periodic motion": (quadratic_function(bmu, tab), False),
        }


def quadratic_data(case: str = "forward", mu: float = 0.15, *, other_cases: tuple = ("neutral", "backward"),
                   n_psi: int = 12, eps: tuple = (1e-2, 1e-4)) -> QuadraticData:
    """The quadratic functions of ``case`` in hover (``Q = I`` and optimised,
    :func:`rotorlyap.analysis.functions.optimised_quadratic_function`), of ``other_cases``
    in hover, the attempt for the backward C.G. without aerodynamic pitch damping, and the
    function at ``mu`` about the hover equilibrium (the paper's steady motion), whose ``W'``
    is tested along ``eps`` times one unit of flap rate at ``n_psi`` azimuths."""
    p = BladeParameters.table_i(case)
    b0 = Blade(p, 0.0)
    xh = b0.equilibrium()
    q_id = quadratic_function(b0)
    q_opt = optimised_quadratic_function(b0)
    others = [quadratic_function(Blade(BladeParameters.table_i(c), 0.0)) for c in other_cases]
    try:
        quadratic_function(Blade(BladeParameters.table_i("backward", cm_pitch_rate=0.0), 0.0))
        flutter = ""
    except ValueError as exc:
        flutter = str(exc)
    bmu = Blade(p, mu)
    q_hov = quadratic_function(bmu, xh)
    psi = np.radians(np.arange(0, 360, 360 // n_psi))
    d = np.array([0, 0, 0, 1.0, 0, 0]) * DEFAULT_SCALES  # a flap-rate disturbance
    dd = np.broadcast_to(d, (psi.size, 6))
    lin = 2 * np.einsum("mi,mij,mj->m", dd, q_hov.P(psi), q_hov.f(psi, np.zeros((psi.size, 6))))
    ratios = np.array([q_hov.dW(psi, e * dd) / e for e in eps])
    return QuadraticData(
        case=case, mu=float(mu), summaries=(q_id.summary(), q_opt.summary()),
        condition_number=q_id.condition_number, lambda0_ratio=q_id.lambda0_ratio,
        lambda0_ratio_optimised=q_opt.lambda0_ratio, weights=np.diag(q_opt.Q) * DEFAULT_SCALES**2,
        other_cases=tuple(other_cases), other_summaries=tuple(q.summary() for q in others),
        other_lambda0_ratio=np.array([q.lambda0_ratio for q in others]),
        other_condition_number=np.array([q.condition_number for q in others]),
        other_growth_rate=np.array([q.growth_rate for q in others]),
        flutter_message=flutter, psi=psi, eps=np.asarray(eps, dtype=float), dW_ratio=ratios, linear_term=lin,
        functions={"identity": q_id, "optimised": q_opt, "hover_equilibrium": q_hov, "blade_hover": b0,
                   "blade_mu": bmu, "equilibrium": xh})


# --------------------------------------------------------------------------------------
# 3. Scans: the paper's Fig. 8 with numerical certificates
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Candidate:
    """One Liapunov function, reading and steady motion of the scans."""

    key: str
    label: str
    function: str  # "energy", "quadratic", "quadratic-opt"
    reading: str  # "strict" or "practical"
    steady: str  # "hover" (the paper's) or "periodic"


#: The functions compared, in the order of the rows of :func:`plot_scan`.
CANDIDATES = (
    Candidate("paper", "energy, practical, hover equilibrium (the paper's choice)", "energy", "practical", "hover"),
    Candidate("energy-practical", "energy, practical, periodic motion", "energy", "practical", "periodic"),
    Candidate("energy", "energy, strict, periodic motion", "energy", "strict", "periodic"),
    Candidate("quadratic-hover", "quadratic Q = I, strict, hover equilibrium", "quadratic", "strict", "hover"),
    Candidate("quadratic", "quadratic Q = I, strict, periodic motion", "quadratic", "strict", "periodic"),
    Candidate("quadratic-opt", "quadratic, optimised Q, strict, periodic motion", "quadratic-opt", "strict", "periodic"),
)

#: Outcome of one (azimuth, advance ratio) cell; the first four as in the Fig. 8 chapter.
SCAN_CATEGORY_NAMES = (
    "passes (practical: indicator) / certified (strict: (h) over the whole period)",
    "paper's step 6 fails at this azimuth (practical)",
    "nothing certified (A = 0); W' <= 0 here on ||x|| = A",
    "nothing certified (A = 0); W' > 0 here on ||x|| = A",
    "no quadratic function: linearisation unstable",
    "no periodic motion found",
)
_SCAN_COLORS = CATEGORY_COLORS + SCAN_EXTRA_COLORS


def _category(res) -> np.ndarray:
    if res.A > 0:
        return np.where(res.stable, 0, 1)
    return np.where(res.max_dW > res.tol, 3, 2)


@dataclass(frozen=True)
class ScanData:
    """The engine's verdict for every candidate, case, advance ratio and azimuth.

    Attributes
    ----------
    cases, mu_values, psi
        The grid: (k,), (m,), (n,).
    keys, labels, readings : tuple of str
        The candidates (:data:`CANDIDATES`), (c,).
    category : numpy.ndarray
        Index into :data:`SCAN_CATEGORY_NAMES`, (c, k, m, n).
    stable : numpy.ndarray
        Boolean (c, k, m, n).
    lambda0 : numpy.ndarray
        (c, k, m, n); 0 where no result.
    A_used : numpy.ndarray
        The certified bound ``A`` (0 where nothing is certified), (c, k, m); NaN where no result.
    A_step3 : numpy.ndarray
        Step 3's bound ``A1`` (``W' <= 0`` on the sphere itself), (c, k, m); NaN where no
        result. The sound rule's ``A`` is at most this: it shrinks ``A`` until (h) holds on the
        whole band.
    weights : numpy.ndarray
        Optimised diagonal weights ``w_i`` (``Q = diag(w / a**2)``), per case, (k, 6); NaN
        where none exists.
    messages : tuple
        Per candidate and case, per advance ratio: the engine's message or why no result.
    results : dict
        ``{(key, case, mu): TechnicalStabilityResult}`` (not compared, not exported).
    """

    cases: tuple
    mu_values: np.ndarray
    psi: np.ndarray
    keys: tuple
    labels: tuple
    readings: tuple
    category: np.ndarray
    stable: np.ndarray
    lambda0: np.ndarray
    A_used: np.ndarray
    A_step3: np.ndarray
    weights: np.ndarray
    messages: tuple
    results: dict = field(default_factory=dict, compare=False, repr=False)

    def result(self, key: str, case: str, mu: float):
        """The engine's result, or None."""
        return self.results.get((key, case, round(float(mu), 6)))

    def export(self) -> list:
        """Long columns: one row per (candidate, case, mu, psi)."""
        c, k, m, n = self.category.shape
        idx = np.indices((c, k, m, n)).reshape(4, -1)
        return [("candidate", [self.keys[i] for i in idx[0]]), ("case", [self.cases[i] for i in idx[1]]),
                ("mu", self.mu_values[idx[2]]), ("psi_deg", np.degrees(self.psi)[idx[3]]),
                ("category", self.category.ravel()), ("lambda0", self.lambda0.ravel())]

    def min_certified_lambda0(self, key: str, case: str) -> tuple:
        """Smallest ``lambda0`` over the stable azimuths at each advance ratio (norm units),
        NaN where no azimuth is stable."""
        c, i = self.keys.index(key), self.cases.index(case)
        return tuple(float(self.lambda0[c, i, j][self.stable[c, i, j]].min()) if self.stable[c, i, j].any()
                     else float("nan") for j in range(self.mu_values.size))

    def summary(self) -> str:
        """Per candidate, case and advance ratio: ``passing or certified / step-6-fails`` azimuth counts, or why
        nothing is certified (``s3``, ``band``, ``noQ``, ``noXi``); the optimised weights of the
        forward C.G."""
        lines = [_join("mu:", self.mu_values)]
        why = {4: "noQ", 5: "noXi"}
        for c in range(len(self.keys)):
            lines.append(self.labels[c])
            for i, case in enumerate(self.cases):
                cells = []
                for j in range(self.mu_values.size):
                    counts = np.bincount(self.category[c, i, j], minlength=6)
                    if counts[:2].sum():
                        cells.append("/".join(str(int(v)) for v in counts[[0, 1]]))
                    else:
                        k = int(np.argmax(counts))
                        cells.append(why.get(k) or ("s3" if not self.A_step3[c, i, j] > 0 else "band"))
                lines.append(_join(f"   {case:9s}", "  ".join(f"{v:>6s}" for v in cells)))
        lines.append(f"(passing or certified / step-6-fails azimuths of {self.psi.size}; s3 = step 3 failed, W' > 0 on "
                     "every sphere; band = (h) failed on the band for every bound; "
                     "noQ = no quadratic function; noXi = no periodic motion)")
        lines.append(_join("optimised weights (forward C.G.):", np.round(self.weights[self.cases.index("forward")], 3)))
        return "\n".join(lines)

    def certificate_rows(self, case: str = "forward", keys: tuple = ("quadratic", "quadratic-opt")) -> list:
        """Rows of the certificate table: function, mu, ``A1`` of step 3, the certified bound
        ``A``, smallest and largest certified ``lambda0`` (three decimals), azimuths certified."""
        i, rows = self.cases.index(case), []
        for key in keys:
            c = self.keys.index(key)
            for j, mu in enumerate(self.mu_values):
                lam, ok = self.lambda0[c, i, j], self.stable[c, i, j]
                rows.append((self.labels[c], f"{mu:g}", f"{self.A_step3[c, i, j]:.3f}", f"{self.A_used[c, i, j]:.3f}",
                             f"{lam[ok].min():.3f}" if ok.any() else "-", f"{lam[ok].max():.3f}" if ok.any() else "-",
                             f"{int(ok.sum())} of {ok.size}"))
        return rows

    def certificate_table(self, case: str = "forward") -> str:
        """:meth:`certificate_rows` as a Markdown table."""
        return markdown_table((f"function ({case} C.G., strict, about the periodic motion)", "mu",
                               "A1 (step 3)", "A certified", "min lambda0", "max lambda0",
                               "azimuths certified"), self.certificate_rows(case))

    def _backward_mu(self) -> tuple:
        """Advance ratios of the backward C.G. with ``Q = I``: every azimuth certified, some,
        step 3 failed (``W' > 0`` on every sphere), (h) failed on the band for every bound; and
        of the neutral C.G., optimised: nothing certified."""
        cq, co = self.keys.index("quadratic"), self.keys.index("quadratic-opt")
        ib, ineu = self.cases.index("backward"), self.cases.index("neutral")
        ok = self.stable[cq, ib].all(axis=1)
        part = self.stable[cq, ib].any(axis=1) & ~ok
        ran = ~np.isin(self.category[cq, ib, :, 0], (4, 5))
        s3 = ran & ~(self.A_step3[cq, ib] > 0)
        band = ran & (self.A_step3[cq, ib] > 0) & ~(self.A_used[cq, ib] > 0)
        none_neu = ~self.stable[co, ineu].any(axis=1)
        mu = self.mu_values
        return mu[ok], mu[part], mu[s3], mu[band], mu[none_neu]

    def _energy_sides(self) -> tuple:
        """For the energy, practical, about the periodic motion (forward C.G.): the advance
        ratios where no azimuth is stable, and the share of azimuths with ``W' > 0`` on the
        sphere over the rear (270 to 90 deg) and the front half of the disc, per advance ratio."""
        cp, fwd = self.keys.index("energy-practical"), self.cases.index("forward")
        deg = np.degrees(self.psi)
        dark = self.category[cp, fwd] == 3
        tail = (deg < 90) | (deg >= 270)
        return ~self.stable[cp, fwd].any(axis=1), dark, tail

    def certificate_summary(self) -> str:
        """What the certificate table below it does not hold: where the energy's practical
        reading fails over the disc, the certified cells of the neutral and backward C.G., and
        the advance ratios of each outcome of the backward C.G. (an outcome at no advance ratio
        is left out)."""
        lines = []
        fail, dark, tail = self._energy_sides()
        label = self.labels[self.keys.index("energy-practical")]
        for j, mu in enumerate(self.mu_values):
            if j and fail[j]:
                lines.append(f"{label}, mu = {mu:g}: W' > 0 on the sphere at "
                             f"{dark[j, tail].mean():.2f} of the azimuths over the rear half (270 to 90 deg), "
                             f"{dark[j, ~tail].mean():.2f} over the front half")
        cq, co = self.keys.index("quadratic"), self.keys.index("quadratic-opt")
        for case in ("neutral", "backward"):
            i = self.cases.index(case)
            lam_h = self.lambda0[cq, i, 0][self.stable[cq, i, 0]]
            lines.append(f"{case} C.G.: certified cells, Q = I {int(self.stable[cq, i].sum())}, optimised "
                         f"{int(self.stable[co, i].sum())} of {self.stable[cq, i].size}; hover lambda0 (Q = I) "
                         f"{lam_h.min():.2g}")
            lines.append(_join("   per mu (Q = I):", self.stable[cq, i].sum(axis=1)))
        ok, part, s3, band, none_neu = self._backward_mu()
        parts = [f"{what} {_mu_list(mu)}" for what, mu in
                 (("every azimuth certified at mu =", ok), ("some azimuths at mu =", part),
                  ("step 3 failed at mu =", s3), ("(h) failed on the band at mu =", band)) if mu.size]
        lines.append("backward, Q = I: " + "; ".join(parts))
        lines.append("neutral, optimised: " + (f"nothing certified at mu = {_mu_list(none_neu)}" if none_neu.size
                                               else "certified at every advance ratio"))
        return "\n".join(lines)

    def facts(self) -> dict:
        """The numbers the chapter quotes about the scans: certified start regions and bounds
        of the forward C.G. (norm units, three and two decimals; deg of flap), counts of
        certified cells, where the energy's practical reading fails and on which half of the
        disc, the hover lambda0 of the other cases (two significant digits) and the advance
        ratios where the backward and neutral C.G. are certified or step 3 fails."""
        fwd = self.cases.index("forward")
        cq, co = self.keys.index("quadratic"), self.keys.index("quadratic-opt")
        ce, cp, cqh = self.keys.index("energy"), self.keys.index("energy-practical"), self.keys.index("quadratic-hover")
        lam_q = self.min_certified_lambda0("quadratic", "forward")
        lam_o = self.min_certified_lambda0("quadratic-opt", "forward")
        fail, dark, tail = self._energy_sides()
        out = {
            "ch7_lam_q0": round(lam_q[0], 3),
            "ch7_lam_q25": round(lam_q[-1], 3),
            "ch7_lam_o0": round(lam_o[0], 3),
            "ch7_lam_o_min": round(float(np.nanmin(lam_o[1:])), 3),
            "ch7_lam_o_max": round(float(np.nanmax(lam_o[1:])), 3),
            "ch7_fwd_opt_none_mu": _mu_list(self.mu_values[~self.stable[co, fwd].any(axis=1)]),
            "ch7_A_q0": round(float(self.A_used[cq, fwd, 0]), 2),
            "ch7_A_o0": round(float(self.A_used[co, fwd, 0]), 2),
            "ch7_deg_o0": round(float(lam_o[0] * np.degrees(DEFAULT_SCALES[0])), 2),
            "ch7_ncert_q": int(self.stable[cq, fwd].sum()),
            "ch7_ncert_o": int(self.stable[co, fwd].sum()),
            "ch7_ncells": int(self.stable[cq, fwd].size),
            "ch7_energy_cert": int(self.stable[ce].sum()),
            "ch7_energy_cells": int(self.stable[ce].size),
            "ch7_ep_mu_last": float(self.mu_values[np.flatnonzero(self.stable[cp, fwd].all(axis=1))[-1]]),
            "ch7_ep_mu_fail": float(self.mu_values[fail][0]),
            "ch7_ep_rear": round(float(dark[fail][:, tail].mean()), 2),
            "ch7_ep_front": round(float(dark[fail][:, ~tail].mean()), 2),
            "ch7_qh_fw": int(self.stable[cqh, :, 1:].sum()),
            "ch7_qh_hover": int(self.stable[cqh, :, 0].sum()),
            "ch7_qh_hover_cells": int(self.stable[cqh, :, 0].size),
        }
        for case in ("neutral", "backward"):
            i, tag = self.cases.index(case), _CASE_TAGS[case]
            out[f"ch7_ncert_q_{tag}"] = int(self.stable[cq, i].sum())
            out[f"ch7_ncert_o_{tag}"] = int(self.stable[co, i].sum())
            out[f"ch7_lam_q0_{tag}"] = float("%.2g" % self.lambda0[cq, i, 0][self.stable[cq, i, 0]].min())
        ok, part, s3, band, none_neu = self._backward_mu()
        out.update({"ch7_bwd_cert_mu": _mu_list(ok), "ch7_bwd_s3_mu": _mu_list(s3),
                    "ch7_bwd_band_mu": _mu_list(band), "ch7_neu_opt_none_mu": _mu_list(none_neu)})
        return out


def _scan_cell(task: tuple):
    """One cell of :func:`scan_data` (module level, so that worker processes can run it):
    ``(function, reading, case, mu, steady, Q, A, n_psi, engine_options)`` -> the
    :class:`~rotorlyap.methods.lyapunov.TechnicalStabilityResult`, or the message of a
    :class:`~rotorlyap.errors.NotAsymptoticallyStableError`."""
    function, reading, case, mu, steady, Q, A, n_psi, engine_options = task
    if function == "energy":
        lyap = None
    elif function == "quadratic":
        lyap = quadratic_function
    else:
        lyap = lambda b, steady: quadratic_function(b, steady, Q, label="optimised")  # noqa: E731
    tests = PAPER_TEST_DISTURBANCES if reading == "practical" else None
    try:
        return blade_stability(BladeParameters.table_i(case), mu, lyapunov=lyap, steady=steady, A=A,
                               n_psi=n_psi, test_disturbances=tests, **engine_options)
    except NotAsymptoticallyStableError as exc:
        return str(exc)


def _scan_cost(task: tuple) -> int:
    """Rank of a cell's expected cost (for the process pool, which starts the costliest first):
    the quadratic functions about a periodic motion take seconds, the others a fraction."""
    function, _, _, mu, steady, *_ = task
    return int(function != "energy") + 2 * int(function != "energy" and steady is not None and mu > 0)


def scan_data(motions: SteadyMotions, *, candidates=CANDIDATES, cases=None, mu_values=MU_SCAN,
              n_psi: int = 24, A: float | None = None, workers: int | None = None,
              **engine_options) -> ScanData:
    """Run :func:`rotorlyap.analysis.stability.blade_stability` for every candidate, case and advance ratio.

    The quadratic functions use the default scales as their coordinates (so ``Q = I`` is
    ``diag(1 / a_i**2)``); the optimised weight is found once per case in hover
    (:func:`rotorlyap.analysis.functions.optimised_quadratic_function`) and kept at every advance
    ratio. Where no quadratic function exists (unstable linearisation) or no periodic motion
    was found, the cells get categories 4 and 5 instead of a result.

    The cells are independent: with ``workers`` other than 1 (default: every core) they run in
    that many fresh processes (:func:`rotorlyap.analysis.sweep.process_map`, one BLAS thread
    each, the longest cells first); ``workers=1`` runs them here, one after the other. Each
    cell's result does not depend on where it ran.
    """
    from ..analysis.sweep import process_map, worker_count

    cases = motions.cases if cases is None else tuple(cases)
    mu_values = np.asarray(mu_values, dtype=float)
    A = DEFAULT_A if A is None else float(A)
    weights = np.full((len(cases), 6), np.nan)
    Qopt = {}
    for i, case in enumerate(cases):
        try:
            qo = optimised_quadratic_function(Blade(BladeParameters.table_i(case), 0.0), A=A)
        except NotAsymptoticallyStableError as exc:
            Qopt[case] = exc
            continue
        Qopt[case] = qo.Q
        weights[i] = np.diag(qo.Q) * DEFAULT_SCALES**2
    shape = (len(candidates), len(cases), mu_values.size, n_psi)
    cat = np.zeros(shape, dtype=int)
    stable = np.zeros(shape, dtype=bool)
    lam = np.zeros(shape)
    aused = np.full(shape[:3], np.nan)
    astep3 = np.full(shape[:3], np.nan)
    msgs = [[[None] * mu_values.size for _ in cases] for _ in candidates]
    tasks, where = [], []
    for c, cand in enumerate(candidates):
        for i, case in enumerate(cases):
            for j, mu in enumerate(mu_values):
                mu = float(mu)
                steady = None
                if cand.steady == "periodic" and mu > 0:
                    steady = motions.steady(case, mu)
                    if steady is None:
                        cat[c, i, j] = 5
                        msgs[c][i][j] = "no periodic motion found"
                        continue
                Q = None
                if cand.function not in ("energy", "quadratic"):  # the optimised weight
                    Q = Qopt[case]
                    if isinstance(Q, Exception):
                        cat[c, i, j] = 4
                        msgs[c][i][j] = str(Q)
                        continue
                tasks.append((cand.function, cand.reading, case, mu, steady, Q, A, n_psi, engine_options))
                where.append((c, i, j))
    workers = worker_count(workers, len(tasks))
    outcomes = (process_map(_scan_cell, tasks, workers, cost=_scan_cost) if workers > 1
                else [_scan_cell(t) for t in tasks])
    results, psi = {}, 2 * np.pi * np.arange(n_psi) / n_psi
    for (c, i, j), r in zip(where, outcomes):
        if isinstance(r, str):
            cat[c, i, j] = 4
            msgs[c][i][j] = r
            continue
        results[(candidates[c].key, cases[i], round(float(mu_values[j]), 6))] = r
        cat[c, i, j] = _category(r)
        stable[c, i, j] = r.stable
        lam[c, i, j] = r.lambda0
        aused[c, i, j] = r.A
        astep3[c, i, j] = r.A_step3
        psi = np.asarray(r.psi)
        msgs[c][i][j] = r.message
    return ScanData(cases=cases, mu_values=mu_values, psi=psi, keys=tuple(cd.key for cd in candidates),
                    labels=tuple(cd.label for cd in candidates),
                    readings=tuple(cd.reading for cd in candidates), category=cat, stable=stable,
                    lambda0=lam, A_used=aused, A_step3=astep3, weights=weights,
                    messages=tuple(tuple(tuple(row) for row in per_case) for per_case in msgs), results=results)


_SCAN_HATCHES = CATEGORY_HATCHES + SCAN_EXTRA_HATCHES



def plot_scan(data: ScanData, axes, *, rows=None) -> None:
    """The verdicts in the (psi, mu) plane: one row per candidate, one column per case. Each
    category has its colour and its hatch (:data:`rotorlyap.chapters.style.CATEGORY_HATCHES`,
    ``SCAN_EXTRA_HATCHES``), so that the map also reads without colour. The candidate's label
    is the title of the row's middle panel; the figure names the columns (:func:`figure_scan`)."""
    rows = list(range(len(data.keys)) if rows is None else rows)
    deg = np.degrees(data.psi)
    step = deg[1] - deg[0]
    # the azimuth is periodic: the cell about psi = 0 is drawn again past the last one, so that
    # the map fills 0 to 360 deg
    xe = np.concatenate([deg - step / 2, [deg[-1] + step / 2, deg[-1] + 3 * step / 2]])
    ye = _edges(data.mu_values, lo=0.0)
    mid = len(data.cases) // 2
    for r, c in enumerate(rows):
        for i, case in enumerate(data.cases):
            ax = axes[r, i]
            cat = data.category[c, i]
            cat = np.concatenate([cat, cat[:, :1]], axis=1)
            draw_categories(ax, xe, ye, cat, _SCAN_COLORS, _SCAN_HATCHES)
            ax.axvline(180, color="k", lw=0.8, ls=":")
            ax.set_xlim(0, 360)
            ax.set_ylim(0, ye[-1])
            ax.set_xticks(np.arange(0, 361, 90))
            ax.tick_params(labelsize=8.5)
            if i == mid:
                ax.set_title(f"({r + 1}) {data.labels[c]}", fontsize=9.5)
            if r == len(rows) - 1:
                ax.set_xlabel(r"azimuth $\psi$ (deg)", fontsize=9.5)
            if i == 0:
                ax.set_ylabel(r"advance ratio $\mu$", fontsize=9.5)


def scan_legend_handles(categories=None):
    """Legend patches of the scan categories (colour and hatch), all of them or the indices
    ``categories``."""
    from matplotlib.patches import Patch

    keep = range(len(_SCAN_COLORS)) if categories is None else sorted(int(k) for k in categories)
    return [Patch(facecolor=_SCAN_COLORS[k], edgecolor=HATCH_COLOR, hatch=_SCAN_HATCHES[k],
                  label=SCAN_CATEGORY_NAMES[k]) for k in keep]


def figure_scan(data: ScanData) -> Figure:
    """The figure of :func:`plot_scan` (one row per candidate, one column per case, 8.8 in
    wide, 1.7 in per row) with the legend of the categories present below, laid out and closed
    in pyplot.

    Returns
    -------
    matplotlib.figure.Figure
    """
    import matplotlib

    nc = len(data.keys)
    fig, axes = subplots(nc, len(data.cases), figsize=(8.8, 1.7 * nc + 1.6), sharex=True, sharey=True,
                         squeeze=False)
    plot_scan(data, axes)
    for i, case in enumerate(data.cases):  # the columns, above the first row's title
        axes[0, i].annotate(f"{case} C.G.", xy=(0.5, 1.0), xycoords="axes fraction", xytext=(0, 22),
                            textcoords="offset points", ha="center", va="bottom", fontsize=10.5,
                            fontweight="bold")
    with matplotlib.rc_context({"hatch.linewidth": HATCH_LINEWIDTH}):
        leg = fig.legend(handles=scan_legend_handles(np.unique(data.category)), loc="lower center", ncol=2,
                         fontsize=8.5, frameon=False, handlelength=2.4, handleheight=1.5)
    return finish(fig, rect=(0, _legend_height(fig, leg), 1, 1))


@dataclass(frozen=True)
class SearchCheck:
    """Certificates of the scan recomputed with finer searches: four times the quasi-random
    directions per sphere, and four times the iterations of each local ascent.

    Attributes
    ----------
    case : str
        Table I case.
    keys : tuple of str
        Candidate of each check, (n,).
    mu_values : numpy.ndarray
        Advance ratio of each check, (n,).
    n_sphere : int
        Quasi-random directions per sphere of the first finer search.
    n_iter : int
        Iterations of each local ascent in the second finer search.
    A : numpy.ndarray
        Certified bound, scan and the two finer searches, norm units, (n, 3).
    min_lambda0 : numpy.ndarray
        Smallest ``lambda0``, scan and finer searches, norm units, (n, 3).
    n_stable : numpy.ndarray
        Stable azimuths, scan and finer searches, (n, 3).
    """

    case: str
    keys: tuple
    mu_values: np.ndarray
    n_sphere: int
    n_iter: int
    A: np.ndarray
    min_lambda0: np.ndarray
    n_stable: np.ndarray

    @property
    def relative_change(self) -> np.ndarray:
        """Largest ``|min lambda0 (finer) / min lambda0 (scan) - 1|`` over the finer searches, (n,);
        0 where neither certifies, infinite where only one does."""
        lam0, fine = self.min_lambda0[:, :1], self.min_lambda0[:, 1:]
        with np.errstate(divide="ignore", invalid="ignore"):
            rel = np.where(lam0 > 0, np.abs(fine / lam0 - 1), np.where(fine > 0, np.inf, 0.0))
        return rel.max(axis=1)

    def summary(self) -> str:
        """One line per check: certified ``A``, smallest ``lambda0`` (four decimals) and stable
        azimuths, scan -> more directions -> more iterations."""
        arrow = lambda v, fmt: " -> ".join(format(x, fmt) for x in v.tolist())  # noqa: E731
        head = f"scan -> n_sphere {self.n_sphere} -> n_iter {self.n_iter}"
        return "\n".join([head] + [
            f"{key:14s} mu = {mu:4.2f}: A {arrow(a, '.4f')}, min lambda0 {arrow(lam, '.4f')}, "
            f"azimuths {arrow(n, 'd')}"
            for key, mu, a, lam, n in zip(self.keys, self.mu_values, self.A, self.min_lambda0,
                                          self.n_stable.astype(int))])

    def facts(self) -> dict:
        """The largest relative change of the smallest ``lambda0`` as per cent text with its unit,
        one decimal (``"< 0.05 %"`` below the printed precision, :func:`rotorlyap.reporting.percent`)."""
        return {"ch7_conv": percent(float(max(self.relative_change)), 1)}


@dataclass(frozen=True)
class CellSystem:
    """The system and the Liapunov function behind one cell of a scan.

    Attributes
    ----------
    f : callable
        The disturbed equations ``x' = f(psi, x)`` about the cell's steady motion.
    function : object
        The Liapunov function (``W``, ``dW``; a quadratic one has ``P(psi)``).
    quadratic : bool
        True for ``W = x^T P(psi) x``.
    result : TechnicalStabilityResult
        The scan's result for the cell.
    psi_free : bool
        Nothing depends on the azimuth (the engine's ``psi_free``, as ``blade_stability`` set it).
    """

    f: object
    function: object
    quadratic: bool
    result: object
    psi_free: bool = False


def cell_system(scan: ScanData, motions: SteadyMotions, key: str, case: str, mu: float) -> CellSystem:
    """Rebuild the disturbed equations and the Liapunov function of the scan cell ``(key, case,
    mu)`` (strict candidates), as :func:`scan_data` built them, for an independent check of its
    result.

    Raises
    ------
    KeyError
        The scan has no result for that cell (no steady motion or no function).
    ValueError
        ``key`` is not a strict candidate of the scan.
    """
    cand = {cd.key: cd for cd in CANDIDATES}.get(key)
    if cand is None or cand.reading != "strict" or key not in scan.keys:
        raise ValueError(f"key must be a strict candidate of the scan, one of "
                         f"{tuple(k for k, r in zip(scan.keys, scan.readings) if r == 'strict')}, got {key!r}")
    mu = float(mu)
    result = scan.result(key, case, mu)
    if result is None:
        raise KeyError(f"the scan has no result for {key!r}, {case} C.G., mu = {mu:g}")
    blade = Blade(BladeParameters.table_i(case), mu)
    if cand.steady == "periodic" and mu > 0:
        steady = motions.steady(case, mu)
    else:
        steady = Blade(blade.params, 0.0).equilibrium()
    if cand.function == "energy":
        fun = energy_function(blade, steady)
    else:
        Q = None
        if cand.function == "quadratic-opt":
            Q = np.diag(scan.weights[scan.cases.index(case)] / DEFAULT_SCALES**2)
        fun = quadratic_function(blade, steady, Q)
    f = disturbed_rhs(blade, steady)
    return CellSystem(f=f, function=fun, quadratic=cand.function != "energy", result=result,
                      psi_free=psi_free_system(blade, as_steady_motion(steady), f, fun, result.scales))


@dataclass(frozen=True)
class RuleChanges:
    """The scan's strict verdicts under the sound rule beside the paper's rule (step 6 at each
    start azimuth), on the same functions, azimuths and search.

    Attributes
    ----------
    labels : tuple of str
        Row labels ``"function, case C.G."``, (r,).
    mu_values : numpy.ndarray
        Advance ratios, (m,).
    n_paper, n_sound : numpy.ndarray
        Azimuths certified, (r, m); -1 where the scan has no result.
    A_paper, A_sound : numpy.ndarray
        Certified bound, norm units, (r, m); NaN where no result.
    lambda0_paper, lambda0_sound : numpy.ndarray
        Smallest certified ``lambda0``, norm units, (r, m); 0 where nothing is certified.
    n_psi : int
        Azimuths of each run.
    """

    labels: tuple
    mu_values: np.ndarray
    n_paper: np.ndarray
    n_sound: np.ndarray
    A_paper: np.ndarray
    A_sound: np.ndarray
    lambda0_paper: np.ndarray
    lambda0_sound: np.ndarray
    n_psi: int

    #: A bound or start region that moves by more than this (relative) counts as changed: both
    #: rules find their bounds by searches and a bisection, which do not determine them to the
    #: last digit. Measured: another floating-point environment (the perturbed one of ``.ci/run``)
    #: moves the paper rule's bound for the neutral C.G. at mu = 0.2 by 2.6 % (0.279 and 0.286),
    #: where the sound rule's stays within 0.01 %; the threshold is set well above that, so that
    #: which cells count as changed does not depend on the machine.
    RTOL = 0.10

    def changed(self) -> np.ndarray:
        """Boolean (r, m): the azimuth count differs, or ``A`` or the smallest ``lambda0`` by more
        than :attr:`RTOL`."""
        with np.errstate(divide="ignore", invalid="ignore"):
            dA = np.abs(self.A_sound / self.A_paper - 1)
            dl = np.abs(self.lambda0_sound / self.lambda0_paper - 1)
        ran = self.n_paper >= 0
        return ran & ((self.n_paper != self.n_sound) | (dA > self.RTOL) | (dl > self.RTOL))

    def rows(self) -> list:
        """One row per changed cell: function and case, mu, azimuths certified, ``A`` and
        smallest ``lambda0`` (two significant digits, what the searches determine), paper's
        rule -> sound rule."""
        def two(v: float, zero: str) -> str:  # two significant digits, trailing zeros kept
            if not v > 0:
                return zero
            return f"{v:#.2g}".rstrip(".")

        out = []
        for r, j in zip(*np.nonzero(self.changed())):
            out.append((self.labels[r], f"{self.mu_values[j]:g}",
                        f"{self.n_paper[r, j]} -> {self.n_sound[r, j]}",
                        f"{two(self.A_paper[r, j], '0')} -> {two(self.A_sound[r, j], '0')}",
                        f"{two(self.lambda0_paper[r, j], '-')} -> {two(self.lambda0_sound[r, j], '-')}"))
        return out

    def markdown(self) -> str:
        """:meth:`rows` as a Markdown table."""
        return markdown_table(("function, case", "mu", f"azimuths of {self.n_psi}, paper's -> sound",
                               "A, paper's -> sound", "min lambda0, paper's -> sound"), self.rows())

    def summary(self) -> str:
        """What the table below it does not hold: how many cells changed of how many, and in
        which direction."""
        ran = self.n_paper >= 0
        gained = int(((self.n_sound > 0) & (self.n_paper == 0)).sum())
        return (f"changed: {int(self.changed().sum())} of {int(ran.sum())} cells; passed by the paper's "
                f"rule, not certified by the sound rule: {int(((self.n_paper > 0) & (self.n_sound == 0)).sum())}; "
                + ("certified by the sound rule, not passed by the paper's: none" if not gained else
                   f"certified by the sound rule, not passed by the paper's: {gained}"))

    def facts(self) -> dict:
        """Counts of the changed cells and of those the paper's rule alone certified."""
        ran = self.n_paper >= 0
        return {"ch7_rule_changed": int(self.changed().sum()), "ch7_rule_cells": int(ran.sum()),
                "ch7_rule_rtol_pct": round(100 * self.RTOL, 1),
                "ch7_rule_lost": int(((self.n_paper > 0) & (self.n_sound == 0)).sum()),
                "ch7_rule_gained": int(((self.n_sound > 0) & (self.n_paper == 0)).sum())}


def _paper_rule_cell(task: tuple):
    """One rerun of :func:`rule_changes` (module level, for worker processes): ``(scan, motions,
    key, case, mu)`` -> ``(paper, sound)``, each ``(stable azimuths, A, min lambda0)``: the cell's
    :func:`technical_stability` with the paper's rule beside the scan's own result; None where
    the scan has no result for the cell."""
    scan, motions, key, case, mu = task
    try:
        cell = cell_system(scan, motions, key, case, mu)
    except KeyError:
        return None
    r_s, fun = cell.result, cell.function
    r_p = technical_stability(cell.f, fun.W, r_s.A_requested, scales=r_s.scales, dW=fun.dW,
                              rule="paper", psi_free=cell.psi_free,
                              **{**SCAN_OPTIONS, "n_psi": r_s.psi.size})
    return tuple((int(r.stable.sum()), r.A, r.lambda0[r.stable].min() if r.stable.any() else 0.0)
                 for r in (r_p, r_s))


def rule_changes(scan: ScanData, motions: SteadyMotions, *, keys=("quadratic", "quadratic-opt"),
                 workers: int | None = None) -> RuleChanges:
    """Rerun the scan's cells of ``keys`` (strict candidates, every case and advance ratio) with the
    paper's rule, on the same functions (:func:`cell_system`), azimuths and search options
    (:data:`SCAN_OPTIONS`), and set the verdicts beside the scan's (the sound rule). The reruns
    are independent: in ``workers`` fresh processes (default: every core; 1: here), the same
    numbers either way (:func:`rotorlyap.analysis.sweep.process_map`)."""
    from ..analysis.sweep import process_map, worker_count

    labels, shape = [], (len(keys) * len(scan.cases), scan.mu_values.size)
    n_p, n_s = np.full(shape, -1), np.full(shape, -1)
    A_p, A_s = np.full(shape, np.nan), np.full(shape, np.nan)
    l_p, l_s = np.zeros(shape), np.zeros(shape)
    tasks, where = [], []
    small = replace(scan, results={k: v for k, v in scan.results.items() if k[0] in keys})  # what the reruns need
    for key in keys:
        for case in scan.cases:
            labels.append(f"{scan.labels[scan.keys.index(key)].split(',')[0]}"
                          f"{', optimised' if key == 'quadratic-opt' else ''}, {case} C.G.")
            for j, mu in enumerate(scan.mu_values):
                tasks.append((small, motions, key, case, float(mu)))
                where.append((len(labels) - 1, j))
    workers = worker_count(workers, len(tasks))
    rows = (process_map(_paper_rule_cell, tasks, workers, cost=lambda t: t[4]) if workers > 1
            else [_paper_rule_cell(t) for t in tasks])
    for (row, j), got in zip(where, rows):
        if got is None:
            continue
        for (count, A_r, lam_r), n, A, lam in zip(got, (n_p, n_s), (A_p, A_s), (l_p, l_s)):
            n[row, j], A[row, j], lam[row, j] = count, A_r, lam_r
    return RuleChanges(labels=tuple(labels), mu_values=np.asarray(scan.mu_values, dtype=float),
                       n_paper=n_p, n_sound=n_s, A_paper=A_p, A_sound=A_s, lambda0_paper=l_p,
                       lambda0_sound=l_s, n_psi=int(scan.psi.size))


def _finer_search(task: tuple) -> tuple:
    """One rerun of :func:`search_check` (module level, for worker processes): ``(scan, motions,
    key, case, mu, options)`` -> ``(A, min lambda0, stable azimuths)`` of the cell's
    :func:`technical_stability` with the scan's options changed by ``options``."""
    scan, motions, key, case, mu, opts = task
    cell = cell_system(scan, motions, key, case, mu)
    r0, fun = cell.result, cell.function
    a = np.asarray(r0.scales)
    w_matrix = (lambda psi: a[:, None] * fun.P(psi) * a[None, :]) if cell.quadratic else None
    r = technical_stability(cell.f, fun.W, r0.A_requested, scales=a, dW=fun.dW, w_matrix=w_matrix,
                            psi_free=cell.psi_free, **{**SCAN_OPTIONS, "n_psi": r0.psi.size, **opts})
    return _search_row(r)


def _search_row(r) -> tuple:
    return r.A, (r.lambda0[r.stable].min() if r.stable.any() else 0.0), int(r.stable.sum())


def search_check(scan: ScanData, motions: SteadyMotions, *, case: str = "forward",
                 checks: tuple = ((0.0, "quadratic"), (0.0, "quadratic-opt"), (0.25, "quadratic"),
                                  (0.2, "quadratic-opt")),
                 n_sphere: int = 1024, n_iter: int = 160, workers: int | None = None) -> SearchCheck:
    """Rerun the ``(mu, key)`` cells of ``checks`` (strict candidates of the scan) with
    ``n_sphere`` quasi-random directions per sphere, and again with ``n_iter`` iterations of
    each local ascent, on the scan's azimuths and function (:func:`cell_system`). The reruns are
    independent: in ``workers`` fresh processes (default: every core; 1: here), the same numbers
    either way (:func:`rotorlyap.analysis.sweep.process_map`)."""
    from ..analysis.sweep import process_map, worker_count

    runs = ({"n_sphere": n_sphere}, {"n_iter": n_iter})
    A, lam, n = (np.zeros((len(checks), 1 + len(runs))) for _ in range(3))
    cells = {(key, case, round(float(mu), 6)) for mu, key in checks}
    small = replace(scan, results={k: v for k, v in scan.results.items() if k in cells})  # what the reruns need
    tasks = [(small, motions, key, case, float(mu), opts) for mu, key in checks for opts in runs]
    workers = worker_count(workers, len(tasks))
    rows = process_map(_finer_search, tasks, workers) if workers > 1 else [_finer_search(t) for t in tasks]
    for k, (mu, key) in enumerate(checks):
        for col, row in enumerate([_search_row(scan.result(key, case, mu))]  # the reruns checked it exists
                                  + rows[k * len(runs):(k + 1) * len(runs)]):
            A[k, col], lam[k, col], n[k, col] = row
    return SearchCheck(case=case, keys=tuple(key for _, key in checks),
                       mu_values=np.array([mu for mu, _ in checks], dtype=float), n_sphere=int(n_sphere),
                       n_iter=int(n_iter), A=A, min_lambda0=lam, n_stable=n)


# --------------------------------------------------------------------------------------
# 4. Validation
# --------------------------------------------------------------------------------------


def validation_data(scan: ScanData, motions: SteadyMotions, case: str, mu_values, *,
                    keys=("energy-practical", "energy", "quadratic", "quadratic-opt"),
                    psi_indices=None, n_directions: int = 16, n_periods: float = 10.0,
                    **options) -> tuple:
    """:func:`rotorlyap.methods.validation.validate` of the results of ``scan`` (about the periodic
    motion) for one case at each advance ratio of ``mu_values``.

    In hover the system is autonomous, so one start azimuth stands for all; in forward flight
    the starts are at ``psi_indices`` of the scan's grid (default: 0, 120 and 240 deg).
    """
    out = []
    n = scan.psi.size
    p = BladeParameters.table_i(case)
    for mu in mu_values:
        mu = float(mu)
        res = {k: scan.result(k, case, mu) for k in keys}
        res = {k: v for k, v in res.items() if v is not None}
        steady = motions.steady(case, mu) if mu > 0 else None
        blade = Blade(p, mu)
        if steady is None:
            f = disturbed_rhs(blade, blade.equilibrium() if mu == 0 else Blade(p, 0.0).equilibrium())
        else:
            f = disturbed_rhs(blade, steady)
        idx = (0,) if mu == 0 else (psi_indices or (0, n // 3, 2 * n // 3))
        out.append(validate(f, res, label=f"{case} C.G., mu = {mu:g}", psi_indices=idx,
                            n_directions=n_directions, n_periods=n_periods, **options))
    return tuple(out)


def confusion_rows(validations, labels: dict | None = None) -> list:
    """Table rows: validation, function, reading, the four counts and the violations."""
    rows = []
    for v in validations:
        for name, reading in zip(v.names, v.readings):
            cm = v.confusion(name)
            rows.append((v.label, (labels or {}).get(name, name), reading, int(cm[0, 0]), int(cm[0, 1]),
                         int(cm[1, 0]), int(cm[1, 1]), v.violations(name)))
    return rows


def plot_validation(validations, axes, *, certified=("quadratic-opt", "quadratic"), legend_ax=None) -> None:
    """Largest norm reached against the start norm, one panel per validation; colours (and
    markers): certified by both functions of ``certified``, by the first only, by the second
    only, not certified (stayed within ``A`` or not); lines: ``A`` and each function's
    certified bound. Motions that reached ``A`` were stopped there. The legend (on
    ``legend_ax``, default the first panel) names every group drawn in any panel."""
    def groups(v):
        c1 = v.covered[v.names.index(certified[0])] if certified[0] in v.names else np.zeros(v.n, bool)
        c2 = v.covered[v.names.index(certified[1])] if certified[1] in v.names else np.zeros(v.n, bool)
        return [(c1 & c2, "tab:green", "o", "certified by both quadratic functions"),
                (c1 & ~c2, "yellowgreen", "D", "certified by the optimised one only"),
                (~c1 & c2, "darkgoldenrod", "s", "certified by Q = I only"),
                (~c1 & ~c2 & v.bounded, "tab:blue", "v", "not certified, stayed within A"),
                (~c1 & ~c2 & ~v.bounded, "tab:red", "x", "not certified, reached A")]

    axes = list(np.asarray(axes).ravel())
    present = np.any([[g[0].any() for g in groups(v)] for v in validations], axis=0)
    for ax, v in zip(axes, validations):
        jitter = 1.0 + 0.03 * np.sin(np.arange(v.n) * 2.39996)
        for k, (mask, col, marker, lab) in enumerate(groups(v)):
            if mask.any() or (ax is axes[0] and present[k]):
                ax.scatter(v.radius[mask] * jitter[mask], v.max_norm[mask], s=24, color=col, marker=marker,
                           label=lab, alpha=0.75, linewidths=1.0 if marker == "x" else 0.0)
        ax.axhline(v.A, color="k", lw=1.2, label="$A$")
        for name, ls in zip(certified, ("--", ":")):
            if name in v.names:
                k = v.names.index(name)
                ax.axhline(v.A_used[k], color="tab:green", lw=1.4, ls=ls,
                           label=f"certified $A$, {'optimised' if name.endswith('opt') else 'Q = I'}")
        ax.plot([1e-3, 2], [1e-3, 2], color="0.6", lw=0.8)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlim(0.01, 1.3)
        ax.set_ylim(0.01, 1.5)
        ax.set_xlabel(r"start norm $\|x_0\|$")
        ax.set_title(v.label.replace("mu = ", r"$\mu$ = "), fontsize=10)
    axes[0].set_ylabel(r"largest norm reached, $\max_\psi \|x\|$")
    handles, labels = axes[0].get_legend_handles_labels()
    if legend_ax is None:
        axes[0].legend(fontsize=8.5, loc="upper left")
    else:
        legend_ax.legend(handles, labels, fontsize=9, loc="center")


#: Header of the confusion table (:meth:`ValidationData.confusion_table`).
CONFUSION_HEADER = ("motions", "function", "reading", "covered, stayed within A", "covered, reached A",
                    "not covered, stayed within A", "not covered, reached A", "covered, beyond the certified bound")


@dataclass(frozen=True)
class ValidationData:
    """Every simulated motion of the chapter, with the verdicts it is tabulated against.

    Attributes
    ----------
    forward : tuple of Validation
        The forward C.G., one per advance ratio (drawn in :func:`figure_validation`).
    hover : tuple of Validation
        The hover of each of :attr:`hover_cases`.
    hover_cases : tuple of str
        The other Table I cases.
    labels : dict
        ``{candidate key: label}`` for the tables.
    lambda0_hover : tuple of float
        Smallest certified ``lambda0`` of the forward C.G. in hover with ``Q = I`` and with the
        optimised weights (norm units), from the scan.
    """

    forward: tuple
    hover: tuple
    hover_cases: tuple
    labels: dict
    lambda0_hover: tuple

    @property
    def validations(self) -> tuple:
        """All validations, forward C.G. first."""
        return tuple(self.forward) + tuple(self.hover)

    def rows(self) -> list:
        """:func:`confusion_rows` of every validation."""
        return confusion_rows(self.validations, self.labels)

    def confusion_table(self) -> str:
        """The confusion matrices as a Markdown table (:data:`CONFUSION_HEADER`)."""
        return markdown_table(CONFUSION_HEADER, self.rows())

    def export(self) -> list:
        """Named columns of the forward-C.G. motions for :func:`rotorlyap.chapters.export.figure_csv`."""
        return ([(f"v{i}_" + k, getattr(v, k)) for i, v in enumerate(self.forward)
                 for k in ("radius", "max_norm", "bounded", "psi_index")]
                + [(f"v{i}_covered_" + n, v.covered[j]) for i, v in enumerate(self.forward)
                   for j, n in enumerate(v.names)])

    @staticmethod
    def _strict(v) -> np.ndarray:
        """Motions of ``v`` started inside at least one strict certificate."""
        return np.any([v.covered[j] for j, r in enumerate(v.readings) if r == "strict"], axis=0)

    @staticmethod
    def _strict_violations(v) -> int:
        return int(sum(v.violations(n) for n, r in zip(v.names, v.readings) if r == "strict"))

    def counts(self) -> tuple:
        """Motions simulated, started inside a strict certificate (each counted once), and
        strictly certified motions that went beyond their certified bound ``A``."""
        vals = self.validations
        return (sum(v.n for v in vals), sum(int(self._strict(v).sum()) for v in vals),
                sum(self._strict_violations(v) for v in vals))

    def growth_ratios(self) -> list:
        """Largest ``max ||x|| / ||x0||`` of a bounded motion, per forward-C.G. validation."""
        return [float((v.max_norm / v.radius)[v.bounded].max()) for v in self.forward]

    def observed_bounded(self) -> float:
        """Largest start norm up to which every start of the first forward-C.G. validation
        (hover) stayed within ``A`` (norm units)."""
        v = self.forward[0]
        bnd = {r: bool(v.bounded[v.radius == r].all()) for r in np.unique(v.radius)}
        return float(max(r for r, ok in bnd.items() if ok and all(bnd[s] for s in bnd if s <= r)))

    def summary(self) -> str:
        """What the confusion table below it does not hold: the counts, the starts placed on the
        sphere ``||x|| = A`` itself and the starts inside it that reached ``A``, the largest
        growth of a bounded motion (two decimals)."""
        n_motions, n_cert, viol = self.counts()
        lines = [f"{v.label}: starts on ||x|| = A {self.on_sphere(v)}, started inside A and reached it "
                 f"{self.inside_reached(v)}" for v in self.validations]
        lines.append(_join("motions:", n_motions, "; certified (strict):", n_cert, "; certified but beyond their bound:", viol))
        lines.append(_join("largest max-norm / start-norm of a bounded motion (forward C.G.):",
                           np.round(self.growth_ratios(), 2)))
        return "\n".join(lines)

    @staticmethod
    def on_sphere(v) -> int:
        """Starts of ``v`` placed on the sphere ``||x|| = A`` (or outside): "reached A" at once."""
        return int(np.sum(v.radius >= v.A * (1 - 1e-9)))

    @staticmethod
    def inside_reached(v) -> int:
        """Starts of ``v`` inside ``||x|| < A`` that reached ``A``."""
        return int(np.sum((v.radius < v.A * (1 - 1e-9)) & ~v.bounded))

    def facts(self) -> dict:
        """Counts, the observed bounded region of the forward hover and its ratio to the
        certified ``lambda0`` (one decimal), the largest growth (two decimals), and for each
        other hover the certified starts, their violations and the paper's reading's starts
        that reached ``A``."""
        n_motions, n_cert, viol = self.counts()
        obs = self.observed_bounded()
        out = {
            "ch7_n_motions": int(n_motions),
            "ch7_n_cert": n_cert,
            "ch7_strict_viol": int(viol),
            "ch7_obs_all_bounded": round(obs, 3),
            "ch7_obs_ratio_q": round(obs / self.lambda0_hover[0], 1),
            "ch7_obs_ratio_o": round(obs / self.lambda0_hover[1], 1),
            "ch7_growth_ratio": round(max(self.growth_ratios()), 2),
            "ch7_on_sphere_hover": self.on_sphere(self.forward[0]),
            "ch7_on_sphere_fwd": max(self.on_sphere(v) for v in self.forward),
            "ch7_inside_reached_fwd": sum(self.inside_reached(v) for v in self.forward),
        }
        for case, v in zip(self.hover_cases, self.hover):
            tag = _CASE_TAGS[case]
            out[f"ch7_hov_cert_{tag}"] = int(self._strict(v).sum())
            out[f"ch7_hov_viol_{tag}"] = self._strict_violations(v)
            out[f"ch7_hov_paper_left_{tag}"] = int(v.confusion("paper")[0, 1])
            out[f"ch7_inside_reached_{tag}"] = self.inside_reached(v)
        return out


def validation_set(scan: ScanData, motions: SteadyMotions, *, forward_mu: tuple = (0.0, 0.15, 0.25),
                   hover_cases: tuple = ("neutral", "backward"),
                   hover_keys: tuple = ("paper", "energy", "quadratic", "quadratic-opt"),
                   n_directions: int = 16, n_periods: float = 10) -> ValidationData:
    """:func:`validation_data` of the forward C.G. at ``forward_mu`` (the candidates about the
    periodic motion) and of the hover of ``hover_cases`` (``hover_keys``, the paper's reading
    included)."""
    fwd = validation_data(scan, motions, "forward", forward_mu, n_directions=n_directions, n_periods=n_periods)
    hov = ()
    for case in hover_cases:
        hov += validation_data(scan, motions, case, (0.0,), keys=hover_keys, n_directions=n_directions,
                               n_periods=n_periods)
    lam = tuple(scan.min_certified_lambda0(key, "forward")[0] for key in ("quadratic", "quadratic-opt"))
    return ValidationData(forward=fwd, hover=hov, hover_cases=tuple(hover_cases),
                          labels=dict(zip(scan.keys, scan.labels)), lambda0_hover=lam)


def figure_validation(data: ValidationData) -> Figure:
    """The figure of :func:`plot_validation` for the forward-C.G. validations (one panel
    each, two to a row, 8.6 in wide, 3.6 in per row; with an odd number of panels the legend
    fills the last cell), laid out and closed in pyplot.

    Returns
    -------
    matplotlib.figure.Figure
    """
    n = len(data.forward)
    ncol = min(n, 2)
    nrow = -(-n // ncol)
    fig, axes = subplots(nrow, ncol, figsize=(4.3 * ncol, 3.6 * nrow), squeeze=False)
    axes = axes.ravel()
    spare = axes[n] if n < axes.size else None
    plot_validation(data.forward, axes[:n], legend_ax=spare)
    if spare is not None:
        spare.set_axis_off()
    for k, ax in enumerate(axes[:n]):
        if k % ncol == 0:
            ax.set_ylabel(r"largest norm reached, $\max_\psi \|x\|$")
    return finish(fig)


# --------------------------------------------------------------------------------------
# 5. What the motion does
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class MotionData:
    """Long simulations where a reading marks instability.

    Attributes
    ----------
    histories : tuple of MotionHistory
        One per experiment.
    labels : tuple of str
        What each experiment is.
    start_labels : tuple of tuple of str
        The start disturbance of each motion.
    offsets : tuple of numpy.ndarray
        The steady state the disturbance is measured from, at the output azimuths, per
        experiment (k, 6): hinge angles are ``offset + x``.
    reference : tuple of numpy.ndarray or None
        For the forward-flight experiment about the hover equilibrium: the norm of
        ``xi(psi) - xi_hover`` (the periodic motion seen from the hover equilibrium) at the
        output azimuths; None otherwise.
    check : tuple of float
        Last-revolution peak norm of the first motion of each experiment recomputed for two
        revolutions from its final state with ten times tighter tolerances, relative change.
    parameters : tuple of BladeParameters
        The blade of each experiment (not compared).
    mu_values : tuple of float
        The advance ratio of each experiment.
    """

    histories: tuple
    labels: tuple
    start_labels: tuple
    offsets: tuple
    reference: tuple
    check: tuple
    parameters: tuple = field(default=(), compare=False, repr=False)
    mu_values: tuple = ()

    def export(self) -> list:
        """Per experiment: the peak norm of each revolution and the revolution index."""
        out = []
        for i, h in enumerate(self.histories):
            out += [(f"e{i}_peaks", h.peaks), (f"e{i}_rev", np.arange(h.peaks.shape[0]))]
        return out

    @property
    def check_bound(self) -> float:
        """The power of ten above the largest :attr:`check`
        (:func:`rotorlyap.reporting.decade_above`): an error estimate, known to its order of
        magnitude."""
        return decade_above(max(self.check))

    def summary(self) -> str:
        """Per experiment: the verdicts, the last peak norms (one decimal), the pitch and lag
        range over the last revolution of the first motion (deg); the tolerance check as a
        bound."""
        lines = []
        for h, off in zip(self.histories, self.offsets):
            k = points_per_revolution(h) + 1
            th = np.degrees(off[-k:, 2] + h.x[-k:, 0, 2])
            ze = np.degrees(off[-k:, 1] + h.x[-k:, 0, 1])
            lines.append(f"{h.label}: {_verdicts_in_words(h.verdict)}; peak norm in the last revolution "
                         f"{_join(*np.round(h.peaks[-1], 1))}; "
                         f"pitch {th.min():.1f} to {th.max():.1f} deg, lag {ze.min():.1f} to {ze.max():.1f} deg")
        lines.append(f"relative change of the last peak with ten times tighter tolerances: < {self.check_bound:.0e} "
                     "for every motion")
        return "\n".join(lines)

    def facts(self) -> dict:
        """The tolerance bound, and for the last experiment (forward flight about the hover
        equilibrium) the largest distance of the periodic motion and the last peak of the
        first motion (norm units, two decimals)."""
        return {"ch7_lc_check": self.check_bound,
                "ch7_ff_ref_max": round(float(self.reference[-1].max()), 2),
                "ch7_ff_peak": round(float(self.histories[-1].peaks[-1, 0]), 2)}


def points_per_revolution(h) -> int:
    """Output azimuths per revolution of a :class:`rotorlyap.methods.validation.MotionHistory`."""
    return int(round(2 * np.pi / (h.psi[1] - h.psi[0])))


def _check(f, h, scales, rtol) -> float:
    last = h.peaks[-1, 0]
    k = points_per_revolution(h)
    s = simulate(f, h.x[-1, :1], float(h.psi[-1]), 2, scales=scales, points_per_period=k,
                 rtol=rtol / 10, atol=rtol / 10 * 1e-3)
    return float(abs(s.norm[-(k + 1):, 0].max() / last - 1.0))


def motion_data(*, flutter_periods: int = 15, drift_mu: float = 0.05, drift_periods: int = 20,
                forward_mu: float = 0.15, forward_periods: int = 12,
                rtol: float = 1e-5, points_per_period: int = 128) -> MotionData:
    """Three experiments, each from two start disturbances (pitch angle ``0.5 a_theta``, and
    flap rate ``0.5 a_beta'``), each measured from the hover equilibrium of its blade:

    * backward C.G. in hover *without* the aerodynamic pitch damping (``cm_pitch_rate = 0``),
      whose hover flutters: what that modelling choice decides, ``flutter_periods``
      revolutions;
    * backward C.G. at ``drift_mu``, where no periodic motion is found near the hover
      equilibrium (the white cells of the certificate scan, fig-certificate-scan), ``drift_periods`` revolutions;
    * forward C.G. at ``forward_mu`` about the hover equilibrium (the paper's steady motion,
      where its Fig. 8 reading marks instability), ``forward_periods`` revolutions; the
      reference is the periodic motion seen from the hover equilibrium.
    """
    a = np.asarray(DEFAULT_SCALES)
    x0 = np.array([[0, 0, 0.5, 0, 0, 0], [0, 0, 0, 0.5, 0, 0]]) * a
    starts = (r"$\theta = 0.5 a_\theta$", r"$\beta' = 0.5 a_{\beta'}$")
    experiments = (
        (BladeParameters.table_i("backward", cm_pitch_rate=0.0), 0.0, flutter_periods,
         "backward C.G., hover, no pitch damping"),
        (BladeParameters.table_i("backward"), drift_mu, drift_periods, f"backward C.G., mu = {drift_mu:g}"),
        (BladeParameters.table_i("forward"), forward_mu, forward_periods,
         f"forward C.G., mu = {forward_mu:g}, about the hover equilibrium"),
    )
    hist, labels, offs, refs, checks = [], [], [], [], []
    for p, mu, n_per, label in experiments:
        xh = Blade(p, 0.0).equilibrium()
        f = disturbed_rhs(Blade(p, mu), xh)
        h = long_run(f, x0, 0.0, n_per, A=DEFAULT_A, scales=a, label=label, rtol=rtol,
                     atol=rtol * 1e-3, points_per_period=points_per_period)
        hist.append(h)
        labels.append(h.label)
        offs.append(np.broadcast_to(xh, (h.psi.size, 6)).copy())
        refs.append(None)
        checks.append(_check(f, h, a, rtol))
    p = experiments[-1][0]
    refs[-1] = scaled_norm(periodic_motion(p, forward_mu).xi(hist[-1].psi) - offs[-1][0], a)
    return MotionData(histories=tuple(hist), labels=tuple(labels), start_labels=(starts,) * 3,
                      offsets=tuple(offs), reference=tuple(refs), check=tuple(checks),
                      parameters=tuple(e[0] for e in experiments), mu_values=tuple(float(e[1]) for e in experiments))


def plot_motions(data: MotionData, axes) -> None:
    """(a) Peak norm per revolution, every motion (log scale; colour per experiment, line style
    per start); (b) the pitch (solid) and lag (dashed) angles over the last two revolutions of
    the first two experiments (dotted: the hover equilibrium); (c) the norm of the
    forward-flight motion about the hover equilibrium against the periodic motion seen from
    there."""
    from matplotlib.lines import Line2D
    from matplotlib.ticker import MaxNLocator

    ax = axes[0]
    colors = ("#CC79A7", "#D55E00", "#0072B2")
    starts = ("-", "--")
    for h, col in zip(data.histories, colors):
        for m, ls in zip(range(h.peaks.shape[1]), starts):
            ax.plot(np.arange(1, h.peaks.shape[0] + 1), h.peaks[:, m], ls, color=col, lw=1.4)
    ax.axhline(DEFAULT_A, color="k", lw=1.0, ls="-.")
    ax.set_yscale("log")
    peaks = np.concatenate([h.peaks.ravel() for h in data.histories] + [[DEFAULT_A]])
    lo, hi = np.log10(peaks.min()), np.log10(peaks.max())
    ax.set_ylim(10 ** (lo - 0.6 * (hi - lo)), 10 ** (hi + 0.1 * (hi - lo)))  # room for the legend below
    ax.xaxis.set_major_locator(MaxNLocator(integer=True))
    ax.set_xlabel("revolution")
    ax.set_ylabel(r"peak $\|x\|$ in the revolution")
    ax.set_title("(a) largest norm in each revolution", fontsize=10)
    handles = [Line2D([], [], color=col, lw=2.0, label=h.label.replace("mu = ", r"$\mu$ = ")) for h, col in zip(data.histories, colors)]
    handles += [Line2D([], [], color="0.3", ls=ls, lw=1.4, label=f"start {lab}")
                for lab, ls in zip(data.start_labels[0], starts)]
    handles.append(Line2D([], [], color="k", lw=1.0, ls="-.", label="$A$"))
    ax.legend(handles=handles, fontsize=8.5, ncol=2, loc="lower right")
    ax = axes[1]
    for h, off, col in zip(data.histories[:2], data.offsets[:2], colors):
        k = 2 * points_per_revolution(h) + 1
        az = np.degrees(h.psi[-k:] - h.psi[-k])
        for i, ls in ((2, "-"), (1, "--")):
            ax.plot(az, np.degrees(off[-k:, i] + h.x[-k:, 0, i]), ls, color=col, lw=1.4)
            ax.axhline(np.degrees(off[0, i]), color=col, lw=0.9, ls=":")
    ax.set_xlim(0, 720)
    ax.set_xticks(np.arange(0, 721, 180))
    lo, hi = ax.dataLim.y0, ax.dataLim.y1
    ax.set_ylim(lo - 0.22 * (hi - lo), hi + 0.05 * (hi - lo))  # room for the legend below
    ax.set_xlabel("azimuth over the last two revolutions (deg)")
    ax.set_ylabel("hinge angle (deg)")
    ax.set_title("(b) the first two experiments", fontsize=10)
    ax.legend(handles=[Line2D([], [], color="0.3", ls="-", lw=1.4, label=r"pitch $\theta$"),
                       Line2D([], [], color="0.3", ls="--", lw=1.4, label=r"lag $\zeta$"),
                       Line2D([], [], color="0.3", ls=":", lw=0.9, label="hover equilibrium")],
              fontsize=8.5, ncol=3, loc="lower center", columnspacing=1.2)
    ax = axes[2]
    h, ref = data.histories[2], data.reference[2]
    for m, ls in zip(range(h.norm.shape[1]), starts):
        ax.plot(h.psi / (2 * np.pi), h.norm[:, m], ls, color=colors[2], lw=1.0,
                label=f"start {data.start_labels[2][m]}")
    ax.plot(h.psi / (2 * np.pi), ref, color="k", lw=1.2, alpha=0.7,
            label=r"$\|\xi(\psi) - \xi_{\mathrm{hover}}\|$, periodic motion")
    ax.axhline(DEFAULT_A, color="k", lw=1.0, ls="-.", label="$A$")
    ax.set_xlabel("revolutions")
    ax.set_ylabel(r"$\|x\|$ about the hover equilibrium")
    ax.set_title("(c) " + h.label.replace(", about", ",\nabout").replace("mu = ", r"$\mu$ = "), fontsize=10)
    ax.set_ylim(0.0, 1.5 * max(np.nanmax(h.norm), np.nanmax(ref), DEFAULT_A))  # room for the legend above
    ax.legend(fontsize=8.5, loc="upper right")


def figure_motions(data: MotionData) -> Figure:
    """The figure of :func:`plot_motions` ((a) across the top, (b) and (c) below it; 8.6 x
    7.6 in), laid out and closed in pyplot.

    Returns
    -------
    matplotlib.figure.Figure
    """
    fig = figure(figsize=(8.6, 7.6))
    ax = fig.subplot_mosaic([["a", "a"], ["b", "c"]])
    plot_motions(data, [ax["a"], ax["b"], ax["c"]])
    return finish(fig)


@dataclass(frozen=True)
class FlutterCycle:
    """The limit cycle of a fluttering blade, from the first motion of a long simulation.

    Attributes
    ----------
    label : str
        The experiment.
    peak : float
        Peak norm in the last revolution, norm units.
    theta_min_deg, theta_max_deg : float
        Pitch range over the last revolution, deg.
    theta_eq_deg : float
        Pitch angle of the equilibrium, deg.
    alpha_max_deg : float
        Largest angle of attack over the last revolution, deg.
    oscillations_per_rev : float
        Pitch oscillations per revolution over the last five (zero crossings / 2).
    linear_frequency : float
        Frequency of the unstable linear (flutter) mode, 1/rev.
    settle_revolution : int
        First revolution whose peak is within 2 % of the last.
    stall_deg : float
        Stall angle of the section, deg.
    """

    label: str
    peak: float
    theta_min_deg: float
    theta_max_deg: float
    theta_eq_deg: float
    alpha_max_deg: float
    oscillations_per_rev: float
    linear_frequency: float
    settle_revolution: int
    stall_deg: float

    def summary(self) -> str:
        """One line: angle of attack (deg), oscillations per revolution, linear frequency,
        when it settled."""
        return (f"flutter limit cycle: largest angle of attack {self.alpha_max_deg:.1f} deg, "
                f"{self.oscillations_per_rev:.1f} pitch oscillations per revolution (linear flutter mode: "
                f"{self.linear_frequency:.2f} per rev), peaks within 2 % of the final from revolution "
                f"{self.settle_revolution}")

    def facts(self) -> dict:
        """Peak (one decimal), pitch range and angle of attack (whole deg), equilibrium pitch and
        stall angle (deg, one decimal), frequencies, the revolution it settled."""
        return {
            "ch7_lc_peak": round(float(self.peak), 1),
            "ch7_lc_thmin": int(round(float(self.theta_min_deg))),
            "ch7_lc_thmax": int(round(float(self.theta_max_deg))),
            "ch7_lc_th0": round(float(self.theta_eq_deg), 1),
            "ch7_lc_alpha": int(round(float(self.alpha_max_deg))),
            "ch7_lc_freq": round(float(self.oscillations_per_rev), 1),
            "ch7_lin_freq": round(float(self.linear_frequency), 2),
            "ch7_lc_settle": int(self.settle_revolution),
            "ch7_stall": round(float(self.stall_deg), 1),
        }


def flutter_cycle(data: MotionData, index: int = 0) -> FlutterCycle:
    """Analyse the first motion of experiment ``index`` of ``data`` (the backward C.G. in
    hover without aerodynamic pitch damping): its last revolution, its last five, and the
    linear flutter mode of the blade (:func:`rotorlyap.model.modes.derived_quantities`)."""
    h, off, p = data.histories[index], data.offsets[index], data.parameters[index]
    k = points_per_revolution(h) + 1
    last = slice(-k, None)
    th = np.degrees(off[last, 2] + h.x[last, 0, 2])
    alpha = np.degrees(Blade(p, data.mu_values[index]).angle_of_attack(h.psi[last], off[last] + h.x[last, 0]))
    five = slice(-5 * (k - 1) - 1, None)
    theta = h.x[five, 0, 2] - h.x[five, 0, 2].mean()
    freq = np.sum(np.signbit(theta[1:]) != np.signbit(theta[:-1])) / 2 / 5
    lin_freq = [m.frequency for m in derived_quantities(p).unstable_air_modes][0]
    settle = int(np.flatnonzero(np.abs(h.peaks[:, 0] / h.peaks[-1, 0] - 1) < 0.02)[0]) + 1
    return FlutterCycle(label=h.label, peak=float(h.peaks[-1, 0]), theta_min_deg=float(th.min()),
                        theta_max_deg=float(th.max()), theta_eq_deg=float(np.degrees(off[0, 2])),
                        alpha_max_deg=float(alpha.max()), oscillations_per_rev=float(freq),
                        linear_frequency=float(lin_freq), settle_revolution=settle,
                        stall_deg=float(np.degrees(p.airfoil.alpha_stall)))


@dataclass(frozen=True)
class FarMotion:
    """The periodic motion a long simulation settled on, found by Newton's method from its
    last revolution.

    Attributes
    ----------
    label : str
        The experiment.
    residual : float
        Collocation residual of the periodic motion.
    mean_lag_deg : float
        Its mean lag angle, deg.
    hover_lag_deg : float
        Lag angle of the hover equilibrium, deg.
    spectral_radius : float
        Of its Floquet multipliers.
    distance_end : float
        Largest distance of the simulated last revolution from it, norm units.
    distance_hover : float
        :func:`max_distance` of the hover equilibrium from it, norm units.
    peak : float
        Peak norm of the first motion in the last revolution, about the hover equilibrium.
    """

    label: str
    residual: float
    mean_lag_deg: float
    hover_lag_deg: float
    spectral_radius: float
    distance_end: float
    distance_hover: float
    peak: float

    def summary(self) -> str:
        """Two lines: convergence (residual as a bound), mean lag, spectral radius, distances."""
        return "\n".join([
            f"{self.label}: Newton from the last simulated revolution converges, residual "
            f"{format_small(self.residual)}; mean lag {self.mean_lag_deg:.1f} deg "
            f"(hover {self.hover_lag_deg:.1f} deg), spectral radius {self.spectral_radius:.3f}; "
            f"distance of the simulated last revolution from it {self.distance_end:.1e}",
            _join("   distance from the hover equilibrium:", round(float(self.distance_hover), 1)),
        ])

    def facts(self) -> dict:
        """Mean lag angles (deg, one decimal), residual (a bound), spectral radius (three
        decimals), distance and peak (norm units, one decimal)."""
        return {
            "ch7_far_lag": round(float(self.mean_lag_deg), 1),
            "ch7_far_lag_hover": round(float(self.hover_lag_deg), 1),
            "ch7_far_res": format_small(self.residual),
            "ch7_far_rho": Rounded(self.spectral_radius, 3),
            "ch7_far_dist": round(float(self.distance_hover), 1),
            "ch7_far_peak": round(float(self.peak), 1),
        }


def far_motion(data: MotionData, index: int = 1) -> FarMotion:
    """The periodic motion the first motion of experiment ``index`` of ``data`` settles on
    (the backward C.G. at ``mu = 0.05``): :func:`rotorlyap.model.steady.periodic_motion`
    started from its last revolution, and its Floquet multipliers
    (:func:`rotorlyap.analysis.floquet.blade_floquet`)."""
    h, off, p, mu = data.histories[index], data.offsets[index], data.parameters[index], data.mu_values[index]
    k = points_per_revolution(h) + 1
    far = periodic_motion(p, mu, start=last_revolution(h, off[0]))
    floq = blade_floquet(p, mu, steady=far)
    dist_end = float(scaled_norm(h.x[-k:, 0] + off[0] - far.xi(h.psi[-k:]), DEFAULT_SCALES).max())
    return FarMotion(label=h.label, residual=float(far.residual), mean_lag_deg=float(far.harmonics_deg[1, 0]),
                     hover_lag_deg=float(np.degrees(off[0, 1])), spectral_radius=float(floq.spectral_radius),
                     distance_end=dist_end, distance_hover=max_distance(far, off[0]), peak=float(h.peaks[-1, 0]))


# --------------------------------------------------------------------------------------
# W' near the origin
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class OriginData:
    """The largest ``W'`` on small spheres: what decides whether anything can be certified.

    Attributes
    ----------
    radii : numpy.ndarray
        Sphere radii of the scaled norm, (r,).
    labels : tuple of str
        The functions, (f,).
    max_dW : numpy.ndarray
        ``max W'`` over the sphere and the azimuths, (f, r) (units of each ``W`` per rad).
    max_W : numpy.ndarray
        ``max W`` over the sphere and the azimuths, (f, r).
    """

    radii: np.ndarray
    labels: tuple
    max_dW: np.ndarray
    max_W: np.ndarray

    @property
    def relative_rate(self) -> np.ndarray:
        """``max W' / max W`` (per rev): scale-free, comparable between functions."""
        return self.max_dW / self.max_W

    def export(self) -> dict:
        """The arrays for :func:`rotorlyap.chapters.export.figure_csv`."""
        return {"radius": self.radii, "labels": list(self.labels), "max_dW": self.max_dW, "max_W": self.max_W}

    def summary(self) -> str:
        """The radii and, per function, ``max W' / max W`` on each sphere.

        Two significant digits; one for the functions about the periodic motion (labels ending
        in "periodic motion"), where the largest ``W'`` is a search over the azimuth too that
        settles on maxima a few per cent apart when round-off changes (README, "What a
        committed output may print").
        """
        lines = [_join("radii:", np.array2string(self.radii, formatter={"float": lambda v: f"{v:.0e}"}))]
        for lab, r in zip(self.labels, self.relative_rate):
            fmt = f"{{:.{1 if lab.endswith('periodic motion') else 2}g}}"
            lines.append(_join(f"{lab:46s}", np.array2string(r, formatter={"float": fmt.format})))
        return "\n".join(lines)

    def facts(self) -> dict:
        """``max W' / max W`` on the smallest sphere (per rev, three decimals) of the energy
        (row 0) and of the quadratic function with ``Q = I`` (row 1) in hover; the radii between
        which the latter turns positive (two decimals); the range of radii where the last
        function (the quadratic one about the periodic motion) is negative (one digit). The
        rows are those of :meth:`QuadraticData.origin_functions`."""
        rr = self.relative_rate
        i_pos = int(np.flatnonzero(rr[1] > 0)[0])
        neg = np.flatnonzero(rr[-1] < 0)
        return {
            "ch7_org_energy": round(float(rr[0, 0]), 3),
            "ch7_org_quad": round(float(rr[1, 0]), 3),
            "ch7_org_quad_pos": round(float(self.radii[i_pos]), 2),
            "ch7_org_quad_neg": round(float(self.radii[i_pos - 1]), 2),
            "ch7_org_per_lo": float("%.1g" % self.radii[neg[0]]),
            "ch7_org_per_hi": float("%.1g" % self.radii[neg[-1]]),
        }


def origin_data(functions: dict, radii=None, *, n_psi: int = 12, n_sphere: int = 256,
                scales=None) -> OriginData:
    """``max W'`` and ``max W`` on spheres of the given radii for several functions.

    ``functions`` maps a label to ``(fun, constant)``: an object with vectorised ``W`` and
    ``dW``, and whether it is independent of the azimuth (then one azimuth is searched).
    Strict search: the structured and quasi-random directions of the engine, refined.
    """
    radii = np.geomspace(1e-4, 1.0, 13) if radii is None else np.asarray(radii, dtype=float)
    a = np.asarray(DEFAULT_SCALES if scales is None else scales, dtype=float)
    dirs = unit_sphere_points(a.size, n_sphere, 0)
    dw = np.zeros((len(functions), radii.size))
    w = np.zeros_like(dw)
    for i, (fun, constant) in enumerate(functions.values()):
        psi = np.zeros(1) if constant else 2 * np.pi * np.arange(n_psi) / n_psi
        for k, r in enumerate(radii):
            dw[i, k] = sphere_extremum(fun.dW, psi, r, a, dirs, per_psi=False, free_psi=not constant,
                                       n_refine=4, n_iter=20).value[0]
            w[i, k] = sphere_extremum(fun.W, psi, r, a, dirs, per_psi=False, n_refine=2, n_iter=10).value[0]
    return OriginData(radii=radii, labels=tuple(functions), max_dW=dw, max_W=w)


def plot_origin(data: OriginData, ax) -> None:
    """``max W' / max W`` on spheres against their radius (symmetric-log scale: negative
    values mean ``W' < 0`` on the whole sphere); colour, marker and line style per function."""
    styles = ("-", "-", "-", "--", "--", ":")
    markers = ("o", "s", "D", "^", "v", "P")
    for i, lab in enumerate(data.labels):
        ax.plot(data.radii, data.relative_rate[i], styles[i % len(styles)], marker=markers[i % len(markers)],
                ms=4.5, lw=1.3, label=lab)
    ax.axhline(0.0, color="k", lw=0.8)
    ax.set_xscale("log")
    ax.set_yscale("symlog", linthresh=0.01)
    ax.set_xlabel(r"sphere radius $r = \|x\|$ (norm units)")
    ax.set_ylabel(r"$\max W' \,/\, \max W$ on the sphere (per rev)")
    rate = data.relative_rate[np.isfinite(data.relative_rate)]
    if rate.size:
        ax.set_ylim(min(3 * rate.min(), -0.03), max(3 * rate.max(), 0.03))
    ax.legend(fontsize=8.5)


def figure_origin(data: OriginData) -> Figure:
    """The figure of :func:`plot_origin` (8 x 5.2 in, the legend below the panel), laid out
    and closed in pyplot.

    Returns
    -------
    matplotlib.figure.Figure
    """
    fig, ax = subplots(figsize=(8.0, 5.2))
    plot_origin(data, ax)
    ax.get_legend().remove()
    leg = fig.legend(*ax.get_legend_handles_labels(), loc="lower center", ncol=2, fontsize=8.5, frameon=False)
    return finish(fig, rect=(0, _legend_height(fig, leg), 1, 1))
