"""andoyer.propagate: the three methods agree to the accuracy each claims; dispatcher errors."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from andoyer import FreeRotation, RigidBody, State
from andoyer.integrate.propagation import METHODS, propagate
from andoyer.perturbations import (
    CircularOrbit,
    GravityGradient,
    HeavyTop,
    LinearDamping,
    Model,
    PointMass,
    PrecessingFrame,
    TabulatedOrbit,
)
from conftest import rotation_distance

TRIAXIAL = RigidBody(0.7, 1.0, 1.3)
METHOD_OPTIONS = {"reference": {"rtol": 1e-12}, "splitting": {"step": 0.3}, "secular": {}}


@pytest.fixture
def states(rng):
    return State.from_attitude(Rotation.random(3, rng=rng), rng.normal(size=(3, 3)))


def test_propagate_methods_table_lists_three():
    assert set(METHODS) == {"reference", "splitting", "secular"}


@pytest.mark.parametrize("method", list(METHOD_OPTIONS))
def test_propagate_free_body_every_method_is_the_exact_flow(method, states):
    """Without perturbations the splitting and the mean state reduce to the closed-form free motion."""
    t = np.array([[-1.5], [0.0], [0.7], [2.0]])
    out = propagate(Model(TRIAXIAL), states, t, method=method, **METHOD_OPTIONS[method])
    exact = FreeRotation(TRIAXIAL).propagate(states, t)
    assert out.shape == (4, 3)
    assert np.abs(out.m_body - exact.m_body).max() <= 1e-9
    assert rotation_distance(out.quaternion, exact.quaternion).max() <= 1e-9


def test_propagate_splitting_converges_to_reference_on_gravity_gradient(states):
    """A short gravity-gradient problem: 4th-order splitting error falls ~16x per halved step."""
    sun = PointMass(4.0, CircularOrbit(2.0, 0.3, inclination=0.4))
    model = Model(TRIAXIAL, GravityGradient(sun))
    t = np.array([[0.0], [0.5], [1.0]])
    ref = propagate(model, states, t, method="reference", rtol=1e-13, atol=1e-15)
    errors = []
    for step in (0.2, 0.1):
        out = propagate(model, states, t, method="splitting", step=step, order=4)
        assert out.shape == (3, 3)
        errors.append(
            max(
                np.abs(out.m_body - ref.m_body).max(), rotation_distance(out.quaternion, ref.quaternion).max()
            )
        )
    assert errors[0] <= 1e-4
    assert 10 <= errors[0] / errors[1] <= 25


def test_propagate_secular_frame_about_the_pole_is_exact():
    """ΔH = -μ·M with μ along s3 does not depend on the fast angles: the mean state is the state."""
    body = RigidBody(0.8, 1.0, 1.3)
    model = Model(body, PrecessingFrame([0.0, 0.0, 0.05]))
    start = State.from_andoyer(0.4, 1.1, 0.3, 0.8, 1.0, 0.6)
    t = [-3.0, 0.0, 2.0, 5.0]
    ref = propagate(model, start, t, rtol=1e-13, atol=1e-15)
    mean = propagate(model, start, t, method="secular")
    assert np.abs(mean.m_body - ref.m_body).max() <= 1e-10
    assert rotation_distance(mean.quaternion, ref.quaternion).max() <= 1e-9


def test_propagate_secular_tilted_frame_moves_the_momentum_exactly():
    """For any μ the mean momentum M̄ is the inertial momentum seen from the frame: dM/dt = M × μ."""
    body = RigidBody(0.8, 1.0, 1.3)
    model = Model(body, PrecessingFrame([0.02, -0.03, 0.05]))
    start = State.from_andoyer(0.4, 1.1, 0.3, 0.8, 1.0, 0.6)
    t = np.linspace(-2.0, 6.0, 5)
    ref = propagate(model, start, t, rtol=1e-13, atol=1e-15)
    mean = propagate(model, start, t, method="secular")
    assert np.abs(mean.m_reference - ref.m_reference).max() <= 1e-10


def fast_rotator(omega):
    """An oblate body spinning at ``omega`` (J = 0.02, I = 0.4), a unit circular perturber (n = 1).

    Four initial nodes h0 = kπ/2: their average cancels every periodic term in h - λ.
    """
    body = RigidBody(1.0, 1.0, 1.2)
    G, J, I = body.C * omega, 0.02, 0.4
    h0 = np.pi / 2 * np.arange(4)
    start = State.from_andoyer(0.3, 0.0, h0, G * np.cos(J), G, G * np.cos(I))
    model = Model(body, GravityGradient(PointMass(1.0, CircularOrbit(1.0, 1.0))))
    closed_form = -1.5 / omega * (0.2 / 1.2) * np.cos(I) * (3 * np.cos(J) ** 2 - 1) / 2
    return model, start, h0, closed_form


def mean_node_slope(out, h0, t):
    M = out.m_reference
    h = np.unwrap(np.arctan2(M[..., 0], -M[..., 1]) - h0, axis=0).mean(axis=1)
    return np.polyfit(t, h, 1)[0]


def test_propagate_secular_matches_full_precession_of_a_fast_rotator():
    """Mean precession of the angular momentum: secular (first-order averaging) vs DOP853 on the full torque.

    The averaged model drops terms of second order in the torque, whose relative size is p/n
    (precession rate over orbital mean motion; 0.023 here). Its own rate equals the closed form
    -3/(2ω) H_d cos I P2(cos J).
    """
    model, start, h0, closed_form = fast_rotator(omega=10.0)
    t = np.linspace(0.0, 4 * np.pi, 33)[:, None]
    mean = propagate(model, start, t, method="secular")
    full = propagate(model, start, t, method="reference", rtol=1e-10, atol=1e-13)
    secular_rate = mean_node_slope(mean, h0, t[:, 0])
    full_rate = mean_node_slope(full, h0, t[:, 0])
    assert secular_rate == pytest.approx(closed_form, rel=1e-10)
    assert abs(full_rate / secular_rate - 1) <= abs(closed_form)  # p/n with n = 1
    # The mean state keeps |M| and L of the free motion.
    assert np.abs(np.linalg.norm(mean.m_reference, axis=-1) - 10 * 1.2).max() <= 1e-11


@pytest.mark.slow
@pytest.mark.parametrize("omega", [20.0, 40.0])
def test_propagate_secular_error_shrinks_with_the_perturbation(omega):
    model, start, h0, closed_form = fast_rotator(omega)
    t = np.linspace(0.0, 6 * np.pi, 49)[:, None]
    full = propagate(model, start, t, method="reference", rtol=1e-10, atol=1e-13)
    assert abs(mean_node_slope(full, h0, t[:, 0]) / closed_form - 1) <= abs(closed_form)


BAD_CALLS = {
    "unknown method": ({"method": "rk4"}, "expected method 'reference', 'splitting' or 'secular', got 'rk4'"),
    "option of another method": (
        {"method": "reference", "step": 0.1},
        "expected options of method='reference' among t0, rtol, atol, integrator, got step",
    ),
    "secular order": ({"method": "secular", "order": 4}, "among t0, rtol, got order"),
    "bad rtol": ({"method": "splitting", "rtol": -1.0}, "expected a positive finite rtol"),
    "bad order with rtol": ({"method": "splitting", "rtol": 1e-6, "order": 3}, "expected a splitting order"),
    "bad step": ({"method": "splitting", "step": -1.0}, "expected a positive finite step"),
    "bad order": (
        {"method": "splitting", "step": 0.1, "order": 3},
        "expected a splitting order of 2, 4 or 6",
    ),
}


@pytest.mark.parametrize("name", list(BAD_CALLS))
def test_propagate_rejects_bad_methods_and_options(name, states):
    kwargs, message = BAD_CALLS[name]
    with pytest.raises(ValueError, match=message):
        propagate(Model(TRIAXIAL), states, 1.0, **kwargs)


def orbiting(orbit):
    return GravityGradient(PointMass(1.0, orbit))


BAD_MODELS = {
    "damping with splitting": (
        "splitting",
        LinearDamping(0.1),
        r"expected Hamiltonian attitude-only models or precessing frames for method='splitting'",
    ),
    "damping with secular": ("secular", LinearDamping(0.1), "expected gravity-gradient models"),
    "heavy top with secular": ("secular", HeavyTop(1.0, [0, 0, 0.1]), "expected gravity-gradient models"),
    "tabulated orbit with secular": (
        "secular",
        orbiting(TabulatedOrbit(lambda t: np.stack(np.broadcast_arrays(np.cos(t), np.sin(t), 0 * t), -1))),
        "on Kepler orbits",
    ),
}


@pytest.mark.parametrize("name", list(BAD_MODELS))
def test_propagate_rejects_models_a_method_cannot_integrate(name, states):
    method, perturbation, message = BAD_MODELS[name]
    options = {"step": 0.1} if method == "splitting" else {}
    with pytest.raises(ValueError, match=message):
        propagate(Model(TRIAXIAL, perturbation), states, 1.0, method=method, **options)


def test_propagate_rejects_bad_model_state_and_rest(states):
    with pytest.raises(ValueError, match="expected an andoyer Model, got RigidBody"):
        propagate(TRIAXIAL, states, 1.0)
    with pytest.raises(ValueError, match="expected an andoyer State, got list"):
        propagate(Model(TRIAXIAL), [0, 0, 0, 1.0], 1.0)
    at_rest = State.from_quaternion([0, 0, 0, 1.0], [0.0, 0.0, 0.0])
    with pytest.raises(ValueError, match=r"expected a rotating body \(\|m\| > 0\)"):
        propagate(Model(TRIAXIAL), at_rest, 1.0, method="secular")


@pytest.mark.slow
@pytest.mark.parametrize("t0", [0.0, 3.0e9])
def test_propagate_secular_compiled_rotations_match_dop853(t0):
    """The public secular path (compiled exact rotations, forwards) against its DOP853 fallback.

    A frame of zero rate changes no equation but sends the model to the DOP853 path; the two
    integrators agree to their tolerances, forwards and backwards, from ``t0 = 0`` or not.
    """
    from andoyer import bodies
    from andoyer.perturbations.solar_system import JULIAN_YEAR, OBLIQUITY, mean_perturbers

    earth = bodies.get("earth")
    G = earth.C * 2 * np.pi / 86164.0905
    eps = OBLIQUITY["earth"]
    state = State.from_andoyer(0.3, 0.0, 0.1, 0.999 * G, G, G * np.cos(eps))
    gradient = GravityGradient(mean_perturbers("earth"))
    t = t0 + JULIAN_YEAR * np.array([-300.0, 0.0, 1.0, 250.0, 1000.0])
    fast = propagate(Model(earth, gradient), state, t, method="secular", t0=t0)
    still = PrecessingFrame([0.0, 0.0, 0.0])
    slow = propagate(Model(earth, [gradient, still]), state, t, method="secular", t0=t0)
    M_fast, M_slow = fast.m_reference, slow.m_reference
    assert np.max(np.linalg.norm(M_fast - M_slow, axis=-1)) / G <= 1e-10
    # and the precession is there: ≈ 50″ per year, Δh ≈ 14° over 1000 years, |ΔM|/G = 2 sin ε sin(Δh/2)
    assert np.linalg.norm(M_fast[-1] - M_fast[1]) / G > 2 * np.sin(eps) * np.sin(np.radians(13.0) / 2)
