"""``andoyer orbit``: the elements of every source, in each format, and damaged solution files."""

from __future__ import annotations

import csv
import io
import json
import math
import re

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from andoyer.cli import main
from andoyer.planetary.orbits import LaplaceLagrangeOrbit

# Standish's J2000 mean semi-major axes (JPL, "Keplerian elements for approximate positions of
# the major planets", Table 1, fit to DE405), those of the linear theory.
STANDISH_A = {"earth": 1.00000261, "mars": 1.52371034}


def run(argv, capsys):
    try:
        code = main([str(a) for a in argv])
    except SystemExit as exc:
        code = exc.code
    out = capsys.readouterr()
    return code, out.out, out.err


def test_orbit_json_laplace_lagrange_elements(capsys):
    code, out, err = run(
        [
            "orbit",
            "laplace-lagrange",
            "--planets",
            "mars",
            "earth",
            "--span",
            "-2000",
            "0",
            "--step",
            "1000",
            "--format",
            "json",
        ],
        capsys,
    )
    assert code == 0, err
    data = json.loads(out)
    assert data["t"] == [-2000.0, -1000.0, 0.0]
    assert data["planets"] == ["earth", "mars"]
    for planet in ("earth", "mars"):
        orbit = LaplaceLagrangeOrbit(planet)
        n, e = orbit.normal(np.array(data["t"])), orbit.eccentricity_vector(np.array(data["t"]))
        got = data["elements"][planet]
        # Directly from the vectors: i = acos(n_z), Ω = atan2(n_x, -n_y); ϖ by Ω plus the angle
        # from the node to the perihelion, rotated into the orbit plane with scipy.
        np.testing.assert_allclose(got["e"], np.linalg.norm(e, axis=-1), rtol=1e-12)
        np.testing.assert_allclose(got["inclination"], np.degrees(np.arccos(n[:, 2])), rtol=1e-9, atol=1e-6)
        np.testing.assert_allclose(got["node"], np.degrees(np.arctan2(n[:, 0], -n[:, 1])) % 360, atol=1e-7)
        for k in range(3):
            u = e[k] / np.linalg.norm(e[k])
            node, _, omega = Rotation.from_matrix(np.stack([u, np.cross(n[k], u), n[k]], axis=-1)).as_euler(
                "ZXZ"
            )
            assert got["perihelion"][k] == pytest.approx(math.degrees(node + omega) % 360, abs=1e-7)
        assert got["a"] == [STANDISH_A[planet]] * 3


def test_orbit_csv_rows_per_time_and_planet(tmp_path, capsys):
    out = tmp_path / "vondrak.csv"
    code, _, err = run(
        ["orbit", "vondrak", "--span", "-2000", "0", "--step", "1000", "--format", "csv", "--output", out],
        capsys,
    )
    assert code == 0, err
    rows = list(csv.reader(io.StringIO(out.read_text())))
    assert rows[0] == ["t_yr", "planet", "a_au", "e", "inclination_deg", "perihelion_deg", "node_deg"]
    assert [r[:2] for r in rows[1:]] == [["-2000.0", "earth"], ["-1000.0", "earth"], ["0.0", "earth"]]
    # The ecliptic knows no ellipse: a, e and the perihelion are empty; the ecliptic at J2000 is the frame.
    assert all(r[2] == r[3] == r[5] == "" for r in rows[1:])
    assert float(rows[3][4]) == pytest.approx(0.0, abs=1e-12)


def test_orbit_netcdf_round_trip(tmp_path, capsys):
    import xarray as xr  # the ensemble extra, installed for the tests

    out = tmp_path / "secular.nc"
    code, _, err = run(
        [
            "orbit",
            "secular",
            "--planets",
            "jupiter",
            "saturn",
            "--span",
            "-1e6",
            "0",
            "--step",
            "5e5",
            "--format",
            "netcdf",
            "--output",
            out,
        ],
        capsys,
    )
    assert code == 0, err
    code, text, err = run(
        [
            "orbit",
            "secular",
            "--planets",
            "jupiter",
            "saturn",
            "--span",
            "-1e6",
            "0",
            "--step",
            "5e5",
            "--format",
            "json",
        ],
        capsys,
    )
    data = json.loads(text)
    with xr.open_dataset(out) as ds:
        assert list(ds.planet.values) == ["jupiter", "saturn"]
        np.testing.assert_array_equal(ds.time.values, data["t"])
        for k in ("a", "e", "inclination", "perihelion", "node"):
            np.testing.assert_array_equal(ds[k].values[:, 1], data["elements"]["saturn"][k])


