"""Airfoil tables in the C81 format: read, write, interpolate, tabulate a section.

C81 is the fixed-width table of section coefficients read by the comprehensive rotorcraft
analyses. A file holds three blocks, lift, drag and moment, each a table of one coefficient
against the angle of attack (rows, deg) and the Mach number (columns)::

    NACA 0012                      2 5 2 5 2 3        <- title: A30, then 6I2 = ML NL MD ND MM NM
           0.0    0.6                                 <- ML Mach numbers: 7X, 9F7.0
    -180.  0.     0.                                  <- NL rows: alpha, ML values: 10F7.0
    ...                                               (then the drag block: MD, ND; moment: MM, NM)

Layout, as this module reads and writes it (the facts and their sources, below):

* line 1: the name in columns 1-30, then the six counts as 2-column integers in columns
  31-42: ``ML NL MD ND MM NM``, the numbers of Mach numbers and of angles of the lift, drag
  and moment blocks [MBDynC81], [C81Interface]. Counts are 1..99 (2 columns); some writers
  zero-pad them (``04``) [C81Interface], which is read.
* each block: a row of its Mach numbers (first 7 columns blank, then 7-column fields, at
  most 9 a line, continuing on lines whose first 7 columns are blank), then one row per angle
  of attack: the angle (deg) in columns 1-7 and the coefficient at each Mach number in the
  following 7-column fields, 9 a line, continued the same way (Fortran ``7X,9F7.0`` and
  ``10F7.0/(7X,9F7.0)``) [MBDynC81], [C81Interface]. MBDyn reads each value from its own
  7 columns, so two values may touch (``-1.161-1.161``): the fields are columns, not words
  [MBDynC81code]; public tables do this ([C81NACA0012] line 16).
* angles and Mach numbers strictly increasing [MBDynC81code] (``check_vec``), [c81utils]
  (changelog 1.0.4); a rotor table covers -180..180 deg (the receding blade sees reverse
  flow; the public NACA 0012 deck does, [C81NACA0012]).

Variants. MBDyn also reads a free format: a first line ``# FREE FORMAT``, then
``name; ML NL MD ND MM NM``, then the same numbers separated by blanks [MBDynC81code]; and
tools that split lines on blanks read files whose values are separated but not on the
7-column grid [c81utils] (``load``). MBDyn's "fc511" layout has 10-column fields, 8 a line, but
another arrangement of the blocks [MBDynC81code]: it is not read here. No public source seen
for this module uses 8- or 10-column fields in the C81 arrangement; such files are read by
the whitespace rule below when their values are separated by blanks.

Reading rule of :func:`read_c81` (the detection, in order):

1. a first line starting with ``# FREE FORMAT`` (any case): MBDyn's free format; the
   header is line 2, ``name; ML NL MD ND MM NM``, and the values are read as words;
2. otherwise the title line is read at its fixed columns; if columns 31-42 do not hold six
   right-aligned 2-column counts (or other text follows column 42), the last six words of the
   line are taken as the counts and the words before them as the name;
3. the blocks are read at the fixed 7-column grid; if that fails (a missing or non-numeric
   field, text outside the fields, a non-blank first field of a Mach or continuation line,
   too few or too many lines), they are read again as words (blanks or tabs between
   values). If this fails too, the error of the reading that got further into the file is
   raised (the fixed one if both stop on the same line), with a note on the other.

In word reading each Mach row and each angle row starts on a new line and runs on over the
following lines until it has its values; a line may not hold values of two rows.

Deliberately stricter than Fortran (which never refuses): a blank field where a value is due
is an error (Fortran reads it as 0), as are blanks inside a field (Fortran drops them, so
``1 5`` is 15), ``nan``/``inf``, exponents without a letter (``1.0-3``), text after the last
field of a line or after the moment block, and a value in the first 7 columns of a Mach or
continuation line (Fortran's ``7X`` skips it; here it nearly always means that a header count
is wrong). ``D`` exponents (``1.0D-3``) are read. Every refusal is a ``ValueError`` naming the
line, the field (columns) or word, and what is allowed.

Writing (:func:`write_c81`): the standard fixed layout, names left-aligned in 30 columns,
counts as ``%2d``, every number in 7 columns with as many decimals as fit, at most 4: 4
decimals on -10 < v < 100, 3 on -100 < v <= -10 and 100 <= v < 1000, 2 below -100. So Mach
numbers and coefficients (``|v| < 10``) are rounded by at most 5e-5, angles by at most 0.005 deg
(``-180.00``, ``-97.800``, ``12.5000``, ``180.000``). A number that fills its 7 columns (a
negative one of magnitude 1 or more, one of 10 or more) touches the previous value: valid
C81, but readers that split lines on blanks (e.g. [c81utils]) cannot read such rows.

Units: in the objects angles are rad (SI, like the rest of the package); only the file is in
deg. The coefficients follow :mod:`rotorlyap.model.airfoil`: lift perpendicular and drag
parallel to the relative wind, ``cm`` about the aerodynamic centre (the reference point of
the table), positive nose up.

The shipped table ``rotorlyap/data/naca23012.c81`` was made by (re-run it after a change of
:data:`rotorlyap.model.airfoil.NACA23012`; ``tests/test_c81.py`` checks that the file is what
this call writes)::

    from rotorlyap.model.airfoil import NACA23012
    from rotorlyap.model.c81 import NACA23012_C81, NACA23012_C81_NAME, table_from_section, write_c81
    write_c81(table_from_section(NACA23012, name=NACA23012_C81_NAME), NACA23012_C81)

It has one Mach column (M = 0): the package's NACA 23012 model has no Mach dependence, and a
one-column table is Mach-independent in :class:`C81Section`. (c81utils from 1.0.5 asks for at
least two Mach numbers [c81utils]; MBDyn reads one.)

Accuracy of the shipped table, measured (``C81Section`` on the file against
``NACA23012.coefficients`` on 400 001 angles, :data:`DEFAULT_ALPHAS_DEG`, 98 angles):

* attached flow, -15..18 deg (``alpha_stall_negative``..``alpha_stall``): largest error
  7.0e-4 in ``cl`` (at 16.25 deg, where the lift curve rounds into stall; 0.5-deg steps),
  1.0e-4 in ``cd`` (1.7 % of the minimum drag 0.006; half of it is the 4-decimal rounding),
  5e-8 in ``cm``; on the linear part of the lift curve (-8.5..12.5 deg between grid points)
  ``cl`` is exact to the printed 4 decimals;
* full circle: 1.05e-2 in ``cl`` (post stall, near -129 deg), 1.12e-2 in ``cd`` (near -94
  deg, next to the model's drag corner at -90 deg), 5.1e-3 in ``cm`` (reverse flow, near
  -164 deg).

Sources (public; facts taken, no code copied)
---------------------------------------------
- [MBDynC81] MBDyn, ``mbdyn/aero/c81data.txt`` ("C81 DATA FORMAT": the Fortran edit
  descriptors ``A30,6I2``, ``7x,9F7.0``, ``10F7.0/(7x,9F7.0)``, the meaning of the six counts,
  angles in deg), GitHub mirror alex-marinov/mbdyn.
- [MBDynC81code] MBDyn, ``mbdyn/aero/c81data.cc`` (same mirror): fields read by 7-column
  offsets, strictly increasing Mach numbers and angles, the ``# FREE FORMAT`` variant, the
  fc511 layout.
- [C81Interface] C. Joseph, GitHub cibinjoseph/C81-Interface, ``docs/src/libC81.f90``: read
  formats ``(A30,6I2)``, ``(7X,9F7.0)``, ``(10F7.0)``; written counts zero-padded (``I0.2``).
- [c81utils] C. Joseph, GitHub cibinjoseph/c81utils, ``c81utils.py`` (reads by splitting
  lines on blanks) and https://pypi.org/project/c81utils/ (changelog: strictly increasing
  Mach numbers and angles, 1.0.4; at least two of each, 1.0.5).
- [C81NACA0012] ``naca0012.c81`` of GitHub federico-savorgnan/paraglidyn (the report's
  ``references.bib``): a -180..180 deg deck, values written Fortran-style (``.20``, ``-.8``)
  and touching where they fill their field. It is not on the 7-column grid throughout: its
  Mach rows have ``0.`` in columns 1-7 and its 11-value rows run past column 70 on one line
  with the last two values off the grid; :func:`read_c81` refuses it, naming line 2.
"""

