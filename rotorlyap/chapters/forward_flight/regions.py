"""Chapter 6, forward flight: the regions of instability on a grid of advance ratios and
azimuths in both readings (the paper's Fig. 8), on the rotor disc and in the (psi, mu) plane,
with their categories, legend and reverse-flow mark, and the hover flutter check (linear theory
against the practical reading in hover).

Part of :mod:`rotorlyap.chapters.forward_flight`, which re-exports its names.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...analysis.stability import blade_stability
from ...conventions import DEFAULT_A, PAPER_TEST_DISTURBANCES
from ...model.modes import hover_modes, least_damped
from ...model.parameters import BladeParameters
from ..cases import CASES, MU_GRID, MU_GRID_STRICT, READING_LABELS, _line, case_params
from ..style import (CATEGORY_COLORS, CATEGORY_HATCHES, HATCH_COLOR, HATCH_LINEWIDTH, draw_categories, figure, finish,
                     subplots)

__all__ = [
    "CATEGORY_NAMES", "REVERSE_FLOW_HATCH", "reverse_flow_boundary", "category_legend_handles",
    "RegionsData", "regions_data", "plot_regions_polar", "plot_regions_plane",
    "RegionMaps", "region_maps", "figure_regions_polar", "figure_regions_plane",
    "HoverFlutterCheck", "hover_flutter_check",
]


#: Categories of a (mu, psi) cell in :class:`RegionsData`.
CATEGORY_NAMES = (
    "passes: step 6 holds",
    "step 6 fails at this azimuth",
    "step 3 failed elsewhere (A1 = 0); W' <= 0 here on ||x|| = A",
    "step 3 failed (A1 = 0) and W' > 0 here on ||x|| = A",
)

#: Hatch of the region where reverse flow reaches the blade root, drawn over the verdict maps
#: with an outline: vertical lines, unlike the diagonal and dotted hatches of the verdicts
#: (:data:`rotorlyap.chapters.style.CATEGORY_HATCHES`).
REVERSE_FLOW_HATCH = "||"


def category_legend_handles(reverse_flow_label: str = "reverse flow reaches the blade root", *,
                            wrap: int | None = None) -> list:
    """Legend handles of the region maps: one patch per :data:`CATEGORY_NAMES`, in its colour and
    hatch, and the outlined, hatched reverse-flow region; ``wrap`` breaks the labels into lines
    of at most that many characters."""
    import textwrap

    from matplotlib.patches import Patch

    def lab(text):
        return text if wrap is None else "\n".join(textwrap.wrap(text, wrap))

    handles = [Patch(facecolor=c, hatch=h, edgecolor="0.3", hatchcolor=HATCH_COLOR, lw=0.6, label=lab(n),
                     hatch_linewidth=HATCH_LINEWIDTH)
               for c, h, n in zip(CATEGORY_COLORS, CATEGORY_HATCHES, CATEGORY_NAMES)]
    handles.append(Patch(facecolor="none", edgecolor="k", hatch=REVERSE_FLOW_HATCH, hatchcolor="k", lw=1.5,
                         label=lab(reverse_flow_label)))
    return handles


def _reverse_flow(ax, th, rb, top) -> None:
    """Hatch (:data:`REVERSE_FLOW_HATCH`) and outline the region ``rb <= r <= top`` over the
    azimuths ``th`` where ``rb <= top``: where reverse flow reaches the blade root."""
    import matplotlib.patheffects as pe

    ok = rb <= top
    if not ok.any():
        return
    ax.fill_between(th[ok], rb[ok], top, facecolor="none", edgecolor="k", hatch=REVERSE_FLOW_HATCH, lw=0.0)
    t, r = th[ok], rb[ok]
    # the outline: the boundary, then back along the rim (white-edged, to stand out on any colour)
    ax.plot(np.concatenate([t, np.linspace(t[-1], t[0], 90)]), np.concatenate([r, np.full(90, top)]),
            "k-", lw=1.5, path_effects=[pe.withStroke(linewidth=3.0, foreground="w")], clip_on=False)


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
# Fig. 8: regions of instability
# --------------------------------------------------------------------------------------


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

    def positive_side_fractions(self, case_index: int = 0) -> tuple[np.ndarray, np.ndarray]:
        """Fractions of the advancing (0 to 180 deg) and retreating (180 to 360 deg) azimuths
        with ``W' > 0`` on the requested sphere (category 3), per advance ratio, (m,) each."""
        pos = self.category[case_index] == 3
        adv = (self.psi > 0) & (self.psi < np.pi)
        ret = self.psi > np.pi
        return (np.array([pos[i, adv].mean() for i in range(self.mu_values.size)]),
                np.array([pos[i, ret].mean() for i in range(self.mu_values.size)]))

    def summary(self) -> str:
        """The reading, the advance ratios, per case the stable azimuths and the bound after
        step 3 per ``mu``, and the cells with ``W' > 0`` on the requested sphere."""
        lines = [self.label, _line("  mu:", self.mu_values)]
        for k, case in enumerate(self.cases):
            lines.append(_line(f"  {case:9s} azimuths passing:", self.stable[k].sum(axis=1),
                               " A after step 3:", np.round(self.A_used[k], 3)))
        lines.append(_line("  cells with W' > 0 on the sphere (step 3 failed):", int((self.category == 3).sum()),
                           "of", self.category.size))
        return "\n".join(lines)

    def side_summary(self) -> str:
        """Whether the per-azimuth picture (``W' > 0`` on the sphere) is the same for every
        case, and its fractions on the advancing and retreating sides per ``mu`` (0.01)."""
        pos = self.category == 3
        adv, ret = self.positive_side_fractions(0)
        lines = [_line(f"{self.reading}, W' > 0 on the sphere: the same map for every C.G.:",
                       all(np.array_equal(pos[0], pos[k]) for k in range(len(self.cases)))),
                 f"{self.reading}, fraction of azimuths with W' > 0 on the sphere, advancing / retreating side:"]
        lines += [f"  mu = {mu:.4f}: {a:.2f} / {r:.2f}" for mu, a, r in zip(self.mu_values, adv, ret)]
        return "\n".join(lines)

    def export(self) -> list:
        """One row per (case, mu, psi) cell for :func:`rotorlyap.chapters.export.figure_csv`:
        case index, ``mu``, ``psi`` (deg), category, stable and ``max_dW`` (J/rad)."""
        k, m, n = self.category.shape
        return [("case", np.repeat(np.arange(k), m * n)),
                ("mu", np.tile(np.repeat(self.mu_values, n), k)),
                ("psi_deg", np.tile(np.degrees(self.psi), k * m)),
                ("category", self.category.ravel()), ("stable", self.stable.ravel()),
                ("max_dW", self.max_dW.ravel())]


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


