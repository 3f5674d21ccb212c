"""Chapter 6, forward flight: the loads the reused hover equilibrium leaves unbalanced, ``W`` on
spheres about it (the paper's Fig. 6) and ``W'`` against the azimuth (the paper's Fig. 7), each
in both readings (:data:`rotorlyap.chapters.cases.READING_LABELS`).

Part of :mod:`rotorlyap.chapters.forward_flight`, which re-exports its names.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...analysis.functions import energy_function
from ...conventions import DEFAULT_A, DEFAULT_SCALES, PAPER_TEST_DISTURBANCES
from ...methods.sampling import sphere_extremum, unit_sphere_points
from ...model.blade import Blade
from ...reporting import format_small
from ..cases import _HINGES, READING_LABELS, STATE_LABELS, _Count, _line, case_params, disturbance_names
from ..style import finish, subplots

__all__ = [
    "UnbalancedLoadsData", "unbalanced_loads_data",
    "WSpheresData", "w_spheres_data", "plot_w_spheres", "figure_w_spheres",
    "RateAzimuthData", "rate_azimuth_data", "plot_rate_azimuth", "figure_rate_azimuth",
]


def _colormaps():
    import matplotlib

    return matplotlib.colormaps


def _plain(tex: str) -> str:
    """A state or axis name of a plot label (``"+\\beta'"``, ``"$\\zeta$"``) in plain text for a
    printout (``"+beta'"``, ``"zeta"``): TeX is for the figures only."""
    return tex.replace("$", "").replace("\\", "")


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
