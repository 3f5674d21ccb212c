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

from .blade import Blade
from .lyapunov import TechnicalStabilityResult, technical_stability
from .parameters import BladeParameters

__all__ = [
    "DEFAULT_A", "DEFAULT_SCALES", "PAPER_TEST_DISTURBANCES", "STATE_NAMES",
    "blade_stability", "disturbed_system", "energy_rate_terms",
]

#: Names of the state components, in order.
STATE_NAMES = ("beta", "zeta", "theta", "beta'", "zeta'", "theta'")

_DEG = np.pi / 180.0

#: Default norm scales ``a_i`` (rad and rad/rad): a unit of the norm is 2 deg of flap or lag,
#: 1 deg of pitch, and for each rate the angle scale times the mode's rotating frequency in
#: hover (flap ~1/rev, lag ~0.25/rev, pitch ~5/rev), so that displacement and rate of one
#: mode weigh alike. Assumed: the paper gives neither the a_i nor A.
DEFAULT_SCALES = np.array([2.0 * _DEG, 2.0 * _DEG, 1.0 * _DEG, 2.0 * _DEG, 0.5 * _DEG, 5.0 * _DEG])
DEFAULT_SCALES.setflags(write=False)

#: Default bound of the scaled norm: one unit of every scale (assumed).
DEFAULT_A = 1.0

#: The practical reading's default test disturbances: the 12 signed coordinate axes.
PAPER_TEST_DISTURBANCES = np.vstack([np.eye(6), -np.eye(6)])
PAPER_TEST_DISTURBANCES.setflags(write=False)


def _steady_motion(params: BladeParameters, steady):
    """``(xi, dxi)``: a constant 6-vector and None, or two callables of psi."""
    if steady is None:
        return Blade(params, 0.0).equilibrium(), None
    if isinstance(steady, tuple) and len(steady) == 2 and all(callable(s) for s in steady):
        return steady
    xi = np.asarray(steady, dtype=float)
    if xi.shape != (6,) or not np.all(np.isfinite(xi)):
        raise ValueError(
            "steady must be None (hover equilibrium), a finite state of shape (6,), or a pair "
            f"of callables (xi(psi), dxi(psi)); got {type(steady).__name__} "
            f"{getattr(xi, 'shape', '')}"
        )
    return xi, None


