"""Steady motions of the blade: the one type every analysis takes, and the periodic motion.

A disturbance ``x = z - xi(psi)`` is measured from a *steady motion* ``xi``, a solution (or, in
the paper's forward flight, a chosen reference) of the blade's equations. Every function that
takes a steady motion (the Liapunov functions, :func:`rotorlyap.analysis.stability.blade_stability`,
the Floquet analysis) takes it as a :class:`SteadyMotion`, or as anything
:func:`as_steady_motion` turns into one:

* ``None``: the hover equilibrium of the blade (the paper's choice, reused at every advance
  ratio);
* a constant state, shape (6,);
* a pair of callables ``(xi(psi), dxi(psi))``; one that does not move (on 16 azimuths, to
  1e-12) is made constant, so that hover gets the exact constant treatment;
* an object with a ``steady`` attribute (:class:`PeriodicMotion`, :class:`TabulatedMotion`).

:func:`disturbed_rhs` is the one right-hand side of the disturbed motion,
``f(psi, x) = h(psi, xi + x) - xi'(psi)``.

The paper reuses the hover equilibrium as the steady motion at every advance ratio. In
forward flight that state is not a solution: the blade flaps, lags and pitches once per
revolution. :func:`periodic_motion` finds the ``2 pi``-periodic solution ``xi(psi)`` of the
full nonlinear equations by Fourier collocation (harmonic balance) solved with Newton's
method, all azimuths evaluated at once by the vectorised model. Optionally the cyclic pitch
is trimmed at the same time so that the first harmonics of flapping vanish (the rotor disc is
not tilted relative to the shaft). The solution is stored as a truncated Fourier series, which
gives ``xi(psi)`` and ``xi'(psi)`` for any azimuths; :func:`tabulate_motion` samples it once
for fast evaluation in large batches.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

from ..conventions import MAX_ADVANCE_RATIO, TWO_PI
from ..errors import PeriodicMotionError
from ..jit import jit, use_compiled
from .blade import Blade
from .parameters import BladeParameters

__all__ = [
    "STEADY_CHOICES", "PeriodicMotion", "SteadyMotion", "TabulatedMotion", "as_steady_motion",
    "disturbed_rhs", "periodic_motion", "refine_motion", "steady_motion", "tabulate_motion",
]

#: The steady motions :func:`steady_motion` computes by name.
STEADY_CHOICES = ("periodic", "hover")


# --------------------------------------------------------------------------------------
# The steady-motion type
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class SteadyMotion:
    """A steady motion of the blade: constant (an equilibrium) or ``2 pi``-periodic.

    Build one with :meth:`constant` or :meth:`periodic`, or :func:`as_steady_motion`.

    Attributes
    ----------
    label : str
        What it is, for messages and legends ("hover equilibrium", "periodic motion, mu = 0.15").
    state : numpy.ndarray or None
        The constant state (6,), rad and rad/rad; None for a periodic motion.
    xi_function, dxi_function : callable or None
        ``xi(psi)`` and ``xi'(psi)`` of a periodic motion, vectorised, returning
        ``psi.shape + (6,)``; None for a constant one.
    """

    label: str
    state: np.ndarray | None = None
    xi_function: Callable | None = None
    dxi_function: Callable | None = None

    @classmethod
    def constant(cls, state, label: str = "constant state") -> "SteadyMotion":
        """A constant steady motion (an equilibrium), ``state`` of shape (6,)."""
        state = np.array(state, dtype=float)
        if state.shape != (6,) or not np.all(np.isfinite(state)):
            raise ValueError(f"a constant steady motion must be a finite state of shape (6,), got shape {state.shape}")
        state.setflags(write=False)
        return cls(label=label, state=state)

    @classmethod
    def periodic(cls, xi: Callable, dxi: Callable, label: str = "periodic motion") -> "SteadyMotion":
        """A ``2 pi``-periodic steady motion from ``xi(psi)`` and its derivative ``dxi(psi)``.

        One that does not move (``xi`` constant and ``xi'`` zero to 1e-12 on 16 azimuths, the
        periodic motion in hover) is returned as a constant steady motion, so that hover gets
        the exact constant treatment.
        """
        if not (callable(xi) and callable(dxi)):
            raise TypeError("a periodic steady motion needs two callables, xi(psi) and its derivative dxi(psi)")
        grid = TWO_PI * np.arange(16) / 16
        vals = np.asarray(xi(grid), dtype=float)
        if vals.shape != (16, 6) or not np.all(np.isfinite(vals)):
            raise ValueError(f"xi(psi) must return finite states of shape (k, 6), got {vals.shape}")
        rates = np.asarray(dxi(grid), dtype=float)
        if np.ptp(vals, axis=0).max() < 1e-12 and np.abs(rates).max() < 1e-12:
            return cls.constant(vals[0], label)
        return cls(label=label, xi_function=xi, dxi_function=dxi)

    @property
    def is_constant(self) -> bool:
        """True for a constant steady motion (no explicit dependence on the azimuth)."""
        return self.state is not None

    def xi(self, psi) -> np.ndarray:
        """``xi(psi)``, shape ``psi.shape + (6,)``, rad and rad/rad."""
        psi = np.asarray(psi, dtype=float)
        if self.is_constant:
            return np.broadcast_to(self.state, psi.shape + (6,)).copy()
        return np.asarray(self.xi_function(psi), dtype=float)

    def dxi(self, psi) -> np.ndarray:
        """``xi'(psi)``, shape ``psi.shape + (6,)``, rad/rad and rad/rad^2."""
        psi = np.asarray(psi, dtype=float)
        if self.is_constant:
            return np.zeros(psi.shape + (6,))
        return np.asarray(self.dxi_function(psi), dtype=float)

    def __repr__(self) -> str:  # short and stable
        return f"SteadyMotion({self.label!r}, {'constant' if self.is_constant else 'periodic'})"


