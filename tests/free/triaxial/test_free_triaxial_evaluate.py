"""The theta-series kernels (andoyer.free.triaxial.evaluate): one text, the same bits per state and on arrays.

The numpy path (:mod:`andoyer.free.triaxial.evaluate_numpy`) applies the kernels to whole arrays with the
number of terms of its block; the compiled path (:mod:`andoyer.free.triaxial.evaluate_compiled`, and a
loop here) calls them per state, compiled when numba is (plain Python on floats with
``ANDOYER_NUMBA=0``).  Both must agree bit for bit; the values are checked against
mpmath's theta functions and Jacobi functions.  The one exception is ``exp`` in the
hyperbolic series: numpy's vectorised one and libm's (in compiled code) may differ by an ulp.
"""

from __future__ import annotations

import mpmath
import numpy as np
import pytest
from scipy.spatial.transform import Rotation
from scipy.special import ellipk

from andoyer._jit import jit
from andoyer.free.common.polhode import attitude
from andoyer.free.triaxial.evaluate import circular, half_angle, hyperbolic

Q_MAX = float(np.exp(-np.pi))  # the nome at k² = 1/2, the largest either series meets


@jit
def _circular_loop(s1, c1, q, wa, wb, n_odd, n_even, n_w, out):
    # the kernel on one state's floats at a time, compiled (or plain Python without numba)
    for i in range(s1.size):
        w_a = (wa[0, i], wa[1, i], wa[2, i])
        w_b = (wb[0, i], wb[1, i], wb[2, i])
        res = circular(s1[i], c1[i], q[i], w_a, w_b, n_odd, n_even, n_w)
        for k in range(6):
            out[k, i] = res[k]


@jit
def _hyperbolic_loop(f, q, kk, n_sh, n_th, out):
    for i in range(f.size):
        res = hyperbolic(f[i], q[i], kk[i], n_sh, n_th)
        for k in range(5):
            out[k, i] = res[k]


@jit
def _attitude_loop(psi, slope, f, x, y, u, v, va, vb, sn, cn, m3, G, out):
    for i in range(psi.size):
        cz, sz = half_angle(psi[i], slope[i], f[i], x[i], y[i])
        res = attitude(
            cz, sz, (u[0, i], u[1, i], u[2, i], u[3, i]), (v[0, i], v[1, i], v[2, i], v[3, i]),
            (va[0, i], va[1, i], va[2, i]), (vb[0, i], vb[1, i], vb[2, i]), sn[i], cn[i], m3[i], G[i],
        )
        out[0, i], out[1, i] = cz, sz
        for k in range(4):
            out[2 + k, i] = res[k]


def _circular_inputs(rng, n=400):
    x = 2.0 * np.pi * rng.uniform(-0.5, 0.5, n)
    q = Q_MAX * rng.uniform(0.0, 1.0, n) ** 3
    q[:3] = (0.0, Q_MAX, 1e-6)
    return np.sin(x), np.cos(x), q, rng.normal(size=(3, n)), rng.normal(size=(3, n))


@pytest.mark.parametrize(("n_odd", "n_even", "n_w"), [(4, 4, 3), (3, 2, 3), (2, 1, 0), (1, 0, 1), (4, 3, 2)])
def test_circular_kernel_per_state_equals_arrays(n_odd, n_even, n_w):
    s1, c1, q, wa, wb = _circular_inputs(np.random.default_rng(11))
    arrays = circular(s1, c1, q, wa, wb, n_odd, n_even, n_w)
    per_state = np.empty((6, s1.size))
    _circular_loop(s1, c1, q, wa, wb, n_odd, n_even, n_w, per_state)
    for k in range(6):
        assert np.array_equal(np.broadcast_to(arrays[k], s1.shape), per_state[k]), k


@pytest.mark.parametrize(("n_sh", "n_th"), [(5, 5), (4, 4), (2, 3), (1, 1)])
def test_hyperbolic_kernel_per_state_equals_arrays(n_sh, n_th):
    rng = np.random.default_rng(12)
    n = 400
    f = rng.uniform(-0.5, 0.5, n)
    f[:4] = (0.0, 0.25, -0.25, 0.5)
    q = Q_MAX * rng.uniform(0.0, 1.0, n)
    kk = -2.0 * np.pi**2 / np.log(np.maximum(q, 1e-300))  # 2πK/K' from q' = e^{−πK/K'}
    arrays = hyperbolic(f, q, kk, n_sh, n_th)
    per_state = np.empty((5, n))
    _hyperbolic_loop(f, q, kk, n_sh, n_th, per_state)
    # the one primitive that differs: numpy's vectorised exp and libm's (compiled) are each
    # within an ulp, not always the same one; where e^{−y} agrees, every bit does
    zi = per_state[4]
    assert np.all(np.abs(arrays[4] - zi) <= np.spacing(zi))
    same = arrays[4] == zi
    assert np.mean(same) > 0.8
    for k in range(5):
        assert np.array_equal(arrays[k][same], per_state[k][same]), k


