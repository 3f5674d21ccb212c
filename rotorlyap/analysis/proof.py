"""Proved certificates for the blade: the quadratic function's certificate checked in ball arithmetic.

:func:`prove_blade` takes a :class:`~rotorlyap.analysis.functions.QuadraticFunction` (the
quadratic Liapunov function of the linearised blade about its steady motion, the one
:func:`rotorlyap.certify` uses) and proves condition (h) of the theorem for it with
:func:`rotorlyap.methods.proof.prove_quadratic`, on enclosures of the blade's equations
(:class:`rotorlyap.analysis.enclosure.BladeEnclosure`):

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
"""

from __future__ import annotations

import numpy as np

from ..methods import intervals as iv
from ..methods.proof import Proof, lyapunov_enclosure, prove_quadratic
from .enclosure import BladeEnclosure
from ..model.steady import TabulatedMotion
from .functions import QuadraticFunction

__all__ = ["BladeProofSystem", "proof_problem", "prove_blade"]


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
    """

    n = 6

    def __init__(self, blade, steady, n_coarse: int | None = None):
        self.enclosure = BladeEnclosure(blade, steady)
        self.n_coarse = n_coarse

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
        box = iv.balls(np.zeros(6), r)  # [-r_k, r_k]
        half = np.sum(tube.hessian * box[None, None, None, :], axis=-1) * 0.5
        K = at_centre.jacobian + np.repeat(half, Nf // Nc, axis=0)
        blocked = {}
        for key in set(tube.blocked) | set(at_centre.blocked):
            blocked[key] = (np.repeat(tube.blocked.get(key, np.zeros(Nc, bool)), Nf // Nc)
                            | at_centre.blocked.get(key, np.zeros(Nf, bool)))
        return _spread(K, blocked, N // Nf)


def proof_problem(fun: QuadraticFunction, *, n_intervals: int | None = None, n_coarse: int | None = None):
    """The system, the enclosed ``S`` and the azimuth intervals :func:`prove_blade` works with.

    Parameters
    ----------
    fun : QuadraticFunction
        The function (its blade, steady motion, scales and solution ``P``).
    n_intervals, n_coarse : int, optional
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
    system = BladeProofSystem(fun.blade, motion if motion is not None else steady, n_coarse)
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
                n_coarse: int | None = None, n_bisect: int = 8) -> Proof:
    """Prove the quadratic function's certificate for the blade, up to the bound ``A``.

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

    Returns
    -------
    Proof

    Raises
    ------
    ValueError
        A periodic steady motion that is not tabulated, an airfoil without a table.
    """
    system, quadratic, N = proof_problem(fun, n_intervals=n_intervals, n_coarse=n_coarse)
    return prove_quadratic(system, quadratic, A, scales=fun.scales, n_intervals=N, n_bisect=n_bisect)
