"""Liapunov functions built from a basis and designed by a linear program on sampled states.

A function that is a combination of given basis functions,

    ``W(psi, x) = sum_j c_j phi_j(psi, x)``,    ``W'(psi, x) = sum_j c_j phi_j'(psi, x)``,

with ``phi_j'`` the derivative of ``phi_j`` along the motions of ``x' = f(psi, x)``, is *linear
in its coefficients*, and so is every condition the sound rule of
:func:`rotorlyap.technical_stability` checks. With the level normalised to ``c = 1``:

* ``W >= 1`` on the sphere ``||x|| = A`` (so the level set ``{W < 1}`` stays inside the bound);
* ``W < 1`` on the ball ``||x|| <= lam`` (so that ball is a start region);
* ``W' < 0`` on the band ``||x|| <= A, W >= 1``, which lies in the shell ``lam <= ||x|| <= A``.

:func:`design` asks these on sampled states (quasi-random directions, radii across the shell and,
for a periodic system, azimuths) and maximises the margin ``t`` in ``W' <= -t (||x|| / A)^2`` by a
linear program (scipy's HiGHS): a *scenario* relaxation of the infinite family of conditions.
Rounds of counterexamples follow, until one finds none: an independent, denser sample of the
shell, searched further by local ascent; every state where the designed ``W'`` is not below half
the margin is added to the program, which is solved again (a design whose margin the rounds
squeeze below a fifth of the first program's is given up). :func:`largest_design` searches the start radius ``lam`` (and the ratio ``A / lam``) for
the largest one the program still meets.

The program only *designs* the function; nothing here certifies. The certificate is what the
engine (the sound rule, :func:`rotorlyap.technical_stability`) finds for the designed function
afterwards, with its own searches, and what an adversary cannot break.

Two properties of the theorem's conditions make the design easy: ``W'`` needs to be negative only
on the band, not near ``x = 0`` (a motion that starts inside ``{W < 1}`` cannot reach the sphere
without crossing the band upwards, where ``W`` decreases), and ``W`` need not be a quadratic
form, so the basis can hold what the linearised system lacks (for a mechanical system, its
energy, whose derivative along the motions has no inertial nonlinearity at all).
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, field
from typing import Callable, Sequence

import numpy as np
from scipy.optimize import linprog

from ._checks import positive_float as _positive_float
from ._checks import positive_int as _positive_int
from ..progress import report
from .lyapunov import band_max_dw
from .sampling import sphere_extremum, unit_sphere_points

__all__ = ["Basis", "BasisFunction", "Design", "design", "largest_design", "monomial_basis",
           "monomial_exponents"]

Function = Callable[[np.ndarray, np.ndarray], np.ndarray]
Combination = Callable[[np.ndarray, np.ndarray, np.ndarray], np.ndarray]


@dataclass(frozen=True)
class Basis:
    """``k`` functions ``phi_j(psi, x)`` and their derivatives along the motions.

    Attributes
    ----------
    names : tuple of str
        One name per function (for tables), length ``k``.
    values : callable
        ``values(psi (m,), x (m, n)) -> (m, k)``: the ``phi_j``.
    rates : callable
        ``rates(psi (m,), x (m, n)) -> (m, k)``: ``phi_j' = d phi_j / d psi + grad phi_j . f``.
    rate_with_f : callable, optional
        ``rate_with_f(psi, x, c, f) -> (m,)``: ``rate_of`` given the right-hand side ``f(psi, x)``
        at the states (computed by the caller with something else it needed it for).
    value_of, rate_of : callable, optional
        ``value_of(psi, x, c) -> (m,)``: ``sum_j c_j phi_j`` computed without the ``(m, k)``
        matrix (and ``rate_of`` the same of the rates): what a designed function's ``W`` and
        ``W'`` evaluate, millions of times in the engine's searches. For the augmented energy at
        mu = 0.1 the matrix cost 4.3 of the 7.6 us a state of ``W`` took (measured, 100 000
        states at one azimuth); None: ``values(psi, x) @ c``.
    energy_reference : float, optional
        The divisor ``H_ref`` (J) of a basis function named ``"energy"`` (the augmented energy's,
        :func:`rotorlyap.analysis.nonlinear_functions.energy_basis`), for a prover that rebuilds
        the function in another arithmetic; None where the basis has none.
    """

    names: tuple[str, ...]
    values: Function
    rates: Function
    value_of: Combination | None = field(default=None, compare=False)
    rate_of: Combination | None = field(default=None, compare=False)
    rate_with_f: Callable | None = field(default=None, compare=False)
    energy_reference: float | None = field(default=None, compare=False)

    @property
    def size(self) -> int:
        """Number of basis functions ``k``."""
        return len(self.names)

    def combined_values(self, psi, x, c: np.ndarray) -> np.ndarray:
        """``sum_j c_j phi_j(psi, x)``, shape ``(m,)``: by ``value_of`` where the basis has one
        (without the ``(m, k)`` matrix of :attr:`values`), else ``values(psi, x) @ c``."""
        if self.value_of is not None:
            return self.value_of(psi, x, c)
        return self.values(psi, x) @ c

    def combined_rates(self, psi, x, c: np.ndarray) -> np.ndarray:
        """``sum_j c_j phi_j'(psi, x)``, shape ``(m,)`` (as :meth:`combined_values`, by
        ``rate_of``)."""
        if self.rate_of is not None:
            return self.rate_of(psi, x, c)
        return self.rates(psi, x) @ c

    def __add__(self, other: "Basis") -> "Basis":
        """The two bases side by side (values and rates concatenated; their combinations the sum
        of each part's, the coefficients split at the first basis's size)."""
        if not isinstance(other, Basis):
            return NotImplemented
        first, second = self, other
        k = first.size
        return Basis(
            names=first.names + second.names,
            values=lambda psi, x: np.hstack([first.values(psi, x), second.values(psi, x)]),
            rates=lambda psi, x: np.hstack([first.rates(psi, x), second.rates(psi, x)]),
            value_of=lambda psi, x, c: (first.combined_values(psi, x, c[:k])
                                        + second.combined_values(psi, x, c[k:])),
            rate_of=lambda psi, x, c: first.combined_rates(psi, x, c[:k]) + second.combined_rates(psi, x, c[k:]),
        )


def monomial_exponents(dim: int, degrees: Sequence[int]) -> np.ndarray:
    """Exponents of every monomial of ``dim`` variables with a total degree in ``degrees``,
    shape ``(k, dim)``, degree by degree in lexicographic order."""
    dim = _positive_int("dim", dim)
    out = []
    for degree in sorted(set(int(d) for d in degrees)):
        if degree < 1:
            raise ValueError(f"monomial degrees must be >= 1, got {degree}")
        for combo in itertools.combinations_with_replacement(range(dim), degree):
            e = np.zeros(dim, dtype=int)
            np.add.at(e, list(combo), 1)
            out.append(e)
    return np.array(out, dtype=int).reshape(-1, dim)


def monomial_basis(f: Function, scales, degrees: Sequence[int] = (2,), *, harmonics: int = 0,
                   period: float = 2 * np.pi, names: Sequence[str] | None = None) -> Basis:
    """Monomials of the scaled state ``y = x / a``, times low harmonics of the azimuth.

    ``phi(psi, x) = y^e h(psi)`` for every exponent ``e`` of a total degree in ``degrees`` and
    ``h`` in ``1, cos(w psi), sin(w psi), ..., cos(K w psi), sin(K w psi)`` (``K = harmonics``,
    ``w = 2 pi / period``); ``phi' = h (grad y^e) . (f / a) + y^e h'``.

    Parameters
    ----------
    f : callable
        The vectorised right-hand side ``f(psi, x)``.
    scales : array_like
        The ``a_i`` of the scaled coordinates, shape ``(n,)``, all > 0.
    degrees : sequence of int
        Total degrees of the monomials (each >= 1).
    harmonics : int
        Harmonics of the azimuth (0 for an autonomous system).
    period : float
        The period ``T`` of ``f`` in ``psi``.
    names : sequence of str, optional
        Names of the ``n`` state components (default ``x0, x1, ...``).

    Returns
    -------
    Basis
    """
    a = np.asarray(scales, dtype=float).reshape(-1)
    if a.size == 0 or not np.all(np.isfinite(a)) or np.any(a <= 0):
        raise ValueError(f"scales must be finite and > 0, got {a.tolist()}")
    harmonics = _positive_int("harmonics", harmonics, 0)
    period = _positive_float("period", period)
    n = a.size
    E = monomial_exponents(n, degrees)
    top = int(E.sum(axis=1).max())
    w = 2 * np.pi / period
    labels = list(names) if names is not None else [f"x{i}" for i in range(n)]
    if len(labels) != n:
        raise ValueError(f"names must hold {n} names, got {len(labels)}")
    mono = ["*".join(f"{labels[i]}^{e[i]}" if e[i] > 1 else labels[i] for i in range(n) if e[i]) for e in E]
    waves = ["1"] + [f"{fn}({k}psi)" for k in range(1, harmonics + 1) for fn in ("cos", "sin")]
    all_names = tuple(m if h == "1" else f"{m}*{h}" for h in waves for m in mono)

    def powers(y):  # (top + 1, m, n): y^0 .. y^top
        p = np.empty((top + 1,) + y.shape)
        p[0] = 1.0
        for k in range(1, top + 1):
            p[k] = p[k - 1] * y
        return p

    def monomials_of(p, ex):  # (m, k): prod_i y_i^ex_i
        out = np.ones((ex.shape[0], p.shape[1]))
        for i in range(n):
            out *= p[ex[:, i], :, i]
        return out.T

    def monomials(p):
        return monomials_of(p, E)

    k_w = np.arange(1, harmonics + 1) * w

    def waves_of(psi):  # h = (1, cos w psi, sin w psi, cos 2w psi, ...) and h', each (m, 2K + 1)
        h = np.empty((psi.size, 2 * harmonics + 1))
        dh = np.zeros_like(h)
        h[:, 0] = 1.0
        if harmonics:
            arg = np.outer(psi, k_w)
            c, s = np.cos(arg), np.sin(arg)
            h[:, 1::2], h[:, 2::2] = c, s
            dh[:, 1::2], dh[:, 2::2] = -k_w * s, k_w * c
        return h, dh

    quadratic = set(int(d) for d in degrees) == {2}
    if quadratic:  # y_i y_j and its rate f_i y_j + y_i f_j, without the general machinery
        I, J = (np.array(ix) for ix in zip(*[np.flatnonzero(e).tolist() * (2 // int(np.count_nonzero(e)))
                                              for e in E]))

    def values(psi, x):
        psi = np.broadcast_to(np.asarray(psi, dtype=float), (np.shape(x)[0],))
        y = np.asarray(x, dtype=float) / a
        m = y[:, I] * y[:, J] if quadratic else monomials(powers(y))
        h, _ = waves_of(psi)
        return (h[:, :, None] * m[:, None, :]).reshape(y.shape[0], -1)

    def monomials_and_rates(psi, x):  # y^e and grad(y^e) . f / a, each (m, len(E))
        x = np.asarray(x, dtype=float)
        y = x / a
        fy = np.asarray(f(psi, x), dtype=float) / a
        if quadratic:
            m = y[:, I] * y[:, J]
            grad_dot_f = fy[:, I] * y[:, J] + y[:, I] * fy[:, J]
        else:
            p = powers(y)
            m = monomials(p)
            grad_dot_f = np.zeros_like(m)
            for i in range(n):  # d(y^e)/dy_i = e_i y^(e - 1_i)
                lowered = E.copy()
                lowered[:, i] = np.maximum(E[:, i] - 1, 0)
                grad_dot_f += E[:, i] * monomials_of(p, lowered) * fy[:, i:i + 1]
        return m, grad_dot_f

    def rates(psi, x):
        psi = np.broadcast_to(np.asarray(psi, dtype=float), (np.shape(x)[0],))
        m, grad_dot_f = monomials_and_rates(psi, x)
        h, dh = waves_of(psi)
        return (h[:, :, None] * grad_dot_f[:, None, :] + dh[:, :, None] * m[:, None, :]).reshape(m.shape[0], -1)

    n_waves, n_mono = 2 * harmonics + 1, E.shape[0]

    def forms(c):  # quadratic: the symmetric matrices S_h of sum_e c_(h, e) y^e = y^T S_h y, (n, n H)
        C = np.asarray(c, dtype=float).reshape(n_waves, n_mono)
        S = np.zeros((n_waves, n, n))
        S[:, I, J] += 0.5 * C
        S[:, J, I] += 0.5 * C
        return S.transpose(1, 0, 2).reshape(n, n_waves * n)

    def value_of(psi, x, c):  # sum_j c_j phi_j without the (m, k) matrix
        psi = np.broadcast_to(np.asarray(psi, dtype=float), (np.shape(x)[0],))
        y = np.asarray(x, dtype=float) / a
        h, _ = waves_of(psi)
        if quadratic:  # sum_h h_h(psi) y^T S_h y
            Sy = (y @ forms(c)).reshape(-1, n_waves, n)
            return np.einsum("ih,ih->i", np.einsum("ihj,ij->ih", Sy, y), h)
        m = monomials(powers(y))
        C = np.asarray(c, dtype=float).reshape(n_waves, n_mono)
        return np.einsum("ij,ij->i", m @ C.T, h)

    def rate_of(psi, x, c, fx=None):
        psi = np.broadcast_to(np.asarray(psi, dtype=float), (np.shape(x)[0],))
        h, dh = waves_of(psi)
        if quadratic:  # sum_h [h_h 2 (S_h y) . f / a + h_h' y^T S_h y]
            x = np.asarray(x, dtype=float)
            y = x / a
            fy = np.asarray(f(psi, x) if fx is None else fx, dtype=float) / a
            Sy = (y @ forms(c)).reshape(-1, n_waves, n)
            rate = 2.0 * np.einsum("ih,ih->i", np.einsum("ihj,ij->ih", Sy, fy), h)
            return rate + np.einsum("ih,ih->i", np.einsum("ihj,ij->ih", Sy, y), dh) if harmonics else rate
        m, grad_dot_f = monomials_and_rates(psi, x)
        C = np.asarray(c, dtype=float).reshape(n_waves, n_mono)
        return np.einsum("ij,ij->i", grad_dot_f @ C.T, h) + np.einsum("ij,ij->i", m @ C.T, dh)

    return Basis(names=all_names, values=values, rates=rates, value_of=value_of, rate_of=rate_of,
                 rate_with_f=rate_of if quadratic else None)


@dataclass(frozen=True)
class BasisFunction:
    """``W = sum_j c_j phi_j``: a Liapunov function the engine takes (``W``, ``dW``, ``f``).

    Attributes
    ----------
    basis : Basis
    coefficients : numpy.ndarray
        The ``c_j``, shape ``(k,)``.
    f : callable
        The right-hand side ``f(psi, x)`` the rates are taken along.
    label : str
        A short name for tables and legends.
    """

    basis: Basis
    coefficients: np.ndarray
    f: Function
    label: str = "designed"

    def __post_init__(self) -> None:
        c = np.array(self.coefficients, dtype=float).reshape(-1)
        if c.size != self.basis.size:
            raise ValueError(f"{c.size} coefficients for a basis of {self.basis.size} functions")
        c.setflags(write=False)
        object.__setattr__(self, "coefficients", c)

    def W(self, psi, x) -> np.ndarray:
        """``W(psi, x)``, shape ``(m,)`` for ``x`` of shape ``(m, n)``."""
        x = np.atleast_2d(np.asarray(x, dtype=float))
        psi = np.broadcast_to(np.asarray(psi, dtype=float), x.shape[:1])
        return self.basis.combined_values(psi, x, self.coefficients)

    def dW(self, psi, x) -> np.ndarray:
        """``W'(psi, x)`` along the motions of ``f``, shape ``(m,)``."""
        x = np.atleast_2d(np.asarray(x, dtype=float))
        psi = np.broadcast_to(np.asarray(psi, dtype=float), x.shape[:1])
        return self.basis.combined_rates(psi, x, self.coefficients)

    def __repr__(self) -> str:  # short and stable: no arrays, no addresses
        return f"BasisFunction({self.label}, {self.basis.size} basis functions)"


