"""Hamiltonians of the free body in each chart, and their equations of motion."""

from __future__ import annotations

import mpmath
import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.spatial.transform import Rotation

from andoyer import RigidBody, State, bodies
from andoyer.state import (
    andoyer_equations,
    andoyer_hamiltonian,
    attitude_rate,
    euler_equations,
    euler_hamiltonian,
    euler_poinsot,
    euler_poinsot_omega,
    lie_poisson,
    state_hamiltonian,
)
from conftest import REGIME_BODIES, random_states, rotation_distance


@pytest.mark.parametrize("regime", list(REGIME_BODIES))
def test_hamiltonians_agree_in_three_charts(rng, regime):
    body = REGIME_BODIES[regime]
    q, m = random_states(rng, 2000)
    state = State.from_quaternion(q, m)
    e, a = state.as_euler(), state.as_andoyer()
    T = state_hamiltonian(body, m)
    # Independent form of the energy: ½ Σ I_i ω_i² (eq. 38).
    omega = state.omega(body)
    assert np.max(np.abs(T - 0.5 * np.sum(body.moments * omega**2, -1)) / T) <= 1e-14
    assert np.max(np.abs(andoyer_hamiltonian(body, a.l, a.L, a.G) - T) / T) <= 1e-14
    well = np.sin(e.theta) > 0.05  # eq. 23 divides by sin θ; its conditioning is tested elsewhere
    assert np.max(np.abs(euler_hamiltonian(body, *e) - T)[well] / T[well]) <= 1e-14


def central_gradient(f, x, i, step):
    """Richardson-extrapolated central difference of f along coordinate i."""

    def d(hh):
        xp, xm = x.copy(), x.copy()
        xp[i] += hh
        xm[i] -= hh
        return (f(xp) - f(xm)) / (2 * hh)

    return (4 * d(step / 2) - d(step)) / 3


@pytest.mark.parametrize("regime", ["triaxial", "strongly-triaxial", "earth", "oblate"])
def test_euler_equations_are_hamiltons_equations_of_eq23(rng, regime):
    body = REGIME_BODIES[regime]
    for _ in range(20):
        x = np.array([*rng.uniform(0, 6, 1), rng.uniform(0.3, 2.8), *rng.uniform(0, 6, 1), 0, 0, 0])
        x[3:] = rng.normal(size=3)
        rates = euler_equations(body, *x)
        H = lambda y: float(euler_hamiltonian(body, *y))  # noqa: E731
        grad = np.array([central_gradient(H, x, i, 1e-3) for i in range(6)])
        expected = np.concatenate([grad[3:], -grad[:3]])
        scale = np.abs(expected).max()
        assert np.abs(np.array(rates) - expected).max() <= 1e-9 * scale


@pytest.mark.parametrize("regime", ["triaxial", "strongly-triaxial", "earth", "prolate"])
def test_andoyer_equations_are_hamiltons_equations_of_eq89(rng, regime):
    body = REGIME_BODIES[regime]
    for _ in range(20):
        G = rng.uniform(0.5, 2)
        x = np.array([*rng.uniform(0, 6, 3), G * rng.uniform(-0.95, 0.95), G, G * rng.uniform(-1, 1)])

        def H(y):
            return float(andoyer_hamiltonian(body, y[0], y[3], y[4]))

        grad = np.array([central_gradient(H, x, i, 1e-4) for i in range(6)])
        expected = np.concatenate([grad[3:], -grad[:3]])
        rates = np.array(andoyer_equations(body, *x))
        assert np.abs(rates - expected).max() <= 1e-9 * np.abs(expected).max()


def test_euler_poinsot_without_cancellation_on_earth():
    """The c_i m_j m_k form keeps full precision where m × I⁻¹m loses ~3 digits."""
    mpmath.mp.dps = 50
    earth = bodies.get("earth")
    m = np.array([1e-3, 2e-3, 1.0])
    got = euler_poinsot(earth, m)
    I = [mpmath.mpf(x) for x in earth.moments]
    M = [mpmath.mpf(x) for x in m]
    exact = [
        M[1] * M[2] * (1 / I[2] - 1 / I[1]),
        M[2] * M[0] * (1 / I[0] - 1 / I[2]),
        M[0] * M[1] * (1 / I[1] - 1 / I[0]),
    ]
    rel = [abs((g - float(x)) / float(x)) for g, x in zip(got, exact, strict=True)]
    assert max(rel) <= 4e-16
    literal = np.cross(m, m / earth.moments)
    rel_literal = abs((literal[2] - float(exact[2])) / float(exact[2]))
    assert rel_literal > 1e-13  # the cancellation the library avoids is real


