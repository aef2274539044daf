"""Heavy tops: the Euler–Poisson reference integrator conserves Casimirs, energy and the extra integrals.

Integrals are compared with their values at t = 0 (relative error). The 10⁴-period runs with DOP853
take about 20–40 s each on this machine and are marked slow; the default run keeps 300 periods with
DOP853 and, where heyoka is installed, 10⁴ periods with heyoka's Taylor integrator.
"""

from __future__ import annotations

import importlib.util

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from andoyer import RigidBody, State
from andoyer.integrate import Model, integrate_reference
from andoyer.integrate.reference.euler_poisson import (
    euler_poisson_integrals,
    euler_poisson_rates,
    integrate_euler_poisson,
)
from andoyer.liepoisson import get_algebra
from andoyer.perturbations import HeavyTop, kovalevskaya_integral, kovalevskaya_top, lagrange_top
from andoyer.perturbations.heavy_top import kovalevskaya_integral_e3

HAVE_HEYOKA = importlib.util.find_spec("heyoka") is not None
ROT0 = Rotation.from_euler("ZXZ", [0.2, 1.0, 0.5])
M0 = np.array([0.4, -0.3, 2.0])
GAMMA0 = ROT0.as_matrix()[2]


def tops():
    generic = (RigidBody(1.0, 1.6, 2.1), HeavyTop(1.1, [0.3, -0.2, 0.5]))
    return {
        "lagrange": lagrange_top(1.0, 0.6, 1.5, 0.4),
        "kovalevskaya": kovalevskaya_top(1.0, 1.3, 0.7),
        "generic": generic,
    }


def integrals(name, body, top, m, gamma):
    out = euler_poisson_integrals(body, top, m, gamma)
    out["|gamma|"] = np.sqrt(out.pop("gamma2"))
    if name == "lagrange":
        out["M3"] = m[..., 2]
    if name == "kovalevskaya":
        out["K"] = kovalevskaya_integral_e3(body, top, m, gamma)
    return out


def worst_relative_drift(name, periods, method):
    body, top = tops()[name]
    spin_period = 2 * np.pi * body.moments[2] / abs(M0[2])
    t = np.linspace(0.0, periods * spin_period, 201)
    m, gamma = integrate_euler_poisson(body, top, M0, GAMMA0, t, method=method)
    values = integrals(name, body, top, m, gamma)
    drift = {k: float(np.max(np.abs(v - v[0])) / abs(v[0])) for k, v in values.items()}
    # the top moves: the test is not satisfied by a frozen state
    assert np.ptp(gamma, axis=0).max() > 0.1
    return drift


@pytest.mark.slow
@pytest.mark.parametrize("name", ["lagrange", "kovalevskaya", "generic"])
@pytest.mark.parametrize(
    ("method", "periods"), [("dop853", 300), *([("heyoka", 10_000)] if HAVE_HEYOKA else [])]
)
def test_heavy_top_integrals_conserved_default(name, method, periods):
    drift = worst_relative_drift(name, periods, method)
    assert max(drift.values()) <= 1e-10, drift


@pytest.mark.slow
@pytest.mark.parametrize("name", ["lagrange", "kovalevskaya"])
def test_heavy_top_integrals_conserved_10k_periods_dop853(name):
    drift = worst_relative_drift(name, 10_000, "dop853")
    assert max(drift.values()) <= 1e-10, drift


@pytest.mark.parametrize("name", ["lagrange", "kovalevskaya", "generic"])
def test_euler_poisson_matches_quaternion_reference(name):
    """Two state spaces, two right-hand sides: (m, γ) vs the general (q, m) hub equations."""
    body, top = tops()[name]
    t = np.linspace(0.0, 4.0, 9)
    m, gamma = integrate_euler_poisson(body, top, M0, GAMMA0, t)
    ref = integrate_reference(Model(body, top), State.from_attitude(ROT0, M0), t, rtol=1e-13, atol=1e-15)
    assert np.abs(m - ref.m_body).max() <= 1e-10
    assert np.abs(gamma - top.gamma(ref.quaternion)).max() <= 1e-10
    if name == "kovalevskaya":
        np.testing.assert_allclose(
            kovalevskaya_integral_e3(body, top, m, gamma),
            kovalevskaya_integral(body, top, ref.quaternion, ref.m_body),
            rtol=1e-10,
        )


