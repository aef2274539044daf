"""Disturbing models: torques against their potentials, conservation laws, the precessing frame."""

from __future__ import annotations

import mpmath
import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.spatial.transform import Rotation

from andoyer import RigidBody, bodies
from andoyer import _quaternion as quat
from andoyer.perturbations import (
    CircularOrbit,
    GravityGradient,
    HeavyTop,
    KeplerOrbit,
    LinearDamping,
    Model,
    PointMass,
    PrecessingFrame,
    TabulatedOrbit,
    UserPotential,
    UserTorque,
    perturbed_rates,
    solve_kepler,
)
from conftest import REGIME_BODIES, rotation_distance

SUN_LIKE = PointMass(3.0, KeplerOrbit(5.0, 0.3, 0.4, 1.0, 2.0, 0.5, 0.2), name="Sun")
MOON_LIKE = PointMass(0.5, CircularOrbit(2.0, 1.3, inclination=0.1, node_rate=-0.01), name="Moon")


def numeric_torque(model, t, q, m, h=1e-5):
    """-dΔH/dθ by Richardson central differences over body rotations q ⊗ exp(θ e_i / 2)."""
    out = []
    for axis in np.eye(3):

        def v(s, axis=axis):
            dq = np.append(np.sin(s / 2) * axis, np.cos(s / 2))
            return model.potential(t, quat.multiply(q, dq), m)

        d1 = (v(h) - v(-h)) / (2 * h)
        d2 = (v(h / 2) - v(-h / 2)) / h
        out.append(-(4 * d2 - d1) / 3)
    return np.stack(out, -1)


MODELS = {
    "gravity-gradient": lambda body: GravityGradient([SUN_LIKE, MOON_LIKE]).bind(body),
    "heavy-top": lambda body: HeavyTop(2.5, [0.1, -0.2, 0.7]),
    "precessing-frame": lambda body: PrecessingFrame([0.01, -0.02, 0.3]),
    "precessing-frame-t": lambda body: PrecessingFrame(
        lambda t: np.stack([0.1 * np.cos(t), 0.1 * np.sin(t), 0.2 + 0 * t], -1)
    ),
    "user-potential": lambda body: UserPotential(
        lambda rot, t: np.sum(rot.inv().apply([1.0, 2.0, 3.0]) ** 3, -1)
    ),
}


@pytest.mark.parametrize("name", list(MODELS))
@pytest.mark.parametrize("regime", ["triaxial", "earth", "oblate"])
def test_perturbation_torque_is_minus_attitude_gradient(rng, name, regime):
    model = MODELS[name](REGIME_BODIES[regime])
    q = Rotation.random(50, rng=rng).as_quat()
    m = rng.normal(size=(50, 3))
    t = rng.uniform(0, 10, 50)
    got = model.torque(t, q, m)
    expected = numeric_torque(model, t, q, m)
    assert np.abs(got - expected).max() <= 1e-8 * max(1.0, np.abs(expected).max())


def test_precessing_frame_momentum_gradient_is_minus_mu_body(rng):
    frame = PrecessingFrame([0.01, -0.02, 0.3])
    q = Rotation.random(20, rng=rng).as_quat()
    m = rng.normal(size=(20, 3))
    h = 1e-6
    for i in range(3):
        dm = np.zeros(3)
        dm[i] = h
        d = (frame.potential(0.0, q, m + dm) - frame.potential(0.0, q, m - dm)) / (2 * h)
        assert np.abs(d - frame.momentum_gradient(0.0, q, m)[:, i]).max() <= 1e-9


def test_gravity_gradient_torque_without_cancellation_on_earth():
    mpmath.mp.dps = 40
    earth = bodies.get("earth")
    model = GravityGradient(PointMass(1.0, TabulatedOrbit(lambda t: np.array([0.3, 0.5, 0.8])))).bind(earth)
    got = model.torque(0.0, [0, 0, 0, 1.0], [0, 0, 1.0])
    r = [mpmath.mpf(x) for x in (0.3, 0.5, 0.8)]
    I = [mpmath.mpf(x) for x in earth.moments]
    r2 = sum(x * x for x in r)
    Ir = [I[i] * r[i] for i in range(3)]
    cross = [r[1] * Ir[2] - r[2] * Ir[1], r[2] * Ir[0] - r[0] * Ir[2], r[0] * Ir[1] - r[1] * Ir[0]]
    exact = [3 * c / r2**2.5 for c in cross]
    for g, e in zip(got, exact, strict=True):
        assert abs(g - float(e)) <= 4e-16 * abs(float(e))


