"""The triaxiality tables against an independent plain-sympy Deprit computation, and their
JSON, Markdown and LaTeX forms."""

from __future__ import annotations

import json
from fractions import Fraction
from math import comb, factorial

import pytest
import sympy as sp

from andoyer.theories.sam_tables import (
    sam_tables,
    tables_from_json,
    tables_to_json,
    tables_to_latex,
    tables_to_markdown,
)

L, G, z = sp.symbols("L G z", positive=True)  # z = exp(iℓ): cos kℓ = (z^k + z^-k)/2
ALPHA, C = sp.Rational(3, 10), sp.Rational(7, 5)


def _terms(f):
    """``{k: coefficient}`` of a Laurent polynomial in z."""
    out = {}
    for t in sp.Add.make_args(sp.expand(f)):
        c, k = t.as_coeff_exponent(z)
        if c.has(z):
            raise AssertionError(t)
        out[int(k)] = out.get(int(k), 0) + c
    return out


def _d_angle(f):
    return sp.expand(sp.I * z * sp.diff(f, z))


def _bracket(f, w):
    # {f, w} = ∂f/∂ℓ ∂w/∂L − ∂f/∂L ∂w/∂ℓ (g does not occur).
    return sp.expand(_d_angle(f) * sp.diff(w, L) - sp.diff(f, L) * _d_angle(w))


def plain_sympy_deprit(beta, s, order):
    """Deprit's triangle in plain sympy (Deprit 1969): new Hamiltonian and generator."""
    omega = ALPHA * s * G / C
    H = [G**2 / (2 * C) + ALPHA * s * G * L / C, -ALPHA * L**2 * (1 + beta * (z**2 + z**-2) / 2) / (2 * C)]
    H += [sp.Integer(0)] * (order + 1 - len(H))
    table = [H] + [[None] * (order + 1) for _ in range(order)]
    W, K = [], [H[0]]
    for n in range(1, order + 1):
        for q in range(1, n + 1):
            m = n - q
            acc = table[q - 1][m + 1]
            for k in range(m + 1):
                if k + 1 < n:
                    acc += comb(m, k) * _bracket(table[q - 1][m - k], W[k])
            table[q][m] = sp.expand(acc)
        terms = _terms(table[n][0])
        mean = terms.get(0, 0)
        # ω ∂W/∂ℓ = H̃ − ⟨H̃⟩, zero average
        w = sp.Add(*(c * z**k / (sp.I * k * omega) for k, c in terms.items() if k))
        correction = mean - table[n][0]
        for q in range(1, n + 1):
            table[q][n - q] = sp.expand(table[q][n - q] + correction)
        W.append(sp.expand(w))
        K.append(mean)
    return K, W


def plain_sympy_direct(W, f0, conjugate=None):
    """``f(X(y))`` by the Lie triangle; for an angle (f0 = 0 standing for it), the first
    bracket is {θ, W} = ∂W/∂(conjugate momentum)."""
    order = len(W)
    rows = [[f0] + [sp.Integer(0)] * order]
    out = [f0]
    for n in range(1, order + 1):
        for q in range(1, n + 1):
            m = n - q
            if len(rows) <= q:
                rows.append([None] * (order + 1))
            acc = rows[q - 1][m + 1]
            for k in range(m + 1):
                f = rows[q - 1][m - k]
                first = conjugate is not None and q == 1 and m - k == 0
                bracket = sp.diff(W[k], conjugate) if first else _bracket(f, W[k])
                acc += comb(m, k) * bracket
            rows[q][m] = sp.expand(acc)
        out.append(rows[n][0])
    return out


def value(poly, beta):
    return sum(sp.Rational(c.numerator, c.denominator) * beta**p for p, c in poly.items())


