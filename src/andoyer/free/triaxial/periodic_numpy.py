r"""Many epochs per body: the triaxial solution as piecewise polynomials of its two phases (numpy driver).

The torque-free motion of a triaxial body is periodic up to a precession: with the
polhode phase ``f = f₀ + ν t`` and the secular phase ``g = g₀ + ν_ψ t`` (both in cycles,
double-double frequencies, reduced to ``[−1/2, 1/2)`` as in :mod:`andoyer.free.common.cycles_numpy`),

.. math:: m(t) = M(f), \qquad q(t) = \cos(\pi g)\,A(f) + \sin(\pi g)\,B(f),

where ``M``, ``A``, ``B`` are periodic in ``f``: the attitude of
:func:`andoyer.free.common.polhode_numpy.anchored_attitude` is ``(Q_u cos Φ + Q_v sin Φ) ⊗ b(f)``
with ``Φ = πg + P(f)``, so ``A = (Q_u cos P + Q_v sin P) ⊗ b`` and
``B = (Q_v cos P − Q_u sin P) ⊗ b``.  Since ``Q_v = n ⊗ Q_u`` with ``n`` the unit vector of
the angular momentum in the reference frame (:func:`andoyer.free.common.polhode_numpy.attitude_anchor`:
``V = Q₀ ⊗ e_z ⊗ P``, ``U = Q₀ ⊗ P``), ``B = n ⊗ A`` and

.. math:: q(t) = (\sin(\pi g)\,n,\ \cos(\pi g)) \otimes A(f),

one rotation about ``n`` after ``A``.  With any unit quaternion ``Q`` that takes ``e_z`` to
``n`` (:func:`_frame`: the shortest arc) and ``a = Q* ⊗ A``, the attitude relative to the
momentum's frame, ``(s n, c) = Q ⊗ (s e_z, c) ⊗ Q*`` and ``R(q)ᵀ n = R(a)ᵀ e_z``, so

.. math:: q(t) = Q \otimes (\sin(\pi g)\,e_z,\ \cos(\pi g)) \otimes a(f), \qquad
          m(t) = G\,R(a(f))^{\mathsf T} e_z,

the momentum the third row of ``R(a)`` times ``G = |m|``: four periodic components give
both (:func:`andoyer.free.triaxial.periodic.body_momentum`,
:func:`andoyer.free.triaxial.periodic.turned`).  :func:`build` samples ``M`` (or ``a``: the anchor
turned by ``Q*``) once per body through the existing kernels, run with the frequencies replaced by
``ν = 1, f₀ = 0`` (so that their time is the phase) and ``g = 0``, takes ``n = V ⊗ U*`` from the anchor,
and fits ``M`` (the momentum alone) or ``a`` (with the attitude) by a polynomial of degree
:data:`DEGREE` in each of ``n`` equal
pieces of the period (values at Chebyshev nodes, then Chebyshev coefficients, then monomial
ones).  ``n`` starts from the nome (the poles of ``sn, cn, dn`` lie ``K'/(4K)`` cycles
off the real axis) and doubles until the pieces agree with the kernels at the ends and
between the nodes of every piece to 32 ulps, or until doubling stops helping (the kernels'
own rounding, up to ~40 ulps near the separatrix) — with the attitude, ``a`` and the momentum
``G R(a)ᵀ e_z`` derived from the pieces, relative to ``G``; a body that would need more than
:data:`MAX_PIECES` keeps the direct evaluation.

Per epoch the evaluation then costs the reduced phase ``f``, ``3`` polynomials (the momentum
alone) or ``4`` (``a``: the momentum from it), and with the attitude the phase ``g``, one
``sincos`` and one product
(:func:`andoyer.free.triaxial.periodic_compiled.fill`, compiled, and :func:`fill_numpy`,
vectorised; both call the kernels of :mod:`andoyer.free.triaxial.periodic`).  The
compiled fill evaluates the epochs that fall on one piece together, in blocks sorted by
piece (a counting sort), so that the polynomials run as vectors over epochs with their
coefficients in registers; each epoch still gets the same operations as alone.  The
pieces break at ``f = 0, ±1/4, ±1/2`` (``n`` is a power of two ``≥ 4``), where the
hyperbolic series of the kernels switch branch.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from andoyer._jit import NUMBA
from andoyer._quaternion import product
from andoyer.free.common import constants as _const
from andoyer.free.common.blocks import _CHUNK, Group, evaluate_blocks
from andoyer.free.common.cycles import sincos_half_cycles
from andoyer.free.common.cycles_numpy import cycles, frequency
from andoyer.free.common.polhode import shortest_arc
from andoyer.free.triaxial import evaluate_compiled as _ceval
from andoyer.free.triaxial.columns import FRAC0, NU, NU_PSI, PSI0, QUAT_U, QUAT_V
from andoyer.free.triaxial.periodic import DEGREE, body_momentum, horner, locate, turned
from andoyer.free.triaxial.periodic_compiled import fill
from andoyer.free.triaxial.setup_compiled import as_triaxial

__all__ = ["MAX_PIECES", "Periodic", "build", "evaluate", "fill_numpy"]

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
    params : ndarray, shape (N, 13)
        Per state: ``ν`` (hi, lo) and ``f₀``, ``ν_ψ`` (hi, lo) and ``g₀`` (frequencies
        in cycles per unscaled time), the number of pieces ``n`` and the first row of its
        pieces in ``coef`` (as floats), then the momentum's frame ``Q`` (scalar last) and
        ``G = |m|`` (unscaled; zeros without the attitude).
    coef : ndarray, shape (rows, DEGREE + 1, 4)
        Monomial coefficients of ``a`` (with the attitude), else of ``M`` (unscaled
        momentum, and a component of zeros).
    attitude : bool
        Whether the pieces hold ``a`` (and the attitude can be evaluated).
    """

    params: np.ndarray
    coef: np.ndarray
    attitude: bool


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


