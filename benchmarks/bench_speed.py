"""Speed of the report, side by side: numpy path against compiled kernels, analyses, chapters.

Run: ``python benchmarks/bench_speed.py [--quick] [--no-chapters]``.

Prints, in one run:

1. states per second of the blade's right-hand side ``rhs`` and of ``W'`` of the energy and the
   quadratic Liapunov functions, numpy path (``ROTORLYAP_KERNEL=numpy``) and compiled path, at
   batches of 1, 32, 4096 and 1e6 states (the median of repeated calls);
2. the floating-point operations of one evaluation, counted in the kernels' source (additions,
   subtractions, multiplications and divisions; the square roots and trigonometric calls
   separately), and the fraction of one core's peak that the compiled path reaches;
3. the wall time of the command line's strict analyses (hover; mu = 0.15 about the periodic
   motion with the quadratic function), each in a fresh interpreter;
4. the searches' polish (:mod:`rotorlyap.methods.polish`): the same 64 starts on a blade's
   band polished one at a time by scipy's L-BFGS-B (the path before issue 27) and all together
   by the batched quasi-Newton ascent: time, calls of ``W'``, states evaluated, best value;
5. ``certify(..., verify=True)`` from a warm interpreter: the three Table I hover cases and the
   trimmed helicopter at mu = 0.1 (forward C.G.), beside the issue's targets and the times
   measured when it was filed (2026-12-03);
6. the execution time of every chapter from a fresh kernel (nbclient, one at a time), and
   their sum.

Single-threaded numerics (OMP/OPENBLAS/MKL threads = 1, set before numpy is imported). The
issue-12 targets are printed beside each figure; they are targets of this benchmark, not of
the tests. ``--quick`` skips the 1e6 batch and takes fewer repeats; ``--no-flight`` skips the
forward-flight proof of part 5.
"""

from __future__ import annotations

import os

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "NUMEXPR_NUM_THREADS"):
    os.environ[_var] = "1"

import argparse  # noqa: E402
import ast  # noqa: E402
import inspect  # noqa: E402
import statistics  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
BATCHES = (1, 32, 4096, 1_000_000)
FLOPS_PER_CYCLE_SIMD = 16  # AVX2: two 4-wide fused multiply-adds per cycle
FLOPS_PER_CYCLE_SCALAR = 4  # two scalar fused multiply-adds per cycle


# --------------------------------------------------------------------------------------
# Timing
# --------------------------------------------------------------------------------------

def _median_time(fn, *, budget: float = 0.5, min_repeat: int = 5) -> float:
    """Median wall time of ``fn()`` over repeated calls (at least ``min_repeat``, about
    ``budget`` seconds), s."""
    fn()  # warm: compile, caches
    times = []
    start = time.perf_counter()
    while len(times) < min_repeat or time.perf_counter() - start < budget:
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
        if len(times) >= 2000:
            break
    return statistics.median(times)


def _with_mode(mode: str):
    os.environ["ROTORLYAP_KERNEL"] = mode


def _set_threads(k: int | None) -> None:
    """Threads of the compiled kernels: ``k``, or every core for None."""
    from rotorlyap.jit import numba_available

    if numba_available():
        import numba

        numba.set_num_threads(numba.config.NUMBA_NUM_THREADS if k is None else k)


# --------------------------------------------------------------------------------------
# Operation counts
# --------------------------------------------------------------------------------------

_CALLS = {"sin", "cos", "atan2", "sqrt", "floor", "fmod"}


def _count(node: ast.AST) -> tuple[int, int]:
    """(arithmetic operations, transcendental calls) in an AST, each loop body counted once."""
    flops = calls = 0
    for sub in ast.walk(node):
        if isinstance(sub, ast.BinOp) and isinstance(sub.op, (ast.Add, ast.Sub, ast.Mult, ast.Div, ast.Mod)):
            flops += 1
        elif isinstance(sub, ast.AugAssign) and isinstance(sub.op, (ast.Add, ast.Sub, ast.Mult)):
            flops += 1
        elif isinstance(sub, ast.UnaryOp) and isinstance(sub.op, ast.USub):
            flops += 1
        elif isinstance(sub, ast.Call) and isinstance(sub.func, ast.Attribute) and sub.func.attr in _CALLS:
            calls += 1
    return flops, calls


