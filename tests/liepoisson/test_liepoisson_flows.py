"""Hamiltonian flows of the Lie–Poisson brackets: Casimirs, rigid-body physics, Andoyer angles."""

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from andoyer.liepoisson import (
    e3_to_andoyer,
    gamma_from_quaternion,
    get_algebra,
    l7_from_andoyer,
    l7_to_andoyer,
    quaternion_from_scipy,
)

INERTIA = np.array([1.0, 1.7, 2.4])
CHI = np.array([0.3, -0.2, 1.0])  # centre of mass in body axes (times M g ℓ below)
MGL = 2.0
TOL = {"rtol": 1e-13, "atol": 1e-14, "method": "DOP853"}


def gamma_jacobian(lam):
    """∂γ/∂λ of Pavlov eq. 2.2, shape (3, 4)."""
    w, x, y, z = lam
    return 2 * np.array([[-y, z, -w, x], [x, w, z, y], [w, -x, -y, z]])


def gamma_of(lam):
    """Pavlov eq. 2.2 without the unit-norm check (solver stages leave the sphere slightly)."""
    w, x, y, z = lam
    return np.array([2 * (x * z - w * y), 2 * (w * x + y * z), w * w - x * x - y * y + z * z])


def energy(x, algebra, heavy):
    m = x[..., :3]
    kinetic = 0.5 * np.sum(m * m / INERTIA, -1)
    if not heavy:
        return kinetic
    gamma = x[..., 3:6] if algebra == "e3" else gamma_from_quaternion(x[..., 3:])
    return kinetic + MGL * gamma @ CHI


def gradient(algebra, heavy):
    def grad(x):
        g = np.zeros_like(x)
        g[:3] = x[:3] / INERTIA
        if heavy and algebra == "e3":
            g[3:] = MGL * CHI
        elif heavy and algebra == "l7":
            g[3:] = MGL * CHI @ gamma_jacobian(x[3:])
        return g

    return grad


def initial_state(algebra, rng):
    x = get_algebra(algebra).sample(rng, 1)[0]
    x[:3] *= 2.0
    return x


@pytest.mark.parametrize(
    ("algebra", "heavy"),
    [("so3", False), ("e3", False), ("e3", True), ("l7", False), ("l7", True)],
)
def test_casimirs_and_energy_conserved(algebra, heavy):
    alg = get_algebra(algebra)
    x0 = initial_state(algebra, np.random.default_rng(40))
    sol = solve_ivp(alg.hamiltonian_rhs(gradient(algebra, heavy)), (0.0, 20.0), x0, dense_output=False, **TOL)
    assert sol.success
    traj = sol.y.T
    for cas in alg.casimirs:
        values = cas.value(traj)
        assert np.max(np.abs(values - values[0])) <= 1e-11 * max(1.0, abs(values[0]))
    e = energy(traj, algebra, heavy)
    assert np.max(np.abs(e - e[0])) <= 1e-11 * abs(e[0])
    # the flow moves: the test is not trivially satisfied
    assert np.max(np.abs(traj - x0)) > 0.1


def test_l7_heavy_top_matches_body_frame_newton_euler():
    """Independent model: ṁ = m × ω + M g ℓ γ × χ, d rot/dt = rot·hat(ω), γ = rot[2, :]."""
    rng = np.random.default_rng(41)
    x0 = initial_state("l7", rng)
    l7 = get_algebra("l7")
    sol = solve_ivp(
        l7.hamiltonian_rhs(gradient("l7", True)), (0.0, 5.0), x0, t_eval=np.linspace(0, 5, 11), **TOL
    )

    def newton_euler(_t, y):
        m, R = y[:3], y[3:].reshape(3, 3)
        omega = m / INERTIA
        gamma = R[2]
        hat = np.array([[0, -omega[2], omega[1]], [omega[2], 0, -omega[0]], [-omega[1], omega[0], 0]])
        return np.concatenate([np.cross(m, omega) + MGL * np.cross(gamma, CHI), (R @ hat).ravel()])

    from scipy.spatial.transform import Rotation

    lam0 = x0[3:]
    R0 = Rotation.from_quat(np.r_[lam0[1:], lam0[0]]).as_matrix()
    ref = solve_ivp(newton_euler, (0.0, 5.0), np.r_[x0[:3], R0.ravel()], t_eval=np.linspace(0, 5, 11), **TOL)
    np.testing.assert_allclose(sol.y[:3], ref.y[:3], atol=1e-9)
    for k in range(11):
        lam = sol.y[3:, k]
        q = quaternion_from_scipy(Rotation.from_matrix(ref.y[3:, k].reshape(3, 3)).as_quat())
        assert min(np.abs(lam - q).max(), np.abs(lam + q).max()) < 1e-9


def test_e3_and_l7_heavy_tops_agree():
    rng = np.random.default_rng(42)
    x7 = initial_state("l7", rng)
    x3 = np.r_[x7[:3], gamma_from_quaternion(x7[3:])]
    t = np.linspace(0, 10, 21)
    s7 = solve_ivp(get_algebra("l7").hamiltonian_rhs(gradient("l7", True)), (0, 10), x7, t_eval=t, **TOL)
    s3 = solve_ivp(get_algebra("e3").hamiltonian_rhs(gradient("e3", True)), (0, 10), x3, t_eval=t, **TOL)
    np.testing.assert_allclose(s7.y[:3], s3.y[:3], atol=1e-9)
    np.testing.assert_allclose(gamma_from_quaternion(s7.y[3:].T).T, s3.y[3:], atol=1e-9)


@pytest.mark.parametrize(("momentum", "angle"), [("L", "l"), ("G", "g"), ("H", "h")])
def test_momentum_flow_advances_its_angle(momentum, angle):
    """ż = {z, K}: the flow of a momentum p_i moves only q_i, at unit rate."""
    l7 = get_algebra("l7")
    coords0 = {"l": 0.4, "g": 1.1, "h": 2.0, "L": 0.3, "G": 1.2, "H": -0.5}
    m0, lam0 = l7_from_andoyer(*coords0.values())

    def grad(x):
        m, lam = x[:3], x[3:]
        if momentum == "L":
            return np.r_[0.0, 0.0, 1.0, np.zeros(4)]
        if momentum == "G":
            return np.r_[m / np.linalg.norm(m), np.zeros(4)]
        gamma = gamma_of(lam)  # H = m·γ(λ)
        return np.r_[gamma, m @ gamma_jacobian(lam)]

    T = 0.7
    sol = solve_ivp(l7.hamiltonian_rhs(grad), (0, T), np.r_[m0, lam0], **TOL)
    end = l7_to_andoyer(sol.y[:3, -1], sol.y[3:, -1])._asdict()
    for name, value in coords0.items():
        want = value + (T if name == angle else 0.0)
        assert abs((end[name] - want + np.pi) % (2 * np.pi) - np.pi) < 1e-11, name
    if momentum != "H":  # on e(3) too, for the flows that live there
        gamma0 = gamma_from_quaternion(lam0)
        e3 = get_algebra("e3")
        sol3 = solve_ivp(
            e3.hamiltonian_rhs(lambda x: np.r_[grad(np.r_[x[:3], lam0])[:3], np.zeros(3)]),
            (0, T),
            np.r_[m0, gamma0],
            **TOL,
        )
        c = e3_to_andoyer(sol3.y[:3, -1], sol3.y[3:, -1])._asdict()
        assert abs((c[angle] - coords0[angle] - T + np.pi) % (2 * np.pi) - np.pi) < 1e-11
