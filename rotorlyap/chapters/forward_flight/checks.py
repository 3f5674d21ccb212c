"""Chapter 6, forward flight: how far Fig. 8 can be trusted: the practical threshold (the advance
ratio from which the practical reading stops passing every azimuth), the sensitivity of Fig. 8
to the bound ``A``, the norm scales and the test disturbances, and its convergence in the
resolution parameters, with the test-disturbance sets they use.

Part of :mod:`rotorlyap.chapters.forward_flight`, which re-exports its names.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...analysis.functions import energy_function
from ...analysis.stability import blade_stability
from ...conventions import DEFAULT_A, DEFAULT_SCALES, PAPER_TEST_DISTURBANCES
from ...methods.sampling import sphere_extremum, unit_sphere_points
from ...model.blade import Blade
from ...model.trim import hover_trim
from ...reporting import decade_above
from ..cases import CASES, MU_GRID, _line, balanced_scales, case_params
from ..style import CG_COLORS, CG_MARKERS, figure, finish, subplots
from .regions import RegionsData, category_legend_handles, plot_regions_plane, regions_data

__all__ = [
    "FLAP_LAG_TEST_DISTURBANCES", "AXES_AND_DIAGONALS",
    "THRESHOLD_TEST_SETS", "practical_threshold_mu", "ThresholdData", "practical_threshold_data",
    "SensitivityData", "sensitivity_data", "plot_sensitivity", "figure_sensitivity",
    "ConvergenceData", "convergence_data", "plot_convergence", "figure_convergence",
]

#: Test disturbances without the pitch rate: the eight signed flap and lag axes.
FLAP_LAG_TEST_DISTURBANCES = PAPER_TEST_DISTURBANCES[[0, 1, 3, 4, 6, 7, 9, 10]]
FLAP_LAG_TEST_DISTURBANCES.setflags(write=False)

#: The 12 signed axes and the 60 signed diagonals of the coordinate planes.
AXES_AND_DIAGONALS = unit_sphere_points(6, 0)


# --------------------------------------------------------------------------------------
# The practical threshold
# --------------------------------------------------------------------------------------


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


#: Test-disturbance sets of the threshold study, by name, with the short tag of their glue names.
THRESHOLD_TEST_SETS = {
    "12 axes": ("12", PAPER_TEST_DISTURBANCES),
    "flap and lag axes": ("fl", FLAP_LAG_TEST_DISTURBANCES),
}


@dataclass(frozen=True)
class ThresholdData:
    """The practical threshold (:func:`practical_threshold_mu`) for several inflow models and
    test-disturbance sets, and for one model the hover start region and the flight speed.

    Attributes
    ----------
    cg : str or float
    models : tuple of str
        Inflow models.
    test_sets : tuple of str
        Keys of :data:`THRESHOLD_TEST_SETS`.
    threshold : numpy.ndarray
        Advance ratio up to which the practical reading passes at every azimuth,
        (len(models), len(test_sets)).
    speed_model : str
        The model of :attr:`hover_lambda0` and :attr:`speed`.
    hover_lambda0 : numpy.ndarray
        Practical start region in hover, per test set, -.
    speed : numpy.ndarray
        Threshold flight speed ``mu Omega R``, per test set, m/s.
    mu_lo : float
        The smallest advance ratio the bisection tried; a threshold equal to it means the
        indicator already fails there.
    """

    cg: object
    models: tuple
    test_sets: tuple
    threshold: np.ndarray
    speed_model: str
    hover_lambda0: np.ndarray
    speed: np.ndarray
    mu_lo: float = 1e-7

    def threshold_of(self, model: str, test_set: str) -> float:
        """The threshold of one inflow model and test set."""
        return float(self.threshold[self.models.index(model), self.test_sets.index(test_set)])

    def _threshold_words(self, thr: float) -> str:
        """The threshold in words: where the bisection ran, the advance ratio below which the
        indicator passes at every azimuth; where it already fails at the smallest advance ratio
        tried (:func:`practical_threshold_mu` then returns that ratio), that."""
        if thr <= self.mu_lo:
            return f"fails already at mu = {self.mu_lo:.2g} (threshold below it)"
        return f"passes at every azimuth below mu = {thr:.2g}"

    def summary(self) -> str:
        """Every threshold (2 digits), then the start region (0.001) and threshold speed (m/s,
        2 digits) of :attr:`speed_model`."""
        lines = [f"inflow {model:8s}, {tname:18s}: " + self._threshold_words(self.threshold_of(model, tname))
                 for model in self.models for tname in self.test_sets]
        lines += [f"inflow {self.speed_model:8s}, {tname:18s}: hover start region lambda0 = {lam:.3f}; "
                  f"threshold flight speed {v:.2g} m/s"
                  for tname, lam, v in zip(self.test_sets, self.hover_lambda0, self.speed)]
        return "\n".join(lines)

    def facts(self) -> dict:
        """For :attr:`speed_model` (tag: its first two letters) and each test set (tag of
        :data:`THRESHOLD_TEST_SETS`): ``ch6_thr_<m>_<t>`` (2 digits), ``ch6_lam_<m>_<t>``
        (0.001) and ``ch6_v_<m>_<t>`` (m/s, 2 digits)."""
        m = self.speed_model[:2]
        out = {}
        for tname in self.test_sets:
            thr = self.threshold_of(self.speed_model, tname)
            out[f"ch6_thr_{m}_{THRESHOLD_TEST_SETS[tname][0]}"] = float("%.2g" % thr)
        for tname, lam, v in zip(self.test_sets, self.hover_lambda0, self.speed):
            tag = THRESHOLD_TEST_SETS[tname][0]
            out[f"ch6_lam_{m}_{tag}"] = round(float(lam), 3)
            out[f"ch6_v_{m}_{tag}"] = float("%.2g" % v)
        return out


def practical_threshold_data(cg="forward", models=("glauert", "drees"), test_sets=tuple(THRESHOLD_TEST_SETS), *,
                             speed_model: str = "drees", mu_lo: float = 1e-7, n_psi: int = 72,
                             n_bisect: int = 20) -> ThresholdData:
    """Bisect the practical threshold for each inflow model and test set (``mu_lo``, ``n_psi``
    and ``n_bisect`` go to :func:`practical_threshold_mu`), and for ``speed_model`` the hover
    start region (4 azimuths: nothing depends on the azimuth in hover) and the speed."""
    thr = np.array([[practical_threshold_mu(cg, mu_lo=mu_lo, n_psi=n_psi, n_bisect=n_bisect,
                                            test_disturbances=THRESHOLD_TEST_SETS[t][1],
                                            params_overrides=dict(inflow_model=model))
                     for t in test_sets] for model in models])
    p = case_params(cg, inflow_model=speed_model)
    lam = np.array([float(blade_stability(p, 0.0, n_psi=4, test_disturbances=THRESHOLD_TEST_SETS[t][1]).lambda0.min())
                    for t in test_sets])
    speed = thr[list(models).index(speed_model)] * p.rotor_speed * p.radius
    return ThresholdData(cg=cg, models=tuple(models), test_sets=tuple(test_sets), threshold=thr,
                         speed_model=speed_model, hover_lambda0=lam, speed=speed, mu_lo=float(mu_lo))


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

    def variant(self, name: str) -> RegionsData:
        """The map of one variant."""
        return self.regions[self.names.index(name)]

    def stable_forward_flight(self, name: str) -> tuple[int, float, list[int]]:
        """Of one variant: the stable cells with ``mu > 0``, the first such ``mu`` and its stable
        azimuths (deg); ``(0, nan, [])`` if there are none."""
        r = self.variant(name)
        rows = np.flatnonzero(r.stable[0, 1:].any(axis=1)) + 1
        if rows.size == 0:
            return 0, float("nan"), []
        i = int(rows[0])
        return (int(r.stable[0, 1:].sum()), float(r.mu_values[i]),
                [int(v) for v in np.round(np.degrees(r.psi[r.stable[0, i]]))])

    def summary(self) -> str:
        """Per variant: test disturbances, hover start region, bound after step 3 and stable
        azimuths per ``mu``; whether the flap-and-lag variant gives the default map; where the
        ``A = 4`` variant keeps its bound and is stable in forward flight (default variants of
        :func:`sensitivity_data`)."""
        lines = [_line("mu:", self.regions[0].mu_values),
                 "variant                        tests  hover lambda0  A after step 3 (per mu)            "
                 "azimuths passing (per mu)"]
        for name, r, n in zip(self.names, self.regions, self.n_tests):
            lines.append(f"{name:30s} {n:4d}  {r.lambda0[0, 0].min():12.3f}  {np.round(r.A_used[0], 3)}  "
                         f"{r.stable[0].sum(axis=1)}")
        fl = self.variant("flap and lag axes only (8)")
        lines.append(_line("flap and lag axes only: the same map as the default, cell by cell:",
                           np.array_equal(fl.category[0, :, :], self.regions[0].category[0, :, :])))
        r4 = self.variant("A = 4")
        ok4 = np.flatnonzero(r4.A_used[0] > 0)
        i4 = np.flatnonzero(r4.stable[0, 1:].any(axis=1)) + 1
        lines.append(_line("A = 4: step 3 keeps A up to mu =", r4.mu_values[ok4[-1]], "; passing cells with mu > 0 at",
                           [(float(r4.mu_values[i]), [int(v) for v in np.round(np.degrees(r4.psi[r4.stable[0, i]]))])
                            for i in i4],
                           "; lambda0 =", np.round(np.unique(r4.lambda0[0, 1:ok4[-1] + 1]), 3)))
        return "\n".join(lines)

    def facts(self) -> dict:
        """Chapter 6's sensitivity numbers (default variants of :func:`sensitivity_data`):
        ``ch6_a4_*`` (the ``A = 4`` variant: last ``mu`` where step 3 keeps ``A``, the next,
        its stable cells with ``mu > 0``, the first such ``mu`` and its azimuths, its start
        region), ``ch6_bal_lambda0``, ``ch6_def_lambda0`` (hover start regions, 0.001),
        ``ch6_diag_A0`` (hover bound with the diagonals), ``ch6_sens_fw_stable`` (stable
        cells with ``mu > 0`` over all variants) and ``ch6_bal_scales`` (the balanced scales,
        deg and deg/rad, as text)."""
        r4 = self.variant("A = 4")
        ok4 = np.flatnonzero(r4.A_used[0] > 0)
        n4, mu4, psi4 = self.stable_forward_flight("A = 4")
        bal = self.names.index("energy-balanced a_i")
        return {
            "ch6_a4_mu_last": float(r4.mu_values[ok4[-1]]),
            "ch6_a4_mu_fail": float(r4.mu_values[ok4[-1] + 1]),
            "ch6_a4_stable": n4,
            "ch6_a4_stable_mu": mu4,
            "ch6_a4_stable_psi": ", ".join(str(v) for v in psi4),
            "ch6_a4_lambda0": round(float(r4.lambda0[0, 1].min()), 3),
            "ch6_bal_lambda0": round(float(self.regions[bal].lambda0[0, 0].min()), 3),
            "ch6_def_lambda0": round(float(self.regions[0].lambda0[0, 0].min()), 3),
            "ch6_diag_A0": round(float(self.variant("axes + diagonals (72)").A_used[0, 0]), 4),
            "ch6_sens_fw_stable": int(sum(r.stable[0, 1:].sum() for r in self.regions)),
            "ch6_bal_scales": ", ".join(f"{v:.2f}" for v in np.degrees(self.scales[bal])),
        }

    def export(self) -> list:
        """Named columns for :func:`rotorlyap.chapters.export.figure_csv`: ``v<k>_category``
        (mu, psi) and ``v<k>_A_used`` (mu) of variant ``k``, then ``mu`` and ``psi_deg``."""
        return ([(f"v{i}_" + k, v) for i, r in enumerate(self.regions)
                 for k, v in (("category", r.category[0]), ("A_used", r.A_used[0]))]
                + [("mu", self.regions[0].mu_values), ("psi_deg", np.degrees(self.regions[0].psi))])


def sensitivity_data(cg="forward", mu_values=(0.0, 0.0125, 0.025, 0.05, 0.1, 0.15, 0.2, 0.25), variants: dict | None = None, *, n_psi: int = 72) -> SensitivityData:
    """Run the practical Fig. 8 for each variant: ``{name: dict(A=, scales=, test_disturbances=)}``.

    Default variants: the report's default (12 axes, A = 1, default scales); A = 0.5, 2 and 4;
    energy-balanced scales (:func:`~rotorlyap.chapters.cases.balanced_scales`); the axes and
    pairwise diagonals; the flap and lag axes only (no pitch rate).
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
    """One (psi, mu) map per variant; the first spare axes, if any, holds the category legend.
    Axis labels only on the outer panels of a grid."""
    axes = np.ravel(axes)
    for i, (ax, name, reg) in enumerate(zip(axes, data.names, data.regions)):
        plot_regions_plane(reg, ax, 0, title=name, legend=False)
        spec = ax.get_subplotspec()
        if spec is None:
            continue
        if not spec.is_first_col():
            ax.set_ylabel("")
        if i + spec.get_gridspec().ncols < len(data.names):
            ax.set_xlabel("")  # another map below
        else:
            ax.tick_params(labelbottom=True)  # the lowest map of its column
    for ax in axes[len(data.names):]:
        ax.axis("off")
        ax.legend(handles=category_legend_handles("reverse flow reaches the root", wrap=34), fontsize=8, loc="center")
        break


