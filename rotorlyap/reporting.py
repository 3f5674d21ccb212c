"""How the report prints a number: only the digits its computation determines.

The committed outputs of the book are compared, as text, with the outputs of a fresh
execution on the reader's machine (nbval). A digit that depends on the CPU, the BLAS kernel or
the thread count (the last bits of a floating-point result) would make that comparison fail
anywhere but on the machine that made the outputs. The rule (README, "What a committed output
may print"):

1. A result is rounded to the digits the computation determines: a quantity found by a
   search, an iteration or an integration to a tolerance keeps fewer digits than the
   tolerance allows (usually two to four significant digits).
2. A residual, a tolerance or any other quantity at round-off level is never printed as its
   value: it is printed as a bound below a stated threshold (``"< 1e-10"``) or as a
   pass/fail. :func:`format_small` does this for one number, :func:`format_small_array` for
   several; an error estimate (the change of a result with a tighter tolerance) is stated as
   the power of ten it stays below, :func:`decade_above`.

``tests/test_committed_outputs.py`` scans every committed output for numbers that break the
second rule.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["ROUNDOFF_FLOOR", "Rounded", "count", "decade_above", "degrees", "format_small", "format_small_array",
           "percent"]

ROUNDOFF_FLOOR = 1e-10
"""Threshold below which a residual or relative error is round-off, not a result.

