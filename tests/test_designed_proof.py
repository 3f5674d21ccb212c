"""The designed hover functions proved on a level set (rotorlyap.analysis.designed_proof).

Facts checked:

* the Taylor models of ``W`` and ``W'`` enclose the float model's values (the designed function's
  own ``W`` and ``W'``, computed by other code: the compiled energy kernels) at random points of
  boxes far into the nonlinear range, with polynomial parts that follow them to within their
  remainders;
* the models of ``W`` alone equal those the rate evaluation gives (one function, two paths);
* the start radius the proof reports is the level set's nearest point to within the bisection, on
  the safe side (the neutral C.G.'s function, a quadratic form, whose nearest point is known in
  closed form), and ``W`` sampled on its sphere stays below the level;
* a function with a weight on a term the models do not hold is refused.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from rotorlyap.analysis.certificate_file import read_certificate
from rotorlyap.analysis.designed_proof import designed_models, designed_parts
from rotorlyap.methods.sampling import unit_sphere_points

BOOK = Path(__file__).resolve().parents[1] / "book" / "certificates"


@pytest.fixture(scope="module")
def forward():
    return read_certificate(BOOK / "hover_forward.json").function


@pytest.fixture(scope="module")
def neutral():
    return read_certificate(BOOK / "hover_neutral.json").function


def test_the_models_enclose_the_float_function_far_into_the_nonlinear_range(forward):
    a = np.asarray(forward.scales)
    c0, _, _ = designed_parts(forward)
    assert c0 > 0                                   # the energy is in it
    models = designed_models(forward)
    centre = unit_sphere_points(6, 64, seed=4) * 3.0
    half = np.full_like(centre, 0.25)
    W, dW = models(centre, half, True)
    W_only, _ = models(centre, half, False)
    assert np.array_equal(W.coef, W_only.coef) and np.array_equal(W.rem, W_only.rem)
    rng = np.random.default_rng(5)
    for i in range(0, 64, 8):
        t = rng.uniform(-1.0, 1.0, (300, 6))
        x = (centre[i] + half[i] * t) * a
        w, dw = forward.W(0.0, x), forward.dW(0.0, x)
        lo, hi = W[i:i + 1].bounds()
        assert np.all((lo <= w) & (w <= hi))
        lo, hi = dW[i:i + 1].bounds()
        assert np.all((lo <= dw) & (dw <= hi))
        # the polynomial part follows W' (float rounding of both aside)
        assert np.max(np.abs(dW[i](t) - dw)) <= dW.rem[i] + 1e-9


def test_the_start_radius_lies_inside_the_level_set(neutral):
    from rotorlyap.methods.level_set import ball_maximum, start_radius

    a = np.asarray(neutral.scales)
    models = designed_models(neutral)
    c0, _, S = designed_parts(neutral)
    assert c0 == 0.0                                          # W = y^T S y: its level set in closed form
    level = 0.1
    r = start_radius(models, level, 6, 10.0)
    nearest = np.sqrt(level / np.linalg.eigvalsh(S)[-1])      # the level set's nearest point
    assert 0.999 * nearest <= r <= nearest
    u = unit_sphere_points(6, 4000, seed=6)
    assert np.max(neutral.W(0.0, r * u * a)) < level
    assert ball_maximum(models, 6, r) < level <= ball_maximum(models, 6, 1.001 * nearest)


def test_a_function_with_other_terms_is_refused(neutral):
    bf = neutral.function
    names = list(bf.basis.names)
    coefficients = np.array(bf.coefficients, dtype=float)
    assert "energy" not in names or coefficients[names.index("energy")] == 0.0
    # a harmonic-free cubic monomial cannot be named in this basis; a forward-flight function is
    # not autonomous
    with pytest.raises(ValueError, match="autonomous"):
        designed_parts(replace(neutral, autonomous=False))
