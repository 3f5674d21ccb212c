"""How the book's notebooks are executed and compared: once per run, text only.

**Compared as text, never as image bytes.** Strict nbval compares every output but
``image/png`` and ``image/jpeg``; a figure glued with myst-nb's ``glue`` is stored under
``application/papermill.record/image/png``, whose bytes move with round-off. The root
``conftest.py`` adds every MIME type of :data:`IMAGE_MIMES` to nbval's skip list; what proves a
figure reproduced is the short, rounded numeric summary its notebook prints (README, "What a
committed output may print").

**Executed once.** The notebooks are executed for two reasons: nbval compares their printed
outputs with the committed ones (the published numbers are reproduced), and the build renders
them (the HTML and its figures are made from the code as it is). Executing them twice doubles
the cost of a check, so the two share one execution through the build's notebook cache:

* ``python -m pytest`` (nbval) executes each notebook once, in a fresh kernel, and compares
  it; the root ``conftest.py`` then stores every notebook whose cells all ran without an
  error, with its fresh outputs, in the jupyter-cache of the build (:data:`CACHE_DIR`), under
  the hash of its code cells (jupyter-cache's own key);
* the build (``execute_notebooks: cache`` in ``_config.yml``) takes a notebook's outputs from
  that cache when its code cells match, and executes it itself otherwise.

The cache key covers only the notebooks' code, not the package they call: a cached output
made before an edit of ``rotorlyap/`` would be stale. This module therefore stamps the cache
with a :func:`fingerprint` of everything outside the notebooks that their outputs depend on
(the package's source, the pinned requirements, the project metadata) and empties the cache
whenever the stamp differs from the working tree, both before the test run stores into it and
when a build starts (the Sphinx extension below, loaded from ``_config.yml``). A build also
empties it when ``book/_data`` is missing: the notebooks write their figures' CSV files there
as they run, and a cached output would link a file nobody wrote. So the HTML is always made
from outputs of the code as it is, never from stale or committed outputs.
"""

from __future__ import annotations

import hashlib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
"""The project root (this file is ``book/_ext/notebook_execution.py``)."""

CACHE_DIR = ROOT / "_build" / ".jupyter_cache"
"""The build's jupyter-cache: myst-nb's default, ``<build dir>/.jupyter_cache``."""

IMAGE_MIMES = tuple(prefix + "image/" + kind for prefix in ("", "application/papermill.record/")
                    for kind in ("png", "jpeg", "gif", "svg+xml"))
"""Output MIME types that hold an image, plain or stored by ``glue``: never compared."""

STAMP_NAME = "rotorlyap-fingerprint"
"""File in the cache folder that holds the fingerprint its outputs were made with."""

FINGERPRINT_PATTERNS = ("rotorlyap/**/*.py", "requirements.txt", "pyproject.toml")
"""What the notebooks' outputs depend on besides their own code (paths under the root)."""


def fingerprint(root: Path = ROOT) -> str:
    """SHA-256 of the files of :data:`FINGERPRINT_PATTERNS`, names and contents, in sorted order."""
    digest = hashlib.sha256()
    files = sorted({p for pattern in FINGERPRINT_PATTERNS for p in root.glob(pattern) if p.is_file()})
    for path in files:
        digest.update(path.relative_to(root).as_posix().encode() + b"\0")
        digest.update(path.read_bytes() + b"\0")
    return digest.hexdigest()


def refresh(cache_dir: Path = CACHE_DIR, root: Path = ROOT, *, force_clear: bool = False,
            current: str | None = None) -> bool:
    """Empty the cache unless its stamp matches ``current`` (default: the working tree's
    :func:`fingerprint`); stamp it with ``current``. True if it was emptied."""
    current = fingerprint(root) if current is None else current
    stamp = cache_dir / STAMP_NAME
    stale = force_clear or not (stamp.is_file() and stamp.read_text().strip() == current)
    if stale and cache_dir.exists():
        import shutil

        shutil.rmtree(cache_dir)
    cache_dir.mkdir(parents=True, exist_ok=True)
    stamp.write_text(current + "\n")
    return stale


def store(notebooks, cache_dir: Path = CACHE_DIR, root: Path = ROOT, *,
          executed_with: str | None = None) -> list[str]:
    """Store executed notebooks in the cache, after :func:`refresh`; return their names.

    Parameters
    ----------
    notebooks : iterable of (path, notebook, seconds)
        The notebook's source path, the notebook (``nbformat.NotebookNode``) with the fresh
        outputs of one top-to-bottom execution, and the execution time in seconds.
    executed_with : str, optional
        The :func:`fingerprint` of the tree the notebooks were executed with, taken when the
        execution started (default: the tree now). Should the package change during the
        run, the cache is stamped with the old tree and the next build empties it.
    """
    from jupyter_cache import get_cache
    from jupyter_cache.base import CacheBundleIn

    notebooks = list(notebooks)
    if not notebooks:
        return []
    refresh(cache_dir, root, current=executed_with)
    cache = get_cache(str(cache_dir))
    names = []
    for path, nb, seconds in notebooks:
        cache.cache_notebook_bundle(
            CacheBundleIn(nb, str(path), data={"execution_seconds": seconds, "executed_by": "nbval"}),
            check_validity=False, overwrite=True)
        names.append(Path(path).name)
    return names


def _check_cache(app) -> None:
    """Sphinx ``builder-inited``: empty a stale cache before myst-nb reads it."""
    from sphinx.util import logging

    logger = logging.getLogger(__name__)
    cache_dir = Path(app.outdir).parent / ".jupyter_cache"
    data_missing = not (Path(app.srcdir) / "book" / "_data").is_dir()
    if refresh(cache_dir, Path(app.srcdir), force_clear=data_missing):
        reason = "book/_data is missing" if data_missing else "the package or requirements changed"
        logger.info(f"notebook cache emptied ({reason}): every notebook is executed by this build")
    else:
        logger.info("notebook cache is current: notebooks executed by the last test run are reused")


def setup(app):
    """Register the stale-cache check, before myst-nb sets up its cache (priority 400 < 500)."""
    app.connect("builder-inited", _check_cache, priority=400)
    return {"version": "1.0", "parallel_read_safe": True, "parallel_write_safe": True}
