"""Figures of chapter 2, the algorithm: data, summaries, facts, drawings.

The conventions every chapter's module follows (data objects, ``summary()``, ``facts()``,
``plot_*`` and ``figure_*``) are in :mod:`rotorlyap.chapters`.

The chapter's figures: the level sets of ``W`` and ``W'`` (:func:`level_sets_data`), the start
region and step 6 by azimuth (:func:`start_region_data`), the largest norm of simulated motions
(:func:`max_norm_data`, from the motions of
:func:`~rotorlyap.chapters.norm_history.norm_history_data`, which chapter 1 uses too and which
lives in :mod:`rotorlyap.chapters.norm_history`), the convergence in the sampling
(:func:`convergence_data`) and the paper's rule against the sound one
(:func:`rule_comparison_data`). The certificate itself
(:class:`rotorlyap.methods.lyapunov.TechnicalStabilityResult`) is summarised step by step by
:func:`steps_summary`, and quoted through :func:`steps_facts`. All quantities are dimensionless
(the systems of :mod:`rotorlyap.methods.examples`); azimuths are in radians unless a name ends
in ``_deg``. Every number is rounded to the digits the search or integration behind it
determines (:mod:`rotorlyap.reporting`): three or four decimals.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from ..methods.examples import PeriodicSystem, pulsed_growth
from ..methods.lyapunov import TechnicalStabilityResult, technical_stability
from ..methods.simulation import simulate
from ..reporting import percent
# the chapter's notebook calls norm_history_data (of chapters 1 and 2) from this module
from .norm_history import NormHistoryData, _circle, norm_history_data  # noqa: F401
from .style import finish, subplots

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = [
    "steps_summary", "steps_facts",
    "LevelSetData", "level_set_data", "plot_level_sets",
    "LevelSetsData", "level_sets_data", "figure_level_sets",
    "StartRegionData", "start_region_data", "plot_start_region", "figure_start_region",
    "MaxNormData", "max_norm_data", "plot_max_norm", "figure_max_norm",
    "ConvergenceData", "convergence_data", "plot_convergence", "figure_convergence",
    "RuleComparisonData", "rule_comparison_data", "figure_rule_comparison",
]


def steps_summary(result: TechnicalStabilityResult) -> str:
    """The certificate step by step (steps 3 to 6 of the algorithm), as chapter 2 prints it.

    Returns
    -------
    str
        The result's message (its verdict in the book's words), then one line per step: the largest ``W'``
        on the requested sphere (step 3, four decimals), ``A`` and ``alpha`` (steps 3 and 4,
        four and five decimals), the smallest and largest ``lambda0`` with their azimuths in
        degrees (step 5), the largest ``W'`` on the shells (two significant digits) and the
        number of azimuths where step 6 passes.
    """
    lam = np.asarray(result.lambda0)
    psi_deg = np.degrees(result.psi)
    return "\n".join([
        result.message,
        "step 3: largest W' on ||x|| = %.2f: %.4f" % (result.A_requested, result.step3_max_dW),
        "step 3: A = %.4f;  step 4: alpha = %.5f" % (result.A, result.alpha),
        "step 5: lambda0 from %.4f (psi = %.0f deg) to %.4f (psi = %.0f deg)" % (
            lam.min(), psi_deg[lam.argmin()], lam.max(), psi_deg[lam.argmax()]),
        "step 6: largest W' on the shells: %.2e; step 6 passes at %d of %d azimuths" % (
            np.max(result.max_dW), np.sum(result.stable), np.size(result.stable)),
    ])


def steps_facts(result: TechnicalStabilityResult, prefix: str = "ch2") -> dict:
    """The numbers of the six steps that the text quotes, keyed by glue name.

    Parameters
    ----------
    result : TechnicalStabilityResult
        From :func:`rotorlyap.technical_stability`.
    prefix : str
        Glue-name prefix of the chapter quoting them.

    Returns
    -------
    dict
        ``{prefix}_A_req`` (as requested), ``{prefix}_step3`` (largest ``W'`` on the requested
        sphere, three decimals), ``{prefix}_A``, ``{prefix}_alpha``, ``{prefix}_lam_min``,
        ``{prefix}_lam_max`` (four decimals) and ``{prefix}_n_stable`` (certified azimuths).
    """
    return {
        f"{prefix}_A_req": float(result.A_requested),
        f"{prefix}_step3": round(float(result.step3_max_dW), 3),
        f"{prefix}_A": round(float(result.A), 4),
        f"{prefix}_alpha": round(float(result.alpha), 4),
        f"{prefix}_lam_min": round(float(np.min(result.lambda0)), 4),
        f"{prefix}_lam_max": round(float(np.max(result.lambda0)), 4),
        f"{prefix}_n_stable": int(np.sum(result.stable)),
    }


@dataclass(frozen=True)
class LevelSetData:
    """``W`` and ``W'`` on a grid of the state plane at one azimuth.

    Attributes
    ----------
    psi : float
        The azimuth.
    y, v : numpy.ndarray
        Grid axes (first and second state component).
    W, dW : numpy.ndarray
        Values on the grid, shape ``(len(v), len(y))``.
    alpha, A, A_requested, lambda0 : float
        The algorithm's numbers at this azimuth.
    scales : numpy.ndarray
        Norm scales.
    positive_fraction_requested : float
        Fraction of the requested sphere ``||x|| = A_requested`` on which ``W' > 0``
        (sampled at 3600 points): why step 3 reduced ``A``.
    """

    psi: float
    y: np.ndarray
    v: np.ndarray
    W: np.ndarray
    dW: np.ndarray
    alpha: float
    A: float
    A_requested: float
    lambda0: float
    scales: np.ndarray
    positive_fraction_requested: float

    def subsampled(self, step: int) -> "LevelSetData":
        """The same data on every ``step``-th line of the grid (for a smaller CSV file)."""
        if int(step) < 1:
            raise ValueError(f"step must be a positive integer, got {step!r}")
        k = slice(None, None, int(step))
        return dataclasses.replace(self, y=self.y[k], v=self.v[k], W=self.W[k, k], dW=self.dW[k, k])

    def summary(self) -> str:
        """One line: the azimuth (deg), ``lambda0`` (four decimals), the fraction of the requested
        sphere where ``W' > 0`` and the range of ``W'`` on the grid (three decimals)."""
        return ("psi = %3.0f deg: lambda0 = %.4f; W' > 0 on %.3f of the requested sphere; "
                "W' on the grid from %.3f to %.3f" % (np.degrees(self.psi), self.lambda0,
                self.positive_fraction_requested, self.dW.min(), self.dW.max()))


def level_set_data(
    system: PeriodicSystem, result: TechnicalStabilityResult, j: int = 0, *, n_grid: int = 301, extent: float = 1.2
) -> LevelSetData:
    """Evaluate ``W`` and ``W'`` on a square grid of half-width ``extent * A_requested``."""
    half = extent * result.A_requested
    y = np.linspace(-half, half, n_grid) * result.scales[0]
    v = np.linspace(-half, half, n_grid) * result.scales[1]
    Y, V = np.meshgrid(y, v)
    x = np.stack([Y.ravel(), V.ravel()], axis=1)
    psi = np.full(x.shape[0], result.psi[j])
    t = np.linspace(0, 2 * np.pi, 3600, endpoint=False)
    ring = result.A_requested * np.stack([np.cos(t), np.sin(t)], axis=1) * result.scales
    frac = float(np.mean(system.dW(np.full(t.size, result.psi[j]), ring) > result.tol))
    return LevelSetData(
        psi=float(result.psi[j]), y=y, v=v, W=system.W(psi, x).reshape(Y.shape),
        dW=system.dW(psi, x).reshape(Y.shape), alpha=result.alpha, A=result.A,
        A_requested=result.A_requested, lambda0=float(result.lambda0[j]), scales=result.scales,
        positive_fraction_requested=frac,
    )


