"""Liapunov functions of the blade for its nonlinear range: the augmented energy and polynomials.

A quadratic form of the linearised blade (:mod:`rotorlyap.analysis.functions`) certifies only
where the linearisation dominates: its ``W'`` turns positive a degree or so from the steady
motion, long before the blade itself is in trouble. What stops it is known: the blade's
accelerations hold inertial terms quadratic in the disturbance (Coriolis and centrifugal
couplings of the flap and lag rates, of order ``2 beta beta'`` in the lag equation), and a quadratic
form of the state meets them head on. The blade's own energy does not: Jacobi's integral of the
rotating blade, ``H = T2 + U`` (kinetic energy relative to the hub plus the effective potential
of springs, gravity and the centrifugal field), holds the geometric and inertial nonlinearity
exactly, and along the motions ``H' = q' . (Q_aero + Q_damp)``: only the work of the air loads and
dampers, every inertial term gone. It cannot certify alone (the paper's difficulty: the
aerodynamic coupling makes ``H'`` indefinite, :func:`~rotorlyap.analysis.functions.energy_function`),
but it can carry a function that does.

Two families, each a combination of basis functions whose coefficients are found by the scenario
program of :mod:`rotorlyap.methods.scenario` (conditions of the sound rule asked on sampled states,
counterexamples added round by round):

``"energy"`` (the augmented energy)
    ``W = c_0 H_s / H_ref + sum_{i<=j} c_ij(psi) y_i y_j``: the energy of the disturbed motion
    (:class:`~rotorlyap.analysis.functions.EnergyFunction`, ``H_s`` its value shifted to vanish
    with its gradient at the steady motion; ``H_ref`` its mean on the unit sphere, for scale)
    plus every quadratic form of the scaled state ``y = x / a``, with coefficients constant in
    hover and trigonometric polynomials of the azimuth in forward flight. The quadratic part
    supplies the cross and correction terms that cancel the aerodynamic coupling the energy
    lacks; its derivative ``2 y^T C f / a`` still meets the inertial terms. How much the program
    leans on the energy depends on the case and its norm: measured 2026-12-06 on the certificate
    files the book ships (chapter 10's :func:`rotorlyap.chapters.large_disturbances.anatomy`, the
    energy term's share of ``W`` on the start sphere), none for the Table I neutral C.G. in hover
    (a quadratic form designed on the shell certifies alone), 9 % for the backward C.G., 19 % for
    the trimmed helicopter at mu = 0.2, and 81 % and 83 % for the forward C.G. in hover and the
    trimmed helicopter at mu = 0.1. Either way the quadratic form shaped for the nonlinear blade on
    the shell where the theorem asks ``W' < 0`` is what carries the family past the quadratic
    function of the Lyapunov equation: where the energy has no weight it does so alone.
``"polynomial"``
    ``W = sum c_e(psi) y^e`` over the monomials of degree 2 to 4 of the scaled state: the cubic
    and quartic terms can cancel the quadratic part of the accelerations to their own order, as
    a truncated power series of Zubov's equation would, without knowing the physics. Its linear
    programs are large (203 coefficients in hover): measured 2026-12-06, the forward C.G.'s
    design in hover in chapter 10's norm, searched from the start radius 2, had not finished after
    19 minutes of one core (the augmented energy's: 10 s), so ``certify``'s default does not try it.

Both are certified the same way as every function of the report: by the engine's sound rule
(:func:`rotorlyap.technical_stability`) afterwards, on the shell between the largest ball inside
the level set and the bound (``band="shell"``), a numerical certificate; the falsifier attacks
them in the tests.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..conventions import DEFAULT_SCALES, STATE_NAMES, TWO_PI
from ..methods.sampling import unit_sphere_points
from ..methods.scenario import Basis, BasisFunction, Design, largest_design, monomial_basis
from ..model.blade import Blade
from ..model.steady import SteadyMotion, as_steady_motion, disturbed_rhs
from .functions import EnergyFunction, energy_function

__all__ = ["DESIGN_EFFORTS", "FAMILIES", "LAM_MAX", "LAM_START", "N_BISECT", "RATIOS", "DesignedFunction",
           "basis_harmonics", "designed_function", "energy_basis", "energy_reference", "is_autonomous",
           "mode_directions", "polynomial_basis"]

FAMILIES = ("energy", "polynomial")
"""The designed function families (module docstring)."""

#: Start radii of the design's search, scaled norm: from ``LAM_START`` up by factors of 2 (and
#: down, if it fails) to ``LAM_MAX``; the ratios ``A / lam`` tried at each, smallest first (a
#: badly damped mode needs a level set long in its direction, hence the large ratios). Measured
#: 2026-12-06 in chapter 10's hover norms: a ratio of 2 tried first met the start radius 3.74
#: instead of 3.72 at the forward C.G. and 2.66 instead of 2.20 at the neutral C.G., but the start
#: set's least reach along a hinge moved only from 18.4 % to 17.8 % and from 12.6 % to 13.7 % of the
#: simulated region (the flap rate limits both), so the ratios start at 2.5.
LAM_START, LAM_MAX, RATIOS = 0.1, 20.0, (2.5, 4.0, 8.0, 16.0, 32.0)

#: Bisection steps of the start radius between the last success and the first failure: two
#: halve the factor 2 of the growth twice (the start radius to within 19 %); a third step costs
#: a quarter of the trimmed helicopter's design time for 9 % more radius at most.
N_BISECT = 2

#: The design program's efforts, by name: the options :func:`designed_function` passes on to
#: :func:`rotorlyap.methods.scenario.largest_design` and :func:`~rotorlyap.methods.scenario.design`.
#: ``"default"`` is the package's own (the default :func:`rotorlyap.certify`: tens of seconds in
#: forward flight). ``"thorough"`` runs 16 counterexample rounds per design instead of 8 and 40 per
#: thorough design instead of 12, a bisection step more (3), and a bisection below a start
#: radius whose thorough design failed (``bisect_below``): minutes in forward flight, for the
#: certificate files the book ships (``tools/make_certificates.py``). The rounds are what the larger
#: start radii need: the program stops a design whose rounds have squeezed its margin, and with few
#: rounds a thorough design of a start radius the program can meet runs out of them. Measured
#: 2026-12-06 on the trimmed helicopter in chapter 10's norms (without refining the periodic
#: motion): at mu = 0.1 start radius 3.0 -> 3.6, the least reach of the start set along a hinge 14 %
#: -> 18 % of the simulated region; at mu = 0.2 2.1 -> 2.5, 9.6 % -> 13 %; 85 s -> 114 s and 83 s
#: -> 182 s from a warm interpreter.
DESIGN_EFFORTS: dict[str, dict] = {
    "default": {},
    "thorough": {"rounds": 16, "harden_rounds": 40, "n_bisect": 3, "bisect_below": True},
}


def is_autonomous(blade: Blade, steady: SteadyMotion) -> bool:
    """True if the disturbed blade does not depend on the azimuth: hover (``mu = 0``) about a
    constant steady motion without cyclic pitch (the rotating frame then sees a steady flow)."""
    return blade.mu == 0.0 and steady.is_constant and not blade.has_cyclic


def mode_directions(blade: Blade, steady: SteadyMotion, scales) -> np.ndarray:
    """Unit directions of the scaled state along the linearised blade's modes: the real and
    imaginary parts of the eigenvectors of the Jacobian about the steady motion (averaged over
    the period in forward flight), each normalised, shape ``(k, 6)``. Along a slowly decaying
    mode ``W'`` is small, so the design samples these directions densely."""
    a = _check_scales(scales)
    if steady.is_constant:
        psi = np.zeros(1) if is_autonomous(blade, steady) else TWO_PI * np.arange(16) / 16
        z = np.broadcast_to(steady.state, (psi.size, 6))
    else:
        psi = TWO_PI * np.arange(16) / 16
        z = np.asarray(steady.xi_function(psi), dtype=float)
    J = blade.jacobian(psi, z).mean(axis=0) * a[None, :] / a[:, None]  # scaled coordinates
    _, V = np.linalg.eig(J)
    parts = np.vstack([V.real.T, V.imag.T])
    norms = np.linalg.norm(parts, axis=1)
    parts = parts[norms > 1e-9 * norms.max()]
    return parts / np.linalg.norm(parts, axis=1, keepdims=True)


