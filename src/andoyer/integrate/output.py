"""Output times shared by the integrators: each (state, time) pair of a broadcast shape."""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._limits import check_size, check_spin_phase
from andoyer._validation import as_finite
from andoyer.state import State

Array = NDArray[np.float64]


#: Bytes per (state, output time): the attitude and momentum (7 float64) in the table of
#: every state at every distinct time, its gathered copy and the returned state.
OUTPUT_BYTES = 3 * 7 * 8


def output_times(
    state: State, t: ArrayLike, moments: ArrayLike | None = None, t0: float = 0.0
) -> tuple[Array, Array, tuple[int, ...]]:
    """Validated times, their sorted unique values, and the broadcast output shape.

    With the body's ``moments``, the phase reached at ``t − t0`` is checked
    (:func:`andoyer._limits.check_phase`); the output's memory is checked in every case.
    """
    if not isinstance(state, State):
        msg = f"expected an andoyer State, got {type(state).__name__}"
        raise ValueError(msg)
    times = as_finite(t, "t")
    if times.size == 0:
        msg = f"expected at least one output time t, got an empty array of shape {times.shape}"
        raise ValueError(msg)
    try:
        shape = np.broadcast_shapes(state.shape, times.shape)
    except ValueError as exc:
        msg = f"expected times broadcastable with the state's shape {state.shape}, got shape {times.shape}"
        raise ValueError(msg) from exc
    unique = times.reshape(1).copy() if times.size == 1 else np.unique(times)  # one time: nothing to sort
    check_size("an output", nbytes=OUTPUT_BYTES * (unique.size * state.size + float(math.prod(shape))))
    if moments is not None:
        t0 = float(as_finite(t0, "t0"))
        with np.errstate(over="ignore"):  # an overflow is an infinite phase: refused
            spans = unique - t0
        check_spin_phase(moments, state.m_body, spans, "the propagation")
    return times, unique, shape


def gather_states(
    state: State,
    times: Array,
    unique: Array,
    shape: tuple[int, ...],
    values: dict[float, tuple[Array, Array]],
) -> State:
    """Pick, for each pair of the broadcast shape, its state at its time.

    ``values[t] = (q, m)`` holds every state (flattened, (N, 4) and (N, 3)) at time ``t``.
    """
    q_table = np.stack([values[float(x)][0] for x in unique])  # (U, N, 4)
    m_table = np.stack([values[float(x)][1] for x in unique])
    return gather_table(state, times, unique, shape, q_table, m_table)


def gather_table(
    state: State,
    times: Array,
    unique: Array,
    shape: tuple[int, ...],
    q_table: Array,
    m_table: Array,
    conserved: bool = False,
) -> State:
    """:func:`gather_states` from the tables ``q_table`` (U, N, 4) and ``m_table`` (U, N, 3).

    Row ``k`` holds every state (flattened) at time ``unique[k]``; the quaternions are
    normalised here. ``conserved``: the momenta have the magnitudes of ``state``'s (already
    validated), so the returned state is built without checking them again.
    """
    if q_table.shape[:2] == (1, 1) and math.prod(shape) == 1:  # one state, one time: the table is the output
        q = q_table.reshape((*shape, 4))
        m = m_table.reshape((*shape, 3))
    else:
        n = max(state.size, 1)
        state_index = np.broadcast_to(np.arange(n).reshape(state.shape or ()), shape)
        which = np.searchsorted(unique, np.broadcast_to(times, shape))
        q = q_table[which, state_index]
        m = m_table[which, state_index]
    q = q / np.linalg.norm(q, axis=-1, keepdims=True)
    return State.from_unit_quaternion(q, m) if conserved else State.from_quaternion(q, m)
