"""Keplerian elements and vectors against REBOUND's own conversions, and the shipped planets."""

from __future__ import annotations

import numpy as np
import pytest

from andoyer.planetary.orbits.elements import (
    eccentricity_from_elements,
    elements_to_state,
    normal_from_elements,
    state_to_vectors,
)
from andoyer.planetary.orbits.planets import PLANETS, check_planet, planet_data


@pytest.fixture
def random_elements(rng):
    n = 20
    return {
        "a": rng.uniform(0.3, 30.0, n),
        "e": rng.uniform(0.0, 0.9, n),
        # Prograde: REBOUND defines ϖ = Ω − ω for retrograde orbits, this module ϖ = Ω + ω always.
        "inc": rng.uniform(0.001, 1.5, n),
        "Omega": rng.uniform(-np.pi, np.pi, n),
        "pomega": rng.uniform(-np.pi, np.pi, n),
        "l": rng.uniform(-np.pi, np.pi, n),
    }


def test_elements_to_state_matches_rebound(random_elements):
    import rebound

    el = random_elements
    mu = 2.5
    r, v = elements_to_state(mu, el["a"], el["e"], el["inc"], el["Omega"], el["pomega"], el["l"])
    for k in range(len(el["a"])):
        sim = rebound.Simulation()
        sim.G = 1.0
        sim.add(m=mu)
        kwargs = {key: float(value[k]) for key, value in el.items()}
        sim.add(primary=sim.particles[0], m=0.0, **kwargs)
        p = sim.particles[1]
        np.testing.assert_allclose(r[k], p.xyz, rtol=1e-11, atol=1e-11 * el["a"][k])
        np.testing.assert_allclose(v[k], p.vxyz, rtol=1e-11, atol=1e-11)


def test_state_to_vectors_matches_rebound_elements(random_elements, rng):
    import rebound

    el = random_elements
    mu = 0.7
    for k in range(len(el["a"])):
        sim = rebound.Simulation()
        sim.add(m=mu)
        sim.add(primary=sim.particles[0], m=0.0, **{key: float(value[k]) for key, value in el.items()})
        p = sim.particles[1]
        orbit = p.orbit(primary=sim.particles[0])
        n, e = state_to_vectors(mu, p.xyz, p.vxyz)
        i, node = orbit.inc, orbit.Omega
        expected = [np.sin(i) * np.sin(node), -np.sin(i) * np.cos(node), np.cos(i)]
        np.testing.assert_allclose(n, expected, atol=1e-12)
        np.testing.assert_allclose(
            e, eccentricity_from_elements(orbit.e, orbit.inc, orbit.Omega, orbit.pomega), atol=1e-12
        )
        np.testing.assert_allclose(normal_from_elements(i, node), n, atol=1e-12)


@pytest.mark.parametrize("e", [-0.1, 1.0, 2.0])
def test_elements_to_state_rejects_unbound(e):
    with pytest.raises(ValueError, match="expected eccentricities in"):
        elements_to_state(1.0, 1.0, e, 0.0, 0.0, 0.0, 0.0)


def test_planet_data_periods_and_masses():
    data = planet_data()
    # Kepler's third law with the Sun's GM: the Earth–Moon barycentre's period is 1.0000 yr.
    period = 2 * np.pi * np.sqrt(data.a**3 / (data.sun_gm + data.gm))
    assert period[2] == pytest.approx(1.0000, abs=1e-4)
    # Sun/Jupiter-system mass ratio 1047.3486 (IAU 2009 system of constants, Luzum et al. 2011).
    assert data.sun_gm / data.gm[4] == pytest.approx(1047.3486, rel=1e-6)
    # Heliocentric distances of the shipped states lie between perihelion and aphelion.
    r = np.linalg.norm(data.position, axis=-1)
    assert np.all((r >= data.a * (1 - data.e) * (1 - 1e-12)) & (r <= data.a * (1 + data.e) * (1 + 1e-12)))


@pytest.mark.parametrize("name", ["Earth", "MARS", "neptune"])
def test_check_planet_accepts_names(name):
    assert PLANETS[check_planet(name)] == name.lower()


@pytest.mark.parametrize("name", ["pluto", "moon", ""])
def test_check_planet_rejects_others(name):
    with pytest.raises(ValueError, match="expected a planet among"):
        check_planet(name)