def _name_harmonic(name: str) -> int:
    """The harmonic of the azimuth in a basis name (``"flap*lag*sin(2psi)"`` -> 2; 0 without)."""
    for part in name.split("*"):
        if part.endswith("psi)"):
            return int(part[part.index("(") + 1:-4])
    return 0


def _check_scales(scales) -> np.ndarray:
    a = np.asarray(DEFAULT_SCALES if scales is None else scales, dtype=float).reshape(-1)
    if a.size != 6 or not np.all(np.isfinite(a)) or np.any(a <= 0):
        raise ValueError(f"scales must hold 6 finite numbers > 0 (rad, rad/rad), got {np.asarray(scales).tolist()}")
    return a


def basis_harmonics(blade: Blade, steady: SteadyMotion, harmonics: int | None) -> int:
    """The harmonics of the azimuth a basis of the blade takes: ``None`` gives 0 where the disturbed
    blade is autonomous (:func:`is_autonomous`) and 1 otherwise; an integer >= 0 is kept.

    Raises
    ------
    ValueError
        Not an integer >= 0, or harmonics where the blade is autonomous (the engine searches such
        a function at one azimuth).
    """
    autonomous = is_autonomous(blade, steady)
    if harmonics is None:
        return 0 if autonomous else 1
    if isinstance(harmonics, bool) or int(harmonics) != harmonics or harmonics < 0:
        raise ValueError(f"harmonics must be an integer >= 0, got {harmonics!r}")
    if autonomous and harmonics:
        # the engine searches such a function at one azimuth (its ``autonomous`` option): a W that
        # depends on the azimuth would be checked at psi = 0 only
        raise ValueError(f"harmonics must be 0 where the disturbed blade does not depend on the azimuth "
                         f"(hover without cyclic pitch, about a constant steady motion), got {harmonics!r}")
    return int(harmonics)