def plot_regions_polar(data: RegionsData, ax, case_index: int = 0, *, title: str | None = None) -> None:
    """The verdict on the rotor disc seen from above: azimuth as angle, radius = mu.

    ``psi = 0`` points to the tail (bottom), rotation counter-clockwise, so the advancing
    side (``psi = 90 deg``) is on the right; each verdict in its colour and hatch; hatched
    with vertical lines and outlined: where reverse flow reaches the blade root
    (``mu |sin psi| > (R - R1)/R`` on the retreating side). A ``mu = 0`` row (hover) is drawn
    as a central disc below ``r = 0``, so that the radius of every other row is exactly its
    advance ratio.
    """
    import matplotlib.patheffects as pe

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
    draw_categories(ax, th_edges, r_edges, data.category[case_index], CATEGORY_COLORS, CATEGORY_HATCHES)
    th = np.linspace(np.pi, 2 * np.pi, 361)
    rb = data.root_r_over_R / np.maximum(-np.sin(th), 1e-9)
    rmax = r_edges[-1]
    _reverse_flow(ax, th, rb, rmax)
    ax.set_ylim(-hole, rmax)
    ticks = [m for m in (0.05, 0.1, 0.15, 0.2, 0.25) if m <= rmax]
    ax.set_yticks(ticks)
    ax.set_yticklabels([f"{m:g}" for m in ticks])
    ax.tick_params(axis="y", labelsize=8)
    ax.set_rlabel_position(157.5)
    names = {0: "0°\ntail", 90: "90°\nadvancing", 180: "nose\n180°", 270: "retreating\n270°"}
    ax.set_xticks(np.radians(np.arange(0, 360, 45)))
    ax.set_xticklabels([names.get(d, f"{d}°") for d in range(0, 360, 45)], fontsize=8)
    ax.tick_params(axis="x", pad=2)
    for lab in ax.get_xticklabels():
        # the side labels are wide: anchor them at their inner edge, clear of the disc
        if "advancing" in lab.get_text():
            lab.set(color="tab:orange", ha="left")
        elif "retreating" in lab.get_text():
            lab.set(color="tab:blue", ha="right")
    for lab in ax.get_yticklabels():
        lab.set_path_effects([pe.withStroke(linewidth=2.5, foreground="w")])
    case = data.cases[case_index]
    ax.set_title(title or f"{case} C.G.", fontsize=9, pad=20)


