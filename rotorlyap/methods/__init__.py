"""The general method, for any periodic system ``x' = f(psi, x)``: nothing here knows the blade.

* :mod:`~rotorlyap.methods.lyapunov`: the paper's six-step algorithm of technical stability,
  :func:`~rotorlyap.methods.lyapunov.technical_stability`;
* :mod:`~rotorlyap.methods.start_set`: the certified start set, beyond the start ball;
* :mod:`~rotorlyap.methods.certificate_check`: a sound-rule certificate's claims (the level
  facts and condition (h)) checked again, by the engine's own final check;
* :mod:`~rotorlyap.methods.sampling`: points on scaled spheres, batched sup/inf searches;
* :mod:`~rotorlyap.methods.polish`: the searches' local polish of their best candidates;
* :mod:`~rotorlyap.methods.simulation`: many motions integrated at once;
* :mod:`~rotorlyap.methods.floquet`: Floquet multipliers of linear periodic systems;
* :mod:`~rotorlyap.methods.periodic_lyapunov`: the periodic Lyapunov equation;
* :mod:`~rotorlyap.methods.scenario`: Liapunov functions designed by linear programming on
  sampled states (scenario design with counterexample rounds);
* :mod:`~rotorlyap.methods.region`: the region of stable motion by batched simulation (ray
  extents and slices);
* :mod:`~rotorlyap.methods.validation`: certificates measured against simulated motions;
* :mod:`~rotorlyap.methods.balls`: float balls, rigorous midpoint-radius arithmetic on numpy
  arrays;
* :mod:`~rotorlyap.methods.intervals`: ball arithmetic (float balls or Arb) with derivatives,
  rigorous eigenvalue bounds;
* :mod:`~rotorlyap.methods.taylor`: Taylor models (polynomials in the box variables with a
  rigorous remainder), enclosures that keep the cancellations ball arithmetic loses;
* :mod:`~rotorlyap.methods.band`: ``W' < 0`` on the band shown by a branch and bound over
  Taylor models;
* :mod:`~rotorlyap.methods.proof`: proofs of technical stability with a quadratic function;
* :mod:`~rotorlyap.methods.examples`: small periodic systems for the method chapters.

This layer imports nothing from :mod:`rotorlyap.model` or :mod:`rotorlyap.analysis` (a test
checks it), so it can be used, and read, on its own.
"""

from .floquet import FloquetResult, floquet_multipliers
from .lyapunov import TechnicalStabilityResult, orbital_derivative, technical_stability
from .periodic_lyapunov import PeriodicLyapunovSolution, periodic_lyapunov
from .simulation import SimulationResult, scaled_norm, simulate

__all__ = [
    "FloquetResult", "floquet_multipliers",
    "TechnicalStabilityResult", "orbital_derivative", "technical_stability",
    "PeriodicLyapunovSolution", "periodic_lyapunov",
    "SimulationResult", "scaled_norm", "simulate",
]