def disturbed_system(blade: Blade, xi, dxi=None) -> Callable:
    """Right-hand side of the disturbed motion, ``f(psi, x) = h(psi, xi + x) - xi'``.

    Parameters
    ----------
    blade : Blade
        The blade (its advance ratio and controls).
    xi : numpy.ndarray or callable
        Steady motion: a constant state (6,) or ``xi(psi) -> (..., 6)``.
    dxi : callable, optional
        ``xi'(psi)`` for a callable ``xi``.

    Returns
    -------
    callable
        ``f(psi, x)`` vectorised as :func:`rotorlyap.technical_stability` takes it.
    """
    if callable(xi):
        def f(psi, x):
            psi = np.asarray(psi, dtype=float)
            return blade.rhs(psi, xi(psi) + x) - dxi(psi)
    else:
        xi = np.asarray(xi, dtype=float)

        def f(psi, x):
            return blade.rhs(psi, xi + x)
    return f


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
        ``lyapunov(blade, xi, dxi)`` returning an object with vectorised ``W(psi, x)`` and
        ``dW(psi, x)`` (J and J/rad). Default: the paper's energy function,
        :meth:`Blade.energy_function`.
    A : float, optional
        Requested bound of the scaled norm; default :data:`DEFAULT_A`.
    scales : array_like, optional
        Norm scales ``a_i`` (rad, rad/rad); default :data:`DEFAULT_SCALES`.
    n_psi : int
        Azimuths of the grid (steps 5 and 6).
    steady : None, array_like or (callable, callable)
        Steady motion ``xi``: None for the hover equilibrium of ``params`` (the paper's
        choice, reused at every ``mu``), a constant state (6,), or ``(xi(psi), dxi(psi))``.
    test_disturbances : None or array_like
        None for the strict reading (whole spheres); an array of directions ``(k, 6)`` in
        scaled coordinates for the practical reading (e.g. :data:`PAPER_TEST_DISTURBANCES`).
    **engine_options
        Passed on to :func:`rotorlyap.technical_stability` (``n_sphere``, ``n_radii``, ...).

    Returns
    -------
    TechnicalStabilityResult
        With ``reading`` "strict" or "practical".

    Raises
    ------
    ValueError
        Bad ``mu``, ``steady``, scales or bound (from the engine), or a trim that does not
        converge (:class:`rotorlyap.trim.TrimError`).
    """
    if not isinstance(params, BladeParameters):
        raise TypeError(f"params must be a BladeParameters, got {type(params).__name__}")
    mu = float(mu)
    if not (np.isfinite(mu) and 0.0 <= mu <= 0.5):
        raise ValueError(f"mu must be an advance ratio in [0, 0.5], got {mu!r}")
    if scales is not None and np.size(scales) != 6:
        raise ValueError(
            f"scales must hold 6 positive numbers, one per state component {STATE_NAMES}, "
            f"got {np.size(scales)}"
        )
    blade = Blade(params, mu)  # trims the collective in hover if params.collective is None
    xi, dxi = _steady_motion(blade.params, steady)
    if lyapunov is None:
        fun = blade.energy_function(xi, dxi)
    else:
        if not callable(lyapunov):
            raise TypeError("lyapunov must be callable as lyapunov(blade, xi, dxi)")
        fun = lyapunov(blade, xi, dxi)
    f = getattr(fun, "f", None) or disturbed_system(blade, xi, dxi)
    return technical_stability(
        f, fun.W, DEFAULT_A if A is None else A,
        scales=DEFAULT_SCALES if scales is None else scales,
        n_psi=n_psi, dW=fun.dW, test_directions=test_disturbances, **engine_options,
    )


def energy_rate_terms(blade: Blade, xi, psi, x) -> dict[str, np.ndarray]:
    """Split the energy function's ``W'`` into the work rates of the forces on each hinge.

    For a constant steady motion ``xi`` and no cyclic pitch, Lagrange's equations give
    ``dW/dt = qdot . (Q_damp + Q_aero(z) + F_c(xi))``, where ``F_c(xi)`` is the conservative
    generalised force at ``xi`` at rest (minus the gradient of the effective potential), so
    that, per unit of azimuth,

    ``W' = sum_h q'_h [Q_damp,h + (Q_aero,h(psi, z) + F_c,h(xi))]``.

    At the hover equilibrium ``F_c(xi) = -Q_aero(xi)``: the second bracket is the change of
    the aerodynamic load caused by the disturbance. The sum of all terms equals
    ``blade.energy_function(xi).dW`` (a unit test checks it).

    Parameters
    ----------
    blade : Blade
        The blade (no cyclic pitch).
    xi : array_like
        Constant steady motion, shape (6,).
    psi : float or numpy.ndarray
        Azimuth(s), broadcasting with ``x[..., 0]``.
    x : numpy.ndarray
        Disturbed states, shape (..., 6).

    Returns
    -------
    dict
        ``"damping"`` and ``"aerodynamic"``: per-hinge work rates (J/rad), shape (..., 3),
        hinges in the order flap, lag, pitch; ``"total"``: their sum over hinges and kinds,
        shape (...).
    """
    if blade.has_cyclic:
        raise ValueError("energy_rate_terms needs a blade without cyclic pitch (W then has no explicit psi-dependence)")
    xi = np.asarray(xi, dtype=float)
    if xi.shape != (6,):
        raise ValueError(f"xi must be a constant state of shape (6,), got {xi.shape}")
    x = np.asarray(x, dtype=float)
    z = xi + x
    forces = blade.generalised_forces(psi, z)
    steady = blade.generalised_forces(0.0, np.concatenate([xi[:3], np.zeros(3)]))["conservative"]
    rates = z[..., 3:] - xi[3:]
    damping = rates * forces["damping"]
    aero = rates * (forces["aerodynamic"] + steady)
    return {"damping": damping, "aerodynamic": aero, "total": damping.sum(-1) + aero.sum(-1)}
