"""Partial derivatives and the Poisson bracket of Poisson series."""

from __future__ import annotations

from functools import lru_cache
from typing import Any

from andoyer.series.components import Comps, Ring, Series, Shift, times_i

__all__ = ["derivative", "poisson_bracket"]


def _relation_variables(ring: Ring) -> set[str]:
    names = set(ring._rel)
    ctx_names = ring._free + ring.angles
    for d in ring._rel_polys:
        names.update(n for n, deg in zip(ctx_names, d.degrees(), strict=True) if int(deg))
    return names


def _euler_index(f: Series, i: int) -> Comps:
    """Shift-preserving derivative: ``x ∂f/∂x`` for a polynomial variable, ``∂f/∂θ`` for an angle.

    On ``x^a P`` the Euler operator gives ``x^a (a P + x ∂P/∂x)`` and on ``z^a P``
    (``z = e^{iθ}``) the angle derivative gives ``i z^a (a P + z ∂P/∂z)``: the shift stays.
    ``i`` indexes the flint variables (free polynomial variables, then one ``z`` per angle).
    """
    ring = f.ring
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


def _check_variable(ring: Ring, name: str) -> None:
    if name in _relation_variables(ring):
        msg = (
            "expected a variable independent of the declared relations, "
            f"got {name!r} (it appears in {ring.relations})"
        )
        raise ValueError(msg)
    if name not in ring._index:
        msg = f"expected an angle, momentum or parameter of {ring.variables}, got {name!r}"
        raise ValueError(msg)


def derivative(f: Series, name: str) -> Series:
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
    comps = _euler_index(f, i)
    if i >= ring._nfree:
        return f._new(f._shift, comps)
    shift = list(f._shift)
    shift[i] -= 1
    return f._new(tuple(shift), comps)


@lru_cache(maxsize=64)
def _bracket_layout(ring: Ring) -> tuple[Shift, tuple[tuple[Shift, int, int], ...]]:
    """Common denominator monomial and, per canonical pair, ``(rest, index of q, index of p)``.

    With shift-preserving derivatives (``∂/∂θ``, or ``x ∂/∂x``) the pair ``(q, p)`` contributes
    ``(D_q f D_p g − D_p f D_q g) / (p q)`` (``q`` only for a polynomial coordinate); over the
    common denominator ``M = Π p q`` its numerator is multiplied by ``rest = M / (p q)``.
    """
    nvars = len(ring._zero_shift)
    denoms = []
    for q, p in ring.pairs:
        d = [0] * nvars
        d[ring._index[p]] += 1
        if q not in ring.angles:
            d[ring._index[q]] += 1
        denoms.append(d)
    total = tuple(sum(col) for col in zip(*denoms, strict=True)) if denoms else ring._zero_shift
    layout = tuple(
        (tuple(t - x for t, x in zip(total, d, strict=True)), ring._index[q], ring._index[p])
        for d, (q, p) in zip(denoms, ring.pairs, strict=True)
    )
    return total, layout


def _pairwise_sum(polys: list[Any]) -> Any:
    """Sum by halving rounds: each term is merged about log2(len) times, not len/2 times."""
    while len(polys) > 1:
        merged = [polys[i] + polys[i + 1] for i in range(0, len(polys) - 1, 2)]
        if len(polys) % 2:
            merged.append(polys[-1])
        polys = merged
    return polys[0]


def poisson_bracket(f: Series, g: Series) -> Series:
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
    total, layout = _bracket_layout(ring)
    # Every product of shift-preserving derivatives has the shift of f·g, so all products of all
    # pairs are summed in flint over the common denominator monomial.  The cost is in the large
    # products and their sums: the sign, the overlap factor of the basis (i² = −1, g_j² = D_j)
    # and the monomial ``rest`` are folded into the short left factors, each product goes
    # straight to its result component, and each component is summed pairwise.
    by_mask: dict[int, list[Any]] = {}
    for rest, iq, ip in layout:
        for left, right, sign in (
            (_euler_index(f, iq), _euler_index(g, ip), 1),
            (_euler_index(f, ip), _euler_index(g, iq), -1),
        ):
            if not left or not right:
                continue
            mono = ring._ctx.term(exp_vec=rest) * sign if any(rest) or sign < 0 else None
            for ma, pa in left.items():
                scaled_a = pa * mono if mono is not None else pa
                for mb, pb in right.items():
                    overlap = ma & mb
                    factor = scaled_a
                    if overlap == 1:
                        factor = -scaled_a
                    elif overlap:
                        factor = scaled_a * ring.overlap_factor(overlap)
                    by_mask.setdefault(ma ^ mb, []).append(factor * pb)
    if not by_mask:
        return ring.zero
    comps = {m: _pairwise_sum(ps) for m, ps in by_mask.items()}
    shift = tuple(a + b - t for a, b, t in zip(f._shift, g._shift, total, strict=True))
    return f._new(shift, comps)
