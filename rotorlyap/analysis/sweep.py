"""Sweeps: :func:`~rotorlyap.analysis.certify.certify` over a grid, one tidy table.

:func:`sweep` runs the certificate at every point of a full-factorial grid of advance ratios,
C.G. positions, bounds ``A``, flight conditions and any numeric field of
:class:`~rotorlyap.model.parameters.BladeParameters` (``lag_damping``, ``pitch_stiffness``, ...),
and returns a :class:`SweepResult`: one row per grid point, the grid's values first, then what
was certified. A point whose trim or model fails becomes a row with ``certified = False`` and
the message in the ``error`` column; the sweep goes on.

Where the points run
--------------------
* ``workers=1``: one after the other in this process;
* ``workers=None`` (default) or ``N``: ``N`` (default: every core, or ``ROTORLYAP_WORKERS``,
  :func:`available_cores`) processes
  of a :class:`concurrent.futures.ProcessPoolExecutor`, started by ``"spawn"`` with one
  BLAS/OpenMP thread each (:data:`WORKER_ENVIRONMENT`), never by ``"fork"``: numba's OpenMP
  threading layer (GNU OpenMP) aborts a child forked after its threads started. As with any
  ``multiprocessing`` code, a script that sweeps with several processes must guard its entry
  point with ``if __name__ == "__main__":``;
* ``scheduler="local"``: a local Dask cluster (``dask.distributed.LocalCluster``, one process per
  worker, one thread each), closed afterwards; ``scheduler="tcp://host:port"``: the Dask
  cluster at that address (its workers need rotorlyap installed). Dask is an optional
  dependency: ``pip install "dask[distributed]"``.

Same numbers on every route
---------------------------
Every route evaluates the same function on each point (:func:`evaluate_point`), in a process
that shares nothing mutable with the others (the trims are cached per process, and a cached trim
is the one a fresh computation gives), and the rows are always in grid order, whatever the order
in which the points complete. The worker processes of both the pool and Dask run one BLAS thread
each, so their tables are identical. ``workers=1`` runs with this process's BLAS threads (the command
line starts with one): where that is more than one, the trim's linear solves round differently
and the numbers differ in the last digits (relative 1e-10 in the growth rate, seen); start Python
with ``OPENBLAS_NUM_THREADS=1`` for identical tables.
"""

from __future__ import annotations

import contextlib
import csv
import itertools
import json
import math
import multiprocessing
import os
import pickle
import uuid
import warnings
from collections.abc import Callable, Iterable, Mapping, Sequence
from concurrent.futures import ProcessPoolExecutor, as_completed
from dataclasses import dataclass, fields, replace
from pathlib import Path
from typing import Any

import numpy as np

from ..conventions import HINGES, MAX_ADVANCE_RATIO
from ..errors import ConvergenceError, TemplateValuesWarning
from ..model.forward_trim import TRIM_TARGETS
from ..model.parameters import CG_POSITIONS, BladeParameters
from .certify import FUNCTIONS, Certificate, certify

__all__ = ["DASK_INSTALL", "GRID_SETTINGS", "RESULT_COLUMNS", "WORKER_ENVIRONMENT", "WORKERS_VARIABLE", "SweepResult",
           "available_cores", "evaluate_point", "grid_names", "grid_value_type", "process_map", "sweep", "sweep_fields",
           "worker_count"]

DASK_INSTALL: str = 'pip install "dask[distributed]"'
"""The install line of the optional Dask dependency (``scheduler=``)."""

GRID_SETTINGS: tuple[str, ...] = ("mu", "cg", "A", "condition")
"""Grid names that are not fields of :class:`BladeParameters`: the advance ratio, the C.G. case
(a name of :data:`rotorlyap.model.parameters.CG_POSITIONS`), the requested bound ``A`` of the
scaled norm and the flight condition (:data:`rotorlyap.model.forward_trim.TRIM_TARGETS`)."""

_HINGE_SYMBOLS: tuple[str, str, str] = HINGES  # flap, lag, pitch: the names of Certificate's per-hinge readings

