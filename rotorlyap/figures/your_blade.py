"""What the chapter "Your own blade" prints and draws, so that its cells are calls to the API.

The chapter compares a blade of the reader's own (the *variant*) with the Table I case it
was made from (the *base*). The computations are the package's public ones, called in the
chapter itself (:func:`rotorlyap.derived_quantities`, :func:`rotorlyap.blade_stability`,
:func:`rotorlyap.periodic_motion`); this module only gathers their results into frozen
data objects, each with ``summary()`` (the text the chapter prints) and, where the chapter
quotes numbers in its text, ``facts()`` (``{glue name: value}``, rounded):

* :func:`parameter_changes`: the fields in which the variant differs from the base;
* :func:`refusals`: the messages with which bad parameter values are refused;
* :func:`hover_comparison`: hover trim, equilibrium and linear modes of both blades;
* :func:`both_readings`: the direct method in its practical and strict readings, both blades;
* :func:`worst_state`: where the strict reading found ``W' > 0``;
* :func:`harmonic_data` with :func:`plot_harmonics`: the first harmonics of the periodic
  motion against the advance ratio.

Angles are printed in degrees, rates and frequencies per revolution (units of ``Omega``).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from ..analysis.stability import blade_stability
from ..conventions import HINGES, PAPER_TEST_DISTURBANCES, STATE_NAMES
from ..methods.lyapunov import TechnicalStabilityResult
from ..model.modes import DerivedQuantities, least_damped
from ..model.parameters import BladeParameters, parameter_table
from ..model.steady import PeriodicMotion
from .style import finish, subplots

__all__ = [
    "LABELS", "READINGS",
    "ParameterChanges", "parameter_changes",
    "Refusals", "refusals",
    "HoverSummary", "hover_summary", "HoverComparison", "hover_comparison",
    "Readings", "both_readings",
    "WorstState", "worst_state",
    "HarmonicData", "harmonic_data", "plot_harmonics",
]

LABELS: tuple[str, str] = ("Table I neutral", "variant")
"""Default names of the two blades the chapter compares: the base, then the variant."""

READINGS: tuple[str, str] = ("practical", "strict")
"""The two readings of the direct method, in the order the chapter prints them."""

_COMPONENTS = ("mean", "cos", "sin")
_COMPONENT_LEGEND = (("mean", "-"), ("1st cosine", "--"), ("1st sine", ":"))


# --------------------------------------------------------------------------------------
# Step 1: the parameters
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class ParameterChanges:
    """The fields in which one parameter set differs from another.

    Attributes
    ----------
    rows : tuple of (str, str, str, str)
        ``(field, before, after, unit)`` for each changed field, as text: the parameter
        fields in the order of :func:`rotorlyap.model.parameters.parameter_table` (values as
        that table shows them, units as :data:`~rotorlyap.model.parameters.FIELD_INFO` gives
        them), then the changed real-valued fields of the airfoil model as
        ``airfoil.<name>`` (four significant digits, no unit).
    """

    rows: tuple[tuple[str, str, str, str], ...]

    def summary(self) -> str:
        """``changed fields:`` and one line ``field: before -> after unit`` per change."""
        lines = ["changed fields:"]
        for name, before, after, unit in self.rows:
            lines.append(f"  {name}: {before} -> {after}" + (f" {unit}" if unit else ""))
        return "\n".join(lines)


def parameter_changes(base: BladeParameters, variant: BladeParameters) -> ParameterChanges:
    """The fields of ``variant`` that differ from ``base``, and the changed airfoil coefficients.

    Parameters
    ----------
    base, variant : BladeParameters
        The parameter set started from and the one made from it (``dataclasses.replace``).

    Returns
    -------
    ParameterChanges
        A parameter field counts as changed when its text in the parameter table differs;
        an airfoil coefficient (a real ``__init__`` field of the airfoil model) when its
        value differs.
    """
    before = {name: value for name, value, _unit, _source in parameter_table(base)}
    rows = [(name, str(before[name]), str(value), unit)
            for name, value, unit, _source in parameter_table(variant)
            if str(value) != str(before[name])]
    if dataclasses.is_dataclass(base.airfoil) and type(base.airfoil) is type(variant.airfoil):
        for f in dataclasses.fields(variant.airfoil):
            a, b = getattr(base.airfoil, f.name), getattr(variant.airfoil, f.name)
            if f.init and isinstance(a, float) and a != b:
                rows.append((f"airfoil.{f.name}", f"{a:.4g}", f"{b:.4g}", ""))
    return ParameterChanges(rows=tuple(rows))


@dataclass(frozen=True)
class Refusals:
    """What the parameter checks say about some changes of a parameter set.

    Attributes
    ----------
    changes : tuple of dict
        The changes tried, each ``{field: value}`` (given to ``dataclasses.replace``).
    errors : tuple of (str or None, str or None)
        For each change, the error's type name and message, or ``(None, None)`` if the
        change was accepted.
    """

    changes: tuple[dict, ...]
    errors: tuple[tuple[str | None, str | None], ...]

    def summary(self) -> str:
        """One line per change: ``{change}: ErrorType: message`` (or ``{change}: accepted``)."""
        lines = []
        for change, (kind, message) in zip(self.changes, self.errors):
            lines.append(f"{change}: accepted" if kind is None else f"{change}: {kind}: {message}")
        return "\n".join(lines)


def refusals(params: BladeParameters, changes: Sequence[Mapping]) -> Refusals:
    """Try each change of ``params`` and record how the constructor's checks refuse it.

    Parameters
    ----------
    params : BladeParameters
        The parameter set changed.
    changes : sequence of mapping
        Each ``{field: value}``, applied alone with ``dataclasses.replace``.

    Returns
    -------
    Refusals
        The ``ValueError`` or ``TypeError`` each change raised (any other exception
        propagates).
    """
    errors = []
    for change in changes:
        try:
            dataclasses.replace(params, **change)
        except (ValueError, TypeError) as exc:
            errors.append((type(exc).__name__, str(exc)))
        else:
            errors.append((None, None))
    return Refusals(changes=tuple(dict(c) for c in changes), errors=tuple(errors))


# --------------------------------------------------------------------------------------
# Step 2: what the parameters imply (hover)
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class HoverSummary:
    """The hover quantities the chapter compares, for one blade.

    Attributes
    ----------
    lock_number : float
        ``gamma``, -.
    collective_deg : float
        Collective pitch at the pitch hinge (hover trim), deg.
    coning_deg, lag_angle_deg, pitch_angle_deg : float
        Hover equilibrium with air, flap, lag and pitch hinge angles, deg.
    lag_frequency_vacuum : float
        Lowest natural frequency of the lag modes in vacuum, /rev.
    pitch_frequency_vacuum : float
        Highest natural frequency of the pitch modes in vacuum, /rev.
    largest_growth_rate : float
        Growth rate of the least damped linear mode with air, /rev (negative: it decays).
    least_damped_hinge : str
        ``"flap"``, ``"lag"`` or ``"pitch"``: that mode's dominant hinge.
    """

    lock_number: float
    collective_deg: float
    coning_deg: float
    lag_angle_deg: float
    pitch_angle_deg: float
    lag_frequency_vacuum: float
    pitch_frequency_vacuum: float
    largest_growth_rate: float
    least_damped_hinge: str

    #: Row label of each field in the chapter's table, in order (not a field).
    ROWS: ClassVar[dict[str, str]] = {
        "lock_number": "Lock number",
        "collective_deg": "collective (deg)",
        "coning_deg": "coning (deg)",
        "lag_angle_deg": "lag angle (deg)",
        "pitch_angle_deg": "pitch angle (deg)",
        "lag_frequency_vacuum": "lag frequency, vacuum (/rev)",
        "pitch_frequency_vacuum": "pitch frequency, vacuum (/rev)",
        "largest_growth_rate": "largest growth rate with air (/rev)",
        "least_damped_hinge": "its hinge",
    }


def hover_summary(derived: DerivedQuantities) -> HoverSummary:
    """The compared hover quantities of one blade, from :func:`rotorlyap.derived_quantities`.

    Parameters
    ----------
    derived : DerivedQuantities
        The blade's derived quantities in hover.

    Returns
    -------
    HoverSummary
    """
    worst = least_damped(derived.air_modes)
    return HoverSummary(
        lock_number=float(derived.lock_number),
        collective_deg=float(np.degrees(derived.collective)),
        coning_deg=float(np.degrees(derived.equilibrium[0])),
        lag_angle_deg=float(np.degrees(derived.equilibrium[1])),
        pitch_angle_deg=float(np.degrees(derived.equilibrium[2])),
        lag_frequency_vacuum=float(min(m.natural_frequency for m in derived.modes("lag", air=False))),
        pitch_frequency_vacuum=float(max(m.natural_frequency for m in derived.modes("pitch", air=False))),
        largest_growth_rate=float(worst.growth_rate),
        least_damped_hinge=worst.dominant_hinge,
    )


@dataclass(frozen=True)
class HoverComparison:
    """Hover quantities of the base blade and the variant, side by side.

    Attributes
    ----------
    labels : tuple of 2 str
        Column names: the base blade, then the variant.
    base, variant : HoverSummary
    """

    labels: tuple[str, str]
    base: HoverSummary
    variant: HoverSummary

    def summary(self) -> str:
        """A text table: one row per quantity, numbers to three decimals.

        Each blade's column is one character wider than its label, and at least 10.
        """
        w0, w1 = (max(len(label) + 1, 10) for label in self.labels)
        lines = [f"{'quantity':38s} {self.labels[0]:>{w0}s} {self.labels[1]:>{w1}s}"]
        for name, label in HoverSummary.ROWS.items():
            a, b = getattr(self.base, name), getattr(self.variant, name)
            if isinstance(a, str):
                lines.append(f"{label:38s} {a:>{w0}s} {b:>{w1}s}")
            else:
                lines.append(f"{label:38s} {a:{w0}.3f} {b:{w1}.3f}")
        return "\n".join(lines)

    def facts(self) -> dict:
        """The least damped hover mode of each blade: growth rate (/rev, three decimals) and hinge."""
        return {
            "own_growth_base": round(self.base.largest_growth_rate, 3),
            "own_growth_mine": round(self.variant.largest_growth_rate, 3),
            "own_hinge_base": self.base.least_damped_hinge,
            "own_hinge_mine": self.variant.least_damped_hinge,
        }


def hover_comparison(base: DerivedQuantities, variant: DerivedQuantities,
                     labels: tuple[str, str] = LABELS) -> HoverComparison:
    """Compare the hover quantities of two blades.

    Parameters
    ----------
    base, variant : DerivedQuantities
        :func:`rotorlyap.derived_quantities` of the base blade and of the variant.
    labels : tuple of 2 str
        Their names in the table.

    Returns
    -------
    HoverComparison
    """
    if len(labels) != 2:
        raise ValueError(f"labels must name the two blades (base, variant), got {labels!r}")
    return HoverComparison(labels=tuple(labels), base=hover_summary(base), variant=hover_summary(variant))


# --------------------------------------------------------------------------------------
# Step 3: the direct method in both readings
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Readings:
    """:func:`rotorlyap.blade_stability` for several blades, in the practical and strict readings.

    Attributes
    ----------
    labels : tuple of str
        The blades, in order.
    readings : tuple of str
        :data:`READINGS`.
    results : mapping
        ``{(label, reading): TechnicalStabilityResult}``.
    """

    labels: tuple[str, ...]
    readings: tuple[str, ...]
    results: Mapping[tuple[str, str], TechnicalStabilityResult]

    def __getitem__(self, key: tuple[str, str]) -> TechnicalStabilityResult:
        """The result for ``(label, reading)``."""
        return self.results[key]

    def summary(self) -> str:
        """One line per blade and reading: the bound ``A`` kept after step 3 (three decimals),
        the number of azimuths found stable, and the engine's message."""
        wl = max(len(label) for label in self.labels) + 1
        wr = max(len(reading) for reading in self.readings)
        lines = []
        for label in self.labels:
            for reading in self.readings:
                res = self.results[label, reading]
                lines.append(f"{label:{wl}s} {reading:{wr}s}: A = {res.A:.3f}, stable at "
                             f"{int(res.stable.sum()):2d}/{res.stable.size} azimuths; {res.message}")
        return "\n".join(lines)


