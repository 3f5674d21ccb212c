"""Benchmark: the warm time of the default :func:`rotorlyap.certify`, stage by stage.

Run: ``python benchmarks/bench_certify.py [--mu 0 0.1] [--repeat 1] [--profile FILE]``.

"Warm" here means: the package imported, the numba kernels loaded and the caches that a first
call fills (the sphere directions, ...) filled, by one ``certify`` of the Table I forward C.G. in
hover before anything is timed. The kernels that only forward flight uses are loaded from
numba's disk cache (``__pycache__``) inside the first timed call at mu > 0; on a machine (or a
checkout) where they were never compiled, that first call compiles them too (about 25 s, measured
2026-12-05): run the benchmark twice, or use ``--repeat 2``. Each timed call is then the default ``certify`` of the
trimmed Table I helicopter (forward C.G., ``BladeParameters.flight_case("forward")``) at the
given advance ratio, from the trim to the start set; its stages are timed by listening to
:mod:`rotorlyap.progress` (a stage lasts from its first report to the next stage's first report,
and stages with the same leading words are summed). Prints the wall time of each call, the
stage shares and the certified numbers. One BLAS thread, as the command line runs
(:mod:`rotorlyap.cli`); the compiled kernels on numba's threads (``NUMBA_NUM_THREADS``). Figures,
not tests: nothing here fails, and no test times anything.
"""

from __future__ import annotations

import os

for _var in ("OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):  # as the command line (rotorlyap.cli)
    os.environ.setdefault(_var, "1")

import argparse  # noqa: E402
import re  # noqa: E402
import time  # noqa: E402
from collections import defaultdict  # noqa: E402


def stage_group(stage: str) -> str:
    """The group a progress stage is summed into: its leading words, numbers dropped
    (``"design: start radius 0.4, bound 1.6: round"`` -> ``"design"``, thorough rounds apart)."""
    if stage.startswith("design"):
        return "design (thorough rounds)" if "thorough" in stage else "design (search rounds)"
    if stage.startswith("sound rule: final check"):
        return "sound rule: final check"
    if stage.startswith("sound rule: the band"):  # the bound's tests: level, shell, band searches
        return "sound rule: band tests of the bound"
    if stage.startswith("candidate"):
        return "candidate setup: " + stage.split("the ", 1)[-1]
    return re.sub(r"[\d.]+", "#", stage)


class StageTimer:
    """A :mod:`rotorlyap.progress` listener that sums the wall time of each stage group."""

    def __init__(self) -> None:
        self.totals: dict[str, float] = defaultdict(float)
        self.order: list[str] = []
        self._stage: str | None = None
        self._family = ""
        self._since = time.perf_counter()

    def __call__(self, stage: str, done: int | None = None, total: int | None = None) -> None:
        if stage.startswith("candidate"):
            self._family = stage.split("the ", 1)[-1].split()[0]
        group = stage_group(stage)
        if group.startswith("sound rule"):
            group = f"{self._family}: {group}"
        if group != self._stage:
            self._switch(group)

    def _switch(self, group: str | None) -> None:
        now = time.perf_counter()
        if self._stage is not None:
            self.totals[self._stage] += now - self._since
        if group is not None and group not in self.totals:
            self.order.append(group)
            self.totals[group] += 0.0
        self._stage, self._since = group, now

    def close(self) -> None:
        self._switch(None)


def run(params, mu: float):
    """``(seconds, certificate, stage totals)`` of one default certify."""
    import rotorlyap
    from rotorlyap.progress import listening

    timer = StageTimer()
    t0 = time.perf_counter()
    with listening(timer):
        cert = rotorlyap.certify(params, mu)
    return time.perf_counter() - t0, cert, timer


def describe(cert) -> str:
    lines = [f"  certified={cert.certified} function={cert.function} A={cert.bound:.6g} "
             f"lambda0={cert.start_region:.6g}"]
    design = getattr(cert.lyapunov, "design", None)
    if design is not None:
        res = cert.result
        lines.append(f"  design {design!r}, A requested {res.A_requested:.6g}, step 3 {res.A_step3:.6g}, "
                     f"level {res.level:.6g}, final check {res.check_evaluations} evaluations of W'")
        lines.append("  tried " + ", ".join(f"({lam:.4g}, {A:.4g}, {ok})" for lam, A, ok in design.tried))
    for c in cert.candidates:
        reach = ", ".join(f"{v:.4g}" for v in c.start_set)
        lines.append(f"    {c.function:9s}: certified={c.certified} A={c.bound:.6g} lambda0={c.start_region:.6g} "
                     f"start set [{reach}]")
    return "\n".join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mu", type=float, nargs="+", default=[0.0, 0.1])
    parser.add_argument("--repeat", type=int, default=1, help="timed calls per advance ratio (best of)")
    parser.add_argument("--profile", help="write a cProfile of the timed calls to this file")
    args = parser.parse_args()

    import rotorlyap
    from rotorlyap.model.parameters import BladeParameters

    params = BladeParameters.flight_case("forward")
    t = time.perf_counter()
    rotorlyap.certify(BladeParameters.table_i("forward"), 0.0)  # warms imports, numba, caches
    print(f"warm-up (hover certify, imports and compiles): {time.perf_counter() - t:.1f} s", flush=True)
    profiler = None
    if args.profile:
        import cProfile

        profiler = cProfile.Profile()
    for mu in args.mu:
        best = None
        for k in range(args.repeat):
            if profiler is not None:
                profiler.enable()
            seconds, cert, timer = run(params, mu)
            if profiler is not None:
                profiler.disable()
            print(f"mu = {mu:g}, call {k + 1}: {seconds:.1f} s", flush=True)
            if best is None or seconds < best[0]:
                best = (seconds, cert, timer)
        seconds, cert, timer = best
        print(f"mu = {mu:g}: best of {args.repeat}: {seconds:.1f} s")
        for group in timer.order:
            share = timer.totals[group]
            print(f"    {group:45s} {share:7.1f} s  {100 * share / seconds:5.1f} %")
        print(describe(cert), flush=True)
    if profiler is not None:
        profiler.dump_stats(args.profile)
        print(f"profile written to {args.profile}")


if __name__ == "__main__":
    main()
