"""Small periodic systems with Liapunov functions, for the theorem and algorithm chapters.

Each builder returns a :class:`PeriodicSystem`: the right-hand side ``f(psi, x)``, a
Liapunov function ``W(psi, x)`` and its exact derivative along solutions ``dW(psi, x)``,
all vectorised in the form :func:`rotorlyap.technical_stability` takes.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np

__all__ = ["PeriodicSystem", "mathieu_duffing", "mathieu_duffing_proof", "mathieu_matrix", "pulsed_growth",
           "pulsed_growth_proof"]

Function = Callable[[np.ndarray, np.ndarray], np.ndarray]


@dataclass(frozen=True)
class PeriodicSystem:
    """A periodic system ``x' = f(psi, x)`` with a candidate Liapunov function.

    Attributes
    ----------
    f : callable
        Right-hand side, ``(psi (m,), x (m, n)) -> (m, n)``.
    W : callable
        Liapunov function, ``(psi, x) -> (m,)``.
    dW : callable
        Its derivative along solutions, ``W' = dW/dpsi + grad W . f``, ``(psi, x) -> (m,)``.
    period : float
        Period of ``f`` and ``W`` in ``psi``.
    dim : int
        State dimension ``n``.
    """

    f: Function
    W: Function
    dW: Function
    period: float
    dim: int


def mathieu_duffing(
    damping: float = 0.4, modulation: float = 0.3, softening: float = 1.0, cross: float | None = None
) -> PeriodicSystem:
    """Damped Mathieu oscillator with a softening cubic spring.

    ``y'' + c y' + k(psi) y - b y**3 = 0``, ``k(psi) = 1 + eps cos psi``, state
    ``x = (y, y')``, period ``2 pi``. The softening spring makes large motions escape (the
    separatrix of the static case lies at ``|y| = sqrt(k / b)``), so boundedness is a
    genuinely local property: the setting of technical stability.

    The Liapunov function is the energy of the linear part plus a cross term,
    ``W = y'**2 / 2 + k(psi) y**2 / 2 + d y y'``, with ``d = c / 2`` by default. Its derivative
    along solutions is, exactly,

    ``W' = (k'/2 - d k) y**2 - d c y y' + (d - c) y'**2 + b y**3 (y' + d y)``,

    a negative-definite quadratic form near the origin when ``eps`` is small enough against
    ``c``, spoiled at large ``|y|`` by the softening term: step 3 of the algorithm then has to
    reduce the bound ``A``, and ``lambda0`` varies with ``psi`` through ``k(psi)``.

    Parameters
    ----------
    damping : float
        ``c`` (> 0), per unit of ``psi``.
    modulation : float
        ``eps``, with ``0 <= eps < 1`` so that ``k > 0``.
    softening : float
        ``b`` (>= 0), the cubic softening coefficient.
    cross : float, optional
        ``d``, the cross-term weight; default ``c / 2``. ``W`` is positive definite for
        ``d**2 < 1 - eps``.

    Returns
    -------
    PeriodicSystem
    """
    c, eps, b = float(damping), float(modulation), float(softening)
    d = c / 2 if cross is None else float(cross)
    if not c > 0:
        raise ValueError(f"damping must be > 0, got {damping!r}")
    if not 0 <= eps < 1:
        raise ValueError(f"modulation must satisfy 0 <= eps < 1 (stiffness stays positive), got {modulation!r}")
    if not b >= 0:
        raise ValueError(f"softening must be >= 0, got {softening!r}")
    if not d * d < 1 - eps:
        raise ValueError(f"cross term d={d!r} makes W indefinite: need d**2 < 1 - eps = {1 - eps:.4g}")

    def k(psi):
        return 1.0 + eps * np.cos(psi)

    def f(psi, x):
        y, v = x[..., 0], x[..., 1]
        return np.stack([v, -c * v - k(psi) * y + b * y**3], axis=-1)

    def W(psi, x):
        y, v = x[..., 0], x[..., 1]
        return 0.5 * v**2 + 0.5 * k(psi) * y**2 + d * y * v

    def dW(psi, x):
        y, v = x[..., 0], x[..., 1]
        kp = -eps * np.sin(psi)
        return (0.5 * kp - d * k(psi)) * y**2 - d * c * y * v + (d - c) * v**2 + b * y**3 * (v + d * y)

    return PeriodicSystem(f=f, W=W, dW=dW, period=2 * np.pi, dim=2)


def pulsed_growth(growth: float = 0.5, pulse: float = 2.0, saturation: float = 1.0) -> PeriodicSystem:
    """A one-state periodic system where the paper's step 6 certifies starts that escape.

    ``x' = (a + b cos psi) x - k x**3``: growth ``a > 0`` on average, a growth pulse ``b`` around
    ``psi = 0`` and a cubic saturation ``k``; period ``2 pi``. The origin is unstable and every
    motion settles on a periodic motion whose amplitude peaks near ``psi = 0`` at about
    ``sqrt((a + b) / k)``.

    The Liapunov function ``W = p(psi) x**2`` with ``p = exp(-2 b sin psi)`` is built so that
    the paper's checks pass: its derivative along solutions is, exactly,
    ``W' = 2 p x**2 (a - k x**2)``, negative on every sphere ``|x| = A`` with ``A**2 > a / k``
    (step 3) and positive inside, for ``x**2 < a / k``. Step 4 gives ``alpha = A**2 exp(-2 b)``,
    step 5 ``lambda0(psi_j) = A exp(-b (1 - sin psi_j))``, and step 6 at ``psi_j`` alone passes
    wherever ``lambda0(psi_j)**2 >= a / k``, around ``psi = 90 deg``. A motion started there
    inside ``lambda0`` grows on the next pulse beyond ``A`` when ``(a + b) / k > A**2``. The
    theorem's (h) over the whole period fails on the band ``|x| <= A, W >= alpha`` (at
    ``psi`` near 270 deg the band reaches down to ``|x| = A exp(-2 b)``, where ``W' > 0``): the
    sound rule certifies nothing, rightly.

    Parameters
    ----------
    growth : float
        ``a`` (> 0).
    pulse : float
        ``b`` (> 0).
    saturation : float
        ``k`` (> 0).

    Returns
    -------
    PeriodicSystem
    """
    a, b, k = float(growth), float(pulse), float(saturation)
    for name, v in (("growth", a), ("pulse", b), ("saturation", k)):
        if not (np.isfinite(v) and v > 0):
            raise ValueError(f"{name} must be finite and > 0, got {v!r}")

    def p(psi):
        return np.exp(-2.0 * b * np.sin(psi))

    def f(psi, x):
        y = x[..., 0]
        return ((a + b * np.cos(psi)) * y - k * y**3)[..., None]

    def W(psi, x):
        return p(psi) * x[..., 0] ** 2

    def dW(psi, x):
        y2 = x[..., 0] ** 2
        return 2.0 * p(psi) * y2 * (a - k * y2)

    return PeriodicSystem(f=f, W=W, dW=dW, period=2 * np.pi, dim=1)


def mathieu_matrix(a: float, q: float, damping: float = 0.0) -> Callable[[np.ndarray], np.ndarray]:
    """The damped Mathieu equation as a linear periodic system ``x' = A(t) x``.

    ``y'' + c y' + (a - 2 q cos 2t) y = 0`` (DLMF ch. 28 notation), ``x = (y, y')``, period
    ``pi``: the classical test of Floquet theory (the stability chart of DLMF 28.17) and of the
    periodic Lyapunov equation.

    Parameters
    ----------
    a, q : float
        Mathieu parameters.
    damping : float
        ``c`` (>= 0).

    Returns
    -------
    callable
        ``A(t)``: shape ``t.shape + (2, 2)``, for a float ``t`` a ``(2, 2)`` array.
    """
    a, q, c = float(a), float(q), float(damping)
    if not c >= 0:
        raise ValueError(f"damping must be >= 0, got {damping!r}")

    def A(t):
        t = np.asarray(t, dtype=float)
        out = np.zeros(t.shape + (2, 2))
        out[..., 0, 1] = 1.0
        out[..., 1, 0] = -(a - 2.0 * q * np.cos(2.0 * t))
        out[..., 1, 1] = -c
        return out

    return A


# --------------------------------------------------------------------------------------
# The same systems for proofs in ball arithmetic (rotorlyap.methods.proof)
# --------------------------------------------------------------------------------------


class _ExampleProofSystem:
    """A :class:`rotorlyap.methods.proof.ProofSystem` from closed forms (see the builders)."""

    def __init__(self, n: int, residual, linear, averaged):
        self.n = n
        self._residual, self._linear, self._averaged = residual, linear, averaged

    def residual(self, N: int):
        return self._residual(N), {}

    def linear(self, N: int):
        return self._linear(N)

    def averaged_jacobian(self, N: int, radius):
        return self._averaged(N, np.asarray(radius, dtype=float)), {}


def mathieu_duffing_proof(damping: float = 0.4, modulation: float = 0.3, softening: float = 1.0,
                          cross: float | None = None):
    """:func:`mathieu_duffing` for :func:`rotorlyap.methods.proof.prove_quadratic`.

    The averaged Jacobian over ``|y| <= r_0`` is exact: ``int_0^1 J(psi, t x) dt =
    [[0, 1], [-k(psi) + b y^2, -c]]`` (the cubic's ``3 b t^2 y^2`` averages to ``b y^2``), with
    ``y^2`` in ``[0, r_0^2]``; the steady motion ``x = 0`` has no residual. ``W``'s matrix is
    ``[[k / 2, d / 2], [d / 2, 1 / 2]]``.

    Returns
    -------
    system : ProofSystem
        The oscillator (scales 1).
    quadratic : callable
        ``quadratic(N) -> (S, dS)``, balls of ``W``'s matrix and its derivative.
    """
    from . import intervals as iv

    mathieu_duffing(damping, modulation, softening, cross)  # checks the arguments
    c, eps, b = float(damping), float(modulation), float(softening)
    d = c / 2 if cross is None else float(cross)

    def k(N):
        return iv.cos(iv.psi_intervals(N)) * eps + 1.0

    def jac(N, y2):
        J = iv.zeros((N, 2, 2))
        J[:, 0, 1] = J[:, 0, 1] + 1
        J[:, 1, 0] = -k(N) + y2 * b
        J[:, 1, 1] = J[:, 1, 1] - c
        return J

    def quadratic(N):
        S = iv.zeros((N, 2, 2))
        S[:, 0, 0] = k(N) * 0.5
        S[:, 0, 1] = S[:, 0, 1] + d / 2
        S[:, 1, 0] = S[:, 1, 0] + d / 2
        S[:, 1, 1] = S[:, 1, 1] + 0.5
        dS = iv.zeros((N, 2, 2))
        dS[:, 0, 0] = -iv.sin(iv.psi_intervals(N)) * (eps / 2)
        return S, dS

    system = _ExampleProofSystem(
        2, lambda N: iv.zeros((N, 2)), lambda N: jac(N, 0.0),
        lambda N, r: jac(N, iv.hull(0.0, float(r[0]) ** 2)[()]))
    return system, quadratic


def pulsed_growth_proof(growth: float = 0.5, pulse: float = 2.0, saturation: float = 1.0):
    """:func:`pulsed_growth` for :func:`rotorlyap.methods.proof.prove_quadratic`: the averaged
    Jacobian ``a + b cos psi - k x^2`` over ``|x| <= r_0``, ``W``'s matrix ``p(psi) =
    exp(-2 b sin psi)``. The origin is unstable, so no proof may succeed.

    Returns
    -------
    system, quadratic
        As :func:`mathieu_duffing_proof`.
    """
    from . import intervals as iv

    pulsed_growth(growth, pulse, saturation)  # checks the arguments
    a, b, k = float(growth), float(pulse), float(saturation)
    exp = np.frompyfunc(lambda x: x.exp(), 1, 1)

    def jac(N, x2):
        return (iv.cos(iv.psi_intervals(N)) * b + a - x2 * k).reshape(N, 1, 1)

    def quadratic(N):
        psi = iv.psi_intervals(N)
        p = np.asarray(exp(iv.sin(psi) * (-2 * b)), dtype=object)
        return p.reshape(N, 1, 1), (p * iv.cos(psi) * (-2 * b)).reshape(N, 1, 1)

    system = _ExampleProofSystem(
        1, lambda N: iv.zeros((N, 1)), lambda N: jac(N, 0.0),
        lambda N, r: jac(N, iv.hull(0.0, float(r[0]) ** 2)[()]))
    return system, quadratic