def both_readings(base: BladeParameters, variant: BladeParameters, mu: float = 0.0, *,
                  labels: tuple[str, str] = LABELS, test_disturbances=PAPER_TEST_DISTURBANCES,
                  **options) -> Readings:
    """Run :func:`rotorlyap.blade_stability` on both blades in both readings.

    Parameters
    ----------
    base, variant : BladeParameters
        The two blades.
    mu : float
        Advance ratio, -.
    labels : tuple of 2 str
        Their names.
    test_disturbances : array_like, shape (k, 6)
        Directions of the practical reading, scaled coordinates (default: the paper's 12
        signed axes, :data:`rotorlyap.PAPER_TEST_DISTURBANCES`); the strict reading searches
        whole spheres.
    **options
        Passed on to :func:`rotorlyap.blade_stability` (``A``, ``n_psi``, ``n_sphere``, ...).

    Returns
    -------
    Readings
    """
    if len(labels) != 2:
        raise ValueError(f"labels must name the two blades (base, variant), got {labels!r}")
    directions = {"practical": test_disturbances, "strict": None}
    results = {}
    for label, params in zip(labels, (base, variant)):
        for reading in READINGS:
            results[label, reading] = blade_stability(params, mu, test_disturbances=directions[reading], **options)
    return Readings(labels=tuple(labels), readings=READINGS, results=results)


