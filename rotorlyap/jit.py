"""Compilation of the package's numeric kernels: numba when it is installed and asked for.

The kernels of the blade model (:mod:`rotorlyap.model.compiled`), of the periodic Liapunov
function (:mod:`rotorlyap.methods.periodic_lyapunov`) and of the tabulated steady motion
(:mod:`rotorlyap.model.steady`) are plain Python loops over states, written so that numba
compiles them to machine code (``nopython`` mode, cached on disk in ``__pycache__`` beside
each module: only the first use on a machine compiles, a few seconds). Every kernel has a
numpy twin that computes the same formulas, the reference of the tests. The blade's kernels
run large batches of independent states on :func:`threads` threads (chunks of the batch on a
thread pool, :mod:`rotorlyap.model.compiled`; the kernels release the GIL); each state is
computed alone, so the numbers do not depend on the number of threads.

Which path runs
---------------
The environment variable ``ROTORLYAP_KERNEL`` chooses: ``"compiled"`` (default) runs the
compiled kernels, ``"numpy"`` the numpy path everywhere (for comparison, or on a machine where
numba does not install). It is read where a path is chosen: when a blade's equations are built
(:class:`rotorlyap.model.equations.BladeEquations` keeps its choice), and at each evaluation of
a tabulated steady motion or of a periodic Liapunov function. Without numba the numpy path
runs whatever the variable says.
"""

from __future__ import annotations

import os

__all__ = ["KERNEL_MODES", "PARALLEL_MIN_STATES", "jit", "kernel_mode", "numba_available",
           "threads", "use_compiled"]

KERNEL_MODES = ("compiled", "numpy")
"""Allowed values of the environment variable ``ROTORLYAP_KERNEL``."""

try:  # numba is a dependency (requirements.txt); the numpy path stays complete without it
    import numba as _numba
except ImportError:  # pragma: no cover - exercised only without numba
    _numba = None

PARALLEL_MIN_STATES = 2048
"""Batches of at least this many states are split over the :func:`threads` threads;
smaller ones run on one thread, where starting the threads would cost more than it saves."""


def numba_available() -> bool:
    """True if numba can be imported."""
    return _numba is not None


def kernel_mode() -> str:
    """The kernel path asked for by ``ROTORLYAP_KERNEL`` (default ``"compiled"``).

    Raises
    ------
    ValueError
        If the variable holds anything but ``"compiled"`` or ``"numpy"``.
    """
    mode = os.environ.get("ROTORLYAP_KERNEL", "compiled").strip().lower() or "compiled"
    if mode not in KERNEL_MODES:
        raise ValueError(f"ROTORLYAP_KERNEL must be one of {KERNEL_MODES}, got {mode!r}")
    return mode


def use_compiled() -> bool:
    """True if the compiled kernels run: numba is installed and ``ROTORLYAP_KERNEL`` allows it."""
    return _numba is not None and kernel_mode() == "compiled"


def jit(fn=None, **options):
    """Compile ``fn`` with numba (``nopython``, cached on disk, releasing the GIL), or return
    it unchanged when numba is not installed.

    ``options`` are further numba options (e.g. ``error_model="numpy"``: a division by zero
    gives inf or nan instead of raising, which lets LLVM vectorise loops with divisions;
    ``inline="always"``); ``jit(**options)`` returns the decorator."""
    if fn is None:
        return lambda f: jit(f, **options)
    if _numba is None:  # pragma: no cover
        return fn
    return _numba.njit(cache=True, nogil=True, **options)(fn)


def threads() -> int:
    """Threads of the kernels over large batches (1 without numba): numba's number of threads,
    which ``NUMBA_NUM_THREADS`` or :func:`numba.set_num_threads` set."""
    return 1 if _numba is None else int(_numba.get_num_threads())
