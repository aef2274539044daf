"""Helpers of the body-dependent charts of :class:`~andoyer.State`.

Sadov's action–angle variables, the modified Andoyer set, Serret's elements and Lara's
SAM/LAM variables all need the body's moments (:func:`check_body`), and the time-dependent
ones the free flow (:func:`free_flow`, which loads :mod:`andoyer.free.motion` on first use so
that a state costs no numba start-up).  Their ``from_*``/``as_*`` converters are written in
the chart modules, registered in :mod:`andoyer.charts.registry`, and installed on
:class:`~andoyer.State` as its methods.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from numpy.typing import ArrayLike

from andoyer.body import RigidBody

if TYPE_CHECKING:
    from andoyer.state import State

__all__ = ["check_body", "free_flow"]


def check_body(body: Any) -> RigidBody:
    """Return ``body`` if it is a :class:`~andoyer.RigidBody`, else raise ``ValueError``."""
    if not isinstance(body, RigidBody):
        msg = f"expected an andoyer.RigidBody, got {type(body).__name__}"
        raise ValueError(msg)
    return body


def free_flow(body: RigidBody, state: State, dt: ArrayLike) -> State:
    """The states reached by the free flow after ``dt`` (``FreeRotation.propagate`` without the wrapper).

    Parameters
    ----------
    body : RigidBody
        The body.
    state : State, shape (...)
        The states at the start.
    dt : array_like, shape (...)
        The times of flight; broadcast with the state's shape.

    Returns
    -------
    State
        The states after ``dt``.

    Examples
    --------
    >>> from andoyer import RigidBody, State
    >>> from andoyer.state_charts import free_flow
    >>> s = State.from_andoyer(0.3, 0.4, 0.5, 0.9, 1.0, 0.2)
    >>> round(float(free_flow(RigidBody(1.0, 2.0, 3.0), s, 1.5).as_andoyer().G), 12)
    1.0
    """
    # Imported here so that a State costs no numba/theta-series start-up until a time chart is used.
    from andoyer.free.motion import FreeMotion

    m, q = FreeMotion(body.moments, state.m_body, state.quaternion).propagate(dt)
    return type(state).from_quaternion(q, m)