def plot_level_sets(data: LevelSetData, ax, *, labels=("$y$", "$y'$"), legend: bool = True) -> None:
    """Draw the sign of ``W'``, the level set ``W = alpha`` and the three circles (and a legend
    of them unless ``legend`` is False)."""
    ax.contourf(data.y, data.v, data.dW > 0, levels=[0.5, 1.5], colors=["tab:red"], alpha=0.25)
    ax.contour(data.y, data.v, data.dW, levels=[0.0], colors="tab:red", linewidths=1)
    ax.contour(data.y, data.v, data.W, levels=[data.alpha], colors="k", linewidths=1.5)
    for radius, color, label in (
        (data.A_requested, "0.5", r"requested $\|x\| = A$"),
        (data.A, "tab:green", r"$\|x\| = A_1$ after step 3"),
        (data.lambda0, "tab:blue", r"$\|x\| = \lambda_0(\psi)$"),
    ):
        ax.plot(*_circle(radius, data.scales).T, color=color, lw=2, ls="--" if color == "0.5" else "-", label=label)
    ax.plot([], [], color="tab:red", lw=6, alpha=0.25, label="$W' > 0$")
    ax.plot([], [], color="k", lw=1.5, label=r"$W = \alpha$")
    ax.set_xlabel(labels[0])
    ax.set_ylabel(labels[1])
    ax.set_aspect("equal")
    ax.set_title(rf"$\psi = {np.degrees(data.psi):.0f}^\circ$", fontsize=10)
    if legend:
        ax.legend(loc="lower left", fontsize=8)


