"""Progress of long computations, told to whoever listens; silent unless someone does.

The package's long calls (:func:`rotorlyap.certify`: the trim, the steady motion, each candidate
function, the design program's attempts and rounds, the sound rule's bounds and its final check)
say which stage they are in with :func:`report`. Nobody listens by default, so a library call, a
test or a notebook prints nothing. The command line listens while it works
(:func:`listening` with a :class:`Bar` on a terminal's standard error, a line per stage
otherwise), so a user sees what stage the work is in and how far it has got; nothing of it goes
to standard output, where the JSON result is printed.

The listener is held in a :class:`contextvars.ContextVar`: a thread or a worker process started
inside :func:`listening` does not inherit it (those report nothing), and nesting restores the
outer listener on exit. Blade-free: every layer may report.
"""

from __future__ import annotations

import sys
from contextlib import contextmanager
from contextvars import ContextVar
from typing import Callable, Iterator, TextIO

__all__ = ["Bar", "Lines", "listening", "report"]

Listener = Callable[[str, "int | None", "int | None"], None]

_LISTENER: ContextVar[Listener | None] = ContextVar("rotorlyap_progress", default=None)


def report(stage: str, done: int | None = None, total: int | None = None) -> None:
    """Tell the listener (if any) the current stage, and how far it has got.

    Parameters
    ----------
    stage : str
        What is being done, a few words ("design: start radius 3.2, round 2").
    done, total : int, optional
        Steps done of ``total`` in this stage (``total`` None: unknown).
    """
    listener = _LISTENER.get()
    if listener is not None:
        listener(stage, done, total)


@contextmanager
def listening(listener: Listener) -> Iterator[Listener]:
    """Within the block, :func:`report` calls ``listener(stage, done, total)``; a listener with a
    ``close()`` method is closed on exit."""
    if not callable(listener):
        raise TypeError(f"listener must be callable (stage, done, total), got {type(listener).__name__}")
    token = _LISTENER.set(listener)
    try:
        yield listener
    finally:
        _LISTENER.reset(token)
        close = getattr(listener, "close", None)
        if close is not None:
            close()


class Lines:
    """A listener that writes one line per new stage to ``stream`` (default: standard error), for a
    log or a pipe: no carriage returns, no repeated lines for steps within a stage."""

    def __init__(self, stream: TextIO | None = None, prefix: str = ""):
        self.stream = stream if stream is not None else sys.stderr
        self.prefix = prefix
        self._last: str | None = None

    def __call__(self, stage: str, done: int | None = None, total: int | None = None) -> None:
        if stage != self._last:
            self._last = stage
            print(f"{self.prefix}{stage}", file=self.stream, flush=True)

    def close(self) -> None:
        self._last = None


class Bar:
    """A listener that draws a progress bar on a terminal (``tqdm``, on standard error by default):
    the stage as its description, the steps as its count; a new stage starts a new bar, the last
    one is left on screen."""

    def __init__(self, stream: TextIO | None = None):
        from tqdm import tqdm  # imported here: only the command line on a terminal needs it

        self._tqdm = tqdm
        self.stream = stream if stream is not None else sys.stderr
        self._bar = None
        self._stage: str | None = None

    def __call__(self, stage: str, done: int | None = None, total: int | None = None) -> None:
        if stage != self._stage or self._bar is None or (total is not None and self._bar.total != total):
            if self._bar is not None:
                self._bar.close()
            self._stage = stage
            self._bar = self._tqdm(total=total, desc=stage, file=self.stream, leave=False, dynamic_ncols=True,
                                   bar_format="{desc}: {n_fmt}/{total_fmt} [{elapsed}]" if total else "{desc} [{elapsed}]")
        if done is not None:
            self._bar.n = done
            self._bar.refresh()

    def close(self) -> None:
        if self._bar is not None:
            self._bar.close()
            self._bar = None