RESULT_COLUMNS: tuple[str, ...] = (
    "certified", "bound", "start_region",
    *(f"start_{h}_{unit}" for h in _HINGE_SYMBOLS for unit in ("deg", "deg_per_s")),
    "growth_rate_per_rev", "collective_deg", "cyclic_cos_deg", "cyclic_sin_deg", "shaft_tilt_deg", "error",
)
"""The columns after the grid's, in order:

``certified``
    True if every azimuth was certified (a numerical certificate, see
    :class:`~rotorlyap.analysis.certify.Certificate`);
``bound``, ``start_region``
    the certified bound ``A`` and the smallest start radius ``lambda0``, scaled norm (0 if nothing
    was certified);
``start_<hinge>_deg``, ``start_<hinge>_deg_per_s``
    the start region along each hinge angle (deg) and rate (deg/s), hinges ``flap``, ``lag``,
    ``pitch`` (:data:`rotorlyap.conventions.HINGES`);
``growth_rate_per_rev``
    largest real part of the Floquet exponents about the steady motion, per rev (units of the
    rotor speed, i.e. per rad of azimuth);
``collective_deg``, ``cyclic_cos_deg``, ``cyclic_sin_deg``, ``shaft_tilt_deg``
    the trim, deg;
``error``
    empty, or the failure of the point (its numbers are then empty: None, CSV ``""``, JSON ``null``).
"""

_POINT_ERRORS = (ConvergenceError, ValueError, ArithmeticError)
"""What makes a point an error row: a trim or iteration that does not converge, a value the model
refuses (``ValueError``, which includes ``numpy.linalg.LinAlgError``), a float failure. Anything
else is a bug and stops the sweep."""


def sweep_fields() -> tuple[str, ...]:
    """The numeric fields of :class:`BladeParameters` a grid may vary (a float, int or optional float:
    ``radius``, ``lag_damping``, ``pitch_stiffness``, ``collective``, ...)."""
    return tuple(f.name for f in fields(BladeParameters) if _field_kind(f) is not None)


def grid_names() -> tuple[str, ...]:
    """Every name a grid may use: :data:`GRID_SETTINGS` then :func:`sweep_fields`."""
    return GRID_SETTINGS + sweep_fields()


def _field_kind(f) -> type | None:
    """``float`` or ``int`` for a numeric field (a number, an optional number or a spanwise profile
    whose default is a number), else None (tuples, strings, the airfoil)."""
    default = f.default
    if isinstance(default, bool) or not (default is None or isinstance(default, (int, float))):
        return None
    if isinstance(default, int) or str(f.type) == "int":
        return int
    if isinstance(default, float) or "float" in str(f.type):
        return float
    return None


def grid_value_type(name: str) -> type:
    """The Python type of the values of grid name ``name``: ``str`` (``"cg"``, ``"condition"``),
    ``int`` (``n_blades``, ``n_stations``) or ``float``."""
    if name in ("cg", "condition"):
        return str
    if name in ("mu", "A"):
        return float
    for f in fields(BladeParameters):
        if f.name == name:
            return _field_kind(f) or float
    return float


# ---------------------------------------------------------------------- the grid


def _values(name: str, values: Any) -> tuple:
    """``values`` of the grid entry ``name`` as a non-empty tuple (a single value is a tuple of one)."""
    if isinstance(values, np.ndarray):
        values = values.tolist() if values.ndim else [values.item()]
    elif isinstance(values, (str, bytes)) or not isinstance(values, Iterable):
        values = (values,)
    values = tuple(v.item() if isinstance(v, np.generic) else v for v in values)
    if not values:
        raise ValueError(f"grid[{name!r}] is empty: give at least one value")
    return values