@dataclass(frozen=True)
class LevelSetsData:
    """The two panels of the level-set figure: :class:`LevelSetData` at two telling azimuths.

    Attributes
    ----------
    smallest : LevelSetData
        At the azimuth of the smallest start region ``lambda0``.
    tightest : LevelSetData
        At the azimuth where the largest ``W'`` on the shell (step 6) comes closest to zero.
    """

    smallest: LevelSetData
    tightest: LevelSetData

    @property
    def panels(self) -> tuple[LevelSetData, LevelSetData]:
        """``(smallest, tightest)``: the figure's left and right panel."""
        return (self.smallest, self.tightest)

    def export(self, step: int = 3) -> list[LevelSetData]:
        """What the CSV file holds: both panels on every ``step``-th line of the grid."""
        return [panel.subsampled(step) for panel in self.panels]

    def summary(self) -> str:
        """One line per panel (:meth:`LevelSetData.summary`)."""
        return "\n".join(panel.summary() for panel in self.panels)

    def facts(self, prefix: str = "ch2") -> dict:
        """Both azimuths (``{prefix}_psi_small``, ``{prefix}_psi_tight``, whole degrees) and the
        percentage of the requested sphere where ``W' > 0`` at each (``{prefix}_pos_frac_small``,
        ``{prefix}_pos_frac_tight``, one decimal)."""
        facts = {}
        for name, panel in (("small", self.smallest), ("tight", self.tightest)):
            facts[f"{prefix}_psi_{name}"] = int(round(np.degrees(panel.psi)))
        for name, panel in (("small", self.smallest), ("tight", self.tightest)):
            facts[f"{prefix}_pos_frac_{name}"] = round(100 * panel.positive_fraction_requested, 1)
        return facts


def level_sets_data(
    system: PeriodicSystem, result: TechnicalStabilityResult, *, n_grid: int = 301, extent: float = 1.2
) -> LevelSetsData:
    """:func:`level_set_data` at the smallest start region and where ``W'`` is tightest on the shell.

    Parameters
    ----------
    system : PeriodicSystem
        A 2-state system.
    result : TechnicalStabilityResult
        Its certificate; the azimuths are ``argmin(result.lambda0)`` and ``argmax(result.max_dW)``.
    n_grid, extent : int, float
        As for :func:`level_set_data`.
    """
    j_small = int(np.argmin(result.lambda0))
    j_tight = int(np.argmax(result.max_dW))
    return LevelSetsData(
        smallest=level_set_data(system, result, j_small, n_grid=n_grid, extent=extent),
        tightest=level_set_data(system, result, j_tight, n_grid=n_grid, extent=extent),
    )


def figure_level_sets(data: LevelSetsData) -> Figure:
    """A new 7.6 x 4.2 in figure, the two panels of :class:`LevelSetsData` side by side over one
    legend.

    Returns
    -------
    matplotlib.figure.Figure
        Laid out and already closed in pyplot (a notebook shows it only where it is glued).
    """
    fig, axes = subplots(1, 2, figsize=(7.6, 4.2))
    for ax, panel in zip(axes, data.panels):
        plot_level_sets(panel, ax, legend=False)
    fig.legend(*axes[0].get_legend_handles_labels(), loc="lower center", ncol=3, fontsize=8,
               frameon=False, handlelength=2.5)
    return finish(fig, rect=(0, 0.08, 1, 1))


