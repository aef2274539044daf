"""The constants of the uniform motions, per state in one compiled loop (the compiled driver of ``setup``).

:func:`andoyer.free.uniform.setup_numpy.uniform` forms the constants of axisymmetric bodies,
spheres, steady spins and bodies at rest by applying the kernels of
:mod:`andoyer.free.uniform.setup` to whole arrays: about a hundred array passes, which for a
single body cost ~0.3 ms.  Here the same kernels (the same double-double arithmetic,
:mod:`andoyer.special.compensated`) run per body in a compiled loop, a few µs, with the same
bits (``tests/free/uniform/test_free_uniform_kernels.py``).  :class:`andoyer.free.FreeMotion`
uses it with the compiled backend, as it does :mod:`andoyer.free.triaxial.setup_compiled` for
triaxial bodies.

The table has one row per state (columns in :data:`COLUMNS`): the double-double
frequencies ``Ω/2π`` and ``λ/2π``, the vectors ``m_par, m_perp, m_cross`` and the
quaternions ``q1 … q4`` of :class:`andoyer.free.uniform.setup_numpy.Uniform`; it is read by
:mod:`andoyer.free.uniform.evaluate_compiled`.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from andoyer._jit import jit
from andoyer.free.uniform.setup import axes, component, decomposition, frequencies, quaternions
from andoyer.regime import Regime

__all__ = ["COLUMNS", "UniformTable", "uniform_table"]

#: Columns of the table: ``spin`` (hi, lo), ``body`` (hi, lo), ``m_par``, ``m_perp``,
#: ``m_cross`` (3 each, from column 4), ``q1 … q4`` (4 each, from column 13).
COLUMNS = 29


class UniformTable(NamedTuple):
    """Constants of uniform motions for the compiled kernel.

    Attributes
    ----------
    table : ndarray, shape (N, 29)
        One row per state (see :data:`COLUMNS`).
    period, precession_rate : ndarray, shape (N,)
        ``2π/|λ|`` (``inf`` if ``λ = 0``) and ``Ω``.
    """

    table: np.ndarray
    period: np.ndarray
    precession_rate: np.ndarray


@jit
def _setup(moments, m0, axisymmetric, q0, out, period, rate):
    with_attitude = q0.shape[0] > 0
    for i in range(m0.shape[0]):
        m = m0[i]
        k, I_s, I_t = axes(moments[i], m, axisymmetric[i])
        m_s = component(m, k)
        G, sh, sl, lh, ll, period[i], rate[i] = frequencies(m, m_s, I_s, I_t)
        m_par, m_perp, m_cross = decomposition(m, k, m_s)
        row = out[i]
        row[0], row[1], row[2], row[3] = sh, sl, lh, ll
        for j in range(3):
            row[4 + j] = m_par[j]
            row[7 + j] = m_perp[j]
            row[10 + j] = m_cross[j]
        if not with_attitude:
            continue
        q = q0[i]
        q2, q3, q4 = quaternions(q, m, k, G)
        for j in range(4):
            row[13 + j] = q[j]
            row[17 + j] = q2[j]
            row[21 + j] = q3[j]
            row[25 + j] = q4[j]


def uniform_table(moments, m0, regime, q0=None):
    """Constants of regular precession about a body axis (or steady spin), compiled.

    The axis and moments of :func:`andoyer.free.uniform.setup_numpy.uniform_axes` and the constants
    of :func:`andoyer.free.uniform.setup_numpy.uniform`: the same kernels
    (:mod:`andoyer.free.uniform.setup`) per state, in one loop.

    Parameters
    ----------
    moments, m0 : ndarray, shape (N, 3)
        Moments and body angular momenta.
    regime : ndarray of int, shape (N,)
        :class:`andoyer.regime.Regime` codes: axisymmetric states turn about the axis of
        the distinct moment; the others (steady spins, spheres, rest) about the largest
        momentum component, with ``λ = 0``.
    q0 : ndarray, shape (N, 4), optional
        Initial attitudes (unit quaternions, scalar last).

    Returns
    -------
    UniformTable

    Examples
    --------
    >>> u = uniform_table(np.array([[2.0, 2.0, 3.0]]), np.array([[0.5, 0.0, 1.0]]), np.array([3]))
    >>> round(float(u.period[0]), 12), round(float(u.precession_rate[0]), 12)
    (37.699111843078, 0.559016994375)
    """
    n = m0.shape[0]
    out = np.zeros((n, COLUMNS))
    period, rate = np.empty(n), np.empty(n)
    q = np.zeros((0, 4)) if q0 is None else np.ascontiguousarray(q0, dtype=np.float64)
    _setup(
        np.ascontiguousarray(moments, dtype=np.float64),
        np.ascontiguousarray(m0, dtype=np.float64),
        np.ascontiguousarray(np.asarray(regime) == Regime.AXISYMMETRIC),
        q,
        out,
        period,
        rate,
    )
    return UniformTable(out, period, rate)