def test_gravity_gradient_potential_macCullagh_formula(rng):
    body = RigidBody(0.7, 1.0, 1.3)
    model = GravityGradient(SUN_LIKE).bind(body)
    q = Rotation.random(10, rng=rng).as_quat()
    t = 1.7
    r_ref = SUN_LIKE.orbit.position(t)
    rho = Rotation.from_quat(q).inv().apply(r_ref)
    r = np.linalg.norm(r_ref)
    # MacCullagh: V = -GM/(2 r^3) (A + B + C - 3 I_r), I_r the moment about the line to the perturber.
    I_r = np.sum(body.moments * rho**2, -1) / r**2
    expected = -3.0 / (2 * r**3) * (np.sum(body.moments) - 3 * I_r)
    assert np.abs(model.potential(t, q, np.zeros(3)) - expected).max() <= 1e-15


def integrate(body, model, q0, m0, t_end, rtol=1e-12):
    def rhs(t, y):
        dq, dm = perturbed_rates(body, model, t, y[:4], y[4:])
        return np.concatenate([dq, dm])

    return solve_ivp(
        rhs, (0, t_end), np.concatenate([q0, m0]), method="DOP853", rtol=rtol, atol=1e-13, dense_output=True
    )


def test_heavy_top_conserves_energy_and_casimirs():
    body = RigidBody(1.0, 1.5, 2.0)
    top = HeavyTop(1.0, [0.1, 0.2, 0.5])
    q0 = Rotation.from_euler("ZXZ", [0.1, 0.8, 0.3]).as_quat()
    m0 = np.array([0.3, -0.4, 2.0])
    sol = integrate(body, top, q0, m0, 50.0)
    ts = np.linspace(0, 50, 200)
    y = sol.sol(ts).T
    q, m = y[:, :4] / np.linalg.norm(y[:, :4], axis=-1, keepdims=True), y[:, 4:]
    energy = body.energy(m) + top.potential(0.0, q, m)
    gamma = top.gamma(q)
    assert np.abs(energy - energy[0]).max() <= 1e-9
    assert np.abs(np.sum(m * gamma, -1) - m0 @ top.gamma(q0)).max() <= 1e-9
    assert np.abs(np.linalg.norm(gamma, axis=-1) - 1).max() <= 1e-12


def test_gravity_gradient_fixed_perturber_conserves_energy():
    body = RigidBody(0.7, 1.0, 1.3)
    model = GravityGradient(PointMass(5.0, CircularOrbit(3.0, 0.0, inclination=0.3))).bind(body)
    q0 = Rotation.from_euler("ZXZ", [0.1, 0.8, 0.3]).as_quat()
    sol = integrate(body, model, q0, np.array([0.2, 0.1, 1.0]), 40.0)
    y = sol.y.T
    q, m = y[:, :4], y[:, 4:]
    energy = body.energy(m) + model.potential(0.0, q, m)
    assert np.abs(energy - energy[0]).max() <= 1e-10


@pytest.mark.parametrize("regime", ["triaxial", "earth"])
def test_precessing_frame_equals_inertial_motion_seen_from_the_frame(regime):
    """Integrating in a frame turning at μ equals the inertial motion rotated by exp(-μt)."""
    body = REGIME_BODIES[regime]
    mu = np.array([0.02, -0.01, 0.05])
    q0 = Rotation.from_euler("ZXZ", [0.4, 1.0, 0.2]).as_quat()
    m0 = np.array([0.3, 0.2, 1.0])
    t_end = 30.0
    rel = integrate(body, PrecessingFrame(mu), q0, m0, t_end).y[:, -1]
    inert = integrate(body, None, q0, m0, t_end).y[:, -1]
    frame = Rotation.from_rotvec(mu * t_end)  # frame attitude w.r.t. inertial axes
    expected = (frame.inv() * Rotation.from_quat(inert[:4])).as_quat()
    assert rotation_distance(rel[:4] / np.linalg.norm(rel[:4]), expected) <= 1e-9
    assert np.abs(rel[4:] - inert[4:]).max() <= 1e-10


def test_damping_dissipates_energy():
    body = RigidBody(1.0, 1.5, 2.0)
    damping = LinearDamping(0.05).bind(body)
    sol = integrate(body, damping, [0, 0, 0, 1.0], np.array([0.5, 0.3, 1.0]), 20.0)
    energy = body.energy(sol.y[4:].T)
    assert np.all(np.diff(energy) < 0)
    # dT/dt = ω·dm/dt = ω·τ = -c |ω|² (the free part conserves T).
    m = np.array([0.5, 0.3, 1.0])
    omega = m / body.moments
    _, dm = perturbed_rates(body, damping, 0.0, [0, 0, 0, 1.0], m)
    assert omega @ dm == pytest.approx(-0.05 * omega @ omega, rel=1e-15)


