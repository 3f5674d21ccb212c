"""The block kernels (states in SIMD lanes, issue 27) against the one-state kernels.

Run: ``NUMBA_NUM_THREADS=1 python benchmarks/bench_simd.py [--quick]``.

Prints, on one thread:

1. the error of the vectorised ``atan2`` (:func:`rotorlyap.model.compiled._atan2`) against the C
   library's (numpy's ``arctan2``), in ulp, over 2e6 random arguments spanning 12 decades;
2. the largest difference between the block and the one-state kernels, relative to each
   column's largest magnitude (the measure of tests/test_compiled.py), for ``rhs`` and the
   energy function's ``W'`` over random states (small, large and very large disturbances:
   every branch of the airfoil table, reverse flow), several blades;
3. states per second of ``rhs`` and ``W'``, one-state and block kernels, at batches of 32, 256,
   4096 and 1e5 states: the median of repeated calls of the serial kernels, timed by
   ``time.process_time`` (the machine may be shared).
"""

from __future__ import annotations

import argparse
import time
from dataclasses import replace

import numpy as np

from rotorlyap.analysis.functions import energy_function
from rotorlyap.model import compiled as C
from rotorlyap.model.blade import Blade
from rotorlyap.model.parameters import BladeParameters
from rotorlyap.model.steady import periodic_motion, tabulate_motion


def blades():
    """Blades of the comparison: hover; forward flight with cyclic pitch, twist and the
    Prandtl-Glauert model; forward flight, backward C.G., no pitch damping."""
    fwd = BladeParameters.table_i("forward")
    return {
        "hover": (Blade(fwd, 0.0), None),
        "forward, cyclic, twist, compressible": (
            Blade(replace(fwd, cyclic_cos=0.02, cyclic_sin=-0.05, twist=-0.1,
                          compressibility="prandtl-glauert"), 0.3),
            np.array([0.05, 0.01, 0.15, 0.0, 0.0, 0.0])),
        "mu 0.15 about the periodic motion": (
            Blade(fwd, 0.15), tabulate_motion(periodic_motion(fwd, 0.15, n_points=32))),
        "backward C.G., no pitch damping": (
            Blade(replace(BladeParameters.table_i("backward"), cm_pitch_rate=0.0), 0.15), None),
    }


def states(n, spread, seed):
    rng = np.random.default_rng(seed)
    z = np.array([0.05, 0.02, 0.1, 0.0, 0.0, 0.0]) + rng.normal(scale=spread, size=(n, 6))
    return rng.uniform(0.0, 2.0 * np.pi, n), z


def rhs_args(blade, psi, z):
    d = blade.kernel
    return (psi, np.ascontiguousarray(z), C._controls(blade), d.P, d.scalars, d.stations,
            d.table, np.empty((z.shape[0], 6)))


def energy_args(blade, xi, psi, x):
    d = blade.kernel
    ef = energy_function(blade, blade.equilibrium() if xi is None else xi)
    xi_rows, ps, dxi = ef._steady_rows(psi, rates=True)
    c = np.ascontiguousarray
    return (c(psi), c(x), c(xi_rows, dtype=float), c(dxi, dtype=float), c(ps, dtype=float),
            C._controls(blade), d.P, d.scalars, d.stations, d.table,
            bool(ef.steady.is_constant), np.empty(x.shape[0]))


def scaled_difference(a, b):
    a = a.reshape(a.shape[0], -1)
    b = b.reshape(b.shape[0], -1)
    return float((np.abs(a - b) / np.max(np.abs(b), axis=0, keepdims=True)).max())


def atan2_error(n=2_000_000):
    rng = np.random.default_rng(0)
    y = rng.normal(size=n) * 10.0 ** rng.uniform(-6, 6, n)
    x = rng.normal(size=n) * 10.0 ** rng.uniform(-6, 6, n)
    got = np.empty(n)
    C._atan2_array(y, x, got)
    ref = np.arctan2(y, x)
    ulps = np.abs(got - ref) / np.spacing(np.abs(ref))
    return ulps.max(), ulps.mean(), float(np.mean(got == ref))


def rate(kernel, args, n, seconds):
    kernel(*args, 0, n)
    times, stop = [], time.process_time() + seconds
    while len(times) < 5 or time.process_time() < stop:
        t0 = time.process_time()
        kernel(*args, 0, n)
        times.append(time.process_time() - t0)
    return n / float(np.median(times))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fewer states and shorter timings")
    opts = parser.parse_args()
    seconds = 0.2 if opts.quick else 0.6
    worst_ulp, mean_ulp, exact = atan2_error(200_000 if opts.quick else 2_000_000)
    print(f"atan2: max {worst_ulp:.1f} ulp, mean {mean_ulp:.2f} ulp, {100 * exact:.0f}% equal "
          "to the C library's")
    cases = blades()
    print("\nlargest difference block - one-state kernel (relative to each column's largest value)")
    for name, (blade, xi) in cases.items():
        d_rhs = d_dw = 0.0
        for seed, spread in enumerate((0.01, 0.3, 3.0)):
            psi, z = states(5000 if opts.quick else 50000, spread, seed)
            a, b = rhs_args(blade, psi, z), rhs_args(blade, psi, z)
            C._rhs_range(*a, 0, psi.size)
            C._rhs_block_range(*b, 0, psi.size)
            d_rhs = max(d_rhs, scaled_difference(b[-1], a[-1]))
            x = z - z.mean(axis=0)
            a, b = energy_args(blade, xi, psi, x), energy_args(blade, xi, psi, x)
            C._energy_rate_range(*a, 0, psi.size)
            C._energy_rate_block_range(*b, 0, psi.size)
            d_dw = max(d_dw, scaled_difference(b[-1][:, None], a[-1][:, None]))
        print(f"  {name:40s} rhs {d_rhs:.1e}   W' {d_dw:.1e}")
    print("\nstates/s on one thread (M/s): one-state kernel -> block kernel (ratio)")
    for name in ("hover", "forward, cyclic, twist, compressible"):
        blade, xi = cases[name]
        print(f"  {name}")
        for n in (32, 256, 4096, 100_000):
            psi, z = states(n, 0.3, 7)
            r0 = rate(C._rhs_range, rhs_args(blade, psi, z), n, seconds)
            r1 = rate(C._rhs_block_range, rhs_args(blade, psi, z), n, seconds)
            x = 0.3 * (z - z.mean(axis=0))
            e0 = rate(C._energy_rate_range, energy_args(blade, xi, psi, x), n, seconds)
            e1 = rate(C._energy_rate_block_range, energy_args(blade, xi, psi, x), n, seconds)
            print(f"    n = {n:6d}   rhs {r0 / 1e6:5.2f} -> {r1 / 1e6:5.2f} ({r1 / r0:3.1f}x)"
                  f"   W' {e0 / 1e6:5.2f} -> {e1 / 1e6:5.2f} ({e1 / e0:3.1f}x)", flush=True)


if __name__ == "__main__":
    main()