def test_orbit_solution_file_by_content(tmp_path, capsys):
    # A ZB18a HNBody file named plainly, in HCI: the J2000 ecliptic's pole lies at i = 7.155 deg,
    # Ω = 180 deg there (Zeebe 2017's Sun equator, as snvecR turns it), so an orbit in the ecliptic
    # reads back with inclination 0.
    path = tmp_path / "run.out"
    path.write_text("".join(f"{-36525.0 * k} 1.0 0.0167 7.155 282.9 180.0 102.9 0.0\n" for k in range(5)))
    code, out, err = run(["orbit", path, "--step", "100", "--format", "json"], capsys)
    assert code == 0, err
    data = json.loads(out)
    assert data["t"] == [-400.0, -300.0, -200.0, -100.0, 0.0]
    earth = data["elements"]["earth"]
    np.testing.assert_allclose(earth["inclination"], 0.0, atol=1e-12)
    np.testing.assert_allclose(earth["e"], 0.0167, rtol=1e-14)
    np.testing.assert_allclose(earth["a"], 1.0, rtol=1e-14)


@pytest.mark.parametrize(
    ("text", "argv", "match"),
    [
        ("0 1 0 0.0167 0 0 0\n-1 1 0 0.0167 0 0\n", [], r"expected 7 columns \(t a l k h q p\) on line 2 of"),
        (
            "".join(f"{-k} 1 0 nan 0 0 0\n" for k in range(5)),
            [],
            r"expected finite numbers, got nan .* line 1",
        ),
        (
            "".join(f"{-k % 3} 1 0 0.01 0 0 0\n" for k in range(5)),
            [],
            r"strictly monotonic times .*got 1 after 2 on line 3",
        ),
        (
            "".join(f"{-k} 1 0 0.01 0 0 0\n" for k in range(5)),
            ["--span", "-1e5", "0"],
            r"expected --span T0 T1 within the la\.dat orbit's span -4000 to 0",
        ),
        (
            "".join(f"{-k} 1 0 0.01 0 0 0\n" for k in range(5)),
            ["--planets", "mars"],
            "expected planets earth",
        ),
        ("".join(f"{-k} 0.01 1.5\n" for k in range(5)), ["--orbit-format", "la2004"], "expected 4 columns"),
        ("0 1 2 3 4 5\n", [], r"expected an orbit or solution file of a known format"),
        (
            "".join(f"{-k} 1 0 0.01 0 0 0\n" for k in range(5)),
            ["--format", "netcdf"],
            "expected --output FILE",
        ),
    ],
)
def test_orbit_bad_file_one_line_exit_2_nothing_written(tmp_path, capsys, text, argv, match):
    path = tmp_path / "la.dat"
    path.write_text(text)
    out = tmp_path / "out.json"
    extra = [] if "netcdf" in argv else ["--output", out]
    code, _, err = run(["orbit", path, *argv, *extra], capsys)
    assert code == 2, err
    assert len(err.splitlines()) == 1, err
    assert re.search(match, err), err
    assert not out.exists()


def test_orbit_binary_and_bom(tmp_path, capsys):
    binary = tmp_path / "INSOLN.LA2004.BTL.ASC"
    binary.write_bytes(b"\x00\x01\xfe\xff garbage")
    code, _, err = run(["orbit", binary], capsys)
    assert code == 2
    assert "expected a text file of numbers, got byte 0xfe on line 1 of" in err
    bom = tmp_path / "ZB20a.dat"
    bom.write_bytes(b"\xef\xbb\xbf" + "".join(f"{k}.0 0.0{k + 1} 1.5\n" for k in range(4)).encode())
    code, out, err = run(["orbit", bom, "--format", "json"], capsys)
    assert code == 0, err
    assert json.loads(out)["elements"]["earth"]["e"] == [0.04, 0.03, 0.02, 0.01]


def test_orbit_named_source_refuses_format(capsys):
    code, _, err = run(["orbit", "secular", "--orbit-format", "la2010"], capsys)
    assert code == 2
    assert "expected --orbit-format only with a SOURCE file" in err


