"""Proofs from Taylor models: condition (h), or W' < 0 on a level set, shown by branch and bound
over directions (rotorlyap.methods.band, rotorlyap.methods.proof.prove_quadratic_models).

Facts checked, on systems whose largest provable bound is known in closed form (a prover that
proves too much fails them):

* ``x' = -x + x^3`` with ``W = x^2 / 2``: ``W' = -x^2 + x^4 < 0`` exactly for ``|x| < 1``; the
  proved bound lies in ``[0.95, 1)``;
* ``x' = -x + x^2``: ``W' = -x^2 + x^3``, negative on the band ``|x| = A`` exactly for ``A < 1``
  (the sign of the quadratic term matters on one side only); the proved bound lies in ``[0.95, 1)``;
* a rotated linear system with a cubic term, ``x' = (-I + w J) x + phi(x) x`` in 3 dimensions with
  ``phi(x) = x^T F x`` an indefinite quadratic form whose worst direction is oblique to the axes:
  with ``W = |x|^2 / 2``, ``W' = |x|^2 (phi(x) - 1)``, negative on the sphere ``|x| = A`` exactly for
  ``A < 1 / sqrt(lambda_max(F))``; the proved bound lies in ``[0.85, 1)`` times that;
* the same system with the cubic term scaled up a hundredfold: the proved bound follows the closed
  form down (a prover blind to the cubic term would not);
* the face polynomials reproduce ``W'`` at random points of the band, and the compiled box bounds
  contain a face polynomial's value at the centre and every sampled partial derivative in the box;
* the blade: every Table I hover proved between 0.8 and 1 of its numerical bound, above the balls'
  proof, with the float ``W'`` negative on the proved sphere;
* ``x' = (x^T F x - 1) x`` with an elongated ``W = x^T S x``: on the level set ``W = c`` the proof
  reaches its closed-form bound (2.2 times the band's) and never passes it.
"""

from __future__ import annotations

import numpy as np
import pytest

from rotorlyap.methods import intervals as iv
from rotorlyap.methods import taylor as tm
from rotorlyap.methods.balls import Balls
from rotorlyap.methods.band import band_polynomial
from rotorlyap.methods.proof import prove_quadratic_models


class PolynomialSystem:
    """``x' = K(x) x`` (no residual) with the averaged Jacobian ``K`` given in closed form as a
    function of Taylor models of the state (``K_of(x) -> n x n nested list of models or floats``),
    and ``W = x^T S x`` with a constant ``S``."""

    def __init__(self, n: int, K_of, J0: np.ndarray, S: np.ndarray):
        self.n, self.K_of, self.J0, self.S = n, K_of, np.asarray(J0, float), np.asarray(S, float)

    def residual(self, N: int):
        return Balls(np.zeros((N, self.n))), {}

    def linear(self, N: int):
        return Balls(np.broadcast_to(self.J0, (N, self.n, self.n)).copy())

    def jacobian_models(self, N: int, radius, order: int):
        xs = tm.variables(np.zeros(self.n), np.asarray(radius, float), order)
        sp = xs[0].space
        K = self.K_of(xs)
        coef = np.zeros((N, sp.size, self.n, self.n))
        rem = np.zeros((N, self.n, self.n))
        for i in range(self.n):
            for j in range(self.n):
                kij = K[i][j]
                if not isinstance(kij, tm.TaylorModel):
                    kij = tm.TaylorModel.constant(float(kij), sp)
                coef[:, :, i, j] = kij.coef
                rem[:, i, j] = kij.rem
        return Balls(coef), rem, sp.exponents, {}

    def quadratic(self, N: int):
        S = Balls(np.broadcast_to(self.S, (N, self.n, self.n)).copy())
        return S, Balls(np.zeros(S.shape))


def _prove(system: PolynomialSystem, A: float, **kw):
    with iv.arithmetic("balls"):
        return prove_quadratic_models(system, system.quadratic, A, scales=np.ones(system.n), **kw)


def test_cubic_decay_is_proved_up_to_its_closed_form_region():
    # x' = -x + x^3: K(x) = -1 + x^2, W = x^2 / 2, W' = -x^2 + x^4 < 0 iff |x| < 1
    system = PolynomialSystem(1, lambda x: [[x[0] * x[0] - 1.0]], [[-1.0]], [[0.5]])
    proof = _prove(system, 2.0)
    assert proof.proved
    assert 0.95 <= proof.A < 1.0


