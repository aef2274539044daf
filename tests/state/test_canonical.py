"""The Euler -> Andoyer map is canonical: its Jacobian M satisfies Mᵀ J M = J."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from andoyer import State
from andoyer.state import andoyer_from_euler, euler_from_andoyer

J6 = np.block([[np.zeros((3, 3)), np.eye(3)], [-np.eye(3), np.zeros((3, 3))]])


def wrap(d):
    """Differences of angles taken on the circle."""
    return np.angle(np.exp(1j * d))


def jacobian(f, x, angle_outputs, step=1e-5):
    """Richardson-extrapolated central-difference Jacobian, angles differenced on the circle."""

    def column(i, h):
        xp, xm = x.copy(), x.copy()
        xp[i] += h
        xm[i] -= h
        d = np.asarray(f(xp)) - np.asarray(f(xm))
        d[angle_outputs] = wrap(d[angle_outputs])
        return d / (2 * h)

    return np.stack([(4 * column(i, step / 2) - column(i, step)) / 3 for i in range(len(x))], axis=1)


def euler_to_andoyer_via_state(x):
    a = State.from_euler(*x).as_andoyer()
    return np.array([a.l, a.g, a.h, a.L, a.G, a.H], dtype=float)


def andoyer_to_euler_via_state(y):
    e = State.from_andoyer(*y).as_euler()
    return np.array(e, dtype=float)


def random_euler(rng):
    m = rng.normal(size=3)
    phi, psi = rng.uniform(0, 2 * np.pi, 2)
    theta = rng.uniform(0.3, 2.8)
    state = State.from_attitude(Rotation.from_euler("ZXZ", [phi, theta, psi]), m)
    return np.array(state.as_euler(), dtype=float)


@pytest.mark.parametrize("route", ["state", "direct"])
def test_euler_to_andoyer_is_symplectic(rng, route):
    f = euler_to_andoyer_via_state if route == "state" else lambda x: np.array(andoyer_from_euler(*x), float)
    for _ in range(25):
        x = random_euler(rng)
        M = jacobian(f, x, angle_outputs=[0, 1, 2])
        assert np.abs(M.T @ J6 @ M - J6).max() <= 1e-8


@pytest.mark.parametrize("route", ["state", "direct"])
def test_andoyer_to_euler_is_symplectic(rng, route):
    f = andoyer_to_euler_via_state if route == "state" else lambda y: np.array(euler_from_andoyer(*y), float)
    for _ in range(25):
        G = rng.uniform(0.5, 3.0)
        y = np.array(
            [*rng.uniform(0, 2 * np.pi, 3), G * rng.uniform(-0.9, 0.9), G, G * rng.uniform(-0.9, 0.9)]
        )
        M = jacobian(f, y, angle_outputs=[0, 1, 2])
        assert np.abs(M.T @ J6 @ M - J6).max() <= 1e-8


def test_symplectic_check_detects_a_non_canonical_map(rng):
    """The check has teeth: scaling one momentum without its angle breaks it."""

    def broken(x):
        y = euler_to_andoyer_via_state(x)
        y[4] *= 1.001
        return y

    M = jacobian(broken, random_euler(rng), angle_outputs=[0, 1, 2])
    assert np.abs(M.T @ J6 @ M - J6).max() > 1e-4
