"""The norm of the example systems' motions, shared by chapters 1 and 2.

Chapter 1 (:mod:`rotorlyap.chapters.technical_stability`) draws the norm of motions started in
the certified start region against azimuth; chapter 2 (:mod:`rotorlyap.chapters.algorithm`)
reduces the same kind of motions to the largest norm each reaches. Both simulate them with
:func:`norm_history_data` (a :class:`NormHistoryData`), and both chapters' drawings of the state
plane draw circles of the scaled norm (``_circle``), which is here too. All quantities are
dimensionless (the systems of :mod:`rotorlyap.methods.examples`); azimuths are in radians.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..methods.examples import PeriodicSystem
from ..methods.lyapunov import TechnicalStabilityResult
from ..methods.simulation import simulate

__all__ = ["NormHistoryData", "norm_history_data"]


def _circle(radius: float, scales: np.ndarray, n: int = 361) -> np.ndarray:
    t = np.linspace(0, 2 * np.pi, n)
    return radius * np.stack([np.cos(t), np.sin(t)], axis=1) * scales[:2]


@dataclass(frozen=True)
class NormHistoryData:
    """Norm of simulated motions against azimuth, with ``A`` and ``lambda0(psi)``.

    Attributes
    ----------
    psi_grid, lambda0 : numpy.ndarray
        The certificate's azimuths and start radii.
    A : float
        The bound.
    psi : list of numpy.ndarray
        For each start azimuth, the output azimuths (shape ``(k,)``).
    norm : list of numpy.ndarray
        For each start azimuth, norms of its motions, shape ``(k, m)``.
    max_ratio : float
        Largest ``||x|| / A`` over all motions: below 1 is the theorem's conclusion.
    n_periods : float
        Simulated length of every motion, in periods.
    fraction : float
        Start radius of the motions as a fraction of ``lambda0`` at their start azimuth.
    """

    psi_grid: np.ndarray
    lambda0: np.ndarray
    A: float
    psi: list
    norm: list
    max_ratio: float
    n_periods: float
    fraction: float

    @property
    def n_motions(self) -> int:
        """Number of simulated motions, over all start azimuths."""
        return int(sum(n.shape[1] for n in self.norm))

    def summary(self) -> str:
        """The largest ``||x|| / A`` over all motions (three decimals), with their number and length."""
        return "largest ||x|| / A over %d motions and %g periods: %.3f" % (
            self.n_motions, self.n_periods, self.max_ratio)

    def facts(self, prefix: str = "ch1") -> dict:
        """``{prefix}_max_ratio``, and the certificate the motions test: ``{prefix}_A``,
        ``{prefix}_lam_min``, ``{prefix}_lam_max`` (scaled norm), all to three decimals."""
        return {
            f"{prefix}_max_ratio": round(float(self.max_ratio), 3),
            f"{prefix}_A": round(float(self.A), 3),
            f"{prefix}_lam_min": round(float(np.min(self.lambda0)), 3),
            f"{prefix}_lam_max": round(float(np.max(self.lambda0)), 3),
        }


def norm_history_data(
    system: PeriodicSystem,
    result: TechnicalStabilityResult,
    start_indices,
    *,
    n_starts: int = 32,
    n_periods: float = 20.0,
    fraction: float = 0.999,
    seed: int = 0,
) -> NormHistoryData:
    """Simulate motions started on ``fraction * lambda0`` at several azimuths.

    Start directions are spread deterministically on the sphere (a seeded generator), so
    the same call gives the same motions.

    Parameters
    ----------
    system : PeriodicSystem
        The system (see :mod:`rotorlyap.methods.examples`).
    result : TechnicalStabilityResult
        Its certificate from :func:`rotorlyap.technical_stability`.
    start_indices : iterable of int
        Indices of the start azimuths in ``result.psi``.
    n_starts : int
        Motions per start azimuth.
    n_periods : float
        Simulated length, in periods.
    fraction : float
        Start radius as a fraction of ``lambda0`` at the start azimuth (scaled norm).
    seed : int
        Seed of the start directions.
    """
    rng = np.random.default_rng(seed)
    n = result.scales.size
    psis, norms, worst = [], [], 0.0
    for j in start_indices:
        u = rng.normal(size=(n_starts, n))
        u /= np.linalg.norm(u, axis=1, keepdims=True)
        x0 = fraction * result.lambda0[j] * u * result.scales
        sim = simulate(system.f, x0, result.psi[j], n_periods, period=system.period, scales=result.scales)
        psis.append(sim.psi)
        norms.append(sim.norm)
        worst = max(worst, float(sim.max_norm.max()) / result.A)
    return NormHistoryData(result.psi, result.lambda0, result.A, psis, norms, worst,
                           n_periods=float(n_periods), fraction=float(fraction))
