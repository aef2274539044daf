"""Text, sympy and LaTeX forms of Poisson series (sympy is imported only when used)."""

from __future__ import annotations

from collections.abc import Mapping
from fractions import Fraction
from typing import Any

from andoyer.series.components import Ring, Series

__all__ = ["series_from_sympy", "series_to_latex", "series_to_sympy"]


def _sympy() -> Any:
    # sympy is an optional dependency (the test extra): import it only when a conversion runs.
    import sympy

    return sympy


def _symbols(ring: Ring, symbols: Mapping[str, Any] | None) -> dict[str, Any]:
    sympy = _sympy()
    symbols = dict(symbols or {})
    return {n: symbols.get(n, sympy.Symbol(n)) for n in ring.variables}


def series_to_sympy(f: Series, symbols: Mapping[str, Any] | None = None) -> Any:
    """Convert a series to a sympy expression (exact rationals, ``cos``/``sin`` of sums).

    Parameters
    ----------
    f : PoissonSeries
    symbols : mapping of str to sympy.Symbol, optional
        Symbols to use for the ring variables; default ``sympy.Symbol(name)``.

    Returns
    -------
    sympy.Expr

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> series_to_sympy(PoissonRing(["q"], ["p"])("3*p**-1*sin(2*q)"))
    3*sin(2*q)/p
    """
    sympy = _sympy()
    ring = f.ring
    sym = _symbols(ring, symbols)
    terms = []
    for t in f.terms():
        expr = sympy.Rational(t.coeff.numerator, t.coeff.denominator)
        for name, e in zip(ring.poly_names, t.exponents, strict=True):
            if e:
                expr *= sym[name] ** e
        if any(t.harmonics):
            arg = sympy.Add(*(v * sym[a] for a, v in zip(ring.angles, t.harmonics, strict=True)))
            expr *= (sympy.cos if t.kind == "cos" else sympy.sin)(arg)
        terms.append(expr)
    return sympy.Add(*terms)


def series_from_sympy(ring: Ring, expr: Any) -> Series:
    """Convert a sympy expression built from the ring's symbols to a series.

    Allowed: rationals, momenta and parameters (integer powers; negative only of monomials),
    ``+``, ``*``, and ``cos``/``sin`` of integer combinations of the angles.  Symbols are
    matched by name.

    Parameters
    ----------
    ring : PoissonRing
    expr : sympy.Expr or str
        A string is parsed with ``sympy.sympify``.

    Returns
    -------
    PoissonSeries

    Examples
    --------
    >>> import sympy
    >>> from andoyer.series import PoissonRing
    >>> q, p = sympy.symbols("q p")
    >>> series_from_sympy(PoissonRing(["q"], ["p"]), p * sympy.cos(q) ** 2)
    1/2*p + 1/2*p*cos(2*q)
    """
    sympy = _sympy()
    if isinstance(expr, str):
        expr = sympy.sympify(expr)
    return _convert(ring, sympy.sympify(expr), sympy)


def _convert(ring: Ring, expr: Any, sympy: Any) -> Series:
    if expr.is_Rational:
        return ring.constant(Fraction(int(expr.p), int(expr.q)))
    if expr.is_Symbol:
        if expr.name in ring.angles:
            msg = f"expected angles only inside cos/sin, got bare angle {expr.name!r}"
            raise ValueError(msg)
        return ring.gen(expr.name)
    if expr.is_Add:
        return sum((_convert(ring, a, sympy) for a in expr.args), ring.zero)
    if expr.is_Mul:
        out = ring.one
        for a in expr.args:
            out = out * _convert(ring, a, sympy)
        return out
    if expr.is_Pow:
        base, exp = expr.args
        if not exp.is_Integer:
            msg = f"expected integer exponents, got {expr}"
            raise ValueError(msg)
        return _convert(ring, base, sympy) ** int(exp)
    if isinstance(expr, (sympy.cos, sympy.sin)):
        k = _harmonic(ring, expr.args[0])
        return ring.cos(k) if isinstance(expr, sympy.cos) else ring.sin(k)
    msg = f"expected a Poisson-series expression, got {expr}"
    raise ValueError(msg)


def _harmonic(ring: Ring, arg: Any) -> tuple[int, ...]:
    k = dict.fromkeys(ring.angles, 0)
    for term, coeff in arg.as_coefficients_dict().items():
        name = getattr(term, "name", None)
        if name not in k or not coeff.is_Integer:
            msg = f"expected an integer combination of the angles {ring.angles}, got {arg}"
            raise ValueError(msg)
        k[name] += int(coeff)
    return tuple(k[a] for a in ring.angles)


def series_to_latex(f: Series) -> str:
    r"""LaTeX form grouping the terms by trigonometric argument.

    Parameters
    ----------
    f : PoissonSeries

    Returns
    -------
    str

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> R = PoissonRing(["l"], ["L", "G"])
    >>> series_to_latex(R("G - (L + G)*sin(l)"))
    'G - \\left(G + L\\right) \\sin{\\left(l \\right)}'
    """
    sympy = _sympy()
    ring = f.ring
    sym = _symbols(ring, None)
    groups: dict[tuple[str, tuple[int, ...]], list[Any]] = {}
    for t in f.terms():
        c = sympy.Rational(t.coeff.numerator, t.coeff.denominator)
        mono = sympy.Mul(*(sym[n] ** e for n, e in zip(ring.poly_names, t.exponents, strict=True)))
        groups.setdefault((t.kind, t.harmonics), []).append(c * mono)
    out = ""
    for (kind, k), parts in groups.items():
        coeff = sympy.Add(*parts)
        sign = ""
        if coeff.could_extract_minus_sign():
            coeff, sign = -coeff, "-"
        if any(k):
            arg = sympy.Add(*(v * sym[a] for a, v in zip(ring.angles, k, strict=True)))
            trig = sympy.latex((sympy.cos if kind == "cos" else sympy.sin)(arg))
            if coeff == 1:
                text = trig
            elif len(parts) > 1:
                text = rf"\left({sympy.latex(coeff)}\right) {trig}"
            else:
                text = f"{sympy.latex(coeff)} {trig}"
        else:
            text = sympy.latex(coeff)
        if not out:
            out = sign + text
        else:
            out += f" - {text}" if sign else f" + {text}"
    return out or "0"
