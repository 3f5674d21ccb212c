"""Ball arithmetic against Taylor models: how wide the blade's enclosures are (issue 41).

Run: ``python benchmarks/bench_taylor.py [--proof] [--flight]``.

For the Table I forward C.G. blade in hover (``Blade(BladeParameters.table_i("forward"), 0)``
about its hover equilibrium) and the boxes ``|y_i| <= b`` of the scaled state ``y = x / a``
(``a`` :data:`rotorlyap.conventions.DEFAULT_SCALES`, ``b`` = 0.03, 0.1, 0.3), with and without the
air loads, prints per arithmetic (Arb balls and float balls, :class:`BladeEnclosure`; Taylor
models of order 1, 2, 3, :func:`taylor_evaluate`):

* ``J ratio``: the widest radius of the enclosure of a Jacobian entry over the largest sampled
  variation ``|J(x) - J(0)|`` (scaled entries ``J_ij a_j / a_i``), as
  :func:`rotorlyap.analysis.proof.enclosure_width` measures it;
* ``f ratio``: the same for the right-hand side itself (entries ``f_i / a_i``);
* ``time``: the enclosure's wall time (value and Jacobian, one box; best of 3).

``centred`` is the mean-value (centred) form in float balls, the form of the prover's averaged
Jacobian (:class:`rotorlyap.analysis.proof.BladeProofSystem`): ``J(0) + H(box) [-r, r]`` with the
Hessians ``H`` enclosed over the box and the slopes of the piecewise-linear pieces frozen at
their hulls over it, and ``f(0) + J(box) [-r, r]`` for the right-hand side.

With ``--proof``, also the quadratic function's certificate (``certify(..., verify=True)``, the
same blade) proved by :func:`rotorlyap.methods.proof.prove_quadratic` with the averaged Jacobian
``K`` of the tube enclosed by the package's prover (float balls, the mean-value form) and, as an
experiment outside the package, by Taylor models (the Jacobian's models averaged along the rays,
:meth:`~rotorlyap.methods.taylor.TaylorModel.ray_average`, bounded entrywise): the proved bound
``A`` against the numerical one; and, a further experiment (:func:`_euclidean_bound`), the bound
up to which the prover's condition holds when the nonlinear term is bounded over the Euclidean
ball ``|y| <= A`` from the models' coefficient matrices, instead of over the cube ``|y_i| <= A``
from entrywise hulls (the next step of issue 41).

With ``--flight``, the same Jacobian measure for the trimmed helicopter at ``mu = 0.1``
(``flight_case("forward")``, compressible sections) about its tabulated periodic motion on 256
azimuth intervals, the azimuth a model variable (the variation: the float Jacobian at 8 random
azimuths and states per interval against the one at the interval's midpoint on the steady
motion).

With both, also the forward-flight quadratic certificate proved with Taylor-model averaged
Jacobians on the prover's fine intervals (4096: minutes), against the prover's.

The variation is sampled at the 64 corners and 256 random states of the box (the float model's
``rhs`` and finite-difference ``jacobian``). Single-threaded numerics. Figures, not tests: nothing
here fails; a line ``NOT CONTAINED`` would flag a sampled value outside an enclosure.
"""

from __future__ import annotations

import os

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "NUMBA_NUM_THREADS"):
    os.environ[_var] = "1"

import time  # noqa: E402

import numpy as np  # noqa: E402

BOXES = (0.03, 0.1, 0.3)
ARITHMETICS = (("arb", 0), ("balls", 0), ("centred", 0), ("taylor", 1), ("taylor", 2), ("taylor", 3))


