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
"""

from __future__ import annotations

import numpy as np

from ..jit import jit

# the kernels joined here are the model's and the method's own (private to their modules: this
# module is their one other caller)
from ..methods.periodic_lyapunov import _hermite_forms
from ..model.compiled import _controls, _rhs_block_range
from ..model.steady import _hermite_rows

__all__ = ["fused_arguments", "quadratic_rate_about_tabulated"]


@jit(error_model="numpy")
def _quadratic_rate(psi, x, scales, values, slopes, ctrl, P, sc, st, tab, P_grid, D_grid, period, out):
    m = x.shape[0]
    xi = np.empty((m, 6))
    dxi = np.empty((m, 6))
    _hermite_rows(psi, values, slopes, False, xi)
    _hermite_rows(psi, values, slopes, True, dxi)
    z = np.empty((m, 6))
    for i in range(m):
        for c in range(6):
            z[i, c] = xi[i, c] + x[i, c]
    h = np.empty((m, 6))
    _rhs_block_range(psi, z, ctrl, P, sc, st, tab, h, 0, m)
    y = np.empty((m, 6))
    fy = np.empty((m, 6))
    for i in range(m):
        for c in range(6):
            y[i, c] = x[i, c] / scales[c]
            fy[i, c] = (h[i, c] - dxi[i, c]) / scales[c]
    w = np.empty(m)
    _hermite_forms(psi, y, fy, P_grid, D_grid, period, True, w, out)


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
    parallel kernels for large batches. Returns ``W'`` per rad of azimuth, shape ``(m,)``."""
    c = np.ascontiguousarray
    out = np.empty(x.shape[0])
    _quadratic_rate(c(psi, dtype=float), c(x, dtype=float), c(scales, dtype=float), motion.values,
                    motion.slopes, controls, kernel.P, kernel.scalars, kernel.stations, kernel.table,
                    grids[0], grids[1], float(period), out)
    return out