def test_user_torque_matches_constant_spin_up():
    body = RigidBody(1.0, 1.0, 1.0)
    spin_up = UserTorque(lambda t, rot, w: np.array([0.0, 0.0, 0.5])).bind(body)
    sol = integrate(body, spin_up, [0, 0, 0, 1.0], np.zeros(3), 4.0)
    assert sol.y[6, -1] == pytest.approx(2.0, abs=1e-12)
    # Angle turned: ∫ 0.5 t dt = t²/4 = 4 rad about s3.
    expected = Rotation.from_rotvec([0, 0, 4.0]).as_quat()
    assert rotation_distance(sol.y[:4, -1] / np.linalg.norm(sol.y[:4, -1]), expected) <= 1e-10


@pytest.mark.parametrize("e", [0.0, 0.1, 0.7, 0.97, 0.999])
def test_solve_kepler_against_mpmath(e):
    mpmath.mp.dps = 40
    for M in np.linspace(-20, 20, 41):
        E = solve_kepler(M, e)
        ref = mpmath.findroot(lambda x, M=M: x - e * mpmath.sin(x) - M, M + (e if M > 0 else -e))
        assert abs(E - float(ref)) <= 4e-15 * max(1.0, abs(M))


def test_kepler_orbit_radius_and_period():
    orbit = KeplerOrbit(2.0, 0.4, 0.3, 0.2, 0.1, 0.0, 0.5)
    t = np.linspace(0, 40, 101)
    r = np.linalg.norm(orbit.position(t), axis=-1)
    E = solve_kepler(0.5 * t, 0.4)
    assert np.abs(r - 2.0 * (1 - 0.4 * np.cos(E))).max() <= 1e-14
    period = 2 * np.pi / 0.5
    assert np.abs(orbit.position(t + period) - orbit.position(t)).max() <= 1e-12


BAD = {
    "gm <= 0": lambda: PointMass(-1.0, CircularOrbit(1.0, 1.0)),
    "not an orbit": lambda: PointMass(1.0, "orbit"),
    "eccentricity >= 1": lambda: KeplerOrbit(1.0, 1.2, 0, 0, 0, 0, 1),
    "a <= 0": lambda: CircularOrbit(-1.0, 1.0),
    "weight <= 0": lambda: HeavyTop(0.0, [0, 0, 1]),
    "centre of mass shape": lambda: HeavyTop(1.0, [0, 1]),
    "rate shape": lambda: PrecessingFrame([0.0, 1.0]),
    "damping negative": lambda: LinearDamping(-1.0),
    "damping of a non-body": lambda: LinearDamping("earth", 1.0),
    "not callable": lambda: UserPotential(3.0),
    "not a body": lambda: GravityGradient("earth", SUN_LIKE),
    "no perturbers": lambda: GravityGradient([]),
    "three arguments": lambda: GravityGradient(RigidBody(1, 1, 1), SUN_LIKE, SUN_LIKE),
    "unbound gravity gradient": lambda: GravityGradient(SUN_LIKE).torque(0.0, [0, 0, 0, 1.0], [0, 0, 1.0]),
    "quaternion shape": lambda: HeavyTop(1.0, [0, 0, 1]).torque(0.0, [0, 0, 1.0], [0, 0, 1.0]),
}


@pytest.mark.parametrize("case", list(BAD))
def test_perturbation_bad_input_raises(case):
    with pytest.raises(ValueError, match=r"^expected .+, got .+"):
        BAD[case]()


def test_gravity_gradient_deprecated_signature_gives_same_torque(rng):
    """``GravityGradient(body, perturbers)`` warns and equals ``GravityGradient(perturbers)`` on that body."""
    body = RigidBody(0.8, 1.1, 1.4)
    q = Rotation.random(5, random_state=rng).as_quat()
    m = rng.normal(size=(5, 3))
    with pytest.warns(DeprecationWarning, match="give the body to the Model"):
        old = GravityGradient(body, [SUN_LIKE, MOON_LIKE])
    new = Model(body, GravityGradient([SUN_LIKE, MOON_LIKE])).parts[0]
    assert new.body is body
    assert np.array_equal(old.torque(0.7, q, m), new.torque(0.7, q, m))
    assert np.array_equal(Model(body, old).parts[0].torque(0.7, q, m), new.torque(0.7, q, m))


