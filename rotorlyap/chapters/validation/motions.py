"""Chapter 7 ("Validation and beyond"), section 5: what the motion does where a reading marks
instability (:func:`motion_data`), the flutter limit cycle (:func:`flutter_cycle`) and the distant
periodic motion (:func:`far_motion`) of the long simulations."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from ...analysis.floquet import blade_floquet
from ...conventions import DEFAULT_A, DEFAULT_SCALES
from ...methods.simulation import scaled_norm, simulate
from ...methods.validation import last_revolution, long_run
from ...model.blade import Blade
from ...model.modes import derived_quantities
from ...model.parameters import BladeParameters
from ...model.steady import disturbed_rhs, periodic_motion
from ...reporting import Rounded, decade_above, format_small
from ..scans import _join
from ..style import figure, finish
from .common import _verdicts_in_words, max_distance

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = [
    "MotionData", "motion_data", "plot_motions", "figure_motions", "points_per_revolution",
    "FlutterCycle", "flutter_cycle", "FarMotion", "far_motion",
]


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
        :func:`~rotorlyap.chapters.validation.common.max_distance` of the hover equilibrium from it, norm units.
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
