"""Test-run hooks for the book's notebooks (nbval); ``book/_ext/notebook_execution.py``
explains the design.

1. **Image outputs are never compared**: every MIME type of
   ``notebook_execution.IMAGE_MIMES`` joins nbval's skip list.
2. **One execution feeds the build**: each notebook nbval executed completely (every code
   cell ran, none raised) is stored, with its fresh outputs, in the book build's notebook
   cache, so that ``jupyter-book build`` renders it without executing it again. Under
   pytest-xdist each worker hands its notebooks to the controller, which stores them.
3. **One BLAS and kernel thread per worker**: with several xdist workers, each worker and the
   notebook kernels it starts use one OpenBLAS/OpenMP thread and one thread for the compiled
   kernels (``NUMBA_NUM_THREADS``; unless the environment already says how many): the workers
   already fill the cores, and threads waiting for a busy core cost more than they save
   (measured: two processes side by side, each a forward-flight scan cell, 31 s each with two
   kernel threads, 25 s with one). Likewise one process for the chapters that spread their cells
   over every core (``ROTORLYAP_WORKERS``, :func:`rotorlyap.analysis.sweep.available_cores`:
   measured, the test command 688 s with chapters 7 and 8 in one process each, 720 s with two
   worker processes each). The numbers do not depend on it (a compiled kernel computes
   each state alone, :mod:`rotorlyap.jit`; a committed output prints only the digits that
   survive another BLAS, "What a committed output may print" in the README).
4. **The longest files first**: pytest-xdist hands each worker whole files (``--dist
   loadfile``) in the order of the collection (``--no-loadscope-reorder``: not by number of
   tests, which started the one-test falsifier files of half a minute each last); the two
   chapters of minutes first, then the other notebooks and the files with a ``slow`` test, the
   quick files last, so that both workers finish together (the order of the tests within a
   file is kept).
"""

from __future__ import annotations

import copy
import json
import os
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent / "book" / "_ext"))
import notebook_execution  # noqa: E402

_WORKER_KEY = "rotorlyap_executed_notebooks"
_THREAD_VARIABLES = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS", "NUMBA_NUM_THREADS",
                     "ROTORLYAP_WORKERS")


def pytest_configure(config):
    """Point 3: one BLAS and kernel thread per xdist worker (set before the workers start).

    Each xdist worker also keeps its own numba cache (``_build/numba-cache/<worker>``, unless
    ``NUMBA_CACHE_DIR`` is set), which the notebooks' kernels it starts inherit: numba's on-disk
    cache is not safe against two processes compiling the same function into it at once (numba
    issues 4807 and 10128: a cached function loaded half-written segfaults). A clean clone's
    run starts with no cache, both workers compile the same kernels in their first minutes, and
    a notebook's kernel crashed so on 2026-12-05, leaving nbval waiting for a reply that never
    came."""
    workers = getattr(config.option, "numprocesses", None)
    if workers not in (None, 0, "0") and not hasattr(config, "workerinput"):
        for name in _THREAD_VARIABLES:
            os.environ.setdefault(name, "1")
    worker = getattr(config, "workerinput", {}).get("workerid")
    if worker is not None and "NUMBA_CACHE_DIR" not in os.environ:
        os.environ["NUMBA_CACHE_DIR"] = str(Path(__file__).resolve().parent / "_build" / "numba-cache" / worker)
        if "numba" in sys.modules:  # numba read its configuration when imported: read it again
            sys.modules["numba"].core.config.reload_config()


def _nbval_cell_class():
    try:
        from nbval.plugin import IPyNbCell
    except ImportError:  # nbval not installed: nothing to do
        return None
    return IPyNbCell


