"""Figures of chapter 1, the theorem of technical stability: data, summaries, facts, drawings.

The conventions every chapter's module follows (data objects, ``summary()``, ``facts()``,
``plot_*`` and ``figure_*``) are in :mod:`rotorlyap.chapters`.

The chapter's figures: the phase portrait (:func:`phase_portrait_data`,
:func:`figure_phase_portrait`) and the norm of motions against azimuth
(:func:`~rotorlyap.chapters.norm_history.norm_history_data`, which chapter 2 uses too and which
lives in :mod:`rotorlyap.chapters.norm_history`, with :func:`figure_norm_history`). The
certificate itself (:class:`rotorlyap.methods.lyapunov.TechnicalStabilityResult`) is summarised
by :func:`certificate_summary`. All quantities are dimensionless (the systems of
:mod:`rotorlyap.methods.examples`); azimuths are in radians unless a name ends in ``_deg``.
Every number is rounded to the digits the search or integration behind it determines
(:mod:`rotorlyap.reporting`): three or four decimals.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from ..methods.examples import PeriodicSystem
from ..methods.lyapunov import TechnicalStabilityResult
from ..methods.simulation import simulate
# the chapter's notebook calls norm_history_data (of chapters 1 and 2) from this module
from .norm_history import NormHistoryData, _circle, norm_history_data  # noqa: F401
from .style import finish, subplots

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = [
    "certificate_summary",
    "PhasePortraitData", "phase_portrait_data", "plot_phase_portrait", "figure_phase_portrait",
    "plot_norm_history", "figure_norm_history",
]


def certificate_summary(result: TechnicalStabilityResult) -> str:
    """The certificate in two lines: its message, then ``A``, ``alpha`` and the range of ``lambda0``.

    Parameters
    ----------
    result : TechnicalStabilityResult
        From :func:`rotorlyap.technical_stability`.

    Returns
    -------
    str
        ``A`` and ``alpha`` (scaled norm and units of ``W``, dimensionless here) to four
        decimals, ``lambda0`` to three significant digits (a start radius searched where ``W`` has
        no closed form is determined to 0.1 %, :data:`rotorlyap.methods.lyapunov.BOUND_RTOL`).
    """
    return (
        f"{result.message}\n"
        f"A = {result.A:.4f}, alpha = {result.alpha:.4f}, "
        f"lambda0 from {np.min(result.lambda0):.3g} to {np.max(result.lambda0):.3g}"
    )


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

    @property
    def max_inside_norm(self) -> float:
        """Largest Euclidean norm, in the plotted coordinates ``(y, y')``, of the motions started inside."""
        return float(np.sqrt((self.inside**2).sum(axis=2)).max())

    def summary(self) -> str:
        """``A`` and the largest norm reached from inside (four decimals), ``lambda0(psi0)`` (three
        significant digits, as :func:`certificate_summary`), and
        for each motion started outside ``A`` its start (two decimals) and whether it escaped."""
        lines = [
            "phase portrait: A = %.4f, lambda0(psi0) = %.3g" % (self.A, self.lambda0),
            "largest norm of the motions started inside lambda0: %.4f" % self.max_inside_norm,
        ]
        for path, esc in zip(self.outside, self.outside_escaped):
            lines.append("motion started at (y, y') = (%.2f, %.2f): %s" % (*path[0], "escapes" if esc else "bounded"))
        return "\n".join(lines)


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
    # under the axes, not over the motions, two columns (readable at phone width)
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=2, fontsize=9, frameon=False,
              borderaxespad=0.0)


def figure_phase_portrait(data: PhasePortraitData, *, title: str | None = None) -> Figure:
    """A new 6 x 7 in figure of :class:`PhasePortraitData` (:func:`plot_phase_portrait`), the
    state plane at equal aspect, the legend under the axes.

    Parameters
    ----------
    data : PhasePortraitData
    title : str, optional
        Axes title (the system's name, say).

    Returns
    -------
    matplotlib.figure.Figure
        Laid out and already closed in pyplot (a notebook shows it only where it is glued).
    """
    fig, ax = subplots(figsize=(6, 7))
    plot_phase_portrait(data, ax)
    if title is not None:
        ax.set_title(title, fontsize=10)
    return finish(fig)


def plot_norm_history(data: NormHistoryData, ax, *, unit: str = "rev") -> None:
    """Draw :class:`~rotorlyap.chapters.norm_history.NormHistoryData` (in the spirit of the paper's lost Fig. 2)."""
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
    ax.set_ylim(0, 1.6 * data.A)  # room above A for the legend
    ax.set_xlabel(r"azimuth $\psi$ / $2\pi$ (periods)")
    ax.set_ylabel(r"scaled norm $\|x(\psi)\|$")
    ax.legend(loc="upper right", fontsize=8, ncol=3, columnspacing=1.0, handlelength=1.5)


def figure_norm_history(data: NormHistoryData) -> Figure:
    """A new 7 x 3.6 in figure of :class:`~rotorlyap.chapters.norm_history.NormHistoryData`
    (:func:`plot_norm_history`), titled
    with the start radius.

    Returns
    -------
    matplotlib.figure.Figure
        Laid out and already closed in pyplot (a notebook shows it only where it is glued).
    """
    fig, ax = subplots(figsize=(7, 3.6))
    plot_norm_history(data, ax)
    ax.set_title(rf"Norm of motions started on ${data.fraction:g}\,\lambda_0(\psi_0)$")
    return finish(fig)
