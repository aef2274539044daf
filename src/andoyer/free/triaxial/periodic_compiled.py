"""The piecewise representation of triaxial states, per state and epoch (compiled driver of ``periodic``).

:func:`fill` evaluates a :class:`~andoyer.free.triaxial.periodic_numpy.Periodic` group (built
by :func:`andoyer.free.triaxial.periodic_numpy.build`) straight into the outputs of
:func:`andoyer.free.common.blocks.evaluate_blocks`: per state, blocks of :data:`_BLOCK` epochs,
the reduced phases, then the polynomials of :mod:`andoyer.free.triaxial.periodic` piece by
piece (epochs on one piece together, as vectors, their coefficients in registers: sorted by
piece, in runs, or epoch by epoch), then the momentum and (with the attitude) one ``sincos``
and one product per epoch; outputs beyond the caches are written by non-temporal stores.
Every epoch gets the same operations as alone, so the values do not depend on the other
epochs nor on their order.  The loops let LLVM fuse each product with the sum that uses it
(``jit(contract=True)``; measured, 10 × 10⁵ epochs with the attitude: 15 % less time on an
AVX2 processor), so they round once where :func:`~andoyer.free.triaxial.periodic_numpy.fill_numpy`,
the same kernels on numpy arrays, rounds twice: the two agree to a few ulps.
"""

from __future__ import annotations

import numpy as np

from andoyer._jit import jit, when_compiled
from andoyer.free.common.cycles import sincos_half_cycles
from andoyer.free.triaxial.periodic import DEGREE, body_momentum, horner, locate, turned
from andoyer.special.compensated import two_prod

__all__ = ["fill"]


@jit(inline=True)
def _reduced(hi, lo, offset, t):
    """``offset + (hi + lo) t`` reduced to ``[−1/2, 1/2]`` cycles (error-free product)."""
    p, e = two_prod(hi, t)
    e += lo * t
    f = p - np.rint(p)
    f += e
    f += offset
    return f - np.rint(f)


_BLOCK = 4096  # epochs per block of the compiled fill (its buffers stay in the L2 cache)


_LANES = 8  # epochs on one piece are evaluated in whole vectors of this many epochs


_SHORT = 2.0  # blocks whose runs (consecutive epochs on one piece) are shorter are evaluated epoch by epoch


_BUCKET = 16  # blocks with this many epochs per piece or more are sorted by piece


_LONG = 8.0  # ... unless they are runs this long on average (measured)


@jit(inline=True)
def _row(piece, j, k):
    """Coefficients of ``uʲ`` of components ``k … k+3``."""
    return piece[j, k], piece[j, k + 1], piece[j, k + 2], piece[j, k + 3]


@jit(inline=True)
def _coefficients(piece, k):
    """Components ``k … k+3`` of a piece as a tuple of rows (values, so that loops keep them in registers).

    Written out for ``DEGREE = 9`` (ten rows; ``tests/free/triaxial/test_free_triaxial_periodic.py``
    checks it).
    """
    return (_row(piece, 0, k), _row(piece, 1, k), _row(piece, 2, k), _row(piece, 3, k), _row(piece, 4, k),
            _row(piece, 5, k), _row(piece, 6, k), _row(piece, 7, k), _row(piece, 8, k), _row(piece, 9, k))


@jit(inline=True)
def _horner_rows(c, u):
    """:func:`~andoyer.free.triaxial.periodic.horner` on rows of :func:`_coefficients` (same operations)."""
    a0, a1, a2, a3 = c[DEGREE]
    for j in range(DEGREE - 1, -1, -1):
        r = c[j]
        a0 = a0 * u + r[0]
        a1 = a1 * u + r[1]
        a2 = a2 * u + r[2]
        a3 = a3 * u + r[3]
    return a0, a1, a2, a3


@jit(inline=True)
def _phases(t, nu_hi, nu_lo, f0, n, x_out, u_out):
    """Pieces and local variables of the reduced polhode phases at times ``t`` (two loops that vectorise)."""
    for j in range(t.size):
        u_out[j] = _reduced(nu_hi, nu_lo, f0, t[j])
    for j in range(t.size):
        x, u = locate(u_out[j], n)
        x_out[j] = x
        u_out[j] = u


