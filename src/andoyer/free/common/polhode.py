r"""The polhode-centred working frame, its invariants and the attitude anchor: one kernel each.

Conventions of :mod:`andoyer.free.common.polhode_numpy`: working axis ``j`` is ``σⱼ b_{pⱼ}``
(body axis ``pⱼ``, sign ``σⱼ``, ``σ₁ = +1``, a proper rotation ``P``, ``m_w = P m_body``), axis 3 the
polhode axis (``C`` for SAM and the separatrix, ``A`` for LAM), axis 2 the middle one, and
``m₃ ≥ 0``; ``s = +1`` SAM, ``−1`` LAM; ``e_{ij} = s(1/I_i − 1/I_j)``, ``P₁, P₂, P₃`` the
invariants, ``G = |m|``, ``w₃ = 1/I₃``; double-doubles are ``(hi, lo)`` tuples.

Each kernel is plain arithmetic with :func:`andoyer._jit.select` for its branches (axis indices
are integers, chosen by ``select`` too), registered with :func:`andoyer._jit.jitable`: the
compiled drivers (:mod:`andoyer.free.triaxial.setup_compiled`,
:mod:`andoyer.free.triaxial.evaluate_compiled`, :mod:`andoyer.free.common.polhode_compiled`) and
the scalar step (:mod:`andoyer.free.step_scalar`) inline them on floats, the numpy driver
(:mod:`andoyer.free.common.polhode_numpy`) calls them on arrays.  The double-double operations
are :mod:`andoyer.special.compensated` (error-free products by fused multiply-add compiled, by
Dekker's splitting on arrays: the same exact values), so the two ways give the same bits.
"""

from __future__ import annotations

import numpy as np

from andoyer._jit import jitable, select
from andoyer._quaternion import product
from andoyer.special.compensated import dd_add, dd_div, dd_mul, dd_sqrt, two_prod, two_sum

__all__ = [
    "anchor",
    "component",
    "invariants",
    "inverse_difference",
    "permutation_quaternion",
    "polhode_axes",
    "shortest_arc",
    "sorted_axes",
    "steady_spin_limit",
]

# the one Hamilton product, compiled inline into the kernels below
jitable(product)


@jitable
def sorted_axes(i1, i2, i3):
    """Indices ``(a, b, c)`` of the axes of minimum, middle and maximum moment (stable for ties).

    Three compare-and-swap steps, each swapping on a strict ``<`` only, so equal moments keep
    their order (as :func:`numpy.argsort` with ``kind="stable"``).

    Parameters
    ----------
    i1, i2, i3 : float or ndarray, shape (...)
        Moments along body axes 0, 1, 2.

    Returns
    -------
    a, b, c : int or ndarray of int, shape (...)

    Examples
    --------
    >>> sorted_axes(3.0, 1.0, 2.0), sorted_axes(2.0, 1.0, 1.0)
    ((1, 2, 0), (1, 2, 0))
    """
    v0, v1, v2 = i1, i2, i3
    o0, o1, o2 = 0, 1, 2
    c = v1 < v0
    v0, v1, o0, o1 = select(c, v1, v0), select(c, v0, v1), select(c, o1, o0), select(c, o0, o1)
    c = v2 < v1
    v1, o1, o2 = select(c, v2, v1), select(c, o2, o1), select(c, o1, o2)
    c = v1 < v0  # (false when the second step did not swap)
    return select(c, o1, o0), select(c, o0, o1), o2


@jitable
def component(x0, x1, x2, k):
    """Component ``k`` (0, 1 or 2) of ``(x₀, x₁, x₂)``.

    Parameters
    ----------
    x0, x1, x2 : float or ndarray, shape (...)
    k : int or ndarray of int, shape (...)

    Returns
    -------
    float or ndarray, shape (...)

    Examples
    --------
    >>> component(5.0, 6.0, 7.0, 2)
    7.0
    """
    return select(k == 0, x0, select(k == 1, x1, x2))


