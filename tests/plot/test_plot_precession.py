"""Precession, obliquity and nutation series: definitions, slopes of known precessing states."""

import numpy as np
import pytest

from andoyer import FreeRotation, RigidBody, State, bodies
from andoyer.integrate.secular import propagate_momentum
from andoyer.perturbations.averaged_gravity import SecularGravityGradient
from andoyer.perturbations.solar_system import JULIAN_YEAR, OBLIQUITY, mean_perturbers
from andoyer.planetary.precession import fit_trend
from andoyer.plot import precession, precession_data


@pytest.mark.parametrize(
    ("A", "C", "G", "J"), [(1.0, 1.5, 2.0, 0.45), (2.0, 2.2, 0.7, 1.2), (1.0, 0.6, 1.0, 0.3)]
)
def test_regular_precession_rate_is_G_over_A(A, C, G, J):
    # Euler: an axisymmetric body (A = B) with m along s3 precesses regularly, φ̇ = G/A, θ = J.
    body = RigidBody(A, A, C)
    state = State.from_andoyer(0.2, 0.3, 0.0, G * np.cos(J), G, G)
    t = np.linspace(0.0, 7.0, 301)
    data = precession_data(t, FreeRotation(body).propagate(state, t))
    assert data.precession_rate == pytest.approx(G / A, rel=1e-12)
    np.testing.assert_allclose(data.obliquity, J, rtol=1e-12)
    assert np.max(np.abs(data.nutation_longitude)) < 1e-11
    assert np.max(np.abs(data.nutation_obliquity)) < 1e-12
    assert data.obliquity_rate == pytest.approx(0.0, abs=1e-12)


def test_series_are_the_euler_and_andoyer_angles():
    # Ω, ε of the figure axis are Euler's φ, θ; of the momentum axis Andoyer's h, I (charts module).
    body = RigidBody(1.0, 2.0, 3.0)
    state = State.from_andoyer(0.5, 0.2, 0.7, 0.95, 1.0, 0.8)
    t = np.linspace(0.0, 30.0, 601)
    path = FreeRotation(body).propagate(state, t)
    fig_axis = precession_data(t, path, "figure")
    euler = path.as_euler()
    np.testing.assert_allclose(np.cos(fig_axis.precession - euler.phi), 1.0, atol=1e-13)
    np.testing.assert_allclose(fig_axis.obliquity, euler.theta, atol=1e-12)
    momentum = precession_data(t, path, "momentum")
    andoyer = path.as_andoyer()
    np.testing.assert_allclose(np.cos(momentum.precession - andoyer.h), 1.0, atol=1e-13)
    np.testing.assert_allclose(momentum.obliquity, np.arccos(andoyer.H / andoyer.G), atol=1e-7)
    # Torque-free: the momentum axis does not move.
    assert momentum.precession_rate == pytest.approx(0.0, abs=1e-12)
    assert np.ptp(momentum.obliquity) < 1e-12
    # The trend plus the nutation give back the series.
    np.testing.assert_allclose(
        fig_axis.precession_at_zero + fig_axis.precession_rate * t + fig_axis.nutation_longitude,
        fig_axis.precession,
        atol=1e-12,
    )


def test_triaxial_mean_precession_rate_about_the_momentum():
    # m along s3 (H = G): φ of the figure axis advances on average at the attitude's precession
    # rate about m (FreeRotation.periods, from the elliptic-function solution); the least-squares
    # slope of a bounded periodic wiggle of amplitude a over a span D is off by at most 3a/D.
    body = RigidBody(1.0, 2.0, 3.0)
    state = State.from_andoyer(0.5, 0.0, 0.0, 0.95, 1.0, 1.0)
    free = FreeRotation(body)
    periods = free.periods(state)
    t = np.linspace(0.0, 40 * float(periods.period), 8001)
    data = precession_data(t, free.propagate(state, t))
    amplitude = np.max(np.abs(data.nutation_longitude))
    assert data.precession_rate == pytest.approx(float(periods.precession_rate), abs=3 * amplitude / t[-1])
    assert 3 * amplitude / t[-1] < 3e-3 * float(periods.precession_rate)
    # With I = 0 the figure axis' node is h + g exactly: over whole periods Ω advances by the
    # attitude's precession per period.
    advance = data.precession[::200] - data.precession[0]
    np.testing.assert_allclose(advance, np.arange(41) * float(periods.precession), rtol=0, atol=1e-9)


def test_lunisolar_precession_of_the_sun_alone_has_the_classical_rate():
    # Secular gravity gradient of the Sun in the reference plane: the momentum node regresses at
    # dh/dt = −3/2 n²/ω H_d cos ε (1 − e²)^(−3/2) (the classical precession constant).
    body = bodies.get("earth")
    sun = mean_perturbers("earth")[0]
    omega = 2 * np.pi / bodies.info("earth").rotation_period
    G, eps = body.C * omega, OBLIQUITY["earth"]
    t = np.linspace(0.0, 2000 * JULIAN_YEAR, 401)
    M = propagate_momentum(
        SecularGravityGradient(body, [sun]), G * np.array([0.0, -np.sin(eps), np.cos(eps)]), G, t
    )
    h = np.arctan2(M[:, 0], -M[:, 1])
    states = State.from_andoyer(0.0, 0.0, h, 0.9 * G, G, M[:, 2])
    data = precession_data(t, states, "momentum")
    # The torque's strength is GM/a³ (n² only for a massless planet); abs=0 because the rate
    # (~8e-12 rad/s) is below pytest's default absolute tolerance.
    n2, e = sun.gm / sun.orbit.semi_major_axis**3, sun.orbit.eccentricity
    H_d = (body.C - 0.5 * (body.A + body.B)) / body.C
    expected = -1.5 * n2 / omega * H_d * np.cos(eps) / (1 - e * e) ** 1.5
    assert data.precession_rate == pytest.approx(expected, rel=1e-8, abs=0)
    assert np.max(np.abs(data.obliquity - eps)) < 1e-12


