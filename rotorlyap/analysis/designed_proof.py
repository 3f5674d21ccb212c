"""Proofs of the designed hover functions on one of their level sets (issue 41).

A designed function of :mod:`rotorlyap.analysis.nonlinear_functions` (the augmented energy
``W = c_0 H_s / H_ref + y^T S y``, ``y = x / a``) is made for large disturbances: its ``W'`` is
negative far out, but its quadratic part near the steady motion may be thin (the forward C.G.'s
quadratic form leaves the linear part at -0.0016), so a proof over the band from the steady
motion outwards (:func:`rotorlyap.analysis.proof.prove_designed`) stops near it. The theorem does
not need that band: :mod:`rotorlyap.methods.level_set` shows that the set ``{W <= c}`` is invariant
from ``W' < 0`` on the level set ``W = c`` alone, and so that every motion starting within the
largest ball inside it stays within the smallest ball around it.

:func:`designed_models` gives that prover Taylor models of ``W`` and ``W'`` over boxes of the
scaled state: the blade's right-hand side from
:func:`rotorlyap.analysis.taylor_enclosure.taylor_evaluate` (without the Jacobian), the energy
``H_s = 1/2 Omega^2 x_r^T M(q) x_r + U(q) - U(q_s) - grad U(q_s) . x_q`` and its gradient
(``grad_xq = 1/2 Omega^2 x_r^T dM/dq x_r + grad U(q) - grad U(q_s)``, ``grad_xr = Omega^2 M(q) x_r``)
from the generated ``rhs_dw_terms`` and ``potential_terms`` run on the same models, so
``W' = grad W . f`` keeps the inertial terms' cancellation in its coefficients.
:func:`prove_designed_level` picks the level from the start radius asked and runs the proof.
"""

from __future__ import annotations

import types
from dataclasses import dataclass

import numpy as np

from ..methods import intervals as iv
from ..methods import taylor as tm
from ..methods.balls import Balls
from ..methods.level_set import LevelProof, ball_maximum, prove_level
from ..methods.sampling import unit_sphere_points
from ..methods.taylor import TaylorMath
from ..model._generated import blade_scalar as _scalar
from ..model.compiled import _OMEGA
from .enclosure import BladeEnclosure
from .proof import quadratic_terms
from .taylor_enclosure import _rhs_dw_terms, taylor_evaluate

__all__ = ["DEFAULT_ORDER", "DesignedLevelProof", "designed_models", "designed_parts", "prove_designed_level"]

DEFAULT_ORDER = 3
"""Order of the Taylor models of :func:`designed_models`."""

_potential_terms = types.FunctionType(_scalar.potential_terms_into.__code__,
                                      {**_scalar.potential_terms_into.__globals__, "math": TaylorMath},
                                      "potential_terms_taylor")


def designed_parts(fun) -> tuple[float, float, np.ndarray]:
    """The energy's weight ``c_0``, its divisor ``H_ref`` (J) and the quadratic form ``S`` of a
    designed function whose every term is the energy or a quadratic monomial of the scaled state.

    Raises
    ------
    ValueError
        A term of another kind with a nonzero weight (a harmonic of the azimuth, a cubic or
        quartic monomial), or a function that is not autonomous.
    """
    if not getattr(fun, "autonomous", False):
        raise ValueError("the level-set proof takes autonomous (hover) designed functions; in forward flight "
                         "the coefficients depend on the azimuth")
    S, others = quadratic_terms(fun)
    c0 = float(others.pop("energy", 0.0))
    if others:
        listed = [f"{name} ({c:.3g})" for name, c in others.items()]
        raise ValueError("the level-set proof takes the energy and quadratic monomials; this function has "
                         "nonzero weights on " + ", ".join(listed[:4]) + (" ..." if len(listed) > 4 else ""))
    bf = fun.function
    H_ref = bf.basis.energy_reference if c0 else 1.0
    if H_ref is None or not (np.isfinite(H_ref) and H_ref > 0):
        raise ValueError("the function's energy term has no divisor H_ref recorded on its basis "
                         "(energy_basis records it)")
    return c0, float(H_ref), S


