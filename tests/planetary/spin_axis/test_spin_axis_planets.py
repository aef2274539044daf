"""The spin axes of Venus and the giant planets: their catalogued constant, the s_k resonances, α drifting."""

from __future__ import annotations

import json

import numpy as np
import pytest
from spin_cases import FixedOrbit

from andoyer import catalogue
from andoyer.catalogue.units import ARCSEC
from andoyer.planetary.orbits import orbit_history
from andoyer.planetary.precession_constant import obliquity, precession_constant
from andoyer.planetary.spin_axis import SpinAxisModel, default_axis, spin_axis_history
from andoyer.planetary.spin_axis.resonances import resonance_distances

PLANETS = ("venus", "jupiter", "saturn", "uranus", "neptune")


@pytest.mark.parametrize("body", PLANETS)
def test_planet_axis_starts_at_the_catalogued_obliquity_and_rate(body):
    """At J2000 the secular orbit's normal and the IAU pole give the obliquity of the catalogue's orbit
    (the secular model's J2000 plane differs from Standish's mean elements by < 0.01°), and ψ̇ = α cos ε."""
    orbit = orbit_history("secular", body)
    h = spin_axis_history(orbit, body, [0.0, 1000.0])
    assert np.degrees(h.obliquity[0]) == pytest.approx(np.degrees(obliquity(body)), abs=0.01)
    c = precession_constant(body)
    assert h.precession_rate == pytest.approx(c.alpha * np.cos(h.obliquity[0]) / ARCSEC, rel=1e-3)


@pytest.mark.parametrize("body", ["saturn", "jupiter", "venus"])
def test_planet_axis_on_a_fixed_orbit_precesses_at_alpha_cos_epsilon(body):
    """On a fixed orbit ṡ = α (s·n)(s×n) turns s uniformly about n at α cos ε: after T the node has moved
    by α cos ε T (closed form), the obliquity not at all."""
    orbit = FixedOrbit(e=catalogue.get(body).eccentricity.value)
    model = SpinAxisModel.from_precession_constant(body)
    eps = 0.4
    axis = [np.sin(eps), 0.0, np.cos(eps)]
    T = 2e6
    h = spin_axis_history(orbit, body, np.linspace(0.0, T, 4001), axis=axis, step=2000.0)
    node = np.unwrap(np.arctan2(h.axis[:, 1], h.axis[:, 0]))
    expected = model.rate(0.0, orbit.e) * np.cos(eps) * T
    assert abs(node[-1] - node[0]) == pytest.approx(expected, rel=1e-9)
    assert np.abs(h.obliquity - eps).max() <= 1e-12


def test_planet_axis_drift_of_alpha_is_linear_in_time():
    """α(t) = α₀ (1 + t/τ): the node moves by α₀ cos ε (T + T²/2τ) on a fixed orbit."""
    orbit = FixedOrbit(e=0.0)
    tau = 5e6
    eps = 0.45
    h = spin_axis_history(
        orbit,
        "saturn",
        np.linspace(0.0, 3e6, 301),
        axis=[np.sin(eps), 0.0, np.cos(eps)],
        ellipticity_drift=1 / tau,
        step=2000.0,
    )
    alpha0 = h.model.rate(0.0, 0.0)
    assert h.model.rate(1e6, 0.0) == pytest.approx(alpha0 * (1 + 1e6 / tau), rel=1e-14)
    # Titan's ring makes the figure: the effective ellipticity (0.30) may grow past 1/2
    SpinAxisModel.from_precession_constant("saturn", 1 / tau).check_span(0.0, 2 * tau)
    node = np.unwrap(np.arctan2(h.axis[:, 1], h.axis[:, 0]))
    T = 3e6
    assert abs(node[-1] - node[0]) == pytest.approx(alpha0 * np.cos(eps) * (T + T**2 / (2 * tau)), rel=1e-9)


