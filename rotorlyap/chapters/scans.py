"""The certificate scans' verdict maps, shared by chapter 7 ("Validation and beyond",
:mod:`rotorlyap.chapters.validation`) and chapter 8 (the trimmed helicopter,
:mod:`rotorlyap.chapters.trimmed_flight`).

:class:`ScanData` holds the engine's verdict for every candidate Liapunov function, case,
advance ratio and azimuth, each cell in one of the categories :data:`SCAN_CATEGORY_NAMES`
(:func:`_category`); :func:`figure_scan` draws it in the (psi, mu) plane. Beside them, the
advance ratios of chapter 8's test of the paper's Fig. 8 (:data:`MU_FORENSIC`, whose step
chapter 9 quotes) and the small text and layout helpers of the scans' summaries and figures.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from ..conventions import DEFAULT_SCALES
from .export import markdown_table
from .style import (CATEGORY_COLORS, CATEGORY_HATCHES, HATCH_COLOR, HATCH_LINEWIDTH, SCAN_EXTRA_COLORS,
                    SCAN_EXTRA_HATCHES, draw_categories, finish, subplots)

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["MU_FORENSIC", "SCAN_CATEGORY_NAMES", "ScanData", "plot_scan", "figure_scan", "scan_legend_handles"]

#: Advance ratios of the forensic test of Fig. 8 (the paper's range, in its Fig. 8 steps).
MU_FORENSIC = (0.0, 0.05, 0.1, 0.15, 0.2, 0.25)

#: Short names of the cases in chapter 7's glue names (``ch7_ncert_q_neu``, ...).
_CASE_TAGS = {"forward": "fw", "neutral": "neu", "backward": "bwd"}


def _join(*parts) -> str:
    """The line ``print(*parts)`` writes, without its newline."""
    return " ".join(str(p) for p in parts)


def _mu_list(values) -> str:
    """Advance ratios as the chapter's text quotes them: ``"0.2, 0.25"``."""
    return ", ".join(f"{float(m):g}" for m in values)


def _edges(values, lo=None) -> np.ndarray:
    v = np.asarray(values, dtype=float)
    mid = 0.5 * (v[1:] + v[:-1])
    first = v[0] - (mid[0] - v[0]) if lo is None else lo
    return np.concatenate([[first], mid, [v[-1] + (v[-1] - mid[-1])]])


def _legend_height(fig, legend, pad_in: float = 0.05) -> float:
    """Height of a figure legend placed at the bottom, as a fraction of the figure's height
    (for ``tight_layout(rect=(0, h, 1, 1))``)."""
    fig.draw_without_rendering()
    return (legend.get_window_extent().height / fig.dpi + pad_in) / fig.get_size_inches()[1]


#: Outcome of one (azimuth, advance ratio) cell; the first four as in the Fig. 8 chapter.
SCAN_CATEGORY_NAMES = (
    "passes (practical: indicator) / certified (strict: (h) over the whole period)",
    "paper's step 6 fails at this azimuth (practical)",
    "nothing certified (A = 0); W' <= 0 here on ||x|| = A",
    "nothing certified (A = 0); W' > 0 here on ||x|| = A",
    "no quadratic function: linearisation unstable",
    "no periodic motion found",
)
_SCAN_COLORS = CATEGORY_COLORS + SCAN_EXTRA_COLORS


def _category(res) -> np.ndarray:
    """Index into :data:`SCAN_CATEGORY_NAMES` of each azimuth of an engine result
    (:class:`~rotorlyap.methods.lyapunov.TechnicalStabilityResult`)."""
    if res.A > 0:
        return np.where(res.stable, 0, 1)
    return np.where(res.max_dW > res.tol, 3, 2)


