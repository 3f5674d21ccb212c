"""Benchmark of the blade model: states per second of ``rhs`` and ``dW``, derive vs load.

Run: ``python benchmarks/bench_blade.py [n_states]``.  Single-threaded (OMP/OPENBLAS/MKL
threads set to 1 before numpy is imported).  Target (issue 3): at least 1e5 states/s for
``dW`` with the default number of spanwise stations.
"""

from __future__ import annotations

import os

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "NUMEXPR_NUM_THREADS"):
    os.environ[_var] = "1"

import subprocess  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402


def _best(fn, repeat: int = 3) -> float:
    """Best wall time of ``repeat`` calls, s."""
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return min(times)


def _timed_in_fresh_interpreter(setup: str, stmt: str) -> float:
    """Time of ``stmt`` after ``setup`` in a fresh interpreter (timed inside it), s."""
    code = (f"import time\n{setup}\nt0 = time.perf_counter()\n{stmt}\n"
            "print(time.perf_counter() - t0)")
    out = subprocess.run([sys.executable, "-c", code], check=True, capture_output=True, text=True)
    return float(out.stdout.strip().splitlines()[-1])


def main(n: int = 100_000) -> None:
    from rotorlyap.analysis.functions import energy_function
    from rotorlyap.model.blade import Blade
    from rotorlyap.model.parameters import BladeParameters

    params = BladeParameters.table_i("forward")
    t0 = time.perf_counter()
    blade = Blade(params, mu=0.15)
    t_build = time.perf_counter() - t0
    xi = blade.equilibrium()
    E = energy_function(blade, xi)
    rng = np.random.default_rng(0)
    x = rng.normal(scale=0.05, size=(n, 6))
    psi = rng.uniform(0.0, 2.0 * np.pi, n)
    z = xi + x

    print(f"blade: Table I forward C.G., mu = 0.15, n_stations = {params.n_stations}, "
          f"{n} states, 1 thread")
    print(f"Blade(...) construction incl. hover trim: {t_build:.3f} s")
    t = _best(lambda: blade.rhs(psi, z))
    print(f"rhs : {t:.3f} s  -> {n / t:,.0f} states/s")
    t = _best(lambda: E.dW(psi, x))
    print(f"dW  : {t:.3f} s  -> {n / t:,.0f} states/s  (target >= 100,000)")
    t = _best(lambda: E.W(psi, x))
    print(f"W   : {t:.3f} s  -> {n / t:,.0f} states/s")

    t_load = _timed_in_fresh_interpreter("import numpy, scipy.optimize, scipy.integrate",
                                         "import rotorlyap.model.blade")
    t_derive = _timed_in_fresh_interpreter(
        "import numpy, rotorlyap", "from rotorlyap.model import derivation; derivation.generate_source()")
    print(f"load cached code: {t_load:.3f} s (fresh interpreter: `import rotorlyap.model.blade`, which "
          "loads the generated model, after numpy and scipy)")
    print(f"derive + generate: {t_derive:.3f} s (fresh interpreter, sympy import included): "
          f"{t_derive / t_load:,.0f} x the load time")

if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 100_000)
