"""Figures of the reproduction chapters (the paper's Figs 4-8): a data function and a drawing
function each.

Data functions return frozen dataclasses of arrays (no plotting) and take their grids as
arguments, so that the notebooks, the benchmark and the tests can choose the resolution;
drawing functions take that data and matplotlib ``Axes``. Every quantity computed in a
reading carries that reading's label, :data:`READING_LABELS`: the strict reading (suprema
and infima over whole spheres, the theorem as stated) is a certificate as far as the search
is exhaustive; the practical reading (``W`` and ``W'`` only along test disturbances) is an
indicator, never a certificate.

Conventions (``.notes/BLADE_SPEC.md``): azimuth ``psi = 0`` with the blade pointing aft
(over the tail), rotation counter-clockwise seen from above, so ``psi = 90 deg`` is the
advancing side and ``psi = 270 deg`` the retreating side.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..analysis.functions import energy_function, energy_rate_terms
from ..analysis.stability import blade_stability
from ..conventions import DEFAULT_A, DEFAULT_SCALES, PAPER_TEST_DISTURBANCES
from ..methods.sampling import sphere_extremum, unit_sphere_points
from ..model.blade import Blade
from ..model.parameters import CG_POSITIONS, BladeParameters
from ..model.trim import hover_trim
from .export import markdown_table  # noqa: F401  (chapter 6 writes its tables with it)
from .style import CATEGORY_COLORS

__all__ = [
    "READING_LABELS", "CASES", "MU_GRID", "MU_GRID_STRICT", "STATE_LABELS",
    "FLAP_LAG_TEST_DISTURBANCES", "AXES_AND_DIAGONALS",
    "case_params", "balanced_scales", "practical_threshold_mu", "reverse_flow_boundary",
    "HoverTrimData", "hover_trim_data", "plot_hover_trim",
    "HoverRateData", "hover_rate_data", "plot_hover_rate",
    "WSpheresData", "w_spheres_data", "plot_w_spheres",
    "RateAzimuthData", "rate_azimuth_data", "plot_rate_azimuth",
    "RegionsData", "regions_data", "plot_regions_polar", "plot_regions_plane",
    "CATEGORY_NAMES", "SensitivityData", "sensitivity_data", "plot_sensitivity",
    "ConvergenceData", "convergence_data", "plot_convergence",
    "markdown_table",
]

#: How each reading is labelled everywhere in the book.
READING_LABELS = {
    "strict": "strict (certificate)",
    "practical": "practical (indicator, not a certificate)",
}

#: The paper's three cases (Table I computation parameters), in order.
CASES = ("forward", "neutral", "backward")

#: Advance ratios of Fig. 8 in the practical reading: 0 to 0.25, finer near hover.
MU_GRID = (0.0, 0.0125, 0.025, 0.05, 0.075, 0.1, 0.125, 0.15, 0.175, 0.2, 0.225, 0.25)

#: Advance ratios of Fig. 8 in the strict reading (each costs a sphere search per azimuth).
MU_GRID_STRICT = (0.0, 0.05, 0.1, 0.15, 0.2, 0.25)

# TeX labels of the six state components (plot labels; kept out of the API page).
STATE_LABELS = (r"$\beta$", r"$\zeta$", r"$\theta$", r"$\beta'$", r"$\zeta'$", r"$\theta'$")

#: Test disturbances without the pitch rate: the eight signed flap and lag axes.
FLAP_LAG_TEST_DISTURBANCES = PAPER_TEST_DISTURBANCES[[0, 1, 3, 4, 6, 7, 9, 10]]
FLAP_LAG_TEST_DISTURBANCES.setflags(write=False)

#: The 12 signed axes and the 60 signed diagonals of the coordinate planes.
AXES_AND_DIAGONALS = unit_sphere_points(6, 0)

_HINGES = ("flap", "lag", "pitch")


def case_params(cg, **overrides) -> BladeParameters:
    """Table I parameters for a named case ("forward", ...) or a C.G. position (fraction of chord)."""
    if isinstance(cg, str):
        return BladeParameters.table_i(cg, **overrides)
    return replace(BladeParameters.table_i("forward", **overrides), cg_position=float(cg))


def _colormaps():
    import matplotlib

    return matplotlib.colormaps


class _Count:
    """Wrap a vectorised ``g(psi, x)`` and count the states it is evaluated at."""

    def __init__(self, fun):
        self.fun, self.n = fun, 0

    def __call__(self, psi, x):
        self.n += int(np.asarray(x).shape[0])
        return self.fun(psi, x)


def balanced_scales(params: BladeParameters, scales=None) -> np.ndarray:
    """Norm scales that give every signed axis the same energy ``W`` at ``||x|| = 1``.

    Each ``a_i`` of ``scales`` (default :data:`DEFAULT_SCALES`) is multiplied by
    ``sqrt(W_ref / W_i)``, with ``W_i`` the mean of ``W`` at ``+a_i e_i`` and ``-a_i e_i``
    about the hover equilibrium and ``W_ref`` their geometric mean (``W`` is nearly
    quadratic at these amplitudes, so one correction suffices).
    """
    a = np.array(DEFAULT_SCALES if scales is None else scales, dtype=float)
    blade = Blade(params, 0.0)
    fun = energy_function(blade)
    eye = np.eye(6)
    w = 0.5 * (fun.W(0.0, eye * a) + fun.W(0.0, -eye * a))
    ref = float(np.exp(np.mean(np.log(w))))
    return a * np.sqrt(ref / w)


def reverse_flow_boundary(params: BladeParameters, psi: np.ndarray) -> np.ndarray:
    """Advance ratio above which reverse flow reaches the blade root, at each azimuth.

    The reverse-flow region is ``r/R < mu |sin psi|`` on the retreating side
    (``180 < psi < 360`` deg); it reaches the aerodynamic span, which starts at
    ``r/R = (R - R1)/R``, when ``mu > (R - R1)/(R |sin psi|)``. Returns ``inf`` on the
    advancing side.
    """
    psi = np.asarray(psi, dtype=float)
    s = -np.sin(psi)
    with np.errstate(divide="ignore"):
        return np.where(s > 1e-12, params.root_r_over_R / np.where(s > 1e-12, s, 1.0), np.inf)


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
    """Left: the cases' angles as grouped bars; right: the C.G. sweep (deg)."""
    ax, ax2 = axes
    names = ("collective", r"flap $\beta$", r"lag $\zeta$", r"pitch $\theta$")
    vals = np.degrees(np.column_stack([data.case_collective, data.case_equilibrium]))
    colors = ("tab:blue", "0.45", "tab:red")
    w = 0.26
    xs = np.arange(len(names))
    for i, (case, c) in enumerate(zip(data.case_names, colors)):
        bars = ax.bar(xs + (i - 1) * w, vals[i], w, color=c,
                      label=f"{case} C.G. ({data.case_cg[i]:.3g} c)")
        for b, v in zip(bars, vals[i]):
            ax.text(b.get_x() + b.get_width() / 2, v + 0.15, f"{v:.1f}", ha="center", fontsize=6.5)
    ax.set_xticks(xs, names)
    ax.set_ylabel("angle (deg)")
    ax.set_title("hover trim of the three cases (thrust = weight)", fontsize=10)
    ax.legend(fontsize=7.5, loc="upper left")
    ax.set_ylim(0, 1.15 * vals.max())
    series = (np.degrees(data.collective),) + tuple(np.degrees(data.equilibrium.T))
    for s, name, style in zip(series, names, ("o-", "s-", "^-", "d-")):
        ax2.plot(data.cg, s, style, ms=4, label=name)
    ax2.axvline(data.pitch_axis, color="0.5", ls="--", lw=0.8)
    ax2.axvline(data.aerodynamic_centre, color="tab:green", ls=":", lw=1)
    y = ax2.get_ylim()[1]
    ax2.text(data.pitch_axis, y, " pitch axis", fontsize=7, va="top", color="0.4")
    ax2.text(data.aerodynamic_centre, 0.93 * y, "aero. centre ", fontsize=7, va="top", ha="right",
             color="tab:green")
    ax2.set_xlabel("section C.G. position (fraction of chord behind the leading edge)")
    ax2.set_ylabel("angle (deg)")
    ax2.set_title("C.G. sweep", fontsize=10)
    ax2.legend(fontsize=7.5, loc="lower left")


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
        :data:`READING_LABELS` of the two readings.
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


