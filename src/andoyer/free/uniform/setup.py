r"""The set-up formulas of the uniform motions (precession, spheres, steady spins, rest), written once.

For an axisymmetric body (symmetry axis ``ŝ`` with moment ``I_s``, transverse moment
``I_t``) the motion is

.. math::
   \mathrm{rot}(t) = R_{\hat m_{ref}}(\Omega t)\;\mathrm{rot}_0\;R_{\hat s}(\lambda t),\qquad
   m(t) = R_{\hat s}(-\lambda t)\, m_0,\qquad
   \frac{\Omega}{2\pi} = \frac{G}{2\pi I_t},\quad
   \frac{\lambda}{2\pi} = \frac{m_s (I_t - I_s)}{2\pi I_s I_t},

and, with ``I_t = I_s`` (so ``λ = 0``), that of a sphere, of a steady spin about a principal
axis and of a body at rest (:mod:`andoyer.free.uniform` derives it).  Each formula below is
one function of arithmetic only: the branches are :func:`andoyer._jit.select`, the
double-double is :mod:`andoyer.special.compensated`, the quaternion product and the rotation
of a vector are :func:`andoyer._quaternion.product` and :func:`~andoyer._quaternion.apply`.
So the same text runs on floats inside numba kernels (registered with
:func:`andoyer._jit.jitable`: the compiled loop of :mod:`andoyer.free.uniform.setup_compiled`
and :mod:`andoyer.free.step_scalar` inline them) and on whole numpy arrays, one array per
component (:mod:`andoyer.free.uniform.setup_numpy`); both give the same bits
(``tests/free/uniform/test_free_uniform_kernels.py``).

Vectors and quaternions are passed as anything indexed by component: a 3- or 4-tuple, a
row of a table, or an array whose first axis holds the components.
"""

from __future__ import annotations

import numpy as np

from andoyer._jit import jitable, select
from andoyer._quaternion import apply, product
from andoyer.special.compensated import PI_DD, dd_add, dd_div, dd_mul, dd_sqrt, two_prod, two_sum

__all__ = ["axes", "component", "decomposition", "frequencies", "quaternions"]

# the one Hamilton product and rotation, compiled inline into the kernels below
jitable(product)
jitable(apply)

_TWO_PI_HI, _TWO_PI_LO = 2.0 * PI_DD[0], 2.0 * PI_DD[1]


@jitable
def component(v, k):
    """The component ``v[k]`` of a 3-vector, ``k`` an integer (array) chosen per state.

    Parameters
    ----------
    v : indexable of 3 float or ndarray, shape (N,)
        The components.
    k : int or ndarray of int, shape (N,)
        Which one, 0, 1 or 2.

    Returns
    -------
    float or ndarray, shape (N,)

    Examples
    --------
    >>> component(np.array([[1.0, 2.0], [3.0, 4.0], [5.0, 6.0]]), np.array([2, 0])).tolist()
    [5.0, 2.0]
    """
    return select(k == 0, v[0], select(k == 1, v[1], v[2]))


@jitable
def axes(I, m, axisymmetric):
    """The body axis ``ŝ`` of the motion and its axial and transverse moments ``I_s``, ``I_t``.

    An axisymmetric state turns about the axis of its distinct moment, ``I_t`` the repeated
    one; any other (a steady spin, also of a triaxial body or with a wobble so small that
    its square underflows, a sphere, rest) about its largest momentum component (the first
    of equals), with ``I_t = I_s`` so that ``λ = 0``.

    Parameters
    ----------
    I, m : indexable of 3 float or ndarray, shape (N,)
        Principal moments and body angular momentum.
    axisymmetric : bool or ndarray of bool, shape (N,)
        Whether exactly two moments are equal (:data:`andoyer.regime.Regime.AXISYMMETRIC`).

    Returns
    -------
    k : int or ndarray of int, shape (N,)
        The axis ``ŝ``.
    I_s, I_t : float or ndarray, shape (N,)

    Examples
    --------
    >>> [float(v) for v in axes((2.0, 3.0, 2.0), (0.1, 1.0, 0.2), True)]  # ŝ = y, I_s = 3, I_t = 2
    [1.0, 3.0, 2.0]
    >>> [float(v) for v in axes((1.0, 2.0, 3.0), (0.0, 0.0, -2.0), False)]  # a steady spin about z
    [2.0, 3.0, 3.0]
    """
    distinct = select(I[0] == I[1], 2, select(I[0] == I[2], 1, 0))
    transverse = select(I[0] == I[2], I[0], I[1])  # the repeated moment
    a0, a1, a2 = abs(m[0]), abs(m[1]), abs(m[2])
    largest = select(a2 > select(a1 > a0, a1, a0), 2, select(a1 > a0, 1, 0))
    k = select(axisymmetric, distinct, largest)
    I_s = component(I, k)
    return k, I_s, select(axisymmetric, transverse, I_s)