def test_planet_resonances_saturn_near_s8_jupiter_below_s7():
    """Saturn's ψ̇ lies 0.04″/yr above |s8| (Ward & Hamilton 2004), Jupiter's 0.39″/yr below |s7|
    (Ward & Canup 2006; Saillenfest et al. 2020: Jupiter will reach s7 as its satellites migrate)."""
    saturn = resonance_distances(precession_constant("saturn").precession_rate)[0]
    jupiter = resonance_distances(precession_constant("jupiter").precession_rate)[0]
    assert (saturn["mode"], jupiter["mode"]) == ("s8", "s7")
    assert saturn["frequency"] == -0.691736
    assert 0 < saturn["distance"] < 0.07
    assert -0.45 < jupiter["distance"] < 0


def test_planet_default_axis_is_the_iau_pole_reversed_for_retrograde_spin():
    venus = default_axis("venus")
    assert np.linalg.norm(venus) == pytest.approx(1.0, abs=1e-15)
    assert venus[2] < 0
    assert np.degrees(np.arccos(default_axis("uranus")[2])) == pytest.approx(97.86, abs=0.5)


def test_planet_body_file_named_after_a_planet(tmp_path):
    """A body file is a body of the user's own: no satellites from the catalogue, α from its own values."""
    entry = catalogue.get("saturn").to_dict()
    entry["moment_of_inertia"] = {"value": 0.22, "unit": "1"}
    path = tmp_path / "saturn.json"
    path.write_text(json.dumps(entry))
    body = catalogue.read_body(path)
    model = SpinAxisModel.from_precession_constant(body)
    assert model.entry is body
    c = precession_constant(body)
    assert c.satellites == ()
    assert c.figure == pytest.approx(0.016290573 / 0.22, rel=1e-15)
    assert model.dynamical_ellipticity() == pytest.approx(c.figure, rel=1e-12)


def test_planet_mercury_is_refused_as_a_cassini_state():
    with pytest.raises(ValueError, match="expected a body out of spin-orbit resonance"):
        SpinAxisModel.from_precession_constant("mercury")


def test_cli_obliquity_saturn_json_resonances(run_cli):
    code, out, _ = run_cli(
        "obliquity", "saturn", "--span", "-20000", "20000", "--step", "10000", "--format", "json"
    )
    assert code == 0
    fields = json.loads(out)
    nearest = fields["resonances"][0]
    assert nearest["mode"] == "s8"
    assert nearest["distance"] == pytest.approx(fields["precession_rate"] - 0.691736, abs=1e-12)
    assert fields["obliquity"][2] == pytest.approx(np.degrees(obliquity("saturn")), abs=0.01)


def test_cli_obliquity_drift_timescale_grows_the_rate(run_cli):
    """With TAU the rate at J2000 is unchanged (α(0) = α₀) and the axis turns faster after it."""
    argv = ("obliquity", "saturn", "--span", "0", "100000", "--step", "10000", "--format", "json")
    _, plain, _ = run_cli(*argv)
    code, drifted, _ = run_cli(*argv, "--drift-timescale", "3e5")
    assert code == 0
    plain, drifted = json.loads(plain), json.loads(drifted)
    assert drifted["precession_rate"] == pytest.approx(plain["precession_rate"], rel=1e-12)
    # ∫(1 + t/τ) dt over 1e5 years: 1 + 1e5/(2·3e5) = 1.167 times the plain precession
    assert drifted["precession"][-1] == pytest.approx(plain["precession"][-1] * (1 + 1e5 / 6e5), rel=2e-3)


