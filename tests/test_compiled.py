"""The compiled kernels (rotorlyap.model.compiled) against the numpy path.

Fact checked: both paths evaluate the same formulas (the generated code of one derivation and
the same strip loads), so they agree to round-off, about 1e-15 relative to the size of each
quantity; the test allows 1e-13. The compiled path runs the block kernels (states in SIMD
lanes); they are also checked against the one-state kernels, and their atan2 against C's. The numpy path is the reference: it is the one the physics
tests of tests/test_blade.py and tests/test_derivation.py check against closed forms.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from rotorlyap.analysis.functions import energy_function
from rotorlyap.jit import numba_available
from rotorlyap.model.airfoil import LinearAirfoil
from rotorlyap.model import compiled
from rotorlyap.model.blade import Blade
from rotorlyap.model.parameters import BladeParameters
from rotorlyap.model.steady import periodic_motion, tabulate_motion

pytestmark = pytest.mark.skipif(not numba_available(), reason="numba is not installed")

RTOL = 1e-13


def _states(rng, n, spread):
    """Disturbed states about a typical hover trim, and azimuths over the whole circle."""
    z = np.array([0.05, 0.02, 0.1, 0.0, 0.0, 0.0]) + rng.normal(scale=spread, size=(n, 6))
    return rng.uniform(0.0, 2.0 * np.pi, n), z


def _close(a, b):
    """Equal to RTOL relative to each column's largest magnitude (round-off is relative to the
    size of the terms, not of a result that cancels to near zero)."""
    scale = np.max(np.abs(b), axis=0, keepdims=True)
    assert a.shape == b.shape
    excess = np.abs(a - b) / (RTOL * scale + 1e-300)
    assert excess.max() <= 1.0, f"differs by {excess.max():.1f} x {RTOL} of the column's size"


CASES = [
    ("hover, Table I forward C.G.", {}, 0.0),
    ("forward flight, cyclic and twist", {"cyclic_cos": 0.02, "cyclic_sin": -0.05, "twist": -0.1}, 0.3),
    ("vacuum (no air loads)", {"air_density": 0.0, "collective": 0.1}, 0.0),
    ("no pitch damping, backward C.G.", {"cm_pitch_rate": 0.0}, 0.15),
]


@pytest.mark.parametrize("label, changes, mu", CASES, ids=[c[0] for c in CASES])
def test_rhs_equals_numpy_path(kernel_pair, label, changes, mu):
    """h(psi, z) of the compiled kernel equals the numpy path to 1e-13 relative, small and large
    disturbances (large ones reach reverse flow and stall: every branch of the airfoil table)."""
    base = BladeParameters.table_i("backward" if "backward" in label else "forward")
    fast, slow = kernel_pair(replace(base, **changes), mu)
    rng = np.random.default_rng(1)
    for spread in (0.01, 0.5, 3.0):
        psi, z = _states(rng, 2000, spread)
        _close(fast.rhs(psi, z), slow.rhs(psi, z))
    # the shapes of the public API: one state, a scalar azimuth, leading axes
    psi, z = _states(rng, 12, 0.1)
    _close(fast.rhs(0.7, z[0]), slow.rhs(0.7, z[0]))
    assert fast.rhs(0.7, z[0]).shape == (6,)
    assert fast.rhs(psi.reshape(3, 4), z.reshape(3, 4, 6)).shape == (3, 4, 6)
    _close(fast.rhs(psi.reshape(3, 4), z.reshape(3, 4, 6)).reshape(-1, 6), slow.rhs(psi, z))


def test_potential_terms_equal_numpy_path(kernel_pair):
    """The effective potential and its derivatives (14 rows) agree with the numpy path."""
    params = replace(BladeParameters.table_i("neutral"), cyclic_cos=0.03, cyclic_sin=0.01)
    fast, slow = kernel_pair(params, 0.2)
    rng = np.random.default_rng(2)
    psi, z = _states(rng, 500, 0.3)
    _close(fast.potential_terms(psi, z[:, :3].T).T, slow.potential_terms(psi, z[:, :3].T).T)


@pytest.mark.parametrize("steady", ["hover", "cyclic", "periodic"])
def test_energy_rate_equals_numpy_path(kernel_pair, steady):
    """W and W' of the energy function (each its own compiled kernel) agree with the numpy path:
    about the hover equilibrium, about a constant state with cyclic pitch (psi-dependent
    control), and about a periodic motion."""
    params = BladeParameters.table_i("forward")
    if steady == "cyclic":
        params = replace(params, cyclic_cos=0.02, cyclic_sin=-0.04, collective=0.15)
    mu = 0.0 if steady == "hover" else 0.15
    fast, slow = kernel_pair(params, mu)
    if steady == "periodic":
        xi = tabulate_motion(periodic_motion(params, mu, n_points=32))
    else:
        xi = fast.equilibrium() if steady == "hover" else np.array([0.05, 0.01, 0.15, 0, 0, 0])
    rng = np.random.default_rng(3)
    psi = np.repeat(np.linspace(0.0, 2.0 * np.pi, 24, endpoint=False), 50)
    x = rng.normal(scale=0.1, size=(psi.size, 6))
    a, b = energy_function(fast, xi), energy_function(slow, xi)
    _close(a.dW(psi, x)[:, None], b.dW(psi, x)[:, None])
    _close(a.W(psi, x)[:, None], b.W(psi, x)[:, None])


def test_kernel_mode_rejects_unknown_values(monkeypatch):
    """A clear error names the variable and the allowed values."""
    monkeypatch.setenv("ROTORLYAP_KERNEL", "fortran")
    with pytest.raises(ValueError, match=r"ROTORLYAP_KERNEL must be one of \('compiled', 'numpy'\)"):
        Blade(BladeParameters.table_i("forward"), 0.0)


def test_untabulated_airfoils_use_the_numpy_path(monkeypatch):
    """An airfoil without a table (LinearAirfoil) has no compiled kernel: the numpy path runs."""
    monkeypatch.setenv("ROTORLYAP_KERNEL", "compiled")
    blade = Blade(replace(BladeParameters.table_i("forward"), airfoil=LinearAirfoil()), 0.0)
    assert blade.kernel is None
    assert np.isfinite(blade.rhs(0.0, blade.equilibrium())).all()


def _kernel_args(blade, psi, z):
    d = blade.kernel
    return (psi, np.ascontiguousarray(z), compiled._controls(blade), d.P, d.scalars, d.stations,
            d.table, np.empty((z.shape[0], 6)))


@pytest.mark.parametrize("label, changes, mu", CASES, ids=[c[0] for c in CASES])
def test_block_kernel_equals_one_state_kernel(label, changes, mu):
    """The block kernel of rhs (states in SIMD lanes) equals the one-state kernel to 1e-13 (the
    operations are the same but atan2, a polynomial of at most 2 ulp), and its numbers do not
    depend on where a state falls in a block: a batch split at odd places gives the same bits."""
    base = BladeParameters.table_i("backward" if "backward" in label else "forward")
    blade = Blade(replace(base, **changes), mu)
    assert blade.kernel is not None and blade.kernel.block
    rng = np.random.default_rng(11)
    for spread in (0.01, 0.5, 3.0):
        psi, z = _states(rng, 1000, spread)
        a, b = _kernel_args(blade, psi, z), _kernel_args(blade, psi, z)
        compiled._rhs_range(*a, 0, 1000)
        compiled._rhs_block_range(*b, 0, 1000)
        _close(b[-1], a[-1])
        c = _kernel_args(blade, psi, z)
        for start, stop in ((0, 3), (3, 200), (200, 1000)):
            compiled._rhs_block_range(*c, start, stop)
        np.testing.assert_array_equal(c[-1], b[-1])


@pytest.mark.parametrize("steady", ["hover", "periodic"])
def test_block_energy_value_kernel_gives_the_bits_of_the_one_state_kernel(steady):
    """The energy function's W by blocks (the mass matrix of the vectorised rhs_terms block code)
    equals the one-state kernel bit for bit, wherever a state falls in a block."""
    params = BladeParameters.table_i("forward")
    mu = 0.0 if steady == "hover" else 0.15
    blade = Blade(params, mu)
    assert blade.kernel is not None and blade.kernel.block
    fun = energy_function(blade, blade.equilibrium() if steady == "hover"
                          else tabulate_motion(periodic_motion(params, mu, n_points=32)))
    rng = np.random.default_rng(5)
    psi = rng.uniform(0.0, 2.0 * np.pi, 700)
    x = rng.normal(scale=0.3, size=(psi.size, 6))
    xi, ps = fun._steady_rows(psi)
    d = blade.kernel
    args = (psi, x, np.ascontiguousarray(xi), np.ascontiguousarray(ps), compiled._controls(blade), d.P, d.scalars)
    one, block, split = np.empty(psi.size), np.empty(psi.size), np.empty(psi.size)
    compiled._energy_value_range(*args, one, 0, psi.size)
    compiled._energy_value_block_range(*args, block, 0, psi.size)
    for start, stop in ((0, 3), (3, 200), (200, psi.size)):
        compiled._energy_value_block_range(*args, split, start, stop)
    np.testing.assert_array_equal(block, one)
    np.testing.assert_array_equal(split, one)


def test_threaded_batches_give_the_bits_of_one_thread(monkeypatch):
    """A batch of at least PARALLEL_MIN_STATES states runs in chunks on the kernels' thread pool
    (rotorlyap.model.compiled._run, here with two threads whatever NUMBA_NUM_THREADS says);
    each state is computed alone, so rhs, W and W' of the energy function are the same bits as
    with one thread, and an error raised in a chunk reaches the caller."""
    from rotorlyap.jit import PARALLEL_MIN_STATES

    params = replace(BladeParameters.table_i("neutral"), cyclic_cos=0.02, cyclic_sin=-0.03)
    blade = Blade(params, 0.2)
    xi = np.array([0.05, 0.01, 0.15, 0.0, 0.0, 0.0])
    fun = energy_function(blade, xi)
    rng = np.random.default_rng(5)
    n = 2 * PARALLEL_MIN_STATES + 37  # chunks of unequal length
    psi, z = _states(rng, n, 0.3)
    results = []
    for k in (1, 2):
        monkeypatch.setattr(compiled, "threads", lambda k=k: k)
        results.append((blade.rhs(psi, z), fun.W(psi, z), fun.dW(psi, z)))
    for one, two in zip(*results):
        np.testing.assert_array_equal(one, two)
    assert any(key[1] == 1 for key in compiled._POOLS)  # the two-thread run used the pool

    def failing(*args):
        raise ZeroDivisionError("in a chunk")

    with pytest.raises(ZeroDivisionError, match="in a chunk"):
        compiled._run(failing, n, ())


def test_vectorised_atan2_is_within_two_ulp():
    """The branch-free atan2 of the block kernels against the C library's: at most 2 ulp over
    random arguments of 12 decades, and exact at the zeros and axes (signs as C's atan2)."""
    rng = np.random.default_rng(12)
    y = rng.normal(size=100_000) * 10.0 ** rng.uniform(-6, 6, 100_000)
    x = rng.normal(size=100_000) * 10.0 ** rng.uniform(-6, 6, 100_000)
    zeros = np.array([0.0, -0.0])
    y = np.concatenate([y, np.repeat(zeros, 2), [1.0, -1.0, 2.5, -2.5, 0.0, -0.0]])
    x = np.concatenate([x, np.tile(zeros, 2), [0.0, -0.0, 2.5, -2.5, 3.0, -3.0]])
    got = np.empty_like(y)
    compiled._atan2_array(y, x, got)
    ref = np.arctan2(y, x)
    assert np.all(np.abs(got - ref) <= 2.0 * np.spacing(np.abs(ref)))
    np.testing.assert_array_equal(np.signbit(got), np.signbit(ref))


@pytest.mark.skipif(not numba_available(), reason="numba is not installed")
def test_periodic_lyapunov_sweeps_equal_their_numpy_twins():
    """The compiled forward and backward sweeps of the periodic Lyapunov solver
    (rotorlyap.methods.periodic_lyapunov: the forcing carried to the period's start, and P at each
    piece's start) give their numpy twins' matrices to round-off: the same products, summed in
    another order."""
    import importlib

    pl = importlib.import_module("rotorlyap.methods.periodic_lyapunov")
    rng = np.random.default_rng(3)
    K, n = 64, 6
    S = np.eye(n) + 0.05 * rng.normal(size=(K, n, n))
    G = rng.normal(size=(K, n, n))
    G = G + np.swapaxes(G, 1, 2)
    total = pl._gramian_sum_numpy(S, G)
    assert np.allclose(pl._gramian_sum(S, G), total, rtol=0, atol=1e-13 * np.abs(total).max())
    P0 = rng.normal(size=(n, n))
    P0 = P0 + P0.T
    expected, got = np.empty((K, n, n)), np.empty((K, n, n))
    pl._backward_sweep_numpy(S, G, P0, expected)
    pl._backward_sweep(S, G, P0, got)
    assert np.allclose(got, expected, rtol=0, atol=1e-13 * np.abs(expected).max())
    assert np.array_equal(got, np.swapaxes(got, 1, 2))  # symmetric by construction