from __future__ import annotations

import inspect
import math
import os
import re
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .airfoil import grid_position, wrap_angle
from .compressibility import THICKNESS_RATIO

__all__ = [
    "DEFAULT_ALPHAS_DEG",
    "GRID_SIZES",
    "NACA23012_C81",
    "NACA23012_C81_NAME",
    "C81Block",
    "C81Section",
    "C81Table",
    "read_c81",
    "table_from_section",
    "write_c81",
]

FloatArray = NDArray[np.float64]

NACA23012_C81: Path = Path(__file__).resolve().parents[1] / "data" / "naca23012.c81"
"""The shipped C81 table of :data:`rotorlyap.model.airfoil.NACA23012` (module docstring)."""

NACA23012_C81_NAME: str = "NACA 23012 (rotorlyap model)"
"""Title of the shipped table: the package's model, not wind-tunnel data."""

_FIELD = 7          # columns of a field
_PER_LINE = 9       # values after the first field of a line
_MAX_COUNT = 99     # 2-column counts of the title line
_NAME_WIDTH = 30
_MAX_DECIMALS = 4
_ANGLE_TOL = 1e-9   # rad: how far inside +-pi a table's end angles may stop
_BLOCKS = ("cl", "cd", "cm")
_NUMBER = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eEdD][+-]?\d+)?")


def _segments(*spec: tuple[float, float, float]) -> tuple[float, ...]:
    """Angles (deg) of uniform segments ``(start, stop, step)``, joined, 2 decimals."""
    pts: list[float] = []
    for a, b, h in spec:
        n = round((b - a) / h)
        pts.extend(np.round(np.linspace(a, b, n + 1), 2).tolist())
    return tuple(sorted(set(pts)))


DEFAULT_ALPHAS_DEG: tuple[float, ...] = _segments(
    (-180.0, -168.0, 1.5),   # reverse flow: rounding and stall of the reverse lift curve
    (-168.0, -90.0, 8.67),
    (-90.0, -30.0, 8.57),    # +-90 deg on the grid: the drag corner of the model
    (-30.0, -18.0, 4.0),
    (-18.0, -15.0, 1.0),     # negative stall blend
    (-15.0, -10.0, 0.5),     # rounding of the lift curve into cl_min
    (-10.0, 12.5, 1.5),      # linear lift: exact; the drag polar within 1e-4
    (12.5, 18.0, 0.5),       # rounding into cl_max
    (18.0, 21.0, 1.0),       # stall blend
    (21.0, 30.0, 4.5),
    (30.0, 90.0, 8.57),
    (90.0, 166.0, 8.44),
    (166.0, 180.0, 1.4),     # reverse flow
)
"""Default angle grid of :func:`table_from_section`, deg: 98 angles (a C81 block holds at most
99), -180..180, two decimals; 0.5-deg steps where the NACA 23012 lift curve bends into stall
(-15..-10 and 12.5..18 deg), 1 deg over the stall blends, 1.5 deg on the linear part of the
lift curve (for the drag polar), 1.4-1.5 deg in reverse flow, 8.4-8.7 deg post stall. The
points go where the attached-flow coefficients need them: the rotor works there. Accuracy
with :data:`~rotorlyap.model.airfoil.NACA23012`: module docstring. It suits sections
stalling near +-15..20 deg; pass other angles for other sections."""


# --------------------------------------------------------------------------------------
# The table
# --------------------------------------------------------------------------------------

def _readonly(a: FloatArray) -> FloatArray:
    a = np.array(a, dtype=np.float64)  # a copy
    a.flags.writeable = False
    return a


@dataclass(frozen=True, eq=False)
class C81Block:
    """One coefficient of a C81 table against angle of attack and Mach number.

    Parameters
    ----------
    mach : array_like, shape (n_mach,)
        Mach numbers, -, >= 0, strictly increasing, at least one.
    alpha : array_like, shape (n_alpha,)
        Angles of attack, rad, strictly increasing, from -pi or below to pi or above
        (within 1e-9 rad): the whole circle.
    values : array_like, shape (n_alpha, n_mach)
        The coefficient, -, finite; ``values[i, j]`` at ``alpha[i]``, ``mach[j]``.

    Equality and hash compare the numbers (two blocks with equal arrays are equal).
    """

    mach: FloatArray
    alpha: FloatArray
    values: FloatArray

    def __post_init__(self) -> None:
        def arr(name: str, v: Any) -> FloatArray:
            try:
                a = np.array(v, dtype=np.float64)
            except (TypeError, ValueError) as exc:
                raise TypeError(f"{name} must be an array of real numbers, got {v!r}") from exc
            if not np.all(np.isfinite(a)):
                raise ValueError(f"{name} must be finite, got non-finite values at indices "
                                 f"{np.argwhere(~np.isfinite(a)).tolist()[:5]}")
            return a

        mach, alpha, values = arr("mach", self.mach), arr("alpha", self.alpha), arr("values", self.values)
        if mach.ndim != 1 or mach.size < 1:
            raise ValueError(f"mach must be 1-D with at least one Mach number, got shape {mach.shape}")
        if np.any(mach < 0):
            raise ValueError(f"mach must be >= 0, got {mach.tolist()}")
        if np.any(np.diff(mach) <= 0):
            k = int(np.argmax(np.diff(mach) <= 0))
            raise ValueError(f"mach must be strictly increasing, got {mach[k]!r} then {mach[k + 1]!r} "
                             f"(indices {k}, {k + 1})")
        if alpha.ndim != 1 or alpha.size < 2:
            raise ValueError(f"alpha must be 1-D with at least two angles, got shape {alpha.shape}")
        if np.any(np.diff(alpha) <= 0):
            k = int(np.argmax(np.diff(alpha) <= 0))
            raise ValueError(f"alpha must be strictly increasing, got {alpha[k]!r} then {alpha[k + 1]!r} rad "
                             f"(indices {k}, {k + 1})")
        if alpha[0] > -math.pi + _ANGLE_TOL or alpha[-1] < math.pi - _ANGLE_TOL:
            raise ValueError(f"alpha must cover the whole circle, from -pi or below to pi or above "
                             f"(-180..180 deg), got {alpha[0]!r}..{alpha[-1]!r} rad "
                             f"({math.degrees(alpha[0]):.6g}..{math.degrees(alpha[-1]):.6g} deg)")
        if values.shape != (alpha.size, mach.size):
            raise ValueError(f"values must have shape (n_alpha, n_mach) = ({alpha.size}, {mach.size}), "
                             f"got {values.shape}")
        object.__setattr__(self, "mach", _readonly(mach))
        object.__setattr__(self, "alpha", _readonly(alpha))
        object.__setattr__(self, "values", _readonly(values))

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, C81Block):
            return NotImplemented
        return (np.array_equal(self.mach, other.mach) and np.array_equal(self.alpha, other.alpha)
                and np.array_equal(self.values, other.values))

    def __hash__(self) -> int:
        return hash((self.values.shape, self.mach.tobytes(), self.alpha.tobytes(), self.values.tobytes()))