def plot_hover_rate(data: HoverRateData, axes) -> None:
    """Four panels: (a) ``W'`` against the C.G. in both readings; (b) the linear verdict;
    (c) the sign of ``W'`` on the (pitch, flap-rate) plane; (d) which work rates make the
    strict maximum positive."""
    ax_a, ax_b, ax_c, ax_d = axes
    cg = data.cg
    ax_a.plot(cg, data.strict_max, "o-", color="tab:red",
              label=f"{data.strict_label}: max $W'$ on the sphere")
    ax_a.plot(cg, data.practical_max, "s-", color="tab:blue",
              label=f"{data.practical_label}: max $W'$ over the 12 axes")
    rate_idx = [i for i, d in enumerate(data.test_disturbances) if np.abs(d[3:]).max() > 0.5]
    for i in rate_idx:
        k = int(np.argmax(np.abs(data.test_disturbances[i])))
        sgn = "+" if data.test_disturbances[i, k] > 0 else "-"
        ax_a.plot(cg, data.practical_dW[:, i], ":", lw=1, color="tab:blue", alpha=0.6)
        ax_a.annotate(sgn + STATE_LABELS[k], (cg[-1], data.practical_dW[-1, i]), fontsize=6.5,
                      color="tab:blue", xytext=(3, 0), textcoords="offset points", va="center")
    ax_a.set_yscale("symlog", linthresh=10.0)
    ax_a.axhline(0, color="k", lw=0.6)
    ax_a.set_xlabel("section C.G. (fraction of chord)")
    ax_a.set_ylabel(r"$W'$ on $\|x\| = A$ (J/rad)")
    ax_a.set_title("(a) $W'$ in hover; dotted: each rate axis (practical)", fontsize=9)
    ax_a.legend(fontsize=6.5, loc="lower left")
    ax_b.plot(cg, data.eig_max_real, "o-", color="k", label="least-damped mode (largest real part)")
    if np.isfinite(data.eig_real_root).any():
        ax_b.plot(cg, data.eig_real_root, "^--", color="tab:purple", label="largest real root (divergence if > 0)")
    ax_b.axhline(0, color="k", lw=0.6)
    ax_b.fill_between(cg, 0, max(0.05, 1.1 * float(np.nanmax(data.eig_max_real))), color="tab:red", alpha=0.07)
    for c, r, f in zip(cg, data.eig_max_real, data.eig_freq):
        ax_b.annotate(f"{f:.2f}/rev", (c, r), fontsize=6, xytext=(0, 5), textcoords="offset points", ha="center")
    ax_b.set_xlabel("section C.G. (fraction of chord)")
    ax_b.set_ylabel(r"eigenvalue real part ($\Omega$)")
    ax_b.set_title("(b) linearised hover: unstable above zero", fontsize=9)
    ax_b.legend(fontsize=7, loc="upper left")
    ext = [data.slice_theta[0], data.slice_theta[-1], data.slice_betadot[0], data.slice_betadot[-1]]
    from matplotlib.colors import TwoSlopeNorm

    lo, hi = float(data.slice_dW.min()), float(data.slice_dW.max())
    norm = TwoSlopeNorm(vmin=min(lo, -1e-9), vcenter=0.0, vmax=max(hi, 1e-9))
    im = ax_c.imshow(data.slice_dW, origin="lower", extent=ext, cmap="RdBu_r", norm=norm, aspect="auto")
    ax_c.contour(data.slice_theta, data.slice_betadot, data.slice_dW, levels=[0.0], colors="k", linewidths=1)
    ax_c.contourf(data.slice_theta, data.slice_betadot, data.slice_dW > 0, levels=[0.5, 1.5], colors="none",
                  hatches=["...."])
    t = np.linspace(0, 2 * np.pi, 361)
    ax_c.plot(data.A * np.cos(t), data.A * np.sin(t), color="tab:green", lw=1.5, label=r"$\|x\| = A$")
    ax_c.set_xlabel(r"pitch displacement $\theta / a_\theta$")
    ax_c.set_ylabel(r"flap rate $\beta' / a_{\beta'}$")
    ax_c.set_title(f"(c) $W'$ on the ($\\theta$, $\\beta'$) plane, C.G. {data.slice_cg:.3g} c (dotted: $W' > 0$)", fontsize=9)
    ax_c.legend(fontsize=7, loc="upper right")
    cb = ax_c.figure.colorbar(im, ax=ax_c, label="$W'$ (J/rad); two linear scales either side of 0", shrink=0.85)
    cb.set_ticks([lo, 0.5 * lo, 0.0, 0.5 * hi, hi])
    cb.set_ticklabels([f"{v:.0f}" for v in (lo, 0.5 * lo, 0.0, 0.5 * hi, hi)])
    width = 0.8 / len(cg)
    xs = np.arange(6)
    vals = np.concatenate([data.terms_damping, data.terms_aero], axis=1)
    cmap = _colormaps()["viridis"]
    for i, c in enumerate(cg):
        ax_d.bar(xs + (i - (len(cg) - 1) / 2) * width, vals[i], width, color=cmap(i / max(len(cg) - 1, 1)),
                 label=f"{c:.3g} c")
    ax_d.set_xticks(xs, [f"damper\n{h}" for h in _HINGES] + [f"aero\n{h}" for h in _HINGES], fontsize=7)
    ax_d.axhline(0, color="k", lw=0.6)
    ax_d.set_ylabel("work rate at the strict argmax (J/rad)")
    ax_d.set_title("(d) why $W' > 0$: work rates per hinge", fontsize=9)
    ax_d.legend(fontsize=6, ncol=2, title="C.G.", title_fontsize=6.5)


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


