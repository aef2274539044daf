"""Operations with one name for compiled floats and numpy arrays: what the shared set-up kernels call.

The kernels of :mod:`andoyer.free.kernels.triaxial` are written once and run on floats inside
the compiled set-up (:mod:`andoyer.free.compiled_setup`) and on arrays in the numpy set-up
(:mod:`andoyer.free.triaxial`).  The double-double operations and Carlson's ``R_F`` they
call still have two implementations each, tuned to their path: on arrays
:mod:`andoyer.special.compensated` (Dekker products, a two-correction division) and
:func:`scipy.special.elliprf`; on floats :mod:`andoyer.free.scalar_dd` (fused multiply-add
products, one-correction division) and :func:`andoyer.free.kernels.elliptic.carlson_rf`.
Each function here chooses by its arguments (any ndarray: the array version) and, inside a
kernel compiled by numba, is the float version, so each path keeps its arithmetic bit for
bit.  When :mod:`andoyer.special.compensated` serves floats and arrays alike (issue 16), the
kernels import it instead and this module goes.

Examples
--------
>>> import numpy as np
>>> hi, lo = dd_div(np.array([1.0]), 0.0, 3.0, 0.0)  # arrays: compensated
>>> float(hi[0]), float(lo[0])
(0.3333333333333333, 1.850371707708594e-17)
>>> dd_div(1.0, 0.0, 3.0, 0.0)  # floats: scalar_dd
(0.3333333333333333, 1.850371707708594e-17)
"""

from __future__ import annotations

import numpy as np

from andoyer._jit import NUMBA
from andoyer.free import scalar_dd as _float
from andoyer.free.kernels.elliptic import carlson_rf
from andoyer.special import compensated as _array

__all__ = ["dd_add", "dd_div", "dd_mul", "dd_sqrt", "elliprf"]


def _arrays(*args):
    return any(isinstance(a, np.ndarray) for a in args)


def dd_add(ah, al, bh, bl):
    """Double-double sum ``(ah + al) + (bh + bl)`` (:func:`andoyer.special.compensated.dd_add`).

    Parameters
    ----------
    ah, al, bh, bl : float or ndarray, shape (...)
        High and low words of the operands.

    Returns
    -------
    hi, lo : float or ndarray, shape (...)

    Examples
    --------
    >>> dd_add(1.0, 0.0, -1.0, 1e-30)
    (1e-30, 0.0)
    """
    return (_array if _arrays(ah, al, bh, bl) else _float).dd_add(ah, al, bh, bl)


def dd_mul(ah, al, bh, bl):
    """Double-double product (:func:`andoyer.special.compensated.dd_mul`).

    Parameters
    ----------
    ah, al, bh, bl : float or ndarray, shape (...)
        High and low words of the operands.

    Returns
    -------
    hi, lo : float or ndarray, shape (...)

    Examples
    --------
    >>> dd_mul(0.1, 0.0, 10.0, 0.0)
    (1.0, 5.551115123125783e-17)
    """
    return (_array if _arrays(ah, al, bh, bl) else _float).dd_mul(ah, al, bh, bl)


def dd_div(ah, al, bh, bl):
    """Double-double quotient (:func:`andoyer.special.compensated.dd_div`).

    Parameters
    ----------
    ah, al, bh, bl : float or ndarray, shape (...)
        High and low words of the numerator and the (non-zero) denominator.

    Returns
    -------
    hi, lo : float or ndarray, shape (...)

    Examples
    --------
    >>> dd_div(1.0, 0.0, 4.0, 0.0)
    (0.25, 0.0)
    """
    return (_array if _arrays(ah, al, bh, bl) else _float).dd_div(ah, al, bh, bl)


def dd_sqrt(ah, al):
    """Double-double square root of ``ah + al ≥ 0`` (:func:`andoyer.special.compensated.dd_sqrt`).

    Parameters
    ----------
    ah, al : float or ndarray, shape (...)
        High and low words, ``ah + al ≥ 0``.

    Returns
    -------
    hi, lo : float or ndarray, shape (...)

    Examples
    --------
    >>> dd_sqrt(4.0, 0.0)
    (2.0, 0.0)
    """
    return (_array if _arrays(ah, al) else _float).dd_sqrt(ah, al)


def elliprf(x, y, z):
    """Carlson's ``R_F(x, y, z)`` (DLMF 19.16.1): scipy's on arrays, the scalar kernel on floats.

    Parameters
    ----------
    x, y, z : float or ndarray, shape (...)
        Non-negative, at most one zero.

    Returns
    -------
    float or ndarray, shape (...)

    Examples
    --------
    >>> round(float(elliprf(0.0, 1.0, 2.0)), 13)  # the lemniscate constant Γ(1/4)²/(4√(2π))
    1.3110287771461
    """
    if _arrays(x, y, z):
        from scipy.special import elliprf as rf

        return rf(x, y, z)
    return carlson_rf(x, y, z)


if NUMBA:  # inside a compiled kernel each name is the float version
    from numba.extending import overload

    @overload(dd_add)
    def _dd_add_compiled(ah, al, bh, bl):  # noqa: ARG001 - numba's overload signature
        def impl(ah, al, bh, bl):
            return _float.dd_add(ah, al, bh, bl)

        return impl

    @overload(dd_mul)
    def _dd_mul_compiled(ah, al, bh, bl):  # noqa: ARG001 - numba's overload signature
        def impl(ah, al, bh, bl):
            return _float.dd_mul(ah, al, bh, bl)

        return impl

    @overload(dd_div)
    def _dd_div_compiled(ah, al, bh, bl):  # noqa: ARG001 - numba's overload signature
        def impl(ah, al, bh, bl):
            return _float.dd_div(ah, al, bh, bl)

        return impl

    @overload(dd_sqrt)
    def _dd_sqrt_compiled(ah, al):  # noqa: ARG001 - numba's overload signature
        def impl(ah, al):
            return _float.dd_sqrt(ah, al)

        return impl

    @overload(elliprf)
    def _elliprf_compiled(x, y, z):  # noqa: ARG001 - numba's overload signature
        def impl(x, y, z):
            return carlson_rf(x, y, z)

        return impl
