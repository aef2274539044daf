"""Each formula written once: no module but its home defines a Hamilton product or a Jacobi amplitude.

Read from the source (AST), not by name only: a function with four sums of four
two-factor products is a quaternion product, whatever it is called; a function that
loops (``while``) and calls ``asin``/``arcsin`` is the AGM amplitude.
"""

from __future__ import annotations

import ast
import functools
from pathlib import Path

import pytest

import andoyer

SRC = Path(andoyer.__file__).resolve().parent
PRODUCT_HOME = ("_quaternion.py", "product")
AMPLITUDE_HOME = ("special/jacobi.py", "amplitude")


def _modules() -> list[tuple[str, ast.Module]]:
    paths = sorted(SRC.rglob("*.py"))
    return [(p.relative_to(SRC).as_posix(), ast.parse(p.read_text(encoding="utf-8"))) for p in paths]


def _summands(node: ast.AST) -> list[ast.AST]:
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add | ast.Sub):
        return _summands(node.left) + _summands(node.right)
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
        return _summands(node.operand)
    return [node]


def _is_two_factor_product(node: ast.AST) -> bool:
    return (
        isinstance(node, ast.BinOp)
        and isinstance(node.op, ast.Mult)
        and not any(isinstance(side, ast.BinOp) for side in (node.left, node.right))
    )


def _four_product_sums(function: ast.AST) -> int:
    """How many maximal sums of exactly four two-factor products the function holds."""
    inner = set()
    count = 0
    for node in ast.walk(function):
        if id(node) in inner or not (isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add | ast.Sub)):
            continue
        terms = _summands(node)
        inner.update(id(n) for n in ast.walk(node))
        if len(terms) == 4 and all(_is_two_factor_product(t) for t in terms):
            count += 1
    return count


def _calls(function: ast.AST) -> set[str]:
    names = set()
    for node in ast.walk(function):
        if isinstance(node, ast.Call):
            f = node.func
            names.add(f.attr if isinstance(f, ast.Attribute) else getattr(f, "id", ""))
    return names


@functools.cache
def _functions() -> tuple[tuple[str, ast.FunctionDef], ...]:
    found = ((path, node) for path, tree in _modules() for node in ast.walk(tree))
    return tuple((path, node) for path, node in found if isinstance(node, ast.FunctionDef))


@pytest.mark.slow
def test_one_source_hamilton_product():
    found = [(path, f.name) for path, f in _functions() if _four_product_sums(f) >= 4]
    assert found == [PRODUCT_HOME]


def test_one_source_jacobi_amplitude():
    found = [
        (path, f.name)
        for path, f in _functions()
        if {"asin", "arcsin"} & _calls(f) and any(isinstance(n, ast.While) for n in ast.walk(f))
    ]
    assert found == [AMPLITUDE_HOME]
    named = sorted((path, f.name) for path, f in _functions() if f.name in ("am", "_am", "amplitude"))
    assert named == [("special/jacobi.py", "am"), AMPLITUDE_HOME]


@pytest.mark.parametrize(
    "source",
    [
        (
            "def f(a, b):\n    ax, ay, az, aw = a\n    bx, by, bz, bw = b\n"
            "    return (aw * bx + ax * bw + ay * bz - az * by, aw * by - ax * bz + ay * bw + az * bx,\n"
            "            aw * bz + ax * by - ay * bx + az * bw, aw * bw - ax * bx - ay * by - az * bz)\n"
        ),
        (
            "def g(q, o, a, b):\n    o[0] = a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1]\n"
            "    o[1] = a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0]\n"
            "    o[2] = a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3]\n"
            "    o[3] = a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2]\n"
        ),
    ],
    ids=["tuple", "assignments"],
)
def test_one_source_detector_finds_a_copy(source):
    # the detector itself: the two shapes the removed copies had are recognised
    function = ast.parse(source).body[0]
    assert _four_product_sums(function) == 4