def _node_group(group, frame_q):
    """The group's kernel with ``ν = 1, f₀ = 0`` and the secular phase held at 0.

    With ``frame_q`` (``Q`` of :func:`_frame`, shape (N, 4)) the anchor ``U, V`` becomes
    ``Q* ⊗ U, Q* ⊗ V``: the attitude, linear in them, is then ``a = Q* ⊗ A`` itself.
    """
    const = group.const
    if group.kernel is _ceval.evaluate:
        table = np.array(const, copy=True)
        table[:, NU : NU + 4] = (1.0, 0.0, 1.0, 0.0)  # hi, lo, hh, hl
        table[:, FRAC0] = 0.0
        table[:, NU_PSI : NU_PSI + 4] = 0.0
        table[:, PSI0] = 0.0
        if frame_q is not None:
            table[:, QUAT_U : QUAT_U + 4] = _relative(frame_q.T, table[:, QUAT_U : QUAT_U + 4])
            table[:, QUAT_V : QUAT_V + 4] = _relative(frame_q.T, table[:, QUAT_V : QUAT_V + 4])
        const = table
    else:
        one = np.ones_like(const.frac0)
        const = const._replace(
            nu=frequency(one), frac0=0.0 * one, nu_psi=frequency(0.0 * one), psi0=0.0 * one
        )
        if frame_q is not None:
            const = const._replace(quat_u=_relative(frame_q.T, const.quat_u.T).T,
                                   quat_v=_relative(frame_q.T, const.quat_v.T).T)
    size = group.members.size
    return Group(group.kernel, np.arange(size), const, np.zeros(size, dtype=np.int64), group.mshift)