def as_steady_motion(steady, blade: Blade | None = None) -> SteadyMotion:
    """The :class:`SteadyMotion` that ``steady`` stands for (module docstring).

    Parameters
    ----------
    steady : None, SteadyMotion, array_like (6,), (callable, callable) or object with ``steady``
        The steady motion; None means the hover equilibrium of ``blade``.
    blade : Blade, optional
        Needed only for ``steady=None``.

    Raises
    ------
    ValueError, TypeError
        For anything else, saying what is allowed.
    """
    if isinstance(steady, SteadyMotion):
        return steady
    if steady is None:
        if blade is None:
            raise ValueError("steady=None means the hover equilibrium of a blade: give the blade")
        return SteadyMotion.constant(blade.equilibrium(), "hover equilibrium")
    inner = getattr(steady, "steady", None)
    if isinstance(inner, SteadyMotion):
        return inner
    if isinstance(steady, tuple) and len(steady) == 2 and all(callable(s) for s in steady):
        return SteadyMotion.periodic(*steady)
    if callable(steady):
        raise ValueError("a callable steady motion xi(psi) needs its derivative: give (xi, dxi)")
    xi = np.asarray(steady, dtype=float) if not isinstance(steady, (str, bytes)) else None
    if xi is None or xi.shape != (6,) or not np.all(np.isfinite(xi)):
        raise ValueError(
            "steady must be None (hover equilibrium), a finite state of shape (6,), a pair of "
            "callables (xi(psi), dxi(psi)), a SteadyMotion or a motion with a .steady attribute; "
            f"got {type(steady).__name__} {getattr(xi, 'shape', '')}")
    return SteadyMotion.constant(xi)


def disturbed_rhs(blade: Blade, steady) -> Callable:
    """Right-hand side of the disturbed motion, ``f(psi, x) = h(psi, xi + x) - xi'(psi)``.

    Parameters
    ----------
    blade : Blade
        The blade (its advance ratio and controls).
    steady : SteadyMotion or anything :func:`as_steady_motion` takes
        The steady motion ``xi``.

    Returns
    -------
    callable
        ``f(psi, x)``, vectorised as :func:`rotorlyap.methods.lyapunov.technical_stability`
        takes it, shape of ``x``.
    """
    steady = as_steady_motion(steady, blade)
    if steady.is_constant:
        xi = steady.state

        def f(psi, x):
            return blade.rhs(psi, xi + x)
    else:
        xi_f, dxi_f = steady.xi_function, steady.dxi_function

        def f(psi, x):
            psi = np.asarray(psi, dtype=float)
            return blade.rhs(psi, xi_f(psi) + x) - dxi_f(psi)
    return f


