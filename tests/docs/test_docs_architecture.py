"""docs/architecture.md: its layer table is the one scripts/architecture.py draws from the import graph."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PAGE = ROOT / "docs" / "architecture.md"


def _script():
    spec = importlib.util.spec_from_file_location("architecture_script", ROOT / "scripts" / "architecture.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


ARCHITECTURE = _script()

#: A package ``p`` drawn by hand: ``p.group`` gathers ``a`` and ``b`` (its ``__init__`` imports
#: neither); the package ``p.x`` and the module ``p.y`` import each other through ``p.x.m`` and
#: ``p.x.n``, so ``p.x`` is shown split into its members.
GRAPH = {
    "p": set(),
    "p.low": set(),
    "p.group": set(),
    "p.group.a": {"p.low"},
    "p.group.b": {"p.group.a"},
    "p.x": {"p.x.m"},
    "p.x.m": {"p.y"},
    "p.y": {"p.x.n"},
    "p.x.n": {"p.low"},
}


def test_docs_architecture_layers_are_current():
    text = PAGE.read_text(encoding="utf-8")
    assert ARCHITECTURE.section(text) == ARCHITECTURE.render(ROOT / "src" / "andoyer"), (
        f"docs/architecture.md is stale: run `{ARCHITECTURE.COMMAND}` and commit the page"
    )


def test_docs_architecture_units_split_a_cycle_and_a_gathering_package():
    unit = ARCHITECTURE.units(GRAPH, "p")
    assert unit == {name: name for name in GRAPH if name != "p"}
    assert ARCHITECTURE.layers(GRAPH, unit) == {
        "p.low": 0,
        "p.group": 0,
        "p.group.a": 1,
        "p.group.b": 2,
        "p.x.n": 1,
        "p.y": 2,
        "p.x.m": 3,
        "p.x": 4,
    }


def test_docs_architecture_package_without_a_cycle_is_one_unit():
    graph = {"p": set(), "p.low": set(), "p.x": {"p.x.m"}, "p.x.m": {"p.low"}, "p.x.n": {"p.x.m"}}
    unit = ARCHITECTURE.units(graph, "p")
    assert unit == {"p.low": "p.low", "p.x": "p.x", "p.x.m": "p.x", "p.x.n": "p.x"}
    assert ARCHITECTURE.layers(graph, unit) == {"p.low": 0, "p.x": 1}


def test_docs_architecture_summary_reads_roles_as_sphinx_shows_them(tmp_path):
    path = tmp_path / "m.py"
    path.write_text('"""See :func:`~a.b.c` and :mod:`x.y`: ``|u|`` | bar.\n\nMore."""\n', encoding="utf-8")
    assert ARCHITECTURE.summary(path) == r"See `c` and `x.y`: `|u|` \| bar."


@pytest.mark.slow
def test_docs_architecture_check_says_the_command(tmp_path, capsys):
    page = tmp_path / "architecture.md"
    text = PAGE.read_text(encoding="utf-8")
    stale = text.replace(ARCHITECTURE.section(text), "| an old table |\n")
    page.write_text(stale, encoding="utf-8")
    assert ARCHITECTURE.main(["--check", "--page", str(page)]) == 1
    assert "stale: run `python3 scripts/architecture.py`" in capsys.readouterr().err
    assert page.read_text(encoding="utf-8") == stale  # --check writes nothing
    assert ARCHITECTURE.main(["--page", str(page)]) == 0
    assert page.read_text(encoding="utf-8") == text
    assert ARCHITECTURE.main(["--check", "--page", str(page)]) == 0


def test_docs_architecture_page_without_markers_raises(tmp_path):
    page = tmp_path / "architecture.md"
    page.write_text("# Architecture\n", encoding="utf-8")
    with pytest.raises(ValueError, match="expected the markers"):
        ARCHITECTURE.main(["--page", str(page)])
