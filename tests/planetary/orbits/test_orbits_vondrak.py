"""The Vondrák–Capitaine–Wallace (2011) ecliptic against ERFA's own rotations."""

from __future__ import annotations

import numpy as np
import pytest

from andoyer.planetary.orbits import OrbitHistory, VondrakEcliptic

ARCSEC = np.pi / (180.0 * 3600.0)
J2000_JD = 2451545.0


def angle_between(a, b):
    """Angle between unit vectors (radians), accurate for small angles."""
    return 2.0 * np.arcsin(np.clip(np.linalg.norm(a - b, axis=-1) / 2.0, 0.0, 1.0))


@pytest.fixture
def times(rng):
    return np.concatenate([[-2e5, -1e5, 0.0, 1.0, 1e5, 2e5], rng.uniform(-2e5, 2e5, 40)])


def test_vondrak_normal_matches_ltpecl_rotated_by_erfa_rx(times):
    import erfa

    # Independent path: ERFA's IAU 2006 obliquity at J2000 and ERFA's own x-rotation.
    rotation = erfa.rx(erfa.obl06(J2000_JD, 0.0), np.eye(3))
    expected = erfa.ltpecl(2000.0 + times) @ rotation.T
    got = VondrakEcliptic().normal(times)
    # obl06 at J2000 is 84381.406″ to 1e-3″ (its series at t = 0): the two agree far below 1″.
    assert angle_between(got, expected).max() < 0.01 * ARCSEC


def test_vondrak_normal_matches_ltpecl_through_ecm06(times):
    import erfa

    # ecm06 at J2000 maps the GCRS to the J2000 ecliptic (it includes the ~0.02″ frame bias).
    rotation = erfa.ecm06(J2000_JD, 0.0)
    expected = erfa.ltpecl(2000.0 + times) @ rotation.T
    got = VondrakEcliptic().normal(times)
    assert angle_between(got, expected).max() < 1.0 * ARCSEC


def test_vondrak_normal_at_j2000_is_the_pole():
    n = VondrakEcliptic().normal(0.0)
    assert n.shape == (3,)
    np.testing.assert_allclose(n, [0.0, 0.0, 1.0], atol=1e-9)


@pytest.mark.parametrize("shape", [(), (5,), (2, 3)])
def test_vondrak_normal_shape_and_unit_length(shape, rng):
    t = rng.uniform(-2e5, 2e5, shape)
    n = VondrakEcliptic().normal(t)
    assert n.shape == (*shape, 3)
    np.testing.assert_allclose(np.linalg.norm(n, axis=-1), 1.0, atol=1e-14)


def test_vondrak_inclination_rate_at_j2000():
    # The J2000 ecliptic turns at 46.8″/cy about its node (IAU 2006 P03: π_A rate 46.998″/cy,
    # Capitaine et al. 2003 eq. 39: π_A = 46.998973 t), in the VCW 2011 model to 0.1″/cy.
    n = VondrakEcliptic().normal([-0.5, 0.5])
    rate = angle_between(n[0], n[1]) / ARCSEC * 100.0
    assert rate == pytest.approx(46.998973, abs=0.1)


@pytest.mark.parametrize("t", [-200000.001, 200000.001, -1e6, 3e5])
def test_vondrak_span_error_outside(t):
    with pytest.raises(ValueError, match="expected times within the vondrak orbit's span"):
        VondrakEcliptic().normal(t)


def test_vondrak_rejects_nan():
    with pytest.raises(ValueError, match="expected finite times"):
        VondrakEcliptic().normal([0.0, np.nan])


def test_vondrak_has_no_eccentricity():
    orbit = VondrakEcliptic()
    assert isinstance(orbit, OrbitHistory)
    assert orbit.has_eccentricity is False
    with pytest.raises(NotImplementedError, match="eccentricity"):
        orbit.eccentricity_vector(0.0)
