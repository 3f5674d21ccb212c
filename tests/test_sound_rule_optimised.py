"""The optimised quadratic functions in hover: the paper's rule reports a bound that is not true,
the sound rule one that is.

Fact checked: for the optimised weights of ``optimised_quadratic_function`` the largest ``W'`` on
a sphere sits in a small cap near the flap axis. The paper's rule misses it and reports a bound
``A`` with ``W' > 0`` on its own sphere (neutral and backward C.G.); the sound rule finds the cap
and reports a bound more than 10 % smaller. The witness is a state found by the sound rule's band
search and checked by evaluating its norm and ``W'``. The sound certificates themselves are
attacked with every other certificate of the book (``test_falsifier_*.py``).
"""

from __future__ import annotations

import numpy as np
import pytest

from rotorlyap.analysis.functions import optimised_quadratic_function
from rotorlyap.conventions import DEFAULT_SCALES
from rotorlyap.methods.lyapunov import band_max_dw, technical_stability
from rotorlyap.model.blade import Blade
from rotorlyap.model.parameters import BladeParameters
from rotorlyap.model.steady import disturbed_rhs


@pytest.mark.slow
@pytest.mark.parametrize("cg", ["neutral", "backward"])
def test_the_paper_rule_overestimates_the_bound_and_the_sound_rule_does_not(cg):
    blade = Blade(BladeParameters.table_i(cg), 0.0)
    fun = optimised_quadratic_function(blade, A=1.0)
    f = disturbed_rhs(blade, blade.equilibrium())
    a = DEFAULT_SCALES
    S = lambda psi: a[:, None] * fun.P(psi) * a[None, :]  # noqa: E731
    paper = technical_stability(f, fun.W, 1.0, scales=a, dW=fun.dW, n_psi=24, rule="paper")
    sound = technical_stability(f, fun.W, 1.0, scales=a, dW=fun.dW, n_psi=24, w_matrix=S)
    assert paper.stable.all() and sound.stable.all()
    assert sound.A < 0.9 * paper.A
    # a witness of W' > 0 on the paper's shell: ||x|| <= A and W >= alpha (so outside every start
    # ball, where W < alpha), which its step 6 declared free of W' > 0
    ext = max((band_max_dw(f, fun.W, fun.dW, paper.alpha, paper.A, scales=a, psi=paper.psi, w_matrix=S,
                           starts=starts, n_lbfgs=256) for starts in ("levels", "band")),
              key=lambda e: e.value[0])
    p, x = ext.psi[:1], ext.x[:1]
    assert np.linalg.norm(x / a) <= paper.A * (1 + 1e-12) and fun.W(p, x)[0] >= paper.alpha
    assert fun.dW(p, x)[0] > 0, "no state with W' > 0 on the paper's shell"