def _check_value(params: BladeParameters, name: str, value: Any, label: str | None = None) -> Any:
    """The value of grid name ``name``, normalised (floats for float fields), or a ValueError or
    TypeError saying what is allowed; ``label`` names it in the message (default ``grid[name]``)."""
    label = label or f"grid[{name!r}] values"
    if name == "cg":
        if not isinstance(value, str) or value not in CG_POSITIONS:
            raise ValueError(f"{label} must be among {tuple(CG_POSITIONS)}, got {value!r}")
        return value
    if name == "condition":
        if not isinstance(value, str) or value not in TRIM_TARGETS:
            raise ValueError(f"{label} must be among {TRIM_TARGETS}, got {value!r}")
        return value
    kind = grid_value_type(name)
    integer = isinstance(value, int) and not isinstance(value, bool)
    if kind is int and not integer:
        raise TypeError(f"{label} must be integers, got {value!r}")
    if kind is float and not (integer or isinstance(value, float)):
        raise TypeError(f"{label} must be real numbers, got {value!r}")
    value = kind(value)
    if name == "mu":
        if not (math.isfinite(value) and 0.0 <= value <= MAX_ADVANCE_RATIO):
            raise ValueError(f"{label} must lie in [0, {MAX_ADVANCE_RATIO:g}] (advance ratio), got {value!r}")
        return value
    if name == "A":
        if not (math.isfinite(value) and value > 0.0):
            raise ValueError(f"{label} must be finite and > 0 (a bound of the scaled norm), got {value!r}")
        return value
    try:  # the field's own validation, one value at a time
        replace(params, **{name: value})
    except (ValueError, TypeError) as exc:
        raise type(exc)(f"grid[{name!r}] = {value!r} is not allowed: {exc}") from exc
    return value


def _normalised_grid(params: BladeParameters, grid: Mapping[str, Any]) -> dict[str, tuple]:
    if not isinstance(grid, Mapping) or not grid:
        raise ValueError("grid must be a non-empty mapping {name: sequence of values}, e.g. "
                         "{'mu': [0.0, 0.1], 'cg': ['forward', 'backward']}")
    allowed = grid_names()
    unknown = [n for n in grid if n not in allowed]
    if unknown:
        raise ValueError(f"unknown grid name(s) {unknown}: allowed are {GRID_SETTINGS} and the numeric "
                         f"fields of BladeParameters {sweep_fields()}")
    if "cg" in grid and "cg_position" in grid:
        raise ValueError("grid: give 'cg' (a Table I case name) or 'cg_position' (a fraction of chord), not both")
    return {name: tuple(_check_value(params, name, v) for v in _values(name, values))
            for name, values in grid.items()}


# ---------------------------------------------------------------------- one point


def _certificate_row(cert: Certificate) -> tuple:
    start = cert.start_region_per_hinge  # {flap/lag/pitch: (deg, deg/s)}, hinge order
    per_hinge = [float(x) for pair in start.values() for x in pair]
    p = cert.trim.params
    controls = [math.degrees(p.collective), math.degrees(p.cyclic_cos), math.degrees(p.cyclic_sin),
                math.degrees(p.shaft_tilt)]
    return (bool(cert.certified), float(cert.bound), float(cert.start_region), *per_hinge,
            float(cert.growth_rate), *controls, "")


def _error_row(exc: BaseException) -> tuple:
    n_numbers = len(RESULT_COLUMNS) - 2
    return (False, *([None] * n_numbers), f"{type(exc).__name__}: {exc}")


def evaluate_point(params: BladeParameters, point: tuple[tuple[str, Any], ...], settings: Mapping[str, Any]) -> tuple:
    """Certify one grid point; the row of :data:`RESULT_COLUMNS` (without the grid's values).

    Parameters
    ----------
    params : BladeParameters
        The base blade.
    point : tuple of (name, value)
        The grid values of this point (names of :func:`grid_names`).
    settings : mapping
        ``mu``, ``condition``, ``A`` (used where the point does not set them), ``n_psi``,
        ``scales`` and ``engine_options`` (passed to :func:`~rotorlyap.analysis.certify.certify`).

    Returns
    -------
    tuple
        Plain Python values (bool, float, str, None): the same in any process.
    """
    mu, condition, A = settings["mu"], settings["condition"], settings["A"]
    overrides: dict[str, Any] = {}
    for name, value in point:
        if name == "mu":
            mu = value
        elif name == "condition":
            condition = value
        elif name == "A":
            A = value
        elif name == "cg":
            overrides["cg_position"] = CG_POSITIONS[value]
        else:
            overrides[name] = value
    try:
        with warnings.catch_warnings():
            # the caller was warned about the base blade's template values (once, in its own
            # process); a worker rebuilding it must not warn again for every point
            warnings.simplefilter("ignore", TemplateValuesWarning)
            blade = replace(params, **overrides) if overrides else params
        cert = certify(blade, mu, condition=condition, A=A, scales=settings["scales"], n_psi=settings["n_psi"],
                       **settings["engine_options"])
    except _POINT_ERRORS as exc:
        return _error_row(exc)
    return _certificate_row(cert)