@dataclass(frozen=True)
class Design:
    """Result of :func:`design` (and of :func:`largest_design`).

    Attributes
    ----------
    function : BasisFunction or None
        The designed ``W`` (level 1), None where the program found no margin ``t > 0``.
    lam : float
        The start radius asked for, scaled norm.
    A : float
        The bound asked for, scaled norm.
    margin : float
        The program's ``t`` in ``W' <= -t (||x|| / A)^2`` on the sampled band (> 0 where feasible).
    feasible : bool
        ``t > 0`` and the last round of counterexamples found no state with ``W' >= 0`` on the
        band of the smallest ``W`` it found on the sphere (on its sample: a design, not a
        certificate; how large the start region is, the engine measures).
    rounds : int
        Counterexample rounds run.
    n_constraints : int
        Sampled conditions of the last program.
    tried : tuple
        ``(lam, A, feasible)`` of every design tried (:func:`largest_design`).
    """

    function: BasisFunction | None
    lam: float
    A: float
    margin: float
    feasible: bool
    rounds: int
    n_constraints: int
    tried: tuple = field(default=(), compare=False)

    def __repr__(self) -> str:
        return (f"Design(lam={self.lam:.4g}, A={self.A:.4g}, feasible={self.feasible}, "
                f"margin={self.margin:.3g}, rounds={self.rounds})")


