"""Today's rates and values from the models' own equations against the measured ones."""

from __future__ import annotations

import math

import numpy as np
import pytest

from andoyer.planetary.spin_axis import SpinAxisModel
from andoyer.planetary.tides import EarthMoonSystem, OceanTides, present_rates, tidal_history, tidal_model
from andoyer.planetary.tides import equations as eq
from andoyer.planetary.tides.evolution import LUNAR_AGE, kernel_constants

SYSTEM = EarthMoonSystem()
MODELS = ["constant-lag", "ocean"]


@pytest.mark.parametrize("name", MODELS)
def test_present_recession_is_the_lunar_laser_ranging_rate(name):
    """3.830 ± 0.008 cm/yr (Williams & Boggs 2016): the calibration of both models."""
    assert present_rates(tidal_model(name))["recession"] == pytest.approx(3.830, abs=2e-5)


@pytest.mark.parametrize("name", MODELS)
def test_present_lunar_spin_down_is_the_recession_by_angular_momentum(name):
    """Without the Sun, d(Cω cos ε)/dt = −(m_r n a/2) da/dt at J2000 (the rate-level identity)."""
    s = SYSTEM
    c = kernel_constants(tidal_model(name), s)
    dx, dw, de = eq.rates(1.0, 1.0, s.obliquity, c, 0)
    year = 365.25 * 86400
    omega, eps, a = s.spin_rate, s.obliquity, s.lunar_semi_major_axis
    spin_change = ((s.polar_moment + 2 * s.centrifugal_moment * omega**2) * dw * omega * math.cos(eps)
                   - s.polar_moment * omega * math.sin(eps) * de) / year
    orbit_change = s.reduced_mass * s.lunar_mean_motion(a) * a / 2 * dx * a / year
    assert spin_change == pytest.approx(-orbit_change, rel=1e-12)


@pytest.mark.parametrize(("name", "excess"), [("constant-lag", 0.074), ("ocean", 0.048)])
def test_present_spin_deceleration_against_the_eclipse_record(name, excess):
    """dω/dt against the tidal −6.39 ± 0.03 × 10⁻²² rad/s² (Morrison et al. 2021, Proc. R. Soc. A 477).

    Both models are too fast by the Sun's share: a constant lag makes the solar torque 22 % of the
    lunar one (the ratio of the tide-raising forces squared, 0.21), where the measured ocean
    tides give about 14 % (6.39/5.63 − 1; 5.63 is the lunar part, from the recession); the
    ocean model's response at the S2 frequency is weaker, 19 %. docs/tides.md states these.
    """
    measured = -6.39e-22
    omega_dot = present_rates(tidal_model(name))["spin_acceleration"]
    assert omega_dot / measured - 1 == pytest.approx(excess, abs=0.002)
    lunar = present_rates(tidal_model(name), solar_tide=False)["spin_acceleration"]
    assert lunar == pytest.approx(-5.63e-22, rel=2e-3)  # the LLR recession by angular momentum


def test_present_day_length_is_the_mean_solar_day():
    """2π/(ω0 − n_⊙) from IERS ω0 and the sidereal year: 86400.0 s (to the 1e-8 of ω0's digits)."""
    h = tidal_history([0.0], "ocean")
    assert h.day_length[0] * 3600 == pytest.approx(86400.0, abs=1e-3)
    assert h.lunar_distance[0] == 384399.0


def test_present_precession_constant_from_the_model_parameters():
    """p0 = α cos ε0 from H (MHB 2002), the orbits and ε0 (IAU 2006): 50.4004″/yr.

    An independent code, the spin-axis model built from the same H, gives ψ̇ = α cos ε0 (to 2.5e-6:
    its Sun is at 1 au, the catalogue's Earth orbit at Standish's 1.00000261 au); La2004's
    50.475838″/yr is α cos ε̄ with the long-term mean obliquity ε̄ = 23.24°, not J2000's 23.44°.
    """
    p0 = tidal_history([0.0], "ocean").precession_constant[0]
    spin_axis = SpinAxisModel.from_dynamical_ellipticity("earth", SYSTEM.dynamical_ellipticity)
    assert p0 == pytest.approx(spin_axis.precession_rate(SYSTEM.obliquity), rel=4e-6)
    mean_obliquity = math.acos(50.475838 / p0 * math.cos(SYSTEM.obliquity))
    assert math.degrees(mean_obliquity) == pytest.approx(23.24, abs=0.005)


def test_present_ocean_fit_reaches_the_lunar_age():
    """The fitted ocean brings the Moon to the Laplace-plane transition 4.425 Gyr ago (the fit)."""
    c = kernel_constants(OceanTides(), SYSTEM)
    out = np.empty((1, 3))
    _, status, t_stop = eq.advance(1.0, 1.0, SYSTEM.obliquity, np.array([-6e9]), c, 1, 1e-11, out)
    assert status == 1
    assert t_stop == pytest.approx(-LUNAR_AGE, rel=2e-4)


def test_present_constant_lag_collapses_in_the_proterozoic():
    """The classical failure of a constant lag fitted to today's rate: the Moon at the Earth
    ~1.1–1.2 Gyr ago (with and without the solar tide), far short of its age."""
    for solar in (1, 0):
        c = kernel_constants(tidal_model("constant-lag"), SYSTEM)
        out = np.empty((1, 3))
        _, status, t_stop = eq.advance(1.0, 1.0, SYSTEM.obliquity, np.array([-6e9]), c, solar, 1e-11, out)
        assert status == 1
        assert -1.2e9 < t_stop < -1.1e9
