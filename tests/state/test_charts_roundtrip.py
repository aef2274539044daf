"""Round trips Euler <-> state <-> Andoyer, generic and within 1e-8 of every singularity."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from andoyer import State
from andoyer.state import andoyer_matrix, euler_matrix, inclinations
from conftest import random_states, rotation_distance

EPS = np.finfo(float).eps
NEAR = 1e-8  # distance to the singular configurations


def matrix_distance(R1: np.ndarray, R2: np.ndarray) -> np.ndarray:
    return np.max(np.abs(R1 - R2), axis=(-2, -1))


def test_state_andoyer_state_generic(rng):
    q, m = random_states(rng, 20_000)
    state = State.from_quaternion(q, m)
    back = State.from_andoyer(*state.as_andoyer())
    assert rotation_distance(back.quaternion, state.quaternion).max() <= 1e-13
    G = np.linalg.norm(m, axis=-1)
    assert (np.abs(back.m_body - m).max(axis=-1) / G).max() <= 1e-13


def test_state_euler_state_generic(rng):
    q, m = random_states(rng, 20_000)
    state = State.from_quaternion(q, m)
    back = State.from_euler(*state.as_euler())
    assert rotation_distance(back.quaternion, state.quaternion).max() <= 1e-13
    G = np.linalg.norm(m, axis=-1)
    # (Φ - Ψ cos θ)/sin θ is conditioned like 1/sin θ: uniform attitudes reach sin θ ~ 1e-3.
    sin_theta = np.sin(state.as_euler().theta)
    bound = 1e-13 + 16 * EPS / sin_theta
    assert np.all(np.abs(back.m_body - m).max(axis=-1) / G <= bound)


def andoyer_samples(rng, n, near=None):
    l, g, h = rng.uniform(0, 2 * np.pi, size=(3, n))
    G = 10.0 ** rng.uniform(-6, 12, n)
    I = rng.uniform(0, np.pi, n)
    J = rng.uniform(0, np.pi, n)
    if near == "I=0":
        I[:] = 2 * NEAR
    elif near == "I=pi":
        I[:] = np.pi - 2 * NEAR
    elif near == "J=0":
        J[:] = 2 * NEAR
    elif near == "J=pi":
        J[:] = np.pi - 2 * NEAR
    return l, g, h, G * np.cos(J), G, G * np.cos(I)


@pytest.mark.parametrize("near", [None, "I=0", "I=pi", "J=0", "J=pi"])
def test_andoyer_state_andoyer(rng, near):
    l, g, h, L, G, H = andoyer_samples(rng, 5000, near)
    a = State.from_andoyer(l, g, h, L, G, H).as_andoyer()
    for got, ref in ((a.L, L), (a.G, G), (a.H, H)):
        assert np.max(np.abs(got - ref) / G) <= 1e-13
    # Angles are compared through the rotation they define, with the original I, J.
    I, J = inclinations(L, G, H)
    R0 = andoyer_matrix(h, I, g, J, l)
    R1 = andoyer_matrix(a.h, I, a.g, J, a.l)
    assert matrix_distance(R0, R1).max() <= 1e-13


def euler_samples(rng, n, near=None):
    phi, psi = rng.uniform(0, 2 * np.pi, size=(2, n))
    theta = rng.uniform(0, np.pi, n)
    if near == "theta=0":
        theta[:] = NEAR
    elif near == "theta=pi":
        theta[:] = np.pi - NEAR
    # Physical momenta: draw m_body, and attitude, then project (eqs. 40-42).
    G = 10.0 ** rng.uniform(-6, 12, n)
    m = rng.normal(size=(n, 3))
    m *= (G / np.linalg.norm(m, axis=-1))[:, None]
    R = euler_matrix(phi, theta, psi)  # reference -> body
    gamma = R[..., :, 2]  # s3 in body components
    Phi = np.sum(m * gamma, axis=-1)
    Theta = m[:, 0] * np.cos(psi) - m[:, 1] * np.sin(psi)
    return (phi, theta, psi, Phi, Theta, m[:, 2]), G


@pytest.mark.parametrize("near", [None, "theta=0", "theta=pi"])
def test_euler_state_euler(rng, near):
    e, G = euler_samples(rng, 5000, near)
    back = State.from_euler(*e).as_euler()
    for got, ref in zip(back[3:], e[3:], strict=True):
        assert np.max(np.abs(got - ref) / G) <= 1e-13
    R0 = euler_matrix(*e[:3])
    R1 = euler_matrix(*back[:3])
    assert matrix_distance(R0, R1).max() <= 1e-13


@pytest.mark.parametrize("near", ["I=0", "I=pi", "J=0", "J=pi"])
def test_state_andoyer_state_near_singular_is_conditioned(rng, near):
    """From the state side, (L, G, H) fix J, I only to eps/sin: the error obeys that bound."""
    l, g, h, L, G, H = andoyer_samples(rng, 2000, near)
    state = State.from_andoyer(l, g, h, L, G, H)
    back = State.from_andoyer(*state.as_andoyer())
    bound = 1e-13 + 8 * EPS / np.sin(2 * NEAR)
    assert rotation_distance(back.quaternion, state.quaternion).max() <= bound
    assert np.max(np.abs(back.m_body - state.m_body).max(axis=-1) / G) <= bound


def test_euler_andoyer_euler_through_state(rng):
    e, G = euler_samples(rng, 5000)
    a = State.from_euler(*e).as_andoyer()
    back = State.from_andoyer(*a).as_euler()
    for got, ref in zip(back[3:], e[3:], strict=True):
        assert np.max(np.abs(got - ref) / G) <= 1e-12
    assert matrix_distance(euler_matrix(*e[:3]), euler_matrix(*back[:3])).max() <= 1e-13


angles = st.floats(0.0, 2 * np.pi, allow_nan=False)
unit = st.floats(-1.0, 1.0, allow_nan=False)
scale = st.floats(1e-6, 1e12)


@settings(max_examples=150, deadline=None)
@given(l=angles, g=angles, h=angles, cJ=unit, cI=unit, G=scale)
def test_andoyer_round_trip_hypothesis(l, g, h, cJ, cI, G):
    L, H = G * cJ, G * cI
    I, J = inclinations(L, G, H)
    assume(min(np.sin(I), np.sin(J)) > 1e-12)  # exact singularities: test_charts_singular
    a = State.from_andoyer(l, g, h, L, G, H).as_andoyer()
    assert abs(a.G - G) <= 1e-13 * G
    assert abs(a.L - L) <= 1e-13 * G
    assert abs(a.H - H) <= 1e-13 * G
    assert matrix_distance(andoyer_matrix(h, I, g, J, l), andoyer_matrix(a.h, I, a.g, J, a.l)) <= 1e-13


@settings(max_examples=150, deadline=None)
@given(
    q=st.lists(st.floats(-1, 1, allow_nan=False), min_size=4, max_size=4).filter(
        lambda v: np.linalg.norm(v) > 0.1
    ),
    m=st.lists(st.floats(-1e6, 1e6, allow_nan=False), min_size=3, max_size=3).filter(
        lambda v: np.linalg.norm(v) > 1e-6
    ),
)
def test_state_round_trip_hypothesis(q, m):
    q = np.asarray(q) / np.linalg.norm(q)
    state = State.from_quaternion(q, m)
    m_ref = state.m_reference
    # 1e-2: the round trip loses ε/sin J and ε/sin I, under the 1e-13 asked below
    assume(min(np.hypot(*m[:2]), np.hypot(*m_ref[:2])) > 1e-2 * np.linalg.norm(m))
    a = state.as_andoyer()  # conditioning near singularities has its own test
    back = State.from_andoyer(*a)
    assert rotation_distance(back.quaternion, state.quaternion) <= 1e-13
    assert np.abs(back.m_body - state.m_body).max() <= 1e-13 * np.linalg.norm(m)
