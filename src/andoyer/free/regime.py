r"""Regimes of torque-free rotation and the polhode-centred working frame.

With the sorted moments ``A ≤ B ≤ C``, the angular momentum ``G = |m|`` and twice the
kinetic energy ``D = 2T = Σ mᵢ²/Iᵢ``, the body angular momentum of a triaxial body
circulates around the axis of maximum inertia (SAM, ``G²/C ≤ D < G²/B``), around the
axis of minimum inertia (LAM, ``G²/B < D ≤ G²/A``), or lies on the separatrix
(``D = G²/B``).  The sign of

.. math:: P_2 = G^2/B - D = m_C^2 \Big(\frac1B - \frac1C\Big) - m_A^2 \Big(\frac1A - \frac1B\Big)

decides; it is a difference of nearly equal numbers near the separatrix, so it is
formed in double-double arithmetic from the exact products of the inputs (the
differences of moments and the squares of the components are exact there), which
makes the classification exact for the floating-point inputs as given.

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

give every constant of the solution (:mod:`andoyer.free.triaxial`).
"""

from __future__ import annotations

from enum import IntEnum
from typing import NamedTuple

import numpy as np

from andoyer._quaternion import product
from andoyer.free.quaternion import matrix_quat, shortest_arc
from andoyer.special.compensated import dd_add, dd_div, dd_mul, dd_sqrt, two_prod, two_sum

__all__ = [
    "PolhodeFrame",
    "Regime",
    "attitude_anchor",
    "check_inputs",
    "classify",
    "classify_scaled",
    "normalise",
    "polhode_frame",
    "working_axes",
]

class Regime(IntEnum):
    """Kind of torque-free motion of one body and state."""

    SAM = 0
    """Short-axis mode: the momentum circles the axis of maximum inertia (triaxial body)."""
    LAM = 1
    """Long-axis mode: the momentum circles the axis of minimum inertia (triaxial body)."""
    SEPARATRIX = 2
    """On the separatrix (``2T = G²/B``), including steady spin about the middle axis."""
    AXISYMMETRIC = 3
    """Two equal moments (not three): regular precession."""
    SPHERE = 4
    """Three equal moments: uniform rotation about the fixed momentum."""
    REST = 5
    """Zero angular momentum: the body does not move."""


def check_inputs(moments, m0):
    """Validate moments and body angular momenta and broadcast them to a common shape.

    Parameters
    ----------
    moments : array_like, shape (..., 3)
        Principal moments along body axes b1, b2, b3: positive, finite, any order.  The
        solution does not need the triangle inequality ``A + B ≥ C`` of a mass distribution
        (:class:`~andoyer.RigidBody` warns where it fails).
    m0 : array_like, shape (..., 3)
        Body-frame angular momentum, finite.

    Returns
    -------
    moments, m0 : ndarray, shape (..., 3)
        Float64 arrays broadcast against each other.

    Raises
    ------
    ValueError
        On a wrong shape, a non-finite value or a non-positive moment.

    Examples
    --------
    >>> moments, m = check_inputs([1.0, 2.0, 2.5], [[0.1, 0.2, 1.0], [1.0, 0.0, 0.0]])
    >>> moments.shape, m.shape
    ((2, 3), (2, 3))
    """
    moments = np.asarray(moments, dtype=np.float64)
    m0 = np.asarray(m0, dtype=np.float64)
    for name, a in (("moments", moments), ("m0", m0)):
        if a.ndim == 0 or a.shape[-1] != 3:
            raise ValueError(f"expected {name} with shape (..., 3), got shape {a.shape}")
        if not np.all(np.isfinite(a)):
            raise ValueError(f"expected finite {name}, got {a[~np.isfinite(a)].ravel()[:3]}")
    if np.any(moments <= 0):
        bad = moments[moments <= 0].ravel()[:3]
        raise ValueError(f"expected positive moments of inertia, got {bad}")
    shape = np.broadcast_shapes(moments.shape, m0.shape)
    return np.broadcast_to(moments, shape), np.broadcast_to(m0, shape)


