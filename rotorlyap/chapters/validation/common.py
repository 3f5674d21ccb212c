"""Chapter 7 ("Validation and beyond"): the cases, the advance-ratio grids and the scans'
resolution, with the small helpers the chapter's other modules share (:func:`max_distance`, the
simulated motions' verdicts in words)."""

from __future__ import annotations

import numpy as np

from ...conventions import DEFAULT_A, DEFAULT_SCALES
from ...methods.simulation import scaled_norm
from ..scans import _join

__all__ = ["CASES", "MU_FLOQUET", "MU_SCAN", "grid_summary", "max_distance", "SCAN_OPTIONS"]

#: The paper's three cases.
CASES = ("forward", "neutral", "backward")

#: Advance ratios of the Floquet sweep (fine enough to follow the modes by continuity).
MU_FLOQUET = tuple(float(m) for m in np.round(np.arange(0.0, 0.2501, 0.025), 3))

#: Advance ratios of the scans (each costs a sphere search per azimuth and function).
MU_SCAN = (0.0, 0.05, 0.1, 0.15, 0.2, 0.25)

#: The engine's resolution in the chapter's scan
#: (:func:`~rotorlyap.chapters.validation.scan.scan_data`): 24 azimuths and 256
#: quasi-random directions per sphere (with the structured ones). The falsifier tests attack
#: the certificates of exactly these runs.
SCAN_OPTIONS = {"n_psi": 24, "n_sphere": 256}


#: What :func:`rotorlyap.methods.validation.classify_motion`'s verdicts say about a motion of
#: the (periodic) blade, in the chapter's words: a forced blade's "limit cycle" is the periodic
#: motion it settles on.
_VERDICT_WORDS = {"limit cycle outside A": "settles on a periodic motion outside A",
                  "limit cycle within A": "settles on a periodic motion within A"}


def _verdicts_in_words(verdicts: tuple) -> str:
    """``"both starts: settles on ..."`` when the starts agree, else each start's verdict."""
    words = [_VERDICT_WORDS.get(v, v) for v in verdicts]
    if len(set(words)) == 1:
        return f"{'both' if len(words) == 2 else 'every'} start{'s' if len(words) > 1 else ''}: {words[0]}"
    return "; ".join(f"start {i + 1}: {w}" for i, w in enumerate(words))


def grid_summary() -> str:
    """The norm's scales (deg and deg per rad), the bound ``A`` and the advance-ratio grids.

    Returns
    -------
    str
        Three lines, as chapter 7 prints them.
    """
    return "\n".join([
        _join("scales a_i (deg, deg/rad):", np.round(np.degrees(DEFAULT_SCALES), 2), "; A =", DEFAULT_A),
        _join("advance ratios, Floquet:", MU_FLOQUET),
        _join("advance ratios, scans:  ", MU_SCAN),
    ])


def max_distance(motion, state: np.ndarray, n_psi: int = 256) -> float:
    """Largest distance of a periodic motion from a constant state in the scaled norm.

    Parameters
    ----------
    motion : object with ``xi(psi)``
        A periodic motion (:class:`~rotorlyap.model.steady.PeriodicMotion`,
        :class:`~rotorlyap.model.steady.TabulatedMotion`, ...), states in rad and rad/rad.
    state : array_like
        The constant state, shape (6,), rad and rad/rad.
    n_psi : int
        Uniform azimuths over one revolution at which the distance is evaluated.

    Returns
    -------
    float
        ``max_psi ||xi(psi) - state||`` in the scaled norm of
        :data:`rotorlyap.conventions.DEFAULT_SCALES` (norm units).
    """
    grid = 2 * np.pi * np.arange(n_psi) / n_psi
    return float(scaled_norm(motion.xi(grid) - state, DEFAULT_SCALES).max())
