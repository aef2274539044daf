"""The published solution files (La2004, La2010, ZB18a, ZB20, ZB23): known orbits written in each
format and read back, the frames' rotations, the formats recognised, and damaged files refused."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from andoyer.planetary.orbits.factory import orbit_history, planet_orbits, read_solution, solution_format
from andoyer.planetary.orbits.planets import PLANETS, planet_data

DEG = math.pi / 180.0
# The invariable plane on the J2000 ecliptic: Souami & Souchay (2012), A&A 543, A133 (DE405).
PLANE_I = (1.0 + 34.0 / 60.0 + 43.3 / 3600.0) * DEG
PLANE_NODE = (107.0 + 34.0 / 60.0 + 56.0 / 3600.0) * DEG
# The Sun's equator on the J2000 ecliptic as snvecR turns ZB18a's HCI frame (Zeebe 2017, AJ 154, 193).
SUN_NODE, SUN_I = 75.5940 * DEG, 7.155 * DEG


def frame_axes(inclination, node, x_angle=0.0):
    """Rows: the axes of a frame whose pole is at (i, Ω) on the ecliptic and whose x axis lies
    ``x_angle`` past the ascending node in its plane, in J2000-ecliptic components."""
    node_dir = np.array([math.cos(node), math.sin(node), 0.0])
    pole = np.array(
        [
            math.sin(inclination) * math.sin(node),
            -math.sin(inclination) * math.cos(node),
            math.cos(inclination),
        ]
    )
    ahead = np.cross(pole, node_dir)
    x = math.cos(x_angle) * node_dir + math.sin(x_angle) * ahead
    return np.stack([x, np.cross(pole, x), pole])


def elements_in(axes, normal, ecc):
    """i, Ω, ϖ, e of vectors given in the ecliptic, expressed in the frame ``axes`` (rows), by
    scipy's Euler angles (z-x-z: Ω, i, ω) instead of the library's formulas."""
    n, e = normal @ axes.T, ecc @ axes.T
    out = []
    for nk, ek in zip(n, e, strict=True):
        # The orbit frame: x to perihelion, z the normal; its z-x-z Euler angles are Ω, i, ω.
        u = ek / np.linalg.norm(ek)
        matrix = np.stack([u, np.cross(nk, u), nk], axis=-1)
        node, inc, omega = Rotation.from_matrix(matrix).as_euler("ZXZ")
        out.append((inc, node % (2 * math.pi), (node + omega) % (2 * math.pi), np.linalg.norm(ek)))
    return np.array(out).T


def earth_j2000():
    """The Earth-Moon barycentre's osculating normal and eccentricity vector at J2000 (DE421 states)."""
    data = planet_data()
    j = PLANETS.index("earth")
    r, v = data.position[j], data.velocity[j]
    mu = data.sun_gm + data.gm[j]
    h = np.cross(r, v)
    return h / np.linalg.norm(h), np.cross(v, h) / mu - r / np.linalg.norm(r)


def turning_orbit(n0, e0, t, pole, s=-2.0e-5, g=3.0e-5):
    """The J2000 orbit (n0, e0) turned about ``pole`` by s·t and its perihelion by g·t about the normal."""
    normals, eccs = [], []
    for tk in t:
        node_turn = Rotation.from_rotvec(s * tk * pole)
        n = node_turn.apply(n0)
        e = Rotation.from_rotvec(g * tk * n).apply(node_turn.apply(e0))
        normals.append(n)
        eccs.append(e)
    return np.array(normals), np.array(eccs)


def write_alkhqp(path, t_kyr, axes, normal, ecc, a=1.00000261):
    inc, node, varpi, e = elements_in(axes, normal, ecc)
    rows = zip(
        t_kyr,
        np.full(t_kyr.size, a),
        0.1 * t_kyr,
        e * np.cos(varpi),
        e * np.sin(varpi),
        np.sin(inc / 2) * np.cos(node),
        np.sin(inc / 2) * np.sin(node),
        strict=True,
    )
    path.write_text("".join(" ".join(f"{x: .16E}" for x in row) + "\n" for row in rows))


