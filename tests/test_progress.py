"""Progress of long computations (rotorlyap.progress): silent by default, told to a listener."""

import io

import pytest

from rotorlyap import BladeParameters, certify
from rotorlyap.progress import Bar, Lines, listening, report


def test_nobody_listens_by_default_so_a_report_does_nothing(capsys):
    report("stage", 1, 2)
    out = capsys.readouterr()
    assert out.out == "" and out.err == ""


def test_certify_reports_its_stages_in_order_and_nothing_unless_listened_to(capsys):
    seen = []
    with listening(lambda stage, done, total: seen.append((stage, done, total))):
        certify(BladeParameters.table_i("forward"), 0.0, condition="none", function="quadratic")
    stages = list(dict.fromkeys(s for s, _, _ in seen))
    order = ["trim (none, mu = 0)", "steady motion", "Floquet exponents", "candidate 1 of 1: the quadratic function",
             "the quadratic function's start set"]
    assert [s for s in stages if s in order] == order
    assert any(s.startswith("sound rule: final check of the band") for s in stages)
    assert capsys.readouterr().err == ""  # the listener got it all; nothing printed


def test_lines_writes_one_line_per_stage_and_nesting_restores_the_outer_listener():
    stream, inner = io.StringIO(), []
    with listening(Lines(stream, prefix="> ")):
        report("a", 1, 3)
        report("a", 2, 3)
        with listening(lambda *args: inner.append(args)):
            report("b")
        report("c")
    report("d")  # outside: nobody listens
    assert stream.getvalue() == "> a\n> c\n"
    assert inner == [("b", None, None)]


def test_the_bar_draws_the_stage_and_its_count_on_its_stream():
    stream = io.StringIO()
    with listening(Bar(stream)):
        report("design: round", 2, 5)
        report("final check")
    text = stream.getvalue()
    assert "design: round: 2/5" in text and "final check" in text


def test_a_listener_must_be_callable():
    with pytest.raises(TypeError, match="listener must be callable"):
        with listening("not a function"):
            pass