def energy_reference(blade: Blade, steady=None, *, scales=None) -> float:
    """``H_ref``, J: the mean of the energy of the disturbed motion on the unit sphere of the scaled
    norm (256 quasi-random directions at ``psi = 0``), by which :func:`energy_basis` divides it.

    Raises
    ------
    ValueError
        If it is not positive (the effective potential has no minimum at the steady motion).
    """
    a = _check_scales(scales)
    fun = energy_function(blade, as_steady_motion(steady, blade))
    u = unit_sphere_points(6, 256, 0)
    size = float(np.mean(fun.W(np.zeros(u.shape[0]), u * a)))
    if not (np.isfinite(size) and size > 0):
        raise ValueError("the energy of the disturbed motion is not positive on the unit sphere "
                         f"(mean {size:.3g} J): its effective potential is not a minimum at the steady motion")
    return size


def energy_basis(blade: Blade, steady=None, *, scales=None, harmonics: int | None = None,
                 reference: float | None = None) -> Basis:
    """The augmented energy's basis: the energy of the disturbed motion and the quadratic forms.

    Parameters
    ----------
    blade : Blade
        The blade at its advance ratio.
    steady : SteadyMotion, optional
        The steady motion (anything :func:`~rotorlyap.model.steady.as_steady_motion` takes; None:
        the hover equilibrium).
    scales : array_like, optional
        The ``a_i`` of the scaled state (rad, rad/rad); default
        :data:`rotorlyap.conventions.DEFAULT_SCALES`.
    harmonics : int, optional
        Harmonics of the azimuth in the quadratic coefficients; default 0 where the disturbed
        blade is autonomous (:func:`is_autonomous`), else 1.
    reference : float, optional
        ``H_ref``, J, the energy's divisor (default :func:`energy_reference`; a stored function
        is rebuilt with its own, :mod:`rotorlyap.analysis.certificate_file`).

    Returns
    -------
    rotorlyap.methods.scenario.Basis
        ``1 + 21 (2 harmonics + 1)`` functions: ``"energy"`` (dimensionless: the energy in J
        divided by its mean on the unit sphere of the scaled norm), then the quadratic monomials.
    """
    a = _check_scales(scales)
    steady = as_steady_motion(steady, blade)
    fun = energy_function(blade, steady)
    size = energy_reference(blade, steady, scales=a) if reference is None else float(reference)
    if not (np.isfinite(size) and size > 0):
        raise ValueError(f"the energy's reference H_ref must be finite and > 0 J, got {reference!r}")
    energy = Basis(("energy",), lambda psi, x: (fun.W(psi, x) / size)[:, None],
                   lambda psi, x: (fun.dW(psi, x) / size)[:, None])
    k = basis_harmonics(blade, steady, harmonics)
    forms = monomial_basis(fun.f, a, (2,), harmonics=k, names=STATE_NAMES)

    def rate_of(psi, x, c):  # the energy's W' and the f its quadratic forms need, from one kernel
        x = np.asarray(x, dtype=float)
        psi = np.broadcast_to(np.asarray(psi, dtype=float), (x.shape[0],))
        dw, fx = fun.dW_and_f(psi, x)
        return c[0] * (dw / size) + forms.rate_with_f(psi, x, c[1:], fx)

    return replace(energy + forms, rate_of=rate_of, energy_reference=size)


