"""Compiled loops of the Euler and Andoyer conversions over arrays of states (numba).

Each loop (defined in :mod:`andoyer.state._kernels`, beside the scalar kernel it
applies state by state) is compiled here, so an array conversion gives the same bits as
the single-state fast path. The module
imports numba (through :mod:`andoyer._jit`); the chart modules import it only for
arrays, and only use it when ``NUMBA`` is true, else the same kernels on whole arrays
(the ``*_arrays`` functions of :mod:`andoyer.state._kernels`).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from andoyer._jit import NUMBA, jit, jitable
from andoyer.state import _kernels

__all__ = ["NUMBA", "andoyer_to_hub", "euler_to_hub", "hub_to_andoyer", "hub_to_euler"]

Array = NDArray[np.float64]

# The scalar kernels and their helpers, called by name inside the loops, compile inline.
for _helper in _kernels.HELPERS:
    jitable(_helper)

_hub_to_euler_loop = jit(_kernels.hub_to_euler_loop)
_euler_to_hub_loop = jit(_kernels.euler_to_hub_loop)
_hub_to_andoyer_loop = jit(_kernels.hub_to_andoyer_loop)
_andoyer_to_hub_loop = jit(_kernels.andoyer_to_hub_loop)


def _flat(values) -> list[Array]:
    return [np.ascontiguousarray(v, dtype=np.float64).reshape(-1) for v in values]


def hub_to_euler(q: Array, m: Array) -> tuple[Array, Array]:
    """Euler variables (6, n) and the singular mask (n,) of quaternions (n, 4) and momenta (n, 3)."""
    q, m = np.ascontiguousarray(q), np.ascontiguousarray(m)
    out = np.empty((6, q.shape[0]))
    singular = np.empty(q.shape[0], dtype=np.bool_)
    _hub_to_euler_loop(q, m, out, singular)
    return out, singular


def euler_to_hub(values) -> tuple[Array, Array, NDArray[np.int8]]:
    """Unit quaternions (n, 4), momenta (n, 3) and statuses (n,) of six Euler arrays of equal shape."""
    flat = _flat(values)
    n = flat[0].shape[0]
    q, m, status = np.empty((n, 4)), np.empty((n, 3)), np.empty(n, dtype=np.int8)
    _euler_to_hub_loop(*flat, q, m, status)
    return q, m, status


def hub_to_andoyer(q: Array, m: Array) -> tuple[Array, Array, Array, int]:
    """Andoyer variables (6, n), pole masks (n,) and the count of zero momenta, as the numpy kernel."""
    q, m = np.ascontiguousarray(q), np.ascontiguousarray(m)
    n = q.shape[0]
    out = np.empty((6, n))
    on_pole_j, on_pole_i = np.zeros(n, dtype=np.bool_), np.zeros(n, dtype=np.bool_)
    zero = _hub_to_andoyer_loop(q, m, out, on_pole_j, on_pole_i)
    return out, on_pole_j, on_pole_i, int(zero)


def andoyer_to_hub(values) -> tuple[Array, Array]:
    """Unit quaternions (n, 4) and momenta (n, 3) of six checked Andoyer arrays of equal shape."""
    flat = _flat(values)
    n = flat[0].shape[0]
    q, m = np.empty((n, 4)), np.empty((n, 3))
    _andoyer_to_hub_loop(*flat, q, m)
    return q, m
