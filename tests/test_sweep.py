"""rotorlyap.analysis.sweep: certify over a grid, one table, the same on every route."""

from __future__ import annotations

import csv
import json
import math
import os
import sys
import time
from dataclasses import replace

import pytest

from rotorlyap.analysis.sweep import RESULT_COLUMNS, SweepResult, sweep, sweep_fields
from rotorlyap.model.parameters import BladeParameters

# small searches (1.5-3.5 s a point); no air makes the trim refuse at once: a 4-point grid with
# 2 error rows, a hover and a forward-flight certificate (the rounding-sensitive trim), ~6 s serial
SIZES = {"n_psi": 4, "n_sphere": 16}
GRID = {"air_density": [0.0, 1.225], "mu": [0.0, 0.1]}


# True if this process runs one BLAS thread, as the worker processes (pool and Dask) do: the test
# suite under xdist sets it for its workers (conftest.py). Read once, at import: what counts is the
# value numpy started with.
ONE_BLAS_THREAD = os.environ.get("OPENBLAS_NUM_THREADS") == "1"


def assert_same_table(a: SweepResult, b: SweepResult) -> None:
    """Equal tables. Exactly where this process runs one BLAS thread like the workers (CI); with
    several BLAS threads here, the trims' linear solves (LAPACK on the collocation Jacobian) round
    differently, relative differences up to 1e-10 were seen in the growth rate, so floats are then
    compared to 1e-9 relative (and everything else, the verdicts included, exactly)."""
    assert a.columns == b.columns and len(a.rows) == len(b.rows)
    if ONE_BLAS_THREAD:
        assert a.rows == b.rows
        return
    for ra, rb in zip(a.rows, b.rows):
        for col, x, y in zip(a.columns, ra, rb):
            if isinstance(x, float) and isinstance(y, float):
                assert y == pytest.approx(x, rel=1e-9, abs=1e-12), col
            else:
                assert x == y, col


@pytest.fixture(scope="module")
def serial():
    """The grid run in this process, with the progress hook's calls."""
    calls = []
    result = sweep(BladeParameters.table_i("forward"), GRID, workers=1,
                   progress=lambda done, total: calls.append((done, total)), **SIZES)
    return result, calls


def test_the_table_has_the_grid_first_and_rows_in_grid_order(serial):
    """One row per grid point, the grid's names first (in the grid's order, the last varying
    fastest), then the result columns; the progress hook sees 0 and every completion."""
    result, calls = serial
    assert result.columns == ("air_density", "mu") + RESULT_COLUMNS
    assert [r[:2] for r in result.rows] == [(0.0, 0.0), (0.0, 0.1), (1.225, 0.0), (1.225, 0.1)]
    assert calls == [(0, 4), (1, 4), (2, 4), (3, 4), (4, 4)]
    assert result.column("certified") == (False, False, True, True) and result.n_certified == 2


def test_a_failing_point_becomes_an_error_row_and_the_sweep_goes_on(serial):
    """A point the model refuses (the forward-flight trim needs air) is a row with certified False,
    no numbers and the message in 'error'; the points after it are computed."""
    records = serial[0].as_records()
    for failed in records[:2]:
        assert failed["certified"] is False and failed["error"].startswith("ValueError: ")
        assert "needs air" in failed["error"]
        assert all(failed[c] is None for c in RESULT_COLUMNS if c not in ("certified", "error"))
    for fine in records[2:]:
        assert fine["certified"] is True and fine["error"] == "" and 0.0 < fine["start_region"] < fine["bound"]