def test_quadratic_term_is_proved_up_to_its_one_sided_region():
    # x' = -x + x^2: K(x) = -1 + x (the averaged Jacobian of -1 + 2 x), W' = -x^2 + x^3 < 0 on |x| = A iff A < 1
    system = PolynomialSystem(1, lambda x: [[x[0] - 1.0]], [[-1.0]], [[0.5]])
    proof = _prove(system, 1.5)
    assert proof.proved
    assert 0.95 <= proof.A < 1.0


F = np.array([[0.5, 0.4, 0.0], [0.4, 0.25, 0.5], [0.0, 0.5, -0.3]])
W_ROT = 0.7


def _rotated_cubic(scale: float) -> tuple[PolynomialSystem, float]:
    """``x' = (-I + w J) x + s phi(x) x``, ``phi = x^T F x``: ``K(x) = -I + w J + s (phi I + x grad phi^T) / 3``
    (``f(s x) = s^3 f(x)`` for the cubic term, so its averaged Jacobian is a third of its Jacobian);
    the exact bound ``1 / sqrt(s lambda_max(F))``."""
    Jskew = np.array([[0.0, 1.0, 0.0], [-1.0, 0.0, 1.0], [0.0, -1.0, 0.0]])
    L = -np.eye(3) + W_ROT * Jskew

    def K_of(x):
        Fx = [sum(x[j] * F[i, j] for j in range(3) if F[i, j] != 0.0) for i in range(3)]
        phi = sum(x[i] * Fx[i] for i in range(3))
        out = []
        for i in range(3):
            row = []
            for j in range(3):
                term = x[i] * Fx[j] * 2.0          # x_i d(phi)/dx_j, grad phi = 2 F x
                if i == j:
                    term = term + phi
                row.append(term * (scale / 3.0) + L[i, j])
            out.append(row)
        return out

    exact = 1.0 / np.sqrt(scale * np.linalg.eigvalsh(F)[-1])
    return PolynomialSystem(3, K_of, L, 0.5 * np.eye(3)), exact


@pytest.mark.parametrize("scale", [1.0, 100.0])
def test_rotated_system_with_a_cubic_term_is_proved_within_its_closed_form_bound(scale):
    system, exact = _rotated_cubic(scale)
    proof = _prove(system, 2.0 * exact)
    assert proof.proved
    assert 0.85 * exact <= proof.A < exact


def test_face_polynomials_reproduce_w_dot_on_the_band():
    system, exact = _rotated_cubic(1.0)
    A = 0.8 * exact
    coef, rem, exps, _ = system.jacobian_models(1, A * np.ones(3), 3)
    S, dS = system.quadratic(1)
    bp = band_polynomial(S, dS, coef, exps, rem, np.zeros(1), A)
    rng = np.random.default_rng(3)
    for face in range(6):
        i, sign = face // 2, (1.0 if face % 2 == 0 else -1.0)
        for _ in range(5):
            free = rng.uniform(-1, 1, 2)
            sigma = rng.uniform(0.1, 1.0) / np.sqrt(3.0)
            v = np.insert(free, i, sign)
            x = A * sigma * v
            phi = x @ F @ x
            f = (system.J0 @ x) + phi * x
            w_dot = 2 * x @ system.S @ f
            H = np.sum(bp.coef.mid[0, face] * np.prod(np.append(free, sigma)[None, :] ** bp.exponents, axis=1))
            quad = v @ (system.J0.T @ system.S + system.S @ system.J0) @ v
            assert np.isclose(quad + sigma * H, w_dot / (A * sigma) ** 2, rtol=1e-10, atol=1e-12)


