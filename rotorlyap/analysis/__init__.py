"""The blade in the general method: Liapunov functions, technical stability, Floquet analysis.

* :mod:`~rotorlyap.analysis.functions`: the paper's energy function and quadratic functions
  from the periodic Lyapunov equation;
* :mod:`~rotorlyap.analysis.fused`: the quadratic function's ``W'`` about a tabulated motion in
  one compiled call (and, for the band searches, with the map of a search coordinate to its
  point on the ray);
* :mod:`~rotorlyap.analysis.nonlinear_functions`: :func:`designed_function`, the augmented
  energy (and a polynomial family) designed on sampled states for the nonlinear range;
* :mod:`~rotorlyap.analysis.region`: :func:`stable_region`, the region of stable motion found by
  simulation, the yardstick of every certificate;
* :mod:`~rotorlyap.analysis.stability`: :func:`blade_stability`, the blade in the engine, in the
  strict and the practical reading;
* :mod:`~rotorlyap.analysis.floquet`: Floquet multipliers of the blade about its steady motion,
  followed over the advance ratio;
* :mod:`~rotorlyap.analysis.certify`: :func:`certify`, the trim, the steady motion, the quadratic
  function and the sound rule in one call;
* :mod:`~rotorlyap.analysis.certificate_file`: a certificate as one JSON file
  (:meth:`Certificate.save`) and :func:`~rotorlyap.analysis.certificate_file.verify`, which checks
  it from nothing but the file;
* :mod:`~rotorlyap.analysis.enclosure`: the blade's equations and Jacobian enclosed in ball
  arithmetic, over an interval of azimuth and a tube of states;
* :mod:`~rotorlyap.analysis.taylor_enclosure`: :func:`taylor_evaluate`, the blade's equations
  and Jacobian in Taylor models;
* :mod:`~rotorlyap.analysis.proof`: :func:`prove_blade`, the quadratic function's certificate
  proved with Taylor models and a branch and bound over the band (ball arithmetic alone:
  ``method="balls"``);
* :mod:`~rotorlyap.analysis.modes`: the blade's frequencies, hover modes against the rotor
  speed and Floquet modes against the advance ratio;
* :mod:`~rotorlyap.analysis.disturbance`: the motion of the full nonlinear blade after a
  disturbance, beside a certificate's bound;
* :mod:`~rotorlyap.analysis.sweep`: :func:`sweep`, certificates over a grid of blades and
  conditions, on every core or a Dask cluster, as one table.
"""

from .certify import Certificate, certify
from .floquet import blade_floquet, floquet_sweep
from .functions import energy_function, optimised_quadratic_function, quadratic_function
from .nonlinear_functions import designed_function
from .proof import prove_blade
from .region import StableRegion, stable_region
from .stability import blade_stability
from .sweep import SweepResult, sweep

__all__ = ["Certificate", "StableRegion", "SweepResult", "blade_floquet", "blade_stability", "certify",
           "designed_function", "energy_function", "floquet_sweep", "optimised_quadratic_function", "prove_blade",
           "quadratic_function", "stable_region", "sweep"]
