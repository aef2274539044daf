"""The package's import graph: lower layers never import higher ones, so it has no cycles.

Every import counts: one inside a function (a late import that hides a cycle is still a
cycle), one made only for type checking (in an ``if TYPE_CHECKING:`` block: a type hint
that names a higher layer ties the layers as much as a call does) and
``importlib.import_module("andoyer.x")`` of a literal name. ``from andoyer.x import y``
counts as an import of the module ``andoyer.x.y`` when that is a submodule, else of
``andoyer.x`` itself.
"""

from __future__ import annotations

import importlib.util
from pathlib import Path

import andoyer


def _walk():
    """``scripts/architecture.py``: the one walk of the import graph (it also draws the layers)."""
    path = Path(__file__).resolve().parents[2] / "scripts" / "architecture.py"
    spec = importlib.util.spec_from_file_location("architecture_script", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


WALK = _walk()
SOURCE = Path(andoyer.__file__).parent

#: Cycles still to be untangled: none. The test fails when one disappears as well, so that
#: this list only shrinks.
KNOWN_CYCLES: list[set[str]] = []
strongly_connected = WALK.strongly_connected
_imports = WALK.imports
#: Upward imports kept for one release, each with its reason (listed with the walk, which leaves
#: them out of the layers too): andoyer.free -> andoyer.free_rotation, the deprecated name
#: andoyer.free.FreeRotation.
EXEMPT_EDGES = WALK.EXEMPT_EDGES

def _modules() -> dict[str, Path]:
    return WALK.modules(SOURCE)


def test_strongly_connected_finds_a_planted_cycle():
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}, "e": set()}
    assert strongly_connected(graph) == [{"a", "b", "c"}]


def _graph() -> dict[str, set[str]]:
    """The whole graph, the exempt edges included."""
    modules = _modules()
    return {name: _imports(name, path, set(modules)) for name, path in modules.items()}


def test_import_graph_exempt_edges_listed():
    assert sorted(EXEMPT_EDGES) == [("andoyer.free", "andoyer.free_rotation")]
    assert all(len(reason) > 40 for reason in EXEMPT_EDGES.values())
    graph = WALK.import_graph(SOURCE)
    assert "andoyer.free_rotation" not in graph["andoyer.free"]


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
