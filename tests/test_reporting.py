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


def test_rounded_prints_the_digits_kept_and_glue_drops_a_fake_decimal():
    """A glued number shows what the rounding kept: 0.600 (three decimals) is not 0.6, and a
    whole number rounded to units, -21096.0, is shown -21096 (no decimal was kept)."""
    from rotorlyap.chapters.export import glue_value
    from rotorlyap.reporting import Rounded

    r = Rounded(0.59996, 3)
    assert repr(r) == str(r) == "0.600" and r == 0.6 and f"{r:.2f}" == "0.60"
    assert repr(Rounded(-1, 2)) == "-1.00"
    import pickle
    assert repr(pickle.loads(pickle.dumps(r))) == "0.600"
    with pytest.raises(ValueError, match="decimals"):
        Rounded(1.0, -1)
    assert glue_value(-21096.0) == -21096 and isinstance(glue_value(-21096.0), int)
    assert glue_value(2.0) == 2.0 and isinstance(glue_value(2.0), float)  # 2.0 may be round(x, 1)
    assert isinstance(glue_value(Rounded(20.0, 1)), Rounded)
    assert glue_value(True) is True and glue_value("0.6") == "0.6"


def test_a_percentage_below_the_printed_precision_is_printed_as_the_bound_it_lies_below():
    """Chapters 2 and 7 printed "changes by at most 0.0 %" for a change that was not zero
    (issue 42): a change too small for the printed digits is stated as "< 0.05 %"."""
    from rotorlyap.reporting import percent

    assert percent(0.0123) == "1.2 %"
    assert percent(0.0004) == "< 0.05 %"
    assert percent(0.0004, 2) == "0.04 %"
    assert percent(0.00004, 2) == "< 0.005 %"
    assert percent(-0.0004) == "> -0.05 %"
    assert percent(-0.0123) == "-1.2 %"
    assert percent(0.0) == percent(1e-16) == "< 0.05 %"  # the same on every machine
    assert percent(0.0005) == "0.1 %"  # 0.05 % itself rounds to one decimal (banker's or not, not zero)
    assert percent(float("nan")) == "nan"
    with pytest.raises(ValueError, match="digits"):
        percent(0.1, -1)


def test_a_count_agrees_with_its_noun():
    """Chapter 7 printed "at 1 advance ratio(s) of the grid" (issue 42)."""
    from rotorlyap.reporting import count

    assert count(1, "advance ratio") == "1 advance ratio"
    assert count(0, "advance ratio") == "0 advance ratios"
    assert count(3, "advance ratio") == "3 advance ratios"
    assert count(2, "C.G. case", "C.G. cases") == "2 C.G. cases"
    assert count(1, "child", "children") == "1 child"
    assert count(4, "child", "children") == "4 children"
    for bad in (-1, 1.5, True):
        with pytest.raises(ValueError, match="non-negative integer"):
            count(bad, "azimuth")


def test_an_angle_prints_in_whole_degrees_with_a_true_minus_sign():
    from rotorlyap.reporting import degrees

    assert degrees(np.radians(-15.2)) == "\u221215°" and degrees(np.radians(3.0)) == "3°"
    assert degrees(np.radians(-0.4)) == "0°"  # no minus on a zero