def test_cli_obliquity_body_file(run_cli, tmp_path):
    entry = catalogue.get("jupiter").to_dict()
    entry["moment_of_inertia"] = {"value": 0.26, "unit": "1"}
    path = tmp_path / "jupiter.json"
    path.write_text(json.dumps(entry))
    code, out, err = run_cli(
        "obliquity", "--body-file", str(path), "--span", "0", "20000", "--step", "10000", "--format", "json"
    )
    assert code == 0, err
    alpha = 1.5 * precession_constant("jupiter").mean_motion_squared * 0.014696572 / 0.26
    alpha /= precession_constant("jupiter").spin_rate  # no satellites: a body file has none
    rate = alpha * (1 - catalogue.get("jupiter").eccentricity.value ** 2) ** -1.5
    assert json.loads(out)["precession_rate"] == pytest.approx(
        rate * 365.25 * 86400 * np.cos(obliquity("jupiter")) / ARCSEC, rel=2e-3
    )


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        ([], "expected a BODY or a --body-file PATH, got neither"),
        (["saturn", "--body-file", "x.json"], "expected a BODY or a --body-file PATH, got both"),
        (["saturn", "--drift-timescale", "0"], "expected 0 < |--drift-timescale TAU| <= 1e+15 years"),
        (["saturn", "--drift-timescale", "nan"], "expected a finite number"),
        (["jupiter", "--tidal-dissipation", "1"], "expected tidal dissipation 0 for a planet without a moon"),
        (
            ["saturn", "--span", "0", "1e8", "--drift-timescale", "-1e7"],
            "expected a drift that keeps the precession constant positive over the span",
        ),
        (["venus", "--span", "0", "1e8", "--drift-timescale", "1e3"], "expected an ellipticity drift"),
    ],
)
def test_cli_obliquity_planet_refusals(run_cli, tmp_path, argv, message):
    code, out, err = run_cli("obliquity", *argv, "--output", str(tmp_path / "out.csv"))
    assert code == 2
    assert out == ""
    assert len(err.strip().splitlines()) == 1
    assert message in err
    assert list(tmp_path.iterdir()) == []


def test_cli_obliquity_body_file_of_another_name_needs_a_table(run_cli, tmp_path):
    path = tmp_path / "exo.toml"
    path.write_text('name = "Exo b"\nprimary = "sun"\nj2 = 0.01\nmoment_of_inertia = 0.3\n')
    code, _, err = run_cli("obliquity", "--body-file", str(path))
    assert code == 2
    assert "expected --orbit PATH (an orbit table) for the body file's 'Exo b'" in err


def test_cli_obliquity_body_file_ensemble_refused_in_one_line(run_cli, tmp_path):
    """The ensemble's members are Mars' and the Earth's: a body file is refused naming both sides."""
    path = tmp_path / "saturn.json"
    path.write_text(json.dumps(catalogue.get("saturn").to_dict()))
    code, out, err = run_cli(
        "obliquity", "--body-file", str(path), "--ensemble", "3", "--output", str(tmp_path / "out.json")
    )
    assert (code, out) == (2, "")
    line = (
        "andoyer obliquity: error: expected a BODY in mars, earth with --ensemble (its members are those "
        f"bodies' spin axes), got --body-file {str(path)!r}"
    )
    assert err.strip().splitlines() == [line]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["saturn.json"]


def test_default_axis_mars_is_the_iau_2015_pole_turned_to_the_ecliptic():
    """Mars' axis at J2000: the IAU WGCCRE 2015 pole with its periodic terms (317.680854°, 52.886439°,
    Archinal et al. 2018) turned by ε₀ = 84381.406″ about the x axis, computed here apart."""
    ra, dec, eps = np.radians(317.680854), np.radians(52.886439), np.radians(84381.406 / 3600)
    x, y, z = np.cos(dec) * np.cos(ra), np.cos(dec) * np.sin(ra), np.sin(dec)
    expected = [x, np.cos(eps) * y + np.sin(eps) * z, -np.sin(eps) * y + np.cos(eps) * z]
    assert default_axis("mars") == pytest.approx(expected, abs=2e-8)


def test_neptune_obliquity_with_the_iau_periodic_terms_is_the_fact_sheet_value():
    """Neptune's pole moves by 0.70 sin N, −0.51 cos N (IAU 2015): with them its obliquity to the
    Standish J2000 orbit is NASA's fact-sheet 28.32° (given to 0.01°); without, it was 27.85°."""
    assert np.degrees(obliquity("neptune")) == pytest.approx(28.32, abs=0.005)
