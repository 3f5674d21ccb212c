"""The falsifier on chapter 11's certificates of the SA 330 Puma (the book's own blade from a
parameter file, without pitch-flap coupling): each certificate ``certify`` gives there, built as
the chapter builds it, survives an independent adversary (:func:`falsifier.falsify_certificate`:
the theorem's three facts, the start set's reported reach, the worst motions from the start set
for 20 revolutions), with the designed certificates' budget (:data:`EVALUATIONS` on ``W``, ten
times as many on ``W'``): ten times the engine's own final check, the budget of chapter 7's
scan, costs about a minute of one core per hover certificate.

The hover certificates (the built-in section and the same section read from a C81 file) and the
forward-flight ones (mu = 0.1 and 0.2, the chapter's certified advance ratios) are attacked in every
test run (the forward-flight pair about 11 s on an AMD EPYC of CI's kind, 2026-12-06)."""

import dataclasses

import pytest

from falsifier import falsify_certificate
from rotorlyap import certify
from rotorlyap.model.c81 import C81Section, read_c81, table_from_section, write_c81
from rotorlyap.model.parameters import EXAMPLE_FILES, BladeParameters

#: Evaluations of each search on ``W`` (ten times as many on the band for ``W'``).
EVALUATIONS = 20_000


def puma() -> BladeParameters:
    """Chapter 11's blade: the Puma file, pitch-flap coupling 0 (its certified case)."""
    with pytest.warns(Warning):  # the file leaves three fields to the template, and says so
        params = BladeParameters.from_file(EXAMPLE_FILES["sa330-puma"])
    return dataclasses.replace(params, pitch_flap_coupling=0.0)


@pytest.mark.slow
@pytest.mark.parametrize("section", ["built-in", "c81"])
def test_the_puma_hover_certificates_survive_the_falsifier(section, tmp_path):
    blade = puma()
    if section == "c81":  # as the chapter makes it: the section's C81 table written, then read back
        write_c81(table_from_section(blade.airfoil, name="Puma symmetric section"), tmp_path / "puma.c81")
        blade = dataclasses.replace(blade, airfoil=C81Section(read_c81(tmp_path / "puma.c81"), file_name="puma.c81"))
    falsify_certificate(certify(blade, 0.0, function="quadratic"), evaluations=EVALUATIONS)


@pytest.mark.slow
@pytest.mark.parametrize("mu", [0.1, 0.2])
def test_the_puma_forward_flight_certificates_survive_the_falsifier(mu):
    falsify_certificate(certify(puma(), mu, function="quadratic"), evaluations=EVALUATIONS)
