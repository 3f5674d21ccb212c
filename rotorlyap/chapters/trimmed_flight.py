"""Figures and tables of the chapter on the trimmed helicopter in forward flight.

The paper's forward-flight condition (the hover collective, no cyclic pitch, an untilted disc,
Glauert's inflow) is not a flight condition: the rotor lifts far more than the weight. This
module compares it with a trimmed helicopter (:func:`rotorlyap.model.forward_trim.forward_flight_trim`
on :meth:`rotorlyap.model.parameters.BladeParameters.flight_case`), measures what the choices the
paper leaves open do to the stability verdicts (inflow model, compressibility, the sign of the
pitch-flap coupling, the pitch inertia), and tests its Fig. 8 under every combination of the
readings it leaves open (:func:`forensic_data`).

The conventions every chapter's module follows (data objects, ``summary()``, ``facts()``,
``plot_*`` and ``figure_*``) are in :mod:`rotorlyap.chapters`. Growth
rates are the largest real part of the Floquet exponents, per radian of azimuth ("per rev" in
the text, the usual unit of rotor dynamics: 1/rad of ``psi``).
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, replace

import numpy as np

from ..analysis.floquet import blade_floquet
from ..analysis.functions import quadratic_function
from ..analysis.stability import blade_stability
from ..analysis.sweep import process_map, worker_count
from ..conventions import PAPER_TEST_DISTURBANCES, TWO_PI
from ..errors import NotAsymptoticallyStableError, TrimError
from ..model.blade import Blade
from ..model.compressibility import C81_NACA0012_CL_2DEG, MACH_CAP, prandtl_glauert_factor, validity_map
from ..model.forward_trim import forward_flight_trim
from ..model.inflow import kx_factor
from ..reporting import count
from ..model.mass import mass_properties
from ..model.parameters import CG_POSITIONS, BladeParameters
from ..model.steady import tabulate_motion
from .export import markdown_table
from .scans import MU_FORENSIC, ScanData, _category
from .style import CG_COLORS, CG_MARKERS, figure, finish, subplots

__all__ = [
    "CASES", "MU_TRIM", "MU_FORENSIC", "INFLOW_CHOICES", "PUMA_SECTION", "puma_radius_of_gyration",
    "TrimData", "trim_data", "figure_trim",
    "DiscData", "disc_data", "figure_disc",
    "ModelChoiceData", "model_choice_data",
    "Delta3Data", "delta3_data",
    "PitchInertiaData", "pitch_inertia_data", "figure_pitch_inertia",
    "FORENSIC_FACTORS", "ForensicData", "forensic_data",
    "VERDICT_CANDIDATES", "verdict_data", "verdict_summary", "verdict_facts",
]

CASES = ("forward", "neutral", "backward")

#: Advance ratios of the trim sweep.
MU_TRIM = (0.0, 0.05, 0.1, 0.15, 0.2, 0.25, 0.3)

#: Inflow models compared.
INFLOW_CHOICES = ("glauert", "drees", "pitt-peters")

_DEG = math.pi / 180.0

#: A published blade of this class for the pitch inertia: the SA330 Puma research blade's main
#: aerofoil span carries 0.109 kg m of torsional inertia per metre on 8.929 kg/m, chord 0.537 m
#: [PumaBladeData], a radius of gyration of 0.206 chord about the feathering axis.
PUMA_SECTION = {"torsional_inertia_per_length": 0.109, "mass_per_length": 8.929, "chord": 0.537}


def puma_radius_of_gyration() -> float:
    """The Puma blade section's pitch radius of gyration, fraction of chord (:data:`PUMA_SECTION`)."""
    s = PUMA_SECTION
    return math.sqrt(s["torsional_inertia_per_length"] / s["mass_per_length"]) / s["chord"]


def _growth(params: BladeParameters, mu: float, steady) -> float:
    """Largest real part of the Floquet exponents about ``steady`` (a steady motion, or None for
    the hover trim of ``params``), per rev (per radian of azimuth)."""
    return float(blade_floquet(params, mu, steady="periodic" if steady is None else steady).exponents.real.max())


def _lift_ratio_or_nan(params: BladeParameters, mu: float, target: str) -> tuple[float, object]:
    try:
        tr = forward_flight_trim(params, mu, target)
    except TrimError:
        return float("nan"), None
    return tr.lift_over_weight, tr


def _fmt(values, digits: int) -> str:
    """``[1.00 – 2.67]``: fixed decimals, "–" where there is no value (NaN)."""
    return "[" + " ".join("–" if not np.isfinite(v) else f"{v:.{digits}f}" for v in np.ravel(values)) + "]"


# --------------------------------------------------------------------------------------
# The trim sweep
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class TrimData:
    """The trimmed helicopter against the paper's condition, per C.G. and advance ratio.

    Attributes
    ----------
    cases : tuple of str
    mu_values : numpy.ndarray
        (m,).
    controls_deg : numpy.ndarray
        Trimmed collective, ``cyclic_cos`` and ``cyclic_sin``, deg, (k, m, 3).
    shaft_tilt_deg : numpy.ndarray
        Forward shaft tilt of the trim, deg, (k, m).
    induced_inflow : numpy.ndarray
        Induced inflow ratio of the trim, (k, m).
    paper_lift_ratio : numpy.ndarray
        Vertical rotor force over the weight in the paper's condition (table_i, hover controls,
        periodic motion), (k, m); NaN where the blade has no periodic motion near hover.
    growth_paper : numpy.ndarray
        Largest Floquet real part about the paper's condition's periodic motion, per rev, (k, m).
    growth_trimmed : numpy.ndarray
        The same about the trimmed helicopter's periodic motion, (k, m).
    growth_trimmed_incompressible : numpy.ndarray
        The same with the paper's incompressible sections (the trim alone changed), (k, m).
    retreating_alpha_deg : numpy.ndarray
        Mean angle of attack of the outer 10 % of the span at psi = 270 deg, deg, (2, m):
        paper's condition, trimmed (forward C.G.); NaN where the paper's condition has no
        periodic motion.
    """

    cases: tuple
    mu_values: np.ndarray
    controls_deg: np.ndarray
    shaft_tilt_deg: np.ndarray
    induced_inflow: np.ndarray
    paper_lift_ratio: np.ndarray
    growth_paper: np.ndarray
    growth_trimmed: np.ndarray
    growth_trimmed_incompressible: np.ndarray
    retreating_alpha_deg: np.ndarray

    def summary(self) -> str:
        """Per case: the paper's lift over weight (0.01), the trimmed controls and tilt (0.01 deg),
        both growth rates (0.001 per rev); "–" where the paper's condition has no periodic motion."""
        lines = [f"mu: {_fmt(self.mu_values, 3)}"]
        for i, case in enumerate(self.cases):
            lines += [
                f"{case} C.G.",
                f"  paper's condition, lift / weight: {_fmt(self.paper_lift_ratio[i], 2)}",
                f"  trimmed collective, deg:          {_fmt(self.controls_deg[i, :, 0], 2)}",
                f"  trimmed cyclic cos, deg:          {_fmt(self.controls_deg[i, :, 1], 2)}",
                f"  trimmed cyclic sin, deg:          {_fmt(self.controls_deg[i, :, 2], 2)}",
                f"  trimmed shaft tilt, deg:          {_fmt(self.shaft_tilt_deg[i], 2)}",
                f"  growth rate, paper's condition:   {_fmt(self.growth_paper[i], 3)}",
                f"  growth rate, trimmed:             {_fmt(self.growth_trimmed[i], 3)}",
                f"  growth rate, trimmed, incompr.:   {_fmt(self.growth_trimmed_incompressible[i], 3)}",
            ]
        lines.append(f"forward C.G., outboard angle of attack at psi = 270 deg, deg: paper's "
                     f"{_fmt(self.retreating_alpha_deg[0], 1)}, trimmed {_fmt(self.retreating_alpha_deg[1], 1)}")
        if not np.isfinite(self.paper_lift_ratio).all():
            lines.append("(–: the paper's condition has no periodic motion near hover there)")
        return "\n".join(lines)

    def facts(self) -> dict:
        """The numbers the chapter quotes."""
        j = int(np.argmin(np.abs(self.mu_values - 0.25)))
        k = int(np.argmin(np.abs(self.mu_values - 0.15)))
        fw = self.paper_lift_ratio[0, 1:]
        bw = self.paper_lift_ratio[-1]
        jb = int(np.nanargmax(bw))
        gi = self.growth_trimmed_incompressible
        neu = self.cases.index("neutral") if "neutral" in self.cases else 0
        return {
            "ch8_paper_lw_fw_lo": f"{np.nanmin(fw):.2f}",
            "ch8_paper_lw_fw_hi": f"{np.nanmax(fw):.2f}",
            "ch8_paper_lw_fw15": f"{self.paper_lift_ratio[0, k]:.2f}",
            "ch8_paper_lw_bw_max": f"{bw[jb]:.2f}",
            "ch8_paper_lw_bw_mu": f"{self.mu_values[jb]:g}",
            "ch8_paper_growth_bw_at_max": f"{self.growth_paper[-1, jb]:+.3f}",
            "ch8_incompr_trim_bw_at_max": f"{gi[-1, jb]:.3f}",
            "ch8_incompr_trim_neu_at_max": f"{gi[neu, jb]:.3f}",
            "ch8_paper_neu_at_max": f"{self.growth_paper[neu, jb]:.3f}",
            "ch8_tilt25": f"{self.shaft_tilt_deg[0, j]:.1f}",
            "ch8_coll25": f"{self.controls_deg[0, j, 0]:.1f}",
            "ch8_coll0": f"{self.controls_deg[0, 0, 0]:.1f}",
            "ch8_theta1s25": f"{self.controls_deg[0, j, 2]:.1f}",
            "ch8_alpha270_paper": f"{self.retreating_alpha_deg[0, j]:.1f}",
            "ch8_alpha270_trim": f"{self.retreating_alpha_deg[1, j]:.1f}",
            "ch8_growth_trim_max": f"{np.nanmax(self.growth_trimmed):.3f}",
            "ch8_growth_bw_paper25": f"{self.growth_paper[-1, j]:.3f}",
            "ch8_growth_bw_trim25": f"{self.growth_trimmed[-1, j]:.3f}",
            "ch8_bw_stable_from": (f"{self.mu_values[np.argmax(self.growth_trimmed[-1] < 0)]:g}"
                                   if (self.growth_trimmed[-1] < 0).any() else "never"),
            **model_facts(),
        }


