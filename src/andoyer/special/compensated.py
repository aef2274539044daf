"""Double-double (compensated) arithmetic on numpy arrays.

A double-double number is an unevaluated sum ``hi + lo`` of two float64 arrays with
``|lo| ≤ ulp(hi)/2``; it carries about 106 bits.  The exact solution of the free rigid
body needs it in three places, each documented where it is used: the complementary
parameter ``m' = 1 − m`` near the separatrix (a difference of nearly equal energies),
the frequencies that are multiplied by long times (a phase of 100 periods keeps
16 digits only if the frequency has 18), and the complete integral ``K`` that sets the
period.  The error-free transformations are Knuth's two-sum and Dekker's two-product
(numpy has no fused multiply-add).

All functions are vectorised with numpy broadcasting and return float64 arrays; the
error-free transformations, sums and products are also callable from kernels compiled by
:func:`andoyer._jit.jit` (on float64 scalars, :func:`andoyer._jit.jitable`), so a kernel written
once (:func:`andoyer.regime.regime_code`) runs both on arrays and compiled.
"""

from __future__ import annotations

import numpy as np

from andoyer._jit import NUMBA, as_float64, fused_multiply_add, jitable

__all__ = [
    "PI_DD",
    "dd_add",
    "dd_div",
    "dd_mul",
    "dd_sqrt",
    "split",
    "two_prod",
    "two_sum",
]

#: π as a double-double ``(hi, lo)``.
PI_DD = (3.141592653589793, 1.2246467991473532e-16)

_SPLITTER = 134217729.0  # 2**27 + 1


@jitable
def two_sum(a, b):
    """Error-free sum: ``a + b = s + e`` exactly (Knuth).

    Parameters
    ----------
    a, b : array_like
        Float64 operands, broadcast together.

    Returns
    -------
    s, e : ndarray
        ``s = fl(a + b)`` and the rounding error ``e``.

    Examples
    --------
    >>> two_sum(1.0, 1e-17)
    (np.float64(1.0), np.float64(1e-17))
    """
    a = as_float64(a)
    b = as_float64(b)
    s = a + b
    bb = s - a
    e = (a - (s - bb)) + (b - bb)
    return s, e


@jitable
def _fast_two_sum(a, b):
    # Valid when |a| >= |b| (or a == 0): the renormalisation step.
    s = a + b
    return s, b - (s - a)


@jitable
def split(a):
    """Dekker split of ``a`` into two 26-bit halves, ``a = hi + lo`` exactly.

    Parameters
    ----------
    a : array_like
        Float64 values with ``|a| < 1e300`` (the split multiplies by 2²⁷ + 1).

    Returns
    -------
    hi, lo : ndarray
        Non-overlapping halves whose products are exact in float64.

    Examples
    --------
    >>> hi, lo = split(0.1)
    >>> bool(hi + lo == 0.1)
    True
    """
    a = as_float64(a)
    c = _SPLITTER * a
    hi = c - (c - a)
    return hi, a - hi


def two_prod(a, b):
    """Error-free product: ``a·b = p + e`` exactly (Dekker; a fused multiply-add when compiled).

    Parameters
    ----------
    a, b : array_like
        Float64 operands, broadcast together, ``|a|, |b| < 1e300``.

    Returns
    -------
    p, e : ndarray
        ``p = fl(a·b)`` and its rounding error ``e``.

    Examples
    --------
    >>> p, e = two_prod(0.1, 0.1)
    >>> float(e)
    -8.326672684688674e-19
    """
    a = as_float64(a)
    b = as_float64(b)
    p = a * b
    ah, al = split(a)
    bh, bl = split(b)
    e = ((ah * bh - p) + ah * bl + al * bh) + al * bl
    return p, e


if NUMBA:
    from numba.extending import overload

    @overload(two_prod, inline="always")
    def _two_prod_compiled(a, b):  # noqa: ARG001 - numba's overload signature
        def fused(a, b):
            p = a * b
            return p, fused_multiply_add(a, b, -p)  # the same exact error as Dekker's, in one instruction

        return fused


@jitable
def dd_add(ah, al, bh, bl):
    """Double-double sum ``(ah + al) + (bh + bl)``, accurate to about 2⁻¹⁰⁴ relative.

    Parameters
    ----------
    ah, al, bh, bl : array_like
        High and low parts of the two operands.

    Returns
    -------
    hi, lo : ndarray
        The normalised double-double sum.

    Examples
    --------
    >>> dd_add(1.0, 0.0, -1.0, 1e-30)
    (np.float64(1e-30), np.float64(0.0))
    """
    s, e = two_sum(ah, bh)
    t, f = two_sum(al, bl)
    e = e + t
    s, e = _fast_two_sum(s, e)
    e = e + f
    return _fast_two_sum(s, e)


@jitable
def dd_mul(ah, al, bh, bl):
    """Double-double product ``(ah + al)(bh + bl)``.

    Parameters
    ----------
    ah, al, bh, bl : array_like
        High and low parts of the two operands (``bl = 0`` multiplies by a double).

    Returns
    -------
    hi, lo : ndarray
        The normalised double-double product.

    Examples
    --------
    >>> hi, lo = dd_mul(0.1, 0.0, 10.0, 0.0)
    >>> float(hi), float(lo)
    (1.0, 5.551115123125783e-17)
    """
    p, e = two_prod(ah, bh)
    e = e + (as_float64(ah) * bl + as_float64(al) * bh)
    return _fast_two_sum(p, e)


def dd_div(ah, al, bh, bl):
    """Double-double quotient ``(ah + al)/(bh + bl)`` by two correction steps.

    Parameters
    ----------
    ah, al, bh, bl : array_like
        High and low parts of numerator and (non-zero) denominator.

    Returns
    -------
    hi, lo : ndarray
        The normalised double-double quotient.

    Examples
    --------
    >>> hi, lo = dd_div(1.0, 0.0, 3.0, 0.0)
    >>> float(hi), float(lo)
    (0.3333333333333333, 1.850371707708594e-17)
    """
    q1 = np.asarray(ah, dtype=np.float64) / bh
    ph, pl = dd_mul(q1, 0.0, bh, bl)
    rh, rl = dd_add(ah, al, -ph, -pl)
    q2 = rh / bh
    ph, pl = dd_mul(q2, 0.0, bh, bl)
    rh, _ = dd_add(rh, rl, -ph, -pl)
    q3 = rh / bh
    q1, q2 = _fast_two_sum(q1, q2)
    return dd_add(q1, q2, q3, 0.0)


def dd_sqrt(ah, al):
    """Double-double square root of a non-negative double-double, by one Newton step.

    Parameters
    ----------
    ah, al : array_like
        High and low parts, ``ah + al ≥ 0``.

    Returns
    -------
    hi, lo : ndarray
        The normalised double-double square root (``0`` for a zero argument).

    Examples
    --------
    >>> hi, lo = dd_sqrt(2.0, 0.0)
    >>> float(hi), float(lo)
    (1.4142135623730951, -9.6672933134529e-17)
    """
    ah = np.asarray(ah, dtype=np.float64)
    x = np.sqrt(ah)
    safe = np.where(x > 0, x, 1.0)
    ph, pl = two_prod(x, x)
    rh, _ = dd_add(ah, al, -ph, -pl)
    corr = np.where(x > 0, rh / (2.0 * safe), 0.0)
    return _fast_two_sum(x, corr)
