"""One call that certifies: the trim, the steady motion, a certifying function and the sound rule.

:func:`certify` is the path that chapters 7 and 8 show to certify technical stability where the
paper's energy cannot: the blade trimmed (in forward flight the helicopter, by
:func:`rotorlyap.model.forward_trim.forward_flight_trim`), its own steady motion (the trimmed
hover state, or the periodic motion), a Liapunov function about it, and the strict reading with
the sound rule (the theorem's (h) over the whole period) in
:func:`rotorlyap.analysis.stability.blade_stability`. The result reads as an engineer would:
which disturbances, per hinge in degrees and degrees per second, are guaranteed to keep the
motion within which bound.

The function (``function=``): ``"quadratic"``, the quadratic form of the linearised blade
(:func:`rotorlyap.analysis.functions.quadratic_function`: seconds, the linear range);
``"energy"`` or ``"polynomial"``, a function designed for the nonlinear range
(:func:`rotorlyap.analysis.nonlinear_functions.designed_function`: the augmented energy, or a
polynomial; tens of seconds, ``benchmarks/bench_certify.py``); ``"auto"`` (the default), the
quadratic function and the augmented energy both, and the certificate with the larger start
region, so that a user gets the largest certificate without choosing (where the linearised
blade is unstable only the quadratic function is tried: it says why nothing can be certified).

Every such result rests on sampled searches of ``W'``: it is a numerical certificate, and its
message says so. With ``verify=True`` the function of the certificate returned is also *proved*
from enclosures (:func:`prove_certificate`: :func:`rotorlyap.analysis.proof.prove_blade` for the
quadratic function, Taylor models of the equations in float balls and a branch and bound over the
band; :func:`rotorlyap.analysis.designed_proof.prove_designed_level` for a designed hover
function, its level set through the ball of ``proof_fraction`` of the numerical start radius
shown invariant, issue 41): the result carries the proof, with the bound and start radius that
follow from the theorem for the model as enclosed, and a :class:`ProvedPart` saying what is
proved as fractions of the numerical certificate, or why nothing is (a function no prover
encloses). In forward flight a
proof needs a steady motion with a residual near round-off, so ``verify=True`` first refines the
periodic motion by shooting (:func:`rotorlyap.model.steady.refine_motion`) and computes both
certificates about it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..conventions import DEFAULT_A, DEFAULT_SCALES, HINGES
from ..errors import NotAsymptoticallyStableError
from ..methods.lyapunov import TechnicalStabilityResult
from ..model.blade import Blade
from ..model.forward_trim import TRIM_TARGETS, ForwardFlightTrim, forward_flight_trim
from ..model.parameters import BladeParameters
from ..methods.proof import Proof
from ..methods.start_set import StartSet, start_set
from ..progress import report
from ..model.steady import refine_motion, tabulate_motion
from .floquet import blade_floquet
from .functions import quadratic_function
from .nonlinear_functions import DESIGN_EFFORTS, FAMILIES, designed_function
from .proof import prove_blade
from .stability import blade_stability

__all__ = ["FUNCTIONS", "Candidate", "Certificate", "ProvedPart", "certify", "function_start_set",
           "prove_certificate"]

FUNCTIONS = ("auto", "quadratic") + FAMILIES
"""The ``function`` choices of :func:`certify` (module docstring)."""


@dataclass(frozen=True)
class Candidate:
    """One function :func:`certify` tried: its family, verdict, bound and start radius (scaled norm);
    for a designed family, ``tried`` holds the scenario program's attempts ``(lam, A, designed)``
    (:attr:`rotorlyap.methods.scenario.Design.tried`: where its search stopped, and why);
    ``start_set``, where certified, the reach of the certified start set along each state
    component, scaled norm, the smaller sign at the worst start azimuth
    (:attr:`rotorlyap.methods.start_set.StartSet.axis_reach`; empty where not certified)."""

    function: str
    certified: bool
    bound: float
    start_region: float
    message: str
    tried: tuple = ()
    start_set: tuple = ()


@dataclass(frozen=True)
class ProvedPart:
    """What ``verify=True`` proved of the certificate :func:`certify` returns (its own function).

    Attributes
    ----------
    function : str
        The family of the function proved: the certificate's own (``"quadratic"``, ``"energy"``
        or ``"polynomial"``).
    proved : bool
        True if a bound was proved (``bound > 0``).
    method : str
        The prover, e.g. ``"Taylor models and branch and bound (prove_blade)"``; empty where no
        prover could take the function.
    bound : float
        The proved bound ``A``, scaled norm (0 if nothing is proved).
    start_region : float
        The smallest proved start radius over the period, scaled norm (0 if nothing).
    bound_fraction : float
        ``bound`` over the numerical certificate's bound (0 where nothing is proved; NaN where
        nothing was certified numerically).
    start_fraction : float
        ``start_region`` over the numerical certificate's start region (as ``bound_fraction``).
    not_proved : str
        Empty where something is proved; else why nothing is (the prover's message, or why no
        prover takes the function).
    """

    function: str
    proved: bool
    method: str
    bound: float
    start_region: float
    bound_fraction: float
    start_fraction: float
    not_proved: str = ""

    def __str__(self) -> str:
        if not self.proved:
            return f"{self.function} function not proved: {self.not_proved}"
        return (f"{self.function} function proved ({self.method}): bound {self.bound:.3g} "
                f"({self.bound_fraction:.3g} of the numerical), start region {self.start_region:.3g} "
                f"({self.start_fraction:.3g} of the numerical)")


@dataclass(frozen=True)
class Certificate:
    """Result of :func:`certify`.

    Attributes
    ----------
    certified : bool
        True if the sound rule certified every azimuth: motions that start within the start
        region stay within the bound for ever (a numerical certificate).
    mu : float
        Advance ratio.
    condition : str
        The flight condition, one of :data:`rotorlyap.model.forward_trim.TRIM_TARGETS`.
    trim : ForwardFlightTrim
        The trim: controls, shaft tilt, inflow and the steady motion.
    growth_rate : float
        Largest real part of the Floquet exponents about the steady motion, per rev (in units of
        the rotor speed, i.e. per rad of azimuth: the amplitude grows by ``exp(2 pi growth_rate)``
        each revolution; linear theory, for comparison).
    bound : float
        The certified bound ``A`` of the scaled norm (0 if nothing is certified).
    start_region : float
        The smallest start radius ``lambda0`` over the azimuths, scaled norm (0 if nothing).
    scales : numpy.ndarray
        The norm's scales ``a_i``, rad and rad/rad, (6,).
    result : TechnicalStabilityResult or None
        The engine's result (None where no quadratic function exists).
    message : str
        What was certified, or why nothing was.
    proof : Proof or None
        ``verify=True``: the proof of the certificate's own function (bound, level, start radii
        per azimuth interval, or why nothing was proved); None otherwise, and where no prover takes
        the function (see ``proved_part``).
    function : str
        The family of the function the certificate rests on (``"quadratic"``, ``"energy"`` or
        ``"polynomial"``).
    candidates : tuple of Candidate
        Every function tried, in order (one unless ``function="auto"``).
    lyapunov : object or None
        The function itself (``W``, ``dW``, ``f``), for a falsifier or a figure; None where none
        was built.
    start_set : StartSet or None
        Where certified: the start set ``{||x|| < A, W(psi0, x) < alpha}`` that the sound rule
        certifies, measured along the signed hinge axes at every start azimuth
        (:func:`rotorlyap.methods.start_set.start_set`); it holds the ball ``start_region`` and
        reaches further along most hinges. None where nothing is certified.
    proved_part : ProvedPart or None
        ``verify=True``: which part of this certificate is proved (the bound, start region and
        their fractions of the numerical ones, the prover), or why nothing is; None otherwise.
    """

    certified: bool
    mu: float
    condition: str
    trim: ForwardFlightTrim
    growth_rate: float
    bound: float
    start_region: float
    scales: np.ndarray
    result: TechnicalStabilityResult | None
    message: str
    proof: Proof | None = None
    function: str = "quadratic"
    candidates: tuple = ()
    lyapunov: object | None = None
    start_set: StartSet | None = None
    proved_part: ProvedPart | None = None

    def _per_hinge(self, radius) -> dict:
        omega = self.trim.params.rotor_speed
        a = np.degrees(self.scales) * np.broadcast_to(radius, self.scales.shape)
        return {h: (float(a[i]), float(a[i + 3] * omega)) for i, h in enumerate(HINGES)}

    @property
    def start_region_per_hinge(self) -> dict:
        """``{hinge: (deg, deg/s)}``: a disturbance of one hinge alone, angle or rate, within these
        is inside the start region (a combined disturbance must satisfy the scaled norm)."""
        return self._per_hinge(self.start_region)

    @property
    def start_set_per_hinge(self) -> dict:
        """``{hinge: (deg, deg/s)}``: how far the certified start set reaches along each hinge
        angle and rate alone (the smaller sign, the worst start azimuth); empty if not certified."""
        return {} if self.start_set is None else self._per_hinge(self.start_set.axis_reach)

    @property
    def bound_per_hinge(self) -> dict:
        """``{hinge: (deg, deg/s)}``: the bound's extent along each hinge angle and rate."""
        return self._per_hinge(self.bound)

    def save(self, path: str | Path) -> Path:
        """Write the certificate as a JSON file that :func:`rotorlyap.verify` checks from nothing
        (:func:`rotorlyap.analysis.certificate_file.save_certificate`); returns the path."""
        from .certificate_file import save_certificate

        return save_certificate(self, path)

    def summary(self) -> str:
        """The verdict, then per hinge (0.01 deg, 0.1 deg/s) the start ball, the start set along each
        hinge alone and the bound, and the proof's where there is one."""
        by = {"quadratic": "", "energy": " by the augmented energy",
              "polynomial": " by the polynomial function"}[self.function]
        head = (f"mu = {self.mu:g}, {self.condition}: {'certified' + by if self.certified else 'not certified'}"
                f" (largest Floquet real part {self.growth_rate:.3f} per rev)")
        if not self.certified:
            if "growth rate" in self.message:  # the message gives the linear reason itself: say it once
                return f"mu = {self.mu:g}, {self.condition}: not certified:\n  {self.message}"
            return head + "\n  " + self.message
        fmt = lambda d: ", ".join(f"{h} {v[0]:.2f} deg / {v[1]:.1f} deg/s" for h, v in d.items())  # noqa: E731
        lines = [head, f"  start within (ball lambda0): {fmt(self.start_region_per_hinge)}"]
        if self.start_set is not None:
            lines.append(f"  start set, each hinge alone: {fmt(self.start_set_per_hinge)}")
        lines.append(f"  stays within: {fmt(self.bound_per_hinge)}")
        part = self.proved_part
        if part is not None:
            if part.proved:
                lines += [f"  proved ({part.method}): start within {fmt(self._per_hinge(part.start_region))}",
                          f"  proved: stays within {fmt(self._per_hinge(part.bound))}"]
            else:
                lines.append(f"  not proved: {part.not_proved}")
        return "\n".join(lines)


