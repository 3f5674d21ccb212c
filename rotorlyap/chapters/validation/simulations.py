"""Chapter 7 ("Validation and beyond"), section 4: simulated motions against the scan's verdicts
(:func:`validation_data`, :func:`validation_set`), with their figure."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from ...methods.validation import validate
from ...model.blade import Blade
from ...model.parameters import BladeParameters
from ...model.steady import disturbed_rhs
from ..export import markdown_table
from ..scans import ScanData, _CASE_TAGS, _join
from ..style import finish, subplots
from .steady import SteadyMotions

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = [
    "CONFUSION_HEADER", "validation_data", "confusion_rows", "plot_validation", "ValidationData",
    "validation_set", "figure_validation",
]


# --------------------------------------------------------------------------------------
# 4. Validation
# --------------------------------------------------------------------------------------


def validation_data(scan: ScanData, motions: SteadyMotions, case: str, mu_values, *,
                    keys=("energy-practical", "energy", "quadratic", "quadratic-opt"),
                    psi_indices=None, n_directions: int = 16, n_periods: float = 10.0,
                    **options) -> tuple:
    """:func:`rotorlyap.methods.validation.validate` of the results of ``scan`` (about the periodic
    motion) for one case at each advance ratio of ``mu_values``.

    In hover the system is autonomous, so one start azimuth stands for all; in forward flight
    the starts are at ``psi_indices`` of the scan's grid (default: 0, 120 and 240 deg).
    """
    out = []
    n = scan.psi.size
    p = BladeParameters.table_i(case)
    for mu in mu_values:
        mu = float(mu)
        res = {k: scan.result(k, case, mu) for k in keys}
        res = {k: v for k, v in res.items() if v is not None}
        steady = motions.steady(case, mu) if mu > 0 else None
        blade = Blade(p, mu)
        if steady is None:
            f = disturbed_rhs(blade, blade.equilibrium() if mu == 0 else Blade(p, 0.0).equilibrium())
        else:
            f = disturbed_rhs(blade, steady)
        idx = (0,) if mu == 0 else (psi_indices or (0, n // 3, 2 * n // 3))
        out.append(validate(f, res, label=f"{case} C.G., mu = {mu:g}", psi_indices=idx,
                            n_directions=n_directions, n_periods=n_periods, **options))
    return tuple(out)


def confusion_rows(validations, labels: dict | None = None) -> list:
    """Table rows: validation, function, reading, the four counts and the violations."""
    rows = []
    for v in validations:
        for name, reading in zip(v.names, v.readings):
            cm = v.confusion(name)
            rows.append((v.label, (labels or {}).get(name, name), reading, int(cm[0, 0]), int(cm[0, 1]),
                         int(cm[1, 0]), int(cm[1, 1]), v.violations(name)))
    return rows


def plot_validation(validations, axes, *, certified=("quadratic-opt", "quadratic"), legend_ax=None) -> None:
    """Largest norm reached against the start norm, one panel per validation; colours (and
    markers): certified by both functions of ``certified``, by the first only, by the second
    only, not certified (stayed within ``A`` or not); lines: ``A`` and each function's
    certified bound. Motions that reached ``A`` were stopped there. The legend (on
    ``legend_ax``, default the first panel) names every group drawn in any panel."""
    def groups(v):
        c1 = v.covered[v.names.index(certified[0])] if certified[0] in v.names else np.zeros(v.n, bool)
        c2 = v.covered[v.names.index(certified[1])] if certified[1] in v.names else np.zeros(v.n, bool)
        return [(c1 & c2, "tab:green", "o", "certified by both quadratic functions"),
                (c1 & ~c2, "yellowgreen", "D", "certified by the optimised one only"),
                (~c1 & c2, "darkgoldenrod", "s", "certified by Q = I only"),
                (~c1 & ~c2 & v.bounded, "tab:blue", "v", "not certified, stayed within A"),
                (~c1 & ~c2 & ~v.bounded, "tab:red", "x", "not certified, reached A")]

    axes = list(np.asarray(axes).ravel())
    present = np.any([[g[0].any() for g in groups(v)] for v in validations], axis=0)
    for ax, v in zip(axes, validations):
        jitter = 1.0 + 0.03 * np.sin(np.arange(v.n) * 2.39996)
        for k, (mask, col, marker, lab) in enumerate(groups(v)):
            if mask.any() or (ax is axes[0] and present[k]):
                ax.scatter(v.radius[mask] * jitter[mask], v.max_norm[mask], s=24, color=col, marker=marker,
                           label=lab, alpha=0.75, linewidths=1.0 if marker == "x" else 0.0)
        ax.axhline(v.A, color="k", lw=1.2, label="$A$")
        for name, ls in zip(certified, ("--", ":")):
            if name in v.names:
                k = v.names.index(name)
                ax.axhline(v.A_used[k], color="tab:green", lw=1.4, ls=ls,
                           label=f"certified $A$, {'optimised' if name.endswith('opt') else 'Q = I'}")
        ax.plot([1e-3, 2], [1e-3, 2], color="0.6", lw=0.8)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlim(0.01, 1.3)
        ax.set_ylim(0.01, 1.5)
        ax.set_xlabel(r"start norm $\|x_0\|$")
        ax.set_title(v.label.replace("mu = ", r"$\mu$ = "), fontsize=10)
    axes[0].set_ylabel(r"largest norm reached, $\max_\psi \|x\|$")
    handles, labels = axes[0].get_legend_handles_labels()
    if legend_ax is None:
        axes[0].legend(fontsize=8.5, loc="upper left")
    else:
        legend_ax.legend(handles, labels, fontsize=9, loc="center")


#: Header of the confusion table (:meth:`ValidationData.confusion_table`).
CONFUSION_HEADER = ("motions", "function", "reading", "covered, stayed within A", "covered, reached A",
                    "not covered, stayed within A", "not covered, reached A", "covered, beyond the certified bound")


@dataclass(frozen=True)
class ValidationData:
    """Every simulated motion of the chapter, with the verdicts it is tabulated against.

    Attributes
    ----------
    forward : tuple of Validation
        The forward C.G., one per advance ratio (drawn in :func:`figure_validation`).
    hover : tuple of Validation
        The hover of each of :attr:`hover_cases`.
    hover_cases : tuple of str
        The other Table I cases.
    labels : dict
        ``{candidate key: label}`` for the tables.
    lambda0_hover : tuple of float
        Smallest certified ``lambda0`` of the forward C.G. in hover with ``Q = I`` and with the
        optimised weights (norm units), from the scan.
    """

    forward: tuple
    hover: tuple
    hover_cases: tuple
    labels: dict
    lambda0_hover: tuple

    @property
    def validations(self) -> tuple:
        """All validations, forward C.G. first."""
        return tuple(self.forward) + tuple(self.hover)

    def rows(self) -> list:
        """:func:`confusion_rows` of every validation."""
        return confusion_rows(self.validations, self.labels)

    def confusion_table(self) -> str:
        """The confusion matrices as a Markdown table (:data:`CONFUSION_HEADER`)."""
        return markdown_table(CONFUSION_HEADER, self.rows())

    def export(self) -> list:
        """Named columns of the forward-C.G. motions for :func:`rotorlyap.chapters.export.figure_csv`."""
        return ([(f"v{i}_" + k, getattr(v, k)) for i, v in enumerate(self.forward)
                 for k in ("radius", "max_norm", "bounded", "psi_index")]
                + [(f"v{i}_covered_" + n, v.covered[j]) for i, v in enumerate(self.forward)
                   for j, n in enumerate(v.names)])

    @staticmethod
    def _strict(v) -> np.ndarray:
        """Motions of ``v`` started inside at least one strict certificate."""
        return np.any([v.covered[j] for j, r in enumerate(v.readings) if r == "strict"], axis=0)

    @staticmethod
    def _strict_violations(v) -> int:
        return int(sum(v.violations(n) for n, r in zip(v.names, v.readings) if r == "strict"))

    def counts(self) -> tuple:
        """Motions simulated, started inside a strict certificate (each counted once), and
        strictly certified motions that went beyond their certified bound ``A``."""
        vals = self.validations
        return (sum(v.n for v in vals), sum(int(self._strict(v).sum()) for v in vals),
                sum(self._strict_violations(v) for v in vals))

    def growth_ratios(self) -> list:
        """Largest ``max ||x|| / ||x0||`` of a bounded motion, per forward-C.G. validation."""
        return [float((v.max_norm / v.radius)[v.bounded].max()) for v in self.forward]

    def observed_bounded(self) -> float:
        """Largest start norm up to which every start of the first forward-C.G. validation
        (hover) stayed within ``A`` (norm units)."""
        v = self.forward[0]
        bnd = {r: bool(v.bounded[v.radius == r].all()) for r in np.unique(v.radius)}
        return float(max(r for r, ok in bnd.items() if ok and all(bnd[s] for s in bnd if s <= r)))

    def summary(self) -> str:
        """What the confusion table below it does not hold: the counts, the starts placed on the
        sphere ``||x|| = A`` itself and the starts inside it that reached ``A``, the largest
        growth of a bounded motion (two decimals)."""
        n_motions, n_cert, viol = self.counts()
        lines = [f"{v.label}: starts on ||x|| = A {self.on_sphere(v)}, started inside A and reached it "
                 f"{self.inside_reached(v)}" for v in self.validations]
        lines.append(_join("motions:", n_motions, "; certified (strict):", n_cert, "; certified but beyond their bound:", viol))
        lines.append(_join("largest max-norm / start-norm of a bounded motion (forward C.G.):",
                           np.round(self.growth_ratios(), 2)))
        return "\n".join(lines)

    @staticmethod
    def on_sphere(v) -> int:
        """Starts of ``v`` placed on the sphere ``||x|| = A`` (or outside): "reached A" at once."""
        return int(np.sum(v.radius >= v.A * (1 - 1e-9)))

    @staticmethod
    def inside_reached(v) -> int:
        """Starts of ``v`` inside ``||x|| < A`` that reached ``A``."""
        return int(np.sum((v.radius < v.A * (1 - 1e-9)) & ~v.bounded))

    def facts(self) -> dict:
        """Counts, the observed bounded region of the forward hover and its ratio to the
        certified ``lambda0`` (one decimal), the largest growth (two decimals), and for each
        other hover the certified starts, their violations and the paper's reading's starts
        that reached ``A``."""
        n_motions, n_cert, viol = self.counts()
        obs = self.observed_bounded()
        out = {
            "ch7_n_motions": int(n_motions),
            "ch7_n_cert": n_cert,
            "ch7_strict_viol": int(viol),
            "ch7_obs_all_bounded": round(obs, 3),
            "ch7_obs_ratio_q": round(obs / self.lambda0_hover[0], 1),
            "ch7_obs_ratio_o": round(obs / self.lambda0_hover[1], 1),
            "ch7_growth_ratio": round(max(self.growth_ratios()), 2),
            "ch7_on_sphere_hover": self.on_sphere(self.forward[0]),
            "ch7_on_sphere_fwd": max(self.on_sphere(v) for v in self.forward),
            "ch7_inside_reached_fwd": sum(self.inside_reached(v) for v in self.forward),
        }
        for case, v in zip(self.hover_cases, self.hover):
            tag = _CASE_TAGS[case]
            out[f"ch7_hov_cert_{tag}"] = int(self._strict(v).sum())
            out[f"ch7_hov_viol_{tag}"] = self._strict_violations(v)
            out[f"ch7_hov_paper_left_{tag}"] = int(v.confusion("paper")[0, 1])
            out[f"ch7_inside_reached_{tag}"] = self.inside_reached(v)
        return out


def validation_set(scan: ScanData, motions: SteadyMotions, *, forward_mu: tuple = (0.0, 0.15, 0.25),
                   hover_cases: tuple = ("neutral", "backward"),
                   hover_keys: tuple = ("paper", "energy", "quadratic", "quadratic-opt"),
                   n_directions: int = 16, n_periods: float = 10) -> ValidationData:
    """:func:`validation_data` of the forward C.G. at ``forward_mu`` (the candidates about the
    periodic motion) and of the hover of ``hover_cases`` (``hover_keys``, the paper's reading
    included)."""
    fwd = validation_data(scan, motions, "forward", forward_mu, n_directions=n_directions, n_periods=n_periods)
    hov = ()
    for case in hover_cases:
        hov += validation_data(scan, motions, case, (0.0,), keys=hover_keys, n_directions=n_directions,
                               n_periods=n_periods)
    lam = tuple(scan.min_certified_lambda0(key, "forward")[0] for key in ("quadratic", "quadratic-opt"))
    return ValidationData(forward=fwd, hover=hov, hover_cases=tuple(hover_cases),
                          labels=dict(zip(scan.keys, scan.labels)), lambda0_hover=lam)


def figure_validation(data: ValidationData) -> Figure:
    """The figure of :func:`plot_validation` for the forward-C.G. validations (one panel
    each, two to a row, 8.6 in wide, 3.6 in per row; with an odd number of panels the legend
    fills the last cell), laid out and closed in pyplot.

    Returns
    -------
    matplotlib.figure.Figure
    """
    n = len(data.forward)
    ncol = min(n, 2)
    nrow = -(-n // ncol)
    fig, axes = subplots(nrow, ncol, figsize=(4.3 * ncol, 3.6 * nrow), squeeze=False)
    axes = axes.ravel()
    spare = axes[n] if n < axes.size else None
    plot_validation(data.forward, axes[:n], legend_ax=spare)
    if spare is not None:
        spare.set_axis_off()
    for k, ax in enumerate(axes[:n]):
        if k % ncol == 0:
            ax.set_ylabel(r"largest norm reached, $\max_\psi \|x\|$")
    return finish(fig)
