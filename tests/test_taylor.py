"""Taylor models (rotorlyap.methods.taylor) and the blade's equations in them (issue 41).

Facts checked:

* a model encloses its function: at random points of the box the exact value (Arb at 200 bits,
  the polynomial's float coefficients taken exactly) lies within the remainder of the polynomial,
  for compositions of every operation (``+ - * /``, powers, ``sin``, ``cos``, ``atan``,
  ``sqrt``), orders 1 to 4, single boxes and batches;
* terms that cancel exactly cancel in the model: ``x y - y x`` and ``(x + 1)^2 - x^2 - 2 x - 1``
  enclose 0 with a width of round-off, not of the box (order >= 2);
* the remainder of an order-``k`` model shrinks as the box to the power ``k + 1``;
* ``x' = -x + x^3`` on ``[0.2, 0.3]``: the model's range of ``x'`` and of its derivative contain
  the exact ranges and are tighter than the ball enclosures (which keep their over-estimate);
* what cannot be enclosed (a reciprocal of a range through 0, a square root below 0) gives
  infinite bounds; bad orders, mismatched spaces and boxes raise ``ValueError``;
* the blade (Table I, forward C.G., hover): the models of the right-hand side and of the Jacobian
  over a box contain the float model sampled in the box (also where the angles of attack span
  hundreds of the airfoil table's segments); on the box ``|y_i| <= 0.1`` the Jacobian's enclosure
  is at most 1.05 times the sampled variation with order 2 (the balls: about 430 times), with and
  without the air loads; ``enclosure_width(arithmetic="taylor")`` measures it.
"""

from __future__ import annotations

import numpy as np
import pytest
from flint import arb, ctx

from rotorlyap.methods import intervals as iv
from rotorlyap.methods import taylor as tm
from rotorlyap.methods.balls import Balls

CENTRE = np.array([0.3, -0.7])
RNG_SEED = 41


def _arb_poly(model: tm.TaylorModel, t: np.ndarray) -> arb:
    """The polynomial part of a scalar model at the float point ``t``, exactly (Arb)."""
    out = arb(0)
    for c, e in zip(model.coef, model.space.exponents):
        term = arb(float(c))
        for ti, ei in zip(t, e):
            term = term * arb(float(ti)) ** int(ei)
        out += term
    return out


def _composite(x, y, sin, cos, atan, sqrt):
    return sin(x * y) + atan(x) / (2 + cos(y)) + sqrt(x * x + 1.0) - (x - y) ** 3 * 0.5


def _check_contains(model: tm.TaylorModel, exact, centre, radius, rng, n_points: int = 60):
    """|f(c + r t) - p(t)| <= rem at random t, in Arb at 200 bits."""
    old = ctx.prec
    ctx.prec = 200
    try:
        for _ in range(n_points):
            t = rng.uniform(-1.0, 1.0, len(centre))
            x = [arb(float(c)) + arb(float(r)) * arb(float(ti)) for c, r, ti in zip(centre, radius, t)]
            gap = abs(exact(*x) - _arb_poly(model, t))
            assert gap <= arb(float(model.rem)), (t, gap, model.rem)
    finally:
        ctx.prec = old


@pytest.mark.parametrize("order", [1, 2, 3, 4])
def test_composition_contains_the_exact_function(order):
    rng = np.random.default_rng(RNG_SEED + order)
    radius = np.array([0.1, 0.05])
    x, y = tm.variables(CENTRE, radius, order)
    f = _composite(x, y, tm.sin, tm.cos, tm.atan, tm.sqrt)
    _check_contains(f, lambda a, b: _composite(a, b, arb.sin, arb.cos, arb.atan, arb.sqrt), CENTRE, radius, rng)
    lo, hi = f.bounds()
    t = rng.uniform(-1, 1, (500, 2))
    p = CENTRE + radius * t
    vals = (np.sin(p[:, 0] * p[:, 1]) + np.arctan(p[:, 0]) / (2 + np.cos(p[:, 1])) + np.sqrt(p[:, 0] ** 2 + 1)
            - (p[:, 0] - p[:, 1]) ** 3 * 0.5)
    assert lo <= vals.min() and vals.max() <= hi


