"""The power-of-two scaling and the regime of many states on arrays (the numpy driver of ``scaling``).

The exponents of :func:`andoyer.free.common.scaling.scale_exponents` applied to whole arrays,
and the regime of :func:`andoyer.regime.regime_codes`; the compiled driver
(:func:`andoyer.free.common.scaling_compiled.classify_and_scale`) gives the same bits.
"""

from __future__ import annotations

import numpy as np

from andoyer.free.common.scaling import scale_exponents
from andoyer.regime import regime_codes

__all__ = ["classify_scaled", "normalise"]


def normalise(moments, m0):
    """Scale moments and momenta by powers of two into ``[1/2, 1)`` (exact, per state).

    The motion is covariant: with ``I = 2^a I'`` and ``m₀ = 2^b m₀'``,
    ``m(t) = 2^b m'(2^{b−a} t)`` and the attitude is ``q'(2^{b−a} t)``.  Working on the
    scaled state keeps every product of the solution (``m²/I`` in double-double, ``K``,
    frequencies) far from overflow and underflow whatever the units.

    Parameters
    ----------
    moments, m0 : ndarray, shape (..., 3)

    Returns
    -------
    moments, m0 : ndarray
        Scaled copies (the largest moment and the largest ``|m₀|`` component in ``[1/2, 1)``).
    a, b : ndarray of int, shape (...)
        The exponents.

    Examples
    --------
    >>> i, m, a, b = normalise(np.array([3.0, 4.0, 6.0]), np.array([0.0, 48.0, 0.0]))
    >>> i.tolist(), m.tolist(), int(a), int(b)
    ([0.375, 0.5, 0.75], [0.0, 0.75, 0.0], 3, 6)
    """
    a, b = scale_exponents(*(moments[..., k] for k in range(3)), *(m0[..., k] for k in range(3)))
    a, b = np.broadcast_to(a, moments.shape[:-1]), np.broadcast_to(b, m0.shape[:-1])
    return np.ldexp(moments, -a[..., None]), np.ldexp(m0, -b[..., None]), a, b


def classify_scaled(moments, m0):
    """:func:`andoyer.regime.classify` for validated states, without the checks.

    The states need not be scaled any more (:func:`andoyer.regime.regime_code` scales each
    state itself); the name stays for the callers of :func:`normalise` that used it.

    Parameters
    ----------
    moments, m0 : ndarray, shape (..., 3)
        Validated moments and momenta, e.g. the output of :func:`normalise`.

    Returns
    -------
    ndarray of int8, shape (...)
        :class:`andoyer.regime.Regime` codes.

    Examples
    --------
    >>> from andoyer.regime import Regime
    >>> Regime(int(classify_scaled(np.array([0.375, 0.5, 0.75]), np.array([0.0, 0.75, 0.0])))).name
    'SEPARATRIX'
    """
    return regime_codes(moments, m0)
