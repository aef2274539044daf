"""Unit-quaternion arithmetic, scalar-last ``(x, y, z, w)`` as in scipy.

The hub state keeps its attitude as quaternions so that chart conversions on
millions of states are a handful of numpy expressions, with no per-state
Python work and no round trip through rotation matrices.

:func:`product` is the project's one Hamilton product and :func:`apply` its one rotation of
a vector: arithmetic on components only, so the same function serves floats, numpy arrays
of components (:func:`multiply` and :func:`rotate` on ``(..., 4)`` arrays), sympy and heyoka
expressions, and numba kernels, which compile it inline after :func:`andoyer._jit.jitable`
has registered it (the compiled modules do so; this module does not import numba).
"""

from __future__ import annotations

from math import cos, sin

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._jit import on_arrays

Array = NDArray[np.float64]


def cross(a: Array, b: Array) -> Array:
    """Cross product on the last axis (``np.cross`` spends ~20 µs on axis bookkeeping per call)."""
    a0, a1, a2 = a[..., 0], a[..., 1], a[..., 2]
    b0, b1, b2 = b[..., 0], b[..., 1], b[..., 2]
    return np.stack([a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0], axis=-1)


def product(px, py, pz, pw, qx, qy, qz, qw):
    """Hamilton product ``p ⊗ q`` of two quaternions given by their components.

    ``p ⊗ q = (p_w q_v + q_w p_v + p_v × q_v,  p_w q_w − p_v · q_v)`` with vector parts
    ``p_v = (p_x, p_y, p_z)``: active rotations compose as ``R(p ⊗ q) = R(p) R(q)``.
    Every other product of the project (arrays, compiled kernels, Pavlov's scalar-first
    ``λ``, sympy) calls this one.

    Parameters
    ----------
    px, py, pz, pw, qx, qy, qz, qw : float, ndarray or expression
        Components of ``p`` and ``q`` (scalar last), broadcast together.

    Returns
    -------
    tuple of 4
        ``(x, y, z, w)`` of ``p ⊗ q``.

    Examples
    --------
    ``i ⊗ j = k``:

    >>> product(1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0)
    (0.0, 0.0, 1.0, 0.0)
    """
    return (
        pw * qx + px * qw + py * qz - pz * qy,
        pw * qy - px * qz + py * qw + pz * qx,
        pw * qz + px * qy - py * qx + pz * qw,
        pw * qw - px * qx - py * qy - pz * qz,
    )


# From this many quaternions on, one transposing copy per operand (each component then
# contiguous) costs less than reading every component with a stride of four.
_CONTIGUOUS = 4096


def _components(q: Array):
    if q.size >= _CONTIGUOUS:
        return np.ascontiguousarray(np.moveaxis(q, -1, 0))
    return q[..., 0], q[..., 1], q[..., 2], q[..., 3]


def multiply(p: ArrayLike, q: ArrayLike) -> Array:
    """Hamilton product ``p ⊗ q`` of quaternion arrays (:func:`product` on their components).

    Parameters
    ----------
    p, q : array_like, shape (..., 4)
        Quaternions (scalar last), broadcast together.

    Returns
    -------
    ndarray, shape (..., 4)
        ``p ⊗ q``; active rotations compose as ``R(p ⊗ q) = R(p) R(q)``.

    Examples
    --------
    >>> multiply([0.0, 0.0, 0.0, 1.0], [0.5, 0.5, 0.5, 0.5]).tolist()
    [0.5, 0.5, 0.5, 0.5]
    """
    p = np.asarray(p, dtype=np.float64)
    q = np.asarray(q, dtype=np.float64)
    return np.stack(product(*_components(p), *_components(q)), axis=-1)


def conjugate(q: Array) -> Array:
    """Inverse of a unit quaternion."""
    return q * np.array([-1.0, -1.0, -1.0, 1.0])


def apply(qx, qy, qz, qw, vx, vy, vz):
    """The rotation of the unit quaternion ``q`` applied to the vector ``v``, by components.

    ``R(q) v = v + w t + u × t`` with ``t = 2 u × v``, ``u = (q_x, q_y, q_z)``, ``w = q_w``
    (``q ⊗ (v, 0) ⊗ q*`` expanded): the project's one formula, on floats, arrays, heyoka
    expressions and in numba kernels (registered with :func:`andoyer._jit.jitable`).
    ``R(q)ᵀ v`` is ``apply(−q_x, −q_y, −q_z, q_w, …)``.

    Parameters
    ----------
    qx, qy, qz, qw : float, ndarray or expression
        Unit quaternion (scalar last).
    vx, vy, vz : float, ndarray or expression
        The vector, broadcast with ``q``.

    Returns
    -------
    tuple of 3
        ``R(q) v``.

    Examples
    --------
    A quarter turn about ``z`` takes ``x`` to ``y``:

    >>> h = 0.5 ** 0.5
    >>> [round(c, 12) + 0.0 for c in apply(0.0, 0.0, h, h, 1.0, 0.0, 0.0)]
    [0.0, 1.0, 0.0]
    """
    tx = 2.0 * (qy * vz - qz * vy)
    ty = 2.0 * (qz * vx - qx * vz)
    tz = 2.0 * (qx * vy - qy * vx)
    return (
        vx + qw * tx + (qy * tz - qz * ty),
        vy + qw * ty + (qz * tx - qx * tz),
        vz + qw * tz + (qx * ty - qy * tx),
    )


def rotate(q: Array, v: Array) -> Array:
    """Apply the rotation of unit quaternions ``q`` (..., 4) to vectors ``v`` (..., 3) (:func:`apply`)."""
    q = np.asarray(q, dtype=np.float64)
    v = np.asarray(v, dtype=np.float64)
    return np.stack(apply(*_components(q), v[..., 0], v[..., 1], v[..., 2]), axis=-1)


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
