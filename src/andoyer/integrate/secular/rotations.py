r"""The secular method's stepper: exact rotations about the orbit normals, composed to order 2-8.

The averaged equations of :class:`~andoyer.perturbations.averaged_gravity.SecularGravityGradient`,

.. math:: \dot{\mathbf M} = \sum_p c_p\,(\mathbf M\cdot\mathbf k_p(t))\;\mathbf k_p(t)\times\mathbf M,
   \qquad c_p = 2\kappa_p/G^2,

are a sum of flows that are each exact rotations once time is frozen: the term of
perturber ``p`` alone conserves ``M·k_p``, so it turns ``M`` about ``k_p`` at the
constant rate ``c_p (M·k_p)``, by the angle ``θ = c_p (M·k_p) h`` in a time ``h``
(Rodrigues: ``M cos θ + k×M sin θ + k (k·M)(1 − cos θ)``, with
``1 − cos θ = 2 sin²(θ/2)`` for accuracy at small angles). Time is split off as a
flow of its own, ``t → t + h`` at fixed ``M``. The perturbers whose normal does not
move (no node drift, or no inclination) and equals that of the first such perturber,
``k₀``, commute with that time flow and with each other; together with it they form the
*outer* flow ``A``, a rotation about ``k₀`` at the rate ``(Σ c_p)(M·k₀)``. The others
``B_1 … B_m`` (drifting, or fixed about another normal) are rotations about their
normals at the current time. The symmetric Strang step

.. math:: S(h) = A(\tfrac h2)\,B_1(\tfrac h2)\cdots B_{m-1}(\tfrac h2)\,B_m(h)\,
   B_{m-1}(\tfrac h2)\cdots B_1(\tfrac h2)\,A(\tfrac h2)

is of order 2; the palindromic compositions ``S(γ_s h)⋯S(γ_1 h)`` of
:data:`~andoyer.compositions.COMPOSITIONS` raise it to 4, 6 or 8 (the rotations and the
compositions are those of :mod:`andoyer.compositions`, shared with the spin axis).
Consecutive ``A`` halves merge (``A`` is a one-parameter group), so a step of ``s``
stages costs ``s (2m − 1)`` rotations about the ``B`` normals and ``s`` about ``k₀``. Every
rotation conserves ``|M|``; the kernel also rescales ``M`` to ``G`` after each step so that
round-off cannot accumulate in it.
With no ``B`` (Mars and the Sun) the outer flow is the whole flow and one rotation to
each output is exact.

The steps are equal and span ``[0, t_K]``; every output time is reached by one partial
step off the grid (order ``p`` accurate, and not fed back), so dense outputs cost one
step each and do not shorten the grid's step.

The loop is compiled by :func:`andoyer._jit.jit` when numba is installed; the
same source runs interpreted on arrays of states (one Python loop over the steps).
Compiled, a state's loop (:func:`_advance_compiled`) takes ``sin φ`` and ``1 − cos φ`` of
the small rotation angles from short series and the drifting normals by the addition
theorem from their value at the start of each step: the same flows, agreeing with the
interpreted loop to round-off, at half the cost.
Richardson's pair (the runs at ``h`` and ``2h`` of :func:`propagate_controlled`) goes
through one compiled loop that takes each coarse step beside the fine one it spans
(:func:`_advance_pair`): the two chains of dependent operations overlap in the processor,
each with exactly its own operations (the results are those of two separate runs, bit for
bit), and the pair costs ~1.2 fine runs instead of 1.5.
"""

from __future__ import annotations

import functools
import math

import numpy as np
from numpy.typing import NDArray

from andoyer._jit import NUMBA, jit
from andoyer.compositions import COMPOSITIONS, turn_about, turn_about_series

__all__ = ["propagate_controlled", "propagate_rotations"]

Array = NDArray[np.float64]

_EPSILON = float(np.finfo(float).eps)
_MAX_ANGLE = 2.0  # rad per coarse step (Richardson's pair): the error law still holds there
_MAX_PASSES = 6


@functools.lru_cache(maxsize=32)
def _sequence_of(order: int, inner: int) -> tuple[NDArray[np.int64], Array, float, float]:
    """:func:`_sequence` of the composition of ``order`` (one step, no composition, without ``B``).

    Cached (read-only arrays): a secular run asks for it twice, and building it is a Python loop.
    """
    flows, weights, first, last = _sequence(COMPOSITIONS[order] if inner else COMPOSITIONS[2], inner)
    flows.flags.writeable = False
    weights.flags.writeable = False
    return flows, weights, first, last