def test_orbit_obliquity_reads_named_format(tmp_path, capsys):
    # ``andoyer obliquity --orbit PATH --orbit-format``: a plainly named ZB18a file, the Earth's
    # orbit in the J2000 ecliptic written in HCI (i = 7.155 deg, node 180 deg); the obliquity then
    # follows the fixed ecliptic, as with the orbit written as a CSV table of that same orbit.
    path = tmp_path / "run.out"
    path.write_text("".join(f"{-36525.0 * k} 1.0 0.0167 7.155 282.9 180.0 102.9 0.0\n" for k in range(11)))
    table = tmp_path / "same.csv"
    table.write_text(
        "t_years,e,inclination_deg,node_deg,varpi_deg\n"
        + "".join(f"{-100.0 * k},0.0167,0.0,0.0,102.9\n" for k in range(10, -1, -1))
    )
    args = ["obliquity", "earth", "--span", "-900", "0", "--step", "300", "--format", "json"]
    code, out, err = run([*args, "--orbit", path, "--orbit-format", "zb18a"], capsys)
    assert code == 0, err
    code, same, err = run([*args, "--orbit", table], capsys)
    assert code == 0, err
    np.testing.assert_allclose(json.loads(out)["obliquity"], json.loads(same)["obliquity"], atol=1e-9)
    code, _, err = run([*args, "--orbit", "secular", "--orbit-format", "zb18a"], capsys)
    assert code == 2
    assert "expected orbit_format only with a file" in err


def test_orbit_nbody_members(tmp_path, capsys, monkeypatch):
    monkeypatch.setenv("ANDOYER_CACHE_DIR", str(tmp_path / "cache"))
    argv = [
        "orbit",
        "nbody",
        "--members",
        "3",
        "--seed",
        "2",
        "--planets",
        "mercury",
        "earth",
        "--span",
        "-1000",
        "0",
        "--step",
        "500",
        "--scheduler",
        "synchronous",
    ]
    code, out, err = run([*argv, "--format", "json"], capsys)
    assert code == 0, err
    data = json.loads(out)
    assert (data["members"], data["seed"], data["delta"], data["perturb"]) == (3, 2, 1e-10, "mercury")
    e = np.array(data["elements"]["mercury"]["e"])
    assert e.shape == (3, 3)
    # Member 0 is the nominal N-body orbit; the others differ from it by the displacement only.
    from andoyer.planetary.orbits import NBodyOrbit

    nominal = np.linalg.norm(
        NBodyOrbit("mercury", progress=False).eccentricity_vector(np.array(data["t"])), axis=-1
    )
    np.testing.assert_array_equal(e[0], nominal)
    assert 0 < np.abs(e[1:] - e[0]).max() < 1e-7
    # The Earth's heliocentric state is not moved: its orbit at J2000 is the same in every member.
    assert len({row[-1] for row in data["elements"]["earth"]["e"]}) == 1
    code, out, err = run([*argv, "--format", "csv"], capsys)
    rows = list(csv.reader(io.StringIO(out)))
    assert rows[0][:3] == ["t_yr", "member", "planet"]
    assert len(rows) == 1 + 3 * 3 * 2
    out_nc = tmp_path / "ens.nc"
    code, _, err = run([*argv, "--format", "netcdf", "--output", out_nc], capsys)
    assert code == 0, err
    import xarray as xr

    with xr.open_dataset(out_nc) as ds:
        assert ds.e.dims == ("member", "time", "planet")
        np.testing.assert_array_equal(ds.e.values[:, :, 0], e)


@pytest.mark.parametrize(
    ("argv", "match"),
    [
        (["orbit", "secular", "--members", "2"], "expected --members only with SOURCE nbody"),
        (["orbit", "nbody", "--members", "0", "--span", "-1000", "0"], "expected --members N >= 1"),
        (
            ["orbit", "nbody", "--members", "2", "--seed", "-1", "--span", "-1000", "0"],
            "expected --seed S >= 0",
        ),
        (
            ["orbit", "nbody", "--members", "2", "--workers", "0", "--span", "-1000", "0"],
            "expected --workers W",
        ),
        (
            [
                "orbit",
                "nbody",
                "--members",
                "2",
                "--delta",
                "1",
                "--span",
                "-1000",
                "0",
                "--scheduler",
                "synchronous",
            ],
            "expected a displacement 0 < delta",
        ),
        (
            [
                "orbit",
                "nbody",
                "--members",
                "2",
                "--perturb",
                "pluto",
                "--span",
                "-1000",
                "0",
                "--scheduler",
                "synchronous",
            ],
            "expected",
        ),
        (["orbit", "nbody", "--members", "2", "--span", "-1000", "0", "--delta", "nan"], "finite number"),
    ],
)
def test_orbit_nbody_members_bad_input(tmp_path, capsys, monkeypatch, argv, match):
    monkeypatch.setenv("ANDOYER_CACHE_DIR", str(tmp_path / "cache"))
    out = tmp_path / "out.json"
    code, _, err = run([*argv, "--output", out], capsys)
    assert code == 2, err
    assert len(err.splitlines()) == 1, err
    assert re.search(match, err), err
    assert not out.exists()
    assert not (tmp_path / "cache").exists()
