"""The falsifier on the forward-flight certificate files the book ships (``book/certificates/``, made by
``tools/make_certificates.py``, verified by chapter 10): each file first verifies from nothing,
then survives the attack of :func:`falsifier.falsify_file` (the theorem's three facts on the
band itself with :data:`EVALUATIONS` evaluations on ``W`` and ten times as many on ``W'``, the
start set's reported reach, the worst motions from 0.97 of the start set's boundary at four start
azimuths for 20 revolutions), on whatever machine runs the tests. The hover files are attacked by
``test_falsifier_designed_{forward,neutral,backward}.py``."""

from pathlib import Path

import pytest

from falsifier import falsify_file

FOLDER = Path(__file__).resolve().parents[1] / "book" / "certificates"

#: Evaluations of each search on ``W`` (the designed hover certificates' budget).
EVALUATIONS = 20_000


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(p.name for p in FOLDER.glob("forward_mu*.json")))
def test_each_certificate_file_of_the_book_survives_the_falsifier(name):
    falsify_file(FOLDER / name, evaluations=EVALUATIONS)


def test_the_book_ships_its_forward_flight_certificate_files():
    assert {p.name for p in FOLDER.glob("*.json")} >= {"forward_mu010.json", "forward_mu020.json",
                                                       "forward_mu025.json", "hover_forward.json",
                                                       "hover_neutral.json", "hover_backward.json"}


def test_each_forward_flight_file_holds_the_harmonics_its_maker_chose():
    """The files are what ``tools/make_certificates.py`` says it makes: the harmonics of the
    azimuth in each designed function (``HARMONICS``, chosen by measurement) read back from the
    file's basis, and the thorough design's effort."""
    import importlib.util

    from rotorlyap.analysis.certificate_file import read_certificate

    spec = importlib.util.spec_from_file_location("make_certificates", FOLDER.parents[1] / "tools" / "make_certificates.py")
    maker = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(maker)
    for mu, harmonics in maker.HARMONICS.items():
        fun = read_certificate(maker.path_for(mu)).function
        assert (fun.harmonics, fun.effort) == (harmonics, maker.DESIGN["forward flight"]), mu
