"""Conversion methods of :class:`~andoyer.series.PoissonSeries` (JSON, sympy, LaTeX, numpy)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

from andoyer.series import numeric, serialize, symbolic

if TYPE_CHECKING:
    from andoyer.series.poisson import PoissonSeries
    from andoyer.series.ring import PoissonRing

__all__ = ["ConversionsMixin"]


class ConversionsMixin:
    """Conversions of Poisson series; mixed into :class:`~andoyer.series.PoissonSeries`."""

    __slots__ = ()

    def to_json(self, indent: int | None = None) -> str:
        """Serialise to JSON with exact ``"p/q"`` coefficients and the ring declaration.

        Parameters
        ----------
        indent : int, optional

        Returns
        -------
        str

        Examples
        --------
        >>> from andoyer.series import PoissonRing, PoissonSeries
        >>> f = PoissonRing(["q"], ["p"])("p/3*sin(q)")
        >>> PoissonSeries.from_json(f.to_json()) == f
        True
        """
        return serialize.series_to_json(self, indent=indent)

    @staticmethod
    def from_json(text: str, ring: PoissonRing | None = None) -> PoissonSeries:
        """Read a series written by :meth:`to_json`.

        Parameters
        ----------
        text : str
        ring : PoissonRing, optional
            If given, the stored ring must equal it (and the series uses this object).

        Returns
        -------
        PoissonSeries

        Examples
        --------
        >>> from andoyer.series import PoissonRing, PoissonSeries
        >>> PoissonSeries.from_json(PoissonRing(["q"], ["p"])("p").to_json())
        p
        """
        return serialize.series_from_json(text, ring)

    def to_sympy(self, symbols: Mapping[str, Any] | None = None) -> Any:
        """Convert to a sympy expression.

        Parameters
        ----------
        symbols : mapping of str to sympy.Symbol, optional
            Symbols to use; default ``sympy.Symbol(name)``.

        Returns
        -------
        sympy.Expr

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> PoissonRing(["q"], ["p"])("p**2/2*cos(q)").to_sympy()
        p**2*cos(q)/2
        """
        return symbolic.series_to_sympy(self, symbols)

    def to_latex(self) -> str:
        r"""Return a LaTeX string, grouping terms by trigonometric argument.

        Returns
        -------
        str

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> PoissonRing(["l"], ["L"], ["beta"])("beta*L**2*cos(2*l)/2").to_latex()
        '\\frac{L^{2} \\beta}{2} \\cos{\\left(2 l \\right)}'
        """
        return symbolic.series_to_latex(self)

    def compile(self) -> numeric.CompiledSeries:
        """Compile to a vectorised numpy function of ``ring.variables``.

        Returns
        -------
        CompiledSeries
            Callable with positional (in ``ring.variables`` order) or keyword arrays; all
            arguments broadcast together.

        Examples
        --------
        >>> from andoyer.series import PoissonRing
        >>> f = PoissonRing(["q"], ["p"])("p**2*cos(q)").compile()
        >>> f(q=[0.0, 3.141592653589793], p=2.0)
        array([ 4., -4.])
        """
        return numeric.CompiledSeries(self)
