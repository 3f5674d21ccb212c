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
  motion against the advance ratio;
* :func:`read_blade`: a blade from a parameter file, with the fields it left to the template;
* :func:`certificate_table`: certificates (:func:`rotorlyap.certify`) read per hinge;
* :func:`sweep_figure_data` with :func:`plot_sweep`: a sweep
  (:func:`rotorlyap.analysis.sweep.sweep`) over two parameters drawn as linear stability and
  certified start region.

Angles are printed in degrees, rates and frequencies per revolution (units of ``Omega``).
"""

from __future__ import annotations

import dataclasses
import re
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
    "BladeFile", "read_blade", "CertificateTable", "certificate_table",
    "SweepFigureData", "sweep_figure_data", "plot_sweep",
    "mode_summary",
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



_CITATION_KEY = re.compile(r"[A-Za-z][\w:-]*")


def _cited(source: str) -> str:
    """A parameter file's source in the book's table: ``KEY`` or ``KEY; note`` (a citation key of the
    book's bibliography, then what was assumed) as a MyST citation, any other text as it is."""
    key, _, note = (part.strip() for part in source.partition(";"))
    if not _CITATION_KEY.fullmatch(key):
        return source
    return f"{{cite:p}}`{key}`" + (f"; {note}" if note else "")

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
        """The columns for :func:`rotorlyap.chapters.export.figure_csv`: ``mu``, then
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
        A new figure, 9 x 3.2 in, already closed in pyplot (so a notebook shows it only
        where it is glued or saved).
    """
    fig, axes = subplots(1, 3, figsize=(9.0, 3.2), sharex=True)
    for k, (ax, hinge) in enumerate(zip(axes, HINGES)):
        for j, (label, style) in enumerate(_COMPONENT_LEGEND):
            ax.plot(data.mu, data.harmonics_deg[:, k, j], style, marker="os^"[j], ms=4, label=label)
        ax.set_title(f"{hinge} angle", fontsize=10)
        ax.set_xlabel(r"advance ratio $\mu$")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("harmonic (deg)")
    axes[0].legend(fontsize=8.5)
    return finish(fig)


# --------------------------------------------------------------------------------------
# A real blade: its file, its certificates, a sweep
# --------------------------------------------------------------------------------------


#: Units of the field table a reader cannot decode from the symbol alone.
_UNIT_WORDS = {"R1": "× R1 (blade length)"}


@dataclass(frozen=True)
class BladeFile:
    """A blade read from a parameter file, with what the file left to the template.

    Attributes
    ----------
    params : BladeParameters
        The blade.
    name : str
        The file's name (without its folder, so that the chapter prints the same on any machine).
    left_out : tuple of str
        The blade fields the file does not give (they take the Table I template's values).
    warning : str
        The reader's :class:`~rotorlyap.errors.TemplateValuesWarning`, with the file's name only
        ("" if the file gives every blade field).
    sources : dict
        The file's ``[about.sources]``: ``{field: citation}``.
    """

    params: BladeParameters
    name: str
    left_out: tuple[str, ...]
    warning: str
    sources: dict = dataclasses.field(default_factory=dict)

    def markdown(self) -> str:
        """The blade fields as a Markdown table: field, value, unit, and 'given' or the template's source
        (a source that is a citation key, alone or before ``;`` and a note, shown as a citation)."""
        from ..model.parameters import BLADE_FIELDS
        from .export import format_value, markdown_table
        rows = []
        for name, value, unit, source in parameter_table(self.params):  # value: as given, 4 digits
            if name in BLADE_FIELDS:
                origin = (f"template: {source.split(': ', 1)[-1]}" if name in self.left_out else
                          f"the file: {_cited(self.sources[name])}" if name in self.sources else "the file")
                shown = (value if isinstance(value, str) else
                         "(" + ", ".join(f"{v:.4g}" for v in value) + ")" if isinstance(value, tuple) else
                         f"{value:.5g}" if isinstance(value, float) else format_value(value))
                rows.append((f"`{name}`", shown, _UNIT_WORDS.get(unit, unit), origin))
        return markdown_table(("field", "value", "unit", "source"), rows)

    def summary(self) -> str:
        """The file's name, the blade's key numbers and the fields left to the template."""
        p = self.params
        return "\n".join([
            f"{self.name}: R = {p.radius:g} m, c = {p.chord:g} m, {p.n_blades} blades, Omega = {p.rotor_speed:.2f} rad/s, "
            f"{p.helicopter_mass:g} kg",
            f"Lock number {p.lock_number:.1f}, solidity {p.solidity:.4f}, C_T/sigma in hover {p.blade_loading:.3f}",
            f"left to the template: {', '.join(self.left_out) if self.left_out else 'nothing'}",
        ])


def read_blade(path) -> BladeFile:
    """Read a parameter file (:meth:`BladeParameters.from_file`) and keep its template warning.

    Parameters
    ----------
    path : str or pathlib.Path

    Returns
    -------
    BladeFile
    """
    import warnings
    from pathlib import Path

    from ..errors import TemplateValuesWarning
    from ..model.parameters import BLADE_FIELDS

    path = Path(path)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", TemplateValuesWarning)
        params = BladeParameters.from_file(path)
    texts = [str(w.message).replace(str(path), path.name) for w in caught
             if issubclass(w.category, TemplateValuesWarning)]
    import tomllib
    with open(path, "rb") as fh:
        data = tomllib.load(fh)
    sources = dict(data.get("about", {}).get("sources", {}))
    return BladeFile(params=params, name=path.name, left_out=tuple(n for n in BLADE_FIELDS if n not in data),
                     warning="\n".join(texts), sources=sources)


@dataclass(frozen=True)
class CertificateTable:
    """Certificates of one blade at several advance ratios, read per hinge.

    Attributes
    ----------
    certificates : tuple of Certificate
        From :func:`rotorlyap.certify`, in the order to print.
    """

    certificates: tuple

    def markdown(self) -> str:
        """One row per certificate: mu, the verdict, then the start region and the bound along
        the flap, lag and pitch angles (deg, two decimals; "-" where nothing is certified) and the
        largest Floquet real part."""
        from .export import markdown_table
        rows = []
        for c in self.certificates:
            s, b = c.start_region_per_hinge, c.bound_per_hinge
            region = ([f"{s[h][0]:.2f}" for h in HINGES] + [f"{b[h][0]:.2f}" for h in HINGES] if c.certified
                      else ["-"] * 6)
            rows.append((f"{c.mu:g}", "certified" if c.certified else "not certified", *region,
                         f"{c.growth_rate:.3f}"))
        return markdown_table(("mu", "verdict", "start: flap (deg)", "start: lag (deg)", "start: pitch (deg)",
                               "bound: flap (deg)", "bound: lag (deg)", "bound: pitch (deg)",
                               "largest Floquet real part (per rev)"), rows)

    def summary(self) -> str:
        """Each certificate's own three-line summary."""
        return "\n".join(c.summary() for c in self.certificates)

    def facts(self, prefix: str) -> dict:
        """``{prefix_mu<k>_<quantity>: text}``: the verdict, the flap and pitch start balls (deg, two
        decimals), the flap bound (deg) and the flap-rate start ball (deg/s, one decimal), and the
        start set's reach along the flap angle and the flap rate alone (``_flap_set``,
        ``_flap_rate_set``; "–" without a start set), k the advance ratio times 100."""
        out = {}
        for c in self.certificates:
            key = f"{prefix}_mu{round(100 * c.mu):02d}"
            s, b = c.start_region_per_hinge, c.bound_per_hinge
            out[f"{key}_verdict"] = "certified" if c.certified else "not certified"
            out[f"{key}_flap_start"] = f"{s['flap'][0]:.2f}"
            out[f"{key}_flap_rate_start"] = f"{s['flap'][1]:.1f}"
            out[f"{key}_pitch_start"] = f"{s['pitch'][0]:.2f}"
            reach = c.start_set_per_hinge
            out[f"{key}_flap_set"] = f"{reach['flap'][0]:.2f}" if reach else "–"
            out[f"{key}_flap_rate_set"] = f"{reach['flap'][1]:.1f}" if reach else "–"
            out[f"{key}_flap_bound"] = f"{b['flap'][0]:.2f}"
            out[f"{key}_growth"] = f"{c.growth_rate:.3f}"
        return out


def certificate_table(certificates) -> CertificateTable:
    """Gather certificates (:func:`rotorlyap.certify`) for :class:`CertificateTable`.

    Raises
    ------
    ValueError
        If ``certificates`` is empty.
    """
    certificates = tuple(certificates)
    if not certificates:
        raise ValueError("certificate_table needs at least one certificate")
    return CertificateTable(certificates)


@dataclass(frozen=True)
class SweepFigureData:
    """A sweep (:func:`rotorlyap.analysis.sweep.sweep`) over one parameter, one line per value of a
    second: the largest Floquet real part and the certified start region along the flap angle.

    Attributes
    ----------
    x_name, series_name : str
        The swept parameter (x axis) and the one that labels the lines.
    x : numpy.ndarray
        The values of ``x_name``, shape (n,).
    series : tuple
        The values of ``series_name``, one per line.
    growth : numpy.ndarray
        Largest real part of the Floquet exponents, per rev (per radian of azimuth), shape
        (len(series), n).
    start_flap_deg : numpy.ndarray
        Start region along the flap angle, deg (NaN where nothing is certified), same shape.
    certified : numpy.ndarray of bool
        Same shape.
    """

    x_name: str
    series_name: str
    x: np.ndarray
    series: tuple
    growth: np.ndarray
    start_flap_deg: np.ndarray
    certified: np.ndarray

    def export(self) -> dict:
        """Columns for :func:`rotorlyap.chapters.export.figure_csv`: x, then per line its growth
        rate, start region and verdict."""
        out = {self.x_name: self.x}
        for k, s in enumerate(self.series):
            out[f"growth_per_rev_{self.series_name}_{s:g}"] = self.growth[k]
            out[f"start_flap_deg_{self.series_name}_{s:g}"] = self.start_flap_deg[k]
            out[f"certified_{self.series_name}_{s:g}"] = self.certified[k].astype(int)
        return out

    def summary(self) -> str:
        """Per line: the x values certified, the growth rates (3 decimals) and the flap start
        regions (deg, 2 decimals; "–" where nothing is certified)."""
        lines = [f"{self.x_name}: {[float(v) for v in self.x]}"]
        for k, s in enumerate(self.series):
            lines.append(f"{self.series_name} = {s:g}: certified at {[float(v) for v in self.x[self.certified[k]]]}")
            lines.append(f"  growth per rev: {np.round(self.growth[k], 3).tolist()}")
            lines.append("  flap start (deg): [" + ", ".join("–" if not np.isfinite(v) else f"{v:.2f}"
                                                         for v in self.start_flap_deg[k]) + "]")
        return "\n".join(lines)


def sweep_figure_data(result, x_name: str, series_name: str) -> SweepFigureData:
    """Arrange a two-parameter sweep's table for :func:`plot_sweep`.

    Parameters
    ----------
    result : rotorlyap.analysis.sweep.SweepResult
        A full grid over ``x_name`` and ``series_name`` (and nothing else that varies).
    x_name, series_name : str
        Two of its grid columns.

    Returns
    -------
    SweepFigureData

    Raises
    ------
    ValueError
        If a column is missing or the grid is not full.
    """
    for name in (x_name, series_name):
        if name not in result.columns:
            raise ValueError(f"the sweep has no column {name!r}; its columns are {result.columns}")
    xs, ss = result.column(x_name), result.column(series_name)
    x = np.array(sorted(set(xs)), dtype=float)
    series = tuple(sorted(set(ss)))
    shape = (len(series), x.size)
    growth, start, ok = np.full(shape, np.nan), np.full(shape, np.nan), np.zeros(shape, dtype=bool)
    seen = np.zeros(shape, dtype=bool)
    for xv, sv, g, st, c in zip(xs, ss, result.column("growth_rate_per_rev"), result.column("start_flap_deg"),
                                result.column("certified")):
        i, j = series.index(sv), int(np.searchsorted(x, xv))
        seen[i, j] = True
        growth[i, j] = np.nan if g is None else g
        start[i, j] = np.nan if (st is None or not c) else st
        ok[i, j] = bool(c)
    if not seen.all():
        raise ValueError(f"the sweep is not a full grid over {x_name} and {series_name}")
    return SweepFigureData(x_name=x_name, series_name=series_name, x=x, series=series, growth=growth,
                           start_flap_deg=start, certified=ok)


def plot_sweep(data: SweepFigureData, *, x_label: str, series_label: str):
    """Two panels against the swept parameter: (a) the largest Floquet real part (per rev; above 0
    the linearised blade is unstable and nothing can be certified), (b) the certified start region
    along the flap angle (deg); filled markers certified, crosses not. One line per series value,
    told apart by colour, marker and line style.

    Returns
    -------
    matplotlib.figure.Figure
        7.5 x 3 in, closed in pyplot.
    """
    fig, (ax1, ax2) = subplots(1, 2, figsize=(7.5, 3.0), sharex=True)
    styles = (("C0", "o", "-"), ("C1", "s", "--"), ("C2", "^", ":"), ("C3", "D", "-."))
    for k, s in enumerate(data.series):
        colour, marker, line = styles[k % len(styles)]
        label = f"{series_label} = {s:g}"
        ax1.plot(data.x, data.growth[k], line, color=colour, marker=marker, ms=4, label=label)
        ax2.plot(data.x, data.start_flap_deg[k], line, color=colour, lw=1)
        ok = data.certified[k]
        ax2.plot(data.x[ok], data.start_flap_deg[k][ok], marker, color=colour, ms=5, ls="none")
        # not certified: no start region to draw; a cross on the axis marks the point
        ax2.plot(data.x[~ok], np.zeros(int((~ok).sum())), "x", color=colour, ms=7, mew=1.5, ls="none",
                 clip_on=False, zorder=5)
    ax1.axhline(0.0, color="k", lw=0.8)
    ax1.set_ylabel("largest Floquet real part (per rev)")
    ax1.set_title("(a) linear stability", fontsize=10)
    ax2.set_ylabel("certified flap start region (deg)")
    ax2.set_title("(b) the certificate (x on the axis: not certified)", fontsize=10)
    for ax in (ax1, ax2):
        ax.set_xlabel(x_label)
        ax.grid(alpha=0.3)
    ax2.set_ylim(bottom=0.0)
    ax1.legend(fontsize=8)
    return finish(fig)


def mode_summary(data) -> str:
    """The modes of a fan plot or of a Floquet sweep as chapter 11 prints them, in words.

    The book keeps one symbol for one quantity: zeta is the lag angle and sigma the solidity,
    so a mode's damping ratio and its growth rate are named, not given those symbols, as the
    ``summary`` methods of :mod:`rotorlyap.analysis.modes` print them (this returns that summary).

    Parameters
    ----------
    data : rotorlyap.analysis.modes.FanData or rotorlyap.analysis.modes.FloquetModes
        From :func:`rotorlyap.fan_plot` (hover modes against the rotor speed: frequency per rev
        and damping ratio, three decimals) or :func:`rotorlyap.floquet_modes` (Floquet modes
        against the advance ratio: frequency and growth rate per rev, three decimals).

    Returns
    -------
    str
        A title line, then one line per rotor speed or advance ratio.
    """
    return data.summary()
