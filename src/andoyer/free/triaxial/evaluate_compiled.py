"""Per-epoch evaluation of the triaxial solution from its constant table, compiled by numba.

The formulas of :mod:`andoyer.free.triaxial.evaluate_numpy`, for one state and one epoch at a
time and looped over a block of states × epochs: no array temporaries, the circular and
hyperbolic series chosen per state.  The formulas themselves are the kernels both paths call:
the theta series of ``sn, cn, dn`` (all their terms here), the circular ``ϑ₁`` and the ``ψ``
half angle (:mod:`andoyer.free.triaxial.evaluate`), the anchored attitude
(:func:`andoyer.free.common.polhode.attitude`), ``sin``/``cos`` of a reduced phase
(:func:`andoyer.free.common.cycles.sincos_cycles`).  Written here: the phases
from the table's double-doubles (``_cycles``: the error-free product by a fused
multiply-add, where the numpy path splits the times once for all its phases) and the
hyperbolic ``ϑ₁`` sum, whose powers of ``1/e^{−y}`` are divisions here and products by the
reciprocal there (one form for both moves either path's attitude by up to 2 ulps).  The
constants are the table of :func:`andoyer.free.triaxial.setup_compiled.triaxial_table`, its
columns named in :mod:`andoyer.free.triaxial.columns`.
"""

from __future__ import annotations

import math

import numpy as np

from andoyer._jit import jit
from andoyer.free.common.cycles import sincos_cycles
from andoyer.free.common.polhode import attitude as anchored
from andoyer.free.triaxial import evaluate as series
from andoyer.free.triaxial.columns import (
    A3,
    C_CN,
    C_DN,
    C_SN,
    CIRCULAR,
    FRAC0,
    HI,
    KK,
    LO,
    MU_CN,
    MU_DN,
    MU_SN,
    NU,
    NU_PSI,
    PSI0,
    QUAT_U,
    QUAT_V,
    SLOPE,
    V_CN,
    V_SN,
    WA,
    WB,
    G,
    Q,
)
from andoyer.special.compensated import two_prod

__all__ = ["evaluate", "fill"]


_NEGLIGIBLE = 1e-18


@jit
def _count(powers):
    """Number of leading series terms: the first, and those whose power of the nome is not negligible."""
    n = 1
    while n < len(powers) and powers[n] > _NEGLIGIBLE:
        n += 1
    return n


@jit
def _cycles(c, r, col, t):
    """``ν t`` reduced to ``[-1/2, 1/2]`` cycles, ``ν`` the double-double at column ``col``."""
    p, e = two_prod(c[r, col + HI], t)
    e += c[r, col + LO] * t
    f = p - np.rint(p)
    return f + e


@jit
def _circular(c, r, f, out_m):
    """Momentum and ``(sn, cn, dn, f, x, y)`` by the circular series (``k² ≤ 1/2``).

    All terms up to ``q¹⁶`` (``< 10⁻²¹`` at ``k² = 1/2``) and three of ``ϑ₁``
    (:func:`andoyer.free.triaxial.evaluate.circular`): those the numpy kernel drops below
    1e-18 change nothing at double precision.
    """
    s1, c1 = sincos_cycles(f)
    wa = (c[r, WA], c[r, WA + 1], c[r, WA + 2])
    wb = (c[r, WB], c[r, WB + 1], c[r, WB + 2])
    num_s, num_c, th3, inv, x, y = series.circular(s1, c1, c[r, Q], wa, wb, 4, 4, 3)
    for k in range(3):
        out_m[k] = inv * (c[r, MU_CN + k] * num_c + c[r, MU_SN + k] * num_s + c[r, MU_DN + k] * th3)
    return c[r, C_SN] * inv * num_s, c[r, C_CN] * inv * num_c, c[r, C_DN] * inv * th3, f, x, y


