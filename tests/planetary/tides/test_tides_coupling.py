"""The coupling point: a tidal history as the spin-axis model's α(t)."""

from __future__ import annotations

import numpy as np
import pytest

from andoyer.planetary.orbits import VondrakEcliptic
from andoyer.planetary.spin_axis import SpinAxisModel, spin_axis_history
from andoyer.planetary.tides import (
    ConstantTimeLag,
    tidal_history,
    tidal_spin_axis_history,
    tidal_spin_axis_model,
)

BASE = SpinAxisModel.from_precession_rate("earth", 50.38481507, np.radians(84381.406 / 3600))


@pytest.mark.parametrize("tides", ["constant-lag", "ocean"])
def test_coupling_rate_follows_the_history(tides):
    """α(t)/α(0) = (ω/ω0)[(1−e²)^{-3/2} + β(a0/a)³]/[(1−e²)^{-3/2} + β], from the history's own outputs
    (the model interpolates knots 1 Myr apart; the history here is integrated to each time)."""
    times = np.array([-1.0e8, -3.7e7, -1.23e6, 0.0, 2.5e6])
    model = tidal_spin_axis_model(BASE, (times[0], times[-1]), tides)
    h = tidal_history(times, tides)
    e = 0.02
    sun = (1 - e * e) ** -1.5
    spin = h.spin_rate / h.spin_rate[3]
    moon = (h.lunar_distance[3] / h.lunar_distance) ** 3
    expected = spin * (sun + BASE.beta * moon) / (sun + BASE.beta)
    assert np.allclose(model.rate(times, e) / BASE.rate(0.0, e), expected, rtol=1e-10, atol=0)


def test_coupling_at_j2000_alone_is_the_calibration():
    model = tidal_spin_axis_model(BASE, (0.0, 0.0), "ocean")
    assert model.precession_rate(np.radians(84381.406 / 3600)) == pytest.approx(50.38481507, rel=1e-14)


def test_coupling_without_dissipation_is_the_plain_model():
    times = np.linspace(-2e5, 0.0, 9)
    plain = spin_axis_history(VondrakEcliptic(), "earth", times, step=1000.0, order=8)
    tidal = tidal_spin_axis_history(
        VondrakEcliptic(), "earth", times, ConstantTimeLag(0.0), step=1000.0, order=8
    )
    assert np.abs(tidal.axis - plain.axis).max() < 1e-14


def test_coupling_changes_the_precession_as_alpha():
    """Over 200 kyr the tides change p_A by ∫(α(t) − α0) cos ε dt: 0.14° (docs/tides.md)."""
    times = np.array([-2e5, 0.0])
    plain = spin_axis_history(VondrakEcliptic(), "earth", times)
    tidal = tidal_spin_axis_history(VondrakEcliptic(), "earth", times, "constant-lag")
    assert np.degrees(plain.precession[0] - tidal.precession[0]) == pytest.approx(0.141, abs=0.002)


def test_coupling_refuses_mars_and_linear_dissipation():
    with pytest.raises(ValueError, match="expected the body 'earth'"):
        tidal_spin_axis_history(VondrakEcliptic(), "mars", [0.0])
    damped = SpinAxisModel.from_precession_rate("earth", 50.38, 0.409, tidal_dissipation=1.0)
    with pytest.raises(ValueError, match="expected tidal dissipation T_d = 0"):
        tidal_spin_axis_model(damped, (-1e5, 0.0))
    model = tidal_spin_axis_model(BASE, (-1e5, 0.0))
    with pytest.raises(ValueError, match="expected times within the tidal history's span"):
        model.rate(-2e5)