#: The start radius :func:`prove_certificate` asks of a designed function's level-set proof, as a
#: fraction of the numerical certificate's (the proof's cost grows as the fifth power of it:
#: measured 2026-12-06 for the Table I forward C.G. in hover, ... at 0.5).
DESIGNED_PROOF_FRACTION = 0.5


def certify(params: BladeParameters, mu: float = 0.0, *, condition: str = "propulsive", function: str = "auto",
            A: float | None = None, scales=None, n_psi: int = 36, Q=None, verify: bool = False,
            proof_fraction: float = DESIGNED_PROOF_FRACTION,
            refine: bool | None = None, design: str = "default", harmonics: int | None = None,
            **engine_options) -> Certificate:
    """Certify technical stability of the blade's trimmed steady motion at ``mu``.

    Parameters
    ----------
    params : BladeParameters
        The blade and helicopter (for ``"propulsive"`` the controls, tilt and inflow are trimmed;
        for ``"flapping"`` and ``"none"`` a ``None`` collective is trimmed in hover).
    mu : float
        Advance ratio, >= 0.
    condition : str
        One of :data:`rotorlyap.model.forward_trim.TRIM_TARGETS`: the trimmed helicopter
        (default), the hover collective with cyclic for zero flapping, or the paper's hover
        controls.
    function : str
        One of :data:`FUNCTIONS` (module docstring): ``"auto"`` (default) tries the quadratic
        function and the augmented energy and keeps the larger start region.
    A : float, optional
        Requested bound of the scaled norm of the quadratic function (default
        :data:`rotorlyap.conventions.DEFAULT_A`); the sound rule reduces it until it holds. A
        designed function asks for the bound it was designed for.
    scales : array_like, optional
        Norm scales ``a_i``, rad and rad/rad (default :data:`rotorlyap.conventions.DEFAULT_SCALES`).
    n_psi : int
        Azimuths of the grid.
    Q : array_like, optional
        Weight of the quadratic function (default: the identity in scaled coordinates).
    verify : bool
        Also prove the certificate returned, its own function (:func:`prove_certificate`: the
        quadratic function up to its numerical bound by
        :func:`rotorlyap.analysis.proof.prove_blade`, Taylor models and a branch and bound over the
        band, seconds in hover and tens of seconds in forward flight; a designed hover function by
        :func:`rotorlyap.analysis.designed_proof.prove_designed_level`, its level set through the
        ball of ``proof_fraction`` times the numerical start radius shown invariant, up to minutes
        at the default); the result's ``proved_part`` says what is proved, or why nothing is (a
        designed function in forward flight: no prover encloses it). In forward flight the
        periodic motion is first refined by shooting (module docstring). The candidates are those
        of ``verify=False``.
    proof_fraction : float
        With ``verify``, the start radius asked of a designed function's proof, as a fraction of
        the numerical one (default :data:`DESIGNED_PROOF_FRACTION`; the proof's work grows about
        as the fifth power of it).
    refine : bool, optional
        In forward flight, refine the trim's periodic motion by shooting
        (:func:`rotorlyap.model.steady.refine_motion`, a residual near round-off) and certify about
        it, instead of the tabulated Fourier motion (whose residual is that of its truncation: for
        the trimmed Table I helicopter 4e-4 of the largest rate at mu = 0.1, 6e-3 at mu = 0.25).
        Default: with ``verify`` only. A certificate to be
        saved as a file (:meth:`Certificate.save`) is best made about the refined motion, whose
        table :func:`rotorlyap.verify` finds to solve the equations.
    design : str
        The design program's effort for a designed function, a key of
        :data:`rotorlyap.analysis.nonlinear_functions.DESIGN_EFFORTS`: ``"default"``, or
        ``"thorough"`` (more counterexample rounds and bisection steps: larger start regions where
        the default's rounds run out, in minutes instead of tens of seconds in forward flight).
    harmonics : int, optional
        In forward flight, the harmonics of the azimuth in a designed function's quadratic
        coefficients (:func:`rotorlyap.analysis.nonlinear_functions.designed_function`; default 1;
        in hover they are constant and only None or 0 is taken). More harmonics shape the
        function per azimuth; whether that reaches further depends on the case (the book's
        files, ``tools/make_certificates.py``, measured it).
    **engine_options
        Passed on to :func:`rotorlyap.technical_stability` (``n_sphere``, ...).

    Returns
    -------
    Certificate

    Raises
    ------
    ValueError
        Unknown ``condition``, ``function`` or ``design``, bad ``mu`` (from the trim).
    rotorlyap.errors.TrimError
        If the trim does not converge.
    """
    if condition not in TRIM_TARGETS:
        raise ValueError(f"condition must be one of {TRIM_TARGETS}, got {condition!r}")
    if function not in FUNCTIONS:
        raise ValueError(f"function must be one of {FUNCTIONS}, got {function!r}")
    if design not in DESIGN_EFFORTS:
        raise ValueError(f"design must be one of {tuple(DESIGN_EFFORTS)}, got {design!r}")
    bad_harmonics = (f"harmonics must be None or an integer >= 0, and 0 or None in hover (mu = 0), "
                     f"got {harmonics!r} at mu = {mu!r}")
    if harmonics is not None and (isinstance(harmonics, bool) or not isinstance(harmonics, (int, np.integer))
                                  or harmonics < 0):
        raise ValueError(bad_harmonics)
    report(f"trim ({condition}, mu = {float(mu):g})")
    trim = forward_flight_trim(params, float(mu), condition)
    mu = trim.mu
    if harmonics and mu == 0.0:  # before any design: in hover the coefficients are constant
        raise ValueError(bad_harmonics)
    refine = bool(verify) if refine is None else bool(refine)
    report("steady motion" + (" (refined by shooting)" if mu and refine else ""))
    if mu == 0.0:
        steady = trim.steady
    elif refine:
        steady = refine_motion(Blade(trim.params, mu), trim.motion)
    else:
        steady = tabulate_motion(trim.motion)
    report("Floquet exponents")
    growth = float(blade_floquet(trim.params, mu, steady=trim.steady).exponents.real.max())
    a = np.asarray(DEFAULT_SCALES if scales is None else scales, dtype=float)
    A_quadratic = DEFAULT_A if A is None else float(A)
    if function == "auto":
        families = ("quadratic",) if growth >= 0.0 else ("quadratic", "energy")
    else:
        families = (function,)

    def one(family):
        """(TechnicalStabilityResult or None, the function or None, message)"""
        functions = []  # the function the engine works with, kept for the proof and the caller

        def keep(blade, st):
            if family == "quadratic":
                functions.append(quadratic_function(blade, st, Q, scales=a))
            else:
                functions.append(designed_function(blade, st, family, scales=a, effort=design,
                                                   harmonics=harmonics))
                if not functions[-1].designed:
                    raise _NotDesigned(functions[-1])
            return functions[-1]

        try:
            res = blade_stability(trim.params, mu, lyapunov=keep, steady=steady,
                                  A=A_quadratic if family == "quadratic" else None, scales=a, n_psi=n_psi,
                                  **engine_options)
        except NotAsymptoticallyStableError as exc:
            return None, None, (f"the linearised blade is unstable (spectral radius {exc.spectral_radius:.4g}, "
                                f"growth rate {growth:+.3f} per rev): no quadratic function exists, so no "
                                "certificate with a small bound is possible")
        except _NotDesigned as exc:
            return None, exc.function, (f"the {exc.function.label} design found no function that decreases "
                                        f"on a shell about the steady motion ({exc.function.design!r})")
        return res, functions[-1], res.message

    tried = []
    for k, family in enumerate(families):
        report(f"candidate {k + 1} of {len(families)}: the {family} function")
        res, fun, message = one(family)
        ok = res is not None and bool(np.all(res.stable))
        lam = float(np.min(res.lambda0)) if ok else 0.0
        lam = lam if math.isfinite(lam) else 0.0
        attempts = tuple(fun.design.tried) if family in FAMILIES and fun is not None else ()
        if ok:
            report(f"the {family} function's start set")
        reach = _start_set(fun, res, family) if ok else None
        tried.append((family, res, fun, reach,
                      Candidate(family, ok, float(res.A) if ok else 0.0, lam, message, attempts,
                                tuple(float(v) for v in reach.axis_reach) if reach is not None else ())))
    best = max(tried, key=lambda item: (item[4].certified, item[4].start_region))
    family, res, fun, reach, cand = best
    proof, part = None, None
    if verify:
        report(f"proof of the {family} function (Taylor models, branch and bound)")
        proof, part = prove_certificate(fun, family, cand.bound, cand.start_region, cand.certified,
                                        A_requested=A_quadratic, designed_fraction=proof_fraction)
    return Certificate(certified=cand.certified, mu=mu, condition=condition, trim=trim, growth_rate=growth,
                       bound=cand.bound, start_region=cand.start_region, scales=a, result=res,
                       message=cand.message, proof=proof, function=family,
                       candidates=tuple(item[4] for item in tried), lyapunov=fun, start_set=reach,
                       proved_part=part)


