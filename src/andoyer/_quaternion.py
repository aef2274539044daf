"""Vectorised unit-quaternion arithmetic, scalar-last ``(x, y, z, w)`` as in scipy.

The hub state keeps its attitude as quaternions so that chart conversions on
millions of states are a handful of numpy expressions, with no per-state
Python work and no round trip through rotation matrices.
"""

from __future__ import annotations

from math import cos, sin

import numpy as np
from numpy.typing import NDArray

from andoyer._jit import on_arrays

Array = NDArray[np.float64]


def cross(a: Array, b: Array) -> Array:
    """Cross product on the last axis (``np.cross`` spends ~20 µs on axis bookkeeping per call)."""
    a0, a1, a2 = a[..., 0], a[..., 1], a[..., 2]
    b0, b1, b2 = b[..., 0], b[..., 1], b[..., 2]
    return np.stack([a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0], axis=-1)


def multiply(p: Array, q: Array) -> Array:
    """Hamilton product ``p ⊗ q`` (active rotations compose as ``R(p) R(q)``)."""
    px, py, pz, pw = p[..., 0], p[..., 1], p[..., 2], p[..., 3]
    qx, qy, qz, qw = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    return np.stack(
        [
            pw * qx + px * qw + py * qz - pz * qy,
            pw * qy - px * qz + py * qw + pz * qx,
            pw * qz + px * qy - py * qx + pz * qw,
            pw * qw - px * qx - py * qy - pz * qz,
        ],
        axis=-1,
    )


def conjugate(q: Array) -> Array:
    """Inverse of a unit quaternion."""
    return q * np.array([-1.0, -1.0, -1.0, 1.0])


def rotate(q: Array, v: Array) -> Array:
    """Apply the rotation of unit quaternions ``q`` (..., 4) to vectors ``v`` (..., 3)."""
    u = q[..., :3]
    w = q[..., 3:]
    t = 2.0 * cross(u, v)
    return v + w * t + cross(u, t)


def from_zxz_one(a: float, b: float, c: float) -> tuple[float, float, float, float]:
    """Quaternion ``(x, y, z, w)`` of ``Rz(a) Rx(b) Rz(c)`` (intrinsic 3-1-3 sequence): the scalar kernel.

    ``w = cos(b/2) cos((a+c)/2)``, ``z = cos(b/2) sin((a+c)/2)``,
    ``x = sin(b/2) cos((a-c)/2)``, ``y = sin(b/2) sin((a-c)/2)``. Written once for floats,
    the compiled chart loops and (through :func:`andoyer._jit.on_arrays`) :func:`from_zxz`.

    Examples
    --------
    >>> [round(v, 12) for v in from_zxz_one(0.0, 3.141592653589793, 0.0)]
    [1.0, 0.0, 0.0, 0.0]
    """
    half_sum = 0.5 * (a + c)
    half_diff = 0.5 * (a - c)
    cb, sb = cos(0.5 * b), sin(0.5 * b)
    return sb * cos(half_diff), sb * sin(half_diff), cb * sin(half_sum), cb * cos(half_sum)


def from_xz_one(b: float, c: float) -> tuple[float, float, float, float]:
    """Quaternion ``(x, y, z, w)`` of ``Rx(b) Rz(c)``: the scalar kernel of :func:`from_xz`.

    Examples
    --------
    >>> [round(v, 12) for v in from_xz_one(0.0, 3.141592653589793)]
    [0.0, -0.0, 1.0, 0.0]
    """
    cb, sb = cos(0.5 * b), sin(0.5 * b)
    cc, sc = cos(0.5 * c), sin(0.5 * c)
    return sb * cc, -sb * sc, cb * sc, cb * cc


_from_zxz_arrays, _from_xz_arrays = on_arrays(from_zxz_one, from_xz_one)


def from_zxz(a: Array, b: Array, c: Array) -> Array:
    """Quaternion of ``Rz(a) Rx(b) Rz(c)``, shape (..., 4): :func:`from_zxz_one` on arrays."""
    return np.stack(_from_zxz_arrays(a, b, c), axis=-1)


def from_xz(b: Array, c: Array) -> Array:
    """Quaternion of ``Rx(b) Rz(c)``, shape (..., 4): :func:`from_xz_one` on arrays."""
    return np.stack(_from_xz_arrays(b, c), axis=-1)


def normalise(q: Array) -> Array:
    """Scale quaternions to unit norm."""
    return q / np.linalg.norm(q, axis=-1, keepdims=True)
