"""What chapters 5 (hover, :mod:`rotorlyap.chapters.hover`) and 6 (forward flight,
:mod:`rotorlyap.chapters.forward_flight`) share, with the inputs of the paper's figures that
the command line (:mod:`rotorlyap.chapters.commands`) also uses: the paper's three cases and
their parameters, Fig. 8's grids of advance ratios and the test-disturbance sets, the labels
of the two readings and of the state components, the norm scales balanced in energy, the
reverse-flow boundary and its mark, and the categories of the region maps with their legend.

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
from ..conventions import DEFAULT_SCALES, PAPER_TEST_DISTURBANCES
from ..methods.sampling import unit_sphere_points
from ..model.blade import Blade
from ..model.parameters import BladeParameters
from .style import CATEGORY_COLORS, CATEGORY_HATCHES, HATCH_COLOR, HATCH_LINEWIDTH

__all__ = [
    "READING_LABELS", "CASES", "MU_GRID", "MU_GRID_STRICT", "STATE_LABELS",
    "FLAP_LAG_TEST_DISTURBANCES", "AXES_AND_DIAGONALS", "CATEGORY_NAMES", "REVERSE_FLOW_HATCH",
    "case_params", "balanced_scales", "reverse_flow_boundary", "disturbance_names",
    "category_legend_handles",
]

#: How each reading is labelled everywhere in the book.
READING_LABELS = {
    "strict": "strict (numerical certificate)",
    "practical": "practical (indicator, not a certificate)",
}

def _plain(tex: str) -> str:
    """A state or axis name of a plot label (``"+\\beta'"``, ``"$\\zeta$"``) in plain text for a
    printout (``"+beta'"``, ``"zeta"``): TeX is for the figures only."""
    return tex.replace("$", "").replace("\\", "")


#: The paper's three cases (Table I computation parameters), in order.
CASES = ("forward", "neutral", "backward")

#: Advance ratios of Fig. 8 in the practical reading: 0 to 0.25, finer near hover.
MU_GRID = (0.0, 0.0125, 0.025, 0.05, 0.075, 0.1, 0.125, 0.15, 0.175, 0.2, 0.225, 0.25)

#: Advance ratios of Fig. 8 in the strict reading (each costs a sphere search per azimuth).
MU_GRID_STRICT = (0.0, 0.05, 0.1, 0.15, 0.2, 0.25)

# TeX labels of the six state components (plot labels; kept out of the API page).
STATE_LABELS = (r"$\beta$", r"$\zeta$", r"$\theta$", r"$\beta'$", r"$\zeta'$", r"$\theta'$")

#: Test disturbances without the pitch rate: the eight signed flap and lag axes.
FLAP_LAG_TEST_DISTURBANCES = PAPER_TEST_DISTURBANCES[[0, 1, 3, 4, 6, 7, 9, 10]]
FLAP_LAG_TEST_DISTURBANCES.setflags(write=False)

#: The 12 signed axes and the 60 signed diagonals of the coordinate planes.
AXES_AND_DIAGONALS = unit_sphere_points(6, 0)

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


def reverse_flow_boundary(params: BladeParameters, psi: np.ndarray) -> np.ndarray:
    """Advance ratio above which reverse flow reaches the blade root, at each azimuth.

    The reverse-flow region is ``r/R < mu |sin psi|`` on the retreating side
    (``180 < psi < 360`` deg); it reaches the aerodynamic span, which starts at
    ``r/R = (R - R1)/R``, when ``mu > (R - R1)/(R |sin psi|)``. Returns ``inf`` on the
    advancing side.
    """
    psi = np.asarray(psi, dtype=float)
    s = -np.sin(psi)
    with np.errstate(divide="ignore"):
        return np.where(s > 1e-12, params.root_r_over_R / np.where(s > 1e-12, s, 1.0), np.inf)


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


#: Categories of a (mu, psi) cell in :class:`rotorlyap.chapters.forward_flight.RegionsData`.
CATEGORY_NAMES = (
    "passes: step 6 holds",
    "step 6 fails at this azimuth",
    "step 3 failed elsewhere (A1 = 0); W' <= 0 here on ||x|| = A",
    "step 3 failed (A1 = 0) and W' > 0 here on ||x|| = A",
)

#: Hatch of the region where reverse flow reaches the blade root, drawn over the verdict maps
#: with an outline: vertical lines, unlike the diagonal and dotted hatches of the verdicts
#: (:data:`rotorlyap.chapters.style.CATEGORY_HATCHES`).
REVERSE_FLOW_HATCH = "||"


def category_legend_handles(reverse_flow_label: str = "reverse flow reaches the blade root", *,
                            wrap: int | None = None) -> list:
    """Legend handles of the region maps: one patch per :data:`CATEGORY_NAMES`, in its colour and
    hatch, and the outlined, hatched reverse-flow region; ``wrap`` breaks the labels into lines
    of at most that many characters."""
    import textwrap

    from matplotlib.patches import Patch

    def lab(text):
        return text if wrap is None else "\n".join(textwrap.wrap(text, wrap))

    handles = [Patch(facecolor=c, hatch=h, edgecolor="0.3", hatchcolor=HATCH_COLOR, lw=0.6, label=lab(n),
                     hatch_linewidth=HATCH_LINEWIDTH)
               for c, h, n in zip(CATEGORY_COLORS, CATEGORY_HATCHES, CATEGORY_NAMES)]
    handles.append(Patch(facecolor="none", edgecolor="k", hatch=REVERSE_FLOW_HATCH, hatchcolor="k", lw=1.5,
                         label=lab(reverse_flow_label)))
    return handles


def _reverse_flow(ax, th, rb, top) -> None:
    """Hatch (:data:`REVERSE_FLOW_HATCH`) and outline the region ``rb <= r <= top`` over the
    azimuths ``th`` where ``rb <= top``: where reverse flow reaches the blade root."""
    import matplotlib.patheffects as pe

    ok = rb <= top
    if not ok.any():
        return
    ax.fill_between(th[ok], rb[ok], top, facecolor="none", edgecolor="k", hatch=REVERSE_FLOW_HATCH, lw=0.0)
    t, r = th[ok], rb[ok]
    # the outline: the boundary, then back along the rim (white-edged, to stand out on any colour)
    ax.plot(np.concatenate([t, np.linspace(t[-1], t[0], 90)]), np.concatenate([r, np.full(90, top)]),
            "k-", lw=1.5, path_effects=[pe.withStroke(linewidth=3.0, foreground="w")], clip_on=False)
