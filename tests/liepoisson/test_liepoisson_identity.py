"""The algebraic zero test behind the symbolic proofs: true identities proven, false ones never."""

import pytest
import sympy as sp

from andoyer.liepoisson._identity import vanishes

a, b, x, y = sp.symbols("a b x y", real=True)
G = sp.Symbol("G", positive=True)
L = sp.Symbol("L", real=True)


@pytest.mark.parametrize(
    "expr",
    [
        sp.sin(a) ** 2 + sp.cos(a) ** 2 - 1,
        sp.sin(a + b) - sp.sin(a) * sp.cos(b) - sp.cos(a) * sp.sin(b),
        sp.cos(a / 2) ** 2 - (1 + sp.cos(a)) / 2,
        sp.sin(a / 3) * 0 + sp.sin(3 * (a / 3)) - sp.sin(a),
        sp.tan(a) * sp.cos(a) - sp.sin(a),
        sp.sin(a + sp.pi / 2) - sp.cos(a),
        sp.sqrt(G**2) - G,
        sp.sqrt(G**2 - L**2) ** 2 - G**2 + L**2,
        1 / sp.sqrt(G**2 - L**2) - sp.sqrt(G**2 - L**2) / (G**2 - L**2),
        sp.sqrt((G + L) / (2 * G)) ** 2 - (G + L) / (2 * G),
        (x**2 - y**2) / (x - y) - x - y,
        sp.sin(a) / (1 + sp.cos(a)) - (1 - sp.cos(a)) / sp.sin(a),
    ],
)
def test_true_identities_are_proven(expr):
    assert vanishes(expr)


@pytest.mark.parametrize(
    "expr",
    [
        sp.sin(a) - sp.cos(a),
        sp.sin(a / 2) - sp.sqrt((1 - sp.cos(a)) / 2),  # wrong sign for a in (2π, 4π)
        sp.sqrt(x**2) - x,  # false for x < 0
        sp.sqrt(G**2 - L**2) - sp.sqrt(G - L) * sp.sqrt(G + L) + 1,
        sp.atan2(x, y) - sp.atan2(2 * x, 2 * y),  # true, but atan2 is opaque: not proven
        sp.sin(x * y) - sp.sin(y * x) + 1e-30 * x,
        sp.Rational(1, 10**20),
    ],
)
def test_false_or_unprovable_are_not_proven(expr):
    assert not vanishes(expr)


def test_relations_are_used():
    g1, g2, g3 = sp.symbols("gamma1:4", real=True)
    unit = ((g1, g1**2 + g2**2 + g3**2 - 1),)
    assert vanishes(g1**2 + g2**2 + g3**2 - 1, unit)
    assert not vanishes(g1**2 + g2**2 + g3**2 - 1)
    assert not vanishes(g1**2 + g2**2 - 1, unit)


def test_substitution_is_applied():
    assert vanishes(x**2 + y**2 - 1, substitution={x: sp.sin(a), y: sp.cos(a)})
    assert not vanishes(x**2 + y**2 - 1, substitution={x: sp.sin(a), y: sp.sin(a)})