def test_batches_enclose_each_box_as_alone():
    """A batch of boxes gives each box the model it gets alone (vectorised over the boxes)."""
    rng = np.random.default_rng(RNG_SEED)
    centres = rng.uniform(-1, 1, (5, 2))
    radius = np.full((5, 2), 0.05)
    x, y = tm.variables(centres, radius, 3)
    f = _composite(x, y, tm.sin, tm.cos, tm.atan, tm.sqrt)
    assert f.shape == (5,)
    for b in range(5):
        xs, ys = tm.variables(centres[b], radius[b], 3)
        g = _composite(xs, ys, tm.sin, tm.cos, tm.atan, tm.sqrt)
        np.testing.assert_array_equal(f.coef[b], g.coef)
        assert f.rem[b] == g.rem
        _check_contains(f[b], lambda a, c: _composite(a, c, arb.sin, arb.cos, arb.atan, arb.sqrt),
                        centres[b], radius[b], rng, n_points=10)


def test_compiled_product_is_the_numpy_product():
    """The compiled product kernel (numba) and the numpy path sum the same products in the same
    order: equal coefficients (to a fused multiply-add's rounding)."""
    rng = np.random.default_rng(RNG_SEED)
    sp = tm.space(6, 3)
    a, b = rng.normal(size=(4, 3, sp.size)), rng.normal(size=(3, sp.size))
    np.testing.assert_allclose(tm._product(a, b, sp), tm._product_numpy(a, b, sp), rtol=1e-14, atol=1e-14)


ELEMENTARY = {
    "reciprocal": (lambda x: 1.0 / x, lambda x: 1 / x, [(-3.0, 0.5), (1e-3, 5e-4), (1e5, 1e4), (-0.2, 0.1)]),
    "sqrt": (tm.sqrt, lambda x: x.sqrt(), [(1e-3, 9e-4), (2.0, 1.5), (1e8, 1e7)]),
    "atan": (tm.atan, lambda x: x.atan(), [(0.0, 1.0), (-50.0, 10.0), (1e3, 5e2), (0.5, 3.0)]),
    "sin": (tm.sin, lambda x: x.sin(), [(0.0, 2.0), (100.0, 0.3), (1.5, 4.0), (-7.0, 0.01)]),
    "cos": (tm.cos, lambda x: x.cos(), [(0.0, 2.0), (100.0, 0.3), (1.5, 4.0), (-7.0, 0.01)]),
    "power 5": (lambda x: x ** 5, lambda x: x ** 5, [(0.0, 2.0), (-3.0, 0.1)]),
}


@pytest.mark.parametrize("name", list(ELEMENTARY))
def test_elementary_functions_contain_the_exact_values_on_hard_boxes(name):
    """Tiny, huge, wide and negative boxes, the box's ends included, orders 1 to 4 (Arb at 200 bits)."""
    f, exact, boxes = ELEMENTARY[name]
    rng = np.random.default_rng(RNG_SEED)
    old = ctx.prec
    ctx.prec = 200
    try:
        for order in (1, 2, 3, 4):
            for c, r in boxes:
                x, = tm.variables([c], [r], order)
                m = f(x)
                assert np.isfinite(m.rem)
                for t in np.concatenate([[-1.0, 1.0], rng.uniform(-1, 1, 12)]):
                    gap = abs(exact(arb(c) + arb(r) * arb(float(t))) - _arb_poly(m, [t]))
                    assert gap <= arb(float(m.rem)), (order, c, r, t)
    finally:
        ctx.prec = old


def test_rounding_is_enclosed_for_large_cancelling_magnitudes():
    """Coefficients of 1e8 that cancel: the exact result (Arb) stays within the remainder."""
    rng = np.random.default_rng(RNG_SEED)
    c, r = np.array([1e8 / 3, 0.1]), np.array([1e-3, 0.05])
    x, y = tm.variables(c, r, 2)
    f = (x * 3.0 + y) * (x * 3.0 - y) - x * x * 9.0 + y * y + x / 7.0
    _check_contains(f, lambda a, b: (a * 3 + b) * (a * 3 - b) - a * a * 9 + b * b + a / 7, c, r, rng)