def w_spheres_data(cg="forward", mu: float = 0.15, A_values=(0.5, 1.0, 2.0, 4.0, 8.0), *, n_psi: int = 72,
                   n_sphere: int = 1024, scales=None, test_disturbances=PAPER_TEST_DISTURBANCES,
                   seed: int = 0) -> WSpheresData:
    """Compute :class:`WSpheresData` for the energy function about the hover equilibrium."""
    a = np.array(DEFAULT_SCALES if scales is None else scales, dtype=float)
    p = case_params(cg)
    xi = Blade(p, 0.0).equilibrium()
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
                        strict_label=READING_LABELS["strict"], practical_label=READING_LABELS["practical"], n_evaluations=w.n)


def plot_w_spheres(data: WSpheresData, axes) -> None:
    """Left: inf and sup of ``W`` against azimuth for each ``A`` (log scale); right: the same
    divided by ``A^2``, against ``A``."""
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
    ax.plot([], [], "k-", label=f"inf / sup over the sphere: {data.strict_label}")
    ax.plot([], [], "k--", label=f"min / max over the 12 axes: {data.practical_label}")
    ax.set_yscale("log")
    ax.set_xlabel(r"azimuth $\psi$ (deg)")
    ax.set_ylabel(r"$W(\psi, x)$ on $\|x\| = A$ (J)")
    ax.set_xticks(np.arange(0, 361, 90))
    ax.set_title(f"(a) $W$ at $\\mu$ = {data.mu:g}, {data.cg} C.G.", fontsize=9)
    ax.legend(fontsize=6.5, loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=4)
    A = data.A_values
    for arr, style, lab in ((data.strict_inf, "o-", "inf (sphere)"), (data.strict_sup, "s-", "sup (sphere)"),
                            (data.practical_min, "o--", "min (12 axes)"), (data.practical_max, "s--", "max (12 axes)")):
        ax2.plot(A, arr.mean(axis=1) / A ** 2, style, ms=4, label=lab)
    ax2.set_xscale("log", base=2)
    ax2.set_yscale("log")
    ax2.set_xlabel("bound $A$")
    ax2.set_ylabel(r"azimuth mean of $W / A^2$ (J)")
    ax2.set_title("(b) $W / A^2$: nearly constant, so $W \\propto A^2$", fontsize=9)
    ax2.legend(fontsize=7)


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
    smax, pmax, parg, n_eval = [], [], [], 0
    for mu in mu_values:
        dw = _Count(energy_function(Blade(p, mu), xi).dW)
        smax.append(sphere_extremum(dw, psi, A, a, dirs).value)
        vals = dw(np.repeat(psi, len(tests)), np.tile(A * tests * a, (n_psi, 1))).reshape(n_psi, -1)
        pmax.append(vals.max(axis=1))
        parg.append(vals.argmax(axis=1))
        n_eval += dw.n
    return RateAzimuthData(cg=cg, A=float(A), mu_values=np.asarray(mu_values, dtype=float), psi=psi,
                           strict_max=np.array(smax), practical_max=np.array(pmax),
                           practical_argmax=np.array(parg), test_disturbances=tests,
                           strict_label=READING_LABELS["strict"], practical_label=READING_LABELS["practical"], n_evaluations=n_eval)


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
        ax.text(90, 0.02, "advancing", transform=ax.get_xaxis_transform(), ha="center", fontsize=7, color="tab:orange")
        ax.text(270, 0.02, "retreating", transform=ax.get_xaxis_transform(), ha="center", fontsize=7, color="tab:blue")
        ax.set_xticks(np.arange(0, 361, 45))
        ax.set_xlim(0, 360)
        ax.set_xlabel(r"azimuth $\psi$ (deg)")
        where = "the sphere" if reading == "strict" else "the 12 axes"
        ax.set_ylabel(rf"max $W'$ over {where}, $\|x\| = A$ (J/rad)")
        ax.set_title((data.strict_label if reading == 'strict' else data.practical_label), fontsize=9)
    axes[0].legend(fontsize=7, ncol=2, loc="center right")


