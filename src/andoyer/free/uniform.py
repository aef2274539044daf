r"""Torque-free motion without elliptic functions: regular precession and steady spin.

For an axisymmetric body (symmetry axis ``ŝ`` with moment ``I_s``, transverse moment
``I_t``), the body angular velocity ``ω = w_t m + (w_s − w_t) m_s ŝ`` splits into a
uniform rotation about the fixed angular momentum and one about the body axis ``ŝ``:

.. math::
   \mathrm{rot}(t) = R_{\hat m_{ref}}(\Omega t)\;\mathrm{rot}_0\;R_{\hat s}(\lambda t),\qquad
   m(t) = R_{\hat s}(-\lambda t)\, m_0,\qquad \Omega = G w_t,\quad \lambda = m_s (w_s - w_t),

(check: ``rot⁻¹ d rot/dt = Ω m̂(t) + λ ŝ = ω``).  The same formula with ``λ = 0`` is the
motion of a sphere, of any steady spin about a principal axis (including the unstable
one) and, with ``Ω = 0``, of a body at rest.  Both angles are carried as double-double
phases (:mod:`andoyer.free.phase`).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from scipy.spatial.transform import Rotation

from andoyer._quaternion import product
from andoyer.free.phase import Frequency, cycles, frequency
from andoyer.regime import Regime
from andoyer.special.compensated import (
    PI_DD,
    dd_add,
    dd_div,
    dd_mul,
    dd_sqrt,
    split,
    two_prod,
    two_sum,
)

__all__ = ["Uniform", "evaluate", "uniform", "uniform_axes"]

_TWO_PI = (2.0 * PI_DD[0], 2.0 * PI_DD[1])


class Uniform(NamedTuple):
    """Per-state constants of uniform motions (vectors ``(3, N)``, quaternions ``(4, N)``).

    Attributes
    ----------
    spin, body : Frequency
        ``Ω/2π`` and ``λ/2π`` in cycles per unit time.
    m_par, m_perp, m_cross : ndarray, shape (3, N)
        ``ŝ(ŝ·m₀)``, ``m₀ − ŝ(ŝ·m₀)`` and ``ŝ × m₀``.
    q1, q2, q3, q4 : ndarray, shape (4, N)
        ``q₀``, ``q₀ ⊗ ŝ``, ``m̂ ⊗ q₀`` and ``m̂ ⊗ q₀ ⊗ ŝ``.
    period, precession_rate : ndarray
        ``2π/|λ|`` (``inf`` if ``λ = 0``) and ``Ω``.
    """

    spin: Frequency
    body: Frequency
    m_par: np.ndarray
    m_perp: np.ndarray
    m_cross: np.ndarray
    q1: np.ndarray
    q2: np.ndarray
    q3: np.ndarray
    q4: np.ndarray
    period: np.ndarray
    precession_rate: np.ndarray


def uniform(m0, axis, I_s, I_t, q0=None):
    """Constants of regular precession about a body axis (or steady spin).

    Parameters
    ----------
    m0 : ndarray, shape (N, 3)
        Body angular momenta.
    axis : ndarray of int, shape (N,)
        The body axis ``ŝ``: the symmetry axis of an axisymmetric body, or the spin axis
        of a steady spin (any axis for a sphere or a body at rest).
    I_s, I_t : ndarray, shape (N,)
        Axial and transverse moments (``I_t = I_s`` for a steady spin or a sphere,
        which makes ``λ = 0``).
    q0 : ndarray, shape (N, 4), optional
        Initial attitudes.

    Returns
    -------
    Uniform

    Examples
    --------
    >>> u = uniform(np.array([[0.5, 0.0, 1.0]]), np.array([2]), np.array([3.0]), np.array([2.0]))
    >>> round(float(u.period[0]), 12), round(float(u.precession_rate[0]), 12)
    (37.699111843078, 0.559016994375)
    """
    n = m0.shape[0]
    rows = np.arange(n)
    m_s = m0[rows, axis]
    s_hat = np.zeros((n, 3))
    s_hat[rows, axis] = 1.0
    sq = [two_prod(m0[:, i], m0[:, i]) for i in range(3)]
    G = dd_sqrt(*dd_add(*dd_add(*sq[0], *sq[1]), *sq[2]))
    spin = dd_div(*G, *dd_mul(I_t, 0.0, *_TWO_PI))  # Ω/2π = G/(2π I_t)
    # λ = m_s (I_t − I_s)/(I_s I_t), exact difference, then / 2π
    lam = dd_div(*dd_mul(*two_sum(I_t, -I_s), m_s, 0.0), *two_prod(I_s, I_t))
    lam = dd_div(*lam, *_TWO_PI)
    m_par = s_hat * m_s[:, None]
    m_perp = m0 - m_par
    m_cross = np.cross(s_hat, m0)
    with np.errstate(divide="ignore"):
        period = np.abs(1.0 / lam[0])
    const = Uniform(
        spin=frequency(*spin),
        body=frequency(*lam),
        m_par=m_par.T,
        m_perp=m_perp.T,
        m_cross=m_cross.T,
        q1=np.zeros((4, n)),
        q2=np.zeros((4, n)),
        q3=np.zeros((4, n)),
        q4=np.zeros((4, n)),
        period=period,
        precession_rate=2.0 * np.pi * spin[0],
    )
    if q0 is None:
        return const
    g = G[0]
    m_ref = Rotation.from_quat(q0).apply(m0)
    m_hat = np.where(g[:, None] > 0, m_ref / np.where(g > 0, g, 1.0)[:, None], 0.0)
    sq_ = (*s_hat.T, np.zeros(n))
    mq = (*m_hat.T, np.zeros(n))
    q1 = tuple(q0.T)
    q2 = product(*q1, *sq_)
    return const._replace(
        q1=np.stack(q1), q2=np.stack(q2), q3=np.stack(product(*mq, *q1)), q4=np.stack(product(*mq, *q2))
    )


def uniform_axes(moments, m0, regime):
    """Axis, axial and transverse moments of states moving without elliptic functions.

    Parameters
    ----------
    moments, m0 : ndarray, shape (N, 3)
    regime : ndarray of int, shape (N,)
        :class:`andoyer.regime.Regime` codes: axisymmetric states use the axis of the
        distinct moment; steady spins (of any regime, including a wobble so small that
        its square underflows), spheres and rest use the largest momentum component,
        with ``I_t = I_s`` so that ``λ = 0``.

    Returns
    -------
    axis : ndarray of int
    I_s, I_t : ndarray

    Examples
    --------
    >>> axis, I_s, I_t = uniform_axes(np.array([[2.0, 3.0, 2.0]]), np.array([[0.1, 1.0, 0.2]]),
    ...                               np.array([Regime.AXISYMMETRIC]))
    >>> int(axis[0]), float(I_s[0]), float(I_t[0])
    (1, 3.0, 2.0)
    """
    order = np.argsort(moments, axis=-1, kind="stable")
    rows = np.arange(moments.shape[0])
    s = moments[rows[:, None], order]
    distinct = np.where(s[:, 0] == s[:, 1], order[:, 2], order[:, 0])
    spin_axis = np.argmax(np.abs(m0), axis=-1)
    axis = np.where(regime == Regime.AXISYMMETRIC, distinct, spin_axis)
    I_s = moments[rows, axis]
    transverse = np.where(s[:, 0] == s[:, 1], s[:, 0], s[:, 2])
    I_t = np.where(regime == Regime.AXISYMMETRIC, transverse, I_s)
    return axis, I_s, I_t


def evaluate(c: Uniform, t, attitude=True):
    """Body angular momentum and attitude of uniform motions at times ``t``.

    Parameters
    ----------
    c : Uniform
        Constants shaped to broadcast against ``t``.
    t : ndarray
        Times since the initial state.
    attitude : bool, optional
        Also return the attitude quaternion components.

    Returns
    -------
    m : tuple of 3 ndarray
    q : tuple of 4 ndarray or None

    Examples
    --------
    >>> u = uniform(np.array([[0.5, 0.0, 1.0]]), np.array([2]), np.array([3.0]), np.array([2.0]))
    >>> m, _ = evaluate(u, np.array([u.period[0] / 4]), attitude=False)
    >>> [round(float(v[0]), 12) for v in m]
    [0.0, 0.5, 1.0]
    """
    tt = split(t)
    beta = np.pi * cycles(c.body, t, tt)
    cb, sb = np.cos(beta), np.sin(beta)
    c2 = 1.0 - 2.0 * sb * sb
    s2 = -2.0 * sb * cb  # sin(−λt)
    m = tuple(c.m_par[k] + c.m_perp[k] * c2 + c.m_cross[k] * s2 for k in range(3))
    if not attitude:
        return m, None
    alpha = np.pi * cycles(c.spin, t, tt)
    ca, sa = np.cos(alpha), np.sin(alpha)
    w1, w2, w3, w4 = ca * cb, ca * sb, sa * cb, sa * sb
    q = tuple(w1 * c.q1[k] + w2 * c.q2[k] + w3 * c.q3[k] + w4 * c.q4[k] for k in range(4))
    return m, q
