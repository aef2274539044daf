"""The averaged gravity-gradient model: its Hamiltonian by brute-force averaging, and precession rates."""

from __future__ import annotations

import numpy as np
import pytest

from andoyer import RigidBody, State, bodies
from andoyer.integrate.secular import propagate_momentum
from andoyer.perturbations import GravityGradient, KeplerOrbit, PointMass
from andoyer.perturbations.averaged_gravity import SecularGravityGradient
from andoyer.perturbations.solar_system import JULIAN_YEAR, OBLIQUITY, mean_perturbers

ARCSEC = np.pi / 648000


def brute_force_average(body, perturber, h, I, J, G, n=48, n_orbit=96):
    """⟨ΔH⟩ over uniform l, g and the perturber's mean anomaly, by the trapezoid rule (spectral)."""
    model = GravityGradient(perturber).bind(body)
    grid = 2 * np.pi * np.arange(n) / n
    l, g = np.meshgrid(grid, grid, indexing="ij")
    state = State.from_andoyer(l, g, h, G * np.cos(J), G, G * np.cos(I))
    period = 2 * np.pi / perturber.orbit.mean_motion
    total = 0.0
    for t in period * np.arange(n_orbit) / n_orbit:
        total += float(np.mean(model.potential(t, state.quaternion, state.m_body)))
    return total / n_orbit


@pytest.mark.parametrize("inclination", [0.0, 0.4])
def test_secular_hamiltonian_equals_brute_force_average(inclination):
    body = RigidBody(0.8, 0.9, 1.2)  # triaxial: the l-average must remove the A-B term
    perturber = PointMass(2.0, KeplerOrbit(3.0, 0.3, inclination, 0.7, 0.2, 0.0, 0.5))
    secular = SecularGravityGradient(body, perturber)
    G, J = 1.3, 0.35

    def secular_value(h, I):
        M = G * np.array([np.sin(I) * np.sin(h), -np.sin(I) * np.cos(h), np.cos(I)])
        return float(secular.potential(0.0, M, G * np.cos(J)))

    pairs = [((0.3, 0.5), (1.9, 1.2)), ((2.5, 0.1), (0.4, 2.0))]
    for (h1, I1), (h2, I2) in pairs:
        brute = brute_force_average(body, perturber, h1, I1, J, G) - brute_force_average(
            body, perturber, h2, I2, J, G
        )
        formula = secular_value(h1, I1) - secular_value(h2, I2)
        assert formula == pytest.approx(brute, rel=1e-9, abs=1e-14)


def test_secular_node_rate_matches_vector_form():
    body = bodies.get("mars")
    model = SecularGravityGradient(body, mean_perturbers("mars"))
    G, L = 1.0, 0.999
    I, h = 0.44, 1.1
    M = G * np.array([np.sin(I) * np.sin(h), -np.sin(I) * np.cos(h), np.cos(I)])
    dM = model.momentum_rate(0.0, M, L)
    # dh/dt from the vector form: h = atan2(M1, -M2), so dh = (-M2 dM1 + M1 dM2)/(M1² + M2²)
    # (the node regresses: dh/dt < 0).
    dh = (-M[1] * dM[0] + M[0] * dM[1]) / (M[0] ** 2 + M[1] ** 2)
    assert dh < 0
    # abs=0: with G = 1 the rate (~1e-16) is far below pytest's default absolute tolerance
    assert model.node_rate(L, G, G * np.cos(I), h=h) == pytest.approx(dh, rel=1e-12, abs=0)


def precession_rate(planet, years=1000.0):
    body = bodies.get(planet)
    rotation_period = bodies.info(planet).rotation_period
    G = body.C * 2 * np.pi / rotation_period
    eps = OBLIQUITY[planet]
    model = SecularGravityGradient(body, mean_perturbers(planet))
    t = np.linspace(0.0, years * JULIAN_YEAR, 2001)
    M0 = G * np.array([np.sin(eps) * np.sin(0.0), -np.sin(eps) * np.cos(0.0), np.cos(eps)])
    M = propagate_momentum(model, M0, G, t)
    h = np.unwrap(np.arctan2(M[:, 0], -M[:, 1]))
    slope = np.polyfit(t / JULIAN_YEAR, h, 1)[0]
    return -slope / ARCSEC


def test_secular_precession_of_the_earth_lunisolar():
    """Observed luni-solar precession 50.38″/yr; a rigid Earth with Lara's moments: 50.0-50.8."""
    rate = precession_rate("earth")
    assert 50.0 <= rate <= 50.8


def test_secular_precession_of_mars():
    """Observed 7.58″/yr; the issue's band: 7.4-7.8."""
    rate = precession_rate("mars")
    assert 7.4 <= rate <= 7.8


def test_secular_precession_rate_closed_form_sun_only():
    """One perturber in the reference plane: dh/dt = -3/2 n²/ω H_d cos ε (1 - e²)^(-3/2).

    The torque's strength is GM/a³ (the perturber's n² only for a massless Earth), so n² is
    taken as GM/a³; ``abs=0`` because the rate (~8e-12 rad/s) is below pytest's default
    absolute tolerance.
    """
    body = bodies.get("earth")
    sun = mean_perturbers("earth")[0]
    rate = -precession_rate_with(body, [sun])
    n = np.sqrt(sun.gm / sun.orbit.semi_major_axis**3)
    omega = 2 * np.pi / bodies.info("earth").rotation_period
    H_d = (body.C - 0.5 * (body.A + body.B)) / body.C
    e = sun.orbit.eccentricity
    expected = 1.5 * n**2 / omega * H_d * np.cos(OBLIQUITY["earth"]) / (1 - e * e) ** 1.5
    assert rate == pytest.approx(expected, rel=1e-12, abs=0)


def precession_rate_with(body, perturbers):
    omega = 2 * np.pi / bodies.info("earth").rotation_period
    G = body.C * omega
    eps = OBLIQUITY["earth"]
    model = SecularGravityGradient(body, perturbers)
    return float(model.node_rate(G, G, G * np.cos(eps)))


def test_secular_bad_input():
    with pytest.raises(ValueError, match=r"expected an andoyer\.RigidBody"):
        SecularGravityGradient("earth", mean_perturbers("earth"))
    with pytest.raises(ValueError, match="expected 'earth' or 'mars'"):
        mean_perturbers("venus")
    model = SecularGravityGradient(bodies.get("earth"), mean_perturbers("earth"))
    with pytest.raises(ValueError, match="expected increasing"):
        propagate_momentum(model, [0, 0, 1.0], 1.0, [2.0, 1.0])


def test_secular_deprecated_alias_warns_and_propagates_the_same():
    """``andoyer.integrate.secular.SecularGravityGradient`` moved to the models; the old name still works."""
    import andoyer.integrate.secular as old_place

    moved = "andoyer.perturbations.averaged_gravity.SecularGravityGradient"
    with pytest.warns(DeprecationWarning, match=moved):
        alias = old_place.SecularGravityGradient
    body = bodies.get("earth")
    G = body.C * 2 * np.pi / 86164.0905
    M0 = G * np.array([0.0, -0.4, np.sqrt(1 - 0.16)])
    old = alias(body, mean_perturbers("earth"))
    assert isinstance(old, SecularGravityGradient)
    t = [0.0, 3e9]
    new = propagate_momentum(SecularGravityGradient(body, mean_perturbers("earth")), M0, G, t)
    assert np.array_equal(old.propagate_momentum(M0, G, t), new)
