"""``andoyer obliquity earth --tides MODEL``: the API's coupled spin axis, with the tidal history per row.

Checked three ways: against :func:`tidal_spin_axis_history` and :func:`tidal_history` called
directly (the same numbers); with the tidal model frozen (no dissipation), against the plain
command (the same axis); and the drift of the general precession over 2 Myr against the one of
the linear ``T_d = 1`` model of Zeebe & Lourens (2022), scaled by the ratio of the two models'
present rates of change of the precession constant (first order in time: the tidal history's
own curvature is below 0.1 % of the drift there).
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from andoyer.cli import main
from andoyer.planetary.orbits import VondrakEcliptic
from andoyer.planetary.spin_axis import SpinAxisModel, output_times
from andoyer.planetary.tides import (
    ConstantTimeLag,
    EarthMoonSystem,
    present_rates,
    tidal_history,
    tidal_spin_axis_history,
)

PLAIN_KEYS = {"t", "obliquity", "precession", "axis", "orbit_normal", "eccentricity", "climatic_precession",
              "precession_rate", "resonances", "error_estimate", "integration_step"}
TIDAL_KEYS = {"day_length", "lunar_distance", "precession_constant"}


def _json(argv, tmp_path, name="o.json"):
    out = tmp_path / name
    code = main(["obliquity", "earth", *argv, "--format", "json", "--output", str(out)])
    assert code == 0
    return json.loads(out.read_text())


@pytest.mark.parametrize("model", ["ocean", "constant-lag"])
def test_obliquity_tides_json_is_tidal_spin_axis_history(model, tmp_path):
    fields = _json(["--tides", model, "--span", "-200000", "0", "--step", "5000"], tmp_path)
    assert set(fields) == PLAIN_KEYS | TIDAL_KEYS
    t = output_times(-200000.0, 0.0, 5000.0)
    assert fields["t"] == t.tolist()
    h = tidal_spin_axis_history(VondrakEcliptic(), "earth", t, model)
    np.testing.assert_allclose(fields["obliquity"], np.degrees(h.obliquity), rtol=1e-15, atol=0)
    np.testing.assert_allclose(fields["precession"], np.degrees(h.precession), rtol=1e-15, atol=0)
    np.testing.assert_allclose(fields["axis"], h.axis, rtol=0, atol=1e-16)
    assert fields["precession_rate"] == pytest.approx(h.precession_rate, rel=1e-15)
    tides = tidal_history(t, model)
    for key in TIDAL_KEYS:
        np.testing.assert_allclose(fields[key], getattr(tides, key), rtol=1e-15, atol=0)
    # 200 kyr ago the day was 2.6 s shorter and the Moon 7.7 km closer (3.83 cm/yr, docs/tides.md)
    assert fields["lunar_distance"][0] == pytest.approx(384399 - 0.0383e-3 * 200000, abs=0.2)


def test_obliquity_tides_precession_rate_calibrates_alpha_at_j2000(tmp_path):
    argv = ["--tides", "ocean", "--precession-rate", "50.3", "--span", "-100000", "0", "--step", "5000"]
    fields = _json(argv, tmp_path)
    assert fields["precession_rate"] == pytest.approx(50.3, rel=1e-12)
    t = output_times(-100000.0, 0.0, 5000.0)
    h = tidal_spin_axis_history(VondrakEcliptic(), "earth", t, "ocean", precession_rate=50.3)
    np.testing.assert_allclose(fields["precession"], np.degrees(h.precession), rtol=1e-15, atol=0)


def test_obliquity_tides_csv_and_table_carry_the_tidal_columns(tmp_path):
    argv = ["obliquity", "earth", "--tides", "ocean", "--span", "-20000", "0", "--step", "10000"]
    fields = _json(argv[2:], tmp_path)
    out = tmp_path / "o.csv"
    assert main([*argv, "--format", "csv", "--output", str(out)]) == 0
    header, *rows = out.read_text().strip().splitlines()
    names = header.split(",")
    assert names[-3:] == ["day_length_h", "lunar_distance_km", "precession_constant_arcsec_yr"]
    values = np.array([[float(v) for v in row.split(",")] for row in rows])
    np.testing.assert_array_equal(values[:, -3], fields["day_length"])
    np.testing.assert_array_equal(values[:, -1], fields["precession_constant"])
    table = tmp_path / "o.txt"
    assert main([*argv, "--format", "table", "--output", str(table)]) == 0
    assert table.read_text().splitlines()[0].split()[-1] == "precession_constant_arcsec_yr"


def test_obliquity_tides_frozen_is_the_plain_axis(tmp_path, monkeypatch):
    """A tidal model without dissipation keeps α constant: the plain command's axis, bit for bit."""
    from andoyer.planetary.tides import coupling

    monkeypatch.setattr(coupling, "tidal_model", lambda name, system: ConstantTimeLag(0.0))
    span = ["--span", "-200000", "0", "--step", "5000"]
    frozen = _json(["--tides", "constant-lag", *span], tmp_path, "frozen.json")
    plain = _json(["--tidal-dissipation", "0", *span], tmp_path, "plain.json")
    for key in PLAIN_KEYS:
        assert frozen[key] == plain[key], key