def test_the_start_region_per_hinge_is_the_radius_times_the_scales(serial):
    """start_<hinge>_deg is a_i lambda0 in deg and _deg_per_s a_(i+3) lambda0 Omega (Table I's
    28.35 rad/s): the default scales are 2, 2, 1 deg and 2, 0.5, 5 deg/rad; the trim is in deg
    (forward flight: cyclic pitch and a forward shaft tilt)."""
    hover, forward = serial[0].as_records()[2:]
    lam = hover["start_region"]
    assert hover["start_flap_deg"] == pytest.approx(2.0 * lam, rel=1e-12)
    assert hover["start_pitch_deg"] == pytest.approx(1.0 * lam, rel=1e-12)
    assert hover["start_lag_deg_per_s"] == pytest.approx(0.5 * lam * 28.35, rel=1e-12)
    assert 5.0 < hover["collective_deg"] < 15.0 and hover["growth_rate_per_rev"] < 0.0
    assert hover["shaft_tilt_deg"] == 0.0 and forward["shaft_tilt_deg"] > 0.0 and forward["cyclic_cos_deg"] != 0.0


def test_process_pool_equals_serial(serial):
    """workers=2 (a spawn process pool, one BLAS thread per process) gives the serial table: the same
    function on each point, rows in grid order whatever the order of completion."""
    pooled = sweep(BladeParameters.table_i("forward"), GRID, workers=2, **SIZES)
    assert_same_table(serial[0], pooled)


def test_a_process_map_by_cost_returns_the_results_in_the_items_order():
    """process_map(..., cost=...) submits the costliest items first and still returns
    [fn(item) for item in items] in the items' order; the worker processes run one thread of the
    compiled kernels (WORKER_ENVIRONMENT)."""
    from rotorlyap.analysis.sweep import WORKER_ENVIRONMENT, process_map

    items = [4.0, 9.0, 1.0, 16.0, 2.0]
    assert process_map(math.sqrt, items, 2, cost=lambda x: x % 5) == [math.sqrt(x) for x in items]
    assert WORKER_ENVIRONMENT["NUMBA_NUM_THREADS"] == "1"


def test_the_default_number_of_workers_follows_rotorlyap_workers(monkeypatch):
    """ROTORLYAP_WORKERS sets the default number of worker processes (the test run sets 1 in each
    xdist worker); anything but a positive integer is refused, saying what is allowed."""
    from rotorlyap.analysis.sweep import available_cores

    monkeypatch.setenv("ROTORLYAP_WORKERS", "3")
    assert available_cores() == 3
    for bad in ("0", "two", "-1"):
        monkeypatch.setenv("ROTORLYAP_WORKERS", bad)
        with pytest.raises(ValueError, match="must be a positive integer"):
            available_cores()
    monkeypatch.delenv("ROTORLYAP_WORKERS")
    assert available_cores() >= 1


def test_the_processes_of_a_chapter_are_at_most_one_per_item_and_zero_is_refused():
    """worker_count: the requested workers, at most one per item and at least one; workers < 1
    refused with what is allowed (a chapter's cells never run silently in zero processes)."""
    from rotorlyap.analysis.sweep import worker_count
    from rotorlyap.chapters import trimmed_flight

    assert worker_count(8, 3) == 3 and worker_count(2, 0) == 1 and worker_count(1, 50) == 1
    for bad in (0, -2):
        with pytest.raises(ValueError, match="workers must be >= 1"):
            worker_count(bad, 5)
    with pytest.raises(ValueError, match="workers must be >= 1"):
        trimmed_flight.verdict_data(cases=("backward",), mu_values=(0.0,), n_psi=8, workers=0)


@pytest.mark.slow
def test_local_dask_cluster_equals_serial(request):
    """scheduler='local' (a dask.distributed LocalCluster of 2 single-threaded worker processes) gives
    the serial table. Skipped without dask unless ROTORLYAP_REQUIRE_DASK=1 (CI), where it fails."""
    try:
        import dask.distributed  # noqa: F401
    except ImportError:
        if os.environ.get("ROTORLYAP_REQUIRE_DASK") == "1":
            pytest.fail('ROTORLYAP_REQUIRE_DASK=1 but dask.distributed is not installed: pip install "dask[distributed]"')
        pytest.skip("dask.distributed is not installed (optional): pip install \"dask[distributed]\"")
    serial = request.getfixturevalue("serial")  # only once dask is known to be there
    start = time.perf_counter()
    on_dask = sweep(BladeParameters.table_i("forward"), GRID, workers=2, scheduler="local", **SIZES)
    print(f"Dask sweep of {len(on_dask)} points: {time.perf_counter() - start:.1f} s")
    assert_same_table(serial[0], on_dask)


