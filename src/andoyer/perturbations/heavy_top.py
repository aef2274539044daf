r"""The heavy top: a rigid body with a fixed point in a uniform field (Pavlov §1).

With ``γ = Rᵀ s3`` the upward vertical in body components, ``r_c`` the centre
of mass from the fixed point (body components) and ``weight = m g0``,

.. math:: \Delta H = \text{weight}\;\mathbf r_c\cdot\boldsymbol\gamma, \qquad
   \boldsymbol\tau = \text{weight}\;\boldsymbol\gamma\times\mathbf r_c .

The moments of the :class:`~andoyer.RigidBody` are then taken about the fixed
point.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer import _quaternion as quat
from andoyer._validation import as_finite, as_vectors
from andoyer.body import RigidBody
from andoyer.perturbations.base import Perturbation
from andoyer.perturbations.expressions import HeyokaContext, HubRates, Quaternion, Vector

__all__ = [
    "HeavyTop",
    "kovalevskaya_integral",
    "kovalevskaya_integral_e3",
    "kovalevskaya_top",
    "lagrange_top",
]

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

    def _potential(self, t: Array, q: Array, m: Array) -> Array:
        value = self.weight * np.sum(self.gamma(q) * self.center_of_mass, axis=-1)
        return value * np.ones(np.broadcast_shapes(np.shape(t), m.shape[:-1], value.shape))

    def _torque(self, t: Array, q: Array, m: Array) -> Array:
        value = self.weight * quat.cross(self.gamma(q), self.center_of_mass)
        return value * np.ones((*np.broadcast_shapes(np.shape(t), m.shape[:-1], value.shape[:-1]), 3))

    # The term protocol (andoyer.perturbations.base).

    @property
    def tabulable(self) -> bool:
        """Always: ``τ = γ × c`` with ``γ`` the fixed vertical seen in the body."""
        return True

    def uniform_field(self) -> Array:
        """``c = m g0 r_c`` (body components): ``τ = γ × c``."""
        return self.weight * self.center_of_mass

    def hub_rates(self) -> HubRates:
        """``δṁ = γ × c`` with ``γ`` from the quaternion's components."""
        x, y, z = self.uniform_field().tolist()

        def rates(_t: float, q: Quaternion, _m: Vector) -> tuple[None, Vector]:
            qx, qy, qz, qw = q
            g1, g2, g3 = 2 * (qx * qz - qw * qy), 2 * (qy * qz + qw * qx), 1 - 2 * (qx * qx + qy * qy)
            return None, (g2 * z - g3 * y, g3 * x - g1 * z, g1 * y - g2 * x)

        return rates

    @property
    def heyoka_supported(self) -> bool:
        """Always."""
        return True

    def heyoka_rates(self, ctx: HeyokaContext) -> tuple[None, list[list[Any]]]:
        """``δṁ = γ × c`` with ``c`` runtime parameters."""
        par = ctx.par
        x, y, z = (ctx.time_unit * self.weight * self.center_of_mass / ctx.scale).tolist()
        qx, qy, qz, qw = ctx.q
        g = [2 * (qx * qz - qw * qy), 2 * (qy * qz + qw * qx), 1 - 2 * (qx * qx + qy * qy)]
        torque = [g[1] * par(z) - g[2] * par(y), g[2] * par(x) - g[0] * par(z), g[0] * par(y) - g[1] * par(x)]
        return None, [torque]

    def __repr__(self) -> str:
        return f"HeavyTop(weight={self.weight!r}, center_of_mass={self.center_of_mass.tolist()})"