@dataclass(frozen=True)
class ConvergenceData:
    """Results of the algorithm against the sampling resolution.

    Attributes
    ----------
    n_sphere : numpy.ndarray
        Quasi-random directions per sphere (0: the structured directions only).
    A, alpha, lambda0_min, lambda0_mean : numpy.ndarray
        Results with refinement, one per resolution.
    A_raw, lambda0_mean_raw : numpy.ndarray
        The same without local refinement (``n_iter = 0``): pure sampling.
    """

    n_sphere: np.ndarray
    A: np.ndarray
    alpha: np.ndarray
    lambda0_min: np.ndarray
    lambda0_mean: np.ndarray
    A_raw: np.ndarray
    lambda0_mean_raw: np.ndarray

    @property
    def largest_deviation(self) -> float:
        """Largest relative deviation of the refined ``A`` and mean ``lambda0`` from the finest
        (last) resolution, over the resolutions with quasi-random directions (``n_sphere > 0``);
        ``nan`` if there are none."""
        sampled = np.asarray(self.n_sphere) > 0
        if not sampled.any():
            return float("nan")
        dev = np.concatenate([self.A[sampled] / self.A[-1] - 1,
                              self.lambda0_mean[sampled] / self.lambda0_mean[-1] - 1])
        return float(np.abs(dev).max())

    def summary(self) -> str:
        """The resolutions, ``A`` and mean ``lambda0`` with and without refinement (four
        decimals), and :attr:`largest_deviation` in per cent (two decimals, :func:`rotorlyap.reporting.percent`:
        a deviation below 0.005 % is printed as that bound)."""
        sampled = np.asarray(self.n_sphere)[np.asarray(self.n_sphere) > 0]
        lowest = int(sampled.min()) if sampled.size else 0
        return "\n".join([
            f"n_sphere:          {self.n_sphere}",
            f"A (refined):       {np.round(self.A, 4)}",
            f"A (sampling only): {np.round(self.A_raw, 4)}",
            f"mean lambda0 (refined):       {np.round(self.lambda0_mean, 4)}",
            f"mean lambda0 (sampling only): {np.round(self.lambda0_mean_raw, 4)}",
            "largest deviation from the finest, refined, n_sphere >= %d: %s"
            % (lowest, percent(self.largest_deviation, 2)),
        ])

    def facts(self, prefix: str = "ch2") -> dict:
        """``{prefix}_conv_dev``: :attr:`largest_deviation` as per cent text with its unit, two
        decimals (``"0.31 %"``, or ``"< 0.005 %"`` below the printed precision)."""
        return {f"{prefix}_conv_dev": percent(self.largest_deviation, 2)}


def convergence_data(system: PeriodicSystem, A: float, n_sphere_values, *, n_psi: int = 24,
                     rule: str = "paper") -> ConvergenceData:
    """Run :func:`technical_stability` at several sampling resolutions, with and without refinement.

    By default with the paper's rule (``rule="paper"``): the study is of the sphere search of
    steps 3-6, which both rules share.

    Parameters
    ----------
    system : PeriodicSystem
        The system and its Liapunov function.
    A : float
        Requested bound (scaled norm).
    n_sphere_values : sequence of int
        Quasi-random directions per sphere, in increasing order (the last is the reference).
    n_psi : int
        Azimuths of every run.
    rule : {"paper", "sound"}
        Passed on to :func:`technical_stability`.
    """
    rows, raw = [], []
    for ns in n_sphere_values:
        r = technical_stability(system.f, system.W, A, dim=system.dim, dW=system.dW, n_psi=n_psi,
                                n_sphere=int(ns), rule=rule)
        rows.append((r.A, r.alpha, r.lambda0.min(), r.lambda0.mean()))
        q = technical_stability(system.f, system.W, A, dim=system.dim, dW=system.dW, n_psi=n_psi,
                                n_sphere=int(ns), n_iter=0, rule=rule)
        raw.append((q.A, q.lambda0.mean()))
    rows, raw = np.array(rows), np.array(raw)
    return ConvergenceData(np.asarray(n_sphere_values), rows[:, 0], rows[:, 1], rows[:, 2], rows[:, 3],
                           raw[:, 0], raw[:, 1])


