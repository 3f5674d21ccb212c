"""Chapter 7 ("Validation and beyond"), sections 1 and 2: the true periodic motion of every case
(:func:`steady_motions`), the inflow models' distance of the hover equilibrium from it
(:func:`inflow_data`), the end of the backward-C.G. branch (:func:`fold_data`) and the Floquet
modes about it (:func:`floquet_data`), with their figures."""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from ...analysis.floquet import blade_floquet, floquet_sweep
from ...analysis.functions import optimised_quadratic_function
from ...conventions import DEFAULT_A, DEFAULT_SCALES
from ...errors import PeriodicMotionError
from ...methods.simulation import scaled_norm
from ...model.blade import Blade
from ...model.inflow import GLAUERT_KX
from ...model.parameters import BladeParameters
from ...model.steady import periodic_motion, tabulate_motion
from ...reporting import count, format_small_array
from ..scans import _join, _legend_height, _mu_list
from ..style import CG_COLORS, CG_MARKERS, HINGE_COLORS, finish, subplots
from .common import CASES, MU_FLOQUET, max_distance

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = [
    "SteadyMotions", "steady_motions", "plot_steady_motions", "figure_steady_motions", "InflowData",
    "inflow_data", "FoldData", "fold_data", "FloquetData", "floquet_data", "plot_floquet",
    "figure_floquet", "floquet_legend_handles", "settings_facts",
]


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

    from ...analysis.functions import DEFAULT_N_STEPS

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
    from ...analysis.sweep import process_map, worker_count

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
        :func:`~rotorlyap.chapters.validation.common.max_distance` of the hover equilibrium from
        the periodic motion (64 collocation points), norm units, (k, m).
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
    """:func:`~rotorlyap.chapters.validation.common.max_distance` of the hover equilibrium from the periodic motion
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
