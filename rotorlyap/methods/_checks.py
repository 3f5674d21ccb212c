"""Argument checks shared by the analysis modules: clear errors naming what is allowed."""

from __future__ import annotations

import numpy as np


def positive_float(name: str, value) -> float:
    """``value`` as a finite float > 0, or TypeError/ValueError naming ``name``."""
    return _finite_float(name, value, strict=True)


def nonnegative_float(name: str, value) -> float:
    """``value`` as a finite float >= 0, or TypeError/ValueError naming ``name``."""
    return _finite_float(name, value, strict=False)


def _finite_float(name: str, value, strict: bool) -> float:
    if isinstance(value, bool):
        raise TypeError(f"{name} must be a real number, got {value!r}")
    try:
        v = float(value)
    except (TypeError, ValueError) as exc:
        raise TypeError(f"{name} must be a real number, got {value!r}") from exc
    if not np.isfinite(v) or (v <= 0 if strict else v < 0):
        raise ValueError(f"{name} must be a finite number {'>' if strict else '>='} 0, got {value!r}")
    return v


def positive_int(name: str, value, minimum: int = 1) -> int:
    """``value`` as an int >= ``minimum`` (bools refused), or ValueError naming ``name``."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < minimum:
        raise ValueError(f"{name} must be an integer >= {minimum}, got {value!r}")
    return int(value)
