"""Precession of the Earth's and Mars' spin axes: secular model and full splitting integration."""

from __future__ import annotations

import mpmath as mp
import numpy as np
import pytest

from andoyer import catalogue
from andoyer.perturbations.solar_system import DAY, JULIAN_YEAR, OBLIQUITY, mean_perturbers
from andoyer.planetary.precession import (
    ARCSEC,
    PrecessionRates,
    default_step,
    mean_node_rate,
    planet_body,
    precession_problem,
    precession_rates,
)

#: Acceptance bands (″/yr) of the issue: observed 50.38 (Earth, luni-solar) and 7.58 (Mars).
BANDS = {"earth": (50.0, 50.8), "mars": (7.4, 7.8)}


def closed_form_rate(planet, moments=None):
    """p = Σ 3μ/(2a³(1-e²)^{3/2} ω) H_d cos ε (1 - 3/2 sin² i), first order, averaged over the lunar node."""
    body, period = planet_body(planet, moments)
    omega = 2 * np.pi / period
    H_d = (body.C - 0.5 * (body.A + body.B)) / body.C
    total = 0.0
    for p in mean_perturbers(planet):
        a, e, i = p.orbit.semi_major_axis, p.orbit.eccentricity, p.orbit.inclination
        total += 1.5 * p.gm / (a**3 * (1 - e * e) ** 1.5 * omega) * (1 - 1.5 * np.sin(i) ** 2)
    return total * H_d * np.cos(OBLIQUITY[planet]) * JULIAN_YEAR / ARCSEC


def mpmath_earth_rate(H, rotation_period):
    """The Earth's first-order rate (″/yr) in 30 digits from the cited constants alone.

    Sun: IAU 2015 B3 GM 1.3271244e20 m³/s², a = 1 au = 1.495978707e11 m (IAU 2012), e = 0.0167086;
    Moon: DE440 GM 4.9028e12, a = 384399 km, e = 0.0549, i = 5.145°; ε = 84381.406″ (IAU 2006).
    """
    mp.mp.dps = 30
    omega = 2 * mp.pi / mp.mpf(rotation_period)

    def term(gm, a, e, i):
        return (
            3
            * mp.mpf(gm)
            / (2 * mp.mpf(a) ** 3 * (1 - mp.mpf(e) ** 2) ** 1.5 * omega)
            * (1 - mp.mpf(1.5) * mp.sin(mp.radians(mp.mpf(i))) ** 2)
        )

    total = term("1.3271244e20", "1.495978707e11", "0.0167086", 0) + term(
        "4.9028e12", "384399e3", "0.0549", "5.145"
    )
    epsilon = mp.radians(mp.mpf("84381.406") / 3600)
    return float(total * mp.mpf(H) * mp.cos(epsilon) * mp.mpf(365.25 * 86400) * 648000 / mp.pi)


def test_precession_earth_default_is_the_iau_h():
    """The catalogue's H_MHB2000 = 0.00327379492 and sidereal day 360.9856235°/d (IAU) give 50.4006″/yr at
    first order; Lara's Table 1 (H = 0.0032789, day 86164.0905 s) 50.4792″/yr."""
    iau = mpmath_earth_rate("0.00327379492", mp.mpf(86400) * 360 / mp.mpf("360.9856235"))
    lara = mpmath_earth_rate(1 - (mp.mpf("0.99672") + mp.mpf("0.9967222")) / 2, "86164.0905")
    assert iau == pytest.approx(50.40057, abs=1e-5)
    assert lara == pytest.approx(50.47916, abs=1e-5)
    assert precession_rates("earth").secular == pytest.approx(iau, rel=2e-5)
    assert precession_rates("earth", moments="lara2013").secular == pytest.approx(lara, rel=2e-5)
    assert catalogue.get("earth").dynamical_ellipticity.value == 0.00327379492


def test_precession_unknown_moment_set_is_refused():
    with pytest.raises(ValueError, match="expected a moment set among catalogue, lara2013, got 'iers'"):
        precession_rates("earth", moments="iers")


@pytest.mark.parametrize("planet", list(BANDS))
def test_precession_secular_rate_in_band_and_closed_form(planet):
    """The closed form misses the second-order coupling of the 18.6-yr nutations (~1e-5 relative)."""
    rates = precession_rates(planet)
    low, high = BANDS[planet]
    assert low <= rates.secular <= high
    assert rates.secular == pytest.approx(closed_form_rate(planet), rel=1e-4 if planet == "earth" else 1e-11)
    assert rates.integrated is None


# Full integrations short enough for the default run: one orbit of the slowest perturber, order 2,
# and for the Earth 8.25 rotations per step (the rate moves by 1e-4″/yr from the default 2.25).
SHORT_RUNS = {"earth": (1.0, 33), "mars": (1.9, None)}


