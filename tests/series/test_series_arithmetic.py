"""Exact arithmetic laws, canonical form and construction of Poisson series."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from series_strategies import PLAIN_RING, POLY_RING, SAM_RING, random_series, series_strategy

from andoyer.series import PoissonRing

RINGS = {"sam": SAM_RING, "plain": PLAIN_RING, "poly": POLY_RING}


@pytest.mark.parametrize("name", RINGS)
@pytest.mark.parametrize("seed", range(4))
def test_arithmetic_ring_laws_random(name, seed):
    ring = RINGS[name]
    rng = np.random.default_rng(seed)
    a, b, c = (random_series(ring, rng) for _ in range(3))
    assert a + b == b + a
    assert a * b == b * a
    assert (a + b) + c == a + (b + c)
    assert (a * b) * c == a * (b * c)
    assert a * (b + c) == a * b + a * c
    assert a - a == 0
    assert a * 1 == a
    assert a * 0 == 0
    assert (a * Fraction(3, 7)) / Fraction(3, 7) == a
    assert a**3 == a * a * a


@settings(max_examples=40, deadline=None)
@given(series_strategy(SAM_RING), series_strategy(SAM_RING), series_strategy(SAM_RING))
def test_arithmetic_ring_laws_hypothesis(a, b, c):
    assert a * (b + c) == a * b + a * c
    assert (a * b) * c == a * (b * c)
    assert hash(a + b) == hash(b + a)


def test_arithmetic_relation_reduces_powers():
    R = SAM_RING
    beta, s = R.gen("beta"), R.gen("s")
    assert beta**2 == 1 - s**2
    assert beta**5 == beta * (1 - s**2) ** 2
    # s is invertible, beta is not: beta²/s² = 1/s² − 1
    assert beta**2 / s**2 == s**-2 - 1
    with pytest.raises(ValueError, match="expected a rational times a Laurent monomial"):
        R.one / beta


def test_arithmetic_canonical_form_from_different_constructions():
    R = SAM_RING
    a = R("L**2*cos(l)**2")
    b = R("L**2/2 + L**2/2*cos(2*l)")
    c = R.from_terms([("1/2", {"L": 2}, "cos", [0, 0]), ("1/2", {"L": 2}, "cos", [-2, 0])])
    assert a == b == c
    assert hash(a) == hash(b) == hash(c)
    assert R("sin(-l + g)") == -R("sin(l - g)")
    assert R("L/L") == 1
    assert (R("L**-3") * R("L**3")).terms() == R.one.terms()


@pytest.mark.parametrize(
    ("text", "match"),
    [
        ("l + L", "angles only inside"),
        ("cos(l + 1)", "no constant phase"),
        ("cos(l/2)", "integer combination"),
        ("L**0.5", "integer exponent"),
        ("L/(L + G)", "a divisor that is a rational times a monomial"),
        ("1.5*L", "integer constant"),
        ("zeta", "a variable of"),
        ("L +", "Python syntax"),
    ],
)
def test_arithmetic_parse_errors(text, match):
    with pytest.raises(ValueError, match=match):
        SAM_RING(text)


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"angles": ["l"], "momenta": ["l"]}, "distinct"),
        ({"angles": ["cos"], "momenta": ["L"]}, "identifiers"),
        ({"angles": ["l"], "momenta": ["L"], "pairs": [("L", "l")]}, "pairs"),
        (
            {"angles": ["l"], "momenta": ["L"], "params": ["b"], "relations": {"L": "b"}},
            "relations",
        ),
        (
            {"angles": ["l"], "momenta": ["L"], "params": ["b"], "relations": {"b": "L"}},
            "relation b",
        ),
        ({"angles": ["l"], "momenta": ["L"], "weights": {"l": 1}}, "weights"),
    ],
)
def test_arithmetic_ring_declaration_errors(kwargs, match):
    with pytest.raises(ValueError, match=match):
        PoissonRing(**kwargs)


def test_arithmetic_rejects_floats_and_foreign_rings():
    R = PLAIN_RING
    with pytest.raises(ValueError, match="exact rational"):
        R.constant(0.5)
    other = PoissonRing(["x"], ["X"])
    with pytest.raises(ValueError, match="expected a series of"):
        R("X") + other("X")
    assert R("X") != other("X")
    assert R("X") == PoissonRing.from_spec(R.spec())("X")
    with pytest.raises(TypeError):
        R("X") + 0.5


def test_arithmetic_trig_coefficient_and_variables():
    R = SAM_RING
    f = R("3*L*G*sin(2*l - g) + beta*cos(l) + a")
    assert f.trig_coefficient("sin", {"l": -2, "g": 1}) == R("-3*L*G")
    assert f.trig_coefficient("cos", [1, 0]) == R("beta")
    assert f.trig_coefficient("cos", [0, 0]) == R("a")
    assert f.variables() == ("l", "g", "L", "G", "beta", "a")
    assert len(f) == 3