@jitable
def frequencies(m, m_s, I_s, I_t):
    """``G``, ``Ω/2π = G/(2π I_t)`` and ``λ/2π = m_s (I_t − I_s)/(2π I_s I_t)`` in double-double.

    ``G²`` is the double-double sum of exact squares, ``I_t − I_s`` an exact difference.

    Parameters
    ----------
    m : indexable of 3 float or ndarray, shape (N,)
        Body angular momentum.
    m_s, I_s, I_t : float or ndarray, shape (N,)
        Its component on the axis ``ŝ`` and the moments of :func:`axes`.

    Returns
    -------
    G : float or ndarray, shape (N,)
        ``|m|`` (the high part).
    spin_hi, spin_lo, body_hi, body_lo : float or ndarray, shape (N,)
        ``Ω/2π`` and ``λ/2π``, cycles per unit time.
    period, rate : float or ndarray, shape (N,)
        ``2π/|λ|`` (``inf`` where ``λ = 0``) and ``Ω``.

    Examples
    --------
    >>> G, sh, sl, bh, bl, period, rate = frequencies((0.5, 0.0, 1.0), 1.0, 3.0, 2.0)
    >>> round(float(period), 12), round(float(rate), 12)  # λ = 1/6, Ω = √1.25/2
    (37.699111843078, 0.559016994375)
    """
    a0, a1 = two_prod(m[0], m[0])
    b0, b1 = two_prod(m[1], m[1])
    c0, c1 = two_prod(m[2], m[2])
    gh, gl = dd_add(a0, a1, b0, b1)
    gh, gl = dd_add(gh, gl, c0, c1)
    gh, gl = dd_sqrt(gh, gl)
    dh, dl = dd_mul(I_t, 0.0, _TWO_PI_HI, _TWO_PI_LO)
    sh, sl = dd_div(gh, gl, dh, dl)
    xh, xl = two_sum(I_t, -I_s)
    xh, xl = dd_mul(xh, xl, m_s, 0.0)
    ph, pl = two_prod(I_s, I_t)
    lh, ll = dd_div(xh, xl, ph, pl)
    lh, ll = dd_div(lh, ll, _TWO_PI_HI, _TWO_PI_LO)
    turning = lh != 0.0
    period = select(turning, abs(1.0 / select(turning, lh, 1.0)), np.inf)
    return gh, sh, sl, lh, ll, period, _TWO_PI_HI * sh


@jitable
def decomposition(m, k, m_s):
    """``m_par = ŝ(ŝ·m₀)``, ``m_perp = m₀ − m_par`` and ``m_cross = ŝ × m₀`` for ``ŝ`` the unit axis ``k``.

    Parameters
    ----------
    m : indexable of 3 float or ndarray, shape (N,)
        Body angular momentum ``m₀``.
    k : int or ndarray of int, shape (N,)
        The axis ``ŝ``.
    m_s : float or ndarray, shape (N,)
        ``m[k]``.

    Returns
    -------
    m_par, m_perp, m_cross : tuple of 3 float or ndarray, shape (N,)

    Examples
    --------
    >>> [[float(c) for c in v] for v in decomposition((1.0, 2.0, 3.0), 2, 3.0)]
    [[0.0, 0.0, 3.0], [1.0, 2.0, 0.0], [-2.0, 1.0, 0.0]]
    """
    p0, p1, p2 = select(k == 0, m_s, 0.0), select(k == 1, m_s, 0.0), select(k == 2, m_s, 0.0)
    cross = (
        select(k == 1, m[2], select(k == 2, -m[1], 0.0)),
        select(k == 2, m[0], select(k == 0, -m[2], 0.0)),
        select(k == 0, m[1], select(k == 1, -m[0], 0.0)),
    )
    return (p0, p1, p2), (m[0] - p0, m[1] - p1, m[2] - p2), cross


@jitable
def quaternions(q0, m, k, G):
    """``q₂ = q₀ ⊗ ŝ``, ``q₃ = m̂ ⊗ q₀`` and ``q₄ = m̂ ⊗ q₀ ⊗ ŝ``, with ``m̂ = R(q₀) m₀/G``.

    ``q(t) = cos α cos β q₀ + cos α sin β q₂ + sin α cos β q₃ + sin α sin β q₄`` is then
    ``R_m̂(2α) q₀ R_ŝ(2β)`` (:func:`attitude`); ``m̂ = 0`` at rest.

    Parameters
    ----------
    q0 : indexable of 4 float or ndarray, shape (N,)
        Initial attitude (unit quaternion, scalar last).
    m : indexable of 3 float or ndarray, shape (N,)
        Body angular momentum.
    k : int or ndarray of int, shape (N,)
        The axis ``ŝ``.
    G : float or ndarray, shape (N,)
        ``|m|`` (:func:`frequencies`).

    Returns
    -------
    q2, q3, q4 : tuple of 4 float or ndarray, shape (N,)

    Examples
    --------
    >>> q = quaternions((0.0, 0.0, 0.0, 1.0), (0.0, 0.0, 2.0), 2, 2.0)
    >>> [[float(c) for c in v] for v in q]  # ŝ = m̂ = z: q₂ = q₃ = k, q₄ = k² = −1
    [[0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, -1.0]]
    """
    r = apply(q0[0], q0[1], q0[2], q0[3], m[0], m[1], m[2])
    moving = G > 0.0
    g = select(moving, G, 1.0)
    r0, r1, r2 = select(moving, r[0] / g, 0.0), select(moving, r[1] / g, 0.0), select(moving, r[2] / g, 0.0)
    s0, s1, s2 = select(k == 0, 1.0, 0.0), select(k == 1, 1.0, 0.0), select(k == 2, 1.0, 0.0)
    q2 = product(q0[0], q0[1], q0[2], q0[3], s0, s1, s2, 0.0)
    q3 = product(r0, r1, r2, 0.0, q0[0], q0[1], q0[2], q0[3])
    q4 = product(r0, r1, r2, 0.0, q2[0], q2[1], q2[2], q2[3])
    return q2, q3, q4


