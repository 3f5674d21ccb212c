"""Chapter 5 of the book, hover (``book/05_hover.ipynb``, the paper's Figs 4 and 5): the
hover trim of the C.G. sweep and its aft limit, the linear modes, the algorithm in both
readings, ``W'`` against the C.G. and where linear theory turns unstable.

The conventions every chapter's module follows (data objects, ``summary()``, ``facts()``,
``plot_*`` and ``figure_*``) are in :mod:`rotorlyap.chapters`. Every quantity computed in a reading carries
that reading's label, :data:`rotorlyap.chapters.cases.READING_LABELS`. The cases, their
parameters and the labels shared with chapter 6 are in :mod:`rotorlyap.chapters.cases`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from ..analysis.functions import energy_function, energy_rate_terms
from ..analysis.stability import blade_stability
from ..conventions import DEFAULT_A, DEFAULT_SCALES, PAPER_TEST_DISTURBANCES
from ..errors import TrimError
from ..methods.sampling import sphere_extremum, unit_sphere_points
from ..model.blade import Blade
from ..model.modes import Mode, hover_modes, least_damped, pitch_mode
from ..model.parameters import CG_POSITIONS
from ..model.trim import hover_trim
from ..reporting import Rounded, format_small
from .cases import _HINGES, CASES, READING_LABELS, _Count, _line, case_params, disturbance_names
from .style import CG_COLORS, HINGE_COLORS, HINGE_LINESTYLES, finish, subplots

__all__ = [
    "cg_sweep",
    "HoverSweep", "hover_sweep",
    "HoverTrimData", "hover_trim_data", "plot_hover_trim", "figure_hover_trim",
    "TrimLimitData", "trim_limit_data",
    "HoverModesData", "hover_modes_data",
    "HoverReadingsData", "hover_readings_data", "SearchCheckData", "search_check",
    "HoverRateData", "hover_rate_data", "plot_hover_rate", "figure_hover_rate",
    "HoverDivergenceData", "hover_divergence_data",
]


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
        :data:`~rotorlyap.chapters.cases.READING_LABELS` of the two readings.
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
