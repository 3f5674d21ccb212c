"""The hover equilibrium of the blade: the paper's steady motion.

Hinge angles with zero rates where the right-hand side vanishes at ``mu = 0``, found by
Newton's method with continuation in the collective from the unloaded blade, so that the
equilibrium lies on the branch connected to it.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import root

from ..errors import EquilibriumError
from .equations import BladeEquations

__all__ = ["hover_equilibrium"]

FloatArray = NDArray[np.float64]


def hover_equilibrium(blade: BladeEquations, x0: ArrayLike | None = None, tol: float = 1e-10) -> FloatArray:
    """Hover equilibrium: hinge angles with zero rates where ``rhs = 0`` at ``mu = 0``.

    The controls are the blade's collective (the cyclic pitch is ignored: with cyclic there
    is no constant equilibrium).  This is the paper's steady motion, reused for every
    advance ratio.

    Parameters
    ----------
    blade : BladeEquations
        The blade (its collective; its advance ratio and cyclic pitch are ignored).
    x0 : array_like, shape (3,), optional
        Starting hinge angles, rad.  Default: continuation in the collective from the
        unloaded blade (zero collective), which selects the branch of equilibria connected
        to it.
    tol : float
        Tolerance on the hinge angles, rad: the Newton correction at the solution (one
        Newton step with the finite-difference Jacobian is applied to the root found).

    Returns
    -------
    numpy.ndarray, shape (6,)
        ``(beta, zeta, theta, 0, 0, 0)``.

    Raises
    ------
    rotorlyap.errors.EquilibriumError
        If the root finder does not converge (from ``x0``, or along the continuation); a
        ``RuntimeError``.
    """
    p = blade.params
    hover = blade if (blade.mu == 0.0 and p.cyclic_cos == 0.0 and p.cyclic_sin == 0.0) \
        else BladeEquations(replace(p, cyclic_cos=0.0, cyclic_sin=0.0), mu=0.0)

    def newton_step(h: BladeEquations, q: FloatArray):
        zq = np.concatenate([q, np.zeros(3)])
        r = h.rhs(0.0, zq)[3:]
        J = h.jacobian(0.0, zq)[3:, :3]
        return np.linalg.solve(J, r)

    def solve(h: BladeEquations, start: FloatArray):
        """Newton's method (finite-difference Jacobian, steps limited to 0.1 rad); hybr
        from scipy if Newton fails.  Accepted when the Newton correction is < tol rad,
        which is scale-free (stiff springs make the residual large for tiny errors)."""
        q = np.array(start, dtype=np.float64)
        err = np.inf
        try:
            for _ in range(60):
                dq = newton_step(h, q)
                err = float(np.abs(dq).max())
                q = q - dq * min(1.0, 0.1 / max(err, 1e-300))
                if err < tol:
                    return q, "Newton converged", err
        except np.linalg.LinAlgError:
            pass
        sol = root(lambda u: h.rhs(0.0, np.concatenate([u, np.zeros(3)]))[3:], start,
                   method="hybr", options={"xtol": 1e-13})
        try:
            dq = newton_step(h, sol.x)
        except np.linalg.LinAlgError:
            return None, sol.message + " (singular Jacobian)", np.inf
        err = float(np.abs(dq).max())
        return (sol.x - dq if err < tol else None), sol.message, err

    messages = []
    if x0 is not None:
        q, msg, err = solve(hover, np.asarray(x0, dtype=np.float64))
        if q is None:
            messages.append(f"from {x0}: {msg} (Newton correction {err:.3g} rad)")
    else:
        # Continuation in the collective from the unloaded blade (zero collective), with
        # step halving; it follows the branch of equilibria connected to the unloaded blade.
        q, msg, err = solve(hover.with_collective(0.0), np.zeros(3))
        c, step, target = 0.0, 0.01, float(p.collective)
        if q is None:
            messages.append(f"no equilibrium at zero collective: {msg} (Newton correction {err:.3g} rad)")
        while q is not None and c != target:
            c_next = c + float(np.clip(target - c, -step, step))
            q_next, msg, err = solve(hover.with_collective(c_next), q)
            if q_next is None:
                step *= 0.5
                if step < 1e-4:
                    messages.append(
                        f"continuation from zero collective stopped at {c:.5f} rad "
                        f"(target {target:.5f} rad): {msg} (Newton correction {err:.3g} rad); the branch "
                        "of equilibria folds before the target collective. Trim the "
                        "collective (params.collective = None) or give x0.")
                    q = None
                continue
            c, q = c_next, q_next
    if q is not None:
        return np.concatenate([q, np.zeros(3)])
    raise EquilibriumError("hover equilibrium did not converge:\n  " + "\n  ".join(messages),
                           residual=float(err), tolerance=tol,
                           collective=None if x0 is not None else float(c))

