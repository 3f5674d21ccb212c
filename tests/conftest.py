"""Fixtures shared by the unit and physics tests, and the ``slow`` marker.

The Table I blade with the forward C.G. is the reference case of most tests: it is built once
per test session (its hover trim is cached by :func:`rotorlyap.model.trim.hover_trim` too).
Tests that take seconds are marked ``slow``; ``python -m pytest -m "not slow" tests`` is the
quick loop while editing (README, "The two commands").
"""

from __future__ import annotations

import pytest

from rotorlyap.model.blade import Blade
from rotorlyap.model.parameters import BladeParameters
from rotorlyap.model.steady import TabulatedMotion, periodic_motion, tabulate_motion


@pytest.fixture(scope="session")
def forward() -> BladeParameters:
    """Table I with the forward C.G. (the collective left to the hover trim)."""
    return BladeParameters.table_i("forward")


@pytest.fixture(scope="session")
def forward_hover(forward) -> Blade:
    """The forward-C.G. blade in hover, trimmed for thrust = weight."""
    return Blade(forward, 0.0)


@pytest.fixture(scope="session")
def forward_periodic_015(forward) -> TabulatedMotion:
    """The forward-C.G. blade's periodic motion at mu = 0.15 (256 collocation points), tabulated."""
    return tabulate_motion(periodic_motion(forward, 0.15, n_points=256))


@pytest.fixture
def kernel_pair(monkeypatch):
    """A function ``pair(params, mu)`` giving the same blade twice: with the compiled kernels and
    with the numpy kernels (``ROTORLYAP_KERNEL``), the environment restored afterwards."""

    def pair(params: BladeParameters, mu: float) -> tuple[Blade, Blade]:
        monkeypatch.setenv("ROTORLYAP_KERNEL", "compiled")
        fast = Blade(params, mu)
        monkeypatch.setenv("ROTORLYAP_KERNEL", "numpy")
        slow = Blade(params, mu)
        monkeypatch.delenv("ROTORLYAP_KERNEL")
        assert fast.kernel is not None and slow.kernel is None
        return fast, slow

    return pair



# --- the small periodic system of chapters 1 and 2 (tests of both chapters' modules) ----------

@pytest.fixture(scope="session")
def osc():
    """The Mathieu-Duffing oscillator of chapters 1 and 2."""
    from rotorlyap.methods.examples import mathieu_duffing

    return mathieu_duffing(damping=0.4, modulation=0.3, softening=1.0)


@pytest.fixture(scope="session")
def osc_cert(osc):
    """Its certificate, made once on a coarse azimuth grid (24 azimuths) to keep the tests quick."""
    import rotorlyap

    return rotorlyap.technical_stability(osc.f, osc.W, 1.0, dim=osc.dim, dW=osc.dW, n_psi=24, n_sphere=256)


@pytest.fixture(scope="session")
def osc_history(osc, osc_cert):
    """Motions from three start azimuths, as chapters 1 and 2 draw them (shorter)."""
    from rotorlyap.chapters.norm_history import norm_history_data

    return norm_history_data(osc, osc_cert, [0, 6, 12], n_starts=4, n_periods=2)
