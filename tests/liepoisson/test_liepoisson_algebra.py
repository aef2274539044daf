"""Lie–Poisson algebras: structure, Casimirs, brackets, vector fields, input checks."""

import itertools

import numpy as np
import pytest
import sympy as sp

from andoyer.liepoisson import ALGEBRA_NAMES, get_algebra

ALGEBRAS = list(ALGEBRA_NAMES)


def levi_civita(i, j, k):
    return (i - j) * (j - k) * (k - i) / 2


def pavlov_table_value(algebra, a, b, x):
    """{x_a, x_b} written from Pavlov eqs. 1.1 and 2.9 with explicit ε and δ."""
    m = x[:3]
    if a < 3 and b < 3:
        return -sum(levi_civita(a, b, k) * m[k] for k in range(3))
    if a >= 3 and b >= 3:
        return 0.0
    if a >= 3:  # antisymmetry
        return -pavlov_table_value(algebra, b, a, x)
    if algebra == "e3":
        gamma = x[3:]
        return -sum(levi_civita(a, b - 3, k) * gamma[k] for k in range(3))
    lam = x[3:]
    mu = b - 3
    if mu == 0:
        return 0.5 * lam[1 + a]
    j = mu - 1
    return -0.5 * (sum(levi_civita(a, j, k) * lam[1 + k] for k in range(3)) + (lam[0] if a == j else 0.0))


@pytest.mark.parametrize("algebra", ALGEBRAS)
def test_structure_matches_pavlov_eqs_1_1_and_2_9(algebra):
    alg = get_algebra(algebra)
    x = alg.sample(np.random.default_rng(3), 1)[0]
    P = alg.poisson_tensor(x)
    for a, b in itertools.product(range(alg.dim), repeat=2):
        assert P[a, b] == pytest.approx(pavlov_table_value(algebra, a, b, x), abs=1e-15)


@pytest.mark.parametrize("algebra", ALGEBRAS)
def test_structure_is_a_lie_algebra(algebra):
    """Antisymmetry and the Jacobi identity of the structure constants."""
    C = get_algebra(algebra).structure
    assert np.array_equal(C, -np.transpose(C, (1, 0, 2)))
    jac = (
        np.einsum("abd,dce->abce", C, C) + np.einsum("bcd,dae->abce", C, C) + np.einsum("cad,dbe->abce", C, C)
    )
    assert np.max(np.abs(jac)) == 0.0


@pytest.mark.parametrize("algebra", ALGEBRAS)
def test_casimirs_commute_with_every_generator(algebra):
    alg = get_algebra(algebra)
    x = alg.sample(np.random.default_rng(4), 500) * 3.0
    for cas in alg.casimirs:
        field = alg.vector_field(x, cas.gradient(x))
        assert np.max(np.abs(field)) < 1e-14
        expr = cas.expr(alg.symbols())
        for s in alg.symbols():
            assert alg.bracket_sym(s, expr) == 0


def test_casimir_list():
    assert [c.name for c in get_algebra("so3").casimirs] == ["m·m"]
    assert [c.name for c in get_algebra("e3").casimirs] == ["γ·γ", "m·γ"]
    assert [c.name for c in get_algebra("l7").casimirs] == ["λ·λ"]
    m1, m2, m3, g1, g2, g3 = get_algebra("e3").symbols()
    assert get_algebra("e3").casimirs[1].expr(get_algebra("e3").symbols()) == (m1 * g1 + m2 * g2 + m3 * g3)


def test_gurfil_eq_28_sign():
    so3 = get_algebra("so3")
    m = np.array([0.7, -1.1, 2.3])
    e = np.eye(3)
    assert so3.bracket(m, e[0], e[1]) == pytest.approx(-m[2])
    assert so3.bracket(m, e[1], e[2]) == pytest.approx(-m[0])
    assert so3.bracket(m, e[2], e[0]) == pytest.approx(-m[1])


