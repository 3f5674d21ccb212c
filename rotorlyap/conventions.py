"""Conventions shared by the whole package: state names, hinges, the norm, the test disturbances.

The blade's state is ``z = (beta, zeta, theta, beta', zeta', theta')``: flap, lag and pitch
hinge angles (rad) and their derivatives with respect to the azimuth ``psi = Omega t``
(rad/rad). A disturbance ``x = z - xi(psi)`` is measured from a steady motion ``xi`` in the
scaled norm ``||x|| = |x / a|`` with the scales ``a_i`` below.

Nothing here depends on the blade model: the general method (:mod:`rotorlyap.methods`) may use
these names, and so may the model, the analysis and the figures.
"""

from __future__ import annotations

import numpy as np

__all__ = [
    "DEFAULT_A", "DEFAULT_SCALES", "HINGES", "MAX_ADVANCE_RATIO", "PAPER_TEST_DISTURBANCES",
    "STATE_NAMES", "TWO_PI",
]

TWO_PI = 2.0 * np.pi
"""One revolution of azimuth, rad."""

STATE_NAMES = ("beta", "zeta", "theta", "beta'", "zeta'", "theta'")
"""Names of the state components, in order: hinge angles (rad), then their azimuth rates (rad/rad)."""

HINGES: tuple[str, str, str] = ("flap", "lag", "pitch")
"""Hinge names, in the order of the state vector."""

_DEG = np.pi / 180.0

MAX_ADVANCE_RATIO = 3.0
"""Largest advance ratio the analyses accept, -. The blade model is complete at any advance ratio
(full-circle angle of attack, reverse flow, the free stream in every strip); 3 lies past the
classical flap instability of a centrally hinged blade (near mu = 2.2 for a Lock number of 8),
which the tests reproduce. Whether a section model is valid there is another matter:
:mod:`rotorlyap.model.compressibility` maps where it is."""

DEFAULT_SCALES = np.array([2.0 * _DEG, 2.0 * _DEG, 1.0 * _DEG, 2.0 * _DEG, 0.5 * _DEG, 5.0 * _DEG])
"""Default norm scales ``a_i`` (rad and rad/rad): a unit of the norm is 2 deg of flap or lag,
1 deg of pitch, and for each rate the angle scale times the mode's rotating frequency in
hover (flap ~1/rev, lag ~0.25/rev, pitch ~5/rev), so that displacement and rate of one mode
weigh alike. Assumed: the paper gives neither the ``a_i`` nor ``A``."""
DEFAULT_SCALES.setflags(write=False)

DEFAULT_A = 1.0
"""Default bound ``A`` of the scaled norm: one unit of every scale (assumed)."""

PAPER_TEST_DISTURBANCES = np.vstack([np.eye(6), -np.eye(6)])
"""The practical reading's default test disturbances: the 12 signed coordinate axes (one hinge
angle or one hinge rate disturbed at a time), in scaled coordinates."""
PAPER_TEST_DISTURBANCES.setflags(write=False)
