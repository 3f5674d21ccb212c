"""Fused kernels: the blade's, the steady motion's and the quadratic function's compiled kernels
in one call.

The forward-flight searches evaluate ``W'`` of a quadratic function about a tabulated periodic
motion (:class:`~rotorlyap.analysis.functions.QuadraticFunction`,
:class:`~rotorlyap.model.steady.TabulatedMotion`) tens of thousands of times on batches of a
few hundred states. Each evaluation runs four compiled kernels (the motion ``xi`` and its rate
``xi'`` by Hermite interpolation, the blade's right-hand side, the Hermite form of ``P``) with
some twenty numpy operations between them, and that Python between the kernels cost as much as
the kernels. :func:`quadratic_rate_about_tabulated` runs the same kernels, with the same
operations between them in the same order, inside one compiled function: the same numbers to
the last bit (tested), without the Python.

The searches of condition (h) (:func:`rotorlyap.methods.lyapunov.band_max_dw`) evaluate ``W'``
at points of rays: a search coordinate ``y`` is a direction ``u = y / |y|`` and a fraction
``t = |y|`` of the way from the ray's level radius ``r_c`` (where ``W = c``) out to the bound
``A``. :func:`quadratic_rate_on_rays` maps ``y`` to the state and evaluates ``W'`` there in
the same compiled call, with the operations of the search's numpy code in the same order (the
same numbers to the last bit, tested).
"""

from __future__ import annotations

import numpy as np

from ..jit import jit

# the kernels joined here are the model's and the method's own (private to their modules: this
# module is their one other caller)
from ..methods.periodic_lyapunov import _hermite_weights
from ..model.compiled import _controls, _rhs_block_range
from ..model.steady import _hermite_rows

__all__ = ["fused_arguments", "quadratic_rate_about_tabulated", "quadratic_rate_on_rays"]


@jit
def _azimuth_runs(psi):
    """Runs of equal consecutive azimuths: ``(run, pu)``, the run of each state and the azimuth
    of each run (the searches put the states of one azimuth together; what depends on the
    azimuth alone is then computed once per run, with the numbers each state would get)."""
    m = psi.shape[0]
    run = np.empty(m, np.int64)
    nu = 0
    for i in range(m):
        if i == 0 or psi[i] != psi[i - 1]:
            nu += 1
        run[i] = nu - 1
    pu = np.empty(nu)
    for i in range(m):
        pu[run[i]] = psi[i]
    return run, pu