def _sequence(gamma: Array, inner: int) -> tuple[NDArray[np.int64], Array, float, float]:
    """One step's flows (0 = outer, p + 1 = drifting perturber p) and their weights.

    The step is ``A(a_1) [B…(a_1) A(a_1 + a_2) … B…(a_s) A(a_s + a_1)]``: the first
    outer weight is applied once, the last one of the last step is ``a_s``.
    """
    flows, weights = [], []
    halves = 0.5 * gamma
    for j, a in enumerate(halves):
        for p in range(inner):
            flows.append(p + 1)
            weights.append(a if p < inner - 1 else 2 * a)
        for p in range(inner - 2, -1, -1):
            flows.append(p + 1)
            weights.append(a)
        flows.append(0)
        weights.append(a + halves[(j + 1) % len(halves)])
    return np.array(flows, dtype=np.int64), np.array(weights), float(halves[0]), float(halves[-1])


@jit
def _advance(mx, my, mz, g, t, h, n, flows, weights, first, last, c0, k0, coef, si, ci, node0, rate):
    """``n`` steps of size ``h`` from time ``t``; scalars (compiled) or arrays of states."""
    size = flows.shape[0]
    total = n * size
    for e in range(-1, total):
        if e < 0:
            f = 0
            w = first * h
        else:
            f = flows[e % size]
            w = weights[e % size] * h
            if e == total - 1:
                w = last * h
        if f == 0:
            kx, ky, kz = k0[0], k0[1], k0[2]
            c = c0
            t = t + w  # the outer flow carries time; its rotation does not depend on it
        else:
            p = f - 1
            node = node0[p] + rate[p] * t
            kx = si[p] * np.sin(node)
            ky = -si[p] * np.cos(node)
            kz = ci[p]
            c = coef[p]
        mx, my, mz = turn_about(mx, my, mz, kx, ky, kz, c * w)
        if e % size == size - 1:
            scale = g / np.sqrt(mx * mx + my * my + mz * mz)
            mx, my, mz = mx * scale, my * scale, mz * scale
    return mx, my, mz


@jit(inline=True)
def _offsets(flows, weights, rate, h):
    """Per flow of a step of size ``h``: its drifting node's advance since the step's start (sin, cos)."""
    size = flows.shape[0]
    offs = np.empty((size, 2))
    tau = 0.0
    for j in range(size):
        f = flows[j]
        if f == 0:
            tau += weights[j] * h
        else:
            a = rate[f - 1] * tau
            offs[j, 0], offs[j, 1] = math.sin(a), math.cos(a)
    return offs


@jit(inline=True)
def _nodes_at(base, node0, rate, t):
    """``sin, cos`` of every drifting node at ``t`` (the start of a step), into ``base`` (m, 2)."""
    for p in range(base.shape[0]):
        node = node0[p] + rate[p] * t
        base[p, 0], base[p, 1] = math.sin(node), math.cos(node)


@jit(inline=True)
def _rescaled(mx, my, mz, g):
    """``M`` rescaled to ``|M| = g`` (round-off must not accumulate in ``|M|``)."""
    scale = g / math.sqrt(mx * mx + my * my + mz * mz)
    return mx * scale, my * scale, mz * scale


@jit(inline=True)
def _flow(mx, my, mz, t, f, w, j, base, offs, c0, k0, coef, si, ci):
    """Flow ``f`` of a step (0: outer, about ``k0``, carrying time; ``p + 1``: drifting perturber ``p``)."""
    if f == 0:
        t = t + w
        mx, my, mz = turn_about_series(mx, my, mz, k0[0], k0[1], k0[2], c0 * w)
    else:
        p = f - 1
        sn = base[p, 0] * offs[j, 1] + base[p, 1] * offs[j, 0]
        cn = base[p, 1] * offs[j, 1] - base[p, 0] * offs[j, 0]
        mx, my, mz = turn_about_series(mx, my, mz, si[p] * sn, -si[p] * cn, ci[p], coef[p] * w)
    return mx, my, mz, t


