"""orbit_history: every source by name, tables by path, and the errors."""

from __future__ import annotations

import numpy as np
import pytest

from andoyer.planetary.orbits import (
    LaplaceLagrangeOrbit,
    NBodyOrbit,
    OrbitHistory,
    SecularOrbit,
    TableOrbit,
    VondrakEcliptic,
    orbit_history,
    write_orbit_csv,
)


def test_factory_vondrak():
    orbit = orbit_history("vondrak")
    assert isinstance(orbit, VondrakEcliptic)
    np.testing.assert_array_equal(orbit.normal([-1e5, 1e5]), VondrakEcliptic().normal([-1e5, 1e5]))


@pytest.mark.parametrize("body", ["earth", "Mars", "jupiter"])
def test_factory_laplace_lagrange(body):
    orbit = orbit_history("laplace-lagrange", body=body, frequencies="la2004")
    assert isinstance(orbit, LaplaceLagrangeOrbit)
    assert orbit.body == body.lower()
    assert orbit.frequencies == "la2004"


@pytest.mark.parametrize("body", ["earth", "Mars"])
def test_factory_secular_is_the_long_model(body):
    orbit = orbit_history("secular", body=body, step=4000.0)
    assert isinstance(orbit, SecularOrbit)
    assert (orbit.body, orbit.step) == (body.lower(), 4000.0)


def test_factory_nbody(tmp_path, monkeypatch):
    monkeypatch.setenv("ANDOYER_CACHE_DIR", str(tmp_path))
    orbit = orbit_history("nbody", body="mars", gr=False, sample_years=50.0)
    assert isinstance(orbit, NBodyOrbit)
    assert (orbit.body, orbit.gr, orbit.sample_years) == ("mars", False, 50.0)


def test_factory_csv_path(tmp_path):
    path = tmp_path / "orbit.csv"
    write_orbit_csv(path, VondrakEcliptic(), np.linspace(-1e4, 1e4, 11))
    for source in (path, str(path)):
        orbit = orbit_history(source, body="earth")
        assert isinstance(orbit, TableOrbit)
        assert isinstance(orbit, OrbitHistory)
        assert orbit.span == (-1e4, 1e4)


@pytest.mark.parametrize(
    ("source", "body", "options", "match"),
    [
        ("vondrak", "mars", {}, "expected body 'earth' for the vondrak orbit"),
        ("vondrak", "earth", {"gr": True}, "expected no options for the vondrak orbit, got gr"),
        ("secular", "pluto", {}, "expected a planet among"),
        ("nbody", "moon", {}, "expected a planet among"),
        ("laplace-lagrange", "pluto", {}, "expected a planet among"),
        ("laskar", "earth", {}, "expected an orbit source among vondrak, nbody, secular, laplace-lagrange"),
        ("/no/such/file.csv", "earth", {}, "expected an orbit source among"),
    ],
)
def test_factory_errors(source, body, options, match):
    with pytest.raises(ValueError, match=match):
        orbit_history(source, body=body, **options)


def test_factory_reads_la2010_file_by_name_short(tmp_path):
    # Recognised as La2010 by its name, refused by the reader: one row is not a history.
    path = tmp_path / "La2010a_alkhqp3L.dat"
    path.write_text("0 1 0 0 0 0 0\n")
    with pytest.raises(ValueError, match=r"expected at least 4 rows of t a l k h q p in .*La2010a_alkhqp3L"):
        orbit_history(path)


def test_factory_rejects_options_for_tables(tmp_path):
    path = tmp_path / "orbit.csv"
    write_orbit_csv(path, VondrakEcliptic(), np.linspace(-1e4, 1e4, 11))
    with pytest.raises(ValueError, match="expected no options for an orbit file"):
        orbit_history(path, frequencies="linear")
