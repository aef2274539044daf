"""The secular tidal equations against closed forms, conservation laws and a second integrator."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import solve_ivp

from andoyer.planetary.tides import (
    ConstantPhaseLag,
    ConstantTimeLag,
    EarthMoonSystem,
    OceanTides,
    calibrate,
    tidal_history,
)
from andoyer.planetary.tides import equations as eq
from andoyer.planetary.tides.evolution import integrate_states, kernel_constants

SYSTEM = EarthMoonSystem()


def _vector_torque(k, omega, n, eps):
    """Mignard's constant-time-lag torque T = −K[(ω/2)(s + cos ε k) − n k], as (T·s, T·k)."""
    s = np.array([0.0, math.sin(eps), math.cos(eps)])
    kk = np.array([0.0, 0.0, 1.0])
    torque = -k * (omega / 2 * (s + (s @ kk) * kk) - n * kk)
    return torque @ s, torque @ kk


@settings(max_examples=60, deadline=None, derandomize=True)
@given(
    eps=st.floats(0.0, 3.0),
    omega=st.floats(1e-6, 1e-3),
    n=st.floats(1e-8, 1e-5),
    k2dt=st.floats(1.0, 1e3),
)
def test_torques_constant_lag_equals_vector_form(eps, omega, n, k2dt):
    """The Kaula sum with Q = k2Δt σ closes to the vector torque of Mignard / Néron de Surgy & Laskar."""
    strength = 2.5e30
    ts, tk = eq.torques(eq.CONSTANT_LAG, k2dt, 0.0, 0.0, 0.0, strength, n, omega, eps)
    ref_s, ref_k = _vector_torque(2 * strength * k2dt, omega, n, eps)  # K = 3 k2Δt G m² R⁵/a⁶ = 2 P k2Δt
    scale = strength * k2dt * omega
    assert ts == pytest.approx(ref_s, abs=1e-13 * scale)
    assert tk == pytest.approx(ref_k, abs=1e-13 * scale)


def test_torques_zero_obliquity_is_the_semidiurnal_wave_alone():
    """At ε = 0 only the (2, 2) wave is left: T_s = T_k = −P Q(2ω − 2n), for any response."""
    ocean = OceanTides()
    p = ocean.kernel_parameters(SYSTEM)
    omega, n, strength = 7.3e-5, 2.66e-6, 1e30
    ts, tk = eq.torques(eq.OCEAN, *p, strength, n, omega, 0.0)
    q = float(ocean.lag(2, 2 * omega - 2 * n))
    assert ts == pytest.approx(-strength * q, rel=1e-14)
    assert tk == pytest.approx(-strength * q, rel=1e-14)


@pytest.mark.parametrize("response", [ConstantTimeLag(200.0), ConstantPhaseLag(0.02), OceanTides()])
def test_lag_odd_in_frequency(response):
    sigma = np.array([1e-7, 3e-5, 1.4e-4, 5e-4])
    for order in (0, 1, 2):
        assert np.array_equal(response.lag(order, -sigma), -response.lag(order, sigma))


def test_ocean_love_number_matches_time_domain_oscillator():
    """The degree-2 ocean mode driven at σ, integrated in time, settles to the closed-form k₂^oc(σ).

    The mode's equation is written here from the shallow-water equations (not from the class):
    ζ̈ + σ_R ζ̇ + σ₂²[1 − (1+k'−h')κ] ζ = σ₂² (1+k−h) U/g cos σt, and the ocean's potential is
    (1+k') κ g ζ. The steady state's amplitude and phase against cos σt give k₂^oc.
    """
    ocean = OceanTides(depth=4000.0, drag=2e-5)
    radius = SYSTEM.mean_radius
    g = SYSTEM.gm_earth / radius**2
    density = SYSTEM.mass_earth / (4 / 3 * math.pi * radius**3)
    kappa = 0.6 * 1025.0 / density
    sigma2 = 6 * g * 4000.0 / radius**2
    k, h = 0.30, 0.6078
    kl, hl = -0.3025, -0.9902
    stiffness = sigma2 * (1 - (1 + kl - hl) * kappa)
    potential = 1.0  # U, m²/s²
    sigma = 1.3e-4

    def rhs(t, y):
        forcing = sigma2 * (1 + k - h) * potential / g * math.cos(sigma * t)
        return [y[1], -2e-5 * y[1] - stiffness * y[0] + forcing]

    period = 2 * math.pi / sigma
    t_end = 40 / 2e-5  # 40 damping times: the transient is e^-20 of the response
    tail = np.linspace(t_end - 4 * period, t_end, 4001)
    sol = solve_ivp(rhs, (0.0, t_end), [0.0, 0.0], method="DOP853", rtol=1e-11, atol=1e-16, t_eval=tail)
    basis = np.stack([np.cos(sigma * tail), np.sin(sigma * tail)], axis=1)
    (c, s), *_ = np.linalg.lstsq(basis, sol.y[0], rcond=None)
    # ζ = Re[Z e^{iσt}] = c cos − (−s)… : Z = c − i s
    response = (1 + kl) * kappa * g * (c - 1j * s) / potential
    expected = complex(ocean.love_number(sigma))
    assert response.real == pytest.approx(expected.real, rel=1e-6)
    assert response.imag == pytest.approx(expected.imag, rel=1e-6)
    assert expected.imag < 0  # a lag