@dataclass(frozen=True)
class C81Table:
    """A C81 airfoil table: a name and the lift, drag and moment blocks.

    Parameters
    ----------
    name : str
        Title, printable ASCII, at most 30 characters (the C81 title field).
    cl, cd, cm : C81Block
        Lift, drag and pitching-moment (about the aerodynamic centre, positive nose up)
        coefficients; each block has its own Mach numbers and angles (rad).
    """

    name: str
    cl: C81Block
    cd: C81Block
    cm: C81Block

    def __post_init__(self) -> None:
        if not isinstance(self.name, str):
            raise TypeError(f"name must be a str, got {self.name!r}")
        if len(self.name) > _NAME_WIDTH or not all(" " <= ch <= "~" for ch in self.name):
            raise ValueError(f"name must be printable ASCII of at most {_NAME_WIDTH} characters "
                             f"(the C81 title field), got {self.name!r} ({len(self.name)} characters)")
        for key in _BLOCKS:
            if not isinstance(getattr(self, key), C81Block):
                raise TypeError(f"{key} must be a C81Block, got {type(getattr(self, key)).__name__}")


# --------------------------------------------------------------------------------------
# Reading
# --------------------------------------------------------------------------------------

class _ParseError(ValueError):
    """A structural failure of one reading (fixed columns or words); internal. Its message
    starts with ``line N`` (or says that the file ends after line N)."""

    @property
    def line(self) -> int:
        """How far the reading got: the line of the failure (one past the end if the file ended)."""
        m = re.match(r"line (\d+)", str(self))
        if m:
            return int(m.group(1))
        m = re.search(r"ends after line (\d+)", str(self))
        return int(m.group(1)) + 1 if m else 0


@dataclass
class _Raw:
    """Numbers of one block as read, with where each came from (for the messages)."""

    mach: list[float]
    mach_where: list[str]
    alpha: list[float]
    alpha_where: list[str]
    values: list[list[float]]


def _number(text: str, where: str, what: str) -> float:
    s = text.strip()
    if not s:
        raise _ParseError(f"{where}: missing value ({what}); a blank field is not read as 0")
    if not _NUMBER.fullmatch(s):
        raise _ParseError(f"{where}: {s!r} is not a number ({what}); allowed: a decimal number such "
                          f"as -12.5, .25, 180. or 1.5E-3 (no blanks inside, no nan/inf)")
    v = float(s.replace("D", "E").replace("d", "e"))
    if not math.isfinite(v):
        raise _ParseError(f"{where}: {s!r} overflows a float ({what})")
    return v


class _Lines:
    """The lines after the header, with their 1-based line numbers in the file."""

    def __init__(self, lines: Sequence[str], first_number: int, skip_blank: bool) -> None:
        self.items = [(first_number + k, ln) for k, ln in enumerate(lines)]
        self.pos = 0
        self.skip_blank = skip_blank

    def next(self, what: str) -> tuple[int, str]:
        while self.pos < len(self.items):
            number, line = self.items[self.pos]
            self.pos += 1
            if self.skip_blank and not line.strip():
                continue
            return number, line
        last = self.items[-1][0] if self.items else 0
        raise _ParseError(f"the file ends after line {last}, before {what}: the counts of the title "
                          f"line (line 1) ask for more lines than the file has")

    def rest(self) -> tuple[int, str] | None:
        """The first non-blank line left, if any."""
        for number, line in self.items[self.pos:]:
            if line.strip():
                return number, line
        return None


def _fixed_record(lines: _Lines, n: int, row: bool, what: str, hint: str = ""
                  ) -> tuple[list[float], list[str]]:
    """One Mach row (``row=False``: n values) or angle row (alpha and n values) at fixed columns;
    ``hint`` is added to the message of a non-blank first field of a Mach row."""
    vals: list[float] = []
    wheres: list[str] = []
    need = n + 1 if row else n
    first = True
    while len(vals) < need:
        number, line = lines.next(what)
        if not line.strip():
            raise _ParseError(f"line {number}: blank line where {what} is due (a C81 table has no "
                              f"blank lines; check the counts of the title line, line 1)")
        if "\t" in line:
            raise _ParseError(f"line {number}, column {line.index(chr(9)) + 1}: a tab in a fixed-column "
                              f"C81 file ({what}); C81 fields are columns, use blanks")
        lead = row and first  # the first line of an angle row has a value in columns 1-7
        if not lead and line[:_FIELD].strip():
            why = (hint if first else "; is it the next row? then the title line (line 1) announces "
                   "more Mach numbers than the block has")
            raise _ParseError(f"line {number}, field 1 (columns 1-{_FIELD}): found "
                              f"{line[:_FIELD].strip()!r} where columns 1-{_FIELD} must be blank (the "
                              f"start of {'a continuation line of ' if not first else ''}{what}; "
                              f"Fortran format 7X, a value there is not read){why}")
        start = 0 if lead else 1
        k = min(need - len(vals), _PER_LINE + (1 if lead else 0))
        for j in range(start, start + k):
            a, b = _FIELD * j, _FIELD * (j + 1)
            where = f"line {number}, field {j + 1} (columns {a + 1}-{b})"
            if lead and j == 0:
                item = "the angle of attack"
            else:
                item = f"value {len(vals) + (0 if row else 1)} of {what}"
            text = line[a:b]
            if lead and j == 0 and not text.strip():
                raise _ParseError(f"{where}: missing value (the angle of attack of {what}); a blank first "
                                  f"field starts a Mach-number row: does the title line (line 1) announce "
                                  f"more angles than the block has?")
            vals.append(_number(text, where, item))
            wheres.append(where)
        end = _FIELD * (start + k)
        if line[end:].strip():
            raise _ParseError(f"line {number}: unexpected text after column {end} ({line[end:].strip()!r}) "
                              f"in {what}: a line holds at most {_PER_LINE} values after its first "
                              f"{_FIELD} columns, more go on continuation lines; check the counts of "
                              f"the title line (line 1)")
        first = False
    return vals, wheres


