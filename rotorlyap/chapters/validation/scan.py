"""Chapter 7 ("Validation and beyond"), section 3: the engine's verdict on a (psi, mu) grid for
several Liapunov functions and steady motions (:data:`CANDIDATES`, :func:`scan_data`), the
certificate counterpart of the paper's Fig. 8. The verdicts' container and drawing, shared with
chapter 8, are in :mod:`rotorlyap.chapters.scans`."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...analysis.functions import optimised_quadratic_function, quadratic_function
from ...analysis.stability import blade_stability
from ...conventions import DEFAULT_A, DEFAULT_SCALES, PAPER_TEST_DISTURBANCES
from ...errors import NotAsymptoticallyStableError
from ...model.blade import Blade
from ...model.parameters import BladeParameters
from ..scans import ScanData, _category
from .common import MU_SCAN
from .steady import SteadyMotions

__all__ = ["CANDIDATES", "Candidate", "scan_data"]


# --------------------------------------------------------------------------------------
# 3. Scans: the paper's Fig. 8 with numerical certificates
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Candidate:
    """One Liapunov function, reading and steady motion of the scans."""

    key: str
    label: str
    function: str  # "energy", "quadratic", "quadratic-opt"
    reading: str  # "strict" or "practical"
    steady: str  # "hover" (the paper's) or "periodic"


#: The functions compared, in the order of the rows of :func:`~rotorlyap.chapters.scans.plot_scan`.
CANDIDATES = (
    Candidate("paper", "energy, practical, hover equilibrium (the paper's choice)", "energy", "practical", "hover"),
    Candidate("energy-practical", "energy, practical, periodic motion", "energy", "practical", "periodic"),
    Candidate("energy", "energy, strict, periodic motion", "energy", "strict", "periodic"),
    Candidate("quadratic-hover", "quadratic Q = I, strict, hover equilibrium", "quadratic", "strict", "hover"),
    Candidate("quadratic", "quadratic Q = I, strict, periodic motion", "quadratic", "strict", "periodic"),
    Candidate("quadratic-opt", "quadratic, optimised Q, strict, periodic motion", "quadratic-opt", "strict", "periodic"),
)


def _scan_cell(task: tuple):
    """One cell of :func:`scan_data` (module level, so that worker processes can run it):
    ``(function, reading, case, mu, steady, Q, A, n_psi, engine_options)`` -> the
    :class:`~rotorlyap.methods.lyapunov.TechnicalStabilityResult`, or the message of a
    :class:`~rotorlyap.errors.NotAsymptoticallyStableError`."""
    function, reading, case, mu, steady, Q, A, n_psi, engine_options = task
    if function == "energy":
        lyap = None
    elif function == "quadratic":
        lyap = quadratic_function
    else:
        lyap = lambda b, steady: quadratic_function(b, steady, Q, label="optimised")  # noqa: E731
    tests = PAPER_TEST_DISTURBANCES if reading == "practical" else None
    try:
        return blade_stability(BladeParameters.table_i(case), mu, lyapunov=lyap, steady=steady, A=A,
                               n_psi=n_psi, test_disturbances=tests, **engine_options)
    except NotAsymptoticallyStableError as exc:
        return str(exc)


def _scan_cost(task: tuple) -> int:
    """Rank of a cell's expected cost (for the process pool, which starts the costliest first):
    the quadratic functions about a periodic motion take seconds, the others a fraction."""
    function, _, _, mu, steady, *_ = task
    return int(function != "energy") + 2 * int(function != "energy" and steady is not None and mu > 0)


def scan_data(motions: SteadyMotions, *, candidates=CANDIDATES, cases=None, mu_values=MU_SCAN,
              n_psi: int = 24, A: float | None = None, workers: int | None = None,
              **engine_options) -> ScanData:
    """Run :func:`rotorlyap.analysis.stability.blade_stability` for every candidate, case and advance ratio.

    The quadratic functions use the default scales as their coordinates (so ``Q = I`` is
    ``diag(1 / a_i**2)``); the optimised weight is found once per case in hover
    (:func:`rotorlyap.analysis.functions.optimised_quadratic_function`) and kept at every advance
    ratio. Where no quadratic function exists (unstable linearisation) or no periodic motion
    was found, the cells get categories 4 and 5 instead of a result.

    The cells are independent: with ``workers`` other than 1 (default: every core) they run in
    that many fresh processes (:func:`rotorlyap.analysis.sweep.process_map`, one BLAS thread
    each, the longest cells first); ``workers=1`` runs them here, one after the other. Each
    cell's result does not depend on where it ran.
    """
    from ...analysis.sweep import process_map, worker_count

    cases = motions.cases if cases is None else tuple(cases)
    mu_values = np.asarray(mu_values, dtype=float)
    A = DEFAULT_A if A is None else float(A)
    weights = np.full((len(cases), 6), np.nan)
    Qopt = {}
    for i, case in enumerate(cases):
        try:
            qo = optimised_quadratic_function(Blade(BladeParameters.table_i(case), 0.0), A=A)
        except NotAsymptoticallyStableError as exc:
            Qopt[case] = exc
            continue
        Qopt[case] = qo.Q
        weights[i] = np.diag(qo.Q) * DEFAULT_SCALES**2
    shape = (len(candidates), len(cases), mu_values.size, n_psi)
    cat = np.zeros(shape, dtype=int)
    stable = np.zeros(shape, dtype=bool)
    lam = np.zeros(shape)
    aused = np.full(shape[:3], np.nan)
    astep3 = np.full(shape[:3], np.nan)
    msgs = [[[None] * mu_values.size for _ in cases] for _ in candidates]
    tasks, where = [], []
    for c, cand in enumerate(candidates):
        for i, case in enumerate(cases):
            for j, mu in enumerate(mu_values):
                mu = float(mu)
                steady = None
                if cand.steady == "periodic" and mu > 0:
                    steady = motions.steady(case, mu)
                    if steady is None:
                        cat[c, i, j] = 5
                        msgs[c][i][j] = "no periodic motion found"
                        continue
                Q = None
                if cand.function not in ("energy", "quadratic"):  # the optimised weight
                    Q = Qopt[case]
                    if isinstance(Q, Exception):
                        cat[c, i, j] = 4
                        msgs[c][i][j] = str(Q)
                        continue
                tasks.append((cand.function, cand.reading, case, mu, steady, Q, A, n_psi, engine_options))
                where.append((c, i, j))
    workers = worker_count(workers, len(tasks))
    outcomes = (process_map(_scan_cell, tasks, workers, cost=_scan_cost) if workers > 1
                else [_scan_cell(t) for t in tasks])
    results, psi = {}, 2 * np.pi * np.arange(n_psi) / n_psi
    for (c, i, j), r in zip(where, outcomes):
        if isinstance(r, str):
            cat[c, i, j] = 4
            msgs[c][i][j] = r
            continue
        results[(candidates[c].key, cases[i], round(float(mu_values[j]), 6))] = r
        cat[c, i, j] = _category(r)
        stable[c, i, j] = r.stable
        lam[c, i, j] = r.lambda0
        aused[c, i, j] = r.A
        astep3[c, i, j] = r.A_step3
        psi = np.asarray(r.psi)
        msgs[c][i][j] = r.message
    return ScanData(cases=cases, mu_values=mu_values, psi=psi, keys=tuple(cd.key for cd in candidates),
                    labels=tuple(cd.label for cd in candidates),
                    readings=tuple(cd.reading for cd in candidates), category=cat, stable=stable,
                    lambda0=lam, A_used=aused, A_step3=astep3, weights=weights,
                    messages=tuple(tuple(tuple(row) for row in per_case) for per_case in msgs), results=results)
