"""The errors rotorlyap raises when a computation cannot give an answer.

Two families, each a subclass of the built-in exception a caller would expect:

* :class:`ConvergenceError` (a ``RuntimeError``): an iteration did not converge. Its
  subclasses name the iteration (the hover trim, the hover equilibrium, the periodic motion,
  the induced inflow) and carry the numbers a user needs to act on it: the residual or
  correction reached, the tolerance asked for, the number of iterations, and the condition
  (advance ratio, flap angle, thrust and weight) where it failed.
* :class:`NotAsymptoticallyStableError` (a ``ValueError``): a linear periodic system, or the
  blade linearised about its steady motion, is not asymptotically stable, so no quadratic
  Liapunov function about that motion exists. It carries the spectral radius of the monodromy
  matrix and the largest growth rate.

A file that cannot be read as what it claims to be raises :class:`CertificateFileError` (a
``ValueError``): a certificate file (:mod:`rotorlyap.analysis.certificate_file`) that is not JSON,
is truncated, lacks a field or holds a bad value.

One warning: :class:`TemplateValuesWarning`, for a parameter set of another rotor that keeps
values of the paper's blade it was not given.

Callers catch the type, never the text of the message. Bad arguments (a negative advance
ratio, an unknown option) raise ``ValueError`` or ``TypeError`` with a message that says what
is allowed.
"""

from __future__ import annotations

__all__ = [
    "CertificateFileError", "ConvergenceError", "EquilibriumError", "InflowConvergenceError",
    "NotAsymptoticallyStableError", "PeriodicMotionError", "TemplateValuesWarning", "TrimError",
]


class ConvergenceError(RuntimeError):
    """An iteration did not converge.

    Attributes
    ----------
    residual : float or None
        The residual (or Newton correction) reached, in the units the message states.
    tolerance : float or None
        The tolerance it had to fall below, same units.
    iterations : int or None
        Iterations (or function evaluations) spent.
    """

    def __init__(self, message: str, *, residual: float | None = None, tolerance: float | None = None,
                 iterations: int | None = None):
        super().__init__(message)
        self.residual = residual
        self.tolerance = tolerance
        self.iterations = iterations


class TrimError(ConvergenceError):
    """A trim failed: the hover trim (thrust = weight) or the forward-flight trim.

    Attributes
    ----------
    thrust : float or None
        Rotor thrust reached where the trim stopped, N.
    weight : float or None
        The weight to balance, N.
    flap_angle : float or None
        Flap angle of the equilibrium branch where it stopped, rad.
    """

    def __init__(self, message: str, *, thrust: float | None = None, weight: float | None = None,
                 flap_angle: float | None = None, **numbers):
        super().__init__(message, **numbers)
        self.thrust = thrust
        self.weight = weight
        self.flap_angle = flap_angle


class EquilibriumError(ConvergenceError):
    """No hover equilibrium was found (from the given start, or along the continuation).

    Attributes
    ----------
    collective : float or None
        Collective where the continuation stopped, rad.
    """

    def __init__(self, message: str, *, collective: float | None = None, **numbers):
        super().__init__(message, **numbers)
        self.collective = collective


class PeriodicMotionError(ConvergenceError):
    """Newton's method on the Fourier collocation equations found no periodic motion.

    Attributes
    ----------
    mu : float or None
        Advance ratio.
    """

    def __init__(self, message: str, *, mu: float | None = None, **numbers):
        super().__init__(message, **numbers)
        self.mu = mu


class InflowConvergenceError(ConvergenceError):
    """The momentum-theory inflow iteration did not converge."""


class NotAsymptoticallyStableError(ValueError):
    """The (linearised) periodic system is not asymptotically stable.

    Attributes
    ----------
    spectral_radius : float
        Largest modulus of the Floquet multipliers (>= 1 minus the test's margin).
    growth_rate : float or None
        Largest real part of the characteristic exponents, per unit of the independent
        variable (for the blade, per rad of azimuth: "per rev").
    """

    def __init__(self, message: str, *, spectral_radius: float, growth_rate: float | None = None):
        super().__init__(message)
        self.spectral_radius = spectral_radius
        self.growth_rate = growth_rate


class TemplateValuesWarning(UserWarning):
    """A parameter set describes another rotor than the paper's but keeps blade fields of the
    Table I template (:func:`rotorlyap.model.parameters.field_origins`): values the user did not
    give, such as the pitch-flap coupling or the lag damper of the paper's blade."""


class CertificateFileError(ValueError):
    """A certificate file (:mod:`rotorlyap.analysis.certificate_file`) that cannot be read: not
    JSON, truncated, of another format or version, a field missing, of the wrong type or shape, or
    a non-finite number. The message names the file and the field and says what is allowed. (A
    file that reads but whose claims do not hold is not an error: the checks refuse it.)"""
