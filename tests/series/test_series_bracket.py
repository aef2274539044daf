"""Poisson bracket: Jacobi identity, Leibniz rule, antisymmetry, canonical pairs; averaging and
the homological equation."""

from __future__ import annotations

import numpy as np
import pytest
import sympy
from hypothesis import given, settings
from series_strategies import PLAIN_RING, POLY_RING, SAM_RING, random_series, series_strategy

from andoyer.series import PoissonRing, frequencies, poisson_bracket, solve_homological

RINGS = {"sam": SAM_RING, "plain": PLAIN_RING, "poly": POLY_RING}


@pytest.mark.parametrize("name", RINGS)
@pytest.mark.parametrize("seed", range(3))
def test_bracket_jacobi_leibniz_antisymmetry_random(name, seed):
    ring = RINGS[name]
    rng = np.random.default_rng(100 + seed)
    f, g, h = (random_series(ring, rng, nterms=4) for _ in range(3))
    jacobi = f.bracket(g.bracket(h)) + g.bracket(h.bracket(f)) + h.bracket(f.bracket(g))
    assert jacobi.is_zero()
    assert f.bracket(g * h) == f.bracket(g) * h + g * f.bracket(h)
    assert f.bracket(g) == -g.bracket(f)
    assert f.bracket(f).is_zero()


@settings(max_examples=25, deadline=None)
@given(series_strategy(SAM_RING, 3), series_strategy(SAM_RING, 3), series_strategy(SAM_RING, 3))
def test_bracket_jacobi_hypothesis(f, g, h):
    jacobi = f.bracket(g.bracket(h)) + g.bracket(h.bracket(f)) + h.bracket(f.bracket(g))
    assert jacobi.is_zero()


def test_bracket_canonical_pairs():
    R = POLY_RING  # pairs (q, p) polynomial and (t, T) angle-action
    q, p, T = R.gen("q"), R.gen("p"), R.gen("T")
    assert poisson_bracket(q, p) == 1
    assert poisson_bracket(p, q) == -1
    assert poisson_bracket(q, T).is_zero()
    assert poisson_bracket(R("cos(t)"), T) == R("-sin(t)")
    # parameters and unpaired variables do not enter
    Rp = PoissonRing(["a"], ["A", "B"], ["c"])
    assert poisson_bracket(Rp("B*c*cos(a)"), Rp("A")) == Rp("-B*c*sin(a)")
    assert poisson_bracket(Rp("B"), Rp("c*A")).is_zero()


def test_bracket_matches_sympy_definition():
    f = random_series(PLAIN_RING, np.random.default_rng(5), nterms=4)
    g = random_series(PLAIN_RING, np.random.default_rng(6), nterms=4)
    x, y, X, Y = sympy.symbols("x y X Y")
    fs, gs = f.to_sympy(), g.to_sympy()
    expected = sum(
        sympy.diff(fs, a) * sympy.diff(gs, b) - sympy.diff(fs, b) * sympy.diff(gs, a)
        for a, b in ((x, X), (y, Y))
    )
    assert PLAIN_RING.from_sympy(sympy.expand(expected)) == f.bracket(g)


def test_bracket_derivative_refuses_relation_variables():
    with pytest.raises(ValueError, match="independent of the declared relations"):
        SAM_RING("beta*L").diff("beta")
    with pytest.raises(ValueError, match="independent of the declared relations"):
        SAM_RING("s*L").diff("s")
    with pytest.raises(ValueError, match="expected an angle, momentum or parameter"):
        SAM_RING("L").diff("zeta")


@pytest.mark.parametrize("seed", range(4))
@pytest.mark.parametrize("angles", [None, ["l"], ["g"]])
def test_homological_equation_exact_constant_frequencies(seed, angles):
    R = SAM_RING
    H0 = R("5*L + 7*G")  # k·ω = 5 k1 + 7 k2 ≠ 0 for |k| ≤ 3 (k ≠ 0)
    f = random_series(R, np.random.default_rng(seed), nterms=6)
    W = solve_homological(f, H0, angles)
    assert (H0.bracket(W) + f - f.average(angles)).is_zero()
    assert W.average(angles).is_zero()


@pytest.mark.parametrize("seed", range(4))
def test_homological_equation_exact_monomial_frequency(seed):
    R = SAM_RING
    H0 = R("G**2/2 + a*s*G*L")  # frequency of l: a s G, a monomial; g-harmonics kept out
    f = random_series(R, np.random.default_rng(seed), nterms=8).average(["g"])
    f = f + R("beta*L**2*G**-1*sin(2*l)")
    W = solve_homological(f, H0, ["l"])
    assert (H0.bracket(W) + f - f.average(["l"])).is_zero()
    assert W.average(["l"]).is_zero()
    assert W.terms()  # the check above is not vacuous


def test_homological_exact_division_by_polynomial_divisor():
    R = PoissonRing(["x", "y"], ["X", "Y"])
    H0 = R("X**2/2 + Y")  # k·ω = k1 X + k2: not a monomial
    f = R("(X + 1)*(X - 2)*cos(x + y)*(2*X + 1) + X*cos(x)")
    W = solve_homological(f, H0)
    assert (H0.bracket(W) + f - f.average()).is_zero()
    with pytest.raises(ValueError, match="to divide the coefficient"):
        solve_homological(R("cos(x + y)"), H0)


