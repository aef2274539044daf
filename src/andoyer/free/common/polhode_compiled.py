"""The working frame of many states in one compiled loop (the compiled driver of ``polhode``).

:func:`polhode_limit`: the period and precession rate of steady spins about the polhode axis,
the limit of nearby polhodes, from the kernels of :mod:`andoyer.free.common.polhode` per state
(:class:`andoyer.free.FreeMotion` forms the same numbers with
:func:`andoyer.free.common.polhode_numpy.polhode_frame` on the numpy backend).
"""

from __future__ import annotations

import numpy as np

from andoyer._jit import jit
from andoyer.free.common.polhode import invariants, polhode_axes, sorted_axes, steady_spin_limit

__all__ = ["polhode_limit"]


@jit
def _limits(moments, m0, lam, period, rate):
    for i in range(moments.shape[0]):
        I, m = moments[i], m0[i]
        a, b, c = sorted_axes(I[0], I[1], I[2])
        p1, p2, p3, _, _ = polhode_axes(a, b, c, lam[i], m[0], m[1], m[2])
        s = -1.0 if lam[i] else 1.0
        _, e13, e23, _, _, _, G, w3 = invariants(
            s, I[p1], I[p2], I[p3], m[p1], m[p2], m[p3]
        )
        period[i], rate[i] = steady_spin_limit(s, e13[0], e23[0], G[0], w3[0])


def polhode_limit(moments, m0, lam):
    """Period and precession rate of a steady spin about the polhode axis: the limit of nearby polhodes.

    ``ω = G √(e₁₃ e₂₃)``, period ``2π/ω`` and rate ``G w₃ + s ω`` in the working frame of
    :func:`andoyer.free.common.polhode_numpy.polhode_frame` (the numbers
    :class:`andoyer.free.FreeMotion` forms from it without numba).

    Parameters
    ----------
    moments, m0 : ndarray, shape (N, 3)
        Strictly triaxial moments and body angular momenta (steady spins).
    lam : ndarray of bool, shape (N,)
        True for a spin about the axis of least moment.

    Returns
    -------
    period, rate : ndarray, shape (N,)

    Examples
    --------
    >>> period, rate = polhode_limit(np.array([[1.0, 2.0, 4.0]]), np.array([[0.0, 0.0, 1.0]]),
    ...                              np.array([False]))
    >>> round(float(period[0]), 12), round(float(rate[0]), 12)  # ω = √(3/4 · 1/4)
    (14.510394913874, 0.683012701892)
    """
    n = moments.shape[0]
    period, rate = np.empty(n), np.empty(n)
    _limits(
        np.ascontiguousarray(moments, dtype=np.float64),
        np.ascontiguousarray(m0, dtype=np.float64),
        np.ascontiguousarray(lam, dtype=np.bool_),
        period,
        rate,
    )
    return period, rate
