"""The andoyer command line: output, round trips, and one-line errors with exit code 2."""

from __future__ import annotations

import csv
import json
import subprocess
import sys

import numpy as np
import pytest

from andoyer import State
from andoyer.cli import main


def run_cli(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def test_cli_bodies_lara_set_csv_lists_lara_table1(capsys):
    code, out, _ = run_cli(capsys, "bodies", "--moments", "lara2013", "--format", "csv")
    assert code == 0
    rows = {r["name"]: r for r in csv.DictReader(out.splitlines())}
    assert set(rows) == {"earth", "mars", "moon", "eros"}
    assert float(rows["eros"]["beta"]) == pytest.approx(0.977853, abs=6e-7)  # Lara (2013) Table 1
    assert float(rows["mars"]["I1"]) == 0.9942917


def test_cli_bodies_json_lists_every_body_with_sources(capsys):
    code, out, _ = run_cli(capsys, "bodies", "--format", "json")
    assert code == 0
    rows = {r["name"].lower(): r for r in json.loads(out)}
    assert {"sun", "earth", "moon", "titan", "triton", "eros"} <= set(rows)
    assert rows["mars"]["moment_sets"]["lara2013"]["a_over_c"]["value"] == 0.9942917
    assert all(v["source"] for r in rows.values() for v in r.values() if isinstance(v, dict) and "value" in v)


def test_cli_convert_values_matches_library(capsys):
    code, out, _ = run_cli(
        capsys,
        "convert",
        "--from",
        "andoyer",
        "--to",
        "euler",
        "--values",
        "0.1",
        "0.2",
        "0.3",
        "0.9",
        "1.0",
        "0.5",
        "--format",
        "csv",
    )
    assert code == 0
    header, values = out.strip().splitlines()
    assert header == "phi,theta,psi,Phi,Theta,Psi"
    got = np.array([float(x) for x in values.split(",")])
    # Independent route: the rotation matrix entries give theta, Phi = H, Psi = L.
    a = State.from_andoyer(0.1, 0.2, 0.3, 0.9, 1.0, 0.5)
    R = a.rotation.as_matrix()
    assert got[1] == pytest.approx(np.arccos(R[2, 2]), abs=1e-14)
    assert got[3] == pytest.approx(0.5, abs=1e-15)
    assert got[5] == pytest.approx(0.9, abs=1e-15)


def test_cli_convert_csv_round_trip(tmp_path, capsys, rng):
    src = tmp_path / "in.csv"
    l, g, h = rng.uniform(0, 2 * np.pi, (3, 50))
    G = rng.uniform(1, 2, 50)
    L, H = G * rng.uniform(-0.9, 0.9, (2, 50))
    with open(src, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["l", "g", "h", "L", "G", "H"])
        w.writerows(np.stack([l, g, h, L, G, H], -1).tolist())
    mid, back = tmp_path / "euler.csv", tmp_path / "back.csv"
    assert (
        main(
            [
                "convert",
                "--from",
                "andoyer",
                "--to",
                "euler",
                "--input",
                str(src),
                "--format",
                "csv",
                "--output",
                str(mid),
            ]
        )
        == 0
    )
    assert (
        main(
            [
                "convert",
                "--from",
                "euler",
                "--to",
                "andoyer",
                "--input",
                str(mid),
                "--format",
                "csv",
                "--output",
                str(back),
            ]
        )
        == 0
    )
    data = np.loadtxt(back, delimiter=",", skiprows=1)
    assert np.abs(data[:, 3:] - np.stack([L, G, H], -1)).max() <= 1e-13
    assert np.abs(np.angle(np.exp(1j * (data[:, :3] - np.stack([l, g, h], -1))))).max() <= 1e-12
    assert not list(tmp_path.glob("*.part"))


def test_cli_convert_degrees(capsys):
    code, out, _ = run_cli(
        capsys,
        "convert",
        "--from",
        "euler",
        "--to",
        "euler",
        "--degrees",
        "--values",
        "30",
        "60",
        "90",
        "0.5",
        "0.1",
        "0.8",
        "--format",
        "csv",
    )
    assert code == 0
    got = [float(x) for x in out.strip().splitlines()[1].split(",")]
    assert got == pytest.approx([30, 60, 90, 0.5, 0.1, 0.8], abs=1e-12)


BAD_ARGS = [
    ["convert", "--from", "andoyer", "--to", "euler", "--values", "0", "0", "0", "2", "1", "0"],
    ["convert", "--from", "andoyer", "--to", "euler", "--values", "0", "0", "0"],
    ["convert", "--from", "nowhere", "--to", "euler", "--values", "1"],
    ["convert", "--from", "euler", "--to", "andoyer", "--input", "/nonexistent/file.csv"],
    [
        "convert",
        "--from",
        "euler",
        "--to",
        "andoyer",
        "--values",
        "0",
        "0",
        "0",
        "1",
        "0",
        "1",
        "--output",
        "/nonexistent/dir/out.csv",
    ],
    ["demo", "--body", "pluto"],
    ["frobnicate"],
    [],
]


@pytest.mark.parametrize("argv", BAD_ARGS, ids=[" ".join(a[:3]) or "empty" for a in BAD_ARGS])
def test_cli_bad_arguments_one_line_exit_2(argv):
    proc = subprocess.run(
        [sys.executable, "-m", "andoyer", *argv], capture_output=True, text=True, check=False
    )
    assert proc.returncode == 2
    assert "Traceback" not in proc.stderr
    assert "error" in proc.stderr.strip().splitlines()[-1]
    assert "np.float64" not in proc.stderr


def test_cli_bad_file_leaves_no_output(tmp_path, capsys):
    src = tmp_path / "bad.csv"
    src.write_text("l,g,h,L,G,H\n0,0,0,0.5,1,0\n0,0,0,3.0,1,0\n")
    out = tmp_path / "out.csv"
    out.write_text("previous contents\n")
    code, _, err = run_cli(
        capsys, "convert", "--from", "andoyer", "--to", "euler", "--input", str(src), "--output", str(out)
    )
    assert code == 2
    assert "expected |L| <= G" in err
    assert out.read_text() == "previous contents\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.csv", "out.csv"]


