"""Cache-friendly evaluation for the vectorised hot paths.

numpy's ``arctan2`` costs about 50 ns per element while ``arctan`` costs
about 12 ns, and on arrays of millions of states every temporary lives in
main memory. :func:`atan2_2pi` rebuilds ``atan2`` from ``arctan`` on the
octant-reduced ratio (error within 2 ulp of the result), and :func:`chunked`
evaluates an element-wise kernel on slices small enough for the temporaries
to stay in cache. Together they make the state → Andoyer conversion about
2.5 times faster at 10⁶ states (``benchmarks/bench_conversions.py``).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np
from numpy.typing import NDArray

Array = NDArray[np.float64]

TWO_PI = 2.0 * np.pi
HALF_PI = 0.5 * np.pi

#: Elements per slice: eight float64 temporaries of this length fit in a 512 KiB cache.
CHUNK = 8192


def atan2_2pi(y: Array, x: Array) -> Array:
    """``atan2(y, x)`` mapped to ``[0, 2π)``; ``(0, 0)`` gives 0."""
    ax, ay = np.abs(x), np.abs(y)
    big = np.maximum(ax, ay)
    a = np.arctan(np.minimum(ax, ay) / np.where(big == 0, 1.0, big))
    a = np.where(ay > ax, HALF_PI - a, a)
    a = np.where(x < 0, np.pi - a, a)
    a = np.where(y < 0, TWO_PI - a, a)
    # 2π - (tiny) rounds to 2π: fold it onto 0, the same point of the circle.
    return np.where(a >= TWO_PI, 0.0, a)


def wrap_2pi(a: Array) -> Array:
    """Angles reduced to ``[0, 2π)`` (``np.mod`` alone can return 2π for tiny negatives)."""
    r = np.mod(a, TWO_PI)
    return np.where(r >= TWO_PI, 0.0, r)


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
        return [np.asarray(r, dtype=float) for r in kernel(*arrays)]
    out = np.empty((n_out, n))
    for start in range(0, n, chunk):
        stop = min(start + chunk, n)
        for k, value in enumerate(kernel(*(a[start:stop] for a in arrays))):
            out[k, start:stop] = value
    return list(out)