@jit(inline=True)
def _half_angles(t, g_hi, g_lo, g0, s_out, c_out):
    """``sin, cos(πg)`` of the reduced secular phases at times ``t``."""
    for j in range(t.size):
        s, c = sincos_half_cycles(_reduced(g_hi, g_lo, g0, t[j]))
        s_out[j] = s
        c_out[j] = c


@jit(contract=True)
def _span_momentum(piece, u, ys, j, m):
    """Momentum on one piece at ``u[j : j+m]`` into ``ys[0:3, j : j+m]`` (loops from 0: they vectorise)."""
    c = _coefficients(piece, 0)
    uu, y0, y1, y2 = u[j : j + m], ys[0, j : j + m], ys[1, j : j + m], ys[2, j : j + m]
    for e in range(m):
        a0, a1, a2, _ = _horner_rows(c, uu[e])
        y0[e] = a0
        y1[e] = a1
        y2[e] = a2


@jit(contract=True)
def _span_a(piece, u, ys, j, m):
    """The attitude ``a`` on one piece at ``u[j : j+m]`` into ``ys[7:11, j : j+m]`` (as the momentum).

    Only the polynomials: per span LLVM checks every pair of the loop's arrays for overlap
    before its vector loop, and the spans are short (~30 epochs), so the momentum and the
    attitude that follow from ``a`` are formed afterwards over the whole block (:func:`_from_a`).
    """
    ca = _coefficients(piece, 0)
    uu, a0, a1, a2, a3 = u[j : j + m], ys[7, j : j + m], ys[8, j : j + m], ys[9, j : j + m], ys[10, j : j + m]
    for e in range(m):
        a0[e], a1[e], a2[e], a3[e] = _horner_rows(ca, uu[e])


@jit(contract=True)
def _from_a(ys, sb, cb, frame, nb, attitude):
    """From ``a`` in ``ys[7:11, :nb]``: the momentum into ``ys[0:3]`` (and the attitude into ``ys[3:7]``).

    ``frame`` is ``(Q_x, Q_y, Q_z, Q_w, G)`` (:func:`~andoyer.free.triaxial.periodic.body_momentum`,
    :func:`~andoyer.free.triaxial.periodic.turned`); ``sb``, ``cb`` are ``sin, cos(πg)``.
    """
    qx, qy, qz, qw, g = frame
    a0, a1, a2, a3 = ys[7, :nb], ys[8, :nb], ys[9, :nb], ys[10, :nb]
    y0, y1, y2 = ys[0, :nb], ys[1, :nb], ys[2, :nb]
    z0, z1, z2, z3 = ys[3, :nb], ys[4, :nb], ys[5, :nb], ys[6, :nb]
    ss, cc = sb[:nb], cb[:nb]
    if attitude:
        for e in range(nb):
            x, y, z, w = a0[e], a1[e], a2[e], a3[e]
            y0[e], y1[e], y2[e] = body_momentum(g, x, y, z, w)
            z0[e], z1[e], z2[e], z3[e] = turned(qx, qy, qz, qw, ss[e], cc[e], x, y, z, w)
    else:
        for e in range(nb):
            y0[e], y1[e], y2[e] = body_momentum(g, a0[e], a1[e], a2[e], a3[e])


@jit(contract=True)
def _epochwise(coef, base, xs, us, sb, cb, frame, nb, ys, pieces_a, attitude):
    """Epoch by epoch (short runs): :func:`~andoyer.free.triaxial.periodic.horner`, the same operations."""
    qx, qy, qz, qw, g = frame
    for j in range(nb):
        a0, a1, a2, a3 = horner(coef[int(base + xs[j])], 0, us[j])
        if not pieces_a:
            ys[0, j], ys[1, j], ys[2, j] = a0, a1, a2
            continue
        ys[0, j], ys[1, j], ys[2, j] = body_momentum(g, a0, a1, a2, a3)
        if attitude:
            ys[3, j], ys[4, j], ys[5, j], ys[6, j] = turned(qx, qy, qz, qw, sb[j], cb[j], a0, a1, a2, a3)


