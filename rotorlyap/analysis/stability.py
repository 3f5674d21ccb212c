"""The blade plugged into the engine: technical stability of its steady motion.

:func:`blade_stability` builds the blade at an advance ratio, the disturbed equations about a
steady motion (by default the hover equilibrium of the same parameters, reused at every
advance ratio, as the paper does), a Liapunov function (by default the paper's energy
function) and runs :func:`rotorlyap.technical_stability` on them, in one of two readings:

``strict``
    the theorem as stated: suprema and infima over whole spheres of the scaled norm;
``practical``
    ``W`` and ``W'`` examined only along a finite set of test disturbances (by default the
    twelve signed coordinate axes: one hinge angle or one hinge rate disturbed at a time).
    This is how the paper's figures can show a stable hover with the energy function; it
    is an indicator, never a certificate.
"""

from __future__ import annotations

from typing import Callable

import numpy as np

from ..conventions import DEFAULT_A, DEFAULT_SCALES, MAX_ADVANCE_RATIO, STATE_NAMES
from ..methods.lyapunov import TechnicalStabilityResult, technical_stability
from ..model.blade import Blade
from ..model.parameters import BladeParameters
from ..model.steady import as_steady_motion, disturbed_rhs
from .functions import EnergyFunction, QuadraticFunction, energy_function

__all__ = ["blade_stability", "psi_free_system", "same_at_every_azimuth"]


def blade_stability(
    params: BladeParameters,
    mu: float = 0.0,
    *,
    lyapunov: Callable | None = None,
    A: float | None = None,
    scales=None,
    n_psi: int = 72,
    steady=None,
    test_disturbances=None,
    **engine_options,
) -> TechnicalStabilityResult:
    """Technical stability of the blade's steady motion at advance ratio ``mu``.

    Parameters
    ----------
    params : BladeParameters
        The blade; with ``collective=None`` it is trimmed in hover (thrust = weight) and that
        collective is kept at every advance ratio, as the paper keeps the hover controls.
    mu : float
        Advance ratio (>= 0).
    lyapunov : callable, optional
        ``lyapunov(blade, steady)`` (``steady`` a :class:`~rotorlyap.model.steady.SteadyMotion`)
        returning an object with vectorised ``W(psi, x)`` and ``dW(psi, x)`` (J and J/rad),
        for example :func:`~rotorlyap.analysis.functions.quadratic_function`. Default: the
        paper's energy function, :func:`~rotorlyap.analysis.functions.energy_function`.
    A : float, optional
        Requested bound of the scaled norm; default :data:`rotorlyap.conventions.DEFAULT_A`, or
        for a designed function (an object with ``design`` and ``engine_options()``, such as
        :class:`~rotorlyap.analysis.nonlinear_functions.DesignedFunction`) the bound it was
        designed for, with the engine options it was designed for.
    scales : array_like, optional
        Norm scales ``a_i`` (rad, rad/rad); default :data:`rotorlyap.conventions.DEFAULT_SCALES`.
    n_psi : int
        Azimuths of the grid (steps 5 and 6).
    steady : SteadyMotion, optional
        Steady motion ``xi``, or anything :func:`~rotorlyap.model.steady.as_steady_motion`
        takes: None for the hover equilibrium of ``params`` (the paper's choice, reused at
        every ``mu``), a constant state (6,), a periodic motion.
    test_disturbances : None or array_like
        None for the strict reading (whole spheres); an array of directions ``(k, 6)`` in
        scaled coordinates for the practical reading (e.g.
        :data:`rotorlyap.conventions.PAPER_TEST_DISTURBANCES`).
    **engine_options
        Passed on to :func:`rotorlyap.technical_stability` (``n_sphere``, ``n_radii``,
        ``rule``, ...). The strict reading's default rule is ``"sound"`` (the theorem's (h)
        over the whole period: a numerical certificate); ``rule="paper"`` gives the paper's
        per-azimuth step 6. ``psi_free`` is set here where nothing depends on the azimuth
        (:func:`psi_free_system`): the same result, computed at one azimuth for all.

    Returns
    -------
    TechnicalStabilityResult
        With ``reading`` "strict" or "practical".

    Raises
    ------
    ValueError
        Bad ``mu``, ``steady``, scales or bound (from the engine).
    rotorlyap.errors.TrimError
        A hover trim that does not converge (a ``RuntimeError``).
    """
    if not isinstance(params, BladeParameters):
        raise TypeError(f"params must be a BladeParameters, got {type(params).__name__}")
    mu = float(mu)
    if not (np.isfinite(mu) and 0.0 <= mu <= MAX_ADVANCE_RATIO):
        raise ValueError(f"mu must be an advance ratio in [0, {MAX_ADVANCE_RATIO:g}], got {mu!r}")
    if scales is not None and np.size(scales) != 6:
        raise ValueError(
            f"scales must hold 6 positive numbers, one per state component {STATE_NAMES}, "
            f"got {np.size(scales)}"
        )
    blade = Blade(params, mu)  # trims the collective in hover if params.collective is None
    motion = as_steady_motion(steady, Blade(blade.params, 0.0) if steady is None else None)
    if lyapunov is None:
        fun = energy_function(blade, motion)
    else:
        if not callable(lyapunov):
            raise TypeError("lyapunov must be callable as lyapunov(blade, steady)")
        fun = lyapunov(blade, motion)
    f = getattr(fun, "f", None) or disturbed_rhs(blade, motion)
    a = np.asarray(DEFAULT_SCALES if scales is None else scales, dtype=float)
    rule = engine_options.get("rule") or ("paper" if test_disturbances is not None else "sound")
    if rule == "sound" and isinstance(fun, QuadraticFunction):
        # W = x^T P x: its extrema on the engine's spheres in closed form
        engine_options.setdefault("w_matrix", lambda psi: a[:, None] * fun.P(psi) * a[None, :])
    if "psi_free" not in engine_options:
        engine_options["psi_free"] = psi_free_system(blade, motion, f, fun, a)
    designed = getattr(fun, "design", None)
    if designed is not None and test_disturbances is None:
        for key, value in fun.engine_options().items():
            engine_options.setdefault(key, value)
        if A is None:
            A = designed.A
    return technical_stability(
        f, fun.W, DEFAULT_A if A is None else A, scales=a,
        n_psi=n_psi, dW=fun.dW, test_directions=test_disturbances, **engine_options,
    )


