"""figure_csv: the CSV files behind the download link under each figure of the book."""

from __future__ import annotations

import csv
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest

from rotorlyap.chapters.export import figure_csv, format_value
from rotorlyap.chapters.algorithm import ConvergenceData


@dataclass(frozen=True)
class _Panel:
    psi: float
    y: np.ndarray
    W: np.ndarray


def _read(path: Path) -> list[list[str]]:
    with open(path, newline="") as fh:
        return list(csv.reader(fh))


def test_one_dimensional_fields_of_one_length_give_one_column_each(tmp_path):
    data = ConvergenceData(
        n_sphere=np.array([0, 16, 64]), A=np.array([0.4, 0.41, 0.4006349]),
        alpha=np.array([1.0, 2.0, 3.0]), lambda0_min=np.zeros(3), lambda0_mean=np.ones(3),
        A_raw=np.array([1 / 3, 2 / 3, 1.0]), lambda0_mean_raw=np.array([np.nan, np.inf, -0.0]),
    )
    out = figure_csv(data, tmp_path / "conv.csv")
    assert out.read_text() == (
        "n_sphere,A,alpha,lambda0_min,lambda0_mean,A_raw,lambda0_mean_raw\n"
        "0,0.4,1,0,1,0.333333,nan\n"
        "16,0.41,2,0,1,0.666667,inf\n"
        "64,0.400635,3,0,1,1,-0\n"
    )


def test_scalars_are_repeated_on_every_row_of_the_wide_layout(tmp_path):
    out = figure_csv({"psi": [0.0, 0.5], "A": 0.4, "stable": True}, tmp_path / "w.csv")
    assert out.read_text() == "psi,A,stable\n0,0.4,1\n0.5,0.4,1\n"


def test_all_scalars_give_one_row(tmp_path):
    assert figure_csv({"A": 0.4, "n": 3}, tmp_path / "s.csv").read_text() == "A,n\n0.4,3\n"


def test_multidimensional_and_ragged_fields_use_the_long_layout(tmp_path):
    data = {
        "A": 0.5,
        "grid": np.arange(6.0).reshape(2, 3),
        "paths": (np.array([[1.0, 2.0]]), np.array([[3.0, 4.0], [5.0, 6.0]])),
        "escaped": (True, False),
    }
    rows = _read(figure_csv(data, tmp_path / "long.csv"))
    assert rows[0] == ["field", "i0", "i1", "i2", "value"]
    assert rows[1] == ["A", "", "", "", "0.5"]
    # a 2-D field: two indices, row-major
    assert rows[2:8] == [["grid", str(i), str(j), "", str(3 * i + j)] for i in range(2) for j in range(3)]
    # a ragged field: the item first, then the item's own indices
    assert rows[8:14] == [
        ["paths", "0", "0", "0", "1"], ["paths", "0", "0", "1", "2"],
        ["paths", "1", "0", "0", "3"], ["paths", "1", "0", "1", "4"],
        ["paths", "1", "1", "0", "5"], ["paths", "1", "1", "1", "6"],
    ]
    assert rows[14:] == [["escaped", "0", "", "", "1"], ["escaped", "1", "", "", "0"]]


def test_long_layout_gives_back_the_arrays_to_six_digits(tmp_path):
    rng = np.random.default_rng(1)
    grid = rng.normal(size=(4, 5)) * 1e3
    rows = _read(figure_csv({"grid": grid, "x": np.linspace(0, 1, 7)}, tmp_path / "g.csv", layout="long"))
    back = np.full(grid.shape, np.nan)
    for field, i0, i1, value in rows[1:]:
        if field == "grid":
            back[int(i0), int(i1)] = float(value)
    np.testing.assert_allclose(back, grid, rtol=5e-6)


def test_panels_of_one_dataclass_become_ragged_fields_indexed_by_panel(tmp_path):
    panels = [_Panel(0.0, np.array([1.0, 2.0]), np.eye(2)), _Panel(1.5, np.array([3.0]), np.ones((1, 1)))]
    rows = _read(figure_csv(panels, tmp_path / "p.csv"))
    assert rows[0] == ["field", "i0", "i1", "i2", "value"]
    assert ["psi", "1", "", "", "1.5"] in rows
    assert ["y", "1", "0", "", "3"] in rows
    assert ["W", "0", "1", "1", "1"] in rows
    assert len(rows) == 1 + 2 + 3 + 5


def test_a_list_of_named_columns_keeps_its_order(tmp_path):
    out = figure_csv([("b", [1, 2]), ("a", np.array([0.25, 0.5]))], tmp_path / "c.csv")
    assert out.read_text() == "b,a\n1,0.25\n2,0.5\n"


def test_formatting_is_deterministic_and_exact_for_integers():
    assert format_value(123456789) == "123456789"
    assert format_value(np.int64(-7)) == "-7"
    assert format_value(np.float32(0.1)) == "0.1"
    assert format_value(2.0 / 3.0) == "0.666667"
    assert format_value(1.23456789e-12) == "1.23457e-12"
    assert format_value(np.bool_(False)) == "0"
    assert format_value("escapes") == "escapes"


def test_same_data_same_bytes_and_no_temporary_file_left(tmp_path):
    data = {"x": np.linspace(0, 1, 11), "m": np.arange(4.0).reshape(2, 2)}
    a = figure_csv(data, tmp_path / "a.csv").read_bytes()
    b = figure_csv(data, tmp_path / "a.csv").read_bytes()
    assert a == b
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.csv"]


def test_creates_directories_and_returns_the_path_as_given(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    out = figure_csv({"x": [1.0]}, "_data/deep/fig-x.csv")
    assert out == Path("_data/deep/fig-x.csv")
    assert not out.is_absolute()
    assert (tmp_path / "_data" / "deep" / "fig-x.csv").read_text() == "x\n1\n"


@pytest.mark.parametrize(
    ("data", "kwargs", "error"),
    [
        ({"z": np.array([1 + 2j])}, {}, TypeError),
        ({"z": None}, {}, TypeError),
        ({"z": {"nested": 1}}, {}, TypeError),
        (42, {}, TypeError),
        ([("a", [1]), ("a", [2])], {}, ValueError),
        ({}, {}, ValueError),
        ({"m": np.eye(2)}, {"layout": "wide"}, ValueError),
        ({"a": [1.0, 2.0], "b": [1.0]}, {"layout": "wide"}, ValueError),
        ({"a": [1.0]}, {"layout": "tall"}, ValueError),
    ],
)
def test_bad_input_is_refused_with_a_clear_error(tmp_path, data, kwargs, error):
    with pytest.raises(error):
        figure_csv(data, tmp_path / "bad.csv", **kwargs)
    assert not (tmp_path / "bad.csv").exists()