class _Executions:
    """Fresh outputs of the notebooks executed in this process, cell by cell."""

    def __init__(self) -> None:
        self.cells: dict[str, dict[int, list | None]] = {}
        self.seconds: dict[str, float] = {}
        self.notebooks: dict[str, object] = {}

    def record(self, item, report) -> None:
        path = str(item.path)
        outputs = item.test_outputs
        ok = outputs is not None and not item.parent.timed_out and not any(
            o.get("output_type") == "error" for o in outputs)
        self.cells.setdefault(path, {})[item.cell_num] = copy.deepcopy(outputs) if ok else None
        self.seconds[path] = self.seconds.get(path, 0.0) + report.duration
        self.notebooks[path] = item.parent.nb

    def complete(self) -> list[tuple[str, dict, float]]:
        """(path, executed notebook as a dict, seconds) for every completely executed notebook."""
        done = []
        for path, cells in self.cells.items():
            nb = copy.deepcopy(self.notebooks[path])
            code = [c for c in nb.cells if c.cell_type == "code"]
            if len(cells) != len(code) or any(cells.get(k) is None for k in range(len(code))):
                continue
            for k, cell in enumerate(code):
                cell.outputs = cells[k]
                cell.execution_count = k + 1
                for out in cell.outputs:
                    if out.get("output_type") == "execute_result":
                        out["execution_count"] = k + 1
            done.append((path, nb, self.seconds[path]))
        return done


_EXECUTIONS = _Executions()
_FROM_WORKERS: list[tuple[str, dict, float]] = []
_STORED: list[str] = []
_TREE = notebook_execution.fingerprint()  # the package the notebooks of this run execute


#: The two longest files of the test run (chapters 7 and 8, minutes each): the first two a
#: worker starts (point 4).
LONGEST_FIRST = ("book/07_validation.ipynb", "book/08_trimmed_flight.ipynb")


def _file_rank(item, slow_files: set) -> int:
    """Point 4: 0 for :data:`LONGEST_FIRST`, 1 for the other notebooks and the files with a
    ``slow`` test, 2 for the rest."""
    path = item.nodeid.split("::")[0]
    if path in LONGEST_FIRST:
        return 0
    return 1 if path.endswith(".ipynb") or path in slow_files else 2


def pytest_collection_modifyitems(session, config, items):
    cell_class = _nbval_cell_class()
    for item in items:
        if cell_class is not None and isinstance(item, cell_class):
            nbfile = item.parent
            nbfile.skip_compare = tuple(dict.fromkeys(tuple(nbfile.skip_compare) + notebook_execution.IMAGE_MIMES))
    # point 4: the longest files first, the quick ones last (pytest-xdist hands out whole files
    # in this order, --no-loadscope-reorder in pyproject.toml), so that the run does not end
    # with one worker busy on a long file while the other waits
    slow_files = {item.nodeid.split("::")[0] for item in items if item.get_closest_marker("slow")}
    order = {id(item): (_file_rank(item, slow_files), k) for k, item in enumerate(items)}
    items.sort(key=lambda item: order[id(item)])


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item, call):
    outcome = yield
    cell_class = _nbval_cell_class()
    if call.when == "call" and cell_class is not None and isinstance(item, cell_class):
        _EXECUTIONS.record(item, outcome.get_result())


@pytest.hookimpl(optionalhook=True)
def pytest_testnodedown(node, error):
    """xdist controller: collect the notebooks a worker executed."""
    import nbformat

    for path, nb_json, seconds in json.loads(getattr(node, "workeroutput", {}).get(_WORKER_KEY, "[]")):
        _FROM_WORKERS.append((path, nbformat.from_dict(nb_json), seconds))


def pytest_sessionfinish(session, exitstatus):
    done = _EXECUTIONS.complete()
    workeroutput = getattr(session.config, "workeroutput", None)
    if workeroutput is not None:  # an xdist worker: the controller stores
        workeroutput[_WORKER_KEY] = json.dumps([(p, nb, s) for p, nb, s in done])
        return
    _STORED.extend(notebook_execution.store(done + _FROM_WORKERS, executed_with=_TREE))


def pytest_terminal_summary(terminalreporter):
    if _STORED:
        terminalreporter.write_line(f"notebook outputs stored for the book build in "
                                    f"{notebook_execution.CACHE_DIR}: {', '.join(sorted(_STORED))}")
