r"""Truncated power series ("jets") in complex variables and their conjugates, on whole grids.

A jet of degree ``D`` in the variables ``w_1 … w_V`` is the polynomial
``Σ_{|m| ≤ D} c_m w^m`` (``w^m = Π w_i^{m_i}``), the Taylor expansion of a function at
``w = 0`` to degree ``D``; products, powers and functions of jets are truncated at ``D``, so
jet arithmetic gives the Taylor coefficients of a composite function exactly (to round-off).
Here the variables come in conjugate pairs, ``(u, ū, v, v̄)`` per planet, and the
coefficients are arrays over a grid of mean longitudes: a jet is a numpy array of shape
``grid + (M,)`` with ``M`` the number of monomials, so one product serves every grid point.

This is the algebra that expands the disturbing function of two planets in their
eccentricities and inclinations (:mod:`andoyer.planetary.orbits.disturbing`); it is
build-time code (the expansion runs once, when the secular model's coefficients are made),
written for clarity in numpy.

Examples
--------
>>> space = JetSpace(2, 3)          # w1, w2 up to degree 3
>>> w1, w2 = space.variable(0), space.variable(1)
>>> p = space.multiply(space.add_constant(w1, 1.0), space.add_constant(w2, 1.0))
>>> sorted((space.exponents[i].tolist(), complex(c).real) for i, c in enumerate(p) if c)
[([0, 0], 1.0), ([0, 1], 1.0), ([1, 0], 1.0), ([1, 1], 1.0)]
"""

from __future__ import annotations

from functools import cached_property
from itertools import product

import numpy as np
from numpy.typing import NDArray

__all__ = ["JetSpace"]

Array = NDArray[np.complex128]


def _support(jet: Array) -> bytes:
    """Which monomials are present anywhere on the grid (a boolean mask, as bytes)."""
    present = np.any(jet != 0, axis=tuple(range(jet.ndim - 1))) if jet.ndim > 1 else jet != 0
    return np.ascontiguousarray(present, dtype=bool).tobytes()