@jit
def _forms_per_run(pu, P_grid, D_grid, period, n):
    """``P(psi)`` and ``P'(psi)`` at each azimuth of ``pu``, the upper triangle row by row
    (``n (n + 1) / 2`` entries), with the operations of ``periodic_lyapunov._hermite_forms``."""
    N = P_grid.shape[0]
    Pm = np.empty((pu.shape[0], n * (n + 1) // 2))
    Dm = np.empty((pu.shape[0], n * (n + 1) // 2))
    for q in range(pu.shape[0]):
        j, j1, a0, b0, a1, b1, da0, db0, da1, db1 = _hermite_weights(pu[q], period, N)
        k = 0
        for r in range(n):
            for c in range(r, n):
                Pm[q, k] = (a0 * P_grid[j, r, c] + b0 * D_grid[j, r, c]
                            + a1 * P_grid[j1, r, c] + b1 * D_grid[j1, r, c])
                Dm[q, k] = (da0 * P_grid[j, r, c] + db0 * D_grid[j, r, c]
                            + da1 * P_grid[j1, r, c] + db1 * D_grid[j1, r, c])
                k += 1
    return Pm, Dm


@jit
def _rate_of_forms(x, h, dxi, run, fscales, Pm, Dm, out):
    """``W' = y^T P' y + 2 y^T P f_y`` (``y = x / a``, ``f_y = (h - xi') / a``) of each state
    from its run's ``P`` and ``P'`` (:func:`_forms_per_run`), with the operations of
    ``periodic_lyapunov._hermite_forms``."""
    n = x.shape[1]
    yy = np.empty(n)
    fy = np.empty(n)
    for i in range(x.shape[0]):
        q = run[i]
        for c in range(n):
            yy[c] = x[i, c] / fscales[c]
            fy[c] = (h[i, c] - dxi[q, c]) / fscales[c]
        acc_d = 0.0
        k = 0
        for r in range(n):
            xr = yy[r]
            for c in range(r, n):
                p = Pm[q, k]
                xc = yy[c]
                if r == c:
                    acc_d += Dm[q, k] * xr * xc + 2.0 * p * xr * fy[c]
                else:
                    acc_d += 2.0 * (Dm[q, k] * xr * xc + p * (xr * fy[c] + xc * fy[r]))
                k += 1
        out[i] = acc_d


@jit(error_model="numpy")
def _quadratic_rate(psi, x, scales, values, slopes, ctrl, P, sc, st, tab, P_grid, D_grid, period, out):
    run, pu = _azimuth_runs(psi)
    Pm, Dm = _forms_per_run(pu, P_grid, D_grid, period, x.shape[1])
    _rate_at(psi, x, run, pu, values, slopes, ctrl, P, sc, st, tab, scales, Pm, Dm, out)


@jit(error_model="numpy")
def _rate_at(psi, x, run, pu, values, slopes, ctrl, P, sc, st, tab, scales, Pm, Dm, out):
    """``W'`` at the disturbances ``x`` (m, n) about the tabulated motion, the azimuths' runs
    ``run``/``pu`` (:func:`_azimuth_runs`) and the forms ``Pm``, ``Dm`` of each run given."""
    m = x.shape[0]
    n = x.shape[1]
    xi = np.empty((pu.shape[0], n))
    dxi = np.empty((pu.shape[0], n))
    _hermite_rows(pu, values, slopes, False, xi)
    _hermite_rows(pu, values, slopes, True, dxi)
    z = np.empty((m, n))
    for i in range(m):
        for c in range(n):
            z[i, c] = xi[run[i], c] + x[i, c]
    h = np.empty((m, n))
    _rhs_block_range(psi, z, ctrl, P, sc, st, tab, h, 0, m)
    _rate_of_forms(x, h, dxi, run, scales, Pm, Dm, out)


@jit(error_model="numpy")
def _ray_rate(psi, y, level, bound, scales, fscales, values, slopes, ctrl, P, sc, st, tab, P_grid, D_grid,
              period, w_unit, out):
    m = y.shape[0]
    n = y.shape[1]
    # P and P' once per run of equal azimuths, used twice (W on the ray, W' at its point)
    run, pu = _azimuth_runs(psi)
    Pm, Dm = _forms_per_run(pu, P_grid, D_grid, period, n)
    x = np.empty((m, n))
    z = np.empty(n)
    for i in range(m):
        q = run[i]
        s = 0.0
        for c in range(n):  # numpy's norm of a row of six: the squares summed in order
            s += y[i, c] * y[i, c]
        ti = np.sqrt(s)
        d = max(ti, 1e-300)
        for c in range(n):
            z[c] = ((y[i, c] / d) * scales[c]) / fscales[c]
        acc = 0.0  # W at u * scales
        k = 0
        for r in range(n):
            zr = z[r]
            for c in range(r, n):
                if r == c:
                    acc += Pm[q, k] * zr * z[c]
                else:
                    acc += 2.0 * Pm[q, k] * zr * z[c]
                k += 1
        w_unit[i] = acc
        rc = bound
        if acc > 0:
            rr = np.sqrt(level / acc)
            rc = rr if rr < bound else bound
        ri = rc + min(max(ti, 0.0), 1.0) * (bound - rc)
        for c in range(n):
            x[i, c] = ((y[i, c] / d) * ri) * scales[c]
    _rate_at(psi, x, run, pu, values, slopes, ctrl, P, sc, st, tab, fscales, Pm, Dm, out)


def quadratic_rate_on_rays(psi: np.ndarray, y: np.ndarray, level: float, bound: float, scales: np.ndarray,
                           function_scales: np.ndarray, motion, controls: np.ndarray, kernel, grids: tuple,
                           period: float) -> tuple[np.ndarray, np.ndarray]:
    """``W`` on the unit sphere and ``W'`` on the band, for search coordinates ``y`` of the rays.

    The point of search coordinate ``y`` (shape ``(m, 6)``, scaled) at azimuth ``psi`` (rad,
    shape ``(m,)``) is ``x = (r u) a`` with ``u = y / |y|``, ``a = scales``,
    ``r = r_c + min(|y|, 1) (A - r_c)`` and ``r_c = min(sqrt(c / W(psi, u a)), A)`` (``A``
    where ``W(psi, u a) <= 0``), for ``W = x^T P(psi) x`` in the function's coordinates
    ``x / function_scales``; the remaining arguments as :func:`quadratic_rate_about_tabulated`.
    ``level`` is ``c`` (J) and ``bound`` is ``A`` (scaled norm). Returns ``W(psi, u a)`` and
    ``W'(psi, x)`` (J per rad of azimuth), each of shape ``(m,)``."""
    c = np.ascontiguousarray
    m = y.shape[0]
    w_unit, out = np.empty(m), np.empty(m)
    _ray_rate(c(psi, dtype=float), c(y, dtype=float), float(level), float(bound), c(scales, dtype=float),
              c(function_scales, dtype=float), motion.values, motion.slopes, controls, kernel.P,
              kernel.scalars, kernel.stations, kernel.table, grids[0], grids[1], float(period), w_unit, out)
    return w_unit, out


def fused_arguments(blade, motion, solution) -> tuple:
    """The arguments of :func:`quadratic_rate_about_tabulated` after ``psi``, ``x`` and the
    scales, for a blade with block kernels (:class:`~rotorlyap.model.blade.Blade`), a
    :class:`~rotorlyap.model.steady.TabulatedMotion` and a Hermite
    :class:`~rotorlyap.methods.periodic_lyapunov.PeriodicLyapunovSolution`."""
    return (motion, _controls(blade), blade.kernel, solution.kernel_grids(), float(solution.period))


def quadratic_rate_about_tabulated(psi: np.ndarray, x: np.ndarray, scales: np.ndarray, motion,
                                   controls: np.ndarray, kernel, grids: tuple, period: float) -> np.ndarray:
    """``W' = y^T P' y + 2 y^T P f_y`` (``y = x / a``, ``f_y = (h(psi, xi + x) - xi') / a``) in
    one compiled call, for states ``x`` of shape ``(m, 6)`` (rad, rad/rad) at azimuths ``psi``
    of shape ``(m,)`` (rad): ``xi`` and ``xi'`` the Hermite interpolant of ``motion`` (a
    :class:`~rotorlyap.model.steady.TabulatedMotion`), ``h`` the blade's block kernel
    (``kernel``, its :class:`~rotorlyap.model.compiled.KernelData`, and ``controls``, the
    collective and cyclic pitch, rad), ``P`` the Hermite interpolant of the symmetric grids
    ``grids = (P_grid, dP_grid)`` over ``period`` (rad). One thread: the caller keeps the
    threaded kernels for large batches. Returns ``W'`` per rad of azimuth, shape ``(m,)``."""
    c = np.ascontiguousarray
    out = np.empty(x.shape[0])
    _quadratic_rate(c(psi, dtype=float), c(x, dtype=float), c(scales, dtype=float), motion.values,
                    motion.slopes, controls, kernel.P, kernel.scalars, kernel.stations, kernel.table,
                    grids[0], grids[1], float(period), out)
    return out