@jit(inline=True)
def _step(mx, my, mz, g, t, h, final, flows, weights, last, base, offs, c0, k0, coef, si, ci, node0, rate):
    """One step of size ``h`` from time ``t`` (its first outer flow applied by the previous step)."""
    size = flows.shape[0]
    _nodes_at(base, node0, rate, t)
    for j in range(size):
        w = weights[j] * h
        if final and j == size - 1:
            w = last * h
        mx, my, mz, t = _flow(mx, my, mz, t, flows[j], w, j, base, offs, c0, k0, coef, si, ci)
    mx, my, mz = _rescaled(mx, my, mz, g)
    return mx, my, mz, t


@jit(inline=True)
def _start(mx, my, mz, g, t, h, first, c0, k0):
    """The first outer flow ``A(a_1 h)`` of a run of steps (the later ones merge with each step's last)."""
    w = first * h
    mx, my, mz = turn_about_series(mx, my, mz, k0[0], k0[1], k0[2], c0 * w)
    mx, my, mz = _rescaled(mx, my, mz, g)
    return mx, my, mz, t + w


@jit
def _advance_compiled(mx, my, mz, g, t, h, n, flows, weights, first, last, c0, k0, coef, si, ci, node0, rate):
    """:func:`_advance` for one state, compiled: the same flows, cheaper sines.

    The rotations by :func:`turn_about_series`; the nodes of the drifting normals by the
    addition theorem from their values at the start of each step (one ``sin, cos`` per
    perturber and step), the advance within a step (the same for every step) tabulated
    once. Agrees with :func:`_advance` to round-off (the tests compare them).
    """
    offs = _offsets(flows, weights, rate, h)
    base = np.empty((si.shape[0], 2))
    mx, my, mz, t = _start(mx, my, mz, g, t, h, first, c0, k0)
    for step in range(n):
        mx, my, mz, t = _step(
            mx, my, mz, g, t, h, step == n - 1, flows, weights, last, base, offs,
            c0, k0, coef, si, ci, node0, rate,
        )  # fmt: skip
    return mx, my, mz


@jit
def _advance_pair(a, b, g, h, n, n_b, flows, weights, first, last, c0, k0, coef, si, ci, node0, rate):
    """:func:`_advance_compiled` twice: ``a`` by ``n`` steps of ``2h``, ``b`` by ``n_b ≥ 2n`` of ``h``.

    ``a`` and ``b`` are ``(mx, my, mz, t)``; each run's operations are exactly those of its own
    :func:`_advance_compiled` call (the same results, bit for bit), but a step of ``a`` is
    taken flow by flow beside the first of the two steps of ``b`` that it spans: two
    independent chains of dependent operations that the processor overlaps, so that the coarse
    run of Richardson's pair costs little more than the fine run alone.
    """
    size = flows.shape[0]
    inner = si.shape[0]
    H = 2.0 * h
    offs_a = _offsets(flows, weights, rate, H)
    offs_b = _offsets(flows, weights, rate, h)
    base_a = np.empty((inner, 2))
    base_b = np.empty((inner, 2))
    ax, ay, az, ta = _start(a[0], a[1], a[2], g, a[3], H, first, c0, k0)
    bx, by, bz, tb = _start(b[0], b[1], b[2], g, b[3], h, first, c0, k0)
    for step in range(n):
        final = step == n - 1
        _nodes_at(base_a, node0, rate, ta)
        _nodes_at(base_b, node0, rate, tb)
        for j in range(size):
            wa = weights[j] * H
            if final and j == size - 1:
                wa = last * H
            ax, ay, az, ta = _flow(ax, ay, az, ta, flows[j], wa, j, base_a, offs_a, c0, k0, coef, si, ci)
            wb = weights[j] * h
            bx, by, bz, tb = _flow(bx, by, bz, tb, flows[j], wb, j, base_b, offs_b, c0, k0, coef, si, ci)
        ax, ay, az = _rescaled(ax, ay, az, g)
        bx, by, bz = _rescaled(bx, by, bz, g)
        bx, by, bz, tb = _step(
            bx, by, bz, g, tb, h, 2 * step + 1 == n_b - 1, flows, weights, last, base_b, offs_b,
            c0, k0, coef, si, ci, node0, rate,
        )  # fmt: skip
    for step in range(2 * n, n_b):
        bx, by, bz, tb = _step(
            bx, by, bz, g, tb, h, step == n_b - 1, flows, weights, last, base_b, offs_b,
            c0, k0, coef, si, ci, node0, rate,
        )  # fmt: skip
    return ax, ay, az, bx, by, bz


