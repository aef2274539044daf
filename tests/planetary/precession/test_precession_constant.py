"""The precession constant of every body: the Sun's torque, the satellites' share, published rates."""

from __future__ import annotations

import math

import mpmath as mp
import pytest

from andoyer import catalogue
from andoyer.catalogue.units import ARCSEC
from andoyer.planetary.cassini import get as cassini_body
from andoyer.planetary.precession_constant import (
    obliquity,
    precession_constant,
    satellites_of,
    spin_axis_ecliptic,
)

mp.mp.dps = 30
YEAR = mp.mpf(365.25 * 86400)
TO_ARCSEC = YEAR * 648000 / mp.pi
#: La2004 s7, s8 (″/yr), Laskar et al. (2004), A&A 428, 261, Table 3 (andoyer.planetary.orbits.LA2004_S).
S7, S8 = -2.9925259, -0.691736


def test_precession_constant_earth_first_order_and_iau():
    """Sun and Moon from the catalogue's numbers in 30 digits; the IAU 2006 rate 50.38481507″/yr holds
    the planets' torques and the geodesic precession (−0.0192″/yr) this model leaves out."""
    gm_sun, gm_moon = mp.mpf("1.3271244004127942e11"), mp.mpf("4902.80007")  # km³/s², DE440
    a = mp.mpf("1.00000261") * mp.mpf("149597870.7")  # km, Standish; au IAU 2012
    e, a_m, e_m, i_m = mp.mpf("0.01671123"), mp.mpf(384399), mp.mpf("0.0549"), mp.radians(mp.mpf("5.145"))
    omega = mp.radians(mp.mpf("360.9856235")) / 86400  # IAU W rate
    H = mp.mpf("0.00327379492")  # MHB2000
    sun = gm_sun / a**3
    moon = gm_moon / a_m**3 * (1 - mp.mpf(1.5) * mp.sin(i_m) ** 2) / (1 - e_m**2) ** 1.5
    alpha = mp.mpf(1.5) * H / omega * (sun / (1 - e**2) ** 1.5 + moon) * TO_ARCSEC
    rate = alpha * mp.cos(mp.radians(mp.mpf("84381.406") / 3600))
    earth = precession_constant("earth")
    assert earth.alpha / ARCSEC == pytest.approx(float(alpha), rel=1e-12)
    assert earth.precession_rate == pytest.approx(float(rate), rel=1e-12)
    assert earth.precession_rate == pytest.approx(50.38481507, rel=4e-4)
    assert [(s.name, s.regime) for s in earth.satellites] == [("Moon", "outer")]


def test_precession_constant_earth_laplace_radius_is_eight_earth_radii():
    """r_L⁵ = J2 R² a³ (1−e²)^{3/2} M/M_⊙ (Tremaine, Touma & Namouni 2009): about 8.4 R_E."""
    r5 = (
        mp.mpf("0.0010826359")
        * mp.mpf("6378.1366") ** 2
        * (mp.mpf("1.00000261") * mp.mpf("149597870.7")) ** 3
        * (1 - mp.mpf("0.01671123") ** 2) ** 1.5
        * mp.mpf("398600.4418")
        / mp.mpf("1.3271244004127942e11")
    )
    earth = precession_constant("earth")
    assert earth.laplace_radius == pytest.approx(float(r5 ** mp.mpf(0.2)), rel=1e-12)
    assert 8.3 < earth.laplace_radius / 6378.1366 < 8.5


def test_precession_constant_mars_matches_the_measured_rate():
    """Radio tracking gives 7.59-7.61″/yr (Konopliv et al. 2016; Le Maistre et al. 2023)."""
    mars = precession_constant("mars")
    assert 7.58 <= mars.precession_rate <= 7.61
    assert mars.satellites == ()


