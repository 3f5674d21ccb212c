"""The isolated rigid three-hinge blade, trimmed in hover: the object every chapter uses.

:class:`Blade` is :class:`rotorlyap.model.equations.BladeEquations` (the equations of motion:
generated Lagrangian terms, hinge dampers, strip aerodynamics) with two additions:

* when the parameters leave the collective open (``collective=None``, as the paper's Table I
  does), it is trimmed for thrust = weight in hover (:func:`rotorlyap.model.trim.hover_trim`)
  and kept at every advance ratio, as the paper keeps the hover controls;
* :meth:`Blade.equilibrium`, the hover equilibrium (:mod:`rotorlyap.model.equilibrium`),
  computed once and kept.

The pieces live in their own modules: mass properties in :mod:`rotorlyap.model.mass`, air
loads and the pitch-damping couple in :mod:`rotorlyap.model.aero`, the equations in
:mod:`rotorlyap.model.equations`; steady motions (constant or periodic) in
:mod:`rotorlyap.model.steady`; the Liapunov functions in :mod:`rotorlyap.analysis.functions`.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .equations import BladeEquations
from .equilibrium import hover_equilibrium
from .parameters import BladeParameters
from .trim import hover_trim

__all__ = ["Blade"]

FloatArray = NDArray[np.float64]


class Blade(BladeEquations):
    """The paper's rigid blade with three hinges, in hover or forward flight.

    Parameters
    ----------
    params : BladeParameters
        Blade, rotor and flight parameters.  If ``params.collective`` is None the collective is
        trimmed for thrust = weight in hover (:func:`rotorlyap.model.trim.hover_trim`).
    mu : float
        Advance ratio ``V / (Omega R)``, >= 0.

    Attributes
    ----------
    params : BladeParameters
        The parameters with the collective filled in (trimmed if it was None).
    mu : float
        Advance ratio.
    mass_properties : rotorlyap.model.mass.MassProperties
        Blade mass properties about the pitch hinge.
    r : numpy.ndarray
        Aerodynamic station radii (m, at zero hinge angles), shape ``(n_stations,)``.

    Raises
    ------
    ValueError
        A negative or non-finite ``mu``.
    rotorlyap.errors.TrimError
        The hover trim does not converge (a ``RuntimeError``).
    """

    def __init__(self, params: BladeParameters, mu: float = 0.0):
        mu = float(mu)
        if not (math.isfinite(mu) and mu >= 0):
            raise ValueError(f"mu must be a finite advance ratio >= 0, got {mu!r}")
        trimmed = None
        if params.collective is None:
            trimmed = hover_trim(params)
            params = replace(params, collective=trimmed.collective)
        super().__init__(params, mu)
        self._hover_equilibrium: FloatArray | None = (
            None if trimmed is None else np.array(trimmed.equilibrium, dtype=np.float64))

    def with_collective(self, collective: float) -> "Blade":
        """A copy of this blade with another collective (shares the precomputed data)."""
        other = super().with_collective(collective)
        other._hover_equilibrium = None
        return other

    def equilibrium(self, x0: ArrayLike | None = None, tol: float = 1e-10) -> FloatArray:
        """Hover equilibrium ``(beta, zeta, theta, 0, 0, 0)``, rad: the paper's steady motion.

        :func:`rotorlyap.model.equilibrium.hover_equilibrium` (same arguments); without ``x0``
        the result is kept, and for a trimmed blade it is the trimmed equilibrium (which may
        lie past a fold of the branch a continuation in the collective follows, see
        :mod:`rotorlyap.model.trim`).

        Raises
        ------
        rotorlyap.errors.EquilibriumError
            If no equilibrium is found (a ``RuntimeError``).
        """
        if x0 is None and self._hover_equilibrium is not None:
            return self._hover_equilibrium.copy()
        z = hover_equilibrium(self, x0, tol)
        if x0 is None:
            self._hover_equilibrium = z.copy()
        return z
