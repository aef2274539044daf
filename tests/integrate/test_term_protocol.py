"""The integrators use the term protocol only: no switch on a term's type, no private attribute.

An AST scan of every module of ``andoyer.integrate``: no ``isinstance(x, C)`` or ``type(x) is C``
with ``C`` a disturbing-term class, and no read of a ``._name`` attribute of anything but ``self``
(the terms' private attributes are theirs; each integrator asks a term through
:class:`andoyer.perturbations.base.Perturbation`'s methods).
"""

from __future__ import annotations

import ast
import inspect
from pathlib import Path

import pytest

import andoyer.integrate
import andoyer.perturbations
from andoyer.perturbations.base import Perturbation

INTEGRATE = Path(andoyer.integrate.__file__).parent
#: The concrete term classes (the protocol's base class itself may be named, e.g. in type hints).
TERM_CLASSES = {
    name
    for name, value in vars(andoyer.perturbations).items()
    if inspect.isclass(value) and issubclass(value, Perturbation) and value is not Perturbation
}
#: Every module of the package, those of the methods' subpackages included.
MODULES = sorted(INTEGRATE.rglob("*.py"))


def _type_switches(tree: ast.AST) -> list[str]:
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Call) and getattr(node.func, "id", "") in {"isinstance", "issubclass"}:
            classes = node.args[1] if len(node.args) > 1 else None
            names = {n.id for n in ast.walk(classes) if isinstance(n, ast.Name)} if classes else set()
            names |= {n.attr for n in ast.walk(classes) if isinstance(n, ast.Attribute)} if classes else set()
            found += [f"line {node.lineno}: isinstance(…, {n})" for n in names & TERM_CLASSES]
        if (
            isinstance(node, ast.Compare)
            and any(isinstance(op, ast.Is | ast.In | ast.Eq) for op in node.ops)
            and isinstance(node.left, ast.Call)
            and getattr(node.left.func, "id", "") == "type"
        ):
            names = {n.id for c in node.comparators for n in ast.walk(c) if isinstance(n, ast.Name)}
            found += [f"line {node.lineno}: type(…) is {n}" for n in names & TERM_CLASSES]
    return found


def _private_reads(tree: ast.AST) -> list[str]:
    return [
        f"line {node.lineno}: {ast.unparse(node)}"
        for node in ast.walk(tree)
        if isinstance(node, ast.Attribute)
        and node.attr.startswith("_")
        and not node.attr.startswith("__")
        and not (isinstance(node.value, ast.Name) and node.value.id in {"self", "cls"})
    ]


def test_term_classes_found():
    assert {"GravityGradient", "HeavyTop", "PrecessingFrame", "LinearDamping", "UserTorque"} <= TERM_CLASSES


@pytest.mark.parametrize("path", MODULES, ids=lambda p: p.relative_to(INTEGRATE).as_posix())
def test_integrator_module_does_not_switch_on_term_types(path):
    assert _type_switches(ast.parse(path.read_text(encoding="utf-8"))) == []


@pytest.mark.parametrize("path", MODULES, ids=lambda p: p.relative_to(INTEGRATE).as_posix())
def test_integrator_module_reads_no_private_attribute(path):
    assert _private_reads(ast.parse(path.read_text(encoding="utf-8"))) == []


def test_scan_catches_a_type_switch_and_a_private_read():
    """The scan is not vacuous: it flags the patterns the integrators used to contain."""
    source = (
        "if isinstance(part, PrecessingFrame):\n    mu = part._constant\n"
        "if type(part) is GravityGradient:\n    pass\n"
    )
    tree = ast.parse(source)
    assert len(_type_switches(tree)) == 2
    assert _private_reads(tree) == ["line 2: part._constant"]
