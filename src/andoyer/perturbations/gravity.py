r"""Gravitational torque of point masses at second order in the body's size (MacCullagh).

For a perturber of gravitational parameter ``μ_p = G M_p`` at position ``r``
(reference frame), seen in the body as ``ρ = Rᵀ r`` (``ρ = |r|``),

.. math::
   \Delta H = \frac{\mu_p}{2\rho^5}\sum_i I_i\,(3\rho_i^2 - \rho^2), \qquad
   \tau_1 = \frac{3\mu_p}{\rho^5}(I_3 - I_2)\,\rho_2\rho_3 \ \text{(and cyclic)},

i.e. ``τ = 3μ_p/ρ⁵ ρ × Iρ``, written with the differences of moments formed
once so that near-axisymmetric bodies keep their digits. The monopole
``-μ_p m/ρ`` does not depend on the attitude and is left out.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer import _quaternion as quat
from andoyer.body import RigidBody
from andoyer.perturbations.base import Perturbation
from andoyer.perturbations.orbits import Orbit

__all__ = ["GravityGradient", "PointMass"]

Array = NDArray[np.float64]


@dataclass(frozen=True)
class PointMass:
    """A perturbing point mass: gravitational parameter ``gm = G M`` and its orbit.

    Examples
    --------
    >>> from andoyer.perturbations import CircularOrbit
    >>> sun = PointMass(1.0, CircularOrbit(1.0, 1.0), name="Sun")
    >>> sun.name
    'Sun'
    """

    gm: float
    orbit: Orbit
    name: str = ""

    def __post_init__(self) -> None:
        if not np.isfinite(self.gm) or self.gm <= 0:
            msg = f"expected a positive finite gravitational parameter gm, got {self.gm!r}"
            raise ValueError(msg)
        if not isinstance(self.orbit, Orbit):
            msg = f"expected an Orbit, got {type(self.orbit).__name__}"
            raise ValueError(msg)


class GravityGradient(Perturbation):
    """The gravity-gradient (MacCullagh) torque of one or several point masses on a body.

    Parameters
    ----------
    body : RigidBody
        Moments in the same units as ``gm * time²`` per length² times mass·length²,
        i.e. consistent with the angular momentum.
    perturbers : PointMass or sequence of PointMass
        The Sun and the Moon, say.

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> from andoyer.perturbations import CircularOrbit
    >>> body = RigidBody(1.0, 2.0, 2.5)
    >>> model = GravityGradient(body, PointMass(1.0, CircularOrbit(1.0, 0.0)))
    >>> model.torque(0.0, [0, 0, 0, 1.0], [0, 0, 1.0]).tolist()  # perturber on b1
    [0.0, 0.0, 0.0]
    """

    hamiltonian = True
    attitude_only = True

    def __init__(self, body: RigidBody, perturbers: PointMass | Sequence[PointMass]) -> None:
        if not isinstance(body, RigidBody):
            msg = f"expected an andoyer.RigidBody, got {type(body).__name__}"
            raise ValueError(msg)
        self.body = body
        self.perturbers = (perturbers,) if isinstance(perturbers, PointMass) else tuple(perturbers)
        if not self.perturbers or not all(isinstance(p, PointMass) for p in self.perturbers):
            msg = f"expected one or more PointMass perturbers, got {perturbers!r}"
            raise ValueError(msg)

    def _directions(self, t: ArrayLike, q: Array) -> list[tuple[float, Array]]:
        conj = quat.conjugate(q)
        return [(p.gm, quat.rotate(conj, p.orbit.position(t))) for p in self.perturbers]

    def _potential(self, t: Array, q: Array, m: Array) -> Array:
        I = self.body.moments
        total = 0.0
        for gm, rho in self._directions(t, q):
            r2 = np.sum(rho * rho, axis=-1)
            total = total + gm / (2 * r2**2.5) * np.sum(I * (3 * rho * rho - r2[..., None]), axis=-1)
        return total * np.ones(np.broadcast_shapes(np.shape(total), m.shape[:-1]))

    def _torque(self, t: Array, q: Array, m: Array) -> Array:
        I1, I2, I3 = self.body.moments
        total = 0.0
        for gm, rho in self._directions(t, q):
            r2 = np.sum(rho * rho, axis=-1)
            scale = 3 * gm / r2**2.5
            x, y, z = rho[..., 0], rho[..., 1], rho[..., 2]
            total = total + scale[..., None] * np.stack(
                [(I3 - I2) * y * z, (I1 - I3) * z * x, (I2 - I1) * x * y], -1
            )
        return total * np.ones((*np.broadcast_shapes(np.shape(total)[:-1], m.shape[:-1]), 3))

    def __repr__(self) -> str:
        names = ", ".join(p.name or "PointMass" for p in self.perturbers)
        return f"GravityGradient({self.body!r}, [{names}])"
