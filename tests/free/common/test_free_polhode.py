"""The working-frame kernels of the triaxial solution (:mod:`andoyer.free.common.polhode`).

Each kernel is written once and runs on floats inside compiled code (the compiled set-up) and on
arrays from numpy (:func:`andoyer.free.common.polhode_numpy.polhode_frame`): both ways are run on the same
states and must give the same bits.  Each kernel is also checked against an independent
computation: the axes against :func:`numpy.argsort` and the definition of the frame, the
invariants against exact rational arithmetic, the quaternions against scipy's rotations.
"""

from fractions import Fraction

import mpmath as mp
import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from andoyer._jit import jit, select
from andoyer.free.common import polhode as kf

TIES = [[1.0, 1.0, 2.0], [2.0, 1.0, 1.0], [1.0, 2.0, 1.0], [2.0, 2.0, 2.0], [1.5, 1.0, 1.5]]


def _states(seed, n=200):
    """Random moments (some with ties), momenta (some components zero), LAM flags, attitudes."""
    rng = np.random.default_rng(seed)
    moments = np.vstack([rng.uniform(0.5, 1.0, (n, 3)), TIES])
    m0 = rng.normal(size=moments.shape)
    m0[::7, 2] = 0.0
    m0[::11, 0] = 0.0
    lam = rng.random(moments.shape[0]) < 0.5
    q0 = Rotation.random(moments.shape[0], random_state=seed).as_quat()
    return moments, m0, lam, q0


@jit
def _on_floats(moments, m0, lam, q0, ints, floats):
    # every frame kernel on one state's floats, compiled (or plain Python without numba)
    for i in range(moments.shape[0]):
        i1, i2, i3 = moments[i, 0], moments[i, 1], moments[i, 2]
        x1, x2, x3 = m0[i, 0], m0[i, 1], m0[i, 2]
        a, b, c = kf.sorted_axes(i1, i2, i3)
        p1, p2, p3, sigma2, sigma3 = kf.polhode_axes(a, b, c, lam[i], x1, x2, x3)
        m1 = kf.component(x1, x2, x3, p1)
        m2 = kf.component(x1, x2, x3, p2) * sigma2
        m3 = kf.component(x1, x2, x3, p3) * sigma3
        s = select(lam[i], -1.0, 1.0)
        inv = kf.invariants(s, kf.component(i1, i2, i3, p1), kf.component(i1, i2, i3, p2),
                            kf.component(i1, i2, i3, p3), m1, m2, m3)
        pq = kf.permutation_quaternion(p1, p2, p3, sigma2, sigma3)
        u, v = kf.anchor(q0[i, 0], q0[i, 1], q0[i, 2], q0[i, 3], pq, m1, m2, m3, inv[6][0])
        row_i = (a, b, c, p1, p2, p3)
        for k in range(6):
            ints[i, k] = row_i[k]
        row = (sigma2, sigma3, m1, m2, m3)
        for k in range(5):
            floats[i, k] = row[k]
        for k in range(8):
            floats[i, 5 + 2 * k] = inv[k][0]
            floats[i, 6 + 2 * k] = inv[k][1]
        for k in range(4):
            floats[i, 21 + k] = pq[k]
            floats[i, 25 + k] = u[k]
            floats[i, 29 + k] = v[k]


def _on_arrays(moments, m0, lam, q0):
    i1, i2, i3 = moments.T
    x1, x2, x3 = m0.T
    a, b, c = kf.sorted_axes(i1, i2, i3)
    p1, p2, p3, sigma2, sigma3 = kf.polhode_axes(a, b, c, lam, x1, x2, x3)
    m1 = kf.component(x1, x2, x3, p1)
    m2 = kf.component(x1, x2, x3, p2) * sigma2
    m3 = kf.component(x1, x2, x3, p3) * sigma3
    s = select(lam, -1.0, 1.0)
    inv = kf.invariants(s, kf.component(i1, i2, i3, p1), kf.component(i1, i2, i3, p2),
                        kf.component(i1, i2, i3, p3), m1, m2, m3)
    pq = kf.permutation_quaternion(p1, p2, p3, sigma2, sigma3)
    u, v = kf.anchor(*q0.T, pq, m1, m2, m3, inv[6][0])
    ints = np.stack([a, b, c, p1, p2, p3], axis=1)
    floats = np.stack([sigma2, sigma3, m1, m2, m3, *(x for pair in inv for x in pair), *pq, *u, *v], axis=1)
    return ints, floats


@pytest.mark.parametrize("seed", [3, 11])
def test_frame_kernels_on_floats_equal_kernels_on_arrays_bitwise(seed):
    moments, m0, lam, q0 = _states(seed)
    ints = np.zeros((moments.shape[0], 6), dtype=np.int64)
    floats = np.zeros((moments.shape[0], 33))
    _on_floats(moments, m0, lam, q0, ints, floats)
    want_ints, want_floats = _on_arrays(moments, m0, lam, q0)
    assert np.array_equal(ints, want_ints)
    # error-free products by fused multiply-add (compiled) or Dekker's splitting (arrays): the
    # same exact values, so every double-double and quaternion has the same bits
    assert np.array_equal(floats, want_floats)


def test_sorted_axes_match_stable_argsort():
    moments, _, _, _ = _states(5)
    got = np.stack(kf.sorted_axes(*moments.T), axis=1)
    assert np.array_equal(got, np.argsort(moments, axis=1, kind="stable"))