@pytest.mark.parametrize("x_angle", [0.0, 1.234])
def test_solutions_la2010_invariable_frame_round_trip(tmp_path, x_angle):
    # The Earth's orbit written in a frame on the invariable plane, x axis anywhere in it: the
    # reader finds the rotation from the J2000 row and gives back the ecliptic vectors.
    axes = frame_axes(PLANE_I, PLANE_NODE, x_angle)
    t = np.linspace(-20.0, 0.0, 21) * 1000.0
    n0, e0 = earth_j2000()
    normal, ecc = turning_orbit(n0, e0, t, axes[2])
    path = tmp_path / "La2010a_alkhqp3L.dat"
    write_alkhqp(path, t / 1000.0, axes, normal, ecc)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        sol = read_solution(path)
    assert (sol.format, sol.planet) == ("la2010", "earth")
    np.testing.assert_allclose(sol.t, t)
    np.testing.assert_allclose(sol.normal, normal, atol=1e-13)
    np.testing.assert_allclose(sol.eccentricity_vector, ecc, atol=1e-13)
    np.testing.assert_allclose(sol.a, 1.00000261)
    assert "i = 1.57869 deg, node 107.5822 deg" in sol.frame
    orbit = orbit_history(path)
    np.testing.assert_allclose(orbit.normal(t[3]), normal[3], atol=1e-13)


def test_solutions_la2010_other_frame_warns(tmp_path):
    # Written in the J2000 ecliptic itself: the plane found is the ecliptic, 1.58 deg from the
    # invariable plane, and the reader says so.
    t = np.linspace(-5.0, 0.0, 6) * 1000.0
    n0, e0 = earth_j2000()
    normal, ecc = turning_orbit(n0, e0, t, np.array([0.0, 0.0, 1.0]))
    path = tmp_path / "earth.dat"
    write_alkhqp(path, t / 1000.0, np.eye(3), normal, ecc)
    with pytest.warns(UserWarning, match=r"1\.57[0-9] deg from the invariable plane"):
        sol = read_solution(path, "la2010")
    np.testing.assert_allclose(sol.normal, normal, atol=1e-13)


def test_solutions_la2010_needs_j2000_row(tmp_path):
    path = tmp_path / "La2010b_alkhqp3.dat"
    path.write_text("".join(f"{-k - 1} 1.0 0.0 0.0167 0.0 0.0 0.0\n" for k in range(4)))
    with pytest.raises(ValueError, match=r"expected a row at t = 0 \(J2000\) in .*La2010b_alkhqp3\.dat"):
        read_solution(path)


def hci_components(v):
    """Components in HCI (x: the Sun's equator's node on the J2000 ecliptic, z: the Sun's pole)."""
    return v @ frame_axes(SUN_I, SUN_NODE).T


def test_solutions_hci_earth_pole():
    # The J2000 ecliptic pole in HCI: inclination 7.155 deg, node 180 deg (module notes of zeebe).
    n = hci_components(np.array([0.0, 0.0, 1.0]))
    assert math.degrees(math.acos(n[2])) == pytest.approx(7.155, abs=1e-12)
    assert math.degrees(math.atan2(n[0], -n[1])) % 360.0 == pytest.approx(180.0, abs=1e-12)


def write_hnbody(path, t_days, axes, normal, ecc, a=1.0000):
    inc, node, varpi, e = elements_in(axes, normal, ecc)
    omega = (varpi - node) % (2 * math.pi)
    # A header of three lines that are not numbers (snvecR skips three), no comment mark.
    lines = ["HNBody 1.0.10 output", "t a e i varpi Omega omega M", "units: days, AU, degrees"]
    columns = (t_days, np.full(t_days.size, a), e, *np.degrees([inc, varpi, node, omega]), 0 * t_days)
    lines += [" ".join(f"{x:.15g}" for x in row) for row in zip(*columns, strict=True)]
    path.write_text("\n".join(lines) + "\n")


def test_solutions_zb18a_hci_round_trip(tmp_path):
    t_years = np.linspace(-4000.0, 0.0, 9)
    n0, e0 = earth_j2000()
    normal, ecc = turning_orbit(n0, e0, t_years, frame_axes(PLANE_I, PLANE_NODE)[2], s=-5e-4, g=4e-4)
    path = tmp_path / "ems-plan3.dat"
    write_hnbody(path, t_years * 365.25, frame_axes(SUN_I, SUN_NODE), normal, ecc)
    sol = read_solution(path)
    assert (sol.format, sol.planet) == ("zb18a", "earth")
    np.testing.assert_allclose(sol.t, t_years, rtol=0, atol=1e-9)
    np.testing.assert_allclose(sol.normal, normal, atol=1e-12)
    np.testing.assert_allclose(sol.eccentricity_vector, ecc, atol=1e-12)
    # Through the elements: the planets' elements of the file are the ecliptic ones.
    record = planet_orbits(path).elements(t_years[2:5])
    inc, node, varpi, e = elements_in(np.eye(3), normal[2:5], ecc[2:5])
    np.testing.assert_allclose(record.values["earth"]["inclination"], inc, atol=1e-12)
    np.testing.assert_allclose(record.values["earth"]["node"], node, atol=1e-9)
    np.testing.assert_allclose(record.values["earth"]["perihelion"], varpi, atol=1e-9)
    np.testing.assert_allclose(record.values["earth"]["e"], e, atol=1e-14)