Double precision carries about 16 significant digits; residuals of linear solves, of Newton's
method at convergence and of identities that hold exactly in exact arithmetic land between
1e-16 and 1e-11 (relative) and change with the machine. Everything this report computes to a
tolerance is converged far above 1e-10, so a value below it says only "converged"."""


def format_small(value: float, floor: float = ROUNDOFF_FLOOR) -> str:
    """A small non-negative quantity (a residual, an error estimate) as printable text.

    Parameters
    ----------
    value : float
        The quantity, dimensionless or in the units the caller states.
    floor : float
        Threshold below which ``value`` is round-off: it is then printed as ``"< floor"``.

    Returns
    -------
    str
        ``"< 1e-10"`` below ``floor``; otherwise the value to one significant digit
        (``"5e-08"``); ``"nan"`` if it is not finite (nothing was computed).

    Raises
    ------
    ValueError
        If ``value`` is negative or ``floor`` is not positive.

    Examples
    --------
    >>> format_small(2.6e-15), format_small(4.6e-5)
    ('< 1e-10', '5e-05')
    """
    if not floor > 0:
        raise ValueError(f"floor must be positive, got {floor!r}")
    value = float(value)
    if not math.isfinite(value):
        return "nan"
    if value < 0:
        raise ValueError(f"format_small prints a non-negative quantity (a residual, an error), got {value!r}")
    if value < floor:
        return f"< {floor:.0e}"
    return f"{value:.0e}"


def format_small_array(values, floor: float = ROUNDOFF_FLOOR) -> str:
    """Several small non-negative quantities, each as :func:`format_small` prints it.

    Returns
    -------
    str
        The items in brackets, separated by commas: ``"[< 1e-10, 5e-08, nan]"``.
    """
    return "[" + ", ".join(format_small(v, floor) for v in np.ravel(np.asarray(values, dtype=float))) + "]"


def decade_above(value: float) -> float:
    """The smallest power of ten above a positive error estimate: the bound the report states.

    An error estimate, such as the change of a result when a tolerance is tightened, is known
    to its order of magnitude, not to its digits: the report says "less than 1e-03", not
    "3e-04".

    Raises
    ------
    ValueError
        If ``value`` is not a positive finite number.

    Examples
    --------
    >>> decade_above(3e-4), decade_above(0.02)
    (0.001, 0.1)
    """
    value = float(value)
    if not (math.isfinite(value) and value > 0):
        raise ValueError(f"decade_above needs a positive finite error estimate, got {value!r}")
    return float(10.0 ** math.floor(math.log10(value) + 1.0))


def percent(fraction: float, digits: int = 1) -> str:
    """A relative change or share, given as a fraction, as printable per cent text.

    A value that would print as zero at ``digits`` decimals is printed as the bound it lies
    below (``"< 0.05 %"`` for one decimal), so the text never claims "0.0 %" for a change that
    was merely too small to show. An exact zero prints the same bound: a change that is zero on
    one machine and 1e-16 on another is the same result (the rule of this module's docstring).

    Parameters
    ----------
    fraction : float
        The quantity as a fraction (0.012 is 1.2 %).
    digits : int
        Decimals of the per cent value printed.

    Returns
    -------
    str
        ``"1.2 %"``; ``"< 0.05 %"`` for a magnitude below half the last digit, zero included
        (``"> -0.05 %"`` if negative); ``"nan"`` if not finite.

    Raises
    ------
    ValueError
        If ``digits`` is not a non-negative integer.

    Examples
    --------
    >>> percent(0.0123), percent(0.0004), percent(0.0004, 2), percent(0.0)
    ('1.2 %', '< 0.05 %', '0.04 %', '< 0.05 %')
    """
    if not isinstance(digits, (int, np.integer)) or digits < 0:
        raise ValueError(f"digits must be a non-negative integer, got {digits!r}")
    value = 100.0 * float(fraction)
    if not math.isfinite(value):
        return "nan"
    half = 0.5 * 10.0 ** (-int(digits))
    if abs(value) < half:
        bound = f"{half:.{int(digits) + 1}f}"
        return f"> -{bound} %" if value < 0 else f"< {bound} %"
    return f"{value:.{int(digits)}f} %"


def count(n: int, noun: str, plural: str | None = None) -> str:
    """A count with its noun in the number the count needs: ``count(1, "advance ratio")`` is
    ``"1 advance ratio"``, ``count(3, "advance ratio")`` is ``"3 advance ratios"``.

    Parameters
    ----------
    n : int
        The count (a non-negative integer).
    noun : str
        The singular noun, or a noun phrase whose first word is the noun
        (``"advance ratio of the grid"`` puts the plural on ``ratio``: pass ``plural``
        for any phrase where the plural is not the singular plus "s").
    plural : str, optional
        The plural form; default ``noun + "s"``.

    Raises
    ------
    ValueError
        If ``n`` is negative or not an integer.

    Examples
    --------
    >>> count(0, "azimuth"), count(1, "azimuth"), count(2, "motion", "motions")
    ('0 azimuths', '1 azimuth', '2 motions')
    """
    if isinstance(n, (bool, np.bool_)) or not isinstance(n, (int, np.integer)) or n < 0:
        raise ValueError(f"count needs a non-negative integer, got {n!r}")
    word = noun if int(n) == 1 else (plural if plural is not None else noun + "s")
    return f"{int(n)} {word}"


def degrees(angle: float) -> str:
    """An angle given in rad as text in whole degrees, with a true minus sign (the book's typography).

    Examples
    --------
    >>> degrees(-0.2618), degrees(0.0524)
    ('−15°', '3°')
    """
    return f"{round(float(np.degrees(angle))):d}°".replace("-", "\u2212")


class Rounded(float):
    """A float that prints with a fixed number of decimals: ``Rounded(0.6, 3)`` is 0.6 and
    prints ``0.600``, so a glued fact shows the digits the computation determines, trailing zeros
    included (``round(0.59996, 3)`` would print ``0.6``). Arithmetic gives plain floats."""

    def __new__(cls, value: float, decimals: int):
        if not isinstance(decimals, (int, np.integer)) or decimals < 0:
            raise ValueError(f"decimals must be a non-negative integer, got {decimals!r}")
        self = super().__new__(cls, round(float(value), int(decimals)))
        self.decimals = int(decimals)
        return self

    def __repr__(self) -> str:
        return f"{float(self):.{self.decimals}f}"

    __str__ = __repr__

    def __reduce__(self):
        return (Rounded, (float(self), self.decimals))
