"""Proved certificates for the blade: the quadratic function's certificate checked in ball arithmetic.

:func:`prove_blade` takes a :class:`~rotorlyap.analysis.functions.QuadraticFunction` (the
quadratic Liapunov function of the linearised blade about its steady motion, the one
:func:`rotorlyap.certify` uses) and proves its certificate: every motion that starts within the
start radius stays within the bound. By default (``method="taylor"``, issue 41) with Taylor models
of the averaged Jacobian over shells of cubes (:meth:`BladeProofSystem.jacobian_models`, from
:func:`rotorlyap.analysis.taylor_enclosure.taylor_evaluate`): ``W'`` is a polynomial in the
disturbance plus a remainder, and :func:`rotorlyap.methods.proof.prove_quadratic_models` shows it
negative on the level set ``W = c`` by branch and bound over directions and radii
(:mod:`rotorlyap.methods.band`), which makes ``{W <= c}`` invariant (``level_set=True``); with
``level_set=False`` on the whole band ``|y| <= A, W >= c`` of the theorem's condition (h), which
asks more than the invariance needs (sampled at mu = 0.1, ``W'`` on the band turns positive at 1.5
times the numerical bound, on the level set it stays below ``-0.5 |y|^2`` out to 3 times). In
forward flight the models are taken on coarse azimuth intervals (:data:`DEFAULT_MODEL_INTERVALS`)
and the linear part on the fine ones. With
``method="balls"``, the earlier prover, :func:`rotorlyap.methods.proof.prove_quadratic` on ball
enclosures of the blade's equations (:class:`rotorlyap.analysis.enclosure.BladeEnclosure`):

* the residual ``g0`` of the steady motion on ``n_intervals`` azimuth intervals
  (:meth:`rotorlyap.analysis.enclosure.BladeEnclosure.residual`, a mean-value form in the azimuth);
* over the tube ``|x_i| <= A a_i`` about it, the averaged Jacobian
  ``K = int_0^1 J(psi, t x) dt`` from the mean-value theorem with the slopes of the
  piecewise-linear pieces (airfoil table, ``|cl|``, the Mach cap) frozen at their hulls over
  the tube: ``K = J(xi; slopes of the tube) + 1/2 H(tube) [-A a, A a]``, with ``H`` the
  Hessians (second-order Jets) over the tube on ``n_coarse`` coarser intervals and the first
  term (first-order Jets at the steady motion, the slopes replayed) on the fine ones. For
  fixed slopes ``sigma`` the equations are smooth in the state, so
  ``J(t x; sigma) - J(0; sigma)`` lies in ``H t x``, whose average over ``t`` is ``H x / 2``;
  the true slopes at ``t x`` lie in the hulls, so ``J(0; sigma)`` lies in the first term.

:func:`prove_designed` runs the same proof for a designed function of
:mod:`rotorlyap.analysis.nonlinear_functions` that is a quadratic form in hover
(:func:`designed_quadratic_form`). :func:`enclosure_width` measures what limits both: the balls of
the Jacobian over a box about the equilibrium against the Jacobian of the float model sampled in
it (chapter 10: for the Table I blade the balls are some hundreds of times wider than the
variation, in the inertial terms of the pitch equation, at every size of box).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..conventions import DEFAULT_SCALES, STATE_NAMES
from ..methods import intervals as iv
from ..methods.proof import Proof, lyapunov_enclosure, prove_quadratic, prove_quadratic_models
from ..model.blade import Blade
from ..model.steady import TabulatedMotion, as_steady_motion
from .enclosure import BladeEnclosure
from .functions import QuadraticFunction
from .taylor_enclosure import taylor_evaluate

_STATE_INDEX = {name: i for i, name in enumerate(STATE_NAMES)}

DEFAULT_MODEL_INTERVALS = 32
"""Azimuth intervals of the Taylor models of :func:`prove_blade` in forward flight (``method="taylor"``)."""

FLIGHT_FIRST_CUBE = 0.7
"""The first bound :func:`prove_blade` tries in forward flight on the band (``level_set=False``), as a
fraction of the bound asked (``method="taylor"``; the outer cube of its shells, ``first_cube``); on
the level set (the default) the first bound is the one asked: the whole numerical bound at mu = 0.1
is proved in 11 to 14 s (917 974 boxes; measured 2026-12-06 on an AMD EPYC,
``benchmarks/bench_proof.py --flight``), and in hover 1.00 of it for every Table I case in about
0.6 s, where the band proof reaches 0.90 to 0.95. Measured on the trimmed
helicopter at mu = 0.1 (2026-12-06, shells in the ratio :data:`FLIGHT_SHELLS`, 32 model intervals):
0.7 of the numerical bound proved in 34 to 38 s. With shells in the ratio 0.85, 0.75 is not proved:
the second cube's search does not close (0.705 of the bound reached in 1.5 million boxes, 74 s;
also with models of order 4); with 64 model intervals 0.75 is proved in 131 s, and 0.8 with 64 or
128 is not.
One cube of the models (``shells=False``, the prover before) proved 0.60 from its first cube,
:data:`FLIGHT_ONE_CUBE`. What stops 0.8 (measured 2026-12-06, :func:`remainder_sources`): over the
cube of 0.8 of the bound the models' largest remainder is 0.089 (scaled) at psi = 309 deg, against
0.005 on the advancing side; it comes from the two innermost strips (r/R = 0.15 and 0.18), whose
angle of attack there sweeps -26 to -16 deg and -16 to -9 deg, past and across the airfoil's
negative stall at -15 deg, whose 3 deg blend a polynomial of order 3 cannot follow; without their
air loads it would be 0.005. Fitting the table's slopes over each angle range with a cubic instead
of a line (``_tm_table``) cut those strips' slope deviation three times but the remainder only to
0.073, and the bound proved stayed 0.72 of the numerical one. What a proof to 0.8 would take
(measured 2026-12-06 with the models' remainders scaled by hand, a feasibility measurement and
not a proof): with every remainder zero, 0.8 is proved with 4 million boxes per shell (26 s) but
not with the default 1.2 million (0.76); with the remainders above 0.01 (the retreating side's)
at a tenth, 0.8 with 4 million boxes (38 s); at a quarter, not (0.76). So models whose retreating
remainder is near the advancing side's, ten times below today's, and a search three times as
long; with today's models a longer search alone proves no more (4 million boxes per shell: 0.72,
0.76 not). Models over the two halves of the cube along the flap rate, the disturbance that moves
those strips' angle of attack most, lower it only to 0.062 and 0.034 (the azimuth within a
model interval alone sweeps the innermost strip's angle by 3 deg)."""

