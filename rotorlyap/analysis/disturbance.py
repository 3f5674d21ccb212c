"""The nonlinear motion of the trimmed blade after a disturbance, with the certificate's bound.

:func:`simulate_disturbance` trims the helicopter at an advance ratio
(:func:`rotorlyap.model.forward_trim.forward_flight_trim`), takes the blade's steady motion of
that trim (the hover state, or the periodic motion), adds a disturbance of the hinge angles (and
rates) at azimuth 0 and integrates the full nonlinear equations of the disturbed motion
(:func:`rotorlyap.model.steady.disturbed_rhs`, :func:`rotorlyap.methods.simulation.simulate`).
The result holds the hinge angles (steady, disturbed, and their difference) in degrees against
revolutions, the scaled norm of the difference, and, if a :class:`rotorlyap.Certificate` of the
same trim is given, the certificate's bound per hinge: a disturbance inside its start region
keeps the difference of each hinge angle within ``a_i A`` degrees for ever.

Units: angles in deg, rates in deg/s, time in revolutions (``psi / 2 pi``) and seconds.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from ..conventions import DEFAULT_SCALES, HINGES, TWO_PI
from ..methods.simulation import simulate
from ..model.blade import Blade
from ..model.forward_trim import TRIM_TARGETS, forward_flight_trim
from ..model.parameters import BladeParameters
from ..model.steady import disturbed_rhs, tabulate_motion

__all__ = ["DISTURBANCE_NAMES", "DisturbedMotion", "simulate_disturbance"]

DISTURBANCE_NAMES: tuple[str, ...] = HINGES + tuple(f"{h}_rate" for h in HINGES)
"""The keys of a disturbance: the hinge angles (rad) and their rates (rad/s)."""


@dataclass(frozen=True)
class DisturbedMotion:
    """The trimmed blade's motion after a disturbance (:func:`simulate_disturbance`).

    Attributes
    ----------
    mu : float
        Advance ratio, -.
    condition : str
        The trim, one of :data:`rotorlyap.model.forward_trim.TRIM_TARGETS`.
    rotor_speed : float
        rad/s.
    disturbance : numpy.ndarray
        The disturbance at azimuth 0: hinge angles (deg) and rates (deg/s), shape (6,).
    revolutions : numpy.ndarray
        Time in revolutions, ``psi / (2 pi)``, shape (k,).
    steady_deg : numpy.ndarray
        The steady motion's hinge angles, deg, shape (k, 3) (flap, lag, pitch).
    angles_deg : numpy.ndarray
        The disturbed motion's hinge angles, deg, shape (k, 3).
    norm : numpy.ndarray
        Scaled norm of the difference (the certificate's norm, scales ``scales``), shape (k,).
    scales : numpy.ndarray
        The norm's scales ``a_i``, rad and rad/rad, shape (6,).
    escaped : bool
        The integration stopped early because the scaled norm passed ``escape``.
    certified : bool or None
        The certificate's verdict (None: no certificate given).
    bound_deg : numpy.ndarray or None
        The certificate's bound along each hinge angle, ``a_i A`` in deg, shape (3,) (None: no
        certificate, or nothing certified).
    start_region : float or None
        The certificate's start radius, scaled norm (None as for ``bound_deg``).
    """

    mu: float
    condition: str
    rotor_speed: float
    disturbance: np.ndarray
    revolutions: np.ndarray
    steady_deg: np.ndarray
    angles_deg: np.ndarray
    norm: np.ndarray
    scales: np.ndarray
    escaped: bool
    certified: bool | None = None
    bound_deg: np.ndarray | None = None
    start_region: float | None = None

    @property
    def deviation_deg(self) -> np.ndarray:
        """The disturbed minus the steady hinge angles, deg, shape (k, 3)."""
        return self.angles_deg - self.steady_deg

    @property
    def time_s(self) -> np.ndarray:
        """Time, s: ``revolutions * 2 pi / rotor_speed``."""
        return self.revolutions * TWO_PI / self.rotor_speed

    @property
    def start_norm(self) -> float:
        """Scaled norm of the disturbance."""
        return float(self.norm[0])

    @property
    def inside_start_region(self) -> bool | None:
        """The disturbance lies inside the certificate's start region (None without one)."""
        return None if self.start_region is None else bool(self.start_norm <= self.start_region)

    def export(self) -> list[dict]:
        """One record per output time: ``revolution``, ``time_s``, per hinge ``<hinge>_deg`` (the
        disturbed angle), ``<hinge>_steady_deg`` and ``<hinge>_deviation_deg``, ``scaled_norm``, and
        with a certified certificate ``<hinge>_bound_deg`` (the same on every row)."""
        rows = []
        dev = self.deviation_deg
        t = self.time_s
        for k, rev in enumerate(self.revolutions):
            row = {"revolution": float(rev), "time_s": float(t[k])}
            for i, h in enumerate(HINGES):
                row[f"{h}_deg"] = float(self.angles_deg[k, i])
                row[f"{h}_steady_deg"] = float(self.steady_deg[k, i])
                row[f"{h}_deviation_deg"] = float(dev[k, i])
            row["scaled_norm"] = float(self.norm[k])
            if self.bound_deg is not None:
                for i, h in enumerate(HINGES):
                    row[f"{h}_bound_deg"] = float(self.bound_deg[i])
            rows.append(row)
        return rows

    def summary(self) -> str:
        """The disturbance, the largest and last deviation per hinge (deg), and the certificate."""
        dev = np.abs(self.deviation_deg)
        lines = [f"mu = {self.mu:g}, {self.condition}: disturbance "
                 + ", ".join(f"{n} {v:.3g} {'deg' if i < 3 else 'deg/s'}"
                             for i, (n, v) in enumerate(zip(DISTURBANCE_NAMES, self.disturbance)) if v != 0.0)
                 + f" (scaled norm {self.start_norm:.3g}), {self.revolutions[-1]:.3g} revolutions"
                 + (" (stopped: the motion left the escape radius)" if self.escaped else "")]
        for i, h in enumerate(HINGES):
            lines.append(f"  {h}: largest deviation {dev[:, i].max():.3g} deg, last {dev[-1, i]:.3g} deg"
                         + ("" if self.bound_deg is None else f", bound {self.bound_deg[i]:.3g} deg"))
        if self.certified is not None:
            if self.bound_deg is None:
                lines.append("  the certificate certifies nothing here")
            else:
                lines.append(f"  inside the certificate's start region: {self.inside_start_region}")
        return "\n".join(lines)


