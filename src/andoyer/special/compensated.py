"""Double-double (compensated) arithmetic, written once for scalars and arrays.

A double-double number is an unevaluated sum ``hi + lo`` of two float64 values with
``|lo| ≤ ulp(hi)/2``; it carries about 106 bits.  The exact solution of the free rigid
body needs it in three places, each documented where it is used: the complementary
parameter ``m' = 1 − m`` near the separatrix (a difference of nearly equal energies),
the frequencies that are multiplied by long times (a phase of 100 periods keeps
16 digits only if the frequency has 18), and the complete integral ``K`` that sets the
period.

Each operation is one function of arithmetic only, so the same text serves every path:
called from Python it works element-wise on numpy arrays (broadcast together) or on
floats (the numpy path of the free solution, :mod:`andoyer.special.agm`); a kernel
compiled by :func:`andoyer._jit.jit` that calls it compiles it inline (the functions are
registered with :func:`andoyer._jit.jitable`), which is how the compiled set-up of
:mod:`andoyer.free.triaxial.setup_compiled` uses them.  The one place where the two paths differ is
the exact rounding error of a product, :func:`product_error`: a fused multiply-add when
compiled, Dekker's splitting in numpy (which has no fused multiply-add); both return the
same, exact, value.

The error-free transformations are Knuth's two-sum and the two-product; the quotient is
Joldes, Muller & Popescu's *DWDivDW2* (ACM TOMS 44, 2017: relative error at most
``15u²``), the square root one Newton step on the exact remainder.
"""

from __future__ import annotations

import numpy as np

from andoyer._jit import fused_multiply_add, jitable, select, when_compiled

