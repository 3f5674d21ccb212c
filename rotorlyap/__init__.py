"""rotorlyap: technical stability of a rotor blade by Liapunov's direct method.

A re-implementation of J. Narkiewicz & W. Lucjanek, "Investigation of helicopter rotor blade
motion stability by direct Liapunov method", 15th European Rotorcraft Forum, 1989.

The package has three layers, and data flows one way through them:

* :mod:`rotorlyap.methods`: the general method for any periodic system (the six-step
  algorithm, sphere searches, simulation, Floquet theory, the periodic Lyapunov equation);
* :mod:`rotorlyap.model`: parameters -> the equations of the blade -> its steady motions;
* :mod:`rotorlyap.analysis`: the blade in the methods (Liapunov functions, technical
  stability, Floquet analysis of the blade);

then :mod:`rotorlyap.chapters` (one module per chapter) and the command line
(:mod:`rotorlyap.cli`). :mod:`rotorlyap.conventions` holds the names and defaults they share,
:mod:`rotorlyap.errors` the errors, :mod:`rotorlyap.reporting` how a number is printed.

The names a chapter needs (``rotorlyap.__all__``; the API reference lists them) are
importable from ``rotorlyap`` itself; each is imported from its module on first use, so
``import rotorlyap.methods`` loads nothing of the model.
"""

from __future__ import annotations

import importlib

_PUBLIC = {
    # the general method
    "technical_stability": "methods.lyapunov", "TechnicalStabilityResult": "methods.lyapunov",
    "simulate": "methods.simulation", "scaled_norm": "methods.simulation",
    "floquet_multipliers": "methods.floquet", "periodic_lyapunov": "methods.periodic_lyapunov",
    "prove_quadratic": "methods.proof", "Proof": "methods.proof",
    # the model
    "BladeParameters": "model.parameters", "Blade": "model.blade", "hover_trim": "model.trim",
    "SteadyMotion": "model.steady", "periodic_motion": "model.steady",
    "derived_quantities": "model.modes",
    # the blade in the methods
    "blade_stability": "analysis.stability", "energy_function": "analysis.functions",
    "quadratic_function": "analysis.functions", "designed_function": "analysis.nonlinear_functions",
    "optimised_quadratic_function": "analysis.functions", "blade_floquet": "analysis.floquet",
    "certify": "analysis.certify", "Certificate": "analysis.certify", "prove_blade": "analysis.proof",
    "verify": "analysis.certificate_file", "Verification": "analysis.certificate_file",
    "forward_flight_trim": "model.forward_trim",
    "sweep": "analysis.sweep", "SweepResult": "analysis.sweep",
    "stable_region": "analysis.region", "StableRegion": "analysis.region",
    "fan_plot": "analysis.modes", "FanData": "analysis.modes",
    "floquet_modes": "analysis.modes", "FloquetModes": "analysis.modes",
    "simulate_disturbance": "analysis.disturbance", "DisturbedMotion": "analysis.disturbance",
    # shared conventions, errors and printing
    "DEFAULT_A": "conventions", "DEFAULT_SCALES": "conventions",
    "PAPER_TEST_DISTURBANCES": "conventions", "STATE_NAMES": "conventions",
    "ConvergenceError": "errors", "NotAsymptoticallyStableError": "errors", "CertificateFileError": "errors",
    "format_small": "reporting", "decade_above": "reporting",
}

_SUBPACKAGES = ("analysis", "cli", "conventions", "chapters", "errors", "methods", "model", "reporting")

__all__ = sorted(_PUBLIC)


def __getattr__(name: str):
    if name in _PUBLIC:
        value = getattr(importlib.import_module(f".{_PUBLIC[name]}", __name__), name)
        globals()[name] = value
        return value
    if name in _SUBPACKAGES:
        return importlib.import_module(f".{name}", __name__)
    raise AttributeError(f"module 'rotorlyap' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_PUBLIC) | set(_SUBPACKAGES))