#: Highest Mach number of the C81 NACA 0012 table up to which the chapter quotes the agreement of
#: the Prandtl-Glauert lift factor with it.
C81_CHECK_MACH = 0.6


def model_facts() -> dict:
    """The parameters of the chapter's model that its text quotes: the flat-plate area (m², 0.1)
    and the helicopter's mass (t, 0.1) of :class:`BladeParameters`, the pitch radius of gyration
    (chord), the Mach number above which the Prandtl-Glauert factor is held, and the largest
    deviation of that factor from the C81 NACA 0012 table's lift at 2 deg up to
    :data:`C81_CHECK_MACH` (per cent, one decimal)."""
    p = BladeParameters.table_i("forward")
    table = C81_NACA0012_CL_2DEG
    dev = max(abs(cl / (table[0.0] * float(prandtl_glauert_factor(m))) - 1.0)
              for m, cl in table.items() if m <= C81_CHECK_MACH)
    return {"ch8_flat_plate_area": f"{p.flat_plate_area:.1f}", "ch8_mass_t": f"{p.helicopter_mass / 1000:.1f}",
            "ch8_pitch_k": f"{p.pitch_radius_of_gyration:g}", "ch8_mach_cap": f"{MACH_CAP:g}",
            "ch8_c81_mach": f"{C81_CHECK_MACH:g}", "ch8_c81_dev": f"{100 * dev:.1f} %"}


def _outboard_alpha_270(params: BladeParameters, mu: float, motion) -> float:
    blade = Blade(params, mu)
    psi = np.array([1.5 * math.pi])
    al = blade.angle_of_attack(psi, motion.xi(psi))[0]
    outer = blade.r_over_R >= 0.9
    return float(np.degrees(al[outer].mean()))


def trim_data(cases=CASES, mu_values=MU_TRIM) -> TrimData:
    """Trim every case at every advance ratio (:meth:`BladeParameters.flight_case`, propulsive
    trim) and compute the paper's condition beside it (:meth:`BladeParameters.table_i`, hover
    controls), with the Floquet growth rate of both."""
    mu_values = np.asarray(mu_values, dtype=float)
    k, m = len(cases), mu_values.size
    ctrl = np.full((k, m, 3), np.nan)
    tilt = np.full((k, m), np.nan)
    lam = np.full((k, m), np.nan)
    ratio = np.full((k, m), np.nan)
    g_paper = np.full((k, m), np.nan)
    g_trim = np.full((k, m), np.nan)
    g_inc = np.full((k, m), np.nan)
    a270 = np.full((2, m), np.nan)
    for i, case in enumerate(cases):
        for j, mu in enumerate(mu_values):
            tr = forward_flight_trim(BladeParameters.flight_case(case), float(mu))
            ctrl[i, j] = tr.controls_deg
            tilt[i, j] = math.degrees(tr.shaft_tilt)
            lam[i, j] = tr.induced_inflow
            g_trim[i, j] = _growth(tr.params, float(mu), tr.steady)
            inc = forward_flight_trim(BladeParameters.flight_case(case, compressibility="none"), float(mu))
            g_inc[i, j] = _growth(inc.params, float(mu), inc.steady)
            ratio[i, j], paper = _lift_ratio_or_nan(BladeParameters.table_i(case), float(mu), "none")
            if paper is not None:
                g_paper[i, j] = _growth(paper.params, float(mu), paper.steady)
            if i == 0:
                a270[1, j] = _outboard_alpha_270(tr.params, float(mu), tr.motion)
                if paper is not None:
                    a270[0, j] = _outboard_alpha_270(paper.params, float(mu), paper.motion)
    return TrimData(cases=tuple(cases), mu_values=mu_values, controls_deg=ctrl, shaft_tilt_deg=tilt,
                    induced_inflow=lam, paper_lift_ratio=ratio, growth_paper=g_paper, growth_trimmed=g_trim,
                    growth_trimmed_incompressible=g_inc, retreating_alpha_deg=a270)


def figure_trim(data: TrimData, figsize=(8.6, 7.0)):
    """Three panels: (a) the paper's lift over weight; (b) the trimmed controls and tilt (forward
    C.G.); (c, the full width below) the growth rates of both conditions, per rev (colour and
    marker per C.G. case, line style per condition). Returns the figure."""
    from matplotlib.lines import Line2D

    fig = figure(figsize=figsize)
    ax = fig.subplot_mosaic([["a", "b"], ["c", "c"]])
    ax = [ax["a"], ax["b"], ax["c"]]
    mu = data.mu_values
    conditions = (("paper's condition", "--", dict(mfc="white")),
                  ("trimmed, incompressible", ":", dict(ms=4)),
                  ("trimmed, compressible", "-", {}))
    for i, case in enumerate(data.cases):
        c, m = CG_COLORS[case], CG_MARKERS[case]
        ax[0].plot(mu, data.paper_lift_ratio[i], "-", marker=m, color=c, label=f"{case} C.G.")
        for g, (_, ls, kw) in zip((data.growth_paper[i], data.growth_trimmed_incompressible[i],
                                   data.growth_trimmed[i]), conditions):
            ax[2].plot(mu, g, ls, marker=m, color=c, **{"ms": 6, **kw})
    ax[0].axhline(1.0, color="k", lw=0.8)
    ax[0].text(mu[-1], 1.02, "trimmed: 1", ha="right", va="bottom", fontsize=9)
    ax[0].set(xlabel=r"advance ratio $\mu$", ylabel="vertical rotor force / weight")
    ax[0].set_title("(a) the paper's condition overloads the rotor", fontsize=10)
    ax[0].legend(fontsize=8.5)
    labels = ("collective", r"cyclic $\theta_{1c}$", r"cyclic $\theta_{1s}$")
    styles = ("-", "--", ":")
    for q in range(3):
        ax[1].plot(mu, data.controls_deg[0, :, q], styles[q], color="#0072B2", label=labels[q])
    ax[1].plot(mu, data.shaft_tilt_deg[0], "-", color="#E69F00", lw=2.0, label="shaft tilt (forward)")
    ax[1].axhline(0.0, color="k", lw=0.5)
    ax[1].set(xlabel=r"advance ratio $\mu$", ylabel="angle (deg)")
    ax[1].set_title("(b) trim, forward C.G.", fontsize=10)
    _headroom(ax[1], 0.3)
    ax[1].legend(fontsize=8.5, ncol=2, loc="upper left", columnspacing=1.0)
    ax[2].axhline(0.0, color="k", lw=0.8)
    ax[2].set(xlabel=r"advance ratio $\mu$", ylabel="largest Floquet real part (per rev)")
    ax[2].set_title("(c) linear stability: above 0 the linearised blade is unstable", fontsize=10)
    handles = [Line2D([], [], color=CG_COLORS[case], marker=CG_MARKERS[case], ls="none", ms=6,
                      label=f"{case} C.G.") for case in data.cases]
    handles += [Line2D([], [], color="k", ls=ls, marker="o", label=lab, **{"ms": 6, **kw})
                for lab, ls, kw in conditions]
    _headroom(ax[2], 0.45)
    ax[2].legend(handles=handles, fontsize=8.5, ncol=2, loc="upper right")
    return finish(fig)


