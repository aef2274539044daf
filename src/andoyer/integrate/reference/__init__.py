r"""The reference method: DOP853 or heyoka on the attitude quaternion and the body angular momentum.

``andoyer.propagate(..., method="reference")`` is :func:`integrate_reference`: the hub
equations (:func:`andoyer.perturbations.perturbed_rates`, free part ``ṁ_1 = c_1 m_2 m_3``
written without cancellation, ``q̇ = ½ q ⊗ (ω, 0)`` scalar last). With DOP853
(:mod:`andoyer.integrate.reference.dop853`) the state vector of ``N`` bodies is integrated as
one system of ``7N`` equations with dense output to reach every requested time. With
heyoka (:mod:`andoyer.integrate.reference.heyoka`) each body has its own Taylor
integration, compiled once per model structure, in SIMD batches. The quaternion is
renormalised on output only: the flow preserves ``|q|`` and the error control keeps the
drift at the tolerance. The heavy top also has its own reference integrator on e(3),
:mod:`andoyer.integrate.reference.euler_poisson`.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from andoyer._validation import as_finite
from andoyer.integrate.output import gather_states, output_times
from andoyer.integrate.reference.dop853 import dop853_values
from andoyer.integrate.reference.heyoka import heyoka_values
from andoyer.perturbations.model import Model
from andoyer.state import State

__all__ = ["integrate_reference"]

Array = NDArray[np.float64]

#: The integrators of :func:`integrate_reference`.
METHODS = ("dop853", "heyoka")


def integrate_reference(
    model: Model,
    state: State,
    t: ArrayLike,
    t0: float = 0.0,
    rtol: float | None = None,
    atol: float | None = None,
    method: str = "dop853",
) -> State:
    """Propagate ``state`` (at time ``t0``) under ``model`` to times ``t`` with DOP853 or heyoka.

    Parameters
    ----------
    model : Model
    state : State, shape (S...)
    t : array_like, shape (T...)
        Output times; they broadcast with the state's shape.
    t0 : float
        Time of ``state``.
    rtol, atol : float, optional
        DOP853 tolerances, default ``1e-12`` and ``1e-14``; ``atol`` applies to
        quaternion components and, scaled by the largest ``|m|``, to the
        momenta. For heyoka, ``rtol`` is its single tolerance (default: machine
        epsilon; quaternion and ``m/max|m|`` alike) and ``atol`` must be ``None``.
    method : {"dop853", "heyoka"}
        scipy's DOP853 (any model), or heyoka's Taylor integrator (optional
        dependency; gravity gradients of Kepler and circular orbits,
        constant-rate precessing frames, heavy tops and linear damping).

    Returns
    -------
    State, shape broadcast(S..., T...)

    Raises
    ------
    ValueError
        For bad input, an unknown method, heyoka missing, a model heyoka cannot
        express, or a failed integration.

    Examples
    --------
    >>> from andoyer import RigidBody, State
    >>> body = RigidBody(1.0, 2.0, 2.5)
    >>> s = State.from_quaternion([0, 0, 0, 1.0], [0.0, 0.0, 2.0])  # steady spin about b3
    >>> out = integrate_reference(Model(body), s, [0.0, 1.0])
    >>> out.m_body.round(12).tolist()
    [[0.0, 0.0, 2.0], [0.0, 0.0, 2.0]]
    """
    if not isinstance(model, Model):
        msg = f"expected an andoyer Model, got {type(model).__name__}"
        raise ValueError(msg)
    if not isinstance(state, State):
        msg = f"expected an andoyer State, got {type(state).__name__}"
        raise ValueError(msg)
    if method not in METHODS:
        msg = f"expected method in {METHODS}, got {method!r}"
        raise ValueError(msg)
    t0 = float(as_finite(t0, "t0"))
    times, unique, shape = output_times(state, t, model.body.moments, t0)
    q0 = state.quaternion.reshape(-1, 4)
    m0 = state.m_body.reshape(-1, 3)
    if method == "heyoka":
        if atol is not None:
            msg = f"expected atol=None with method='heyoka' (one tolerance, rtol), got {atol!r}"
            raise ValueError(msg)
        values = heyoka_values(model, q0, m0, t0, unique, rtol)
    else:
        values = dop853_values(
            model, q0, m0, t0, unique, 1e-12 if rtol is None else rtol, 1e-14 if atol is None else atol
        )
    for time in unique:
        if time == t0:
            values[float(time)] = (q0, m0)
    return gather_states(state, times, unique, shape, values)