def _shell_points(rng, dirs, lo, hi, m, period, periodic):
    u = dirs[rng.integers(0, dirs.shape[0], m)]
    r = np.sqrt(rng.uniform(lo * lo, hi * hi, m))  # more points outside, where the band is
    psi = rng.uniform(0.0, period, m) if periodic else np.zeros(m)
    return psi, u * r[:, None], r


def _sphere_points(rng, dirs, radius, m, period, periodic):
    u = dirs[:m] if m <= dirs.shape[0] else dirs[rng.integers(0, dirs.shape[0], m)]
    psi = rng.uniform(0.0, period, u.shape[0]) if periodic else np.zeros(u.shape[0])
    return psi, radius * u


def design(basis: Basis, f: Function, scales, A: float, lam: float, *, period: float = 2 * np.pi,
           periodic: bool = True, n_samples: int = 2048, n_check: int = 8192, rounds: int = 8,
           level_margin: float = 0.02, coefficient_bound: float = 1e4, n_azimuths: int = 8,
           n_ascent: int = 32, thorough: bool = False, directions=None, inner_factor: float = 0.8,
           seed: int = 0,
           label: str = "designed") -> Design:
    """Design ``W`` from ``basis`` for the start radius ``lam`` and the bound ``A`` (module docstring).

    Parameters
    ----------
    basis : Basis
        The basis functions.
    f : callable
        The right-hand side (kept with the function; the rates in ``basis`` already use it).
    scales : array_like
        The ``a_i`` of the scaled norm, shape ``(n,)``.
    A, lam : float
        Bound and start radius asked for, scaled norm, ``0 < lam < A``.
    period : float
        The period of ``f`` in ``psi``.
    periodic : bool
        Sample the azimuth (False: the system is autonomous, ``psi = 0`` stands for all).
    n_samples : int
        States of the sphere and of the shell in the first program (half as many of the start
        ball: its condition shapes the level set, not the certificate).
    n_check : int
        States of the band (and of the sphere and ball) in each round of counterexamples.
    rounds : int
        Rounds of counterexamples at most.
    level_margin : float
        ``W <= 1 - level_margin`` asked on the start ball's sample.
    n_azimuths : int
        Azimuths the ascent of each round starts from (periodic systems; the azimuth then moves).
    n_ascent : int
        States of the shell refined by local ascent of ``W'`` in each round (the engine's
        search, :func:`rotorlyap.methods.sampling.sphere_extremum`).
    thorough : bool
        Also search each round's shell with the engine's search of the sound rule
        (:func:`rotorlyap.methods.lyapunov.band_max_dw` on the shell ``lam <= ||x|| <= A``), so
        that the engine's check afterwards meets no counterexample the design did not.
    coefficient_bound : float
        Bound of each coefficient, relative to the size of its basis function on the sphere.
    inner_factor : float
        ``W' < 0`` is asked on the shell from ``inner_factor * lam`` (not ``lam``) to ``A``, and
        the ball of that radius must lie in the level set: the engine's shell starts at the
        largest ball inside the level set, which a sampled program places only approximately.
    directions : array_like, optional
        Unit directions ``(k, n)`` in scaled coordinates that the system singles out (for
        example the eigenvectors of its linearisation: along a slowly decaying mode ``W'`` is
        small, and a sample that misses it lets the program overreach): each direction, its
        opposite and 15 random neighbours of each are added to the sphere's and the shell's
        samples.
    seed : int
        Seed of the samples (deterministic).
    label : str
        Label of the function.

    Returns
    -------
    Design
    """
    a = np.asarray(scales, dtype=float).reshape(-1)
    A = _positive_float("A", A)
    lam = _positive_float("lam", lam)
    if not lam < A:
        raise ValueError(f"the start radius lam must be below the bound A, got lam={lam!r}, A={A!r}")
    n_samples = _positive_int("n_samples", n_samples, 16)
    n_check = _positive_int("n_check", n_check, 16)
    rounds = _positive_int("rounds", rounds, 0)
    n = a.size
    rng = np.random.default_rng(seed)
    dirs = unit_sphere_points(n, max(n_samples, n_check), seed)

    # the first program's states
    ps, ys = _sphere_points(rng, dirs, A, n_samples, period, periodic)
    pl, yl = _sphere_points(rng, dirs, lam, n_samples // 2, period, periodic)
    inner = inner_factor * lam
    pb, yb, rb = _shell_points(rng, dirs, inner, A, n_samples, period, periodic)
    if directions is not None:  # the singled-out directions, each with a cloud of neighbours
        d = np.asarray(directions, dtype=float).reshape(-1, n)
        d = d / np.linalg.norm(d, axis=1, keepdims=True)
        near = np.repeat(np.vstack([d, -d]), 16, axis=0)
        near = near + 0.15 * rng.normal(size=near.shape) * (np.arange(near.shape[0]) % 16 > 0)[:, None]
        near /= np.linalg.norm(near, axis=1, keepdims=True)
        m_near = near.shape[0]
        q1, y1 = _sphere_points(rng, near, A, m_near, period, periodic)
        q2, y2, r2 = _shell_points(rng, near, inner, A, 4 * m_near, period, periodic)
        ps, ys = np.concatenate([ps, q1]), np.vstack([ys, y1])
        pb, yb, rb = np.concatenate([pb, q2]), np.vstack([yb, y2]), np.concatenate([rb, r2])
    Vs = basis.values(ps, ys * a)
    Vl = basis.values(pl, yl * a)
    Db = basis.rates(pb, yb * a)
    wb = (rb / A) ** 2
    size = np.maximum(np.abs(Vs).max(axis=0), 1e-300)  # column scaling of the program

    c = None
    t = -np.inf
    done = 0
    clean = False
    program = _Program(basis.size, level_margin, coefficient_bound)
    pending = (Vs / size, Vl / size, Db / size, wb)  # the rows not yet in the program
    grid = period * np.arange(n_azimuths) / n_azimuths if periodic else np.zeros(1)
    for r in range(rounds + 1):
        report(f"design: start radius {lam:.3g}, bound {A:.3g}{', thorough' if thorough else ''}: round",
               r + 1, rounds + 1)
        program.add(*pending)
        c_new, t_new = program.solve()
        if c_new is None:
            break
        c, t = c_new / size, t_new
        done = r
        t_first = t if r == 0 else t_first
        if t <= 0 or (r >= 3 and t < 0.2 * t_first):  # no margin left, or the rounds squeeze it away
            break
        # counterexamples: an independent, denser sample ...
        d_r = unit_sphere_points(n, n_check, seed + 1 + r)
        qs, zs = _sphere_points(rng, d_r, A, n_check, period, periodic)
        ql, zl = _sphere_points(rng, d_r, lam, n_check // 2, period, periodic)
        qi, zi = _sphere_points(rng, d_r, inner, n_check // 2, period, periodic)
        qb, zb, rr = _shell_points(rng, d_r, inner, A, n_check, period, periodic)
        vs, vl, vi = (basis.values(q_, z_ * a) for q_, z_ in ((qs, zs), (ql, zl), (qi, zi)))
        db = basis.rates(qb, zb * a)
        ws, wl, wi, dw = vs @ c, vl @ c, vi @ c, db @ c
        # ... and the largest W' on the shell by local ascent from the best samples (with
        # ``thorough``, also the engine's own search of the shell: the sound rule's band="shell")
        rate = lambda p_, x_: basis.combined_rates(p_, x_, c)  # noqa: E731
        top = sphere_extremum(rate, grid, None, a, unit_sphere_points(n, n_check // 4, seed + 101 + r),
                              per_psi=False, free_psi=periodic, period=period,
                              shell=(np.full(grid.size, inner), np.full(grid.size, A)),
                              n_levels=4, n_refine=n_ascent, n_iter=30, keep=n_ascent)
        tops = [top]
        if thorough:
            fun = BasisFunction(basis, c, f)
            tops.append(band_max_dw(f, fun.W, fun.dW, 1.0, A, scales=a, period=period, psi=grid, inner=inner,
                                    autonomous=not periodic, n_sphere=n_check // 4, seed=seed + 201 + r,
                                    n_polish=64, n_lbfgs=16, n_sweep=256 if periodic else 0))
        qt = np.concatenate([e.psi for e in tops])
        xt = np.vstack([e.x for e in tops])
        vt = np.concatenate([e.value for e in tops])
        qb, zb = np.concatenate([qb, qt]), np.vstack([zb, xt / a])
        rr = np.concatenate([rr, np.linalg.norm(xt / a, axis=1)])
        db, dw = np.vstack([db, basis.rates(qt, xt)]), np.concatenate([dw, vt])
        # clean: W' < 0 on the whole shell sampled, and the ball of radius ``inner`` inside the
        # level set W reaches on the sphere (so the engine's shell starts at ``inner`` or below)
        clean = bool(np.all(dw < 0.0) and wi.max() < ws.min())
        if clean:
            break
        bad_s = ws < 1.0
        bad_l = wl > 1.0 - 0.5 * level_margin
        bad_b = dw > -0.5 * t * (rr / A) ** 2
        pending = (vs[bad_s] / size, vl[bad_l] / size, db[bad_b] / size, ((rr / A) ** 2)[bad_b])
        Vs, Vl = np.vstack([Vs, vs[bad_s]]), np.vstack([Vl, vl[bad_l]])
        Db, wb = np.vstack([Db, db[bad_b]]), np.concatenate([wb, ((rr / A) ** 2)[bad_b]])
    feasible = bool(c is not None and t > 0 and clean)
    fun = BasisFunction(basis, c, f, label) if c is not None and t > 0 else None
    return Design(function=fun, lam=lam, A=A, margin=float(t), feasible=feasible, rounds=done,
                  n_constraints=int(Vs.shape[0] + Vl.shape[0] + Db.shape[0]))


def _rows(Vs, Vl, Db, wb, level_margin):
    """The program's rows ``A_ub z <= b_ub`` in ``z = (c, t)``: ``-Vs c <= -1``,
    ``Vl c <= 1 - level_margin``, ``Db c + t wb <= 0``."""
    A_ub = np.vstack([
        np.column_stack([-Vs, np.zeros(Vs.shape[0])]),
        np.column_stack([Vl, np.zeros(Vl.shape[0])]),
        np.column_stack([Db, wb]),
    ])
    b_ub = np.concatenate([-np.ones(Vs.shape[0]), np.full(Vl.shape[0], 1.0 - level_margin),
                           np.zeros(Db.shape[0])])
    return A_ub, b_ub


def _highs():
    """scipy's HiGHS model class (kept across the rounds of one design), or None where this scipy
    does not have it (then :class:`_Program` solves each program afresh with ``linprog``)."""
    try:
        from scipy.optimize._highspy._core import _Highs, kHighsInf
    except ImportError:  # pragma: no cover - scipy without the bundled highspy core
        return None
    return _Highs, kHighsInf


class _Program:
    """``max t: Vs c >= 1, Vl c <= 1 - level_margin, Db c + t wb <= 0, |c_j| <= bound, t <= 100``
    over every row added so far, by row generation.

    The program on a subset of the rows (8 per unknown of the first rows, drawn at random), then
    the most violated of the others added (4 per unknown at a time) until none is violated by
    more than 1e-9: the optimum of the whole program, from programs a few times smaller. The
    rows a round of counterexamples adds (:meth:`add`) enter the same row generation. One HiGHS
    model is kept for all of it and re-solved from its last basis after each addition (the dual
    simplex then needs tens of iterations, not hundreds): on the trimmed helicopter at mu = 0.1
    a design's program took 0.2 s instead of 1.0 s (measured on its three rounds), the same
    optimum ``t`` to 1e-14. Where the optimum is not a single point, the ``c`` found may be
    another point of the optimal face than a program solved afresh finds.
    """

    def __init__(self, k: int, level_margin: float, bound: float, seed: int = 0):
        self.k, self.level_margin, self.bound, self.seed = k, level_margin, float(bound), seed
        self.A = np.zeros((0, k + 1))
        self.b = np.zeros(0)
        self.active = np.zeros(0, dtype=bool)
        self.model = None
        self.backend = _highs()

    def add(self, Vs, Vl, Db, wb) -> None:
        """Add rows (not yet in the solved program: the row generation takes the violated ones)."""
        A_ub, b_ub = _rows(Vs, Vl, Db, wb, self.level_margin)
        self.A, self.b = np.vstack([self.A, A_ub]), np.concatenate([self.b, b_ub])
        self.active = np.concatenate([self.active, np.zeros(b_ub.size, dtype=bool)])

    def _start(self) -> np.ndarray:
        m, k = self.b.size, self.k
        return np.random.default_rng(self.seed).choice(m, min(m, 8 * (k + 1)), replace=False)

    def _run(self, new: np.ndarray):
        """Add the rows ``new`` to the solved program and solve it: ``z`` or None."""
        self.active[new] = True
        k = self.k
        if self.backend is None:
            cost = np.zeros(k + 1)
            cost[-1] = -1.0
            res = linprog(cost, A_ub=self.A[self.active], b_ub=self.b[self.active],
                          bounds=[(-self.bound, self.bound)] * k + [(None, 100.0)], method="highs")
            return res.x if res.status == 0 and res.x is not None else None
        Highs, inf = self.backend
        if self.model is None:
            h = Highs()
            h.setOptionValue("output_flag", False)
            h.addVars(k + 1, np.concatenate([np.full(k, -self.bound), [-inf]]),
                      np.concatenate([np.full(k, self.bound), [100.0]]))
            h.changeColsCost(1, np.array([k], dtype=np.int32), np.array([-1.0]))
            self.model = h
        h = self.model
        rows = self.A[new]
        n_rows, n_cols = rows.shape
        starts = (np.arange(n_rows) * n_cols).astype(np.int32)
        columns = np.tile(np.arange(n_cols, dtype=np.int32), n_rows)
        h.addRows(n_rows, np.full(n_rows, -inf), self.b[new].astype(float), n_rows * n_cols, starts, columns,
                  np.ascontiguousarray(rows, dtype=float).reshape(-1))
        h.run()
        if h.modelStatusToString(h.getModelStatus()) != "Optimal":
            return None
        return np.array(h.getSolution().col_value, dtype=float)

    def solve(self) -> tuple[np.ndarray | None, float]:
        """``(c, t)`` at the optimum of the program over every row added, or ``(None, -inf)``
        where it has none (infeasible)."""
        k = self.k
        tol = 1e-9 * np.maximum(1.0, np.abs(self.b))
        new = self._start() if not self.active.any() else np.zeros(0, dtype=int)
        z = self._run(new) if new.size or self.model is None else self._current()
        for _ in range(100):
            if z is None:
                return None, -np.inf
            excess = self.A @ z - self.b
            bad = np.flatnonzero((excess > tol) & ~self.active)
            if bad.size == 0:
                return z[:k], float(z[-1])
            z = self._run(bad[np.argsort(-excess[bad])][:4 * (k + 1)])
        return None, -np.inf

    def _current(self):
        """The last solution (the rows added since are checked by the row generation)."""
        if self.model is None:
            return self._run(np.zeros(0, dtype=int))
        return np.array(self.model.getSolution().col_value, dtype=float)


def largest_design(basis: Basis, f: Function, scales, *, lam_start: float, lam_max: float,
                   ratios: Sequence[float] = (2.5, 3.5), growth: float = 2.0, n_bisect: int = 3,
                   lam_min: float | None = None, harden_rounds: int = 12, bisect_below: bool = False,
                   **options) -> Design:
    """The largest start radius ``lam`` for which :func:`design` succeeds, with ``A = ratio lam``.

    From ``lam_start``, grows ``lam`` by ``growth`` while some ratio succeeds (up to ``lam_max``;
    or, if ``lam_start`` fails, shrinks it by ``growth`` until one succeeds, down to
    ``lam_min``). Then the largest success is designed again with ``thorough=True`` (the design
    returned is a thorough one). If that passes, ``n_bisect`` geometric bisection steps between
    it and the first failure follow, each success designed thoroughly at once and kept where
    that passes; if it fails, the next largest successes are designed thoroughly, largest first
    (four in all), and the first that passes is returned, without the bisection above it (it would
    only search above a start radius whose thorough design already failed); with ``bisect_below``,
    ``n_bisect`` geometric bisection steps between the next largest success and the start radius
    whose thorough design failed come first, each success designed thoroughly at once (the next
    largest successes follow only if none passes). ``feasible=False`` if no
    thorough design passes; every attempt is in ``tried``. The first ``lam`` tries every ratio,
    smallest first; later ones the ratio that succeeded last and its two neighbours in
    ``ratios``.

    The order saves the searches a failed thorough design makes useless: on the trimmed
    helicopter at mu = 0.1 the bisection above a start radius of 3.2 tried four designs that
    failed (a third of the search's time) before the thorough design at 3.2 failed and the one
    at 1.6 was returned, which is what this order returns without them.

    Parameters
    ----------
    basis, f, scales
        As :func:`design`.
    lam_start, lam_max : float
        Start radius of the search and the largest searched, scaled norm.
    ratios : sequence of float
        Ratios ``A / lam`` tried at each ``lam`` (each > 1).
    growth : float
        Factor between the start radii of the growing (or shrinking) phase (> 1).
    n_bisect : int
        Bisection steps.
    lam_min : float, optional
        Smallest start radius tried when shrinking (default ``lam_start / 1000``).
    harden_rounds : int
        Rounds of counterexamples of the thorough designs at the end.
    bisect_below : bool
        Where the largest success fails thoroughly, bisect below it (above).
    **options
        Passed on to :func:`design`.

    Returns
    -------
    Design
    """
    lam = _positive_float("lam_start", lam_start)
    lam_max = _positive_float("lam_max", lam_max)
    lam_min = lam / 1000 if lam_min is None else _positive_float("lam_min", lam_min)
    growth = _positive_float("growth", growth)
    if growth <= 1:
        raise ValueError(f"growth must be > 1, got {growth!r}")
    ratios = tuple(float(r) for r in ratios)
    if not ratios or any(not r > 1 for r in ratios):
        raise ValueError(f"every ratio A / lam must be > 1, got {ratios}")
    tried = []
    last = [0]

    def attempt(lam_):  # the ratio that succeeded last, then its neighbours
        i = last[0]
        order = [ratios[j] for j in (i, i + 1, i - 1) if 0 <= j < len(ratios)] if tried else list(ratios)
        for ratio in order:
            d = design(basis, f, scales, ratio * lam_, lam_, **options)
            tried.append((float(lam_), float(ratio * lam_), d.feasible))
            if d.feasible:
                last[0] = ratios.index(ratio)
                return d
        return None

    best = attempt(lam)
    fail = None
    if best is None:  # shrink until one succeeds
        fail = lam
        while best is None and lam / growth >= lam_min:
            lam /= growth
            best = attempt(lam)
            if best is None:
                fail = lam
        if best is None:
            return Design(function=None, lam=lam, A=ratios[0] * lam, margin=-np.inf, feasible=False, rounds=0,
                          n_constraints=0, tried=tuple(tried))
    else:
        while lam < lam_max:
            lam = min(lam * growth, lam_max)
            d = attempt(lam)
            if d is None:
                fail = lam
                break
            best = d
    thorough = dict(options, rounds=harden_rounds, thorough=True)

    def harden(d_: Design) -> Design | None:  # the design again, thoroughly (the engine's search each round)
        h = design(basis, f, scales, d_.A, d_.lam, **thorough)
        tried.append((float(d_.lam), float(d_.A), h.feasible))
        return h if h.feasible else None

    def bisect(lo: float, hi: float) -> Design | None:  # geometric, each success hardened at once
        found = None
        for _ in range(n_bisect):
            mid = np.sqrt(lo * hi)
            d = attempt(mid)
            h = harden(d) if d is not None else None
            if h is None:
                hi = mid
            else:
                found, lo = h, mid
        return found

    hardened = harden(best)
    if hardened is None:  # the largest success fails thoroughly
        successes = sorted({(l_, A_) for l_, A_, ok in tried[:-1] if ok and l_ < best.lam}, reverse=True)
        if successes and bisect_below:  # between the next largest success and it
            hardened = bisect(successes[0][0], best.lam)
        # none of it passes: the next largest successes, largest first
        for lam_, A_ in (successes[:3] if hardened is None else ()):
            h = design(basis, f, scales, A_, lam_, **thorough)
            tried.append((float(lam_), float(A_), h.feasible))
            if h.feasible:
                hardened = h
                break
    elif fail is not None:  # bisection above it
        hardened = bisect(best.lam, fail) or hardened
    if hardened is not None:
        return Design(function=hardened.function, lam=hardened.lam, A=hardened.A, margin=hardened.margin,
                      feasible=True, rounds=hardened.rounds, n_constraints=hardened.n_constraints,
                      tried=tuple(tried))
    return Design(function=best.function, lam=best.lam, A=best.A, margin=best.margin, feasible=False,
                  rounds=best.rounds, n_constraints=best.n_constraints, tried=tuple(tried))