def _function_ast(fn) -> ast.FunctionDef:
    fn = getattr(fn, "py_func", fn)
    return ast.parse(inspect.cleandoc("\n" + inspect.getsource(fn))).body[0]


def operation_counts(n_stations: int) -> dict[str, tuple[int, int]]:
    """(flops, transcendental calls) of one evaluation of rhs and of the energy W'."""
    from rotorlyap.model import compiled
    from rotorlyap.model._generated import blade_scalar

    def generated(name):
        return _count(ast.parse(inspect.getsource(getattr(blade_scalar, name))))

    acc = _function_ast(compiled._accelerations)
    loop = next(n for n in ast.walk(acc) if isinstance(n, ast.For))
    loop_f, loop_c = _count(loop)
    all_f, all_c = _count(acc)
    acc_f = all_f - loop_f + n_stations * loop_f
    acc_c = all_c - loop_c + n_stations * loop_c
    t_f, t_c = generated("rhs_terms_into")
    dw_f, dw_c = generated("rhs_dw_terms_into")
    ker = _function_ast(compiled._energy_rate_range)
    k_loop = next(n for n in ast.walk(ker) if isinstance(n, ast.For))
    k_f, k_c = _count(k_loop)
    return {"rhs": (t_f + acc_f, t_c + acc_c), "energy W'": (dw_f + acc_f + k_f, dw_c + acc_c + k_c)}


def clock_ghz() -> float | None:
    """The CPU clock read from /proc/cpuinfo (GHz), or None."""
    try:
        text = Path("/proc/cpuinfo").read_text()
    except OSError:
        return None
    mhz = [float(line.split(":")[1]) for line in text.splitlines() if line.startswith("cpu MHz")]
    return max(mhz) / 1000.0 if mhz else None


# --------------------------------------------------------------------------------------
# The parts
# --------------------------------------------------------------------------------------

def kernels(batches) -> dict:
    """States per second of rhs, energy W' and quadratic W', both paths, every batch."""
    from rotorlyap.analysis.functions import energy_function, quadratic_function
    from rotorlyap.model.blade import Blade
    from rotorlyap.model.parameters import BladeParameters
    from rotorlyap.model.steady import periodic_motion, tabulate_motion

    params = BladeParameters.table_i("forward")
    motion = tabulate_motion(periodic_motion(params, 0.15, n_points=128))
    rng = np.random.default_rng(0)
    n_max = max(batches)
    x = rng.normal(scale=0.02, size=(n_max, 6))
    psi = rng.uniform(0.0, 2.0 * np.pi, n_max)
    rates = {}
    for mode in ("numpy", "compiled, one state", "compiled", "compiled, all cores"):
        _with_mode(mode.split(",")[0])
        _set_threads(None if "all" in mode else 1)
        hover = Blade(params, 0.0)
        forward = Blade(params, 0.15)
        if "one state" in mode:  # the kernels before issue 27: one state at a time
            for blade in (hover, forward):
                blade.kernel.block = False
        xi = hover.equilibrium()
        energy = energy_function(hover, xi)
        quad = quadratic_function(forward, motion)
        z = xi + x
        for n in batches:
            budget = 0.3 if n < 1e5 else 0.0
            jobs = {
                "rhs (hover)": lambda: hover.rhs(psi[:n], z[:n]),
                "energy W' (hover)": lambda: energy.dW(psi[:n], x[:n]),
                "quadratic W' (mu = 0.15, periodic)": lambda: quad.dW(psi[:n], x[:n]),
            }
            for name, fn in jobs.items():
                t = _median_time(fn, budget=budget, min_repeat=3 if n >= 1e5 else 5)
                rates[(name, mode, n)] = n / t
    os.environ.pop("ROTORLYAP_KERNEL", None)
    return rates