@jit
def _run_compiled(m0, g, c0, coef, k0, si, ci, node0, rate, h, index, offset, flows, weights, a, b, out):
    for i in range(m0.shape[0]):
        mx, my, mz = m0[i, 0], m0[i, 1], m0[i, 2]
        row = coef[:, i].copy()
        done = 0
        for j in range(index.shape[0]):
            if index[j] > done:
                mx, my, mz = _advance_compiled(
                    mx, my, mz, g[i], done * h, h, index[j] - done, flows, weights, a, b,
                    c0[i], k0, row, si, ci, node0, rate,
                )  # fmt: skip
                done = index[j]
            out[j, i, 0], out[j, i, 1], out[j, i, 2] = _branch(
                mx, my, mz, g[i], done * h, offset[j], flows, weights, a, b,
                c0[i], k0, row, si, ci, node0, rate,
            )  # fmt: skip


@jit(inline=True)
def _branch(mx, my, mz, g, t, offset, flows, weights, first, last, c0, k0, coef, si, ci, node0, rate):
    """The output ``offset`` past the grid point ``t``: one partial step, not fed back."""
    if offset == 0.0:
        return mx, my, mz
    return _advance_compiled(
        mx, my, mz, g, t, offset, 1, flows, weights, first, last, c0, k0, coef, si, ci, node0, rate
    )


@jit
def _run_pair_compiled(m0, g, c0, coef, k0, si, ci, node0, rate, h, index, offset, index2, offset2, flows,
                       weights, a, b, out, out2):  # fmt: skip
    """:func:`_run_compiled` at the step ``h`` (into ``out``) and at ``2h`` (into ``out2``), overlapped.

    Whole steps of both runs go through :func:`_advance_pair` where the fine run has at least
    twice the coarse run's steps to take (always, but for round-off in the grid indices),
    otherwise each its own; each run's results are bit for bit those of :func:`_run_compiled`.
    """
    H = 2.0 * h
    for i in range(m0.shape[0]):
        fx, fy, fz = m0[i, 0], m0[i, 1], m0[i, 2]
        cx, cy, cz = fx, fy, fz
        row = coef[:, i].copy()
        done, done2 = 0, 0
        for j in range(index.shape[0]):
            n, n2 = index[j] - done, index2[j] - done2
            if n2 > 0 and n >= 2 * n2:
                cx, cy, cz, fx, fy, fz = _advance_pair(
                    (cx, cy, cz, done2 * H), (fx, fy, fz, done * h), g[i], h, n2, n, flows, weights, a, b,
                    c0[i], k0, row, si, ci, node0, rate,
                )  # fmt: skip
                done, done2 = index[j], index2[j]
                n, n2 = 0, 0
            if n2 > 0:
                cx, cy, cz = _advance_compiled(
                    cx, cy, cz, g[i], done2 * H, H, n2, flows, weights, a, b,
                    c0[i], k0, row, si, ci, node0, rate,
                )  # fmt: skip
                done2 = index2[j]
            out2[j, i, 0], out2[j, i, 1], out2[j, i, 2] = _branch(
                cx, cy, cz, g[i], done2 * H, offset2[j], flows, weights, a, b,
                c0[i], k0, row, si, ci, node0, rate,
            )  # fmt: skip
            if n > 0:
                fx, fy, fz = _advance_compiled(
                    fx, fy, fz, g[i], done * h, h, n, flows, weights, a, b,
                    c0[i], k0, row, si, ci, node0, rate,
                )  # fmt: skip
                done = index[j]
            out[j, i, 0], out[j, i, 1], out[j, i, 2] = _branch(
                fx, fy, fz, g[i], done * h, offset[j], flows, weights, a, b,
                c0[i], k0, row, si, ci, node0, rate,
            )  # fmt: skip


def _grid(times: Array, steps: int) -> tuple[float, NDArray[np.int64], Array]:
    """Step ``h = t_K / steps``, and per output its grid step and the remainder to branch over."""
    h = float(times[-1]) / steps if steps else 0.0
    if h == 0:
        return h, np.zeros(len(times), dtype=np.int64), np.zeros(len(times))
    index = np.minimum(np.floor(times / h), steps).astype(np.int64)
    return h, index, times - index * h


def _prepared(M0, k0, normals, order, g=None):
    """The kernels' arrays: ``(si, ci, node0, rate)``, the step's flows and weights, ``|M0|``, ``k0``."""
    si, ci, node0, rate = (np.ascontiguousarray(v, dtype=np.float64) for v in normals)
    flows, weights, first, last = _sequence_of(order, si.shape[0])
    g = np.sqrt(np.sum(M0 * M0, axis=-1)) if g is None else g
    return (si, ci, node0, rate), (flows, weights, first, last), g, np.ascontiguousarray(k0, dtype=np.float64)


