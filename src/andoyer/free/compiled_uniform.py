"""Regular precession and steady spin (:mod:`andoyer.free.uniform`), set up and evaluated by numba.

:func:`andoyer.free.uniform.uniform` and :func:`andoyer.free.uniform.evaluate` form the
constants and the motion of axisymmetric bodies, spheres, steady spins and bodies at rest
by applying the kernels of :mod:`andoyer.free.kernels.uniform` to whole arrays: about a
hundred array passes, which for a single body cost ~0.3 ms to set up and ~0.1 ms to
evaluate. Here the same kernels (the same double-double arithmetic,
:mod:`andoyer.special.compensated`) run per body in a compiled loop, a few µs in all, with
the same bits; the phases (:func:`andoyer.free.phase.phase` here, the pre-split
:func:`andoyer.free.phase.cycles` there) the same values (``tests/free/test_free_uniform_kernels.py``).
:class:`andoyer.free.FreeMotion` uses them with the compiled backend, as it does
:mod:`andoyer.free.compiled_setup` for triaxial bodies.

The table has one row per state (columns in :data:`COLUMNS`): the double-double
frequencies ``Ω/2π`` and ``λ/2π``, the vectors ``m_par, m_perp, m_cross`` and the
quaternions ``q1 … q4`` of :class:`andoyer.free.uniform.Uniform`.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from andoyer._jit import jit
from andoyer.free.kernels.frame import invariants, polhode_axes, sorted_axes, steady_spin_limit
from andoyer.free.kernels.uniform import (
    attitude,
    axes,
    component,
    decomposition,
    frequencies,
    momentum,
    quaternions,
    turn,
)
from andoyer.free.phase import phase
from andoyer.regime import Regime

__all__ = ["COLUMNS", "UniformTable", "evaluate", "fill", "polhode_limit", "uniform_table"]

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

    The axis and moments of :func:`andoyer.free.uniform.uniform_axes` and the constants of
    :func:`andoyer.free.uniform.uniform`: the same kernels (:mod:`andoyer.free.kernels.uniform`)
    per state, in one loop.

    Parameters
    ----------
    moments, m0 : ndarray, shape (N, 3)
        Moments and body angular momenta.
    regime : ndarray of int, shape (N,)
        :class:`andoyer.free.regime.Regime` codes: axisymmetric states turn about the axis of
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


@jit(inline=True)  # per epoch of the loop below: a call costs as much as the state
def _state(c, t, m, q, attitude_too):
    """Momentum (and attitude) of the state whose row is ``c`` at the scaled time ``t``."""
    cb, sb = turn(phase(c[2], c[3], t))
    m[0], m[1], m[2] = momentum(cb, sb, (c[4], c[5], c[6]), (c[7], c[8], c[9]), (c[10], c[11], c[12]))
    if not attitude_too:
        return
    ca, sa = turn(phase(c[0], c[1], t))
    q1, q2 = (c[13], c[14], c[15], c[16]), (c[17], c[18], c[19], c[20])
    q3, q4 = (c[21], c[22], c[23], c[24]), (c[25], c[26], c[27], c[28])
    q[0], q[1], q[2], q[3] = attitude(cb, sb, ca, sa, q1, q2, q3, q4)


@jit
def _fill(c, pos, rows, t, tshift, mshift, m_out, q_out, attitude):
    per_row = t.shape[0] > 1
    for i in range(rows.size):
        r, o = pos[i], rows[i]
        row = c[r]
        ts, ms = tshift[r], mshift[r]
        exact = abs(ts) < 1000 and abs(ms) < 1000  # then products by the powers are exact
        ft, fm = (2.0**ts, 2.0**ms) if exact else (1.0, 1.0)
        for e in range(t.shape[1]):
            m = m_out[o, e]
            tk = t[o if per_row else 0, e]
            _state(row, tk * ft if exact else math.ldexp(tk, ts), m, q_out[o, e], attitude)
            for k in range(3):
                m[k] = m[k] * fm if exact else math.ldexp(m[k], ms)


def fill(c, pos, rows, t, scale, outs):
    """Evaluate states straight into the output arrays of :func:`andoyer.free.blocks.evaluate_blocks`.

    Parameters
    ----------
    c : UniformTable
        The constants of :func:`uniform_table`.
    pos, rows : ndarray of int, shape (r,)
        Rows of the table and the output rows they fill.
    t : ndarray, shape (rows_out, e) or (1, e)
        Unscaled times, per output row or shared.
    scale : tuple of ndarray, shape (N,)
        Exponents ``(tshift, mshift)``: kernel time ``2^tshift t``, momentum ``2^mshift m``.
    outs : tuple of ndarray
        ``m_out`` of shape ``(rows_out, e, 3)`` and ``q_out`` of shape ``(rows_out, e, 4)``
        or None.

    Examples
    --------
    >>> u = uniform_table(np.array([[2.0, 2.0, 3.0]]), np.array([[0.5, 0.0, 1.0]]), np.array([3]))
    >>> m = np.empty((1, 1, 3))
    >>> one = np.array([0])
    >>> fill(u, one, one, np.array([[u.period[0] / 4]]), (one, one + 1), (m, None))  # momentum × 2
    >>> m.round(12).tolist()
    [[[0.0, 1.0, 2.0]]]
    """
    m_out, q_out = outs
    attitude = q_out is not None
    q = q_out if attitude else np.empty((m_out.shape[0], m_out.shape[1], 4))
    tshift, mshift = (np.asarray(x, dtype=np.int64) for x in scale)
    _fill(
        c.table,
        np.asarray(pos, dtype=np.intp),
        np.asarray(rows, dtype=np.intp),
        t,
        tshift,
        mshift,
        m_out,
        q,
        attitude,
    )


def evaluate(c, t, attitude=True):
    """Body angular momentum and attitude of uniform motions at times ``t`` (compiled).

    The same motion as :func:`andoyer.free.uniform.evaluate`.

    Parameters
    ----------
    c : UniformTable
        The constants of :func:`uniform_table` (N states).
    t : ndarray, shape (N, e) or (1, e)
        Scaled times: per state or shared.
    attitude : bool, optional
        Also return the attitude quaternion components.

    Returns
    -------
    m : tuple of 3 ndarray, shape (N, e)
    q : tuple of 4 ndarray, shape (N, e), or None

    Examples
    --------
    >>> u = uniform_table(np.array([[2.0, 2.0, 3.0]]), np.array([[0.5, 0.0, 1.0]]), np.array([3]))
    >>> m, _ = evaluate(u, np.array([[u.period[0] / 4]]), attitude=False)
    >>> [round(float(v[0, 0]), 12) for v in m]
    [0.0, 0.5, 1.0]
    """
    n = c.table.shape[0]
    t = np.asarray(t, dtype=np.float64)
    m = np.empty((n, t.shape[1], 3))
    q = np.empty((n, t.shape[1], 4)) if attitude else None
    rows = np.arange(n)
    fill(c, rows, rows, t, (np.zeros(n, dtype=np.int64), np.zeros(n, dtype=np.int64)), (m, q))
    return tuple(np.moveaxis(m, -1, 0)), (None if q is None else tuple(np.moveaxis(q, -1, 0)))


evaluate.fill = fill  # andoyer.free.blocks fills its outputs through this


@jit
def _limits(moments, m0, lam, period, rate):
    for i in range(moments.shape[0]):
        I, m = moments[i], m0[i]
        a, b, c = sorted_axes(I[0], I[1], I[2])
        p1, p2, p3, _, _ = polhode_axes(a, b, c, lam[i], m[0], m[1], m[2])
        s = -1.0 if lam[i] else 1.0
        _, e13, e23, _, _, _, G, w3 = invariants(
            s, I[p1], I[p2], I[p3], m[p1], m[p2], m[p3]
        )
        period[i], rate[i] = steady_spin_limit(s, e13[0], e23[0], G[0], w3[0])


def polhode_limit(moments, m0, lam):
    """Period and precession rate of a steady spin about the polhode axis: the limit of nearby polhodes.

    ``ω = G √(e₁₃ e₂₃)``, period ``2π/ω`` and rate ``G w₃ + s ω`` in the working frame of
    :func:`andoyer.free.regime.polhode_frame` (the numbers :class:`andoyer.free.FreeMotion`
    forms from it without numba).

    Parameters
    ----------
    moments, m0 : ndarray, shape (N, 3)
        Strictly triaxial moments and body angular momenta (steady spins).
    lam : ndarray of bool, shape (N,)
        True for a spin about the axis of least moment.

    Returns
    -------
    period, rate : ndarray, shape (N,)

    Examples
    --------
    >>> period, rate = polhode_limit(np.array([[1.0, 2.0, 4.0]]), np.array([[0.0, 0.0, 1.0]]),
    ...                              np.array([False]))
    >>> round(float(period[0]), 12), round(float(rate[0]), 12)  # ω = √(3/4 · 1/4)
    (14.510394913874, 0.683012701892)
    """
    n = moments.shape[0]
    period, rate = np.empty(n), np.empty(n)
    _limits(
        np.ascontiguousarray(moments, dtype=np.float64),
        np.ascontiguousarray(m0, dtype=np.float64),
        np.ascontiguousarray(lam, dtype=np.bool_),
        period,
        rate,
    )
    return period, rate