def test_precession_constant_venus_matches_margot_2021():
    """Margot et al. (2021) measured 44.58 ± 3.3″/yr (and C/MR² from it); Venus spins retrograde, ε = 177.4°:
    ψ̇ = α cos ε < 0, the axis precesses the other way."""
    venus = precession_constant("venus")
    assert math.degrees(venus.obliquity) == pytest.approx(177.36, abs=0.01)
    assert venus.precession_rate < 0
    assert abs(abs(venus.precession_rate) - 44.58) <= 3.3


def test_precession_constant_saturn_ward_hamilton_from_the_numbers():
    """α = 3n²/(2ω)(1−e²)^{-3/2}(J2 + q)/(λ + l) with Titan's and Enceladus' rings, recomputed from the
    catalogue's numbers (Laplace-plane tilt of Titan 0.6°, Jacobson 2022); Saturn's ψ̇ lies within 10 % of
    |s8| (Ward & Hamilton 2004: Saturn's precession is near Neptune's nodal mode)."""
    M, R = mp.mpf("37940584.8418"), mp.mpf(60330)
    sun = mp.mpf("1.3271244004127942e11")
    a, e = mp.mpf("9.53667594") * mp.mpf("149597870.7"), mp.mpf("0.05386179")
    omega = 2 * mp.pi / mp.mpf(38018)
    j2, lam = mp.mpf("0.016290573"), mp.mpf("0.210")
    eps = mp.mpf(obliquity("saturn"))
    q = l = mp.mpf(0)
    for gm, axis, inc, tilt in (("8978.1383", 1221900, "0.3", "0.6"), ("7.210443", 238400, "0", "0")):
        m, ak = mp.mpf(gm), mp.mpf(axis)
        i, L = mp.radians(mp.mpf(inc)), mp.radians(mp.mpf(tilt))
        size = m / M * (ak / R) ** 2
        q += size / 2 * (3 * mp.cos(i) ** 2 - 1) / 2 * mp.sin(2 * (eps - L)) / mp.sin(2 * eps)
        l += size * mp.sqrt((M + m) / ak**3) / omega * mp.cos(i) * mp.sin(eps - L) / mp.sin(eps)
    alpha = mp.mpf(1.5) * sun / (a**3 * omega) / (1 - e**2) ** 1.5 * (j2 + q) / (lam + l) * TO_ARCSEC
    saturn = precession_constant("saturn")
    assert saturn.alpha / ARCSEC == pytest.approx(float(alpha), rel=1e-12)
    assert [s.name for s in saturn.satellites] == ["Titan", "Enceladus"]
    assert saturn.alpha / saturn.solar > 3.5  # Titan's ring: q ≈ 3 J2
    assert abs(saturn.precession_rate - abs(S8)) <= 0.1 * abs(S8)


def test_precession_constant_jupiter_near_s7():
    """Jupiter's ψ̇ is close to |s7| (Ward & Canup 2006; Saillenfest et al. 2020): within 15 %, below it."""
    jupiter = precession_constant("jupiter")
    assert [s.regime for s in jupiter.satellites] == ["ring"] * 4
    assert 0.9 < jupiter.satellites[-1].laplace_ratio < 1.0  # Callisto: just inside r_L
    assert abs(S7) * 0.85 <= jupiter.precession_rate < abs(S7)


def test_precession_constant_ring_of_vanishing_mass_is_the_sun_alone():
    saturn = precession_constant("saturn", satellites=False)
    assert saturn.satellites == ()
    assert saturn.alpha == saturn.solar
    assert saturn.figure == pytest.approx(0.016290573 / 0.210, rel=1e-15)


def test_precession_constant_uranus_and_neptune_satellites():
    """Uranus' five major satellites and Triton (retrograde: l < 0) are rings inside r_L; ε > 90° for
    Uranus makes ψ̇ negative."""
    uranus = precession_constant("uranus")
    assert [s.name for s in uranus.satellites] == [b.name for b in satellites_of("uranus")]
    assert all(s.regime == "ring" for s in uranus.satellites)
    assert uranus.precession_rate < 0
    neptune = precession_constant("neptune")
    (triton,) = neptune.satellites
    assert triton.angular_momentum < 0 < triton.quadrupole


