"""Benchmark: regenerate the data of Figs 4-8 from scratch with the notebooks' default grids.

Run: ``python benchmarks/bench_figures.py``. Single-threaded (OMP/OPENBLAS/MKL threads set
to 1 before numpy is imported); every cache is cleared first (the hover trim, the sphere
directions). Prints the time of each figure's data and the evaluations per second of the
Liapunov function and its derivative where the data function counts them. Target (issue 4):
all of Figs 4-8 in under 5 minutes on the 2-core CI machine.
"""

from __future__ import annotations

import os

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "NUMEXPR_NUM_THREADS"):
    os.environ[_var] = "1"

import sys  # noqa: E402
import time  # noqa: E402

TARGET_S = 300.0


def main() -> int:
    import numpy as np

    from rotorlyap.methods import sampling
    from rotorlyap.model import trim
    from rotorlyap.chapters import forward_flight, hover
    from rotorlyap.chapters.cases import CASES, MU_GRID, MU_GRID_STRICT

    trim.hover_trim.cache_clear()
    sampling._sphere_points_cached.cache_clear()
    cg_sweep = np.round(np.linspace(0.21, 0.28, 8), 3)
    jobs = [
        ("Fig 4  hover trim (8 C.G. + 3 cases)", lambda: hover.hover_trim_data(cg_sweep)),
        ("Fig 5  W' in hover (8 C.G., both readings)", lambda: hover.hover_rate_data(cg_sweep)),
        ("Fig 6  W on spheres, mu = 0.15 (5 A, 72 psi)",
         lambda: forward_flight.w_spheres_data("forward", 0.15, (0.5, 1.0, 2.0, 4.0, 8.0), n_psi=72)),
        ("Fig 7  W' against azimuth (6 mu, 72 psi)",
         lambda: forward_flight.rate_azimuth_data("forward", (0.0, 0.05, 0.1, 0.15, 0.2, 0.25), n_psi=72)),
        ("Fig 8  regions, practical (3 C.G. x 12 mu x 72 psi)",
         lambda: forward_flight.regions_data(CASES, MU_GRID, reading="practical", n_psi=72)),
        ("Fig 8  regions, strict (3 C.G. x 6 mu x 72 psi)",
         lambda: forward_flight.regions_data(CASES, MU_GRID_STRICT, reading="strict", n_psi=72, n_sphere=64)),
        ("Fig 8  sensitivity (7 variants x 8 mu)", lambda: forward_flight.sensitivity_data("forward")),
        ("Fig 8  convergence (n_sphere, n_stations, n_psi)", lambda: forward_flight.convergence_data()),
    ]
    total = 0.0
    print(f"{'data':55s} {'time (s)':>9s} {'evaluations':>12s} {'eval/s':>10s}")
    for name, fn in jobs:
        t0 = time.perf_counter()
        data = fn()
        dt = time.perf_counter() - t0
        total += dt
        n = getattr(data, "n_evaluations", None)
        rate = f"{n / dt:10.3g}" if n else f"{'-':>10s}"
        print(f"{name:55s} {dt:9.1f} {n if n else '-':>12} {rate}", flush=True)
    verdict = "meets" if total < TARGET_S else "MISSES"
    print(f"{'total':55s} {total:9.1f}   ({verdict} the target of {TARGET_S:.0f} s)")
    return 0 if total < TARGET_S else 1


if __name__ == "__main__":
    sys.exit(main())
