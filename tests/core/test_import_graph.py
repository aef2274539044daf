"""The package's import graph: lower layers never import higher ones, so it has no cycles.

Every import counts, also one inside a function (a late import that hides a cycle is still a
cycle); only ``if TYPE_CHECKING:`` blocks are left out. ``from andoyer.x import y`` counts as an
import of the module ``andoyer.x.y`` when that is a submodule, else of ``andoyer.x`` itself.
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


def _modules() -> dict[str, Path]:
    return WALK.modules(SOURCE)


def test_strongly_connected_finds_a_planted_cycle():
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}, "e": set()}
    assert strongly_connected(graph) == [{"a", "b", "c"}]


def test_import_graph_cycles_only_known():
    modules = _modules()
    graph = {name: _imports(name, path, set(modules)) for name, path in modules.items()}
    cycles = strongly_connected(graph)
    assert sorted(map(sorted, cycles)) == sorted(map(sorted, KNOWN_CYCLES))


def test_import_graph_sees_known_edges():
    modules = _modules()
    known = set(modules)
    assert "andoyer.charts.euler" in _imports("andoyer.state", modules["andoyer.state"], known)
    # a function-level import counts too
    assert "andoyer.free.motion" in _imports("andoyer.state_charts", modules["andoyer.state_charts"], known)
