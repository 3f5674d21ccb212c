"""The batched polish of the searches (rotorlyap.methods.polish): closed-form maxima, the bound
of the ray parameter, independence of the starts, and agreement with scipy's L-BFGS-B."""

from __future__ import annotations

import numpy as np
import pytest

from rotorlyap.methods.polish import T_MIN, polish, polish_scipy
from rotorlyap.methods.sampling import Extremum

RNG_SEED = 20261204


def _starts(fun, m: int, n: int, rng, *, psi=None, t=None) -> Extremum:
    u = rng.normal(size=(m, n))
    u /= np.linalg.norm(u, axis=1)[:, None]
    t = rng.uniform(0.2, 0.9, m) if t is None else np.full(m, float(t))
    psi = rng.uniform(0, 2 * np.pi, m) if psi is None else np.full(m, float(psi))
    y = u * t[:, None]
    return Extremum(np.asarray(fun(psi, y), dtype=float), psi, y)


def _quadratic_form(n: int, rng):
    A = rng.normal(size=(n, n))
    S = A @ A.T + n * np.eye(n)
    return S, lambda psi, y: np.einsum("ki,ij,kj->k", y, S, y)


@pytest.mark.parametrize("polisher", [polish, polish_scipy], ids=["batched", "scipy"])
def test_a_positive_quadratic_form_is_maximised_on_the_sphere_by_its_largest_eigenvalue(polisher):
    """max of y^T S y over |y| <= 1 is lambda_max(S), at t = 1 (the bound of t active)."""
    rng = np.random.default_rng(RNG_SEED)
    S, fun = _quadratic_form(6, rng)
    start = _starts(fun, 32, 6, rng, psi=0.0)
    value, psi, y = polisher(fun, start, free_psi=False)
    lam = np.linalg.eigvalsh(S)[-1]
    assert np.all(value >= start.value)
    assert value.max() == pytest.approx(lam, rel=1e-8)
    assert np.all(np.linalg.norm(y, axis=1) <= 1.0 + 1e-15)
    assert np.all(psi == 0.0)


def test_a_polish_told_to_stop_above_a_value_stops_there_and_otherwise_runs_in_full():
    """stop_above (a band search deciding "max <= stop" only): below lambda_max(S) the polish
    returns a value above the threshold that the form takes at the point returned; above it the
    threshold is never reached and the polish is the full one to the last bit."""
    rng = np.random.default_rng(RNG_SEED)
    S, fun = _quadratic_form(6, rng)
    start = _starts(fun, 32, 6, rng, psi=0.0)
    full = polish(fun, start, free_psi=False)
    lam = np.linalg.eigvalsh(S)[-1]
    stop = start.value.max() + 0.5 * (lam - start.value.max())
    value, psi, y = polish(fun, start, free_psi=False, stop_above=stop)
    assert value.max() > stop and np.array_equal(value, fun(psi, y))
    above = polish(fun, start, free_psi=False, stop_above=lam * (1 + 1e-6))
    assert all(np.array_equal(a, b) for a, b in zip(above, full))


def test_an_interior_maximum_in_the_ray_parameter_and_the_azimuth_is_found():
    """f = cos(psi - 1) - 4 (t - 0.3)^2 + (u . e)^2 with t = |y|: the maximum 2 at psi = 1,
    t = 0.3, u = +-e, none of the bounds active."""
    e = np.array([0.0, 1.0, 0.0, 0.0])

    def fun(psi, y):
        t = np.linalg.norm(y, axis=1)
        return np.cos(psi - 1.0) - 4 * (t - 0.3) ** 2 + (y @ e / t) ** 2

    rng = np.random.default_rng(RNG_SEED)
    start = _starts(fun, 16, 4, rng)
    value, psi, y = polish(fun, start, free_psi=True)
    best = int(np.argmax(value))
    assert value[best] == pytest.approx(2.0, abs=1e-9)
    assert np.mod(psi[best], 2 * np.pi) == pytest.approx(1.0, abs=1e-4)
    assert np.linalg.norm(y[best]) == pytest.approx(0.3, abs=1e-4)


def test_a_maximum_at_the_smallest_ray_parameter_stays_inside_the_bound():
    """f = -|y| is largest at t = T_MIN: the polish never leaves [T_MIN, 1]."""
    rng = np.random.default_rng(RNG_SEED)

    def fun(psi, y):
        return -np.linalg.norm(y, axis=1)

    start = _starts(fun, 8, 3, rng, psi=0.5)
    value, _, y = polish(fun, start, free_psi=False)
    t = np.linalg.norm(y, axis=1)
    assert np.all(t >= T_MIN * (1 - 1e-12)) and np.all(t <= 1e-6)
    assert np.all(value >= start.value)


def test_each_start_moves_alone_and_bad_starts_are_returned_unchanged():
    """Polishing a subset of the starts gives the same points as polishing all of them; a start
    at y = 0 or with a non-finite value is returned as it came."""
    rng = np.random.default_rng(RNG_SEED)
    _, fun = _quadratic_form(5, rng)
    start = _starts(fun, 12, 5, rng, psi=0.0)
    x = start.x.copy()
    x[3] = 0.0
    val = start.value.copy()
    val[7] = np.nan
    start = Extremum(val, start.psi, x)
    v_all, _, y_all = polish(fun, start, free_psi=False)
    sub = np.array([0, 5, 9])
    v_sub, _, y_sub = polish(fun, Extremum(start.value[sub], start.psi[sub], start.x[sub]), free_psi=False)
    np.testing.assert_array_equal(v_all[sub], v_sub)
    np.testing.assert_array_equal(y_all[sub], y_sub)
    assert np.all(y_all[3] == 0.0) and v_all[3] == start.value[3]
    assert np.isnan(v_all[7]) and np.all(y_all[7] == start.x[7])


def test_the_batched_polish_reaches_the_maxima_scipy_reaches_on_the_blades_band():
    """The largest W' of the forward C.G.'s hover quadratic function on the shell
    0.2 A <= |x| <= A (scaled), polished from the same 24 starts by both methods: the same best value (to the search's tolerance), and
    start by start never far below scipy's."""
    from rotorlyap.analysis.functions import quadratic_function
    from rotorlyap.model.blade import Blade
    from rotorlyap.model.parameters import BladeParameters

    blade = Blade(BladeParameters.table_i("forward"), 0.0)
    q = quadratic_function(blade, blade.equilibrium())
    A = 0.5
    rng = np.random.default_rng(RNG_SEED)
    u = rng.normal(size=(24, 6))
    u /= np.linalg.norm(u, axis=1)[:, None]
    t = rng.uniform(0.1, 1.0, 24)

    def fun(psi, y):  # W' along the shell 0.2 A <= |x| <= A (scaled), y = t u
        tt = np.linalg.norm(y, axis=1)
        r = 0.2 * A + np.clip(tt, 0, 1) * 0.8 * A
        return q.dW(psi, (y / np.maximum(tt, 1e-300)[:, None]) * r[:, None] * q.scales)

    start = Extremum(fun(np.zeros(24), u * t[:, None]), np.zeros(24), u * t[:, None])
    vb, _, _ = polish(fun, start, free_psi=False)
    vs, _, _ = polish_scipy(fun, start, free_psi=False)
    scale = np.abs(vs).max()
    assert vb.max() == pytest.approx(vs.max(), abs=1e-6 * scale)
    assert np.all(vb >= start.value) and np.all(vs >= start.value)
    assert np.median(vb - vs) >= -1e-6 * scale