def _enclose(model, steady, radius, arithmetic: str, order: int):
    """(value lo, hi (6,), Jacobian lo, hi (6, 6)) over the box ``|x| <= radius``."""
    from rotorlyap.analysis.enclosure import BladeEnclosure
    from rotorlyap.analysis.taylor_enclosure import taylor_evaluate
    from rotorlyap.methods import intervals as iv

    if arithmetic == "centred":  # mean-value forms in float balls, as the prover's averaged Jacobian
        from rotorlyap.methods.balls import Balls

        enc = BladeEnclosure(model, steady, arithmetic="balls")
        tube = enc.evaluate(1, radius=radius, order=2)
        at_centre = enc.evaluate(1, slopes=tube.slopes)
        box = Balls(np.zeros(6), radius)
        jac = at_centre.jacobian[0] + (tube.hessian[0] * box[None, None, :]).sum(axis=-1)
        value = at_centre.value[0] + (tube.jacobian[0] * box[None, :]).sum(axis=-1)
        return value.lower(), value.upper(), jac.lower(), jac.upper()
    if arithmetic == "taylor":
        ev = taylor_evaluate(BladeEnclosure(model, steady, arithmetic="balls"), np.zeros(6), radius, order)
        return ev.value.bounds() + ev.jacobian.bounds()
    ev = BladeEnclosure(model, steady, arithmetic=arithmetic).evaluate(1, radius=radius)
    return (iv.lower(ev.value[0]), iv.upper(ev.value[0]), iv.lower(ev.jacobian[0]), iv.upper(ev.jacobian[0]))


def _proofs() -> None:
    """The proved bound with the prover's balls and with Taylor-model averaged Jacobians."""
    from rotorlyap.analysis.certify import certify
    from rotorlyap.analysis.proof import BladeProofSystem, proof_problem
    from rotorlyap.analysis.taylor_enclosure import taylor_evaluate
    from rotorlyap.methods import intervals as iv
    from rotorlyap.methods.balls import Balls
    from rotorlyap.methods.proof import prove_quadratic
    from rotorlyap.model.parameters import BladeParameters

    class TaylorProofSystem(BladeProofSystem):
        """The hover system with ``K`` from Taylor models of order ``order`` (one box, the tube)."""

        def __init__(self, blade, steady, order: int):
            super().__init__(blade, steady, arithmetic="balls")
            self.order = order

        def averaged_jacobian(self, N: int, radius):
            ev = taylor_evaluate(self.enclosure, np.zeros(6), np.asarray(radius, dtype=float), self.order)
            K = ev.jacobian.ray_average().to_balls()
            return Balls(np.broadcast_to(K.mid, (N, 6, 6)), np.broadcast_to(K.rad, (N, 6, 6))), {}

    cert = certify(BladeParameters.table_i("forward"), 0.0, verify=True)
    fun = cert.lyapunov
    print(f"\nquadratic function, Table I forward C.G. hover: numerical A = {cert.bound:.4g}, "
          f"lambda0 = {cert.start_region:.4g}")
    system, quadratic, N = proof_problem(fun, arithmetic="balls")
    systems = [("balls (prover)", system)] + [(f"taylor order {k}", TaylorProofSystem(fun.blade, fun.steady, k))
                                              for k in (1, 2, 3)]
    for label, sys_ in systems:
        t = time.perf_counter()
        with iv.arithmetic("balls"):
            proof = prove_quadratic(sys_, quadratic, cert.bound, scales=fun.scales, n_intervals=N, n_bisect=10)
        print(f"{label:15s}: proved A = {proof.A:.4g} ({proof.A / cert.bound:.2f} of the numerical), "
              f"lambda0 = {proof.min_lambda0:.4g}, {time.perf_counter() - t:.2f} s", flush=True)
    for order in (2, 3, 4):
        t = time.perf_counter()
        A = _euclidean_bound(system, quadratic, fun.scales, cert.bound, order)
        print(f"taylor order {order}, the ball |y| <= A (experiment): condition (h) proved up to A = {A:.4g} "
              f"({A / cert.bound:.2f} of the numerical), {time.perf_counter() - t:.2f} s", flush=True)