@pytest.mark.slow
def test_obliquity_tides_precession_drift_follows_the_present_rates(tmp_path):
    """Over 2 Myr the change of ``p_A`` the tides make is the linear model's times the ratio of ``α̇/α``.

    ``α̇/α = ω̇/ω + b (2ṅ/n)``, ``b = β/((1 − e²)^{-3/2} + β)`` the Moon's share: for ``T_d = 1``
    Zeebe & Lourens' constants (the spin-axis model's ``tide_spin``, ``tide_moon``), for the
    tidal model its present spin-down and recession (``2ṅ/n = −3ȧ/a``).
    """
    span = ["--orbit", "secular", "--span", "-2000000", "0", "--step", "2000"]
    base = _json(["--tidal-dissipation", "0", *span], tmp_path, "none.json")
    linear = _json(["--tidal-dissipation", "1", *span], tmp_path, "linear.json")
    linear_drift = np.subtract(linear["precession"], base["precession"])[0]
    assert linear_drift < -10.0  # degrees: the slower precession of a faster, flatter Earth
    e0 = base["eccentricity"][-1]
    model = SpinAxisModel.from_precession_rate("earth", 50.38481507, math.radians(23.4393), e0, 1.0)
    moon_share = model.beta / ((1 - e0 * e0) ** -1.5 + model.beta)
    linear_rate = model.tide_spin + moon_share * model.tide_moon  # per year
    system = EarthMoonSystem()
    year = 365.25 * 86400.0
    for name in ("ocean", "constant-lag"):
        tidal = _json(["--tides", name, *span], tmp_path, f"{name}.json")
        drift = np.subtract(tidal["precession"], base["precession"])[0]
        rates = present_rates(name)
        spin = rates["spin_acceleration"] / system.spin_rate * year
        moon = -3 * rates["recession"] / 100.0 / (system.lunar_semi_major_axis) * moon_share
        # measured: 1.0545 (ocean) and 1.0701 (constant-lag) against 1.0548 and 1.0703
        assert drift / linear_drift == pytest.approx((spin + moon) / linear_rate, rel=2e-3)


@pytest.mark.parametrize(
    ("argv", "said"),
    [
        (["mars", "--tides", "ocean"], "expected the body earth with --tides"),
        (["earth", "--tides", "ocean", "--tidal-dissipation", "0"],
         "expected no --tidal-dissipation with --tides"),
        (["earth", "--tides", "ocean", "--tidal-dissipation", "1"], "(the tidal model sets the dissipation)"),
        (["earth", "--tides", "constant-lag", "--dynamical-ellipticity", "0.0033"],
         "expected no --dynamical-ellipticity with --tides"),
        (["earth", "--tides", "ocean", "--ensemble", "2"], "expected no --tides with --ensemble"),
    ],
)
def test_obliquity_tides_refusals_are_one_line(argv, said, tmp_path, capsys):
    out = tmp_path / "o.json"
    code = main(["obliquity", *argv, "--span", "-2000", "0", "--step", "1000", "--output", str(out)])
    err = capsys.readouterr().err
    assert code == 2
    assert len(err.splitlines()) == 1
    assert said in err
    assert list(tmp_path.iterdir()) == []


