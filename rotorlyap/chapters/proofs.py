"""The proofs chapter: numerical certificates beside the ones proved from enclosures.

* :func:`proof_table`: :func:`rotorlyap.certify` with ``verify=True`` for the Table I hovers and
  one forward-flight case of the trimmed helicopter (Taylor models and branch and bound): bound
  and start region, numerical and proved, the size of each term of the proof, the same
  function proved by ball arithmetic alone for comparison, and in forward flight which strips'
  air loads make the models' remainder large (:func:`rotorlyap.analysis.proof.remainder_sources`);
* :func:`nonlinear_growth` and :func:`figure_nonlinear_growth`: the ball-arithmetic prover's
  nonlinear term against the bound in hover, as enclosed and as sampled (why balls stop short);
* :func:`figure_flight_proof`: the forward-flight proof over the period: start radii and the
  terms per azimuth interval;
* :func:`example_proofs`: the systems of chapters 1 and 2 (the oscillator, the counterexample);
* :func:`reverse_flow_block`: where the enclosure of the trimmed helicopter's equations stops.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..analysis.certify import Certificate, certify
from ..analysis.functions import quadratic_function
from ..analysis.proof import FLIGHT_SHELLS, proof_problem, prove_blade
from ..conventions import DEFAULT_SCALES
from ..methods.proof import SHELL_CORE, Proof, nonlinear_bounds
from ..model.blade import Blade
from ..model.forward_trim import forward_flight_trim
from ..model.parameters import BladeParameters
from ..reporting import Rounded, decade_above

#: Below this, a residual term is round-off (the hover equilibrium's): printed as "< 1e-08".
ROUNDOFF_TERM = 1e-8


#: The residual term of a periodic motion refined by shooting sits at the shooting's noise floor,
#: which moves with the floating-point environment (the trimmed helicopter at mu = 0.1, scaled:
#: 1.2e-5 in this machine's environment, 3.2e-6 in CI's perturbed one, 2026-12-05). A forward-flight
#: residual is stated as a bound above this floor, the same in every environment.
SHOOTING_NOISE = 3e-5


def _range_text(values) -> str:
    """The smallest and largest of ratios as text, 3 decimals: ``"0.900 to 0.950"``, or the one
    value where both round alike (``"1.000"``)."""
    lo, hi = f"{min(values):.3f}", f"{max(values):.3f}"
    return lo if lo == hi else f"{lo} to {hi}"


def _bound_text(value: float, floor: float = 0.0) -> str:
    """A small non-negative term as a bound: ``"< 1e-08"`` at round-off, else the power of ten above
    it (above ``floor`` at least, for a term whose size is noise)."""
    value = max(float(value), float(floor))
    return f"< {ROUNDOFF_TERM:.0e}" if value < ROUNDOFF_TERM else f"< {decade_above(value):.0e}"
from .style import CG_COLORS, CG_MARKERS, finish, subplots

__all__ = ["FLIGHT_CASE", "HOVER_CASES", "ExampleProofs", "NonlinearGrowth", "ProofRow", "ProofTable",
           "ReverseFlowBlock", "example_proofs", "figure_flight_proof", "figure_nonlinear_growth",
           "nonlinear_growth", "proof_table", "reverse_flow_block"]

#: The Table I C.G. cases proved in hover.
HOVER_CASES: tuple[str, ...] = ("forward", "neutral", "backward")
#: The forward-flight case proved: the trimmed helicopter of chapter 8 (flight_case), forward C.G.,
#: mu = 0.1: the largest advance ratio of chapter 8's grid (steps of 0.05) below 0.15, where the
#: reverse-flow edge reaches a compressible section, the equations jump and no proof of this kind
#: exists (:func:`reverse_flow_block`).
FLIGHT_CASE: tuple[str, float] = ("forward", 0.1)


@dataclass(frozen=True)
class ProofRow:
    """One case: the numerical certificate and the proved one (scaled norm).

    Attributes
    ----------
    key : str
        The case in the names of the glued facts (``forward``, ..., ``flight``).
    label : str
        The case as the table names it.
    certificate : Certificate
        :func:`rotorlyap.certify` with ``verify=True`` (its proof: Taylor models and branch and
        bound, :func:`rotorlyap.analysis.proof.prove_blade`'s default).
    balls : Proof, optional
        The same function proved by ball arithmetic alone (``method="balls"``, the mean-value
        form over the tube), for comparison.
    band : Proof, optional
        The same function proved on the whole band of the theorem's condition (h)
        (``level_set=False``), for comparison (hover).
    """

    key: str
    label: str
    certificate: Certificate
    balls: Proof | None = None
    band: Proof | None = None

    @property
    def numerical(self) -> tuple[float, float]:
        """(bound, smallest start radius) of the numerical certificate."""
        return self.certificate.bound, self.certificate.start_region

    @property
    def proved(self) -> tuple[float, float]:
        """(bound, smallest start radius) of the proof (zeros if not proved)."""
        p = self.certificate.proof
        return p.A, p.min_lambda0

    @property
    def ratio(self) -> float:
        """Proved over numerical smallest start radius."""
        return self.proved[1] / self.numerical[1] if self.numerical[1] > 0 else 0.0

    @property
    def balls_ratio(self) -> float:
        """The ball-arithmetic proof's smallest start radius over the numerical one (NaN without)."""
        if self.balls is None or not self.numerical[1] > 0:
            return float("nan")
        return self.balls.min_lambda0 / self.numerical[1]

    @property
    def band_ratio(self) -> float:
        """The band proof's smallest start radius over the numerical one (NaN without)."""
        if self.band is None or not self.numerical[1] > 0:
            return float("nan")
        return self.band.min_lambda0 / self.numerical[1]

    @property
    def residual_text(self) -> str:
        """The steady motion's residual term as a bound (:func:`_bound_text`; in forward flight above
        :data:`SHOOTING_NOISE`)."""
        floor = SHOOTING_NOISE if self.certificate.mu > 0 else 0.0
        return _bound_text(self.term("residual"), floor)

    def term(self, name: str) -> float:
        """The largest over the period of a term of the proof at the proved bound."""
        return float(np.max(self.certificate.proof.terms[name]))


@dataclass(frozen=True)
class ProofTable:
    """The certificates of :func:`proof_table`, one row per case.

    Attributes
    ----------
    rows : tuple of ProofRow
    collocation_residual : float
        The flight case: largest residual ``|h(psi, xi) - xi'|`` in the scaled norm of the Fourier
        collocation's periodic motion (tabulated), at 4096 azimuths between its grid points, before
        the shooting refines it (NaN without a flight case).
    """

    rows: tuple[ProofRow, ...]
    collocation_residual: float = float("nan")

    def markdown(self) -> str:
        """The table: bound and start radius, numerical and proved, their ratio, and the ratio the
        band's proof reaches (a dash where it is not run)."""
        head = ("| case | numerical $A$ | numerical $\\lambda_0$ | proved $A$ | proved $\\lambda_0$ "
                "| proved / numerical $\\lambda_0$ | on the band: proved / numerical $\\lambda_0$ |"
                "\n|---|---|---|---|---|---|---|")
        lines = [head]
        for r in self.rows:
            (na, nl), (pa, pl) = r.numerical, r.proved
            band = "–" if r.band is None else f"{r.band_ratio:.3f}"
            lines.append(f"| {r.label} | {na:.3g} | {nl:.3g} | {pa:.3g} | {pl:.3g} | {r.ratio:.3f} | {band} |")
        return "\n".join(lines)

    def summary(self) -> str:
        """One line per case (3 significant digits), then the terms of each proof."""
        out = []
        for r in self.rows:
            (na, nl), (pa, pl) = r.numerical, r.proved
            out.append(f"{r.label}: numerical A {na:.3g}, lambda0 {nl:.3g}; proved A {pa:.3g}, "
                       f"lambda0 {pl:.3g}; ratio {r.ratio:.3f}; {r.certificate.proof.n_intervals} intervals")
            out.append(f"    terms at the proved bound: linear <= {r.term('linear'):.3f}, "
                       f"Taylor-model remainder <= {r.term('deviation'):.2g}, |S g0| {r.residual_text}")
            if r.band is not None:
                out.append(f"    on the whole band (condition (h)): A {r.band.A:.3g}, lambda0 "
                           f"{r.band.min_lambda0:.3g}; ratio {r.band_ratio:.3f}")
            if r.balls is not None:
                out.append(f"    ball arithmetic alone (mean-value form): A {r.balls.A:.3g}, lambda0 "
                           f"{r.balls.min_lambda0:.3g}; ratio {r.balls_ratio:.3f}")
        return "\n".join(out)

    def facts(self) -> dict:
        """``ch10_<key>_{numA,numl0,A,l0,ratio,lin,dev,res,flap,numflap}`` per case (3 significant
        digits; ``flap``: the start region's flap disturbance alone, deg, 2 digits;
        the residual term as a bound, :func:`_bound_text`), plus ``ch10_flight_tight`` (the azimuth,
        whole deg, where the flight case's nonlinear term comes closest to zero), ``ch10_hover_res``
        (the largest residual term) over the hovers and the
        flight case's ``ch10_flight_mu`` and ``ch10_flight_n``; the settings the text quotes: the
        numerical certificates' azimuths ``ch10_n_psi``, the Taylor models' order
        ``ch10_taylor_order`` (:func:`rotorlyap.analysis.proof.prove_blade`'s default) and the
        step of chapter 8's advance-ratio grid ``ch10_mu_step``; the proof's shells
        (``ch10_shell_ratio``, ``ch10_shell_core``: the settings of
        :func:`rotorlyap.analysis.proof.prove_blade` on the level set) and the flight case's proved
        bound as a fraction of the numerical one, ``ch10_flight_Afrac`` (2 decimals); where the band's
        proofs ran, ``ch10_<key>_band_ratio``; over the hovers the ranges of the ratios as text,
        ``ch10_ratio_range``, ``ch10_band_range``, ``ch10_balls_range`` (:func:`_range_text`)."""
        import inspect

        from .scans import MU_FORENSIC

        f = {"ch10_n_psi": int(self.rows[0].certificate.result.psi.size),
             "ch10_taylor_order": int(inspect.signature(prove_blade).parameters["order"].default),
             "ch10_mu_step": float(f"{MU_FORENSIC[1] - MU_FORENSIC[0]:.3g}")}
        for r in self.rows:
            key = r.key
            (na, nl), (pa, pl) = r.numerical, r.proved
            cert = r.certificate
            f[f"ch10_{key}_flap"] = float(f"{cert._per_hinge(pl)['flap'][0]:.2g}")
            f[f"ch10_{key}_numflap"] = float(f"{cert._per_hinge(nl)['flap'][0]:.2g}")
            f.update({f"ch10_{key}_numA": float(f"{na:.3g}"), f"ch10_{key}_numl0": float(f"{nl:.3g}"),
                      f"ch10_{key}_A": float(f"{pa:.3g}"), f"ch10_{key}_l0": float(f"{pl:.3g}"),
                      f"ch10_{key}_ratio": Rounded(r.ratio, 3),
                      f"ch10_{key}_lin": Rounded(r.term("linear"), 3),
                      f"ch10_{key}_dev": float(f"{r.term('deviation'):.2g}"),
                      f"ch10_{key}_res": r.residual_text})
            if r.balls is not None:
                f[f"ch10_{key}_balls_ratio"] = Rounded(r.balls_ratio, 3)
            if r.band is not None:
                f[f"ch10_{key}_band_ratio"] = Rounded(r.band_ratio, 3)
        hover = [r for r in self.rows if r.certificate.mu == 0]
        if hover and all(r.band is not None for r in hover):
            f["ch10_band_range"] = _range_text([r.band_ratio for r in hover])
        if all(r.balls is not None for r in hover):
            f["ch10_balls_range"] = _range_text([r.balls_ratio for r in hover])
        f["ch10_ratio_range"] = _range_text([r.ratio for r in hover])
        f["ch10_hover_res"] = _bound_text(max(r.term("residual") for r in hover))
        flight = [r for r in self.rows if r.certificate.mu > 0]
        if flight:
            proof = flight[0].certificate.proof
            f["ch10_flight_mu"] = flight[0].certificate.mu
            f["ch10_flight_n"] = proof.n_intervals
            k = int(np.argmax(proof.terms["nonlinear"]))
            f["ch10_flight_tight"] = round(float(np.degrees(proof.psi[k] + np.pi / proof.n_intervals)))
            f["ch10_colloc_res"] = float(f"{self.collocation_residual:.1g}")
            # the proof over shells of cubes (prove_blade's defaults on the level set)
            f["ch10_shell_ratio"] = FLIGHT_SHELLS
            f["ch10_shell_core"] = SHELL_CORE
            f["ch10_flight_Afrac"] = float(f"{proof.A / flight[0].numerical[0]:.2f}")
        return f

    def export(self) -> dict:
        """Columns for the CSV."""
        return {
            "case": [r.label for r in self.rows],
            "mu": [r.certificate.mu for r in self.rows],
            "numerical_A": [r.numerical[0] for r in self.rows],
            "numerical_lambda0": [r.numerical[1] for r in self.rows],
            "proved_A": [r.proved[0] for r in self.rows],
            "proved_lambda0": [r.proved[1] for r in self.rows],
            "linear_max": [r.term("linear") for r in self.rows],
            "nonlinear_max": [r.term("nonlinear") for r in self.rows],
            "residual_max": [r.term("residual") for r in self.rows],
        }


def proof_table(hover_cases=HOVER_CASES, flight=FLIGHT_CASE) -> ProofTable:
    """:func:`rotorlyap.certify` of the quadratic function with ``verify=True`` for each hover case
    (Table I, hover trim) and the forward-flight case (``None`` to skip it): the trimmed helicopter
    of chapter 8."""
    def row(key, label, cert, compare: bool = False):
        balls = prove_blade(cert.lyapunov, cert.bound, method="balls") if cert.certified and compare else None
        on_band = prove_blade(cert.lyapunov, cert.bound, level_set=False) if cert.certified and compare else None
        return ProofRow(key, label, cert, balls, on_band)

    # the quadratic function by name: this chapter proves it (verify=True proves the function
    # certify returns, by default the augmented energy where it certifies more: chapter 10)
    # in hover also the band's proof (condition (h) on the whole band) and ball arithmetic's, about a
    # second together; in forward flight they take as long as the level set's proof (the README's
    # measurements, python benchmarks/bench_proof.py --flight), so the chapter does not run them
    rows = [row(cg, f"{cg} C.G., hover", certify(BladeParameters.table_i(cg), 0.0, function="quadratic",
                                                 verify=True), compare=True)
            for cg in hover_cases]
    residual = float("nan")
    if flight is not None:
        cg, mu = flight
        cert = certify(BladeParameters.flight_case(cg), float(mu), function="quadratic", verify=True)
        rows.append(row("flight", f"{cg} C.G., mu = {mu:g}, trimmed", cert))
        residual = _collocation_residual(cert)
    return ProofTable(tuple(rows), residual)


def _collocation_residual(cert: Certificate, n: int = 4096) -> float:
    """Largest scaled residual of the trim's (collocated) periodic motion, tabulated as
    :func:`rotorlyap.certify` tabulates it without ``verify``, at the midpoints of its grid."""
    from ..model.steady import tabulate_motion

    tab = tabulate_motion(cert.trim.motion, n=n)
    blade = Blade(cert.trim.params, cert.mu)
    psi = 2 * np.pi * (np.arange(n) + 0.5) / n
    r = (blade.rhs(psi, tab.xi(psi)) - tab.dxi(psi)) / cert.scales
    return float(np.max(np.linalg.norm(r, axis=1)))


# --------------------------------------------------------------------------------------
# The nonlinear term against the bound
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class NonlinearGrowth:
    """The proof's nonlinear term ``max n`` against the bound ``A`` in hover.

    Attributes
    ----------
    cases : tuple of str
        C.G. cases.
    A : numpy.ndarray
        Bounds (scaled norm), (m,).
    enclosed : numpy.ndarray
        ``max n`` as the proof encloses it (ball arithmetic), (cases, m).
    sampled : numpy.ndarray
        The same matrix's largest eigenvalue at sampled states of the sphere ``|y| = A`` (float
        Jacobians averaged along the ray, 3-point Gauss): a lower estimate of the exact term, (cases, m).
    n_samples : int
        States sampled per bound.
    """

    cases: tuple
    A: np.ndarray
    enclosed: np.ndarray
    sampled: np.ndarray
    n_samples: int

    def crossing(self, which: str = "enclosed") -> np.ndarray:
        """Per case, the bound where ``max n`` reaches 0 (log-linear interpolation; NaN if it does
        not in the range)."""
        vals = getattr(self, which)
        out = np.full(len(self.cases), np.nan)
        for i, v in enumerate(vals):
            k = np.flatnonzero((v[:-1] < 0) & (v[1:] >= 0))
            if k.size:
                j = int(k[0])
                t = -v[j] / (v[j + 1] - v[j])
                out[i] = float(np.exp(np.log(self.A[j]) + t * (np.log(self.A[j + 1]) - np.log(self.A[j]))))
        return out

    def summary(self) -> str:
        """Per case, the bounds where the term crosses zero, enclosed and sampled (2 digits)."""
        ce, cs = self.crossing("enclosed"), self.crossing("sampled")
        return "\n".join(f"{c} C.G.: max n = 0 at A = {e:.2g} (enclosed), {s:.2g} (sampled); ratio {s / e:.2g}"
                         for c, e, s in zip(self.cases, ce, cs))

    def facts(self) -> dict:
        """``ch10_cross_<case>_{enc,smp,gap}``: the zero crossings and their ratio (2 digits);
        ``ch10_gap_lo``/``_hi``: the smallest and largest ratio."""
        f = {}
        gaps = []
        for c, e, s in zip(self.cases, self.crossing("enclosed"), self.crossing("sampled")):
            gaps.append(s / e)
            f.update({f"ch10_cross_{c}_enc": float(f"{e:.2g}"), f"ch10_cross_{c}_smp": float(f"{s:.2g}"),
                      f"ch10_cross_{c}_gap": float(f"{s / e:.2g}")})
        f["ch10_gap_lo"], f["ch10_gap_hi"] = float(f"{min(gaps):.2g}"), float(f"{max(gaps):.2g}")
        return f

    def export(self) -> dict:
        """Columns for the CSV: the bounds, then both curves per case."""
        cols = {"A": self.A}
        for c, e, s in zip(self.cases, self.enclosed, self.sampled):
            cols[f"{c}_enclosed"] = e
            cols[f"{c}_sampled"] = s
        return cols


def _sampled_term(fun, A: float, u: np.ndarray) -> float:
    """``max lambda_max(S' + K^T S + S K)`` over the rays ``u`` (unit, scaled) at radius ``A``, with
    ``K`` the float Jacobian averaged along the ray by 3-point Gauss-Legendre."""
    a = fun.scales
    xi = fun.steady.state
    t, w = np.polynomial.legendre.leggauss(3)
    t, w = 0.5 * (t + 1), 0.5 * w
    psi = np.zeros(u.shape[0])
    K = sum(wi * fun.blade.jacobian(psi, xi + ti * A * u * a) for ti, wi in zip(t, w))
    K = K / a[None, :, None] * a[None, None, :]
    S = fun.solution.P_grid[0]
    S = 0.5 * (S + S.T)
    SK = np.einsum("ij,mjk->mik", S, K)
    return float(np.linalg.eigvalsh(SK + np.swapaxes(SK, 1, 2)).max())


def nonlinear_growth(cases=HOVER_CASES, A=None, n_samples: int = 2000, seed: int = 0) -> NonlinearGrowth:
    """The proof's nonlinear term against the bound for each hover case, enclosed and sampled.

    Parameters
    ----------
    cases : tuple of str
        C.G. cases (Table I, hover trim: the function :func:`rotorlyap.certify` uses).
    A : array_like, optional
        Bounds (scaled norm); default 25 from 1e-3 to 1, logarithmic.
    n_samples : int
        Rays sampled (normal directions, fixed seed) per bound for the sampled curve.
    seed : int
        Seed of the rays.
    """
    A = np.geomspace(1e-3, 1.0, 25) if A is None else np.asarray(A, dtype=float)
    rng = np.random.default_rng(seed)
    u = rng.normal(size=(n_samples, 6))
    u /= np.linalg.norm(u, axis=1)[:, None]
    enclosed, sampled = [], []
    for cg in cases:
        trim = forward_flight_trim(BladeParameters.table_i(cg), 0.0)
        fun = quadratic_function(Blade(trim.params, 0.0), trim.steady, scales=DEFAULT_SCALES)
        system, quadratic, N = proof_problem(fun)
        enclosed.append(nonlinear_bounds(system, quadratic, A, scales=fun.scales, n_intervals=N))
        sampled.append(np.array([_sampled_term(fun, float(x), u) for x in A]))
    return NonlinearGrowth(cases=tuple(cases), A=A, enclosed=np.array(enclosed), sampled=np.array(sampled),
                           n_samples=int(n_samples))


def figure_nonlinear_growth(data: NonlinearGrowth, figsize=(6.4, 4.8)):
    """``max n`` against ``A``: enclosed (solid) and sampled (dashed) per C.G. case, zero marked.
    Returns the figure."""
    fig, ax = subplots(figsize=figsize)
    for c, e, s in zip(data.cases, data.enclosed, data.sampled):
        col, m = CG_COLORS.get(c, "k"), CG_MARKERS.get(c, "o")
        ax.plot(data.A, e, "-", color=col, marker=m, ms=4, label=f"{c} C.G., enclosed by balls")
        ax.plot(data.A, s, "--", color=col, marker=m, ms=4, mfc="white", label=f"{c} C.G., sampled")
    ax.axhline(0.0, color="k", lw=0.8)
    ax.set_xscale("log")
    ax.set_ylim(-1.2, 2.0)
    ax.set(xlabel="bound $A$ (scaled norm)", ylabel=r"largest $n$ over the tube (per rev)")
    ax.legend(fontsize=8.5, loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=2, frameon=False)
    return finish(fig)


def figure_flight_proof(row: ProofRow, figsize=(6.6, 5.6)):
    """The forward-flight proof over the period: (a) start radius, proved per interval and numerical
    per azimuth (scaled norm); (b) the linear and nonlinear terms per interval at the
    proved bound. Returns the figure."""
    cert = row.certificate
    proof = cert.proof
    fig, (ax1, ax2) = subplots(2, 1, figsize=figsize, sharex=True)
    psi_p = np.degrees(proof.psi + 0.5 * (2 * np.pi / proof.n_intervals))
    ax1.plot(psi_p, proof.lambda0, "-", color="k", lw=1.2,
             label=f"proved, $A$ = {proof.A:.3g} ({proof.n_intervals} intervals)")
    res = cert.result
    ax1.plot(np.degrees(res.psi), res.lambda0, "o", color=CG_COLORS["forward"], ms=4,
             label=f"numerical, $A$ = {cert.bound:.3g} ({res.psi.size} azimuths)")
    ax1.set_ylim(0.0, 1.25 * max(float(np.max(res.lambda0)), float(np.max(proof.lambda0))))
    ax1.set(ylabel=r"start radius $\lambda_0$ (scaled)")
    # below both curves, where the axis from zero leaves room (issue 42: "center right" covered the
    # proved line from 240 to 360 deg)
    ax1.legend(fontsize=8.5, loc="lower center", ncol=2)
    ax2.plot(psi_p, proof.terms["linear"], "-", color="0.5", lw=1, label="linear part (tube radius 0)")
    ax2.plot(psi_p, proof.terms["nonlinear"], "-", color="k", lw=1,
             label="polynomial part on the level set (estimate)")
    ax2.axhline(0.0, color="k", lw=0.8)
    lo = min(float(np.min(proof.terms["linear"])), float(np.min(proof.terms["nonlinear"])))
    ax2.set(xlabel=r"azimuth $\psi$ (deg)", ylabel=r"largest $W' / |y|^2$ (per rev)", xlim=(0, 360),
            xticks=np.arange(0, 361, 60), ylim=(min(lo, 0.0) - 0.1, 0.5))
    ax2.legend(fontsize=8.5, loc="upper center", ncol=2)  # above the zero line, clear of the curves
    ax1.set_title("(a) start radius", fontsize=10, loc="left")
    ax2.set_title("(b) the terms of the proof", fontsize=10, loc="left")
    return finish(fig)


# --------------------------------------------------------------------------------------
# The systems of chapters 1 and 2, and where the enclosure stops
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class ExampleProofs:
    """The proof on the systems of the method chapters.

    Attributes
    ----------
    oscillator_numerical : tuple of float
        (bound, smallest start radius) of the sound rule's numerical certificate of the
        Mathieu-Duffing oscillator of chapter 1 (72 azimuths).
    oscillator_proved : tuple of float
        The same, proved (256 azimuth intervals).
    counterexample_proved : bool
        Whether the proof succeeded on chapter 2's counterexample (it must not).
    counterexample_message : str
        Why it did not.
    """

    oscillator_numerical: tuple
    oscillator_proved: tuple
    counterexample_proved: bool
    counterexample_message: str

    def summary(self) -> str:
        """Three lines (3 significant digits)."""
        (na, nl), (pa, pl) = self.oscillator_numerical, self.oscillator_proved
        return "\n".join([
            f"oscillator of chapter 1: numerical A {na:.3g}, lambda0 {nl:.3g}; proved A {pa:.3g}, lambda0 {pl:.3g}",
            f"counterexample of chapter 2: {'proved' if self.counterexample_proved else 'not proved'}",
            f"    {self.counterexample_message}"])

    def facts(self) -> dict:
        """``ch10_osc_{numA,numl0,A,l0}``, ``ch10_cx_proved`` ("proved" or "not proved")."""
        (na, nl), (pa, pl) = self.oscillator_numerical, self.oscillator_proved
        return {"ch10_osc_numA": float(f"{na:.3g}"), "ch10_osc_numl0": float(f"{nl:.3g}"),
                "ch10_osc_A": float(f"{pa:.3g}"), "ch10_osc_l0": float(f"{pl:.3g}"),
                "ch10_cx_proved": "proved" if self.counterexample_proved else "not proved"}


def example_proofs() -> ExampleProofs:
    """The chapter-1 oscillator (numerical certificate and proof) and chapter 2's counterexample."""
    from ..methods.examples import mathieu_duffing, mathieu_duffing_proof, pulsed_growth_proof
    from ..methods.lyapunov import technical_stability
    from ..methods.proof import prove_quadratic

    s = mathieu_duffing()
    numerical = technical_stability(s.f, s.W, 1.0, dim=s.dim, dW=s.dW, n_psi=72, rule="sound")
    system, quadratic = mathieu_duffing_proof()
    proof = prove_quadratic(system, quadratic, 1.0, scales=[1.0, 1.0], n_intervals=256)
    cx_system, cx_quadratic = pulsed_growth_proof()
    cx = prove_quadratic(cx_system, cx_quadratic, 1.0, scales=[1.0], n_intervals=64)
    return ExampleProofs(oscillator_numerical=(float(numerical.A), float(np.min(numerical.lambda0))),
                         oscillator_proved=(proof.A, proof.min_lambda0),
                         counterexample_proved=cx.proved, counterexample_message=cx.message)


@dataclass(frozen=True)
class ReverseFlowBlock:
    """Where the enclosure of the trimmed helicopter's equations stops (compressible sections).

    Attributes
    ----------
    mu : float
        Advance ratio.
    n_intervals : int
        Azimuth intervals evaluated (the steady motion's tube of radius 0).
    blocked : numpy.ndarray
        Per interval: no enclosure (the angle of attack of a compressible section may cross 90 deg).
    reason : str
        The enclosure's reason, or "" where nothing is blocked.
    """

    mu: float
    n_intervals: int
    blocked: np.ndarray
    reason: str

    def span(self) -> tuple[float, float]:
        """First and last blocked azimuth (deg, interval midpoints); NaN if none."""
        k = np.flatnonzero(self.blocked)
        if not k.size:
            return float("nan"), float("nan")
        mid = 360.0 * (k + 0.5) / self.n_intervals
        return float(mid.min()), float(mid.max())

    def summary(self) -> str:
        """One line: how many intervals are blocked, where, why."""
        lo, hi = self.span()
        return (f"mu = {self.mu:g}: {int(self.blocked.sum())} of {self.n_intervals} intervals blocked, "
                f"psi {lo:.0f} to {hi:.0f} deg" + (f": {self.reason}" if self.reason else ""))

    def facts(self) -> dict:
        """``ch10_block_{mu,lo,hi}``: the advance ratio and the blocked azimuths (whole deg)."""
        lo, hi = self.span()
        return {"ch10_block_mu": self.mu, "ch10_block_lo": round(lo), "ch10_block_hi": round(hi)}


def reverse_flow_block(case: str = "forward", mu: float = 0.15, n_intervals: int = 64) -> ReverseFlowBlock:
    """The enclosure of the trimmed helicopter's equations about its periodic motion at ``mu``
    (compressible sections): which azimuth intervals it cannot enclose."""
    from ..analysis.enclosure import BladeEnclosure
    from ..model.steady import tabulate_motion

    trim = forward_flight_trim(BladeParameters.flight_case(case), float(mu))
    ev = BladeEnclosure(Blade(trim.params, float(mu)), tabulate_motion(trim.motion, n=256)).evaluate(n_intervals)
    blocked = np.zeros(n_intervals, dtype=bool)
    for mask in ev.blocked.values():
        blocked |= mask
    return ReverseFlowBlock(mu=float(mu), n_intervals=n_intervals, blocked=blocked,
                            reason="; ".join(ev.blocked))
