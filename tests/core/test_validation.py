"""Bad input raises ValueError with a message 'expected …, got …', never a wrong number."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from andoyer import RigidBody, State, bodies
from andoyer.state import (
    andoyer_equations,
    andoyer_from_euler,
    andoyer_hamiltonian,
    andoyer_matrix,
    euler_hamiltonian,
    euler_matrix,
    euler_poinsot,
    inclinations,
)

EARTH = RigidBody(0.99672, 0.9967222, 1.0)
IDENT = Rotation.identity()

BAD = {
    "negative moment": lambda: RigidBody(-1.0, 1.0, 1.0),
    "zero moment": lambda: RigidBody(0.0, 1.0, 1.0),
    "nan moment": lambda: RigidBody(np.nan, 1.0, 1.0),
    "infinite moment": lambda: RigidBody(np.inf, 1.0, 1.0),
    "array moment": lambda: RigidBody([1.0, 2.0], 1.0, 1.0),
    "string moment": lambda: RigidBody("a", 1.0, 1.0),
    "moments length": lambda: RigidBody.from_moments([1.0, 2.0]),
    "beta > 1": lambda: RigidBody.from_alpha_beta(0.1, 1.5),
    "unknown body": lambda: bodies.get("vulcan"),
    "|L| > G": lambda: State.from_andoyer(0, 0, 0, 2.0, 1.0, 0.0),
    "|H| > G": lambda: State.from_andoyer(0, 0, 0, 0.0, 1.0, -1.5),
    "G = 0": lambda: State.from_andoyer(0, 0, 0, 0.0, 0.0, 0.0),
    "G < 0": lambda: State.from_andoyer(0, 0, 0, 0.0, -1.0, 0.0),
    "nan angle": lambda: State.from_andoyer(np.nan, 0, 0, 0.5, 1.0, 0.0),
    "nan momentum": lambda: State.from_euler(0, 1, 0, np.nan, 0, 0),
    "theta out of range": lambda: State.from_euler(0, -0.1, 0, 1, 0, 1),
    "mismatched shapes": lambda: State.from_andoyer(np.zeros(3), np.zeros(4), 0, 0.5, 1.0, 0.0),
    "m_body shape": lambda: State.from_attitude(IDENT, [1.0, 2.0]),
    "quaternion shape": lambda: State.from_quaternion([0, 0, 1], [1, 0, 0]),
    "non-unit quaternion": lambda: State.from_quaternion([0, 0, 0, 2.0], [1, 0, 0]),
    "attitude/momentum shapes": lambda: State.from_quaternion(
        np.tile([0, 0, 0, 1.0], (3, 1)), np.ones((4, 3))
    ),
    "not a Rotation": lambda: State.from_attitude(np.eye(3), [1, 0, 0]),
    "not a body": lambda: State.from_attitude(IDENT, [1, 0, 0]).energy((1, 2, 3)),
    "zero momentum to Andoyer": lambda: State.from_attitude(IDENT, [0, 0, 0]).as_andoyer(),
    "inclinations |L| > G": lambda: inclinations(1.5, 1.0, 0.0),
    "infinite matrix angle": lambda: euler_matrix(np.inf, 0, 0),
    "matrix shapes": lambda: andoyer_matrix(np.zeros(2), 0, np.zeros(3), 0, 0),
    "direct formulas at singularity": lambda: andoyer_from_euler(0, 0, 0, 1, 0, 1),
    "euler hamiltonian at singularity": lambda: euler_hamiltonian(EARTH, 0, 0, 0, 1, 0, 1),
    "andoyer hamiltonian |L| > G": lambda: andoyer_hamiltonian(EARTH, 0, 2.0, 1.0),
    "andoyer equations G < 0": lambda: andoyer_equations(EARTH, 0, 0, 0, 0, -1.0, 0),
    "euler-poinsot shape": lambda: euler_poinsot(EARTH, [1.0, 2.0]),
    "angular velocity shape": lambda: State.from_angular_velocity(IDENT, [1.0], EARTH),
}


@pytest.mark.parametrize("case", list(BAD))
def test_bad_input_raises_expected_got(case):
    with pytest.raises(ValueError, match=r"^expected .+, got .+"):
        BAD[case]()


def test_bad_input_count_meets_acceptance():
    assert len(BAD) >= 20