@jitable
def polhode_axes(a, b, c, lam, m1, m2, m3):
    """Body axes ``p₁, p₂, p₃`` and signs ``σ₂, σ₃`` of the working frame.

    ``p₃`` is the polhode axis (``c``, the axis of maximum moment, or ``a`` for LAM), ``p₂ = b``,
    ``σ₃ = sign(m_{p₃})`` (``+1`` for zero) and ``σ₂ = ±σ₃`` makes the frame proper: ``+σ₃``
    when ``(p₁, p₂, p₃)`` is a cyclic shift of ``(0, 1, 2)``.

    Parameters
    ----------
    a, b, c : int or ndarray of int, shape (...)
        From :func:`sorted_axes`.
    lam : bool or ndarray of bool, shape (...)
        True for LAM states (polhode around ``A``).
    m1, m2, m3 : float or ndarray, shape (...)
        Body angular momentum.

    Returns
    -------
    p1, p2, p3 : int or ndarray of int, shape (...)
    sigma2, sigma3 : float or ndarray, shape (...)

    Examples
    --------
    >>> polhode_axes(1, 2, 0, False, 1.0, 0.1, -0.2)
    (1, 2, 0, 1.0, 1.0)
    """
    p1, p3 = select(lam, c, a), select(lam, a, c)
    parity = select((b - p1) % 3 == 1, 1.0, -1.0)
    sigma3 = select(component(m1, m2, m3, p3) < 0.0, -1.0, 1.0)
    return p1, b, p3, parity * sigma3, sigma3


@jitable
def inverse_difference(s, Ii, Ij):
    """``s (1/Iᵢ − 1/Iⱼ) = s (Iⱼ − Iᵢ)/(Iᵢ Iⱼ)`` as a double-double.

    Parameters
    ----------
    s, Ii, Ij : float or ndarray, shape (...)

    Returns
    -------
    hi, lo : float or ndarray, shape (...)

    Examples
    --------
    >>> [float(x) for x in inverse_difference(1.0, 2.0, 4.0)]
    [0.25, 0.0]
    """
    dh, dl = two_sum(Ij, -Ii)
    ph, pl = two_prod(Ii, Ij)
    return dd_div(s * dh, s * dl, ph, pl)


@jitable
def invariants(s, I1, I2, I3, m1, m2, m3):
    r"""The double-double invariants of a state in the working frame.

    .. math::
       P_1 = m_1^2 e_{13} + m_2^2 e_{23},\quad P_3 = m_2^2 e_{12} + m_3^2 e_{13},\quad
       P_2 = m_3^2 e_{23} - m_1^2 e_{12},\quad G = \sqrt{m_1^2 + m_2^2 + m_3^2},\quad w_3 = 1/I_3.

    Parameters
    ----------
    s : float or ndarray, shape (...)
        ``±1``.
    I1, I2, I3, m1, m2, m3 : float or ndarray, shape (...)
        Moments and momentum in the working frame.

    Returns
    -------
    e12, e13, e23, P1, P2, P3, G, w3 : tuple
        Double-doubles.

    Examples
    --------
    >>> inv = invariants(1.0, 1.0, 2.0, 4.0, 0.0, 0.0, 1.0)  # a pure spin about C: P₁ = 0
    >>> [float(x[0]) for x in inv]
    [0.5, 0.75, 0.25, 0.0, 0.25, 0.75, 1.0, 0.25]
    """
    e12 = inverse_difference(s, I1, I2)
    e13 = inverse_difference(s, I1, I3)
    e23 = inverse_difference(s, I2, I3)
    x1h, x1l = two_prod(m1, m1)
    x2h, x2l = two_prod(m2, m2)
    x3h, x3l = two_prod(m3, m3)
    P1 = dd_add(*dd_mul(x1h, x1l, e13[0], e13[1]), *dd_mul(x2h, x2l, e23[0], e23[1]))
    P3 = dd_add(*dd_mul(x2h, x2l, e12[0], e12[1]), *dd_mul(x3h, x3l, e13[0], e13[1]))
    th, tl = dd_mul(x1h, x1l, e12[0], e12[1])
    P2 = dd_add(*dd_mul(x3h, x3l, e23[0], e23[1]), -th, -tl)
    G = dd_sqrt(*dd_add(*dd_add(x1h, x1l, x2h, x2l), x3h, x3l))
    w3 = dd_div(1.0, 0.0, I3, 0.0)
    return e12, e13, e23, P1, P2, P3, G, w3


@jitable
def _entry(p, sigma, k):
    """Entry ``k`` of the row ``σ e_p`` of the frame's matrix."""
    return select(p == k, sigma, 0.0)