@pytest.mark.parametrize("cg", ["forward", "neutral", "backward"])
def test_the_taylor_prover_reaches_most_of_every_table_i_hover_and_never_exceeds_it(cg):
    """prove_blade (Taylor models, the default: on the level set) in hover: between 0.8 and 1 of the
    numerical bound (issue 41's target), the band's proof between 0.8 of it and the level set's,
    the balls' proof below both; the float W' negative at states sampled on the proved level set,
    and on the band's outer sphere, where the band comes nearest to W' = 0."""
    from rotorlyap import certify
    from rotorlyap.analysis.proof import prove_blade
    from rotorlyap.model.parameters import BladeParameters

    cert = certify(BladeParameters.table_i(cg), 0.0, function="quadratic")
    fun = cert.lyapunov
    proof = prove_blade(fun, cert.bound)
    band = prove_blade(fun, cert.bound, level_set=False)
    assert proof.proved and band.proved and "level set" in proof.message and "band" in band.message
    assert 0.8 * cert.bound <= band.A <= proof.A <= cert.bound
    assert prove_blade(fun, cert.bound, method="balls").A < band.A
    rng = np.random.default_rng(5)
    u = rng.normal(size=(4000, 6))
    u /= np.linalg.norm(u, axis=1)[:, None]
    x = u * band.A * fun.scales
    assert np.all(fun.dW(np.zeros(x.shape[0]), x) < 0)
    S = fun.solution.P_grid[0]
    r = np.sqrt(proof.level / np.einsum("mi,ij,mj->m", u, S, u))      # where W = c along each ray
    assert np.all(fun.dW(np.zeros(u.shape[0]), u * r[:, None] * fun.scales) < 0)


def test_the_box_bounds_contain_the_polynomial_and_its_gradient():
    """The compiled bound of a face polynomial over boxes (rotorlyap.methods.band._Evaluator): the
    ball at the centre contains the polynomial's value there (floats in long double), and the
    gradient's bound over the box is at least every sampled partial derivative in it; the second-order
    form's gradient at the centre bounds the exact one, its Hessian balls contain every sampled second
    derivative in the box."""
    from rotorlyap.methods.band import _Evaluator

    system, exact = _rotated_cubic(3.0)
    A = 0.9 * exact
    coef, rem, exps, _ = system.jacobian_models(1, A * np.ones(3), 3)
    S, dS = system.quadratic(1)
    bp = band_polynomial(S, dS, coef, exps, rem, np.zeros(1), A, keep=None)
    ev = _Evaluator(bp)
    rng = np.random.default_rng(11)
    B = 64
    face = rng.integers(0, 6, B)
    xc = rng.uniform(-0.8, 0.8, (B, 3))
    xc[:, -1] = rng.uniform(0.2, 0.8, B)
    xw = rng.uniform(0.0, 0.2, (B, 3))
    c = Balls(bp.coef.mid[0, face], bp.coef.rad[0, face])
    centre, grad = ev.centre_and_gradient(c, xc, xw)
    E = bp.exponents
    exact_c = np.sum(c.mid.astype(np.longdouble) * np.prod(xc[:, None, :].astype(np.longdouble) ** E, axis=-1), axis=1)
    assert np.all((centre.lower() <= exact_c) & (exact_c <= centre.upper()))
    for _ in range(20):
        x = xc + xw * rng.uniform(-1, 1, xc.shape)
        for i in range(3):
            dE = E.copy()
            mult = dE[:, i].astype(float)
            dE[:, i] = np.maximum(dE[:, i] - 1, 0)
            g = np.sum(c.mid * mult * np.prod(x[:, None, :] ** dE, axis=-1), axis=1)
            assert np.all(np.abs(g) <= grad[:, i] * (1 + 1e-12) + 1e-12)
    # the second-order form's pieces: the gradient at the centre and the Hessian over the box
    g_c, hess = ev.second_order(c, xc, xw)
    for i in range(3):
        dE = E.copy()
        mult = dE[:, i].astype(float)
        dE[:, i] = np.maximum(dE[:, i] - 1, 0)
        g = np.sum(c.mid * mult * np.prod(xc[:, None, :] ** dE, axis=-1), axis=1)
        assert np.all(np.abs(g) <= g_c[:, i] * (1 + 1e-12) + 1e-12)
    for _ in range(20):
        x = xc + xw * rng.uniform(-1, 1, xc.shape)
        for p, (i, j) in enumerate(ev.pairs):
            dE = E.copy()
            mult = (dE[:, i] * (dE[:, i] - 1) if i == j else dE[:, i] * dE[:, j]).astype(float)
            dE[:, i] -= 1
            dE[:, j] -= 1
            dE = np.maximum(dE, 0)
            h = np.sum(c.mid * mult * np.prod(x[:, None, :] ** dE, axis=-1), axis=1)
            slack = 1e-12 * (1 + np.abs(h))
            assert np.all((hess[:, p].lower() - slack <= h) & (h <= hess[:, p].upper() + slack))