@jit
def _hyperbolic(c, r, f, out_m, attitude):
    """Momentum and ``(sn, cn, dn, f_w, x, y)`` by the hyperbolic series (``k² > 1/2``).

    All terms up to ``q'¹⁶`` (``z = q'e^{2y} ≤ 1`` and ``ρ = e^{−2y} ≤ 1`` keep them
    bounded; :func:`andoyer.free.triaxial.evaluate.hyperbolic`); the ``ϑ₁`` series grows like
    ``e^{2ny}`` and is cut where its coefficients ``q*^{n²+n}`` fall below 1e-18, as in the
    numpy kernel.
    """
    q = c[r, Q]
    sh, t4, t3, fw, zi = series.hyperbolic(f, q, c[r, KK], 5, 5)
    for k in range(3):
        out_m[k] = c[r, MU_CN + k] * t4 + c[r, MU_SN + k] * sh + c[r, MU_DN + k] * t3
    if not attitude:
        return 0.0, 0.0, 0.0, fw, 0.0, 0.0
    q2 = q * q
    q3 = q2 * q
    q6 = q3 * q3
    n_w = _count((1.0, q, q3, q6, q6 * (q2 * q2), q6 * q6 * q3))  # q*^{n² + n}, q* = √q
    up, down = 1.0, zi
    x = c[r, WA] * (1.0 + zi)
    y = c[r, WB] * (1.0 - zi)
    for n in range(1, n_w):
        up /= zi
        down *= zi
        x += c[r, WA + n] * (up + down)
        y += c[r, WB + n] * (up - down)
    return c[r, C_SN] * sh, c[r, C_CN] * t4, c[r, C_DN] * t3, fw, x, -y if fw < 0 else y


@jit
def _state(c, r, t, out_m, out_q, attitude):
    """Momentum (and attitude) of the state in row ``r`` at the scaled time ``t``."""
    f = _cycles(c, r, NU, t) + c[r, FRAC0]
    f -= np.rint(f)
    if c[r, CIRCULAR] > 0:
        sn, cn, dn, f_lin, x, y = _circular(c, r, f, out_m)
    else:
        sn, cn, dn, f_lin, x, y = _hyperbolic(c, r, f, out_m, attitude)
    if attitude:
        _attitude(c, r, t, sn, cn, dn, f_lin, x, y, out_q)


@jit
def _attitude(c, r, t, sn, cn, dn, f_lin, x, y, out_q):
    """Attitude of the state in row ``r`` at the scaled time ``t`` from its series values."""
    psi = _cycles(c, r, NU_PSI, t) + c[r, PSI0]
    psi -= np.rint(psi)
    cz, sz = series.half_angle(psi, c[r, SLOPE], f_lin, x, y)
    u = (c[r, QUAT_U], c[r, QUAT_U + 1], c[r, QUAT_U + 2], c[r, QUAT_U + 3])
    v = (c[r, QUAT_V], c[r, QUAT_V + 1], c[r, QUAT_V + 2], c[r, QUAT_V + 3])
    va = (c[r, V_SN], c[r, V_SN + 1], c[r, V_SN + 2])
    vb = (c[r, V_CN], c[r, V_CN + 1], c[r, V_CN + 2])
    q = anchored(cz, sz, u, v, va, vb, sn, cn, c[r, A3] * dn, c[r, G])
    out_q[0], out_q[1], out_q[2], out_q[3] = q[0], q[1], q[2], q[3]


@jit
def _block(c, rows, t, m, q, attitude):
    mk = np.empty(3)
    qk = np.empty(4)
    per_row = t.shape[0] > 1
    for i in range(rows.size):
        r = rows[i]
        for e in range(t.shape[1]):
            _state(c, r, t[i if per_row else 0, e], mk, qk, attitude)
            for k in range(3):
                m[k, i, e] = mk[k]
            if attitude:
                for k in range(4):
                    q[k, i, e] = qk[k]


@jit
def _fill(c, pos, rows, t, tshift, mshift, m_out, q_out, attitude):
    per_row = t.shape[0] > 1
    for i in range(rows.size):
        r, o = pos[i], rows[i]
        ts, ms = tshift[r], mshift[r]
        exact = abs(ts) < 1000 and abs(ms) < 1000  # then products by the powers are exact
        ft, fm = (2.0**ts, 2.0**ms) if exact else (1.0, 1.0)
        # the row's series chosen once, not per epoch through _state: the epoch loop then
        # compiles to one straight body (measured 2x on the momentum, issue 25 item 2)
        circular = c[r, CIRCULAR] > 0
        for e in range(t.shape[1]):
            m = m_out[o, e]
            tk = t[o if per_row else 0, e]
            tk = tk * ft if exact else math.ldexp(tk, ts)
            f = _cycles(c, r, NU, tk) + c[r, FRAC0]
            f -= np.rint(f)
            if circular:
                sn, cn, dn, f_lin, x, y = _circular(c, r, f, m)
            else:
                sn, cn, dn, f_lin, x, y = _hyperbolic(c, r, f, m, attitude)
            if attitude:
                _attitude(c, r, tk, sn, cn, dn, f_lin, x, y, q_out[o, e])
            for k in range(3):
                m[k] = m[k] * fm if exact else math.ldexp(m[k], ms)