#: The provers :func:`prove_certificate` names.
_METHODS = {"quadratic": "Taylor models and branch and bound on the level set (prove_blade)",
            "designed": "Taylor models and branch and bound on a level set (prove_designed_level)"}

def prove_certificate(fun, family: str, bound: float, start_region: float, certified: bool, *,
                      A_requested: float = DEFAULT_A,
                      designed_fraction: float = DESIGNED_PROOF_FRACTION) -> tuple[Proof | None, ProvedPart]:
    """Prove a certificate's own function: what ``certify(verify=True)`` does.

    The quadratic function by :func:`rotorlyap.analysis.proof.prove_blade`, up to its numerical
    bound; a designed function (``"energy"``, ``"polynomial"``) of the energy and quadratic
    monomials in hover by :func:`rotorlyap.analysis.designed_proof.prove_designed_level`: its level
    set through the ball of ``designed_fraction`` times the numerical start radius shown
    invariant (``W' < 0`` on it), which proves that start radius and a bound around that level
    set. A designed function with weights on cubic or quartic monomials, or with coefficients
    that depend on the azimuth (forward flight), is not taken by a prover, and the result says so.

    Parameters
    ----------
    fun : QuadraticFunction or DesignedFunction or None
        The certificate's function (None where none was built).
    family : str
        ``"quadratic"``, ``"energy"`` or ``"polynomial"``.
    bound, start_region : float
        The numerical certificate's bound and smallest start radius (scaled norm).
    certified : bool
        Whether the numerical certificate holds. Where it does not, the quadratic function is
        proved up to ``A_requested`` (a proof may exist where the search failed); a designed
        function is not tried.
    A_requested : float
        The bound asked of the quadratic function (used where nothing is certified).
    designed_fraction : float
        The start radius asked of a designed function's proof, as a fraction (in (0, 1]) of the
        numerical one.

    Returns
    -------
    proof : Proof or DesignedLevelProof or None
        The prover's result, None where no prover takes the function.
    part : ProvedPart
        What is proved, as fractions of the numerical certificate, or why nothing is.

    Raises
    ------
    ValueError
        An unknown family, a fraction outside (0, 1].
    """
    from .designed_proof import designed_parts, prove_designed_level

    if family not in ("quadratic",) + FAMILIES:
        raise ValueError(f"family must be one of {('quadratic',) + FAMILIES}, got {family!r}")
    if not (0.0 < float(designed_fraction) <= 1.0):
        raise ValueError(f"designed_fraction must lie in (0, 1], got {designed_fraction!r}")

    def unproved(why: str, method: str = "") -> tuple[None, ProvedPart]:
        nan = float("nan") if not certified else 0.0
        return None, ProvedPart(family, False, method, 0.0, 0.0, nan, nan, why)

    if fun is None:
        return unproved("no function was built (the linearised blade is unstable, or the design found none)")
    if family == "quadratic":
        method = _METHODS["quadratic"]
        proof = prove_blade(fun, bound if certified else A_requested)
    else:
        if not certified:
            return unproved(f"the {family} function certified nothing numerically: there is no bound to prove")
        if not fun.autonomous:
            return unproved(f"the designed {family} function's coefficients depend on the azimuth (forward "
                            "flight); the level-set prover takes autonomous (hover) functions only")
        try:
            designed_parts(fun)
        except ValueError as exc:
            return unproved(f"the designed {family} function has terms the prover's models do not hold ({exc})")
        method = _METHODS["designed"]
        proof = prove_designed_level(fun, float(designed_fraction) * start_region, numerical_start=start_region)
    ok = bool(proof.proved) and proof.A > 0
    if certified:
        fa = proof.A / bound if ok and bound > 0 else 0.0
        fl = proof.min_lambda0 / start_region if ok and start_region > 0 else 0.0
    else:
        fa = fl = float("nan")
    return proof, ProvedPart(family, ok, method, float(proof.A) if ok else 0.0,
                             float(proof.min_lambda0) if ok else 0.0, float(fa), float(fl),
                             "" if ok else proof.message)


