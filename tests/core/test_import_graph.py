"""The package's import graph: lower layers never import higher ones, so it has no cycles.

Every import counts: one inside a function (a late import that hides a cycle is still a
cycle), one made only for type checking (in an ``if TYPE_CHECKING:`` block: a type hint
that names a higher layer ties the layers as much as a call does) and
``importlib.import_module("andoyer.x")`` of a literal name. ``from andoyer.x import y``
counts as an import of the module ``andoyer.x.y`` when that is a submodule, else of
``andoyer.x`` itself.
"""

from __future__ import annotations

import ast
from pathlib import Path

import andoyer

SOURCE = Path(andoyer.__file__).parent

#: Cycles still to be untangled: none. The test fails when one disappears as well, so that
#: this list only shrinks.
KNOWN_CYCLES: list[set[str]] = []

#: Upward imports kept for one release, each with its reason; left out of the graph. The test
#: fails when one is no longer made, so that this list only shrinks.
EXEMPT_EDGES: dict[tuple[str, str], str] = {
    ("andoyer.free", "andoyer.free_rotation"): (
        "andoyer.free.FreeRotation, deprecated: FreeRotation moved above the state package; the "
        "package's __getattr__ serves the old name with a DeprecationWarning until the next release"
    ),
}

def _modules() -> dict[str, Path]:
    out = {}
    for path in SOURCE.rglob("*.py"):
        parts = path.relative_to(SOURCE.parent).with_suffix("").parts
        name = ".".join(parts[:-1] if parts[-1] == "__init__" else parts)
        out[name] = path
    return out


def _imported_by_name(node: ast.AST) -> bool:
    """Whether ``node`` is ``importlib.import_module("<a literal name>")``."""
    return (
        isinstance(node, ast.Call)
        and getattr(node.func, "attr", getattr(node.func, "id", "")) == "import_module"
        and bool(node.args)
        and isinstance(node.args[0], ast.Constant)
        and isinstance(node.args[0].value, str)
    )


def _imports(name: str, path: Path, known: set[str]) -> set[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found.update(alias.name for alias in node.names)
        elif _imported_by_name(node):
            found.add(node.args[0].value)
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                parent = package.split(".")[: len(package.split(".")) - node.level + 1]
                base = ".".join([*parent, base] if base else parent)
            for alias in node.names:
                # A submodule imported by name is an edge to it alone; any other name comes
                # from the package's (or module's) own namespace.
                submodule = f"{base}.{alias.name}"
                found.add(submodule if submodule in known else base)
    return {target for target in found if target in known and target != name}


def strongly_connected(graph: dict[str, set[str]]) -> list[set[str]]:
    """Tarjan's strongly connected components with more than one member."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    out: list[set[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in graph[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = set()
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.add(w)
                if w == v:
                    break
            if len(component) > 1:
                out.append(component)

    for v in graph:
        if v not in index:
            visit(v)
    return out


def test_strongly_connected_finds_a_planted_cycle():
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}, "e": set()}
    assert strongly_connected(graph) == [{"a", "b", "c"}]


def _graph() -> dict[str, set[str]]:
    modules = _modules()
    return {name: _imports(name, path, set(modules)) for name, path in modules.items()}


def test_import_graph_cycles_only_known():
    graph = _graph()
    for source, target in EXEMPT_EDGES:
        graph[source].discard(target)
    cycles = strongly_connected(graph)
    assert sorted(map(sorted, cycles)) == sorted(map(sorted, KNOWN_CYCLES))


def test_import_graph_exempt_edges_still_made():
    graph = _graph()
    assert [edge for edge in EXEMPT_EDGES if edge[1] not in graph[edge[0]]] == []


def _reachable(graph: dict[str, set[str]], start: str) -> set[str]:
    seen, todo = set(), [start]
    while todo:
        for target in graph[todo.pop()] - seen:
            seen.add(target)
            todo.append(target)
    return seen


def test_import_graph_exempt_edges_point_upward():
    # An exemption is for an upward import: its target depends, through the graph without the
    # exempt edges, on the source's package (free_rotation on andoyer.free.motion).
    graph = _graph()
    for source, target in EXEMPT_EDGES:
        graph[source].discard(target)
    for source, target in EXEMPT_EDGES:
        below = {m for m in _reachable(graph, target) if m == source or m.startswith(source + ".")}
        assert below, (source, target)


def test_import_graph_sees_known_edges():
    modules = _modules()
    known = set(modules)
    # the package's __init__ imports its chart modules; the hub imports none of them
    assert "andoyer.state.euler" in _imports("andoyer.state", modules["andoyer.state"], known)
    hub = _imports("andoyer.state.hub", modules["andoyer.state.hub"], known)
    assert hub & {"andoyer.state.euler", "andoyer.state.andoyer", "andoyer.state.sadov"} == set()
    # a function-level import counts too
    assert "andoyer.free.motion" in hub


def test_import_graph_counts_type_checking_imports(tmp_path):
    module = tmp_path / "typed.py"
    module.write_text(
        "from typing import TYPE_CHECKING\n"
        "if TYPE_CHECKING:\n"
        "    from andoyer.state import State\n",
        encoding="utf-8",
    )
    assert _imports("andoyer.typed", module, {"andoyer.state", "andoyer.typed"}) == {"andoyer.state"}


def test_import_graph_counts_import_module_of_a_literal(tmp_path):
    module = tmp_path / "late.py"
    module.write_text(
        "import importlib\n"
        "def f():\n"
        "    return importlib.import_module('andoyer.state')\n",
        encoding="utf-8",
    )
    assert _imports("andoyer.late", module, {"andoyer.state", "andoyer.late"}) == {"andoyer.state"}