def steady_motion(params: BladeParameters, mu: float, kind: str = "periodic") -> SteadyMotion:
    """The steady motion of the blade at ``mu`` named by ``kind``.

    ``"periodic"``: the periodic motion (:func:`periodic_motion`; the hover equilibrium at
    ``mu = 0``); ``"hover"``: the hover equilibrium, the paper's choice at every ``mu``.

    Raises
    ------
    rotorlyap.errors.PeriodicMotionError
        If no periodic motion is found.
    """
    if kind not in STEADY_CHOICES:
        raise ValueError(f"kind must be one of {STEADY_CHOICES}, got {kind!r}")
    if kind == "hover" or mu == 0.0:
        return SteadyMotion.constant(Blade(params, 0.0).equilibrium(), "hover equilibrium")
    return periodic_motion(params, mu).steady


# --------------------------------------------------------------------------------------
# The periodic motion
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class PeriodicMotion:
    """A ``2 pi``-periodic solution of the blade equations.

    Attributes
    ----------
    params : BladeParameters
        Parameters of the blade (with the trimmed collective, and the trimmed cyclic pitch if
        ``trim_flapping`` was asked for).
    mu : float
        Advance ratio.
    z0 : numpy.ndarray
        State at ``psi = 0``, shape (6,).
    coefficients : numpy.ndarray
        Complex Fourier coefficients ``c_k``, ``k = 0..n/2``, shape (n/2 + 1, 6):
        ``xi(psi) = Re(c_0) + 2 Re(sum_k c_k exp(i k psi))``.
    residual : float
        Largest collocation residual ``|xi' - h(psi, xi)|`` at the converged solution.
    fourier_error : float
        Size of the highest harmonics kept (an estimate of the truncation error, rad).
    harmonics_deg : numpy.ndarray
        Mean, first cosine and first sine harmonics of the three hinge angles, deg, shape
        (3, 3): rows flap, lag, pitch.
    """

    params: BladeParameters
    mu: float
    z0: np.ndarray
    coefficients: np.ndarray
    residual: float
    fourier_error: float
    harmonics_deg: np.ndarray

    def xi(self, psi) -> np.ndarray:
        """The periodic motion at azimuths ``psi`` (any shape), shape ``psi.shape + (6,)``."""
        psi = np.asarray(psi, dtype=float)
        k = np.arange(self.coefficients.shape[0])
        e = np.exp(1j * psi[..., None] * k)  # (..., K)
        return np.real(e[..., :1] * 0 + self.coefficients[0]) + 2.0 * np.real(e[..., 1:] @ self.coefficients[1:])

    def dxi(self, psi) -> np.ndarray:
        """Its azimuth derivative ``xi'(psi)``, shape ``psi.shape + (6,)``."""
        psi = np.asarray(psi, dtype=float)
        k = np.arange(1, self.coefficients.shape[0])
        e = 1j * k * np.exp(1j * psi[..., None] * k)
        return 2.0 * np.real(e @ self.coefficients[1:])

    @property
    def steady(self) -> SteadyMotion:
        """This motion as a :class:`SteadyMotion` (Fourier series evaluated at every call)."""
        return SteadyMotion.periodic(self.xi, self.dxi, f"periodic motion, mu = {self.mu:g}")


def _differentiation_matrix(n: int) -> np.ndarray:
    """Spectral differentiation matrix on ``n`` (even) uniform points of ``[0, 2 pi)``.

    ``(D f)_j`` is the derivative at ``psi_j`` of the trigonometric interpolant of ``f``
    (Trefethen, *Spectral Methods in MATLAB*, 2000, ch. 3).
    """
    h = TWO_PI / n
    j = np.arange(n)
    diff = j[:, None] - j[None, :]
    with np.errstate(divide="ignore"):
        D = 0.5 * (-1.0) ** diff / np.tan(diff * h / 2.0)
    D[j, j] = 0.0
    return D


