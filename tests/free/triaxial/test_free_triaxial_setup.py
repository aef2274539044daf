"""The shared set-up kernels of the triaxial solution (:mod:`andoyer.free.triaxial.setup`).

Each kernel is written once and runs on floats inside compiled code and on arrays from numpy:
here both ways are run on the same states and must agree, and the double-double kernels are
checked against mpmath (the modulus and frequency against the definitions, the secular rate
of ``ψ`` against a quadrature of ``dψ/dt`` over a polhode period).
"""

import mpmath as mp
import numpy as np
import pytest
from free_cases import with_k2

from andoyer._jit import jit
from andoyer.free.common.polhode_numpy import polhode_frame
from andoyer.free.common.scaling_numpy import normalise
from andoyer.free.triaxial import setup as kt

EPS = np.finfo(float).eps
MOMENTS = np.array([1.0, 1.7, 2.3])


def _frame(seed=5, n=40):
    """Random SAM and LAM states and the edges of the series (k² near 0, 1/2, 1)."""
    rng = np.random.default_rng(seed)
    moments = list(rng.uniform(1.0, 2.0, (n, 3)))
    m0 = list(rng.normal(size=(n, 3)))
    for k2 in (1e-10, 0.5 - 1e-12, 0.5 + 1e-12, 1 - 1e-10):
        moments.append(MOMENTS)
        m0.append(with_k2(MOMENTS, k2))
    moments, m0 = np.array(moments), np.array(m0)
    srt = np.sort(moments, axis=1)
    D = np.sum(m0**2 / moments, axis=1)
    lam = D * srt[:, 1] > np.sum(m0**2, axis=1)  # energy above the separatrix: LAM
    moments, m0, _, _ = normalise(moments, m0)
    return polhode_frame(moments, m0, lam)


def _dd(x):
    hi = float(x)
    return hi, float(x - mp.mpf(hi))


def _mp(pair, i):
    # call at a working precision above 106 bits
    return mp.mpf(float(pair[0][i])) + mp.mpf(float(pair[1][i]))


@jit
def _pair(x, i):
    return x[0, i], x[1, i]


@jit
def _on_floats(e12, e13, e23, P1, P2, P3, G, w3, s, mw, K, Kp, pi3, out):
    # every kernel on one state's floats, compiled (or plain Python without numba)
    for i in range(s.size):
        m, mc, omega2 = kt.modulus(_pair(e12, i), _pair(e13, i), _pair(e23, i), _pair(P1, i), _pair(P2, i),
                                   _pair(P3, i))
        amp = kt.amplitudes(e13[0, i], e23[0, i], P1[0, i], P3[0, i])
        nu = kt.polhode_frequency(omega2, _pair(K, i))
        frac0 = kt.initial_phase(mw[i, 0], mw[i, 1], mw[i, 2], amp, s[i], K[0, i])
        v1 = kt.pole_offset(e12[0, i] / e23[0, i], m)
        rate, cyc = kt.secular_rate(_pair(e13, i), _pair(e23, i), _pair(P3, i), _pair(G, i), _pair(w3, i),
                                    s[i], _pair(pi3, i), _pair(K, i))
        period, kk = kt.polhode_scales(nu[0], K[0, i], Kp[i])
        slope, prec = kt.psi_constants(m <= 0.5, s[i], Kp[i], v1, rate[0], period)
        coef = kt.momentum_coefficients(amp, s[i], 1.1, 0.9, 0.8)
        row = (m, mc[0], mc[1], omega2[0], nu[0], nu[1], frac0, v1, rate[0], rate[1], cyc[0], period, kk,
               slope, prec)
        for k in range(len(row)):
            out[i, k] = row[k]
        for k in range(3):
            out[i, len(row) + k] = amp[k]
        for k in range(5):
            out[i, len(row) + 3 + k] = coef[k]