class JetSpace:
    """The monomials of degree ≤ ``degree`` in ``count`` variables, and jet arithmetic on them.

    Parameters
    ----------
    count : int
        Number of variables ``V``.
    degree : int
        Truncation degree ``D``.

    Attributes
    ----------
    exponents : numpy.ndarray, shape (M, V)
        The exponents of each monomial, by increasing total degree (the constant first).
    degrees : numpy.ndarray, shape (M,)
        Total degree of each monomial.

    Examples
    --------
    >>> JetSpace(8, 4).size
    495
    """

    def __init__(self, count: int, degree: int) -> None:
        if count < 1 or degree < 0:
            msg = f"expected at least one variable and a degree >= 0, got {count} and {degree}"
            raise ValueError(msg)
        self.count, self.degree = int(count), int(degree)
        rows = [m for m in product(range(degree + 1), repeat=count) if sum(m) <= degree]
        rows.sort(key=lambda m: (sum(m), tuple(-x for x in m)))
        self.exponents = np.array(rows, dtype=np.int64).reshape(-1, count)
        self.degrees = self.exponents.sum(axis=1)
        self.index = {tuple(m): i for i, m in enumerate(rows)}
        self._cache: dict = {}

    @property
    def size(self) -> int:
        """Number of monomials ``M``."""
        return len(self.exponents)

    @cached_property
    def _table(self) -> tuple[NDArray[np.int64], NDArray[np.int64], NDArray[np.int64]]:
        """``(i, j, k)`` with monomial ``i`` times monomial ``j`` = monomial ``k``, degree ≤ D."""
        left, right, out = [], [], []
        # Monomials are sorted by degree: the partners of monomial i are a prefix of the list.
        ends = np.searchsorted(self.degrees, np.arange(self.degree + 1), side="right")
        for i, mi in enumerate(self.exponents):
            for j in range(ends[self.degree - self.degrees[i]]):
                left.append(i)
                right.append(j)
                out.append(self.index[tuple(mi + self.exponents[j])])
        return np.array(left), np.array(right), np.array(out)

    def zeros(self, shape: tuple[int, ...] = ()) -> Array:
        """The zero jet on a grid of ``shape``."""
        return np.zeros((*shape, self.size), dtype=complex)

    def constant(self, value: NDArray | complex) -> Array:
        """The jet of a constant (array of grid values, or a number)."""
        value = np.asarray(value, dtype=complex)
        out = self.zeros(value.shape)
        out[..., 0] = value
        return out

    def variable(self, i: int) -> Array:
        """The jet of the variable ``w_i``."""
        out = self.zeros()
        unit = np.zeros(self.count, dtype=np.int64)
        unit[i] = 1
        out[self.index[tuple(unit)]] = 1.0
        return out

    def add_constant(self, jet: Array, value: NDArray | complex) -> Array:
        """``jet + value``."""
        out = np.array(jet, dtype=complex, copy=True)
        out[..., 0] = out[..., 0] + value
        return out

    def multiply(self, a: Array, b: Array) -> Array:
        """The truncated product ``a b`` (grid shapes broadcast).

        Examples
        --------
        >>> s = JetSpace(1, 2)
        >>> x = s.add_constant(s.variable(0), 1.0)   # 1 + w
        >>> s.multiply(x, x).real.tolist()           # 1 + 2w + w²
        [1.0, 2.0, 1.0]
        """
        a, b = np.asarray(a, dtype=complex), np.asarray(b, dtype=complex)
        left, right, gather = self._restricted(_support(a), _support(b))
        if left.size == 0:
            return self.zeros(np.broadcast_shapes(a.shape[:-1], b.shape[:-1]))
        terms = a[..., left] * b[..., right]  # every product of a monomial pair, then summed by target
        shape = terms.shape[:-1]
        return np.asarray(terms.reshape(-1, terms.shape[-1]) @ gather).reshape(*shape, self.size)

    def _restricted(self, support_a: bytes, support_b: bytes):
        """The rows of :attr:`_table` between the monomials present in ``a`` and in ``b`` (cached)."""
        key = (support_a, support_b)
        if key not in self._cache:
            from scipy.sparse import csc_array

            left, right, target = self._table
            in_a = np.frombuffer(support_a, dtype=bool)
            in_b = np.frombuffer(support_b, dtype=bool)
            rows = np.nonzero(in_a[left] & in_b[right])[0]
            gather = csc_array(
                (np.ones(rows.size), (np.arange(rows.size), target[rows])), shape=(rows.size, self.size)
            )
            if len(self._cache) > 256:
                self._cache.clear()
            self._cache[key] = (left[rows], right[rows], gather)
        return self._cache[key]

    def power_series(self, jet: Array, coefficients: list[NDArray | complex]) -> Array:
        """``Σ_n c_n (jet − jet(0))^n`` for ``n ≤ D``: a function's Taylor series composed with a jet.

        Parameters
        ----------
        jet : numpy.ndarray, shape (..., M)
        coefficients : list of array_like
            ``c_0 … c_D``, each a number or an array over the grid (the derivatives of the
            function at the constant term, divided by ``n!``).

        Examples
        --------
        >>> s = JetSpace(1, 3)
        >>> w = s.variable(0)
        >>> s.power_series(w, [1.0, 1.0, 0.5, 1 / 6]).real.round(6).tolist()   # exp(w)
        [1.0, 1.0, 0.5, 0.166667]
        """
        delta = np.array(jet, dtype=complex, copy=True)
        delta[..., 0] = 0.0
        out = self.constant(np.asarray(coefficients[0], dtype=complex) * np.ones(delta.shape[:-1]))
        term = None
        for n in range(1, min(len(coefficients), self.degree + 1)):
            term = delta if term is None else self.multiply(term, delta)
            out = out + np.asarray(coefficients[n], dtype=complex)[..., None] * term
        return out

    def exp(self, jet: Array) -> Array:
        """``exp(jet)``."""
        c0 = np.exp(np.asarray(jet)[..., 0])
        factorial = np.cumprod([1.0, *range(1, self.degree + 1)])
        return self.power_series(jet, [c0 / f for f in factorial])

    def power(self, jet: Array, exponent: float) -> Array:
        """``jet ** exponent`` (the constant term must be nonzero; principal branch)."""
        c0 = np.asarray(jet)[..., 0]
        coefficients = []
        binom = 1.0
        for n in range(self.degree + 1):
            coefficients.append(binom * c0 ** (exponent - n))
            binom *= (exponent - n) / (n + 1)
        return self.power_series(jet, coefficients)

    def conjugate(self, jet: Array, pairs: list[tuple[int, int]]) -> Array:
        """The jet of the complex-conjugate function, the variables being conjugate in ``pairs``.

        ``conj(f)(w) = Σ conj(c_m) w^{m'}`` with the exponents of each pair ``(i, ī)`` swapped.
        """
        perm = np.empty(self.size, dtype=np.int64)
        for k, m in enumerate(self.exponents):
            swapped = m.copy()
            for i, j in pairs:
                swapped[i], swapped[j] = m[j], m[i]
            perm[self.index[tuple(swapped)]] = k
        return np.conj(np.asarray(jet)[..., perm])

    def embed(self, jet: Array, other: JetSpace, positions: list[int]) -> Array:
        """The jet of ``other``'s variables placed at ``positions`` of this space's variables."""
        target = np.empty(other.size, dtype=np.int64)
        for k, m in enumerate(other.exponents):
            full = np.zeros(self.count, dtype=np.int64)
            full[positions] = m
            target[k] = self.index[tuple(full)]
        out = self.zeros(np.asarray(jet).shape[:-1])
        out[..., target] = jet
        return out

    def derivative(self, jet: Array, i: int) -> Array:
        """``∂ jet / ∂ w_i`` (degree ``D − 1`` exact; the top degree is lost)."""
        out = self.zeros(np.asarray(jet).shape[:-1])
        for k, m in enumerate(self.exponents):
            if m[i] == 0:
                continue
            lower = m.copy()
            lower[i] -= 1
            out[..., self.index[tuple(lower)]] += m[i] * np.asarray(jet)[..., k]
        return out
