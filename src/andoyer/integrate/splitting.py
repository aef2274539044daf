r"""Symplectic splitting: the exact free flow composed with the flow of ``ΔH``.

``K = T + V + F`` with ``T`` the free Hamiltonian, ``V(t, q)`` the
attitude-only terms and ``F = -μ·M`` a precessing frame. Their flows are
exact:

* ``T``: the closed-form torque-free motion (:class:`andoyer.free.FreeMotion`);
* ``V``: a kick of the body momentum, ``m → m + τ(t, q) h`` (``q`` fixed);
* ``F``: a rotation of the attitude about the frame's axis,
  ``q → exp(-μ h/2) ⊗ q`` (``m`` fixed) — exact for a constant ``μ``; a
  time-dependent ``μ(t)`` is taken at the substep's midpoint, which keeps the
  scheme second order in the frame term.

``F`` commutes with ``T`` (the free flow conserves the inertial momentum
``M``), so a step of the symmetric Strang scheme is
``S(h) = V(h/2) ∘ F(h) ∘ T(h) ∘ V(h/2)``; orders 4 and 6 are Yoshida's
triple-jump compositions of ``S`` (Yoshida 1990, solution A for order 6).
Time enters the kicks at the substep's time, the free flow advancing it.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer import _quaternion as quat
from andoyer.integrate.output import gather_states, output_times
from andoyer.perturbations.base import Perturbation, SumOfPerturbations
from andoyer.perturbations.frame import PrecessingFrame
from andoyer.perturbations.model import Model
from andoyer.state import State

__all__ = ["COMPOSITIONS", "integrate_splitting", "split_step", "splitting_coefficients"]

Array = NDArray[np.float64]


def _triple_jump(inner: list[float], order: int) -> list[float]:
    root = 2.0 ** (1.0 / (order + 1))
    outer = 1.0 / (2.0 - root)
    middle = -root / (2.0 - root)
    return [w * outer for w in inner] + [w * middle for w in inner] + [w * outer for w in inner]


#: Yoshida (1990) solution A: the 7-stage 6th-order composition of Strang steps.
_YOSHIDA6_A = (-1.17767998417887, 0.235573213359357, 0.784513610477560)


def splitting_coefficients(order: int) -> list[float]:
    """Fractions of the step taken by each Strang substep for an ``order``-th order scheme.

    Examples
    --------
    >>> splitting_coefficients(2)
    [1.0]
    >>> round(sum(splitting_coefficients(6)), 14)
    1.0
    """
    if order == 2:
        return [1.0]
    if order == 4:
        return _triple_jump([1.0], 2)
    if order == 6:
        w1, w2, w3 = _YOSHIDA6_A
        w0 = 1.0 - 2.0 * (w1 + w2 + w3)
        return [w3, w2, w1, w0, w1, w2, w3]
    msg = f"expected a splitting order of 2, 4 or 6, got {order!r}"
    raise ValueError(msg)


COMPOSITIONS = {order: splitting_coefficients(order) for order in (2, 4, 6)}


def _parts(perturbation: Perturbation | None) -> tuple[list[Perturbation], list[PrecessingFrame]]:
    models = (
        []
        if perturbation is None
        else (list(perturbation.models) if isinstance(perturbation, SumOfPerturbations) else [perturbation])
    )
    kicks, frames = [], []
    for model in models:
        if isinstance(model, PrecessingFrame):
            frames.append(model)
        elif model.hamiltonian and model.attitude_only:
            kicks.append(model)
        else:
            msg = (
                "expected Hamiltonian attitude-only models or precessing frames for splitting, "
                f"got {model!r} (use method='reference')"
            )
            raise ValueError(msg)
    return kicks, frames


FreeFlow = Callable[[Array, Array, Array, float], tuple[Array, Array]]


def split_step(
    model: Model, free_flow: FreeFlow, t: float, q: Array, m: Array, h: float, order: int = 2
) -> tuple[Array, Array]:
    """Advance attitudes ``q`` (N, 4) and momenta ``m`` (N, 3) from ``t`` by one step ``h``.

    ``free_flow(moments, q, m, h) -> (q, m)`` is the exact torque-free flow.
    """
    kicks, frames = _parts(model.perturbation)
    moments = model.body.moments
    time = t
    for weight in COMPOSITIONS[order]:
        sub = weight * h
        for kick in kicks:
            m = m + kick._torque(np.asarray(time), q, m) * (0.5 * sub)
        q, m = free_flow(moments, q, m, sub)
        for frame in frames:
            mu = frame.rate(np.asarray(time + 0.5 * sub))
            angle = -np.asarray(mu) * sub
            norm = np.linalg.norm(angle, axis=-1, keepdims=True)
            half = 0.5 * norm
            axis = np.divide(angle, norm, out=np.zeros_like(angle), where=norm > 0)
            turn = np.concatenate([np.sin(half) * axis, np.cos(half)], axis=-1)
            q = quat.multiply(np.broadcast_to(turn, q.shape), q)
        time = time + sub
        for kick in kicks:
            m = m + kick._torque(np.asarray(time), q, m) * (0.5 * sub)
    return q, m


def exact_free_flow(moments: Array, q: Array, m: Array, h: float) -> tuple[Array, Array]:
    """The closed-form torque-free flow over ``h`` of attitudes (N, 4) and momenta (N, 3)."""
    from andoyer.free import FreeMotion

    m_new, q_new = FreeMotion(moments, m, q).propagate(h)
    return q_new, m_new


def integrate_splitting(
    model: Model,
    state: State,
    t: ArrayLike,
    step: float,
    order: int = 4,
    t0: float = 0.0,
) -> State:
    """Propagate ``state`` (at ``t0``) under ``model`` to times ``t`` by symmetric splitting.

    Fixed steps of length ``step`` (the last step to each output time is
    shortened to land on it), each a composition of :func:`split_step` of
    order 2, 4 or 6. The output broadcasts the state's shape with ``t``'s.

    Parameters
    ----------
    model : Model
        Body plus attitude-only Hamiltonian models and/or precessing frames.
    state : State, shape (S...)
    t : array_like, shape (T...)
    step : float
        Step length (> 0).
    order : {2, 4, 6}
    t0 : float

    Returns
    -------
    State, shape broadcast(S..., T...)
    """
    if not isinstance(model, Model):
        msg = f"expected an andoyer Model, got {type(model).__name__}"
        raise ValueError(msg)
    if not (np.isfinite(step) and step > 0):
        msg = f"expected a positive finite step, got {step!r}"
        raise ValueError(msg)
    splitting_coefficients(order)
    _parts(model.perturbation)
    times, unique, shape = output_times(state, t)
    q0 = state.quaternion.reshape(-1, 4)
    m0 = state.m_body.reshape(-1, 3)
    values: dict[float, tuple[Array, Array]] = {}
    for direction in (1.0, -1.0):
        targets = np.sort(unique[(unique - t0) * direction > 0])[:: int(direction)]
        q, m, now = q0, m0, t0
        for target in targets:
            while (target - now) * direction > 0:
                h = direction * min(step, abs(target - now))
                q, m = split_step(model, exact_free_flow, now, q, m, h, order)
                now = target if abs(target - (now + h)) <= 1e-12 * max(1.0, abs(target)) else now + h
            values[float(target)] = (q, m)
    for time in unique:
        if time == t0:
            values[float(time)] = (q0, m0)
    return gather_states(state, times, unique, shape, values)
