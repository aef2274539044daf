"""Regimes and power-of-two scaling of many states in one compiled loop.

:func:`andoyer.regime.classify` and :func:`andoyer.free.common.scaling_numpy.normalise` for
validated inputs, per state in a numba kernel (the compiled driver of
:mod:`~andoyer.free.common.scaling`): the same exponents and the same scaled values
(:func:`andoyer.free.common.scaling.scale_exponents`) and the same regimes, from the same kernel
(:func:`andoyer.regime.regime_code`, compiled here, run on arrays there), so the decision is
the same bit for bit.  :class:`andoyer.free.FreeMotion` uses it when numba is installed.
"""

from __future__ import annotations

import numpy as np

from andoyer._jit import jit
from andoyer.free.common.scaling import scale_exponents
from andoyer.regime import regime_code

__all__ = ["classify_and_scale"]


@jit
def _state(Ib, mb, Is, ms):
    """Scale one state into ``Is, ms``; return its regime code and the exponents ``a, b``."""
    a, b = scale_exponents(Ib[0], Ib[1], Ib[2], mb[0], mb[1], mb[2])
    for k in range(3):
        Is[k] = np.ldexp(Ib[k], -a)
        ms[k] = np.ldexp(mb[k], -b)
    return regime_code(Is[0], Is[1], Is[2], ms[0], ms[1], ms[2]), a, b


@jit
def _all(moments, m0, Is, ms, regime, a, b):
    for i in range(moments.shape[0]):
        regime[i], a[i], b[i] = _state(moments[i], m0[i], Is[i], ms[i])


def classify_and_scale(moments, m0):
    """Regimes, scaled states and exponents (as ``classify`` and ``normalise``).

    Parameters
    ----------
    moments, m0 : ndarray, shape (N, 3)
        Validated moments and body angular momenta
        (:func:`andoyer.regime.check_inputs`).

    Returns
    -------
    regime : ndarray of int8, shape (N,)
        :class:`andoyer.regime.Regime` codes of the scaled states, the states the solution
        works on: those of the inputs (:func:`andoyer.regime.classify`) unless the scaling
        rounded a component below ``2⁻¹⁰²²`` times the largest (a subnormal).
    moments, m0 : ndarray, shape (N, 3)
        The states scaled by powers of two.
    a, b : ndarray of int, shape (N,)
        Exponents: ``I = 2^a I'``, ``m₀ = 2^b m₀'``.

    Examples
    --------
    >>> r, i, m, a, b = classify_and_scale(np.array([[3.0, 4.0, 6.0]]), np.array([[0.0, 48.0, 0.0]]))
    >>> r.tolist(), i.tolist(), m.tolist(), a.tolist(), b.tolist()
    ([2], [[0.375, 0.5, 0.75]], [[0.0, 0.75, 0.0]], [3], [6])
    """
    moments = np.ascontiguousarray(moments, dtype=np.float64)
    m0 = np.ascontiguousarray(m0, dtype=np.float64)
    n = moments.shape[0]
    Is, ms = np.empty((n, 3)), np.empty((n, 3))
    regime = np.empty(n, dtype=np.int8)
    a, b = np.empty(n, dtype=np.int64), np.empty(n, dtype=np.int64)
    _all(moments, m0, Is, ms, regime, a, b)
    return regime, Is, ms, a, b