@pytest.mark.parametrize("q", [1e-4, 0.01, Q_MAX])
def test_circular_kernel_theta_functions_mpmath(q):
    # th3 = ϑ₃(x|q), 1/inv = ϑ₄(x|q), num_s = ϑ₁(x|q)/(2q^{1/4}), num_c = ϑ₂(x|q)/(2q^{1/4}) (DLMF 20.2)
    x = np.linspace(-np.pi, np.pi, 13)[:-1] + 0.1
    num_s, num_c, th3, inv, _, _ = circular(np.sin(x), np.cos(x), q, (), (), 4, 4, 0)
    scale = 2.0 * mpmath.mpf(q) ** 0.25
    with mpmath.workdps(30):
        for i, xi in enumerate(x):
            want = [mpmath.jtheta(n, xi, q) for n in (1, 2, 3, 4)]
            assert abs(num_s[i] - float(want[0] / scale)) <= 4e-16
            assert abs(num_c[i] - float(want[1] / scale)) <= 4e-16
            assert abs(th3[i] - float(want[2])) <= 4e-16
            assert abs(inv[i] - float(1 / want[3])) <= 4e-16


@pytest.mark.parametrize("m", [0.5 + 1e-12, 0.7, 0.99, 1.0 - 1e-10])
def test_hyperbolic_kernel_jacobi_ratios_mpmath(m):
    # each quotient is sn, cn, dn of τ = 4K f up to a constant factor: ratios of two phases
    big_k, small_k = ellipk(m), ellipk(1.0 - m)
    q, kk = np.exp(-np.pi * big_k / small_k), 2.0 * np.pi * big_k / small_k
    f = np.linspace(-0.5, 0.5, 21)[1:-1] + 0.013
    sh, t4, t3, _, _ = hyperbolic(f, q, kk, 5, 5)
    with mpmath.workdps(30):  # scipy's ellipj loses digits as m → 1
        u = [4 * mpmath.ellipk(m) * mpmath.mpf(fi) for fi in f]
        sn, cn, dn = (np.array([float(mpmath.ellipfun(w, ui, m=m)) for ui in u]) for w in ("sn", "cn", "dn"))
    np.testing.assert_allclose(sh / t4 / (sh[0] / t4[0]), (sn / cn) / (sn[0] / cn[0]), rtol=1e-12)
    np.testing.assert_allclose(t3 / t4 / (t3[0] / t4[0]), (dn / cn) / (dn[0] / cn[0]), rtol=1e-12)


def _attitude_inputs(rng, n=400):
    psi, f = rng.uniform(-0.5, 0.5, n), rng.uniform(-0.5, 0.5, n)
    slope, x, y = rng.normal(size=n), rng.normal(size=n), rng.normal(size=n)
    u, v = Rotation.random(n, random_state=4).as_quat().T, Rotation.random(n, random_state=5).as_quat().T
    va, vb = rng.normal(size=(3, n)), rng.normal(size=(3, n))
    G = rng.uniform(0.5, 2.0, n)
    m3 = G * rng.uniform(-0.99, 1.0, n)
    return psi, slope, f, x, y, u, v, va, vb, rng.normal(size=n), rng.normal(size=n), m3, G


def test_attitude_kernels_per_state_equals_arrays():
    psi, slope, f, x, y, u, v, va, vb, sn, cn, m3, G = _attitude_inputs(np.random.default_rng(13))
    cz, sz = half_angle(psi, slope, f, x, y)
    arrays = (cz, sz, *attitude(cz, sz, u, v, va, vb, sn, cn, m3, G))
    per_state = np.empty((6, psi.size))
    _attitude_loop(psi, slope, f, x, y, u, v, va, vb, sn, cn, m3, G, per_state)
    for k in range(6):
        assert np.array_equal(arrays[k], per_state[k]), k


def test_attitude_kernels_rotation_composition():
    # half_angle: the angle 2πg + arg(x + iy); attitude: (U cos + V sin) ⊗ the arc (v, G + m₃)/norm
    rng = np.random.default_rng(14)
    psi, slope, f, x, y, u, v, va, vb, sn, cn, m3, G = _attitude_inputs(rng)
    cz, sz = half_angle(psi, slope, f, x, y)
    g = 0.5 * psi + slope * f
    angle = 2.0 * np.pi * g + np.arctan2(y, x)
    np.testing.assert_allclose(cz, np.cos(angle), atol=1e-14)
    np.testing.assert_allclose(sz, np.sin(angle), atol=1e-14)
    got = np.array(attitude(cz, sz, u, v, va, vb, sn, cn, m3, G)).T
    arc = np.concatenate([(va * sn + vb * cn).T, (G + m3)[:, None]], axis=1)
    arc /= np.sqrt(2.0 * G * (G + m3))[:, None]
    a = (u * cz + v * sz).T
    # Hamilton product a ⊗ b, scalar last, written out independently
    av, aw, bv, bw = a[:, :3], a[:, 3], arc[:, :3], arc[:, 3]
    vector = aw[:, None] * bv + bw[:, None] * av + np.cross(av, bv)
    want = np.concatenate([vector, (aw * bw - np.sum(av * bv, axis=1))[:, None]], axis=1)
    np.testing.assert_allclose(got, want, atol=1e-13)
