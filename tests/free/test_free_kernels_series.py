"""The theta-series kernels (andoyer.free.kernels.series): one text, the same bits per state and on arrays.

The numpy path (:mod:`andoyer.free.series`) applies the kernels to whole arrays with the
number of terms of its block; the compiled path (:mod:`andoyer.free.compiled_eval`, and a
loop here) calls them per state, compiled when numba is (plain Python on floats with
``ANDOYER_NUMBA=0``).  Both must agree bit for bit; the values are checked against
mpmath's theta functions and Jacobi functions.  The one exception is ``exp`` in the
hyperbolic series: numpy's vectorised one and libm's (in compiled code) may differ by an ulp.
"""

from __future__ import annotations

import mpmath
import numpy as np
import pytest
from scipy.special import ellipk

from andoyer._jit import jit
from andoyer.free.kernels.series import circular, hyperbolic

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
