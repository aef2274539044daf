"""Regimes and power-of-two scaling of many states in one compiled loop.

:func:`andoyer.free.regime.classify` and :func:`andoyer.free.regime.normalise` for
validated inputs, per state in a numba kernel: the same exponents, the same scaled
values and the same regimes (the sign of ``P₂ = G²/B − D`` from the same error-free
products and double-double sums, :mod:`andoyer.special.compensated`, so the decision is the
same bit for bit).  :class:`andoyer.free.FreeMotion` uses it when numba is installed.
"""

from __future__ import annotations

import math

import numpy as np

from andoyer._jit import jit
from andoyer.free.regime import Regime
from andoyer.special.compensated import dd_add, dd_mul, two_prod, two_sum

__all__ = ["classify_and_scale"]

_SAM, _LAM, _SEP = int(Regime.SAM), int(Regime.LAM), int(Regime.SEPARATRIX)
_AXI, _SPHERE, _REST = int(Regime.AXISYMMETRIC), int(Regime.SPHERE), int(Regime.REST)


@jit
def _state(Ib, mb, Is, ms):
    """Scale one state into ``Is, ms``; return its regime code and the exponents ``a, b``."""
    a = math.frexp(max(Ib[0], Ib[1], Ib[2]))[1]
    big = max(abs(mb[0]), abs(mb[1]), abs(mb[2]))
    b = math.frexp(big if big > 0 else 1.0)[1]
    for k in range(3):
        Is[k] = math.ldexp(Ib[k], -a)
        ms[k] = math.ldexp(mb[k], -b)
    o0, o1, o2 = 0, 1, 2  # stable sort of three moments
    if Is[o1] < Is[o0]:
        o0, o1 = o1, o0
    if Is[o2] < Is[o1]:
        o1, o2 = o2, o1
        if Is[o1] < Is[o0]:
            o0, o1 = o1, o0
    A, B, C = Is[o0], Is[o1], Is[o2]
    if big == 0:
        return _REST, a, b
    if A == C:
        return _SPHERE, a, b
    if B in (A, C):
        return _AXI, a, b
    # m_C² (C − B) A − m_A² (B − A) C: the sign of P₂ (andoyer.free.regime._separatrix_sign)
    ma, mc = ms[o0], ms[o2]
    t1 = dd_mul(*two_prod(mc, mc), *dd_mul(*two_sum(C, -B), A, 0.0))
    t2 = dd_mul(*two_prod(ma, ma), *dd_mul(*two_sum(B, -A), C, 0.0))
    hi = dd_add(t1[0], t1[1], -t2[0], -t2[1])[0]
    return (_SAM if hi > 0 else (_LAM if hi < 0 else _SEP)), a, b


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
        (:func:`andoyer.free.regime.check_inputs`).

    Returns
    -------
    regime : ndarray of int8, shape (N,)
        :class:`andoyer.free.regime.Regime` codes.
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