def test_the_split_by_share_never_proves_beyond_the_closed_form(monkeypatch):
    """The other split rule (:data:`rotorlyap.methods.band.SPLIT_BY_SHARE`) chooses only where a box
    is cut: the rotated system is proved within, never beyond, its closed-form bound with it too."""
    import rotorlyap.methods.band as band

    monkeypatch.setattr(band, "SPLIT_BY_SHARE", True)
    system, exact = _rotated_cubic(1.0)
    proof = _prove(system, 2.0 * exact)
    assert proof.proved
    assert 0.85 * exact <= proof.A < exact


def test_proofs_over_shells_of_cubes_stay_within_the_closed_form_bounds():
    """The proof over shells of cubes (``prove_quadratic_models(..., shells=)``): each shell's search
    covers only its part of the band, so a gap between shells would let it prove too much. On the
    one-dimensional cubic and the rotated system with its cubic term (also scaled up a hundredfold)
    it proves within, never beyond, the closed-form bound, and above 0.85 of it."""
    cubic = PolynomialSystem(1, lambda x: [[x[0] * x[0] - 1.0]], [[-1.0]], [[0.5]])
    proof = _prove(cubic, 1.0, shells=0.8)
    assert proof.proved and 0.95 <= proof.A < 1.0
    assert "shells of cubes" in proof.message
    for scale in (1.0, 100.0):
        system, exact = _rotated_cubic(scale)
        proof = _prove(system, exact, shells=0.8)
        assert proof.proved
        assert 0.85 * exact <= proof.A < exact
    with pytest.raises(ValueError, match="shells must lie in"):
        _prove(cubic, 1.0, shells=1.0)


def test_a_shell_search_covers_its_shell_only_and_a_complete_search_proves_all_or_nothing():
    """``largest_bound``'s ``sigma_floor`` and ``complete``. ``x' = x - 2 x^3`` with ``W = x^2 / 2``:
    ``W' = x^2 (1 - 2 x^2)``, positive for ``|x| < 1 / sqrt(2)``, negative beyond. Over the cube of 1
    the shell ``0.75 <= |x| <= 1`` is shown (complete); the whole band is not (the complete search
    returns 0, not a smaller bound), nor the shell from 0.6, which reaches into ``W' > 0``."""
    from rotorlyap.methods.band import largest_bound

    system = PolynomialSystem(1, lambda x: [[1.0 - 2.0 * x[0] * x[0]]], [[1.0]], [[0.5]])
    cube = 1.0
    coef, rem, exps, _ = system.jacobian_models(1, cube * np.ones(1), 3)
    S, dS = system.quadratic(1)
    bp = band_polynomial(S, dS, coef, exps, rem, np.zeros(1), cube)
    level = 0.5 * 0.01 ** 2
    with iv.arithmetic("balls"):
        shell = largest_bound(bp, 1.0, level, sigma_floor=0.75, complete=True)
        inner = largest_bound(bp, 1.0, level, sigma_floor=0.6, complete=True)
        whole = largest_bound(bp, 1.0, level, complete=True)
    assert 0.999 < shell.A <= 1.0
    assert inner.A == 0.0 and whole.A == 0.0
    with pytest.raises(ValueError, match="sigma_floor"):
        largest_bound(bp, 1.0, level, sigma_floor=1.0)


def test_where_no_bound_closes_every_shell_the_search_over_one_cube_follows():
    """A bound asked far beyond the region (``x' = -x + x^3``, region ``|x| < 1``, asked 10): none of
    the shells' first bounds (10 down to 8) closes, and the proof falls back to the search over one
    cube, which still ends inside the closed form; ``tried`` lists the shells' bounds first."""
    cubic = PolynomialSystem(1, lambda x: [[x[0] * x[0] - 1.0]], [[-1.0]], [[0.5]])
    proof = _prove(cubic, 10.0, shells=0.8)
    assert proof.proved and 0.5 <= proof.A < 1.0
    assert [ok for _, ok in proof.tried[:5]] == [False] * 5
    assert [round(T, 6) for T, _ in proof.tried[:2]] == [10.0, 9.5]
    assert "shells" not in proof.message


