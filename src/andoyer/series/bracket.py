"""Partial derivatives and the Poisson bracket of Poisson series."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from andoyer.series.algebra import product_comps, times_i

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
    if name in _relation_variables(ring):
        msg = (
            "expected a variable independent of the declared relations, "
            f"got {name!r} (it appears in {ring.relations})"
        )
        raise ValueError(msg)
    if name not in ring._index:
        msg = f"expected an angle, momentum or parameter of {ring.variables}, got {name!r}"
        raise ValueError(msg)
    if not f._comps:
        return f
    i = ring._index[name]
    a = f._shift[i]
    gen = ring._ctx.gens()[i]
    if i >= ring._nfree:  # angle: i · (a P + z ∂P/∂z), same shift
        comps = {m: p * a + p.derivative(i) * gen for m, p in f._comps.items()}
        return f._new(f._shift, times_i(comps))
    if a == 0:
        return f._new(f._shift, {m: p.derivative(i) for m, p in f._comps.items()})
    shift = list(f._shift)
    shift[i] -= 1
    comps = {m: p * a + p.derivative(i) * gen for m, p in f._comps.items()}
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
    # Accumulate products at a common shift and normalise once.
    parts = []
    for q, p in ring.pairs:
        fq, gp = derivative(f, q), derivative(g, p)
        fp, gq = derivative(f, p), derivative(g, q)
        if fq._comps and gp._comps:
            parts.append((1, fq, gp))
        if fp._comps and gq._comps:
            parts.append((-1, fp, gq))
    if not parts:
        return ring.zero
    shifts = [tuple(x + y for x, y in zip(a._shift, b._shift, strict=True)) for _, a, b in parts]
    common = tuple(map(min, *shifts)) if len(shifts) > 1 else shifts[0]
    out: dict[int, Any] = {}
    for (sign, a, b), shift in zip(parts, shifts, strict=True):
        comps = product_comps(ring, a._comps, b._comps)
        diff = tuple(x - y for x, y in zip(shift, common, strict=True))
        mono = ring._ctx.term(coeff=sign, exp_vec=diff)
        for m, poly in comps.items():
            term = poly * mono
            out[m] = out[m] + term if m in out else term
    return f._new(common, out)
