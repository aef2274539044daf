"""Conversion between real trigonometric terms and the exponential decomposition.

With ``z = e^{iθ}``: ``cos(k·θ) = (z^k + z^−k)/2`` and ``sin(k·θ) = (−i/2) z^k + (i/2) z^−k``.
A real series has ``c_−k = conj(c_k)``, so its real terms are read off the harmonics whose
first nonzero entry is positive: ``a_k = 2 Re c_k`` (cosine) and ``b_k = −2 Im c_k`` (sine).
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from fractions import Fraction
from typing import Any, NamedTuple

from andoyer.series.components import Comps, Ring, Shift, add_into, aligned, normalized, product_comps
from andoyer.series.rationals import as_rational, to_fmpq

__all__ = ["Term", "decompose", "harmonic_sign", "real_terms"]


class Term(NamedTuple):
    """One real term ``coeff · Π x^exponents · kind(harmonics·θ)`` of a Poisson series.

    ``exponents`` follow ``ring.poly_names`` (momenta, then parameters); ``kind`` is
    ``"cos"`` or ``"sin"``; ``harmonics`` has its first nonzero entry positive.
    """

    coeff: Fraction
    exponents: tuple[int, ...]
    kind: str
    harmonics: tuple[int, ...]


def harmonic_sign(k: Sequence[int]) -> int:
    """Sign of the first nonzero entry (0 for the zero harmonic).

    Examples
    --------
    >>> harmonic_sign((0, -2, 1)), harmonic_sign((0, 0))
    (-1, 0)
    """
    for v in k:
        if v:
            return 1 if v > 0 else -1
    return 0


def real_terms(ring: Ring, shift: Shift, comps: Comps) -> tuple[Term, ...]:
    """Real terms of a decomposition, sorted by harmonic, kind and total degree.

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> f = PoissonRing(["q"], ["p"])("2*p*sin(q)")
    >>> real_terms(f.ring, f._shift, f._comps)
    (Term(coeff=Fraction(2, 1), exponents=(1,), kind='sin', harmonics=(1,)),)
    """
    nf = ring._nfree
    out: dict[tuple[Any, ...], Fraction] = {}
    for mask, p in comps.items():
        imag = mask & 1
        for exps, c in p.terms():
            full = [int(e) + s for e, s in zip(exps, shift, strict=True)]
            k = tuple(full[nf:])
            sign = harmonic_sign(k)
            if sign < 0:
                continue
            e = tuple(
                full[slot] if where == "ctx" else (1 if mask & slot else 0) for where, slot in ring._slots
            )
            value = Fraction(int(c.p), int(c.q))
            if sign == 0 and imag:
                msg = "internal error: imaginary constant term in a real series"
                raise AssertionError(msg)
            if sign == 0:
                out[(k, 0, e)] = value
            elif imag:
                out[(k, 1, e)] = -2 * value
            else:
                out[(k, 0, e)] = 2 * value

    def key(t: tuple[Any, ...]) -> tuple[Any, ...]:
        return (sum(map(abs, t[0])), t[0], t[1], sum(t[2]), [-x for x in t[2]])

    return tuple(Term(out[t], t[2], ("cos", "sin")[t[1]], t[0]) for t in sorted(out, key=key))


def _entries(
    ring: Ring, term: Sequence[Any]
) -> tuple[tuple[int, ...], list[tuple[int, tuple[int, ...], Fraction]]]:
    if len(term) != 4:
        msg = f"expected terms (coeff, exponents, kind, harmonics), got {term!r}"
        raise ValueError(msg)
    coeff, exps, kind, k = term
    c = as_rational(coeff)
    e = ring.exponent_vector(exps)
    k = ring.harmonic_vector(k)
    if kind not in ("cos", "sin"):
        msg = f"expected kind 'cos' or 'sin', got {kind!r}"
        raise ValueError(msg)
    free = [0] * ring._nfree
    relexp = [0] * len(ring._rel)
    for (where, slot), v in zip(ring._slots, e, strict=True):
        if where == "ctx":
            free[slot] = v
        else:
            relexp[slot.bit_length() - 2] = v
    rel_mask = sum(1 << (j + 1) for j, v in enumerate(relexp) if v % 2)
    halves = tuple(v // 2 for v in relexp)
    neg = tuple(-v for v in k)
    half = Fraction(1, 2)
    if not any(k):
        return halves, ([] if kind == "sin" else [(rel_mask, (*free, *k), c)])
    if kind == "cos":
        return halves, [(rel_mask, (*free, *k), c * half), (rel_mask, (*free, *neg), c * half)]
    return halves, [
        (rel_mask | 1, (*free, *k), -c * half),
        (rel_mask | 1, (*free, *neg), c * half),
    ]


def decompose(ring: Ring, terms: Iterable[Sequence[Any]]) -> tuple[Shift, Comps]:
    """Exponential decomposition of real terms ``(coeff, exponents, kind, harmonics)``.

    Powers ``x^n`` of a relation generator become ``x^(n mod 2) D^(n // 2)``.

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> R = PoissonRing(["q"], ["p"])
    >>> decompose(R, [(1, [1], "cos", [1])])     # p cos q = p (z + 1/z)/2, z printed as q
    ((1, -1), {0: 1/2*q^2 + 1/2})
    """
    groups: dict[tuple[int, ...], dict[int, dict[tuple[int, ...], Fraction]]] = {}
    for term in terms:
        halves, entries = _entries(ring, term)
        group = groups.setdefault(halves, {})
        for mask, full, value in entries:
            d = group.setdefault(mask, {})
            d[full] = d.get(full, 0) + value
    total: tuple[Shift, Comps] = (ring._zero_shift, {})
    for halves, by_mask in groups.items():
        every = [full for d in by_mask.values() for full, v in d.items() if v]
        if not every:
            continue
        shift = tuple(map(min, *every)) if len(every) > 1 else every[0]
        comps = {
            m: ring._ctx.from_dict(
                {
                    tuple(x - s for x, s in zip(full, shift, strict=True)): to_fmpq(v)
                    for full, v in d.items()
                    if v
                }
            )
            for m, d in by_mask.items()
        }
        for j, h in enumerate(halves):
            if h:
                comps = product_comps(ring, comps, {0: ring._rel_polys[j] ** h})
        common, ca, cb = aligned(ring, total, (shift, comps))
        out = dict(ca)
        add_into(out, cb)
        total = normalized(ring, common, out)
    return total