@jit(contract=True)
def _sort_by_piece(xs, us, sb, cb, nb, n, attitude, starts, runs, count, order, ub, sbb, cbb):
    """Counting sort of a block's epochs by piece into ``order``, ``ub`` (``sbb``, ``cbb``).

    Leaves ``count[p]`` at the end of piece ``p`` in the sorted order.

    Counted per run of equal pieces (``starts``) where the runs are long (sorted epochs: a
    count per epoch would wait on the previous one's store to the same counter).
    """
    count[: n + 1] = 0
    if _SHORT * runs <= nb:
        for r in range(runs):
            count[int(xs[starts[r]]) + 1] += starts[r + 1] - starts[r]
    else:
        for j in range(nb):
            count[int(xs[j]) + 1] += 1
    for p in range(n):
        count[p + 1] += count[p]
    if _SHORT * runs <= nb:
        for r in range(runs):
            j, k = starts[r], starts[r + 1]
            x = int(xs[j])
            d = count[x]
            count[x] = d + (k - j)
            for e in range(k - j):
                order[d + e] = j + e
                ub[d + e] = us[j + e]
            if attitude:
                for e in range(k - j):
                    sbb[d + e] = sb[j + e]
                    cbb[d + e] = cb[j + e]
    else:
        for j in range(nb):
            x = int(xs[j])
            d = count[x]
            count[x] = d + 1
            order[d] = j
            ub[d] = us[j]
        if attitude:
            for d in range(nb):
                sbb[d] = sb[order[d]]
                cbb[d] = cb[order[d]]


# outputs this large are written past the caches (:func:`_stream`); measured, the fill and one read of its
# output: slower below ~8 MB (the output would have stayed in the 32 MB L3), faster from ~11 MB
_STREAM_BYTES = 1 << 23


def _stream(flat, i, value):
    """``flat[i] = value``; in compiled kernels a non-temporal store (LLVM's ``!nontemporal``).

    A store that bypasses the caches: the processor need not read each line of the output
    before writing it, which halves the memory traffic of outputs larger than the caches
    (writing 56 MB of momenta and attitudes in order: 3.6 → 1.3 ms).  Same value either way.
    """
    flat[i] = value


def _stream_fence():
    """Orders the stores of :func:`_stream` before any later store (a fence; nothing in Python)."""


@when_compiled
def _compiled_stream(overload):
    from llvmlite import ir
    from numba.core import types
    from numba.extending import intrinsic

    @intrinsic
    def _nontemporal(typingctx, flat, i, value):  # noqa: ARG001 - numba's intrinsic signature
        if not (isinstance(flat, types.Array) and flat.ndim == 1 and flat.layout == "C"):
            return None

        def codegen(context, builder, sig, args):
            ary = context.make_array(sig.args[0])(context, builder, args[0])
            ptr = builder.gep(ary.data, [args[1]])
            val = context.cast(builder, args[2], sig.args[2], sig.args[0].dtype)
            store = builder.store(val, ptr)
            store.set_metadata("nontemporal", builder.module.add_metadata([ir.Constant(ir.IntType(32), 1)]))
            return context.get_dummy_value()

        return types.void(flat, i, value), codegen

    @intrinsic
    def _fence(typingctx):  # noqa: ARG001 - numba's intrinsic signature
        def codegen(context, builder, sig, args):  # noqa: ARG001 - numba's codegen signature
            builder.fence("seq_cst")
            return context.get_dummy_value()

        return types.void(), codegen

    @overload(_stream)
    def _stream_compiled(flat, i, value):  # noqa: ARG001 - numba's overload signature
        return lambda flat, i, value: _nontemporal(flat, i, value)  # noqa: PLW0108 - numba wants Python

    @overload(_stream_fence)
    def _stream_fence_compiled():
        return lambda: _fence()  # noqa: PLW0108 - numba wants a Python implementation


@jit(inline=True)
def _copy_out(ys, nb, m_out, q_out, o, e0, attitude, flat_m, flat_q, stream):
    """``ys[:, :nb]`` into the outputs' row ``o`` from epoch ``e0`` (``stream``: through their flat views)."""
    if stream:
        b = (o * m_out.shape[1] + e0) * 3
        for j in range(nb):
            _stream(flat_m, b + 3 * j, ys[0, j])
            _stream(flat_m, b + 3 * j + 1, ys[1, j])
            _stream(flat_m, b + 3 * j + 2, ys[2, j])
        if attitude:
            b = (o * m_out.shape[1] + e0) * 4
            for j in range(nb):
                _stream(flat_q, b + 4 * j, ys[3, j])
                _stream(flat_q, b + 4 * j + 1, ys[4, j])
                _stream(flat_q, b + 4 * j + 2, ys[5, j])
                _stream(flat_q, b + 4 * j + 3, ys[6, j])
        return
    for j in range(nb):
        m_out[o, e0 + j, 0] = ys[0, j]
        m_out[o, e0 + j, 1] = ys[1, j]
        m_out[o, e0 + j, 2] = ys[2, j]
    if attitude:
        for j in range(nb):
            q_out[o, e0 + j, 0] = ys[3, j]
            q_out[o, e0 + j, 1] = ys[4, j]
            q_out[o, e0 + j, 2] = ys[5, j]
            q_out[o, e0 + j, 3] = ys[6, j]