def _deprecated(term, *args):
    with pytest.warns(DeprecationWarning, match="give the body to the Model"):
        return term(*args)


INCONSISTENT = {
    "gravity gradient of another body": lambda: _deprecated(GravityGradient, RigidBody(4, 5, 6), SUN_LIKE),
    "damping of another body": lambda: _deprecated(LinearDamping, RigidBody(4, 5, 6), 0.1),
    "torque of another body": lambda: _deprecated(UserTorque, RigidBody(1, 2, 2.5), lambda t, rot, w: -w),
}


@pytest.mark.parametrize("case", list(INCONSISTENT))
def test_model_refuses_a_term_built_for_another_body(case):
    term = INCONSISTENT[case]()
    with pytest.raises(ValueError, match=r"^expected .+ the model's body RigidBody.+, got RigidBody"):
        Model(RigidBody(1, 2, 3), term)
    with pytest.raises(ValueError, match=r"^expected .+ the model's body"):
        Model(RigidBody(1, 2, 3), [HeavyTop(1.0, [0, 0, 1]) + term])


def test_model_binds_terms_to_its_body_and_leaves_the_term_unbound():
    body = RigidBody(1, 2, 3)
    term = GravityGradient(SUN_LIKE)
    model = Model(body, [term, PrecessingFrame([0, 0, 1.0])])
    assert model.parts[0].body is body
    assert model.perturbation.models[0].body is body
    assert model.parts[1] is model.perturbations[1]
    with pytest.raises(ValueError, match=r"^expected a GravityGradient bound to a body"):
        _ = term.body


ANDOYER_MODELS = {
    "gravity-gradient": lambda body: GravityGradient([SUN_LIKE, MOON_LIKE]).bind(body),
    "heavy-top": lambda body: HeavyTop(0.7, [0.1, -0.2, 0.5]),
    "precessing-frame": lambda body: PrecessingFrame([0.01, -0.02, 0.3]),
}


@pytest.mark.parametrize("name", list(ANDOYER_MODELS))
def test_andoyer_form_gradient_matches_finite_differences(rng, name):
    """The chain rule through the attitude equals ∂ΔH/∂a by Richardson differences in the chart."""
    from andoyer.perturbations import Model, andoyer_perturbed_equations
    from andoyer.state import andoyer_equations
    from andoyer.state.andoyer import andoyer_to_hub

    body = RigidBody(0.7, 1.0, 1.3)
    model = ANDOYER_MODELS[name](body)
    for _ in range(10):
        G = rng.uniform(0.5, 2)
        x = np.array([*rng.uniform(0, 6, 3), G * rng.uniform(-0.9, 0.9), G, G * rng.uniform(-0.9, 0.9)])
        t = rng.uniform(0, 5)

        def dH(y, t=t):
            q, m = andoyer_to_hub(*y)
            return float(model.potential(t, q, m))

        grad = []
        for i in range(6):

            def d(hh, i=i, x=x):
                xp, xm = x.copy(), x.copy()
                xp[i] += hh
                xm[i] -= hh
                return (dH(xp) - dH(xm)) / (2 * hh)

            grad.append((4 * d(5e-5) - d(1e-4)) / 3)
        grad = np.array(grad)
        full = np.array(andoyer_perturbed_equations(Model(body, model), t, *x))
        free = np.array(andoyer_equations(body, *x))
        expected = np.concatenate([grad[3:], -grad[:3]])
        assert np.abs(full - free - expected).max() <= 1e-8 * max(1.0, np.abs(expected).max())


@pytest.mark.slow
@pytest.mark.parametrize("name", list(ANDOYER_MODELS))
def test_andoyer_form_integration_agrees_with_hub(name):
    from andoyer import State
    from andoyer.integrate import integrate_reference
    from andoyer.perturbations import Model, andoyer_perturbed_equations

    body = RigidBody(0.7, 1.0, 1.3)
    model = Model(body, ANDOYER_MODELS[name](body))
    start = State.from_andoyer(0.4, 1.1, 2.0, 0.8, 1.0, 0.3)
    sol = solve_ivp(
        lambda t, y: np.array(andoyer_perturbed_equations(model, t, *y)),
        (0, 10.0),
        np.array(start.as_andoyer(), dtype=float),
        method="DOP853",
        rtol=1e-12,
        atol=1e-14,
    )
    via_andoyer = State.from_andoyer(*sol.y[:, -1])
    via_hub = integrate_reference(model, start, 10.0)
    assert np.abs(via_andoyer.m_body - via_hub.m_body).max() <= 1e-8
    assert rotation_distance(via_andoyer.quaternion, via_hub.quaternion) <= 1e-8