def _word_record(lines: _Lines, n: int, row: bool, what: str, hint: str = ""
                 ) -> tuple[list[float], list[str]]:
    """The same record read as words: starts on a new line, runs on until it has its values
    (``hint`` is for the fixed reading's column check, unused here)."""
    vals: list[float] = []
    wheres: list[str] = []
    need = n + 1 if row else n
    while len(vals) < need:
        number, line = lines.next(what)
        words = line.split()
        if len(vals) + len(words) > need:
            raise _ParseError(f"line {number}: {len(words)} values where {what} needs "
                              f"{need - len(vals)} more (it has {need} in all"
                              f"{': the angle and ' + str(n) + ' coefficients' if row else ''}); "
                              f"a line may not hold values of two rows; check the counts of the title "
                              f"line and for a missing value")
        for j, w in enumerate(words):
            where = f"line {number}, word {j + 1}"
            vals.append(_number(w, where, what))
            wheres.append(where)
    return vals, wheres


def _read_blocks(lines: _Lines, counts: Sequence[int], fixed: bool) -> list[_Raw]:
    record = _fixed_record if fixed else _word_record
    blocks = []
    for b, key in enumerate(_BLOCKS):
        nm, na = counts[2 * b], counts[2 * b + 1]
        label = key.upper()
        hint = "" if b == 0 else ("; is it an angle row? then the title line (line 1) announces fewer "
                                  f"angles for {_BLOCKS[b - 1].upper()} than that block has")
        mach, mach_where = record(lines, nm, False, f"the Mach-number row of the {label} block", hint)
        alpha: list[float] = []
        alpha_where: list[str] = []
        values: list[list[float]] = []
        for i in range(na):
            vals, wheres = record(lines, nm, True, f"angle row {i + 1} of {na} of the {label} block")
            alpha.append(vals[0])
            alpha_where.append(wheres[0])
            values.append(vals[1:])
        blocks.append(_Raw(mach, mach_where, alpha, alpha_where, values))
    extra = lines.rest()
    if extra is not None:
        number, line = extra
        raise _ParseError(f"line {number}: unexpected text after the moment block ({line.strip()[:40]!r}); "
                          f"the title line (line 1) announces {counts[5]} angles for CM, and "
                          f"{counts[1]}, {counts[3]} for CL, CD: check these counts")
    return blocks


def _counts(fields: Sequence[str], where: Sequence[str]) -> list[int]:
    out = []
    for text, w, label in zip(fields, where, ("ML", "NL", "MD", "ND", "MM", "NM"), strict=True):
        s = text.strip()
        if not s.isdigit():
            raise _ParseError(f"{w}: count {label} is {text!r}, not an integer; the six counts "
                              f"ML NL MD ND MM NM follow the name, 2 columns each (columns 31-42)")
        if text != text.rstrip() and text.strip():
            raise _ParseError(f"{w}: count {label} {text!r} is left-aligned (Fortran reads it as "
                              f"{int(s)} or {int(s) * 10} depending on its blank mode); right-align it")
        v = int(s)
        low = 2 if label.startswith("N") else 1
        if not low <= v <= _MAX_COUNT:
            what = "angles (at least 2)" if low == 2 else "Mach numbers (at least 1)"
            raise _ParseError(f"{w}: count {label} = {v}: the number of {what}, at most {_MAX_COUNT}")
        out.append(v)
    return out


def _header(line: str) -> tuple[str, list[int]]:
    """Name and counts of a title line: fixed columns first, then the last six words."""
    try:
        if len(line.rstrip()) > 42:
            raise _ParseError(f"line 1: unexpected text after column 42 ({line[42:].strip()!r})")
        fields = [line[30 + 2 * k: 32 + 2 * k].ljust(2) for k in range(6)]
        wheres = [f"line 1, columns {31 + 2 * k}-{32 + 2 * k}" for k in range(6)]
        return line[:_NAME_WIDTH].strip(), _counts(fields, wheres)
    except _ParseError as fixed_error:
        words = line.split()
        if len(words) >= 6 and all(w.isdigit() for w in words[-6:]):
            cut = len(line)  # the name is the text before the sixth-last word
            for w in reversed(words[-6:]):
                cut = line.rfind(w, 0, cut)
            try:
                counts = _counts([w.rjust(2) if len(w) <= 2 else w for w in words[-6:]],
                                 [f"line 1, word {len(words) - 5 + k}" for k in range(6)])
            except _ParseError as word_error:
                raise _ParseError(f"{fixed_error} [read as words instead, it fails too: {word_error}]"
                                  ) from None
            return line[:cut].strip(), counts
        raise _ParseError(f"{fixed_error}; nor are the last six words of line 1 integers: the title "
                          f"line is the name (columns 1-30) and the counts ML NL MD ND MM NM") from None


def _free_header(line: str, number: int) -> tuple[str, list[int]]:
    if ";" not in line:
        raise _ParseError(f"line {number}: the free-format header is 'name; ML NL MD ND MM NM', "
                          f"no ';' found in {line.strip()!r}")
    name, rest = line.split(";", 1)
    words = rest.split()
    if len(words) != 6:
        raise _ParseError(f"line {number}: {len(words)} counts after ';', expected 6 (ML NL MD ND MM NM)")
    return name.strip(), _counts([w.rjust(2) for w in words],
                                 [f"line {number}, word {k + 2}" for k in range(6)])


