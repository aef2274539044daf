"""``andoyer cassini``: named bodies, body files, values given whole, the inverse problem, refusals.

The numbers are checked against bodies built here from the same inputs through the API (the
command is a thin layer), the small-angle Cassini relation, and the refusals word for word.
"""

from __future__ import annotations

import functools
import json
import math
import os
import subprocess
import sys
from pathlib import Path

import pytest

from andoyer import catalogue
from andoyer.catalogue.units import ARCSEC
from andoyer.planetary import cassini

#: Titan's values, whole (the catalogue's, with the ~700-yr node and 0.28° of issue 23).
TITAN = [
    *("--j2", "31.808e-6", "--c22", "9.983e-6", "--moment-of-inertia", "0.3414"),
    *("--orbital-period", "15.945448", "--eccentricity", "0.029", "--node-period", "703"),
    *("--inclination", "0.28", "--mass-ratio", "2.367e-4", "--resonance", "1"),
]


@pytest.fixture
def cli(run_cli):
    """``andoyer cassini ARGV`` in process: (exit code, stdout, stderr)."""
    return functools.partial(run_cli, "cassini")


def test_cli_cassini_refuses_part_of_a_body(cli):
    """Issue 23: Titan's J2, C22, C/MR², node period and inclination on the Moon kept the Moon's
    27.3-day orbit and printed 0.2519°. Now refused, naming what is missing."""
    argv = (
        "moon --j2 31.808e-6 --c22 9.983e-6 --moment-of-inertia 0.3414 --node-period 703 --inclination 0.28"
    )
    code, out, err = cli(*argv.split())
    assert (code, out) == (2, "")
    expected = (
        "andoyer cassini: error: expected every value option or none (a body given whole: use "
        "--body-file to change a few), got --j2, --c22, --moment-of-inertia, --node-period, "
        "--inclination without --orbital-period, --eccentricity, --mass-ratio, --resonance"
    )
    assert err.strip().splitlines() == [expected]


def test_cli_cassini_values_whole(cli):
    code, out, _ = cli(*TITAN, "--format", "json")
    assert code == 0
    fields = json.loads(out)
    body = cassini.CassiniBody(
        "command line", 31.808e-6, 9.983e-6, 0.3414, 2 * math.pi * 365.25 / 15.945448, 0.029,
        math.radians(0.28), -2 * math.pi / 703, resonance=1.0, mass_ratio=2.367e-4,
    )  # fmt: skip
    state1 = next(s for s in cassini.states(body) if s.number == 1)
    assert fields["body"] == "command line"
    assert fields["node_source"] == "command line"
    assert fields["states"][0]["number"] == 1
    assert fields["states"][0]["obliquity"] == pytest.approx(state1.obliquity_deg, rel=1e-12)
    # small angle: θ = g sin i/(α + β + g cos i)
    g, i = body.node_rate, body.inclination
    small = g * math.sin(i) / (body.precession_constant + body.resonance_constant + g * math.cos(i))
    assert fields["obliquity"] == pytest.approx(math.degrees(abs(small)), rel=1e-4)
    assert fields["node_rate"] == pytest.approx(-1296000 / 703, rel=1e-14)


@pytest.mark.parametrize(
    ("body", "numbers", "source"),
    [("moon", [2, 3], "catalogue"), ("mercury", [1, 2, 3, 4], "catalogue"), ("titan", [1, 2, 3, 4], "model")],
)
def test_cli_cassini_json_keys(cli, body, numbers, source):
    code, out, _ = cli(body, "--format", "json")
    assert code == 0
    fields = json.loads(out)
    old = {
        "body",
        "resonance",
        "states",
        "precession_constant",
        "resonance_constant",
        "node_rate",
        "inclination",
    }
    new = {"node_source", "node_period", "modes", "obliquity", "obliquity_range"}
    assert set(fields) == old | new
    assert fields["body"] == body
    assert fields["node_source"] == source
    assert [s["number"] for s in fields["states"]] == numbers
    for s in fields["states"]:
        assert set(s) == {"number", "obliquity", "inclination_to_laplace", "stable"}
    system = cassini.get(body)
    assert fields["node_rate"] == pytest.approx(system.node_rate / ARCSEC, rel=1e-14)
    assert fields["precession_constant"] == pytest.approx(system.precession_constant / ARCSEC, rel=1e-14)
    for mode in fields["modes"]:
        assert set(mode) == {"node_period", "inclination", "phase", "state", "obliquity"}


