"""Berger's daily-mean insolation against a direct average of the instantaneous insolation."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import quad

from andoyer.planetary.spin_axis import daily_insolation


def _quadrature(phi, lam, eps, e, varpi, s0=1361.0):
    """(1/2π)∫ S₀ (a/r)² max(0, cos z) dH over the hour angle, with the distance from Kepler's ellipse."""
    delta = np.arcsin(np.sin(eps) * np.sin(lam))
    v = lam - varpi - np.pi  # true anomaly of the Earth: the Sun's geocentric perihelion is at ϖ + π
    distance = (1 - e * e) / (1 + e * np.cos(v))  # r/a

    def cos_zenith(hour):
        return max(0.0, np.sin(phi) * np.sin(delta) + np.cos(phi) * np.cos(delta) * np.cos(hour))

    value, _ = quad(cos_zenith, -np.pi, np.pi, limit=200, epsabs=1e-14, epsrel=1e-13,
                    points=[-np.pi / 2, np.pi / 2])
    return s0 / distance**2 * value / (2 * np.pi)


@pytest.mark.parametrize(
    ("lat", "lam", "eps", "e", "varpi"),
    [
        (65.0, 90.0, 23.44, 0.0167, 102.94),  # 65° N, June solstice, today
        (65.0, 90.0, 24.5, 0.05, 270.0),  # high obliquity, perihelion at the June solstice
        (-30.0, 200.0, 22.1, 0.03, 10.0),
        (0.0, 0.0, 23.44, 0.0, 0.0),  # equator at the equinox: S0/π exactly
        (85.0, 100.0, 23.44, 0.0167, 102.94),  # polar day
        (-85.0, 100.0, 23.44, 0.0167, 102.94),  # polar night
    ],
)
def test_daily_insolation_matches_hour_angle_quadrature(lat, lam, eps, e, varpi):
    args = [*np.radians([lat, lam, eps]).tolist(), e, np.radians(varpi)]
    got = float(daily_insolation(*args))
    assert got == pytest.approx(_quadrature(*args), rel=1e-10, abs=1e-9)


def test_daily_insolation_65n_june_solstice_today():
    """About 478 W/m² with S0 = 1361: the commonly quoted present-day value is near 480 W/m²."""
    q = float(daily_insolation(np.radians(65), np.pi / 2, np.radians(23.439), 0.0167, np.radians(102.94)))
    assert 470.0 <= q <= 490.0


def test_history_insolation_uses_its_obliquity_and_perihelion():
    from spin_cases import PrecessingOrbit

    from andoyer.planetary.spin_axis import spin_axis_history

    orbit = PrecessingOrbit()
    h = spin_axis_history(orbit, "mars", [-50000.0, 0.0, 30000.0], precession_rate=7.597)
    got = h.insolation(np.radians(65.0), np.pi / 2)
    expected = [_quadrature(np.radians(65.0), np.pi / 2, eps, e, w) for eps, e, w in
                zip(h.obliquity, h.eccentricity, h.perihelion, strict=True)]
    assert np.allclose(got, expected, rtol=1e-10)
    assert np.allclose(h.eccentricity, orbit.e, rtol=1e-14)