def test_lie_poisson_free_body_equals_euler_poinsot(rng):
    body = RigidBody(0.7, 1.0, 1.3)
    m = rng.normal(size=(100, 3))
    assert np.abs(lie_poisson(m, m / body.moments) - euler_poinsot(body, m)).max() <= 1e-15


def test_forced_euler_poinsot_momentum_and_omega_forms_agree(rng):
    body = RigidBody(0.7, 1.0, 1.3)
    omega, torque = rng.normal(size=(2, 100, 3))
    m_rate = euler_poinsot(body, omega * body.moments, torque)
    w_rate = euler_poinsot_omega(body, omega, torque)
    assert np.abs(m_rate - w_rate * body.moments).max() <= 1e-14


def test_attitude_rate_constant_spin_matches_rotvec():
    omega = np.array([0.3, -0.2, 0.5])
    sol = solve_ivp(
        lambda t, q: attitude_rate(q, omega),
        (0, 3.0),
        [0, 0, 0, 1.0],
        method="DOP853",
        rtol=1e-13,
        atol=1e-14,
    )
    expected = Rotation.from_rotvec(3.0 * omega).as_quat()
    assert rotation_distance(sol.y[:, -1] / np.linalg.norm(sol.y[:, -1]), expected) <= 1e-11


def _integrate_state(body, state, t_end):
    def rhs(t, y):
        q, m = y[:4], y[4:]
        return np.concatenate([attitude_rate(q, m / body.moments), euler_poinsot(body, m)])

    y0 = np.concatenate([state.quaternion, state.m_body])
    sol = solve_ivp(rhs, (0, t_end), y0, method="DOP853", rtol=1e-12, atol=1e-14)
    q = sol.y[:4, -1]
    return State.from_quaternion(q / np.linalg.norm(q), sol.y[4:, -1])


@pytest.mark.parametrize("regime", ["triaxial", "strongly-triaxial", "earth", "oblate", "prolate"])
@pytest.mark.parametrize("mode", ["SAM", "LAM"])
def test_andoyer_canonical_equations_agree_with_euler_poinsot(regime, mode):
    body = REGIME_BODIES[regime]
    L = 0.95 if mode == "SAM" else 0.15
    start = State.from_andoyer(0.4, 1.1, 2.0, L, 1.0, 0.3)
    sol = solve_ivp(
        lambda t, y: np.array(andoyer_equations(body, *y)),
        (0, 20.0),
        np.array(start.as_andoyer(), dtype=float),
        method="DOP853",
        rtol=1e-12,
        atol=1e-14,
    )
    from_andoyer = State.from_andoyer(*sol.y[:, -1])
    reference = _integrate_state(body, start, 20.0)
    assert np.abs(from_andoyer.m_body - reference.m_body).max() <= 1e-9
    assert rotation_distance(from_andoyer.quaternion, reference.quaternion) <= 1e-9


def test_euler_canonical_equations_agree_with_euler_poinsot():
    body = REGIME_BODIES["triaxial"]
    start = State.from_euler(0.3, 1.2, 0.5, 0.4, 0.6, 0.8)
    sol = solve_ivp(
        lambda t, y: np.array(euler_equations(body, *y)),
        (0, 5.0),
        np.array(start.as_euler(), dtype=float),
        method="DOP853",
        rtol=1e-12,
        atol=1e-14,
    )
    reference = _integrate_state(body, start, 5.0)
    final = State.from_euler(*sol.y[:, -1])
    assert np.abs(final.m_body - reference.m_body).max() <= 1e-9
    assert rotation_distance(final.quaternion, reference.quaternion) <= 1e-9
