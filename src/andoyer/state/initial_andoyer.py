"""Gurfil's modified Andoyer set ``(l0, g0, h, L0, G, H)`` (Gurfil et al. §4.1).

The Andoyer variables, at ``epoch``, of the free motion through the state: with the state
taken at time ``t``, the free flow carries it to ``epoch`` and :mod:`andoyer.state.andoyer`
reads its variables there. They are the constants of integration of the free motion, so the
chart's Hamiltonian is nil ("consists only of constants of integration, and hence the
corresponding Hamiltonian becomes nil", Gurfil §4.1) and every rate vanishes: the dynamics
registered with the chart (:func:`initial_andoyer_hamiltonian`,
:func:`initial_andoyer_equations`).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._validation import broadcast_finite, check_momenta
from andoyer.body import RigidBody
from andoyer.state.andoyer import Andoyer
from andoyer.state.hub import State, check_body, free_flow
from andoyer.state.registry import Chart, register

__all__ = ["InitialAndoyer", "initial_andoyer_equations", "initial_andoyer_hamiltonian"]

Array = NDArray[np.float64]


class InitialAndoyer(NamedTuple):
    """The modified Andoyer set (or its rates); each field has the state's shape."""

    l0: Array
    g0: Array
    h: Array
    L0: Array
    G: Array
    H: Array


# The chart's methods of State (installed when the chart registers, below): their signatures
# are the chart's, written once here. ``cls`` and ``self`` are the State class and a state.


def _as_initial_andoyer(self, body: RigidBody, epoch: ArrayLike, t: ArrayLike = 0.0) -> Andoyer:
    """The modified Andoyer set (Gurfil §4.1): Andoyer variables at ``epoch`` of the free motion.

    The state is taken at time ``t``; the free flow carries it to ``epoch``.
    ``(l0, g0, h, L0, G, H)`` are constants of the free motion.

    Parameters
    ----------
    body : RigidBody
        The body.
    epoch, t : array_like, shape (...)
        The epoch of the set and the time of the state; broadcast with the state's shape.

    Returns
    -------
    Andoyer of arrays, each of shape (...)
        ``(l0, g0, h, L0, G, H)``, the fields named ``(l, g, h, L, G, H)``.

    Examples
    --------
    >>> from andoyer import FreeRotation, RigidBody, State
    >>> body = RigidBody(1.0, 2.0, 3.0)
    >>> s = State.from_andoyer(0.3, 0.4, 0.5, 0.9, 1.0, 0.2)
    >>> later = FreeRotation(body).propagate(s, 2.5)
    >>> a, b = s.as_initial_andoyer(body, 0.0), later.as_initial_andoyer(body, 0.0, t=2.5)
    >>> bool(max(abs(x - y) for x, y in zip(a, b)) < 1e-12)
    True
    """
    dt = np.asarray(epoch, dtype=float) - np.asarray(t, dtype=float)
    return free_flow(check_body(body), self, dt).as_andoyer()


def _from_initial_andoyer(
    cls: type[State],
    body: RigidBody,
    l0: ArrayLike,
    g0: ArrayLike,
    h: ArrayLike,
    L0: ArrayLike,
    G: ArrayLike,
    H: ArrayLike,
    epoch: ArrayLike,
    t: ArrayLike = 0.0,
) -> State:
    """State at time ``t`` of the free motion whose Andoyer variables at ``epoch`` are given.

    The inverse of :meth:`as_initial_andoyer` (Gurfil §4.1's modified Andoyer set
    ``(l0, g0, h, L0, G, H)``): the free flow carries ``from_andoyer(l0, …, H)`` from
    ``epoch`` to ``t``. All arguments broadcast.

    Parameters
    ----------
    body : RigidBody
        The body.
    l0, g0, h : array_like, shape (...)
        The Andoyer angles at ``epoch``, in radians.
    L0, G, H : array_like, shape (...)
        The momenta at ``epoch``.
    epoch, t : array_like, shape (...)
        The epoch of the set and the time of the state.

    Returns
    -------
    State, shape (...)
        The states at ``t`` (the broadcast shape of the arguments).

    Examples
    --------
    >>> from andoyer import RigidBody, State
    >>> body = RigidBody(1.0, 2.0, 3.0)
    >>> s = State.from_initial_andoyer(body, 0.3, 0.4, 0.5, 0.9, 1.0, 0.2, epoch=1.0, t=2.5)
    >>> a = s.as_initial_andoyer(body, 1.0, t=2.5)
    >>> [round(float(x), 12) for x in a]
    [0.3, 0.4, 0.5, 0.9, 1.0, 0.2]
    """
    dt = np.asarray(t, dtype=float) - np.asarray(epoch, dtype=float)
    return free_flow(check_body(body), cls.from_andoyer(l0, g0, h, L0, G, H), dt)


# ---------------------------------------------------------------- the chart's dynamics


def _checked(values: tuple[ArrayLike, ...]) -> list[Array]:
    """The six variables, finite and broadcast, with ``G > 0`` and ``|L0|, |H| <= G``."""
    l0, g0, h, L0, G, H = broadcast_finite(InitialAndoyer._fields, values)
    check_momenta(L0, G, H)
    return [l0, g0, h, L0, G, H]


def initial_andoyer_hamiltonian(
    body: RigidBody, l0: ArrayLike, g0: ArrayLike, h: ArrayLike, L0: ArrayLike, G: ArrayLike, H: ArrayLike
) -> Array:
    """The free Hamiltonian in the modified Andoyer set: nil (Gurfil §4.1).

    Parameters
    ----------
    body : RigidBody
    l0, g0, h, L0, G, H : array_like, shape (...)
        The modified Andoyer set; they broadcast.

    Returns
    -------
    numpy.ndarray, shape (...)
        Zeros.

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> initial_andoyer_hamiltonian(RigidBody(1.0, 2.0, 3.0), 0.3, 0.4, 0.5, [0.9, 0.8], 1.0, 0.2).tolist()
    [0.0, 0.0]
    """
    check_body(body)
    return np.zeros_like(_checked((l0, g0, h, L0, G, H))[0])


def initial_andoyer_equations(
    body: RigidBody, l0: ArrayLike, g0: ArrayLike, h: ArrayLike, L0: ArrayLike, G: ArrayLike, H: ArrayLike
) -> InitialAndoyer:
    """Hamilton's equations of the free body in the modified Andoyer set: every rate is zero.

    Parameters
    ----------
    body : RigidBody
    l0, g0, h, L0, G, H : array_like, shape (...)
        The modified Andoyer set; they broadcast.

    Returns
    -------
    InitialAndoyer
        The six rates, zeros of the broadcast shape.

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> [float(r) for r in initial_andoyer_equations(RigidBody(1.0, 2.0, 3.0), 0.3, 0.4, 0.5, 0.9, 1.0, 0.2)]
    [0.0, 0.0, 0.0, 0.0, 0.0, 0.0]
    """
    check_body(body)
    return InitialAndoyer(*(np.zeros_like(v) for v in _checked((l0, g0, h, L0, G, H))))


# Gurfil §4.1's modified Andoyer set: the Andoyer variables at ``epoch`` of the free motion.
register(
    Chart(
        "initial_andoyer",
        InitialAndoyer._fields,
        ("l0", "g0", "h"),
        "Andoyer variables at `epoch` of the free motion, the state taken at `t` (Gurfil §4.1)",
        _from_initial_andoyer,
        _as_initial_andoyer,
        source="andoyer.state.initial_andoyer",
        hamiltonian=initial_andoyer_hamiltonian,
        equations=initial_andoyer_equations,
    ),
    State,
)
