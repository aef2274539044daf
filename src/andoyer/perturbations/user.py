r"""Models the user writes: a potential of the attitude, or a torque (possibly dissipative).

``UserPotential`` derives its torque from ``V`` by central differences on body
rotations unless an analytic torque is given:
``τ_i = -[V(q ⊗ e^{+h e_i/2}) - V(q ⊗ e^{-h e_i/2})] / (2h)``.
"""

from __future__ import annotations

import copy
import warnings
from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.spatial.transform import Rotation

from andoyer import _quaternion as quat
from andoyer._validation import as_finite, as_vectors
from andoyer.body import RigidBody
from andoyer.perturbations.base import Perturbation
from andoyer.perturbations.expressions import HeyokaContext, HubRates, Quaternion, Vector

__all__ = ["LinearDamping", "UserPotential", "UserTorque"]

Array = NDArray[np.float64]


def _check_callable(function: object, what: str) -> None:
    if not callable(function):
        msg = f"expected a callable {what}, got {type(function).__name__}"
        raise ValueError(msg)


class UserPotential(Perturbation):
    """A potential ``V(rotation, t)`` of the attitude, with an optional analytic torque.

    Parameters
    ----------
    potential : callable
        ``potential(rotation, t) -> (...)`` with ``rotation`` a
        :class:`scipy.spatial.transform.Rotation` of shape (...) (body → reference).
    torque : callable, optional
        ``torque(rotation, t) -> (..., 3)`` in body components; by default
        central differences of ``potential`` with step ``step`` radians.
    step : float
        Finite-difference step (radians); the truncation error is ``O(step²)``.

    Examples
    --------
    >>> import numpy as np
    >>> gamma = lambda rot: rot.inv().apply([0.0, 0.0, 1.0])
    >>> top = UserPotential(lambda rot, t: 2.0 * gamma(rot)[..., 2])
    >>> q = Rotation.from_euler("x", 0.3).as_quat()
    >>> (np.round(top.torque(0.0, q, [0, 0, 1.0]), 8) + 0.0).tolist()  # = 2 γ × e3
    [0.59104041, 0.0, 0.0]
    """

    hamiltonian = True
    attitude_only = True

    def __init__(
        self,
        potential: Callable[[Rotation, Array], ArrayLike],
        torque: Callable[[Rotation, Array], ArrayLike] | None = None,
        step: float = 1e-5,
    ) -> None:
        _check_callable(potential, "potential(rotation, t)")
        if torque is not None:
            _check_callable(torque, "torque(rotation, t)")
        self._user_potential = potential
        self._user_torque = torque
        self.step = float(step)

    def _value(self, t: ArrayLike, q: Array) -> Array:
        return as_finite(self._user_potential(Rotation.from_quat(q), t), "potential(rotation, t)")

    def _potential(self, t: Array, q: Array, m: Array) -> Array:
        return self._value(t, q) * np.ones(m.shape[:-1])

    def _torque(self, t: Array, q: Array, m: Array) -> Array:
        if self._user_torque is not None:
            return as_vectors(self._user_torque(Rotation.from_quat(q), t), "torque(rotation, t)")
        h = self.step
        out = []
        for axis in np.eye(3):
            plus = quat.multiply(q, np.append(np.sin(h / 2) * axis, np.cos(h / 2)))
            minus = quat.multiply(q, np.append(-np.sin(h / 2) * axis, np.cos(h / 2)))
            out.append(-(self._value(t, plus) - self._value(t, minus)) / (2 * h))
        return np.stack(np.broadcast_arrays(*out), axis=-1) * np.ones_like(m)


def _body_and(args: tuple[Any, ...], name: str) -> tuple[RigidBody | None, Any]:
    """``(body, value)`` of the former signature ``name(body, value)``, or ``(None, value)``."""
    if len(args) == 2:
        if not isinstance(args[0], RigidBody):
            msg = f"expected an andoyer.RigidBody, got {type(args[0]).__name__}"
            raise ValueError(msg)
        return args[0], args[1]
    if len(args) == 1:
        return None, args[0]
    msg = f"expected {name}(value) (the body comes from the Model), got {len(args)} arguments"
    raise ValueError(msg)


def _warn_body(name: str) -> None:
    warnings.warn(
        f"{name}(body, ...) is deprecated: give the body to the Model, Model(body, {name}(...))",
        DeprecationWarning,
        stacklevel=3,
    )