@pytest.mark.parametrize(
    "grid, error, message",
    [
        ({"lag_dampin": [1.0]}, ValueError, "unknown grid name"),
        ({"hub_elements": [1.0]}, ValueError, "allowed are"),
        ({"cg": ["middle"]}, ValueError, "grid['cg'] values must be among ('forward', 'neutral', 'backward')"),
        ({"mu": [0.1, 3.5]}, ValueError, "grid['mu'] values must lie in [0, 3] (advance ratio)"),
        ({"A": [0.0]}, ValueError, "grid['A'] values must be finite and > 0"),
        ({"condition": ["cruise"]}, ValueError, "grid['condition'] values must be among"),
        ({"mu": []}, ValueError, "grid['mu'] is empty"),
        ({"lag_damping": [-5.0]}, ValueError, "lag_damping must be >= 0"),
        ({"n_blades": [3.5]}, TypeError, "grid['n_blades'] values must be integers"),
        ({"pitch_stiffness": ["stiff"]}, TypeError, "must be real numbers"),
        ({"cg": ["forward"], "cg_position": [0.2]}, ValueError, "not both"),
        ({}, ValueError, "non-empty mapping"),
    ],
)
def test_a_bad_grid_is_refused_before_any_work_saying_what_is_allowed(grid, error, message):
    """Unknown names, values a name does not allow and empty lists raise at once, naming what is allowed."""
    with pytest.raises(error) as info:
        sweep(BladeParameters.table_i("forward"), grid, workers=1)
    assert message in str(info.value)


def test_the_sweepable_fields_are_the_numeric_fields():
    """Numbers, optional numbers and spanwise profiles with a number as default; not the hub tuple,
    the airfoil or the model names."""
    names = sweep_fields()
    assert {"lag_damping", "pitch_stiffness", "cg_position", "collective", "n_blades"} <= set(names)
    assert not {"hub_elements", "airfoil", "inflow_model", "compressibility"} & set(names)


def test_bad_execution_options_are_refused():
    """workers must be None or >= 1; a blade with a lambda profile cannot go to worker processes."""
    params = BladeParameters.table_i("forward")
    with pytest.raises(ValueError, match="workers must be None"):
        sweep(params, {"mu": [0.0]}, workers=0)
    with pytest.raises(TypeError, match="cannot be sent to worker processes"):
        sweep(replace(params, cg_position=lambda r: 0.215 + 0.0 * r), {"mu": [0.0, 0.1]}, workers=2)


def test_without_dask_a_scheduler_says_how_to_install_it(monkeypatch):
    """scheduler= without dask.distributed raises ImportError with the install line."""
    monkeypatch.setitem(sys.modules, "dask", None)
    monkeypatch.setitem(sys.modules, "dask.distributed", None)
    with pytest.raises(ImportError, match=r'pip install "dask\[distributed\]"'):
        sweep(BladeParameters.table_i("forward"), {"air_density": [0.0]}, scheduler="local")


def test_csv_and_json_round_trip(serial, tmp_path):
    """The table written as CSV and as JSON reads back equal (floats in full precision, a missing
    number empty in CSV and null in JSON), and plain csv/json readers see one record per row."""
    result = serial[0]
    csv_path = result.write(tmp_path / "t.csv")
    json_path = result.write(tmp_path / "t.json")
    assert SweepResult.read(csv_path) == result
    assert SweepResult.read(json_path) == result
    with csv_path.open(newline="") as fh:
        rows = list(csv.DictReader(fh))
    records = json.loads(json_path.read_text())
    assert len(rows) == len(records) == len(result)
    for row, rec, mine in zip(rows, records, result.as_records()):
        assert rec == mine
        assert row["certified"] == str(mine["certified"])
        bound = mine["bound"]
        assert row["bound"] == ("" if bound is None else repr(bound))
        assert bound is None or math.isfinite(bound)
    with pytest.raises(ValueError, match="must end in .csv or .json"):
        result.write(tmp_path / "t.txt")
