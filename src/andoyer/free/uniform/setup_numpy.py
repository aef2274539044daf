"""The constants of the uniform motions on arrays (the numpy driver of ``setup``).

Each formula is a kernel of :mod:`andoyer.free.uniform.setup` applied to whole arrays, one per
component, the same kernels that :mod:`andoyer.free.uniform.setup_compiled` compiles per state;
the motion they describe is derived in :mod:`andoyer.free.uniform`.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from andoyer.free.common.cycles_numpy import Frequency, frequency
from andoyer.free.uniform import setup as _k
from andoyer.regime import Regime

__all__ = ["Uniform", "uniform", "uniform_axes"]


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


