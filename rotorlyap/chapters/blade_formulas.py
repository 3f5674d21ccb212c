"""Closed forms of the blade that chapters 3 and 4 both quote.

:func:`effective_flap_frequency`, the classical hover flap frequency with pitch-flap coupling:
chapter 3 (:mod:`rotorlyap.chapters.blade_model`) states it with the blade's pitch-flap coupling,
chapter 4 (:mod:`rotorlyap.chapters.table_i`) sets it beside the flap mode of the hover modes in air.
"""

from __future__ import annotations

import math

__all__ = ["effective_flap_frequency"]


def effective_flap_frequency(flap_frequency: float, lock_number: float, pitch_flap_coupling: float) -> float:
    """Classical hover flap frequency with pitch-flap coupling, ``sqrt(nu_beta^2 + gamma/8 k3)``,
    per rev (Johnson 1980; ``k3 = tan(delta3)``, the pitch change per flap being ``-k3``).

    Parameters
    ----------
    flap_frequency : float
        ``nu_beta``, per rev.
    lock_number : float
        ``gamma``, -.
    pitch_flap_coupling : float
        ``tan(delta3)``, -.
    """
    return math.sqrt(flap_frequency ** 2 + lock_number / 8 * pitch_flap_coupling)