def test_cli_bad_csv_columns_and_numbers(tmp_path, capsys):
    wrong = tmp_path / "wrong.csv"
    wrong.write_text("a,b\n1,2\n")
    code, _, err = run_cli(capsys, "convert", "--from", "andoyer", "--to", "euler", "--input", str(wrong))
    assert code == 2
    assert "expected CSV columns l, g, h, L, G, H, got a, b" in err
    text = tmp_path / "text.csv"
    text.write_text("l,g,h,L,G,H\n0,0,0,x,1,0\n")
    code, _, err = run_cli(capsys, "convert", "--from", "andoyer", "--to", "euler", "--input", str(text))
    assert code == 2
    assert "expected numbers in column 'L'" in err


@pytest.mark.parametrize("algebra", ["so3", "e3"])
def test_cli_brackets_json_every_entry_verified(capsys, algebra):
    code, out, _ = run_cli(capsys, "brackets", "--algebra", algebra, "--format", "json")
    assert code == 0
    table = json.loads(out)
    assert {"left", "right", "value", "symbolic_ok", "numeric_ok"} <= set(table[0])
    assert all(row["symbolic_ok"] and row["numeric_ok"] for row in table)
    pairs = {(row["left"], row["right"]): row["value"] for row in table}
    assert pairs[("l", "L")] == "1"
    if algebra == "e3":  # so(3) has only the pair (l, L) and the Casimir G
        assert pairs[("g", "G")] == "1"


#: A triaxial body and an Andoyer state shared by the propagate tests.
PROPAGATE_START = ("--moments", "1", "2", "3", "--values", "0.1", "0.2", "0.3", "0.9", "1.0", "0.5")


@pytest.fixture
def propagate_csv(capsys):
    """Run ``andoyer propagate`` on the shared start with extra arguments; return the CSV rows."""

    def run(*extra):
        code, out, _ = run_cli(capsys, "propagate", *PROPAGATE_START, *extra, "--format", "csv")
        assert code == 0
        return np.loadtxt(out.splitlines()[1:], delimiter=",")

    return run


def test_cli_propagate_one_period_returns_the_start(propagate_csv):
    from andoyer import FreeRotation, RigidBody

    body = RigidBody(1.0, 2.0, 3.0)
    start = State.from_andoyer(0.1, 0.2, 0.3, 0.9, 1.0, 0.5)
    T = float(FreeRotation(body).periods(start).period)
    rows = propagate_csv("--times", "0", repr(T), "--to", "state")
    m0, m1 = rows[0, 6:], rows[1, 6:]
    assert np.abs(m1 - m0).max() <= 1e-13
    assert np.abs(m0 - start.m_body).max() <= 1e-15


def test_cli_propagate_sadov_angles_advance_linearly(propagate_csv):
    rows = propagate_csv("--range", "0", "3", "4", "--to", "sadov")
    phi = np.unwrap(rows[:, 2])
    assert np.abs(np.diff(phi, 2)).max() <= 1e-12
    assert np.ptp(rows[:, 5]) <= 1e-13  # I_l constant


def test_cli_propagate_needs_a_body(capsys):
    code, _, err = run_cli(capsys, "propagate", "--values", "0", "0", "0", "0.5", "1", "0", "--times", "1")
    assert code == 2
    assert "expected --body NAME or --moments" in err