def figure_sensitivity(data: SensitivityData, figsize=(8.6, 10.4)):
    """The book's sensitivity figure (:func:`plot_sensitivity` on a grid two panels wide, shared
    axes, the legend in the spare cell), laid out and checked
    (:func:`rotorlyap.chapters.style.finish`); returns the Figure."""
    nrows = (len(data.names) + 2) // 2
    fig, axes = subplots(nrows, 2, figsize=figsize, sharex=True, sharey=True)
    plot_sensitivity(data, axes)
    return finish(fig)


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

    @property
    def default_stations_index(self) -> int:
        """Index in :attr:`n_stations` of the model's default number of stations."""
        return int(np.flatnonzero(self.n_stations == case_params("forward").n_stations)[0])

    def deviations(self) -> tuple[float, float, float]:
        """Largest relative deviations from the finest resolution: of the strict hover maxima
        with 64 or more directions (the second column on), of the three quantities at the
        default number of stations, and (absolute) of the per-azimuth fraction with
        ``W' > 0`` on coarser azimuth grids."""
        dev_ns = np.abs(self.sup_dW_hover[:, 1:] / self.sup_dW_hover[:, -1:] - 1).max()
        i = self.default_stations_index
        dev_st = max(abs(self.sup_dW_stations[i] / self.sup_dW_stations[-1] - 1),
                     abs(self.practical_rate_stations[i] / self.practical_rate_stations[-1] - 1),
                     np.abs(self.collective[:, i] / self.collective[:, -1] - 1).max())
        dev_psi = np.abs(self.positive_fraction_psi[:-1] - self.positive_fraction_psi[-1]).max()
        return float(dev_ns), float(dev_st), float(dev_psi)

    def bounds(self) -> tuple[float, float]:
        """The first two :meth:`deviations` in percent, as the power of ten they stay below
        (:func:`rotorlyap.reporting.decade_above`)."""
        dev_ns, dev_st, _ = self.deviations()
        return decade_above(max(100 * dev_ns, 1e-6)), decade_above(max(100 * dev_st, 1e-6))

    def summary(self) -> str:
        """Every convergence number (J/rad, deg, fractions) and the deviation bounds."""
        bound_ns, bound_st = self.bounds()
        i = self.default_stations_index
        return "\n".join([
            _line("n_sphere:", self.n_sphere),
            _line("strict hover max W' (J/rad):\n", np.round(self.sup_dW_hover, 2)),
            _line("n_stations:", self.n_stations),
            _line("collective (deg):\n", np.round(np.degrees(self.collective), 3)),
            _line("strict hover max W' (J/rad):", np.round(self.sup_dW_stations, 2)),
            _line(f"practical max W' at mu = {self.mu_check:g}, azimuth mean (J/rad):",
                  np.round(self.practical_rate_stations, 1)),
            _line("fraction of azimuths that do not pass (flap and lag axes) per mu, for n_psi =", self.n_psi),
            str(np.round(self.unstable_fraction_psi, 3)),
            "W' > 0 on the sphere (flap and lag axes), fraction of azimuths per mu:",
            str(np.round(self.positive_fraction_psi, 3)),
            f"largest deviation: n_sphere >= {self.n_sphere[1]}: < {bound_ns:.0e} %; "
            f"{self.n_stations[i]} stations vs {self.n_stations[-1]}: < {bound_st:.0e} %",
            "per-azimuth fraction, largest difference from %d azimuths: %.3f" % (self.n_psi[-1], self.deviations()[2]),
        ])

    def facts(self) -> dict:
        """``ch6_dev_ns``, ``ch6_dev_st`` (:meth:`bounds`, %) and ``ch6_dev_psi`` (0.001)."""
        bound_ns, bound_st = self.bounds()
        return {"ch6_dev_ns": bound_ns, "ch6_dev_st": bound_st, "ch6_dev_psi": round(self.deviations()[2], 3)}


