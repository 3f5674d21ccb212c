"""The frequencies and damping of a blade's modes: against rotor speed (hover) and advance ratio (Floquet).

Two pure functions, each returning a frozen data object with ``export()`` (one record per mode,
for a CSV or JSON table) and ``summary()``:

:func:`fan_plot`
    the linear modes of the hover equilibrium (:func:`rotorlyap.model.modes.hover_modes`) at
    each of several rotor speeds: the fan diagram. At each rotor speed the blade is the one given
    with ``rotor_speed`` replaced, so a blade whose ``collective`` is None is trimmed at every
    speed to carry the helicopter's weight (the rotor speed changes, the helicopter hovers), and a
    given collective is kept. With ``air=False`` the modes are those in vacuum at the collective
    trimmed at the blade's own (nominal) rotor speed: the classical fan diagram of the hinges'
    springs, centrifugal and inertial forces. A rotor speed at which the hover trim or
    equilibrium is not found is kept as a row with its message (nothing else is lost).
:func:`floquet_modes`
    the Floquet modes of the periodic motion of the trimmed helicopter
    (:func:`rotorlyap.model.forward_trim.forward_flight_trim`) at each advance ratio, followed by
    continuity from hover by :func:`rotorlyap.analysis.floquet.floquet_sweep` on a grid refined
    to steps of at most ``max_step`` (the frequency of a Floquet exponent is known modulo 1/rev;
    continuity from hover, where it is the true one, fixes the branch). At ``mu = 0`` the
    exponents are the eigenvalues of the hover Jacobian.

Units: rotor speeds in rad/s; frequencies per revolution (units of the rotor speed Omega: an
eigenvalue ``s`` of the azimuth-form equations means ``exp(s Omega t)``) and in Hz
(``frequency_per_rev * Omega / (2 pi)``); growth rates per revolution (per radian of azimuth,
negative = decaying); damping ratios ``-Re s / |s|``, dimensionless.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, replace

import numpy as np

from ..conventions import MAX_ADVANCE_RATIO, TWO_PI
from ..errors import ConvergenceError, TemplateValuesWarning
from ..model.blade import Blade
from ..model.forward_trim import TRIM_TARGETS, forward_flight_trim
from ..model.modes import Mode, modes_from_jacobian
from ..model.parameters import BladeParameters
from .floquet import DEFAULT_N_STEPS, floquet_sweep

__all__ = ["MODE_COLUMNS", "FanData", "FloquetModes", "fan_plot", "floquet_modes"]

MODE_COLUMNS: tuple[str, ...] = (
    "kind", "rotor_speed_rad_s", "rotor_speed_ratio", "mu", "mode", "hinge", "frequency_per_rev",
    "frequency_hz", "growth_rate_per_rev", "damping_ratio", "error")
"""The columns of :meth:`FanData.export` and :meth:`FloquetModes.export`, in order: ``kind``
(``"hover"`` for the fan diagram, ``"floquet"``), the rotor speed (rad/s, and over the blade's
nominal one), the advance ratio, the mode's name and dominant hinge, its frequency (per rev and
Hz), growth rate (per rev), damping ratio (-), and ``error`` (why a point has no modes, else
empty)."""


def _record(kind: str, omega: float, nominal: float, mu: float, mode: str, hinge: str, freq: float,
            growth: float, zeta: float, error: str = "") -> dict:
    return {"kind": kind, "rotor_speed_rad_s": float(omega), "rotor_speed_ratio": float(omega / nominal),
            "mu": float(mu), "mode": mode, "hinge": hinge, "frequency_per_rev": float(freq),
            "frequency_hz": float(freq * omega / TWO_PI), "growth_rate_per_rev": float(growth),
            "damping_ratio": float(zeta), "error": error}


# --------------------------------------------------------------------------------------
# The fan diagram
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class FanData:
    """The hover modes of a blade at several rotor speeds (:func:`fan_plot`).

    Attributes
    ----------
    nominal_rotor_speed : float
        The blade's own ``rotor_speed``, rad/s.
    rotor_speed : numpy.ndarray
        The rotor speeds, rad/s, shape (k,), increasing.
    air : bool
        True: with air (the hover trim at each speed); False: in vacuum.
    modes : tuple of tuple of Mode
        The modes at each rotor speed (:func:`rotorlyap.model.modes.modes_from_jacobian`: a
        complex pair once, ordered flap, lag, pitch); empty where none were found.
    collective : numpy.ndarray
        Collective pitch of the equilibrium at each speed, rad (NaN where not found).
    messages : tuple of str
        Why no modes at a rotor speed (empty strings where found).
    """

    nominal_rotor_speed: float
    rotor_speed: np.ndarray
    air: bool
    modes: tuple[tuple[Mode, ...], ...]
    collective: np.ndarray
    messages: tuple[str, ...]

    @property
    def found(self) -> np.ndarray:
        """Boolean per rotor speed: the modes were found."""
        return np.array([not m for m in self.messages], dtype=bool)

    def names(self, i: int) -> tuple[str, ...]:
        """The names of the modes at rotor speed ``i``: the dominant hinge, numbered from 1 in
        their order when a hinge dominates several (``"lag1"``, ``"lag2"``)."""
        hinges = [m.dominant_hinge for m in self.modes[i]]
        return tuple(h if hinges.count(h) == 1 else f"{h}{hinges[:k + 1].count(h)}"
                     for k, h in enumerate(hinges))

    def frequency_hz(self, i: int) -> np.ndarray:
        """The damped frequencies of the modes at rotor speed ``i``, Hz."""
        return np.array([m.frequency for m in self.modes[i]]) * self.rotor_speed[i] / TWO_PI

    def export(self) -> list[dict]:
        """One record per mode and rotor speed (:data:`MODE_COLUMNS`, ``kind = "hover"``, ``mu = 0``);
        a rotor speed without modes is one record with NaN numbers and its ``error``."""
        rows = []
        kind = "hover" if self.air else "vacuum"
        for i, omega in enumerate(self.rotor_speed):
            if self.messages[i]:
                rows.append(_record(kind, omega, self.nominal_rotor_speed, 0.0, "", "", math.nan, math.nan,
                                    math.nan, self.messages[i]))
                continue
            for name, m in zip(self.names(i), self.modes[i]):
                rows.append(_record(kind, omega, self.nominal_rotor_speed, 0.0, name, m.dominant_hinge,
                                    m.frequency, m.growth_rate, m.damping_ratio))
        return rows

    def summary(self) -> str:
        """One line per rotor speed: each mode's frequency (/rev) and damping ratio (in words, not
        the symbols zeta and sigma, which are the lag angle and the solidity)."""
        lines = [f"hover modes {'with air' if self.air else 'in vacuum'} against rotor speed "
                 f"(nominal {self.nominal_rotor_speed:.4g} rad/s): frequency, damping ratio"]
        for i, omega in enumerate(self.rotor_speed):
            if self.messages[i]:
                lines.append(f"  {omega:8.4g} rad/s: not found ({self.messages[i]})")
                continue
            text = ", ".join(f"{n} {m.frequency:.3f}/rev, {m.damping_ratio:.3f}"
                             for n, m in zip(self.names(i), self.modes[i]))
            lines.append(f"  {omega:8.4g} rad/s: {text}")
        return "\n".join(lines)


def fan_plot(params: BladeParameters, rotor_speeds, *, air: bool = True) -> FanData:
    """The blade's hover modes (frequency, damping) at each rotor speed: the fan diagram's data.

    Parameters
    ----------
    params : BladeParameters
        The blade. Its ``collective``: None trims the hover collective (thrust = weight) at
        each rotor speed; a value is kept at every speed.
    rotor_speeds : array_like
        Rotor speeds, rad/s, positive, finite, increasing (each must keep the tip below the speed
        of sound, as :class:`~rotorlyap.model.parameters.BladeParameters` requires).
    air : bool
        True (default): the modes with air at the hover equilibrium, as
        :func:`rotorlyap.model.modes.hover_modes` (equal to it at the blade's own rotor speed).
        False: in vacuum (``air_density = 0``), at the collective of the hover trim at the blade's
        own rotor speed (or the given collective).

    Returns
    -------
    FanData

    Raises
    ------
    ValueError
        Rotor speeds that are not positive, finite and increasing, or that the parameter checks
        refuse (a tip speed at or above the speed of sound); ``air=False`` with a collective None
        whose nominal hover trim fails.
    """
    speeds = np.atleast_1d(np.asarray(rotor_speeds, dtype=float))
    if speeds.ndim != 1 or speeds.size == 0:
        raise ValueError(f"rotor_speeds must be a non-empty list of rotor speeds in rad/s, got {rotor_speeds!r}")
    if not (np.all(np.isfinite(speeds)) and np.all(speeds > 0.0)):
        raise ValueError(f"rotor_speeds must be positive and finite, rad/s, got {speeds.tolist()}")
    if np.any(np.diff(speeds) <= 0.0):
        raise ValueError(f"rotor_speeds must increase, got {speeds.tolist()}")
    base = params
    if not air:
        if params.collective is None:
            try:
                base = Blade(params).params  # the hover collective at the nominal rotor speed
            except ConvergenceError as exc:
                raise ValueError(f"fan_plot(air=False) needs the hover collective at the nominal rotor "
                                 f"speed, and its trim failed: {exc}") from exc
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", TemplateValuesWarning)
            base = replace(base, air_density=0.0)
    modes, collective, messages = [], [], []
    for omega in speeds:
        with warnings.catch_warnings():  # the blade given, at another speed: its template fields are its own
            warnings.simplefilter("ignore", TemplateValuesWarning)
            p = replace(base, rotor_speed=float(omega))  # the parameter checks refuse a bad speed (ValueError)
        try:
            blade = Blade(p)  # trims the collective if it is None
            z = blade.equilibrium()
            modes.append(modes_from_jacobian(blade.jacobian(0.0, z)))  # as hover_modes(p)
            collective.append(float(blade.params.collective))
            messages.append("")
        except ConvergenceError as exc:
            modes.append(())
            collective.append(math.nan)
            messages.append(" ".join(str(exc).split()))
    return FanData(nominal_rotor_speed=float(params.rotor_speed), rotor_speed=speeds, air=bool(air),
                   modes=tuple(modes), collective=np.array(collective), messages=tuple(messages))


# --------------------------------------------------------------------------------------
# Floquet modes of the trimmed periodic motion
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class FloquetModes:
    """The Floquet modes of the trimmed blade's periodic motion against the advance ratio
    (:func:`floquet_modes`).

    Attributes
    ----------
    condition : str
        The flight condition of the trim, one of
        :data:`rotorlyap.model.forward_trim.TRIM_TARGETS`.
    rotor_speed : float
        rad/s.
    mu : numpy.ndarray
        The advance ratios asked for, shape (k,).
    names : tuple of str
        The modes, one per complex pair or real exponent, named from their dominant hinge in
        hover (:class:`rotorlyap.analysis.floquet.FloquetSweep`; ``"pitch+"`` is the pair of the
        pitch mode).
    frequency : numpy.ndarray
        Frequency with the branch followed from hover, per rev, shape (k, len(names)).
    growth_rate : numpy.ndarray
        Real part of the exponent, per rev, same shape (negative = decaying).
    damping_ratio : numpy.ndarray
        ``-sigma / |eta|``, -, same shape.
    dominant : numpy.ndarray
        Dominant hinge of each mode at each advance ratio (strings), same shape.
    found : numpy.ndarray
        Boolean, shape (k,): the trim and its periodic motion were found.
    messages : tuple of str
        Why not, per advance ratio (empty where found).
    """

    condition: str
    rotor_speed: float
    mu: np.ndarray
    names: tuple[str, ...]
    frequency: np.ndarray
    growth_rate: np.ndarray
    damping_ratio: np.ndarray
    dominant: np.ndarray
    found: np.ndarray
    messages: tuple[str, ...]

    @property
    def frequency_hz(self) -> np.ndarray:
        """``frequency`` in Hz."""
        return self.frequency * self.rotor_speed / TWO_PI

    @property
    def stable(self) -> np.ndarray:
        """Boolean per advance ratio: every exponent decays (False where not found)."""
        with np.errstate(invalid="ignore"):
            return self.found & np.all(self.growth_rate < 0.0, axis=1)

    def export(self) -> list[dict]:
        """One record per mode and advance ratio (:data:`MODE_COLUMNS`, ``kind = "floquet"``); an
        advance ratio without a trim is one record with NaN numbers and its ``error``."""
        rows = []
        omega = self.rotor_speed
        for i, mu in enumerate(self.mu):
            if not self.found[i]:
                rows.append(_record("floquet", omega, omega, mu, "", "", math.nan, math.nan, math.nan,
                                    self.messages[i]))
                continue
            for j, name in enumerate(self.names):
                rows.append(_record("floquet", omega, omega, mu, name, str(self.dominant[i, j]),
                                    self.frequency[i, j], self.growth_rate[i, j], self.damping_ratio[i, j]))
        return rows

    def summary(self) -> str:
        """One line per advance ratio: each mode's frequency and growth rate (both per rev)."""
        lines = [f"Floquet modes of the {self.condition} trim against the advance ratio: "
                 "frequency, growth rate (both per rev)"]
        for i, mu in enumerate(self.mu):
            if not self.found[i]:
                lines.append(f"  mu = {mu:.4g}: not found ({self.messages[i]})")
                continue
            text = ", ".join(f"{n} {self.frequency[i, j]:.3f}, {self.growth_rate[i, j]:+.3f}"
                             for j, n in enumerate(self.names))
            lines.append(f"  mu = {mu:.4g}: {text}")
        return "\n".join(lines)


def floquet_modes(params: BladeParameters, mu_values, *, condition: str = "propulsive",
                  max_step: float = 0.025, n_steps: int = DEFAULT_N_STEPS) -> FloquetModes:
    """Floquet modes of the trimmed blade's periodic motion at each advance ratio.

    Parameters
    ----------
    params : BladeParameters
        The blade and helicopter.
    mu_values : array_like
        Advance ratios, in ``[0, MAX_ADVANCE_RATIO]``, increasing.
    condition : str
        The trim, one of :data:`rotorlyap.model.forward_trim.TRIM_TARGETS` (default the trimmed
        helicopter).
    max_step : float
        Largest step of the grid along which the modes are followed from hover (the grid holds
        ``mu_values`` and is refined between them; its extra points are not reported).
    n_steps : int
        Magnus steps per revolution of the monodromy matrix.

    Returns
    -------
    FloquetModes
        An advance ratio whose trim fails is kept with its message (``found`` False).

    Raises
    ------
    ValueError
        Bad advance ratios, ``condition`` or ``max_step``.
    """
    if condition not in TRIM_TARGETS:
        raise ValueError(f"condition must be one of {TRIM_TARGETS}, got {condition!r}")
    mu = np.atleast_1d(np.asarray(mu_values, dtype=float))
    if mu.ndim != 1 or mu.size == 0 or not np.all(np.isfinite(mu)):
        raise ValueError(f"mu_values must be a non-empty list of finite advance ratios, got {mu_values!r}")
    if np.any(mu < 0.0) or np.any(mu > MAX_ADVANCE_RATIO) or np.any(np.diff(mu) <= 0.0):
        raise ValueError(f"mu_values must increase within [0, {MAX_ADVANCE_RATIO:g}], got {mu.tolist()}")
    if not (math.isfinite(max_step) and max_step > 0.0):
        raise ValueError(f"max_step must be a positive advance ratio, got {max_step!r}")
    # the tracking grid: 0, the values asked for, and points between them at most max_step apart
    knots = np.unique(np.concatenate([[0.0], mu]))
    grid = [0.0]
    for a, b in zip(knots[:-1], knots[1:]):
        n = max(1, int(math.ceil((b - a) / max_step - 1e-9)))
        grid.extend(a + (b - a) * np.arange(1, n + 1) / n)
    grid = np.array(grid)
    grid[np.searchsorted(grid, mu - 1e-12)] = mu  # the values asked for exactly
    motions, blades = {}, {}
    for m in grid:
        try:
            trim = forward_flight_trim(params, float(m), condition)
        except ConvergenceError as exc:
            motions[float(m)] = " ".join(str(exc).split())
            continue
        motions[float(m)] = trim.steady
        blades[float(m)] = trim.params
    fs = floquet_sweep(params, grid, case=condition, n_steps=n_steps, motions=motions, blades=blades)
    rows = np.searchsorted(fs.mu, mu - 1e-12)
    keep = [j for j, n in enumerate(fs.names) if not n.endswith("-")]
    return FloquetModes(
        condition=condition, rotor_speed=float(params.rotor_speed), mu=mu,
        names=tuple(fs.names[j] for j in keep),
        frequency=fs.frequency[np.ix_(rows, keep)], growth_rate=fs.growth_rate[np.ix_(rows, keep)],
        damping_ratio=fs.damping_ratio[np.ix_(rows, keep)], dominant=fs.dominant[np.ix_(rows, keep)],
        found=fs.found[rows].copy(), messages=tuple(fs.messages[r] for r in rows))