def test_solutions_zb18a_ecliptic_frame(tmp_path):
    t_years = np.linspace(-300.0, 0.0, 4)
    n0, e0 = earth_j2000()
    normal, ecc = turning_orbit(n0, e0, t_years, np.array([0.0, 0.0, 1.0]))
    path = tmp_path / "mar-plan3.dat"
    write_hnbody(path, t_years * 365.25, np.eye(3), normal, ecc, a=1.5237)
    from andoyer.planetary.orbits.zeebe import read_zb18a

    sol = read_zb18a(path, frame="ecliptic")
    assert sol.planet == "mars"
    np.testing.assert_allclose(sol.normal, normal, atol=1e-12)
    with pytest.raises(ValueError, match=r"expected an orbit of earth, got the mars's orbit"):
        orbit_history(path, "earth")


def test_solutions_la2004_columns(tmp_path):
    t = -np.arange(6.0)
    e = 0.0167 + 1e-4 * t
    obliquity = 0.409 + 1e-3 * t
    varpi = 1.796 + 0.3 * t
    path = tmp_path / "INSOLN.LA2004.BTL.ASC"
    path.write_text(
        "".join(
            f"{tk:13.3f}{ek:25.16E}{ok:25.16E}{wk:25.16E}\n".replace("E", "D")
            for tk, ek, ok, wk in zip(t, e, obliquity, varpi, strict=True)
        )
    )
    sol = read_solution(path)
    assert (sol.format, sol.planet, sol.has_plane) == ("la2004", "earth", False)
    np.testing.assert_allclose(sol.t, t[::-1] * 1000.0)
    np.testing.assert_allclose(sol.e, e[::-1], rtol=1e-15)
    np.testing.assert_allclose(sol.obliquity, obliquity[::-1], rtol=1e-15)
    np.testing.assert_allclose(sol.climatic_precession, (e * np.sin(varpi))[::-1], rtol=1e-14)
    with pytest.raises(ValueError, match=r"expected an orbit solution with the orbit plane .* la2004 file"):
        orbit_history(path)
    record = planet_orbits(path).elements([-2500.0])
    assert record.values["earth"]["inclination"] is None
    assert set(record.as_dict()["elements"]["earth"]) == {"a", "e", "inclination", "perihelion", "node"}


@given(st.lists(st.floats(0.0, 0.07), min_size=4, max_size=12))
def test_solutions_zb_ecc_round_trip(tmp_path_factory, values):
    path = tmp_path_factory.mktemp("zb") / "ZB18a.dat"
    ages = np.arange(len(values)) * 2.0
    path.write_text(
        "% age(kyr) ecc inc(deg)\n"
        + "".join(f"{a:.3f} {e!r} 1.5\n" for a, e in zip(ages, values, strict=True))
    )
    sol = read_solution(path)
    assert sol.format == "zb-ecc"
    np.testing.assert_array_equal(sol.t, -ages[::-1] * 1000.0)
    np.testing.assert_array_equal(sol.e, np.array(values)[::-1])


def test_solutions_zb23_and_la2010_ecc(tmp_path):
    zb = tmp_path / "ZB23.R07.eiop.dat"
    zb.write_text("".join(f"{-k:.1f} 0.01{k} 0.02 0.41 0.00{k}\n" for k in range(5)))
    sol = read_solution(zb)
    assert sol.format == "zb23"
    np.testing.assert_allclose(sol.climatic_precession, [0.004, 0.003, 0.002, 0.001, 0.0])
    ecc = tmp_path / "La2010c_ecc3L.dat"
    ecc.write_text("".join(f"{-k}.0 0.0{k + 1}\n" for k in range(4)))
    assert read_solution(ecc).e.tolist() == [0.04, 0.03, 0.02, 0.01]