@dataclass(frozen=True)
class ScanData:
    """The engine's verdict for every candidate, case, advance ratio and azimuth.

    Attributes
    ----------
    cases, mu_values, psi
        The grid: (k,), (m,), (n,).
    keys, labels, readings : tuple of str
        The candidates (:data:`~rotorlyap.chapters.validation.scan.CANDIDATES`), (c,).
    category : numpy.ndarray
        Index into :data:`SCAN_CATEGORY_NAMES`, (c, k, m, n).
    stable : numpy.ndarray
        Boolean (c, k, m, n).
    lambda0 : numpy.ndarray
        (c, k, m, n); 0 where no result.
    A_used : numpy.ndarray
        The certified bound ``A`` (0 where nothing is certified), (c, k, m); NaN where no result.
    A_step3 : numpy.ndarray
        Step 3's bound ``A1`` (``W' <= 0`` on the sphere itself), (c, k, m); NaN where no
        result. The sound rule's ``A`` is at most this: it shrinks ``A`` until (h) holds on the
        whole band.
    weights : numpy.ndarray
        Optimised diagonal weights ``w_i`` (``Q = diag(w / a**2)``), per case, (k, 6); NaN
        where none exists.
    messages : tuple
        Per candidate and case, per advance ratio: the engine's message or why no result.
    results : dict
        ``{(key, case, mu): TechnicalStabilityResult}`` (not compared, not exported).
    """

    cases: tuple
    mu_values: np.ndarray
    psi: np.ndarray
    keys: tuple
    labels: tuple
    readings: tuple
    category: np.ndarray
    stable: np.ndarray
    lambda0: np.ndarray
    A_used: np.ndarray
    A_step3: np.ndarray
    weights: np.ndarray
    messages: tuple
    results: dict = field(default_factory=dict, compare=False, repr=False)

    def result(self, key: str, case: str, mu: float):
        """The engine's result, or None."""
        return self.results.get((key, case, round(float(mu), 6)))

    def export(self) -> list:
        """Long columns: one row per (candidate, case, mu, psi)."""
        c, k, m, n = self.category.shape
        idx = np.indices((c, k, m, n)).reshape(4, -1)
        return [("candidate", [self.keys[i] for i in idx[0]]), ("case", [self.cases[i] for i in idx[1]]),
                ("mu", self.mu_values[idx[2]]), ("psi_deg", np.degrees(self.psi)[idx[3]]),
                ("category", self.category.ravel()), ("lambda0", self.lambda0.ravel())]

    def min_certified_lambda0(self, key: str, case: str) -> tuple:
        """Smallest ``lambda0`` over the stable azimuths at each advance ratio (norm units),
        NaN where no azimuth is stable."""
        c, i = self.keys.index(key), self.cases.index(case)
        return tuple(float(self.lambda0[c, i, j][self.stable[c, i, j]].min()) if self.stable[c, i, j].any()
                     else float("nan") for j in range(self.mu_values.size))

    def summary(self) -> str:
        """Per candidate, case and advance ratio: ``passing or certified / step-6-fails`` azimuth counts, or why
        nothing is certified (``s3``, ``band``, ``noQ``, ``noXi``); the optimised weights of the
        forward C.G."""
        lines = [_join("mu:", self.mu_values)]
        why = {4: "noQ", 5: "noXi"}
        for c in range(len(self.keys)):
            lines.append(self.labels[c])
            for i, case in enumerate(self.cases):
                cells = []
                for j in range(self.mu_values.size):
                    counts = np.bincount(self.category[c, i, j], minlength=6)
                    if counts[:2].sum():
                        cells.append("/".join(str(int(v)) for v in counts[[0, 1]]))
                    else:
                        k = int(np.argmax(counts))
                        cells.append(why.get(k) or ("s3" if not self.A_step3[c, i, j] > 0 else "band"))
                lines.append(_join(f"   {case:9s}", "  ".join(f"{v:>6s}" for v in cells)))
        lines.append(f"(passing or certified / step-6-fails azimuths of {self.psi.size}; s3 = step 3 failed, W' > 0 on "
                     "every sphere; band = (h) failed on the band for every bound; "
                     "noQ = no quadratic function; noXi = no periodic motion)")
        lines.append(_join("optimised weights (forward C.G.):", np.round(self.weights[self.cases.index("forward")], 3)))
        return "\n".join(lines)

    def certificate_rows(self, case: str = "forward", keys: tuple = ("quadratic", "quadratic-opt")) -> list:
        """Rows of the certificate table: function, mu, ``A1`` of step 3, the certified bound
        ``A``, smallest and largest certified ``lambda0`` (three decimals), azimuths certified."""
        i, rows = self.cases.index(case), []
        for key in keys:
            c = self.keys.index(key)
            for j, mu in enumerate(self.mu_values):
                lam, ok = self.lambda0[c, i, j], self.stable[c, i, j]
                rows.append((self.labels[c], f"{mu:g}", f"{self.A_step3[c, i, j]:.3f}", f"{self.A_used[c, i, j]:.3f}",
                             f"{lam[ok].min():.3f}" if ok.any() else "-", f"{lam[ok].max():.3f}" if ok.any() else "-",
                             f"{int(ok.sum())} of {ok.size}"))
        return rows

    def certificate_table(self, case: str = "forward") -> str:
        """:meth:`certificate_rows` as a Markdown table."""
        return markdown_table((f"function ({case} C.G., strict, about the periodic motion)", "mu",
                               "A1 (step 3)", "A certified", "min lambda0", "max lambda0",
                               "azimuths certified"), self.certificate_rows(case))

    def _backward_mu(self) -> tuple:
        """Advance ratios of the backward C.G. with ``Q = I``: every azimuth certified, some,
        step 3 failed (``W' > 0`` on every sphere), (h) failed on the band for every bound; and
        of the neutral C.G., optimised: nothing certified."""
        cq, co = self.keys.index("quadratic"), self.keys.index("quadratic-opt")
        ib, ineu = self.cases.index("backward"), self.cases.index("neutral")
        ok = self.stable[cq, ib].all(axis=1)
        part = self.stable[cq, ib].any(axis=1) & ~ok
        ran = ~np.isin(self.category[cq, ib, :, 0], (4, 5))
        s3 = ran & ~(self.A_step3[cq, ib] > 0)
        band = ran & (self.A_step3[cq, ib] > 0) & ~(self.A_used[cq, ib] > 0)
        none_neu = ~self.stable[co, ineu].any(axis=1)
        mu = self.mu_values
        return mu[ok], mu[part], mu[s3], mu[band], mu[none_neu]

    def _energy_sides(self) -> tuple:
        """For the energy, practical, about the periodic motion (forward C.G.): the advance
        ratios where no azimuth is stable, and the share of azimuths with ``W' > 0`` on the
        sphere over the rear (270 to 90 deg) and the front half of the disc, per advance ratio."""
        cp, fwd = self.keys.index("energy-practical"), self.cases.index("forward")
        deg = np.degrees(self.psi)
        dark = self.category[cp, fwd] == 3
        tail = (deg < 90) | (deg >= 270)
        return ~self.stable[cp, fwd].any(axis=1), dark, tail

    def certificate_summary(self) -> str:
        """What the certificate table below it does not hold: where the energy's practical
        reading fails over the disc, the certified cells of the neutral and backward C.G., and
        the advance ratios of each outcome of the backward C.G. (an outcome at no advance ratio
        is left out)."""
        lines = []
        fail, dark, tail = self._energy_sides()
        label = self.labels[self.keys.index("energy-practical")]
        for j, mu in enumerate(self.mu_values):
            if j and fail[j]:
                lines.append(f"{label}, mu = {mu:g}: W' > 0 on the sphere at "
                             f"{dark[j, tail].mean():.2f} of the azimuths over the rear half (270 to 90 deg), "
                             f"{dark[j, ~tail].mean():.2f} over the front half")
        cq, co = self.keys.index("quadratic"), self.keys.index("quadratic-opt")
        for case in ("neutral", "backward"):
            i = self.cases.index(case)
            lam_h = self.lambda0[cq, i, 0][self.stable[cq, i, 0]]
            lines.append(f"{case} C.G.: certified cells, Q = I {int(self.stable[cq, i].sum())}, optimised "
                         f"{int(self.stable[co, i].sum())} of {self.stable[cq, i].size}; hover lambda0 (Q = I) "
                         f"{lam_h.min():.2g}")
            lines.append(_join("   per mu (Q = I):", self.stable[cq, i].sum(axis=1)))
        ok, part, s3, band, none_neu = self._backward_mu()
        parts = [f"{what} {_mu_list(mu)}" for what, mu in
                 (("every azimuth certified at mu =", ok), ("some azimuths at mu =", part),
                  ("step 3 failed at mu =", s3), ("(h) failed on the band at mu =", band)) if mu.size]
        lines.append("backward, Q = I: " + "; ".join(parts))
        lines.append("neutral, optimised: " + (f"nothing certified at mu = {_mu_list(none_neu)}" if none_neu.size
                                               else "certified at every advance ratio"))
        return "\n".join(lines)

    def facts(self) -> dict:
        """The numbers the chapter quotes about the scans: certified start regions and bounds
        of the forward C.G. (norm units, three and two decimals; deg of flap), counts of
        certified cells, where the energy's practical reading fails and on which half of the
        disc, the hover lambda0 of the other cases (two significant digits) and the advance
        ratios where the backward and neutral C.G. are certified or step 3 fails."""
        fwd = self.cases.index("forward")
        cq, co = self.keys.index("quadratic"), self.keys.index("quadratic-opt")
        ce, cp, cqh = self.keys.index("energy"), self.keys.index("energy-practical"), self.keys.index("quadratic-hover")
        lam_q = self.min_certified_lambda0("quadratic", "forward")
        lam_o = self.min_certified_lambda0("quadratic-opt", "forward")
        fail, dark, tail = self._energy_sides()
        out = {
            "ch7_lam_q0": round(lam_q[0], 3),
            "ch7_lam_q25": round(lam_q[-1], 3),
            "ch7_lam_o0": round(lam_o[0], 3),
            "ch7_lam_o_min": round(float(np.nanmin(lam_o[1:])), 3),
            "ch7_lam_o_max": round(float(np.nanmax(lam_o[1:])), 3),
            "ch7_fwd_opt_none_mu": _mu_list(self.mu_values[~self.stable[co, fwd].any(axis=1)]),
            "ch7_A_q0": round(float(self.A_used[cq, fwd, 0]), 2),
            "ch7_A_o0": round(float(self.A_used[co, fwd, 0]), 2),
            "ch7_deg_o0": round(float(lam_o[0] * np.degrees(DEFAULT_SCALES[0])), 2),
            "ch7_ncert_q": int(self.stable[cq, fwd].sum()),
            "ch7_ncert_o": int(self.stable[co, fwd].sum()),
            "ch7_ncells": int(self.stable[cq, fwd].size),
            "ch7_energy_cert": int(self.stable[ce].sum()),
            "ch7_energy_cells": int(self.stable[ce].size),
            "ch7_ep_mu_last": float(self.mu_values[np.flatnonzero(self.stable[cp, fwd].all(axis=1))[-1]]),
            "ch7_ep_mu_fail": float(self.mu_values[fail][0]),
            "ch7_ep_rear": round(float(dark[fail][:, tail].mean()), 2),
            "ch7_ep_front": round(float(dark[fail][:, ~tail].mean()), 2),
            "ch7_qh_fw": int(self.stable[cqh, :, 1:].sum()),
            "ch7_qh_hover": int(self.stable[cqh, :, 0].sum()),
            "ch7_qh_hover_cells": int(self.stable[cqh, :, 0].size),
        }
        for case in ("neutral", "backward"):
            i, tag = self.cases.index(case), _CASE_TAGS[case]
            out[f"ch7_ncert_q_{tag}"] = int(self.stable[cq, i].sum())
            out[f"ch7_ncert_o_{tag}"] = int(self.stable[co, i].sum())
            out[f"ch7_lam_q0_{tag}"] = float("%.2g" % self.lambda0[cq, i, 0][self.stable[cq, i, 0]].min())
        ok, part, s3, band, none_neu = self._backward_mu()
        out.update({"ch7_bwd_cert_mu": _mu_list(ok), "ch7_bwd_s3_mu": _mu_list(s3),
                    "ch7_bwd_band_mu": _mu_list(band), "ch7_neu_opt_none_mu": _mu_list(none_neu)})
        return out


