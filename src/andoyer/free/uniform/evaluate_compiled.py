"""The uniform motions at many epochs, per state in one compiled loop (the compiled driver of ``evaluate``).

:func:`andoyer.free.uniform.evaluate_numpy.evaluate` applies the kernels of
:mod:`andoyer.free.uniform.evaluate` to whole arrays: about a hundred array passes, ~0.1 ms for
a single body.  Here the same kernels run per state and epoch in a compiled loop, from the
table of :func:`andoyer.free.uniform.setup_compiled.uniform_table`, with the same bits; the
phases (:func:`andoyer.free.common.cycles.phase` here, the pre-split
:func:`andoyer.free.common.cycles_numpy.cycles` there) the same values
(``tests/free/uniform/test_free_uniform_kernels.py``).
"""

from __future__ import annotations

import math

import numpy as np

from andoyer._jit import jit
from andoyer.free.common.cycles import phase
from andoyer.free.uniform.evaluate import attitude, momentum, turn

__all__ = ["evaluate", "fill"]


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
    """Evaluate states straight into the output arrays of :func:`andoyer.free.common.blocks.evaluate_blocks`.

    Parameters
    ----------
    c : andoyer.free.uniform.setup_compiled.UniformTable
        The constants of :func:`~andoyer.free.uniform.setup_compiled.uniform_table`.
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
    >>> from andoyer.free.uniform.setup_compiled import uniform_table
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

    The same motion as :func:`andoyer.free.uniform.evaluate_numpy.evaluate`.

    Parameters
    ----------
    c : andoyer.free.uniform.setup_compiled.UniformTable
        The constants of :func:`~andoyer.free.uniform.setup_compiled.uniform_table` (N states).
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
    >>> from andoyer.free.uniform.setup_compiled import uniform_table
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


evaluate.fill = fill  # andoyer.free.common.blocks fills its outputs through this