def _headroom(ax, fraction: float) -> None:
    """Raise the top of ``ax``'s y axis by ``fraction`` of its data range: room for a legend
    above the data."""
    lo, hi = ax.dataLim.y0, ax.dataLim.y1
    ax.set_ylim(lo - 0.05 * (hi - lo), hi + fraction * (hi - lo))


# --------------------------------------------------------------------------------------
# The disc: angle of attack, stall, reverse flow, Mach number
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class DiscData:
    """The section model's range over the disc at one advance ratio, for two conditions.

    Attributes
    ----------
    labels : tuple of str
        The conditions (paper's, trimmed).
    mu : float
    psi : numpy.ndarray
        (n,), rad.
    r_over_R : numpy.ndarray
        (s,).
    alpha_deg : numpy.ndarray
        Angle of attack, deg, (2, n, s).
    mach : numpy.ndarray
        Section Mach number, (2, n, s).
    stalled, reverse_flow, transonic : numpy.ndarray
        Flags of :func:`rotorlyap.model.compressibility.validity_map`, (2, n, s).
    stall_deg : tuple of float
        The stall angles, deg.
    """

    labels: tuple
    mu: float
    psi: np.ndarray
    r_over_R: np.ndarray
    alpha_deg: np.ndarray
    mach: np.ndarray
    stalled: np.ndarray
    reverse_flow: np.ndarray
    transonic: np.ndarray
    stall_deg: tuple

    def summary(self) -> str:
        """Per condition: fractions of the disc stalled, in reverse flow, transonic (0.001) and
        the largest Mach number (0.01)."""
        lines = [f"mu = {self.mu:g}; fractions of the (azimuth, station) grid"]
        for i, lab in enumerate(self.labels):
            lines.append(f"  {lab}: stalled {self.stalled[i].mean():.3f}, reverse flow {self.reverse_flow[i].mean():.3f}, "
                         f"transonic {self.transonic[i].mean():.3f}, largest Mach {self.mach[i].max():.2f}")
        return "\n".join(lines)

    def facts(self) -> dict:
        """Stall fractions (percent, one decimal) and the largest Mach number (0.01)."""
        return {
            "ch8_stall_paper": f"{100 * self.stalled[0].mean():.1f}",
            "ch8_stall_trim": f"{100 * self.stalled[1].mean():.1f}",
            "ch8_mach_max": f"{self.mach[1].max():.2f}",
            "ch8_transonic_trim": f"{100 * self.transonic[1].mean():.1f}",
            "ch8_disc_mu": f"{self.mu:g}",
        }


def disc_data(case: str = "forward", mu: float = 0.25, n_azimuth: int = 72, n_stations: int = 24) -> DiscData:
    """:func:`rotorlyap.model.compressibility.validity_map` for the paper's condition
    (table_i, hover controls, its periodic motion) and the trimmed helicopter (flight_case),
    both with ``n_stations`` stations for a finer picture."""
    out = []
    for params, target in ((BladeParameters.table_i(case, n_stations=n_stations), "none"),
                           (BladeParameters.flight_case(case, n_stations=n_stations), "propulsive")):
        tr = forward_flight_trim(params, mu, target)
        out.append(validity_map(Blade(tr.params, mu), tr.motion.xi, n_azimuth=n_azimuth))
    v0 = out[0]
    return DiscData(labels=("paper's condition", "trimmed helicopter"), mu=float(mu), psi=v0.psi,
                    r_over_R=v0.r_over_R, alpha_deg=np.degrees(np.stack([v.alpha for v in out])),
                    mach=np.stack([v.mach for v in out]), stalled=np.stack([v.stalled for v in out]),
                    reverse_flow=np.stack([v.reverse_flow for v in out]),
                    transonic=np.stack([v.transonic for v in out]),
                    stall_deg=tuple(math.degrees(a) for a in v0.stall_angles))


def figure_disc(data: DiscData, figsize=(6.4, 4.5)):
    """Two discs seen from above (psi = 0 over the tail, advancing side on the right): the
    angle of attack in colour, stall and reverse flow hatched, the transonic region outlined;
    the colour bar and the legend of the hatches below. Returns the figure.

    The discs are round (equal aspect), and the figure is narrower than the book's text column
    (:data:`rotorlyap.chapters.style.PAGE_WIDTH_PX`), so that it is shown at its own size and not
    rescaled into ellipses."""
    from matplotlib.colors import BoundaryNorm
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    fig, ax = subplots(1, 2, figsize=figsize, subplot_kw={"projection": "polar"}, layout="constrained")
    th = np.concatenate([data.psi, [data.psi[0] + TWO_PI]])
    r = data.r_over_R
    levels = np.arange(-8.0, 22.0, 2.0)
    norm = BoundaryNorm(levels, 256, extend="both")
    hatches = {"stalled": "xxx", "reverse": "///"}
    for i, lab in enumerate(data.labels):
        a = ax[i]
        a.set_aspect("equal")
        a.set_theta_zero_location("S")
        a.set_theta_direction(1)
        al = np.clip(data.alpha_deg[i], -90, 90)
        al = np.where(data.reverse_flow[i], np.nan, al)
        al = np.vstack([al, al[:1]])
        T, Rr = np.meshgrid(th, r, indexing="ij")
        cs = a.contourf(T, Rr, al, levels=levels, cmap="viridis", norm=norm, extend="both")
        for flag, hatch in ((data.stalled[i], hatches["stalled"]), (data.reverse_flow[i], hatches["reverse"])):
            f = np.vstack([flag, flag[:1]]).astype(float)
            if f.any():
                a.contourf(T, Rr, f, levels=[0.5, 1.5], colors="none", hatches=[hatch])
                a.contour(T, Rr, f, levels=[0.5], colors="k", linewidths=0.6)
        tr = np.vstack([data.transonic[i], data.transonic[i][:1]]).astype(float)
        if tr.any():
            a.contour(T, Rr, tr, levels=[0.5], colors="tab:red", linewidths=1.8)
        a.set_ylim(0, 1)
        a.set_yticks([0.25, 0.5, 0.75, 1.0])
        a.set_yticklabels(["", "r/R = 0.5", "", "1"], fontsize=8.5)
        a.set_rlabel_position(225)
        a.set_xticks(np.radians([0, 90, 180, 270]))
        a.set_xticklabels(["0° tail", "90°\nadvancing", "180° nose", "270°\nretreating"], fontsize=9)
        a.tick_params(axis="x", pad=7)
        a.set_title(f"({'ab'[i]}) {lab}, $\\mu$ = {data.mu:g}", fontsize=10.5, pad=14)
    cb = fig.colorbar(cs, ax=ax, orientation="horizontal", fraction=0.05, pad=0.04, aspect=40, shrink=0.8)
    cb.set_label("angle of attack (deg)", fontsize=9.5)
    cb.ax.tick_params(labelsize=9)
    handles = [Patch(facecolor="white", edgecolor="k", hatch=hatches["stalled"],
                     label=f"stalled: beyond {data.stall_deg[1]:.0f} deg"),
               Patch(facecolor="white", edgecolor="k", hatch=hatches["reverse"], label="reverse flow"),
               Line2D([], [], color="tab:red", lw=1.8, label=r"transonic: $M > M_{dd}$")]
    fig.legend(handles=handles, loc="outside lower center", ncol=3, fontsize=9, frameon=False,
               handlelength=2.5, handleheight=1.4)
    fig.get_layout_engine().set(wspace=0.12)  # the discs' side labels apart
    return finish(fig, layout=False)