def plot_convergence(data: ConvergenceData, ax) -> None:
    """Draw the relative change of ``A`` and mean ``lambda0`` against the resolution."""
    ref_A, ref_l = data.A[-1], data.lambda0_mean[-1]
    ns = np.where(data.n_sphere == 0, 1, data.n_sphere)  # plot "structured only" at 1
    ax.plot(ns, data.A / ref_A, "o-", color="tab:green", label="$A$ after step 3, refined")
    ax.plot(ns, data.lambda0_mean / ref_l, "s-", color="tab:blue", label=r"mean $\lambda_0$, refined")
    ax.plot(ns, data.A_raw / ref_A, "o--", color="tab:green", alpha=0.5, label="$A$, sampling only")
    ax.plot(ns, data.lambda0_mean_raw / ref_l, "s--", color="tab:blue", alpha=0.5,
            label=r"mean $\lambda_0$, sampling only")
    ax.set_xscale("log", base=2)
    ax.set_xlabel("quasi-random directions per sphere, n_sphere (1 = structured directions only)")
    ax.set_ylabel("value / value at the finest resolution")
    ax.axhline(1.0, color="0.5", lw=0.8)
    ax.legend(fontsize=8)


def figure_convergence(data: ConvergenceData) -> Figure:
    """A new 7 x 3.8 in figure of :class:`ConvergenceData` (:func:`plot_convergence`).

    Returns
    -------
    matplotlib.figure.Figure
        Laid out and already closed in pyplot (a notebook shows it only where it is glued).
    """
    fig, ax = subplots(figsize=(7, 3.8))
    plot_convergence(data, ax)
    return finish(fig)


@dataclass(frozen=True)
class StartRegionData:
    """Steps 5 and 6 at every azimuth of a certificate: the start region and ``max W'`` on the shell.

    Attributes
    ----------
    psi_deg : numpy.ndarray
        The azimuths ``psi_j`` (deg).
    lambda0 : numpy.ndarray
        Start-region radius at each azimuth (scaled norm; step 5).
    A, A_requested : float
        The bound after step 3 and as requested (scaled norm).
    max_dW : numpy.ndarray
        Largest ``W'`` found on the shell ``lambda0_j < ||x|| <= A`` (step 6).
    """

    psi_deg: np.ndarray
    lambda0: np.ndarray
    A: float
    A_requested: float
    max_dW: np.ndarray

    def _quarters(self) -> tuple[np.ndarray, str]:
        """Indices of the azimuths nearest a quarter period apart from the first, and their label."""
        n = self.psi_deg.size
        idx = np.unique(np.round(np.arange(4) * n / 4).astype(int) % n)
        return idx, ", ".join("%.0f" % d for d in self.psi_deg[idx])

    def summary(self) -> str:
        """``lambda0`` (four decimals) and ``max W'`` (six decimals) at four azimuths a quarter
        period apart."""
        idx, label = self._quarters()
        return (f"lambda0 at psi = {label} deg: {np.round(self.lambda0[idx], 4)}\n"
                f"max W' on the shell at psi = {label} deg: {np.round(self.max_dW[idx], 6)}")


def start_region_data(result: TechnicalStabilityResult) -> StartRegionData:
    """Steps 5 and 6 of ``result`` at its azimuths (:class:`StartRegionData`)."""
    return StartRegionData(psi_deg=np.degrees(result.psi), lambda0=np.asarray(result.lambda0),
                           A=float(result.A), A_requested=float(result.A_requested),
                           max_dW=np.asarray(result.max_dW))


