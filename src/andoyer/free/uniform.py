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

Here is the numpy path, on arrays of states: each formula is a kernel of
:mod:`andoyer.free.kernels.uniform` applied to whole arrays, one per component, the same
kernels that :mod:`andoyer.free.compiled_uniform` compiles per state.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from andoyer.free.kernels import uniform as _k
from andoyer.free.phase import Frequency, cycles, frequency
from andoyer.regime import Regime
from andoyer.special.compensated import split

__all__ = ["Uniform", "evaluate", "uniform", "uniform_axes"]

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
    m = np.ascontiguousarray(m0.T)  # one array per component
    m_s = _k.component(m, axis)
    G, sh, sl, lh, ll, period, rate = _k.frequencies(m, m_s, I_s, I_t)
    m_par, m_perp, m_cross = _k.decomposition(m, axis, m_s)
    const = Uniform(
        spin=frequency(sh, sl),
        body=frequency(lh, ll),
        m_par=np.stack(m_par),
        m_perp=np.stack(m_perp),
        m_cross=np.stack(m_cross),
        q1=np.zeros((4, n)),
        q2=np.zeros((4, n)),
        q3=np.zeros((4, n)),
        q4=np.zeros((4, n)),
        period=period,
        precession_rate=rate,
    )
    if q0 is None:
        return const
    q1 = np.ascontiguousarray(q0.T)
    q2, q3, q4 = _k.quaternions(q1, m, axis, G)
    return const._replace(q1=q1, q2=np.stack(q2), q3=np.stack(q3), q4=np.stack(q4))


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
    return _k.axes(moments.T, m0.T, regime == Regime.AXISYMMETRIC)


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
    cb, sb = _k.turn(cycles(c.body, t, tt))
    m = _k.momentum(cb, sb, c.m_par, c.m_perp, c.m_cross)
    if not attitude:
        return m, None
    ca, sa = _k.turn(cycles(c.spin, t, tt))
    return m, _k.attitude(cb, sb, ca, sa, c.q1, c.q2, c.q3, c.q4)
