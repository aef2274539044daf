"""Jacobi elliptic functions and amplitude against mpmath, for large u and m → 1."""

import zlib

import mpmath as mp
import numpy as np
import pytest
import scipy.special as sc
from hypothesis import given, settings
from hypothesis import strategies as st

from andoyer.special import am, ellipf, ellipj, ellipk
from andoyer.special.theta import lattice

EPS = np.finfo(float).eps


def _ref(u, mc):
    """sn, cn, dn at 1 − m = mc (exact float) with enough digits for the reduction."""
    dps = 40 + int(max(0.0, -np.log10(max(mc, 1e-320)))) + int(np.log10(1 + abs(u)))
    with mp.workdps(dps):
        m = 1 - mp.mpf(float(mc))
        return [mp.ellipfun(f, mp.mpf(float(u)), m=m) for f in ("sn", "cn", "dn")]


# (label, 1 − m values, u range): moderate parameters, huge arguments, m → 1 with many
# periods, the extreme 1 − m = 1e-300 (K ≈ 347), and m → 0.
CASES = [
    ("moderate", lambda r, n: r.uniform(0.05, 0.95, n), 10.0),
    ("large u", lambda r, n: r.uniform(0.05, 0.95, n), 1e6),
    ("1-m=1e-10", lambda r, n: np.full(n, 1e-10), 400.0),
    ("1-m in [1e-16, 1e-10]", lambda r, n: 10 ** r.uniform(-16, -10, n), 1e4),
    ("1-m=1e-300", lambda r, n: np.full(n, 1e-300), 3000.0),
    ("m in [1e-14, 1e-10]", lambda r, n: 1 - 10 ** r.uniform(-14, -10, n), 1e3),
]


@pytest.mark.parametrize(("label", "mcs", "umax"), CASES, ids=[c[0] for c in CASES])
def test_ellipj_matches_mpmath(label, mcs, umax):
    rng = np.random.default_rng(zlib.crc32(label.encode()))
    mc = mcs(rng, 12)
    u = rng.uniform(-umax, umax, 12)
    sn, cn, dn, _ = ellipj(u, 1 - mc, mc=mc)
    for i in range(u.size):
        ref = _ref(u[i], mc[i])
        err = max(abs(float(a - b)) for a, b in zip((sn[i], cn[i], dn[i]), ref, strict=True))
        assert err <= 3 * EPS, (label, u[i], mc[i], err)


def test_ellipj_beats_scipy_where_scipy_fails():
    # scipy's ellipj (Cephes) only sees the rounded m and loses the phase for large u:
    # record that it is off where ours is not (see docs/errata-free.md).
    u, mc = 37.5, 1e-10
    ref = [float(x) for x in _ref(u, mc)]
    ours = ellipj(u, 1 - mc, mc=mc)[:3]
    theirs = sc.ellipj(u, 1 - mc)[:3]
    assert max(abs(a - b) for a, b in zip(ours, ref, strict=True)) <= 2 * EPS
    assert max(abs(a - b) for a, b in zip(theirs, ref, strict=True)) > 1e-6


@pytest.mark.parametrize("mc", [0.9, 0.3, 1e-5, 1e-12])
def test_identities_hold_to_round_off(mc):
    u = np.linspace(-50, 50, 2001)
    sn, cn, dn, _ = ellipj(u, 1 - mc, mc=mc)
    assert np.max(np.abs(sn**2 + cn**2 - 1)) <= 8 * EPS
    assert np.max(np.abs(dn**2 + (1 - mc) * sn**2 - 1)) <= 8 * EPS


@given(
    st.floats(min_value=-30.0, max_value=30.0),
    st.floats(min_value=0.0, max_value=0.999999),
)
@settings(max_examples=200, deadline=None)
def test_amplitude_round_trip(phi, m):
    # am inverts F: am(F(φ|m)|m) = φ; F comes from Carlson's R_F, am from theta series
    u = ellipf(phi, m)
    assert abs(am(u, m) - phi) <= 16 * EPS * max(1.0, abs(phi), abs(float(u)))


def test_amplitude_is_continuous_and_quasi_periodic():
    m = 0.8
    K = float(ellipk(m))
    u = np.linspace(-10 * K, 10 * K, 10001)
    ph = am(u, m)
    assert np.all(np.diff(ph) > 0)
    assert abs(am(3.3 + 2 * K, m) - am(3.3, m) - np.pi) <= 8 * EPS * 10


def test_limits_m_zero_and_one():
    u = np.linspace(-20, 20, 101)
    sn, cn, dn, ph = ellipj(u, 0.0)
    assert np.max(np.abs(sn - np.sin(u))) <= 4 * EPS
    assert np.max(np.abs(cn - np.cos(u))) <= 4 * EPS
    assert np.all(dn == 1.0)
    sn, cn, dn, ph = ellipj(u, 1.0)
    assert np.array_equal(sn, np.tanh(u))
    assert np.allclose(cn, 1 / np.cosh(u), rtol=0, atol=EPS)
    assert np.allclose(ph, np.arctan(np.sinh(u)), rtol=0, atol=4 * EPS)


@pytest.mark.parametrize("mc", [0.7, 0.5, 0.3, 1e-6])
def test_nome_and_quarter_period_are_consistent(mc):
    # K = (π/2) ϑ₃(0|q)² (DLMF 20.9.2), with the active nome q or q' of each series
    lat = lattice(1 - mc, mc)
    with mp.workdps(40):
        m = 1 - mp.mpf(mc)
        q = mp.qfrom(m=m) if lat.circular else mp.qfrom(m=1 - m)
        assert abs(float(lat.q) - float(q)) <= 2 * EPS * float(q)
    qq = float(lat.q)
    theta3 = 1 + 2 * (qq + qq**4 + qq**9)
    quarter = float(lat.K_hi) if lat.circular else float(lat.Kp)
    assert abs(0.5 * np.pi * theta3**2 - quarter) <= 4 * EPS * quarter


def test_small_u_keeps_relative_accuracy():
    sn = ellipj(np.array([1e-30, 1e-12]), 1 - 1e-9, mc=1e-9)[0]
    assert np.allclose(sn, [1e-30, 1e-12], rtol=4 * EPS, atol=0)


@pytest.mark.parametrize(
    ("args", "message"),
    [((1.0, 1.5), "parameter m"), ((1.0, -0.1), "parameter m"), ((np.nan, 0.5), "finite argument")],
)
def test_bad_input_raises(args, message):
    with pytest.raises(ValueError, match=message):
        ellipj(*args)