def _evaluate_task(task: tuple) -> tuple:
    """Picklable entry of the worker processes: ``(params, point, settings)``."""
    return evaluate_point(*task)


# ---------------------------------------------------------------------- the table


def _parse(kind: type, text: str) -> Any:
    if text == "":
        return None if kind is not str else ""
    if kind is bool:
        if text not in ("True", "False"):
            raise ValueError(f"a boolean column holds True or False, got {text!r}")
        return text == "True"
    return kind(text)


@dataclass(frozen=True)
class SweepResult:
    """The table of a :func:`sweep`: one row per grid point, in grid order.

    Attributes
    ----------
    columns : tuple of str
        The grid's names (in the grid's order), then :data:`RESULT_COLUMNS`.
    rows : tuple of tuple
        One row per point (bool, int, float, str or None; None where a failed point has no number).
    """

    columns: tuple[str, ...]
    rows: tuple[tuple, ...]

    def __len__(self) -> int:
        return len(self.rows)

    @property
    def grid_columns(self) -> tuple[str, ...]:
        """The grid's names: the columns before :data:`RESULT_COLUMNS`."""
        return self.columns[: len(self.columns) - len(RESULT_COLUMNS)]

    @property
    def n_certified(self) -> int:
        """Number of points certified."""
        i = self.columns.index("certified")
        return sum(1 for r in self.rows if r[i])

    def column(self, name: str) -> tuple:
        """The values of column ``name``, in row order."""
        if name not in self.columns:
            raise KeyError(f"no column {name!r}; the columns are {self.columns}")
        i = self.columns.index(name)
        return tuple(r[i] for r in self.rows)

    def as_records(self) -> list[dict[str, Any]]:
        """The rows as ``[{column: value}]`` (what :meth:`to_json` writes)."""
        return [dict(zip(self.columns, r)) for r in self.rows]

    def to_csv(self, path: str | Path) -> Path:
        """Write the table as CSV (a header, then one line per row; floats in full precision, a
        missing number as an empty field); returns the path."""
        path = Path(path)
        with path.open("w", newline="", encoding="utf-8") as fh:
            w = csv.writer(fh)
            w.writerow(self.columns)
            for r in self.rows:
                w.writerow(["" if v is None else repr(v) if isinstance(v, float) else v for v in r])
        return path

    def to_json(self, path: str | Path) -> Path:
        """Write the table as a JSON list of records (``null`` for a missing number); returns the path."""
        path = Path(path)
        with path.open("w", encoding="utf-8") as fh:
            json.dump(self.as_records(), fh, indent=1, allow_nan=False)
            fh.write("\n")
        return path

    def write(self, path: str | Path) -> Path:
        """Write the table in the format of the file's suffix, ``.csv`` or ``.json``."""
        suffix = Path(path).suffix.lower()
        if suffix == ".csv":
            return self.to_csv(path)
        if suffix == ".json":
            return self.to_json(path)
        raise ValueError(f"the table's file must end in .csv or .json, got {str(path)!r}")

    @classmethod
    def read(cls, path: str | Path) -> "SweepResult":
        """Read a table written by :meth:`to_csv` or :meth:`to_json` (by the suffix) back, equal.

        Raises
        ------
        ValueError
            Another suffix, or a file whose columns do not end in :data:`RESULT_COLUMNS`.
        """
        path = Path(path)
        suffix = path.suffix.lower()
        if suffix == ".json":
            records = json.loads(path.read_text(encoding="utf-8"))
            columns = tuple(records[0]) if records else ()
            cls._check_columns(path, columns)
            kinds = [cls._column_kind(c) for c in columns]
            rows = tuple(tuple(None if v is None else k(v) for k, v in zip(kinds, (rec[c] for c in columns)))
                         for rec in records)
            return cls(columns, rows)
        if suffix == ".csv":
            with path.open(newline="", encoding="utf-8") as fh:
                lines = list(csv.reader(fh))
            columns = tuple(lines[0]) if lines else ()
            cls._check_columns(path, columns)
            kinds = [cls._column_kind(c) for c in columns]
            return cls(columns, tuple(tuple(_parse(k, t) for k, t in zip(kinds, line)) for line in lines[1:]))
        raise ValueError(f"a sweep table ends in .csv or .json, got {str(path)!r}")

    @staticmethod
    def _column_kind(name: str) -> type:
        if name == "certified":
            return bool
        if name == "error":
            return str
        return float if name in RESULT_COLUMNS else grid_value_type(name)

    @staticmethod
    def _check_columns(path: Path, columns: tuple) -> None:
        if tuple(columns[-len(RESULT_COLUMNS):]) != RESULT_COLUMNS:
            raise ValueError(f"{path}: not a sweep table (its columns must end in {RESULT_COLUMNS})")