# --------------------------------------------------------------------------------------
# Inflow model and compressibility
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class ModelChoiceData:
    """Trim and growth rate of the trimmed helicopter under each inflow model and with and
    without compressibility, per C.G. and advance ratio.

    Attributes
    ----------
    cases : tuple of str
    mu_values : numpy.ndarray
        (m,).
    variants : tuple of str
        Labels: one per inflow model (compressible sections), then Pitt-Peters incompressible.
    kx : numpy.ndarray
        Longitudinal inflow gradient of each variant at the forward C.G.'s trim, (v, m).
    collective_deg : numpy.ndarray
        Trimmed collective, deg, (v, k, m).
    lateral_cyclic_deg : numpy.ndarray
        Trimmed ``cyclic_cos`` of the forward C.G., deg, (v, m): what cancels the lateral
        flapping the longitudinal inflow gradient drives.
    growth : numpy.ndarray
        Largest Floquet real part, per rev, (v, k, m).
    """

    cases: tuple
    mu_values: np.ndarray
    variants: tuple
    kx: np.ndarray
    collective_deg: np.ndarray
    lateral_cyclic_deg: np.ndarray
    growth: np.ndarray

    def summary(self) -> str:
        """k_x (0.01), collective (0.01 deg) and growth rate (0.001 per rev) of each variant."""
        lines = [f"mu: {_fmt(self.mu_values, 3)}"]
        for v, lab in enumerate(self.variants):
            lines.append(f"{lab}: k_x {_fmt(self.kx[v], 2)}, forward C.G. cyclic cos, deg {_fmt(self.lateral_cyclic_deg[v], 2)}")
            for i, case in enumerate(self.cases):
                lines.append(f"  {case:8s} collective {_fmt(self.collective_deg[v, i], 2)}  growth {_fmt(self.growth[v, i], 3)}")
        return "\n".join(lines)

    def markdown(self) -> str:
        """The growth rates at the largest advance ratio as a table (0.001 per rev)."""
        j = -1
        header = (["model", "k_x"] + [f"growth rate, {c} C.G., per rev" for c in self.cases]
                  + ["collective, forward C.G., deg", "lateral cyclic, forward C.G., deg"])
        rows = [[lab, f"{self.kx[v, j]:.2f}"] + [f"{self.growth[v, i, j]:.3f}" for i in range(len(self.cases))]
                + [f"{self.collective_deg[v, 0, j]:.2f}", f"{self.lateral_cyclic_deg[v, j]:.2f}"]
                for v, lab in enumerate(self.variants)]
        return markdown_table(header, rows)

    def facts(self) -> dict:
        """Largest spread of the growth rates and the lateral cyclic between the inflow models,
        the backward C.G.'s hover growth rate with and without compressibility."""
        n_inflow = len(INFLOW_CHOICES)
        spread = np.nanmax(self.growth[:n_inflow], axis=0) - np.nanmin(self.growth[:n_inflow], axis=0)
        pg = self.variants.index("pitt-peters")
        inc = len(self.variants) - 1
        dcoll = self.collective_deg[inc] - self.collective_deg[pg]
        dlat = np.nanmax(self.lateral_cyclic_deg[:n_inflow], axis=0) - np.nanmin(self.lateral_cyclic_deg[:n_inflow], axis=0)
        jl = int(np.nanargmax(dlat))
        return {
            "ch8_inflow_dlat_mu": f"{self.mu_values[jl]:g}",
            "ch8_inflow_dlat_last": f"{dlat[-1]:.2f}",
            # the largest change, or the rounding step it stays below
            "ch8_inflow_spread": "0.001" if np.nanmax(spread) < 0.001 else f"{np.nanmax(spread):.3f}",
            "ch8_inflow_dlat": f"{np.nanmax(dlat):.1f}",
            "ch8_compr_bw_hover": f"{self.growth[pg, -1, 0]:.3f}",
            "ch8_incompr_bw_hover": f"{self.growth[inc, -1, 0]:.3f}",
            "ch8_kx_glauert": f"{self.kx[0, -1]:.2f}",
            "ch8_kx_pp": f"{self.kx[pg, -1]:.2f}",
            "ch8_kx_pp_first": f"{self.kx[pg, 1]:.2f}",
            "ch8_mu_first": f"{self.mu_values[1]:g}",
            "ch8_compr_dcoll": f"{np.nanmax(np.abs(dcoll)):.1f}",
            "ch8_model_mu_last": f"{self.mu_values[-1]:g}",
            "ch8_coll0_incompr": f"{self.collective_deg[inc, 0, 0]:.2f}",
        }


def model_choice_data(cases=CASES, mu_values=(0.0, 0.05, 0.1, 0.15, 0.2, 0.25)) -> ModelChoiceData:
    """:func:`trim_data`'s trim under Glauert, Drees and Pitt-Peters inflow (compressible
    sections), and Pitt-Peters with incompressible sections."""
    mu_values = np.asarray(mu_values, dtype=float)
    variants = [(m, dict(inflow_model=m)) for m in INFLOW_CHOICES]
    variants.append(("pitt-peters, incompressible", dict(compressibility="none")))
    k, m, v = len(cases), mu_values.size, len(variants)
    kx = np.full((v, m), np.nan)
    coll = np.full((v, k, m), np.nan)
    lat = np.full((v, m), np.nan)
    growth = np.full((v, k, m), np.nan)
    for a, (_, over) in enumerate(variants):
        for i, case in enumerate(cases):
            for j, mu in enumerate(mu_values):
                p = BladeParameters.flight_case(case, **over)
                tr = forward_flight_trim(p, float(mu))
                coll[a, i, j] = tr.controls_deg[0]
                growth[a, i, j] = _growth(tr.params, float(mu), tr.steady)
                if i == 0:
                    lat[a, j] = tr.controls_deg[1]
                    kx[a, j] = kx_factor(p.inflow_model, float(mu), tr.induced_inflow + mu * math.tan(tr.shaft_tilt))
    return ModelChoiceData(cases=tuple(cases), mu_values=mu_values, variants=tuple(lab for lab, _ in variants),
                           kx=kx, collective_deg=coll, lateral_cyclic_deg=lat, growth=growth)


