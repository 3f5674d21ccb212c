"""What chapters 5 (hover, :mod:`rotorlyap.chapters.hover`) and 6 (forward flight,
:mod:`rotorlyap.chapters.forward_flight`) share, with the inputs of the paper's figures that
the command line (:mod:`rotorlyap.chapters.commands`) also uses: the paper's three cases and
their parameters, Fig. 8's grids of advance ratios, the labels of the two readings and of the
state components, the names of test disturbances and the norm scales balanced in energy. What
only chapter 6 uses (the test-disturbance sets, the reverse-flow boundary and its mark, the
categories of the region maps with their legend) is in its package
:mod:`rotorlyap.chapters.forward_flight`.

Every quantity computed in a reading carries that reading's label, :data:`READING_LABELS`:
the strict reading (suprema and infima over whole spheres, the theorem as stated) is a
certificate as far as the search is exhaustive; the practical reading (``W`` and ``W'`` only
along test disturbances) is an indicator, never a certificate.

Conventions (``.notes/BLADE_SPEC.md``): azimuth ``psi = 0`` with the blade pointing aft
(over the tail), rotation counter-clockwise seen from above, so ``psi = 90 deg`` is the
advancing side and ``psi = 270 deg`` the retreating side.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from ..analysis.functions import energy_function
from ..conventions import DEFAULT_SCALES
from ..model.blade import Blade
from ..model.parameters import BladeParameters

__all__ = [
    "READING_LABELS", "CASES", "MU_GRID", "MU_GRID_STRICT", "STATE_LABELS", "case_params",
    "balanced_scales", "disturbance_names",
]

#: How each reading is labelled everywhere in the book.
READING_LABELS = {
    "strict": "strict (numerical certificate)",
    "practical": "practical (indicator, not a certificate)",
}

#: The paper's three cases (Table I computation parameters), in order.
CASES = ("forward", "neutral", "backward")

#: Advance ratios of Fig. 8 in the practical reading: 0 to 0.25, finer near hover.
MU_GRID = (0.0, 0.0125, 0.025, 0.05, 0.075, 0.1, 0.125, 0.15, 0.175, 0.2, 0.225, 0.25)

#: Advance ratios of Fig. 8 in the strict reading (each costs a sphere search per azimuth).
MU_GRID_STRICT = (0.0, 0.05, 0.1, 0.15, 0.2, 0.25)

# TeX labels of the six state components (plot labels; kept out of the API page).
STATE_LABELS = (r"$\beta$", r"$\zeta$", r"$\theta$", r"$\beta'$", r"$\zeta'$", r"$\theta'$")

_HINGES = ("flap", "lag", "pitch")


def case_params(cg, **overrides) -> BladeParameters:
    """Table I parameters for a named case ("forward", ...) or a C.G. position (fraction of chord)."""
    if isinstance(cg, str):
        return BladeParameters.table_i(cg, **overrides)
    return replace(BladeParameters.table_i("forward", **overrides), cg_position=float(cg))


class _Count:
    """Wrap a vectorised ``g(psi, x)`` and count the states it is evaluated at."""

    def __init__(self, fun):
        self.fun, self.n = fun, 0

    def __call__(self, psi, x):
        self.n += int(np.asarray(x).shape[0])
        return self.fun(psi, x)


def balanced_scales(params: BladeParameters, scales=None) -> np.ndarray:
    """Norm scales that give every signed axis the same energy ``W`` at ``||x|| = 1``.

    Each ``a_i`` of ``scales`` (default :data:`~rotorlyap.conventions.DEFAULT_SCALES`) is
    multiplied by ``sqrt(W_ref / W_i)``, with ``W_i`` the mean of ``W`` at ``+a_i e_i`` and
    ``-a_i e_i`` about the hover equilibrium and ``W_ref`` their geometric mean (``W`` is nearly
    quadratic at these amplitudes, so one correction suffices).
    """
    a = np.array(DEFAULT_SCALES if scales is None else scales, dtype=float)
    blade = Blade(params, 0.0)
    fun = energy_function(blade)
    eye = np.eye(6)
    w = 0.5 * (fun.W(0.0, eye * a) + fun.W(0.0, -eye * a))
    ref = float(np.exp(np.mean(np.log(w))))
    return a * np.sqrt(ref / w)


def disturbance_names(test_disturbances) -> tuple[str, ...]:
    """TeX names (without ``$``) of test disturbances along signed axes, ``"+\\beta'"`` etc.

    Each direction is named after its largest component and that component's sign.
    """
    names = []
    for d in np.asarray(test_disturbances, dtype=float):
        k = int(np.argmax(np.abs(d)))
        names.append(("+" if d[k] > 0 else "-") + STATE_LABELS[k].strip("$"))
    return tuple(names)


def _line(*parts) -> str:
    """One printed line, the way ``print(*parts)`` writes it."""
    return " ".join(str(p) for p in parts)
