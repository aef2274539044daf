r"""Many epochs per body: the triaxial solution as piecewise polynomials of its two phases.

The torque-free motion of a triaxial body is periodic up to a precession: with the
polhode phase ``f = f₀ + ν t`` and the secular phase ``g = g₀ + ν_ψ t`` (both in cycles,
double-double frequencies, reduced to ``[−1/2, 1/2)`` as in :mod:`andoyer.free.phase`),

.. math:: m(t) = M(f), \qquad q(t) = \cos(\pi g)\,A(f) + \sin(\pi g)\,B(f),

where ``M``, ``A``, ``B`` are periodic in ``f``: the attitude of
:func:`andoyer.free.quaternion.anchored_attitude` is ``(Q_u cos Φ + Q_v sin Φ) ⊗ b(f)``
with ``Φ = πg + P(f)``, so ``A = (Q_u cos P + Q_v sin P) ⊗ b`` and
``B = (Q_v cos P − Q_u sin P) ⊗ b``.  Since ``Q_v = n ⊗ Q_u`` with ``n`` the unit vector of
the angular momentum in the reference frame (:func:`andoyer.free.regime.attitude_anchor`:
``V = Q₀ ⊗ e_z ⊗ P``, ``U = Q₀ ⊗ P``), ``B = n ⊗ A`` and

.. math:: q(t) = (\sin(\pi g)\,n,\ \cos(\pi g)) \otimes A(f),

one rotation about ``n`` after ``A``.  :func:`build` samples ``M`` (and ``A``) once per
body through the existing kernels, run with the frequencies replaced by ``ν = 1, f₀ = 0``
(so that their time is the phase) and ``g = 0``, takes ``n = V ⊗ U*`` from the anchor,
and fits a polynomial of degree :data:`DEGREE` in each of ``n`` equal
pieces of the period (values at Chebyshev nodes, then Chebyshev coefficients, then monomial
ones).  ``n`` starts from the nome (the poles of ``sn, cn, dn`` lie ``K'/(4K)`` cycles
off the real axis) and doubles until the pieces agree with the kernels at the ends and
between the nodes of every piece to 32 ulps, or until doubling stops helping (the kernels'
own rounding, up to ~40 ulps near the separatrix); a body that would need more than
:data:`MAX_PIECES` keeps the direct evaluation.

Per epoch the evaluation then costs the two reduced phases, ``3`` (momentum) or ``7``
(with ``A``) polynomials, one ``sincos`` and one product (:func:`fill`, compiled, and
:func:`fill_numpy`, vectorised; both call :mod:`andoyer.free.kernels.piecewise`).  The
compiled fill evaluates the epochs that fall on one piece together, in blocks sorted by
piece (a counting sort), so that the polynomials run as vectors over epochs with their
coefficients in registers; each epoch still gets the same operations as alone.  The
pieces break at ``f = 0, ±1/4, ±1/2`` (``n`` is a power of two ``≥ 4``), where the
hyperbolic series of the kernels switch branch.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from andoyer._jit import NUMBA, jit, when_compiled
from andoyer._quaternion import product
from andoyer.free import compiled_eval as _ceval
from andoyer.free import constants as _const
from andoyer.free.blocks import _CHUNK, Group, evaluate_blocks
from andoyer.free.compiled_setup import as_triaxial
from andoyer.free.kernels.piecewise import DEGREE, horner, locate
from andoyer.free.phase import cycles, frequency, sincos_cycles
from andoyer.free.table import FRAC0, NU, NU_PSI, PSI0
from andoyer.special.compensated import two_prod

__all__ = ["DEGREE", "MAX_PIECES", "Periodic", "build", "evaluate", "fill", "fill_numpy"]

#: Most pieces per period; bodies that need more keep the direct evaluation.
MAX_PIECES = 1 << 15
_NODES = DEGREE + 1
_TOL = 32.0  # accepted deviation of the pieces from the kernels (ulps of the scale; the kernels carry a few)
_FLOOR = 2e-14  # accepted where more pieces no longer help (the kernels' own rounding)
# Chebyshev nodes of the first kind on [-1, 1] and the maps values -> Chebyshev -> monomial
_U = np.cos(np.pi * (np.arange(_NODES) + 0.5) / _NODES)
_TO_CHEB = np.cos(np.pi * np.outer(np.arange(_NODES), np.arange(_NODES) + 0.5) / _NODES) * (2.0 / _NODES)
_TO_CHEB[0] *= 0.5

def _chebyshev_monomials(n):
    """Column ``k``: the monomial coefficients of ``Tₖ`` (``T_{k+1} = 2u Tₖ − T_{k−1}``; exact integers)."""
    out = np.zeros((n, n))
    out[0, 0] = 1.0
    out[1, 1] = 1.0
    for k in range(1, n - 1):
        out[1:, k + 1] = 2.0 * out[:-1, k]
        out[:, k + 1] -= out[:, k - 1]
    return out


_TO_MONO = _chebyshev_monomials(_NODES)
_CHECK = np.array([-1.0, -0.5, 0.0, 0.5, 1.0])  # where the pieces are compared with the kernels
_POWERS = _CHECK[:, None] ** np.arange(_NODES)


class Periodic(NamedTuple):
    """Piecewise-polynomial representation of triaxial states (:func:`build`).

    Attributes
    ----------
    params : ndarray, shape (N, 11)
        Per state: ``ν`` (hi, lo) and ``f₀``, ``ν_ψ`` (hi, lo) and ``g₀`` (frequencies
        in cycles per unscaled time), the number of pieces ``n`` and the first row of its
        pieces in ``coef`` (as floats), then the unit vector ``n`` of the angular momentum
        in the reference frame (zeros without the attitude).
    coef : ndarray, shape (rows, DEGREE + 1, 4 or 8)
        Monomial coefficients of ``M`` (unscaled momentum, and a component of zeros), then ``A``.
    """

    params: np.ndarray
    coef: np.ndarray


def _first_pieces(const):
    """Initial number of pieces from the nome: ``n ≈ 8/ρ`` with ``ρ = K'/(4K)``, a power of 2 ≥ 8.

    ``−ln q = πK'/K`` for the circular nome; the hyperbolic series carry the
    complementary nome ``q'``, with ``ln q ln q' = π²``.
    """
    lq = -np.log(np.asarray(const.q, dtype=np.float64))
    lq = np.where(np.asarray(const.circular), lq, np.pi**2 / lq)
    rho = lq / (4.0 * np.pi)
    want = np.clip(8.0 / rho, 8.0, MAX_PIECES)  # most bodies pass at once (16/ρ: twice the pieces needed)
    return np.exp2(np.ceil(np.log2(want)))


def _node_group(group, g0):
    """The group's kernel with ``ν = 1, f₀ = 0`` and the secular phase held at ``g₀``."""
    const = group.const
    if group.kernel is _ceval.evaluate:
        table = np.array(const, copy=True)
        table[:, NU : NU + 4] = (1.0, 0.0, 1.0, 0.0)  # hi, lo, hh, hl
        table[:, FRAC0] = 0.0
        table[:, NU_PSI : NU_PSI + 4] = 0.0
        table[:, PSI0] = g0
        const = table
    else:
        one = np.ones_like(const.frac0)
        const = const._replace(
            nu=frequency(one), frac0=0.0 * one, nu_psi=frequency(0.0 * one), psi0=g0 * one
        )
    size = group.members.size
    return Group(group.kernel, np.arange(size), const, np.zeros(size, dtype=np.int64), group.mshift)


