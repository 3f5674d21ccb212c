"""Float balls (rotorlyap.methods.balls) against Arb, and the blade's proofs built on them.

Facts checked:

* every operation of :class:`Balls` (``+ - * /``, reciprocal, ``sqrt``, ``sin``, ``cos``, ``atan``,
  sums, matrix products, ``|x|``, ``max(x, 0)``, ``min(x, c)``) contains the exact result: the Arb
  image (at 200 bits) of points of the operands, on random inputs and adversarial ones (huge and
  tiny magnitudes, subnormals, cancellation, denominators near or containing zero);
* what cannot be enclosed (a division by a ball containing zero, the square root of a ball
  reaching below zero, overflow) gives infinite bounds, never numbers;
* Jets on float balls contain the exact value, gradient and Hessian of a composite function;
* the blade's enclosure on float balls contains the float model at sampled states (hover, and the
  compressible forward flight), and is about as tight as the Arb one;
* the hover proofs on float balls prove the same bound as on Arb balls, the start radius to
  round-off.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from flint import arb, ctx

from rotorlyap.conventions import DEFAULT_SCALES
from rotorlyap.methods import intervals as iv
from rotorlyap.methods.balls import Balls, from_bounds, matmul
from rotorlyap.model.blade import Blade
from rotorlyap.model.parameters import BladeParameters

RNG_SEED = 23


def _adversarial(rng, n: int) -> tuple[np.ndarray, np.ndarray]:
    """Midpoints and radii spanning the float range: huge, tiny, subnormal, exact, wide."""
    scale = 10.0 ** rng.uniform(-300, 300, n)
    mid = rng.choice([-1.0, 1.0], n) * rng.uniform(0.5, 2.0, n) * scale
    mid[: n // 8] = rng.normal(size=n // 8)  # ordinary numbers
    mid[n // 8: n // 4] = rng.choice([5e-324, -3e-320, 2.0 ** -1022, 1.0, -1.0, 0.0], n // 4 - n // 8)
    rel = 10.0 ** rng.uniform(-17, 0.5, n)
    rad = np.abs(mid) * rel
    rad[::5] = 0.0  # exact points
    rad[1::7] = 10.0 ** rng.uniform(-320, -300, rad[1::7].size)
    return mid, rad


def _points(mid: float, rad: float, rng, k: int = 4) -> list:
    """Arb points of the ball: its two ends, its midpoint and random points (exact floats)."""
    pts = [arb(mid) - arb(rad), arb(mid) + arb(rad), arb(mid)]
    pts += [arb(mid) + arb(rad) * arb(float(t)) for t in rng.uniform(-1, 1, k)]
    return pts


def _contains(b: Balls, i: int, exact: arb) -> bool:
    """The ball ``i`` of ``b`` contains the (high-precision, thin) Arb ball ``exact``."""
    lo, hi = b.lower().reshape(-1)[i], b.upper().reshape(-1)[i]
    if not exact.is_finite():
        return not (np.isfinite(lo) and np.isfinite(hi))
    return bool(arb(float(lo)) <= exact.lower() and exact.upper() <= arb(float(hi))) if np.isfinite(lo) and \
        np.isfinite(hi) else True


@pytest.fixture
def high_precision():
    old = ctx.prec
    ctx.prec = 2300  # the float range: sums of any two floats are exact
    yield
    ctx.prec = old


def _check_binary(op, arb_op, n: int, rng, exclude_zero: bool = False, exact_second: bool = False):
    m1, r1 = _adversarial(rng, n)
    m2, r2 = _adversarial(rng, n)
    # cancellation: half of the second operands are minus the first, or equal, to the last bit
    m2[::2] = -m1[::2] * (1 + rng.choice([0.0, 2.0 ** -52, -2.0 ** -52], m1[::2].size))
    a, b = Balls(m1, r1), Balls(m2, r2)
    out = op(a, b)
    for i in range(n):
        for x in _points(m1[i], r1[i], rng, 2):
            for y in ([arb(m2[i])] if exact_second else _points(m2[i], r2[i], rng, 2)):
                if exclude_zero and y == 0:
                    continue
                exact = arb_op(x, y)
                if np.isfinite(out.mid[i]) and np.isfinite(out.rad[i]):
                    assert _contains(out, i, exact), (i, m1[i], r1[i], m2[i], r2[i], out.mid[i], out.rad[i])


def test_sums_differences_and_products_contain_every_exact_result(high_precision):
    rng = np.random.default_rng(RNG_SEED)
    _check_binary(lambda a, b: a + b, lambda x, y: x + y, 400, rng)
    _check_binary(lambda a, b: a - b, lambda x, y: x - y, 400, rng)
    _check_binary(lambda a, b: a * b, lambda x, y: x * y, 400, rng)
    _check_binary(lambda a, b: a * b.mid, lambda x, y: x * y, 200, rng, exact_second=True)  # float operand
    _check_binary(lambda a, b: a + b.mid, lambda x, y: x + y, 200, rng, exact_second=True)


def test_quotients_contain_every_exact_result_and_a_zero_denominator_gives_no_bound(high_precision):
    rng = np.random.default_rng(RNG_SEED + 1)
    _check_binary(lambda a, b: a / b, lambda x, y: x / y, 400, rng, exclude_zero=True)
    _check_binary(lambda a, b: a / b.mid, lambda x, y: x / y, 200, rng, exclude_zero=True, exact_second=True)
    x = Balls([1.0, -2.0, 3.0, 1.0], [0.0, 0.1, 0.0, 0.0])
    y = Balls([0.0, 1e-3, -1.0, 5e-324], [1.0, 1e-3, 1.0, 0.0])  # contain 0, touch it, tiny
    q = x / y
    assert not np.isfinite(q.upper()[:3]).any() and not np.isfinite(q.lower()[:3]).any()
    assert not np.isfinite(q.magnitude()[3])  # 1 / 5e-324 overflows: no bound


def test_square_roots_contain_every_exact_result_and_a_negative_ball_gives_no_bound(high_precision):
    rng = np.random.default_rng(RNG_SEED + 2)
    m, r = _adversarial(rng, 400)
    m = np.abs(m)
    r = np.minimum(r, 0.9 * m)
    out = Balls(m, r).sqrt()
    for i in range(m.size):
        for x in _points(m[i], r[i], rng):
            assert _contains(out, i, x.sqrt()), (m[i], r[i])
    bad = Balls([0.0, 1.0, -1e-300], [1.0, 1.5, 0.0]).sqrt()
    assert not np.isfinite(bad.magnitude()).any()


@pytest.mark.parametrize("name", ["sin", "cos", "atan"])
def test_elementary_functions_contain_every_exact_result(name, high_precision):
    """Points near multiples of pi/2 (argument reduction), wide balls (range clipping), large
    and tiny arguments; atan near +-1 and beyond (reduction and halvings)."""
    rng = np.random.default_rng(RNG_SEED + 3)
    m = np.concatenate([rng.uniform(-20, 20, 200), np.pi / 2 * np.arange(-12, 13), [0.0, 1e-300, -5e-324, 1.0,
                        -1.0, 1e5, -3e5, 1e15, 1e300], rng.uniform(-1.1, 1.1, 50)])
    r = np.concatenate([10.0 ** rng.uniform(-16, 1, 200), np.zeros(25), np.zeros(9), 10.0 ** rng.uniform(-9, -1, 50)])
    out = getattr(Balls(m, r), name)()
    for i in range(m.size):
        for x in _points(m[i], r[i], rng):
            assert _contains(out, i, getattr(x, name)()), (name, m[i], r[i], out.mid[i], out.rad[i])
    # thin balls stay thin where the argument is moderate
    thin = getattr(Balls(rng.uniform(-6, 6, 100)), name)()
    assert np.all(thin.rad < 1e-14)


def test_piecewise_functions_contain_every_exact_result(high_precision):
    rng = np.random.default_rng(RNG_SEED + 4)
    m = rng.normal(size=300)
    r = np.abs(rng.normal(size=300)) * rng.choice([0.0, 1e-12, 0.5], 300)
    b = Balls(m, r)
    cap = 0.3
    absb, pos, mn = abs(b), b.nonnegative_part(), b.minimum(cap)
    for i in range(m.size):
        for x in _points(m[i], r[i], rng):
            assert _contains(absb, i, abs(x))
            assert _contains(pos, i, x.nonnegative_part())
            assert _contains(mn, i, x.min(arb(cap)))


def test_sums_and_matrix_products_contain_the_exact_ones(high_precision):
    """Rump's product: every product of point matrices sampled in the balls (Arb, exact) lies in
    the result, including ill-conditioned inner products (large terms that cancel)."""
    rng = np.random.default_rng(RNG_SEED + 5)
    A = rng.normal(size=(20, 6, 6)) * 10.0 ** rng.uniform(-5, 5, (20, 6, 6))
    B = rng.normal(size=(20, 6, 6))
    B[:, :, 0] = -B[:, :, 1]  # rows that cancel
    A[:, :, 0] = A[:, :, 1]
    rA, rB = np.abs(A) * 1e-10, np.abs(B) * rng.choice([0.0, 1e-8], (20, 6, 6))
    C = matmul(Balls(A, rA), Balls(B, rB))
    S = Balls(A, rA).sum(axis=-1)
    for _ in range(3):
        tA = A + rA * rng.uniform(-1, 1, A.shape)
        tB = B + rB * rng.uniform(-1, 1, B.shape)
        for k in range(0, 20, 3):
            for i in range(6):
                row = [arb(float(tA[k, i, j])) for j in range(6)]
                assert _contains(S, k * 6 + i, sum(row, arb(0)))
                for j in range(6):
                    exact = sum((row[m] * arb(float(tB[k, m, j])) for m in range(6)), arb(0))
                    assert _contains(C, (k * 6 + i) * 6 + j, exact)


def test_overflow_and_nan_never_give_a_finite_bound():
    big = Balls([1e308, -1e308, np.nan], [1e308, 0.0, 0.0])
    for out in (big * 10.0, big + big, big * big, (big * 10.0).sin(), (big * 10.0).atan(), (big * big) / 3.0):
        lo, hi = out.lower(), out.upper()
        assert not np.all(np.isfinite(lo[[0, 2]]) & np.isfinite(hi[[0, 2]]))
    assert not np.isfinite((big * 10.0)[1].upper())  # -1e309 overflows to -inf
    assert from_bounds(-np.inf, 1.0).upper() == np.inf


def test_jets_on_float_balls_enclose_values_gradients_and_hessians_of_a_composite_function():
    """f = sin(x y) + sqrt(1 + x^2) / (2 + cos y) - x / y + atan-free: as tests/test_proof.py for Arb,
    with the Jet on float balls, and the float balls no wider than 1e-12 beyond the Arb ones."""
    from test_proof import composite_function

    f, mid, rad, enclose = composite_function()
    outs = {}
    for a in ("balls", "arb"):
        with iv.arithmetic(a):
            outs[a] = enclose()
    out = outs["balls"]
    assert isinstance(out.v, Balls) and isinstance(out.h, Balls)
    lo = [iv.lower(t) for t in (out.v, out.d, out.h)]
    hi = [iv.upper(t) for t in (out.v, out.d, out.h)]
    rng = np.random.default_rng(RNG_SEED)
    for k in range(mid.shape[0]):
        for _ in range(50):
            p = mid[k] + rad * rng.uniform(-1, 1, 2)
            value, g, h = f(*p)
            assert lo[0][k] <= value <= hi[0][k]
            assert np.all((lo[1][:, k] <= g) & (g <= hi[1][:, k]))
            assert np.all((lo[2][:, :, k] <= np.array(h)) & (np.array(h) <= hi[2][:, :, k]))
    ref = outs["arb"]
    for b, a in ((out.v, ref.v), (out.d, ref.d), (out.h, ref.h)):
        wb, wa = iv.upper(b) - iv.lower(b), iv.upper(a) - iv.lower(a)
        assert np.all(wb <= wa * 1.03 + 1e-12)  # midpoints differ (exact ranges of sqrt, sin, cos)


def _check_blade(blade, tab, n, radius, n_samples=40):
    from rotorlyap.analysis.enclosure import BladeEnclosure
    from test_proof import _check_blade_box

    ev = _check_blade_box(blade, tab, n, radius, n_samples, arithmetic="balls")
    assert isinstance(ev.jacobian, Balls)
    ref = BladeEnclosure(blade, tab, arithmetic="arb").evaluate(n, radius=radius)
    w = iv.upper(ev.jacobian) - iv.lower(ev.jacobian)
    w_ref = iv.upper(ref.jacobian) - iv.lower(ref.jacobian)
    assert np.max(w / np.maximum(w_ref, 1e-300)) < 1.1  # about as tight as Arb


def test_blade_enclosure_on_float_balls_contains_the_float_model_in_hover():
    _check_blade(Blade(BladeParameters.table_i("backward"), 0.0), None, 1, 0.2 * DEFAULT_SCALES)


def test_blade_enclosure_on_float_balls_contains_the_float_model_in_compressible_forward_flight():
    from rotorlyap.model.forward_trim import forward_flight_trim
    from rotorlyap.model.steady import tabulate_motion

    trim = forward_flight_trim(BladeParameters.flight_case("forward"), 0.1)
    blade = Blade(trim.params, 0.1)
    _check_blade(blade, tabulate_motion(trim.motion, n=256), 16, 0.1 * DEFAULT_SCALES)


def test_hover_proofs_on_float_balls_prove_what_arb_proves():
    """prove_blade's ball prover (method="balls") on both arithmetics: the same bounds tried, the
    same proved bound, and the start radius equal to round-off (1e-12 relative)."""
    from rotorlyap.analysis.functions import quadratic_function
    from rotorlyap.analysis.proof import prove_blade
    from rotorlyap.model.forward_trim import forward_flight_trim

    trim = forward_flight_trim(BladeParameters.table_i("neutral"), 0.0)
    fun = quadratic_function(Blade(trim.params, 0.0), trim.steady)
    fast = prove_blade(fun, 0.1, arithmetic="balls", method="balls")
    ref = prove_blade(fun, 0.1, arithmetic="arb", method="balls")
    assert fast.proved and ref.proved
    assert fast.A >= ref.A and [ok for _, ok in fast.tried] == [ok for _, ok in ref.tried]
    assert fast.min_lambda0 == pytest.approx(ref.min_lambda0, rel=1e-12)