def normalise(moments, m0):
    """Scale moments and momenta by powers of two into ``[1/2, 1)`` (exact, per state).

    The motion is covariant: with ``I = 2^a I'`` and ``m₀ = 2^b m₀'``,
    ``m(t) = 2^b m'(2^{b−a} t)`` and the attitude is ``q'(2^{b−a} t)``.  Working on the
    scaled state keeps every product of the solution (``m²/I`` in double-double, ``K``,
    frequencies) far from overflow and underflow whatever the units.

    Parameters
    ----------
    moments, m0 : ndarray, shape (..., 3)

    Returns
    -------
    moments, m0 : ndarray
        Scaled copies (the largest moment and the largest ``|m₀|`` component in ``[1/2, 1)``).
    a, b : ndarray of int, shape (...)
        The exponents.

    Examples
    --------
    >>> i, m, a, b = normalise(np.array([3.0, 4.0, 6.0]), np.array([0.0, 48.0, 0.0]))
    >>> i.tolist(), m.tolist(), int(a), int(b)
    ([0.375, 0.5, 0.75], [0.0, 0.75, 0.0], 3, 6)
    """
    _, a = np.frexp(np.max(moments, axis=-1))
    big = np.max(np.abs(m0), axis=-1)
    _, b = np.frexp(np.where(big > 0, big, 1.0))
    return np.ldexp(moments, -a[..., None]), np.ldexp(m0, -b[..., None]), a, b


def _sorted_axes(moments):
    """Indices of the axes of minimum, middle and maximum moment (stable for ties)."""
    order = np.argsort(moments, axis=-1, kind="stable")
    return order[..., 0], order[..., 1], order[..., 2]


def _separatrix_sign(moments, m0):
    """Sign of ``P₂ = G²/B − D`` in double-double (``+1`` SAM, ``−1`` LAM, ``0`` separatrix)."""
    ia, ib, ic = _sorted_axes(moments)
    take = lambda a, i: np.take_along_axis(a, i[..., None], axis=-1)[..., 0]  # noqa: E731
    A, B, C = take(moments, ia), take(moments, ib), take(moments, ic)
    ma, mc = take(m0, ia), take(m0, ic)
    # m_C² (C − B)/(B C) − m_A² (B − A)/(A B), times A B C > 0: same sign.
    t1 = dd_mul(*two_prod(mc, mc), *dd_mul(*two_sum(C, -B), A, 0.0))
    t2 = dd_mul(*two_prod(ma, ma), *dd_mul(*two_sum(B, -A), C, 0.0))
    hi, _ = dd_add(*t1, -t2[0], -t2[1])
    return np.sign(hi)


def classify(moments, m0):
    """Regime of the torque-free motion of each body and state.

    Parameters
    ----------
    moments : array_like, shape (..., 3)
        Principal moments (any order, positive).
    m0 : array_like, shape (..., 3)
        Body-frame angular momentum.

    Returns
    -------
    ndarray of int, shape (...)
        :class:`Regime` codes.  Exact equalities decide: two equal moments make a body
        axisymmetric, and the separatrix is ``2T = G²/B`` for the floating-point inputs as
        given (evaluated in double-double arithmetic).

    Examples
    --------
    >>> moments = [1.0, 2.0, 3.0]
    >>> [Regime(int(r)).name for r in classify(moments, [[0.1, 0.2, 1.0], [1.0, 0.2, 0.1],
    ...                                              [0.0, 1.0, 0.0]])]
    ['SAM', 'LAM', 'SEPARATRIX']
    >>> Regime(int(classify([2.0, 2.0, 3.0], [0.3, 0.0, 1.0]))).name
    'AXISYMMETRIC'
    """
    moments, m0 = check_inputs(moments, m0)
    moments, m0, _, _ = normalise(moments, m0)
    return classify_scaled(moments, m0)


def classify_scaled(moments, m0):
    """:func:`classify` for validated states already scaled by :func:`normalise`.

    Parameters
    ----------
    moments, m0 : ndarray, shape (..., 3)
        Output of :func:`normalise`.

    Returns
    -------
    ndarray of int8, shape (...)
        :class:`Regime` codes.

    Examples
    --------
    >>> Regime(int(classify_scaled(np.array([0.375, 0.5, 0.75]), np.array([0.0, 0.75, 0.0])))).name
    'SEPARATRIX'
    """
    s = np.sort(moments, axis=-1)
    sign = _separatrix_sign(moments, m0)
    regime = np.where(sign > 0, Regime.SAM, np.where(sign < 0, Regime.LAM, Regime.SEPARATRIX))
    axisymmetric = (s[..., 0] == s[..., 1]) | (s[..., 1] == s[..., 2])
    regime = np.where(axisymmetric, Regime.AXISYMMETRIC, regime)
    regime = np.where(s[..., 0] == s[..., 2], Regime.SPHERE, regime)
    regime = np.where(np.all(m0 == 0, axis=-1), Regime.REST, regime)
    return regime.astype(np.int8)


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


