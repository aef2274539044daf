r"""Reference integration: DOP853 or heyoka on the attitude quaternion and the body angular momentum.

The hub equations (:func:`andoyer.perturbations.perturbed_rates`, free part
``ṁ_1 = c_1 m_2 m_3`` written without cancellation, ``q̇ = ½ q ⊗ (ω, 0)``
scalar last). With DOP853 the state vector of ``N`` bodies is integrated as
one system of ``7N`` equations with dense output to reach every requested
time. With heyoka (:mod:`andoyer.integrate.reference_heyoka`) each body has
its own Taylor integration, compiled once per model structure, in SIMD
batches. The quaternion is renormalised on output only: the flow preserves
``|q|`` and the error control keeps the drift at the tolerance.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.integrate import solve_ivp

from andoyer._limits import check_size, progress, spin_rate
from andoyer._validation import as_finite
from andoyer.integrate.output import gather_states, output_times
from andoyer.integrate.reference_heyoka import _propagate_heyoka
from andoyer.perturbations.base import Perturbation
from andoyer.perturbations.frame import PrecessingFrame
from andoyer.perturbations.gravity import GravityGradient
from andoyer.perturbations.heavy_top import HeavyTop
from andoyer.perturbations.model import Model
from andoyer.perturbations.orbits import CircularOrbit, KeplerOrbit, Orbit
from andoyer.perturbations.user import LinearDamping
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


#: DOP853 steps per radian turned at ``rtol = 1e-12`` (measured on heavy tops, 2.7-2.9); the
#: count of an 8th-order method scales as ``rtol^(-1/8)``.
_DOP853_STEPS_PER_RADIAN = 2.5
#: Seconds per DOP853 step of one body (measured, 70 µs: 12 Python right-hand sides).
_DOP853_STEP_SECONDS = 7e-5


def _check_dop853_size(model: Model, m0: Array, t0: float, unique: Array, rtol: float) -> None:
    """Refuse a DOP853 run whose dense output or duration cannot fit, before it starts.

    Steps: at least ``2.5 (1e-12/rtol)^(1/8)`` per radian turned at the spin rate over the
    longer of the two spans. Each step keeps its interpolant (about ``600 + 450 n`` bytes
    for ``n`` bodies: 950 measured for one) and costs ``n`` times 70 µs.
    """
    n = m0.shape[0]
    span = max(float(unique[-1]) - t0, t0 - float(unique[0]), 0.0)
    per_radian = _DOP853_STEPS_PER_RADIAN * (1e-12 / rtol) ** 0.125 if rtol > 0 else 0.0
    steps = per_radian * spin_rate(model.body.moments, m0) * span
    check_size(
        "a DOP853 run",
        steps=steps * n,
        nbytes=steps * (600 + 450 * n),
        step_seconds=_DOP853_STEP_SECONDS,
    )


def _dop853_values(
    model: Model, q0: Array, m0: Array, t0: float, unique: Array, rtol: float, atol: float
) -> dict[float, tuple[Array, Array]]:
    n = q0.shape[0]
    _check_dop853_size(model, m0, t0, unique, rtol)
    scale = max(float(np.max(np.linalg.norm(m0, axis=-1), initial=0.0)), np.finfo(float).tiny)
    atol_vec = np.concatenate([np.full(4 * n, atol), np.full(3 * n, atol * scale)])
    rhs = _rhs(model, n)
    y0 = np.concatenate([q0.ravel(), m0.ravel()])
    values: dict[float, tuple[Array, Array]] = {}
    span = max(float(unique[-1]) - t0, 0.0) + max(t0 - float(unique[0]), 0.0)
    with progress(span, "DOP853", unit="time") as bar:
        for direction in (1.0, -1.0):
            targets = unique[(unique - t0) * direction > 0]
            if targets.size == 0:
                continue
            end = targets.max() if direction > 0 else targets.min()
            sol = solve_ivp(
                _reporting(rhs, t0, span, bar),
                (t0, end),
                y0,
                method="DOP853",
                rtol=rtol,
                atol=atol_vec,
                dense_output=True,
            )
            if not sol.success:
                msg = f"expected the reference integration to succeed, got: {sol.message}"
                raise ValueError(msg)
            for time in targets:
                y = sol.sol(time) if time != end else sol.y[:, -1]
                values[float(time)] = (y[: 4 * n].reshape(n, 4), y[4 * n :].reshape(n, 3))
    return values


def _reporting(
    rhs: Callable[[float, Array], Array], t0: float, span: float, bar: Any
) -> Callable[[float, Array], Array]:
    """``rhs`` that tells ``bar`` how far from ``t0`` the integration has gone (every 1/1000 of ``span``)."""
    if bar is None:
        return rhs
    reported = [0.0]

    def wrapped(t: float, y: Array) -> Array:
        done = abs(t - t0)
        if done - reported[0] > 1e-3 * span:
            bar.update(done - reported[0])
            reported[0] = done
        return rhs(t, y)

    return wrapped


# The right-hand side of the DOP853 path. The generic hub equations
# (:func:`andoyer.perturbations.perturbed_rates`) cost 0.1-1 ms a call, most of
# it numpy's per-call overhead on small arrays (stack, broadcast, a vectorised
# Kepler solve for one time); here each known model is one function on the
# components of the state, the orbit positions are solved on Python floats,
# and any other model goes through its generic ``_momentum_gradient``/``_torque``.

# Components: Python floats for one body (a numpy call costs 20 times a float operation), else arrays (N,).
Vector = tuple[Any, Any, Any]
Quaternion = tuple[Any, Any, Any, Any]
Term = Callable[[float, Quaternion, Vector], tuple[Vector | None, Vector | None]]


def _to_body(q: Quaternion, v: Vector) -> Vector:
    """``Rᵀ v`` (as ``quat.rotate(quat.conjugate(q), v)``), by components."""
    ux, uy, uz, w = -q[0], -q[1], -q[2], q[3]
    tx, ty, tz = 2.0 * (uy * v[2] - uz * v[1]), 2.0 * (uz * v[0] - ux * v[2]), 2.0 * (ux * v[1] - uy * v[0])
    return (
        v[0] + w * tx + (uy * tz - uz * ty),
        v[1] + w * ty + (uz * tx - ux * tz),
        v[2] + w * tz + (ux * ty - uy * tx),
    )


def _eccentric_anomaly(M: float, e: float) -> float:
    """:func:`~andoyer.perturbations.solve_kepler` on one float (same start and stopping rule)."""
    turns = math.floor((M + math.pi) / (2 * math.pi))
    Mr = M - 2 * math.pi * turns
    E = Mr + 0.85 * e * (math.copysign(1.0, math.sin(Mr)) if math.sin(Mr) != 0 else 0.0)
    for _ in range(60):
        step = (E - e * math.sin(E) - Mr) / (1 - e * math.cos(E))
        E -= step
        if abs(step) <= 4 * np.finfo(float).eps * max(1.0, abs(E)):
            break
    return E + 2 * math.pi * turns


def _position(orbit: Orbit) -> Callable[[float], Vector]:
    """``orbit.position`` at one time, on Python floats for Kepler and circular orbits."""
    if type(orbit) not in (KeplerOrbit, CircularOrbit):
        return lambda t: tuple(np.asarray(orbit.position(t), dtype=float).reshape(3).tolist())
    a, e, epoch = orbit.semi_major_axis, orbit.eccentricity, orbit.epoch
    b = a * math.sqrt((1 - e) * (1 + e))
    ci, si = math.cos(orbit.inclination), math.sin(orbit.inclination)

    def position(t: float) -> Vector:
        dt = t - epoch
        mean = orbit.mean_anomaly + orbit.mean_motion * dt
        if e == 0.0:
            x, y = a * math.cos(mean), a * math.sin(mean)
        else:
            E = _eccentric_anomaly(mean, e)
            x, y = a * (math.cos(E) - e), b * math.sin(E)
        node = orbit.node + orbit.node_rate * dt
        periapsis = orbit.periapsis + orbit.periapsis_rate * dt
        cO, sO, cw, sw = math.cos(node), math.sin(node), math.cos(periapsis), math.sin(periapsis)
        return (
            (cO * cw - sO * ci * sw) * x + (-cO * sw - sO * ci * cw) * y,
            (sO * cw + cO * ci * sw) * x + (-sO * sw + cO * ci * cw) * y,
            si * sw * x + si * cw * y,
        )

    return position


def _gravity_term(part: GravityGradient) -> Term:
    I1, I2, I3 = part.body.moments.tolist()
    perturbers = [(3 * p.gm, _position(p.orbit)) for p in part.perturbers]

    def term(t: float, q: Quaternion, _m: Vector) -> tuple[None, Vector]:
        total = [0.0, 0.0, 0.0]
        for gm3, position in perturbers:
            x, y, z = _to_body(q, position(t))
            scale = gm3 / (x * x + y * y + z * z) ** 2.5
            total = [
                total[0] + scale * ((I3 - I2) * y * z),
                total[1] + scale * ((I1 - I3) * z * x),
                total[2] + scale * ((I2 - I1) * x * y),
            ]
        return None, (total[0], total[1], total[2])

    return term


def _frame_term(part: PrecessingFrame) -> Term:
    # ∂ΔH/∂m = -μ_b and the torque m × μ_b cancel exactly in dm/dt (eq. 132): neither is formed.
    constant = None if part._constant is None else part._constant.tolist()

    def term(t: float, q: Quaternion, _m: Vector) -> tuple[Vector, None]:
        mu = constant or part.rate(t).reshape(3).tolist()
        bx, by, bz = _to_body(q, mu)
        return (-bx, -by, -bz), None

    return term


def _heavy_top_term(part: HeavyTop) -> Term:
    x, y, z = (part.weight * part.center_of_mass).tolist()

    def term(_t: float, q: Quaternion, _m: Vector) -> tuple[None, Vector]:
        qx, qy, qz, qw = q
        g1, g2, g3 = 2 * (qx * qz - qw * qy), 2 * (qy * qz + qw * qx), 1 - 2 * (qx * qx + qy * qy)
        return None, (g2 * z - g3 * y, g3 * x - g1 * z, g1 * y - g2 * x)

    return term


def _damping_term(part: LinearDamping) -> Term:
    c = np.broadcast_to(part.coefficient, 3).tolist()
    I = part.body.moments.tolist()

    def term(_t: float, _q: Quaternion, m: Vector) -> tuple[None, Vector]:
        return None, (-c[0] * (m[0] / I[0]), -c[1] * (m[1] / I[1]), -c[2] * (m[2] / I[2]))

    return term


def _generic_term(part: Perturbation) -> Term:
    def term(t: float, qc: Quaternion, mc: Vector) -> tuple[Vector | None, Vector]:
        q, m = np.stack(np.broadcast_arrays(*qc), -1), np.stack(np.broadcast_arrays(*mc), -1)
        torque = np.broadcast_to(part._torque(t, q, m), m.shape)
        if part.attitude_only:
            return None, (torque[..., 0], torque[..., 1], torque[..., 2])
        g = np.broadcast_to(part._momentum_gradient(t, q, m), m.shape)
        m1, m2, m3 = mc
        g1, g2, g3 = g[..., 0], g[..., 1], g[..., 2]
        rate = (
            m2 * g3 - m3 * g2 + torque[..., 0],
            m3 * g1 - m1 * g3 + torque[..., 1],
            m1 * g2 - m2 * g1 + torque[..., 2],
        )
        return (g1, g2, g3), rate

    return term


def _term(part: Perturbation) -> Term:
    if type(part) is GravityGradient:
        return _gravity_term(part)
    if type(part) is PrecessingFrame:
        return _frame_term(part)
    if type(part) is HeavyTop:
        return _heavy_top_term(part)
    if type(part) is LinearDamping:
        return _damping_term(part)
    return _generic_term(part)


def _rhs(model: Model, n: int) -> Callable[[float, Array], Array]:
    """The hub equations of ``n`` bodies on the flat state ``(q (n, 4), m (n, 3))``."""
    terms = [_term(part) for part in model.parts]
    c1, c2, c3 = model.body.euler_coefficients.tolist()
    I1, I2, I3 = model.body.moments.tolist()

    def rhs(t: float, y: Array) -> Array:
        if n == 1:
            qx, qy, qz, qw, m1, m2, m3 = y.tolist()
        else:
            qx, qy, qz, qw = (y[k : 4 * n : 4] for k in range(4))
            m1, m2, m3 = (y[4 * n + k :: 3] for k in range(3))
        q, m = (qx, qy, qz, qw), (m1, m2, m3)
        w1, w2, w3 = m1 / I1, m2 / I2, m3 / I3
        d1, d2, d3 = c1 * m2 * m3, c2 * m3 * m1, c3 * m1 * m2
        for term in terms:
            dv, dm = term(t, q, m)
            if dv is not None:
                w1, w2, w3 = w1 + dv[0], w2 + dv[1], w3 + dv[2]
            if dm is not None:
                d1, d2, d3 = d1 + dm[0], d2 + dm[1], d3 + dm[2]
        rates = (
            0.5 * (qw * w1 + qy * w3 - qz * w2),
            0.5 * (qw * w2 + qz * w1 - qx * w3),
            0.5 * (qw * w3 + qx * w2 - qy * w1),
            -0.5 * (qx * w1 + qy * w2 + qz * w3),
            d1,
            d2,
            d3,
        )
        if n == 1:
            return np.array([float(v) for v in rates])
        out = np.empty(7 * n)
        for k in range(4):
            out[k : 4 * n : 4] = rates[k]
        for k in range(3):
            out[4 * n + k :: 3] = rates[4 + k]
        return out

    return rhs