def _sample(group, sel, pieces, attitude):
    """Values ``(M, A)`` of states ``sel`` at the nodes of ``pieces`` pieces (and checks).

    Returns the values at the nodes, shape ``(s, pieces, NODES, c)``, and at the check
    points, shape ``(s, pieces, len(_CHECK), c)``.
    """
    u = np.concatenate([_U, _CHECK])
    f = -0.5 + (np.arange(pieces)[:, None] + 0.5 * (u + 1.0)) / pieces
    f = np.broadcast_to(f.ravel(), (sel.size, f.size))
    node = _node_group(group, 0.0)
    node = Group(node.kernel, np.arange(sel.size), _rows_of(node.const, sel, group.kernel),
                 node.tshift[sel], node.mshift[sel])
    m, q = evaluate_blocks([node], (sel.size, 1), f, attitude)
    comps = [m, np.zeros_like(m[..., :1])] + ([q] if attitude else [])  # momentum padded to four components
    vals = np.concatenate(comps, axis=-1).reshape(sel.size, pieces, u.size, -1)
    return vals[:, :, :_NODES], vals[:, :, _NODES:]


def _rows_of(const, sel, kernel):
    return const[sel] if kernel is _ceval.evaluate else _const.subset(const, sel)


def _fit(values):
    """Monomial coefficients in ``u`` from values at the Chebyshev nodes (axis −2 of ``values``)."""
    cheb = np.matmul(_TO_CHEB, values)  # (NODES, NODES) @ (..., NODES, c): one small product per piece
    return np.matmul(_TO_MONO, cheb)


