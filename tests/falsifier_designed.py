"""The falsifier on the designed functions' certificates (the default ``certify`` in hover).

Not a test module: ``test_falsifier_designed_{forward,neutral,backward}.py`` call :func:`falsify`
for their Table I case (three files, so that pytest-xdist's ``--dist loadfile`` spreads them
over the workers).

The certificate of ``rotorlyap.certify(table_i(cg), 0, condition="none")``, the augmented energy
of :mod:`rotorlyap.analysis.nonlinear_functions` checked by the sound rule on the shell that holds
the band, is attacked through the theorem's three facts on the band itself (not the shell): the
searches of :mod:`falsifier` (pseudo-random points, differential evolution, L-BFGS-B; the level
along each ray by bisection) with :data:`EVALUATIONS` evaluations each for ``W`` on the sphere
and on the start balls and ten times as many for ``W'`` on the band; then the worst simulated
starts (directions chosen by optimisation) from the start region's boundary for 20 revolutions.
The budget is not the quadratic certificates' ten times the engine's final check: that check
evaluates ``W'`` a million times on the shell, and an attack of ten million band points, each
placed by a bisection of ``W`` along its ray, would take an hour per case.
"""

from __future__ import annotations

import numpy as np

from rotorlyap import certify
from rotorlyap.model.parameters import BladeParameters

from falsifier import attack, start_set_excess, worst_start_peak

#: Evaluations of each search on ``W`` (ten times as many on the band for ``W'``).
EVALUATIONS = 20_000


def falsify(cg: str) -> None:
    """Attack the default hover certificate of one Table I case. It must be the augmented
    energy's, chosen by ``function="auto"`` over the quadratic function (the other candidate),
    with at least ten times its start region."""
    _attack(certify(BladeParameters.table_i(cg), 0.0, condition="none"), n_azimuths=1)


def falsify_flight(mu: float = 0.1) -> None:
    """The same on the trimmed helicopter (forward C.G.) at ``mu``: on demand (README, "The
    falsifier"), since its design and attack take minutes."""
    _attack(certify(BladeParameters.flight_case("forward"), float(mu)), n_azimuths=4)
    print(f"mu = {mu:g}: the default certificate survives the falsifier")


def _attack(cert, *, n_azimuths: int) -> None:
    assert cert.certified and cert.function == "energy", cert.message
    assert [c.function for c in cert.candidates] == ["quadratic", "energy"]  # function="auto"
    quadratic, energy = cert.candidates
    assert quadratic.certified and cert.start_region == energy.start_region
    assert cert.start_region >= 10.0 * quadratic.start_region
    assert "by the augmented energy" in cert.summary()
    res, fun = cert.result, cert.lyapunov
    assert res.rule == "sound" and res.stable.all() and "shell" in res.message
    hit = attack(fun.W, fun.dW, res, evaluations=EVALUATIONS, quadratic=False)
    assert hit.min_w_sphere >= res.alpha * (1 - 1e-9), f"W = {hit.min_w_sphere:.6g} < alpha on the sphere A"
    assert hit.sup_w_balls <= 1e-9 * abs(res.alpha), "a start on the boundary of lambda0 has W above the level"
    assert hit.max_dw_band < 0, f"W' = {hit.max_dw_band:.3g} >= 0 found on the band"
    # the start set's reach along each hinge: W below the level on every segment it reports
    assert cert.start_set is not None and np.all(cert.start_set.axis_reach >= cert.start_region)
    excess = start_set_excess(fun.W, cert.start_set, evaluations=EVALUATIONS)
    assert excess < 0, f"W - alpha = {excess:.3g} >= 0 inside the start set's reported reach"
    # the worst motions from the whole start set (0.97 of its boundary), not only from the ball
    peak = worst_start_peak(fun.f, res, n_periods=20.0, n_azimuths=n_azimuths, W=fun.W)
    assert np.isfinite(peak) and peak < 1.0, f"a motion from a worst-case start reached {peak:.3f} A"
