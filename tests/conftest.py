"""Shared fixtures: seeded random states and comparison helpers."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import settings
from scipy.spatial.transform import Rotation

from andoyer import RigidBody, bodies

# Seeded like every other test: hypothesis draws the same examples on every run and machine.
settings.register_profile("andoyer", derandomize=True, deadline=None)
settings.load_profile("andoyer")

REGIME_BODIES = {
    "triaxial": RigidBody(0.7, 1.0, 1.3),
    "strongly-triaxial": RigidBody(0.229427, 0.963754, 1.0),
    "earth": bodies.get("earth"),
    "oblate": RigidBody(1.0, 1.0, 1.5),
    "prolate": RigidBody(0.5, 1.0, 1.0),
    "spherical": RigidBody(1.0, 1.0, 1.0),
}


def rotation_distance(q1: np.ndarray, q2: np.ndarray) -> np.ndarray:
    """Angle (radians) of the rotation between two attitudes given as quaternions (..., 4)."""
    # |q1 - q2| = 2 sin(angle/4) for the nearer sign of q2: accurate for small angles, unlike acos.
    diff = np.minimum(np.linalg.norm(q1 - q2, axis=-1), np.linalg.norm(q1 + q2, axis=-1))
    return 4.0 * np.arcsin(np.clip(diff / 2.0, 0.0, 1.0))


def random_states(rng: np.random.Generator, n: int) -> tuple[np.ndarray, np.ndarray]:
    """Uniform random attitudes and momenta with |m| spread over decades."""
    q = Rotation.random(n, rng=rng).as_quat()
    m = rng.normal(size=(n, 3)) * 10.0 ** rng.uniform(-3, 3, size=(n, 1))
    return q, m


@pytest.fixture
def rng() -> np.random.Generator:
    return np.random.default_rng(20261121)