def plot_start_region(data: StartRegionData, ax) -> None:
    """Draw ``lambda0(psi)`` and ``A`` (left axis) and the step-6 ``max W'`` (right axis)."""
    deg = data.psi_deg
    ax.plot(deg, data.lambda0, "o-", ms=3, color="tab:blue", label=r"$\lambda_0(\psi_j)$ (step 5)")
    ax.axhline(data.A, color="tab:green", lw=2, label="$A$ after step 3")
    ax.axhline(data.A_requested, color="0.5", ls="--", label="requested $A$")
    ax.set_ylim(0, 1.1 * data.A_requested)
    ax.set_xlabel(r"azimuth $\psi_j$ (deg)")
    ax.set_ylabel("scaled norm")
    ax.set_xticks(np.arange(0, 361, 45))
    ax2 = ax.twinx()
    ax2.plot(deg, data.max_dW, "-", color="tab:red", lw=1, label=r"max $W'$ on the shell (step 6)")
    ax2.axhline(0, color="tab:red", lw=0.5, ls=":")
    ax2.set_ylabel(r"max $W'$ on $\lambda_0 < \|x\| \leq A$", color="tab:red")
    lines = ax.get_legend_handles_labels()
    lines2 = ax2.get_legend_handles_labels()
    ax.legend(lines[0] + lines2[0], lines[1] + lines2[1], loc="center left", fontsize=8)


def figure_start_region(data: StartRegionData) -> Figure:
    """A new 7 x 3.6 in figure of :class:`StartRegionData` (:func:`plot_start_region`, two y axes).

    Returns
    -------
    matplotlib.figure.Figure
        Laid out and already closed in pyplot (a notebook shows it only where it is glued).
    """
    fig, ax = subplots(figsize=(7, 3.6))
    plot_start_region(data, ax)
    return finish(fig)


@dataclass(frozen=True)
class MaxNormData:
    """The largest norm each simulated motion reaches, relative to ``A``, by start azimuth.

    One row per motion, the columns of the figure's CSV file.

    Attributes
    ----------
    start_psi_deg : numpy.ndarray
        Start azimuth of each motion (deg).
    max_norm_over_A : numpy.ndarray
        Its largest scaled norm over the simulation, divided by ``A``.
    start_radius_over_A : numpy.ndarray
        The start-region radius ``lambda0`` at its start azimuth, divided by ``A``.
    """

    start_psi_deg: np.ndarray
    max_norm_over_A: np.ndarray
    start_radius_over_A: np.ndarray

    @property
    def max_ratio(self) -> float:
        """Largest ``||x|| / A`` over all motions: below 1 is the theorem's conclusion."""
        return float(np.max(self.max_norm_over_A))

    def summary(self) -> str:
        """The number of motions and the largest ``||x|| / A`` (three decimals)."""
        return "%d motions; largest ||x|| / A: %.3f" % (self.start_psi_deg.size, self.max_ratio)

    def facts(self, prefix: str = "ch2") -> dict:
        """``{prefix}_max_ratio``: :attr:`max_ratio` to three decimals."""
        return {f"{prefix}_max_ratio": round(self.max_ratio, 3)}


def max_norm_data(history: NormHistoryData) -> MaxNormData:
    """Reduce simulated motions (:func:`~rotorlyap.chapters.norm_history.norm_history_data`) to one
    row per motion."""
    start_deg = np.concatenate([np.full(n.shape[1], np.degrees(p[0])) for p, n in zip(history.psi, history.norm)])
    return MaxNormData(
        start_psi_deg=start_deg,
        max_norm_over_A=np.concatenate([n.max(axis=0) for n in history.norm]) / history.A,
        start_radius_over_A=np.interp(start_deg, np.degrees(history.psi_grid), history.lambda0) / history.A,
    )


def plot_max_norm(data: MaxNormData, ax) -> None:
    """Draw the largest ``||x|| / A`` of every simulated motion against its start azimuth."""
    ax.plot(data.start_psi_deg, data.max_norm_over_A, "o", color="0.3", ms=3, alpha=0.5)
    ax.axhline(1.0, color="tab:green", lw=2, label=r"$\|x\| = A$")
    starts, first = np.unique(data.start_psi_deg, return_index=True)
    ax.plot(starts, data.start_radius_over_A[first], "_", color="tab:blue", ms=14, mew=2,
            label=r"start radius $\lambda_0(\psi_0) / A$")
    ax.plot([], [], "o", color="0.3", ms=3, label="largest $\\|x\\| / A$ of one motion")
    ax.set_ylim(0, 1.1)
    ax.set_xlabel(r"start azimuth $\psi_0$ (deg)")
    ax.set_ylabel(r"largest $\|x(\psi)\| / A$, $\psi \geq \psi_0$")
    ax.set_xticks(np.arange(0, 361, 45))
    ax.legend(loc="lower right", fontsize=8)