def polynomial_basis(blade: Blade, steady=None, *, scales=None, degrees=(2, 3, 4),
                     harmonics: int | None = None) -> Basis:
    """The polynomial family's basis: monomials of the scaled state of the given degrees.

    ``harmonics`` (default as :func:`energy_basis`) multiply the quadratic monomials only; the
    higher degrees have constant coefficients (their number grows fast: 56 cubic and 126 quartic
    monomials of six variables).
    """
    a = _check_scales(scales)
    steady = as_steady_motion(steady, blade)
    f = disturbed_rhs(blade, steady)
    k = basis_harmonics(blade, steady, harmonics)
    higher = tuple(d for d in degrees if d > 2)
    basis = monomial_basis(f, a, (2,), harmonics=k, names=STATE_NAMES)
    if higher:
        basis = basis + monomial_basis(f, a, higher, names=STATE_NAMES)
    return basis


@dataclass(frozen=True)
class DesignedFunction:
    """A designed Liapunov function of the blade: what the engine takes, and how it was made.

    Attributes
    ----------
    blade : Blade
    steady : SteadyMotion
    family : str
        One of :data:`FAMILIES`.
    design : rotorlyap.methods.scenario.Design
        The scenario program's result (start radius and bound asked for, margin, rounds, ...).
    scales : numpy.ndarray
        The ``a_i`` of the scaled state.
    autonomous : bool
        The disturbed blade does not depend on the azimuth (:func:`is_autonomous`).
    label : str
        Name for tables and legends.
    effort : str
        The design program's effort, a key of :data:`DESIGN_EFFORTS`.
    """

    blade: Blade
    steady: SteadyMotion
    family: str
    design: Design
    scales: np.ndarray
    autonomous: bool
    label: str
    effort: str = "default"

    @property
    def function(self) -> BasisFunction:
        """The designed ``W`` (raises if the design found none)."""
        if self.design.function is None:
            raise ValueError(f"the {self.family} design found no function: {self.design!r}")
        return self.design.function

    @property
    def harmonics(self) -> int:
        """The highest harmonic of the azimuth in the basis (0: constant coefficients), read from
        the basis names (``"beta*zeta*sin(2psi)"`` is of the second)."""
        return max([_name_harmonic(n) for n in self.function.basis.names] + [0])

    @property
    def designed(self) -> bool:
        """The program found a function that passed its own counterexample rounds."""
        return bool(self.design.feasible and self.design.function is not None)

    def f(self, psi, x) -> np.ndarray:
        """The disturbed right-hand side ``h(psi, xi + x) - xi'``."""
        return self.function.f(psi, x)

    def W(self, psi, x) -> np.ndarray:
        """``W(psi, x)`` (dimensionless; level 1 at the designed bound), shape ``(m,)``."""
        return self.function.W(psi, x)

    def dW(self, psi, x) -> np.ndarray:
        """``W'`` along the motions of the full nonlinear blade, per rad of azimuth, shape ``(m,)``."""
        return self.function.dW(psi, x)

    def engine_options(self) -> dict:
        """The sound rule's options this function is made for: the shell search, and the azimuth
        held fixed where nothing depends on it."""
        return {"band": "shell", "autonomous": self.autonomous}

    def __repr__(self) -> str:
        return f"DesignedFunction({self.label}, {self.design!r})"