def designed_models(fun, order: int = DEFAULT_ORDER):
    """Taylor models of a designed hover function ``W`` and of ``W'`` over boxes of the scaled state.

    Parameters
    ----------
    fun : rotorlyap.analysis.nonlinear_functions.DesignedFunction
        An autonomous function of the energy and quadratic monomials (:func:`designed_parts`).
    order : int
        Order of the models.

    Returns
    -------
    callable
        ``models(centre, half_width, rates)`` for :func:`rotorlyap.methods.level_set.prove_level`:
        boxes ``|y - centre| <= half_width`` of the scaled state (arrays ``(m, 6)``), the models of
        ``W`` (dimensionless) and, with ``rates``, of ``W'`` (per rad of azimuth), shape ``(m,)``.
        Each box is widened by the rounding of ``x = a y`` and of the steady state added to it.
    """
    c0, H_ref, S = designed_parts(fun)
    a = np.asarray(fun.scales, dtype=float)
    enc = BladeEnclosure(fun.blade, fun.steady, arithmetic="balls")
    xi = np.asarray(enc.state, dtype=float)
    om2 = float(enc.sc[_OMEGA]) ** 2
    with iv.arithmetic("balls"):
        theta_c = iv.const(enc.controls[0])
        ps = [None] * 14
        _potential_terms(Balls(float(xi[0])), Balls(float(xi[1])), Balls(float(xi[2])), theta_c, enc.params, ps)
        inv_a = [Balls(1.0) / float(v) for v in a]
        weight = Balls(c0) / H_ref if c0 else None
    eps = np.finfo(float).eps

    def models(centre, half_width, rates: bool):
        C = np.asarray(centre, dtype=float)
        H = np.asarray(half_width, dtype=float)
        xc = C * a
        xr = H * a * (1.0 + 8.0 * eps) + 8.0 * eps * (np.abs(xc) + np.abs(xi))   # covers a y and xi + x
        with iv.arithmetic("balls"):
            T = None
            if rates:
                ev = taylor_evaluate(enc, xc, xr, order, jacobian=False, energy_terms=bool(c0))
                z, T = ev.state, ev.terms
                f = [ev.value[..., i] for i in range(6)]
            else:
                z = tm.variables(xi + xc, xr, order)
            x = [z[i] - float(xi[i]) for i in range(6)]
            y = [x[i] * inv_a[i] for i in range(6)]
            Sy = []
            for i in range(6):
                s = y[0] * float(S[i, 0])
                for j in range(1, 6):
                    s = s + y[j] * float(S[i, j])
                Sy.append(s)
            W = y[0] * Sy[0]
            for i in range(1, 6):
                W = W + y[i] * Sy[i]
            dW = None
            if rates:
                fy = [f[i] * inv_a[i] for i in range(6)]
                q = fy[0] * Sy[0]
                for i in range(1, 6):
                    q = q + fy[i] * Sy[i]
                dW = q * 2.0
            if c0:
                if T is None:
                    T = [None] * 49
                    _rhs_dw_terms(z[0], z[1], z[2], z[3], z[4], z[5], theta_c, x[3], x[4], x[5], enc.params, T)
                P = [None] * 14
                _potential_terms(z[0], z[1], z[2], theta_c, enc.params, P)
                m00, m01, m02, m11, m12, m22 = T[0:6]
                Mx = [m00 * x[3] + m01 * x[4] + m02 * x[5], m01 * x[3] + m11 * x[4] + m12 * x[5],
                      m02 * x[3] + m12 * x[4] + m22 * x[5]]
                kin = (Mx[0] * x[3] + Mx[1] * x[4] + Mx[2] * x[5]) * (0.5 * om2)
                H_s = kin + P[0] - ps[0] - (x[0] * ps[1] + x[1] * ps[2] + x[2] * ps[3])
                W = W + H_s * weight
                if rates:
                    gq = [T[42 + i] + T[45 + i] - ps[1 + i] for i in range(3)]
                    dH = gq[0] * f[0] + gq[1] * f[1] + gq[2] * f[2] \
                        + (Mx[0] * f[3] + Mx[1] * f[4] + Mx[2] * f[5]) * om2
                    dW = dW + dH * weight
        return W, dW

    return models


