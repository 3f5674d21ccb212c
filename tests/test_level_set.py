"""Proofs on one level set (rotorlyap.methods.level_set) and models on the halves of a box (taylor.split).

Facts checked, on systems whose invariant sublevel sets are known in closed form (a prover that
proves too much fails them):

* ``x' = -x + x^3`` with ``W = x^2``: ``W' = -2 x^2 (1 - x^2)``, negative on the level ``W = c``
  exactly for ``0 < c < 1``; the level 0.9 is proved with the start radius and bound
  ``sqrt(0.9)`` (the start radius to the bisection's width, the bound to the sub-boxes', both
  on the safe side), the levels 1 and 1.2 are not;
* ``x' = x - x^3`` with ``W = x^2``: the origin is unstable and ``W' > 0`` for ``0 < |x| < 1``,
  yet ``W' < 0`` on every level ``c > 1``: the level 4 is proved (the set ``|x| <= 2`` is
  invariant, whatever ``W'`` does inside), the level 0.25 is not;
* a rotated linear system with a cubic term in the plane, ``x' = (-I + 2 J) x + |x|^2 x``:
  ``W = |x|^2`` has ``W' = -2 |x|^2 (1 - |x|^2)``, the level ``c`` proved exactly for ``c < 1``;
  with ``W = |x|^2 + 0.3 x_1^4`` (not a quadratic form) the prover proves the level 0.8, whose
  set lies within the unit disc, and not a level whose set reaches past it on the ``x_1`` axis;
* :func:`rotorlyap.methods.taylor.split` reproduces the polynomial on each half and encloses it
  (the expansion exact to rounding, its bounds inside the whole box's);
* bad input is refused with a message.
"""

from __future__ import annotations

import numpy as np
import pytest

from rotorlyap.methods import taylor as tm
from rotorlyap.methods.level_set import prove_level


def cubic_1d(sign: float):
    """``x' = sign (x - x^3) * -1``: ``-x + x^3`` (sign 1) or ``x - x^3`` (sign -1), ``W = x^2``."""

    def models(C, H, rates):
        (x,) = tm.variables(C, H, 4)
        W = x * x
        if not rates:
            return W, None
        f = (x * x * x - x) * sign
        return W, x * f * 2.0

    return models


def planar(quartic: float):
    """``x' = (-I + 2 J) x + |x|^2 x`` with ``W = |x|^2 + quartic x_1^4``."""

    def models(C, H, rates):
        x1, x2 = tm.variables(C, H, 4)
        r2 = x1 * x1 + x2 * x2
        W = r2 + x1 * x1 * x1 * x1 * quartic
        if not rates:
            return W, None
        f1 = -x1 - x2 * 2.0 + r2 * x1
        f2 = x1 * 2.0 - x2 + r2 * x2
        g1 = x1 * 2.0 + x1 * x1 * x1 * (4.0 * quartic)
        return W, g1 * f1 + x2 * f2 * 2.0

    return models


def test_the_stable_cubic_is_proved_below_its_closed_form_level_and_not_at_it():
    ok = prove_level(cubic_1d(1.0), 0.9, 1.5, 1, min_width=2.0 ** -12)
    assert ok.proved
    assert np.sqrt(0.9) - 1e-6 <= ok.start_radius <= np.sqrt(0.9) <= ok.bound <= np.sqrt(0.9) + 0.3
    for level in (1.0, 1.2):
        res = prove_level(cubic_1d(1.0), level, 1.5, 1, min_width=2.0 ** -12)
        assert not res.proved and res.start_radius == 0.0 and "kappa" in res.reason


def test_a_level_set_is_proved_where_w_dot_is_positive_inside_it():
    # x' = x - x^3: W' = 2 x^2 (1 - x^2) > 0 inside |x| < 1, negative on W = 4
    ok = prove_level(cubic_1d(-1.0), 4.0, 3.0, 1, min_width=2.0 ** -12)
    assert ok.proved
    assert 2.0 - 1e-6 <= ok.start_radius <= 2.0 <= ok.bound <= 2.3
    assert not prove_level(cubic_1d(-1.0), 0.25, 3.0, 1, min_width=2.0 ** -12).proved


@pytest.mark.parametrize("level, proved", [(0.5, True), (0.9, True), (1.0, False), (1.3, False)])
def test_the_rotated_planar_system_follows_its_closed_form(level, proved):
    res = prove_level(planar(0.0), level, 1.5, 2, min_width=2.0 ** -9)
    assert res.proved == proved
    if proved:
        assert np.sqrt(level) - 1e-6 <= res.start_radius <= np.sqrt(level) <= res.bound <= np.sqrt(level) + 0.3


def test_a_function_that_is_not_a_quadratic_form_is_proved_within_the_closed_form_region():
    # W = |x|^2 + 0.3 x1^4: the level 0.8 lies inside the unit disc (W' < 0 there), proved; the level
    # 1.1 reaches |x| = 1.05 on the x2 axis, where W' > 0: not proved
    assert prove_level(planar(0.3), 0.8, 1.5, 2, min_width=2.0 ** -9).proved
    assert not prove_level(planar(0.3), 1.1, 1.5, 2, min_width=2.0 ** -9).proved


def test_split_reproduces_and_encloses_the_polynomial_on_each_half():
    rng = np.random.default_rng(3)
    sp = tm.space(3, 3)
    m = tm.TaylorModel(rng.normal(size=(4, sp.size)), np.full(4, 1e-6), sp)
    halves, centres = tm.split(m)
    assert halves.shape == (4, 8) and centres.shape == (8, 3)
    s = rng.uniform(-1.0, 1.0, (500, 3))
    lo, hi = halves.bounds()
    whole_lo, whole_hi = m.bounds()
    for i in range(4):
        for k in range(8):
            exact = m[i](centres[k] + 0.5 * s)
            assert np.max(np.abs(halves[i, k](s) - exact)) < 1e-12
            assert np.all((lo[i, k] <= exact) & (exact <= hi[i, k]))
        assert np.all(hi[i] <= whole_hi[i]) and np.all(lo[i] >= whole_lo[i])


def test_bad_input_is_refused():
    sp = tm.space(2, 2)
    m = tm.TaylorModel(np.ones((2, 2, sp.size)), np.zeros((2, 2)), sp)
    with pytest.raises(ValueError, match="shape \\(m,\\)"):
        tm.split(m)
    with pytest.raises(ValueError, match="finite"):
        prove_level(cubic_1d(1.0), np.nan, 1.0, 1)
    with pytest.raises(ValueError, match="kappas"):
        prove_level(cubic_1d(1.0), 0.5, 1.0, 1, kappas=(-1.0,))
