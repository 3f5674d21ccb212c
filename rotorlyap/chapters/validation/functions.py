"""Chapter 7 ("Validation and beyond"): the quadratic Liapunov functions (:func:`quadratic_data`)
and ``W'`` near the origin (:func:`origin_data`), with its figure."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from ...analysis.functions import energy_function, optimised_quadratic_function, quadratic_function
from ...conventions import DEFAULT_SCALES
from ...methods.sampling import sphere_extremum, unit_sphere_points
from ...model.blade import Blade
from ...model.parameters import BladeParameters
from ..scans import _join, _legend_height
from ..style import finish, subplots
from .steady import SteadyMotions

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["QuadraticData", "quadratic_data", "OriginData", "origin_data", "plot_origin", "figure_origin"]


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
