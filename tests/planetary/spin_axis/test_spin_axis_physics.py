"""The spin-axis equation against the project's secular model, Gurfil's precessing-frame form, IAU 2006."""

from __future__ import annotations

import erfa
import numpy as np
import pytest
from scipy.integrate import solve_ivp
from spin_cases import FixedOrbit, PrecessingOrbit, angle

from andoyer import bodies
from andoyer.perturbations.averaged_gravity import SecularGravityGradient
from andoyer.perturbations.solar_system import JULIAN_YEAR, mean_perturbers
from andoyer.planetary.orbits import VondrakEcliptic
from andoyer.planetary.spin_axis import (
    EPSILON_0,
    SpinAxisModel,
    mean_pole_j2000,
    output_times,
    spin_axis_history,
)
from andoyer.planetary.spin_axis.model import ARCSEC

J2000 = 2451545.0
#: IAU 2006 precession (Capitaine, Wallace & Chapront 2003, A&A 412, 567, eqs. 37 and 39):
#: p_A = 5028.796195 t + ..., ε_A = 84381.406 − 46.836769 t + ... (″, t in Julian centuries).
P_A_RATE = 5028.796195
EPS_A_RATE = -46.836769


def _ecliptic(v):
    """J2000 mean equator → J2000 ecliptic (rotation by ε₀ about x)."""
    c, s = np.cos(EPSILON_0), np.sin(EPSILON_0)
    v = np.asarray(v)
    return np.stack([v[..., 0], c * v[..., 1] + s * v[..., 2], -s * v[..., 1] + c * v[..., 2]], -1)


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_axis_rate_matches_secular_gravity_gradient_earth(seed):
    """ṡ = α (s·n)(s×n) equals SecularGravityGradient's dM/dt / G averaged over the Moon's node."""
    earth = bodies.get("earth")
    I1, I2, I3 = earth.moments
    H = (I3 - 0.5 * (I1 + I2)) / I3
    model = SpinAxisModel.from_dynamical_ellipticity("earth", H)
    secular = SecularGravityGradient(earth, mean_perturbers("earth"))
    rng = np.random.default_rng(seed)
    s = rng.normal(size=3)
    s /= np.linalg.norm(s)
    G = I3 * 2 * np.pi / bodies.info("earth").rotation_period
    node_period = 6798.38 * 86400.0  # the Moon's nodal period in solar_system.py
    t = node_period * np.arange(64) / 64  # exact average of a trigonometric polynomial of degree 2
    rate = secular.momentum_rate(t, np.broadcast_to(G * s, (64, 3)), np.full(64, G)).mean(axis=0)
    expected = rate / G * JULIAN_YEAR
    n = np.array([0.0, 0.0, 1.0])
    got = model.rate(0.0) * (s @ n) * np.cross(s, n)
    assert np.abs(got - expected).max() <= 1e-12 * np.abs(expected).max()


def test_axis_rate_matches_secular_gravity_gradient_mars_sun_only():
    mars = bodies.get("mars")
    I1, I2, I3 = mars.moments
    model = SpinAxisModel.from_dynamical_ellipticity("mars", (I3 - 0.5 * (I1 + I2)) / I3)
    secular = SecularGravityGradient(mars, mean_perturbers("mars"))
    s = np.array([0.3, -0.4, 0.8])
    s /= np.linalg.norm(s)
    G = I3 * 2 * np.pi / bodies.info("mars").rotation_period
    expected = secular.momentum_rate(0.0, G * s, G) / G * JULIAN_YEAR
    got = model.rate(0.0) * s[2] * np.cross(s, [0.0, 0.0, 1.0])
    assert model.beta == 0.0
    assert np.abs(got - expected).max() <= 1e-12 * np.abs(expected).max()


