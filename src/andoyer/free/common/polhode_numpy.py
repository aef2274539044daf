r"""The polhode-centred working frame of triaxial states on arrays (the numpy driver of ``polhode``).

Working frame.  The kernels use body axes relabelled by a signed permutation ``P``
(a proper rotation) such that axis 3 is the axis the polhode circles (``C`` for SAM and
the separatrix, ``A`` for LAM), axis 2 is the middle axis ``B`` and ``m₃ > 0``:
``m_w = P m_body`` and ``rot = rot_w · P``.  In that frame, with ``wᵢ = 1/Iᵢ`` and
``s = sign(w₁ − w₃)`` (``+1`` SAM, ``−1`` LAM), the positive quantities

.. math::
   e_{ij} = s (w_i - w_j),\quad
   P_1 = m_1^2 e_{13} + m_2^2 e_{23} = s(D - G^2 w_3),\quad
   P_3 = m_2^2 e_{12} + m_3^2 e_{13} = s(G^2 w_1 - D),\quad
   P_2 = m_3^2 e_{23} - m_1^2 e_{12} = s(G^2 w_2 - D)

give every constant of the solution (:mod:`andoyer.free.triaxial.setup`).  Each formula of the
frame is one kernel of :mod:`andoyer.free.common.polhode`, run here on arrays and by the compiled
set-up on floats.

Quaternions on component arrays (scalar last, as scipy).  A rotation ``rot`` (body → reference)
is the unit quaternion ``q = (x, y, z, w)`` with ``v_ref = q ⊗ (v_body, 0) ⊗ q*``; composition
``rot_a · rot_b`` is ``q_a ⊗ q_b``, the one product :func:`andoyer._quaternion.product`.
Components are kept as separate arrays (a tuple of four) in the hot loops, so that numpy
broadcasts per-body constants against per-epoch arrays without stacking.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from andoyer.free.common import polhode as kf

__all__ = [
    "PolhodeFrame",
    "anchored_attitude",
    "attitude_anchor",
    "matrix_quat",
    "polhode_frame",
    "shortest_arc",
    "working_axes",
]


class PolhodeFrame(NamedTuple):
    """Working-frame data of triaxial states (flat arrays of length ``N``).

    Attributes
    ----------
    perm : ndarray of int, shape (N, 3)
        ``perm[:, j]`` is the body axis that becomes working axis ``j``.
    sign : ndarray, shape (N, 3)
        Signs ``σⱼ``: working axis ``j`` is ``σⱼ b_{perm[j]}`` (a proper rotation).
    s : ndarray, shape (N,)
        ``+1`` for SAM and the separatrix (axis 3 is ``C``), ``−1`` for LAM (axis 3 is ``A``).
    Iw, mw : ndarray, shape (N, 3)
        Moments and angular momentum in the working frame (``mw[:, 2] ≥ 0``).
    e12, e13, e23, P1, P2, P3, G, w3 : tuple of ndarray
        Double-double ``(hi, lo)`` pairs of the quantities defined in the module docstring
        (``G = |m|``, ``w3 = 1/I₃``).
    """

    perm: np.ndarray
    sign: np.ndarray
    s: np.ndarray
    Iw: np.ndarray
    mw: np.ndarray
    e12: tuple
    e13: tuple
    e23: tuple
    P1: tuple
    P2: tuple
    P3: tuple
    G: tuple
    w3: tuple


def polhode_frame(moments, m0, lam):
    """Working frame and double-double invariants of triaxial states.

    The kernels of :mod:`andoyer.free.common.polhode` on arrays (the compiled set-up runs the
    same kernels on floats).

    Parameters
    ----------
    moments, m0 : ndarray, shape (N, 3)
        Moments (strictly triaxial) and body angular momenta.
    lam : ndarray of bool, shape (N,)
        True for LAM states (polhode around ``A``), False for SAM and separatrix (``C``).

    Returns
    -------
    PolhodeFrame

    Examples
    --------
    >>> fr = polhode_frame(np.array([[3.0, 1.0, 2.0]]), np.array([[1.0, 0.1, -0.2]]),
    ...                    np.array([False]))
    >>> fr.perm.tolist(), fr.mw.tolist()
    ([[1, 2, 0]], [[0.1, -0.2, 1.0]])
    """
    i = [moments[:, k] for k in range(3)]
    m = [m0[:, k] for k in range(3)]
    a, b, c = kf.sorted_axes(*i)
    p1, p2, p3, sigma2, sigma3 = kf.polhode_axes(a, b, c, lam, *m)
    perm = np.stack([p1, p2, p3], axis=-1)
    sign = np.stack([np.ones_like(sigma3), sigma2, sigma3], axis=-1)
    Iw = np.take_along_axis(moments, perm, axis=-1)
    mw = np.take_along_axis(m0, perm, axis=-1) * sign
    s = np.where(lam, -1.0, 1.0)
    inv = kf.invariants(s, Iw[:, 0], Iw[:, 1], Iw[:, 2], mw[:, 0], mw[:, 1], mw[:, 2])
    e12, e13, e23, P1, P2, P3, G, w3 = inv
    return PolhodeFrame(perm, sign, s, Iw, mw, e12, e13, e23, P1, P2, P3, G, w3)


def working_axes(frame: PolhodeFrame):
    """Body components of the working axes.

    Parameters
    ----------
    frame : PolhodeFrame

    Returns
    -------
    ndarray, shape (3, 3, N)
        ``cols[j][:, i]`` is working axis ``j`` of state ``i`` in body components, so that
        ``m_body = Σⱼ m_w[j] cols[j]`` and ``P[i] = cols[:, :, i]`` (rows) maps body to
        working components.

    Examples
    --------
    >>> fr = polhode_frame(np.array([[3.0, 1.0, 2.0]]), np.array([[1.0, 0.1, -0.2]]),
    ...                    np.array([False]))
    >>> working_axes(fr)[:, :, 0].tolist()
    [[0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0]]
    """
    n = frame.s.size
    cols = np.zeros((3, 3, n))
    for j in range(3):
        np.put_along_axis(cols[j].T, frame.perm[:, j : j + 1], frame.sign[:, j : j + 1], axis=1)
    return cols


def attitude_anchor(frame: PolhodeFrame, q0):
    """Constant quaternions ``U = Q₀ ⊗ P`` and ``V = Q₀ ⊗ e_z ⊗ P`` of the attitude.

    The attitude is ``rot(t) = Q₀ ⊗ R_z(Δψ) ⊗ S(m_w(t)) ⊗ P`` with ``P`` the working frame
    (body → working), ``S`` the shortest arc taking ``m_w`` to ``+z`` and
    ``Q₀ = q₀ ⊗ P* ⊗ S(m_w(0))*``; writing ``R_z(Δψ) = cos(Δψ/2) + sin(Δψ/2) e_z`` and
    moving ``P`` through ``S`` gives
    ``rot(t) = (cos(Δψ/2) U + sin(Δψ/2) V) ⊗ (P* ⊗ S ⊗ P)``.  The kernels
    :func:`andoyer.free.common.polhode.permutation_quaternion` and
    :func:`andoyer.free.common.polhode.anchor` on arrays (the compiled set-up runs them on floats).

    Parameters
    ----------
    frame : PolhodeFrame
    q0 : ndarray, shape (N, 4)
        Initial attitudes (unit quaternions, scalar last, body → reference).

    Returns
    -------
    U, V : ndarray, shape (4, N)

    Examples
    --------
    >>> fr = polhode_frame(np.array([[1.0, 2.0, 3.0]]), np.array([[0.0, 0.0, 1.0]]),
    ...                    np.array([False]))
    >>> U, V = attitude_anchor(fr, np.array([[0.0, 0.0, 0.0, 1.0]]))
    >>> U[:, 0].tolist(), V[:, 0].tolist()
    ([0.0, 0.0, 0.0, 1.0], [0.0, 0.0, 1.0, 0.0])
    """
    perm, sign, mw = frame.perm, frame.sign, frame.mw
    pq = kf.permutation_quaternion(perm[:, 0], perm[:, 1], perm[:, 2], sign[:, 1], sign[:, 2])
    u, v = kf.anchor(*q0.T, pq, mw[:, 0], mw[:, 1], mw[:, 2], frame.G[0])
    return np.stack(u), np.stack(v)


def shortest_arc(m):
    """Rotation taking the direction of ``m`` to ``+z`` by the shortest arc, on ``(..., 3)`` arrays.

    ``S(m) = (m_y, −m_x, 0, |m| + m_z) / √(2|m|(|m| + m_z))``: the rotation about
    ``m × z`` by the angle between them; regular wherever ``m`` is not along ``−z``
    (the kernel :func:`andoyer.free.common.polhode.shortest_arc`).

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
    return np.stack(np.broadcast_arrays(*kf.shortest_arc(m[..., 0], m[..., 1], m[..., 2], g)), axis=-1)


def anchored_attitude(c, half, arc, m3):
    """Attitude ``(cos U + sin V) ⊗ (v, G + m₃)/√(2G(G + m₃))`` on component arrays.

    The per-epoch end of the construction of
    :func:`andoyer.free.common.polhode_numpy.attitude_anchor`: ``(cos, sin)`` of ``Δψ/2`` combine the
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
    return kf.attitude(*half, c.quat_u, c.quat_v, va, vb, xa, xb, m3, c.G)


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