#: Refined starts of every strict search of :func:`convergence_data`.
CONVERGENCE_N_REFINE = 16


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
                                        n_refine=CONVERGENCE_N_REFINE, n_iter=60).value[0]
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
                                    n_refine=CONVERGENCE_N_REFINE, n_iter=60).value[0]
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
    (c) the practical unstable fraction against mu for each azimuth grid. Each C.G. case in
    its colour and marker."""
    ax_a, ax_b, ax_c = axes
    ns = np.where(data.n_sphere == 0, 1, data.n_sphere)
    tick_labels = ["0" if v == 0 else f"{v // 1024}k" if v >= 1024 and v % 1024 == 0 else f"{v:d}"
                   for v in data.n_sphere]
    dev = lambda v, ref: 100.0 * (v / ref - 1.0)  # noqa: E731
    for i, cg in enumerate(CASES):
        ax_a.plot(ns, dev(data.sup_dW_hover[i], data.sup_dW_hover[i, -1]), "-", marker=CG_MARKERS[cg], ms=5,
                  color=CG_COLORS[cg], label=f"{cg} C.G.")
    ax_a.set_xscale("log", base=2)
    ax_a.set_xticks(ns, tick_labels)
    ax_a.axhline(0, color="0.5", lw=0.6)
    ax_a.set_xlabel("quasi-random directions per sphere\n(0 = structured only)", fontsize=9)
    ax_a.set_ylabel("strict max $W'$ in hover:\ndeviation from finest (%)", fontsize=9)
    ax_a.set_title("(a) sampling resolution", fontsize=9)
    ax_a.legend(fontsize=8)
    st = data.n_stations
    ax_b.plot(st, dev(data.sup_dW_stations, data.sup_dW_stations[-1]), "o-", color="k", ms=4,
              label="strict max $W'$, hover")
    ax_b.plot(st, dev(data.practical_rate_stations, data.practical_rate_stations[-1]), "D-", color="#0072B2", ms=4,
              label=f"practical max $W'$, $\\mu$ = {data.mu_check:g}\n(azimuth mean)")
    for i, cg in enumerate(CASES):
        ax_b.plot(st, dev(data.collective[i], data.collective[i, -1]), "--", marker=CG_MARKERS[cg], ms=4,
                  color=CG_COLORS[cg], label=f"collective, {cg} C.G.")
    ax_b.axhline(0, color="0.5", lw=0.6)
    ax_b.set_xticks(st)
    ax_b.set_xlabel("spanwise stations", fontsize=9)
    ax_b.set_ylabel(f"deviation from {st[-1]} stations (%)", fontsize=9)
    ax_b.set_title("(b) spanwise stations", fontsize=9)
    lo, hi = ax_b.get_ylim()
    ax_b.set_ylim(lo, hi + 0.75 * (hi - lo))  # room for the legend above the curves
    ax_b.legend(fontsize=8, loc="upper right")
    for k, npsi in enumerate(data.n_psi):
        line, = ax_c.plot(data.mu_values, data.unstable_fraction_psi[k], "o-", ms=3,
                          label=f"does not pass, {npsi} azimuths")
        ax_c.plot(data.mu_values, data.positive_fraction_psi[k], "s--", ms=3, color=line.get_color(),
                  label=f"$W' > 0$ on the sphere, {npsi} azimuths")
    ax_c.set_xlabel(r"advance ratio $\mu$", fontsize=9)
    ax_c.set_ylabel("fraction of azimuths", fontsize=9)
    ax_c.set_title(f"(c) azimuth grid (practical, {data.variant})", fontsize=9)
    ax_c.legend(fontsize=8, loc="center left", bbox_to_anchor=(1.01, 0.5))
    for ax in axes:
        ax.tick_params(labelsize=8)


def figure_convergence(data: ConvergenceData, figsize=(9.0, 7.4)):
    """The book's convergence figure (:func:`plot_convergence`: (a) and (b) side by side, (c)
    below them), laid out and checked (:func:`rotorlyap.chapters.style.finish`); returns the
    Figure."""
    fig = figure(figsize=figsize)
    grid = fig.add_gridspec(2, 2, height_ratios=(1.1, 1))
    axes = [fig.add_subplot(grid[0, 0]), fig.add_subplot(grid[0, 1]), fig.add_subplot(grid[1, :])]
    plot_convergence(data, axes)
    return finish(fig)
