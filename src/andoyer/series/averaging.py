"""Averaging over angles and the homological equation of normal-form theory."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

from flint.utils.flint_exceptions import DomainError

from andoyer.series.bracket import derivative
from andoyer.series.components import Ring, Series, times_i

__all__ = ["average", "frequencies", "solve_homological"]


def _angle_indices(ring: Ring, angles: Sequence[str] | None) -> list[int]:
    if angles is None:
        angles = ring.angles
    if isinstance(angles, str) or not set(angles) <= set(ring.angles):
        msg = f"expected a sequence of angles of {ring.angles}, got {angles!r}"
        raise ValueError(msg)
    return [ring._index[a] for a in angles]


def _split(f: Series, idx: list[int]) -> dict[tuple[int, ...], dict[int, dict]]:
    """Group the exponential terms by their harmonic in the angles ``idx``."""
    shift = f._shift
    groups: dict[tuple[int, ...], dict[int, dict]] = {}
    for mask, p in f._comps.items():
        for exps, c in p.terms():
            key = tuple(int(exps[i]) + shift[i] for i in idx)
            groups.setdefault(key, {}).setdefault(mask, {})[exps] = c
    return groups


def _from_groups(f: Series, by_mask: dict[int, dict]) -> Series:
    ctx = f.ring._ctx
    return f._new(f._shift, {m: ctx.from_dict(d) for m, d in by_mask.items()})


def average(f: Series, angles: Sequence[str] | None = None) -> Series:
    """Average ``⟨f⟩ = (2π)^(−n) ∮ f dθ`` over the given angles.

    Parameters
    ----------
    f : PoissonSeries
    angles : sequence of str, optional
        Angles to average over; default all.

    Returns
    -------
    PoissonSeries
        The terms of ``f`` whose harmonic vanishes in ``angles``.

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> R = PoissonRing(["q"], ["p"])
    >>> average(R("(p + cos(q))**2"))
    1/2 + p**2
    """
    idx = _angle_indices(f.ring, angles)
    if not idx or not f._comps:
        return f
    zero = (0,) * len(idx)
    part = _split(f, idx).get(zero)
    return _from_groups(f, part) if part else f.ring.zero


def frequencies(H0: Series) -> dict[str, Series]:
    """Frequencies ``ω_j = ∂H0/∂p_j`` of the angles, for ``H0`` depending on momenta only.

    Parameters
    ----------
    H0 : PoissonSeries
        Must not depend on angles, nor on pairs whose coordinate is polynomial.

    Returns
    -------
    dict of str to PoissonSeries
        One entry per angle (zero for an angle without a conjugate momentum).

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> R = PoissonRing(["l", "g"], ["L", "G"], ["a"])
    >>> frequencies(R("a*L*G + G**2/2"))
    {'l': G*a, 'g': G + L*a}
    """
    ring = H0.ring
    nf = ring._nfree
    if any(t.harmonics != (0,) * len(ring.angles) for t in H0.terms()) or any(H0._shift[nf:]):
        msg = f"expected H0 independent of the angles, got {H0}"
        raise ValueError(msg)
    out = dict.fromkeys(ring.angles, ring.zero)
    for q, p in ring.pairs:
        if q in ring.angles:
            out[q] = derivative(H0, p)
        elif not (derivative(H0, q).is_zero() and derivative(H0, p).is_zero()):
            msg = f"expected H0 independent of the polynomial pair ({q}, {p}), got {H0}"
            raise ValueError(msg)
    return out


def _divide(g: Series, d: Series, k: Any) -> Series:
    if d.is_zero():
        msg = f"expected a nonresonant harmonic, got k·ω = 0 for k = {k}"
        raise ValueError(msg)
    if d.is_unit():
        return g * d.inverse()
    if list(d._comps) != [0]:
        msg = f"expected a divisor k·ω free of relation generators, got {d} for k = {k}"
        raise ValueError(msg)
    pd = d._comps[0]
    try:
        comps = {m: p / pd for m, p in g._comps.items()}
    except DomainError:
        msg = (
            f"expected k·ω = {d} (k = {k}) to divide the coefficient {g} exactly "
            "(rational-function coefficients are not supported)"
        )
        raise ValueError(msg) from None
    shift = tuple(a - b for a, b in zip(g._shift, d._shift, strict=True))
    return g._new(shift, comps)


def solve_homological(
    f: Series,
    H0: Series | Mapping[str, Series],
    angles: Sequence[str] | None = None,
) -> Series:
    """Solve ``{H0, W} + f − ⟨f⟩ = 0`` for ``W`` with zero average.

    With ``H0`` depending on momenta only, ``{H0, W} = −Σ ω_j ∂W/∂θ_j`` with
    ``ω_j = ∂H0/∂p_j``; each term of ``f`` with harmonic ``k`` (nonzero in ``angles``) is
    divided by ``k·ω``.  ``⟨f⟩`` is the average over ``angles``.  The divisor ``k·ω`` must be
    a monomial or divide the coefficient exactly.

    Parameters
    ----------
    f : PoissonSeries
        Right-hand side.
    H0 : PoissonSeries or mapping of str to PoissonSeries
        Unperturbed Hamiltonian, a function of the momenta (and parameters) only, or directly
        its frequencies ``{angle: ω}`` (angle-free series; missing angles have ω = 0).
    angles : sequence of str, optional
        Angles to remove; default all.

    Returns
    -------
    PoissonSeries
        The generator ``W`` (no terms with zero harmonic in ``angles``).

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> R = PoissonRing(["q"], ["p"])
    >>> H0, f = R("p**2/2"), R("p*cos(q) + p")
    >>> W = solve_homological(f, H0)
    >>> W
    sin(q)
    >>> H0.bracket(W) + f - f.average()
    0
    >>> solve_homological(f, {"q": R("p")}) == W
    True
    """
    ring = f.ring
    idx = _angle_indices(ring, angles)
    if isinstance(H0, Mapping):
        omega = dict.fromkeys(ring.angles, ring.zero)
        for a, w in H0.items():
            if a not in omega or any(any(t.harmonics) for t in w.terms()):
                msg = f"expected angle-free frequencies keyed by {ring.angles}, got {a!r}: {w}"
                raise ValueError(msg)
            ring.check(w)
            omega[a] = w
    else:
        ring.check(H0)
        omega = frequencies(H0)
    if not f._comps or not idx:
        return ring.zero
    nf = ring._nfree
    all_idx = list(range(nf, nf + len(ring.angles)))
    chosen = [all_idx.index(i) for i in idx]
    out = ring.zero
    for k, by_mask in _split(f, all_idx).items():
        if not any(k[j] for j in chosen):
            continue
        g = _from_groups(f, by_mask)
        d = sum((omega[a] * v for a, v in zip(ring.angles, k, strict=True) if v), ring.zero)
        # w_k = f_k / (i k·ω) = −i f_k / (k·ω)
        minus_i_g = g._new(g._shift, {m: -p for m, p in times_i(g._comps).items()})
        out = out + _divide(minus_i_g, d, k)
    return out