@pytest.mark.parametrize("lam", [False, True])
def test_working_axes_give_a_proper_frame_around_the_polhode_axis(lam):
    moments, m0, _, _ = _states(7)
    flags = np.full(moments.shape[0], lam)
    a, b, c = kf.sorted_axes(*moments.T)
    p1, p2, p3, sigma2, sigma3 = kf.polhode_axes(a, b, c, flags, *m0.T)
    matrix = np.zeros((moments.shape[0], 3, 3))  # rows: working axes in body components
    rows = np.arange(moments.shape[0])
    for j, (p, sigma) in enumerate(((p1, 1.0), (p2, sigma2), (p3, sigma3))):
        matrix[rows, j, p] = sigma
    np.testing.assert_allclose(np.linalg.det(matrix), 1.0, rtol=0, atol=1e-15)
    mw = np.einsum("nij,nj->ni", matrix, m0)
    assert np.all(mw[:, 2] >= 0)
    srt = np.sort(moments, axis=1)
    iw = np.einsum("nij,nj->ni", np.abs(matrix), moments)
    assert np.array_equal(iw[:, 2], srt[:, 0] if lam else srt[:, 2])
    assert np.array_equal(iw[:, 1], srt[:, 1])


def test_permutation_quaternion_matches_scipy_for_every_proper_frame():
    cases = []
    for perm in ([0, 1, 2], [0, 2, 1], [1, 0, 2], [1, 2, 0], [2, 0, 1], [2, 1, 0]):
        for sigma2 in (1.0, -1.0):
            for sigma3 in (1.0, -1.0):
                matrix = np.zeros((3, 3))
                matrix[[0, 1, 2], perm] = (1.0, sigma2, sigma3)
                if np.linalg.det(matrix) > 0:
                    cases.append((perm, sigma2, sigma3, matrix))
    assert len(cases) == 12
    for perm, sigma2, sigma3, matrix in cases:
        q = np.array([float(x) for x in kf.permutation_quaternion(*perm, sigma2, sigma3)])
        np.testing.assert_allclose(Rotation.from_quat(q).as_matrix(), matrix, rtol=0, atol=4e-16)
        assert abs(np.dot(q, q) - 1.0) <= 4e-16


def _exact(x):
    return Fraction(float(x))


@pytest.mark.parametrize("s", [1.0, -1.0])
def test_invariants_match_exact_rational_arithmetic(s):
    rng = np.random.default_rng(13)
    for _ in range(20):
        i1, i2, i3 = np.sort(rng.uniform(0.5, 1.0, 3))[:: int(s)]
        m1, m2, m3 = rng.normal(size=3)
        got = kf.invariants(s, i1, i2, i3, m1, m2, m3)
        w = [1 / _exact(i) for i in (i1, i2, i3)]
        e = {(i, j): Fraction(int(s)) * (w[i] - w[j]) for i, j in ((0, 1), (0, 2), (1, 2))}
        sq = [_exact(m) ** 2 for m in (m1, m2, m3)]
        want = [
            e[0, 1], e[0, 2], e[1, 2],
            sq[0] * e[0, 2] + sq[1] * e[1, 2],
            sq[2] * e[1, 2] - sq[0] * e[0, 1],
            sq[1] * e[0, 1] + sq[2] * e[0, 2],
        ]  # fmt: skip
        # (P₂ is a difference: its error is relative to the size of its terms)
        size = [abs(x) for x in want[:3]] + [sum(sq) * max(abs(x) for x in want[:3])] * 3
        for (hi, lo), exact, scale in zip(got[:6], want, size, strict=True):
            assert abs(Fraction(float(hi)) + Fraction(float(lo)) - exact) <= Fraction(1, 2**100) * scale
        with mp.workdps(50):
            g = mp.sqrt(sum(mp.mpf(x.numerator) / x.denominator for x in sq))
            assert abs(mp.mpf(float(got[6][0])) + mp.mpf(float(got[6][1])) - g) <= mp.mpf(2) ** -100 * g
        hi, lo = got[7]
        assert abs(Fraction(float(hi)) + Fraction(float(lo)) - w[2]) <= Fraction(1, 2**100) * w[2]


def test_anchor_reproduces_the_initial_attitude():
    moments, m0, lam, q0 = _states(17, n=50)
    a, b, c = kf.sorted_axes(*moments.T)
    p1, p2, p3, sigma2, sigma3 = kf.polhode_axes(a, b, c, lam, *m0.T)
    x1, x2, x3 = m0.T
    mw = np.stack([kf.component(x1, x2, x3, p1), kf.component(x1, x2, x3, p2) * sigma2,
                   kf.component(x1, x2, x3, p3) * sigma3], axis=1)
    g = np.linalg.norm(m0, axis=1)
    pq = kf.permutation_quaternion(p1, p2, p3, sigma2, sigma3)
    u, v = kf.anchor(*q0.T, pq, *mw.T, g)
    frame = Rotation.from_quat(np.stack(pq, axis=1))
    # the shortest arc from m_w to +z, built from scipy's rotation vector (independent formula)
    axis = np.cross(mw, [0.0, 0.0, 1.0])
    angle = np.arccos(np.clip(mw[:, 2] / g, -1.0, 1.0))
    norm = np.linalg.norm(axis, axis=1)
    arc = Rotation.from_rotvec(axis / np.where(norm > 0, norm, 1.0)[:, None] * angle[:, None])
    # rot(0) = U ⊗ P* ⊗ S(m_w) ⊗ P = q₀ and V = U ⊗ P* ⊗ e_z ⊗ P
    rot0 = Rotation.from_quat(np.stack(u, axis=1)) * frame.inv() * arc * frame
    assert np.all((rot0 * Rotation.from_quat(q0).inv()).magnitude() < 1e-14)
    half_turn = Rotation.from_rotvec([0.0, 0.0, np.pi])
    want_v = Rotation.from_quat(np.stack(u, axis=1)) * frame.inv() * half_turn * frame
    assert np.all((Rotation.from_quat(np.stack(v, axis=1)) * want_v.inv()).magnitude() < 1e-14)