def _euclidean_bound(system, quadratic, scales, A_max: float, order: int, n_bisect: int = 12) -> float:
    """The largest bound for which the certificate's condition holds with ``n`` bounded over the
    Euclidean ball ``|y| <= A`` instead of the cube: an experiment for the next step of issue 41.

    The Taylor models of the averaged Jacobian over the cube ``|y_i| <= A`` (which contains the
    ball) give ``K(t) in sum_alpha C_alpha t^alpha + [-R, R]``, ``t = y / A``; with
    ``N_alpha = C_alpha^T S + S C_alpha`` (scaled), for ``|t| <= 1``, by Weyl's inequality,
    ``lambda_max(N(t)) <= lambda_max(N_0 ball with R) + sqrt(sum_i ||N_i||^2)
    + sum_{|alpha|>=2} ||N_alpha|| sup_{|t|=1} |t^alpha|``, ``sup |t^alpha| = prod (alpha_i/|alpha|)^(alpha_i/2)``;
    the spectral norms from rigorous eigenvalue bounds. Then the prover's test: ``n < 0`` and
    ``n r + 2 e < 0`` (:mod:`rotorlyap.methods.proof`). Hover only (one azimuth interval).
    """
    from rotorlyap.analysis.taylor_enclosure import taylor_evaluate
    from rotorlyap.methods import intervals as iv
    from rotorlyap.methods.balls import Balls
    from rotorlyap.methods.proof import _Base, _quadratic_form_matrix, _scaled_matrix

    a = np.asarray(scales, dtype=float)
    with iv.arithmetic("balls"):
        base = _Base(system, quadratic, a, 1)
    S, dS = base.S, base.dS
    s_min = float(np.min(base.s_lo))

    def norm_upper(M: Balls) -> float:
        lo, hi = iv.symmetric_eigenvalue_bounds(M)
        return float(np.nextafter(max(-lo[0], hi[0]), np.inf))

    def holds(A: float) -> bool:
        K = taylor_evaluate(system.enclosure, np.zeros(6), A * a, order).jacobian.ray_average()
        sp = K.space
        with iv.arithmetic("balls"):
            K0 = _scaled_matrix(Balls(K.coef[None, ..., 0], K.rem[None]), a)
            _, n0 = iv.symmetric_eigenvalue_bounds(dS + _quadratic_form_matrix(S, K0))
            terms = []
            for m in range(1, sp.size):
                Nm = _quadratic_form_matrix(S, _scaled_matrix(Balls(K.coef[None, ..., m]), a))
                alpha = sp.exponents[m]
                d = alpha.sum()
                peak = float(np.prod([(ai / d) ** (ai / 2) for ai in alpha if ai])) * (1 + 1e-12)
                terms.append((sp.degree[m], norm_upper(Nm) * peak))
        lin = np.sqrt(sum(v * v for deg, v in terms if deg == 1)) * (1 + 1e-12)
        higher = sum(v for deg, v in terms if deg > 1) * (1 + 1e-12)
        n = float(np.nextafter(np.nextafter(float(n0[0]) + lin, np.inf) + higher, np.inf))
        c = A * A * s_min * (1 - 1e-15)
        r = np.sqrt(c / float(base.s_hi[0])) * (1 - 1e-15)
        return n < 0 and n * r * (1 - 1e-15) + 2 * float(base.e[0]) * (1 + 1e-15) < 0

    lo, hi = 0.0, A_max
    if holds(hi):
        return hi
    for _ in range(n_bisect):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if holds(mid) else (lo, mid)
    return lo