# ---------------------------------------------------------------------- execution


#: The environment of the worker processes: one BLAS/OpenMP thread each, as Dask's workers have
#: (``distributed.nanny.pre-spawn-environ``): the processes already fill the cores, and the same
#: thread count in every worker gives the same rounding (the trim's linear solves round differently
#: with another number of BLAS threads). One thread of the compiled kernels too (their results do
#: not depend on it; two processes on two cores, each with two kernel threads, measured 31 s a
#: scan cell against 25 s with one).
WORKER_ENVIRONMENT: dict[str, str] = {"OMP_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1", "MKL_NUM_THREADS": "1",
                                      "NUMBA_NUM_THREADS": "1"}


@contextlib.contextmanager
def _environment(values: Mapping[str, str]):
    """Set environment variables for the processes started inside the block; afterwards this
    process's environment is as before, whatever the block changed (Dask's nanny sets its
    ``pre-spawn-environ`` in the parent process and leaves it there)."""
    saved = dict(os.environ)
    os.environ.update(values)
    try:
        yield
    finally:
        for k in set(os.environ) - set(saved):
            del os.environ[k]
        for k, v in saved.items():
            if os.environ.get(k) != v:
                os.environ[k] = v


#: Environment variable that sets the default number of worker processes (a positive integer):
#: the test run sets it to 1 in each of its xdist workers, which already fill the cores
#: (``conftest.py``), as it sets one BLAS and kernel thread.
WORKERS_VARIABLE = "ROTORLYAP_WORKERS"


def available_cores() -> int:
    """The default number of workers: ``ROTORLYAP_WORKERS`` where it is set, else the cores this
    process may run on (its CPU affinity where the platform tells it, else ``os.cpu_count()``)."""
    value = os.environ.get(WORKERS_VARIABLE, "").strip()
    if value:
        try:
            n = int(value)
        except ValueError:
            n = 0
        if n < 1:
            raise ValueError(f"{WORKERS_VARIABLE} must be a positive integer (the default number of worker "
                             f"processes), got {value!r}")
        return n
    if hasattr(os, "process_cpu_count"):  # Python >= 3.13
        return os.process_cpu_count() or 1
    if hasattr(os, "sched_getaffinity"):
        return len(os.sched_getaffinity(0)) or 1
    return os.cpu_count() or 1


def worker_count(workers: int | None, n_items: int) -> int:
    """The number of processes for ``n_items`` independent items: ``workers`` (default
    :func:`available_cores`), at most one per item, at least 1. A ``workers`` below 1 is refused."""
    n = available_cores() if workers is None else int(workers)
    if n < 1:
        raise ValueError(f"workers must be >= 1 (None: every core), got {workers}")
    return max(1, min(n, n_items))


def _run_serial(tasks: list[tuple], progress: Callable[[int, int], None]) -> list[tuple]:
    progress(0, len(tasks))
    out = []
    for i, task in enumerate(tasks):
        out.append(_evaluate_task(task))
        progress(i + 1, len(tasks))
    return out


def _run_processes(tasks: list[tuple], workers: int, progress: Callable[[int, int], None]) -> list[tuple]:
    try:
        pickle.dumps(tasks[0][0])
    except Exception as exc:  # noqa: BLE001 (pickling fails with several types)
        raise TypeError("the blade cannot be sent to worker processes (a profile given as a lambda or a local "
                        "function cannot be pickled): use a TabulatedProfile or a module-level function, or "
                        f"workers=1 ({exc})") from exc
    return process_map(_evaluate_task, tasks, workers, progress)