@pytest.mark.parametrize("tau", [sp.Rational(1, 2), sp.Rational(2, 3), sp.Rational(3, 4), sp.Rational(5, 3)])
def test_sam_tables_match_plain_sympy_deprit(tau):
    # Rational β = (1 − τ²)/(1 + τ²), s = 2τ/(1 + τ²) (τ > 1: β < 0).  The tables hold
    # polynomials of degree ≤ 2 in β for i ≤ 3, so four values of β prove them equal.
    beta, s = (1 - tau**2) / (1 + tau**2), 2 * tau / (1 + tau**2)
    order = 3
    K, W = plain_sympy_deprit(beta, s, order)
    tables = sam_tables(order)
    x, delta = L / G, L / (G * s)
    for i in (1, 2):  # K_(i+1)/(i+1)! = −(G²/2C) α x² β² δ^i q_i
        q = -K[i + 1] / factorial(i + 1) / (G**2 / (2 * C) * ALPHA * x**2 * beta**2 * delta**i)
        assert sp.simplify(q - value(tables["q"][i][0], beta)) == 0
    dl = plain_sympy_direct(W, sp.Integer(0), conjugate=L)
    dg = plain_sympy_direct(W, sp.Integer(0), conjugate=G)
    dL = plain_sympy_direct(W, L)
    for i in range(1, order + 1):
        l_terms, L_terms = _terms(dl[i] / factorial(i)), _terms(dL[i] / factorial(i))
        g_terms = _terms(dg[i] / factorial(i))
        for m, poly in tables["g"][i].items():  # −x Σ (−β)^m g_(i,m) sin 2mℓ
            assert (
                sp.simplify(2 * sp.I * g_terms[2 * m] + x * delta**i * (-beta) ** m * value(poly, beta)) == 0
            )
        assert set(g_terms) == {k for m in tables["g"][i] for k in (2 * m, -2 * m)}
        for m, poly in tables["l"][i].items():  # Σ (−β)^m ℓ_(i,m) sin 2mℓ: sin = (z − 1/z)/(2i)
            assert sp.simplify(2 * sp.I * l_terms[2 * m] - delta**i * (-beta) ** m * value(poly, beta)) == 0
        for m, poly in tables["L"][i].items():
            got = L_terms.get(0, 0) if m == 0 else -2 * L_terms[2 * m]
            expected = L * delta**i * (beta**2 if m == 0 else (-beta) ** m) * value(poly, beta)
            assert sp.simplify(got - expected) == 0
        assert set(l_terms) == {k for m in tables["l"][i] for k in (2 * m, -2 * m)}


def test_sam_tables_json_schema_and_round_trip():
    tables = sam_tables(4)
    doc = json.loads(tables_to_json(tables))
    assert list(doc) == ["q", "g", "l", "L"]
    assert doc["q"]["1"] == {"0": {"0": "1/2"}}
    assert doc["q"]["3"] == {"0": {"0": "3/4", "2": "9/32"}}
    assert doc["L"]["2"]["0"] == {"0": "1/4"}  # coefficient of β² in eq. 34
    for family in doc.values():
        for i, row in family.items():
            assert i.isdigit()
            for m, poly in row.items():
                assert m.isdigit()
                for p, c in poly.items():
                    assert p.isdigit()
                    num, den = c.split("/")
                    assert int(den) >= 1
                    assert Fraction(int(num), int(den)) != 0
    back = tables_from_json(tables_to_json(tables))
    assert back == tables
    assert all(
        isinstance(c, Fraction) for row in back["l"].values() for p in row.values() for c in p.values()
    )


@pytest.mark.parametrize(
    ("text", "match"),
    [
        ("[1, 2]", "keys"),
        ('{"q": {}, "g": {}, "l": {}}', "keys"),
        ('{"q": {"x": {}}, "g": {}, "l": {}, "L": {}}', "index i"),
        ('{"q": {"1": {"0": {"0": 0.5}}}, "g": {}, "l": {}, "L": {}}', "rational"),
        ('{"q": {"1": {"0": {"0": "1/0"}}}, "g": {}, "l": {}, "L": {}}', "rational"),
        ("{", "invalid JSON"),
    ],
)
def test_sam_tables_from_json_rejects_malformed(text, match):
    with pytest.raises(ValueError, match=match):
        tables_from_json(text)


def test_sam_tables_markdown_and_latex():
    tables = sam_tables(5)
    md = tables_to_markdown(tables)
    assert "| 5 | 1 + 177/64 β² + 45/128 β⁴ |" in md
    assert "| 3 | 3 | 1/96 |" in md  # ℓ_(3,3)
    tex = tables_to_latex(tables)
    assert tex.count(r"\begin{tabular}") == 4
    assert tex.count(r"\end{tabular}") == 4
    assert r"5 & $1 + \frac{177}{64}\beta^{2} + \frac{45}{128}\beta^{4}$ \\" in tex


def test_sam_tables_errors():
    with pytest.raises(ValueError, match="order >= 1"):
        sam_tables(0)
