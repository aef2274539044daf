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
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer import _quaternion as quat
from andoyer._validation import as_vectors
from andoyer.perturbations.base import Perturbation
from andoyer.perturbations.expressions import HeyokaContext, HubRates, Quaternion, Vector, to_body

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

    # The term protocol (andoyer.perturbations.base).

    @property
    def splitting_flow(self) -> str:
        """``"frame"``: the exact flow of ``−μ·M`` turns the attitude and commutes with the free flow."""
        return "frame"

    def frame_rate(self, t: Array) -> Array:
        """``μ(t)``, shape (..., 3) (as :meth:`rate`)."""
        return self.rate(t)

    def secular_average(self) -> FrameAverage:
        """Itself: ``ΔH = −μ·M`` does not depend on the fast angles (``dM̄/dt = M̄ × μ``)."""
        return FrameAverage(self)

    def hub_rates(self) -> HubRates:
        """``δω = −μ_b``; ``∂ΔH/∂m`` and the torque cancel exactly in ``ṁ`` (eq. 132): neither is formed."""
        constant = None if self._constant is None else self._constant.tolist()

        def rates(t: float, q: Quaternion, _m: Vector) -> tuple[Vector, None]:
            mu = constant or self.rate(t).reshape(3).tolist()
            bx, by, bz = to_body(q, mu)
            return (-bx, -by, -bz), None

        return rates

    @property
    def heyoka_supported(self) -> bool:
        """A constant rate only."""
        return self._function is None

    def heyoka_rates(self, ctx: HeyokaContext) -> tuple[list[Any], list[list[Any]]]:
        """``δω = −Rᵀ μ`` (``μ`` runtime parameters)."""
        mu = to_body(ctx.q, [ctx.par(ctx.time_unit * v) for v in self._constant.tolist()])
        return [-mu[0], -mu[1], -mu[2]], []

    def __repr__(self) -> str:
        return f"PrecessingFrame({'<function>' if self._function else self._constant.tolist()})"


class FrameAverage:
    """The average of a precessing frame over the fast angles: itself, ``dM̄/dt = M̄ × μ(t)``."""

    #: Not propagated by the compiled rotations of the gravity gradient's average (DOP853 instead).
    exact_rotations = False

    def __init__(self, frame: PrecessingFrame) -> None:
        self.frame = frame

    def momentum_rate(self, t: ArrayLike, M: Array, L: Array) -> Array:  # noqa: ARG002 - the protocol's
        """``M × μ(t)``, shape (..., 3) (``L`` unused)."""
        return quat.cross(M, self.frame.rate(np.asarray(t)))
