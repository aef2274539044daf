"""Elliptic integrals of the first, second and third kinds against mpmath at high precision."""

import mpmath as mp
import numpy as np
import pytest

from andoyer.special import ellipe, ellipeinc, ellipf, ellipk, ellippi, ellippiinc

EPS = np.finfo(float).eps


def _m(mc):
    """Exact parameter 1 − mc for mpmath (enough digits that 1 − m keeps all of mc)."""
    return 1 - mp.mpf(float(mc))


def _dps(mc):
    return 40 + int(max(0.0, -np.log10(max(float(mc), 1e-320))))


def _rel(got, ref):
    return abs(float((mp.mpf(float(got)) - ref) / ref))


# parameters from m = 0 to 1 − m = 1e-300, and m < 0
MCS = [1.0, 0.9, 0.5, 0.3, 0.1, 1e-3, 1e-6, 1e-10, 1e-16, 1e-50, 1e-300, 1.5, 4.0]


@pytest.mark.parametrize("mc", MCS)
def test_ellipk_matches_mpmath_to_one_ulp(mc):
    with mp.workdps(_dps(mc)):
        ref = mp.ellipk(_m(mc))
        assert _rel(ellipk(1 - mc, mc=mc), ref) <= EPS


@pytest.mark.parametrize("mc", MCS)
def test_ellipe_matches_mpmath(mc):
    with mp.workdps(_dps(mc)):
        ref = mp.ellipe(_m(mc))
        assert _rel(ellipe(1 - mc, mc=mc), ref) <= 4 * EPS


def test_complete_integrals_at_m_one():
    assert np.isinf(ellipk(1.0))
    assert ellipe(1.0) == 1.0


@pytest.mark.parametrize("mc", [0.7, 0.2, 1e-8])
def test_legendre_relation(mc):
    # E K' + E' K − K K' = π/2 (DLMF 19.7.1): couples the two kinds and both parameters
    m = 1 - mc
    K, E = ellipk(m, mc=mc), ellipe(m, mc=mc)
    Kp, Ep = ellipk(mc, mc=m), ellipe(mc, mc=m)
    assert abs(E * Kp + Ep * K - K * Kp - np.pi / 2) < 8 * EPS * K * Kp


def _incomplete_cases(seed, n):
    rng = np.random.default_rng(seed)
    mc = np.concatenate([rng.uniform(0.0, 1.0, n // 2), 10 ** rng.uniform(-16, -1, n - n // 2)])
    phi = rng.uniform(-20.0, 20.0, n)
    phi[::7] = np.pi / 2 * rng.choice([-1, 1], phi[::7].size)  # complete values
    return mc, phi


@pytest.mark.parametrize("seed", [0, 1])
def test_ellipf_matches_mpmath(seed):
    mc, phi = _incomplete_cases(seed, 40)
    got = ellipf(phi, 1 - mc, mc=mc)
    for g, p, c in zip(got, phi, mc, strict=True):
        with mp.workdps(_dps(c)):
            assert _rel(g, mp.ellipf(float(p), _m(c))) <= 2 * EPS


@pytest.mark.parametrize("seed", [2, 3])
def test_ellipeinc_matches_mpmath(seed):
    mc, phi = _incomplete_cases(seed, 40)
    got = ellipeinc(phi, 1 - mc, mc=mc)
    for g, p, c in zip(got, phi, mc, strict=True):
        with mp.workdps(_dps(c)):
            assert _rel(g, mp.ellipe(float(p), _m(c))) <= 6 * EPS


@pytest.mark.parametrize(("n_range", "bound"), [((-10.0, 0.9), 8 * EPS), ((-1e3, -10.0), 30 * EPS)])
def test_ellippiinc_matches_mpmath(n_range, bound):
    # Large negative characteristics cancel between the R_F and R_J terms (DLMF 19.25.14):
    # the error grows like √|n| ulps (documented in the module).
    mc, phi = _incomplete_cases(5, 40)
    n = np.random.default_rng(6).uniform(*n_range, mc.size)
    got = ellippiinc(n, phi, 1 - mc, mc=mc)
    for g, k, p, c in zip(got, n, phi, mc, strict=True):
        with mp.workdps(_dps(c)):
            assert _rel(g, mp.ellippi(float(k), float(p), _m(c))) <= bound


@pytest.mark.parametrize(("n", "mc"), [(-0.5, 0.5), (-30.0, 0.2), (0.4, 1e-9), (0.99, 0.5)])
def test_ellippi_complete_matches_mpmath(n, mc):
    with mp.workdps(_dps(mc)):
        assert _rel(ellippi(n, 1 - mc, mc=mc), mp.ellippi(n, _m(mc))) <= 8 * EPS


@pytest.mark.parametrize(("n", "phi", "m"), [(2.0, 1.2, 0.5), (3.0, 0.3, 0.2), (1.5, 0.9, 0.7)])
def test_ellippi_above_one_is_the_principal_value(n, phi, m):
    # mpmath continues analytically; its real part is the Cauchy principal value
    # (checked here independently: PV of the complete integral, DLMF 19.6.5,
    # Π(n|m) = K(m) − Π(m/n|m) for n > 1).
    with mp.workdps(30):
        assert _rel(ellippiinc(n, phi, m), mp.re(mp.ellippi(n, phi, m))) <= 8 * EPS
        pv = mp.ellipk(m) - mp.ellippi(m / n, m)
        assert _rel(ellippi(n, m), pv) <= 8 * EPS


def test_ellippi_at_n_one_is_infinite():
    assert np.isinf(ellippi(1.0, 0.5))


def test_amplitude_reduction_uses_periods():
    m = 0.7
    for j in (-3, 1, 40):
        r = 0.4
        assert abs(ellipf(j * np.pi + r, m) - (2 * j * ellipk(m) + ellipf(r, m))) < 8 * EPS * abs(
            2 * j * ellipk(m)
        )
        whole = 2 * j * ellippi(-2.0, m) + ellippiinc(-2.0, r, m)
        assert abs(ellippiinc(-2.0, j * np.pi + r, m) - whole) < 1e-13 * abs(j)


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (lambda: ellipk(1.5), "parameter m"),
        (lambda: ellipk(np.nan), "finite parameter"),
        (lambda: ellipf(np.inf, 0.5), "finite amplitude"),
        (lambda: ellipk(0.9, mc=0.2), "mc = 1 - m"),
    ],
)
def test_bad_input_raises(call, message):
    with pytest.raises(ValueError, match=message):
        call()


def test_scalar_in_scalar_out_and_broadcasting():
    assert np.shape(ellipk(0.5)) == ()
    assert ellipf(np.zeros((2, 1)), np.full(3, 0.5)).shape == (2, 3)
