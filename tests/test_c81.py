"""Tests of rotorlyap.model.c81: the C81 layout, its refusals, interpolation, the shipped NACA 23012 table."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from rotorlyap.model.airfoil import NACA23012
from rotorlyap.model.c81 import (
    DEFAULT_ALPHAS_DEG,
    NACA23012_C81,
    NACA23012_C81_NAME,
    C81Block,
    C81Section,
    C81Table,
    read_c81,
    table_from_section,
    write_c81,
)


def _block(alpha_deg, mach, values) -> C81Block:
    return C81Block(mach=np.asarray(mach, float), alpha=np.deg2rad(np.asarray(alpha_deg, float)),
                    values=np.asarray(values, float))


def _small_text() -> str:
    """A valid 2-Mach, 5-angle table; lines: 1 title, 2 CL Mach row, 3-7 CL rows, 8 CD Mach row,
    9-13 CD rows, 14 CM Mach row, 15-19 CM rows."""
    a = [-180.0, -15.0, 0.0, 15.0, 180.0]
    cl = [[0.0, 0.0], [-1.2, -1.1], [0.1, 0.12], [1.4, 1.3], [0.0, 0.0]]
    cd = [[0.02, 0.02], [0.03, 0.04], [0.006, 0.008], [0.03, 0.04], [0.02, 0.02]]
    cm = [[0.0, 0.0], [-0.01, -0.02], [-0.014, -0.016], [-0.02, -0.03], [0.0, 0.0]]
    t = C81Table("TEST", _block(a, [0.3, 0.7], cl), _block(a, [0.3, 0.7], cd), _block(a, [0.3, 0.7], cm))
    return write_c81(t)


def _edit(text: str, line: int, new: str) -> str:
    lines = text.splitlines()
    lines[line - 1] = new
    return "\n".join(lines) + "\n"


def _set_field(text: str, line: int, field: int, value: str) -> str:
    ln = text.splitlines()[line - 1].ljust(7 * field)
    return _edit(text, line, ln[: 7 * (field - 1)] + value.rjust(7)[:7] + ln[7 * field:])


# ----------------------------------------------------------------------------- the layout

def test_round_trip_reproduces_every_number_to_half_a_unit_of_its_last_printed_decimal():
    """read_c81(write_c81(t)) == t to the printed precision (4 decimals for coefficients and
    Mach numbers below 10, angles to 0.005 deg), with 12 Mach numbers (continuation lines), and
    writing what was read gives the same text."""
    rng = np.random.default_rng(1)
    a = np.concatenate([[-180.0], np.sort(rng.uniform(-179, 179, 40)), [180.0]])
    m = np.linspace(0.0, 1.1, 12)
    blocks = [_block(a, m, rng.uniform(-9.5, 9.5, (a.size, m.size))) for _ in range(3)]
    t = C81Table("random table", *blocks)
    text = write_c81(t)
    back = read_c81(text)
    assert back.name == "random table"
    for key in ("cl", "cd", "cm"):
        b0, b1 = getattr(t, key), getattr(back, key)
        assert np.max(np.abs(b1.values - b0.values)) <= 0.5e-4 + 1e-12
        assert np.max(np.abs(b1.mach - b0.mach)) <= 0.5e-4 + 1e-12
        assert np.max(np.abs(np.rad2deg(b1.alpha - b0.alpha))) <= 0.005 + 1e-9
    assert write_c81(back) == text


def test_numbers_on_the_printed_grid_come_back_exactly_and_the_table_is_equal():
    """Numbers with at most the printed decimals are read back bit for bit: the tables compare equal."""
    t = read_c81(_small_text())
    assert read_c81(write_c81(t)) == t
    assert hash(read_c81(write_c81(t))) == hash(t)


def test_written_layout_is_a30_6i2_then_7_column_fields_9_a_line():
    """Title: name in columns 1-30, counts in 2-column fields; Mach rows start with 7 blanks; an
    angle row holds the angle and 9 values, the 10th to 12th on a continuation line starting
    with 7 blanks; every line is at most 70 columns."""
    a = [-180.0, 0.0, 180.0]
    m = np.linspace(0.0, 1.1, 12)
    v = np.arange(36, dtype=float).reshape(3, 12) / 100
    t = C81Table("NACA 0012", _block(a, m, v), _block(a, m[:2], v[:, :2]), _block(a, m[:1], v[:, :1]))
    lines = write_c81(t).splitlines()
    assert lines[0] == "NACA 0012" + " " * 21 + "12 3 2 3 1 3"
    assert lines[1].startswith(" " * 7 + " 0.0000 0.1000") and len(lines[1]) == 70
    assert lines[2] == " " * 7 + " 0.9000 1.0000 1.1000"
    assert lines[3][:14] == "-180.00 0.0000" and lines[4] == " " * 7 + " 0.0900 0.1000 0.1100"
    assert len(lines) == 1 + 2 + 3 * 2 + 1 + 3 + 1 + 3
    assert max(len(ln) for ln in lines) <= 70


def test_reads_the_mbdyn_example_and_its_free_format_and_the_whitespace_variant():
    """The example of MBDyn's c81data.txt (fixed columns, values like '-180.' and '0.'), MBDyn's
    '# FREE FORMAT' ('name; counts', values as words) and a table whose values are separated by
    blanks off the 7-column grid all give the same numbers."""
    fixed = ("NACA 0012                      2 5 2 5 2 3\n"
             "       0.0    0.6\n-180.  1.2    1.3\n-15.   1.2    1.3\n0.     0.     0.\n"
             "15.    1.2    1.3\n180.   1.2    1.3\n"
             "       0.0    0.6\n-180.  0.5    0.2\n-15.   0.1    0.2\n0.     0.01   0.01\n"
             "15.    0.1    0.2\n180.   0.5    0.2\n"
             "       0.0    0.6\n-180.  0.0    -0.1\n0.     0.0    -0.05\n180.   0.0    -0.1\n")
    rows = ["0.0 0.6", "-180 1.2 1.3", "-15 1.2 1.3", "0 0 0", "15 1.2 1.3", "180 1.2 1.3",
            "0.0 0.6", "-180 0.5 0.2", "-15 0.1 0.2", "0 0.01 0.01", "15 0.1 0.2", "180 0.5 0.2",
            "0.0 0.6", "-180 0.0 -0.1", "0 0.0 -0.05", "180 0.0 -0.1"]
    free = "# FREE FORMAT\nNACA 0012; 2 5 2 5 2 3\n" + "\n".join(rows) + "\n"
    words = "NACA 0012 2 5 2 5 2 3\n" + "\n\n".join("  " + r for r in rows) + "\n"
    t = read_c81(fixed)
    assert t.name == "NACA 0012"
    assert t.cl.values.tolist() == [[1.2, 1.3], [1.2, 1.3], [0.0, 0.0], [1.2, 1.3], [1.2, 1.3]]
    assert t.cm.alpha.tolist() == [-math.pi, 0.0, math.pi]
    assert read_c81(free) == t
    assert read_c81(words) == t


def test_reads_zero_padded_counts_d_exponents_crlf_and_a_path(tmp_path):
    """Counts written as '05' (C81-Interface's I0.2), Fortran D exponents, CRLF line ends, and a path."""
    text = _small_text()
    t = read_c81(text)
    head = text.splitlines()[0]
    variant = _edit(text, 1, head[:30] + "".join(f"{int(head[30 + 2 * k:32 + 2 * k]):02d}" for k in range(6)))
    variant = _set_field(variant, 4, 2, "-12.D-1")
    assert read_c81(variant.replace("\n", "\r\n")) == t
    p = tmp_path / "small.c81"
    write_c81(t, p)
    assert read_c81(p) == t and read_c81(str(p)) == t


# ----------------------------------------------------------------------------- refusals

def _refused(text: str, *fragments: str) -> str:
    with pytest.raises(ValueError) as info:
        read_c81(text)
    msg = str(info.value)
    for f in fragments:
        assert f in msg, (f, msg)
    return msg


def test_refuses_angles_not_covering_minus_180_to_180_naming_the_line():
    """A block starting at -170 deg is refused: the message names its first row (line 3) and -180..180."""
    _refused(_set_field(_small_text(), 3, 1, "-170."), "line 3,", "-180..180 deg")
    _refused(_set_field(_small_text(), 19, 1, "170."), "line 19,", "-180..180 deg")


def test_refuses_angles_not_strictly_increasing_naming_the_line():
    """-20 deg after 0 deg (line 6 after line 5) and a repeated angle are refused at their line."""
    _refused(_set_field(_small_text(), 6, 1, "-20."), "line 6, field 1", "strictly increasing", "line 5")
    _refused(_set_field(_small_text(), 12, 1, "0."), "line 12, field 1", "strictly increasing")


def test_refuses_mach_numbers_not_increasing_naming_the_line():
    """Mach numbers 0.7, 0.3 on line 8 (the drag block) are refused at line 8, field 3."""
    text = _set_field(_set_field(_small_text(), 8, 2, "0.7"), 8, 3, "0.3")
    _refused(text, "line 8, field 3", "strictly increasing")


def test_refuses_a_missing_value_naming_line_and_columns():
    """A blank field (Fortran would read 0) is refused: line 5, field 3, columns 15-21."""
    text = _edit(_small_text(), 5, _small_text().splitlines()[4][:14])
    _refused(text, "line 5, field 3 (columns 15-21)", "missing value")
    _refused(_set_field(_small_text(), 10, 2, ""), "line 10, field 2 (columns 8-14)", "missing value")


def test_refuses_non_numeric_fields_nan_and_blanks_inside_a_field():
    """'abc', 'nan', 'inf' and '1 5' (Fortran: 15) in a field are refused with line and columns."""
    for bad in ("abc", "nan", "inf", "  1 5"):
        _refused(_set_field(_small_text(), 16, 3, bad), "line 16, field 3 (columns 15-21)", "not a number")


def test_refuses_a_header_count_that_does_not_match_the_rows():
    """NL = 4 for 5 CL rows: line 7 (the fifth row) is met where the drag block's Mach row must
    start; NL = 6: line 8 (the drag Mach row) is met where an angle is due; ND = 5 -> 6 leaves
    the file short; NM = 5 -> 4 leaves text after the table (line 19)."""
    text = _small_text()
    head = text.splitlines()[0]

    def with_counts(*c):
        return _edit(text, 1, head[:30] + "".join(f"{v:2d}" for v in c))

    _refused(with_counts(2, 4, 2, 5, 2, 5), "line 7, field 1", "fewer angles for CL")
    _refused(with_counts(2, 6, 2, 5, 2, 5), "line 8, field 1", "missing value", "more angles")
    _refused(with_counts(2, 5, 2, 5, 2, 4), "line 19", "after the moment block")
    _refused(with_counts(2, 5, 2, 5, 2, 6), "after line 19", "more lines than the file has")
    _refused(with_counts(3, 5, 2, 5, 2, 5), "line 2, field 4", "missing value")


def test_refuses_text_after_the_fields_and_bad_title_lines():
    """Text after the last field of a row, a tab, counts of 0 or over 99 columns, no counts at all."""
    text = _small_text()
    _refused(_edit(text, 4, text.splitlines()[3] + "   9.9"), "line 4: unexpected text after column 21")
    _refused(text.replace("\n 0.0000", "\n\t0.0000", 1), "line 5, column 1")
    head = text.splitlines()[0]
    _refused(_edit(text, 1, head[:30] + " 2 0 2 5 2 5"), "line 1, columns 33-34", "NL = 0")
    _refused(_edit(text, 1, "TEST"), "line 1", "counts")
    _refused("\n" + text, "line 1", "empty title line")


def test_a_table_of_words_is_refused_where_its_word_reading_fails():
    """For a table whose values are words off the 7-column grid, the error reported is that of
    the reading that got further into the file (the word reading): line 6, word 3 for 'abc';
    a stray blank line inside a fixed table is refused by the fixed reading at its line."""
    rows = ["0.3 0.7", "-180 0 0", "-15 -1.2 -1.1", "0 0.1 0.12", "15 1.4 abc", "180 0 0"]
    text = "TEST 2 5 2 5 2 5\n" + "\n".join(rows * 3) + "\n"
    msg = _refused(text, "line 6, word 3", "'abc' is not a number")
    assert msg.startswith("line 6, word 3")
    lines = _small_text().splitlines()
    fixed = "\n".join([*lines[:4], "", *lines[4:]]) + "\n"  # its row on line 4 has touching values
    assert _refused(fixed, "line 5: blank line").startswith("line 5")


def test_refuses_the_public_paraglidyn_deck_that_is_off_the_7_column_grid():
    """A row of 11 values on one line past column 70 with '0.' in columns 1-7 of the Mach row
    (as in federico-savorgnan/paraglidyn naca0012.c81) is refused at line 2, both readings failing."""
    vals = "".join(f"{m:7.2f}" for m in np.linspace(0.0, 1.0, 11))
    text = "PROFILO NACA 0012             11 211 211 2\n" + "  0.   " + vals + "\n"
    msg = _refused(text, "line 2, field 1 (columns 1-7)", "must be blank")
    assert re.search(r"read as words .* fails too, at line 2\]", msg)


# ----------------------------------------------------------------------------- the shipped table

def test_shipped_file_is_what_the_documented_call_writes():
    """rotorlyap/data/naca23012.c81 == write_c81(table_from_section(NACA23012, name=...)):
    98 angles, one Mach column (M = 0), 298 lines. If this fails after a change of NACA23012,
    regenerate the file with the call in the module docstring."""
    expected = write_c81(table_from_section(NACA23012, name=NACA23012_C81_NAME))
    assert NACA23012_C81.read_text(encoding="ascii") == expected
    t = read_c81(NACA23012_C81)
    assert t.name == NACA23012_C81_NAME
    for key in ("cl", "cd", "cm"):
        blk = getattr(t, key)
        assert blk.alpha.size == len(DEFAULT_ALPHAS_DEG) == 98 and blk.mach.tolist() == [0.0]
    assert len(expected.splitlines()) == 298


@pytest.fixture(scope="module")
def shipped() -> C81Section:
    return C81Section(read_c81(NACA23012_C81))


def _max_error(section, lo_deg, hi_deg, n=400_001):
    a = np.deg2rad(np.linspace(lo_deg, hi_deg, n))
    ref = NACA23012.coefficients(a)
    got = section.coefficients(a)
    return [float(np.max(np.abs(g - r))) for g, r in zip(got, ref, strict=True)]


def test_shipped_table_reproduces_naca23012_in_attached_flow_to_7e_4_in_cl(shipped):
    """Over -15..18 deg (alpha_stall_negative..alpha_stall) the interpolated shipped table is
    within 7.0e-4 of NACA23012 in cl (stated: about 1e-3), 1.0e-4 in cd, 1e-7 in cm."""
    e_cl, e_cd, e_cm = _max_error(shipped, -15.0, 18.0)
    assert e_cl < 7.1e-4 and e_cd < 1.01e-4 and e_cm < 1e-7


def test_shipped_table_is_exact_to_the_printed_digits_on_the_linear_lift_curve(shipped):
    """On -8.5..12.5 deg (grid intervals inside the linear lift curve, -9.83..13.06 deg) cl
    differs from the model only by the 4-decimal rounding (5e-5)."""
    e_cl, _, _ = _max_error(shipped, -8.5, 12.5, 10_001)
    assert e_cl <= 0.5e-4 + 1e-9


def test_shipped_table_reproduces_naca23012_on_the_full_circle_to_1_2e_2(shipped):
    """Over -180..180 deg: within 1.05e-2 in cl (post stall), 1.12e-2 in cd (next to the drag
    corner at -90 deg), 5.1e-3 in cm (reverse flow), as the module docstring states."""
    e_cl, e_cd, e_cm = _max_error(shipped, -180.0, 180.0 - 1e-9)
    assert e_cl < 1.06e-2 and e_cd < 1.13e-2 and e_cm < 5.2e-3


# ----------------------------------------------------------------------------- the section

def _mach_table() -> C81Table:
    """cl = f(alpha) + g(alpha) M at Mach 0.3 and 0.7 (known linear Mach dependence); cd, cm one column."""
    a = np.array([-180.0, -10.0, 0.0, 10.0, 180.0])
    f = np.array([0.0, -1.0, 0.1, 1.1, 0.0])
    g = np.array([0.0, -0.5, 0.2, 0.6, 0.0])
    m = np.array([0.3, 0.7])
    cl = f[:, None] + g[:, None] * m[None, :]
    return C81Table("mach", _block(a, m, cl), _block(a, [0.0], np.full((5, 1), 0.01)),
                    _block(a, [0.0], np.full((5, 1), -0.02)))


def test_mach_interpolation_is_exact_for_a_linear_mach_dependence():
    """cl = f + g M between Mach 0.3 and 0.7: the section gives f + g M exactly at the nodes
    (10 deg, M = 0.45) and the bilinear value between them (5 deg: f, g halfway)."""
    s = C81Section(_mach_table())
    cl, cd, cm = s.coefficients(np.deg2rad([10.0, 5.0, -10.0]), mach=0.45)
    assert cl == pytest.approx([1.1 + 0.6 * 0.45, 0.6 + 0.4 * 0.45, -1.0 - 0.5 * 0.45], abs=1e-14)
    assert cd == pytest.approx([0.01] * 3) and cm == pytest.approx([-0.02] * 3)


def test_mach_outside_the_table_is_clipped_to_its_first_and_last_mach_number():
    """Below 0.3 the M = 0.3 column, above 0.7 the M = 0.7 column (no extrapolation); a
    one-column block ignores the Mach number."""
    s = C81Section(_mach_table())
    a = np.deg2rad(10.0)
    assert s.coefficients(a, mach=0.0)[0] == pytest.approx(1.1 + 0.6 * 0.3, abs=1e-14)
    assert s.coefficients(a, mach=0.95)[0] == pytest.approx(1.1 + 0.6 * 0.7, abs=1e-14)
    assert s.coefficients(a, mach=5.0)[1] == s.coefficients(a, mach=0.0)[1] == pytest.approx(0.01)


def test_coefficients_are_vectorised_any_shape_with_broadcast_mach():
    """alpha of shape (3, 4) gives (3, 4) outputs; a Mach array of shape (4,) broadcasts; each
    element equals the scalar call."""
    s = C81Section(_mach_table())
    rng = np.random.default_rng(3)
    alpha = rng.uniform(-4.0, 4.0, (3, 4))
    mach = np.array([0.0, 0.4, 0.6, 0.9])
    out = s.coefficients(alpha, mach)
    assert all(c.shape == (3, 4) and c.dtype == np.float64 for c in out)
    assert all(c.shape == (3, 4) for c in s.coefficients(alpha))
    for i in range(3):
        for j in range(4):
            one = s.coefficients(alpha[i, j], mach[j])
            assert [float(c) for c in one] == pytest.approx([out[k][i, j] for k in range(3)], abs=1e-15)


def test_angles_are_wrapped_to_minus_pi_pi_like_the_package_sections(shipped):
    """alpha + 2 pi k gives the same coefficients; pi gives the value at -pi."""
    a = np.linspace(-3.0, 3.0, 13)
    base = shipped.coefficients(a)
    for k in (-2, 1, 3):
        assert np.allclose(shipped.coefficients(a + 2 * math.pi * k), base, atol=1e-12)
    assert np.array_equal(np.array(shipped.coefficients(math.pi)), np.array(shipped.coefficients(-math.pi)))


def test_table_from_section_uses_a_mach_argument_when_the_section_has_one():
    """A section with coefficients(alpha, mach) is tabulated per Mach number; one without it
    (NACA23012) has its column repeated; reading the C81Section of a table back through
    table_from_section on the same angles gives the same table."""
    class MachSection:
        name = "mach section"

        def coefficients(self, alpha, mach=0.0):
            alpha = np.asarray(alpha, float)
            return 2 * np.pi * alpha * (1 + mach), np.full_like(alpha, 0.01 + mach), np.zeros_like(alpha)

    t = table_from_section(MachSection(), mach=(0.0, 0.5))
    assert np.allclose(t.cl.values[:, 1], 1.5 * t.cl.values[:, 0]) and np.allclose(t.cd.values[:, 1], 0.51)
    n = table_from_section(NACA23012, mach=(0.0, 0.4, 0.8))
    assert n.name == "NACA 23012" and np.array_equal(n.cl.values[:, 0], n.cl.values[:, 2])
    back = table_from_section(C81Section(n), alphas_deg=DEFAULT_ALPHAS_DEG, mach=(0.0, 0.4, 0.8), name=n.name)
    assert np.allclose(back.cl.values, n.cl.values, atol=1e-12)


# ----------------------------------------------------------------------------- the objects

def test_table_objects_refuse_bad_content_with_clear_errors():
    """Angles short of the circle, wrong value shapes, non-finite values, long names, more than
    99 angles for a file: ValueError naming what is allowed."""
    a = [-180.0, 0.0, 180.0]
    good = _block(a, [0.0], [[0.0], [0.1], [0.0]])
    with pytest.raises(ValueError, match="cover the whole circle"):
        _block([-170.0, 0.0, 180.0], [0.0], [[0.0], [0.1], [0.0]])
    with pytest.raises(ValueError, match=r"shape \(n_alpha, n_mach\) = \(3, 1\)"):
        _block(a, [0.0], [[0.0, 1.0]] * 3)
    with pytest.raises(ValueError, match="finite"):
        _block(a, [0.0], [[0.0], [np.nan], [0.0]])
    with pytest.raises(ValueError, match="strictly increasing"):
        _block(a, [0.5, 0.5], [[0.0, 0.0]] * 3)
    with pytest.raises(ValueError, match="at most 30"):
        C81Table("x" * 31, good, good, good)
    many = np.linspace(-180.0, 180.0, 100)
    big = _block(many, [0.0], np.zeros((100, 1)))
    with pytest.raises(ValueError, match="at most 99"):
        write_c81(C81Table("big", big, good, good))
    with pytest.raises(ValueError, match=r"cover -180\.\.180"):
        table_from_section(NACA23012, alphas_deg=[-90.0, 0.0, 90.0])
    with pytest.raises(ValueError, match=r"cover -180\.\.180"):
        read_c81(write_c81(C81Table("ok", good, good, good)).replace("-180.00", "-179.00", 1))
