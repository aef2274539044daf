"""The DOP853 reference integrator against closed forms, in both time directions and broadcast."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from andoyer import RigidBody, State
from andoyer.integrate import Model, integrate_reference
from andoyer.perturbations import HeavyTop
from conftest import rotation_distance


def symmetric_top(A, C, m0, t):
    """Closed form of the free symmetric top (A = B): m turns about b3 at λ = (C - A) L/(A C);
    the attitude is a regular precession R(t) = exp(t M/A) R0 exp(-λ t b3)."""
    L = m0[2]
    lam = (C - A) * L / (A * C)
    m = np.stack(
        [
            m0[0] * np.cos(lam * t) - m0[1] * np.sin(lam * t),
            m0[0] * np.sin(lam * t) + m0[1] * np.cos(lam * t),
            np.full_like(t, L),
        ],
        -1,
    )
    return m, lam


@pytest.mark.parametrize(("A", "C"), [(1.0, 1.5), (1.0, 0.6)])
def test_reference_matches_symmetric_top_closed_form(A, C):
    body = RigidBody(A, A, C)
    q0 = Rotation.from_euler("ZXZ", [0.3, 0.9, 1.1])
    m0 = np.array([0.3, -0.2, 1.2])
    t = np.linspace(-20, 30, 11)
    out = integrate_reference(Model(body), State.from_attitude(q0, m0), t)
    m, lam = symmetric_top(A, C, m0, t)
    assert np.abs(out.m_body - m).max() <= 1e-10
    # Attitude: R(t) = exp(t M_ref / A) R0 exp(-λ t e3), M_ref = R0 m0 fixed in space.
    M = q0.apply(m0)
    expected = (
        Rotation.from_rotvec(np.outer(t, M / A)) * q0 * Rotation.from_rotvec(np.outer(-lam * t, [0, 0, 1.0]))
    )
    assert rotation_distance(out.quaternion, expected.as_quat()).max() <= 1e-9


def test_reference_broadcasts_states_and_times(rng):
    body = RigidBody(0.7, 1.0, 1.3)
    states = State.from_attitude(Rotation.random(3, rng=rng), rng.normal(size=(3, 3)))
    t = np.array([[0.0], [1.0], [-2.0], [3.5]])
    out = integrate_reference(Model(body), states, t)
    assert out.shape == (4, 3)
    for k in range(3):
        single = integrate_reference(Model(body), states[k], t[:, 0])
        assert np.abs(single.m_body - out.m_body[:, k]).max() <= 1e-9
    assert np.array_equal(out.m_body[0], states.m_body)


def test_reference_heavy_top_energy_and_casimirs(rng):
    body = RigidBody(1.0, 1.5, 2.0)
    top = HeavyTop(1.0, [0.1, 0.2, 0.5])
    s = State.from_attitude(Rotation.random(5, rng=rng), rng.normal(size=(5, 3)))
    t = np.linspace(0, 30, 7)[:, None]
    out = integrate_reference(Model(body, top), s, t)
    energy = out.energy(body) + top.potential(0.0, out.quaternion, out.m_body)
    gamma = top.gamma(out.quaternion)
    assert np.abs(energy - energy[0]).max() <= 1e-9
    assert (
        np.abs(np.sum(out.m_body * gamma, -1) - np.sum(s.m_body * top.gamma(s.quaternion), -1)).max() <= 1e-9
    )


@pytest.mark.parametrize(
    "call",
    [
        lambda: integrate_reference("free", State.from_quaternion([0, 0, 0, 1.0], [0, 0, 1.0]), [1.0]),
        lambda: integrate_reference(Model(RigidBody(1, 1, 1)), "state", [1.0]),
        lambda: integrate_reference(
            Model(RigidBody(1, 1, 1)), State.from_quaternion([[0, 0, 0, 1.0]] * 3, [0, 0, 1.0]), [1.0, 2.0]
        ),
        lambda: integrate_reference(
            Model(RigidBody(1, 1, 1)), State.from_quaternion([0, 0, 0, 1.0], [0, 0, 1.0]), [np.nan]
        ),
        lambda: Model("body"),
        lambda: Model(RigidBody(1, 1, 1), ["gravity"]),
    ],
)
def test_reference_bad_input(call):
    with pytest.raises(ValueError, match=r"^expected .+, got .+"):
        call()