@jit(inline=True)
def _scatter_out(ys, order, nb, m_out, q_out, o, e0, attitude):
    """``ys[:, d]`` into the outputs' row ``o`` at epoch ``e0 + order[d]``."""
    for d in range(nb):
        e = e0 + order[d]
        m_out[o, e, 0] = ys[0, d]
        m_out[o, e, 1] = ys[1, d]
        m_out[o, e, 2] = ys[2, d]
    if attitude:
        for d in range(nb):
            e = e0 + order[d]
            q_out[o, e, 0] = ys[3, d]
            q_out[o, e, 1] = ys[4, d]
            q_out[o, e, 2] = ys[5, d]
            q_out[o, e, 3] = ys[6, d]


@jit(contract=True)
def _fill(params, coef, pieces_a, pos, rows, t, m_out, q_out, attitude, flat_m, flat_q, stream):
    """Blocks of :data:`_BLOCK` epochs per state: phases, then the polynomials piece by piece, then outputs.

    ``pieces_a``: the pieces hold the attitude ``a`` relative to the momentum's frame (the
    momentum follows from it), else the momentum.  Epochs on one piece are evaluated
    together as vectors (spans), their coefficients held
    in registers: the block sorted by piece when it holds :data:`_BUCKET` epochs a piece or
    more (unless the epochs come in long runs on one piece: then the runs are evaluated
    in place), else its runs of consecutive epochs on one piece, else (short runs) epoch
    by epoch.  Outputs of :data:`_STREAM_BYTES` or more are written by non-temporal stores
    (``stream``, through their flat views ``flat_m``, ``flat_q``).  Each span covers a whole number of
    :data:`_LANES` epochs; the excess is overwritten by the next span (the buffers are
    padded).  Every epoch gets the same operations as alone, so the values do not depend
    on the other epochs nor on their order.  (The spans are evaluated here only, so that
    their code is compiled once.)
    """
    per_row = t.shape[0] > 1
    ne = t.shape[1]
    size = _BLOCK + _LANES
    xs, us, ub = np.zeros(size), np.zeros(size), np.zeros(size)
    sb, cb, sbb, cbb = np.zeros(size), np.zeros(size), np.zeros(size), np.zeros(size)
    order, starts = np.arange(size), np.zeros(size + 1, dtype=np.int64)
    span_piece, span_start, span_end = (np.zeros(size, dtype=np.int64), np.zeros(size, dtype=np.int64),
                                        np.zeros(size, dtype=np.int64))
    ys, yo = np.empty((11, size)), np.empty((7, size))
    most = 1
    for i in range(rows.size):
        most = max(most, int(params[pos[i], 6]))
    count = np.zeros(most + 1, dtype=np.int64)
    for i in range(rows.size):
        r, o = pos[i], rows[i]
        nu_hi, nu_lo, f0 = params[r, 0], params[r, 1], params[r, 2]
        g_hi, g_lo, g0 = params[r, 3], params[r, 4], params[r, 5]
        n, base = params[r, 6], params[r, 7]
        frame = (params[r, 8], params[r, 9], params[r, 10], params[r, 11], params[r, 12])
        tr = o if per_row else 0
        for e0 in range(0, ne, _BLOCK):
            nb = min(_BLOCK, ne - e0)
            tb = t[tr, e0 : e0 + nb]
            _phases(tb, nu_hi, nu_lo, f0, n, xs[:nb], us[:nb])
            if attitude:
                _half_angles(tb, g_hi, g_lo, g0, sb[:nb], cb[:nb])
            runs = 0
            for j in range(1, nb):  # the starts of the runs, branch-free (sorted epochs: 0.68 -> 0.44 ms)
                starts[runs + 1] = j
                runs += xs[j] != xs[j - 1]
            runs += 1
            starts[runs] = nb
            long_runs = nb >= _LONG * runs  # sorted epochs: no sort needed (measured)
            sorted_ = not long_runs and nb >= _BUCKET * n
            if sorted_:
                _sort_by_piece(xs, us, sb, cb, nb, int(n), attitude, starts, runs, count, order, ub, sbb, cbb)
                spans, start = 0, 0
                for p in range(int(n)):
                    if count[p] > start:
                        span_piece[spans], span_start[spans], span_end[spans] = p, start, count[p]
                        spans += 1
                    start = count[p]
                u, s, c = ub, sbb, cbb
            elif nb >= _SHORT * runs:
                spans = runs
                for k in range(runs):
                    span_piece[k], span_start[k], span_end[k] = int(xs[starts[k]]), starts[k], starts[k + 1]
                u, s, c = us, sb, cb
            else:
                _epochwise(coef, base, xs, us, sb, cb, frame, nb, ys, pieces_a, attitude)
                _copy_out(ys, nb, m_out, q_out, o, e0, attitude, flat_m, flat_q, stream)
                continue
            for k in range(spans):
                j = span_start[k]
                m = (span_end[k] - j + _LANES - 1) // _LANES * _LANES
                piece = coef[int(base) + span_piece[k]]
                if pieces_a:
                    _span_a(piece, u, ys, j, m)
                else:
                    _span_momentum(piece, u, ys, j, m)
            if pieces_a:
                _from_a(ys, s, c, frame, nb, attitude)
            if not sorted_:
                _copy_out(ys, nb, m_out, q_out, o, e0, attitude, flat_m, flat_q, stream)
            elif nb >= _SHORT * runs:  # runs: the outputs are written run by run, nearly in sequence
                _scatter_out(ys, order, nb, m_out, q_out, o, e0, attitude)
            else:  # scattered epochs: back to their order in the cache, then written in sequence (measured)
                for k in range(7 if attitude else 3):
                    yk, zk = ys[k], yo[k]
                    for d in range(nb):
                        zk[order[d]] = yk[d]
                _copy_out(yo, nb, m_out, q_out, o, e0, attitude, flat_m, flat_q, stream)
    if stream:
        _stream_fence()