@pytest.mark.parametrize("inclination", [0.02, 0.3])
def test_history_matches_gurfil_precessing_frame_andoyer_form(inclination):
    """Gurfil et al. §4.4.2–4.4.6: Andoyer variables (h, H) in the frame of the orbit, ΔH = −μ·G.

    The frame (s1 = node, s3 = n) turns at μ = Ω̇ z (inertial z), so with the averaged torque
    K(h, H) = −α H²/(2G) − μ·G, G = G(sin I sin h, −sin I cos h, cos I) in frame components,
    and ḣ = ∂K/∂H, Ḣ = −∂K/∂h (eq. 127 with the convective terms of eq. 126).
    """
    orbit = PrecessingOrbit(inclination=inclination, node_rate=-2 * np.pi / 3000.0, e=0.0)
    model = SpinAxisModel("mars", 2 * np.pi / 57000.0, 0.0, 0.0)  # α: one turn in 57 kyr at s·n = 1
    alpha = float(model.rate(0.0))
    mu = orbit.g * np.array([0.0, np.sin(inclination), np.cos(inclination)])  # z in the frame (u, n×u, n)
    G = 1.0

    def frame(t):
        u = orbit.node_vector(t)
        n = orbit.normal(t)
        return np.stack([u, np.cross(n, u), n], axis=-2)  # rows: frame axes in inertial components

    assert np.allclose(frame(0.0) @ [0.0, 0.0, 1.0], mu / orbit.g)

    def rhs(_, y):
        h, H = y
        sin_i = np.sqrt(G * G - H * H) / G
        # K = -alpha H²/(2G) - [mu1 G sinI sin h - mu2 G sinI cos h + mu3 H]
        dK_dH = -alpha * H / G - (mu[0] * np.sin(h) - mu[1] * np.cos(h)) * (-H / (G * sin_i)) - mu[2]
        dK_dh = -G * sin_i * (mu[0] * np.cos(h) + mu[1] * np.sin(h))
        return [dK_dH, -dK_dh]

    s0 = np.array([0.2, 0.5, 0.8])
    s0 /= np.linalg.norm(s0)
    local = frame(0.0) @ s0
    y0 = [np.arctan2(local[0], -local[1]), local[2]]
    times = np.linspace(0.0, 20000.0, 11)
    sol = solve_ivp(rhs, (0.0, times[-1]), y0, method="DOP853", t_eval=times, rtol=1e-13, atol=1e-14)
    h, H = sol.y
    sin_i = np.sqrt(1 - H * H)
    local = np.stack([sin_i * np.sin(h), -sin_i * np.cos(h), H], -1)
    expected = np.einsum("tji,tj->ti", frame(times), local)
    from andoyer.planetary.spin_axis.history import integrate_axis

    _, axes, index = integrate_axis(orbit, model, times, s0[None, :], step=100.0)
    got = axes[0, index]
    assert angle(got, expected).max() <= 1e-10


@pytest.mark.parametrize("e", [0.0, 0.0934])
def test_fixed_orbit_precesses_westward_at_the_given_rate(e):
    """On a fixed orbit the axis turns uniformly about n: p_A(t) = ψ̇ t exactly, ε constant."""
    times = np.array([-3000.0, 0.0, 1000.0, 2500.0])
    h = spin_axis_history(FixedOrbit(e), "mars", times, precession_rate=7.597)
    assert np.abs(h.precession - 7.597 * ARCSEC * times).max() <= 1e-12
    assert np.abs(h.obliquity - h.obliquity[1]).max() <= 1e-13
    # westward: the pole's ecliptic longitude decreases (the equinox regresses)
    longitude = np.unwrap(np.arctan2(h.axis[:, 1], h.axis[:, 0]))
    assert np.all(np.diff(longitude) < 0)


def test_axis_at_j2000_is_the_iau2006_mean_pole():
    """The mean pole of J2000 from ERFA (bias-precession matrix, ecliptic of date) within 0.1″."""
    rbp = erfa.bp06(J2000, 0.0)[2]
    pole_gcrs = rbp[2]  # the mean pole of date (J2000) in the GCRS
    pole = erfa.ecm06(J2000, 0.0) @ pole_gcrs  # in the mean ecliptic and equinox of J2000
    h = spin_axis_history(VondrakEcliptic(), "earth", [0.0], precession_rate=50.3848)
    assert angle(h.axis[0], pole) / ARCSEC <= 0.1
    assert angle(mean_pole_j2000(), pole) / ARCSEC <= 1e-6


def test_iau2006_rates_at_j2000_vondrak():
    """Acceptance: dp_A/dt = 5028.80 ± 0.01″/cy and dε/dt = −46.84 ± 0.04″/cy at J2000."""
    t = np.arange(-200.0, 201.0, 10.0)
    h = spin_axis_history(VondrakEcliptic(), "earth", t, precession_rate=50.3848)
    centuries = t / 100.0
    p_rate = np.polyfit(centuries, h.precession / ARCSEC, 4)[-2]
    eps_rate = np.polyfit(centuries, h.obliquity / ARCSEC, 4)[-2]
    assert abs(p_rate - P_A_RATE) <= 0.01
    assert abs(eps_rate - EPS_A_RATE) <= 0.04
    # the same against ERFA's series directly over ±200 years
    pa = np.array([erfa.p06e(J2000, x * 365.25)[12] for x in t]) / ARCSEC
    eps = np.array([erfa.obl06(J2000, x * 365.25) for x in t]) / ARCSEC
    assert np.abs(h.precession / ARCSEC - pa).max() <= 0.05
    assert np.abs(h.obliquity / ARCSEC - eps).max() <= 0.1