# --------------------------------------------------------------------------------------
# The sign of the pitch-flap coupling
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Delta3Data:
    """Hover growth rates of the three C.G. cases under both signs of ``tan(delta3)``.

    Attributes
    ----------
    cases : tuple of str
    couplings : numpy.ndarray
        The two values of ``pitch_flap_coupling`` (tan delta3), (2,).
    growth : numpy.ndarray
        Largest real part of the hover eigenvalues, per rev, (2, k).
    growth_trimmed : numpy.ndarray
        The same for the trimmed helicopter at ``mu``, (2, k).
    mu : float
    flap_frequency_sq : numpy.ndarray
        Classical flap frequency squared with the pitch following the coupling rigidly,
        ``nu_beta^2 + (gamma/8) tan(delta3)``, per rev^2, (2,), forward C.G.
    """

    cases: tuple
    couplings: np.ndarray
    growth: np.ndarray
    growth_trimmed: np.ndarray
    mu: float
    flap_frequency_sq: np.ndarray

    def aft_trend(self, row: int) -> str:
        """'less stable aft' if the growth rate rises from forward to backward C.G., else 'more stable aft'."""
        g = self.growth[row]
        return "less stable aft" if g[-1] > g[0] else "more stable aft"

    def summary(self) -> str:
        """Growth rates (0.001 per rev) per sign and the aft trend."""
        lines = []
        for a, t in enumerate(self.couplings):
            lines.append(f"tan(delta3) = {t:+.1f}: hover {_fmt(self.growth[a], 3)} ({self.aft_trend(a)}), "
                         f"trimmed at mu = {self.mu:g} {_fmt(self.growth_trimmed[a], 3)}, "
                         f"flap frequency^2 with the pitch following the coupling {self.flap_frequency_sq[a]:.3f}")
        return "\n".join(lines)

    def facts(self) -> dict:
        """The numbers the chapter quotes."""
        out = {}
        for a, name in enumerate(("neg", "pos")):
            for i, case in enumerate(self.cases):
                out[f"ch8_d3{name}_{case}"] = f"{self.growth[a, i]:.3f}"
            out[f"ch8_d3{name}_nu2"] = f"{self.flap_frequency_sq[a]:.3f}"
            out[f"ch8_d3{name}_trend"] = self.aft_trend(a)
        return out


def _effective_flap_frequency_sq(params: BladeParameters) -> float:
    """The classical flap frequency squared with the pitch following the coupling rigidly,
    ``nu_e^2 = nu_beta^2 + (gamma / 8) tan(delta3)`` per rev^2 [Johnson1980]: a flap angle
    ``beta`` changes the pitch by ``-tan(delta3) beta``, whose lift adds ``(gamma/8) tan(delta3)``
    to the flap stiffness (hover, hinge near the shaft, no inflow change). ``nu_beta^2`` is the
    blade's own rotating flap frequency squared in vacuum, ``-dh_beta'/d beta`` of the model with
    the coupling removed."""
    p = replace(params, air_density=0.0, gravity=0.0, collective=0.0, pitch_flap_coupling=0.0)
    blade = Blade(p, 0.0)
    nu2 = float(-blade.jacobian(0.0, blade.equilibrium())[3, 0])
    return nu2 + params.lock_number / 8.0 * params.pitch_flap_coupling


def delta3_data(cases=CASES, couplings=(-0.4, 0.4), mu: float = 0.25) -> Delta3Data:
    """Hover growth rates (:func:`rotorlyap.analysis.floquet.blade_floquet` at ``mu = 0``) and
    the trimmed helicopter's at ``mu`` for each sign."""
    couplings = np.asarray(couplings, dtype=float)
    g = np.full((couplings.size, len(cases)), np.nan)
    gt = np.full_like(g, np.nan)
    nu2 = np.full(couplings.size, np.nan)
    for a, t in enumerate(couplings):
        for i, case in enumerate(cases):
            g[a, i] = _growth(BladeParameters.table_i(case, pitch_flap_coupling=float(t)), 0.0, None)
            tr = forward_flight_trim(BladeParameters.flight_case(case, pitch_flap_coupling=float(t)), mu)
            gt[a, i] = _growth(tr.params, mu, tr.steady)
        nu2[a] = _effective_flap_frequency_sq(BladeParameters.table_i("forward", pitch_flap_coupling=float(t)))
    return Delta3Data(cases=tuple(cases), couplings=couplings, growth=g, growth_trimmed=gt, mu=float(mu),
                      flap_frequency_sq=nu2)


# --------------------------------------------------------------------------------------
# The pitch inertia
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class PitchInertiaData:
    """Hover growth rate of one C.G. case against the section's pitch radius of gyration.

    Attributes
    ----------
    case : str
    radius_of_gyration : numpy.ndarray
        ``pitch_radius_of_gyration`` values, fraction of chord, (n,).
    pitch_inertia : numpy.ndarray
        Blade inertia about the pitch axis, kg m^2, (n,).
    growth : numpy.ndarray
        Largest real part of the hover eigenvalues, per rev, (n,): the paper's incompressible
        sections (:meth:`BladeParameters.table_i`).
    growth_compressible : numpy.ndarray
        The same with the report's forward-flight model (:meth:`BladeParameters.flight_case`), (n,).
    assumed : float
        The report's radius of gyration, fraction of chord.
    reference : tuple of float
        The Puma blade section's radius of gyration (:func:`puma_radius_of_gyration`), the
        pitch inertia it gives this blade (kg m^2) and the growth rate there (per rev).
    """

    case: str
    radius_of_gyration: np.ndarray
    pitch_inertia: np.ndarray
    growth: np.ndarray
    growth_compressible: np.ndarray
    assumed: float
    reference: tuple

    def summary(self) -> str:
        """Inertia (0.01 kg m^2) and growth rate (0.001 per rev) along the sweep, and at the
        Puma section's radius of gyration."""
        return "\n".join([
            f"{self.case} C.G., hover; pitch radius of gyration / chord: {_fmt(self.radius_of_gyration, 2)}",
            f"  pitch inertia, kg m^2: {_fmt(self.pitch_inertia, 2)}",
            f"  growth rate, per rev:  {_fmt(self.growth, 3)}",
            f"  compressible sections: {_fmt(self.growth_compressible, 3)}",
            f"  Puma section k/c = {self.reference[0]:.3f}: {self.reference[1]:.2f} kg m^2, growth rate {self.reference[2]:.3f}",
        ])

    def facts(self) -> dict:
        """Inertia and growth rate at the assumed value and at the ends of the sweep."""
        i0 = int(np.argmin(np.abs(self.radius_of_gyration - self.assumed)))
        return {
            "ch8_pi_assumed": f"{self.pitch_inertia[i0]:.2f}",
            "ch8_pi_growth_assumed": f"{self.growth[i0]:.3f}",
            "ch8_pi_lo": f"{self.pitch_inertia[0]:.2f}",
            "ch8_pi_hi": f"{self.pitch_inertia[-1]:.2f}",
            "ch8_pi_growth_lo": f"{self.growth[0]:.3f}",
            "ch8_pi_growth_hi": f"{self.growth[-1]:.3f}",
            "ch8_puma_k": f"{self.reference[0]:.2f}",
            "ch8_puma_inertia": f"{self.reference[1]:.2f}",
            "ch8_puma_growth": f"{self.reference[2]:.3f}",
            "ch8_pi_compr_max": f"{np.nanmax(self.growth_compressible):.3f}",
            "ch8_pi_compr_min": f"{np.nanmin(self.growth_compressible):.3f}",
            "ch8_pi_factor_hi": f"{self.pitch_inertia[-1] / self.pitch_inertia[i0]:.0f}",
        }


def pitch_inertia_data(case: str = "backward",
                       radii=(0.12, 0.16, 0.2, 0.24, 0.28, 0.32, 0.4, 0.5, 0.64)) -> PitchInertiaData:
    """Sweep ``pitch_radius_of_gyration`` in hover, with the paper's sections
    (:meth:`BladeParameters.table_i`) and the report's forward-flight model
    (:meth:`BladeParameters.flight_case`). The largest radii stand for a heavy cuff or pitch
    horn, which add pitch inertia the section does not carry."""
    radii = np.asarray(radii, dtype=float)
    inertia = np.empty(radii.size)
    growth = np.empty(radii.size)
    growth_c = np.empty(radii.size)
    for i, k in enumerate(radii):
        p = BladeParameters.table_i(case, pitch_radius_of_gyration=float(k))
        inertia[i] = float(mass_properties(p).inertia[0, 0])
        growth[i] = _growth(p, 0.0, None)
        growth_c[i] = _growth(BladeParameters.flight_case(case, pitch_radius_of_gyration=float(k)), 0.0, None)
    k_ref = puma_radius_of_gyration()
    p_ref = BladeParameters.table_i(case, pitch_radius_of_gyration=k_ref)
    ref = (k_ref, float(mass_properties(p_ref).inertia[0, 0]), _growth(p_ref, 0.0, None))
    return PitchInertiaData(case=case, radius_of_gyration=radii, pitch_inertia=inertia, growth=growth,
                            growth_compressible=growth_c, assumed=BladeParameters().pitch_radius_of_gyration,
                            reference=ref)