def _flight() -> None:
    """The trimmed helicopter at mu = 0.1 about its tabulated motion, 256 azimuth intervals."""
    from rotorlyap.analysis.enclosure import BladeEnclosure
    from rotorlyap.analysis.taylor_enclosure import taylor_evaluate
    from rotorlyap.conventions import DEFAULT_SCALES
    from rotorlyap.methods import intervals as iv
    from rotorlyap.model.blade import Blade
    from rotorlyap.model.forward_trim import forward_flight_trim
    from rotorlyap.model.parameters import BladeParameters
    from rotorlyap.model.steady import tabulate_motion

    trim = forward_flight_trim(BladeParameters.flight_case("forward"), 0.1)
    blade = Blade(trim.params, 0.1)
    n = 256
    tab = tabulate_motion(trim.motion, n=n)
    enc = BladeEnclosure(blade, tab, arithmetic="balls")
    a = np.asarray(DEFAULT_SCALES, dtype=float)
    scale = a[None, :] / a[:, None]
    rng = np.random.default_rng(0)
    print(f"\nforward flight, flight_case('forward'), mu = 0.1, compressible, {n} azimuth intervals "
          "(the box and the interval): ")
    print(f"{'arithmetic':10s} {'order':>5s} {'box':>5s} {'J ratio':>9s} {'J radius':>9s} {'J var':>8s} {'time':>8s}")
    for bound in (0.03, 0.1):
        radius = bound * a
        k = np.repeat(np.arange(n), 8)
        psi = 2 * np.pi * (k + rng.uniform(0, 1, k.size)) / n
        z = tab.xi(psi) + radius * rng.uniform(-1, 1, (k.size, 6))
        psi_c = 2 * np.pi * (np.arange(n) + 0.5) / n
        J0 = blade.jacobian(psi_c, tab.xi(psi_c))
        variation = np.abs(blade.jacobian(psi, z) - J0[k]) * scale
        for arithmetic, order in (("balls", 0), ("taylor", 1), ("taylor", 2), ("taylor", 3)):
            t = time.perf_counter()
            if arithmetic == "balls":
                J = enc.evaluate(n, radius=radius).jacobian
                lo, hi = iv.lower(J), iv.upper(J)
            else:
                lo, hi = taylor_evaluate(enc, np.zeros(6), radius, order, n_intervals=n).jacobian.bounds()
            dt = time.perf_counter() - t
            rad = 0.5 * (hi - lo) * scale
            print(f"{arithmetic:10s} {order if order else '-':>5} {bound:5.2f} {rad.max() / variation.max():9.3f} "
                  f"{rad.max():9.3g} {variation.max():8.3g} {dt:7.2f}s", flush=True)


def _flight_proof() -> None:
    """The forward-flight quadratic certificate (``flight_case("forward")``, mu = 0.1) proved with
    the prover's balls and with Taylor-model averaged Jacobians on its coarse intervals."""
    from rotorlyap.analysis.certify import certify
    from rotorlyap.analysis.proof import BladeProofSystem, proof_problem
    from rotorlyap.analysis.taylor_enclosure import taylor_evaluate
    from rotorlyap.methods import intervals as iv
    from rotorlyap.methods.balls import Balls
    from rotorlyap.methods.proof import prove_quadratic
    from rotorlyap.model.parameters import BladeParameters

    class TaylorFlightSystem(BladeProofSystem):
        """``K`` on the fine intervals from Taylor models (the azimuth a variable, held in the
        average: on coarse intervals its variation over the interval alone makes ``n > 0``);
        residual and linear part as the prover's."""

        def __init__(self, blade, steady, order: int):
            super().__init__(blade, steady, arithmetic="balls")
            self.order = order

        def averaged_jacobian(self, N: int, radius):
            ev = taylor_evaluate(self.enclosure, np.zeros(6), np.asarray(radius, dtype=float), self.order,
                                 n_intervals=N)
            K = ev.jacobian.ray_average(over=range(6)).to_balls()
            return K, {}

    t = time.perf_counter()
    cert = certify(BladeParameters.flight_case("forward"), 0.1, verify=True)
    fun = cert.lyapunov
    system, quadratic, N = proof_problem(fun, arithmetic="balls")
    print(f"\nforward flight, quadratic function: numerical A = {cert.bound:.4g}, lambda0 = "
          f"{cert.start_region:.4g}; prover (balls, {N} intervals, {system.n_coarse} coarse): A = "
          f"{cert.proof.A:.4g} ({cert.proof.A / cert.bound:.2f}), certify {time.perf_counter() - t:.0f} s")
    motion = system.enclosure.motion
    for order in (2,):
        t = time.perf_counter()
        ts = TaylorFlightSystem(fun.blade, motion, order)
        with iv.arithmetic("balls"):
            proof = prove_quadratic(ts, quadratic, cert.bound, scales=fun.scales, n_intervals=N, n_bisect=6)
        print(f"taylor order {order}: proved A = {proof.A:.4g} ({proof.A / cert.bound:.2f} of the numerical), "
              f"lambda0 = {proof.min_lambda0:.4g}, {time.perf_counter() - t:.0f} s", flush=True)


