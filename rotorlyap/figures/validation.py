"""Figures of the chapter "Validation and beyond": a data function and a drawing function each.

Data functions return frozen dataclasses (no plotting) and take their grids as arguments;
drawing functions take that data and matplotlib ``Axes``. The chain is

1. :func:`steady_motions`: the true periodic motion of every case at every advance ratio
   (:func:`rotorlyap.model.steady.periodic_motion`), computed once and reused;
2. :func:`floquet_data`: Floquet modes about it and about the hover equilibrium
   (:mod:`rotorlyap.analysis.floquet`);
3. :func:`scan_data`: the engine's verdict on a (psi, mu) grid for several Liapunov functions
   and steady motions (:data:`CANDIDATES`): the rigorous counterpart of the paper's Fig. 8;
4. :func:`validation_data`: simulated motions against those verdicts (:mod:`rotorlyap.methods.validation`);
5. :func:`motion_data`: what the motion does where a reading marks instability.

Conventions as :mod:`rotorlyap.figures.paper`: ``psi = 0`` over the tail, ``psi = 90 deg``
the advancing side; growth rates and frequencies per rev.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..analysis.floquet import floquet_sweep
from ..analysis.functions import optimised_quadratic_function, quadratic_function
from ..analysis.stability import blade_stability
from ..conventions import DEFAULT_A, DEFAULT_SCALES, PAPER_TEST_DISTURBANCES
from ..errors import NotAsymptoticallyStableError, PeriodicMotionError
from ..methods.sampling import sphere_extremum, unit_sphere_points
from ..methods.simulation import scaled_norm, simulate
from ..methods.validation import long_run, validate
from ..model.blade import Blade
from ..model.parameters import BladeParameters
from ..model.steady import disturbed_rhs, periodic_motion, tabulate_motion
from .export import markdown_table  # noqa: F401  (chapter 7 writes its tables with it)
from .style import CATEGORY_COLORS, HINGE_COLORS, SCAN_EXTRA_COLORS

__all__ = [
    "CASES", "MU_FLOQUET", "MU_SCAN", "CANDIDATES", "Candidate", "SCAN_CATEGORY_NAMES",
    "SteadyMotions", "steady_motions", "plot_steady_motions",
    "FloquetData", "floquet_data", "plot_floquet",
    "ScanData", "scan_data", "plot_scan",
    "validation_data", "confusion_rows", "plot_validation",
    "MotionData", "motion_data", "plot_motions", "OriginData", "origin_data", "plot_origin",
    "scan_legend_handles",
    "markdown_table",
]

#: The paper's three cases.
CASES = ("forward", "neutral", "backward")

#: Advance ratios of the Floquet sweep (fine enough to follow the modes by continuity).
MU_FLOQUET = tuple(float(m) for m in np.round(np.arange(0.0, 0.2501, 0.025), 3))

#: Advance ratios of the scans (each costs a sphere search per azimuth and function).
MU_SCAN = (0.0, 0.05, 0.1, 0.15, 0.2, 0.25)



def _edges(values, lo=None) -> np.ndarray:
    v = np.asarray(values, dtype=float)
    mid = 0.5 * (v[1:] + v[:-1])
    first = v[0] - (mid[0] - v[0]) if lo is None else lo
    return np.concatenate([[first], mid, [v[-1] + (v[-1] - mid[-1])]])


# --------------------------------------------------------------------------------------
# 1. The true steady motion
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class SteadyMotions:
    """The periodic motion of each case at each advance ratio.

    Attributes
    ----------
    cases : tuple of str
    mu_values : numpy.ndarray
        (m,).
    found : numpy.ndarray
        Boolean (k, m): :func:`rotorlyap.model.steady.periodic_motion` converged.
    distance : numpy.ndarray
        ``max_psi ||xi(psi) - xi_hover||`` in the scaled norm of
        :data:`rotorlyap.analysis.stability.DEFAULT_SCALES`, (k, m): how far the paper's steady motion
        is from the true one. NaN where not found.
    harmonics_deg : numpy.ndarray
        Mean, cos and sin first harmonics of flap, lag, pitch, deg, (k, m, 3, 3).
    residual : numpy.ndarray
        ``max_psi ||h(psi, xi) - xi'||`` (scaled norm) of the tabulated motion on 4001
        azimuths, (k, m): ``f(psi, 0)`` of the disturbed equations.
    psi_plot : numpy.ndarray
        Azimuths of :attr:`angles_deg`, rad, (n,).
    angles_deg : numpy.ndarray
        Hinge angles of the periodic motion, deg, (k, m, n, 3); NaN where not found.
    hover_deg : numpy.ndarray
        Hover equilibrium angles, deg, (k, 3).
    messages : tuple
        Per case, per advance ratio: empty, or why not found.
    motions : dict
        ``{(case, mu): TabulatedMotion}`` for the ones found (not compared, not exported).
    """

    cases: tuple
    mu_values: np.ndarray
    found: np.ndarray
    distance: np.ndarray
    harmonics_deg: np.ndarray
    residual: np.ndarray
    psi_plot: np.ndarray
    angles_deg: np.ndarray
    hover_deg: np.ndarray
    messages: tuple
    motions: dict = field(default_factory=dict, compare=False, repr=False)

    def steady(self, case: str, mu: float):
        """The tabulated periodic motion as a :class:`~rotorlyap.model.steady.SteadyMotion`, or
        None if not found."""
        m = self.motions.get((case, round(float(mu), 6)))
        return None if m is None else m.steady

    def export(self) -> dict:
        """The arrays for :func:`rotorlyap.figures.export.figure_csv`."""
        return {"mu": self.mu_values, "found": self.found, "distance": self.distance, "residual": self.residual,
                "harmonics_deg": self.harmonics_deg, "psi_deg": np.degrees(self.psi_plot),
                "angles_deg": self.angles_deg, "hover_deg": self.hover_deg}


def steady_motions(cases=CASES, mu_values=MU_FLOQUET, *, n_points: int = 256, n_table: int = 4096,
                   n_plot: int = 73) -> SteadyMotions:
    """Periodic motions of every case at every advance ratio (failures recorded, not raised).

    Each motion is first sought with the default 64 collocation points (a quick test of
    existence), then recomputed with ``n_points``: the blade's loads have kinks (reverse flow
    at the root, stall), so the Fourier series converges slowly and between the collocation
    points the residual ``|h(psi, xi) - xi'|`` of 64 points is up to about 1e-2 in the
    scaled norm at ``mu = 0.25``, ten times less with 256. The motion is then tabulated
    (:func:`rotorlyap.analysis.floquet.tabulate_motion`, ``n_table`` azimuths) for fast
    evaluation. :attr:`SteadyMotions.residual` is the largest scaled residual on 4001
    azimuths: the size of ``f(psi, 0)``, the part of ``W'`` linear in ``x``.
    """
    mu_values = np.asarray(mu_values, dtype=float)
    k, m = len(cases), mu_values.size
    psi = np.linspace(0.0, 2 * np.pi, n_plot)
    grid = 2 * np.pi * np.arange(256) / 256
    fine = np.linspace(0.0, 2 * np.pi, 4001)
    found = np.zeros((k, m), dtype=bool)
    dist = np.full((k, m), np.nan)
    harm = np.full((k, m, 3, 3), np.nan)
    res = np.full((k, m), np.nan)
    ang = np.full((k, m, n_plot, 3), np.nan)
    hov = np.zeros((k, 3))
    msgs, motions = [], {}
    for i, case in enumerate(cases):
        p = BladeParameters.table_i(case)
        xh = Blade(p, 0.0).equilibrium()
        hov[i] = np.degrees(xh[:3])
        row = []
        for j, mu in enumerate(mu_values):
            try:
                pm = periodic_motion(p, float(mu))
                if mu > 0 and n_points != 64:
                    pm = periodic_motion(p, float(mu), n_points=n_points)
            except PeriodicMotionError as exc:
                row.append(str(exc))
                continue
            row.append("")
            tab = tabulate_motion(pm, n_table)
            motions[(case, round(float(mu), 6))] = tab
            found[i, j] = True
            dist[i, j] = float(scaled_norm(tab.xi(grid) - xh, DEFAULT_SCALES).max())
            harm[i, j] = pm.harmonics_deg
            blade = Blade(p, float(mu))
            res[i, j] = float(scaled_norm(blade.rhs(fine, tab.xi(fine)) - tab.dxi(fine), DEFAULT_SCALES).max())
            ang[i, j] = np.degrees(tab.xi(psi)[:, :3])
        msgs.append(tuple(row))
    return SteadyMotions(cases=tuple(cases), mu_values=mu_values, found=found, distance=dist,
                         harmonics_deg=harm, residual=res, psi_plot=psi, angles_deg=ang, hover_deg=hov,
                         messages=tuple(msgs), motions=motions)


def plot_steady_motions(data: SteadyMotions, axes, case_index: int = 0) -> None:
    """Flap, lag and pitch angles of the periodic motion of one case against azimuth (three
    panels, one line per advance ratio, dashed: the hover equilibrium), and in a fourth
    panel the distance of the hover equilibrium from it against ``mu`` for every case."""
    import matplotlib.pyplot as plt

    cmap = plt.get_cmap("viridis")
    mu = data.mu_values
    names = (r"flap $\beta$", r"lag $\zeta$", r"pitch $\theta$")
    for h in range(3):
        ax = axes[h]
        for j in range(mu.size):
            if not data.found[case_index, j]:
                continue
            ax.plot(np.degrees(data.psi_plot), data.angles_deg[case_index, j, :, h],
                    color=cmap(j / max(mu.size - 1, 1)), lw=1.0, label=f"$\\mu$ = {mu[j]:g}")
        ax.axhline(data.hover_deg[case_index, h], color="k", ls="--", lw=1.0, label="hover equilibrium")
        ax.set_xlim(0, 360)
        ax.set_xticks(np.arange(0, 361, 90))
        ax.set_xlabel(r"azimuth $\psi$ (deg)")
        ax.set_ylabel(names[h] + " (deg)")
    axes[0].legend(fontsize=6, ncol=2)
    ax = axes[3]
    for i, case in enumerate(data.cases):
        ok = data.found[i]
        ax.plot(mu[ok], data.distance[i, ok], "o-", ms=3, label=f"{case} C.G.")
        if (~ok).any():
            ax.plot(mu[~ok], np.zeros((~ok).sum()), "x", color=ax.lines[-1].get_color(), ms=6)
    ax.axhline(DEFAULT_A, color="tab:green", lw=1.5, label="$A$")
    ax.set_xlabel(r"advance ratio $\mu$")
    ax.set_ylabel(r"$\max_\psi \|\xi(\psi) - \xi_{\mathrm{hover}}\|$")
    ax.legend(fontsize=7)


# --------------------------------------------------------------------------------------
# 2. Floquet
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class FloquetData:
    """Floquet sweeps of every case about the periodic motion and about the hover equilibrium."""

    cases: tuple
    mu_values: np.ndarray
    periodic: tuple
    hover: tuple

    def export(self) -> list:
        """Named columns for :func:`rotorlyap.figures.export.figure_csv` (long layout)."""
        out = [("mu", self.mu_values)]
        for case, sp, sh in zip(self.cases, self.periodic, self.hover):
            for tag, sw in (("periodic", sp), ("hover", sh)):
                out += [(f"{case}_{tag}_names", list(sw.names)),
                        (f"{case}_{tag}_growth_rate", sw.growth_rate),
                        (f"{case}_{tag}_frequency", sw.frequency),
                        (f"{case}_{tag}_spectral_radius", sw.spectral_radius)]
        return out


def floquet_data(motions: SteadyMotions, *, n_steps: int = 1024) -> FloquetData:
    """:func:`rotorlyap.analysis.floquet.floquet_sweep` of every case of ``motions``, about the
    periodic motions found there and about the hover equilibrium."""
    per, hov = [], []
    for case in motions.cases:
        p = BladeParameters.table_i(case)
        i = motions.cases.index(case)
        given = {float(mu): (motions.steady(case, mu) if motions.found[i, j] else motions.messages[i][j])
                 for j, mu in enumerate(motions.mu_values)}
        per.append(floquet_sweep(p, motions.mu_values, steady="periodic", case=case, n_steps=n_steps,
                                 motions=given))
        hov.append(floquet_sweep(p, motions.mu_values, steady="hover", case=case, n_steps=n_steps))
    return FloquetData(cases=motions.cases, mu_values=motions.mu_values, periodic=tuple(per), hover=tuple(hov))


def _hinge(name: str) -> str:
    return name.rstrip("+-0123456789")


def plot_floquet(data: FloquetData, axes) -> None:
    """Growth rates (top row) and frequencies (bottom row, branch resolved by continuity) of
    the Floquet modes against ``mu``, one column per case. Solid with dots: about the
    periodic motion; dotted: about the hover equilibrium (the paper's steady motion)."""
    for c, case in enumerate(data.cases):
        for sw, style in ((data.periodic[c], dict(ls="-", marker="o", ms=2.5, lw=1.2)),
                          (data.hover[c], dict(ls=":", lw=1.0))):
            for t, name in enumerate(sw.names):
                color = HINGE_COLORS.get(_hinge(name), "0.3")
                lab = name if sw.steady == "periodic" else None
                axes[0, c].plot(sw.mu, sw.growth_rate[:, t], color=color, label=lab, **style)
                axes[1, c].plot(sw.mu, np.abs(sw.frequency[:, t]), color=color, **style)
            miss = ~sw.found
            if miss.any():
                for ax in axes[:, c]:
                    for m in sw.mu[miss]:
                        ax.axvspan(m - 0.0125, m + 0.0125, color="0.85", lw=0)
        axes[0, c].axhline(0.0, color="k", lw=0.6)
        axes[0, c].set_title(f"{case} C.G.", fontsize=9)
        axes[0, c].set_ylabel("growth rate (1/rev)")
        axes[1, c].set_ylabel(r"frequency $|\omega|$ (1/rev)")
        axes[1, c].set_yscale("symlog", linthresh=1.0, linscale=0.6)
        axes[1, c].set_ylim(-0.02, 6.0)
        axes[1, c].set_yticks([0, 0.25, 0.5, 1, 2, 3, 4, 5])
        axes[1, c].set_yticklabels(["0", "0.25", "0.5", "1", "2", "3", "4", "5"])
        axes[1, c].set_xlabel(r"advance ratio $\mu$")
        axes[0, c].legend(fontsize=6, ncol=2, loc="lower left")


# --------------------------------------------------------------------------------------
# 3. Scans: the rigorous Fig. 8
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Candidate:
    """One Liapunov function, reading and steady motion of the scans."""

    key: str
    label: str
    function: str  # "energy", "quadratic", "quadratic-opt"
    reading: str  # "strict" or "practical"
    steady: str  # "hover" (the paper's) or "periodic"


#: The functions compared, in the order of the rows of :func:`plot_scan`.
CANDIDATES = (
    Candidate("paper", "energy, practical, hover equilibrium (the paper's choice)", "energy", "practical", "hover"),
    Candidate("energy-practical", "energy, practical, periodic motion", "energy", "practical", "periodic"),
    Candidate("energy", "energy, strict, periodic motion", "energy", "strict", "periodic"),
    Candidate("quadratic-hover", "quadratic Q = I, strict, hover equilibrium", "quadratic", "strict", "hover"),
    Candidate("quadratic", "quadratic Q = I, strict, periodic motion", "quadratic", "strict", "periodic"),
    Candidate("quadratic-opt", "quadratic, optimised Q, strict, periodic motion", "quadratic-opt", "strict", "periodic"),
)

#: Outcome of one (azimuth, advance ratio) cell; the first four as in the Fig. 8 chapter.
SCAN_CATEGORY_NAMES = (
    "stable: step 6 holds",
    "step 6 fails at this azimuth",
    "step 3 failed elsewhere (A1 = 0); W' <= 0 here on ||x|| = A",
    "step 3 failed (A1 = 0) and W' > 0 here on ||x|| = A",
    "no quadratic function: linearisation unstable",
    "no periodic motion found",
)
_SCAN_COLORS = CATEGORY_COLORS + SCAN_EXTRA_COLORS


def _category(res) -> np.ndarray:
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
        The candidates (:data:`CANDIDATES`), (c,).
    category : numpy.ndarray
        Index into :data:`SCAN_CATEGORY_NAMES`, (c, k, m, n).
    stable : numpy.ndarray
        Boolean (c, k, m, n).
    lambda0 : numpy.ndarray
        (c, k, m, n); 0 where no result.
    A_used : numpy.ndarray
        Bound after step 3, (c, k, m); NaN where no result.
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


def scan_data(motions: SteadyMotions, *, candidates=CANDIDATES, cases=None, mu_values=MU_SCAN,
              n_psi: int = 24, A: float | None = None, **engine_options) -> ScanData:
    """Run :func:`rotorlyap.analysis.stability.blade_stability` for every candidate, case and advance ratio.

    The quadratic functions use the default scales as their coordinates (so ``Q = I`` is
    ``diag(1 / a_i**2)``); the optimised weight is found once per case in hover
    (:func:`rotorlyap.analysis.functions.optimised_quadratic_function`) and kept at every advance
    ratio. Where no quadratic function exists (unstable linearisation) or no periodic motion
    was found, the cells get categories 4 and 5 instead of a result.
    """
    cases = motions.cases if cases is None else tuple(cases)
    mu_values = np.asarray(mu_values, dtype=float)
    A = DEFAULT_A if A is None else float(A)
    weights = np.full((len(cases), 6), np.nan)
    Qopt = {}
    for i, case in enumerate(cases):
        try:
            qo = optimised_quadratic_function(Blade(BladeParameters.table_i(case), 0.0), A=A)
        except NotAsymptoticallyStableError as exc:
            Qopt[case] = exc
            continue
        Qopt[case] = qo.Q
        weights[i] = np.diag(qo.Q) * DEFAULT_SCALES**2
    shape = (len(candidates), len(cases), mu_values.size, n_psi)
    cat = np.zeros(shape, dtype=int)
    stable = np.zeros(shape, dtype=bool)
    lam = np.zeros(shape)
    aused = np.full(shape[:3], np.nan)
    msgs, results, psi = [], {}, 2 * np.pi * np.arange(n_psi) / n_psi
    for c, cand in enumerate(candidates):
        per_case = []
        for i, case in enumerate(cases):
            p = BladeParameters.table_i(case)
            row = []
            for j, mu in enumerate(mu_values):
                mu = float(mu)
                steady = None
                if cand.steady == "periodic" and mu > 0:
                    steady = motions.steady(case, mu)
                    if steady is None:
                        cat[c, i, j] = 5
                        row.append("no periodic motion found")
                        continue
                if cand.function == "energy":
                    lyap = None
                elif cand.function == "quadratic":
                    lyap = quadratic_function
                else:
                    Q = Qopt[case]
                    if isinstance(Q, Exception):
                        cat[c, i, j] = 4
                        row.append(str(Q))
                        continue
                    lyap = lambda b, steady, Q=Q: quadratic_function(b, steady, Q, label="optimised")  # noqa: E731
                tests = PAPER_TEST_DISTURBANCES if cand.reading == "practical" else None
                try:
                    r = blade_stability(p, mu, lyapunov=lyap, steady=steady, A=A, n_psi=n_psi,
                                        test_disturbances=tests, **engine_options)
                except NotAsymptoticallyStableError as exc:
                    cat[c, i, j] = 4
                    row.append(str(exc))
                    continue
                results[(cand.key, case, round(mu, 6))] = r
                cat[c, i, j] = _category(r)
                stable[c, i, j] = r.stable
                lam[c, i, j] = r.lambda0
                aused[c, i, j] = r.A
                psi = np.asarray(r.psi)
                row.append(r.message)
            per_case.append(tuple(row))
        msgs.append(tuple(per_case))
    return ScanData(cases=cases, mu_values=mu_values, psi=psi, keys=tuple(cd.key for cd in candidates),
                    labels=tuple(cd.label for cd in candidates),
                    readings=tuple(cd.reading for cd in candidates), category=cat, stable=stable,
                    lambda0=lam, A_used=aused, weights=weights, messages=tuple(msgs), results=results)


def plot_scan(data: ScanData, axes, *, rows=None) -> None:
    """The verdicts in the (psi, mu) plane: one row per candidate, one column per case."""
    from matplotlib.colors import BoundaryNorm, ListedColormap

    cmap = ListedColormap(_SCAN_COLORS)
    norm = BoundaryNorm(np.arange(-0.5, len(_SCAN_COLORS) + 0.5), len(_SCAN_COLORS))
    rows = range(len(data.keys)) if rows is None else rows
    deg = np.degrees(data.psi)
    step = deg[1] - deg[0]
    xe = np.concatenate([deg - step / 2, [deg[-1] + step / 2]])
    ye = _edges(data.mu_values, lo=0.0)
    for r, c in enumerate(rows):
        for i, case in enumerate(data.cases):
            ax = axes[r, i]
            ax.pcolormesh(xe, ye, data.category[c, i], cmap=cmap, norm=norm, shading="flat",
                          edgecolors="w", linewidth=0.2)
            ax.axvline(180, color="k", lw=0.6, ls=":")
            ax.set_xlim(0, 360)
            ax.set_ylim(0, ye[-1])
            ax.set_xticks(np.arange(0, 361, 90))
            ax.tick_params(labelsize=7)
            if r == 0:
                ax.set_title(f"{case} C.G.", fontsize=9)
            if r == len(list(rows)) - 1:
                ax.set_xlabel(r"azimuth $\psi$ (deg)", fontsize=8)
            if i == 0:
                ax.set_ylabel(data.labels[c].replace(", ", ",\n", 2) + "\n" + r"$\mu$", fontsize=7)


def scan_legend_handles():
    """Legend patches of the scan categories."""
    from matplotlib.patches import Patch

    return [Patch(facecolor=col, edgecolor="0.5", label=name)
            for col, name in zip(_SCAN_COLORS, SCAN_CATEGORY_NAMES)]


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


def plot_validation(validations, axes, *, certified=("quadratic-opt", "quadratic")) -> None:
    """Largest norm reached against the start norm, one panel per validation; colours:
    certified by the first, by the second function, not certified (stayed within ``A`` or
    not). Motions that reached ``A`` were stopped there."""
    for ax, v in zip(axes, validations):
        c1 = v.covered[v.names.index(certified[0])] if certified[0] in v.names else np.zeros(v.n, bool)
        c2 = v.covered[v.names.index(certified[1])] if certified[1] in v.names else np.zeros(v.n, bool)
        groups = [(c1 & c2, "tab:green", "certified by both quadratic functions"),
                  (c1 & ~c2, "yellowgreen", "certified by the optimised one only"),
                  (~c1 & ~c2 & v.bounded, "tab:blue", "not certified, stayed within A"),
                  (~c1 & ~c2 & ~v.bounded, "tab:red", "not certified, reached A")]
        jitter = 1.0 + 0.03 * np.sin(np.arange(v.n) * 2.39996)
        for mask, col, lab in groups:
            if mask.any():
                ax.scatter(v.radius[mask] * jitter[mask], v.max_norm[mask], s=6, color=col, label=lab, alpha=0.7)
        ax.axhline(v.A, color="k", lw=1.2, label="$A$")
        for name, ls in zip(certified, ("--", ":")):
            if name in v.names:
                k = v.names.index(name)
                ax.axhline(v.A_used[k], color="tab:green", lw=1.0, ls=ls,
                           label=f"$A_1$ of {'optimised' if name.endswith('opt') else 'Q = I'}")
        ax.plot([1e-3, 2], [1e-3, 2], color="0.6", lw=0.6)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlim(0.01, 1.3)
        ax.set_ylim(0.01, 1.5)
        ax.set_xlabel(r"start norm $\|x_0\|$")
        ax.set_title(v.label, fontsize=9)
    axes[0].set_ylabel(r"largest norm reached, $\max_\psi \|x\|$")
    axes[0].legend(fontsize=6, loc="upper left")


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
    """

    histories: tuple
    labels: tuple
    start_labels: tuple
    offsets: tuple
    reference: tuple
    check: tuple

    def export(self) -> list:
        out = []
        for i, h in enumerate(self.histories):
            out += [(f"e{i}_peaks", h.peaks), (f"e{i}_rev", np.arange(h.peaks.shape[0]))]
        return out


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
      equilibrium (the white cells of the rigorous Fig. 8), ``drift_periods`` revolutions;
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
                      offsets=tuple(offs), reference=tuple(refs), check=tuple(checks))


def plot_motions(data: MotionData, axes) -> None:
    """(a) Peak norm per revolution, every motion (log scale); (b) the pitch and lag angles
    over the last two revolutions of the first two experiments; (c) the norm of the forward-flight
    motion about the hover equilibrium against the periodic motion seen from there."""
    ax = axes[0]
    colors = ("tab:purple", "tab:red", "tab:blue")
    for h, col in zip(data.histories, colors):
        for m, ls in zip(range(h.peaks.shape[1]), ("-", "--")):
            ax.plot(np.arange(1, h.peaks.shape[0] + 1), h.peaks[:, m], ls, color=col, lw=1.2,
                    label=f"{h.label}: {data.start_labels[0][m]}")
    ax.axhline(DEFAULT_A, color="tab:green", lw=1.5, label="$A$")
    ax.set_yscale("log")
    ax.set_xlabel("revolution")
    ax.set_ylabel(r"peak $\|x\|$ in the revolution")
    ax.legend(fontsize=6)
    ax = axes[1]
    for h, off, col in zip(data.histories[:2], data.offsets[:2], colors):
        k = 2 * points_per_revolution(h) + 1
        az = np.degrees(h.psi[-k:] - h.psi[-k])
        for i, name, ls in ((2, r"pitch $\theta$", "-"), (1, r"lag $\zeta$", "--")):
            ax.plot(az, np.degrees(off[-k:, i] + h.x[-k:, 0, i]), ls, color=col, lw=1.2,
                    label=f"{h.label}: {name}")
            ax.axhline(np.degrees(off[0, i]), color=col, lw=0.6, ls=":")
    ax.set_xlabel(r"azimuth over the last two revolutions (deg)")
    ax.set_ylabel("hinge angle (deg; dotted: hover equilibrium)")
    ax.legend(fontsize=6)
    ax = axes[2]
    h, ref = data.histories[2], data.reference[2]
    for m, ls in zip(range(h.norm.shape[1]), ("-", "--")):
        ax.plot(h.psi / (2 * np.pi), h.norm[:, m], ls, color="tab:blue", lw=0.8,
                label=f"motion from {data.start_labels[2][m]}")
    ax.plot(h.psi / (2 * np.pi), ref, color="k", lw=1.0, alpha=0.7,
            label=r"$\|\xi(\psi) - \xi_{\mathrm{hover}}\|$ (periodic motion)")
    ax.axhline(DEFAULT_A, color="tab:green", lw=1.5, label="$A$")
    ax.set_xlabel("revolutions")
    ax.set_ylabel(r"$\|x\|$ about the hover equilibrium")
    ax.set_title(h.label, fontsize=8)
    ax.legend(fontsize=6)


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
        """``max W' / max W`` (per rad): scale-free, comparable between functions."""
        return self.max_dW / self.max_W


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
    values mean ``W' < 0`` on the whole sphere)."""
    styles = ("-", "-", "-", "--", "--", ":")
    for i, lab in enumerate(data.labels):
        ax.plot(data.radii, data.relative_rate[i], styles[i % len(styles)], marker="o", ms=3, label=lab)
    ax.axhline(0.0, color="k", lw=0.8)
    ax.set_xscale("log")
    ax.set_yscale("symlog", linthresh=0.01)
    ax.set_xlabel(r"sphere radius $r = \|x\|$")
    ax.set_ylabel(r"$\max W' \,/\, \max W$ on the sphere (1/rad)")
    ax.legend(fontsize=7)
