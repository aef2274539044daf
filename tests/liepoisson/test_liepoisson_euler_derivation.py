"""The sign conventions of the brackets, derived from the canonical Euler-angle bracket.

Independent of the package: the rotation matrix, the body angular velocity, the
momenta and the quaternion are built here from scratch with sympy; only the
structure constants under test come from ``andoyer.liepoisson``.
"""

import itertools

import numpy as np
import pytest
import sympy as sp
from scipy.spatial.transform import Rotation

from andoyer.liepoisson import get_algebra
from andoyer.liepoisson._identity import vanishes

phi, theta, psi = sp.symbols("phi theta psi", real=True)
Phi, Theta, Psi = sp.symbols("Phi Theta Psi", real=True)
PAIRS = ((phi, Phi), (theta, Theta), (psi, Psi))


def rz(a):
    return sp.Matrix([[sp.cos(a), -sp.sin(a), 0], [sp.sin(a), sp.cos(a), 0], [0, 0, 1]])


def rx(a):
    return sp.Matrix([[1, 0, 0], [0, sp.cos(a), -sp.sin(a)], [0, sp.sin(a), sp.cos(a)]])


ROT = rz(phi) * rx(theta) * rz(psi)  # body -> reference, Rotation.from_euler("ZXZ")


def qmul(a, b):
    aw, av = a[0], sp.Matrix(a[1:])
    bw, bv = b[0], sp.Matrix(b[1:])
    v = aw * bv + bw * av + av.cross(bv)
    return [aw * bw - av.dot(bv), *v]


def half_quat(axis, a):
    q = [sp.cos(a / 2), 0, 0, 0]
    q[{"x": 1, "z": 3}[axis]] = sp.sin(a / 2)
    return q


QUAT = qmul(qmul(half_quat("z", phi), half_quat("x", theta)), half_quat("z", psi))


def canonical(f, k):
    return sum(sp.diff(f, q) * sp.diff(k, p) - sp.diff(f, p) * sp.diff(k, q) for q, p in PAIRS)


def angular_velocity_matrix():
    """B with ω_body = B q̇, from hat(ω) = rotᵀ d(rot)/dt."""
    qdots = sp.symbols("qd1:4", real=True)
    omega_hat = ROT.T * sum(
        (ROT.diff(q) * qd for q, qd in zip((phi, theta, psi), qdots, strict=True)),
        sp.zeros(3),
    )
    omega = sp.Matrix([omega_hat[2, 1], omega_hat[0, 2], omega_hat[1, 0]])
    return omega.jacobian(qdots), qdots


GURFIL_25_27 = sp.Matrix(
    [
        (Phi * sp.sin(psi) + Theta * sp.sin(theta) * sp.cos(psi) - Psi * sp.sin(psi) * sp.cos(theta))
        / sp.sin(theta),
        (Phi * sp.cos(psi) - Theta * sp.sin(psi) * sp.sin(theta) - Psi * sp.cos(psi) * sp.cos(theta))
        / sp.sin(theta),
        Psi,
    ]
)


def test_euler_rotation_matrix_matches_scipy():
    rng = np.random.default_rng(1)
    f = sp.lambdify([phi, theta, psi], ROT)
    q = sp.lambdify([phi, theta, psi], QUAT)
    for angles in rng.uniform(-3, 3, (20, 3)):
        rot = Rotation.from_euler("ZXZ", angles)
        assert np.allclose(np.array(f(*angles), float), rot.as_matrix(), atol=1e-15)
        x, y, z, w = rot.as_quat()
        lam = np.array(q(*angles), float)
        want = np.array([w, x, y, z])
        assert min(np.abs(lam - want).max(), np.abs(lam + want).max()) < 1e-15


def test_gurfil_eqs_25_27_from_lagrangian():
    """p = ∂T/∂q̇ = Bᵀ I ω = Bᵀ m for T = ½ ωᵀ I ω; eqs. 25–27 must invert it."""
    B, qdots = angular_velocity_matrix()
    inertia = sp.diag(*sp.symbols("I1:4", positive=True))
    omega = B * sp.Matrix(qdots)
    T = (omega.T * inertia * omega)[0] / 2
    p = sp.Matrix([sp.diff(T, qd) for qd in qdots])
    assert sp.expand(p - B.T * inertia * omega) == sp.zeros(3, 1)
    momenta = B.T * GURFIL_25_27
    for got, want in zip(momenta, (Phi, Theta, Psi), strict=True):
        assert vanishes(got - want)
    assert vanishes(B.det() + sp.sin(theta))  # B invertible off sθ = 0, so m is unique


def test_gurfil_eq_28_body_momentum_brackets():
    m = GURFIL_25_27
    assert vanishes(canonical(m[0], m[1]) + m[2])
    assert vanishes(canonical(m[1], m[2]) + m[0])
    assert vanishes(canonical(m[2], m[0]) + m[1])


@pytest.mark.parametrize("algebra", ["so3", "e3", "l7"])
def test_structure_constants_from_euler_bracket(algebra):
    """{x_a, x_b}_canonical = P_ab(x) for x = (m, γ = third row of rot, λ = quaternion of rot)."""
    alg = get_algebra(algebra)
    x = list(GURFIL_25_27)
    if algebra == "e3":
        x += list(ROT[2, :])
    elif algebra == "l7":
        x += QUAT
    P = alg.poisson_tensor_sym().xreplace(dict(zip(alg.symbols(), x, strict=True)))
    for a, b in itertools.combinations(range(alg.dim), 2):
        assert vanishes(canonical(x[a], x[b]) - P[a, b]), (alg.generators[a], alg.generators[b])


def test_reference_frame_momentum_brackets_gurfil_eq_33():
    """m_ref = rot m has {G1, G2} = +G3 (Gurfil eq. 33), computed in l(7)."""
    l7 = get_algebra("l7")
    m1, m2, m3, w, x, y, z = l7.symbols()
    R = sp.Matrix(
        [
            [w**2 + x**2 - y**2 - z**2, 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), w**2 - x**2 + y**2 - z**2, 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (w * x + y * z), w**2 - x**2 - y**2 + z**2],
        ]
    )
    g = R * sp.Matrix([m1, m2, m3])
    unit = ((w, w**2 + x**2 + y**2 + z**2 - 1),)
    for i, j, k in ((0, 1, 2), (1, 2, 0), (2, 0, 1)):
        assert vanishes(l7.bracket_sym(g[i], g[j]) - g[k], unit)