def _first_harmonics(samples: np.ndarray) -> np.ndarray:
    """Mean, cos and sin harmonic of each column of uniformly sampled periodic data."""
    n = samples.shape[0]
    psi = TWO_PI * np.arange(n) / n
    mean = samples.mean(axis=0)
    c = 2.0 * (samples * np.cos(psi)[:, None]).mean(axis=0)
    s = 2.0 * (samples * np.sin(psi)[:, None]).mean(axis=0)
    return np.stack([mean, c, s])


def periodic_motion(
    params: BladeParameters,
    mu: float,
    *,
    trim_flapping: bool = False,
    n_points: int = 64,
    tol: float = 1e-10,
    max_iter: int = 30,
    start: Callable[[np.ndarray], np.ndarray] | None = None,
) -> PeriodicMotion:
    """The ``2 pi``-periodic solution of the blade equations at advance ratio ``mu``.

    Method: Fourier collocation (harmonic balance in physical space). The unknowns are the
    states ``Z_j = xi(psi_j)`` at ``n_points`` uniform azimuths; the residual is
    ``D Z - h(psi_j, Z_j)`` with ``D`` the spectral differentiation matrix, solved by
    Newton's method with the exact block Jacobian ``D (x) I - diag(dh/dz(psi_j, Z_j))``
    (:meth:`Blade.jacobian`), all azimuths in one vectorised call. The start is the hover
    equilibrium unless ``start`` is given; Newton steps are damped (halved) while they do not
    reduce the residual.
    Spectral accuracy: for a smooth solution the error falls faster than any power of
    ``1 / n_points``; ``fourier_error`` reports the size of the highest retained harmonic.

    Parameters
    ----------
    params : BladeParameters
        The blade; a ``None`` collective is trimmed in hover (thrust = weight) and kept.
    mu : float
        Advance ratio in [0, MAX_ADVANCE_RATIO]. At ``mu = 0`` the solution is the hover equilibrium.
    trim_flapping : bool
        Also trim ``cyclic_cos`` and ``cyclic_sin`` (rad) so that the first harmonics of
        flapping vanish (the disc stays perpendicular to the shaft).
    n_points : int
        Collocation points (even, >= 8).
    tol : float
        Convergence criterion: largest residual ``|D Z - h|`` (rad/rad, rad/rad^2), and the
        first flapping harmonics (rad) when trimming, below ``tol``.
    max_iter : int
        Largest number of Newton iterations.
    start : callable, optional
        Initial guess ``start(psi) -> states`` of shape ``psi.shape + (6,)`` (for example a
        simulated motion over its last revolution, interpolated), to reach a periodic motion
        that Newton's method does not find from the hover equilibrium. Default: the hover
        equilibrium at every azimuth.

    Returns
    -------
    PeriodicMotion

    Raises
    ------
    PeriodicMotionError
        If Newton's method does not converge, with the residual reached.
    ValueError
        For a bad ``mu`` or ``n_points``.
    """
    mu = float(mu)
    if not (np.isfinite(mu) and 0.0 <= mu <= MAX_ADVANCE_RATIO):
        raise ValueError(f"mu must be an advance ratio in [0, {MAX_ADVANCE_RATIO:g}], got {mu!r}")
    if not (isinstance(n_points, int) and n_points >= 8 and n_points % 2 == 0):
        raise ValueError(f"n_points must be an even integer >= 8, got {n_points!r}")
    hover = Blade(params, 0.0)
    base = hover.params  # collective filled in
    n = n_points
    psi = TWO_PI * np.arange(n) / n
    D = _differentiation_matrix(n)
    eye6 = np.eye(6)
    big_D = np.kron(D, eye6)
    cos_w = 2.0 * np.cos(psi) / n
    sin_w = 2.0 * np.sin(psi) / n

    def make_blade(cyc):
        if not trim_flapping:
            return Blade(base, mu)
        return Blade(dataclasses.replace(base, cyclic_cos=float(cyc[0]), cyclic_sin=float(cyc[1])), mu)

    def residual(Z, blade):
        r = (D @ Z - blade.rhs(psi, Z)).reshape(-1)
        if trim_flapping:
            r = np.concatenate([r, [cos_w @ Z[:, 0], sin_w @ Z[:, 0]]])
        return r

    if start is None:
        Z = np.tile(hover.equilibrium(), (n, 1))
    elif not callable(start):
        raise TypeError(f"start must be None or a callable start(psi) -> states of shape (n, 6), got {start!r}")
    else:
        Z = np.asarray(start(psi), dtype=float)
        if Z.shape != (n, 6) or not np.all(np.isfinite(Z)):
            raise ValueError(f"start(psi) must return finite states of shape ({n}, 6), got shape {Z.shape}")
    cyc = np.array([base.cyclic_cos, base.cyclic_sin])
    blade = make_blade(cyc)
    r = residual(Z, blade)
    err = float(np.abs(r).max())
    for _ in range(max_iter):
        if err < tol:
            break
        J = big_D.copy()
        jac = blade.jacobian(psi, Z)  # (n, 6, 6)
        for j in range(n):
            J[6 * j:6 * j + 6, 6 * j:6 * j + 6] -= jac[j]
        if trim_flapping:
            m = 6 * n
            full = np.zeros((m + 2, m + 2))
            full[:m, :m] = J
            full[m, 0:m:6] = cos_w
            full[m + 1, 0:m:6] = sin_w
            h = 1e-6
            for k in range(2):
                dc = cyc.copy()
                dc[k] += h
                full[:m, m + k] = -(make_blade(dc).rhs(psi, Z) - blade.rhs(psi, Z)).reshape(-1) / h
            J = full
        step = np.linalg.solve(J, -r)
        lam = 1.0
        while True:
            Z_new = Z + lam * step[: 6 * n].reshape(n, 6)
            cyc_new = cyc + lam * step[6 * n:] if trim_flapping else cyc
            blade_new = make_blade(cyc_new)
            r_new = residual(Z_new, blade_new)
            err_new = float(np.abs(r_new).max())
            if err_new < err or lam < 1e-3:
                break
            lam *= 0.5
        Z, cyc, blade, r, err = Z_new, cyc_new, blade_new, r_new, err_new
    if not err < tol:
        raise PeriodicMotionError(
            f"no periodic solution found at mu = {mu:.4g}: collocation residual {err:.0e} "
            f"after {max_iter} Newton iterations (converged means < {tol:.1g})"
        )
    coeffs = np.fft.rfft(Z, axis=0) / n
    coeffs[-1] *= 0.5  # the Nyquist term is shared between +-n/2
    motion = PeriodicMotion(
        params=blade.params, mu=mu, z0=Z[0].copy(), coefficients=coeffs, residual=err,
        fourier_error=float(np.abs(coeffs[-4:]).max() * 2.0),
        harmonics_deg=np.degrees(_first_harmonics(Z[:, :3]).T),
    )
    return motion


