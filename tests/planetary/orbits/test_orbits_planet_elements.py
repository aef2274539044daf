"""The planets' elements of a source (planet_orbits, PlanetOrbits): against each planet's own orbit."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from andoyer.planetary.orbits import LaplaceLagrangeOrbit, SecularOrbit, planet_orbits
from andoyer.planetary.orbits.elements import elements_from_vectors

T = np.array([-3.0e5, -1.0e5, 0.0, 2.0e4])


def test_planet_elements_secular_system_is_each_orbit():
    # One integration for several planets gives each planet's orbit exactly as alone.
    t = np.array([-4.0e4, -1.0e4, 0.0, 2.0e4])
    system = SecularOrbit.system(["saturn", "mercury", "earth"])
    for planet, orbit in system.items():
        alone = SecularOrbit(planet)
        np.testing.assert_array_equal(orbit.normal(t), alone.normal(t))
        np.testing.assert_array_equal(orbit.eccentricity_vector(t), alone.eccentricity_vector(t))


def test_planet_elements_secular_record():
    record = planet_orbits("secular", ["venus", "jupiter"]).elements(T)
    for planet in ("venus", "jupiter"):
        orbit = SecularOrbit(planet)
        n, e = orbit.normal(T), orbit.eccentricity_vector(T)
        np.testing.assert_allclose(record.values[planet]["e"], np.linalg.norm(e, axis=-1), rtol=1e-14)
        np.testing.assert_allclose(
            record.values[planet]["inclination"], np.arccos(n[:, 2]), rtol=1e-9, atol=1e-12
        )


@pytest.mark.parametrize("planet", ["mercury", "mars", "neptune"])
def test_planet_elements_from_vectors_against_euler_angles(planet):
    # i, Ω, ϖ = Ω + ω as scipy's z-x-z Euler angles of the orbit frame (perihelion, 90° ahead, normal).
    orbit = LaplaceLagrangeOrbit(planet)
    n, e = orbit.normal(T), orbit.eccentricity_vector(T)
    ecc, inc, node, varpi = elements_from_vectors(n, e)
    for k in range(T.size):
        u = e[k] / np.linalg.norm(e[k])
        frame = np.stack([u, np.cross(n[k], u), n[k]], axis=-1)
        Omega, i, omega = Rotation.from_matrix(frame).as_euler("ZXZ")
        assert inc[k] == pytest.approx(i, abs=1e-12)
        assert node[k] == pytest.approx(Omega % (2 * np.pi), abs=1e-10)
        assert varpi[k] == pytest.approx((Omega + omega) % (2 * np.pi), abs=1e-10)
        assert ecc[k] == pytest.approx(np.linalg.norm(e[k]), rel=1e-15)
