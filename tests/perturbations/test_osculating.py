"""Convective terms (Gurfil eqs. 111-130), eq. 133, and osculating vs non-osculating elements."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from andoyer import State
from andoyer import _quaternion as quat
from andoyer.integrate import integrate_reference
from andoyer.perturbations import Model, PrecessingFrame, perturbed_rates
from andoyer.perturbations.osculating import convective_terms, euler_rates_to_omega, osculating_state
from andoyer.state import euler_equations
from conftest import REGIME_BODIES, rotation_distance

MU = np.array([0.013, -0.021, 0.034])


def frame_states(rng, n=200):
    rot = Rotation.from_euler(
        "ZXZ", np.stack([rng.uniform(0, 6, n), rng.uniform(0.2, 2.9, n), rng.uniform(0, 6, n)], -1)
    )
    return State.from_attitude(rot, rng.normal(size=(n, 3)))


def eq125(mu_b, e):
    """Gurfil eq. 125 (V = 0), written literally."""
    _phi, theta, psi, Phi, Theta, Psi = e
    st, ct, sp, cp = np.sin(theta), np.cos(theta), np.sin(psi), np.cos(psi)
    return (
        -mu_b[..., 0] * (sp / st * (Phi - Psi * ct) + Theta * cp)
        - mu_b[..., 1] * (cp / st * (Phi - Psi * ct) - Theta * sp)
        - mu_b[..., 2] * Psi
    )


def test_convective_terms_are_eqs_128_to_130_and_finite_differences(rng):
    model = Model(REGIME_BODIES["triaxial"], PrecessingFrame(MU))
    state = frame_states(rng)
    e = state.as_euler()
    mu_b = quat.rotate(quat.conjugate(state.quaternion), MU)
    got = convective_terms(model, 0.0, state)
    sp, cp, st, ct = np.sin(e.psi), np.cos(e.psi), np.sin(e.theta), np.cos(e.theta)
    eq128 = -(mu_b[:, 0] * sp + mu_b[:, 1] * cp) / st
    eq129 = -mu_b[:, 0] * cp + mu_b[:, 1] * sp
    eq130 = (mu_b[:, 0] * sp + mu_b[:, 1] * cp) * ct / st - mu_b[:, 2]
    for a, b in ((got.phi, eq128), (got.theta, eq129), (got.psi, eq130)):
        assert np.abs(a - b).max() <= 1e-14 * np.abs(b).max()
    # ∂ΔH/∂p by Richardson differences of eq. 125 at fixed angles (mu_b fixed with the attitude).
    for k, name in zip((3, 4, 5), ("phi", "theta", "psi"), strict=True):

        def f(h, k=k):
            ep, em = list(e), list(e)
            ep[k] = ep[k] + h
            em[k] = em[k] - h
            return (eq125(mu_b, ep) - eq125(mu_b, em)) / (2 * h)

        fd = (4 * f(5e-6) - f(1e-5)) / 3
        assert np.abs(fd - getattr(got, name)).max() <= 1e-8 * np.abs(fd).max()


@pytest.mark.parametrize("regime", ["triaxial", "earth", "oblate"])
def test_eq133_unperturbed_formula_returns_inertial_angular_velocity(rng, regime):
    body = REGIME_BODIES[regime]
    model = Model(body, PrecessingFrame(MU))
    state = frame_states(rng)
    e = state.as_euler()
    mu_b = quat.rotate(quat.conjugate(state.quaternion), MU)
    # g(A): the unperturbed velocities dT/dp; ω(g(A)) is the inertial angular velocity I⁻¹m.
    g = euler_equations(body, *e)
    omega_g = euler_rates_to_omega(e, g)
    inertial = state.m_body / body.moments
    assert np.max(np.abs(omega_g - inertial) / np.linalg.norm(inertial, axis=-1, keepdims=True)) <= 1e-12
    # ω(∂ΔH/∂p) = -μ (eq. 132; eq. 133 prints +μ).
    omega_conv = euler_rates_to_omega(e, convective_terms(model, 0.0, state))
    assert np.max(np.abs(omega_conv + mu_b)) <= 1e-12 * np.abs(MU).max()
    # The actual relative angular velocity of the perturbed flow is ω(g) + ω(conv) = I⁻¹m - μ_b.
    dq, _ = perturbed_rates(body, model.perturbation, 0.0, state.quaternion, state.m_body)
    relative = 2 * quat.multiply(quat.conjugate(state.quaternion), dq)[..., :3]
    assert (
        np.max(np.abs(relative - (omega_g + omega_conv)) / np.linalg.norm(inertial, axis=-1, keepdims=True))
        <= 1e-12
    )


def test_osculating_state_is_tangent_and_canonical_is_not(rng):
    body = REGIME_BODIES["triaxial"]
    model = Model(body, PrecessingFrame(MU * 10))
    state = frame_states(rng, 4)
    osc = osculating_state(model, 0.0, state)
    errors = {"osc": [], "canonical": []}
    for dt in (0.02, 0.01):
        true = integrate_reference(model, state, dt)
        errors["osc"].append(
            rotation_distance(integrate_reference(Model(body), osc, dt).quaternion, true.quaternion).max()
        )
        errors["canonical"].append(
            rotation_distance(integrate_reference(Model(body), state, dt).quaternion, true.quaternion).max()
        )
    # Tangent: the attitude error is O(dt²) (ratio 4); the canonical elements drift at O(dt) (ratio 2).
    assert errors["osc"][0] / errors["osc"][1] == pytest.approx(4.0, rel=0.05)
    assert errors["canonical"][0] / errors["canonical"][1] == pytest.approx(2.0, rel=0.05)
    a_osc, a_can = osc.as_andoyer(), state.as_andoyer()
    assert np.all(a_osc.G != a_can.G)  # the correction between the two element sets is real


def test_osculating_state_unchanged_for_attitude_only_models(rng):
    from andoyer.perturbations import HeavyTop

    state = frame_states(rng, 5)
    model = Model(REGIME_BODIES["triaxial"], HeavyTop(1.0, [0, 0, 1.0]))
    assert np.array_equal(osculating_state(model, 0.0, state).m_body, state.m_body)