def _start_set(fun, res: TechnicalStabilityResult, family: str) -> StartSet | None:
    """The start set a sound-rule certificate covers (:func:`function_start_set`); None for the
    paper's rule."""
    if res.rule != "sound":
        return None
    return function_start_set(fun, family, res.level, res.A, res.scales, res.period)


def function_start_set(fun, family: str, level: float, A: float, scales, period: float = 2 * math.pi) -> StartSet:
    """The start set ``{||x|| < A, W < level}`` of one of :func:`certify`'s functions, measured along
    the signed hinge axes at every start azimuth (one where ``W`` does not depend on it; the
    crossing in closed form for the quadratic function): :func:`rotorlyap.methods.start_set.start_set`.

    Parameters
    ----------
    fun : QuadraticFunction or DesignedFunction
        The function (``W``).
    family : str
        ``"quadratic"``, ``"energy"`` or ``"polynomial"``.
    level, A : float
        The certificate's level and bound (scaled norm).
    scales : array_like
        The norm's ``a_i``, rad and rad/rad.
    period : float
        rad.
    """
    quadratic = family == "quadratic"
    autonomous = fun.constant if quadratic else fun.autonomous
    return start_set(fun.W, level, A, scales, period=period, autonomous=autonomous, quadratic=quadratic)


class _NotDesigned(Exception):
    """A designed family found no function (carried to :func:`certify`)."""

    def __init__(self, function):
        super().__init__(function.label)
        self.function = function
