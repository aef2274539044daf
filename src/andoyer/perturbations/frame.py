r"""A precessing reference frame (Gurfil et al. §4.4, eqs. 119–126).

When the reference frame rotates with angular velocity ``μ`` relative to
inertial space (``μ`` given in the reference frame's own components,
constant or a function of time), the Hamiltonian of the motion relative to
that frame gains

.. math:: \Delta H = -\boldsymbol\mu\cdot\mathbf M = -\boldsymbol\mu_b\cdot\mathbf m,
   \qquad \boldsymbol\mu_b = R\,\boldsymbol\mu,

(eq. 126) with ``∂ΔH/∂m = -μ_b`` and attitude torque ``τ = m × μ_b``. The two
cancel in ``dm/dt``: the body angular momentum evolves as in inertial space,
while the attitude relative to the frame turns at ``ω - μ_b`` (eq. 132).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer import _quaternion as quat
from andoyer._validation import as_vectors
from andoyer.perturbations.base import Perturbation

__all__ = ["PrecessingFrame"]

Array = NDArray[np.float64]


class PrecessingFrame(Perturbation):
    """The fictitious term ``ΔH = -μ·M`` of a reference frame turning at ``μ``.

    Parameters
    ----------
    rate : array_like, shape (3,), or callable
        The frame's angular velocity relative to inertial space, in the frame's
        components; a callable ``rate(t) -> (..., 3)`` for a time-dependent rate.

    Examples
    --------
    >>> frame = PrecessingFrame([0.0, 0.0, 0.1])
    >>> float(frame.potential(0.0, [0, 0, 0, 1.0], [0, 0, 2.0]))
    -0.2
    """

    hamiltonian = True
    attitude_only = False

    def __init__(self, rate: ArrayLike | Callable[[Array], ArrayLike]) -> None:
        self._function = rate if callable(rate) else None
        self._constant = None if callable(rate) else as_vectors(rate, "rate")

    def rate(self, t: ArrayLike) -> Array:
        """``μ`` in reference components at times ``t``, shape (..., 3)."""
        if self._function is not None:
            return as_vectors(self._function(t), "rate(t)")
        return np.broadcast_to(self._constant, (*np.shape(t), 3))

    def _rate_body(self, t: ArrayLike, q: Array) -> Array:
        return quat.rotate(quat.conjugate(q), self.rate(t))

    def _potential(self, t: Array, q: Array, m: Array) -> Array:
        return -np.sum(self._rate_body(t, q) * m, axis=-1)

    def _momentum_gradient(self, t: Array, q: Array, m: Array) -> Array:
        return -self._rate_body(t, q) * np.ones_like(m)

    def _torque(self, t: Array, q: Array, m: Array) -> Array:
        return quat.cross(m, self._rate_body(t, q))

    def __repr__(self) -> str:
        return f"PrecessingFrame({'<function>' if self._function else self._constant.tolist()})"
