"""Ball arithmetic for the proofs: the measurements behind the choice of Arb (issue 17).

Run: ``python benchmarks/bench_intervals.py [--flight]``.

Prints, in one run:

1. the cost per element of a product, a sum and a sine of two arrays of intervals, for
   (a) Arb balls (python-flint) in numpy object arrays, the layout of
   :mod:`rotorlyap.methods.intervals`; (b) Arb balls in a Python list; (c) a numpy interval
   type on float arrays (lower and upper bounds, four products, min, max and ``nextafter``
   outward rounding; its sine would also have to assume an error bound of the C library);
2. the wall time of the blade's enclosures: the right-hand side and its Jacobian on one
   interval (first order), with Hessians (second order), and on 512 azimuth intervals;
3. the wall time of one hover proof (``certify(..., verify=True)``, forward C.G.) and, with
   ``--flight``, of the forward-flight proof of the proofs chapter.

Single-threaded numerics (OMP/OPENBLAS threads = 1). Figures, not tests: nothing here fails.
"""

from __future__ import annotations

import os

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ[_var] = "1"

import argparse  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402
from flint import arb  # noqa: E402


def _per_element(fun, n: int, repeat: int = 5) -> float:
    """Best of ``repeat`` calls of ``fun()`` on ``n`` elements, in microseconds per element."""
    best = np.inf
    for _ in range(repeat):
        t = time.perf_counter()
        fun()
        best = min(best, time.perf_counter() - t)
    return best / n * 1e6


def elementary(n: int = 20000) -> None:
    rng = np.random.default_rng(0)
    m1, m2 = rng.uniform(0.5, 1.5, n), rng.uniform(0.5, 1.5, n)
    r = 1e-6
    A = np.array([arb(float(a), r) for a in m1], dtype=object)
    B = np.array([arb(float(b), r) for b in m2], dtype=object)
    La, Lb = list(A), list(B)
    lo1, hi1, lo2, hi2 = m1 - r, m1 + r, m2 - r, m2 + r

    def np_mul():
        p = np.stack([lo1 * lo2, lo1 * hi2, hi1 * lo2, hi1 * hi2])
        return np.nextafter(p.min(0), -np.inf), np.nextafter(p.max(0), np.inf)

    def np_add():
        return np.nextafter(lo1 + lo2, -np.inf), np.nextafter(hi1 + hi2, np.inf)

    def np_sin():  # monotone pieces only; a C-library error bound still has to be assumed
        s1, s2 = np.sin(lo1), np.sin(hi1)
        return np.nextafter(np.minimum(s1, s2) - 4e-16, -np.inf), np.nextafter(np.maximum(s1, s2) + 4e-16, np.inf)

    sin = np.frompyfunc(lambda b: b.sin(), 1, 1)
    rows = [
        ("product", lambda: A * B, lambda: [a * b for a, b in zip(La, Lb)], np_mul),
        ("sum", lambda: A + B, lambda: [a + b for a, b in zip(La, Lb)], np_add),
        ("sine", lambda: sin(A), lambda: [a.sin() for a in La], np_sin),
    ]
    print("1. cost per element, us (best of 5, %d elements)" % n)
    print(f"   {'operation':10s} {'Arb, object array':>18s} {'Arb, list':>10s} {'numpy intervals':>16s}")
    for name, f_obj, f_list, f_np in rows:
        print(f"   {name:10s} {_per_element(f_obj, n):18.3f} {_per_element(f_list, n):10.3f} "
              f"{_per_element(f_np, n):16.4f}")


def blade(flight: bool) -> None:
    from rotorlyap import certify
    from rotorlyap.analysis.enclosure import BladeEnclosure
    from rotorlyap.conventions import DEFAULT_SCALES
    from rotorlyap.model.blade import Blade
    from rotorlyap.model.parameters import BladeParameters

    b = Blade(BladeParameters.table_i("forward"), 0.0)
    enc = BladeEnclosure(b)
    print("2. the blade's enclosures, s")
    for label, kwargs in (("first order, 1 interval", {}),
                          ("second order, 1 interval, tube A = 0.03", {"radius": 0.03 * DEFAULT_SCALES, "order": 2})):
        t = time.perf_counter()
        enc.evaluate(1, **kwargs)
        print(f"   {label:45s} {time.perf_counter() - t:8.3f}")
    from rotorlyap.model.forward_trim import forward_flight_trim
    from rotorlyap.model.steady import tabulate_motion

    trim = forward_flight_trim(BladeParameters.flight_case("forward"), 0.1)
    fe = BladeEnclosure(Blade(trim.params, 0.1), tabulate_motion(trim.motion, n=512))
    for label, kwargs in (("first order, 512 intervals (mu = 0.1)", {}),
                          ("second order, 512 intervals, tube A = 0.01", {"radius": 0.01 * DEFAULT_SCALES, "order": 2})):
        t = time.perf_counter()
        fe.evaluate(512, **kwargs)
        print(f"   {label:45s} {time.perf_counter() - t:8.3f}")
    print("3. proofs, s")
    t = time.perf_counter()
    certify(BladeParameters.table_i("forward"), 0.0, function="quadratic", verify=True)
    print(f"   {'hover, forward C.G. (numerical + proof)':45s} {time.perf_counter() - t:8.1f}")
    if flight:
        t = time.perf_counter()
        certify(BladeParameters.flight_case("forward"), 0.1, function="quadratic", verify=True)
        print(f"   {'mu = 0.1, trimmed (numerical + proof)':45s} {time.perf_counter() - t:8.1f}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--flight", action="store_true", help="also time the forward-flight proof (minutes)")
    args = parser.parse_args()
    elementary()
    blade(args.flight)


if __name__ == "__main__":
    main()
