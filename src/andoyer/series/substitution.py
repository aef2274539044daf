"""Truncation by weighted order, exact substitution and Taylor shifts of Poisson series."""

from __future__ import annotations

from collections.abc import Mapping
from fractions import Fraction
from math import factorial
from typing import TYPE_CHECKING, Any

from andoyer.series.bracket import derivative
from andoyer.series.components import Ring, Series
from andoyer.series.rationals import as_rational

if TYPE_CHECKING:
    from andoyer.series.terms import Term

__all__ = ["substitute", "taylor_shift", "term_order", "truncate"]


def term_order(ring: Ring, term: Term) -> Fraction:
    """Weighted order ``Σ w_x e_x`` of one real term.

    Parameters
    ----------
    ring : PoissonRing
    term : Term

    Returns
    -------
    Fraction

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> R = PoissonRing(["l"], ["L", "G"], weights={"L": 1, "G": -1})
    >>> term_order(R, R("L**3*G*cos(l)").terms()[0])
    Fraction(2, 1)
    """
    return sum(
        (ring.weights.get(n, 0) * e for n, e in zip(ring.poly_names, term.exponents, strict=True)),
        Fraction(0),
    )


def truncate(f: Series, order: Any) -> Series:
    """Drop the terms of weighted order larger than ``order``.

    Parameters
    ----------
    f : PoissonSeries
    order : rational

    Returns
    -------
    PoissonSeries

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> R = PoissonRing(["l"], ["L", "G"], weights={"L": 1, "G": -1})
    >>> truncate(R("G + L + L**2/G + L**3"), 1)
    L + G
    """
    order = as_rational(order, "a rational truncation order")
    ring = f.ring
    if not ring.weights:
        return f if order >= 0 else ring.zero
    w, w_rel = ring._w, ring._w_rel
    base = sum((wi * s for wi, s in zip(w, f._shift, strict=True)), Fraction(0))
    used = [i for i, wi in enumerate(w) if wi]
    comps = {}
    for mask, p in f._comps.items():
        extra = base + sum((wr for j, wr in enumerate(w_rel) if mask >> (j + 1) & 1), Fraction(0))
        keep = {exps: c for exps, c in p.terms() if extra + sum(w[i] * int(exps[i]) for i in used) <= order}
        if len(keep) == len(p):
            comps[mask] = p
        elif keep:
            comps[mask] = ring._ctx.from_dict(keep)
    return f._new(f._shift, comps)


def substitute(f: Series, values: Mapping[str, Any]) -> Series:
    """Substitute momenta or parameters simultaneously by rationals or series.

    Parameters
    ----------
    f : PoissonSeries
    values : mapping of str to rational or PoissonSeries
        Negative powers of a substituted variable require a unit value (rational times
        monomial).  Angles cannot be substituted (use :func:`taylor_shift`).

    Returns
    -------
    PoissonSeries

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> R = PoissonRing(["q"], ["p"], ["a"])
    >>> substitute(R("p**-1 + a*p"), {"p": R("2*a")})
    1/2*a**-1 + 2*a**2
    """
    ring = f.ring
    vals = {}
    for name, v in values.items():
        if name not in ring.poly_names:
            msg = f"expected momenta or parameters {ring.poly_names} to substitute, got {name!r}"
            raise ValueError(msg)
        vals[name] = ring(v)
    if not vals or not f._comps:
        return f
    slots = [(ring._slots[ring.poly_names.index(n)], vals[n]) for n in vals]
    ctx_idx = [slot for (where, slot), _ in slots if where == "ctx"]
    rel_bits = sum(slot for (where, slot), _ in slots if where == "rel")
    shift = list(f._shift)
    for i in ctx_idx:
        shift[i] = 0
    groups: dict[tuple[int, ...], dict[int, dict]] = {}
    for mask, p in f._comps.items():
        for exps, c in p.terms():
            key = tuple(
                int(exps[slot]) + f._shift[slot] if where == "ctx" else int(bool(mask & slot))
                for (where, slot), _ in slots
            )
            rest = list(exps)
            for i in ctx_idx:
                rest[i] = 0
            d = groups.setdefault(key, {}).setdefault(mask & ~rel_bits, {})
            d[tuple(rest)] = c
    powers: dict[tuple[int, int], Series] = {}
    out = ring.zero
    for key, by_mask in groups.items():
        part = f._new(tuple(shift), {m: ring._ctx.from_dict(d) for m, d in by_mask.items()})
        for j, e in enumerate(key):
            if e:
                if (j, e) not in powers:
                    powers[(j, e)] = slots[j][1] ** e
                part = part * powers[(j, e)]
        out = out + part
    return out


def taylor_shift(f: Series, deltas: Mapping[str, Series], order: Any) -> Series:
    """Expand ``f(x + Δ(x))`` in a Taylor series truncated at weighted order ``order``.

    ``f(x + Δ) = Σ_α ∂^α f(x) Δ(x)^α / α!``, exact up to ``order``.  Every increment must
    raise the order: ``order(Δ_x) > weight(x)`` (angles have weight 0).

    Parameters
    ----------
    f : PoissonSeries
    deltas : mapping of str to PoissonSeries
        Increments of angles or momenta (not of relation-bound parameters).
    order : rational

    Returns
    -------
    PoissonSeries

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> R = PoissonRing(["q"], ["p"], ["eps"], weights={"eps": 1})
    >>> taylor_shift(R("p**-1"), {"p": R("eps*p")}, order=2)
    p**-1 - p**-1*eps + p**-1*eps**2
    """
    ring = f.ring
    order = as_rational(order, "a rational truncation order")
    items = []
    for name, delta in deltas.items():
        ring.check(delta)
        if delta.is_zero():
            continue
        weight = ring.weights.get(name, Fraction(0))
        gain = delta.order() - weight
        if gain <= 0:
            msg = f"expected the increment of {name} to have order above {weight}, got order {delta.order()}"
            raise ValueError(msg)
        items.append((name, delta, gain))
    return _expand(f, items, 0, order)


def _expand(g: Series, items: list, i: int, order: Fraction) -> Series:
    if g.is_zero() or g.order() > order:
        return g.ring.zero
    if i == len(items):
        return truncate(g, order)
    name, delta, gain = items[i]
    ring = g.ring
    base = g.order()
    out = ring.zero
    deriv, power, m = g, ring.one, 0
    while not deriv.is_zero() and base + m * gain <= order:
        inner = _expand(deriv, items, i + 1, order)
        if not inner.is_zero():
            term = truncate(power * inner, order) / factorial(m)
            out = out + term
        m += 1
        deriv = derivative(deriv, name)
        if deriv.is_zero():
            break
        power = truncate(power * delta, order - deriv.order())
    return out
