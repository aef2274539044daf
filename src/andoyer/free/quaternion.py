"""Quaternions of the free solution on component arrays (scalar last, as scipy).

A rotation ``rot`` (body → reference) is the unit quaternion ``q = (x, y, z, w)`` with
``v_ref = q ⊗ (v_body, 0) ⊗ q*``; composition ``rot_a · rot_b`` is ``q_a ⊗ q_b``, the one
product :func:`andoyer._quaternion.product`. Components are kept as separate arrays (a tuple
of four) in the hot loops, so that numpy broadcasts per-body constants against per-epoch
arrays without stacking.
"""

from __future__ import annotations

import numpy as np

from andoyer.free.kernels import series
from andoyer.free.kernels.frame import shortest_arc as arc

__all__ = ["anchored_attitude", "matrix_quat", "shortest_arc"]


def shortest_arc(m):
    """Rotation taking the direction of ``m`` to ``+z`` by the shortest arc, on ``(..., 3)`` arrays.

    ``S(m) = (m_y, −m_x, 0, |m| + m_z) / √(2|m|(|m| + m_z))``: the rotation about
    ``m × z`` by the angle between them; regular wherever ``m`` is not along ``−z``
    (the kernel :func:`andoyer.free.kernels.frame.shortest_arc`).

    Parameters
    ----------
    m : array_like, shape (..., 3)
        Vectors with ``m_z > −|m|``.

    Returns
    -------
    ndarray, shape (..., 4)

    Examples
    --------
    >>> from scipy.spatial.transform import Rotation
    >>> q = shortest_arc([1.0, 2.0, 2.0])
    >>> Rotation.from_quat(q).apply([1.0, 2.0, 2.0]).round(12).tolist()
    [0.0, 0.0, 3.0]
    """
    m = np.asarray(m, dtype=np.float64)
    g = np.sqrt(np.sum(m * m, axis=-1))
    return np.stack(np.broadcast_arrays(*arc(m[..., 0], m[..., 1], m[..., 2], g)), axis=-1)


def anchored_attitude(c, half, arc, m3):
    """Attitude ``(cos U + sin V) ⊗ (v, G + m₃)/√(2G(G + m₃))`` on component arrays.

    The per-epoch end of the construction of
    :func:`andoyer.free.regime.attitude_anchor`: ``(cos, sin)`` of ``Δψ/2`` combine the
    constant quaternions ``U, V``, and the body-frame shortest-arc factor has the vector
    part ``v = v_a x_a + v_b x_b`` (constant body vectors times per-epoch scalars).

    Parameters
    ----------
    c : NamedTuple
        Constants with fields ``quat_u``, ``quat_v`` (``(4, …)``) and ``G``.
    half : tuple of ndarray
        ``(cos(Δψ/2), sin(Δψ/2))``.
    arc : tuple
        ``((v_a, x_a), (v_b, x_b))``: vectors ``(3, …)`` and their scalar factors.
    m3 : ndarray
        Polhode-axis component of the momentum in the working frame.

    Returns
    -------
    tuple of 4 ndarray
        Quaternion components ``(x, y, z, w)``.

    Examples
    --------
    >>> from collections import namedtuple
    >>> C = namedtuple("C", "quat_u quat_v G")
    >>> c = C(np.array([0.0, 0.0, 0.0, 1.0]), np.array([0.0, 0.0, 1.0, 0.0]), 1.0)
    >>> e = np.eye(3)
    >>> [float(x) for x in anchored_attitude(c, (1.0, 0.0), ((e[0], 0.0), (e[1], 0.0)), 1.0)]
    [0.0, 0.0, 0.0, 1.0]
    """
    (va, xa), (vb, xb) = arc
    return series.attitude(*half, c.quat_u, c.quat_v, va, vb, xa, xb, m3, c.G)


def matrix_quat(cols):
    """Quaternions of rotations given by the rows of their matrices (Shepperd's largest pivot).

    The algorithm of ``scipy.spatial.transform.Rotation.from_matrix`` for exact rotation
    matrices (here signed permutations), without its per-call overhead.

    Parameters
    ----------
    cols : ndarray, shape (3, 3, N)
        ``cols[j][:, i]`` is row ``j`` of matrix ``i``.

    Returns
    -------
    ndarray, shape (4, N)
        Unit quaternions (scalar last).

    Examples
    --------
    >>> cols = np.array([[0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])[..., None]
    >>> matrix_quat(cols)[:, 0].round(12).tolist()  # a quarter turn about -z (sign free)
    [0.0, 0.0, 0.707106781187, -0.707106781187]
    """
    M = np.moveaxis(cols, -1, 0)  # (N, 3, 3), M[:, j] = cols[j]
    diag = np.stack([M[:, 0, 0], M[:, 1, 1], M[:, 2, 2]])
    tr = diag.sum(axis=0)
    choice = np.argmax(np.vstack([diag, tr]), axis=0)
    q = np.empty((4, M.shape[0]))
    for i in range(3):
        sel = choice == i
        j, k = (i + 1) % 3, (i + 2) % 3
        Ms = M[sel]
        q[i, sel] = 1.0 - tr[sel] + 2.0 * Ms[:, i, i]
        q[j, sel] = Ms[:, j, i] + Ms[:, i, j]
        q[k, sel] = Ms[:, k, i] + Ms[:, i, k]
        q[3, sel] = Ms[:, k, j] - Ms[:, j, k]
    sel = choice == 3
    Ms = M[sel]
    q[0, sel] = Ms[:, 2, 1] - Ms[:, 1, 2]
    q[1, sel] = Ms[:, 0, 2] - Ms[:, 2, 0]
    q[2, sel] = Ms[:, 1, 0] - Ms[:, 0, 1]
    q[3, sel] = 1.0 + tr[sel]
    return q / np.sqrt(np.sum(q * q, axis=0))