def lagrange_top(A: float, C: float, weight: float, height: float) -> tuple[RigidBody, HeavyTop]:
    """The Lagrange top: ``I1 = I2 = A``, centre of mass on the symmetry axis ``b3`` at ``height``.

    ``M3 = L`` (the momentum about the symmetry axis) is an integral besides the
    energy and the Casimirs ``|γ| = 1`` and ``M·γ``.

    Examples
    --------
    >>> body, top = lagrange_top(1.0, 0.5, 2.0, 0.3)
    >>> body.moments.tolist(), top.center_of_mass.tolist()
    ([1.0, 1.0, 0.5], [0.0, 0.0, 0.3])
    """
    return RigidBody(A, A, C, name="Lagrange top"), HeavyTop(weight, [0.0, 0.0, height])


def kovalevskaya_top(C: float, weight: float, distance: float) -> tuple[RigidBody, HeavyTop]:
    """The Kovalevskaya top: ``I1 = I2 = 2 I3 = 2C``, centre of mass on ``b1`` at ``distance``.

    Examples
    --------
    >>> body, top = kovalevskaya_top(1.0, 1.0, 0.5)
    >>> body.moments.tolist()
    [2.0, 2.0, 1.0]
    """
    return RigidBody(2 * C, 2 * C, C, name="Kovalevskaya top"), HeavyTop(weight, [distance, 0.0, 0.0])


def kovalevskaya_integral(body: RigidBody, top: HeavyTop, quaternion: ArrayLike, m_body: ArrayLike) -> Array:
    r"""Kovalevskaya's integral ``K = (p² - q² - c γ1)² + (2pq - c γ2)²``, ``c = m g0 x0 / I3``.

    ``(p, q, r) = ω`` is the body angular velocity and ``γ`` the upward vertical
    (:meth:`HeavyTop.gamma`), for the top of :func:`kovalevskaya_top`.

    Parameters
    ----------
    body : RigidBody
    top : HeavyTop
    quaternion : array_like, shape (..., 4)
    m_body : array_like, shape (..., 3)

    Returns
    -------
    numpy.ndarray, shape (...)

    Examples
    --------
    >>> body, top = kovalevskaya_top(1.0, 1.0, 0.5)
    >>> float(kovalevskaya_integral(body, top, [0, 0, 0, 1.0], [2.0, 0.0, 0.0]))  # p = 1, γ = e3
    1.0
    """
    q = as_vectors(quaternion, "quaternion", 4)
    return kovalevskaya_integral_e3(body, top, m_body, top.gamma(q))


def kovalevskaya_integral_e3(body: RigidBody, top: HeavyTop, m_body: ArrayLike, gamma: ArrayLike) -> Array:
    r"""Kovalevskaya's integral at points ``(m, γ)`` of e(3): ``(p² - q² - c γ1)² + (2pq - c γ2)²``.

    As :func:`kovalevskaya_integral`, with the vertical ``γ`` given directly
    (any norm), ``(p, q) = (m1/I1, m2/I2)`` and ``c = m g0 x0 / I3``.

    Parameters
    ----------
    body : RigidBody
    top : HeavyTop
    m_body, gamma : array_like, shape (..., 3)

    Returns
    -------
    numpy.ndarray, shape (...)

    Examples
    --------
    >>> body, top = kovalevskaya_top(1.0, 1.0, 0.5)
    >>> float(kovalevskaya_integral_e3(body, top, [2.0, 0.0, 0.0], [0.0, 0.0, 1.0]))
    1.0
    """
    I1, I2, I3 = body.moments
    x0, y0, z0 = top.center_of_mass
    if not (I1 == I2 == 2 * I3 and y0 == 0 and z0 == 0):
        msg = f"expected a Kovalevskaya top (I1 = I2 = 2 I3, centre of mass on b1), got {body!r} and {top!r}"
        raise ValueError(msg)
    m, gamma = as_vectors(m_body, "m_body"), as_vectors(gamma, "gamma")
    p, qq = m[..., 0] / I1, m[..., 1] / I2
    c = top.weight * x0 / I3
    return (p * p - qq * qq - c * gamma[..., 0]) ** 2 + (2 * p * qq - c * gamma[..., 1]) ** 2
