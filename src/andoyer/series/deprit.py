"""Deprit's Lie-transform method: normalisation, generator, direct and inverse transformations.

Conventions (Deprit 1969).  ``H = Σ εⁿ/n! Hₙ`` in old variables ``x``; the generator
``W = Σ εⁿ/n! Wₙ₊₁`` defines ``x = X(y; ε)`` through ``dx/dε = J∇W`` and the Lie derivative
``L_W f = {f, W}`` (bracket of :func:`~andoyer.series.poisson_bracket`).  Deprit's triangle

    f_n^(q) = f_(n+1)^(q−1) + Σ_(k=0)^n C(n, k) {f_(n−k)^(q−1), W_(k+1)}

maps ``f(x; ε) = Σ εⁿ/n! f_n^(0)(x)`` to ``f(X(y; ε); ε) = Σ εⁿ/n! f_0^(n)(y)``.  At each order
``W_n`` solves ``{H₀, W_n} + H̃_n − ⟨H̃_n⟩ = 0`` so that the new Hamiltonian
``K_n = f_0^(n) = ⟨H̃_n⟩`` is averaged over the chosen angles.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from math import comb, factorial
from typing import Any

from andoyer.series.averaging import average, frequencies, solve_homological
from andoyer.series.bracket import derivative, poisson_bracket
from andoyer.series.poisson import PoissonRing, PoissonSeries
from andoyer.series.rationals import as_rational

__all__ = ["LieTransform", "deprit", "lie_sum"]


@dataclass(frozen=True)
class _Angle:
    """The (non-periodic) angle coordinate θ itself, allowed as the zeroth entry of a triangle."""

    name: str


def _lie(ring: PoissonRing, f: PoissonSeries | _Angle, w: PoissonSeries) -> PoissonSeries:
    if isinstance(f, _Angle):  # {θ, W} = ∂W/∂p for the pair (θ, p)
        for q, p in ring.pairs:
            if q == f.name:
                return derivative(w, p)
        return ring.zero
    return poisson_bracket(f, w)


def lie_sum(terms: Sequence[PoissonSeries], eps: Any = 1) -> PoissonSeries:
    """Sum ``Σ εⁿ/n! termsₙ`` for a rational or a series ``ε``.

    Parameters
    ----------
    terms : sequence of PoissonSeries
        Coefficients in Deprit's factorial convention.
    eps : rational or PoissonSeries, optional
        Value of the small parameter (default 1: the ordering is carried by the terms).

    Returns
    -------
    PoissonSeries

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> R = PoissonRing(["q"], ["p"], ["e"])
    >>> lie_sum([R("p"), R("p**2"), R("2*p**3")], R("e"))
    p + p**2*e + p**3*e**2
    """
    if not terms:
        msg = "expected at least one term, got an empty sequence"
        raise ValueError(msg)
    ring = terms[0].ring
    eps = eps if isinstance(eps, PoissonSeries) else ring.constant(as_rational(eps))
    out, power = ring.zero, ring.one
    for n, t in enumerate(terms):
        if n:
            power = power * eps
        if not t.is_zero():
            out = out + power * t / factorial(n)
    return out


class LieTransform:
    """A Lie transformation ``x = X(y; ε)`` of Deprit's type, given by its generator.

    Usually obtained from :func:`deprit`.

    Parameters
    ----------
    generator : sequence of PoissonSeries
        ``(W₁, …, W_N)`` with ``W = Σ εⁿ/n! Wₙ₊₁``.
    new_hamiltonian : sequence of PoissonSeries, optional
        ``(K₀, …, K_N)`` when the transform comes from a normalisation.

    Attributes
    ----------
    order : int
        ``N``: every transformed series is exact through ``ε^N``.
    ring : PoissonRing

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> R = PoissonRing(["q"], ["p"])
    >>> T = LieTransform([R("p")])       # W = p: a shift of q by ε
    >>> T.direct_angle("q")
    (0, 1)
    >>> T.inverse(R("cos(q)"))
    (cos(q), sin(q))
    """

    def __init__(
        self,
        generator: Sequence[PoissonSeries],
        new_hamiltonian: Sequence[PoissonSeries] | None = None,
    ) -> None:
        if not generator:
            msg = "expected at least one generator term W_1, got none"
            raise ValueError(msg)
        self.ring = generator[0].ring
        for w in generator:
            self.ring.check(w)
        self.generator = tuple(generator)
        self.order = len(self.generator)
        self.new_hamiltonian = tuple(new_hamiltonian) if new_hamiltonian is not None else None

    def _terms(self, f: Any) -> list[Any]:
        ring = self.ring
        if isinstance(f, _Angle):
            head: list[Any] = [f]
        elif isinstance(f, str):
            if f in ring.angles:
                msg = f"expected a series or momentum, got angle {f!r} (use direct_angle)"
                raise ValueError(msg)
            head = [ring.gen(f)]
        elif isinstance(f, PoissonSeries):
            head = [f]
        else:
            head = list(f)
            for t in head:
                ring.check(t)
        if len(head) > self.order + 1:
            msg = f"expected at most {self.order + 1} ε-terms, got {len(head)}"
            raise ValueError(msg)
        return head + [ring.zero] * (self.order + 1 - len(head))

    def _w(self, k: int) -> PoissonSeries:
        return self.generator[k - 1]

    def direct(self, f: Any) -> tuple[PoissonSeries, ...]:
        """Express a function of the old variables in the new ones: ``f(X(y; ε))``.

        Parameters
        ----------
        f : PoissonSeries, str or sequence of PoissonSeries
            A series, a momentum/parameter name, or ``(f₀, f₁, …)`` for
            ``f = Σ εⁿ/n! fₙ``.

        Returns
        -------
        tuple of PoissonSeries
            ``(F₀, …, F_N)`` with ``f(X(y; ε)) = Σ εⁿ/n! Fₙ(y) + O(ε^(N+1))``.

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["q"], ["p"])
        >>> LieTransform([R("sin(q)")]).direct("p")    # p = p' − ε cos q' + …
        (p, -cos(q))
        """
        fs = self._terms(f)
        n_max, ring = self.order, self.ring
        table = [fs]  # table[q][m] = f_m^(q)
        out = [fs[0]]
        for n in range(1, n_max + 1):
            for q in range(1, n + 1):
                m = n - q
                if len(table) <= q:
                    table.append([None] * (n_max + 1))
                acc = table[q - 1][m + 1]
                for k in range(m + 1):
                    acc = acc + comb(m, k) * _lie(ring, table[q - 1][m - k], self._w(k + 1))
                table[q][m] = acc
            out.append(table[n][0])
        return tuple(out)

    def inverse(self, f: Any) -> tuple[PoissonSeries, ...]:
        """Express a function of the new variables in the old ones: ``f(Y(x; ε))``.

        Parameters
        ----------
        f : PoissonSeries, str or sequence of PoissonSeries
            As in :meth:`direct`, now a function of the new variables.

        Returns
        -------
        tuple of PoissonSeries
            ``(F₀, …, F_N)`` with ``f(Y(x; ε)) = Σ εⁿ/n! Fₙ(x) + O(ε^(N+1))``.

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["q"], ["p"])
        >>> LieTransform([R("sin(q)")]).inverse("p")
        (p, cos(q))
        """
        gs = self._terms(f)
        n_max, ring = self.order, self.ring
        table: list[list[Any]] = [[None] * (n_max + 2) for _ in range(n_max + 1)]
        table[0][0] = gs[0]
        for n in range(1, n_max + 1):
            table[n][0] = gs[n]
            for q in range(n, 0, -1):
                m = n - q
                acc = table[q][m]
                for k in range(m + 1):
                    acc = acc - comb(m, k) * _lie(ring, table[q - 1][m - k], self._w(k + 1))
                table[q - 1][m + 1] = acc
        return (gs[0], *(table[0][n] for n in range(1, n_max + 1)))

    def _angle(self, name: str) -> _Angle:
        if name not in self.ring.angles:
            msg = f"expected an angle of {self.ring.angles}, got {name!r}"
            raise ValueError(msg)
        return _Angle(name)

    def direct_angle(self, name: str) -> tuple[PoissonSeries, ...]:
        """Old angle in new variables: ``θ = θ' + Σ εⁿ/n! Δₙ(y)``.

        Parameters
        ----------
        name : str

        Returns
        -------
        tuple of PoissonSeries
            ``(0, Δ₁, …, Δ_N)``: the periodic correction, without ``θ'`` itself.

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["q"], ["p"])
        >>> LieTransform([R("p**2/2")]).direct_angle("q")
        (0, p)
        """
        return (self.ring.zero, *self.direct(self._angle(name))[1:])

    def inverse_angle(self, name: str) -> tuple[PoissonSeries, ...]:
        """New angle in old variables: ``θ' = θ + Σ εⁿ/n! Δₙ(x)``.

        Parameters
        ----------
        name : str

        Returns
        -------
        tuple of PoissonSeries
            ``(0, Δ₁, …, Δ_N)``.

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["q"], ["p"])
        >>> LieTransform([R("p**2/2")]).inverse_angle("q")
        (0, -p)
        """
        return (self.ring.zero, *self.inverse(self._angle(name))[1:])


def deprit(
    hamiltonian: Sequence[PoissonSeries], order: int, angles: Sequence[str] | None = None
) -> LieTransform:
    """Normalise ``H = Σ εⁿ/n! Hₙ`` by Deprit's Lie transforms, averaging over ``angles``.

    Parameters
    ----------
    hamiltonian : sequence of PoissonSeries
        ``(H₀, H₁, …)``; ``H₀`` depends on momenta (and parameters) only; missing orders are
        zero.
    order : int
        ``N ≥ 1``: the new Hamiltonian and generator are computed through ``ε^N``.
    angles : sequence of str, optional
        Angles removed from the new Hamiltonian; default all.

    Returns
    -------
    LieTransform
        With ``new_hamiltonian = (K₀, …, K_N)``, ``K = Σ εⁿ/n! Kₙ``, and
        ``generator = (W₁, …, W_N)``.

    Examples
    --------
    Duffing oscillator ``p²/2 + q²/2 + ε q⁴/4`` in action–angle variables of the harmonic
    oscillator (``q = √(2J) sin φ``):

    >>> from andoyer.series import PoissonRing
    >>> R = PoissonRing(["phi"], ["J"])
    >>> H1 = R("J**2 * sin(phi)**4")
    >>> T = deprit([R("J"), H1], order=3)
    >>> T.new_hamiltonian
    (J, 3/8*J**2, -17/32*J**3, 1125/512*J**4)
    >>> T.generator[0]
    -1/4*J**2*sin(2*phi) + 1/32*J**2*sin(4*phi)
    """
    if not isinstance(order, int) or isinstance(order, bool) or order < 1:
        msg = f"expected an integer order >= 1, got {order!r}"
        raise ValueError(msg)
    hs = list(hamiltonian)
    if not hs:
        msg = "expected at least H0, got an empty Hamiltonian"
        raise ValueError(msg)
    ring = hs[0].ring
    for h in hs:
        ring.check(h)
    if len(hs) > order + 1:
        msg = f"expected at most order + 1 = {order + 1} terms Hₙ, got {len(hs)}"
        raise ValueError(msg)
    hs += [ring.zero] * (order + 1 - len(hs))
    H0 = hs[0]
    frequencies(H0)  # validates H0 before the work starts
    table: list[list[Any]] = [hs] + [[None] * (order + 1) for _ in range(order)]
    ws: list[PoissonSeries] = []
    ks = [H0]
    for n in range(1, order + 1):
        for q in range(1, n + 1):
            m = n - q
            acc = table[q - 1][m + 1]
            for k in range(m + 1):
                if k + 1 == n:
                    continue  # {H0, W_n}: added once W_n is known
                acc = acc + comb(m, k) * poisson_bracket(table[q - 1][m - k], ws[k])
            table[q][m] = acc
        tilde = table[n][0]
        kn = average(tilde, angles)
        wn = solve_homological(tilde, H0, angles)
        correction = kn - tilde  # = {H0, W_n}
        for q in range(1, n + 1):
            table[q][n - q] = table[q][n - q] + correction
        ws.append(wn)
        ks.append(kn)
    return LieTransform(ws, ks)