def _disturbance_vector(disturbance: Mapping, omega: float) -> np.ndarray:
    """The state disturbance (rad and rad per rad of azimuth) of ``{name: rad or rad/s}``."""
    if not isinstance(disturbance, Mapping) or not disturbance:
        raise ValueError("disturbance must be a non-empty mapping {name: value} with names in "
                         f"{DISTURBANCE_NAMES} (angles in rad, rates in rad/s), got {disturbance!r}")
    x0 = np.zeros(6)
    for name, value in disturbance.items():
        if name not in DISTURBANCE_NAMES:
            raise ValueError(f"unknown disturbance {name!r}: the names are {', '.join(DISTURBANCE_NAMES)}")
        v = float(value)
        if not math.isfinite(v):
            raise ValueError(f"disturbance {name} must be finite, got {value!r}")
        i = DISTURBANCE_NAMES.index(name)
        x0[i] = v if i < 3 else v / omega  # d/dpsi = (d/dt) / Omega
    return x0


def simulate_disturbance(params: BladeParameters, mu: float, disturbance: Mapping[str, float],
                         n_revs: float = 10.0, *, condition: str = "propulsive", certificate=None,
                         scales=None, points_per_rev: int = 72, escape: float = 100.0) -> DisturbedMotion:
    """The nonlinear motion of the trimmed blade from a disturbance of its steady motion.

    Parameters
    ----------
    params : BladeParameters
        The blade and helicopter.
    mu : float
        Advance ratio, in ``[0, MAX_ADVANCE_RATIO]``.
    disturbance : mapping
        ``{name: value}`` at azimuth 0, names in :data:`DISTURBANCE_NAMES`: ``"flap"``, ``"lag"``,
        ``"pitch"`` (rad) and ``"flap_rate"``, ``"lag_rate"``, ``"pitch_rate"`` (rad/s); the others
        are zero.
    n_revs : float
        Length of the motion, revolutions (> 0).
    condition : str
        The trim, one of :data:`rotorlyap.model.forward_trim.TRIM_TARGETS`.
    certificate : rotorlyap.Certificate, optional
        A certificate of the same blade, advance ratio and condition (:func:`rotorlyap.certify`);
        its bound per hinge is then recorded (``bound_deg``) and its scales are the norm's.
    scales : array_like, optional
        The norm's scales ``a_i`` (rad, rad/rad) without a certificate (default
        :data:`rotorlyap.conventions.DEFAULT_SCALES`).
    points_per_rev : int
        Output points per revolution.
    escape : float
        Stop when the scaled norm of the difference passes this value (an unstable motion).

    Returns
    -------
    DisturbedMotion

    Raises
    ------
    ValueError
        Bad ``mu``, ``condition``, ``n_revs`` or disturbance, or a certificate of another case.
    rotorlyap.errors.TrimError
        If the trim does not converge.
    """
    if condition not in TRIM_TARGETS:
        raise ValueError(f"condition must be one of {TRIM_TARGETS}, got {condition!r}")
    n_revs = float(n_revs)
    if not (math.isfinite(n_revs) and n_revs > 0.0):
        raise ValueError(f"n_revs must be a positive number of revolutions, got {n_revs!r}")
    if int(points_per_rev) < 4:
        raise ValueError(f"points_per_rev must be at least 4, got {points_per_rev!r}")
    trim = forward_flight_trim(params, float(mu), condition)
    if certificate is not None:
        if (certificate.mu != trim.mu or certificate.condition != condition
                or certificate.trim.params != trim.params):
            raise ValueError(f"the certificate is of another case (mu = {certificate.mu:g}, "
                             f"{certificate.condition}), not of this blade at mu = {trim.mu:g}, {condition}")
        a = np.asarray(certificate.scales, dtype=float)
    else:
        a = np.asarray(DEFAULT_SCALES if scales is None else scales, dtype=float)
    if a.shape != (6,) or not np.all(a > 0.0):
        raise ValueError(f"scales must be 6 positive numbers (rad, rad/rad), got {a!r}")
    omega = trim.params.rotor_speed
    x0 = _disturbance_vector(disturbance, omega)
    steady = trim.steady if trim.mu == 0.0 else tabulate_motion(trim.motion).steady
    blade = Blade(trim.params, trim.mu)
    res = simulate(disturbed_rhs(blade, steady), x0, 0.0, n_revs, scales=a, points_per_period=int(points_per_rev),
                   escape=float(escape), rtol=1e-8, atol=1e-10)
    psi = res.psi
    xi = steady.xi(psi)
    x = res.x[:, 0, :]
    bound = start = None
    if certificate is not None and certificate.certified:
        bound = np.degrees(a[:3]) * float(certificate.bound)
        start = float(certificate.start_region)
    rates = np.degrees(x0[3:]) * omega
    return DisturbedMotion(
        mu=trim.mu, condition=condition, rotor_speed=omega,
        disturbance=np.concatenate([np.degrees(x0[:3]), rates]),
        revolutions=psi / TWO_PI, steady_deg=np.degrees(xi[:, :3]), angles_deg=np.degrees(xi[:, :3] + x[:, :3]),
        norm=res.norm[:, 0], scales=a, escaped=bool(res.escaped[0]),
        certified=None if certificate is None else bool(certificate.certified), bound_deg=bound, start_region=start)
