"""Splitting integrators: exact free limit, convergence order, agreement with the reference."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from andoyer import FreeRotation, RigidBody, State
from andoyer.integrate import integrate_reference
from andoyer.integrate.splitting import integrate_splitting
from andoyer.perturbations import CircularOrbit, GravityGradient, HeavyTop, Model, PointMass, PrecessingFrame
from conftest import REGIME_BODIES, rotation_distance


def start():
    return State.from_attitude(Rotation.from_euler("ZXZ", [0.3, 0.9, 0.4]), [0.2, -0.3, 1.5])


def test_splitting_of_free_body_is_the_exact_flow():
    body = REGIME_BODIES["triaxial"]
    out = integrate_splitting(Model(body), start(), [3.0], step=0.7, order=4)
    exact = FreeRotation(body).propagate(start(), 3.0)
    assert np.abs(out.m_body[0] - exact.m_body).max() <= 1e-13
    assert rotation_distance(out.quaternion[0], exact.quaternion) <= 1e-13


def test_splitting_frame_only_is_exact():
    body = REGIME_BODIES["triaxial"]
    model = Model(body, PrecessingFrame([0.01, 0.02, 0.05]))
    out = integrate_splitting(model, start(), [2.0], step=1.0, order=2)
    ref = integrate_reference(model, start(), 2.0, rtol=1e-13, atol=1e-15)
    assert rotation_distance(out.quaternion[0], ref.quaternion) <= 1e-10


MODELS = {
    "gravity-gradient": lambda body: GravityGradient(
        PointMass(4.0, CircularOrbit(2.0, 0.3, inclination=0.4))
    ),
    "heavy-top": lambda body: HeavyTop(0.8, [0.1, 0.0, 0.3]),
}


# Steps that divide t_end, in the asymptotic range and above the reference's ~1e-12 error.
STEPS = {2: [0.25, 0.125, 0.0625], 4: [0.25, 0.125, 0.0625], 6: [0.5, 0.4, 0.25, 0.2]}


@pytest.mark.parametrize("name", list(MODELS))
@pytest.mark.parametrize("order", [2, 4, 6])
def test_splitting_converges_at_its_order(name, order):
    body = RigidBody(0.7, 1.0, 1.3)
    model = Model(body, MODELS[name](body))
    t_end = 2.0
    ref = integrate_reference(model, start(), t_end, rtol=1e-13, atol=1e-15)
    steps = STEPS[order]
    errors = []
    for h in steps:
        out = integrate_splitting(model, start(), [t_end], step=h, order=order)
        errors.append(
            np.abs(out.m_body[0] - ref.m_body).max() + rotation_distance(out.quaternion[0], ref.quaternion)
        )
    slope = np.polyfit(np.log(steps), np.log(errors), 1)[0]
    assert abs(slope - order) <= 0.2


def test_splitting_rejects_dissipative_models():
    from andoyer.perturbations import LinearDamping

    body = RigidBody(1.0, 1.5, 2.0)
    with pytest.raises(ValueError, match=r"expected Hamiltonian attitude-only models"):
        integrate_splitting(Model(body, LinearDamping(0.1)), start(), [1.0], step=0.1)
    with pytest.raises(ValueError, match=r"expected a positive finite step"):
        integrate_splitting(Model(body), start(), [1.0], step=0.0)