# --------------------------------------------------------------------------------------
# Fig. 8: regions of instability
# --------------------------------------------------------------------------------------

#: Categories of a (mu, psi) cell in :class:`RegionsData`.
CATEGORY_NAMES = (
    "stable: step 6 holds",
    "step 6 fails at this azimuth",
    "step 3 failed elsewhere (A1 = 0); W' <= 0 here on ||x|| = A",
    "step 3 failed (A1 = 0) and W' > 0 here on ||x|| = A",
)


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
        Index into :data:`CATEGORY_NAMES`, (k, m, n).
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


def _category_cmap():
    from matplotlib.colors import BoundaryNorm, ListedColormap

    return ListedColormap(CATEGORY_COLORS), BoundaryNorm(np.arange(-0.5, 4.5), 4)


def plot_regions_polar(data: RegionsData, ax, case_index: int = 0, *, title: str | None = None) -> None:
    """The verdict on the rotor disc seen from above: azimuth as angle, radius = mu.

    ``psi = 0`` points to the tail (bottom), rotation counter-clockwise, so the advancing
    side (``psi = 90 deg``) is on the right; hatched: where reverse flow reaches the
    blade root (``mu |sin psi| > (R - R1)/R`` on the retreating side). A
    ``mu = 0`` row (hover) is drawn as a central disc below ``r = 0``, so that the radius
    of every other row is exactly its advance ratio.
    """
    cmap, norm = _category_cmap()
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
    ax.pcolormesh(th_edges, r_edges, data.category[case_index], cmap=cmap, norm=norm, shading="flat")
    th = np.linspace(np.pi, 2 * np.pi, 361)
    rb = data.root_r_over_R / np.maximum(-np.sin(th), 1e-9)
    rmax = r_edges[-1]
    ok = rb <= rmax
    if ok.any():
        ax.fill_between(th[ok], rb[ok], rmax, facecolor="none", edgecolor="k", hatch="///", lw=0.0, alpha=0.6)
        ax.plot(th[ok], rb[ok], "k-", lw=0.8)
    ax.set_ylim(-hole, rmax)
    ticks = [m for m in (0.05, 0.1, 0.15, 0.2, 0.25) if m <= rmax]
    ax.set_yticks(ticks)
    ax.set_yticklabels([f"{m:g}" for m in ticks])
    ax.tick_params(axis="y", labelsize=6)
    ax.set_rlabel_position(135)
    ax.set_xticks(np.radians(np.arange(0, 360, 45)))
    names = {0: "0°\ntail", 90: "90°\nadvancing", 180: "nose\n180°", 270: "retreating\n270°"}
    ax.set_xticks(np.radians(np.arange(0, 360, 45)))
    ax.set_xticklabels([names.get(d, f"{d}°") for d in range(0, 360, 45)], fontsize=7)
    for lab in ax.get_xticklabels():
        if "advancing" in lab.get_text():
            lab.set_color("tab:orange")
        elif "retreating" in lab.get_text():
            lab.set_color("tab:blue")
    case = data.cases[case_index]
    ax.set_title(title or f"{case} C.G.", fontsize=9, pad=18)


