"""Compare the text a notebook publishes with another version of it (default: git HEAD).

Usage: python tools/compare_outputs.py book/NAME.ipynb [REV]

For a change that restructures a chapter (cells merged or split, code moved into the package)
but must not change a single published number: it lists every glued value (name -> text) and
every printed line that differs between the working copy and ``REV``, whatever cell they are
in. Exit status 0 when both are the same, 1 otherwise. Images are not compared.
"""

from __future__ import annotations

import collections
import json
import subprocess
import sys
from pathlib import Path


def published(nb: dict) -> tuple[dict, collections.Counter]:
    """(glued values by name, multiset of printed lines) of an executed notebook."""
    glued, lines = {}, collections.Counter()
    for cell in nb["cells"]:
        for out in cell.get("outputs", []):
            if out.get("output_type") == "stream":
                lines.update(line.rstrip() for line in "".join(out["text"]).splitlines() if line.strip())
            name = out.get("metadata", {}).get("scrapbook", {}).get("name")
            for mime, value in out.get("data", {}).items():
                text = "".join(value) if isinstance(value, list) else str(value)
                if name and mime.startswith("application/papermill.record/text"):
                    glued[name] = text
                elif not name and mime in ("text/plain", "text/markdown", "text/latex"):
                    lines.update(f"[{mime}] {line.rstrip()}" for line in text.splitlines() if line.strip())
    return glued, lines


def main(argv: list[str]) -> int:
    if not argv or len(argv) > 2:
        print(__doc__)
        return 2
    path, rev = Path(argv[0]), (argv[1] if len(argv) > 1 else "HEAD")
    old = json.loads(subprocess.run(["git", "show", f"{rev}:{path.as_posix()}"], capture_output=True,
                                    text=True, check=True).stdout)
    new = json.loads(path.read_text(encoding="utf-8"))
    (g_old, l_old), (g_new, l_new) = published(old), published(new)
    problems = []
    for name in sorted(set(g_old) | set(g_new)):
        if g_old.get(name) != g_new.get(name):
            problems.append(f"glue {name}: {g_old.get(name)!r} -> {g_new.get(name)!r}")
    for line, n in sorted((l_old - l_new).items()):
        problems.append(f"printed line gone ({n}x): {line}")
    for line, n in sorted((l_new - l_old).items()):
        problems.append(f"printed line new ({n}x): {line}")
    print(f"{path}: {len(g_new)} glued values, {sum(l_new.values())} printed lines; "
          + ("the same as " + rev if not problems else f"{len(problems)} differences from {rev}:"))
    for p in problems:
        print("  " + p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