@dataclass(frozen=True)
class WorstState:
    """Where a search found the largest ``W'`` at one azimuth.

    Attributes
    ----------
    psi : float
        The azimuth, rad.
    state : numpy.ndarray
        The disturbance there in units of the norm scales ``a_i`` (``x_i / a_i``), shape (6,),
        components in the order of :data:`rotorlyap.STATE_NAMES`.
    dW : float
        ``W'`` at that state, J/rad.
    """

    psi: float
    state: np.ndarray
    dW: float

    def summary(self) -> str:
        """The azimuth (deg; ``psi = 0`` without a unit), the scaled state to three decimals and
        ``W'`` to three significant digits."""
        deg = float(np.degrees(self.psi))
        where = "psi = 0" if deg == 0.0 else f"psi = {deg:.4g} deg"
        return "\n".join([
            f"worst state at {where}, in units of the scales a_i:",
            "  " + ", ".join(f"{n} {v:+.3f}" for n, v in zip(STATE_NAMES, self.state)),
            f"  W' there = {self.dW:.3g} J/rad",
        ])


def worst_state(result: TechnicalStabilityResult, index: int = 0) -> WorstState:
    """The state with the largest ``W'`` found at the ``index``-th azimuth of a result.

    Parameters
    ----------
    result : TechnicalStabilityResult
        From :func:`rotorlyap.blade_stability`. When nothing was certified (``A`` = 0) its
        ``max_dW`` and ``argmax_dW`` are the evidence of step 3: the positive ``W'`` found on
        the requested sphere.
    index : int
        Azimuth index into ``result.psi``.

    Returns
    -------
    WorstState

    Raises
    ------
    IndexError
        If ``index`` is not an azimuth of the result.
    """
    n = len(result.psi)
    if not -n <= index < n:
        raise IndexError(f"index must be an azimuth index in [0, {n}), got {index}")
    return WorstState(psi=float(result.psi[index]), state=np.asarray(result.argmax_dW[index]) / result.scales,
                      dW=float(result.max_dW[index]))