def _check(raw: _Raw, label: str) -> None:
    """Order and coverage in deg, with the line of the offending value."""
    for k in range(1, len(raw.mach)):
        if raw.mach[k] <= raw.mach[k - 1]:
            raise ValueError(f"{raw.mach_where[k]}: Mach number {raw.mach[k]:g} of the {label} block is not "
                             f"greater than the previous one, {raw.mach[k - 1]:g} ({raw.mach_where[k - 1]}); "
                             f"Mach numbers must be strictly increasing")
    for k, m in enumerate(raw.mach):
        if m < 0:
            raise ValueError(f"{raw.mach_where[k]}: Mach number {m:g} of the {label} block is negative")
    for k in range(1, len(raw.alpha)):
        if raw.alpha[k] <= raw.alpha[k - 1]:
            raise ValueError(f"{raw.alpha_where[k]}: angle of attack {raw.alpha[k]:g} deg of the {label} "
                             f"block is not greater than the previous one, {raw.alpha[k - 1]:g} deg "
                             f"({raw.alpha_where[k - 1]}); angles must be strictly increasing")
    if raw.alpha[0] > -180.0 or raw.alpha[-1] < 180.0:
        bad = 0 if raw.alpha[0] > -180.0 else -1
        first, last = (w.split(",")[0] for w in (raw.alpha_where[0], raw.alpha_where[-1]))
        raise ValueError(f"{raw.alpha_where[bad]}: the angles of the {label} block run from "
                         f"{raw.alpha[0]:g} to {raw.alpha[-1]:g} deg (rows from {first} to {last}); a "
                         f"rotor table must cover -180..180 deg (first angle <= -180, last >= 180): "
                         f"the blade meets every angle of attack")


def _table(name: str, raws: Sequence[_Raw], where: str) -> C81Table:
    blocks = {}
    for key, raw in zip(_BLOCKS, raws, strict=True):
        _check(raw, key.upper())
        values = np.array(raw.values, dtype=np.float64).reshape(len(raw.alpha), len(raw.mach))
        blocks[key] = C81Block(mach=np.array(raw.mach), alpha=np.deg2rad(np.array(raw.alpha)), values=values)
    try:
        return C81Table(name=name, **blocks)
    except ValueError as exc:
        raise ValueError(f"{where}line 1: {exc}") from None


def read_c81(source: str | os.PathLike[str]) -> C81Table:
    """Read a C81 airfoil table.

    Parameters
    ----------
    source : str or path-like
        A path, or the text of a table (a ``str`` containing a line break is taken as the text).

    Returns
    -------
    C81Table
        The table, angles in rad.

    Raises
    ------
    ValueError
        With the line, the field (columns) or word and what is allowed: a missing or
        non-numeric value, text outside the fields, counts of the title line that do not match
        the rows, Mach numbers or angles not strictly increasing, angles not covering
        -180..180 deg, a name longer than 30 characters. Detection of the layout (fixed
        columns, words, MBDyn's ``# FREE FORMAT``): module docstring.
    OSError
        If the file cannot be read.
    """
    if isinstance(source, str) and ("\n" in source or "\r" in source):
        text, prefix = source, ""
    else:
        path = Path(source)
        text, prefix = path.read_text(encoding="utf-8"), f"{path.name}, "
    lines = text.splitlines()
    if not lines or not lines[0].strip():
        raise ValueError(f"{prefix}line 1: empty title line; a C81 table starts with the name "
                         f"(columns 1-30) and the six counts ML NL MD ND MM NM")
    try:
        if lines[0].lstrip().upper().startswith("# FREE FORMAT"):
            if len(lines) < 2:
                raise _ParseError("line 2: missing the free-format header 'name; ML NL MD ND MM NM'")
            name, counts = _free_header(lines[1], 2)
            raws = _read_blocks(_Lines(lines[2:], 3, skip_blank=True), counts, fixed=False)
        else:
            name, counts = _header(lines[0])
            try:
                raws = _read_blocks(_Lines(lines[1:], 2, skip_blank=False), counts, fixed=True)
            except _ParseError as fixed_error:
                try:
                    raws = _read_blocks(_Lines(lines[1:], 2, skip_blank=True), counts, fixed=False)
                except _ParseError as word_error:
                    # report the reading that got further into the file
                    if word_error.line > fixed_error.line:
                        raise _ParseError(f"{word_error} [read as words separated by blanks; read at "
                                          f"the fixed 7-column grid it fails earlier: {fixed_error}]"
                                          ) from None
                    raise _ParseError(f"{fixed_error} [read as words separated by blanks instead, it "
                                      f"fails too, at line {word_error.line}]") from None
    except _ParseError as exc:
        raise ValueError(f"{prefix}{exc}") from None
    try:
        return _table(name, raws, prefix)
    except ValueError as exc:
        msg = str(exc)
        raise ValueError(msg if msg.startswith(prefix) else f"{prefix}{msg}") from None


# --------------------------------------------------------------------------------------
# Writing
# --------------------------------------------------------------------------------------

def _fmt(v: float, what: str) -> str:
    """``v`` in 7 columns with the most decimals (at most 4) that fit."""
    for d in range(_MAX_DECIMALS, -1, -1):
        s = f"{v:.{d}f}"
        if d == 0:
            s += "."
        if len(s) <= _FIELD:
            if float(s) == 0.0:
                s = s.lstrip("-")
            return s.rjust(_FIELD)
    raise ValueError(f"{what} = {v!r} does not fit in {_FIELD} columns (with its decimal point)")


def _rows(first: str, values: Sequence[str]) -> list[str]:
    """A record: ``first`` (7 columns) and the values, 9 a line, continued after 7 blanks."""
    out = []
    for k in range(0, max(len(values), 1), _PER_LINE):
        head = first if k == 0 else " " * _FIELD
        out.append((head + "".join(values[k:k + _PER_LINE])).rstrip())
    return out


def _printed_increasing(texts: Sequence[str], what: str) -> None:
    vals = [float(t) for t in texts]
    for k in range(1, len(vals)):
        if vals[k] <= vals[k - 1]:
            raise ValueError(f"{what}: {texts[k - 1].strip()} and {texts[k].strip()} print alike or out of "
                             f"order in {_FIELD} columns; space them by more than the printed precision")