# --------------------------------------------------------------------------------------
# Tabulated motions
# --------------------------------------------------------------------------------------


@jit
def _hermite_rows(psi, values, slopes, derivative, out):
    """:meth:`TabulatedMotion._eval`, one azimuth at a time (the same operations in the same
    order, so the same numbers)."""
    n = values.shape[0]
    h = TWO_PI / n
    for i in range(psi.shape[0]):
        u = (psi[i] % TWO_PI) / h
        j = min(int(math.floor(u)), n - 1)
        t = u - j
        j1 = (j + 1) % n
        t2 = t * t
        t3 = t2 * t
        for c in range(values.shape[1]):
            P0 = values[j, c]
            P1 = values[j1, c]
            D0 = h * slopes[j, c]
            D1 = h * slopes[j1, c]
            if derivative:
                out[i, c] = ((6 * t2 - 6 * t) * (P0 - P1) + (3 * t2 - 4 * t + 1) * D0
                             + (3 * t2 - 2 * t) * D1) / h
            else:
                out[i, c] = ((2 * t3 - 3 * t2 + 1) * P0 + (t3 - 2 * t2 + t) * D0
                             + (-2 * t3 + 3 * t2) * P1 + (t3 - t2) * D1)


@dataclass(frozen=True)
class TabulatedMotion:
    """A periodic steady motion as a piecewise cubic Hermite interpolant: fast to evaluate.

    :class:`rotorlyap.model.steady.PeriodicMotion` evaluates its Fourier series with one
    complex exponential per harmonic and azimuth, several times the cost of the blade's
    right-hand side for the large batches of the sphere searches. This class samples ``xi``
    and ``xi'`` once on ``n`` uniform azimuths and interpolates them by the periodic cubic
    Hermite interpolant; :meth:`dxi` is the *exact derivative of the interpolant*, so that
    ``(xi, dxi)`` is a consistent, continuously differentiable steady motion and the disturbed
    equations about it are exact (a certificate about it is a certificate for the blade). It
    differs from the series by ``max_error`` (of order ``h**4`` times the fourth derivative,
    ``h = 2 pi / n``).

    Attributes
    ----------
    values, slopes : numpy.ndarray
        ``xi`` and ``xi'`` on the grid ``2 pi j / n``, shape (n, 6).
    max_error : float
        Largest ``|xi_interpolated - xi|`` found at the grid midpoints (rad, rad/rad).
    """

    values: np.ndarray
    slopes: np.ndarray
    max_error: float
    label: str = "periodic motion"

    def _eval(self, psi, derivative: bool) -> np.ndarray:
        psi = np.asarray(psi, dtype=float)
        if psi.size > 1 and use_compiled():
            out = np.empty((psi.size, 6))
            _hermite_rows(np.ascontiguousarray(psi.reshape(-1)), self.values, self.slopes,
                          derivative, out)
            return out.reshape(psi.shape + (6,))
        n = self.values.shape[0]
        h = TWO_PI / n
        u = np.mod(psi, TWO_PI) / h
        j = np.minimum(np.floor(u).astype(int), n - 1)
        t = (u - j)[..., None]
        j1 = (j + 1) % n
        P0, P1 = self.values[j], self.values[j1]
        D0, D1 = h * self.slopes[j], h * self.slopes[j1]
        t2 = t * t
        if derivative:
            return ((6 * t2 - 6 * t) * (P0 - P1) + (3 * t2 - 4 * t + 1) * D0 + (3 * t2 - 2 * t) * D1) / h
        t3 = t2 * t
        return ((2 * t3 - 3 * t2 + 1) * P0 + (t3 - 2 * t2 + t) * D0 + (-2 * t3 + 3 * t2) * P1
                + (t3 - t2) * D1)

    def xi(self, psi) -> np.ndarray:
        """The interpolated motion, shape ``psi.shape + (6,)``."""
        return self._eval(psi, False)

    def dxi(self, psi) -> np.ndarray:
        """The derivative of the interpolant, shape ``psi.shape + (6,)``."""
        return self._eval(psi, True)

    @property
    def steady(self) -> SteadyMotion:
        """This motion as a :class:`SteadyMotion`."""
        return SteadyMotion.periodic(self.xi, self.dxi, self.label)


