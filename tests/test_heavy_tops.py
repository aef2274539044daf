"""The Lagrange and Kovalevskaya tops conserve their extra integrals under the reference integrator."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from andoyer import State
from andoyer.integrate import integrate_reference
from andoyer.perturbations import Model, kovalevskaya_integral, kovalevskaya_top, lagrange_top


def run(body, top, periods, samples=50):
    state = State.from_attitude(Rotation.from_euler("ZXZ", [0.2, 1.0, 0.5]), [0.4, -0.3, 2.0])
    spin_period = 2 * np.pi / abs(state.omega(body)[2])
    t = np.linspace(0, periods * spin_period, samples)
    out = integrate_reference(Model(body, top), state, t, rtol=1e-13, atol=1e-15)
    return state, out


def invariants(body, top, s):
    gamma = top.gamma(s.quaternion)
    energy = s.energy(body) + top.potential(0.0, s.quaternion, s.m_body)
    return energy, np.sum(s.m_body * gamma, -1), np.linalg.norm(gamma, axis=-1)


def relative_spread(x):
    return np.ptp(x) / np.abs(x).max()


@pytest.mark.parametrize("periods", [100])
def test_lagrange_top_conserves_m3_energy_and_casimirs(periods):
    body, top = lagrange_top(1.0, 0.6, 1.5, 0.4)
    _, out = run(body, top, periods)
    energy, casimir, norm = invariants(body, top, out)
    assert relative_spread(out.m_body[:, 2]) <= 1e-10
    assert relative_spread(energy) <= 1e-10
    assert relative_spread(casimir) <= 1e-10
    assert np.abs(norm - 1).max() <= 1e-12


@pytest.mark.parametrize("periods", [100])
def test_kovalevskaya_top_conserves_its_integral(periods):
    body, top = kovalevskaya_top(1.0, 1.3, 0.7)
    _, out = run(body, top, periods)
    K = kovalevskaya_integral(body, top, out.quaternion, out.m_body)
    assert relative_spread(K) <= 1e-10
    energy, casimir, _ = invariants(body, top, out)
    assert relative_spread(energy) <= 1e-10
    assert relative_spread(casimir) <= 1e-10


def test_kovalevskaya_integral_has_teeth():
    """With the wrong sign of c the same expression is not conserved."""
    body, top = kovalevskaya_top(1.0, 1.3, 0.7)
    _, out = run(body, top, 5)
    p, q = (out.m_body[:, :2] / body.moments[:2]).T
    gamma = top.gamma(out.quaternion)
    c = -top.weight * 0.7 / 1.0
    wrong = (p * p - q * q - c * gamma[:, 0]) ** 2 + (2 * p * q - c * gamma[:, 1]) ** 2
    assert relative_spread(wrong) > 1e-3


def test_kovalevskaya_integral_rejects_other_tops():
    body, top = lagrange_top(1.0, 0.6, 1.5, 0.4)
    with pytest.raises(ValueError, match=r"^expected a Kovalevskaya top"):
        kovalevskaya_integral(body, top, [0, 0, 0, 1.0], [0, 0, 1.0])
