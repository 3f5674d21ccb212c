"""The falsifier's own tools (:mod:`falsifier`), checked on closed forms.

Facts checked: the level along a ray of a non-quadratic ``W`` is the first crossing, to
``LEVEL_WIDTH`` of the bound, on the band's side (``W >= c``); a ray that stays below the
level gives the bound ``A``; hyperspherical coordinates give unit vectors.
"""

from __future__ import annotations

import numpy as np

from falsifier import LEVEL_WIDTH, band_level, unit_vectors


def _radial(psi, x):
    """``W = r^2 + r^4`` (``r = |x|``), 0 at the origin: its level ``c`` at ``r^2 = (sqrt(1 + 4 c) - 1) / 2``."""
    r2 = np.sum(x * x, axis=1)
    return r2 + r2 * r2


def test_the_level_along_a_ray_is_its_first_crossing_on_the_bands_side():
    rng = np.random.default_rng(20261204)
    u = unit_vectors(rng.uniform(0, np.pi, (200, 5)), 6)
    a, c, A = np.ones(6), 0.3, 1.0
    r = band_level(_radial, rng.uniform(0, 2 * np.pi, 200), u, a, c, A, quadratic=False)
    exact = np.sqrt((np.sqrt(1 + 4 * c) - 1) / 2)
    assert np.all(np.abs(r - exact) <= A * LEVEL_WIDTH)
    assert np.all(_radial(None, r[:, None] * u) >= c)


def test_a_ray_below_the_level_gives_the_bound_and_a_wavy_ray_its_first_crossing():
    """W = r sin(10 r)^2 + r^2 / 10 (along the ray) crosses c = 0.1 three times below 1: the first
    crossing is returned; with c above its maximum on [0, A], the bound A."""
    def wavy(psi, x):
        r = np.linalg.norm(x, axis=1)
        return r * np.sin(10 * r) ** 2 + r * r / 10

    u = np.eye(6)[:2]
    r = band_level(wavy, np.zeros(2), u, np.ones(6), 0.1, 1.0, quadratic=False)
    grid = np.linspace(0, 1, 1_000_001)
    first = grid[np.argmax(wavy(None, grid[:, None] * u[:1]) >= 0.1)]
    assert np.all(np.abs(r - first) <= 1e-6) and np.all(wavy(None, r[:, None] * u) >= 0.1)
    assert np.all(band_level(wavy, np.zeros(2), u, np.ones(6), 10.0, 1.0, quadratic=False) == 1.0)


def test_hyperspherical_coordinates_give_unit_vectors():
    rng = np.random.default_rng(1)
    for n in range(1, 8):
        v = unit_vectors(rng.uniform(0, np.pi, (100, max(n - 1, 1))), n)
        assert v.shape == (100, n) and np.allclose(np.linalg.norm(v, axis=1), 1.0, rtol=0, atol=1e-15)
