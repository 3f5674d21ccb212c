"""Execute notebooks in place, top to bottom, each in a fresh kernel, keeping the outputs.

Usage: python tools/run_notebooks.py [-j JOBS] [book/NAME.ipynb ...]   (default: every book notebook)

This is how the committed notebooks are produced, so that strict nbval compares real,
current outputs. Notebooks run ``JOBS`` at a time (default: one per CPU, at most one per
notebook), each in its own kernel; the longest first, by the size of the file, as a guess.
Run it in the ordinary environment of your machine, not under the perturbed floating-point
environment that CI compares in (README, "What a committed output may print").
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from concurrent.futures import ProcessPoolExecutor, as_completed
from pathlib import Path

import nbformat
from nbclient import NotebookClient

ROOT = Path(__file__).resolve().parents[1]


def run(path: Path) -> float:
    """Execute one notebook in place from a fresh kernel; return the wall time in seconds."""
    nb = nbformat.read(path, as_version=4)
    start = time.perf_counter()
    # record_timing=False: no execution timestamps in the cells' metadata (volatile text that
    # would change every committed notebook on every run)
    NotebookClient(nb, timeout=3600, kernel_name="python3", record_timing=False,
                   resources={"metadata": {"path": str(path.parent)}}).execute()
    nbformat.write(nb, path)
    return time.perf_counter() - start


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("notebooks", nargs="*", type=Path, help="notebooks to execute (default: book/*.ipynb)")
    parser.add_argument("-j", "--jobs", type=int, default=os.cpu_count() or 1,
                        help="notebooks executed at a time (default: the number of CPUs)")
    args = parser.parse_args(argv)
    if args.jobs < 1:
        parser.error(f"--jobs must be at least 1, got {args.jobs}")
    os.environ.setdefault("PYTHONHASHSEED", "0")
    paths = [p.resolve() for p in args.notebooks] or sorted((ROOT / "book").glob("*.ipynb"))
    missing = [str(p) for p in paths if not p.is_file()]
    if missing:
        parser.error(f"no such notebook: {', '.join(missing)}")
    paths.sort(key=lambda p: -p.stat().st_size)
    with ProcessPoolExecutor(max_workers=min(args.jobs, len(paths))) as pool:
        futures = {pool.submit(run, p): p for p in paths}
        for fut in as_completed(futures):
            print(f"{futures[fut].relative_to(ROOT)}: {fut.result():.1f} s", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
