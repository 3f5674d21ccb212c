"""The sound rule's options for functions without closed forms: the level along a ray, an
autonomous system searched at one azimuth, and the shell that holds the band.

Facts checked:

* the level along each ray (regula falsi in its Illinois form) is the closed form
  ``r = sqrt(c / W(u))`` of a quadratic ``W`` to round-off;
* for an autonomous system and function, ``autonomous=True`` (one azimuth searched) gives the
  certificate of the search over the whole period;
* the shell ``rho <= ||x|| <= A`` holds the band, so ``band="shell"`` asks more than
  ``band="level"``: its bound is never larger, and on the softening system of the engine's tests,
  whose ``W'`` changes sign exactly at ``||x|| = 1``, both find that radius.
"""

from __future__ import annotations

import numpy as np
import pytest

from rotorlyap import technical_stability
from rotorlyap.methods.lyapunov import _Checked, _ray_level


def radial_softening():
    """x' = -x (1 - |x|^2), W = x1^2 + 2 x2^2: W' = -2 (1 - r^2) W, <= 0 exactly for r <= 1."""
    return (lambda p, x: -x * (1.0 - np.sum(x ** 2, axis=1, keepdims=True)),
            lambda p, x: x[:, 0] ** 2 + 2.0 * x[:, 1] ** 2)


def duffing(c: float = 0.3):
    """x'' + c x' + x + x^3 = 0 (autonomous) and a quadratic W with a cross term."""
    f = lambda p, x: np.column_stack([x[:, 1], -x[:, 0] - x[:, 0] ** 3 - c * x[:, 1]])  # noqa: E731
    W = lambda p, x: x[:, 0] ** 2 + x[:, 1] ** 2 + 0.2 * x[:, 0] * x[:, 1]  # noqa: E731
    return f, W


def test_the_level_along_a_ray_is_the_closed_form_of_a_quadratic_function():
    f, W = radial_softening()
    rng = np.random.default_rng(3)
    u = rng.normal(size=(500, 2))
    u /= np.linalg.norm(u, axis=1, keepdims=True)
    psi = np.zeros(500)
    c, A = 0.7, 2.0
    sys = _Checked(f, W, None, 2, 1e-4)
    r = _ray_level(sys, psi, u, np.ones(2), c, A, None)
    exact = np.minimum(np.sqrt(c / W(psi, u)), A)
    np.testing.assert_allclose(r, exact, rtol=1e-11)
    assert np.all(W(psi, r[:, None] * u) >= c * (1 - 1e-12))


@pytest.mark.slow
def test_an_autonomous_system_searched_at_one_azimuth_gives_the_same_certificate():
    """Duffing with a quadratic W: the bound and start radius with the azimuth searched over the
    period and with ``autonomous=True`` agree (to the searches' resolution, 0.5 %)."""
    f, W = duffing()
    full = technical_stability(f, W, 3.0, dim=2, n_psi=8)
    one = technical_stability(f, W, 3.0, dim=2, n_psi=8, autonomous=True)
    assert full.certified and one.certified
    assert one.A == pytest.approx(full.A, rel=5e-3)
    np.testing.assert_allclose(one.lambda0, full.lambda0, rtol=5e-3)
    assert one.psi.shape == full.psi.shape and np.all(one.lambda0 == one.lambda0[0])


def test_the_shell_holds_the_band_and_asks_no_less():
    """Softening system: W' < 0 exactly inside the unit circle, so both searches certify A = 1
    (to 2 %), the shell's bound never above the band's; the message names the shell."""
    f, W = radial_softening()
    level = technical_stability(f, W, 1.5, dim=2, n_psi=4, autonomous=True)
    shell = technical_stability(f, W, 1.5, dim=2, n_psi=4, autonomous=True, band="shell")
    assert level.certified and shell.certified
    assert shell.A == pytest.approx(1.0, rel=0.02) and level.A == pytest.approx(1.0, rel=0.02)
    assert shell.A <= level.A * (1 + 1e-9)
    assert "shell" in shell.message and "shell" not in level.message
    np.testing.assert_allclose(shell.lambda0, shell.A / np.sqrt(2), rtol=0.02)


@pytest.mark.parametrize("kwargs, match", [
    (dict(autonomous=True, rule="paper"), "autonomous=True is an option of rule='sound' only"),
    (dict(band="ball"), "band must be 'level' or 'shell'"),
    (dict(band="shell", rule="paper"), "band='shell' is an option of rule='sound' only"),
])
def test_options_are_checked(kwargs, match):
    f, W = radial_softening()
    with pytest.raises(ValueError, match=match):
        technical_stability(f, W, 1.0, dim=2, **kwargs)