@pytest.fixture(scope="module", params=list(SHORT_RUNS))
def short_run(request):
    planet = request.param
    years, quarters = SHORT_RUNS[planet]
    step = None if quarters is None else quarters * planet_body(planet)[1] / 4
    return planet, precession_rates(planet, integrate=years, step=step)


def test_precession_integrated_rate_in_band(short_run):
    planet, rates = short_run
    low, high = BANDS[planet]
    assert low <= rates.integrated <= high


def test_precession_integrated_matches_secular(short_run):
    """First-order averaging differs from the full torque by ~p/n (4e-5 relative for the Earth's Sun,
    1e-6 for Mars); the splitting's step error is below 1e-3″/yr (module docstring's table)."""
    _, rates = short_run
    assert abs(rates.integrated - rates.secular) <= 0.01


@pytest.mark.slow
@pytest.mark.parametrize(("planet", "years"), [("earth", 18.6), ("mars", 10.0)])
def test_precession_long_integration_at_default_step(planet, years):
    rates = precession_rates(planet, integrate=years, order=4)
    low, high = BANDS[planet]
    assert low <= rates.integrated <= high
    assert abs(rates.integrated - rates.secular) <= 0.01


@pytest.mark.slow
def test_precession_resonant_step_aliases_the_triaxial_torque():
    """A step of 19.5 rotations samples Mars' (B-A) torque at one phase: the rate leaves the band."""
    step = 78 * planet_body("mars")[1] / 4
    rates = precession_rates("mars", integrate=1.9, step=step, order=4)
    assert abs(rates.integrated - rates.secular) >= 0.3


@pytest.mark.parametrize("planet", list(BANDS))
def test_precession_default_step_is_odd_quarter_rotations_under_a_twelfth_orbit(planet):
    step = default_step(planet)
    quarters = step / (planet_body(planet)[1] / 4)
    assert quarters == pytest.approx(round(quarters), abs=1e-9)
    assert round(quarters) % 2 == 1
    shortest = min(2 * np.pi / p.orbit.mean_motion for p in mean_perturbers(planet))
    assert shortest / 12 - planet_body(planet)[1] / 2 <= step <= shortest / 12


def test_precession_problem_states_start_at_the_obliquity():
    model, states = precession_problem("Earth")
    M = states.m_reference
    inclination = np.arctan2(np.hypot(M[:, 0], M[:, 1]), M[:, 2])
    assert np.allclose(inclination, OBLIQUITY["earth"], atol=1e-15)
    assert np.allclose(np.arctan2(M[:, 0], -M[:, 1]) % (2 * np.pi), np.pi / 2 * np.arange(4), atol=1e-15)
    assert [p.name for p in model.perturbation.perturbers] == ["Sun", "Moon"]


def test_precession_mean_node_rate_removes_orbital_harmonics(rng):
    sun = mean_perturbers("mars")[0]
    n = sun.orbit.mean_motion
    t = np.linspace(0.0, 2 * JULIAN_YEAR, 300)
    phases = rng.uniform(0, 2 * np.pi, 3)
    h = -1e-12 * t + sum(1e-5 / k * np.cos(k * n * t + phases[k - 1]) for k in (1, 2, 3))
    # abs=0: the rate is below pytest's default absolute tolerance (1e-12)
    assert mean_node_rate(t, h, [sun]) == pytest.approx(-1e-12, rel=1e-9, abs=0)
    assert mean_node_rate(t, np.stack([h - 1e-6, h + 1e-6], -1), [sun]) == pytest.approx(
        -1e-12, rel=1e-9, abs=0
    )


def test_precession_rates_as_dict():
    rates = PrecessionRates("mars", ("Sun",), 0.44, 7.59, 7.58, 1.9, 10 * DAY)
    assert rates.as_dict() == {
        "body": "mars",
        "perturbers": ["Sun"],
        "obliquity_deg": pytest.approx(np.degrees(0.44)),
        "secular_arcsec_per_year": 7.59,
        "integrated_arcsec_per_year": 7.58,
        "integration_years": 1.9,
        "step_days": pytest.approx(10.0),
    }


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"body": "venus"}, "expected one of earth, mars, got 'venus'"),
        ({"body": "mars", "integrate": -1.0}, "expected a positive number of years for integrate"),
        ({"body": "mars", "secular_years": 0.0}, "expected a positive number of years for secular_years"),
        ({"body": "mars", "integrate": 1.0, "step": float("nan")}, "expected a positive finite step"),
    ],
)
def test_precession_rejects_bad_input(kwargs, message):
    with pytest.raises(ValueError, match=message):
        precession_rates(**kwargs)


def test_precession_mean_node_rate_rejects_bad_shapes():
    with pytest.raises(ValueError, match=r"expected times \(T,\) with T >= 3"):
        mean_node_rate(np.arange(5.0), np.zeros(4))