@pytest.mark.parametrize(("span", "obliquity_tol", "pole_tol"), [(1e4, 0.02, 0.03), (2e5, 0.4, 4.0)])
def test_obliquity_follows_vcw2011_equator(span, obliquity_tol, pole_tol):
    """Against the long-term equator of Vondrák et al. 2011 (erfa.ltpequ), degrees.

    Measured: obliquity 0.012° and pole 0.023° over ±10 kyr; 0.37° and 3.6° (mostly the phase of
    the precession) over ±200 kyr, where VCW's fits themselves reach a few tenths of a degree.
    """
    t = output_times(-span, span, span / 20)
    h = spin_axis_history(VondrakEcliptic(), "earth", t, precession_rate=50.3848)
    pole = _ecliptic(erfa.ltpequ(2000.0 + t))
    eps = angle(pole, h.orbit_normal)
    assert np.degrees(np.abs(h.obliquity - eps)).max() <= obliquity_tol
    assert np.degrees(angle(h.axis, pole)).max() <= pole_tol


def test_climatic_precession_at_j2000_convention():
    """ϖ heliocentric from the moving equinox: with the Earth's J2000 perihelion at longitude 102.94°
    (JPL mean elements, J2000 ecliptic), e sin ϖ = 0.016709 sin 102.94° ≈ +0.01629."""
    varpi = np.radians(102.94)
    e = 0.0167086

    class Earthlike(FixedOrbit):
        def eccentricity_vector(self, t):
            t = np.asarray(t, dtype=float)
            return e * np.stack([np.cos(varpi) + 0 * t, np.sin(varpi) + 0 * t, 0 * t], -1)

    h = spin_axis_history(Earthlike(), "earth", [0.0], precession_rate=50.3848)
    assert abs(h.climatic_precession[0] - e * np.sin(varpi)) <= 1e-15
    assert abs(h.perihelion[0] - varpi) <= 1e-14


def test_model_rejects_bad_parameters_with_expected_messages():
    with pytest.raises(ValueError, match="expected a body in earth, mars, got 'venus'"):
        SpinAxisModel.from_precession_rate("venus", 1.0, 0.4)
    with pytest.raises(ValueError, match="expected a precession rate P > 0 arcsec/yr"):
        SpinAxisModel.from_precession_rate("earth", -1.0, 0.4)
    with pytest.raises(ValueError, match="expected tidal dissipation 0 for a planet without a moon"):
        SpinAxisModel.from_dynamical_ellipticity("mars", 0.005, tidal_dissipation=1.0)
    with pytest.raises(ValueError, match="expected a precession rate or a dynamical ellipticity, got both"):
        spin_axis_history(FixedOrbit(), "earth", [0.0], precession_rate=50.0, dynamical_ellipticity=0.003)
    with pytest.raises(ValueError, match="expected times within the vondrak orbit's span"):
        spin_axis_history(VondrakEcliptic(), "earth", [0.0, 3e5])

    class Past(FixedOrbit):
        span = (-1e7, -1e6)

    with pytest.raises(ValueError, match="expected an orbit span containing J2000"):
        spin_axis_history(Past(), "earth", [-2e6])


def test_tidal_dissipation_follows_zeebe_lourens_convention():
    """T_d = 1: α/α₀ − 1 = W t + β/(1+β)·2N t to first order (N = −4.6e−18 s⁻¹, W = 51 (n_M/ω) N)."""
    base = SpinAxisModel.from_precession_rate("earth", 50.3848, EPSILON_0)
    tidal = SpinAxisModel.from_precession_rate("earth", 50.3848, EPSILON_0, tidal_dissipation=1.0)
    t = -1e6
    N = -4.6e-18 * JULIAN_YEAR
    W = 51 * (27.321661 / (86164.0905 / 86400)) ** -1 * N
    ratio = float(tidal.rate(t) / base.rate(t))
    beta = base.beta
    s = (1 - 0.01671123**2) ** -1.5  # the Earth's e: Standish's J2000 mean elements (the catalogue's)
    expected = (1 + W * t) * (s + beta * (1 + 2 * N * t)) / (s + beta)
    assert abs(ratio - expected) <= 1e-14
    assert tidal.rate(0.0) == base.rate(0.0)


def test_ellipticity_drift_scales_the_whole_torque():
    base = SpinAxisModel.from_dynamical_ellipticity("earth", 0.00327)
    drift = SpinAxisModel.from_dynamical_ellipticity("earth", 0.00327, ellipticity_drift=2e-8)
    t = np.array([-1e6, 0.0, 5e5])
    assert np.allclose(drift.rate(t, 0.02) / base.rate(t, 0.02), 1 + 2e-8 * t, rtol=1e-14, atol=0)
    assert drift.dynamical_ellipticity() == pytest.approx(0.00327, rel=1e-14)
