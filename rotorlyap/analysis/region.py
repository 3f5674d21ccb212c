"""The blade's region of stable motion found by simulation: the yardstick of every certificate.

:func:`stable_region` sets up exactly the steady motion :func:`rotorlyap.certify` certifies (the
trimmed hover state, or in forward flight the trimmed periodic motion, tabulated) and measures,
with :mod:`rotorlyap.methods.region`, how large a disturbance the full nonlinear blade survives:

* the **extent** along the 12 signed single-hinge directions (each hinge angle and each hinge
  rate alone, + and -), in the scaled norm, the smallest over the start azimuths (hover: one,
  the system is autonomous; forward flight: four, 0, 90, 180 and 270 deg);
* per hinge, in degrees and degrees per second, in the layout of
  :attr:`rotorlyap.analysis.certify.Certificate.start_region_per_hinge`, so that a certificate's
  start region and the yardstick can be set side by side;
* optionally two slices: verdicts on a grid of starts in the plane of the flap and lag angles,
  and of the flap and pitch angles, at the azimuth 0.

Definition (:mod:`rotorlyap.methods.region`): the state ``x`` is the disturbance from the
steady motion, ``(beta, zeta, theta, beta', zeta', theta')`` in rad and rad/rad (derivatives
with respect to the azimuth ``psi = Omega t``), measured in the scaled norm ``||x|| = |x / a|``
with ``a`` = :data:`rotorlyap.conventions.DEFAULT_SCALES`. A start ``x0`` at the azimuth
``psi0`` is *stable* (it returns) if over a horizon of ``n_periods`` revolutions (1) the motion
never leaves ``||x(psi)|| <= bound`` (default 45: 90 deg of flap) and (2) the largest ``||x||``
over its last revolution is at most ``decay`` (default 0.5) times ``||x0||``. The horizon is
``max(10, ceil(2 ln(1/decay) / (2 pi |sigma|)))`` revolutions, at most 100, with ``sigma`` the
largest real part of the Floquet exponents about the steady motion (per rad of azimuth).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..conventions import DEFAULT_SCALES, HINGES, PAPER_TEST_DISTURBANCES, STATE_NAMES, TWO_PI
from ..errors import NotAsymptoticallyStableError
from ..methods.region import (
    DEFAULT_BOUND, DEFAULT_DECAY, DEFAULT_STEPS_PER_PERIOD, MAX_PERIODS, RayExtent, SliceMap, horizon,
    ray_extent, slice_map,
)
from ..model.blade import Blade
from ..model.forward_trim import TRIM_TARGETS, forward_flight_trim
from ..model.parameters import BladeParameters
from ..model.steady import disturbed_rhs, tabulate_motion
from .floquet import blade_floquet

__all__ = ["DEFAULT_S_MAX", "SLICES", "StableRegion", "stable_region"]

DEFAULT_S_MAX = 40.0
"""Largest start amplitude tried along a ray, scaled norm: 80 deg of flap or lag, 40 deg of
pitch, below the bound 45 (:data:`rotorlyap.methods.region.DEFAULT_BOUND`)."""

SLICES = {"flap-lag": (0, 1), "flap-pitch": (0, 2)}
"""The slices :func:`stable_region` maps: name -> the two state components (angles)."""

_FORWARD_AZIMUTHS = 4


@dataclass(frozen=True)
class StableRegion:
    """Result of :func:`stable_region`: how large a disturbance the nonlinear blade survives.

    Attributes
    ----------
    mu : float
        Advance ratio, -.
    condition : str
        The flight condition (:data:`rotorlyap.model.forward_trim.TRIM_TARGETS`).
    rotor_speed : float
        ``Omega``, rad/s (turns the rates per rad of azimuth into per second).
    scales : numpy.ndarray
        Norm scales ``a_i``, rad and rad/rad, shape (6,).
    growth_rate : float
        ``sigma``, the largest real part of the Floquet exponents, per rad of azimuth (< 0).
    n_periods : int
        Horizon, revolutions.
    horizon_capped : bool
        The horizon formula asked for more than ``max_periods`` revolutions.
    bound, decay, s_max : float
        The definition's bound and decay ratio, and the largest amplitude tried (scaled norm).
    steps_per_period : int
        RK4 steps per revolution.
    psi0 : numpy.ndarray
        Start azimuths, rad, shape (p,).
    directions : numpy.ndarray
        The 12 signed single-component directions, rows ``+e_0 .. +e_5, -e_0 .. -e_5``.
    extent : numpy.ndarray
        Extent along each direction, scaled norm, smallest over the start azimuths, shape (12,).
    hit_s_max : numpy.ndarray
        Boolean, shape (12,): every start up to ``s_max`` was stable (at every azimuth).
    non_monotone : numpy.ndarray
        Boolean, shape (12,): at some azimuth a start beyond the first unstable grid amplitude was
        stable again.
    rays : RayExtent
        The full ray result (per direction and azimuth, the grid's verdicts).
    slices : dict of str to SliceMap
        ``"flap-lag"`` and ``"flap-pitch"`` (:data:`SLICES`), or empty.
    """

    mu: float
    condition: str
    rotor_speed: float
    scales: np.ndarray
    growth_rate: float
    n_periods: int
    horizon_capped: bool
    bound: float
    decay: float
    s_max: float
    steps_per_period: int
    psi0: np.ndarray
    directions: np.ndarray
    extent: np.ndarray
    hit_s_max: np.ndarray
    non_monotone: np.ndarray
    rays: RayExtent
    slices: dict[str, SliceMap]

    @property
    def component_extent(self) -> np.ndarray:
        """Extent per state component, the smaller of its two signs, scaled norm, shape (6,)."""
        return np.minimum(self.extent[:6], self.extent[6:])

    def _per_hinge(self, scaled: np.ndarray) -> dict:
        deg = np.degrees(self.scales) * scaled
        return {h: (float(deg[i]), float(deg[i + 3] * self.rotor_speed)) for i, h in enumerate(HINGES)}

    @property
    def per_hinge(self) -> dict:
        """``{hinge: (deg, deg/s)}``: the extent of the hinge angle alone (deg) and of its rate
        alone (deg/s, ``scaled * a_(i+3) * Omega``), the smaller sign; the layout of
        :attr:`rotorlyap.analysis.certify.Certificate.start_region_per_hinge`."""
        return self._per_hinge(self.component_extent)

    @property
    def per_hinge_signed(self) -> dict:
        """``{"+": {hinge: (deg, deg/s)}, "-": {...}}``: the extents of each sign."""
        return {"+": self._per_hinge(self.extent[:6]), "-": self._per_hinge(self.extent[6:])}

    def summary(self) -> str:
        """Rounded lines (2 significant digits): the case, the definition, the extents per hinge."""
        def g(v: float) -> str:
            return f"{float(f'{v:.2g}'):g}"

        head = (f"mu = {self.mu:g}, {self.condition}: stable region by simulation "
                f"({self.n_periods} rev, bound {g(self.bound)}, decay to {g(self.decay)}, "
                f"{self.psi0.size} start azimuth{'s' if self.psi0.size > 1 else ''}; "
                f"slowest linear decay {g(self.growth_rate)} per rev)")
        ph = self.per_hinge
        cap = self.hit_s_max[:6] & self.hit_s_max[6:]
        parts = []
        for i, h in enumerate(HINGES):
            ang = (">= " if cap[i] else "") + g(ph[h][0])
            rate = (">= " if cap[i + 3] else "") + g(ph[h][1])
            parts.append(f"{h} {ang} deg / {rate} deg/s")
        lines = [head, "  returns from (one hinge alone, smaller sign): " + ", ".join(parts)]
        if self.non_monotone.any():
            names = [("+" if d < 6 else "-") + STATE_NAMES[d % 6] for d in np.flatnonzero(self.non_monotone)]
            lines.append("  not an interval along: " + ", ".join(names))
        for name, s in self.slices.items():
            lines.append(f"  slice {name}: {g(100 * s.stable_fraction)} % of the grid returns")
        return "\n".join(lines)


def stable_region(params: BladeParameters, mu: float = 0.0, *, condition: str = "propulsive",
                  slices: bool = True, scales=None, bound: float = DEFAULT_BOUND, decay: float = DEFAULT_DECAY,
                  n_periods: int | None = None, max_periods: int = MAX_PERIODS, s_max: float = DEFAULT_S_MAX,
                  n_grid: int = 16, n_bisect: int = 6, n_slice: int = 31, slice_half_widths=None,
                  steps_per_period: int = DEFAULT_STEPS_PER_PERIOD) -> StableRegion:
    """The region of stable motion of the blade's trimmed steady motion, by batched simulation.

    Parameters
    ----------
    params : BladeParameters
        The blade and helicopter, as :func:`rotorlyap.certify` takes them.
    mu : float
        Advance ratio, >= 0.
    condition : str
        One of :data:`rotorlyap.model.forward_trim.TRIM_TARGETS` (as :func:`rotorlyap.certify`).
    slices : bool
        Also map the flap-lag and flap-pitch slices (:data:`SLICES`).
    scales : array_like, optional
        Norm scales ``a_i``, rad and rad/rad (default :data:`rotorlyap.conventions.DEFAULT_SCALES`).
    bound : float
        Bound of the scaled norm (default 45: 90 deg of flap).
    decay : float
        Decay ratio over the last revolution, in (0, 1) (default 0.5).
    n_periods : int, optional
        Horizon, revolutions; default from the slowest linear decay rate
        (:func:`rotorlyap.methods.region.horizon`, at most ``max_periods``).
    max_periods : int
        Longest default horizon, revolutions.
    s_max : float
        Largest amplitude tried along a ray, scaled norm (< ``bound``).
    n_grid, n_bisect : int
        Grid amplitudes and bisection steps of :func:`rotorlyap.methods.region.ray_extent`.
    n_slice : int
        Points per axis of each slice.
    slice_half_widths : dict, optional
        ``{slice name: (half-width of component i, of component j)}``, scaled units; default 1.5
        times the smaller of the component's two ray extents (the nearest edge of the region
        along that component, the one a certificate meets first; at least the smallest grid
        amplitude), at most ``s_max``.
    steps_per_period : int
        RK4 steps per revolution.

    Returns
    -------
    StableRegion

    Raises
    ------
    ValueError
        Unknown ``condition``, bad arguments.
    rotorlyap.errors.NotAsymptoticallyStableError
        If the linearised blade does not decay (``sigma >= 0``): no motion returns to it.
    rotorlyap.errors.TrimError
        If the trim does not converge.
    """
    if condition not in TRIM_TARGETS:
        raise ValueError(f"condition must be one of {TRIM_TARGETS}, got {condition!r}")
    trim = forward_flight_trim(params, float(mu), condition)
    mu = trim.mu
    if mu == 0.0:
        blade = Blade(trim.params, 0.0)
        steady = trim.steady
        psi0 = np.zeros(1)
    else:
        blade = Blade(trim.params, mu)
        steady = tabulate_motion(trim.motion)
        psi0 = TWO_PI * np.arange(_FORWARD_AZIMUTHS) / _FORWARD_AZIMUTHS
    f = disturbed_rhs(blade, steady)
    sigma = float(blade_floquet(trim.params, mu, steady=trim.steady).exponents.real.max())
    if sigma >= 0.0:
        raise NotAsymptoticallyStableError(
            f"the linearised blade does not decay at mu = {mu:g} (largest Floquet real part {sigma:.3g} per rev): "
            "no motion returns to the steady motion, no region of stable motion to measure",
            spectral_radius=float(np.exp(TWO_PI * sigma)), growth_rate=sigma)
    a = np.asarray(DEFAULT_SCALES if scales is None else scales, dtype=float)
    wanted = horizon(sigma, decay, max_periods=10**9)
    n_rev = min(wanted, int(max_periods)) if n_periods is None else int(n_periods)
    directions = np.asarray(PAPER_TEST_DISTURBANCES, dtype=float)
    rays = ray_extent(f, directions, psi0, scales=a, s_max=s_max, n_grid=n_grid, n_bisect=n_bisect,
                      n_periods=n_rev, bound=bound, decay=decay, steps_per_period=steps_per_period)
    extent = rays.min_extent
    maps = {}
    if slices:
        smaller = np.minimum(extent[:6], extent[6:])
        floor = float(rays.amplitudes[0])
        for name, (i, j) in SLICES.items():
            if slice_half_widths is not None and name in slice_half_widths:
                wi, wj = (float(w) for w in slice_half_widths[name])
            else:
                wi, wj = (min(s_max, max(1.5 * smaller[c], floor)) for c in (i, j))
            maps[name] = slice_map(f, i, j, wi, wj, n_slice, float(psi0[0]), scales=a, n_periods=n_rev,
                                   bound=bound, decay=decay, steps_per_period=steps_per_period)
    return StableRegion(
        mu=mu, condition=condition, rotor_speed=float(trim.params.rotor_speed), scales=a, growth_rate=sigma,
        n_periods=n_rev, horizon_capped=n_periods is None and wanted > max_periods, bound=float(bound),
        decay=float(decay), s_max=float(s_max), steps_per_period=int(steps_per_period), psi0=psi0,
        directions=rays.directions, extent=extent, hit_s_max=rays.hit_s_max.all(axis=1),
        non_monotone=rays.non_monotone.any(axis=1), rays=rays, slices=maps)