def _on_arrays(e12, e13, e23, P1, P2, P3, G, w3, s, mw, K, Kp, pi3):
    m, mc, omega2 = kt.modulus(e12, e13, e23, P1, P2, P3)
    amp = kt.amplitudes(e13[0], e23[0], P1[0], P3[0])
    nu = kt.polhode_frequency(omega2, K)
    frac0 = kt.initial_phase(mw[:, 0], mw[:, 1], mw[:, 2], amp, s, K[0])
    v1 = kt.pole_offset(e12[0] / e23[0], m)
    rate, cyc = kt.secular_rate(e13, e23, P3, G, w3, s, pi3, K)
    period, kk = kt.polhode_scales(nu[0], K[0], Kp)
    slope, prec = kt.psi_constants(m <= 0.5, s, Kp, v1, rate[0], period)
    coef = kt.momentum_coefficients(amp, s, 1.1, 0.9, 0.8)
    row = (m, mc[0], mc[1], omega2[0], nu[0], nu[1], frac0, v1, rate[0], rate[1], cyc[0], period, kk,
           slope, prec)
    return np.stack([*row, *amp, *coef], axis=1)


def _inputs():
    """Frame invariants and K, K', Π(−κ²|k²) from mpmath (dd), shared by both evaluations."""
    fr = _frame()
    n = fr.s.size
    K, pi3, Kp = np.zeros((2, n)), np.zeros((2, n)), np.zeros(n)
    with mp.workdps(40):
        for i in range(n):
            m = _mp(fr.e12, i) * _mp(fr.P1, i) / (_mp(fr.e23, i) * _mp(fr.P3, i))
            K[:, i] = _dd(mp.ellipk(m))
            Kp[i] = float(mp.ellipk(1 - m))
            pi3[:, i] = _dd(mp.ellippi(-_mp(fr.e12, i) / _mp(fr.e23, i), m))
    pairs = [np.array(x) for x in (fr.e12, fr.e13, fr.e23, fr.P1, fr.P2, fr.P3, fr.G, fr.w3)]
    return fr, (*pairs, fr.s, np.ascontiguousarray(fr.mw), K, Kp, pi3)


def test_kernels_on_floats_equal_kernels_on_arrays():
    _, args = _inputs()
    floats = np.empty((args[8].size, 23))
    _on_floats(*args, floats)
    arrays = _on_arrays(*[tuple(a) if a.ndim == 2 and a.shape[0] == 2 else a for a in args])
    # the two paths have their own double-double arithmetic: the double-doubles (1 − k², ν,
    # Ω_ψ) agree far beyond float64, everything else to a few ulps
    for hi in (1, 4, 8):
        diff = (floats[:, hi] - arrays[:, hi]) + (floats[:, hi + 1] - arrays[:, hi + 1])
        assert np.all(np.abs(diff) <= 1e-28 * np.abs(arrays[:, hi])), hi
    single = [k for k in range(arrays.shape[1]) if k not in (2, 5, 9)]
    scale = np.maximum(np.abs(arrays[:, single]), 1.0)
    assert np.all(np.abs(floats[:, single] - arrays[:, single]) <= 4 * EPS * scale)


def test_modulus_and_frequency_match_mpmath():
    fr, args = _inputs()
    K = args[10]
    m, mc, omega2 = kt.modulus(fr.e12, fr.e13, fr.e23, fr.P1, fr.P2, fr.P3)
    nu = kt.polhode_frequency(omega2, (K[0], K[1]))
    with mp.workdps(40):
        for i in range(fr.s.size):
            den = _mp(fr.e23, i) * _mp(fr.P3, i)
            want_mc = _mp(fr.e13, i) * _mp(fr.P2, i) / den
            want_nu = mp.sqrt(den) / (4 * (mp.mpf(float(K[0, i])) + mp.mpf(float(K[1, i]))))
            assert abs(float(m[i]) - float(_mp(fr.e12, i) * _mp(fr.P1, i) / den)) <= 2 * EPS * float(m[i])
            assert abs((mp.mpf(float(mc[0][i])) + float(mc[1][i])) / want_mc - 1) < 1e-30
            assert abs((mp.mpf(float(nu[0][i])) + float(nu[1][i])) / want_nu - 1) < 1e-30


