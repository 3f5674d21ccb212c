"""Time the yardstick (the blade's region of stable motion by simulation) and measure its integrator.

    python benchmarks/bench_region.py            # the five cases: time and extents per hinge
    python benchmarks/bench_region.py --steps    # RK4 steps per revolution against DOP853
    python benchmarks/bench_region.py --bound    # the extents' sensitivity to the bound

The five cases are those of the book: the Table I hovers (forward, neutral and backward C.G.,
the paper's controls) and the trimmed helicopter (forward C.G.) at mu = 0.1 and 0.2. Each runs
:func:`rotorlyap.analysis.region.stable_region` with its defaults (12 ray extents, two 31 x 31
slices). The numbers are measurements for a person; nothing here is compared by a test.

``--steps`` checks :data:`rotorlyap.methods.region.DEFAULT_STEPS_PER_PERIOD`: for three cases it
takes the starts that bracket each ray's extent (the last stable and the first unstable
amplitude of the bisection, and 0.9 and 1.1 times them), integrates them by RK4 with 32, 64, 128
and 256 steps per revolution and by scipy's DOP853 (rtol 1e-9, atol 1e-12, the norm sampled at
64 azimuths per revolution as RK4 with 64 steps samples it), and prints how many verdicts differ
from DOP853's, off the edge and on it, and the largest relative difference of the peak norms of
the motions that stayed within the bound.
"""

from __future__ import annotations

import sys
import time

import numpy as np

from rotorlyap.analysis.region import stable_region
from rotorlyap.conventions import HINGES
from rotorlyap.model.blade import Blade
from rotorlyap.model.forward_trim import forward_flight_trim
from rotorlyap.model.parameters import BladeParameters
from rotorlyap.model.steady import disturbed_rhs, tabulate_motion

CASES = [
    ("Table I forward C.G., hover", lambda: BladeParameters.table_i("forward"), 0.0, "none"),
    ("Table I neutral C.G., hover", lambda: BladeParameters.table_i("neutral"), 0.0, "none"),
    ("Table I backward C.G., hover", lambda: BladeParameters.table_i("backward"), 0.0, "none"),
    ("trimmed helicopter, mu = 0.1", lambda: BladeParameters.flight_case("forward"), 0.1, "propulsive"),
    ("trimmed helicopter, mu = 0.2", lambda: BladeParameters.flight_case("forward"), 0.2, "propulsive"),
]


def _setup(params, mu, condition):
    """The disturbed right-hand side about the trimmed steady motion, as stable_region builds it."""
    trim = forward_flight_trim(params, mu, condition)
    if trim.mu == 0.0:
        return disturbed_rhs(Blade(trim.params, 0.0), trim.steady)
    return disturbed_rhs(Blade(trim.params, trim.mu), tabulate_motion(trim.motion))


def cases() -> None:
    total = 0.0
    for label, params, mu, condition in CASES:
        p = params()
        forward_flight_trim(p, mu, condition)  # the trim is cached: time the yardstick alone
        t = time.perf_counter()
        r = stable_region(p, mu, condition=condition)
        dt = time.perf_counter() - t
        total += dt
        print(f"{label}: {dt:.1f} s ({r.n_periods} rev, sigma {r.growth_rate:.4f} per rev)")
        print("  " + r.summary().replace("\n", "\n  "))
        for sign, d in r.per_hinge_signed.items():
            print(f"    {sign}: " + ", ".join(f"{h} {d[h][0]:.3g} deg / {d[h][1]:.3g} deg/s" for h in HINGES))
        print(f"    scaled extents +: {np.round(r.extent[:6], 3)}  -: {np.round(r.extent[6:], 3)}")
        print(f"    per azimuth (scaled, rows = directions):\n{np.round(r.rays.extent, 2)}")
        for name, s in r.slices.items():
            print(f"    slice {name}: half-widths {s.axis_i[-1]:.3g}, {s.axis_j[-1]:.3g} scaled; "
                  f"stable {s.stable.sum()} of {s.stable.size}")
    print(f"total {total:.1f} s")


