"""The layout of andoyer.free: one naming rule for backends, and names no other package uses.

In every folder of ``andoyer/free``, ``<step>.py`` holds the kernels of a step (each formula
written once, registered for numba) and ``<step>_<backend>.py`` its drivers, ``<backend>`` one
of :data:`andoyer.free.backends.BACKENDS`; no module says its backend any other way (a
``compiled_`` prefix, a ``kernels`` folder). A compiled driver defines compiled loops, a numpy
driver none, and a step with drivers on both backends has its kernels. No module of the free
solution has the name of a module outside it.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

import andoyer
from andoyer.free.backends import BACKENDS

SOURCE = Path(andoyer.__file__).parent
FREE = SOURCE / "free"


def _relative(root: Path) -> list[str]:
    return sorted(str(p.relative_to(root)) for p in root.rglob("*.py"))


def _backend_words(paths: list[str]) -> list[str]:
    """Paths that say a backend other than as the last word ``_<backend>`` of a file's name."""
    other = {"kernel", "kernels", "lean", "numba", "jit", "vectorised"}
    found = []
    for path in paths:
        parts = Path(path).with_suffix("").parts
        words = [w for part in parts for w in part.split("_")]
        if other & set(words) or set(BACKENDS) & set(words[:-1]):
            found.append(path)
    return found


def _decorators(path: Path) -> set[str]:
    """Names of the decorators of the module's top-level functions (``jit``, ``jitable``, ...)."""
    out = set()
    for node in ast.parse(path.read_text(encoding="utf-8")).body:
        if isinstance(node, ast.FunctionDef):
            for decorator in node.decorator_list:
                d = decorator.func if isinstance(decorator, ast.Call) else decorator
                out.add(d.id if isinstance(d, ast.Name) else getattr(d, "attr", ""))
    return out


def test_free_layout_backend_words_find_planted_names():
    planted = ["compiled_setup.py", "kernels/uniform.py", "lean.py", "uniform/numpy_setup.py", "jit/setup.py"]
    fine = ["triaxial/setup.py", "triaxial/setup_compiled.py", "uniform/evaluate_numpy.py", "step_scalar.py"]
    assert _backend_words(planted + fine) == planted


def test_free_layout_backends_only_as_suffix():
    assert _backend_words(_relative(FREE)) == []


def test_free_layout_drivers_compile_only_on_the_compiled_backend():
    paths = [FREE / p for p in _relative(FREE)]
    compiled = [p for p in paths if p.stem.endswith("_compiled")]
    numpy = [p for p in paths if p.stem.endswith("_numpy")]
    assert len(compiled) >= 5
    assert len(numpy) >= 5
    assert all("jit" in _decorators(p) for p in compiled)
    assert not any(_decorators(p) & {"jit", "jitable"} for p in numpy)


def test_free_layout_steps_on_both_backends_have_their_kernels():
    stems = {str(Path(p).with_suffix("")) for p in _relative(FREE)}
    steps = {s.rpartition("_")[0] for s in stems if s.endswith("_compiled")} & {
        s.rpartition("_")[0] for s in stems if s.endswith("_numpy")
    }
    assert steps >= {"triaxial/setup", "triaxial/evaluate", "uniform/setup", "uniform/evaluate"}
    for step in sorted(steps):
        assert step in stems, step
        assert _decorators(FREE / f"{step}.py") & {"jitable", "jit"}, step


@pytest.mark.parametrize("name", sorted({Path(p).name for p in _relative(FREE)} - {"__init__.py"}))
def test_free_layout_name_unused_outside_free(name):
    outside = [p for p in _relative(SOURCE) if not p.startswith("free/") and Path(p).name == name]
    assert outside == []