@pytest.mark.parametrize("name", ["lagrange", "kovalevskaya", "generic"])
def test_euler_poisson_rates_equal_lie_poisson_vector_field(name):
    body, top = tops()[name]
    x = get_algebra("e3").sample(np.random.default_rng(6), 200)
    grad_gamma = np.broadcast_to(top.weight * top.center_of_mass, (200, 3))
    grad = np.concatenate([x[:, :3] / body.moments, grad_gamma], -1)
    expected = get_algebra("e3").vector_field(x, grad)
    dm, dgamma = euler_poisson_rates(body, top, x[:, :3], x[:, 3:])
    np.testing.assert_allclose(np.concatenate([dm, dgamma], -1), expected, rtol=0, atol=1e-14)


def test_euler_poisson_time_reversal_and_broadcasting():
    body, top = tops()["generic"]
    m0 = np.stack([M0, 0.5 * M0[::-1]])
    gamma0 = np.stack([GAMMA0, GAMMA0[::-1]])
    t = np.array([[-3.0], [0.0], [2.0]])  # (3, 1) with states (2,) → (3, 2)
    m, gamma = integrate_euler_poisson(body, top, m0, gamma0, t)
    assert m.shape == gamma.shape == (3, 2, 3)
    np.testing.assert_array_equal(m[1], m0)
    back_m, back_gamma = integrate_euler_poisson(body, top, m[2], gamma[2], 0.0, t0=2.0)
    np.testing.assert_allclose(back_m, m0, rtol=0, atol=1e-12)
    np.testing.assert_allclose(back_gamma, gamma0, rtol=0, atol=1e-12)
    one_m, _ = integrate_euler_poisson(body, top, m0[1], gamma0[1], -3.0)
    np.testing.assert_allclose(one_m, m[0, 1], rtol=0, atol=1e-15)


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"method": "rk4"}, r"^expected method in"),
        ({"t": [0.0, np.nan]}, r"^expected finite t"),
        ({"m": [1.0, 2.0]}, r"^expected m with shape"),
        ({"t": np.zeros(4), "m": np.ones((3, 3))}, r"^expected times broadcastable"),
        ({"body": "earth"}, r"^expected an andoyer RigidBody"),
        ({"top": None}, r"^expected an andoyer HeavyTop"),
        ({"method": "heyoka", "rtol": 1e-12}, r"^expected (rtol=None|heyoka to be installed)"),
    ],
)
def test_integrate_euler_poisson_rejects_bad_input(kwargs, match):
    body, top = tops()["generic"]
    args = {"body": body, "top": top, "m": M0, "gamma": GAMMA0, "t": [0.0, 1.0]} | kwargs
    with pytest.raises(ValueError, match=match):
        integrate_euler_poisson(**args)


def test_kovalevskaya_integral_has_teeth():
    """With the wrong sign of c the same expression is not conserved."""
    body, top = kovalevskaya_top(1.0, 1.3, 0.7)
    m, gamma = integrate_euler_poisson(body, top, M0, GAMMA0, np.linspace(0, 20, 50))
    wrong_top = HeavyTop(1.3, [-0.7, 0.0, 0.0])
    right = kovalevskaya_integral_e3(body, top, m, gamma)
    wrong = kovalevskaya_integral_e3(body, wrong_top, m, gamma)
    assert np.ptp(right) / right.max() <= 1e-11
    assert np.ptp(wrong) / wrong.max() > 1e-3


def test_kovalevskaya_integral_rejects_other_tops():
    body, top = lagrange_top(1.0, 0.6, 1.5, 0.4)
    with pytest.raises(ValueError, match=r"^expected a Kovalevskaya top"):
        kovalevskaya_integral(body, top, [0, 0, 0, 1.0], [0, 0, 1.0])
    with pytest.raises(ValueError, match=r"^expected a Kovalevskaya top"):
        kovalevskaya_integral_e3(body, top, [0, 0, 1.0], [0, 0, 1.0])
