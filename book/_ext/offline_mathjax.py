"""Serve MathJax 3 from the built book itself, so that equations render with no network.

Sphinx points ``mathjax_path`` at a CDN by default; a reader who opens ``_build/html``
offline (or CI, which reaches only the package registries) would then see raw TeX. This
extension, loaded through ``sphinx: local_extensions`` in ``_config.yml``, makes the build
self-contained:

* at ``builder-inited`` (HTML builders only) it makes sure the npm package ``mathjax`` at the
  pinned version :data:`MATHJAX_VERSION` is installed under ``_build/.mathjax/`` (never
  committed; ``rm -rf _build`` removes it, the next build installs it again, in about a
  second), by ``npm install --no-save --prefix _build/.mathjax/npm mathjax@VERSION``;
* it copies the package's ``es5`` directory (the browser build: ``tex-chtml.js``, the CHTML
  fonts, the TeX extensions MathJax autoloads) and its licence to
  ``_build/.mathjax/static/mathjax/``, adds ``_build/.mathjax/static`` to
  ``html_static_path`` (so it lands in ``_build/html/_static/mathjax/``), and
* sets ``mathjax_path`` to ``mathjax/tex-chtml.js``, which Sphinx resolves relative to
  ``_static``.

Node.js and npm are needed at build time; without them, or if npm fails, the build stops
with a message that says so (a book whose equations need the network is not the book we
publish). The installed version is checked against the pin.
"""

from __future__ import annotations

import json
import shutil
import subprocess
import time
from pathlib import Path

from sphinx.application import Sphinx
from sphinx.errors import ExtensionError
from sphinx.util import logging

MATHJAX_VERSION = "3.2.2"
"""Exact version of the npm package ``mathjax`` served with the book."""

MATHJAX_ENTRY = "tex-chtml.js"
"""The combined component loaded by every page: TeX input, CommonHTML output."""

logger = logging.getLogger(__name__)


def cache_dir(srcdir: str | Path) -> Path:
    """Where the package is installed and staged: ``<book root>/_build/.mathjax``."""
    return Path(srcdir) / "_build" / ".mathjax"


def _installed_version(package_dir: Path) -> str | None:
    try:
        return json.loads((package_dir / "package.json").read_text())["version"]
    except (OSError, ValueError, KeyError):
        return None


def ensure_mathjax(root: Path, version: str = MATHJAX_VERSION) -> Path:
    """Install ``mathjax@version`` under ``root`` if needed; return the staged static dir.

    The returned directory contains one folder, ``mathjax/``, with the contents of the
    package's ``es5`` build and its ``LICENSE``.
    """
    prefix = root / "npm"
    package = prefix / "node_modules" / "mathjax"
    static = root / "static"
    staged = static / "mathjax"
    stamp = staged / ".version"
    if stamp.is_file() and stamp.read_text().strip() == version and (staged / MATHJAX_ENTRY).is_file():
        return static

    if _installed_version(package) != version:
        npm = shutil.which("npm")
        if npm is None:
            raise ExtensionError(
                "offline MathJax: `npm` was not found on PATH. The book serves MathJax "
                f"{version} from the npm package `mathjax` so that equations render offline; "
                "install Node.js and npm (Debian: `apt-get install nodejs npm`) and build again."
            )
        prefix.mkdir(parents=True, exist_ok=True)
        cmd = [npm, "install", "--no-save", "--no-package-lock", "--no-audit", "--no-fund",
               "--prefix", str(prefix), f"mathjax@{version}"]
        start = time.perf_counter()
        try:
            proc = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
        except (OSError, subprocess.TimeoutExpired) as exc:
            raise ExtensionError(f"offline MathJax: `{' '.join(cmd)}` failed: {exc}") from exc
        if proc.returncode != 0:
            tail = "\n".join((proc.stdout + proc.stderr).strip().splitlines()[-15:])
            raise ExtensionError(
                f"offline MathJax: `{' '.join(cmd)}` exited with {proc.returncode}:\n{tail}"
            )
        found = _installed_version(package)
        if found != version:
            raise ExtensionError(
                f"offline MathJax: npm installed mathjax {found!r} in {package}, expected {version}"
            )
        logger.info("offline MathJax: installed mathjax %s with npm in %.1f s",
                    version, time.perf_counter() - start)

    es5 = package / "es5"
    if not (es5 / MATHJAX_ENTRY).is_file():
        raise ExtensionError(f"offline MathJax: {es5 / MATHJAX_ENTRY} is missing after install")
    if staged.exists():
        shutil.rmtree(staged)
    shutil.copytree(es5, staged)
    shutil.copy2(package / "LICENSE", staged / "LICENSE")
    stamp.write_text(version + "\n")
    return static


def _builder_inited(app: Sphinx) -> None:
    if app.builder.format != "html":
        return
    static = ensure_mathjax(cache_dir(app.srcdir))
    # html_static_path was validated at config-inited; the entry exists now, and Sphinx
    # copies the contents of each entry into _static at the end of the build.
    app.config.html_static_path = [*app.config.html_static_path, str(static)]
    app.config.mathjax_path = f"mathjax/{MATHJAX_ENTRY}"


def setup(app: Sphinx) -> dict:
    app.setup_extension("sphinx.ext.mathjax")
    app.connect("builder-inited", _builder_inited)
    return {"version": MATHJAX_VERSION, "parallel_read_safe": True, "parallel_write_safe": True}
