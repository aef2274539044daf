"""Orbit tables: round trips against analytic orbits, the La2010-style reader, and the errors."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from andoyer.planetary.orbits import TableOrbit, read_alkhqp, read_orbit_csv, write_orbit_csv
from andoyer.planetary.orbits.table import MIN_ROWS


class PrecessingOrbit:
    """An analytic orbit: the plane tilted by I precessing at rate s, the perihelion at rate g."""

    name = "analytic"
    span = (-1e5, 1e5)
    has_eccentricity = True

    def __init__(self, inclination=0.02, s=-1e-4, e=0.03, g=2e-4):
        self.I, self.s, self.e, self.g = inclination, s, e, g

    def elements(self, t):
        t = np.asarray(t, float)
        return self.e + 0 * t, self.I + 0 * t, self.s * t, 1.0 + self.g * t

    def normal(self, t):
        _, i, node, _ = self.elements(t)
        return np.stack([np.sin(i) * np.sin(node), -np.sin(i) * np.cos(node), np.cos(i)], axis=-1)

    def eccentricity_vector(self, t):
        e, i, node, varpi = self.elements(t)
        w = varpi - node
        P = np.stack(
            [
                np.cos(w) * np.cos(node) - np.sin(w) * np.sin(node) * np.cos(i),
                np.cos(w) * np.sin(node) + np.sin(w) * np.cos(node) * np.cos(i),
                np.sin(w) * np.sin(i),
            ],
            axis=-1,
        )
        return e[..., None] * P


def test_table_csv_round_trip_matches_the_analytic_orbit(tmp_path, rng):
    orbit = PrecessingOrbit()
    path = tmp_path / "orbit.csv"
    write_orbit_csv(path, orbit, np.linspace(-1e5, 1e5, 401))
    table = read_orbit_csv(path)
    assert table.span == (-1e5, 1e5)
    t = rng.uniform(-1e5, 1e5, 200)
    # Cubic spline at h = 500 yr: error ≲ (5/384) h⁴ |f⁗| = 1.6e-9 for the normal (amplitude 0.02,
    # frequency 1e-4/yr) and 6e-7 for e (0.03, frequencies up to |g − 2s| = 4e-4/yr), for a clamped
    # spline; the not-a-knot ends add a small factor.
    np.testing.assert_allclose(table.normal(t), orbit.normal(t), atol=1e-8)
    np.testing.assert_allclose(table.eccentricity_vector(t), orbit.eccentricity_vector(t), atol=1e-6)
    # At the nodes the table returns what was written (repr round-trips floats).
    nodes = np.linspace(-1e5, 1e5, 401)[::37]
    np.testing.assert_allclose(table.normal(nodes), orbit.normal(nodes), atol=1e-15)


def test_table_csv_elements_columns(tmp_path, rng):
    orbit = PrecessingOrbit()
    t = np.linspace(-5e4, 5e4, 201)
    e, i, node, varpi = orbit.elements(t)
    lines = ["# an orbit in elements", "t_kyr,e,inclination_deg,node_deg,varpi_deg,comment"]
    columns = (t / 1000, e, np.degrees(i), np.degrees(node), np.degrees(varpi))
    lines += [",".join(repr(float(x)) for x in row) + ",x" for row in zip(*columns, strict=True)]
    path = tmp_path / "elements.csv"
    path.write_text("\n".join(lines) + "\n")
    table = read_orbit_csv(path)
    tt = rng.uniform(-5e4, 5e4, 50)
    # The same spacing and bounds as the vector round trip above.
    np.testing.assert_allclose(table.normal(tt), orbit.normal(tt), atol=1e-8)
    np.testing.assert_allclose(table.eccentricity_vector(tt), orbit.eccentricity_vector(tt), atol=1e-6)


def test_table_csv_without_eccentricity(tmp_path):
    path = tmp_path / "plane.csv"
    path.write_text("t_years,nx,ny,nz\n" + "".join(f"{t},0,0,1\n" for t in range(5)))
    table = read_orbit_csv(path)
    assert table.has_eccentricity is False
    with pytest.raises(NotImplementedError, match="expected a table with the eccentricity"):
        table.eccentricity_vector(1.0)


@given(
    inclination=st.floats(0.0, 0.5),
    s=st.floats(-1e-3, 1e-3),
    e=st.floats(0.0, 0.5),
    g=st.floats(-1e-3, 1e-3),
)
def test_table_arrays_round_trip_at_nodes(inclination, s, e, g):
    orbit = PrecessingOrbit(inclination, s, e, g)
    t = np.linspace(-1e4, 1e4, 41)
    table = TableOrbit(t, orbit.normal(t), orbit.eccentricity_vector(t))
    np.testing.assert_allclose(table.normal(t), orbit.normal(t), atol=1e-14)
    np.testing.assert_allclose(table.eccentricity_vector(t), orbit.eccentricity_vector(t), atol=1e-15)


def test_table_alkhqp_with_rotation(tmp_path):
    # A file in a frame turned by R from the J2000 ecliptic: k, h, q = sin(i/2) cos Ω, p = sin(i/2) sin Ω.
    orbit = PrecessingOrbit()
    t = np.linspace(-2e4, 2e4, 81)
    e, i, node, varpi = orbit.elements(t)
    columns = (
        t / 1000,
        1.0 + 0 * t,
        0 * t,
        e * np.cos(varpi),
        e * np.sin(varpi),
        np.sin(i / 2) * np.cos(node),
        np.sin(i / 2) * np.sin(node),
    )
    rows = [" ".join(repr(float(x)) for x in row).replace("e-", "D-") for row in zip(*columns, strict=True)]
    path = tmp_path / "La2010x_alkhqp.dat"
    path.write_text("\n".join(rows) + "\n")
    angle = 0.3
    R = np.array([[1, 0, 0], [0, np.cos(angle), -np.sin(angle)], [0, np.sin(angle), np.cos(angle)]])
    table = read_alkhqp(path, rotation=R)
    np.testing.assert_allclose(table.normal(t), orbit.normal(t) @ R.T, atol=1e-12)
    np.testing.assert_allclose(table.eccentricity_vector(t), orbit.eccentricity_vector(t) @ R.T, atol=1e-12)


def write(tmp_path, text, name="bad.csv"):
    path = tmp_path / name
    path.write_text(text)
    return path


GOOD_ROWS = "".join(f"{t},0,0,1\n" for t in range(5))
HEAD = "t_years,nx,ny,nz\n"
ELEMENTS = "t_years,e,inclination_deg,node_deg,varpi_deg\n"


@pytest.mark.parametrize(
    ("text", "match"),
    [
        ("", "expected a CSV header row and data rows"),
        ("time,nx,ny,nz\n" + GOOD_ROWS, "expected a time column t_years or t_kyr"),
        ("t_years,nx,ny\n" + "".join(f"{t},0,0\n" for t in range(5)), "expected the columns nx, ny, nz"),
        (HEAD + "0,0,0,1\n1,0,0,1\n1,0,0,1\n2,0,0,1\n", "increasing times, got 1 after 1 on line 4"),
        (HEAD + "0,0,0,1\n2,0,0,1\n1,0,0,1\n3,0,0,1\n", "increasing times, got 1 after 2 on line 4"),
        (HEAD + "0,0,0,1\n1,0,nan,1\n2,0,0,1\n3,0,0,1\n", "finite number in column ny on line 3"),
        (HEAD + "0,0,0,1\n1,0,abc,1\n2,0,0,1\n3,0,0,1\n", "a number in column ny on line 3 .*'abc'"),
        (HEAD + "0,0,0,1\n1,0,1\n2,0,0,1\n3,0,0,1\n", "expected 4 values on line 3"),
        (HEAD + "0,0,0,1\n1,0,0,1\n2,0,0,1\n", f"at least {MIN_ROWS} rows"),
        (HEAD + "0,0,0,1\n1,0,0,2\n2,0,0,1\n3,0,0,1\n", "unit orbit normals, got length 2 at row"),
        (
            "t_years,e,inclination_deg,node_deg,varpi_deg\n" + "".join(f"{t},1.2,0,0,0\n" for t in range(4)),
            "expected an eccentricity 0 <= e < 1 .*got 1.2 in column e on line 2",
        ),
        (
            ELEMENTS + "".join(f"{t},0.1,{100 * t},0,0\n" for t in range(4)),
            r"expected an inclination 0 <= i <= 180 deg .*got 200.0 in column inclination_deg on line 4",
        ),
    ],
)
def test_table_csv_errors(tmp_path, text, match):
    with pytest.raises(ValueError, match=match):
        read_orbit_csv(write(tmp_path, text))


def test_table_span_error(tmp_path):
    table = read_orbit_csv(write(tmp_path, "t_years,nx,ny,nz\n" + GOOD_ROWS, "ok.csv"))
    with pytest.raises(ValueError, match=r"expected times within the ok\.csv orbit's span 0 to 4"):
        table.normal(4.5)


@pytest.mark.parametrize(
    ("text", "rotation", "match"),
    [
        (
            "0 1 0 0 0 0 0\n1 1 0 0 0 0\n",
            np.eye(3),
            r"expected 7 columns \(t a l k h q p\) on line 2 .*got 6",
        ),
        ("0 1 0 0 0 0 0\n" * 3 + "3 1 0 0 0 0 x\n", np.eye(3), "expected numbers .* on line 4"),
        (
            "".join(f"{t} 1 0 0 0 0 0\n" for t in range(3)) + "3 1 0 0 0 0 nan\n",
            np.eye(3),
            "expected finite numbers, got nan in column p on line 4",
        ),
        ("0 1 0 0 0 0 0\n", 2 * np.eye(3), "expected a proper orthogonal 3x3 rotation"),
    ],
)
def test_table_alkhqp_errors(tmp_path, text, rotation, match):
    with pytest.raises(ValueError, match=match):
        read_alkhqp(write(tmp_path, text, "bad.dat"), rotation)
