r"""The disturbing-model interface and the sum of models.

A model adds to the free Hamiltonian ``T = ½ m·I⁻¹m`` a term ``ΔH(t, q, m)`` of
the attitude quaternion ``q`` (body → reference) and the body angular momentum
``m``, or a non-Hamiltonian torque. On the hub ``(q, m)`` the equations of
motion of ``K = T + ΔH`` are

.. math::
   \dot q = \tfrac12\, q \otimes (\partial K/\partial \mathbf m,\ 0), \qquad
   \dot{\mathbf m} = \mathbf m \times \partial K/\partial \mathbf m + \boldsymbol\tau ,

where ``τ`` is the torque of the attitude dependence, defined by
``δΔH = -τ·δθ`` for a body-frame rotation ``q → q ⊗ exp(δθ/2)``. A model
therefore supplies ``potential`` (``ΔH``), ``momentum_gradient``
(``∂ΔH/∂m``, zero for attitude-only models) and ``torque``.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._validation import as_finite, as_vectors

__all__ = ["Perturbation", "SumOfPerturbations"]

Array = NDArray[np.float64]


class Perturbation:
    """Base class of disturbing models.

    Subclasses implement the raw methods ``_potential``, ``_momentum_gradient``
    and ``_torque`` on validated float arrays; the public methods check their
    arguments once and call them, and integrators call the raw methods in
    their inner loops.

    Attributes
    ----------
    hamiltonian : bool
        ``True`` if the model derives from a Hamiltonian term ``ΔH`` (then
        :meth:`potential` is defined); ``False`` for dissipative or user torques.
    attitude_only : bool
        ``True`` if ``ΔH`` depends on the attitude (and time) only: its flow is
        then a kick of the body angular momentum, ``m → m + τ dt``, exactly.
    """

    hamiltonian: bool = True
    attitude_only: bool = True

    def potential(self, t: ArrayLike, q: ArrayLike, m: ArrayLike) -> Array:
        """``ΔH`` at times ``t`` (...), attitudes ``q`` (..., 4) and body momenta ``m`` (..., 3)."""
        if not self.hamiltonian:
            msg = f"expected a Hamiltonian model for potential(), got {type(self).__name__}"
            raise ValueError(msg)
        q, m = hub_arrays(q, m)
        return self._potential(times(t), q, m)

    def momentum_gradient(self, t: ArrayLike, q: ArrayLike, m: ArrayLike) -> Array:
        """``∂ΔH/∂m`` in body components, shape (..., 3); zero for attitude-only models."""
        q, m = hub_arrays(q, m)
        return self._momentum_gradient(times(t), q, m)

    def torque(self, t: ArrayLike, q: ArrayLike, m: ArrayLike) -> Array:
        """Torque in body components, shape (..., 3)."""
        q, m = hub_arrays(q, m)
        return self._torque(times(t), q, m)

    def _potential(self, t: Array, q: Array, m: Array) -> Array:
        raise NotImplementedError

    def _momentum_gradient(self, t: Array, q: Array, m: Array) -> Array:
        return np.zeros((*np.broadcast_shapes(np.shape(t), q.shape[:-1], m.shape[:-1]), 3))

    def _torque(self, t: Array, q: Array, m: Array) -> Array:
        raise NotImplementedError

    def __add__(self, other: Perturbation) -> SumOfPerturbations:
        return SumOfPerturbations([self, other])


class SumOfPerturbations(Perturbation):
    """Several models acting at once (e.g. the Sun and the Moon, plus a precessing frame).

    Examples
    --------
    >>> from andoyer.perturbations import HeavyTop
    >>> model = HeavyTop(1.0, [0, 0, 1]) + HeavyTop(2.0, [0, 0, 1])
    >>> float(model.potential(0.0, [0, 0, 0, 1.0], [0, 0, 1.0]))
    3.0
    """

    def __init__(self, models: Sequence[Perturbation]) -> None:
        flat: list[Perturbation] = []
        for model in models:
            if not isinstance(model, Perturbation):
                msg = f"expected Perturbation models, got {type(model).__name__}"
                raise ValueError(msg)
            flat.extend(model.models if isinstance(model, SumOfPerturbations) else [model])
        self.models = tuple(flat)
        self.hamiltonian = all(m.hamiltonian for m in flat)
        self.attitude_only = all(m.attitude_only for m in flat)

    def _potential(self, t: Array, q: Array, m: Array) -> Array:
        return sum(model._potential(t, q, m) for model in self.models)

    def _momentum_gradient(self, t: Array, q: Array, m: Array) -> Array:
        return sum(model._momentum_gradient(t, q, m) for model in self.models)

    def _torque(self, t: Array, q: Array, m: Array) -> Array:
        return sum(model._torque(t, q, m) for model in self.models)

    def __repr__(self) -> str:
        return " + ".join(repr(m) for m in self.models)


def hub_arrays(q: ArrayLike, m: ArrayLike) -> tuple[Array, Array]:
    """Validate attitude quaternions (..., 4) and body momenta (..., 3)."""
    return as_vectors(q, "quaternion", 4), as_vectors(m, "m_body", 3)


def times(t: ArrayLike) -> Array:
    """Validate times."""
    return as_finite(t, "t")