def _pieces_for(group, attitude):
    """Coefficients per state of a triaxial group: list of arrays or None (too many pieces).

    The number of pieces doubles until the pieces agree with the kernels to :data:`_TOL`
    ulps, or until a doubling no longer helps (the truncation error falls by ``2^{DEGREE+1}``
    per doubling, the kernels' own rounding does not): then the previous pieces are kept if
    within :data:`_FLOOR`.
    """
    const = as_triaxial(group.const) if group.kernel is _ceval.evaluate else group.const
    pieces = _first_pieces(const)
    size = group.members.size
    out = [None] * size
    prev = [None] * size  # (error, coefficients) at half the pieces
    todo = np.arange(size)
    eps = np.finfo(float).eps
    while todo.size:
        nxt = []
        for n in np.unique(pieces[todo]):
            sel = todo[pieces[todo] == n]
            nodes, checks = _sample(group, sel, int(n), attitude)
            coef = _fit(nodes)  # (s, n, NODES, c)
            approx = np.matmul(_POWERS, coef)  # (s, n, len(_CHECK), c)
            scale = np.max(np.abs(nodes), axis=(1, 2))  # (s, c)
            scale[:, 3:] = 1.0  # quaternion components: absolute (and the padding)
            err = np.max(np.abs(approx - checks) / scale[:, None, None], axis=(1, 2, 3))
            for j, s in enumerate(sel):
                if err[j] <= _TOL * eps:
                    out[s] = coef[j]
                elif prev[s] is not None and err[j] > 0.25 * prev[s][0]:  # at the rounding floor
                    if prev[s][0] <= _FLOOR:
                        out[s] = prev[s][1]
                elif n < MAX_PIECES:
                    prev[s] = (err[j], coef[j])
                    pieces[s] = 2 * n
                    nxt.append(s)
        todo = np.array(nxt, dtype=np.int64)
    return out, const


def _axis(const, sel):
    """Unit vector ``n = V ⊗ U*`` of the angular momentum in the reference frame, per state ``sel``.

    From the attitude's anchor (:func:`andoyer.free.regime.attitude_anchor`: ``U = Q₀ ⊗ P``,
    ``V = Q₀ ⊗ e_z ⊗ P``, so ``V ⊗ U* = Q₀ e_z Q₀*``, a pure unit quaternion).
    """
    u = np.asarray(const.quat_u)[:, sel]
    v = np.asarray(const.quat_v)[:, sel]
    return np.stack(product(*v, -u[0], -u[1], -u[2], u[3])[:3], axis=1)


