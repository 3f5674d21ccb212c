"""How numbers are printed (rotorlyap.reporting): round-off as a bound, error estimates as a decade."""

from __future__ import annotations

import numpy as np
import pytest

from rotorlyap.reporting import ROUNDOFF_FLOOR, decade_above, format_small, format_small_array


def test_residuals_at_roundoff_level_print_as_the_same_bound_on_every_machine():
    # the committed and the recomputed residual of issue 10 differed in every digit
    assert format_small(2.6e-15) == format_small(1.1e-15) == "< 1e-10"
    assert format_small(0.0) == "< 1e-10"
    assert format_small(3e-13, floor=1e-12) == "< 1e-12"


def test_residuals_above_roundoff_keep_one_significant_digit():
    assert format_small(4.6e-5) == "5e-05"
    assert format_small(ROUNDOFF_FLOOR) == "1e-10"
    assert format_small(float("nan")) == "nan"


def test_an_array_prints_each_item_by_the_same_rule():
    assert format_small_array(np.array([6e-13, 5.2e-8, np.nan])) == "[< 1e-10, 5e-08, nan]"


def test_an_error_estimate_is_stated_as_the_next_power_of_ten():
    assert decade_above(3e-4) == pytest.approx(1e-3)
    assert decade_above(9e-5) == pytest.approx(1e-4)
    assert decade_above(1e-3) == pytest.approx(1e-2)  # strictly above
    for v in np.geomspace(1e-9, 1e3, 37):
        b = decade_above(v)
        assert v < b <= 10 * v * (1 + 1e-12)
        assert np.log10(b) == pytest.approx(round(np.log10(b)))


@pytest.mark.parametrize("call, match", [
    (lambda: format_small(-1e-3), "non-negative"),
    (lambda: format_small(1e-3, floor=0.0), "floor must be positive"),
    (lambda: decade_above(0.0), "positive finite"),
    (lambda: decade_above(float("inf")), "positive finite"),
])
def test_bad_input_says_what_is_allowed(call, match):
    with pytest.raises(ValueError, match=match):
        call()