def plot_regions_plane(data: RegionsData, ax, case_index: int = 0, *, title: str | None = None,
                       legend: bool = True) -> None:
    """The verdict in the (psi, mu) plane, with the reverse-flow boundary."""
    cmap, norm = _category_cmap()
    deg = np.degrees(data.psi)
    step = deg[1] - deg[0]
    ax.pcolormesh(np.concatenate([deg - step / 2, [deg[-1] + step / 2]]), _edges(data.mu_values, lo=0.0),
                  data.category[case_index], cmap=cmap, norm=norm, shading="flat")
    th = np.linspace(180, 360, 361)
    rb = data.root_r_over_R / np.maximum(-np.sin(np.radians(th)), 1e-9)
    top = _edges(data.mu_values, lo=0.0)[-1]
    ok = rb <= top
    if ok.any():
        ax.fill_between(th[ok], rb[ok], top, facecolor="none", edgecolor="k", hatch="///", lw=0.0, alpha=0.6)
        ax.plot(th[ok], rb[ok], "k-", lw=0.8)
    ax.axvline(180, color="k", lw=0.6, ls=":")
    ax.text(90, 1.01, "advancing", transform=ax.get_xaxis_transform(), ha="center", fontsize=7, color="tab:orange")
    ax.text(270, 1.01, "retreating", transform=ax.get_xaxis_transform(), ha="center", fontsize=7, color="tab:blue")
    ax.set_xlim(0, 360)
    ax.set_ylim(0, top)
    ax.set_xticks(np.arange(0, 361, 90))
    ax.set_xlabel(r"azimuth $\psi$ (deg)")
    ax.set_ylabel(r"advance ratio $\mu$")
    ax.set_title(title or f"{data.cases[case_index]} C.G.", fontsize=9, pad=12)
    if legend:
        from matplotlib.patches import Patch

        handles = [Patch(color=c, label=n) for c, n in zip(CATEGORY_COLORS, CATEGORY_NAMES)]
        handles.append(Patch(facecolor="none", edgecolor="k", hatch="///", label="reverse flow reaches the blade root"))
        ax.legend(handles=handles, fontsize=6.5, loc="upper left", bbox_to_anchor=(1.02, 1.0))


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


