"""The one Jacobi amplitude against mpmath, and its paths (float, numpy, compiled) against each other."""

from __future__ import annotations

import zlib

import mpmath as mp
import numpy as np
import pytest

from andoyer._jit import jit
from andoyer.free.common.elliptic import am as am_kernel
from andoyer.special import am
from andoyer.special.jacobi import amplitude

EPS = np.finfo(float).eps


def _reference(u: float, mc: float) -> float:
    """``am(u|m)`` at ``1 − m = mc`` from mpmath's ``sn``, ``cn`` on the reduced argument."""
    dps = 40 + int(max(0.0, -np.log10(max(mc, 1e-320)))) + int(np.log10(1 + abs(u)))
    with mp.workdps(dps):
        m = 1 - mp.mpf(mc)
        if mc == 0:
            return float(mp.atan(mp.sinh(mp.mpf(u))))
        K = mp.ellipk(m)
        j = mp.nint(mp.mpf(u) / (2 * K))
        r = mp.mpf(u) - 2 * j * K
        return float(mp.atan2(mp.ellipfun("sn", r, m=m), mp.ellipfun("cn", r, m=m)) + j * mp.pi)


# (label, 1 − m values, u range): the AGM's regimes, m near 1 where arcsin would lose
# half the digits, arguments of many periods (negative too), and m = 0, 1 exactly.
CASES = [
    ("moderate", lambda r, n: r.uniform(0.05, 0.95, n), 4.0),
    ("small m", lambda r, n: 1 - 10 ** r.uniform(-12, -1, n), 4.0),
    ("1-m in [1e-16, 1e-6]", lambda r, n: 10 ** r.uniform(-16, -6, n), 25.0),
    ("1-m=1e-300", lambda r, n: np.full(n, 1e-300), 600.0),
    ("large u", lambda r, n: r.uniform(0.05, 0.95, n), 1e5),
    ("large u, m near 1", lambda r, n: 10 ** r.uniform(-15, -8, n), 3e3),
    ("m=0", lambda r, n: np.ones(n), 50.0),
    ("m=1", lambda r, n: np.zeros(n), 30.0),
]


@pytest.mark.parametrize(("label", "mcs", "umax"), CASES, ids=[c[0] for c in CASES])
def test_amplitude_matches_mpmath(label, mcs, umax):
    rng = np.random.default_rng(zlib.crc32(label.encode()))
    mc = mcs(rng, 10)
    u = rng.uniform(-umax, umax, 10)
    ours = am(u, 1 - mc, mc=mc)
    for i in range(u.size):
        ref = _reference(u[i], mc[i])
        # the documented level: a few eps relative to max(1, |am|)
        assert abs(ours[i] - ref) <= 4 * EPS * max(1.0, abs(ref)), (label, u[i], mc[i])


@pytest.mark.parametrize("mc", [0.5, 1e-3, 1e-12])
def test_amplitude_kernel_on_one_period_matches_mpmath(mc):
    # the kernel alone (no reduction), as the compiled flow calls it on |u| <= K
    K = float(mp.ellipk(1 - mp.mpf(mc)))
    u = np.linspace(-K, K, 21)
    ours = amplitude(u, 1 - mc, mc)
    assert all(abs(ours[i] - _reference(u[i], mc)) <= 4 * EPS * max(1.0, abs(ours[i])) for i in range(u.size))


@jit
def _kernel_loop(u, m, mc, out):  # pragma: no cover - run compiled
    for i in range(u.size):
        out[i] = am_kernel(u[i], m[i], mc[i])


def test_amplitude_paths_agree():
    # floats one by one and numpy arrays: the same bits (elements that converge early
    # take exact halvings); the compiled kernel: numba's libm against numpy's, a few ulp
    rng = np.random.default_rng(5)
    n = 400
    mc = np.concatenate([rng.uniform(0, 1, n // 2), 10 ** rng.uniform(-300, -1, n // 2 - 2), [0.0, 1.0]])
    u = rng.uniform(-30, 30, n)
    arrays_ = amplitude(u, 1 - mc, mc)
    floats = np.array([amplitude(float(a), float(1 - b), float(b)) for a, b in zip(u, mc, strict=True)])
    compiled = np.empty(n)
    _kernel_loop(u, 1 - mc, mc, compiled)
    assert np.array_equal(arrays_, floats)
    assert np.all(np.abs(compiled - arrays_) <= 8 * np.spacing(np.abs(arrays_)))


def test_amplitude_matches_ellipj_phase():
    # sn, cn from the theta quotients agree with sin, cos of the one amplitude
    from andoyer.special import ellipj

    u = np.linspace(-40, 40, 801)
    sn, cn, _, ph = ellipj(u, 1 - 1e-9, mc=1e-9)
    assert np.max(np.abs(np.sin(ph) - sn)) <= 8 * EPS * np.max(np.abs(ph))
    assert np.max(np.abs(np.cos(ph) - cn)) <= 8 * EPS * np.max(np.abs(ph))


@pytest.mark.parametrize(("u", "m"), [(np.inf, 0.5), (1.0, 1.5), (1.0, -0.5)])
def test_amplitude_bad_input_raises(u, m):
    with pytest.raises(ValueError, match="expected"):
        am(u, m)