@jitable
def permutation_quaternion(p1, p2, p3, sigma2, sigma3):
    """Unit quaternion of the working frame ``P`` (rows ``σⱼ e_{pⱼ}``), by Shepperd's pivot.

    The pivot is the trace when it is at least every diagonal entry, else the first largest
    diagonal entry; exact rotation matrices give the quaternion exactly up to the rounding
    of the normalisation (the sign is the pivot's).

    Parameters
    ----------
    p1, p2, p3 : int or ndarray of int, shape (...)
    sigma2, sigma3 : float or ndarray, shape (...)
        From :func:`polhode_axes` (``σ₁ = +1``).

    Returns
    -------
    x, y, z, w : float or ndarray, shape (...)
        Scalar last: ``P`` maps body to working components.

    Examples
    --------
    >>> [round(float(x), 12) for x in permutation_quaternion(1, 2, 0, 1.0, 1.0)]  # (x, y, z) → (y, z, x)
    [-0.5, -0.5, -0.5, 0.5]
    """
    m00, m01, m02 = _entry(p1, 1.0, 0), _entry(p1, 1.0, 1), _entry(p1, 1.0, 2)
    m10, m11, m12 = _entry(p2, sigma2, 0), _entry(p2, sigma2, 1), _entry(p2, sigma2, 2)
    m20, m21, m22 = _entry(p3, sigma3, 0), _entry(p3, sigma3, 1), _entry(p3, sigma3, 2)
    tr = m00 + m11 + m22
    big = select(m11 > m00, m11, m00)
    big = select(m22 > big, m22, big)
    on_trace = tr >= big
    first = m00 == big
    second = (m11 == big) & (m00 != big)
    # the four candidates 4 q_pivot q (Shepperd), all cheap: chosen by select
    x = select(
        on_trace,
        m21 - m12,
        select(first, 1.0 - tr + 2.0 * big, select(second, m01 + m10, m02 + m20)),
    )
    y = select(
        on_trace,
        m02 - m20,
        select(first, m10 + m01, select(second, 1.0 - tr + 2.0 * big, m12 + m21)),
    )
    z = select(
        on_trace,
        m10 - m01,
        select(first, m20 + m02, select(second, m21 + m12, 1.0 - tr + 2.0 * big)),
    )
    w = select(on_trace, 1.0 + tr, select(first, m21 - m12, select(second, m02 - m20, m10 - m01)))
    r = 1.0 / np.sqrt(x * x + y * y + z * z + w * w)
    return x * r, y * r, z * r, w * r


@jitable
def shortest_arc(m1, m2, m3, g):
    """Rotation taking the direction of ``m`` to ``+z`` by the shortest arc.

    ``S(m) = (m₂, −m₁, 0, G + m₃)/√(2G(G + m₃))``: the rotation about ``m × z`` by the angle
    between them; regular wherever ``m`` is not along ``−z``.

    Parameters
    ----------
    m1, m2, m3, g : float or ndarray, shape (...)
        The vector and its norm ``G`` (``m₃ > −G``).

    Returns
    -------
    x, y, z, w : float or ndarray, shape (...)
        Scalar last.

    Examples
    --------
    >>> [round(float(x), 12) for x in shortest_arc(1.0, 2.0, 2.0, 3.0)]
    [0.36514837167, -0.182574185835, 0.0, 0.912870929175]
    """
    w = g + m3
    nrm = np.sqrt(2.0 * g * w)
    return m2 / nrm, -m1 / nrm, 0.0, w / nrm


