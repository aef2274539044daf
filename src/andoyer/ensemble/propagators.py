"""Propagation kernels an ensemble can run: any callable ``(state chunk, times, **parameters) -> State``.

The contract: given states of shape ``(n,)``, times of shape ``(T,)`` and the
per-sample parameters of the sampler (arrays of shape ``(n, ...)``, as keyword
arguments), return the states at those times, shape ``(n, T)``. The callable is
shipped to the Dask workers, so it must be picklable (by cloudpickle: closures
and lambdas are fine) and deterministic.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer.body import RigidBody
from andoyer.free import FreeMotion
from andoyer.free_rotation import FreeRotation
from andoyer.state import State

__all__ = ["FreePropagator", "Propagator"]


class Propagator(Protocol):
    """What the ensemble runner calls on every chunk."""

    def __call__(self, state: State, times: NDArray[np.float64], **parameters: NDArray[np.float64]) -> State:
        """States of shape (n, T) from states (n,) and times (T,)."""
        ...  # pragma: no cover - protocol


@dataclass(frozen=True)
class FreePropagator:
    """The exact torque-free flow, :meth:`andoyer.FreeRotation.propagate`, as an ensemble kernel.

    Without parameters it is exactly ``FreeRotation(body).propagate(state[:, None], times)``.
    With the per-sample parameter ``moments`` (shape (n, 3), e.g. from
    :class:`~andoyer.ensemble.InertiaSampler`) every sample moves with its own
    body (``body`` may then be ``None``).

    Parameters
    ----------
    body : RigidBody or None

    Examples
    --------
    >>> import numpy as np
    >>> from andoyer import RigidBody, State
    >>> prop = FreePropagator(RigidBody(1.0, 2.0, 3.0))
    >>> s = State.from_quaternion([[0, 0, 0, 1.0]] * 2, [[0.3, 0.2, 1.0], [1.0, 0.1, 0.1]])
    >>> prop(s, np.array([0.0, 1.0, 2.0])).shape
    (2, 3)
    """

    body: RigidBody | None = None

    def __post_init__(self) -> None:
        if self.body is not None and not isinstance(self.body, RigidBody):
            msg = f"expected an andoyer.RigidBody or None, got {type(self.body).__name__}"
            raise ValueError(msg)

    def __call__(self, state: State, times: ArrayLike, moments: ArrayLike | None = None) -> State:
        """States at ``times`` (T,) from ``state`` (n,): shape (n, T)."""
        times = np.asarray(times, dtype=np.float64)
        column = state.reshape(-1, 1)
        if moments is None:
            if self.body is None:
                msg = "expected a body or per-sample moments for the free flow, got neither"
                raise ValueError(msg)
            return FreeRotation(self.body).propagate(column, times)
        moments = np.asarray(moments, dtype=np.float64)
        if moments.shape != (state.size, 3):
            msg = f"expected per-sample moments of shape ({state.size}, 3), got shape {moments.shape}"
            raise ValueError(msg)
        m, q = FreeMotion(moments[:, None, :], column.m_body, column.quaternion).propagate(times)
        return State.from_quaternion(q, m)