def build(group, attitude):
    """Piecewise representation of a group of triaxial states, and the states left out.

    Parameters
    ----------
    group : andoyer.free.blocks.Group
        A triaxial group of :class:`andoyer.free.FreeMotion` (compiled table or numpy
        :class:`~andoyer.free.triaxial.Triaxial` constants).
    attitude : bool
        Also represent the attitude.

    Returns
    -------
    periodic : andoyer.free.blocks.Group or None
        The states represented, evaluated by :func:`evaluate`.
    rest : andoyer.free.blocks.Group or None
        The states that keep the direct evaluation (more than :data:`MAX_PIECES` pieces).

    Examples
    --------
    >>> from andoyer.free import FreeMotion
    >>> fm = FreeMotion([1.0, 2.0, 3.0], [0.3, 0.2, 1.0])
    >>> per, rest = build(fm._groups[0], attitude=False)
    >>> per.const.coef.shape[1:], rest  # degree 9, the momentum and a padding component
    ((10, 4), None)
    """
    coefs, const = _pieces_for(group, attitude)
    keep = np.array([c is not None for c in coefs])
    rest = None
    if not np.all(keep):
        sel = np.nonzero(~keep)[0]
        rest = Group(group.kernel, group.members[sel], _rows_of(group.const, sel, group.kernel),
                     group.tshift[sel], group.mshift[sel])
    sel = np.nonzero(keep)[0]
    if sel.size == 0:
        return None, rest
    n = np.array([coefs[s].shape[0] for s in sel], dtype=np.float64)
    base = np.concatenate([[0.0], np.cumsum(n)[:-1]])
    coef = np.ascontiguousarray(np.concatenate([coefs[s] for s in sel]))
    ts = group.tshift[sel]
    params = np.stack(
        [
            np.ldexp(np.asarray(const.nu.hi)[sel], ts),  # exact: the time scaling is a power of two
            np.ldexp(np.asarray(const.nu.lo)[sel], ts),
            np.asarray(const.frac0)[sel],
            np.ldexp(np.asarray(const.nu_psi.hi)[sel], ts),
            np.ldexp(np.asarray(const.nu_psi.lo)[sel], ts),
            np.asarray(const.psi0)[sel],
            n,
            base,
        ],
        axis=1,
    )
    if attitude:
        params = np.concatenate([params, _axis(const, sel)], axis=1)
    else:
        params[:, 3:6] = 0.0  # the table may lack them (no attitude asked)
        params = np.concatenate([params, np.zeros((sel.size, 3))], axis=1)
    periodic = Group(evaluate, group.members[sel], Periodic(params, coef), np.zeros(sel.size, dtype=np.int64),
                     np.zeros(sel.size, dtype=np.int64))
    return periodic, rest


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

    Written out for ``DEGREE = 9`` (ten rows; ``tests/free/test_free_periodic.py`` checks it).
    """
    return (_row(piece, 0, k), _row(piece, 1, k), _row(piece, 2, k), _row(piece, 3, k), _row(piece, 4, k),
            _row(piece, 5, k), _row(piece, 6, k), _row(piece, 7, k), _row(piece, 8, k), _row(piece, 9, k))


@jit(inline=True)
def _horner_rows(c, u):
    """:func:`~andoyer.free.kernels.piecewise.horner` on rows of :func:`_coefficients` (same operations)."""
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
        s, c = sincos_cycles(0.5 * _reduced(g_hi, g_lo, g0, t[j]))
        s_out[j] = s
        c_out[j] = c


@jit
def _span_momentum(piece, u, ys, j, m):
    """Momentum on one piece at ``u[j : j+m]`` into ``ys[0:3, j : j+m]`` (loops from 0: they vectorise)."""
    c = _coefficients(piece, 0)
    uu, y0, y1, y2 = u[j : j + m], ys[0, j : j + m], ys[1, j : j + m], ys[2, j : j + m]
    for e in range(m):
        a0, a1, a2, _ = _horner_rows(c, uu[e])
        y0[e] = a0
        y1[e] = a1
        y2[e] = a2


@jit(inline=True)
def _turn(nx, ny, nz, s, c, a0, a1, a2, a3):
    """``(s n, c) ⊗ A``: the rotation by ``2πg`` about ``n`` after ``A`` (``s, c = sin, cos(πg)``)."""
    return product(s * nx, s * ny, s * nz, c, a0, a1, a2, a3)


@jit
def _span_attitude(piece, u, sb, cb, nx, ny, nz, ys, j, m):
    """Attitude ``(sin(πg) n, cos(πg)) ⊗ A(f)`` on one piece into ``ys[3:7, j : j+m]`` (as the momentum)."""
    ca = _coefficients(piece, 4)
    uu, ss, cc = u[j : j + m], sb[j : j + m], cb[j : j + m]
    z0, z1, z2, z3 = ys[3, j : j + m], ys[4, j : j + m], ys[5, j : j + m], ys[6, j : j + m]
    for e in range(m):
        a0, a1, a2, a3 = _horner_rows(ca, uu[e])
        z0[e], z1[e], z2[e], z3[e] = _turn(nx, ny, nz, ss[e], cc[e], a0, a1, a2, a3)


@jit
def _epochwise(coef, base, xs, us, sb, cb, nx, ny, nz, nb, ys, attitude):
    """Epoch by epoch (short runs): :func:`~andoyer.free.kernels.piecewise.horner`, the same operations."""
    for j in range(nb):
        piece = coef[int(base + xs[j])]
        u = us[j]
        ys[0, j], ys[1, j], ys[2, j], _ = horner(piece, 0, u)
        if attitude:
            a0, a1, a2, a3 = horner(piece, 4, u)
            ys[3, j], ys[4, j], ys[5, j], ys[6, j] = _turn(nx, ny, nz, sb[j], cb[j], a0, a1, a2, a3)


@jit
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


@jit
def _fill(params, coef, pos, rows, t, m_out, q_out, attitude, flat_m, flat_q, stream):
    """Blocks of :data:`_BLOCK` epochs per state: phases, then the polynomials piece by piece, then outputs.

    Epochs on one piece are evaluated together as vectors (spans), their coefficients held
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
    ys, yo = np.empty((7, size)), np.empty((7, size))
    most = 1
    for i in range(rows.size):
        most = max(most, int(params[pos[i], 6]))
    count = np.zeros(most + 1, dtype=np.int64)
    for i in range(rows.size):
        r, o = pos[i], rows[i]
        nu_hi, nu_lo, f0 = params[r, 0], params[r, 1], params[r, 2]
        g_hi, g_lo, g0 = params[r, 3], params[r, 4], params[r, 5]
        n, base = params[r, 6], params[r, 7]
        nx, ny, nz = params[r, 8], params[r, 9], params[r, 10]
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
                _epochwise(coef, base, xs, us, sb, cb, nx, ny, nz, nb, ys, attitude)
                _copy_out(ys, nb, m_out, q_out, o, e0, attitude, flat_m, flat_q, stream)
                continue
            for k in range(spans):
                j = span_start[k]
                m = (span_end[k] - j + _LANES - 1) // _LANES * _LANES
                piece = coef[int(base) + span_piece[k]]
                _span_momentum(piece, u, ys, j, m)
                if attitude:
                    _span_attitude(piece, u, s, c, nx, ny, nz, ys, j, m)
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
    """Evaluate a :class:`Periodic` group into the outputs of :func:`andoyer.free.blocks.evaluate_blocks`.

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
    >>> per, _ = build(fm._groups[0], attitude=False)
    >>> m = np.empty((1, 1, 3))
    >>> fill(per.const, np.array([0]), np.array([0]), np.zeros((1, 1)), None, (m, None))
    >>> m.round(14).tolist()
    [[[0.3, 0.2, 1.0]]]
    """
    del scale
    m_out, q_out = outs
    attitude = q_out is not None
    q = q_out if attitude else np.empty((0, 0, 4))
    stream = m_out.nbytes + q.nbytes >= _STREAM_BYTES and m_out.flags.c_contiguous and q.flags.c_contiguous
    flat_m, flat_q = (m_out.reshape(-1), q.reshape(-1)) if stream else (np.empty(0), np.empty(0))
    _fill(const.params, const.coef, np.asarray(pos, dtype=np.intp), np.asarray(rows, dtype=np.intp),
          t, m_out, q, attitude, flat_m, flat_q, stream)