FLIGHT_ONE_CUBE = 0.75
"""The first cube of :func:`prove_blade` in forward flight over one cube of models
(``shells=False``), as a fraction of the bound asked: over the cube of the whole numerical bound
the models' remainder on the retreating side makes the search at mu = 0.1 end far inside
(measured 2026-12-05: 0.60 of the bound from 0.75, 0.601 from 1 in three times the time)."""

FLIGHT_SHELLS = 0.8
"""The ratio of the cubes of :func:`prove_blade`'s proof over shells in forward flight
(``shells``; :func:`rotorlyap.methods.proof.prove_quadratic_models`). Finer shells do not reach
0.8 of the bound at mu = 0.1 (measured 2026-12-06 on an AMD EPYC, where the default takes 14 s
for 0.70): ratio 0.9 or 0.85 from the first bound 0.8, with 32 or 64 model intervals, fail at
0.8 and prove 0.72, in 81 to 86 s."""

__all__ = ["BladeProofSystem", "EnclosureWidth", "RemainderSources", "designed_quadratic_form", "enclosure_width",
           "proof_problem", "prove_blade", "prove_designed", "quadratic_terms", "remainder_sources"]


def _spread(balls: np.ndarray, blocked: dict, rep: int):
    """Each interval's balls and blocked flags repeated ``rep`` times (coarse to fine intervals)."""
    return np.repeat(balls, rep, axis=0), {k: np.repeat(v, rep) for k, v in blocked.items()}