def main() -> None:
    import argparse

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--proof", action="store_true", help="also the proved bounds (balls and Taylor models)")
    parser.add_argument("--flight", action="store_true", help="also the forward-flight case (256 intervals)")
    args = parser.parse_args()
    _widths()
    if args.proof:
        _proofs()
    if args.flight:
        _flight()
    if args.proof and args.flight:
        _flight_proof()


def _widths() -> None:
    from rotorlyap.analysis.proof import _without_air
    from rotorlyap.conventions import DEFAULT_SCALES
    from rotorlyap.model.blade import Blade
    from rotorlyap.model.parameters import BladeParameters
    from rotorlyap.model.steady import as_steady_motion

    blade = Blade(BladeParameters.table_i("forward"), 0.0)
    steady = as_steady_motion(None, blade)
    a = np.asarray(DEFAULT_SCALES, dtype=float)
    scale = a[None, :] / a[:, None]
    rng = np.random.default_rng(0)
    corners = np.array(np.meshgrid(*[[-1.0, 1.0]] * 6, indexing="ij")).reshape(6, -1).T
    unit = np.vstack([corners, rng.uniform(-1.0, 1.0, (256, 6))])
    print(f"{'air loads':9s} {'arithmetic':10s} {'order':>5s} {'box':>5s} {'J ratio':>9s} {'J radius':>9s} "
          f"{'J var':>8s} {'f ratio':>8s} {'time':>8s}")
    for air in (True, False):
        model = blade if air else _without_air(blade)
        for bound in BOXES:
            z = steady.state + unit * bound * a
            psi = np.zeros(len(z))
            J = model.jacobian(psi, z)
            J0 = model.jacobian(np.zeros(1), steady.state[None])[0]
            f = model.rhs(psi, z)
            f0 = model.rhs(np.zeros(1), steady.state[None])[0]
            j_var = np.max(np.abs(J - J0), axis=0) * scale
            f_var = np.max(np.abs(f - f0), axis=0) / a
            for arithmetic, order in ARITHMETICS:
                times = []
                for _ in range(3):
                    t = time.perf_counter()
                    flo, fhi, jlo, jhi = _enclose(model, steady, bound * a, arithmetic, order)
                    times.append(time.perf_counter() - t)
                j_rad = 0.5 * (jhi - jlo) * scale
                f_rad = 0.5 * (fhi - flo) / a
                slack = 1e-6 * (np.abs(J) + 1.0)
                ok = (np.all((J >= jlo - slack) & (J <= jhi + slack))
                      and np.all((f >= flo - 1e-9) & (f <= fhi + 1e-9)))
                print(f"{'yes' if air else 'no':9s} {arithmetic:10s} {order if order else '-':>5} {bound:5.2f} "
                      f"{j_rad.max() / j_var.max():9.3f} {j_rad.max():9.3g} {j_var.max():8.3g} "
                      f"{f_rad.max() / f_var.max():8.3f} {min(times):7.3f}s" + ("" if ok else "  NOT CONTAINED"),
                      flush=True)


if __name__ == "__main__":
    main()
