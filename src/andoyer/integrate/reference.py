r"""Reference integration: DOP853 on the attitude quaternion and the body angular momentum.

The state vector of ``N`` bodies is integrated as one system of ``7N``
equations (:func:`andoyer.perturbations.perturbed_rates`, free part written
without cancellation), with dense output to reach every requested time. The
quaternion is renormalised on output only: the flow preserves ``|q|`` and
DOP853's error control keeps the drift at the tolerance.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.integrate import solve_ivp

from andoyer._validation import as_finite
from andoyer.integrate.output import gather_states, output_times
from andoyer.integrate.reference_heyoka import _propagate_heyoka
from andoyer.perturbations.equations import _perturbed_rates
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
    """Propagate ``state`` (at time ``t0``) under ``model`` to times ``t`` with DOP853.

    Parameters
    ----------
    model : Model
    state : State, shape (S...)
    t : array_like, shape (T...)
        Output times; they broadcast with the state's shape.
    t0 : float
        Time of ``state``.
    rtol, atol : float
        DOP853 tolerances; ``atol`` applies to quaternion components and,
        scaled by the largest ``|m|``, to the momenta.

    Returns
    -------
    State, shape broadcast(S..., T...)

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
    times, unique, shape = output_times(state, t)
    t0 = float(as_finite(t0, "t0"))
    q0 = state.quaternion.reshape(-1, 4)
    m0 = state.m_body.reshape(-1, 3)
    if method == "heyoka":
        if atol is not None:
            msg = f"expected atol=None with method='heyoka' (one tolerance, rtol), got {atol!r}"
            raise ValueError(msg)
        values = _heyoka_values(model, q0, m0, t0, unique, rtol)
    else:
        values = _dop853_values(
            model, q0, m0, t0, unique, 1e-12 if rtol is None else rtol, 1e-14 if atol is None else atol
        )
    for time in unique:
        if time == t0:
            values[float(time)] = (q0, m0)
    return gather_states(state, times, unique, shape, values)


def _heyoka_values(
    model: Model, q0: Array, m0: Array, t0: float, unique: Array, rtol: float | None
) -> dict[float, tuple[Array, Array]]:
    values: dict[float, tuple[Array, Array]] = {}
    for targets in (unique[unique > t0], unique[unique < t0][::-1]):
        if targets.size:
            q, m = _propagate_heyoka(model, q0, m0, t0, targets, rtol)
            values.update((float(time), (q[k], m[k])) for k, time in enumerate(targets))
    return values


def _dop853_values(
    model: Model, q0: Array, m0: Array, t0: float, unique: Array, rtol: float, atol: float
) -> dict[float, tuple[Array, Array]]:
    n = q0.shape[0]
    scale = max(float(np.max(np.linalg.norm(m0, axis=-1), initial=0.0)), np.finfo(float).tiny)
    atol_vec = np.concatenate([np.full(4 * n, atol), np.full(3 * n, atol * scale)])
    perturbation = model.perturbation
    body = model.body

    def rhs(time: float, y: Array) -> Array:
        dq, dm = _perturbed_rates(
            body, perturbation, time, y[: 4 * n].reshape(n, 4), y[4 * n :].reshape(n, 3)
        )
        return np.concatenate([dq.ravel(), dm.ravel()])

    y0 = np.concatenate([q0.ravel(), m0.ravel()])
    values: dict[float, tuple[Array, Array]] = {}
    for direction in (1.0, -1.0):
        targets = unique[(unique - t0) * direction > 0]
        if targets.size == 0:
            continue
        end = targets.max() if direction > 0 else targets.min()
        sol = solve_ivp(rhs, (t0, end), y0, method="DOP853", rtol=rtol, atol=atol_vec, dense_output=True)
        if not sol.success:
            msg = f"expected the reference integration to succeed, got: {sol.message}"
            raise ValueError(msg)
        for time in targets:
            y = sol.sol(time) if time != end else sol.y[:, -1]
            values[float(time)] = (y[: 4 * n].reshape(n, 4), y[4 * n :].reshape(n, 3))
    return values