def test_cli_cassini_several_modes_table(cli):
    code, out, _ = cli("europa")
    assert code == 0
    assert "mode_period_yr" in out
    forced = cassini.forced_obliquity("europa")
    assert f"obliquity (modes summed) {math.degrees(float(forced.obliquity())):.6g} deg" in out
    code, out, _ = cli("europa", "--node", "catalogue", "--format", "json")
    fields = json.loads(out)
    assert fields["node_source"] == "catalogue"
    assert fields["node_period"] == pytest.approx(catalogue.get("europa").node_period.to("yr"), rel=1e-14)


def test_cli_cassini_inverse(cli):
    code, out, _ = cli("titan", "--obliquity", "0.32", "--obliquity-error", "0.02", "--format", "json")
    assert code == 0
    inverse = json.loads(out)["inverse"]
    (expected,) = cassini.moment_of_inertia_from_obliquity("titan", math.radians(0.32), math.radians(0.02))
    (solution,) = inverse["solutions"]
    assert solution["moment_of_inertia"] == pytest.approx(expected.moment_of_inertia, rel=1e-12)
    assert solution["error"] == pytest.approx(expected.error, rel=1e-12)
    assert set(solution["contributions"]) == {"obliquity", "j2", "c22"}
    code, out, _ = cli("titan", "--obliquity", "0.32", "--obliquity-error", "0.02")
    assert "C/MR^2 from the obliquity 0.32 +- 0.02 deg:" in out


def test_cli_cassini_inverse_values_whole(cli):
    argv = [a for a in TITAN if a not in ("--moment-of-inertia", "0.3414")]
    code, out, err = cli(*argv, "--obliquity", "0.3", "--format", "json")
    assert code == 0, err
    (solution,) = json.loads(out)["inverse"]["solutions"]
    assert set(solution["contributions"]) == {"obliquity"}
    assert solution["error"] == 0.0


def test_cli_cassini_body_file_json_and_toml(cli, run_cli, tmp_path):
    code, out, _ = run_cli("bodies", "moon", "--format", "json")
    assert code == 0
    path = tmp_path / "moon.json"
    path.write_text(out)
    _, named, _ = cli("moon", "--format", "json")
    code, mine, _ = cli("--body-file", str(path), "--format", "json")
    assert code == 0
    assert json.loads(mine) == json.loads(named)
    toml = tmp_path / "mine.toml"
    toml.write_text(
        'name = "Mine"\nkind = "satellite"\nprimary = "earth"\ngm = 4902.8\nj2 = 2.0e-4\nc22 = 2.2e-5\n'
        "moment_of_inertia = 0.39\nresonance = 1\norbital_period = 27.32\neccentricity = 0.05\n"
        "laplace_inclination = 5.0\nnode_period = 18.6\n"
    )
    code, out, err = cli("--body-file", str(toml), "--format", "json")
    assert code == 0, err
    fields = json.loads(out)
    assert fields["body"] == "mine"
    assert fields["inclination"] == pytest.approx(5.0, rel=1e-15)


MOMENT = "argument --moment-of-inertia: expected a polar moment of inertia 0 < C/MR^2 <= 1"
NODE = "argument --node-period: expected a node period T_node > 0 yr"
SLOPE = "argument --inclination: expected an inclination 0 < i < 90 deg"

