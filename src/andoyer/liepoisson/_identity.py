"""Decide that a trigonometric–radical expression vanishes identically.

``sympy.simplify`` is slow and unpredictable on the brackets of the Andoyer
coordinates (minutes for one bracket of e(3)). This module replaces it with an
algebraic normal form:

1. every angle ``a`` that appears in ``sin``/``cos`` with rational multiples is
   rescaled so that the multiples are integers, the trigonometric functions are
   expanded and ``sin a``, ``cos a`` become symbols ``s_a``, ``c_a`` with the
   relation ``s_a² + c_a² - 1``;
2. every square root ``√p`` (after reducing ``p``) becomes a symbol ``w`` with the
   relation ``w² - p``; sympy first extracts exact squares under its assumptions
   (``√(G²) = G`` for a positive ``G``);
3. the numerator of the resulting rational function is reduced modulo the
   relations. Their leading monomials (lex order: radicals, sines, cosines,
   constrained generators, rest) are powers of distinct variables, hence
   pairwise coprime, so the relations are a Gröbner basis and the remainder is
   a normal form.

A zero remainder is a proof: the identity holds at every point where the
relations hold (whatever the branch of each root). A non-zero remainder means
"not proven" (it can be a false negative, never a false positive). Function
calls that are not ``sin``/``cos`` of linear arguments (``atan2``, ...) are
replaced by opaque symbols, which keeps the test sound.

Bracket expressions are DAGs with much sharing (derivatives of ``atan2`` of
long expressions); every pass here is memoised on sub-expressions, because
sympy's own traversals (``xreplace``, ``atoms``) walk the unshared tree.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from typing import Any

import sympy as sp
from sympy.polys.orderings import lex
from sympy.polys.rings import PolyElement, PolyRing, ring

__all__ = ["vanishes"]

_TRIG = (sp.sin, sp.cos)
_RECIPROCAL_TRIG = (sp.tan, sp.cot, sp.sec, sp.csc)


def _nodes(*roots: Any) -> Iterator[Any]:
    """Distinct sub-expressions of ``roots`` (each visited once)."""
    seen: set[Any] = set()
    stack = list(roots)
    while stack:
        e = stack.pop()
        if e in seen:
            continue
        seen.add(e)
        yield e
        stack.extend(e.args)


def _linear_coefficients(arg: Any) -> dict[Any, Any] | None:
    """``{symbol: rational coefficient}`` if ``arg`` is linear with rational coefficients."""
    syms = arg.free_symbols
    if not syms:
        return None
    try:
        poly = sp.Poly(arg, *sorted(syms, key=str))
    except sp.PolynomialError:
        return None
    if poly.total_degree() > 1:
        return None
    coeffs = {s: poly.coeff_monomial(s) for s in syms}
    return coeffs if all(c.is_Rational for c in coeffs.values()) else None


class _Algebraizer:
    def __init__(self, relations: tuple[tuple[Any, Any], ...], substitution: Mapping[Any, Any]) -> None:
        self.substitution = dict(substitution)
        self.scale: dict[Any, tuple[int, Any]] = {}
        self.sines: dict[Any, Any] = {}
        self.cosines: dict[Any, Any] = {}
        self.radicals: list[tuple[Any, Any]] = []
        self.opaque: dict[Any, Any] = {}
        self.level = [lead for lead, _ in relations]
        self.level_relations = [sp.expand(poly) for _, poly in relations]
        self.memo: dict[Any, Any] = {}
        self.seen_symbols: set[Any] = set()

    def prepare(self, expr: Any) -> None:
        """Find the angles and the integer scale that makes their trig multiples integral."""
        dens: dict[Any, int] = {}
        for node in _nodes(expr, *self.substitution.values()):
            if isinstance(node, _TRIG + _RECIPROCAL_TRIG):
                coeffs = _linear_coefficients(node.args[0])
                if coeffs is None or set(coeffs) & set(self.substitution):
                    continue
                for s, c in coeffs.items():
                    dens[s] = sp.ilcm(dens.get(s, 1), sp.Rational(c).q)
        for s in sorted(dens, key=str):
            dummy = sp.Dummy(f"{s}_scaled", real=True)
            self.scale[s] = (int(dens[s]), dummy)
            self.sines[dummy] = sp.Symbol(f"s_{s}_{dens[s]}", real=True)
            self.cosines[dummy] = sp.Symbol(f"c_{s}_{dens[s]}", real=True)

    # --- relations and normal form ---

    def generators(self, extra: set[Any]) -> list[Any]:
        ordered = [w for w, _ in reversed(self.radicals)]
        ordered += list(self.sines.values()) + list(self.cosines.values()) + self.level
        return ordered + sorted(extra - set(ordered), key=str)

    def relations(self) -> list[Any]:
        rel = [self.sines[d] ** 2 + self.cosines[d] ** 2 - 1 for d in self.sines]
        rel += [w**2 - p for w, p in self.radicals]
        return rel + self.level_relations

    def normal_form(self, expr: Any) -> tuple[Any, Any]:
        """Numerator (reduced) and denominator of ``expr`` as sympy expressions."""
        rel = self.relations()
        symbols = self.seen_symbols.union(*(r.free_symbols for r in rel))
        R, *_ = ring(self.generators(symbols), sp.QQ, lex)
        basis = [R.from_expr(r) for r in rel]
        num, den = _Fraction(R, basis).convert(expr)
        denominator = sp.Mul(*(f.as_expr() ** k for f, k in den.items()))
        return num.as_expr(), denominator

    # --- one memoised bottom-up pass ---

    def walk(self, e: Any) -> Any:
        if e in self.memo:
            return self.memo[e]
        out = self._walk(e)
        self.memo[e] = out
        return out

    def _walk(self, e: Any) -> Any:
        if e in self.substitution:
            return self.walk(self.substitution[e])
        if e.is_Symbol:
            if e in self.scale:
                den, dummy = self.scale[e]
                self.seen_symbols.add(dummy)
                return den * dummy
            self.seen_symbols.add(e)
            return e
        if e.is_Number or e in (sp.pi, sp.E):
            return e
        if isinstance(e, _RECIPROCAL_TRIG):
            return self.walk(e.rewrite(sp.sin))
        if isinstance(e, _TRIG):
            return self._trig(e)
        if not (e.is_Add or e.is_Mul or e.is_Pow):
            return self._opaque(e)
        out = e.func(*(self.walk(a) for a in e.args))
        if out.is_Pow and out.exp.is_Rational and out.exp.q == 2:
            out = self._root(out.base) ** out.exp.p
        return out

    def _trig(self, e: Any) -> Any:
        coeffs = _linear_coefficients(e.args[0])
        if coeffs is None or not set(coeffs) <= set(self.scale):
            return self._opaque(e)
        arg = e.args[0].xreplace({s: self.scale[s][0] * self.scale[s][1] for s in coeffs})
        expanded = sp.expand_trig(e.func(arg))
        expanded = expanded.xreplace({sp.sin(d): s for d, s in self.sines.items()})
        expanded = expanded.xreplace({sp.cos(d): c for d, c in self.cosines.items()})
        self.seen_symbols.update(expanded.free_symbols)
        if expanded.has(sp.sin, sp.cos):
            return self._opaque(e)
        return self.walk(expanded) if expanded.has(sp.Pow) else expanded

    def _opaque(self, e: Any) -> Any:
        symbol = self.opaque.setdefault(e, sp.Dummy("opaque"))
        self.seen_symbols.add(symbol)
        return symbol

    def _root(self, base: Any) -> Any:
        num, den = self.normal_form(base)
        if den.is_positive:
            root = sp.sqrt(sp.factor(sp.expand(num * den))) / den
        elif den.is_negative:
            root = -sp.sqrt(sp.factor(sp.expand(num * den))) / den
        else:
            return self._opaque(sp.sqrt(base))
        return root.replace(lambda x: x.is_Pow and x.exp == sp.S.Half, lambda x: self._radical(x.base))

    def _radical(self, radicand: Any) -> Any:
        radicand = sp.expand(radicand)
        for w, p in self.radicals:
            if sp.expand(p - radicand) == 0:
                return w
        w = sp.Symbol(f"w{len(self.radicals)}", positive=True)
        self.radicals.append((w, radicand))
        self.seen_symbols.add(w)
        return w


class _Fraction:
    """Rational expression → (numerator, {denominator factor: exponent}) without gcds.

    Denominators are kept as products of the factors met in the expression tree, so
    sums only take the lcm of factor multisets; numerators are reduced modulo the
    Gröbner basis at every step, which keeps them small and is valid because only
    the numerator's class modulo the relations matters.
    """

    def __init__(self, R: PolyRing, basis: list[PolyElement]) -> None:
        self.R = R
        self.basis = basis
        self.memo: dict[Any, tuple[PolyElement, dict[PolyElement, int]]] = {}

    def reduce(self, p: PolyElement) -> PolyElement:
        return p.rem(self.basis) if self.basis else p

    def convert(self, e: Any) -> tuple[PolyElement, dict[PolyElement, int]]:
        if e in self.memo:
            return self.memo[e]
        if e.is_Add:
            out = self._add([self.convert(a) for a in e.args])
        elif e.is_Mul:
            num, den = self.R.one, {}
            for a in e.args:
                n, d = self.convert(a)
                num = self.reduce(num * n)
                for f, k in d.items():
                    den[f] = den.get(f, 0) + k
            out = (num, den)
        elif e.is_Pow and e.exp.is_Integer:
            n, d = self.convert(e.base)
            k = int(e.exp)
            if k >= 0:
                out = (self.reduce(n**k), {f: j * k for f, j in d.items()})
            else:
                num = self.R.one
                for f, j in d.items():
                    num = self.reduce(num * f ** (-j * k))
                out = (num, self._factors(n, -k))
        elif e.is_Rational and not e.is_Integer:
            out = (self.R(e.p), {self.R(e.q): 1})
        else:
            out = (self.R.from_expr(e), {})
        self.memo[e] = out
        return out

    def _add(self, parts: list[tuple[PolyElement, dict[PolyElement, int]]]) -> tuple[Any, Any]:
        den: dict[PolyElement, int] = {}
        for _, d in parts:
            for f, k in d.items():
                den[f] = max(den.get(f, 0), k)
        num = self.R.zero
        for n, d in parts:
            cofactor = n
            for f, k in den.items():
                if k > d.get(f, 0):
                    cofactor = cofactor * f ** (k - d.get(f, 0))
            num += self.reduce(cofactor)
        return self.reduce(num), den

    def _factors(self, p: PolyElement, k: int) -> dict[PolyElement, int]:
        if p.is_ground:
            return {p: k}
        content, prim = p.primitive()
        sign = -1 if prim.LC < 0 else 1
        out = {prim * sign: k}
        if content * sign != 1:
            out[self.R(content * sign)] = k
        return out


def vanishes(
    expr: Any,
    relations: tuple[tuple[Any, Any], ...] = (),
    substitution: Mapping[Any, Any] | None = None,
) -> bool:
    """True when ``expr`` is proven to vanish identically (see module docstring).

    Parameters
    ----------
    expr : sympy expression
    relations : tuple of (Symbol, expression)
        Extra polynomial relations ``poly = 0`` with the symbol that leads them,
        e.g. ``(gamma1, gamma1**2 + gamma2**2 + gamma3**2 - 1)``; each leading
        symbol must appear squared in its relation and in no other relation.
    substitution : mapping, optional
        Symbols to replace by expressions first (memoised, unlike ``xreplace``).

    Returns
    -------
    bool
        ``True``: proven identity. ``False``: not proven.

    Examples
    --------
    >>> import sympy as sp
    >>> l, L = sp.symbols("l L", real=True)
    >>> G = sp.Symbol("G", positive=True)
    >>> r = sp.sqrt(G**2 - L**2)
    >>> vanishes(sp.sqrt((r * sp.sin(l))**2 + (r * sp.cos(l))**2 + L**2) - G)
    True
    >>> vanishes(sp.sin(l / 2) ** 2 - (1 - sp.cos(l)) / 2)
    True
    >>> vanishes(sp.sin(l) - sp.cos(l))
    False
    """
    alg = _Algebraizer(relations, substitution or {})
    expr = sp.sympify(expr)
    alg.prepare(expr)
    num, _ = alg.normal_form(alg.walk(expr))
    return sp.expand(num) == 0
