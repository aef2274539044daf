"""The power-of-two scaling of a state, written once: the kernel :func:`scale_exponents`.

The motion is covariant under ``I = 2^a I'``, ``m = 2^b m'``: ``m(t) = 2^b m'(2^{b−a} t)`` and
the attitude is ``q'(2^{b−a} t)``.  The solution works on the scaled state (the largest moment
and the largest ``|m|`` component in ``[1/2, 1)``), which keeps every product (``m²/I`` in
double-double, ``K``, the frequencies) far from overflow and underflow whatever the units.  The
exponents are this one kernel, run on arrays by :func:`andoyer.free.common.scaling_numpy.normalise`
and per state by :func:`andoyer.free.common.scaling_compiled.classify_and_scale`.
"""

from __future__ import annotations

import numpy as np

from andoyer._jit import exponent, jitable, select

__all__ = ["scale_exponents"]


@jitable
def scale_exponents(i1, i2, i3, m1, m2, m3):
    """Exponents ``a, b`` that scale a state into ``[1/2, 1)``: ``max Iᵢ = 2^a f``, ``max |mᵢ| = 2^b g``.

    ``f, g ∈ [1/2, 1)``; a zero momentum gives ``b = 1`` (the exponent of 1).  The motion
    is covariant under ``I = 2^a I'``, ``m = 2^b m'`` (:func:`normalise`),
    and the regime does not change.  A kernel written once: floats (compiled or not) or
    arrays broadcast together.

    Parameters
    ----------
    i1, i2, i3 : float or ndarray, shape (...)
        Principal moments (positive, finite).
    m1, m2, m3 : float or ndarray, shape (...)
        Body angular momentum (finite).

    Returns
    -------
    a, b : int or ndarray of int, shape (...)
        The exponents.

    Examples
    --------
    >>> a, b = scale_exponents(3.0, 4.0, 6.0, 0.0, 48.0, 0.0)
    >>> int(a), int(b)
    (3, 6)
    """
    big_i = np.maximum(np.maximum(i1, i2), i3)
    big_m = np.maximum(np.maximum(np.abs(m1), np.abs(m2)), np.abs(m3))
    return exponent(big_i), exponent(select(big_m > 0, big_m, 1.0))
