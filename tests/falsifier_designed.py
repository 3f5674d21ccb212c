"""The falsifier on the designed functions' certificates (the default ``certify`` in hover).

Not a test module: ``test_falsifier_designed_{forward,neutral,backward}.py`` call :func:`falsify`
for their Table I case (three files, so that pytest-xdist's ``--dist loadfile`` spreads them
over the workers).

The certificate of ``rotorlyap.certify(table_i(cg), 0, condition="none")``, the augmented energy
of :mod:`rotorlyap.analysis.nonlinear_functions` checked by the sound rule on the shell that holds
the band, is attacked as the book ships it: the file ``book/certificates/hover_<cg>.json`` that
``tools/make_certificates.py`` made with that call (chapter 10 verifies the same file; designed
once, not in both). The attack (:func:`falsifier.falsify_file`) goes through the theorem's three
facts on the band itself (not the shell): the searches of :mod:`falsifier` (pseudo-random points,
differential evolution, L-BFGS-B; the level along each ray by bisection) with
:data:`EVALUATIONS` evaluations each for ``W`` on the sphere and on the start balls and ten times
as many for ``W'`` on the band; then the start set's reported reach and the worst simulated starts
(directions chosen by optimisation) from 0.97 of the start set's boundary for 20 revolutions.
The budget is not the quadratic certificates' (as many as the engine's final check, ten times on
demand): that check evaluates ``W'`` a million times on the shell, and every band point of the
attack is placed by a bisection of ``W`` along its ray.
"""

from __future__ import annotations

from pathlib import Path

from rotorlyap import certify
from rotorlyap.analysis.certificate_file import read_certificate
from rotorlyap.model.parameters import BladeParameters

from falsifier import falsify_certificate, falsify_file

#: Evaluations of each search on ``W`` (ten times as many on the band for ``W'``).
EVALUATIONS = 20_000

#: The book's certificate files (``tools/make_certificates.py``).
FOLDER = Path(__file__).resolve().parents[1] / "book" / "certificates"


def falsify(cg: str) -> None:
    """Attack the default hover certificate of one Table I case as the book ships it. It must be
    the augmented energy's, with at least ten times the start region of the quadratic function
    (the other candidate of ``function="auto"``, computed here in the file's norm)."""
    path = FOLDER / f"hover_{cg}.json"
    stored = read_certificate(path)
    assert stored.family == "energy", f"{path.name}: {stored.family}"
    quadratic = certify(BladeParameters.table_i(cg), 0.0, condition="none", function="quadratic",
                        scales=stored.scales)
    assert quadratic.certified and stored.lambda0.min() >= 10.0 * quadratic.start_region
    falsify_file(path, evaluations=EVALUATIONS, n_azimuths=1)


def falsify_flight(mu: float = 0.1) -> None:
    """The default certificate of the trimmed helicopter (forward C.G.) at ``mu``, designed here
    by ``certify`` and attacked the same way: on demand (README, "The falsifier"), since its
    design and attack take minutes."""
    cert = certify(BladeParameters.flight_case("forward"), float(mu))
    assert cert.certified and cert.function == "energy", cert.message
    assert [c.function for c in cert.candidates] == ["quadratic", "energy"]  # function="auto"
    quadratic, energy = cert.candidates
    assert quadratic.certified and cert.start_region == energy.start_region
    assert cert.start_region >= 10.0 * quadratic.start_region
    assert "by the augmented energy" in cert.summary()
    assert "shell" in cert.result.message
    falsify_certificate(cert, evaluations=EVALUATIONS, n_azimuths=4)
    print(f"mu = {mu:g}: the default certificate survives the falsifier")