def process_map(fn: Callable[[Any], Any], items: Sequence[Any], workers: int | None = None,
                progress: Callable[[int, int], None] | None = None,
                cost: Callable[[Any], float] | None = None) -> list:
    """``[fn(item) for item in items]`` in ``workers`` fresh processes, results in the items' order.

    The processes of :func:`sweep` (module docstring): started by ``"spawn"`` with
    :data:`WORKER_ENVIRONMENT` (one BLAS/OpenMP thread each), so that each result is the one a
    fresh interpreter computes. ``fn`` must be a module-level function and the items picklable;
    items are submitted in order, so put the longest first, or give ``cost(item)``: then they
    are submitted by decreasing cost (in order among equal costs). ``workers`` defaults to
    :func:`available_cores`; ``progress(done, total)`` is called as results arrive.
    """
    workers = worker_count(workers, len(items))
    if cost is not None:
        order = sorted(range(len(items)), key=lambda k: -cost(items[k]))
        done = process_map(fn, [items[k] for k in order], workers, progress)
        out = [None] * len(items)
        for k, r in zip(order, done):
            out[k] = r
        return out
    progress = progress or _no_progress
    # "spawn": a fresh interpreter per worker, started with WORKER_ENVIRONMENT (a forked child
    # would inherit this process's BLAS threads, and numba's GNU OpenMP layer aborts a child forked
    # after its threads started; a fork server keeps the environment it was started with)
    ctx = multiprocessing.get_context("spawn")
    out: list = [None] * len(items)
    pool = ProcessPoolExecutor(max_workers=workers, mp_context=ctx)
    try:
        with _environment(WORKER_ENVIRONMENT):  # the workers start at the first submissions
            futures = {pool.submit(fn, item): i for i, item in enumerate(items)}
        progress(0, len(items))
        for done, fut in enumerate(as_completed(futures), start=1):
            out[futures[fut]] = fut.result()
            progress(done, len(items))
    except BaseException:  # an interrupt or a bug: drop the items not started rather than wait for them
        pool.shutdown(wait=False, cancel_futures=True)
        raise
    pool.shutdown()
    return out


def _dask():
    try:
        from dask import distributed
    except ImportError as exc:
        raise ImportError(f"sweeps on a Dask scheduler need dask.distributed, an optional dependency: "
                          f"{DASK_INSTALL}") from exc
    return distributed


def _run_dask(tasks: list[tuple], scheduler: str, workers: int | None,
              progress: Callable[[int, int], None]) -> list[tuple]:
    """The points on Dask: a local cluster (closed afterwards) or the scheduler at an address."""
    distributed = _dask()
    if scheduler != "local":
        with distributed.Client(scheduler) as client:
            return _gather_dask(distributed, client, tasks, progress)
    n = worker_count(workers, len(tasks))
    with _environment(WORKER_ENVIRONMENT):
        with distributed.LocalCluster(n_workers=n, threads_per_worker=1, processes=True,
                                      dashboard_address=None) as cluster, distributed.Client(cluster) as client:
            return _gather_dask(distributed, client, tasks, progress)


def _gather_dask(distributed, client, tasks: list[tuple], progress: Callable[[int, int], None]) -> list[tuple]:
    """Submit the points to the Dask client and collect the rows in grid order."""
    progress(0, len(tasks))
    tag = uuid.uuid4().hex[:8]
    futures = client.map(_evaluate_task, tasks, key=[f"rotorlyap-sweep-{tag}-{i}" for i in range(len(tasks))],
                         pure=False)
    index = {f.key: i for i, f in enumerate(futures)}
    out: list[tuple | None] = [None] * len(tasks)
    for done, fut in enumerate(distributed.as_completed(futures), start=1):
        out[index[fut.key]] = tuple(fut.result())
        progress(done, len(tasks))
    return out  # type: ignore[return-value]


def _no_progress(done: int, total: int) -> None:
    pass


def _check_function(function: str) -> str:
    if function not in FUNCTIONS:
        raise ValueError(f"function must be one of {FUNCTIONS}, got {function!r}")
    return function