def test_ray_average_contains_the_average_along_the_segment():
    """``int_0^1 f(c + s r t) ds`` (Arb's rigorous integral) lies within the averaged model's remainder."""
    from flint import acb

    rng = np.random.default_rng(RNG_SEED)
    radius = np.array([0.1, 0.05])
    x, y = tm.variables(CENTRE, radius, 3)
    f = _composite(x, y, tm.sin, tm.cos, tm.atan, tm.sqrt)
    F = f.ray_average()
    assert F.rem >= f.rem
    for _ in range(4):
        t = rng.uniform(-1, 1, 2)

        def g(s, _):
            a = acb(float(CENTRE[0])) + s * acb(float(radius[0] * t[0]))
            b = acb(float(CENTRE[1])) + s * acb(float(radius[1] * t[1]))
            return _composite(a, b, acb.sin, acb.cos, acb.atan, acb.sqrt)

        exact = acb.integral(g, 0, 1).real
        assert abs(exact - _arb_poly(F, t)) <= arb(float(F.rem))


def test_ray_average_over_some_variables_holds_the_others():
    """Averaging over ``x`` only: ``f = x^2 y + y^3`` gives ``x^2 y / 3 + y^3`` exactly."""
    x, y = tm.variables([0.0, 0.0], [1.0, 1.0], 3)
    F = (x * x * y + y * y * y).ray_average(over=[0])
    G = x * x * y * (1.0 / 3.0) + y * y * y
    np.testing.assert_allclose(F.coef, G.coef, atol=1e-16)
    assert F.rem < 1e-14
    with pytest.raises(ValueError, match="average"):
        F.ray_average(over=[2])


@pytest.mark.parametrize("order", [2, 3, 4])
def test_exact_cancellations_leave_round_off(order):
    x, y = tm.variables(CENTRE, [0.5, 0.5], order)
    lo, hi = (x * y - y * x).bounds()
    assert lo <= 0 <= hi and hi - lo < 1e-14
    lo, hi = ((x + 1) ** 2 - x * x - 2 * x - 1).bounds()
    assert lo <= 0 <= hi and hi - lo < 1e-13     # the box is 1 wide, the values about 2


def test_order_one_keeps_the_quadratic_terms_in_the_remainder():
    """Order 1 (the first-order Taylor model: affine arithmetic with a remainder) cannot cancel
    products: ``x y - y x`` keeps twice the bound of ``x y``'s quadratic term."""
    x, y = tm.variables(CENTRE, [0.1, 0.1], 1)
    lo, hi = (x * y - y * x).bounds()
    assert lo <= 0 <= hi and hi - lo > 0.01


@pytest.mark.parametrize("order", [1, 2, 3])
def test_remainder_shrinks_as_the_box_to_the_power_order_plus_one(order):
    rems = []
    for r in (0.1, 0.05, 0.025):
        x, y = tm.variables(CENTRE, [r, r], order)
        rems.append(float(_composite(x, y, tm.sin, tm.cos, tm.atan, tm.sqrt).rem))
    rates = np.log2(np.array(rems[:-1]) / np.array(rems[1:]))
    assert np.all(np.abs(rates - (order + 1)) < 0.35), rates


def test_cubic_system_range_and_derivative():
    """``x' = -x + x^3`` on [0.2, 0.3]: exact ranges [-0.273, -0.192] and, of the derivative
    ``-1 + 3 x^2``, [-0.88, -0.73]."""
    x, = tm.variables([0.25], [0.05], 3)
    one = tm.TaylorModel.constant(np.ones(1), x.space)
    xj = iv.Jet(x, one)
    f = -xj + xj * xj * xj
    lo, hi = f.v.bounds()
    assert lo <= -0.273 and -0.192 <= hi
    assert hi - lo < 1.05 * 0.081
    dlo, dhi = f.d.bounds()
    assert dlo[0] <= -0.88 and -0.73 <= dhi[0] and dhi[0] - dlo[0] < 1.06 * 0.15
    b = Balls(0.25, 0.05)
    g = -b + b * b * b
    assert g.upper() - g.lower() > 1.4 * 0.081           # the balls' dependency problem
    b = Balls(0.25, 0.005)                                # ... which does not shrink with the box
    g = -b + b * b * b
    x, = tm.variables([0.25], [0.005], 3)
    lo, hi = (-x + x ** 3).bounds()
    exact = (0.255 - 0.255 ** 3) - (0.245 - 0.245 ** 3)
    assert g.upper() - g.lower() > 1.4 * exact and hi - lo < 1.005 * exact


def test_what_cannot_be_enclosed_gives_infinite_bounds():
    x, = tm.variables([0.0], [0.5], 2)
    assert np.all(np.isinf((1.0 / x).bounds()))
    assert np.all(np.isinf((x - 0.2).sqrt().bounds()))
    assert np.all(np.isinf(tm.atan(1.0 / x).bounds()))