def psi_free_system(blade: Blade, motion, f, fun, scales) -> bool:
    """Whether the disturbed blade ``f`` and the function ``fun`` (its ``W`` and ``W'``) are the
    same floats at every azimuth, so that the engine may compute one azimuth for all
    (``psi_free`` of :func:`rotorlyap.technical_stability`).

    True only for the blade in hover (``mu = 0``, no cyclic pitch) about a constant steady
    motion, with a constant quadratic function or the blade's energy (nothing else in the
    model depends on the azimuth there: the free stream and the cyclic pitch are its only
    sources), and only if 64 states at 8 azimuths confirm it bit for bit.

    Parameters
    ----------
    blade : Blade
    motion : SteadyMotion
    f : callable
        The disturbed right-hand side ``f(psi, x)``.
    fun : object
        The function, with ``W`` and ``dW``.
    scales : numpy.ndarray
        Norm scales ``a_i`` (the probe's states are of their size).

    Returns
    -------
    bool
    """
    if blade.mu != 0.0 or blade.has_cyclic or not motion.is_constant:
        return False
    if not ((isinstance(fun, QuadraticFunction) and fun.constant) or isinstance(fun, EnergyFunction)):
        return False
    return same_at_every_azimuth((f, fun.W, fun.dW), scales)


def same_at_every_azimuth(functions, scales, n_states: int = 64, n_azimuths: int = 8) -> bool:
    """Whether each of ``functions`` (``g(psi, x)``, vectorised) gives the same floats at
    ``n_states`` pseudo-random states (of the size of ``scales``) on ``n_azimuths`` azimuths of
    the period ``2 pi``: the probe of :func:`psi_free_system`."""
    x = np.random.default_rng(0).normal(size=(n_states, 6)) * (0.5 * np.asarray(scales, dtype=float))
    psi = np.repeat(2.0 * np.pi * np.arange(n_azimuths) / n_azimuths, n_states)
    states = np.tile(x, (n_azimuths, 1))
    for g in functions:
        v = np.asarray(g(psi, states), dtype=float).reshape(n_azimuths, n_states, -1)
        if not np.array_equal(v, np.broadcast_to(v[:1], v.shape)):
            return False
    return True
