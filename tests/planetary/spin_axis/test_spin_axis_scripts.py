"""The measuring scripts of docs/spin-axis.md: La2004 files, the nbody variants' inputs, the figure's name."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq

from andoyer.planetary.orbits.planets import planet_data

SCRIPTS = Path(__file__).resolve().parents[3] / "scripts"


def load(name):
    spec = importlib.util.spec_from_file_location(f"{name}_script", SCRIPTS / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


PAST = """% downloaded from laskar website
% -Ka BP   Eccentricity    Obliquity    Perihelion
         0.000   0.1670236225492288D-01   0.4090928042223415D+00   0.1796256991128036D+01
        -1.000   0.1716078552110340D-01   0.4113524046362453D+00   0.1497910466087432D+01
        -2.000   0.1749697542256000D-01   0.4135554015563000D+00   0.1200024000000000D+01
"""
FUTURE = """         0.000   0.1670236225492288D-01   0.4090928042223415D+00   0.1796256991128036D+01
         1.000   0.1627519714977170D-01   0.4068337899307937D+00   0.2098560774622779D+01
"""


def test_compare_la2004_reads_imcce_files_merged_sorted(tmp_path):
    script = load("compare_la2004")
    (tmp_path / "past.asc").write_text(PAST)
    (tmp_path / "future.asc").write_text(FUTURE)
    rows = script.read_la2004([tmp_path / "past.asc", tmp_path / "future.asc"])
    assert rows[:, 0].tolist() == [-2000.0, -1000.0, 0.0, 1000.0]  # years, J2000 once
    assert rows[2, 2] == 0.4090928042223415  # the Fortran D exponent read exactly
    assert rows[3, 1] == pytest.approx(0.01627519714977170, rel=1e-15)


def test_compare_la2004_rejects_short_rows(tmp_path):
    script = load("compare_la2004")
    (tmp_path / "bad.asc").write_text("0.0 0.0167 0.409\n")
    with pytest.raises(ValueError, match="expected 4 columns"):
        script.read_la2004([tmp_path / "bad.asc"])


def test_nbody_variants_moon_quadrupole_against_averaged_pair():
    # The quadrupole J2 R² = (C − (A+B)/2)/M of the Earth–Moon pair about its barycentre, averaged
    # over the lunar orbit (Kepler's equation solved numerically), its perigee (8.85 yr) and its node
    # (18.6 yr), by direct summation: exact for these trigonometric polynomials of degree 2.
    script = load("nbody_variants")
    j2, radius = script.moon_quadrupole()
    q, e, inc = script.MOON_MASS_RATIO, script.MOON_E, np.radians(script.MOON_I_DEG)
    a = script.MOON_A_KM / script.AU_KM
    mean = (np.arange(400) + 0.5) / 400 * 2 * np.pi
    ecc = np.array([brentq(lambda x, m=m: x - e * np.sin(x) - m, 0.0, 2 * np.pi) for m in mean])
    p, w = a * (np.cos(ecc) - e), a * np.sqrt(1 - e**2) * np.sin(ecc)  # perifocal coordinates
    perigee = (np.arange(16) + 0.5) / 16 * 2 * np.pi
    u = (p[:, None] * np.cos(perigee) - w[:, None] * np.sin(perigee)).ravel()  # towards the node
    v = (p[:, None] * np.sin(perigee) + w[:, None] * np.cos(perigee)).ravel()
    node = (np.arange(16) + 0.5) / 16 * 2 * np.pi
    x = (u[:, None] * np.cos(node) - v[:, None] * np.cos(inc) * np.sin(node)).ravel()
    y = (u[:, None] * np.sin(node) + v[:, None] * np.cos(inc) * np.cos(node)).ravel()
    z = (v[:, None] * np.sin(inc) * np.ones_like(node)).ravel()
    reduced = q / (1 + q) ** 2  # m_E m_M / (m_E + m_M)²
    expected = reduced * np.mean(0.5 * (x**2 + y**2) - z**2)
    assert j2 * radius**2 == pytest.approx(expected, rel=1e-6)
    # and the barycentre's perihelion advance (3/2) n J2 (R/a)² quoted in docs/spin-axis.md: 7.6″/cy
    n = 2 * np.pi * np.sqrt((planet_data().sun_gm + planet_data().gm[2]) / (4 * np.pi**2))
    rate = 1.5 * n * j2 * (radius / planet_data().a[2]) ** 2 * 206264.806 * 100
    assert rate == pytest.approx(7.6, abs=0.05)


def test_nbody_variants_plan94_states_near_shipped():
    # erfa.plan94 and Standish's mean elements agree to their short-period terms: the inner planets
    # within 1e-4 au, Jupiter and Saturn within 0.03 au (the great inequality); velocities in au/yr.
    script = load("nbody_variants")
    states = script.plan94_states()
    data = planet_data()
    gap = np.linalg.norm(states[:, :3] - data.position, axis=-1)
    assert gap[:4].max() < 1e-4
    assert gap[4:].max() < 0.03
    speed = np.linalg.norm(states[:, 3:], axis=-1)
    np.testing.assert_allclose(speed, np.linalg.norm(data.velocity, axis=-1), rtol=2e-3)


def test_nbody_variants_unknown_variant():
    with pytest.raises(ValueError, match="expected a variant among"):
        load("nbody_variants").install("asteroids")


def test_spin_axis_figure_script_name_option(tmp_path):
    args = ["--orbit", "vondrak", "--span", "-2000", "0", "--step", "1000", "--out", str(tmp_path)]
    load("spin_axis_figure").main([*args, "--name", "x.png"])
    assert (tmp_path / "x.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