def figure_pitch_inertia(data: PitchInertiaData, figsize=(6.4, 4.0)):
    """The hover growth rate (per rev) against the blade's pitch inertia, with the report's
    assumption and the Puma section's radius of gyration marked. Returns the figure."""
    reference = {"Puma blade section": data.reference[1]}
    fig, ax = subplots(figsize=figsize)
    c = CG_COLORS.get(data.case, "k")
    m = CG_MARKERS.get(data.case, "o")
    ax.plot(data.pitch_inertia, data.growth, "-", marker=m, color=c, label=f"{data.case} C.G., hover, incompressible")
    ax.plot(data.pitch_inertia, data.growth_compressible, ":", marker=m, mfc="white", color=c,
            label=f"{data.case} C.G., hover, compressible")
    i0 = int(np.argmin(np.abs(data.radius_of_gyration - data.assumed)))
    ax.plot(data.pitch_inertia[i0], data.growth[i0], "k*", ms=12, label="the report's assumption")
    for lab, val in reference.items():
        ax.axvline(val, color="0.5", ls="--", lw=1, label=lab)
    ax.axhline(0.0, color="k", lw=0.8)
    ax.set(xlabel=r"blade inertia about the pitch axis (kg m$^2$)", ylabel="largest real part (per rev)")
    ax.legend(fontsize=8.5, loc="upper right")
    return finish(fig)


# --------------------------------------------------------------------------------------
# The forensic Fig. 8
# --------------------------------------------------------------------------------------

#: The readings the paper leaves open, each with its choices (the first is the report's reading
#: of the paper).
FORENSIC_FACTORS = {
    "condition": ("paper: hover controls, hover angles", "hover controls, periodic motion",
                  "cyclic trim (zero flapping), periodic motion", "trimmed helicopter, periodic motion"),
    "inflow": INFLOW_CHOICES,
    "delta3": (-0.4, 0.4),
    "function": ("energy", "quadratic"),
    "cg_reading": ("neutral at the aerodynamic centre", "neutral at the pitch axis"),
    "thrust": ("6400 kg", "4800 kg"),
    "reading": ("practical", "strict"),
}

_CG_READINGS = {
    "neutral at the aerodynamic centre": CG_POSITIONS,
    "neutral at the pitch axis": {"forward": 0.23, "neutral": 0.25, "backward": 0.27},
}


@dataclass(frozen=True)
class ForensicData:
    """Verdicts of the paper's Fig. 8 picture under combinations of its open readings.

    A combination reproduces the picture if, for each C.G. case, (1) every azimuth is stable in
    hover, (2) at the first advance ratio with an azimuth where ``W' > 0`` (on the sphere of the
    bound, or inside it where step 3 held) those azimuths lie on the retreating side only and
    some azimuths stay free of it, and (3) at ``mu = 0.25`` such azimuths lie on both sides.

    Attributes
    ----------
    factors : tuple of str
        Names of the varied factors, in the order of each row's choices.
    rows : tuple of tuple
        Per combination, its choices.
    hover_stable : numpy.ndarray
        Per combination and case: every azimuth stable at ``mu = 0``, (c, k).
    first_mu : numpy.ndarray
        First advance ratio with an azimuth where ``W' > 0``, (c, k); NaN if none.
    first_side : tuple of tuple of str
        Where those azimuths lie at ``first_mu``: "retreating", "advancing", "both", "whole disc", "none".
    last_side : tuple of tuple of str
        The same at the largest advance ratio.
    matches : numpy.ndarray
        Per combination and case: the three points hold, (c, k).
    mu_values : numpy.ndarray
    n_psi : int
    """

    factors: tuple
    rows: tuple
    hover_stable: np.ndarray
    first_mu: np.ndarray
    first_side: tuple
    last_side: tuple
    matches: np.ndarray
    mu_values: np.ndarray
    n_psi: int

    @property
    def n_matching(self) -> np.ndarray:
        """Cases for which each combination reproduces the picture, (c,)."""
        return self.matches.sum(axis=1)

    _LETTERS = {"retreating": "R", "advancing": "A", "both": "B", "whole disc": "W",
                "no steady motion": "n", "no quadratic function": "q", "tail/nose": "T", "none": "-"}

    def code(self, c: int) -> str:
        """Row ``c``'s first region, one entry per case: the advance ratio and where the azimuths
        with ``W' > 0`` lie (R retreating side only, A advancing only, B both sides, W the whole
        disc, n no steady motion found, q no quadratic function (linearised blade unstable), - none
        up to the last advance ratio)."""
        parts = []
        for i, side in enumerate(self.first_side[c]):
            mu = self.first_mu[c, i]
            parts.append("-" if not np.isfinite(mu) else f"{mu:g}{self._LETTERS[side]}")
        return " / ".join(parts)

    def pivot_markdown(self, row_factors=("condition", "inflow"), column_factors=("delta3", "function")) -> str:
        """The combinations that differ only in ``row_factors`` and ``column_factors`` from the
        first row's other choices, as a table: one cell per combination, :meth:`code`."""
        idx = {n: k for k, n in enumerate(self.factors)}
        rest = [n for n in self.factors if n not in row_factors + column_factors]
        base = self.rows[0]
        cells, row_keys, col_keys = {}, [], []
        for c, choice in enumerate(self.rows):
            if any(choice[idx[n]] != base[idx[n]] for n in rest):
                continue
            rk = tuple(choice[idx[n]] for n in row_factors)
            ck = tuple(choice[idx[n]] for n in column_factors)
            row_keys += [rk] if rk not in row_keys else []
            col_keys += [ck] if ck not in col_keys else []
            cells[(rk, ck)] = self.code(c)
        header = list(row_factors) + [", ".join(_short(v) for v in ck) for ck in col_keys]
        rows = [[_short(v) for v in rk] + [cells.get((rk, ck), "") for ck in col_keys] for rk in row_keys]
        return markdown_table(header, rows)

    def others_markdown(self, row_factors=("condition", "inflow"), column_factors=("delta3", "function")) -> str:
        """The combinations outside :meth:`pivot_markdown`: the factor changed from the first row,
        the function, hover stable per case, and :meth:`code`."""
        idx = {n: k for k, n in enumerate(self.factors)}
        rest = [n for n in self.factors if n not in row_factors + column_factors]
        base = self.rows[0]
        rows = []
        for c, choice in enumerate(self.rows):
            changed = [n for n in rest if choice[idx[n]] != base[idx[n]]]
            if not changed:
                continue
            what = "; ".join(f"{n.replace('_', ' ')}: {_short(choice[idx[n]])}" for n in changed)
            hv = "/".join("yes" if h else "no" for h in self.hover_stable[c])  # passes at every hover azimuth
            rows.append([_short(choice[idx["condition"]]), what, _short(choice[idx["function"]]), hv, self.code(c)])
        return markdown_table(["condition", "changed", "function", "hover passes (F/N/B)",
                               "first W' > 0 (F/N/B)"], rows)

    def summary(self) -> str:
        """Counts: combinations, hover passing at every azimuth for every case, picture for any and
        for every case."""
        c = len(self.rows)
        return (f"{c} combinations; hover passes at every azimuth for all three C.G.: "
                f"{int(self.hover_stable.all(axis=1).sum())}; the picture for at least one C.G.: "
                f"{int((self.n_matching > 0).sum())}, for all three: {int((self.n_matching == self.matches.shape[1]).sum())}")

    def retreating_first(self) -> list:
        """(row, case index) pairs whose first region lies on the retreating side only."""
        return [(c, i) for c in range(len(self.rows)) for i in range(self.matches.shape[1])
                if self.first_side[c][i] == "retreating"]

    def facts(self) -> dict:
        """The counts of :meth:`summary` and of (combination, case) pairs whose first region lies
        on the retreating side only."""
        rf = self.retreating_first()
        return {
            "ch8_forensic_cells": len(self.rows) * self.matches.shape[1],
            "ch8_forensic_retreating": len(rf),
            "ch8_forensic_retreating_mu": ", ".join(sorted({f"{self.first_mu[c, i]:g}" for c, i in rf})) or "-",
            "ch8_forensic_n": len(self.rows),
            "ch8_forensic_hover": int(self.hover_stable.all(axis=1).sum()),
            "ch8_forensic_any": int((self.n_matching > 0).sum()),
            "ch8_forensic_all": int((self.n_matching == self.matches.shape[1]).sum()),
            "ch8_forensic_base_thrust": (_short(self.rows[0][self.factors.index("thrust")])
                                         if "thrust" in self.factors else ""),
        }