@jitable
def anchor(q0x, q0y, q0z, q0w, pq, m1, m2, m3, g):
    """Constant quaternions ``U = Q₀ ⊗ P`` and ``V = Q₀ ⊗ e_z ⊗ P`` of the attitude.

    ``Q₀ = q₀ ⊗ P* ⊗ S(m_w)*`` with ``S`` the :func:`shortest_arc` taking ``m_w`` to ``+z``
    (:func:`andoyer.free.common.polhode_numpy.attitude_anchor`).

    Parameters
    ----------
    q0x, q0y, q0z, q0w : float or ndarray, shape (...)
        Initial attitude (unit, scalar last, body → reference).
    pq : tuple of 4
        :func:`permutation_quaternion`.
    m1, m2, m3, g : float or ndarray, shape (...)
        Momentum in the working frame (``m₃ ≥ 0``) and its norm.

    Returns
    -------
    U, V : tuple of 4

    Examples
    --------
    >>> u, v = anchor(0.0, 0.0, 0.0, 1.0, (0.0, 0.0, 0.0, 1.0), 0.0, 0.0, 1.0, 1.0)
    >>> [float(x) for x in u], [float(x) for x in v]
    ([0.0, 0.0, 0.0, 1.0], [0.0, 0.0, 1.0, 0.0])
    """
    sx, sy, sz, sw = shortest_arc(m1, m2, m3, g)
    q_rw = product(q0x, q0y, q0z, q0w, -pq[0], -pq[1], -pq[2], pq[3])
    q_0 = product(q_rw[0], q_rw[1], q_rw[2], q_rw[3], -sx, -sy, sz, sw)  # S* (its z is 0)
    u = product(q_0[0], q_0[1], q_0[2], q_0[3], pq[0], pq[1], pq[2], pq[3])
    z = product(q_0[0], q_0[1], q_0[2], q_0[3], 0.0, 0.0, 1.0, 0.0)
    return u, product(z[0], z[1], z[2], z[3], pq[0], pq[1], pq[2], pq[3])


@jitable
def attitude(cz, sz, u, v, va, vb, sn, cn, m3, G):
    r"""Attitude ``(U cos + V sin)(Δψ/2) ⊗ (v, G + m₃)/√(2G(G + m₃))``, ``v = v_a sn + v_b cn``.

    The per-epoch end of the anchored attitude (:func:`anchor` builds ``U``, ``V``): the
    constant quaternions turned by the half angle, times the body-frame shortest arc from the
    momentum to ``+z``.

    Parameters
    ----------
    cz, sz : float or ndarray, shape (...)
        ``cos``, ``sin`` of ``Δψ/2`` (:func:`half_angle`).
    u, v : indexable of 4 float or ndarray, shape (...)
        The anchor quaternions ``U``, ``V``.
    va, vb : indexable of 3 float or ndarray, shape (...)
        Constant body vectors of the arc.
    sn, cn, m3 : float or ndarray, shape (...)
        Their per-epoch factors and the polhode-axis component of the momentum.
    G : float or ndarray, shape (...)
        ``|m|``.

    Returns
    -------
    tuple of 4 float or ndarray, shape (...)
        Quaternion components ``(x, y, z, w)``.

    Examples
    --------
    >>> one, k = (0.0, 0.0, 0.0, 1.0), (0.0, 0.0, 1.0, 0.0)
    >>> e = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0))
    >>> [float(c) for c in attitude(1.0, 0.0, one, k, *e, 0.0, 0.0, 1.0, 1.0)]  # m = G ẑ: no arc
    [0.0, 0.0, 0.0, 1.0]
    """
    # augmented assignments only to values made here (in place on arrays)
    a0, a1, a2, a3 = u[0] * cz, u[1] * cz, u[2] * cz, u[3] * cz
    a0 += v[0] * sz
    a1 += v[1] * sz
    a2 += v[2] * sz
    a3 += v[3] * sz
    w = m3 + G
    inv = 1.0 / np.sqrt((2.0 * G) * w)
    xa, xb = sn * inv, cn * inv
    b0, b1, b2 = va[0] * xa, va[1] * xa, va[2] * xa
    b0 += vb[0] * xb
    b1 += vb[1] * xb
    b2 += vb[2] * xb
    w *= inv
    return product(a0, a1, a2, a3, b0, b1, b2, w)


@jitable
def steady_spin_limit(s, e13, e23, G, w3):
    """Period and precession rate of a steady spin about the polhode axis: the limit of nearby polhodes.

    ``ω = G √(e₁₃ e₂₃)``, period ``2π/ω`` and rate ``G w₃ + s ω``, from the working frame's
    invariants (:func:`invariants`, high words).

    Parameters
    ----------
    s, e13, e23, G, w3 : float or ndarray, shape (...)
        ``s = ±1`` (SAM, LAM) and the invariants.

    Returns
    -------
    period, rate : float or ndarray, shape (...)

    Examples
    --------
    >>> period, rate = steady_spin_limit(1.0, 0.75, 0.25, 1.0, 0.25)  # ω = √(3/4 · 1/4)
    >>> round(float(period), 12), round(float(rate), 12)
    (14.510394913874, 0.683012701892)
    """
    om = G * np.sqrt(e13 * e23)
    return 2.0 * np.pi / om, G * w3 + s * om
