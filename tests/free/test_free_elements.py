"""Constants of the free motion on State arrays: the modified Andoyer set, Sadov's actions."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from andoyer import FreeRotation, State
from conftest import REGIME_BODIES, rotation_distance


def angle_error(a, b):
    return np.abs(np.angle(np.exp(1j * (a - b))))


@pytest.mark.parametrize("regime", ["triaxial", "strongly-triaxial", "earth", "oblate", "prolate"])
def test_initial_andoyer_constant_along_free_flow(rng, regime):
    body = REGIME_BODIES[regime]
    state = State.from_attitude(Rotation.random(20, rng=rng), rng.normal(size=(20, 3)))
    later_t = 7.3
    later = FreeRotation(body).propagate(state, later_t)
    a = state.as_initial_andoyer(body, epoch=1.5)
    b = later.as_initial_andoyer(body, epoch=1.5, t=later_t)
    G = a.G
    for name in ("L", "G", "H"):
        assert np.max(np.abs(getattr(a, name) - getattr(b, name)) / G) <= 1e-12
    for name in ("l", "g", "h"):
        assert angle_error(getattr(a, name), getattr(b, name)).max() <= 1e-11


@pytest.mark.parametrize("regime", ["triaxial", "strongly-triaxial", "earth"])
def test_sadov_actions_constant_and_state_round_trip(rng, regime):
    body = REGIME_BODIES[regime]
    state = State.from_andoyer(
        *rng.uniform(0, 6, (3, 30)), rng.uniform(0.2, 0.95, 30), 1.0, rng.uniform(-0.9, 0.9, 30)
    )
    sad = state.as_sadov(body)
    later = FreeRotation(body).propagate(state, 3.7).as_sadov(body)
    assert np.abs(later.I_l - sad.I_l).max() <= 1e-12
    back = State.from_sadov(body, *sad)
    assert rotation_distance(back.quaternion, state.quaternion).max() <= 1e-12
    assert np.abs(back.m_body - state.m_body).max() <= 1e-12
