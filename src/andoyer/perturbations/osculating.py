r"""Convective terms, osculating and non-osculating elements (Gurfil et al. §4.2–4.4).

With a momentum-dependent perturbation the canonical (non-osculating) chart
variables no longer give the velocity through the unperturbed formula: the
Euler angles move at ``q̇ = g + ∂ΔH/∂p`` (eqs. 111–118, 127), where
``g = ∂T/∂p`` is the unperturbed velocity and ``∂ΔH/∂p`` the convective term.
On the hub, ``∂ΔH/∂p = (∂ΔH/∂m)·∂m/∂p`` at fixed attitude, with (eqs. 25–27)

.. math::
   \partial\mathbf m/\partial\Phi = (\sin\psi, \cos\psi, 0)/\sin\theta,\quad
   \partial\mathbf m/\partial\Theta = (\cos\psi, -\sin\psi, 0),\quad
   \partial\mathbf m/\partial\Psi = (-\sin\psi\cot\theta, -\cos\psi\cot\theta, 1).

For a precessing frame (``∂ΔH/∂m = -μ_b``) this reproduces eqs. 128–130, and
the body angular velocity of the convective term is exactly ``-μ_b``
(eq. 132; eq. 133 prints ``+μ``, see ``docs/errata.md``): the unperturbed
formula ``ω(g(A)) = I⁻¹ m`` returns the angular velocity relative to
*inertial* space, while the body turns relative to the frame at
``I⁻¹ m - μ_b``.

The *osculating* state shares the attitude and replaces the momentum by the
one whose unperturbed motion is tangent to the perturbed one,
``m_osc = I (I⁻¹ m + ∂ΔH/∂m)``; its chart values are the osculating elements.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._validation import as_vectors
from andoyer.perturbations.model import Model
from andoyer.state import State
from andoyer.state.euler import Euler, EulerRates

__all__ = ["convective_terms", "euler_rates_to_omega", "osculating_state"]

Array = NDArray[np.float64]


def _check(model: Model, state: State) -> None:
    if not isinstance(model, Model):
        msg = f"expected an andoyer Model, got {type(model).__name__}"
        raise ValueError(msg)
    if not isinstance(state, State):
        msg = f"expected an andoyer State, got {type(state).__name__}"
        raise ValueError(msg)


def _momentum_gradient(model: Model, t: ArrayLike, state: State) -> Array:
    perturbation = model.perturbation
    if perturbation is None or perturbation.attitude_only:
        return np.zeros((*state.shape, 3))
    return perturbation.momentum_gradient(t, state.quaternion, state.m_body)


def convective_terms(model: Model, t: ArrayLike, state: State) -> EulerRates:
    """The convective rates ``∂ΔH/∂(Φ, Θ, Ψ)`` of the Euler angles (eqs. 114, 118, 128–130).

    Parameters
    ----------
    model : Model
    t : array_like, shape (...)
    state : State, shape (...)
        Off the Euler singularity ``sin θ = 0``.

    Returns
    -------
    EulerRates
        ``(φ̇, θ̇, ψ̇)`` contributions; the momentum rates are zero (the
        convective term is a velocity correction).

    Examples
    --------
    >>> from andoyer import RigidBody, State
    >>> from andoyer.perturbations import PrecessingFrame
    >>> model = Model(RigidBody(1.0, 1.0, 1.0), PrecessingFrame([0.0, 0.0, 0.5]))
    >>> state = State.from_euler(0.0, 0.3, 0.0, 1.0, 0.0, 1.0)
    >>> rates = convective_terms(model, 0.0, state)
    >>> round(float(rates.phi), 12), round(float(rates.psi), 12)  # the frame's own turn, undone
    (-0.5, 0.0)
    """
    _check(model, state)
    e = state.as_euler()
    st, ct = np.sin(e.theta), np.cos(e.theta)
    if np.any(st == 0):
        msg = "expected sin(theta) != 0 for the Euler-chart convective terms, got a singular state"
        raise ValueError(msg)
    grad = _momentum_gradient(model, t, state)
    sp, cp = np.sin(e.psi), np.cos(e.psi)
    s = grad[..., 0] * sp + grad[..., 1] * cp
    zero = np.zeros_like(s)
    return EulerRates(
        s / st,
        grad[..., 0] * cp - grad[..., 1] * sp,
        -s * ct / st + grad[..., 2],
        zero,
        zero.copy(),
        zero.copy(),
    )


def euler_rates_to_omega(euler: Euler, rates: ArrayLike) -> Array:
    """Body angular velocity from Euler-angle rates (Gurfil eqs. 5–7).

    ``ω1 = φ̇ sin θ sin ψ + θ̇ cos ψ``, ``ω2 = φ̇ sin θ cos ψ - θ̇ sin ψ``,
    ``ω3 = ψ̇ + φ̇ cos θ``.

    Parameters
    ----------
    euler : Euler
        The angles (momenta are ignored).
    rates : array_like, shape (3, ...) or EulerRates
        ``(φ̇, θ̇, ψ̇)``.

    Returns
    -------
    numpy.ndarray, shape (..., 3)

    Examples
    --------
    >>> from andoyer.state import Euler
    >>> e = Euler(0.0, 0.5, 0.0, 0.0, 0.0, 0.0)
    >>> euler_rates_to_omega(e, [0.0, 0.0, 2.0]).tolist()
    [0.0, 0.0, 2.0]
    """
    dphi, dtheta, dpsi = (np.asarray(r, dtype=float) for r in list(rates)[:3])
    st, ct = np.sin(euler.theta), np.cos(euler.theta)
    sp, cp = np.sin(euler.psi), np.cos(euler.psi)
    return np.stack([dphi * st * sp + dtheta * cp, dphi * st * cp - dtheta * sp, dpsi + dphi * ct], axis=-1)


def osculating_state(model: Model, t: ArrayLike, state: State) -> State:
    """The osculating state: same attitude, momentum ``I (I⁻¹ m + ∂ΔH/∂m)``.

    Its unperturbed motion is tangent to the perturbed one at time ``t``;
    ``osculating_state(...).as_andoyer()`` gives the osculating Andoyer
    elements and the difference from ``state.as_andoyer()`` is the
    correction between the two sets. Attitude-only models leave the state
    unchanged (their canonical elements osculate).

    Parameters
    ----------
    model : Model
    t : array_like, shape (...)
    state : State, shape (...)

    Returns
    -------
    State

    Examples
    --------
    >>> from andoyer import RigidBody, State
    >>> from andoyer.perturbations import PrecessingFrame
    >>> model = Model(RigidBody(1.0, 1.0, 2.0), PrecessingFrame([0.0, 0.0, 0.5]))
    >>> osculating_state(model, 0.0, State.from_quaternion([0, 0, 0, 1.0], [0, 0, 3.0])).m_body.tolist()
    [0.0, 0.0, 2.0]
    """
    _check(model, state)
    grad = as_vectors(_momentum_gradient(model, t, state), "momentum gradient")
    return State.from_quaternion(state.quaternion, state.m_body + model.body.moments * grad)
