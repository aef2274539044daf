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

**The term protocol.** Each term also carries the pieces the integrators need,
so that no integrator asks what type a term is:

* :meth:`~Perturbation.bind` — the term given the model's body (the body is given
  once, to :class:`~andoyer.perturbations.Model`);
* :meth:`~Perturbation.hub_rates` — its share ``(δω, δṁ)`` of the hub equations on
  components (the reference DOP853 path), :meth:`~Perturbation.heyoka_rates` — the
  same as heyoka expressions, or ``None`` where it has none;
* :attr:`~Perturbation.splitting_flow` — ``"kick"`` (the exact flow
  ``m → m + τ(t, q) h`` of an attitude-only ``ΔH``, through :meth:`~Perturbation.kick`),
  ``"frame"`` (a rotation of the attitude, ``q → exp(−μ h/2) ⊗ q``, that commutes
  with the free flow, through :meth:`~Perturbation.frame_rate`) or ``None``;
  :meth:`~Perturbation.point_masses` and :meth:`~Perturbation.uniform_field` describe a
  kick the compiled loop can tabulate (:attr:`~Perturbation.tabulable`);
* :meth:`~Perturbation.secular_average` — the averaged term over the fast angles
  (an object with ``momentum_rate(t, M, L)``), or ``None``.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._validation import as_finite, as_vectors
from andoyer.perturbations.expressions import HeyokaContext, HubRates, Quaternion, Vector

if TYPE_CHECKING:
    from andoyer.body import RigidBody
    from andoyer.perturbations.point_mass import PointMass

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

    # The term protocol (see the module docstring): what the integrators call.

    def bind(self, body: RigidBody) -> Perturbation:  # noqa: ARG002 - terms that need the body override it
        """The term acting on ``body`` (itself when it does not use the body).

        Raises ``ValueError`` when the term was built for another body.
        """
        return self

    @property
    def splitting_flow(self) -> str | None:
        """``"kick"``, ``"frame"`` or ``None``: how a splitting step takes this term's exact flow."""
        return "kick" if self.hamiltonian and self.attitude_only else None

    def kick(self, t: Array, q: Array, m: Array) -> Array:
        """The torque ``τ(t, q)`` of a kick term on validated arrays (no checks), shape (..., 3)."""
        return self._torque(t, q, m)

    def frame_rate(self, t: Array) -> Array:  # noqa: ARG002 - frame terms override it
        """``μ(t)`` of a frame term (:attr:`splitting_flow` ``== "frame"``), shape (..., 3)."""
        msg = f"expected a precessing-frame term for frame_rate(), got {self!r}"
        raise ValueError(msg)

    @property
    def tabulable(self) -> bool:
        """``True`` when the kick is ``Σ_p`` point-mass gravity gradients plus ``γ × c`` (compiled loop)."""
        return False

    def point_masses(self) -> tuple[tuple[PointMass, Array], ...]:
        """The ``(perturber, moments)`` pairs of a tabulable gravity-gradient kick."""
        return ()

    def uniform_field(self) -> Array | None:
        """``c`` of a kick ``τ = γ × c`` in a uniform field along ``s3`` (body components), or ``None``."""
        return None

    def secular_average(self) -> Any | None:
        """The term averaged over the fast angles (``momentum_rate(t, M, L)``), or ``None``."""
        return None

    @property
    def heyoka_supported(self) -> bool:
        """``True`` when :meth:`heyoka_rates` can write this term (asked before heyoka is imported)."""
        return False

    def heyoka_rates(self, ctx: HeyokaContext) -> tuple[list[Any] | None, list[list[Any]]]:  # noqa: ARG002
        """``(δω or None, [δṁ, …])`` as heyoka expressions, rates multiplied by ``T``.

        The torques come as a list (one per source) that the integrator sums with the others.
        """
        msg = f"expected a term with a heyoka form, got {self!r}"
        raise ValueError(msg)

    def hub_rates(self) -> HubRates:
        """``(δω, δṁ)`` of the hub equations on components (floats or arrays (N,)).

        The generic form through :meth:`momentum_gradient` and :meth:`torque`: with
        ``g = ∂ΔH/∂m``, ``δω = g`` and ``δṁ = m × g + τ``.
        """

        def rates(t: float, qc: Quaternion, mc: Vector) -> tuple[Vector | None, Vector]:
            q, m = np.stack(np.broadcast_arrays(*qc), -1), np.stack(np.broadcast_arrays(*mc), -1)
            torque = np.broadcast_to(self._torque(t, q, m), m.shape)
            if self.attitude_only:
                return None, (torque[..., 0], torque[..., 1], torque[..., 2])
            g = np.broadcast_to(self._momentum_gradient(t, q, m), m.shape)
            m1, m2, m3 = mc
            g1, g2, g3 = g[..., 0], g[..., 1], g[..., 2]
            rate = (
                m2 * g3 - m3 * g2 + torque[..., 0],
                m3 * g1 - m1 * g3 + torque[..., 1],
                m1 * g2 - m2 * g1 + torque[..., 2],
            )
            return (g1, g2, g3), rate

        return rates

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

    def bind(self, body: RigidBody) -> SumOfPerturbations:
        """Every member bound to ``body`` (see :meth:`Perturbation.bind`)."""
        bound = [model.bind(body) for model in self.models]
        if all(a is b for a, b in zip(bound, self.models, strict=True)):
            return self
        return SumOfPerturbations(bound)

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
