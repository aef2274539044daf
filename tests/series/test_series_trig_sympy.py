"""Products, derivatives, averages and conversions checked against sympy (independent CAS)."""

from __future__ import annotations

import numpy as np
import pytest
import sympy
from hypothesis import given, settings
from series_strategies import PLAIN_RING, SAM_RING, random_series, series_strategy

from andoyer.series import PoissonRing


def _zero_by_sympy(expr) -> bool:
    """Exact zero test independent of the engine.

    sympy's ``expand_trig`` writes every cos/sin of a sum with single-angle factors; then
    ``cos θ = (u + 1/u)/2`` and ``sin θ = (u − 1/u)/(2i)`` turn the expression into a rational
    function of ``u``, which is zero iff its expanded numerator is.
    """
    expr = sympy.expand_trig(sympy.expand(expr))
    subs = {}
    for angle in sorted({a for f in expr.atoms(sympy.cos, sympy.sin) for a in f.args}, key=str):
        u = sympy.Symbol(f"u_{angle}")
        subs[sympy.cos(angle)] = (u + 1 / u) / 2
        subs[sympy.sin(angle)] = (u - 1 / u) / (2 * sympy.I)
    numerator, _ = sympy.fraction(sympy.together(expr.xreplace(subs)))
    return sympy.expand(numerator) == 0


def _sympy_with_beta(expr):
    """Substitute beta² = 1 − s² in a sympy expression so that both sides live in one ring."""
    beta, s = sympy.symbols("beta s")
    return sympy.expand(expr).subs(beta**2, 1 - s**2)


@pytest.mark.parametrize(
    ("kind_a", "kind_b"), [("cos", "cos"), ("cos", "sin"), ("sin", "cos"), ("sin", "sin")]
)
@pytest.mark.parametrize(("ka", "kb"), [((1, 0), (1, 0)), ((2, -1), (1, 3)), ((0, 1), (-3, 1))])
def test_trig_product_to_sum_matches_sympy(kind_a, kind_b, ka, kb):
    R = PLAIN_RING
    a = getattr(R, kind_a)(ka) * R("X")
    b = getattr(R, kind_b)(kb) * R("Y**-1")
    diff = (a * b).to_sympy() - a.to_sympy() * b.to_sympy()
    assert _zero_by_sympy(diff)


@pytest.mark.slow
@pytest.mark.parametrize("seed", range(3))
def test_trig_random_product_matches_sympy(seed):
    rng = np.random.default_rng(seed)
    a, b = random_series(PLAIN_RING, rng, nterms=4), random_series(PLAIN_RING, rng, nterms=4)
    assert _zero_by_sympy((a * b).to_sympy() - a.to_sympy() * b.to_sympy())


def test_trig_relation_product_matches_sympy():
    rng = np.random.default_rng(7)
    a, b = random_series(SAM_RING, rng, nterms=3), random_series(SAM_RING, rng, nterms=3)
    diff = (a * b).to_sympy() - _sympy_with_beta(a.to_sympy() * b.to_sympy())
    assert _zero_by_sympy(_sympy_with_beta(sympy.expand_trig(diff)))


@pytest.mark.parametrize("var", ["x", "y", "X", "Y", "c"])
@pytest.mark.parametrize("seed", range(2))
def test_trig_derivative_matches_sympy(var, seed):
    f = random_series(PLAIN_RING, np.random.default_rng(seed))
    diff = f.diff(var).to_sympy() - sympy.diff(f.to_sympy(), sympy.Symbol(var))
    assert _zero_by_sympy(diff)


def test_trig_average_matches_sympy_integral():
    f = random_series(PLAIN_RING, np.random.default_rng(3), nterms=5)
    x, y = sympy.symbols("x y")
    expr = f.to_sympy()
    over_x = sympy.integrate(expr, (x, 0, 2 * sympy.pi)) / (2 * sympy.pi)
    assert _zero_by_sympy(f.average(["x"]).to_sympy() - over_x)
    over_both = sympy.integrate(over_x, (y, 0, 2 * sympy.pi)) / (2 * sympy.pi)
    assert _zero_by_sympy(f.average().to_sympy() - over_both)


@pytest.mark.parametrize("seed", range(4))
def test_trig_sympy_round_trip(seed):
    for ring in (PLAIN_RING, SAM_RING):
        f = random_series(ring, np.random.default_rng(seed))
        assert ring.from_sympy(f.to_sympy()) == f
        assert ring.from_sympy(sympy.expand(f.to_sympy() ** 2)) == f * f


@settings(max_examples=30, deadline=None)
@given(series_strategy(PLAIN_RING))
def test_trig_sympy_round_trip_hypothesis(f):
    assert PLAIN_RING.from_sympy(f.to_sympy()) == f


def test_trig_from_sympy_rejects_non_series():
    R = PLAIN_RING
    x, X = sympy.symbols("x X")
    for bad in (sympy.exp(X), X ** sympy.Rational(1, 2), sympy.cos(x / 2), x, sympy.Float(0.5)):
        with pytest.raises(ValueError, match="expected"):
            R.from_sympy(bad)


def test_trig_latex_is_sympy_latex_of_each_group():
    R = PoissonRing(["l"], ["L"], ["beta"])
    f = R("beta*L**2*cos(2*l)/2 - L*sin(l) + 3")
    latex = f.to_latex()
    assert latex == (r"3 - L \sin{\left(l \right)} + \frac{L^{2} \beta}{2} \cos{\left(2 l \right)}")