class BladeProofSystem:
    """The blade's disturbed equations as a :class:`rotorlyap.methods.proof.ProofSystem`.

    Parameters
    ----------
    blade : Blade
        The blade.
    steady : SteadyMotion or TabulatedMotion
        The steady motion (a constant state or a tabulated periodic motion).
    n_coarse : int, optional
        Azimuth intervals of the tube's enclosures (default: as many as asked); the fine
        intervals must be a multiple.
    arithmetic : {"auto", "balls", "arb"}, optional
        The ball arithmetic (:class:`~rotorlyap.analysis.enclosure.BladeEnclosure`; default
        ``"auto"``: Arb in hover, float balls in forward flight).
    """

    n = 6

    def __init__(self, blade, steady, n_coarse: int | None = None, arithmetic: str | None = None):
        self.enclosure = BladeEnclosure(blade, steady, arithmetic=arithmetic)
        self.n_coarse = n_coarse
        self._blade, self._steady = blade, steady
        self._float_enclosure = None

    def jacobian_models(self, N: int, radius, order: int):
        """Taylor models of the averaged Jacobian over the cube ``|x_i| <= radius_i`` (state units).

        :func:`rotorlyap.analysis.taylor_enclosure.taylor_evaluate` of order ``order`` (float
        balls), the Jacobian's models averaged along the rays from the steady motion
        (:meth:`~rotorlyap.methods.taylor.TaylorModel.ray_average`). In forward flight the azimuth
        offset within each of the ``N`` intervals is a model variable; its monomials are moved into
        the radii of the coefficients of the state's monomials (``|tau^j| <= 1``).

        Returns
        -------
        coef : Balls, shape (N, M, 6, 6)
            Coefficients per monomial of ``exponents`` in ``t = x / radius``.
        rem : numpy.ndarray, shape (N, 6, 6)
            Remainders.
        exponents : numpy.ndarray of int, shape (M, 6)
        blocked : dict
            ``{reason: boolean (N,)}`` where the models are not finite.
        """
        from ..methods.balls import Balls

        enc = self.float_enclosure()
        r = np.asarray(radius, dtype=float)
        if enc.constant:
            ev = taylor_evaluate(enc, np.zeros(6), r, order)
            K = ev.jacobian.ray_average()
            exps = K.space.exponents
            coef = Balls(np.moveaxis(K.coef, -1, 0)[None])                     # (1, M, 6, 6)
            rem = K.rem[None]
            coef = Balls(np.broadcast_to(coef.mid, (N,) + coef.shape[1:]), 0.0)
            rem = np.broadcast_to(rem, (N, 6, 6))
        else:
            ev = taylor_evaluate(enc, np.zeros(6), r, order, n_intervals=N)
            K = ev.jacobian.ray_average(over=range(6))                         # batch (N, 6, 6)
            E = K.space.exponents
            base = E[:, 6] == 0
            exps = E[base, :6]
            index = {tuple(e): i for i, e in enumerate(exps)}
            target = np.array([index[tuple(e[:6])] for e in E])
            c = np.moveaxis(K.coef, -1, 1)                                       # (N, M7, 6, 6)
            mid = c[:, base]
            rad = np.zeros_like(mid)
            for j in np.flatnonzero(~base):
                rad[:, target[j]] += np.abs(c[:, j])
            # the sums of |c| rounded: relative u each, covered by the factor
            coef = Balls(mid, rad * (1.0 + 1e-12))
            rem = K.rem
        bad = ~(np.all(np.isfinite(coef.mid) & np.isfinite(coef.rad), axis=(1, 2, 3))
                & np.all(np.isfinite(rem), axis=(1, 2)))
        reason = "the Taylor models are not finite (relative wind may vanish, or reverse flow)"
        blocked = {reason: bad} if bad.any() else {}
        return coef, rem, exps, blocked

    def float_enclosure(self) -> BladeEnclosure:
        """The blade's enclosure in float balls (the Taylor models' arithmetic), made once."""
        if self._float_enclosure is None:
            self._float_enclosure = (self.enclosure if self.enclosure.arithmetic == "balls"
                                     else BladeEnclosure(self._blade, self._steady, arithmetic="balls"))
        return self._float_enclosure

    def _coarse(self, N: int) -> int:
        if self.enclosure.constant:
            return 1
        Nc = N if self.n_coarse is None else min(int(self.n_coarse), N)
        if N % Nc:
            raise ValueError(f"n_intervals ({N}) must be a multiple of n_coarse ({Nc})")
        return Nc

    def residual(self, N: int):
        Nc = 1 if self.enclosure.constant else N
        g0, blocked = self.enclosure.residual(Nc)
        return _spread(g0, blocked, N // Nc)

    def linear(self, N: int):
        Nc = 1 if self.enclosure.constant else N
        ev = self.enclosure.evaluate(Nc)
        return np.repeat(ev.jacobian, N // Nc, axis=0)

    def averaged_jacobian(self, N: int, radius):
        r = np.asarray(radius, dtype=float)
        Nc = self._coarse(N)
        Nf = 1 if self.enclosure.constant else N
        tube = self.enclosure.evaluate(Nc, radius=r, order=2)
        slopes = [np.repeat(sl, Nf // Nc) for sl in tube.slopes]
        at_centre = self.enclosure.evaluate(Nf, slopes=slopes)
        with iv.arithmetic(self.enclosure.arithmetic):
            box = iv.balls(np.zeros(6), r)  # [-r_k, r_k]
        half = np.sum(tube.hessian * box[None, None, None, :], axis=-1) * 0.5
        K = at_centre.jacobian + np.repeat(half, Nf // Nc, axis=0)
        blocked = {}
        for key in set(tube.blocked) | set(at_centre.blocked):
            blocked[key] = (np.repeat(tube.blocked.get(key, np.zeros(Nc, bool)), Nf // Nc)
                            | at_centre.blocked.get(key, np.zeros(Nf, bool)))
        return _spread(K, blocked, N // Nf)


def proof_problem(fun: QuadraticFunction, *, n_intervals: int | None = None, n_coarse: int | None = None,
                  arithmetic: str | None = None):
    """The system, the enclosed ``S`` and the azimuth intervals :func:`prove_blade` works with.

    Parameters
    ----------
    fun : QuadraticFunction
        The function (its blade, steady motion, scales and solution ``P``).
    n_intervals, n_coarse : int, optional
        As :func:`prove_blade`.
    arithmetic : {"auto", "balls", "arb"}, optional
        As :func:`prove_blade`.

    Returns
    -------
    system : BladeProofSystem
    quadratic : callable
        ``quadratic(N) -> (S, dS)`` (:func:`rotorlyap.methods.proof.lyapunov_enclosure`).
    n_intervals : int
    """
    steady = fun.steady
    motion = None
    if not steady.is_constant:
        xi = getattr(steady.xi_function, "__self__", None)
        if isinstance(xi, TabulatedMotion):
            motion = xi
        if motion is None:
            raise ValueError("a proof needs a constant steady state or a TabulatedMotion "
                             "(rotorlyap.model.steady.tabulate_motion or refine_motion)")
    system = BladeProofSystem(fun.blade, motion if motion is not None else steady, n_coarse, arithmetic)
    if n_intervals is None:
        if system.enclosure.constant and fun.constant:
            n_intervals = 1
        else:
            grids = [fun.solution.n_grid if not fun.constant else 1]
            if motion is not None:
                grids.append(motion.values.shape[0])
            n_intervals = int(np.lcm.reduce(grids))
    if n_coarse is None and not system.enclosure.constant:
        system.n_coarse = max(1, n_intervals // 8)
    return system, lyapunov_enclosure(fun.solution), int(n_intervals)


def prove_blade(fun: QuadraticFunction, A: float, *, n_intervals: int | None = None,
                n_coarse: int | None = None, n_bisect: int = 8, arithmetic: str | None = None,
                method: str = "taylor", order: int = 3, n_models: int | None = None,
                max_boxes: int | None = None, patience: int | None = None,
                first_cube: float | None = None, shells: float | bool | None = None,
                level_set: bool = True) -> Proof:
    """Prove the quadratic function's certificate for the blade, up to the bound ``A``.

    Two provers (issue 41). ``method="taylor"`` (the default): the averaged Jacobian in Taylor
    models of order ``order`` over the cubes of shells about the steady motion
    (:meth:`BladeProofSystem.jacobian_models`), so that ``W'`` is a polynomial in the disturbance
    that keeps the cancellations of the pitch equation, plus a remainder; ``W' < 0`` shown on the
    level set ``W = c`` (``level_set``, the default) or on the band by branch and bound over
    directions and radii (:func:`rotorlyap.methods.proof.prove_quadratic_models`,
    :func:`rotorlyap.methods.band.largest_bound`). On the level set the whole numerical bound is
    proved for the Table I hovers and the trimmed helicopter at mu = 0.1; on the band 0.90 to 0.95
    of it in hover and 0.70 at mu = 0.1. ``method="balls"``: the mean-value form in ball
    arithmetic over the tube (:func:`rotorlyap.methods.proof.prove_quadratic`; 0.17 to 0.32 of
    the numerical bound in hover: the balls widen the cancelling terms).

    Parameters
    ----------
    fun : QuadraticFunction
        The function (its blade, steady motion, scales and solution ``P``).
    A : float
        The largest bound to prove (scaled norm; usually the numerical certificate's).
    n_intervals : int, optional
        Azimuth intervals of the residual and of the first term of ``K``; default 1 where nothing
        depends on the azimuth (hover about the equilibrium), else the finest grid of the steady
        motion and of ``P`` (the intervals must split both grids).
    n_coarse : int, optional
        Azimuth intervals of the Hessians over the tube (default ``n_intervals / 8``).
    n_bisect : int
        Bisection steps on the bound.
    arithmetic : {"auto", "balls", "arb"}, optional
        The ball arithmetic of every enclosure: float balls (:mod:`rotorlyap.methods.balls`), Arb
        balls (the reference) or ``"auto"`` (the default,
        :data:`rotorlyap.analysis.enclosure.DEFAULT_ARITHMETIC`: Arb where the equations do not
        depend on the azimuth, a hover proof on one interval, float balls elsewhere, 25 times
        faster for the forward-flight proof). Both are rigorous. ``method="taylor"``: float balls
        (the Taylor models' arithmetic); Arb is refused.
    method : {"taylor", "balls"}
        The prover (above).
    order : int
        Order of the Taylor models (``"taylor"``).
    n_models : int, optional
        Azimuth intervals of the Taylor models and of the branch and bound (``"taylor"``; a divisor
        of ``n_intervals``): default 1 in hover, else ``DEFAULT_MODEL_INTERVALS``.
    max_boxes : int, optional
        Boxes of each branch and bound (``"taylor"``; default 200 000 in hover, 1 200 000 elsewhere).
    patience : int, optional
        Boxes spent on one bound before the next smaller one (``"taylor"``; default a quarter of
        ``max_boxes`` in hover, a sixth elsewhere).
    first_cube : float, optional
        The first cube of the models as a fraction of ``A`` (``"taylor"``; default 1 in hover,
        elsewhere :data:`FLIGHT_ONE_CUBE` over one cube: over the whole cube of the numerical bound
        the models' remainder on the retreating side, where the innermost strips' angle of attack
        crosses the airfoil's stall (:func:`remainder_sources`), makes the search at mu = 0.1 end
        far inside); with shells, the first bound
        tried (default :data:`FLIGHT_FIRST_CUBE`).
    shells : float or bool, optional
        The proof over shells of cubes in the ratio ``shells``
        (:func:`rotorlyap.methods.proof.prove_quadratic_models`; ``"taylor"``): each point of the
        band shown with models over a cube little larger than its own, not over the cube of the
        whole bound. Default (None): :data:`FLIGHT_SHELLS` on the level set and in forward flight,
        one cube for the band in hover (where one cube reaches 0.90 to 0.95 of the numerical
        bound); True: :data:`FLIGHT_SHELLS`; False: one cube (the band only).
    level_set : bool
        ``W' < 0`` shown on the level set ``W = c`` alone (default; ``"taylor"``): ``{W <= c}`` is
        invariant, so every motion that starts within the start radius stays within the bound,
        the certificate's claim (:func:`rotorlyap.methods.proof.prove_quadratic_models`). False:
        on the whole band of the theorem's condition (h). A bound whose shells do not all close
        falls back to the band's search over one cube (the message says which was proved).

    Returns
    -------
    Proof

    Raises
    ------
    ValueError
        A periodic steady motion that is not tabulated, an airfoil without a table, a Mach-dependent
        C81 section (``compressibility = "table"``: no Mach axis in the enclosures), an unknown
        method, ``method="taylor"`` with ``arithmetic="arb"``.
    """
    if method == "balls":
        system, quadratic, N = proof_problem(fun, n_intervals=n_intervals, n_coarse=n_coarse, arithmetic=arithmetic)
        with iv.arithmetic(system.enclosure.arithmetic):
            return prove_quadratic(system, quadratic, A, scales=fun.scales, n_intervals=N, n_bisect=n_bisect)
    if method != "taylor":
        raise ValueError(f"method must be 'taylor' or 'balls', got {method!r}")
    if arithmetic not in (None, "auto", "balls"):
        raise ValueError(f"method='taylor' works in float balls, got arithmetic={arithmetic!r}")
    system, quadratic, N = proof_problem(fun, n_intervals=n_intervals, n_coarse=n_coarse, arithmetic="balls")
    if n_models is None:
        n_models = 1 if system.enclosure.constant and N == 1 else min(DEFAULT_MODEL_INTERVALS, N)
    if max_boxes is None:
        max_boxes = 200_000 if n_models == 1 else 1_200_000
    if level_set:
        if shells is False:
            raise ValueError("level_set needs the proof over shells (shells=None, True or a ratio)")
        shells = FLIGHT_SHELLS if shells is None or shells is True else shells
        first_cube = 1.0 if first_cube is None else first_cube
    if shells is None or shells is True:
        shells = FLIGHT_SHELLS if shells is True or n_models > 1 else False
    if first_cube is None:
        first_cube = 1.0 if n_models == 1 else FLIGHT_FIRST_CUBE if shells is not False else FLIGHT_ONE_CUBE
    with iv.arithmetic("balls"):
        return prove_quadratic_models(system, quadratic, A, scales=fun.scales, n_intervals=N, order=order,
                                      n_models=n_models, max_boxes=max_boxes,
                                      patience=(max(max_boxes // (4 if n_models == 1 else 6), 1)
                                                if patience is None else int(patience)),
                                      first_cube=first_cube, shells=None if shells is False else float(shells),
                                      level_set=level_set)


def designed_quadratic_form(fun) -> np.ndarray:
    """The matrix ``S`` of a designed function that is a quadratic form of the scaled state.

    A :class:`~rotorlyap.analysis.nonlinear_functions.DesignedFunction` is a combination of basis
    functions; where every term but the constant quadratic monomials has the weight exactly 0 (the
    augmented energy of the Table I neutral C.G. in hover, the file the book ships: the program
    gives the energy no weight), ``W = y^T S y`` with ``y = x / a`` exactly, ``S_ii`` the weight of ``y_i^2`` and
    ``S_ij = S_ji`` half the weight of ``y_i y_j``.

    Returns
    -------
    numpy.ndarray, shape (6, 6)
        ``S`` (dimensionless; ``W = 1`` on the designed level).

    Raises
    ------
    ValueError
        A function with a nonzero weight on any other term (the energy, a harmonic of the azimuth,
        a cubic or quartic monomial): the proof encloses quadratic forms only.
    """
    S, others = quadratic_terms(fun)
    if others:
        listed = [f"{name} ({c:.3g})" for name, c in others.items()]
        raise ValueError("the proof encloses quadratic forms of the scaled state; this function has nonzero "
                         "weights on " + ", ".join(listed[:4]) + (" ..." if len(listed) > 4 else ""))
    return S


def quadratic_terms(fun) -> tuple[np.ndarray, dict]:
    """A designed function's quadratic monomials of the scaled state as the symmetric ``S`` of
    ``y^T S y`` (``S_ii`` the weight of ``y_i^2``, ``S_ij = S_ji`` half that of ``y_i y_j``,
    exact), and the nonzero weights of its other terms (name -> weight: the energy, a harmonic of
    the azimuth, a cubic or quartic monomial)."""
    bf = fun.function
    S = np.zeros((6, 6))
    others = {}
    for name, c in zip(bf.basis.names, bf.coefficients):
        c = float(c)
        factors = []
        for p in name.split("*"):
            var, _, power = p.partition("^")
            factors += [var] * (int(power) if power else 1)
        idx = [_STATE_INDEX.get(v) for v in factors]
        if len(idx) == 2 and None not in idx:
            i, j = sorted(idx)
            if i == j:
                S[i, i] = c
            else:
                S[i, j] = S[j, i] = 0.5 * c
        elif c != 0.0:
            others[name] = c
    return S, others


def prove_designed(fun, A: float | None = None, *, n_bisect: int = 8, arithmetic: str | None = None,
                   method: str = "taylor", order: int = 3, max_boxes: int = 200_000,
                   level_set: bool = True) -> Proof:
    """Prove the certificate of a designed function that is a quadratic form (hover).

    The same proof as :func:`prove_blade` (``method="taylor"``, the default: Taylor models of the
    averaged Jacobian and branch and bound on the level set; ``"balls"``: the tube ``|y_i| <= A``
    about the equilibrium, one ball matrix ``K`` for all of it), with ``S`` from
    :func:`designed_quadratic_form`.

    Parameters
    ----------
    fun : rotorlyap.analysis.nonlinear_functions.DesignedFunction
        An autonomous (hover) designed function whose only nonzero weights are on quadratic
        monomials.
    A : float, optional
        The largest bound to prove, scaled norm (default: the design's).
    n_bisect : int
        Bisection steps on the bound.
    arithmetic : {"auto", "balls", "arb"}, optional
        As :func:`prove_blade`.
    method, order, max_boxes, level_set :
        As :func:`prove_blade`.

    Returns
    -------
    Proof

    Raises
    ------
    ValueError
        A function that is not a quadratic form, or not autonomous.
    """
    if not fun.autonomous:
        raise ValueError("prove_designed proves autonomous (hover) functions; in forward flight the designed "
                         "coefficients depend on the azimuth")
    S = designed_quadratic_form(fun)
    if method not in ("taylor", "balls"):
        raise ValueError(f"method must be 'taylor' or 'balls', got {method!r}")
    if method == "taylor" and arithmetic not in (None, "auto", "balls"):
        raise ValueError(f"method='taylor' works in float balls, got arithmetic={arithmetic!r}")
    system = BladeProofSystem(fun.blade, fun.steady, arithmetic="balls" if method == "taylor" else arithmetic)

    def quadratic(N: int):
        balls = iv.balls(np.broadcast_to(S, (N, 6, 6)))
        return balls, iv.zeros(balls.shape)

    bound = float(fun.design.A if A is None else A)
    with iv.arithmetic(system.enclosure.arithmetic):
        if method == "taylor":
            return prove_quadratic_models(system, quadratic, bound, scales=fun.scales, n_intervals=1, order=order,
                                          max_boxes=max_boxes, patience=max(max_boxes // 4, 1),
                                          shells=FLIGHT_SHELLS if level_set else None, level_set=level_set)
        return prove_quadratic(system, quadratic, bound, scales=fun.scales, n_intervals=1, n_bisect=n_bisect)


@dataclass(frozen=True)
class EnclosureWidth:
    """How wide the ball enclosure of the Jacobian is, against how much the Jacobian varies.

    Over the box ``|x_i| <= bound a_i`` about a constant steady motion (hover), in the scaled
    coordinates ``y = x / a`` (entries ``J_ij a_j / a_i``, per rad of azimuth).

    Attributes
    ----------
    bound : float
        Half-width of the box, scaled norm.
    radius : numpy.ndarray, shape (6, 6)
        Radius of the enclosure's ball of each entry (:meth:`BladeEnclosure.evaluate`).
    variation : numpy.ndarray, shape (6, 6)
        Largest ``|J(x) - J(0)|`` over the sampled states of the box (the float model's
        Jacobian): a lower bound of the true variation.
    contained : bool
        Every sampled Jacobian lies in the enclosure (to the finite differences' error).
    entry : tuple of int
        ``(i, j)`` of the widest enclosure.
    """

    bound: float
    radius: np.ndarray
    variation: np.ndarray
    contained: bool
    entry: tuple

    def __repr__(self) -> str:  # short and stable: no arrays
        return (f"EnclosureWidth(bound={self.bound:g}, radius <= {self.radius.max():.3g}, "
                f"variation >= {self.variation.max():.3g}, contained={self.contained})")

    @property
    def ratio(self) -> float:
        """The widest enclosure radius over the largest sampled variation (>= the overestimate)."""
        return float(self.radius.max() / self.variation.max())


def enclosure_width(blade, steady=None, bound: float = 0.1, *, scales=None, samples: int = 256, seed: int = 0,
                    aerodynamics: bool = True, arithmetic: str | None = None, order: int = 2) -> EnclosureWidth:
    """Measure the ball enclosure of the blade's Jacobian against the Jacobian itself.

    Parameters
    ----------
    blade : Blade
        The blade in hover.
    steady : optional
        A constant steady motion (default: the hover equilibrium).
    bound : float
        Half-width of the box, scaled norm (> 0).
    scales : array_like, optional
        The norm's ``a_i`` (default :data:`rotorlyap.conventions.DEFAULT_SCALES`).
    samples : int
        Random states of the box (the 64 corners are added).
    seed : int
        Seed of the sample.
    aerodynamics : bool
        False encloses the blade without its air loads (the inertial, spring and damper terms).
    arithmetic : {"auto", "balls", "arb", "taylor"}, optional
        The enclosure: ball arithmetic (:class:`BladeEnclosure`, default ``"auto"``) or Taylor
        models of order ``order`` (:func:`rotorlyap.analysis.taylor_enclosure.taylor_evaluate`,
        issue 41: they keep the cancellations of the pitch equation that the balls lose).
    order : int
        Order of the Taylor models (``arithmetic="taylor"`` only).

    Returns
    -------
    EnclosureWidth
    """
    if not (np.isfinite(bound) and bound > 0):
        raise ValueError(f"bound must be a finite number > 0, got {bound!r}")
    a = np.asarray(DEFAULT_SCALES if scales is None else scales, dtype=float)
    steady = as_steady_motion(steady, blade)
    if not steady.is_constant:
        raise ValueError("enclosure_width measures a constant steady motion (hover)")
    model = blade if aerodynamics else _without_air(blade)
    if arithmetic == "taylor":
        enc = BladeEnclosure(model, steady, arithmetic="balls")
        lo, hi = taylor_evaluate(enc, np.zeros(6), bound * a, order).jacobian.bounds()
    else:
        ev = BladeEnclosure(model, steady, arithmetic=arithmetic).evaluate(1, radius=bound * a)
        lo, hi = iv.lower(ev.jacobian[0]), iv.upper(ev.jacobian[0])
    scale = a[None, :] / a[:, None]
    radius = 0.5 * (hi - lo) * scale
    rng = np.random.default_rng(seed)
    corners = np.array(np.meshgrid(*[[-1.0, 1.0]] * 6, indexing="ij")).reshape(6, -1).T
    y = np.vstack([corners, rng.uniform(-1.0, 1.0, (int(samples), 6))]) * bound
    z = steady.state + y * a
    J = model.jacobian(np.zeros(z.shape[0]), z)
    J0 = model.jacobian(np.zeros(1), steady.state[None])[0]
    variation = np.max(np.abs(J - J0), axis=0) * scale
    slack = 1e-6 * (np.abs(J) + 1.0)
    contained = bool(np.all((J >= lo - slack) & (J <= hi + slack)))
    entry = tuple(int(k) for k in np.unravel_index(np.argmax(radius), radius.shape))
    return EnclosureWidth(float(bound), radius, variation, contained, entry)


def _without_air(blade):
    """The blade with its air loads switched off (density zero)."""
    return Blade(replace(blade.params, air_density=0.0), blade.mu)


SOURCE_SHARE = 0.1
"""A strip is a source of :func:`remainder_sources`' largest remainder where leaving its air loads
out lowers that remainder by at least this fraction."""


@dataclass(frozen=True)
class RemainderSources:
    """Where the remainder of the averaged Jacobian's Taylor models comes from (:func:`remainder_sources`).

    Attributes
    ----------
    bound : float
        Half-width of the cube of the models, scaled norm.
    psi : numpy.ndarray, shape (N,)
        Midpoints of the models' azimuth intervals, rad (one, 0, in hover).
    remainder : numpy.ndarray, shape (N,)
        Per interval, the largest remainder of the models (scaled coordinates, per rad of azimuth).
    worst : int
        The interval of the largest remainder.
    station : numpy.ndarray, shape (n_strips,)
        The strips' radii over the rotor radius, -.
    angles : numpy.ndarray, shape (n_strips, 2)
        Each strip's angle of attack over the cube, on the worst interval: lower and upper bound, rad.
    without : numpy.ndarray, shape (n_strips,)
        The worst interval's largest remainder with each strip's air loads left out.
    sources : tuple of int
        The strips whose loads left out lower it by at least :data:`SOURCE_SHARE`.
    without_sources : float
        The worst interval's largest remainder with the air loads of every source left out.
    """

    bound: float
    psi: np.ndarray
    remainder: np.ndarray
    worst: int
    station: np.ndarray
    angles: np.ndarray
    without: np.ndarray
    sources: tuple
    without_sources: float

    def __repr__(self) -> str:  # short and stable: no arrays
        return (f"RemainderSources(bound={self.bound:.3g}, largest {self.remainder[self.worst]:.2g} at psi = "
                f"{np.degrees(self.psi[self.worst]):.0f} deg, sources {self.sources})")

    def summary(self) -> str:
        """Two lines: the largest remainder and where, then its sources (2 significant digits, deg)."""
        k = self.worst
        adv = self.psi < np.pi
        head = (f"Taylor-model remainder over the cube {self.bound:.3g}: largest {self.remainder[k]:.2g} at psi = "
                f"{np.degrees(self.psi[k]):.0f} deg" + (f" (advancing side at most {self.remainder[adv].max():.2g})"
                                                         if adv.any() and not adv[k] else ""))
        parts = [f"r/R = {self.station[i]:.2f} (angle of attack {np.degrees(self.angles[i, 0]):.0f} to "
                 f"{np.degrees(self.angles[i, 1]):.0f} deg; without it {self.without[i]:.2g})" for i in self.sources]
        tail = ("    from the strips at " + ", ".join(parts) + f"; without all of them {self.without_sources:.2g}"
                if parts else "    no strip's air loads carry a share of it")
        return head + "\n" + tail


def remainder_sources(fun: QuadraticFunction, bound: float, *, n_models: int | None = None,
                      order: int | None = None) -> RemainderSources:
    """Which strips' air loads make the Taylor models' remainder large, over the cube ``|y_i| <= bound``.

    The averaged Jacobian's models of :meth:`BladeProofSystem.jacobian_models` (what
    :func:`prove_blade` takes) over the cube, their largest remainder per azimuth interval (scaled
    coordinates), and on the interval where it is largest the same with each strip's air loads
    left out in turn (:func:`rotorlyap.analysis.taylor_enclosure.taylor_evaluate`'s ``strips``),
    then with every strip that carries at least :data:`SOURCE_SHARE` of it left out together. A
    measurement of what limits the proof (chapter 9): a model without some strips is another
    blade's, and proves nothing about this one.

    Parameters
    ----------
    fun : QuadraticFunction
        The function of the proof (its blade, steady motion and scales).
    bound : float
        Half-width of the cube, scaled norm (> 0).
    n_models : int, optional
        Azimuth intervals of the models (default :func:`prove_blade`'s: 1 in hover, else
        :data:`DEFAULT_MODEL_INTERVALS`).
    order : int, optional
        Order of the models (default :func:`prove_blade`'s).

    Returns
    -------
    RemainderSources
    """
    import inspect

    bound = float(bound)
    if not (np.isfinite(bound) and bound > 0):
        raise ValueError(f"bound must be finite and > 0, got {bound!r}")
    if order is None:
        order = int(inspect.signature(prove_blade).parameters["order"].default)
    system, _, _ = proof_problem(fun)
    enc = system.float_enclosure()
    N = None if enc.constant else int(DEFAULT_MODEL_INTERVALS if n_models is None else n_models)
    a = np.asarray(fun.scales, dtype=float)
    n_strips = enc.st.shape[1]

    def evaluate(strips=None):
        ev = taylor_evaluate(enc, np.zeros(6), bound * a, order, n_intervals=N, strips=strips)
        K = ev.jacobian.ray_average() if N is None else ev.jacobian.ray_average(over=range(6))
        rem = np.asarray(K.rem, dtype=float).reshape(-1, 6, 6) * a[None, None, :] / a[None, :, None]
        angles = None if ev.angles is None else np.asarray(ev.angles).reshape(-1, n_strips, 2)
        return np.max(rem, axis=(1, 2)), angles

    remainder, angles = evaluate()
    k = int(np.argmax(remainder))
    without = np.empty(n_strips)
    for i in range(n_strips):
        mask = np.ones(n_strips, dtype=bool)
        mask[i] = False
        without[i] = evaluate(mask)[0][k]
    sources = tuple(int(i) for i in np.flatnonzero(without <= (1.0 - SOURCE_SHARE) * remainder[k]))
    mask = np.ones(n_strips, dtype=bool)
    mask[list(sources)] = False
    rest = float(evaluate(mask)[0][k]) if sources else float(remainder[k])
    psi = np.zeros(1) if N is None else 2 * np.pi * (np.arange(N) + 0.5) / N
    station = np.asarray(fun.blade.r, dtype=float) / float(fun.blade.params.radius)
    ang = np.full((n_strips, 2), np.nan) if angles is None else angles[k]
    return RemainderSources(bound=bound, psi=psi, remainder=remainder, worst=k, station=station, angles=ang,
                            without=without, sources=sources, without_sources=rest)