@pytest.mark.parametrize(("name", "k2", "lam"), [("sam", 0.3, False), ("sam_hyperbolic", 0.8, False),
                                                  ("lam", 0.95, True)])
def test_secular_rate_matches_the_mean_of_psi_dot(name, k2, lam):
    """``Ω_ψ = G w₃ + (sP₁/G)⟨1/(1 + c dn τ)⟩``, the mean by mpmath quadrature over ``2K``."""
    m1, m2 = (0.2, 1.0) if lam else (0.3, 0.2)
    m0 = with_k2(MOMENTS, 1 / k2 if lam else k2, m1=m1, m2=m2)
    moments, mw, _, _ = normalise(MOMENTS[None], m0[None])
    fr = polhode_frame(moments, mw, np.array([lam]))
    s = float(fr.s[0])
    with mp.workdps(30):
        x = {k: _mp(getattr(fr, k), 0) for k in ("e12", "e13", "e23", "P1", "P3", "G", "w3")}
        m = x["e12"] * x["P1"] / (x["e23"] * x["P3"])
        K = mp.ellipk(m)
        c = mp.sqrt(x["P3"] / x["e13"]) / x["G"]
        mean = mp.quad(lambda t: 1 / (1 + c * mp.ellipfun("dn", t, m)), [0, K, 2 * K]) / (2 * K)
        want = x["G"] * x["w3"] + s * x["P1"] / x["G"] * mean
        pi3 = mp.ellippi(-x["e12"] / x["e23"], m)
    dd = lambda p: (np.array([p[0][0]]), np.array([p[1][0]]))  # noqa: E731
    with mp.workdps(30):
        K_dd, pi_dd = _dd(K), _dd(pi3)
    rate, cyc = kt.secular_rate(dd(fr.e13), dd(fr.e23), dd(fr.P3), dd(fr.G), dd(fr.w3), fr.s,
                                (np.array([pi_dd[0]]), np.array([pi_dd[1]])),
                                (np.array([K_dd[0]]), np.array([K_dd[1]])))
    with mp.workdps(30):
        got = mp.mpf(float(rate[0][0])) + float(rate[1][0])
        assert abs(got / want - 1) < 1e-25, name
        assert abs((mp.mpf(float(cyc[0][0])) + float(cyc[1][0])) * 2 * mp.pi / got - 1) < 1e-30


@pytest.mark.parametrize("circular", [True, False])
def test_theta_coefficients_match_the_power_series(circular):
    """The recurrences of the ``ϑ₁`` coefficients against their closed forms in mpmath."""
    rng = np.random.default_rng(11)
    q = rng.uniform(1e-6, 0.0432, 8)  # up to e^{−π}
    v1, K = rng.uniform(0.2, 2.0, 8), rng.uniform(1.6, 3.0, 8)
    s = np.where(rng.uniform(size=8) < 0.5, -1.0, 1.0)
    wa, wb = np.zeros((2, 6, 8))
    (kt.theta_circular if circular else kt.theta_hyperbolic)(q, v1, K, s, wa, wb)
    for i in range(8):
        qi, vi, Ki = (mp.mpf(float(x[i])) for x in (q, v1, K))
        for n in range(3 if circular else 6):
            if circular:
                eta = mp.exp(-mp.pi * vi / Ki)
                head, tail = qi ** (2 * n * n) * eta**n, qi ** (2 * (n + 1) ** 2) * eta ** (-(n + 1))
                want = ((-1) ** n * (head + tail), (-1) ** n * (head - tail))
            else:
                a = -mp.pi / 2 + mp.pi / 4 * vi / Ki
                amp = (-1) ** n * mp.sqrt(qi) ** (n * n + n)
                want = (amp * mp.sin((2 * n + 1) * a), amp * mp.cos((2 * n + 1) * a))
            assert abs(wa[n, i] - float(want[0])) <= 8 * EPS, (n, i)
            assert abs(wb[n, i] - s[i] * float(want[1])) <= 8 * EPS, (n, i)