def _dop853(f, x0, psi0, n_rev, scales, bound, steps=64):
    """The verdict's inputs by DOP853 (rtol 1e-9, atol 1e-12), sampled as RK4 samples them: the
    norm at ``steps`` azimuths per revolution. Returns (left, peak, last_peak): left = some
    sample beyond ``bound``; peak over all samples; last_peak over the last revolution's."""
    from rotorlyap.methods.simulation import simulate
    from rotorlyap.methods.validation import simulate_within

    left = np.zeros(len(x0), dtype=bool)
    peak = np.full(len(x0), np.nan)
    last = np.full(len(x0), np.nan)
    for p in np.unique(psi0):
        sel = np.flatnonzero(psi0 == p)
        # stop a motion only far beyond the bound (3 times): its samples decide whether it left
        run = simulate_within(f, x0[sel], float(p), n_rev, 3.0 * bound, scales=scales, points_per_period=steps,
                              rtol=1e-9, atol=1e-12)
        left[sel] = run.max_norm > bound
        keep = sel[~left[sel]]
        if keep.size:
            s = simulate(f, x0[keep], float(p), n_rev, scales=scales, points_per_period=steps, rtol=1e-9,
                         atol=1e-12)
            peak[keep] = s.max_norm
            last[keep] = s.norm[-steps - 1:].max(axis=0)
    return left, peak, last


def steps() -> None:
    from rotorlyap.methods.region import integrate_batch

    for label, params, mu, condition in (CASES[0], CASES[2], CASES[4]):
        p = params()
        r = stable_region(p, mu, condition=condition, slices=False)
        f = _setup(p, mu, condition)
        rays = r.rays
        d, j = np.nonzero(~rays.hit_s_max)
        m = d.size
        s = np.concatenate([0.9 * rays.extent[d, j], rays.extent[d, j], rays.upper[d, j],
                            np.minimum(1.1 * rays.upper[d, j], 0.99 * r.bound)])
        edge = np.repeat([False, True, True, False], m)
        dd, jj = np.tile(d, 4), np.tile(j, 4)
        keep = s > 0
        s, dd, jj, edge = s[keep], dd[keep], jj[keep], edge[keep]
        x0 = s[:, None] * rays.directions[dd] * r.scales
        psi0 = rays.psi0[jj]
        t = time.perf_counter()
        left_ref, peak_ref, last_ref = _dop853(f, x0, psi0, r.n_periods, r.scales, r.bound)
        stable_ref = ~left_ref & (last_ref <= r.decay * s)
        print(f"{label}: {len(s)} starts ({edge.sum()} at the bisection's last bracket, 0.7 % wide), "
              f"{r.n_periods} rev, DOP853 {time.perf_counter() - t:.0f} s")
        for n in (32, 64, 128, 256):
            run = integrate_batch(f, x0, psi0, r.n_periods, scales=r.scales, bound=r.bound, steps_per_period=n)
            stable = ~run.left & (run.last_peak <= r.decay * s)
            diff = stable != stable_ref
            line = (f"  RK4 {n:4d} steps/rev: verdicts differing {diff[~edge].sum()} off the edge (0.9, 1.1 x), "
                    f"{diff[edge].sum()} on it")
            if n == 64:  # the same samples as the reference: compare the peaks too
                both = ~run.left & ~left_ref
                err = np.max(np.abs(run.peak[both] - peak_ref[both]) / peak_ref[both]) if both.any() else 0.0
                line += f"; peak norm rel. diff. {err:.1e}"
            print(line)


def bound() -> None:
    for label, params, mu, condition in (CASES[0], CASES[2], CASES[3]):
        p = params()
        for b in (30.0, 45.0, 90.0):
            r = stable_region(p, mu, condition=condition, slices=False, bound=b, s_max=min(40.0, 0.9 * b))
            print(f"{label}, bound {b:g}: scaled extents + {np.round(r.extent[:6], 2)} - {np.round(r.extent[6:], 2)}")


if __name__ == "__main__":
    {"--steps": steps, "--bound": bound}.get(sys.argv[1] if len(sys.argv) > 1 else "", cases)()