REFUSED = {
    "partial": (["mercury", "--moment-of-inertia", "0.34"], "expected every value option or none"),
    "missing_value": (["triton"], "expected Triton to have j2 for the Cassini states"),
    "not_inclined": (["enceladus"], "expected Enceladus to have orbital_period"),
    "unknown_body": (["vulcan"], "expected a body among"),
    "nothing": ([], "expected a BODY, a --body-file or every value option, got neither"),
    "both": (
        ["moon", "--body-file", "x.json"],
        "expected a BODY, a --body-file or every value option, got both",
    ),
    "model_for_a_planet": (["mercury", "--node", "model"], "expected a satellite of a planet"),
    "no_node_period": (["titan", "--node", "catalogue"], "expected Titan to have node_period"),
    "error_alone": (["titan", "--obliquity-error", "0.02"], "expected --obliquity with --obliquity-error"),
    "moment_and_inverse": (
        [*TITAN, "--obliquity", "0.3"],
        "expected no --moment-of-inertia with --obliquity",
    ),
    "obliquity_90": (["titan", "--obliquity", "90"], "expected 0 < --obliquity < 90 degrees"),
    "negative_error": (
        ["titan", "--obliquity", "0.3", "--obliquity-error=-1"],
        "expected 0 <= --obliquity-error",
    ),
    "negative_moment": ([*TITAN[:4], "--moment-of-inertia", "-0.3", *TITAN[6:]], MOMENT),
    "c22_too_large": ([*TITAN[:2], "--c22", "1e-4", *TITAN[4:]], "expected J2 > 0 and 0 <= C22 <= J2/2"),
    "zero_node_period": ([*TITAN[:10], "--node-period", "0", *TITAN[12:]], NODE),
    "inclination_90": ([*TITAN[:12], "--inclination", "90", *TITAN[14:]], SLOPE),
    "resonance": ([*TITAN[:16], "--resonance", "0.7"], "expected a spin-orbit resonance p with 2p"),
    "mass_ratio": ([*TITAN[:14], "--mass-ratio", "2", *TITAN[16:]], "expected 0 <= mass_ratio < 1"),
    "nan_j2": (
        ["--j2", "nan", *TITAN[2:]],
        "argument --j2: expected a second-degree zonal coefficient J2 > 0",
    ),
    "nan_period": ([*TITAN[:6], "--orbital-period", "nan", *TITAN[8:]], "expected a finite number"),
    "bad_node": (["titan", "--node", "jpl"], "invalid choice"),
    "node_with_values": ([*TITAN, "--node", "model"], "expected --node with a BODY or a --body-file"),
    "values_and_file": ([*TITAN, "--body-file", "x.json"], "expected the value options or --body-file"),
    "bad_format": (["moon", "--format", "csv"], "invalid choice"),
    "missing_directory": (["moon", "--output", "/nonexistent/dir/x.json"], "expected an existing directory"),
}


@pytest.mark.parametrize("name", list(REFUSED))
def test_cli_cassini_bad_input_exit_2(cli, name):
    argv, message = REFUSED[name]
    code, out, err = cli(*argv)
    assert code == 2
    assert out == ""
    assert len(err.strip().splitlines()) == 1
    assert message in err


def test_cli_cassini_table_and_output_file(cli, tmp_path):
    code, out, _ = cli("moon")
    assert code == 0
    assert out.splitlines()[0].split() == [
        "state",
        "obliquity_deg",
        "inclination_to_laplace_deg",
        "stability",
    ]
    target = tmp_path / "moon.json"
    code, out, _ = cli("moon", "--format", "json", "--output", str(target))
    assert (code, out) == (0, "")
    assert json.loads(target.read_text())["body"] == "moon"


def test_cli_cassini_refusal_in_a_process_has_no_traceback():
    proc = subprocess.run(
        [sys.executable, "-m", "andoyer", "cassini", "triton"],
        capture_output=True,
        text=True,
        check=False,
        env={**os.environ, "PYTHONPATH": str(Path(__file__).resolve().parents[3] / "src")},
    )
    assert proc.returncode == 2
    assert "Traceback" not in proc.stderr
    (line,) = proc.stderr.strip().splitlines()
    assert line.startswith("andoyer cassini: error: expected Triton to have j2 for the Cassini states")
