"""The public secular path's mean state against the general evaluation it replaced.

``integrate_secular`` now evaluates the free motion with the compiled kernels (regular
precession and steady spins included) and turns it with one vectorised quaternion product.
The general path, written out here: the same mean momentum ``M̄``
(:func:`andoyer.integrate.secular.propagate_momentum`), the free motion of the numpy kernels
(:class:`andoyer.FreeRotation` with ``backend="numpy"``) and
scipy's ``Rotation`` for ``Rz(h̄) Rx(Ī − I₀) Rz(−h₀)`` at each time.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from andoyer import FreeRotation, RigidBody, State, bodies
from andoyer.integrate import secular
from andoyer.integrate.secular import integrate_secular, propagate_momentum, secular_parts
from andoyer.perturbations import GravityGradient, Model
from andoyer.perturbations.solar_system import JULIAN_YEAR, mean_perturbers
from conftest import rotation_distance

SIDEREAL_DAY = 86164.0905
EARTH = bodies.get("earth")  # triaxial: B − A = 2.2e-6 C

# (body, body-frame direction of m, wobble): Earth-like spins and triaxial tumbling
REGIMES = {
    "earth steady spin": (EARTH, [0.0, 0.0, 1.0], 0.0),
    "earth wobbling": (EARTH, [0.0, 0.0, 1.0], 1e-6),
    "axisymmetric earth-like": (RigidBody(0.99672, 0.99672, 1.0), [0.0, 0.0, 1.0], 1e-3),
    "axisymmetric steady spin": (RigidBody(0.99672, 0.99672, 1.0), [0.0, 0.0, 1.0], 0.0),
    "triaxial SAM": (RigidBody(0.8, 0.9, 1.0), [0.1, 0.2, 1.0], 0.05),
    "triaxial LAM": (RigidBody(0.8, 0.9, 1.0), [1.0, 0.2, 0.1], 0.05),
    "triaxial spin about the least axis": (RigidBody(0.8, 0.9, 1.0), [1.0, 0.0, 0.0], 0.0),
    "sphere": (RigidBody(1.0, 1.0, 1.0), [0.3, 0.4, 1.0], 0.0),
}


def starts(body, direction, wobble, rng):
    """Two seeded states spinning once a sidereal day about the body's largest moment's axis scale."""
    m = np.array(direction, dtype=float) + wobble * rng.normal(size=(2, 3))
    G = body.C * 2 * np.pi / SIDEREAL_DAY
    m *= G / np.linalg.norm(m, axis=-1, keepdims=True)
    return State.from_attitude(Rotation.random(2, rng=rng), m)


def general_path(model, state, t):
    """Mean states at the times ``t`` (1-D, ≥ 0) by the general evaluation, shape (T, S)."""
    M0 = state.m_reference
    M = propagate_momentum(secular_parts(model)[0], M0, state.m_body[..., 2], t)
    free = FreeRotation(model.body, backend="numpy").propagate(state, t[:, None])

    def node_inclination(v):
        return np.arctan2(v[..., 0], -v[..., 1]), np.arctan2(np.hypot(v[..., 0], v[..., 1]), v[..., 2])

    h0, I0 = node_inclination(M0)
    q = np.empty(free.quaternion.shape)
    for k in range(len(t)):
        h, inclination = node_inclination(M[k])
        turn = Rotation.from_euler("ZXZ", np.stack([h, inclination - I0, -h0], -1))
        q[k] = (turn * Rotation.from_quat(free.quaternion[k])).as_quat()
    return q, free.m_body


@pytest.mark.parametrize("regime", list(REGIMES))
def test_averaged_fast_mean_state_equals_the_general_path(regime):
    body, direction, wobble = REGIMES[regime]
    rng = np.random.default_rng(sum(map(ord, regime)))
    state = starts(body, direction, wobble, rng)
    model = Model(body, GravityGradient(mean_perturbers("earth")))
    t = np.array([0.0, 0.37, 10.0, 100.0]) * JULIAN_YEAR
    out = integrate_secular(model, state, t[:, None])
    q, m = general_path(model, state, t)
    G = np.linalg.norm(m, axis=-1)
    assert out.shape == (4, 2)
    assert np.max(np.abs(out.m_body - m) / G[..., None]) <= 1e-15
    # the same unit quaternions (sign included) to 1e-15 in each component: a few ulps
    assert np.max(np.abs(out.quaternion - q)) <= 1e-15
    assert np.max(rotation_distance(out.quaternion, q)) <= 3e-15


@pytest.mark.parametrize("regime", ["earth steady spin", "earth wobbling", "triaxial SAM", "sphere"])
@pytest.mark.parametrize(
    ("state_shape", "time_shape"), [((), ()), ((1,), ()), ((), (1,)), ((1,), (1, 1))], ids=str
)
def test_averaged_fast_one_state_one_time_equals_the_general_path(regime, state_shape, time_shape):
    """One state at one time (the benchmark's call): the output is the table itself, unsorted, ungathered."""
    body, direction, wobble = REGIMES[regime]
    rng = np.random.default_rng(sum(map(ord, regime)) + len(state_shape) + 3 * len(time_shape))
    one = starts(body, direction, wobble, rng)[:1]
    model = Model(body, GravityGradient(mean_perturbers("earth")))
    t = 1000 * JULIAN_YEAR * rng.uniform(0.5, 1.0)
    q0, m0 = one.quaternion.reshape((*state_shape, 4)), one.m_body.reshape((*state_shape, 3))
    state = State.from_quaternion(q0, m0)
    out = integrate_secular(model, state, np.full(time_shape, t))
    q, m = general_path(model, one, np.array([t]))
    assert out.shape == np.broadcast_shapes(state_shape, time_shape)
    G = np.linalg.norm(m)
    assert np.max(np.abs(out.m_body.reshape(3) - m.reshape(3))) / G <= 1e-15
    assert np.max(np.abs(out.quaternion.reshape(4) - q.reshape(4))) <= 1e-15


def test_averaged_fast_turn_compiled_equals_numpy(rng):
    """The compiled ``Rz(h̄) Rx(Ī − I₀) Rz(−h₀) ⊗ q`` loop against the numpy quaternion algebra."""
    M0 = rng.normal(size=(5, 3))
    M = rng.normal(size=(3, 5, 3))
    M[0, 0] = [0.0, 0.0, 2.0]  # along the pole: h and I − I₀ from atan2 at zero
    q = Rotation.random(15, rng=rng).as_quat().reshape(3, 5, 4)
    fast = secular._turned(M0, M, q)
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(secular, "NUMBA", False)
        slow = secular._turned(M0, M, q)
    assert np.max(np.abs(fast - slow)) <= 1e-15
    # and the rotation it applies takes M₀ onto the direction of M̄
    turn = Rotation.from_quat(fast.reshape(-1, 4)) * Rotation.from_quat(q.reshape(-1, 4)).inv()
    moved = turn.apply(np.broadcast_to(M0, M.shape).reshape(-1, 3))
    unit = M.reshape(-1, 3) / np.linalg.norm(M.reshape(-1, 3), axis=-1, keepdims=True)
    assert np.max(np.abs(moved / np.linalg.norm(moved, axis=-1, keepdims=True) - unit)) <= 1e-14