@pytest.mark.parametrize("algebra", ALGEBRAS)
def test_numeric_bracket_matches_symbolic(algebra):
    alg = get_algebra(algebra)
    xs = alg.symbols()
    f = xs[0] ** 2 * xs[-1] + sp.sin(xs[1]) * xs[-2]
    k = xs[2] * xs[-3] + xs[0] * xs[1] ** 2
    sym = sp.lambdify([xs], alg.bracket_sym(f, k))
    grad = [sp.lambdify([xs], [sp.diff(e, s) for s in xs]) for e in (f, k)]
    x = alg.sample(np.random.default_rng(5), 200)
    gf, gk = (np.stack([np.broadcast_to(c, len(x)) for c in g(x.T)], -1) for g in grad)
    np.testing.assert_allclose(alg.bracket(x, gf, gk), sym(x.T), rtol=1e-13, atol=1e-13)
    vf = np.stack([np.broadcast_to(sp.lambdify([xs], e)(x.T), len(x)) for e in alg.vector_field_sym(k)], -1)
    np.testing.assert_allclose(alg.vector_field(x, gk), vf, rtol=1e-13, atol=1e-13)


def test_free_body_vector_field_is_euler_equations():
    """ṁ_i = c_i m_j m_k, c_1 = (I2 − I3)/(I2 I3), cyclic (preamble form)."""
    inertia = np.array([1.0, 1.7, 2.4])
    m = np.random.default_rng(6).standard_normal((100, 3))
    c = np.array(
        [
            (inertia[1] - inertia[2]) / (inertia[1] * inertia[2]),
            (inertia[2] - inertia[0]) / (inertia[2] * inertia[0]),
            (inertia[0] - inertia[1]) / (inertia[0] * inertia[1]),
        ]
    )
    euler = c * np.stack([m[:, 1] * m[:, 2], m[:, 2] * m[:, 0], m[:, 0] * m[:, 1]], -1)
    got = get_algebra("so3").vector_field(m, m / inertia)
    np.testing.assert_allclose(got, euler, rtol=1e-13, atol=1e-14)


def test_shapes_broadcast_and_scalar():
    e3 = get_algebra("e3")
    x = e3.sample(np.random.default_rng(7), 12).reshape(3, 4, 6)
    grad = np.eye(6)[0]
    assert e3.bracket(x, grad, np.eye(6)[4]).shape == (3, 4)
    assert e3.vector_field(x, grad).shape == (3, 4, 6)
    assert e3.poisson_tensor(x).shape == (3, 4, 6, 6)
    assert np.ndim(e3.bracket(x[0, 0], grad, grad)) == 0
    assert e3.casimirs[0].value(x).shape == (3, 4)


def test_hamiltonian_rhs_for_solve_ivp():
    l7 = get_algebra("l7")
    x = l7.sample(np.random.default_rng(8), 1)[0]
    rhs = l7.hamiltonian_rhs(lambda y: np.concatenate([y[:3], np.zeros(4)]))
    np.testing.assert_allclose(rhs(0.0, x), l7.vector_field(x, np.r_[x[:3], np.zeros(4)]))


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (lambda: get_algebra("so4"), "expected one of"),
        (
            lambda: get_algebra("e3").bracket(np.zeros(5), np.zeros(6), np.zeros(6)),
            "expected x with last axis of length 6",
        ),
        (lambda: get_algebra("so3").vector_field([1.0, np.nan, 0.0], [1, 0, 0]), "expected finite x"),
        (
            lambda: get_algebra("so3").bracket([1.0, 0, 0], 1.0, [1, 0, 0]),
            "expected grad_f with last axis of length 3",
        ),
        (
            lambda: get_algebra("e3").bracket(np.zeros((2, 6)), np.zeros((3, 6)), np.zeros(6)),
            r"expected broadcastable leading shapes, got x \(2,\), grad_f \(3,\)",
        ),
    ],
)
def test_bad_inputs_raise(call, message):
    with pytest.raises(ValueError, match=message):
        call()