def fill_numpy(const, pos, rows, t, scale, outs):
    """:func:`fill` with numpy arrays, in blocks of states × epochs (the path without numba).

    Parameters and examples as :func:`fill`.

    Examples
    --------
    >>> from andoyer.free import FreeMotion
    >>> fm = FreeMotion([1.0, 2.0, 3.0], [0.3, 0.2, 1.0])
    >>> per, _ = build(fm._groups[0], attitude=False)
    >>> m = np.empty((1, 1, 3))
    >>> fill_numpy(per.const, np.array([0]), np.array([0]), np.zeros((1, 1)), None, (m, None))
    >>> m.round(14).tolist()
    [[[0.3, 0.2, 1.0]]]
    """
    del scale
    m_out, q_out = outs
    params, coef = const.params, const.coef
    ncols = t.shape[1]
    cstep = min(ncols, _CHUNK)
    rstep = max(1, _CHUNK // cstep)
    per_row = t.shape[0] > 1
    for r0 in range(0, rows.size, rstep):
        o = rows[r0 : r0 + rstep]
        p = params[pos[r0 : r0 + rstep]].T[..., None]  # (11, r, 1)
        nu, g_nu = frequency(p[0], p[1]), frequency(p[3], p[4])
        for c0 in range(0, ncols, cstep):
            cols = slice(c0, c0 + cstep)
            tk = t[o, cols] if per_row else t[:, cols]
            x, u = locate(cycles(nu, tk, offset=p[2]), p[6])
            piece = np.moveaxis(coef[(p[7] + x).astype(np.intp)], (-2, -1), (0, 1))
            m_out[o, cols] = np.stack(horner(piece, 0, u)[:3], axis=-1)
            if q_out is not None:
                sb, cb = sincos_cycles(0.5 * cycles(g_nu, tk, offset=p[5]))
                q_out[o, cols] = np.stack(_turn(p[8], p[9], p[10], sb, cb, *horner(piece, 4, u)), axis=-1)


def evaluate(const, rows, t, attitude=True):
    """Body angular momentum and attitude of :class:`Periodic` states at unscaled times ``t``.

    Parameters
    ----------
    const : Periodic
        The representation.
    rows : ndarray of int, shape (r,)
        States to evaluate.
    t : ndarray, shape (r, e) or (1, e)
        Times, per state or shared.
    attitude : bool, optional
        Also return the attitude quaternion components.

    Returns
    -------
    m : tuple of 3 ndarray, shape (r, e)
    q : tuple of 4 ndarray, shape (r, e), or None

    Examples
    --------
    >>> from andoyer.free import FreeMotion
    >>> fm = FreeMotion([1.0, 2.0, 3.0], [0.3, 0.2, 1.0])
    >>> per, _ = build(fm._groups[0], attitude=False)
    >>> m, _ = evaluate(per.const, np.array([0]), np.zeros((1, 2)), attitude=False)
    >>> np.round(m, 14).tolist()
    [[[0.3, 0.3]], [[0.2, 0.2]], [[1.0, 1.0]]]
    """
    rows = np.asarray(rows, dtype=np.intp)
    t = np.asarray(t, dtype=np.float64)
    m = np.empty((rows.size, t.shape[1], 3))
    q = np.empty((rows.size, t.shape[1], 4)) if attitude else None
    out_rows = np.arange(rows.size)
    _FILL(const, rows, out_rows, t, None, (m, q))
    m = tuple(np.moveaxis(m, -1, 0))
    return m, (tuple(np.moveaxis(q, -1, 0)) if attitude else None)


_FILL = fill if NUMBA else fill_numpy
evaluate.fill = _FILL  # andoyer.free.blocks fills its outputs through this