_SCAN_HATCHES = CATEGORY_HATCHES + SCAN_EXTRA_HATCHES


def plot_scan(data: ScanData, axes, *, rows=None) -> None:
    """The verdicts in the (psi, mu) plane: one row per candidate, one column per case. Each
    category has its colour and its hatch (:data:`rotorlyap.chapters.style.CATEGORY_HATCHES`,
    ``SCAN_EXTRA_HATCHES``), so that the map also reads without colour. The candidate's label
    is the title of the row's middle panel; the figure names the columns (:func:`figure_scan`)."""
    rows = list(range(len(data.keys)) if rows is None else rows)
    deg = np.degrees(data.psi)
    step = deg[1] - deg[0]
    # the azimuth is periodic: the cell about psi = 0 is drawn again past the last one, so that
    # the map fills 0 to 360 deg
    xe = np.concatenate([deg - step / 2, [deg[-1] + step / 2, deg[-1] + 3 * step / 2]])
    ye = _edges(data.mu_values, lo=0.0)
    mid = len(data.cases) // 2
    for r, c in enumerate(rows):
        for i, case in enumerate(data.cases):
            ax = axes[r, i]
            cat = data.category[c, i]
            cat = np.concatenate([cat, cat[:, :1]], axis=1)
            draw_categories(ax, xe, ye, cat, _SCAN_COLORS, _SCAN_HATCHES)
            ax.axvline(180, color="k", lw=0.8, ls=":")
            ax.set_xlim(0, 360)
            ax.set_ylim(0, ye[-1])
            ax.set_xticks(np.arange(0, 361, 90))
            ax.tick_params(labelsize=8.5)
            if i == mid:
                ax.set_title(f"({r + 1}) {data.labels[c]}", fontsize=9.5)
            if r == len(rows) - 1:
                ax.set_xlabel(r"azimuth $\psi$ (deg)", fontsize=9.5)
            if i == 0:
                ax.set_ylabel(r"advance ratio $\mu$", fontsize=9.5)


