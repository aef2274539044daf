r"""The polhode-centred working frame of triaxial states and the power-of-two scaling.

The regime vocabulary and its one classification live in :mod:`andoyer.regime` (below the
body, which uses them too); :class:`Regime`, :func:`classify` and :func:`check_inputs` are
re-exported here, where they were first defined.

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

give every constant of the solution (:mod:`andoyer.free.triaxial`).  Each formula of the frame
is one kernel of :mod:`andoyer.free.kernels.frame`, run here on arrays and by the compiled
set-up on floats.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from andoyer._jit import exponent, jitable, select
from andoyer.free.kernels import frame as kf
from andoyer.regime import Regime, check_inputs, classify, regime_codes

__all__ = [
    "PolhodeFrame",
    "Regime",
    "attitude_anchor",
    "check_inputs",
    "classify",
    "classify_scaled",
    "normalise",
    "polhode_frame",
    "scale_exponents",
    "working_axes",
]


@jitable
def scale_exponents(i1, i2, i3, m1, m2, m3):
    """Exponents ``a, b`` that scale a state into ``[1/2, 1)``: ``max Iᵢ = 2^a f``, ``max |mᵢ| = 2^b g``.

    ``f, g ∈ [1/2, 1)``; a zero momentum gives ``b = 1`` (the exponent of 1).  The motion
    is covariant under ``I = 2^a I'``, ``m = 2^b m'`` (:func:`normalise`),
    and the regime does not change.  A kernel written once: floats (compiled or not) or
    arrays broadcast together.

    Parameters
    ----------
    i1, i2, i3 : float or ndarray, shape (...)
        Principal moments (positive, finite).
    m1, m2, m3 : float or ndarray, shape (...)
        Body angular momentum (finite).

    Returns
    -------
    a, b : int or ndarray of int, shape (...)
        The exponents.

    Examples
    --------
    >>> a, b = scale_exponents(3.0, 4.0, 6.0, 0.0, 48.0, 0.0)
    >>> int(a), int(b)
    (3, 6)
    """
    big_i = np.maximum(np.maximum(i1, i2), i3)
    big_m = np.maximum(np.maximum(np.abs(m1), np.abs(m2)), np.abs(m3))
    return exponent(big_i), exponent(select(big_m > 0, big_m, 1.0))


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
    a, b = scale_exponents(*(moments[..., k] for k in range(3)), *(m0[..., k] for k in range(3)))
    a, b = np.broadcast_to(a, moments.shape[:-1]), np.broadcast_to(b, m0.shape[:-1])
    return np.ldexp(moments, -a[..., None]), np.ldexp(m0, -b[..., None]), a, b


def classify_scaled(moments, m0):
    """:func:`andoyer.regime.classify` for validated states, without the checks.

    The states need not be scaled any more (:func:`andoyer.regime.regime_code` scales each
    state itself); the name stays for the callers of :func:`normalise` that used it.

    Parameters
    ----------
    moments, m0 : ndarray, shape (..., 3)
        Validated moments and momenta, e.g. the output of :func:`normalise`.

    Returns
    -------
    ndarray of int8, shape (...)
        :class:`Regime` codes.

    Examples
    --------
    >>> Regime(int(classify_scaled(np.array([0.375, 0.5, 0.75]), np.array([0.0, 0.75, 0.0])))).name
    'SEPARATRIX'
    """
    return regime_codes(moments, m0)


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

    The kernels of :mod:`andoyer.free.kernels.frame` on arrays (the compiled set-up runs the
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
    :func:`andoyer.free.kernels.frame.permutation_quaternion` and
    :func:`andoyer.free.kernels.frame.anchor` on arrays (the compiled set-up runs them on floats).

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