_SHORT = {
    "paper: hover controls, hover angles": "paper: hover controls and angles",
    "hover controls, periodic motion": "hover controls, periodic motion",
    "cyclic trim (zero flapping), periodic motion": "cyclic trim, periodic motion",
    "trimmed helicopter, periodic motion": "trimmed helicopter, periodic motion",
    "neutral at the aerodynamic centre": "a.c.",
    "neutral at the pitch axis": "neutral C.G. at the pitch axis",
    -0.4: "tan δ₃ = −0.4", 0.4: "tan δ₃ = +0.4",
}


def _short(value) -> str:
    """A choice as the tables print it; a thrust choice ("4800 kg") as the weight it carries."""
    if isinstance(value, str) and value.endswith(" kg"):
        mass = float(value.split()[0])
        return f"weight of {mass:.0f} kg ({mass * BladeParameters.table_i('forward').gravity / 1000:.1f} kN)"
    return _SHORT.get(value, str(value))


def _side(bad: np.ndarray, psi: np.ndarray) -> str:
    """Where the flagged azimuths lie: advancing (0 < psi < 180 deg), retreating (180-360 deg)."""
    if not bad.any():
        return "none"
    if bad.all():
        return "whole disc"
    s = np.sin(psi[bad])
    adv, ret = bool((s > 1e-9).any()), bool((s < -1e-9).any())
    if adv and ret:
        return "both"
    if ret:
        return "retreating"
    if adv:
        return "advancing"
    return "tail/nose"


def _forensic_params(case: str, choice: dict) -> BladeParameters:
    """The blade of one forensic choice: the paper's incompressible sections in every condition
    (compressibility is not among the readings the paper leaves open)."""
    cg = _CG_READINGS[choice["cg_reading"]][case]
    mass = float(choice["thrust"].split()[0])
    over = dict(inflow_model=choice["inflow"], pitch_flap_coupling=float(choice["delta3"]), helicopter_mass=mass)
    if choice["condition"].startswith("trimmed"):
        return replace(BladeParameters.flight_case(case, **over), cg_position=cg, compressibility="none")
    return replace(BladeParameters.table_i(case, **over), cg_position=cg)


def _remembered(memo: dict, key, compute, error: type[Exception]):
    """``memo[key]``, computed by ``compute()`` the first time; an ``error`` it raised is kept
    and raised again on every later call with the same key."""
    if key not in memo:
        try:
            memo[key] = compute()
        except error as exc:
            memo[key] = exc
    if isinstance(memo[key], error):
        raise memo[key]
    return memo[key]


def _forensic_case(task: tuple) -> list:
    """``(combinations, case, mu_values, n_psi)`` -> :func:`_forensic_cell` of each combination
    for one case, sharing one memo (module level, so that worker processes can run it)."""
    combinations, case, mu_values, n_psi = task
    memo: dict = {}
    return [_forensic_cell(choice, case, mu_values, n_psi, memo) for choice in combinations]


def _forensic_cell(choice: dict, case: str, mu_values, n_psi: int, memo: dict) -> tuple:
    """One case of a row: hover stable, first mu, first side, last side, matches.

    ``memo`` keeps the trims, quadratic functions and verdicts of earlier rows by their inputs
    (the blade's parameters, the advance ratio, the trim's target, the function and the
    reading): many combinations share them (every condition has the same hover, both functions
    the same trims, both readings the same quadratic function). The advance ratios are taken in
    order up to the first flagged one, then the last: the row needs no other.
    """
    p = _forensic_params(case, choice)
    lyap = quadratic_function if choice["function"] == "quadratic" else None
    tests = PAPER_TEST_DISTURBANCES if choice["reading"] == "practical" else None
    cond = choice["condition"]
    psi = TWO_PI * np.arange(n_psi) / n_psi

    def flagged(mu: float):
        """The azimuths flagged at ``mu`` (bool array), None (no steady motion) or a message;
        and the verdict (None without one)."""
        try:
            if mu == 0.0 or cond.startswith("paper"):
                # the collective is left to the hover trim, whose equilibrium is kept
                # (a new one at the trimmed collective may lie on another branch)
                params, steady, trim_key = p, None, None
            else:
                target = {"hover": "none", "cyclic": "flapping", "trimmed": "propulsive"}[cond.split()[0]]
                trim_key = ("trim", p, mu, target)

                def trimmed(p=p, mu=mu, target=target):
                    tr = forward_flight_trim(p, mu, target)
                    return tr.params, tabulate_motion(tr.motion, 1024)

                params, steady = _remembered(memo, trim_key, trimmed, TrimError)
            key = ("verdict", params, mu, trim_key, choice["function"], choice["reading"], n_psi)
            fun = lyap
            if lyap is not None:
                # both readings of a quadratic function share its periodic Lyapunov solve
                def fun(blade, motion, fkey=("quadratic", params, mu, trim_key)):
                    return _remembered(memo, fkey, lambda: quadratic_function(blade, motion),
                                       NotAsymptoticallyStableError)
            r = _remembered(memo, key, lambda: blade_stability(
                params, mu, lyapunov=fun, steady=steady, n_psi=n_psi, test_disturbances=tests),
                NotAsymptoticallyStableError)
        except TrimError:
            return None, None
        except NotAsymptoticallyStableError:
            return "no quadratic function", None
        cat = _category(r)
        return (cat == 1) | (cat == 3), r

    mus = [float(mu) for mu in mu_values]
    hover, r = flagged(mus[0])
    hover_ok = r is not None and bool(np.all(r.stable))
    if r is not None:
        psi = np.asarray(r.psi)
    first_mu, first_side, bad, mu = float("nan"), "none", hover, mus[0]
    for mu in mus[1:]:
        bad, r = flagged(mu)
        if r is not None:
            psi = np.asarray(r.psi)
        if bad is None or isinstance(bad, str):
            first_mu, first_side = mu, "no steady motion" if bad is None else bad
            break
        if bad.any():
            first_mu, first_side = mu, _side(bad, psi)
            break
    if mu != mus[-1]:
        bad, r = flagged(mus[-1])
        if r is not None:
            psi = np.asarray(r.psi)
    last_side = "no steady motion" if bad is None else bad if isinstance(bad, str) else _side(bad, psi)
    match = hover_ok and first_side == "retreating" and last_side == "both"
    return (hover_ok, first_mu, first_side, last_side, match)