def test_bad_input_raises():
    with pytest.raises(ValueError, match="order"):
        tm.variables([0.0], [1.0], 0)
    with pytest.raises(ValueError, match="order"):
        tm.space(2, tm.MAX_ORDER + 1)
    with pytest.raises(ValueError, match="do not match"):
        tm.variables([0.0, 1.0], [1.0, 1.0, 1.0], 2)
    with pytest.raises(ValueError, match="radius"):
        tm.variables([0.0], [-1.0], 2)
    x, = tm.variables([0.0], [1.0], 2)
    y, = tm.variables([0.0], [1.0], 3)
    with pytest.raises(ValueError, match="different spaces"):
        x + y
    with pytest.raises(ValueError, match="integer powers"):
        x ** 0.5
    with pytest.raises(ValueError, match="remainder"):
        tm.TaylorModel(np.zeros(3), -1.0, x.space)
    with pytest.raises(ValueError, match="coefficients"):
        tm.TaylorModel(np.zeros(4), 0.0, x.space)


# --------------------------------------------------------------------------------------
# The blade
# --------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def hover():
    from rotorlyap.analysis.enclosure import BladeEnclosure
    from rotorlyap.analysis.proof import _without_air
    from rotorlyap.conventions import DEFAULT_SCALES
    from rotorlyap.model.blade import Blade
    from rotorlyap.model.parameters import BladeParameters
    from rotorlyap.model.steady import as_steady_motion

    blade = Blade(BladeParameters.table_i("forward"), 0.0)
    steady = as_steady_motion(None, blade)
    out = {}
    for wet, model in (("air", blade), ("dry", _without_air(blade))):
        out[wet] = (model, BladeEnclosure(model, steady, arithmetic="balls"))
    return steady, np.asarray(DEFAULT_SCALES, dtype=float), out


def _samples(steady, a, bound, n=200):
    rng = np.random.default_rng(RNG_SEED)
    corners = np.array(np.meshgrid(*[[-1.0, 1.0]] * 6, indexing="ij")).reshape(6, -1).T
    y = np.vstack([corners, rng.uniform(-1, 1, (n, 6))]) * bound
    return steady.state + y * a


@pytest.mark.parametrize("wet", ["air", "dry"])
@pytest.mark.parametrize("bound, order", [(0.02, 2), (0.3, 3)])
def test_blade_models_contain_the_sampled_equations(hover, wet, bound, order):
    """Also over a box whose angles of attack span hundreds of the airfoil table's segments (0.3)."""
    from rotorlyap.analysis.taylor_enclosure import taylor_evaluate

    steady, a, cases = hover
    model, enc = cases[wet]
    ev = taylor_evaluate(enc, np.zeros(6), bound * a, order)
    z = _samples(steady, a, bound)
    f = model.rhs(np.zeros(len(z)), z)
    lo, hi = ev.value.bounds()
    assert np.all((f >= lo - 1e-12 * (1 + np.abs(f))) & (f <= hi + 1e-12 * (1 + np.abs(f))))
    J = model.jacobian(np.zeros(len(z)), z)               # finite differences: their error as slack
    jlo, jhi = ev.jacobian.bounds()
    slack = 1e-6 * (np.abs(J) + 1.0)
    assert np.all((J >= jlo - slack) & (J <= jhi + slack))


@pytest.mark.parametrize("wet", ["air", "dry"])
def test_blade_jacobian_enclosure_is_close_to_the_variation(hover, wet):
    """Issue 41's measure on |y_i| <= 0.1: order 2 within 1.05 of the sampled variation (balls: ~430)."""
    from rotorlyap.analysis.taylor_enclosure import taylor_evaluate

    steady, a, cases = hover
    model, enc = cases[wet]
    bound = 0.1
    ev = taylor_evaluate(enc, np.zeros(6), bound * a, 2)
    scale = a[None, :] / a[:, None]
    lo, hi = ev.jacobian.bounds()
    radius = 0.5 * (hi - lo) * scale
    z = _samples(steady, a, bound, n=64)
    J = model.jacobian(np.zeros(len(z)), z)
    J0 = model.jacobian(np.zeros(1), steady.state[None])[0]
    variation = np.max(np.abs(J - J0), axis=0) * scale
    assert radius.max() / variation.max() < 1.05
    slack = 1e-6 * (np.abs(J) + 1.0)
    assert np.all((J >= lo - slack) & (J <= hi + slack))