def _sample(node, sel, pieces, attitude):
    """Values ``(M, a)`` of states ``sel`` at the nodes of ``pieces`` pieces (and checks).

    Returns the values at the nodes, shape ``(s, pieces, NODES, c)``, and at the check
    points, shape ``(s, pieces, len(_CHECK), c)``.
    """
    u = np.concatenate([_U, _CHECK])
    f = -0.5 + (np.arange(pieces)[:, None] + 0.5 * (u + 1.0)) / pieces
    f = np.broadcast_to(f.ravel(), (sel.size, f.size))
    node = Group(node.kernel, np.arange(sel.size), _rows_of(node.const, sel, node.kernel),
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


def _pieces_for(group, frame):
    """Coefficients per state of a triaxial group: list of arrays or None (too many pieces).

    ``frame``: ``(Q, G)`` of :func:`_frame` to fit ``a`` (with the attitude), or None to fit
    the momentum.  The number of pieces doubles until the pieces agree with the kernels to
    :data:`_TOL` ulps (the components of ``a`` absolutely, the momentum relative to the
    largest value of each component, or with the attitude the momentum derived from ``a``
    relative to ``G``), or until a doubling no longer helps (the truncation error falls by
    ``2^{DEGREE+1}`` per doubling, the kernels' own rounding does not): then the previous
    pieces are kept if within :data:`_FLOOR`.
    """
    const = _table_of(group)
    pieces = _first_pieces(const)
    node = _node_group(group, None if frame is None else frame[0])
    size = group.members.size
    out = [None] * size
    prev = [None] * size  # (error, coefficients) at half the pieces
    todo = np.arange(size)
    eps = np.finfo(float).eps
    while todo.size:
        nxt = []
        for n in np.unique(pieces[todo]):
            sel = todo[pieces[todo] == n]
            nodes, checks = _sample(node, sel, int(n), frame is not None)
            if frame is None:
                coef = _fit(nodes[..., :4])  # (s, n, NODES, 4): the momentum and its padding
                approx = np.matmul(_POWERS, coef)  # (s, n, len(_CHECK), 4)
                scale = np.max(np.abs(nodes[..., :4]), axis=(1, 2))  # (s, 4)
                scale[:, 3] = 1.0  # the padding
                err = np.max(np.abs(approx - checks[..., :4]) / scale[:, None, None], axis=(1, 2, 3))
            else:
                g = frame[1][sel, None, None]
                coef = _fit(nodes[..., 4:])  # a = Q* ⊗ A from the kernels (_node_group)
                approx = np.matmul(_POWERS, coef)
                want = checks[..., 4:]
                mom = np.stack(body_momentum(g, *np.moveaxis(approx, -1, 0)), axis=-1)
                err = np.maximum(np.max(np.abs(approx - want), axis=(1, 2, 3)),
                                 np.max(np.abs(mom - checks[..., :3]), axis=(1, 2, 3)) / g[:, 0, 0])
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


def _relative(q, attitude):
    """``Q* ⊗ A`` of attitudes ``A`` (components on the last axis), ``Q`` components first."""
    return np.stack(product(-q[0], -q[1], -q[2], q[3], *np.moveaxis(attitude, -1, 0)), axis=-1)


def _table_of(group):
    """The group's constants as :class:`~andoyer.free.triaxial.setup_numpy.Triaxial` (compiled or not)."""
    return as_triaxial(group.const) if group.kernel is _ceval.evaluate else group.const


def _axis(const):
    """Unit vector ``n = V ⊗ U*`` of the angular momentum in the reference frame, shape (N, 3).

    From the attitude's anchor (:func:`andoyer.free.common.polhode_numpy.attitude_anchor`:
    ``U = Q₀ ⊗ P``, ``V = Q₀ ⊗ e_z ⊗ P``, so ``V ⊗ U* = Q₀ e_z Q₀*``, a pure unit quaternion).
    """
    u = np.asarray(const.quat_u)
    v = np.asarray(const.quat_v)
    return np.stack(product(*v, -u[0], -u[1], -u[2], u[3])[:3], axis=1)


def _frame(group):
    """The momentum's frame ``Q`` (shape (N, 4), ``R(Q) e_z = n``) and ``G = |m|`` (unscaled, shape (N,)).

    ``Q`` is the shortest arc from ``e_z`` to ``n`` (the inverse of
    :func:`andoyer.free.common.polhode.shortest_arc` of ``n``), or where ``n_z < 0``, that
    from ``−e_z`` after the half turn ``(1, 0, 0, 0)`` about ``x``: regular for every ``n``.
    """
    const = _table_of(group)
    n = _axis(const)
    up = n[:, 2] >= 0.0
    m = np.where(up[:, None], n, -n)
    arc = shortest_arc(m[:, 0], m[:, 1], m[:, 2], np.sqrt(np.sum(m * m, axis=1)))
    x, y, z, w = (np.broadcast_to(c, up.shape) for c in arc)
    turned_x = product(-x, -y, -z, w, 1.0, 0.0, 0.0, 0.0)
    q = np.where(up[:, None], np.stack([-x, -y, -z, w], axis=1), np.stack(turned_x, axis=1))
    return q, np.ldexp(np.asarray(const.G, dtype=np.float64), group.mshift)


def build(group, attitude):
    """Piecewise representation of a group of triaxial states, and the states left out.

    Parameters
    ----------
    group : andoyer.free.common.blocks.Group
        A triaxial group of :class:`andoyer.free.FreeMotion` (compiled table or numpy
        :class:`~andoyer.free.triaxial.setup_numpy.Triaxial` constants).
    attitude : bool
        Also represent the attitude.

    Returns
    -------
    periodic : andoyer.free.common.blocks.Group or None
        The states represented, evaluated by :func:`evaluate`.
    rest : andoyer.free.common.blocks.Group or None
        The states that keep the direct evaluation (more than :data:`MAX_PIECES` pieces).

    Examples
    --------
    >>> from andoyer.free import FreeMotion
    >>> fm = FreeMotion([1.0, 2.0, 3.0], [0.3, 0.2, 1.0])
    >>> per, rest = build(fm._groups[0], attitude=False)
    >>> per.const.coef.shape[1:], rest  # degree 9, the momentum and a padding component
    ((10, 4), None)
    """
    frame = _frame(group) if attitude else None
    coefs, const = _pieces_for(group, frame)
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
        params = np.concatenate([params, frame[0][sel], frame[1][sel, None]], axis=1)
    else:
        params[:, 3:6] = 0.0  # the table may lack them (no attitude asked)
        params = np.concatenate([params, np.zeros((sel.size, 5))], axis=1)
    zeros = np.zeros(sel.size, dtype=np.int64)
    periodic = Group(evaluate, group.members[sel], Periodic(params, coef, attitude), zeros, zeros)
    return periodic, rest


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
    if q_out is not None and not const.attitude:
        raise ValueError("expected a representation built with the attitude, got one of the momentum alone")
    params, coef = const.params, const.coef
    ncols = t.shape[1]
    cstep = min(ncols, _CHUNK)
    rstep = max(1, _CHUNK // cstep)
    per_row = t.shape[0] > 1
    for r0 in range(0, rows.size, rstep):
        o = rows[r0 : r0 + rstep]
        p = params[pos[r0 : r0 + rstep]].T[..., None]  # (13, r, 1)
        nu, g_nu = frequency(p[0], p[1]), frequency(p[3], p[4])
        for c0 in range(0, ncols, cstep):
            cols = slice(c0, c0 + cstep)
            tk = t[o, cols] if per_row else t[:, cols]
            x, u = locate(cycles(nu, tk, offset=p[2]), p[6])
            piece = np.moveaxis(coef[(p[7] + x).astype(np.intp)], (-2, -1), (0, 1))
            a = horner(piece, 0, u)
            if not const.attitude:
                m_out[o, cols] = np.stack(a[:3], axis=-1)
                continue
            m_out[o, cols] = np.stack(body_momentum(p[12], *a), axis=-1)
            if q_out is not None:
                sb, cb = sincos_half_cycles(cycles(g_nu, tk, offset=p[5]))
                q_out[o, cols] = np.stack(turned(p[8], p[9], p[10], p[11], sb, cb, *a), axis=-1)


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
evaluate.fill = _FILL  # andoyer.free.common.blocks fills its outputs through this
