"""The one Hamilton product and rotation against scipy; their float, numpy and compiled paths bit for bit."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, seed, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays
from scipy.spatial.transform import Rotation

from andoyer._jit import jit, jitable
from andoyer._quaternion import _CONTIGUOUS, apply, multiply, product, rotate
from andoyer.liepoisson.quaternion import quaternion_product

EPS = np.finfo(float).eps
_finite = st.floats(min_value=-2.0, max_value=2.0, allow_nan=False, allow_subnormal=False)
quaternions = arrays(np.float64, (4,), elements=_finite).filter(lambda q: np.linalg.norm(q) > 1e-3)

jitable(product)
jitable(apply)


@jit
def _product_loop(p, q, out):  # pragma: no cover - run compiled
    for i in range(p.shape[0]):
        r = product(p[i, 0], p[i, 1], p[i, 2], p[i, 3], q[i, 0], q[i, 1], q[i, 2], q[i, 3])
        for k in range(4):
            out[i, k] = r[k]


def _left_matrix(p):
    """``L(p)`` with ``p ⊗ q = L(p) q`` (scalar last): the product as a matrix, written independently."""
    x, y, z, w = p
    return np.array([[w, -z, y, x], [z, w, -x, y], [-y, x, w, z], [-x, -y, -z, w]])


@seed(16)
@settings(max_examples=200, deadline=None)
@given(quaternions, quaternions)
def test_product_composes_rotation_matrices(p, q):
    # R(p ⊗ q) = R(p) R(q) (active rotations, scipy's matrices), and |p ⊗ q| = |p| |q|
    pq = np.array(product(*p, *q))
    expected = Rotation.from_quat(p).as_matrix() @ Rotation.from_quat(q).as_matrix()
    assert np.allclose(Rotation.from_quat(pq).as_matrix(), expected, rtol=0, atol=16 * EPS)
    norm = np.linalg.norm(pq)
    assert abs(norm - np.linalg.norm(p) * np.linalg.norm(q)) <= 16 * EPS * max(1.0, norm)


@seed(17)
@settings(max_examples=200, deadline=None)
@given(quaternions, quaternions, quaternions)
def test_product_matches_matrix_form_and_associates(p, q, r):
    assert np.allclose(product(*p, *q), _left_matrix(p) @ q, rtol=0, atol=8 * EPS * 4)
    left = product(*product(*p, *q), *r)
    right = product(*p, *product(*q, *r))
    assert np.allclose(left, right, rtol=0, atol=64 * EPS)


@pytest.mark.parametrize(
    ("a", "b", "c"),
    [("i", "j", "k"), ("j", "k", "i"), ("k", "i", "j"), ("j", "i", "-k"), ("i", "i", "-1")],
)
def test_product_units_follow_hamilton(a, b, c):
    unit = {"i": [1.0, 0, 0, 0], "j": [0, 1.0, 0, 0], "k": [0, 0, 1.0, 0], "1": [0, 0, 0, 1.0]}
    sign = -1.0 if c.startswith("-") else 1.0
    assert product(*unit[a], *unit[b]) == tuple(sign * np.array(unit[c.lstrip("-")]))


@pytest.mark.parametrize("n", [1, 7, _CONTIGUOUS - 1, _CONTIGUOUS, 3 * _CONTIGUOUS])
def test_product_paths_agree_bit_for_bit(n):
    # floats one by one, numpy arrays (strided and contiguous components), compiled loop
    rng = np.random.default_rng(n)
    p, q = rng.normal(size=(n, 4)), rng.normal(size=(n, 4))
    arrays_ = multiply(p, q)
    floats = np.array([product(*map(float, a), *map(float, b)) for a, b in zip(p, q, strict=True)])
    compiled = np.empty((n, 4))
    _product_loop(p, q, compiled)
    assert np.array_equal(arrays_, floats)
    assert np.array_equal(compiled, floats)


@pytest.mark.parametrize(("shape_p", "shape_q"), [((4,), (5000, 4)), ((3, 1, 4), (1, 2000, 4)), ((4,), (4,))])
def test_multiply_broadcasts(shape_p, shape_q):
    rng = np.random.default_rng(len(shape_p))
    p, q = rng.normal(size=shape_p), rng.normal(size=shape_q)
    out = multiply(p, q)
    pb, qb = np.broadcast_arrays(p, q)
    expected = np.array([product(*a, *b) for a, b in zip(pb.reshape(-1, 4), qb.reshape(-1, 4), strict=True)])
    assert out.shape == pb.shape
    assert np.array_equal(out.reshape(-1, 4), expected)


def test_product_scalar_first_reordering():
    # Pavlov's λ = (w, x, y, z): the same product through a reordering
    rng = np.random.default_rng(3)
    p, q = rng.normal(size=(50, 4)), rng.normal(size=(50, 4))
    lam = quaternion_product(np.roll(p, 1, axis=-1), np.roll(q, 1, axis=-1))
    assert np.array_equal(np.roll(lam, -1, axis=-1), multiply(p, q))


def test_product_symbolic_norm_is_multiplicative():
    # the same function on sympy symbols: |p ⊗ q|² = |p|² |q|² identically
    p = sp.symbols("px py pz pw")
    q = sp.symbols("qx qy qz qw")
    r = product(*p, *q)
    assert sp.expand(sum(c**2 for c in r) - sum(c**2 for c in p) * sum(c**2 for c in q)) == 0


@jit
def _apply_loop(q, v, out):  # pragma: no cover - run compiled
    for i in range(q.shape[0]):
        r = apply(q[i, 0], q[i, 1], q[i, 2], q[i, 3], v[i, 0], v[i, 1], v[i, 2])
        for k in range(3):
            out[i, k] = r[k]


@seed(18)
@settings(max_examples=200, deadline=None)
@given(quaternions, arrays(np.float64, (3,), elements=_finite))
def test_apply_matches_scipy(q, v):
    q = q / np.linalg.norm(q)
    assert np.allclose(apply(*q, *v), Rotation.from_quat(q).apply(v), rtol=0, atol=16 * EPS)
    # the transpose: apply with the conjugate undoes it
    back = apply(-q[0], -q[1], -q[2], q[3], *apply(*q, *v))
    assert np.allclose(back, v, rtol=0, atol=32 * EPS)


@pytest.mark.parametrize("n", [1, 9, _CONTIGUOUS, 2 * _CONTIGUOUS + 3])
def test_apply_paths_agree_bit_for_bit(n):
    rng = np.random.default_rng(100 + n)
    q = rng.normal(size=(n, 4))
    q /= np.linalg.norm(q, axis=1)[:, None]
    v = rng.normal(size=(n, 3))
    floats = np.array([apply(*map(float, a), *map(float, b)) for a, b in zip(q, v, strict=True)])
    compiled = np.empty((n, 3))
    _apply_loop(q, v, compiled)
    assert np.array_equal(rotate(q, v), floats)
    assert np.array_equal(compiled, floats)
