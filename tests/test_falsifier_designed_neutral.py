"""The falsifier on the neutral-C.G. hover certificate of the default ``certify`` (the augmented
energy), as the book ships it (``book/certificates/hover_neutral.json``): :mod:`falsifier_designed`."""

import pytest

from falsifier_designed import falsify


@pytest.mark.slow
def test_the_designed_hover_certificate_survives_the_falsifier():
    falsify("neutral")
