"""Quadratic Casimir functions ``C(x) = xᵀ Q x`` of the Lie–Poisson algebras."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from andoyer.liepoisson._domain import as_components

__all__ = ["Casimir", "quadratic_form"]


@dataclass(frozen=True)
class Casimir:
    """A quadratic Casimir function ``C(x) = xᵀ Q x`` of a Lie–Poisson algebra.

    Parameters
    ----------
    name : str
        Human-readable formula, e.g. ``"m·γ"``.
    matrix : numpy.ndarray, shape (n, n)
        Symmetric matrix ``Q``.

    Examples
    --------
    >>> from andoyer.liepoisson import get_algebra
    >>> c = get_algebra("e3").casimirs[1]
    >>> c.name
    'm·γ'
    >>> float(c.value([1.0, 2.0, 3.0, 0.0, 0.0, 1.0]))
    3.0
    """

    name: str
    matrix: np.ndarray = field(repr=False)

    def value(self, x: Any) -> np.ndarray:
        """Evaluate ``xᵀ Q x``; ``x`` has shape (..., n), the result (...).

        Examples
        --------
        >>> from andoyer.liepoisson import get_algebra
        >>> float(get_algebra("so3").casimirs[0].value([1.0, 2.0, 2.0]))
        9.0
        """
        x = as_components("x", x, self.matrix.shape[0])
        return np.einsum("...a,ab,...b->...", x, self.matrix, x)[()]

    def gradient(self, x: Any) -> np.ndarray:
        """Gradient ``2 Q x``, shape (..., n).

        Examples
        --------
        >>> from andoyer.liepoisson import get_algebra
        >>> get_algebra("so3").casimirs[0].gradient([1.0, 2.0, 2.0])
        array([2., 4., 4.])
        """
        x = as_components("x", x, self.matrix.shape[0])
        return 2.0 * x @ self.matrix

    def expr(self, symbols: Any) -> Any:
        """The Casimir as a sympy expression of the algebra's ``symbols``.

        Examples
        --------
        >>> from andoyer.liepoisson import get_algebra
        >>> l7 = get_algebra("l7")
        >>> l7.casimirs[0].expr(l7.symbols())
        lambda0**2 + lambda1**2 + lambda2**2 + lambda3**2
        """
        import sympy as sp

        xs = sp.Matrix(symbols)
        return sp.expand((xs.T * sp.Matrix(self.matrix.tolist()) * xs)[0]).nsimplify()


def quadratic_form(n: int, pairs: list[tuple[int, int]]) -> np.ndarray:
    """The symmetric matrix ``Q`` (n, n) of ``Σ x_i x_j`` over ``pairs`` of generator indices.

    Examples
    --------
    >>> quadratic_form(3, [(0, 0), (1, 2)])
    array([[1. , 0. , 0. ],
           [0. , 0. , 0.5],
           [0. , 0.5, 0. ]])
    """
    q = np.zeros((n, n))
    for i, j in pairs:
        q[i, j] += 0.5
        q[j, i] += 0.5
    return q