def designed_function(blade: Blade, steady=None, family: str = "energy", *, scales=None,
                      harmonics: int | None = None, lam_start: float = LAM_START, lam_max: float = LAM_MAX,
                      ratios=RATIOS, label: str | None = None, effort: str = "default",
                      **design_options) -> DesignedFunction:
    """Design a Liapunov function of ``family`` for the blade about its steady motion.

    The scenario program (:func:`rotorlyap.methods.scenario.largest_design`) searches the largest
    start radius it can meet, with the bound ``A`` a ratio of it; the engine then certifies what
    it can (:meth:`DesignedFunction.engine_options`).

    Parameters
    ----------
    blade : Blade
    steady : SteadyMotion, optional
        Anything :func:`~rotorlyap.model.steady.as_steady_motion` takes (None: the hover equilibrium).
    family : {"energy", "polynomial"}
        The function family (module docstring).
    scales : array_like, optional
        The norm's ``a_i``; default :data:`rotorlyap.conventions.DEFAULT_SCALES`.
    harmonics : int, optional
        Harmonics of the azimuth in the quadratic coefficients (default: 0 where the disturbed blade
        is autonomous, :func:`is_autonomous`, 1 otherwise; it must be 0 where it is autonomous).
    lam_start, lam_max : float
        Range of start radii searched, scaled norm.
    ratios : sequence of float
        Ratios ``A / lam`` tried at each start radius.
    label : str, optional
        Name for tables (default: the family's).
    effort : str
        The design program's effort, a key of :data:`DESIGN_EFFORTS` (its options, which
        ``design_options`` override).
    **design_options
        Passed on to :func:`rotorlyap.methods.scenario.largest_design` (``n_bisect``, default
        :data:`N_BISECT`) and :func:`rotorlyap.methods.scenario.design` (``n_samples``,
        ``rounds``, ...).

    Returns
    -------
    DesignedFunction
        Check :attr:`DesignedFunction.designed`: False where the program found nothing.

    Raises
    ------
    ValueError
        An unknown family or effort, bad scales or harmonics.
    """
    if family not in FAMILIES:
        raise ValueError(f"family must be one of {FAMILIES}, got {family!r}")
    if effort not in DESIGN_EFFORTS:
        raise ValueError(f"effort must be one of {tuple(DESIGN_EFFORTS)}, got {effort!r}")
    design_options = {**DESIGN_EFFORTS[effort], **design_options}
    a = _check_scales(scales)
    steady = as_steady_motion(steady, blade)
    autonomous = is_autonomous(blade, steady)
    make = energy_basis if family == "energy" else polynomial_basis
    basis = make(blade, steady, scales=a, harmonics=harmonics)
    f = disturbed_rhs(blade, steady)
    name = label or ("augmented energy" if family == "energy" else "polynomial")
    design_options.setdefault("directions", mode_directions(blade, steady, a))
    design_options.setdefault("n_bisect", N_BISECT)
    d = largest_design(basis, f, a, lam_start=lam_start, lam_max=lam_max, ratios=ratios,
                       period=TWO_PI, periodic=not autonomous, label=name, **design_options)
    return DesignedFunction(blade=blade, steady=steady, family=family, design=d, scales=a,
                            autonomous=autonomous, label=name, effort=effort)
