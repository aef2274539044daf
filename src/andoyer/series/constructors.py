"""Series constructors of :class:`~andoyer.series.PoissonRing`.

Constants, generators, ``cos``/``sin``, real terms, text and sympy input.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from fractions import Fraction
from typing import TYPE_CHECKING, Any

import flint

# Module import (not names): poisson imports the ring module back through serialize.
from andoyer.series import poisson as _poisson
from andoyer.series.rationals import to_fmpq
from andoyer.series.symbolic import series_from_sympy
from andoyer.series.terms import decompose
from andoyer.series.text import parse_series

if TYPE_CHECKING:
    from andoyer.series.poisson import PoissonSeries

__all__ = ["RingConstructorsMixin"]


class RingConstructorsMixin:
    """Constructors of series; mixed into :class:`~andoyer.series.PoissonRing`."""

    __slots__ = ()

    def __call__(self, value: Any) -> PoissonSeries:
        """Make a series from a rational, a string expression or a series of this ring."""
        if isinstance(value, _poisson.PoissonSeries):
            self.check(value)
            return value
        if isinstance(value, str) and not _looks_rational(value):
            return parse_series(self, value)
        return self.constant(value)

    def check(self, series: PoissonSeries) -> None:
        """Raise ``ValueError`` unless ``series`` belongs to this ring.

        Parameters
        ----------
        series : PoissonSeries

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["q"], ["p"])
        >>> R.check(R("p"))
        """
        if series.ring is not self and series.ring != self:
            msg = f"expected a series of {self!r}, got one of {series.ring!r}"
            raise ValueError(msg)

    def constant(self, value: Any) -> PoissonSeries:
        """Return the constant series ``value`` (an exact rational).

        Parameters
        ----------
        value : int, Fraction, fmpq or "p/q" string

        Returns
        -------
        PoissonSeries

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> PoissonRing(["q"], ["p"]).constant("3/4")
        3/4
        """
        c = to_fmpq(value)
        return _poisson.make_series(self, self._zero_shift, {0: self._ctx.constant(c)})

    @property
    def zero(self) -> PoissonSeries:
        """The zero series.

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> PoissonRing(["q"], ["p"]).zero.is_zero()
        True
        """
        return self.constant(0)

    @property
    def one(self) -> PoissonSeries:
        """The unit series.

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> PoissonRing(["q"], ["p"]).one
        1
        """
        return self.constant(1)

    def gen(self, name: str) -> PoissonSeries:
        """Return the series of one polynomial variable or parameter.

        Parameters
        ----------
        name : str
            A momentum or parameter name.

        Returns
        -------
        PoissonSeries

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["q"], ["p"], ["a"])
        >>> R.gen("p") * R.gen("a") ** -2
        p*a**-2
        """
        if name in self._rel:
            bit = 1 << (self._rel.index(name) + 1)
            return _poisson.make_series(self, self._zero_shift, {bit: self._ctx.constant(1)})
        if name not in self._free:
            msg = f"expected a momentum or parameter of {self.poly_names}, got {name!r}"
            raise ValueError(msg)
        shift = list(self._zero_shift)
        shift[self._index[name]] = 1
        return _poisson.make_series(self, tuple(shift), {0: self._ctx.constant(1)})

    def harmonic_vector(self, k: Sequence[int] | Mapping[str, int]) -> tuple[int, ...]:
        """Normalise a harmonic given as a sequence (angle order) or ``{angle: int}``.

        Parameters
        ----------
        k : sequence of int or mapping of str to int

        Returns
        -------
        tuple of int

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> PoissonRing(["l", "g"], ["L", "G"]).harmonic_vector({"g": -1})
        (0, -1)
        """
        if isinstance(k, Mapping):
            bad = set(k) - set(self.angles)
            if bad:
                msg = f"expected harmonics keyed by angles {self.angles}, got {sorted(bad)}"
                raise ValueError(msg)
            vec = [k.get(a, 0) for a in self.angles]
        else:
            vec = list(k)
        if len(vec) != len(self.angles) or not all(
            isinstance(v, int) and not isinstance(v, bool) for v in vec
        ):
            msg = f"expected {len(self.angles)} integer harmonics, got {k!r}"
            raise ValueError(msg)
        return tuple(vec)

    def cos(self, k: Sequence[int] | Mapping[str, int]) -> PoissonSeries:
        """Return ``cos(k·θ)``.

        Parameters
        ----------
        k : sequence of int or mapping of str to int
            Integer harmonic, one entry per angle.

        Returns
        -------
        PoissonSeries

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["l", "g"], ["L", "G"])
        >>> R.cos([-2, 1])
        cos(2*l - g)
        """
        return self._trig(self.harmonic_vector(k), sine=False)

    def sin(self, k: Sequence[int] | Mapping[str, int]) -> PoissonSeries:
        """Return ``sin(k·θ)``.

        Parameters
        ----------
        k : sequence of int or mapping of str to int
            Integer harmonic, one entry per angle.

        Returns
        -------
        PoissonSeries

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["l", "g"], ["L", "G"])
        >>> R.sin({"l": -1})
        -sin(l)
        """
        return self._trig(self.harmonic_vector(k), sine=True)

    def _trig(self, k: tuple[int, ...], *, sine: bool) -> PoissonSeries:
        if not any(k):
            return self.constant(0 if sine else 1)
        nf = self._nfree
        shift = (0,) * nf + tuple(min(v, -v) for v in k)
        plus = (0,) * nf + tuple(v - s for v, s in zip(k, shift[nf:], strict=True))
        minus = (0,) * nf + tuple(-v - s for v, s in zip(k, shift[nf:], strict=True))
        half = flint.fmpq(1, 2)
        if sine:  # sin x = (−i/2) e^{ix} + (i/2) e^{−ix}
            comps = {1: self._ctx.from_dict({plus: -half, minus: half})}
        else:
            comps = {0: self._ctx.from_dict({plus: half, minus: half})}
        return _poisson.make_series(self, shift, comps)

    def from_terms(self, terms: Iterable[Sequence[Any]]) -> PoissonSeries:
        """Build a series from real terms ``(coeff, exponents, kind, harmonics)``.

        Parameters
        ----------
        terms : iterable of (rational, sequence of int or mapping, {"cos", "sin"}, harmonics)
            ``exponents`` follow :attr:`poly_names` (momenta then parameters) or are a
            ``{name: int}`` mapping; ``harmonics`` as in :meth:`cos`.

        Returns
        -------
        PoissonSeries

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["q"], ["p"])
        >>> R.from_terms([("1/2", [2], "cos", [1]), (3, {"p": -1}, "sin", [2])])
        1/2*p**2*cos(q) + 3*p**-1*sin(2*q)
        """
        shift, comps = decompose(self, terms)
        return _poisson.PoissonSeries(self, shift, comps)

    def from_sympy(self, expr: Any) -> PoissonSeries:
        """Convert a sympy expression (or a string for ``sympy.sympify``) to a series.

        Parameters
        ----------
        expr : sympy.Expr or str
            Built from rationals, the ring's symbols (matched by name), ``+``, ``*``, integer
            powers and ``cos``/``sin`` of integer combinations of angles.

        Returns
        -------
        PoissonSeries

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["q"], ["p"])
        >>> R.from_sympy("cos(q)**3")
        3/4*cos(q) + 1/4*cos(3*q)
        """
        return series_from_sympy(self, expr)

    def exponent_vector(self, e: Sequence[int] | Mapping[str, int]) -> tuple[int, ...]:
        """Normalise monomial exponents given in :attr:`poly_names` order or by name.

        Parameters
        ----------
        e : sequence of int or mapping of str to int

        Returns
        -------
        tuple of int

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> PoissonRing(["q"], ["p"], ["a"]).exponent_vector({"a": 2})
        (0, 2)
        """
        if isinstance(e, Mapping):
            bad = set(e) - set(self.poly_names)
            if bad:
                msg = f"expected exponents keyed by {self.poly_names}, got {sorted(bad)}"
                raise ValueError(msg)
            vec = [e.get(n, 0) for n in self.poly_names]
        else:
            vec = list(e)
        if len(vec) != len(self.poly_names) or not all(
            isinstance(v, int) and not isinstance(v, bool) for v in vec
        ):
            msg = f"expected {len(self.poly_names)} integer exponents, got {e!r}"
            raise ValueError(msg)
        for name, v in zip(self.poly_names, vec, strict=True):
            if v < 0 and name in self.relations:
                msg = f"expected a nonnegative exponent of relation generator {name}, got {v}"
                raise ValueError(msg)
        return tuple(vec)


def _looks_rational(text: str) -> bool:
    try:
        Fraction(text)
    except ValueError:
        return False
    return True