def _inv_diff(s, Ii, Ij):
    """``s (1/Iᵢ − 1/Iⱼ) = s (Iⱼ − Iᵢ)/(Iᵢ Iⱼ)`` as a double-double."""
    dh, dl = two_sum(Ij, -Ii)
    ph, pl = two_prod(Ii, Ij)
    return dd_div(s * dh, s * dl, ph, pl)


def polhode_frame(moments, m0, lam):
    """Working frame and double-double invariants of triaxial states.

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
    ia, ib, ic = _sorted_axes(moments)
    p3 = np.where(lam, ia, ic)
    p1 = np.where(lam, ic, ia)
    perm = np.stack([p1, ib, p3], axis=-1)
    parity = _permutation_parity(perm)
    m3 = np.take_along_axis(m0, p3[:, None], axis=-1)[:, 0]
    s3 = np.where(m3 < 0, -1.0, 1.0)
    sign = np.stack([np.ones_like(s3), parity * s3, s3], axis=-1)
    Iw = np.take_along_axis(moments, perm, axis=-1)
    mw = np.take_along_axis(m0, perm, axis=-1) * sign
    s = np.where(lam, -1.0, 1.0)
    I1, I2, I3 = Iw[:, 0], Iw[:, 1], Iw[:, 2]
    e12 = _inv_diff(s, I1, I2)
    e13 = _inv_diff(s, I1, I3)
    e23 = _inv_diff(s, I2, I3)
    sq = [two_prod(mw[:, i], mw[:, i]) for i in range(3)]
    P1 = dd_add(*dd_mul(*sq[0], *e13), *dd_mul(*sq[1], *e23))
    P3 = dd_add(*dd_mul(*sq[1], *e12), *dd_mul(*sq[2], *e13))
    t = dd_mul(*sq[0], *e12)
    P2 = dd_add(*dd_mul(*sq[2], *e23), -t[0], -t[1])
    G2 = dd_add(*dd_add(*sq[0], *sq[1]), *sq[2])
    G = dd_sqrt(*G2)
    w3 = dd_div(1.0, 0.0, I3, 0.0)
    return PolhodeFrame(perm, sign, s, Iw, mw, e12, e13, e23, P1, P2, P3, G, w3)


def _permutation_parity(perm):
    """``+1`` for even, ``−1`` for odd permutations of (0, 1, 2), row by row."""
    a, b, c = perm[:, 0], perm[:, 1], perm[:, 2]
    inversions = (a > b).astype(int) + (a > c) + (b > c)
    return 1.0 - 2.0 * (inversions % 2)


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


def attitude_anchor(frame: PolhodeFrame, cols, q0):
    """Constant quaternions ``U = Q₀ ⊗ P`` and ``V = Q₀ ⊗ e_z ⊗ P`` of the attitude.

    The attitude is ``rot(t) = Q₀ ⊗ R_z(Δψ) ⊗ S(m_w(t)) ⊗ P`` with ``P`` the working frame
    (body → working), ``S`` the shortest arc taking ``m_w`` to ``+z`` and
    ``Q₀ = q₀ ⊗ P* ⊗ S(m_w(0))*``; writing ``R_z(Δψ) = cos(Δψ/2) + sin(Δψ/2) e_z`` and
    moving ``P`` through ``S`` gives
    ``rot(t) = (cos(Δψ/2) U + sin(Δψ/2) V) ⊗ (P* ⊗ S ⊗ P)``.

    Parameters
    ----------
    frame : PolhodeFrame
    cols : ndarray, shape (3, 3, N)
        From :func:`working_axes`.
    q0 : ndarray, shape (N, 4)
        Initial attitudes (unit quaternions, scalar last, body → reference).

    Returns
    -------
    U, V : ndarray, shape (4, N)

    Examples
    --------
    >>> fr = polhode_frame(np.array([[1.0, 2.0, 3.0]]), np.array([[0.0, 0.0, 1.0]]),
    ...                    np.array([False]))
    >>> U, V = attitude_anchor(fr, working_axes(fr), np.array([[0.0, 0.0, 0.0, 1.0]]))
    >>> U[:, 0].tolist(), V[:, 0].tolist()
    ([0.0, 0.0, 0.0, 1.0], [0.0, 0.0, 1.0, 0.0])
    """
    pq = matrix_quat(cols)
    arc = shortest_arc(frame.mw).T
    q_0 = product(*product(*q0.T, -pq[0], -pq[1], -pq[2], pq[3]), -arc[0], -arc[1], -arc[2], arc[3])
    return np.stack(product(*q_0, *pq)), np.stack(product(*product(*q_0, 0.0, 0.0, 1.0, 0.0), *pq))