class _BodyTerm(Perturbation):
    """A term that reads the model's body (``ω = I⁻¹ m``): bound by :meth:`bind`."""

    _body: RigidBody | None = None

    @property
    def body(self) -> RigidBody:
        """The body the term acts on (its model's); ``ValueError`` before it is bound."""
        if self._body is None:
            msg = (
                f"expected a {type(self).__name__} bound to a body (inside a Model, or through bind(body)), "
                "got an unbound term"
            )
            raise ValueError(msg)
        return self._body

    def bind(self, body: RigidBody) -> _BodyTerm:
        """The term on ``body``; ``ValueError`` if it was built for a body of other moments."""
        if self._body is not None:
            if not np.array_equal(self._body.moments, body.moments):
                msg = f"expected the torque model to act on the model's body {body!r}, got {self._body!r}"
                raise ValueError(msg)
            return self
        bound = copy.copy(self)
        bound._body = body
        return bound


class UserTorque(_BodyTerm):
    """A torque ``u(t, rotation, omega)`` in body components; not Hamiltonian in general.

    The body (to form ``ω = I⁻¹ m``) is the model's: ``Model(body, UserTorque(torque))``, or
    ``UserTorque(torque).bind(body)`` alone. ``UserTorque(body, torque)``, the former signature,
    still works with a ``DeprecationWarning``.

    Parameters
    ----------
    torque : callable
        ``torque(t, rotation, omega) -> (..., 3)``.

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> spin_up = UserTorque(lambda t, rot, w: np.array([0.0, 0.0, 1.0])).bind(RigidBody(1, 1, 1))
    >>> spin_up.torque(0.0, [0, 0, 0, 1.0], [0, 0, 0.0]).tolist()
    [0.0, 0.0, 1.0]
    """

    hamiltonian = False
    attitude_only = False

    def __init__(self, torque: Callable[[Array, Rotation, Array], ArrayLike], *deprecated: Any) -> None:
        # ``UserTorque(body, torque)``, the former signature, arrives as (body, (torque,)).
        body, torque = _body_and((torque, *deprecated), "UserTorque")
        _check_callable(torque, "torque(t, rotation, omega)")
        self._body = body
        self._user_torque = torque
        if body is not None:
            _warn_body("UserTorque")

    def _torque(self, t: Array, q: Array, m: Array) -> Array:
        value = self._user_torque(t, Rotation.from_quat(q), m / self.body.moments)
        return as_vectors(value, "torque(t, rotation, omega)") * np.ones_like(m)


class LinearDamping(UserTorque):
    """Linear damping of the body angular velocity, ``τ = -c ω`` (``c >= 0``, per axis or scalar).

    ``LinearDamping(coefficient)``; the body is the model's (``LinearDamping(body, coefficient)``,
    the former signature, still works with a ``DeprecationWarning``).

    Examples
    --------
    >>> from andoyer import RigidBody
    >>> damping = LinearDamping(0.1).bind(RigidBody(1, 2, 2.5))
    >>> damping.torque(0.0, [0, 0, 0, 1.0], [1.0, 2.0, 5.0]).tolist()
    [-0.1, -0.1, -0.2]
    """

    def __init__(self, coefficient: ArrayLike, *deprecated: Any) -> None:
        # ``LinearDamping(body, coefficient)``, the former signature, arrives as (body, (coefficient,)).
        body, coefficient = _body_and((coefficient, *deprecated), "LinearDamping")
        c = as_finite(coefficient, "coefficient")
        if np.any(c < 0) or c.shape not in {(), (3,)}:
            msg = f"expected a non-negative scalar or 3-vector coefficient, got {c.tolist()!r}"
            raise ValueError(msg)
        self.coefficient = c
        self._body = body
        self._user_torque = lambda _t, _rot, w: -c * w
        if body is not None:
            _warn_body("LinearDamping")

    # The term protocol (andoyer.perturbations.base).

    def hub_rates(self) -> HubRates:
        """``δṁ = −c m/I`` on components."""
        c = np.broadcast_to(self.coefficient, 3).tolist()
        I = self.body.moments.tolist()

        def rates(_t: float, _q: Quaternion, m: Vector) -> tuple[None, Vector]:
            return None, (-c[0] * (m[0] / I[0]), -c[1] * (m[1] / I[1]), -c[2] * (m[2] / I[2]))

        return rates

    @property
    def heyoka_supported(self) -> bool:
        """Always."""
        return True

    def heyoka_rates(self, ctx: HeyokaContext) -> tuple[None, list[list[Any]]]:
        """``δṁ = −(c/I) m`` with ``c/I`` runtime parameters."""
        damping = np.broadcast_to(ctx.time_unit * self.coefficient * self.body.inverse_moments, 3).tolist()
        return None, [[-ctx.par(damping[i]) * ctx.m[i] for i in range(3)]]