def write_c81(table: C81Table, path: str | os.PathLike[str] | None = None) -> str:
    """Write a table in the standard fixed-column C81 layout.

    Numbers take 7 columns each, with as many decimals as fit, at most 4 (module docstring:
    4 decimals for coefficients and Mach numbers of magnitude below 10, angles to 0.005 deg
    or better);
    :func:`read_c81` of the text gives back every number to half a unit of its last printed
    decimal. Angles are written in deg.

    Parameters
    ----------
    table : C81Table
        The table; each block at most 99 Mach numbers and 99 angles (2-column counts).
    path : str or path-like, optional
        If given, the text is also written to this file (ASCII, ``\\n`` line ends).

    Returns
    -------
    str
        The text of the table, ending with a line break.

    Raises
    ------
    ValueError
        A block with more than 99 angles or Mach numbers, a value that does not fit in 7
        columns, or angles (Mach numbers) closer than the printed precision.
    """
    if not isinstance(table, C81Table):
        raise TypeError(f"table must be a C81Table, got {type(table).__name__}")
    counts = []
    for key in _BLOCKS:
        blk: C81Block = getattr(table, key)
        for n, what in ((blk.mach.size, "Mach numbers"), (blk.alpha.size, "angles")):
            if n > _MAX_COUNT:
                raise ValueError(f"the {key.upper()} block has {n} {what}; a C81 title line counts at most "
                                 f"{_MAX_COUNT} (2 columns)")
        counts += [blk.mach.size, blk.alpha.size]
    lines = [f"{table.name:<{_NAME_WIDTH}}" + "".join(f"{n:2d}" for n in counts)]
    for key in _BLOCKS:
        blk = getattr(table, key)
        label = key.upper()
        mach = [_fmt(m, f"{label} Mach number") for m in blk.mach]
        _printed_increasing(mach, f"{label} Mach numbers")
        alpha = [_fmt(a, f"{label} angle (deg)") for a in np.rad2deg(blk.alpha)]
        _printed_increasing(alpha, f"{label} angles (deg)")
        if float(alpha[0]) > -180.0 or float(alpha[-1]) < 180.0:
            raise ValueError(f"{label} angles print as {alpha[0].strip()}..{alpha[-1].strip()} deg, "
                             f"inside -180..180 deg: the table would not be read back")
        lines += _rows(" " * _FIELD, mach)
        for i in range(blk.alpha.size):
            lines += _rows(alpha[i], [_fmt(v, f"{label} at {alpha[i].strip()} deg") for v in blk.values[i]])
    text = "\n".join(lines) + "\n"
    if path is not None:
        Path(path).write_text(text, encoding="ascii", newline="\n")
    return text


# --------------------------------------------------------------------------------------
# The section and the tabulation of a section
# --------------------------------------------------------------------------------------

def _interpolate(blk: C81Block, alpha: FloatArray, mach: FloatArray) -> FloatArray:
    """Bilinear in (alpha, Mach); Mach clipped to the block's range."""
    a, v = blk.alpha, blk.values
    i = np.clip(np.searchsorted(a, alpha, side="right") - 1, 0, a.size - 2)
    t = (alpha - a[i]) / (a[i + 1] - a[i])
    if blk.mach.size == 1:
        return v[i, 0] + t * (v[i + 1, 0] - v[i, 0])
    ms = blk.mach
    m = np.clip(mach, ms[0], ms[-1])
    j = np.clip(np.searchsorted(ms, m, side="right") - 1, 0, ms.size - 2)
    s = (m - ms[j]) / (ms[j + 1] - ms[j])
    v0 = v[i, j] + t * (v[i + 1, j] - v[i, j])
    v1 = v[i, j + 1] + t * (v[i + 1, j + 1] - v[i, j + 1])
    return v0 + s * (v1 - v0)


#: Sizes of the uniform angle grid :class:`C81Section` tries, smallest first: steps of 0.1,
#: 0.05, 0.01, 0.005 and 0.001 deg. The first that puts every angle of the table (within
#: -180..180 deg) on the grid is taken; tables written by :func:`write_c81` from
#: :data:`DEFAULT_ALPHAS_DEG` (two decimals) take 36 000.
GRID_SIZES: tuple[int, ...] = (3600, 7200, 36000, 72000, 360000)

_ON_GRID_TOL = 1e-6  # grid steps: how close to a grid point an angle of the table counts as on it


def _grid_size(table: C81Table) -> int:
    """The smallest of :data:`GRID_SIZES` with every table angle in [-180, 180] deg on the grid,
    else the largest."""
    angles = np.unique(np.concatenate([getattr(table, k).alpha for k in _BLOCKS]))
    angles = angles[(angles >= -math.pi - _ANGLE_TOL) & (angles <= math.pi + _ANGLE_TOL)]
    deg = np.rad2deg(angles) + 180.0
    for n in GRID_SIZES:
        k = deg * (n / 360.0)
        if np.all(np.abs(k - np.round(k)) < _ON_GRID_TOL):
            return n
    return GRID_SIZES[-1]


def _uniform_table(blk: C81Block, n: int) -> tuple[FloatArray, FloatArray]:
    """Node values ``v`` (n, n_mach) of the block's piecewise-linear interpolant on the grid
    ``-pi + 2 pi k / n`` and the increments ``d`` to the next node (periodic: node n is node 0)."""
    grid = -math.pi + (2.0 * math.pi / n) * np.arange(n)
    v = np.stack([np.interp(grid, blk.alpha, blk.values[:, j]) for j in range(blk.mach.size)], axis=1)
    d = np.diff(np.concatenate([v, v[:1]]), axis=0)
    return _readonly(v), _readonly(d)


def _mach_blend(blk: C81Block, mach: FloatArray, cols: list[FloatArray]) -> FloatArray:
    """Linear in the Mach number between the columns ``cols`` (one per Mach number of the
    block), the Mach number clipped to the block's range."""
    if blk.mach.size == 1:
        return cols[0]
    ms = blk.mach
    m = np.clip(mach, ms[0], ms[-1])
    j = np.clip(np.searchsorted(ms, m, side="right") - 1, 0, ms.size - 2)
    s = (m - ms[j]) / (ms[j + 1] - ms[j])
    stack = np.stack(cols)  # (n_mach, ...)
    v0 = np.take_along_axis(stack, j[None, ...], axis=0)[0]
    v1 = np.take_along_axis(stack, (j + 1)[None, ...], axis=0)[0]
    return v0 + s * (v1 - v0)


