"""A certificate's claims checked again, for any periodic system: the level facts and (h).

A certificate of the sound rule (:func:`rotorlyap.technical_stability` with ``rule="sound"``)
claims, for a system ``x' = f(psi, x)`` of period ``T``, a function ``W`` with its derivative
``W'`` along the motions, the scaled norm ``||x|| = sqrt(sum((x_i / a_i)**2))``, a bound ``A``, a
level ``c`` and start radii ``lambda0_j`` at the azimuths ``psi_j = j T / n``:

``level``
    ``c <= inf W`` on the sphere ``||x|| = A`` over the period (so a motion in ``{W < c}``
    cannot reach the sphere without crossing the band);
``start``
    ``W(psi_j, x) < c`` on the ball ``||x|| < lambda0_j`` at each azimuth (so a motion started
    there is in ``{W < c}``);
``band``
    ``W' < 0`` on the band ``||x|| <= A, W >= c`` at every azimuth of the period: below
    ``-margin`` times the largest ``|W|`` on the sphere ``||x|| = A`` (the engine's allowance
    against a search that misses the true maximum by a little).

:func:`check_claims` checks the three from nothing but ``f``, ``W``, ``W'`` and the numbers: the
level facts in closed form for a quadratic ``W`` (``w_matrix``: the extreme eigenvalues of the
scaled matrix, unwidened, since the engine's level and start radii already lie the eigen-solver's
allowance :data:`rotorlyap.methods.lyapunov.EIGENVALUE_ROUNDOFF` inside them) or by the engine's
searches of ``W``; condition (h) by exactly the search the engine's sound rule ends with (its
thorough final check: five band searches, two sets of directions, 256 polished candidates,
:func:`rotorlyap.methods.lyapunov.band_max_dw`), run at the claimed ``A`` and ``c``. Like the
engine's, these are sampled searches: a claim that passes is a numerical certificate, and one
that fails is refused with the state where it fails.

Nothing here knows the blade (:mod:`rotorlyap.analysis.certificate_file` gives it the blade's
functions).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np

from .lyapunov import (_band_searches, _band_verdict, _Checked, _Level, _min_over_period, _second_directions,
                       band_max_dw)
from .polish import T_MIN
from .sampling import PsiFree, sphere_extremum, unit_sphere_points

__all__ = ["Check", "check_claims"]

Function = Callable[[np.ndarray, np.ndarray], np.ndarray]


@dataclass(frozen=True)
class Check:
    """One claim of a certificate, checked.

    Attributes
    ----------
    name : str
        Short name (``"level"``, ``"start"``, ``"band"``, ...).
    holds : bool
        The claim holds (as far as the check determines it).
    value : float
        What the check found (its unit in ``detail``).
    limit : float
        What ``value`` is compared with: the claim holds where ``value`` is on the right side of it.
    margin : float
        How far inside the claim is, relative (``> 0`` where it holds): what a notebook prints,
        rounded to two or three significant digits.
    meaning : str
        What the claim means, in a sentence.
    detail : str
        The numbers: what was found against what, and where it fails, why.
    quantity : str
        What ``value`` and ``limit`` are, in a few words each (``"inf W on the sphere / the
        level"``).
    """

    name: str
    holds: bool
    value: float
    limit: float
    margin: float
    meaning: str
    detail: str
    quantity: str = "value / limit"

    def __str__(self) -> str:
        return f"{'holds' if self.holds else 'FAILS'}  {self.name}: {self.detail}"


def _raw_eigenvalues(w_matrix, psi: np.ndarray) -> np.ndarray:
    """Eigenvalues of the symmetric part of ``w_matrix(psi)``, ascending, ``psi.shape + (n,)``."""
    S = np.asarray(w_matrix(np.asarray(psi, dtype=float)), dtype=float)
    if not np.all(np.isfinite(S)):
        raise ValueError("w_matrix(psi) returned non-finite values")
    return np.linalg.eigvalsh(0.5 * (S + np.swapaxes(S, -1, -2)))


def check_claims(f: Function, W: Function, dW: Function | None, *, level: float, A: float, lambda0,
                 scales, period: float = 2 * np.pi, w_matrix: Callable | None = None, autonomous: bool = False,
                 band: str = "level", psi_free: bool = False, margin: float = 1e-6, n_sphere: int = 1024,
                 n_radii: int = 12, n_shells: int = 5, n_bisect: int = 12, n_refine: int = 4, n_iter: int = 40,
                 fd_step: float = 1e-4, seed: int = 0) -> tuple[Check, Check, Check]:
    """Check a sound-rule certificate's claims (module docstring): ``(level, start, band)``.

    Parameters
    ----------
    f, W, dW : callable
        As :func:`rotorlyap.technical_stability` takes them (``dW`` None: a central difference).
    level : float
        The claimed level ``c`` (> 0), in the unit of ``W``.
    A : float
        The claimed bound of the scaled norm (> 0).
    lambda0 : array_like
        The claimed start radius at each azimuth ``psi_j = j period / n``, shape ``(n,)``, scaled
        norm, each in ``(0, A]``.
    scales : array_like
        The norm's ``a_i``.
    period : float
        The period of ``f`` and ``W`` (rad for the blade).
    w_matrix : callable, optional
        For a quadratic ``W = y^T S(psi) y`` in scaled coordinates: ``S(psi)``; the level facts
        are then closed forms.
    autonomous, band, psi_free, margin, n_sphere, n_radii, n_shells, n_bisect, n_refine, n_iter, fd_step, seed
        The engine's settings the certificate was made with
        (:func:`rotorlyap.technical_stability`): the same searches are run again.

    Returns
    -------
    tuple of Check
        ``level`` (``c <= inf W`` on the sphere ``A``), ``start`` (``W < c`` on each start ball)
        and ``band`` (``W' < -margin max|W|`` on the band over the period).

    Raises
    ------
    ValueError
        Non-positive or non-finite ``level``, ``A`` or scales; start radii outside ``(0, A]``.
    """
    a = np.asarray(scales, dtype=float).reshape(-1)
    if a.size == 0 or not np.all(np.isfinite(a)) or np.any(a <= 0):
        raise ValueError(f"scales must be finite and > 0, got {a.tolist()}")
    level, A, period = float(level), float(A), float(period)
    for name, v in (("level", level), ("A", A), ("period", period)):
        if not (np.isfinite(v) and v > 0):
            raise ValueError(f"{name} must be finite and > 0, got {v!r}")
    lam = np.asarray(lambda0, dtype=float).reshape(-1)
    if lam.size == 0 or not np.all(np.isfinite(lam)) or np.any(lam <= 0) or np.any(lam > A):
        raise ValueError(f"the start radii lambda0 must be finite numbers in (0, A = {A!r}], "
                         f"got values in [{lam.min() if lam.size else 'none'}, {lam.max() if lam.size else 'none'}]")
    if band not in ("level", "shell"):
        raise ValueError(f"band must be 'level' or 'shell', got {band!r}")
    n = a.size
    n_psi = lam.size
    psi = period * np.arange(n_psi) / n_psi
    sys = _Checked(f, W, dW, n, fd_step * period / (2 * np.pi))
    if psi_free:
        sys.dw, sys.w = PsiFree(sys.dw, sys), PsiFree(sys.w, sys)
    dirs = unit_sphere_points(n, n_sphere, seed)
    common = dict(period=period, n_refine=n_refine, n_iter=n_iter)
    search_psi = psi[:1] if autonomous else psi
    shell = band == "shell"
    levels = _Level(sys, w_matrix, search_psi, period, a, dirs, common, free=not autonomous, shell=shell,
                    n_radii=n_radii, n_bisect=n_bisect)
    return (_level_check(levels, w_matrix, level, A, period),
            _start_check(sys, levels, w_matrix, level, lam, psi, a, dirs, autonomous, n_shells),
            _band_check(sys, levels, w_matrix, level, A, search_psi, period, a, dirs, autonomous, psi_free,
                        margin, n_shells, common))


def _level_check(levels, w_matrix, level: float, A: float, period: float) -> Check:
    if w_matrix is not None:  # inf W on the sphere = A^2 min over the period of the smallest eigenvalue
        found = A * A * _min_over_period(lambda p: _raw_eigenvalues(w_matrix, p)[..., 0], period)
        how = "closed form, A^2 min_psi l_min(S)"
    else:
        found = levels.sphere_min(A)
        how = "the engine's search of W on the sphere"
    holds = bool(level > 0 and level <= found)
    return Check("level", holds, float(found), level, float(1.0 - level / found) if found > 0 else -np.inf,
                 "the level set {W < c} lies inside the bound: c <= inf W on the sphere ||x|| = A over the period",
                 f"inf W on ||x|| = {A:.6g} is {found:.6g} ({how}); the level c = {level:.6g} "
                 + ("is not above it" if holds else "is ABOVE it: the level set reaches beyond the bound"),
                 "inf W on the sphere A / the level")


def _start_check(sys, levels, w_matrix, level: float, lam: np.ndarray, psi: np.ndarray, a: np.ndarray, dirs,
                 autonomous: bool, n_shells: int) -> Check:
    if w_matrix is not None:  # sup W on the ball = lambda0^2 l_max(S(psi_j))
        sup = lam * lam * _raw_eigenvalues(w_matrix, psi)[..., -1]
        how = "closed form, lambda0^2 l_max(S)"
    elif autonomous:  # W is the same at every azimuth: the largest ball holds every other
        j = int(np.argmax(lam))
        sup = np.full(lam.shape, -np.inf)
        sup[j] = _ball_sup(sys, psi[:1], lam[j:j + 1], a, dirs, n_shells, levels.w_common)[0]
        how = "the engine's search of W over the largest ball (W does not depend on the azimuth)"
    else:
        sup = _ball_sup(sys, psi, lam, a, dirs, n_shells, levels.w_common)
        how = "the engine's search of W over each ball"
    j = int(np.argmax(sup / level))
    holds = bool(np.all(sup < level))
    return Check("start", holds, float(sup[j]), level, float(1.0 - sup[j] / level),
                 "a motion started in the start region is inside the level set: W < c on the ball "
                 "||x|| < lambda0_j at each azimuth psi_j",
                 f"largest sup W on a start ball is {sup[j]:.6g} at psi = {np.degrees(psi[j]):.4g} deg "
                 f"(lambda0 = {lam[j]:.6g}; {how}); the level c = {level:.6g}"
                 + ("" if holds else f": {int(np.sum(sup >= level))} of {lam.size} start balls LEAVE the level set"),
                 "largest sup W on a start ball / the level")


def _ball_sup(sys, psi: np.ndarray, radii: np.ndarray, a: np.ndarray, dirs, n_shells: int, common: dict) -> np.ndarray:
    """The largest ``W`` found on the ball of radius ``radii[j]`` at each azimuth ``psi[j]``: the
    engine's search over the shell from the centre out, the azimuth fixed."""
    return sphere_extremum(sys.w, psi, None, a, dirs, per_psi=True, shell=(T_MIN * radii, radii),
                           n_levels=max(n_shells, 8), **common).value


def _band_check(sys, levels, w_matrix, level: float, A: float, psi: np.ndarray, period: float, a: np.ndarray,
                dirs, autonomous: bool, psi_free: bool, margin: float, n_shells: int, common: dict) -> Check:
    count = sys.count_dw
    need = -margin * levels.size(A)
    inner = levels.inner(A, level)

    def search(stop, per_psi=False, starts="levels", directions=None, n_lbfgs=64):
        return band_max_dw(sys, None, None, level, A, scales=a, period=period, psi=psi, w_matrix=w_matrix,
                           per_psi=per_psi, autonomous=autonomous, inner=inner,
                           directions=dirs if directions is None else directions, n_levels=n_shells,
                           stop_above=stop, n_refine=common["n_refine"], n_iter=common["n_iter"], starts=starts,
                           n_lbfgs=n_lbfgs, psi_free=psi_free)

    searches = _band_searches(search, need, dirs, _second_directions(dirs, a.size), thorough=True)
    holds, worst, k = _band_verdict(searches, need)
    where = ("the band ||x|| <= A, W >= c" if inner is None
             else f"the shell {inner:.4g} <= ||x|| <= A (which holds the band W >= c)")
    detail = (f"largest W' found on {where} over the period is {worst:.6g} per rad; it must be below "
              f"{need:.6g} (-{margin:g} x max|W| on the sphere); {sys.count_dw - count} states searched")
    if not holds:
        detail += f": W' >= -margin found by search {k} of the final check, (h) FAILS"
    return Check("band", bool(holds), float(worst), float(need),
                 float((need - worst) / abs(need)) if need != 0 and np.isfinite(worst) else -np.inf,
                 "W' < 0 on the band between the level set and the bound at every azimuth of the period "
                 "(condition (h) of the theorem, the sound rule's final check)", detail,
                 "largest W' on the band, per rad / -margin max|W|")