def _radial_cubic(S: np.ndarray, F: np.ndarray) -> PolynomialSystem:
    """``x' = (x^T F x - 1) x`` with ``W = x^T S x``: ``W' = 2 (x^T F x - 1) W``. ``K(x) = -I + (phi I
    + x grad phi^T) / 3`` (the cubic term's averaged Jacobian, as in :func:`_rotated_cubic`)."""
    n = S.shape[0]

    def K_of(x):
        Fx = [sum(x[j] * F[i, j] for j in range(n) if F[i, j] != 0.0) for i in range(n)]
        phi = sum(x[i] * Fx[i] for i in range(n))
        return [[(x[i] * Fx[j] * 2.0 + (phi if i == j else 0.0)) * (1.0 / 3.0) - (1.0 if i == j else 0.0)
                 for j in range(n)] for i in range(n)]

    return PolynomialSystem(n, K_of, -np.eye(n), S)


def test_the_level_set_proof_reaches_its_closed_form_bound_beyond_the_bands():
    """``prove_quadratic_models(..., level_set=True)``: ``W' < 0`` on the level set ``W = c`` alone
    (``c = A^2 min eig S``), which makes ``{W <= c}`` invariant. For ``x' = (x^T F x - 1) x`` with
    ``W = x^T S x`` (``S`` and ``F`` rotated off the axes), ``W' = 2 (x^T F x - 1) W``:

    * on the level set, ``max x^T F x = c lambda_max(S^-1/2 F S^-1/2)``: the level-set condition
      holds exactly for ``A < 1 / sqrt(min eig S lambda_max(S^-1/2 F S^-1/2))`` (2.24 here);
    * on the band ``|x| <= A, W >= c``, which reaches the sphere in every direction, exactly for
      ``A < 1 / sqrt(lambda_max F)`` (1 here).

    The level-set proof reaches above 0.85 of its own bound and never beyond it; the band proof
    stays below the band's; asked beyond its bound, the level-set proof of that bound fails."""
    c, s = np.cos(0.4), np.sin(0.4)
    Rot = np.array([[c, -s], [s, c]])
    S = Rot @ np.diag([0.5, 4.5]) @ Rot.T
    F = Rot @ np.diag([0.2, 1.0]) @ Rot.T
    system = _radial_cubic(S, F)
    w, V = np.linalg.eigh(S)
    root = V @ np.diag(w ** -0.5) @ V.T
    exact_level = 1.0 / np.sqrt(w[0] * np.linalg.eigvalsh(root @ F @ root)[-1])
    exact_band = 1.0 / np.sqrt(np.linalg.eigvalsh(F)[-1])
    assert exact_level > 2.0 * exact_band
    proof = _prove(system, exact_level, shells=0.8, level_set=True, first_cube=0.9)
    assert proof.proved and "level set" in proof.message
    assert 0.85 * exact_level <= proof.A < exact_level
    band = _prove(system, exact_level, shells=0.8)
    assert band.proved and band.A < exact_band
    # asked beyond the closed form: the shells' first bounds (1.2 and 1.14 times it) fail; the fallback is
    # the band's search
    beyond = _prove(system, 1.2 * exact_level, shells=0.8, level_set=True, refits=1, max_boxes=20_000)
    assert beyond.A < exact_band and "level set" not in beyond.message
    with pytest.raises(ValueError, match="level_set"):
        _prove(system, exact_level, level_set=True)
    from rotorlyap.methods.band import largest_bound

    coef, rem, exps, _ = system.jacobian_models(1, np.ones(2), 3)
    bp = band_polynomial(*system.quadratic(1), coef, exps, rem, np.zeros(1), 1.0)
    with pytest.raises(ValueError, match="level_set needs complete"):
        largest_bound(bp, 1.0, 0.4, level_set=True)