@dataclass(frozen=True)
class C81Section:
    """A section whose coefficients come from a C81 table.

    The interface of :mod:`rotorlyap.model.airfoil` (``coefficients(alpha)``), with an
    optional Mach number: ``alpha`` in rad wrapped to [-pi, pi); lift perpendicular and drag
    parallel to the relative wind; ``cm`` about the table's reference point (the aerodynamic
    centre for tables made by :func:`table_from_section` from the package's sections),
    positive nose up.

    The model: the table's piecewise-linear interpolant in the angle, linear in the Mach
    number (bilinear; :meth:`exact_coefficients`). The Mach number is clipped to each block's
    range: below its first Mach number the first column is used, above its last the last (no
    extrapolation: a table says nothing outside its range). A block with one Mach column is
    Mach-independent; a section is :attr:`mach_dependent` if any block has two or more.

    :meth:`coefficients` evaluates the same interpolant through a uniform periodic angle grid
    of :attr:`table_size` intervals, ``-pi + 2 pi k / table_size`` (the grid
    :class:`~rotorlyap.model.airfoil.Airfoil` uses, so that the compiled kernels of
    :mod:`rotorlyap.model.compiled` and the enclosures of the proofs read a C81 section as
    they read the package's own, :meth:`table_rows`). By default the grid is the coarsest of
    :data:`GRID_SIZES` that holds every angle of the table: then the grid's interpolant *is*
    the table's (every kink of the table a grid point), equal to :meth:`exact_coefficients` to
    round-off (about 1e-15). Where no grid size holds every angle, the largest (0.001 deg) is
    taken and the grid's interpolant differs from the table's only in the grid intervals
    holding an angle of the table, by at most ``|slope jump| * h / 4`` there (``h`` = 2 pi /
    table_size: below 3e-6 for a jump of the slope of 1 per deg);
    :attr:`resampling_error` gives the bound of the table at hand. The closure at +-180 deg
    is periodic (``alpha = pi`` is wrapped to ``-pi``): a table whose values at -180 and 180
    deg differ is followed to its last angle below 180 deg and, in the last grid interval,
    joined to its value at -180 deg.

    Compressibility (:mod:`rotorlyap.model.compressibility`,
    ``BladeParameters.compressibility``): a Mach-dependent table carries the compressibility
    of its section, so the strip loads read it at the section Mach number ``|w| / a`` with
    ``compressibility = "table"`` and the package's Prandtl-Glauert factor and drag rise are not
    applied; ``"none"`` and ``"prandtl-glauert"`` with a Mach-dependent table are refused
    (:class:`~rotorlyap.model.parameters.BladeParameters`), and so is ``"table"`` with a
    Mach-independent section. A Mach-independent table is a section like the package's own:
    ``"none"`` uses it as it is, ``"prandtl-glauert"`` corrects it as an incompressible
    section (its one Mach column taken as incompressible data, whatever its Mach number).

    Paths: the numpy strip loads take every C81 section; the compiled kernels and the proofs'
    enclosures take a Mach-independent one (:meth:`table_rows`); for a Mach-dependent one
    :meth:`table_rows` is None, the compiled kernels fall back to the numpy path and the
    proofs refuse it (no Mach axis in the kernels or the enclosures).

    Parameters
    ----------
    table : C81Table
        The table.
    table_size : int, optional
        Intervals of the uniform angle grid, >= 360; 0 evaluates :meth:`exact_coefficients`
        every call (numpy path only: no :meth:`table_rows`). Default: the smallest of
        :data:`GRID_SIZES` holding every angle of the table (above).
    thickness_ratio : float, optional
        Thickness over chord, -, in (0, 0.5): used only by the Lock drag rise of
        ``compressibility = "prandtl-glauert"`` on a Mach-independent table. Default 0.12
        (:data:`rotorlyap.model.compressibility.THICKNESS_RATIO`).
    file_name : str, optional
        The C81 file the table was read from, as a parameter file names it (kept for writing the
        parameter file back, :mod:`rotorlyap.model.parameter_files`); not compared.
    """

    table: C81Table
    table_size: int | None = None
    thickness_ratio: float = THICKNESS_RATIO
    file_name: str | None = field(default=None, compare=False)
    _grid: tuple = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        if not isinstance(self.table, C81Table):
            raise TypeError(f"table must be a C81Table, got {type(self.table).__name__}")
        ts = self.table_size
        if ts is None:
            ts = _grid_size(self.table)
        if isinstance(ts, (bool, np.bool_)) or not isinstance(ts, (int, np.integer)):
            raise TypeError(f"table_size must be None, 0 or an int >= 360, got {ts!r}")
        if ts != 0 and ts < 360:
            raise ValueError(f"table_size must be None (automatic), 0 (no grid) or >= 360, got {ts!r}")
        object.__setattr__(self, "table_size", int(ts))
        tc = self.thickness_ratio
        if isinstance(tc, (bool, np.bool_)) or not isinstance(tc, (int, float, np.integer, np.floating)) \
                or not 0.0 < float(tc) < 0.5:
            raise ValueError(f"thickness_ratio must be a real number in (0, 0.5), got {tc!r}")
        object.__setattr__(self, "thickness_ratio", float(tc))
        if self.file_name is not None and not isinstance(self.file_name, str):
            raise TypeError(f"file_name must be None or a str, got {self.file_name!r}")
        grid = tuple(_uniform_table(getattr(self.table, k), ts) for k in _BLOCKS) if ts else ()
        object.__setattr__(self, "_grid", grid)

    @property
    def name(self) -> str:
        """The table's name."""
        return self.table.name

    @property
    def mach_dependent(self) -> bool:
        """True if a block has two or more Mach columns."""
        return any(getattr(self.table, k).mach.size > 1 for k in _BLOCKS)

    @property
    def resampling_error(self) -> float:
        """Bound of ``|coefficients - exact_coefficients|`` from the uniform grid, -: ``|slope
        jump| * h / 4`` at the largest jump of a table angle off the grid (0 where every angle
        is on it; round-off aside). ``nan`` with ``table_size = 0`` (no grid)."""
        n = self.table_size
        if n == 0:
            return float("nan")
        h = 2.0 * math.pi / n
        worst = 0.0
        for k in _BLOCKS:
            blk = getattr(self.table, k)
            a = blk.alpha
            s = np.diff(blk.values, axis=0) / np.diff(a)[:, None]
            jumps = np.abs(np.diff(s, axis=0)).max(axis=1)   # at the inner angles a[1:-1]
            inner = a[1:-1]
            kk = (inner + math.pi) / h
            off = np.abs(kk - np.round(kk)) >= _ON_GRID_TOL
            inside = (inner > -math.pi) & (inner < math.pi)
            if np.any(off & inside):
                worst = max(worst, float(jumps[off & inside].max()) * h / 4.0)
        return worst

    def table_rows(self) -> FloatArray | None:
        """The uniform table of :meth:`coefficients` as one read-only array, in the layout of
        :meth:`rotorlyap.model.airfoil.Airfoil.table_rows`, or None.

        Returns
        -------
        numpy.ndarray, shape (table_size, 6) or None
            Columns: value and increment of cl, cd and cm on the grid ``-pi + 2 pi k /
            table_size`` (the compiled kernels and the proofs' enclosures read it). None for a
            Mach-dependent table (the kernels and enclosures have no Mach axis: the compiled
            path falls back to numpy, the proofs refuse) and with ``table_size = 0``.
        """
        if not self._grid or self.mach_dependent:
            return None
        rows = self.__dict__.get("_table_rows")
        if rows is None:
            rows = np.ascontiguousarray(np.stack([a[:, 0] for pair in self._grid for a in pair], axis=1))
            rows.flags.writeable = False
            object.__setattr__(self, "_table_rows", rows)
        return rows

    def coefficients(self, alpha: ArrayLike, mach: ArrayLike = 0.0
                     ) -> tuple[FloatArray, FloatArray, FloatArray]:
        """Lift, drag and moment coefficients at the angles of attack ``alpha``.

        Through the uniform angle grid (class docstring: equal to :meth:`exact_coefficients`
        to round-off where every angle of the table is on the grid), linear in the Mach number.

        Parameters
        ----------
        alpha : array_like
            Angle of attack, rad, any shape; wrapped to [-pi, pi).
        mach : array_like, optional
            Mach number, -, broadcastable with ``alpha``; clipped to each block's Mach range;
            ignored by a Mach-independent table. Default 0.

        Returns
        -------
        cl, cd, cm : ndarray
            Lift, drag and pitching-moment coefficients, float64, of the broadcast shape of
            ``alpha`` and ``mach``.
        """
        if not self._grid:
            return self.exact_coefficients(alpha, mach)
        n = self.table_size
        if not self.mach_dependent:
            al = np.asarray(alpha, dtype=np.float64)
            if np.ndim(mach) and np.shape(mach) != al.shape:
                al = np.broadcast_arrays(al, np.asarray(mach, dtype=np.float64))[0]
            i, u = grid_position(al, n)
            return tuple(v[i, 0] + u * d[i, 0] for v, d in self._grid)  # type: ignore[return-value]
        al, m = np.broadcast_arrays(np.asarray(alpha, dtype=np.float64), np.asarray(mach, dtype=np.float64))
        i, u = grid_position(al, n)
        out = []
        for key, (v, d) in zip(_BLOCKS, self._grid):
            blk = getattr(self.table, key)
            cols = [v[i, j] + u * d[i, j] for j in range(blk.mach.size)]
            out.append(_mach_blend(blk, m, cols))
        return out[0], out[1], out[2]

    def exact_coefficients(self, alpha: ArrayLike, mach: ArrayLike = 0.0
                           ) -> tuple[FloatArray, FloatArray, FloatArray]:
        """The table's bilinear interpolant itself (no grid); same interface as
        :meth:`coefficients`."""
        al, m = np.broadcast_arrays(wrap_angle(alpha), np.asarray(mach, dtype=np.float64))
        t = self.table
        return _interpolate(t.cl, al, m), _interpolate(t.cd, al, m), _interpolate(t.cm, al, m)

    def _forward_lift(self) -> tuple[FloatArray, FloatArray]:
        """Angles (rad) and ``cl`` of the lowest Mach column at the table angles within +-90 deg."""
        blk = self.table.cl
        keep = np.abs(blk.alpha) <= 0.5 * math.pi
        return blk.alpha[keep], blk.values[keep, 0]

    @property
    def cl_max(self) -> float:
        """Largest ``cl`` of forward flow (+-90 deg) at the lowest Mach number of the table, -."""
        return float(self._forward_lift()[1].max())

    @property
    def alpha_stall(self) -> float:
        """Angle of :attr:`cl_max`, rad (the stall angle :func:`~rotorlyap.model.compressibility.validity_map` uses)."""
        a, c = self._forward_lift()
        return float(a[int(np.argmax(c))])

    @property
    def cl_min(self) -> float:
        """Smallest ``cl`` of forward flow (+-90 deg) at the lowest Mach number, -."""
        return float(self._forward_lift()[1].min())

    @property
    def alpha_stall_negative(self) -> float:
        """Angle of :attr:`cl_min`, rad."""
        a, c = self._forward_lift()
        return float(a[int(np.argmin(c))])

    @property
    def alpha_zero_lift(self) -> float:
        """Zero-lift angle between :attr:`alpha_stall_negative` and :attr:`alpha_stall` at the
        lowest Mach number (linear between the table angles), rad."""
        a, c = self._forward_lift()
        lo, hi = int(np.argmin(c)), int(np.argmax(c))
        if lo >= hi:
            raise ValueError(f"the table {self.name!r} has its cl_min at or above the angle of its cl_max "
                             "in forward flow: no zero-lift angle between them")
        a, c = a[lo:hi + 1], c[lo:hi + 1]
        k = int(np.argmax(c >= 0.0))  # first angle with cl >= 0 (k >= 1: c[0] = cl_min < 0)
        return float(a[k - 1] + (a[k] - a[k - 1]) * (0.0 - c[k - 1]) / (c[k] - c[k - 1]))