def fill(c, pos, rows, t, scale, outs):
    """Evaluate states straight into the output arrays of :func:`andoyer.free.common.blocks.evaluate_blocks`.

    One compiled loop over states and epochs: the times scaled, the kernel, the momentum
    scaled and stored, with no block temporaries.

    Parameters
    ----------
    c : ndarray, shape (N, NCOLUMNS)
        The table of :func:`andoyer.free.triaxial.setup_compiled.triaxial_table`.
    pos, rows : ndarray of int, shape (r,)
        Rows of ``c`` and the output rows they fill.
    t : ndarray, shape (rows_out, e) or (1, e)
        Unscaled times, per output row or shared.
    scale : tuple of ndarray, shape (N,)
        Exponents ``(tshift, mshift)``: kernel time ``2^tshift t``, momentum ``2^mshift m``.
    outs : tuple of ndarray
        ``m_out`` of shape ``(rows_out, e, 3)`` and ``q_out`` of shape ``(rows_out, e, 4)``
        or None.

    Examples
    --------
    >>> from andoyer.free.triaxial.setup_compiled import triaxial_table
    >>> table, _ = triaxial_table(np.array([[0.25, 0.5, 0.75]]), np.array([[0.3, 0.2, 1.0]]),
    ...                           np.array([False]))
    >>> m = np.empty((1, 1, 3))
    >>> one = np.array([0])
    >>> fill(table, one, one, np.zeros((1, 1)), (one, np.array([1])), (m, None))
    >>> m.round(14).tolist()
    [[[0.6, 0.4, 2.0]]]
    """
    m_out, q_out = outs
    attitude = q_out is not None
    q = q_out if attitude else np.empty((m_out.shape[0], m_out.shape[1], 4))
    tshift, mshift = (np.asarray(x, dtype=np.int64) for x in scale)
    _fill(
        c,
        np.asarray(pos, dtype=np.intp),
        np.asarray(rows, dtype=np.intp),
        t,
        tshift,
        mshift,
        m_out,
        q,
        attitude,
    )


def evaluate(c, rows, t, attitude=True):
    """Body angular momentum and attitude of triaxial states at times ``t`` (compiled).

    Parameters
    ----------
    c : ndarray, shape (N, NCOLUMNS)
        The table of :func:`andoyer.free.triaxial.setup_compiled.triaxial_table`.
    rows : ndarray of int, shape (r,)
        The states to evaluate (rows of ``c``).
    t : ndarray, shape (r, e) or (1, e)
        Scaled times: per state or shared.
    attitude : bool, optional
        Also return the attitude quaternion components.

    Returns
    -------
    m : tuple of 3 ndarray, shape (r, e)
    q : tuple of 4 ndarray, shape (r, e), or None

    Examples
    --------
    >>> from andoyer.free.triaxial.setup_compiled import triaxial_table
    >>> table, _ = triaxial_table(np.array([[0.25, 0.5, 0.75]]), np.array([[0.3, 0.2, 1.0]]),
    ...                           np.array([False]), np.array([[0.0, 0.0, 0.0, 1.0]]))
    >>> m, q = evaluate(table, np.array([0]), np.zeros((1, 2)))
    >>> np.round(m, 14).tolist(), np.round(q, 14)[:, 0, 0].tolist()
    ([[[0.3, 0.3]], [[0.2, 0.2]], [[1.0, 1.0]]], [0.0, 0.0, 0.0, 1.0])
    """
    rows = np.asarray(rows, dtype=np.intp)
    t = np.asarray(t, dtype=np.float64)
    shape = (rows.size, t.shape[1])
    m = np.empty((3, *shape))
    q = np.empty((4, *shape)) if attitude else np.empty((4, 0, 0))
    _block(c, rows, t, m, q, attitude)
    return tuple(m), (tuple(q) if attitude else None)


evaluate.fill = fill  # andoyer.free.common.blocks fills its outputs through this, no blocks