def test_homological_errors():
    R = PoissonRing(["x", "y"], ["X", "Y"])
    with pytest.raises(ValueError, match="nonresonant"):
        solve_homological(R("cos(x - y)"), R("X + Y"))
    with pytest.raises(ValueError, match="independent of the angles"):
        solve_homological(R("cos(x)"), R("X + cos(y)"))
    Rq = POLY_RING
    with pytest.raises(ValueError, match="independent of the polynomial pair"):
        frequencies(Rq("p**2/2 + T"))
    with pytest.raises(ValueError, match="sequence of angles"):
        solve_homological(R("cos(x)"), R("X"), "x")
    with pytest.raises(ValueError, match="angle-free frequencies"):
        solve_homological(R("cos(x)"), {"x": R("cos(y)")})
    with pytest.raises(ValueError, match="angle-free frequencies"):
        solve_homological(R("cos(x)"), {"z": R("X")})


def test_homological_given_frequencies_equals_given_hamiltonian():
    R = SAM_RING
    H0 = R("G**2/2 + a*s*G*L")
    f = random_series(R, np.random.default_rng(9), nterms=8).average(["g"]) + R("L*sin(2*l)")
    omega = {"l": R("a*s*G"), "g": R("G + a*s*L")}
    assert solve_homological(f, omega, ["l"]) == solve_homological(f, H0, ["l"])


def _naive_derivative(ring, terms, name):
    """Term-by-term derivative of real terms ``(coeff, exponents, kind, harmonics)``."""
    out = []
    if name in ring.angles:
        j = ring.angles.index(name)
        for c, e, kind, k in terms:
            if k[j]:
                # d/dθ cos(k·θ) = −k_j sin(k·θ), d/dθ sin(k·θ) = k_j cos(k·θ)
                out.append((c * (-k[j] if kind == "cos" else k[j]), e, "sin" if kind == "cos" else "cos", k))
        return out
    i = ring.poly_names.index(name)
    for c, e, kind, k in terms:
        if e[i]:
            lowered = list(e)
            lowered[i] -= 1
            out.append((c * e[i], tuple(lowered), kind, k))
    return out


def _naive_product(a, b):
    """Product of two lists of real terms by the product-to-sum identities."""
    out = []
    for ca, ea, ka_kind, ka in a:
        for cb, eb, kb_kind, kb in b:
            c = ca * cb / 2
            e = tuple(x + y for x, y in zip(ea, eb, strict=True))
            ks = tuple(x + y for x, y in zip(ka, kb, strict=True))
            kd = tuple(x - y for x, y in zip(ka, kb, strict=True))
            kinds = (ka_kind, kb_kind)
            if kinds == ("cos", "cos"):  # cos a cos b = [cos(a−b) + cos(a+b)]/2
                out += [(c, e, "cos", kd), (c, e, "cos", ks)]
            elif kinds == ("sin", "sin"):  # sin a sin b = [cos(a−b) − cos(a+b)]/2
                out += [(c, e, "cos", kd), (-c, e, "cos", ks)]
            elif kinds == ("sin", "cos"):  # sin a cos b = [sin(a+b) + sin(a−b)]/2
                out += [(c, e, "sin", ks), (c, e, "sin", kd)]
            else:  # cos a sin b = [sin(a+b) − sin(a−b)]/2
                out += [(c, e, "sin", ks), (-c, e, "sin", kd)]
    return out


def naive_bracket(f, g):
    """``Σ (∂f/∂q ∂g/∂p − ∂f/∂p ∂g/∂q)`` term by term: no flint polynomial arithmetic."""
    ring = f.ring
    ft = [(t.coeff, t.exponents, t.kind, t.harmonics) for t in f.terms()]
    gt = [(t.coeff, t.exponents, t.kind, t.harmonics) for t in g.terms()]
    out = []
    for q, p in ring.pairs:
        out += _naive_product(_naive_derivative(ring, ft, q), _naive_derivative(ring, gt, p))
        minus = [(-c, e, kind, k) for c, e, kind, k in _naive_derivative(ring, ft, p)]
        out += _naive_product(minus, _naive_derivative(ring, gt, q))
    merged: dict = {}
    for c, e, kind, k in out:  # canonical harmonic: first nonzero entry positive
        sign = next((1 if v > 0 else -1 for v in k if v), 0)
        if kind == "sin" and sign == 0:
            continue
        key = (e, kind, tuple(-v for v in k) if sign < 0 else k)
        merged[key] = merged.get(key, 0) + (-c if sign < 0 and kind == "sin" else c)
    return ring.from_terms([(c, e, kind, k) for (e, kind, k), c in merged.items() if c])


@pytest.mark.parametrize("name", RINGS)
@pytest.mark.parametrize("seed", range(4))
def test_bracket_equals_naive_term_by_term(name, seed):
    ring = RINGS[name]
    rng = np.random.default_rng(300 + seed)
    f = random_series(ring, rng, nterms=12, max_harmonic=4)
    g = random_series(ring, rng, nterms=9, max_harmonic=4)
    expected = naive_bracket(f, g)
    assert expected.terms()  # not vacuous
    assert f.bracket(g) == expected
    assert g.bracket(f) == -expected