def test_enclosure_width_measures_taylor_models():
    """``enclosure_width(arithmetic="taylor")``: the issue's target ratio <= 3 on |y_i| <= 0.1 (order 2)."""
    from rotorlyap.analysis.proof import enclosure_width
    from rotorlyap.model.blade import Blade
    from rotorlyap.model.parameters import BladeParameters

    w = enclosure_width(Blade(BladeParameters.table_i("forward"), 0.0), bound=0.1, samples=32,
                        arithmetic="taylor", order=2)
    assert w.contained and w.ratio < 1.2


def test_forward_flight_models_contain_the_sampled_equations_and_are_tighter_than_balls():
    """The trimmed helicopter at mu = 0.1 (compressible sections, Pitt-Peters inflow), about its
    tabulated periodic motion, the azimuth a seventh model variable on 16 intervals: the models
    contain the float right-hand side and Jacobian at random azimuths and states of the boxes
    ``|y_i| <= 0.1``, and the Jacobian's enclosure is over 50 times narrower than the balls'; on 8
    coarser intervals (the steady motion's hull over two pieces) they contain them too; without the
    Jacobian (``jacobian=False``) the value models are the same."""
    from rotorlyap.analysis.enclosure import BladeEnclosure
    from rotorlyap.analysis.taylor_enclosure import taylor_evaluate
    from rotorlyap.conventions import DEFAULT_SCALES
    from rotorlyap.model.blade import Blade
    from rotorlyap.model.forward_trim import forward_flight_trim
    from rotorlyap.model.parameters import BladeParameters
    from rotorlyap.model.steady import tabulate_motion

    trim = forward_flight_trim(BladeParameters.flight_case("forward"), 0.1)
    blade = Blade(trim.params, 0.1)
    assert blade.params.compressibility == "prandtl-glauert"
    n = 16
    tab = tabulate_motion(trim.motion, n=n)
    enc = BladeEnclosure(blade, tab, arithmetic="balls")
    radius = 0.1 * np.asarray(DEFAULT_SCALES, dtype=float)
    ev = taylor_evaluate(enc, np.zeros(6), radius, 2, n_intervals=n)
    lo, hi = ev.value.bounds()
    jlo, jhi = ev.jacobian.bounds()
    assert np.all(np.isfinite(lo) & np.isfinite(hi))
    rng = np.random.default_rng(RNG_SEED)
    k = rng.integers(0, n, 100)
    psi = 2 * np.pi * (k + rng.uniform(0, 1, k.size)) / n
    z = tab.xi(psi) + radius * rng.uniform(-1, 1, (k.size, 6))
    value = blade.rhs(psi, z) - tab.dxi(psi)
    scale = np.abs(value).max() + 1.0
    assert np.all((lo[k] - 1e-12 * scale <= value) & (value <= hi[k] + 1e-12 * scale))
    J = blade.jacobian(psi, z)
    slack = 1e-6 * (np.abs(J).max() + 1.0)
    assert np.all((jlo[k] - slack <= J) & (J <= jhi[k] + slack))
    balls = enc.evaluate(n, radius=radius).jacobian
    assert np.max(balls.upper() - balls.lower()) > 50 * np.max(jhi - jlo)
    # coarse intervals (8, each over two pieces of the steady motion): the pieces' hull
    coarse = taylor_evaluate(enc, np.zeros(6), radius, 2, n_intervals=n // 2)
    clo, chi = coarse.jacobian.bounds()
    assert np.all((clo[k // 2] - slack <= J) & (J <= chi[k // 2] + slack))
    vlo, vhi = coarse.value.bounds()
    assert np.all((vlo[k // 2] - 1e-12 * scale <= value) & (value <= vhi[k // 2] + 1e-12 * scale))
    # without the Jacobian (the compressible sections' kinks taken on values alone): the same value models
    bare = taylor_evaluate(enc, np.zeros(6), radius, 2, n_intervals=n, jacobian=False)
    assert bare.jacobian is None
    assert np.array_equal(bare.value.coef, ev.value.coef) and np.array_equal(bare.value.rem, ev.value.rem)


@pytest.mark.parametrize("centre", [-0.3, -0.02, 0.0, 0.05, 0.4])
def test_kinks_of_the_compressible_loads_contain_values_and_slopes(centre):
    """``min(x, cap)``, ``|x|``, ``max(x, 0)^4`` on Jets of models over boxes on either side of
    their kinks and straddling them: values and (generalised) derivatives at points contained."""
    from rotorlyap.analysis.taylor_enclosure import _tm_abs, _tm_min_const, _tm_pos4

    x, y = tm.variables([centre, 0.1], [0.1, 0.05], 2)
    grad = tm.TaylorModel.constant(np.eye(6)[0], x.space)                   # d/dx_0 of six inputs
    u = iv.Jet(x * 0.5 + y * y, grad * 0.5)                                  # u = x/2 + y^2, du/dx_0 = 1/2
    cases = [(_tm_min_const(u, 0.02), lambda v: min(v, 0.02), lambda v: 1.0 if v < 0.02 else 0.0),
             (_tm_abs(u), abs, lambda v: np.sign(v)),
             (_tm_pos4(u), lambda v: max(v, 0.0) ** 4, lambda v: 4 * max(v, 0.0) ** 3)]
    rng = np.random.default_rng(RNG_SEED)
    for f, value, slope in cases:
        lo, hi = f.v.bounds()
        dlo, dhi = f.d.bounds()
        for t in rng.uniform(-1, 1, (50, 2)):
            v = 0.5 * (centre + 0.1 * t[0]) + (0.1 + 0.05 * t[1]) ** 2
            assert lo - 1e-15 <= value(v) <= hi + 1e-15
            assert dlo[0] - 1e-15 <= 0.5 * slope(v) <= dhi[0] + 1e-15


def _random_program(rng, depth: int):
    """A random expression over the variables ``x, y, z`` as a function of a namespace (so the
    same program runs on models and on Arb balls); every operation's domain kept safe."""
    if depth == 0:
        pick = rng.integers(0, 4)
        if pick == 3:
            c = float(rng.normal())
            return lambda ns: ns["const"](c)
        return lambda ns, i=int(pick): ns["vars"][i]
    a, b = _random_program(rng, depth - 1), _random_program(rng, depth - 1)
    op = rng.integers(0, 8)
    if op == 0:
        return lambda ns: a(ns) + b(ns)
    if op == 1:
        return lambda ns: a(ns) - b(ns)
    if op == 2:
        return lambda ns: a(ns) * b(ns)
    if op == 3:
        return lambda ns: a(ns) / (ns["const"](3.0) + ns["sin"](b(ns)))
    if op == 4:
        return lambda ns: ns["sin"](a(ns)) * ns["cos"](b(ns))
    if op == 5:
        return lambda ns: ns["atan"](a(ns) * 2.0 - b(ns))
    if op == 6:
        return lambda ns: ns["sqrt"](a(ns) * a(ns) + 0.5)
    return lambda ns: a(ns) * 1e3 - a(ns) * 999.0    # cancellation


def test_random_programs_contain_the_exact_values():
    """Random expression trees of every operation over three variables, orders 1 to 4, random
    boxes: the exact value (Arb, 200 bits) at random points lies within the remainder. A model may
    refuse (a non-finite remainder: ``sqrt(a a + 1/2)`` of a wide ``a`` whose bound reaches below
    0): most do not."""
    rng = np.random.default_rng(RNG_SEED)
    old = ctx.prec
    ctx.prec = 200
    finite = 0
    try:
        for trial in range(24):
            program = _random_program(rng, 3)
            order = int(rng.integers(1, 5))
            centre = rng.normal(size=3)
            radius = 10.0 ** rng.uniform(-3, -0.5, 3)
            xs = tm.variables(centre, radius, order)
            model = program({"vars": xs, "const": Balls, "sin": tm.sin, "cos": tm.cos,
                             "atan": tm.atan, "sqrt": tm.sqrt})
            model = model if isinstance(model, tm.TaylorModel) else tm.TaylorModel.constant(model, xs[0].space)
            points = rng.uniform(-1, 1, (6, 3))
            if not np.isfinite(model.rem):
                assert np.all(np.isinf(model.bounds()))
                continue
            finite += 1
            for t in points:
                pts = [arb(float(c)) + arb(float(r)) * arb(float(ti)) for c, r, ti in zip(centre, radius, t)]
                exact = program({"vars": pts, "const": arb, "sin": arb.sin, "cos": arb.cos, "atan": arb.atan,
                                 "sqrt": arb.sqrt})
                assert abs(exact - _arb_poly(model, t)) <= arb(float(model.rem)), (trial, order)
    finally:
        ctx.prec = old
    assert finite >= 18