def sensitivity_data(cg="forward", mu_values=(0.0, 0.0125, 0.025, 0.05, 0.1, 0.15, 0.2, 0.25), variants: dict | None = None, *, n_psi: int = 72) -> SensitivityData:
    """Run the practical Fig. 8 for each variant: ``{name: dict(A=, scales=, test_disturbances=)}``.

    Default variants: the report's default (12 axes, A = 1, default scales); A = 0.5, 2 and 4;
    energy-balanced scales (:func:`balanced_scales`); the axes and pairwise diagonals; the
    flap and lag axes only (no pitch rate).
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
    """One (psi, mu) map per variant."""
    axes = np.ravel(axes)
    for k, (ax, name, reg) in enumerate(zip(axes, data.names, data.regions)):
        plot_regions_plane(reg, ax, 0, title=name, legend=False)
        if k % 4:
            ax.set_ylabel("")
    for ax in axes[len(data.names):]:
        from matplotlib.patches import Patch

        ax.axis("off")
        handles = [Patch(color=c, label=n) for c, n in zip(CATEGORY_COLORS, CATEGORY_NAMES)]
        handles.append(Patch(facecolor="none", edgecolor="k", hatch="///", label="reverse flow reaches the root"))
        ax.legend(handles=handles, fontsize=6.5, loc="center")
        break


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
                                        n_refine=16, n_iter=60).value[0]
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
                                    n_refine=16, n_iter=60).value[0]
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
    (c) the practical unstable fraction against mu for each azimuth grid."""
    ax_a, ax_b, ax_c = axes
    ns = np.where(data.n_sphere == 0, 1, data.n_sphere)
    dev = lambda v, ref: 100.0 * (v / ref - 1.0)  # noqa: E731
    for i, cg in enumerate(CASES):
        ax_a.plot(ns, dev(data.sup_dW_hover[i], data.sup_dW_hover[i, -1]), "o-", ms=4, label=f"{cg} C.G.")
    ax_a.set_xscale("log", base=2)
    ax_a.axhline(0, color="0.5", lw=0.6)
    ax_a.set_xlabel("quasi-random directions per sphere (1 = structured only)")
    ax_a.set_ylabel("strict max $W'$ in hover: deviation from finest (%)")
    ax_a.set_title("(a) sampling resolution", fontsize=9)
    ax_a.legend(fontsize=7)
    st = data.n_stations
    ax_b.plot(st, dev(data.sup_dW_stations, data.sup_dW_stations[-1]), "o-", label="strict max $W'$, hover")
    ax_b.plot(st, dev(data.practical_rate_stations, data.practical_rate_stations[-1]), "s-",
              label=rf"practical max $W'$, $\mu$ = {data.mu_check:g} (azimuth mean)")
    for i, cg in enumerate(CASES):
        ax_b.plot(st, dev(data.collective[i], data.collective[i, -1]), "^--", ms=4, label=f"collective, {cg}")
    ax_b.axhline(0, color="0.5", lw=0.6)
    ax_b.set_xlabel("spanwise stations")
    ax_b.set_ylabel("deviation from 24 stations (%)")
    ax_b.set_title("(b) spanwise stations", fontsize=9)
    ax_b.legend(fontsize=6.5)
    for k, npsi in enumerate(data.n_psi):
        line, = ax_c.plot(data.mu_values, data.unstable_fraction_psi[k], "o-", ms=3,
                          label=f"not stable, {npsi} azimuths")
        ax_c.plot(data.mu_values, data.positive_fraction_psi[k], "s--", ms=3, color=line.get_color(),
                  label=f"$W' > 0$ on the sphere, {npsi} azimuths")
    ax_c.set_xlabel(r"advance ratio $\mu$")
    ax_c.set_ylabel("fraction of azimuths")
    ax_c.set_title(f"(c) azimuth grid (practical, {data.variant})", fontsize=9)
    ax_c.legend(fontsize=7)


# --------------------------------------------------------------------------------------
# Tables
# --------------------------------------------------------------------------------------