def _run_pair(M0, c0, k0, coef, normals, times, steps, order, compiled, g=None):
    """``(_run(…, 2 steps, …), _run(…, steps, …))``: Richardson's pair, overlapped in one compiled loop."""
    if not (NUMBA if compiled is None else compiled):
        return (
            _run(M0, c0, k0, coef, normals, times, 2 * steps, order, compiled),
            _run(M0, c0, k0, coef, normals, times, steps, order, compiled),
        )
    (si, ci, node0, rate), sequence, g, k0 = _prepared(M0, k0, normals, order, g)
    h, index, offset = _grid(times, 2 * steps)
    coarse, index2, offset2 = _grid(times, steps)
    if coarse != 2 * h:  # never for normal numbers (halving is exact), but the kernel relies on it
        return (
            _run(M0, c0, k0, coef, normals, times, 2 * steps, order, compiled),
            _run(M0, c0, k0, coef, normals, times, steps, order, compiled),
        )
    out = np.empty((len(times), *M0.shape))
    out2 = np.empty((len(times), *M0.shape))
    _run_pair_compiled(
        np.ascontiguousarray(M0), g, np.ascontiguousarray(c0), np.ascontiguousarray(coef), k0,
        si, ci, node0, rate, h, index, offset, index2, offset2, *sequence, out, out2,
    )  # fmt: skip
    return out, out2


def _run(M0, c0, k0, coef, normals, times, steps, order, compiled):
    """``steps`` equal steps to ``times[-1]``; each output is one partial step off the grid."""
    (si, ci, node0, rate), (flows, weights, first, last), g, k0 = _prepared(M0, k0, normals, order)
    h, index, offset = _grid(times, steps)
    out = np.empty((len(times), *M0.shape))
    if NUMBA if compiled is None else compiled:
        _run_compiled(
            np.ascontiguousarray(M0), g, np.ascontiguousarray(c0), np.ascontiguousarray(coef), k0,
            si, ci, node0, rate, h, index, offset, flows, weights, first, last, out,
        )  # fmt: skip
        return out
    advance = getattr(_advance, "py_func", _advance)
    mx, my, mz = M0[:, 0], M0[:, 1], M0[:, 2]
    done = 0
    groups, starts = np.unique(index, return_index=True)
    for k, lo, hi in zip(groups, starts, [*starts[1:], len(times)], strict=True):
        if k > done:
            mx, my, mz = advance(
                mx, my, mz, g, done * h, h, int(k - done), flows, weights, first, last,
                c0, k0, coef, si, ci, node0, rate,
            )  # fmt: skip
            done = k
        out[lo:hi] = np.stack([mx, my, mz], axis=-1)
        rows = lo + np.flatnonzero(offset[lo:hi])
        if len(rows):  # all branches of this step at once, vectorised over (outputs, states)
            bx, by, bz = advance(
                mx, my, mz, g, done * h, offset[rows, None], 1, flows, weights, first, last,
                c0, k0, coef, si, ci, node0, rate,
            )  # fmt: skip
            out[rows] = np.stack([bx, by, bz], axis=-1)
    return out


