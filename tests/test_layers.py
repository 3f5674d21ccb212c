"""The package's layers hold: data flows one way, and no module imports itself in a circle.

    conventions, errors, jit, progress, reporting  (shared, depend on nothing of the package)
    methods   (the general method)  may use: shared
    model     (the blade)           may use: shared
    analysis  (blade in methods)    may use: shared, methods, model
    chapters, cli                   may use: everything below

The import graph is read from the source (every import statement, also those inside
functions), so a lazy import cannot hide a circle.
"""

from __future__ import annotations

import ast
import json
import re
import subprocess
import sys
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "rotorlyap"

ALLOWED = {
    "shared": set(),
    "methods": {"shared"},
    "model": {"shared"},
    "analysis": {"shared", "methods", "model"},
    "chapters": {"shared", "methods", "model", "analysis"},
    "cli": {"shared", "methods", "model", "analysis", "chapters"},
}


def _module_name(path: Path) -> str:
    parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _modules() -> dict[str, Path]:
    return {_module_name(p): p for p in PACKAGE.rglob("*.py") if "_generated" not in p.parts}


def _imports(name: str, path: Path, known: set[str]) -> set[str]:
    """Package modules imported by ``name`` (absolute names), from every import statement."""
    package = name if path.name == "__init__.py" else name.rsplit(".", 1)[0]
    found = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            found |= {a.name for a in node.names if a.name.startswith("rotorlyap")}
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")
                base = base[: len(base) - (node.level - 1)]
                target = ".".join(base + ([node.module] if node.module else []))
            else:
                target = node.module or ""
            if not target.startswith("rotorlyap"):
                continue
            found.add(target)
            found |= {f"{target}.{a.name}" for a in node.names if f"{target}.{a.name}" in known}
    return {m for m in found if m in known and m != name}


def _layer(name: str) -> str:
    parts = name.split(".")
    if len(parts) == 1:
        return "package"
    head = parts[1]
    if head in ("conventions", "errors", "jit", "progress", "reporting"):
        return "shared"
    if head == "__main__":
        return "cli"
    return head


@pytest.fixture(scope="module")
def graph() -> dict[str, set[str]]:
    mods = _modules()
    return {name: _imports(name, path, set(mods)) for name, path in mods.items()}


def test_every_module_belongs_to_a_known_layer(graph):
    assert {_layer(m) for m in graph} <= set(ALLOWED) | {"package"}


def test_each_layer_imports_only_the_layers_below_it(graph):
    bad = [f"{m} imports {t}" for m, targets in graph.items() for t in targets
           if _layer(m) in ALLOWED and _layer(t) != _layer(m) and _layer(t) not in ALLOWED[_layer(m)]]
    assert not bad, "\n".join(bad)


def test_the_import_graph_has_no_circle(graph):
    # depth-first search for a back edge; package __init__ files re-export their modules, so
    # an edge from a module to its own package is the module importing a sibling through it
    state: dict[str, int] = {}
    stack: list[str] = []
    cycles = []

    def visit(m: str) -> None:
        state[m] = 1
        stack.append(m)
        for t in sorted(graph[m]):
            if state.get(t) == 1:
                cycles.append(" -> ".join(stack[stack.index(t):] + [t]))
            elif t not in state:
                visit(t)
        stack.pop()
        state[m] = 2

    for m in sorted(graph):
        if m not in state:
            visit(m)
    assert not cycles, "import circles:\n" + "\n".join(cycles)