def test_history_no_dissipation_nothing_moves():
    h = tidal_history(np.array([-3e9, -1e9, 0.0, 1e9]), ConstantTimeLag(0.0))
    assert np.all(h.lunar_distance == SYSTEM.lunar_semi_major_axis / 1e3)
    assert np.all(h.spin_rate == SYSTEM.spin_rate)
    assert np.all(h.obliquity == SYSTEM.obliquity)


def test_history_constant_q_follows_the_thirteen_halves_law():
    """Constant Q, zero obliquity, no Sun, C fixed: a^{13/2} grows linearly; ω from L conserved."""
    system = replace(SYSTEM, fluid_love_number=0.0)
    kq = 0.02
    times = np.array([-1.5e9, -1.0e9, -5e8, 0.0, 5e8])
    h = tidal_history(times, ConstantPhaseLag(kq), system, solar_tide=False, obliquity=0.0, rtol=1e-12)
    s = system
    mu = s.gm_earth + s.gm_moon
    rate = 3 * kq * s.gm_moon**2 * s.equatorial_radius**5 / s.gravitational_constant / (
        s.reduced_mass * math.sqrt(mu)
    )  # da/dt = rate · a^{-11/2}, m/s
    a0 = s.lunar_semi_major_axis
    a = (a0**6.5 + 6.5 * rate * times * 365.25 * 86400) ** (1 / 6.5)
    omega = s.spin_rate + s.reduced_mass * math.sqrt(mu) * (math.sqrt(a0) - np.sqrt(a)) / s.polar_moment
    assert np.allclose(h.lunar_distance * 1e3, a, rtol=1e-10, atol=0)
    assert np.allclose(h.spin_rate, omega, rtol=1e-10, atol=0)
    assert np.all(h.obliquity == 0.0)


@pytest.mark.parametrize("response", [calibrate(), OceanTides()], ids=["constant-lag", "ocean"])
def test_history_earth_moon_angular_momentum_conserved_without_sun(response):
    """Without the solar tide, C(ω)ω cos ε + m_r √(G(M+m)a) holds to the integrator's tolerance."""
    times = np.linspace(-1.0e9, 1.0e9, 21)
    h = tidal_history(times, response, solar_tide=False, rtol=1e-12)
    s = SYSTEM
    moment = s.polar_moment + s.centrifugal_moment * (h.spin_rate**2 - s.spin_rate**2)
    spin = moment * h.spin_rate * np.cos(h.obliquity)
    orbit = s.reduced_mass * np.sqrt((s.gm_earth + s.gm_moon) * h.lunar_distance * 1e3)
    total = spin + orbit
    assert np.ptp(total) / total[10] < 1e-10
    assert np.ptp(spin) / total[10] > 1e-2  # and the spin did change


@pytest.mark.parametrize(
    ("response", "start"), [(calibrate(), -1.1e9), (OceanTides(), -4.3e9)], ids=["constant-lag", "ocean"]
)
def test_integrator_matches_dop853(response, start):
    """The compiled Dormand–Prince 5(4) against scipy's DOP853 at rtol 1e-13 on the same equations."""
    c = kernel_constants(response, SYSTEM)
    times = np.linspace(start, 0.0, 12)
    ours = integrate_states(times, c, (1.0, 1.0, SYSTEM.obliquity), True, 1e-11, response.name)

    def rhs(t, y):
        return eq.rates(y[0], y[1], y[2], c, 1)

    sol = solve_ivp(rhs, (0.0, start), [1.0, 1.0, SYSTEM.obliquity], method="DOP853", rtol=1e-13,
                    atol=1e-13, t_eval=times[::-1])
    reference = sol.y.T[::-1]
    assert np.abs(ours - reference).max() < 2e-9