def test_precession_figure_content():
    body = RigidBody(1.0, 1.0, 1.5)
    state = State.from_andoyer(0.0, 0.0, 0.0, 1.8, 2.0, 2.0)
    t = np.linspace(0.0, 5.0, 101)
    fig = precession(t, FreeRotation(body).propagate(state, t), degrees=True)
    top, mid, low = fig.axes
    data = fig.andoyer_data
    np.testing.assert_allclose(top.get_lines()[0].get_ydata(), np.degrees(data.precession), rtol=1e-15)
    np.testing.assert_allclose(mid.get_lines()[0].get_ydata(), np.degrees(data.obliquity), rtol=1e-15)
    assert "deg" in top.get_ylabel()
    assert "\\varphi" in top.get_lines()[0].get_label()
    assert "$\\dot\\Omega = 114.592$ deg per unit time" in top.get_lines()[1].get_label()  # 2 rad/unit
    assert low.get_xlabel() == "time $t$ (units of the input)"
    fig2 = precession(t, FreeRotation(body).propagate(state, t), axis="momentum")
    assert "h" in fig2.axes[0].get_lines()[0].get_label()


@pytest.mark.parametrize(
    ("times", "n_states", "axis", "match"),
    [
        ([0.0], 1, "figure", "two distinct times"),
        ([1.0, 1.0], 2, "figure", "two distinct times"),
        ([0.0, 1.0, 2.0], 2, "figure", "one per time"),
        ([0.0, 1.0], 2, "spin", "axis"),
    ],
)
def test_precession_rejects_bad_input(times, n_states, axis, match):
    states = State.from_quaternion(np.tile([0, 0, 0, 1.0], (n_states, 1)), [0.0, 0.0, 1.0])
    with pytest.raises(ValueError, match=match):
        precession_data(times, states, axis)


def test_precession_rejects_bad_axes():
    state = State.from_quaternion(np.tile([0, 0, 0, 1.0], (2, 1)), [0.1, 0.0, 1.0])
    with pytest.raises(ValueError, match="three matplotlib Axes"):
        precession([0.0, 1.0], state, axes=(None, None))


@pytest.mark.parametrize(
    ("rate", "amplitude", "periods"), [(-2e-4, 8e-5, 1.3), (0.5, 0.1, 2.7), (-1.0, 0.0, 1.0)]
)
def test_precession_trend_fitted_with_the_nutation_frequencies(rate, amplitude, periods):
    # A node h(t) = h₀ + ḣ t + a sin(ν t + φ) + b cos(2ν t) known in closed form: the fit with the
    # frequencies ν, 2ν returns ḣ exactly; a straight line over a span that is not a whole number
    # of periods is off by a fraction of a/span (the demo's 52.2″/yr instead of 50.48″/yr, Lara's moments).
    nu = 2 * np.pi / 18.6
    t = np.linspace(0.0, periods * 18.6, 400)
    h = 0.3 + rate * t + amplitude * np.sin(nu * t + 0.4) + 0.3 * amplitude * np.cos(2 * nu * t)
    states = State.from_andoyer(0.1, 0.2, h, 0.9, 1.0, 0.8)
    fitted = precession_data(t, states, "momentum", frequencies=[nu, -2 * nu])
    assert fitted.precession_rate == pytest.approx(rate, rel=1e-12, abs=1e-14)
    assert fitted.precession_at_zero == pytest.approx(0.3, abs=1e-12)
    np.testing.assert_allclose(fitted.frequencies, [nu, 2 * nu])
    line = precession_data(t, states, "momentum")
    if amplitude and periods % 1:
        assert abs(line.precession_rate - rate) > 1e-3 * amplitude / t[-1]
    fig = precession(t, states, "momentum", frequencies=[nu, 2 * nu], regression=True, degrees=True)
    label = fig.axes[0].get_lines()[1].get_label()
    assert "fitted with 2 nutation terms" in label
    assert f"$p = -\\dot\\Omega$ = {-rate * 180 / np.pi * 3600:.4g}″" in label


@pytest.mark.parametrize(
    ("t", "y", "frequencies", "match"),
    [
        (np.zeros((2, 3)), np.zeros((2, 3)), (), r"expected times \(T,\) and values \(T,\)"),
        (np.arange(5.0), np.zeros(4), (), r"expected times \(T,\) and values \(T,\)"),
        (np.arange(5.0), np.array([0, 1, np.nan, 3, 4]), (), "expected finite values"),
        (np.arange(5.0), np.zeros(5), [np.inf], "expected finite frequencies"),
        (np.zeros(5), np.zeros(5), (), "expected times spanning a nonzero interval"),
        (np.arange(5.0), np.zeros(5), [2.0, 3.0], "expected at least 6 times"),
    ],
)
def test_fit_trend_rejects_bad_input(t, y, frequencies, match):
    with pytest.raises(ValueError, match=match):
        fit_trend(t, y, frequencies)