def propagate_rotations(
    M0: Array,
    c0: Array,
    k0: Array,
    coef: Array,
    normals: tuple[Array, Array, Array, Array],
    times: Array,
    max_step: float,
    order: int = 8,
    compiled: bool | None = None,
) -> Array:
    r"""Compose exact rotations from ``t = 0`` to ``times`` at a fixed step; shape (len(times), N, 3).

    Parameters
    ----------
    M0 : numpy.ndarray, shape (N, 3)
        Initial momenta (reference frame).
    c0 : numpy.ndarray, shape (N,)
        Rate coefficient of the outer flow (``Σ c_p`` over the perturbers about ``k0``).
    k0 : numpy.ndarray, shape (3,)
        Unit normal of the outer flow.
    coef : numpy.ndarray, shape (m, N)
        ``c_p`` of the other perturbers, per state.
    normals : tuple of numpy.ndarray, each shape (m,)
        ``(sin i, cos i, Ω(0), dΩ/dt)`` of the other perturbers:
        ``k_p(t) = (sin i sin Ω, −sin i cos Ω, cos i)``, ``Ω = Ω(0) + t dΩ/dt``.
    times : numpy.ndarray, shape (K,)
        Non-negative, increasing.
    max_step : float
        Each interval between outputs is cut into equal steps no longer than this.
    order : {2, 4, 6, 8}
    compiled : bool, optional
        Run the compiled loop (default: when numba is installed) or the interpreted
        loop vectorised over the states.

    Returns
    -------
    numpy.ndarray, shape (K, N, 3)

    Examples
    --------
    One perturber in the reference plane turns ``M`` about ``s3`` at ``c M₃``:

    >>> M0 = np.array([[0.6, 0.0, 0.8]])
    >>> none = tuple(np.zeros(0) for _ in range(4))
    >>> M = propagate_rotations(M0, np.array([2.0]), np.array([0, 0, 1.0]), np.zeros((0, 1)),
    ...                         none, np.array([np.pi / 1.6]), np.inf)
    >>> np.round(M[0, 0], 12)
    array([-0.6,  0. ,  0.8])
    """
    steps = 1 if len(normals[0]) == 0 else int(np.ceil(times[-1] / max_step))
    return _run(M0, c0, k0, coef, normals, times, steps, order, compiled)


def propagate_controlled(
    M0: Array,
    c0: Array,
    k0: Array,
    coef: Array,
    normals: tuple[Array, Array, Array, Array],
    times: Array,
    rate: float,
    rtol: float,
    order: int = 8,
    max_step: float = np.inf,
    compiled: bool | None = None,
    g: Array | None = None,
) -> tuple[Array, float]:
    r""":func:`propagate_rotations` at the step that meets ``rtol``, by Richardson's estimate.

    A coarse run at ``2 / rate`` (``rate`` the fastest rate of the problem, rad per
    time unit, so two radians per step) and a fine run at half its step estimate the
    fine run's global error as ``max |M_fine − M_coarse| / (G (2^order − 1))`` over
    the outputs and states. While that exceeds ``max(rtol, 16 ε √n)`` (``n`` the
    rotations of the fine run: their round-off) the step shrinks by the ratio the
    order predicts, at most six passes.

    Parameters
    ----------
    M0, c0, k0, coef, normals, times, order, compiled
        As in :func:`propagate_rotations`.
    rate : float
        Node drifts ``|dΩ_p/dt|`` and rotation rates ``|c_p| G``, the largest.
    rtol : float
        Target relative global error of ``M``.
    max_step : float
        Upper bound on the fine step.
    g : numpy.ndarray, shape (N,), optional
        ``|M0|`` where the caller has it (computed otherwise).

    Returns
    -------
    M : numpy.ndarray, shape (K, N, 3)
        The fine run.
    error : float
        Its estimated relative error.

    Examples
    --------
    >>> M0 = np.array([[0.6, 0.0, 0.8]])
    >>> normals = (np.array([0.5]), np.array([0.75**0.5]), np.array([0.0]), np.array([1.0]))
    >>> M, error = propagate_controlled(M0, np.zeros(1), np.array([0, 0, 1.0]), np.array([[1.0]]),
    ...                                 normals, np.array([10.0]), 1.0, 1e-10)
    >>> bool(error < 1e-10)
    True
    """
    inner = len(normals[0])
    if inner == 0:  # the outer flow alone: one exact rotation to each output
        return _run(M0, c0, k0, coef, normals, times, 1, order, compiled), 0.0
    coarse = min(_MAX_ANGLE / rate if rate > 0 else np.inf, 2 * max_step)
    steps = max(1, int(np.ceil(times[-1] / coarse)))
    rotations = (2 * inner + 1) * len(COMPOSITIONS[order])
    g = np.sqrt(np.sum(M0 * M0, axis=-1)) if g is None else g
    fine, error = None, np.inf
    for _ in range(_MAX_PASSES):
        fine, rough = _run_pair(M0, c0, k0, coef, normals, times, steps, order, compiled, g)
        difference = fine - rough  # its norm with np.linalg.norm's arithmetic, without the dispatch
        error = float((np.sqrt(np.sum(difference * difference, axis=-1)) / g).max()) / (2**order - 1)
        floor = 16 * _EPSILON * math.sqrt(2 * steps * rotations)
        if error <= max(rtol, floor):
            break
        steps = int(np.ceil(steps * min(10.0, 1.2 * (error / max(rtol, floor)) ** (1 / order))))
    return fine, error
