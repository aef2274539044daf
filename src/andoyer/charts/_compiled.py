"""Compiled loops of the Euler and Andoyer conversions over arrays of states (numba).

Each loop applies one scalar kernel of :mod:`andoyer.charts._kernels` state by state,
so an array conversion gives the same bits as the single-state fast path. The module
imports numba (through :mod:`andoyer._jit`); the chart modules import it only for
arrays, and only use it when ``NUMBA`` is true, else their numpy expressions.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from andoyer._jit import NUMBA, jit, jitable
from andoyer.charts import _kernels

__all__ = ["NUMBA", "andoyer_to_hub", "euler_to_hub", "hub_to_andoyer", "hub_to_euler"]

Array = NDArray[np.float64]

# The kernels' helpers, called by name inside them, compile inline.
for _helper in (_kernels.wrap_2pi, _kernels.atan2_2pi, _kernels.unit_quaternion, _kernels.from_zxz):
    jitable(_helper)

_hub_to_euler_one = jit(_kernels.hub_to_euler_one)
_euler_to_hub_one = jit(_kernels.euler_to_hub_one)
_hub_to_andoyer_one = jit(_kernels.hub_to_andoyer_one)
_andoyer_to_hub_one = jit(_kernels.andoyer_to_hub_one)


@jit
def _hub_to_euler_loop(q, m, out, singular):  # pragma: no cover - compiled
    for i in range(q.shape[0]):
        r = _hub_to_euler_one(q[i, 0], q[i, 1], q[i, 2], q[i, 3], m[i, 0], m[i, 1], m[i, 2])
        out[0, i], out[1, i], out[2, i], out[3, i], out[4, i], out[5, i] = r[0], r[1], r[2], r[3], r[4], r[5]
        singular[i] = r[6]


@jit
def _euler_to_hub_loop(phi, theta, psi, Phi, Theta, Psi, q, m, status):  # pragma: no cover - compiled
    for i in range(phi.shape[0]):
        r = _euler_to_hub_one(phi[i], theta[i], psi[i], Phi[i], Theta[i], Psi[i])
        q[i, 0], q[i, 1], q[i, 2], q[i, 3] = r[0], r[1], r[2], r[3]
        m[i, 0], m[i, 1], m[i, 2] = r[4], r[5], r[6]
        status[i] = r[7]


@jit
def _hub_to_andoyer_loop(q, m, out, on_pole_j, on_pole_i):  # pragma: no cover - compiled
    zero = 0
    for i in range(q.shape[0]):
        m1, m2, m3 = m[i, 0], m[i, 1], m[i, 2]
        if m1 * m1 + m2 * m2 + m3 * m3 <= 0:
            zero += 1
            continue
        r = _hub_to_andoyer_one(q[i, 0], q[i, 1], q[i, 2], q[i, 3], m1, m2, m3)
        out[0, i], out[1, i], out[2, i], out[3, i], out[4, i], out[5, i] = r[0], r[1], r[2], r[3], r[4], r[5]
        on_pole_j[i] = r[6]
        on_pole_i[i] = r[7]
    return zero


@jit
def _andoyer_to_hub_loop(l, g, h, L, G, H, q, m):  # pragma: no cover - compiled
    for i in range(l.shape[0]):
        r = _andoyer_to_hub_one(l[i], g[i], h[i], L[i], G[i], H[i])
        q[i, 0], q[i, 1], q[i, 2], q[i, 3] = r[0], r[1], r[2], r[3]
        m[i, 0], m[i, 1], m[i, 2] = r[4], r[5], r[6]


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