@dataclass(frozen=True)
class DesignedLevelProof:
    """A designed hover function's level set shown invariant (:func:`prove_designed_level`).

    Attributes
    ----------
    proof : rotorlyap.methods.level_set.LevelProof
        The branch and bound's result (its start radius and bound, scaled norm).
    asked : float
        The start radius the level was chosen for, scaled norm.
    numerical_start : float
        The certificate's start radius (its numerical certificate), scaled norm.
    numerical_bound : float
        The certificate's bound, scaled norm.
    order : int
    """

    proof: LevelProof
    asked: float
    numerical_start: float
    numerical_bound: float
    order: int

    @property
    def proved(self) -> bool:
        """The level set is shown invariant."""
        return self.proof.proved

    @property
    def A(self) -> float:
        """The proved bound, scaled norm (0 where not proved): the names of
        :class:`rotorlyap.methods.proof.Proof`."""
        return float(self.proof.bound) if self.proof.proved else 0.0

    @property
    def min_lambda0(self) -> float:
        """The proved start radius, scaled norm (0 where not proved)."""
        return float(self.proof.start_radius) if self.proof.proved else 0.0

    @property
    def level(self) -> float:
        """The level ``c`` of ``W`` whose set is invariant."""
        return float(self.proof.level)

    @property
    def n_intervals(self) -> int:
        """Azimuth intervals (1: the function and the blade do not depend on the azimuth)."""
        return 1

    @property
    def message(self) -> str:
        """What is proved, or why not."""
        if not self.proof.proved:
            return f"not proved: {self.proof.reason}"
        return (f"the set W <= {self.level:.4g} is invariant (W' < 0 on its level set, {self.proof.rate_boxes} "
                f"boxes): start radius {self.min_lambda0:.3g}, bound {self.A:.3g} (scaled norm)")

    @property
    def start_fraction(self) -> float:
        """Proved start radius over the numerical one (0 where not proved)."""
        return self.proof.start_radius / self.numerical_start if self.proof.proved else 0.0

    def __repr__(self) -> str:
        return (f"DesignedLevelProof({self.proof!r}; start radius {self.start_fraction:.3g} of the numerical "
                f"{self.numerical_start:.4g})")


def _level_for(fun, models, radius: float, n: int = 4096, seed: int = 0) -> tuple[float, float]:
    """The level: a shade above the rigorous bound of ``W`` on the ball of ``radius``
    (:func:`rotorlyap.methods.level_set.ball_maximum`, so the proof's start radius is at least
    ``radius``); and a cube around that level set (its largest reach over sampled directions,
    widened: the proof checks that ``W`` exceeds the level on the cube's boundary)."""
    a = np.asarray(fun.scales, dtype=float)
    c = ball_maximum(models, 6, radius) * (1.0 + 1e-6)
    u = unit_sphere_points(6, n, seed=seed)
    reach = float(np.max(np.sqrt(c / fun.W(0.0, u * a))))
    return c, 2.2 * reach


def prove_designed_level(fun, start_radius: float | None = None, *, numerical_start: float | None = None,
                         fraction: float = 0.5, order: int = DEFAULT_ORDER, max_boxes: int = 400_000,
                         rate_width: float | None = None) -> DesignedLevelProof:
    """Prove a start radius of a designed hover function by its level set (module docstring).

    Parameters
    ----------
    fun : rotorlyap.analysis.nonlinear_functions.DesignedFunction
        An autonomous function of the energy and quadratic monomials.
    start_radius : float, optional
        The start radius to prove, scaled norm (default: ``fraction`` of the numerical one). The
        level is taken just above a rigorous bound of ``W`` on that ball, so the proof, where it
        holds, shows at least this radius.
    numerical_start : float, optional
        The numerical certificate's start radius, scaled norm (default: the one the function was
        designed for, ``fun.design.lam``; a certificate file's claimed ``lambda0`` where known).
    fraction : float
        The default start radius as a fraction of the numerical one.
    order : int
        Order of the Taylor models.
    max_boxes : int
        Boxes at most.
    rate_width : float, optional
        Boxes wider than this (scaled norm) are split without the models of ``W'`` (default: none
        is; a box whose models do not close it is taken again over its open halves. Measured
        2026-12-06 on the Table I forward C.G.'s certificate file at half its start radius, before
        the faster product of Taylor models: 64 s, against 77 s with the models taken from an
        eighth of the cube's half-width down and 116 s from a sixteenth; 43 s now).

    Returns
    -------
    DesignedLevelProof

    Raises
    ------
    ValueError
        A start radius that is not finite and positive; a function the models do not hold
        (:func:`designed_parts`).
    """
    design = fun.design
    lam = float(design.lam if numerical_start is None else numerical_start)
    asked = float(fraction * lam if start_radius is None else start_radius)
    if not (np.isfinite(asked) and asked > 0):
        raise ValueError(f"start_radius must be finite and > 0 (scaled norm), got {asked!r}")
    models = designed_models(fun, order)
    level, cube = _level_for(fun, models, asked)
    if not np.isfinite(level):
        raise ValueError(f"W has no finite bound on the ball of radius {asked!r} (scaled norm)")
    width = np.inf if rate_width is None else float(rate_width)
    proof = prove_level(models, level, cube, 6, max_boxes=max_boxes, rate_width=width)
    return DesignedLevelProof(proof, asked, lam, float(design.A), int(order))
