"""Proved against numerical bounds: the quadratic function's certificates proved by both provers (issue 41).

Run: ``python benchmarks/bench_proof.py [--flight] [--designed] [--repeat N]``.

For each Table I hover (forward, neutral and backward C.G.) the quadratic function's numerical
certificate (``certify(params, 0.0, function="quadratic")``: the bound ``A`` and the start radius
``lambda0``) and the proof of the same function by
:func:`rotorlyap.analysis.proof.prove_blade` with ``method="balls"`` (the mean-value form in ball
arithmetic) and ``method="taylor"`` (Taylor models and branch and bound) on the whole band of
condition (h) (``band``, ``level_set=False``) and on the level set (``level``, the default): the
proved bound and start radius, their ratios to the numerical ones, and the proof's wall time from
a warm interpreter (the best of ``--repeat`` runs after one that warms the caches and compiles the
kernels).

``--flight``: the same for the trimmed helicopter at ``mu = 0.1`` (``flight_case("forward")``,
the motion refined as ``certify(..., verify=True)`` refines it; minutes for the numerical
certificate), the band's proof both over shells of cubes (``band``, its default there) and over
one cube (``band1``, ``shells=False``).

``--designed``: the forward C.G.'s designed hover function (a quadratic form,
:func:`rotorlyap.analysis.proof.prove_designed`): its proved bound and start radius against the
design's.

Figures, not tests: nothing here fails. Single-threaded numerics.
"""

from __future__ import annotations

import os

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "NUMBA_NUM_THREADS"):
    os.environ[_var] = "1"

import importlib  # noqa: E402
import time  # noqa: E402


def _timed(fun, repeat: int):
    """``(result, best wall time)`` of ``fun()`` over ``repeat`` runs after a warm-up run."""
    out = fun()
    best = float("inf")
    for _ in range(max(int(repeat), 1)):
        t = time.perf_counter()
        out = fun()
        best = min(best, time.perf_counter() - t)
    return out, best


def _row(case: str, method: str, A_num: float, lam_num: float, proof, seconds: float) -> None:
    print(f"{case:26s} {method:7s} {A_num:9.4g} {proof.A:9.4g} {proof.A / A_num:6.3f} {lam_num:9.4g} "
          f"{proof.min_lambda0:9.4g} {proof.min_lambda0 / lam_num:6.3f} {seconds:8.2f}", flush=True)


def _header() -> None:
    print(f"{'case':26s} {'prover':7s} {'A num':>9s} {'A proved':>9s} {'ratio':>6s} {'lam0 num':>9s} "
          f"{'lam0 prv':>9s} {'ratio':>6s} {'time s':>8s}")


def _hover(repeat: int) -> None:
    from rotorlyap import certify
    from rotorlyap.analysis.proof import prove_blade
    from rotorlyap.model.parameters import BladeParameters

    _header()
    for cg in ("forward", "neutral", "backward"):
        cert = certify(BladeParameters.table_i(cg), 0.0, function="quadratic")
        for label, kw in (("balls", dict(method="balls")), ("band", dict(level_set=False)), ("level", {})):
            proof, dt = _timed(lambda: prove_blade(cert.lyapunov, cert.bound, **kw), repeat)
            _row(f"{cg} C.G. hover", label, cert.bound, cert.start_region, proof, dt)


def _flight(repeat: int) -> None:
    from rotorlyap.analysis.proof import prove_blade
    from rotorlyap.model.parameters import BladeParameters

    certify_module = importlib.import_module("rotorlyap.analysis.certify")
    skip = certify_module.prove_certificate
    certify_module.prove_certificate = lambda *args, **kwargs: (None, None)  # the motion refined, no proof yet
    try:
        t = time.perf_counter()
        cert = certify_module.certify(BladeParameters.flight_case("forward"), 0.1, function="quadratic",
                                      verify=True)
        print(f"(numerical certificate at mu = 0.1: {time.perf_counter() - t:.0f} s)", flush=True)
    finally:
        certify_module.prove_certificate = skip
    for label, kw in (("balls", dict(method="balls")), ("band1", dict(level_set=False, shells=False)),
                      ("band", dict(level_set=False)), ("level", {})):
        proof, dt = _timed(lambda: prove_blade(cert.lyapunov, cert.bound, **kw), repeat)
        _row("trimmed helicopter mu=0.1", label, cert.bound, cert.start_region, proof, dt)


def _designed(repeat: int) -> None:
    from rotorlyap import certify
    from rotorlyap.analysis.proof import prove_designed
    from rotorlyap.model.parameters import BladeParameters

    cert = certify(BladeParameters.table_i("forward"), 0.0)
    fun = cert.lyapunov
    for method in ("balls", "taylor"):
        proof, dt = _timed(lambda: prove_designed(fun, method=method), repeat)
        _row("forward C.G. designed", method, cert.bound, cert.start_region, proof, dt)


def main() -> None:
    import argparse

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--flight", action="store_true", help="also the trimmed helicopter at mu = 0.1 (minutes)")
    parser.add_argument("--designed", action="store_true", help="also the forward C.G.'s designed hover function")
    parser.add_argument("--repeat", type=int, default=1, help="timed runs after the warm-up (best reported)")
    args = parser.parse_args()
    _hover(args.repeat)
    if args.designed:
        _designed(args.repeat)
    if args.flight:
        _flight(args.repeat)


if __name__ == "__main__":
    main()