def plot_regions_plane(data: RegionsData, ax, case_index: int = 0, *, title: str | None = None,
                       legend: bool = True) -> None:
    """The verdict in the (psi, mu) plane, each verdict in its colour and hatch, with the
    reverse-flow region (hatched with vertical lines and outlined)."""
    deg = np.degrees(data.psi)
    step = deg[1] - deg[0]
    top = _edges(data.mu_values, lo=0.0)[-1]
    draw_categories(ax, np.concatenate([deg - step / 2, [deg[-1] + step / 2]]), _edges(data.mu_values, lo=0.0),
                     data.category[case_index], CATEGORY_COLORS, CATEGORY_HATCHES)
    th = np.linspace(180, 360, 361)
    rb = data.root_r_over_R / np.maximum(-np.sin(np.radians(th)), 1e-9)
    _reverse_flow(ax, th, rb, top)
    ax.axvline(180, color="k", lw=1.2, ls=":", zorder=5)  # on top of the hatching
    ax.text(90, 1.01, "advancing", transform=ax.get_xaxis_transform(), ha="center", fontsize=8, color="tab:orange")
    ax.text(270, 1.01, "retreating", transform=ax.get_xaxis_transform(), ha="center", fontsize=8, color="tab:blue")
    ax.set_xlim(0, 360)
    ax.set_ylim(0, top)
    ax.set_xticks(np.arange(0, 361, 90))
    ax.set_xlabel(r"azimuth $\psi$ (deg)", fontsize=9)
    ax.set_ylabel(r"advance ratio $\mu$", fontsize=9)
    ax.tick_params(labelsize=8)
    ax.set_title(title or f"{data.cases[case_index]} C.G.", fontsize=9, pad=14)
    if legend:
        ax.legend(handles=category_legend_handles(wrap=34), fontsize=8, loc="upper left", bbox_to_anchor=(1.02, 1.0))


@dataclass(frozen=True)
class RegionMaps:
    """The Fig. 8 maps of chapter 6 in both readings.

    Attributes
    ----------
    practical, strict : RegionsData
    """

    practical: RegionsData
    strict: RegionsData

    def summary(self) -> str:
        """Both maps' :meth:`RegionsData.summary`, then the practical per-azimuth picture."""
        return "\n".join([self.practical.summary(), self.strict.summary(), self.practical.side_summary()])

    def facts(self) -> dict:
        """Chapter 6's Fig. 8 numbers: practical ``ch6_p_hover_stable`` of ``ch6_p_n_hover``
        (case, azimuth) pairs in hover, ``ch6_p_mu1`` (first ``mu > 0``), ``ch6_p_fw_stable``
        (stable cells in forward flight), ``ch6_p_lambda0`` (forward C.G. in hover),
        ``ch6_p_adv/ret_<1, mid, last>`` (side fractions of ``W' > 0`` at the first ``mu > 0``,
        at ``mu`` = ``ch6_p_mu_mid`` = 0.1 and at the last); strict ``ch6_s_stable`` of
        ``ch6_s_cells``; ``ch6_root`` (blade root station ``r/R``)."""
        p, s = self.practical, self.strict
        out = {
            "ch6_p_hover_stable": int(p.stable[:, 0].sum()),
            "ch6_p_n_hover": int(p.stable[:, 0].size),
            "ch6_p_mu1": float(p.mu_values[1]),
            "ch6_p_fw_stable": int(p.stable[:, 1:].sum()),
            "ch6_s_stable": int(s.stable.sum()),
            "ch6_s_cells": int(s.stable.size),
            "ch6_root": round(p.root_r_over_R, 3),
            "ch6_p_lambda0": round(float(p.lambda0[0, 0].min()), 3),
        }
        adv, ret = p.positive_side_fractions(0)
        i_mid = int(np.flatnonzero(np.isclose(p.mu_values, 0.1))[0])
        for tag, i in (("1", 1), ("mid", i_mid), ("last", -1)):
            out[f"ch6_p_adv_{tag}"] = round(float(adv[i]), 2)
            out[f"ch6_p_ret_{tag}"] = round(float(ret[i]), 2)
        out["ch6_p_mu_mid"] = float(p.mu_values[i_mid])
        return out