def _takes_mach(section: Any) -> bool:
    try:
        return "mach" in inspect.signature(section.coefficients).parameters
    except (TypeError, ValueError):
        return False


def table_from_section(section: Any, alphas_deg: ArrayLike | None = None,
                       mach: ArrayLike = (0.0,), name: str | None = None) -> C81Table:
    """Tabulate a section (any object with ``coefficients(alpha)``) as a C81 table.

    The same angles and Mach numbers serve the three blocks. If the section's
    ``coefficients`` has a ``mach`` parameter it is called once per Mach number
    (``coefficients(alpha, mach=M)``); otherwise it is called once and its column repeated
    for every Mach number.

    Parameters
    ----------
    section : object
        With ``coefficients(alpha) -> (cl, cd, cm)``, ``alpha`` in rad (e.g.
        :data:`rotorlyap.model.airfoil.NACA23012`).
    alphas_deg : array_like, optional
        Angles of the table, deg, strictly increasing, from -180 to 180 (at most 99 for a
        file). Default :data:`DEFAULT_ALPHAS_DEG` (98 angles; with NACA 23012 linear
        interpolation is within 7.0e-4 in ``cl`` and 1.0e-4 in ``cd`` over -15..18 deg,
        within 1.2e-2 in all coefficients over the circle, measured: module docstring). Two
        decimals keep the angles exact through a file.
    mach : array_like, optional
        Mach numbers, -, >= 0, strictly increasing. Default ``(0.0,)``: one column.
    name : str, optional
        Title (printable ASCII, at most 30 characters). Default: the section's ``name``.

    Returns
    -------
    C81Table
        Angles in rad.

    Raises
    ------
    ValueError
        Angles not strictly increasing or not covering -180..180 deg, bad Mach numbers,
        coefficients of the wrong shape or not finite, a name that is not a C81 title.
    """
    a_deg = np.asarray(DEFAULT_ALPHAS_DEG if alphas_deg is None else alphas_deg, dtype=np.float64)
    if a_deg.ndim != 1 or a_deg.size < 2 or np.any(np.diff(a_deg) <= 0):
        raise ValueError("alphas_deg must be 1-D, strictly increasing, at least two angles")
    if a_deg[0] > -180.0 or a_deg[-1] < 180.0:
        raise ValueError(f"alphas_deg must cover -180..180 deg (first <= -180, last >= 180), got "
                         f"{a_deg[0]:g}..{a_deg[-1]:g}")
    m = np.atleast_1d(np.asarray(mach, dtype=np.float64))
    if name is None:
        name = getattr(section, "name", None)
        if not isinstance(name, str):
            raise ValueError("the section has no str attribute 'name': pass name=")
    alpha = np.deg2rad(a_deg)
    if _takes_mach(section):
        cols = [section.coefficients(alpha, mach=float(mj)) for mj in m]
    else:
        cols = [section.coefficients(alpha)] * m.size
    blocks = {}
    for k, key in enumerate(_BLOCKS):
        vals = np.stack([np.broadcast_to(np.asarray(c[k], dtype=np.float64), alpha.shape) for c in cols], axis=1)
        try:
            blocks[key] = C81Block(mach=m, alpha=alpha, values=vals)
        except ValueError as exc:
            raise ValueError(f"{key}: {exc}") from None
    return C81Table(name=name, **blocks)
