r"""The heavy top: a rigid body with a fixed point in a uniform field (Pavlov §1).

With ``γ = Rᵀ s3`` the upward vertical in body components, ``r_c`` the centre
of mass from the fixed point (body components) and ``weight = m g0``,

.. math:: \Delta H = \text{weight}\;\mathbf r_c\cdot\boldsymbol\gamma, \qquad
   \boldsymbol\tau = \text{weight}\;\boldsymbol\gamma\times\mathbf r_c .

The moments of the :class:`~andoyer.RigidBody` are then taken about the fixed
point.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer import _quaternion as quat
from andoyer._validation import as_finite, as_vectors
from andoyer.perturbations.base import Perturbation, hub_arrays

__all__ = ["HeavyTop"]

Array = NDArray[np.float64]

_UP = np.array([0.0, 0.0, 1.0])


class HeavyTop(Perturbation):
    """Uniform gravity on a body with a fixed point: ``ΔH = m g0 r_c·γ``.

    Parameters
    ----------
    weight : float
        ``m g0`` (mass times field strength), positive.
    center_of_mass : array_like, shape (3,)
        Centre of mass relative to the fixed point, body components.

    Examples
    --------
    >>> top = HeavyTop(2.0, [0.0, 0.0, 0.5])
    >>> float(top.potential(0.0, [0, 0, 0, 1.0], [0, 0, 1.0]))  # upright: +m g0 z
    1.0
    """

    hamiltonian = True
    attitude_only = True

    def __init__(self, weight: float, center_of_mass: ArrayLike) -> None:
        self.weight = float(as_finite(weight, "weight"))
        if self.weight <= 0:
            msg = f"expected weight = m g0 > 0, got {self.weight!r}"
            raise ValueError(msg)
        self.center_of_mass = as_vectors(center_of_mass, "center_of_mass")
        if self.center_of_mass.shape != (3,):
            msg = f"expected center_of_mass with shape (3,), got {self.center_of_mass.shape}"
            raise ValueError(msg)

    def gamma(self, q: Array) -> Array:
        """The upward vertical in body components, shape (..., 3)."""
        return quat.rotate(quat.conjugate(q), _UP)

    def potential(self, t: ArrayLike, q: Array, m: Array) -> Array:
        """``ΔH``, shape (...)."""
        q, m = hub_arrays(q, m)
        value = self.weight * np.sum(self.gamma(q) * self.center_of_mass, axis=-1)
        return value * np.ones(np.broadcast_shapes(np.shape(t), m.shape[:-1], value.shape))

    def torque(self, t: ArrayLike, q: Array, m: Array) -> Array:
        """``τ = m g0 γ × r_c``, shape (..., 3)."""
        q, m = hub_arrays(q, m)
        value = self.weight * np.cross(self.gamma(q), self.center_of_mass)
        return value * np.ones((*np.broadcast_shapes(np.shape(t), m.shape[:-1], value.shape[:-1]), 3))

    def __repr__(self) -> str:
        return f"HeavyTop(weight={self.weight!r}, center_of_mass={self.center_of_mass.tolist()})"
