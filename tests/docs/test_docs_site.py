"""The documentation site: navigation complete and consistent, strict build, paper-reproduction scripts."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

ROOT = Path(__file__).resolve().parents[2]
DOCS = ROOT / "docs"


def nav_pages(node):
    """Every Markdown path named in a mkdocs ``nav`` tree."""
    if isinstance(node, str):
        return [node] if node.endswith(".md") else []
    if isinstance(node, list):
        return [page for item in node for page in nav_pages(item)]
    if isinstance(node, dict):
        return [page for value in node.values() for page in nav_pages(value)]
    return []


def config():
    # mkdocs.yml has no custom tags, so the safe loader reads it.
    return yaml.safe_load((ROOT / "mkdocs.yml").read_text(encoding="utf-8"))


def test_docs_site_nav_pages_exist():
    pages = nav_pages(config()["nav"])
    assert len(pages) > 30
    missing = [p for p in pages if not (DOCS / p).is_file()]
    assert missing == []


def test_docs_site_nav_has_no_duplicates():
    pages = nav_pages(config()["nav"])
    assert sorted(pages) == sorted(set(pages))


def test_docs_site_every_page_is_in_the_nav():
    pages = set(nav_pages(config()["nav"]))
    on_disk = {p.relative_to(DOCS).as_posix() for p in DOCS.rglob("*.md")}
    assert sorted(on_disk - pages) == []


def test_docs_site_is_strict_and_documents_the_source():
    cfg = config()
    assert cfg["strict"] is True
    python = next(p["mkdocstrings"] for p in cfg["plugins"] if isinstance(p, dict) and "mkdocstrings" in p)
    handler = python["handlers"]["python"]
    assert handler["paths"] == ["src"]
    assert handler["options"]["docstring_style"] == "numpy"


def test_docs_site_api_pages_name_importable_objects():
    import importlib

    names = [
        line.split(":::", 1)[1].strip()
        for page in (DOCS / "api").glob("*.md")
        for line in page.read_text(encoding="utf-8").splitlines()
        if line.startswith(":::")
    ]
    assert "andoyer.State" in names
    for name in names:
        module, _, attr = name.rpartition(".")
        try:
            importlib.import_module(name)
        except ModuleNotFoundError:
            assert hasattr(importlib.import_module(module), attr), name


def test_docs_site_benchmarks_page_includes_results():
    text = (DOCS / "benchmarks.md").read_text(encoding="utf-8")
    assert '--8<-- "benchmarks/RESULTS.md"' in text
    assert (ROOT / "benchmarks" / "RESULTS.md").is_file()


def run(args, cwd=ROOT):
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(ROOT / "src"), os.environ.get("PYTHONPATH", "")]))
    env["MPLBACKEND"] = "Agg"
    env["NO_MKDOCS_2_WARNING"] = "1"
    return subprocess.run(
        [sys.executable, *args], cwd=cwd, env=env, capture_output=True, text=True, timeout=1800, check=False
    )


@pytest.mark.slow
def test_docs_site_builds_strict(tmp_path):
    site = tmp_path / "site"
    result = run(
        [
            "-m",
            "mkdocs",
            "build",
            "--strict",
            "--config-file",
            str(ROOT / "mkdocs.yml"),
            "--site-dir",
            str(site),
        ]
    )
    assert result.returncode == 0, result.stderr[-4000:]
    for page in (
        "index.html",
        "install/index.html",
        "tutorials/index.html",
        "tutorials/charts/index.html",
        "reproducing/index.html",
        "conventions/index.html",
        "errata/index.html",
        "benchmarks/index.html",
        "api/core/index.html",
        "api/liepoisson/index.html",
    ):
        assert (site / page).is_file(), page
    core = (site / "api/core/index.html").read_text(encoding="utf-8")
    assert 'id="andoyer.State"' in core
    # The chart methods installed on State from the registry (scripts/griffe_chart_methods.py).
    from andoyer.state.registry import charts

    for name in (n for n, chart in charts().items() if chart.method):
        assert f'id="andoyer.State.from_{name}"' in core, name
        assert f'id="andoyer.State.as_{name}"' in core, name
    # ... with their docstrings parsed as numpy docstrings, as the static ones are.
    section = core.split('id="andoyer.State.from_euler"', 1)[1].split('id="andoyer.State.as_euler"', 1)[0]
    for title in ("Parameters:", "Returns:", "Examples:"):
        assert f'doc-section-title">{title}<' in section, title
    assert "Chart conversions" in (site / "benchmarks/index.html").read_text(encoding="utf-8")


@pytest.mark.slow
def test_docs_site_reproduction_scripts(tmp_path):
    result = run([str(ROOT / "scripts" / "reproduce_papers.py"), "--out", str(tmp_path)])
    assert result.returncode == 0, result.stderr[-4000:]
    for name in ("gurfil_figure1.png", "gurfil_figure4.png", "lara_figure1.png"):
        assert (tmp_path / name).stat().st_size > 10_000, name
    # Lara Table 1: β from eq. 2 equals the printed β to its seven digits; both δ columns agree.
    rows = [
        r.split("|")[1:-1] for r in (tmp_path / "lara_table1.md").read_text(encoding="utf-8").splitlines()
    ]
    body_rows = [
        [c.strip() for c in r] for r in rows if r and r[0].strip() in {"mars", "earth", "moon", "eros"}
    ]
    assert len(body_rows) == 4
    for _, _, _, printed, recomputed, _, delta, delta_chart in body_rows:
        assert abs(float(printed) - float(recomputed)) <= 1e-6
        assert delta == delta_chart
    tables = json.loads((tmp_path / "lara_tables_2_5.json").read_text(encoding="utf-8"))
    assert sorted(tables) == ["L", "g", "l", "q"]
    assert tables["q"]["1"] == {"0": {"0": "1/2"}}
    assert "10" in tables["q"]
    # Pavlov: only eq. 2.12 {l, λ1} fails, and only as printed.
    pavlov = (tmp_path / "pavlov_tables.md").read_text(encoding="utf-8").splitlines()
    failing = [line for line in pavlov if "FAILS" in line]
    assert len(failing) == 1
    assert failing[0].startswith("| 2.12 | {l, lambda1}")
    assert failing[0].rstrip(" |").endswith("proven | proven | FAILS")
    for algebra in ("so3", "e3", "l7"):
        assert "False" not in (tmp_path / f"pavlov_brackets_{algebra}.txt").read_text(encoding="utf-8")
