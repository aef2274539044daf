"""Arithmetic on the internal decomposition of a series (shift and basis components).

A series is ``x^shift · Σ_c g^c P_c``: ``x^shift`` a Laurent monomial in the flint variables
(polynomial variables, free parameters and ``z_j = e^{iθ_j}``), ``P_c`` python-flint
``fmpq_mpoly`` polynomials, and ``g^c`` the square-free product of the imaginary unit (bit 0)
and relation generators (bit j+1) selected by the mask ``c``.  These functions work on
``(shift, {mask: poly})`` pairs so that they carry no dependency on the series class.
"""

from __future__ import annotations

from typing import Any

__all__ = [
    "accumulate_products",
    "add_into",
    "aligned",
    "normalized",
    "product_comps",
    "reduce_overlaps",
    "scaled",
    "times_i",
]

Comps = dict[int, Any]
Shift = tuple[int, ...]
# A ring and a series of :mod:`andoyer.series.poisson`, as the modules below it annotate them:
# poisson imports those modules, so they name its classes without importing them (not even for
# type checking: tests/core/test_import_graph.py); their docstrings name the classes.
Ring = Any
Series = Any


def normalized(ring: Ring, shift: Shift, comps: Comps) -> tuple[Shift, Comps]:
    """Drop zero components and move the common monomial factor into the shift.

    Parameters
    ----------
    ring : PoissonRing
    shift : tuple of int
    comps : dict of int to fmpq_mpoly

    Returns
    -------
    (tuple of int, dict of int to fmpq_mpoly)
        The canonical pair: minimum exponent zero in every flint variable.

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> R = PoissonRing(["q"], ["p"])
    >>> p, z = R._ctx.gens()        # flint names z = exp(iq) after the angle: q
    >>> normalized(R, (0, -1), {0: p**2 * z + p**3})
    ((2, -1), {0: p + q})
    """
    comps = {m: p for m, p in comps.items() if not p.is_zero()}
    if not comps:
        return ring._zero_shift, {}
    mins = None
    for p in comps.values():
        e = tuple(map(int, p.term_content().monoms()[0]))
        mins = e if mins is None else tuple(map(min, mins, e))
    if any(mins):
        mono = ring._ctx.term(exp_vec=mins)
        comps = {m: p / mono for m, p in comps.items()}
        shift = tuple(a + b for a, b in zip(shift, mins, strict=True))
    return shift, comps


def scaled(ring: Ring, comps: Comps, diff: Shift) -> Comps:
    """Multiply every component by the monomial ``x^diff`` (nonnegative exponents).

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> R = PoissonRing(["q"], ["p"])
    >>> scaled(R, {0: R._ctx.constant(3)}, (2, 0))
    {0: 3*p^2}
    """
    if not any(diff):
        return comps
    mono = ring._ctx.term(exp_vec=diff)
    return {m: p * mono for m, p in comps.items()}


def aligned(ring: Ring, a: tuple[Shift, Comps], b: tuple[Shift, Comps]) -> tuple[Shift, Comps, Comps]:
    """Rewrite two decompositions over their common (elementwise minimum) shift.

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> R = PoissonRing(["q"], ["p"])
    >>> one = R._ctx.constant(1)
    >>> aligned(R, ((1, 0), {0: one}), ((-1, 0), {0: one}))
    ((-1, 0), {0: p^2}, {0: 1})
    """
    if a[0] == b[0]:
        return a[0], a[1], b[1]
    common = tuple(map(min, a[0], b[0]))
    ca = scaled(ring, a[1], tuple(x - y for x, y in zip(a[0], common, strict=True)))
    cb = scaled(ring, b[1], tuple(x - y for x, y in zip(b[0], common, strict=True)))
    return common, ca, cb


def add_into(out: Comps, comps: Comps, sign: int = 1) -> None:
    """Add (or subtract, ``sign=-1``) components into ``out`` in place.

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> one = PoissonRing(["q"], ["p"])._ctx.constant(1)
    >>> out = {0: one}
    >>> add_into(out, {0: one, 1: one}, sign=-1)
    >>> out
    {0: 0, 1: -1}
    """
    for m, p in comps.items():
        q = p if sign > 0 else -p
        out[m] = out[m] + q if m in out else q


def times_i(comps: Comps) -> Comps:
    """Multiply by the imaginary unit (``i · i = −1``).

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> one = PoissonRing(["q"], ["p"])._ctx.constant(1)
    >>> times_i({0: one, 1: one})
    {1: 1, 0: -1}
    """
    return {m ^ 1: (-p if m & 1 else p) for m, p in comps.items()}


def accumulate_products(acc: dict[tuple[int, int], Any], ca: Comps, cb: Comps) -> None:
    """Add the products of all component pairs into ``acc[(mask_a ^ mask_b, mask_a & mask_b)]``.

    Keeping the overlap mask apart lets :func:`reduce_overlaps` multiply each relation factor
    once per sum rather than once per product.

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> one = PoissonRing(["q"], ["p"])._ctx.constant(1)
    >>> acc = {}
    >>> accumulate_products(acc, {1: one}, {0: one, 1: one})
    >>> acc
    {(1, 0): 1, (0, 1): 1}
    """
    for ma, pa in ca.items():
        for mb, pb in cb.items():
            key = (ma ^ mb, ma & mb)
            prod = pa * pb
            if key in acc:
                acc[key] += prod
            else:
                acc[key] = prod


def reduce_overlaps(ring: Ring, acc: dict[tuple[int, int], Any]) -> Comps:
    """Apply ``i² = −1`` and ``g_j² = D_j`` to accumulated products, merging by result mask.

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> one = PoissonRing(["q"], ["p"])._ctx.constant(1)
    >>> reduce_overlaps(PoissonRing(["q"], ["p"]), {(0, 1): one, (0, 0): one * 3})
    {0: 2}
    """
    out: Comps = {}
    for (target, overlap), p in acc.items():
        q = p
        if overlap == 1:
            q = -p
        elif overlap:
            q = p * ring.overlap_factor(overlap)
        if target in out:
            out[target] += q
        else:
            out[target] = q
    return out


def product_comps(ring: Ring, ca: Comps, cb: Comps) -> Comps:
    """Multiply two decompositions, reducing ``i² = −1`` and ``g_j² = D_j`` (shifts add).

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> R = PoissonRing([], [], ["b", "s"], relations={"b": "1 - s**2"})
    >>> one = R._ctx.constant(1)
    >>> product_comps(R, {2: one}, {2: one})    # b · b = 1 − s²
    {0: -s^2 + 1}
    """
    acc: dict[tuple[int, int], Any] = {}
    accumulate_products(acc, ca, cb)
    return reduce_overlaps(ring, acc)