@pytest.mark.parametrize(
    ("row", "expected"),
    [
        ("0 0.01", "la2010-ecc"),
        ("0 0.01 1.5", "zb-ecc"),
        ("0.000  0.1670236225492288D-01  0.4090928042223415D+00  0.1796256991128036D+01", "la2004"),
        ("0 0.01 0.02 0.41 0.001", "zb23"),
        ("0 1 0 0.0167 0 0 0", "la2010"),
        ("0 1 0.0167 0 102 0 102 0", "zb18a"),
        ("t_years,nx,ny,nz", "csv"),
    ],
)
def test_solutions_format_from_columns(tmp_path, row, expected):
    path = tmp_path / "solution.txt"
    path.write_text("# a comment\n" + row + "\n")
    assert solution_format(path) == expected


@pytest.mark.parametrize(
    ("name", "expected"),
    [
        ("INSOLP.LA2004.BTL.ASC", "la2004"),
        ("INSOLN.LA2004.MARS.ASC", "la2004"),
        ("La2010d_alkhqp3.dat", "la2010"),
        ("La2010a_ecc3L.dat", "la2010-ecc"),
        ("ems-plan3.dat", "zb18a"),
        ("ZB20a.dat", "zb-ecc"),
        ("ZB17c.dat", "zb-ecc"),
        ("ZB23.R01.eiop.dat", "zb23"),
        ("earth.CSV", "csv"),
    ],
)
def test_solutions_format_from_name(name, expected):
    assert solution_format(name) == expected


def test_solutions_format_unknown(tmp_path):
    path = tmp_path / "six.dat"
    path.write_text("0 1 2 3 4 5\n")
    with pytest.raises(
        ValueError,
        match=r"expected an orbit or solution file of a known format .* got 6 columns "
        r"on line 1 of .*six\.dat",
    ):
        orbit_history(path)


GOOD = {
    "La2010a_alkhqp3L.dat": [f"{-k}.0 1.0 0.0 0.0167 0.001 0.01 0.002" for k in range(5)],
    "INSOLN.LA2004.BTL.ASC": [f"{-k}.000 0.1670D-01 0.4090D+00 0.1796D+01" for k in range(5)],
    "ZB20a.dat": [f"{k}.0 0.0167 1.5" for k in range(5)],
    "ZB23.R01.eiop.dat": [f"{-k}.0 0.0167 0.02 0.41 0.001" for k in range(5)],
    "ems-plan3.dat": [f"{-365.25 * k} 1.0 0.0167 7.155 282.9 180.0 102.9 0.0" for k in range(5)],
}


def damaged(name, how):
    rows = list(GOOD[name])
    if how == "truncated":
        rows[-1] = rows[-1][: len(rows[-1]) // 2].rstrip()
        return ("\n".join(rows)).encode(), r"expected \d columns .* on line 5 of .*, got \d"
    if how == "nan":
        fields = rows[2].split()
        fields[1] = "NaN"
        rows[2] = " ".join(fields)
        return (
            "\n".join(rows) + "\n"
        ).encode(), r"expected finite numbers, got nan in column .* on line 3 of"
    if how == "repeated time":
        rows[3] = rows[2]
        return ("\n".join(rows) + "\n").encode(), r"expected strictly monotonic times .* on line 4 of"
    if how == "extra column":
        rows[1] += " 7.0"
        return ("\n".join(rows) + "\n").encode(), r"expected \d columns .* on line 2 of .*, got \d"
    if how == "binary":
        return (
            b"\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR\xff\xfe",
            r"expected a text file of numbers, got byte 0x89 on line 1",
        )
    raise AssertionError(how)


@pytest.mark.parametrize("how", ["truncated", "nan", "repeated time", "extra column", "binary"])
@pytest.mark.parametrize("name", sorted(GOOD))
def test_solutions_damaged_files(tmp_path, name, how):
    data, match = damaged(name, how)
    path = tmp_path / name
    path.write_bytes(data)
    with pytest.raises(ValueError, match=match) as info:
        read_solution(path)
    assert "\n" not in str(info.value)
    assert name in str(info.value)


@pytest.mark.parametrize("name", sorted(GOOD))
def test_solutions_utf8_bom_read(tmp_path, name):
    plain, marked = tmp_path / name, tmp_path / "bom" / name
    marked.parent.mkdir()
    text = "\n".join(GOOD[name]) + "\n"
    plain.write_text(text)
    marked.write_bytes(b"\xef\xbb\xbf" + text.encode())
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)  # the made-up La2010 frame is not the invariable plane
        a, b = read_solution(plain), read_solution(marked)
    np.testing.assert_array_equal(a.t, b.t)
    np.testing.assert_array_equal(a.e, b.e)
