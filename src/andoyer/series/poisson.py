"""Poisson series with exact rational coefficients: the :class:`PoissonSeries` type.

A Poisson series is a finite sum ``Σ c · x^e · cos(k·θ)`` or ``… sin(k·θ)`` with rational ``c``,
Laurent monomials ``x^e`` in the momenta and parameters and integer harmonics ``k``.  Its
internal form (see :mod:`andoyer.series.algebra`) uses ``z = e^{iθ}`` and python-flint
polynomials, so that a product is a handful of C-level polynomial products.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping, Sequence
from typing import TYPE_CHECKING, Any

from andoyer.series import text
from andoyer.series.algebra import Comps, Shift, add_into, aligned, normalized, product_comps
from andoyer.series.calculus import CalculusMixin
from andoyer.series.conversions import ConversionsMixin
from andoyer.series.rationals import EXACT_TYPES, to_fmpq
from andoyer.series.terms import Term, harmonic_sign, real_terms

if TYPE_CHECKING:
    from andoyer.series.ring import PoissonRing

__all__ = ["PoissonSeries", "make_series"]


def make_series(ring: PoissonRing, shift: Shift, comps: Comps) -> PoissonSeries:
    """Canonical series from a decomposition ``x^shift · Σ g^c P_c``.

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> R = PoissonRing(["q"], ["p"])
    >>> make_series(R, (-1, 0), {0: R._ctx.gens()[0] ** 3})
    p**2
    """
    shift, comps = normalized(ring, shift, comps)
    return PoissonSeries(ring, shift, comps)


class PoissonSeries(CalculusMixin, ConversionsMixin):
    """An exact Poisson series ``Σ c · x^e · {cos, sin}(k·θ)``; immutable.

    Build series from a :class:`~andoyer.series.PoissonRing` (``R("L**2*cos(2*l)")``,
    :meth:`~andoyer.series.PoissonRing.gen`, :meth:`~andoyer.series.PoissonRing.cos`, ...)
    and combine them with ``+ - *``, ``/`` (by a rational or a monomial) and ``**``.
    Equal series compare equal: the representation is canonical.

    Examples
    --------
    >>> from andoyer.series import PoissonRing
    >>> R = PoissonRing(["q"], ["p"])
    >>> f = R("p*cos(q)")
    >>> f * f
    1/2*p**2 + 1/2*p**2*cos(2*q)
    >>> f.bracket(R("p**2/2")) == f.diff("q") * R("p")
    True
    """

    __slots__ = ("_comps", "_ring", "_shift", "_terms")

    def __init__(self, ring: PoissonRing, shift: tuple[int, ...], comps: Comps) -> None:
        self._ring = ring
        self._shift = shift
        self._comps = comps
        self._terms: tuple[Term, ...] | None = None

    def _new(self, shift: Shift, comps: Comps) -> PoissonSeries:
        return make_series(self._ring, shift, comps)

    # ------------------------------------------------------------------ basic protocol
    @property
    def ring(self) -> PoissonRing:
        """The :class:`~andoyer.series.PoissonRing` of this series.

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> PoissonRing(["q"], ["p"])("p").ring.momenta
        ('p',)
        """
        return self._ring

    def is_zero(self) -> bool:
        """Whether the series is zero.

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["q"], ["p"])
        >>> (R("p") - R("p")).is_zero()
        True
        """
        return not self._comps

    def _coerce(self, other: Any) -> PoissonSeries | None:
        if isinstance(other, PoissonSeries):
            self._ring.check(other)
            return other
        if isinstance(other, EXACT_TYPES) and not isinstance(other, bool):
            return self._ring.constant(other)
        return None

    def __eq__(self, other: object) -> bool:
        if isinstance(other, PoissonSeries) and other._ring != self._ring:
            return False
        o = self._coerce(other)
        if o is None:
            return NotImplemented
        return (
            self._shift == o._shift
            and self._comps.keys() == o._comps.keys()
            and all(p == o._comps[m] for m, p in self._comps.items())
        )

    def __hash__(self) -> int:
        return hash((self._shift, tuple(sorted((m, str(p)) for m, p in self._comps.items()))))

    def __bool__(self) -> bool:
        return bool(self._comps)

    def __len__(self) -> int:
        return len(self.terms())

    def __repr__(self) -> str:
        return text.series_to_text(self)

    __str__ = __repr__

    # ------------------------------------------------------------------ arithmetic
    def __add__(self, other: Any) -> PoissonSeries:
        o = self._coerce(other)
        if o is None:
            return NotImplemented
        if not o._comps:
            return self
        if not self._comps:
            return o
        shift, ca, cb = aligned(self._ring, (self._shift, self._comps), (o._shift, o._comps))
        out = dict(ca)
        add_into(out, cb)
        return make_series(self._ring, shift, out)

    __radd__ = __add__

    def __neg__(self) -> PoissonSeries:
        return PoissonSeries(self._ring, self._shift, {m: -p for m, p in self._comps.items()})

    def __pos__(self) -> PoissonSeries:
        return self

    def __sub__(self, other: Any) -> PoissonSeries:
        o = self._coerce(other)
        if o is None:
            return NotImplemented
        return self + (-o)

    def __rsub__(self, other: Any) -> PoissonSeries:
        o = self._coerce(other)
        if o is None:
            return NotImplemented
        return o + (-self)

    def __mul__(self, other: Any) -> PoissonSeries:
        if isinstance(other, EXACT_TYPES) and not isinstance(other, bool):
            c = to_fmpq(other)
            if c == 0:
                return self._ring.zero
            return PoissonSeries(self._ring, self._shift, {m: p * c for m, p in self._comps.items()})
        o = self._coerce(other)
        if o is None:
            return NotImplemented
        if not self._comps or not o._comps:
            return self._ring.zero
        shift = tuple(a + b for a, b in zip(self._shift, o._shift, strict=True))
        return make_series(self._ring, shift, product_comps(self._ring, self._comps, o._comps))

    __rmul__ = __mul__

    def is_unit(self) -> bool:
        """Whether the series is a nonzero rational times a Laurent monomial (invertible).

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["q"], ["p"], ["a"])
        >>> R("3*p**-2*a").is_unit(), R("p + a").is_unit(), R("cos(q)").is_unit()
        (True, False, False)
        """
        nf = self._ring._nfree
        return (
            list(self._comps) == [0]
            and len(self._comps[0]) == 1
            and not any(self._shift[nf:])
            and self._comps[0].is_constant()
        )

    def inverse(self) -> PoissonSeries:
        """Return ``1/self`` for a unit (rational times Laurent monomial).

        Returns
        -------
        PoissonSeries

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> PoissonRing(["q"], ["p"], ["a"])("2*p*a**-1").inverse()
        1/2*p**-1*a
        """
        if not self.is_unit():
            msg = f"expected a rational times a Laurent monomial to invert, got {self}"
            raise ValueError(msg)
        c = self._comps[0].coeffs()[0]
        return PoissonSeries(self._ring, tuple(-a for a in self._shift), {0: self._ring._ctx.constant(1 / c)})

    def __truediv__(self, other: Any) -> PoissonSeries:
        if isinstance(other, EXACT_TYPES) and not isinstance(other, bool):
            c = to_fmpq(other)
            if c == 0:
                msg = "expected a nonzero divisor, got 0"
                raise ValueError(msg)
            return self * (1 / c)
        o = self._coerce(other)
        if o is None:
            return NotImplemented
        return self * o.inverse()

    def __rtruediv__(self, other: Any) -> PoissonSeries:
        o = self._coerce(other)
        if o is None:
            return NotImplemented
        return o * self.inverse()

    def __pow__(self, n: int) -> PoissonSeries:
        if not isinstance(n, int) or isinstance(n, bool):
            msg = f"expected an integer exponent, got {n!r}"
            raise ValueError(msg)
        if n < 0:
            return self.inverse() ** (-n)
        result = self._ring.one
        base = self
        while n:
            if n & 1:
                result = result * base
            n >>= 1
            if n:
                base = base * base
        return result

    # ------------------------------------------------------------------ structure
    def terms(self) -> tuple[Term, ...]:
        """Return the real terms in canonical order.

        Each :class:`Term` holds ``coeff`` (Fraction), ``exponents`` (over
        ``ring.poly_names``: momenta then parameters), ``kind`` (``"cos"`` or ``"sin"``) and
        ``harmonics`` (first nonzero entry positive).  Terms are sorted by harmonic, then
        kind, then total degree.

        Returns
        -------
        tuple of Term

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["q"], ["p"])
        >>> R("p*sin(-q) + 1").terms()
        (Term(coeff=Fraction(1, 1), exponents=(0,), kind='cos', harmonics=(0,)),
         Term(coeff=Fraction(-1, 1), exponents=(1,), kind='sin', harmonics=(1,)))
        """
        if self._terms is None:
            self._terms = real_terms(self._ring, self._shift, self._comps)
        return self._terms

    def variables(self) -> tuple[str, ...]:
        """Names of the variables and parameters that occur, in ring order.

        Returns
        -------
        tuple of str

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> PoissonRing(["l", "g"], ["L", "G"])("L*cos(g)").variables()
        ('g', 'L')
        """
        ring = self._ring
        used = set()
        for t in self.terms():
            used.update(a for a, v in zip(ring.angles, t.harmonics, strict=True) if v)
            used.update(n for n, v in zip(ring.poly_names, t.exponents, strict=True) if v)
        return tuple(n for n in ring.variables if n in used)

    def trig_coefficient(self, kind: str, harmonics: Sequence[int] | Mapping[str, int]) -> PoissonSeries:
        """Return the angle-free coefficient of ``cos(k·θ)`` or ``sin(k·θ)``.

        Parameters
        ----------
        kind : {"cos", "sin"}
        harmonics : sequence of int or mapping of str to int
            The harmonic ``k``; its sign is normalised (``sin(−x) = −sin x``).

        Returns
        -------
        PoissonSeries

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["q"], ["p"])
        >>> R("3*p*sin(2*q) + cos(q)").trig_coefficient("sin", [-2])
        -3*p
        """
        k = self._ring.harmonic_vector(harmonics)
        if kind not in ("cos", "sin"):
            msg = f"expected kind 'cos' or 'sin', got {kind!r}"
            raise ValueError(msg)
        factor = 1
        if harmonic_sign(k) < 0:
            k = tuple(-v for v in k)
            factor = -1 if kind == "sin" else 1
        zero = (0,) * len(k)
        picked = [
            (t.coeff * factor, t.exponents, "cos", zero)
            for t in self.terms()
            if t.kind == kind and t.harmonics == k
        ]
        return self._ring.from_terms(picked)

    def __iter__(self) -> Iterator[Term]:
        return iter(self.terms())