def test_importing_the_general_method_loads_nothing_of_the_blade():
    code = ("import sys, rotorlyap.methods; "
            "print(sorted(m for m in sys.modules if m.startswith(('rotorlyap.model', 'rotorlyap.analysis', "
            "'rotorlyap.chapters'))))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"


def test_the_package_top_level_loads_its_names_on_first_use():
    code = ("import sys, rotorlyap; before = {m for m in sys.modules if m.startswith('rotorlyap.')}; "
            "rotorlyap.blade_stability; after = {m for m in sys.modules if m.startswith('rotorlyap.')}; "
            "print(sorted(before), 'rotorlyap.analysis.stability' in after)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[] True"


# --- the top floor arranged by the book (issue 43) ------------------------------------------

MAX_MODULE_LINES = 1500
BOOK = PACKAGE.parent / "book"
# the line under a chapter's title that names the module its computations live in, e.g.
# "*Computed in {doc}`rotorlyap.chapters.hover <api/rotorlyap.chapters.hover>`*"
_NAMED = re.compile(r"^\*Computed in \{doc\}`(rotorlyap\.chapters\.\w+) <api/\1>`\.?\*$", re.M)


def _chapter_modules() -> dict[str, str]:
    """Notebook name -> the module its first cell names under the title."""
    named = {}
    for nb in sorted(BOOK.glob("*.ipynb")):
        first = "".join(json.loads(nb.read_text())["cells"][0]["source"])
        found = _NAMED.findall(first)
        named[nb.name] = found[0] if len(found) == 1 else None
    return named


def _inside(module: str, target: str) -> bool:
    return target == module or target.startswith(module + ".")


def test_no_module_is_longer_than_the_limit():
    """A module a newcomer can read: none above 1,500 lines (the generated equations excepted)."""
    long = {name: n for name, path in _modules().items()
            if (n := len(path.read_text().splitlines())) > MAX_MODULE_LINES}
    assert not long, f"modules above {MAX_MODULE_LINES} lines: {long}"


def test_each_chapter_names_the_one_module_its_computations_live_in():
    named = _chapter_modules()
    missing = [nb for nb, m in named.items() if m is None]
    assert not missing, ("chapters without the line under their title naming their module "
                         f"('*Computed in {{doc}}`rotorlyap.chapters.X <api/rotorlyap.chapters.X>`*'): {missing}")
    mods = _modules()
    unknown = {nb: m for nb, m in named.items() if m not in mods}
    assert not unknown, f"chapters naming a module that does not exist: {unknown}"


def test_a_chapter_module_imports_no_other_chapters_module(graph):
    """A chapter's module (with its submodules) uses no other chapter's module, directly or
    through a shared module: a change to one chapter's experiments stays in that chapter. (The
    command line's figures, ``chapters.commands``, draw several chapters: no chapter uses it.)"""
    chapters = set(_chapter_modules().values()) - {None}
    bad = []
    for own in sorted(chapters):
        seen, todo = set(), [m for m in graph if _inside(own, m)]
        while todo:
            m = todo.pop()
            for t in graph[m]:
                if t in seen or not t.startswith("rotorlyap.chapters"):
                    continue
                seen.add(t)
                other = next((c for c in chapters if _inside(c, t)), None)
                if other is not None and other != own:
                    bad.append(f"{own} uses {t} (through {m}), another chapter's module")
                elif other is None:
                    todo.append(t)
    assert not bad, "\n".join(bad)


def test_a_notebook_calls_only_its_own_chapter_module_and_shared_ones():
    chapters = set(_chapter_modules().values()) - {None}
    bad = []
    for nb, own in _chapter_modules().items():
        code = "\n".join("".join(c["source"]) for c in json.loads((BOOK / nb).read_text())["cells"]
                         if c["cell_type"] == "code")
        used = set()
        for node in ast.walk(ast.parse("\n".join(l for l in code.splitlines() if not l.startswith(("%", "!"))))):
            if isinstance(node, ast.ImportFrom) and (node.module or "").startswith("rotorlyap.chapters"):
                used |= {node.module} | {f"{node.module}.{a.name}" for a in node.names}
            elif isinstance(node, ast.Import):
                used |= {a.name for a in node.names if a.name.startswith("rotorlyap.chapters")}
        for t in used:
            other = next((c for c in chapters if _inside(c, t)), None)
            if other is not None and other != own:
                bad.append(f"{nb} uses {t}, another chapter's module")
    assert not bad, "\n".join(bad)