def forensic_data(combinations=None, cases=CASES, mu_values=MU_FORENSIC, n_psi: int = 36, *,
                  workers: int | None = None) -> ForensicData:
    """Run the paper's picture test for each combination of :data:`FORENSIC_FACTORS` choices.

    Parameters
    ----------
    combinations : iterable of dict, optional
        Each a full choice ``{factor: value}``. Default: every combination of condition, inflow,
        delta3 sign and function in the practical reading (the report's C.G. and thrust), then
        one-at-a-time changes of C.G. reading, thrust and reading from the paper's own row and
        from the row closest to the picture (hover controls with the periodic motion, the quadratic
        function).
    cases, mu_values, n_psi
        Cases, advance ratios (the first must be 0) and azimuths.
    workers : int, optional
        The cases are independent (each shares its trims and verdicts between the combinations,
        :func:`_forensic_case`): with ``workers`` other than 1 (default: every core) they run in
        that many fresh processes (:func:`rotorlyap.analysis.sweep.process_map`); ``workers=1``
        here, one after the other. The table does not depend on where they ran.
    """
    names = tuple(FORENSIC_FACTORS)
    if combinations is None:
        base = {n: v[0] for n, v in FORENSIC_FACTORS.items()}
        combos = []
        for cond, inflow, d3, fun in itertools.product(*(FORENSIC_FACTORS[n] for n in
                                                          ("condition", "inflow", "delta3", "function"))):
            combos.append({**base, "condition": cond, "inflow": inflow, "delta3": d3, "function": fun})
        closest = {**base, "condition": FORENSIC_FACTORS["condition"][1], "function": "quadratic"}
        for name in ("cg_reading", "thrust", "reading"):
            for value in FORENSIC_FACTORS[name][1:]:
                for fun in FORENSIC_FACTORS["function"]:
                    combos.append({**base, name: value, "function": fun})
                combos.append({**closest, name: value})
        combinations = combos
    mu_values = np.asarray(mu_values, dtype=float)
    if mu_values[0] != 0.0:
        raise ValueError("mu_values must start with 0 (hover)")
    combinations = tuple(combinations)
    tasks = [(combinations, case, mu_values, n_psi) for case in cases]
    workers = worker_count(workers, len(tasks))
    per_case = process_map(_forensic_case, tasks, workers) if workers > 1 else [_forensic_case(t) for t in tasks]
    rows, hover, first_mu, first_side, last_side, match = [], [], [], [], [], []
    for k, choice in enumerate(combinations):
        res = tuple(cells[k] for cells in per_case)
        rows.append(tuple(choice[n] for n in names))
        hover.append([r[0] for r in res])
        first_mu.append([r[1] for r in res])
        first_side.append(tuple(r[2] for r in res))
        last_side.append(tuple(r[3] for r in res))
        match.append([r[4] for r in res])
    return ForensicData(factors=names, rows=tuple(rows), hover_stable=np.array(hover, dtype=bool),
                        first_mu=np.array(first_mu, dtype=float), first_side=tuple(first_side),
                        last_side=tuple(last_side), matches=np.array(match, dtype=bool), mu_values=mu_values,
                        n_psi=int(n_psi))


# --------------------------------------------------------------------------------------
# The Liapunov verdicts on the trimmed helicopter
# --------------------------------------------------------------------------------------

#: The candidates of :func:`verdict_data`: (label, function, reading).
VERDICT_CANDIDATES = (
    ("energy, practical", "energy", "practical"),
    ("quadratic (Q = I), practical", "quadratic", "practical"),
    ("quadratic (Q = I), strict", "quadratic", "strict"),
)


def _verdict_cell(task: tuple):
    """One cell of :func:`verdict_data` (module level, so that worker processes can run it):
    ``(params, mu, steady, n_psi, function, reading)`` -> the result of
    :func:`~rotorlyap.analysis.stability.blade_stability`, or the message of a
    :class:`~rotorlyap.errors.NotAsymptoticallyStableError`."""
    params, mu, steady, n_psi, function, reading = task
    try:
        return blade_stability(params, mu, steady=steady, n_psi=n_psi,
                               lyapunov=quadratic_function if function == "quadratic" else None,
                               test_disturbances=PAPER_TEST_DISTURBANCES if reading == "practical" else None)
    except NotAsymptoticallyStableError as exc:
        return str(exc)


def _verdict_cost(task: tuple) -> int:
    """Rank of a cell's expected cost (for the process pool): the quadratic function's strict
    reading about a periodic motion first."""
    _, mu, _, _, function, reading = task
    return int(function == "quadratic") + int(reading == "strict") + 2 * int(mu > 0)


def verdict_data(cases=CASES, mu_values=MU_FORENSIC, *, n_psi: int = 36, candidates=VERDICT_CANDIDATES,
                 workers: int | None = None):
    """The engine's verdicts about the trimmed helicopter's periodic motion
    (:meth:`BladeParameters.flight_case`, :func:`forward_flight_trim`, its own state in hover),
    as a :class:`rotorlyap.chapters.scans.ScanData` (for
    :func:`rotorlyap.chapters.scans.figure_scan`): categories of
    :data:`rotorlyap.chapters.scans.SCAN_CATEGORY_NAMES`, 4 where the linearised blade is
    unstable and no quadratic function exists. The trims run here; the cells, independent, in
    ``workers`` fresh processes (default: every core; 1: here, one after the other; the same
    verdicts either way, :func:`rotorlyap.analysis.sweep.process_map`).
    """
    mu_values = np.asarray(mu_values, dtype=float)
    trims = {(case, float(mu)): forward_flight_trim(BladeParameters.flight_case(case), float(mu))
             for case in cases for mu in mu_values}
    # the trim's own state in hover too: past a fold of the hover branch (the backward C.G. with
    # compressible sections) a new equilibrium at the trimmed collective is another, stable one
    steadies = {key: (tr.steady if key[1] == 0.0 else tabulate_motion(tr.motion, 1024)) for key, tr in trims.items()}
    psi = TWO_PI * np.arange(n_psi) / n_psi
    shape = (len(candidates), len(cases), mu_values.size, n_psi)
    cat = np.zeros(shape, dtype=int)
    stable = np.zeros(shape, dtype=bool)
    lam = np.zeros(shape)
    aused = np.full(shape[:3], np.nan)
    astep3 = np.full(shape[:3], np.nan)
    tasks, where = [], []
    for c, (_, function, reading) in enumerate(candidates):
        for i, case in enumerate(cases):
            for j, mu in enumerate(mu_values):
                tr = trims[(case, float(mu))]
                tasks.append((tr.params, float(mu), steadies[(case, float(mu))], n_psi, function, reading))
                where.append((c, i, j))
    workers = worker_count(workers, len(tasks))
    outcomes = (process_map(_verdict_cell, tasks, workers, cost=_verdict_cost) if workers > 1
                else [_verdict_cell(t) for t in tasks])
    msgs = [[[None] * mu_values.size for _ in cases] for _ in candidates]
    for (c, i, j), r in zip(where, outcomes):
        if isinstance(r, str):
            cat[c, i, j] = 4
            msgs[c][i][j] = r
            continue
        stable[c, i, j] = r.stable
        cat[c, i, j] = _category(r)
        lam[c, i, j] = r.lambda0
        aused[c, i, j] = r.A
        astep3[c, i, j] = r.A_step3
        msgs[c][i][j] = r.message
    msgs = [tuple(tuple(row) for row in per_case) for per_case in msgs]
    return ScanData(cases=tuple(cases), mu_values=mu_values, psi=psi,
                    keys=tuple(f"{f}_{r}" for _, f, r in candidates), labels=tuple(lab for lab, _, _ in candidates),
                    readings=tuple(r for _, _, r in candidates), category=cat, stable=stable, lambda0=lam,
                    A_used=aused, A_step3=astep3, weights=np.full((len(cases), 6), np.nan), messages=tuple(msgs))


def verdict_summary(scan) -> str:
    """Per candidate and case, the stable azimuths at each advance ratio, and the cells without
    a quadratic function."""
    lines = []
    for c, label in enumerate(scan.labels):
        lines.append(f"{label}; mu: {_fmt(scan.mu_values, 2)}")
        for i, case in enumerate(scan.cases):
            none = int((scan.category[c, i] == 4).all(axis=1).sum())
            lines.append(f"  {case:8s} azimuths passing, of {scan.psi.size}: {scan.stable[c, i].sum(axis=1)}"
                         + (f"  (no quadratic function at {count(none, 'advance ratio')})" if none else ""))
    return "\n".join(lines)


def verdict_facts(scan) -> dict:
    """Stable cells per candidate in forward flight (``ch8_v<k>_fw_stable``), and per case the
    largest advance ratio up to which the last candidate (the strict one) holds at every azimuth
    (``ch8_v_strict_upto_<case>``) and its forward-flight cells (``ch8_v_strict_fw_<case>``)."""
    fw = scan.mu_values > 0
    out = {f"ch8_v{c}_fw_stable": int(scan.stable[c][:, fw].sum()) for c in range(len(scan.labels))}
    strict = scan.stable[-1]
    for i, case in enumerate(scan.cases):
        whole = np.logical_and.accumulate(strict[i].all(axis=1))
        upto = scan.mu_values[whole]
        out[f"ch8_v_strict_upto_{case}"] = f"{upto[-1]:g}" if upto.size else "none"
        out[f"ch8_v_strict_fw_{case}"] = int(strict[i][fw].sum())
    return out