def test_obliquity_tides_beyond_the_models_reach_is_one_line(tmp_path, capsys):
    """An orbit table reaching further back than the constant lag (1.145 Gyr): refused, nothing written."""
    table = tmp_path / "orbit.csv"
    rows = [f"{t:.0f},0,0,1\n" for t in np.linspace(-1.5e9, 0.0, 7)]
    table.write_text("t_years,nx,ny,nz\n" + "".join(rows))
    out = tmp_path / "o.csv"
    argv = ["obliquity", "earth", "--orbit", str(table), "--tides", "constant-lag", "--span", "-1.2e9", "0",
            "--step", "1e3", "--output", str(out)]
    code = main(argv)
    err = capsys.readouterr().err
    assert code == 2
    assert len(err.splitlines()) == 1
    assert "constant-lag" in err
    assert not out.exists()


#: La2004's obliquity of the Earth (degrees) every 500 kyr over the last 5 Myr (kyr from J2000):
#: INSOLN.LA2004.BTL.ASC of Laskar et al. (2004, A&A 428, 261) as distributed by the IMCCE, read
#: from the copy in github.com/mcrucifix/palinsol (inst/extdata, commit e5178a9).
LA2004_EARTH_5MYR = {
    -5000: 23.94442199,
    -4500: 23.09655137,
    -4000: 22.76654475,
    -3500: 23.03656078,
    -3000: 23.55903877,
    -2500: 23.73265943,
    -2000: 22.61022178,
    -1500: 22.80241130,
    -1000: 23.62815765,
    -500: 23.70890344,
}


@pytest.mark.slow
def test_obliquity_default_dissipation_is_closer_to_la2004_over_5_myr(tmp_path):
    """Issue 22 item 5: the Earth's default is its present-day dissipation, nearer La2004 than none.

    On the secular orbit, measured at these epochs: rms 0.138° (max 0.230°) from La2004 with the
    default, 0.281° (max 0.681°, 5 Myr ago) with ``--tidal-dissipation 0``.
    """
    span = ["--orbit", "secular", "--span", "-5000000", "0", "--step", "2000"]  # below half ϖ's fastest turn
    default = _json(span, tmp_path, "default.json")
    none = _json([*span, "--tidal-dissipation", "0"], tmp_path, "none.json")
    t = np.array(default["t"])
    at = np.searchsorted(t, [1000.0 * kyr for kyr in LA2004_EARTH_5MYR])
    la2004 = np.array(list(LA2004_EARTH_5MYR.values()))
    runs = {"default": default, "none": none}
    error = {name: np.array(run["obliquity"])[at] - la2004 for name, run in runs.items()}
    rms = {name: float(np.sqrt(np.mean(e**2))) for name, e in error.items()}
    assert rms["default"] < 0.7 * rms["none"]
    assert rms["default"] < 0.2
    assert abs(error["default"][0]) < 0.3 < abs(error["none"][0])  # 5 Myr ago


@pytest.mark.slow
def test_tidal_history_more_output_times_than_a_million_steps():
    """Every output time ends a step: 1.2 million of them were refused ("status 3") before the step
    budget counted them; the history at every thousandth time is the one integrated to those alone."""
    t = np.linspace(-1.2e8, 0.0, 1_200_001)
    dense = tidal_history(t, "ocean")
    sparse = tidal_history(t[::100_000], "ocean")
    np.testing.assert_allclose(dense.lunar_distance[::100_000], sparse.lunar_distance, rtol=1e-12, atol=0)
    np.testing.assert_allclose(dense.day_length[::100_000], sparse.day_length, rtol=1e-12, atol=0)