def scan_legend_handles(categories=None):
    """Legend patches of the scan categories (colour and hatch), all of them or the indices
    ``categories``."""
    from matplotlib.patches import Patch

    keep = range(len(_SCAN_COLORS)) if categories is None else sorted(int(k) for k in categories)
    return [Patch(facecolor=_SCAN_COLORS[k], edgecolor=HATCH_COLOR, hatch=_SCAN_HATCHES[k],
                  label=SCAN_CATEGORY_NAMES[k]) for k in keep]


def figure_scan(data: ScanData) -> Figure:
    """The figure of :func:`plot_scan` (one row per candidate, one column per case, 8.8 in
    wide, 1.7 in per row) with the legend of the categories present below, laid out and closed
    in pyplot.

    Returns
    -------
    matplotlib.figure.Figure
    """
    import matplotlib

    nc = len(data.keys)
    fig, axes = subplots(nc, len(data.cases), figsize=(8.8, 1.7 * nc + 1.6), sharex=True, sharey=True,
                         squeeze=False)
    plot_scan(data, axes)
    for i, case in enumerate(data.cases):  # the columns, above the first row's title
        axes[0, i].annotate(f"{case} C.G.", xy=(0.5, 1.0), xycoords="axes fraction", xytext=(0, 22),
                            textcoords="offset points", ha="center", va="bottom", fontsize=10.5,
                            fontweight="bold")
    with matplotlib.rc_context({"hatch.linewidth": HATCH_LINEWIDTH}):
        leg = fig.legend(handles=scan_legend_handles(np.unique(data.category)), loc="lower center", ncol=2,
                         fontsize=8.5, frameon=False, handlelength=2.4, handleheight=1.5)
    return finish(fig, rect=(0, _legend_height(fig, leg), 1, 1))