def region_maps(cases=CASES, mu_practical=MU_GRID, mu_strict=MU_GRID_STRICT, *, n_psi: int = 72,
                n_sphere_strict: int = 64) -> RegionMaps:
    """:func:`regions_data` in the practical reading on ``mu_practical`` and in the strict
    reading on ``mu_strict`` (``n_sphere_strict`` quasi-random directions per sphere)."""
    return RegionMaps(
        practical=regions_data(cases, mu_practical, reading="practical", n_psi=n_psi),
        strict=regions_data(cases, mu_strict, reading="strict", n_psi=n_psi, n_sphere=n_sphere_strict),
    )


def _regions_grid(readings) -> tuple[int, int, list]:
    """Panels of the region figures: with two or more readings one column per reading and one
    row per case; with one reading its cases two to a row. Returns ``(nrows, ncols, panels)``,
    ``panels`` a list of ``(index in the grid, reading, case index)``."""
    ncases = max(len(r.cases) for r in readings)
    if len(readings) > 1:
        ncols, nrows = len(readings), ncases
        panels = [(k * ncols + j, reg, k) for j, reg in enumerate(readings) for k in range(len(reg.cases))]
    else:
        ncols = min(2, ncases)
        nrows = -(-ncases // ncols)
        panels = [(k, readings[0], k) for k in range(len(readings[0].cases))]
    return nrows, ncols, panels


def _region_legend(fig, ncols: int, empty_ax=None):
    """The category legend of a region figure: in ``empty_ax`` (a spare grid cell) if given,
    else below the panels, two columns wide if the figure has two; returns the layout's
    ``rect`` keyword."""
    if empty_ax is not None:
        empty_ax.axis("off")
        fig.legend(handles=category_legend_handles(wrap=34), loc="center", fontsize=8,
                   bbox_to_anchor=(0.5, 0.5), bbox_transform=empty_ax.transAxes)
        return {}
    two = ncols > 1
    fig.legend(handles=category_legend_handles(wrap=None if two else 40), loc="lower center",
               ncol=2 if two else 1, fontsize=8)
    height = 3 * 0.2 + 0.15 if two else 5 * 0.2 + 0.4  # legend rows of 8 pt, 0.2 in each, and margins
    return {"rect": (0, height / fig.get_size_inches()[1], 1, 1)}


def figure_regions_polar(*readings: RegionsData, figsize=None):
    """The book's Fig. 8 on the rotor disc (:func:`plot_regions_polar`): with two readings one
    column per reading and one row per case, with one reading its cases two to a row; the
    category legend below (or in a spare cell). ``figsize`` defaults to 4.3 in per column and
    3.75 in per row plus the legend (8.6 x 12.0 in for the book's two readings of three cases).
    Laid out and checked (:func:`rotorlyap.chapters.style.finish`); returns the Figure."""
    nrows, ncols, panels = _regions_grid(readings)
    spare = len(readings) == 1 and nrows * ncols > len(panels)
    if figsize is None:
        figsize = (4.3 * ncols, 3.75 * nrows + (0 if spare else 0.75 if ncols > 1 else 1.4))
    fig = figure(figsize=figsize)
    for idx, reg, k in panels:
        ax = fig.add_subplot(nrows, ncols, idx + 1, projection="polar")
        plot_regions_polar(reg, ax, k, title=f"{reg.cases[k]} C.G., {reg.label}")
    empty = fig.add_subplot(nrows, ncols, nrows * ncols) if spare else None
    return finish(fig, **_region_legend(fig, ncols, empty))


def figure_regions_plane(*readings: RegionsData, figsize=None):
    """The maps of :func:`figure_regions_polar` in the (psi, mu) plane
    (:func:`plot_regions_plane`), in the same grid; ``figsize`` defaults to 4.3 in per column
    and 2.75 in per row plus the legend (8.6 x 9.0 in for the book's two readings of three
    cases). Laid out and checked (:func:`rotorlyap.chapters.style.finish`); returns the Figure."""
    nrows, ncols, panels = _regions_grid(readings)
    spare = len(readings) == 1 and nrows * ncols > len(panels)
    if figsize is None:
        figsize = (4.3 * ncols, 2.75 * nrows + (0 if spare else 0.75 if ncols > 1 else 1.4))
    fig, axes = subplots(nrows, ncols, figsize=figsize, sharex=True, squeeze=False)
    axes = axes.ravel()
    for idx, reg, k in panels:
        ax = axes[idx]
        plot_regions_plane(reg, ax, k, title=f"{reg.cases[k]} C.G., {reg.label}", legend=False)
        if not ax.get_subplotspec().is_last_row():
            ax.set_xlabel("")
        if not ax.get_subplotspec().is_first_col():
            ax.set_ylabel("")
    empty = axes[-1] if spare else None
    return finish(fig, **_region_legend(fig, ncols, empty))


@dataclass(frozen=True)
class HoverFlutterCheck:
    """Linear theory against the practical reading in hover: the largest growth rate of each
    case, and a blade that flutters (a case without the aerodynamic pitch damping,
    ``cm_pitch_rate = 0``) in the practical reading.

    Attributes
    ----------
    case_names : tuple of str
    growth_rate : numpy.ndarray
        Largest real part of the linearised hover eigenvalues of each case, per rev, (3,).
    flutter_case : str
    flutter_growth_rate : float
        The same for the fluttering blade, per rev.
    flutter_stable : int
        Azimuths the practical reading calls stable for it, of ``n_psi``.
    n_psi : int
    """

    case_names: tuple
    growth_rate: np.ndarray
    flutter_case: str
    flutter_growth_rate: float
    flutter_stable: int
    n_psi: int

    def summary(self) -> str:
        """The fluttering blade's growth rate (per rev, 0.001) and practical verdict."""
        return (f"{self.flutter_case} C.G. without pitch damping, hover: largest real part "
                f"{self.flutter_growth_rate:+.3f}, practical (indicator): passes at {self.flutter_stable} of {self.n_psi} azimuths")

    def facts(self) -> dict:
        """``ch6_flut_re`` (signed text, per rev) and ``ch6_flut_stable`` (azimuths)."""
        return {"ch6_flut_re": f"{self.flutter_growth_rate:+.3f}", "ch6_flut_stable": self.flutter_stable}


def hover_flutter_check(cases=CASES, flutter_case: str = "backward", *, n_psi: int = 72,
                        test_disturbances=PAPER_TEST_DISTURBANCES) -> HoverFlutterCheck:
    """Compute :class:`HoverFlutterCheck` (:func:`rotorlyap.model.modes.hover_modes`, then the
    practical reading of the fluttering blade on ``n_psi`` azimuths)."""
    p_flut = case_params(flutter_case, cm_pitch_rate=0.0)
    stable = blade_stability(p_flut, 0.0, n_psi=n_psi, test_disturbances=test_disturbances).stable
    return HoverFlutterCheck(
        case_names=tuple(cases),
        growth_rate=np.array([least_damped(hover_modes(case_params(c))).growth_rate for c in cases]),
        flutter_case=flutter_case, flutter_growth_rate=float(least_damped(hover_modes(p_flut)).growth_rate),
        flutter_stable=int(stable.sum()), n_psi=int(n_psi),
    )
