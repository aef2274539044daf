"""Angles on ``[0, 2π)`` written once, and cache-friendly evaluation for the vectorised hot paths.

numpy's ``arctan2`` costs about 50 ns per element while ``arctan`` costs
about 12 ns, and on arrays of millions of states every temporary lives in
main memory. :func:`atan2_2pi_one` rebuilds ``atan2`` from ``atan`` on the
octant-reduced ratio (error within 2 ulp of the result), and :func:`chunked`
evaluates an element-wise kernel on slices small enough for the temporaries
to stay in cache. Together they make the state → Andoyer conversion about
2.5 times faster at 10⁶ states (``benchmarks/bench_conversions.py``).

:func:`wrap_2pi_one` and :func:`atan2_2pi_one` are scalar kernels (:mod:`math`, branches through
:func:`andoyer._jit.select`): Python on floats, compiled inline by the callers' numba loops;
:func:`wrap_2pi` and :func:`atan2_2pi` are the same code on whole arrays
(:func:`andoyer._jit.on_arrays`):

>>> atan2_2pi(np.array([1.0, -1.0]), np.array([0.0, 0.0])).tolist() == [HALF_PI, 3 * HALF_PI]
True
>>> wrap_2pi(np.array([-1e-300, 7.0])).tolist() == [0.0, 7.0 - TWO_PI]
True
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from math import atan

import numpy as np
from numpy.typing import NDArray

from andoyer._jit import on_arrays, select

__all__ = ["atan2_2pi", "atan2_2pi_one", "chunked", "wrap_2pi", "wrap_2pi_one"]

Array = NDArray[np.float64]

PI = 3.141592653589793
TWO_PI = 2.0 * PI
HALF_PI = 0.5 * PI

#: Elements per slice: eight float64 temporaries of this length fit in a 512 KiB cache.
CHUNK = 8192


def atan2_2pi_one(y: float, x: float) -> float:
    """``atan2(y, x)`` mapped to ``[0, 2π)``; ``(0, 0)`` gives 0 (the kernel of :func:`atan2_2pi`).

    ``a = atan(min/max)`` of ``|x|``, ``|y|`` (``max = 0`` read as 1), reflected into the
    octant of ``(x, y)``: ``π/2 - a`` above the diagonal, ``π - a`` for ``x < 0``, ``2π - a``
    for ``y < 0``.

    Examples
    --------
    >>> atan2_2pi_one(-1.0, 0.0) == 1.5 * PI
    True
    """
    ax, ay = abs(x), abs(y)
    above = ay > ax
    big = select(above, ay, ax)
    a = atan(select(above, ax, ay) / select(big == 0, 1.0, big))
    a = select(above, HALF_PI - a, a)
    a = select(x < 0, PI - a, a)
    a = select(y < 0, TWO_PI - a, a)
    # 2π - (tiny) rounds to 2π: fold it onto 0, the same point of the circle.
    return select(a >= TWO_PI, 0.0, a)


def wrap_2pi_one(a: float) -> float:
    """``a`` reduced to ``[0, 2π)`` (the kernel of :func:`wrap_2pi`; ``a % 2π`` alone can give 2π).

    Examples
    --------
    >>> wrap_2pi_one(-1e-300)
    0.0
    """
    r = a % TWO_PI
    return select(r >= TWO_PI, 0.0, r)


atan2_2pi, wrap_2pi = on_arrays(atan2_2pi_one, wrap_2pi_one)
atan2_2pi.__doc__ = "``atan2(y, x)`` mapped to ``[0, 2π)`` on arrays (:func:`atan2_2pi_one`); (0, 0) gives 0."
wrap_2pi.__doc__ = "Angles reduced to ``[0, 2π)`` on arrays (:func:`wrap_2pi_one`)."


def chunked(
    kernel: Callable[..., Sequence[Array]], arrays: Sequence[Array], n_out: int, chunk: int = CHUNK
) -> list[Array]:
    """Apply an element-wise ``kernel`` to 1-D ``arrays`` slice by slice.

    ``kernel(*slices)`` returns ``n_out`` arrays of the slice's length; the
    results are written into preallocated outputs of dtype float64 (boolean
    outputs come back as 0.0/1.0).
    """
    n = arrays[0].shape[0]
    if n <= chunk:
        # copies: a kernel may hand back one of its inputs, which the caller must not alias
        return [np.array(r, dtype=float) for r in kernel(*arrays)]
    out = np.empty((n_out, n))
    for start in range(0, n, chunk):
        stop = min(start + chunk, n)
        for k, value in enumerate(kernel(*(a[start:stop] for a in arrays))):
            out[k, start:stop] = value
    return list(out)