def analyses() -> dict[str, float]:
    """Wall time of the command line's strict analyses, each in a fresh interpreter, s."""
    commands = {
        "analyse --cg forward --mu 0 (hover, energy, strict)":
            ["analyse", "--cg", "forward", "--mu", "0"],
        "analyse --cg forward --mu 0.15 --steady periodic --lyapunov quadratic":
            ["analyse", "--cg", "forward", "--mu", "0.15", "--steady", "periodic", "--lyapunov", "quadratic"],
    }
    out = {}
    for name, args in commands.items():
        t0 = time.perf_counter()
        subprocess.run([sys.executable, "-m", "rotorlyap", *args], check=True, cwd=ROOT,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        out[name] = time.perf_counter() - t0
    return out


#: ``certify(..., verify=True)`` from a warm interpreter when issue 27 was filed (2026-12-03, s)
#: and its targets (s).
CERTIFY_BEFORE = {"hover, forward C.G.": 5.5, "flight, mu = 0.1, forward C.G.": 269.0}
CERTIFY_TARGET = {"hover": 2.0, "flight": 20.0}


def polish_comparison(n_starts: int = 64) -> dict:
    """The same ``n_starts`` starts on the band of the forward C.G.'s quadratic function about its
    periodic motion at mu = 0.15 polished by both methods: time (s), calls, states, best value."""
    from rotorlyap.analysis.functions import quadratic_function
    from rotorlyap.methods.polish import polish, polish_scipy
    from rotorlyap.methods.sampling import Extremum
    from rotorlyap.model.blade import Blade
    from rotorlyap.model.parameters import BladeParameters
    from rotorlyap.model.steady import periodic_motion, tabulate_motion

    params = BladeParameters.table_i("forward")
    q = quadratic_function(Blade(params, 0.15), tabulate_motion(periodic_motion(params, 0.15, n_points=128)))
    A = 0.4
    calls = {"n": 0, "states": 0}

    def fun(psi, y):  # W' on the shell 0.2 A <= |x| <= A (scaled coordinates), y = t u
        calls["n"] += 1
        calls["states"] += psi.size
        t = np.linalg.norm(y, axis=1)
        r = A * (0.2 + 0.8 * np.clip(t, 0.0, 1.0))
        return q.dW(psi, (y / np.maximum(t, 1e-300)[:, None]) * r[:, None] * q.scales)

    rng = np.random.default_rng(0)
    u = rng.normal(size=(n_starts, 6))
    y = u / np.linalg.norm(u, axis=1)[:, None] * rng.uniform(0.1, 1.0, n_starts)[:, None]
    psi = rng.uniform(0.0, 2.0 * np.pi, n_starts)
    start = Extremum(fun(psi, y), psi, y)
    out = {}
    for name, method in (("scipy L-BFGS-B, one start at a time", polish_scipy), ("batched", polish)):
        method(fun, start, free_psi=True)  # warm
        calls.update(n=0, states=0)
        t0 = time.perf_counter()
        value, _, _ = method(fun, start, free_psi=True)
        out[name] = (time.perf_counter() - t0, calls["n"], calls["states"], float(value.max()))
    return out


def certify_times(flight: bool = True) -> dict[str, tuple[float, str]]:
    """``certify(..., verify=True)`` from a warm interpreter: (s, the proof's summary)."""
    from rotorlyap.analysis.certify import certify
    from rotorlyap.model.parameters import BladeParameters

    cases = {f"hover, {cg} C.G.": (BladeParameters.table_i(cg), 0.0) for cg in ("forward", "neutral", "backward")}
    if flight:
        cases["flight, mu = 0.1, forward C.G."] = (BladeParameters.flight_case("forward"), 0.1)
    certify(BladeParameters.table_i("forward"), 0.0, verify=True)  # warm: compile, caches
    out = {}
    for name, (params, mu) in cases.items():
        t0 = time.perf_counter()
        cert = certify(params, mu, verify=True)
        out[name] = (time.perf_counter() - t0, f"proved A = {cert.proof.A:.4g}, min lambda0 = "
                     f"{cert.proof.min_lambda0:.4g}" if cert.proof.proved else "not proved")
    return out


def chapters() -> dict[str, float]:
    """Execution time of every chapter from a fresh kernel, one at a time, s."""
    import nbformat
    from nbclient import NotebookClient

    out = {}
    for path in sorted((ROOT / "book").glob("[0-9][0-9]_*.ipynb")):
        nb = nbformat.read(path, as_version=4)  # executed in memory: the file is not written
        t0 = time.perf_counter()
        NotebookClient(nb, timeout=3600, kernel_name="python3",
                       resources={"metadata": {"path": str(path.parent)}}).execute()
        out[path.name] = time.perf_counter() - t0
        print(f"  {path.name:32s} {out[path.name]:6.1f} s", flush=True)
    return out


# --------------------------------------------------------------------------------------
# Report
# --------------------------------------------------------------------------------------

def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="no 1e6 batch, fewer repeats")
    parser.add_argument("--no-chapters", action="store_true", help="skip the chapter times")
    parser.add_argument("--no-flight", action="store_true", help="skip the forward-flight proof")
    args = parser.parse_args(argv)
    batches = BATCHES[:-1] if args.quick else BATCHES

    from rotorlyap.jit import numba_available
    from rotorlyap.model.parameters import BladeParameters

    print(f"python {sys.version.split()[0]}, numpy {np.__version__}, numba available: {numba_available()}, "
          "numerics on one thread unless said")
    rates = kernels(batches)
    print("\n1. states per second (median of repeated calls)")
    from rotorlyap.jit import PARALLEL_MIN_STATES

    print(f"(numpy and compiled: one thread; all cores: {os.cpu_count()} here, for batches of "
          f">= {PARALLEL_MIN_STATES} states)")
    head = (f"{'kernel':36s} {'batch':>8s} {'numpy':>11s} {'one state':>11s} {'block':>11s} "
            f"{'vs numpy':>8s} {'vs one':>7s} {'all cores':>11s}")
    print("compiled: 'one state', the kernels before issue 27 (one state at a time); 'block', today's"
          " (128 states in SIMD lanes)")
    print(head)
    names = sorted({k[0] for k in rates}, key=lambda s: ("rhs" not in s, "energy" not in s))
    for name in names:
        for n in batches:
            a, o, b = (rates[(name, m, n)] for m in ("numpy", "compiled, one state", "compiled"))
            c = rates[(name, "compiled, all cores", n)]
            print(f"{name:36s} {n:8d} {a:11,.0f} {o:11,.0f} {b:11,.0f} {b / a:7.1f}x {b / o:6.1f}x {c:11,.0f}")
    print("targets: W' of the energy and quadratic functions >= 5,000,000 states/s at batches >= 4096; "
          "rhs on 32 states >= 20x faster per call; the physical limit of the kernel: some tens of "
          "millions of states per second per core (issue 27)")

    counts = operation_counts(BladeParameters.table_i("forward").n_stations)
    ghz = clock_ghz()
    print("\n2. operations of one evaluation (counted in the kernels' source) and the share of one "
          "core's peak (compiled, one thread, best batch)")
    for name, key in (("rhs", "rhs (hover)"), ("energy W'", "energy W' (hover)")):
        flops, calls = counts[name]
        rate = max(rates[(key, "compiled", n)] for n in batches)  # one thread
        gflops = flops * rate / 1e9
        line = f"{name:10s} {flops:5d} flops + {calls:3d} sqrt/trig calls per state; {gflops:.2f} GFLOP/s"
        if ghz:
            line += (f" = {100 * gflops / (FLOPS_PER_CYCLE_SIMD * ghz):.1f} % of the AVX2 peak"
                     f" ({FLOPS_PER_CYCLE_SIMD} flops/cycle x {ghz:.2f} GHz),"
                     f" {100 * gflops / (FLOPS_PER_CYCLE_SCALAR * ghz):.0f} % of the scalar peak")
        print(line)

    print("\n3. command line, strict analyses (fresh interpreter, import included); target <= 3 s")
    for name, t in analyses().items():
        print(f"  python -m rotorlyap {name:70s} {t:6.1f} s")

    print("\n4. the searches' polish: 64 starts on a band of the forward C.G. at mu = 0.15, azimuth free")
    best_w = "best W'"
    print(f"  {'method':38s} {'time':>8s} {'calls':>7s} {'states':>9s} {best_w:>14s}")
    for name, (t, n_calls, n_states, best) in polish_comparison().items():
        print(f"  {name:38s} {t:7.3f}s {n_calls:7d} {n_states:9d} {best:14.8g}")

    print("\n5. certify(..., verify=True) from a warm interpreter (all cores); targets: hover <= "
          f"{CERTIFY_TARGET['hover']:g} s, flight <= {CERTIFY_TARGET['flight']:g} s")
    for name, (t, proof) in certify_times(not args.no_flight).items():
        before = CERTIFY_BEFORE.get(name)
        then = f"(2026-12-03: {before:g} s)" if before else ""
        print(f"  {name:34s} {t:7.1f} s {then:20s} {proof}")

    if not args.no_chapters:
        print("\n6. chapters executed from a fresh kernel, one at a time; target <= 180 s each")
        times = chapters()
        print(f"  {'all chapters':32s} {sum(times.values()):6.1f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
