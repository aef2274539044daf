"""Calculus methods of Poisson series, delegating to the modules that implement them.

Derivatives, the Poisson bracket, averaging, truncation and substitution.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from fractions import Fraction
from typing import TYPE_CHECKING, Any

from andoyer.series import averaging, bracket, substitution

if TYPE_CHECKING:
    from andoyer.series.poisson import PoissonSeries

__all__ = ["CalculusMixin"]


class CalculusMixin:
    """Calculus on Poisson series; mixed into :class:`~andoyer.series.PoissonSeries`."""

    __slots__ = ()

    def diff(self, name: str) -> PoissonSeries:
        """Partial derivative with respect to an angle, momentum or free parameter.

        Parameters
        ----------
        name : str
            Variable name; relation generators and the parameters in a relation are refused
            (they are not independent).

        Returns
        -------
        PoissonSeries

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["q"], ["p"])
        >>> R("p**-1*cos(2*q)").diff("q"), R("p**-1*cos(2*q)").diff("p")
        (-2*p**-1*sin(2*q), -p**-2*cos(2*q))
        """
        return bracket.derivative(self, name)

    def bracket(self, other: PoissonSeries) -> PoissonSeries:
        """Poisson bracket ``{self, other} = Σ (∂self/∂q ∂other/∂p − ∂self/∂p ∂other/∂q)``.

        Parameters
        ----------
        other : PoissonSeries

        Returns
        -------
        PoissonSeries

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["q"], ["p"])
        >>> R("cos(q)").bracket(R("p"))
        -sin(q)
        """
        return bracket.poisson_bracket(self, other)

    def average(self, angles: Sequence[str] | None = None) -> PoissonSeries:
        """Average over the given angles (default: all angles).

        Parameters
        ----------
        angles : sequence of str, optional

        Returns
        -------
        PoissonSeries

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["l", "g"], ["L", "G"])
        >>> R("L + cos(l) + cos(g)").average(["l"])
        L + cos(g)
        """
        return averaging.average(self, angles)

    def truncate(self, order: Any) -> PoissonSeries:
        """Drop the terms whose weighted order (ring weights) exceeds ``order``.

        Parameters
        ----------
        order : rational

        Returns
        -------
        PoissonSeries

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["q"], ["p"], ["eps"], weights={"eps": 1})
        >>> R("(1 + eps)**3 * cos(q)").truncate(1)
        cos(q) + 3*eps*cos(q)
        """
        return substitution.truncate(self, order)

    def order(self) -> Fraction | None:
        """Lowest weighted order among the terms (``None`` for the zero series).

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["q"], ["p"], ["eps"], weights={"eps": 1})
        >>> R("eps**2 + eps**3*p").order()
        Fraction(2, 1)
        """
        if not self._comps:
            return None
        return min(substitution.term_order(self._ring, t) for t in self.terms())

    def subs(self, values: Mapping[str, Any]) -> PoissonSeries:
        """Substitute momenta or parameters by rationals or series (exactly, no truncation).

        Parameters
        ----------
        values : mapping of str to rational or PoissonSeries
            A negative power of a substituted variable needs a unit (monomial) value.

        Returns
        -------
        PoissonSeries

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["q"], ["p"], ["a"])
        >>> R("a*p**2*cos(q)").subs({"a": "1/2", "p": R("p + 1")})
        1/2*cos(q) + p*cos(q) + 1/2*p**2*cos(q)
        """
        return substitution.substitute(self, values)

    def shifted(self, deltas: Mapping[str, PoissonSeries], order: Any) -> PoissonSeries:
        """Taylor-expand ``f(x + Δ)`` for angles or momenta ``x``, truncated at ``order``.

        Parameters
        ----------
        deltas : mapping of str to PoissonSeries
            Increments ``Δ_x``; each must have weighted order larger than the weight of ``x``.
        order : rational
            Truncation order (ring weights).

        Returns
        -------
        PoissonSeries

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> R = PoissonRing(["q"], ["p"], ["eps"], weights={"eps": 1})
        >>> R("cos(q)").shifted({"q": R("eps")}, order=2)
        cos(q) - 1/2*eps**2*cos(q) - eps*sin(q)
        """
        return substitution.taylor_shift(self, deltas, order)