def fill(const, pos, rows, t, scale, outs):
    """Evaluate a ``Periodic`` group into the outputs of :func:`~andoyer.free.common.blocks.evaluate_blocks`.

    One compiled loop over states and epochs (plain Python without numba).

    Parameters
    ----------
    const : Periodic
        The representation.
    pos, rows : ndarray of int, shape (r,)
        States (rows of ``const.params``) and the output rows they fill.
    t : ndarray, shape (rows_out, e) or (1, e)
        Unscaled times, per output row or shared.
    scale : tuple
        Ignored: the scalings are folded into ``const``.
    outs : tuple of ndarray
        ``m_out`` of shape ``(rows_out, e, 3)`` and ``q_out`` of shape ``(rows_out, e, 4)`` or None.

    Examples
    --------
    >>> from andoyer.free import FreeMotion
    >>> fm = FreeMotion([1.0, 2.0, 3.0], [0.3, 0.2, 1.0])
    >>> from andoyer.free.triaxial.periodic_numpy import build
    >>> per, _ = build(fm._groups[0], attitude=False)
    >>> m = np.empty((1, 1, 3))
    >>> fill(per.const, np.array([0]), np.array([0]), np.zeros((1, 1)), None, (m, None))
    >>> m.round(14).tolist()
    [[[0.3, 0.2, 1.0]]]
    """
    del scale
    m_out, q_out = outs
    attitude = q_out is not None
    if attitude and not const.attitude:
        raise ValueError("expected a representation built with the attitude, got one of the momentum alone")
    q = q_out if attitude else np.empty((0, 0, 4))
    stream = m_out.nbytes + q.nbytes >= _STREAM_BYTES and m_out.flags.c_contiguous and q.flags.c_contiguous
    flat_m, flat_q = (m_out.reshape(-1), q.reshape(-1)) if stream else (np.empty(0), np.empty(0))
    _fill(const.params, const.coef, const.attitude, np.asarray(pos, dtype=np.intp),
          np.asarray(rows, dtype=np.intp), t, m_out, q, attitude, flat_m, flat_q, stream)
