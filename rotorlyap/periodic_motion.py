"""The true periodic steady motion of the blade in forward flight.

The paper reuses the hover equilibrium as the "steady motion" at every advance ratio. In
forward flight that state is not a solution: the blade flaps, lags and pitches once per
revolution. :func:`periodic_motion` finds the ``2 pi``-periodic solution ``xi(psi)`` of the
full nonlinear equations by Fourier collocation (harmonic balance) solved with Newton's
method, all azimuths evaluated at once by the vectorised model.
Optionally the cyclic pitch is trimmed at the same time so that the first harmonics of
flapping vanish (the rotor disc is not tilted relative to the shaft).

The solution is stored as a truncated Fourier series, which gives ``xi(psi)`` and
``xi'(psi)`` for any azimuths, vectorised, in the form
:meth:`rotorlyap.Blade.energy_function` and :func:`rotorlyap.stability.blade_stability` take.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Callable

import numpy as np

from .blade import Blade
from .parameters import BladeParameters

__all__ = ["PeriodicMotion", "PeriodicMotionError", "periodic_motion"]

TWO_PI = 2.0 * np.pi


class PeriodicMotionError(RuntimeError):
    """The shooting iteration did not converge to a periodic solution."""


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
    def steady(self) -> tuple:
        """``(xi, dxi)``, the form :func:`rotorlyap.stability.blade_stability` takes."""
        return (self.xi, self.dxi)


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
        Advance ratio in [0, 0.5]. At ``mu = 0`` the solution is the hover equilibrium.
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
    if not (np.isfinite(mu) and 0.0 <= mu <= 0.5):
        raise ValueError(f"mu must be an advance ratio in [0, 0.5], got {mu!r}")
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
