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

import warnings
from collections.abc import Sequence
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer import _quaternion as quat
from andoyer.body import RigidBody
from andoyer.perturbations.averaged_gravity import SecularGravityGradient
from andoyer.perturbations.base import Perturbation
from andoyer.perturbations.expressions import (
    HeyokaContext,
    HubRates,
    Quaternion,
    Vector,
    float_position,
    kepler_position,
    to_body,
)
from andoyer.perturbations.orbits import CircularOrbit, KeplerOrbit
from andoyer.perturbations.point_mass import PointMass

__all__ = ["GravityGradient", "PointMass"]

Array = NDArray[np.float64]


class GravityGradient(Perturbation):
    """The gravity-gradient (MacCullagh) torque of one or several point masses on a body.

    The body is the model's: ``Model(body, GravityGradient(perturbers))`` (or
    ``GravityGradient(perturbers).bind(body)`` to evaluate the term alone).

    Parameters
    ----------
    perturbers : PointMass or sequence of PointMass
        The Sun and the Moon, say. Their ``gm`` in units consistent with the body's moments
        and the angular momentum (``gm`` · moment / length³ is a torque).

    Notes
    -----
    The former signature ``GravityGradient(body, perturbers)`` still works and issues a
    ``DeprecationWarning``; the term is then bound to that body, and a model of another body
    refuses it.

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> from andoyer.perturbations import CircularOrbit
    >>> model = GravityGradient(PointMass(1.0, CircularOrbit(1.0, 0.0))).bind(RigidBody(1.0, 2.0, 2.5))
    >>> model.torque(0.0, [0, 0, 0, 1.0], [0, 0, 1.0]).tolist()  # perturber on b1
    [0.0, 0.0, 0.0]
    """

    hamiltonian = True
    attitude_only = True

    def __init__(self, perturbers: PointMass | Sequence[PointMass], *deprecated: Any) -> None:
        # ``GravityGradient(body, perturbers)``, the former signature, arrives as (body, (perturbers,)).
        args = (perturbers, *deprecated)
        if len(args) == 2:
            body, perturbers = args
            if not isinstance(body, RigidBody):
                msg = f"expected an andoyer.RigidBody, got {type(body).__name__}"
                raise ValueError(msg)
            warnings.warn(
                "GravityGradient(body, perturbers) is deprecated: give the body to the Model, "
                "Model(body, GravityGradient(perturbers))",
                DeprecationWarning,
                stacklevel=2,
            )
        elif len(args) == 1:
            body, perturbers = None, args[0]
        else:
            msg = f"expected GravityGradient(perturbers), got {len(args)} arguments"
            raise ValueError(msg)
        self._body = body
        self.perturbers = (perturbers,) if isinstance(perturbers, PointMass) else tuple(perturbers)
        if not self.perturbers or not all(isinstance(p, PointMass) for p in self.perturbers):
            msg = f"expected one or more PointMass perturbers, got {perturbers!r}"
            raise ValueError(msg)

    @property
    def body(self) -> RigidBody:
        """The body the term acts on (its model's); ``ValueError`` before it is bound."""
        if self._body is None:
            msg = (
                "expected a GravityGradient bound to a body (inside a Model, or through bind(body)), "
                "got an unbound term"
            )
            raise ValueError(msg)
        return self._body

    def bind(self, body: RigidBody) -> GravityGradient:
        """The term on ``body``; ``ValueError`` if it was built for a body of other moments."""
        if self._body is not None:
            if not np.array_equal(self._body.moments, body.moments):
                msg = (
                    f"expected the gravity-gradient model to act on the model's body {body!r}, "
                    f"got {self._body!r}"
                )
                raise ValueError(msg)
            return self
        bound = object.__new__(GravityGradient)
        bound.__dict__.update(self.__dict__)
        bound._body = body
        return bound

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

    # The term protocol (andoyer.perturbations.base).

    @property
    def tabulable(self) -> bool:
        """Always: the kick depends on time only through the perturbers' positions."""
        return True

    def point_masses(self) -> tuple[tuple[PointMass, Array], ...]:
        """Each perturber with the body's moments."""
        return tuple((p, self.body.moments) for p in self.perturbers)

    def secular_average(self) -> Any | None:
        """:class:`~andoyer.perturbations.SecularGravityGradient` (Kepler orbits), else ``None``."""
        if not all(isinstance(p.orbit, KeplerOrbit) for p in self.perturbers):
            return None
        return SecularGravityGradient(self.body, self.perturbers)

    def hub_rates(self) -> HubRates:
        """``δṁ = Σ_p 3μ_p/ρ⁵ ((I3−I2) ρ2 ρ3, …)`` on components, positions solved on floats."""
        I1, I2, I3 = self.body.moments.tolist()
        perturbers = [(3 * p.gm, float_position(p.orbit)) for p in self.perturbers]

        def rates(t: float, q: Quaternion, _m: Vector) -> tuple[None, Vector]:
            total = [0.0, 0.0, 0.0]
            for gm3, position in perturbers:
                x, y, z = to_body(q, position(t))
                scale = gm3 / (x * x + y * y + z * z) ** 2.5
                total = [
                    total[0] + scale * ((I3 - I2) * y * z),
                    total[1] + scale * ((I1 - I3) * z * x),
                    total[2] + scale * ((I2 - I1) * x * y),
                ]
            return None, (total[0], total[1], total[2])

        return rates

    @property
    def heyoka_supported(self) -> bool:
        """Kepler and circular orbits (closed-form positions)."""
        return all(type(p.orbit) in (KeplerOrbit, CircularOrbit) for p in self.perturbers)

    def heyoka_rates(self, ctx: HeyokaContext) -> tuple[None, list[list[Any]]]:
        """The torque of each perturber, ``kepE`` for its eccentric anomaly."""
        I1, I2, I3 = self.body.moments.tolist()
        par, q, factor = ctx.par, ctx.q, ctx.time_unit / ctx.scale
        out = []
        for p in self.perturbers:
            rho = to_body(q, kepler_position(ctx.hy, par, p.orbit, ctx.time))
            r5 = (rho[0] * rho[0] + rho[1] * rho[1] + rho[2] * rho[2]) ** -2.5
            k = 3 * p.gm * factor
            out.append(
                [
                    par(k * (I3 - I2)) * r5 * rho[1] * rho[2],
                    par(k * (I1 - I3)) * r5 * rho[2] * rho[0],
                    par(k * (I2 - I1)) * r5 * rho[0] * rho[1],
                ]
            )
        return None, out

    def __repr__(self) -> str:
        names = ", ".join(p.name or "PointMass" for p in self.perturbers)
        body = "" if self._body is None else f"{self._body!r}, "
        return f"GravityGradient({body}[{names}])"