def sweep(params: BladeParameters, grid: Mapping[str, Sequence[Any] | Any], *, n_psi: int = 36,
          condition: str = "propulsive", mu: float = 0.0, A: float | None = None, scales=None,
          function: str = "quadratic", workers: int | None = None, scheduler: str | None = None,
          progress: Callable[[int, int], None] | None = None, **engine_options) -> SweepResult:
    """Certify technical stability at every point of a grid (full factorial), one table.

    Parameters
    ----------
    params : BladeParameters
        The base blade; each point is ``dataclasses.replace(params, ...)`` with the point's fields.
    grid : mapping
        ``{name: values}``; names: ``"mu"`` (advance ratio, -), ``"cg"`` (names of
        :data:`~rotorlyap.model.parameters.CG_POSITIONS`, sets ``cg_position``), ``"A"`` (requested
        bound, scaled norm), ``"condition"`` (:data:`~rotorlyap.model.forward_trim.TRIM_TARGETS`),
        or any numeric field of :class:`BladeParameters` (:func:`sweep_fields`, SI units:
        ``lag_damping`` in N m s/rad, ...). A single value counts as a list of one. The points run
        through the grid in the order of its keys, the last varying fastest.
    n_psi : int
        Azimuths of each certificate's grid.
    condition : str
        Flight condition where the grid has no ``"condition"``.
    mu : float
        Advance ratio where the grid has no ``"mu"``.
    A : float, optional
        Requested bound where the grid has no ``"A"`` (default
        :data:`rotorlyap.conventions.DEFAULT_A`).
    scales : array_like, optional
        Norm scales ``a_i``, rad and rad/rad (default :data:`rotorlyap.conventions.DEFAULT_SCALES`).
    function : str
        The Liapunov function of every point (:data:`rotorlyap.analysis.certify.FUNCTIONS`).
        Default ``"quadratic"``, seconds a point, where :func:`~rotorlyap.analysis.certify.certify`
        defaults to ``"auto"`` (tens of seconds a point, for the largest certificate).
    workers : int, optional
        Processes (or Dask workers of a local cluster); default every core (:func:`available_cores`);
        1 runs in this process.
    scheduler : str, optional
        None: this machine (``workers``); ``"local"``: a local Dask cluster; ``"tcp://host:port"``
        (any address ``dask.distributed.Client`` takes): that Dask cluster.
    progress : callable, optional
        ``progress(done, total)``, called with 0 first and after each point completes.
    **engine_options
        Passed on to :func:`~rotorlyap.analysis.certify.certify` (``n_sphere``, ``Q``, ...).

    Returns
    -------
    SweepResult
        Rows in grid order whatever the route and the order of completion.

    Raises
    ------
    ValueError
        An unknown grid name (the message lists the allowed ones), an empty list, a value the
        name does not allow, a bad ``workers``, ``condition`` or ``mu``.
    TypeError
        A value of the wrong type, or a blade that cannot be sent to worker processes.
    ImportError
        ``scheduler`` given without dask.distributed installed (the message has the install line).
    """
    if not isinstance(params, BladeParameters):
        raise TypeError(f"params must be a BladeParameters, got {type(params).__name__}")
    if workers is not None and (isinstance(workers, bool) or not isinstance(workers, int) or workers < 1):
        raise ValueError(f"workers must be None (every core) or an integer >= 1, got {workers!r}")
    if scheduler is not None and (not isinstance(scheduler, str) or not scheduler):
        raise ValueError(f"scheduler must be None, 'local' or a Dask scheduler address, got {scheduler!r}")
    if isinstance(n_psi, bool) or not isinstance(n_psi, int) or n_psi < 1:
        raise ValueError(f"n_psi must be an integer >= 1, got {n_psi!r}")
    settings = {"mu": _check_value(params, "mu", mu, "mu"),
                "condition": _check_value(params, "condition", condition, "condition"),
                "A": None if A is None else _check_value(params, "A", A, "A"),
                "scales": None if scales is None else np.asarray(scales, dtype=float),
                "n_psi": n_psi, "engine_options": dict(engine_options, function=_check_function(function))}
    axes = _normalised_grid(params, grid)
    points = [tuple(zip(axes, values)) for values in itertools.product(*axes.values())]
    tasks = [(params, point, settings) for point in points]
    progress = progress or _no_progress
    if scheduler is not None:
        results = _run_dask(tasks, scheduler, workers, progress)
    else:
        n = worker_count(workers, len(tasks))
        results = _run_serial(tasks, progress) if n == 1 else _run_processes(tasks, n, progress)
    rows = tuple(tuple(v for _, v in point) + tuple(r) for point, r in zip(points, results))
    return SweepResult(columns=tuple(axes) + RESULT_COLUMNS, rows=rows)
