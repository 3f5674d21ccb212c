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
