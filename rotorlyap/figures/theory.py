"""Figures of the theorem and algorithm chapters: a data function and a drawing function each.

Data functions return frozen dataclasses of arrays (no plotting); drawing functions take
that data and a matplotlib ``Axes`` and draw it. Notebooks call both, and print a rounded
summary of the data so that nbval checks what the figure shows.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..methods.examples import PeriodicSystem
from ..methods.lyapunov import TechnicalStabilityResult, technical_stability
from ..methods.simulation import simulate

__all__ = [
    "PhasePortraitData", "phase_portrait_data", "plot_phase_portrait",
    "NormHistoryData", "norm_history_data", "plot_norm_history",
    "LevelSetData", "level_set_data", "plot_level_sets",
    "ConvergenceData", "convergence_data", "plot_convergence",
    "plot_start_region", "plot_max_norm",
]


def _circle(radius: float, scales: np.ndarray, n: int = 361) -> np.ndarray:
    t = np.linspace(0, 2 * np.pi, n)
    return radius * np.stack([np.cos(t), np.sin(t)], axis=1) * scales[:2]


@dataclass(frozen=True)
class PhasePortraitData:
    """Motions in the state plane of a 2-state system, with the bounds of the theorem.

    Attributes
    ----------
    psi0 : float
        Start azimuth.
    A, lambda0 : float
        Bound after step 3 and the start-region radius at ``psi0``.
    inside : numpy.ndarray
        Motions started just inside ``lambda0``, shape ``(k, m, 2)``.
    outside : tuple of numpy.ndarray
        Motions started outside ``A``, each of shape ``(k_i, 2)`` (an escaping motion is
        stopped when its norm reaches ``escape``).
    outside_escaped : tuple of bool
        Whether each of those motions escaped (left the norm ``escape``).
    circle_A, circle_lambda0 : numpy.ndarray
        The two circles of the scaled norm, shape ``(361, 2)``.
    """

    psi0: float
    A: float
    lambda0: float
    inside: np.ndarray
    outside: tuple
    outside_escaped: tuple
    circle_A: np.ndarray
    circle_lambda0: np.ndarray


def phase_portrait_data(
    system: PeriodicSystem,
    result: TechnicalStabilityResult,
    j: int = 0,
    *,
    n_starts: int = 8,
    n_periods: float = 6.0,
    outside_starts=((0.8, 0.5), (0.0, 1.0)),
    escape: float = 3.0,
) -> PhasePortraitData:
    """Simulate motions from the certified start region and some from outside ``A``.

    Parameters
    ----------
    system : PeriodicSystem
        A 2-state system (see :mod:`rotorlyap.methods.examples`).
    result : TechnicalStabilityResult
        Its certificate from :func:`rotorlyap.technical_stability`.
    j : int
        Index of the start azimuth in ``result.psi``.
    n_starts : int
        Starts equally spaced on the circle of radius ``0.99 lambda0_j``.
    n_periods : float
        Simulated length.
    outside_starts : sequence of pairs
        Initial states of the motions started outside ``A``.
    escape : float
        Norm at which a motion counts as escaped and is stopped.
    """
    psi0 = float(result.psi[j])
    lam = float(result.lambda0[j])
    t = 2 * np.pi * np.arange(n_starts) / n_starts
    x0 = 0.99 * lam * np.stack([np.cos(t), np.sin(t)], axis=1) * result.scales
    inside = simulate(system.f, x0, psi0, n_periods, period=system.period, scales=result.scales)
    outs, escaped = [], []
    for start in outside_starts:
        out = simulate(
            system.f, np.asarray(start, dtype=float)[None, :], psi0, n_periods,
            period=system.period, scales=result.scales, escape=escape,
        )
        outs.append(out.x[:, 0, :])
        escaped.append(bool(out.escaped[0]))
    return PhasePortraitData(
        psi0=psi0, A=result.A, lambda0=lam, inside=inside.x, outside=tuple(outs),
        outside_escaped=tuple(escaped), circle_A=_circle(result.A, result.scales),
        circle_lambda0=_circle(lam, result.scales),
    )


def plot_phase_portrait(data: PhasePortraitData, ax, *, labels=("$y$", "$y'$")) -> None:
    """Draw :class:`PhasePortraitData` (in the spirit of the paper's lost Fig. 1)."""
    ax.fill(*data.circle_A.T, color="tab:green", alpha=0.08, lw=0)
    ax.plot(*data.circle_A.T, color="tab:green", lw=2, label=r"$\|x\| = A$ (bound)")
    ax.plot(*data.circle_lambda0.T, color="tab:blue", lw=2,
            label=rf"$\|x\| = \lambda_0(\psi_0)$, $\psi_0 = {np.degrees(data.psi0):.0f}^\circ$")
    for i in range(data.inside.shape[1]):
        ax.plot(*data.inside[:, i, :].T, color="0.35", lw=0.7,
                label="motions started inside $\\lambda_0$" if i == 0 else None)
        ax.plot(*data.inside[0, i, :], "o", color="tab:blue", ms=3)
    for path, esc in zip(data.outside, data.outside_escaped):
        color = "tab:red" if esc else "tab:purple"
        ax.plot(*path.T, color=color, lw=1.2,
                label="started outside $A$, " + ("escapes" if esc else "stays bounded"))
        ax.plot(*path[0], "o", color=color, ms=4)
    lim = max(2.5 * data.A, 1.3 * max(float(np.abs(p[0]).max()) for p in data.outside))
    ax.set_xlim(-lim, lim)
    ax.set_ylim(-lim, lim)
    ax.set_xlabel(labels[0])
    ax.set_ylabel(labels[1])
    ax.set_aspect("equal")
    ax.legend(loc="upper right", fontsize=7, framealpha=0.9)


@dataclass(frozen=True)
class NormHistoryData:
    """Norm of simulated motions against azimuth, with ``A`` and ``lambda0(psi)``.

    Attributes
    ----------
    psi_grid, lambda0 : numpy.ndarray
        The certificate's azimuths and start radii.
    A : float
        The bound.
    psi : list of numpy.ndarray
        For each start azimuth, the output azimuths (shape ``(k,)``).
    norm : list of numpy.ndarray
        For each start azimuth, norms of its motions, shape ``(k, m)``.
    max_ratio : float
        Largest ``||x|| / A`` over all motions: below 1 is the theorem's conclusion.
    """

    psi_grid: np.ndarray
    lambda0: np.ndarray
    A: float
    psi: list
    norm: list
    max_ratio: float


def norm_history_data(
    system: PeriodicSystem,
    result: TechnicalStabilityResult,
    start_indices,
    *,
    n_starts: int = 32,
    n_periods: float = 20.0,
    fraction: float = 0.999,
    seed: int = 0,
) -> NormHistoryData:
    """Simulate motions started on ``fraction * lambda0`` at several azimuths.

    Start directions are spread deterministically on the sphere (a seeded generator), so
    the same call gives the same motions.
    """
    rng = np.random.default_rng(seed)
    n = result.scales.size
    psis, norms, worst = [], [], 0.0
    for j in start_indices:
        u = rng.normal(size=(n_starts, n))
        u /= np.linalg.norm(u, axis=1, keepdims=True)
        x0 = fraction * result.lambda0[j] * u * result.scales
        sim = simulate(system.f, x0, result.psi[j], n_periods, period=system.period, scales=result.scales)
        psis.append(sim.psi)
        norms.append(sim.norm)
        worst = max(worst, float(sim.max_norm.max()) / result.A)
    return NormHistoryData(result.psi, result.lambda0, result.A, psis, norms, worst)


def plot_norm_history(data: NormHistoryData, ax, *, unit: str = "rev") -> None:
    """Draw :class:`NormHistoryData` (in the spirit of the paper's lost Fig. 2)."""
    period = 2 * np.pi
    end = max(p[-1] for p in data.psi)
    reps = int(np.ceil(end / period)) + 1
    grid = np.concatenate([data.psi_grid + k * period for k in range(reps)])
    lam = np.tile(data.lambda0, reps)
    ax.axhline(data.A, color="tab:green", lw=2, label="$A$")
    ax.fill_between(grid / period, 0, lam, color="tab:blue", alpha=0.25, step="mid",
                    label=r"start region $\|x\| < \lambda_0(\psi)$")
    colors = ["0.2", "tab:orange", "tab:purple", "tab:brown", "tab:olive"]
    for i, (p, nrm) in enumerate(zip(data.psi, data.norm)):
        ax.plot(p / period, nrm, color=colors[i % len(colors)], lw=0.4, alpha=0.6)
        ax.plot(p[0] / period, nrm[0, 0], "o", color=colors[i % len(colors)], ms=4,
                label=rf"starts at $\psi_0 = {np.degrees(p[0]):.0f}^\circ$")
    ax.set_xlim(0, end / period)
    ax.set_ylim(0, 1.15 * data.A)
    ax.set_xlabel(r"azimuth $\psi$ / $2\pi$ (periods)")
    ax.set_ylabel(r"scaled norm $\|x(\psi)\|$")
    ax.legend(loc="upper right", fontsize=8, ncol=2)


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


def plot_level_sets(data: LevelSetData, ax, *, labels=("$y$", "$y'$")) -> None:
    """Draw the sign of ``W'``, the level set ``W = alpha`` and the three circles."""
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
    ax.set_title(rf"$\psi = {np.degrees(data.psi):.0f}^\circ$")
    ax.legend(loc="lower left", fontsize=7)


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


def convergence_data(system: PeriodicSystem, A: float, n_sphere_values, *, n_psi: int = 24) -> ConvergenceData:
    """Run :func:`technical_stability` at several sampling resolutions, with and without refinement."""
    rows, raw = [], []
    for ns in n_sphere_values:
        r = technical_stability(system.f, system.W, A, dim=system.dim, dW=system.dW, n_psi=n_psi, n_sphere=int(ns))
        rows.append((r.A, r.alpha, r.lambda0.min(), r.lambda0.mean()))
        q = technical_stability(system.f, system.W, A, dim=system.dim, dW=system.dW, n_psi=n_psi,
                                n_sphere=int(ns), n_iter=0)
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


def plot_start_region(result: TechnicalStabilityResult, ax) -> None:
    """Draw ``lambda0(psi)`` and ``A`` (left axis) and the step-6 ``max W'`` (right axis)."""
    deg = np.degrees(result.psi)
    ax.plot(deg, result.lambda0, "o-", ms=3, color="tab:blue", label=r"$\lambda_0(\psi_j)$ (step 5)")
    ax.axhline(result.A, color="tab:green", lw=2, label="$A$ after step 3")
    ax.axhline(result.A_requested, color="0.5", ls="--", label="requested $A$")
    ax.set_ylim(0, 1.1 * result.A_requested)
    ax.set_xlabel(r"azimuth $\psi_j$ (deg)")
    ax.set_ylabel("scaled norm")
    ax.set_xticks(np.arange(0, 361, 45))
    ax2 = ax.twinx()
    ax2.plot(deg, result.max_dW, "-", color="tab:red", lw=1, label=r"max $W'$ on the shell (step 6)")
    ax2.axhline(0, color="tab:red", lw=0.5, ls=":")
    ax2.set_ylabel(r"max $W'$ on $\lambda_0 < \|x\| \leq A$", color="tab:red")
    lines = ax.get_legend_handles_labels()
    lines2 = ax2.get_legend_handles_labels()
    ax.legend(lines[0] + lines2[0], lines[1] + lines2[1], loc="center left", fontsize=8)


def plot_max_norm(data: NormHistoryData, ax) -> None:
    """Draw the largest ``||x|| / A`` of every simulated motion against its start azimuth."""
    for p, nrm in zip(data.psi, data.norm):
        ratio = nrm.max(axis=0) / data.A
        ax.plot(np.full(ratio.size, np.degrees(p[0])), ratio, "o", color="0.3", ms=3, alpha=0.5)
    ax.axhline(1.0, color="tab:green", lw=2, label=r"$\|x\| = A$")
    lam = np.interp([np.degrees(p[0]) for p in data.psi], np.degrees(data.psi_grid), data.lambda0)
    ax.plot([np.degrees(p[0]) for p in data.psi], lam / data.A, "_", color="tab:blue", ms=14, mew=2,
            label=r"start radius $\lambda_0(\psi_0) / A$")
    ax.plot([], [], "o", color="0.3", ms=3, label="largest $\\|x\\| / A$ of one motion")
    ax.set_ylim(0, 1.1)
    ax.set_xlabel(r"start azimuth $\psi_0$ (deg)")
    ax.set_ylabel(r"$\max_{\psi \geq \psi_0} \|x(\psi)\| / A$")
    ax.set_xticks(np.arange(0, 361, 45))
    ax.legend(loc="lower right", fontsize=8)