def tabulate_motion(motion, n: int = 4096) -> TabulatedMotion:
    """:class:`TabulatedMotion` of a steady motion on ``n`` azimuths.

    Parameters
    ----------
    motion : SteadyMotion, PeriodicMotion, (xi, dxi) or anything :func:`as_steady_motion` takes
        The motion to sample (usually a :class:`PeriodicMotion`).
    n : int
        Grid points on ``[0, 2 pi)``, >= 8.
    """
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 8:
        raise ValueError(f"n must be an integer >= 8, got {n!r}")
    steady = as_steady_motion(motion)
    grid = TWO_PI * np.arange(n) / n
    tab = TabulatedMotion(values=steady.xi(grid), slopes=steady.dxi(grid), max_error=0.0)
    mid = grid + 0.5 * TWO_PI / n
    err = float(np.abs(tab.xi(mid) - steady.xi(mid)).max())
    return TabulatedMotion(values=tab.values, slopes=tab.slopes, max_error=err, label=steady.label)


def refine_motion(blade: Blade, motion, n: int = 4096, *, rtol: float = 1e-12, tol: float = 1e-11,
                  max_iter: int = 8, floor_tol: float = 1e-9) -> TabulatedMotion:
    """The periodic motion by shooting, tabulated: a steady motion with a residual near round-off.

    :func:`periodic_motion` collocates a truncated Fourier series at a few dozen azimuths; between
    them its residual ``h(psi, xi) - xi'`` is that of the truncation (of order 1e-4 rad/rad^2 in
    forward flight, where the airfoil table's kinks slow the convergence of the series). A proof
    (:mod:`rotorlyap.methods.proof`) needs the residual far smaller. This function takes the
    motion's state at ``psi = 0`` as the start of Newton's method on the return map
    ``z(0) -> z(2 pi)`` of the full equations (DOP853 with relative tolerance ``rtol``; the
    Jacobian by the variational equations' finite-difference twin: six neighbouring motions in
    the same vectorised integration), then samples the converged motion and its right-hand side
    on ``n`` azimuths.

    Parameters
    ----------
    blade : Blade
        The blade at its advance ratio.
    motion : PeriodicMotion, TabulatedMotion or SteadyMotion
        The periodic motion to refine (its state at ``psi = 0`` is the start).
    n : int
        Grid of the tabulated result (>= 8).
    rtol : float
        Relative tolerance of the integration (the absolute one is ``rtol`` times 1e-2).
    tol : float
        Convergence criterion: ``|z(2 pi) - z(0)|`` below ``tol`` (rad, rad/rad).
    max_iter : int
        Largest number of Newton iterations.
    floor_tol : float
        The integration's own error bounds how small the mismatch can be made (near ``tol`` at
        the default ``rtol``: the last digits of the kernels' round-off decide whether it lands
        below ``tol``). Once the best mismatch is below ``floor_tol`` and a Newton step no longer
        halves it, the iteration stops at its best start (the mismatch is then noise).

    Returns
    -------
    TabulatedMotion
        ``max_error``: the largest change of the state at the grid points from ``motion``.

    Raises
    ------
    PeriodicMotionError
        If Newton's method does not bring the mismatch below ``floor_tol`` (with the mismatch
        reached).
    """
    from scipy.integrate import solve_ivp

    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 8:
        raise ValueError(f"n must be an integer >= 8, got {n!r}")
    steady = as_steady_motion(motion)
    z0 = np.asarray(steady.xi(np.zeros(1))[0], dtype=float)
    eps = 1e-7

    def rhs(psi, y):
        return blade.rhs(psi, y.reshape(-1, 6)).reshape(-1)

    def flow(starts: np.ndarray, dense: bool = False):
        sol = solve_ivp(rhs, (0.0, TWO_PI), starts.reshape(-1), method="DOP853", rtol=rtol,
                        atol=rtol * 1e-2, dense_output=dense)
        if not sol.success:
            raise PeriodicMotionError(f"the integration over one revolution failed: {sol.message}")
        return sol

    mismatch = previous = best = math.inf
    best_z0 = z0
    for _ in range(max_iter):
        starts = np.vstack([z0, z0 + eps * np.eye(6)])
        end = flow(starts).y[:, -1].reshape(7, 6)
        F = end[0] - z0
        mismatch = float(np.max(np.abs(F)))
        if mismatch < best:
            best, best_z0 = mismatch, z0
        if mismatch < tol:
            break
        if best < floor_tol and mismatch > 0.5 * previous:
            # Newton no longer converges: the mismatch is the integration's own error (its
            # noise floor, near rtol times the number of steps); the best start is kept.
            z0, mismatch = best_z0, best
            break
        previous = mismatch
        monodromy = ((end[1:] - end[0]) / eps).T
        z0 = z0 - np.linalg.solve(monodromy - np.eye(6), F)
    else:
        if best >= floor_tol:
            raise PeriodicMotionError(f"shooting did not converge in {max_iter} Newton iterations: "
                                      f"|z(2 pi) - z(0)| = {mismatch:.3g} (tolerance {tol:.3g})")
        z0, mismatch = best_z0, best
    grid = TWO_PI * np.arange(n) / n
    values = flow(z0, dense=True).sol(grid).T
    slopes = blade.rhs(grid, values)
    change = float(np.max(np.abs(values - steady.xi(grid))))
    return TabulatedMotion(values=values, slopes=slopes, max_error=change,
                           label=f"{steady.label} (shooting)")
