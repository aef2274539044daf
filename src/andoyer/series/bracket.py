"""Partial derivatives and the Poisson bracket of Poisson series."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from andoyer.series.algebra import (
    Comps,
    accumulate_products,
    reduce_overlaps,
    scaled,
    times_i,
)

if TYPE_CHECKING:
    from andoyer.series.poisson import PoissonSeries
    from andoyer.series.ring import PoissonRing

__all__ = ["derivative", "poisson_bracket"]


def _relation_variables(ring: PoissonRing) -> set[str]:
    names = set(ring._rel)
    ctx_names = ring._free + ring.angles
    for d in ring._rel_polys:
        names.update(n for n, deg in zip(ctx_names, d.degrees(), strict=True) if int(deg))
    return names


def _euler(f: PoissonSeries, name: str) -> Comps:
    """Shift-preserving derivative: ``x ∂f/∂x`` for a polynomial variable, ``∂f/∂θ`` for an angle.

    On ``x^a P`` the Euler operator gives ``x^a (a P + x ∂P/∂x)`` and on ``z^a P``
    (``z = e^{iθ}``) the angle derivative gives ``i z^a (a P + z ∂P/∂z)``: the shift stays.
    """
    ring = f.ring
    i = ring._index[name]
    a = f._shift[i]
    gen = ring._ctx.gens()[i]
    comps = {}
    for m, p in f._comps.items():
        d = p.derivative(i) * gen
        if a:
            d += p * a
        if not d.is_zero():
            comps[m] = d
    return times_i(comps) if i >= ring._nfree else comps


def _check_variable(ring: PoissonRing, name: str) -> None:
    if name in _relation_variables(ring):
        msg = (
            "expected a variable independent of the declared relations, "
            f"got {name!r} (it appears in {ring.relations})"
        )
        raise ValueError(msg)
    if name not in ring._index:
        msg = f"expected an angle, momentum or parameter of {ring.variables}, got {name!r}"
        raise ValueError(msg)


def derivative(f: PoissonSeries, name: str) -> PoissonSeries:
    """Partial derivative of a series with respect to an angle, momentum or free parameter.

    The derivative of ``x^a · P`` is ``x^(a−1) (a P + x ∂P/∂x)``; for an angle ``θ`` with
    ``z = e^{iθ}`` it is ``i z ∂/∂z``.

    Parameters
    ----------
    f : PoissonSeries
    name : str
        An angle, a momentum or a parameter that is neither a relation generator nor used in
        a relation (those are not independent variables).

    Returns
    -------
    PoissonSeries

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> R = PoissonRing(["q"], ["p"], ["a"])
    >>> derivative(R("a*p**3*sin(q)"), "p")
    3*p**2*a*sin(q)
    """
    ring = f.ring
    _check_variable(ring, name)
    if not f._comps:
        return f
    i = ring._index[name]
    comps = _euler(f, name)
    if i >= ring._nfree:
        return f._new(f._shift, comps)
    shift = list(f._shift)
    shift[i] -= 1
    return f._new(tuple(shift), comps)


def poisson_bracket(f: PoissonSeries, g: PoissonSeries) -> PoissonSeries:
    """Poisson bracket over the ring's canonical pairs.

    ``{f, g} = Σ_(q,p) (∂f/∂q ∂g/∂p − ∂f/∂p ∂g/∂q)``, so ``{q, p} = 1``.  With this sign the
    Lie derivative of Deprit's method is ``L_W f = {f, W}``.

    Parameters
    ----------
    f, g : PoissonSeries
        Series of the same ring.

    Returns
    -------
    PoissonSeries

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> R = PoissonRing(["l", "g"], ["L", "G"])
    >>> poisson_bracket(R("L**2*cos(l - g)"), R("G*L"))
    L**3*sin(l - g) - L**2*G*sin(l - g)
    """
    ring = f.ring
    ring.check(g)
    if not f._comps or not g._comps:
        return ring.zero
    # With shift-preserving derivatives D (∂/∂θ, or x ∂/∂x = x · ∂/∂x) every product has the
    # shift of f·g; the division by the momenta (and polynomial coordinates) is one monomial
    # M, folded into the left factors so that all products land in one accumulator.
    nvars = len(ring._zero_shift)
    denom = [[0] * nvars for _ in ring.pairs]
    for j, (q, p) in enumerate(ring.pairs):
        denom[j][ring._index[p]] += 1
        if q not in ring.angles:
            denom[j][ring._index[q]] += 1
    total = [sum(col) for col in zip(*denom, strict=True)] if denom else [0] * nvars
    acc: dict[tuple[int, int], Any] = {}
    for j, (q, p) in enumerate(ring.pairs):
        fq, gp = _euler(f, q), _euler(g, p)
        fp, gq = _euler(f, p), _euler(g, q)
        rest = tuple(t - d for t, d in zip(total, denom[j], strict=True))
        if fq and gp:
            accumulate_products(acc, scaled(ring, fq, rest), gp)
        if fp and gq:
            minus = {m: -poly for m, poly in fp.items()}
            accumulate_products(acc, scaled(ring, minus, rest), gq)
    if not acc:
        return ring.zero
    shift = tuple(a + b - t for a, b, t in zip(f._shift, g._shift, total, strict=True))
    return f._new(shift, reduce_overlaps(ring, acc))