# --------------------------------------------------------------------------------------
# Step 4: forward flight
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class HarmonicData:
    """Mean and first harmonics of the hinge angles of periodic motions against the advance ratio.

    Attributes
    ----------
    mu : numpy.ndarray
        Advance ratios, -, shape (m,).
    harmonics_deg : numpy.ndarray
        deg, shape (m, 3, 3): advance ratio, hinge (flap, lag, pitch), component (mean, first
        cosine, first sine), as :attr:`rotorlyap.model.steady.PeriodicMotion.harmonics_deg`.
    """

    mu: np.ndarray
    harmonics_deg: np.ndarray

    def export(self) -> dict:
        """The columns for :func:`rotorlyap.figures.export.figure_csv`: ``mu``, then
        ``<hinge>_<mean|cos|sin>_deg`` for flap, lag and pitch."""
        return {"mu": self.mu, **{f"{h}_{c}_deg": self.harmonics_deg[:, k, j]
                                  for k, h in enumerate(HINGES) for j, c in enumerate(_COMPONENTS)}}

    def summary(self) -> str:
        """The advance ratios, then per hinge the (mean, cos, sin) triples, deg to two decimals."""
        lines = [f"mu: {tuple(float(m) for m in self.mu)}"]
        for k, hinge in enumerate(HINGES):
            lines.append(f"{hinge:5s} mean / cos / sin (deg): {np.round(self.harmonics_deg[:, k, :], 2).tolist()}")
        return "\n".join(lines)


def harmonic_data(motions: Sequence[PeriodicMotion]) -> HarmonicData:
    """The harmonics of periodic motions, one per advance ratio.

    Parameters
    ----------
    motions : sequence of PeriodicMotion
        From :func:`rotorlyap.periodic_motion`, in the order to plot.

    Returns
    -------
    HarmonicData

    Raises
    ------
    ValueError
        If ``motions`` is empty.
    """
    if len(motions) == 0:
        raise ValueError("harmonic_data needs at least one periodic motion")
    return HarmonicData(mu=np.array([float(m.mu) for m in motions]),
                        harmonics_deg=np.array([m.harmonics_deg for m in motions]))


def plot_harmonics(data: HarmonicData):
    """Three panels (flap, lag, pitch): mean, first cosine and first sine harmonic against ``mu``.

    Returns
    -------
    matplotlib.figure.Figure
        A new figure, 11 x 3.2 in, already closed in pyplot (so a notebook shows it only
        where it is glued or saved).
    """
    fig, axes = subplots(1, 3, figsize=(11, 3.2), sharex=True)
    for k, (ax, hinge) in enumerate(zip(axes, HINGES)):
        for j, (label, style) in enumerate(_COMPONENT_LEGEND):
            ax.plot(data.mu, data.harmonics_deg[:, k, j], style, marker="o", ms=3, label=label)
        ax.set_title(f"{hinge} angle")
        ax.set_xlabel(r"advance ratio $\mu$")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("harmonic (deg)")
    axes[0].legend(fontsize=8)
    return finish(fig)