__all__ = [
    "PI_DD",
    "dd_add",
    "dd_div",
    "dd_mul",
    "dd_sqrt",
    "fast_two_sum",
    "product_error",
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
    a, b : float or ndarray, shape (...)
        Float64 operands, broadcast together.

    Returns
    -------
    s, e : float or ndarray, shape (...)
        ``s = fl(a + b)`` and the rounding error ``e``.

    Examples
    --------
    >>> two_sum(1.0, 1e-17)
    (1.0, 1e-17)
    """
    s = a + b
    bb = s - a
    return s, (a - (s - bb)) + (b - bb)


@jitable
def fast_two_sum(a, b):
    """Error-free sum ``a + b = s + e`` when ``|a| ≥ |b|`` or ``a = 0`` (the renormalisation).

    Parameters
    ----------
    a, b : float or ndarray, shape (...)
        Float64 operands, broadcast together, ``|a| ≥ |b|``.

    Returns
    -------
    s, e : float or ndarray, shape (...)
        ``s = fl(a + b)`` and the rounding error ``e``.

    Examples
    --------
    >>> fast_two_sum(1.0, 1e-17)
    (1.0, 1e-17)
    """
    s = a + b
    return s, b - (s - a)


@jitable
def split(a):
    """Dekker split of ``a`` into two 26-bit halves, ``a = hi + lo`` exactly.

    Parameters
    ----------
    a : float or ndarray, shape (...)
        Float64 values with ``|a| < 1e300`` (the split multiplies by 2²⁷ + 1).

    Returns
    -------
    hi, lo : float or ndarray, shape (...)
        Non-overlapping halves whose products are exact in float64.

    Examples
    --------
    >>> hi, lo = split(0.1)
    >>> hi + lo == 0.1
    True
    """
    c = _SPLITTER * a
    hi = c - (c - a)
    return hi, a - hi


def product_error(a, b, p):
    """The exact rounding error ``a·b − p`` of the product ``p = fl(a·b)``.

    In numpy, by Dekker's splitting of both factors into 26-bit halves (exact partial
    products); in a compiled kernel, by one fused multiply-add ``fma(a, b, −p)``
    (LLVM's ``llvm.fma.f64``). The error of a rounded product is a float64, so both
    give the same exact value.

    Parameters
    ----------
    a, b : float or ndarray, shape (...)
        Float64 factors, ``|a|, |b| < 1e300``, broadcast together.
    p : float or ndarray, shape (...)
        Their rounded product ``a·b``.

    Returns
    -------
    float or ndarray, shape (...)
        ``a·b − p``, exactly (unless it underflows).

    Examples
    --------
    >>> product_error(0.1, 0.1, 0.1 * 0.1)
    -8.326672684688674e-19
    """
    ah, al = split(a)
    bh, bl = split(b)
    return ((ah * bh - p) + ah * bl + al * bh) + al * bl


@when_compiled
def _compiled_product_error(overload):
    @overload(product_error)
    def _product_error_compiled(a, b, p):  # noqa: ARG001 - numba's overload signature
        return lambda a, b, p: fused_multiply_add(a, b, -p)


@jitable
def two_prod(a, b):
    """Error-free product: ``a·b = p + e`` exactly.

    Parameters
    ----------
    a, b : float or ndarray, shape (...)
        Float64 operands, broadcast together, ``|a|, |b| < 1e300``.

    Returns
    -------
    p, e : float or ndarray, shape (...)
        ``p = fl(a·b)`` and its rounding error ``e`` (:func:`product_error`).

    Examples
    --------
    >>> two_prod(0.1, 0.1)
    (0.010000000000000002, -8.326672684688674e-19)
    """
    p = a * b
    return p, product_error(a, b, p)


@jitable
def dd_add(ah, al, bh, bl):
    """Double-double sum ``(ah + al) + (bh + bl)``, accurate to about 2⁻¹⁰⁴ relative.

    Parameters
    ----------
    ah, al, bh, bl : float or ndarray, shape (...)
        High and low parts of the two operands, broadcast together.

    Returns
    -------
    hi, lo : float or ndarray, shape (...)
        The normalised double-double sum.

    Examples
    --------
    >>> dd_add(1.0, 0.0, -1.0, 1e-30)
    (1e-30, 0.0)
    """
    s, e = two_sum(ah, bh)
    t, f = two_sum(al, bl)
    s, e = fast_two_sum(s, e + t)
    return fast_two_sum(s, e + f)


@jitable
def dd_mul(ah, al, bh, bl):
    """Double-double product ``(ah + al)(bh + bl)``.

    Parameters
    ----------
    ah, al, bh, bl : float or ndarray, shape (...)
        High and low parts of the two operands (``bl = 0`` multiplies by a double).

    Returns
    -------
    hi, lo : float or ndarray, shape (...)
        The normalised double-double product.

    Examples
    --------
    >>> dd_mul(0.1, 0.0, 10.0, 0.0)
    (1.0, 5.551115123125783e-17)
    """
    p, e = two_prod(ah, bh)
    return fast_two_sum(p, e + (ah * bl + al * bh))


@jitable
def dd_div(ah, al, bh, bl):
    """Double-double quotient ``(ah + al)/(bh + bl)``: one correction of ``ah/bh``.

    ``t = a_h/b_h``, the remainder ``a − t b`` formed with an error-free product, and
    ``t + (a − t b)/b_h`` (Joldes, Muller & Popescu 2017, *DWDivDW2*: relative error at
    most ``15u²``, ``u = 2⁻⁵³``).

    Parameters
    ----------
    ah, al, bh, bl : float or ndarray, shape (...)
        High and low parts of numerator and (non-zero) denominator.

    Returns
    -------
    hi, lo : float or ndarray, shape (...)
        The normalised double-double quotient.

    Examples
    --------
    >>> dd_div(1.0, 0.0, 3.0, 0.0)
    (0.3333333333333333, 1.850371707708594e-17)
    """
    th = ah / bh
    ph, pl = two_prod(th, bh)
    pl = pl + th * bl
    r = ((ah - ph) - pl) + al  # a_h − p_h is exact (Sterbenz)
    return fast_two_sum(th, r / bh)


@jitable
def dd_sqrt(ah, al):
    """Double-double square root of a non-negative double-double, by one Newton step.

    ``x = √a_h`` corrected by the exact remainder: ``x + (a − x²)/(2x)``.

    Parameters
    ----------
    ah, al : float or ndarray, shape (...)
        High and low parts, ``ah + al ≥ 0``.

    Returns
    -------
    hi, lo : float or ndarray, shape (...)
        The normalised double-double square root (``0`` for a zero argument).

    Examples
    --------
    >>> hi, lo = dd_sqrt(2.0, 0.0)
    >>> float(hi), float(lo)
    (1.4142135623730951, -9.667293313452912e-17)
    """
    x = np.sqrt(ah)
    ph, pl = two_prod(x, x)
    r = ((ah - ph) - pl) + al  # the remainder a − x², a_h − p_h exact (Sterbenz)
    positive = x > 0.0
    return fast_two_sum(x, select(positive, r, 0.0) / (2.0 * select(positive, x, 1.0)))