def figure_max_norm(data: MaxNormData) -> Figure:
    """A new 7 x 3.4 in figure of :class:`MaxNormData` (:func:`plot_max_norm`).

    Returns
    -------
    matplotlib.figure.Figure
        Laid out and already closed in pyplot (a notebook shows it only where it is glued).
    """
    fig, ax = subplots(figsize=(7, 3.4))
    plot_max_norm(data, ax)
    return finish(fig)


@dataclass(frozen=True)
class RuleComparisonData:
    """The paper's step 6 against the theorem's (h) over the whole period, on one system.

    Attributes
    ----------
    paper, sound : TechnicalStabilityResult
        The engine's results with ``rule="paper"`` and ``rule="sound"``.
    growth, pulse, saturation : float
        ``a``, ``b`` and ``k`` of :func:`rotorlyap.methods.examples.pulsed_growth` (``W' > 0`` for
        ``x**2 < a / k``).
    level_radius : numpy.ndarray
        Inner boundary of the band ``W >= alpha`` at :attr:`psi_fine_deg` (scaled norm).
    psi_fine_deg : numpy.ndarray
        A fine azimuth grid (deg) for the band.
    sim_psi : numpy.ndarray
        Azimuth (rev, from the start) of the simulated motions.
    sim_norm : numpy.ndarray
        Their norms, shape ``(len(sim_psi), number of certified azimuths)``.
    """

    paper: TechnicalStabilityResult
    sound: TechnicalStabilityResult
    growth: float
    pulse: float
    saturation: float
    level_radius: np.ndarray
    psi_fine_deg: np.ndarray
    sim_psi: np.ndarray
    sim_norm: np.ndarray

    @property
    def max_ratio(self) -> float:
        """Largest ``||x|| / A`` reached by a motion started inside a start region the paper's
        rule certified."""
        return float(self.sim_norm.max() / self.paper.A)

    def summary(self) -> str:
        """Both verdicts, the certified azimuths and the motions' largest norm (rounded)."""
        idx = np.flatnonzero(self.paper.stable)
        deg = ", ".join("%.0f" % d for d in np.degrees(self.paper.psi[idx]))
        return (f"paper's rule: {idx.size} of {self.paper.psi.size} azimuths pass (an indicator) "
                f"(psi = {deg} deg)\n"
                f"  lambda0 up to {self.paper.lambda0.max():.2f}; motions from 0.99 lambda0: "
                f"largest ||x|| / A = {self.max_ratio:.2f}\n"
                f"sound rule: {self.sound.stable.sum()} certified; largest W' on the band: "
                f"{self.sound.band_max_dW:.2f}")

    def facts(self, prefix: str = "ch2") -> dict:
        """Glue values: the system's parameters and ``A``, the paper's count, the motions'
        largest ``||x|| / A``, the band's ``W'``."""
        return {f"{prefix}_cx_a": self.growth, f"{prefix}_cx_b": self.pulse,
                f"{prefix}_cx_k": self.saturation, f"{prefix}_cx_A": self.paper.A_requested,
                f"{prefix}_cx_n_paper": int(self.paper.stable.sum()),
                f"{prefix}_cx_n_psi": int(self.paper.psi.size),
                f"{prefix}_cx_max_ratio": round(self.max_ratio, 2),
                f"{prefix}_cx_band_max": round(float(self.sound.band_max_dW), 2),
                f"{prefix}_cx_n_sound": int(self.sound.stable.sum())}

    def export(self) -> dict:
        """Columns of the figure's CSV: the paper's start regions by azimuth."""
        return {"psi_deg": np.degrees(self.paper.psi), "lambda0_paper": self.paper.lambda0,
                "certified_paper": self.paper.stable.astype(int),
                "certified_sound": self.sound.stable.astype(int)}


