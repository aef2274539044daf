"""Evaluation of the kernels over states × epochs, in cache-sized blocks.

States are grouped by kernel (:class:`Group`).  The broadcast of the state shape with
the shape of the times is laid out as rows (states) × columns (epochs) whenever the
leading axes of ``t`` are those of the states or 1 (the common cases: one time for all,
one time per state, a grid of states by epochs); any other broadcast becomes one row per
output element.  Each block of about ``_CHUNK`` elements calls the kernel once with the
constants of its rows shaped ``(r, 1)``, so that numpy broadcasts them along the epochs.

The kernels solve the state scaled by powers of two
(:func:`andoyer.free.common.scaling_numpy.normalise`): times enter as ``2^{b−a} t`` and momenta
leave as ``2^b m``, both exact.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from andoyer.free.common import constants as _const

__all__ = ["Group", "evaluate_blocks"]

_CHUNK = 16384  # elements per block: amortises numpy call overhead, temporaries stay in cache


class Group(NamedTuple):
    """States evaluated by one kernel.

    Attributes
    ----------
    kernel : callable
        ``kernel(constants, t, attitude) -> (m, q)`` on component tuples, the constants
        of the block's states shaped as rows.  A kernel with an attribute ``fill``
        (compiled, e.g. :func:`andoyer.free.triaxial.evaluate_compiled.fill`) is instead handed
        the whole table, the positions, the output rows, the unscaled times, the exponents and
        the output arrays, and fills them itself.
    members : ndarray of int
        Flat indices of the states.
    const : NamedTuple
        The kernel's constants for ``members`` (state axis last).
    tshift, mshift : ndarray of int
        Per-member exponents: kernel time ``2^tshift t``, momentum ``2^mshift m``.
    """

    kernel: object
    members: np.ndarray
    const: tuple
    tshift: np.ndarray
    mshift: np.ndarray


def evaluate_blocks(groups, shape, t, attitude):
    """Body angular momentum (and attitude) of all states at times ``t``.

    Parameters
    ----------
    groups : list of Group
        Every state of ``shape`` in exactly one group.
    shape : tuple
        Shape of the states.
    t : ndarray
        Finite times, broadcast against ``shape``.
    attitude : bool
        Also evaluate the attitude quaternions.

    Returns
    -------
    m : ndarray, shape (*broadcast(shape, t.shape), 3)
    q : ndarray, shape (*broadcast(shape, t.shape), 4) or None

    Examples
    --------
    >>> from andoyer.free.motion import FreeMotion
    >>> fm = FreeMotion([2.0, 2.0, 3.0], [0.5, 0.0, 1.0])
    >>> m, q = evaluate_blocks(fm._groups, fm.shape, np.zeros(2), False)
    >>> m.tolist(), q
    ([[0.5, 0.0, 1.0], [0.5, 0.0, 1.0]], None)
    """
    n = int(np.prod(shape))
    out_shape = np.broadcast_shapes(shape, t.shape)
    if 0 in out_shape:  # no state or no epoch: nothing to evaluate (and no -1 to reshape by)
        return np.empty((*out_shape, 3)), np.empty((*out_shape, 4)) if attitude else None
    nd = len(out_shape)
    bs = (1,) * (nd - len(shape)) + tuple(shape)
    ts = (1,) * (nd - t.ndim) + t.shape

    def outer(k):
        lead = zip(ts[:k], bs[:k], strict=True)
        return set(bs[k:]) <= {1} and all(a in (1, b) for a, b in lead)

    split_at = next((k for k in range(nd + 1) if outer(k)), None)
    if split_at is not None:  # states along rows, epochs along columns
        body_rows = None
        lead = ts[:split_at] if set(ts[:split_at]) <= {1} else bs[:split_at]
        t2 = np.broadcast_to(t.reshape(ts), (*lead, *ts[split_at:]))
        t2 = t2.reshape(int(np.prod(lead)), -1)
    else:  # general broadcast: one row per output element
        body_rows = np.broadcast_to(np.arange(n).reshape(bs), out_shape).ravel()
        t2 = np.broadcast_to(t, out_shape).reshape(-1, 1)
    nrows = n if body_rows is None else body_rows.size
    ncols = t2.shape[1]
    m_out = np.empty((nrows, ncols, 3))
    q_out = np.empty((nrows, ncols, 4)) if attitude else None
    for group in groups:
        if body_rows is None:
            rows, pos = group.members, np.arange(group.members.size)
        else:
            where = np.full(n, -1)
            where[group.members] = np.arange(group.members.size)
            rows = np.nonzero(where[body_rows] >= 0)[0]
            pos = where[body_rows[rows]]
        _run(group, rows, pos, t2, (m_out, q_out))
    m_out = m_out.reshape(*out_shape, 3)
    return m_out, (None if q_out is None else q_out.reshape(*out_shape, 4))


def _scale(x, exponent):
    """``x · 2^exponent``, exact.

    A multiplication by the power of two (``np.ldexp`` on arrays is 20 times slower),
    unless the power itself would overflow.
    """
    if np.all(np.abs(exponent) < 1000):
        return x * np.ldexp(1.0, exponent)
    return np.ldexp(x, exponent)


def _run(group, rows, pos, t2, outs):
    """Evaluate one group on output rows ``rows`` (constants at ``pos``), block by block."""
    fill = getattr(group.kernel, "fill", None)
    if fill is not None:  # a compiled kernel that writes the outputs itself
        fill(group.const, pos, rows, t2, (group.tshift, group.mshift), outs)
        return
    m_out, q_out = outs
    ncols = t2.shape[1]
    cstep = min(ncols, _CHUNK)
    rstep = max(1, _CHUNK // cstep)
    per_row_t = t2.shape[0] > 1
    contiguous = rows.size > 0 and rows[-1] - rows[0] == rows.size - 1
    for r0 in range(0, rows.size, rstep):
        r_idx = rows[r0 : r0 + rstep]
        # a slice keeps the writes below in place; fancy indices would copy
        r_sel = slice(r_idx[0], r_idx[-1] + 1) if contiguous else r_idx
        p_rows = pos[r0 : r0 + rstep]
        c_rows = _const.rows(group.const, p_rows)
        tsh, msh = group.tshift[p_rows][:, None], group.mshift[p_rows][:, None]
        for c0 in range(0, ncols, cstep):
            cols = slice(c0, c0 + cstep)
            tc = _scale(t2[r_sel, cols] if per_row_t else t2[:, cols], tsh)
            m, q = group.kernel(c_rows, tc, q_out is not None)
            m = [_scale(comp, msh) for comp in m]
            for out, comps in ((m_out, m), (q_out, q)):
                if out is None:
                    continue
                if contiguous:  # a view: write the components in place, strided
                    block = out[r_sel, cols]
                    for k, comp in enumerate(comps):
                        block[..., k] = comp
                else:
                    out[r_sel, cols] = np.stack(comps, axis=-1)