def test_precession_constant_resonant_body_is_the_cassini_constant():
    """The Moon in 1:1 resonance: α = (3n'²/2ω)[J2(1−e²)^{-3/2} + C22 G₁(e)]/λ, as andoyer.planetary.cassini
    (which takes n from the sidereal month, not from a and GM: 0.2 % apart)."""
    moon = precession_constant("moon")
    assert moon.resonance == 1.0
    assert moon.alpha == pytest.approx(cassini_body("moon").precession_constant, rel=3e-3)


@pytest.mark.parametrize(
    ("body", "degrees", "tolerance"),
    # NASA fact sheets: Jupiter 3.13, Saturn 26.73, Uranus 97.77, Neptune 28.32 (the IAU pole's constant
    # term leaves out Neptune's 0.7° periodic terms), Venus 177.36.
    [
        ("jupiter", 3.13, 0.02),
        ("saturn", 26.73, 0.01),
        ("uranus", 97.77, 0.01),
        ("neptune", 28.32, 0.6),
        ("venus", 177.36, 0.01),
    ],
)
def test_precession_constant_obliquity_from_the_iau_pole(body, degrees, tolerance):
    assert math.degrees(obliquity(body)) == pytest.approx(degrees, abs=tolerance)


def test_precession_constant_spin_axis_is_a_unit_vector_opposite_the_pole_when_retrograde():
    v = spin_axis_ecliptic("venus")
    assert sum(x * x for x in v) == pytest.approx(1.0, abs=1e-15)
    assert v[2] < 0  # Venus' angular momentum points south of the ecliptic


@pytest.mark.parametrize(
    ("body", "message"),
    [
        (
            "pluto",
            "expected Pluto to have dynamical_ellipticity, a_over_c and b_over_c, or j2 and moment_of",
        ),
        ("sun", "expected Sun to have a primary"),
        ("triton", "expected Triton to have eccentricity for the precession constant"),
    ],
)
def test_precession_constant_names_the_missing_value(body, message):
    with pytest.raises(ValueError, match=message):
        precession_constant(body)


def test_precession_constant_body_file_without_satellites(tmp_path):
    path = tmp_path / "warm-jupiter.toml"
    path.write_text(
        'name = "warm Jupiter"\nprimary = "sun"\nj2 = 0.0147\nmoment_of_inertia = 0.254\n'
        'rotation_period = {value = 10.0, unit = "h"}\nsemi_major_axis = {value = 0.5, unit = "au"}\n'
        "eccentricity = 0.0\nobliquity = 10.0\n"
    )
    body = catalogue.read_body(path)
    got = precession_constant(body)
    n2 = mp.mpf("1.3271244004127942e11") / (mp.mpf("0.5") * mp.mpf("149597870.7")) ** 3
    alpha = mp.mpf(1.5) * n2 / (2 * mp.pi / 36000) * mp.mpf("0.0147") / mp.mpf("0.254") * TO_ARCSEC
    assert got.alpha / ARCSEC == pytest.approx(float(alpha), rel=1e-12)
    assert got.precession_rate == pytest.approx(float(alpha * mp.cos(mp.radians(10))), rel=1e-12)
    assert got.satellites == ()


def test_precession_constant_dynamical_ellipticity_refused_with_rings():
    with pytest.raises(ValueError, match="expected no dynamical ellipticity for Jupiter, whose satellite Io"):
        precession_constant("jupiter", dynamical_ellipticity=0.05)
    with pytest.raises(ValueError, match="expected no dynamical ellipticity for Titan, a body in spin-orbit"):
        precession_constant("titan", dynamical_ellipticity=0.05)
    mars = precession_constant("mars", dynamical_ellipticity=0.0054)
    assert mars.figure == 0.0054