def rule_comparison_data(growth: float = 0.5, pulse: float = 2.0, saturation: float = 1.0, *,
                         A: float = 1.0, n_psi: int = 24, n_periods: float = 3.0) -> RuleComparisonData:
    """Run both rules on :func:`~rotorlyap.methods.examples.pulsed_growth` with these parameters
    and simulate a motion from ``0.99 lambda0_j`` at every azimuth the paper's rule certifies."""
    system = pulsed_growth(growth=growth, pulse=pulse, saturation=saturation)
    kw = dict(scales=np.ones(system.dim), n_psi=n_psi, dW=system.dW, period=system.period)
    paper = technical_stability(system.f, system.W, A, rule="paper", **kw)
    sound = technical_stability(system.f, system.W, A, rule="sound", **kw)
    psi_fine = np.linspace(0.0, system.period, 361)
    w_unit = system.W(psi_fine, np.ones((psi_fine.size, system.dim)) / np.sqrt(system.dim))
    level = np.sqrt(paper.alpha / w_unit)  # W = p(psi) x^2: the radius where W = alpha
    idx = np.flatnonzero(paper.stable)
    norms, psi_rel = [], None
    for j in idx:
        sim = simulate(system.f, 0.99 * paper.lambda0[j] * np.ones((1, system.dim)) / np.sqrt(system.dim),
                       paper.psi[j], n_periods, period=system.period, points_per_period=180)
        norms.append(sim.norm[:, 0])
        psi_rel = (sim.psi - sim.psi[0]) / system.period
    return RuleComparisonData(paper=paper, sound=sound, growth=float(growth), pulse=float(pulse),
                              saturation=float(saturation), level_radius=level, psi_fine_deg=np.degrees(psi_fine),
                              sim_psi=psi_rel, sim_norm=np.stack(norms, axis=1))


def figure_rule_comparison(data: RuleComparisonData) -> Figure:
    """Left: the azimuth-norm plane with the band ``W >= alpha`` inside ``A``, the region
    ``W' > 0`` and the start regions the paper's rule passes; right: the motions started there.

    Returns
    -------
    matplotlib.figure.Figure
        7.6 x 4.6 in, laid out and closed in pyplot; each panel's legend under it.
    """
    fig, (ax, bx) = subplots(1, 2, figsize=(7.6, 4.6))
    A = data.paper.A
    deg = data.psi_fine_deg
    grow = np.sqrt(data.growth / data.saturation)
    inner = np.minimum(data.level_radius, A)
    top = np.minimum(grow, A)
    ax.fill_between(deg, 0, np.minimum(inner, top), color="0.85", lw=0)
    ax.fill_between(deg, inner, A, color="tab:orange", alpha=0.3, lw=0)
    ax.fill_between(deg, inner, np.maximum(inner, top), color="tab:red", alpha=0.6, lw=0)
    ax.plot([], [], "s", color="0.85", label=r"$W' > 0$, $W < \alpha$")
    ax.plot([], [], "s", color="tab:orange", alpha=0.4, label=r"band $W \geq \alpha$, $\|x\| \leq A$")
    ax.plot([], [], "s", color="tab:red", alpha=0.6, label=r"$W' > 0$ on the band: (h) fails")
    ax.axhline(A, color="tab:green", lw=2, label="$A$")
    idx = data.paper.stable
    ax.vlines(np.degrees(data.paper.psi[idx]), 0, data.paper.lambda0[idx], color="tab:blue", lw=3,
              label=r"starts the paper's rule passes")
    ax.set_xlim(0, 360)
    ax.set_ylim(0, 1.1 * A)
    ax.set_xticks(np.arange(0, 361, 90))
    ax.set_xlabel(r"azimuth $\psi$ (deg)")
    ax.set_ylabel(r"$\|x\|$")
    ax.legend(loc="upper left", bbox_to_anchor=(-0.02, -0.2), fontsize=9, frameon=False)
    for k in range(data.sim_norm.shape[1]):
        bx.plot(data.sim_psi, data.sim_norm[:, k] / A, color="tab:blue", lw=1)
    bx.axhline(1.0, color="tab:green", lw=2, label=r"$\|x\| = A$")
    bx.plot([], [], color="tab:blue", label=r"motions from $0.99\,\lambda_0$")
    bx.set_xlabel("revolutions after the start")
    bx.set_ylabel(r"$\|x\| / A$")
    bx.set_ylim(0, 1.1 * max(1.0, float(data.sim_norm.max() / A)))
    bx.legend(loc="upper left", bbox_to_anchor=(-0.02, -0.2), fontsize=9, frameon=False)
    return finish(fig)
