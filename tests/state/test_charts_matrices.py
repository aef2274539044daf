"""Gurfil's rotation matrices and the direct Euler <-> Andoyer formulas against scipy and the state."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from andoyer import State
from andoyer.state import andoyer_from_euler, andoyer_matrix, euler_from_andoyer, euler_matrix, inclinations
from conftest import random_states


def angle_diff(a, b):
    return np.abs(np.angle(np.exp(1j * (a - b))))


def test_euler_matrix_matches_scipy_zxz(rng):
    phi, theta, psi = rng.uniform(0, 2 * np.pi, (3, 1000))
    R = euler_matrix(phi, theta, psi)
    ref = Rotation.from_euler("ZXZ", np.stack([phi, theta, psi], -1)).as_matrix()
    assert np.abs(R - np.swapaxes(ref, -1, -2)).max() <= 1e-14


def test_euler_matrix_is_gurfil_eq1_product(rng):
    """Eq. 1: R = R3(psi) R1(theta) R3(phi), with passive elementary matrices."""

    def r3(a):
        c, s = np.cos(a), np.sin(a)
        return np.array([[c, s, 0], [-s, c, 0], [0, 0, 1]])

    def r1(a):
        c, s = np.cos(a), np.sin(a)
        return np.array([[1, 0, 0], [0, c, s], [0, -s, c]])

    for phi, theta, psi in rng.uniform(0, 6, (20, 3)):
        assert np.abs(euler_matrix(phi, theta, psi) - r3(psi) @ r1(theta) @ r3(phi)).max() <= 1e-15


def test_andoyer_matrix_matches_scipy_and_state(rng):
    h, I, g, J, l = rng.uniform(0, np.pi, (5, 1000))
    R = andoyer_matrix(h, I, g, J, l)
    rot = Rotation.from_euler("ZXZ", np.stack([h, I, g], -1)) * Rotation.from_euler(
        "XZ", np.stack([J, l], -1)
    )
    assert np.abs(R - np.swapaxes(rot.as_matrix(), -1, -2)).max() <= 1e-14
    G = 2.5
    L, H = G * np.cos(J), G * np.cos(I)
    state = State.from_andoyer(l, g, h, L, G, H)
    # The state only knows I, J through H/G and L/G (conditioning eps/sin): compare with those.
    I2, J2 = inclinations(L, G, H)
    R2 = andoyer_matrix(h, I2, g, J2, l)
    assert np.abs(R2 - np.swapaxes(state.rotation.as_matrix(), -1, -2)).max() <= 1e-14


def test_andoyer_momentum_components_gurfil_eq39_eq84(rng):
    q, m = random_states(rng, 1000)
    state = State.from_quaternion(q, m)
    a = state.as_andoyer()
    I, J = inclinations(a.L, a.G, a.H)
    expected_body = a.G[:, None] * np.stack([np.sin(J) * np.sin(a.l), np.sin(J) * np.cos(a.l), np.cos(J)], -1)
    assert np.abs(expected_body - m).max(axis=-1).max() <= 1e-13 * a.G.max()
    # The reference momentum is G s3 rotated by R3(h)^T R1(I)^T: G (sI sh, -sI ch, cI).
    expected_ref = a.G[:, None] * np.stack([np.sin(I) * np.sin(a.h), -np.sin(I) * np.cos(a.h), np.cos(I)], -1)
    assert (np.abs(expected_ref - state.m_reference).max(axis=-1) / a.G).max() <= 1e-13


def test_euler_momenta_gurfil_eq30_eq32(rng):
    """Reference components of the momentum from the Euler momenta (eqs. 30-32)."""
    q, m = random_states(rng, 1000)
    state = State.from_quaternion(q, m)
    phi, theta, _psi, Phi, Theta, Psi = state.as_euler()
    st, ct, sf, cf = np.sin(theta), np.cos(theta), np.sin(phi), np.cos(phi)
    G1 = (Psi * sf + Theta * st * cf - Phi * sf * ct) / st
    G2 = (Phi * ct * cf - Psi * cf + Theta * sf * st) / st
    M = state.m_reference
    G = np.linalg.norm(m, axis=-1)
    well = st > 1e-3
    assert (np.abs(G1 - M[:, 0]) / G)[well].max() <= 1e-12
    assert (np.abs(G2 - M[:, 1]) / G)[well].max() <= 1e-12
    assert (np.abs(Phi - M[:, 2]) / G).max() <= 1e-14


def test_direct_andoyer_from_euler_matches_state_route(rng):
    q, m = random_states(rng, 5000)
    state = State.from_quaternion(q, m)
    e = state.as_euler()
    keep = np.sin(e.theta) > 1e-3
    direct = andoyer_from_euler(*(x[keep] for x in e))
    via = state[keep].as_andoyer()
    G = via.G
    for name in ("L", "G", "H"):
        assert np.max(np.abs(getattr(direct, name) - getattr(via, name)) / G) <= 1e-12
    I, J = inclinations(via.L, via.G, via.H)
    good = (np.sin(I) > 1e-3) & (np.sin(J) > 1e-3)
    for name in ("l", "g", "h"):
        assert angle_diff(getattr(direct, name), getattr(via, name))[good].max() <= 1e-10


def test_direct_euler_from_andoyer_matches_state_route(rng):
    q, m = random_states(rng, 5000)
    state = State.from_quaternion(q, m)
    a = state.as_andoyer()
    direct = euler_from_andoyer(*a)
    via = state.as_euler()
    G = a.G
    for name in ("Phi", "Theta", "Psi"):
        assert np.max(np.abs(getattr(direct, name) - getattr(via, name)) / G) <= 1e-12
    good = np.sin(via.theta) > 1e-3
    for name in ("phi", "theta", "psi"):
        assert angle_diff(getattr(direct, name), getattr(via, name))[good].max() <= 1e-12


def test_gurfil_eq85_cos_theta(rng):
    l, g, h, L, G, H = rng.uniform(0.1, 1.0, (6, 500))
    G = G + 1.0
    e = euler_from_andoyer(l, g, h, L, G, H)
    eq85 = L * H / G**2 - np.cos(g) / G**2 * np.sqrt((G**2 - L**2) * (G**2 - H**2))
    assert np.abs(np.cos(e.theta) - eq85).max() <= 1e-14


@pytest.mark.parametrize("shape", [(), (7,), (2, 3)])
def test_chart_shapes_broadcast(shape):
    rng = np.random.default_rng(1)
    l, g, h = rng.uniform(0, 6, (3, *shape))
    a = State.from_andoyer(l, g, h, 0.5, 1.0, -0.3).as_andoyer()
    assert all(np.shape(x) == shape for x in a)
    assert euler_matrix(l, g, h).shape == (*shape, 3, 3)


def test_state_gamma_is_third_row_and_projects_momentum_on_H(rng):
    q, m = random_states(rng, 500)
    state = State.from_quaternion(q, m)
    R = state.rotation.as_matrix()
    assert np.abs(state.gamma - R[:, 2, :]).max() <= 1e-15
    a = state.as_andoyer()
    assert np.max(np.abs(np.sum(state.m_body * state.gamma, -1) - a.H) / a.G) <= 1e-14
